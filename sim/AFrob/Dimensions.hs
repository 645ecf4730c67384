-- |
-- Module      : AFrob.Dimensions
-- Description : Physical quantities of the robot vocabulary, as type synonyms.
--
-- The names under which AFrob talks about physical quantities. They are
-- plain synonyms (for 'Double' unless said otherwise), so they document a
-- signature without costing any conversions; the type checker does /not/
-- tell a 'Velocity' from a 'Distance'.
--
-- Units are SI (metres, seconds, radians) with one exception: a 'Bearing'
-- is in compass degrees. 2-D quantities are expressed in the world's
-- Cartesian frame: x grows to the east, y to the north, and angles that are
-- not bearings grow counter-clockwise from the positive x axis. See
-- "AFrob.Angle" for the normalised ranges of the three angle types and the
-- conversions between them.
module AFrob.Dimensions
  ( -- * Linear quantities
    Length
  , Distance
  , Position
  , Velocity
  , Speed
  , Acceleration
    -- * Angular quantities
  , Angle
  , Heading
  , Bearing
  , RotVel
  , RotAcc
    -- * 2-D quantities
  , Position2
  , Velocity2
  , Distance2
    -- * Robot identification
  , RobotType
  , RobotId
  ) where

import AFRP.Geometry (Point2, Vector2)

-- | A length, in metres (m), such as the size of a robot or of an
-- obstacle. Non-negative.
type Length = Double

-- | A distance between two places or objects, in metres (m). Non-negative
-- when it is a measured distance (a range finder reading, say).
type Distance = Double

-- | One coordinate of a position in the world, in metres (m).
type Position = Double

-- | A signed velocity along a direction, in metres per second (m\/s):
-- positive forwards, negative backwards (for a wheel, the ground speed of
-- its rim).
type Velocity = Double

-- | The magnitude of a velocity, in metres per second (m\/s). Non-negative.
type Speed = Double

-- | A translational acceleration, in metres per second squared (m\/s²).
type Acceleration = Double

-- | A /relative/ angle, in radians: the difference between two directions,
-- or a direction measured from the robot's own heading. Positive is
-- counter-clockwise (to the left). Normalised range [-pi, pi) (see
-- 'AFrob.Angle.normalizeAngle').
type Angle = Double

-- | An /absolute/ direction in radians, in the Cartesian convention: 0 is
-- the positive x axis (east), pi\/2 the positive y axis (north), growing
-- counter-clockwise. Normalised range [-pi, pi) (see
-- 'AFrob.Angle.normalizeHeading').
type Heading = Double

-- | An /absolute/ direction in compass degrees: 0 is north (the positive y
-- axis), 90 east (the positive x axis), growing clockwise. Normalised range
-- [0, 360) (see 'AFrob.Angle.normalizeBearing').
type Bearing = Double

-- | A rotational velocity, in radians per second (rad\/s). Positive is
-- counter-clockwise.
type RotVel = Double

-- | A rotational acceleration, in radians per second squared (rad\/s²).
-- Positive is counter-clockwise.
type RotAcc = Double

-- | A position in the world: (x, y) in metres, x east, y north.
type Position2 = Point2 Position

-- | A velocity in the plane: (x, y) components in metres per second.
type Velocity2 = Vector2 Velocity

-- | A displacement in the plane: (x, y) components in metres.
type Distance2 = Vector2 Distance

-- | The kind of a robot, by name, e.g. @\"SimbotA\"@ or @\"SimbotB\"@ for
-- the simulator's two simbot types.
type RobotType = String

-- | The identity of a robot: a number chosen by whoever places the robot
-- in the world. Robots that share a controller can branch on it.
type RobotId = Int
