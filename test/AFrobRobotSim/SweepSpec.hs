{-# LANGUAGE ScopedTypeVariables #-}
-- | @--result@, @--param@ and the sweep scripts (@scripts/sweep@,
-- @scripts/sweep.sbatch@, @scripts/sweep-merge@), run as child processes:
-- the program of a sweep is this test binary started with
-- 'childVariable' set.
module AFrobRobotSim.SweepSpec (spec, childVariable, child) where

import           Control.Concurrent  (threadDelay)
import           Control.Monad       (forM, forM_, unless)
import qualified Data.ByteString     as B
import qualified Data.ByteString.Char8 as BC
import           Data.Int            (Int8)
import qualified Data.Map            as M
import           Data.Maybe          (fromMaybe, isJust)
import           Data.Ratio          (Ratio, (%))
import qualified Data.Set            as S
import           Data.List           (intercalate, isInfixOf, isPrefixOf, isSuffixOf, sort)
import           Data.Word           (Word8)
import           System.Directory    (canonicalizePath, copyFile, createDirectory, createDirectoryIfMissing, createFileLink, doesFileExist, findExecutable,
                                      listDirectory, makeAbsolute)
import           System.Environment  (getArgs, getEnvironment, getExecutablePath, withProgName)
import           System.Exit         (ExitCode (..))
import           System.FilePath     ((</>))
import           System.IO           (hGetContents, readFile')
import           System.Posix.Signals (sigKILL, sigTERM, signalProcess, signalProcessGroup)
import           System.Process      (CreateProcess (..), StdStream (..), createProcess, getPid, proc,
                                      readCreateProcessWithExitCode, readProcess, readProcessWithExitCode,
                                      waitForProcess)
import           System.Timeout      (timeout)
import           Test.Hspec
import           Test.QuickCheck     (forAll, shuffle)

import           AFrob               hiding (forAll)
import           AFrobRobotSim
import           AFrobRobotSim.JSON
import           AFrobRobotSim.Sweep (maxLineBytes, mergeResults, sweepMergeMain)
import           AFrobRobotSim.Sweep.Merge (addLine, addLineUtf8, emptyMerge, renderMerge)
import           AFrobRobotSim.UTF8 (checkUtf8)
import           AFrobRobotSim.WorldFile.Lexical (utf8Text)
import           TestUtil (cLocale, withTempDir, writeScript)

-- | The environment variable that makes the test binary run 'child'.
childVariable :: String
childVariable = "AFRP_SPEC_SWEEP_CHILD"

-- | The test binary as a child: @program@ is a runSim program whose robot
-- starts further right the larger the seed, drives at @--param speed=V@
-- (default 0.1) and whose controller throws from @--param failAt=T@ on;
-- @announcer@ reads @--param speed@ with 'paramOr', prints it (an action
-- of its own before 'runSim'), then runs; @ownline@ has a command line of
-- its own, as @afrp-examples@ has, @NAME [flags]@: it reads @--param
-- speed@ of the flags after the name with 'paramOrFrom', prints it, then
-- runs those flags ('runSimWith'), or prints its own usage for @--help@;
-- @merge@ is @afrp-sweep-merge@.
child :: String -> IO ()
child "merge" = withProgName "afrp-sweep-merge" sweepMergeMain   -- (signed as the executable is)
child "program" = do
  args <- getArgs
  speed  <- paramOr "speed" (0.1 :: Double)
  failAt <- paramOr "failAt" (1 / 0 :: Double)
  _      <- paramOr "ratio" (0 :: Rational)   -- read, for the test of a value that cannot be made
  _      <- lookupSimParam "tag"               -- asked for, so that runSim does not warn of it
  _      <- lookupSimParam "größe"             -- (a name beyond ASCII, read in the C locale)
  let seed = case parseSimArgs defaultSimOptions args of
        Right (RunWith o) -> optSeed o
        _                 -> 0
      start = -3 + 0.25 * fromIntegral (seed `mod` 8)
      world = [OTSimbotA 1 (Point2 start 0) 0, OTVWall (Point2 0 0), OTBall (Point2 0 2)]
      ctl _ = localTime >>> arr (\t -> if t >= failAt then error "the test controller gives up"
                                       else mrFinalize (ddVelDiff speed speed))
  runSim (Just world) ctl ctl
child "announcer" = do
  speed <- paramOr "speed" (0.1 :: Double)
  putStrLn ("speed " ++ show speed)
  runSim (Just [OTSimbotA 1 (Point2 0 0) 0]) (\_ -> constant (mrFinalize (ddVelDiff speed speed)))
                                            (\_ -> constant (mrFinalize (ddVelDiff 0 0)))
child "ownline" = do
  args <- getArgs
  case args of
    name : flags -> do
      speed <- paramOrFrom flags "speed" (0.1 :: Double)
      putStrLn (name ++ " speed " ++ show speed)
      case parseSimArgs defaultSimOptions flags of
        Right (RunWith o) -> runSimWith o (Just [OTSimbotA 1 (Point2 0 0) 0])
                               (\_ -> constant (mrFinalize (ddVelDiff speed speed))) (\_ -> constant (mrFinalize (ddVelDiff 0 0)))
        Right ShowHelp    -> putStrLn ("usage: ownline NAME [flags]")
        Left err          -> ioError (userError err)
    [] -> ioError (userError "ownline NAME [flags]")
child other = ioError (userError ("unknown child " ++ show other))

-- The program run with a @--param@ that 'paramOr' refuses: a usage error,
-- as a malformed command line is (exit 2, one line naming the parameter
-- and its value, no GHC "user error" wrapping), before anything is run
-- (no result line).
stopsForParam :: String -> String -> Expectation
stopsForParam param message = withTempDir $ \dir -> do
  (code, err, line) <- runOnce dir ["--seconds", "1", "--param", param]
  code `shouldBe` ExitFailure 2
  err `shouldSatisfy` (message `isInfixOf`)
  err `shouldNotSatisfy` ("user error" `isInfixOf`)
  length (lines err) `shouldBe` 1
  line `shouldBe` ""

-- @scripts/sweep -j 2 --jobs DIR/jobs PROG DIR/r.jsonl@, with @TMPDIR@
-- set to @DIR/tmp@ (made here), sent SIGTERM to its process group (as
-- Slurm's time limit does) once @ready@ holds: its exit code ('Nothing' if
-- it had not ended a minute later; it is then killed) and its standard
-- error, read to the end once it has ended (a pipe whose reading end was
-- dropped would kill the sweep's last message with SIGPIPE). If @ready@
-- does not hold within a minute, the sweep is stopped (SIGTERM, which
-- stops its runs; SIGKILL if it has not ended ten seconds later) and the
-- test fails, saying @what@ within a minute.
sweepInterrupted :: FilePath -> FilePath -> String -> IO Bool -> IO (Maybe ExitCode, String)
sweepInterrupted dir prog what ready = do
  sweep <- script "sweep"
  createDirectory (dir </> "tmp")
  environment <- filter ((/= "TMPDIR") . fst) <$> getEnvironment
  (_, _, Just errH, ph) <- createProcess (proc "bash" [sweep, "-j", "2", "--jobs", dir </> "jobs", prog, dir </> "r.jsonl"])
    { env = Just (("TMPDIR", dir </> "tmp") : environment), create_group = True, std_err = CreatePipe }
  Just pid <- getPid ph
  let signalGroup s = signalProcessGroup s pid
      stop = do
        signalGroup sigTERM
        ended <- timeout 10000000 (waitForProcess ph)
        unless (isJust ended) (signalGroup sigKILL >> () <$ waitForProcess ph)
      waitReady :: Int -> IO ()
      waitReady k = do
        ok <- ready
        unless ok $
          if k <= 0 then stop >> expectationFailure (what ++ " within a minute")
          else threadDelay 100000 >> waitReady (k - 1)
  waitReady 600
  signalGroup sigTERM
  code <- timeout 60000000 (waitForProcess ph)
  unless (isJust code) (signalGroup sigKILL >> () <$ waitForProcess ph)
  err <- fromMaybe "" <$> timeout 10000000 (hGetContents errH >>= \e -> length e `seq` pure e)
  pure (code, err)

-- @sweep --list ARGS@: its exit code, the job lines it lists, and its
-- standard error.
listedBy :: FilePath -> [String] -> IO (ExitCode, [String], String)
listedBy sweep args = do
  (code, out, err) <- runScriptCode [] sweep ("--list" : args)
  pure (code, lines out, err)

-- A script in @dir@ that starts this test binary as the given child.
childScript :: FilePath -> String -> IO FilePath
childScript dir what = do
  self <- getExecutablePath
  let file = dir </> what
  writeScript file ("#!/bin/sh\n" ++ childVariable ++ "=" ++ what ++ " exec '" ++ self ++ "' \"$@\"\n")
  pure file

-- A script @dir/file@ that runs the program child ('childScript') under
-- the name @name@ (its @argv[0]@): a program whose result lines name it
-- otherwise than its file, as one that sets 'optProgram' does.
namedProgram :: FilePath -> FilePath -> String -> IO FilePath
namedProgram dir file name = do
  self <- getExecutablePath
  let prog = dir </> file
  writeScript prog ("#!/bin/bash\n" ++ childVariable ++ "=program exec -a '" ++ name ++ "' '" ++ self ++ "' \"$@\"\n")
  pure prog

-- A script in @dir@ that runs the program child ('childScript'), but
-- stops at once for @--seed 2@, writing no result (exit code 3).
failingSeed2 :: FilePath -> IO FilePath
failingSeed2 dir = do
  real <- childScript dir "program"
  let prog = dir </> "fails2"
  writeScript prog (unlines [ "#!/bin/bash"
                          , "case \" $* \" in *' --seed 2 '*) echo 'no luck' >&2; exit 3 ;; esac"
                          , "exec '" ++ real ++ "' \"$@\"" ])
  pure prog

-- Run the program once with these flags and a result file; its exit code,
-- standard error and result line.
runOnce :: FilePath -> [String] -> IO (ExitCode, String, String)
runOnce dir flags = do
  prog <- childScript dir "program"
  let file = dir </> "result.json"
  (code, _, err) <- readProcessWithExitCode prog (["--quiet", "--no-svg", "--no-replay"] ++ flags ++ ["--result", file]) ""
  there <- doesFileExist file
  line <- if there then readFile file else pure ""
  length line `seq` pure (code, err, line)

field :: [String] -> JSON -> JSON
field path v = either error id (foldl (\acc k -> acc >>= member k) (Right v) path)

parsed :: String -> JSON
parsed = either error id . parseJSON

-- A script of this repository, or a failure saying where it was looked for.
script :: String -> IO FilePath
script name = do
  f <- makeAbsolute ("scripts" </> name)
  there <- doesFileExist f
  unless there (expectationFailure ("no " ++ f ++ " (run the tests from the repository's root)"))
  pure f

-- GNU parallel, or a failed test that says how to install it.
requireParallel :: IO ()
requireParallel = do
  found <- findExecutable "parallel"
  ok <- case found of
    Nothing -> pure False
    Just p  -> do
      (_, out, _) <- readProcessWithExitCode p ["--version"] ""
      pure ("GNU parallel" `isInfixOf` out)
  unless ok (expectationFailure "the sweep tests need GNU parallel on the PATH (Debian: apt-get install parallel)")

-- Run a script with these extra environment variables; fail the test
-- with its messages unless it succeeds; its standard output.
runScript :: [(String, String)] -> FilePath -> [String] -> IO String
runScript extraEnv file args = do
  (code, out, err) <- runScriptCode extraEnv file args
  unless (code == ExitSuccess) (expectationFailure (file ++ " " ++ unwords args ++ " failed: " ++ show code ++ "\n" ++ err))
  pure out

-- A script's exit code, standard output and error, whatever the code.
runScriptCode :: [(String, String)] -> FilePath -> [String] -> IO (ExitCode, String, String)
runScriptCode extraEnv file args = do
  environment <- filter ((`notElem` map fst extraEnv) . fst) <$> getEnvironment
  readCreateProcessWithExitCode (proc "bash" (file : args)) { env = Just (extraEnv ++ environment) } ""

-- The merged table of result files, by scripts/sweep-merge.
merged :: FilePath -> [FilePath] -> IO String
merged dir files = do
  merger <- childScript dir "merge"
  sweepMerge <- script "sweep-merge"
  runScript [("AFRP_SWEEP_MERGE", merger)] sweepMerge files

seeds :: [Int]
seeds = [1 .. 8]

speeds :: [String]
speeds = ["0.05", "0.1"]

-- The sweep's runs one after the other, in the job list's order.
sequentialLines :: FilePath -> IO [String]
sequentialLines dir = fmap concat . forM speeds $ \v -> forM seeds $ \s -> do
  (code, err, line) <- runOnce dir ["--seconds", "3", "--seed", show s, "--param", "speed=" ++ v]
  (code, err) `shouldBe` (ExitSuccess, "")
  pure (filter (/= '\n') line)

-- A result line as a run writes it, with one robot.
resultLine :: Int -> [(String, String)] -> Double -> Maybe String -> String
resultLine seed params dist failure = encodeJSON $ JObject
  [ ("program", JString "p"), ("world", JString "default"), ("seed", JNumber (fromIntegral seed))
  , ("dt", JNumber 0.01), ("seconds", JNumber 1), ("params", JObject [ (k, JString v) | (k, v) <- params ])
  , ("outcome", JObject
      [ ("simulated", JNumber 1), ("steps", JNumber 101), ("interrupted", JBool False)
      , ("failure", maybe JNull JString failure)
      , ("robots", JArray [JObject [ ("type", JString "SimbotA"), ("id", JNumber 1), ("x", JNumber 0)
                                   , ("y", JNumber 0), ("heading", JNumber 0), ("distance", JNumber dist)
                                   , ("bumps", JNumber 0), ("stuckTime", JNumber 0), ("battery", JNumber 1) ]])
      , ("scores", JObject [("goals", JNumber (fromIntegral seed))]) ]) ]

-- The text with the first occurrence of @old@ replaced by @new@.
replace :: String -> String -> String -> String
replace old new = go
  where
    go t | old `isPrefixOf` t = new ++ drop (length old) t
    go (c : cs) = c : go cs
    go []       = []

-- The headings of the table that mergeResults makes of these lines (the
-- lines "== SETTING  (N runs, M failed)"), or its refusal, "refused: ...".
headings :: [String] -> [String]
headings ls = either (\e -> ["refused: " ++ e]) (filter ("== " `isPrefixOf`) . lines) (mergeResults (unlines ls))

-- A result line of 'resultLine' as the program named @q@ writes it.
ofProgram :: String -> String -> String
ofProgram q = replace "\"program\":\"p\"" ("\"program\":" ++ encodeJSON (JString q))

-- The sweep's line for a run of seed @seed@ that wrote no result (a flag
-- it rejected): its program @prog@, with its executable when the sweep
-- knows it, and its world as JSON text (@null@ for a run given no
-- --world).
noResult :: String -> Maybe String -> String -> Int -> String
noResult prog exe world seed =
  "{\"program\":" ++ encodeJSON (JString prog) ++ maybe "" (\e -> ",\"executable\":" ++ encodeJSON (JString e)) exe
  ++ ",\"world\":" ++ world ++ ",\"seed\":" ++ show seed ++ ",\"params\":{\"speed\":\"0.1\"}"
  ++ ",\"flags\":\"--seed " ++ show seed ++ "\",\"failure\":\"exit code 2, no result: bad flag\"}"

-- A program's message without its name, the text after the first colon
-- (a runSim program signs its messages "NAME: ...", NAME its file's).
unsigned :: String -> String
unsigned = drop 1 . dropWhile (/= ':')

spec :: Spec
spec = do
  describe "mergeResults" $ do
    let sampleLines = [ resultLine 1 [("speed", "0.1")] 1 Nothing, resultLine 2 [("speed", "0.1")] 2 Nothing, resultLine 3 [("speed", "0.1")] 6 Nothing
                 , resultLine 1 [("speed", "0.2")] 0.1 Nothing, resultLine 2 [("speed", "0.2")] 0.3 (Just "it broke") ]
    it "gives per setting the mean, min and max of every outcome, and the failed runs" $ do
      table <- either (\e -> expectationFailure e >> pure "") pure (mergeResults (unlines sampleLines))
      lines table `shouldSatisfy` elem "== world=default speed=0.1  (3 runs, 0 failed)"
      lines table `shouldSatisfy` elem "== world=default speed=0.2  (2 runs, 1 failed)"
      map words (lines table) `shouldSatisfy` elem ["SimbotA", "1", "distance", "3.0000", "1.0000", "6.0000"]
      map words (lines table) `shouldSatisfy` elem ["score", "goals", "2.0000", "1.0000", "3.0000"]
      map words (lines table) `shouldSatisfy` elem ["SimbotA", "1", "distance", "0.2000", "0.1000", "0.3000"]
      table `shouldSatisfy` ("  FAILED seed 2: it broke" `isInfixOf`)
    it "with two parameters varying, adds each value over all the values of the other" $ do
      let two = [ resultLine i [("speed", v), ("k", k)] (fromIntegral i) Nothing
                | (i, (v, k)) <- zip [1 ..] [("0.1", "a"), ("0.2", "b"), ("0.1", "b"), ("0.2", "a"), ("0.1", "a")] ]
      table <- either (\e -> expectationFailure e >> pure "") pure (mergeResults (unlines two))
      lines table `shouldSatisfy` elem "== world=default k=a speed=0.1  (2 runs, 0 failed)"
      lines table `shouldSatisfy` elem "== k=a over all other settings  (3 runs, 0 failed)"
      lines table `shouldSatisfy` elem "== k=b over all other settings  (2 runs, 0 failed)"
      lines table `shouldSatisfy` elem "== speed=0.1 over all other settings  (3 runs, 0 failed)"
      -- the world is the same in every run: no line for it
      lines table `shouldSatisfy` all (not . ("== world=default over" `isPrefixOf`))
    it "does not depend on the order of the lines" $
      forAll (shuffle sampleLines) $ \ls -> mergeResults (unlines ls) == mergeResults (unlines sampleLines)
    it "reports a line that is not JSON with its number" $
      mergeResults (unlines [head sampleLines, "not json"]) `shouldSatisfy` either ("line 2" `isInfixOf`) (const False)
    it "places a fault in a line that is not JSON by its column of the line, the file's line the only line named (it said: line 2: ... line 1, column 151)" $ do
      let cut = take 150 (head sampleLines)
      mergeResults (unlines [head sampleLines, cut]) `shouldSatisfy`
        either (\e -> "line 2: not a result line of a sweep (not JSON: column 151 of the line: " `isPrefixOf` e
                      && not ("line 1" `isInfixOf` e))
               (const False)
      mergeResults (unlines [head sampleLines, "{\"program\" 1}"]) `shouldBe`
        Left "line 2: not a result line of a sweep (not JSON: column 12 of the line: expected ':', found '1')"
    it "refuses a line that repeats a run (the same setting and seed: a file merged twice), naming it" $ do
      let twice = mergeResults (unlines (sampleLines ++ take 2 sampleLines))
      twice `shouldSatisfy` either ("line 6: the run world=default speed=0.1 seed 1 (dt 0.01, seconds 1) is on an earlier line too" `isPrefixOf`)
                                   (const False)
      -- runs told apart by their time step, duration or odometry noise
      -- are two runs (a line written before the noise was recorded has none)
      mergeResults (unlines (sampleLines ++ [replace "\"seconds\":1," "\"seconds\":2," (head sampleLines)]))
        `shouldSatisfy` either (const False) ("== note: 1 setting mixes runs of different dt, seconds or odometry noise" `isInfixOf`)
      let noisy x = replace "\"seconds\":1," ("\"seconds\":1,\"odometryNoise\":" ++ x ++ ",") (head sampleLines)
      mergeResults (unlines (sampleLines ++ [noisy "0.1", noisy "0.2"]))
        `shouldSatisfy` either (const False) ("== note: 1 setting mixes runs of different dt, seconds or odometry noise" `isInfixOf`)
      mergeResults (unlines (sampleLines ++ [noisy "0"]))
        `shouldSatisfy` either ("the run world=default speed=0.1 seed 1 (dt 0.01, seconds 1) is on an earlier line too" `isInfixOf`)
                               (const False)
      mergeResults (unlines (sampleLines ++ [noisy "0.1", noisy "0.1"]))
        `shouldSatisfy` either ("seed 1 (dt 0.01, seconds 1, odometry noise 0.1) is on an earlier line too" `isInfixOf`)
                               (const False)
    it "takes a null outcome (a number that was not finite) as no value, never as NaN" $ do
      let nullDistance = replace "\"distance\":6," "\"distance\":null," (sampleLines !! 2)
          rows t = [ words l | l <- lines t, "SimbotA 1 distance" `isInfixOf` l ]
      nullDistance `shouldSatisfy` ("\"distance\":null" `isInfixOf`)
      table <- either (\e -> expectationFailure e >> pure "") pure
                 (mergeResults (unlines (nullDistance : drop 3 sampleLines ++ take 2 sampleLines)))
      table `shouldNotSatisfy` ("NaN" `isInfixOf`)
      rows table `shouldSatisfy` elem ["SimbotA", "1", "distance", "1.5000", "1.0000", "2.0000", "(2", "runs;", "1", "not", "a", "finite", "number)"]
      -- no finite value at all
      let allNull = mergeResults (replace "\"distance\":1," "\"distance\":null," (head sampleLines))
      allNull `shouldSatisfy` either (const False) (\t -> elem ["SimbotA", "1", "distance", "n/a", "n/a", "n/a", "(0", "runs;", "1", "not", "a", "finite", "number)"] (rows t))
    it "says there are no result lines when there are none" $ do
      mergeResults "" `shouldBe` Left "no result lines"
      mergeResults "\n  \n" `shouldBe` Left "no result lines"
    it "gives the same means in any order, where floating-point sums would not" $
      forAll (shuffle [1e16, 1, -1e16, 1, 3e-5, 2.5]) $ \ds ->
        mergeResults (unlines [ resultLine k [] d Nothing | (k, d) <- zip [1 ..] ds ])
          `shouldSatisfy` either (const False) (elem ["SimbotA", "1", "distance", "0.7500", "-1.0000e16", "1.0000e16"] . map words . lines)
    it "prints a setting or a failure with control characters escaped" $ do
      let evil = resultLine 1 [("speed", "0.1\ESC[2J")] 1 (Just "bad\nFAILED seed 9: forged")
      mergeResults evil `shouldSatisfy` either (const False)
        (\t -> "speed=\"0.1\\ESC[2J\"" `isInfixOf` t && "bad\\nFAILED seed 9: forged" `isInfixOf` t
               && all (\c -> c == '\n' || c >= ' ') t)
    it "names settings that are not alike so that they do not read alike (a value with a space and an = read as two parameters, a newline as a backslash and an n)" $ do
      let headingsOf ps = sort (headings [ resultLine 1 p 1 Nothing | p <- ps ])
      headingsOf [[("a", "1 b=2")], [("a", "1"), ("b", "2")]] `shouldBe`
        sort [ "== world=default a=\"1 b=2\"  (1 runs, 0 failed)", "== world=default a=1 b=2  (1 runs, 0 failed)" ]
      headingsOf [[("e", "x\ny")], [("e", "x\\ny")]] `shouldBe`
        sort [ "== world=default e=\"x\\ny\"  (1 runs, 0 failed)", "== world=default e=\"x\\\\ny\"  (1 runs, 0 failed)" ]
      -- (a quote, an empty value, a name with a space; a value beyond ASCII that prints is plain)
      headingsOf [[("q", "\"fast\""), ("empty", ""), ("my name", "caf\233")]] `shouldBe`
        [ "== world=default empty=\"\" \"my name\"=caf\233 q=\"\\\"fast\\\"\"  (1 runs, 0 failed)" ]

    it "files the sweep's line for a run with no result and no --world (world null) with the result lines' own world (it went under \"default\" apart from the program's runs)" $ do
      let own w = replace "\"world\":\"default\"" ("\"world\":" ++ w)
          tableOf' ls = either (\e -> "refused: " ++ e) id (mergeResults (unlines ls))
      -- the program's own world
      lines (tableOf' (map (own "\"program\"") (take 2 sampleLines) ++ [noResult "p" Nothing "null" 7]))
        `shouldSatisfy` elem "== world=program speed=0.1  (3 runs, 1 failed)"
      -- the built-in default, in any order of the lines
      forM_ [noResult "p" Nothing "null" 7 : take 2 sampleLines, take 2 sampleLines ++ [noResult "p" Nothing "null" 7]] $ \ls ->
        lines (tableOf' ls) `shouldSatisfy` elem "== world=default speed=0.1  (3 runs, 1 failed)"
      -- no result line to tell: said as not given
      lines (tableOf' [noResult "p" Nothing "null" 7]) `shouldSatisfy` elem "== world=(not given) speed=0.1  (1 runs, 1 failed)"
      -- an empty world (the sweep's line of --world '') and a parameter named
      -- world are names as given, not the unnamed world (the parameter's
      -- name quoted: it read as the world's)
      lines (tableOf' ["{\"program\":\"p\",\"world\":\"\",\"seed\":1,\"params\":{\"world\":\"\"},\"flags\":\"x\",\"failure\":\"boom\"}"])
        `shouldSatisfy` elem "== world=\"\" \"world\"=\"\"  (1 runs, 1 failed)"
      -- the line an older sweep wrote for a run of a world file named
      -- default or program (it wrote such a name bare) is that file's, as
      -- a result line names it (./default), not the built-in world's
      let ofFile w = replace "\"world\":null" ("\"world\":\"" ++ w ++ "\"") (noResult "p" Nothing "null" 7)
      filter ("== " `isPrefixOf`) (lines (tableOf' (take 2 sampleLines ++ [ofFile "default", own "\"./default\"" (sampleLines !! 2)])))
        `shouldBe` ["== world=./default speed=0.1  (2 runs, 1 failed)", "== world=default speed=0.1  (2 runs, 0 failed)"]
      filter ("== " `isPrefixOf`) (lines (tableOf' (map (own "\"program\"") (take 2 sampleLines) ++ [ofFile "program"])))
        `shouldBe` ["== world=./program speed=0.1  (1 runs, 1 failed)", "== world=program speed=0.1  (2 runs, 0 failed)"]
      -- a run that is a result line too is merged twice
      tableOf' (take 2 sampleLines ++ [noResult "p" Nothing "null" 2]) `shouldSatisfy`
        ("refused: the run world=default speed=0.1 seed 2 is on a line for a run with no result and on a result line too" `isPrefixOf`)
      -- a result line must name its world
      tableOf' [own "null" (head sampleLines)] `shouldSatisfy` ("refused: line 1: not a result line of a sweep" `isPrefixOf`)
    it "merges the lines of two programs as two settings, naming the program only then (the same world and seed was refused as a run merged twice)" $ do
      let rcStop = map (ofProgram "afrp-examples rcStop") (take 2 sampleLines)
      headings (map (ofProgram "afrp-examples rcReverse") (take 2 sampleLines) ++ rcStop) `shouldBe`
        [ "== program=\"afrp-examples rcReverse\" world=default speed=0.1  (2 runs, 0 failed)"
        , "== program=\"afrp-examples rcStop\" world=default speed=0.1  (2 runs, 0 failed)" ]
      -- (with a parameter varying too, each program over the other settings)
      headings (sampleLines ++ map (ofProgram "q") sampleLines) `shouldBe`
        [ "== program=p world=default speed=0.1  (3 runs, 0 failed)", "== program=p world=default speed=0.2  (2 runs, 1 failed)"
        , "== program=q world=default speed=0.1  (3 runs, 0 failed)", "== program=q world=default speed=0.2  (2 runs, 1 failed)"
        , "== program=p over all other settings  (5 runs, 1 failed)", "== program=q over all other settings  (5 runs, 1 failed)"
        , "== speed=0.1 over all other settings  (6 runs, 0 failed)", "== speed=0.2 over all other settings  (4 runs, 2 failed)" ]
      -- one program's table is as it was, whatever the program's name
      mergeResults (unlines (map (ofProgram "another name") sampleLines)) `shouldBe` mergeResults (unlines sampleLines)
      -- a run merged twice is one program's run twice
      headings (rcStop ++ take 1 rcStop) `shouldBe`
        [ "refused: line 3: the run world=default speed=0.1 seed 1 (dt 0.01, seconds 1) is on an earlier line too (a result file"
          ++ " merged twice, a run merged with its rerun, or runs told apart only by flags a result line does not record, such"
          ++ " as --keys: give each such run a --param that names its setting): each run may be merged once" ]
      -- (named with its program when the lines so far name more than one)
      headings (sampleLines ++ rcStop ++ take 1 rcStop) `shouldSatisfy` \hs -> case hs of
        [h] -> ("refused: line 8: the run program=\"afrp-examples rcStop\" world=default speed=0.1 seed 1 (dt 0.01, seconds 1)"
                ++ " is on an earlier line too") `isPrefixOf` h
        _   -> False
      -- a parameter named program is a parameter, not the program (its
      -- name quoted, so that it never reads as the program's)
      headings [resultLine 1 [("program", "p")] 1 Nothing] `shouldBe` ["== world=default \"program\"=p  (1 runs, 0 failed)"]
      headings [ofProgram "q" (resultLine 1 [("program", "p")] 1 Nothing), resultLine 2 [("program", "p")] 1 Nothing] `shouldBe`
        [ "== program=p world=default \"program\"=p  (1 runs, 0 failed)", "== program=q world=default \"program\"=p  (1 runs, 0 failed)" ]
    it "tells a parameter named world from the run's world: apart in the settings that vary, its name quoted (both were world=, mixed as one setting)" $ do
      let ofWorld w = replace "\"world\":\"default\"" ("\"world\":" ++ encodeJSON (JString w))
      headings [ ofWorld w (resultLine k [("world", p)] 1 Nothing)
               | (k, (w, p)) <- zip [1 ..] [("a", "b"), ("b", "a"), ("a", "a")] ] `shouldBe`
        [ "== world=a \"world\"=a  (1 runs, 0 failed)", "== world=a \"world\"=b  (1 runs, 0 failed)"
        , "== world=b \"world\"=a  (1 runs, 0 failed)"
        , "== world=a over all other settings  (2 runs, 0 failed)", "== world=b over all other settings  (1 runs, 0 failed)"
        , "== \"world\"=a over all other settings  (2 runs, 0 failed)", "== \"world\"=b over all other settings  (1 runs, 0 failed)" ]
      -- (the run's world the same in every run, the parameter varying: one
      -- setting varies, and no line is per value)
      headings [ resultLine k [("world", p)] 1 Nothing | (k, p) <- zip [1 ..] ["1", "2"] ] `shouldBe`
        [ "== world=default \"world\"=1  (1 runs, 0 failed)", "== world=default \"world\"=2  (1 runs, 0 failed)" ]

    it "files the sweep's line for a run with no result, which names the program's file, under the program its result lines name; with several programs, under its own name unless a result line names it" $ do
      -- one program: its runs with no result are its own, whatever name
      -- the sweep gave them (a wrapper script's), the world too
      headings (take 2 sampleLines ++ [noResult "p.sh" Nothing "null" 7]) `shouldBe` ["== world=default speed=0.1  (3 runs, 1 failed)"]
      headings (map (replace "\"world\":\"default\"" "\"world\":\"w.world\"") (take 2 sampleLines) ++ [noResult "p.sh" Nothing "\"w.world\"" 7])
        `shouldBe` ["== world=w.world speed=0.1  (3 runs, 1 failed)"]
      headings (take 2 sampleLines ++ [noResult "p.sh" Nothing "null" 2]) `shouldBe`
        [ "refused: the run world=default speed=0.1 seed 2 is on a line for a run with no result and on a result line too (a result"
          ++ " file merged with the sweep's line for the same run): each run may be merged once" ]
      headings (take 2 sampleLines ++ [noResult "p.sh" Nothing "null" 7, noResult "p.bash" Nothing "null" 7]) `shouldBe`
        [ "refused: the run world=(not given) speed=0.1 seed 7 is on two lines for a run with no result (the sweep's lines for the"
          ++ " same run merged twice, under two programs' names): each run may be merged once" ]
      -- two programs: a line of one of them is filed with it (its own
      -- world as its result lines name it), one of another program is a
      -- setting of its own
      let q = map (replace "\"world\":\"default\"" "\"world\":\"program\"" . ofProgram "q") (take 2 sampleLines)
      headings (take 2 sampleLines ++ q ++ [noResult "q" Nothing "null" 7, noResult "p" Nothing "null" 8, noResult "r.sh" Nothing "null" 9]) `shouldBe`
        [ "== program=p world=default speed=0.1  (3 runs, 1 failed)", "== program=q world=program speed=0.1  (3 runs, 1 failed)"
        , "== program=r.sh world=(not given) speed=0.1  (1 runs, 1 failed)"
        , "== program=p over all other settings  (3 runs, 1 failed)", "== program=q over all other settings  (3 runs, 1 failed)"
        , "== program=r.sh over all other settings  (1 runs, 1 failed)"
        , "== world=(not given) over all other settings  (1 runs, 1 failed)"
        , "== world=default over all other settings  (3 runs, 1 failed)", "== world=program over all other settings  (3 runs, 1 failed)" ]

    it "files the sweep's line for a run with no result that names its program as the result lines do (with the executable) under that program, whatever other programs' lines are merged (with one other program's result lines, every such run went under it)" $ do
      let settings = filter (not . ("over all other settings" `isInfixOf`)) . headings
      -- a program every run of which wrote no result, merged with another
      -- program's result lines: its own setting
      settings (take 2 sampleLines ++ [noResult "q" (Just "q.sh") "null" 7, noResult "q" (Just "q.sh") "null" 8]) `shouldBe`
        [ "== program=p world=default speed=0.1  (2 runs, 0 failed)", "== program=q world=(not given) speed=0.1  (2 runs, 2 failed)" ]
      -- its run with a result line too: under it, the world too (a wrapper's
      -- runs, named otherwise than its file)
      settings (take 2 sampleLines ++ [ofProgram "q" (sampleLines !! 2), noResult "q" (Just "q.sh") "null" 7]) `shouldBe`
        [ "== program=p world=default speed=0.1  (2 runs, 0 failed)", "== program=q world=default speed=0.1  (2 runs, 1 failed)" ]
      settings (take 2 sampleLines ++ [noResult "p" (Just "p.sh") "null" 7]) `shouldBe` ["== world=default speed=0.1  (3 runs, 1 failed)"]
      -- a line that names only the file (an older sweep's) is filed under
      -- the program another line says that file is named by (its
      -- executable); else with the one program that result lines name, as
      -- before (also when a program whose runs all failed is merged: it
      -- was a setting of its own then); else it is a setting of its own
      settings (take 2 sampleLines ++ [noResult "p.sh" Nothing "null" 7]) `shouldBe` ["== world=default speed=0.1  (3 runs, 1 failed)"]
      settings (take 2 sampleLines ++ [noResult "q" (Just "q.sh") "null" 7, noResult "q.sh" Nothing "null" 9]) `shouldBe`
        [ "== program=p world=default speed=0.1  (2 runs, 0 failed)", "== program=q world=(not given) speed=0.1  (2 runs, 2 failed)" ]
      settings (take 2 sampleLines ++ [noResult "q" (Just "q.sh") "null" 7, noResult "r.sh" Nothing "null" 9]) `shouldBe`
        [ "== program=p world=default speed=0.1  (3 runs, 1 failed)", "== program=q world=(not given) speed=0.1  (1 runs, 1 failed)" ]
      -- (other lines saying the file is two programs': a setting of its own)
      settings (take 2 sampleLines ++ [noResult "q1" (Just "w.sh") "null" 7, noResult "q2" (Just "w.sh") "null" 8, noResult "w.sh" Nothing "null" 9])
        `shouldBe` [ "== program=p world=default speed=0.1  (2 runs, 0 failed)", "== program=q1 world=(not given) speed=0.1  (1 runs, 1 failed)"
                   , "== program=q2 world=(not given) speed=0.1  (1 runs, 1 failed)", "== program=w.sh world=(not given) speed=0.1  (1 runs, 1 failed)" ]
      settings (take 2 sampleLines ++ [ofProgram "q" (sampleLines !! 2), noResult "r.sh" Nothing "null" 9]) `shouldBe`
        [ "== program=p world=default speed=0.1  (2 runs, 0 failed)", "== program=q world=default speed=0.1  (1 runs, 0 failed)"
        , "== program=r.sh world=(not given) speed=0.1  (1 runs, 1 failed)" ]
      -- the same run named both ways: merged twice
      headings (take 2 sampleLines ++ [noResult "p" (Just "p.sh") "null" 7, noResult "p.sh" Nothing "null" 7]) `shouldSatisfy` \hs -> case hs of
        [h] -> "refused: the run world=(not given) speed=0.1 seed 7 is on two lines for a run with no result" `isPrefixOf` h
        _   -> False
      -- an executable that is not a string: not the sweep's line
      mergeResults (replace "\"executable\":\"q.sh\"" "\"executable\":1" (noResult "q" (Just "q.sh") "null" 7))
        `shouldSatisfy` either ("line 1: not a result line of a sweep" `isPrefixOf`) (const False)

    it "refuses a line that is neither a run's result line nor the sweep's line for a run with no result" $ do
      let failureLine = "{\"program\":\"p\",\"world\":\"default\",\"seed\":\"007\",\"params\":{\"speed\":\"1\"}"
                        ++ ",\"flags\":\"--seed 007 --no-such-flag\",\"failure\":\"exit code 2, no result: bad flag\"}"
          refusedAt k ls = mergeResults (unlines ls) `shouldSatisfy`
            either (("line " ++ show (k :: Int) ++ ": not a result line of a sweep") `isPrefixOf`) (const False)
      -- the sweep's line for a run that wrote no result is a failed run;
      -- its seed, written as an older sweep wrote --seed 007, is the
      -- number the run reads (it was listed as "007", and not matched with
      -- the run's result line, seed 7)
      mergeResults (unlines (take 2 sampleLines ++ [failureLine])) `shouldSatisfy`
        either (const False) (\t -> "speed=1  (1 runs, 1 failed)" `isInfixOf` t
                                   && "FAILED seed 7: exit code 2, no result: bad flag" `isInfixOf` t)
      -- (the line's world default is the file so named, ./default: an
      -- older sweep's line)
      mergeResults (unlines [failureLine, replace "\"world\":\"default\"" "\"world\":\"./default\"" (resultLine 7 [("speed", "1")] 1 Nothing)])
        `shouldSatisfy` either ("line 2: the run world=./default speed=1 seed 7 (dt 0.01, seconds 1) is on an earlier line too" `isPrefixOf`)
                               (const False)
      forM_ ["+7", " 7 ", "-0", "9007199254740993", "7.0", "abc", ""] $ \t -> do
        let odd' = replace "\"seed\":\"007\"" ("\"seed\":" ++ encodeJSON (JString t)) failureLine
            listed = either (const []) (filter ("  FAILED" `isPrefixOf`) . lines) (mergeResults odd')
        listed `shouldBe` ["  FAILED seed " ++ (case t of { "+7" -> "7"; " 7 " -> "7"; "-0" -> "0"; _ -> encodeJSON (JString t) })
                           ++ ": exit code 2, no result: bad flag"]
      -- an empty object, a run log's lines, another JSON value, not JSON
      refusedAt 1 ["{}"]
      refusedAt 2 [head sampleLines, "{\"kind\":\"summary\",\"simulated\":1,\"steps\":101,\"interrupted\":false,\"failure\":null,\"scores\":{}}"]
      refusedAt 1 ["{\"kind\":\"header\",\"format\":\"afrp-log\",\"version\":1}"]
      refusedAt 1 ["[1,2]"]
      refusedAt 2 [head sampleLines, "not json"]
      -- a result line or a failure line with a field missing or of the wrong kind
      let without k = encodeJSON . (\v -> case v of
            JObject kvs -> JObject (filter ((/= k) . fst) kvs)
            other       -> other) . parsed
      forM_ ["program", "world", "seed", "dt", "seconds", "params", "outcome"] $ \k ->
        refusedAt 1 [without k (head sampleLines)]
      forM_ ["program", "world", "seed", "params", "flags", "failure"] $ \k ->
        refusedAt 1 [without k failureLine]
      refusedAt 1 [replace "\"seed\":1," "\"seed\":\"1\"," (head sampleLines)]
      refusedAt 1 [replace "\"failure\":\"exit" "\"failure\":{\"exit\":1},\"x\":\"exit" failureLine]

    it "afrp-sweep-merge: a result line cut short is refused with its file and line, and its column of the line (it said line 1 too)" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      writeFile (dir </> "r.jsonl") (unlines [head sampleLines, take 150 (head sampleLines)])
      (code, out, err) <- readProcessWithExitCode merger [dir </> "r.jsonl"] ""
      (code, out) `shouldBe` (ExitFailure 1, "")
      err `shouldSatisfy` ((dir </> "r.jsonl" ++ ": line 2: not a result line of a sweep (not JSON: column 151 of the line: ") `isInfixOf`)
      err `shouldNotSatisfy` ("line 1" `isInfixOf`)

    it "afrp-sweep-merge: a run log given by mistake is refused with its file and line (exit 1)" $ withTempDir $ \dir -> do
      prog <- childScript dir "program"
      merger <- childScript dir "merge"
      (code, _, err) <- readProcessWithExitCode prog ["--quiet", "--no-svg", "--no-replay", "--seconds", "1", "--log", dir </> "run.jsonl"] ""
      (code, err) `shouldBe` (ExitSuccess, "")
      writeFile (dir </> "r.jsonl") (unlines (take 2 sampleLines))
      (code', out, err') <- readProcessWithExitCode merger [dir </> "r.jsonl", dir </> "run.jsonl"] ""
      (code', out) `shouldBe` (ExitFailure 1, "")
      err' `shouldSatisfy` ((dir </> "run.jsonl" ++ ": line 1: not a result line of a sweep") `isInfixOf`)

    it "afrp-sweep-merge: a file that is not UTF-8 is refused with its line, column and byte (exit 1)" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      B.writeFile (dir </> "r.jsonl") (B.concat [B.pack (map (fromIntegral . fromEnum) (head sampleLines)), B.pack [10, 0x7b, 0xff, 10]])
      (code, out, err) <- readProcessWithExitCode merger [dir </> "r.jsonl"] ""
      (code, out) `shouldBe` (ExitFailure 1, "")
      err `shouldBe` ("afrp-sweep-merge: " ++ dir </> "r.jsonl" ++ ":2:2: invalid UTF-8 (byte 0xff)\n")

    it "afrp-sweep-merge: a line longer than maxLineBytes (an endless /dev/zero) is refused at once, with its file and line (exit 2)" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      let file = dir </> "long.jsonl"
          tooLong name k = "afrp-sweep-merge: " ++ name ++ ": line " ++ show (k :: Int) ++ ": longer than 16777216 bytes"
      B.writeFile file (B.concat [ B.pack (map (fromIntegral . fromEnum) (head sampleLines ++ "\n"))
                                 , B.replicate (maxLineBytes + 1) 0x61, B.pack [10] ])
      -- (in a heap of 512 MB, which the whole input read at once overflows)
      forM_ [(file, 2), ("/dev/zero", 1)] $ \(input, k) -> do
        r <- timeout 60000000 (readProcessWithExitCode merger ["+RTS", "-M512m", "-RTS", input] "")
        fmap (\(code, out, err) -> (code, out, tooLong input k `isPrefixOf` err)) r `shouldBe` Just (ExitFailure 2, "", True)
      -- a line just at the limit is read (and here refused for what it is)
      B.writeFile file (B.replicate maxLineBytes 0x61)
      (code, _, err) <- readProcessWithExitCode merger [file] ""
      (code, "line 1: not a result line of a sweep" `isInfixOf` err) `shouldBe` (ExitFailure 1, True)

    it "afrp-sweep-merge: its memory does not grow with the lines (10,000 lines in a heap of 32 MB)" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      let file = dir </> "many.jsonl"
      writeFile file (unlines [ resultLine s [("speed", show (s `mod` 4))] (fromIntegral s) Nothing | s <- [1 .. 10000] ])
      (code, out, err) <- readProcessWithExitCode merger ["+RTS", "-M32m", "-RTS", file] ""
      (code, err) `shouldBe` (ExitSuccess, "")
      lines out `shouldSatisfy` elem "== world=default speed=0  (2500 runs, 0 failed)"
      map words (lines out) `shouldSatisfy` elem ["SimbotA", "1", "distance", "5002.0000", "4.0000", "10000.0000"]

    it "addLineUtf8 merges a line's bytes as addLine its text: every cut of a result line, blank lines, spaces beyond ASCII" $ do
      let line = BC.pack (head sampleLines)
          viaText b = either ("refused: " ++) (either ("no table: " ++) id . renderMerge)
                        (either (const (Left "not UTF-8")) (addLine emptyMerge) (utf8Text "" b))
          viaBytes b = either ("refused: " ++) (either ("no table: " ++) id . renderMerge)
                         (either (const (Left "not UTF-8")) (addLineUtf8 emptyMerge) (checkUtf8 b))
          extra = [B.empty, BC.pack " \t ", B.pack [0xc2, 0xa0], B.pack [0x20, 0xe3, 0x80, 0x80], B.pack [0xc2, 0xa0, 0x7b], BC.pack "{}"]
      forM_ ([ B.take k line | k <- [0 .. B.length line] ] ++ extra) $ \b ->
        (b, viaBytes b) `shouldBe` (b, viaText b)

    it "afrp-sweep-merge: a result line of 12 MiB is read in a heap of 60 MB (its text as a String took about 300 MB)" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      let file = dir </> "wide.jsonl"
          line = head sampleLines
          -- (a member the merge does not read, which the parser still reads over)
          padded = B.concat [ BC.pack (init line), BC.pack ",\"padding\":["
                            , B.concat (replicate 63000 (BC.pack ("[" ++ intercalate "," (replicate 100 "1") ++ "],")))
                            , BC.pack "[1]]}\n" ]
      B.length padded `shouldSatisfy` (> 12 * 1024 * 1024)
      B.writeFile file padded
      (code, out, err) <- readProcessWithExitCode merger ["+RTS", "-M60m", "-RTS", file] ""
      (code, err) `shouldBe` (ExitSuccess, "")
      Right out `shouldBe` mergeResults line

    it "afrp-sweep-merge: a run both on a result line and on the sweep's line without --world is refused as merged twice, in either order (it said: no result lines)" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      writeFile (dir </> "a.jsonl") "{\"program\":\"p\",\"world\":\"program\",\"seed\":1,\"dt\":0.01,\"seconds\":1,\"params\":{\"a\":\"1\"},\"outcome\":{\"simulated\":1,\"steps\":101,\"interrupted\":false,\"failure\":null,\"robots\":[],\"scores\":{}}}\n"
      writeFile (dir </> "c.jsonl") "{\"program\":\"p\",\"world\":null,\"seed\":1,\"params\":{\"a\":\"1\"},\"flags\":\"x\",\"failure\":\"boom\"}\n"
      forM_ [["a.jsonl", "c.jsonl"], ["c.jsonl", "a.jsonl"]] $ \files -> do
        (code, out, err) <- readProcessWithExitCode merger (map (dir </>) files) ""
        (code, out) `shouldBe` (ExitFailure 1, "")
        err `shouldSatisfy` ("afrp-sweep-merge: the run world=program a=1 seed 1 is on a line for a run with no result and on a result line too" `isPrefixOf`)

    it "afrp-sweep-merge: no result line at all (empty files, empty standard input) is refused (exit 1)" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      writeFile (dir </> "a.jsonl") ""
      writeFile (dir </> "b.jsonl") "\n"
      readProcessWithExitCode merger [dir </> "a.jsonl", dir </> "b.jsonl"] "" `shouldReturn`
        (ExitFailure 1, "", "afrp-sweep-merge: no result lines in " ++ dir </> "a.jsonl, " ++ dir </> "b.jsonl\n")
      readProcessWithExitCode merger [] "" `shouldReturn` (ExitFailure 1, "", "afrp-sweep-merge: no result lines in standard input\n")
      -- an empty shard among others is no fault
      writeFile (dir </> "c.jsonl") (unlines (take 2 sampleLines))
      (code, out, _) <- readProcessWithExitCode merger [dir </> "a.jsonl", dir </> "c.jsonl"] ""
      (code, "(2 runs, 0 failed)" `isInfixOf` out) `shouldBe` (ExitSuccess, True)

    it "afrp-sweep-merge: a file given twice, under any name, or a run in two files is refused" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      let r = dir </> "r.jsonl"
      writeFile r (unlines (take 2 sampleLines))
      _ <- readProcess "ln" [r, dir </> "hard.jsonl"] ""
      createFileLink r (dir </> "soft.jsonl")
      forM_ [[r, r], [r, dir </> "." </> "r.jsonl"], [r, dir </> "hard.jsonl"], [dir </> "soft.jsonl", r]] $ \args -> do
        (code, out, err) <- readProcessWithExitCode merger args ""
        (code, out, "its runs would be counted twice" `isInfixOf` err) `shouldBe` (ExitFailure 2, "", True)
      writeFile (dir </> "s.jsonl") (unlines (drop 1 sampleLines))
      (code, out, err) <- readProcessWithExitCode merger [r, dir </> "s.jsonl"] ""
      (code, out) `shouldBe` (ExitFailure 1, "")
      err `shouldSatisfy` ((dir </> "s.jsonl: line 1: the run world=default speed=0.1 seed 2") `isInfixOf`)

    it "afrp-sweep-merge: a file that cannot be read is named once (exit 2)" $ withTempDir $ \dir -> do
      merger <- childScript dir "merge"
      readProcessWithExitCode merger [dir </> "none.jsonl"] "" `shouldReturn`
        (ExitFailure 2, "", "afrp-sweep-merge: " ++ dir </> "none.jsonl: cannot read it: does not exist (No such file or directory)\n")

  describe "--param" $ do
    it "collects NAME=VALUE pairs in order, a repeated name keeping its last value" $
      simParamsOf ["--seed", "3", "--param", "a=1", "--param", "b=x=y", "--param", "a=2", "--param", "c="]
        `shouldBe` [("a", "2"), ("b", "x=y"), ("c", "")]
    it "reads the pairs of a command line whose settings fit only the program's own (--dt 0.05 with a program's frame rate of 10), and none of one whose flags are refused" $ do
      -- (the defaults' 25 frames a second and --dt 0.05 do not fit: the
      -- pairs were dropped, and getSimParams would have stopped the program)
      simParamsOf ["--dt", "0.05", "--param", "speed=2"] `shouldBe` [("speed", "2")]
      fmap (const ()) (parseSimArgs defaultSimOptions { optFps = 10 } ["--dt", "0.05"]) `shouldBe` Right ()
      simParamsOf ["--dt", "abc", "--param", "speed=2"] `shouldBe` []
      simParamsOf ["--frobnicate", "--param", "speed=2"] `shouldBe` []
    it "a name given twice: the run warns, naming the values and the one used (the last), and exits 0" $ withTempDir $ \dir -> do
      (code, err, line) <- runOnce dir ["--seconds", "0.1", "--param", "speed=0.2", "--param", "tag=x", "--param", "speed=0.3"]
      code `shouldBe` ExitSuccess
      map unsigned (lines err) `shouldBe`
        [" warning: --param speed is given twice, speed=0.2 then speed=0.3: the last, speed=0.3, is used"]
      field ["params"] (parsed line) `shouldBe` JObject [("speed", JString "0.3"), ("tag", JString "x")]
      (_, err3, _) <- runOnce dir ["--seconds", "0.1", "--param", "speed=1", "--param", "speed=2", "--param", "speed=1"]
      err3 `shouldSatisfy` (": warning: --param speed is given 3 times, speed=1 then speed=2 then speed=1: the last, speed=1, is used\n" `isSuffixOf`)
    it "a flag with one value given twice: the run warns, naming the values and the one used (the last), and exits 0 (it was silent)" $
      withTempDir $ \dir -> do
        (code, err, line) <- runOnce dir [ "--seconds", "0.1", "--keys", "0:a", "--odometry-noise", "0", "--seconds", "0.2"
                                         , "--keys", "0.1:b", "--odometry-noise", "0.01", "--param", "tag=x" ]
        code `shouldBe` ExitSuccess
        map unsigned (lines err) `shouldBe`
          [ " warning: --seconds is given twice, 0.1 then 0.2: the last, 0.2, is used"
          , " warning: --odometry-noise is given twice, 0 then 0.01: the last, 0.01, is used" ]
        (field ["seconds"] (parsed line), field ["odometryNoise"] (parsed line)) `shouldBe` (JNumber 0.2, JNumber 0.01)
        -- (a value that is empty or holds a space is quoted)
        (code', err', _) <- runOnce dir ["--seconds", "0.1", "--out", dir </> "a b", "--out", dir </> "c"]
        code' `shouldBe` ExitSuccess
        err' `shouldSatisfy` ((": warning: --out is given twice, " ++ show (dir </> "a b") ++ " then " ++ dir </> "c"
                               ++ ": the last, " ++ dir </> "c" ++ ", is used\n") `isSuffixOf`)
    it "paramOr on a command line runSim refuses stops the program at once, with runSim's message and exit code 2 (it read the default and the program went on); --help prints the usage and exits 0" $
      withTempDir $ \dir -> do
        prog <- childScript dir "announcer"
        forM_ [ (["--param", "=5"], " --param expects NAME=VALUE, got \"=5\"")
              , (["--param", "speed=0.2", "--seconds", "abc"], " --seconds expects a non-negative number (written as in a world file: 2, 0.5, 1e-3), got \"abc\"")
              , (["--no-such-flag"], " unknown argument \"--no-such-flag\" (see --help)")
                -- (an empty file name is its flag's fault, whatever the settings: the program's
                -- own action ran first)
              , (["--param", "speed=0.2", "--svg", ""], " --svg must not be empty (a file name)") ] $ \(args, message) -> do
          (code, out, err) <- readProcessWithExitCode prog args ""
          (code, out, map unsigned (lines err)) `shouldBe` (ExitFailure 2, "", [message])
        (code, out, err) <- readProcessWithExitCode prog ["--param", "speed=0.2", "--help"] ""
        (code, err) `shouldBe` (ExitSuccess, "")
        out `shouldSatisfy` ("usage: " `isPrefixOf`)
        -- (the program's own action, which prints "speed 0.2", did not run)
        lines out `shouldNotSatisfy` elem "speed 0.2"
        length (filter ("usage: " `isPrefixOf`) (lines out)) `shouldBe` 1
        -- (a command line runSim takes: the program's own action, then the run)
        (code', out', _) <- readProcessWithExitCode prog ["--param", "speed=0.2", "--seconds", "0.1", "--quiet", "--no-svg", "--no-replay"] ""
        (code', take 1 (lines out')) `shouldBe` (ExitSuccess, ["speed 0.2"])
    it "paramOrFrom: a program with its own command line (NAME [flags]) reads a --param of its flags, and the run does not warn of it (simParamsOf counted none, and every one was warned of); one it never reads is" $
      withTempDir $ \dir -> do
        prog <- childScript dir "ownline"
        let quiet = ["--seconds", "0.1", "--quiet", "--no-svg", "--no-replay"]
        (code, out, err) <- readProcessWithExitCode prog (["wander"] ++ quiet ++ ["--param", "speed=0.2"]) ""
        (code, take 1 (lines out), err) `shouldBe` (ExitSuccess, ["wander speed 0.2"], "")
        (code', out', err') <- readProcessWithExitCode prog (["wander"] ++ quiet ++ ["--param", "speed=0.3", "--param", "sped=2"]) ""
        (code', take 1 (lines out')) `shouldBe` (ExitSuccess, ["wander speed 0.3"])
        map unsigned (lines err') `shouldBe`
          [" warning: --param sped=2: this program has asked for no parameter named \"sped\" (it reads \"speed\")"]
        -- (not given: the default, and nothing to warn of)
        readProcessWithExitCode prog (["wander"] ++ quiet) "" >>= \(c, o, e) ->
          (c, take 1 (lines o), e) `shouldBe` (ExitSuccess, ["wander speed 0.1"], "")
    it "paramOrFrom: a value paramOr refuses stops the program at once with paramOr's message and exit code 2, and so does a flag runSim refuses; --help is the program's own" $
      withTempDir $ \dir -> do
        prog <- childScript dir "ownline"
        forM_ [ (["--param", "speed=fast"], " --param speed=fast: cannot read the value \"fast\" (write it as Haskell's read reads it: 0.5, 3, True, \"quoted text\")")
              , (["--param", "speed=1e999"], " --param speed=1e999: the value \"1e999\" is out of range for this parameter (it would read as Infinity)")
              , (["--param", "speed=0.2", "--seconds", "abc"], " --seconds expects a non-negative number (written as in a world file: 2, 0.5, 1e-3), got \"abc\"")
              , (["--frobnicate", "--param", "speed=0.2"], " unknown argument \"--frobnicate\" (see --help)") ] $ \(flags, message) -> do
          (code, out, err) <- readProcessWithExitCode prog ("wander" : flags) ""
          -- (the program's own action, which prints the speed, did not run)
          (code, out, map unsigned (lines err)) `shouldBe` (ExitFailure 2, "", [message])
        -- (--help: the default read, the program's own usage printed; the
        -- flags after --help are not read, as runSim reads none)
        readProcessWithExitCode prog ["wander", "--param", "speed=0.2", "--help", "--param", "speed=fast"] ""
          `shouldReturn` (ExitSuccess, "wander speed 0.1\nusage: ownline NAME [flags]\n", "")
    it "rejects a value without a name or an =" $ do
      parseSimArgs defaultSimOptions ["--param", "speed"] `shouldSatisfy` either ("NAME=VALUE" `isInfixOf`) (const False)
      parseSimArgs defaultSimOptions ["--param", "=1"] `shouldSatisfy` either ("NAME=VALUE" `isInfixOf`) (const False)
    it "paramOr: a value that does not read stops the program before it runs, naming it" $
      stopsForParam "speed=fast" "--param speed=fast: cannot read the value \"fast\""

    it "readSimParam: a value the type cannot hold is refused, never wrapped" $ do
      -- integers that a bounded type would wrap around
      (readSimParam "n" "99999999999999999999" :: Either String Int)
        `shouldSatisfy` either ("--param n=99999999999999999999: the value \"99999999999999999999\" is out of range" `isInfixOf`) (const False)
      (readSimParam "n" "300" :: Either String Word8) `shouldSatisfy` either ("out of range" `isInfixOf`) (const False)
      (readSimParam "n" "-1" :: Either String Word) `shouldSatisfy` either ("out of range" `isInfixOf`) (const False)
      (readSimParam "n" "128" :: Either String Int8) `shouldSatisfy` either ("would read as -128" `isInfixOf`) (const False)
      -- a number too large for a Double, unless infinity is what is written
      (readSimParam "x" "1e400" :: Either String Double) `shouldSatisfy` either ("out of range" `isInfixOf`) (const False)
      (readSimParam "x" "Infinity" :: Either String Double) `shouldBe` Right (1 / 0)
      -- values that fit are read as they are, at their bounds too
      (readSimParam "n" "9223372036854775807" :: Either String Int) `shouldBe` Right maxBound
      (readSimParam "n" "-9223372036854775808" :: Either String Int) `shouldBe` Right minBound
      (readSimParam "n" " 255 " :: Either String Word8) `shouldBe` Right 255
      (readSimParam "n" "0x10" :: Either String Int) `shouldBe` Right 16
      (readSimParam "x" "3" :: Either String Double) `shouldBe` Right 3
      (readSimParam "x" "99999999999999999999" :: Either String Double) `shouldBe` Right 1e20
      (readSimParam "n" "99999999999999999999" :: Either String Integer) `shouldBe` Right 99999999999999999999
      (readSimParam "s" "\"text\"" :: Either String String) `shouldBe` Right "text"
      (readSimParam "b" "True" :: Either String Bool) `shouldBe` Right True
      (readSimParam "n" "fast" :: Either String Int) `shouldSatisfy` either ("cannot read the value \"fast\"" `isInfixOf`) (const False)
    it "readSimParam: NaN is refused, and so is a number that a Double or a Float reads as zero" $ do
      let refusedAs :: String -> Either String b -> Bool
          refusedAs what = either (what `isInfixOf`) (const False)
      (readSimParam "x" "NaN" :: Either String Double)
        `shouldSatisfy` refusedAs "--param x=NaN: the value \"NaN\" is not a number (NaN), which no parameter may be"
      (readSimParam "p" "[1, NaN]" :: Either String [Float]) `shouldSatisfy` refusedAs "is not a number (NaN)"
      (readSimParam "x" "1e-400" :: Either String Double)
        `shouldSatisfy` refusedAs "the value \"1e-400\" is out of range for this parameter (it would read as 0.0)"
      (readSimParam "x" "-0.0000000000000000000000000000000000000000000000001" :: Either String Float)
        `shouldSatisfy` refusedAs "out of range"
      (readSimParam "p" "Just [2, 5e-324, 1e-330]" :: Either String (Maybe [Double])) `shouldSatisfy` refusedAs "out of range"
      -- zero written as zero, and the smallest numbers a Double holds, are read
      (readSimParam "x" "0.0e-400" :: Either String Double) `shouldBe` Right 0
      (readSimParam "p" "[0, -0.0, 00.000e5]" :: Either String [Double]) `shouldBe` Right [0, 0, 0]
      (readSimParam "x" "5e-324" :: Either String Double) `shouldBe` Right 5e-324
      (readSimParam "x" "-Infinity" :: Either String Double) `shouldBe` Right (-1 / 0)
    it "readSimParam: a number the type cannot hold is refused wherever it is in the value" $ do
      let refused :: Either String b -> Bool
          refused = either ("out of range" `isInfixOf`) (const False)
      (readSimParam "p" "[1,2,300]" :: Either String [Word8]) `shouldSatisfy` refused
      -- (a set drops duplicates, so it writes back fewer numbers than the
      -- text: 300 wrapped to 44 was taken)
      (readSimParam "p" "fromList [1,1,300]" :: Either String (S.Set Word8)) `shouldSatisfy` refused
      (readSimParam "p" "fromList [1,1,3]" :: Either String (S.Set Word8)) `shouldBe` Right (S.fromList [1, 3])
      (readSimParam "p" "fromList [1,1,1e-400]" :: Either String (S.Set Double)) `shouldSatisfy` refused
      (readSimParam "p" "fromList [1,1,1e400]" :: Either String (S.Set Double)) `shouldSatisfy` refused
      (readSimParam "p" (show [1 .. 20000 :: Int]) :: Either String [Int]) `shouldBe` Right [1 .. 20000]
      (readSimParam "p" "(300,1)" :: Either String (Word8, Int)) `shouldSatisfy` refused
      (readSimParam "p" "Just 99999999999999999999" :: Either String (Maybe Int)) `shouldSatisfy` refused
      (readSimParam "p" "300 % 1" :: Either String (Ratio Word8)) `shouldSatisfy` refused
      (readSimParam "p" "[1e400]" :: Either String [Double]) `shouldSatisfy` refused
      (readSimParam "p" "Just (-1e400)" :: Either String (Maybe Double)) `shouldSatisfy` refused
      (readSimParam "p" "1e39" :: Either String Float) `shouldSatisfy` refused
      -- and what fits is read as it is
      (readSimParam "p" "[-128,127]" :: Either String [Int8]) `shouldBe` Right [-128, 127]
      (readSimParam "p" "Just (-5)" :: Either String (Maybe Int)) `shouldBe` Right (Just (-5))
      (readSimParam "p" "(-5)" :: Either String Int) `shouldBe` Right (-5)
      (readSimParam "p" "6 % 8" :: Either String Rational) `shouldBe` Right (3 % 4)
      (readSimParam "p" "[3, 12345678901234567891]" :: Either String [Double]) `shouldBe` Right [3, 12345678901234567891]
      (readSimParam "p" "[\"1\",\"300\"]" :: Either String [String]) `shouldBe` Right ["1", "300"]
      (readSimParam "p" "[Infinity,-Infinity,2]" :: Either String [Double]) `shouldBe` Right [1 / 0, -1 / 0, 2]
      (readSimParam "p" "0xFF" :: Either String Word8) `shouldBe` Right 255
      (readSimParam "p" "[1.5, 2]" :: Either String [Double]) `shouldBe` Right [1.5, 2]
      -- a set or a map writes its elements back sorted: not a change of value
      (readSimParam "p" "fromList [3,1]" :: Either String (S.Set Int)) `shouldBe` Right (S.fromList [1, 3])
      (readSimParam "p" "fromList [(2,1),(1,5)]" :: Either String (M.Map Int Int)) `shouldBe` Right (M.fromList [(1, 5), (2, 1)])
      (readSimParam "p" "fromList [300,1]" :: Either String (S.Set Word8)) `shouldSatisfy` refused
    it "paramOr: a value that cannot be made (1 % 0) stops the program, naming it" $
      stopsForParam "ratio=1 % 0" "--param ratio=1 % 0: the value \"1 % 0\" cannot be made"
    it "paramOr: a value out of range stops the program before it runs, naming it" $
      stopsForParam "speed=1e999" "--param speed=1e999: the value \"1e999\" is out of range"

  describe "--result" $ do
    it "writes one JSON line with the settings and the outcome; the parameter reaches the controller" $ withTempDir $ \dir -> do
      results <- forM ["0.05", "0.1"] $ \v -> do
        (code, err, line) <- runOnce dir ["--seconds", "2", "--seed", "3", "--param", "speed=" ++ v, "--param", "tag=a=b"]
        (code, err) `shouldBe` (ExitSuccess, "")
        length (lines line) `shouldBe` 1
        pure (parsed line)
      forM_ results $ \r -> do
        -- (the child runs a world of its own: runSim (Just world); it was "default")
        field ["world"] r `shouldBe` JString "program"
        field ["seed"] r `shouldBe` JNumber 3
        field ["dt"] r `shouldBe` JNumber 0.01
        field ["seconds"] r `shouldBe` JNumber 2
        field ["odometryNoise"] r `shouldBe` JNumber 0
        field ["outcome", "simulated"] r `shouldBe` JNumber 2
        field ["outcome", "steps"] r `shouldBe` JNumber 201
        field ["outcome", "interrupted"] r `shouldBe` JBool False
        field ["outcome", "failure"] r `shouldBe` JNull
        field ["outcome", "scores"] r `shouldBe` JObject []
      map (field ["params"]) results `shouldBe`
        [ JObject [("speed", JString v), ("tag", JString "a=b")] | v <- ["0.05", "0.1"] ]
      let robot r = case field ["outcome", "robots"] r of
            JArray [x] -> x
            other      -> error ("one robot expected: " ++ show other)
          number k r = either error id (asNumber (field [k] (robot r)))
      map (field ["type"] . robot) results `shouldBe` replicate 2 (JString "SimbotA")
      -- the robot starts at x = -2.25 (seed 3) and drives along y = 0
      forM_ results $ \r -> do
        number "x" r - (-2.25) `shouldSatisfy` (\dx -> abs (dx - number "distance" r) < 1e-9)
        number "battery" r `shouldSatisfy` (\b -> b > 0 && b <= 1)
        number "bumps" r `shouldBe` 0
        number "stuckTime" r `shouldBe` 0
      map (number "distance") results `shouldSatisfy` (\ds -> case ds of
        [slow, fast] -> slow > 0.05 && fast > 1.5 * slow
        _            -> False)
    it "in the C locale, a parameter and a world file named beyond ASCII are read and written as spelt (the parameter was not found, the names were U+FFFD)" $
      withTempDir $ \dir -> do
        prog <- childScript dir "program"
        let wf = dir </> cLocale "wé.world"
            file = dir </> "result.json"
        writeFile wf "simbotA 1 at 0 0\n"
        (code, _, err) <- runScriptCode [("LC_ALL", "C")] prog
          [ "--quiet", "--no-svg", "--no-replay", "--seconds", "0.1", "--world", wf
          , "--param", cLocale "größe=ü", "--result", file ]
        (code, err) `shouldBe` (ExitSuccess, "")
        r <- parsed <$> readFile' file
        field ["world"] r `shouldBe` JString (dir </> "wé.world")
        field ["params"] r `shouldBe` JObject [("größe", JString "ü")]
    it "counts the bumps and the time stuck against a wall" $ withTempDir $ \dir -> do
      (code, err, line) <- runOnce dir ["--seconds", "10", "--seed", "7", "--param", "speed=1"]
      (code, err) `shouldBe` (ExitSuccess, "")
      let robotOf = case field ["outcome", "robots"] (parsed line) of
            JArray [x] -> x
            other      -> error (show other)
          number k = either error id (asNumber (field [k] robotOf))
      number "bumps" `shouldBe` 1
      number "stuckTime" `shouldSatisfy` (\t -> t > 1 && t < 9)
    it "a controller that throws at its first sample: the line lists the robots where the world places them (it listed none)" $ withTempDir $ \dir -> do
      (code, _, line) <- runOnce dir ["--seconds", "2", "--seed", "3", "--param", "failAt=0"]
      code `shouldBe` ExitFailure 1
      let r = parsed line
      field ["outcome", "failure"] r `shouldSatisfy` (/= JNull)
      case field ["outcome", "robots"] r of
        JArray [x] -> do
          -- (the robot starts at x = -2.25, y = 0, with seed 3)
          map (\k -> field [k] x) ["type", "id", "x", "y", "distance", "bumps", "stuckTime", "battery"]
            `shouldBe` [JString "SimbotA", JNumber 1, JNumber (-2.25), JNumber 0, JNumber 0, JNumber 0, JNumber 0, JNumber 1]
        other -> expectationFailure ("one robot expected: " ++ show other)

    it "a controller that throws: exit code 1, and the line has the failure and the time simulated" $ withTempDir $ \dir -> do
      (code, err, line) <- runOnce dir ["--seconds", "2", "--param", "failAt=0.5"]
      code `shouldBe` ExitFailure 1
      err `shouldSatisfy` ("gives up" `isInfixOf`)
      let r = parsed line
      field ["outcome", "failure"] r `shouldSatisfy` \f -> case f of
        JString s -> all (`isInfixOf` s) ["SimbotA 1", "0.500", "gives up"]
        _         -> False
      field ["outcome", "simulated"] r `shouldBe` JNumber 0.49

  describe "scripts/sweep" $ do
    it "8 seeds x 2 speeds with GNU parallel give the lines and the table of the runs one by one" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sweep <- script "sweep"
      _ <- runScript [] sweep ["-j", "4", "--seeds", "1..8", "--param", "speed=" ++ concatMap (++ ",") (init speeds) ++ last speeds
                              , prog, dir </> "sweep.jsonl", "--", "--seconds", "3"]
      swept <- lines <$> readFile (dir </> "sweep.jsonl")
      one <- sequentialLines dir
      swept `shouldBe` one
      writeFile (dir </> "one.jsonl") (unlines one)
      table <- merged dir [dir </> "sweep.jsonl"]
      merged dir [dir </> "one.jsonl"] `shouldReturn` table
      table `shouldSatisfy` \t -> all (`isInfixOf` t) ["speed=0.05", "speed=0.1", "(8 runs, 0 failed)", "SimbotA 1 distance"]

    it "the Slurm script's task for every SLURM_ARRAY_TASK_ID gives the same results and table" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sbatch <- script "sweep.sbatch"
      forM_ [0 .. 2 :: Int] $ \i ->
        runScript [("SLURM_ARRAY_TASK_ID", show i), ("SLURM_ARRAY_TASK_COUNT", "3")] sbatch
                  [dir </> "out", prog, "--seeds", "1..8", "--param", "speed=0.05,0.1", "--", "--seconds", "3"]
      let shards = [ dir </> "out" </> ("shard-" ++ show i ++ ".jsonl") | i <- [2, 0, 1 :: Int] ]
      shardLines <- concat <$> mapM (fmap lines . readFile) shards
      map length [shardLines] `shouldBe` [16]
      one <- sequentialLines dir
      sort shardLines `shouldBe` sort one
      writeFile (dir </> "one.jsonl") (unlines one)
      expected <- merged dir [dir </> "one.jsonl"]
      merged dir shards `shouldReturn` expected

    it "a run that fails, or writes no result at all, is in the merged table" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sweep <- script "sweep"
      writeFile (dir </> "jobs") (unlines
        [ "# seed 2 throws, seed 3 has a flag the program rejects, seed 4 cannot write its SVG"
        , "--seed 1 --param speed=1", "--seed 2 --param speed=1 --param failAt=0.5", ""
        , "--seed 3 --param speed=1 --no-such-flag", "--seed 4 --param speed=2 --svg /dev/full" ])
      (code, _, err) <- runScriptCode [] sweep ["--jobs", dir </> "jobs", prog, dir </> "r.jsonl", "--", "--seconds", "2"]
      (code, "4 runs, 3 failed" `isInfixOf` err) `shouldBe` (ExitFailure 1, True)
      table <- merged dir [dir </> "r.jsonl"]
      table `shouldSatisfy` ("speed=1  (2 runs, 1 failed)" `isInfixOf`)
      table `shouldSatisfy` ("failAt=0.5 speed=1  (1 runs, 1 failed)" `isInfixOf`)
      table `shouldSatisfy` ("FAILED seed 2: the controller of SimbotA 1 failed at t = 0.500" `isInfixOf`)
      table `shouldSatisfy` ("FAILED seed 3: exit code 2, no result" `isInfixOf`)
      table `shouldSatisfy` ("FAILED seed 4: exit code 1: " `isInfixOf`)

    it "names a run with no result by its program as the program's result lines do, so that the merge files it with that program's runs, never another's (a program every run of which wrote no result went under the one other program merged)" $
      withTempDir $ \dir -> do
        requireParallel
        sweep <- script "sweep"
        a <- namedProgram dir "a.sh" "robot-a"
        b <- namedProgram dir "b.sh" "robot-b"
        _ <- runScript [] sweep ["--seeds", "1..2", a, dir </> "a.jsonl", "--", "--seconds", "1"]
        -- every run of b stops at a flag of its job line: no result line at all
        writeFile (dir </> "jobs") "--seed 1 --no-such-flag\n--seed 2 --no-such-flag\n"
        (code, _, _) <- runScriptCode [] sweep ["--jobs", dir </> "jobs", b, dir </> "b.jsonl", "--", "--seconds", "1"]
        code `shouldBe` ExitFailure 1
        bs <- map parsed . lines <$> readFile (dir </> "b.jsonl")
        map (\r -> (field ["program"] r, field ["executable"] r)) bs `shouldBe` replicate 2 (JString "robot-b", JString "b.sh")
        table <- merged dir [dir </> "a.jsonl", dir </> "b.jsonl"]
        filter (\l -> "== " `isPrefixOf` l && not ("over all other settings" `isInfixOf` l)) (lines table) `shouldBe`
          [ "== program=robot-a world=program  (2 runs, 0 failed)", "== program=robot-b world=(not given)  (2 runs, 2 failed)" ]
        -- a program that does not print its name for --print-program
        -- (here: exits at once) leaves its name unknown: the line names
        -- its file alone, as an older sweep's did, and a note says so
        let c = dir </> "c.sh"
        writeScript c (unlines [ "#!/bin/bash", "case \" $* \" in *' --print-program '*) exit 0 ;; esac", "exec '" ++ a ++ "' \"$@\"" ])
        (codeC, _, errC) <- runScriptCode [] sweep ["--jobs", dir </> "jobs", c, dir </> "c.jsonl", "--", "--seconds", "1"]
        codeC `shouldBe` ExitFailure 1
        errC `shouldSatisfy` ("note: the program did not print its name for --print-program (exit code 0)" `isInfixOf`)
        cs <- map parsed . lines <$> readFile (dir </> "c.jsonl")
        map (\r -> (field ["program"] r, either (const Nothing) Just (member "executable" r))) cs
          `shouldBe` replicate 2 (JString "c.sh", Nothing)

    it "asks the program its name with --print-program, which runs nothing: a log the program names in code is not written over (a first version learnt the name from a 0-second run, which wrote it)" $
      withTempDir $ \dir -> do
        requireParallel
        sweep <- script "sweep"
        real <- childScript dir "program"
        let logger = dir </> "logger.sh"
            kept   = dir </> "run.jsonl"
        writeScript logger (unlines [ "#!/bin/bash", "exec '" ++ real ++ "' --log '" ++ kept ++ "' \"$@\"" ])
        writeFile kept "precious user data\n"
        writeFile (dir </> "jobs") (unlines [ "--seed " ++ show k ++ " --log " ++ (dir </> ("run-" ++ show k ++ ".jsonl"))
                                            | k <- [1, 2 :: Int] ])
        (code, _, err) <- runScriptCode [] sweep ["--jobs", dir </> "jobs", logger, dir </> "r.jsonl", "--", "--seconds", "1"]
        (code, "note:" `isInfixOf` err) `shouldBe` (ExitSuccess, False)
        readFile kept `shouldReturn` "precious user data\n"
        mapM_ (\k -> doesFileExist (dir </> ("run-" ++ show k ++ ".jsonl")) `shouldReturn` True) [1, 2 :: Int]
        -- (what it prints: the name, a JSON string on a line of its own)
        (codeP, out, _) <- readProcessWithExitCode logger ["--print-program"] ""
        (codeP, take 1 out, drop (length out - 2) out, length (lines out)) `shouldBe` (ExitSuccess, "\"", "\"\n", 1)
        readFile kept `shouldReturn` "precious user data\n"

    it "a run that writes no result is filed under its setting when a parameter holds a control character (a tab was a space there: a setting of its own)" $ withTempDir $ \dir -> do
      requireParallel
      prog <- failingSeed2 dir
      sweep <- script "sweep"
      (code, _, _) <- runScriptCode [] sweep ["--seeds", "1..2", "--param", "note=a\tb", prog, dir </> "r.jsonl", "--", "--seconds", "1"]
      code `shouldBe` ExitFailure 1
      rs <- map parsed . lines <$> readFile (dir </> "r.jsonl")
      map (field ["params"]) rs `shouldBe` replicate 2 (JObject [("note", JString "a\tb")])
      table <- merged dir [dir </> "r.jsonl"]
      filter ("== " `isPrefixOf`) (lines table) `shouldBe` ["== world=program note=\"a\\tb\"  (2 runs, 1 failed)"]

    it "a run that writes no result is filed under the world and parameters it got after --, the job line's winning (it was filed under the job line's alone)" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sweep <- script "sweep"
      let world = dir </> "w.world"
      writeFile world "simbotA 1 at 0 0 heading 0 deg\n"
      -- (the second job line's run stops before it runs, at a parameter
      -- it cannot read: the sweep's own check reads the first line's)
      writeFile (dir </> "jobs") "--seed 1 --param speed=2\n--seed 2 --param speed=2 --param ratio=1%0\n"
      (code, _, _) <- runScriptCode [] sweep [ "--jobs", dir </> "jobs", prog, dir </> "r.jsonl"
                                             , "--", "--seconds", "1", "--world", world, "--param", "speed=3"
                                             , "--param", "k=a" ]
      code `shouldBe` ExitFailure 1
      [_, line] <- lines <$> readFile (dir </> "r.jsonl")
      field ["world"] (parsed line) `shouldBe` JString world
      field ["params"] (parsed line) `shouldBe` JObject [("speed", JString "2"), ("k", JString "a"), ("ratio", JString "1%0")]
      table <- merged dir [dir </> "r.jsonl"]
      table `shouldSatisfy` ("k=a ratio=1%0 speed=2  (1 runs, 1 failed)" `isInfixOf`)

    it "a world file named default is ./default on a run's result line and on the sweep's line for a run with no result (both said \"default\", the built-in world's name)" $ withTempDir $ \dir -> do
      requireParallel
      prog <- failingSeed2 dir
      sweep <- script "sweep"
      writeFile (dir </> "default") "simbotA 1 at 0 0 heading 0 deg\n"
      writeFile (dir </> "jobs") "--seed 1 --world default\n--seed 2 --world default\n--seed 3\n"
      (code, _, _) <- readCreateProcessWithExitCode
        (proc "bash" [sweep, "--jobs", dir </> "jobs", prog, dir </> "r.jsonl", "--", "--seconds", "1"]) { cwd = Just dir } ""
      code `shouldBe` ExitFailure 1
      rs <- map parsed . lines <$> readFile (dir </> "r.jsonl")
      map (field ["world"]) rs `shouldBe` [JString "./default", JString "./default", JString "program"]
      table <- merged dir [dir </> "r.jsonl"]
      filter ("== " `isPrefixOf`) (lines table) `shouldBe` ["== world=./default  (2 runs, 1 failed)", "== world=program  (1 runs, 0 failed)"]

    it "reads --shard and --seeds in decimal (010 is ten), and refuses what would run the wrong jobs" $ withTempDir $ \dir -> do
      sweep <- script "sweep"
      sbatch <- script "sweep.sbatch"
      let listed args = do
            (code, out, _) <- runScriptCode [] sweep ("--list" : args)
            pure (code, lines out)
      listed ["--seeds", "0..11", "--shard", "1/08"] `shouldReturn` (ExitSuccess, ["--seed 1", "--seed 9"])
      listed ["--seeds", "0..11", "--shard", "0/010"] `shouldReturn` (ExitSuccess, ["--seed 0", "--seed 10"])
      listed ["--seeds", "008..010"] `shouldReturn` (ExitSuccess, ["--seed 8", "--seed 9", "--seed 10"])
      -- a shard with no job (an array of more tasks than jobs) is no error
      listed ["--seeds", "1..4", "--shard", "5/8"] `shouldReturn` (ExitSuccess, [])
      -- refused with exit code 2 and a message: a range too long to list,
      -- an empty job list, -j that is not a number, a flag after -- with a
      -- space (runs' flags are split on spaces), a results file in no folder
      let refused args what = do
            (code, _, err) <- runScriptCode [] sweep args
            (code, what `isInfixOf` err) `shouldBe` (ExitFailure 2, True)
      refused ["--list", "--seeds", "0..9999999999"] "more than a million seeds"
      refused ["--seeds", "5..1", "prog", dir </> "r.jsonl"] "the job list is empty: --seeds 5..1 runs backwards"
      -- (--list refuses an empty list as the sweep does: it printed
      -- nothing and exited 0)
      forM_ [("3..1", "1..3"), ("1..0", "0..1"), ("-1..-3", "-3..-1")] $ \(range, upwards) ->
        refused ["--list", "--seeds", range] ("--seeds " ++ range ++ " runs backwards, and a range A..B counts up from A to B (write "
                                              ++ upwards ++ ")")
      writeFile (dir </> "comments") "# only a comment\n\n"
      refused ["--list", "--jobs", dir </> "comments"] "the job list is empty: the jobs file"
      refused ["-j", "abc", "prog", dir </> "r.jsonl"] "-j expects a number"
      refused ["prog", dir </> "r.jsonl", "--", "--world", "a b.world"] "cannot hold a space"
      prog <- childScript dir "program"
      refused [prog, dir </> "no" </> "r.jsonl"] "no folder"
      -- a job array with a step would skip shards
      (code, _, err) <- runScriptCode [ ("SLURM_ARRAY_TASK_ID", "2"), ("SLURM_ARRAY_TASK_COUNT", "4")
                                      , ("SLURM_ARRAY_TASK_MIN", "0"), ("SLURM_ARRAY_TASK_MAX", "6") ]
                                      sbatch [dir </> "out", prog, "--seeds", "0..7"]
      (code, "not contiguous" `isInfixOf` err) `shouldBe` (ExitFailure 2, True)

    it "refuses a run listed twice, a --param given twice or with an empty value, an empty --shard; reads CR LF lines (all were taken)" $
      withTempDir $ \dir -> do
        sweep <- script "sweep"
        let refused args what = do
              (code, _, err) <- runScriptCode [] sweep ("--list" : args)
              (code, what `isInfixOf` err) `shouldBe` (ExitFailure 2, True)
            listed args = do
              (code, out, _) <- runScriptCode [] sweep ("--list" : args)
              pure (code, lines out)
        -- (sweep-merge refuses a run merged twice, after the whole sweep)
        refused ["--seeds", "1,2,01"] "names the seed 1 twice"
        refused ["--seeds", "1", "--worlds", "a.world,b.world,a.world"] "names the world a.world twice"
        refused ["--param", "speed=0.5,1,0.5"] "names the value 0.5 twice"
        refused ["--param", "speed=0.5", "--param", "speed=1"] "--param speed is given twice"
        forM_ ["speed=,0.5", "speed=0.5,", "speed=", "speed=1,,2"] $ \p -> refused ["--param", p] "a value is empty"
        refused ["--seeds", "1..3", "--shard", ""] "--shard expects I/N"
        writeFile (dir </> "jobs") (unlines ["--seed 1 --param a=1", "--seed 2", "--seed  1\t--param a=1 ", "--seed 'x y'", "--seed 'x y'"])
        (code, _, err) <- runScriptCode [] sweep ["--list", "--jobs", dir </> "jobs"]
        code `shouldBe` ExitFailure 2
        lines err `shouldBe` map (\(k, j) -> "sweep: " ++ dir </> "jobs" ++ ": line " ++ show k ++ " is line " ++ show j
                                          ++ " again: each run may be in the list once (scripts/sweep-merge refuses a run merged twice)")
                                 [(3 :: Int, 1 :: Int), (5, 4)]
        -- (the line numbers counted past comments and blank lines; a line of
        -- form feeds or of two CRs is blank, as the sweep skips it)
        writeFile (dir </> "blanks") "# a\n\n--seed 1\n\f\n \n--seed 2\n\r\r\n--seed  1\n\f\n"
        (code', _, err') <- runScriptCode [] sweep ["--list", "--jobs", dir </> "blanks"]
        code' `shouldBe` ExitFailure 2
        lines err' `shouldBe` ["sweep: " ++ dir </> "blanks" ++ ": line 8 is line 3 again: each run may be in the list once"
                               ++ " (scripts/sweep-merge refuses a run merged twice)"]
        -- lines ending in CR LF (a jobs file written on Windows)
        writeFile (dir </> "crlf") "--seed 1 --param a=1\r\n# a comment\r\n\r\n--seed 2\r\n"
        listed ["--jobs", dir </> "crlf"] `shouldReturn` (ExitSuccess, ["--seed 1 --param a=1", "--seed 2"])
        -- a UTF-8 byte order mark (Notepad's) is no part of the first line,
        -- as in a world file (its run stopped at the flag "\65279--seed",
        -- and its failure line said seed 0); a NUL is refused (the rest of
        -- its line was dropped unsaid: the run ran without its --param)
        B.writeFile (dir </> "bom") (B.pack [0xEF, 0xBB, 0xBF] `B.append` BC.pack "--seed 1\r\n--seed 2\r\n")
        listed ["--jobs", dir </> "bom"] `shouldReturn` (ExitSuccess, ["--seed 1", "--seed 2"])
        B.writeFile (dir </> "nul") (BC.pack "--seed 1\n--seed 2\NUL --param a=1\n")
        refused ["--jobs", dir </> "nul"] "holds a NUL byte"
        -- what stays accepted: one parameter's values, two parameters
        listed ["--seeds", "1", "--param", "a=1,2", "--param", "b=x"]
          `shouldReturn` (ExitSuccess, ["--seed 1 --param a=1 --param b=x", "--seed 1 --param a=2 --param b=x"])
    it "a program whose answer to a question before the runs is long: its message of 200,000 lines cut to 20, exit code 2 (it was 141, SIGPIPE, at random); a name printed on and on cut at 64 KiB as it is written (it filled the disk for 30 s)" $ withTempDir $ \dir -> do
      sweep <- script "sweep"
      let noisy = dir </> "noisy.sh"
      writeScript noisy (unlines [ "#!/bin/bash"
                                 , "case \" $* \" in"
                                 , "  *' --dump-world '*) seq 1 200000 >&2; exit 2 ;;"
                                 , "  *' --print-program '*) exec yes ;;"
                                 , "esac"
                                 , "exit 3" ])
      forM_ [1 :: Int .. 3] $ \_ -> do
        (code, _, err) <- runScriptCode [] sweep ["--seeds", "1", noisy, dir </> "r.jsonl", "--", "--seconds", "1"]
        (code, take 3 (drop 1 (dropWhile (not . ("the program stops before it runs" `isInfixOf`)) (lines err))))
          `shouldBe` (ExitFailure 2, ["1", "2", "3"])
        length (lines err) `shouldBe` 21
      (code, _, err) <- runScriptCode [] sweep ["--seeds", "1", noisy, dir </> "r.jsonl"]
      code `shouldBe` ExitFailure 1
      err `shouldSatisfy` ("note: the program did not print its name for --print-program (exit code 141)" `isInfixOf`)
    it "reads a Char literal as one character in the C locale too: an e acute's literal and ',' are two values (the C locale saw four bytes and no literal, and split it in three)" $ withTempDir $ \dir -> do
      sweep <- script "sweep"
      let lister = dir </> "list.sh"
      -- (the bytes of é in UTF-8 written by the shell, whatever this
      -- program's locale)
      writeScript lister (unlines [ "#!/bin/bash", "exec bash '" ++ sweep ++ "' --list --param \"c='\"$'\\xc3\\xa9'\"',','\"" ])
      (code, out, err) <- runScriptCode [("LC_ALL", "C"), ("LANG", "C")] lister []
      (code, length (lines out), err) `shouldBe` (ExitSuccess, 2, "")
      lines out !! 1 `shouldBe` "--seed 0 --param 'c='\\'','\\'''"
    it "refuses, before any run, flags after -- that the program stops at (--seconds abc: every run failed)" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sweep <- script "sweep"
      (code, _, err) <- runScriptCode [] sweep ["--seeds", "1..3", prog, dir </> "r.jsonl", "--", "--seconds", "abc"]
      code `shouldBe` ExitFailure 2
      err `shouldSatisfy` ("the program stops before it runs with the flags after -- (--seconds abc)" `isInfixOf`)
      err `shouldSatisfy` (": --seconds expects a non-negative number" `isInfixOf`)
      doesFileExist (dir </> "r.jsonl") `shouldReturn` False
      -- (and a --param after -- that the program cannot read)
      (code', _, err') <- runScriptCode [] sweep ["--seeds", "1", prog, dir </> "r.jsonl", "--", "--param", "speed=fast"]
      code' `shouldBe` ExitFailure 2
      err' `shouldSatisfy` ("cannot read the value \"fast\"" `isInfixOf`)
      doesFileExist (dir </> "r.jsonl") `shouldReturn` False
      -- but a job line's own bad value fails that run alone: the others run
      (code'', _, _) <- runScriptCode [] sweep ["--seeds", "1", "--param", "speed=fast,0.1", prog, dir </> "r.jsonl"
                                               , "--", "--seconds", "1"]
      code'' `shouldBe` ExitFailure 1
      rs <- map parsed . lines <$> readFile (dir </> "r.jsonl")
      map (\r -> field ["params"] r) rs `shouldBe` [JObject [("speed", JString v)] | v <- ["fast", "0.1"]]
      map (\r -> either (const False) (const True) (member "outcome" r)) rs `shouldBe` [False, True]

    it "shows a run's warning (a --param the program never asks for) once, and counts the runs that warned (it swallowed them)" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sweep <- script "sweep"
      (code, _, err) <- runScriptCode [] sweep ["-j", "2", "--seeds", "1..2", "--param", "sped=0.2,0.5", prog, dir </> "r.jsonl"
                                               , "--", "--seconds", "1"]
      code `shouldBe` ExitSuccess
      let named = "asked for no parameter named \"sped\""
      length (filter (named `isInfixOf`) (lines err)) `shouldBe` 1
      err `shouldSatisfy` ("4 of 4 runs printed warnings" `isInfixOf`)
      length . lines <$> readFile (dir </> "r.jsonl") `shouldReturn` 4
      -- (a parameter the program reads: no warning)
      (code', _, err') <- runScriptCode [] sweep ["--seeds", "1..2", "--param", "speed=0.2", prog, dir </> "r2.jsonl"
                                                 , "--", "--seconds", "1"]
      code' `shouldBe` ExitSuccess
      err' `shouldNotSatisfy` ("warning" `isInfixOf`)

    it "finds a cabal executable of the current folder's project by its name (it looked in afrp's only)" $ withTempDir $ \dir -> do
      requireParallel
      -- (a user's project beside afrp: its program where cabal builds it)
      let binDir = dir </> "dist-newstyle/build/x86_64-linux/ghc-9.0.2/my-robot-0.1.0.0/x/my-robot/build/my-robot"
      createDirectoryIfMissing True binDir
      program <- childScript dir "program"
      let prog = binDir </> "my-robot"
      copyFile program prog
      sweep <- script "sweep"
      let run = readCreateProcessWithExitCode (proc "bash" [sweep, "--seeds", "1..2", "my-robot", "r.jsonl", "--", "--seconds", "1"])
                  { cwd = Just dir } ""
      (code, _, err) <- run
      (code, err) `shouldBe` (ExitSuccess, "sweep: 2 runs, 0 failed; results in r.jsonl\n")
      rs <- lines <$> readFile (dir </> "r.jsonl")
      length rs `shouldBe` 2
      -- (and a name found nowhere is still refused)
      (code', _, err') <- readCreateProcessWithExitCode (proc "bash" [sweep, "--seeds", "1", "no-such-robot", "r2.jsonl"])
                            { cwd = Just dir } ""
      code' `shouldBe` ExitFailure 2
      err' `shouldSatisfy` ("no-such-robot is neither a path, a command, nor a built cabal executable" `isInfixOf`)

    it "counts as failed only the runs that failed, keeps job lines unexpanded, writes valid lines for odd seeds" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sweep <- script "sweep"
      -- files a job line's * would match, were it expanded as a pattern
      writeFile (dir </> "k=yyy") ""
      writeFile (dir </> "k=zzz") ""
      writeFile (dir </> "jobs") (unlines
        [ "--seed 1 --param flags=a --param failure=nan", "--seed 2 --param k=*", "--seed 007 --no-such-flag" ])
      (code, _, err) <- readCreateProcessWithExitCode
        (proc "bash" [sweep, "--jobs", dir </> "jobs", prog, dir </> "r.jsonl", "--", "--seconds", "1"]) { cwd = Just dir } ""
      (code, "3 runs, 1 failed" `isInfixOf` err) `shouldBe` (ExitFailure 1, True)
      ls <- lines <$> readFile (dir </> "r.jsonl")
      map (field ["params"] . parsed) (take 2 ls)
        `shouldBe` [JObject [("flags", JString "a"), ("failure", JString "nan")], JObject [("k", JString "*")]]
      field ["seed"] (parsed (ls !! 2)) `shouldBe` JNumber 7
      table <- merged dir [dir </> "r.jsonl"]
      table `shouldSatisfy` ("FAILED seed 7: exit code 2, no result" `isInfixOf`)

    it "writes the seed of a run with no result as the run reads it, a number (--seed 007 was \"007\", which the merge did not match with the run's result line, seed 7)" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sweep <- script "sweep"
      writeFile (dir </> "jobs") (unlines
        [ "--seed 007 --no-such-flag", "--seed +8 --no-such-flag", "--seed 9007199254740992 --no-such-flag"
        , "--seed 09007199254740993 --no-such-flag", "--seed abc --no-such-flag", "--param speed=2 --no-such-flag"
        , "--seed -005 --no-such-flag", "--seed -0 --param speed=3 --no-such-flag" ])
      (code, _, _) <- runScriptCode [] sweep ["--jobs", dir </> "jobs", prog, dir </> "r.jsonl", "--", "--seconds", "1"]
      code `shouldBe` ExitFailure 1
      ls <- lines <$> readFile (dir </> "r.jsonl")
      map (field ["seed"] . parsed) ls `shouldBe`
        [ JNumber 7, JNumber 8, JNumber 9007199254740992, JString "09007199254740993", JString "abc"
        , JNumber 0, JNumber (-5), JNumber 0 ]
      -- the run of seed 7 rerun, with its result line: the same run twice
      (code7, _, line7) <- runOnce dir ["--seconds", "1", "--seed", "7"]
      code7 `shouldBe` ExitSuccess
      writeFile (dir </> "rerun.jsonl") line7
      merger <- childScript dir "merge"
      (codeM, out, err) <- readProcessWithExitCode merger [dir </> "r.jsonl", dir </> "rerun.jsonl"] ""
      (codeM, out) `shouldBe` (ExitFailure 1, "")
      err `shouldSatisfy` ("afrp-sweep-merge: the run world=program seed 7 is on a line for a run with no result and on a result line too" `isPrefixOf`)

    it "refuses a RESULTS that is a world, the jobs file or the program, under any name, before writing anything" $ withTempDir $ \dir -> do
      prog <- childScript dir "program"
      sweep <- script "sweep"
      let world = dir </> "my.world"
          keep = "the world, which must not be emptied\n"
      writeFile world keep
      writeFile (dir </> "jobs") "--seed 1\n"
      writeFile (dir </> "world-jobs") ("--seed 1 --world " ++ world ++ "\n")
      createFileLink world (dir </> "link.jsonl")
      _ <- readProcess "ln" [world, dir </> "hard.jsonl"] ""
      let refused args what = do
            (code, _, err) <- runScriptCode [] sweep args
            (code, what `isInfixOf` err, "would be emptied" `isInfixOf` err) `shouldBe` (ExitFailure 2, True, True)
            readFile world `shouldReturn` keep
      forM_ [world, dir </> "link.jsonl", dir </> "hard.jsonl"] $ \results -> do
        refused ["--seeds", "1..2", "--worlds", world, prog, results, "--", "--seconds", "1"] "is the world"
        refused ["--jobs", dir </> "world-jobs", prog, results] "is the world"
        refused [prog, results, "--", "--world", world] "is the world"
      refused ["--jobs", dir </> "jobs", prog, dir </> "jobs"] "is the jobs file"
      readFile (dir </> "jobs") `shouldReturn` "--seed 1\n"
      refused [prog, prog] "is the program"
      readFile prog >>= (`shouldSatisfy` (childVariable `isInfixOf`))

    it "RESULTS that cannot be written (/dev/full): exit 1 at once, saying so" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      sweep <- script "sweep"
      -- (timeout ends the whole sweep, should it hang)
      (code, _, err) <- readProcessWithExitCode "timeout" ["120", "bash", sweep, "--seeds", "1..3", prog, "/dev/full", "--", "--seconds", "1"] ""
      code `shouldBe` ExitFailure 1
      err `shouldSatisfy` ("could not write the results to /dev/full (No space left on device)" `isInfixOf`)
      err `shouldNotSatisfy` ("0 failed" `isInfixOf`)

    it "refuses flags after -- that make every run write the same file or print and exit, and a file two job lines write" $ withTempDir $ \dir -> do
      prog <- childScript dir "program"
      sweep <- script "sweep"
      let results = dir </> "r.jsonl"
          refused args what = do
            (code, _, err) <- runScriptCode [] sweep args
            (code, what `isInfixOf` err) `shouldBe` (ExitFailure 2, True)
            doesFileExist results `shouldReturn` False
      forM_ [["--log", dir </> "run.jsonl"], ["--svg", dir </> "run.svg"], ["--replay", dir </> "run.html"], ["--video", dir </> "run.mp4"]] $ \flags ->
        refused (["--seeds", "1..2", prog, results, "--", "--seconds", "1"] ++ flags) "would make every run write the same file"
      forM_ [["--out", dir </> "out"], ["--frames"]] $ \flags ->
        refused (["--seeds", "1..2", prog, results, "--", "--seconds", "1"] ++ flags) "into the same folder"
      refused ["--seeds", "1..2", prog, results, "--", "--result", dir </> "x.json"] "sweep writes each run's result line itself"
      -- (and flags that make every run print and exit, with no result)
      forM_ ["--help", "-h", "--dump-world", "--print-program"] $ \flag ->
        refused ["--seeds", "1..2", prog, results, "--", flag] (flag ++ " after -- would make every run print and exit")
      let jobs ls = writeFile (dir </> "jobs") (unlines ls) >> pure ["--jobs", dir </> "jobs", prog, results, "--", "--seconds", "1"]
      jobs ["--seed 1 --log a.jsonl", "--seed 2 --log b.jsonl", "--seed 3 --log a.jsonl"]
        >>= \args -> refused args ("jobs: line 3: --log a.jsonl: " ++ dir </> "jobs: line 1 writes it too")
      jobs ["--seed 1 --frames", "--seed 2 --frames --out f2", "--seed 3 --frames"]
        >>= \args -> refused args "jobs: line 3: --frames into simbot-out"
      jobs ["--seed 1 --result x.json"] >>= \args -> refused args "jobs: line 1: --result: sweep writes each run's result line itself"
      forM_ ["--help", "-h", "--dump-world", "--print-program"] $ \flag ->
        jobs ["--seed 1 " ++ flag] >>= \args -> refused args ("jobs: line 1: " ++ flag ++ ": the run would print and exit, with no result")
      jobs ["--seed 1 --log --print-program"] >>= \args -> refused args "jobs: line 1: --log needs a value, found the flag --print-program"
      jobs ["--seed 1 --world --print-program"] >>= \args -> refused args "--world needs a value, found the flag --print-program"
      jobs ["--seed 1 --log " ++ results] >>= \args -> refused args "is a file that a run writes too"
      -- a file of its own for each run is what a jobs file is for
      requireParallel
      args <- jobs ["--seed 1 --log " ++ dir </> "a.jsonl", "--seed 2 --log " ++ dir </> "b.jsonl"]
      _ <- runScript [] sweep args
      mapM (doesFileExist . (dir </>)) ["a.jsonl", "b.jsonl"] `shouldReturn` [True, True]
      length . lines <$> readFile results `shouldReturn` 2

    it "refuses, before any run, a job's output that is the jobs file, the program, or a world or run log a job reads (under any name)" $ withTempDir $ \dir -> do
      prog <- childScript dir "program"
      sweep <- script "sweep"
      (dumped, worldText, _) <- readProcessWithExitCode prog ["--dump-world"] ""
      dumped `shouldBe` ExitSuccess
      let results = dir </> "r.jsonl"
          jobs = dir </> "jobs"
          keep = [("w1.world", worldText), ("w2.world", worldText), ("run.jsonl", "a run log\n")]
      forM_ keep $ \(f, t) -> writeFile (dir </> f) t
      createFileLink (dir </> "w2.world") (dir </> "link.jsonl")
      let refused ls what = do
            writeFile jobs (unlines ls)
            (code, _, err) <- runScriptCode [] sweep ["--jobs", jobs, prog, results, "--", "--seconds", "1"]
            (code, what `isInfixOf` err) `shouldBe` (ExitFailure 2, True)
            readFile' jobs `shouldReturn` unlines ls
            forM_ keep $ \(f, t) -> readFile' (dir </> f) `shouldReturn` t
            doesFileExist results `shouldReturn` False
      refused ["--seed 1", "--seed 2 --svg " ++ jobs] (jobs ++ ": line 2: --svg " ++ jobs ++ " would overwrite the jobs file " ++ jobs)
      refused ["--seed 1 --world " ++ dir </> "w1.world", "--seed 2 --svg " ++ dir </> "w1.world"]
              (jobs ++ ": line 2: --svg " ++ dir </> "w1.world would overwrite the world file " ++ dir </> "w1.world (read by " ++ jobs ++ ": line 1)")
      refused ["--seed 1 --world " ++ dir </> "w2.world", "--seed 2 --log " ++ dir </> "link.jsonl"]
              (jobs ++ ": line 2: --log " ++ dir </> "link.jsonl would overwrite the world file " ++ dir </> "w2.world")
      refused ["--seed 1 --replay-from " ++ dir </> "run.jsonl --replay " ++ dir </> "p.html"
              , "--seed 2 --frames --out " ++ dir </> "f2 --video " ++ dir </> "." </> "run.jsonl"]
              (jobs ++ ": line 2: --video " ++ dir </> "./run.jsonl would overwrite the run log " ++ dir </> "run.jsonl")
      refused ["--seed 1 --log " ++ prog] (jobs ++ ": line 1: --log " ++ prog ++ " would overwrite the program " ++ prog)

    it "refuses a file two job lines write under two spellings (a and ./a, a folder with and without /, a hard link); not a device" $ withTempDir $ \dir -> do
      prog <- childScript dir "program"
      sweep <- script "sweep"
      writeFile (dir </> "old.jsonl") "an old log\n"
      _ <- readProcess "ln" [dir </> "old.jsonl", dir </> "hard.jsonl"] ""
      let results = dir </> "r.jsonl"
          jobs = dir </> "jobs"
          sweepIn ls args = do
            writeFile jobs (unlines ls)
            readCreateProcessWithExitCode (proc "bash" ([sweep, "--jobs", jobs] ++ args)) { cwd = Just dir } ""
          refused ls what = do
            (code, _, err) <- sweepIn ls [prog, results, "--", "--seconds", "1"]
            (code, what `isInfixOf` err) `shouldBe` (ExitFailure 2, True)
            doesFileExist results `shouldReturn` False
      refused ["--seed 1 --log L.jsonl", "--seed 2 --log ./L.jsonl"] (jobs ++ ": line 2: --log ./L.jsonl: " ++ jobs ++ ": line 1 writes it too")
      refused ["--seed 1 --frames --out od2", "--seed 2 --frames --out od2/"]
              (jobs ++ ": line 2: --frames into od2/: " ++ jobs ++ ": line 1 writes its frames there too")
      refused ["--seed 1 --log old.jsonl", "--seed 2 --svg hard.jsonl"] (jobs ++ ": line 2: --svg hard.jsonl: " ++ jobs ++ ": line 1 writes it too")
      refused ["--seed 1 --log L.jsonl --svg " ++ dir </> "L.jsonl"] (jobs ++ ": line 1: --log L.jsonl and --svg " ++ dir </> "L.jsonl are the same file")
      readFile' (dir </> "old.jsonl") `shouldReturn` "an old log\n"
      -- a device is not a file to keep: /dev/null on every line is no clash
      (code, out, err) <- sweepIn ["--seed 1 --log /dev/null", "--seed 2 --log /dev/null"] ["--list"]
      (code, lines out, err) `shouldBe` (ExitSuccess, ["--seed 1 --log /dev/null", "--seed 2 --log /dev/null"], "")

    it "refuses, before any run, what each run would stop at: an input not there, an output in no folder, a flag with no value" $ withTempDir $ \dir -> do
      prog <- childScript dir "program"
      sweep <- script "sweep"
      real <- canonicalizePath dir
      createDirectory (dir </> "adir")
      writeFile (dir </> "jobs") (unlines
        [ "--seed 1 --world " ++ dir </> "none.world"
        , "--seed 2 --log " ++ dir </> "no" </> "run.jsonl"
        , "--seed 3 --svg " ++ dir </> "adir"
        , "--seed 4 --log"
        , "--seed 5 --log --seed 6"
        , "--seed 6 --video " ++ dir </> "v.mp4"
        , "--seed 7 --replay-from " ++ dir </> "none.jsonl --replay " ++ dir </> "p.html"
        , "--seed 8 --frames --out " ++ dir </> "no" </> "frames"
          -- (the run makes its own --out folder: no fault)
        , "--seed 9 --log " ++ dir </> "new" </> "run.jsonl --out " ++ dir </> "new" ])
      (code, _, err) <- runScriptCode [] sweep ["--jobs", dir </> "jobs", prog, dir </> "r.jsonl", "--", "--seconds", "1"]
      code `shouldBe` ExitFailure 2
      let faults = [ (1, "--world " ++ dir </> "none.world: no such file")
                   , (2, "--log " ++ dir </> "no" </> "run.jsonl: no folder " ++ real </> "no")
                   , (3, "--svg " ++ dir </> "adir: it is a folder")
                   , (4, "--log needs a value")
                   , (5, "--log needs a value, found the flag --seed")
                   , (6, "--video needs the frames (add --frames)")
                   , (7, "--replay-from " ++ dir </> "none.jsonl: no such file")
                   , (8, "--frames into " ++ dir </> "no" </> "frames: no folder " ++ real </> "no") ]
      [ k | (k, what) <- faults, not ((dir </> "jobs: line " ++ show (k :: Int) ++ ": " ++ what) `isInfixOf` err) ] `shouldBe` []
      err `shouldNotSatisfy` ("line 9" `isInfixOf`)
      doesFileExist (dir </> "r.jsonl") `shouldReturn` False

    it "refuses a flag with no value on every job line, one that names no file too (--seed 1 --seconds was run, and failed)" $ withTempDir $ \dir -> do
      sweep <- script "sweep"
      writeFile (dir </> "jobs") (unlines ["--seed 1 --seconds", "--seed 2 --seed --quiet", "--seed 3 --keys", "--seed 4 --dt 0.01"])
      (code, out, err) <- listedBy sweep ["--jobs", dir </> "jobs"]
      (code, out) `shouldBe` (ExitFailure 2, [])
      lines err `shouldBe` [ "sweep: " ++ dir </> "jobs: line " ++ show k ++ ": " ++ fault
                           | (k, fault) <- [ (1 :: Int, "--seconds needs a value"), (2, "--seed needs a value, found the flag --quiet")
                                           , (3, "--keys needs a value") ] ]

    it "refuses an empty flag after -- (split on spaces, it was lost: --seconds '' took the next flag for its value)" $ do
      sweep <- script "sweep"
      (code, out, err) <- listedBy sweep ["--seeds", "1", "--", "--seconds", "", "--quiet"]
      (code, out) `shouldBe` (ExitFailure 2, [])
      err `shouldSatisfy` ("a flag after -- cannot be empty" `isInfixOf`)

    it "--list prints every job line as it is (a line -n, -e or -E was taken for echo's option, and not printed)" $ withTempDir $ \dir -> do
      sweep <- script "sweep"
      writeFile (dir </> "jobs") (unlines ["-n", "--seed 1", "-e", "-E"])
      listedBy sweep ["--jobs", dir </> "jobs"] `shouldReturn` (ExitSuccess, ["-n", "--seed 1", "-e", "-E"], "")

    it "writes the line of a run with no result whose --param has no name or no = (--param =5 ended the sweep, its lines and summary unwritten)" $
      withTempDir $ \dir -> do
        requireParallel
        prog <- childScript dir "program"
        sweep <- script "sweep"
        writeFile (dir </> "jobs") (unlines ["--seed 1", "--seed 2 --param =5", "--seed 3 --param speed"])
        (code, _, err) <- runScriptCode [] sweep ["--jobs", dir </> "jobs", prog, dir </> "r.jsonl", "--", "--seconds", "0.1"]
        (code, "3 runs, 2 failed" `isInfixOf` err) `shouldBe` (ExitFailure 1, True)
        rs <- map parsed . lines <$> readFile (dir </> "r.jsonl")
        map (field ["seed"]) rs `shouldBe` map JNumber [1, 2, 3]
        -- (the pairs the runs refused name no parameter)
        map (field ["params"]) (drop 1 rs) `shouldBe` replicate 2 (JObject [])

    it "checks --jobs, --seeds and --worlds up front, and runs worlds and parameters with spaces" $ withTempDir $ \dir -> do
      sweep <- script "sweep"
      let refused args what = do
            (code, _, err) <- runScriptCode [] sweep args
            (code, what `isInfixOf` err) `shouldBe` (ExitFailure 2, True)
      refused ["--list", "--jobs", dir] "is a folder"
      forM_ ["", "abc", "1,,2", "1,", ",1", "1..x", "1;2"] $ \seedList ->
        refused ["--list", "--seeds", seedList] "--seeds expects"
      forM_ ["", "a.world,,b.world", "a.world,"] $ \worldList ->
        refused ["--list", "--worlds", worldList] "--worlds expects"
      writeFile (dir </> "jobs") (unlines ["--seed 1", "--seed 2 --world 'a b.world", "--seed 3"])
      refused ["--list", "--jobs", dir </> "jobs"] "jobs: line 2: a ' is not closed"
      -- (with the other lines' faults: only the quote's was said)
      writeFile (dir </> "jobs") (unlines ["--seed 1 --seconds", "--seed 2 --world 'a b.world", "--seed 3 --dt"])
      (codeQ, _, errQ) <- runScriptCode [] sweep ["--list", "--jobs", dir </> "jobs"]
      (codeQ, filter ("jobs: line " `isInfixOf`) (lines errQ)) `shouldBe`
        (ExitFailure 2, [ "sweep: " ++ dir </> "jobs" ++ ": line 1: --seconds needs a value"
                        , "sweep: " ++ dir </> "jobs" ++ ": line 2: a ' is not closed (a job line's words are separated by spaces, and quoted as in a shell: '...', \"...\", \\)"
                        , "sweep: " ++ dir </> "jobs" ++ ": line 3: --dt needs a value" ])
      -- what is accepted: spaces around a seed, leading zeros (decimal)
      (code, out, _) <- runScriptCode [] sweep ["--list", "--seeds", "1, 010,-2"]
      (code, lines out) `shouldBe` (ExitSuccess, ["--seed 1", "--seed 10", "--seed -2"])
      -- a world and a parameter with a space, from --worlds and --param and from a jobs file
      requireParallel
      prog <- childScript dir "program"
      createDirectory (dir </> "my worlds")
      let world = dir </> "my worlds" </> "it's a.world"
      (dumped, worldText, _) <- readProcessWithExitCode prog ["--dump-world"] ""
      dumped `shouldBe` ExitSuccess
      writeFile world worldText
      writeFile (dir </> "jobs") ("--seed 3 --world '" ++ replace "'" "'\\''" world ++ "' --param \"note=a \\\"b\\\"\"\n")
      _ <- runScript [] sweep ["--seeds", "1..2", "--worlds", world, "--param", "note=x y,z", prog, dir </> "r.jsonl", "--", "--seconds", "1"]
      _ <- runScript [] sweep ["--jobs", dir </> "jobs", prog, dir </> "j.jsonl", "--", "--seconds", "1"]
      rs <- map parsed . concatMap lines <$> mapM readFile [dir </> "r.jsonl", dir </> "j.jsonl"]
      map (field ["world"]) rs `shouldBe` replicate 5 (JString world)
      map (field ["outcome", "failure"]) rs `shouldBe` replicate 5 JNull
      map (field ["seed"]) rs `shouldBe` map JNumber [1, 2, 1, 2, 3]
      map (field ["params", "note"]) rs `shouldBe` map JString ["x y", "x y", "z", "z", "a \"b\""]

    it "takes \\, as a comma within a --param value or a --worlds name, and refuses a value whose quote a comma split (it was run as two values)" $
      withTempDir $ \dir -> do
        sweep <- script "sweep"
        let listed = listedBy sweep
        -- (a comma inside quotes, not escaped: refused, naming the value
        -- and the escape; it listed mode="a and mode=b" and exited 0)
        (code, out, err) <- listed ["--seeds", "1,2", "--param", "mode=\"a,b\""]
        (code, out) `shouldBe` (ExitFailure 2, [])
        err `shouldSatisfy` ("--param mode=\"a,b\": the value \"a has a \" that is not closed" `isInfixOf`)
        err `shouldSatisfy` ("write a comma within a value as \\," `isInfixOf`)
        -- \, is a comma; every other \ is as it is, \\ too (a Haskell
        -- string's backslash: "C:\\dir" as written, where it became the
        -- "C:\dir" that read refuses; and "a\\" before a comma, which was
        -- refused)
        listed ["--param", "mode=\"a\\,b\",c", "--param", "p=\"C:\\\\dir\""] `shouldReturn`
          ( ExitSuccess
          , [ "--seed 0 --param 'mode=\"a,b\"' --param 'p=\"C:\\\\dir\"'"
            , "--seed 0 --param mode=c --param 'p=\"C:\\\\dir\"'" ]
          , "" )
        listed ["--param", "p=\"a\\\\\",b"] `shouldReturn`
          (ExitSuccess, ["--seed 0 --param 'p=\"a\\\\\"'", "--seed 0 --param p=b"], "")
        -- (one value alone is as given, a quote in it too; a quote escaped
        -- inside a Haskell string counts as no quote)
        listed ["--param", "note=5\""] `shouldReturn` (ExitSuccess, ["--seed 0 --param 'note=5\"'"], "")
        listed ["--param", "s=\"a\\\"b\",c"] `shouldReturn`
          (ExitSuccess, ["--seed 0 --param 's=\"a\\\"b\"'", "--seed 0 --param s=c"], "")
        -- (a comma escaped at either end is no empty value; a line break
        -- is refused, the job list being a run a line: the value was cut
        -- at it)
        listed ["--param", "a=\\,,x"] `shouldReturn` (ExitSuccess, ["--seed 0 --param a=,", "--seed 0 --param a=x"], "")
        (codeNl, _, errNl) <- listed ["--param", "a=x\ny,z"]
        (codeNl, "a value cannot hold a line break" `isInfixOf` errNl) `shouldBe` (ExitFailure 2, True)
        -- a world file whose name has a comma
        writeFile (dir </> "a,b.world") ""
        writeFile (dir </> "c.world") ""
        listed ["--worlds", dir </> "a\\,b.world," ++ dir </> "c.world"] `shouldReturn`
          (ExitSuccess, ["--seed 0 --world " ++ dir </> "a,b.world", "--seed 0 --world " ++ dir </> "c.world"], "")
        -- and a run gets the value with its comma
        requireParallel
        prog <- childScript dir "program"
        _ <- runScript [] sweep ["--param", "tag=\"a\\,b\",c", prog, dir </> "r.jsonl", "--", "--seconds", "0.1"]
        rs <- map parsed . lines <$> readFile (dir </> "r.jsonl")
        map (field ["params", "tag"]) rs `shouldBe` map JString ["\"a,b\"", "c"]

    it "reads a Char literal in a list of --param values as Haskell's read does: '\"' leaves no quote open (it was refused)" $
      withTempDir $ \dir -> do
        sweep <- script "sweep"
        let listed = listedBy sweep
            refusedOpen p = do
              (code, out, err) <- listed ["--param", p]
              (code, out, "that is not closed" `isInfixOf` err) `shouldBe` (ExitFailure 2, [], True)
        listed ["--param", "c='a','\"'"] `shouldReturn`
          (ExitSuccess, ["--seed 0 --param 'c='\\''a'\\'''", "--seed 0 --param 'c='\\''\"'\\'''"], "")
        -- (escaped, and in a value beside a string)
        (code, out, _) <- listed ["--param", "c='\\\"','\\\\',Just '\"'", "--param", "s=\"'\",\"x\" '\"'"]
        (code, length out) `shouldBe` (ExitSuccess, 6)
        -- what a comma leaves open is still refused: a string after a Char
        -- literal, and a quote after a name's ' (x' is a name: its " opens
        -- a string)
        refusedOpen "c='\"'\"a,b\""
        refusedOpen "c=x'\"',y"
        -- and a run gets the Char literals as given
        requireParallel
        prog <- childScript dir "program"
        _ <- runScript [] sweep ["--param", "tag='a','\"'", prog, dir </> "r.jsonl", "--", "--seconds", "0.1"]
        rs <- map parsed . lines <$> readFile (dir </> "r.jsonl")
        map (field ["params", "tag"]) rs `shouldBe` map JString ["'a'", "'\"'"]

    it "keeps the comma of a Char literal in a list of --param values, ',', in its value (it was split into ' and ', and refused as a value given twice)" $
      withTempDir $ \dir -> do
        sweep <- script "sweep"
        let listed = listedBy sweep
        listed ["--param", "c='a',','"] `shouldReturn`
          (ExitSuccess, ["--seed 0 --param 'c='\\''a'\\'''", "--seed 0 --param 'c='\\'','\\'''"], "")
        listed ["--param", "c=','"] `shouldReturn` (ExitSuccess, ["--seed 0 --param 'c='\\'','\\'''"], "")
        -- (where a Char literal starts, as Haskell's read reads it: not
        -- after a name's ', nor in a string; and '\,', the escaped comma,
        -- is one value as before)
        listed ["--param", "c=Just ',',x',','"] `shouldReturn`
          ( ExitSuccess, [ "--seed 0 --param 'c=Just '\\'','\\'''", "--seed 0 --param 'c=x'\\'''"
                         , "--seed 0 --param 'c='\\'','\\'''" ], "" )
        listed ["--param", "c='\\,','x'"] `shouldReturn`
          (ExitSuccess, ["--seed 0 --param 'c='\\'','\\'''", "--seed 0 --param 'c='\\''x'\\'''"], "")
        (code, out, err) <- listed ["--param", "c=\"a',','\""]
        (code, out, "that is not closed" `isInfixOf` err) `shouldBe` (ExitFailure 2, [], True)
        -- and a run gets the comma
        requireParallel
        prog <- childScript dir "program"
        _ <- runScript [] sweep ["--param", "tag='a',','", prog, dir </> "r.jsonl", "--", "--seconds", "0.1"]
        rs <- map parsed . lines <$> readFile (dir </> "r.jsonl")
        map (field ["params", "tag"]) rs `shouldBe` map JString ["'a'", "','"]

    it "interrupted (SIGTERM to its process group, as at Slurm's time limit): a line for every run, a message, no temporary file" $ withTempDir $ \dir -> do
      requireParallel
      prog <- childScript dir "program"
      -- two slots: seeds 1 and 2 end, 3 and 4 never do, 5 and 6 never start
      writeFile (dir </> "jobs") (unlines [ "--seed " ++ show k ++ " --seconds " ++ (if k `elem` [3, 4] then "100000" else "1")
                                          | k <- [1 .. 6 :: Int] ])
      let results = dir </> "r.jsonl"
      -- (ready when the sweep's temporary folder is there, so that its
      -- removal is seen, and two runs have ended)
      (code, err) <- sweepInterrupted dir prog "the first two runs did not end" $
        (&&) <$> (not . null <$> listDirectory (dir </> "tmp"))
             <*> ((>= 2) . length . lines <$> (doesFileExist results >>= \e -> if e then readFile' results else pure ""))
      code `shouldBe` Just (ExitFailure 143)
      err `shouldSatisfy` ("interrupted (SIGTERM): 2 of 6 runs ended" `isInfixOf`)
      rs <- map parsed . lines <$> readFile' results
      map (field ["seed"]) rs `shouldBe` map JNumber [1 .. 6]
      [ either (const Nothing) Just (member "outcome" r) /= Nothing | r <- rs ] `shouldBe` [True, True, False, False, False, False]
      forM_ (drop 2 rs) $ \r -> field ["failure"] r `shouldSatisfy` \f -> case f of
        JString t -> "interrupted (SIGTERM)" `isInfixOf` t
        _         -> False
      table <- merged dir [results]
      table `shouldSatisfy` ("(6 runs, 4 failed)" `isInfixOf`)
      listDirectory (dir </> "tmp") `shouldReturn` []

    it "interrupted before its runs (RESULTS, a pipe, waiting for a reader), leaves no temporary folder (the signal's default action ended it, the folder left behind)" $
      withTempDir $ \dir -> do
        requireParallel
        real <- childScript dir "program"
        sweep <- script "sweep"
        -- (the program says when it has answered the sweep's last question
        -- before the runs: then the sweep opens RESULTS, and waits there)
        let prog = dir </> "asked"
            results = dir </> "results.pipe"
        writeScript prog (unlines [ "#!/bin/bash"
                                  , "case \" $* \" in *' --print-program '*) '" ++ real ++ "' \"$@\"; s=$?; : > '" ++ dir </> "answered" ++ "'; exit $s ;; esac"
                                  , "exec '" ++ real ++ "' \"$@\"" ])
        _ <- readProcess "mkfifo" [results] ""
        createDirectory (dir </> "tmp")
        environment <- filter ((/= "TMPDIR") . fst) <$> getEnvironment
        (_, _, _, ph) <- createProcess (proc "bash" [sweep, "--seeds", "1", prog, results, "--", "--seconds", "0.1"])
          { env = Just (("TMPDIR", dir </> "tmp") : environment), std_err = CreatePipe }
        Just pid <- getPid ph
        let waitAnswered :: Int -> IO ()
            waitAnswered k = do
              done <- doesFileExist (dir </> "answered")
              unless (done || k <= 0) (threadDelay 100000 >> waitAnswered (k - 1))
        waitAnswered 600
        threadDelay 1000000
        signalProcess sigTERM pid
        -- (a reader, should the sweep still wait to open the pipe)
        _ <- readProcessWithExitCode "timeout" ["5", "cat", results] ""
        code <- timeout 60000000 (waitForProcess ph)
        unless (isJust code) (signalProcess sigKILL pid >> () <$ waitForProcess ph)
        code `shouldBe` Just (ExitFailure 143)
        listDirectory (dir </> "tmp") `shouldReturn` []

    it "interrupted, leaves no temporary folder even of a run that GNU parallel has to kill (one slow to end on SIGTERM)" $ withTempDir $ \dir -> do
      requireParallel
      createDirectory (dir </> "started")
      -- a program that says it has started, then takes 2 s to end on
      -- SIGTERM: GNU parallel sends SIGKILL 350 ms after its SIGTERM
      let prog = dir </> "slow"
          results = dir </> "r.jsonl"
      writeScript prog (unlines [ "#!/bin/bash"
                              , "case \" $* \" in *' --dump-world '*|*' --print-program '*) exit 0 ;; esac   # (the sweep's checks: of the flags, of the name)"
                              , "trap 'sleep 2; exit 143' TERM"
                              , ": > '" ++ dir </> "started" ++ "'/$$"
                              , "sleep 1000 & wait" ])
      writeFile (dir </> "jobs") "--seed 1\n--seed 2\n"
      (code, err) <- sweepInterrupted dir prog "the two runs did not start" $
        (&&) <$> (not . null <$> listDirectory (dir </> "tmp"))
             <*> ((>= 2) . length <$> listDirectory (dir </> "started"))
      code `shouldBe` Just (ExitFailure 143)
      err `shouldSatisfy` ("interrupted (SIGTERM): 0 of 2 runs ended" `isInfixOf`)
      map (field ["seed"]) . map parsed . lines <$> readFile' results `shouldReturn` map JNumber [1, 2]
      listDirectory (dir </> "tmp") `shouldReturn` []
