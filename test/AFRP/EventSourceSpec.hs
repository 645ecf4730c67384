-- | Tests for "AFRP.EventSource": every event source and event-stream
-- transformer, on fixed input lists with hand-computed outputs.
module AFRP.EventSourceSpec (spec) where

import           Control.Arrow     (arr, (>>>))
import           Control.Exception (ErrorCall (..), evaluate)
import           Data.List         (findIndices, isInfixOf, isPrefixOf)
import           Data.Maybe        (fromMaybe)
import           Test.Hspec        hiding (after)

import           Test.QuickCheck   (Gen, choose, counterexample, elements, forAll, oneof, vectorOf,
                                    withMaxSuccess)

import           AFRP.Basic        (localTime)
import           AFRP.Event        (Event (..), isEvent)
import           AFRP.EventSource
import           AFRP.Internal.SF  (DTime, SF, Time)
import           AFRP.Run          (embed)
import           TestUtil

-- | An error call whose message (not its location) mentions the text.
errorMentioning :: String -> Selector ErrorCall
errorMentioning s (ErrorCallWithLocation msg _) = s `isInfixOf` msg

-- | Feed the signal function a bottom wherever the outer input is
-- 'Nothing'. The runner may force each outer sample, but not what the
-- inner signal function receives, so this observes whether the signal
-- function under test evaluates its current input.
bottomWhereNothing :: SF a b -> SF (Maybe a) b
bottomWhereNothing sf = arr (fromMaybe (error "the current input was evaluated")) >>> sf

-- | Force every output constructor of a run of an event stream.
forceEvents :: [Event a] -> IO Int
forceEvents = evaluate . length . filter isEvent

-- | Run a source that ignores its input for @k@ samples with step @dt@.
source :: DTime -> Int -> SF () b -> [b]
source dt k sf = runDt dt sf (replicate k ())

-- | The indices of the samples that carry an occurrence.
occurrences :: [Event a] -> [Int]
occurrences = findIndices isEvent

e :: a -> Event a
e = Event

n :: Event a
n = NoEvent

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

  describe "edge" $ do
    it "occurs on rising edges only" $
      runDt 1 edge [False, True, True, False, True] `shouldBe` [n, e (), n, n, e ()]
    it "does not occur for True at time 0" $
      runDt 1 edge [True, True, False, True] `shouldBe` [n, n, n, e ()]
    it "follows the documented example" $
      embed edge (True, [(1, Just False), (1, Just True), (1, Nothing)])
        `shouldBe` [n, n, e (), n]

  describe "iEdge" $ do
    it "iEdge False occurs for True at time 0" $
      runDt 1 (iEdge False) [True, True, False, True] `shouldBe` [e (), n, n, e ()]
    it "iEdge False does not occur for False at time 0" $
      runDt 1 (iEdge False) [False, True] `shouldBe` [n, e ()]
    it "iEdge True does not occur for True at time 0" $
      runDt 1 (iEdge True) [True, False, True] `shouldBe` [n, n, e ()]

  describe "edgeTag" $ do
    it "is edge carrying the given value" $
      runDt 1 (edgeTag 'k') [True, False, True, True] `shouldBe` [n, n, e 'k', n]
    it "does not occur for True at time 0" $
      runDt 1 (edgeTag 'k') [True] `shouldBe` [n]

  describe "edgeJust" $ do
    it "occurs, with the value, on each change from Nothing to Just" $
      runDt 1 edgeJust [Just 1, Nothing, Just 2, Just 3, Nothing, Nothing, Just (4 :: Int)]
        `shouldBe` [n, n, e 2, n, n, n, e 4]
    it "occurs right after a Nothing at time 0" $
      runDt 1 edgeJust [Nothing, Just 'v', Just 'w'] `shouldBe` [n, e 'v', n]
    it "does not look at an input that follows a Just until the next sample (as Yampa)" $ do
      let bad = error "input" :: Maybe Int
      take 1 (runDt 1 edgeJust [bad, Just 1]) `shouldBe` [n]
      take 2 (runDt 1 edgeJust [Just 1, bad, Nothing]) `shouldBe` [n, n]
      forceEvents (runDt 1 edgeJust [bad, Just 1]) `shouldThrow` errorCall "input"

  describe "edgeBy" $ do
    let rise prev cur = if cur > prev then Just (cur - prev) else Nothing
    it "applies the function to the previous and current samples" $
      runDt 1 (edgeBy rise 0) [3, 2, 5, 5, 7 :: Int] `shouldBe` [e 3, n, e 3, n, e 2]
    it "uses the initial value as the previous sample at time 0" $
      runDt 1 (edgeBy rise 10) [3, 4 :: Int] `shouldBe` [n, e 1]
    it "evaluates each input sample at the next sample" $
      forceEvents (runDt 1 (bottomWhereNothing (edgeBy (\_ _ -> Nothing :: Maybe ()) (0 :: Int))) [Just 1, Nothing, Just 2])
        `shouldThrow` anyErrorCall

  describe "notYet" $ do
    it "suppresses an occurrence at time 0 and passes later ones" $
      runDt 1 notYet [e 1, e 2, n, e (3 :: Int)] `shouldBe` [n, e 2, n, e 3]
    it "passes occurrences from the second sample on" $
      runDt 1 notYet [n, e 'a'] `shouldBe` [n, e 'a']

  describe "once" $ do
    it "passes only the first occurrence" $
      runDt 1 once [n, e 1, e 2, n, e (3 :: Int)] `shouldBe` [n, e 1, n, n, n]
    it "passes an occurrence at time 0 and nothing after" $
      runDt 1 once [e 'a', e 'b', e 'c'] `shouldBe` [e 'a', n, n]

  describe "takeEvents" $ do
    it "passes the first n occurrences" $
      runDt 1 (takeEvents 2) [e 1, n, e 2, e 3, e (4 :: Int)] `shouldBe` [e 1, n, e 2, n, n]
    it "with 0 (or less) passes nothing" $ do
      runDt 1 (takeEvents 0) [e 'a', e 'b'] `shouldBe` [n, n]
      runDt 1 (takeEvents (-3)) [e 'a', e 'b'] `shouldBe` [n, n]

  describe "dropEvents" $ do
    it "suppresses the first n occurrences, then passes all" $
      runDt 1 (dropEvents 2) [e 1, n, e 2, e 3, n, e (4 :: Int)] `shouldBe` [n, n, n, e 3, n, e 4]
    it "with 0 is the identity" $
      runDt 1 (dropEvents 0) [e 'a', n, e 'b'] `shouldBe` [e 'a', n, e 'b']
    it "does not look at an input sample before the next sample while it drops (as Yampa)" $ do
      let bad = error "input" :: Event Int
      take 2 (runDt 1 (dropEvents 1) [n, bad, e 1]) `shouldBe` [n, n]
      take 3 (runDt 1 (dropEvents 2) [e 1, n, bad, e 2]) `shouldBe` [n, n, n]
      forceEvents (runDt 1 (dropEvents 1) [n, bad, e 1]) `shouldThrow` errorCall "input"
      -- (once the occurrences are dropped, the input is the output)
      forceEvents (take 2 (runDt 1 (dropEvents 1) [e 0, bad])) `shouldThrow` errorCall "input"

  describe "snap" $ do
    it "occurs at time 0 only, carrying the input there" $
      runDt 1 snap [10, 11, 12 :: Int] `shouldBe` [e 10, n, n]

  describe "snapAfter" $ do
    it "occurs once at the first sample at or after t, with that input" $
      runDt 0.5 (snapAfter 1.0) [10, 11, 12, 13 :: Int] `shouldBe` [n, n, e 12, n]
    it "occurs past t when no sample falls on it" $
      runDt 0.4 (snapAfter 1.0) [10, 11, 12, 13, 14 :: Int] `shouldBe` [n, n, n, e 13, n]
    it "with t = 0 occurs at time 0" $
      runDt 1 (snapAfter 0) "ab" `shouldBe` [e 'a', n]
    it "rejects a negative t, as after does" $
      evaluate (length (runDt 1 (snapAfter (-2)) "ab")) `shouldThrow` anyErrorCall

  describe "sample" $ do
    it "refuses a period that is not positive, naming itself (it named repeatedly)" $
      mapM_ (\p -> evaluate (sample p :: SF () (Event ()))
                     `shouldThrow` (\(ErrorCall m) -> "AFRP.EventSource.sample: the period must be positive" `isPrefixOf` m))
            [0, -1, 0 / 0]
    it "occurs every p seconds (not at 0) with the input at that instant" $
      runDt 0.25 (sample 0.5) [0 .. 6 :: Int] `shouldBe` [n, n, e 2, n, e 4, n, e 6]
    it "produces one occurrence when a step spans several periods" $
      runSamples (sample 0.5) [(0, 'a'), (2, 'b'), (0.25, 'c'), (0.25, 'd')]
        `shouldBe` [n, e 'b', n, e 'd']

  describe "sampleWindow" $ do
    it "produces the last w samples, oldest first, at each sampling instant" $
      runDt 0.25 (sampleWindow 2 0.5) [0 .. 8 :: Int]
        `shouldBe` [n, n, e [2], n, e [2, 4], n, e [4, 6], n, e [6, 8]]
    it "takes one sample per period when a step spans several periods" $
      -- times 0, .5, 2.0, 2.5: the step to 2.0 spans 1.0, 1.5 and 2.0
      runSamples (sampleWindow 3 0.5) [(0, 0), (0.5, 1), (1.5, 2), (0.5, 3 :: Int)]
        `shouldBe` [n, e [1], e [2, 2, 2], e [2, 2, 3]]
    it "a step spanning more periods than the window fills it with that step's input" $
      runSamples (sampleWindow 3 0.5) [(0, 0), (0.5, 1), (10, 2), (0.5, 3 :: Int)]
        `shouldBe` [n, e [1], e [2, 2, 2], e [2, 2, 3]]
    it "a step spanning billions of periods ends at once, in bounded memory (it built a list of every period)" $ do
      runSamples (sampleWindow 3 1e-6) [(0, 'a'), (1e6, 'b'), (0.5, 'c'), (1e-6, 'd')]
        `withoutHanging` [n, e "bbb", e "ccc", e "ccd"]
      -- more periods than a Double counts, a period below the clock's
      -- resolution, and an infinite time: every sample fills the window
      runSamples (sampleWindow 2 1e-300) [(0, 'a'), (1, 'b'), (1, 'c')]
        `withoutHanging` [n, e "bb", e "cc"]
      runSamples (sampleWindow 2 1e-9) [(0, 'a'), (1e9, 'b'), (1e-9, 'c')]
        `withoutHanging` [n, e "bb", e "cc"]
      runSamples (sampleWindow 2 1) [(0, 'a'), (1 / 0, 'b'), (1, 'c')]
        `withoutHanging` [n, e "bb", e "cc"]
    it "has no instant at a sample where no time passes (it filled the window where every instant counts as reached)" $ do
      runSamples (sampleWindow 2 1e-13) [(0, 'a'), (1000, 'b'), (0, 'c'), (0, 'd'), (1, 'e')]
        `withoutHanging` [n, e "bb", n, n, e "ee"]
      runSamples (sampleWindow 2 1) [(0, 'a'), (1 / 0, 'b'), (0, 'c'), (1, 'd')]
        `withoutHanging` [n, e "bb", n, e "dd"]
      runSamples (sampleWindow 2 0.5) [(0, 'a'), (0.5, 'b'), (0, 'c'), (0.5, 'd')]
        `shouldBe` [n, e "b", n, e "bd"]
    it "a huge window costs no more than a small one (it counted the periods one by one up to its size)" $ do
      let lens = map (fmap length) . drop 1
      lens (runSamples (sampleWindow 5000 1) [(0, 'a'), (4500.5, 'b'), (2, 'c')]) `shouldBe` [e 4500, e 4502]
      fmap (fmap (take 2)) (runSamples (sampleWindow maxBound 1) [(0, 'a'), (1e12, 'b'), (1e300, 'c')])
        `withoutHanging` [n, e "bb", e "cc"]
      fmap (fmap (take 2)) (runSamples (sampleWindow maxBound 1e-300) [(0, 'a'), (1, 'b')])
        `withoutHanging` [n, e "bb"]
    it "after a step spanning many periods, the instants stay on the multiples of the period" $
      -- 20,000 periods of 0.5 in one step (counted at once), then steps of 0.25
      runSamples (sampleWindow 2 0.5) ((0, 0) : (10000.25, 1) : [ (0.25, k) | k <- [2 .. 6 :: Int] ])
        `shouldBe` [n, e [1, 1], e [1, 2], n, e [2, 4], n, e [4, 6]]
    it "with a window of 1 is sample with singleton lists" $
      runDt 0.5 (sampleWindow 1 1) "abcde" `shouldBe` [n, n, e "c", n, e "e"]
    it "with a window below 1 is an error" $
      forceEvents (runDt 1 (sampleWindow 0 1) [(), ()]) `shouldThrow` errorMentioning "window"
    it "with a zero period is an error" $
      forceEvents (runDt 1 (sampleWindow 2 0) [(), ()]) `shouldThrow` anyErrorCall
    it "with a negative period is an error" $
      forceEvents (runDt 1 (sampleWindow 2 (-1)) [(), ()]) `shouldThrow` anyErrorCall

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
