-- |
-- Module      : AFrobRobotSim.Robot
-- Description : What a simbot's controller sees and says: 'SimbotInput',
--               'SimbotOutput', 'SimbotProperties', 'SimbotController'.
--
-- Each type is an instance of the AFrob classes it supports, so controllers
-- are written against the classes ("AFrob.RobotIO") exactly as in the notes.
module AFrobRobotSim.Robot
  ( -- * Controllers
    SimbotController
    -- * Static properties
  , SimbotProperties (..)
    -- * Input
  , SimbotInput (..)
    -- * Output
  , SimbotOutput (..)
  , DriveCommand (..)
  ) where

import           AFRP
import           AFrob.Dimensions
import           AFrob.MergeableRecord
import           AFrob.RobotIO
import           AFrobRobotSim.World

-- | A simbot controller: from the robot's static properties to a signal
-- function from what it senses to what it does. The same controller runs
-- every robot of one type; use 'rpId' to tell them apart.
type SimbotController = SimbotProperties -> SF SimbotInput SimbotOutput

-- | The static properties of one simbot (see the table in
-- "AFrobRobotSim.World").
data SimbotProperties = SimbotProperties
  { spKind :: !RobotKind  -- ^ SimbotA or SimbotB
  , spId   :: !RobotId    -- ^ its id, unique within its type
  } deriving (Eq, Show)

-- | 'rpType' is @"SimbotA"@ or @"SimbotB"@; 'rpDiameter' is the distance
-- between the wheels (0.5 m).
instance HasRobotProperties SimbotProperties where
  rpType     = kindType . spKind
  rpId       = spId
  rpDiameter = kindWheelBase . spKind
  rpAccMax   = kindAccMax . spKind
  rpWSMax    = kindWSMax . spKind

-- | One sample of what a simbot senses. The range finder and the tracker
-- are computed on demand: a controller pays only for the rays it casts.
data SimbotInput = SimbotInput
  { siBattery  :: !BatteryStatus                            -- ^ battery level
  , siStuck    :: !Bool                                     -- ^ blocked by an obstacle
  , siPosition :: !Position2                                -- ^ odometry position
  , siHeading  :: !Heading                                  -- ^ odometry heading
  , siRange    :: Angle -> Distance                         -- ^ the range finder
  , siMaxRange :: !Distance                                 -- ^ its maximum range
  , siRobots   :: [(RobotType, RobotId, Angle, Distance)]   -- ^ tracked robots
  , siBalls    :: [(Angle, Distance)]                       -- ^ tracked balls
  , siKey      :: !(Maybe Char)                             -- ^ the key pressed now, if any
  }

instance HasRobotStatus SimbotInput where
  rsBattStat = siBattery
  rsIsStuck  = siStuck

-- | Exact unless the simulation was started with noisy odometry.
instance HasOdometry SimbotInput where
  odometryPosition = siPosition
  odometryHeading  = siHeading

-- | @rfRange i a@ is the distance from the robot's edge to the nearest wall,
-- block, boundary or other robot in the direction @a@ (radians, relative to
-- the heading, counter-clockwise), or 'rfMaxRange' if there is none that
-- close. Balls are too low to be seen.
instance HasRangeFinder SimbotInput where
  rfRange    = siRange
  rfMaxRange = siMaxRange

-- | Other robots and balls within the tracking range, with their angle
-- relative to the own heading (an 'AFrob.Dimensions.Angle' in radians,
-- counter-clockwise positive, normalised to [-pi, pi); not a compass
-- 'AFrob.Dimensions.Bearing') and their centre-to-centre distance,
-- nearest first.
instance HasAnimateObjectTracker SimbotInput where
  aotOtherRobots = siRobots
  aotBalls       = siBalls

-- | The scripted keyboard: a key is down for one sample per press, one
-- key a sample; a key pressed again straight after itself is released
-- for a sample between, so that each press changes 'tciKey' and
-- 'AFrob.RobotIO.tciKeyDown' fires once per press
-- ('AFrobRobotSim.Simulator.keyAtStep').
instance HasTextualConsoleInput SimbotInput where
  tciKey = siKey

-- | What a simbot does at one sample: how to drive, and what to print.
data SimbotOutput = SimbotOutput
  { soDrive    :: !DriveCommand  -- ^ the wheel command
  , soMessages :: [String]       -- ^ lines to print, in order (a run keeps the first 10,000 characters of each)
  } deriving (Eq, Show)

-- | A wheel command, interpreted by the simulator with the robot's
-- dimensions and limits.
data DriveCommand
  = DriveBrake                    -- ^ stop: decelerate at the maximum acceleration, no rotation
  | DriveWheels !Velocity !Velocity -- ^ left and right wheel speeds
  | DriveTR !Velocity !RotVel     -- ^ forward speed and rotational velocity
  deriving (Eq, Show)

-- | Unset fields: brake, and print nothing.
instance MergeableRecord SimbotOutput where
  mrDefault = SimbotOutput DriveBrake []

-- | Sets the drive command (the left operand of 'mrMerge' wins).
instance HasDiffDrive SimbotOutput where
  ddBrake       = setDrive DriveBrake
  ddVelDiff l r = setDrive (DriveWheels l r)
  ddVelTR v w   = setDrive (DriveTR v w)

-- | Adds a line to print when the event occurs; merged messages are all
-- printed, the left operand's first.
instance HasTextConsoleOutput SimbotOutput where
  tcoPrintMessage e = mrMake (\o -> event o (\s -> o { soMessages = s : soMessages o }) e)

setDrive :: DriveCommand -> MR SimbotOutput
setDrive d = mrMake (\o -> o { soDrive = d })
