{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Ex09
-- Description : Exercise 9 of the notes: rcMoveTo that stops at its target.
--
-- \"@rcMoveTo@ will behave a little bit funny once the simbot reaches its
-- destination, because a differential drive robot is not able to maneuver
-- well at slow velocities ... Modify @rcMove@ so that once it gets
-- reasonably close to its target, it stops (using @rcStop@).\"
--
-- 'rcMoveTo' runs beside an event source, 'arrivedAt', that fires as soon
-- as the odometry puts the robot within a given distance of the target;
-- 'switch' then hands over to 'rcStop', which brakes. Because 'rcMoveTo'
-- slows down on its last 2 m, the robot is already crawling when it
-- arrives, and stops within a few millimetres.
module Exercises.Ex09
  ( rcMoveToStop
  , arrivedAt
  , ex9World
  , examples
  ) where

import           AFrob
import           AFrobRobotSim
import           Examples.Types
import           Paper.Section3 (rcMoveTo, rcStop)

-- | @rcMoveToStop vd eps pd@: 'rcMoveTo' @vd pd@ until within @eps@ metres
-- of @pd@, then 'rcStop'.
rcMoveToStop :: Velocity -> Distance -> Position2 -> SimbotController
rcMoveToStop vd eps pd rps =
  switch (rcMoveTo vd pd rps &&& arrivedAt eps pd) (\() -> rcStop rps)

-- | An event when the robot's odometry position comes within @eps@ of the
-- point (at time 0 if it starts there).
arrivedAt :: HasOdometry i => Distance -> Position2 -> SF i (Event ())
arrivedAt eps p = proc i -> do
  iEdge False -< norm (p .-. odometryPosition i) < eps

-- | A SimbotA and a SimbotB heading for targets marked by a block just
-- north of each.
ex9World :: WorldTemplate
ex9World =
  [ OTSimbotA 1 (Point2 (-4) (-4)) 0, OTSimbotB 1 (Point2 4 (-4)) (pi / 2)
  , OTBlock (Point2 (-1) 3.2), OTBlock (Point2 2 2.2) ]

examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex9"
      , exDescription = "rcMoveTo that brakes with rcStop once within 10 cm of its target"
      , exWorld       = ex9World
      , exControllerA = rcMoveToStop 0.6 0.1 (Point2 (-1) 2)
      , exControllerB = rcMoveToStop 1.2 0.1 (Point2 2 1)
      , exSeconds     = 25
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]
