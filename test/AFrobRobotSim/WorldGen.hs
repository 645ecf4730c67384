-- | Random worlds for the simulator's specs: squares of walls and blocks,
-- the arena "AFrobRobotSim.Arena" makes of them, and robots, balls, wheel
-- commands and time steps to put in them; and what the specs' reference
-- versions share.
module AFrobRobotSim.WorldGen
  ( World (..)
  , genWorld
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
  ) where

import           Test.QuickCheck

import           AFRP.Geometry
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Balls   (Ball (..))
import           AFrobRobotSim.Physics
import           AFrobRobotSim.Shapes  (Box (..))
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
