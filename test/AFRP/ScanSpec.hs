module AFRP.ScanSpec (spec) where

import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Scan
import           TestUtil

-- | Reference semantics of 'sscanPrim' on lists: the held output and the
-- accumulator change only where the function gives 'Just'.
refScanPrim :: (c -> a -> Maybe (c, b)) -> c -> b -> [a] -> [b]
refScanPrim _ _ _ []       = []
refScanPrim f c b (a : as) = case f c a of
  Nothing       -> b  : refScanPrim f c b as
  Just (c', b') -> b' : refScanPrim f c' b' as

spec :: Spec
spec = do
  describe "sscan" $ do
    it "applies the function at time 0 too" $
      runDt 1 (sscan (+) 10) [1, 2, 3 :: Int] `shouldBe` [11, 13, 16]
    it "is scanl1 of the inputs after the seed, whatever the time steps (property)" $
      property $ forAll (genSamples (arbitrary :: Gen Int)) $ \samples ->
        runSamples (sscan (-) 7) samples === drop 1 (scanl (-) 7 (map snd samples))

  describe "sscanPrim" $ do
    it "holds the initial output until the function first gives Just" $
      runDt 1 (sscanPrim (\c a -> if a then Just (c + 1, c + 1) else Nothing) (0 :: Int) (-1))
        [False, False, True, False, True] `shouldBe` [-1, -1, 1, 1, 2]
    it "agrees with the list reference on random inputs (property)" $
      property $ forAll (genSamples (arbitrary :: Gen Int)) $ \samples ->
        let f c a | a > 0     = Just (c + a, show (c + a))
                  | otherwise = Nothing
        in runSamples (sscanPrim f (0 :: Int) "init") samples
             === refScanPrim f 0 "init" (map snd samples)
