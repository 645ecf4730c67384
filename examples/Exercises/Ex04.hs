-- |
-- Module      : Exercises.Ex04
-- Description : Exercise 4: a wheel speed negated every time the simbot
--               gets stuck.
--
-- Exercise 4 of the notes: rather than set the wheel speed to zero when
-- the simbot gets stuck (the notes' @xspd@, "Paper.Section2"), negate it;
-- then define @xspd@ recursively, so that the speed is negated /every/
-- time the simbot gets stuck. Driven straight at that speed, a simbot
-- bounces back and forth between two walls ("ex4").
--
-- The recursion is through an immediate 'switch': at the instant of a
-- stuck event the output is already the negated speed. It is well founded
-- because the 'rsStuck' of the signal function switched in starts afresh
-- at that instant and, as for any simbot that is stuck at its time 0,
-- produces no event there; it fires again only when the simbot has come
-- free and got stuck again.
module Exercises.Ex04
  ( xspdNegated
  , xspd
  , bounceWorld
  , bounceController
  , examples
  ) where

import           Data.List       (zip4)

import           AFrob
import           AFrobRobotSim

import           Examples.Types  (Example (..))
import           Paper.Section2  (formatTable, runEvery, scriptedInput, showD, showE)

-- | The first part of the exercise: @v@ until the simbot gets stuck, @-v@
-- from the instant of that event on (later events change nothing).
xspdNegated :: Speed -> SF SimbotInput Speed
xspdNegated v = (constant v &&& rsStuck) `switch` \() -> constant (-v)

-- | The wheel speed negated at every 'rsStuck' event: @v@ until the first,
-- @-v@ from its instant until the second, @v@ again from the second, and
-- so on.
xspd :: Speed -> SF SimbotInput Speed
xspd v = (constant v &&& rsStuck) `switch` \() -> xspd (-v)

-- | Two walls, at x = -2 and x = 2, and between them a SimbotA facing the
-- right one.
bounceWorld :: WorldTemplate
bounceWorld = [OTVWall (Point2 (-2) 0), OTVWall (Point2 2 0), OTSimbotA 1 (Point2 0 0) 0]

-- | Drive straight ahead (both wheels) at @xspd 0.5@: back and forth
-- between the walls of 'bounceWorld', turning round each time it hits one.
bounceController :: SimbotController
bounceController _ = xspd 0.5 >>> arr (\s -> mrFinalize (ddVelDiff s s))

-- | The bouncing simbot, and a table of both answers on a scripted stuck
-- flag.
examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex4"
      , exDescription = "Exercise 4: a simbot bouncing between two walls, its speed negated at every stuck event"
      , exWorld       = bounceWorld
      , exControllerA = bounceController
      , exControllerB = bounceController
      , exSeconds     = 40
      , exKeys        = []
      , exReferee     = noReferee
      }
  , SignalExample "ex4-table"
      "Exercise 4: the negated and the recursive xspd 0.5 on a scripted stuck flag"
      report
  ]

report :: String
report =
  "xspdNegated 0.5 and the recursive xspd 0.5 on a scripted stuck flag, sampled\n"
  ++ "every 0.5 s: the first turns round once, the second at every rsStuck event.\n\n"
  ++ formatTable ["t", "stuck", "rsStuck", "xspdNegated 0.5", "xspd 0.5"]
       [ [showD t, show s, showE e, showD a, showD b]
       | ((t, s), e, a, b) <- zip4 (zip times stuck) (run rsStuck) (run (xspdNegated 0.5)) (run (xspd 0.5)) ]
  where
    stuck  = [False, False, True, True, False, False, True, False, True, True, False]
    times  = [ fromIntegral n * 0.5 | n <- [0 :: Int ..] ] :: [Time]
    run s  = runEvery 0.5 s [ scriptedInput origin 0 b Nothing | b <- stuck ]
