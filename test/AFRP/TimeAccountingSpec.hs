-- | One time accounting for every time-based combinator ("AFRP.EventSource",
-- "AFRP.Delay"): an event due at time t fires at the first sample whose
-- 'localTime' has 'reached' t (is >= t, or short of it by no more than the
-- rounding of binary fractions), for any sequence of time steps, decimal
-- or random.
-- Each property runs the combinator beside 'localTime' and checks it
-- against that rule.
module AFRP.TimeAccountingSpec (spec) where

import           Data.List       (findIndex, nub)
import           Test.Hspec      hiding (after)
import           Test.QuickCheck

import           AFRP hiding (forAll)
import           AFRP.Internal.Clock (reached)
import           TestUtil

-- | Time steps: decimal ones (the troublesome case) or random ones.
genDts :: Gen [DTime]
genDts = do
  n <- choose (1, 120)
  oneof [ vectorOf n (elements [0.1, 0.05, 0.01, 0.2, 0.3, 0.25])
        , vectorOf n (choose (0.001, 0.5)) ]

-- | A delay or period: decimal or random.
genQ :: Gen Time
genQ = oneof [elements [0.1, 0.3, 0.7, 1.1, 2.0, 0.05], choose (0.01, 2)]

-- | The local times of the samples, read from 'localTime'.
localTimes :: [DTime] -> [Time]
localTimes dts = runSamples localTime [(dt, ()) | dt <- 0 : dts]

-- | The first sample whose local time has reached t.
firstAtOrAfter :: [Time] -> Time -> Maybe Int
firstAtOrAfter lts t = findIndex (reached t) lts

-- | The indices of the samples with an event.
eventIndices :: [Event a] -> [Int]
eventIndices es = [i | (i, e) <- zip [0 ..] es, isEvent e]

spec :: Spec
spec = describe "every event due at t fires at the first sample whose localTime has reached t" $ do
  it "after" $ property $ forAll genDts $ \dts -> forAll genQ $ \q ->
    let lts = localTimes dts
    in eventIndices (runSamples (after q ()) [(dt, ()) | dt <- 0 : dts])
         === maybe [] pure (firstAtOrAfter lts q)

  it "repeatedly" $ property $ forAll genDts $ \dts -> forAll genQ $ \q ->
    let lts = localTimes dts
        dues = takeWhile (`reached` last lts) [fromIntegral k * q | k <- [1 :: Int ..]]
    in eventIndices (runSamples (repeatedly q ()) [(dt, ()) | dt <- 0 : dts])
         === nub [i | Just i <- map (firstAtOrAfter lts) dues]

  it "afterEachCat" $ property $ forAll genDts $ \dts ->
    forAll (listOf1 ((,) <$> genQ <*> (arbitrary :: Gen Int))) $ \qxs ->
      let lts  = localTimes dts
          dues = scanl1 (+) (map (toRational . fst) qxs)
          expected = [ (i, [x | (d, (_, x)) <- zip dues qxs, firstAtOrAfter lts (fromRational d) == Just i])
                     | i <- [0 .. length lts - 1] ]
          out = runSamples (afterEachCat qxs) [(dt, ()) | dt <- 0 : dts]
      in [(i, xs) | (i, Event xs) <- zip [0 ..] out]
           === [(i, xs) | (i, xs) <- expected, not (null xs)]

  it "delayEventCat" $ property $ forAll genDts $ \dts -> forAll genQ $ \q ->
    forAll (vectorOf (length dts + 1) (frequency [(3, pure NoEvent), (1, Event <$> (arbitrary :: Gen Int))])) $ \es ->
      let lts = localTimes dts
          released i = [x | (t, Event x) <- zip lts es, firstAtOrAfter lts (t + q) == Just i]
          expected = [(i, released i) | i <- [0 .. length lts - 1], not (null (released i))]
          out = runSamples (delayEventCat q) (zip (0 : dts) es)
      in [(i, xs) | (i, Event xs) <- zip [0 ..] out] === expected

  it "delay" $ property $ forAll genDts $ \dts -> forAll genQ $ \q ->
    let lts = localTimes dts
        xs  = [1 .. length lts]
        expected = [ last (0 : [x | (t, x) <- zip lts xs, reached (t + q) tj]) | tj <- lts ]
    in runSamples (delay q 0) (zip (0 : dts) xs) === expected

  it "sampleWindow fires at the same samples as repeatedly" $ property $ forAll genDts $ \dts -> forAll genQ $ \q ->
    let samples = [(dt, ()) | dt <- 0 : dts]
    in eventIndices (runSamples (sampleWindow 1000 q) samples)
         === eventIndices (runSamples (repeatedly q ()) samples)

  it "after, switched in: its clock restarts at the switch (property)" $ property $
    forAll genDts $ \dts -> forAll genQ $ \s -> forAll genQ $ \q ->
      let samples = [(dt, ()) | dt <- 0 : dts]
          lts = runSamples (switch (constant 0 &&& after s ()) (const localTime)) samples
          evs = runSamples (switch (constant NoEvent &&& after s ()) (const (after q ()))) samples
          start = firstAtOrAfter (localTimes dts) s
      in eventIndices evs
           === [st + i | Just st <- [start], Just i <- [firstAtOrAfter (drop st lts) q]]

  it "a member of a collection keeps its clock across the collection's switches (property)" $ property $
    forAll genDts $ \dts -> forAll genQ $ \q ->
      forAll (vectorOf (length dts + 1) (frequency [(4, pure False), (1, pure True)])) $ \adds ->
        let member = localTime &&& after q ()
            edits  = arr (\add -> ((), if add then Event (++ [member]) else NoEvent))
            out    = runSamples (edits >>> rpSwitchB [member]) (zip (0 : dts) adds)
            column k = [m !! k | m <- out, length m > k]
            ok k = let col = column k
                       ltk = map fst col
                   in eventIndices (map snd col) == maybe [] pure (firstAtOrAfter ltk q)
        in conjoin [counterexample ("member " ++ show k) (ok k) | k <- [0 .. length (last out) - 1]]

  describe "the examples of docs/YAMPA.md (Time accounting)" $ do
    let at001 sf n = runDt 0.01 sf (replicate n ())
    it "afterEach [(3.0, ()), (2.0, ())] at dt 0.01 fires at t = 3.00 and 5.00 (samples 300, 500)" $
      eventIndices (at001 (afterEach [(3.0, ()), (2.0, ())]) 600) `shouldBe` [300, 500]
    it "two events due 0.001 s apart at dt 0.01 land in two samples" $
      [(i, xs) | (i, Event xs) <- zip [0 :: Int ..] (at001 (afterEachCat [(3.0, 'a'), (0.001, 'b')]) 400)]
        `shouldBe` [(300, "a"), (301, "b")]
    it "delay 1.1 at dt 0.05 releases the sample of time 0 at t = 1.1 (sample 22)" $
      findIndex (== 1) (runDt 0.05 (delay 1.1 0) [1 .. 40 :: Int]) `shouldBe` Just 22

  describe "decimal steps and times, as exact decimals (and Yampa, here) have them" $ do
    -- (the compensated clock reads a binary-fraction sum just short of the
    -- decimal time, and these fired or released one sample late, or
    -- released a sample twice and skipped the next, before 'reached')
    it "after 0.9 at dt 0.15 fires at the sixth sample (local time 0.8999999999999999)" $
      eventIndices (runDt 0.15 (after 0.9 ()) (replicate 10 ())) `shouldBe` [6]
    it "delay 0.3 at dt 0.1 shifts every sample by three, none twice and none skipped" $
      runDt 0.1 (delay 0.3 (-1)) [0 .. 12 :: Int] `shouldBe` ([-1, -1, -1] ++ [0 .. 9])
    it "delay 0.9 at dt 0.3 releases the sample of time 0 at t = 0.9" $
      runDt 0.3 (delay 0.9 (-1)) [0 .. 8 :: Int] `shouldBe` ([-1, -1, -1] ++ [0 .. 5])
    it "repeatedly 0.2 at dt 0.01 fires every 20 samples" $
      eventIndices (runDt 0.01 (repeatedly 0.2 ()) (replicate 130 ())) `shouldBe` [20, 40, 60, 80, 100, 120]
    it "delayEvent 0.2 at dt 0.2 releases an occurrence one sample later" $
      eventIndices (runDt 0.2 (delayEvent 0.2) [ if k == 17 then Event () else NoEvent | k <- [0 .. 25 :: Int] ])
        `shouldBe` [18]

  describe "reached" $ do
    it "allows a few units in the last place, no more: 8 short counts, 64 short does not (property)" $
      property $ forAll (choose (1e-3, 1e9)) $ \t ->
        let u = t * 2 ** (-52)
        in reached (t + 8 * u) t .&&. not (reached (t + 64 * u) t) .&&. reached t t
    it "never for NaN, and for infinity only at infinity" $ do
      reached (0 / 0) 1 `shouldBe` False
      reached 1 (0 / 0) `shouldBe` False
      reached (1 / 0) 1e308 `shouldBe` False
      reached (1 / 0) (1 / 0) `shouldBe` True

  describe "delay never releases a sample at the step it came in" $ do
    it "a delay below the rounding of a late local time delays by one sample (it passed the input through)" $
      runSamples (delay 1e-12 0) ((0, 1) : (1000, 2) : [ (0.01, k) | k <- [3 .. 5 :: Int] ])
        `shouldBe` [0, 1, 2, 3, 4]
    it "so that it closes a loop at any local time (it hung)" $ do
      let acc = loop (arr (\(a, c) -> (c + a, c + a)) >>> second (delay 1e-12 0))
      runSamples acc ((0, 1) : (1000, 2) : [ (0.01, k) | k <- [3 .. 5 :: Int] ])
        `withoutHanging` [1, 3, 6, 10, 15]
