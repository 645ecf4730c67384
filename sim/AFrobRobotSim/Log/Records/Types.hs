-- |
-- Module      : AFrobRobotSim.Log.Records.Types
-- Description : The records of a run log: its lines, the header, the
--               frames and the summary.
--
-- A run log (@docs/LOG.md@) is JSON lines: a 'LogHeader', then one
-- 'LogFrame' per frame period, then a 'LogSummary'. These are the plain
-- records, with no JSON: "AFrobRobotSim.Log.Records.Encode",
-- "AFrobRobotSim.Log.Records.Bytes" and "AFrobRobotSim.Log.Records.Decode"
-- write and read them. Part of "AFrobRobotSim.Log.Records", which
-- re-exports all of it. The module exports everything it defines (it has
-- no export list: its sections are in its body).
module AFrobRobotSim.Log.Records.Types where

-- * Lines

-- | The format's name, the header's @format@: @"afrp-log"@.
logFormatName :: String
logFormatName = "afrp-log"

-- | The format's version, the header's @version@: 1. A reader refuses a
-- log of another version.
logFormatVersion :: Int
logFormatVersion = 1

-- | One line of a log.
data LogLine
  = LineHeader LogHeader
  | LineFrame LogFrame
  | LineSummary LogSummary
  deriving (Eq, Show)

-- * The header

-- | An axis-aligned rectangle, by its centre and size (m).
data LogRect = LogRect
  { rectX :: !Double, rectY :: !Double, rectWidth :: !Double, rectHeight :: !Double }
  deriving (Eq, Show)

-- | The first line: what the run was, and the world at time 0.
data LogHeader = LogHeader
  { lhFormat       :: String          -- ^ 'logFormatName'
  , lhVersion      :: !Int            -- ^ 'logFormatVersion'
  , lhBounds       :: LogRect         -- ^ the world's extent
  , lhWalls        :: [LogRect]       -- ^ wall segments
  , lhBlocks       :: [LogRect]       -- ^ blocks
  , lhBalls        :: [(Double, Double)] -- ^ balls' centres at time 0
  , lhBallRadius   :: !Double         -- ^ a ball's radius (m)
  , lhGoals        :: [LogRect]       -- ^ goal areas, if the program has any
  , lhRobots       :: [LogRobotInfo]  -- ^ every robot, in template order
  , lhRangeAngles  :: [Double]        -- ^ the angles of the logged range readings (rad, relative to the heading)
  , lhRangeMax     :: !Double         -- ^ the range finder's maximum range (m)
  , lhTrackerRange :: !Double         -- ^ the tracker's range, centre to centre (m)
  , lhDt           :: !Double         -- ^ the simulation's time step (s)
  , lhFps          :: !Double         -- ^ frames per simulated second: one frame line per 1/fps s
  , lhSeed         :: !Int            -- ^ the seed of the odometry noise
  , lhCommandLine  :: [String]        -- ^ the program's name and arguments
  } deriving (Eq, Show)

-- | A robot as the header lists it.
data LogRobotInfo = LogRobotInfo
  { riType          :: String   -- ^ @"SimbotA"@ or @"SimbotB"@
  , riId            :: !Int     -- ^ its id, unique within its type
  , riRadius        :: !Double  -- ^ body radius (m)
  , riWheelBase     :: !Double  -- ^ distance between the wheels (m)
  , riMaxWheelSpeed :: !Double  -- ^ (m/s)
  , riSensors       :: [String] -- ^ the sensors it has, by name
  } deriving (Eq, Show)

-- * Frames

-- | One frame period: the world at the frame's instant, and what happened
-- since the previous frame.
data LogFrame = LogFrame
  { lfTime     :: !Double          -- ^ simulated time of the frame (s)
  , lfRobots   :: [LogRobot]       -- ^ every robot, in the header's order
  , lfBalls    :: [(Double, Double)] -- ^ every ball's centre, in template order
  , lfScores   :: [(String, Int)]  -- ^ the program's scores now, if it keeps any
  , lfEvents   :: [LogEvent]       -- ^ events since the previous frame (after it, up to this one)
  , lfConsole  :: [String]         -- ^ console lines of the period that no robot printed
  } deriving (Eq, Show)

-- | One robot at a frame's instant.
data LogRobot = LogRobot
  { lrX, lrY        :: !Double     -- ^ true position of its centre (m)
  , lrHeading       :: !Double     -- ^ true heading (rad)
  , lrWheelLeft     :: !Double     -- ^ left wheel speed (m/s), over the last step
  , lrWheelRight    :: !Double     -- ^ right wheel speed (m/s), over the last step
  , lrSpeed         :: !Double     -- ^ translational velocity (m/s, signed: negative backwards)
  , lrRotVel        :: !Double     -- ^ rotational velocity (rad/s, counter-clockwise), over the last step
  , lrBumper        :: !Bool       -- ^ stuck against an obstacle
  , lrRange         :: [Double]    -- ^ range readings (m) at the header's angles
  , lrSeenRobots    :: [(String, Int, Double, Double)]
    -- ^ the robots its tracker sees, nearest first: type, id, angle
    -- relative to its heading (rad), distance between centres (m)
  , lrSeenBalls     :: [(Double, Double)]
    -- ^ the balls its tracker sees, nearest first: angle (rad), distance (m)
  , lrBattery       :: String      -- ^ @"high"@, @"low"@ or @"critical"@
  , lrCharge        :: !Double     -- ^ battery charge, 1 = full
  , lrOdoX, lrOdoY  :: !Double     -- ^ what its odometry reads (m)
  , lrMessages      :: [(Double, String)] -- ^ lines it printed in the period, each with its time
  } deriving (Eq, Show)

-- | Something that happened at an instant.
data LogEvent = LogEvent
  { evTime  :: !Double    -- ^ (s)
  , evKind  :: String     -- ^ @"bump"@ (a robot got stuck) or @"score"@
  , evRobot :: Maybe (String, Int) -- ^ the robot concerned, if one is
  , evText  :: String     -- ^ a sentence for people
  } deriving (Eq, Show)

-- * The summary

-- | The last line: the same facts as the summary the runner prints.
data LogSummary = LogSummary
  { lsSimulated   :: !Double       -- ^ simulated time (s)
  , lsSteps       :: !Int          -- ^ samples stepped, the one at time 0 included (the steps after time 0, plus one)
  , lsFrames      :: !Int          -- ^ frame lines written
  , lsWallTime    :: !Double       -- ^ wall-clock time of the run (s)
  , lsInterrupted :: !Bool         -- ^ stopped by Ctrl-C
  , lsFailure     :: Maybe String
    -- ^ a controller's or the referee's failure, as printed
    -- (@displayException@ of the 'AFrobRobotSim.Simulator.ControllerError',
    -- which names the robot and the time, or of the
    -- 'AFrobRobotSim.Simulator.RefereeError', which names the rule and
    -- the time), or a write that failed: the failing step has no state,
    -- so no frame shows it
  , lsFalsified   :: Maybe (Double, String)
    -- ^ a test's property of the run decided false: the instant that
    -- decided (s) and a line that says so (afrp-test's @forAllRuns@
    -- writes it, the explanation's first line; a run of simbot never
    -- does). Written only when there is one
  , lsScores      :: [(String, Int)] -- ^ final scores, if any: the last simulated state's
  } deriving (Eq, Show)
