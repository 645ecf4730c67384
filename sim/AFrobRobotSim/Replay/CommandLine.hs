-- |
-- Module      : AFrobRobotSim.Replay.CommandLine
-- Description : @simbot --replay-from FILE.jsonl --replay OUT.html@: its
--               command line, its messages and its exit codes.
--
-- The page of a run log is made by 'AFrobRobotSim.Replay.writeReplayFromLog';
-- this module is the program around it that @simbot@ runs when its
-- command line asks for it: the two flags read ('replayFromArgs'), the
-- page written (or the usage printed, for @--help@), what went wrong said
-- on standard error with the exit code a run would give for it
-- ('replayFromMain').
module AFrobRobotSim.Replay.CommandLine
  ( ReplayCommand (..)
  , replayFromArgs
  , replayFromMain
  ) where

import           System.Environment        (getProgName)

import           AFrobRobotSim.Console     (displayPath, endOutput, putErr, stopProgram)
import           AFrobRobotSim.Log         (LogEnd (..))
import           AFrobRobotSim.Options     (isHelpFlag, usage)
import           AFrobRobotSim.Replay      (ReplayFault (..), writeReplayFromLog)

-- | What the command line of @simbot --replay-from@ asks for.
data ReplayCommand
  = ReplayFrom FilePath FilePath  -- ^ the page of this run log: the log's name, then the page's
  | ReplayHelp                    -- ^ @--help@ (or @-h@): print the usage and exit
  deriving (Eq, Show)

-- | The log's and the page's names on the command line of @simbot
-- --replay-from FILE.jsonl --replay OUT.html@ (the two flags in either
-- order, each once, and no other), or what is wrong with it: a flag
-- without its value (or with a flag for its value: @./--replay@ names
-- such a file), the other flag missing, a flag given twice, any other
-- argument.
--
-- @--help@ (or @-h@) asks for the usage, as it does of a simulation's
-- command line ('AFrobRobotSim.Options.parseSimFlags'): the arguments are
-- read from the left, and the first that is @--help@ or a fault decides,
-- so @--replay-from x --replay p --help@ and @--help --frobnicate@ are
-- 'ReplayHelp', and @--frobnicate --help@ is refused for @--frobnicate@.
-- What only the end can tell (the other flag missing) is no fault before
-- @--help@: @--replay-from x --help@ is 'ReplayHelp'.
--
-- >>> replayFromArgs ["--replay", "run.html", "--replay-from", "run.jsonl"]
-- Right (ReplayFrom "run.jsonl" "run.html")
-- >>> replayFromArgs ["--replay-from", "run.jsonl", "--replay", "run.html", "--help"]
-- Right ReplayHelp
-- >>> replayFromArgs ["--replay-from"]
-- Left "--replay-from needs the name of the run log to read (written with --log): --replay-from FILE.jsonl --replay OUT.html"
replayFromArgs :: [String] -> Either String ReplayCommand
replayFromArgs = go Nothing Nothing
  where
    go mlog mpage args = case args of
      [] -> case (mlog, mpage) of
        (Just f, Just o) -> Right (ReplayFrom f o)
        (Just _, _)      -> Left ("--replay-from needs --replay OUT.html, the page to write: " ++ usageLine)
        _                -> Left ("--replay needs --replay-from FILE.jsonl, the run log to read: " ++ usageLine)
      flag : rest
        | isHelpFlag flag -> Right ReplayHelp
        | flag `elem` flags -> case rest of
            [] -> Left (flag ++ " needs " ++ what flag ++ ": " ++ usageLine)
            v : _ | v `elem` flags || isHelpFlag v -> Left (flag ++ " needs " ++ what flag ++ ", found the flag " ++ v)
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
-- 'ReplayWriteFailed'), or standard output cannot be written. A command
-- line that asks for @--help@ ('ReplayHelp') prints the usage of @simbot
-- --help@ ('AFrobRobotSim.Options.usage', which ends with this mode's) on
-- standard output, writes nothing else, and exits with 0, as @simbot
-- --help@ does.
replayFromMain :: [String] -> IO ()
replayFromMain args = do
  prog <- getProgName
  command <- either (stopProgram prog 2) pure (replayFromArgs args)
  case command of
    ReplayHelp             -> putStrLn (usage prog)
    ReplayFrom logPath out -> replayPage prog logPath out
  endOutput prog

-- The page written, and said; or the program stopped with the fault's
-- exit code.
replayPage :: String -> FilePath -> FilePath -> IO ()
replayPage prog logPath out = do
  r <- writeReplayFromLog logPath out
  case r of
    Left (ReplayRefused msg)     -> stopProgram prog 2 msg
    Left (ReplayWriteFailed msg) -> stopProgram prog 1 msg
    Right end -> do
      -- (a log cut off, by a full disk: its page is made, and the cut
      -- said)
      mapM_ (\i -> putErr (prog ++ ": warning: " ++ displayPath logPath ++ ":" ++ show i ++ ": the log's last line"
                            ++ " stops in its middle (did its disk fill up?); it is left out, and the page shows"
                            ++ " the frames before it\n")) (leCutLine end)
      putStrLn ("wrote " ++ displayPath out)
