{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Sweep.Merge
-- Description : A sweep's result lines folded, one at a time, into the
--               tallies of its settings, and the table of them.
--
-- The pure part of "AFrobRobotSim.Sweep" (which re-exports 'mergeResults'
-- and 'maxListedFailures'; see it for the design): a line read ('addLine':
-- a run's result line, or the sweep's line for a run that wrote none;
-- 'addLineUtf8' the same from the line's bytes),
-- added to its setting's tallies (a count, an exact sum, the least and
-- the greatest of each outcome; the seeds seen, to refuse a run merged
-- twice), and the table of the tallies ('renderMerge').
module AFrobRobotSim.Sweep.Merge
  ( -- * Merging
    Merge
  , emptyMerge
  , mergedRuns
  , addLine
  , addLineUtf8
  , renderMerge
  , mergeResults
  , maxListedFailures
  ) where

import           Control.Monad       (foldM)
import           Data.Bits           (shiftL)
import           Data.Char           (isDigit, isPrint, isSpace)
import qualified Data.ByteString     as B
import qualified Data.IntMap.Strict  as IM
import qualified Data.IntSet         as IS
import qualified Data.Map.Strict     as M
import           Data.List           (sortOn, stripPrefix)
import           Data.Ratio          ((%))
import qualified Data.Set            as S
import           Text.Printf         (printf)

import           AFrobRobotSim.Console (printableLine, quote)
import           AFrobRobotSim.JSON
import           AFrobRobotSim.UTF8  (Utf8, utf8Bytes)
import           AFrobRobotSim.WorldFile.Lexical (integerLit, utf8Text)

-- | The failed runs a group of the table lists, at most: 1000, the least
-- by seed (then by message); the others are counted in a line of their
-- own. (Every failed run is counted in the group's heading.)
maxListedFailures :: Int
maxListedFailures = 1000

------------------------------------------------------------------------------
-- Runs

-- The setting of a run: the world, then the parameters by name.
type Setting = [(String, String)]

-- The world of the sweep's line for a run that wrote no result and got no
-- @--world@ (@"world": null@): the program's own world (a result line's
-- @"program"@) or the built-in default (@"default"@), which the sweep
-- cannot tell. 'renderMerge' files such runs with the result lines of
-- that world, when the lines merged name one of the two ('ownWorlds'),
-- as a sweep of one program does. (A NUL, which no world's name holds:
-- a command line cannot pass one, so neither @--world@ nor a world of
-- @""@, which the sweep writes for @--world ''@, reads as it.)
unnamedWorld :: String
unnamedWorld = "\NUL"

-- The worlds a result line names when the run got no @--world@ (it names
-- a world file of either name @./default@, @./program@:
-- 'AFrobRobotSim.Result.worldSourceName').
ownWorlds :: [String]
ownWorlds = ["default", "program"]

-- A run's seed: as the table writes it (a whole number as such, any
-- other seed as its JSON text), and the key that tells runs apart (an
-- integer, or the text of any other seed).
data Seed = Seed !String !(Either String Int)

-- One line, read: the setting, the seed, the time step and duration of a
-- result line (their JSON text; 'Nothing' for the sweep's line for a run
-- with no result), the failure, and every outcome's value ('Nothing':
-- @null@, which is how a result line writes a number that is not finite).
data Run = Run
  { runSetting :: Setting
  , runSeed    :: Seed
  , runSteps   :: Maybe (String, String, String)
  , runFailure :: Maybe String
  , runValues  :: [(String, Maybe Double)]
  }

-- | One line of a sweep's result file: either the result line a run
-- writes (@--result@, "AFrobRobotSim.Result": @program@, @world@, @seed@
-- a number, @dt@, @seconds@, @params@ and the @outcome@ object with
-- @simulated@, @steps@, @interrupted@, @failure@, @robots@ and @scores@),
-- or the line @scripts/sweep@ writes for a run that wrote none
-- (@program@, @world@ a string or @null@ when the run got no @--world@:
-- @default@ or @program@ there, from an older sweep, is the world file of
-- that name, which the result line calls @./default@ or @./program@;
-- @seed@ a number or a string (a string that @--seed@ reads as a whole
-- number, @"007"@ from an older sweep, is that number, the seed its run's
-- result line says: 7), @params@, @flags@, and @failure@ a string
-- where the result line has its outcome). Any
-- other JSON (a run log's line, @{}@) is refused, naming what it lacks,
-- rather than counted as a failed run.
readRun :: JSON -> Either String Run
readRun v = either (\e -> Left ("not a result line of a sweep (" ++ e ++ ")")) Right $ do
  fields <- case v of
    JObject kvs -> Right kvs
    _           -> Left "not a JSON object"
  _      <- member "program" v >>= asString
  worldValue <- member "world" v
  world  <- case (worldValue, lookup "outcome" fields) of
    -- (the sweep's line for a run that got no --world: which world the
    -- program ran, the sweep cannot tell)
    (JNull, Nothing) -> Right unnamedWorld
    -- (the sweep's line for a run of --world default, written by a sweep
    -- from before it wrote such a file as a result line does, ./default:
    -- the file, not the built-in world)
    (_, Nothing) -> asString worldValue >>= \w -> Right (if w `elem` ownWorlds then "./" ++ w else w)
    _            -> asString worldValue
  params <- member "params" v >>= \p -> case p of
    JObject kvs -> mapM (\(k, x) -> (,) k <$> asString x) kvs
    _           -> Left "\"params\" is not an object"
  seedValue <- member "seed" v
  let setting = ("world", world) : sortOn fst params
  case lookup "outcome" fields of
    Nothing -> do
      -- the sweep's line for a run with no result
      seed <- case seedValue of
        JNumber x -> Right (numberSeed x)
        JString t -> Right (textSeed t)
        _         -> Left "\"seed\" is neither a number nor a string"
      _       <- member "flags" v >>= asString
      failure <- member "failure" v >>= asString
      pure (Run setting seed Nothing (Just failure) [])
    Just out -> do
      seed <- case seedValue of
        JNumber x -> Right (numberSeed x)
        _         -> Left "\"seed\" is not a number"
      dt      <- member "dt" v >>= numberText
      seconds <- member "seconds" v >>= numberText
      -- (a result line written before it was recorded: no noise, the default)
      noise   <- maybe (Right "0") numberText (lookup "odometryNoise" fields)
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
      pure (Run setting seed (Just (dt, seconds, noise)) fault
                ([("simulated", simulated), ("steps", steps)] ++ perRobot ++ scores))
  where
    -- (a seed is a whole number of at most 2^53, as --seed takes it)
    numberSeed x
      | x == fromIntegral r && seedInRange (toInteger r) = Seed (show r) (Right r)
      | otherwise = Seed (encodeNumber x) (Left (encodeNumber x))
      where r = round x :: Int
    -- (the seed of the sweep's line for a run with no result, as the
    -- program would have read it: written as the --seed of its job line
    -- was when --seed reads it as a whole number (007, +7, which an older
    -- sweep wrote as such strings: their run is seed 7, as its result line
    -- says), else as the text, quoted, and told apart from every number)
    textSeed t = case integerLit (trimmed t) of
      Just n | seedInRange n -> Seed (show n) (Right (fromInteger n))
      _                      -> Seed (encodeJSON (JString t)) (Left (encodeJSON (JString t)))
    seedInRange n = abs n <= 2 ^ (53 :: Int)
    trimmed = reverse . dropWhile isSpace . reverse . dropWhile isSpace
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

seedsUnion :: Seeds -> Seeds -> Seeds
seedsUnion (Seeds is1 ts1) (Seeds is2 ts2) = Seeds (IS.union is1 is2) (S.union ts1 ts2)

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
  , gBySteps :: !(M.Map (String, String, String) Seeds)
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

-- | The merged lines so far: the numbers of the outcomes' names, each
-- group's tallies, and the runs counted.
data Merge = Merge !(M.Map String Int) !(M.Map Setting Group) !Int

-- | No line merged yet.
emptyMerge :: Merge
emptyMerge = Merge M.empty M.empty 0

-- | How many runs are merged so far (lines, blank ones not counted): 0
-- is the one case 'renderMerge' refuses for having nothing to show.
mergedRuns :: Merge -> Int
mergedRuns (Merge _ _ n) = n

-- Add a run, or say why not: a run of the same setting and seed (and,
-- both being result lines, time step and duration) is there already.
addRun :: Merge -> Run -> Either String Merge
addRun (Merge names groups n) run
  | repeated  = Left ("the run " ++ showSetting (runSetting run) ++ " seed " ++ seedText ++ steps
                      ++ " is on an earlier line too (a result file merged twice, a run merged with its"
                      ++ " rerun, or runs told apart only by flags a result line does not record, such as"
                      ++ " --keys: give each such run a --param that names its setting):"
                      ++ " each run may be merged once")
  | otherwise = Right (Merge names' (M.insert (runSetting run) g' groups) (n + 1))
  where
    seed@(Seed seedText _) = runSeed run
    g = M.findWithDefault emptyGroup (runSetting run) groups
    repeated = hasSeed seed (gNoRes g) || case runSteps run of
      Nothing -> hasSeed seed (gResults g)
      Just ds -> hasSeed seed (M.findWithDefault noSeeds ds (gBySteps g))
    steps = maybe "" (\(dt, s, noise) -> " (dt " ++ dt ++ ", seconds " ++ s
                                         ++ (if noise == "0" then "" else ", odometry noise " ++ noise) ++ ")")
                  (runSteps run)
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

-- | Merge one line of text (a blank one is skipped): a result line of a
-- sweep, or the sweep's line for a run that wrote none; any other line,
-- or one that repeats a run (the same setting and seed, and for two
-- result lines the same @dt@ and @seconds@), is a 'Left' saying why.
addLine :: Merge -> String -> Either String Merge
addLine m l
  | all isSpace l = Right m
  | otherwise = either (Left . notJSON) Right (parseJSON l) >>= readRun >>= addRun m

-- The message of a line that is not JSON (the parser's message given). The
-- parser places its fault at @line 1, column C@ of the text it parsed,
-- which is this one line (its first and only line): said as @column C of
-- the line@, so that the only line a message numbers is the file's
-- (@line 2: ... (not JSON: line 1, column 151 ...)@ read as two lines).
notJSON :: String -> String
notJSON e = "not a result line of a sweep (not JSON: " ++ ofTheLine e ++ ")"
  where
    ofTheLine m = case stripPrefix "line 1, column " m of
      Just rest | (c@(_ : _), ':' : msg) <- span isDigit rest -> "column " ++ c ++ " of the line:" ++ msg
      _                                                       -> m

-- | 'addLine' of a line's bytes, found to be UTF-8: the same merge, or the
-- same message, as 'addLine' of its text. The bytes are parsed as they
-- are ('parseJSONUtf8'), without the text of the whole line, which would
-- take about 30 times the line's bytes (a 16 MiB line, 550 MB).
addLineUtf8 :: Merge -> Utf8 -> Either String Merge
addLineUtf8 m u
  | B.all asciiSpace bs = Right m
  | otherwise = case parseJSONUtf8 u of
      Right v -> readRun v >>= addRun m
      Left e
        -- (a line blank but for spaces beyond ASCII, U+00A0 and the like,
        -- is blank to 'isSpace' too)
        | B.any (>= 0x80) bs, Right l <- utf8Text "" bs, all isSpace l -> Right m
        | otherwise -> Left (notJSON e)
  where
    bs = utf8Bytes u
    asciiSpace b = b == 0x20 || (b >= 0x09 && b <= 0x0d)

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

-- | The table of the merged lines: per setting, the mean, least and
-- greatest of every outcome and the failed runs, then (when two or more
-- settings vary) the same per value of each ('Left' when no line was
-- merged). The sweep's lines for runs with no result that got no
-- @--world@ (@"world": null@) are filed under the world the result lines
-- name for such runs (@"program"@ or @"default"@), when they name one;
-- otherwise under @world=(not given)@ ('Left' when a run so filed is a
-- result line's too).
renderMerge :: Merge -> Either String String
renderMerge (Merge names groups0 n)
  | n == 0    = Left "no result lines"
  | otherwise = tableOf names <$> fileUnnamed groups0

-- The table of the groups (see 'renderMerge').
tableOf :: M.Map String Int -> M.Map Setting Group -> String
tableOf names groups = unlines (map printableLine
      (  concatMap (\(s, g) -> table nameOf (showSetting s) g) (M.toList groups)
      ++ concatMap (\(kv, g) -> table nameOf (showSetting [kv] ++ " over all other settings") g) marginal
      ++ mixed))
  where
    nameOf = IM.fromList [ (i, k) | (k, i) <- M.toList names ]
    values = M.fromListWith (+) [ (k, 1 :: Int) | (k, _) <- S.toList (S.fromList (concat (M.keys groups))) ]
    varying = [ k | (k, c) <- M.toList values, c > 1 ]
    -- with two or more settings varying, also each value of each over all the others
    marginal
      | length varying > 1 =
          M.toList (M.fromListWith (flip (joinGroups False)) [ (kv, g) | (s, g) <- M.toList groups, kv@(k, _) <- s, k `elem` varying ])
      | otherwise = []
    nMixed = length [ () | g <- M.elems groups, M.size (gBySteps g) > 1 ]
    mixed = [ "== note: " ++ show nMixed ++ (if nMixed == 1 then " setting mixes" else " settings mix")
              ++ " runs of different dt, seconds or odometry noise, which the table does not tell apart (give"
              ++ " each a --param to tell them apart)" | nMixed > 0 ]

-- The groups with the runs of an unnamed world ('unnamedWorld') filed
-- under the world the result lines name for a run without @--world@, when
-- they name one ('ownWorlds'); left as they are when they name none (every
-- such run failed) or both (two programs' sweeps merged). A run so filed
-- that a result line has too (the same setting and seed) is refused, as
-- 'addRun' refuses a run merged twice.
fileUnnamed :: M.Map Setting Group -> Either String (M.Map Setting Group)
fileUnnamed groups = case S.toList (S.fromList [ w | ("world", w) : _ <- M.keys groups, w `elem` ownWorlds ]) of
  [own] -> foldM (file own) named (M.toList unnamed)
  _     -> Right groups
  where
    (unnamed, named) = M.partitionWithKey (\k _ -> take 1 k == [("world", unnamedWorld)]) groups
    file own acc (setting, g) =
      let setting' = ("world", own) : drop 1 setting
      in case M.lookup setting' acc of
           Nothing -> Right (M.insert setting' g acc)
           Just g0 -> case commonSeed (gNoRes g) (seedsUnion (gNoRes g0) (gResults g0)) of
             Just seed -> Left ("the run " ++ showSetting setting' ++ " seed " ++ seed ++ " is on a line for a run with"
                                ++ " no result and on a result line too (a result file merged with the sweep's"
                                ++ " line for the same run): each run may be merged once")
             Nothing -> Right (M.insert setting' (joinGroups True g0 g) acc)
    commonSeed (Seeds is1 ts1) (Seeds is2 ts2) =
      case (fst <$> IS.minView (IS.intersection is1 is2), S.lookupMin (S.intersection ts1 ts2)) of
        (Just i, _) -> Just (show i)
        (_, Just t) -> Just t
        _           -> Nothing

-- Two groups' runs as one: the runs and failures counted, the failures
-- listed and the outcomes' tallies added; with @keepSeeds@ the seeds seen
-- too (a setting's group, which a mixed run or a run merged twice is
-- told by), otherwise none (a group of the per-value lines, whose seeds
-- are never asked).
joinGroups :: Bool -> Group -> Group -> Group
joinGroups keepSeeds a b =
  Group (gRuns a + gRuns b) (gFailed a + gFailed b) (foldr listAdd (gListed a) (listedRuns (gListed b)))
        (IM.unionWith addStat (gStats a) (gStats b)) (seeds gNoRes) (seeds gResults)
        (if keepSeeds then M.unionWith seedsUnion (gBySteps a) (gBySteps b) else M.empty)
  where
    seeds f = if keepSeeds then seedsUnion (f a) (f b) else noSeeds

-- A setting as the table names it: @world=default speed=0.1@, each name
-- and value as it is when it is plain (not empty; no space, @=@, quote,
-- backslash or character that does not print), otherwise in quotes with
-- the quote, the backslash and the characters that do not print escaped
-- ('quote'): @mode="1 b=2"@, @note="x\ny"@. So two settings never read
-- alike: unquoted, a value @1 b=2@ read as two parameters, and a value
-- with a newline as one with a backslash and an @n@. The world of a run
-- with no result and no @--world@ that 'fileUnnamed' could not file is
-- @world=(not given)@.
showSetting :: Setting -> String
showSetting g = unwords $ case g of
  ("world", w) : rest | w == unnamedWorld -> "world=(not given)" : map pair rest
  _                                       -> map pair g
  where
    pair (k, v) = shown k ++ "=" ++ shown v
    shown t | not (null t) && all plain t = t
            | otherwise                   = quote t
    plain c = isPrint c && not (isSpace c) && c `notElem` "=\"\\"

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
