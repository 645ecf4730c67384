{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE MagicHash     #-}
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
--
-- = Runs of integrals
--
-- Three or more integrals in series, each fed by the one before, are kept
-- after the chain's first step as one array of their running sums
-- ('IRun'; 'IRunF' when functions stand between them, as in @integral >>>
-- arr f >>> integral@), stepped by one loop that writes a new array: one
-- allocation per step for the run instead of one cell per integral. The
-- arithmetic is the one above, stage by stage in the same order: the new
-- sum of the @i@-th is its old sum plus @dt@ times the old sum of the
-- @(i-1)@-th (of the integral before the run for the first), or times @f@
-- of it where a function @f@ stands before the @i@-th, applied at that
-- step as 'IIntF' applies it; so the same bits. The old
-- array is never written: a chain may be stepped twice from the same
-- state (a signal function is a value), and each step gets its own.
module AFRP.Internal.Chain
  ( AfterI (..)
  , AfterL (..)
  , Funs (..)
  , Sums
  , sumsList
  , stepAfterL
  ) where

import           GHC.Exts (ByteArray#, Double (..), Int (..), indexDoubleArray#, newByteArray#,
                           sizeofByteArray#, unsafeFreezeByteArray#, writeDoubleArray#, (*#),
                           (*##), (+#), (+##), (-#), (<#), isTrue#, quotInt#)
import           GHC.ST   (ST (..), runST)

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
  -- before: their running sums, in order (see "Runs of integrals"). Made
  -- at the chain's first step from its 'IIntS' and 'IIntFS' stages.
  | IRun !Sums !AfterI
  -- | A run of integrals with functions before some of them ('IInt' and
  -- 'IIntF' stages): their running sums, and for each, in order, the
  -- function it applies to its predecessor's sum, if any.
  | IRunF !Sums !Funs !AfterI

-- | The functions before the integrals of an 'IRunF', one entry per
-- integral, in order.
data Funs
  = FNil
  -- | The integral sums its predecessor's sum as it is.
  | FNone !Funs
  -- | The integral sums @f@ of its predecessor's sum.
  | FSome !(Double -> Double) !Funs

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

-- An integral (its running sum, and the function before it, if any) in
-- front of the stages that follow it, after the chain's first step:
-- joined to the run that follows, or made a run with the integral that
-- follows, or a stage of its own.
-- (A run starts at three integrals: for two, the array and the run's
-- cell allocate more than the two cells they replace.)
consInt :: Maybe (Double -> Double) -> Double -> AfterI -> AfterI
consInt mf acc c = case c of
  IRun sums rest      -> run (acc : sumsList sums) (nones (sumsList sums)) rest
  IRunF sums fs rest  -> run (acc : sumsList sums) fs rest
  _ | Just (acc2, f2, acc3, f3, rest) <- twoInts c -> run [acc, acc2, acc3] (f2 (f3 FNil)) rest
  _                   -> maybe (IInt acc c) (\f -> IIntF f acc c) mf
  where
    twoInts x = case x of
      IInt a2 r     | Just (a3, f3, r') <- oneInt r -> Just (a2, FNone, a3, f3, r')
      IIntF g a2 r  | Just (a3, f3, r') <- oneInt r -> Just (a2, FSome g, a3, f3, r')
      _             -> Nothing
    oneInt x = case x of
      IInt a r    -> Just (a, FNone, r)
      IIntF g a r -> Just (a, FSome g, r)
      _           -> Nothing
    nones = foldr (const FNone) FNil
    run sums fs rest = case (mf, fs) of
      (Nothing, _) | allNone fs -> IRun (sumsFromList sums) rest
      _                         -> IRunF (sumsFromList sums) (maybe FNone FSome mf fs) rest
    allNone fs = case fs of
      FNil      -> True
      FNone r   -> allNone r
      FSome _ _ -> False

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

-- The last sum of a run.
lastSum :: Sums -> Double
lastSum (Sums a) = D# (indexDoubleArray# a ((sizeofByteArray# a `quotInt#` 8#) -# 1#))

-- ('stepSumsF' with no function anywhere, written out: walking the list
-- of absent functions made network b take 41% more instructions:
-- valgrind, `throughput 0.02 b`, 78.0 M against 109.9 M.)
--
-- One step of a run fed by an integral whose sum was @old@ before this
-- step: @s'_0 = s_0 + dt * old@, @s'_i = s_i + dt * s_(i-1)@, in a new
-- array.
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

-- The same for a run with functions before some of its integrals: @f@ of
-- the predecessor's old sum where the entry has one.
stepSumsF :: Double -> Double -> Sums -> Funs -> Sums
stepSumsF (D# dt) (D# old0) (Sums a) fs0 = runST (ST (\s0 -> case newByteArray# bytes s0 of
  (# s1, m #) -> case go m 0# old0 fs0 s1 of
    s2 -> case unsafeFreezeByteArray# m s2 of
      (# s3, a' #) -> (# s3, Sums a' #)))
  where
    bytes = sizeofByteArray# a
    go m i old fs s = case fs of
      FNil      -> s
      FNone r   ->
        let acc = indexDoubleArray# a i
        in go m (i +# 1#) acc r (writeDoubleArray# m i (acc +## (dt *## old)) s)
      FSome f r -> case f (D# old) of
        D# v -> let acc = indexDoubleArray# a i
                in go m (i +# 1#) acc r (writeDoubleArray# m i (acc +## (dt *## v)) s)
