{-# LANGUAGE FlexibleInstances #-}
-- | Fixed cases and round-trip properties for "AFRP.Geometry": polar and
-- spherical coordinates, rotations, and the affine space of points.
module AFRP.GeometrySpec (spec) where

import Control.DeepSeq (rnf)
import Control.Exception (evaluate)
import Test.Hspec
import Test.QuickCheck

import AFRP.Geometry

------------------------------------------------------------------------------
-- Approximate comparison

-- | Types compared component-wise; components are read directly from the
-- constructors, not through the functions under test.
class Show v => Components v where
  components :: v -> [Double]

instance Components Double where
  components x = [x]

instance Components (Double, Double) where
  components (x, y) = [x, y]

instance Components (Double, Double, Double) where
  components (x, y, z) = [x, y, z]

instance Components (Vector2 Double) where
  components (Vector2 x y) = [x, y]

instance Components (Vector3 Double) where
  components (Vector3 x y z) = [x, y, z]

instance Components (Point2 Double) where
  components (Point2 x y) = [x, y]

instance Components (Point3 Double) where
  components (Point3 x y z) = [x, y, z]

-- | @closeWithin eps x y@: relative error at most @eps@, or absolute error
-- at most @eps@ for values of magnitude below 1.
closeWithin :: Double -> Double -> Double -> Bool
closeWithin eps x y = abs (x - y) <= eps * max 1 (max (abs x) (abs y))

nearWithin :: Components v => Double -> v -> v -> Bool
nearWithin eps u v =
  length cu == length cv && and (zipWith (closeWithin eps) cu cv)
  where
    cu = components u
    cv = components v

-- | Approximate equality (tolerance 1e-9) as a QuickCheck property.
(~=) :: Components v => v -> v -> Property
u ~= v = counterexample (show u ++ " is not approximately " ++ show v)
  (nearWithin 1e-9 u v)
infix 4 ~=

-- | Approximate equality (tolerance 1e-12) as an hspec expectation.
shouldBeNear :: (HasCallStack, Components v) => v -> v -> Expectation
shouldBeNear u v
  | nearWithin 1e-12 u v = pure ()
  | otherwise =
      expectationFailure (show u ++ " is not within 1e-12 of " ++ show v)
infix 1 `shouldBeNear`

-- | Distance between two angles modulo @2 * pi@.
angleDiff :: Double -> Double -> Double
angleDiff a b = abs (d - 2 * pi * fromIntegral (round (d / (2 * pi)) :: Integer))
  where
    d = a - b

sameAngle :: Double -> Double -> Property
sameAngle a b = counterexample (show a ++ " and " ++ show b ++
                                " are not the same angle")
  (angleDiff a b <= 1e-9)

------------------------------------------------------------------------------
-- Generators

genCoord :: Gen Double
genCoord = oneof [choose (-100, 100), elements [0, 1, -1]]

genAngle :: Gen Double
genAngle = choose (-10, 10)

genRho :: Gen Double
genRho = choose (1e-2, 100)

-- | Azimuths in @(-pi, pi]@.
genTheta :: Gen Double
genTheta = choose (-pi, pi) `suchThat` (> negate pi)

-- | Elevations away from the poles, where the azimuth is ill-conditioned.
genPhi :: Gen Double
genPhi = choose (-1.5, 1.5)

genV2 :: Gen (Vector2 Double)
genV2 = Vector2 <$> genCoord <*> genCoord

genV3 :: Gen (Vector3 Double)
genV3 = Vector3 <$> genCoord <*> genCoord <*> genCoord

genP2 :: Gen (Point2 Double)
genP2 = Point2 <$> genCoord <*> genCoord

genP3 :: Gen (Point3 Double)
genP3 = Point3 <$> genCoord <*> genCoord <*> genCoord

v2 :: Double -> Double -> Vector2 Double
v2 = Vector2

v3 :: Double -> Double -> Double -> Vector3 Double
v3 = Vector3

p2 :: Double -> Double -> Point2 Double
p2 = Point2

p3 :: Double -> Double -> Double -> Point3 Double
p3 = Point3

------------------------------------------------------------------------------
-- Spec

spec :: Spec
spec = do
  vector2Spec
  vector3Spec
  pointSpec
  nfDataSpec

vector2Spec :: Spec
vector2Spec = describe "Vector2" $ do
  it "has accessors for its components" $ do
    vector2 1 2 `shouldBe` v2 1 2
    vector2X (v2 1 2) `shouldBe` 1
    vector2Y (v2 1 2) `shouldBe` 2
    vector2XY (v2 1 2) `shouldBe` (1, 2)

  it "vector2Polar 2 (pi/2) is (0, 2)" $
    vector2Polar 2 (pi / 2) `shouldBeNear` v2 0 2

  it "vector2Polar measures angles counter-clockwise from +x" $ do
    vector2Polar 1 0 `shouldBeNear` v2 1 0
    vector2Polar 3 pi `shouldBeNear` v2 (-3) 0
    vector2Polar (sqrt 2) (-pi / 4) `shouldBeNear` v2 1 (-1)

  it "vector2RhoTheta gives (length, angle)" $ do
    vector2RhoTheta (v2 (-1) 0) `shouldBe` (1, pi)
    vector2RhoTheta (v2 0 (-2)) `shouldBe` (2, -pi / 2)
    vector2RhoTheta (v2 3 4) `shouldBeNear` (5, atan2 4 3)
    vector2RhoTheta (v2 (-1) (-1)) `shouldBeNear` (sqrt 2, -3 * pi / 4)
    vector2Rho (v2 (-5) 12) `shouldBe` 13

  it "vector2Theta is in (-pi, pi], also for a y component of -0.0" $ do
    vector2Theta (v2 (-1) (-0.0)) `shouldBe` pi
    vector2Theta (v2 0 0) `shouldBe` 0
    -- (the zero vector's angle is 0 whatever the signs of its zeros: a
    -- rotated or negated zero vector gave pi)
    vector2Theta (v2 (-0.0) 0) `shouldBe` 0
    vector2Theta (v2 (-0.0) (-0.0)) `shouldBe` 0
    vector2Theta (vector2Rotate pi (zeroVector :: Vector2 Double)) `shouldBe` 0
    vector3Theta (Vector3 (-0.0) 0 5 :: Vector3 Double) `shouldBe` 0
    -- (both components infinite: the diagonal, not NaN)
    let inf = 1 / 0
    map vector2Theta [v2 inf inf, v2 (-inf) inf, v2 (-inf) (-inf), v2 inf (-inf)]
      `shouldBe` [pi / 4, 3 * pi / 4, -3 * pi / 4, -pi / 4]

  it "vector2Rotate rotates counter-clockwise" $ do
    vector2Rotate (pi / 2) (v2 1 0) `shouldBeNear` v2 0 1
    vector2Rotate (pi / 2) (v2 0 1) `shouldBeNear` v2 (-1) 0
    vector2Rotate (-pi / 4) (v2 0 2) `shouldBeNear` v2 (sqrt 2) (sqrt 2)

  it "round-trips polar -> cartesian -> polar" $
    forAll ((,) <$> genRho <*> genTheta) $ \(rho, theta) ->
      let (rho', theta') = vector2RhoTheta (vector2Polar rho theta)
      in rho' ~= rho .&&. sameAngle theta' theta

  it "round-trips cartesian -> polar -> cartesian" $ forAll genV2 $ \v ->
    uncurry vector2Polar (vector2RhoTheta v) ~= v

  it "vector2Theta is always in (-pi, pi]" $ forAll genV2 $ \v ->
    let t = vector2Theta v in counterexample (show t) (t > -pi && t <= pi)

  it "vector2Rho agrees with norm" $ forAll genV2 $ \v ->
    vector2Rho v ~= norm v

  it "rotating by a then by -a is the identity" $
    forAll ((,) <$> genAngle <*> genV2) $ \(a, v) ->
      vector2Rotate (-a) (vector2Rotate a v) ~= v

  it "rotating by a preserves length and adds a to the angle" $
    forAll ((,) <$> genAngle <*> (genV2 `suchThat` ((> 1e-3) . norm))) $
      \(a, v) ->
        let w = vector2Rotate a v
        in norm w ~= norm v .&&. sameAngle (vector2Theta w) (vector2Theta v + a)

  it "rotations compose by adding angles" $
    forAll ((,,) <$> genAngle <*> genAngle <*> genV2) $ \(a, b, v) ->
      vector2Rotate a (vector2Rotate b v) ~= vector2Rotate (a + b) v

vector3Spec :: Spec
vector3Spec = describe "Vector3" $ do
  it "has accessors for its components" $ do
    vector3 1 2 3 `shouldBe` v3 1 2 3
    vector3X (v3 1 2 3) `shouldBe` 1
    vector3Y (v3 1 2 3) `shouldBe` 2
    vector3Z (v3 1 2 3) `shouldBe` 3
    vector3XYZ (v3 1 2 3) `shouldBe` (1, 2, 3)

  it "vector3Spherical uses (length, azimuth, elevation)" $ do
    vector3Spherical 2 0 0 `shouldBeNear` v3 2 0 0
    vector3Spherical 1 (pi / 2) 0 `shouldBeNear` v3 0 1 0
    vector3Spherical 2 0 (pi / 2) `shouldBeNear` v3 0 0 2
    vector3Spherical 2 1 (-pi / 2) `shouldBeNear` v3 0 0 (-2)
    vector3Spherical 2 pi (pi / 4) `shouldBeNear` v3 (-sqrt 2) 0 (sqrt 2)

  it "vector3RhoThetaPhi gives (length, azimuth, elevation)" $ do
    vector3RhoThetaPhi (v3 0 0 (-3)) `shouldBe` (3, 0, -pi / 2)
    vector3RhoThetaPhi (v3 1 1 0) `shouldBeNear` (sqrt 2, pi / 4, 0)
    vector3RhoThetaPhi (v3 (-1) 0 1) `shouldBeNear` (sqrt 2, pi, pi / 4)
    vector3RhoThetaPhi (v3 0 (-2) (-2)) `shouldBeNear`
      (sqrt 8, -pi / 2, -pi / 4)
    vector3Rho (v3 2 3 6) `shouldBe` 7
    vector3Theta (v3 (-1) (-0.0) 5) `shouldBe` pi

  it "vector3Rotate theta 0 rotates about the z axis" $ do
    vector3Rotate (pi / 2) 0 (v3 1 0 5) `shouldBeNear` v3 0 1 5
    vector3Rotate pi 0 (v3 1 2 3) `shouldBeNear` v3 (-1) (-2) 3

  it "vector3Rotate 0 phi tilts +x towards +z about the y axis" $ do
    vector3Rotate 0 (pi / 2) (v3 1 0 0) `shouldBeNear` v3 0 0 1
    vector3Rotate 0 (pi / 2) (v3 0 0 1) `shouldBeNear` v3 (-1) 0 0
    vector3Rotate 0 (pi / 2) (v3 0 1 0) `shouldBeNear` v3 0 1 0

  it "vector3Rotate applies the elevation before the azimuth" $
    vector3Rotate (pi / 2) (pi / 2) (v3 0 1 0) `shouldBeNear` v3 (-1) 0 0

  it "round-trips spherical -> cartesian -> spherical" $
    forAll ((,,) <$> genRho <*> genTheta <*> genPhi) $ \(rho, theta, phi) ->
      let (rho', theta', phi') =
            vector3RhoThetaPhi (vector3Spherical rho theta phi)
      in rho' ~= rho .&&. sameAngle theta' theta .&&. phi' ~= phi

  it "round-trips cartesian -> spherical -> cartesian" $ forAll genV3 $ \v ->
    let (rho, theta, phi) = vector3RhoThetaPhi v
    in vector3Spherical rho theta phi ~= v

  it "angles are in range: theta in (-pi, pi], phi in [-pi/2, pi/2]" $
    forAll genV3 $ \v ->
      let (_, t, p) = vector3RhoThetaPhi v
      in counterexample (show (t, p)) $
           t > -pi && t <= pi && p >= -pi / 2 && p <= pi / 2

  it "the azimuth agrees with vector2Theta of the xy projection" $
    forAll genV3 $ \v@(Vector3 x y _) ->
      vector3Theta v === vector2Theta (v2 x y)

  it "vector3Rho agrees with norm" $ forAll genV3 $ \v ->
    vector3Rho v ~= norm v

  it "vector3Rotate theta phi maps the x axis to direction (theta, phi)" $
    forAll ((,,) <$> genRho <*> genAngle <*> genAngle) $ \(r, t, p) ->
      vector3Rotate t p (v3 r 0 0) ~= vector3Spherical r t p

  it "vector3Rotate theta 0 is vector2Rotate on (x, y), keeping z" $
    forAll ((,) <$> genAngle <*> genV3) $ \(a, v@(Vector3 x y z)) ->
      let Vector2 x' y' = vector2Rotate a (v2 x y)
      in vector3Rotate a 0 v ~= v3 x' y' z

  it "rotating then undoing (azimuth, then elevation) is the identity" $
    forAll ((,,) <$> genAngle <*> genAngle <*> genV3) $ \(t, p, v) ->
      vector3Rotate 0 (-p) (vector3Rotate (-t) 0 (vector3Rotate t p v)) ~= v

  it "vector3Rotate preserves dot products (and hence lengths)" $
    forAll ((,,,) <$> genAngle <*> genAngle <*> genV3 <*> genV3) $
      \(t, p, u, v) ->
        let size = norm u * norm v
            lhs  = dot (vector3Rotate t p u) (vector3Rotate t p v)
        in counterexample (show lhs ++ " /= " ++ show (dot u v)) $
             abs (lhs - dot u v) <= 1e-9 * max 1 size

point2Spec :: Spec
point2Spec = describe "Point2" $ do
  it "has accessors for its coordinates" $ do
    point2X (p2 1 2) `shouldBe` 1
    point2Y (p2 1 2) `shouldBe` 2

  it "origin is Point2 0 0" $
    origin `shouldBe` p2 0 0

  it "Point2 3 4 .-. Point2 0 0 == Vector2 3 4" $
    p2 3 4 .-. p2 0 0 `shouldBe` v2 3 4

  it ".-. gives the displacement from the second point to the first" $
    p2 1 2 .-. p2 4 6 `shouldBe` v2 (-3) (-4)

  it ".+^ and .-^ move a point" $ do
    p2 1 2 .+^ v2 3 4 `shouldBe` p2 4 6
    p2 1 2 .-^ v2 3 4 `shouldBe` p2 (-2) (-2)

  it "distance is the Euclidean distance" $ do
    distance (p2 1 2) (p2 4 6) `shouldBe` 5
    distance (p2 0 0) (p2 (-3) 4) `shouldBe` 5

  it "(p .+^ v) .-. p == v" $ forAll ((,) <$> genP2 <*> genV2) $ \(p, v) ->
    (p .+^ v) .-. p ~= v

  it "q .+^ (p .-. q) == p" $ forAll ((,) <$> genP2 <*> genP2) $ \(p, q) ->
    q .+^ (p .-. q) ~= p

  it "p .-^ v == p .+^ negateVector v" $
    forAll ((,) <$> genP2 <*> genV2) $ \(p, v) ->
      p .-^ v ~= p .+^ negateVector v

  it "distance is symmetric and equals the norm of the difference" $
    forAll ((,) <$> genP2 <*> genP2) $ \(p, q) ->
      distance p q === distance q p .&&. distance p q ~= norm (p .-. q)

pointSpec :: Spec
pointSpec = do
  point2Spec
  describe "Point3" $ do
    it "has accessors for its coordinates" $ do
      point3X (p3 1 2 3) `shouldBe` 1
      point3Y (p3 1 2 3) `shouldBe` 2
      point3Z (p3 1 2 3) `shouldBe` 3

    it "origin is Point3 0 0 0" $
      origin `shouldBe` p3 0 0 0

    it ".-., .+^ and .-^ work component-wise" $ do
      p3 1 2 3 .-. p3 0 0 0 `shouldBe` v3 1 2 3
      p3 1 2 3 .-. p3 4 6 8 `shouldBe` v3 (-3) (-4) (-5)
      p3 1 2 3 .+^ v3 1 1 1 `shouldBe` p3 2 3 4
      p3 1 2 3 .-^ v3 1 1 1 `shouldBe` p3 0 1 2

    it "distance is the Euclidean distance" $
      distance (p3 1 1 1) (p3 3 4 7) `shouldBe` 7

    it "(p .+^ v) .-. p == v" $ forAll ((,) <$> genP3 <*> genV3) $ \(p, v) ->
      (p .+^ v) .-. p ~= v

    it "q .+^ (p .-. q) == p" $ forAll ((,) <$> genP3 <*> genP3) $ \(p, q) ->
      q .+^ (p .-. q) ~= p

    it "p .-^ v == p .+^ negateVector v" $
      forAll ((,) <$> genP3 <*> genV3) $ \(p, v) ->
        p .-^ v ~= p .+^ negateVector v

    it "distance p (p .+^ v) == norm v" $
      forAll ((,) <$> genP3 <*> genV3) $ \(p, v) ->
        distance p (p .+^ v) ~= norm v

nfDataSpec :: Spec
nfDataSpec = describe "NFData instances" $ do
  let boom :: Maybe Int
      boom = Just (error "forced")
  it "rnf forces every component of a Vector2" $ do
    evaluate (rnf (Vector2 boom Nothing)) `shouldThrow` anyErrorCall
    evaluate (rnf (Vector2 Nothing boom)) `shouldThrow` anyErrorCall
  it "rnf forces every component of a Vector3" $ do
    evaluate (rnf (Vector3 boom Nothing Nothing)) `shouldThrow` anyErrorCall
    evaluate (rnf (Vector3 Nothing Nothing boom)) `shouldThrow` anyErrorCall
  it "rnf forces every component of a Point2" $ do
    evaluate (rnf (Point2 boom Nothing)) `shouldThrow` anyErrorCall
    evaluate (rnf (Point2 Nothing boom)) `shouldThrow` anyErrorCall
  it "rnf forces every component of a Point3" $ do
    evaluate (rnf (Point3 boom Nothing Nothing)) `shouldThrow` anyErrorCall
    evaluate (rnf (Point3 Nothing Nothing boom)) `shouldThrow` anyErrorCall
