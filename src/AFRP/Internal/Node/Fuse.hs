{-# LANGUAGE GADTs         #-}
{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Internal.Node.Fuse
-- Description : The nodes that stand for several: a pair of integrals,
--               a run of integrals and delays.
--
-- Internal, part of "AFRP.Internal.Node", whose stepper
-- ('AFRP.Internal.Node.stepN') makes these where it meets the shapes they
-- replace, once those have been stepped, and whose design notes say what
-- each saves. Two kinds, each stated with the identity it relies on:
-- @integral *** integral@ at 'Double', with the functions around it, as
-- one node holding its input pair unevaluated ('int2On', 'fuseInt2'); and
-- a run of integrals and delays at 'Double' as one chain node
-- ('chainN', stepped by "AFRP.Internal.Chain"; the stepper collects the
-- run).
module AFRP.Internal.Node.Fuse
  ( -- * A pair of integrals
    int2On
  , int2OnPair
  , fuseInt2
    -- * Runs of integrals and delays
  , chainN
  ) where

import           AFRP.Internal.Chain
import           AFRP.Internal.Node.Build
import           AFRP.Internal.Node.FunD

------------------------------------------------------------------------------
-- A pair of integrals

-- | @int2On p s1 s2 prev@ is @arr p >>> (integral *** integral)@ at
-- 'Double' after a step, as one node: the two running sums and the
-- previous input sample as it came, unevaluated. The nodes would hold two
-- selectors of the unevaluated @p prev@, evaluated at this step, where
-- the sums need them; this node applies @p@ at this step instead, and
-- takes the pair apart: the same values, evaluated at the same step, with
-- the same sums @y_n = y_(n-1) + dt_n * a_(n-1)@, without the three
-- thunks (and without the pair's two nodes, rebuilt at every step). A
-- step that is replayed ('AFRP.Internal.Deferred.freezeN') applies @p@ again: the same value,
-- computed twice, on that one step.
int2On :: (c -> (Double, Double)) -> Double -> Double -> c -> Node c (Double, Double)
int2On p !s1 !s2 prev = NStep (\dt a -> case p prev of
  (x, z) -> let !s1' = s1 + dt * x
                !s2' = s2 + dt * z
            in (# int2On p s1' s2' a, (s1', s2') #))

-- | @integral *** integral@ at 'Double' after its step in place
-- ('AFRP.Internal.Node.stepN'): 'int2On' with the identity in front.
-- Defined here, beside 'int2On', so that GHC specialises 'int2On' to the
-- identity (the specialisation sees only the calls in 'int2On''s own
-- module): the node takes the pair apart without a thunk of @id prev@.
int2OnPair :: Double -> Double -> (Double, Double) -> Node (Double, Double) (Double, Double)
int2OnPair s1 s2 prev = int2On (\p -> p) s1 s2 prev

-- | @fuseInt2 p g@ is @Just@ @arr p >>> g@ as one 'int2On' node (followed
-- by the rest of the spine) when @g@ is @integral *** integral@ at
-- 'Double' after its first step, alone or at the head of a composition,
-- and 'Nothing' otherwise. The fused node's first step uses the previous
-- inputs the two integral nodes hold (selectors of @p@ of the previous
-- input, unevaluated): the same sums as the pair's step. The tests are
-- inlined into 'AFRP.Internal.Node.stepN', the building ('fuseInt2Out')
-- is not, so that the stepper's code does not grow (inlined, it slowed
-- network c by 5%).
fuseInt2 :: (a -> c) -> Node c b -> Maybe (Node a b)
fuseInt2 p g = case g of
  NPar (NIntD _ _) (NIntD _ _)            -> Just (fuseInt2Out p g)
  NComp (NPar (NIntD _ _) (NIntD _ _)) _ -> Just (fuseInt2Out p g)
  _                                       -> Nothing
{-# INLINE fuseInt2 #-}

-- @arr p >>> g@ with the pair of integrals at the head of @g@ made one
-- node; any other @g@ (never passed) is left as the composition.
fuseInt2Out :: (a -> c) -> Node c b -> Node a b
fuseInt2Out p g = case g of
  NPar (NIntD acc1 prev1) (NIntD acc2 prev2) -> int2S p acc1 prev1 acc2 prev2
  -- with a function behind the pair, taken into the node ('int2OnQ')
  NComp (NPar (NIntD acc1 prev1) (NIntD acc2 prev2)) (NPure (FDG q)) ->
    int2SQ p q acc1 prev1 acc2 prev2
  NComp (NPar (NIntD acc1 prev1) (NIntD acc2 prev2)) (NComp (NPure (FDG q)) rest) ->
    NComp (int2SQ p q acc1 prev1 acc2 prev2) rest
  NComp (NPar (NIntD acc1 prev1) (NIntD acc2 prev2)) rest ->
    NComp (int2S p acc1 prev1 acc2 prev2) rest
  _ -> NComp (NPure (FDG p)) g
{-# NOINLINE fuseInt2Out #-}

-- | @int2OnQ p q s1 s2 prev@ is @int2On p s1 s2 prev >>> arr q@ as one
-- node: its output is @q@ of the pair of sums, applied lazily, as the
-- composition applies the function behind a stateful node (the same
-- value, without the pair's boxes, the composition node and its step).
int2OnQ :: (c -> (Double, Double)) -> ((Double, Double) -> b) -> Double -> Double -> c
        -> Node c b
int2OnQ p q !s1 !s2 prev = NStep (\dt a -> case p prev of
  (x, z) -> let !s1' = s1 + dt * x
                !s2' = s2 + dt * z
            in (# int2OnQ p q s1' s2' a, q (s1', s2') #))

-- The first step of a fused pair with a function behind it.
int2SQ :: (a -> (Double, Double)) -> ((Double, Double) -> b) -> Double -> Double -> Double
       -> Double -> Node a b
int2SQ p q !acc1 prev1 !acc2 prev2 = NStep (\dt a ->
  let !s1 = acc1 + dt * prev1
      !s2 = acc2 + dt * prev2
  in (# int2OnQ p q s1 s2 a, q (s1, s2) #))

-- The first step of a fused pair: the previous inputs held by the nodes.
int2S :: (a -> (Double, Double)) -> Double -> Double -> Double -> Double
      -> Node a (Double, Double)
int2S p !acc1 prev1 !acc2 prev2 = NStep (\dt a ->
  let !s1 = acc1 + dt * prev1
      !s2 = acc2 + dt * prev2
  in (# int2On p s1 s2 a, (s1, s2) #))

------------------------------------------------------------------------------
-- Runs of integrals and delays

-- | A chain as a node: its first step; then, if it has delays fed by
-- integrals, its second step, after which they are stages of the runs
-- ('settleL'); then every later step. (Three near-copies on purpose: one
-- stepper taking what follows the step as a function, inlined, cost 3%
-- more instructions on `afrp-bench --run b 300000`.)
chainN :: AfterL -> Node Double Double
chainN c = NStep (\dt a -> case stepAfterL dt a c of
  (# c', y #) -> case (if hasDelayI c' then chainSettleN c' else chainRunN c') of
    !n -> (# n, y #))

chainSettleN :: AfterL -> Node Double Double
chainSettleN c = NStep (\dt a -> case stepAfterL dt a c of
  (# c', y #) -> case settleL c c' of
    !c'' -> case chainRunN c'' of !n -> (# n, y #))

chainRunN :: AfterL -> Node Double Double
chainRunN c = NStep (\dt a -> case stepAfterL dt a c of
  (# c', y #) -> case chainRunN c' of !n -> (# n, y #))
