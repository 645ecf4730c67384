{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.EventSource.Sample
-- Description : Events that carry samples of the input: at time 0, at a
--               time, periodically, and a window of the last samples.
--
-- Part of "AFRP.EventSource", whose timing conventions apply to the
-- sources here that occur at scheduled times ('snapAfter', 'sample',
-- 'sampleWindow'), as to those of "AFRP.EventSource.Timed". 'snapAfter'
-- and 'sample' are built on 'after' and 'repeatedly'; 'sampleWindow'
-- keeps a clock of its own (its instants those of
-- 'AFRP.EventSource.afterEachCat' with the period as every delay), which
-- counts every period a time step spans, in bounded time and memory
-- however many they are.
module AFRP.EventSource.Sample
  ( snap
  , snapAfter
  , sample
  , sampleWindow
  ) where

import qualified Data.Sequence        as Seq

import           AFRP.Event
import           AFRP.EventSource.Timed    (after, never, repeatedly)
import           AFRP.Internal.Clock
import           AFRP.Internal.EventSource (errNeg, errPeriod, twoTo53)
import           AFRP.Internal.SF

-- | One occurrence at time 0 carrying the input sample there.
snap :: SF a (Event a)
snap = SF (initN (\a -> (# sfNode never, Event a #)))

-- | One occurrence, carrying the input sample, at the first sample whose
-- local time has reached @t@ (at time 0 if @t == 0@). A negative @t@ is an
-- error, as for 'after'.
snapAfter :: Time -> SF a (Event a)
snapAfter t
  | t < 0 || isNaN t = errNeg "snapAfter" t
  | otherwise        = SF (compN (fanN (sfNode (after t ())) idN) (arrN (\(e, a) -> e `tag` a)))

-- | @sample p@ occurs at local times @p, 2p, ...@ (as 'repeatedly')
-- carrying the input sample at that instant. No occurrence at time 0. A
-- period that is not positive (or NaN) is an error.
sample :: Time -> SF a (Event a)
sample p
  | p <= 0 || isNaN p = errPeriod "sample" p
  | otherwise = SF (compN (fanN (sfNode (repeatedly p ())) idN) (arrN (\(e, a) -> e `tag` a)))

-- | @sampleWindow w p@ takes a sample of the input every @p@ seconds (as
-- 'sample', but one sample per period even when a time step spans several
-- periods) and, at each sampling instant, produces the last @w@ samples
-- taken, oldest first. No occurrence at time 0. A window size below 1 or a
-- non-positive period is an error (Yampa does not check: there a window of
-- 0 gives empty lists and a period of 0 hangs).
--
-- The sampling instants are those of @afterEachCat (repeat (p, ()))@: each
-- is @p@ after the previous, in the compensated sum of "AFRP.Internal.Clock".
-- Memory and time stay bounded whatever one step spans: the samples of one
-- step are all the same input, so a step that spans more periods than the
-- window holds fills the window with that input and no more. When a step
-- spans more than 4096 periods, the rest of them are counted at once (a
-- multiple of @p@ added to the clock in one sum), so that the following
-- instants may differ from the period-by-period sum by its rounding; a
-- window of any size (@maxBound@ included) costs no more. Where the periods cannot be counted (a step that lands more
-- than @2^53@ periods beyond, an infinite time, or a period too small to
-- move a clock showing that time), the current time is taken as the last
-- instant, and the window is filled with the input. A sample whose time
-- step is 0 passes no instant (elsewhere this is what the count gives; in
-- those cases, where every instant counts as reached, it kept filling
-- the window at samples where no time passed).
sampleWindow :: Int -> Time -> SF a (Event [a])
sampleWindow w p
  | w < 1     = error ("AFRP.EventSource.sampleWindow: window size must be at least 1, got "
                       ++ show w)
  | p <= 0 || isNaN p = errPeriod "sampleWindow" p
  | otherwise = SF (initN (\_ -> (# go clockZero clockZero Seq.empty, NoEvent #)))
  where
    -- clock: local time now; due: the last sampling instant so far.
    go !clock !due !win = NStep (\dt a ->
      let !clock' = tick clock dt
      in if dt == 0 then (# go clock due win, NoEvent #) else case crossings clock' due of
        (# due', k #)
          | k == 0    -> (# go clock' due' win, NoEvent #)
          | otherwise ->
              let n     = min k w
                  -- (the old samples that stay, then the new: no size
                  -- beyond the window's, even at maxBound)
                  old   = Seq.length win - min (Seq.length win) (w - n)
                  !win' = Seq.drop old win Seq.>< Seq.replicate n a
              in (# go clock' due' win', Event (foldr (:) [] win') #))
    -- The instants after @due@ up to the clock's time: the last of them,
    -- and how many there are (one by one up to 'jumpAt', then the rest at
    -- once; where they cannot be counted, at least the window's size: all
    -- the window needs).
    crossings :: Clock -> Clock -> (# Clock, Int #)
    crossings clock = count 0
      where
        t = clockTime clock
        count :: Int -> Clock -> (# Clock, Int #)
        count !k !d
          | not (reached (clockTime d') t) = (# d, k #)
          | k < jumpAt              = count (k + 1) d'
          -- beyond the window: the periods but the last one or two at once
          | r > 2 && r < twoTo53 =
              let skipped = floor r - 1 :: Int
              in count (k + skipped) (tick d (fromIntegral skipped * p))
          -- the last one or two, while each is a visible step
          | r <= 2 && clockTime d' > clockTime d = count (k + 1) d'
          -- further than a Double counts, or no visible step: caught up
          | otherwise               = (# clock, max k w #)
          where
            d' = tick d p
            r  = (t - clockTime d) / p
    jumpAt = 4096 :: Int
