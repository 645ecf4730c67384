{-# LANGUAGE BangPatterns        #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Sweep
-- Description : Merging the result lines of a sweep into one table.
--
-- A sweep (@scripts/sweep@, @scripts/sweep.sbatch@) writes one result line
-- per run ("AFrobRobotSim.Result"), in shards, in whatever order the runs
-- finished. 'mergeResults' groups the runs by their setting (the world and
-- the parameters) and prints, per group, the mean, minimum and maximum of
-- every outcome over its runs; when two or more settings vary (two
-- parameters, or a parameter and the world), it then prints the same per
-- value of each setting, over all the values of the others. A run that
-- failed (a controller error, or a line the sweep wrote for a run that
-- wrote none) is counted and listed under its group, never dropped; its
-- outcome, as far as it got, still counts. A line that is neither a run's
-- result line nor the sweep's line for a run with no result (a run log
-- given by mistake, @{}@) is refused with its number and what it lacks,
-- never counted as a failed run.
--
-- The design trade-off is memory: the lines are read one at a time and
-- each is folded into its group's tallies (a count, an exact sum, the
-- least and the greatest value of each outcome) and dropped, so the
-- memory is the table's, whatever the number of lines: 10^6 lines of 8
-- settings take no more than 10^3 do. Two things grow with the runs: the
-- seeds seen per setting (a set of integers, for refusing a run merged
-- twice; a few bytes per run, less for consecutive seeds), and the failed
-- runs listed, at most 'maxListedFailures' per group. A line is read up
-- to 'maxLineBytes' bytes: a longer one (an endless line of
-- @\/dev\/zero@) is refused once that much is read.
--
-- The table does not depend on the order of the lines: the sums are
-- exact (a 'Double' is a binary fraction, and binary fractions add
-- exactly as integers times a power of two; the mean is rounded once, at
-- the end), and everything else is ordered by seed, so shards merged in
-- any order give the same table.
module AFrobRobotSim.Sweep
  ( mergeResults
  , maxLineBytes
  , maxListedFailures
  , sweepMergeMain
  ) where

import           Control.Exception   (IOException, try)
import           Control.Monad       (foldM, when)
import           Data.Bits           (shiftL)
import qualified Data.ByteString     as B
import           Data.Char           (isSpace)
import qualified Data.IntMap.Strict  as IM
import qualified Data.IntSet         as IS
import           Data.List           (intercalate, isPrefixOf, sortOn, stripPrefix, tails)
import qualified Data.Map.Strict     as M
import           Data.Ratio          ((%))
import qualified Data.Set            as S
import           System.Environment  (getArgs)
import           System.Exit         (exitWith, ExitCode (..))
import           System.IO           (Handle, IOMode (ReadMode), hClose, hIsTerminalDevice, hPutStrLn,
                                      hSetBinaryMode, openBinaryFile, stderr, stdin)
import           Text.Printf         (printf)

import           AFrobRobotSim.JSON
import           AFrobRobotSim.Console (displayPath, endOutput, printableLine, tolerantOutput)
import           AFrobRobotSim.OutputFile (fileIdentity)
import           AFrobRobotSim.WorldFile.Lexical (canonicalPath, cannotRead, utf8Text)

-- | The longest line 'sweepMergeMain' reads: 16 MiB (16,777,216 bytes).
-- A run's result line is about 250 bytes a robot at most (every number
-- at its longest, @-2.2250738585072014e-308@), 2.4 MiB for the 10,000
-- robots a world file may hold; what else it holds comes from the run's
-- command line (the world's name, the parameters), at most 2 MiB of
-- arguments on Linux, 12 MiB were every character escaped (@\\u001b@).
-- A line at the limit takes about 1.7 GB and 20 s to read (the parser
-- works on a 'String'): the most memory a hostile input can take.
maxLineBytes :: Int
maxLineBytes = 16 * 1024 * 1024

-- | The failed runs a group of the table lists, at most: 1000, the least
-- by seed (then by message); the others are counted in a line of their
-- own. (Every failed run is counted in the group's heading.)
maxListedFailures :: Int
maxListedFailures = 1000

------------------------------------------------------------------------------
-- Runs

-- The setting of a run: the world, then the parameters by name.
type Setting = [(String, String)]

-- A run's seed: as the table writes it (its JSON text), and the key that
-- tells runs apart (an integer, or the text of any other seed).
data Seed = Seed !String !(Either String Int)

-- One line, read: the setting, the seed, the time step and duration of a
-- result line (their JSON text; 'Nothing' for the sweep's line for a run
-- with no result), the failure, and every outcome's value ('Nothing':
-- @null@, which is how a result line writes a number that is not finite).
data Run = Run
  { runSetting :: Setting
  , runSeed    :: Seed
  , runSteps   :: Maybe (String, String)
  , runFailure :: Maybe String
  , runValues  :: [(String, Maybe Double)]
  }

-- | One line of a sweep's result file: either the result line a run
-- writes (@--result@, "AFrobRobotSim.Result": @program@, @world@, @seed@
-- a number, @dt@, @seconds@, @params@ and the @outcome@ object with
-- @simulated@, @steps@, @interrupted@, @failure@, @robots@ and @scores@),
-- or the line @scripts/sweep@ writes for a run that wrote none
-- (@program@, @world@, @seed@ a number or a string, @params@, @flags@,
-- and @failure@ a string where the result line has its outcome). Any
-- other JSON (a run log's line, @{}@) is refused, naming what it lacks,
-- rather than counted as a failed run.
readRun :: JSON -> Either String Run
readRun v = either (\e -> Left ("not a result line of a sweep (" ++ e ++ ")")) Right $ do
  fields <- case v of
    JObject kvs -> Right kvs
    _           -> Left "not a JSON object"
  _      <- member "program" v >>= asString
  world  <- member "world" v >>= asString
  params <- member "params" v >>= \p -> case p of
    JObject kvs -> mapM (\(k, x) -> (,) k <$> asString x) kvs
    _           -> Left "\"params\" is not an object"
  seedValue <- member "seed" v
  let setting = ("world", world) : sortOn fst params
      seed k  = Seed (encodeJSON seedValue) k
  case lookup "outcome" fields of
    Nothing -> do
      -- the sweep's line for a run with no result
      key <- case seedValue of
        JNumber x -> Right (seedNumber x)
        JString _ -> Right (Left (encodeJSON seedValue))
        _         -> Left "\"seed\" is neither a number nor a string"
      _       <- member "flags" v >>= asString
      failure <- member "failure" v >>= asString
      pure (Run setting (seed key) Nothing (Just failure) [])
    Just out -> do
      key <- case seedValue of
        JNumber x -> Right (seedNumber x)
        _         -> Left "\"seed\" is not a number"
      dt      <- member "dt" v >>= numberText
      seconds <- member "seconds" v >>= numberText
      outFailure  <- member "failure" out >>= \f -> case f of
        JNull -> Right Nothing
        _     -> Just <$> asString f
      interrupted <- member "interrupted" out >>= asBool
      simulated   <- member "simulated" out >>= finite
      steps       <- member "steps" out >>= finite
      robots      <- member "robots" out >>= asArray
      perRobot    <- concat <$> mapM robotValues robots
      scores      <- member "scores" out >>= \s -> case s of
        JObject kvs -> mapM (\(k, x) -> (,) ("score " ++ k) <$> finite x) kvs
        _           -> Left "\"scores\" is not an object"
      let fault = case (outFailure, interrupted) of
            (Just f, _)   -> Just f
            (_, True)     -> Just "interrupted"
            _             -> Nothing
      pure (Run setting (seed key) (Just (dt, seconds)) fault
                ([("simulated", simulated), ("steps", steps)] ++ perRobot ++ scores))
  where
    -- (a seed is a whole number of at most 2^53, as --seed takes it)
    seedNumber x
      | x == fromIntegral r && abs r <= 2 ^ (53 :: Int) = Right r
      | otherwise = Left (encodeNumber x)
      where r = round x :: Int
    numberText x = encodeJSON . maybe JNull JNumber <$> finite x
    robotValues r = do
      ty <- member "type" r >>= asString
      i  <- member "id" r >>= asInt
      let name f = ty ++ " " ++ show i ++ " " ++ f
      mapM (\f -> (,) (name f) <$> (member f r >>= finite))
           ["x", "y", "heading", "distance", "bumps", "stuckTime", "battery"]

-- A number, or 'Nothing' for @null@ or a number that is not finite
-- (1e999 reads as infinity); -0 is 0 (so that the least of 0 and -0 is
-- the same whichever comes first).
finite :: JSON -> Either String (Maybe Double)
finite JNull = Right Nothing
finite x     = (\d -> if isNaN d || isInfinite d then Nothing else Just (d + 0)) <$> asNumber x

------------------------------------------------------------------------------
-- Tallies

-- A sum of doubles, exactly: @m * 2^e@.
data ExactSum = ExactSum !Integer !Int

addExact :: ExactSum -> ExactSum -> ExactSum
addExact a@(ExactSum m1 e1) b@(ExactSum m2 e2)
  | m1 == 0   = b
  | m2 == 0   = a
  | e1 <= e2  = ExactSum (m1 + m2 `shiftL` (e2 - e1)) e1
  | otherwise = addExact b a

exactOf :: Double -> ExactSum
exactOf x = uncurry ExactSum (decodeFloat x)

-- The sum divided by n, rounded once.
exactMean :: ExactSum -> Int -> Double
exactMean (ExactSum m e) n
  | e >= 0    = fromRational ((m `shiftL` e) % fromIntegral n)
  | otherwise = fromRational (m % (fromIntegral n `shiftL` negate e))

-- One outcome over a group's runs: where it is first named (the least
-- seed, as text, and its place in that run's line: the table's order),
-- how many runs gave a finite value and how many @null@, their exact sum,
-- least and greatest.
data Stat = Stat !(String, Int) !Int !Int !ExactSum !Double !Double

statOf :: (String, Int) -> Maybe Double -> Stat
statOf at (Just x) = Stat at 1 0 (exactOf x) x x
statOf at Nothing  = Stat at 0 1 (ExactSum 0 0) 0 0

addStat :: Stat -> Stat -> Stat
addStat (Stat f1 n1 z1 s1 lo1 hi1) (Stat f2 n2 z2 s2 lo2 hi2) =
  Stat (min f1 f2) (n1 + n2) (z1 + z2) (addExact s1 s2) lo hi
  where
    (lo, hi) | n1 == 0   = (lo2, hi2)
             | n2 == 0   = (lo1, hi1)
             | otherwise = (min lo1 lo2, max hi1 hi2)

-- Seeds seen: the integers, and the text of any other.
data Seeds = Seeds !IS.IntSet !(S.Set String)

noSeeds :: Seeds
noSeeds = Seeds IS.empty S.empty

hasSeed :: Seed -> Seeds -> Bool
hasSeed (Seed _ k) (Seeds is ts) = either (`S.member` ts) (`IS.member` is) k

withSeed :: Seed -> Seeds -> Seeds
withSeed (Seed _ k) (Seeds is ts) = either (\t -> Seeds is (S.insert t ts)) (\i -> Seeds (IS.insert i is) ts) k

-- A group's tallies: its runs, its failed runs (those listed, by seed and
-- message, with how many of each), each outcome's 'Stat' (by the number
-- of its name), and the seeds of its runs: of the sweep's lines for runs
-- with no result, of all result lines, and of the result lines of each
-- time step and duration.
data Group = Group
  { gRuns    :: !Int
  , gFailed  :: !Int
  , gListed  :: !Listed
  , gStats   :: !(IM.IntMap Stat)
  , gNoRes   :: !Seeds
  , gResults :: !Seeds
  , gBySteps :: !(M.Map (String, String) Seeds)
  }

emptyGroup :: Group
emptyGroup = Group 0 0 (Listed 0 M.empty) IM.empty noSeeds noSeeds M.empty

-- The failed runs a group lists: how many, and by seed and message, with
-- how many of each; the least ones, at most 'maxListedFailures'.
data Listed = Listed !Int !(M.Map (String, String) Int)

-- Add a failed run (its seed and message) to the list.
listAdd :: (String, String) -> Listed -> Listed
listAdd key (Listed n m)
  | n < maxListedFailures = Listed (n + 1) (M.insertWith (+) key 1 m)
  | otherwise = case M.lookupMax m of
      Just (top, _) | key < top -> Listed n (M.insertWith (+) key 1 (M.updateMax (\k -> if k > 1 then Just (k - 1) else Nothing) m))
      _                         -> Listed n m

-- The listed failed runs, by seed and message.
listedRuns :: Listed -> [(String, String)]
listedRuns (Listed _ m) = [ key | (key, k) <- M.toList m, _ <- [1 .. k] ]

-- The merged lines so far: the numbers of the outcomes' names, each
-- group's tallies, and the runs counted.
data Merge = Merge !(M.Map String Int) !(M.Map Setting Group) !Int

emptyMerge :: Merge
emptyMerge = Merge M.empty M.empty 0

-- Add a run, or say why not: a run of the same setting and seed (and,
-- both being result lines, time step and duration) is there already.
addRun :: Merge -> Run -> Either String Merge
addRun (Merge names groups n) run
  | repeated  = Left ("the run " ++ showSetting (runSetting run) ++ " seed " ++ seedText ++ steps
                      ++ " is on an earlier line too (a result file merged twice, or a run merged with"
                      ++ " its rerun?): each run may be merged once")
  | otherwise = Right (Merge names' (M.insert (runSetting run) g' groups) (n + 1))
  where
    seed@(Seed seedText _) = runSeed run
    g = M.findWithDefault emptyGroup (runSetting run) groups
    repeated = hasSeed seed (gNoRes g) || case runSteps run of
      Nothing -> hasSeed seed (gResults g)
      Just ds -> hasSeed seed (M.findWithDefault noSeeds ds (gBySteps g))
    steps = maybe "" (\(dt, s) -> " (dt " ++ dt ++ ", seconds " ++ s ++ ")") (runSteps run)
    (names', numbered) = foldr number (names, []) (runValues run)
    number (k, x) (ns, acc) = case M.lookup k ns of
      Just i  -> (ns, (i, x) : acc)
      Nothing -> let i = M.size ns in (M.insert k i ns, (i, x) : acc)
    g' = g { gRuns = gRuns g + 1
           , gFailed = gFailed g + maybe 0 (const 1) (runFailure run)
           , gListed = maybe (gListed g) (\f -> listAdd (seedText, cutMessage f) (gListed g)) (runFailure run)
           , gStats = foldr (\(place, (i, x)) -> IM.insertWith addStat i (statOf (seedText, place) x))
                            (gStats g) (zip [0 ..] numbered)
           , gNoRes = maybe (withSeed seed (gNoRes g)) (const (gNoRes g)) (runSteps run)
           , gResults = maybe (gResults g) (const (withSeed seed (gResults g))) (runSteps run)
           , gBySteps = maybe (gBySteps g) (\ds -> M.insertWith (\_ old -> withSeed seed old) ds (withSeed seed noSeeds)
                                                                (gBySteps g))
                              (runSteps run) }
    -- (a message is listed up to 2000 characters)
    cutMessage f = case splitAt 2000 f of
      (short, [])   -> short
      (short, _)    -> short ++ " (cut)"

-- Merge one line of text (a blank one is skipped).
addLine :: Merge -> String -> Either String Merge
addLine m l
  | all isSpace l = Right m
  | otherwise = either (\e -> Left ("not a result line of a sweep (not JSON: " ++ e ++ ")")) Right (parseJSON l)
                  >>= readRun >>= addRun m

------------------------------------------------------------------------------
-- The table

-- | The table of a sweep's result lines (the text of one or more result
-- files, one JSON object a line; blank lines are skipped), or the first
-- line that is not a result line of a sweep, or repeats a run (the same
-- setting and seed, and for two result lines the same @dt@ and
-- @seconds@), with its number; or, when there is no line,
-- @no result lines@.
mergeResults :: String -> Either String String
mergeResults text = do
  m <- foldM (\acc (k, l) -> either (\e -> Left ("line " ++ show k ++ ": " ++ e)) Right (addLine acc l))
             emptyMerge (zip [1 :: Int ..] (lines text))
  renderMerge m

-- The table of the merged lines ('Left' when there were none).
renderMerge :: Merge -> Either String String
renderMerge (Merge names groups n)
  | n == 0    = Left "no result lines"
  | otherwise = Right (unlines (map printableLine
      (  concatMap (\(s, g) -> table nameOf (showSetting s) g) (M.toList groups)
      ++ concatMap (\(kv, g) -> table nameOf (showSetting [kv] ++ " over all other settings") g) marginal
      ++ mixed)))
  where
    nameOf = IM.fromList [ (i, k) | (k, i) <- M.toList names ]
    values = M.fromListWith (+) [ (k, 1 :: Int) | (k, _) <- S.toList (S.fromList (concat (M.keys groups))) ]
    varying = [ k | (k, c) <- M.toList values, c > 1 ]
    -- with two or more settings varying, also each value of each over all the others
    marginal
      | length varying > 1 =
          M.toList (M.fromListWith (flip mergeGroups) [ (kv, g) | (s, g) <- M.toList groups, kv@(k, _) <- s, k `elem` varying ])
      | otherwise = []
    nMixed = length [ () | g <- M.elems groups, M.size (gBySteps g) > 1 ]
    mixed = [ "== note: " ++ show nMixed ++ (if nMixed == 1 then " setting mixes" else " settings mix")
              ++ " runs of different dt or seconds, which the table does not tell apart" | nMixed > 0 ]
    mergeGroups a b = Group (gRuns a + gRuns b) (gFailed a + gFailed b) (foldr listAdd (gListed a) (listedRuns (gListed b)))
                            (IM.unionWith addStat (gStats a) (gStats b)) noSeeds noSeeds M.empty

showSetting :: Setting -> String
showSetting g = unwords [ k ++ "=" ++ v | (k, v) <- g ]

-- One group's lines of the table: its heading, its outcomes (in the
-- order the runs, by seed, first name them), its failed runs by seed.
table :: IM.IntMap String -> String -> Group -> [String]
table nameOf heading g =
  [ "== " ++ heading ++ printf "  (%d runs, %d failed)" (gRuns g) (gFailed g) ]
  ++ [ printf "  %-28s %14s %14s %14s" ("outcome" :: String) ("mean" :: String) ("min" :: String) ("max" :: String)
     | not (IM.null (gStats g)) ]
  ++ map row (sortOn (\(k, Stat at _ _ _ _ _) -> (at, k)) [ (IM.findWithDefault "?" i nameOf, s) | (i, s) <- IM.toList (gStats g) ])
  ++ [ "  FAILED seed " ++ seed ++ ": " ++ f | (seed, f) <- listedRuns (gListed g) ]
  ++ [ printf "  and %d more failed runs (the first %d by seed are listed)" unlisted listed | unlisted > 0 ]
  where
    Listed listed _ = gListed g
    unlisted = gFailed g - listed
    row (name, Stat _ have other total lo hi) =
      printf "  %-28s %14s %14s %14s" name (orNA (exactMean total have)) (orNA lo) (orNA hi)
      ++ (if other > 0 then printf "  (%d runs; %d not a finite number)" have other
          else if have < gRuns g then printf "  (%d runs)" have else "")
      where orNA x = if have == 0 then "n/a" else number x
    number :: Double -> String
    number x
      | x /= 0 && (abs x < 1e-3 || abs x >= 1e7) = printf "%.4e" x
      | otherwise                                 = printf "%.4f" x

------------------------------------------------------------------------------
-- The program

-- A fault: the exit code, and the message.
data Fault = Fault !Int String

-- Fold the lines of one input into the merge, reading it in pieces: a
-- line is kept whole only up to 'maxLineBytes'.
mergeHandle :: String -> Handle -> Merge -> IO (Either Fault Merge)
mergeHandle name h = go 1 [] 0
  where
    go :: Int -> [B.ByteString] -> Int -> Merge -> IO (Either Fault Merge)
    go !k pending !len !m = do
      piece <- B.hGetSome h 65536
      if B.null piece
        then pure (if len == 0 then Right m else one k (B.concat (reverse pending)) m)
        else split k pending len m piece
    split !k pending !len !m piece = case B.elemIndex 10 piece of
      _ | B.null piece -> go k pending len m
      Nothing
        | len + B.length piece > maxLineBytes -> pure (Left (tooLong k))
        | otherwise -> go k (piece : pending) (len + B.length piece) m
      Just i
        | len + i > maxLineBytes -> pure (Left (tooLong k))
        | otherwise -> case one k (B.concat (reverse (B.take i piece : pending))) m of
            Left f   -> pure (Left f)
            Right m' -> m' `seq` split (k + 1) [] 0 m' (B.drop (i + 1) piece)
    one k bytes m = case utf8Text name bytes of
      Left msg -> Left (Fault 1 (maybe msg (\rest -> name ++ ":" ++ show k ++ ":" ++ rest) (stripPrefix (name ++ ":1:") msg)))
      Right l  -> either (\e -> Left (Fault 1 (name ++ ": line " ++ show k ++ ": " ++ e))) Right (addLine m l)
    tooLong k = Fault 2 (name ++ ": line " ++ show k ++ ": longer than " ++ show maxLineBytes
                         ++ " bytes (16 MiB), more than any result line: not a result file of a sweep?")

-- | The @afrp-sweep-merge [FILE...]@ program (and @scripts/sweep-merge@):
-- print the table of the result files, read in the order given, or of
-- standard input when none is given (refused when standard input is a
-- terminal). Exit code 0 with the table; otherwise nothing on standard
-- output, a message on standard error, and
--
-- * 1 when the lines are not a sweep's results: no result line at all
--   (@no result lines in FILE, ...@), a line that is not UTF-8
--   (@FILE:LINE:COLUMN: invalid UTF-8@), a line that is not a result line
--   of a sweep (@FILE: line N: not a result line of a sweep (...)@: not
--   JSON, or JSON that is neither a run's result line nor the sweep's
--   line for a run with no result, such as a run log given by mistake),
--   or a line that repeats a run (@FILE: line N: the run ... is on an
--   earlier line too@);
--
-- * 2 when they cannot be read: a file that cannot be read, one given
--   twice (under any name: the same canonical path, or the same device
--   and inode; not @\/dev\/...@ or @\/proc\/...@), a line longer than
--   'maxLineBytes', standard input a terminal.
sweepMergeMain :: IO ()
sweepMergeMain = do
  tolerantOutput
  args <- getArgs
  when (any (`elem` ["-h", "--help"]) args) $ do
    putStrLn usage
    endOutput prog
    exitWith ExitSuccess
  merged <- if null args
    then do
      tty <- either (\(_ :: IOException) -> False) id <$> try (hIsTerminalDevice stdin)
      when tty $ stop (Fault 2 ("no result files given, and standard input is a terminal\n" ++ usage))
      hSetBinaryMode stdin True
      readAll "standard input" stdin emptyMerge
    else do
      sameFiles args >>= mapM_ stop
      foldM (\m f -> do
               opened <- try (openBinaryFile f ReadMode)
               case opened of
                 Left e  -> stop (Fault 2 (cannotRead f e))
                 Right h -> readAll f h m <* hClose h)
            emptyMerge args
  case renderMerge merged of
    Right out -> putStr out >> endOutput prog
    Left _    -> stop (Fault 1 ("no result lines in " ++ (if null args then "standard input" else intercalate ", " (map displayPath args))))
  where
    prog = "afrp-sweep-merge"
    usage = "usage: afrp-sweep-merge RESULTS...   (the result lines of a sweep; standard input when none is given)"
    stop (Fault code msg) = endOutput prog >> hPutStrLn stderr (prog ++ ": " ++ msg) >> exitWith (ExitFailure code)
    -- (a file by its path, standard input by that name)
    readAll path h m = do
      r <- try (mergeHandle (displayPath path) h m)
      case r of
        Left e                -> stop (Fault 2 (cannotRead path (e :: IOException)))
        Right (Left fault)    -> stop fault
        Right (Right merged') -> pure merged'

-- The first file given twice, as a fault.
sameFiles :: [FilePath] -> IO (Maybe Fault)
sameFiles files = do
  keys <- mapM (\f -> do
                  c <- canonicalPath f
                  i <- fileIdentity f
                  pure (f, c, i))
               files
  let special (f, c, _) = any (\p -> any (p `isPrefixOf`) [f, c]) ["/dev/", "/proc/"]
      same (_, c1, i1) (_, c2, i2) = c1 == c2 || (i1 /= Nothing && i1 == i2)
  pure $ case [ (a, b) | (a : rest) <- tails (filter (not . special) keys), b <- rest, same a b ] of
    ((f1, _, _), (f2, _, _)) : _
      | f1 == f2  -> Just (Fault 2 (displayPath f1 ++ " is given twice: its runs would be counted twice"))
      | otherwise -> Just (Fault 2 (displayPath f1 ++ " and " ++ displayPath f2
                                    ++ " are the same file: its runs would be counted twice"))
    [] -> Nothing
