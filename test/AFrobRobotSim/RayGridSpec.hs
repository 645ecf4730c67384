-- | "AFrobRobotSim.RayGrid" on its own, for any boxes: when a list answers
-- for a segment; that the list for a start and a quadrant holds every box
-- a segment from there can reach; how the lists are laid out and counted;
-- and when there are none. ("AFrobRobotSim.RayCastSpec" checks the rays
-- that read the lists, through 'AFrobRobotSim.RayCast.foldBoxesAlong', in
-- walled worlds, where the grid's last row and column lie inside a
-- boundary wall and the margins are tested at their hardest; here the
-- boxes are anywhere, over a few metres or spread over kilometres, where
-- the cells are larger.)
module AFrobRobotSim.RayGridSpec (spec) where

import           Data.List               (nub, sort)
import           Test.Hspec              hiding (after)
import           Test.QuickCheck

import           AFrobRobotSim.Arena
import           AFrobRobotSim.FlatArray (indexI)
import           AFrobRobotSim.RayGrid
import           AFrobRobotSim.Shapes    (Box (..))
import           AFrobRobotSim.WorldGen

-- | Boxes (1 to 30) of all shapes (points, thin walls, blocks, long bars)
-- in a rectangle of half sides @hx@ and @hy@.
genBoxesIn :: (Double, Double) -> Gen [Box]
genBoxesIn (hx, hy) = do
  n <- chooseInt (1, 30)
  vectorOf n $ do
    x <- choose (-hx, hx)
    y <- choose (-hy, hy)
    w <- oneof [pure 0, choose (0, 0.2), choose (0.2, 2), choose (2, 2 * hx)]
    t <- oneof [pure 0, choose (0, 0.2), choose (0.2, 2)]
    elements [Box x y (x + w) (y + t), Box x y (x + t) (y + w)]

-- | Boxes over a few metres (where a list holds many of them), in a
-- square of half side 10, or spread over 800 m (where the cells are
-- larger) or a strip 6 km long (where they are larger still).
genBoxes :: Gen [Box]
genBoxes = elements [(3, 3), (10, 10), (10, 10), (400, 400), (3000, 1)] >>= genBoxesIn

-- | Boxes anywhere, or a world's.
genAnyBoxes :: Gen [Box]
genAnyBoxes = oneof [genBoxes, arenaBoxes . arenaFor <$> genWorld]

-- | Boxes anywhere, most often over a few metres (where many of them lie
-- in the grid's last row or column), or a world's.
genManyBoxes :: Gen [Box]
genManyBoxes = frequency [ (3, elements [(3, 3), (10, 10)] >>= genBoxesIn), (1, genBoxes)
                         , (1, arenaBoxes . arenaFor <$> genWorld) ]

-- | The ray grid of boxes, each with its position.
gridOf :: [Box] -> RayGrid
gridOf = rayGrid . zip [0 ..]

-- | The list that answers for a segment, if one does.
listFor :: RayGrid -> (Double, Double, Double, Double) -> Maybe (Int, Int, [Int])
listFor rg (px, py, qx, qy) =
  rayGridList rg px py qx qy (\items s e -> Just (s, e, map (indexI items) [s .. e - 1])) Nothing

-- | The list 'rayGridLookup' gives for a segment, if any, and whether
-- it came from the cell's line.
lookupFor :: RayGrid -> (Double, Double, Double, Double) -> Maybe (Bool, [Int])
lookupFor rg (px, py, qx, qy) =
  rayGridLookup rg px py qx qy (\ls w s e -> Just (True, map (rayGridLineItem ls w) [s .. e - 1]))
                (\items s e -> Just (False, map (indexI items) [s .. e - 1])) Nothing

-- | A short segment from every point of a lattice over the domain finer
-- than any grid's cells (and through its far edges), into each quadrant:
-- together they read every list.
probes :: [Box] -> [(Double, Double, Double, Double)]
probes bs =
  [ (x, y, x + dx, y + dy) | x <- lattice x0 x1, y <- lattice y0 y1, (dx, dy) <- quadrants ]
  where
    (x0, y0, x1, y1) = boxesExtent bs
    lattice a b = nub (takeWhile (< b) [ a + fromIntegral k * rayGridCellSide / 2 | k <- [0 :: Int ..] ] ++ [b])
    quadrants = [(1e-3, 1e-3), (-1e-3, 1e-3), (1e-3, -1e-3), (-1e-3, -1e-3)]

-- | Does a segment from @p@ into the closed quadrant of directions @q@,
-- at most 'rayGridReach' long, reach the box? (The part of the box in the
-- quadrant, if any, is within the reach.)
reaches :: (Double, Double) -> (Double, Double) -> Box -> Bool
reaches (px, py) (sx, sy) (Box a b c d) =
  let (a', c') = if sx > 0 then (max a px, c) else (a, min c px)
      (b', d') = if sy > 0 then (max b py, d) else (b, min d py)
  in a' <= c' && b' <= d' && pointBoxDistance px py (Box a' b' c' d') <= rayGridReach

spec :: Spec
spec = do
  describe "rayGridList" $
    it "answers for a segment exactly when it starts in the boxes' bounding box and is at most rayGridReach long, with every box near it" $
      property $ forAll genAnyBoxes $ \bs ->
        forAll (vectorOf 20 (frequency [(2, genSegmentAmong bs), (2, genAtLimits bs), (1, genWild)])) $ \segs ->
          let rg = gridOf bs
              (x0, y0, x1, y1) = boxesExtent bs
          in conjoin
               [ case listFor rg seg of
                   Nothing -> counterexample (show seg ++ ": no answer") (not mustAnswer)
                   Just (_, _, got) -> counterexample (show (seg, got, near)) (mayAnswer && all (`elem` got) near)
               | seg@(px, py, qx, qy) <- segs
               , let len = sqrt ((qx - px) ^ (2 :: Int) + (qy - py) ^ (2 :: Int))
                     inDomain = px >= x0 && px <= x1 && py >= y0 && py <= y1
                     -- (a segment within rounding of the reach may go either way)
                     mustAnswer = inDomain && len <= rayGridReach * (1 - 1e-12)
                     mayAnswer  = inDomain && len <= rayGridReach * (1 + 1e-12)
                     near = [ k | (k, b) <- zip [0 ..] bs, segmentBoxDistance (px, py) (qx, qy) b <= 0.9 * rayGridTolerance ] ]

  describe "the lists" $ do
    it "hold, for a start and a quadrant, every box that a segment from there into the quadrant, at most rayGridReach long, reaches" $
      property $ forAll genManyBoxes $ \bs -> forAll (vectorOf 100 (genStart bs)) $ \starts ->
        let rg = gridOf bs
        in conjoin [ case listFor rg (px, py, px + 1e-3 * sx, py + 1e-3 * sy) of
                       Nothing         -> counterexample (show (p, q) ++ ": no list") False
                       Just (_, _, is) -> counterexample (show (p, q, want, is)) (all (`elem` is) want)
                   | p@(px, py) <- starts, q@(sx, sy) <- [(1, 1), (-1, 1), (1, -1), (-1, -1)]
                   , let want = [ k | (k, b) <- zip [0 ..] bs, reaches p q b ] ]
    it "hold each box at most once, in index order, end to end from 0 up to rayGridEntries" $
      -- (over at most 42 m, for a lattice of a few thousand points)
      property $ forAll (oneof [elements [(3, 3), (10, 10)] >>= genBoxesIn, arenaBoxes . arenaFor <$> genWorld]) $ \bs ->
        let rg = gridOf bs
            lists = nub (sort [ l | Just l@(s, e, _) <- map (listFor rg) (probes bs), e > s ])
            spans = [ (s, e) | (s, e, _) <- lists ]
            ascending xs = and (zipWith (<) xs (drop 1 xs))
        in conjoin [ counterexample (show l) (ascending is && all (\i -> i >= 0 && i < length bs) is)
                   | l@(_, _, is) <- lists ]
             .&&. counterexample (show spans)
                    (map fst spans === 0 : map snd (take (length spans - 1) spans)
                       .&&. maybe 0 snd (lastMay spans) === rayGridEntries rg)

  describe "rayGridLookup" $ do
    it "gives rayGridList's boxes, in its order, for every list and segments of every kind" $
      property $ forAll (oneof [elements [(3, 3), (10, 10)] >>= genBoxesIn, arenaBoxes . arenaFor <$> genWorld]) $ \bs ->
        forAll (vectorOf 100 (oneof [genAtLimits bs, genWild])) $ \segs ->
          let rg = gridOf bs
          in conjoin [ counterexample (show seg) (fmap snd (lookupFor rg seg) === fmap (\(_, _, is) -> is) (listFor rg seg))
                     | seg <- probes bs ++ segs ]
    it "reads a cell's short lists from its line, and long ones from the lists" $ do
      -- 20 small boxes around the origin (every cell near them has more
      -- than 15 entries) and one box 20 m away
      let bs = [ Box (x - 0.01) (y - 0.01) (x + 0.01) (y + 0.01)
               | k <- [0 .. 19 :: Int], let x = 0.02 * fromIntegral k, let y = 0.01 * fromIntegral k ]
               ++ [Box 20 20 20.2 20.2]
          rg = gridOf bs
          seg x y = (x, y, x + 1, y + 1)
      fmap fst (lookupFor rg (seg 0.1 0.05)) `shouldBe` Just False
      fmap fst (lookupFor rg (seg 19 19)) `shouldBe` Just True
      lookupFor rg (seg 0.1 0.05) `shouldBe` Just (False, [0 .. 19])
      lookupFor rg (seg 19 19) `shouldBe` Just (True, [20])
    it "keeps in a line the lists of up to 15 entries with positions below 2^16, and no others" $ do
      -- A cell's entries are those of its four lists. Boxes side by side
      -- wholly north-east of the cell of (5, 5) (4.4 to 5.5 m on either
      -- axis) are listed for its north-east quadrant only: 15 of them fit
      -- its line, 16 do not. (The box at the origin, out of reach, makes
      -- the domain hold the cell.) And one box at the largest position a
      -- line holds, or one past it.
      let row k = Box 0 0 0.01 0.01
                  : [ Box x 5.6 (x + 0.01) 5.61 | j <- [0 .. k - 1 :: Int], let x = 5.6 + 0.02 * fromIntegral j ]
          ne = (5, 5, 5.1, 5.1)
          viaLine sg bs = fmap fst (lookupFor (rayGrid bs) sg)
      viaLine ne (zip [0 ..] (row 15)) `shouldBe` Just True
      viaLine ne (zip [0 ..] (row 16)) `shouldBe` Just False
      lookupFor (rayGrid (zip [0 ..] (row 15))) ne `shouldBe` Just (True, [1 .. 15])
      lookupFor (rayGrid (zip [0 ..] (row 16))) ne `shouldBe` Just (False, [1 .. 16])
      let seg = (0.1, 0.005, 0.2, 0.105)
          viaLine' = viaLine seg
      -- (the box is listed in all four quadrants: entry 2, 65535, is the
      -- top half of the line's first word, which a check of that word's
      -- sign would take for a long cell)
      viaLine' [(65535, Box 0 0 1 1)] `shouldBe` Just True
      viaLine' [(65536, Box 0 0 1 1)] `shouldBe` Just False
      lookupFor (rayGrid [(7, Box 2 2 3 3), (65535, Box 0 0 1 1)]) seg `shouldBe` Just (True, [7, 65535])
      -- the other quadrants' lists, read from the line's other ends
      lookupFor (rayGrid [(7, Box 2 2 3 3), (65535, Box 0 0 1 1)]) (0.1, 0.005, 0.0, 0.105) `shouldBe` Just (True, [65535])
      lookupFor (rayGrid [(7, Box 2 2 3 3), (65535, Box 0 0 1 1), (9, Box (-0.5) (-0.5) (-0.4) (-0.4))])
                (0.1, 0.005, 0.0, -0.095) `shouldBe` Just (True, [65535, 9])

  describe "rayGrid" $ do
    it "has no lists, and answers for no segment, without boxes or when their extent overflows" $ do
      let none = [gridOf [], gridOf [Box (-1e308) 0 (-1e308) 1, Box 1e308 0 1e308 1]]
          segs = [(0, 0, 0, 0), (0, 0.5, 1, 0.5), (-1e308, 0, -1e308, 1), (1e308, 0.5, 1e308, 0.5)]
      map rayGridEntries none `shouldBe` [0, 0]
      [ () | rg <- none, seg <- segs, Just _ <- [listFor rg seg] ] `shouldBe` []
    it "answers for a segment exactly rayGridReach long, and not for a longer one" $ do
      let rg = gridOf [Box (-5) (-5) 5 5]
          r = rayGridReach
          answers seg = maybe False (const True) (listFor rg seg)
      map answers [(0, 0, r, 0), (0, 0, 0, -r), (0, 0, r + 1e-12, 0), (0, 0, 0, -r - 1e-12)]
        `shouldBe` [True, True, False, False]
    it "has lists of up to 2^22 entries, and none beyond" $ do
      -- boxes over the whole of the largest grid (2^18 cells, of 600 m /
      -- 512): each is listed for every cell and quadrant, 2^20 times
      let big = replicate 5 (Box (-300) (-300) 300 300)
      rayGridEntries (gridOf (take 4 big)) `shouldBe` 2 ^ (22 :: Int)
      rayGridEntries (gridOf big) `shouldBe` 0
      listFor (gridOf big) (0, 0, 1, 1) `shouldBe` Nothing
  where
    -- a segment with a coordinate that is not finite
    genWild = do
      v <- elements [0 / 0, 1 / 0, -1 / 0]
      k <- chooseInt (0, 3 :: Int)
      let pick i x = if i == k then v else x
      pure (pick 0 0, pick 1 0, pick 2 0.5, pick 3 0.5)
    -- a segment from on the domain's edge, or just inside or outside it,
    -- of about the reach
    genAtLimits bs = do
      let (x0, y0, x1, y1) = boxesExtent bs
      px  <- choose (x0, x1)
      py  <- choose (y0, y1)
      off <- elements [0, 1e-9, -1e-9, 1e-3, -1e-3]    -- outwards
      (sx, sy) <- elements [(px, py), (x0 - off, py), (x1 + off, py), (px, y0 - off), (px, y1 + off)]
      len <- elements [0, 1, rayGridReach, rayGridReach * (1 - 1e-9), rayGridReach * (1 + 1e-9), rayGridReach + 1e-3]
      th  <- oneof [choose (-pi, pi), elements [0, pi / 2, pi, -pi / 2]]
      pure (sx, sy, sx + len * cos th, sy + len * sin th)
    -- a start in the domain: anywhere, on its edges, or on a cell
    -- boundary (the cells are of 'rayGridCellSide' for boxes over at most
    -- a few hundred metres)
    genStart bs = do
      let (x0, y0, x1, y1) = boxesExtent bs
          at a b = frequency [ (2, choose (a, b)), (1, elements [a, b]), (1, pure b)
                             , (1, (\i -> min b (a + fromIntegral i * rayGridCellSide)) <$> chooseInt (0, 40 :: Int)) ]
      (,) <$> at x0 x1 <*> at y0 y1
    lastMay xs = if null xs then Nothing else Just (last xs)
