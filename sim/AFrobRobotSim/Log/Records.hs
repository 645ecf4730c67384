{-# LANGUAGE MagicHash #-}
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

import qualified Data.ByteString          as BS
import qualified Data.ByteString.Char8    as BC
import qualified Data.ByteString.Builder  as B
import qualified Data.ByteString.Builder.Internal as BI
import qualified Data.ByteString.Builder.Prim as P
import           Data.ByteString.Builder.Prim.Internal (boundedPrim, runB)
import qualified Data.ByteString.Lazy     as BL
import           Data.Word                (Word8)
import           Foreign.Marshal.Utils    (copyBytes)
import           Foreign.Ptr              (Ptr, plusPtr)
import           Foreign.Storable         (pokeByteOff)
import           GHC.Exts                 (Addr#, Int (I#), Ptr (Ptr), cstringLength#)

import           AFrobRobotSim.JSON
import           AFrobRobotSim.UTF8       (Utf8)

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

-- | The last line: the same facts as the summary the runner prints.
data LogSummary = LogSummary
  { lsSimulated   :: !Double       -- ^ simulated time (s)
  , lsSteps       :: !Int          -- ^ samples stepped, the one at time 0 included (the steps after time 0, plus one)
  , lsFrames      :: !Int          -- ^ frame lines written
  , lsWallTime    :: !Double       -- ^ wall-clock time of the run (s)
  , lsInterrupted :: !Bool         -- ^ stopped by Ctrl-C
  , lsFailure     :: Maybe String
    -- ^ a controller's failure, as printed (@displayException@ of the
    -- 'AFrobRobotSim.Simulator.ControllerError', which names the robot
    -- and the time): the failing step has no state, so no frame shows it
  , lsScores      :: [(String, Int)] -- ^ final scores, if any
  } deriving (Eq, Show)

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
logLineJSON (LineSummary s) = JObject
  [ ("kind", JString "summary"), ("simulated", num (lsSimulated s)), ("steps", int (lsSteps s))
  , ("frames", int (lsFrames s)), ("wallTime", num (lsWallTime s))
  , ("interrupted", JBool (lsInterrupted s)), ("failure", maybe JNull JString (lsFailure s))
  , ("scores", scores (lsScores s)) ]

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

-- | One line's JSON text as bytes (ASCII), evaluated to the last one: the
-- characters of 'encodeLogLine', made without a 'String'; a frame's made
-- without its 'JSON' value too (a run log and a replay page write 25
-- frames a simulated second by default, with some twenty numbers a robot
-- in each).
encodeLogLineBytes :: LogLine -> BS.ByteString
encodeLogLineBytes l = BL.toStrict (B.toLazyByteString (case l of
  LineFrame f -> frameBuilder f
  _           -> encodeJSONBuilder (logLineJSON l)))

-- A frame's JSON text, written member by member: the characters of
-- 'encodeJSONBuilder' of its 'logLineJSON' (the members in that order).
frameBuilder :: LogFrame -> B.Builder
frameBuilder f =
  lit "{\"kind\":\"frame\",\"t\":" <> numB (lfTime f)
  <> lit ",\"robots\":[" <> commas robot (lfRobots f)
  <> lit "],\"balls\":[" <> pairs (lfBalls f)
  <> lit "],\"scores\":{" <> commas score (lfScores f)
  <> lit "},\"events\":[" <> commas event (lfEvents f)
  <> lit "],\"console\":[" <> commas strB (lfConsole f)
  <> lit "]}"
  where
    -- (the literal pieces are packed once: each is a constant)
    lit = B.byteString . BC.pack
    numB = numberBuilder
    intB = numberBuilder . fromIntegral   -- (as the 'JSON' value has it: a number)
    strB = stringBuilder
    comma = B.char7 ','
    commas _ []       = mempty
    commas g (x : xs) = g x <> foldr (\y acc -> comma <> g y <> acc) mempty xs
    score (k, n) = strB k <> B.char7 ':' <> intB n
    -- A robot: the usual one (short plain types and battery) in one
    -- write ('writeRobot'), then its messages. Any other: its members up
    -- to the range finders' readings as one bounded write, the lists as
    -- loops of bounded writes, and the members between and after them
    -- likewise.
    robot r
      | all (isShortPlain . (\(ty, _, _, _) -> ty)) (lrSeenRobots r) && isShortPlain (lrBattery r) =
          writeAtMost (robotBound r) (writeRobot r) <> commas message (lrMessages r) <> lit "]}"
      | otherwise =
      P.primBounded robotHead r <> numbers (lrRange r)
      <> lit "],\"seenRobots\":[" <> commas seen (lrSeenRobots r)
      <> lit "],\"seenBalls\":[" <> pairs (lrSeenBalls r)
      <> lit "],\"battery\":" <> strB (lrBattery r)
      <> P.primBounded robotTail r
      <> commas message (lrMessages r)
      <> lit "]}"
    seen e@(ty, _, _, _) = B.char7 '[' <> strB ty <> P.primBounded seenRest e
    numbers []       = mempty
    numbers (x : xs) = P.primBounded numberPrim x <> P.primMapListBounded commaNumber xs
    pairs []       = mempty
    pairs (p : ps) = P.primBounded pairPrim p <> P.primMapListBounded commaPair ps
    message (t, m) = B.char7 '[' <> numB t <> comma <> strB m <> B.char7 ']'
    event e = lit "{\"t\":" <> numB (evTime e) <> lit ",\"kind\":" <> strB (evKind e)
              <> maybe mempty (\(ty, i) -> lit ",\"robot\":[" <> strB ty <> comma <> intB i <> B.char7 ']')
                       (evRobot e)
              <> lit ",\"text\":" <> strB (evText e) <> B.char7 '}'

-- A robot's members up to its messages (the opening bracket of
-- @messages@), when its seen robots' types and its battery are short
-- plain strings (always, in a simulator's log), in one write of at most
-- 'robotBound' bytes: the bytes of 'frameBuilder''s general case (the
-- same writes, one after the other, with no builder piece between them).
-- With a builder piece for each member and list element, a page of 1000
-- robots spent about 26,400 instructions a robot-frame encoding (and
-- allocated 6.8 KB); about 21,700 so.
writeRobot :: LogRobot -> Ptr Word8 -> IO (Ptr Word8)
writeRobot r op0 =
  runB robotHead r op0 >>= numbersAt (lrRange r)
  >>= litAt "],\"seenRobots\":["# >>= listAt seenAt (lrSeenRobots r)
  >>= litAt "],\"seenBalls\":["# >>= listAt (runB pairPrim) (lrSeenBalls r)
  >>= litAt "],\"battery\":"# >>= runB shortStringPrim (lrBattery r)
  >>= runB robotTail r
  where
    numbersAt []       op = pure op
    numbersAt (x : xs) op = numAt x op >>= listRest numAt xs
    seenAt e@(ty, _, _, _) op = charAt '[' op >>= runB shortStringPrim ty >>= runB seenRest e
    listAt _ []       op = pure op
    listAt w (x : xs) op = w x op >>= listRest w xs
    listRest _ []       op = pure op
    listRest w (x : xs) op = charAt ',' op >>= w x >>= listRest w xs

-- The most bytes 'writeRobot' writes: its constants (73 before the range
-- readings, 16, 15 and 12 between the lists, 38 after the battery), 10
-- numbers of at most 32 bytes, and for each reading a comma and a number,
-- for each seen robot a comma, a bracket, a quoted short string and
-- 'seenRest', for each seen ball a comma and 'pairPrim', for the battery
-- a quoted short string.
robotBound :: LogRobot -> Int
robotBound r = 73 + 16 + 15 + 12 + 38 + 10 * 32
               + 33 * length (lrRange r)
               + (2 + shortString + 2 + 4 + 3 * 32) * length (lrSeenRobots r)
               + (1 + 3 + 2 * 32) * length (lrSeenBalls r)
               + (shortString + 2)

-- A write of at most @n@ bytes, @n@ known when it is written (a
-- 'P.BoundedPrim' needs it before): room for @n@ bytes is made, then the
-- write is run in it.
writeAtMost :: Int -> (Ptr Word8 -> IO (Ptr Word8)) -> B.Builder
writeAtMost n w = BI.ensureFree n <> BI.builder step
  where
    step k (BI.BufferRange op ope) = w op >>= \op' -> k (BI.BufferRange op' ope)

-- The bounded writes of 'frameBuilder'. Each writes constants (ASCII
-- literals, copied whole) and numbers ('numberPrim', at most 32 bytes
-- each) straight into the buffer, within its bound.

-- A robot's members before its range finders' readings, to the opening
-- bracket of @range@: 73 bytes of constants and 7 numbers.
robotHead :: P.BoundedPrim LogRobot
robotHead = boundedPrim (73 + 7 * 32) $ \r op ->
  litAt "{\"x\":"# op >>= numAt (lrX r) >>= litAt ",\"y\":"# >>= numAt (lrY r)
  >>= litAt ",\"heading\":"# >>= numAt (lrHeading r)
  >>= litAt ",\"wheels\":["# >>= numAt (lrWheelLeft r) >>= charAt ',' >>= numAt (lrWheelRight r)
  >>= litAt "],\"v\":"# >>= numAt (lrSpeed r) >>= litAt ",\"omega\":"# >>= numAt (lrRotVel r)
  >>= (if lrBumper r then litAt ",\"bumper\":true"# else litAt ",\"bumper\":false"#)
  >>= litAt ",\"range\":["#

-- A robot's members after its battery, to the opening bracket of
-- @messages@: 38 bytes of constants and 3 numbers.
robotTail :: P.BoundedPrim LogRobot
robotTail = boundedPrim (38 + 3 * 32) $ \r op ->
  litAt ",\"charge\":"# op >>= numAt (lrCharge r)
  >>= litAt ",\"odometry\":["# >>= numAt (lrOdoX r) >>= charAt ',' >>= numAt (lrOdoY r)
  >>= litAt "],\"messages\":["#

-- A seen robot after its type: its number, bearing and distance, and the
-- closing bracket.
seenRest :: P.BoundedPrim (String, Int, Double, Double)
seenRest = boundedPrim (4 + 3 * 32) $ \(_, i, a, d) op ->
  charAt ',' op >>= numAt (fromIntegral i) >>= charAt ',' >>= numAt a >>= charAt ',' >>= numAt d
  >>= charAt ']'

-- A pair of numbers in brackets, and the same after a comma.
pairPrim, commaPair :: P.BoundedPrim (Double, Double)
pairPrim = boundedPrim (3 + 2 * 32) $ \(x, y) op ->
  charAt '[' op >>= numAt x >>= charAt ',' >>= numAt y >>= charAt ']'
commaPair = boundedPrim (4 + 2 * 32) $ \p op -> charAt ',' op >>= runB pairPrim p

-- A number after a comma.
commaNumber :: P.BoundedPrim Double
commaNumber = boundedPrim (1 + 32) $ \x op -> charAt ',' op >>= numAt x

-- An ASCII literal's bytes (its length is a constant GHC folds), then the
-- pointer after them.
litAt :: Addr# -> Ptr Word8 -> IO (Ptr Word8)
litAt a op = let n = I# (cstringLength# a) in copyBytes op (Ptr a) n >> pure (op `plusPtr` n)
{-# INLINE litAt #-}

-- One ASCII character.
charAt :: Char -> Ptr Word8 -> IO (Ptr Word8)
charAt c op = pokeByteOff op 0 (fromIntegral (fromEnum c) :: Word8) >> pure (op `plusPtr` 1)
{-# INLINE charAt #-}

-- A number ('numberPrim').
numAt :: Double -> Ptr Word8 -> IO (Ptr Word8)
numAt = runB numberPrim
{-# INLINE numAt #-}

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
      <*> (memberMaybe "failure" v >>= traverse asString) <*> field "scores" toScores

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
