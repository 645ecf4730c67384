{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Internal.Chain
-- Description : Runs of 'Double'-valued integrals and delays in series,
--               stepped as one node.
--
-- Internal, not part of the API (exposed for the library's own tests and
-- benchmarks).
--
-- = Why
--
-- A chain @integral >>> integral >>> ...@ stepped node by node costs, per
-- integral and per sample, a call of the generic stepper, a composition
-- node, an integral node and a boxed output, all rebuilt. Written out by
-- hand the same arithmetic is one addition and one multiplication per
-- integral. A /chain/ is such a run of stages kept as one strict list of
-- their states, stepped by one loop in which the values passed from an
-- integral to the next stay unboxed, and which rebuilds one small cell per
-- stage.
--
-- = The identity it relies on
--
-- An integral at 'Double' ('AFRP.Internal.Node.NIntD') stores its input
-- sample unevaluated and adds @dt * prev@ at the next step. Inside the
-- chain every stage is stepped at every step on its predecessor's output
-- of that step, so, from the chain's second step on, an integral whose
-- predecessor is an integral holds, as its previous input, exactly that
-- predecessor's previous output, which is the predecessor's running sum;
-- and one behind @integral >>> arr f@ holds the unevaluated @f@ of it,
-- which it evaluates at its next step. So these stages need not store
-- their input at all: at each step the chain computes @acc + dt * old@ (or
-- @acc + dt * f old@), where @old@ is the predecessor's running sum
-- /before/ this step: the same operations on the same numbers, in the
-- same order, so the same bits; @f@ is applied once per step, at the step
-- where the integral needed its value, as before. At the chain's first
-- step they use the previous input their integral nodes held ('IIntS',
-- 'IIntFS'): before the chain, the predecessor's last output need not
-- have been its sum (@(5 --> integral) >>> integral@ output 5, not the
-- sum 0, at time 0). The other stages (an integral after a
-- delay or at the head of the chain, a delay) store their input exactly
-- as their own nodes do, unevaluated. Nothing is evaluated earlier than it
-- was: the chain's input is stored and evaluated at the next step, the
-- output of a trailing delay is its stored value, unevaluated, and that of
-- a trailing integral its running sum, evaluated, as the nodes'.
module AFRP.Internal.Chain
  ( AfterI (..)
  , AfterL (..)
  , stepAfterL
  ) where

-- | The stages that follow an integral (whose running sum before and
-- after this step is known, evaluated).
data AfterI
  -- | The end of the chain: its output is the last integral's sum.
  = IEnd
  -- | An integral fed by the integral before it: its running sum.
  | IInt {-# UNPACK #-} !Double !AfterI
  -- | @arr f >>> integral@ fed by the integral before it: @f@ and the sum.
  | IIntF !(Double -> Double) {-# UNPACK #-} !Double !AfterI
  -- | A delay fed by an integral: the value it outputs at the next step
  -- (unevaluated, as 'AFRP.Delay.iPre' holds it).
  | IPre Double !AfterL
  -- | 'IInt' at the chain's first step: the running sum and the previous
  -- input its integral node held, used once; 'IInt' afterwards.
  | IIntS {-# UNPACK #-} !Double Double !AfterI
  -- | 'IIntF' at the chain's first step: @f@, the running sum and the
  -- previous input its integral node held (@f@ already applied,
  -- unevaluated), used once; 'IIntF' afterwards.
  | IIntFS !(Double -> Double) {-# UNPACK #-} !Double Double !AfterI

-- | The stages that follow the chain's input or a delay (whose output is
-- known only as an unevaluated value).
data AfterL
  -- | The end of the chain: its output is the delay's output.
  = LEnd
  -- | An integral that stores its input: its running sum and the previous
  -- input sample (unevaluated, as 'AFRP.Internal.Node.NIntD' holds it).
  | LInt {-# UNPACK #-} !Double Double !AfterI
  -- | @arr f >>> integral@ that stores its input: @f@, the running sum
  -- and @f@ of the previous input sample, unevaluated, as the integral of
  -- the composition holds it.
  | LIntF !(Double -> Double) {-# UNPACK #-} !Double Double !AfterI
  -- | A delay: the value it outputs at the next step (unevaluated).
  | LPre Double !AfterL

-- | One step of a chain whose first stage sees the input @a@ (stored, not
-- evaluated): its successor and its output.
stepAfterL :: Double -> Double -> AfterL -> (# AfterL, Double #)
stepAfterL !dt a c = case c of
  LEnd -> (# LEnd, a #)
  LInt acc prev rest ->
    -- y_n = y_(n-1) + dt_n * a_(n-1), as 'AFRP.Internal.Node.NIntD'
    let !acc' = acc + dt * prev
    in case stepAfterI dt acc acc' rest of
         (# rest', y #) -> case LInt acc' a rest' of !c' -> (# c', y #)
  LIntF f acc prev rest ->
    let !acc' = acc + dt * prev
    in case stepAfterI dt acc acc' rest of
         (# rest', y #) -> case LIntF f acc' (f a) rest' of !c' -> (# c', y #)
  LPre v rest -> case stepAfterL dt v rest of
    (# rest', y #) -> case LPre a rest' of !c' -> (# c', y #)

-- The stages after an integral whose sum was @old@ before this step and
-- is @new@ after it.
stepAfterI :: Double -> Double -> Double -> AfterI -> (# AfterI, Double #)
stepAfterI !dt !old !new c = case c of
  IEnd -> (# IEnd, new #)
  IInt acc rest ->
    let !acc' = acc + dt * old
    in case stepAfterI dt acc acc' rest of
         (# rest', y #) -> case IInt acc' rest' of !c' -> (# c', y #)
  IIntF f acc rest ->
    let !acc' = acc + dt * f old
    in case stepAfterI dt acc acc' rest of
         (# rest', y #) -> case IIntF f acc' rest' of !c' -> (# c', y #)
  IPre v rest -> case stepAfterL dt v rest of
    (# rest', y #) -> case IPre new rest' of !c' -> (# c', y #)
  IIntS acc prev rest ->
    let !acc' = acc + dt * prev
    in case stepAfterI dt acc acc' rest of
         (# rest', y #) -> case IInt acc' rest' of !c' -> (# c', y #)
  IIntFS f acc prev rest ->
    let !acc' = acc + dt * prev
    in case stepAfterI dt acc acc' rest of
         (# rest', y #) -> case IIntF f acc' rest' of !c' -> (# c', y #)
