-- | The small Yampa names added for ported programs, each tested beside the
-- others (their modules' own specs are edited in parallel branches):
-- 'arr3'..'arr5', '-:>' ("AFRP.Basic"), 'noEventFst'/'noEventSnd'
-- ("AFRP.Event"), 'iterFrom' ("AFRP.Integration"), 'pause'
-- ("AFRP.Conditional"), 'parC' ("AFRP.Parallel"), 'evalFuture'
-- ("AFRP.Run"). Expected outputs worked out by hand from the Haddocks.
module AFRP.YampaNamesSpec (spec) where

import           Test.Hspec
import           Test.QuickCheck

import           AFRP hiding (forAll)
import           TestUtil

spec :: Spec
spec = do
  describe "arr3, arr4, arr5" $
    it "lift functions of tuples" $ do
      runDt 1 (arr3 (\a b c -> a * b + c)) [(2, 3, 4 :: Int)] `shouldBe` [10]
      runDt 1 (arr4 (\a b c d -> [a, b, c, d])) [('w', 'x', 'y', 'z')] `shouldBe` ["wxyz"]
      runDt 1 (arr5 (\a b c d e -> a + b + c + d + e)) [(1, 2, 3, 4, 5 :: Int)] `shouldBe` [15]

  describe "-:>" $ do
    it "inserts the first output and delays the signal function by one sample" $
      runDt 1 (0 -:> localTime) (replicate 3 ()) `shouldBe` [0, 0, 1]
    it "differs from --> (which runs the signal function at time 0)" $
      runDt 1 (0 --> localTime) (replicate 3 ()) `shouldBe` [0, 1, 2]
    it "passes the current input after the first sample" $
      runDt 1 ('x' -:> identity) "abc" `shouldBe` "xbc"

  describe "noEventFst and noEventSnd" $
    it "drop the event of one component" $ do
      noEventFst (Event 'e', 3 :: Int) `shouldBe` (NoEvent :: Event (), 3)
      noEventSnd (3 :: Int, Event 'e') `shouldBe` (3, NoEvent :: Event ())

  describe "iterFrom" $ do
    it "outputs the seed at time 0, then applies the rule to consecutive inputs" $
      runDt 1 (iterFrom (\a a' dt v -> v + dt * (a + a') / 2) 0) [0, 2, 2 :: Double]
        `shouldBe` [0, 1, 3]
    it "is trapezoidIntegral for the trapezoid rule (property)" $ property $
      forAll (genSamples (choose (-5, 5))) $ \samples ->
        and (zipWith approx
               (runSamples (iterFrom (\a a' dt v -> v + dt * (a + a') / 2) 0) samples)
               (runSamples trapezoidIntegral samples))

  describe "pause" $ do
    it "freezes the signal function and holds its output while the condition holds" $
      runDt 1 (pause 0 (arr id) localTime) [False, False, True, True, False]
        `shouldBe` [0, 1, 1, 1, 2]
    it "outputs the initial value until the signal function first runs" $
      runDt 1 (pause (-1) (arr id) localTime) [True, True, False, False]
        `shouldBe` [-1, -1, 0, 1]

  describe "parC" $ do
    it "runs one copy per element of the first input list" $
      runDt 1 (parC (sscan (+) 0)) [[1, 10], [2, 20], [3, 30 :: Int]]
        `shouldBe` [[1, 10], [3, 30], [6, 60]]
    it "ignores extra elements after time 0" $
      runDt 1 (parC identity) [[1], [2, 3 :: Int]] `shouldBe` [[1], [2]]

  describe "evalFuture" $
    it "runs time 0 and returns the rest, whose first sample comes dt later" $ do
      let (b0, rest) = evalFuture localTime () 0.5
      b0 `shouldBe` 0
      runDt 7 rest [(), ()] `shouldBe` [0.5, 7.5]
