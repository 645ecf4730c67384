{-# LANGUAGE Arrows #-}
-- | Tests for "AFRP.Delay": the one-sample delays and the time delay.
module AFRP.DelaySpec (spec) where

import           Control.Arrow     (arr, loop, returnA, second, (>>>))
import           Control.Exception (ErrorCall (..), evaluate)
import           Data.List         (isInfixOf)
import           Data.Maybe        (fromMaybe)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Basic        (identity, localTime)
import           AFRP.Delay
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (SF)
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

-- | A counter closed through 'iPre' with 'loop': 0, 1, 2, ...
counter :: SF () Int
counter = loop (second (iPre 0) >>> arr (\(_, k) -> (k, k + 1)))

-- | Running sums closed through 'iPre' in arrow notation.
runningSum :: SF Int Int
runningSum = proc x -> do
  rec let s = prev + x
      prev <- iPre 0 -< s
  returnA -< s

spec :: Spec
spec = do
  describe "delay at the edges" $ do
    it "by infinity outputs the initial value for ever" $
      embed (delay (1 / 0) 'z') ('a', [(1, Just 'b'), (1e308, Just 'c'), (1 / 0, Just 'd')]) `withoutHanging` "zzzz"
    it "with samples at one instant (dt 0): the newest of them comes out, as with every sample kept" $
      -- times 0 0 0 1 1 2: a delay of 1 outputs the last sample of time 0
      -- from time 1 on, the last of time 1 at time 2
      embed (delay 1 (0 :: Int)) (1, [(0, Just 2), (0, Just 3), (1, Just 4), (0, Just 5), (1, Just 6)])
        `withoutHanging` [0, 0, 0, 3, 3, 5]
    it "after an infinite step: the sample of the infinite time comes out at the next one" $
      -- times 0, inf, inf: at the second infinite sample the one of the
      -- first has been due since inf + 1 = inf
      embed (delay 1 (0 :: Int)) (1, [(1 / 0, Just 2), (1, Just 3), (0, Just 4)]) `withoutHanging` [0, 1, 2, 3]
    it "by less than the clock's rounding, with samples at one instant: still one sample late" $
      -- times 0, 1, 1, 1: 1 + 1e-16 is 1, so every earlier sample is due
      embed (delay 1e-16 (0 :: Int)) (1, [(1, Just 2), (0, Just 3), (0, Just 4)]) `withoutHanging` [0, 1, 2, 3]
  describe "pre" $ do
    it "outputs the previous input from the second sample on" $
      drop 1 (runDt 1 pre [1, 2, 3, 4 :: Int]) `shouldBe` [1, 2, 3]
    it "is an error, naming pre, only when the output at time 0 is demanded" $
      evaluate (head (runDt 1 pre [1, 2 :: Int])) `shouldThrow` errorMentioning "pre"
    it "lets the run go on when the output at time 0 is not demanded" $
      length (runDt 1 pre "abc") `shouldBe` 3
    it "works with irregular steps" $
      drop 1 (runSamples pre [(0, 'a'), (0.3, 'b'), (7, 'c')]) `shouldBe` "ab"

  describe "iPre" $ do
    it "outputs the initial value, then the previous input" $
      runDt 1 (iPre 0) [1, 2, 3 :: Int] `shouldBe` [0, 1, 2]
    it "follows the documented example" $
      embed (iPre 0) (1, [(1, Just 2), (1, Just 3)]) `shouldBe` [0, 1, 2 :: Int]
    it "does not evaluate its current input" $
      runDt 1 (bottomWhereNothing (iPre 0)) [Just 1, Nothing] `shouldBe` [0, 1 :: Int]
    it "closes a loop as a counter" $
      withoutHanging (runDt 1 counter (replicate 6 ())) [0 .. 5]
    it "closes a rec as a running sum" $
      withoutHanging (runDt 1 runningSum [1, 2, 3, 4, 5]) [1, 3, 6, 10, 15]
    it "is iPre x0 on any input: the shifted list" $
      property $ \x0 (NonEmpty xs) ->
        runDt 1 (iPre x0) xs === take (length xs) (x0 : (xs :: [Int]))

  describe "fby" $ do
    it "outputs b0 at time 0, then the previous output of sf" $
      (5 `fby` arr (* 10)) `runOn` [1, 2, 3 :: Int] `shouldBe` [5, 10, 20]
    it "runs sf from time 0" $
      runDt 0.5 (100 `fby` localTime) (replicate 4 ()) `shouldBe` [100, 0, 0.5, 1.0]
    it "delays a stateful sf by one sample" $
      runDt 0.5 (9 `fby` integral) [2, 2, 2, 2] `shouldBe` [9, 0, 1, 2 :: Double]
    it "is right-associative (infixr 0)" $
      runDt 1 (1 `fby` 2 `fby` identity) [10, 20, 30, 40 :: Int] `shouldBe` [1, 2, 10, 20]

  describe "delay" $ do
    it "follows the documented example" $
      embed (delay 1 0) (1, [(0.5, Just 2), (0.5, Just 3), (0.5, Just 4)]) `shouldBe` [0, 0, 1, 2 :: Int]
    it "delays by q with constant steps (q = 1, steps of 0.5)" $
      runDt 0.5 (delay 1 0) [1, 2, 3, 4, 5, 6 :: Int] `shouldBe` [0, 0, 1, 2, 3, 4]
    it "outputs a0 at time 0" $
      runDt 1 (delay 2 'z') "abc" `shouldBe` "zza"
    it "follows the latest sample at or before t - q with irregular steps" $
      -- sample times 0 .25 .875 1 1.25 1.875 2 3.5 3.625, inputs 10 .. 18
      --   t - q      -1 -.75 -.125 0 .25 .875 1 2.5 2.625
      runSamples (delay 1 (-1))
        (zip [0, 0.25, 0.625, 0.125, 0.25, 0.625, 0.125, 1.5, 0.125] [10 .. 18 :: Int])
        `shouldBe` [-1, -1, -1, 10, 11, 12, 13, 16, 16]
    it "holds the delayed value over a long step and catches up after it" $
      -- sample times 0 .5 3 3.5 4 4.5, q = 1: t - q = -1 -.5 2 2.5 3 3.5
      runSamples (delay 1 0) (zip [0, 0.5, 2.5, 0.5, 0.5, 0.5] [1 .. 6 :: Int])
        `shouldBe` [0, 0, 2, 2, 3, 4]
    it "is exact with steps of 0.1 (q = 0.5 delays by five samples)" $
      runDt 0.1 (delay 0.5 (-1)) [0 .. 12 :: Int]
        `shouldBe` [-1, -1, -1, -1, -1, 0, 1, 2, 3, 4, 5, 6, 7]
    it "acts as a one-sample delay when q is below the step" $
      runDt 0.5 (delay 0.1 0) [1, 2, 3, 4 :: Int] `shouldBe` [0, 1, 2, 3]
    it "delay 0 is the identity (a0 is not used)" $
      runDt 1 (delay 0 undefined) [1, 2, 3 :: Int] `shouldBe` [1, 2, 3]
    it "with a negative delay is an error" $
      evaluate (length (runDt 1 (delay (-1) (0 :: Int)) [1, 2])) `shouldThrow` anyErrorCall
    it "outputs, at every sample, the input at the latest time s <= t - q" $
      property $ \(Positive q0) ->
        forAll (genSamples (arbitrary :: Gen Int)) $ \samples ->
          let q     = q0 / 4 :: Double
              -- use dyadic steps so that sample times are exact
              exact = [(fromIntegral (round (dt * 64) + 1 :: Int) / 64, x) | (dt, x) <- samples]
              ts    = scanl1 (+) (0 : map fst (drop 1 exact))
              xs    = map snd exact
              model t = case [x | (s, x) <- zip ts xs, s <= t - q] of
                [] -> 0
                ys -> last ys
          in runSamples (delay q 0) exact === map model ts
  where
    runOn = runDt 1
