-- |
-- Module      : AFrobRobotSim.Sweep
-- Description : Merging the result lines of a sweep into one table.
--
-- A sweep (@scripts/sweep@, @scripts/sweep.sbatch@) writes one result line
-- per run ("AFrobRobotSim.Result"), in shards, in whatever order the runs
-- finished. 'mergeResults' groups the runs by their setting (the
-- parameters and the world: every field of the settings but the seed) and
-- prints, per group, the mean, minimum and maximum of every outcome over
-- its runs; when two or more settings vary (two parameters, or a parameter
-- and the world), it then prints the same per value of each setting, over
-- all the values of the others. The table does not depend on the order of the lines (the
-- values are sorted before they are summed), so shards merged in any order
-- give the same table. A run that failed (a controller error, or a line
-- the sweep wrote for a run that wrote none) is counted and listed under
-- its group, never dropped; its outcome, as far as it got, still counts.
-- A line that is neither a run's result line nor the sweep's line for a
-- run with no result (a run log given by mistake, @{}@) is refused with
-- its number and what it lacks, never counted as a failed run.
module AFrobRobotSim.Sweep
  ( mergeResults
  , sweepMergeMain
  ) where

import           Control.Exception   (try)
import qualified Data.ByteString     as B
import           Data.List           (sort, sortOn)
import qualified Data.Map.Strict     as M
import qualified Data.Set            as S
import           System.Environment  (getArgs)
import           System.Exit         (exitWith, ExitCode (..))
import           System.IO           (hPutStrLn, stderr)
import           Text.Printf         (printf)

import           AFrobRobotSim.JSON
import           AFrobRobotSim.Console (displayPath, endOutput, ioErrorText, printableLine, tolerantOutput)
import           AFrobRobotSim.WorldFile.Lexical (utf8Text)

-- One run as the table needs it.
data Run = Run
  { runGroup   :: [(String, String)]   -- the setting: world and parameters
  , runSeed    :: String
  , runFailure :: Maybe String
  , runValues  :: [(String, Double)]   -- outcome name, value
  }

-- | The table of a sweep's result lines (the text of one or more result
-- files, one JSON object a line; blank lines are skipped), or the first
-- line that is not a result line of a sweep, with its number.
mergeResults :: String -> Either String String
mergeResults text = do
  runs <- mapM readLine [ (k, l) | (k, l) <- zip [1 :: Int ..] (lines text), any (/= ' ') l ]
  let byGroup  = inOrder [ (runGroup r, r) | r <- runs ]
      settings = S.toList (S.fromList (concatMap runGroup runs))
      values   = M.fromListWith (+) [ (k, 1 :: Int) | (k, _) <- settings ]
      varying  = [ k | (k, n) <- M.toList values, n > 1 ]
      -- with two or more settings varying, also each value of each over all the others
      marginal
        | length varying > 1 =
            M.toList (inOrder [ (kv, r) | r <- runs, kv@(k, _) <- runGroup r, k `elem` varying ])
        | otherwise = []
      repeats = length runs - S.size (S.fromList [ (runGroup r, runSeed r) | r <- runs ])
      note = [ "== note: " ++ show repeats ++ " result line" ++ (if repeats == 1 then " repeats a run" else "s repeat runs")
               ++ " (the same world, parameters and seed: a result file merged twice, or runs told"
               ++ " apart only by other flags?); each is counted"
             | repeats > 0 ]
  pure (unlines (map printableLine
    (  concatMap (\(g, rs) -> table (showSetting g) rs) (M.toList byGroup)
    ++ concatMap (\(kv, rs) -> table (showSetting [kv] ++ " over all other settings") rs) marginal
    ++ note)))
  where
    readLine (k, l) = either (\e -> Left ("line " ++ show k ++ ": " ++ e)) Right
                        (either (\e -> Left ("not a result line of a sweep (not JSON: " ++ e ++ ")")) Right (parseJSON l) >>= readRun)
    -- the runs of each key, in input order
    inOrder kvs = M.map reverse (M.fromListWith (++) [ (k, [v]) | (k, v) <- kvs ])

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
  let group = ("world", world) : sort params
      seed  = encodeJSON seedValue
  case lookup "outcome" fields of
    Nothing -> do
      -- the sweep's line for a run with no result
      case seedValue of
        JNumber _ -> Right ()
        JString _ -> Right ()
        _         -> Left "\"seed\" is neither a number nor a string"
      _       <- member "flags" v >>= asString
      failure <- member "failure" v >>= asString
      pure (Run group seed (Just failure) [])
    Just out -> do
      _ <- asNumber seedValue
      _ <- member "dt" v >>= asNumber
      _ <- member "seconds" v >>= asNumber
      outFailure  <- member "failure" out >>= \f -> case f of
        JNull -> Right Nothing
        _     -> Just <$> asString f
      interrupted <- member "interrupted" out >>= asBool
      simulated   <- member "simulated" out >>= asNumber
      steps       <- member "steps" out >>= asNumber
      robots      <- member "robots" out >>= asArray
      perRobot    <- concat <$> mapM robotValues robots
      scores      <- member "scores" out >>= \s -> case s of
        JObject kvs -> mapM (\(k, x) -> (,) ("score " ++ k) <$> asNumber x) kvs
        _           -> Left "\"scores\" is not an object"
      let fault = case (outFailure, interrupted) of
            (Just f, _)   -> Just f
            (_, True)     -> Just "interrupted"
            _             -> Nothing
      pure (Run group seed fault ([("simulated", simulated), ("steps", steps)] ++ perRobot ++ scores))
  where
    robotValues r = do
      ty <- member "type" r >>= asString
      i  <- member "id" r >>= asInt
      let name f = ty ++ " " ++ show i ++ " " ++ f
      mapM (\f -> (,) (name f) <$> (member f r >>= asNumber))
           ["x", "y", "heading", "distance", "bumps", "stuckTime", "battery"]

showSetting :: [(String, String)] -> String
showSetting g = unwords [ k ++ "=" ++ v | (k, v) <- g ]

-- One group's lines of the table: its heading and its runs.
table :: String -> [Run] -> [String]
table heading mine =
  [ "== " ++ heading
    ++ printf "  (%d runs, %d failed)" (length mine) (length failed) ]
  ++ [ printf "  %-28s %14s %14s %14s" ("outcome" :: String) ("mean" :: String) ("min" :: String) ("max" :: String)
     | not (null names) ]
  ++ [ printf "  %-28s %14s %14s %14s" n (number (mean xs)) (number (minimum xs)) (number (maximum xs))
       ++ (if length xs < length mine then printf "  (%d runs)" (length xs) else "")
     | n <- names, let xs = sort (M.findWithDefault [] n valuesOf) ]
  ++ [ "  FAILED seed " ++ runSeed r ++ ": " ++ f
     | r <- sortOn runSeed failed, Just f <- [runFailure r] ]
  where
    failed = [ r | r <- mine, runFailure r /= Nothing ]
    bySeed = sortOn runSeed mine
    -- the outcomes in the order the runs (by seed) first name them, and
    -- each one's values: one pass, however many robots and runs
    names  = firstSeen S.empty (concatMap (map fst . runValues) bySeed)
    valuesOf = M.fromListWith (++) [ (n, [x]) | r <- mine, (n, x) <- runValues r ]
    firstSeen _ [] = []
    firstSeen seen (n : ns)
      | n `S.member` seen = firstSeen seen ns
      | otherwise         = n : firstSeen (S.insert n seen) ns
    mean xs = sum xs / fromIntegral (length xs)
    number :: Double -> String
    number x
      | x /= 0 && (abs x < 1e-3 || abs x >= 1e7) = printf "%.4e" x
      | otherwise                                 = printf "%.4f" x

-- | The @afrp-sweep-merge FILE...@ program (and @scripts/sweep-merge@):
-- print the table of the result files (standard input when none is
-- given); exit code 1 with the message when a line is not a result line
-- of a sweep (@FILE: line N: not a result line of a sweep (...)@: not
-- JSON, or JSON that is neither a run's result line nor the sweep's line
-- for a run with no result, such as a run log given by mistake).
sweepMergeMain :: IO ()
sweepMergeMain = do
  tolerantOutput
  args <- getArgs
  -- (each input read as UTF-8 whatever the locale, and checked to be so)
  inputs <- if null args then (:[]) . (,) "standard input" <$> B.getContents
            else mapM (\f -> (,) (displayPath f) <$> readOrExit f) args
  texts <- mapM decoded inputs
  let merged = mergeResults (concatMap (ensureNewline . snd) texts)
      -- a fault located in its own file: the first file that fails alone
      located e = case [ name ++ ": " ++ e' | (name, t) <- texts, Left e' <- [mergeResults t] ] of
        first : _ -> first
        []        -> e
  case merged of
    Right out -> putStr out >> endOutput prog
    Left e    -> endOutput prog >> hPutStrLn stderr (prog ++ ": " ++ located e) >> exitWith (ExitFailure 1)
  where
    prog = "afrp-sweep-merge"
    ensureNewline t = if null t || last t == '\n' then t else t ++ "\n"
    readOrExit f = try (B.readFile f) >>= either (cannotRead f) pure
    cannotRead f e = do
      hPutStrLn stderr (prog ++ ": " ++ displayPath f ++ ": " ++ ioErrorText e)
      exitWith (ExitFailure 2)
    decoded (name, bytes) = case utf8Text name bytes of
      Right text -> pure (name, text)
      Left msg   -> do
        hPutStrLn stderr (prog ++ ": " ++ msg)
        exitWith (ExitFailure 1)
