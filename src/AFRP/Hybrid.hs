{-# LANGUAGE BangPatterns #-}
{-# LANGUAGE UnboxedTuples #-}
-- |
-- Module      : AFRP.Hybrid
-- Description : Between the continuous and the discrete: holding and
--               accumulating event values.
--
-- Every combinator comes in an immediate form and a delayed (@d@) form.
-- The immediate form reacts /at/ the instant of an event: its output at
-- that sample already reflects the event. The delayed form outputs, at
-- every sample, what the immediate form output at the previous sample
-- (its initial value at time 0), so an event is reflected one sample
-- later. Delayed forms do not evaluate their current input, so they can
-- close a feedback loop.
--
-- No combinator here evaluates its input before its output is demanded:
-- an event is folded into the state at the next sample (or when the
-- output is demanded), so every combinator can watch a signal fed back
-- through a 'Control.Arrow.loop' whose output nobody needs at that
-- instant. Accumulated values are evaluated (to weak head normal form)
-- when the next sample folds them in, so a long run accumulates no
-- thunks. (This is where afrp differs from Yampa: an accumulating
-- function that gives an error, as in
-- @accumBy (\_ a -> if a == 2 then error "e" else a) 0@, stops the run
-- at the sample after the one whose event made the error, one sample
-- before Yampa's does.)
module AFRP.Hybrid
  ( -- * Holding
    hold
  , dHold
  , trackAndHold
  , dTrackAndHold
    -- * Accumulating
  , accum
  , accumHold
  , dAccumHold
  , accumBy
  , accumHoldBy
  , dAccumHoldBy
  , accumFilter
  ) where

import           AFRP.Delay       (iPre)
import           AFRP.Event
import           AFRP.Internal.SF

-- | @hold a0@ outputs @a0@ until the first event, then the value of the
-- most recent event. At the instant of an event it already outputs the
-- new value; an event at time 0 is output at time 0 (as in Yampa).
--
-- > embed (hold 0) (NoEvent, [(1, Just (Event 5)), (1, Just NoEvent)])  ==  [0, 5, 5]
hold :: a -> SF (Event a) a
hold a0 = SF (go a0 NoEvent)
  where
    -- The previous sample's event is folded in only now (not when it
    -- arrived), so the input is evaluated only if the output is demanded.
    go held ePrev = NStep (\_ e -> case ePrev of
      NoEvent -> (# go held e, current held e #)
      Event x -> (# go x e, current x e #))
    current held e = case e of
      NoEvent -> held
      Event x -> x

-- | Delayed 'hold': @a0@ at time 0, then at each sample what 'hold' output
-- at the previous one (Yampa: @hold a0 >>> iPre a0@).
dHold :: a -> SF (Event a) a
dHold a0 = delayed NoEvent (hold a0)

-- | @trackAndHold a0@ follows the input while it is 'Just', and holds the
-- last 'Just' value while it is 'Nothing' (@a0@ before any 'Just'; a
-- 'Just' at time 0 is output at time 0).
trackAndHold :: a -> SF (Maybe a) a
trackAndHold a0 = SF (compN (arrN maybeToEvent) (sfNode (hold a0)))

-- | Delayed 'trackAndHold': @a0@ at time 0, then at each sample what
-- 'trackAndHold' output at the previous one (Yampa's definition,
-- @trackAndHold a0 >>> iPre a0@).
dTrackAndHold :: a -> SF (Maybe a) a
dTrackAndHold a0 = delayed Nothing (trackAndHold a0)

-- | @accum a0@ turns an event stream of functions into an event stream of
-- values: the n-th output event carries @f_n (... (f_1 a0))@. At an event
-- instant it outputs the event with the new value.
--
-- > embed (accum 0) (Event (+1), [(1, Just NoEvent), (1, Just (Event (*10)))])
-- >   ==  [Event 1, NoEvent, Event 10]
accum :: a -> SF (Event (a -> a)) (Event a)
accum = accumBy (\a f -> f a)

-- | @accumHold a0 = accum a0 >>> hold a0@: the accumulated value, updated
-- at the instant of each event (an event at time 0 is folded in at time
-- 0).
accumHold :: a -> SF (Event (a -> a)) a
accumHold = accumHoldBy (\a f -> f a)
{-# INLINE accumHold #-}

-- | Delayed 'accumHold': the accumulated value excluding the current
-- sample's event; @a0@ at time 0 (Yampa: @accumHold a0 >>> iPre a0@).
dAccumHold :: a -> SF (Event (a -> a)) a
dAccumHold a0 = delayed NoEvent (accumHold a0)

-- | @accumBy f b0@: each event @a@ updates the accumulator @b := f b a@ and
-- produces an event carrying the new @b@, at the event's instant (time 0
-- included).
accumBy :: (b -> a -> b) -> b -> SF (Event a) (Event b)
accumBy f = accumFilter (\b a -> let b' = f b a in (b', Just b'))

-- | @accumHoldBy f b0@: the accumulator of 'accumBy', held as a signal.
-- Where @arr p >>> accumHoldBy f b0@ (or @accumHold@) is written in the
-- source, a rewrite rule makes it one node that applies @p@ in the
-- output's thunk, which means the same and allocates less.
accumHoldBy :: (b -> a -> b) -> b -> SF (Event a) b
accumHoldBy f b0 = SF (accumHoldFrom f (\e -> e) b0)
{-# NOINLINE [1] accumHoldBy #-}

-- @accumHoldByOn f p b0 = arr p >>> accumHoldBy f b0@, in one node: @p@
-- is applied in the one thunk that both the output and the next step
-- read, instead of in a thunk of its own. The idiom @arr (\e -> tag e g)
-- >>> accumHold a0@ becomes this by the rewrite rules below wherever GHC
-- sees it written.
accumHoldByOn :: (b -> a -> b) -> (c -> Event a) -> b -> SF c b
accumHoldByOn f p b0 = SF (accumHoldFrom f p b0)

{-# RULES
"AFRP arr>>>accumHoldBy" forall p f b0.
  compSF (accumHoldBy f b0) (arrSF p) = accumHoldByOn f p b0
"AFRP arr>>>accumHoldBy>>>sf" forall p f b0 h.
  compSF (compSF h (accumHoldBy f b0)) (arrSF p) = compSF h (accumHoldByOn f p b0)
  #-}

-- The accumulator of @p@'s events. The output is the next state: kept
-- unevaluated, and forced at the start of the next step (an event is
-- folded in only then, or when the output is demanded).
accumHoldFrom :: (b -> a -> b) -> (c -> Event a) -> b -> Node c b
accumHoldFrom f p = go
  where
    go acc = NStep (\_ c -> case acc of
      !b -> let out = case p c of
                  NoEvent -> b
                  Event a -> f b a
            in (# go out, out #))
{-# INLINE accumHoldFrom #-}

-- | Delayed 'accumHoldBy'.
dAccumHoldBy :: (b -> a -> b) -> b -> SF (Event a) b
dAccumHoldBy f b0 = delayed NoEvent (accumHoldBy f b0)

-- | @accumFilter f c0@: each event @a@ updates the accumulator with
-- @(c', mb) = f c a@ and produces an event exactly when @mb@ is @Just b@.
accumFilter :: (c -> a -> (c, Maybe b)) -> c -> SF (Event a) (Event b)
accumFilter f c0 = SF (mealyN step c0)
  where
    step c NoEvent   = (c, NoEvent)
    step c (Event a) = case f c a of (c', mb) -> (c', maybeToEvent mb)

-- The delayed form of an immediate combinator: delay its /input/ by one
-- sample, with a neutral first input. This equals delaying the output
-- (with the combinator's initial value) but never evaluates the current
-- input, so it is safe in a feedback loop.
delayed :: a -> SF a b -> SF a b
delayed neutral (SF n) = SF (compN (sfNode (iPre neutral)) n)
