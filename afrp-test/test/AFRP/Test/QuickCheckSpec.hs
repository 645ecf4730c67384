module AFRP.Test.QuickCheckSpec (spec) where

import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Test.QuickCheck
import           AFRP.Test.Stream

-- Every time step after the first is positive, the first is 0.
wellFormed :: SignalSampleStream a -> Bool
wellFormed []             = False
wellFormed ((dt0, _) : s) = dt0 == 0 && all ((> 0) . fst) s

spec :: Spec
spec = do
  describe "generators (property)" $ do
    it "generateStream keeps the time steps inside the range" $
      forAll (generateStream DistRandom (Just 0.1, Just 0.3) Nothing) $ \s ->
        wellFormed (s :: SignalSampleStream Int) && all (\(dt, _) -> dt >= 0.1 && dt <= 0.3) (drop 1 s)
    it "DistNormal keeps the time steps inside the range" $
      forAll (generateStream (DistNormal (0.2, 0.1)) (Just 0.05, Just 0.5) (Just (Left 50))) $ \s ->
        length (s :: SignalSampleStream ()) == 51 && all (\(dt, _) -> dt >= 0.05 && dt <= 0.5) (drop 1 s)
    it "DistConstant uses one time step" $
      forAll (generateStream DistConstant (Just 0.01, Just 1) Nothing) $ \s ->
        length (nubDts (s :: SignalSampleStream Bool)) <= 1
    it "a length in time reaches that time" $
      forAll (generateStream DistRandom (Nothing, Just 0.5) (Just (Right 3))) $ \s ->
        wellFormed (s :: SignalSampleStream ()) && last (sampleTimes s) >= 3
    it "fixedDelayStreamWith gives each sample the value at its time" $
      forAll (fixedDelayStreamWith (* 2) 0.25) $ \s ->
        all (\(t, x) -> abs (x - 2 * t) < 1e-9) (zip (sampleTimes s) (samples (s :: SignalSampleStream Double)))
    it "uniDistStreamMaxDT streams are well formed" $
      forAll (uniDistStreamMaxDT 0.5) $ \s ->
        wellFormed (s :: SignalSampleStream ()) && all ((<= 0.5) . fst) s
  describe "shrinkStream (property)" $ do
    it "offers only well-formed streams, each smaller than the original" $
      forAll (generateStream DistRandom (Nothing, Just 2) (Just (Left 6))) $ \s ->
        all (\s' -> wellFormed s' && smaller s' s) (shrinkStream (s :: SignalSampleStream Int))
    it "keeps the other samples' times when it removes one" $
      let s = [(0, 'a'), (0.5, 'b'), (0.25, 'c'), (1, 'd')] :: SignalSampleStream Char
      in shrinkStreamWith (Nothing, Nothing) (const []) s `shouldContain` [[(0, 'a'), (0.75, 'c'), (1, 'd')]]
    it "rounds time steps, never to 0 nor out of the range" $
      shrinkStreamWith (Just 0.1, Nothing) (const []) [(0, ()), (0.137, ())]
        `shouldBe` [[(0, ())], [(0, ()), (0.1, ())], [(0, ()), (0.14, ())]]
  where
    nubDts s = foldr (\dt acc -> if dt `elem` acc then acc else dt : acc) [] (map fst (drop 1 s))
    -- Fewer samples, or as many with rounder steps or simpler values: the
    -- total of samples, decimals and value sizes goes down.
    smaller s' s = measure s' < measure s
    measure s = (length s, sum (map (decimals . fst) s) + sum (map (valueSize . snd) s))
    valueSize x = 2 * abs x + (if x < 0 then 1 else 0)
    decimals :: Double -> Int
    decimals x = head ([k | k <- [0 .. 8], fromIntegral (round (x * 10 ^ k) :: Integer) / 10 ^ k == x] ++ [9])
