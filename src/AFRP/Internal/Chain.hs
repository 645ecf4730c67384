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
--
-- = Delays among the integrals
--
-- A delay fed by an integral stores the integral's sum as its input
-- ('IPre'), evaluated, and outputs it at the next step: its output at
-- step @n@ is the integral's sum at step @n-1@, which is the @old@ the
-- chain's stepper is given at step @n@. So, like an integral fed by an
-- integral, it need not store its input; what the stages behind it need
-- is its output at the last step, the value they stored as their input.
-- From the chain's second step on, such a delay is a stage that keeps its
-- output at the last step ('IPreI'; 'FPre' in a run): at each step its
-- output is its predecessor's output at the last step, and the stages
-- behind it see it as they see an integral, @old@ being its last output
-- and @new@ its output now. In a run, where each entry holds its stage's
-- output at the last step, a delay's new entry is its predecessor's old
-- one. The change is made once, at the chain's second step ('settleL'),
-- because only then is every delay's output one the chain itself stored,
-- evaluated: at the first step a delay outputs the value its node held,
-- which may be unevaluated (an initial value, or an output of a
-- stage before the chain formed), and making it an entry would evaluate
-- it one step earlier than the integral behind it would. A delay
-- behind a delay stays as it is for the same reason. The same values in
-- the same order: the same bits, nothing evaluated earlier.
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

import           GHC.Exts (ByteArray#, Double (..), Int (..), SmallArray#, indexDoubleArray#,
                           indexIntArray#, indexSmallArray#, newByteArray#, newSmallArray#,
                           sizeofByteArray#, unsafeFreezeByteArray#, unsafeFreezeSmallArray#,
                           writeDoubleArray#, writeIntArray#, writeSmallArray#, (*#), (*##), (+#),
                           (+##), (-#), (<#), isTrue#, quotInt#)
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
  -- 'IIntF' stages), and, from the chain's second step, delays among
  -- them ('IPreI'): each stage's output at the last step, and for each,
  -- in order, what it is ('Funs', packed as 'Kinds').
  | IRunF !Sums !Kinds !AfterI
  -- | A delay fed by an integral (or by a stage of this form), from the
  -- chain's second step on: its output at the last step, evaluated (see
  -- "Delays among the integrals"). Its output at this step is its
  -- predecessor's output at the last step, which the stepper is given.
  | IPreI {-# UNPACK #-} !Double !AfterI

-- | The stages of an 'IRunF', one entry per stage, in order.
data Funs
  = FNil
  -- | An integral that sums its predecessor's output as it is.
  | FNone !Funs
  -- | An integral that sums @f@ of its predecessor's output.
  | FSome !(Double -> Double) !Funs
  -- | A delay: it outputs its predecessor's output of the last step.
  | FPre !Funs

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
  -- a delay fed by an integral outputs the integral's sum before this step
  IPreI lastOut rest -> case stepAfterI dt lastOut old rest of
    (# rest', y #) -> case IPreI old rest' of !c' -> (# c', y #)

-- An integral (its running sum, and the function before it, if any) in
-- front of the stages that follow it, after the chain's first step:
-- grouped with the integrals in series behind it ('groupEntries', as
-- 'settleL' groups them; the delays wait for the second step), three or
-- more as one run, fewer as cells of their own. (A run starts at three
-- integrals: for two, the array and the run's cell allocate more than the
-- two cells they replace.)
consInt :: Maybe (Double -> Double) -> Double -> AfterI -> AfterI
consInt mf acc c = case entriesI Nothing c of
  (es, rest) -> groupEntries (maybe (EInt acc) (\f -> EIntF f acc) mf : es) rest

-- | Whether a chain has a delay fed by an integral ('IPre'), which
-- 'settleL' makes a stage of its own kind at the chain's second step.
hasDelayI :: AfterL -> Bool
hasDelayI c = case c of
  LEnd          -> False
  LInt _ _ r    -> afterI r
  LIntF _ _ _ r -> afterI r
  LPre _ r      -> hasDelayI r
  where
    afterI x = case x of
      IEnd           -> False
      IPre _ _       -> True
      IInt _ r       -> afterI r
      IIntF _ _ r    -> afterI r
      IIntS _ _ r    -> afterI r
      IIntFS _ _ _ r -> afterI r
      IRun _ r       -> afterI r
      IRunF _ _ r    -> afterI r
      IPreI _ r      -> afterI r

-- | @settleL pre post@, where @post@ is the successor of @pre@ at the
-- chain's second step: @post@ with each delay fed by an integral made an
-- 'IPreI' (its output at this step is what @pre@ held), the stages it
-- feeds (which stored that output as their input) made stages fed by it
-- ('IInt', 'IIntF', 'IPre'), and the integrals and delays in series
-- regrouped, three or more as one run ('IRun', 'IRunF'). The same
-- stages, so the same steps (see "Delays among the integrals").
settleL :: AfterL -> AfterL -> AfterL
settleL pre post = case (pre, post) of
  (LInt _ _ p, LInt acc prev q)       -> LInt acc prev (settleI p q)
  (LIntF _ _ _ p, LIntF f acc prev q) -> LIntF f acc prev (settleI p q)
  (LPre _ p, LPre v q)                -> LPre v (settleL p q)
  _                                   -> post

-- The stages after an integral, settled.
settleI :: AfterI -> AfterI -> AfterI
settleI pre post = case entriesI (Just pre) post of
  (es, rest) -> groupEntries es rest

-- A stage of a run, as 'settleL' collects them: its output at the last
-- step and what it is.
data Entry = EInt !Double | EIntF !(Double -> Double) !Double | EPre !Double

-- The longest series of integrals and delays at the head of the stages
-- after an integral (before and after this step), and what follows it.
entriesI :: Maybe AfterI -> AfterI -> ([Entry], AfterI)
entriesI mpre post = case post of
  IInt acc q    -> more [EInt acc] q
  IIntF f acc q -> more [EIntF f acc] q
  IRun s q      -> more (map EInt (sumsList s)) q
  IRunF s ks q  -> more (funEntries (sumsList s) (kindsList ks)) q
  IPreI out q   -> more [EPre out] q
  -- given the state before the chain's second step: the delay's output
  -- at this step is what it held before it, which the chain's first step
  -- stored there, evaluated
  IPre _ q | Just (IPre out p) <- mpre -> withEntries [EPre out] (entriesL p q)
  _             -> ([], post)
  where
    more es q = withEntries es (entriesI (mpre >>= restOf) q)
    restOf pre = case pre of
      IInt _ p    -> Just p
      IIntF _ _ p -> Just p
      IRun _ p    -> Just p
      IRunF _ _ p -> Just p
      IPreI _ p   -> Just p
      _           -> Nothing
    funEntries ss fs = case (ss, fs) of
      (x : xs, FNone r)   -> EInt x : funEntries xs r
      (x : xs, FSome f r) -> EIntF f x : funEntries xs r
      (x : xs, FPre r)    -> EPre x : funEntries xs r
      _                   -> []

-- The same for the stages after a delay that 'settleL' makes an 'IPreI':
-- each held that delay's output at this step as its input, which the
-- 'IPreI' gives them as its last output.
entriesL :: AfterL -> AfterL -> ([Entry], AfterI)
entriesL pre post = case (pre, post) of
  (LInt _ _ p, LInt acc _ q)       -> withEntries [EInt acc] (entriesI (Just p) q)
  (LIntF _ _ _ p, LIntF f acc _ q) -> withEntries [EIntF f acc] (entriesI (Just p) q)
  _                                -> ([], fedByDelay post)
  where
    -- (a delay behind a delay keeps its value: what it output at this
    -- step, which it would report as its last output, may still be
    -- unevaluated)
    fedByDelay c = case c of
      LEnd             -> IEnd
      LInt acc _ q     -> IInt acc q
      LIntF f acc _ q  -> IIntF f acc q
      LPre v q         -> IPre v q

withEntries :: [Entry] -> ([Entry], AfterI) -> ([Entry], AfterI)
withEntries es (es', rest) = (es ++ es', rest)

-- Stages in series: three or more as one run, fewer as cells.
groupEntries :: [Entry] -> AfterI -> AfterI
groupEntries es rest = case es of
  (_ : _ : _ : _)
    | all plain es -> IRun (sumsFromList (map out es)) rest
    | otherwise    -> IRunF (sumsFromList (map out es)) (packKinds (foldr kind FNil es)) rest
  _                -> foldr cell rest es
  where
    plain e = case e of
      EInt _ -> True
      _      -> False
    out e = case e of
      EInt x    -> x
      EIntF _ x -> x
      EPre x    -> x
    kind e r = case e of
      EInt _    -> FNone r
      EIntF f _ -> FSome f r
      EPre _    -> FPre r
    cell e r = case e of
      EInt x    -> IInt x r
      EIntF f x -> IIntF f x r
      EPre x    -> IPreI x r

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
-- valgrind, `throughput 0.02 b`, 78.0 M against 109.9 M. The three
-- lines that make and freeze the new array, the same in 'sumsFromList',
-- 'stepSums' and 'stepSumsF', stay written out too: passing the loop to
-- one inlined helper cost b 4% more instructions, `afrp-bench --run b
-- 300000`, 149.3 M against 143.2 M.)
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

-- | The stages of an 'IRunF', packed for its loop: one machine word per
-- stage saying what it is (0: an integral that sums its predecessor's
-- output as it is, 1: one that sums @f@ of it, 2: a delay), and the
-- functions, each at the index of its stage. The loop reads them without
-- evaluating anything: walking a list of 'Funs' instead, GHC checks at
-- each stage that the next cell is evaluated, saving and restoring the
-- loop's variables around the check (valgrind, @afrp-bench --run bi@: 5%
-- more instructions once the list had a fourth constructor).
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

-- The same for a run with functions before some of its integrals, and
-- delays among them: @f@ of the predecessor's old output where the stage
-- has one; a delay's new output is its predecessor's old one.
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
