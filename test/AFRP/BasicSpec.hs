module AFRP.BasicSpec (spec) where

import           Control.Arrow    (arr, left, (>>>), (|||))
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Basic
import           AFRP.Delay       (iPre)
import           AFRP.Integration (integral)
import           TestUtil

spec :: Spec
spec = do
  describe "identity and constant" $ do
    it "identity outputs its input at every sample, time 0 included" $
      runDt 0.1 identity [3, 1, 4 :: Int] `shouldBe` [3, 1, 4]
    it "constant ignores its input" $
      runDt 0.1 (constant 'k') [1, 2, 3 :: Int] `shouldBe` "kkk"
    it "arr2 lifts a binary function to pairs" $
      runDt 0.1 (arr2 (-)) [(5, 2), (1, 4 :: Int)] `shouldBe` [3, -3]

  describe "localTime and time" $ do
    it "starts at 0 and sums the time steps" $
      runSamples localTime [(9, ()), (0.5, ()), (0.25, ()), (1, ())]
        `shouldBe` [0, 0.5, 0.75, 1.75]
    it "reads exactly 1.0 after ten steps of 0.1 (compensated sum)" $
      last (runDt 0.1 localTime (replicate 11 ())) `shouldBe` 1.0
    it "reads exactly 100.0 after a thousand steps of 0.1" $
      last (runDt 0.1 localTime (replicate 1001 ())) `shouldBe` 100.0
    it "time is localTime" $
      runDt 0.2 time "abcd" `shouldBe` runDt 0.2 localTime "abcd"
    it "agrees with the exact sum of random time steps" $ property $
      forAll (genSamples (pure ())) $ \samples ->
        let exact = map fromRational (scanl1 (+) (0 : map (toRational . fst) (drop 1 samples)))
        in and (zipWith approx (runSamples localTime samples) exact)

  describe "initialisation operators" $ do
    it "--> replaces only the output at time 0" $
      runDt 1 (0 --> identity) [5, 6, 7 :: Int] `shouldBe` [0, 6, 7]
    it "--> still runs the signal function at time 0" $
      runDt 1 (100 --> integral) [2, 2, 2 :: Double] `shouldBe` [100, 2, 4]
    it "initially replaces the first output and passes the input after" $
      runDt 1 (initially 'x') "abc" `shouldBe` "xbc"
    it "initially changes what a following integral sees at time 0" $
      runDt 1 (initially 0 >>> integral) [5, 2, 3 :: Double] `shouldBe` [0, 0, 2]
    it "dup duplicates" $
      dup 'q' `shouldBe` ('q', 'q')
    it ">-- replaces only the input at time 0" $
      runDt 1 (10 >-- iPre 0) [1, 2, 3 :: Int] `shouldBe` [0, 10, 2]
    it "-=> maps the output at time 0 only" $
      runDt 1 (negate -=> identity) [1, 2, 3 :: Int] `shouldBe` [-1, 2, 3]
    it ">=- maps the input at time 0 only" $
      runDt 1 ((* 10) >=- identity) [1, 2, 3 :: Int] `shouldBe` [10, 2, 3]

  describe "Functor and Applicative instances" $ do
    it "fmap maps every output" $
      runDt 0.5 (fmap (* 2) localTime) [(), (), ()] `shouldBe` [0, 1, 2]
    it "pure is constant" $
      runDt 0.5 (pure 'p') [(), ()] `shouldBe` "pp"
    it "<*> applies outputs sample by sample" $
      runDt 0.5 ((+) <$> localTime <*> arr fromIntegral) [1, 2, 3 :: Int]
        `shouldBe` [1, 2.5, 4]

  describe "ArrowChoice" $ do
    it "left freezes its signal function on Right samples (as Yampa)" $
      runDt 1 (left localTime) [Left (), Left (), Right 'r', Right 's', Left (), Left ()]
        `shouldBe` [Left 0, Left 1, Right 'r', Right 's', Left 2, Left 3]
    it "left starts its signal function at the first Left sample" $
      runDt 1 (left integral) [Right 'a', Right 'b', Left 1, Left 1, Left (1 :: Double)]
        `shouldBe` [Right 'a', Right 'b', Left 0, Left 1, Left 2]
    it "||| merges both branches" $
      runDt 1 (arr (* 2) ||| arr length) [Left 4, Right "abc"] `shouldBe` [8, 3 :: Int]
    it "routes each sample by its Either tag" $
      runDt 1 pick [1, -2, 3 :: Int] `shouldBe` [1, 2, 3]
  where
    pick = arr (\x -> if x >= 0 then Left x else Right x) >>> (identity ||| arr negate)
