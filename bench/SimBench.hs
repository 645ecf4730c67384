{-# LANGUAGE Arrows #-}
-- |
-- The simulator benchmark: worlds scaled to hold 1, 10, 100 or 1000
-- simbots at the density of a notes-style world (10 simbots and a few
-- dozen obstacles in the notes' 10 m square), every simbot running a
-- wall follower in the style of the notes' @rcFollowLeftWall@ that reads
-- all four range finders and the animate object tracker, at dt = 0.01.
module SimBench
  ( worldSide
  , benchBounds
  , benchWorld
  , benchConfig
  , benchController
  , idleController
  , raysController
  , trackerController
  , benchRunWith
  , nearestRobot
  , runBench
  , sharedWorld
  , worldChecksum
  , simDtBench
  , ballCrowd
  , runBallBench
  , packedWorld
  , packedRobots
  , wanderer
  , runPacked
  , benchRun
  , benchRunAlone
  , packedRun
  , snapshotsChecksum
  ) where

import           Data.List     (foldl', sortOn)

import           AFrob
import           AFrobRobotSim

-- | The time step of every simulator run.
simDtBench :: DTime
simDtBench = 0.01

-- | The side of the square world for @n@ robots: the notes' 10 m for up
-- to 10 robots, then growing with the area per robot kept at 10 m^2.
worldSide :: Int -> Double
worldSide n = max 10 (10 * sqrt (fromIntegral n / 10))

-- | The bounds of the world for @n@ robots, centred on the origin.
benchBounds :: Int -> Bounds
benchBounds n = let h = worldSide n / 2 in Bounds (-h) (-h) h h

-- | The settings of a run with @n@ robots.
benchConfig :: Int -> SimConfig
benchConfig n = defaultSimConfig { simDt = simDtBench, simBounds = benchBounds n }

-- | The world for @n@ robots: two obstacles (a horizontal or vertical wall
-- and a block) in every 5 m tile (8 in the 10 m world, 800 in the 100 m
-- one), and the robots on a jittered lattice, clear of the obstacles and
-- of each other. Deterministic.
benchWorld :: Int -> WorldTemplate
benchWorld n = latticeWorld (worldSide n) n

-- | @latticeWorld side n@: the obstacles of 'benchWorld' over a world of
-- the given side and as many of @n@ robots as fit on its jittered lattice
-- (at least 0.53 m apart), clear of the obstacles.
latticeWorld :: Double -> Int -> WorldTemplate
latticeWorld side n = obstacles ++ take n robots
  where
    h     = side / 2
    tiles = max 2 (floor (side / 5)) :: Int
    tile  = side / fromIntegral tiles
    obstacles = concat
      [ [ if even (hash (i * 7 + j * 13)) then OTHWall (Point2 (cx + 0.5 * jx) (cy + 1.2))
                                          else OTVWall (Point2 (cx + 1.2) (cy + 0.5 * jy))
        , OTBlock (Point2 (cx - 1.2 + 0.3 * jy) (cy - 1.2 + 0.3 * jx)) ]
      | i <- [0 .. tiles - 1], j <- [0 .. tiles - 1]
      , let cx = -h + (fromIntegral i + 0.5) * tile
            cy = -h + (fromIntegral j + 0.5) * tile
            jx = unit (i * 31 + j)
            jy = unit (i + j * 29) ]
    -- candidate places on a lattice twice as fine as needed, in a
    -- scrambled order, keeping those clear of the obstacles and the walls
    k      = ceiling (sqrt (2 * fromIntegral (max 1 n) :: Double)) :: Int
    sp     = side / fromIntegral k
    cands  = [ (hash (a * 1009 + b * 9176), Point2 (-h + (fromIntegral a + 0.5) * sp + 0.2 * sp * unit (a * 3 + b))
                                                  (-h + (fromIntegral b + 0.5) * sp + 0.2 * sp * unit (a + b * 5)))
             | a <- [0 .. k - 1], b <- [0 .. k - 1] ]
    clear p@(Point2 x y) = x > -h + 0.4 && x < h - 0.4 && y > -h + 0.4 && y < h - 0.4
                           && all (\o -> norm (otPos o .-. p) > 1.1) obstacles
    places = [ p | (_, p) <- sortOn fst cands, clear p ]
    robots = [ (if even i then OTSimbotA else OTSimbotB) (i `div` 2 + 1) p (2 * pi * unit (i * 17))
             | (i, p) <- zip [0 :: Int ..] places ]

-- A small deterministic hash, and a number in [0, 1) from it.
hash :: Int -> Int
hash x = let y = (x * 2654435761 + 12345) `mod` 4294967296
         in (y `div` 65536) * 31 + y `mod` 65536

unit :: Int -> Double
unit x = fromIntegral (hash x `mod` 10007) / 10007

-- | The benchmark controller: follows the wall on its left at 0.5 m
-- (proportional-derivative on the left range finder, as the notes'
-- @rcFollowLeftWall@), slows down for what is ahead (front range finder)
-- and for the nearest robot (the tracker), creeps when boxed in (right
-- and back range finders), and backs away turning when stuck. Every
-- reading reaches the wheels, so every sensor is computed at every step
-- (except when stuck).
benchController :: SimbotController
benchController _ = proc sbi -> do
  let l    = rfLeft sbi
      f    = rfFront sbi
      r    = rfRight sbi
      b    = rfBack sbi
      near = nearestRobot sbi
  dl <- derivative -< l
  let v     = 0.3
      kd    = 5
      kp    = v * kd * kd / 4
      omega = kp * (l - 0.5) + kd * dl
      away  = if f < 0.6 then -0.6 else 0
      speed = v * min 1 f * min 1 (near / 1.5) + 0.02 * min 1 (r + b)
      stuck = rsIsStuck sbi
  returnA -< mrFinalize (if stuck then ddVelTR (-0.1) 0.6
                                  else ddVelTR speed (max (-0.6) (min 0.6 (omega + away))))

-- | The distance to the nearest robot the tracker sees, or its range (4 m)
-- when it sees none.
nearestRobot :: SimbotInput -> Distance
nearestRobot sbi = case aotOtherRobots sbi of
  (_, _, _, d) : _ -> d
  []               -> 4

-- | The first of the controllers that split a robot-step's cost (see
-- 'benchRunWith'): reads nothing and drives a constant curve (0.3 m/s,
-- 0.1 rad/s). It never reads its input, so no ray is cast and no
-- tracker's list is made: its robot-step is the engine's own work
-- (stepping a trivial network, the input's unread record, the move, the
-- bound on the distance to the others that the move takes, a gathering
-- of the robots near it, the lists and the snapshot).
idleController :: SimbotController
idleController _ = arr (\_ -> mrFinalize (ddVelTR 0.3 0.1))

-- | 'idleController''s work and the four quarter-turn range finders,
-- every one reaching the wheels (no tracker, no state).
raysController :: SimbotController
raysController _ = arr (driveByRanges 1)

-- | 'raysController''s work and the tracker's nearest robot: every sensor
-- 'benchController' reads, without its derivative (no state).
trackerController :: SimbotController
trackerController _ = arr (\sbi -> driveByRanges (min 1 (nearestRobot sbi / 1.5)) sbi)

-- The drive of 'raysController' and 'trackerController': ahead at
-- 0.3 m/s slowed by what is in front (and by the given factor), a creep
-- when boxed in (right and back), turning to keep the left range at
-- 0.5 m.
driveByRanges :: Double -> SimbotInput -> SimbotOutput
driveByRanges slow sbi =
  let f = rfFront sbi
      l = rfLeft sbi
      r = rfRight sbi
      b = rfBack sbi
  in mrFinalize (ddVelTR (0.3 * min 1 f * slow + 0.02 * min 1 (r + b)) (max (-0.6) (min 0.6 (l - 0.5))))

-- | The snapshots of 'benchRun''s world of @n@ robots, every robot driven
-- by the given controller. Timed with 'idleController',
-- 'raysController', 'trackerController' and 'benchController' in turn
-- (@afrp-bench --steady-with@), the differences split a robot-step's
-- cost into the engine's, the range finders', the tracker's and the
-- controller's own (its derivative and its network).
benchRunWith :: SimbotController -> Int -> [WorldState]
benchRunWith c n = benchRunIn (benchConfig n) c n

-- | 'benchRun' stepped alone ('simParallel' 'False'): on the thread that
-- reads it, whatever the capabilities (@afrp-bench --side-by-side@ runs
-- one on each).
benchRunAlone :: Int -> [WorldState]
benchRunAlone n = benchRunIn (benchConfig n) { simParallel = False } benchController n

-- The snapshots of the world of @n@ robots with the given settings, every
-- robot driven by the given controller.
benchRunIn :: SimConfig -> SimbotController -> Int -> [WorldState]
benchRunIn cfg c n = simulateWith cfg (sharedWorld n) c c

-- | Run @n@ robots for @steps@ steps and return a checksum of every
-- robot's position at every step (so that every step is computed). The
-- worlds of the benchmark sizes are built once ('sharedWorld'), so that a
-- timed run is the simulation (including its validation of the world),
-- not the making of the world.
runBench :: Int -> Int -> Double
runBench n steps =
  foldl' (\acc ws -> foldl' (\a r -> let Point2 x y = robotPos r in a + x + y) acc (wsRobots ws)) 0
         (take steps (simulateWith (benchConfig n) (sharedWorld n) benchController benchController))

-- | 'benchWorld', shared between runs for 1, 10, 100 and 1000 robots.
sharedWorld :: Int -> WorldTemplate
sharedWorld n = case lookup n sharedWorlds of
  Just w  -> w
  Nothing -> benchWorld n

sharedWorlds :: [(Int, WorldTemplate)]
sharedWorlds = [ (k, benchWorld k) | k <- [1, 10, 100, 1000] ]
{-# NOINLINE sharedWorlds #-}

-- | A number that depends on every object of 'sharedWorld' (to build it).
worldChecksum :: Int -> Double
worldChecksum n = foldl' (\acc o -> let Point2 x y = otPos o in acc + x + y) 0 (sharedWorld n)

-- | @n@ balls (at most 1024) packed 0.28 m apart on a square lattice over
-- the notes' 10 m world, so that every ball overlaps its neighbours (the
-- balls are 0.3 m across) and the first steps are a crowd of ball-ball
-- contacts; one SimbotA in a corner, driving through them.
ballCrowd :: Int -> WorldTemplate
ballCrowd n = OTSimbotA 1 (Point2 (-4.7) (-4.7)) 0.3 : take (min 1024 n) balls
  where
    balls = [ OTBall (Point2 (-4.34 + 0.28 * fromIntegral i) (-4.34 + 0.28 * fromIntegral j))
            | i <- [0 .. 31 :: Int], j <- [0 .. 31 :: Int] ]

-- | Run 'ballCrowd' for @steps@ steps and return a checksum of every
-- ball's position at every step.
runBallBench :: Int -> Int -> Double
runBallBench n steps =
  foldl' (\acc ws -> foldl' (\a (Point2 x y) -> a + x + y) acc (wsBalls ws)) 0
         (take steps (simulate simDtBench (ballCrowd n) drive drive))
  where
    drive _ = constant (mrFinalize (ddVelTR 1 0.2))

-- | @n@ robots (at most about 130) packed in the notes' 10 m world with
-- the 8 obstacles of 'benchWorld': 100 robots cover a fifth of the floor,
-- about 0.7 m apart, so that every tracker sees most of the others.
packedWorld :: Int -> WorldTemplate
packedWorld = latticeWorld 10

-- | How many robots 'packedWorld' holds (forcing the world).
packedRobots :: Int -> Int
packedRobots n = length [ () | o <- packedWorld n, isRobot o ]
  where isRobot o = case o of
          OTSimbotA {} -> True
          OTSimbotB {} -> True
          _            -> False

-- | A wanderer that senses what is around it: drives on, slowing down for
-- what its front range finder sees and for the nearest robot the tracker
-- reports, turns away from every robot within 1.2 m (the tracker's list,
-- read as far as that), towards the freer side (left and right range
-- finders) when blocked ahead, and backs away turning when stuck. Every
-- reading reaches the wheels.
wanderer :: SimbotController
wanderer props = proc sbi -> do
  let f = rfFront sbi
      l = rfLeft sbi
      r = rfRight sbi
      others = aotOtherRobots sbi
      near  = case others of
        (_, _, _, d) : _ -> d
        []               -> 4
      close = takeWhile (\(_, _, _, d) -> d < 1.2) others
      curve = 0.1 * fromIntegral (rpId props `mod` 3 - 1)
      dodge = max (-1) (min 1 (sum [ negate (signum a) * (1.2 - d) | (_, _, a, d) <- close ]))
      free  | f < 0.6    = if l > r then 1 else -1
            | otherwise  = 0
      speed = 0.4 * min 1 f * min 1 (near / 1.2)
  returnA -< mrFinalize (if rsIsStuck sbi then ddVelTR (-0.1) 0.8
                                          else ddVelTR speed (curve + dodge + free))

-- | Run @n@ wanderers of 'packedWorld' for @steps@ steps and return a
-- checksum of every robot's position at every step.
runPacked :: Int -> Int -> Double
runPacked n steps =
  foldl' (\acc ws -> foldl' (\a r -> let Point2 x y = robotPos r in a + x + y) acc (wsRobots ws)) 0
         (take steps (simulateWith defaultSimConfig { simDt = simDtBench } (packedWorld n) wanderer wanderer))

-- | The snapshots of 'runBench' with @n@ robots (for timing the steps
-- apart from the start of the run).
benchRun :: Int -> [WorldState]
benchRun = benchRunWith benchController

-- | The snapshots of 'runPacked' with @n@ wanderers.
packedRun :: Int -> [WorldState]
packedRun n = simulateWith defaultSimConfig { simDt = simDtBench } (packedWorld n) wanderer wanderer

-- | A number that depends on every robot's position in every snapshot.
snapshotsChecksum :: [WorldState] -> Double
snapshotsChecksum =
  foldl' (\acc ws -> foldl' (\a r -> let Point2 x y = robotPos r in a + x + y) acc (wsRobots ws)) 0
