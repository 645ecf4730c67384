-- |
-- Module      : AFrobRobotSim.Sweep.Line
-- Description : One line of a sweep's results read: a run's setting, seed
--               and outcome.
--
-- A line is a run's result line (@--result@, "AFrobRobotSim.Result") or
-- the line @scripts/sweep@ writes for a run that wrote none; 'readRun'
-- reads either into a 'Run', which "AFrobRobotSim.Sweep.Merge" adds to
-- the tallies of its setting. A setting is the program, the world and the
-- parameters' values, each under its name; the program and the world
-- under names no parameter can have ('programKey', 'worldKey').
--
-- Internal: "AFrobRobotSim.Sweep.Merge" alone uses it; exposed, as every
-- module of the library is, but not part of the API that
-- "AFrobRobotSim.Sweep" gives, and free to change.
module AFrobRobotSim.Sweep.Line
  ( -- * Settings
    Setting
  , programKey
  , worldKey
  , programOf
  , withProgram
  , unnamedWorld
  , ownWorlds
    -- * Lines
  , Run (..)
  , readRun
  ) where

import           Data.Char           (isSpace)
import           Data.List           (sortOn)

import           AFrobRobotSim.JSON
import           AFrobRobotSim.Sweep.Tally
import           AFrobRobotSim.WorldFile.Lexical (integerLit)


-- | The setting of a run: the program (under 'programKey'), the world
-- (under 'worldKey'), then the parameters by name.
type Setting = [(String, String)]

-- | The name under which a setting holds its program: a NUL and
-- @program@, which no parameter's name is (a command line cannot pass a
-- NUL), so that a parameter named @program@ is not taken for it, and
-- which sorts before every name: the program first, as the table names
-- it ("AFrobRobotSim.Sweep.Merge").
programKey :: String
programKey = "\NULprogram"

-- | The name under which a setting holds its world: a NUL and @world@, as
-- 'programKey' is the program's, so that a parameter named @world@
-- (@--param world=3@) is neither taken for the world nor mixed with it
-- in the settings that vary; it sorts after 'programKey' and before
-- every parameter's name: the world second, as the table names it.
worldKey :: String
worldKey = "\NULworld"

-- | The program of a setting.
programOf :: Setting -> String
programOf s = case s of
  (k, p) : _ | k == programKey -> p
  _                            -> ""

-- | A setting with its program replaced.
withProgram :: String -> Setting -> Setting
withProgram p s = case s of
  (k, _) : rest | k == programKey -> (k, p) : rest
  _                               -> (programKey, p) : s

-- | The world of the sweep's line for a run that wrote no result and got no
-- @--world@ (@"world": null@): the program's own world (a result line's
-- @"program"@) or the built-in default (@"default"@), which the sweep
-- cannot tell. "AFrobRobotSim.Sweep.Merge" files such runs with the result lines of
-- that world, when the lines merged name one of the two ('ownWorlds'),
-- as a sweep of one program does. (A NUL, which no world's name holds:
-- a command line cannot pass one, so neither @--world@ nor a world of
-- @""@, which the sweep writes for @--world ''@, reads as it.)
unnamedWorld :: String
unnamedWorld = "\NUL"

-- | The worlds a result line names when the run got no @--world@ (it names
-- a world file of either name @./default@, @./program@:
-- 'AFrobRobotSim.Result.worldSourceName').
ownWorlds :: [String]
ownWorlds = ["default", "program"]

-- | One line, read: the setting, whether its program is named as the
-- program's result lines name it (a result line's is; the sweep's line
-- for a run with no result says so by its @executable@), the file the
-- sweep ran (that @executable@), the seed, the
-- time step and duration of a result line (their JSON text; 'Nothing' for
-- the sweep's line for a run with no result), the failure, and every
-- outcome's value ('Nothing': @null@, which is how a result line writes a
-- number that is not finite).
data Run = Run
  { runSetting :: Setting
  , runNamed   :: Bool
  , runExecutable :: Maybe String   -- ^ the file the sweep ran, when its line for a run with no result says it
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
-- (@program@: the program as its result lines name it, when the line has
-- @executable@ too, the name of the file the sweep ran; without
-- @executable@, from an older sweep or one that could not learn the
-- program's name, @program@ is that file's name; then
-- @world@ a string or @null@ when the run got no @--world@:
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
  program <- member "program" v >>= asString
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
  let setting = (programKey, program) : (worldKey, world) : sortOn fst params
  case lookup "outcome" fields of
    Nothing -> do
      -- the sweep's line for a run with no result
      seed <- case seedValue of
        JNumber x -> Right (numberSeed x)
        JString t -> Right (textSeed t)
        _         -> Left "\"seed\" is neither a number nor a string"
      _       <- member "flags" v >>= asString
      failure <- member "failure" v >>= asString
      exe     <- maybe (Right Nothing) (fmap Just . asString) (lookup "executable" fields)
      pure (Run setting (exe /= Nothing) exe seed Nothing (Just failure) [])
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
      pure (Run setting True Nothing seed (Just (dt, seconds, noise)) fault
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
