-- |
-- Module      : AFrobRobotSim.Options
-- Description : The settings of a simulation run and the command line that
--               sets them.
--
-- Every program built on 'AFrobRobotSim.runSim' accepts these flags:
--
-- @
-- --seconds T        simulated time to run                 (default 30)
-- --dt D             fixed time step, seconds, at most 1e6 (default 0.01)
-- --fps F            frames per simulated second           (default 25)
-- --out DIR          output folder (frames, default SVG and page) (default simbot-out)
-- --frames           also write PPM frames into the output folder
-- --no-frames        write no frames (the default)
-- --scale PX         pixels per metre  (default: the world's long side 600 px, 'fitScale')
-- --keys "1.5:a,3:b" scripted key presses (time:key, ...; 2:space and 4:comma name those keys;
--                    repeatable)
-- --seed N           seed of the odometry noise, |N| <= 2^53 (default 0)
-- --odometry-noise X relative odometry error per step, 0-1 (default 0 = exact)
-- --quiet            print only the summary line
-- --world FILE       load the world from FILE instead of the program's
-- --dump-world       print the world in the world-file format and exit
-- --rays             draw the four range-finder rays
-- --trails           draw each robot's path so far
-- --svg FILE         write one SVG picture of the whole run  (default simbot-out/run.svg)
-- --no-svg           write no SVG
-- --replay FILE      write the HTML replay page              (default simbot-out/replay.html)
-- --no-replay        write no replay page
-- --log FILE.jsonl   write the JSON-lines run log (docs/LOG.md)
-- --video FILE.mp4   assemble the frames into a video (needs ffmpeg and --frames;
--                    also .m4v .mkv .webm .mov .avi .gif)
-- --result FILE      write the run's settings and outcome as one JSON line
-- --param NAME=VALUE a parameter for the controllers (repeatable; see
--                    'AFrobRobotSim.Result.getSimParams')
-- --help             print this usage and exit
-- @
--
-- 'validateOptions' checks the numbers together before anything is
-- simulated: the step count @seconds / dt@ is finite and at most
-- 'maxSteps' (a run takes the whole number of steps nearest to it, a half
-- rounded up, with a millionth of a step's slack for times written in
-- decimals, so @--seconds@ greater than 0 must be at least half of
-- @--dt@), the frame period @1 / fps@ is a whole number of steps;
-- 'validateOptionsIn', once the world is known, also that the frame is at
-- most 'maxFrameSide' pixels wide and tall. A @--video@'s name must end
-- in one of 'videoExtensions'.
--
-- = Scale
--
-- Frames, the SVG and the replay page show the whole world. Without
-- @--scale@ the scale fits the world ('fitScale'): its long side is
-- 'fitPixels' (600) pixels, so the notes' 10 m world is drawn at 60
-- pixels per metre (a 620 by 620 frame with the margin), a 100 m world
-- at 6, a 30 by 10 m world at 20 (a 620 by 220 frame).
module AFrobRobotSim.Options
  ( SimOptions (..)
  , defaultSimOptions
  , Command (..)
  , parseSimArgs
  , parseKeys
  , parseParam
  , argText
  , validateOptions
  , validateOptionsIn
  , videoExtensions
  , runSteps
  , scaleFor
  , fitScale
  , fitPixels
  , maxSteps
  , maxFrameSide
  , minWorldPixels
  , usage
  ) where

import           Data.Char       (isSpace, toLower)
import           Data.List       (intercalate, isSuffixOf)
import           Numeric         (showFFloat)
import           System.FilePath (takeExtension, (</>))
import           Text.Printf     (printf)

import           AFrobRobotSim.Simulator (maxOdometryNoise, maxTimeStep)
import           AFrobRobotSim.World (Bounds (..))
import           AFrobRobotSim.WorldFile.Lexical (decimalLit, integerLit)

-- | The settings of a run.
data SimOptions = SimOptions
  { optSeconds       :: !Double            -- ^ simulated seconds to run
  , optDt            :: !Double            -- ^ the fixed time step (s)
  , optFps           :: !Double            -- ^ frames per simulated second
  , optOut           :: FilePath           -- ^ the output folder (the frames go there)
  , optFrames        :: !Bool              -- ^ write frames at all
  , optScale         :: !(Maybe Double)    -- ^ pixels per metre; 'Nothing' fits the world ('scaleFor')
  , optKeys          :: [(Double, Char)]   -- ^ scripted key presses
  , optSeed          :: !Int               -- ^ seed of the odometry noise
  , optOdometryNoise :: !Double            -- ^ relative odometry error per step
  , optQuiet         :: !Bool              -- ^ print only the summary
  , optWorldFile     :: Maybe FilePath     -- ^ load the world from this file
  , optDumpWorld     :: !Bool              -- ^ print the world and exit
  , optRays          :: !Bool              -- ^ draw range-finder rays
  , optTrails        :: !Bool              -- ^ draw trails
  , optSvg           :: Maybe FilePath     -- ^ write an SVG of the whole run
  , optVideo         :: Maybe FilePath     -- ^ assemble an mp4 with ffmpeg
  , optLog           :: Maybe FilePath     -- ^ write the JSON-lines run log
  , optReplay        :: Maybe FilePath     -- ^ write the HTML replay page
  , optResult        :: Maybe FilePath     -- ^ write the result line (settings and outcome)
  , optParams        :: [(String, String)] -- ^ the @--param@s, in order, one per name
  } deriving (Eq, Show)

-- | The defaults listed in the module documentation: no frames, the SVG
-- and the replay page in @simbot-out/@ (a 30 s run writes about 2 MB).
defaultSimOptions :: SimOptions
defaultSimOptions = SimOptions
  { optSeconds = 30, optDt = 0.01, optFps = 25, optOut = defaultOut, optFrames = False
  , optScale = Nothing, optKeys = [], optSeed = 0, optOdometryNoise = 0, optQuiet = False
  , optWorldFile = Nothing, optDumpWorld = False, optRays = False, optTrails = False
  , optSvg = Just (defaultOut </> "run.svg"), optVideo = Nothing, optLog = Nothing
  , optReplay = Just (defaultOut </> "replay.html"), optResult = Nothing, optParams = [] }

defaultOut :: FilePath
defaultOut = "simbot-out"

-- | What a command line asks for.
data Command
  = RunWith SimOptions  -- ^ run (or dump the world) with these settings
  | ShowHelp            -- ^ print 'usage' and exit
  deriving (Eq, Show)

-- | Parse a command line on top of the given settings. Unknown flags,
-- missing or malformed values and out-of-range numbers are errors whose
-- message names the flag.
--
-- The SVG picture and the replay page that the command line does not name
-- (with @--svg@, @--no-svg@, @--replay@ or @--no-replay@) and that are
-- the given settings' default files in their output folder follow
-- @--out@ into the new folder; the ones it names stay where it says,
-- whatever the order of the flags (@--svg a.svg --out x@ and
-- @--out x --svg a.svg@ both write @a.svg@).
--
-- A flag given twice takes its last value, but for the two that add:
-- each @--keys@ adds its presses to the settings' ('optKeys', those given
-- included), each @--param@ sets its name's value.
parseSimArgs :: SimOptions -> [String] -> Either String Command
parseSimArgs o0 = go o0 False False
  where
  -- the settings so far, and whether the SVG and the page were named
  go o svgNamed pageNamed args = case args of
    []                       -> check (relocated o svgNamed pageNamed)
    "--help" : _             -> Right ShowHelp
    "-h" : _                 -> Right ShowHelp
    flag : rest | Just switch <- lookup flag switches ->
      case switch (o, svgNamed, pageNamed) of (o', s', p') -> go o' s' p' rest
    flag : rest | Just set <- lookup flag (valued o) -> case rest of
      v : _ | isFlag v -> Left (flag ++ " needs a value (see --help), found the flag " ++ v)
      v : rest' -> set v >>= \o' -> go o' (svgNamed || flag == "--svg") (pageNamed || flag == "--replay") rest'
      []        -> Left (flag ++ " needs a value (see --help)")
    flag : _                 -> Left ("unknown argument " ++ show flag ++ " (see --help)")
  -- a value that is one of the flags is a value left out (@--out --no-svg@
  -- would write into a folder named @--no-svg@); @./--no-svg@ names such a file
  isFlag v = v `elem` (["--help", "-h"] ++ map fst switches ++ map fst (valued o0))
  -- the flags without a value: the settings, and whether the SVG and the
  -- page were named
  switches =
    [ ("--no-frames",  \(o, s, p) -> (o { optFrames = False }, s, p))
    , ("--frames",     \(o, s, p) -> (o { optFrames = True }, s, p))
    , ("--no-svg",     \(o, _, p) -> (o { optSvg = Nothing }, True, p))
    , ("--no-replay",  \(o, s, _) -> (o { optReplay = Nothing }, s, True))
    , ("--quiet",      \(o, s, p) -> (o { optQuiet = True }, s, p))
    , ("--dump-world", \(o, s, p) -> (o { optDumpWorld = True }, s, p))
    , ("--rays",       \(o, s, p) -> (o { optRays = True }, s, p))
    , ("--trails",     \(o, s, p) -> (o { optTrails = True }, s, p))
    ]
  valued o =
      [ ("--seconds", \v -> (\x -> o { optSeconds = x }) <$> number "--seconds" secondsOk v)
      , ("--dt",      \v -> (\x -> o { optDt = x }) <$> number "--dt" dtOk v)
      , ("--fps",     \v -> (\x -> o { optFps = x }) <$> number "--fps" (> 0) v)
      , ("--out",     \v -> if null v then Left "--out expects a folder name, got \"\""
                             else Right o { optOut = v })
      , ("--scale",   \v -> (\x -> o { optScale = Just x }) <$> number "--scale" (> 0) v)
      , ("--keys",    \v -> (\ks -> o { optKeys = optKeys o ++ ks }) <$> parseKeys v)
      , ("--seed",    \v -> case integerLit (trim v) of
                             -- (read as an Int, 2^64 + 1 wrapped round to 1; beyond 2^53 the
                             -- result line and the log, JSON numbers, could not record it exactly)
                             Just x | seedOk x -> Right o { optSeed = fromInteger x }
                             _ -> Left ("--seed expects a whole number from -2^53 to 2^53, got " ++ show v))
      , ("--odometry-noise", \v -> (\x -> o { optOdometryNoise = x }) <$> number "--odometry-noise" noiseOk v)
      , ("--world",   \v -> if null v then Left "--world must not be empty (a world file's name)"
                                        else Right o { optWorldFile = Just v })
      , ("--svg",     \v -> Right o { optSvg = Just v })
      , ("--video",   \v -> Right o { optVideo = Just v })
      , ("--log",     \v -> Right o { optLog = Just v })
      , ("--replay",  \v -> Right o { optReplay = Just v })
      , ("--result",  \v -> Right o { optResult = Just v })
      , ("--param",   \v -> (\(k, x) -> o { optParams = setParam (argText k, x) (optParams o) }) <$> parseParam v)
      ]
  -- the default files that were not named follow the output folder
  relocated o svgNamed pageNamed = o
    { optSvg    = if svgNamed  then optSvg o    else moved o <$> optSvg o
    , optReplay = if pageNamed then optReplay o else moved o <$> optReplay o }
  moved o f
    | f `elem` [optOut o0 </> "run.svg", optOut o0 </> "replay.html"] = optOut o </> drop (length (optOut o0) + 1) f
    | otherwise = f
  number flag ok v = case decimalLit (trim v) of
    Just x | not (isNaN x || isInfinite x) && ok x -> Right x
    _ -> Left (flag ++ " expects " ++ what flag ++ " (written as in a world file: 2, 0.5, 1e-3), got "
               ++ show v)
  what flag | flag == "--seconds"        = "a non-negative number"
            | flag == "--odometry-noise" = "a number from 0 to " ++ num maxOdometryNoise
            | flag == "--dt"             = "a positive number up to " ++ num maxTimeStep
            | otherwise                  = "a positive number"
  check opts = case validateOptions opts of
    []   -> Right (RunWith opts)
    errs -> Left (intercalate "; " errs)

-- | Parse a @--param@ value, @NAME=VALUE@: the name is what comes before
-- the first @=@ and must not be empty; the value may be empty or hold @=@.
parseParam :: String -> Either String (String, String)
parseParam v = case break (== '=') v of
  (name, '=' : value) | not (null name) -> Right (name, value)
  _ -> Left ("--param expects NAME=VALUE, got " ++ show (argText v))

-- | A command-line argument (or the program's name) as text. GHC
-- decodes the arguments in the locale's encoding; in one that is not
-- UTF-8 (the C locale of many batch jobs and containers) each byte above
-- 127 comes as a stand-in character, U+DC80 to U+DCFF, which is how a
-- file of that name is opened again. As text, @--param naïve=1@ then did
-- not name the parameter @"naïve"@ that a controller asks for, and a
-- result line wrote the world @wé.world@ as two replacement characters.
-- 'argText' decodes each run of stand-ins that is UTF-8 as the
-- characters it spells, and leaves any other stand-in (a byte that is no
-- UTF-8) as it is. An argument without stand-ins is returned unchanged.
-- A @--param@'s name is read through it, to be compared with the names a
-- program asks for. Its value, like a file's name, is kept as given (as
-- 'System.Environment.getArgs' gives it, so that a value naming a file
-- opens it), and written through 'argText' in a result line or a log.
--
-- >>> argText "w\56515\56489.world"   -- "wé.world" in the C locale
-- "w\233.world"
-- >>> argText "a\56575b"              -- the byte 0xFF: no UTF-8
-- "a\56575b"
argText :: String -> String
argText s = case break standIn s of
  (plain, [])   -> plain
  (plain, rest) -> let (run, rest') = span standIn rest
                   in plain ++ utf8 [ fromEnum c - 0xDC00 | c <- run ] ++ argText rest'
  where
    standIn c = c >= '\xDC80' && c <= '\xDCFF'
    -- (the bytes of a run, all above 127: a well-formed UTF-8 sequence
    -- becomes its character; any other byte stays a stand-in)
    utf8 :: [Int] -> String
    utf8 [] = []
    utf8 (b : bs)
      | b >= 0xC2, b <= 0xDF, c1 : r <- bs, cont c1 = toEnum (bits b 0x1F [c1]) : utf8 r
      | b >= 0xE0, b <= 0xEF, c1 : c2 : r <- bs, cont c1, cont c2
      , let v = bits b 0x0F [c1, c2], v >= 0x800, v < 0xD800 || v > 0xDFFF = toEnum v : utf8 r
      | b >= 0xF0, b <= 0xF4, c1 : c2 : c3 : r <- bs, cont c1, cont c2, cont c3
      , let v = bits b 0x07 [c1, c2, c3], v >= 0x10000, v <= 0x10FFFF = toEnum v : utf8 r
      | otherwise = toEnum (0xDC00 + b) : utf8 bs
    cont c = c >= 0x80 && c <= 0xBF
    bits b mask cs = foldl (\acc c -> acc * 64 + (c - 0x80)) (b `mod` (mask + 1)) cs

-- | Set a parameter: a later @--param@ of the same name replaces the
-- earlier one where it stood.
setParam :: (String, String) -> [(String, String)] -> [(String, String)]
setParam (k, v) ps
  | any ((== k) . fst) ps = [ (k', if k' == k then v else v') | (k', v') <- ps ]
  | otherwise             = ps ++ [(k, v)]

-- | The largest magnitude of a @--seed@: 2^53, the largest up to which
-- every whole number is a 'Double' (the result line and the log record the
-- seed as a JSON number).
maxSeed :: Integer
maxSeed = 2 ^ (53 :: Int)

-- The ranges of the numbered settings, as the flags check them one at a
-- time and 'validateOptions' checks options set in code (NaN is in none).
secondsOk, dtOk, noiseOk, keyTimeOk :: Double -> Bool
secondsOk x = x >= 0
dtOk x      = x > 0 && x <= maxTimeStep
noiseOk x   = x >= 0 && x <= maxOdometryNoise
keyTimeOk x = x >= 0 && not (isInfinite x)

seedOk :: Integer -> Bool
seedOk x = abs x <= maxSeed

-- | The most steps a run may take: 10^8 (about 280 simulated hours at the
-- default step).
maxSteps :: Double
maxSteps = 1e8

-- | The widest (and tallest) frame, and SVG, 'optScale' may ask for, in
-- pixels.
maxFrameSide :: Double
maxFrameSide = 8000

-- | The pixels the long side of a world spans at the default scale
-- ('fitScale'): 600.
fitPixels :: Double
fitPixels = 600

-- | The scale, in pixels per metre, at which the long side of a world of
-- this extent spans 'fitPixels': 60 for the notes' 10 m world, 6 for a
-- 100 m one. A frame is then at most 620 pixels on each side (with its
-- margin), whatever the world's size and shape.
fitScale :: Bounds -> Double
fitScale (Bounds x0 y0 x1 y1) = fitPixels / max (x1 - x0) (y1 - y0)

-- | The scale a run draws at, in a world of this extent: @--scale@ if
-- given, else 'fitScale'.
scaleFor :: Bounds -> SimOptions -> Double
scaleFor b o = maybe (fitScale b) id (optScale o)

-- | The faults of a set of options that no flag alone shows and that do
-- not depend on the world, one message each (empty when the options are
-- fine). Checked by 'parseSimArgs'; 'validateOptionsIn' adds the frame's
-- size.
validateOptions :: SimOptions -> [String]
validateOptions o =
  [ "--seconds and --dt must be finite numbers, --dt positive" | not (all finite [secs, dt, fps, scale]) || dt <= 0 || fps <= 0 ]
  -- (what the flags refuse one at a time, for options set in code and
  -- given to 'AFrobRobotSim.runSimWith': the simulator stopped at them
  -- with a bare error, after the log was begun)
  ++ [ "--seconds must be a number >= 0, got " ++ full secs | finite secs, not (secondsOk secs) ]
  ++ [ "--dt must be a positive number up to " ++ num maxTimeStep ++ ", got " ++ full dt
     | finite dt, dt > 0, not (dtOk dt) ]
  ++ [ "--odometry-noise must be a number from 0 to " ++ num maxOdometryNoise ++ ", got " ++ show noise
     | not (noiseOk noise) ]
  ++ [ "--scale must be a positive number, got " ++ full x | Just x <- [optScale o], finite x, x <= 0 ]
  ++ [ "--seed must be a whole number from -2^53 to 2^53, got " ++ show (optSeed o)
     | not (seedOk (toInteger (optSeed o))) ]
  ++ [ "--keys: a key press's time must be a finite number >= 0, got " ++ show t ++ " for " ++ show k
     | (t, k) <- optKeys o, not (keyTimeOk t) ]
  ++ [ "--seconds " ++ num secs ++ " with --dt " ++ num dt ++ " is "
       ++ (if isInfinite steps then "more steps than a number holds" else num steps ++ " steps")
       ++ ", more than the " ++ num maxSteps ++ " allowed"
     | all finite [secs, dt], dt > 0, tooMany ]
  ++ [ "--seconds " ++ full secs ++ " with --dt " ++ full dt ++ " is less than half a step, so nothing would be"
       ++ " simulated after time 0 (a run takes the whole number of steps nearest seconds / dt); give"
       ++ " --seconds " ++ full (dt / 2) ++ " or more, or 0 for the time-0 sample alone"
     | all finite [secs, dt], dt > 0, secs > 0, stepsBeforeFloor secs dt < 1 ]
  ++ [ "--fps times --dt must not exceed 1 (at most one frame per time step)"
     | finite fps, finite dt, fps * dt > 1 + 1e-9 ]
  ++ [ "--dt " ++ num dt ++ " does not divide the frame period 1/" ++ num fps ++ " s; --fps "
       ++ suggestion ++ " would work"
     | finite fps, finite dt, dt > 0, fps > 0, fps * dt <= 1 + 1e-9, fps * dt >= 1e-9, not tooMany
     , not (divides fps) ]
  ++ [ "--fps " ++ num fps ++ " is less than one frame in 10^9 steps of --dt " ++ num dt
     | finite fps, finite dt, fps > 0, dt > 0, fps * dt < 1e-9 ]
  ++ [ "--out must not be empty" | null (optOut o) ]
  ++ [ flag ++ " must not be empty (a file name)"
     | (flag, Just "") <- [ ("--svg", optSvg o), ("--replay", optReplay o), ("--log", optLog o)
                          , ("--result", optResult o), ("--video", optVideo o) ] ]
  ++ [ "--video " ++ show v ++ ": a video's name ends in " ++ intercalate ", " (map ('.' :) videoExtensions)
       ++ " (ffmpeg picks the format by it; an image's, such as .ppm or .png, would write frames)"
     | Just v@(_ : _) <- [optVideo o], map toLower (takeExtension v) `notElem` map ('.' :) videoExtensions ]
  where
    secs = optSeconds o; dt = optDt o; fps = optFps o; scale = maybe 1 id (optScale o)
    noise = optOdometryNoise o
    steps = secs / dt
    -- (more than maxSteps as runSteps counts them, with its slack)
    tooMany = isNaN steps || stepsBeforeFloor secs dt >= maxSteps + 1
    -- a number as it is, without rounding (0.0025, 1.25e-301)
    full x | x /= 0 && (abs x < 1e-4 || abs x >= 1e9) = show x
           | otherwise                               = showFFloat Nothing x ""
    finite x = not (isNaN x || isInfinite x)
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

-- | The steps a run of these options takes after its time-0 sample: the
-- whole number nearest @seconds / dt@, a half rounded up (0 at least),
-- with a millionth of a step's slack, as for the key presses
-- ('AFrobRobotSim.Simulator.keyDue'), so that a half written in decimals
-- counts as one whatever its rounding (0.15 / 0.1 is a little under 1.5):
-- @--seconds 0.25 --dt 0.1@ is 3 steps, @--seconds 0.15 --dt 0.1@ 2,
-- @--seconds 0.005@ at the default step 1 (a tie went to the even number
-- before: 2, 1 and 0, the last refused).
runSteps :: SimOptions -> Int
runSteps o = max 0 (floor (stepsBeforeFloor (optSeconds o) (optDt o)))

-- @seconds / dt@ with a half and the slack added: 'runSteps' is its whole
-- part (the checks before a run compare it, not the rounded count, so
-- that an infinite or huge quotient is not taken whole).
stepsBeforeFloor :: Double -> Double -> Double
stepsBeforeFloor secs dt = secs / dt + 0.5 + 1e-6

-- | The extensions (in any case) that @--video@ takes, each a video
-- format that Debian's ffmpeg writes from the frames: @mp4@, @m4v@,
-- @mkv@, @webm@, @mov@, @avi@ and @gif@. Any other is refused before the
-- run: ffmpeg chooses the format by the extension, and would fail after
-- the run on one it does not know, or take an image's (@.ppm@) as a
-- pattern of numbered files and write frames over the run's own.
videoExtensions :: [String]
videoExtensions = ["mp4", "m4v", "mkv", "webm", "mov", "avi", "gif"]

-- | The fewest pixels a frame may give its world's long side: 10. A
-- @--scale@ that gives fewer draws nothing that can be seen.
minWorldPixels :: Double
minWorldPixels = 10

-- | 'validateOptions' and the faults that depend on the world, of this
-- extent: a frame (world and margin) at the scale in effect ('scaleFor')
-- more than 'maxFrameSide' pixels wide or tall, or a world less than
-- 'minWorldPixels' across on its long side. Checked by
-- 'AFrobRobotSim.runSimWith' before simulating.
validateOptionsIn :: Bounds -> SimOptions -> [String]
validateOptionsIn b@(Bounds x0 y0 x1 y1) o =
  validateOptions o
  ++ [ "--scale " ++ num scale ++ " makes the frame of this " ++ num w ++ " by " ++ num h
       ++ " m world " ++ num side ++ " pixels on its long side, more than " ++ num maxFrameSide
     | finite scale, side > maxFrameSide ]
  ++ [ "--scale " ++ num scale ++ " draws this " ++ num w ++ " by " ++ num h ++ " m world " ++ num (side - 20)
       ++ " pixels across, too small to show it (at least " ++ num minWorldPixels ++ "; without --scale it is "
       ++ num fitPixels ++ ")"
     | finite scale, side - 20 < minWorldPixels ]
  where
    scale = scaleFor b o
    w = x1 - x0
    h = y1 - y0
    side = max w h * scale + 20
    finite x = not (isNaN x || isInfinite x)

-- A number as a person writes it: 25, 0.01, 33.333, 1e+20.
num :: Double -> String
num x
  | x /= 0 && (abs x < 1e-3 || abs x >= 1e9) = printf "%.3e" x
  | otherwise = let s = printf "%.3f" x :: String
                in reverse (dropWhile (== '.') (dropWhile (== '0') (reverse s)))

-- | Parse scripted key presses: @"1.5:a,3:b"@ is @a@ at 1.5 s and @b@ at
-- 3 s (@--keys@ may be given more than once: the presses of all are
-- taken). Times must be finite and non-negative; a key is one character, or
-- one of the names @space@ and @comma@ for the two characters the list
-- itself cannot hold (@"2:space,4:comma"@).
parseKeys :: String -> Either String [(Double, Char)]
parseKeys s
  | all isSpace s = Right []
  | otherwise     = mapM one (splitOn ',' s)
  where
    one item = case break (== ':') (trim item) of
      (t, ':' : key) | Just x <- decimalLit (trim t), keyTimeOk x
                     , Just k <- keyNamed key -> Right (x, k)
      _ -> Left ("--keys expects TIME:KEY pairs separated by commas (e.g. \"1.5:a,3:b\"; a KEY is one "
                 ++ "character, or space or comma), got " ++ show item)
    keyNamed [c] = Just c
    keyNamed key = case map toLower key of
      "space" -> Just ' '
      "comma" -> Just ','
      _       -> Nothing

splitOn :: Char -> String -> [String]
splitOn c str = case break (== c) str of
  (a, _ : rest) -> a : splitOn c rest
  (a, [])       -> [a]

trim :: String -> String
trim = reverse . dropWhile isSpace . reverse . dropWhile isSpace

-- | The usage text, with the defaults.
usage :: String -> String
usage prog = intercalate "\n"
  [ "usage: " ++ prog ++ " [flags]"
  , ""
  , "Runs the simbot simulator headless: prints the robots' console messages,"
  , "writes an SVG of the run and an HTML replay page (PPM frames with --frames),"
  , "and ends with a one-line summary."
  , ""
  , "  --seconds T        simulated time to run                 (default 30)"
  , "  --dt D             fixed time step, seconds, at most 1e6 (default 0.01)"
  , "  --fps F            frames per simulated second           (default 25)"
  , "  --out DIR          output folder                         (default simbot-out)"
  , "  --frames           also write PPM frames (1.15 MB each: 866 MB for 30 s at 25 fps)"
  , "  --no-frames        write no frames (the default)"
  , "  --scale PX         pixels per metre   (default: the world's long side is 600 px)"
  , "  --keys \"1.5:a,3:b\" scripted key presses (time:key, ...; 2:space and 4:comma name those keys;"
  , "                     repeatable)"
  , "  --seed N           seed of the odometry noise            (default 0)"
  , "  --odometry-noise X relative odometry error per step, 0-1 (default 0 = exact)"
  , "  --quiet            print only the summary line"
  , "  --world FILE       load the world from FILE instead of the program's"
  , "  --dump-world       print the world in the world-file format and exit"
  , "  --rays             draw the four range-finder rays"
  , "  --trails           draw each robot's path so far"
  , "  --svg FILE         write one SVG picture of the whole run  (default simbot-out/run.svg)"
  , "  --no-svg           write no SVG"
  , "  --replay FILE      write the HTML replay page              (default simbot-out/replay.html)"
  , "  --no-replay        write no replay page"
  , "  --log FILE.jsonl   write the JSON-lines run log (see docs/LOG.md)"
  , "  --video FILE.mp4   assemble the frames into a video (needs ffmpeg and --frames;"
  , "                     also .m4v .mkv .webm .mov .avi .gif)"
  , "  --result FILE      write the run's settings and outcome as one JSON line"
  , "  --param NAME=VALUE a parameter the controllers read (repeatable)"
  , "  --help             print this usage and exit"
  ] ++ concat [ "\n\n" ++ prog ++ " --replay-from F.jsonl --replay OUT.html\n"
                ++ "  turns a run log written with --log into a replay page (simulates nothing)"
              | "simbot" `isSuffixOf` prog ]
