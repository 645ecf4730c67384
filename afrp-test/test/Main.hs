-- | The afrp-test kit's own tests: the kit checked on properties of the
-- afrp library it is for.
module Main (main) where

import           Test.Hspec

import qualified AFRP.Test.LTLSpec
import qualified AFRP.Test.PropertiesSpec
import qualified AFRP.Test.QuickCheckSpec
import qualified AFRP.Test.StreamSpec
import qualified AFrobRobotSim.TestSpec

main :: IO ()
main = hspec $ do
  describe "AFRP.Test.Stream" AFRP.Test.StreamSpec.spec
  describe "AFRP.Test.LTL" AFRP.Test.LTLSpec.spec
  describe "AFRP.Test.QuickCheck" AFRP.Test.QuickCheckSpec.spec
  describe "Properties of afrp, written with the kit" AFRP.Test.PropertiesSpec.spec
  describe "AFrobRobotSim.Test" AFrobRobotSim.TestSpec.spec
