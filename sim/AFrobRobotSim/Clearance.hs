{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Clearance
-- Description : How far the static world is, cell by cell: a cheap test
--               that a small move cannot touch any wall or block.
--
-- A simbot moves a centimetre or so per step and spends most of its time
-- well clear of walls and blocks, yet every step its swept disc would be
-- tested against the boxes that the grid finds near its path. A
-- 'Clearance' answers first, from one array read, whether any box can be
-- near enough to matter: for every cell of a grid over the arena it holds a
-- lower bound on the distance from /any/ point of the cell to /any/ box
-- (capped at 'clearanceCap'). A disc of radius @r@ at @p@ moving by @d@
-- cannot touch a box when that bound for @p@'s cell exceeds @|d| + r@: every
-- point of its path is within @|d|@ of @p@. Skipping the boxes then gives
-- exactly the answer testing them would (none touches), so the physics
-- stays bit for bit what it was.
--
-- The bound of a cell is the least distance between the cell's rectangle
-- and a box's rectangle, over the boxes the index finds within the cap of
-- the cell (a box it does not find is further than the cap along x or y),
-- rounded down to a multiple of 'clearanceQuantum' and kept in one byte: a
-- large world's grid (512 by 512 cells) then takes 256 KB instead of 2 MB,
-- and each robot's read of it at each step, at a place of no relation to
-- the previous robot's, seldom misses the processor's caches (at 10,000
-- robots the read of the 2 MB grid took two thirds of the time of planning
-- a move: @bench/README.md@, the twentieth round).
-- A world with a box that is not finite gets no clearance anywhere (every
-- bound 0), so that nothing is ever skipped there.
module AFrobRobotSim.Clearance
  ( Clearance
  , clearanceOf
  , clearanceAt
  , clearanceCap
  , clearanceQuantum
  , clearanceQuanta
  , clearanceCellSize
  ) where

import           Control.Monad.ST        (runST)

import           AFrobRobotSim.FlatArray (W8Arr, freezeW8, indexW8, newW8Arr, writeW8)

import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex

-- | Lower bounds on the distance to the static world, cell by cell.
data Clearance = Clearance
  { clX0   :: {-# UNPACK #-} !Double
  , clY0   :: {-# UNPACK #-} !Double
  , clCs   :: {-# UNPACK #-} !Double
  , clNx   :: {-# UNPACK #-} !Int
  , clNy   :: {-# UNPACK #-} !Int
  , clDist :: !W8Arr  -- cell (ix, iy) at iy * nx + ix, in quanta
  }

-- | The largest bound a cell holds, 1 m: enough for a step at any speed
-- a simbot reaches, and it keeps the search for each cell's bound short.
clearanceCap :: Double
clearanceCap = 1

-- | The step of the bounds a cell holds: a 255th of 'clearanceCap' (about
-- 4 mm). Each bound is the largest multiple of it not above the distance
-- computed for the cell ('clearanceQuanta'), so it is still a lower bound,
-- and less than a quantum below that distance.
clearanceQuantum :: Double
clearanceQuantum = clearanceCap / 255

-- | The side of the cells over an extent of @w@ by @h@ metres: a quarter
-- of a metre (about a simbot's radius, so that a simbot following a wall
-- at a few decimetres is clear of it), larger in worlds so big that the
-- grid would otherwise have more than 512 cells a side.
clearanceCellSize :: Double -> Double -> Double
clearanceCellSize w h = max 0.25 (max w h / 512)

-- | @clearanceOf index (x0, y0, x1, y1)@: the clearance of the boxes of
-- @index@ over the extent @[x0, x1] x [y0, y1]@, computed once, when first
-- needed. 0 everywhere if a box is not finite.
clearanceOf :: BoxIndex -> (Double, Double, Double, Double) -> Clearance
clearanceOf bi (x0, y0, x1, y1)
  | not (null (boxIndexWild bi)) || not (all finite [x0, y0, x1, y1]) || x1 < x0 || y1 < y0 =
      Clearance 0 0 1 1 1 (fromList [0])
  | otherwise = Clearance x0 y0 cs nx ny (fromList bounds)
  where
    cs = clearanceCellSize (x1 - x0) (y1 - y0)
    nx = max 1 (ceiling ((x1 - x0) / cs))
    ny = max 1 (ceiling ((y1 - y0) / cs))
    bounds = [ cellBound (x0 + fromIntegral ix * cs) (y0 + fromIntegral iy * cs)
             | iy <- [0 .. ny - 1], ix <- [0 .. nx - 1] ]
    cellBound ax0 ay0 =
      let ax1 = ax0 + cs
          ay1 = ay0 + cs
      in foldBoxesIn bi (ax0 - clearanceCap) (ay0 - clearanceCap)
                        (ax1 + clearanceCap) (ay1 + clearanceCap)
           (\acc _ (Box bx0 by0 bx1 by1) ->
              let gx = max 0 (max (bx0 - ax1) (ax0 - bx1))
                  gy = max 0 (max (by0 - ay1) (ay0 - by1))
              in min acc (sqrt (gx * gx + gy * gy)))
           clearanceCap
    fromList xs = runST $ do
      arr <- newW8Arr (length xs)
      mapM_ (\(i, d) -> writeW8 arr i (fromIntegral (clearanceQuanta d))) (zip [0 ..] xs)
      freezeW8 arr

-- | The bound a cell holds for the distance @d@, in quanta: the largest
-- @q@ from 0 to 255 with @q * 'clearanceQuantum' <= d@ (the product as
-- 'clearanceAt' computes it), so 255 for @d >= 'clearanceCap'@, and 0 for
-- a @d@ that is not positive (or NaN).
clearanceQuanta :: Double -> Int
clearanceQuanta d
  | not (d > 0) = 0
  | otherwise   = down (up (max 0 (min 255 (floor (min 1 d * 255)))))
  where
    -- (@d * 255@ rounds, so the first guess can be a quantum off either
    -- way: 33 quanta's distance times 255 came to 32.99...)
    fits q = fromIntegral q * clearanceQuantum <= d
    up q   | q < 255 && fits (q + 1) = up (q + 1)
           | otherwise               = q
    down q | q > 0 && not (fits q) = down (q - 1)
           | otherwise             = q

-- | The bound for the cell holding the point @(x, y)@: no box is nearer to
-- the point than this. 0 for a point outside the grid (or not finite).
clearanceAt :: Clearance -> Double -> Double -> Double
clearanceAt cl x y
  | fx >= 0 && fy >= 0 && ix < clNx cl && iy < clNy cl =
      fromIntegral (indexW8 (clDist cl) (iy * clNx cl + ix)) * clearanceQuantum
  | otherwise                                         = 0
  where
    fx = (x - clX0 cl) / clCs cl
    fy = (y - clY0 cl) / clCs cl
    -- truncate only what is known to be in range (and so finite)
    ix = if fx >= 0 && fx < fromIntegral (clNx cl) then truncate fx else clNx cl
    iy = if fy >= 0 && fy < fromIntegral (clNy cl) then truncate fy else clNy cl
{-# INLINE clearanceAt #-}
