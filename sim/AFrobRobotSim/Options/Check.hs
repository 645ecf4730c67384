-- |
-- Module      : AFrobRobotSim.Options.Check
-- Description : The checks of a run's settings before anything is
--               simulated, and the limits they hold the settings to.
--
-- 'validateOptions' finds the faults of a 'SimOptions' that no flag alone
-- shows and that do not depend on the world (the step count, the frame
-- period, the files' names); 'validateOptionsIn', once the world is
-- known, adds the frame's size. The ranges the flags check one at a time
-- ('secondsOk' and its siblings) are here too, so that options set in
-- code are held to the same. What the checks are, in prose, is in
-- "AFrobRobotSim.Options", which re-exports the checks and the limits.
module AFrobRobotSim.Options.Check
  ( -- * The checks
    validateOptions
  , validateOptionsIn
  , outputNameFaults
  , printingModesFault
    -- * The limits
  , maxSteps
  , maxFrameSide
  , minWorldPixels
  , videoExtensions
    -- * The ranges of the numbered settings
  , secondsOk
  , dtOk
  , noiseOk
  , keyTimeOk
  , seedOk
    -- * Repeated parameters
  , repeatedBy
  , timesText
    -- * Numbers in messages
  , readableNumber
  ) where

import           Data.Char       (toLower)
import           Data.List       (intercalate, nub)
import           Numeric         (showFFloat)
import           System.FilePath (takeExtension)
import           Text.Printf     (printf)

import           AFrobRobotSim.FlatArray (finite)
import           AFrobRobotSim.Options.Settings
import           AFrobRobotSim.Simulator (maxOdometryNoise, maxTimeStep)
import           AFrobRobotSim.World (Bounds (..))

-- | The faults of a set of options that no flag alone shows and that do
-- not depend on the world, one message each (empty when the options are
-- fine). Checked by 'AFrobRobotSim.Options.CommandLine.parseSimArgs';
-- 'validateOptionsIn' adds the frame's size.
--
-- A fault that only options set in code can have (a value a flag
-- refuses, such as a negative 'optSeconds', or a name twice in
-- 'optParams', where a command line keeps the last) is named by the
-- record's field, as the code set it: @optSeconds must be a finite number
-- >= 0, got -1.0@. A fault that a command line can have too (@--seconds
-- 1e20 with --dt 0.01@, an empty @--svg@) is named by its flags, which
-- are the fields' names on the command line; both printing modes set
-- ('printingModesFault') by both.
validateOptions :: SimOptions -> [String]
validateOptions o =
  -- (what the flags refuse one at a time, for options set in code and
  -- given to 'AFrobRobotSim.runSimWith' or as the settings
  -- 'AFrobRobotSim.Options.CommandLine.parseSimArgs' starts from: the
  -- simulator stopped at them with a bare error, after the log was begun)
  [ "optSeconds must be a finite number >= 0, got " ++ full secs | not (finite secs && secondsOk secs) ]
  ++ [ "optDt must be a positive number up to " ++ readableNumber maxTimeStep ++ ", got " ++ full dt
     | not (dtOk dt) ]
  ++ [ "optFps must be a finite number > 0, got " ++ full fps | not (finite fps && fps > 0) ]
  ++ [ "optOdometryNoise must be a number from 0 to " ++ readableNumber maxOdometryNoise ++ ", got " ++ show noise
     | not (noiseOk noise) ]
  ++ [ "optScale must be Nothing (the scale that fits the world) or Just a finite number > 0, got Just " ++ full x
     | Just x <- [optScale o], not (finite x && x > 0) ]
  ++ [ "optSeed must be a whole number from -2^53 to 2^53, got " ++ show (optSeed o)
     | not (seedOk (toInteger (optSeed o))) ]
  ++ [ "optKeys: a key press's time must be a finite number >= 0, got " ++ show t ++ " for " ++ show k
     | (t, k) <- optKeys o, not (keyTimeOk t) ]
  ++ [ "--seconds " ++ readableNumber secs ++ " with --dt " ++ readableNumber dt ++ " is "
       ++ (if isInfinite steps then "more steps than a number holds" else readableNumber steps ++ " steps")
       ++ ", more than the " ++ readableNumber maxSteps ++ " allowed"
     | all finite [secs, dt], dt > 0, tooMany ]
  ++ [ "--seconds " ++ full secs ++ " with --dt " ++ full dt ++ " is less than half a step, so nothing would be"
       ++ " simulated after time 0 (a run takes the whole number of steps nearest seconds / dt); give"
       ++ " --seconds " ++ full (dt / 2) ++ " or more, or 0 for the time-0 sample alone"
     | all finite [secs, dt], dt > 0, secs > 0, stepsBeforeFloor secs dt < 1 ]
  ++ [ "--fps times --dt must not exceed 1 (at most one frame per time step)"
     | finite fps, finite dt, fps > 0, dt > 0, fps * dt > 1 + 1e-9 ]
  ++ [ "--dt " ++ readableNumber dt ++ " does not divide the frame period 1/" ++ readableNumber fps ++ " s; --fps "
       ++ suggestion ++ " would work"
     | finite fps, finite dt, dt > 0, fps > 0, fps * dt <= 1 + 1e-9, fps * dt >= 1e-9, not tooMany
     , not (divides fps) ]
  ++ [ "--fps " ++ readableNumber fps ++ " is less than one frame in 10^9 steps of --dt " ++ readableNumber dt
     | finite fps, finite dt, fps > 0, dt > 0, fps * dt < 1e-9 ]
  ++ [ "optParams names the parameter " ++ show k ++ " " ++ timesText (length vs) ++ "; a name holds one value"
     | (k, vs) <- repeatedBy (optParams o) ]
  ++ [ "optOut must not be empty" | null (optOut o) ]
  ++ maybe [] pure (printingModesFault o)
  ++ outputNameFaults o
  where
    secs = optSeconds o; dt = optDt o; fps = optFps o
    noise = optOdometryNoise o
    steps = secs / dt
    -- (more than maxSteps as runSteps counts them, with its slack)
    tooMany = isNaN steps || stepsBeforeFloor secs dt >= maxSteps + 1
    -- a number as it is, without rounding (0.0025, 1.25e-301)
    full x | x /= 0 && (abs x < 1e-4 || abs x >= 1e9) = show x
           | otherwise                               = showFFloat Nothing x ""
    -- whether dt divides the frame period 1/f (to a relative 1e-4)
    divides f = let k = 1 / (f * dt) in abs (k - fromIntegral (round k :: Int)) <= 1e-4 * k
    -- frame rates that work, a whole number of steps apart, each written
    -- with the fewest decimals (3 or more) that still work as written
    suggestion :: String
    suggestion = let k = max 1 (round (1 / (fps * dt)) :: Int)
                     good j = let f = 1 / (fromIntegral j * dt)
                              in head ([ w | d <- [3 .. 17], let w = decimals d f, divides (read w) ] ++ [show f])
                 in good k ++ " or " ++ good (k + 1)
    decimals d f = let w = showFFloat (Just d) f ""
                   in if '.' `elem` w then reverse (dropWhile (== '.') (dropWhile (== '0') (reverse w))) else w

-- | 'validateOptions' and the faults that depend on the world, of this
-- extent: a frame (world and margin) at the scale in effect ('scaleFor')
-- more than 'maxFrameSide' pixels wide or tall, or a world less than
-- 'minWorldPixels' across on its long side. Checked by
-- 'AFrobRobotSim.runSimWith' before simulating.
validateOptionsIn :: Bounds -> SimOptions -> [String]
validateOptionsIn b@(Bounds x0 y0 x1 y1) o =
  validateOptions o
  ++ [ "--scale " ++ readableNumber scale ++ " makes the frame of this " ++ readableNumber w ++ " by "
       ++ readableNumber h ++ " m world " ++ readableNumber side ++ " pixels on its long side, more than "
       ++ readableNumber maxFrameSide
     | finite scale, side > maxFrameSide ]
  ++ [ "--scale " ++ readableNumber scale ++ " draws this " ++ readableNumber w ++ " by " ++ readableNumber h
       ++ " m world " ++ readableNumber (side - 20) ++ " pixels across, too small to show it (at least "
       ++ readableNumber minWorldPixels ++ "; without --scale it is " ++ readableNumber fitPixels ++ ")"
     | finite scale, side - 20 < minWorldPixels ]
  where
    scale = scaleFor b o
    w = x1 - x0
    h = y1 - y0
    side = max w h * scale + 20

-- | The fault of settings that ask for both printing modes,
-- 'optDumpWorld' and 'optPrintProgram', each of which prints something
-- and exits instead of running: 'Just' its message when both are set,
-- 'Nothing' otherwise. The message names both flags and both fields, as
-- the settings may come from a command line or from code. It is the one
-- check of the pair: a command line's reader refuses the pair with it
-- alone ('AFrobRobotSim.Options.CommandLine.parseSimFlags', before the
-- other faults of its flags), 'validateOptions' lists it with the other
-- faults, and 'AFrobRobotSim.runSimWith', which prints the program's
-- name before it checks anything else, refuses the pair with it (exit
-- code 2) before either prints.
--
-- >>> printingModesFault defaultSimOptions { optDumpWorld = True, optPrintProgram = True }
-- Just "--dump-world and --print-program (optDumpWorld and optPrintProgram) each print something and exit: ask for one"
printingModesFault :: SimOptions -> Maybe String
printingModesFault o
  | optDumpWorld o && optPrintProgram o =
      Just "--dump-world and --print-program (optDumpWorld and optPrintProgram) each print something and exit: ask for one"
  | otherwise = Nothing

-- | The faults of the outputs' names that the settings themselves show,
-- whatever they started from: an empty @--svg@, @--replay@, @--log@,
-- @--result@ or @--video@, a @--video@ whose name is no video format's.
-- Part of 'validateOptions'; a reader of the command line's flags alone
-- ('AFrobRobotSim.Options.CommandLine.parseSimFlags') checks them too, as
-- they are the faults of a flag's value.
outputNameFaults :: SimOptions -> [String]
outputNameFaults o =
  [ flag ++ " must not be empty (a file name)"
  | (flag, Just "") <- [ ("--svg", optSvg o), ("--replay", optReplay o), ("--log", optLog o)
                       , ("--result", optResult o), ("--video", optVideo o) ] ]
  ++ [ "--video " ++ show v ++ ": a video's name ends in " ++ intercalate ", " (map ('.' :) videoExtensions)
       ++ " (ffmpeg picks the format by it; an image's, such as .ppm or .png, would write frames)"
     | Just v@(_ : _) <- [optVideo o], map toLower (takeExtension v) `notElem` map ('.' :) videoExtensions ]

-- | The most steps a run may take: 10^8 (about 280 simulated hours at the
-- default step).
maxSteps :: Double
maxSteps = 1e8

-- | The widest (and tallest) frame, and SVG, 'optScale' may ask for, in
-- pixels.
maxFrameSide :: Double
maxFrameSide = 8000

-- | The fewest pixels a frame may give its world's long side: 10. A
-- @--scale@ that gives fewer draws nothing that can be seen.
minWorldPixels :: Double
minWorldPixels = 10

-- | The extensions (in any case) that @--video@ takes, each a video
-- format that Debian's ffmpeg writes from the frames: @mp4@, @m4v@,
-- @mkv@, @webm@, @mov@, @avi@ and @gif@. Any other is refused before the
-- run: ffmpeg chooses the format by the extension, and would fail after
-- the run on one it does not know, or take an image's (@.ppm@) as a
-- pattern of numbered files and write frames over the run's own.
videoExtensions :: [String]
videoExtensions = ["mp4", "m4v", "mkv", "webm", "mov", "avi", "gif"]

-- | The largest magnitude of a @--seed@: 2^53, the largest up to which
-- every whole number is a 'Double' (the result line and the log record the
-- seed as a JSON number).
maxSeed :: Integer
maxSeed = 2 ^ (53 :: Int)

-- | The ranges of the numbered settings, as the flags check them one at a
-- time and 'validateOptions' checks options set in code (NaN is in none):
-- @--seconds@, @--dt@ (up to 'AFrobRobotSim.Simulator.maxTimeStep'),
-- @--odometry-noise@ (up to 'AFrobRobotSim.Simulator.maxOdometryNoise')
-- and a key press's time.
secondsOk, dtOk, noiseOk, keyTimeOk :: Double -> Bool
secondsOk x = x >= 0
dtOk x      = x > 0 && x <= maxTimeStep
noiseOk x   = x >= 0 && x <= maxOdometryNoise
keyTimeOk x = x >= 0 && not (isInfinite x)

-- | The range of @--seed@: a magnitude of at most 2^53 (the result line
-- and the log record the seed as a JSON number).
seedOk :: Integer -> Bool
seedOk x = abs x <= maxSeed

-- | A number as a person writes it, in the checks' messages and the
-- flags': at most three decimals, no trailing zeros, and an exponent
-- below 0.001 or from 10^9 on (25, 0.01, 33.333, 1.000e20). Not for a
-- value to be read back: it rounds.
readableNumber :: Double -> String
readableNumber x
  | x /= 0 && (abs x < 1e-3 || abs x >= 1e9) = printf "%.3e" x
  | otherwise = let s = printf "%.3f" x :: String
                in reverse (dropWhile (== '.') (dropWhile (== '0') (reverse s)))

-- | The names that come more than once in a list of pairs, in the order
-- first met, each with all its values in order: how a command line's
-- repeated @--param@s and other flags are kept ('optParamsRepeated',
-- 'optFlagsRepeated'), and how the
-- parameters of options set in code are checked ('validateOptions').
--
-- >>> repeatedBy [("a", 1), ("b", 2), ("a", 3)]
-- [("a",[1,3])]
repeatedBy :: Eq k => [(k, v)] -> [(k, [v])]
repeatedBy kvs = [ (k, vs) | k <- nub (map fst kvs), let vs = [ v | (k', v) <- kvs, k' == k ], length vs > 1 ]

-- | How often, in words: @twice@, @3 times@ (a repeated @--param@'s
-- messages).
timesText :: Int -> String
timesText n = if n == 2 then "twice" else show n ++ " times"
