-- |
-- Module      : AFrob
-- Description : The robot vocabulary: AFRP plus the robot-generic AFrob classes.
--
-- AFrob is the robot-specific part of the library described in section 3
-- of the notes \"Arrows, Robots, and Functional Reactive Programming\"
-- (Hudak, Courtney, Nilsson, Peterson). @import AFrob@ gives a robot
-- controller everything it needs: the whole of "AFRP" (signal functions,
-- arrow notation, events, switches, geometry) and the robot vocabulary
-- below.
--
-- AFrob is /robot-generic/: it knows no concrete robot. Sensors and
-- actuators are described by type classes, and a robot type takes part by
-- making its input type an instance of the input classes for the sensors
-- it has (status, odometry, range finders, ...), its output type an
-- instance of the output classes for its actuators (differential drive,
-- console), and its static properties an instance of
-- 'HasRobotProperties'. A controller written against the classes, e.g.
--
-- > rcStop :: (HasDiffDrive o) => p -> SF i o
-- > rcStop _ = constant (mrFinalize ddBrake)
--
-- runs on any robot with those capabilities; a simulator or a driver for a
-- real robot supplies the concrete types.
--
-- Units are SI (metres, seconds, radians) except for compass bearings,
-- which are in degrees; see "AFrob.Dimensions" and "AFrob.Angle".
module AFrob
  ( -- * The FRP core
    module AFRP
    -- * Dimensions
    -- | "AFrob.Dimensions".
  , Length
  , Distance
  , Position
  , Velocity
  , Speed
  , Acceleration
  , Angle
  , Heading
  , Bearing
  , RotVel
  , RotAcc
  , Position2
  , Velocity2
  , Distance2
  , RobotType
  , RobotId
    -- * Angles, headings and bearings
    -- | "AFrob.Angle".
  , normalizeAngle
  , normalizeHeading
  , normalizeBearing
  , bearingToHeading
  , headingToBearing
  , degToRad
  , radToDeg
    -- * Mergeable records
    -- | "AFrob.MergeableRecord": outputs built up from merged updates.
  , MergeableRecord (..)
  , MR
  , mrMake
  , mrMerge
  , mrFinalize
    -- * Input classes
    -- | "AFrob.RobotIO".

    -- ** Robot status
  , HasRobotStatus (..)
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

import AFRP

import AFrob.Angle
import AFrob.Dimensions
import AFrob.MergeableRecord
import AFrob.RobotIO
