-- | "AFrobRobotSim.Clearance": every cell's bound is a lower bound on the
-- distance from each of its points to every box, and is not needlessly
-- small (a point far from everything gets the cap).
module AFrobRobotSim.ClearanceSpec (spec) where

import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.Clearance
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.Arena
import           AFrobRobotSim.WorldGen (arenaFor, boxesExtent, genWorld, halfSide, pointBoxDistance)

-- | Boxes of all shapes (thin walls, blocks, long bars) in a square of
-- half-side @h@, and a finite one always present.
genBoxes :: Double -> Gen [Box]
genBoxes h = do
  n <- chooseInt (1, 30)
  vectorOf n $ do
    x <- choose (-h, h)
    y <- choose (-h, h)
    w <- oneof [choose (0, 0.2), choose (0.2, 2), choose (2, 2 * h)]
    t <- oneof [choose (0, 0.2), choose (0.2, 2)]
    elements [Box x y (x + w) (y + t), Box x y (x + t) (y + w)]

spec :: Spec
spec = do
  describe "clearanceQuanta" $ do
    it "is the largest number of quanta, up to 255, whose distance is at most the given one" $
      property $ forAll (oneof [ choose (0, 1.2)
                               , (\k -> fromIntegral k * clearanceQuantum) <$> chooseInt (0, 260)
                               , (\k e -> fromIntegral (k :: Int) * clearanceQuantum + e) <$> chooseInt (0, 255) <*> elements [-1e-15, 1e-15] ]) $ \d ->
        let q = clearanceQuanta d
        in counterexample (show (d, q)) $
             q >= 0 && q <= 255 && fromIntegral q * clearanceQuantum <= max 0 d
               && (q == 255 || fromIntegral (q + 1) * clearanceQuantum > d)
    it "is k for each multiple of a quantum k times, and 255 from the cap on" $ do
      [ clearanceQuanta (fromIntegral k * clearanceQuantum) | k <- [0 .. 255 :: Int] ] `shouldBe` [0 .. 255]
      map clearanceQuanta [clearanceCap, 1.5, 1 / 0] `shouldBe` [255, 255, 255]
    it "is 0 for a distance that is not positive, or NaN" $
      map clearanceQuanta [0, -0, -1, -1 / 0, 0 / 0] `shouldBe` [0, 0, 0, 0, 0]

  describe "clearanceAt" $ do
    it "is never more than the distance from the point to any box" $
      property $ forAll (elements [5, 20, 200]) $ \h -> forAll (genBoxes h) $ \bs ->
        forAll (vectorOf 50 ((,) <$> choose (-h - 1, 3 * h) <*> choose (-h - 1, 3 * h))) $ \pts ->
          let cl = clearanceOf (boxIndex bs) (boxesExtent bs)
          in conjoin [ counterexample (show (x, y, b)) (clearanceAt cl x y <= pointBoxDistance x y b + 1e-12)
                     | (x, y) <- pts, b <- bs ]
    it "is at most the cap, and the cap for a cell with nothing near" $ do
      let bs = [Box 0 0 0.1 0.1, Box 9.9 9.9 10 10]
          cl = clearanceOf (boxIndex bs) (boxesExtent bs)
      clearanceAt cl 5 5 `shouldBe` clearanceCap
      clearanceAt cl 0.05 0.05 `shouldBe` 0
      -- a point 0.6 m right of the first box: its cell starts at most one
      -- cell nearer
      clearanceAt cl 0.7 0.05 `shouldSatisfy` (\c -> c >= 0.6 - clearanceCellSize 10 10 - clearanceQuantum && c <= 0.6)
    it "is a whole number of quanta, less than a quantum below the cell's distance" $ do
      -- one box, its right side at x = 0: a cell from x = a to x = a + cs
      -- (and level with the box) has the distance a; the point 0.01 m into
      -- the cell reads that distance rounded down to quanta
      let bs = [Box (-1) 0 0 10, Box 9.9 9.9 10 10]
          cs = clearanceCellSize 11 10
          cl = clearanceOf (boxIndex bs) (boxesExtent bs)
      conjoin [ counterexample (show (a, c)) $
                  c <= a && c > a - clearanceQuantum
                    && abs (c / clearanceQuantum - fromIntegral (round (c / clearanceQuantum) :: Int)) < 1e-9
              | k <- [5 .. 8 :: Int]
              , let a = fromIntegral k * cs - 1
                    c = clearanceAt cl (a + 0.01) 5 ]
    it "is 0 outside the grid and for points that are not finite" $ do
      let bs = [Box 0 0 1 1, Box 5 5 6 6]
          cl = clearanceOf (boxIndex bs) (boxesExtent bs)
      map (uncurry (clearanceAt cl)) [(-0.5, 3), (3, 7), (0 / 0, 3), (1 / 0, 3), (3, -1 / 0)]
        `shouldBe` [0, 0, 0, 0, 0]
    it "is 0 everywhere when a box is not finite" $ do
      let bs = [Box 0 0 1 1, Box 5 5 6 6, Box (0 / 0) 2 3 3]
          cl = clearanceOf (boxIndex bs) (0, 0, 6, 6)
      [ clearanceAt cl x y | x <- [0.5, 1.5 .. 5.5], y <- [0.5, 1.5 .. 5.5] ]
        `shouldSatisfy` all (== 0)
    it "is never more than the distance to any box in an arena's own clearance" $
      property $ forAll genWorld $ \w ->
        forAll (vectorOf 30 ((,) <$> choose (-halfSide w, halfSide w) <*> choose (-halfSide w, halfSide w))) $ \pts ->
          let arena = arenaFor w
              cl = arenaClearance arena
          in conjoin [ counterexample (show (x, y, b)) (clearanceAt cl x y <= pointBoxDistance x y b + 1e-12)
                     | (x, y) <- pts, b <- arenaBoxes arena ]
