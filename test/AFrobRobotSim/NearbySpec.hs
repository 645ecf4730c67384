-- | The points gathered near a place ("AFrobRobotSim.Nearby") are exactly
-- those a look at every point of the index finds, and what is made of
-- them (the bound, the fold, the sorted list) is what the plain list
-- functions below make of those: on random points, with many at equal
-- distances (a lattice), few (the index scanned) and many (its cells
-- walked, the list sorted a band at a time).
module AFrobRobotSim.NearbySpec (spec) where

import           Data.List                  (sort, sortOn)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.Nearby
import           AFrobRobotSim.SpatialIndex

-- | Points of an index, a place, a distance to gather within and a point
-- to skip (-1 for none).
data Case = Case [(Double, Double)] (Double, Double) Double Int
  deriving Show

-- | Up to 40 random points over a square of up to 20 m with a place in
-- it, or a lattice of 0.5 m of up to 400 points (so that many are equally
-- far from a lattice place) with a place on it or near it; a distance of
-- 1 to 6 m.
genCase :: Gen Case
genCase = do
  (pts, place) <- oneof
    [ do side <- elements [3, 8, 20]
         n <- chooseInt (0, 40)
         pts <- vectorOf n ((,) <$> choose (0, side) <*> choose (0, side))
         place <- (,) <$> choose (0, side) <*> choose (0, side)
         pure (pts, place)
    , do k <- chooseInt (1, 20)
         let pts = [ (0.5 * fromIntegral i, 0.5 * fromIntegral j) | i <- [0 .. k - 1], j <- [0 .. k - 1 :: Int] ]
             side = 0.5 * fromIntegral (k - 1)
         place <- oneof [ (\i j -> (0.5 * fromIntegral i, 0.5 * fromIntegral j)) <$> chooseInt (0, k - 1) <*> chooseInt (0, k - 1)
                        , (,) <$> choose (0, side) <*> choose (0, side) ]
         pure (pts, place) ]
  r <- elements [1, 2.5, 4.001] >>= \r0 -> oneof [pure r0, choose (1, 6)]
  skip <- chooseInt (-1, length pts - 1)
  pure (Case pts place r skip)

-- | A property of every case, with the share of cases that reach the
-- window's walk (more than 32 points) and the bands (more than 16
-- gathered) checked.
forCases :: Testable p => (Case -> p) -> Property
forCases p = checkCoverage $ forAll genCase $ \c@(Case pts _ _ _) ->
  cover 20 (length pts > 32) "the index's cells walked" $
  cover 15 (length (reference c) > 16) "more than 16 gathered" $
  p c

-- | The index of the points, over their square (and the place).
indexOf :: Case -> PointIndex
indexOf (Case pts (px, py) _ _) =
  let xs = px : map fst pts
      ys = py : map snd pts
  in pointIndex (minimum xs) (minimum ys) (maximum xs) (maximum ys) pts

-- | 'gatherNear' of a case.
gathered :: Case -> Gathered
gathered c@(Case _ (px, py) r skip) = gatherNear r (indexOf c) skip px py

-- | Every point within the distance, but the one skipped, looked at one
-- by one: its number, coordinates and squared distance (computed as the
-- gathering computes it).
reference :: Case -> [(Int, Double, Double, Double)]
reference (Case pts (px, py) r skip) =
  [ (j, x, y, d2) | (j, (x, y)) <- zip [0 ..] pts, j /= skip
                  , let dx = x - px, let dy = y - py, let d2 = dx * dx + dy * dy
                  , d2 <= r * r ]

-- | The points a fold over a selection visits: coordinates and squared
-- distance.
visited :: Gathered -> Some -> [(Double, Double, Double)]
visited = foldNear (\acc x y d2 -> (x, y, d2) : acc) []

-- | The reference's points: coordinates and squared distance.
referencePoints :: Case -> [(Double, Double, Double)]
referencePoints c = [ (x, y, d2) | (_, x, y, d2) <- reference c ]

spec :: Spec
spec = do
  describe "gatherNear, foldNear and allNear" $ do
    it "gather every point within the distance but the one skipped, and only those" $
      forCases $ \c ->
        let g = gathered c
        in sort (visited g (allNear g)) === sort (referencePoints c)
    it "gathers within 0 for a negative or NaN distance" $ do
      let at0 n = Case ((0, 0) : [ (0.1 * fromIntegral i, 1) | i <- [1 .. n :: Int] ]) (0, 0)
          found c = let g = gathered c in visited g (allNear g)
      -- 5 points (the index scanned) and 50 (its cells walked)
      map found [at0 4 (-1) (-1), at0 49 (-1) (-1), at0 4 (0 / 0) (-1), at0 49 (0 / 0) (-1)]
        `shouldBe` replicate 4 [(0, 0, 0)]
      nearestOf (gathered (at0 49 (-1) 0)) `shouldBe` 0

  describe "selectNear" $
    it "selects the gathered points that pass the test, and foldNear visits those" $
      forCases $ \c@(Case _ (px, _) _ _) ->
        let g = gathered c
            keep x _ d2 = x >= px && d2 <= 4
        in sort (visited g (selectNear keep g))
             === sort [ p | p@(x, y, d2) <- referencePoints c, keep x y d2 ]

  describe "nearestOf" $ do
    it "is the distance to the nearest gathered point, the distance gathered within if none, 0 beyond 16" $
      forCases $ \c@(Case _ _ r _) ->
        let ref = reference c
        in nearestOf (gathered c)
             === (if length ref > 16 then 0
                  else sqrt (minimum ((r * r) : [ d2 | (_, _, _, d2) <- ref ])))
    it "is 0 for 17 gathered points, and not for 16" $ do
      let row k = Case [ (5 + 0.2 * fromIntegral i, 5) | i <- [1 .. k :: Int] ] (5, 5) 4.001 (-1)
      nearestOf (gathered (row 16)) `shouldBe` sqrt ((5.2 - 5) * (5.2 - 5))
      nearestOf (gathered (row 17)) `shouldBe` 0
    it "is never above the distance to a point of the index not skipped" $
      forCases $ \c@(Case pts (px, py) _ skip) ->
        let b = nearestOf (gathered c)
        in conjoin [ counterexample (show p) (b <= sqrt ((x - px) ^ (2 :: Int) + (y - py) ^ (2 :: Int)))
                   | (j, p@(x, y)) <- zip [0 ..] pts, j /= skip ]

  describe "inRangeSorted" $ do
    it "lists the points within the range, nearest first, in index order among equally near ones" $
      forCases $ \c@(Case _ _ r _) -> forAll (elements [r, r / 2, 4]) $ \range ->
        let range' = min r range
        in inRangeSorted range' (\d j x y -> (d, j, x, y)) (gathered c)
             === sortOn (\(d, j, _, _) -> (d, j))
                   [ (d, j, x, y) | (j, x, y, d2) <- reference c, let d = sqrt d2, d <= range' ]
    it "puts first the place's own point of a lattice, in a crowd sorted a band at a time" $ do
      -- 400 points of a lattice of 0.5 m, about 200 within 4 m of (5, 5),
      -- the 211th (number 210) at (5, 5) itself
      let c = Case [ (0.5 * fromIntegral i, 0.5 * fromIntegral j) | i <- [0 .. 19 :: Int], j <- [0 .. 19 :: Int] ]
                   (5, 5) 4.001 (-1)
          xs = inRangeSorted 4 (\d j _ _ -> (d, j)) (gathered c)
      take 1 xs `shouldBe` [(0, 210)]
      length xs `shouldBe` length [ () | (_, _, _, d2) <- reference c, sqrt d2 <= 4 ]
