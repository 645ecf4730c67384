{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Internal.Deferred
-- Description : Nodes built from a step function, and steps deferred:
--               state machines, lazy wrappers, hand-overs, frozen steps.
--
-- Internal, not part of the API (re-exported by "AFRP.Internal.SF" for
-- the library's own modules). "AFRP.Internal.Node" holds the nodes the
-- optimiser understands; every stateful primitive whose state it cannot
-- see is an opaque 'NStep', built with one of the functions here.
--
-- Each keeps the rule of "AFRP.Internal.Node" that no step evaluates its
-- input sample: a state machine ('mealyN') applies its transition lazily
-- and forces the new state at the start of the next step; a primitive
-- whose step must evaluate its input (a switch deciding whether its event
-- occurred, a collection routing its input) is wrapped by 'lazyN' or
-- 'lazyHandoverN', so that its step is performed only when its output is
-- demanded or, at the latest, at the start of the next step; a decoupled
-- switch returns its successor through 'deferN', decided after the
-- instant is over; and a switch hands its continuation the step it
-- pre-empted through 'freezeN'.
module AFRP.Internal.Deferred
  ( -- * Built from a step
    initN
  , mealyN
    -- * Steps deferred
  , lazyN
  , HandoverStep (..)
  , Next (..)
  , lazyHandoverN
  , deferN
  , freezeN
  ) where

import           AFRP.Internal.Node

-- | A node from its first step (which has no time step).
initN :: (a -> (# Node a b, b #)) -> Node a b
initN f = NStep (\_ a -> f a)
{-# INLINE initN #-}

-- | A time-independent state machine: state, output function and
-- transition. The step does not evaluate its input: the transition is
-- applied lazily, and its new state is forced at the start of the next
-- step (so a state never holds more than one step's thunk).
mealyN :: (s -> a -> (s, b)) -> s -> Node a b
mealyN f s0 = NStep (\_ a -> let r = f s0 a in (# pending r, snd r #))
  where
    pending r = NStep (\_ a -> case r of
      (!s, _) -> let r' = f s a in (# pending r', snd r' #))
{-# INLINE mealyN #-}

-- | @lazyN n@ behaves as @n@, but each of its steps is performed only
-- when its output is demanded or, at the latest, at the start of the next
-- step. For primitives whose step evaluates their input (a switch
-- deciding whether its event occurred, a collection routing its input):
-- wrapped, they no longer demand their input before someone downstream
-- demands their output. A successor that has become pure is returned as
-- it is, and so stops paying for the wrapper.
lazyN :: Node a b -> Node a b
lazyN n = case n of
  NPure _ -> n
  _       -> NStep (stepLazyN n)

stepLazyN :: Node a b -> DTime -> a -> (# Node a b, b #)
stepLazyN n dt a =
  let r = boxStep n dt a
  in (# NStep (resumeLazyN r), case r of Boxed _ b -> b #)

resumeLazyN :: Boxed a b -> DTime -> a -> (# Node a b, b #)
resumeLazyN (Boxed n _) dt a = case n of
  NPure _ -> stepN n dt a
  _       -> stepLazyN n dt a

-- | The step of a switch that runs lazily until it hands over for good
-- ('lazyHandoverN'): its output and what follows, 'Stay' (its own next
-- step) or 'Leave' (the node it hands over to, already started).
newtype HandoverStep a b = HandoverStep (DTime -> a -> (# Next a b, b #))

-- | What follows a step of a 'lazyHandoverN' switch. It may be left
-- unevaluated until the next step (a decoupled switch decides there
-- whether it switched).
data Next a b
  = Stay (HandoverStep a b)  -- ^ the switch's own next step, lazy as this one
  | Leave (Node a b)         -- ^ the node handed over to, stepped as it is from now on

-- A 'HandoverStep' result in a box (both parts lazy).
data BoxedNext a b = BoxedNext (Next a b) b

-- | @lazyHandoverN s@: a switch whose steps are performed as 'lazyN'
-- performs them (when the output is demanded, or at the latest at the
-- start of the next step) for as long as it stays, and which, once a step
-- has left for a node, is that node: stepped as it is, not wrapped.
-- A switch whose continuation is a lazy switch again (a 'AFRP.Switch.kSwitch'
-- or a 'AFRP.Parallel.pSwitch' calling itself, the usual way of writing
-- one that recurs) would otherwise be wrapped once more at every switch,
-- each later step costing one more layer (quadratic time, and the layers
-- kept).
lazyHandoverN :: HandoverStep a b -> Node a b
lazyHandoverN h = NStep (stepHandover h)

stepHandover :: HandoverStep a b -> DTime -> a -> (# Node a b, b #)
stepHandover (HandoverStep f) dt a =
  let r = case f dt a of (# nx, b #) -> BoxedNext nx b
  in (# NStep (resumeHandover r), case r of BoxedNext _ b -> b #)

resumeHandover :: BoxedNext a b -> DTime -> a -> (# Node a b, b #)
resumeHandover (BoxedNext nx _) dt a = case nx of
  Stay h  -> stepHandover h dt a
  Leave n -> stepN n dt a


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
