{-# LANGUAGE Arrows #-}
-- | Tests for "AFRP.Hybrid": holding and accumulating, in immediate and
-- delayed forms, the delayed forms closing feedback loops, and a long run.
module AFRP.HybridSpec (spec) where

import           Control.Arrow     (arr, first, loop, returnA, second, (>>>))
import           Control.Exception (evaluate)
import           Data.Maybe        (fromMaybe)
import           Test.Hspec

import           AFRP.Event        (Event (..), eventToMaybe, tag)
import           AFRP.EventSource  (edge)
import           AFRP.Hybrid
import           AFRP.Internal.SF  (SF)
import           AFRP.Run          (embed)
import           TestUtil

e :: a -> Event a
e = Event

n :: Event a
n = NoEvent

-- | Feed the signal function a bottom wherever the outer input is
-- 'Nothing'. The runner may force each outer sample, but not what the
-- inner signal function receives, so this observes whether the signal
-- function under test evaluates its current input.
bottomWhereNothing :: SF a b -> SF (Maybe a) b
bottomWhereNothing sf = arr (fromMaybe (error "the current input was evaluated")) >>> sf

-- | A staircase whose level @k@ steps up at each rising edge of
-- "input >= k + 1": the edge detector looks at the held output, and the
-- held value is computed from it. Closed through 'dHold'.
staircaseHold :: SF Double Int
staircaseHold = proc x -> do
  rec k  <- dHold 0 -< up `tag` (k + 1)
      up <- edge -< x >= fromIntegral k + 1
  returnA -< k

-- | The same staircase, written with 'loop' and plain combinators.
staircaseLoop :: SF Double Int
staircaseLoop = loop $
      second (dHold 0)
  >>> arr (\(x, k) -> ((x >= fromIntegral k + 1, k), k))
  >>> first (first edge)
  >>> arr (\((up, k), out) -> (out, up `tag` (k + 1)))

-- | The staircase closed through 'dAccumHold'.
staircaseAccum :: SF Double Int
staircaseAccum = proc x -> do
  rec k  <- dAccumHold 0 -< up `tag` (+ 1)
      up <- edge -< x >= fromIntegral k + 1
  returnA -< k

-- | The staircase closed through 'dAccumHoldBy'.
staircaseAccumBy :: SF Double Int
staircaseAccumBy = proc x -> do
  rec k  <- dAccumHoldBy (+) 0 -< up `tag` 1
      up <- edge -< x >= fromIntegral k + 1
  returnA -< k

-- | The staircase closed through 'dTrackAndHold'.
staircaseTrack :: SF Double Int
staircaseTrack = proc x -> do
  rec k  <- dTrackAndHold 0 -< eventToMaybe (up `tag` (k + 1))
      up <- edge -< x >= fromIntegral k + 1
  returnA -< k

-- | Input for the staircases, and the expected levels:
--
-- > x     0  1.5  1.5  2.5  0  2.5  3.5  3.5
-- > cond  F   T    F    T   F   F    T    F      (x >= k + 1)
-- > edge  -   1    -    2   -   -    3    -      (the new level)
-- > k     0   0    1    1   2   2    2    3      (one sample later)
staircaseInput :: [Double]
staircaseInput = [0, 1.5, 1.5, 2.5, 0, 2.5, 3.5, 3.5]

staircaseExpected :: [Int]
staircaseExpected = [0, 0, 1, 1, 2, 2, 2, 3]

spec :: Spec
spec = do
  describe "hold" $ do
    it "outputs the initial value, then the latest event value, from its instant" $
      runDt 1 (hold 0) [n, e 5, n, e 7, n] `shouldBe` [0, 5, 5, 7, 7 :: Int]
    it "takes an event at time 0 at once" $
      runDt 1 (hold 0) [e 3, n, n] `shouldBe` [3, 3, 3 :: Int]
    it "follows the documented example" $
      embed (hold 0) (n, [(1, Just (e 5)), (1, Just n)]) `shouldBe` [0, 5, 5 :: Int]

  describe "dHold" $ do
    it "shows an event value one sample after the event" $
      runDt 1 (dHold 0) [n, e 5, n, e 7, n] `shouldBe` [0, 0, 5, 5, 7 :: Int]
    it "outputs the initial value at time 0 even with an event there" $
      runDt 1 (dHold 0) [e 3, n, n] `shouldBe` [0, 3, 3 :: Int]
    it "shows consecutive events one sample late each" $
      runDt 1 (dHold 'a') [e 'b', e 'c', e 'd'] `shouldBe` "abc"
    it "does not evaluate its current input" $
      runDt 1 (bottomWhereNothing (dHold 0)) [Just n, Just (e 4), Nothing] `shouldBe` [0, 0, 4 :: Int]

  describe "trackAndHold" $ do
    it "tracks Just values and holds the last one through Nothing" $
      runDt 1 (trackAndHold 0) [Nothing, Just 1, Just 2, Nothing, Just 3] `shouldBe` [0, 1, 2, 2, 3 :: Int]
    it "tracks a Just at time 0" $
      runDt 1 (trackAndHold 0) [Just 9, Nothing] `shouldBe` [9, 9 :: Int]

  describe "dTrackAndHold" $ do
    it "is trackAndHold one sample later" $
      runDt 1 (dTrackAndHold 0) [Nothing, Just 1, Just 2, Nothing, Just 3] `shouldBe` [0, 0, 1, 2, 2 :: Int]
    it "outputs the initial value at time 0 even with a Just there" $
      runDt 1 (dTrackAndHold 0) [Just 9, Nothing] `shouldBe` [0, 9 :: Int]
    it "does not evaluate its current input" $
      runDt 1 (bottomWhereNothing (dTrackAndHold 0)) [Just (Just 1), Nothing] `shouldBe` [0, 1 :: Int]

  describe "accum" $ do
    it "applies each event's function and occurs with the new value, at the instant" $
      runDt 1 (accum 0) [e (+ 1), n, e (* 10), e (subtract 3)] `shouldBe` [e 1, n, e 10, e (7 :: Int)]
    it "follows the documented example" $
      embed (accum 0) (e (+ 1), [(1, Just n), (1, Just (e (* 10)))]) `shouldBe` [e 1, n, e (10 :: Int)]
    it "has no occurrence at time 0 without an input event" $
      runDt 1 (accum 'x') [n, e succ] `shouldBe` [n, e 'y']
    it "evaluates the accumulated value at the next sample" $
      evaluate (length (runDt 1 (accum (0 :: Int)) [e (const undefined), n]))
        `shouldThrow` anyErrorCall

  describe "accumHold" $ do
    it "holds the accumulated value, updated at each event's instant" $
      runDt 1 (accumHold 0) [e (+ 1), n, e (* 10), e (subtract 3), n] `shouldBe` [1, 1, 10, 7, 7 :: Int]
    it "outputs the initial value until the first event" $
      runDt 1 (accumHold 0) [n, n, e (+ 1)] `shouldBe` [0, 0, 1 :: Int]
    it "counts 10^5 events in a long run" $
      last (runDt 0.01 (accumHold (0 :: Int)) (replicate 100000 (e (+ 1)))) `shouldBe` 100000
    it "evaluates the accumulated value when an event is folded in" $
      evaluate (length (runDt 1 (accumHold (0 :: Int)) [n, e (const undefined), n]))
        `shouldThrow` anyErrorCall

  describe "dAccumHold" $ do
    it "is accumHold one sample later" $
      runDt 1 (dAccumHold 0) [e (+ 1), n, e (* 10), e (subtract 3), n] `shouldBe` [0, 1, 1, 10, 7 :: Int]
    it "does not evaluate its current input" $
      runDt 1 (bottomWhereNothing (dAccumHold 0)) [Just (e (+ 2)), Nothing] `shouldBe` [0, 2 :: Int]
    it "counts 10^5 events in a long run, excluding the last sample's" $
      last (runDt 0.01 (dAccumHold (0 :: Int)) (replicate 100000 (e (+ 1)))) `shouldBe` 99999

  describe "accumBy" $ do
    it "folds the event values into the accumulator and occurs with it" $
      runDt 1 (accumBy (\acc c -> acc ++ [c]) "") [n, e 'a', e 'b', n, e 'c']
        `shouldBe` [n, e "a", e "ab", n, e "abc"]
    it "passes the accumulator first and the event value second" $
      runDt 1 (accumBy (-) 100) [e 1, e (10 :: Int)] `shouldBe` [e 99, e 89]
    it "takes an event at time 0" $
      runDt 1 (accumBy (+) 5) [e 2, n] `shouldBe` [e 7, n :: Event Int]

  describe "accumHoldBy" $ do
    it "holds the accumulator of accumBy" $
      runDt 1 (accumHoldBy (+) 100) [e 1, n, e 2, n] `shouldBe` [101, 101, 103, 103 :: Int]
    it "passes the accumulator first and the event value second" $
      runDt 1 (accumHoldBy (-) 100) [n, e 1, e (10 :: Int)] `shouldBe` [100, 99, 89]
    it "counts 10^5 events in a long run" $
      last (runDt 0.01 (accumHoldBy (+) (0 :: Int)) (replicate 100000 (e 1))) `shouldBe` 100000

  describe "dAccumHoldBy" $ do
    it "is accumHoldBy one sample later" $
      runDt 1 (dAccumHoldBy (+) 100) [e 1, n, e 2, n] `shouldBe` [100, 101, 101, 103 :: Int]
    it "does not evaluate its current input" $
      runDt 1 (bottomWhereNothing (dAccumHoldBy (+) 100)) [Just (e 1), Nothing] `shouldBe` [100, 101 :: Int]

  describe "accumFilter" $ do
    -- a running sum, reported only when it is even
    let evenSums c a = let c' = c + a in (c', if even c' then Just c' else Nothing)
    it "updates the state at every event and occurs only for Just" $
      runDt 1 (accumFilter evenSums 0) [e 1, e 1, n, e 3, e (1 :: Int)]
        `shouldBe` [n, e 2, n, n, e 6]
    it "may change the type of the output" $
      runDt 1 (accumFilter (\c a -> (c + a, Just (show c))) (0 :: Int)) [e 5, n, e 2]
        `shouldBe` [e "0", n, e "5"]

  describe "the delayed forms close feedback loops" $ do
    it "dHold in rec (the edge detector sees the held output)" $
      withoutHanging (runDt 1 staircaseHold staircaseInput) staircaseExpected
    it "dHold in loop" $
      withoutHanging (runDt 1 staircaseLoop staircaseInput) staircaseExpected
    it "dAccumHold in rec" $
      withoutHanging (runDt 1 staircaseAccum staircaseInput) staircaseExpected
    it "dAccumHoldBy in rec" $
      withoutHanging (runDt 1 staircaseAccumBy staircaseInput) staircaseExpected
    it "dTrackAndHold in rec" $
      withoutHanging (runDt 1 staircaseTrack staircaseInput) staircaseExpected
    it "a dHold loop keeps going for 10^4 samples" $ do
      -- the input is huge at odd samples and 0 at even ones, so every odd
      -- sample is a rising edge that steps the level up
      let pulses = [if odd i then 1e9 else 0 | i <- [0 .. 10000 :: Int]]
          outs   = runDt 1 staircaseHold pulses
      withoutHanging [length (show outs) `seq` last outs] [5000]
