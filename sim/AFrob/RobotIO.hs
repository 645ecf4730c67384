-- |
-- Module      : AFrob.RobotIO
-- Description : The robot input and output classes (Fig. 3 of the notes).
--
-- AFrob does not depend on any particular robot. A robot's sensors and
-- actuators are described by classes; a robot's input type (what its
-- controller reads at each sample) is an instance of the input classes for
-- the sensors it has, its output type (what the controller produces) an
-- instance of the output classes for its actuators, and its static
-- properties an instance of 'HasRobotProperties'. Controllers written
-- against the classes run on every robot that has the capabilities they
-- use.
--
-- The classes and their methods are those of Fig. 3 of the notes, with one
-- change taken from the notes' later text (\"Mass hysteria\"):
-- 'aotOtherRobots' also reports each robot's 'RobotId'.
--
-- Conventions: distances in metres, velocities in m\/s, angles in radians;
-- angles that locate something relative to the robot ('Angle') are
-- measured from the robot's own heading, counter-clockwise positive (left),
-- normalised into [-pi, pi) (see "AFrob.Angle").
--
-- The derived event sources ('rsStuck', 'tciKeyDown', ...) compare each
-- input sample with the previous one; each documents what it does at time 0.
module AFrob.RobotIO
  ( -- * Input classes
    -- ** Robot status
    HasRobotStatus (..)
  , BatteryStatus (..)
  , rsBattStatChanged
  , rsBattStatLow
  , rsBattStatCritical
  , rsStuck
    -- ** Odometry
  , HasOdometry (..)
    -- ** Range finders
  , HasRangeFinder (..)
  , rfFront
  , rfBack
  , rfLeft
  , rfRight
    -- ** Animate object tracker
  , HasAnimateObjectTracker (..)
    -- ** Textual console input
  , HasTextualConsoleInput (..)
  , tciNewKeyDown
  , tciKeyDown
    -- * Output classes
    -- ** Differential drive
  , HasDiffDrive (..)
    -- ** Text console output
  , HasTextConsoleOutput (..)
    -- * Robot properties
  , HasRobotProperties (..)
  ) where

import AFRP (Event, SF, arr, edge, edgeBy, filterE, tag, (>>>), (>>^))

import AFrob.Dimensions
import AFrob.MergeableRecord (MR, MergeableRecord)

------------------------------------------------------------------------------
-- Robot status

-- | Robots that report the state of their battery and whether they are
-- stuck.
class HasRobotStatus i where
  -- | The current battery status.
  rsBattStat :: i -> BatteryStatus
  -- | Whether the robot is currently stuck (blocked by an obstacle, its
  -- wheels unable to move it).
  rsIsStuck :: i -> Bool

-- | The charge of a robot's battery, from full to nearly empty; the 'Ord'
-- instance orders them that way ('BSHigh' < 'BSLow' < 'BSCritical').
data BatteryStatus
  = BSHigh      -- ^ Charged enough for normal operation.
  | BSLow       -- ^ Low: time to head for a charger.
  | BSCritical  -- ^ Nearly empty: the robot may stop at any moment.
  deriving (Eq, Ord, Show, Enum, Bounded)

-- | An event, carrying the new status, at every sample whose battery
-- status differs from the previous sample's. No event at time 0 (there is
-- no previous sample), whatever the status then.
rsBattStatChanged :: HasRobotStatus i => SF i (Event BatteryStatus)
rsBattStatChanged = arr (Just . rsBattStat) >>> edgeBy changed Nothing
  where
    changed (Just old) (Just new) | new /= old = Just new
    changed _          _                       = Nothing

-- | An event at every sample where the battery status /becomes/ 'BSLow'
-- (a 'rsBattStatChanged' event to 'BSLow', from 'BSHigh' or, after a
-- recharge, from 'BSCritical'). No event at time 0, even if the status is
-- 'BSLow' then.
rsBattStatLow :: HasRobotStatus i => SF i (Event ())
rsBattStatLow = rsBattStatChanged >>^ becomes BSLow

-- | An event at every sample where the battery status /becomes/
-- 'BSCritical'. No event at time 0, even if the status is 'BSCritical'
-- then.
rsBattStatCritical :: HasRobotStatus i => SF i (Event ())
rsBattStatCritical = rsBattStatChanged >>^ becomes BSCritical

becomes :: BatteryStatus -> Event BatteryStatus -> Event ()
becomes s e = filterE (== s) e `tag` ()

-- | An event at every sample where the robot becomes stuck: 'rsIsStuck' is
-- 'True' and was 'False' at the previous sample (@arr rsIsStuck >>> edge@).
-- At time 0 the robot counts as having been stuck before, so a robot that
-- is stuck at time 0 produces no event until it has come free and got
-- stuck again.
rsStuck :: HasRobotStatus i => SF i (Event ())
rsStuck = arr rsIsStuck >>> edge

------------------------------------------------------------------------------
-- Odometry

-- | Robots that know where they are and which way they face (the
-- simulator's odometry is perfect; a real robot's drifts).
class HasOdometry i where
  -- | The current position in the world, in metres.
  odometryPosition :: i -> Position2
  -- | The current heading, in radians (0 = positive x axis,
  -- counter-clockwise), normalised into [-pi, pi).
  odometryHeading :: i -> Heading

------------------------------------------------------------------------------
-- Range finders

-- | Robots that can measure the distance to the nearest obstacle in a
-- given direction.
class HasRangeFinder i where
  -- | @rfRange i a@: the distance, in metres, to the nearest object in
  -- direction @a@, measured from the robot's heading (counter-clockwise
  -- positive) and interpreted modulo 2*pi (so @pi@ and @-pi@ both mean
  -- straight back). At most 'rfMaxRange' (the reading when nothing is in
  -- range). A robot may only support some directions (the notes' simbots
  -- are queried at 0, pi\/2, pi and -pi\/2 only); see its documentation.
  -- The simulator's simbots read every direction: the four quarter turns
  -- exactly (their rays are cast once per sample, however often read), any
  -- other finite angle as the ray at heading + @a@, a sum of floats (from
  -- about 1e15 on it holds the heading only to a tenth of a radian or
  -- worse, so so large an angle is no direction to rely on). An angle that
  -- is NaN or infinite names no direction: the simbots read 'rfMaxRange'
  -- for it, as for nothing in range.
  rfRange :: i -> Angle -> Distance
  -- | The largest distance the range finder reports, in metres.
  rfMaxRange :: i -> Distance

-- | The range straight ahead: @rfRange i 0@.
rfFront :: HasRangeFinder i => i -> Distance
rfFront i = rfRange i 0

-- | The range straight back: @rfRange i pi@.
rfBack :: HasRangeFinder i => i -> Distance
rfBack i = rfRange i pi

-- | The range to the left (counter-clockwise from the heading):
-- @rfRange i (pi \/ 2)@.
rfLeft :: HasRangeFinder i => i -> Distance
rfLeft i = rfRange i (pi / 2)

-- | The range to the right (clockwise from the heading):
-- @rfRange i (-pi \/ 2)@.
rfRight :: HasRangeFinder i => i -> Distance
rfRight i = rfRange i (-pi / 2)

------------------------------------------------------------------------------
-- Animate object tracker

-- | Robots that can see the other robots and the balls in the world.
-- Each object is located by the 'Angle' under which the robot sees it,
-- relative to its own heading (counter-clockwise positive, normalised into
-- [-pi, pi)), and its 'Distance' in metres, centre to centre.
class HasAnimateObjectTracker i where
  -- | The other robots (never the robot itself): type, identity, angle and
  -- distance of each, in no particular order.
  aotOtherRobots :: i -> [(RobotType, RobotId, Angle, Distance)]
  -- | The balls: angle and distance of each, in no particular order.
  aotBalls :: i -> [(Angle, Distance)]

------------------------------------------------------------------------------
-- Textual console input

-- | Robots that can read keys typed on a console.
class HasTextualConsoleInput i where
  -- | The key currently pressed, if any.
  tciKey :: i -> Maybe Char

-- | @tciNewKeyDown k0@: an event carrying the key at every sample where
-- 'tciKey' changes to a @Just c@ different from the previous sample's
-- value (from 'Nothing', or from another key). Holding a key produces one
-- event, releasing it none. @k0@ is the value assumed for the sample
-- before time 0: there is an event at time 0 if the key then is a @Just c@
-- other than @k0@.
tciNewKeyDown :: HasTextualConsoleInput i => Maybe Char -> SF i (Event Char)
tciNewKeyDown k0 = arr tciKey >>> edgeBy newKey k0
  where
    newKey old new@(Just c) | new /= old = Just c
    newKey _   _                         = Nothing

-- | @tciNewKeyDown Nothing@: every key press, including one already
-- pressed at time 0 (an event then).
tciKeyDown :: HasTextualConsoleInput i => SF i (Event Char)
tciKeyDown = tciNewKeyDown Nothing

------------------------------------------------------------------------------
-- Output classes

-- | Robots driven by two independently powered wheels on a common axle
-- (differential drive). Each method is an update of the output record, to
-- be merged with others (@mrMerge@, see "AFrob.MergeableRecord"). By
-- convention an output in which no drive method was used brakes (the
-- output type's @mrDefault@ sets the drive as 'ddBrake' does). The robot
-- limits the wheel speeds to its 'rpWSMax' and their changes to its
-- 'rpAccMax'; a robot may limit them further (a simbot whose battery is
-- critical, 'BSCritical', drives at half its 'rpWSMax': see
-- "AFrobRobotSim.Physics").
class MergeableRecord o => HasDiffDrive o where
  -- | Brake both wheels: decelerate them towards standstill at the
  -- maximal acceleration ('rpAccMax').
  ddBrake :: MR o
  -- | @ddVelDiff vl vr@: set the left and the right wheel velocities, in
  -- m\/s (positive forwards). Equal velocities drive straight; @vr > vl@
  -- turns left (counter-clockwise).
  ddVelDiff :: Velocity -> Velocity -> MR o
  -- | @ddVelTR v w@: drive forwards at @v@ m\/s while turning at @w@ rad\/s
  -- (counter-clockwise positive). For wheel base @l@ ('rpDiameter') this
  -- means wheel velocities @(v - w*l\/2, v + w*l\/2)@ (left, right), which
  -- the instance computes.
  ddVelTR :: Velocity -> RotVel -> MR o

-- | Robots with a console they can print messages on.
class MergeableRecord o => HasTextConsoleOutput o where
  -- | Print the message at each occurrence of the event; no output when
  -- there is no occurrence. Messages /accumulate/ when updates are merged:
  -- @mrMerge (tcoPrintMessage e1) (tcoPrintMessage e2)@ prints both (when
  -- both occur), @e1@'s first.
  tcoPrintMessage :: Event String -> MR o

------------------------------------------------------------------------------
-- Robot properties

-- | The static properties of a robot, passed to its controller when it is
-- started.
class HasRobotProperties i where
  -- | The kind of robot, e.g. @\"SimbotA\"@.
  rpType :: i -> RobotType
  -- | The robot's identity, as given in the world description.
  rpId :: i -> RobotId
  -- | The distance between the wheels in metres: the wheel base @l@ of
  -- 'ddVelTR'.
  rpDiameter :: i -> Length
  -- | The maximal translational acceleration, in m\/s².
  rpAccMax :: i -> Acceleration
  -- | The maximal wheel speed, in m\/s.
  rpWSMax :: i -> Speed
