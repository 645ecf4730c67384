-- | Random worlds for the simulator's specs: squares of walls and blocks,
-- and the arena "AFrobRobotSim.Arena" makes of them.
module AFrobRobotSim.WorldGen
  ( World (..)
  , genWorld
  , arenaFor
  , halfSide
  ) where

import           Test.QuickCheck

import           AFRP.Geometry
import           AFrobRobotSim.Physics
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
