-- |
-- Module      : AFrobRobotSim.Log
-- Description : The run log: JSON lines made from a simulation's states.
--
-- A run log is what a person needs to answer "what did my robot see and
-- do at 12.3 s?" after a headless run, and what the replay page draws
-- ("AFrobRobotSim.Replay"). Its format is documented field by field in
-- @docs/LOG.md@; the records are in "AFrobRobotSim.Log.Records".
--
-- The log is made from what 'AFrobRobotSim.Simulator.simulate' gives, the
-- stream of 'AFrobRobotSim.Simulator.WorldState's, one per step, and
-- nothing else: the simulator does not report wheel speeds or sensor
-- readings, so they are recomputed here.
-- Range readings and tracker sightings are the sensors'
-- ('AFrobRobotSim.Sensors.senseRobot') at the frame's instant, exactly
-- what the controllers saw; wheel speeds and rotational velocity come from
-- the heading's change over the step that ended at the instant (0 at time
-- 0), so they are what the robot did, not what its controller asked for.
--
-- The numbers of a frame are rounded: positions, angles, speeds and
-- the charge to a millionth, times to a nanosecond.
--
-- Frames are the runner's: frame @f@ is the step nearest simulated time
-- @f / fps@ (the first step is frame 0). A frame line carries the events
-- and the messages of its period: the steps after the previous frame, up
-- to and including its own.
--
-- Three ways to use it: 'logStep' one state at a time (what a streaming
-- writer needs), 'logFrames' on a whole list, and 'LogWriter', which
-- writes a file as the run goes; and 'LogRates', 'logStep' at several
-- frame rates at once, for the replay page's recorder. A log is read back with 'readLog' and
-- 'readLogFile' (from "AFrobRobotSim.Log.Read", re-exported here).
--
-- = Modules
--
-- This module gathers the log's, and has no code of its own:
-- "AFrobRobotSim.Log.Config" (the settings and the header),
-- "AFrobRobotSim.Log.Frame" (a frame's record made from a state, and the
-- rounding), "AFrobRobotSim.Log.Step" (frames step by step),
-- "AFrobRobotSim.Log.Rates" (at several frame rates at once),
-- "AFrobRobotSim.Log.Writer" (a file written as the run goes),
-- "AFrobRobotSim.Log.Read" (a log read back) and
-- "AFrobRobotSim.Log.Records" (the records and their JSON).
module AFrobRobotSim.Log
  ( -- * Settings
    LogConfig (..)
  , defaultLogConfig
    -- * From states to records
  , logHeader
  , LogState
  , logStart
  , logStep
  , logFrames
  , isFrameStep
  , linesByRobot
    -- * Several frame rates at once
  , LogRates
  , logRatesStart
  , logRatesStep
  , logRatesKeep
    -- * The values' rounding
  , roundHalfEven
  , roundTo
    -- * Writing a file as the run goes
  , LogWriter
  , openLogWriter
  , writeLogState
  , writeLogStateLine
  , closeLogWriter
  , logWriterFrames
    -- * Reading a log back
  , RunLog (..)
  , LogEnd (..)
  , readLog
  , readLogFile
  , readLogFileUpTo
  , foldLogFile
  , maxLogBytes
  , maxLogLineBytes
    -- * The records
  , module AFrobRobotSim.Log.Records
  ) where

import           AFrobRobotSim.Log.Config
import           AFrobRobotSim.Log.Frame   (linesByRobot, roundHalfEven, roundTo)
import           AFrobRobotSim.Log.Rates
import           AFrobRobotSim.Log.Read
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.Log.Step    (LogState, isFrameStep, logFrames, logStart, logStep)
import           AFrobRobotSim.Log.Writer
