-- |
-- Module      : AFrob.Angle
-- Description : Headings, bearings and relative angles: normalisation and conversion.
--
-- AFrob has three types of angle, all synonyms for 'Double' (see
-- "AFrob.Dimensions"):
--
-- * 'Heading': an absolute direction in radians, Cartesian convention
--   (0 = positive x axis = east, pi\/2 = north, counter-clockwise).
--   Normalised range [-pi, pi).
-- * 'Bearing': an absolute direction in compass degrees (0 = north = the
--   positive y axis, 90 = east, clockwise). Normalised range [0, 360).
-- * 'Angle': a /relative/ angle in radians, counter-clockwise positive,
--   e.g. the error @hd - ha@ between a desired and an actual heading, or the
--   direction of an object seen from the robot. Normalised range [-pi, pi).
--
-- The ranges are half-open: pi is normalised to -pi and 360 to 0.
--
-- = Guarantees of the normalising functions
--
-- * A value already in range is returned unchanged, bit for bit (so
--   normalising is idempotent, and cheap in the common case).
-- * The result is always in range, for every finite input, however large
--   or negative: a rounding that would land exactly on the excluded upper
--   bound gives the lower bound instead (the same direction).
-- * The reduction is /exact/: the result is the input minus a whole number
--   of periods, computed without error and then rounded once. The period of
--   the radian functions is @2 * pi@ as a 'Double', the value every other
--   computation uses; measured against the mathematical 2π a huge input is
--   off by at most about @|x| * 4e-17@ radians.
-- * NaN gives NaN, and so do the infinities (they have no direction).
module AFrob.Angle
  ( -- * The angle types
    Angle
  , Heading
  , Bearing
    -- * Normalisation
  , normalizeAngle
  , normalizeHeading
  , normalizeBearing
    -- * Conversions
  , bearingToHeading
  , headingToBearing
  , degToRad
  , radToDeg
  ) where

import AFrob.Dimensions (Angle, Bearing, Heading)

-- | Normalise a relative angle (radians) into [-pi, pi): the result
-- differs from the input by a whole number of turns (@2 * pi@).
--
-- > normalizeAngle pi          == -pi
-- > normalizeAngle (-pi)       == -pi
-- > normalizeAngle (3 * pi / 2) == -pi / 2
--
-- Values already in range are returned unchanged; NaN and the infinities
-- give NaN. See the module header for the precise guarantees.
normalizeAngle :: Angle -> Angle
normalizeAngle = reduceInto (-pi) (2 * pi)
{-# INLINE normalizeAngle #-}

-- | Normalise a heading (radians, 0 = east, counter-clockwise) into
-- [-pi, pi). The same function as 'normalizeAngle', at the type 'Heading'.
normalizeHeading :: Heading -> Heading
normalizeHeading = normalizeAngle
{-# INLINE normalizeHeading #-}

-- | Normalise a bearing (compass degrees) into [0, 360): the result
-- differs from the input by a whole number of turns (360 degrees).
--
-- > normalizeBearing 360    == 0
-- > normalizeBearing (-90)  == 270
-- > normalizeBearing (-1e-17) == 0    -- 360 - 1e-17 rounds to 360, i.e. 0
--
-- Values already in range are returned unchanged; NaN and the infinities
-- give NaN.
normalizeBearing :: Bearing -> Bearing
normalizeBearing = reduceInto 0 360
{-# INLINE normalizeBearing #-}

-- | The heading of a compass bearing, normalised into [-pi, pi): north
-- (0) is pi\/2, east (90) is 0, south (180) is -pi\/2, west (270) is -pi.
-- The bearing is first normalised (exactly, in degrees), so whole turns of
-- any size cost no precision. NaN gives NaN.
bearingToHeading :: Bearing -> Heading
bearingToHeading b = normalizeHeading (degToRad (90 - normalizeBearing b))

-- | The compass bearing of a heading, normalised into [0, 360): pi\/2 is
-- north (0), 0 is east (90), -pi\/2 is south (180), -pi is west (270). The
-- inverse of 'bearingToHeading' up to normalisation and rounding. NaN
-- gives NaN.
headingToBearing :: Heading -> Bearing
headingToBearing h = normalizeBearing (90 - radToDeg (normalizeHeading h))

-- | Degrees to radians, without normalising: @degToRad d = d \/ 180 * pi@.
-- Dividing first keeps the common angles exact (@degToRad 90 == pi \/ 2@,
-- @degToRad 180 == pi@) and cannot overflow (a finite argument gives a
-- finite result).
degToRad :: Double -> Double
degToRad d = d / 180 * pi
{-# INLINE degToRad #-}

-- | Radians to degrees, without normalising: @radToDeg r = r \/ pi * 180@.
-- Exact for the common angles (@radToDeg (pi \/ 2) == 90@). Finite for
-- any angle up to about 3e306 radians in magnitude; beyond, the product
-- overflows to an infinity (normalise first: 'normalizeAngle').
radToDeg :: Double -> Double
radToDeg r = r / pi * 180
{-# INLINE radToDeg #-}

-- | @reduceInto lo p x@: the value congruent to @x@ modulo @p@ in
-- [lo, lo + p). Requires @p > 0@ and @lo + p@ exact (true for both uses).
--
-- Three paths:
--
-- 1. In range: @x@ itself.
-- 2. One period out, with @p\/2 <= |x| <= 2p@: a single addition or
--    subtraction of @p@, which is exact by Sterbenz's lemma (the operands
--    are within a factor of two of each other).
-- 3. Otherwise: the remainder computed exactly in 'Rational' and rounded
--    once; a rounding up onto the excluded bound @lo + p@ wraps to @lo@.
reduceInto :: Double -> Double -> Double -> Double
reduceInto lo p x
  | x >= lo && x < hi                        = x
  | isNaN x || isInfinite x                  = x - x   -- NaN
  | x >= hi && x >= halfP && x <= twoP
  , let y = x - p, y < hi                    = y
  | x < lo && negate x >= halfP && negate x <= twoP
  , let y = x + p, y >= lo                   = y
  | otherwise                                = exactReduce
  where
    hi    = lo + p
    halfP = p / 2
    twoP  = 2 * p
    exactReduce =
      let xr = toRational x
          pr = toRational p
          lr = toRational lo
          k  = floor ((xr - lr) / pr) :: Integer
          y  = fromRational (xr - fromInteger k * pr) :: Double
      in if y >= hi then lo else y
{-# INLINE reduceInto #-}
