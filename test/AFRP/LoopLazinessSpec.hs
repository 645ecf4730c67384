{-# LANGUAGE Arrows #-}
-- | Laziness of every stateful combinator inside 'loop' (issue 14, part 1).
--
-- Two cases per combinator, each built from @sf :: SF (Double, Double)
-- Double@: the combinator, fed from a pair (the loop's input @a@, a value
-- @c@ fed back through the loop), with its output made a 'Double'.
--
-- * /discarded/: @c@ is computed from the current input (@c = a@), and the
--   combinator's output is thrown away. The network has no real cycle, so
--   the loop must output its input at every sample; a combinator that
--   evaluates its input before its output is demanded makes it diverge
--   (@<<loop>>@).
-- * /through iPre/: the combinator's output is fed back, one sample late,
--   as @c@. The loop must agree with the same feedback done by hand,
--   stepping the combinator with its previous output.
--
-- Every case runs under a time limit and fails on @<<loop>>@ rather than
-- hanging the suite.
module AFRP.LoopLazinessSpec (spec) where

import           Test.Hspec        hiding (after)

import           AFRP
import           AFRP.Internal.SF  (stepSF)
import           TestUtil          (runDt, withoutHanging)

spec :: Spec
spec = do
  describe "a stateful combinator whose fed-back input is discarded" $
    mapM_ (\(name, sf) -> it name (discarded sf)) (cases ++ inputDiscardedOnly)
  describe "a stateful combinator whose output is fed back through iPre" $
    mapM_ (\(name, sf) -> it name (throughPre sf)) cases
  describe "recursive arrow notation" $ do
    it "a mode flag fed back into an edge detector" $
      withoutHanging (take 8 (runDt 0.1 modeFlag inputs)) (take 8 inputs)
    it "a state machine whose switch event comes from its own fed-back output" $
      withoutHanging (take 7 (runDt 0.1 selfSwitching inputs)) [0, 1, 2, 3, -10, -10, -10]

-- The input samples (dt = 0.1): signs change, so edges, holds and switches
-- all see events.
inputs :: [Double]
inputs = [1, -1, 2, 0, 3, -2, 5, 1, -4, 2, 6, 0]

dt :: DTime
dt = 0.1

-- The loop outputs its input: the combinator's output is discarded.
discarded :: SF (Double, Double) Double -> Expectation
discarded sf =
  withoutHanging (runDt dt (loop (second (arr (\c -> (c, c)) >>> sf) >>> arr (\(a, _) -> (a, a)))) inputs)
         inputs

-- The combinator's output fed back through iPre 0, against the same
-- feedback done by hand.
throughPre :: SF (Double, Double) Double -> Expectation
throughPre sf =
  withoutHanging (runDt dt (loop (sf >>> arr (\y -> (y, y)) >>> second (iPre 0))) inputs)
         (byHand sf 0 inputs)

byHand :: SF (Double, Double) Double -> Double -> [Double] -> [Double]
byHand _  _    []       = []
byHand sf prev (a : as) = case stepSF sf dt (a, prev) of (sf', y) -> y : byHand sf' y as

------------------------------------------------------------------------------
-- The combinators, fed from (a, c)

fed :: (Double -> x) -> SF x y -> (y -> Double) -> SF (Double, Double) Double
fed inp sf out = arr (\(_, c) -> inp c) >>> sf >>> arr out
{-# NOINLINE fed #-}

-- An edge that no rewrite rule can fuse with the function before it.
plainEdge :: SF Bool (Event ())
plainEdge = edge
{-# NOINLINE plainEdge #-}

pos :: Double -> Event Double
pos c = if c > 0 then Event c else NoEvent

big :: Double -> Event Double
big c = if c > 2 then Event c else NoEvent

ev :: Event Double -> Double
ev = event 0 id

evU :: Event () -> Double
evU = event 0 (const 1)

evL :: Event [Double] -> Double
evL = event 0 sum

cases :: [(String, SF (Double, Double) Double)]
cases =
  -- sources (they never look at their input)
  [ ("now",              fed id (now 1) evU')
  , ("after",            fed id (after 0.3 ()) evU)
  , ("repeatedly",       fed id (repeatedly 0.2 ()) evU)
  , ("afterEach",        fed id (afterEach [(0.2, 1), (0.3, 2)]) ev)
  , ("afterEachCat",     fed id (afterEachCat [(0.2, 1), (0, 2)]) evL)
  , ("localTime",        fed id localTime id)
  , ("time",             fed id time id)
  , ("noiseWith",        fed id (noiseWith (\g -> (g, g + 1)) (0 :: Double)) id)
  , ("occasionallyWith", fed id (occasionallyWith (\g -> (0.5, g)) (0 :: Int) 0.1 ()) evU)
  -- event delays
  , ("delayEvent",       fed pos (delayEvent 0.2) ev)
  , ("delayEventCat",    fed pos (delayEventCat 0.2) evL)
  -- edges
  , ("edge",             fed (> 0) plainEdge evU)
  , ("arr p >>> edge",   arr (\(_, c) -> c) >>> (arr (> 0) >>> edge) >>> arr evU)
  , ("iEdge",            fed (> 0) (iEdge False) evU)
  , ("edgeTag",          fed (> 0) (edgeTag 7) ev)
  , ("edgeJust",         fed (\c -> if c > 0 then Just c else Nothing) edgeJust ev)
  , ("edgeBy",           fed id (edgeBy (\x y -> if y > x then Just y else Nothing) 0) ev)
  -- reshaping event streams
  , ("notYet",           fed pos notYet ev)
  , ("once",             fed pos once ev)
  , ("takeEvents",       fed pos (takeEvents 2) ev)
  , ("dropEvents",       fed pos (dropEvents 1) ev)
  -- sampling
  , ("snap",             fed id snap ev)
  , ("snapAfter",        fed id (snapAfter 0.2) ev)
  , ("sample",           fed id (sample 0.2) ev)
  , ("sampleWindow",     fed id (sampleWindow 2 0.2) evL)
  -- holds and accumulators
  , ("hold",             fed pos (hold 0) id)
  , ("dHold",            fed pos (dHold 0) id)
  , ("trackAndHold",     fed (\c -> if c > 0 then Just c else Nothing) (trackAndHold 0) id)
  , ("dTrackAndHold",    fed (\c -> if c > 0 then Just c else Nothing) (dTrackAndHold 0) id)
  , ("accum",            fed (fmap (+) . pos) (accum 0) ev)
  , ("accumHold",        fed (fmap (+) . pos) (accumHold 0) id)
  , ("dAccumHold",       fed (fmap (+) . pos) (dAccumHold 0) id)
  , ("accumBy",          fed pos (accumBy (+) 0) ev)
  , ("accumHoldBy",      fed pos (accumHoldBy (+) 0) id)
  , ("arr p >>> accumHold", arr (\(_, c) -> c) >>> (arr (fmap (+) . pos) >>> accumHold 0) >>> arr id)
  , ("arr p >>> accumHoldBy", arr (\(_, c) -> c) >>> (arr pos >>> accumHoldBy (+) 0) >>> arr id)
  , ("dAccumHoldBy",     fed pos (dAccumHoldBy (+) 0) id)
  , ("accumFilter",      fed pos (accumFilter (\s x -> (s + x, if x > 2 then Just s else Nothing)) 0) ev)
  -- delays
  , ("iPre",             fed id (iPre 0) id)
  , ("fby",              fed id (0 `fby` integral) id)
  , ("delay",            fed id (delay 0.2 0) id)
  -- integration
  , ("integral",         fed id integral id)
  , ("imIntegral",       fed id (imIntegral 0) id)
  , ("trapezoidIntegral", fed id trapezoidIntegral id)
  , ("impulseIntegral",  fed (\c -> (c, pos c)) impulseIntegral id)
  , ("count",            fed pos count (event 0 fromIntegral . fmap (id :: Int -> Int)))
  , ("derivative",       fed id derivative id)
  -- initialisation
  , ("-->",              fed id (0 --> derivative) id)
  , (">--",              fed id (0 >-- (arr pos >>> hold 0)) id)
  , ("-=>",              fed id (negate -=> derivative) id)
  , (">=-",              fed id (negate >=- derivative) id)
  , ("initially",        fed id (arr pos >>> hold 0 >>> initially 0) id)
  -- switches
  , ("switch",           fed id (switch (identity &&& arr big) (\x -> constant x)) id)
  , ("switch on an edge", fed id (switch (identity &&& (arr (> 2) >>> edge)) (\() -> derivative)) id)
  , ("dSwitch",          fed id (dSwitch (identity &&& arr big) (\x -> constant x)) id)
  , ("rSwitch",          fed (\c -> (c, fmap (\x -> arr (* x)) (big c))) (rSwitch identity) id)
  , ("arr p >>> rSwitch", arr (\(_, c) -> (c, fmap (\x -> arr (* x)) (big c))) >>> rSwitch identity >>> arr id)
  , ("drSwitch",         fed (\c -> (c, fmap (\x -> arr (* x)) (big c))) (drSwitch identity) id)
  , ("kSwitch",          fed id (kSwitch integral (arr (big . fst)) (\sf _ -> sf)) id)
  , ("dkSwitch",         fed id (dkSwitch integral (arr (big . fst)) (\sf _ -> sf)) id)
  , ("left",             fed (\c -> if c > 0 then Left c else Right c) (left integral) (either id id))
  -- collections
  , ("par",              fed id (par zipAll members) sum)
  , ("parB",             fed id (parB members) sum)
  , ("parZ",             fed (\c -> if c > 100 then [] else [c, c]) (parZ members) sum)
  , ("pSwitch",          fed id (pSwitch zipAll members (arr (big . fst)) (\sfs _ -> parB sfs)) sum)
  , ("dpSwitch",         fed id (dpSwitch zipAll members (arr (big . fst)) (\sfs _ -> parB sfs)) sum)
  , ("pSwitchB",         fed id (pSwitchB members (arr (big . fst)) (\sfs _ -> parB sfs)) sum)
  , ("dpSwitchB",        fed id (dpSwitchB members (arr (big . fst)) (\sfs _ -> parB sfs)) sum)
  , ("pSwitchZ",         fed twice (pSwitchZ members (arr (big . head . fst)) (\sfs _ -> parZ sfs)) sum)
  , ("dpSwitchZ",        fed twice (dpSwitchZ members (arr (big . head . fst)) (\sfs _ -> parZ sfs)) sum)
  , ("rpSwitch",         fed (\c -> (c, grow c)) (rpSwitch zipAll members) sum)
  , ("drpSwitch",        fed (\c -> (c, grow c)) (drpSwitch zipAll members) sum)
  , ("rpSwitchB",        fed (\c -> (c, grow c)) (rpSwitchB members) sum)
  , ("drpSwitchB",       fed (\c -> (c, grow c)) (drpSwitchB members) sum)
  , ("rpSwitchZ",        fed (\c -> (twice c, swap c)) (rpSwitchZ members) sum)
  , ("drpSwitchZ",       fed (\c -> (twice c, swap c)) (drpSwitchZ members) sum)
  -- loops
  , ("loopPre",          fed id (loopPre 0 (arr (\(c, s) -> (s + c, s + c)))) id)
  , ("loopPre over a hold", fed id (loopPre 0 (arr (\(c, s) -> pos (c + s)) >>> hold 0 >>> arr (\h -> (h, h)))) id)
  , ("loopIntegral",     fed id (loopIntegral (arr (\(c, x) -> (x, c - x)))) id)
  -- tasks
  , ("runTask_",         fed id (runTask_ (mkTask (identity &&& arr big) >>= \x -> constT x)) id)
  -- Yampa's names
  , ("sscan",            fed id (sscan (+) 0) id)
  , ("sscanPrim",        fed id (sscanPrim (\c a -> if a > 2 then Just (c + a, c) else Nothing) 0 0) id)
  , ("iterFrom",         fed id (iterFrom (\a a' h v -> v + h * (a + a') / 2) 0) id)
  , ("provided",         fed id (provided (> 0) integral derivative) id)
  , ("recur",            fed id (recur (arr big >>> notYet)) ev)
  , ("andThen",          fed id ((arr big >>> once) `andThen` (arr pos >>> once)) ev)
  , ("pause",            fed id (pause 0 (arr (> 2)) integral) id)
  , ("parC",             fed twice (parC integral) sum)
  ]
  where
    evU' = event 0 id
    members = [integral, arr pos >>> hold 0]
    -- a route that looks at its input (as a user's may)
    zipAll c sfs = if c > 100 then [] else [(c, s) | s <- sfs]
    twice c = if c > 100 then [] else [c, c]
    grow c = fmap (\_ sfs -> sfs ++ [derivative]) (big c)
    swap c = fmap (\_ -> reverse) (big c)

-- 'pre' has no defined output at time 0, so its output cannot be fed back
-- as it is; it is checked with its output discarded only.
inputDiscardedOnly :: [(String, SF (Double, Double) Double)]
inputDiscardedOnly = [("pre", fed id pre id)]

-- A mode flag fed back into an edge detector: the edge watches the flag
-- that this very sample computes from the input, and its output is not
-- used by the loop's output.
modeFlag :: SF Double Double
modeFlag = proc a -> do
  rec flagUp <- edge -< flag
      let flag = a > 0
  _ <- hold () -< flagUp
  returnA -< a

-- A state machine whose switch event is computed from its own output, fed
-- back through iPre: it integrates 10 until its previous output passes 2,
-- then outputs -10.
selfSwitching :: SF Double Double
selfSwitching = proc _ -> do
  rec out  <- switch ((arr fst >>> integral) &&& arr (big . snd))
                     (\_ -> arr (negate . fst)) -< (10, prev)
      prev <- iPre 0 -< out
  returnA -< out
