module AFRP.NoiseSpec (spec) where

import           Control.Exception (evaluate)
import           Data.Bits         (shiftR, xor)
import           Data.Word         (Word64)
import           Test.Hspec

import           AFRP.Event        (Event (..), isEvent)
import           AFRP.Noise
import           TestUtil

-- A small deterministic generator (SplitMix-style mixing of a counter).
newtype Gen = Gen Word64

nextWord :: Gen -> (Word64, Gen)
nextWord (Gen s) =
  let s' = s + 0x9E3779B97F4A7C15
      z1 = (s' `xor` (s' `shiftR` 30)) * 0xBF58476D1CE4E5B9
      z2 = (z1 `xor` (z1 `shiftR` 27)) * 0x94D049BB133111EB
  in (z2 `xor` (z2 `shiftR` 31), Gen s')

uniform :: Gen -> (Double, Gen)
uniform g = let (w, g') = nextWord g in (fromIntegral (w `shiftR` 11) / 9007199254740992, g')

counter :: Int -> (Int, Int)
counter n = (n, n + 1)

spec :: Spec
spec = do
  describe "noiseWith" $ do
    it "draws one value per sample, the first at time 0" $
      runDt 0.1 (noiseWith counter 7) (replicate 4 ()) `shouldBe` [7, 8, 9, 10]
    it "is reproducible from the generator state" $
      runDt 0.1 (noiseWith uniform (Gen 1)) (replicate 50 ())
        `shouldBe` runDt 0.3 (noiseWith uniform (Gen 1)) (replicate 50 ())
  describe "noiseRWith" $
    it "passes the range to the generator" $
      runDt 1 (noiseRWith (\(lo, hi) n -> (lo + n `mod` (hi - lo + 1), n + 1)) (10, 12) 0)
        (replicate 5 ()) `shouldBe` [10, 11, 12, 10, 11 :: Int]
  describe "occasionallyWith" $ do
    it "never fires at time 0, even with a draw of 0" $
      take 1 (runDt 1 (occasionallyWith (\g -> (0, g)) () 1 'x') (replicate 3 ()))
        `shouldBe` [NoEvent]
    it "fires when the draw is below 1 - exp (-dt / tAvg)" $
      -- dt = 1, tAvg = 1: threshold 1 - 1/e = 0.632
      runDt 1 (occasionallyWith (\rs -> case rs of { r : rest -> (r, rest); [] -> (1, []) }) [0.6, 0.7, 0.1] 1 'x') (replicate 4 ())
        `shouldBe` [NoEvent, Event 'x', NoEvent, Event 'x']
    it "has about dt / tAvg events per sample for a uniform generator" $ do
      let n = 20000 :: Int
          evs = runDt 0.01 (occasionallyWith uniform (Gen 3) 0.5 ()) (replicate (n + 1) ())
          hits = length (filter isEvent evs)
          expected = fromIntegral n * (1 - exp (-0.02)) :: Double
      fromIntegral hits `shouldSatisfy` (\h -> abs (h - expected) < 4 * sqrt expected)
    it "rejects a non-positive mean interval" $
      evaluate (occasionallyWith uniform (Gen 0) 0 ()) `shouldThrow` anyErrorCall
