-- | The replay page in a real browser: headless Chromium, driven by
-- playwright-core from test/browser/ (see test/browser/replay.test.js for
-- the checks). Missing tools fail the test with how to install them.
module AFrobRobotSim.ReplayBrowserSpec (spec) where

import           Control.Exception        (finally)
import           Control.Monad            (unless, when)
import           Data.List                (isInfixOf, isPrefixOf, tails)
import           System.Directory         (doesDirectoryExist, doesFileExist, findExecutable,
                                           getTemporaryDirectory, removeFile)
import           System.Environment       (lookupEnv)
import           System.Exit              (ExitCode (..))
import           System.FilePath          ((</>))
import           System.IO                (hClose, openTempFile)
import           System.Process           (readProcessWithExitCode)
import           Test.Hspec

import           AFrob                    hiding (forAll)
import           AFrobRobotSim
import           AFrobRobotSim.Log
import           AFrobRobotSim.LogFixture
import           AFrobRobotSim.Replay
import           TestUtil                 (withTempDir)

-- | The page of a 1 s run of a world, its robots driving slowly ahead.
pageOf :: WorldTemplate -> String
pageOf w = replayPage (RunLog (logHeader cfg) (logFrames cfg states) Nothing Nothing)
  where
    cfg    = defaultLogConfig { lcWorld = w, lcDt = 0.01, lcFps = 25 }
    states = take 101 (simulate 0.01 w slowAhead slowAhead)

-- | A robot that drives slowly ahead.
slowAhead :: SimbotController
slowAhead _ = constant (mrFinalize (ddVelDiff 0.2 0.2))

-- | The page of a 1 s run in the notes' world with robots at its edges:
-- SimbotA 1 at the right edge, SimbotB 1 at the top edge, SimbotA 22 in
-- the top right corner and SimbotB 22 in the bottom right corner (ids
-- shared: labelled A1, B1, A22, B22); the command line names the world
-- file @worlds/a\b.world@.
edgesPage :: String
edgesPage = replayPage (RunLog (logHeader cfg) (logFrames cfg states) Nothing Nothing)
  where
    world  = [ OTSimbotA 1 (Point2 4.7 0) 0, OTSimbotB 1 (Point2 2 4.7) (pi / 2)
             , OTSimbotA 22 (Point2 4.7 4.7) 0, OTSimbotB 22 (Point2 4.7 (-4.7)) 0 ]
    cfg    = defaultLogConfig { lcWorld = world, lcDt = 0.01, lcFps = 25
                              , lcCommandLine = ["simbot", "--world", "worlds/a\\b.world"] }
    states = take 101 (simulate 0.01 world slowAhead slowAhead)

-- | The page of a 10 s run (25 frames a second) of which a test's
-- property was decided false at 4.01 s, as afrp-test's forAllRuns writes
-- it: its summary's 'lsFalsified'.
verdictPage :: String
verdictPage = replayPage (RunLog (logHeader cfg) frames (Just summary) Nothing)
  where
    world   = [OTSimbotA 1 (Point2 (-2) 0) 0, OTSimbotB 2 (Point2 2 1.5) 1]
    cfg     = defaultLogConfig { lcWorld = world, lcDt = 0.01, lcFps = 25, lcCommandLine = ["afrp-test"] }
    states  = take 1001 (simulate 0.01 world slowAhead slowAhead)
    frames  = logFrames cfg states
    summary = LogSummary 10 (length states) (length frames) 0 False Nothing
                         (Just (4.01, "decided false at t = 4.01 (step 401)")) []

-- | The page of a 2 s run of one robot whose controller failed then, as
-- simbot writes it: its summary's 'lsFailure', two lines.
failedPage :: String
failedPage = replayPage (RunLog (logHeader cfg) frames (Just summary) Nothing)
  where
    world   = [OTSimbotA 1 (Point2 (-2) 0) 0]
    cfg     = defaultLogConfig { lcWorld = world, lcDt = 0.01, lcFps = 25, lcCommandLine = ["afrp-test"] }
    states  = take 201 (simulate 0.01 world slowAhead slowAhead)
    frames  = logFrames cfg states
    summary = LogSummary 2 (length states) (length frames) 0 False
                         (Just "SimbotA 1's controller failed at t = 2.00 s: boom\nat the second line") Nothing []

-- | The page of a 60 s run in the notes' world (25 frames a second) with
-- what a user's audit of the page needed: SimbotA 1 and SimbotB 1, which
-- share an id; SimbotA 1, circling, prints "tick" every second; a score
-- "seconds" rises every second; SimbotB 1 drives into a wall and sticks;
-- the command line names a world file whose name is markup.
usabilityPage :: String
usabilityPage = replayPage (RunLog (logHeader cfg) (logFrames cfg states) Nothing Nothing)
  where
    world  = [OTSimbotA 1 (Point2 (-2) 0) 0, OTSimbotB 1 (Point2 2 1.5) 0, OTVWall (Point2 4 1.5)]
    cfg    = defaultLogConfig { lcWorld = world, lcDt = 0.01, lcFps = 25
                              , lcCommandLine = [ "simbot", "--world", "one.world", "--world", "worlds/<img src=x onerror=alert(1)>two.world"
                                                , "--seconds", "60" ]
                              , lcScores = \s -> [("seconds", floor (wsTime s + 1e-9))] }
    states = take 6001 (simulate 0.01 world ctrlA ctrlB)
    ctrlA _ = repeatedly 1 "tick" >>> arr (\e -> mrFinalize (ddVelDiff 0.3 0.5 `mrMerge` tcoPrintMessage e))
    ctrlB _ = constant (mrFinalize (ddVelDiff 0.5 0.5))

spec :: Spec
spec = do
  it "shows the whole of a 30 by 10 m and a 100 m world, robots near their far corners where the log says (fixed)" $
    mapM_ (runPageTest "replay-size.test.js" . pageOf)
      [ [OTSize 30 10, OTSimbotA 1 (Point2 (-14.5) 4.5) 0, OTSimbotB 2 (Point2 14.5 (-4.5)) pi]
      , [OTSize 100 100, OTSimbotA 1 (Point2 (-49) 49) 0, OTSimbotB 2 (Point2 49 (-49)) pi] ]
  it "draws a crowd of 300 small robots in a 300 m world: every robot, wall and block shows, ids only when readable, zoomed in only those in view (fixed)" $ do
    let crowd = OTSize 300 300 : [ (if even (i + j) then OTSimbotA else OTSimbotB) (20 * i + j)
                                     (Point2 (-140 + 20 * fromIntegral i) (-140 + 15 * fromIntegral j)) 0
                                 | i <- [0 .. 14 :: Int], j <- [0 .. 19] ]
                              ++ [ OTHWall (Point2 (-130 + 20 * fromIntegral k) (-147)) | k <- [0 .. 4 :: Int] ]
                              ++ [ OTVWall (Point2 147 (-130 + 20 * fromIntegral k)) | k <- [0 .. 4 :: Int] ]
                              ++ [ OTBlock (Point2 (-130 + 20 * fromIntegral k) 147.5) | k <- [0 .. 2 :: Int] ]
    runPageTest "replay-crowd.test.js" (pageOf crowd)
  it "takes a touch screen's gestures: a pinch zooms about the fingers' midpoint and moves with it, a drag moves, a tap selects, and a phone's narrow screen shows the canvas scaled (fixed)" $
    runPageTest "replay-touch.test.js"
      (pageOf [OTSize 20 20, OTSimbotA 1 (Point2 3 2) 0, OTSimbotB 2 (Point2 (-3) (-2)) pi])
  it "passes a user's audit of its usability at 1200 by 800 (the checks: test/browser/replay-usability.test.js) (fixed)" $
    runPageTest "replay-usability.test.js" usabilityPage
  it "draws with a HiDPI screen's pixels (2 a CSS pixel): the canvas shown as on a screen of 1, worldToCanvas in the canvas's pixels (fixed)" $
    runPageTest "replay-hidpi.test.js" (replayPage fixtureLog)
  it "shows the robot's messages newest first, the newest in view at any width, indexed once (no more work a frame late in the run than early), and the run's name in its heading (fixed)" $
    runPageTest "replay-panel.test.js" usabilityPage
  it "gives the canvas the screen's new pixels when the browser's zoom changes the ratio, the view and worldToCanvas kept in the canvas's pixels (fixed)" $
    runPageTest "replay-rescale.test.js" (replayPage fixtureLog)
  it "leaves Space to a button or a tick box reached with Tab (after a click it plays), and keeps each tick box's label on one line on a narrow window (fixed)" $
    runPageTest "replay-controls.test.js" (replayPage fixtureLog)
  it "keeps the robots' labels within the canvas at its edges, breaks the text panels' lines between words, keeps the play button's width, and titles a world file named a\\b.world whole (fixed)" $
    runPageTest "replay-edges.test.js" edgesPage
  it "opens the page of a run whose property was decided false at that instant, marked on the slider, and says it; a failed run's heading says its failure, and one robot is \"1 robot\" (fixed)" $
    withTempDir $ \dir -> do
      let failed = dir </> "failed.html"
      writeFile failed failedPage
      () <$ runPageScript "replay-verdict.test.js" [failed] verdictPage
  it "plays the page of a short run in headless Chromium: drawn where the log says, slider, click, keys, no script from the run (fixed)" $
    playFixture (replayPage fixtureLog)
  it "plays it as well with its log split over several data elements, every frame read (fixed)" $ do
    let page = replayPageChunked 3000 fixtureLog
    length (filter ("<script id=\"afrp-log" `isPrefixOf`) (tails page)) `shouldSatisfy` (> 5)
    playFixture page

-- | Run a script of test/browser/ on a page (written to a temporary file,
-- removed after): the test passes when the script exits 0.
runPageTest :: FilePath -> String -> Expectation
runPageTest script pageText = () <$ runPageScript script [] pageText

-- | Run test/browser/replay.test.js on a page of 'fixtureLog', which must
-- show all of its frames. Its screenshot goes to $AFRP_REPLAY_SCREENSHOT,
-- or to a temporary file removed after.
playFixture :: String -> Expectation
playFixture pageText = do
    asked <- lookupEnv "AFRP_REPLAY_SCREENSHOT"
    tmp <- getTemporaryDirectory
    shot <- maybe (openTempFile tmp "afrp-replay.png" >>= \(f, h) -> f <$ hClose h) pure asked
    -- (the temporary screenshot removed also when the script fails)
    out <- runPageScript "replay.test.js" [shot] pageText `finally` when (asked == Nothing) (removeFile shot)
    out `shouldSatisfy` (("the page has the log's frames (" ++ show (length (rlFrames fixtureLog)) ++ ")") `isInfixOf`)

-- | @runPageScript script args page@ runs test/browser/@script@ with node
-- on @page@ (written to a temporary file, removed after) and @args@: its
-- output when it exits 0, a failure with its output otherwise, and a
-- failure naming what is missing when node, Chromium or playwright-core
-- is.
runPageScript :: FilePath -> [String] -> String -> IO String
runPageScript script args pageText = do
    node     <- findExecutable "node"
    chromium <- lookupEnv "CHROMIUM" >>= maybe (pure "/usr/bin/chromium") pure
    haveChromium <- doesFileExist chromium
    haveModules  <- doesDirectoryExist ("test" </> "browser" </> "node_modules" </> "playwright-core")
    let missing = [ "node (apt-get install -y nodejs npm)" | node == Nothing ]
               ++ [ "Chromium at " ++ chromium ++ " (apt-get install -y chromium, or set CHROMIUM)" | not haveChromium ]
               ++ [ "playwright-core (cd test/browser && npm ci)" | not haveModules ]
    unless (null missing) $
      expectationFailure ("the browser test needs: " ++ concatMap ("\n  - " ++) missing
                          ++ "\n(.ci/run installs them)")
    tmp <- getTemporaryDirectory
    (page, h) <- openTempFile tmp "afrp-replay.html"
    hClose h
    writeFile page pageText
    (code, out, err) <- readProcessWithExitCode (maybe "node" id node) (("test" </> "browser" </> script) : page : args) ""
                          `finally` removeFile page
    case code of
      ExitSuccess   -> pure out
      ExitFailure c -> do
        expectationFailure ("node test/browser/" ++ script ++ " exited with " ++ show c ++ ":\n" ++ out ++ err)
        pure out
