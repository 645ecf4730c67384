{-# LANGUAGE GADTs #-}
-- |
-- Module      : AFRP.Internal.Node.FunD
-- Description : The stateless functions a node can be: the identity, a
--               constant, any other function; and their algebra.
--
-- Internal, part of "AFRP.Internal.Node", which re-exports 'FunD' and
-- 'fdFun'. A pure node ('AFRP.Internal.Node.NPure') holds a 'FunD' rather
-- than a bare function so that the smart constructors can see the two
-- cases that simplify a network: an identity vanishes, a constant absorbs
-- what feeds it. 'fdComp' and 'fanFD' compose descriptions with those
-- identities applied, for the smart constructors of
-- "AFRP.Internal.Node.Build"; both are inlined there (as they were when
-- the two lived in one module), so that a case on a description the
-- caller already knows vanishes.
module AFRP.Internal.Node.FunD
  ( FunD (..)
  , fdFun
  , fdComp
  , fanFD
  ) where

-- | Stateless functions, with the two special cases that enable
-- simplification recognised.
data FunD a b where
  -- | The identity.
  FDI :: FunD a a
  -- | A constant function; the value is lazy.
  FDC :: b -> FunD a b
  -- | Any other function.
  FDG :: (a -> b) -> FunD a b

-- | Serial composition of descriptions, simplified.
fdComp :: FunD a b -> FunD b c -> FunD a c
-- Identities: id >>> f = f, f >>> id = f.
fdComp FDI     g       = g
fdComp f       FDI     = f
-- Constants absorb what feeds them: f >>> const c = const c.
fdComp _       (FDC c) = FDC c
-- const b >>> g = const (g b), lazily.
fdComp (FDC b) (FDG g) = FDC (g b)
fdComp (FDG f) (FDG g) = FDG (\a -> g (f a))
{-# INLINE fdComp #-}

-- | The function a 'FunD' stands for.
fdFun :: FunD a b -> a -> b
fdFun FDI     = \a -> a
fdFun (FDC b) = \_ -> b
fdFun (FDG f) = f

-- | Fan-out of descriptions: a pair of constants is a constant.
fanFD :: FunD a b -> FunD a c -> FunD a (b, c)
fanFD (FDC b) (FDC c) = FDC (b, c)
fanFD f g             =
  let f' = fdFun f
      g' = fdFun g
  in FDG (\a -> (f' a, g' a))
{-# INLINE fanFD #-}
