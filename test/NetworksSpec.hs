-- | The benchmark networks compute exactly what their hand-written
-- baselines compute (within rounding where floating-point sums are
-- associated differently).
module NetworksSpec (spec) where

import           Test.Hspec

import           Networks
import           TestUtil  (approxWith)

spec :: Spec
spec =
  mapM_ (\nw -> it (nwName nw ++ " equals its baseline on 10^4 samples") $ do
           let ours = runNetwork (nwSF nw) 10000
               base = nwBaseline nw 10000
           length ours `shouldBe` length base
           let bad = [ (i, o, b) | (i, o, b) <- zip3 [0 :: Int ..] ours base
                                 , not (approxWith 1e-9 o b) ]
           take 3 bad `shouldBe` [])
        networks
