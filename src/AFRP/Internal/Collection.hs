{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE RankNTypes    #-}
{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE MagicHash     #-}
{-# LANGUAGE GADTs         #-}
-- |
-- Module      : AFRP.Internal.Collection
-- Description : How a collection of signal functions is stepped: the
--               steppers chosen by the collection's type, and @parB@ on a
--               list kept as an array (or as a bank of integrals).
--
-- Internal, not part of the API (exposed for the library's own tests and
-- benchmarks): the machinery behind "AFRP.Parallel", whose combinators
-- are written once, over a /stepper/: the function that steps a routed
-- collection, returning the successors and the (lazy) outputs in the
-- collection's shape. @stepColF@ works for any 'Functor' (each member
-- stepped when first demanded: a Functor cannot be walked); 'stepColL' is
-- the same function on lists, done in one strict pass with no
-- intermediate collections, every successor evaluated; @stepColT@ the
-- same on a 'Traversable' (used at 'Map.Map', 'IntMap.IntMap' and
-- 'Seq.Seq'). The public combinators take their stepper from
-- 'stepperFor', which is @stepColF@, and which rewrite rules (here,
-- beside it) replace wherever the collection's type is one of those four:
-- the combinators are inlined, so the rule sees the type at the user's
-- call. Each strict stepper computes the same collections as @stepColF@,
-- more evaluated:
--
-- > stepColL dt routed  ==  stepColF dt routed        (routed :: [(b, Node b c)])
-- > stepColT dt routed  ==  stepColF dt routed        (any Traversable)
--
-- and 'AFRP.Parallel.parB' on a list, which needs no routing at all, is
-- replaced by 'parBL' (by the rule beside 'AFRP.Parallel.parB', in
-- "AFRP.Parallel"):
--
-- > parBL sfs  ==  par broadcast sfs                  (sfs :: [SF a b])
--
-- Rules fire only where GHC optimises (not at -O0, not in GHCi) and only
-- where the type is known at the call (not in code generic over the
-- collection); elsewhere the combinators step on demand, as for any other
-- Functor.
--
-- 'parBL''s helpers (its array, the bank's test and steps) stay beside
-- it, unexported: GHC inlines a helper it sees used once into its user,
-- as when all of this was "AFRP.Parallel"; exported, they would stay
-- calls.
module AFRP.Internal.Collection
  ( -- * Steppers
    Stepper
  , stepperFor
  , stepColL
    -- * Broadcasting to a list
  , parBL
  ) where

import           GHC.Exts         (ByteArray#, Double (D#), Int (I#), SmallArray#,
                                   indexDoubleArray#, indexSmallArray#, isTrue#, newByteArray#,
                                   newSmallArray#, reallyUnsafePtrEquality#, runRW#,
                                   sizeofSmallArray#, thawSmallArray#, unsafeFreezeByteArray#,
                                   unsafeFreezeSmallArray#, writeDoubleArray#, writeSmallArray#,
                                   (*#), (*##), (+#), (+##), (-#), (<#), (==#), Int#, quotInt#,
                                   sizeofByteArray#)

import           Data.Foldable    (foldl')
import qualified Data.IntMap      as IntMap
import qualified Data.Map         as Map
import qualified Data.Sequence    as Seq

import           AFRP.Internal.SF

------------------------------------------------------------------------------
-- Steppers

-- | Steps a routed collection: successors (evaluated) and outputs (lazy).
type Stepper col = forall b c. DTime -> col (b, Node b c) -> (# col (Node b c), col c #)

-- | The stepper of a collection type: @stepColF@, replaced by the rules
-- below at lists, maps, int maps and sequences. Never inlined, so that
-- the rules can see it.
stepperFor :: Functor col => Stepper col
stepperFor = stepColF
{-# NOINLINE stepperFor #-}

-- | Step every member of any 'Functor': each member is stepped once, when
-- its successor or its output is first demanded (a Functor cannot be
-- walked).
stepColF :: Functor col => DTime -> col (b, Node b c) -> (# col (Node b c), col c #)
stepColF dt routed =
  let stepped = fmap (\(b, n) -> boxStep n dt b) routed
  in (# fmap (\(Boxed n _) -> n) stepped, fmap (\(Boxed _ c) -> c) stepped #)

-- | Step every member of a 'Traversable', evaluating every successor
-- node, so that no member accumulates suspended steps. The rules below
-- use it at the containers' 'Map.Map', 'IntMap.IntMap' and 'Seq.Seq',
-- which Yampa programs use as collections; it computes the same
-- collections as 'stepColF', more evaluated.
stepColT :: Traversable col => DTime -> col (b, Node b c) -> (# col (Node b c), col c #)
stepColT dt routed = case stepColF dt routed of
  (# nodes, cs #) -> foldl' (\_ x -> x `seq` ()) () nodes `seq` (# nodes, cs #)

stepMap :: Stepper (Map.Map k)
stepMap = stepColT

stepIntMap :: Stepper IntMap.IntMap
stepIntMap = stepColT

stepSeq :: Stepper Seq.Seq
stepSeq = stepColT

-- | @stepColF@ on lists, in one pass: the members are stepped in order,
-- each successor evaluated, the outputs left lazy.
stepColL :: DTime -> [(b, Node b c)] -> (# [Node b c], [c] #)
stepColL dt = go
  where
    go []              = (# [], [] #)
    go ((b, n) : rest) = case stepN n dt b of
      (# !n', c #) -> case go rest of
        (# ns', cs #) -> (# n' : ns', c : cs #)

-- The strict steppers, chosen by type (see the module's note).
{-# RULES
"stepperFor/list"   stepperFor = stepColL
"stepperFor/map"    stepperFor = stepMap
"stepperFor/intmap" stepperFor = stepIntMap
"stepperFor/seq"    stepperFor = stepSeq
  #-}

------------------------------------------------------------------------------
-- Broadcasting to a list

-- | 'parB' on a list: the members are kept in an array and stepped on the
-- input directly (see 'stepArrB'), with no routed collection in between
-- and no recursion as deep as the list is long.
--
-- Once every member is an 'AFRP.Integration.integral' at 'Double' that
-- has seen the same inputs (the usual bank of integrators, after its
-- first step), the members are kept as one unboxed array of running sums
-- instead ('integralBank'): the same sums, stepped without a node per
-- member.
--
-- A member that is not an integral node gives the bank up for good (one
-- look at each member until then, no allocation): members change only by
-- stepping, and an integral node stays one, so the bank can only have
-- been missed if a member becomes an integral later, through a switch.
parBL :: [SF a b] -> SF a [b]
parBL sfs = SF (go (arrayFromList (map sfNode sfs)))
  where
    go ns = NStep (\dt a -> case stepArrB dt a ns of
      (# ns', cs #) -> case bankOf ns' of
        Banked (Bank sums prev) -> case integralBank sums prev of !n -> (# n, cs #)
        NotYet                  -> case go ns' of !n -> (# n, cs #)
        Never                   -> case general ns' of !n -> (# n, cs #))
    general ns = NStep (\dt a -> case stepArrB dt a ns of
      (# ns', cs #) -> case general ns' of !n -> (# n, cs #))

-- Running sums of integrals at 'Double' that share their previous input.
data Bank a b where
  Bank :: ByteArray# -> Double -> Bank Double [Double]

-- Whether the members can be a bank.
data Banking a b = Banked (Bank a b) | NotYet | Never

-- The members as a bank, if every one is an integral node ('NIntD')
-- holding the very same previous input (one pointer: they were all
-- stepped on it); 'NotYet' if they are all integral nodes but have not
-- all seen the same input; 'Never' if one is not an integral node. Only
-- evaluated values are looked at: the nodes and their strict sums; the
-- shared input is compared by pointer, never evaluated. The sums are
-- copied only once the members have passed.
bankOf :: Arr (Node a b) -> Banking a [b]
bankOf (Arr sa)
  | isTrue# (n <# 1#) = Never
  | otherwise = case indexSmallArray# sa 0# of
      (# NIntD _ prev0 #) ->
        let check i
              | isTrue# (i ==# n) = Just ()
              | otherwise = case indexSmallArray# sa i of
                  (# NIntD _ prev #)
                    | isTrue# (reallyUnsafePtrEquality# prev prev0) -> check (i +# 1#)
                    | otherwise -> Nothing
                  _ -> Nothing
            allIntegrals i
              | isTrue# (i ==# n) = True
              | otherwise = case indexSmallArray# sa i of
                  (# NIntD _ _ #) -> allIntegrals (i +# 1#)
                  _               -> False
        in case check 1# of
          Nothing | allIntegrals 1# -> NotYet
                  | otherwise       -> Never
          Just () -> runRW# (\s0 -> case newByteArray# (n *# 8#) s0 of
            (# s1, m #) ->
              let copy i s
                    | isTrue# (i ==# n) = s
                    | otherwise = case indexSmallArray# sa i of
                        (# NIntD (D# acc) _ #) -> copy (i +# 1#) (writeDoubleArray# m i acc s)
                        _                      -> copy (i +# 1#) s  -- (checked above: not reached)
              in case unsafeFreezeByteArray# m (copy 0# s1) of
                (# _, sums #) -> Banked (Bank sums prev0))
      _ -> Never
  where
    !(I# n) = arrLength (Arr sa)

-- @integralBank sums prev@: the members of a 'parB' of integrals with the
-- given running sums and previous input, as one node. Each step is every
-- member's 'NIntD' step, @y_n = y_(n-1) + dt_n * a_(n-1)@ (the previous
-- input evaluated then, the current one kept unevaluated), with the
-- outputs in the members' order.
integralBank :: ByteArray# -> Double -> Node Double [Double]
integralBank sums prev = NStep (\dt a -> case prev of
  D# p -> case dt of
    D# d -> runRW# (\s0 -> case newByteArray# (n *# 8#) s0 of
      (# s1, m #) ->
        let fill i acc s
              | isTrue# (i <# 0#) = (# s, acc #)
              | otherwise =
                  let y = indexDoubleArray# sums i +## (d *## p)
                  in fill (i -# 1#) (D# y : acc) (writeDoubleArray# m i y s)
        in case fill (n -# 1#) [] s1 of
          (# s2, ys #) -> case unsafeFreezeByteArray# m s2 of
            (# _, sums' #) -> case integralBank sums' a of !node -> (# node, ys #)))
  where
    !n = bankSize sums

bankSize :: ByteArray# -> Int#
bankSize sums = quotInt# (sizeofByteArray# sums) 8#

-- Step every member of an array on the same input (for 'parBL'), each
-- successor evaluated: the successors (a new array) and the outputs (a
-- list). The members are stepped from the last to the first, so that
-- each output is consed onto the list of the ones after it as soon as it
-- is produced, with no array of outputs to collect them from afterwards.
-- The steps are pure and independent of each other, so their order is
-- not observable (which of several failing members is reported is not
-- specified, as for any pure code). The new array starts as a copy of
-- the old one (a block copy, cheaper than filling it with a placeholder)
-- and every element is overwritten.
stepArrB :: DTime -> b -> Arr (Node b c) -> (# Arr (Node b c), [c] #)
stepArrB dt b src@(Arr sa) = runRW# (\s0 ->
  case thawSmallArray# sa 0# n s0 of
    (# s1, dst #) ->
      let fill i acc s
            | isTrue# (i <# 0#) = (# s, acc #)
            | otherwise = case indexSmallArray# sa i of
                (# node #) -> case stepInline node dt b of
                  (# !node', c #) -> fill (i -# 1#) (c : acc) (writeSmallArray# dst i node' s)
      in case fill (n -# 1#) [] s1 of
        (# s2, cs #) -> case unsafeFreezeSmallArray# dst s2 of
          (# _, frozen #) -> (# Arr frozen, cs #))
  where
    !(I# n) = arrLength src

-- An immutable array of members.
data Arr a = Arr (SmallArray# a)

arrLength :: Arr a -> Int
arrLength (Arr a) = I# (sizeofSmallArray# a)

arrayFromList :: [a] -> Arr a
arrayFromList xs = runRW# (\s0 -> case newSmallArray# n undefElem s0 of
  (# s1, m #) ->
    let fill _ [] s       = s
        fill i (y : ys) s = fill (i +# 1#) ys (writeSmallArray# m i y s)
    in case unsafeFreezeSmallArray# m (fill 0# xs s1) of
      (# _, a #) -> Arr a)
  where
    !(I# n) = length xs

undefElem :: a
undefElem = error "AFRP.Internal.Collection: an array element that was never written"
