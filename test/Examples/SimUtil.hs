-- | Helpers shared by the example specs: running an example's world in the
-- pure simulator and reading robots out of its snapshots.
module Examples.SimUtil
  ( runWorld
  , runExample
  , at
  , robot
  , robotA
  , robotB
  , xy
  , dist
  , near
  ) where

import           AFrob          hiding (forAll)
import           AFrobRobotSim
import           Examples.Types

-- | The first @secs@ seconds of a world's run at time step @dt@.
runWorld :: DTime -> Double -> WorldTemplate -> SimbotController -> SimbotController -> [WorldState]
runWorld dt secs world rcA rcB = take (round (secs / dt) + 1) (simulate dt world rcA rcB)

-- | The first @secs@ seconds of an example's run.
runExample :: DTime -> Double -> Example -> [WorldState]
runExample dt secs e = runWorld dt secs (exWorld e) (exControllerA e) (exControllerB e)

-- | The snapshot at time @t@ of a run at time step @dt@.
at :: DTime -> Double -> [WorldState] -> WorldState
at dt t run = run !! round (t / dt)

-- | A robot of a snapshot by type and id.
robot :: String -> RobotId -> WorldState -> RobotState
robot ty i s = case [ r | r <- wsRobots s, robotType r == ty, robotId r == i ] of
  [r] -> r
  _   -> error ("no robot " ++ ty ++ " " ++ show i)

-- | SimbotA 1 and SimbotB 1.
robotA, robotB :: WorldState -> RobotState
robotA = robot "SimbotA" 1
robotB = robot "SimbotB" 1

-- | A robot's position as a pair.
xy :: RobotState -> (Double, Double)
xy r = let Point2 x y = robotPos r in (x, y)

-- | The distance between two points.
dist :: Position2 -> Position2 -> Double
dist p q = norm (p .-. q)

-- | Within a tolerance.
near :: Double -> Double -> Double -> Bool
near tol a b = abs (a - b) <= tol
