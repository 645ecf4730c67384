{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.RayGrid
-- Description : For every place and every quarter of directions, the static
--               boxes a short ray from there can meet.
--
-- A range finder's ray is short (3.25 m) and the obstacles never move, so
-- the work of finding what a ray may hit can be done once per world: a
-- uniform grid of small cells over the boxes' bounding box keeps, for every
-- cell and each of the four closed quadrants of directions (x and y each
-- @>= 0@ or @<= 0@), the list of boxes that a segment of length at most
-- 'rayGridReach' starting in the cell and pointing into the quadrant can
-- come near. A ray then reads one list (a few boxes, with the world's
-- boundary walls only where it can reach them) instead of walking the cells
-- its bounding box covers and looking at everything listed there.
--
-- \"Near\" is within 'rayGridTolerance' of the segment: a list holds every
-- box that meets the cell, widened by a margin, swept by the quarter disc of
-- radius 'rayGridReach' (plus the margin) in its quadrant (see 'rayGrid').
-- The margin covers the tolerance and the rounding of the coordinates that
-- put a ray's origin in its cell, so a box that rounding could make a ray
-- hit is never left out.
--
-- "AFrobRobotSim.SpatialIndex" keeps one of these (built the first time a
-- ray needs it) in every 'AFrobRobotSim.SpatialIndex.BoxIndex', and
-- "AFrobRobotSim.RayCast" reads it.
module AFrobRobotSim.RayGrid
  ( RayGrid
  , rayGrid
  , rayGridReach
  , rayGridTolerance
  , rayGridCellSide
  , rayGridEntries
  , rayGridList
  , rayGridLookup
  , rayGridLineItem
  ) where

import           Control.Monad.ST (ST, runST)
import           Data.Bits        (shiftL, shiftR, (.&.), (.|.))

import           AFrobRobotSim.FlatArray
import           AFrobRobotSim.Shapes     (Box (..))

-- | The longest segment the lists are made for: 3.3 m, the range finder's
-- ray (3 m plus a robot's radius) with room for its rounding. A longer
-- segment has to be answered some other way.
rayGridReach :: Double
rayGridReach = 3.3

-- | How near a segment a box must come to be listed for it: 1 mm. A query
-- widens a segment's bounding box by this much ("AFrobRobotSim.RayCast"),
-- for rounding, so every box it can find is listed.
rayGridTolerance :: Double
rayGridTolerance = 1e-3

-- | The side of a cell: a third of the reach (cells are larger only in a
-- world so large that it would need too many of them). A list holds the
-- boxes near a region of area @cs^2 + 2 cs R + pi R^2 / 4@ (cell, two
-- strips and a quarter disc); the quarter disc dominates below about
-- @R / 3@, so smaller cells would cost memory for little shorter lists.
rayGridCellSide :: Double
rayGridCellSide = rayGridReach / 3

-- At most this many cells (larger worlds get larger cells) and this many
-- list entries (beyond that, no ray grid: a world of many thousands of
-- densely packed boxes falls back to the plain grid walk).
maxCells, maxEntries :: Int
maxCells   = 2 ^ (18 :: Int)
maxEntries = 2 ^ (22 :: Int)

-- | The lists, or none (no finite box, an absurd extent, or too many
-- entries).
--
-- A list is @items [starts l .. starts (l + 1) - 1]@ for
-- @l = 4 * (row * nx + column) + quadrant@, the quadrant 0 for directions
-- @(>= 0, >= 0)@, 1 for @(< 0, >= 0)@, 2 for @(>= 0, < 0)@ and 3 for
-- @(< 0, < 0)@; each box at most once per list, in the order of the
-- boxes given to 'rayGrid' ("AFrobRobotSim.SpatialIndex" gives them in
-- the order of their positions).
data RayGrid
  = NoRayGrid
  | RayGrid
      {-# UNPACK #-} !Double  -- the domain (the boxes' bounding box): min x,
      {-# UNPACK #-} !Double  -- min y,
      {-# UNPACK #-} !Double  -- max x,
      {-# UNPACK #-} !Double  -- max y
      {-# UNPACK #-} !Double  -- 1 / the side of a cell
      {-# UNPACK #-} !Int     -- columns
      {-# UNPACK #-} !Int     -- rows
      !IntArr                 -- list l is items [starts l .. starts (l + 1) - 1]
      !IntArr                 -- the items: box positions in the original list
      !IntArr                 -- the cells' lines (see 'cellLines')

-- | How many entries the lists hold in all (0 for no grid).
rayGridEntries :: RayGrid -> Int
rayGridEntries NoRayGrid = 0
rayGridEntries (RayGrid _ _ _ _ _ nx ny starts _ _) = indexI starts (4 * nx * ny)

-- | @rayGrid boxes@: the lists for the boxes (each with its index; all
-- coordinates finite, each box with min <= max).
--
-- Box @B@ is listed for cell @C@ and quadrant @Q@ when some point of @B@
-- minus some point of @C@ widened by @m@ on every side lies in @Q@ within
-- distance @R + m@ (@R@ = 'rayGridReach'): along each axis the box must not
-- lie wholly behind the widened cell, and the gaps @dx@, @dy@ from the
-- widened cell to the box in the quadrant's direction (0 when they overlap)
-- must have @dx^2 + dy^2 <= (R + m)^2@. The margin @m@ is twice the
-- tolerance (1 mm for the tolerance, 1 mm for rounding) plus @1e-12@ of the
-- largest coordinate's size, far more than any rounding of the cell
-- computation.
--
-- Why that is enough: let a segment start at @p@ in cell @C@ (up to
-- rounding, which the second millimetre covers), point into @Q@ and be at
-- most @R@ long, and let @b@ in @B@ be within the tolerance @e@ of a point
-- @p + v@ of it (@v@ in @Q@, @|v| <= R@). Then @b = (p + e) + v@ with @p + e@
-- in the widened cell, so @B@ is listed.
rayGrid :: [(Int, Box)] -> RayGrid
rayGrid [] = NoRayGrid
rayGrid boxes
  | not (finite w && finite h && finite mag) = NoRayGrid
  | otherwise = runST $ do
      lists <- bucketListsUpTo (4 * nx * ny) maxEntries (\f -> mapM_ (\(i, b) -> forLists b (f i)) boxes)
      pure (case lists of
        Nothing       -> NoRayGrid
        Just (st, it) -> RayGrid x0 y0 x1 y1 (1 / cs) nx ny st it (runST (cellLines (nx * ny) st it)))
  where
    x0 = minimum [ a | (_, Box a _ _ _) <- boxes ]
    y0 = minimum [ b | (_, Box _ b _ _) <- boxes ]
    x1 = maximum [ c | (_, Box _ _ c _) <- boxes ]
    y1 = maximum [ d | (_, Box _ _ _ d) <- boxes ]
    w  = x1 - x0
    h  = y1 - y0
    mag = maximum [abs x0, abs y0, abs x1, abs y1]
    -- cells of 'rayGridCellSide', larger if there would be too many of them
    -- (the second bound keeps a long thin domain's columns or rows in
    -- range)
    cs = maximum [rayGridCellSide, sqrt (w * h / fromIntegral maxCells), max w h / 4096]
    nx = max 1 (ceiling (w / cs))
    ny = max 1 (ceiling (h / cs))
    m  = 2 * rayGridTolerance + 1e-12 * mag
    r  = rayGridReach + m
    -- the cells' edges, widened by the margin
    left   i = x0 + fromIntegral i * cs - m
    right  i = x0 + fromIntegral (i + 1) * cs + m
    bottom j = y0 + fromIntegral j * cs - m
    top    j = y0 + fromIntegral (j + 1) * cs + m
    colOf v = max 0 (min (nx - 1) (floor ((v - x0) / cs)))
    rowOf v = max 0 (min (ny - 1) (floor ((v - y0) / cs)))
    forLists :: Box -> (Int -> ST s ()) -> ST s ()
    forLists (Box a b c d) k =
      mapM_ k
        [ 4 * (j * nx + i) + q
        | (q, east, north) <- [(0, True, True), (1, False, True), (2, True, False), (3, False, False)]
          -- candidate cells (one more on each side than the box and its
          -- reach cover, against the rounding of 'colOf'); the test below
          -- decides
        , let (i0, i1) = if east then (colOf (a - r - m) - 1, colOf (c + m) + 1)
                                 else (colOf (a - m) - 1, colOf (c + r + m) + 1)
              (j0, j1) = if north then (rowOf (b - r - m) - 1, rowOf (d + m) + 1)
                                  else (rowOf (b - m) - 1, rowOf (d + r + m) + 1)
        , j <- [max 0 j0 .. min (ny - 1) j1]
        , let (inY, dy) = if north then (d >= bottom j, max 0 (b - top j))
                                   else (b <= top j, max 0 (bottom j - d))
        , inY
        , i <- [max 0 i0 .. min (nx - 1) i1]
        , let (inX, dx) = if east then (c >= left i, max 0 (a - right i))
                                  else (a <= right i, max 0 (left i - c))
        , inX
        , dx * dx + dy * dy <= r * r ]

-- | @rayGridList rg px py qx qy k none@: @k items s e@ for the list of the
-- segment from @(px, py)@ to @(qx, qy)@ (the boxes @items[s .. e - 1]@) if
-- the grid answers for it: the start lies in the domain and the segment is
-- at most 'rayGridReach' long (both fail for coordinates that are not
-- finite); @none@ otherwise. Every box within 'rayGridTolerance' of such a
-- segment is in the list.
rayGridList :: RayGrid -> Double -> Double -> Double -> Double
            -> (IntArr -> Int -> Int -> r) -> r -> r
rayGridList NoRayGrid _ _ _ _ _ none = none
rayGridList (RayGrid x0 y0 x1 y1 inv nx ny starts items _) px py qx qy k none
  | px >= x0 && px <= x1 && py >= y0 && py <= y1
    && dx * dx + dy * dy <= rayGridReach * rayGridReach =
      let i = min (nx - 1) (truncate ((px - x0) * inv))
          j = min (ny - 1) (truncate ((py - y0) * inv))
          q = (if dx < 0 then 1 else 0) + (if dy < 0 then 2 else 0)
          l = 4 * (j * nx + i) + q
      in k items (indexI starts l) (indexI starts (l + 1))
  | otherwise = none
  where
    dx = qx - px
    dy = qy - py
{-# INLINE rayGridList #-}

-- A cell's four lists again, in half a cache line of its own, when they
-- are short: on a large world the lists and their offsets are megabytes,
-- read at a robot's place once per ray, and the two dependent reads (an
-- offset, then the list) missed the caches on most of a 10,000-robot
-- world's rays; the line is one read, shared by the robot's rays.
--
-- Cell @c@ has the 4 words @lines[4 c .. 4 c + 3]@ (32 bytes, half a
-- cache line: the array is aligned), read as 16 halves of 16 bits, half
-- @h@ in word @h / 4@ (the lowest half for @h@ divisible by 4). Half 0
-- holds the ends of the four lists, counted from the cell's first entry,
-- one nibble each (quadrant @q@'s list ends at nibble @q@ and begins where
-- quadrant @q - 1@'s ends, or at 0), and halves 1 to 15 the entries, entry
-- @k@ in half @k + 1@, in the lists' order. A cell with more than 15
-- entries (or a box position that does not fit in 16 bits) has word 0 =
-- -1: its lists are read from @starts@ and @items@. No short cell's word 0
-- is -1: that would take half 0 = 0xffff (all 15 entries in quadrant 0's
-- list) and that list's first three entries all 65535, where a list holds
-- a box once and the boxes' positions are distinct; and were it -1, the
-- cell would only be read from the full lists, with the same answer.
cellLines :: Int -> IntArr -> IntArr -> ST s IntArr
cellLines cells starts items = do
  ls <- newLineIntArr (max lineWords (lineWords * cells)) 0
  let cell !c
        | c >= cells = pure ()
        | otherwise  = do
            let b     = indexI starts (4 * c)
                ends  = [ indexI starts (4 * c + q + 1) - b | q <- [0 .. 3] ]
                total = indexI starts (4 * c + 4) - b
                its   = [ indexI items k | k <- [b .. b + total - 1] ]
            if total <= lineEntries && all (\i -> i >= 0 && i < 2 ^ (16 :: Int)) its
              then mapM_ (\(h, v) -> do
                            let wd = lineWords * c + h `shiftR` 2
                            old <- readI ls wd
                            writeI ls wd (old .|. (v `shiftL` (16 * (h .&. 3)))))
                         ((0, foldr (\(q, e) acc -> acc .|. (e `shiftL` (4 * q))) 0 (zip [0 ..] ends))
                          : zip [1 :: Int ..] its)
              else writeI ls (lineWords * c) (-1)
            cell (c + 1)
  cell 0
  freezeI ls

lineWords, lineEntries :: Int
lineWords   = 4
lineEntries = 15

-- | @rayGridLookup rg px py qx qy line list none@: the list of
-- 'rayGridList' for the segment, read from its cell's 32-byte line when the
-- cell's lists are short: @line ls w s e@, where the list's boxes are
-- @rayGridLineItem ls w k@ for @k@ from @s@ to @e - 1@; otherwise @list
-- items s e@ as 'rayGridList' gives it; @none@ when the grid does not
-- answer for the segment. Either way the same boxes in the same order as
-- 'rayGridList'.
rayGridLookup :: RayGrid -> Double -> Double -> Double -> Double
              -> (IntArr -> Int -> Int -> Int -> r) -> (IntArr -> Int -> Int -> r) -> r -> r
rayGridLookup NoRayGrid _ _ _ _ _ _ none = none
rayGridLookup (RayGrid x0 y0 x1 y1 inv nx ny starts items ls) px py qx qy line list none
  | px >= x0 && px <= x1 && py >= y0 && py <= y1
    && dx * dx + dy * dy <= rayGridReach * rayGridReach =
      let i = min (nx - 1) (truncate ((px - x0) * inv))
          j = min (ny - 1) (truncate ((py - y0) * inv))
          q = (if dx < 0 then 1 else 0) + (if dy < 0 then 2 else 0)
          c = j * nx + i
          w = lineWords * c
          h = indexI ls w
      in if h /= -1
           then line ls w (if q == 0 then 0 else (h `shiftR` (4 * (q - 1))) .&. 15)
                          ((h `shiftR` (4 * q)) .&. 15)
           else let l = 4 * c + q in list items (indexI starts l) (indexI starts (l + 1))
  | otherwise = none
  where
    dx = qx - px
    dy = qy - py
{-# INLINE rayGridLookup #-}

-- | Entry @k@ of the cell line at word @w@ (see 'rayGridLookup').
rayGridLineItem :: IntArr -> Int -> Int -> Int
rayGridLineItem ls w k = let h = k + 1 in (indexI ls (w + h `shiftR` 2) `shiftR` (16 * (h .&. 3))) .&. 0xffff
{-# INLINE rayGridLineItem #-}
