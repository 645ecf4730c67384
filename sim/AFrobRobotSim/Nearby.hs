{-# LANGUAGE BangPatterns #-}
{-# LANGUAGE RankNTypes   #-}
-- |
-- Module      : AFrobRobotSim.Nearby
-- Description : The points of an index near a place, gathered once and
--               shared: a bound on their distance, a fold over them, and
--               those within a range sorted by distance.
--
-- A robot's sensors look at the robots (and balls) near it: the tracker
-- lists those within its range, nearest first, each ray tests those it
-- can hit, and the move takes a lower bound on the distance to all of
-- them. "AFrobRobotSim.Sensors" gathers them once per robot and sample
-- ('gatherNear'), into unboxed arrays of their numbers in the index and
-- their squared distances (no list or box per point: a packed world puts
-- 50 robots within range of each), and every reading works from those.
-- The tracker's list is sorted in the arrays too ('inRangeSorted'), a
-- band of distances at a time when many points are near. The points
-- gathered are exactly those a look at every point of the index finds
-- within the distance, and the list is sorted by distance, then number,
-- as a look at every point would sort it; 'nearestOf' is a lower bound.
module AFrobRobotSim.Nearby
  ( -- * Gathering
    Gathered
  , gatherNear
  , nearestOf
    -- * Selecting and folding
  , Some
  , allNear
  , selectNear
  , foldNear
    -- * Sorted by distance
  , inRangeSorted
  ) where

import           Control.Monad.ST           (ST, runST)

import           AFrobRobotSim.FlatArray
import           AFrobRobotSim.SpatialIndex

-- | @gatherNear r grid skip px py@: the points of an index (all but number
-- @skip@; -1 skips none) within distance @r@ of @(px, py)@ (a negative or
-- NaN @r@ counts as 0), in unboxed arrays (no list or box per point: a
-- packed world puts 50 robots within range of each): their indexes and
-- squared distances; their coordinates are read from the index itself.
-- An index of a few points is scanned, which costs less than walking the
-- cells of the square around the range (in the 10-robot benchmark, that
-- square covers most of the world); a larger one is walked cell by cell,
-- into arrays as large as the points listed in those cells. The order of the
-- points is the walk's: nothing read from them depends on it (a ray takes
-- the nearest hit, the tracker sorts).
gatherNear :: Double -> PointIndex -> Int -> Double -> Double -> Gathered
gatherNear r grid skip px py
  | n <= 32   = gatherBy n (\add -> let scan !j !c
                                          | j >= n    = pure c
                                          | otherwise = add c j (pointX grid j) (pointY grid j) >>= scan (j + 1)
                                   in scan 0 0)
  | otherwise =
      -- (the window is taken apart here, before the two loops that read
      -- it: bound lazily for both, it was a record allocated for every
      -- robot and step; the points of its cells are tested by distance
      -- alone)
      case pointWindow grid (px - tr) (py - tr) (px + tr) (py + tr) of
        !win -> gatherBy (windowSize win) (\add -> foldWindowCellsM win add 0)
  where
    n  = pointIndexCount grid
    tr = max 0 r   -- (max 0 NaN is 0)
    -- the points a walk gives, into arrays of the given size
    gatherBy :: Int -> (forall s. (Int -> Int -> Double -> Double -> ST s Int) -> ST s Int) -> Gathered
    gatherBy cap walk = runST $ do
      js  <- newIntArrUnset (max 1 cap)
      d2s <- newDblArr (max 1 cap)
      let add !c j qx qy
            | j == skip = pure c
            | otherwise =
                let x  = qx - px
                    y  = qy - py
                    d2 = x * x + y * y
                in if d2 <= tr * tr
                     then writeI js c j >> writeD d2s c d2 >> pure (c + 1)
                     else pure c
      k <- walk add
      Gathered tr grid k <$> freezeI js <*> freezeD d2s
    {-# INLINE gatherBy #-}

-- | The points of an index near a place ('gatherNear'): the distance
-- they were gathered within, the index, how many, and for the k-th its
-- number in the index and its squared distance from the place.
data Gathered = Gathered {-# UNPACK #-} !Double !PointIndex {-# UNPACK #-} !Int !IntArr !DblArr

-- | A lower bound on the distance from the place to every point of the
-- index but the one skipped: the distance to the nearest gathered point,
-- or the distance they were gathered within if there is none; 0 when
-- more than 16 are gathered (in such a crowd a robot is seldom far from
-- all the others, and the bound is not worth its pass over them).
nearestOf :: Gathered -> Double
nearestOf (Gathered tr _ k _ d2s)
  | k > bandsAbove = 0
  | otherwise      = go 0 (tr * tr)
  where
    go !p !m | p >= k    = sqrt m
             | otherwise = go (p + 1) (min m (indexD d2s p))

-- | Some of the gathered points, by their positions in the arrays.
data Some = None | Some {-# UNPACK #-} !Int !Some
          | All  -- every one

-- | All the gathered points.
allNear :: Gathered -> Some
allNear _ = All

-- | The gathered points that pass a test of their coordinates and squared
-- distance.
selectNear :: (Double -> Double -> Double -> Bool) -> Gathered -> Some
selectNear keep (Gathered _ grid k js d2s) = go (k - 1) None
  where
    go !p acc
      | p < 0     = acc
      | let j = indexI js p, keep (pointX grid j) (pointY grid j) (indexD d2s p) = go (p - 1) (Some p acc)
      | otherwise = go (p - 1) acc
{-# INLINE selectNear #-}

-- | A strict left fold over some gathered points (coordinates, squared
-- distance), in the order of their positions in the arrays.
foldNear :: (a -> Double -> Double -> Double -> a) -> a -> Gathered -> Some -> a
foldNear f z0 (Gathered _ grid k js d2s) sel = case sel of
  All -> every 0 z0
  _   -> some sel z0
  where
    -- (the coordinates read before the call: passed unread, each would be
    -- a box allocated for a function that may not look at it)
    at z p = let j   = indexI js p
                 !qx = pointX grid j
                 !qy = pointY grid j
                 !d2 = indexD d2s p
             in f z qx qy d2
    {-# INLINE at #-}
    every !p !z | p >= k    = z
                | otherwise = every (p + 1) (at z p)
    some None !z       = z
    some All !z        = every 0 z
    some (Some p r) !z = some r (at z p)
{-# INLINE foldNear #-}

-- | @inRangeSorted range mk g@: the gathered points within @range@ (at
-- most the distance they were gathered within) of the place, centre to
-- centre (the distance as 'AFRP.Geometry.vector2RhoTheta' has it: the
-- square root of the same sum of squares), nearest first, in index order
-- among equally near ones (as a stable sort of all of them by distance
-- would have them), each
-- made by @mk d j x y@ from its distance, its number in the index and its
-- coordinates there, evaluated as its list cell is made. Sorted in
-- unboxed arrays, with no list or thunk per point: a packed world puts
-- 50 robots within range of each, and sorting them as a list (an
-- insertion sort, then a lazy merge sort) was most of a sample's cost.
--
-- The list is made as it is read, and so is the sorting: more than 16
-- points are first put into bands of distance (below 1 m, 2 m, 3 m, and
-- the rest of the range), and a band is sorted when the list reaches
-- it.
-- A band holds only distances above the previous band's, so the bands'
-- sorted runs one after the other are the whole list sorted; a
-- controller that reads the nearest few robots (the usual case) sorts
-- the nearest bands only, about a tenth of the points in a packed world.
inRangeSorted :: Double -> (Double -> Int -> Double -> Double -> r) -> Gathered -> [r]
inRangeSorted range mk (Gathered _ grid n gjs gd2s)
  | n <= bandsAbove = run (sortedInRange range n gjs gd2s) []
  | otherwise = case banded range n gjs gd2s of
  Banded starts bds bjs ->
    let band b
          | b >= bandCount = []
          | otherwise =
              let lo = indexI starts b
                  hi = indexI starts (b + 1)
              in if lo >= hi then band (b + 1)
                 else run (sortedRun lo hi bds bjs) (band (b + 1))
    in band 0
  where
    -- a sorted run's elements, then @rest@
    run (Sorted k ds js) rest = build 0
      where
        build i
          | i >= k    = rest
          | otherwise = let j = indexI js i
                        in case mk (indexD ds i) j (pointX grid j) (pointY grid j) of
                             !e -> e : build (i + 1)
{-# INLINE inRangeSorted #-}

-- Up to how many gathered points 'inRangeSorted' sorts all at once (in
-- the 1000-robot benchmark world about 5 are gathered; bands there cost
-- 620 instructions a robot-step more than they save). Also the most
-- points 'nearestOf' looks at: beyond it, its bound is 0.
bandsAbove :: Int
bandsAbove = 16

-- The numbers and distances of 'inRangeSorted' sorted all at once.
sortedInRange :: Double -> Int -> IntArr -> DblArr -> Sorted
sortedInRange range n gjs gd2s = runST $ do
  ds <- newDblArr (max 1 n)
  js <- newIntArrUnset (max 1 n)
  let fill !p !c
        | p >= n    = pure c
        | otherwise =
            let d = sqrt (indexD gd2s p)
            in if d <= range then writeD ds c d >> writeI js c (indexI gjs p) >> fill (p + 1) (c + 1)
                             else fill (p + 1) c
  k <- fill 0 0
  sortedFrom k ds js

-- The gathered points within the range, their distances and
-- numbers grouped by band ('bandOf'), each band in the gathered order:
-- band @b@ is positions @[starts b, starts (b + 1))@ of the arrays.
data Banded = Banded !IntArr !DblArr !IntArr

-- How many bands of distance 'inRangeSorted' sorts one at a time.
bandCount :: Int
bandCount = 4

-- The band of a distance (centre to centre), or -1 beyond the range.
-- Bands are in the order of the distances they hold.
bandOf :: Double -> Double -> Int
bandOf range d
  | not (d <= range) = -1
  | d < 1            = 0
  | d < 2            = 1
  | d < 3            = 2
  | otherwise        = 3
{-# INLINE bandOf #-}

-- The gathered points in bands (a counting sort by band: stable).
banded :: Double -> Int -> IntArr -> DblArr -> Banded
banded range n gjs gd2s = runST $ do
  counts <- newIntArr (bandCount + 1) 0
  let count !p
        | p >= n    = pure ()
        | otherwise = do
            let b = bandOf range (sqrt (indexD gd2s p))
            if b >= 0 then readI counts (b + 1) >>= writeI counts (b + 1) . (+ 1) else pure ()
            count (p + 1)
  count 0
  let sums !b !acc
        | b > bandCount = pure acc
        | otherwise     = do c <- readI counts b
                             writeI counts b (acc + c)
                             sums (b + 1) (acc + c)
  total <- sums 0 0
  -- counts b is now where band b starts; 'next' is where its next point goes
  next <- newIntArr bandCount 0
  let copyStarts !b | b >= bandCount = pure ()
                    | otherwise      = readI counts b >>= writeI next b >> copyStarts (b + 1)
  copyStarts 0
  ds <- newDblArr (max 1 total)
  js <- newIntArrUnset (max 1 total)
  let place !p
        | p >= n    = pure ()
        | otherwise = do
            let d = sqrt (indexD gd2s p)
                b = bandOf range d
            if b >= 0
              then do o <- readI next b
                      writeD ds o d
                      writeI js o (indexI gjs p)
                      writeI next b (o + 1)
              else pure ()
            place (p + 1)
  place 0
  Banded <$> freezeI counts <*> freezeD ds <*> freezeI js

-- Positions @[lo, hi)@ of the banded arrays, sorted by distance then
-- number, in arrays of their own.
sortedRun :: Int -> Int -> DblArr -> IntArr -> Sorted
sortedRun lo hi bds bjs = runST $ do
  let k = hi - lo
  ds <- newDblArr (max 1 k)
  js <- newIntArrUnset (max 1 k)
  let copy !i | i >= k    = pure ()
              | otherwise = writeD ds i (indexD bds (lo + i)) >> writeI js i (indexI bjs (lo + i)) >> copy (i + 1)
  copy 0
  sortedFrom k ds js

data Sorted = Sorted !Int !DblArr !IntArr

-- The first @k@ keys of two arrays, sorted ('sortKeys'), as a 'Sorted'.
sortedFrom :: Int -> MDblArr s -> MIntArr s -> ST s Sorted
sortedFrom k ds js = do
  (ds', js') <- sortKeys k ds js
  Sorted k <$> freezeD ds' <*> freezeI js'
{-# INLINE sortedFrom #-}

-- Sort the first @k@ keys (distance, index) of two arrays, by distance
-- then index: runs of 8 by insertion, then merged bottom-up through a
-- second pair of arrays. Gives the arrays that hold the result.
sortKeys :: Int -> MDblArr s -> MIntArr s -> ST s (MDblArr s, MIntArr s)
sortKeys k ds js = do
  let runs !lo | lo >= k   = pure ()
               | otherwise = insertion ds js lo (min k (lo + 8)) >> runs (lo + 8)
  runs 0
  if k <= 8 then pure (ds, js) else do
    ds2 <- newDblArr k
    js2 <- newIntArrUnset k
    let pass !w sd sj td tj
          | w >= k    = pure (sd, sj)
          | otherwise = do
              let merges !lo | lo >= k   = pure ()
                             | otherwise = do
                                 let mid = min k (lo + w)
                                     hi  = min k (lo + 2 * w)
                                 merge sd sj td tj lo mid hi
                                 merges hi
              merges 0
              pass (2 * w) td tj sd sj
    pass 8 ds js ds2 js2

-- Is the key (d, j) before the key (e, k)?
before :: Double -> Int -> Double -> Int -> Bool
before d j e k = d < e || (d == e && j < k)
{-# INLINE before #-}

-- Insertion sort of the keys in [lo, hi).
insertion :: MDblArr s -> MIntArr s -> Int -> Int -> ST s ()
insertion ds js lo hi = outer (lo + 1)
  where
    outer !i
      | i >= hi   = pure ()
      | otherwise = do
          d <- readD ds i
          j <- readI js i
          let shift !p
                | p <= lo   = pure p
                | otherwise = do
                    e <- readD ds (p - 1)
                    k <- readI js (p - 1)
                    if before d j e k
                      then writeD ds p e >> writeI js p k >> shift (p - 1)
                      else pure p
          p <- shift i
          writeD ds p d
          writeI js p j
          outer (i + 1)

-- Merge the sorted runs [lo, mid) and [mid, hi) of the first arrays into
-- [lo, hi) of the second (stable: the left run first among equal keys).
merge :: MDblArr s -> MIntArr s -> MDblArr s -> MIntArr s -> Int -> Int -> Int -> ST s ()
merge sd sj td tj lo mid hi = go lo mid lo
  where
    go !a !b !o
      | o >= hi   = pure ()
      | a >= mid  = copy b o
      | b >= hi   = copy a o
      | otherwise = do
          d <- readD sd a
          j <- readI sj a
          e <- readD sd b
          k <- readI sj b
          if before e k d j
            then writeD td o e >> writeI tj o k >> go a (b + 1) (o + 1)
            else writeD td o d >> writeI tj o j >> go (a + 1) b (o + 1)
    copy !x !o
      | o >= hi   = pure ()
      | otherwise = do
          readD sd x >>= writeD td o
          readI sj x >>= writeI tj o
          copy (x + 1) (o + 1)
