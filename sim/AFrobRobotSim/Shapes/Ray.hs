{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Shapes.Ray
-- Description : Ray casts at a box and at a disc, for the range finders.
--
-- A ray is @o + t*dir@ for @t >= 0@; a cast gives the smallest @t@ at
-- which the ray meets the shape (0 from inside it), or 'Nothing'. Part of
-- "AFrobRobotSim.Shapes", which re-exports 'rayBox' and 'rayCircle'.
--
-- 'fmax' and 'fmin' are defined here, beside the slab method that uses
-- them, and "AFrobRobotSim.Shapes.Collision" takes them from here.
-- Imported into this module instead, they reached 'rayBox' already
-- optimised, and GHC compiled its callers differently: the ray-box test
-- of "AFrobRobotSim.RayCast" boxed a 'Double' it does not box now.
module AFrobRobotSim.Shapes.Ray
  ( -- * Ray casting
    rayBox
  , rayCircle
    -- * Minimum and maximum that keep a zero's sign (internal helpers)
  , fmax
  , fmin
  ) where

import AFRP.Geometry (Point2 (..), Vector2 (..))
import AFrobRobotSim.Shapes.Box (Box (..))

------------------------------------------------------------------------------
-- Small strict helpers (all inlined)

-- | @fmax a b@ / @fmin a b@: like 'max' / 'min', but on a tie the /second/
-- argument wins. Used with the accumulated value second, so that an initial
-- @0.0@ is never replaced by an equal @-0.0@.
--
-- Internal helpers of the kernels, exported for
-- "AFrobRobotSim.Shapes.Collision" (and the tests) only: the umbrella
-- "AFrobRobotSim.Shapes" does not re-export them.
fmax, fmin :: Double -> Double -> Double
fmax a b = if a <= b then b else a
fmin a b = if b <= a then b else a
{-# INLINE fmax #-}
{-# INLINE fmin #-}

-- | One slab of the slab method: intersect the parameter interval
-- @[lo, hi]@ with the set of @t@ for which @o + t*d@ lies in @[a, b]@, and
-- continue with the new interval, or give 'Nothing' if it is empty.
-- A direction component that is zero (either @0.0@ or @-0.0@, both @== 0@)
-- never divides: the ray is parallel to the slab, and either always or never
-- inside it.
slab :: Double -> Double -> Double -> Double -> Double -> Double
     -> (Double -> Double -> Maybe r) -> Maybe r
slab o d a b lo hi k
  | d == 0 = if o < a || o > b then Nothing else k lo hi
  | otherwise =
      let !t1  = (a - o) / d
          !t2  = (b - o) / d
          !lo' = fmax (fmin t1 t2) lo
          !hi' = fmin (fmax t1 t2) hi
      in if lo' > hi' then Nothing else k lo' hi'
{-# INLINE slab #-}

------------------------------------------------------------------------------
-- Ray casting

-- | @rayBox o dir box@ casts the ray @o + t*dir@ (@t >= 0@) at a box.
--
-- Returns the smallest @t >= 0@ at which the ray point lies in the (closed)
-- box, i.e. on its boundary when the origin is outside; @'Just' 0@ when the
-- origin is inside or on the boundary; 'Nothing' when the ray misses. A ray
-- that only touches an edge or a corner counts as a hit.
--
-- @t@ is measured in units of @dir@, so it is the distance travelled when
-- @dir@ is a unit vector (the intended use). Slab method: a component of
-- @dir@ that is exactly zero (@0.0@ or @-0.0@) is handled without division,
-- so axis-parallel rays are exact. With @dir = 0@ the result is @'Just' 0@ if
-- the origin is in the box and 'Nothing' otherwise.
rayBox :: Point2 Double -> Vector2 Double -> Box -> Maybe Double
rayBox (Point2 ox oy) (Vector2 dx dy) (Box x0 y0 x1 y1) =
  slab ox dx x0 x1 0 (1 / 0) $ \lo hi ->
  slab oy dy y0 y1 lo hi $ \lo' _ ->
  Just lo'
{-# INLINE rayBox #-}

-- | @rayCircle o dir c r@ casts the ray @o + t*dir@ (@t >= 0@) at the disc of
-- centre @c@ and radius @r@ (only @r*r@ is used).
--
-- Returns the smallest @t >= 0@ at which the ray point lies on the circle;
-- @'Just' 0@ when the origin is inside or on the circle; 'Nothing' when the
-- ray misses (or points away from the circle). A tangent ray counts as a hit.
-- As for 'rayBox', @t@ is in units of @dir@ (a distance for a unit @dir@),
-- and @dir = 0@ gives @'Just' 0@ or 'Nothing'. The root is computed in a
-- cancellation-free form, so it is accurate even for distant circles.
rayCircle :: Point2 Double -> Vector2 Double -> Point2 Double -> Double
          -> Maybe Double
rayCircle (Point2 ox oy) (Vector2 dx dy) (Point2 cx cy) r
  | c <= 0    = Just 0
  | b >= 0    = Nothing
  | disc < 0  = Nothing
  | otherwise = let !t = c / (sqrt disc - b) in Just t
  where
    !mx   = ox - cx
    !my   = oy - cy
    !a    = dx * dx + dy * dy
    !b    = mx * dx + my * dy
    !c    = mx * mx + my * my - r * r
    !disc = b * b - a * c
{-# INLINE rayCircle #-}
