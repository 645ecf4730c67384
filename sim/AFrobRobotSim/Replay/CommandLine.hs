-- |
-- Module      : AFrobRobotSim.Replay.CommandLine
-- Description : @simbot --replay-from FILE.jsonl --replay OUT.html@: its
--               command line, its messages and its exit codes.
--
-- The page of a run log is made by 'AFrobRobotSim.Replay.writeReplayFromLog';
-- this module is the program around it that @simbot@ runs when its
-- command line asks for it: the two flags read ('replayFromArgs'), the
-- page written, what went wrong said on standard error with the exit code
-- a run would give for it ('replayFromMain').
module AFrobRobotSim.Replay.CommandLine
  ( replayFromArgs
  , replayFromMain
  ) where

import           System.Environment        (getProgName)
import           System.Exit               (ExitCode (..), exitWith)

import           AFrobRobotSim.Console     (displayPath, endOutput, putErr)
import           AFrobRobotSim.Log         (LogEnd (..))
import           AFrobRobotSim.Replay      (ReplayFault (..), writeReplayFromLog)

-- | The log's and the page's names on the command line of @simbot
-- --replay-from FILE.jsonl --replay OUT.html@ (the two flags in either
-- order, each once, and no other), or what is wrong with it: a flag
-- without its value (or with a flag for its value: @./--replay@ names
-- such a file), the other flag missing, a flag given twice, any other
-- argument.
--
-- >>> replayFromArgs ["--replay", "run.html", "--replay-from", "run.jsonl"]
-- Right ("run.jsonl","run.html")
-- >>> replayFromArgs ["--replay-from"]
-- Left "--replay-from needs the name of the run log to read (written with --log): --replay-from FILE.jsonl --replay OUT.html"
replayFromArgs :: [String] -> Either String (FilePath, FilePath)
replayFromArgs = go Nothing Nothing
  where
    go mlog mpage args = case args of
      [] -> case (mlog, mpage) of
        (Just f, Just o) -> Right (f, o)
        (Just _, _)      -> Left ("--replay-from needs --replay OUT.html, the page to write: " ++ usageLine)
        _                -> Left ("--replay needs --replay-from FILE.jsonl, the run log to read: " ++ usageLine)
      flag : rest
        | flag `elem` flags -> case rest of
            [] -> Left (flag ++ " needs " ++ what flag ++ ": " ++ usageLine)
            v : _ | v `elem` flags -> Left (flag ++ " needs " ++ what flag ++ ", found the flag " ++ v)
            v : rest'
              | flag == "--replay-from" -> maybe (go (Just v) mpage rest') (const (twice flag)) mlog
              | otherwise               -> maybe (go mlog (Just v) rest') (const (twice flag)) mpage
        | otherwise -> Left (usageLine ++ " takes no other argument, got " ++ show flag)
    flags = ["--replay-from", "--replay"]
    what flag | flag == "--replay-from" = "the name of the run log to read (written with --log)"
              | otherwise               = "the name of the page to write"
    twice flag = Left (flag ++ " is given twice: " ++ usageLine)
    usageLine = "--replay-from FILE.jsonl --replay OUT.html"

-- | @simbot --replay-from FILE.jsonl --replay OUT.html@: the page of a run
-- log ('writeReplayFromLog'), from these arguments ('replayFromArgs'),
-- with @wrote OUT.html@ on standard output, a warning for a log cut off
-- in its last line, and the messages on standard error signed with the
-- program's name. The exit code is 0 when the page is written; 2 when
-- it is refused before anything is written (a command line that is not
-- those two flags with their values, a log that does not read, a page
-- in a folder that does not exist: 'ReplayRefused'); 1 when a write
-- fails on the way (a full disk, a folder that may not be written to:
-- 'ReplayWriteFailed'), or standard output cannot be written.
replayFromMain :: [String] -> IO ()
replayFromMain args = do
  prog <- getProgName
  let stop code msg = putErr (prog ++ ": " ++ msg ++ "\n") >> exitWith (ExitFailure code)
  (logPath, out) <- either (stop 2) pure (replayFromArgs args)
  r <- writeReplayFromLog logPath out
  case r of
    Left (ReplayRefused msg)     -> stop 2 msg
    Left (ReplayWriteFailed msg) -> stop 1 msg
    Right end -> do
      -- (a log cut off, by a full disk: its page is made, and the cut
      -- said)
      mapM_ (\i -> putErr (prog ++ ": warning: " ++ displayPath logPath ++ ":" ++ show i ++ ": the log's last line"
                            ++ " stops in its middle (did its disk fill up?); it is left out, and the page shows"
                            ++ " the frames before it\n")) (leCutLine end)
      putStrLn ("wrote " ++ displayPath out)
  endOutput prog
