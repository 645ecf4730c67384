-- | Tests for "AFrob.Angle": fixed cases at and around the range
-- boundaries, the cardinal directions, and QuickCheck properties (always
-- in range, idempotent, unchanged when in range, congruent to the input).
module AFrob.AngleSpec (spec) where

import           GHC.Float       (castDoubleToWord64)
import           Test.Hspec      hiding (after)
import           Test.QuickCheck

import           AFrob.Angle

-- | The Double value of 2 * pi, the period of the radian functions.
twoPi :: Double
twoPi = 2 * pi

-- | The largest Double below the argument (positive finite arguments).
predD :: Double -> Double
predD x = encodeFloat (m - 1) e where (m, e) = decodeFloat x

-- | The smallest Double above the argument (positive finite arguments).
succD :: Double -> Double
succD x = encodeFloat (m + 1) e where (m, e) = decodeFloat x

-- | The same bits (distinguishes -0.0 from 0.0).
sameBits :: Double -> Double -> Bool
sameBits x y = castDoubleToWord64 x == castDoubleToWord64 y

-- | Distance between two directions on the circle with the given period.
circDist :: Double -> Double -> Double -> Double
circDist period x y = let d = abs (x - y) `mod'` period in min d (period - d)
  where a `mod'` p = a - p * fromIntegral (floor (a / p) :: Integer)

-- | @x - r@ is a whole number of periods, up to @tol@, computed exactly.
congruent :: Double -> Rational -> Double -> Double -> Bool
congruent period tol x r =
  let d = toRational x - toRational r
      p = toRational period
      k = fromInteger (round (d / p))
  in abs (d - k * p) <= tol

-- | Doubles of every kind: ordinary, near the boundaries of both ranges,
-- multiples of pi and of 360, tiny, and huge.
anyDouble :: Gen Double
anyDouble = oneof
  [ arbitrary
  , choose (-20, 20)
  , choose (-1000, 1000)
  , elements specials
  , (*) <$> elements [pi, 90, 180, 360] <*> (fromInteger <$> choose (-10, 10))
  , (\s k -> s * 10 ^^ k) <$> elements [-1, 1] <*> (choose (-300, 300) :: Gen Int)
  , (\s m k -> s * m * 10 ^^ k) <$> elements [-1, 1] <*> choose (1, 10)
                                 <*> (choose (-20, 300) :: Gen Int)
  ]
  where
    specials =
      [ 0, -0.0, pi, -pi, predD pi, succD pi, -(predD pi), -(succD pi)
      , twoPi, -twoPi, predD twoPi, succD twoPi, 3 * pi, -3 * pi
      , 360, -360, predD 360, succD 360, -(predD 360), 180, -180, 720
      , -1e-17, 1e-17, -1e-300, -5e-324, 5e-324, 1e308, -1e308, 1.7976931348623157e308
      ]

-- | A generated double with its properties shown in full precision.
forAllD :: Testable p => (Double -> p) -> Property
forAllD = forAll anyDouble

spec :: Spec
spec = do
  describe "normalizeAngle" $ do
    it "maps pi to -pi (half-open range)" $
      normalizeAngle pi `shouldBe` -pi
    it "keeps -pi" $
      normalizeAngle (-pi) `shouldBe` -pi
    it "maps 3*pi and -3*pi to -pi" $ do
      normalizeAngle (3 * pi) `shouldBe` -pi
      normalizeAngle (-3 * pi) `shouldBe` -pi
    it "maps 2*pi and -2*pi to 0" $ do
      normalizeAngle twoPi `shouldBe` 0
      normalizeAngle (-twoPi) `shouldBe` 0
    it "keeps the largest value below pi and the smallest above -pi" $ do
      normalizeAngle (predD pi) `shouldBe` predD pi
      normalizeAngle (-(predD pi)) `shouldBe` -(predD pi)
    it "wraps just beyond the boundaries" $ do
      normalizeAngle (succD pi) `shouldBe` -(predD pi)
      normalizeAngle (-(succD pi)) `shouldBe` predD pi
    it "maps 3*pi/2 to -pi/2 and -3*pi/2 to pi/2" $ do
      normalizeAngle (3 * pi / 2) `shouldSatisfy` \r -> abs (r + pi / 2) < 1e-15
      normalizeAngle (-3 * pi / 2) `shouldSatisfy` \r -> abs (r - pi / 2) < 1e-15
    it "returns values in range unchanged, bit for bit" $ do
      normalizeAngle (-0.0) `shouldSatisfy` sameBits (-0.0)
      normalizeAngle 1e-300 `shouldSatisfy` sameBits 1e-300
      normalizeAngle 1 `shouldSatisfy` sameBits 1
    it "reduces huge values into range, exactly modulo 2*pi" $
      mapM_ (\x -> normalizeAngle x `shouldSatisfy` \r ->
                      r >= -pi && r < pi && congruent twoPi 1e-15 x r)
            [1e300, -1e300, 1e308, -1e308, 1.7976931348623157e308, 1e16 + 1, 12345678.9]
    it "reduces 1e6 * 2*pi + 1 to about 1" $
      normalizeAngle (1e6 * twoPi + 1) `shouldSatisfy` \r -> abs (r - 1) < 1e-9
    it "gives NaN for NaN and the infinities" $ do
      normalizeAngle (0 / 0) `shouldSatisfy` isNaN
      normalizeAngle (1 / 0) `shouldSatisfy` isNaN
      normalizeAngle (-1 / 0) `shouldSatisfy` isNaN
    it "normalizeHeading agrees with normalizeAngle" $
      property $ forAllD $ \x ->
        sameBits (normalizeHeading x) (normalizeAngle x)

  describe "normalizeBearing" $ do
    it "maps 360 to 0 and keeps 0" $ do
      normalizeBearing 360 `shouldBe` 0
      normalizeBearing 0 `shouldBe` 0
    it "maps -90 to 270, 450 to 90, -360 to 0, 720 to 0" $ do
      normalizeBearing (-90) `shouldBe` 270
      normalizeBearing 450 `shouldBe` 90
      normalizeBearing (-360) `shouldBe` 0
      normalizeBearing 720 `shouldBe` 0
    it "never rounds a tiny negative value up to 360" $ do
      normalizeBearing (-1e-17) `shouldBe` 0
      normalizeBearing (-5e-324) `shouldBe` 0
      normalizeBearing (-1e-14) `shouldBe` 0   -- 360 - 1e-14 rounds to 360
      normalizeBearing (-1e-12) `shouldSatisfy` \r -> r < 360 && r > 359.9
    it "keeps the largest value below 360" $
      normalizeBearing (predD 360) `shouldBe` predD 360
    it "reduces huge values exactly modulo 360" $ do
      normalizeBearing 1e300 `shouldSatisfy` \r -> r >= 0 && r < 360 && congruent 360 0 1e300 r
      normalizeBearing (-1e300) `shouldSatisfy` \r -> r >= 0 && r < 360 && congruent 360 0 (-1e300) r
      normalizeBearing (360 * 1e13 + 45) `shouldBe` 45
    it "gives NaN for NaN and the infinities" $ do
      normalizeBearing (0 / 0) `shouldSatisfy` isNaN
      normalizeBearing (1 / 0) `shouldSatisfy` isNaN

  describe "bearings and headings" $ do
    it "north (0) is heading pi/2 and back" $ do
      bearingToHeading 0 `shouldBe` pi / 2
      headingToBearing (pi / 2) `shouldBe` 0
    it "east (90) is heading 0 and back" $ do
      bearingToHeading 90 `shouldBe` 0
      headingToBearing 0 `shouldBe` 90
    it "south (180) is heading -pi/2, west (270) is -pi" $ do
      bearingToHeading 180 `shouldBe` -pi / 2
      bearingToHeading 270 `shouldBe` -pi
      headingToBearing (-pi / 2) `shouldBe` 180
      headingToBearing (-pi) `shouldBe` 270
      headingToBearing pi `shouldBe` 270
    it "south-west (225) is heading -3*pi/4 and back" $ do
      bearingToHeading 225 `shouldSatisfy` \h -> abs (h + 3 * pi / 4) < 1e-15
      headingToBearing (-3 * pi / 4) `shouldSatisfy` \b -> abs (b - 225) < 1e-12
    it "normalises: bearing 360 + 90 and -270 are heading 0" $ do
      bearingToHeading 450 `shouldBe` 0
      bearingToHeading (-270) `shouldBe` 0
    it "degToRad and radToDeg are exact on the common angles" $ do
      map degToRad [0, 45, 90, 180, -90] `shouldBe` [0, pi / 4, pi / 2, pi, -pi / 2]
      map radToDeg [0, pi / 4, pi / 2, pi, -pi / 2] `shouldBe` [0, 45, 90, 180, -90]

  describe "properties" $ do
    it "normalizeAngle: result in [-pi, pi) for finite input" $
      property $ forAllD $ \x -> let r = normalizeAngle x in r >= -pi && r < pi
    it "normalizeBearing: result in [0, 360) for finite input" $
      property $ forAllD $ \x -> let r = normalizeBearing x in r >= 0 && r < 360
    it "normalizeAngle is idempotent (bit for bit)" $
      property $ forAllD $ \x -> let r = normalizeAngle x in sameBits (normalizeAngle r) r
    it "normalizeBearing is idempotent (bit for bit)" $
      property $ forAllD $ \x -> let r = normalizeBearing x in sameBits (normalizeBearing r) r
    it "normalizeAngle returns in-range input unchanged" $
      property $ forAll (choose (-pi, pi)) $ \x ->
        x < pi ==> sameBits (normalizeAngle x) x
    it "normalizeAngle: input minus result is a multiple of 2*pi (exactly, up to one rounding)" $
      property $ forAllD $ \x -> congruent twoPi 3e-16 x (normalizeAngle x)
    it "normalizeBearing: input minus result is a multiple of 360 (up to one rounding)" $
      property $ forAllD $ \x -> congruent 360 3e-14 x (normalizeBearing x)
    it "normalizeAngle: congruent to the input in floating point, for moderate input" $
      property $ forAll (choose (-1e4, 1e4)) $ \x ->
        circDist twoPi x (normalizeAngle x) <= 1e-9
    it "headingToBearing . bearingToHeading is normalizeBearing (within 1e-9 degrees on the circle)" $
      property $ forAllD $ \b ->
        circDist 360 (headingToBearing (bearingToHeading b)) (normalizeBearing b) <= 1e-9
    it "bearingToHeading . headingToBearing is normalizeHeading (within 1e-12 on the circle)" $
      property $ forAllD $ \h ->
        circDist twoPi (bearingToHeading (headingToBearing h)) (normalizeHeading h) <= 1e-12
    it "conversions stay in range" $
      property $ forAllD $ \x ->
        let h = bearingToHeading x
            b = headingToBearing x
        in h >= -pi && h < pi && b >= 0 && b < 360
