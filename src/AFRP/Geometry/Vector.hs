{-# LANGUAGE FlexibleInstances      #-}
{-# LANGUAGE MultiParamTypeClasses  #-}
-- |
-- Module      : AFRP.Geometry.Vector
-- Description : 2-D and 3-D Euclidean vectors.
--
-- 'Vector2' and 'Vector3' with their 'VectorSpace' instances, cartesian,
-- polar and spherical views, and rotations. Usually imported through
-- "AFRP.Geometry", whose documentation explains the overall design.
--
-- Conventions: all angles are in radians; 2-D angles are measured
-- counter-clockwise from the positive x axis; 3-D spherical coordinates are
-- @(rho, theta, phi)@ = (length, azimuth, elevation), see
-- 'vector3Spherical'.
module AFRP.Geometry.Vector
  ( -- * 2-D vectors
    Vector2 (..)
  , vector2
  , vector2X
  , vector2Y
  , vector2XY
  , vector2Polar
  , vector2Rho
  , vector2Theta
  , vector2RhoTheta
  , vector2Rotate
    -- * 3-D vectors
  , Vector3 (..)
  , vector3
  , vector3X
  , vector3Y
  , vector3Z
  , vector3XYZ
  , vector3Spherical
  , vector3Rho
  , vector3Theta
  , vector3Phi
  , vector3RhoThetaPhi
  , vector3Rotate
  ) where

import Control.DeepSeq (NFData (..))

import AFRP.VectorSpace

------------------------------------------------------------------------------
-- 2-D vectors

-- | A two-dimensional vector with (strict) x and y components.
data Vector2 a = Vector2 !a !a
  deriving (Eq, Show)

instance NFData a => NFData (Vector2 a) where
  rnf (Vector2 x y) = rnf x `seq` rnf y

-- | Component-wise operations; 'dot' is the Euclidean inner product.
instance (Eq a, Floating a) => VectorSpace (Vector2 a) a where
  {-# SPECIALISE instance VectorSpace (Vector2 Double) Double #-}
  zeroVector                          = Vector2 0 0
  a *^ Vector2 x y                    = Vector2 (a * x) (a * y)
  Vector2 x y ^/ a                    = Vector2 (x / a) (y / a)
  negateVector (Vector2 x y)          = Vector2 (negate x) (negate y)
  Vector2 x1 y1 ^+^ Vector2 x2 y2     = Vector2 (x1 + x2) (y1 + y2)
  Vector2 x1 y1 ^-^ Vector2 x2 y2     = Vector2 (x1 - x2) (y1 - y2)
  dot (Vector2 x1 y1) (Vector2 x2 y2) = x1 * x2 + y1 * y2
  {-# INLINE zeroVector #-}
  {-# INLINE (*^) #-}
  {-# INLINE (^/) #-}
  {-# INLINE negateVector #-}
  {-# INLINE (^+^) #-}
  {-# INLINE (^-^) #-}
  {-# INLINE dot #-}

-- | Build a vector from its cartesian components (same as 'Vector2').
vector2 :: a -> a -> Vector2 a
vector2 = Vector2
{-# INLINE vector2 #-}

-- | The x component.
vector2X :: Vector2 a -> a
vector2X (Vector2 x _) = x
{-# INLINE vector2X #-}

-- | The y component.
vector2Y :: Vector2 a -> a
vector2Y (Vector2 _ y) = y
{-# INLINE vector2Y #-}

-- | Both cartesian components.
--
-- >>> vector2XY (vector2 1 2)
-- (1,2)
vector2XY :: Vector2 a -> (a, a)
vector2XY (Vector2 x y) = (x, y)
{-# INLINE vector2XY #-}

-- | @vector2Polar rho theta@ is the vector of length @rho@ whose direction
-- is at angle @theta@ (radians, counter-clockwise from the positive x axis):
-- @Vector2 (rho * cos theta) (rho * sin theta)@.
--
-- >>> vector2Polar 2 0 :: Vector2 Double
-- Vector2 2.0 0.0
vector2Polar :: Floating a => a -> a -> Vector2 a
vector2Polar rho theta = Vector2 (rho * cos theta) (rho * sin theta)
{-# INLINE vector2Polar #-}

-- | The length (Euclidean norm) of a vector; same as 'norm'.
--
-- >>> vector2Rho (Vector2 3 4 :: Vector2 Double)
-- 5.0
vector2Rho :: Floating a => Vector2 a -> a
vector2Rho (Vector2 x y) = sqrt (x * x + y * y)
{-# INLINE vector2Rho #-}

-- | The direction of a vector: the angle in radians, counter-clockwise from
-- the positive x axis, in the interval @(-pi, pi]@ (computed with 'atan2';
-- a result of exactly @-pi@, e.g. from a y component of @-0.0@, is reported
-- as @pi@). The angle of the zero vector is 0.
--
-- >>> vector2Theta (Vector2 0 1 :: Vector2 Double)
-- 1.5707963267948966
-- >>> vector2Theta (Vector2 (-1) 0 :: Vector2 Double)
-- 3.141592653589793
vector2Theta :: RealFloat a => Vector2 a -> a
vector2Theta (Vector2 x y) = angle y x
{-# INLINE vector2Theta #-}

-- | Polar coordinates @(rho, theta)@: 'vector2Rho' and 'vector2Theta'.
-- Inverse of 'vector2Polar' for @rho > 0@ and @-pi < theta <= pi@.
--
-- >>> vector2RhoTheta (Vector2 (-1) 0 :: Vector2 Double)
-- (1.0,3.141592653589793)
vector2RhoTheta :: RealFloat a => Vector2 a -> (a, a)
vector2RhoTheta v = (vector2Rho v, vector2Theta v)
{-# INLINE vector2RhoTheta #-}

-- | @vector2Rotate alpha v@ rotates @v@ counter-clockwise by the angle
-- @alpha@ (radians) about the origin. Lengths are preserved and
-- @vector2Theta@ increases by @alpha@ (modulo @2 * pi@).
--
-- >>> vector2Rotate pi (Vector2 1 0 :: Vector2 Double)
-- Vector2 (-1.0) 1.2246467991473532e-16
vector2Rotate :: Floating a => a -> Vector2 a -> Vector2 a
vector2Rotate alpha (Vector2 x y) = Vector2 (x * c - y * s) (x * s + y * c)
  where
    c = cos alpha
    s = sin alpha
{-# INLINE vector2Rotate #-}

-- | @atan2@ mapped into @(-pi, pi]@.
angle :: RealFloat a => a -> a -> a
angle y x
  | x == 0 && y == 0 = 0   -- (atan2 gives pi for a zero whose x is -0.0)
  -- (the Report's atan2 gives NaN when both are infinite: the diagonal)
  | isInfinite x && isInfinite y = angle (signum y) (signum x)
  | t == negate pi   = pi
  | otherwise        = t
  where
    t = atan2 y x
{-# INLINE angle #-}

------------------------------------------------------------------------------
-- 3-D vectors

-- | A three-dimensional vector with (strict) x, y and z components.
data Vector3 a = Vector3 !a !a !a
  deriving (Eq, Show)

instance NFData a => NFData (Vector3 a) where
  rnf (Vector3 x y z) = rnf x `seq` rnf y `seq` rnf z

-- | Component-wise operations; 'dot' is the Euclidean inner product.
instance (Eq a, Floating a) => VectorSpace (Vector3 a) a where
  {-# SPECIALISE instance VectorSpace (Vector3 Double) Double #-}
  zeroVector                                = Vector3 0 0 0
  a *^ Vector3 x y z                        = Vector3 (a * x) (a * y) (a * z)
  Vector3 x y z ^/ a                        = Vector3 (x / a) (y / a) (z / a)
  negateVector (Vector3 x y z)              =
    Vector3 (negate x) (negate y) (negate z)
  Vector3 x1 y1 z1 ^+^ Vector3 x2 y2 z2     =
    Vector3 (x1 + x2) (y1 + y2) (z1 + z2)
  Vector3 x1 y1 z1 ^-^ Vector3 x2 y2 z2     =
    Vector3 (x1 - x2) (y1 - y2) (z1 - z2)
  dot (Vector3 x1 y1 z1) (Vector3 x2 y2 z2) = x1 * x2 + y1 * y2 + z1 * z2
  {-# INLINE zeroVector #-}
  {-# INLINE (*^) #-}
  {-# INLINE (^/) #-}
  {-# INLINE negateVector #-}
  {-# INLINE (^+^) #-}
  {-# INLINE (^-^) #-}
  {-# INLINE dot #-}

-- | Build a vector from its cartesian components (same as 'Vector3').
vector3 :: a -> a -> a -> Vector3 a
vector3 = Vector3
{-# INLINE vector3 #-}

-- | The x component.
vector3X :: Vector3 a -> a
vector3X (Vector3 x _ _) = x
{-# INLINE vector3X #-}

-- | The y component.
vector3Y :: Vector3 a -> a
vector3Y (Vector3 _ y _) = y
{-# INLINE vector3Y #-}

-- | The z component.
vector3Z :: Vector3 a -> a
vector3Z (Vector3 _ _ z) = z
{-# INLINE vector3Z #-}

-- | All three cartesian components.
--
-- >>> vector3XYZ (vector3 1 2 3)
-- (1,2,3)
vector3XYZ :: Vector3 a -> (a, a, a)
vector3XYZ (Vector3 x y z) = (x, y, z)
{-# INLINE vector3XYZ #-}

-- | @vector3Spherical rho theta phi@ builds a vector from spherical
-- coordinates in the /azimuth-elevation/ convention:
--
-- * @rho@: the length of the vector;
-- * @theta@: the azimuth, the angle of the projection onto the xy plane,
--   counter-clockwise from the positive x axis (as in 'vector2Theta');
-- * @phi@: the elevation, the angle between the vector and the xy plane,
--   positive towards the positive z axis (so @pi/2@ points along +z).
--
-- That is @Vector3 (rho * cos phi * cos theta) (rho * cos phi * sin theta)
-- (rho * sin phi)@. With @phi = 0@ this is 'vector2Polar' in the xy plane.
--
-- >>> vector3Spherical 2 0 0 :: Vector3 Double
-- Vector3 2.0 0.0 0.0
vector3Spherical :: Floating a => a -> a -> a -> Vector3 a
vector3Spherical rho theta phi =
  Vector3 (rcp * cos theta) (rcp * sin theta) (rho * sin phi)
  where
    rcp = rho * cos phi
{-# INLINE vector3Spherical #-}

-- | The length (Euclidean norm) of a vector; same as 'norm'.
--
-- >>> vector3Rho (Vector3 2 3 6 :: Vector3 Double)
-- 7.0
vector3Rho :: Floating a => Vector3 a -> a
vector3Rho (Vector3 x y z) = sqrt (x * x + y * y + z * z)
{-# INLINE vector3Rho #-}

-- | The azimuth: the angle of the projection onto the xy plane, in radians
-- counter-clockwise from the positive x axis, in @(-pi, pi]@ (the same as
-- 'vector2Theta' of the x and y components; 0 on the z axis).
--
-- >>> vector3Theta (Vector3 0 1 5 :: Vector3 Double)
-- 1.5707963267948966
vector3Theta :: RealFloat a => Vector3 a -> a
vector3Theta (Vector3 x y _) = angle y x
{-# INLINE vector3Theta #-}

-- | The elevation: the angle between the vector and the xy plane, in radians
-- in @[-pi/2, pi/2]@, positive when the z component is positive (0 for the
-- zero vector).
--
-- >>> vector3Phi (Vector3 0 0 1 :: Vector3 Double)
-- 1.5707963267948966
-- >>> vector3Phi (Vector3 1 0 (-1) :: Vector3 Double)
-- -0.7853981633974483
vector3Phi :: RealFloat a => Vector3 a -> a
vector3Phi (Vector3 x y z) = atan2 z (sqrt (x * x + y * y))
{-# INLINE vector3Phi #-}

-- | Spherical coordinates @(rho, theta, phi)@ ('vector3Rho',
-- 'vector3Theta', 'vector3Phi'). Inverse of 'vector3Spherical' for
-- @rho > 0@, @-pi < theta <= pi@ and @-pi/2 < phi < pi/2@.
vector3RhoThetaPhi :: RealFloat a => Vector3 a -> (a, a, a)
vector3RhoThetaPhi v = (vector3Rho v, vector3Theta v, vector3Phi v)
{-# INLINE vector3RhoThetaPhi #-}

-- | @vector3Rotate theta phi v@ rotates @v@ (a proper rotation: linear,
-- length- and angle-preserving) in two steps:
--
-- 1. by the elevation @phi@ about the y axis, tilting the positive x axis
--    towards the positive z axis;
-- 2. then by the azimuth @theta@ about the z axis, counter-clockwise when
--    seen from the positive z axis (as 'vector2Rotate' in the xy plane).
--
-- It is the rotation that maps the x axis to the direction
-- @(theta, phi)@: @vector3Rotate theta phi (Vector3 rho 0 0) ==
-- vector3Spherical rho theta phi@. More generally a vector with azimuth 0
-- and elevation @e@ is mapped to azimuth @theta@ and elevation @e + phi@
-- (when that stays within @[-pi/2, pi/2]@), and @vector3Rotate theta 0@
-- acts as @vector2Rotate theta@ on the x and y components, leaving z
-- unchanged. The inverse of @vector3Rotate theta phi@ is
-- @vector3Rotate 0 (-phi) . vector3Rotate (-theta) 0@.
vector3Rotate :: Floating a => a -> a -> Vector3 a -> Vector3 a
vector3Rotate theta phi (Vector3 x y z) =
  Vector3 (x' * ct - y * st) (x' * st + y * ct) z'
  where
    ct = cos theta
    st = sin theta
    cp = cos phi
    sp = sin phi
    x' = x * cp - z * sp
    z' = x * sp + z * cp
{-# INLINE vector3Rotate #-}

