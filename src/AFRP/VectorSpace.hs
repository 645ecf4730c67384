{-# LANGUAGE FlexibleInstances      #-}
{-# LANGUAGE FunctionalDependencies #-}
{-# LANGUAGE MultiParamTypeClasses  #-}
{-# LANGUAGE TypeFamilies           #-}
-- |
-- Module      : AFRP.VectorSpace
-- Description : Real vector spaces with an inner product.
--
-- A small class of finite-dimensional real vector spaces equipped with an
-- inner product, as needed by the signal functions that integrate or
-- differentiate signals (@integral@, @derivative@, ...).
--
-- A vector type @v@ uniquely determines its scalar type @a@ (functional
-- dependency @v -> a@), so @2 *^ (1, 2 :: Double)@ needs no further
-- annotation.
--
-- Fixities, Yampa's (so that ordinary linear-algebra expressions need no
-- parentheses, e.g. @a *^ u ^+^ b *^ v@ means @(a *^ u) ^+^ (b *^ v)@ and
-- @a *^ u \`dot\` v@ means @(a *^ u) \`dot\` v@):
--
-- > infixr 9 *^
-- > infixl 9 ^/
-- > infix  7 `dot`
-- > infixl 6 ^+^, ^-^
--
-- So @*^@ and @^/@ bind tighter than the scalars' @*@ and @/@:
-- @2 * dt *^ v@ is @2 * (dt *^ v)@; write @(2 * dt) *^ v@. They have the
-- same precedence but different associativity, so an expression mixing
-- them without parentheses is rejected by the compiler; write
-- @(a *^ v) ^/ b@.
module AFRP.VectorSpace
  ( VectorSpace (..)
  ) where

infixr 9 *^
infixl 9 ^/
infix  7 `dot`
infixl 6 ^+^, ^-^

-- | A real vector space @v@ over the scalar field @a@, with an inner product.
--
-- Minimal complete definition: 'zeroVector', '(*^)', '(^+^)' and 'dot'.
--
-- Instances are expected to satisfy the usual laws (up to floating-point
-- rounding):
--
-- * @(u ^+^ v) ^+^ w == u ^+^ (v ^+^ w)@ and @u ^+^ v == v ^+^ u@
-- * @zeroVector ^+^ v == v@ and @v ^+^ negateVector v == zeroVector@
-- * @1 *^ v == v@, @a *^ (b *^ v) == (a * b) *^ v@
-- * @a *^ (u ^+^ v) == a *^ u ^+^ a *^ v@ and @(a + b) *^ v == a *^ v ^+^ b *^ v@
-- * @dot u v == dot v u@, @dot@ is bilinear and @dot v v >= 0@
-- * @v ^/ a == (1 / a) *^ v@, @u ^-^ v == u ^+^ negateVector v@
-- * @norm v == sqrt (dot v v)@ and @norm (normalize v) == 1@ for @v /=
--   zeroVector@, where @dot v v@ neither overflows nor underflows to 0
--   (at 'Double' and 'Float', where 'norm' is 'abs', always; for the
--   vectors of "AFRP.Geometry", components from about 1e-154 to 1e154 in
--   magnitude)
class (Eq a, Floating a) => VectorSpace v a | v -> a where
  -- | The additive identity.
  --
  -- >>> zeroVector :: (Double, Double)
  -- (0.0,0.0)
  zeroVector :: v

  -- | Scalar multiplication.
  --
  -- >>> 2 *^ (1, -3 :: Double)
  -- (2.0,-6.0)
  (*^) :: a -> v -> v

  -- | Division by a scalar. Defaults to @v ^/ a = (1 / a) *^ v@.
  -- Dividing by zero follows the floating-point rules of the scalar type
  -- (it yields infinities or NaNs; it does not throw).
  --
  -- >>> (3, 6 :: Double) ^/ 3
  -- (1.0,2.0)
  (^/) :: v -> a -> v
  v ^/ a = (1 / a) *^ v
  {-# INLINE (^/) #-}

  -- | Additive inverse. Defaults to @negateVector v = (-1) *^ v@.
  --
  -- >>> negateVector (1, -2 :: Double)
  -- (-1.0,2.0)
  negateVector :: v -> v
  negateVector v = (-1) *^ v
  {-# INLINE negateVector #-}

  -- | Vector addition.
  --
  -- >>> (1, 2) ^+^ (10, 20 :: Double)
  -- (11.0,22.0)
  (^+^) :: v -> v -> v

  -- | Vector subtraction. Defaults to @u ^-^ v = u ^+^ negateVector v@.
  --
  -- >>> (10, 20) ^-^ (1, 2 :: Double)
  -- (9.0,18.0)
  (^-^) :: v -> v -> v
  u ^-^ v = u ^+^ negateVector v
  {-# INLINE (^-^) #-}

  -- | Inner (dot) product.
  --
  -- >>> (1, 2) `dot` (3, 4 :: Double)
  -- 11.0
  dot :: v -> v -> a

  -- | Euclidean norm (length). Defaults to @norm v = sqrt (dot v v)@.
  --
  -- >>> norm (3, 4 :: Double)
  -- 5.0
  norm :: v -> a
  norm v = sqrt (dot v v)
  {-# INLINE norm #-}

  -- | The unit vector pointing in the same direction: @v ^/ norm v@.
  --
  -- Calls 'error' (with a message mentioning @normalize@) when the norm of
  -- the argument is zero, since the zero vector has no direction. With the
  -- default 'norm', a vector so small that @dot v v@ underflows to 0
  -- (every component below about 1e-154, at 'Double') is such an error
  -- too, and one so large that it overflows (a component above about
  -- 1e154) normalises to the zero vector: scale it first.
  --
  -- >>> normalize (3, 4 :: Double)
  -- (0.6,0.8)
  normalize :: v -> v
  normalize v
    | n == 0    = error "AFRP.VectorSpace.normalize: zero vector (norm is 0)"
    | otherwise = v ^/ n
    where
      n = norm v
  {-# INLINE normalize #-}

------------------------------------------------------------------------------
-- Scalars as one-dimensional vector spaces

-- | 'Double' as a one-dimensional vector space over itself; 'dot' is
-- multiplication and 'norm' is 'abs'.
instance VectorSpace Double Double where
  zeroVector     = 0
  a *^ x         = a * x
  x ^/ a         = x / a
  negateVector x = negate x
  x ^+^ y        = x + y
  x ^-^ y        = x - y
  dot x y        = x * y
  norm x         = abs x
  {-# INLINE zeroVector #-}
  {-# INLINE (*^) #-}
  {-# INLINE (^/) #-}
  {-# INLINE negateVector #-}
  {-# INLINE (^+^) #-}
  {-# INLINE (^-^) #-}
  {-# INLINE dot #-}
  {-# INLINE norm #-}

-- | 'Float' as a one-dimensional vector space over itself; 'dot' is
-- multiplication and 'norm' is 'abs'.
instance VectorSpace Float Float where
  zeroVector     = 0
  a *^ x         = a * x
  x ^/ a         = x / a
  negateVector x = negate x
  x ^+^ y        = x + y
  x ^-^ y        = x - y
  dot x y        = x * y
  norm x         = abs x
  {-# INLINE zeroVector #-}
  {-# INLINE (*^) #-}
  {-# INLINE (^/) #-}
  {-# INLINE negateVector #-}
  {-# INLINE (^+^) #-}
  {-# INLINE (^-^) #-}
  {-# INLINE dot #-}
  {-# INLINE norm #-}

------------------------------------------------------------------------------
-- Tuples: component-wise operations, Euclidean inner product

-- | Pairs @(a, a)@ as two-dimensional vectors with component-wise
-- operations and the Euclidean inner product.
--
-- The instance head is written @(a, b)@ with the constraint @a ~ b@ so that
-- it is selected as soon as the type is known to be a pair; the components
-- are then unified. This way @(1, 2) ^+^ (3, 4 :: Double)@ type-checks and
-- a pair of unannotated literals defaults to @(Double, Double)@.
instance (a ~ b, Eq a, Floating a) => VectorSpace (a, b) a where
  {-# SPECIALISE instance VectorSpace (Double, Double) Double #-}
  {-# SPECIALISE instance VectorSpace (Float, Float) Float #-}
  zeroVector                = (0, 0)
  a *^ (x, y)               = (a * x, a * y)
  (x, y) ^/ a               = (x / a, y / a)
  negateVector (x, y)       = (negate x, negate y)
  (x1, y1) ^+^ (x2, y2)     = (x1 + x2, y1 + y2)
  (x1, y1) ^-^ (x2, y2)     = (x1 - x2, y1 - y2)
  dot (x1, y1) (x2, y2)     = x1 * x2 + y1 * y2
  {-# INLINE zeroVector #-}
  {-# INLINE (*^) #-}
  {-# INLINE (^/) #-}
  {-# INLINE negateVector #-}
  {-# INLINE (^+^) #-}
  {-# INLINE (^-^) #-}
  {-# INLINE dot #-}

-- | Triples @(a, a, a)@ as three-dimensional vectors with component-wise
-- operations and the Euclidean inner product. As for pairs, the head is
-- @(a, b, c)@ with @a ~ b@ and @a ~ c@, for better type inference.
instance (a ~ b, a ~ c, Eq a, Floating a) => VectorSpace (a, b, c) a where
  {-# SPECIALISE instance VectorSpace (Double, Double, Double) Double #-}
  {-# SPECIALISE instance VectorSpace (Float, Float, Float) Float #-}
  zeroVector                      = (0, 0, 0)
  a *^ (x, y, z)                  = (a * x, a * y, a * z)
  (x, y, z) ^/ a                  = (x / a, y / a, z / a)
  negateVector (x, y, z)          = (negate x, negate y, negate z)
  (x1, y1, z1) ^+^ (x2, y2, z2)   = (x1 + x2, y1 + y2, z1 + z2)
  (x1, y1, z1) ^-^ (x2, y2, z2)   = (x1 - x2, y1 - y2, z1 - z2)
  dot (x1, y1, z1) (x2, y2, z2)   = x1 * x2 + y1 * y2 + z1 * z2
  {-# INLINE zeroVector #-}
  {-# INLINE (*^) #-}
  {-# INLINE (^/) #-}
  {-# INLINE negateVector #-}
  {-# INLINE (^+^) #-}
  {-# INLINE (^-^) #-}
  {-# INLINE dot #-}

-- | Quadruples @(a, a, a, a)@ as four-dimensional vectors, as in Yampa
-- (component-wise operations, the Euclidean inner product; the head as
-- for pairs).
instance (a ~ b, a ~ c, a ~ d, Eq a, Floating a) => VectorSpace (a, b, c, d) a where
  zeroVector                              = (0, 0, 0, 0)
  a *^ (x, y, z, u)                       = (a * x, a * y, a * z, a * u)
  (x, y, z, u) ^/ a                       = (x / a, y / a, z / a, u / a)
  negateVector (x, y, z, u)               = (negate x, negate y, negate z, negate u)
  (x1, y1, z1, u1) ^+^ (x2, y2, z2, u2)   = (x1 + x2, y1 + y2, z1 + z2, u1 + u2)
  (x1, y1, z1, u1) ^-^ (x2, y2, z2, u2)   = (x1 - x2, y1 - y2, z1 - z2, u1 - u2)
  dot (x1, y1, z1, u1) (x2, y2, z2, u2)   = x1 * x2 + y1 * y2 + z1 * z2 + u1 * u2
  {-# INLINE zeroVector #-}
  {-# INLINE (*^) #-}
  {-# INLINE (^/) #-}
  {-# INLINE negateVector #-}
  {-# INLINE (^+^) #-}
  {-# INLINE (^-^) #-}
  {-# INLINE dot #-}

-- | Quintuples @(a, a, a, a, a)@ as five-dimensional vectors, as in Yampa
-- (component-wise operations, the Euclidean inner product; the head as
-- for pairs).
instance (a ~ b, a ~ c, a ~ d, a ~ e, Eq a, Floating a) => VectorSpace (a, b, c, d, e) a where
  zeroVector                                      = (0, 0, 0, 0, 0)
  a *^ (x, y, z, u, v)                            = (a * x, a * y, a * z, a * u, a * v)
  (x, y, z, u, v) ^/ a                            = (x / a, y / a, z / a, u / a, v / a)
  negateVector (x, y, z, u, v)                    = (negate x, negate y, negate z, negate u, negate v)
  (x1, y1, z1, u1, v1) ^+^ (x2, y2, z2, u2, v2)   = (x1 + x2, y1 + y2, z1 + z2, u1 + u2, v1 + v2)
  (x1, y1, z1, u1, v1) ^-^ (x2, y2, z2, u2, v2)   = (x1 - x2, y1 - y2, z1 - z2, u1 - u2, v1 - v2)
  dot (x1, y1, z1, u1, v1) (x2, y2, z2, u2, v2)   = x1 * x2 + y1 * y2 + z1 * z2 + u1 * u2 + v1 * v2
  {-# INLINE zeroVector #-}
  {-# INLINE (*^) #-}
  {-# INLINE (^/) #-}
  {-# INLINE negateVector #-}
  {-# INLINE (^+^) #-}
  {-# INLINE (^-^) #-}
  {-# INLINE dot #-}
