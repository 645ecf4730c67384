-- | @cabal run simbot [-- flags]@: the default world with demo controllers
-- from the notes. SimbotA 1 bounces between two walls ('rcReverse'),
-- SimbotA 2 follows a wall ('rcFollowLeftWall'), SimbotA 3 drives to a
-- point ('rcMoveTo'), and the SimbotBs align their headings ('rcAlign'),
-- backing off whenever they get stuck.
-- Every flag of 'runSim' applies (@--help@ lists them).
--
-- @simbot --replay-from RUN.jsonl --replay OUT.html@ simulates nothing: it
-- turns a run log (written with @--log@) into a replay page
-- ('AFrobRobotSim.Replay.CommandLine.replayFromMain': exit code 2 when it refuses
-- before writing, 1 when a write fails; @--help@ prints the usage, exit
-- code 0).
module Main (main) where

import           System.Environment (getArgs)

import           AFrob
import           AFrobRobotSim
import           AFrobRobotSim.Replay.CommandLine (replayFromMain)
import           Paper.Section3     (rcAlign, rcFollowLeftWall, rcMoveTo, rcReverse)

main :: IO ()
main = do
  args <- getArgs
  -- replay mode when --replay-from is a flag the simulation's command line
  -- does not take (not, say, the name of the --out folder)
  case parseSimArgs defaultSimOptions args of
    Left _ | "--replay-from" `elem` args -> replayFromMain args
    _                                    -> runSim Nothing demoA demoB

-- | The SimbotA demos, by id.
demoA :: SimbotController
demoA rps = case rpId rps of
  1 -> rcReverse 0.5 rps
  2 -> rcFollowLeftWall 0.3 0.25 rps
  _ -> rcMoveTo 0.6 (Point2 3 (-1)) rps

-- | The SimbotB demo: the notes' rcAlign among the other SimbotBs, with a
-- recovery: when stuck, back off while turning for 1.5 s, then align again
-- (a recursive 'switch', fresh each time).
demoB :: SimbotController
demoB rps = ((arr withNeighbours >>> rcAlign 0.4 rps) &&& rsStuck) `switch` const backOff
  where
    backOff = (constant (mrFinalize (ddVelTR (-0.3) 1.5)) &&& after 1.5 ()) `switch` const (demoB rps)
    -- rcAlign needs three neighbours in tracker range; when fewer are in
    -- sight, phantom neighbours far away due east stand in for the missing
    -- ones (a neighbour that does not move pulls towards the robot's own
    -- heading), so the robot keeps its course.
    withNeighbours sbi =
      let flock   = [ r | r@(ty, _, _, _) <- siRobots sbi, ty == "SimbotB" ]
          phantom = ("phantom", 0, normalizeAngle (negate (odometryHeading sbi)), 100)
      in sbi { siRobots = flock ++ replicate (3 - length flock) phantom }
