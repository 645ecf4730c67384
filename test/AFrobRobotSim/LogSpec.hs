-- | The run log: records made from a real run, written as the run goes.
-- (Reading it back is "AFrobRobotSim.Log.ReadSpec"'s.)
module AFrobRobotSim.LogSpec (spec) where

import           Data.List                (nub, stripPrefix)
import           Test.QuickCheck          (Gen, choose, elements, forAll, listOf, oneof, property)
import           Text.Printf              (printf)
import           System.Directory         (getTemporaryDirectory, removeFile)
import           System.IO                (hClose, openTempFile)
import           System.Process           (readProcessWithExitCode)
import           Test.Hspec

import           AFRP.Basic               (constant)
import           AFRP.Geometry            (Point2 (..))
import           AFrob.MergeableRecord    (mrFinalize)
import           AFrob.RobotIO            (ddBrake, ddVelDiff)
import           AFrobRobotSim.Log
import           AFrobRobotSim.LogFixture
import           AFrobRobotSim.Simulator  (RobotState (..), WorldState (..), simulate)
import           AFrobRobotSim.World      (ObjectTemplate (..))

-- The two robots of a frame (the fixture has two).
pair :: [a] -> (a, a)
pair xs = case xs of
  [a, b] -> (a, b)
  _      -> error ("expected two robots, got " ++ show (length xs))

spec :: Spec
spec = do
  describe "the header's bounds" $ do
    it "are the notes' 10 by 10 for a world without a size" $
      lhBounds (logHeader defaultLogConfig { lcWorld = [OTBall (Point2 0 0)] }) `shouldBe` LogRect 0 0 10 10
    it "are the world's size when it has one, whatever lcBounds says" $
      lhBounds (logHeader defaultLogConfig { lcWorld = [OTSize 30 10, OTBall (Point2 12 0)] })
        `shouldBe` LogRect 0 0 30 10
  let frames = rlFrames fixtureLog
  describe "logFrames" $ do
    it "gives one frame per 1/fps s, at time 0 and at the end (fixed)" $ do
      length frames `shouldBe` 51
      map lfTime (take 3 frames) `shouldBe` [0, 0.04, 0.08]
      lfTime (last frames) `shouldSatisfy` (\t -> abs (t - 2) < 1e-9)
    it "gives every robot's true pose of the frame's step (fixed)" $ do
      let at k = fixtureStates !! (4 * k)
      -- to the millionth the log keeps
      sequence_ [ [ (lrX l - x, lrY l - y, lrHeading l - robotHeading r)
                  | (l, r) <- zip (lfRobots f) (wsRobots (at k)), let Point2 x y = robotPos r ]
                    `shouldSatisfy` all (\(dx, dy, dh) -> maximum (map abs [dx, dy, dh]) <= 5e-7)
                | (k, f) <- zip [0 ..] frames ]
      map (length . lfRobots) frames `shouldSatisfy` all (== 2)
    it "derives the wheel speeds from the motion: 0 at time 0, then the commanded ones once up to speed (fixed)" $ do
      let (a0, _) = pair (lfRobots (head frames))
          (a, b)  = pair (lfRobots (last frames))
      (lrWheelLeft a0, lrWheelRight a0) `shouldBe` (0, 0)
      -- SimbotA accelerates at 0.2 m/s^2: not yet at its 0.45 m/s at 2 s,
      -- but turning as the wheels' difference says, 0.1 m/s over 0.5 m
      lrSpeed a `shouldSatisfy` (\v -> v > 0.3 && v < 0.45)
      (lrWheelLeft a + lrWheelRight a) / 2 `shouldSatisfy` (\v -> abs (v - lrSpeed a) <= 1e-6)
      lrWheelRight a - lrWheelLeft a `shouldSatisfy` (\d -> abs (d - 0.1) <= 2e-6)
      lrRotVel a `shouldSatisfy` (\w -> abs (w - 0.2) < 1e-6)
      lrRotVel b `shouldBe` 0
      lrSpeed b `shouldSatisfy` (\v -> abs (v - 1) < 1e-6)
    it "gives the range readings and the tracker's sightings the controllers saw (fixed)" $ do
      let (a, b) = pair (lfRobots (head frames))
      -- SimbotA at (-2, 0) facing +x: the wall at x = 4 - 0.05 is far
      -- beyond the range finder's 3 m in front
      lrRange a `shouldSatisfy` (\rs -> length rs == 4 && head rs == 3)
      -- SimbotB is 4.27 m away: beyond the tracker's 4 m; the ball at 2.83 m
      -- is seen, at 45 degrees to the right; SimbotB is 4.03 m from the ball
      lrSeenRobots a `shouldBe` []
      map (\(ang, d) -> (abs (ang + pi / 4) <= 5e-7, abs (d - sqrt 8) <= 5e-7)) (lrSeenBalls a)
        `shouldBe` [(True, True)]
      (lrSeenRobots b, lrSeenBalls b) `shouldBe` ([], [])
    it "gives a robot's messages to that robot, with their time, in the frame of their period (fixed)" $ do
      let msgs = [ (lfTime f, m) | f <- frames, m <- lrMessages (head (lfRobots f)) ]
      map (snd . snd) msgs `shouldBe` [hostileMessage]
      let (tf, (tm, txt)) = head msgs
      txt `shouldBe` hostileMessage
      tm `shouldSatisfy` (\t -> abs (t - 0.5) < 0.011)
      tf `shouldSatisfy` (\t -> t >= tm && t < tm + 0.04 + 1e-9)
      concatMap lfConsole frames `shouldBe` []
    it "lists the balls and the header lists the world (fixed)" $ do
      lfBalls (head frames) `shouldBe` [(0, -2)]
      let h = rlHeader fixtureLog
      map (\r -> (riType r, riId r, riRadius r)) (lhRobots h) `shouldBe` [("SimbotA", 1, 0.25), ("SimbotB", 2, 0.25)]
      lhWalls h `shouldBe` [LogRect 4 (-2) 0.1 1, LogRect 0 (-4) 1 0.1]
      lhBlocks h `shouldBe` [LogRect (-3) 3 0.5 0.5]
      lhBounds h `shouldBe` LogRect 0 0 10 10

  describe "roundHalfEven" $ do
    it "is round on numbers up to 10^15 in magnitude, ties to even (the log's rounding without a foreign call)" $
      property $ forAll (oneof [ choose (-1e15, 1e15), choose (-1e3, 1e3)
                               , (+ 0.5) . fromIntegral <$> (choose (-10 ^ (14 :: Int), 10 ^ (14 :: Int)) :: Gen Int)
                               , (* 0.5) . fromIntegral <$> (choose (-64, 64) :: Gen Int)
                               , elements [0, -0, 1e15, -1e15, 999999999999999.5, -999999999999999.5] ]) $ \y ->
        roundHalfEven y == (round y :: Int)
    it "rounds the ties of 0.5 to the even neighbour" $
      map roundHalfEven [0.5, 1.5, 2.5, -0.5, -1.5, -2.5, 2.4999, -2.6] `shouldBe` [0, 2, 2, 0, -2, -2, 2, -3]
  describe "isFrameStep" $
    it "takes the steps that rounding with 'round' takes (property)" $
      property $ forAll ((,,) <$> oneof [choose (1e-4, 1), elements [0.01, 0.04, 0.05, 1 / 3]]
                              <*> oneof [choose (0.1, 500), elements [25, 12.5, 25 / 3, 2.5, 40, 100]]
                              <*> oneof [choose (0, 10 ^ (7 :: Int)), choose (0, 1000)]) $ \(dt, fps, n) ->
        let f = fromIntegral n * dt * fps
        in isFrameStep dt fps n == (n == 0 || abs (f - fromIntegral (round f :: Int)) * 2 < dt * fps)

  describe "LogRates (logStep at several frame rates at once)" $ do
    let cfg = fixtureConfig { lcScores = \s -> [("tenths", floor (wsTime s * 10 + 1e-9))] }
        rates = [(1, 25), (2, 12.5), (3, 25 / 3), (7, 25 / 7)] :: [(Int, Double)]
        stepAll lr (s : ss) = let (lr', fs) = logRatesStep cfg lr s in fs : stepAll lr' ss
        stepAll _ []        = []
        byStep = stepAll (logRatesStart cfg rates) fixtureStates
    it "gives at each rate exactly logFrames at that rate, events and the hostile message included (fixed)" $
      mapM_ (\(k, fps) -> [ f | fs <- byStep, (ks, f) <- fs, k `elem` ks ] `shouldBe` logFrames cfg { lcFps = fps } fixtureStates)
            rates
    it "gives a step one frame for the rates whose periods hold the same events and lines, each rate once" $ do
      [ ks | fs <- byStep, let ks = concatMap fst fs, length ks /= length (nub ks) ] `shouldBe` []
      -- (the first step is every rate's frame, all with an empty period)
      map (map fst) (take 1 byStep) `shouldBe` [[[1, 2, 3, 7]]]
      -- (and a step of rates 1 and 2 after a score's rise at an odd frame: two)
      length [ () | fs <- byStep, length fs > 1 ] `shouldSatisfy` (> 0)
    it "goes on as before for the rates logRatesKeep keeps" $ do
      let keepFrom k = let (a, b) = splitAt k fixtureStates
                           lr = foldl (\l s -> fst (logRatesStep cfg l s)) (logRatesStart cfg rates) a
                       in [ f | fs <- stepAll' (logRatesKeep (/= 2) lr) b, (ks, f) <- fs, 3 `elem` ks ]
          stepAll' lr (s : ss) = let (lr', fs) = logRatesStep cfg lr s in fs : stepAll' lr' ss
          stepAll' _ []        = []
      keepFrom 77 `shouldBe` drop (length [ () | n <- [0 .. 76 :: Int], isFrameStep 0.01 (25 / 3) n ])
                                  (logFrames cfg { lcFps = 25 / 3 } fixtureStates)

  describe "linesByRobot" $ do
    it "gives each robot its own lines and leaves the rest to the console (fixed)" $ do
      let (own, rest) = linesByRobot [("SimbotA", 1), ("SimbotB", 10)]
            [ "[0.50] SimbotA.1: hello", "[0.50] SimbotB.7: hi", "plain", "[0.60] SimbotB.10: a: b"
            , "[0.70] SimbotA.1: again", "[0.70] SimbotA.01: zero", "[x] SimbotA.1: t", "[0.80] SimbotA.1:t" ]
      own ("SimbotA", 1) `shouldBe` [(0.5, "hello"), (0.7, "again")]
      own ("SimbotB", 10) `shouldBe` [(0.6, "a: b")]
      own ("SimbotB", 7) `shouldBe` []
      rest `shouldBe` ["[0.50] SimbotB.7: hi", "plain", "[0.70] SimbotA.01: zero", "[x] SimbotA.1: t", "[0.80] SimbotA.1:t"]
    it "reads each line as testing it against every robot in turn does (property)" $
      property $ forAll genRobots $ \robots -> forAll (listOf (genLine robots)) $ \ls ->
        let (own, rest) = linesByRobot robots ls
            naive k = [ m | l <- ls, Just m <- [naiveOwn k l] ]
            naiveRest = [ l | l <- ls, all (\k -> naiveOwn k l == Nothing) robots ]
        in map own robots == map naive robots && rest == naiveRest

  describe "bump events" $ do
    it "say when a robot gets stuck (fixed)" $ do
      let world = [OTSimbotB 1 (Point2 0 0) 0, OTVWall (Point2 1 0)]
          run = take 301 (simulate 0.01 world (\_ -> constant (mrFinalize ddBrake)) (\_ -> constant (mrFinalize (ddVelDiff 1 1))))
          evs = concatMap lfEvents (logFrames defaultLogConfig { lcWorld = world } run)
      map evKind evs `shouldBe` ["bump"]
      map evRobot evs `shouldBe` [Just ("SimbotB", 1)]
    it "are timed to a nanosecond, as the frame's other times are (2.2800000000000002 was written raw)" $ do
      -- (the robot drives into the wall at a step whose time, a sum of
      -- steps of 0.05, is 1.7000000000000002)
      let world = [OTSimbotB 1 (Point2 0 0) 0, OTVWall (Point2 1 0)]
          run = take 61 (simulate 0.05 world (\_ -> constant (mrFinalize ddBrake)) (\_ -> constant (mrFinalize (ddVelDiff 1 1))))
          evs = concatMap lfEvents (logFrames defaultLogConfig { lcWorld = world, lcDt = 0.05, lcFps = 20 } run)
          raw = [ wsTime s | s <- run, any robotStuck (wsRobots s) ]
      take 1 raw `shouldSatisfy` all (\t -> roundTo 1e9 t /= t)
      map evTime evs `shouldBe` map (roundTo 1e9) (take 1 raw)

  describe "score events" $
    it "mark each rise of a score, at the step it rose, in the frame of its period (fixed)" $ do
      let cfg = fixtureConfig { lcScores = \s -> [("seconds", floor (wsTime s + 1e-9))] }
          fs  = logFrames cfg fixtureStates
      [ (lfTime f, evTime e, evText e) | f <- fs, e <- lfEvents f ]
        `shouldBe` [(1, 1, "seconds scores: 1"), (2, 2, "seconds scores: 2")]
      lfScores (last fs) `shouldBe` [("seconds", 2)]

  describe "LogWriter" $ do
    it "writes, step by step, the same lines as the pure function (fixed)" $ do
      tmp <- getTemporaryDirectory
      (path, h) <- openTempFile tmp "afrp-log.jsonl"
      hClose h
      w <- openLogWriter fixtureConfig path
      mapM_ (writeLogState w) fixtureStates
      closeLogWriter w (LogSummary fixtureSeconds (length fixtureStates) (-1) 0.5 False Nothing Nothing [])
      r <- readLogFile path
      removeFile path
      r `shouldBe` Right fixtureLog
    it "leaves a valid log, line by line, while the run goes (fixed)" $ do
      tmp <- getTemporaryDirectory
      (path, h) <- openTempFile tmp "afrp-log.jsonl"
      hClose h
      w <- openLogWriter fixtureConfig path
      mapM_ (writeLogState w) (take 41 fixtureStates)
      -- another process reads the file before the writer is closed
      (_, txt, _) <- readProcessWithExitCode "cat" [path] ""
      closeLogWriter w (LogSummary 0.4 41 (-1) 0 True Nothing Nothing [])
      removeFile path
      fmap (\l -> (length (rlFrames l), rlSummary l)) (readLog txt) `shouldBe` Right (11, Nothing)

-- A robot's own line read as the log first read it: tested against that
-- robot's prefix.
naiveOwn :: (String, Int) -> String -> Maybe (Double, String)
naiveOwn (ty, k) l = case l of
  '[' : rest | (ts, ']' : ' ' : body) <- break (== ']') rest
             , [(t, "")] <- reads ts
             , Just txt <- stripPrefix (ty ++ "." ++ show k ++ ": ") body
             -> Just (t, txt)
  _ -> Nothing

genRobots :: Gen [(String, Int)]
genRobots = listOf ((,) <$> elements ["SimbotA", "SimbotB"] <*> choose (-2, 12))

-- Lines as robots (of the world or not) print them, and near misses.
genLine :: [(String, Int)] -> Gen String
genLine robots = do
  ty  <- elements ("Other" : "SimbotA" : map fst robots)
  k   <- oneof [choose (-2, 12), elements (map snd robots ++ [0])]
  t   <- choose (0, 100 :: Double)
  txt <- elements ["hello", "a: b", "] x", "", "SimbotA.1: nested"]
  elements
    [ printf "[%.2f] %s.%d: %s" t ty k txt
    , printf "[%.2f] %s.%d: %s" t ty k txt
    , printf "[%.2f] %s.0%d: %s" t ty k txt
    , printf "[%.2f] %s.%d:%s" t ty k txt
    , printf "[%.2f]%s.%d: %s" t ty k txt
    , printf "[t%.2f] %s.%d: %s" t ty k txt
    , txt ]
