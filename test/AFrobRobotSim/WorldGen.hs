-- | Random worlds for the simulator's specs: squares of walls and blocks,
-- the arena "AFrobRobotSim.Arena" makes of them, and robots, balls, wheel
-- commands and time steps to put in them.
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
  ) where

import           Test.QuickCheck

import           AFRP.Geometry
import           AFrobRobotSim.Balls   (Ball (..))
import           AFrobRobotSim.Physics
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

-- | Any wheel command, some beyond the wheels' limits.
genCommand :: Gen DriveCommand
genCommand = oneof
  [ pure DriveBrake
  , DriveWheels <$> choose (-3, 3) <*> choose (-3, 3)
  , DriveTR <$> choose (-3, 3) <*> choose (-8, 8)
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
