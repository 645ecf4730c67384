{-# LANGUAGE FlexibleInstances      #-}
{-# LANGUAGE FunctionalDependencies #-}
{-# LANGUAGE MultiParamTypeClasses  #-}
-- |
-- Module      : AFRP.Geometry.Point
-- Description : Affine spaces; 2-D and 3-D points.
--
-- The 'AffineSpace' class and the point types 'Point2' and 'Point3', whose
-- displacements are 'Vector2' and 'Vector3'. Usually imported through
-- "AFRP.Geometry", whose documentation explains why points and vectors are
-- distinct types.
module AFRP.Geometry.Point
  ( -- * Affine spaces
    AffineSpace (..)
    -- * 2-D points
  , Point2 (..)
  , point2X
  , point2Y
    -- * 3-D points
  , Point3 (..)
  , point3X
  , point3Y
  , point3Z
  ) where

import Control.DeepSeq (NFData (..))

import AFRP.Geometry.Vector (Vector2 (..), Vector3 (..))
import AFRP.VectorSpace

infixl 6 .+^, .-^
infix  6 .-.

------------------------------------------------------------------------------
-- Affine spaces

-- | An affine space of points @p@ whose differences are vectors @v@ over
-- the scalars @a@.
--
-- Minimal complete definition: 'origin', '(.+^)' and '(.-.)'.
--
-- Laws (up to rounding): @p .+^ zeroVector == p@,
-- @(p .+^ u) .+^ v == p .+^ (u ^+^ v)@, @(p .+^ v) .-. p == v@,
-- @q .+^ (p .-. q) == p@, @p .-^ v == p .+^ negateVector v@.
--
-- Fixities: @infixl 6 .+^, .-^@ and @infix 6 .-.@.
class (Floating a, VectorSpace v a) => AffineSpace p v a | p -> v, v -> a where
  -- | The point whose coordinates are all zero.
  origin :: p

  -- | Move a point by a displacement vector.
  --
  -- >>> Point2 1 1 .+^ Vector2 2 3 :: Point2 Double
  -- Point2 3.0 4.0
  (.+^) :: p -> v -> p

  -- | Move a point by the opposite of a vector.
  -- Defaults to @p .-^ v = p .+^ negateVector v@.
  --
  -- >>> Point2 3 4 .-^ Vector2 2 3 :: Point2 Double
  -- Point2 1.0 1.0
  (.-^) :: p -> v -> p
  p .-^ v = p .+^ negateVector v
  {-# INLINE (.-^) #-}

  -- | The displacement from the second point to the first:
  -- @p .-. q@ is the vector @v@ with @q .+^ v == p@.
  --
  -- >>> Point2 3 4 .-. Point2 1 1 :: Vector2 Double
  -- Vector2 2.0 3.0
  (.-.) :: p -> p -> v

  -- | The Euclidean distance between two points.
  -- Defaults to @distance p q = norm (p .-. q)@.
  --
  -- >>> distance (Point2 0 0) (Point2 3 4 :: Point2 Double)
  -- 5.0
  distance :: p -> p -> a
  distance p q = norm (p .-. q)
  {-# INLINE distance #-}

------------------------------------------------------------------------------
-- 2-D points

-- | A point in the plane with (strict) x and y coordinates.
data Point2 a = Point2 !a !a
  deriving (Eq, Show)

instance NFData a => NFData (Point2 a) where
  rnf (Point2 x y) = rnf x `seq` rnf y

-- | Points in the plane, with 'Vector2' displacements.
instance (Eq a, Floating a) => AffineSpace (Point2 a) (Vector2 a) a where
  {-# SPECIALISE instance AffineSpace (Point2 Double) (Vector2 Double) Double #-}
  origin                          = Point2 0 0
  Point2 x y .+^ Vector2 vx vy    = Point2 (x + vx) (y + vy)
  Point2 x y .-^ Vector2 vx vy    = Point2 (x - vx) (y - vy)
  Point2 x1 y1 .-. Point2 x2 y2   = Vector2 (x1 - x2) (y1 - y2)
  {-# INLINE origin #-}
  {-# INLINE (.+^) #-}
  {-# INLINE (.-^) #-}
  {-# INLINE (.-.) #-}

-- | The x coordinate.
point2X :: Point2 a -> a
point2X (Point2 x _) = x
{-# INLINE point2X #-}

-- | The y coordinate.
point2Y :: Point2 a -> a
point2Y (Point2 _ y) = y
{-# INLINE point2Y #-}

------------------------------------------------------------------------------
-- 3-D points

-- | A point in space with (strict) x, y and z coordinates.
data Point3 a = Point3 !a !a !a
  deriving (Eq, Show)

instance NFData a => NFData (Point3 a) where
  rnf (Point3 x y z) = rnf x `seq` rnf y `seq` rnf z

-- | Points in space, with 'Vector3' displacements.
instance (Eq a, Floating a) => AffineSpace (Point3 a) (Vector3 a) a where
  {-# SPECIALISE instance AffineSpace (Point3 Double) (Vector3 Double) Double #-}
  origin                                  = Point3 0 0 0
  Point3 x y z .+^ Vector3 vx vy vz       = Point3 (x + vx) (y + vy) (z + vz)
  Point3 x y z .-^ Vector3 vx vy vz       = Point3 (x - vx) (y - vy) (z - vz)
  Point3 x1 y1 z1 .-. Point3 x2 y2 z2     =
    Vector3 (x1 - x2) (y1 - y2) (z1 - z2)
  {-# INLINE origin #-}
  {-# INLINE (.+^) #-}
  {-# INLINE (.-^) #-}
  {-# INLINE (.-.) #-}

-- | The x coordinate.
point3X :: Point3 a -> a
point3X (Point3 x _ _) = x
{-# INLINE point3X #-}

-- | The y coordinate.
point3Y :: Point3 a -> a
point3Y (Point3 _ y _) = y
{-# INLINE point3Y #-}

-- | The z coordinate.
point3Z :: Point3 a -> a
point3Z (Point3 _ _ z) = z
{-# INLINE point3Z #-}
