{-# LANGUAGE GADTs          #-}
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
-- > embed integral (1 :: Double, [(0.5, Just 2), (0.5, Just 3)])  ==  [0, 0.5, 1.5]
integral :: VectorSpace a s => SF a a
integral = SF (initN (\a0 -> case go zeroVector a0 of !n -> (# n, zeroVector #)))
  where
    go !acc prev = NStep (\dt a ->
      let !acc' = acc ^+^ realToFrac dt *^ prev
      in case go acc' a of !n -> (# n, acc' #))
{-# INLINABLE [1] integral #-}

-- At 'Double', 'integral' is the specialised node 'NIntD', which computes
-- the same sums (@acc + dt * prev@) without a closure per step; the
-- rewrite rules below first make it an 'integralsD', so that the functions
-- and integrals next to it, where GHC sees them, join it.
{-# RULES "integral/Double" integral = integralsD FDI MNil FDI #-}

-- | 'integral' at 'Double'.
integralDouble :: SF Double Double
integralDouble = SF (initN (\a0 -> (# NIntD 0 a0, 0 #)))
{-# NOINLINE integralDouble #-}

-- | @integralDOn p q@ is @arr p >>> integral >>> arr q@ at 'Double', as
-- one node: it stores its input sample as it comes and applies @p@ to it
-- at the next step, where the sum needs it (the composition would store
-- the unevaluated @p a@ and evaluate it there: the same value, evaluated
-- at the same step, without the thunk); its output is @q@ of the running
-- sum, lazily, @q 0@ at time 0. Inlined only late (phase 1), after the
-- rules below have made it; once inlined, GHC compiles the step with @p@
-- and @q@ in place.
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

-- | The functions between the integrals of an 'integralsD', in order:
-- the identity where two integrals meet directly.
data Mids = MNil | MCons !(FunD Double Double) Mids

-- | @integralsD p fs q@ is integrals at 'Double' in series, with @p@
-- before the first, @q@ behind the last, and the functions @fs@ between
-- them: @integralsD p [f1, f2] q = arr p >>> integral >>> arr f1 >>>
-- integral >>> arr f2 >>> integral >>> arr q@. The rewrite rules build it
-- from the integrals and functions that GHC sees composed, in either
-- order; inlined late (phase 1), it is one 'integralDOn' node when it
-- holds one integral with functions next to it, 'integralDouble' when it
-- holds a lone integral, and otherwise the composition itself, built as
-- nodes: the run-time chains ("AFRP.Internal.Chain") see every integral
-- of it, where 'integralDOn' nodes, each opaque, would cut it into
-- single integrals. A function between two integrals is one function,
-- composed where GHC sees both halves.
integralsD :: FunD a Double -> Mids -> FunD Double b -> SF a b
integralsD p fs q = case fs of
  MNil -> case (p, q) of
    (FDI, FDI) -> integralDouble
    _          -> integralDOn (fdFun p) (fdFun q)
  _    -> SF (compN (NPure p) (integralsNodes fs q))
-- (CONLIKE: a binding @myInt = integral@ used more than once is not
-- copied into its uses before phase 1, where the rules are over; CONLIKE
-- lets the rules look through it, as they looked through the plain name
-- 'integralDouble' the rule "integral/Double" used to give.)
{-# INLINE CONLIKE [1] integralsD #-}

-- The integrals of an 'integralsD' with more than one, as nodes.
integralsNodes :: Mids -> FunD Double b -> Node Double b
integralsNodes fs q = case fs of
  MNil       -> compN (sfNode integralDouble) (NPure q)
  MCons f fs' -> compN (sfNode integralDouble) (compN (NPure f) (integralsNodes fs' q))

-- @f@ in front of a function: @arr f >>> arr p@.
preFD :: (a -> c) -> FunD c Double -> FunD a Double
preFD f p = FDG (\a -> fdFun p (f a))
{-# INLINE preFD #-}

-- @g@ behind a function: @arr q >>> arr g@.
postFD :: FunD Double b -> (b -> c) -> FunD Double c
postFD q g = FDG (\c -> g (fdFun q c))
{-# INLINE postFD #-}

-- What stands between two integrals: @arr q >>> arr p@, the identity if
-- both are.
midFD :: FunD Double b -> FunD b Double -> FunD Double Double
midFD q p = case q of
  FDI -> p
  _   -> case p of
    FDI -> q
    _   -> FDG (\c -> fdFun p (fdFun q c))
{-# INLINE midFD #-}

-- @fs ++ (m : gs)@, made at compile time where @fs@ is known.
joinMids :: Mids -> FunD Double Double -> Mids -> Mids
joinMids fs m gs = case fs of
  MNil       -> MCons m gs
  MCons f r  -> MCons f (joinMidsRec r m gs)
{-# INLINE joinMids #-}

joinMidsRec :: Mids -> FunD Double Double -> Mids -> Mids
joinMidsRec fs m gs = case fs of
  MNil       -> MCons m gs
  MCons f r  -> MCons f (joinMidsRec r m gs)

-- The functions and integrals next to an 'integral' at 'Double', where GHC
-- can see them (written in the source, as in @arr p >>> integral >>> arr
-- q@, the notes' odometry, any PID controller, @integral >>> arr f >>>
-- integral@, or exposed by inlining), are made part of one 'integralsD':
-- @arr f >>> integralsD p fs q = integralsD (p . f) fs q@, @integralsD p
-- fs q >>> arr g = integralsD p fs (g . q)@, and two 'integralsD' in
-- series are one, with the functions where they meet composed; each alone
-- or at the head of a chain (@... >>> sf@), with the laziness of the
-- compositions (see 'integralDOn' and 'integralsD'). An 'integral' with
-- nothing next to it stays the specialised node 'NIntD', which the
-- switches and 'AFRP.Parallel.parB' step in place.
{-# RULES
"AFRP arr>>>integrals" forall f p fs q.
  compSF (integralsD p fs q) (arrSF f) = integralsD (preFD f p) fs q
"AFRP arr>>>integrals>>>sf" forall f p fs q h.
  compSF (compSF h (integralsD p fs q)) (arrSF f) = compSF h (integralsD (preFD f p) fs q)
"AFRP integrals>>>arr" forall g p fs q.
  compSF (arrSF g) (integralsD p fs q) = integralsD p fs (postFD q g)
"AFRP integrals>>>arr>>>sf" forall g p fs q h.
  compSF (compSF h (arrSF g)) (integralsD p fs q) = compSF h (integralsD p fs (postFD q g))
"AFRP integrals>>>integrals" forall p1 fs1 q1 p2 fs2 q2.
  compSF (integralsD p2 fs2 q2) (integralsD p1 fs1 q1) = integralsD p1 (joinMids fs1 (midFD q1 p2) fs2) q2
"AFRP integrals>>>integrals>>>sf" forall p1 fs1 q1 p2 fs2 q2 h.
  compSF (compSF h (integralsD p2 fs2 q2)) (integralsD p1 fs1 q1)
    = compSF h (integralsD p1 (joinMids fs1 (midFD q1 p2) fs2) q2)
  #-}

-- | The "immediate" integral from a given initial value, by the right
-- rectangle rule: @y0@ at time 0; at each later sample the previous output
-- plus the time step times the /current/ input.
--
-- > embed (imIntegral 10) (1 :: Double, [(0.5, Just 2), (0.5, Just 3)])  ==  [10, 11, 12.5]
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
-- impulse is added at the instant of its event: at time 0 the output is
-- the value of an impulse there (otherwise 'zeroVector').
impulseIntegral :: VectorSpace a k => SF (a, Event a) a
impulseIntegral = SF (compN (sfNode (integral *** accumHoldBy (^+^) zeroVector))
                            (arrN (uncurry (^+^))))

-- | Count events: the n-th occurrence of the input produces an occurrence
-- carrying @n@ (1 for the first; an occurrence at time 0 is counted
-- there).
count :: Integral b => SF (Event a) (Event b)
count = accumBy (\n _ -> n + 1) 0

-- | The derivative of the input: 'zeroVector' at time 0, then the
-- difference quotient of the current and previous samples. A zero time
-- step gives infinite or NaN components, as the arithmetic does.
--
-- > embed derivative (1 :: Double, [(0.5, Just 2), (0.5, Just 2)])  ==  [0, 2, 0]
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
