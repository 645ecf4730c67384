{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Ex13
-- Description : Exercise 13 of the notes: a robust, multi-mode wall
--               follower.
--
-- \"... the @rcFollowLeftWall@ controller is only useful once the robot is
-- close to being on track: i.e. at the proper distance from the wall and
-- at the proper heading. ... Designing a more robust wall follower is
-- tricky business, and is best treated as multi-mode system, where the
-- robot first seeks a wall, aligns itself parallel to the wall, and then
-- tries to follow it. Design such a controller.\"
--
-- = Design
--
-- Four modes, each ending with an event that carries what the next one
-- needs (a snapshot taken at the switch), chained with 'switch':
--
-- 1. /Seek/ ('seekWall'): drive straight ahead, on the heading the robot
--    had at the start, until the front range finder reads @d@ (the speed
--    is capped by a braking profile so that it stops there), a side one
--    reads @d@ or less, or the robot is stuck: a wall met at a glancing
--    angle is seen by a side ray, or touched, before the front ray reads
--    @d@ (the seek used to watch the front alone, and such a robot pushed
--    against the wall for the rest of the run).
--
-- 2. /Sweep/ ('sweepLeft'): turn in place through a full circle, watching
--    the left range finder. Its smallest reading is where the left ray was
--    perpendicular to the nearest wall; the sweep reports that heading and
--    that reading. (A full circle, rather than stopping at the first
--    minimum, makes it indifferent to the angle the wall was met at and to
--    corners: it always finds the nearest wall, also when the seek ended
--    with the robot touching it.)
--
-- 3. /Align/: turn back to that heading ('turnTo'); the wall is now on the
--    left, parallel. If its distance is not @d@ (it is less when the wall
--    was met at a slant), turn to face it, drive forwards or backwards
--    until the front reads @d@, and turn back.
--
-- 4. /Follow/: the maze wall follower of exercise 12
--    ('rcMazeFollower'), which also takes the room's corners.
module Exercises.Ex13
  ( rcRobustFollower
  , seekWall
  , approachFront
  , sweepLeft
  , ex13World
  , examples
  ) where

import           AFrob hiding (andThen)  -- Ex12 names its own (a switch)
import           AFrobRobotSim
import           Examples.Types
import           Exercises.Ex12 (andThen, brakingSpeed, pose, rcMazeFollower, turnTo)

-- | @rcRobustFollower v d@: seek a wall straight ahead, align with it (the
-- wall on the left, @d@ away), then follow it at speed @v@.
rcRobustFollower :: Velocity -> Distance -> SimbotController
rcRobustFollower v d rps =
  (constant (mrFinalize ddBrake) &&& (arr pose >>> snap)) `andThen` \(_, h0) ->
  seekWall v d h0 rps `andThen` \_ ->
  sweepLeft rps `andThen` \(h, r) ->
  turnTo h rps `andThen` \_ ->
  if abs (r - d) <= 0.03
    then follow
    else turnTo (h + pi / 2) rps `andThen` \_ ->
         approachFront v d (h + pi / 2) rps `andThen` \_ ->
         turnTo h rps `andThen` \_ ->
         follow
  where
    follow = rcMazeFollower v d rps

-- | @approachFront v d h@: hold the heading @h@ and drive forwards (or
-- backwards) at up to @v@ until the front range finder reads @d@ (within
-- 1 cm), braking to a stop; an event with the pose then.
approachFront :: Velocity -> Distance -> Heading -> SimbotProperties
              -> SF SimbotInput (SimbotOutput, Event (Position2, Heading))
approachFront v d h rps = proc sbi -> do
  let gap = rfFront sbi - d
      v'  = signum gap * min v (brakingSpeed rps (abs gap))
      he  = normalizeAngle (h - odometryHeading sbi)
  done <- iEdge False -< abs gap <= 0.01
  returnA -< (mrFinalize (ddVelTR v' (2 * he)), done `tag` pose sbi)

-- | @seekWall v d h@, the seek mode: hold the heading @h@ and drive at up
-- to @v@ until a wall is near: the front range finder reads @d@ (braking
-- to a stop there, as 'approachFront'), a side one reads @d@ or less (a
-- wall met at a glancing angle, which the front ray may never see before
-- the robot's side touches it), or the robot is stuck against something
-- (a corner or an obstacle that no ray sees); an event with the pose then.
seekWall :: Velocity -> Distance -> Heading -> SimbotProperties
         -> SF SimbotInput (SimbotOutput, Event (Position2, Heading))
seekWall v d h rps = proc sbi -> do
  (out, atFront) <- approachFront v d h rps -< sbi
  atSide         <- iEdge False -< min (rfLeft sbi) (rfRight sbi) <= d
  stuck          <- rsStuck -< sbi
  returnA -< (out, atFront `lMerge` ((atSide `lMerge` stuck) `tag` pose sbi))

-- What a sweep has seen so far: the heading at the previous sample, how
-- far it has turned (radians), the smallest left reading so far and the
-- heading it was seen at.
data Sweep = Sweep !(Maybe Heading) !Double !Distance !Heading

-- | Turn clockwise in place through a full circle at 1.2 rad/s; an event
-- with the heading at which the left range finder read least, and that
-- reading.
sweepLeft :: SimbotProperties -> SF SimbotInput (SimbotOutput, Event (Heading, Distance))
sweepLeft _ = proc sbi -> do
  sw <- scanS step (Sweep Nothing 0 (1 / 0) 0) -< (odometryHeading sbi, rfLeft sbi)
  let Sweep _ turned bestR bestH = sw
  done <- iEdge False -< turned >= 2 * pi
  returnA -< (mrFinalize (ddVelTR 0 (-1.2)), done `tag` (bestH, bestR))
  where
    step (Sweep prev turned bestR bestH) (h, r) =
      let turned' = turned + maybe 0 (\p -> abs (normalizeAngle (h - p))) prev
          (bestR', bestH') = if r < bestR then (r, h) else (bestR, bestH)
      in Sweep (Just h) turned' bestR' bestH'

-- A running fold over the input samples: the state after each one.
scanS :: (s -> a -> s) -> s -> SF a s
scanS f s0 = loopPre s0 (arr (\(a, s) -> let s' = f s a in (s', s')))

-- | An 8 m square room of walls with a SimbotA and a SimbotB in the
-- middle, more than 3 m (the range finder's reach) from every wall, facing
-- it at a slant.
ex13World :: WorldTemplate
ex13World =
  [OTSimbotA 1 (Point2 (-0.6) 0.2) 2.2, OTSimbotB 1 (Point2 0.6 (-0.2)) (-0.6)]
  ++ concat [ [ OTHWall (Point2 c (-4)), OTHWall (Point2 c 4)
              , OTVWall (Point2 (-4) c), OTVWall (Point2 4 c) ]
            | c <- [-3.5, -2.5 .. 3.5] ]

examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex13"
      , exDescription = "a multi-mode wall follower: seek a wall, sweep and align with it, then follow it round the room"
      , exWorld       = ex13World
      , exControllerA = rcRobustFollower 0.3 0.4
      , exControllerB = rcRobustFollower 0.5 0.4
      , exSeconds     = 80
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]
