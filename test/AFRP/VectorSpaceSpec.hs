{-# LANGUAGE FlexibleContexts  #-}
{-# LANGUAGE FlexibleInstances #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- | Laws and fixed examples for "AFRP.VectorSpace" instances: 'Double',
-- pairs, triples, 'Vector2' and 'Vector3' (and a few 'Float' cases).
module AFRP.VectorSpaceSpec (spec) where

import Control.Exception (ErrorCall (..), evaluate)
import Data.List (isInfixOf)
import Test.Hspec
import Test.QuickCheck

import AFRP.Geometry (Vector2 (..), Vector3 (..))
import AFRP.VectorSpace

------------------------------------------------------------------------------
-- Approximate comparison

-- | Types whose values can be compared component-wise (the components are
-- read directly from the representation, not through 'VectorSpace').
class Show v => Components v where
  components :: v -> [Double]

instance Components Double where
  components x = [x]

instance Components (Double, Double) where
  components (x, y) = [x, y]

instance Components (Double, Double, Double) where
  components (x, y, z) = [x, y, z]

instance Components (Double, Double, Double, Double) where
  components (x, y, z, u) = [x, y, z, u]

instance Components (Double, Double, Double, Double, Double) where
  components (x, y, z, u, v) = [x, y, z, u, v]

instance Components (Vector2 Double) where
  components (Vector2 x y) = [x, y]

instance Components (Vector3 Double) where
  components (Vector3 x y z) = [x, y, z]

-- | Relative relTolerance, with an absolute floor of the same size for values
-- near zero.
relTolerance :: Double
relTolerance = 1e-9

closeTo :: Double -> Double -> Bool
closeTo x y = abs (x - y) <= relTolerance * max 1 (max (abs x) (abs y))

-- | Component-wise approximate equality as a property.
(~=) :: Components v => v -> v -> Property
u ~= v =
  counterexample (show u ++ " is not approximately " ++ show v) $
    length cu == length cv && and (zipWith closeTo cu cv)
  where
    cu = components u
    cv = components v
infix 4 ~=

-- | Exact component-wise equality as a property.
(=~=) :: Components v => v -> v -> Property
u =~= v = counterexample (show u ++ " /= " ++ show v) $
  components u == components v
infix 4 =~=

scalarClose :: Double -> Double -> Property
scalarClose x y =
  counterexample (show x ++ " is not approximately " ++ show y) (closeTo x y)

------------------------------------------------------------------------------
-- Generators

genScalar :: Gen Double
genScalar = oneof [choose (-100, 100), elements [0, 1, -1, 0.5]]

genPair :: Gen (Double, Double)
genPair = (,) <$> genScalar <*> genScalar

genTriple :: Gen (Double, Double, Double)
genTriple = (,,) <$> genScalar <*> genScalar <*> genScalar

genQuadruple :: Gen (Double, Double, Double, Double)
genQuadruple = (,,,) <$> genScalar <*> genScalar <*> genScalar <*> genScalar

genQuintuple :: Gen (Double, Double, Double, Double, Double)
genQuintuple = (,,,,) <$> genScalar <*> genScalar <*> genScalar <*> genScalar <*> genScalar

genVector2 :: Gen (Vector2 Double)
genVector2 = Vector2 <$> genScalar <*> genScalar

genVector3 :: Gen (Vector3 Double)
genVector3 = Vector3 <$> genScalar <*> genScalar <*> genScalar

------------------------------------------------------------------------------
-- Laws

-- | The vector-space laws for one instance over 'Double'.
laws :: forall v. (VectorSpace v Double, Components v) => String -> Gen v -> Spec
laws name gen = describe name $ do
  let zero = zeroVector :: v
      gen2 = (,) <$> gen <*> gen
      gen3 = (,,) <$> gen <*> gen <*> gen

  it "zeroVector has all components 0" $
    components zero `shouldSatisfy` all (== 0)

  it "^+^ is associative" $ forAll gen3 $ \(u, v, w) ->
    (u ^+^ v) ^+^ w ~= u ^+^ (v ^+^ w)

  it "^+^ is commutative" $ forAll gen2 $ \(u, v) ->
    u ^+^ v =~= v ^+^ u

  it "^+^ adds component-wise" $ forAll gen2 $ \(u, v) ->
    components (u ^+^ v) === zipWith (+) (components u) (components v)

  it "zeroVector is a left and right identity of ^+^" $ forAll gen $ \v ->
    zero ^+^ v =~= v .&&. v ^+^ zero =~= v

  it "negateVector negates every component" $ forAll gen $ \v ->
    components (negateVector v) === map negate (components v)

  it "v ^+^ negateVector v is zeroVector" $ forAll gen $ \v ->
    v ^+^ negateVector v ~= zero

  it "^-^ subtracts component-wise" $ forAll gen2 $ \(u, v) ->
    components (u ^-^ v) === zipWith (-) (components u) (components v)

  it "u ^-^ v == u ^+^ negateVector v" $ forAll gen2 $ \(u, v) ->
    u ^-^ v ~= u ^+^ negateVector v

  it "*^ scales every component" $ forAll ((,) <$> genScalar <*> gen) $
    \(a, v) -> components (a *^ v) === map (a *) (components v)

  it "1 *^ v == v and 0 *^ v == zeroVector" $ forAll gen $ \v ->
    1 *^ v =~= v .&&. 0 *^ v ~= zero

  it "*^ distributes over ^+^" $
    forAll ((,,) <$> genScalar <*> gen <*> gen) $ \(a, u, v) ->
      a *^ (u ^+^ v) ~= a *^ u ^+^ a *^ v

  it "*^ distributes over scalar addition" $
    forAll ((,,) <$> genScalar <*> genScalar <*> gen) $ \(a, b, v) ->
      (a + b) *^ v ~= a *^ v ^+^ b *^ v

  it "*^ is compatible with scalar multiplication" $
    forAll ((,,) <$> genScalar <*> genScalar <*> gen) $ \(a, b, v) ->
      a *^ (b *^ v) ~= (a * b) *^ v

  it "v ^/ a == (1 / a) *^ v for a /= 0" $
    forAll ((,) <$> (genScalar `suchThat` (/= 0)) <*> gen) $ \(a, v) ->
      v ^/ a ~= (1 / a) *^ v

  it "dot is symmetric" $ forAll gen2 $ \(u, v) ->
    dot u v === dot v u

  it "dot is the sum of component products" $ forAll gen2 $ \(u, v) ->
    dot u v `scalarClose` sum (zipWith (*) (components u) (components v))

  it "dot is linear in its first argument" $
    forAll ((,,,) <$> genScalar <*> gen <*> gen <*> gen) $ \(a, u, v, w) ->
      -- Cancellation can make the result small compared with the terms,
      -- so the tolerance is scaled by the size of the terms.
      let size  = (abs a * norm u + norm v) * norm w
          lhs   = dot (a *^ u ^+^ v) w
          rhs   = a * dot u w + dot v w
      in counterexample (show lhs ++ " /= " ++ show rhs) $
           abs (lhs - rhs) <= relTolerance * max 1 size

  it "norm v == sqrt (dot v v)" $ forAll gen $ \v ->
    norm v `scalarClose` sqrt (sum (map (^ (2 :: Int)) (components v)))

  it "norm (a *^ v) == abs a * norm v" $
    forAll ((,) <$> genScalar <*> gen) $ \(a, v) ->
      norm (a *^ v) `scalarClose` (abs a * norm v)

  it "norm (normalize v) == 1 for non-zero v" $
    forAll (gen `suchThat` ((> 1e-3) . norm)) $ \v ->
      norm (normalize v) `scalarClose` 1

  it "normalize v points in the direction of v" $
    forAll (gen `suchThat` ((> 1e-3) . norm)) $ \v ->
      norm v *^ normalize v ~= v

  it "normalize zeroVector is an error mentioning normalize" $
    evaluate (sum (components (normalize zero)))
      `shouldThrow` (\(ErrorCall msg) -> "normalize" `isInfixOf` msg)

------------------------------------------------------------------------------
-- Spec

spec :: Spec
spec = do
  describe "laws" $ do
    laws "Double" genScalar
    laws "(Double, Double)" genPair
    laws "(Double, Double, Double)" genTriple
    laws "(Double, Double, Double, Double)" genQuadruple
    laws "(Double, Double, Double, Double, Double)" genQuintuple
    laws "Vector2 Double" genVector2
    laws "Vector3 Double" genVector3

  describe "fixed examples" $ do
    it "Double: dot is multiplication and norm is abs" $ do
      dot (3 :: Double) (-4) `shouldBe` (-12)
      norm (-2.5 :: Double) `shouldBe` 2.5
      normalize (-7 :: Double) `shouldBe` (-1)

    it "Float: arithmetic, dot and norm" $ do
      (2 *^ (1.5 :: Float)) ^+^ 1 `shouldBe` 4
      (10 :: Float) ^-^ 4 ^/ 2 `shouldBe` 8
      dot (3 :: Float) 5 `shouldBe` 15
      norm (-3 :: Float) `shouldBe` 3

    it "pairs" $ do
      (1, 2) ^+^ (10, 20) `shouldBe` (11, 22 :: Double)
      (1, 2) ^-^ (10, 20) `shouldBe` (-9, -18 :: Double)
      3 *^ (1, -2) `shouldBe` (3, -6 :: Double)
      (3, -6) ^/ 3 `shouldBe` (1, -2 :: Double)
      negateVector (1, -2) `shouldBe` (-1, 2 :: Double)
      dot (1, 2) (3, 4 :: Double) `shouldBe` 11
      norm (3, 4 :: Double) `shouldBe` 5
      normalize (0, -5) `shouldBe` (0, -1 :: Double)
      (zeroVector :: (Double, Double)) `shouldBe` (0, 0)

    it "pairs of literals default to Double" $
      norm (6, 8) `shouldBe` (10 :: Double)

    it "triples" $ do
      (1, 2, 3) ^-^ (3, 2, 1) `shouldBe` (-2, 0, 2 :: Double)
      2 *^ (1, 2, 3) `shouldBe` (2, 4, 6 :: Double)
      dot (1, 2, 3) (4, 5, 6 :: Double) `shouldBe` 32
      norm (2, 3, 6 :: Double) `shouldBe` 7

    it "Vector2" $ do
      Vector2 1 2 ^+^ Vector2 10 20 `shouldBe` Vector2 11 (22 :: Double)
      Vector2 1 2 ^-^ Vector2 10 20 `shouldBe` Vector2 (-9) (-18 :: Double)
      2 *^ Vector2 1 (-3) `shouldBe` Vector2 2 (-6 :: Double)
      Vector2 4 (-8) ^/ 4 `shouldBe` Vector2 1 (-2 :: Double)
      negateVector (Vector2 1 (-2)) `shouldBe` Vector2 (-1) (2 :: Double)
      dot (Vector2 1 2) (Vector2 3 (4 :: Double)) `shouldBe` 11
      norm (Vector2 (-3) (4 :: Double)) `shouldBe` 5
      normalize (Vector2 0 (3 :: Double)) `shouldBe` Vector2 0 1
      (zeroVector :: Vector2 Double) `shouldBe` Vector2 0 0

    it "Vector3" $ do
      Vector3 1 2 3 ^+^ Vector3 10 20 30 `shouldBe` Vector3 11 22 (33 :: Double)
      Vector3 1 2 3 ^-^ Vector3 3 2 1 `shouldBe` Vector3 (-2) 0 (2 :: Double)
      2 *^ Vector3 1 2 3 `shouldBe` Vector3 2 4 (6 :: Double)
      dot (Vector3 1 2 3) (Vector3 4 5 (6 :: Double)) `shouldBe` 32
      norm (Vector3 2 (-3) (6 :: Double)) `shouldBe` 7
      normalize (Vector3 0 0 (-2 :: Double)) `shouldBe` Vector3 0 0 (-1)
      (zeroVector :: Vector3 Double) `shouldBe` Vector3 0 0 0

    it "fixities: *^ binds tighter than ^+^, and ^-^ is left-associative" $ do
      2 *^ (1, 1) ^+^ 3 *^ (1, 0) `shouldBe` (5, 2 :: Double)
      (10, 10) ^-^ (1, 1) ^-^ (1, 1) `shouldBe` (8, 8 :: Double)
      1 + (1, 2) `dot` (3, 4) `shouldBe` (12 :: Double)

    it "fixities: *^ and ^/ are Yampa's (infixr 9, infixl 9), tighter than ^, * and dot" $ do
      -- (2 *^ 3) ^ 2, not 2 *^ (3 ^ 2); (8 ^/ 2) ^ 2, not 8 ^/ (2 ^ 2)
      2 *^ 3 ^ (2 :: Int) `shouldBe` (36 :: Double)
      8 ^/ 2 ^ (2 :: Int) `shouldBe` (16 :: Double)
      -- (2 *^ (1, 2)) `dot` (3, 4), as Yampa parses it
      2 *^ (1, 2) `dot` (3, 4) `shouldBe` (22 :: Double)
      (1, 2) ^/ 2 `dot` (2, 2) `shouldBe` (3 :: Double)
