{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFRP.Internal.Clock
-- Description : Local time kept as a compensated sum of time steps.
--
-- Every time-based primitive of the library ('AFRP.Basic.localTime',
-- 'AFRP.EventSource.after', 'AFRP.EventSource.repeatedly',
-- 'AFRP.Delay.delay', ...) measures its local time as the sum of the time
-- steps it has seen. A naive floating-point sum drifts: ten steps of 0.1
-- add up to 0.9999999999999999, so an @after 1@ would fire one sample late.
-- We keep a Neumaier-compensated sum instead, at the cost of two extra
-- additions per step. It is the exact sum of the steps as given, to within
-- one unit in the last place (ten steps of 0.1 give exactly 1.0), which
-- is not always the decimal number a person expects: the steps are binary
-- fractions, so three steps of 0.1 read 0.30000000000000004, as
-- @0.1 + 0.1 + 0.1@ does.
-- What the library promises is one rule for every time-based combinator:
-- an event due at time t happens at the first sample whose clock has
-- 'reached' t: reads t or more, or less than t by no more than the
-- rounding of binary fractions (a relative 2^-48, see 'reached'). Six
-- steps of 0.15 read 0.8999999999999999, and @after 0.9@ fires there, as
-- a person reading decimals expects (and as Yampa's plain sum happens to
-- give); a @delay 0.3@ at steps of 0.1 releases each sample exactly three
-- samples later, none twice and none skipped.
module AFRP.Internal.Clock
  ( Clock
  , clockZero
  , clockAt
  , tick
  , clockTime
  , reached
  , timeTolerance
  ) where

-- | A running compensated sum: the rounded sum and the lost low-order part.
data Clock = Clock {-# UNPACK #-} !Double {-# UNPACK #-} !Double

-- | Time zero.
clockZero :: Clock
clockZero = Clock 0 0

-- | A clock reading the given time.
clockAt :: Double -> Clock
clockAt t = Clock t 0

-- | Advance by a time step.
tick :: Clock -> Double -> Clock
tick (Clock s c) x =
  let !t  = s + x
      !c' | abs s >= abs x = c + ((s - t) + x)
          | otherwise      = c + ((x - t) + s)
  in Clock t c'
{-# INLINE tick #-}

-- | The time the clock shows.
clockTime :: Clock -> Double
clockTime (Clock s c)
  | abs s == 1 / 0 = s   -- overflowed: the compensation is Inf - Inf = NaN
  | otherwise      = s + c
  -- ('isInfinite' is a foreign call: 2.6% more instructions on the
  -- reference benchmark's network f, against none for this comparison)
{-# INLINE clockTime #-}

-- | @reached due t@: has a clock reading @t@ reached the time @due@? True
-- when @t >= due@, and when @t@ falls short of @due@ by no more than
-- 'timeTolerance' of @t@: the error of the binary fractions that decimal
-- steps and times are written in (a step of 0.1 is not a tenth), which a
-- sum of steps and a due time computed from others (@s + q@, @n * p@)
-- each carry, a few units in the last place. Never for a NaN, and for an
-- infinite @due@ only at an infinite @t@.
reached :: Double -> Double -> Bool
reached due t = t >= due || due - t <= timeTolerance * abs t
{-# INLINE reached #-}

-- | The relative tolerance of 'reached': 2^-48 (about 3.6e-15, 32 units in
-- the last place; 3.6 ns at a local time of 10^6 s).
timeTolerance :: Double
timeTolerance = 3.552713678800501e-15
