-- | Shared by the specs of "AFrobRobotSim.Shapes.Box", "AFrobRobotSim.Shapes.Ray"
-- and "AFrobRobotSim.Shapes.Collision": approximate comparisons, an
-- independent reference geometry (which does not use the modules under
-- test) and generators of boxes, rays and moving discs.
module AFrobRobotSim.ShapesFixture
  ( -- * Approximate comparison
    closeWithin, nearV, shouldHitAt, shouldContact
    -- * Reference geometry
  , add, len, dotV, vec, distToBox, inBox, inCircle, depthOf, noOverlap
    -- * Generators
  , genBox, genRadius, genPoint, genPointIn, genDir, genDisp, genOrigin
  , BoxSweep (..), CircleSweep (..), genBoxSweep, genBoxContact, genCircleSweep
  , samples
    -- * Properties
  , contactOk, clearMove, nonDeepening, marchAgrees, prop
  ) where

import Test.Hspec
import Test.QuickCheck

import AFRP.Geometry (Point2 (..), Vector2 (..))
import AFrobRobotSim.Shapes.Box (Box (..), boxAround)
import AFrobRobotSim.Shapes.Collision (circleBoxPenetration)

------------------------------------------------------------------------------
-- Approximate comparison

closeWithin :: Double -> Double -> Double -> Bool
closeWithin eps x y = abs (x - y) <= eps * max 1 (max (abs x) (abs y))

nearV :: Double -> Vector2 Double -> Vector2 Double -> Bool
nearV eps (Vector2 a b) (Vector2 c d) = closeWithin eps a c && closeWithin eps b d

-- | A ray-cast result is within 1e-12 of the expected one.
shouldHitAt :: HasCallStack => Maybe Double -> Maybe Double -> Expectation
shouldHitAt got want = case (got, want) of
  (Just t, Just u) | closeWithin 1e-12 t u -> pure ()
  (Nothing, Nothing)                       -> pure ()
  _ -> expectationFailure (show got ++ " is not within 1e-12 of " ++ show want)
infix 1 `shouldHitAt`

-- | A contact (fraction or depth, normal) is within 1e-12 of the expected
-- one.
shouldContact :: HasCallStack
              => Maybe (Double, Vector2 Double)
              -> Maybe (Double, Vector2 Double) -> Expectation
shouldContact got want = case (got, want) of
  (Just (s, n), Just (s', n'))
    | closeWithin 1e-12 s s' && nearV 1e-12 n n' -> pure ()
  (Nothing, Nothing) -> pure ()
  _ -> expectationFailure (show got ++ " is not within 1e-12 of " ++ show want)
infix 1 `shouldContact`

------------------------------------------------------------------------------
-- Independent reference geometry (no use of the module under test)

add :: Point2 Double -> Double -> Vector2 Double -> Point2 Double
add (Point2 x y) k (Vector2 u v) = Point2 (x + k * u) (y + k * v)

len :: Vector2 Double -> Double
len (Vector2 x y) = sqrt (x * x + y * y)

dotV :: Vector2 Double -> Vector2 Double -> Double
dotV (Vector2 a b) (Vector2 c d) = a * c + b * d

-- | Euclidean distance from a point to a (closed) box; 0 inside.
distToBox :: Point2 Double -> Box -> Double
distToBox (Point2 x y) (Box x0 y0 x1 y1) = sqrt (ex * ex + ey * ey)
  where
    ex = max 0 (max (x0 - x) (x - x1))
    ey = max 0 (max (y0 - y) (y - y1))

inBox :: Point2 Double -> Box -> Bool
inBox (Point2 x y) (Box x0 y0 x1 y1) = x0 <= x && x <= x1 && y0 <= y && y <= y1

inCircle :: Point2 Double -> Point2 Double -> Double -> Bool
inCircle (Point2 x y) (Point2 cx cy) r = dx * dx + dy * dy <= r * r
  where
    dx = x - cx
    dy = y - cy

depthOf :: Maybe (Double, Vector2 Double) -> Double
depthOf = maybe 0 fst

-- | @Nothing@ or a depth below 1e-9: "no overlap to speak of".
noOverlap :: Maybe (Double, Vector2 Double) -> Bool
noOverlap = (< 1e-9) . depthOf

------------------------------------------------------------------------------
-- Generators

genBox :: Gen Box
genBox = do
  cx <- choose (-5, 5)
  cy <- choose (-5, 5)
  w  <- oneof [choose (0.05, 4), pure 0.1]
  h  <- oneof [choose (0.05, 4), pure 0.1, choose (4, 10)]
  pure (boxAround (Point2 cx cy) w h)

genRadius :: Gen Double
genRadius = choose (0.05, 1)

genPoint :: Gen (Point2 Double)
genPoint = Point2 <$> choose (-10, 10) <*> choose (-10, 10)

genPointIn :: Box -> Gen (Point2 Double)
genPointIn (Box x0 y0 x1 y1) = Point2 <$> choose (x0, x1) <*> choose (y0, y1)

-- | Unit directions, a third of them axis-parallel with a zero component of
-- either sign.
genDir :: Gen (Vector2 Double)
genDir = frequency
  [ (2, (\a -> Vector2 (cos a) (sin a)) <$> choose (-pi, pi))
  , (1, elements [ Vector2 1 0, Vector2 1 (-0.0), Vector2 (-1) 0
                 , Vector2 (-1) (-0.0), Vector2 0 1, Vector2 (-0.0) 1
                 , Vector2 0 (-1), Vector2 (-0.0) (-1) ])
  ]

-- | Displacements from @p@: random, aimed at @target@ (short or very long),
-- or axis-parallel.
genDisp :: Point2 Double -> Point2 Double -> Gen (Vector2 Double)
genDisp (Point2 px py) (Point2 tx ty) = frequency
  [ (2, scale' <$> genDir <*> choose (0, 20))
  , (3, aimed <$> choose (0.2, 3) <*> choose (-0.2, 0.2))
  , (1, aimed <$> choose (10, 200) <*> pure 0)
  , (1, scale' <$> elements [ Vector2 1 (-0.0), Vector2 (-0.0) 1
                            , Vector2 (-1) 0, Vector2 0 (-1) ]
               <*> choose (0, 20))
  ]
  where
    scale' (Vector2 x y) k = Vector2 (k * x) (k * y)
    aimed k e = Vector2 (k * (tx - px) + e) (k * (ty - py) - e)

-- | Ray origins: anywhere, or exactly on the line of an edge of the box (to
-- exercise axis-parallel rays along and through edges).
genOrigin :: Box -> Gen (Point2 Double)
genOrigin (Box x0 y0 x1 y1) = frequency
  [ (3, genPoint)
  , (1, Point2 <$> choose (-10, 10) <*> elements [y0, y1])
  , (1, Point2 <$> elements [x0, x1] <*> choose (-10, 10))
  ]

data BoxSweep = BoxSweep (Point2 Double) Double (Vector2 Double) Box
  deriving Show

data CircleSweep =
  CircleSweep (Point2 Double) Double (Vector2 Double) (Point2 Double) Double
  deriving Show

-- | A disc that does not overlap the box at the start.
genBoxSweep :: Gen BoxSweep
genBoxSweep = do
  b <- genBox
  r <- genRadius
  p <- genPoint `suchThat` \p -> circleBoxPenetration p r b == Nothing
  t <- genPointIn b
  d <- genDisp p t
  pure (BoxSweep p r d b)

-- | A disc that overlaps or touches the box at the start.
genBoxContact :: Gen BoxSweep
genBoxContact = do
  b@(Box x0 y0 x1 y1) <- genBox
  r <- genRadius
  p <- oneof [ genPointIn (Box (x0 - r) (y0 - r) (x1 + r) (y1 + r))
             , genPointIn b ]
         `suchThat` \p -> distToBox p b <= r
  d <- scaleBy <$> genDir <*> choose (0.01, 5)
  pure (BoxSweep p r d b)
  where
    scaleBy (Vector2 x y) k = Vector2 (k * x) (k * y)

genCircleSweep :: Bool -> Gen CircleSweep
genCircleSweep touching = do
  q  <- Point2 <$> choose (-5, 5) <*> choose (-5, 5)
  rq <- choose (0, 3)
  r  <- genRadius
  let Point2 qx qy = q
      near = Point2 <$> choose (qx - r - rq, qx + r + rq)
                    <*> choose (qy - r - rq, qy + r + rq)
  p <- if touching
         then near `suchThat` \p -> inCircle p q (r + rq)
         else genPoint `suchThat` \p -> not (inCircle p q (r + rq))
  d <- genDisp p q
  pure (CircleSweep p r d q rq)

-- | Points sampled along the move, at fractions 0, 1/n, ..., 1.
samples :: Int -> Point2 Double -> Vector2 Double -> [Point2 Double]
samples n p d = [ add p (fromIntegral k / fromIntegral n) d | k <- [0 .. n] ]

------------------------------------------------------------------------------
-- Properties

-- | A contact returned for a disc that starts clear: @s@ in @[0, 1]@, a unit
-- normal facing the motion, the disc exactly touching at @s@ (distance of
-- the centre from the obstacle = r, checked with the given function), and no
-- overlap just before contact.
contactOk :: Vector2 Double -> Point2 Double -> Double
          -> (Point2 Double -> Maybe (Double, Vector2 Double))
          -> (Point2 Double -> Double) -> (Double, Vector2 Double) -> Property
contactOk d p r pen clearance (s, n) =
  counterexample ("s = " ++ show s ++ ", n = " ++ show n) $
  conjoin
    [ counterexample "s not in [0, 1]" (s >= 0 && s <= 1)
    , counterexample "normal not unit" (abs (len n - 1) < 1e-12)
    , counterexample "not moving into the obstacle" (dotV d n <= 0)
    , counterexample ("not touching at contact, clearance " ++ show (clearance c))
        (abs (clearance c - r) < 1e-9)
    , counterexample ("overlap just before contact: " ++ show (pen justBefore))
        (noOverlap (pen justBefore))
    ]
  where
    c      = add p s d
    dl     = len d
    justBefore = add p (max 0 (s * dl - 1e-9) / dl) d

-- | No sampled point along the move overlaps.
clearMove :: Point2 Double -> Vector2 Double
          -> (Point2 Double -> Maybe (Double, Vector2 Double)) -> Property
clearMove p d pen =
  conjoin [ counterexample ("overlap at " ++ show x ++ ": " ++ show (pen x))
              (noOverlap (pen x))
          | x <- samples 200 p d ]

-- | Moving out of an initial contact never deepens it.
nonDeepening :: Point2 Double -> Vector2 Double
             -> (Point2 Double -> Maybe (Double, Vector2 Double)) -> Property
nonDeepening p d pen =
  counterexample ("depths " ++ show ds) $
  and (zipWith (\a b -> b <= a + 1e-9) ds (drop 1 ds))
  where
    ds = map (depthOf . pen) (samples 100 p d)

-- | Agreement of an exact ray cast with a march along the ray (step 1e-3,
-- up to @tMax@, beyond which the shape cannot be). A hit the march misses is
-- accepted only if the exact hit point lies on the shape's boundary and the
-- chord is too short to contain a sample (so the sample nearest to the hit
-- is within 1e-3 of the shape).
marchAgrees :: (Point2 Double -> Bool) -> (Point2 Double -> Double) -> Double
            -> Point2 Double -> Vector2 Double -> Maybe Double -> Property
marchAgrees inside dist tMax o dir exact =
  counterexample ("exact " ++ show exact ++ ", march " ++ show march) $
  case (exact, march) of
    (Nothing, Nothing) -> property True
    (Just t, Just u)   -> property (abs (t - u) <= 2e-3)
    (Nothing, Just _)  -> property False
    (Just t, Nothing)  ->
      counterexample "missed hit not on the boundary" $
        dist (add o t dir) <= 1e-9
        && dist (add o (1e-3 * fromIntegral (round (t / 1e-3) :: Int)) dir)
             <= 1e-3
  where
    h :: Double
    h    = 1e-3
    n    = round (tMax / h) :: Int
    march = go 0
    go k | k > n                               = Nothing
         | inside (add o (fromIntegral k * h) dir) = Just (fromIntegral k * h)
         | otherwise                           = go (k + 1)

------------------------------------------------------------------------------


-- | The vector from the second point to the first.
vec :: Point2 Double -> Point2 Double -> Vector2 Double
vec (Point2 a b) (Point2 c d) = Vector2 (a - c) (b - d)

-- | A named QuickCheck property as an hspec example.
prop :: Testable p => String -> p -> Spec
prop name = it name . property
