-- |
-- Module      : AFrobRobotSim.Log.Writer
-- Description : A run log written to its file as the run goes.
--
-- The file side of a run log: 'LogWriter' writes the header when it is
-- opened, a frame's line at each frame's step ('logStep') as the run
-- goes, each line whole or not at all, and the summary when it is
-- closed. The file is read back by "AFrobRobotSim.Log.Read". Part of
-- "AFrobRobotSim.Log", which re-exports it.
module AFrobRobotSim.Log.Writer
  ( LogWriter
  , openLogWriter
  , writeLogState
  , writeLogStateLine
  , closeLogWriter
  , logWriterFrames
  ) where

import           Control.Exception         (evaluate, uninterruptibleMask_)
import qualified Data.ByteString.Char8     as BC
import           Data.IORef
import           System.IO

import           AFrobRobotSim.Log.Config
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.Log.Step
import           AFrobRobotSim.Simulator

-- | A log file being written: the header at once, a frame line for every
-- frame step, the summary at the end, each line flushed as it is written
-- so that a run that stops (Ctrl-C, a crash) leaves a log that is valid up
-- to its last frame.
data LogWriter = LogWriter LogConfig Handle (IORef (LogState, Int))

-- | Create (or truncate) the file and write the header.
openLogWriter :: LogConfig -> FilePath -> IO LogWriter
openLogWriter cfg path = do
  h <- openFile path WriteMode
  hSetEncoding h utf8   -- the encoder writes ASCII only; this is for safety
  hSetBuffering h (BlockBuffering Nothing)
  hPutStrLn h (encodeLogLine (LineHeader (logHeader cfg))) >> hFlush h
  LogWriter cfg h <$> newIORef (logStart cfg, 0)

-- | Give the writer the next step's state (call it for every step, the
-- first at time 0); it writes a frame line when the step is a frame's.
writeLogState :: LogWriter -> WorldState -> IO ()
writeLogState w s = () <$ writeLogStateLine w s

-- | 'writeLogState', giving back the frame line it wrote (without its
-- newline), if the step is a frame's: for a writer of the same frames
-- that need not encode them again ('AFrobRobotSim.Replay.recordReplayStateWith').
writeLogStateLine :: LogWriter -> WorldState -> IO (Maybe BC.ByteString)
writeLogStateLine (LogWriter cfg h ref) s = do
  (st, k) <- readIORef ref
  let (st', mf) = logStep cfg st s
  case mf of
    Just f  -> do
      line <- evaluate (encodeLogLineBytes (LineFrame f))
      -- a whole line or none: Ctrl-C (an asynchronous exception) waits
      -- for the line to be written, so an interrupted run's log reads back
      let k' = k + 1
      uninterruptibleMask_ (BC.hPutStrLn h line >> hFlush h >> (k' `seq` writeIORef ref (st', k')))
      pure (Just line)
    Nothing -> Nothing <$ (st' `seq` writeIORef ref (st', k))

-- | How many frame lines the writer has written.
logWriterFrames :: LogWriter -> IO Int
logWriterFrames (LogWriter _ _ ref) = snd <$> readIORef ref

-- | Write the summary line and close the file. Pass the summary the
-- runner prints ('lsFrames' is taken from the writer's count when it is
-- negative).
closeLogWriter :: LogWriter -> LogSummary -> IO ()
closeLogWriter w@(LogWriter _ h _) s = do
  k <- logWriterFrames w
  let s' = if lsFrames s < 0 then s { lsFrames = k } else s
  hPutStrLn h (encodeLogLine (LineSummary s')) >> hClose h
