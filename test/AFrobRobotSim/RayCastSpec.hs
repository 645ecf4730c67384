-- | "AFrobRobotSim.RayCast": a ray finds, through the ray grid of
-- "AFrobRobotSim.RayGrid", every box it can meet, and the nearest hit is
-- the one testing every box finds, bit for bit.
module AFrobRobotSim.RayCastSpec (spec) where

import           Data.List             (nub, sort)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Geometry
import           AFrobRobotSim.RayCast
import           AFrobRobotSim.Arena
import           AFrobRobotSim.RayGrid (rayGridCellSide, rayGridEntries, rayGridReach, rayGridTolerance)
import           AFrobRobotSim.Sensors (rayDirection)
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World
import           AFrobRobotSim.WorldGen

spec :: Spec
spec = do
  describe "foldBoxesAlong" $ do
    it "visits every box within 1 mm of the segment (and only boxes near its bounding box)" $
      property $ forAll genWorld $ \w -> forAll (genSegment w) $ \(ax, ay, bx, by) ->
        let Arena boxes = arenaFor w
            bi = boxIndex boxes
            got = nub (sort (foldBoxesAlong bi ax ay bx by (\acc k _ -> k : acc) []))
            near = [ k | (k, b) <- zip [0 ..] boxes, segmentBoxDistance (ax, ay) (bx, by) b <= 0.9 * rayGridTolerance ]
            t = rayGridTolerance
            inRect = and [ a <= max ax bx + t && c >= min ax bx - t && b <= max ay by + t && d >= min ay by - t
                         | k <- got, let Box a b c d = boxes !! k ]
        in counterexample (show (got, near)) (all (`elem` got) near && inRect)
    it "visits a box just beyond the end of the longest segment, from a corner of a cell" $
      -- the hardest case for the ray grid: the cell lies behind the
      -- start, so nothing else in it is nearer the box
      property $ forAll genWorld $ \(World bounds os) ->
        forAll (chooseInt (0, 10)) $ \i -> forAll (chooseInt (0, 10)) $ \j ->
        forAll (oneof [choose (-pi, -pi / 2), elements [-pi, -pi / 2, -3 * pi / 4]]) $ \th ->
        forAll (elements [0, 1e-12, 0.5e-3, 0.85e-3]) $ \gap -> forAll (elements [0, 1e-13, -1e-13]) $ \e ->
          let Bounds x0 y0 _ _ = bounds
              cs = rayGridCellSide
              ax = x0 - 1 + fromIntegral i * cs + e
              ay = y0 - 1 + fromIntegral j * cs - e
              ux = cos th
              uy = sin th
              bx = ax + rayGridReach * ux
              by = ay + rayGridReach * uy
              -- a square of side 0.1 that the ray enters @gap@ after the end
              k = gap + 0.05 / max (abs ux) (abs uy)
              extra = boxAround (Point2 (bx + k * ux) (by + k * uy)) 0.1 0.1
              Arena boxes0 = arenaOf bounds os
              boxes = boxes0 ++ [extra]
              got = foldBoxesAlong (boxIndex boxes) ax ay bx by (\acc n _ -> n : acc) []
          in segmentBoxDistance (ax, ay) (bx, by) extra <= 0.9 * rayGridTolerance ==> (length boxes - 1) `elem` got
    it "visits each box at most once when the ray grid answers" $
      property $ forAll genWorld $ \w -> forAll (genSegment w) $ \(ax, ay, bx, by) ->
        let Arena boxes = arenaFor w
            bi = boxIndex boxes
            h = halfSide w + 1
            got = foldBoxesAlong bi ax ay bx by (\acc k _ -> k : acc) []
            answers = abs ax <= h && abs ay <= h && (bx - ax) ^ (2 :: Int) + (by - ay) ^ (2 :: Int) <= rayGridReach ^ (2 :: Int)
        in rayGridEntries (boxIndexRays bi) > 0 && (not answers || length got == length (nub got))

  describe "rayCastBoxes" $
    it "is the nearest hit over every box, as rayBox has it" $
      property $ forAll genWorld $ \w -> forAll (genSegment w) $ \(ax, ay, bx, by) ->
        forAll (elements [Nothing, Just 0, Just (pi / 2), Just pi, Just (-pi / 2)]) $ \quarter ->
        forAll (elements [3.25, 3.3, 1, 6]) $ \len ->
          let Arena boxes = arenaFor w
              bi = boxIndex boxes
              -- the segment's direction, or a quarter turn of it as the
              -- range finder turns it
              Vector2 ux0 uy0 = let l = sqrt ((bx - ax) ^ (2 :: Int) + (by - ay) ^ (2 :: Int))
                                in if l > 0 then Vector2 ((bx - ax) / l) ((by - ay) / l) else Vector2 1 0
              Vector2 ux uy = maybe (Vector2 ux0 uy0) (\a -> rayDirection (atan2 uy0 ux0) a) quarter
              want = foldl (\m b -> maybe m (`min` m) (rayBox (Point2 ax ay) (Vector2 ux uy) b)) len boxes
          in rayCastBoxes bi ax ay ux uy len === want
