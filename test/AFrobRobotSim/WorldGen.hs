-- | Random worlds for the simulator's specs: squares of walls and blocks,
-- the arena "AFrobRobotSim.Arena" makes of them, and robots, balls, wheel
-- commands, time steps and segments (rays) to put in them; and what the
-- specs' reference versions share.
module AFrobRobotSim.WorldGen
  ( World (..)
  , genWorld
  , genMovers
  , arenaFor
  , halfSide
  , genRobot
  , genRobots
  , genCommand
  , genBall
  , genBalls
  , genDt
  , emptyArena
  , robotRadius'
  , ballRadius'
  , pointBoxDistance
  , boxesExtent
  , genSegment
  , genSegmentAmong
  , segmentBoxDistance
  ) where

import           Test.QuickCheck

import           AFRP.Geometry
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Balls   (Ball (..))
import           AFrobRobotSim.Physics
import           AFrobRobotSim.RayGrid (rayGridCellSide, rayGridReach)
import           AFrobRobotSim.Shapes  (Box (..), rayBox)
import           AFrobRobotSim.Robot   (DriveCommand (..))
import           AFrobRobotSim.World

-- | A world: a square of side 8 to 40 m, walls and blocks in it (0 to 60),
-- and its boundary boxes (as 'arenaOf' builds them).
data World = World Bounds [ObjectTemplate]

instance Show World where
  show (World b os) = show b ++ " " ++ show os

genWorld :: Gen World
genWorld = do
  side <- elements [8, 10, 20, 40]
  let h = side / 2
  k <- chooseInt (0, 60)
  obs <- vectorOf k $ do
    x <- choose (-h + 0.6, h - 0.6)
    y <- choose (-h + 0.6, h - 0.6)
    elements [OTBlock (Point2 x y), OTVWall (Point2 x y), OTHWall (Point2 x y)]
  pure (World (Bounds (-h) (-h) h h) obs)

-- | What moves in a world (balls and simbots of both types) anywhere in
-- the square of half side @h@: templates that an arena leaves out.
genMovers :: Double -> Gen [ObjectTemplate]
genMovers h = do
  k <- chooseInt (0, 8)
  vectorOf k $ do
    p  <- Point2 <$> choose (-h, h) <*> choose (-h, h)
    i  <- chooseInt (1, 99)
    th <- choose (-4, 4)
    elements [OTBall p, OTSimbotA i p th, OTSimbotB i p th]

arenaFor :: World -> Arena
arenaFor (World b os) = arenaOf b os

halfSide :: World -> Double
halfSide (World (Bounds _ _ h _) _) = h

-- | A robot anywhere in the square of half side @h@, in any state.
genRobot :: Double -> Gen Robot
genRobot h = do
  k  <- elements [SimbotA, SimbotB]
  i  <- chooseInt (1, 99)
  x  <- choose (-h, h)
  y  <- choose (-h, h)
  th <- choose (-4, 4)
  v  <- choose (-2, 2)
  st <- arbitrary
  c  <- elements [1, 0.5, 0.2, 0.05]
  pure (mkRobot k i (Point2 x y) th v st c)

-- | Robots, often crowded (so that they touch and overlap).
genRobots :: Double -> Gen [Robot]
genRobots h = do
  n <- oneof [chooseInt (0, 12), chooseInt (17, 60)]
  crowd <- elements [h, min h 2, 1]
  vectorOf n (genRobot crowd)

-- | Any wheel command, some beyond the wheels' limits, some that do not
-- turn.
genCommand :: Gen DriveCommand
genCommand = oneof
  [ pure DriveBrake
  , DriveWheels <$> choose (-3, 3) <*> choose (-3, 3)
  , DriveTR <$> choose (-3, 3) <*> choose (-8, 8)
    -- commands that do not turn
  , (\v -> DriveWheels v v) <$> choose (-3, 3)
  , (\v -> DriveTR v 0) <$> choose (-3, 3)
  ]

-- | A ball anywhere in the square of half side @h@, moving fast.
genBall :: Double -> Gen Ball
genBall h = do
  x  <- choose (-h, h)
  y  <- choose (-h, h)
  vx <- choose (-4, 4)
  vy <- choose (-4, 4)
  pure (Ball (Point2 x y) (Vector2 vx vy))

-- | Balls, often crowded (so that they touch and overlap).
genBalls :: Double -> Gen [Ball]
genBalls h = do
  n <- oneof [chooseInt (0, 6), chooseInt (17, 40)]
  crowd <- elements [h, 1, 0.5]
  vectorOf n (genBall crowd)

-- | Time steps, from the usual to the huge.
genDt :: Gen Double
genDt = elements [0.01, 0.05, 0.3, 1, 4]

-- | The notes' 10 m world with nothing in it.
emptyArena :: Arena
emptyArena = arenaOf notesBounds []

-- | The radii of a robot and a ball, from the sizes of
-- "AFrobRobotSim.World" (the references' own, not the implementation's).
robotRadius', ballRadius' :: Double
robotRadius' = simbotDiameter / 2
ballRadius'  = ballDiameter / 2

-- | The distance from a point to a box (0 inside it).
pointBoxDistance :: Double -> Double -> Box -> Double
pointBoxDistance x y (Box x0 y0 x1 y1) =
  let gx = max 0 (max (x0 - x) (x - x1))
      gy = max 0 (max (y0 - y) (y - y1))
  in sqrt (gx * gx + gy * gy)

-- | The boxes' bounding box, @(minX, minY, maxX, maxY)@ (all 0 for no
-- boxes), as the arena's extent is documented.
boxesExtent :: [Box] -> (Double, Double, Double, Double)
boxesExtent [] = (0, 0, 0, 0)
boxesExtent bs = (minimum (map boxMinX bs), minimum (map boxMinY bs), maximum (map boxMaxX bs), maximum (map boxMaxY bs))

-- | A segment among a world's boxes ('genSegmentAmong').
genSegment :: World -> Gen (Double, Double, Double, Double)
genSegment = genSegmentAmong . arenaBoxes . arenaFor

-- | A segment among boxes (at least one): from anywhere in their bounding
-- box widened by a metre, or ending within a millimetre of a box (on its
-- boundary, just outside it, at a corner), or starting on a cell boundary
-- of the ray grid (of the side 'rayGridCellSide', which it has unless the
-- boxes spread over hundreds of metres); mostly as long as a range
-- finder's ray or a little shorter, sometimes longer.
genSegmentAmong :: [Box] -> Gen (Double, Double, Double, Double)
genSegmentAmong boxes = do
  let (x0, y0, x1, y1) = boxesExtent boxes
      cells = max 40 (ceiling (max (x1 - x0) (y1 - y0) / rayGridCellSide))
  len <- oneof [elements [3.25, rayGridReach, 0], choose (0, rayGridReach), choose (3, 8)]
  th  <- oneof [choose (-pi, pi), elements [0, pi / 2, pi, -pi / 2, pi / 4]]
  let ux = cos th
      uy = sin th
  start <- oneof
    [ (,) <$> choose (x0 - 1, x1 + 1) <*> choose (y0 - 1, y1 + 1)
    , do Box a b c d <- elements boxes
         tx <- oneof [elements [a, c], choose (a, c)]
         ty <- oneof [elements [b, d], choose (b, d)]
         ex <- elements [0, 1e-12, 0.5e-3, 0.85e-3, -1e-12]
         ey <- elements [0, 1e-12, 0.5e-3, -0.85e-3]
         k  <- oneof [elements [0, 1], choose (0, 1)]
         pure (tx + ex - k * len * ux, ty + ey - k * len * uy)
      -- ending just short of a box it points at, or starting just
      -- past a box behind it
    , do Box a b c d <- elements boxes
         qx <- choose (a, c)
         qy <- choose (b, d)
         gap <- elements [0, 1e-12, 0.5e-3, 0.85e-3]
         let back | ux > 0    = (qx - a) / ux
                  | ux < 0    = (qx - c) / ux
                  | otherwise = 1 / 0
             down | uy > 0    = (qy - b) / uy
                  | uy < 0    = (qy - d) / uy
                  | otherwise = 1 / 0
             s  = min back down     -- back from (qx, qy) to where the ray enters the box
             ex = qx - s * ux
             ey = qy - s * uy
             -- forward from (qx, qy) to where the ray leaves the box
             lx | ux > 0    = (c - qx) / ux
                | ux < 0    = (a - qx) / ux
                | otherwise = 1 / 0
             ly | uy > 0    = (d - qy) / uy
                | uy < 0    = (b - qy) / uy
                | otherwise = 1 / 0
             l  = min lx ly
         elements [ (ex - (gap + len) * ux, ey - (gap + len) * uy)
                  , (qx + (l + gap) * ux, qy + (l + gap) * uy) ]
    , do i <- chooseInt (0, cells)
         j <- chooseInt (0, cells)
         e <- elements [0, 1e-13, -1e-13]
         pure (x0 + fromIntegral i * rayGridCellSide + e, y0 + fromIntegral j * rayGridCellSide - e) ]
  let (ax, ay) = start
  pure (ax, ay, ax + len * ux, ay + len * uy)

-- | The distance between a segment and a box (0 if they meet): from an end
-- of the segment to the box, or from a corner of the box to the segment.
segmentBoxDistance :: (Double, Double) -> (Double, Double) -> Box -> Double
segmentBoxDistance (ax, ay) (bx, by) box@(Box x0 y0 x1 y1)
  | meets     = 0
  | otherwise = minimum ([pointBoxDistance ax ay box, pointBoxDistance bx by box] ++ [ toSegment cx cy | cx <- [x0, x1], cy <- [y0, y1] ])
  where
    meets = case rayBox (Point2 ax ay) (Vector2 (bx - ax) (by - ay)) box of
      Just t  -> t <= 1
      Nothing -> False
    toSegment cx cy =
      let vx = bx - ax
          vy = by - ay
          l2 = vx * vx + vy * vy
          t  = if l2 > 0 then max 0 (min 1 (((cx - ax) * vx + (cy - ay) * vy) / l2)) else 0
          dx = ax + t * vx - cx
          dy = ay + t * vy - cy
      in sqrt (dx * dx + dy * dy)
