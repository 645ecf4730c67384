-- | Hand-computed cases and brute-force properties for
-- "AFrobRobotSim.Shapes.Ray": ray casts against boxes and discs.
module AFrobRobotSim.Shapes.RaySpec (spec) where

import Test.Hspec
import Test.QuickCheck

import AFRP.Geometry (Point2 (..), Vector2 (..))
import AFrobRobotSim.Shapes.Box (Box (..), boxCentre)
import AFrobRobotSim.Shapes.Ray
import AFrobRobotSim.ShapesFixture

spec :: Spec
spec = do
  describe "rayBox" $ do
    -- x in [1, 3], y in [-1, 1]
    let b = Box 1 (-1) 3 1
        s = sqrt 0.5
    it "hits the near side of an axis-parallel ray" $
      rayBox (Point2 0 0) (Vector2 1 0) b `shouldHitAt` Just 1
    it "handles a -0.0 direction component" $ do
      rayBox (Point2 0 0) (Vector2 1 (-0.0)) b `shouldHitAt` Just 1
      rayBox (Point2 2 5) (Vector2 (-0.0) (-1)) b `shouldHitAt` Just 4
      rayBox (Point2 2 5) (Vector2 0 (-1)) b `shouldHitAt` Just 4
    it "misses when pointing away" $
      rayBox (Point2 0 0) (Vector2 (-1) 0) b `shouldBe` Nothing
    it "misses when parallel to and outside a slab" $ do
      rayBox (Point2 0 2) (Vector2 1 0) b `shouldBe` Nothing
      rayBox (Point2 0 2) (Vector2 1 (-0.0)) b `shouldBe` Nothing
      rayBox (Point2 4 0) (Vector2 0 1) b `shouldBe` Nothing
    it "hits when running along an edge" $
      rayBox (Point2 0 1) (Vector2 1 0) b `shouldHitAt` Just 1
    it "hits a corner exactly" $
      rayBox (Point2 0 (-2)) (Vector2 s s) b `shouldHitAt` Just (sqrt 2)
    it "hits the bottom side obliquely" $
      rayBox (Point2 0 (-2.5)) (Vector2 s s) b `shouldHitAt` Just (1.5 * sqrt 2)
    it "misses obliquely" $ do
      rayBox (Point2 (-1) 0) (Vector2 (1 / sqrt 5) (2 / sqrt 5)) b
        `shouldBe` Nothing
      rayBox (Point2 0 2) (Vector2 s s) b `shouldBe` Nothing
    it "returns Just 0 from inside or on the boundary" $ do
      rayBox (Point2 2 0) (Vector2 s (-s)) b `shouldBe` Just 0
      rayBox (Point2 1 0) (Vector2 1 0) b `shouldBe` Just 0
      rayBox (Point2 1 0) (Vector2 (-1) 0) b `shouldBe` Just 0
    it "never returns -0.0" $
      fmap isNegativeZero (rayBox (Point2 1 0) (Vector2 (-1) (-0.0)) b)
        `shouldBe` Just False
    it "treats a zero direction as a point test" $ do
      rayBox (Point2 2 0) (Vector2 0 0) b `shouldBe` Just 0
      rayBox (Point2 0 0) (Vector2 0 (-0.0)) b `shouldBe` Nothing


  describe "rayCircle" $ do
    let c = Point2 5 0
    it "hits head-on" $
      rayCircle (Point2 0 0) (Vector2 1 0) c 1 `shouldHitAt` Just 4
    it "hits with a -0.0 direction component" $
      rayCircle (Point2 5 (-3)) (Vector2 (-0.0) 1) c 1 `shouldHitAt` Just 2
    it "hits obliquely" $
      -- from (0, 0.6) along +x: x^2 + 0.36 = 1 at x = 5 - 0.8
      rayCircle (Point2 0 0.6) (Vector2 1 0) c 1 `shouldHitAt` Just 4.2
    it "counts a tangent ray as a hit" $
      rayCircle (Point2 0 1) (Vector2 1 0) c 1 `shouldHitAt` Just 5
    it "misses" $ do
      rayCircle (Point2 0 0) (Vector2 (-1) 0) c 1 `shouldBe` Nothing
      rayCircle (Point2 0 2) (Vector2 1 0) c 1 `shouldBe` Nothing
      rayCircle (Point2 0 0) (Vector2 0.6 0.8) c 1 `shouldBe` Nothing
    it "returns Just 0 from inside or on the circle" $ do
      rayCircle (Point2 5 0.5) (Vector2 0 1) c 1 `shouldBe` Just 0
      rayCircle (Point2 4 0) (Vector2 (-1) 0) c 1 `shouldBe` Just 0
    it "is accurate for a distant circle" $
      rayCircle (Point2 0 0) (Vector2 1 0) (Point2 1e6 0) 1
        `shouldBe` Just 999999


  describe "properties" $ do
    prop "rayBox agrees with a march along the ray" $
      forAll genBox $ \b -> forAll (genOrigin b) $ \o -> forAll genDir $ \dir ->
        let Point2 cx cy   = boxCentre b
            Point2 ox oy   = o
            Box x0 y0 x1 y1 = b
            tMax = len (Vector2 (ox - cx) (oy - cy))
                   + len (Vector2 (x1 - x0) (y1 - y0)) / 2 + 1e-2
        in marchAgrees (`inBox` b) (`distToBox` b) tMax o dir (rayBox o dir b)

    prop "rayCircle agrees with a march along the ray" $
      forAll ((,) <$> (Point2 <$> choose (-5, 5) <*> choose (-5, 5))
                  <*> choose (0.05, 3)) $ \(c, r) ->
      forAll genPoint $ \o -> forAll genDir $ \dir ->
        let dist x = max 0 (len (vec x c) - r)
            tMax = len (vec o c) + r + 1e-2
        in marchAgrees (\p -> inCircle p c r) dist tMax o dir
                       (rayCircle o dir c r)

  describe "fmax / fmin" $ do
    it "pick the larger and the smaller of two numbers" $ do
      fmax 1 2 `shouldBe` (2 :: Double)
      fmax 2 1 `shouldBe` (2 :: Double)
      fmin 1 2 `shouldBe` (1 :: Double)
      fmin 2 1 `shouldBe` (1 :: Double)
    it "on a tie give the second argument, so a zero keeps the sign it had" $ do
      isNegativeZero (fmax 0 (-0.0)) `shouldBe` True
      isNegativeZero (fmax (-0.0) 0) `shouldBe` False
      isNegativeZero (fmin 0 (-0.0)) `shouldBe` True
      isNegativeZero (fmin (-0.0) 0) `shouldBe` False
