{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Ex12
-- Description : Exercise 12 of the notes: a wall follower that takes the
--               corners of a maze.
--
-- \"Enhance the wall-follower controller so that it can make left and
-- right turns in a maze constructed only of horizontal and vertical walls.
-- Specifically:
--
-- 1. If the simbot sees a wall directly in front of itself, it should slow
--    down as it approaches the wall, stopping at distance d from the wall.
--    Then it should turn right and continue following the wall which
--    should now be on its left. (This is an inside-corner right turn.)
--
-- 2. If the simbot loses track of the wall on its left, it continues
--    straight ahead for a distance d, turns left, goes straight for
--    distance d again, and then follows the wall which should again be on
--    its left. (This is an outside-corner left turn.)
--
-- Test your controller in an appropriately designed world template.\"
--
-- = Design
--
-- The controller is a small state machine. Each mode is a signal function
-- producing the robot's output together with an event that says the mode
-- is over; the event carries what the next mode needs to know (a snapshot
-- of the robot's pose, and for the follower which kind of corner it met),
-- and 'switch' starts the next mode afresh:
--
-- @
--            wall ahead at d                        turned
--  follow ------------------> turn right 90 deg ---------> follow
--     |
--     | wall on the left lost
--     v
--  straight d+r --> turn left 90 deg --> straight d+r+0.15 --> follow
-- @
--
-- * 'followLeft' is the notes' PD wall follower ('rcFollowLeftWall':
--   @omega = kp (r - d) + kd dr/dt@, @kd = 5@, @kp = v kd^2 / 4@, limited
--   to 0.2 rad/s) with two additions: the forward speed is capped by a
--   braking profile, @sqrt (2 a (front - d))@ with half the robot's maximum
--   deceleration, so that it comes to rest at distance @d@ from a wall
--   ahead; and it ends with an event at an inside corner (front reading
--   down to @d@) or at an outside corner (left reading more than 0.5 m
--   beyond @d@).
--
-- * The turns are in place, to an exact multiple of 90 degrees
--   ('axisHeading' rounds the odometry heading to the nearest axis), so
--   small heading errors do not accumulate from corner to corner: the maze
--   is made only of horizontal and vertical walls.
--
-- * The straight legs hold the axis heading and brake to a stop at the
--   end. The range finder measures from the robot's edge, but the robot
--   turns about its centre, so the legs are measured to the centre: the
--   first is @d + r@ (r the robot's radius), which leaves the robot's edge
--   @d@ from the face of the wall round the corner; the second is 0.15 m
--   longer, to get the left range finder past the end of the wall it
--   turned round (walls are 0.1 m thick).
module Exercises.Ex12
  ( -- * The maze follower
    rcMazeFollower
    -- * Its modes
  , Corner (..)
  , followLeft
  , driveStraight
  , turnTo
    -- * Helpers
  , Pose
  , pose
  , axisHeading
  , brakingSpeed
  , andThen
    -- * The maze
  , mazeWalls
  , mazeWorld
  , examples
  ) where

import           AFrob hiding (andThen)  -- this exercise names its own (a switch)
import           AFrobRobotSim
import           Examples.Types

-- | Where the robot is and which way it faces, by its odometry.
type Pose = (Position2, Heading)

-- | The odometry pose of an input sample.
pose :: SimbotInput -> Pose
pose sbi = (odometryPosition sbi, odometryHeading sbi)

-- | The kinds of corner that end a stretch of wall following.
data Corner
  = InsideCorner   -- ^ a wall ahead: turn right
  | OutsideCorner  -- ^ the wall on the left ended: go round it to the left
  deriving (Eq, Show)

-- | Run a mode until its event, then switch into the continuation (time
-- starts afresh there).
andThen :: SF a (b, Event c) -> (c -> SF a b) -> SF a b
andThen = switch

-- | The heading rounded to the nearest multiple of pi/2.
axisHeading :: Heading -> Heading
axisHeading h = normalizeAngle (fromIntegral (round (h / (pi / 2)) :: Int) * (pi / 2))

-- | The highest speed from which the robot can still stop within the gap,
-- braking at half its maximum acceleration, but at least a crawl of
-- 0.05 m/s (so that the robot does arrive).
brakingSpeed :: SimbotProperties -> Distance -> Velocity
brakingSpeed rps gap = max 0.05 (sqrt (rpAccMax rps * max 0 gap))

-- | The radius of a simbot's body.
radius :: Length
radius = simbotDiameter / 2

-- | @followLeft v d@: follow a wall on the left at distance @d@ (the left
-- range reading) at speed @v@, braking for a wall ahead; an event with the
-- corner met and the pose there.
followLeft :: Velocity -> Distance -> SimbotProperties
           -> SF SimbotInput (SimbotOutput, Event (Corner, Pose))
followLeft v d rps = proc sbi -> do
  let r = rfLeft sbi
      f = rfFront sbi
  dr <- derivative -< r
  let v'    = min v (brakingSpeed rps (f - d))
      kd    = 5
      kp    = v' * kd * kd / 4
      omega = kp * (r - d) + kd * dr
  inside  <- iEdge False -< f <= d + 0.01
  outside <- iEdge False -< r > d + 0.5
  let corner = (inside `tag` InsideCorner) `lMerge` (outside `tag` OutsideCorner)
  returnA -< (mrFinalize (ddVelTR v' (max (-0.2) (min 0.2 omega))), fmap (\c -> (c, pose sbi)) corner)

-- | @driveStraight v s (p0, h)@: drive at up to @v@ along the heading @h@
-- until @s@ metres past @p0@ (measured along @h@), braking to a stop there;
-- an event with the pose at the end.
driveStraight :: Velocity -> Distance -> Pose -> SimbotProperties
              -> SF SimbotInput (SimbotOutput, Event Pose)
driveStraight v s (p0, h) rps = proc sbi -> do
  let travelled = (odometryPosition sbi .-. p0) `dot` vector2Polar 1 h
      rest      = s - travelled
      he        = normalizeAngle (h - odometryHeading sbi)
  done <- iEdge False -< rest <= 0
  returnA -< (mrFinalize (ddVelTR (min v (brakingSpeed rps rest)) (2 * he)), done `tag` pose sbi)

-- | @turnTo h@: turn in place to the heading @h@ (within 0.01 rad); an
-- event with the pose then.
turnTo :: Heading -> SimbotProperties -> SF SimbotInput (SimbotOutput, Event Pose)
turnTo h rps = proc sbi -> do
  let he   = normalizeAngle (h - odometryHeading sbi)
      wMax = rpWSMax rps / rpDiameter rps    -- half the fastest turn in place
      w    = signum he * max 0.1 (min wMax (3 * abs he))
  done <- iEdge False -< abs he < 0.01
  returnA -< (mrFinalize (ddVelTR 0 w), done `tag` pose sbi)

-- | @rcMazeFollower v d@: follow the wall on the left at distance @d@ and
-- speed @v@ through a maze of horizontal and vertical walls, turning right
-- at inside corners and left round outside corners. The robot should start
-- with a wall on its left, about @d@ away.
rcMazeFollower :: Velocity -> Distance -> SimbotController
rcMazeFollower v d rps = following
  where
    following = followLeft v d rps `andThen` corner
    corner (InsideCorner, (_, h)) =
      turnTo (axisHeading h - pi / 2) rps `andThen` \_ ->
      following
    corner (OutsideCorner, (p, h)) =
      let h0 = axisHeading h
          h1 = normalizeAngle (h0 + pi / 2)
          leg = d + radius
      in driveStraight v leg (p, h0) rps `andThen` \_ ->
         turnTo h1 rps `andThen` \(p1, _) ->
         driveStraight v (leg + 0.15) (p1, h1) rps `andThen` \_ ->
         following

------------------------------------------------------------------------------
-- The maze

-- | The walls of the maze: a room with a corner cut out (the upper right)
-- and a 2 m square bump into it from the south wall, so that going round
-- it takes seven inside-corner right turns and three outside-corner left
-- turns. Its outline, clockwise:
--
-- @
-- (-4,4) ---------- (1,4)
--   |                 |
--   |               (1,1) ---------- (4,1)
--   |                                  |
--   |          (-1,-2) -- (1,-2)        |
--   |             |          |          |
-- (-4,-4) ---- (-1,-4)     (1,-4) --- (4,-4)
-- @
mazeWalls :: WorldTemplate
mazeWalls =
  vWall (-4) (-4) 4 ++ hWall 4 (-4) 1 ++ vWall 1 1 4 ++ hWall 1 1 4 ++ vWall 4 (-4) 1
  ++ hWall (-4) 1 4 ++ vWall 1 (-4) (-2) ++ hWall (-2) (-1) 1 ++ vWall (-1) (-4) (-2)
  ++ hWall (-4) (-4) (-1)
  where
    vWall x y0 y1 = [ OTVWall (Point2 x (y + 0.5)) | y <- [y0 .. y1 - 1] ]
    hWall y x0 x1 = [ OTHWall (Point2 (x + 0.5) y) | x <- [x0 .. x1 - 1] ]

-- | The maze with a SimbotB at the west wall, heading north, the wall on
-- its left 0.4 m away.
mazeWorld :: WorldTemplate
mazeWorld = OTSimbotB 1 (Point2 (-3.3) (-2)) (pi / 2) : mazeWalls

examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex12"
      , exDescription = "a wall follower for mazes: slows down and turns right at inside corners, goes round outside corners to the left"
      , exWorld       = mazeWorld
      , exControllerA = rcMazeFollower 0.3 0.4
      , exControllerB = rcMazeFollower 0.5 0.4
      , exSeconds     = 100
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]
