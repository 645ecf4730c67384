{-# LANGUAGE GADTs        #-}
{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFRP.Internal.SF
-- Description : The representation of signal functions and the Arrow instances.
--
-- This module is hidden from users: 'SF' is abstract outside the library.
--
-- = Design
--
-- A signal function is a /network of nodes/ that is stepped one sample at a
-- time. A node is either one of a handful of structural forms that the
-- library understands ('NPure', 'NComp', 'NFirst', 'NSecond', 'NPar', 'NFan')
-- or an opaque stateful step ('NStep'). Because the structure is visible,
-- the smart constructors ('compN', 'fanN', ...) simplify the network both
-- when it is built and every time a part of it changes while it runs: pure
-- functions fuse across '>>>', identities vanish, constants absorb what
-- feeds them, and a stateful node that has become stateless (an 'after'
-- that has fired, a switch whose event can no longer occur) collapses into
-- a pure one, which in turn fuses with its neighbours.
--
-- There is one node type for the whole life of a signal function. The
-- difference between the very first sample (which has no time step) and
-- later ones is carried by the nodes themselves: /a node that has not yet
-- been stepped ignores the time step it is given/. A freshly built 'SF' is
-- always such an initial node, so starting a signal function (at time 0, or
-- at a switch) is just stepping it. The one exception is the node built by
-- 'freezeN', which replays a step that was interrupted by a switch and so
-- deliberately uses the time step it captured.
--
-- A step returns an unboxed pair of the next node and the output. The next
-- node is always evaluated (every structural field is strict and every
-- primitive builds its successor with its state forced), so a network never
-- accumulates thunks however long it runs; the /output/ stays lazy, which is
-- what makes 'loop' and recursive arrow notation work.
module AFRP.Internal.SF
  ( -- * Time
    Time
  , DTime
    -- * Signal functions
  , SF (..)
  , Node (..)
  , FunD (..)
  , Boxed (..)
    -- * Stepping
  , stepN
  , boxStep
  , freezeN
  , deferN
    -- * Smart constructors
  , pureN
  , constN
  , arrN
  , idN
  , compN
  , firstN
  , secondN
  , parN
  , fanN
  , loopN
  , initN
  , mealyN
    -- * Introspection (for tests)
  , stepSF
  , isPureSF
  , isConstantSF
  ) where

import           Control.Arrow
import           Control.Category (Category (..))
import           Prelude          hiding (id, (.))

------------------------------------------------------------------------------
-- Time

-- | Time in seconds. Local time starts at 0 when a signal function starts
-- (at the beginning of a run, or when it is switched in).
type Time = Double

-- | A time step in seconds: the time between two consecutive samples.
-- Time steps are expected to be positive; the first sample of any signal
-- function has no time step at all.
type DTime = Double

------------------------------------------------------------------------------
-- Representation

-- | A signal function: conceptually @Signal a -> Signal b@, a causal
-- transformer of time-varying values. 'SF' is abstract; build signal
-- functions with the primitives and combinators of "AFRP", run them with
-- 'AFRP.Run.reactimate' or 'AFRP.Run.embed'.
newtype SF a b = SF { sfNode :: Node a b }

-- | Stateless functions, with the two special cases that enable
-- simplification recognised.
data FunD a b where
  -- | The identity.
  FDI :: FunD a a
  -- | A constant function; the value is lazy.
  FDC :: b -> FunD a b
  -- | Any other function.
  FDG :: (a -> b) -> FunD a b

-- | A node of a signal-function network.
data Node a b where
  -- | A stateless node.
  NPure   :: !(FunD a b) -> Node a b
  -- | Serial composition.
  NComp   :: !(Node a c) -> !(Node c b) -> Node a b
  -- | Apply to the first component, pass the second through.
  NFirst  :: !(Node a b) -> Node (a, c) (b, c)
  -- | Apply to the second component, pass the first through.
  NSecond :: !(Node a b) -> Node (c, a) (c, b)
  -- | Parallel composition on pairs.
  NPar    :: !(Node a b) -> !(Node c d) -> Node (a, c) (b, d)
  -- | Fan-out: both nodes see the same input.
  NFan    :: !(Node a b) -> !(Node a c) -> Node a (b, c)
  -- | An opaque stateful node: given the time step and the input sample,
  -- its successor and its output.
  NStep   :: !(DTime -> a -> (# Node a b, b #)) -> Node a b

-- | A step result in a box, for the places (knots, collections) that need
-- a lifted value.
data Boxed a b = Boxed !(Node a b) b

------------------------------------------------------------------------------
-- Stepping

-- | Step a node: time step, input sample, successor and output.
stepN :: Node a b -> DTime -> a -> (# Node a b, b #)
stepN n dt a = case n of
  NPure FDI     -> (# n, a #)
  NPure (FDC b) -> (# n, b #)
  NPure (FDG f) -> (# n, f a #)
  NComp f g     -> case stepN f dt a of
    (# f', c #) -> case stepN g dt c of
      (# g', b #) -> (# compN f' g', b #)
  NFirst f      -> let (x, c) = a in case stepN f dt x of
    (# f', y #) -> (# firstN f', (y, c) #)
  NSecond f     -> let (c, x) = a in case stepN f dt x of
    (# f', y #) -> (# secondN f', (c, y) #)
  NPar f g      -> let (x, z) = a in case stepN f dt x of
    (# f', y #) -> case stepN g dt z of
      (# g', w #) -> (# parN f' g', (y, w) #)
  NFan f g      -> case stepN f dt a of
    (# f', y #) -> case stepN g dt a of
      (# g', w #) -> (# fanN f' g', (y, w) #)
  NStep s       -> s dt a

-- | 'stepN' with a boxed result.
boxStep :: Node a b -> DTime -> a -> Boxed a b
boxStep n dt a = case stepN n dt a of (# n', b #) -> Boxed n' b
{-# INLINE boxStep #-}

-- | @freezeN n dt@ is a node that, on its first step, performs the step of
-- @n@ by @dt@ (whatever time step it is given), and then continues as @n@
-- would. This is how a continuation receives a signal function that was
-- interrupted by a switch without losing or repeating any time: the step
-- that the switch pre-empted is replayed exactly once.
freezeN :: Node a b -> DTime -> Node a b
freezeN n@(NPure _) _ = n
freezeN n dt          = NStep (\_ a -> stepN n dt a)

-- | @deferN n@ takes @n@ unevaluated and evaluates it only when it is next
-- stepped. The decoupled (delayed) switches return their successor this
-- way, so that whether they switch (which may depend, through a loop, on
-- their own output at this instant) is decided after the instant is over.
deferN :: Node a b -> Node a b
deferN n = NStep (\dt a -> stepN n dt a)

------------------------------------------------------------------------------
-- Stateless functions

fdComp :: FunD a b -> FunD b c -> FunD a c
-- Identities: id >>> f = f, f >>> id = f.
fdComp FDI     g       = g
fdComp f       FDI     = f
-- Constants absorb what feeds them: f >>> const c = const c.
fdComp _       (FDC c) = FDC c
-- const b >>> g = const (g b), lazily.
fdComp (FDC b) (FDG g) = FDC (g b)
fdComp (FDG f) (FDG g) = FDG (\a -> g (f a))

fdFun :: FunD a b -> a -> b
fdFun FDI     = \a -> a
fdFun (FDC b) = \_ -> b
fdFun (FDG f) = f

------------------------------------------------------------------------------
-- Smart constructors. Each states the identity it relies on.

-- | A stateless node.
pureN :: FunD a b -> Node a b
pureN = NPure
{-# INLINE pureN #-}

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
-- arr f >>> arr g = arr (g . f)
compN (NPure f) (NPure g)            = NPure (fdComp f g)
-- id >>> n = n ; n >>> id = n
compN (NPure FDI) g                  = g
compN f (NPure FDI)                  = f
-- n >>> constant c = constant c (signal functions have no effects)
compN _ (NPure (FDC c))              = NPure (FDC c)
-- arr f >>> (arr g >>> n) = arr (g . f) >>> n
compN (NPure f) (NComp (NPure g) h)  = NComp (NPure (fdComp f g)) h
-- (n >>> arr f) >>> arr g = n >>> arr (g . f)
compN (NComp h (NPure f)) (NPure g)  = NComp h (NPure (fdComp f g))
-- (arr f &&& constant c) >>> arr g = arr (\a -> g (f a, c)): the fan was
-- kept only for the benefit of a switch, and no switch can see it here.
compN (NFan (NPure f) (NPure c)) (NPure g) = NPure (fdComp (fanFD f c) g)
compN f g                            = NComp f g

-- | @first@, simplified.
firstN :: Node a b -> Node (a, c) (b, c)
-- first id = id
firstN (NPure FDI)     = NPure FDI
-- first (arr f) = arr (\(a, c) -> (f a, c))
firstN (NPure (FDC b)) = NPure (FDG (\ ~(_, c) -> (b, c)))
firstN (NPure (FDG f)) = NPure (FDG (\ ~(a, c) -> (f a, c)))
firstN f               = NFirst f

-- | @second@, simplified.
secondN :: Node a b -> Node (c, a) (c, b)
secondN (NPure FDI)     = NPure FDI
secondN (NPure (FDC b)) = NPure (FDG (\ ~(c, _) -> (c, b)))
secondN (NPure (FDG f)) = NPure (FDG (\ ~(c, a) -> (c, f a)))
secondN f               = NSecond f

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

fanFD :: FunD a b -> FunD a c -> FunD a (b, c)
fanFD (FDC b) (FDC c) = FDC (b, c)
fanFD f g             =
  let f' = fdFun f
      g' = fdFun g
  in FDG (\a -> (f' a, g' a))

-- | @loop@: feed the second output component back as the second input
-- component of the same sample.
loopN :: Node (a, c) (b, c) -> Node a b
-- loop (arr f) = arr (\a -> fst (fix (\ ~(_, c) -> f (a, c))))
loopN (NPure fd) =
  let f = fdFun fd
  in NPure (FDG (\a -> let (b, c) = f (a, c) in b))
loopN n = NStep (loopStep n)

loopStep :: Node (a, c) (b, c) -> DTime -> a -> (# Node a b, b #)
loopStep n dt a =
  let r = boxStep n dt (a, c)
      c = case r of Boxed _ (_, c') -> c'
  in case r of Boxed n' bc -> (# loopN n', fst bc #)

-- | A node from its first step (which has no time step).
initN :: (a -> (# Node a b, b #)) -> Node a b
initN f = NStep (\_ a -> f a)
{-# INLINE initN #-}

-- | A time-independent state machine: state, output function and
-- transition, the state forced at every step.
mealyN :: (s -> a -> (s, b)) -> s -> Node a b
mealyN f = go
  where
    go !s = NStep (\_ a -> case f s a of (!s', b) -> (# go s', b #))
{-# INLINE mealyN #-}

------------------------------------------------------------------------------
-- Introspection

-- | One step of a signal function from the outside: its successor and its
-- output. The first step of a fresh signal function ignores the time step.
-- Used by the tests that watch the network simplify as it runs.
stepSF :: SF a b -> DTime -> a -> (SF a b, b)
stepSF (SF n) dt a = case stepN n dt a of (# n', b #) -> (SF n', b)

-- | Is the signal function (in its current form) stateless? Used by the
-- tests that check the optimiser.
isPureSF :: SF a b -> Bool
isPureSF (SF (NPure _)) = True
isPureSF _              = False

-- | Is the signal function (in its current form) a constant?
isConstantSF :: SF a b -> Bool
isConstantSF (SF (NPure (FDC _))) = True
isConstantSF _                    = False

------------------------------------------------------------------------------
-- Instances

-- | 'id' is 'AFRP.Basic.identity'; '.' is composition (right to left).
instance Category SF where
  id = SF idN
  SF g . SF f = SF (compN f g)

-- | 'arr' lifts a function pointwise; 'first', 'second', '***' and '&&&'
-- work sample by sample, all parts seeing the same time step.
instance Arrow SF where
  arr f = SF (arrN f)
  first (SF f) = SF (firstN f)
  second (SF f) = SF (secondN f)
  SF f *** SF g = SF (parN f g)
  SF f &&& SF g = SF (fanN f g)

-- | 'loop' feeds the second output component back, at the same sample, as
-- the second input component. The feedback must be well founded: the
-- value fed back may only be /used/ after a delay ('AFRP.Delay.iPre',
-- 'AFRP.Integration.integral', the @d@-combinators) or inside a lazy
-- structure; demanding it at the same instant diverges with @<<loop>>@.
instance ArrowLoop SF where
  loop (SF f) = SF (loopN f)

-- | Choice. @left sf@ runs @sf@ on the samples that are 'Left' and passes
-- 'Right' samples through unchanged. As in Yampa, @sf@ lives only on its
-- own samples: it starts (local time 0) at the first 'Left' sample, is
-- frozen (not stepped) on 'Right' samples, and when fed again is stepped by
-- the current time step only, so the time spent on the other side is lost
-- to it. For example @left localTime@ on @L, L, R, R, L@ with steps of 1
-- outputs @Left 0, Left 1, Right _, Right _, Left 2@.
instance ArrowChoice SF where
  left (SF f) = SF (leftN f)

leftN :: Node a b -> Node (Either a c) (Either b c)
-- left (arr f) = arr (left f)
leftN (NPure FDI) = NPure FDI
leftN (NPure fd)  = let f = fdFun fd in NPure (FDG (either (Left . f) Right))
leftN n           = NStep (\dt e -> case e of
  Right c -> (# leftN n, Right c #)
  Left a  -> case stepN n dt a of (# n', b #) -> (# leftN n', Left b #))

-- | @fmap f sf = sf >>> arr f@.
instance Functor (SF a) where
  fmap f (SF n) = SF (compN n (arrN f))

-- | @pure = constant@; @sf1 \<*\> sf2@ applies the output of @sf1@ to that
-- of @sf2@ at every sample.
instance Applicative (SF a) where
  pure b = SF (constN b)
  SF f <*> SF x = SF (compN (fanN f x) (arrN (\(g, y) -> g y)))
