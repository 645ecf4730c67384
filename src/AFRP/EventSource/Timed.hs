{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFRP.EventSource.Timed
-- Description : Event sources whose occurrences are scheduled in local
--               time, and delayed events.
--
-- Part of "AFRP.EventSource", whose timing conventions (local time, "at,
-- or as soon after as possible", the compensated clock, one occurrence
-- or all of them when a sample spans several) apply to every source
-- here. The argument checks' errors, which "AFRP.EventSource.Sample"
-- shares, are "AFRP.Internal.EventSource"'s.
module AFRP.EventSource.Timed
  ( -- * Basic sources
    never
  , now
  , after
  , repeatedly
  , afterEach
  , afterEachCat
    -- * Delaying events
  , delayEvent
  , delayEventCat
  ) where

import qualified Data.Sequence        as Seq
import           Data.Sequence        (Seq, (|>))

import           AFRP.Event
import           AFRP.Internal.Clock
import           AFRP.Internal.EventSource (errNeg, errPeriod, twoTo53)
import           AFRP.Internal.SF

-- | The event source with no occurrences. The optimiser knows it: a switch
-- whose event comes from 'never' disappears.
never :: SF a (Event b)
never = SF neverN

neverN :: Node a (Event b)
neverN = constN NoEvent

-- | @now x@ occurs once, at local time 0, with value @x@.
--
-- > embed (now 'x') ((), [(1, Nothing)])  ==  [Event 'x', NoEvent]
now :: b -> SF a (Event b)
now x = SF (initN (\_ -> (# neverN, Event x #)))

-- | @after t x@ occurs once, with value @x@, at the first sample whose
-- local time has reached @t@ (see the timing conventions of
-- "AFRP.EventSource"); @after 0 x@ is @now x@. A negative @t@ is an
-- error.
--
-- > embed (after 1.0 ()) ((), replicate 3 (0.5, Nothing))
-- >   ==  [NoEvent, NoEvent, Event (), NoEvent]
after :: Time -> b -> SF a (Event b)
after t x
  | t < 0 || isNaN t = errNeg "after" t
  | isInfinite t     = never
  | otherwise        = afterEach [(t, x)]

-- | @repeatedly p x@ occurs with value @x@ at local times @p, 2p, 3p, ...@,
-- each at the first sample whose local time has reached it. No backlog: if a time
-- step spans several periods, one occurrence is produced and the schedule
-- moves on to the first period boundary after the current time. There is
-- no occurrence at time 0. A non-positive period is an error; an
-- infinite one never occurs, as @'after' (1/0)@.
--
-- Where the boundaries cannot be told apart: once an occurrence comes at
-- a local time @t@ with @p <= 2^-53 * t@ (the period no longer than one
-- unit in the last place of @t@, so that any move of the clock's reading
-- is a period or more; @p = 1e-14@ after 1000 s, a subnormal period after
-- a second), every later sample that moves the local time on (as the
-- clock reads it) has an occurrence, and a sample that does not move it
-- has none. (Counting the boundaries there could still skip a move now
-- and then, where the tolerance of 'reached' covers it: this regime is
-- the rule's approximation, not the rule.) Above that, the boundaries
-- are counted exactly, even where several of them count as 'reached' at
-- once (a period within the tolerance of 'reached', @2^-48 * t@):
-- @repeatedly 1e-12@ after 1000 s, sampled every 1e-13 s, occurs about
-- once every ten samples. An occurrence at an infinite local time is the
-- last: no boundary lies after it.
repeatedly :: Time -> b -> SF a (Event b)
repeatedly p x
  | p <= 0 || isNaN p = errPeriod "repeatedly" p
  | isInfinite p      = never
  | otherwise         = SF (initN (\_ -> (# go clockZero 1, NoEvent #)))
  where
    go !clock !n = NStep (\dt _ ->
      let !clock' = tick clock dt
          !t      = clockTime clock'
      in if reached (fromIntegral n * p) t
           then (# after' clock' t n, Event x #)
           else (# go clock' n, NoEvent #))
    -- (what follows an occurrence: the next boundary not reached; once
    -- the period is no longer than one unit in the last place of the
    -- local time, an occurrence at every sample that moves the time on;
    -- after an infinite time, none. p <= 2^-53 t is tested as
    -- p * 2^53 <= t: exact (a power of two), even where 2^-53 t would be
    -- subnormal and rounded; then p is at most one unit in the last place
    -- of t. Below that test t / p < 2^53, so the search's
    -- q + tolerance * q cannot overflow)
    after' clock' t n
      | isInfinite t       = neverN
      | p * twoTo53 <= t   = fine clock'
      | otherwise          = go clock' (nextIndex t (n + 1))
    fine !clock = NStep (\dt _ ->
      let !clock' = tick clock dt
      in if clockTime clock' > clockTime clock then (# fine clock', Event x #) else (# fine clock', NoEvent #))
    -- The first period boundary from n0 on that t has not reached. The
    -- boundaries reached are those up to about (t + tolerance * t) / p, so the
    -- search starts there and walks, down or up, to the first one not
    -- reached ('reached' of n * p falls as n grows): a few steps, even
    -- after a huge time step, since t / p < 2^53 here.
    nextIndex :: Time -> Integer -> Integer
    nextIndex t n0
      | beyond start = down start
      | otherwise    = up start
      where
        start = max n0 (let q = t / p in floor (q + timeTolerance * q))
        beyond n = not (reached (fromIntegral n * p) t)
        down n | n > n0, beyond (n - 1) = down (n - 1)
               | otherwise               = n
        up n | beyond n  = n
             | otherwise = up (n + 1)

-- | @afterEach [(q1, x1), (q2, x2), ...]@ occurs with @x1@ at local time
-- @q1@, with @x2@ at @q1 + q2@, and so on: each delay is measured from the
-- previous scheduled occurrence. When one sample interval spans several
-- scheduled occurrences only the first of them is produced (see
-- 'afterEachCat' for all of them). Negative delays are an error, reported
-- when reached (the list may be infinite). A sample reaches every
-- occurrence due by its time: an infinite run of delays summing to no
-- more than that (@repeat (0, x)@) never finishes the sample, as in Yampa.
-- Delays of 0 at the head of the list occur at local time 0:
-- @afterEach [(0, 'a'), (0, 'b'), (1, 'c')]@ gives @Event 'a'@ at time 0
-- and @Event 'c'@ at 1 ('afterEachCat': @Event "ab"@ at 0), as in Yampa.
--
-- A sample that passes many occurrences takes time in their number, but
-- no memory: the occurrences after the first are passed over, not
-- gathered (gathered, a step of 10^4 s over delays of 1 ms took 240 MB).
afterEach :: [(Time, b)] -> SF a (Event b)
afterEach = afterEachBy (\x first -> case first of { Nothing -> Just x; Just _ -> first }) id

-- | Like 'afterEach', but every occurrence scheduled up to the current
-- sample is delivered, in schedule order, in one list.
--
-- > embed (afterEachCat [(0.5, 'a'), (0.1, 'b'), (1, 'c')]) ((), replicate 3 (1, Nothing))
-- >   ==  [NoEvent, Event "ab", Event "c", NoEvent]
afterEachCat :: [(Time, b)] -> SF a (Event [b])
afterEachCat = afterEachBy (\x acc -> case acc of { Nothing -> Just [x]; Just xs -> Just (x : xs) }) reverse

-- The schedule of 'afterEach' and 'afterEachCat': the occurrences due at a
-- sample, in schedule order, gathered by @keep@ as they are passed (from
-- 'Nothing'; only its 'Just' is evaluated, never an occurrence's value),
-- what it kept made the event's value by @done@; no event when none is
-- due.
afterEachBy :: forall a b c. (b -> Maybe c -> Maybe c) -> (c -> c) -> [(Time, b)] -> SF a (Event c)
afterEachBy keep done qxs0 = SF (initN (\_ -> emit clockZero clockZero qxs0))
  where
    -- clock: local time now; due: the schedule time of the last occurrence
    -- already delivered.
    emit :: Clock -> Clock -> [(Time, b)] -> (# Node a (Event c), Event c #)
    emit clock due qxs = collect due qxs Nothing
      where
        now' = clockTime clock
        collect :: Clock -> [(Time, b)] -> Maybe c -> (# Node a (Event c), Event c #)
        collect !d ((q, x) : rest) acc
          | q < 0 || isNaN q                = errNeg "afterEach" q
          | reached (clockTime (tick d q)) now' = case keep x acc of !acc' -> collect (tick d q) rest acc'
        collect !d rest acc =
          (# next clock d rest, maybe NoEvent (Event . done) acc #)
    next :: Clock -> Clock -> [(Time, b)] -> Node a (Event c)
    next _ _ []        = neverN
    next clock due qxs = NStep (\dt _ -> emit (tick clock dt) due qxs)

-- | @delayEvent q@ delays every occurrence by @q@ seconds: an occurrence
-- at local time @t@ is produced at the first sample after it whose local
-- time has reached @t + q@ (the due time is one floating-point addition,
-- and reaching it allows for the rounding, so decimal times and steps
-- give the samples decimal arithmetic gives). When several delayed
-- occurrences fall due at one sample only the first (earliest) is
-- produced ('delayEventCat' gives them all). @delayEvent 0@ is the
-- identity; a negative delay is an error. For @q > 0@ the output at time
-- 0 is 'NoEvent', and an occurrence at time 0 is kept and comes out at
-- @q@, as in Yampa.
delayEvent :: Time -> SF (Event a) (Event a)
delayEvent q
  | q < 0 || isNaN q = errNeg "delayEvent" q
  | q == 0           = SF idN
  | isInfinite q     = SF neverN
  | otherwise        = SF (compN (sfNode (delayEventCat q)) (arrN (fmap head)))

-- | Like 'delayEvent', delivering every occurrence that falls due at a
-- sample, oldest first. The output never depends on the current input, so
-- a delayed event stream can be fed back through a loop (for instance to
-- build a recurring event).
delayEventCat :: forall a. Time -> SF (Event a) (Event [a])
delayEventCat q
  | q < 0 || isNaN q = errNeg "delayEventCat" q
  | q == 0           = SF (arrN (fmap (: [])))
  | isInfinite q     = SF neverN
  | otherwise        = SF (initN (\e -> (# go clockZero Seq.empty e, NoEvent #)))
  where
    -- The input of the previous sample (taken at the clock's previous
    -- reading) is scheduled only now: since q > 0 it cannot be due before
    -- this sample, and the current input is never evaluated, so the delay
    -- can close a feedback loop.
    go :: Clock -> Seq (Time, a) -> Event a -> Node (Event a) (Event [a])
    go !clock !pending ePrev = NStep (\dt e ->
      let !clock'     = tick clock dt
          !now'       = clockTime clock'
          pending'    = event pending (\x -> pending |> (clockTime clock + q, x)) ePrev
          (due, rest) = Seq.spanl (\(tDue, _) -> reached tDue now') pending'
          out         = if Seq.null due then NoEvent else Event (foldr ((:) . snd) [] due)
      in (# go clock' rest e, out #))
