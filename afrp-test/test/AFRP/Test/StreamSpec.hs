{-# LANGUAGE ScopedTypeVariables #-}
module AFRP.Test.StreamSpec (spec) where

import           Control.Exception (evaluate)
import           Data.List        (group)

import           Test.Hspec
import           Test.QuickCheck

import           AFRP             (integral, embed)
import           AFRP.Test.Stream

spec :: Spec
spec = do
  describe "evalSF" $ do
    it "answers each sample with its time step (fixed)" $
      fst (evalSF integral [(0, 1), (0.5, 2), (0.5, 4 :: Double)])
        `shouldBe` [(0, 0), (0.5, 0.5), (0.5, 1.5)]
    it "continues where it stopped with evalFutureSF (fixed)" $ do
      let (_, fsf) = evalSF integral [(0, 1), (0.5, 2 :: Double)]
      fst (evalFutureSF fsf [(0.5, 4)]) `shouldBe` [(0.5, 1.5 :: Double)]
    it "agrees with embed (property)" $ property $ \(Positive dt) (x0 :: Double) xs ->
      samples (fst (evalSF integral (groupDeltas (x0 : xs) (repeat dt))))
        === embed integral (x0, [(dt, Just x) | x <- xs])
  describe "cutting and refining" $ do
    it "sClipBeforeTime restarts the stream at time 0 (fixed)" $
      sClipBeforeTime 1 [(0, 'a'), (0.5, 'b'), (0.5, 'c'), (0.5, 'd')]
        `shouldBe` [(0, 'c'), (0.5, 'd')]
    it "sClipAfterTime keeps the samples up to the time (fixed)" $
      sClipAfterTime 1 [(0, 'a'), (0.5, 'b'), (0.5, 'c'), (0.5, 'd')]
        `shouldBe` [(0, 'a'), (0.5, 'b'), (0.5, 'c')]
    it "sRefine keeps the values and total time, with no step over the bound (property)" $
      property $ \(Positive maxDT) (xs :: [(Positive Double, Int)]) ->
        let s  = (0, 0) : [(d, x) | (Positive d, x) <- xs]
            s' = sRefine maxDT s
        in conjoin
             [ counterexample "a step over the bound" (all ((<= maxDT * (1 + 1e-9)) . fst) (drop 1 s'))
             , counterexample "total time changed"
                 (abs (sum (map fst s') - sum (map fst s)) <= 1e-9 * (1 + sum (map fst s)))
             , map head (group (samples s')) === map head (group (samples s)) ]
    it "sRefine refuses to cut one step into more samples than memory holds (fixed)" $ do
      evaluate (length (sRefine 1e-300 [(0, 'a'), (1e300, 'b')])) `shouldThrow` anyErrorCall
      length (sRefine 0.25 [(0, 'a'), (1, 'b')]) `shouldBe` 5
    it "sMerge samples at every time of either stream (fixed)" $
      sMerge (+) [(0, 1), (1, 2)] [(0, 10), (0.5, 20), (0.5, 30 :: Int)]
        `shouldBe` [(0, 11), (0.5, 20), (0.5, 32)]
