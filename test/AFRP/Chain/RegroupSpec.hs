-- | A chain's stages regrouped into runs ("AFRP.Internal.Chain.Regroup"):
-- the delays fed by integrals, stages of the runs from the chain's second
-- step, checked against the stages stepped one by one, bit for bit, with
-- the same laziness.
module AFRP.Chain.RegroupSpec (spec) where

import           Control.Arrow     (arr, (>>>))
import           Control.Exception (evaluate)
import           Test.Hspec

import           AFRP.Basic        ((-->))
import           AFRP.ChainFixture
import           AFRP.Delay        (iPre)
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (SF, stepSF)
import           TestUtil          (runDt)

spec :: Spec
spec = do
  describe "delays fed by integrals, stages of the runs from the chain's second step" $ do
    it "give the numbers of the stages stepped one by one, in runs of every length, bit for bit (fixed)" $
      let stages k = [SIntegral, SPre 1] ++ concat (replicate k [SIntegral, SPre 2.5, SArr 1, SIntegral, SIntegral])
                     ++ [SPre 0]
      in mapM_ (\k -> runDt 0.05 (chainOf (stages k)) [0 .. 60]
                         `shouldSatisfy` sameBits (runDt 0.05 (opaqueChainOf (stages k)) [0 .. 60]))
               [0 .. 8]
    it "do the same with a delay behind a delay, and a chain ending in one (fixed)" $
      let stages k = [SIntegral] ++ replicate k SIntegral ++ [SPre 3, SPre (-1), SIntegral, SPre 2, SIntegral, SIntegral, SPre 0.5]
      in mapM_ (\k -> runDt 0.1 (chainOf (stages k)) [0 .. 40]
                         `shouldSatisfy` sameBits (runDt 0.1 (opaqueChainOf (stages k)) [0 .. 40]))
               [0 .. 4]
    it "are stepped from a kept state as often as asked, the same each time (fixed)" $ do
      let stages = [SIntegral, SPre 1, SIntegral, SArr 0, SIntegral, SPre 0, SIntegral]
          upTo sf = foldl (\(s, _) (dt, x) -> stepSF s dt x) (sf, 0) [(0, 1), (0.5, 2), (0.5, 3), (0.5, -1)]
          (kept, _) = upTo (chainOf stages)
          (keptRef, _) = upTo (opaqueChainOf stages)
          from s = runSamples' s [(0.25, 4), (0.5, 1), (0.5, 7)]
      sameBits (from kept) (from keptRef) `shouldBe` True
      _ <- evaluate (sum (from (fst (stepSF kept 2 100))))
      sameBits (from kept) (from keptRef) `shouldBe` True
    it "never evaluate a value the chain did not store itself: an output of a stage before the chain formed (fixed)" $ do
      -- the delay holds the replaced first output, an error nobody
      -- needs, when the chain forms; it outputs it at the chain's first
      -- step, to a function that ignores it
      let chain = (error "evaluated too early" --> integral) >>> iPre 0 >>> arr (const 1)
                    >>> integral >>> integral >>> iPre 0 >>> integral :: SF Double Double
      s <- evaluate (sum (runDt 0.1 chain (map fromIntegral [1 .. 12 :: Int])))
      s `shouldSatisfy` (not . isNaN)
