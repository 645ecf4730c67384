-- | Fixed hand-computed cases and brute-force properties for
-- "AFrobRobotSim.Shapes": ray casts, swept disc collisions, penetration and
-- reflection.
module AFrobRobotSim.ShapesSpec (spec) where

import Test.Hspec
import Test.QuickCheck

import AFRP.Geometry (Point2 (..), Vector2 (..))
import AFrobRobotSim.Shapes

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

  describe "sweepCircleBox" $ do
    it "finds a corner of the box on a move so long that its squared length overflows" $
      -- (the discriminant was infinite or NaN, read as a miss: a robot
      -- stepped 1e200 m passed the corner of a wall, ending 0.07 m in it)
      property $ forAll (choose (1e160, 1e300)) $ \far ->
        case sweepCircleBox (Point2 (-0.75) (-0.45)) 0.25 (Vector2 0 (negate far)) (Box (-0.65) (-1.5) 0.35 (-1.4)) of
          Just (s, Vector2 nx ny) -> counterexample (show (s, nx, ny)) $
            abs (s * far - (0.95 - sqrt (0.25 * 0.25 - 0.1 * 0.1))) < 1e-12
            .&&. abs (nx + 0.4) < 1e-12 .&&. ny > 0
          Nothing -> counterexample "missed the corner" False
    let wall = Box 0 (-5) 0.1 5          -- a thin 0.1 m wall
        unit = Box 0 0 1 1
    it "hits a side head-on" $ do
      sweepCircleBox (Point2 (-1) 0) 0.2 (Vector2 2 0) wall
        `shouldContact` Just (0.4, Vector2 (-1) 0)
      sweepCircleBox (Point2 1 0) 0.2 (Vector2 (-2) (-0.0)) wall
        `shouldContact` Just (0.35, Vector2 1 0)
      sweepCircleBox (Point2 0.5 3) 0.5 (Vector2 0 (-4)) unit
        `shouldContact` Just (0.375, Vector2 0 1)
    it "does not tunnel through a thin wall" $ do
      -- both end positions are clear of the wall
      sweepCircleBox (Point2 (-1) 0) 0.2 (Vector2 100 0) wall
        `shouldContact` Just (0.008, Vector2 (-1) 0)
      sweepCircleBox (Point2 (-0.5) 0) 0.2 (Vector2 1 0) wall
        `shouldContact` Just (0.3, Vector2 (-1) 0)
      sweepCircleBox (Point2 (-3) (-1)) 0.2 (Vector2 10 2) wall
        `shouldContact` Just (0.28, Vector2 (-1) 0)
      sweepCircleBox (Point2 1e3 0) 0.2 (Vector2 (-1e4) 0) wall
        `shouldContact` Just ((1e3 - 0.3) / 1e4, Vector2 1 0)
    it "hits a corner obliquely" $ do
      -- centre at (-0.4, -0.3) is 0.5 from the corner (0, 0)
      sweepCircleBox (Point2 (-1) (-0.3)) 0.5 (Vector2 2 0) unit
        `shouldContact` Just (0.3, Vector2 (-0.8) (-0.6))
      -- diagonally into the corner (1, 1)
      sweepCircleBox (Point2 3 3) 0.5 (Vector2 (-2) (-2)) unit
        `shouldContact` Just ((2 - 0.5 * sqrt 0.5) / 2,
                              Vector2 (sqrt 0.5) (sqrt 0.5))
    it "does not report a graze along a side" $ do
      sweepCircleBox (Point2 (-1) (-0.5)) 0.5 (Vector2 3 0) unit
        `shouldBe` Nothing
      sweepCircleBox (Point2 (-1) (-0.50001)) 0.5 (Vector2 3 0) unit
        `shouldBe` Nothing
    it "misses when passing by" $ do
      sweepCircleBox (Point2 (-1) 2) 0.5 (Vector2 3 0) unit `shouldBe` Nothing
      sweepCircleBox (Point2 (-1) 0.5) 0.5 (Vector2 (-3) 0) unit
        `shouldBe` Nothing
    it "stops short, or touches exactly at the end of the move" $ do
      sweepCircleBox (Point2 (-1) 0.5) 0.5 (Vector2 0.4 0) unit
        `shouldBe` Nothing
      sweepCircleBox (Point2 (-1) 0.5) 0.5 (Vector2 0.5 0) unit
        `shouldContact` Just (1, Vector2 (-1) 0)
    it "starting in contact: moving in is a contact at 0" $ do
      sweepCircleBox (Point2 (-0.5) 0.5) 0.5 (Vector2 0.1 0) unit
        `shouldBe` Just (0, Vector2 (-1) 0)
      sweepCircleBox (Point2 (-0.2) 0.5) 0.5 (Vector2 0.1 0.05) unit
        `shouldBe` Just (0, Vector2 (-1) 0)
      sweepCircleBox (Point2 (-0.3) (-0.4)) 1 (Vector2 0.3 0.1) unit
        `shouldContact` Just (0, Vector2 (-0.6) (-0.8))
    it "starting in contact: moving away or along is free" $ do
      sweepCircleBox (Point2 (-0.5) 0.5) 0.5 (Vector2 (-0.1) 0) unit
        `shouldBe` Nothing
      sweepCircleBox (Point2 (-0.5) 0.5) 0.5 (Vector2 0 0.1) unit
        `shouldBe` Nothing
      sweepCircleBox (Point2 (-0.2) 0.5) 0.5 (Vector2 (-0.1) 0.3) unit
        `shouldBe` Nothing
    it "centre inside the box: the way out is the nearest side" $ do
      sweepCircleBox (Point2 0.2 0.5) 0.1 (Vector2 0.1 0) unit
        `shouldBe` Just (0, Vector2 (-1) 0)
      sweepCircleBox (Point2 0.2 0.5) 0.1 (Vector2 (-0.1) 0) unit
        `shouldBe` Nothing
    it "a zero displacement is never a contact" $ do
      sweepCircleBox (Point2 (-1) 0) 0.2 (Vector2 0 0) wall `shouldBe` Nothing
      sweepCircleBox (Point2 0.5 0.5) 0.2 (Vector2 (-0.0) 0) unit
        `shouldBe` Nothing
    it "returns +0.0, not -0.0, for an initial contact" $
      fmap (isNegativeZero . fst)
           (sweepCircleBox (Point2 (-0.5) 0.5) 0.5 (Vector2 0.1 (-0.0)) unit)
        `shouldBe` Just False

  describe "sweepCircleCircle" $ do
    it "finds the disc on a move so long that its squared length overflows" $
      property $ forAll (choose (1e160, 1e300)) $ \far ->
        case sweepCircleCircle (Point2 0 0) 0.25 (Vector2 far 0) (Point2 1 0.3) 0.25 of
          Just (s, Vector2 nx ny) -> counterexample (show (s, nx, ny)) $
            abs (s * far - 0.6) < 1e-12 .&&. abs (nx + 0.8) < 1e-12 .&&. abs (ny + 0.6) < 1e-12
          Nothing -> counterexample "missed the disc" False
    let q = Point2 0 0
    it "hits head-on" $
      sweepCircleCircle (Point2 (-3) 0) 0.5 (Vector2 3 0) q 1
        `shouldContact` Just (0.5, Vector2 (-1) 0)
    it "hits obliquely" $
      -- contact at (-1.2, 0.9), 1.5 from q
      sweepCircleCircle (Point2 (-3) 0.9) 0.5 (Vector2 4 0) q 1
        `shouldContact` Just (0.45, Vector2 (-0.8) 0.6)
    it "does not tunnel with a long displacement" $
      sweepCircleCircle (Point2 (-3) 0) 0.5 (Vector2 1000 0) q 1
        `shouldContact` Just (0.0015, Vector2 (-1) 0)
    it "grazing or passing by is not a contact" $ do
      sweepCircleCircle (Point2 (-3) 1.5) 0.5 (Vector2 6 0) q 1
        `shouldBe` Nothing
      sweepCircleCircle (Point2 (-3) 2) 0.5 (Vector2 6 0) q 1
        `shouldBe` Nothing
      sweepCircleCircle (Point2 (-3) 0) 0.5 (Vector2 (-6) 0) q 1
        `shouldBe` Nothing
    it "stops short" $
      sweepCircleCircle (Point2 (-3) 0) 0.5 (Vector2 1 0) q 1
        `shouldBe` Nothing
    it "starting in contact: moving in vs away or along" $ do
      sweepCircleCircle (Point2 (-1.5) 0) 0.5 (Vector2 0.1 0) q 1
        `shouldBe` Just (0, Vector2 (-1) 0)
      sweepCircleCircle (Point2 (-1.5) 0) 0.5 (Vector2 (-0.1) 0) q 1
        `shouldBe` Nothing
      sweepCircleCircle (Point2 (-1.5) 0) 0.5 (Vector2 0 1) q 1
        `shouldBe` Nothing
      sweepCircleCircle (Point2 0.6 0.8) 0.5 (Vector2 (-1) 0) q 1
        `shouldContact` Just (0, Vector2 0.6 0.8)
    it "coincident centres use the +x normal" $ do
      sweepCircleCircle q 0.5 (Vector2 (-1) 0) q 1
        `shouldBe` Just (0, Vector2 1 0)
      sweepCircleCircle q 0.5 (Vector2 1 0) q 1 `shouldBe` Nothing
    it "a zero displacement is never a contact" $
      sweepCircleCircle (Point2 (-1) 0) 0.5 (Vector2 0 0) q 1
        `shouldBe` Nothing
    it "a point against a point never collides" $
      sweepCircleCircle (Point2 (-1) 0) 0 (Vector2 2 0) q 0 `shouldBe` Nothing

  describe "circleBoxPenetration" $ do
    let unit = Box 0 0 1 1
    it "centre beside a side" $
      circleBoxPenetration (Point2 (-0.3) 0.5) 0.5 unit
        `shouldContact` Just (0.2, Vector2 (-1) 0)
    it "centre beside a corner" $
      circleBoxPenetration (Point2 (-0.3) (-0.4)) 1 unit
        `shouldContact` Just (0.5, Vector2 (-0.6) (-0.8))
    it "touching or apart is no penetration" $ do
      circleBoxPenetration (Point2 (-0.5) 0.5) 0.5 unit `shouldBe` Nothing
      circleBoxPenetration (Point2 5 5) 0.5 unit `shouldBe` Nothing
      circleBoxPenetration (Point2 1 0.5) 0 unit `shouldBe` Nothing
    it "centre inside: the shortest way out" $ do
      circleBoxPenetration (Point2 0.9 0.5) 0.2 unit
        `shouldContact` Just (0.3, Vector2 1 0)
      circleBoxPenetration (Point2 0.5 0.95) 0.1 unit
        `shouldContact` Just (0.15, Vector2 0 1)
      circleBoxPenetration (Point2 0.5 0.2) 0 unit
        `shouldContact` Just (0.2, Vector2 0 (-1))
    it "centre on the boundary" $
      circleBoxPenetration (Point2 1 0.5) 0.2 unit
        `shouldBe` Just (0.2, Vector2 1 0)
    it "breaks ties left, right, bottom, top" $
      circleBoxPenetration (Point2 0.5 0.5) 0.1 unit
        `shouldBe` Just (0.6, Vector2 (-1) 0)

  describe "circleCirclePenetration" $ do
    it "overlapping discs" $ do
      circleCirclePenetration (Point2 0 0) 1 (Point2 1.5 0) 1
        `shouldContact` Just (0.5, Vector2 (-1) 0)
      circleCirclePenetration (Point2 3 4) 3 (Point2 0 0) 3
        `shouldContact` Just (1, Vector2 0.6 0.8)
    it "touching or apart is no penetration" $ do
      circleCirclePenetration (Point2 2 0) 1 (Point2 0 0) 1 `shouldBe` Nothing
      circleCirclePenetration (Point2 5 0) 1 (Point2 0 0) 1 `shouldBe` Nothing
    it "coincident centres use the +x normal" $
      circleCirclePenetration (Point2 1 1) 1 (Point2 1 1) 1
        `shouldBe` Just (2, Vector2 1 0)

  describe "reflect" $ do
    it "reverses the normal component" $ do
      reflect (Vector2 1 (-1)) (Vector2 0 1) `shouldBe` Vector2 1 1
      reflect (Vector2 3 4) (Vector2 1 0) `shouldBe` Vector2 (-3) 4
      reflect (Vector2 3 4) (Vector2 (-1) 0) `shouldBe` Vector2 (-3) 4
    it "keeps a tangential velocity" $
      reflect (Vector2 0 2) (Vector2 1 0) `shouldBe` Vector2 0 2
    prop "preserves the speed and is an involution" $
      forAll ((,) <$> (Vector2 <$> choose (-100, 100) <*> choose (-100, 100))
                  <*> ((\a -> Vector2 (cos a) (sin a)) <$> choose (-pi, pi))) $
        \(v, n) ->
          let w = reflect v n
          in counterexample (show w) $
               closeWithin 1e-12 (len w) (len v)
               .&&. counterexample (show (reflect w n))
                      (nearV 1e-12 (reflect w n) v)

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

    prop "sweepCircleBox: a contact is exact and preceded by no overlap" $
      forAll genBoxSweep $ \(BoxSweep p r d b) ->
        let res = sweepCircleBox p r d b
        in cover 20 (res /= Nothing) "contact" $
           case res of
             Nothing -> property True
             Just sn -> contactOk d p r (\x -> circleBoxPenetration x r b)
                                  (`distToBox` b) sn

    prop "sweepCircleBox: no contact means a collision-free move" $
      forAll genBoxSweep $ \(BoxSweep p r d b) ->
        sweepCircleBox p r d b == Nothing ==>
          clearMove p d (\x -> circleBoxPenetration x r b)

    prop "sweepCircleBox: from a contact, Just (0, n) into it or free away" $
      forAll genBoxContact $ \(BoxSweep p r d b) ->
        case sweepCircleBox p r d b of
          Just (s, n) -> counterexample (show (s, n)) $
                           s == 0 && dotV d n < 0 && abs (len n - 1) < 1e-12
          Nothing     -> nonDeepening p d (\x -> circleBoxPenetration x r b)

    prop "sweepCircleCircle: a contact is exact and preceded by no overlap" $
      forAll (genCircleSweep False) $ \(CircleSweep p r d q rq) ->
        let res = sweepCircleCircle p r d q rq
        in cover 20 (res /= Nothing) "contact" $
           case res of
             Nothing -> property True
             Just sn -> contactOk d p r
                          (\x -> circleCirclePenetration x r q rq)
                          (\x -> len (vec x q) - rq) sn

    prop "sweepCircleCircle: no contact means a collision-free move" $
      forAll (genCircleSweep False) $ \(CircleSweep p r d q rq) ->
        sweepCircleCircle p r d q rq == Nothing ==>
          clearMove p d (\x -> circleCirclePenetration x r q rq)

    prop "sweepCircleCircle: from a contact, Just (0, n) into it or free away" $
      forAll (genCircleSweep True) $ \(CircleSweep p r d q rq) ->
        case sweepCircleCircle p r d q rq of
          Just (s, n) -> counterexample (show (s, n)) $
                           s == 0 && dotV d n < 0 && abs (len n - 1) < 1e-12
          Nothing     ->
            nonDeepening p d (\x -> circleCirclePenetration x r q rq)

    prop "circleBoxPenetration: pushing out by depth along n separates" $
      forAll genBox $ \b@(Box x0 y0 x1 y1) -> forAll genRadius $ \r ->
      forAll (genPointIn (Box (x0 - r) (y0 - r) (x1 + r) (y1 + r))) $ \p ->
        case circleBoxPenetration p r b of
          Nothing -> counterexample "missed overlap" (distToBox p b >= r)
          Just (e, n) ->
            let p' = add p e n
            in counterexample (show (e, n, p')) $
                 e > 0 && abs (len n - 1) < 1e-12
                 && abs (distToBox p' b - r) < 1e-9

    prop "circleCirclePenetration: pushing out by depth along n separates" $
      forAll (genCircleSweep True) $ \(CircleSweep p r _ q rq) ->
        case circleCirclePenetration p r q rq of
          Nothing -> counterexample "missed overlap" (len (vec p q) >= r + rq)
          Just (e, n) ->
            let p' = add p e n
            in counterexample (show (e, n, p')) $
                 e > 0 && abs (len n - 1) < 1e-12
                 && abs (len (vec p' q) - (r + rq)) < 1e-9
  where
    vec (Point2 a b) (Point2 c d) = Vector2 (a - c) (b - d)
    prop :: Testable p => String -> p -> Spec
    prop name = it name . property
