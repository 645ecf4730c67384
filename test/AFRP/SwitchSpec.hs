{-# LANGUAGE Arrows #-}
-- | Tests for "AFRP.Switch": the immediate, delayed, recurring and
-- continuation switches. Every expected output below was computed by hand
-- from the functions' documentation.
module AFRP.SwitchSpec (spec) where

import           Control.Arrow     (arr, first, returnA, (&&&), (>>>))
import           Control.Exception (evaluate)
import           System.Timeout    (timeout)
import           Test.Hspec        hiding (after)
import           Test.QuickCheck

import           AFRP.Basic        (constant, identity, localTime)
import           AFRP.Event        (Event (..), tag)
import           AFRP.EventSource  (after, edge, edgeTag, never, now, repeatedly)
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (DTime, SF)
import           AFRP.Switch
import           TestUtil

-- | Fully evaluate a list of numbers; 'Nothing' when it diverges (no
-- result within 30 s: a guard against a hang, generous for a loaded
-- machine). A @<<loop>>@ also counts as a failure, through the exception
-- it raises.
forceWithin :: [Double] -> IO (Maybe [Double])
forceWithin xs = timeout 30000000 (evaluate (sum xs) >> pure xs)

-- | The outputs must be computed (no divergence) and equal the expected
-- list.
shouldTerminateWith :: [Double] -> [Double] -> Expectation
shouldTerminateWith xs expected = do
  r <- forceWithin xs
  case r of
    Nothing  -> expectationFailure "diverged (no result within 30 s)"
    Just ys  -> ys `shouldApproxList` expected

-- | A switching event when a number reaches a threshold (rising edge).
reaches :: Double -> SF Double (Event ())
reaches x = arr (>= x) >>> edge

-- | Samples with irregular time steps; the first step is ignored.
irregular :: [(DTime, Double)]
irregular =
  [ (0, 1), (0.3, 2), (0.7, -1), (0.2, 4), (1.1, 0.5), (0.05, 3)
  , (0.45, -2), (0.9, 1), (0.15, 2.5), (0.6, 0) ]

spec :: Spec
spec = do
  switchSpec
  dSwitchSpec
  rSwitchSpec
  kSwitchSpec
  decouplingSpec
  propertiesSpec
  documentedSpec

------------------------------------------------------------------------------

switchSpec :: Spec
switchSpec = describe "switch" $ do
  it "outputs the new signal function's first output at the event instant" $
    -- after 1 fires at t = 1.0 (the third sample); the new SF outputs 50 + x.
    runDt 0.5 (switch (arr (* 2) &&& after 1 50) (\c -> arr (+ c))) [1, 2, 3, 4, 5 :: Double]
      `shouldApproxList` [2, 4, 53, 54, 55]

  it "restarts local time at 0 in the switched-in signal function" $
    runDt 0.5 (switch (localTime &&& after 1 ()) (\() -> localTime)) (replicate 6 ())
      `shouldApproxList` [0, 0.5, 0, 0.5, 1.0, 1.5]

  it "restarts local time with irregular time steps" $
    -- Times 0, 0.3, 1.0, 1.2, 2.3: after 0.9 fires at t = 1.0.
    runSamples (switch (localTime &&& after 0.9 ()) (\() -> localTime >>> arr (+ 100)))
               [(0, ()), (0.3, ()), (0.7, ()), (0.2, ()), (1.1, ())]
      `shouldApproxList` [0, 0.3, 100, 100.2, 101.3]

  it "restarts an integral at the switching instant" $
    -- integral of x_k = k+1 with dt 1: 0, 1, 3 | restart at sample 2: 0, 3, 7
    runDt 1 (switch (integral &&& after 2 ()) (\() -> integral)) [1, 2, 3, 4, 5 :: Double]
      `shouldApproxList` [0, 1, 0, 3, 7]

  it "switches at time 0 on an event at time 0" $
    runDt 0.5 (switch ((localTime >>> arr (+ 100)) &&& now 7) (\c -> localTime >>> arr (+ c)))
              (replicate 3 ())
      `shouldApproxList` [7, 7.5, 8]

  it "sees the event-instant input in the new signal function" $
    -- The event is raised by the input reaching 3; the new SF is the identity
    -- plus 1000, and sees that input (3) at once.
    runDt 1 (switch (identity &&& reaches 3) (\() -> arr (+ 1000))) [1, 2, 3, 1, 5 :: Double]
      `shouldApproxList` [1, 2, 1003, 1001, 1005]

  it "switches only once (later events of the old source are ignored)" $
    runDt 1 (switch (constant 0 &&& repeatedly 1 ()) (\() -> localTime)) (replicate 5 ())
      `shouldApproxList` [0, 0, 1, 2, 3]

  it "cascades immediate switches within one instant" $ do
    let chain = switch (constant (-1) &&& after 1 (1 :: Double)) $ \c ->
                switch (constant (-2) &&& now (c + 1)) $ \c' ->
                switch (constant (-3) &&& now (c' * 10)) $ \c'' ->
                localTime >>> arr (+ c'')
    runDt 0.5 chain (replicate 5 ()) `shouldApproxList` [-1, -1, 20, 20.5, 21]

  it "cascades immediate switches at time 0" $ do
    let chain = switch (constant (-1) &&& now (1 :: Double)) $ \c ->
                switch (constant (-2) &&& now (c + 1)) $ \c' ->
                localTime >>> arr (+ c')
    runDt 0.5 chain (replicate 3 ()) `shouldApproxList` [2, 2.5, 3]

  it "can switch again inside the switched-in signal function" $ do
    let sf = switch (localTime &&& after 1 ()) $ \() ->
             switch ((localTime >>> arr (+ 10)) &&& after 0.5 ()) $ \() ->
             localTime >>> arr (+ 20)
    runDt 0.5 sf (replicate 6 ()) `shouldApproxList` [0, 0.5, 10, 20, 20.5, 21]

------------------------------------------------------------------------------

dSwitchSpec :: Spec
dSwitchSpec = describe "dSwitch" $ do
  it "outputs the old output at the event instant, the new one after" $
    runDt 0.5 (dSwitch (arr (* 2) &&& after 1 50) (\c -> arr (+ c))) [1, 2, 3, 4, 5 :: Double]
      `shouldApproxList` [2, 4, 6, 54, 55]

  it "starts the new signal function at the event instant (local time dt at the next sample)" $
    runDt 0.5 (dSwitch (localTime &&& after 1 ()) (\() -> localTime >>> arr (+ 10)))
              (replicate 5 ())
      `shouldApproxList` [0, 0.5, 1.0, 10.5, 11.0]

  it "starts the new signal function at the event instant, irregular steps" $
    -- Times 0, 0.3, 1.0, 1.2, 2.3; event at 1.0; new local times 0.2, 1.3.
    runSamples (dSwitch (localTime &&& after 0.9 ()) (\() -> localTime >>> arr (+ 100)))
               [(0, ()), (0.3, ()), (0.7, ()), (0.2, ()), (1.1, ())]
      `shouldApproxList` [0, 0.3, 1.0, 100.2, 101.3]

  it "gives the new signal function the event-instant input as its first sample" $
    -- The new integral starts on the input of the event instant (3):
    -- at the next sample it outputs 1 * 3.
    runDt 1 (dSwitch (identity &&& reaches 3) (\() -> integral)) [1, 2, 3, 10, 20 :: Double]
      `shouldApproxList` [1, 2, 3, 3, 13]

  it "on an event at time 0 outputs the old output at time 0 and starts the new SF there" $
    runDt 0.5 (dSwitch ((localTime >>> arr (+ 100)) &&& now 7) (\c -> localTime >>> arr (+ c)))
              (replicate 3 ())
      `shouldApproxList` [100, 7.5, 8]

  it "runs immediate cascades in the new SF at the event instant" $ do
    let sf = dSwitch (localTime &&& after 1 (3 :: Double)) $ \c ->
             switch (constant 99 &&& now (c * 2)) $ \c' ->
             localTime >>> arr (+ c')
    runDt 0.5 sf (replicate 5 ()) `shouldApproxList` [0, 0.5, 1.0, 6.5, 7.0]

------------------------------------------------------------------------------

-- Inputs for the recurring switches: the number, and possibly a new SF.
rInputs :: [(Double, Event (SF Double Double))]
rInputs =
  [ (1, Event (arr (* 10)))   -- t0: event at time 0
  , (2, NoEvent)
  , (3, Event integral)
  , (4, NoEvent)
  , (5, Event integral)       -- same event on consecutive samples
  , (6, Event integral)
  , (7, NoEvent)
  , (8, NoEvent)
  ]

rSwitchSpec :: Spec
rSwitchSpec = do
  describe "rSwitch" $ do
    it "switches at every event, at the event instant, including time 0" $
      -- t0: *10 -> 10; t1: 20; t2: fresh integral 0; t3: 3;
      -- t4: restart 0; t5: restart 0; t6: 6; t7: 6 + 7.
      runDt 1 (rSwitch (arr (+ 100))) rInputs
        `shouldApproxList` [10, 20, 0, 3, 0, 0, 6, 13]

    it "restarts local time at each event" $ do
      let ins = [ ((), NoEvent), ((), NoEvent), ((), Event localTime), ((), NoEvent)
                , ((), Event localTime), ((), NoEvent), ((), NoEvent) ]
      runDt 0.5 (rSwitch localTime) ins `shouldApproxList` [0, 0.5, 0, 0.5, 0, 0.5, 1.0]

    it "behaves as the initial SF while there is no event" $
      runDt 0.5 (rSwitch integral) [(x, NoEvent) | x <- [2, 4, 6, 8 :: Double]]
        `shouldApproxList` [0, 1, 3, 6]

  describe "drSwitch" $ do
    it "outputs the old SF at each event instant and the new one from the next sample" $
      -- t0: 101 (old), *10 started; t1: 20; t2: 30, integral started on 3;
      -- t3: 3; t4: 3 + 4 = 7, new integral on 5; t5: 5, new integral on 6;
      -- t6: 6; t7: 13.
      runDt 1 (drSwitch (arr (+ 100))) rInputs
        `shouldApproxList` [101, 20, 30, 3, 7, 5, 6, 13]

    it "starts the new SF at the event instant (local time dt at the next sample)" $ do
      let ins = [ ((), NoEvent), ((), NoEvent), ((), Event localTime), ((), NoEvent)
                , ((), Event localTime), ((), NoEvent), ((), NoEvent) ]
      runDt 0.5 (drSwitch localTime) ins `shouldApproxList` [0, 0.5, 1.0, 0.5, 1.0, 0.5, 1.0]

------------------------------------------------------------------------------

kSwitchSpec :: Spec
kSwitchSpec = do
  describe "kSwitch" $ do
    it "outputs the new SF's first output at the switching instant" $
      runDt 0.5 (kSwitch localTime (arr snd >>> reaches 1) (\_ () -> constant 42)) (replicate 4 ())
        `shouldApproxList` [0, 0.5, 42, 42]

    it "lets the detector see the input and the current output" $
      -- Detector: input + output >= 10. Input 1,2,3,...; output = integral
      -- (dt 1): 0, 1, 3, 6, 10. Sums: 1, 3, 6, 10 -> event at sample 3.
      runDt 1 (kSwitch integral (arr (uncurry (+)) >>> reaches 10) (\_ () -> arr negate))
              [1, 2, 3, 4, 5 :: Double]
        `shouldApproxList` [0, 1, 3, -4, -5]

    it "with k = \\s _ -> s is exactly sf (integral, irregular steps)" $ do
      let sf = integral :: SF Double Double
          ks = kSwitch sf (arr snd >>> reaches 1) (\s () -> s)
      -- integral: 0, 0.3, 1.7, 1.5, 5.9, 5.925, 7.275, 5.475, 5.625, 7.125
      runSamples ks irregular `shouldApproxList`
        [0, 0.3, 1.7, 1.5, 5.9, 5.925, 7.275, 5.475, 5.625, 7.125]
      runSamples ks irregular `shouldApproxList` runSamples sf irregular

    it "with k = \\s _ -> s is exactly sf (localTime, irregular steps)" $ do
      let ks = kSwitch localTime (arr snd >>> reaches 1) (\s () -> s)
      runSamples ks irregular `shouldApproxList`
        [0, 0.3, 1.0, 1.2, 2.3, 2.35, 2.8, 3.7, 3.85, 4.45]

    it "passes the frozen SF, which the continuation may transform" $ do
      -- localTime switched at t = 1.0 into (frozen localTime) * 100.
      let ks = kSwitch localTime (arr snd >>> reaches 1) (\s () -> s >>> arr (* 100))
      runDt 0.5 ks (replicate 5 ()) `shouldApproxList` [0, 0.5, 100, 150, 200]

    it "a frozen SF started later resumes where it stopped (the pause is lost to it)" $ do
      -- Event at t = 1.0; the continuation shows -1 for 1 second, then
      -- starts the frozen localTime, which replays its step 0.5 -> 1.0.
      let ks = kSwitch localTime (arr snd >>> reaches 1)
                 (\s () -> switch (constant (-1) &&& after 1 ()) (\() -> s))
      runDt 0.5 ks (replicate 7 ()) `shouldApproxList` [0, 0.5, -1, -1, 1.0, 1.5, 2.0]

    it "a frozen SF started later replays the captured step, not the current one" $ do
      -- Times 0, 0.5, 1.0, 1.25, 2.0, 2.25, 2.55. Event at 1.0 (frozen:
      -- clock 0.5, pending step 0.5). The continuation starts it at 2.0,
      -- where the time step is 0.75: it still replays 0.5 -> 1.0.
      let ks = kSwitch localTime (arr snd >>> reaches 1)
                 (\s () -> switch (constant (-1) &&& after 1 ()) (\() -> s))
      runSamples ks [(0, ()), (0.5, ()), (0.5, ()), (0.25, ()), (0.75, ()), (0.25, ()), (0.3, ())]
        `shouldApproxList` [0, 0.5, -1, -1, 1.0, 1.25, 1.55]

    it "an event at time 0 passes the original, unstarted SF" $ do
      let ks = kSwitch localTime (now ())
                 (\s () -> switch (constant (-1) &&& after 1 ()) (\() -> s))
      runDt 0.5 ks (replicate 5 ()) `shouldApproxList` [-1, -1, 0, 0.5, 1.0]

    it "an event at time 0 with k = \\s _ -> s is sf" $
      runSamples (kSwitch integral (now ()) (\s () -> s)) irregular
        `shouldApproxList` runSamples integral irregular

    it "passes the event value to the continuation" $
      runDt 1 (kSwitch identity (arr fst >>> arr (>= 3) >>> edgeTag 1000)
                       (\s c -> s >>> arr (+ c)))
              [1, 2, 3, 4 :: Double]
        `shouldApproxList` [1, 2, 1003, 1004]

  describe "dkSwitch" $ do
    it "outputs the old output at the switching instant, the new SF after" $
      runDt 0.5 (dkSwitch localTime (arr snd >>> reaches 1) (\_ () -> constant 42)) (replicate 4 ())
        `shouldApproxList` [0, 0.5, 1.0, 42]

    it "with k = \\s _ -> s is exactly sf (integral, irregular steps)" $
      runSamples (dkSwitch integral (arr snd >>> reaches 1) (\s () -> s)) irregular
        `shouldApproxList` [0, 0.3, 1.7, 1.5, 5.9, 5.925, 7.275, 5.475, 5.625, 7.125]

    it "with k = \\s _ -> s is exactly sf (localTime, irregular steps)" $
      runSamples (dkSwitch localTime (arr snd >>> reaches 1) (\s () -> s)) irregular
        `shouldApproxList` [0, 0.3, 1.0, 1.2, 2.3, 2.35, 2.8, 3.7, 3.85, 4.45]

    it "starts the continuation at the switching instant with the frozen SF" $ do
      -- Event at 1.0 (old output 1.0); the continuation (frozen localTime
      -- * 100) is started there, so at 1.5 it shows 150.
      let ks = dkSwitch localTime (arr snd >>> reaches 1) (\s () -> s >>> arr (* 100))
      runDt 0.5 ks (replicate 5 ()) `shouldApproxList` [0, 0.5, 1.0, 150, 200]

    it "a frozen SF started later resumes where it stopped" $ do
      -- Event at 1.0; the continuation starts there: -1 at 1.5, and at 2.0
      -- (its local time 1.0) it starts the frozen localTime: 0.5 -> 1.0.
      let ks = dkSwitch localTime (arr snd >>> reaches 1)
                 (\s () -> switch (constant (-1) &&& after 1 ()) (\() -> s))
      runDt 0.5 ks (replicate 6 ()) `shouldApproxList` [0, 0.5, 1.0, -1, 1.0, 1.5]

    it "a frozen SF started later replays the captured step (irregular steps)" $ do
      -- Times 0, 0.5, 1.0, 1.25, 2.0, 2.25. Event at 1.0; the continuation
      -- starts at 1.0 and starts the frozen localTime at its local time 1.0
      -- (t = 2.0, time step 0.75): it replays 0.5 -> 1.0.
      let ks = dkSwitch localTime (arr snd >>> reaches 1)
                 (\s () -> switch (constant (-1) &&& after 1 ()) (\() -> s))
      runSamples ks [(0, ()), (0.5, ()), (0.5, ()), (0.25, ()), (0.75, ()), (0.25, ())]
        `shouldApproxList` [0, 0.5, 1.0, -1, 1.0, 1.25]

    it "an event at time 0 outputs the old output and passes the unstarted SF" $ do
      let ks = dkSwitch localTime (now ())
                 (\s () -> switch (constant (-1) &&& after 1 ()) (\() -> s))
      -- t0: old output 0; the continuation starts at t0: -1 at 0.5,
      -- at 1.0 it starts the unstarted localTime: 0, then 0.5.
      runDt 0.5 ks (replicate 5 ()) `shouldApproxList` [0, -1, 0, 0.5, 1.0]

------------------------------------------------------------------------------

-- dSwitch whose event is the rising edge of its own output exceeding 1.
dSwitchLoop :: SF () Double
dSwitchLoop = proc () -> do
  rec v <- dSwitch (first localTime) (\() -> localTime >>> arr (+ 10)) -< ((), e)
      e <- edge -< v > 1
  returnA -< v

-- The same with the switch on a fan (sf &&& e, the shape whose evaluated
-- NoEvent is decided at once), its event side reading the fed-back event
-- through a pure function ...
dSwitchFanLoop :: SF () Double
dSwitchFanLoop = proc () -> do
  rec v <- dSwitch ((arr fst >>> localTime) &&& arr snd) (\() -> localTime >>> arr (+ 10)) -< ((), e)
      e <- edge -< v > 1
  returnA -< v

-- ... and through a stateful one.
dSwitchFanLoopStateful :: SF () Double
dSwitchFanLoopStateful = proc () -> do
  rec v <- dSwitch ((arr fst >>> localTime) &&& (first localTime >>> arr snd))
                   (\() -> localTime >>> arr (+ 10)) -< ((), e)
      e <- edge -< v > 1
  returnA -< v

-- drSwitch restarting localTime whenever its own output reaches 1.
drSwitchLoop :: SF () Double
drSwitchLoop = proc () -> do
  rec v <- drSwitch localTime -< ((), e `tag` localTime)
      e <- edge -< v >= 1
  returnA -< v

-- drSwitch whose new SF is built from its own output at the event instant.
drSwitchLoopValue :: SF () Double
drSwitchLoopValue = proc () -> do
  rec v <- drSwitch localTime -< ((), e `tag` (localTime >>> arr (+ 10 * v)))
      e <- edge -< v >= 1
  returnA -< v

-- dkSwitch whose event comes, through the loop, from its own output.
dkSwitchLoop :: SF () Double
dkSwitchLoop = proc () -> do
  rec v <- dkSwitch localTime (arr (snd . fst)) (\s () -> s >>> arr (* 100)) -< ((), e)
      e <- edge -< v >= 1
  returnA -< v

-- dkSwitch whose detector itself reads the fed-back output.
dkSwitchLoopDetector :: SF () Double
dkSwitchLoopDetector = proc () -> do
  rec v <- dkSwitch localTime (arr (\((_, vfb), _) -> vfb >= 1) >>> edge)
                    (\s () -> s >>> arr (* 100)) -< ((), v)
  returnA -< v

-- The notes' @vel@, with the velocity-increment events as the input.
vel :: Double -> SF (Event ()) Double
vel v0 = proc inp -> do
  rec v <- drSwitch (constant v0) -< (inp, inp `tag` constant (v + 1))
  returnA -< v

decouplingSpec :: Spec
decouplingSpec = describe "decoupling of the delayed switches (rec / loop)" $ do
  it "dSwitch: the event may depend on the switch's own output" $
    -- v: 0, 0.5, 1.0, 1.5 (edge of v > 1 here; old output), then the new
    -- localTime + 10 started at 1.5: 10.5, 11.0.
    runDt 0.5 dSwitchLoop (replicate 6 ()) `shouldTerminateWith` [0, 0.5, 1.0, 1.5, 10.5, 11.0]

  it "dSwitch on a fan: the event may depend on the switch's own output" $ do
    runDt 0.5 dSwitchFanLoop (replicate 6 ()) `shouldTerminateWith` [0, 0.5, 1.0, 1.5, 10.5, 11.0]
    runDt 0.5 dSwitchFanLoopStateful (replicate 6 ()) `shouldTerminateWith` [0, 0.5, 1.0, 1.5, 10.5, 11.0]

  it "drSwitch: the event may depend on the switch's own output" $
    runDt 0.5 drSwitchLoop (replicate 7 ()) `shouldTerminateWith` [0, 0.5, 1.0, 0.5, 1.0, 0.5, 1.0]

  it "drSwitch: the new SF may be built from the switch's own output" $
    -- Event at 1.0 where v = 1.0; new SF localTime + 10: 10.5, 11.0.
    runDt 0.5 drSwitchLoopValue (replicate 5 ()) `shouldTerminateWith` [0, 0.5, 1.0, 10.5, 11.0]

  it "dkSwitch: the event may depend on the switch's own output" $
    runDt 0.5 dkSwitchLoop (replicate 5 ()) `shouldTerminateWith` [0, 0.5, 1.0, 150, 200]

  it "dkSwitch: the detector may read the fed-back output" $
    runDt 0.5 dkSwitchLoopDetector (replicate 5 ()) `shouldTerminateWith` [0, 0.5, 1.0, 150, 200]

  it "the notes' vel: each event adds 1 from the next sample on" $ do
    let evs = [NoEvent, NoEvent, Event (), NoEvent, Event (), Event (), NoEvent, NoEvent]
    runDt 0.1 (vel 0) evs `shouldTerminateWith` [0, 0, 0, 1, 1, 2, 3, 3]

  it "the notes' vel: an event at time 0 counts from the next sample" $ do
    let evs = [Event (), NoEvent, Event (), NoEvent]
    runDt 0.1 (vel 5) evs `shouldTerminateWith` [5, 6, 6, 7]

------------------------------------------------------------------------------

-- Random inputs: a number and a flag; the event is the first raised flag.
genFlagged :: Gen [(DTime, (Double, Bool))]
genFlagged = genSamples ((,) <$> choose (-5, 5) <*> frequency [(1, pure True), (4, pure False)])

flagEvent :: SF (Double, Bool) (Event Double)
flagEvent = arr (\(x, b) -> if b then Event x else NoEvent)

-- A stateful old SF and a stateful family of new ones.
oldSF :: SF (Double, Bool) Double
oldSF = arr fst >>> (integral &&& localTime) >>> arr (\(i, t) -> i + 100 * t)

newSF :: Double -> SF (Double, Bool) Double
newSF c = arr fst >>> (integral &&& localTime) >>> arr (\(i, t) -> c + i - 10 * t)

approxLists :: [Double] -> [Double] -> Bool
approxLists xs ys = length xs == length ys && and (zipWith approx xs ys)

propertiesSpec :: Spec
propertiesSpec = describe "properties" $ do
  it "switch (sf &&& never) k equals sf" $
    property $ forAll (genSamples (choose (-5, 5))) $ \ss ->
      let sf = (integral &&& localTime) >>> arr (uncurry (+)) :: SF Double Double
      in approxLists (runSamples (switch (sf &&& never) (\() -> constant 0)) ss)
                     (runSamples sf ss)

  it "dSwitch equals switch except at the event instant, where it shows the old output" $
    property $ forAll genFlagged $ \ss ->
      let sw  = runSamples (switch (oldSF &&& flagEvent) newSF) ss
          dsw = runSamples (dSwitch (oldSF &&& flagEvent) newSF) ss
          old = runSamples oldSF ss
          evIx = lookup True (zip (map (snd . snd) ss) [0 :: Int ..])
          expected = case evIx of
            Nothing -> sw
            Just j  -> [if i == j then o else s | (i, s, o) <- zip3 [0 ..] sw old]
      in counterexample (show (evIx, sw, dsw)) (approxLists dsw expected)

  it "switch before the event equals the old SF, and from it the new SF started there" $
    property $ forAll genFlagged $ \ss ->
      let sw  = runSamples (switch (oldSF &&& flagEvent) newSF) ss
          old = runSamples oldSF ss
      in case lookup True (zip (map (snd . snd) ss) [0 :: Int ..]) of
           Nothing -> approxLists sw old
           Just j  ->
             let c = fst (snd (ss !! j))
                 fresh = runSamples (newSF c) (drop j ss)
             in approxLists (take j sw) (take j old) && approxLists (drop j sw) fresh

  it "kSwitch sf sfe (\\s _ -> s) equals sf for any steps and any switching instant" $
    property $ forAll genFlagged $ \ss ->
      let sfe = arr (\((x, b), _) -> if b then Event x else NoEvent)
      in approxLists (runSamples (kSwitch oldSF sfe (\s _ -> s)) ss) (runSamples oldSF ss)

  it "dkSwitch sf sfe (\\s _ -> s) equals sf for any steps and any switching instant" $
    property $ forAll genFlagged $ \ss ->
      let sfe = arr (\((x, b), _) -> if b then Event x else NoEvent)
      in approxLists (runSamples (dkSwitch oldSF sfe (\s _ -> s)) ss) (runSamples oldSF ss)

------------------------------------------------------------------------------
-- The cases the module's docs state: an event at time 0, the instant of a
-- switch, and the local time after it (each checked against Yampa 0.15,
-- which gives the same outputs). Samples every 0.5 s.

-- | @localTime@ plus a constant.
ltPlus :: Double -> SF a Double
ltPlus k = localTime >>> arr (+ k)

documentedSpec :: Spec
documentedSpec = describe "as documented: time 0, the switching instant, and the local time after it" $ do
  let units = replicate 5 ()
  it "drSwitch at time 0 keeps sf's output there; each of two switches at consecutive samples gives one output" $ do
    runDt 0.5 (drSwitch localTime) [((), e) | e <- Event (ltPlus 100) : replicate 4 NoEvent]
      `shouldBe` [0, 100.5, 101, 101.5, 102]
    runDt 0.5 (drSwitch localTime) [((), e) | e <- [Event (ltPlus 100), Event (ltPlus 200), NoEvent, NoEvent, NoEvent]]
      `shouldBe` [0, 100.5, 200.5, 201, 201.5]
  it "kSwitch and dkSwitch: the frozen sf goes on from its own local time, what k builds starts at 0" $ do
    let k s () = (s &&& localTime) >>> arr (\(a, b) -> a * 1000 + b)
    runDt 0.5 (kSwitch localTime (after 1 ()) k) units `shouldBe` [0, 0.5, 1000, 1500.5, 2001]
    runDt 0.5 (dkSwitch localTime (after 1 ()) k) units `shouldBe` [0, 0.5, 1, 1500.5, 2001]
  it "dkSwitch at time 0 passes the unstarted sf, and the output at time 0 is sf's" $
    runDt 0.5 (dkSwitch localTime (now ()) (\s () -> s)) units `shouldBe` [0, 0.5, 1, 1.5, 2]
  it "a frozen sf started again later does not count the time it was switched out" $
    runDt 0.5 (kSwitch localTime (after 1 ()) (\s () -> switch (constant (-1) &&& after 1 ()) (\() -> s)))
               (replicate 7 ())
      `shouldBe` [0, 0.5, -1, -1, 1, 1.5, 2]
  it "a delayed switch into one that switches at its own first sample switches again at that instant" $
    runDt 0.5 (dkSwitch (constant 0) (after 1 ()) (\_ () -> dkSwitch (constant 1) (now ()) (\_ () -> ltPlus 100))) units
      `shouldBe` [0, 0, 0, 100.5, 101]
