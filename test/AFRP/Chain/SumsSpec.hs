-- | A run of integrals in a chain as one array of sums
-- ("AFRP.Internal.Chain.Sums"): its loops checked against lists, and the
-- chains that hold runs against their stages stepped one by one, bit for
-- bit.
module AFRP.Chain.SumsSpec (spec) where

import           Control.Arrow            ((>>>))
import           Control.Exception        (evaluate)
import           Test.Hspec
import           Test.QuickCheck          (Gen, choose, elements, forAll, listOf1, property, vectorOf)

import           AFRP.ChainFixture
import           AFRP.Internal.Chain.Sums (Funs (..), kindsList, lastSum, packKinds, stepSums, stepSumsF,
                                          sumsFromList, sumsList)
import           AFRP.Integration         (integral)
import           AFRP.Internal.SF         (SF, stepSF)
import           TestUtil                 (runDt)

-- | What a stage of a run is, for the reference.
data Kind = KNone | KSome Int | KPre
  deriving Show

kindFuns :: [Double -> Double]
kindFuns = [(* 2), negate, sin]

toFuns :: [Kind] -> Funs
toFuns = foldr cons FNil
  where
    cons k r = case k of
      KNone   -> FNone r
      KSome i -> FSome (kindFuns !! i) r
      KPre    -> FPre r

-- | A run's step as the stages take it one by one: each stage's new
-- output from its old one and its predecessor's old one.
refStep :: Double -> Double -> [Double] -> [Kind] -> [Double]
refStep dt old ss ks = zipWith3 stage ss (old : ss) ks
  where
    stage s p k = case k of
      KNone   -> s + dt * p
      KSome i -> s + dt * (kindFuns !! i) p
      KPre    -> p

-- | The stages of a list of 'Funs', each function applied to a probe.
describeFuns :: Funs -> [(Int, Double)]
describeFuns fs = case fs of
  FNil      -> []
  FNone r   -> (0, 0) : describeFuns r
  FSome f r -> (1, f 0.75) : describeFuns r
  FPre r    -> (2, 0) : describeFuns r

genSums :: Gen [Double]
genSums = listOf1 (choose (-100, 100))

genKinds :: Int -> Gen [Kind]
genKinds n = vectorOf n (elements ([KNone, KPre] ++ map KSome [0 .. length kindFuns - 1]))

spec :: Spec
spec = do
  describe "the array of sums, against lists" $ do
    it "holds the sums it was made of, in order, the last as the run's output (property)" $
      property $ forAll genSums $ \ss ->
        sameBits (sumsList (sumsFromList ss)) ss && sameBits [lastSum (sumsFromList ss)] [last ss]
    it "steps a run of integrals as the integrals one by one, in a new array (property)" $
      property $ forAll genSums $ \ss -> forAll (choose (0, 1)) $ \dt -> forAll (choose (-10, 10)) $ \old ->
        let kept = sumsFromList ss
            stepped = stepSums dt old kept
        in sameBits (sumsList stepped) (refStep dt old ss (map (const KNone) ss))
           && sameBits (sumsList kept) ss
    it "steps a run with functions and delays as its stages one by one, in a new array (property)" $
      property $ forAll genSums $ \ss -> forAll (genKinds (length ss)) $ \ks ->
        forAll (choose (0, 1)) $ \dt -> forAll (choose (-10, 10)) $ \old ->
          let kept = sumsFromList ss
              stepped = stepSumsF dt old kept (packKinds (toFuns ks))
          in sameBits (sumsList stepped) (refStep dt old ss ks) && sameBits (sumsList kept) ss
    it "gives back the stages it packed, in order (property)" $
      property $ forAll genSums $ \ss -> forAll (genKinds (length ss)) $ \ks ->
        describeFuns (kindsList (packKinds (toFuns ks))) == describeFuns (toFuns ks)
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
