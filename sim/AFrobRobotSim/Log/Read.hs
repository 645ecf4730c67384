-- |
-- Module      : AFrobRobotSim.Log.Read
-- Description : A run log read back from its text or its file, checked
--               line by line.
--
-- The reading side of "AFrobRobotSim.Log" (which re-exports it): a log's
-- text ('readLog') or file ('readLogFile') parsed into its header, frames
-- and summary ('RunLog'), each line decoded by
-- "AFrobRobotSim.Log.Records", and refused with the line (and, for a line
-- that is not JSON, the column) of the first fault: another format or
-- version, a header whose dt or fps is not positive, a frame whose robots
-- are not the header's, a time written as @null@, a line after the
-- summary. A file is read as world files are: at most so many bytes, and
-- UTF-8.
module AFrobRobotSim.Log.Read
  ( RunLog (..)
  , readLog
  , readLogFile
  , readLogFileUpTo
  , maxLogBytes
  ) where

import           Data.Char                 (isDigit)
import           Data.List                 (stripPrefix)

import           AFrobRobotSim.Console     (displayPath)
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.InputFile (readFileUpTo)
import           AFrobRobotSim.WorldFile.Lexical (cannotRead, utf8Text)

-- | A log read back.
data RunLog = RunLog
  { rlHeader  :: LogHeader
  , rlFrames  :: [LogFrame]
  , rlSummary :: Maybe LogSummary  -- ^ absent when the run stopped before writing it
  } deriving (Eq, Show)

-- | Parse a log's text: a header of this format and version, frames, and
-- at most one summary, last; the header's dt and fps positive, and each
-- frame with as many robots as the header lists (the replay page pairs
-- them by position). Errors say @line N: ...@ (or @line N,
-- column C: ...@ for a line that is not JSON); one saying that the first
-- line is not a log header (not JSON, or another kind of line) asks
-- whether the text is a run log at all. Blank lines are ignored.
readLog :: String -> Either String RunLog
readLog = readLogAt (\i mc -> "line " ++ show i ++ maybe "" (\c -> ", column " ++ show c) mc ++ ": ")

-- 'readLog' with its errors located by the given function of the line and
-- (for a line that is not JSON) the column: 'readLogFile' says where as a
-- world file's errors do.
readLogAt :: (Int -> Maybe Int -> String) -> String -> Either String RunLog
readLogAt loc txt = case [ (i, l) | (i, l) <- zip [1 :: Int ..] (lines txt), not (all (`elem` " \t\r") l) ] of
  [] -> Left (loc 1 Nothing ++ "an empty log (expected a header line)")
  (i0, l0) : rest -> do
    h <- either (Left . (++ notALogHint)) Right $ at i0 (decodeLogLine l0) >>= \ln -> case ln of
      LineHeader h -> Right h
      _            -> Left (loc i0 Nothing ++ "expected the header line first")
    at i0 (checkVersion h)
    go h [] rest
  where
    -- a line's JSON error is at "line 1, column C: ..." of that line
    at i = either (\e -> Left (located i e)) Right
    located i e = case span isDigit <$> (stripPrefix "line 1, column " e) of
      Just (c@(_ : _), ':' : ' ' : msg) -> loc i (Just (read c)) ++ msg
      _                                 -> loc i Nothing ++ e
    checkVersion h
      | lhFormat h /= logFormatName = Left ("not an afrp log (format " ++ show (lhFormat h) ++ ")")
      | lhVersion h /= logFormatVersion =
          Left ("a log of version " ++ show (lhVersion h) ++ "; this reader reads version "
                ++ show logFormatVersion)
      | not (all positive [lhDt h, lhFps h]) =
          Left ("the header's dt and fps must be positive numbers, found " ++ show (lhDt h) ++ " and "
                ++ show (lhFps h))
      | otherwise = Right ()
    -- (a first line that is no header: most often a file that is not a log)
    notALogHint = " (is it a run log? a run writes one with --log FILE.jsonl)"
    positive x = x > 0 && not (isInfinite x)   -- (NaN, read from null, is not > 0)
    finite x = not (isNaN x || isInfinite x)
    go h acc [] = Right (RunLog h (reverse acc) Nothing)
    go h acc ((i, l) : rest) = at i (decodeLogLine l) >>= \ln -> case ln of
      LineFrame f
        | not (finite (lfTime f)) ->
            Left (loc i Nothing ++ "a frame's time must be a number, found " ++ show (lfTime f)
                  ++ " (null is not a time)")
        | length (lfRobots f) /= length (lhRobots h) ->
            Left (loc i Nothing ++ "a frame of " ++ show (length (lfRobots f)) ++ " robots; the header lists "
                  ++ show (length (lhRobots h)))
        | otherwise -> go h (f : acc) rest
      LineSummary s
        | not (all finite [lsSimulated s, lsWallTime s]) ->
            Left (loc i Nothing ++ "the summary's simulated and wall times must be numbers, found "
                  ++ show (lsSimulated s) ++ " and " ++ show (lsWallTime s))
      LineSummary s -> case rest of
        []           -> Right (RunLog h (reverse acc) (Just s))
        (j, _) : _   -> Left (loc j Nothing ++ "a line after the summary")
      LineHeader _  -> Left (loc i Nothing ++ "a second header")

-- | 'readLog' of a file (UTF-8), the error located as @FILE:LINE:COLUMN:@
-- (or @FILE:LINE:@), like a world file's; a file that cannot be read, or
-- is not UTF-8 (with the line and column of the first bad byte), is a
-- 'Left' too.
--
-- At most 'maxLogBytes' are read: a longer file (or an endless one, such
-- as @\/dev\/zero@) gives @FILE: more than N bytes@ and how to make a
-- shorter log.
readLogFile :: FilePath -> IO (Either String RunLog)
readLogFile = readLogFileUpTo maxLogBytes

-- | The longest log 'readLogFile' reads, in bytes: 256 MiB. A one-hour
-- run of the default world, logged at the default frame rate, is about
-- 230 MB; reading it and making its replay page
-- ('AFrobRobotSim.Replay.writeReplayFromLog') took 75 s and 2.5 GB of
-- memory (the log's text and its frames, as Haskell values, are held
-- until the page is written).
maxLogBytes :: Int
maxLogBytes = 256 * 1024 * 1024

-- | 'readLogFile' reading at most the given number of bytes (by
-- 'AFrobRobotSim.InputFile.readFileUpTo', as world files are read).
readLogFileUpTo :: Int -> FilePath -> IO (Either String RunLog)
readLogFileUpTo cap path = do
  r <- readFileUpTo cap path
  pure $ case r of
    Left e             -> Left (cannotRead path e)
    Right Nothing      -> Left (name ++ ": more than " ++ show cap ++ " bytes, more than a log is read (write a"
                                ++ " shorter run, or fewer frames with --fps)")
    Right (Just bytes) ->
      utf8Text name bytes >>= readLogAt (\i mc -> name ++ ":" ++ show i ++ maybe "" (\c -> ":" ++ show c) mc ++ ": ")
  where
    name = displayPath path   -- (a name with control characters escaped)
