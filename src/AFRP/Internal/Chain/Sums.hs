{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE MagicHash     #-}
-- |
-- Module      : AFRP.Internal.Chain.Sums
-- Description : A run of integrals in a chain as one unboxed array of
--               running sums, and the loops that step it.
--
-- Internal, part of "AFRP.Internal.Chain", whose stepper steps a run with
-- the loops here and whose regrouping ("AFRP.Internal.Chain.Regroup")
-- makes the runs.
--
-- = Runs of integrals
--
-- Three or more integrals in series, each fed by the one before, are kept
-- after the chain's first step as one array of their running sums
-- ('AFRP.Internal.Chain.Stage.IRun'; 'AFRP.Internal.Chain.Stage.IRunF'
-- when functions stand between them, as in @integral >>> arr f >>>
-- integral@), stepped by one loop that writes a new array: one allocation
-- per step for the run instead of one cell per integral. The arithmetic
-- is the one the chain's other stages do ("AFRP.Internal.Chain", "The
-- identity it relies on"), stage by stage in the same order: the new sum
-- of the @i@-th is its old sum plus @dt@ times the old sum of the
-- @(i-1)@-th (of the integral before the run for the first), or times @f@
-- of it where a function @f@ stands before the @i@-th, applied at that
-- step as 'AFRP.Internal.Chain.Stage.IIntF' applies it; so the same bits.
-- The old array is never written: a chain may be stepped twice from the
-- same state (a signal function is a value), and each step gets its own.
-- A delay among the integrals is an entry of the run too, from the
-- chain's second step ("AFRP.Internal.Chain.Regroup"): its new entry is
-- its predecessor's old one.
--
-- = Inlined into the stepper
--
-- The loops ('stepSums', 'stepSumsF') and 'lastSum' are INLINE: the
-- chain's stepper, in another module, compiles each loop in place, as
-- one join point whose result goes straight into the run's new cell,
-- with no call and no box for the new 'Sums', the very code it had when
-- one module held them all (GHC inlined each there, as a function used
-- once; from another module, without the pragmas, it called
-- 'stepSumsF').
module AFRP.Internal.Chain.Sums
  ( -- * Running sums
    Sums
  , sumsList
  , sumsFromList
  , lastSum
  , stepSums
    -- * What each stage of a run is
  , Funs (..)
  , Kinds
  , kindsList
  , packKinds
  , stepSumsF
  ) where

import           GHC.Exts (ByteArray#, Double (..), Int (..), SmallArray#, indexDoubleArray#,
                           indexIntArray#, indexSmallArray#, newByteArray#, newSmallArray#,
                           sizeofByteArray#, unsafeFreezeByteArray#, unsafeFreezeSmallArray#,
                           writeDoubleArray#, writeIntArray#, writeSmallArray#, (*#), (*##), (+#),
                           (+##), (-#), (<#), isTrue#, quotInt#)
import           GHC.ST   (ST (..), runST)

-- | The running sums of a run of integrals, as an unboxed array of
-- 'Double's (never written once made).
data Sums = Sums ByteArray#

-- | The sums, in order (for tests and for joining runs).
sumsList :: Sums -> [Double]
sumsList (Sums a) = go 0#
  where
    n = sizeofByteArray# a `quotInt#` 8#
    go i | isTrue# (i <# n) = D# (indexDoubleArray# a i) : go (i +# 1#)
         | otherwise        = []

-- | The sums of a new run, in order.
sumsFromList :: [Double] -> Sums
sumsFromList xs = runST (ST (\s0 -> case newByteArray# (len *# 8#) s0 of
  (# s1, m #) -> case fill m 0# xs s1 of
    s2 -> case unsafeFreezeByteArray# m s2 of
      (# s3, a #) -> (# s3, Sums a #)))
  where
    !(I# len) = length xs
    fill m i ys s = case ys of
      []            -> s
      (D# y : rest) -> fill m (i +# 1#) rest (writeDoubleArray# m i y s)

-- | The last sum of a run: its output.
lastSum :: Sums -> Double
lastSum (Sums a) = D# (indexDoubleArray# a ((sizeofByteArray# a `quotInt#` 8#) -# 1#))
{-# INLINE lastSum #-}

-- | One step of a run fed by an integral whose sum was @old@ before this
-- step: @s'_0 = s_0 + dt * old@, @s'_i = s_i + dt * s_(i-1)@, in a new
-- array.
--
-- ('stepSumsF' with no function anywhere, written out: walking the list
-- of absent functions made network b take 41% more instructions:
-- valgrind, @throughput 0.02 b@, 78.0 M against 109.9 M. The three
-- lines that make and freeze the new array, the same in 'sumsFromList',
-- 'stepSums' and 'stepSumsF', stay written out too: passing the loop to
-- one inlined helper cost b 4% more instructions, @afrp-bench --run b
-- 300000@, 149.3 M against 143.2 M.)
stepSums :: Double -> Double -> Sums -> Sums
stepSums (D# dt) (D# old0) (Sums a) = runST (ST (\s0 -> case newByteArray# bytes s0 of
  (# s1, m #) -> case go m 0# old0 s1 of
    s2 -> case unsafeFreezeByteArray# m s2 of
      (# s3, a' #) -> (# s3, Sums a' #)))
  where
    bytes = sizeofByteArray# a
    n = bytes `quotInt#` 8#
    go m i old s
      | isTrue# (i <# n) =
          let acc = indexDoubleArray# a i
          in go m (i +# 1#) acc (writeDoubleArray# m i (acc +## (dt *## old)) s)
      | otherwise = s
{-# INLINE stepSums #-}

-- | The stages of an 'AFRP.Internal.Chain.Stage.IRunF', one entry per
-- stage, in order.
data Funs
  = FNil
  -- | An integral that sums its predecessor's output as it is.
  | FNone !Funs
  -- | An integral that sums @f@ of its predecessor's output.
  | FSome !(Double -> Double) !Funs
  -- | A delay: it outputs its predecessor's output of the last step.
  | FPre !Funs

-- | The stages of an 'AFRP.Internal.Chain.Stage.IRunF', packed for its
-- loop: one machine word per stage saying what it is (0: an integral
-- that sums its predecessor's output as it is, 1: one that sums @f@ of
-- it, 2: a delay), and the functions, each at the index of its stage.
-- The loop reads them without evaluating anything: walking a list of
-- 'Funs' instead, GHC checks at each stage that the next cell is
-- evaluated, saving and restoring the loop's variables around the check
-- (valgrind, @afrp-bench --run bi@: 5% more instructions once the list
-- had a fourth constructor).
data Kinds = Kinds ByteArray# (SmallArray# (Double -> Double))

-- | The stages of a packed run, as a list.
kindsList :: Kinds -> Funs
kindsList (Kinds ks fns) = go 0#
  where
    n = sizeofByteArray# ks `quotInt#` 8#
    go i
      | isTrue# (i <# n) = case indexIntArray# ks i of
          0# -> FNone (go (i +# 1#))
          1# -> case indexSmallArray# fns i of (# f #) -> FSome f (go (i +# 1#))
          _  -> FPre (go (i +# 1#))
      | otherwise = FNil

-- | The stages of a run, packed.
packKinds :: Funs -> Kinds
packKinds fs0 = runST (ST (\s0 -> case newByteArray# (len *# 8#) s0 of
  (# s1, mk #) -> case newSmallArray# len noFunction s1 of
    (# s2, mf #) -> case fill mk mf 0# fs0 s2 of
      s3 -> case unsafeFreezeByteArray# mk s3 of
        (# s4, ks #) -> case unsafeFreezeSmallArray# mf s4 of
          (# s5, fns #) -> (# s5, Kinds ks fns #)))
  where
    !(I# len) = count fs0
    count fs = case fs of
      FNil      -> 0 :: Int
      FNone r   -> 1 + count r
      FSome _ r -> 1 + count r
      FPre r    -> 1 + count r
    fill mk mf i fs s = case fs of
      FNil      -> s
      FNone r   -> fill mk mf (i +# 1#) r (writeIntArray# mk i 0# s)
      FSome f r -> case writeSmallArray# mf i f (writeIntArray# mk i 1# s) of
        s' -> fill mk mf (i +# 1#) r s'
      FPre r    -> fill mk mf (i +# 1#) r (writeIntArray# mk i 2# s)
    -- (the entry of a stage without a function, never called)
    noFunction x = x

-- | 'stepSums' for a run with functions before some of its integrals,
-- and delays among them: @f@ of the predecessor's old output where the
-- stage has one; a delay's new output is its predecessor's old one.
stepSumsF :: Double -> Double -> Sums -> Kinds -> Sums
stepSumsF (D# dt) (D# old0) (Sums a) (Kinds ks fns) = runST (ST (\s0 -> case newByteArray# bytes s0 of
  (# s1, m #) -> case go m 0# old0 s1 of
    s2 -> case unsafeFreezeByteArray# m s2 of
      (# s3, a' #) -> (# s3, Sums a' #)))
  where
    bytes = sizeofByteArray# a
    n = bytes `quotInt#` 8#
    go m i old s
      | isTrue# (i <# n) =
          let acc = indexDoubleArray# a i
          in case indexIntArray# ks i of
               0# -> go m (i +# 1#) acc (writeDoubleArray# m i (acc +## (dt *## old)) s)
               1# -> case indexSmallArray# fns i of
                 (# f #) -> case f (D# old) of
                   D# v -> go m (i +# 1#) acc (writeDoubleArray# m i (acc +## (dt *## v)) s)
               _  -> go m (i +# 1#) acc (writeDoubleArray# m i old s)
      | otherwise = s
{-# INLINE stepSumsF #-}
