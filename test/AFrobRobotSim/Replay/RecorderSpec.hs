-- | The replay page's recorder: a run's page recorded step by step,
-- thinned for the length the run turns out to have, the same page as one
-- made of the whole log.
module AFrobRobotSim.Replay.RecorderSpec (spec) where

import qualified Data.ByteString.Char8    as BC
import           Control.Monad            (forM, forM_)
import           Data.List                (isPrefixOf, isSuffixOf)
import           System.Directory         (getTemporaryDirectory, listDirectory, removeFile)
import           System.FilePath          ((</>))
import           System.IO                (hClose, openTempFile)
import           Test.Hspec

import           AFrob                    (arr, constant, ddVelDiff, localTime, mrFinalize, mrMerge,
                                           repeatedly, tcoPrintMessage, (&&&), (>>>))
import           AFrobRobotSim            (WorldState (..), simulate)
import           AFrobRobotSim.JSON
import           AFrobRobotSim.Log
import           AFrobRobotSim.LogFixture
import           AFrobRobotSim.Replay
import           AFrobRobotSim.ReplaySpec (embeddedData, occurrences)
import           TestUtil                 (withTMPDIR, withTempDir)

-- | A 20-second run of the fixture's world that makes events at many
-- steps: SimbotA 1 prints a line every 0.13 s and drives forward and back
-- in turns of 3 s, SimbotB 2 drives into the world's edge and stays there;
-- with 'eventfulConfig', a score rises every 0.3 s.
eventfulStates :: [WorldState]
eventfulStates = take 2001 (simulate 0.01 fixtureWorld ctrlA ctrlB)
  where
    ctrlA _ = (localTime &&& repeatedly 0.13 ()) >>> arr (\(t, e) ->
      let v = if even (floor (t / 3) :: Int) then 1.2 else -1.2
      in mrFinalize (ddVelDiff v v `mrMerge` tcoPrintMessage (fmap (const ("tick at " ++ show t)) e)))
    ctrlB _ = constant (mrFinalize (ddVelDiff 1 1))

-- | The fixture's settings, with a score that rises every 0.3 s.
eventfulConfig :: LogConfig
eventfulConfig = fixtureConfig { lcScores = \s -> [("thirds", floor (wsTime s / 0.3))] }

-- | A plan for 'eventfulStates' with pages of at most about 12 frames: the
-- 501 frame periods of its 20 s keep one in 42, and the strides a stop
-- may get are 1, 2, 4, 8, 16, 32 and 42.
smallPlan :: ReplayPlan
smallPlan = ReplayPlan 20 (\t -> max 1 (ceiling (t * 25 / 12)))

-- | The stride of the page of a run of 'smallPlan' that stops at @t@: the
-- first of 1, 2, 4, ... and 42 that is at least the stride of a run planned
-- for @t@.
smallStride :: Double -> Int
smallStride t = head ([ d | d <- [1, 2, 4, 8, 16, 32], d >= planStride smallPlan t ] ++ [42])

-- | The page a recorder writes of these states with this summary.
recordedPage :: ReplayPlan -> LogConfig -> [WorldState] -> LogSummary -> IO String
recordedPage plan cfg states summary = withTempDir $ \dir -> do
  rec <- newReplayRecorder plan cfg
  mapM_ (recordReplayState rec) states
  writeReplay rec summary (dir </> "page.html")
  written <- readFile (dir </> "page.html")
  length written `seq` pure written

-- | The page of these states thinned to one frame period in @d@, made as a
-- recorder that took only those frames made it: 'replayPage' of the log at
-- @fps / d@ ('logFrames'), the summary counting its frames.
pageAtStride :: LogConfig -> Int -> [WorldState] -> LogSummary -> String
pageAtStride cfg d states summary =
  replayPage (RunLog (logHeader cfgD) frames (Just summary { lsFrames = length frames }) Nothing)
  where
    cfgD   = cfg { lcFps = lcFps cfg / fromIntegral d }
    frames = logFrames cfgD states

-- | The frames of a page, read back from its data.
pageFrames :: String -> [LogFrame]
pageFrames page = case embeddedData page >>= either (const Nothing) Just . (\t -> parseJSON t >>= asArray >>= traverse logLineFromJSON) of
  Just ls -> [ f | LineFrame f <- ls ]
  Nothing -> []

spec :: Spec
spec = do
  let page = replayPage fixtureLog
  describe "writeReplayChunked (a long log in several data elements)" $ do
    let edges = fixtureChunkEdges
    it "is written the same by a recorder (writeReplayChunked)" $
      forM_ ([10, 2000] ++ edges) $ \n -> do
        tmp <- getTemporaryDirectory
        rec <- newReplayRecorder replayEveryFrame fixtureConfig
        mapM_ (recordReplayState rec) fixtureStates
        (path, h) <- openTempFile tmp "afrp-replay.html"
        hClose h
        writeReplayChunked n rec (LogSummary fixtureSeconds (length fixtureStates) (-1) 0.5 False Nothing Nothing []) path
        written <- readFile path
        length written `seq` removeFile path
        written `shouldBe` replayPageChunked n fixtureLog

  describe "replayFrameStep (how many frame periods a page keeps one of)" $ do
    it "keeps every frame up to 9000 frames and 1.25 million robot-frames, and thins evenly beyond (fixed)" $ do
      map (\(secs, robots) -> replayFrameStep secs 25 robots)
          [ (30, 6), (360, 6), (360.04, 6), (400, 6), (3600, 2)
          , (5, 10000), (5.04, 10000), (10, 10000), (30, 10000), (30, 1000), (50, 1000), (50.04, 1000) ]
        `shouldBe` [1, 1, 2, 2, 10, 1, 2, 2, 6, 1, 1, 2]
    it "keeps every frame of a run of no time, and counts a world without robots as one robot (fixed)" $
      map (\(secs, robots) -> replayFrameStep secs 25 robots) [(0, 10000), (30, 0), (400, 0)] `shouldBe` [1, 1, 2]
    it "keeps within both limits with the fewest periods skipped" $
      forM_ [ (secs, robots) | secs <- [0.5, 7, 30, 123.4, 400, 3600], robots <- [1, 7, 100, 1000, 3333, 10000, 40000] ] $
        \(secs, robots) -> do
          let k = replayFrameStep secs 25 robots
              frames j = secs * 25 / fromIntegral j
              within j = frames j <= fromIntegral replayMaxFrames
                         && frames j * fromIntegral robots <= fromIntegral replayMaxRobotFrames
          (k >= 1, within k, k == 1 || not (within (k - 1))) `shouldBe` (True, True, True)

  describe "ReplayRecorder" $
    it "records, step by step, the same page as replayPage of the pure log, through a temporary file gone from its folder from the start (fixed)" $
     withTempDir $ \tmp -> withTMPDIR tmp $ do
      -- (TMPDIR is a folder of this test's own: another run's spool file
      -- in the shared one would change the counts)
      let spools = length . filter (\f -> "afrp-replay" `isPrefixOf` f && ".frames" `isSuffixOf` f) <$> listDirectory tmp
      spoolsBefore <- spools
      rec <- newReplayRecorder replayEveryFrame fixtureConfig
      mapM_ (recordReplayState rec) fixtureStates
      -- (removed once made: a run killed now leaves nothing behind)
      during <- spools
      during `shouldBe` spoolsBefore
      (path, h) <- openTempFile tmp "afrp-replay.html"
      hClose h
      writeReplay rec (LogSummary fixtureSeconds (length fixtureStates) (-1) 0.5 False Nothing Nothing []) path
      written <- readFile path
      length written `seq` removeFile path
      written `shouldBe` page
      spoolsAfter <- spools
      spoolsAfter `shouldBe` spoolsBefore

  describe "ReplayRecorder's thinning for the run's actual length" $ do
    let summaryOf states = LogSummary (wsTime (last states)) (length states) (-1) 0.5 False Nothing Nothing []
        interrupted states = (summaryOf states) { lsInterrupted = True }
        failed states = (summaryOf states) { lsFailure = Just "the controller of SimbotA 1 failed" }
        -- (stops at states' counts about the strides' changes)
        stops = [1, 2, 49, 50, 98, 289, 290, 300, 577, 600, 1153, 1234, 1999, 2001]
    it "gives a run that went its planned length the page of its planned thinning, byte for byte (fixed)" $ do
      written <- recordedPage smallPlan eventfulConfig eventfulStates (summaryOf eventfulStates)
      written `shouldBe` pageAtStride eventfulConfig 42 eventfulStates (summaryOf eventfulStates)
      length (pageFrames written) `shouldBe` 12
    it "gives a run that stopped at t the page of a run planned for t, within a factor 2, never fewer frames than planned" $
      forM_ stops $ \k -> do
        let states = take k eventfulStates
            t = wsTime (last states)
            d = smallStride t
        forM_ [interrupted states, failed states] $ \summary -> do
          written <- recordedPage smallPlan eventfulConfig states summary
          (k, written == pageAtStride eventfulConfig d states summary) `shouldBe` (k, True)
          let frames = length (pageFrames written)
          (k, planStride smallPlan t <= d, d < 2 * planStride smallPlan t) `shouldBe` (k, True, True)
          (k, frames >= length (logFrames eventfulConfig { lcFps = 25 / 42 } states)) `shouldBe` (k, True)
    it "keeps every frame period of a run that stopped before it needed thinning (fixed)" $ do
      -- (0.48 s: 12 frame periods, within the 12 frames)
      let states = take 49 eventfulStates
      written <- recordedPage smallPlan eventfulConfig states (failed states)
      length (pageFrames written) `shouldBe` 13
      pageFrames written `shouldBe` logFrames eventfulConfig states
    it "puts the events, console lines and messages of the frame periods it leaves out into the next frame it keeps" $ do
      let states = take 1234 eventfulStates
          full = logFrames eventfulConfig states
      written <- recordedPage smallPlan eventfulConfig states (interrupted states)
      let kept = pageFrames written
          upTo = takeWhile (\f -> lfTime f <= lfTime (last kept)) full
          messagesOf fs = [ (i, m) | f <- fs, (i, r) <- zip [0 :: Int ..] (lfRobots f), m <- lrMessages r ]
      -- (not vacuous: a bump, scores, messages, and frames left out)
      (length kept, length full) `shouldBe` (10, 309)
      [ e | f <- full, e <- lfEvents f, evKind e == "bump" ] `shouldNotBe` []
      length (filter ((== "score") . evKind) (concatMap lfEvents full)) `shouldSatisfy` (> 30)
      length (messagesOf full) `shouldSatisfy` (> 30)
      concatMap lfEvents kept `shouldBe` concatMap lfEvents upTo
      concatMap lfConsole kept `shouldBe` concatMap lfConsole upTo
      messagesOf kept `shouldBe` messagesOf upTo
      -- (each in the first frame kept at or after its time)
      and [ lfTime a < evTime e && evTime e <= lfTime b | (a, b) <- zip kept (drop 1 kept), e <- lfEvents b ]
        `shouldBe` True
      and [ lfTime a < mt && mt <= lfTime b | (a, b) <- zip kept (drop 1 kept), r <- lfRobots b, (mt, _) <- lrMessages r ]
        `shouldBe` True
    it "spools at most about three pages' worth of lines, dropping the strides the run outgrows" $ do
      rec <- newReplayRecorder smallPlan eventfulConfig
      counts <- forM eventfulStates $ \s -> recordReplayState rec s >> replaySpooled rec
      discardReplay rec
      -- (three pages of 12 frames, and a line more for each of the 7 strides)
      maximum counts `shouldSatisfy` (<= 3 * 12 + 7)
      -- (lines were dropped: the count fell, more than once)
      length [ () | (a, b) <- zip counts (drop 1 counts), b < a ] `shouldSatisfy` (>= 3)
    it "says the stride of the page it writes" $ do
      rec <- newReplayRecorder smallPlan eventfulConfig
      let states = take 1234 eventfulStates
      mapM_ (recordReplayState rec) states
      strides <- mapM (replayPageStride rec) [summaryOf states, interrupted states, failed states]
      discardReplay rec
      strides `shouldBe` [42, 32, 32]
    it "is deterministic: the same states give the same page" $ do
      let states = take 1153 eventfulStates
      a <- recordedPage smallPlan eventfulConfig states (interrupted states)
      b <- recordedPage smallPlan eventfulConfig states (interrupted states)
      a `shouldBe` b

  describe "recordReplayStateWith" $ do
    let summary = LogSummary fixtureSeconds (length fixtureStates) (-1) 0.5 False Nothing Nothing []
        pageOf :: (ReplayRecorder -> IO ()) -> IO String
        pageOf record = do
          tmp <- getTemporaryDirectory
          rec <- newReplayRecorder replayEveryFrame fixtureConfig
          record rec
          (path, h) <- openTempFile tmp "afrp-replay.html"
          hClose h
          writeReplay rec summary path
          written <- readFile path
          length written `seq` removeFile path
          pure written
    it "records the same page from the lines a run log of the same frames wrote (fixed)" $ do
      tmp <- getTemporaryDirectory
      (logPath, lh) <- openTempFile tmp "afrp-log.jsonl"
      hClose lh
      w <- openLogWriter fixtureConfig logPath
      written <- pageOf (\rec -> mapM_ (\s -> writeLogStateLine w s >>= \l -> recordReplayStateWith rec l s) fixtureStates)
      closeLogWriter w summary
      removeFile logPath
      written `shouldBe` page
    it "writes the line it is given at a frame's step, not its own (fixed)" $ do
      let marker = "{\"kind\":\"frame\",\"marker\":1}"
      written <- pageOf (\rec -> mapM_ (recordReplayStateWith rec (Just (BC.pack marker))) fixtureStates)
      occurrences marker written `shouldBe` length (rlFrames fixtureLog)
      occurrences "\"kind\":\"frame\"" written `shouldBe` length (rlFrames fixtureLog)
