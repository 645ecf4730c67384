-- | A run of integrals in a chain as one array of sums
-- ("AFRP.Internal.Chain.Sums"): the chains that hold runs checked against
-- their stages stepped one by one, bit for bit.
module AFRP.Chain.SumsSpec (spec) where

import           Control.Arrow     ((>>>))
import           Control.Exception (evaluate)
import           Test.Hspec

import           AFRP.ChainFixture
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (SF, stepSF)
import           TestUtil          (runDt)

spec :: Spec
spec = do
  describe "a run of integrals in a chain (one array of sums)" $ do
    it "is stepped from a kept state as often as asked, the same each time: nothing is written in place (fixed)" $ do
      let sf0 = foldr1 (>>>) (replicate 6 integral) :: SF Double Double
          ref0 = foldr1 (>>>) (replicate 6 (opaque integral)) :: SF Double Double
          upTo sf = foldl (\(s, _) (dt, x) -> stepSF s dt x) (sf, 0) [(0, 1), (0.5, 2), (0.5, 3), (0.5, -1)]
          (kept, _) = upTo sf0
          (keptRef, _) = upTo ref0
          from s = runSamples' s [(0.25, 4), (0.5, 1), (0.5, 7)]
          first1 = from kept
          second1 = from kept
      sameBits first1 (from keptRef) `shouldBe` True
      sameBits second1 first1 `shouldBe` True
      -- and a branch with other inputs does not disturb the kept state
      _ <- evaluate (sum (from (fst (stepSF kept 2 100))))
      sameBits (from kept) (from keptRef) `shouldBe` True
    it "gives the numbers of runs of every length between other stages, bit for bit (fixed)" $
      let stages k = [SArr 3] ++ replicate k SIntegral ++ [SPre 2.5] ++ replicate k SIntegral ++ [SArr 1, SIntegral]
      in mapM_ (\k -> runDt 0.05 (chainOf (stages k)) [0 .. 60]
                         `shouldSatisfy` sameBits (runDt 0.05 (opaqueChainOf (stages k)) [0 .. 60]))
               [1 .. 12]
    it "does the same with functions between the integrals, in any mix, bit for bit (fixed)" $
      let withFs k = [SIntegral] ++ concat (replicate k [SArr (k `mod` 5), SIntegral, SIntegral]) ++ [SArr 4, SIntegral]
      in mapM_ (\k -> runDt 0.05 (chainOf (withFs k)) [0 .. 60]
                         `shouldSatisfy` sameBits (runDt 0.05 (opaqueChainOf (withFs k)) [0 .. 60]))
               [0 .. 8]
