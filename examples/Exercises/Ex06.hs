-- |
-- Module      : Exercises.Ex06
-- Description : Exercise 6: the notes' vel with dSwitch and without rec.
--
-- Exercise 6 of the notes: redefine @vel@ ("Paper.Section2", a velocity
-- incremented at every 'incrVelEvs' event) using 'dSwitch' instead of
-- 'drSwitch', and without the @rec@ keyword, by defining @vel@ itself
-- recursively instead of the velocity signal.
--
-- At an event, 'dSwitch' still outputs the old velocity and starts
-- @vel (v0 + 1)@ at that instant, whose output is used from the next
-- sample on: exactly the timing of the notes' 'drSwitch'. The new
-- 'incrVelEvs' starts afresh at the instant of the key press that caused
-- the switch and so does not see that press again (see 'incrVelEvs'),
-- which makes the recursion well founded and the two definitions equal.
module Exercises.Ex06
  ( vel
  , examples
  ) where

import           Data.List       (zip5)

import           AFrob
import           AFrobRobotSim   (SimbotInput)

import           Examples.Types  (Example (..))
import qualified Paper.Section2  as S2
import           Paper.Section2  (formatTable, incrVelEvs, runEvery, scriptedInput, showD, showE)

-- | A velocity that starts at @v0@ and grows by 1 at every 'incrVelEvs'
-- event, from the sample after the event on (at the event's instant it is
-- still the old velocity): at every sample @v0@ plus the number of events
-- strictly before it, as the notes' @vel@.
vel :: Velocity -> SF SimbotInput Velocity
vel v0 = (constant v0 &&& incrVelEvs) `dSwitch` \() -> vel (v0 + 1)

-- | One report: both definitions on scripted key presses.
examples :: [Example]
examples =
  [ SignalExample "ex6"
      "Exercise 6: vel with dSwitch and without rec, beside the notes' vel"
      report
  ]

report :: String
report =
  "vel 0 (dSwitch, recursive) and the notes' vel 0 (rec, drSwitch) on scripted keys,\n"
  ++ "sampled every 0.5 s.\n\n"
  ++ formatTable ["t", "key", "incrVelEvs", "vel 0 (ex6)", "vel 0 (notes)"]
       [ [showD t, maybe "-" (: []) k, showE e, showD a, showD b]
       | (t, k, e, a, b) <- zip5 [ fromIntegral n * 0.5 | n <- [0 :: Int ..] ] keys
                                 (run incrVelEvs) (run (vel 0)) (run (S2.vel 0)) ]
  where
    keys  = [Nothing, Just '+', Nothing, Just '+', Just '+', Nothing, Just '+', Just 'x', Just '+', Nothing]
    run s = runEvery 0.5 s [ scriptedInput origin 0 False k | k <- keys ]
