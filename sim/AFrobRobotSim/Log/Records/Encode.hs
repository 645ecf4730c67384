-- |
-- Module      : AFrobRobotSim.Log.Records.Encode
-- Description : A run log's line as a JSON value, and as text.
--
-- 'logLineJSON' says which members a line has, and in which order;
-- 'encodeLogLine' writes its text. "AFrobRobotSim.Log.Records.Bytes"
-- writes the same characters as bytes, a frame without this value. Part
-- of "AFrobRobotSim.Log.Records", which re-exports both.
module AFrobRobotSim.Log.Records.Encode
  ( logLineJSON
  , encodeLogLine
  ) where

import           AFrobRobotSim.JSON
import           AFrobRobotSim.Log.Records.Types

-- | A line as a JSON object (its @kind@ is @header@, @frame@ or
-- @summary@).
logLineJSON :: LogLine -> JSON
logLineJSON (LineHeader h) = JObject
  [ ("kind", JString "header"), ("format", JString (lhFormat h)), ("version", int (lhVersion h))
  , ("bounds", rect (lhBounds h)), ("walls", JArray (map rect (lhWalls h)))
  , ("blocks", JArray (map rect (lhBlocks h))), ("balls", JArray (map xy (lhBalls h)))
  , ("ballRadius", num (lhBallRadius h)), ("goals", JArray (map rect (lhGoals h)))
  , ("robots", JArray (map robotInfo (lhRobots h)))
  , ("rangeAngles", JArray (map num (lhRangeAngles h))), ("rangeMax", num (lhRangeMax h))
  , ("trackerRange", num (lhTrackerRange h)), ("dt", num (lhDt h)), ("fps", num (lhFps h))
  , ("seed", int (lhSeed h)), ("commandLine", JArray (map JString (lhCommandLine h))) ]
  where
    robotInfo r = JObject
      [ ("type", JString (riType r)), ("id", int (riId r)), ("radius", num (riRadius r))
      , ("wheelBase", num (riWheelBase r)), ("maxWheelSpeed", num (riMaxWheelSpeed r))
      , ("sensors", JArray (map JString (riSensors r))) ]
logLineJSON (LineFrame f) = JObject
  [ ("kind", JString "frame"), ("t", num (lfTime f)), ("robots", JArray (map robot (lfRobots f)))
  , ("balls", JArray (map xy (lfBalls f))), ("scores", scores (lfScores f))
  , ("events", JArray (map event (lfEvents f))), ("console", JArray (map JString (lfConsole f))) ]
  where
    robot r = JObject
      [ ("x", num (lrX r)), ("y", num (lrY r)), ("heading", num (lrHeading r))
      , ("wheels", JArray [num (lrWheelLeft r), num (lrWheelRight r)])
      , ("v", num (lrSpeed r)), ("omega", num (lrRotVel r)), ("bumper", JBool (lrBumper r))
      , ("range", JArray (map num (lrRange r)))
      , ("seenRobots", JArray [ JArray [JString ty, int i, num a, num d] | (ty, i, a, d) <- lrSeenRobots r ])
      , ("seenBalls", JArray (map xy (lrSeenBalls r)))
      , ("battery", JString (lrBattery r)), ("charge", num (lrCharge r))
      , ("odometry", xy (lrOdoX r, lrOdoY r))
      , ("messages", JArray [ JArray [num t, JString m] | (t, m) <- lrMessages r ]) ]
    event e = JObject ([ ("t", num (evTime e)), ("kind", JString (evKind e)) ]
                       ++ maybe [] (\(ty, i) -> [("robot", JArray [JString ty, int i])]) (evRobot e)
                       ++ [ ("text", JString (evText e)) ])
logLineJSON (LineSummary s) = JObject $
  [ ("kind", JString "summary"), ("simulated", num (lsSimulated s)), ("steps", int (lsSteps s))
  , ("frames", int (lsFrames s)), ("wallTime", num (lsWallTime s))
  , ("interrupted", JBool (lsInterrupted s)), ("failure", maybe JNull JString (lsFailure s)) ]
  ++ maybe [] (\(t, text) -> [("falsified", JObject [("t", num t), ("text", JString text)])]) (lsFalsified s)
  ++ [ ("scores", scores (lsScores s)) ]

num :: Double -> JSON
num = JNumber

int :: Int -> JSON
int = JNumber . fromIntegral

xy :: (Double, Double) -> JSON
xy (x, y) = JArray [num x, num y]

rect :: LogRect -> JSON
rect (LogRect x y w h) = JObject [("x", num x), ("y", num y), ("width", num w), ("height", num h)]

scores :: [(String, Int)] -> JSON
scores ss = JObject [ (k, int n) | (k, n) <- ss ]

-- | A line's JSON text, one line without its newline.
encodeLogLine :: LogLine -> String
encodeLogLine = encodeJSON . logLineJSON
