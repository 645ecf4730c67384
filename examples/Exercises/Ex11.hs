-- |
-- Module      : Exercises.Ex11
-- Description : Exercise 11 of the notes: visit a list of points in turn.
--
-- \"Define a controller that takes a list of points and causes the robot
-- to move to each point successively in turn.\"
--
-- Each leg is 'rcMoveTo' towards one point beside 'arrivedAt' (from
-- exercise 9); when it fires, 'switch' starts the leg to the next point,
-- and after the last point the robot stops with 'rcStop'. The legs are
-- chained with a right fold, so the controller for the whole tour is
-- built lazily, one leg at a time (the list may even be infinite).
module Exercises.Ex11
  ( rcVisit
  , tourA
  , tourB
  , ex11World
  , examples
  ) where

import           AFrob
import           AFrobRobotSim
import           Examples.Types
import           Exercises.Ex09 (arrivedAt)
import           Paper.Section3 (rcMoveTo, rcStop)

-- | @rcVisit vd eps ps@: drive to each point of @ps@ in turn with
-- 'rcMoveTo' @vd@, counting a point as reached within @eps@ metres; stop
-- after the last one.
rcVisit :: Velocity -> Distance -> [Position2] -> SimbotController
rcVisit vd eps ps rps = foldr leg (rcStop rps) ps
  where
    leg p next = switch (rcMoveTo vd p rps &&& arrivedAt eps p) (\() -> next)

-- | The SimbotA's tour: the corners of a 4 m square, anticlockwise.
tourA :: [Position2]
tourA = [Point2 (-1) (-3), Point2 3 (-3), Point2 3 1, Point2 (-1) 1]

-- | The SimbotB's tour: a zig-zag through the upper part of the world and
-- back.
tourB :: [Position2]
tourB = [Point2 (-3) 3.5, Point2 (-1.5) 2, Point2 0 3.5, Point2 1.5 2, Point2 3 3.5, Point2 (-3.8) 2.5]

-- | The SimbotA in the lower left corner, the SimbotB in the upper left
-- one; their tours do not cross.
ex11World :: WorldTemplate
ex11World =
  [OTSimbotA 1 (Point2 (-3.5) (-4)) 0, OTSimbotB 1 (Point2 (-4.2) 4.2) 0]

examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex11"
      , exDescription = "visit a list of points in turn (rcMoveTo legs chained by switches), then stop"
      , exWorld       = ex11World
      , exControllerA = rcVisit 0.6 0.2 tourA
      , exControllerB = rcVisit 1.2 0.2 tourB
      , exSeconds     = 50
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]
