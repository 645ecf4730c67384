{-# LANGUAGE ScopedTypeVariables #-}
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
-- summary. A file is read a line at a time ('foldLogFile'), at most so
-- many bytes in all and in a line, as UTF-8, each line checked to be
-- UTF-8 once and parsed as its bytes ('AFrobRobotSim.JSON.parseJSONUtf8':
-- the same lines, and the same errors, as 'readLog' of the file's text).
--
-- = A log cut off
--
-- A log can end in the middle of a line: its run's disk filled up while
-- the run wrote it, or it was copied while its run still wrote it, or a
-- transfer stopped short. Such a line, the last of its log, with no
-- newline at its end, and JSON cut short ('AFrobRobotSim.JSON.cutShort':
-- not JSON only because it ends too soon, as every proper prefix of a
-- line's JSON object is), is left out: the log reads as its lines before
-- it, with no summary, and 'rlCutLine' (or 'leCutLine') gives its
-- number, so that a reader can say so. A log cut off in its header line
-- is refused, with that said. Any other fault of a last line (a fault
-- before its end, whole JSON that is no log line, bytes that are not
-- UTF-8: a log is ASCII), or a line cut short with a newline after it,
-- is refused as before: only the end of a log is taken as cut. (A whole
-- last line without a newline, as a run killed between a line and its
-- newline leaves, is a line.)
module AFrobRobotSim.Log.Read
  ( RunLog (..)
  , LogEnd (..)
  , readLog
  , readLogFile
  , readLogFileUpTo
  , foldLogFile
  , maxLogBytes
  , maxLogLineBytes
  ) where

import           Control.Exception         (IOException, finally, try)
import qualified Data.ByteString.Char8     as BC
import           Data.Char                 (isDigit)
import           Data.List                 (stripPrefix)
import           System.IO                 (hClose, hFileSize)

import           AFrobRobotSim.Console     (displayPath)
import           AFrobRobotSim.FlatArray   (finite)
import           AFrobRobotSim.JSON        (cutShort, cutShortUtf8)
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.InputFile   (LineFault (..), newLineReader, nextLineEnded, openReading)
import           AFrobRobotSim.UTF8        (Utf8)
import           AFrobRobotSim.WorldFile.Lexical (cannotRead, utf8BytesFrom)

-- | A log read back.
data RunLog = RunLog
  { rlHeader  :: LogHeader
  , rlFrames  :: [LogFrame]
  , rlSummary :: Maybe LogSummary  -- ^ absent when the run stopped before writing it
  , rlCutLine :: Maybe Int
    -- ^ the number of the log's last line (from 1), when that line was
    -- cut off in its middle and left out (see "A log cut off" above: a
    -- full disk, a copy made while the run wrote it). 'Nothing' for a
    -- whole log.
  } deriving (Eq, Show)

-- | How a log read a line at a time ('foldLogFile') ends, after its last
-- frame: its summary, if any, and the number of its last line when that
-- line was cut off and left out (as 'rlSummary' and 'rlCutLine').
data LogEnd = LogEnd
  { leSummary :: Maybe LogSummary
  , leCutLine :: Maybe Int
  } deriving (Eq, Show)

-- | Parse a log's text: a header of this format and version, frames, and
-- at most one summary, last; the header's dt and fps positive, and each
-- frame with as many robots as the header lists (the replay page pairs
-- them by position). Errors say @line N: ...@ (or @line N,
-- column C: ...@ for a line that is not JSON); one saying that the first
-- line is not a log header (not JSON, or another kind of line) asks
-- whether the text is a run log at all. Blank lines are ignored. A
-- last line cut off in its middle, with no newline after it, is left out
-- (see "A log cut off" above).
readLog :: String -> Either String RunLog
readLog = readLogAt (\i mc -> "line " ++ show i ++ maybe "" (\c -> ", column " ++ show c) mc ++ ": ")

-- Where a fault is, as a message's beginning, from the line and (for a
-- line that is not JSON) the column.
type Locate = Int -> Maybe Int -> String

-- 'readLog' with its errors located by the given function: 'readLogFile'
-- says where as a world file's errors do.
readLogAt :: Locate -> String -> Either String RunLog
readLogAt loc txt = case [ (i, l, ended) | (i, (l, ended)) <- zip [1 :: Int ..] (linesEnded txt), not (blank l) ] of
  [] -> Left (loc 1 Nothing ++ emptyLog)
  (i0, l0, ended0) : rest -> headerLine loc (cutOff ended0 l0) i0 (decodeLogLine l0) >>= \h -> go h [] rest
  where
    go h acc [] = Right (RunLog h (reverse acc) Nothing Nothing)
    go h acc ((i, l, ended) : rest)
      | cutOff ended l = Right (RunLog h (reverse acc) Nothing (Just i))
      | otherwise = bodyLine loc h (lastTime acc) i (decodeLogLine l) >>= \ln -> case ln of
          Left f  -> go h (f : acc) rest
          Right s -> case rest of
            []            -> Right (RunLog h (reverse acc) (Just s) Nothing)
            (j, _, _) : _ -> Left (loc j Nothing ++ afterSummary)

-- 'lines', each line with whether a newline ends it (all but a last
-- one that the text ends in), made as they are read: a long log's text
-- is not held whole.
linesEnded :: String -> [(String, Bool)]
linesEnded txt = case break (== '\n') txt of
  (l, _ : rest) -> (l, True) : if null rest then [] else linesEnded rest
  (l, [])       -> [ (l, False) | not (null l) ]

-- Whether a line is the cut-off end of a log (see "A log cut off"
-- above), given whether a newline ends it: none does, and it is JSON
-- cut short.
cutOff :: Bool -> String -> Bool
cutOff ended l = not ended && cutShort l

-- 'cutOff' of a line's bytes, found to be UTF-8.
cutOffUtf8 :: Bool -> Utf8 -> Bool
cutOffUtf8 ended l = not ended && cutShortUtf8 l

-- The time of the newest frame read, of frames newest first (0 before
-- the first: a frame's time is not negative).
lastTime :: [LogFrame] -> Double
lastTime fs = case fs of
  f : _ -> lfTime f
  []    -> 0

-- Whether a line is blank (such lines are skipped).
blank :: String -> Bool
blank = all (`elem` " \t\r")

emptyLog, afterSummary :: String
emptyLog = "an empty log (expected a header line)"
afterSummary = "a line after the summary"

-- The first line that is not blank, line @i@, decoded ('decodeLogLine'
-- or 'decodeLogLineUtf8'): a header of this format and version, whose
-- dt and fps are positive. @cut@: whether the line is a log's cut-off end
-- ('cutOff': looked at only for a line refused).
headerLine :: Locate -> Bool -> Int -> Either String LogLine -> Either String LogHeader
headerLine loc cut i decoded = do
  h <- either (Left . (++ hint)) Right $ located loc i decoded >>= \ln -> case ln of
    LineHeader h -> Right h
    _            -> Left (loc i Nothing ++ "expected the header line first")
  located loc i (checkVersion h)
  pure h
  where
    checkVersion h
      | lhFormat h /= logFormatName = Left ("not an afrp log (format " ++ show (lhFormat h) ++ ")")
      | lhVersion h /= logFormatVersion =
          Left ("a log of version " ++ show (lhVersion h) ++ "; this reader reads version "
                ++ show logFormatVersion)
      | not (all positive [lhDt h, lhFps h]) =
          Left ("the header's dt and fps must be positive numbers, found " ++ show (lhDt h) ++ " and "
                ++ show (lhFps h))
      | LogRect x y w ht <- lhBounds h, not (all finite [x, y] && all positive [w, ht]) =
          Left ("the header's bounds must be numbers, with a positive width and height, found x " ++ show x
                ++ ", y " ++ show y ++ ", width " ++ show w ++ " and height " ++ show ht)
      | otherwise = Right ()
    -- (a first line that is no header: most often a file that is not a
    -- log; or, with no newline after it, a log cut off in its first
    -- line)
    hint | cut            = " (the line stops with no newline after it: did the run that wrote the log stop"
                            ++ " as it began, or its disk fill up?)"
         | otherwise      = " (is it a run log? a run writes one with --log FILE.jsonl)"
    positive x = x > 0 && not (isInfinite x)   -- (NaN, read from null, is not > 0)

-- A line after the header, line @i@, not blank, decoded, the frame before
-- it at time @prev@ (0 for none): a frame (with a time, not before
-- @prev@, the header's robots, and robots and balls at places that are
-- numbers) or the summary (with its times, the instant a property was
-- falsified's too).
bodyLine :: Locate -> LogHeader -> Double -> Int -> Either String LogLine -> Either String (Either LogFrame LogSummary)
bodyLine loc h prev i decoded = located loc i decoded >>= \ln -> case ln of
  LineFrame f
    | not (finite (lfTime f)) ->
        Left (loc i Nothing ++ "a frame's time must be a number, found " ++ show (lfTime f)
              ++ " (null is not a time)")
    | lfTime f < 0 ->
        Left (loc i Nothing ++ "a frame's time must not be negative, found " ++ show (lfTime f))
    | lfTime f < prev ->
        Left (loc i Nothing ++ "a frame at t = " ++ show (lfTime f) ++ " s, before the one above it ("
              ++ show prev ++ " s): frames come in time order")
    | length (lfRobots f) /= length (lhRobots h) ->
        Left (loc i Nothing ++ "a frame of " ++ show (length (lfRobots f)) ++ " robots; the header lists "
              ++ show (length (lhRobots h)))
    | (k, r) : _ <- [ kr | kr@(_, r) <- zip [1 :: Int ..] (lfRobots f), not (all finite [lrX r, lrY r, lrHeading r]) ] ->
        Left (loc i Nothing ++ "robot " ++ show k ++ " of the frame at t = " ++ show (lfTime f)
              ++ " s: its x, y and heading must be numbers, found " ++ show (lrX r) ++ ", " ++ show (lrY r)
              ++ " and " ++ show (lrHeading r))
    | (k, (x, y)) : _ <- [ kb | kb@(_, (x, y)) <- zip [1 :: Int ..] (lfBalls f), not (all finite [x, y]) ] ->
        Left (loc i Nothing ++ "ball " ++ show k ++ " of the frame at t = " ++ show (lfTime f)
              ++ " s: its x and y must be numbers, found " ++ show x ++ " and " ++ show y)
    | otherwise -> Right (Left f)
  LineSummary s
    | not (all finite [lsSimulated s, lsWallTime s]) ->
        Left (loc i Nothing ++ "the summary's simulated and wall times must be numbers, found "
              ++ show (lsSimulated s) ++ " and " ++ show (lsWallTime s))
    | Just (t, _) <- lsFalsified s, not (finite t) ->
        Left (loc i Nothing ++ "the summary's falsified time must be a number, found " ++ show t)
    | otherwise -> Right (Right s)
  LineHeader _ -> Left (loc i Nothing ++ "a second header")

-- A line's error located: a JSON error, at "line 1, column C: ..." of
-- that line, at line @i@ and column C; any other at line @i@.
located :: Locate -> Int -> Either String a -> Either String a
located loc i = either (\e -> Left (at e)) Right
  where
    at e = case span isDigit <$> stripPrefix "line 1, column " e of
      Just (c@(_ : _), ':' : ' ' : msg) -> loc i (Just (read c)) ++ msg
      _                                 -> loc i Nothing ++ e

-- | 'readLog' of a file (UTF-8), the error located as @FILE:LINE:COLUMN:@
-- (or @FILE:LINE:@), like a world file's; a file that cannot be read, or
-- is not UTF-8 (with the line and column of the first bad byte), is a
-- 'Left' too. The file is read a line at a time ('foldLogFile'); its
-- frames are all kept, in the 'RunLog'.
--
-- At most 'maxLogBytes' are read: a longer file gives @FILE: more than N
-- bytes@ and how to make a shorter log. A line longer than
-- 'maxLogLineBytes' (an endless one, such as @\/dev\/zero@'s, included)
-- gives @FILE:LINE: a line of more than N bytes@.
readLogFile :: FilePath -> IO (Either String RunLog)
readLogFile = readLogFileUpTo maxLogBytes

-- | The longest log 'readLogFile' and 'foldLogFile' read, in bytes: 256
-- MiB. A one-hour run of the default world, logged at the default frame
-- rate, is about 230 MB.
maxLogBytes :: Int
maxLogBytes = 256 * 1024 * 1024

-- | The longest line of a log that 'readLogFile' and 'foldLogFile' read,
-- in bytes: 64 MiB. A frame of 10,000 robots is about 3.8 MB, and one of
-- 100,000 robots (a world file's 'AFrobRobotSim.WorldFile.maxObjects',
-- all robots) about 38 MB; the header of a world of as many objects is
-- shorter. A line is longer only when the robots print more than some
-- 26 MB of messages in one frame period, or a world built in code holds
-- more robots. A line is read as its bytes, and only what of its value
-- is used is made ('AFrobRobotSim.Log.Records.decodeLogLineUtf8'): a
-- line of 64 MiB refused for a member it lacks takes some 70 MB of heap
-- (it took 1 to 2 GB as a 'String'), a frame of 10,000 robots some 9
-- times its bytes with the frame made of it. (A line that is made whole,
-- such as a frame of 64 MiB, still takes its value's memory, which can
-- be many times its bytes: each number of a list some 40 bytes, more
-- than a gigabyte for 64 MiB of one-digit numbers.) A longer line (a file that
-- is no log, a line without an end, such as @\/dev\/zero@'s) is refused,
-- not read.
maxLogLineBytes :: Int
maxLogLineBytes = 64 * 1024 * 1024

-- | 'readLogFile' reading at most the given number of bytes.
readLogFileUpTo :: Int -> FilePath -> IO (Either String RunLog)
readLogFileUpTo cap path = do
  r <- foldLogFileUpTo cap maxLogLineBytes path (\h -> pure (h, [])) (\(h, fs) f -> pure (h, f : fs))
  pure (fmap (\((h, fs), LogEnd ms cut) -> RunLog h (reverse fs) ms cut) r)

-- | @foldLogFile path start step@ reads a log file as 'readLogFile' does
-- (the same checks, the same errors, the same limits), a line at a time:
-- @start@ takes the header, @step@ each frame in turn, and the result is
-- the last state with how the log ends ('LogEnd': its summary, if it
-- has one, and whether its last line was cut off). What the log's
-- lines take in memory is one line's, whatever its length: a page made of
-- a log this way ('AFrobRobotSim.Replay.writeReplayFromLog') holds no
-- frame. An error found at a line comes after @step@ has taken the
-- frames before it.
foldLogFile :: FilePath -> (LogHeader -> IO s) -> (s -> LogFrame -> IO s)
            -> IO (Either String (s, LogEnd))
foldLogFile = foldLogFileUpTo maxLogBytes maxLogLineBytes

-- 'foldLogFile' with at most @cap@ bytes in all and @lineCap@ in a line.
foldLogFileUpTo :: Int -> Int -> FilePath -> (LogHeader -> IO s) -> (s -> LogFrame -> IO s)
                -> IO (Either String (s, LogEnd))
foldLogFileUpTo cap lineCap path start step = do
  opened <- try (openReading path)
  -- (only reading the file is caught: what @start@ and @step@ throw is
  -- theirs, thrown on)
  case opened of
    Left e    -> pure (Left (cannotRead path e))
    Right hdl -> readFrom hdl `finally` hClose hdl
  where
    readFrom hdl = do
      size <- either (\e -> const 0 (e :: IOException)) id <$> try (hFileSize hdl)
      if size > fromIntegral cap then pure (Left tooLong) else do
        src <- newLineReader hdl cap lineCap
        let -- the next line that is not blank, with its number and
            -- whether a newline ends it; its bytes, found to be UTF-8 here,
            -- once (it is read as bytes: as a String, a line took some 40
            -- times its length, and gigabytes)
            nextText = nextLineEnded src >>= \r -> case r of
              Left fault                  -> pure (Left (faultText fault))
              Right Nothing               -> pure (Right Nothing)
              Right (Just (i, bs, ended))
                | BC.all (\c -> c == ' ' || c == '\t' || c == '\r') bs -> nextText
                | otherwise -> pure (fmap (\u -> Just (i, u, ended)) (utf8BytesFrom name i bs))
            body h prev s = nextText >>= \r -> case r of
              Left e              -> pure (Left e)
              Right Nothing       -> pure (Right (s, LogEnd Nothing Nothing))
              Right (Just (i, l, ended))
                | cutOffUtf8 ended l -> pure (Right (s, LogEnd Nothing (Just i)))
                | otherwise -> case bodyLine loc h prev i (decodeLogLineUtf8 l) of
                    Left e          -> pure (Left e)
                    Right (Left f)  -> step s f >>= body h (lfTime f)
                    Right (Right m) -> nextText >>= \after -> pure $ case after of
                      Left e                 -> Left e
                      Right Nothing          -> Right (s, LogEnd (Just m) Nothing)
                      Right (Just (j, _, _)) -> Left (loc j Nothing ++ afterSummary)
        first <- nextText
        case first of
          Left e                     -> pure (Left e)
          Right Nothing              -> pure (Left (loc 1 Nothing ++ emptyLog))
          Right (Just (i, l, ended)) -> case headerLine loc (cutOffUtf8 ended l) i (decodeLogLineUtf8 l) of
            Left e  -> pure (Left e)
            Right h -> start h >>= body h 0
    name = displayPath path   -- (a name with control characters escaped)
    loc :: Locate
    loc i mc = name ++ ":" ++ show i ++ maybe "" (\c -> ":" ++ show c) mc ++ ": "
    tooLong = name ++ ": more than " ++ show cap ++ " bytes, more than a log is read (write a"
              ++ " shorter run, or fewer frames with --fps)"
    faultText fault = case fault of
      Unreadable e -> cannotRead path e
      TooManyBytes -> tooLong
      LongLine i -> loc i Nothing ++ "a line of more than " ++ show lineCap ++ " bytes, more than this reader"
                    ++ " takes (a frame of 100,000 robots is about 38 MB; is it a run log?)"
