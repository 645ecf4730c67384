-- |
-- Module      : AFrobRobotSim.Options.CommandLine
-- Description : The command line of a simulation run: its flags parsed
--               into settings, and its usage text.
--
-- 'parseSimArgs' reads the flags listed in "AFrobRobotSim.Options" on top
-- of a program's settings, refusing a flag's bad value with a message
-- that names the flag, and checks the result ('validateOptions');
-- 'usage' is the text of @--help@. The values of two flags have a grammar
-- of their own, @--keys@ ('parseKeys') and @--param@ ('parseParam'), and
-- 'argText' reads an argument that the locale's encoding left as
-- stand-ins as the text it spells. Re-exported by "AFrobRobotSim.Options".
module AFrobRobotSim.Options.CommandLine
  ( -- * Parsing
    Command (..)
  , parseSimArgs
  , parseSimFlags
  , parseKeys
  , parseParam
  , isHelpFlag
  , argText
    -- * Help
  , usage
  ) where

import           Data.Char       (isSpace, toLower)
import           Data.List       (intercalate, isSuffixOf)
import           Data.Maybe      (isJust)
import           System.FilePath ((</>))

import           AFrobRobotSim.Options.Check
import           AFrobRobotSim.Options.Settings
import           AFrobRobotSim.Simulator (maxOdometryNoise, maxTimeStep)
import           AFrobRobotSim.WorldFile.Lexical (decimalLit, integerLit)

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
-- included), and each @--param@ of a new name adds it ('optParams'). A
-- @--param@ whose name this command line has given already replaces that
-- value, where it stood (the last value is used), and the name is kept
-- with all its values in 'optParamsRepeated' (after the given settings'),
-- so that 'AFrobRobotSim.runSimWith' warns of it: a name given twice is
-- usually a mistake (a job line and the flags every run gets both giving
-- it), and a run that silently used one value would be taken for a run
-- of the other. So is every other flag that takes a value (@--seconds@,
-- @--world@, @--svg@, ...) given twice: its last value is used, and it is
-- kept with all its values, as given, in 'optFlagsRepeated' (after the
-- given settings'). A flag that only replaces a value of the given
-- settings is no repeat, and neither is a flag without a value
-- (@--no-svg@ after @--svg a.svg@ is an order, not a repeat); and
-- @--svg@s or @--replay@s that a last @--no-svg@ or @--no-replay@ undoes
-- are none (after @--svg a.svg --svg b.svg --no-svg@ no SVG is written,
-- so no value is said to be used).
parseSimArgs :: SimOptions -> [String] -> Either String Command
parseSimArgs o0 args = parseSimFlags o0 args >>= \c -> case c of
  RunWith opts -> case validateOptions opts of
    []   -> Right (RunWith opts)
    errs -> Left (intercalate "; " errs)
  ShowHelp     -> Right ShowHelp

-- | 'parseSimArgs' without its check that the settings fit together
-- ('validateOptions'): only what each flag refuses on its own (an
-- unknown flag, a missing or malformed value, a number out of the flag's
-- range, an empty file name, a video's name that is no video format's:
-- 'outputNameFaults'), which does not depend on the given settings, and
-- both printing modes asked for ('printingModesFault', refused before
-- the others). For a reader of
-- the command line's @--param@s ('AFrobRobotSim.getSimParams'), which
-- cannot know the settings a program starts from: whether @--dt 0.05@
-- fits the frame rate is the program's run's to say.
parseSimFlags :: SimOptions -> [String] -> Either String Command
parseSimFlags o0 = go o0 False False [] []
  where
  -- the settings so far, whether the SVG and the page were named, the
  -- @--param@s of this command line so far (name and value, latest
  -- first), and its other flags with a value but @--keys@ (the same)
  go o svgNamed pageNamed given flags args = case args of
    []                       -> let o' = repeats given flags (relocated o svgNamed pageNamed)
                                in case (printingModesFault o', outputNameFaults o') of
                                     (Just fault, _) -> Left fault
                                     (Nothing, [])   -> Right (RunWith o')
                                     (Nothing, errs) -> Left (intercalate "; " errs)
    flag : _ | isHelpFlag flag -> Right ShowHelp
    flag : rest | Just switch <- lookup flag switches ->
      case switch (o, svgNamed, pageNamed) of (o', s', p') -> go o' s' p' given flags rest
    flag : rest | Just set <- lookup flag (valued o) -> case rest of
      v : _ | isFlag v -> Left (flag ++ " needs a value (see --help), found the flag " ++ v)
      v : rest' -> set v >>= \o' -> go o' (svgNamed || flag == "--svg") (pageNamed || flag == "--replay")
                                        (givenParam flag v ++ given) (givenFlag flag v ++ flags) rest'
      []        -> Left (flag ++ " needs a value (see --help)")
    flag : _                 -> Left ("unknown argument " ++ show flag ++ " (see --help)")
  -- (a --param's value parsed once more: 'set' has accepted it)
  givenParam flag v
    | flag == "--param", Right (k, x) <- parseParam v = [(argText k, x)]
    | otherwise                                       = []
  -- (the flags that take one value, whose last value is used)
  givenFlag flag v
    | flag `elem` ["--param", "--keys"] = []
    | otherwise                         = [(flag, v)]
  -- the names and flags given more than once, in the order first given,
  -- with their values in order
  repeats given flags o = o { optParamsRepeated = optParamsRepeated o0 ++ repeatedBy (reverse given)
                            , optFlagsRepeated  = optFlagsRepeated o0 ++ repeatedBy (reverse (filter (used o) flags)) }
  -- (an @--svg@ or @--replay@ that a later @--no-svg@ or @--no-replay@
  -- undid: none of its values is used, so none is said to be)
  used o (flag, _) = case flag of
    "--svg"    -> isJust (optSvg o)
    "--replay" -> isJust (optReplay o)
    _          -> True
  -- a value that is one of the flags is a value left out (@--out --no-svg@
  -- would write into a folder named @--no-svg@); @./--no-svg@ names such a file
  isFlag v = isHelpFlag v || v `elem` (map fst switches ++ map fst (valued o0))
  -- the flags without a value: the settings, and whether the SVG and the
  -- page were named
  switches =
    [ ("--no-frames",  \(o, s, p) -> (o { optFrames = False }, s, p))
    , ("--frames",     \(o, s, p) -> (o { optFrames = True }, s, p))
    , ("--no-svg",     \(o, _, p) -> (o { optSvg = Nothing }, True, p))
    , ("--no-replay",  \(o, s, _) -> (o { optReplay = Nothing }, s, True))
    , ("--quiet",      \(o, s, p) -> (o { optQuiet = True }, s, p))
    , ("--dump-world", \(o, s, p) -> (o { optDumpWorld = True }, s, p))
    , ("--print-program", \(o, s, p) -> (o { optPrintProgram = True }, s, p))
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
            | flag == "--odometry-noise" = "a number from 0 to " ++ readableNumber maxOdometryNoise
            | flag == "--dt"             = "a positive number up to " ++ readableNumber maxTimeStep
            | otherwise                  = "a positive number"
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

-- | Whether an argument asks for the usage: @--help@ or @-h@ (read from
-- the left, as every flag is: the first one, or the first fault before
-- it, decides). The simulator's command line, @afrp-examples@' and
-- @simbot --replay-from@'s all take these two.
isHelpFlag :: String -> Bool
isHelpFlag a = a == "--help" || a == "-h"

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
  , "  --print-program    print the program's name as its result line writes it (JSON) and exit"
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
  , "  --param NAME=VALUE a parameter the controllers read (repeatable, a name once: a name given"
  , "                     again warns, and its last value is used)"
  , "  --help             print this usage and exit"
  , ""
  , "A flag that takes a value, given twice, warns, and its last value is used (but --keys:"
  , "the presses of every --keys are taken)."
  ] ++ concat [ "\n\n" ++ prog ++ " --replay-from F.jsonl --replay OUT.html\n"
                ++ "  turns a run log written with --log into a replay page (simulates nothing)"
              | "simbot" `isSuffixOf` prog ]
