{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.SpatialIndex
-- Description : Uniform grids over the world, so that collision tests and
--               sensors only look at what is near.
--
-- Two indexes, both a uniform grid of square cells over a rectangular
-- /domain/ (the world and its boundary walls), stored as flat unboxed
-- arrays (each cell's items contiguous, \"compressed sparse rows\"):
--
-- * a 'BoxIndex' of the static obstacles (built once per world), where
--   each box is listed in every cell its bounding box overlaps;
-- * a 'PointIndex' of points (the centres of robots or balls, built once
--   per step), each listed in the cell that contains it.
--
-- A box index also carries the ray lists of "AFrobRobotSim.RayGrid" for its
-- boxes ('boxIndexRays'), built the first time a ray needs them.
--
-- A query names a rectangle and visits every item listed in a cell the
-- rectangle overlaps: a superset of the items whose shape overlaps the
-- rectangle. So a caller that asks for a rectangle containing every place
-- where an item could matter, and then applies its exact test to what it
-- is given, gets exactly the answer of testing every item. A box may be
-- visited more than once (once per cell); a point is visited once.
--
-- Coordinates outside the domain are clamped to the border cells, which
-- keeps every query a superset (clamping is monotone). A query rectangle
-- that is not finite visits every item, and items whose coordinates are
-- not finite are visited by every query, so that non-finite numbers give
-- what testing every item would give.
module AFrobRobotSim.SpatialIndex
  ( -- * Numbers
    finite
    -- * Static boxes
  , BoxIndex
  , boxIndex
  , boxIndexCount
  , boxAt
  , foldBoxesIn
  , boxIndexRays
  , boxIndexWild
    -- * Points
  , PointIndex
  , pointIndex
  , pointIndexOn
  , pointIndexCount
  , pointX
  , pointY
  , foldPointsIn
  , foldPointsInM
  , pointsInCellsOf
  , PointWindow
  , pointWindow
  , windowSize
  , foldWindowM
  , foldWindowCellsM
  ) where

import           Control.Monad.ST (runST)

import           AFrobRobotSim.FlatArray
import           AFrobRobotSim.RayGrid    (RayGrid, rayGrid)
import           AFrobRobotSim.Shapes     (Box (..))

------------------------------------------------------------------------------
-- Grids

-- | A uniform grid: origin, cell size, number of cells along x and y.
data Grid = Grid
  { gX0 :: {-# UNPACK #-} !Double
  , gY0 :: {-# UNPACK #-} !Double
  , gCs :: {-# UNPACK #-} !Double
  , gNx :: {-# UNPACK #-} !Int
  , gNy :: {-# UNPACK #-} !Int
  } deriving (Show)

-- | @gridFor x0 y0 x1 y1 n@: a grid over the rectangle for about @n@
-- items spread over it: cells of about the area per item, at least 1 m
-- and at most 8 m across, at most 2^16 cells. A degenerate or non-finite
-- rectangle, or @n <= 4@ (where looking at everything is as fast), gets
-- a single cell.
gridFor :: Double -> Double -> Double -> Double -> Int -> Grid
gridFor x0 y0 x1 y1 n
  | n <= 4 || not (finite w && finite h && finite x0 && finite y0) || w <= 0 || h <= 0
  = Grid x0' y0' (1 / 0) 1 1
  | otherwise = Grid x0 y0 cs nx ny
  where
    w  = x1 - x0
    h  = y1 - y0
    x0' = if finite x0 then x0 else 0
    y0' = if finite y0 then y0 else 0
    cs0 = max 1 (min 8 (sqrt (w * h / fromIntegral n)))
    cs  = max cs0 (sqrt (w * h / 65536))
    nx  = max 1 (ceiling (w / cs))
    ny  = max 1 (ceiling (h / cs))

-- | The number of cells of a grid.
gridCells :: Grid -> Int
gridCells g = gNx g * gNy g

-- The column (or row) of a coordinate, clamped to the grid.
cellOf :: Double -> Double -> Int -> Double -> Int
cellOf o cs n v =
  let c = (v - o) / cs
  in if c >= 1 then (if c >= fromIntegral n then n - 1 else truncate c)
     else 0
{-# INLINE cellOf #-}

------------------------------------------------------------------------------
-- Static boxes

-- | The static obstacles on a grid. Every box keeps its position in the
-- list the index was built from (0 for the first).
data BoxIndex = BoxIndex
  { biGrid   :: !Grid
  , biCoords :: !DblArr   -- box i is [4i .. 4i + 3]: min x, min y, max x, max y
  , biCount  :: {-# UNPACK #-} !Int
  , biStarts :: !IntArr   -- cell c lists biItems [starts c .. starts (c + 1) - 1]
  , biItems  :: !IntArr
  , biWild   :: [Int]     -- boxes with non-finite coordinates (visited always)
  , biRays   :: RayGrid   -- for rays ("AFrobRobotSim.RayCast"), built when first needed
  }

-- | Index a list of boxes: the domain is their bounding box.
boxIndex :: [Box] -> BoxIndex
boxIndex boxes = runST $ do
  (st, it) <- bucketLists (gridCells grid) (\f ->
    mapM_ (\(i, b) -> forCells b (f i)) (filter (tameBox . snd) indexed))
  coords <- newDblArr (max 1 (4 * n))
  mapM_ (\(i, Box a b c d) -> do
            writeD coords (4 * i) a
            writeD coords (4 * i + 1) b
            writeD coords (4 * i + 2) c
            writeD coords (4 * i + 3) d) indexed
  co <- freezeD coords
  pure (BoxIndex grid co n st it [ i | (i, b) <- indexed, not (tameBox b) ]
                 (rayGrid (filter (tameBox . snd) indexed)))
  where
    n       = length boxes
    indexed = zip [0 ..] boxes
    tame    = filter tameBox boxes
    tameBox (Box a b c d) = finite a && finite b && finite c && finite d
    grid    = case tame of
      [] -> gridFor 0 0 0 0 0
      _  -> gridFor (minimum (map boxMinX tame)) (minimum (map boxMinY tame))
                    (maximum (map boxMaxX tame)) (maximum (map boxMaxY tame)) (length tame)
    forCells (Box a b c d) k =
      let Grid gx gy cs nx ny = grid
          cx0 = cellOf gx cs nx a
          cx1 = cellOf gx cs nx c
          cy0 = cellOf gy cs ny b
          cy1 = cellOf gy cs ny d
      in mapM_ k [ cy * nx + cx | cy <- [cy0 .. cy1], cx <- [cx0 .. cx1] ]

-- | How many boxes are indexed.
boxIndexCount :: BoxIndex -> Int
boxIndexCount = biCount

-- | The box at a position of the original list.
boxAt :: BoxIndex -> Int -> Box
boxAt bi i = let co = biCoords bi
             in Box (indexD co (4 * i)) (indexD co (4 * i + 1)) (indexD co (4 * i + 2)) (indexD co (4 * i + 3))
{-# INLINE boxAt #-}

-- | The boxes a short ray from each place can meet ("AFrobRobotSim.RayGrid",
-- for "AFrobRobotSim.RayCast"), built the first time a ray needs them.
boxIndexRays :: BoxIndex -> RayGrid
boxIndexRays = biRays

-- | The positions of the boxes with non-finite coordinates (every query
-- visits them).
boxIndexWild :: BoxIndex -> [Int]
boxIndexWild = biWild

-- | @foldBoxesIn bi x0 y0 x1 y1 f z@ folds @f@ (strictly) over the boxes
-- that overlap the rectangle @[x0, x1] x [y0, y1]@ (closed), giving it the
-- box's position in the original list and the box, possibly more than
-- once (once per cell it is listed in). A query that is not finite visits
-- every box, and boxes with non-finite coordinates are always visited. A
-- rectangle with @x1 < x0@ or @y1 < y0@ is empty: it meets no box.
foldBoxesIn :: BoxIndex -> Double -> Double -> Double -> Double
            -> (a -> Int -> Box -> a) -> a -> a
foldBoxesIn bi x0 y0 x1 y1 f z0
  | not (finite x0 && finite y0 && finite x1 && finite y1) = goAll 0 z0
  | x1 < x0 || y1 < y0 = wild (biWild bi) z0
  | otherwise = cell cy0 cx0 z0
  where
    !(Grid gx gy cs nx ny) = biGrid bi
    !cx0 = cellOf gx cs nx x0
    !cx1 = cellOf gx cs nx x1
    !cy0 = cellOf gy cs ny y0
    !cy1 = cellOf gy cs ny y1
    starts = biStarts bi
    items  = biItems bi
    -- One loop, every call a tail call (so that GHC compiles it to jumps,
    -- allocating no closures): the cells row by row, then each cell's
    -- items, then the wild boxes.
    cell !cy !cx !z
      | cx > cx1  = cell (cy + 1) cx0 z
      | cy > cy1  = wild (biWild bi) z
      | otherwise = let c = cy * nx + cx
                    in inCell cy cx (indexI starts c) (indexI starts (c + 1)) z
    inCell !cy !cx !k !e !z
      | k >= e    = cell cy (cx + 1) z
      | otherwise =
          let i = indexI items k
              box@(Box a b c d) = boxAt bi i
          in -- only the boxes that meet the rectangle (a cheap test that
             -- saves the caller's exact one)
             if a <= x1 && c >= x0 && b <= y1 && d >= y0
               then inCell cy cx (k + 1) e (f z i box)
               else inCell cy cx (k + 1) e z
    wild [] !z       = z
    wild (i : is) !z = wild is (f z i (boxAt bi i))
    goAll !i !z
      | i >= biCount bi = z
      | otherwise       = goAll (i + 1) (f z i (boxAt bi i))
{-# INLINE foldBoxesIn #-}

------------------------------------------------------------------------------
-- Points

-- | Points on a grid, each keeping its position in the list the index was
-- built from (0 for the first).
data PointIndex = PointIndex
  { piGrid   :: !Grid
  , piCount  :: {-# UNPACK #-} !Int
  , piXs     :: !DblArr
  , piYs     :: !DblArr
  , piStarts :: !IntArr
  , piItems  :: !IntArr
  , piWild   :: [Int]     -- points with non-finite coordinates (visited always)
  }

-- | Index the points @(x, y)@ of a list on a grid over the given domain
-- (@x0 y0 x1 y1@; points outside it go to the border cells).
pointIndex :: Double -> Double -> Double -> Double -> [(Double, Double)] -> PointIndex
pointIndex = pointIndexOn fst snd

-- | @pointIndexOn px py@: 'pointIndex' of the points @(px e, py e)@ of the
-- elements @e@ of a list, made without the list of pairs (the simulator
-- indexes its robots and balls this way at every step).
pointIndexOn :: (e -> Double) -> (e -> Double) -> Double -> Double -> Double -> Double -> [e] -> PointIndex
pointIndexOn px py dx0 dy0 dx1 dy1 pts = runST $ do
  let Grid gx gy cs nx ny = grid
      cellAt x y = cellOf gy cs ny y * nx + cellOf gx cs nx x
  xs <- newDblArr (max 1 n)
  ys <- newDblArr (max 1 n)
  cellOfPt <- newIntArrUnset (max 1 n)
  -- One pass over the list: the coordinates and each point's cell (-1 for
  -- a point that is not finite); the points that are not finite, in order.
  let scan !_ [] wild = pure (reverse wild)
      scan !i (e : rest) wild = do
        let !x = px e
            !y = py e
        writeD xs i x
        writeD ys i y
        if finite x && finite y
          then writeI cellOfPt i (cellAt x y) >> scan (i + 1) rest wild
          else writeI cellOfPt i (-1) >> scan (i + 1) rest (i : wild)
  wild <- scan 0 pts []
  -- Then every finite point in its cell, in order.
  let eachPoint f = go 0
        where go !i | i >= n    = pure ()
                    | otherwise = do c <- readI cellOfPt i
                                     if c >= 0 then f i c else pure ()
                                     go (i + 1)
  (st, it) <- bucketLists (gridCells grid) eachPoint
  xs' <- freezeD xs
  ys' <- freezeD ys
  pure (PointIndex grid n xs' ys' st it wild)
  where
    n    = length pts
    grid = gridFor dx0 dy0 dx1 dy1 n
{-# INLINE pointIndexOn #-}

-- | How many points are indexed.
pointIndexCount :: PointIndex -> Int
pointIndexCount = piCount

-- | The coordinates a point was indexed with.
pointX, pointY :: PointIndex -> Int -> Double
pointX p i = indexD (piXs p) i
pointY p i = indexD (piYs p) i
{-# INLINE pointX #-}
{-# INLINE pointY #-}

-- | @foldPointsIn p x0 y0 x1 y1 f z@ folds @f@ (strictly) over the points
-- (as indexed) that lie in the rectangle @[x0, x1] x [y0, y1]@ (closed),
-- giving it the point's position in the original list, each once. A query
-- that is not finite visits every point, and points with non-finite
-- coordinates are always visited.
foldPointsIn :: PointIndex -> Double -> Double -> Double -> Double
             -> (a -> Int -> a) -> a -> a
foldPointsIn p x0 y0 x1 y1 f z0 = case pointWindow p x0 y0 x1 y1 of
  PointWindow _ _ _ _ _ cx0 cx1 cy0 cy1
    | cy1 < 0   -> goAll 0 z0   -- (a rectangle that is not finite)
    | otherwise -> row cx0 cx1 cy0 cy1 z0
  where
    nx = gNx (piGrid p)
    starts = piStarts p
    items  = piItems p
    -- One loop of tail calls (no closures allocated): a row's cells are
    -- contiguous in the items array, so each row is one run of items.
    -- ('foldPointsInM' is the same loop in a monad. Written as that at
    -- 'Identity', this fold cost 4% more instructions per robot-step of
    -- the 10-robot simulator benchmark (cachegrind), so it stays apart.)
    row !cx0 !cx1 !cy !cy1 !z
      | cy > cy1  = wild (piWild p) z
      | otherwise = inRow cx0 cx1 cy cy1 (indexI starts (cy * nx + cx0)) (indexI starts (cy * nx + cx1 + 1)) z
    inRow !cx0 !cx1 !cy !cy1 !k !e !z
      | k >= e    = row cx0 cx1 (cy + 1) cy1 z
      | otherwise =
          let i = indexI items k
              x = indexD (piXs p) i
              y = indexD (piYs p) i
          in if x >= x0 && x <= x1 && y >= y0 && y <= y1
               then inRow cx0 cx1 cy cy1 (k + 1) e (f z i)
               else inRow cx0 cx1 cy cy1 (k + 1) e z
    wild [] !z       = z
    wild (i : is) !z = wild is (f z i)
    goAll !i !z
      | i >= piCount p = z
      | otherwise      = goAll (i + 1) (f z i)
{-# INLINE foldPointsIn #-}

-- | 'foldPointsIn' with an action (in 'ST', for example) at every point.
foldPointsInM :: Monad m => PointIndex -> Double -> Double -> Double -> Double
              -> (a -> Int -> m a) -> a -> m a
foldPointsInM p x0 y0 x1 y1 = foldWindowM (pointWindow p x0 y0 x1 y1)
{-# INLINE foldPointsInM #-}

-- | How many points 'foldPointsIn' looks at for the rectangle: those
-- listed in the cells it overlaps and those with non-finite coordinates
-- (every point for a rectangle that is not finite). At least as many as
-- it visits: for sizing a buffer before the fold.
pointsInCellsOf :: PointIndex -> Double -> Double -> Double -> Double -> Int
pointsInCellsOf p x0 y0 x1 y1 = windowSize (pointWindow p x0 y0 x1 y1)

-- | A rectangle's cells in a point index, found once for a caller that
-- both sizes a buffer ('windowSize') and folds over the points
-- ('foldWindowM'): @foldWindowM (pointWindow p x0 y0 x1 y1)@ is
-- @foldPointsInM p x0 y0 x1 y1@, and 'windowSize' is 'pointsInCellsOf'.
data PointWindow = PointWindow
  !PointIndex
  {-# UNPACK #-} !Double {-# UNPACK #-} !Double  -- the rectangle: x0, y0,
  {-# UNPACK #-} !Double {-# UNPACK #-} !Double  -- x1, y1
  {-# UNPACK #-} !Int {-# UNPACK #-} !Int        -- its cells' columns,
  {-# UNPACK #-} !Int {-# UNPACK #-} !Int        -- rows (-1 -1: every point)

-- | The cells of a rectangle (see 'PointWindow').
pointWindow :: PointIndex -> Double -> Double -> Double -> Double -> PointWindow
pointWindow p x0 y0 x1 y1
  | not (finite x0 && finite y0 && finite x1 && finite y1) = PointWindow p x0 y0 x1 y1 0 0 (-1) (-1)
  | otherwise = PointWindow p x0 y0 x1 y1 (cellOf gx cs nx x0) (cellOf gx cs nx x1)
                                          (cellOf gy cs ny y0) (cellOf gy cs ny y1)
  where
    Grid gx gy cs nx ny = piGrid p
{-# INLINE pointWindow #-}

-- | How many points a fold over the window looks at (see 'pointsInCellsOf').
windowSize :: PointWindow -> Int
windowSize (PointWindow p _ _ _ _ cx0 cx1 cy0 cy1)
  | cy1 < 0   = piCount p
  | otherwise = rows cy0 (length (piWild p))
  where
    nx = gNx (piGrid p)
    starts = piStarts p
    rows !cy !acc
      | cy > cy1  = acc
      -- (a rectangle with x1 < x0 has no cells in a row: none counted, as
      -- none are visited)
      | otherwise = rows (cy + 1) (acc + max 0 (indexI starts (cy * nx + cx1 + 1) - indexI starts (cy * nx + cx0)))
{-# INLINE windowSize #-}

-- | 'foldPointsInM' over a window's points.
foldWindowM :: Monad m => PointWindow -> (a -> Int -> m a) -> a -> m a
foldWindowM win@(PointWindow _ x0 y0 x1 y1 _ _ _ _) f =
  foldWindowWith (\x y -> x >= x0 && x <= x1 && y >= y0 && y <= y1) win (\z i _ _ -> f z i)
{-# INLINE foldWindowM #-}

-- | A fold over every point listed in the window's cells, and every point
-- with non-finite coordinates ('windowSize' of them, a superset of what
-- 'foldWindowM' visits), without testing it against the rectangle: for a
-- caller that applies a test of its own, such as a distance, and is given
-- each point's coordinates (as indexed) with its number.
foldWindowCellsM :: Monad m => PointWindow -> (a -> Int -> Double -> Double -> m a) -> a -> m a
foldWindowCellsM = foldWindowWith (\_ _ -> True)
{-# INLINE foldWindowCellsM #-}

-- The fold of both: the points listed in the window's cells that pass
-- the test, then every point with non-finite coordinates (for a window
-- that is not finite, every point, untested).
foldWindowWith :: Monad m => (Double -> Double -> Bool) -> PointWindow
               -> (a -> Int -> Double -> Double -> m a) -> a -> m a
foldWindowWith keep (PointWindow p _ _ _ _ cx0 cx1 cy0 cy1) f z0
  | cy1 < 0   = goAll 0 z0
  | otherwise = row cy0 z0
  where
    nx = gNx (piGrid p)
    starts = piStarts p
    items  = piItems p
    at z i = f z i (indexD (piXs p) i) (indexD (piYs p) i)
    {-# INLINE at #-}
    -- One loop of tail calls (no closures allocated): a row's cells are
    -- contiguous in the items array, so each row is one run of items.
    row !cy !z
      | cy > cy1  = wild (piWild p) z
      | otherwise = inRow cy (indexI starts (cy * nx + cx0)) (indexI starts (cy * nx + cx1 + 1)) z
    inRow !cy !k !e !z
      | k >= e    = row (cy + 1) z
      | otherwise = do
          let i = indexI items k
              x = indexD (piXs p) i
              y = indexD (piYs p) i
          z' <- if keep x y then f z i x y else pure z
          inRow cy (k + 1) e z'
    wild [] !z       = pure z
    wild (i : is) !z = at z i >>= wild is
    goAll !i !z
      | i >= piCount p = pure z
      | otherwise      = at z i >>= goAll (i + 1)
{-# INLINE foldWindowWith #-}
