{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Log
-- Description : The run log: JSON lines made from a simulation's states.
--
-- A run log is what a person needs to answer "what did my robot see and
-- do at 12.3 s?" after a headless run, and what the replay page draws
-- ("AFrobRobotSim.Replay"). Its format is documented field by field in
-- @docs/LOG.md@; the records are in "AFrobRobotSim.Log.Records".
--
-- The log is made from what 'simulate' gives, the stream of
-- 'WorldState's, one per step, and nothing else: the simulator does not
-- report wheel speeds or sensor readings, so they are recomputed here.
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

import           Control.Exception         (evaluate, uninterruptibleMask_)
import           Control.Monad.ST          (runST)
import qualified Data.ByteString.Char8     as BC
import           Data.IORef
import           Data.List                 (nub, stripPrefix)
import qualified Data.Map.Strict           as Map
import           System.IO

import           AFrob.Angle               (normalizeAngle)
import           AFrob.RobotIO             (BatteryStatus (..))
import           AFRP.Geometry
import           AFrob.Dimensions          (Position2, RobotId, RobotType)
import           AFrobRobotSim.Arena       (Arena, arenaOf)
import           AFrobRobotSim.Balls       (Ball (..))
import           AFrobRobotSim.FlatArray   (DblArr, IntArr, freezeD, freezeI, indexD, indexI, newDblArr,
                                            newIntArr, writeD, writeI)
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.Physics     (mkRobot)
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Sensors
import           AFrobRobotSim.Simulator
import           AFrobRobotSim.World
import           AFrobRobotSim.Log.Read

-- | What a log needs besides the states: the world and how it was run.
data LogConfig = LogConfig
  { lcBounds      :: Bounds                    -- ^ the world's extent, unless 'lcWorld' has an 'OTSize' (which wins)
  , lcWorld       :: WorldTemplate             -- ^ the world at time 0
  , lcDt          :: Double                    -- ^ the simulation's time step (s)
  , lcFps         :: Double                    -- ^ frames per simulated second
  , lcSeed        :: Int                       -- ^ the odometry noise's seed
  , lcCommandLine :: [String]                  -- ^ the program's name and arguments
  , lcGoals       :: [LogRect]                 -- ^ goal areas to draw, if any
  , lcScores      :: WorldState -> [(String, Int)]
    -- ^ the program's scores in a state; a rise between two steps is a
    -- @"score"@ event
  }

-- | The notes' world bounds, an empty world, dt 0.01 s, 25 fps, seed 0,
-- no command line, no goals, no scores.
defaultLogConfig :: LogConfig
defaultLogConfig = LogConfig notesBounds [] 0.01 25 0 [] [] (const [])

-- | The header line of a run.
logHeader :: LogConfig -> LogHeader
logHeader cfg = LogHeader
  { lhFormat = logFormatName, lhVersion = logFormatVersion
  , lhBounds = let Bounds x0 y0 x1 y1 = worldBoundsOr (lcBounds cfg) (lcWorld cfg)
               in LogRect ((x0 + x1) / 2) ((y0 + y1) / 2) (x1 - x0) (y1 - y0)
  , lhWalls  = [ box o | o <- world, isWall o ]
  , lhBlocks = [ box o | o@OTBlock {} <- world ]
  , lhBalls  = [ xy (otPos o) | o@OTBall {} <- world ]
  , lhBallRadius = ballDiameter / 2
  , lhGoals  = lcGoals cfg
  , lhRobots = [ LogRobotInfo (kindType k) (otRId o) (simbotDiameter / 2) (kindWheelBase k)
                              (kindWSMax k) sensorNames
               | o <- world, Just k <- [robotKindOf o] ]
  , lhRangeAngles = rangeAngles, lhRangeMax = rangeFinderMax, lhTrackerRange = trackerRange
  , lhDt = lcDt cfg, lhFps = lcFps cfg, lhSeed = lcSeed cfg, lhCommandLine = lcCommandLine cfg }
  where
    world = lcWorld cfg
    isWall o = case o of { OTVWall {} -> True; OTHWall {} -> True; _ -> False }
    box o = let Point2 x y = otPos o
                (hw, hh)   = objectHalfSize o
            in LogRect x y (2 * hw) (2 * hh)
    sensorNames = ["odometry", "bumper", "battery", "rangeFinder", "tracker", "console"]

-- | The angles of the logged range readings: front, left, back, right
-- (0, pi/2, pi, -pi/2), those of 'AFrob.rfFront' and its siblings.
rangeAngles :: [Double]
rangeAngles = [0, pi / 2, pi, -pi / 2]

xy :: Position2 -> (Double, Double)
xy (Point2 x y) = (x, y)

-- | What 'logStep' remembers between steps.
data LogState = LogState
  { stStep    :: !Int
  , stPrev    :: !(Maybe Prev)        -- what the events and a frame need of the previous step
  , stEvents  :: [LogEvent]           -- of the period so far, newest first
  , stLines   :: [String]             -- console lines of the period so far, newest first
  , stArena   :: Arena
  }

-- What the next step needs of a step: each robot's heading and whether
-- it is stuck (by robot number, in unboxed arrays), how many robots, and
-- the scores. Not the state itself: kept until the next step, each
-- state's robot records outlived a collection or two.
data Prev = Prev
  { pvHeading :: !DblArr
  , pvStuck   :: !IntArr
  , pvCount   :: {-# UNPACK #-} !Int
  , pvScores  :: [(String, Int)]
  }

-- 'Prev' of a state, given its scores (evaluated to the last character).
prevOf :: WorldState -> [(String, Int)] -> Prev
prevOf s scores = forceScores `seq` runST (do
  hs <- newDblArr (max 1 n)
  ks <- newIntArr (max 1 n) 0
  let fill !_ []       = pure ()
      fill !i (r : rs) = do
        writeD hs i (robotHeading r)
        writeI ks i (if robotStuck r then 1 else 0)
        fill (i + 1) rs
  fill 0 (wsRobots s)
  Prev <$> freezeD hs <*> freezeI ks <*> pure n <*> pure scores)
  where
    n = length (wsRobots s)
    forceScores = foldr (\(k, v) acc -> foldr seq () k `seq` v `seq` acc) () scores

-- | The state before the first step.
logStart :: LogConfig -> LogState
logStart cfg = LogState 0 Nothing [] [] (arenaOf (lcBounds cfg) (lcWorld cfg))

-- | Is step @n@ (from 0) a frame's step, at @fps@ frames per second and
-- time step @dt@: the step nearest a multiple of @1 / fps@ (and step 0)?
isFrameStep :: Double -> Double -> Int -> Bool
isFrameStep dt fps n =
  let f = fromIntegral n * dt * fps
  in n == 0 || abs (f - fromIntegral (nearest f)) * 2 < dt * fps
  where
    -- ('round', by plain arithmetic where 'roundHalfEven' is exact: the
    -- replay page's recorder asks at every step for each frame rate it
    -- keeps, and 'round' is a foreign call)
    nearest f | abs f < 1e15 = roundHalfEven f
              | otherwise    = round f :: Int

-- | Take the next step's state (the first call gets the state at time 0):
-- the new 'LogState', and the frame record when this step is a frame's.
logStep :: LogConfig -> LogState -> WorldState -> (LogState, Maybe LogFrame)
logStep cfg st s
  | isFrameStep (lcDt cfg) (lcFps cfg) n =
      (st' { stEvents = [], stLines = [] }, Just (frameOf cfg st s scores (reverse events) (reverse lines')))
  | otherwise = (st', Nothing)
  where
    n       = stStep st
    scores  = lcScores cfg s
    -- (the step's events and console lines made now, so that nothing
    -- keeps the state: left lazy until the frame, they kept every state
    -- of the frame period)
    new     = newEvents (stPrev st) s scores
    events  = foldr seq () new `seq` (new ++ stEvents st)
    lines'  = reverse (wsMessages s) ++ stLines st
    st'     = events `seq` lines' `seq`
              st { stStep = n + 1, stPrev = Just $! prevOf s scores, stEvents = events, stLines = lines' }

-- | The frames of a list of states (every step, from time 0), lazily.
logFrames :: LogConfig -> [WorldState] -> [LogFrame]
logFrames cfg = go (logStart cfg)
  where
    go _ []       = []
    go st (s : ss) = case logStep cfg st s of
      (st', Just f)  -> f : go st' ss
      (st', Nothing) -> go st' ss

-- | 'logStep' at several frame rates at once, each named by a key of the
-- caller's: for a writer that cannot yet tell which rate it will keep (the
-- replay page's recorder, which thins its page for the length the run
-- turns out to have: "AFrobRobotSim.Replay"). The frames of the rate
-- @fps@ are exactly 'logStep''s with that 'lcFps': the same steps
-- ('isFrameStep' at @fps@) and the same records, each with the events,
-- console lines and messages of its own period (the steps after that
-- rate's previous frame, up to and including its own). What a step makes
-- for every rate, its events, its console lines and its frame's instant
-- (the robots' readings, the costly part), is made once.
data LogRates k = LogRates !LogState !Int [RatePeriod k]
  -- (the step count, the previous step and the arena, the state's own
  -- period left empty; how many events and console lines the run has
  -- made; each rate's period)

-- One rate's period so far: its key, its frames a second, its events and
-- console lines (newest first), and how many events and lines the run had
-- made when it began. Two rates whose periods began at the same count hold
-- the same events and lines: whatever was made since.
data RatePeriod k = RatePeriod k !Double [LogEvent] [String] !Int

-- | The rates, as (key, frames a second), before the first step.
logRatesStart :: LogConfig -> [(k, Double)] -> LogRates k
logRatesStart cfg rates = LogRates (logStart cfg) 0 [ RatePeriod k fps [] [] 0 | (k, fps) <- rates ]

-- | Only the rates whose keys pass the test, from now on (a rate dropped
-- costs nothing more; its period is forgotten).
logRatesKeep :: (k -> Bool) -> LogRates k -> LogRates k
logRatesKeep keep (LogRates st made rates) = LogRates st made [ r | r@(RatePeriod k _ _ _ _) <- rates, keep k ]

-- | Take the next step's state (the first call gets the state at time 0):
-- the new 'LogRates', and this step's frames, one for each group of the
-- rates whose frame the step is and whose periods hold the same events and
-- lines, with the keys of the group's rates (in the order the rates were
-- given; the groups by their first rate). So each frame is
-- 'logStep''s at each of its rates.
logRatesStep :: LogConfig -> LogRates k -> WorldState -> (LogRates k, [([k], LogFrame)])
logRatesStep cfg (LogRates st made rates) s = (next, frames)
  where
    n        = stStep st
    scores   = lcScores cfg s
    -- (made now, as 'logStep' makes them, so that nothing keeps the state)
    new      = newEvents (stPrev st) s scores
    newLines = reverse (wsMessages s)
    made'    = made + length new + length newLines
    grown | made' == made = rates
          | otherwise     = map grow rates
    grow (RatePeriod k fps evs ls since) =
      let evs' = new ++ evs
          ls'  = newLines ++ ls
      in evs' `seq` ls' `seq` RatePeriod k fps evs' ls' since
    isFrame (RatePeriod _ fps _ _ _) = isFrameStep (lcDt cfg) fps n
    -- (each rate asked once; most steps are no rate's frame)
    framed = [ (r, isFrame r) | r <- grown ]
    firing = [ r | (r, True) <- framed ]
    rates' | null firing = grown
           | otherwise   = [ if f then RatePeriod k fps [] [] made' else r | (r@(RatePeriod k fps _ _ _), f) <- framed ]
    st'    = st { stStep = n + 1, stPrev = Just $! prevOf s scores }
    next   = foldr seq () new `seq` foldr seq () rates' `seq` LogRates st' made' rates'
    instant = frameInstant cfg st s scores
    frames = [ (keys, periodFrame instant (reverse evs) (reverse ls))
             | (keys, evs, ls) <- samePeriods firing ]
    -- (the rates grouped by the count their periods began at)
    samePeriods [] = []
    samePeriods (RatePeriod k _ evs ls since : rest) =
      (k : [ k' | RatePeriod k' _ _ _ since' <- rest, since' == since ], evs, ls)
      : samePeriods [ r | r@(RatePeriod _ _ _ _ since') <- rest, since' /= since ]

-- Events from one step to the next (newest first): a robot that got
-- stuck, a score that rose.
newEvents :: Maybe Prev -> WorldState -> [(String, Int)] -> [LogEvent]
newEvents Nothing _ _ = []
newEvents (Just p) s now = reverse (bumps ++ scores)
  where
    -- (to a nanosecond, as a frame's other times are: 2.28, not
    -- 2.2800000000000002)
    t = roundTo 1e9 (wsTime s)
    bumps = [ LogEvent t "bump" (Just (robotType r, robotId r))
                (robotType r ++ " " ++ show (robotId r) ++ " bumped into something")
            | (i, r) <- zip [0 .. pvCount p - 1] (wsRobots s), robotStuck r, indexI (pvStuck p) i == 0 ]
    scores = [ LogEvent t "score" Nothing (k ++ " scores: " ++ show v)
             | (k, v) <- now, maybe True (< v) (lookup k (pvScores p)) , v > 0 ]

-- (given the state's scores, which the step has made)
frameOf :: LogConfig -> LogState -> WorldState -> [(String, Int)] -> [LogEvent] -> [String] -> LogFrame
frameOf cfg st s scores = periodFrame (frameInstant cfg st s scores)

-- A frame without its period: the frame with no events, console lines or
-- messages, and its robots' names (type and id, in its robots' order).
data Instant = Instant LogFrame [(RobotType, RobotId)]

-- The frame of an instant with the events and console lines of its period
-- (oldest first): each robot's messages, and the lines no robot printed
-- ('linesByRobot').
periodFrame :: Instant -> [LogEvent] -> [String] -> LogFrame
periodFrame (Instant f names) events lines' =
  f { lfRobots = zipWith withMessages names (lfRobots f), lfEvents = events, lfConsole = console }
  where
    (messagesOf, console) = linesByRobot names lines'
    withMessages k r = case messagesOf k of
      [] -> r
      ms -> r { lrMessages = ms }

-- (given the state's scores, which the step has made)
frameInstant :: LogConfig -> LogState -> WorldState -> [(String, Int)] -> Instant
frameInstant cfg st s scores = Instant LogFrame
  { lfTime = roundTo 1e9 (wsTime s)
  , lfRobots = zipWith robotOf [0 ..] (wsRobots s)
  , lfBalls = [ (r6 x, r6 y) | (x, y) <- map xy (wsBalls s) ]
  , lfScores = scores
  , lfEvents = []
  , lfConsole = [] }
  [ (robotType r, robotId r) | r <- wsRobots s ]
  where
    physical = [ mkRobot (kindOfType (robotType r)) (robotId r) (robotPos r) (robotHeading r)
                         (robotSpeed r) (robotStuck r) (robotCharge r) | r <- wsRobots s ]
    ctx = SenseContext (stArena st) physical [ Ball p zeroVector | p <- wsBalls s ]
    robotOf i r =
      let input = senseRobot ctx i (robotOdometry r, robotHeading r) Nothing
          omega = case stPrev st of
            Just p | i < pvCount p, lcDt cfg > 0 ->
              normalizeAngle (robotHeading r - indexD (pvHeading p) i) / lcDt cfg
            _ -> 0
          half = kindWheelBase (kindOfType (robotType r)) / 2
          v = robotSpeed r
          Point2 ox oy = robotOdometry r
          Point2 x y = robotPos r
      in LogRobot
           { lrX = r6 x, lrY = r6 y, lrHeading = r6 (robotHeading r)
           , lrWheelLeft = r6 (v - omega * half), lrWheelRight = r6 (v + omega * half)
           , lrSpeed = r6 v, lrRotVel = r6 omega, lrBumper = robotStuck r
           , lrRange = map (r6 . siRange input) rangeAngles
           , lrSeenRobots = [ (ty, k, r6 a, r6 d) | (ty, k, a, d) <- siRobots input ]
           , lrSeenBalls  = [ (r6 a, r6 d) | (a, d) <- siBalls input ]
           , lrBattery = case robotBattery r of
               BSHigh -> "high"; BSLow -> "low"; BSCritical -> "critical"
           , lrCharge = r6 (robotCharge r), lrOdoX = r6 ox, lrOdoY = r6 oy
           , lrMessages = [] }
    kindOfType ty = if ty == kindType SimbotB then SimbotB else SimbotA

-- Frame values are rounded to a millionth (of a metre, radian, m/s):
-- far finer than anything the page can show or a controller can act on,
-- and it halves the size of a log.
r6 :: Double -> Double
r6 = roundTo 1e6

-- | @roundTo k x@: @x@ rounded to a multiple of @1 / k@, a tie to the
-- even multiple (non-finite numbers and numbers too large for the
-- multiple to be exact stay as they are: NaN fails the comparison). The
-- log writes its frames' times @roundTo 1e9@ (531 steps of 0.01 s are
-- 5.31 s, not 5.3100000000000005) and their other values @roundTo 1e6@. The multiple's count is at most 10^15, so an 'Int' holds
-- it exactly and converts back exactly. (An 'Integer' and the foreign
-- calls of 'isNaN' and 'isInfinite' cost 2,500 instructions a
-- robot-frame in a replay page of 1000 robots.)
roundTo :: Double -> Double -> Double
roundTo k x
  | not (abs x * k <= 1e15) = x
  | otherwise               = fromIntegral (roundHalfEven (x * k)) / k

-- | 'round' to an 'Int' (to the nearest whole number, a tie to the even
-- one) of a number of magnitude at most 10^15, as the log rounds its
-- values to millionths; beyond that magnitude, or for NaN, the result is
-- unspecified (the log keeps such values as they are). Plain arithmetic:
-- GHC's 'round' to an 'Int' is a foreign call of C's @rint@, about 800
-- instructions a robot-frame of a 1000-robot page with its call. Exact:
-- below 2^53 the truncation and the fraction it leaves are exact.
--
-- >>> map roundHalfEven [0.5, 1.5, 2.5, -0.5, -1.5, 2.4999, -2.6]
-- [0,2,2,0,-2,2,-3]
roundHalfEven :: Double -> Int
roundHalfEven y
  | d > 0.5 || (d == 0.5 && odd t)   = t + 1
  | d < -0.5 || (d == -0.5 && odd t) = t - 1
  | otherwise                        = t
  where
    t = truncate y :: Int
    d = y - fromIntegral t

-- | The console lines of a period taken apart, given the robots (type and
-- id) of the world: each robot's own lines as (time, text), in the order
-- printed (a function of the robot), and the lines no robot of the world
-- printed, in order. The simulator writes a robot's line as @[t]
-- Type.id: text@ ('wsMessages'); a line is a robot's when it is exactly
-- that, with the robot's type, its id as 'show' writes it and a time
-- 'reads' reads whole. Each line is parsed once (not once per robot: in a
-- crowd where every robot prints, that was quadratic in the robots).
--
-- >>> let (own, rest) = linesByRobot [("SimbotA", 1)] ["[0.50] SimbotA.1: hello", "[0.50] SimbotB.7: hi", "plain"]
-- >>> (own ("SimbotA", 1), rest)
-- ([(0.5,"hello")],["[0.50] SimbotB.7: hi","plain"])
linesByRobot :: [(RobotType, RobotId)] -> [String] -> ((RobotType, RobotId) -> [(Double, String)], [String])
linesByRobot robots ls = (\k -> Map.findWithDefault [] k owned, console)
  where
    known  = Map.fromList [ (k, ()) | k <- robots ]
    types  = nub (map fst robots)
    parsed = [ (l, [ (k, m) | (k, m) <- candidates l, Map.member k known ]) | l <- ls ]
    owned  = Map.map reverse (Map.fromListWith (++) [ (k, [m]) | (_, ms) <- parsed, (k, m) <- ms ])
    console = [ l | (l, []) <- parsed ]
    -- every (robot, message) the line can be read as, one per type it
    -- can start with (types are names without a dot, so at most one)
    candidates l = case l of
      '[' : rest | (ts, ']' : ' ' : body) <- break (== ']') rest
                 , [(t, "")] <- reads ts
                 -> [ ((ty, k), (t, txt))
                    | ty <- types
                    , Just idAndText <- [stripPrefix (ty ++ ".") body]
                    , (idStr, ':' : ' ' : txt) <- [break (== ':') idAndText]
                    , [(k, "")] <- [reads idStr]
                    , show k == idStr ]
      _ -> []

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
