{-# LANGUAGE DeriveFunctor #-}
-- | "AFRP.Parallel" over collections that have only a 'Functor' instance,
-- as Yampa allows: each combinator is checked against the same combinator
-- on a plain list (the specialised, strict path), on random inputs and
-- time steps.
module AFRP.ParallelFunctorSpec (spec) where

import           Control.Arrow    (arr, (>>>))
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Basic       (constant, localTime)
import           AFRP.Event       (Event (..))
import           AFRP.EventSource (edge)
import           AFRP.Integration (integral)
import           AFRP.Internal.SF (DTime, SF)
import           AFRP.Parallel
import           AFRP.Scan        (sscan)
import           TestUtil

-- | A list behind a newtype that derives nothing but 'Functor': no
-- 'Foldable', no 'Traversable'.
newtype FList a = FList [a]
  deriving Functor

unF :: FList a -> [a]
unF (FList xs) = xs

-- | The members used throughout: stateful, time-dependent, and different.
members :: [SF Double Double]
members = [integral, localTime, sscan (+) 0 >>> arr (* 2), constant 7]

-- | Route the i-th member the input times i.
scaled :: Double -> [sf] -> [(Double, sf)]
scaled x = zipWith (\i sf -> (x * i, sf)) [1 ..]

scaledF :: Double -> FList sf -> FList (Double, sf)
scaledF x (FList sfs) = FList (scaled x sfs)

-- | Fires when the input first exceeds the threshold.
above :: Double -> SF (Double, col) (Event ())
above th = arr ((> th) . fst) >>> edge

genInputs :: Gen [(DTime, Double)]
genInputs = genSamples (choose (-2, 2))

sameAsList :: SF Double [Double] -> SF Double (FList Double) -> Property
sameAsList viaList viaF = forAll genInputs $ \samples ->
  map unF (runSamples viaF samples) === runSamples viaList samples

spec :: Spec
spec = describe "collections with only a Functor instance" $ do
  it "par routes and steps every member as on a list (property)" $ property $
    sameAsList (par scaled members) (par scaledF (FList members))
  it "parB broadcasts as on a list (property)" $ property $
    sameAsList (parB members) (parB (FList members))
  it "pSwitchB switches at the same instant as on a list (property)" $ property $
    sameAsList (pSwitchB members (above 1) (\sfs () -> parB (reverse sfs)))
               (pSwitchB (FList members) (above 1) (\(FList sfs) () -> parB (FList (reverse sfs))))
  it "dpSwitch switches at the same instant as on a list (property)" $ property $
    sameAsList (dpSwitch scaled members (above 1) (\sfs () -> parB (drop 1 sfs)))
               (dpSwitch scaledF (FList members) (above 1) (\(FList sfs) () -> parB (FList (drop 1 sfs))))
  it "rpSwitchB and drpSwitchB apply the same edits as on a list (property)" $ property $
    let edits = arr (\x -> (x, if x > 1.5 then Event (localTime :) else NoEvent))
        editsF = arr (\x -> (x, if x > 1.5 then Event (\(FList sfs) -> FList (localTime : sfs)) else NoEvent))
    in sameAsList (edits >>> rpSwitchB members) (editsF >>> rpSwitchB (FList members))
       .&&. sameAsList (edits >>> drpSwitchB members) (editsF >>> drpSwitchB (FList members))
  it "rpSwitch and drpSwitch route as on a list (property)" $ property $
    let edits = arr (\x -> (x, if x < -1.5 then Event (drop 1) else NoEvent))
        editsF = arr (\x -> (x, if x < -1.5 then Event (\(FList sfs) -> FList (drop 1 sfs)) else NoEvent))
    in sameAsList (edits >>> rpSwitch scaled members) (editsF >>> rpSwitch scaledF (FList members))
       .&&. sameAsList (edits >>> drpSwitch scaled members) (editsF >>> drpSwitch scaledF (FList members))
  it "a member is started afresh at a switch on a Functor collection" $
    map unF (runDt 1 (pSwitchB (FList [localTime]) (above 0) (\_ () -> parB (FList [localTime])))
                     [0, 0, 1, 1])
      `shouldBe` [[0], [1], [0], [1]]
