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

-- | Up to 40 random points, or a lattice of 0.5 m (so that many are
-- equally far from a lattice place) of up to 400, over a square of up to
-- 20 m; a place in it; a distance of 1 to 6 m.
genCase :: Gen Case
genCase = do
  side <- elements [3, 8, 20]
  pts <- oneof
    [ do n <- chooseInt (0, 40)
         vectorOf n ((,) <$> choose (0, side) <*> choose (0, side))
    , do k <- chooseInt (1, 20)
         pure [ (0.5 * fromIntegral i, 0.5 * fromIntegral j) | i <- [0 .. k - 1], j <- [0 .. k - 1 :: Int] ] ]
  place <- oneof [ (,) <$> choose (0, side) <*> choose (0, side)
                 , (\i j -> (0.5 * fromIntegral i, 0.5 * fromIntegral j)) <$> chooseInt (0, 8) <*> chooseInt (0, 8 :: Int) ]
  r <- elements [1, 2.5, 4.001] >>= \r0 -> oneof [pure r0, choose (1, 6)]
  skip <- chooseInt (-1, length pts - 1)
  pure (Case pts place r skip)

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

spec :: Spec
spec = do
  describe "gatherNear, foldNear and allNear" $
    it "gather every point within the distance but the one skipped, and only those" $
      property $ forAll genCase $ \c ->
        let g = gathered c
        in sort (foldNear (\acc x y d2 -> (x, y, d2) : acc) [] g (allNear g))
             === sort [ (x, y, d2) | (_, x, y, d2) <- reference c ]

  describe "selectNear" $
    it "selects the gathered points that pass the test, and foldNear visits those" $
      property $ forAll genCase $ \c@(Case _ (px, _) _ _) ->
        let g = gathered c
            keep x _ d2 = x >= px && d2 <= 4
        in sort (foldNear (\acc x y d2 -> (x, y, d2) : acc) [] g (selectNear keep g))
             === sort [ (x, y, d2) | (_, x, y, d2) <- reference c, keep x y d2 ]

  describe "nearestOf" $ do
    it "is the distance to the nearest gathered point, the distance gathered within if none, 0 beyond 16" $
      property $ forAll genCase $ \c@(Case _ _ r _) ->
        let ref = reference c
        in nearestOf (gathered c)
             === (if length ref > 16 then 0
                  else sqrt (minimum ((r * r) : [ d2 | (_, _, _, d2) <- ref ])))
    it "is 0 for 17 gathered points, and not for 16" $ do
      let row k = Case [ (5 + 0.2 * fromIntegral i, 5) | i <- [1 .. k :: Int] ] (5, 5) 4.001 (-1)
      nearestOf (gathered (row 16)) `shouldBe` sqrt ((5.2 - 5) * (5.2 - 5))
      nearestOf (gathered (row 17)) `shouldBe` 0
    it "is never above the distance to a point of the index not skipped" $
      property $ forAll genCase $ \c@(Case pts (px, py) _ skip) ->
        let b = nearestOf (gathered c)
        in conjoin [ counterexample (show p) (b <= sqrt ((x - px) ^ (2 :: Int) + (y - py) ^ (2 :: Int)))
                   | (j, p@(x, y)) <- zip [0 ..] pts, j /= skip ]

  describe "inRangeSorted" $ do
    it "lists the points within the range, nearest first, in index order among equally near ones" $
      property $ forAll genCase $ \c@(Case _ _ r _) -> forAll (elements [r, r / 2, 4]) $ \range ->
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
