{-# LANGUAGE DeriveFunctor #-}
-- | Tests for "AFRP.Internal.Collection": the strict steppers and 'parBL'
-- compute what the generic stepper ('stepperFor' at a collection with only
-- a 'Functor' instance, where no rule replaces it) computes, on random
-- inputs and time steps, as the module's note says.
module AFRP.CollectionSpec (spec) where

import           Control.Arrow            (arr, (&&&), (>>>))
import           Test.Hspec               hiding (after)
import           Test.QuickCheck

import           AFRP.Basic               (constant, localTime)
import           AFRP.EventSource         (after, edge)
import           AFRP.Integration         (integral)
import           AFRP.Internal.Collection (parBL)
import           AFRP.Internal.SF         (DTime, SF)
import           AFRP.Parallel            (par)
import           AFRP.Scan                (sscan)
import           AFRP.Switch              (kSwitch, switch)
import           TestUtil

-- | A list behind a newtype that derives nothing but 'Functor', so that
-- 'par' on it keeps the generic stepper.
newtype FList a = FList [a]
  deriving Functor

unF :: FList a -> [a]
unF (FList xs) = xs

-- | 'parB' on an 'FList': 'par broadcast', stepped by the generic stepper.
parBF :: [SF a b] -> SF a [b]
parBF sfs = par (\a -> fmap (\sf -> (a, sf))) (FList sfs) >>> arr unF

genInputs :: Gen [(DTime, Double)]
genInputs = genSamples (choose (-2, 2))

-- | A network built with 'parBL' and the same built with the generic
-- stepper give the same outputs.
sameWithEither :: (Eq b, Show b) => (([SF Double Double] -> SF Double [Double]) -> SF Double b) -> Property
sameWithEither build = forAll genInputs $ \samples ->
  runSamples (build parBL) samples === runSamples (build parBF) samples

-- | @parBL sfs@ and the generic stepper give the same outputs.
sameAsGeneric :: [SF Double Double] -> Property
sameAsGeneric sfs = sameWithEither ($ sfs)

spec :: Spec
spec = describe "parBL (parB on a list)" $ do
  it "is par broadcast on members of every kind (property)" $ property $
    sameAsGeneric [integral, localTime, sscan (+) 0 >>> arr (* 2), constant 7]
  it "is par broadcast, bit for bit, on a bank of integrals (property)" $ property $
    sameAsGeneric (replicate 5 integral)
  it "is par broadcast on a bank whose members started apart (property)" $ property $
    -- an integral frozen at t >= 1 and carried into the collection twice,
    -- beside a fresh one: one bank of two sums (the outputs weighted, as
    -- the switch's continuation gives one number)
    sameWithEither $ \parB' ->
      kSwitch integral (localTime >>> arr (>= 1) >>> edge)
              (\frozen () -> parB' [frozen, integral, frozen]
                               >>> arr (sum . zipWith (*) [1, 1000, 1000000]))
  it "is par broadcast when a member becomes an integral only through a switch (property)" $ property $
    -- not an integral at the first step: no bank, ever
    sameAsGeneric [switch (localTime &&& after 0.5 ()) (const integral), integral]
  it "is par broadcast on no members" $
    runDt 1 (parBL []) [1, 2 :: Double] `shouldBe` ([[], []] :: [[Double]])
