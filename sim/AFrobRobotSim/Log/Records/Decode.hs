-- |
-- Module      : AFrobRobotSim.Log.Records.Decode
-- Description : A run log's line read back from its JSON, as text or as
--               bytes.
--
-- 'logLineFromJSON' is 'AFrobRobotSim.Log.Records.Encode.logLineJSON'
-- undone: it takes the members that function writes, and says which one is
-- missing or of the wrong type. 'decodeLogLine', 'decodeLogLineBytes'
-- and 'decodeLogLineUtf8' parse a line's text first. Part of
-- "AFrobRobotSim.Log.Records", which re-exports all four; "AFrobRobotSim.Log.Read" reads whole logs with
-- them.
module AFrobRobotSim.Log.Records.Decode
  ( logLineFromJSON
  , decodeLogLine
  , decodeLogLineBytes
  , decodeLogLineUtf8
  ) where

import qualified Data.ByteString          as BS

import           AFrobRobotSim.JSON
import           AFrobRobotSim.Log.Records.Types
import           AFrobRobotSim.UTF8       (Utf8)

-- | Parse one line's text ('parseJSON', then 'logLineFromJSON').
decodeLogLine :: String -> Either String LogLine
decodeLogLine txt = parseJSON txt >>= logLineFromJSON

-- | Parse one line's bytes, as UTF-8 ('parseJSONBytes', then
-- 'logLineFromJSON'): what 'decodeLogLine' gives of the text the bytes
-- are, errors included. The line's value is made as it is read, and what
-- 'logLineFromJSON' does not look at is not made: a line refused for a
-- member it lacks costs its bytes, not some 40 times their number as a
-- 'String' and its parsed value did.
decodeLogLineBytes :: BS.ByteString -> Either String LogLine
decodeLogLineBytes bs = parseJSONBytes bs >>= logLineFromJSON

-- | 'decodeLogLineBytes' of a line already found to be UTF-8
-- ('parseJSONUtf8'): the same line or error, its UTF-8 not checked again.
decodeLogLineUtf8 :: Utf8 -> Either String LogLine
decodeLogLineUtf8 u = parseJSONUtf8 u >>= logLineFromJSON

-- | A line from its JSON object, or what is missing or wrong. A header's
-- version is not checked here (see 'AFrobRobotSim.Log.readLog').
logLineFromJSON :: JSON -> Either String LogLine
logLineFromJSON v = do
  k <- member "kind" v >>= asString
  case k of
    "header"  -> LineHeader <$> header
    "frame"   -> LineFrame <$> frame
    "summary" -> LineSummary <$> summary
    _         -> Left ("unknown kind of line " ++ show k)
  where
    field f p = member f v >>= p
    header = LogHeader <$> field "format" asString <*> field "version" asInt
      <*> field "bounds" toRect <*> field "walls" (listOf toRect) <*> field "blocks" (listOf toRect)
      <*> field "balls" (listOf toXY) <*> field "ballRadius" asNumber <*> field "goals" (listOf toRect)
      <*> field "robots" (listOf robotInfo) <*> field "rangeAngles" (listOf asNumber)
      <*> field "rangeMax" asNumber <*> field "trackerRange" asNumber <*> field "dt" asNumber
      <*> field "fps" asNumber <*> field "seed" asInt <*> field "commandLine" (listOf asString)
    robotInfo r = LogRobotInfo <$> (member "type" r >>= asString) <*> (member "id" r >>= asInt)
      <*> (member "radius" r >>= asNumber) <*> (member "wheelBase" r >>= asNumber)
      <*> (member "maxWheelSpeed" r >>= asNumber) <*> (member "sensors" r >>= listOf asString)
    frame = LogFrame <$> field "t" asNumber <*> field "robots" (listOf robot)
      <*> field "balls" (listOf toXY) <*> field "scores" toScores <*> field "events" (listOf event)
      <*> field "console" (listOf asString)
    robot r = do
      let f name p = member name r >>= p
      (wl, wr) <- f "wheels" toXY
      (ox, oy) <- f "odometry" toXY
      r' <- LogRobot <$> f "x" asNumber <*> f "y" asNumber <*> f "heading" asNumber <*> pure wl <*> pure wr
        <*> f "v" asNumber <*> f "omega" asNumber <*> f "bumper" asBool <*> f "range" (listOf asNumber)
        <*> f "seenRobots" (listOf seenRobot) <*> f "seenBalls" (listOf toXY) <*> f "battery" asString <*> f "charge" asNumber
        <*> pure ox <*> pure oy <*> f "messages" (listOf message)
      -- (made now: left to be made when used, a robot held its fields
      -- one by one, boxed, and the steps of putting them together)
      pure $! r'
    message m = asArray m >>= \xs -> case xs of
      [t, s] -> (,) <$> asNumber t <*> asString s
      _      -> Left "expected a message as [time, text]"
    seenRobot x = asArray x >>= \xs -> case xs of
      [ty, i, a, d] -> (,,,) <$> asString ty <*> asInt i <*> asNumber a <*> asNumber d
      _             -> Left "expected a sighting as [type, id, angle, distance]"
    event e = LogEvent <$> (member "t" e >>= asNumber) <*> (member "kind" e >>= asString)
      <*> (memberMaybe "robot" e >>= traverse robotRef) <*> (member "text" e >>= asString)
    robotRef r = asArray r >>= \xs -> case xs of
      [ty, i] -> (,) <$> asString ty <*> asInt i
      _       -> Left "expected a robot as [type, id]"
    summary = LogSummary <$> field "simulated" asNumber <*> field "steps" asInt
      <*> field "frames" asInt <*> field "wallTime" asNumber <*> field "interrupted" asBool
      <*> (memberMaybe "failure" v >>= traverse asString) <*> (memberMaybe "falsified" v >>= traverse falsified)
      <*> field "scores" toScores
    falsified f = (,) <$> (member "t" f >>= asNumber) <*> (member "text" f >>= asString)

listOf :: (JSON -> Either String a) -> JSON -> Either String [a]
listOf p v = asArray v >>= traverse p

toXY :: JSON -> Either String (Double, Double)
toXY v = asArray v >>= \xs -> case xs of
  [x, y] -> (,) <$> asNumber x <*> asNumber y
  _      -> Left "expected a pair [x, y]"

toRect :: JSON -> Either String LogRect
toRect v = LogRect <$> (member "x" v >>= asNumber) <*> (member "y" v >>= asNumber)
  <*> (member "width" v >>= asNumber) <*> (member "height" v >>= asNumber)

toScores :: JSON -> Either String [(String, Int)]
toScores (JObject kvs) = traverse (\(k, n) -> (,) k <$> asInt n) kvs
toScores _             = Left "expected scores as an object"
