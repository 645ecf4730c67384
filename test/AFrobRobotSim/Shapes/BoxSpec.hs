-- | Hand-computed cases for "AFrobRobotSim.Shapes.Box".
module AFrobRobotSim.Shapes.BoxSpec (spec) where

import Test.Hspec

import AFRP.Geometry (Point2 (..))
import AFrobRobotSim.Shapes.Box

spec :: Spec
spec = do
  describe "boxAround / boxCentre" $ do
    it "builds a box from centre, width and height" $
      boxAround (Point2 1 2) 4 2 `shouldBe` Box (-1) 1 3 3
    it "uses the absolute values of negative sizes" $
      boxAround (Point2 1 2) (-4) (-2) `shouldBe` Box (-1) 1 3 3
    it "boxCentre inverts boxAround" $
      boxCentre (boxAround (Point2 1 2) 4 2) `shouldBe` Point2 1 2
    it "a zero-size box is a point" $
      boxAround (Point2 1 2) 0 0 `shouldBe` Box 1 2 1 2

