-- | Tests for "AFRP.EventSource.Timed": the sources scheduled in local
-- time and the delayed events, on fixed input lists with hand-computed
-- outputs, and 'repeatedly' near the tolerance of the time against the
-- rule it documents.
module AFRP.EventSource.TimedSpec (spec) where

import           Control.Exception      (ErrorCall (..), evaluate)
import           Data.List              (findIndices, isInfixOf)
import           Test.Hspec             hiding (after)

import           Test.QuickCheck        (Gen, choose, counterexample, elements, forAll, oneof, vectorOf,
                                         withMaxSuccess)

import           AFRP.Basic             (localTime)
import           AFRP.Event             (Event (..), isEvent)
import           AFRP.EventSource.Timed
import           AFRP.EventSourceFixture
import           AFRP.Internal.SF       (DTime, SF, Time)
import           AFRP.Run               (embed)
import           TestUtil

-- | Run a source that ignores its input for @k@ samples with step @dt@.
source :: DTime -> Int -> SF () b -> [b]
source dt k sf = runDt dt sf (replicate k ())

-- | The indices of the samples that carry an occurrence.
occurrences :: [Event a] -> [Int]
occurrences = findIndices isEvent

spec :: Spec
spec = do
  describe "time that overflows, or periods beyond the clock's precision" $ do
    it "local time that overflows is infinite from then on, not NaN" $
      embed localTime ((), [(1, Nothing), (1 / 0, Nothing), (1, Nothing)]) `withoutHanging` [0, 1, 1 / 0, 1 / 0]
    it "after fires at a step that passes its time, even an infinite one; after infinity never fires" $ do
      embed (after 5 ()) ((), [(1 / 0, Nothing), (1, Nothing)]) `withoutHanging` [NoEvent, Event (), NoEvent]
      embed (after 1.5e308 ()) ((), [(1e308, Nothing), (1e308, Nothing)]) `withoutHanging` [NoEvent, NoEvent, Event ()]
      embed (after (1 / 0) ()) ((), [(1e308, Nothing), (1e308, Nothing)]) `withoutHanging` [NoEvent, NoEvent, NoEvent]
    it "repeatedly over a step of more periods than a Double counts ends (it hung): one occurrence a sample" $ do
      -- (after 1e30 s a period of 1 is within the time's tolerance: a
      -- sample that does not move the clock's reading has none)
      embed (repeatedly 1 ()) ((), [(1, Nothing), (1e30, Nothing), (1, Nothing), (1e15, Nothing)])
        `withoutHanging` [NoEvent, Event (), Event (), NoEvent, Event ()]
      length (embed (repeatedly 1e-300 ()) ((), replicate 3 (1, Nothing))) `shouldBe` 4
    it "repeatedly with a period too small for the time to count its boundaries occurs at every sample that moves on" $ do
      -- (t / p overflowed: the next boundary became infinite, and it never occurred again)
      embed (repeatedly 1e-310 'x') ((), replicate 4 (1, Nothing)) `withoutHanging` (NoEvent : replicate 4 (Event 'x'))
      embed (repeatedly 5e-324 'x') ((), [(1, Nothing), (0, Nothing), (2, Nothing)])
        `withoutHanging` [NoEvent, Event 'x', NoEvent, Event 'x']
      -- (a small normal period goes on counting)
      embed (repeatedly 1e-300 'x') ((), replicate 3 (1, Nothing)) `withoutHanging` (NoEvent : replicate 3 (Event 'x'))
    it "repeatedly has no occurrence at a sample where no time passes, whatever the period (it had, below 1e-16 of the time)" $ do
      let zeros = replicate 3 (0, Nothing)
      embed (repeatedly 1e-13 ()) ((), (1000, Nothing) : zeros ++ [(1, Nothing)])
        `withoutHanging` [NoEvent, Event (), NoEvent, NoEvent, NoEvent, Event ()]
      embed (repeatedly 1e-12 ()) ((), (1e4, Nothing) : zeros) `withoutHanging` [NoEvent, Event (), NoEvent, NoEvent, NoEvent]
      -- (a period just above the tolerance still counts its boundaries)
      embed (repeatedly 1e-11 ()) ((), [(1000, Nothing), (0, Nothing), (5e-12, Nothing), (1e-11, Nothing)])
        `withoutHanging` [NoEvent, Event (), NoEvent, NoEvent, Event ()]
    it "repeatedly with a period within the tolerance of the time counts its boundaries exactly (it occurred at nearly every sample)" $ do
      -- (after 1000 s, 1e-12 is about 2^-50 of the time: 'reached' takes
      -- about four boundaries at once, so the next occurrence waits for
      -- the clock to pass them; the clock moves in units of about 1.1e-13)
      let pattern = map (\ev -> if isEvent ev then '1' else '0') . drop 1
      pattern (embed (repeatedly 1e-12 ()) ((), (1000, Nothing) : replicate 20 (1e-13, Nothing)))
        `shouldBe` "100010000000000100000"
      -- (at one unit in the last place of the time or less, every sample that moves the clock)
      pattern (embed (repeatedly 1e-14 ()) ((), (1000, Nothing) : replicate 4 (1e-13, Nothing) ++ [(0, Nothing)]))
        `shouldBe` "111110"
    it "repeatedly with periods near the tolerance of the time follows the rule: occur when the next boundary is reached, then wait for the first not reached" $
      withMaxSuccess 2000 $ forAll genNearTolerance $ \(p, dts) ->
        let samples = [(d, Nothing) | d <- dts]
            times = drop 1 (embed localTime ((), samples))
            got = map isEvent (drop 1 (embed (repeatedly p ()) ((), samples)))
            want = repeatedlyRule p times
        in counterexample (show (p, dts, got, want)) (take (length want) got == want)
    it "repeatedly at the top of the Double range and with subnormal periods (it hung at 1.8e308; at 2^-1020 it fired at every move)" $ do
      let pattern = map (\ev -> if isEvent ev then '1' else '0') . drop 1
      embed (repeatedly 1e300 ()) ((), [(1.7976931348623157e308, Nothing), (0, Nothing)])
        `withoutHanging` [NoEvent, Event (), NoEvent]
      let u = encodeFloat 1 (-1073) :: Double
      pattern (embed (repeatedly u ()) ((), [ (d, Nothing) | d <- 2 ^^ (-1020 :: Int) - 4 * u : replicate 4 u ]))
        `shouldBe` "10101"
    it "repeatedly occurs once at an infinite time, then never; an infinite period never" $ do
      embed (repeatedly 1 ()) ((), [(1, Nothing), (1 / 0, Nothing), (0, Nothing), (1, Nothing)])
        `withoutHanging` [NoEvent, Event (), Event (), NoEvent, NoEvent]
      embed (repeatedly (1 / 0) ()) ((), [(1e308, Nothing), (1 / 0, Nothing), (1, Nothing)])
        `withoutHanging` [NoEvent, NoEvent, NoEvent, NoEvent]
    it "after NaN is an error naming after" $
      evaluate (after (0 / 0) ()) `shouldThrow` (\(ErrorCall m) -> "after" `isInfixOf` m && not ("afterEach" `isInfixOf` m))
    it "delayEvent and delayEventCat by infinity never occur" $ do
      embed (delayEvent (1 / 0)) (Event 'a', [(1, Just (Event 'b')), (1 / 0, Just (Event 'c'))])
        `withoutHanging` [NoEvent, NoEvent, NoEvent]
      embed (delayEventCat (1 / 0)) (Event 'a', [(1, Just (Event 'b'))]) `withoutHanging` [NoEvent, NoEvent]
  describe "never" $ do
    it "never occurs" $
      source 1 5 (never :: SF () (Event Int)) `shouldBe` replicate 5 NoEvent
    it "never occurs, whatever the input" $
      runDt 0.5 never [e 'a', e 'b', n] `shouldBe` (replicate 3 n :: [Event ()])

  describe "now" $ do
    it "occurs at time 0 only" $
      source 1 4 (now 'x') `shouldBe` [e 'x', n, n, n]
    it "occurs at time 0 only, with irregular steps too" $
      runSamples (now (7 :: Int)) [(5, ()), (0.001, ()), (100, ())] `shouldBe` [e 7, n, n]

  describe "after" $ do
    it "after 1.0 with steps of 0.5 fires exactly at t = 1.0 (third sample)" $
      source 0.5 5 (after 1.0 'a') `shouldBe` [n, n, e 'a', n, n]
    it "after 1 with steps of 0.1 fires at t = 1.0, the eleventh sample" $
      occurrences (source 0.1 15 (after 1 ())) `shouldBe` [10]
    it "after 1.0 with steps of 0.3 fires at the first sample past 1.0 (t = 1.2)" $
      source 0.3 6 (after 1.0 'a') `shouldBe` [n, n, n, n, e 'a', n]
    it "after 0 is now" $
      source 1 3 (after 0 'z') `shouldBe` [e 'z', n, n]
    it "fires when a single long step jumps past its time, and only once" $
      runSamples (after 1 'q') [(0, ()), (0.25, ()), (10, ()), (1, ())]
        `shouldBe` [n, n, e 'q', n]
    it "with a negative time is an error" $
      forceEvents (source 1 3 (after (-1) ())) `shouldThrow` anyErrorCall

  describe "repeatedly" $ do
    it "occurs at p, 2p, 3p, ... and not at time 0" $
      source 0.25 11 (repeatedly 0.5 'r')
        `shouldBe` [n, n, e 'r', n, e 'r', n, e 'r', n, e 'r', n, e 'r']
    it "fires at the first sample at or after each multiple of the period" $
      -- steps of 0.4: times 0, .4, .8, 1.2, 1.6, 2.0, 2.4; period 0.5
      occurrences (source 0.4 7 (repeatedly 0.5 ())) `shouldBe` [2, 3, 4, 5]
    it "produces one occurrence when a step spans several periods (no backlog)" $
      -- times 0, .25, 1.75, 2.0, 2.25, 2.5
      runSamples (repeatedly 0.5 'r') [(0, ()), (0.25, ()), (1.5, ()), (0.25, ()), (0.25, ()), (0.25, ())]
        `shouldBe` [n, n, e 'r', e 'r', n, e 'r']
    it "keeps its grid after a long step landing on a boundary" $
      -- times 0, 1.0, 1.25, 1.5, 1.75, 2.0
      runSamples (repeatedly 0.5 'r') [(0, ()), (1, ()), (0.25, ()), (0.25, ()), (0.25, ()), (0.25, ())]
        `shouldBe` [n, e 'r', n, e 'r', n, e 'r']
    it "is exact with steps of 0.1 and period 0.1 (every sample after the first)" $
      occurrences (source 0.1 101 (repeatedly 0.1 ())) `shouldBe` [1 .. 100]
    it "is exact with steps of 0.1 and period 0.2" $
      occurrences (source 0.1 61 (repeatedly 0.2 ())) `shouldBe` [2, 4 .. 60]
    it "is exact with steps of 0.1 and period 0.3" $
      occurrences (source 0.1 61 (repeatedly 0.3 ())) `shouldBe` [3, 6 .. 60]
    it "with a zero period is an error" $
      forceEvents (source 1 3 (repeatedly 0 ())) `shouldThrow` anyErrorCall
    it "with a negative period is an error" $
      forceEvents (source 1 3 (repeatedly (-0.5) ())) `shouldThrow` anyErrorCall

  describe "afterEach" $ do
    let sched = [(0.5, 'a'), (0.5, 'b'), (0, 'c'), (1, 'd')]
    it "occurs at the running sums of the delays, one occurrence per sample" $
      -- due times .5, 1.0, 1.0, 2.0; 'c' shares its sample with 'b' and is dropped
      source 0.5 6 (afterEach sched) `shouldBe` [n, e 'a', e 'b', n, e 'd', n]
    it "measures each delay from the previous scheduled time, not the firing time" $
      -- due .6 and 1.2, reached at 1.0 and 1.5 (from the firing time, 'b'
      -- would be due at 1.6 and fire at 2.0)
      source 0.5 5 (afterEach [(0.6, 'a'), (0.6, 'b')]) `shouldBe` [n, n, e 'a', e 'b', n]
    it "fires leading zero delays at time 0 (only the first of them)" $
      source 1 3 (afterEach [(0, 'x'), (0, 'y'), (1, 'z')]) `shouldBe` [e 'x', e 'z', n]
    it "on the empty schedule never occurs" $
      source 1 3 (afterEach ([] :: [(Time, ())])) `shouldBe` [n, n, n]
    it "works with an infinite schedule" $
      occurrences (source 0.5 9 (afterEach (repeat (1, ())))) `shouldBe` [2, 4, 6, 8]
    it "reports a negative delay only when it is reached" $ do
      let outs = source 0.5 4 (afterEach [(1, 'a'), (-1, 'b')])
      take 2 outs `shouldBe` [n, n]
      forceEvents outs `shouldThrow` anyErrorCall

  describe "afterEachCat" $ do
    it "delivers every occurrence due at a sample, in schedule order" $
      source 1 7 (afterEachCat [(0.1, 'a'), (0.2, 'b'), (0.3, 'c'), (5, 'd')])
        `shouldBe` [n, e "abc", n, n, n, n, e "d"]
    it "delivers occurrences sharing a due time together" $
      source 0.5 6 (afterEachCat [(0.5, 'a'), (0.5, 'b'), (0, 'c'), (1, 'd')])
        `shouldBe` [n, e "a", e "bc", n, e "d", n]
    it "delivers all leading zero delays at time 0" $
      source 1 3 (afterEachCat [(0, 'x'), (0, 'y'), (1, 'z')]) `shouldBe` [e "xy", e "z", n]
    it "follows the documented example" $
      embed (afterEachCat [(0.5, 'a'), (0.1, 'b'), (1, 'c')]) ((), replicate 3 (1, Nothing))
        `shouldBe` [n, e "ab", e "c", n]

  describe "delayEvent" $ do
    it "delays each occurrence by q (steps of 0.25, q = 1)" $
      runDt 0.25 (delayEvent 1.0) [e 'a', n, e 'b', n, n, n, n, n, n]
        `shouldBe` [n, n, n, n, e 'a', n, e 'b', n, n]
    it "fires at the first sample at or after t + q" $
      -- occurrence at 0.5, due 1.2; samples every 0.5
      runDt 0.5 (delayEvent 0.7) [n, e 'a', n, n, n] `shouldBe` [n, n, n, e 'a', n]
    it "is exact with steps of 0.1 (occurrence at 0.1, q = 0.3, out at 0.4)" $
      occurrences (runDt 0.1 (delayEvent 0.3) (n : e () : replicate 8 n)) `shouldBe` [4]
    it "acts as a one-sample delay when q is below the step" $
      runDt 0.5 (delayEvent 0.1) [e 1, n, e 2, e 3, n] `shouldBe` [n, e 1, n, e (2 :: Int), e 3]
    it "keeps only the earliest when several fall due at one sample" $
      -- times 0, .25, .5, 1.5, 1.75, 2.75
      runSamples (delayEvent 1.0)
        [(0, e 'a'), (0.25, e 'b'), (0.25, e 'c'), (1, n), (0.25, e 'd'), (1, n)]
        `shouldBe` [n, n, n, e 'a', n, e 'd']
    it "with q = 0 is the identity" $
      runDt 1 (delayEvent 0) [e 'a', n, e 'b'] `shouldBe` [e 'a', n, e 'b']
    it "with a negative delay is an error" $
      forceEvents (runDt 1 (delayEvent (-1)) [e 'a', n]) `shouldThrow` anyErrorCall

  describe "delayEventCat" $ do
    it "delivers every occurrence due at a sample, oldest first" $
      runSamples (delayEventCat 1.0)
        [(0, e 'a'), (0.25, e 'b'), (0.25, e 'c'), (1, n), (0.25, e 'd'), (1, n)]
        `shouldBe` [n, n, n, e "abc", n, e "d"]
    it "schedules an occurrence arriving at an emitting sample for later" $
      runDt 0.5 (delayEventCat 0.5) [e 'a', e 'b', n, n] `shouldBe` [n, e "a", e "b", n]
    it "with q = 0 wraps each occurrence in a list, undelayed" $
      runDt 1 (delayEventCat 0) [e 'a', n, e 'b'] `shouldBe` [e "a", n, e "b"]
    it "with a negative delay is an error" $
      forceEvents (runDt 1 (delayEventCat (-0.5)) [e 'a', n]) `shouldThrow` anyErrorCall

-- | The rule 'repeatedly' documents, written directly: at each sample time
-- t, an occurrence when boundary n (at n * p) is 'reached'; then n becomes
-- the first boundary after it that t has not reached, found by doubling
-- and bisection ('reached' of n * p falls as n grows). The rule is
-- compared only up to an occurrence at a time where the period is at
-- most 2^-53 of it (from there on, the documented regime is an
-- occurrence at every sample that moves the clock).
repeatedlyRule :: Time -> [Time] -> [Bool]
repeatedlyRule p = go 1
  where
    hit k t = t >= due || due - t <= 3.552713678800501e-15 * abs t
      where due = fromIntegral k * p
    go :: Integer -> [Time] -> [Bool]
    go _ [] = []
    go k (t : ts)
      | hit k t   = True : (if p * 2 ^ (53 :: Int) <= t then [] else go (firstNotHit t (k + 1)) ts)
      | otherwise = False : go k ts
    firstNotHit t lo = bisect lo (grow 1)
      where
        grow k = if hit (lo + k) t then grow (2 * k) else lo + k
        bisect a b
          | a >= b    = a
          | otherwise = let m = (a + b) `div` 2 in if hit m t then bisect (m + 1) b else bisect a m

-- | A first step to a time t0, then steps of 0, of about a period, and of
-- a few units in the last place of t0, with the period from 2^-36 to
-- 2^-56 of t0: around the tolerance of 'reached' (2^-48) and the unit in
-- the last place (2^-52).
genNearTolerance :: Gen (Time, [DTime])
genNearTolerance = do
  t0 <- elements [0.3, 1, 10, 1000, 12345.678, 1e6, 1 - 3 * 2 ^^ (-53 :: Int), 1024 - 2 ^^ (-40 :: Int), 2 ^^ (-1000 :: Int)]
  k <- choose (36, 56 :: Int)
  frac <- choose (0.5, 2)
  let p = t0 * frac * 2 ^^ negate k
  size <- choose (1, 60)
  steps <- vectorOf size (oneof [pure 0, pure p, pure (p / 10), (* p) <$> choose (0, 50), (* (t0 * 2 ^^ (-52 :: Int))) <$> choose (0, 40)])
  pure (p, t0 : steps)
