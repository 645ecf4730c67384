-- | "AFrobRobotSim.Arena": an arena's boxes are its world's walls and
-- blocks, in order, then four boundary boxes around the world; its index
-- and its points' grid find exactly what looking at everything finds; its
-- clearance lies within a cell's diagonal below the distance to the
-- nearest box, over its whole extent.
module AFrobRobotSim.ArenaSpec (spec) where

import           Data.List               (nub, sort)
import           Data.Maybe              (mapMaybe)
import           GHC.Float               (castDoubleToWord64)
import           Test.Hspec              hiding (after)
import           Test.QuickCheck

import           AFRP.Geometry           (Point2 (..))
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Clearance (clearanceAt, clearanceCap, clearanceCellSize, clearanceQuantum)
import           AFrobRobotSim.Shapes    (Box (..))
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World
import           AFrobRobotSim.WorldGen

-- | The box of a wall or block, from the table of sizes in
-- "AFrobRobotSim.World"; nothing for what moves.
staticBox :: ObjectTemplate -> Maybe Box
staticBox o = case o of
  OTBlock (Point2 x y) -> Just (centred x y blockSide blockSide)
  OTVWall (Point2 x y) -> Just (centred x y wallThickness wallLength)
  OTHWall (Point2 x y) -> Just (centred x y wallLength wallThickness)
  _                    -> Nothing
  where centred x y w h = Box (x - w / 2) (y - h / 2) (x + w / 2) (y + h / 2)

-- | Bounds of any shape, anywhere.
genBounds :: Gen Bounds
genBounds = do
  x0 <- choose (-30, 10)
  y0 <- choose (-30, 10)
  w  <- oneof [choose (0.5, 40), elements [10]]
  h  <- oneof [choose (0.5, 40), elements [10]]
  pure (Bounds x0 y0 (x0 + w) (y0 + h))

-- | Any boxes (none, some overlapping, some of width or height 0) in the
-- square of half side 10.
genBoxes :: Gen [Box]
genBoxes = do
  n <- oneof [pure 0, chooseInt (1, 40)]
  vectorOf n $ do
    x <- choose (-10, 10)
    y <- choose (-10, 10)
    w <- oneof [pure 0, choose (0, 3)]
    h <- oneof [pure 0, choose (0, 3)]
    pure (Box x y (x + w) (y + h))

-- | An arena of a world, or of any boxes.
genArena :: Gen (Either World [Box])
genArena = oneof [Left <$> genWorld, Right <$> genBoxes]

arenaOfEither :: Either World [Box] -> Arena
arenaOfEither = either arenaFor Arena

-- | A rectangle (maybe a point) anywhere around the square of half side
-- 12.
genRect :: Gen (Double, Double, Double, Double)
genRect = do
  x0 <- choose (-14, 12)
  y0 <- choose (-14, 12)
  w  <- oneof [pure 0, choose (0, 6)]
  h  <- oneof [pure 0, choose (0, 6)]
  pure (x0, y0, x0 + w, y0 + h)

inBox :: Double -> Double -> Box -> Bool
inBox x y (Box a b c d) = x >= a && x <= c && y >= b && y <= d

spec :: Spec
spec = do
  describe "arenaOf" $ do
    it "has the world's walls and blocks as boxes, in order, and four more; nothing of what moves" $
      property $ forAll genWorld $ \(World bounds os) -> forAll (genMovers 5) $ \movers ->
        forAll (shuffle (os ++ movers)) $ \world ->
          let boxes = arenaBoxes (arenaOf bounds world)
              statics = mapMaybe staticBox world
          in take (length statics) boxes === statics .&&. length boxes === length statics + 4

    it "walls the world in: its last four boxes leave the inside free and cover a ring a simbot wide around it" $
      property $ forAll genBounds $ \bounds@(Bounds x0 y0 x1 y1) -> forAll genWorld $ \(World _ os) ->
        forAll (vectorOf 40 (genRing bounds)) $ \ring ->
          let walls = drop (length (mapMaybe staticBox os)) (arenaBoxes (arenaOf bounds os))
              -- no point strictly inside the world is in a wall
              outside (Box a b c d) = c <= x0 || a >= x1 || d <= y0 || b >= y1
          in counterexample (show walls) $
               length walls === 4 .&&. all outside walls
                 .&&. conjoin [ counterexample (show p) (any (inBox x y) walls) | p@(x, y) <- ring ]

    it "builds nothing before it is needed: its boxes can be read when their index cannot be built" $
      length (arenaBoxes (Arena [Box 0 0 1 1, Box 0 (error "index built") 1 1])) `shouldBe` 2

  describe "Arena" $
    it "matches the boxes it was built of" $
      property $ forAll genBoxes $ \bs -> arenaBoxes (Arena bs) === bs

  describe "arenaIndex" $
    it "holds the arena's boxes at their positions and finds exactly those that meet a rectangle" $
      property $ forAll genArena $ \e -> forAll genRect $ \(x0, y0, x1, y1) ->
        let arena = arenaOfEither e
            boxes = arenaBoxes arena
            bi = arenaIndex arena
            visits = foldBoxesIn bi x0 y0 x1 y1 (\acc k b -> (k, b) : acc) []
            want = [ k | (k, Box a b c d) <- zip [0 ..] boxes, a <= x1, c >= x0, b <= y1, d >= y0 ]
        in boxIndexCount bi === length boxes
             .&&. map (boxAt bi) [0 .. length boxes - 1] === boxes
             .&&. nub (sort (map fst visits)) === want
             .&&. conjoin [ b === boxes !! k | (k, b) <- visits ]

  describe "arenaClearance" $
    -- (the upper bound at points inside a world is checked in
    -- "AFrobRobotSim.ClearanceSpec" too; the lower bound shows that the
    -- clearance covers the whole extent, the boundary walls included)
    it "is at most the distance to the nearest box, and at least that less a cell's diagonal (capped) and a quantum over the boxes' extent" $
      property $ forAll genArena $ \e ->
        let arena = arenaOfEither e
            boxes = arenaBoxes arena
            (ex0, ey0, ex1, ey1) = boxesExtent boxes
            diag = clearanceCellSize (ex1 - ex0) (ey1 - ey0) * sqrt 2
            nearby = (,) <$> choose (ex0 - 1, ex1 + 1) <*> choose (ey0 - 1, ey1 + 1)
            corners = [ (x, y) | x <- [ex0, ex1], y <- [ey0, ey1] ]
        in forAll (vectorOf 40 nearby) $ \pts ->
             conjoin [ counterexample (show (x, y, c, d)) $
                         c <= d + 1e-12
                           && (not inExtent || c >= min clearanceCap (d - diag) - clearanceQuantum - 1e-9)
                     | (x, y) <- corners ++ pts
                     , let c = clearanceAt (arenaClearance arena) x y
                           d = minimum (1 / 0 : map (pointBoxDistance x y) boxes)
                           inExtent = not (null boxes) && x >= ex0 && x <= ex1 && y >= ey0 && y <= ey1 ]

  describe "pointsOver" $
    it "keeps every point at its position and finds exactly those in a rectangle (outside the arena and not finite too)" $
      property $ forAll genArena $ \e -> forAll genRect $ \(x0, y0, x1, y1) ->
        forAll (listOf genPoint) $ \pts ->
          let pix = pointsOver (arenaOfEither e) pts
              n = length pts
              bits = map castDoubleToWord64
              got = sort (foldPointsIn pix x0 y0 x1 y1 (flip (:)) [])
              want = [ k | (k, (x, y)) <- zip [0 ..] pts
                         , not (finite x && finite y) || (x >= x0 && x <= x1 && y >= y0 && y <= y1) ]
          in pointIndexCount pix === n
               .&&. bits (map (pointX pix) [0 .. n - 1]) === bits (map fst pts)
               .&&. bits (map (pointY pix) [0 .. n - 1]) === bits (map snd pts)
               .&&. got === want
  where
    -- a point on the world's edge or outside it, at most a simbot's
    -- diameter away (corners too)
    genRing (Bounds x0 y0 x1 y1) = do
      d  <- oneof [choose (0, simbotDiameter), elements [0, simbotDiameter]]
      tx <- oneof [choose (x0 - d, x1 + d), elements [x0 - d, x1 + d]]
      ty <- oneof [choose (y0 - d, y1 + d), elements [y0 - d, y1 + d]]
      elements [(x0 - d, ty), (x1 + d, ty), (tx, y0 - d), (tx, y1 + d)]
    -- anywhere around the arenas, sometimes crowded, sometimes not finite
    genPoint = do
      x <- frequency [(8, choose (-14, 14)), (2, choose (-1, 1)), (1, elements [0 / 0, 1 / 0, -1 / 0])]
      y <- frequency [(8, choose (-14, 14)), (2, choose (-1, 1)), (1, elements [0 / 0, -1 / 0])]
      pure (x, y)
