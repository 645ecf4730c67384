-- | The chain node ("AFRP.Internal.Chain", issue 19): a run of integrals,
-- delays and functions before integrals at 'Double' is stepped as one
-- node, and must give the very numbers (bit for bit) the nodes give one by
-- one, with the same laziness. (Its runs of sums are
-- "AFRP.Chain.SumsSpec"'s, its delays among them
-- "AFRP.Chain.RegroupSpec"'s.)
module AFRP.ChainSpec (spec) where

import           Control.Arrow     (arr, loop, second, (&&&), (>>>))
import           Control.Exception (evaluate)
import           Test.Hspec
import           Test.QuickCheck   (forAll, listOf1, arbitrary, choose, property)

import           AFRP.Basic        (identity, localTime, (-->))
import           AFRP.ChainFixture
import           AFRP.Delay        (iPre)
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (SF, isStepSF, stepSF)
import           TestUtil          (genSamples, runDt, runSamples, withoutHanging)

spec :: Spec
spec = do
  describe "a chain of integrals built at run time" $ do
    it "is one node after its first step (fixed)" $ do
      let sf0 = foldr1 (>>>) (replicate 10 integral) :: SF Double Double
          (sf1, _) = stepSF sf0 0 1
          (sf2, _) = stepSF sf1 0.1 2
      isStepSF sf0 `shouldBe` False
      isStepSF sf2 `shouldBe` True
    it "takes the previous input of an integral behind a replaced first output from the integral (fixed)" $
      -- the first integral outputs 5, 1, 3, 6; the second 0, 5, 6, 9; the
      -- third sums twice those: 0, 0, 10, 22
      runDt 1 ((5 --> integral) >>> integral >>> arr (* 2) >>> integral :: SF Double Double) [1, 2, 3, 4]
        `shouldBe` [0, 0, 10, 22]
    it "gives the numbers of the integrals stepped one by one, bit for bit (fixed)" $
      runDt 0.01 (chainOf (replicate 10 SIntegral)) [0 .. 300]
        `shouldSatisfy` sameBits (runDt 0.01 (opaqueChainOf (replicate 10 SIntegral)) [0 .. 300])
  describe "a random chain of integrals, delays and functions" $ do
    it "gives the numbers of its stages stepped one by one, bit for bit (property)" $
      property $ forAll (listOf1 arbitrary) $ \stages ->
        forAll (genSamples (choose (-10, 10))) $ \samples ->
          sameBits (runSamples (chainOf stages) samples)
                   (runSamples (opaqueChainOf stages) samples)
    it "does the same between functions and after a stateful node (property)" $
      property $ forAll (listOf1 arbitrary) $ \stages ->
        forAll (genSamples (choose (-10, 10))) $ \samples ->
          let wrap c = localTime &&& identity >>> arr (\(t, x) -> t + x) >>> c >>> arr (* 3)
          in sameBits (runSamples (wrap (chainOf stages)) samples)
                      (runSamples (wrap (opaqueChainOf stages)) samples)
  describe "a chain's laziness (fixed)" $ do
    it "never evaluates its current input: the last input may be an error" $ do
      let chain = foldr1 (>>>) [integral, arr (* 2), integral, iPre 0, integral, integral] :: SF Double Double
          -- (embed evaluates each input sample: the error is made lazily)
          late x = if x > 20 then error "evaluated too early" else x
          ins   = map fromIntegral [1 .. 21 :: Int]
      s <- evaluate (sum (runDt 0.1 (arr late >>> chain) ins))
      s `shouldSatisfy` (not . isNaN)
    it "applies a function before an integral no earlier than the integral needs it" $ do
      -- the first integral outputs 0, 1, ..., 9; f of its last output is
      -- never needed
      let f :: Double -> Double
          f x = if x >= 9 then error "f applied too early" else 2 * x
          chain = foldr1 (>>>) [integral, arr f, integral, integral]
      outs <- evaluate (runDt 1 chain (replicate 10 1))
      s <- evaluate (sum outs)
      (length outs, isNaN s) `shouldBe` (10, False)
    it "closes a loop whose fed-back value it does not need at the instant" $
      withoutHanging (runDt 0.1 (loop (second (foldr1 (>>>) [integral, arr (* 2), integral, iPre 1])
                               >>> arr (\(a, _) -> (a, a)))) inputs)
             inputs
    it "feeds back through its own delay as the nodes one by one do" $
      withoutHanging (runDt 0.1 (loop (arr (uncurry (+)) >>> foldr1 (>>>) [integral, integral, iPre 0]
                               >>> arr (\y -> (y, y)))) inputs)
             (runDt 0.1 (loop (arr (uncurry (+)) >>> foldr1 (>>>) (map opaque [integral, integral, iPre 0])
                               >>> arr (\y -> (y, y)))) inputs)
