-- |
-- Module      : AFRP.Internal.Chain.Stage
-- Description : The stages of a chain, as its stepper keeps them.
--
-- Internal, part of "AFRP.Internal.Chain", which says what a chain is and
-- states the identity these stages rely on.
--
-- = Design
--
-- A chain is kept as one strict list of its stages' states, in two types
-- that say what the stage in front of them is: 'AfterI' follows an
-- integral (or a stage seen as one), whose running sum before and after
-- the step is known, evaluated, so that an integral fed by it need not
-- store its input; 'AfterL' follows the chain's input or a delay, whose
-- output is known only as an unevaluated value, so that an integral fed
-- by it stores its input, unevaluated, as its node did. The stages made for the
-- chain's first step only ('IIntS', 'IIntFS') are replaced after it, and
-- the delays fed by integrals ('IPre') after its second step
-- ("AFRP.Internal.Chain.Regroup"); the runs ('IRun', 'IRunF') hold
-- their sums in the arrays of "AFRP.Internal.Chain.Sums".
module AFRP.Internal.Chain.Stage
  ( AfterI (..)
  , AfterL (..)
  ) where

import           AFRP.Internal.Chain.Sums (Kinds, Sums)

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
  -- | Three or more integrals in series, the first fed by the integral
  -- before: their running sums, in order (see "AFRP.Internal.Chain.Sums").
  -- Made at the chain's first step from its 'IIntS' and 'IIntFS' stages.
  | IRun !Sums !AfterI
  -- | A run of integrals with functions before some of them ('IInt' and
  -- 'IIntF' stages), and, from the chain's second step, delays among
  -- them ('IPreI'): each stage's output at the last step, and for each,
  -- in order, what it is ('AFRP.Internal.Chain.Sums.Funs', packed as
  -- 'Kinds').
  | IRunF !Sums !Kinds !AfterI
  -- | A delay fed by an integral (or by a stage of this form), from the
  -- chain's second step on: its output at the last step, evaluated (see
  -- "AFRP.Internal.Chain.Regroup"). Its output at this step is its
  -- predecessor's output at the last step, which the stepper is given.
  | IPreI {-# UNPACK #-} !Double !AfterI

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
