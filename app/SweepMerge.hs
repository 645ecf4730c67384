-- | @afrp-sweep-merge FILE...@: the table of a sweep's result lines (see
-- "AFrobRobotSim.Sweep"); @scripts/sweep-merge@ runs it.
module Main (main) where

import           AFrobRobotSim.Sweep (sweepMergeMain)

main :: IO ()
main = sweepMergeMain
