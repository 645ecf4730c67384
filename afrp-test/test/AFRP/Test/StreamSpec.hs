{-# LANGUAGE ScopedTypeVariables #-}
module AFRP.Test.StreamSpec (spec) where

import           Control.Exception (evaluate)
import           Data.List        (group)

import           Test.Hspec        hiding (after)
import           Test.QuickCheck

import           AFRP             (after, arr, embed, integral, isEvent, (>>>))
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
    it "sRestart times a suffix from its first sample, reading no further (fixed)" $ do
      sRestart (drop 1 [(0, 'a'), (0.5, 'b'), (0.25, 'c')]) `shouldBe` [(0, 'b'), (0.25, 'c')]
      sRestart ([] :: SignalSampleStream ()) `shouldBe` []
      take 1 (sRestart ((2, 'x') : error "the rest is not read")) `shouldBe` [(0, 'x')]
    it "sClipAfterTime keeps the samples up to the time (fixed)" $
      sClipAfterTime 1 [(0, 'a'), (0.5, 'b'), (0.5, 'c'), (0.5, 'd')]
        `shouldBe` [(0, 'a'), (0.5, 'b'), (0.5, 'c')]
    it "a sample whose time rounds just past t is at t, for both clips and sampleAt (fixed)" $ do
      let s = replicate 5 (0.1, ()) `zip'` "abcde"
          zip' ts cs = [ (dt, c) | ((dt, _), c) <- zip ts cs ]
      sampleTimes s !! 3 `shouldSatisfy` (> 0.3)   -- (0.30000000000000004)
      map snd (sClipAfterTime 0.3 s) `shouldBe` "abcd"
      map snd (sClipBeforeTime 0.3 s) `shouldBe` "de"
      sampleAt 0.3 s `shouldBe` Just 'd'
      sampleAt 0.29 s `shouldBe` Just 'c'
      sampleAt (-1) s `shouldBe` Just 'a'
      sampleAt 0.3 ([] :: SignalSampleStream Char) `shouldBe` Nothing
    it "sampleAt finds the output of an event at its instant" $
      sampleAt 0.3 (fst (evalSF (after 0.3 () >>> arr isEvent) (replicate 5 (0.1, ())))) `shouldBe` Just True
    it "sRefine keeps the values and total time, with no step over the bound (property)" $
      property $ \(Positive maxDT) (xs :: [(Positive Double, Int)]) ->
        let s  = (0, 0) : [(d, x) | (Positive d, x) <- xs]
            s' = sRefine maxDT s
        in conjoin
             [ counterexample "a step over the bound" (all ((<= maxDT) . fst) (drop 1 s'))
             , counterexample "total time changed"
                 (abs (sum (map fst s') - sum (map fst s)) <= 1e-9 * (1 + sum (map fst s)))
             , map head (group (samples s')) === map head (group (samples s)) ]
    it "sRefine makes no step over the bound, even by a rounding (2.3 by 0.1 left a last step of 0.10000000000000009)" $ do
      let s' = sRefine 0.1 [(0, 'a'), (2.3, 'b')]
      filter ((> 0.1) . fst) (drop 1 s') `shouldBe` []
      map snd s' `shouldBe` 'a' : replicate (length s' - 1) 'b'
      abs (sum (map fst s') - 2.3) `shouldSatisfy` (<= 1e-12)
    it "sMerge takes times within timeSlack of each other as one (it left a step of 5.6e-17 between them)" $ do
      let merged = sMerge (+) [(0, 1), (0.1, 1), (0.1, 1), (0.1, 1)] [(0, 10), (0.3, 10 :: Int)]
      map snd merged `shouldBe` [11, 1, 1, 11]
      map snd (sMerge (+) [(0, 1), (0.3, 1)] [(0, 10), (0.3 + 1e-6, 10 :: Int)]) `shouldBe` [11, 1, 10]
      map snd (sMerge (+) [(0, 1), (0.3, 1)] [(0, 10), (0.2, 10), (0.2, 10 :: Int)]) `shouldBe` [11, 10, 1, 10]
      -- (a merged pair is at the earlier of its two times, so that a later
      -- sample of either stream, within the slack too, is never before it:
      -- the steps were -3e-13 and -1e-10 when the pair took the first's)
      sMerge (+) [(0, 1), (5e-13, 1)] [(0, 10), (1e-13, 10), (1e-13, 10 :: Int)] `shouldBe` [(0, 11), (1e-13, 11), (1e-13, 10)]
      map fst (sMerge (+) [(0, 1), (0.3, 1)] [(0, 10), (0.3 - 2e-10, 10), (1e-10, 10 :: Int)]) `shouldSatisfy` all (>= 0)
    it "sMerge's steps are never negative, and its samples are both streams' (property)" $
      property $ \(xs :: [(NonNegative Double, Int)]) (ys :: [(NonNegative Double, Int)]) ->
        let tiny (NonNegative d, v) = (d * 1e-9, v)   -- (steps near the slack)
            s1 = (0, 0) : map tiny xs
            s2 = (0, 0) : map tiny ys
            m  = sMerge (+) s1 s2
        in conjoin [ counterexample "a negative step" (all ((>= 0) . fst) m)
                   , counterexample "a sample lost" (sum (map snd m) === sum (map snd s1) + sum (map snd s2)) ]
    it "sClipBeforeTime of an infinite time keeps the last sample only (it kept them all)" $ do
      let s = zip (0 : repeat 0.1) "abcdefg"
      sClipBeforeTime (1 / 0) s `shouldBe` [(0, 'g')]
      sClipBeforeTime (-1 / 0) s `shouldBe` s
    it "sRefine refuses to cut one step into more samples than memory holds (fixed)" $ do
      evaluate (length (sRefine 1e-300 [(0, 'a'), (1e300, 'b')])) `shouldThrow` anyErrorCall
      length (sRefine 0.25 [(0, 'a'), (1, 'b')]) `shouldBe` 5
    it "sRefine refuses a longest step that is not a positive number (it left the stream as it was)" $
      mapM_ (\m -> evaluate (length (sRefine m [(0, 'a'), (1, 'b')])) `shouldThrow`
                     errorCall ("AFRP.Test.Stream.sRefine: the longest time step must be a number > 0, got " ++ show m))
            [0, -1, 0 / 0]
    it "sConcat, sClipAfterTime and sClipBeforeTime refuse a step or time no run has (NaN, a negative step)" $ do
      let s = [(0, 'a'), (1, 'b')]
      evaluate (length (sConcat s (-1) s)) `shouldThrow`
        errorCall "AFRP.Test.Stream.sConcat: the time step must be a number >= 0, got -1.0"
      evaluate (length (sConcat s (0 / 0) s)) `shouldThrow` anyErrorCall
      evaluate (length (sClipAfterTime (0 / 0) s)) `shouldThrow` errorCall "AFRP.Test.Stream.sClipAfterTime: the time is NaN"
      evaluate (length (sClipBeforeTime (0 / 0) s)) `shouldThrow` errorCall "AFRP.Test.Stream.sClipBeforeTime: the time is NaN"
      map fst (sConcat s 0 s) `shouldBe` [0, 1, 0, 1]
    it "sMerge samples at every time of either stream (fixed)" $
      sMerge (+) [(0, 1), (1, 2)] [(0, 10), (0.5, 20), (0.5, 30 :: Int)]
        `shouldBe` [(0, 11), (0.5, 20), (0.5, 32)]
