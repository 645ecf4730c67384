{-# LANGUAGE ScopedTypeVariables #-}
-- | 'runSimWith' run headless into temporary folders: frames, the world
-- file round trip, every reported fault, determinism.
module AFrobRobotSim.RunSpec (spec, childVariable, child) where

import           Control.Exception   (AsyncException (UserInterrupt), evaluate, finally, try, uninterruptibleMask_)
import           Control.Monad       (forM, forM_, replicateM_)
import           Data.Maybe          (isJust)
import           System.Environment  (getArgs, getEnvironment, getExecutablePath, lookupEnv, setEnv, unsetEnv, withProgName)
import           Control.Concurrent  (threadDelay)
import           System.Process      (CreateProcess (..), ProcessHandle, StdStream (..), createPipe, createProcess,
                                      getPid, getProcessExitCode, interruptProcessGroupOf, proc,
                                      readCreateProcessWithExitCode,
                                      terminateProcess, waitForProcess)
import           System.Posix.Files  (createLink, createNamedPipe)
import qualified System.Posix.Signals as Sig
import           System.Posix.Signals (raiseSignal, signalProcess, signalProcessGroup, sigINT, sigKILL, sigTERM)
import           System.IO.Unsafe    (unsafePerformIO)
import           System.Timeout      (timeout)
import qualified Data.ByteString     as BS
import           Data.Word           (Word8)
import           Data.List           (isInfixOf, isPrefixOf, isSuffixOf, sort, stripPrefix, tails, transpose)
import           Data.Char           (isPrint)
import           System.Directory    (createDirectory, createFileLink, doesFileExist, doesPathExist, listDirectory)
import           System.Exit         (ExitCode (..))
import           System.FilePath     (takeFileName, (</>))
import           System.IO
import           Test.Hspec          hiding (after)

import           AFrob               hiding (forAll)
import           AFrobRobotSim
import           AFrobRobotSim.Log   (LogEnd (..), LogFrame (..), LogHeader (..), LogRobot (..), LogSummary (..),
                                      RunLog (..), readLogFile)
import           AFrobRobotSim.JSON  (JSON (..), member, parseJSON)
import           AFrobRobotSim.Replay (replayPage, writeReplayFromLog)
import           AFrobRobotSim.Replay.CommandLine (replayFromMain)
import           AFrobRobotSim.Run.Signals (Stopper, interruptible, signalReceived, stuckGrace)
import           TestUtil (captured, withCaps, withTMPDIR, withTempDir, withUnsearchable, writeScript)

world :: WorldTemplate
world = [OTSimbotA 1 (Point2 (-3) 0) 0, OTVWall (Point2 3 0), OTBall (Point2 0 2)]

drive :: SimbotController
drive _ = constant (mrFinalize (ddVelDiff 1 1))

-- | Forward and back in turns of 10 s, bumping into the wall and the
-- world's edge, printing a line every 0.12 s; failing (an 'error') at
-- @failAt@ seconds.
restless :: Time -> SimbotController
restless failAt _ = (localTime &&& repeatedly 0.12 ()) >>> arr (\(t, e) ->
  if t >= failAt then error ("gave up at " ++ show t)
  else let v = if even (floor (t / 10) :: Int) then 1 else -1
       in mrFinalize (ddVelDiff v v `mrMerge` tcoPrintMessage (fmap (const ("tick at " ++ show t)) e)))

-- | A log's frames thinned to one frame period in @k@, as a frame rate
-- @k@ times coarser takes them (a reference for the replay page's
-- thinning): frames 0, k, 2k, ..., each with the events, console lines
-- and robots' messages of the frames left out before it; those after the
-- last kept one are in none.
thinFrames :: Int -> [LogFrame] -> [LogFrame]
thinFrames _ [] = []
thinFrames k (f0 : rest) = f0 : go rest
  where
    go fs | length period < k = []
          | otherwise         = merged : go (drop k fs)
      where
        period = take k fs
        lastOne = last period
        merged = lastOne { lfEvents = concatMap lfEvents period, lfConsole = concatMap lfConsole period
                         , lfRobots = zipWith (\r ms -> r { lrMessages = ms }) (lfRobots lastOne)
                                              (map (concatMap lrMessages) (transpose (map lfRobots period))) }

-- | The page of a log thinned to one frame period in @k@ ('thinFrames'),
-- its header's frame rate and its summary's count of frames the page's.
thinnedPage :: Int -> RunLog -> String
thinnedPage k l = replayPage (RunLog (rlHeader l) { lhFps = lhFps (rlHeader l) / fromIntegral k } frames
                                     (fmap (\s -> s { lsFrames = length frames }) (rlSummary l)) Nothing)
  where
    frames = thinFrames k (rlFrames l)

-- | A number never computed: the file @spinning@ made in a folder, then a
-- count up from 1 that ends only when an 'Int' overflows (centuries), in
-- a loop that allocates nothing.
spinning :: FilePath -> Double
spinning dir = unsafePerformIO (writeFile (dir </> "spinning") "") `seq` fromIntegral (countUp 1)
{-# NOINLINE spinning #-}

countUp :: Int -> Int
countUp n = if n < 0 then n else countUp (n + 1)
{-# NOINLINE countUp #-}

-- | 100 robots on a 10 by 10 lattice in the notes' world, 0.9 m apart.
crowd :: WorldTemplate
crowd = [ OTSimbotA k (Point2 (-4.05 + 0.9 * fromIntegral (k `mod` 10)) (-4.05 + 0.9 * fromIntegral (k `div` 10))) 0
        | k <- [0 .. 99] ]

-- | Turning on the spot, so that every robot's heading changes at every
-- step and its centre stays put.
circle :: SimbotController
circle _ = constant (mrFinalize (ddVelDiff 0.3 0.5))

quick :: FilePath -> SimOptions
quick dir = defaultSimOptions { optSeconds = 2, optOut = dir, optQuiet = True, optFrames = True
                              , optSvg = Nothing, optReplay = Nothing }

-- | A text with its wall-clock times blanked: the log's and the result's
-- @"wallTime":@ numbers, the summary line's wall time and speed, and the
-- page's nonce (a hash of its lines, the summary's included).
blankWall :: String -> String
blankWall s = case s of
  [] -> []
  _ | Just rest <- stripPrefix "\"wallTime\":" s -> "\"wallTime\":" ++ blankWall (dropWhile (`elem` "0123456789.e-") rest)
    | Just rest <- stripPrefix "nonce-" s         -> "nonce-" ++ blankWall (dropWhile (/= '\'') rest)
    | Just rest <- stripPrefix "nonce=\"" s       -> "nonce=\"" ++ blankWall (dropWhile (/= '"') rest)
    | Just rest <- stripPrefix "frames, " s, (_ : _, r) <- span (`elem` "0123456789.") rest
    , Just rest' <- stripPrefix " s wall time, " r -> "frames, " ++ blankWall (dropWhile (/= 'x') rest')
  c : cs -> c : blankWall cs

-- | Every occurrence of a string replaced by another.
replaceAll :: String -> String -> String -> String
replaceAll old new = go
  where go t | null old = t
        go t@(c : cs) | old `isPrefixOf` t = new ++ go (drop (length old) t)
                      | otherwise          = c : go cs
        go [] = []

framesIn :: FilePath -> IO [BS.ByteString]
framesIn dir = do
  names <- sort . filter ("frame-" `isPrefixOf`) <$> listDirectory dir
  mapM (BS.readFile . (dir </>)) names

-- | The environment variable that makes the test binary run 'child'
-- instead of the specs.
childVariable :: String
childVariable = "AFRP_SPEC_RUN_CHILD"

-- | What the test binary does when started as a child (the variable's
-- value is @what:folder@). @hour@: a simulated hour of the default world
-- with the SVG and trails, under the heap limit the parent gives it
-- (@+RTS -M40m@); a leak ends it with heap overflow (exit code 251).
-- @long@: ten simulated hours with small frames, the log and the page,
-- for the parent to interrupt. @quick@: two simulated seconds, an SVG.
-- @svgmany@: 100 robots turning on the spot for 2000 s, an SVG of their
-- 2001 snapshots (the most it keeps), under the parent's heap limit.
-- @params@: 0.1 s with a @--param@ it asks for and one it does not (a
-- warning). @noworld@: a world file that is not there (exit code 2).
-- @comments@: 0.1 s of the world file @comments.world@ the parent writes.
-- @dumpfar@: @--dump-world@ of a world whose heading a file cannot say.
-- @badnoise@: options set in code out of their flags' ranges (odometry
-- noise 2, a time step of 2e6 s), with a log.
-- @loop@: a SimbotA whose output depends on itself with no delay.
-- @deep@: a SimbotA whose step overflows a small stack (@+RTS -K1m@).
-- @leak@: a SimbotA that keeps ever more state, for a heap limit.
-- @piped@: ten simulated hours whose log goes into the named pipe
-- @log.fifo@, for the parent to read, or not.
-- @spin@: frames and the log of a SimbotA that drives for half a second,
-- then makes the file @spinning@ and loops for ever without allocating.
-- @held@: 'interruptible' around a thread that holds stops off (an
-- uninterruptible mask), makes the file @ready@, waits for a signal, then
-- makes the file @spinning@ and loops for ever without allocating.
-- @heldtwice@: the same, with a second @SIGTERM@ sent to itself (after
-- 300 ms) before the loop (200 ms after that).
-- @heldint@: the same for Ctrl-C, which the child cannot see come (the
-- runtime's handler throws it to the main thread, which holds it off):
-- after @ready@ it waits 2 s, for the parent's Ctrl-C, then loops.
-- @talker@: ten simulated hours, the log and the page, a SimbotA that
-- prints a line at every step that has a frame (the log's), for the
-- parent to close its standard output.
-- @holdoff@: the same, but after the signal it waits 'stuckGrace' + 3
-- seconds, then takes the stop: prints @stopped@ and ends with exit code
-- 0.
-- @holdoffint@: the same for Ctrl-C, which it cannot see come: it waits
-- 'stuckGrace' + 3 seconds from @ready@ on, the parent's Ctrl-C sent
-- meanwhile.
-- @replayfrom@: @simbot --replay-from@ ('replayFromMain') with the
-- child's arguments, as @simbot@.
-- @pagefifo@: two simulated seconds of the default world, the log, the
-- SVG, the result line and the replay page, written into the named pipe
-- @page.fifo@ (190 kB, more than a pipe holds), for the parent to read,
-- or not.
child :: String -> IO ()
child arg = case break (== ':') arg of
  ("hour", _ : dir) -> runSimWith defaultSimOptions
    { optSeconds = 3600, optQuiet = True, optTrails = True, optFrames = False
    , optSvg = Just (dir </> "run.svg"), optReplay = Nothing, optOut = dir } Nothing drive drive
  ("long", _ : dir) -> runSimWith defaultSimOptions
    { optSeconds = 36000, optQuiet = True, optFrames = True, optScale = Just 10, optOut = dir </> "f"
    , optSvg = Just (dir </> "run.svg"), optLog = Just (dir </> "run.jsonl")
    , optReplay = Just (dir </> "run.html") } Nothing drive drive
  ("quick", _ : dir) -> runSimWith (quick dir) { optFrames = False, optSvg = Just (dir </> "run.svg") } (Just world) drive drive
  ("svgmany", _ : dir) -> runSimWith defaultSimOptions
    { optSeconds = 2000, optDt = 0.04, optQuiet = True, optFrames = False, optSvg = Just (dir </> "run.svg")
    , optReplay = Nothing, optOut = dir } (Just crowd) circle circle
  ("params", _ : dir) -> do
    _ <- paramOr "speed" (1 :: Double)
    runSimWith (quick dir) { optFrames = False, optSeconds = 0.1, optParams = [("sped", "2"), ("speed", "3")] }
      (Just world) drive drive
  ("comments", _ : dir) -> runSimWith (quick dir) { optFrames = False, optSeconds = 0.1, optWorldFile = Just (dir </> "comments.world") }
                                    Nothing drive drive
  ("noworld", _ : dir) -> runSimWith (quick dir) { optWorldFile = Just (dir </> "missing.world") } Nothing drive drive
  ("dumpbig", _ : _) -> runSimWith defaultSimOptions { optDumpWorld = True }
                                   (Just (OTSize 100 100 : [ OTBall (Point2 (fromIntegral i * 2 - 45) (fromIntegral j * 2 - 45))
                                                           | i <- [0 .. 45 :: Int], j <- [0 .. 45 :: Int] ]))
                                   drive drive
  ("dumpfar", _ : _) -> runSimWith defaultSimOptions { optDumpWorld = True } (Just [OTSimbotA 1 (Point2 0 0) 1e10]) drive drive
  ("badnoise", _ : dir) -> runSimWith (quick dir) { optFrames = False, optOdometryNoise = 2, optDt = 2e6
                                                  , optLog = Just (dir </> "run.jsonl") } (Just world) drive drive
  ("loop", _ : dir) -> runSimWith (quick dir) { optFrames = False, optSvg = Just (dir </> "run.svg")
                                              , optResult = Just (dir </> "r.json") } (Just world) selfish drive
  ("lateloop", _ : dir) -> runSimWith (quick dir) { optFrames = False, optLog = Just (dir </> "run.jsonl")
                                                  , optResult = Just (dir </> "r.json") } (Just world) lateSelfish drive
  ("deep", _ : dir) -> runSimWith (quick dir) { optFrames = False, optSvg = Just (dir </> "run.svg")
                                              , optResult = Just (dir </> "r.json") } (Just world) deep drive
  ("leak", _ : dir) -> runSimWith (quick dir) { optFrames = False, optSeconds = 600, optSvg = Just (dir </> "run.svg")
                                              , optResult = Just (dir </> "r.json") } (Just world) hoarder drive
  ("spin", _ : dir) -> runSimWith defaultSimOptions
    { optSeconds = 600, optQuiet = True, optFrames = True, optScale = Just 10, optOut = dir </> "f"
    , optLog = Just (dir </> "run.jsonl"), optSvg = Just (dir </> "run.svg"), optReplay = Nothing }
    (Just world) (spinner dir) drive
  ("piped", _ : dir) -> runSimWith defaultSimOptions
    { optSeconds = 36000, optQuiet = True, optFrames = False, optOut = dir
    , optLog = Just (dir </> "log.fifo"), optSvg = Just (dir </> "run.svg"), optReplay = Nothing } Nothing drive drive
  ("talker", _ : dir) -> runSimWith defaultSimOptions
    { optSeconds = 36000, optQuiet = False, optFrames = False, optOut = dir, optSvg = Nothing
    , optLog = Just (dir </> "run.jsonl"), optReplay = Just (dir </> "run.html") } (Just world) talker drive
  ("held", _ : dir) -> heldThenSpin dir awaitSignal (pure ())
  ("replayfrom", _) -> getArgs >>= withProgName "simbot" . replayFromMain
  ("pagefifo", _ : dir) -> runSimWith (quick dir)
    { optFrames = False, optLog = Just (dir </> "run.jsonl"), optSvg = Just (dir </> "run.svg")
    , optResult = Just (dir </> "r.json"), optReplay = Just (dir </> "page.fifo") } Nothing drive drive
  ("video", _ : dir) -> runSimWith (quick (dir </> "f")) { optSeconds = 0.2, optVideo = Just (dir </> "run.mp4") }
                                  (Just world) drive drive
  ("pagevideo", _ : dir) -> runSimWith (quick (dir </> "f"))
    { optSeconds = 2, optResult = Just (dir </> "r.json"), optReplay = Just (dir </> "page.fifo")
    , optVideo = Just (dir </> "run.mp4") } Nothing drive drive
  ("bigtalk", _ : dir) -> runSimWith (quick dir) { optFrames = False, optSeconds = 1, optQuiet = False
                                                 , optResult = Just (dir </> "r.json") } (Just world) bigTalker drive
  ("heldtwice", _ : dir) -> heldThenSpin dir awaitSignal (threadDelay 300000 >> raiseSignal sigTERM >> threadDelay 200000)
  ("heldint", _ : dir) -> heldThenSpin dir (const (threadDelay 2000000)) (pure ())
  ("holdoff", _ : dir) -> holdOff dir awaitSignal
  ("holdoffint", _ : dir) -> holdOff dir (const (pure ()))
  _ -> ioError (userError ("unknown child " ++ show arg))
  where
    -- (holds stops off; once the signal has come (@await@), 'stuckGrace'
    -- + 3 seconds more, then takes the stop)
    holdOff :: FilePath -> (Stopper -> IO ()) -> IO ()
    holdOff dir await = do
      r <- try (interruptible $ \stopper -> uninterruptibleMask_ $ do
                  writeFile (dir </> "ready") ""
                  await stopper
                  threadDelay ((stuckGrace + 3) * 1000000))
      putStrLn (case r of
                  Left UserInterrupt -> "stopped"
                  Left e             -> "stopped by " ++ show e
                  Right ()           -> "not stopped")
    awaitSignal :: Stopper -> IO ()
    awaitSignal stopper = signalReceived stopper >>= maybe (threadDelay 1000 >> awaitSignal stopper) (const (pure ()))
    -- (holds stops off; once the signal is taken (@await@), @meanwhile@,
    -- then the loop that never allocates)
    heldThenSpin :: FilePath -> (Stopper -> IO ()) -> IO () -> IO ()
    heldThenSpin dir await meanwhile = interruptible $ \stopper -> uninterruptibleMask_ $ do
      writeFile (dir </> "ready") ""
      await stopper
      meanwhile
      () <$ evaluate (spinning dir)
    -- (from 0.5 s on, its wheel speed is a loop that never ends and never
    -- allocates: a step the runtime cannot stop)
    spinner dir _ = localTime >>> arr (\t -> mrFinalize (ddVelDiff (if t < 0.5 then 0.5 else spinning dir) 0.5))
    -- (a sum too deep for a stack of 1 MB, +RTS -K1m)
    deep _ = constant (mrFinalize (ddVelDiff (foldr (+) 0 [1 .. 1e7 :: Double]) 0))
    -- (keeps 10,000 more numbers at every step, all of them read)
    hoarder _ = arr (const ()) >>> sscan (\xs _ -> let ys = [0 .. 9999 :: Int] ++ xs in sum ys `seq` ys) []
                >>> arr (\kept -> mrFinalize (ddVelDiff (if null kept then 0 else 0.1) 0.1))
    -- (a line at steps 0, 4, 8, ...: those with a frame, at 25 frames a
    -- second and steps of 0.01 s)
    talker _ = sscan (\k _ -> k + 1) (0 :: Int)
               >>> arr (\k -> mrFinalize (ddVelDiff 0.5 0.5 `mrMerge`
                                         tcoPrintMessage (if k `mod` 4 == 1 then Event "a frame" else NoEvent)))
    -- (a message longer than standard output's buffer, at the first step)
    bigTalker _ = sscan (\k _ -> k + 1) (0 :: Int)
                  >>> arr (\k -> mrFinalize (ddVelDiff 0.5 0.5 `mrMerge`
                                            tcoPrintMessage (if k == 1 then Event (replicate 10000 'x') else NoEvent)))
    -- (an output that depends on itself with no delay: <<loop>>)
    selfish _ = loop (arr (\(_, o) -> (o, o)))
    -- (the same from 0.3 s on, after 30 steps that run)
    lateSelfish _ = localTime >>> arr (\t -> if t < 0.3 then mrFinalize (ddVelDiff 0.5 0.5) else let o = o in o)

-- The last element, if any.
lastMaybe :: [x] -> Maybe x
lastMaybe [] = Nothing
lastMaybe xs = Just (last xs)

-- | The ways a run is stopped from outside: a name, how to send it to
-- the child, the exit code expected, and the capabilities to run with.
stops :: [(String, ProcessHandle -> IO (), Int, Int)]
stops =
  [ ("Ctrl-C", interruptProcessGroupOf, 130, 1)
  , ("Ctrl-C", interruptProcessGroupOf, 130, 2)
  , ("SIGTERM", terminateProcess, 143, 1)
  , ("SIGTERM", terminateProcess, 143, 2) ]

-- Wait until the child has written 20 frames into @dir/f@ (polled every
-- 50 ms). A child that has not within a minute is stopped (SIGKILL, so
-- that nothing it does on a gentler signal counts) and the test fails
-- saying so, rather than sending the signal under test too early.
awaitFrames :: FilePath -> ProcessHandle -> IO ()
awaitFrames dir = awaitChild "wrote fewer than 20 frames" $
  (>= 20) . length . either (\(_ :: IOError) -> []) id <$> try (listDirectory (dir </> "f"))

-- | @awaitChild what ready child@ waits until @ready@ (polled every 50
-- ms); if it is not within a minute, the child is stopped (SIGKILL) and
-- the test fails: "the child @what@ in a minute".
awaitChild :: String -> IO Bool -> ProcessHandle -> IO ()
awaitChild what ready ph = go (0 :: Int)
  where
    go k = do
      ok <- ready
      if ok then pure ()
      else if k > 1200 then do
        _ <- killChild ph
        expectationFailure ("the child " ++ what ++ " in a minute")
      else threadDelay 50000 >> go (k + 1)

-- | A signal sent to the child's process group (it was started with
-- @create_group@).
toGroup :: Sig.Signal -> ProcessHandle -> IO ()
toGroup sig ph = getPid ph >>= mapM_ (signalProcessGroup sig)

-- | A child stopped at once (SIGKILL, which nothing it does can delay) and
-- reaped: for a test that gives up on it, leaving nothing behind.
killChild :: ProcessHandle -> IO ExitCode
killChild ph = getPid ph >>= mapM_ (signalProcess sigKILL) >> waitForProcess ph

-- | @toClosedPipe mode@: this test program run as the child @mode@ with
-- its standard output a pipe whose reading end is already closed: how it
-- ended ('Nothing' if not within a minute; it is then killed) and its
-- standard error.
toClosedPipe :: String -> IO (Maybe ExitCode, String)
toClosedPipe mode = do
  self <- getExecutablePath
  environment <- getEnvironment
  (readEnd, writeEnd) <- createPipe
  hClose readEnd
  (_, _, Just herr, ph) <- createProcess (proc self [])
    { env = Just ((childVariable, mode) : environment)
    , std_out = UseHandle writeEnd, std_err = CreatePipe }
  err <- hGetContents herr
  done <- timeout 60000000 (length err `seq` waitForProcess ph)
  _ <- maybe (killChild ph) pure done
  pure (done, err)

-- | The signals that a watchdog follows: a name, how the test sends it
-- (Ctrl-C to the child's process group, so the child must be started
-- with @create_group@), what the watchdog's message calls it, and its
-- number.
watched :: [(String, ProcessHandle -> IO (), String, Int)]
watched = [term, ctrlC]

term, ctrlC :: (String, ProcessHandle -> IO (), String, Int)
term = ("SIGTERM", terminateProcess, "SIGTERM", 15)
ctrlC = ("Ctrl-C", interruptProcessGroupOf, "Ctrl-C (SIGINT)", 2)

-- | A child ended by the watchdog of signal @k@ (called @named@): by that
-- signal after all, as without a handler (128 + @k@ in a shell), within
-- the test's wait (@done@), saying why on standard error (@err@).
endedStuck :: String -> Int -> Maybe ExitCode -> String -> Expectation
endedStuck named k done err = do
  done `shouldSatisfy` (`elem` [Just (ExitFailure (-k)), Just (ExitFailure (128 + k))])
  err `shouldSatisfy` ((named ++ " received, but the runtime has not been able to act on it within "
                        ++ show stuckGrace ++ " s") `isInfixOf`)
  err `shouldSatisfy` ("-fno-omit-yields" `isInfixOf`)

-- @simbot --replay-from@'s command line run as the executable runs it
-- (the test binary as the child @replayfrom@): its exit code, standard
-- output and standard error.
replayFrom :: [String] -> IO (ExitCode, String, String)
replayFrom args = do
  self <- getExecutablePath
  environment <- getEnvironment
  readCreateProcessWithExitCode (proc self args) { env = Just ((childVariable, "replayfrom") : environment) } ""

-- | The test binary started as the child @what@ (see 'child') on a folder,
-- with @+RTS -N@ the capabilities given.
childOn :: String -> FilePath -> Int -> IO CreateProcess
childOn what dir caps = do
  self <- getExecutablePath
  environment <- getEnvironment
  pure (proc self ["+RTS", "-N" ++ show caps, "-RTS"]) { env = Just ((childVariable, what ++ ":" ++ dir) : environment) }

-- | The child @what@ run to its end on a folder with the capabilities
-- given: how it exited (Nothing if it had not within a minute) and its
-- standard error. A child that hangs, as one did while the handler of
-- SIGTERM held its thread, is stopped, not left behind.
failingChild :: String -> FilePath -> Int -> IO (Maybe ExitCode, String)
failingChild what dir caps = do
  child' <- childOn what dir caps
  (_, _, Just herr, ph) <- createProcess child' { std_out = NoStream, std_err = CreatePipe }
  err <- hGetContents herr
  done <- timeout 60000000 (length err `seq` waitForProcess ph)
  _ <- maybe (terminateProcess ph >> waitForProcess ph) pure done
  pure (done, err)

spec :: Spec
spec = do
  describe "worlds of any size" $ do
    it "runs worlds/big.world (100 m): 620 by 620 frames, an SVG and a log of the whole world" $ withTempDir $ \dir -> do
      (_, _, r) <- captured (runSimWith (quick (dir </> "f")) { optSeconds = 0.2, optWorldFile = Just "worlds/big.world"
                                                            , optSvg = Just (dir </> "run.svg"), optLog = Just (dir </> "run.jsonl") }
                                        Nothing drive drive)
      r `shouldBe` Right ()
      frames <- framesIn (dir </> "f")
      map (BS.take 15) frames `shouldBe` replicate 6 (BS.pack (map (toEnum . fromEnum) "P6\n620 620\n255\n"))
      svg <- readFile (dir </> "run.svg")
      svg `shouldSatisfy` ("viewBox=\"0 0 790 620\"" `isInfixOf`)
      svg `shouldSatisfy` ("... and 170 more<" `isInfixOf`)
      Right l <- readLogFile (dir </> "run.jsonl")
      lhBounds (rlHeader l) `shouldBe` LogRect 0 0 100 100
      length (lhRobots (rlHeader l)) `shouldBe` 200
    it "a robot of a 100 m world drives beyond the notes' walls" $ withTempDir $ \dir -> do
      let big = [OTSize 100 100, OTSimbotA 1 (Point2 0 0) 0]
      (_, _, r) <- captured (runSimWith (quick dir) { optSeconds = 20, optFrames = False, optLog = Just (dir </> "run.jsonl") }
                                        (Just big) drive drive)
      r `shouldBe` Right ()
      Right l <- readLogFile (dir </> "run.jsonl")
      map lrX (lfRobots (last (rlFrames l))) `shouldSatisfy` all (> 10)
    it "a 30 by 10 world: 620 by 220 frames, a non-square SVG and log bounds" $ withTempDir $ \dir -> do
      let wide = [OTSize 30 10, OTSimbotA 1 (Point2 (-12) 0) 0, OTBall (Point2 12 4)]
      (_, _, r) <- captured (runSimWith (quick (dir </> "f")) { optSvg = Just (dir </> "run.svg")
                                                            , optLog = Just (dir </> "run.jsonl") }
                                        (Just wide) drive drive)
      r `shouldBe` Right ()
      frames <- framesIn (dir </> "f")
      length frames `shouldBe` 51
      map BS.length frames `shouldBe` replicate 51 (length "P6\n620 220\n255\n" + 3 * 620 * 220)
      svg <- readFile (dir </> "run.svg")
      svg `shouldSatisfy` ("width=\"790\" height=\"220\" viewBox=\"0 0 790 220\"" `isInfixOf`)
      Right l <- readLogFile (dir </> "run.jsonl")
      lhBounds (rlHeader l) `shouldBe` LogRect 0 0 30 10
    it "--scale still sets the scale, checked against the world's size" $ withTempDir $ \dir -> do
      (_, _, r) <- captured (runSimWith (quick (dir </> "f")) { optSeconds = 0, optScale = Just 10 }
                                        (Just [OTSize 30 10]) drive drive)
      r `shouldBe` Right ()
      frames <- framesIn (dir </> "f")
      map (BS.take 15) frames `shouldBe` [BS.pack (map (toEnum . fromEnum) "P6\n320 120\n255\n")]
      (_, err, r') <- captured (runSimWith (quick (dir </> "g")) { optScale = Just 100 } (Just [OTSize 100 10]) drive drive)
      r' `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ("--scale 100 makes the frame of this 100 by 10 m world 10020 pixels" `isInfixOf`)
      validateOptionsIn notesBounds defaultSimOptions { optScale = Just 100 } `shouldBe` []
    it "a world file with a bad size is reported with its line, simulating nothing" $ withTempDir $ \dir -> do
      writeFile (dir </> "bad.world") "ball at 0 0\nsize 2000 10\n"
      (_, err, r) <- captured (runSimWith (quick (dir </> "f")) { optWorldFile = Just (dir </> "bad.world") } Nothing drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ((dir </> "bad.world:2:6: expected a world side from 1 to 1000 metres") `isInfixOf`)
    it "--dump-world writes the size, and --world reads it back" $ withTempDir $ \dir -> do
      let wide = [OTSize 30 10, OTSimbotA 1 (Point2 (-12) 0) 0]
      (dumped, _, _) <- captured (runSimWith defaultSimOptions { optDumpWorld = True } (Just wide) drive drive)
      lines dumped `shouldSatisfy` elem "size 30.0 10.0"
      writeFile (dir </> "w.world") dumped
      _ <- captured (runSimWith (quick (dir </> "a")) (Just wide) drive drive)
      _ <- captured (runSimWith (quick (dir </> "b")) { optWorldFile = Just (dir </> "w.world") } Nothing drive drive)
      a <- framesIn (dir </> "a")
      b <- framesIn (dir </> "b")
      (length a, a == b) `shouldBe` (51, True)
  describe "the summary's simulated time" $
    it "is the steps' time rounded as the frames' times are (5.31, not 5.3100000000000005)" $ withTempDir $ \dir -> do
      _ <- captured (runSimWith (quick dir) { optFrames = False, optSeconds = 5.31, optLog = Just (dir </> "run.jsonl")
                                            , optResult = Just (dir </> "r.json") } (Just world) drive drive)
      logRead <- readLogFile (dir </> "run.jsonl")
      fmap (fmap (\sm -> (lsSimulated sm, lsSteps sm)) . rlSummary) logRead `shouldBe` Right (Just (5.31, 532))
      readFile (dir </> "run.jsonl") >>= (`shouldSatisfy` ("\"simulated\":5.31," `isInfixOf`))
      readFile (dir </> "r.json") >>= (`shouldSatisfy` ("\"simulated\":5.31," `isInfixOf`))
  describe "the result line's world" $
    it "is \"default\" for the built-in world, \"program\" for the program's own (it was \"default\"), the file for --world" $
      withTempDir $ \dir -> do
        let wf = dir </> "w.world"
            r = dir </> "r.json"
            worldOf = fmap (\l -> parseJSON l >>= member "world") (readFile r)
            o = (quick dir) { optFrames = False, optSeconds = 0.1, optResult = Just r }
        writeFile wf "simbotA 1 at 0 0\n"
        _ <- captured (runSimWith o Nothing drive drive)
        worldOf `shouldReturn` Right (JString "default")
        _ <- captured (runSimWith o (Just world) drive drive)
        worldOf `shouldReturn` Right (JString "program")
        _ <- captured (runSimWith o { optWorldFile = Just wf } (Just world) drive drive)
        worldOf `shouldReturn` Right (JString wf)
  describe "scripted keys" $
    it "warns of a key pressed after the run's last step (never pressed), and of no other" $ withTempDir $ \dir -> do
      (_, err, r) <- captured (runSimWith (quick dir) { optFrames = False, optSeconds = 1
                                                      , optKeys = [(0.5, 'a'), (1, 'b'), (5, ' ')] } (Just world) drive drive)
      r `shouldBe` Right ()
      lines err `shouldSatisfy` \ls -> length ls == 1
        && all ("warning: the key press space at 5.0 s is never pressed: the run's last step is at 1.0 s" `isSuffixOf`) ls
      -- by the simulator's rule: one key a step, a key due a millionth of
      -- a step after the last one pressed there
      (_, err', _) <- captured (runSimWith (quick dir) { optFrames = False, optSeconds = 1
                                                       , optKeys = [(1, 'a'), (1, 'b'), (0.3000001, 'c')] } (Just world) drive drive)
      lines err' `shouldSatisfy` \ls -> length ls == 1
        && all ("the key press b at 1.0 s is never pressed: it waits behind the presses due before it" `isInfixOf`) ls
      (_, err'', _) <- captured (runSimWith (quick dir) { optFrames = False, optSeconds = 0.3, optDt = 0.1, optFps = 10
                                                        , optKeys = [(0.3000001, 'c')] } (Just world) drive drive)
      err'' `shouldBe` ""
      -- (a key pressed twice in a row is released for a step between:
      -- the second press of a at 0 s is made at 0.2 s, after the run)
      (_, err3, _) <- captured (runSimWith (quick dir) { optFrames = False, optSeconds = 0.1, optDt = 0.1, optFps = 10
                                                       , optKeys = [(0, 'a'), (0, 'a')] } (Just world) drive drive)
      lines err3 `shouldSatisfy` \ls -> length ls == 1
        && all ("the key press a at 0.0 s is never pressed: it waits behind the presses due before it (a step presses at most one key, and a key pressed again straight after itself waits a step, released between) until after the run's last step, at 0.1 s" `isInfixOf`) ls
      (_, err4, _) <- captured (runSimWith (quick dir) { optFrames = False, optSeconds = 0.2, optDt = 0.1, optFps = 10
                                                       , optKeys = [(0, 'a'), (0, 'a')] } (Just world) drive drive)
      err4 `shouldBe` ""
      -- (a time too large for a millionth to count is said as it is: it
      -- was "at Infinity s")
      (_, err5, _) <- captured (runSimWith (quick dir) { optFrames = False, optSeconds = 0.1
                                                       , optKeys = [(1e308, 'a')] } (Just world) drive drive)
      err5 `shouldSatisfy` ("the key press a at 1.0e308 s is never pressed" `isInfixOf`)
  describe "parameters" $
    it "warns of a --param the program never asked for (a misspelled name), naming those it did" $ withTempDir $ \dir -> do
      self <- getExecutablePath
      environment <- getEnvironment
      (code, _, err) <- readCreateProcessWithExitCode
        (proc self []) { env = Just ((childVariable, "params:" ++ dir) : environment) } ""
      code `shouldBe` ExitSuccess
      lines err `shouldBe`
        [ takeWhile (/= '.') (takeFileName self) ++ ": warning: --param sped=2: this program has asked for no parameter named \"sped\" (it reads \"speed\")" ]
  describe "standard error closed (2>&-) or full (/dev/full): its messages are lost, nothing else" $ do
    let withErr what dir stream = do
          self <- getExecutablePath
          environment <- getEnvironment
          (_, Just out, _, ph) <- createProcess (proc self [])
            { env = Just ((childVariable, what ++ ":" ++ dir) : environment), std_out = CreatePipe, std_err = stream }
          o <- hGetContents out
          _ <- evaluate (length o)
          (,) o <$> waitForProcess ph
    it "a run with a warning runs, and exits 0" $ withTempDir $ \dir -> do
      (o, code) <- withErr "params" dir NoStream
      (code, take 25 o) `shouldBe` (ExitSuccess, "0.10 s simulated in 11 st")
      full <- openFile "/dev/full" WriteMode
      (o', code') <- withErr "params" dir (UseHandle full)
      (code', take 25 o') `shouldBe` (ExitSuccess, "0.10 s simulated in 11 st")
    it "--dump-world of a world that a file cannot say prints it and warns that it does not load back (it said nothing)" $
      withTempDir $ \dir -> do
        self <- getExecutablePath
        environment <- getEnvironment
        (code, out, err) <- readCreateProcessWithExitCode
          (proc self []) { env = Just ((childVariable, "dumpfar:" ++ dir) : environment) } ""
        code `shouldBe` ExitSuccess
        lines out `shouldSatisfy` elem "simbotA 1 at 0.0 0.0 heading 1.0e10 rad"
        err `shouldSatisfy` ("warning: this world does not load back with --world: the printed world:2:30: expected a heading within" `isInfixOf`)
    it "options set in code out of their flags' ranges are refused before the run, exit 2 (the simulator stopped at them, the log begun)" $
      withTempDir $ \dir -> do
        writeFile (dir </> "run.jsonl") "an earlier log\n"
        self <- getExecutablePath
        environment <- getEnvironment
        (code, out, err) <- readCreateProcessWithExitCode
          (proc self []) { env = Just ((childVariable, "badnoise:" ++ dir) : environment) } ""
        (code, out) `shouldBe` (ExitFailure 2, "")
        lines err `shouldSatisfy` \ls -> all (`elem` map (dropWhile (== ' ')) ls)
          [ "optOdometryNoise must be a number from 0 to 1, got 2.0", "optDt must be a positive number up to 1000000, got 2000000.0" ]
        err `shouldNotSatisfy` ("CallStack" `isInfixOf`)
        readFile (dir </> "run.jsonl") `shouldReturn` "an earlier log\n"
    it "a world file that is not there still exits with code 2" $ withTempDir $ \dir -> do
      (o, code) <- withErr "noworld" dir NoStream
      (code, o) `shouldBe` (ExitFailure 2, "")
      full <- openFile "/dev/full" WriteMode
      (o', code') <- withErr "noworld" dir (UseHandle full)
      (code', o') `shouldBe` (ExitFailure 2, "")
  describe "memory" $ do
    -- a child run (see 'child') under a heap limit: it ends well, having
    -- simulated what it should
    let underHeap limit what dir summary = do
          self <- getExecutablePath
          environment <- getEnvironment
          (code, out, err) <- readCreateProcessWithExitCode
            (proc self ["+RTS", "-M" ++ limit, "-RTS"]) { env = Just ((childVariable, what ++ ":" ++ dir) : environment) } ""
          (code, err) `shouldBe` (ExitSuccess, "")
          out `shouldSatisfy` (summary `isPrefixOf`)
    it "a simulated hour with the SVG and trails runs in 40 MB of heap (+RTS -M40m)" $ withTempDir $ \dir ->
      underHeap "40m" "hour" dir "3600.00 s simulated in 360001 steps"
    it "a world file of two million lines is read in 40 MB of heap (a cell per line was kept: about 80 MB of heap)" $ withTempDir $ \dir -> do
      writeFile (dir </> "comments.world") (concat (replicate 2000000 "#\n") ++ "simbotA 1 at 0 0 heading 0 deg\n")
      underHeap "40m" "comments" dir "0.10 s simulated in 11 steps"
    it "an SVG of 100 robots' 2001 snapshots runs in 20 MB of heap (+RTS -M20m)" $ withTempDir $ \dir -> do
      underHeap "20m" "svgmany" dir "2000.00 s simulated in 50001 steps"
      svg <- readFile (dir </> "run.svg")
      length (filter ("<polyline" `isPrefixOf`) (tails svg)) `shouldBe` 100

  describe "standard output closed when the program starts" $
    it "runs, writes its files, then fails with exit code 1 and a message (it waited forever)" $ withTempDir $ \dir -> do
      self <- getExecutablePath
      environment <- getEnvironment
      (_, _, Just herr, ph) <- createProcess (proc self [])
        { env = Just ((childVariable, "quick:" ++ dir) : environment)
        , std_out = NoStream, std_err = CreatePipe }
      err <- hGetContents herr
      done <- timeout 60000000 (length err `seq` waitForProcess ph)
      -- (a child that hangs is stopped, not left behind)
      _ <- maybe (terminateProcess ph >> waitForProcess ph) pure done
      done `shouldBe` Just (ExitFailure 1)
      -- (without the descriptor held, the runtime's timer or event
      -- descriptor took number 1: the run hung, or failed with EINVAL)
      err `shouldSatisfy` ("cannot write to standard output" `isInfixOf`)
      err `shouldSatisfy` ("Bad file descriptor" `isInfixOf`)
      doesFileExist (dir </> "run.svg") `shouldReturn` True
  describe "standard output a pipe whose reader has gone" $
    it "--dump-world of a world longer than the output's buffer fails with exit code 1 and a message (it exited 0, unsaid)" $
      withTempDir $ \dir -> do
        (done, err) <- toClosedPipe ("dumpbig:" ++ dir)
        (done, "cannot write to standard output" `isInfixOf` err, "Broken pipe" `isInfixOf` err, length (lines err))
          `shouldBe` (Just (ExitFailure 1), True, True, 1)
  describe "a controller whose output depends on itself with no delay" $ do
    forM_ [1, 2 :: Int] $ \caps ->
      it ("fails the run with <<loop>>, naming the robot, its outputs written (" ++ show caps ++ " capabilities)") $
        withTempDir $ \dir -> do
          (done, err) <- failingChild "loop" dir caps
          done `shouldBe` Just (ExitFailure 1)
          err `shouldSatisfy` ("the controller of SimbotA 1 failed at t = 0.000 s: <<loop>>" `isInfixOf`)
          doesFileExist (dir </> "run.svg") `shouldReturn` True
          -- (in JSON, < is written \u003c)
          readFile (dir </> "r.json") >>= (`shouldSatisfy` ("SimbotA 1 failed at t = 0.000 s: \\u003c\\u003cloop" `isInfixOf`))
    it "fails the run at the same step on 1 and 2 capabilities when the <<loop>> comes after 30 steps" $
      withTempDir $ \dir -> do
        outcomes <- forM [1, 2 :: Int] $ \caps -> do
          let sub = dir </> show caps
          createDirectory sub
          (done, err) <- failingChild "lateloop" sub caps
          done `shouldBe` Just (ExitFailure 1)
          err `shouldSatisfy` ("the controller of SimbotA 1 failed at t = 0.300 s: <<loop>>" `isInfixOf`)
          logText <- readFile (sub </> "run.jsonl")
          -- (every step before the failure: 0 to 0.29 s)
          logText `shouldSatisfy` ("\"simulated\":0.29,\"steps\":30," `isInfixOf`)
          -- (the log less its summary, which has the wall time)
          length logText `seq` pure (filter (not . ("\"kind\":\"summary\"" `isInfixOf`)) (lines logText))
        case outcomes of
          [one, two] -> two `shouldBe` one
          _          -> expectationFailure "two runs"
  describe "a controller that overflows the stack, or fills the heap" $ do
    let childRun what rts dir = do
          self <- getExecutablePath
          environment <- getEnvironment
          readCreateProcessWithExitCode
            (proc self (["+RTS"] ++ rts ++ ["-RTS"])) { env = Just ((childVariable, what ++ ":" ++ dir) : environment) } ""
    it "a stack overflow in a controller's step is its failure: named, exit 1, the outputs written" $ withTempDir $ \dir -> do
      (code, _, err) <- childRun "deep" ["-K1m"] dir
      (code, err) `shouldSatisfy` \(c, e) -> c == ExitFailure 1
                                            && "the controller of SimbotA 1 failed at t = 0.000 s: stack overflow" `isInfixOf` e
      doesFileExist (dir </> "run.svg") `shouldReturn` True
      readFile (dir </> "r.json") >>= (`shouldSatisfy` ("stack overflow" `isInfixOf`))
    it "a run that reaches the heap's limit stops, says so, and writes its outputs (exit 1)" $ withTempDir $ \dir -> do
      (code, out, err) <- childRun "leak" ["-M60m"] dir
      code `shouldBe` ExitFailure 1
      out `shouldSatisfy` ("stopped: " `isPrefixOf`)
      err `shouldSatisfy` ("the run stopped: it ran out of memory (the heap limit, +RTS -M" `isInfixOf`)
      doesFileExist (dir </> "run.svg") `shouldReturn` True
      readFile (dir </> "r.json") >>= (`shouldSatisfy` ("ran out of memory" `isInfixOf`))
  describe "a controller in a loop that never allocates (the runtime cannot stop it)" $
    forM_ watched $ \(name, send, named, k) -> forM_ [1, 2 :: Int] $ \caps ->
      it ("a " ++ name ++ " ends the program after the grace, saying why, the frames already written kept (+RTS -N"
          ++ show caps ++ ")") $ withTempDir $ \dir -> do
        spin <- childOn "spin" dir caps
        (_, _, Just herr, ph) <- createProcess spin { create_group = True, std_out = NoStream, std_err = CreatePipe }
        awaitChild "did not begin its loop" (doesFileExist (dir </> "spinning")) ph
        threadDelay 200000
        send ph
        err <- hGetContents herr
        -- (it hung for ever before the grace: a child that does is stopped,
        -- not left behind; so did a first Ctrl-C, when only Ctrl-C's
        -- second, which ends the program at once, ended it)
        done <- timeout 60000000 (length err `seq` waitForProcess ph)
        _ <- maybe (killChild ph) pure done
        endedStuck named k done err
        -- (the frames are whole; on two capabilities the thread writing
        -- them may have been stopped, by the collection the loop holds
        -- up, in the middle of one, whose temporary file the end leaves)
        names <- listDirectory (dir </> "f")
        let (temps, finals) = (filter (".tmp" `isSuffixOf`) names, filter (".ppm" `isSuffixOf`) names)
        frames <- mapM (BS.readFile . ((dir </> "f") </>)) finals
        (length frames > 0, all ((== 15 + 3 * 120 * 120) . BS.length) frames, length temps <= 1, length (lines err))
          `shouldBe` (True, True, True, 1)
  describe "a second Ctrl-C" $
    forM_ [1, 2 :: Int] $ \caps -> do
      it ("ends the program at once, by SIGINT, as the runtime's does, but saying so (+RTS -N" ++ show caps ++ ")") $
        withTempDir $ \dir -> do
          spin <- childOn "spin" dir caps
          (_, _, Just herr, ph) <- createProcess spin { create_group = True, std_out = NoStream, std_err = CreatePipe }
          awaitChild "did not begin its loop" (doesFileExist (dir </> "spinning")) ph
          threadDelay 200000
          interruptProcessGroupOf ph
          threadDelay 1000000
          interruptProcessGroupOf ph
          err <- hGetContents herr
          -- (well before the grace; the program ended silently)
          done <- timeout ((stuckGrace - 5) * 1000000) (length err `seq` waitForProcess ph)
          _ <- maybe (killChild ph) pure done
          -- (killed by SIGINT, as the runtime's rule ends it: an exit with
          -- status 130, a second later, is what a shell's loop goes on after)
          done `shouldBe` Just (ExitFailure (-2))
          err `shouldSatisfy` ("Ctrl-C (SIGINT) received a second time: ending now, without waiting for the run to stop" `isInfixOf`)
          err `shouldNotSatisfy` ("has not been able to act" `isInfixOf`)
      it ("ends the program at once with its standard error a full pipe, the message left out (it waited for ever to write it) (+RTS -N" ++ show caps ++ ")") $
        withTempDir $ \dir -> do
          spin <- childOn "spin" dir caps
          (r, w) <- createPipe
          -- (a pipe's 64 KiB, filled before the child starts: nobody reads it)
          BS.hPut w (BS.replicate 65536 46)
          (_, _, _, ph) <- createProcess spin { create_group = True, std_out = NoStream, std_err = UseHandle w }
          awaitChild "did not begin its loop" (doesFileExist (dir </> "spinning")) ph
          threadDelay 200000
          interruptProcessGroupOf ph
          threadDelay 1000000
          interruptProcessGroupOf ph
          done <- timeout ((stuckGrace - 5) * 1000000) (waitForProcess ph)
          _ <- maybe (killChild ph) pure done
          hClose r
          -- (killed by SIGINT, as the runtime's rule ends it: an exit with
          -- status 130, a second later, is what a shell's loop goes on after)
          done `shouldBe` Just (ExitFailure (-2))
  describe "a run's thread that holds the stop off (masked) once the signal has been taken" $
    forM_ [1, 2 :: Int] $ \caps -> do
      forM_ [ ("held", "", term), ("heldtwice", ", a second SIGTERM come meanwhile", term)
            , ("heldint", " (Ctrl-C, which the runtime's handler throws to the main thread)", ctrlC) ] $
        \(what, how, (_, send, named, k)) ->
        it ("and then loops without allocating" ++ how ++ ": ended after the grace, saying why (+RTS -N"
            ++ show caps ++ ")") $ withTempDir $ \dir -> do
          held <- childOn what dir caps
          (_, _, Just herr, ph) <- createProcess held { create_group = True, std_out = NoStream, std_err = CreatePipe }
          awaitChild "did not begin" (doesFileExist (dir </> "ready")) ph
          send ph
          err <- hGetContents herr
          -- (it hung for ever: the runtime had acted once, before the stop
          -- reached the thread, and was not watched after; with a second
          -- signal, that signal's handler ended the watch; Ctrl-C was not
          -- watched at all)
          done <- timeout 60000000 (length err `seq` waitForProcess ph)
          _ <- maybe (killChild ph) pure done
          doesFileExist (dir </> "spinning") `shouldReturn` True
          endedStuck named k done err
      forM_ [("holdoff", "", term), ("holdoffint", "Ctrl-C, ", ctrlC)] $ \(what, how, (_, send, _, _)) ->
        it ("and takes it after more than the grace, the runtime acting all along: not cut short (" ++ how ++ "+RTS -N"
            ++ show caps ++ ")") $ withTempDir $ \dir -> do
          holdoff <- childOn what dir caps
          (_, Just hout, Just herr, ph) <- createProcess holdoff { create_group = True, std_out = CreatePipe, std_err = CreatePipe }
          awaitChild "did not begin" (doesFileExist (dir </> "ready")) ph
          send ph
          out <- hGetContents hout
          err <- hGetContents herr
          done <- timeout 60000000 (length out `seq` length err `seq` waitForProcess ph)
          _ <- maybe (killChild ph) pure done
          (done, out, err) `shouldBe` (Just ExitSuccess, "stopped\n", "")
  describe "a run slow to stop (its log written into a pipe nobody reads for a while)" $
    forM_ watched $ \(name, send, _, k) -> forM_ [1, 2 :: Int] $ \caps ->
      it ("is stopped by " ++ name ++ " once the pipe is read again, after more than the grace, its outputs written (+RTS -N"
          ++ show caps ++ ")") $ withTempDir $ \dir -> do
        let fifo = dir </> "log.fifo"
        createNamedPipe fifo 0o600
        -- (opened for reading and writing, which does not wait for a
        -- writer: the child's log, opened without waiting, needs a reader
        -- there; the end of the log is then its summary, not end of file)
        reader <- openFile fifo ReadWriteMode
        piped <- childOn "piped" dir caps
        (_, Just hout, Just herr, ph) <- createProcess piped { create_group = True, std_out = CreatePipe, std_err = CreatePipe }
        -- (the run is going: some of its log read, then no more, so that
        -- its next writes wait)
        replicateM_ 50 (hGetLine reader)
        threadDelay 1000000
        send ph
        threadDelay ((stuckGrace + 3) * 1000000)
        still <- getProcessExitCode ph
        let untilSummary acc = do
              l <- hGetLine reader
              if "\"kind\":\"summary\"" `isInfixOf` l then pure (reverse (l : acc)) else untilSummary (l : acc)
        rest <- timeout 60000000 (untilSummary [])
        done <- timeout 60000000 (waitForProcess ph)
        _ <- maybe (killChild ph) pure done
        out <- hGetContents hout
        err <- hGetContents herr
        (still, done) `shouldBe` (Nothing, Just (ExitFailure (128 + k)))
        out `shouldSatisfy` ("interrupted: " `isPrefixOf`)
        err `shouldBe` ""
        fmap (any ("\"interrupted\":true" `isInfixOf`)) rest `shouldBe` Just True
        doesFileExist (dir </> "run.svg") `shouldReturn` True
  describe "a signal that comes while the outputs are being written" $
    forM_ watched $ \(name, send, named, k) -> forM_ [1, 2 :: Int] $ \caps ->
      it ("(" ++ name ++ ") does not cut the writing short: the outputs are finished, the summary printed, the signal "
          ++ "said, exit code " ++ show (128 + k) ++ " (a Ctrl-C left the page cut short, no SVG, no result line, no "
          ++ "summary, and said nothing) (+RTS -N" ++ show caps ++ ")") $ withTempDir $ \dir -> do
        let fifo = dir </> "page.fifo"
        createNamedPipe fifo 0o600
        -- (opened for reading and writing: the child's page, opened
        -- without waiting, needs a reader there)
        reader <- openBinaryFile fifo ReadWriteMode
        writing <- childOn "pagefifo" dir caps
        (_, Just hout, Just herr, ph) <- createProcess writing { create_group = True, std_out = CreatePipe, std_err = CreatePipe }
        -- (the page's first bytes: the child is writing its outputs, and
        -- waits once the pipe is full, nobody reading; the signal then)
        begun <- timeout 60000000 (BS.hGetSome reader 16)
        _ <- maybe (killChild ph) (const (pure ExitSuccess)) begun
        threadDelay 300000
        send ph
        threadDelay 300000
        -- (the rest of the page, as far as it comes)
        let drain acc = do
              more <- hWaitForInput reader 2000
              if not more then pure acc else do
                chunk <- BS.hGetSome reader 65536
                let acc' = acc <> chunk
                if BS.pack (map (toEnum . fromEnum) "</html>\n") `BS.isSuffixOf` acc' then pure acc' else drain acc'
        page <- drain (maybe BS.empty id begun)
        hClose reader
        out <- hGetContents hout
        err <- hGetContents herr
        done <- timeout 60000000 (length out `seq` length err `seq` waitForProcess ph)
        _ <- maybe (killChild ph) pure done
        done `shouldBe` Just (ExitFailure (128 + k))
        (BS.isPrefixOf (BS.pack (map (toEnum . fromEnum) "<!DOCTYPE html>")) page
          , BS.isSuffixOf (BS.pack (map (toEnum . fromEnum) "</html>\n")) page) `shouldBe` (True, True)
        lines out `shouldSatisfy` \ls -> case ls of
          [summary] -> "2.00 s simulated in 201 steps" `isPrefixOf` summary
          _         -> False
        lines err `shouldBe` ["afrp-spec: " ++ named ++ " received while the outputs were being written: they were written first"]
        doesFileExist (dir </> "run.svg") `shouldReturn` True
        readFile (dir </> "r.json") >>= (`shouldSatisfy` ("\"simulated\":2" `isInfixOf`))
  describe "a signal that comes while ffmpeg assembles the video" $ do
    -- (a stand-in ffmpeg that says it has begun, takes 3 s, then makes
    -- the file named last)
    let withSlowFfmpeg dir act = do
          let bin = dir </> "bin"
          createDirectory bin
          writeScript (bin </> "ffmpeg") ("#!/bin/sh\n: > " ++ (dir </> "started") ++ "\nsleep 3\n"
                                         ++ "for a; do last=$a; done\n: > \"${last#file:}\"\n")
          environment <- getEnvironment
          path <- maybe "" (':' :) <$> lookupEnv "PATH"
          act (filter ((/= "PATH") . fst) environment ++ [("PATH", bin ++ path)])
        -- (the child @what@ with that ffmpeg; @send@ once ffmpeg has begun
        -- (or, for @pagevideo@, once its page is being written); its exit
        -- code and standard error)
        videoChild what dir send = withSlowFfmpeg dir $ \environment -> do
          c <- childOn what dir 1
          (_, Just hout, Just herr, ph) <- createProcess c { env = Just ((childVariable, what ++ ":" ++ dir) : environment)
                                                           , create_group = True, std_out = CreatePipe, std_err = CreatePipe }
          awaitChild "began ffmpeg" (doesFileExist (dir </> "started")) ph
          threadDelay 300000
          () <- send ph
          out <- hGetContents hout
          err <- hGetContents herr
          done <- timeout 60000000 (length out `seq` length err `seq` waitForProcess ph)
          _ <- maybe (killChild ph) pure done
          pure (done, err)
        toChild sig ph = getPid ph >>= mapM_ (signalProcess sig)
    it "Ctrl-C to simbot alone is noted, the video finished, exit code 130 (it was dropped: exit code 0)" $
      withTempDir $ \dir -> do
        (done, err) <- videoChild "video" dir (toChild sigINT)
        (done, lines err) `shouldBe` (Just (ExitFailure 130), ["afrp-spec: Ctrl-C (SIGINT) received while the outputs were "
                                                                 ++ "being written: they were written first"])
        doesFileExist (dir </> "run.mp4") `shouldReturn` True
    forM_ [ ("Ctrl-C", interruptProcessGroupOf, "Ctrl-C (SIGINT)"), ("SIGTERM", toGroup sigTERM, "SIGTERM") ] $
      \(name, send, named) ->
        it (name ++ " to the group, which stops ffmpeg, is said, without claiming the outputs were written, exit code 1 "
            ++ "(Ctrl-C was not said; SIGTERM said they were written first)") $ withTempDir $ \dir -> do
          (done, err) <- videoChild "video" dir send
          done `shouldBe` Just (ExitFailure 1)
          err `shouldSatisfy` (("ffmpeg was stopped by " ++ named) `isInfixOf`)
          -- (this program's own note of the signal may come after the
          -- outputs, its handler being a thread of its own: when it
          -- comes in time, it claims no output written)
          err `shouldNotSatisfy` ("written first" `isInfixOf`)
          doesFileExist (dir </> "run.mp4") `shouldReturn` False
    it "a signal noted before the video is begun: the video is not begun, the frames kept, said, exit code 143" $
      withTempDir $ \dir -> do
        let fifo = dir </> "page.fifo"
        createNamedPipe fifo 0o600
        reader <- openBinaryFile fifo ReadWriteMode
        -- (the page waits in its pipe, nobody reading; SIGTERM then, and
        -- the pipe read to its end)
        let send ph = do
              terminateProcess ph
              threadDelay 300000
              let drain = hWaitForInput reader 2000 >>= \more -> if more then BS.hGetSome reader 65536 >> drain else pure ()
              drain
        (done, err) <- withSlowFfmpeg dir $ \environment -> do
          c <- childOn "pagevideo" dir 1
          (_, Just hout, Just herr, ph) <- createProcess c { env = Just ((childVariable, "pagevideo:" ++ dir) : environment)
                                                           , std_out = CreatePipe, std_err = CreatePipe }
          begun <- timeout 60000000 (BS.hGetSome reader 16)
          _ <- maybe (killChild ph) (const (pure ExitSuccess)) begun
          threadDelay 300000
          send ph
          out <- hGetContents hout
          err <- hGetContents herr
          done <- timeout 60000000 (length out `seq` length err `seq` waitForProcess ph)
          _ <- maybe (killChild ph) pure done
          pure (done, err)
        hClose reader
        (done, lines err) `shouldBe` (Just (ExitFailure 143), ["afrp-spec: SIGTERM received while the outputs were being "
                                                                 ++ "written: they were written first, but for the video, "
                                                                 ++ "which was not begun (the frames are in " ++ (dir </> "f") ++ ")"])
        doesFileExist (dir </> "started") `shouldReturn` False
        length <$> listDirectory (dir </> "f") `shouldReturn` 51
  describe "standard output a pipe whose reader has gone, at the run's summary" $
    it "a robot's message longer than the buffer: exit code 1 and a message (it exited 0, unsaid)" $ withTempDir $ \dir -> do
      (done, err) <- toClosedPipe ("bigtalk:" ++ dir)
      (done, "Broken pipe" `isInfixOf` err) `shouldBe` (Just (ExitFailure 1), True)
      doesFileExist (dir </> "r.json") `shouldReturn` True
  describe "a SIGTERM the program was started ignoring (nohup, a batch system)" $
    it "is still ignored: the run goes on, and Ctrl-C stops it" $ withTempDir $ \dir -> do
      self <- getExecutablePath
      environment <- getEnvironment
      (_, _, _, ph) <- createProcess (proc "sh" ["-c", "trap '' TERM; exec \"$0\"", self])
        { env = Just ((childVariable, "long:" ++ dir) : environment), create_group = True
        , std_out = NoStream, std_err = Inherit }
      awaitFrames dir ph
      terminateProcess ph
      threadDelay 500000
      getProcessExitCode ph `shouldReturn` Nothing
      interruptProcessGroupOf ph
      waitForProcess ph `shouldReturn` ExitFailure 130
  describe "a closed standard output (simbot | head)" $ forM_ [1, 2] $ \caps ->
    it ("stops the run, the log and the page holding every step the summary counts (+RTS -N" ++ show caps ++ ")") $
      withTempDir $ \dir -> do
        talking <- childOn "talker" dir caps
        (_, Just hout, _, ph) <- createProcess talking { std_out = CreatePipe, std_err = CreatePipe }
        _ <- hGetLine hout
        hClose hout
        done <- timeout 60000000 (waitForProcess ph)
        _ <- maybe (killChild ph) pure done
        done `shouldBe` Just (ExitFailure 1)
        logRead <- readLogFile (dir </> "run.jsonl")
        -- (each line came at a step with a frame, so the write that
        -- failed was at one: the summary counts that step, and so must
        -- the log; the messages were written before the log's line)
        case logRead of
          Left err -> expectationFailure err
          Right rl -> case rlSummary rl of
            Nothing -> expectationFailure "no summary"
            Just sm -> do
              fmap ("the run stopped: a write failed: " `isPrefixOf`) (lsFailure sm) `shouldBe` Just True
              map lfTime (rlFrames rl) `shouldBe` [ fromIntegral k / 25 | k <- [0 .. (lsSteps sm - 1) `div` 4] ]
              fmap lfTime (lastMaybe (rlFrames rl)) `shouldBe` Just (lsSimulated sm)
  describe "Ctrl-C and SIGTERM" $ forM_ stops $ \(name, send, expected, caps) ->
    it ("stop with exit code " ++ show expected ++ " (" ++ name ++ "), the summary, whole frames, a log with its summary and the page (+RTS -N"
        ++ show caps ++ ")") $ withTempDir $ \dir -> do
      long <- childOn "long" dir caps
      (_, Just hout, _, ph) <- createProcess long { create_group = True, std_out = CreatePipe, std_err = Inherit }
      awaitFrames dir ph
      send ph
      code <- waitForProcess ph
      code `shouldBe` ExitFailure expected
      out <- hGetContents hout
      out `shouldSatisfy` ("interrupted: " `isPrefixOf`)
      names <- listDirectory (dir </> "f")
      filter (".tmp" `isInfixOf`) names `shouldBe` []
      frames <- framesIn (dir </> "f")
      all ((== 15 + 3 * 120 * 120) . BS.length) frames `shouldBe` True
      logRead <- readLogFile (dir </> "run.jsonl")
      fmap (fmap lsInterrupted . rlSummary) logRead `shouldBe` Right (Just True)
      -- every output ends at the same step: as many frames in the log as
      -- in the folder, none past the summary's time (on one capability
      -- the signal came in the middle of a step's outputs, between the
      -- log's and the frame's, in most runs)
      fmap (length . rlFrames) logRead `shouldBe` Right (length frames)
      fmap (\rl -> (\sm -> all ((<= lsSimulated sm + 1e-9) . lfTime) (rlFrames rl)) <$> rlSummary rl) logRead
        `shouldBe` Right (Just True)
      page <- readFile (dir </> "run.html")
      "<!DOCTYPE html>" `isPrefixOf` page `shouldBe` True
  describe "frames" $ do
    it "writes one P6 frame per 1/fps of simulated time, time 0 included" $ withTempDir $ \dir -> do
      (_, _, r) <- captured (runSimWith (quick (dir </> "f")) (Just world) drive drive)
      r `shouldBe` Right ()
      frames <- framesIn (dir </> "f")
      length frames `shouldBe` 51
      let header = "P6\n620 620\n255\n"
      all ((BS.pack (map (toEnum . fromEnum) header) `BS.isPrefixOf`)) frames `shouldBe` True
      map BS.length frames `shouldBe` replicate 51 (length header + 3 * 620 * 620)
    it "shows the robot moving" $ withTempDir $ \dir -> do
      _ <- captured (runSimWith (quick dir) (Just world) drive drive)
      frames <- framesIn dir
      -- the robot has left its start
      pixel (head frames) (-3) 0 `shouldNotBe` pixel (last frames) (-3) 0
      pixel (head frames) (-3) 0 `shouldNotBe` Nothing
    it "writes byte-identical frames on two runs with the same flags" $ withTempDir $ \dir -> do
      _ <- captured (runSimWith (quick (dir </> "a")) (Just world) drive drive)
      _ <- captured (runSimWith (quick (dir </> "b")) (Just world) drive drive)
      a <- framesIn (dir </> "a")
      b <- framesIn (dir </> "b")
      (length a, a == b) `shouldBe` (51, True)
    it "a shorter run into a folder of a longer run's frames rewrites its own, keeps the others, and says so" $
      withTempDir $ \dir -> do
        let out = dir </> "f"
        _ <- captured (runSimWith (quick out) (Just world) drive drive)
        (o, _, r) <- captured (runSimWith (quick out) { optSeconds = 1, optQuiet = False } (Just world) drive drive)
        r `shouldBe` Right ()
        length <$> listDirectory out `shouldReturn` 51
        filter ("note: " `isPrefixOf`) (lines o) `shouldBe`
          [ "note: " ++ out ++ " also holds frame-000026.ppm and on, from an earlier run, left as they were: "
            ++ "this run wrote 26 frames (--video takes only those)" ]
        (_, o', _) <- captured (runSimWith (quick out) { optQuiet = False } (Just world) drive drive)
        filter ("note: " `isPrefixOf`) (lines o') `shouldBe` []
    it "--video gives ffmpeg only the run's own frames" $ withTempDir $ \dir -> do
      -- (a stand-in ffmpeg that records its arguments)
      let bin = dir </> "bin"
          out = dir </> "f"
      createDirectory bin
      -- (it makes the file named last, as ffmpeg would; FAIL in the
      -- environment: it then exits 1)
      writeScript (bin </> "ffmpeg") ("#!/bin/sh\nprintf '%s\\n' \"$@\" > " ++ (dir </> "args")
                                     ++ "\nfor a; do last=$a; done\n: > \"${last#file:}\"\n[ -z \"$FAIL\" ]\n")
      saved <- lookupEnv "PATH"
      setEnv "PATH" bin
      (do _ <- captured (runSimWith (quick out) (Just world) drive drive)
          (o, _, r) <- captured (runSimWith (quick out) { optSeconds = 1, optVideo = Just (dir </> "run.mp4") }
                                            (Just world) drive drive)
          r `shouldBe` Right ()
          -- (--quiet: only the summary, not the video's line)
          filter ("wrote" `isPrefixOf`) (lines o) `shouldBe` []
          (o', _, _) <- captured (runSimWith (quick out) { optSeconds = 1, optQuiet = False, optVideo = Just (dir </> "run.mp4") }
                                             (Just world) drive drive)
          filter (("wrote " ++ (dir </> "run.mp4")) `isPrefixOf`) (lines o') `shouldBe` ["wrote " ++ (dir </> "run.mp4")])
        `finally` maybe (pure ()) (setEnv "PATH") saved
      args <- lines <$> readFile (dir </> "args")
      take 2 (dropWhile (/= "-frames:v") args) `shouldBe` ["-frames:v", "26"]
      take 2 (dropWhile (/= "-i") args) `shouldBe` ["-i", out </> "frame-%06d.ppm"]
      -- (the names as they are: a % of the folder's is no pattern, the video is a file)
      (do setEnv "PATH" bin
          (_, _, r) <- captured (runSimWith (quick (dir </> "f%d")) { optSeconds = 0.2, optVideo = Just (dir </> "-v.mp4") }
                                            (Just world) drive drive)
          r `shouldBe` Right ())
        `finally` maybe (pure ()) (setEnv "PATH") saved
      args' <- lines <$> readFile (dir </> "args")
      take 2 (dropWhile (/= "-i") args') `shouldBe` ["-i", dir </> "f%%d" </> "frame-%06d.ppm"]
      take 2 (dropWhile (/= "-f") args') `shouldBe` ["-f", "image2"]
      -- (written beside its place, then renamed; odd sides padded)
      -- (.NAME.partialNNNN.EXT: a name of its own, made afresh)
      map (\a -> (("file:" ++ dir </> ".-v.partial") `isPrefixOf` a, ".mp4" `isSuffixOf` a)) (drop (length args' - 1) args')
        `shouldBe` [(True, True)]
      take 2 (dropWhile (/= "-vf") args') `shouldBe` ["-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"]
      doesFileExist (dir </> "-v.mp4") `shouldReturn` True
      filter (".-v.partial" `isPrefixOf`) <$> listDirectory dir `shouldReturn` []
      -- (ffmpeg fails: an earlier video of that name is left as it was)
      writeFile (dir </> "old.mp4") "old"
      (do setEnv "PATH" bin
          setEnv "FAIL" "1"
          (_, err, r) <- captured (runSimWith (quick out) { optSeconds = 0.2, optVideo = Just (dir </> "old.mp4") }
                                              (Just world) drive drive)
          r `shouldBe` Left (ExitFailure 1)
          err `shouldSatisfy` ("ffmpeg failed" `isInfixOf`))
        `finally` (unsetEnv "FAIL" >> maybe (pure ()) (setEnv "PATH") saved)
      readFile (dir </> "old.mp4") `shouldReturn` "old"
      filter (".old.partial" `isPrefixOf`) <$> listDirectory dir `shouldReturn` []
    it "--video writes its video beside its place under a name no other file has (a log, a world there is kept)" $
      withTempDir $ \dir -> do
        -- (a stand-in ffmpeg that writes the file named last, as ffmpeg
        -- -y does, over whatever is there)
        let bin = dir </> "bin"
            out = dir </> "f"
            -- (the name the video was once written under, before its
            -- rename: a file of the run's own, or another, of that name
            -- was written over, then renamed away to the video's)
            oldPartial = dir </> ".v.partial.mp4"
            worldFile = dir </> ".w.partial.mp4"
        createDirectory bin
        writeScript (bin </> "ffmpeg") "#!/bin/sh\nfor a; do last=$a; done\necho video > \"${last#file:}\"\n"
        writeFile worldFile (renderWorld world)
        saved <- lookupEnv "PATH"
        (do setEnv "PATH" bin
            (_, err, r) <- captured (runSimWith (quick out) { optSeconds = 0.2, optVideo = Just (dir </> "v.mp4")
                                                            , optLog = Just oldPartial } (Just world) drive drive)
            (r, err) `shouldBe` (Right (), "")
            (_, err', r') <- captured (runSimWith (quick out) { optSeconds = 0.2, optVideo = Just (dir </> "w.mp4")
                                                              , optWorldFile = Just worldFile } Nothing drive drive)
            (r', err') `shouldBe` (Right (), ""))
          `finally` maybe (pure ()) (setEnv "PATH") saved
        readFile (dir </> "v.mp4") `shouldReturn` "video\n"
        readFile (dir </> "w.mp4") `shouldReturn` "video\n"
        -- (the run's log, and the world the other run read, are as written)
        logRead <- readLogFile oldPartial
        fmap (isJust . rlSummary) logRead `shouldBe` Right True
        readFile worldFile `shouldReturn` renderWorld world
        -- (and no temporary file is left)
        sort <$> listDirectory dir `shouldReturn` sort ["bin", "f", ".v.partial.mp4", ".w.partial.mp4", "v.mp4", "w.mp4"]
    it "writes an SVG of the run" $ withTempDir $ \dir -> do
      _ <- captured (runSimWith (quick dir) { optFrames = False, optSvg = Just (dir </> "run.svg") }
                                (Just world) drive drive)
      svg <- readFile (dir </> "run.svg")
      ("<svg" `isPrefixOf` svg, "polyline" `isInfixOf` svg) `shouldBe` (True, True)

  describe "console" $ do
    it "prints the robots' messages and a summary" $ withTempDir $ \dir -> do
      let talk _ = proc' (after 1 "hello")
          proc' e = e >>> arr (\m -> mrFinalize (ddBrake `mrMerge` tcoPrintMessage m))
      (out, _, _) <- captured (runSimWith (quick dir) { optQuiet = False, optFrames = False }
                                          (Just world) talk talk)
      lines out `shouldSatisfy` elem "[1.00] SimbotA.1: hello"
      last (lines out) `shouldSatisfy` ("2.00 s simulated in 201 steps, 0 frames" `isPrefixOf`)

  describe "world files" $
    it "--dump-world then --world gives the same simulation" $ withTempDir $ \dir -> do
      (dumped, _, _) <- captured (runSimWith defaultSimOptions { optDumpWorld = True } (Just world) drive drive)
      writeFile (dir </> "w.world") dumped
      _ <- captured (runSimWith (quick (dir </> "a")) (Just world) drive drive)
      _ <- captured (runSimWith (quick (dir </> "b")) { optWorldFile = Just (dir </> "w.world") } Nothing drive drive)
      a <- framesIn (dir </> "a")
      b <- framesIn (dir </> "b")
      (length a, a == b) `shouldBe` (51, True)

  describe "faults" $ do
    it "rejects an unknown flag and a bad value, naming them" $ do
      parseSimArgs defaultSimOptions ["--frobnicate"] `shouldSatisfy` either ("--frobnicate" `isInfixOf`) (const False)
      parseSimArgs defaultSimOptions ["--dt", "fast"] `shouldSatisfy` either ("--dt" `isInfixOf`) (const False)
      parseSimArgs defaultSimOptions ["--seconds"] `shouldSatisfy` either ("needs a value" `isInfixOf`) (const False)
      parseSimArgs defaultSimOptions ["--keys", "1.5a"] `shouldSatisfy` either ("--keys" `isInfixOf`) (const False)
    it "parses every documented flag" $
      parseSimArgs defaultSimOptions ["--seconds", "5", "--dt", "0.02", "--fps", "10", "--out", "x", "--scale", "30"
                                     , "--keys", "1.5:a,3:b", "--seed", "7", "--quiet", "--rays", "--trails"]
        `shouldBe` Right (RunWith defaultSimOptions
          { optSeconds = 5, optDt = 0.02, optFps = 10, optOut = "x", optScale = Just 30
          , optSvg = Just ("x" </> "run.svg"), optReplay = Just ("x" </> "replay.html")
          , optKeys = [(1.5, 'a'), (3, 'b')], optSeed = 7, optQuiet = True, optRays = True, optTrails = True })
    it "reports an invalid world, naming the object, with exit code 2" $ do
      (_, err, r) <- captured (runSimWith defaultSimOptions { optFrames = False } (Just [OTSimbotB 9 (Point2 7 0) 0]) drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ("SimbotB 9" `isInfixOf`)
    it "reports a malformed world file with its line and column, simulating nothing" $ withTempDir $ \dir -> do
      writeFile (dir </> "bad.world") "ball at 0 0\nwall v at 1 x2\n"
      (_, err, r) <- captured (runSimWith (quick (dir </> "f")) { optWorldFile = Just (dir </> "bad.world") } Nothing drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ((dir </> "bad.world:2:13:") `isInfixOf`)
      listDirectory dir `shouldReturn` ["bad.world"]
    it "reports an output folder that cannot be written, before simulating" $ withTempDir $ \dir -> do
      writeFile (dir </> "file") "not a folder"
      (out, err, r) <- captured (runSimWith (quick (dir </> "file" </> "frames")) (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ("cannot write frames" `isInfixOf`)
      out `shouldBe` ""
    it "reports a controller that throws with the robot and the time, exit code 1" $ withTempDir $ \dir -> do
      let bad _ = localTime >>> arr (\t -> mrFinalize (tcoPrintMessage
                    (if t >= 0.5 then merge (Event "a") (Event "b") else NoEvent)))
      (_, err, r) <- captured (runSimWith (quick dir) (Just world) bad drive)
      r `shouldBe` Left (ExitFailure 1)
      err `shouldSatisfy` ("SimbotA 1" `isInfixOf`)
      err `shouldSatisfy` ("0.500" `isInfixOf`)
      err `shouldSatisfy` ("simultaneous" `isInfixOf`)

  describe "checks before the run (exit code 2, nothing simulated, nothing written)" $ do
    let refused opts check = withTempDir $ \dir -> do
          (out, err, r) <- captured (runSimWith (opts dir) (Just world) drive drive)
          r `shouldBe` Left (ExitFailure 2)
          out `shouldBe` ""
          err `shouldSatisfy` check
          listDirectory dir `shouldReturn` []
    it "an --svg, --log or --replay in a folder that does not exist, all reported in one message" $
      refused (\dir -> (quick (dir </> "f")) { optSvg = Just (dir </> "no" </> "run.svg")
                                            , optLog = Just (dir </> "nolog" </> "run.jsonl")
                                            , optReplay = Just (dir </> "nopage" </> "r.html") })
              (\e -> all (`isInfixOf` e) ["--svg", "--log", "--replay", "does not exist"]
                     && length (filter ("cannot run" `isInfixOf`) (lines e)) == 1)
    it "a run refused before its first step leaves an existing log as it was (it replaced it with an empty log)" $
      withTempDir $ \dir -> do
        let logFile = dir </> "run.jsonl"
            keeps wrap opts = do
              writeFile logFile "old\n"
              (_, err, r) <- captured (wrap (runSimWith opts { optLog = Just logFile } (Just world) drive drive))
              r `shouldBe` Left (ExitFailure 2)
              readFile logFile `shouldReturn` "old\n"
              pure err
        -- the page's temporary file cannot be made (TMPDIR), the frames' folder cannot be
        err1 <- keeps (withTMPDIR (dir </> "no-such-folder")) (quick (dir </> "f")) { optReplay = Just (dir </> "r.html") }
        err1 `shouldSatisfy` ("its temporary file" `isInfixOf`)
        err2 <- keeps id (quick (logFile </> "frames"))
        err2 `shouldSatisfy` ("cannot write frames" `isInfixOf`)
    it "an output that is a link to a file in a folder that does not exist" $ withTempDir $ \dir -> do
      createFileLink (dir </> "gone" </> "run.svg") (dir </> "link.svg")
      (out, err, r) <- captured (runSimWith (quick (dir </> "f")) { optFrames = False, optSvg = Just (dir </> "link.svg") }
                                            (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 2)
      out `shouldBe` ""
      err `shouldSatisfy` (\e -> all (`isInfixOf` e) ["--svg", "does not exist"])
      listDirectory dir `shouldReturn` ["link.svg"]
    it "not an output that is a link into the output folder, which the run creates" $ withTempDir $ \dir -> do
      createFileLink (dir </> "out" </> "via.jsonl") (dir </> "tolog.jsonl")
      (_, err, r) <- captured (runSimWith (quick (dir </> "out")) { optFrames = False, optSeconds = 0.1
                                                                   , optSvg = Just (dir </> "out" </> "run.svg")
                                                                   , optReplay = Nothing
                                                                   , optLog = Just (dir </> "tolog.jsonl") }
                                          (Just world) drive drive)
      r `shouldBe` Right ()
      err `shouldBe` ""
      sort <$> listDirectory (dir </> "out") `shouldReturn` ["run.svg", "via.jsonl"]
    it "an output that is a loop of symbolic links" $ withTempDir $ \dir -> do
      createFileLink (dir </> "la.svg") (dir </> "lb.svg")
      createFileLink (dir </> "lb.svg") (dir </> "la.svg")
      (out, err, r) <- captured (runSimWith (quick (dir </> "f")) { optFrames = False, optSvg = Just (dir </> "la.svg") }
                                            (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 2)
      out `shouldBe` ""
      err `shouldSatisfy` (\e -> all (`isInfixOf` e) ["--svg", "loop of symbolic links"])
    it "two outputs that are the same file under two names" $
      refused (\dir -> (quick (dir </> "f")) { optSvg = Just (dir </> "a.svg"), optLog = Just (dir </> "." </> "a.svg") })
              (\e -> all (`isInfixOf` e) ["same file", "--svg", "--log"])
    it "but not two outputs to devices (/dev/stdout and /dev/stderr may be one terminal or pipe)" $ do
      (_, err, r) <- captured (runSimWith (quick "f") { optFrames = False, optSeconds = 0.1
                                                      , optLog = Just "/dev/null", optResult = Just "/dev/null" }
                                          (Just world) drive drive)
      r `shouldBe` Right ()
      err `shouldBe` ""
    it "an output that would overwrite the world file, which is left as it was" $ withTempDir $ \dir -> do
      let wf = dir </> "w.world"
      writeFile wf "ball at 0 0\n"
      (out, err, r) <- captured (runSimWith (quick (dir </> "f")) { optWorldFile = Just wf, optFrames = False
                                                                   , optLog = Just (dir </> "." </> "w.world") }
                                            Nothing drive drive)
      r `shouldBe` Left (ExitFailure 2)
      out `shouldBe` ""
      err `shouldSatisfy` ("--log" `isInfixOf`)
      err `shouldSatisfy` ("would overwrite the world file" `isInfixOf`)
      readFile wf `shouldReturn` "ball at 0 0\n"
    it "an output named as the output folder, refused before anything is made (it failed after the run, the folder made)" $
      withTempDir $ \dir -> do
        let fw = dir </> "f"
        -- with the frames; without them, where the page goes by default;
        -- through another spelling and through a link
        createFileLink "f" (dir </> "l")
        forM_ [ (quick fw) { optSvg = Just fw }
              , (quick fw) { optFrames = False, optLog = Just fw, optReplay = Just (fw </> "replay.html") }
              , (quick fw) { optResult = Just (dir </> "." </> "f" ++ "/") }
              , (quick fw) { optLog = Just (dir </> "l") } ] $ \o -> do
          (out, err, r) <- captured (runSimWith o { optSeconds = 0.2 } (Just world) drive drive)
          r `shouldBe` Left (ExitFailure 2)
          out `shouldBe` ""
          err `shouldSatisfy` (("is the output folder (--out " ++ show fw ++ ")") `isInfixOf`)
          doesPathExist fw `shouldReturn` False
    it "an output that is a hard link to the world file (one file under two names no path shows)" $ withTempDir $ \dir -> do
      let wf = dir </> "w.world"
      writeFile wf "ball at 0 0\n"
      createLink wf (dir </> "r.json")
      (out, err, r) <- captured (runSimWith (quick (dir </> "f")) { optWorldFile = Just wf, optFrames = False
                                                                   , optResult = Just (dir </> "r.json") }
                                            Nothing drive drive)
      r `shouldBe` Left (ExitFailure 2)
      out `shouldBe` ""
      err `shouldSatisfy` (("--result " ++ show (dir </> "r.json") ++ " would overwrite the world file") `isInfixOf`)
      readFile wf `shouldReturn` "ball at 0 0\n"
    it "a world file or an output named as a frame in the frames' folder (a frame would replace it)" $
      withTempDir $ \dir -> do
        let fw = dir </> "f"
            wf = fw </> "frame-000001.ppm"
        createDirectory fw
        writeFile wf "ball at 0 0\n"
        -- the world file itself, and through a link
        createFileLink wf (dir </> "w.world")
        forM_ [wf, dir </> "w.world"] $ \w -> do
          (out, err, r) <- captured (runSimWith (quick fw) { optWorldFile = Just w, optSeconds = 0.2 } Nothing drive drive)
          r `shouldBe` Left (ExitFailure 2)
          out `shouldBe` ""
          err `shouldSatisfy` (("--world " ++ show w ++ " would be overwritten by a frame") `isInfixOf`)
        -- an output by a frame's name, or its temporary file's, under
        -- another spelling of the folder
        forM_ [ (quick (fw ++ "/")) { optSvg = Just (dir </> "." </> "f" </> "frame-000003.ppm.tmp") }
              , (quick fw) { optResult = Just (fw </> "frame-1000000.ppm") } ] $ \o -> do
          (_, err, r) <- captured (runSimWith o { optSeconds = 0.2 } (Just world) drive drive)
          r `shouldBe` Left (ExitFailure 2)
          err `shouldSatisfy` ("would be overwritten by a frame" `isInfixOf`)
        readFile wf `shouldReturn` "ball at 0 0\n"
        -- without --frames nothing is written there: the world is read
        (_, err, r) <- captured (runSimWith (quick fw) { optWorldFile = Just wf, optFrames = False, optSeconds = 0.2 }
                                            Nothing drive drive)
        r `shouldBe` Right ()
        err `shouldSatisfy` ("has no robots" `isInfixOf`)
        -- and names that are no frame's are free (the run writes its frames beside them)
        writeFile (fw </> "frame-1.ppm") "keep"
        writeFile (fw </> ".afrp-write-test") "keep too"
        (_, err', r') <- captured (runSimWith (quick fw) { optSeconds = 0.2 } (Just world) drive drive)
        r' `shouldBe` Right ()
        err' `shouldBe` ""
        readFile (fw </> "frame-1.ppm") `shouldReturn` "keep"
        readFile (fw </> ".afrp-write-test") `shouldReturn` "keep too"
        doesFileExist (fw </> "frame-000005.ppm") `shouldReturn` True
    it "a world file with no robots (empty, or a generator's output that never came) runs, with a warning" $
      withTempDir $ \dir -> do
        let wf = dir </> "w.world"
        writeFile wf "# nothing yet\nball at 0 0\n"
        (out, err, r) <- captured (runSimWith (quick (dir </> "f")) { optWorldFile = Just wf, optFrames = False }
                                              Nothing drive drive)
        r `shouldBe` Right ()
        out `shouldSatisfy` ("2.00 s simulated" `isPrefixOf`)
        lines err `shouldSatisfy` any (("warning: the world " ++ wf ++ " has no robots") `isInfixOf`)
        (_, err', _) <- captured (runSimWith (quick (dir </> "f")) { optFrames = False } (Just world) drive drive)
        err' `shouldBe` ""
    it "two outputs that are hard links to one file" $ withTempDir $ \dir -> do
      writeFile (dir </> "a.svg") ""
      createLink (dir </> "a.svg") (dir </> "b.jsonl")
      (_, err, r) <- captured (runSimWith (quick (dir </> "f")) { optFrames = False, optSvg = Just (dir </> "a.svg")
                                                               , optLog = Just (dir </> "b.jsonl") }
                                          (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` (\e -> all (`isInfixOf` e) ["same file", "--svg", "--log"])
    it "not an --out with a trailing slash: the folder is created, with the SVG and the page in it" $ withTempDir $ \dir -> do
      let o = (quick (dir </> "new/")) { optFrames = False, optSeconds = 0.1
                                       , optSvg = Just (dir </> "new/run.svg"), optReplay = Just (dir </> "new/replay.html") }
      (_, err, r) <- captured (runSimWith o (Just world) drive drive)
      err `shouldBe` ""
      r `shouldBe` Right ()
      sort <$> listDirectory (dir </> "new") `shouldReturn` ["replay.html", "run.svg"]
    it "an --out whose parent folder does not exist, not said to be for frames when there are none" $
      refused (\dir -> (quick (dir </> "a" </> "b")) { optFrames = False, optSvg = Just (dir </> "a" </> "b" </> "run.svg") })
              (\e -> "output folder (--out)" `isInfixOf` e && not ("frames" `isInfixOf` e))
    it "an --svg whose folder is a file, said so" $ withTempDir $ \dir -> do
      writeFile (dir </> "afile") ""
      (_, err, r) <- captured (runSimWith (quick (dir </> "f")) { optFrames = False, optSvg = Just (dir </> "afile" </> "run.svg") }
                                          (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` (("run.svg\": its folder, " ++ show (dir </> "afile") ++ ", is not a folder") `isInfixOf`)
    it "an --svg named as a folder (foo/.., with --out foo; x/), before the run (it failed after it)" $ withTempDir $ \dir -> do
      let o = (quick (dir </> "foo")) { optSvg = Just (dir </> "foo" </> "..") }
      (out, err, r) <- captured (runSimWith o (Just world) drive drive)
      (r, out) `shouldBe` (Left (ExitFailure 2), "")
      err `shouldSatisfy` ((show (dir </> "foo" </> "..") ++ " names a folder, not a file") `isInfixOf`)
      doesPathExist (dir </> "foo") `shouldReturn` False
      refused (\d -> (quick (d </> "f")) { optFrames = False, optSvg = Just (d </> "x/") })
              ("/x/\" names a folder, not a file" `isInfixOf`)
    it "an existing folder given as --out and as --svg: one message, not two (it was also \"is a folder\")" $ withTempDir $ \dir -> do
      createDirectory (dir </> "o")
      (out, err, r) <- captured (runSimWith (quick (dir </> "o")) { optSvg = Just (dir </> "o") } (Just world) drive drive)
      (r, out) `shouldBe` (Left (ExitFailure 2), "")
      lines err `shouldBe` [ "afrp-spec: cannot run:"
                           , "  --svg " ++ show (dir </> "o") ++ " is the output folder (--out " ++ show (dir </> "o")
                             ++ "), where the run writes the frames: choose another name" ]
    it "a --result or --log in the kernel's /proc or /sys, before the run (it failed after it, saying \"does not exist\")" $ do
      refused (\d -> (quick (d </> "f")) { optFrames = False, optResult = Just "/proc/version" })
              ("--result \"/proc/version\": a file of the kernel's /proc or /sys, which takes no output" `isInfixOf`)
      refused (\d -> (quick (d </> "f")) { optFrames = False, optLog = Just "/proc/new.jsonl" })
              ("--log \"/proc/new.jsonl\": no file can be made there" `isInfixOf`)
    it "an --out that is a file, said so (not \"already exists\"), the file left as it was" $ withTempDir $ \dir -> do
      writeFile (dir </> "afile") "mine"
      (out, err, r) <- captured (runSimWith (quick (dir </> "afile")) (Just world) drive drive)
      (r, out) `shouldBe` (Left (ExitFailure 2), "")
      err `shouldSatisfy` (("cannot write frames to " ++ show (dir </> "afile") ++ ": it is a file, not a folder") `isInfixOf`)
      readFile (dir </> "afile") `shouldReturn` "mine"
    it "an --out whose parent folder does not exist" $
      refused (\dir -> quick (dir </> "a" </> "b")) ("does not exist" `isInfixOf`)
    it "an --out whose parent folder does not exist, said with the other faults (it was said only once they were mended)" $
      refused (\dir -> (quick (dir </> "a" </> "b")) { optLog = Just (dir </> "nolog" </> "run.jsonl") })
              (\e -> all (`isInfixOf` e) ["--log", "cannot write frames to", "a" </> "b" ++ "\": the folder"]
                     && length (filter ("cannot run" `isInfixOf`) (lines e)) == 1)
    it "an --out that is a symbolic link to nothing, said so with the other faults (it was not listed; alone, \"already exists\")" $
      withTempDir $ \dir -> do
        createFileLink (dir </> "gone") (dir </> "out")
        let saying = "cannot write frames to " ++ show (dir </> "out") ++ ": it is a symbolic link to "
                     ++ show (dir </> "gone") ++ ", which does not exist"
        (out, err, r) <- captured (runSimWith (quick (dir </> "out")) { optLog = Just (dir </> "nolog" </> "run.jsonl") }
                                              (Just world) drive drive)
        (r, out) `shouldBe` (Left (ExitFailure 2), "")
        map (dropWhile (== ' ')) (lines err) `shouldSatisfy` \ls -> elem saying ls && any ("--log" `isPrefixOf`) ls
        (out', err', r') <- captured (runSimWith (quick (dir </> "out")) (Just world) drive drive)
        (r', out') `shouldBe` (Left (ExitFailure 2), "")
        lines err' `shouldBe` ["afrp-spec: cannot run:", "  " ++ saying]
        doesPathExist (dir </> "gone") `shouldReturn` False
    it "an --out whose parent folder may not be searched, and an --svg in it, said so with the other faults (it said \"does not exist\", and the --svg failed after the run; as root, every folder may be)" $
      withTempDir $ \dir -> withUnsearchable dir $ \_ -> do
          let o = (quick (dir </> "locked" </> "sub" </> "out")) { optLog = Just (dir </> "nolog" </> "run.jsonl")
                                                                 , optSvg = Just (dir </> "locked" </> "a.svg") }
          (out, err, r) <- captured (runSimWith o (Just world) drive drive)
          (r, out) `shouldBe` (Left (ExitFailure 2), "")
          map (dropWhile (== ' ')) (lines err) `shouldSatisfy` \ls ->
            elem ("cannot write frames to " ++ show (dir </> "locked" </> "sub" </> "out") ++ ": it cannot be reached: the folder "
                  ++ show (dir </> "locked") ++ " on its path may not be searched (no x permission)") ls
            && any ("--log" `isPrefixOf`) ls
            -- (a file in it was refused only after the run, by the write)
            && elem ("--svg " ++ show (dir </> "locked" </> "a.svg") ++ ": its folder, " ++ show (dir </> "locked")
                     ++ ", may not be searched (no x permission)") ls
    it "an empty --out (set in code, an empty optOut, said so)" $ do
      parseSimArgs defaultSimOptions ["--out", ""] `shouldSatisfy` either ("--out" `isInfixOf`) (const False)
      refused (\_ -> (quick "") { optFrames = True }) ("optOut must not be empty" `isInfixOf`)
    it "optDumpWorld and optPrintProgram set together in code: refused before either prints (the name alone was printed)" $ do
      (out, err, r) <- captured (runSimWith (quick "unused") { optDumpWorld = True, optPrintProgram = True } (Just world) drive drive)
      (r, out) `shouldBe` (Left (ExitFailure 2), "")
      lines err `shouldBe` [ "afrp-spec: cannot run:"
                           , "  --dump-world and --print-program (optDumpWorld and optPrintProgram) each print something and exit: ask for one" ]
      doesPathExist "unused" `shouldReturn` False
    it "a step count that overflows or is beyond the maximum" $ do
      refused (\dir -> (quick dir) { optSeconds = 1e20 }) ("steps" `isInfixOf`)
      refused (\dir -> (quick dir) { optDt = 1e-300 }) ("steps" `isInfixOf`)
      refused (\dir -> (quick dir) { optSeconds = 0 / 0 }) ("finite" `isInfixOf`)
      parseSimArgs defaultSimOptions ["--seconds", "1e20"] `shouldSatisfy` either ("steps" `isInfixOf`) (const False)
      parseSimArgs defaultSimOptions ["--dt", "NaN"] `shouldSatisfy` either ("--dt" `isInfixOf`) (const False)
    it "a --scale beyond a sane frame" $
      refused (\dir -> (quick dir) { optScale = Just 5000 }) ("--scale" `isInfixOf`)
    it "a --dt that does not divide the frame period, saying which --fps would work" $ do
      refused (\dir -> (quick dir) { optDt = 0.03 }) ("--fps 33.333 or 16.667 would work" `isInfixOf`)
      validateOptions defaultSimOptions { optDt = 0.03, optFps = 33.333 } `shouldBe` []
      validateOptions defaultSimOptions { optFps = 1e-300 } `shouldSatisfy` any ("--fps" `isInfixOf`)
    it "--video without ffmpeg on the PATH" $ withTempDir $ \empty -> do
      saved <- lookupEnv "PATH"
      setEnv "PATH" empty
      (do refused (\dir -> (quick (dir </> "f")) { optVideo = Just (dir </> "run.mp4") }) ("ffmpeg" `isInfixOf`))
        `finally` maybe (pure ()) (setEnv "PATH") saved
    it "--video without --frames" $
      refused (\dir -> (quick (dir </> "f")) { optFrames = False, optVideo = Just (dir </> "run.mp4") })
              ("--frames" `isInfixOf`)

  describe "writes that fail during the run (exit code 1, the summary so far)" $ do
    it "a full disk for the SVG (/dev/full)" $ withTempDir $ \dir -> do
      (out, err, r) <- captured (runSimWith (quick dir) { optFrames = False, optSvg = Just "/dev/full" } (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 1)
      out `shouldSatisfy` ("2.00 s simulated" `isInfixOf`)
      err `shouldSatisfy` ("/dev/full" `isInfixOf`)
    it "says \"wrote\" of the outputs written and of no other" $ withTempDir $ \dir -> do
      let page = dir </> "page.html"
      (out, _, r) <- captured (runSimWith (quick dir) { optFrames = False, optSvg = Just "/dev/full"
                                                     , optReplay = Just page, optQuiet = False } (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 1)
      filter ("wrote" `isPrefixOf`) (lines out) `shouldBe` ["wrote " ++ page ++ " (open it in a browser)"]
    it "names a written file whose name has a control character in quotes, escaped, on one line" $ withTempDir $ \dir -> do
      let svg = dir </> "run\nwrote forged.svg"
      (out, _, r) <- captured (runSimWith (quick dir) { optFrames = False, optSvg = Just svg, optQuiet = False }
                                          (Just world) drive drive)
      r `shouldBe` Right ()
      doesFileExist svg `shouldReturn` True
      filter ("wrote" `isPrefixOf`) (lines out) `shouldBe` ["wrote " ++ show svg]
    it "a robot's message the terminal cannot show does not stop the run: controls escaped, the rest substituted" $
      withTempDir $ \dir -> do
        let talk _ = constant (mrFinalize (ddVelDiff 1 1 `mrMerge` tcoPrintMessage (Event "caf\233 \ESC[2J\nforged \xD800")))
        (out, _, r) <- captured $ do
          -- standard output as a batch job's C locale has it: ASCII only
          hSetEncoding stdout =<< mkTextEncoding "ASCII"
          runSimWith (quick dir) { optFrames = False, optSeconds = 0.02, optQuiet = False } (Just world) talk talk
        r `shouldBe` Right ()
        let said = filter ("SimbotA.1: caf" `isInfixOf`) (lines out)
        length said `shouldBe` 3   -- t = 0, 0.01, 0.02: one line each
        said `shouldSatisfy` all (\l -> "\\ESC[2J\\nforged \\55296" `isInfixOf` l && all (\c -> c >= ' ' && c < '\DEL') l)
    it "a failed write naming a file with a control character: the message is printable" $ withTempDir $ \dir -> do
      let svg = dir </> "no\ESC[2Jdir" </> "run.svg"
      (_, err, r) <- captured (runSimWith (quick dir) { optFrames = False, optSvg = Just svg } (Just world) drive drive)
      r `shouldSatisfy` either (/= ExitSuccess) (const False)
      err `shouldSatisfy` ("\\ESC[2J" `isInfixOf`)
      err `shouldSatisfy` all (\c -> isPrint c || c == '\n' || c == '\r')
    it "a full disk for the log (/dev/full)" $ withTempDir $ \dir -> do
      (_, err, r) <- captured (runSimWith (quick dir) { optFrames = False, optLog = Just "/dev/full" } (Just world) drive drive)
      r `shouldSatisfy` either (/= ExitSuccess) (const False)
      err `shouldSatisfy` ("/dev/full" `isInfixOf`)
    it "a frame that cannot be written stops the run, leaving whole frames and no .tmp file" $ withTempDir $ \dir -> do
      let out = dir </> "f"
      createDirectory out
      createDirectory (out </> "frame-000003.ppm")   -- in the way of the fourth frame
      (o, err, r) <- captured (runSimWith (quick out) { optLog = Just (dir </> "run.jsonl")
                                                      , optResult = Just (dir </> "r.json") } (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 1)
      -- (the step of the fourth frame, 0.12 s, counts: the log took it,
      -- before the frames did)
      o `shouldSatisfy` ("stopped: 0.12 s simulated in 13 steps, 3 frames" `isInfixOf`)
      err `shouldSatisfy` ("a write failed" `isInfixOf`)
      names <- listDirectory out
      filter (".tmp" `isInfixOf`) names `shouldBe` []
      length names `shouldBe` 4
      -- the log's summary and the result line say what stopped the run
      logRead <- readLogFile (dir </> "run.jsonl")
      fmap (fmap (\sm -> (lsInterrupted sm, fmap ("the run stopped: a write failed: " `isPrefixOf`) (lsFailure sm)))
              . rlSummary) logRead
        `shouldBe` Right (Just (False, Just True))
      -- no output holds a step past the summary's: the log's last frame
      -- is the step it says was simulated last, and so is the result's
      fmap (\rl -> (map lfTime (rlFrames rl), fmap (\sm -> (lsSimulated sm, lsSteps sm)) (rlSummary rl))) logRead
        `shouldBe` Right ([0, 0.04, 0.08, 0.12], Just (0.12, 13))
      result <- readFile (dir </> "r.json")
      result `shouldSatisfy` ("\"failure\":\"the run stopped: a write failed: " `isInfixOf`)
      result `shouldSatisfy` ("\"simulated\":0.12,\"steps\":13," `isInfixOf`)

  describe "every core: the outputs written by a thread of their own (two capabilities)" $ do
    let talk _ = localTime >>> arr (\t -> mrFinalize (ddVelDiff 0.7 0.9 `mrMerge` tcoPrintMessage
                   (if t > 0.3 && t < 0.35 then Event ("at " ++ show t) else NoEvent)))
        full dir = (quick (dir </> "f")) { optSeconds = 1.5, optQuiet = False, optTrails = True
                                          , optSvg = Just (dir </> "run.svg"), optLog = Just (dir </> "run.jsonl")
                                          , optReplay = Just (dir </> "run.html"), optResult = Just (dir </> "r.json") }
        -- every output of a run, the wall-clock times (and the page's
        -- nonce, a hash that includes them) blanked
        outputs dir out = do
          frames <- framesIn (dir </> "f")
          texts <- mapM (fmap blankWall . readFile . (dir </>)) ["run.svg", "run.jsonl", "run.html", "r.json"]
          pure (frames, texts, blankWall out)
        twoRuns opts ctl = withTempDir $ \d1 -> withTempDir $ \d2 -> do
          (o1, _, r1) <- withCaps 1 (captured (runSimWith (opts d1) (Just world) ctl drive))
          (o2, _, r2) <- withCaps 2 (captured (runSimWith (opts d2) (Just world) ctl drive))
          r2 `shouldBe` r1
          a <- outputs d1 (replaceAll d1 "D" o1)
          b <- outputs d2 (replaceAll d2 "D" o2)
          pure (a, b, o2)
    it "writes the same frames, SVG, log, page, result and console lines as one capability" $ do
      ((f1, t1, o1), (f2, t2, o2), _) <- twoRuns full talk
      length f1 `shouldBe` 38
      (f2, t2, o2) `shouldBe` (f1, t1, o1)
      o1 `shouldSatisfy` ("SimbotA.1: at 0.31" `isInfixOf`)
    it "stops at the same state when a frame cannot be written" $ do
      let blocked dir = (full dir) { optSvg = Nothing, optLog = Nothing, optReplay = Nothing, optResult = Nothing }
      withTempDir $ \dir -> do
        createDirectory (dir </> "f")
        createDirectory (dir </> "f" </> "frame-000003.ppm")
        (o, _, r) <- withCaps 2 (captured (runSimWith (blocked dir) (Just world) talk drive))
        r `shouldBe` Left (ExitFailure 1)
        -- (as on one capability: the step of the frame that failed counts)
        o `shouldSatisfy` ("stopped: 0.12 s simulated in 13 steps, 3 frames" `isInfixOf`)
        listDirectory (dir </> "f") >>= (`shouldBe` 4) . length
    it "writes the same outputs as one capability when a controller fails" $ do
      let bad _ = localTime >>> arr (\t -> mrFinalize (tcoPrintMessage
                    (if t >= 0.5 then merge (Event "a") (Event "b") else NoEvent)))
      ((f1, t1, o1), (f2, t2, o2), out) <- twoRuns full bad
      (f2, t2, o2) `shouldBe` (f1, t1, o1)
      out `shouldSatisfy` ("failed: 0.49 s simulated" `isInfixOf`)

  describe "the run log and the replay page" $ do
    it "--log and --replay with --no-frames: a log of every frame period and a page" $ withTempDir $ \dir -> do
      (_, _, r) <- captured (runSimWith (quick dir) { optFrames = False, optLog = Just (dir </> "run.jsonl")
                                                    , optReplay = Just (dir </> "run.html") } (Just world) drive drive)
      r `shouldBe` Right ()
      Right l <- readLogFile (dir </> "run.jsonl")
      length (rlFrames l) `shouldBe` 51
      fmap (\s -> (lsSteps s, lsFrames s, lsInterrupted s, lsFailure s)) (rlSummary l) `shouldBe` Just (201, 51, False, Nothing)
      page <- readFile (dir </> "run.html")
      ("<!DOCTYPE html>" `isPrefixOf` page, "afrp-log" `isInfixOf` page) `shouldBe` (True, True)
      fmap leCutLine <$> writeReplayFromLog (dir </> "run.jsonl") (dir </> "again.html") `shouldReturn` Right Nothing
      readFile (dir </> "again.html") `shouldReturn` page
    it "simbot --replay-from: exit 0 with the page, 2 for what it refuses before writing, 1 for a write that fails (it was 2)" $
      withTempDir $ \dir -> do
        (_, _, r) <- captured (runSimWith (quick dir) { optFrames = False, optLog = Just (dir </> "run.jsonl"), optReplay = Nothing }
                                          (Just world) drive drive)
        r `shouldBe` Right ()
        let logPath = dir </> "run.jsonl"
        replayFrom ["--replay", dir </> "run.html", "--replay-from", logPath]
          `shouldReturn` (ExitSuccess, "wrote " ++ dir </> "run.html\n", "")
        (code1, out1, err1) <- replayFrom ["--replay-from", logPath, "--replay", "/dev/full"]
        (code1, out1) `shouldBe` (ExitFailure 1, "")
        err1 `shouldSatisfy` ("simbot: cannot write the page: /dev/full" `isPrefixOf`)
        -- (refused before anything is written: the command line, a page
        -- in no folder, a log that is not there)
        replayFrom ["--replay-from"] `shouldReturn`
          ( ExitFailure 2, ""
          , "simbot: --replay-from needs the name of the run log to read (written with --log): --replay-from FILE.jsonl"
            ++ " --replay OUT.html\n" )
        (code2, _, err2) <- replayFrom ["--replay-from", logPath, "--replay", dir </> "no" </> "p.html"]
        (code2, "simbot: cannot write the page " `isPrefixOf` err2) `shouldBe` (ExitFailure 2, True)
        (code3, _, err3) <- replayFrom ["--replay-from", dir </> "none.jsonl", "--replay", dir </> "p.html"]
        (code3, (dir </> "none.jsonl") `isInfixOf` err3) `shouldBe` (ExitFailure 2, True)
    it "simbot --replay-from ... --help: the usage of simbot --help, exit 0, nothing written (it exited 2: \"takes no other argument\"); a fault before --help is still refused" $
      withTempDir $ \dir -> do
        let page = dir </> "p.html"
        replayFrom ["--replay-from", dir </> "x.jsonl", "--replay", page, "--help"]
          `shouldReturn` (ExitSuccess, usage "simbot" ++ "\n", "")
        replayFrom ["--replay", page, "--replay-from", dir </> "x.jsonl", "-h"]
          `shouldReturn` (ExitSuccess, usage "simbot" ++ "\n", "")
        ("--replay-from F.jsonl --replay OUT.html" `isInfixOf` usage "simbot") `shouldBe` True
        doesPathExist page `shouldReturn` False
        replayFrom ["--replay-from", dir </> "x.jsonl", "--seconds", "3", "--help"] `shouldReturn`
          (ExitFailure 2, "", "simbot: --replay-from FILE.jsonl --replay OUT.html takes no other argument, got \"--seconds\"\n")
    it "a run longer than the page's 9000 frames keeps one frame period in k, evenly; the log keeps them all" $ withTempDir $ \dir -> do
      -- 400 s at 25 frames a second: 10,001 frame periods, so one in 2
      (out, _, r) <- captured (runSimWith (quick dir) { optSeconds = 400, optDt = 0.04, optFrames = False, optQuiet = False
                                                    , optLog = Just (dir </> "run.jsonl")
                                                    , optReplay = Just (dir </> "run.html") } (Just world) drive drive)
      r `shouldBe` Right ()
      Right l <- readLogFile (dir </> "run.jsonl")
      length (rlFrames l) `shouldBe` 10001
      page <- readFile (dir </> "run.html")
      occurrences "\"kind\":\"frame\"" page `shouldBe` 5001
      out `shouldSatisfy` ("keeps one frame period in 2" `isInfixOf`)
    it "a run that goes its planned length keeps its planned thinning: its log thinned to one frame period in 2, byte for byte (fixed)" $
      withTempDir $ \dir -> do
        (_, _, r) <- restlessRun dir 400 (1 / 0)
        r `shouldBe` Right ()
        Right l <- readLogFile (dir </> "run.jsonl")
        -- (not vacuous: bumps and messages in frames the page leaves out)
        length [ () | f <- every2nd (drop 1 (rlFrames l)), _ <- lfEvents f ] `shouldSatisfy` (>= 5)
        length [ () | f <- every2nd (drop 1 (rlFrames l)), r' <- lfRobots f, _ <- lrMessages r' ] `shouldSatisfy` (> 1000)
        readFile (dir </> "run.html") `shouldReturn` thinnedPage 2 l
    it "a run that fails early gets the page of the length it ran: every frame period of its 100 s of a planned 400 (it kept one in 2)" $
      withTempDir $ \dir -> do
        (out, _, r) <- restlessRun dir 400 100
        r `shouldBe` Left (ExitFailure 1)
        Right l <- readLogFile (dir </> "run.jsonl")
        length (rlFrames l) `shouldBe` 2500
        fmap (fmap ("gave up at 100" `isInfixOf`) . lsFailure) (rlSummary l) `shouldBe` Just (Just True)
        -- (the log's own page, byte for byte)
        fmap leCutLine <$> writeReplayFromLog (dir </> "run.jsonl") (dir </> "again.html") `shouldReturn` Right Nothing
        page <- readFile (dir </> "run.html")
        readFile (dir </> "again.html") `shouldReturn` page
        out `shouldNotSatisfy` ("keeps one frame period" `isInfixOf`)
    it "a run that fails at 500 s of a planned 1200 keeps one frame period in 2 (it kept one in 4), with the events and messages of the others" $
      withTempDir $ \dir -> do
        (out, _, r) <- restlessRun dir 1200 500
        r `shouldBe` Left (ExitFailure 1)
        Right l <- readLogFile (dir </> "run.jsonl")
        length (rlFrames l) `shouldBe` 12500
        length [ () | f <- every2nd (drop 1 (rlFrames l)), _ <- lfEvents f ] `shouldSatisfy` (>= 20)
        readFile (dir </> "run.html") `shouldReturn` thinnedPage 2 l
        out `shouldSatisfy` ("this run's page keeps one frame period in 2" `isInfixOf`)
    it "a controller's failure closes the log with the failure and still writes the page" $ withTempDir $ \dir -> do
      let bad _ = localTime >>> arr (\t -> mrFinalize (tcoPrintMessage
                    (if t >= 0.5 then merge (Event "a") (Event "b") else NoEvent)))
      (_, _, r) <- captured (runSimWith (quick dir) { optFrames = False, optLog = Just (dir </> "run.jsonl")
                                                    , optReplay = Just (dir </> "run.html") } (Just world) bad drive)
      r `shouldBe` Left (ExitFailure 1)
      Right l <- readLogFile (dir </> "run.jsonl")
      fmap (fmap ("SimbotA 1" `isInfixOf`) . lsFailure) (rlSummary l) `shouldBe` Just (Just True)
      page <- readFile (dir </> "run.html")
      "simultaneous" `isInfixOf` page `shouldBe` True
    it "the defaults write the SVG and the page into simbot-out, no frames; --out moves them" $ do
      (optFrames defaultSimOptions, optSvg defaultSimOptions, optReplay defaultSimOptions)
        `shouldBe` (False, Just ("simbot-out" </> "run.svg"), Just ("simbot-out" </> "replay.html"))
      fmap (\c -> case c of RunWith o -> Just (optSvg o, optReplay o, optFrames o, isJust (optLog o)); ShowHelp -> Nothing)
           (parseSimArgs defaultSimOptions ["--out", "x", "--frames", "--log", "l.jsonl"])
        `shouldBe` Right (Just (Just ("x" </> "run.svg"), Just ("x" </> "replay.html"), True, True))
      fmap (\c -> case c of RunWith o -> (optSvg o, optReplay o); ShowHelp -> (Nothing, Nothing))
           (parseSimArgs defaultSimOptions ["--no-svg", "--replay", "p.html"])
        `shouldBe` Right (Nothing, Just "p.html")
  where
    pixel :: BS.ByteString -> Double -> Double -> Maybe (Word8, Word8, Word8)
    pixel bytes x y = ppmAt bytes (worldPx x) (worldPy y)
    worldPx x = round ((x + 5) * 60 + 10) :: Int
    worldPy y = round ((5 - y) * 60 + 10) :: Int
    ppmAt bytes px py =
      let off = length "P6\n620 620\n255\n" + 3 * (py * 620 + px)
      in if off + 2 < BS.length bytes then Just (BS.index bytes off, BS.index bytes (off + 1), BS.index bytes (off + 2)) else Nothing

-- Every second element, from the first.
-- | @restlessRun dir seconds failAt@: a run of 'world' planned for that
-- many seconds at dt 0.04, with a log and a page in @dir@, its SimbotA
-- 'restless' (failing at @failAt@): its standard output and error, and
-- how it ended.
restlessRun :: FilePath -> Double -> Time -> IO (String, String, Either ExitCode ())
restlessRun dir seconds failAt =
  captured (runSimWith (quick dir) { optSeconds = seconds, optDt = 0.04, optFrames = False, optQuiet = False
                                   , optLog = Just (dir </> "run.jsonl")
                                   , optReplay = Just (dir </> "run.html") } (Just world) (restless failAt) drive)

every2nd :: [a] -> [a]
every2nd (x : _ : xs) = x : every2nd xs
every2nd xs           = xs

-- How many times a text occurs in another.
occurrences :: String -> String -> Int
occurrences needle hay = length (filter (needle `isPrefixOf`) (tails hay))
