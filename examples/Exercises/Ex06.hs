{-# LANGUAGE Arrows #-}
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
--
-- @ex6-robot@ shows the exercise on a simbot: 'velDriver' drives at a
-- quarter of @vel 0@ in m/s, so each press of @+@ (scripted with
-- @--keys@, by default at 1, 3 and 5 s) visibly speeds it up, and prints
-- a line.
module Exercises.Ex06
  ( vel
  , velDriver
  , examples
  ) where

import           Data.List       (zip5)
import           Text.Printf     (printf)

import           AFrob
import           AFrobRobotSim   (ObjectTemplate (..), SimbotController, SimbotInput, noReferee)

import           Examples.Types  (Example (..))
import qualified Paper.Section2  as S2
import           Paper.Section2  (formatTable, incrVelEvs, runEvery, scriptedInput, showD, showE)

-- | A velocity that starts at @v0@ and grows by 1 at every 'incrVelEvs'
-- event, from the sample after the event on (at the event's instant it is
-- still the old velocity): at every sample @v0@ plus the number of events
-- strictly before it, as the notes' @vel@.
vel :: Velocity -> SF SimbotInput Velocity
vel v0 = (constant v0 &&& incrVelEvs) `dSwitch` \() -> vel (v0 + 1)

-- | A simbot driving straight on at a quarter of @vel 0@ (m/s), at most
-- its maximum wheel speed: at rest until the first @+@, then 0.25 m/s
-- faster from the sample after each press, with a console line at each
-- press (at its instant).
velDriver :: SimbotController
velDriver rps = proc sbi -> do
  v <- vel 0      -< sbi
  e <- incrVelEvs -< sbi
  t <- localTime  -< ()
  let speed = min (rpWSMax rps) (0.25 * v)
      next  = min (rpWSMax rps) (0.25 * (v + 1))
  returnA -< mrFinalize (ddVelDiff speed speed
               `mrMerge` tcoPrintMessage (e `tag` printf "t = %.2f s: + pressed, speed %.2f m/s from now on" t next))

-- | The report, and the exercise driving a simbot.
examples :: [Example]
examples =
  [ SignalExample "ex6"
      "Exercise 6: vel with dSwitch and without rec, beside the notes' vel"
      report
  , RobotExample
      { exName        = "ex6-robot"
      , exDescription = "Exercise 6 on a simbot: each + key press (--keys) adds 0.25 m/s"
      , exWorld       = [OTSimbotA 1 (Point2 (-4.5) 0) 0, OTVWall (Point2 4.6 0)]
      , exControllerA = velDriver
      , exControllerB = velDriver
      , exSeconds     = 12
      , exKeys        = [(1, '+'), (3, '+'), (5, '+')]
      , exReferee     = noReferee
      }
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
