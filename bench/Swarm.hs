{-# LANGUAGE BangPatterns #-}
-- |
-- The afrp side of @bench/enki.sh@, the comparison with Enki (issue #18):
-- @n@ simbots running a Braitenberg obstacle avoider in a square world
-- sized so that their discs cover a given fraction of the floor, at
-- dt = 0.01, timed in CPU seconds. @bench/enki/swarm.cpp@ runs the same
-- case with Enki's e-pucks: the same placement, headings, sensor angles
-- and weights, every length scaled by the ratio of the robots' radii
-- (0.25 m for a simbot, 3.7 cm for an e-puck) and every speed by the same
-- ratio (so both cover the same number of body lengths per second).
--
-- What differs (the engines, not the benchmark): a simbot's range finder
-- is one exact ray to 3 m (the controller ignores what is beyond its
-- 0.81 m reach, but the engine casts the whole ray), an e-puck's infrared
-- sensor three rays to 12 cm with a noisy response; a simbot's wheels
-- obey an acceleration limit, an e-puck's motors are noisy; the simbots
-- alternate between types A and B.
module Swarm
  ( swarmSide
  , swarmBounds
  , swarmWorld
  , irAngles
  , wheelWeights
  , swarmController
  , runSwarm
  , swarmReport
  ) where

import           Control.Exception (evaluate)
import           Data.List         (foldl')
import           System.CPUTime    (getCPUTime)
import           System.Exit       (exitFailure)
import           System.IO         (hPutStrLn, stderr)
import           Text.Printf       (printf)

import           AFrob
import           AFrobRobotSim

-- | The side, in metres, of the square world in which @n@ simbots (discs
-- 0.5 m across) cover the fraction @coverage@ of the floor.
swarmSide :: Int -> Double -> Double
swarmSide n coverage = sqrt (fromIntegral n * pi * r * r / coverage)
  where r = simbotDiameter / 2

-- | The bounds of that world, from the origin (as Enki's arena).
swarmBounds :: Int -> Double -> Bounds
swarmBounds n coverage = let s = swarmSide n coverage in Bounds 0 0 s s

-- | @n@ simbots on a jittered @k@ by @k@ lattice (@k@ the ceiling of the
-- square root of @n@, filled row by row from the bottom), each moved from
-- its cell's centre by at most a fifth of the gap between neighbours in
-- each direction, so that no two touch and none touches the boundary;
-- headings from a deterministic hash; SimbotA and SimbotB alternating.
-- 'Nothing' when the lattice is too tight (a gap under 5% of a diameter).
swarmWorld :: Int -> Double -> Maybe WorldTemplate
swarmWorld n coverage
  | spacing < 1.05 * d = Nothing
  | otherwise          = Just (map robot [0 .. n - 1])
  where
    d       = simbotDiameter
    k       = ceiling (sqrt (fromIntegral n :: Double)) :: Int
    spacing = swarmSide n coverage / fromIntegral k
    jitter  = 0.2 * (spacing - d)
    robot i =
      let (b, a) = i `divMod` k
          p = Point2 ((fromIntegral a + 0.5) * spacing + jitter * (2 * unit (a * 3 + b) - 1))
                     ((fromIntegral b + 0.5) * spacing + jitter * (2 * unit (a + b * 5) - 1))
          h = 2 * pi * unit (i * 17)
      in (if even i then OTSimbotA else OTSimbotB) (i `div` 2 + 1) p h

-- A small deterministic hash and a number in [0, 1) from it (the same
-- numbers as bench/enki/swarm.cpp's, and as SimBench's).
hash :: Int -> Int
hash x = let y = (x * 2654435761 + 12345) `mod` 4294967296
         in (y `div` 65536) * 31 + y `mod` 65536

unit :: Int -> Double
unit x = fromIntegral (hash x `mod` 10007) / 10007

-- | The directions of the eight range finders the controller reads,
-- relative to the heading: those of the e-puck's infrared sensors 0 to 7
-- (front-front-right, front-right, right, back-right, back-left, left,
-- front-left, front-front-left).
irAngles :: [Angle]
irAngles = [-4 * pi / 45, -pi / 4, -pi / 2, -5 * pi / 6, 5 * pi / 6, pi / 2, pi / 4, 4 * pi / 45]

-- | For each range finder of 'irAngles', its weight on the left and on the
-- right wheel: an obstacle on the right slows the left wheel and speeds up
-- the right one (the robot turns away, to the left), and the other way
-- round; one dead ahead turns it left; one behind speeds it up.
wheelWeights :: [(Double, Double)]
wheelWeights = [(-1.5, 1.0), (-0.8, 0.6), (-0.3, 0.3), (0.3, 0.3), (0.3, 0.3), (0.3, -0.3), (0.6, -0.8), (-0.5, -0.8)]

-- | The Braitenberg avoider: each range finder's reading @r@ (from the
-- robot's edge) gives the activation @1 - r \/ reach@ (0 at or beyond the
-- reach of 0.81 m, 1 at contact), and each wheel's speed is
-- @base * (1 + sum of weight * activation)@, with base 0.43 m\/s, clamped
-- to twice that either way. Memoryless: the output at any time, time 0
-- included, depends on that sample's readings only.
swarmController :: SimbotController
swarmController _ = arr $ \sbi ->
  let (l, r) = foldl' (\(!wl, !wr) (a, (kl, kr)) ->
                         let x = activation (rfRange sbi a) in (wl + kl * x, wr + kr * x))
                      (1, 1) (zip irAngles wheelWeights)
  in mrFinalize (ddVelDiff (wheel l) (wheel r))
  where
    activation x = max 0 (min 1 (1 - x / reach))
    wheel f      = max (-2 * base) (min (2 * base) (base * f))

-- The e-puck's sensor reach (12 cm) and base speed (6.4 cm/s) scaled by
-- 0.25 / 0.037, the ratio of the radii.
reach, base :: Double
reach = 12 * scale
base  = 6.4 * scale

scale :: Double
scale = (simbotDiameter / 2) / 3.7

-- | Run a world of 'swarmWorld' for @steps@ steps at dt = 0.01 with
-- 'swarmController' and return the sum of every robot's coordinates at
-- every step (so that every step is computed).
runSwarm :: Int -> Double -> WorldTemplate -> Int -> Double
runSwarm n coverage world steps =
  foldl' (\acc ws -> foldl' (\s rs -> let Point2 x y = robotPos rs in s + x + y) acc (wsRobots ws)) 0
         (take steps (simulateWith cfg world swarmController swarmController))
  where cfg = defaultSimConfig { simDt = 0.01, simBounds = swarmBounds n coverage }

-- | @swarmReport n coverage seconds@: build the world (outside the timed
-- part), run it for that many simulated seconds, and print one line of
-- key=value pairs: the CPU time, the speed relative to real time and the
-- robot-steps per second (read by bench/enki.sh).
swarmReport :: Int -> Double -> Double -> IO ()
swarmReport n coverage seconds = case swarmWorld n coverage of
  Nothing -> do
    hPutStrLn stderr ("afrp-bench: the lattice is too tight for " ++ show n
                      ++ " robots at coverage " ++ show coverage)
    exitFailure
  Just world -> do
    _  <- evaluate (foldl' (\acc o -> let Point2 x y = otPos o in acc + x + y + otHdng o) 0 world)
    let steps = round (seconds / 0.01) :: Int
    c0 <- getCPUTime
    s  <- evaluate (runSwarm n coverage world steps)
    c1 <- getCPUTime
    let cpu = fromIntegral (c1 - c0) / 1e12 :: Double
    printf "engine=afrp robots=%d coverage=%.3f side=%.2fm steps=%d cpu=%.3f xrt=%.2f robot_steps_per_s=%.0f checksum=%.6e\n"
      n coverage (swarmSide n coverage) steps cpu
      (fromIntegral steps * 0.01 / cpu) (fromIntegral (n * steps) / cpu) s
