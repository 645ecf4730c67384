-- | The nodes that stand for several ("AFRP.Internal.Node.Fuse"): a pair
-- of integrals at 'Double' stepped in place, and with the functions
-- around it one node, checked against the integrals stepped one by one,
-- bit for bit, with the same laziness. (The chain node is
-- "AFRP.ChainSpec"'s.)
module AFRP.Node.FuseSpec (spec) where

import           Control.Arrow     (arr, loop, second, (&&&), (***), (>>>))
import           Control.Exception (evaluate)
import           Test.Hspec
import           Test.QuickCheck   (choose, forAll, property)

import           AFRP.Basic        (identity, localTime)
import           AFRP.ChainFixture (inputs, opaque, sameBits)
import           AFRP.Delay        (iPre)
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (SF, isStepSF, stepSF)
import           TestUtil          (genSamples, runDt, runSamples, withoutHanging)

spec :: Spec
spec = do
  describe "integral *** integral at Double, stepped in place" $ do
    it "gives the numbers of the two integrals stepped one by one, bit for bit (property)" $
      property $ forAll (genSamples (choose (-10, 10))) $ \samples ->
        let pairUp = arr (\x -> (x, sin x)) >>> (integral *** integral) >>> arr (\(u, v) -> u - 2 * v)
            opaquePair = arr (\x -> (x, sin x)) >>> (opaque integral *** opaque integral)
                         >>> arr (\(u, v) -> u - 2 * v)
        in sameBits (runSamples pairUp samples) (runSamples opaquePair samples)
    -- (the pair is made by a function that looks at the value fed back:
    -- taking it apart at once would demand that value)
    it "does not evaluate its input pair: it closes a loop (fixed)" $
      withoutHanging (runDt 0.1 (loop (arr (\(a, c) -> (a, c)) >>> second (arr (\c -> if c > 0 then (c, c) else (c, negate c)) >>> (integral *** integral))
                               >>> arr (\(a, _) -> (a, a)))) inputs)
             inputs
  describe "arr p >>> (integral *** integral) at Double, one node" $ do
    let p x = (x * 2, cos x)
        q (u, v) = u - 3 * v
        fused = arr p >>> (integral *** integral) >>> arr q
        opaqueFused = opaque (arr p) >>> (opaque integral *** opaque integral) >>> opaque (arr q)
    it "is one node after its second step (fixed)" $ do
      let sf0 = arr p >>> (integral *** integral) :: SF Double (Double, Double)
          (sf1, _) = stepSF sf0 0 1
          (sf2, _) = stepSF sf1 0.1 2
          (sf3, _) = stepSF sf2 0.1 3
      map isStepSF [sf0, sf1, sf2, sf3] `shouldBe` [False, False, True, True]
    it "takes the function behind it into the node (fixed)" $ do
      let (sf1, _) = stepSF fused 0 1
          (sf2, _) = stepSF sf1 0.1 2
      map isStepSF [fused, sf1, sf2] `shouldBe` [False, False, True]
    it "gives the numbers of its stages with a function and a stateful node behind it (property)" $
      property $ forAll (genSamples (choose (-10, 10))) $ \samples ->
        let behind sf = sf >>> iPre 1 >>> arr (* 2)
        in sameBits (runSamples (behind fused) samples) (runSamples (behind opaqueFused) samples)
    it "gives the numbers of its stages stepped one by one, bit for bit (property)" $
      property $ forAll (genSamples (choose (-10, 10))) $ \samples ->
        sameBits (runSamples fused samples) (runSamples opaqueFused samples)
    it "does the same after a stateful node and in a loop through a delay (property)" $
      property $ forAll (genSamples (choose (-10, 10))) $ \samples ->
        let wrap sf = loop (arr (\(x, c) -> x + c) >>> (localTime &&& identity)
                            >>> arr (\(t, x) -> t + x) >>> sf >>> arr (\y -> (y, y))
                            >>> second (iPre 0))
        in sameBits (runSamples (wrap fused) samples) (runSamples (wrap opaqueFused) samples)
    it "never evaluates its current input: the last input may be an error (fixed)" $ do
      let late x = if x > 20 then error "evaluated too early" else x
          ins   = map fromIntegral [1 .. 21 :: Int]
      s <- evaluate (sum (runDt 0.1 (arr late >>> fused) ins))
      s `shouldSatisfy` (not . isNaN)
    it "applies p no earlier than the sums need it (fixed)" $ do
      let p' :: Double -> (Double, Double)
          p' x = if x >= 9 then error "p applied too early" else (x, 2 * x)
      outs <- evaluate (runDt 1 (integral >>> arr p' >>> (integral *** integral) >>> arr q)
                                (replicate 10 1))
      s <- evaluate (sum outs)
      (length outs, isNaN s) `shouldBe` (10, False)
    it "closes a loop whose fed-back value it does not need at the instant (fixed)" $
      withoutHanging (runDt 0.1 (loop (second (arr (\c -> (c, c + 1)) >>> (integral *** integral)
                                       >>> arr (uncurry (+)))
                               >>> arr (\(a, _) -> (a, a)))) inputs)
             inputs
