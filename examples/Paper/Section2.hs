{-# LANGUAGE Arrows #-}
-- |
-- Module      : Paper.Section2
-- Description : The definitions of section 2 of the notes, for the simbot.
--
-- Section 2 of "Arrows, Robots, and Functional Reactive Programming"
-- writes its signal functions against a few signal functions it only
-- /assumes/: the wheel speeds @vrSF@ and @vlSF@, the orientation
-- @thetaSF@, a temperature sensor @tempSF@ and an event source
-- @incrVelEvs@. The simbot has none of these as a reading, so this module
-- defines each of them from what a 'SimbotInput' does offer:
--
-- * the wheel speeds are /estimated from the odometry/: the forward
--   velocity is the derivative of 'odometryPosition' projected on the
--   heading, the rotational velocity the derivative of 'odometryHeading'
--   (unwrapped, so that crossing the heading's cut at ±pi is a small turn,
--   not a jump of 2 pi), and for a differential drive with wheel base @l@,
--   @vr = v + w l\/2@ and @vl = v - w l\/2@;
-- * the orientation is the odometry heading;
-- * the temperature is that of a radiator standing at the world's origin;
-- * the commands to increase the velocity are presses of the @+@ key.
--
-- With those in place the notes' listings are kept verbatim (where the
-- typesetting of the notes lost something, the change is marked in a
-- comment). 'examples' runs each of them on a scripted input and prints a
-- table of its outputs; two of them also drive a simbot.
module Paper.Section2
  ( -- * What the notes assume
    -- ** Wheel speeds from the odometry
    forwardVelSF
  , rotVelSF
  , unwrapAngle
  , wheelBase
  , vrSF
  , vlSF
    -- ** Orientation
  , thetaSF
    -- ** Temperature
  , Temp
  , tempSF
    -- ** Velocity commands
  , incrVelEvs
    -- * 2.4 A simple example
  , xSF
    -- * 2.5 Arrow syntax
  , xSF'
    -- * 2.6 Discrete events and switching
  , sf
  , xspd
  , sinAfresh
  , alarmSF
  , alarmCountSF
    -- * 2.7 Recursive signals
  , vel
    -- * Scripted inputs and reports
  , scriptedInput
  , arcPath
  , runEvery
  , formatTable
  , showD
  , showE
    -- * The examples
  , examples
  ) where

import           Data.List     (transpose, zip4, zip5, zip6)
import           Text.Printf   (printf)

import           AFrob
import           AFrobRobotSim

import           Examples.Types (Example (..))

------------------------------------------------------------------------------
-- What the notes assume

-- | The simbot's forward velocity (m\/s, negative when reversing),
-- estimated from its odometry: the derivative of 'odometryPosition',
-- projected on the current heading. 0 at time 0 (like 'derivative', it
-- has no earlier sample to compare with); at each later sample the
-- displacement since the previous sample divided by the time step.
forwardVelSF :: SF SimbotInput Velocity
forwardVelSF = proc inp -> do
  d <- derivative -< odometryPosition inp .-. origin
  returnA -< d `dot` vector2Polar 1 (odometryHeading inp)

-- | The simbot's rotational velocity (rad\/s, counter-clockwise positive),
-- estimated from its odometry: the derivative of the 'unwrapAngle'd
-- heading. 0 at time 0.
rotVelSF :: SF SimbotInput RotVel
rotVelSF = arr odometryHeading >>> unwrapAngle >>> derivative

-- | Make a normalised angle continuous: the output starts at the input's
-- value and then changes, at every sample, by the input's change
-- normalised into [-pi, pi). A heading that crosses the cut at ±pi (from
-- 3.1 to -3.1, say) so reads as a small turn (to 3.18) instead of a jump.
-- Turning by more than pi between two samples is taken for a turn the
-- other way.
unwrapAngle :: SF Angle Angle
unwrapAngle = loopPre Nothing (arr step)
  where
    step (a, Nothing)             = (a, Just (a, a))
    step (a, Just (aPrev, total)) =
      let total' = total + normalizeAngle (a - aPrev)
      in total' `seq` (total', Just (a, total'))

-- | The distance between a simbot's wheels, the notes' @l@: 0.5 m, the
-- 'rpDiameter' of both kinds of simbot.
wheelBase :: Length
wheelBase = kindWheelBase SimbotA

-- | The right wheel's speed, estimated from the odometry:
-- @v + w * l \/ 2@ for the forward velocity @v@ ('forwardVelSF'), the
-- rotational velocity @w@ ('rotVelSF') and the 'wheelBase' @l@ (the
-- kinematics of a differential drive; see 'ddVelTR'). 0 at time 0. The
-- notes assume this signal function without defining it.
vrSF :: SF SimbotInput Speed
vrSF = (forwardVelSF &&& rotVelSF) >>> arr2 (\v w -> v + w * wheelBase / 2)

-- | The left wheel's speed, estimated from the odometry: @v - w * l \/ 2@
-- (see 'vrSF'). 0 at time 0.
vlSF :: SF SimbotInput Speed
vlSF = (forwardVelSF &&& rotVelSF) >>> arr2 (\v w -> v - w * wheelBase / 2)

-- | The simbot's orientation: its odometry heading (radians, 0 = the
-- positive x axis, counter-clockwise, normalised into [-pi, pi)). The
-- notes assume this signal function; Exercise 2 computes it from the
-- wheel speeds instead (see "Exercises.Ex02").
thetaSF :: SF SimbotInput Angle
thetaSF = arr odometryHeading

-- | A temperature, in degrees Celsius.
type Temp = Double

-- | The temperature the simbot feels, a stand-in for the notes' assumed
-- temperature sensor: a radiator stands at the world's origin, 120 °C
-- there and falling off with the distance @r@ (in metres) from it as
-- @20 + 100 * exp (-r^2)@, so 20 °C far away. It is above 100 °C within
-- @sqrt (log 1.25)@ ≈ 0.47 m of the origin. A function of the current
-- position only: no state, and defined at time 0.
tempSF :: SF SimbotInput Temp
tempSF = arr (\inp -> let r = distance (odometryPosition inp) origin
                      in 20 + 100 * exp (-(r * r)))

-- | The commands to increase the velocity, a stand-in for the notes'
-- assumed event source: an event at every press of the @+@ key, i.e. at
-- every sample where the key down is @+@ and was not at the previous
-- sample ('tciNewKeyDown', filtered). A @+@ already down at the very
-- first sample does not count, like a robot already stuck for 'rsStuck':
-- so an @incrVelEvs@ started afresh at the instant of a press (by a
-- switch, as in "Exercises.Ex06") does not see that press a second time.
incrVelEvs :: SF SimbotInput (Event ())
incrVelEvs = tciNewKeyDown (Just '+') >>> arr (\e -> filterE (== '+') e `tag` ())

------------------------------------------------------------------------------
-- 2.4 A simple example

-- | The x coordinate, by the notes' equation
-- @x = (1\/2) (integral ((vr + vl) * cos theta))@, unsugared. 0 at time 0;
-- 'integral' is the left rectangle rule, so the output at a sample uses
-- the wheel speeds and heading up to the previous one. With the odometry
-- estimates above it follows the simbot's displacement along the x axis
-- since time 0, two samples late: one for the derivatives that estimate
-- the wheel speeds, one for the integral.
xSF :: SF SimbotInput Distance
-- The notes' listing, with two repairs: its second let binding was set one
-- column left of the first (a layout error), and its "v1SF" is vlSF (as in
-- the notes' own xSF').
xSF = let v = (vrSF &&& vlSF) >>> arr2 (+)
          t = thetaSF >>> arr cos
      in (v &&& t) >>> arr2 (*) >>> integral >>> arr (/2)

------------------------------------------------------------------------------
-- 2.5 Arrow syntax

-- | 'xSF' in arrow syntax, the notes' listing verbatim. The same signal
-- function: the same outputs at every sample.
xSF' :: SF SimbotInput Distance
xSF' = proc inp -> do
  vr    <- vrSF    -< inp
  vl    <- vlSF    -< inp
  theta <- thetaSF -< inp
  i     <- integral -< (vr+vl) * cos theta
  returnA -< (i/2)

------------------------------------------------------------------------------
-- 2.6 Discrete events and switching

-- | The notes' conditional: @sf flag sfx sfy@ outputs @sfx@'s output at
-- every sample where @flag@ outputs 'True', and @sfy@'s where it outputs
-- 'False'. All three run all the time, from time 0 (so @sfy@'s state
-- keeps evolving while @sfx@ is chosen); nothing switches.
sf :: SF a Bool -> SF a b -> SF a b -> SF a b
-- The notes' listing, with its free variables flag, sfx and sfy made
-- parameters.
sf flag sfx sfy = proc i -> do
  x <- sfx -< i
  y <- sfy -< i
  b <- flag -< i
  returnA -< if b then x else y

-- | A wheel speed that is @v@ until the simbot gets stuck ('rsStuck') and
-- 0 from then on, from the instant of that event (an immediate 'switch').
-- A simbot already stuck at time 0 must come free and get stuck again.
xspd :: Speed -> SF SimbotInput Speed
-- The notes' listing; its 'switch' was typeset with quotes for backquotes.
xspd v = (constant v &&& rsStuck) `switch` \() -> constant 0

-- | The notes' example of time beginning afresh in a signal function
-- switched into: a sinusoid of the time, @sin t@, until the first
-- 'rsStuck' event, and from that instant on a new one of the time since
-- the event (0 at the event's own sample), whatever the time it came at.
sinAfresh :: SF SimbotInput Double
-- The notes' listing, its 'switch' typeset with quotes for backquotes.
sinAfresh =
  let sinSF = time >>> arr sin
  in (sinSF &&& rsStuck) `switch` const sinSF

-- | An event whenever the temperature ('tempSF') rises above 100 °C: at
-- every sample where it is above 100 and was not at the previous one. No
-- event at time 0 ('edge'), even if it is hot then.
alarmSF :: SF SimbotInput (Event ())
alarmSF = tempSF >>> arr (>100) >>> edge

-- | The number of 'alarmSF' events so far, the current sample's included:
-- 0 until the first alarm, 1 from its instant on, and so on.
alarmCountSF :: SF SimbotInput Int
-- The notes' listing; its 'tag' was typeset with quotes for backquotes.
alarmCountSF = alarmSF >>> arr (`tag` (+1)) >>> accum 0 >>> hold 0

------------------------------------------------------------------------------
-- 2.7 Recursive signals

-- | A velocity that starts at @v0@ and grows by 1 at every 'incrVelEvs'
-- event, one sample late: at the instant of an event it is still the old
-- velocity (the delayed 'drSwitch' that makes the recursive definition
-- well founded), the new one from the next sample on. So at every sample
-- it is @v0@ plus the number of events strictly before that sample.
vel :: Velocity -> SF SimbotInput Velocity
-- The notes' listing; its 'tag' was typeset with quotes for backquotes.
vel v0 = proc inp -> do
  rec e <- incrVelEvs -< inp
      v <- drSwitch (constant v0) -< (inp, e `tag` constant (v+1))
  returnA -< v

------------------------------------------------------------------------------
-- Scripted inputs and reports

-- | A sample of a simbot's input with the given odometry position and
-- heading (normalised), stuck flag and key: a full battery, nothing in
-- range of the range finder ('rangeFinderMax' in every direction) and
-- nothing tracked. For running signal functions without a simulator.
scriptedInput :: Position2 -> Heading -> Bool -> Maybe Char -> SimbotInput
scriptedInput p h stuck key = SimbotInput
  { siBattery  = BSHigh
  , siStuck    = stuck
  , siPosition = p
  , siHeading  = normalizeHeading h
  , siRange    = const rangeFinderMax
  , siMaxRange = rangeFinderMax
  , siRobots   = []
  , siBalls    = []
  , siKey      = key
  }

-- | @arcPath v w ts@: the inputs of a simbot that starts at the origin
-- with heading 0 and drives, from time 0, at the constant forward
-- velocity @v@ and rotational velocity @w@ (a circular arc, or a straight
-- line if @w@ is 0), sampled exactly at the times @ts@. Not stuck, no key.
arcPath :: Velocity -> RotVel -> [Time] -> [SimbotInput]
arcPath v w = map at
  where
    at t
      | w == 0    = scriptedInput (Point2 (v * t) 0) 0 False Nothing
      | otherwise = scriptedInput (Point2 (v / w * sin (w * t)) (v / w * (1 - cos (w * t))))
                                  (w * t) False Nothing

-- | Run a signal function on samples taken every @dt@ seconds, the first
-- at local time 0: one output per input.
runEvery :: DTime -> SF a b -> [a] -> [b]
runEvery _  _  []       = []
runEvery dt sf0 (a : as) = embed sf0 (a, [ (dt, Just x) | x <- as ])

-- | A table: a header row and the data rows, every column right-aligned to
-- its widest cell, one line per row.
formatTable :: [String] -> [[String]] -> String
formatTable header rows = unlines (map line (header : rule : rows))
  where
    widths = map (maximum . map length) (transpose (header : rows))
    rule   = [ replicate n '-' | n <- widths ]
    line   = unwords . zipWith pad widths
    pad n s = replicate (n - length s) ' ' ++ s

-- | A number with three decimals, for tables.
showD :: Double -> String
showD = printf "%.3f"

-- | An event as @*@, or as the shown value @*v@; no event as @.@.
showE :: Show a => Event a -> String
showE = event "." (\x -> case show x of
                            "()" -> "*"
                            s    -> '*' : s)

------------------------------------------------------------------------------
-- The examples

-- | The examples of section 2: a table of outputs on a scripted input for
-- each listing, and two robots.
examples :: [Example]
examples =
  [ SignalExample "xSF"
      "2.4: x from the wheel speeds, unsugared, on a circular arc"
      xSFReport
  , SignalExample "xSF'"
      "2.5: x in arrow syntax: the same outputs as xSF"
      xSF'Report
  , SignalExample "sf"
      "2.6: the conditional sf: time, but 0 while stuck"
      sfReport
  , SignalExample "xspd"
      "2.6: a wheel speed switched to 0 when the simbot gets stuck"
      xspdReport
  , SignalExample "alarmSF"
      "2.6: an alarm when passing the radiator at the origin (above 100 C)"
      alarmSFReport
  , SignalExample "alarmCountSF"
      "2.6: the number of alarms, passing the radiator again and again"
      alarmCountSFReport
  , SignalExample "vel"
      "2.7: a velocity incremented at every + key press (rec, drSwitch)"
      velReport
  , RobotExample
      { exName        = "xspd-robot"
      , exDescription = "2.6: a simbot driving at xspd 0.5 until it runs into a wall"
      , exWorld       = [OTSimbotA 1 (Point2 (-3) 0) 0, OTVWall (Point2 1 0)]
      , exControllerA = xspdController
      , exControllerB = xspdController
      , exSeconds     = 12
      , exKeys        = []
      , exReferee     = noReferee
      }
  , RobotExample
      { exName        = "alarmSF-robot"
      , exDescription = "2.6: a simbot circling over the radiator, printing each alarm"
      , exWorld       = [OTSimbotA 1 (Point2 0 (-1.5)) 0]
      , exControllerA = alarmController
      , exControllerB = alarmController
      , exSeconds     = 45
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]

-- The arc of the xSF reports: wheel speeds 0.625 and 0.375 m/s, sampled
-- every 0.1 s for 6 s.
arcDt :: DTime
arcDt = 0.1

arcInputs :: [SimbotInput]
arcInputs = arcPath 0.5 0.5 [ fromIntegral n * arcDt | n <- [0 .. 60 :: Int] ]

-- Every n-th element, from the first.
everyNth :: Int -> [a] -> [a]
everyNth n xs = case xs of
  []       -> []
  x : rest -> x : everyNth n (drop (n - 1) rest)

-- The sample times of a run every dt seconds.
timesEvery :: DTime -> [Time]
timesEvery dt = [ fromIntegral n * dt | n <- [0 :: Int ..] ]

xSFReport :: String
xSFReport =
  "A simbot on a circle (v = 0.5 m/s, w = 0.5 rad/s, so vr = 0.625 and vl = 0.375),\n"
  ++ "sampled every 0.1 s. xSF integrates the wheel speeds estimated from the odometry,\n"
  ++ "so it follows the odometry's x two samples late (one for the estimate's\n"
  ++ "derivative, one for the integral).\n\n"
  ++ formatTable ["t", "odometry x", "vr", "vl", "theta", "xSF"]
       (everyNth 5
         [ [showD t, showD (point2X (odometryPosition i)), showD r, showD l, showD th, showD x]
         | (t, i, r, l, th, x) <- zip6 (timesEvery arcDt) arcInputs (run vrSF) (run vlSF)
                                       (run thetaSF) (run xSF) ])
  where
    run s = runEvery arcDt s arcInputs

xSF'Report :: String
xSF'Report =
  "xSF and xSF' on the circle of the xSF example: the same signal function.\n\n"
  ++ formatTable ["t", "xSF", "xSF'"]
       (everyNth 5 [ [showD t, showD a, showD b] | (t, a, b) <- zip3 (timesEvery arcDt) xs xs' ])
  ++ printf "\nlargest difference over all %d samples: %g\n"
       (length xs) (maximum (zipWith (\a b -> abs (a - b)) xs xs'))
  where
    xs  = runEvery arcDt xSF arcInputs
    xs' = runEvery arcDt xSF' arcInputs

-- A stuck flag script, one sample every 0.5 s.
stuckScript :: [Bool]
stuckScript = [False, False, True, True, False, False, True, False, False]

stuckInputs :: [SimbotInput]
stuckInputs = [ scriptedInput origin 0 s Nothing | s <- stuckScript ]

sfReport :: String
sfReport =
  "sf (arr rsIsStuck) (constant 0) time, sampled every 0.5 s: time keeps running\n"
  ++ "while it is not chosen; the choice is made afresh at every sample.\n\n"
  ++ formatTable ["t", "stuck", "sf"]
       [ [showD t, show s, showD y]
       | (t, s, y) <- zip3 (timesEvery 0.5) stuckScript
                           (runEvery 0.5 (sf (arr rsIsStuck) (constant 0) time) stuckInputs) ]

xspdReport :: String
xspdReport =
  "xspd 0.5 on a scripted stuck flag, sampled every 0.5 s: it switches to 0 at the\n"
  ++ "first rsStuck event, and stays there.\n\n"
  ++ formatTable ["t", "stuck", "rsStuck", "xspd 0.5"]
       [ [showD t, show s, showE e, showD y]
       | (t, s, e, y) <- zip4 (timesEvery 0.5) stuckScript
                              (runEvery 0.5 rsStuck stuckInputs) (runEvery 0.5 (xspd 0.5) stuckInputs) ]

-- Straight past the radiator at the origin, 0.2 m to its side, at 0.5 m/s
-- from x = -2, sampled every 0.25 s.
passInputs :: [SimbotInput]
passInputs = [ scriptedInput (Point2 (-2 + 0.5 * t) 0.2) 0 False Nothing
             | t <- take 33 (timesEvery 0.25) ]

alarmSFReport :: String
alarmSFReport =
  "A simbot passing the radiator at the origin 0.2 m to its side, at 0.5 m/s,\n"
  ++ "sampled every 0.25 s (rows every 0.5 s and at the alarm): one alarm when the\n"
  ++ "temperature rises above 100 C.\n\n"
  ++ formatTable ["t", "x", "tempSF", "alarmSF"]
       [ [showD t, showD (point2X (odometryPosition i)), showD c, showE e]
       | (k, (t, i, c, e)) <- zip [0 :: Int ..]
           (zip4 (timesEvery 0.25) passInputs
                 (runEvery 0.25 tempSF passInputs) (runEvery 0.25 alarmSF passInputs))
       , even k || isEvent e ]

-- Back and forth over the radiator: x = 2 sin (t/2), sampled every 0.25 s
-- for 20 s. At time 0 the simbot is over the radiator (no alarm then).
swingInputs :: [SimbotInput]
swingInputs = [ scriptedInput (Point2 (2 * sin (t / 2)) 0) 0 False Nothing
              | t <- take 81 (timesEvery 0.25) ]

alarmCountSFReport :: String
alarmCountSFReport =
  "A simbot swinging over the radiator (x = 2 sin (t/2)), sampled every 0.25 s;\n"
  ++ "rows every 1 s and at every alarm.\n\n"
  ++ formatTable ["t", "x", "tempSF", "alarmSF", "alarmCountSF"]
       [ [showD t, showD (point2X (odometryPosition i)), showD c, showE e, show n]
       | (k, (t, i, c, e, n)) <- zip [0 :: Int ..]
           (zip5 (timesEvery 0.25) swingInputs (runEvery 0.25 tempSF swingInputs)
                 (runEvery 0.25 alarmSF swingInputs) (runEvery 0.25 alarmCountSF swingInputs))
       , k `mod` 4 == 0 || isEvent e ]

-- Keys pressed, one sample every 0.5 s.
keyScript :: [Maybe Char]
keyScript = [Nothing, Just '+', Nothing, Nothing, Just '+', Just '+', Just 'a', Just '+', Nothing, Nothing]

velReport :: String
velReport =
  "vel 0 on scripted keys, sampled every 0.5 s: every + press adds 1, from the\n"
  ++ "sample after the press (drSwitch is delayed); a + held down counts once.\n\n"
  ++ formatTable ["t", "key", "incrVelEvs", "vel 0"]
       [ [showD t, maybe "-" (: []) k, showE e, showD v]
       | (t, k, e, v) <- zip4 (timesEvery 0.5) keyScript
                              (runEvery 0.5 incrVelEvs keyInputs) (runEvery 0.5 (vel 0) keyInputs) ]
  where
    keyInputs = [ scriptedInput origin 0 False k | k <- keyScript ]

-- Drive straight at the speed xspd 0.5 gives.
xspdController :: SimbotController
xspdController _ = xspd 0.5 >>> arr (\s -> mrFinalize (ddVelDiff s s))

-- Circle (radius about 0.75 m, through the radiator) and print every alarm
-- with the count so far.
alarmController :: SimbotController
alarmController _ = proc inp -> do
  e <- alarmSF      -< inp
  n <- alarmCountSF -< inp
  returnA -< mrFinalize (ddVelTR 0.3 0.4
                         `mrMerge` tcoPrintMessage (e `tag` ("Alarm! (" ++ show n ++ " so far)")))
