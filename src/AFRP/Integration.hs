{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Integration
-- Description : Integration and differentiation over vector spaces, and
--               counting events.
--
-- All of these see the first sample without a time step, so 'integral'
-- and 'derivative' output 'zeroVector' there. After that, with time steps
-- @dt_1, dt_2, ...@ and input samples @a_0, a_1, ...@:
--
-- @
-- integral          y_n = y_(n-1) + dt_n * a_(n-1)            (left rectangle)
-- imIntegral y0     y_n = y_(n-1) + dt_n * a_n                (right rectangle)
-- trapezoidIntegral y_n = y_(n-1) + dt_n * (a_(n-1) + a_n) / 2
-- derivative        y_n = (a_n - a_(n-1)) / dt_n
-- @
--
-- 'integral' never evaluates its current input (its output depends only on
-- earlier samples), so it can close a feedback loop ('AFRP.Loop.loopIntegral').
-- The running sum is evaluated at every step: no thunks build up.
module AFRP.Integration
  ( integral
  , imIntegral
  , trapezoidIntegral
  , impulseIntegral
  , count
  , derivative
  ) where

import           Control.Arrow     ((***))
import           AFRP.Event
import           AFRP.Hybrid       (accumBy, accumHoldBy)
import           AFRP.Internal.SF
import           AFRP.VectorSpace

-- | The integral of the input over local time, by the left rectangle rule:
-- 0 at time 0; at each later sample the previous output plus the time
-- step times the /previous/ input.
--
-- > embed integral (1, [(0.5, Just 2), (0.5, Just 3)])  ==  [0, 0.5, 1.5]
integral :: VectorSpace a s => SF a a
integral = SF (initN (\a0 -> case go zeroVector a0 of !n -> (# n, zeroVector #)))
  where
    go !acc prev = NStep (\dt a ->
      let !acc' = acc ^+^ realToFrac dt *^ prev
      in case go acc' a of !n -> (# n, acc' #))
{-# INLINABLE [1] integral #-}

-- At 'Double', 'integral' is the specialised node 'NIntD', which computes
-- the same sums (@acc + dt * prev@) without a closure per step.
{-# RULES "integral/Double" integral = integralDouble #-}

-- | 'integral' at 'Double'.
integralDouble :: SF Double Double
integralDouble = SF (initN (\a0 -> (# NIntD 0 a0, 0 #)))
{-# NOINLINE integralDouble #-}

-- | The "immediate" integral from a given initial value, by the right
-- rectangle rule: @y0@ at time 0; at each later sample the previous output
-- plus the time step times the /current/ input.
--
-- > embed (imIntegral 10) (1, [(0.5, Just 2), (0.5, Just 3)])  ==  [10, 11, 12.5]
imIntegral :: VectorSpace a s => a -> SF a a
imIntegral y0 = SF (initN (\_ -> (# go y0, y0 #)))
  where
    go !acc = NStep (\dt a ->
      let !acc' = acc ^+^ realToFrac dt *^ a
      in case go acc' of !n -> (# n, acc' #))
{-# INLINABLE imIntegral #-}

-- | The integral by the trapezoid rule: 0 at time 0; then the previous
-- output plus the time step times the mean of the previous and current
-- inputs. Exact for piecewise-linear inputs.
trapezoidIntegral :: VectorSpace a s => SF a a
trapezoidIntegral = SF (initN (\a0 -> case go zeroVector a0 of !n -> (# n, zeroVector #)))
  where
    go !acc prev = NStep (\dt a ->
      let !acc' = acc ^+^ (realToFrac dt / 2) *^ (prev ^+^ a)
      in case go acc' a of !n -> (# n, acc' #))
{-# INLINABLE trapezoidIntegral #-}

-- | The 'integral' of the first input plus the sum of the values of the
-- events of the second: a continuous flow with discrete impulses. An
-- impulse is added at the instant of its event.
impulseIntegral :: VectorSpace a k => SF (a, Event a) a
impulseIntegral = SF (compN (sfNode (integral *** accumHoldBy (^+^) zeroVector))
                            (arrN (uncurry (^+^))))

-- | Count events: the n-th occurrence of the input produces an occurrence
-- carrying @n@ (1 for the first).
count :: Integral b => SF (Event a) (Event b)
count = accumBy (\n _ -> n + 1) 0

-- | The derivative of the input: 'zeroVector' at time 0, then the
-- difference quotient of the current and previous samples. A zero time
-- step gives infinite or NaN components, as the arithmetic does.
--
-- > embed derivative (1, [(0.5, Just 2), (0.5, Just 2)])  ==  [0, 2, 0]
derivative :: VectorSpace a s => SF a a
derivative = SF (initN (\a0 -> case go a0 of !n -> (# n, zeroVector #)))
  where
    go !prev = NStep (\dt a ->
      let !d = (a ^-^ prev) ^/ realToFrac dt
      in case go a of !n -> (# n, d #))
{-# INLINABLE derivative #-}
