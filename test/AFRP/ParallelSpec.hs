{-# LANGUAGE Arrows #-}
-- | Tests for "AFRP.Parallel": parallel composition of collections and the
-- switches over whole collections. Every expected output below was
-- computed by hand from the functions' documentation.
module AFRP.ParallelSpec (spec) where

import           Control.Arrow     (arr, returnA, (&&&), (>>>))
import           Control.Exception (evaluate)
import           Data.Map          (Map)
import qualified Data.Map          as Map
import           System.Timeout    (timeout)
import           Test.Hspec        hiding (after)

import           AFRP.Basic        (constant, identity, localTime)
import           AFRP.Event        (Event (..))
import           AFRP.EventSource  (after, edge, now)
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (SF, stepSF)
import           AFRP.Parallel
import           AFRP.Run          (embed)
import           AFRP.Switch       (kSwitch, switch)
import           TestUtil

------------------------------------------------------------------------------
-- Helpers

shouldApproxLists :: [[Double]] -> [[Double]] -> Expectation
shouldApproxLists xss yss
  | length xss == length yss
  , and (zipWith (\xs ys -> length xs == length ys && and (zipWith approx xs ys)) xss yss)
  = pure ()
  | otherwise = expectationFailure ("expected " ++ show yss ++ "\n but got " ++ show xss)

shouldApproxMaps :: (Ord k, Show k) => [Map k Double] -> [Map k Double] -> Expectation
shouldApproxMaps xs ys
  | length xs == length ys && and (zipWith same xs ys) = pure ()
  | otherwise = expectationFailure ("expected " ++ show ys ++ "\n but got " ++ show xs)
  where
    same m n = Map.keys m == Map.keys n && and (zipWith approx (Map.elems m) (Map.elems n))

-- | Fully evaluate the outputs, failing if that takes 30 s (diverged; the
-- bound is a guard against a hang, generous for a loaded machine).
shouldTerminateWithLists :: [[Double]] -> [[Double]] -> Expectation
shouldTerminateWithLists xss expected = do
  r <- timeout 30000000 (evaluate (sum (map sum xss)) >> pure xss)
  case r of
    Nothing -> expectationFailure "diverged (no result within 30 s)"
    Just ys -> ys `shouldApproxLists` expected

-- | Rising edge of a condition.
when' :: (a -> Bool) -> SF a (Event ())
when' p = arr p >>> edge

-- | A routing function: even-indexed members see the first component of
-- the input, odd-indexed ones the second.
evenOdd :: (Double, Double) -> [sf] -> [(Double, sf)]
evenOdd (x, y) = zipWith (\i sf -> (if even i then x else y, sf)) [0 :: Int ..]

-- | A routing function for maps: each member sees the value at its own key
-- (0 if absent).
byKey :: Map Int Double -> Map Int sf -> Map Int (Double, sf)
byKey m = Map.mapWithKey (\k sf -> (Map.findWithDefault 0 k m, sf))

-- | The last element of a two-element list, otherwise 0.
second' :: [Double] -> Double
second' cs = case cs of
  [_, y] -> y
  _      -> 0

------------------------------------------------------------------------------

spec :: Spec
spec = do
  parSpec
  pSwitchSpec
  rpSwitchSpec
  mapSpec
  loopSpec
  documentedSpec

parSpec :: Spec
parSpec = do
  describe "par" $ do
    it "gives each member the input chosen by the routing function" $
      runDt 0.5 (par evenOdd [integral, identity, arr (* 2)]) [(1, 10), (2, 20), (3, 30)]
        `shouldApproxLists` [[0, 10, 2], [0.5, 20, 4], [1.5, 30, 6]]

    it "runs an empty collection" $
      runDt 1 (par evenOdd ([] :: [SF Double Double])) [(1, 2), (3, 4)] `shouldBe` [[], []]

  describe "parB" $ do
    it "broadcasts the input to every member, all starting at time 0" $
      runDt 0.25 (parB [localTime, integral, arr negate]) [2, 4, 6 :: Double]
        `shouldApproxLists` [[0, 0, -2], [0.25, 0.5, -4], [0.5, 1.5, -6]]

    it "steps every member by the same irregular time steps" $
      runSamples (parB [localTime, integral]) [(0, 1), (0.3, 2), (0.7, 3 :: Double)]
        `shouldApproxLists` [[0, 0], [0.3, 0.3], [1.0, 1.7]]

    it "a bank of integrals gives, bit for bit, what each integral alone gives" $
      -- after the first step the members are kept as one array of sums
      let dts = [0.1, 0.3, 0.05, 1, 0.2, 0.7]
          xs  = [1, -2.5, 3, 0.125, 7, -1, 4 :: Double]
          samples = (head xs, [ (d, Just x) | (d, x) <- zip dts (tail xs) ])
          one = embed integral samples
      in embed (parB (replicate 4 integral)) samples `shouldBe` map (replicate 4) one

    it "keeps a bank's members in order, each with its own sum" $ do
      -- a running integral (frozen by kSwitch at t = 1) beside a fresh
      -- one, and a third started later still: the same outputs as the
      -- members side by side with &&&
      let started = kSwitch integral (arr snd >>> arr (>= 1) >>> edge)
          viaParB = started (\frozen () -> parB [frozen, integral, frozen] >>> arr (\ys -> sum (zipWith (*) [1, 1000, 1000000] ys)))
          viaFan  = started (\frozen () -> (frozen &&& integral &&& frozen) >>> arr (\(a, (b, c)) -> a + 1000 * b + 1000000 * c))
          samples = (1, [ (0.25, Just x) | x <- [2 .. 20 :: Double] ])
      embed viaParB samples `shouldBe` embed viaFan samples

    it "does not evaluate the current input in a bank of integrals" $ do
      -- (stepped by hand: embed evaluates every input sample)
      let (sf1, _)  = stepSF (parB (replicate 3 integral)) 0 (1 :: Double)
          (sf2, y2) = stepSF sf1 0.5 2
          (sf3, y3) = stepSF sf2 0.5 undefined
          (_, y4)   = stepSF sf3 0.5 undefined
      (y2, y3) `shouldBe` ([0.5, 0.5, 0.5], [1.5, 1.5, 1.5])
      evaluate (sum y4) `shouldThrow` anyErrorCall

  describe "parZ" $ do
    it "zips the input list with the members, ignoring extra inputs" $
      runDt 1 (parZ [integral, arr (+ 1), localTime]) [[1, 2, 3], [4, 5, 6, 99 :: Double]]
        `shouldApproxLists` [[0, 3, 0], [1, 6, 1]]

    it "is an error when the input list is too short at time 0" $
      evaluate (sum (map sum (runDt 1 (parZ [identity, identity]) [[1 :: Double]])))
        `shouldThrow` anyErrorCall

    it "is an error when a later input list is too short, naming the function, and at every sample after" $ do
      let outs = runDt 1 (parZ [localTime, identity]) [[1, 2], [5 :: Double], [6, 7]]
          short = errorCall "AFRP.Parallel.parZ: the input list is shorter than the list of signal functions"
      outs !! 0 `shouldBe` [0, 2]
      evaluate (sum (outs !! 1)) `shouldThrow` short
      evaluate (sum (outs !! 2)) `shouldThrow` short

------------------------------------------------------------------------------

-- The input 1, 2, 3, ... at steps of 0.5. The integral member:
-- 0, 0.5, 1.5, 3.0, 5.0, 7.5.
ramp :: [Double]
ramp = [1 .. 7]

-- Start with one integral; when the outputs' sum reaches 1, add a
-- localTime; when that localTime reaches 1, keep only it.
chainB :: SF Double [Double]
chainB = pSwitchB [integral] (when' (\(_, cs) -> sum cs >= 1)) $ \sfs () ->
         pSwitchB (sfs ++ [localTime]) (when' (\(_, cs) -> second' cs >= 1)) $ \sfs' () ->
         parB (drop 1 sfs')

dchainB :: SF Double [Double]
dchainB = dpSwitchB [integral] (when' (\(_, cs) -> sum cs >= 1)) $ \sfs () ->
          dpSwitchB (sfs ++ [localTime]) (when' (\(_, cs) -> second' cs >= 1)) $ \sfs' () ->
          parB (drop 1 sfs')

-- A custom routing, and a detector that looks at the external input.
chainR :: SF (Double, Double) [Double]
chainR = pSwitch evenOdd [integral, integral] (when' (\((x, _), _) -> x >= 3)) $ \sfs () ->
         par evenOdd (sfs ++ [identity])

dchainR :: SF (Double, Double) [Double]
dchainR = dpSwitch evenOdd [integral, integral] (when' (\((x, _), _) -> x >= 3)) $ \sfs () ->
          par evenOdd (sfs ++ [identity])

-- Zipped inputs; at the switch the (frozen) members swap places.
chainZ :: SF [Double] [Double]
chainZ = pSwitchZ [integral, integral] (when' (\(_, cs) -> any (>= 10) cs)) $ \sfs () ->
         parZ (reverse sfs)

dchainZ :: SF [Double] [Double]
dchainZ = dpSwitchZ [integral, integral] (when' (\(_, cs) -> any (>= 10) cs)) $ \sfs () ->
          parZ (reverse sfs)

zInputs :: [[Double]]
zInputs = [[1, 10], [2, 20], [3, 30], [4, 40]]

pSwitchSpec :: Spec
pSwitchSpec = do
  describe "pSwitchB" $ do
    it "switches on the current outputs; frozen members resume, new ones start at 0" $
      -- t=1.0: integral 1.5 (its replayed step), new localTime 0;
      -- t=2.0: localTime reaches 1, only it is kept (its step replayed).
      runDt 0.5 chainB (take 6 ramp)
        `shouldApproxLists` [[0], [0.5], [1.5, 0], [3.0, 0.5], [1.0], [1.5]]

    it "switches at time 0, passing the unstarted collection" $
      runDt 0.5 (pSwitchB [localTime >>> arr (+ 100)] (now ()) (\sfs () -> parB (localTime : sfs)))
                (replicate 3 ())
        `shouldApproxLists` [[0, 100], [0.5, 100.5], [1.0, 101.0]]

    it "frozen members started later replay the captured step, not the current one" $ do
      -- Times 0, 0.5, 1.0, 1.25, 2.0, 2.25, 2.55. Event at 1.0 (localTime
      -- frozen at 0.5 with a pending step of 0.5); the collection is
      -- restarted 1 s later, at 2.0 (time step 0.75): it shows 1.0.
      let sf = pSwitchB [localTime] (when' (\(_, cs) -> sum cs >= 1))
                 (\sfs () -> switch (constant [] &&& after 1 ()) (\() -> parB sfs))
      runSamples sf [(0, ()), (0.5, ()), (0.5, ()), (0.25, ()), (0.75, ()), (0.25, ()), (0.3, ())]
        `shouldApproxLists` [[0], [0.5], [], [], [1.0], [1.25], [1.55]]

  describe "dpSwitchB" $ do
    it "outputs the old collection at the switching instant, the new one after" $
      -- t=1.0: old [1.5]; the new collection starts there.
      -- t=2.0: the second detector fires on [5.0, 1.0]: old output.
      runDt 0.5 dchainB ramp
        `shouldApproxLists` [[0], [0.5], [1.5], [3.0, 0.5], [5.0, 1.0], [1.5], [2.0]]

    it "on an event at time 0 outputs the old collection and starts the new one at 0" $
      runDt 0.5 (dpSwitchB [localTime >>> arr (+ 100)] (now ()) (\sfs () -> parB (localTime : sfs)))
                (replicate 3 ())
        `shouldApproxLists` [[100], [0.5, 100.5], [1.0, 101.0]]

  describe "pSwitch" $ do
    it "routes with a custom function and lets the detector see the input" $
      -- x reaches 3 at t=2: the integrals replay their step (3, 30) and a
      -- new identity member (index 2, sees x) starts.
      runDt 1 chainR [(1, 10), (2, 20), (3, 30), (4, 40)]
        `shouldApproxLists` [[0, 0], [1, 10], [3, 30, 3], [6, 60, 4]]

  describe "dpSwitch" $ do
    it "routes with a custom function; old output at the switching instant" $
      runDt 1 dchainR [(1, 10), (2, 20), (3, 30), (4, 40)]
        `shouldApproxLists` [[0, 0], [1, 10], [3, 30], [6, 60, 4]]

  describe "pSwitchZ" $ do
    it "zips inputs; the new collection's order decides the routing from the switch on" $
      -- Event at t=1 (second integral = 10). Swapped: the first member now
      -- sees the second input and vice versa; each replays its step on its
      -- new input: [0 + 1*10, 0 + 1*1] = [10, 1]; then [10+2, 1+20], ...
      runDt 1 chainZ zInputs `shouldApproxLists` [[0, 0], [10, 1], [12, 21], [15, 51]]

  describe "dpSwitchZ" $ do
    it "zips inputs; old output at the switching instant" $
      runDt 1 dchainZ zInputs `shouldApproxLists` [[0, 0], [1, 10], [12, 21], [15, 51]]

------------------------------------------------------------------------------

type Edit = [SF Double Double] -> [SF Double Double]

rpInputs :: [(Double, Event Edit)]
rpInputs =
  [ (1, Event (localTime :))       -- t0: add at time 0
  , (2, NoEvent)
  , (3, Event (integral :))
  , (4, NoEvent)
  , (5, Event (drop 1))            -- remove the integral
  , (6, Event (arr (* 10) :))
  , (7, Event (arr (* 10) :))      -- the same kind of event on the next sample
  , (8, NoEvent)
  ]

zpInputs :: [([Double], Event Edit)]
zpInputs =
  [ ([1, 2], Event (++ [integral]))
  , ([3, 4], NoEvent)
  , ([5, 6], Event (drop 1))
  , ([7, 8], NoEvent)
  ]

rpSwitchSpec :: Spec
rpSwitchSpec = do
  describe "rpSwitchB" $ do
    it "adds and removes members at the event instants, including time 0" $
      -- Kept members resume (localTime keeps counting: 0,1,2,...), new ones
      -- start at 0, every event applies (also on consecutive samples).
      runDt 1 (rpSwitchB []) rpInputs
        `shouldApproxLists` [[0], [1], [0, 2], [3, 3], [4], [60, 5], [70, 70, 6], [80, 80, 7]]

  describe "drpSwitchB" $ do
    it "shows each change from the sample after its event" $
      runDt 1 (drpSwitchB []) rpInputs
        `shouldApproxLists` [[], [1], [2], [3, 3], [7, 4], [5], [70, 6], [80, 80, 7]]

  describe "rpSwitch" $ do
    it "routes with a custom function (first input component only)" $ do
      let ins = [ ((1, 10), NoEvent), ((2, 20), Event (++ [integral]))
                , ((3, 30), NoEvent), ((4, 40), NoEvent) ]
      -- The new member (index 1) sees the second component: 0, 20, 50.
      runDt 1 (rpSwitch evenOdd [identity]) ins
        `shouldApproxLists` [[1], [2, 0], [3, 20], [4, 50]]

  describe "drpSwitch" $ do
    it "routes with a custom function; changes show from the next sample" $ do
      let ins = [ ((1, 10), NoEvent), ((2, 20), Event (++ [integral]))
                , ((3, 30), NoEvent), ((4, 40), NoEvent) ]
      runDt 1 (drpSwitch evenOdd [identity]) ins
        `shouldApproxLists` [[1], [2], [3, 20], [4, 50]]

  describe "rpSwitchZ" $ do
    it "zips the first input component with the current members" $
      -- t2: the frozen integral, now first, replays its step: 2 + 1*4 = 6.
      runDt 1 (rpSwitchZ [identity]) zpInputs `shouldApproxLists` [[1, 0], [3, 2], [6], [11]]

  describe "drpSwitchZ" $ do
    it "zips the first input component; changes show from the next sample" $
      runDt 1 (drpSwitchZ [identity]) zpInputs `shouldApproxLists` [[1], [3, 2], [5, 6], [11]]

------------------------------------------------------------------------------

type MapEdit = Map String (SF () Double) -> Map String (SF () Double)

mapInputs :: [((), Event MapEdit)]
mapInputs =
  [ ((), NoEvent)
  , ((), Event (Map.insert "b" (localTime >>> arr (+ 100))))
  , ((), NoEvent)
  , ((), Event (Map.delete "a"))
  , ((), Event (Map.insert "a" localTime))
  , ((), NoEvent)
  ]

mapSpec :: Spec
mapSpec = describe "collections other than lists (Data.Map)" $ do
  it "parB runs a map of signal functions" $
    runDt 0.5 (parB (Map.fromList [(1 :: Int, localTime), (2, integral)])) [2, 2, 2 :: Double]
      `shouldApproxMaps` map Map.fromList [[(1, 0), (2, 0)], [(1, 0.5), (2, 1)], [(1, 1), (2, 2)]]

  it "par routes a map of inputs by key" $
    runDt 0.5 (par byKey (Map.fromList [(1, integral), (2, arr (* 3))]))
              (map Map.fromList [[(1, 2), (2, 5)], [(1, 4)], [(2, 1), (1, 6)]])
      `shouldApproxMaps` map Map.fromList [[(1, 0), (2, 15)], [(1, 1), (2, 0)], [(1, 3), (2, 3)]]

  it "rpSwitchB inserts and deletes keyed members" $
    runDt 1 (rpSwitchB (Map.fromList [("a", localTime)])) mapInputs
      `shouldApproxMaps` map Map.fromList
        [ [("a", 0)], [("a", 1), ("b", 100)], [("a", 2), ("b", 101)], [("b", 102)]
        , [("a", 0), ("b", 103)], [("a", 1), ("b", 104)] ]

  it "drpSwitchB inserts and deletes keyed members from the next sample" $
    runDt 1 (drpSwitchB (Map.fromList [("a", localTime)])) mapInputs
      `shouldApproxMaps` map Map.fromList
        [ [("a", 0)], [("a", 1)], [("a", 2), ("b", 101)], [("a", 3), ("b", 102)]
        , [("b", 103)], [("a", 1), ("b", 104)] ]

  it "pSwitchB over a map: frozen members resume, new keys start at 0" $ do
    let sf = pSwitchB (Map.fromList [("x", integral)]) (when' (\(_, cs) -> sum cs >= 2))
               (\m () -> parB (Map.insert "y" localTime m))
    runDt 0.5 sf [2, 2, 2, 2 :: Double]
      `shouldApproxMaps` map Map.fromList
        [[("x", 0)], [("x", 1)], [("x", 2), ("y", 0)], [("x", 3), ("y", 0.5)]]

  it "dpSwitchB over a map: old output at the switching instant" $ do
    let sf = dpSwitchB (Map.fromList [("x", integral)]) (when' (\(_, cs) -> sum cs >= 2))
               (\m () -> parB (Map.insert "y" localTime m))
    runDt 0.5 sf [2, 2, 2, 2 :: Double]
      `shouldApproxMaps` map Map.fromList
        [[("x", 0)], [("x", 1)], [("x", 2)], [("x", 3), ("y", 0.5)]]

------------------------------------------------------------------------------

-- Two ramps (slopes 1 and 2). When an output reaches 1 (at t = 0.5, the
-- faster ramp) the collection becomes the frozen slow ramp plus a new
-- member localTime + 10, started at the switching instant.
ramps :: [SF a Double]
ramps = [localTime, localTime >>> arr (* 2)]

keepFirstAddNew :: [SF a Double] -> () -> SF a [Double]
keepFirstAddNew sfs () = parB (take 1 sfs ++ [localTime >>> arr (+ 10)])

-- The detector reads the collection's own output, fed back.
loopDetectorEdge :: SF () [Double]
loopDetectorEdge = proc () -> do
  rec cs <- dpSwitchB ramps (when' (\((_, fb), _) -> any (>= 1) fb)) keepFirstAddNew -< ((), cs)
  returnA -< cs

-- The same with a detector that is a plain function of the fed-back output.
loopDetectorArr :: SF () [Double]
loopDetectorArr = proc () -> do
  rec cs <- dpSwitchB ramps
              (arr (\((_, fb), _) -> if any (>= 1) fb then Event () else NoEvent))
              keepFirstAddNew -< ((), cs)
  returnA -< cs

-- The event is computed outside from the output and fed back.
loopEventFedBack :: SF () [Double]
loopEventFedBack = proc () -> do
  rec cs <- dpSwitchB ramps (arr (\((_, ev), _) -> ev)) keepFirstAddNew -< ((), e)
      e <- edge -< any (>= 1) cs
  returnA -< cs

loopExpected :: [[Double]]
loopExpected = [[0, 0], [0.25, 0.5], [0.5, 1.0], [0.75, 10.25], [1.0, 10.5]]

loopSpec :: Spec
loopSpec = describe "dpSwitchB in a feedback loop" $ do
  it "the event is computed outside from the output and fed back" $
    runDt 0.25 loopEventFedBack (replicate 5 ()) `shouldTerminateWithLists` loopExpected

  it "the detector (a plain function) reads the fed-back output" $
    runDt 0.25 loopDetectorArr (replicate 5 ()) `shouldTerminateWithLists` loopExpected

  it "the detector (an edge) reads the fed-back output" $
    runDt 0.25 loopDetectorEdge (replicate 5 ()) `shouldTerminateWithLists` loopExpected

------------------------------------------------------------------------------
-- The cases the docs state for the collection switches: an event at time
-- 0, the switching instant, members' local times (each checked against
-- Yampa 0.15, which gives the same outputs). Samples every 0.5 s.

documentedSpec :: Spec
documentedSpec = describe "as documented: collection switches at time 0 and after a switch" $ do
  let units = replicate 5 ()
      lt100 = localTime >>> arr (+ 100)
      addLt100 sfs () = parB (sfs ++ [lt100])
  it "pSwitchB at time 0: the output there is the new collection's; dpSwitchB: the old one's" $ do
    runDt 0.5 (pSwitchB [localTime] (now ()) addLt100) units
      `shouldBe` [[0, 100], [0.5, 100.5], [1, 101], [1.5, 101.5], [2, 102]]
    runDt 0.5 (dpSwitchB [localTime] (now ()) addLt100) units
      `shouldBe` [[0], [0.5, 100.5], [1, 101], [1.5, 101.5], [2, 102]]
  it "a carried member keeps its local time, a new one starts at 0 at the switching instant" $ do
    runDt 0.5 (pSwitchB [localTime] (after 1 ()) addLt100) units
      `shouldBe` [[0], [0.5], [1, 100], [1.5, 100.5], [2, 101]]
    runDt 0.5 (dpSwitchB [localTime] (after 1 ()) addLt100) units
      `shouldBe` [[0], [0.5], [1], [1.5, 100.5], [2, 101]]
  it "a new signal function that switches at its own first sample does so at the same instant" $
    runDt 0.5 (pSwitchB [localTime] (after 1 ())
                 (\sfs () -> pSwitchB (sfs ++ [constant 50]) (now ()) addLt100)) units
      `shouldBe` [[0], [0.5], [1, 50, 100], [1.5, 50, 100.5], [2, 50, 101]]
  it "rpSwitchB at time 0 changes the collection before its first output; drpSwitchB after it" $ do
    let events = [ ((), e) | e <- Event (++ [lt100]) : replicate 4 NoEvent ]
    runDt 0.5 (rpSwitchB [localTime]) events
      `shouldBe` [[0, 100], [0.5, 100.5], [1, 101], [1.5, 101.5], [2, 102]]
    runDt 0.5 (drpSwitchB [localTime]) events
      `shouldBe` [[0], [0.5, 100.5], [1, 101], [1.5, 101.5], [2, 102]]
