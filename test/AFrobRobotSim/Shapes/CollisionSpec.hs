-- | Hand-computed cases and brute-force properties for
-- "AFrobRobotSim.Shapes.Collision": swept disc collisions, penetration and
-- reflection.
module AFrobRobotSim.Shapes.CollisionSpec (spec) where

import Test.Hspec
import Test.QuickCheck

import AFRP.Geometry (Point2 (..), Vector2 (..))
import AFrobRobotSim.Shapes.Box (Box (..))
import AFrobRobotSim.Shapes.Collision
import AFrobRobotSim.ShapesFixture

spec :: Spec
spec = do
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
