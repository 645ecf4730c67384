-- |
-- Module      : AFrobRobotSim.Options
-- Description : The settings of a simulation run and the command line that
--               sets them.
--
-- Every program built on 'AFrobRobotSim.runSim' accepts these flags:
--
-- @
-- --seconds T        simulated time to run                 (default 30)
-- --dt D             fixed time step, seconds              (default 0.01)
-- --fps F            frames per simulated second           (default 25)
-- --out DIR          folder for the PPM frames             (default frames)
-- --no-frames        write no frames
-- --scale PX         pixels per metre                      (default 60)
-- --keys "1.5:a,3:b" scripted key presses (time:key, ...)
-- --seed N           seed of the random parts              (default 0)
-- --odometry-noise X relative odometry error per step      (default 0 = exact)
-- --quiet            print only the summary line
-- --world FILE       load the world from FILE instead of the program's
-- --dump-world       print the world in the world-file format and exit
-- --rays             draw the four range-finder rays
-- --trails           draw each robot's path so far
-- --svg FILE         also write one SVG picture of the whole run
-- --video FILE.mp4   assemble the frames into a video (needs ffmpeg)
-- --help             print this usage and exit
-- @
module AFrobRobotSim.Options
  ( SimOptions (..)
  , defaultSimOptions
  , Command (..)
  , parseSimArgs
  , parseKeys
  , usage
  ) where

import           Data.Char  (isSpace)
import           Data.List  (intercalate)
import           Text.Read  (readMaybe)

-- | The settings of a run.
data SimOptions = SimOptions
  { optSeconds       :: !Double            -- ^ simulated seconds to run
  , optDt            :: !Double            -- ^ the fixed time step (s)
  , optFps           :: !Double            -- ^ frames per simulated second
  , optOut           :: FilePath           -- ^ folder for the frames
  , optFrames        :: !Bool              -- ^ write frames at all
  , optScale         :: !Double            -- ^ pixels per metre
  , optKeys          :: [(Double, Char)]   -- ^ scripted key presses
  , optSeed          :: !Int               -- ^ seed of the random parts
  , optOdometryNoise :: !Double            -- ^ relative odometry error per step
  , optQuiet         :: !Bool              -- ^ print only the summary
  , optWorldFile     :: Maybe FilePath     -- ^ load the world from this file
  , optDumpWorld     :: !Bool              -- ^ print the world and exit
  , optRays          :: !Bool              -- ^ draw range-finder rays
  , optTrails        :: !Bool              -- ^ draw trails
  , optSvg           :: Maybe FilePath     -- ^ write an SVG of the whole run
  , optVideo         :: Maybe FilePath     -- ^ assemble an mp4 with ffmpeg
  } deriving (Eq, Show)

-- | The defaults listed in the module documentation.
defaultSimOptions :: SimOptions
defaultSimOptions = SimOptions
  { optSeconds = 30, optDt = 0.01, optFps = 25, optOut = "frames", optFrames = True
  , optScale = 60, optKeys = [], optSeed = 0, optOdometryNoise = 0, optQuiet = False
  , optWorldFile = Nothing, optDumpWorld = False, optRays = False, optTrails = False
  , optSvg = Nothing, optVideo = Nothing }

-- | What a command line asks for.
data Command
  = RunWith SimOptions  -- ^ run (or dump the world) with these settings
  | ShowHelp            -- ^ print 'usage' and exit
  deriving (Eq, Show)

-- | Parse a command line on top of the given settings. Unknown flags,
-- missing or malformed values and out-of-range numbers are errors whose
-- message names the flag.
parseSimArgs :: SimOptions -> [String] -> Either String Command
parseSimArgs o args = case args of
  []                       -> check o
  "--help" : _             -> Right ShowHelp
  "-h" : _                 -> Right ShowHelp
  "--no-frames" : rest     -> parseSimArgs o { optFrames = False } rest
  "--quiet" : rest         -> parseSimArgs o { optQuiet = True } rest
  "--dump-world" : rest    -> parseSimArgs o { optDumpWorld = True } rest
  "--rays" : rest          -> parseSimArgs o { optRays = True } rest
  "--trails" : rest        -> parseSimArgs o { optTrails = True } rest
  flag : rest | Just set <- lookup flag valued -> case rest of
    v : rest' -> set v >>= \o' -> parseSimArgs o' rest'
    []        -> Left (flag ++ " needs a value (see --help)")
  flag : _                 -> Left ("unknown argument " ++ show flag ++ " (see --help)")
  where
    valued =
      [ ("--seconds", \v -> (\x -> o { optSeconds = x }) <$> number "--seconds" (>= 0) v)
      , ("--dt",      \v -> (\x -> o { optDt = x }) <$> number "--dt" (> 0) v)
      , ("--fps",     \v -> (\x -> o { optFps = x }) <$> number "--fps" (> 0) v)
      , ("--out",     \v -> Right o { optOut = v })
      , ("--scale",   \v -> (\x -> o { optScale = x }) <$> number "--scale" (> 0) v)
      , ("--keys",    \v -> (\ks -> o { optKeys = ks }) <$> parseKeys v)
      , ("--seed",    \v -> maybe (Left ("--seed expects a whole number, got " ++ show v))
                                  (\x -> Right o { optSeed = x }) (readMaybe v))
      , ("--odometry-noise", \v -> (\x -> o { optOdometryNoise = x }) <$> number "--odometry-noise" (>= 0) v)
      , ("--world",   \v -> Right o { optWorldFile = Just v })
      , ("--svg",     \v -> Right o { optSvg = Just v })
      , ("--video",   \v -> Right o { optVideo = Just v })
      ]
    number flag ok v = case readMaybe (trim v) :: Maybe Double of
      Just x | not (isNaN x || isInfinite x) && ok x -> Right x
      _ -> Left (flag ++ " expects a " ++ what flag ++ " number, got " ++ show v)
    what flag | flag `elem` ["--seconds", "--odometry-noise"] = "non-negative"
              | otherwise                                      = "positive"
    check opts
      | optFps opts * optDt opts > 1 + 1e-9 =
          Left "--fps times --dt must not exceed 1 (at most one frame per time step)"
      | otherwise = Right (RunWith opts)

-- | Parse scripted key presses: @"1.5:a,3:b"@ is @a@ at 1.5 s and @b@ at
-- 3 s. Times must be non-negative; a key is one character.
parseKeys :: String -> Either String [(Double, Char)]
parseKeys s
  | all isSpace s = Right []
  | otherwise     = mapM one (splitOn ',' s)
  where
    one item = case break (== ':') (trim item) of
      (t, ':' : [k]) | Just x <- readMaybe (trim t), x >= 0, not (isNaN x) -> Right (x, k)
      _ -> Left ("--keys expects TIME:KEY pairs separated by commas (e.g. \"1.5:a,3:b\"), got "
                 ++ show item)

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
  , "writes PPM frames, and ends with a one-line summary."
  , ""
  , "  --seconds T        simulated time to run                 (default 30)"
  , "  --dt D             fixed time step, seconds              (default 0.01)"
  , "  --fps F            frames per simulated second           (default 25)"
  , "  --out DIR          folder for the PPM frames             (default frames)"
  , "  --no-frames        write no frames"
  , "  --scale PX         pixels per metre                      (default 60)"
  , "  --keys \"1.5:a,3:b\" scripted key presses (time:key, ...)"
  , "  --seed N           seed of the random parts              (default 0)"
  , "  --odometry-noise X relative odometry error per step      (default 0 = exact)"
  , "  --quiet            print only the summary line"
  , "  --world FILE       load the world from FILE instead of the program's"
  , "  --dump-world       print the world in the world-file format and exit"
  , "  --rays             draw the four range-finder rays"
  , "  --trails           draw each robot's path so far"
  , "  --svg FILE         also write one SVG picture of the whole run"
  , "  --video FILE.mp4   assemble the frames into a video (needs ffmpeg)"
  , "  --help             print this usage and exit"
  ]
