-- |
-- Module      : AFRP.Geometry
-- Description : 2-D and 3-D vectors and points.
--
-- Euclidean vectors ('Vector2', 'Vector3') and points ('Point2', 'Point3')
-- for describing positions, velocities, forces, ... in signal functions.
--
-- = Why points and vectors are different types
--
-- A /vector/ is a displacement: it has a direction and a length but no
-- location. Vectors form a vector space ('VectorSpace'): they can be added,
-- scaled and compared by length. A /point/ is a location. Points form an
-- /affine space/ ('AffineSpace'): adding two positions or doubling a
-- position has no meaning independent of the (arbitrary) choice of
-- 'origin', but the following do:
--
-- * point '.+^' vector = point   (move a point by a displacement),
-- * point '.-^' vector = point,
-- * point '.-.' point  = vector  (the displacement between two points),
-- * 'distance' between two points.
--
-- Keeping them apart lets the type checker reject meaningless expressions
-- such as the sum of two positions, while an integrated velocity (a vector)
-- can still be added to a start position with '.+^'.
--
-- = Conventions
--
-- * All angles are in radians.
-- * 2-D angles are measured counter-clockwise from the positive x axis
--   (towards the positive y axis), the usual mathematical orientation.
-- * 3-D vectors use the /azimuth-elevation/ spherical convention
--   @(rho, theta, phi)@ (see 'vector3Spherical'): @rho@ is the length,
--   @theta@ the azimuth (the 2-D angle of the projection onto the xy plane)
--   and @phi@ the elevation above the xy plane. So for a vector in the xy
--   plane @theta@ agrees with 'vector2Theta' and @phi@ is 0.
--
-- = Modules
--
-- This module re-exports "AFRP.VectorSpace", "AFRP.Geometry.Vector" and
-- "AFRP.Geometry.Point".
module AFRP.Geometry
  ( -- * Vector spaces
    module AFRP.VectorSpace
    -- * Vectors
  , module AFRP.Geometry.Vector
    -- * Points and affine spaces
  , module AFRP.Geometry.Point
  ) where

import AFRP.Geometry.Point
import AFRP.Geometry.Vector
import AFRP.VectorSpace
