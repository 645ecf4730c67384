-- |
-- Module      : AFrobRobotSim.Log.Records
-- Description : The records of a run log and their JSON, line by line.
--
-- A run log (@docs/LOG.md@) is JSON lines: a 'LogHeader', then one
-- 'LogFrame' per frame period, then a 'LogSummary'. This module holds the
-- plain records and their JSON both ways; "AFrobRobotSim.Log" makes them
-- from a simulation and writes and reads files. Every position is in the
-- world's frame (metres, x to the right, y up), every heading and angle in
-- radians (headings counter-clockwise from +x, sensor angles relative to
-- the robot's heading, counter-clockwise positive), times in seconds of
-- simulated time.
--
-- = Modules
--
-- This module gathers the records', and has no code of its own:
-- "AFrobRobotSim.Log.Records.Types" (the records),
-- "AFrobRobotSim.Log.Records.Encode" (a line as a JSON value, and as
-- text), "AFrobRobotSim.Log.Records.Bytes" (a line as bytes, a frame
-- written straight into the buffer) and
-- "AFrobRobotSim.Log.Records.Decode" (a line read back).
module AFrobRobotSim.Log.Records
  ( -- * Lines
    LogLine (..)
  , logFormatName
  , logFormatVersion
    -- * The header
  , LogHeader (..)
  , LogRect (..)
  , LogRobotInfo (..)
    -- * Frames
  , LogFrame (..)
  , LogRobot (..)
  , LogEvent (..)
    -- * The summary
  , LogSummary (..)
    -- * JSON
  , logLineJSON
  , encodeLogLine
  , encodeLogLineBytes
  , logLineFromJSON
  , decodeLogLine
  , decodeLogLineBytes
  , decodeLogLineUtf8
  ) where

import           AFrobRobotSim.Log.Records.Bytes
import           AFrobRobotSim.Log.Records.Decode
import           AFrobRobotSim.Log.Records.Encode
import           AFrobRobotSim.Log.Records.Types
