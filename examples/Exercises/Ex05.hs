{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Ex05
-- Description : Exercise 5: an alarm when the simbot has travelled more
--               than d metres, or got stuck.
--
-- Exercise 5 of the notes: given the scalar velocity of a simbot, define
-- an alarm that generates an event when either the simbot has travelled
-- more than @d@ metres, or it has got stuck.
--
-- The distance travelled is the 'integral' of the /speed/, the absolute
-- value of the velocity: reversing is travelling too, and the distance
-- never decreases, so it exceeds @d@ at one instant at most. The alarm is
-- the merge of an event at that instant and the 'rsStuck' events:
--
-- * one event at the first sample where the distance travelled is more
--   than @d@ (never again afterwards);
-- * one event at every sample where the simbot gets stuck;
--
-- whichever comes first is the first alarm ('firstAlarm' keeps only that
-- one). The distance is 'integral''s left rectangle rule: at a sample it
-- counts the speeds up to the previous sample.
--
-- The signal functions work for any robot with a status ('HasRobotStatus'),
-- not only the simbot; the examples use the simbot's forward velocity
-- estimated from its odometry ('forwardVelSF').
module Exercises.Ex05
  ( AlarmCause (..)
  , travelled
  , alarmCause
  , alarm
  , firstAlarm
  , examples
  ) where

import           Data.List       (zip5)

import           AFrob
import           AFrobRobotSim

import           Examples.Types  (Example (..))
import           Paper.Section2  (formatTable, forwardVelSF, runEvery, scriptedInput, showD, showE)

-- | Why the alarm went off.
data AlarmCause
  = TravelledFar  -- ^ the distance travelled has just become more than @d@
  | GotStuck      -- ^ the robot has just got stuck ('rsStuck')
  deriving (Eq, Show)

-- | The distance travelled since time 0, given the velocity: the
-- 'integral' of its absolute value. 0 at time 0, never decreasing.
travelled :: SF i Velocity -> SF i Distance
travelled v = v >>> arr abs >>> integral

-- | @alarmCause d v@, for the velocity @v@: an event 'TravelledFar' at the
-- first sample where the distance 'travelled' is more than @d@ (at time 0
-- if @d@ is negative), and an event 'GotStuck' at every 'rsStuck' event;
-- 'TravelledFar' when both happen at the same sample.
alarmCause :: HasRobotStatus i => Distance -> SF i Velocity -> SF i (Event AlarmCause)
alarmCause d v = proc inp -> do
  dist  <- travelled v -< inp
  far   <- iEdge False -< dist > d
  stuck <- rsStuck     -< inp
  returnA -< lMerge (far `tag` TravelledFar) (stuck `tag` GotStuck)

-- | The alarm of the exercise: an event whenever 'alarmCause' has one
-- (once when the robot has travelled more than @d@ metres, and whenever
-- it gets stuck).
alarm :: HasRobotStatus i => Distance -> SF i Velocity -> SF i (Event ())
alarm d v = alarmCause d v >>> arr (`tag` ())

-- | Only the first alarm, with its cause: travelled too far or stuck,
-- whichever happens first.
firstAlarm :: HasRobotStatus i => Distance -> SF i Velocity -> SF i (Event AlarmCause)
firstAlarm d v = alarmCause d v >>> once

-- | A table of the alarm on a scripted run, and two simbots that stop at
-- their first alarm.
examples :: [Example]
examples =
  [ SignalExample "ex5"
      "Exercise 5: an alarm after 1 m travelled, or when stuck"
      report
  , RobotExample
      { exName        = "ex5-robot"
      , exDescription = "Exercise 5: two simbots brake at their first alarm: one after 2 m, one at a wall"
      , exWorld       = [ OTSimbotA 1 (Point2 (-4) 2) 0
                        , OTSimbotA 2 (Point2 (-4) (-2)) 0
                        , OTVWall (Point2 (-3) (-2))
                        ]
      , exControllerA = stopAtAlarm
      , exControllerB = stopAtAlarm
      , exSeconds     = 15
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]

-- A simbot driving along the x axis at 0.5 m/s, backing up at 0.5 m/s
-- from t = 2 s until it gets stuck at t = 3.5 s, and driving forwards
-- again from t = 4.25 s (free from t = 4.5 s), sampled every 0.25 s:
-- positions and stuck flags. (Steps of 0.125 m keep the sums exact.)
script :: [(Double, Bool)]
script = zip (scanl (+) 0 (map step (drop 1 times))) [ t >= 3.5 && t < 4.5 | t <- times ]
  where
    times = take 23 [ fromIntegral n * 0.25 | n <- [0 :: Int ..] ] :: [Time]
    step t | t <= 2    = 0.125
           | t <= 3.5  = -0.125
           | t <= 4.25 = 0
           | otherwise = 0.125

report :: String
report =
  "alarmCause 1 forwardVelSF on a simbot driving at 0.5 m/s, backing up from\n"
  ++ "t = 2 s until it gets stuck at t = 3.5 s, and driving on at t = 4.25 s, sampled\n"
  ++ "every 0.25 s: one alarm when the distance travelled (forwards and backwards)\n"
  ++ "becomes more than 1 m, one when stuck.\n\n"
  ++ formatTable ["t", "x", "stuck", "velocity", "travelled", "alarmCause 1"]
       [ [showD t, showD x, show s, showD u, showD d, showE e]
       | (t, (x, s), u, d, e) <- zip5 [ fromIntegral n * 0.25 | n <- [0 :: Int ..] ] script
                                      (run forwardVelSF) (run (travelled forwardVelSF))
                                      (run (alarmCause 1 forwardVelSF)) ]
  where
    run sf = runEvery 0.25 sf [ scriptedInput (Point2 x 0) 0 s Nothing | (x, s) <- script ]

-- Drive straight at 0.4 m/s; brake for good at the first alarm of
-- firstAlarm 2, saying why.
stopAtAlarm :: SimbotController
stopAtAlarm _ = (drive &&& firstAlarm 2 forwardVelSF) `switch` stop
  where
    drive = constant (mrFinalize (ddVelDiff 0.4 0.4))
    stop cause = (constant ddBrake &&& now (message cause))
                   >>> arr (\(b, m) -> mrFinalize (b `mrMerge` tcoPrintMessage m))
    message TravelledFar = "travelled more than 2 m: braking"
    message GotStuck     = "stuck: braking"
