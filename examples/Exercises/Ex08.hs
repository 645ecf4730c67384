{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Ex08
-- Description : Exercise 8 of the notes: rcReverse with a snapshot of the
--               velocity.
--
-- \"Write a version of @rcReverse@ that, instead of knowing in advance what
-- its velocity is, takes a snapshot of the velocity, as described in
-- Sec. 2.7, at the moment the stuck event happens, and then negates this
-- value to continue.\"
--
-- The velocity is a signal, @v@, defined recursively exactly like @vel@ in
-- section 2.7: a 'drSwitch' whose switching event is the stuck event
-- tagged with the signal function to switch into, @constant (negate v)@.
-- Because the switch is delayed, @v@ at the moment of the event is still
-- the old velocity, and that is the value the snapshot captures. The
-- recurring switch negates it at every stuck event, so the robot keeps
-- bouncing. The controller is given only how to start (any velocity
-- signal, not necessarily constant); after the first bump it drives at the
-- negation of whatever velocity it had then.
module Exercises.Ex08
  ( rcReverseSnap
  , rampUp
  , ex8World
  , examples
  ) where

import           AFrob
import           AFrobRobotSim
import           Examples.Types

-- | @rcReverseSnap v0@ drives straight at the velocity signal @v0@ until
-- it gets stuck; at every stuck event it takes a snapshot of its current
-- velocity, negates it and goes on at that constant velocity, saying
-- \"Ouch!!\".
rcReverseSnap :: SF SimbotInput Velocity -> SimbotController
rcReverseSnap v0 _ = proc sbi -> do
  rec stuckE <- rsStuck -< sbi
      v      <- drSwitch v0 -< (sbi, stuckE `tag` constant (negate v))
  let mr = ddVelDiff v v `mrMerge` tcoPrintMessage (tag stuckE "Ouch!!")
  returnA -< mrFinalize mr

-- | @rampUp a vMax@: a velocity that starts at 0 and grows at @a@ m/s^2 up
-- to @vMax@. Started with it, 'rcReverseSnap' cannot know its speed at the
-- first bump in advance.
rampUp :: Acceleration -> Velocity -> SF a Velocity
rampUp a vMax = time >>> arr (\t -> min vMax (a * t))

-- | Two lanes between pairs of walls 6 m apart: a SimbotA starting at a
-- constant 0.5 m/s and a SimbotB that speeds up (0.2 m/s^2, up to
-- 1.5 m/s) until its first bump.
ex8World :: WorldTemplate
ex8World =
  [OTSimbotA 1 (Point2 0 (-1.5)) 0, OTSimbotB 1 (Point2 (-2) 1.5) 0]
  ++ [ OTVWall (Point2 x y) | x <- [-3, 3], y <- [-1.5, 1.5] ]
  ++ [ OTHWall (Point2 x 0) | x <- [-2, -1 .. 2] ]

examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex8"
      , exDescription = "rcReverse with a snapshot of its velocity: bounce back at the negated velocity it had at each bump"
      , exWorld       = ex8World
      , exControllerA = rcReverseSnap (constant 0.5)
      , exControllerB = rcReverseSnap (rampUp 0.2 1.5)
      , exSeconds     = 40
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]
