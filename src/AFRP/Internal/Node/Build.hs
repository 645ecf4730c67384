{-# LANGUAGE GADTs         #-}
{-# LANGUAGE UnboxedTuples #-}
-- |
-- Module      : AFRP.Internal.Node.Build
-- Description : The node type, and the smart constructors that build
--               nodes simplified.
--
-- Internal, part of "AFRP.Internal.Node", which re-exports everything
-- here but 'compNI' and explains the design. The smart constructors
-- ('compN', 'firstN', 'parN', 'fanN', ...) build nodes with the arrow
-- laws that simplify them applied (each written beside its case): when a
-- network is built, and every time the stepper ("AFRP.Internal.Node")
-- rebuilds a part of it that has changed. 'compNI' is 'compN' to be
-- inlined, for the stepper.
module AFRP.Internal.Node.Build
  ( -- * Time
    Time
  , DTime
    -- * Nodes
  , Node (..)
    -- * Smart constructors
  , constN
  , arrN
  , idN
  , compN
  , compNI
  , firstN
  , secondN
  , parN
  , fanN
  ) where

import           AFRP.Internal.Node.FunD

------------------------------------------------------------------------------
-- Time

-- | Time in seconds. Local time starts at 0 when a signal function starts
-- (at the beginning of a run, or when it is switched in).
type Time = Double

-- | A time step in seconds: the time between two consecutive samples.
-- A time step is a number, 0 or more, infinity included (the runners of
-- "AFRP.Run" refuse a NaN or negative one); the first sample of any
-- signal function has no time step at all.
type DTime = Double

------------------------------------------------------------------------------
-- Representation

-- | A node of a signal-function network.
data Node a b where
  -- | A stateless node.
  NPure   :: !(FunD a b) -> Node a b
  -- | Serial composition.
  NComp   :: !(Node a c) -> !(Node c b) -> Node a b
  -- | Parallel composition on pairs. @first f@ and @second f@ are
  -- @NPar f id@ and @NPar id f@ (see 'firstN').
  NPar    :: !(Node a b) -> !(Node c d) -> Node (a, c) (b, d)
  -- | Fan-out: both nodes see the same input.
  NFan    :: !(Node a b) -> !(Node a c) -> Node a (b, c)
  -- | An opaque stateful node: given the time step and the input sample,
  -- its successor and its output.
  NStep   :: !(DTime -> a -> (# Node a b, b #)) -> Node a b
  -- | 'AFRP.Delay.iPre' holding the previous input sample (lazy: the
  -- delay never evaluates its input): outputs it and stores the current
  -- one. Visible to @loopN@ ("AFRP.Internal.Loop"), which closes a loop through it without a
  -- knot.
  NPre    :: a -> Node a a
  -- | 'AFRP.Integration.integral' on 'Double' after its first sample: the
  -- running sum and the previous input sample (lazy: the integral never
  -- evaluates its current input). A specialised node, with no closure.
  NIntD   :: {-# UNPACK #-} !Double -> Double -> Node Double Double

------------------------------------------------------------------------------
-- Smart constructors. Each states the identity it relies on.

-- | The constant node.
constN :: b -> Node a b
constN b = NPure (FDC b)
{-# INLINE constN #-}

-- | A lifted function.
arrN :: (a -> b) -> Node a b
arrN f = NPure (FDG f)
{-# INLINE arrN #-}

-- | The identity node.
idN :: Node a a
idN = NPure FDI

-- | Serial composition, simplified.
compN :: Node a c -> Node c b -> Node a b
-- The identities it relies on, in the order they are tried:
--
-- > arr f >>> arr g                 = arr (g . f)
-- > n >>> id                        = n
-- > n >>> constant c                = constant c    (signal functions have no effects)
-- > (n >>> arr f) >>> arr g         = n >>> arr (g . f)
-- > (arr f &&& constant c) >>> arr g = arr (\a -> g (f a, c))
-- >                                  (the fan was kept only for the benefit of
-- >                                  a switch, and no switch can see it here)
-- > id >>> n                        = n
-- > arr f >>> (arr g >>> n)         = arr (g . f) >>> n
--
-- written as a decision tree on the two nodes, so that the common case (two
-- stateful nodes) costs two tests.
compN f g = compNI f g

-- | 'compN', inlined: 'AFRP.Internal.Node.stepN' rebuilds a composition
-- at every step, and with the tree inlined there the tests on the node it
-- already knows (the pure one) vanish and the rest cost no call. The same
-- function as 'compN', so the same identities.
compNI :: Node a c -> Node c b -> Node a b
compNI f g = case g of
  NPure gd -> case f of
    NPure fd -> NPure (fdComp fd gd)
    _        -> case gd of
      FDI   -> f
      FDC c -> NPure (FDC c)
      FDG _ -> case f of
        NComp h (NPure fd)         -> NComp h (NPure (fdComp fd gd))
        NFan (NPure fa) (NPure fc) -> NPure (fdComp (fanFD fa fc) gd)
        _                          -> NComp f g
  _        -> case f of
    NPure FDI -> g
    NPure fd  -> case g of
      NComp (NPure gd) h -> NComp (NPure (fdComp fd gd)) h
      _                  -> NComp f g
    _         -> NComp f g
{-# INLINE compNI #-}

-- | @first@, simplified.
firstN :: Node a b -> Node (a, c) (b, c)
-- first id = id
firstN (NPure FDI)     = NPure FDI
-- first (arr f) = arr (\(a, c) -> (f a, c))
firstN (NPure (FDC b)) = NPure (FDG (\ ~(_, c) -> (b, c)))
firstN (NPure (FDG f)) = NPure (FDG (\ ~(a, c) -> (f a, c)))
firstN f               = NPar f idN
{-# INLINE firstN #-}

-- | @second@, simplified.
secondN :: Node a b -> Node (c, a) (c, b)
secondN (NPure FDI)     = NPure FDI
secondN (NPure (FDC b)) = NPure (FDG (\ ~(c, _) -> (c, b)))
secondN (NPure (FDG f)) = NPure (FDG (\ ~(c, a) -> (c, f a)))
secondN f               = NPar idN f
{-# INLINE secondN #-}

-- | @(***)@, simplified.
parN :: Node a b -> Node c d -> Node (a, c) (b, d)
-- f *** id = first f ; id *** g = second g
parN f (NPure FDI)         = firstN f
parN (NPure FDI) g         = secondN g
-- arr f *** arr g = arr (f `cross` g)
parN (NPure f) (NPure g)   =
  let f' = fdFun f
      g' = fdFun g
  in NPure (FDG (\ ~(a, c) -> (f' a, g' c)))
parN f g                   = NPar f g

-- | @(&&&)@, simplified.
fanN :: Node a b -> Node a c -> Node a (b, c)
-- constant b &&& constant c = constant (b, c)
fanN (NPure (FDC b)) (NPure (FDC c)) = NPure (FDC (b, c))
-- sf &&& constant c is kept as a fan, so that a switch can see that its
-- event part is the constant NoEvent (sf &&& never) and remove itself.
fanN f g@(NPure (FDC _))             = NFan f g
-- arr f &&& arr g = arr (\a -> (f a, g a))
fanN (NPure f) (NPure g)             = NPure (fanFD f g)
fanN f g                             = NFan f g
{-# INLINE fanN #-}
