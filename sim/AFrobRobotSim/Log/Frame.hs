{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Log.Frame
-- Description : A frame's record made from a state: the robots' readings,
--               the events of a step, the console lines by robot, and the
--               rounding of the values.
--
-- A frame is made in two parts. Its instant ('frameInstant') is what the
-- state shows at the frame's step: the robots' poses, their sensors'
-- readings ('AFrobRobotSim.Sensors.senseRobot', exactly what the
-- controllers saw), wheel speeds and rotational velocity from the
-- heading's change over the step that ended at the instant (0 at time 0),
-- the balls and the scores. Its period ('periodFrame') adds the events
-- ('newEvents', step by step) and the console lines of the steps since the
-- previous frame, each robot's own lines ('linesByRobot') as its messages.
-- What a step needs of the step before it is a 'Prev' ('prevOf'), not the
-- state itself.
--
-- The values are rounded ('roundTo'): positions, angles, speeds and the
-- charge to a millionth, times to a nanosecond. Part of
-- "AFrobRobotSim.Log", which re-exports 'linesByRobot', 'roundTo' and
-- 'roundHalfEven'; "AFrobRobotSim.Log.Step" and
-- "AFrobRobotSim.Log.Rates" make frames with the rest.
module AFrobRobotSim.Log.Frame
  ( -- * The previous step
    Prev
  , prevOf
    -- * Events
  , newEvents
    -- * Frames
  , Instant
  , frameInstant
  , periodFrame
  , frameOf
  , linesByRobot
    -- * The values' rounding
  , roundTo
  , roundHalfEven
  ) where

import           Control.Monad.ST          (runST)
import           Data.List                 (nub, stripPrefix)
import qualified Data.Map.Strict           as Map

import           AFrob.Angle               (normalizeAngle)
import           AFrob.RobotIO             (BatteryStatus (..))
import           AFRP.Geometry
import           AFrob.Dimensions          (RobotId, RobotType)
import           AFrobRobotSim.Arena       (Arena)
import           AFrobRobotSim.Balls       (Ball (..))
import           AFrobRobotSim.FlatArray   (DblArr, IntArr, freezeD, freezeI, indexD, indexI, newDblArr,
                                            newIntArr, writeD, writeI)
import           AFrobRobotSim.Log.Config
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.Physics     (mkRobot)
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Sensors
import           AFrobRobotSim.Simulator
import           AFrobRobotSim.World

-- | What the next step needs of a step: each robot's heading and whether
-- it is stuck (by robot number, in unboxed arrays), how many robots, and
-- the scores. Not the state itself: kept until the next step, each
-- state's robot records outlived a collection or two.
data Prev = Prev
  { pvHeading :: !DblArr
  , pvStuck   :: !IntArr
  , pvCount   :: {-# UNPACK #-} !Int
  , pvScores  :: [(String, Int)]
  }

-- | 'Prev' of a state, given its scores (evaluated to the last character).
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

-- | Events from one step to the next (newest first), given the previous
-- step ('Nothing' at time 0, which has none), the state and its scores: a
-- robot that got stuck, a score that rose.
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

-- | The frame of a state, given the world's arena, the previous step, the
-- state's scores (which the step has made) and the events and console
-- lines of its period (oldest first): 'periodFrame' of 'frameInstant'.
frameOf :: LogConfig -> Arena -> Maybe Prev -> WorldState -> [(String, Int)] -> [LogEvent] -> [String] -> LogFrame
frameOf cfg arena prev s scores = periodFrame (frameInstant cfg arena prev s scores)

-- | A frame without its period: the frame with no events, console lines or
-- messages, and its robots' names (type and id, in its robots' order).
data Instant = Instant LogFrame [(RobotType, RobotId)]

-- | The frame of an instant with the events and console lines of its period
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

-- | The instant of a state, given the world's arena (for the sensors), the
-- previous step ('Nothing' at time 0: every rotational velocity 0) and the
-- state's scores (which the step has made).
frameInstant :: LogConfig -> Arena -> Maybe Prev -> WorldState -> [(String, Int)] -> Instant
frameInstant cfg arena prev s scores = Instant LogFrame
  { lfTime = roundTo 1e9 (wsTime s)
  , lfRobots = zipWith robotOf [0 ..] (wsRobots s)
  , lfBalls = [ (r6 x, r6 y) | Point2 x y <- wsBalls s ]
  , lfScores = scores
  , lfEvents = []
  , lfConsole = [] }
  [ (robotType r, robotId r) | r <- wsRobots s ]
  where
    physical = [ mkRobot (kindOfType (robotType r)) (robotId r) (robotPos r) (robotHeading r)
                         (robotSpeed r) (robotStuck r) (robotCharge r) | r <- wsRobots s ]
    ctx = SenseContext arena physical [ Ball p zeroVector | p <- wsBalls s ]
    robotOf i r =
      let input = senseRobot ctx i (robotOdometry r, robotHeading r) Nothing
          omega = case prev of
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
