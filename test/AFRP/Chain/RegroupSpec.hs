-- | A chain's stages regrouped into runs ("AFRP.Internal.Chain.Regroup"):
-- the integrals behind a first-step stage after the chain's first step,
-- and the delays fed by integrals, stages of the runs from its second
-- step, checked against the stages stepped one by one, bit for bit, with
-- the same laziness.
module AFRP.Chain.RegroupSpec (spec) where

import           Control.Arrow               (arr, (>>>))
import           Control.Exception           (evaluate)
import           Test.Hspec

import           AFRP.Basic                  ((-->))
import           AFRP.ChainFixture
import           AFRP.Delay                  (iPre)
import           AFRP.Integration            (integral)
import           AFRP.Internal.Chain.Regroup (consInt, hasDelayI)
import           AFRP.Internal.Chain.Stage   (AfterI (..), AfterL (..))
import           AFRP.Internal.Chain.Sums    (sumsFromList, sumsList)
import           AFRP.Internal.SF            (SF, stepSF)
import           TestUtil                    (runDt)

-- | The stages after an integral, one word each (a run with its sums).
shape :: AfterI -> [String]
shape c = case c of
  IEnd           -> []
  IInt x r       -> ("int " ++ show x) : shape r
  IIntF _ x r    -> ("intF " ++ show x) : shape r
  IPre _ _       -> ["pre"]
  IIntS x _ r    -> ("intS " ++ show x) : shape r
  IIntFS _ x _ r -> ("intFS " ++ show x) : shape r
  IRun s r       -> ("run " ++ show (sumsList s)) : shape r
  IRunF s _ r    -> ("runF " ++ show (sumsList s)) : shape r
  IPreI x r      -> ("preI " ++ show x) : shape r

spec :: Spec
spec = do
  describe "after the chain's first step (fixed)" $ do
    it "makes an integral and the integrals in series behind it one run, three or more" $ do
      shape (consInt Nothing 1 (IInt 2 (IInt 3 IEnd))) `shouldBe` ["run [1.0,2.0,3.0]"]
      shape (consInt (Just negate) 1 (IInt 2 (IInt 3 IEnd))) `shouldBe` ["runF [1.0,2.0,3.0]"]
      shape (consInt Nothing 1 (IRun (sumsFromList [2, 3]) (IInt 4 IEnd))) `shouldBe` ["run [1.0,2.0,3.0,4.0]"]
    it "keeps fewer as cells of their own, and leaves a delay for the second step" $ do
      shape (consInt Nothing 1 (IInt 2 IEnd)) `shouldBe` ["int 1.0", "int 2.0"]
      shape (consInt Nothing 1 (IInt 2 (IPre 0 LEnd))) `shouldBe` ["int 1.0", "int 2.0", "pre"]
    it "finds the delays fed by integrals, which the second step settles" $
      map hasDelayI [ LInt 0 0 (IInt 1 IEnd), LPre 0 (LInt 0 0 IEnd), LInt 0 0 (IInt 1 (IPre 0 LEnd))
                    , LPre 0 (LPre 0 LEnd) ]
        `shouldBe` [False, False, True, False]
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
