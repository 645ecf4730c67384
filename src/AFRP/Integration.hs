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
  , iterFrom
  ) where

import           Control.Arrow     ((***))
import           GHC.Exts          (noinline)
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

-- | @integralDOn p q@ is @arr p >>> integral >>> arr q@ at 'Double', as
-- one node: it stores its input sample as it comes and applies @p@ to it
-- at the next step, where the sum needs it (the composition would store
-- the unevaluated @p a@ and evaluate it there: the same value, evaluated
-- at the same step, without the thunk); its output is @q@ of the running
-- sum, lazily, @q 0@ at time 0. Inlined only late (phase 1), so that the
-- rules below see it; once inlined, GHC compiles the step with @p@ and
-- @q@ in place.
--
-- Two details keep it what the composition is:
--
-- * The time-0 output is @q@ applied to a zero that GHC cannot see as a
--   constant ('GHC.Exts.noinline' of @const 0 a0@): otherwise @q 0@,
--   a closed expression once inlined, would be floated out as one value
--   shared by every run for the life of the program (a leak when @q@
--   builds a large structure), and GHC could fold @0 + k@ to @k@, which
--   IEEE arithmetic does not allow for @k = -0@.
-- * A step that is replayed (the step a 'AFRP.Switch.kSwitch' interrupted,
--   replayed by its continuation) applies @p@ again, where the
--   composition's stored thunk would be evaluated once: the same value,
--   computed twice, on that one step.
integralDOn :: (a -> Double) -> (Double -> b) -> SF a b
integralDOn p q = SF (initN (\a0 -> case go 0 a0 of !n -> (# n, q (noinline const 0 a0) #)))
  where
    go !acc prev = NStep (\dt a ->
      let !acc' = acc + dt * p prev
      in case go acc' a of !n -> (# n, q acc' #))
{-# INLINE [1] integralDOn #-}

-- The functions next to an 'integral' at 'Double', where GHC can see them
-- (written in the source, as in @arr p >>> integral >>> arr q@, the
-- notes' odometry and any PID controller, or exposed by inlining), are
-- made part of one 'integralDOn' node: @integral@ is @integralDOn id id@,
-- and @arr f >>> integralDOn p q = integralDOn (p . f) q@, @integralDOn p
-- q >>> arr g = integralDOn p (g . q)@, alone or at the head of a chain
-- (@... >>> sf@), with the laziness of the compositions (see
-- 'integralDOn'). An 'integral' with no function next to it stays the
-- specialised node 'NIntD', which the switches and 'AFRP.Parallel.parB'
-- step in place.
{-# RULES
"AFRP arr>>>integral" forall f.
  compSF integralDouble (arrSF f) = integralDOn (\a -> f a) (\c -> c)
"AFRP arr>>>integral>>>sf" forall f h.
  compSF (compSF h integralDouble) (arrSF f) = compSF h (integralDOn (\a -> f a) (\c -> c))
"AFRP integral>>>arr" forall g.
  compSF (arrSF g) integralDouble = integralDOn (\a -> a) (\c -> g c)
"AFRP integral>>>arr>>>sf" forall g h.
  compSF (compSF h (arrSF g)) integralDouble = compSF h (integralDOn (\a -> a) (\c -> g c))
"AFRP arr>>>integralDOn" forall f p q.
  compSF (integralDOn p q) (arrSF f) = integralDOn (\a -> p (f a)) q
"AFRP arr>>>integralDOn>>>sf" forall f p q h.
  compSF (compSF h (integralDOn p q)) (arrSF f) = compSF h (integralDOn (\a -> p (f a)) q)
"AFRP integralDOn>>>arr" forall g p q.
  compSF (arrSF g) (integralDOn p q) = integralDOn p (\c -> g (q c))
"AFRP integralDOn>>>arr>>>sf" forall g p q h.
  compSF (compSF h (arrSF g)) (integralDOn p q) = compSF h (integralDOn p (\c -> g (q c)))
  #-}

-- | The "immediate" integral from a given initial value, by the right
-- rectangle rule: @y0@ at time 0; at each later sample the previous output
-- plus the time step times the /current/ input.
--
-- > embed (imIntegral 10) (1, [(0.5, Just 2), (0.5, Just 3)])  ==  [10, 11, 12.5]
imIntegral :: VectorSpace a s => a -> SF a a
imIntegral y0 = SF (initN (\_ -> (# go y0, y0 #)))
  where
    -- The sum is forced at the next sample (or when the output is
    -- demanded), so the current input is not evaluated before then.
    go acc = NStep (\dt a -> case acc of
      !s -> let acc' = s ^+^ realToFrac dt *^ a in (# go acc', acc' #))
{-# INLINABLE imIntegral #-}

-- | The integral by the trapezoid rule: 0 at time 0; then the previous
-- output plus the time step times the mean of the previous and current
-- inputs. Exact for piecewise-linear inputs.
trapezoidIntegral :: VectorSpace a s => SF a a
trapezoidIntegral = SF (initN (\a0 -> case go zeroVector a0 of !n -> (# n, zeroVector #)))
  where
    -- As in 'imIntegral', the sum is forced at the next sample.
    go acc prev = NStep (\dt a -> case acc of
      !s -> let acc' = s ^+^ (realToFrac dt / 2) *^ (prev ^+^ a) in (# go acc' a, acc' #))
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
derivative = SF (initN (\a0 -> (# go a0, zeroVector #)))
  where
    -- The previous sample is evaluated only now, the current one only if
    -- the output is demanded (or at the next sample).
    go prev = NStep (\dt a -> case prev of
      !p -> (# go a, (a ^-^ p) ^/ realToFrac dt #))
{-# INLINABLE derivative #-}

-- | @iterFrom f b0@ outputs @b0@ at the first sample (local time 0) and
-- then, at each sample, @f aPrev a dt b@, from the previous input @aPrev@,
-- the current input @a@, the time step @dt@ between them and the previous
-- output @b@: a custom integration rule ('trapezoidIntegral' is one).
--
-- > embed (iterFrom (\a a' dt v -> v + dt * (a + a') / 2) 0) (0, [(1, Just 2), (1, Just 2)])  ==  [0, 1, 3]
iterFrom :: (a -> a -> DTime -> b -> b) -> b -> SF a b
iterFrom f b0 = SF (initN (\a0 -> (# go a0 b0, b0 #)))
  where
    -- the previous output is evaluated at the start of the next step (the
    -- input is never evaluated here): no chain of thunks, however long
    go aPrev b = NStep (\dt a -> case b of
      !bv -> let b' = f aPrev a dt bv in (# go a b', b' #))
