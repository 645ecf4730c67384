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
-- where the integral needed its value, as before (a step that is replayed,
-- the step a 'AFRP.Switch.kSwitch' interrupted, applies it again: the
-- same value computed twice on that step, where the node's stored thunk
-- was evaluated once, as for 'AFRP.Integration' @integralDOn@). At the chain's first
-- step they use the previous input their integral nodes held ('IIntS',
-- 'IIntFS'): before the chain, the predecessor's last output need not
-- have been its sum (@(5 --> integral) >>> integral@ output 5, not the
-- sum 0, at time 0). The other stages (an integral after a
-- delay or at the head of the chain, a delay) store their input exactly
-- as their own nodes do, unevaluated. Nothing is evaluated earlier than it
-- was: the chain's input is stored and evaluated at the next step, the
-- output of a trailing delay is its stored value, unevaluated, and that of
-- a trailing integral its running sum, evaluated, as the nodes'.
--
-- = Runs, and delays among them
--
-- After the chain's first step, three or more integrals in series are
-- one unboxed array of running sums, stepped by one loop
-- ("AFRP.Internal.Chain.Sums", which states why that gives the same
-- bits); from its second step, the delays fed by integrals are stages of
-- those runs too ("AFRP.Internal.Chain.Regroup", which says why not
-- earlier).
--
-- = Modules
--
-- This module holds the chain's stepper, and re-exports what the chain
-- node ("AFRP.Internal.Node.Fuse") and the node stepper that collects a
-- chain's stages ("AFRP.Internal.Node") use from the three modules it is
-- built on, each of which imports only those before it:
-- "AFRP.Internal.Chain.Sums" (a run's array of sums and the loops that
-- step it, inlined here), "AFRP.Internal.Chain.Stage" (the stages, as
-- the stepper keeps them) and "AFRP.Internal.Chain.Regroup" (the stages
-- regrouped into runs after the chain's first and second steps).
module AFRP.Internal.Chain
  ( AfterI (..)
  , AfterL (..)
  , Funs (..)
  , Kinds
  , kindsList
  , Sums
  , sumsList
  , stepAfterL
  , hasDelayI
  , settleL
  ) where

import           AFRP.Internal.Chain.Regroup (consInt, hasDelayI, settleL)
import           AFRP.Internal.Chain.Stage
import           AFRP.Internal.Chain.Sums    (Funs (..), Kinds, Sums, kindsList, lastSum, stepSums,
                                              stepSumsF, sumsList)

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
         (# rest', y #) -> case consInt Nothing acc' rest' of !c' -> (# c', y #)
  IRun sums rest -> case stepSums dt old sums of
    sums' -> case stepAfterI dt (lastSum sums) (lastSum sums') rest of
      (# rest', y #) -> case IRun sums' rest' of !c' -> (# c', y #)
  IRunF sums fs rest -> case stepSumsF dt old sums fs of
    sums' -> case stepAfterI dt (lastSum sums) (lastSum sums') rest of
      (# rest', y #) -> case IRunF sums' fs rest' of !c' -> (# c', y #)
  IIntFS f acc prev rest ->
    let !acc' = acc + dt * prev
    in case stepAfterI dt acc acc' rest of
         (# rest', y #) -> case consInt (Just f) acc' rest' of !c' -> (# c', y #)
  -- a delay fed by an integral outputs the integral's sum before this step
  IPreI lastOut rest -> case stepAfterI dt lastOut old rest of
    (# rest', y #) -> case IPreI old rest' of !c' -> (# c', y #)
