{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Shapes.Box
-- Description : The closed axis-aligned box the simulator's kernels test
--               against.
--
-- Walls, blocks and the cells of the spatial indexes are 'Box'es. A box is
-- closed: its boundary belongs to it. Part of "AFrobRobotSim.Shapes",
-- which re-exports all of it.
module AFrobRobotSim.Shapes.Box
  ( Box (..)
  , boxAround
  , boxCentre
  ) where

import AFRP.Geometry (Point2 (..))

-- | A closed axis-aligned rectangle
-- @[boxMinX, boxMaxX] × [boxMinY, boxMaxY]@.
--
-- Invariant (not checked): @boxMinX <= boxMaxX@ and @boxMinY <= boxMaxY@.
-- A box of width or height 0 (a segment or a point) is allowed.
data Box = Box
  { boxMinX :: {-# UNPACK #-} !Double  -- ^ Left edge (smallest x).
  , boxMinY :: {-# UNPACK #-} !Double  -- ^ Bottom edge (smallest y).
  , boxMaxX :: {-# UNPACK #-} !Double  -- ^ Right edge (largest x).
  , boxMaxY :: {-# UNPACK #-} !Double  -- ^ Top edge (largest y).
  } deriving (Eq, Show)

-- | @boxAround c w h@ is the box of width @w@ (along x) and height @h@
-- (along y) centred on @c@. The absolute values of @w@ and @h@ are used, so
-- the result always satisfies the 'Box' invariant.
--
-- >>> boxAround (Point2 1 2) 4 2
-- Box {boxMinX = -1.0, boxMinY = 1.0, boxMaxX = 3.0, boxMaxY = 3.0}
boxAround :: Point2 Double -> Double -> Double -> Box
boxAround (Point2 cx cy) w h = Box (cx - hw) (cy - hh) (cx + hw) (cy + hh)
  where
    !hw = 0.5 * abs w
    !hh = 0.5 * abs h
{-# INLINE boxAround #-}

-- | The centre of a box (the midpoint of its diagonal).
boxCentre :: Box -> Point2 Double
boxCentre (Box x0 y0 x1 y1) = Point2 (0.5 * (x0 + x1)) (0.5 * (y0 + y1))
{-# INLINE boxCentre #-}
