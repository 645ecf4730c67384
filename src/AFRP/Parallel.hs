{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE RankNTypes    #-}
{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE MagicHash     #-}
{-# LANGUAGE GADTs         #-}
-- |
-- Module      : AFRP.Parallel
-- Description : Collections of signal functions running side by side, and
--               switching on the whole collection.
--
-- A collection is any 'Functor' container of signal functions (a list, a
-- 'Data.Map.Map', a 'Data.Sequence.Seq', a user's own type with only a
-- 'Functor' instance), as in Yampa. On lists (the common case) and on
-- the containers' 'Map.Map', 'IntMap.IntMap' and 'Seq.Seq' (rewrite rules
-- pick a specialised stepper), every member is stepped, and its state
-- evaluated, at every sample, even when nobody looks at its output, so the
-- collection never accumulates thunks. Any other collection can only be
-- mapped over, not walked: there, as in Yampa, a member is stepped when its
-- output or its successor is demanded, and a member whose output is never
-- demanded builds up one suspended step per sample.
--
-- The rules fire only where GHC optimises the call (@-O@; not at @-O0@,
-- not in GHCi) and sees the collection's type there (not in code generic
-- over the collection, such as a function of any @Functor col@ that calls
-- 'parB'). Elsewhere a list, a map or a sequence is stepped on demand too,
-- like any other collection: a member whose output nobody reads then keeps
-- one suspended step per sample (about 14 MB at 10^5 samples for two
-- members at @-O0@). Read every member's output, or call the combinators
-- where the collection's type is known, in optimised code.
--
-- Naming, as in Yampa: no suffix takes a /routing function/
-- @forall sf. a -> col sf -> col (b, sf)@ that decides what input each
-- member sees (the @forall@ guarantees it can pair inputs only with the
-- members it is given, never with signal functions of its own making; it
-- may still leave members out or use one twice, and the collection then
-- goes on with the members it returned, each copy stepped on its own, as
-- in Yampa: return each member once to keep the collection as it is);
-- @B@ /broadcasts/ the same input to every
-- member; @Z@ /zips/ a list of inputs with a list of members. The @p@
-- switches and their @d@ / @r@ forms mirror 'AFRP.Switch.kSwitch',
-- 'AFRP.Switch.dkSwitch', 'AFRP.Switch.rSwitch' and 'AFRP.Switch.drSwitch':
-- at a switching instant the collection is /frozen/ just before the
-- current step, so members carried over into the new collection resume
-- without losing or repeating time, and new members start at that instant.
-- Every collection steps lazily ('AFRP.Internal.Deferred.lazyN'): its input
-- is routed, and its switching event looked at, only when its output is
-- demanded or at the next sample, so a collection may watch a signal fed
-- back through a 'Control.Arrow.loop' that does not use its output at
-- that instant ('parB' on a list needs no such wrapper: broadcasting
-- never looks at the input).
-- As with the basic switches, the delayed forms are decoupled: their output
-- never depends on their event at the same instant, so the event may be
-- computed, through a loop, from the collection's own output.
module AFRP.Parallel
  ( -- * Parallel composition
    par
  , parB
  , parZ
  , parC
    -- * Switching a collection
  , pSwitch
  , dpSwitch
  , pSwitchB
  , dpSwitchB
  , pSwitchZ
  , dpSwitchZ
    -- * Recurring collection changes
  , rpSwitch
  , drpSwitch
  , rpSwitchB
  , drpSwitchB
  , rpSwitchZ
  , drpSwitchZ
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

import           AFRP.Event
import           AFRP.Internal.SF

------------------------------------------------------------------------------
-- Implementation note
--
-- Every combinator below is written once, over a /stepper/: the function
-- that steps a routed collection, returning the successors and the (lazy)
-- outputs in the collection's shape. 'stepColF' works for any 'Functor'
-- (each member stepped when first demanded: a Functor cannot be walked);
-- 'stepColL' is the same function on lists, done in one strict pass with
-- no intermediate collections, every successor evaluated; 'stepColT' the
-- same on a 'Traversable' (used at 'Map.Map', 'IntMap.IntMap' and
-- 'Seq.Seq'). The public combinators take their stepper from
-- 'stepperFor', which is 'stepColF', and which rewrite rules (at the end
-- of the module) replace wherever the collection's type is one of those
-- four: the combinators are inlined, so the rule sees the type at the
-- user's call. Each strict stepper computes the same collections as
-- 'stepColF', more evaluated:
--
-- > stepColL dt routed  ==  stepColF dt routed        (routed :: [(b, Node b c)])
-- > stepColT dt routed  ==  stepColF dt routed        (any Traversable)
--
-- and 'parB' on a list, which needs no routing at all, is replaced by
-- 'parBL':
--
-- > parBL sfs  ==  par broadcast sfs                  (sfs :: [SF a b])
--
-- Rules fire only where GHC optimises (not at -O0, not in GHCi) and only
-- where the type is known at the call (not in code generic over the
-- collection); elsewhere the combinators step on demand, as for any other
-- Functor.

-- | Steps a routed collection: successors (evaluated) and outputs (lazy).
type Stepper col = forall b c. DTime -> col (b, Node b c) -> (# col (Node b c), col c #)

-- | @par route sfs@ runs every member of @sfs@ at every sample; @route@
-- gives each member its input sample. The output is the collection of the
-- members' outputs, in the same shape.
par :: Functor col => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c) -> SF a (col c)
par = parWith stepperFor
{-# INLINE par #-}

parWith :: Functor col => Stepper col -> (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c) -> SF a (col c)
parWith stepper rf sfs = SF (lazyN (parN' stepper rf (fmap sfNode sfs)))
{-# INLINE parWith #-}

-- | @parB sfs@ runs every member on the same input.
--
-- > embed (parB [constant 1, localTime]) ((), [(0.5, Nothing)])  ==  [[1, 0], [1, 0.5]]
parB :: Functor col => col (SF a b) -> SF a (col b)
parB = parWith stepperFor broadcast
{-# INLINE [1] parB #-}

-- | @parZ sfs@ runs the i-th member on the i-th element of the input list.
-- An input list shorter than @sfs@ is an error (raised when that sample is
-- stepped, naming the function, and at every later sample: the collection
-- is gone); extra inputs are ignored. (Yampa 0.15's @parZ@ raises for the
-- members beyond the list's end only, at that sample and every later
-- one, and runs the others on; its @parC@ raises for the whole output, as
-- afrp's do.)
parZ :: [SF a b] -> SF [a] [b]
parZ = parWith stepColL (zipRoute "parZ")

-- | @parC sf@ runs one copy of @sf@ per element of its input list, the i-th
-- on the i-th element. The number of copies is the length of the input
-- list at local time 0; later a shorter list is an error (as for 'parZ'),
-- extra elements are ignored. The input list is looked at only when the
-- output is demanded (or at the next sample), as for every collection.
--
-- > embed (parC localTime) ("ab", [(1, Just "cd")])  ==  [[0, 0], [1, 1]]
parC :: SF a b -> SF [a] [b]
parC sf = SF (lazyN (initN (\as0 ->
  stepN (parN' stepColL (zipRoute "parC") (map (const (sfNode sf)) as0)) 0 as0)))

parN' :: Stepper col -> (forall sf. a -> col sf -> col (b, sf)) -> col (Node b c) -> Node a (col c)
parN' stepper rf = go
  where
    go ns = NStep (\dt a -> case stepper dt (rf a ns) of
      (# ns', cs #) -> case go ns' of !n -> (# n, cs #))

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

-- | @pSwitch route sfs sfe k@ runs @sfs@ as 'par' does. The event source
-- @sfe@ sees the input and the collection's output; at its first
-- occurrence @Event d@ the whole thing becomes @k sfs' d@, where @sfs'@ is
-- the collection frozen just before the current step. The output at that
-- instant is the new signal function's first output.
--
-- An event at time 0 passes the collection unstarted, and the output at
-- time 0 is the new signal function's first output: the collection's own
-- outputs at time 0 are seen only by @sfe@. Members carried over go on
-- from their own local time when started (time spent switched out does
-- not count); members that @k@ makes afresh start at local time 0 at the
-- switching instant. If the new signal function switches at its own
-- first sample, it does so at this same instant. (As Yampa's @pSwitch@;
-- 'pSwitchB' and 'pSwitchZ' likewise.)
pSwitch :: Functor col
        => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
        -> SF (a, col c) (Event d) -> (col (SF b c) -> d -> SF a (col c)) -> SF a (col c)
pSwitch = pSwitchWith stepperFor
{-# INLINE pSwitch #-}

pSwitchWith :: Functor col => Stepper col
            -> (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
            -> SF (a, col c) (Event d) -> (col (SF b c) -> d -> SF a (col c)) -> SF a (col c)
pSwitchWith stepper rf sfs (SF e0) k = SF (lazyHandoverN (go (fmap sfNode sfs) e0))
  where
    go ns ne = HandoverStep (\dt a -> case stepper dt (rf a ns) of
      (# ns', cs #) -> case stepN ne dt (a, cs) of
        (# ne', NoEvent #) -> (# Stay (go ns' ne'), cs #)
        (# _, Event d #)   -> case stepN (sfNode (k (freezeCol ns dt) d)) dt a of
          (# m, cs' #) -> (# Leave m, cs' #))

-- | Delayed 'pSwitch': at the switching instant the output is still the
-- old collection's; @k sfs' d@ starts at that instant (its first output
-- discarded) and supplies the outputs from the next sample on.
--
-- An event at time 0: the output at time 0 is the initial collection's,
-- and the new signal function, started at time 0, gives the outputs from
-- the next sample on. Members carried over keep their local time, as for
-- 'pSwitch'. (As Yampa's @dpSwitch@; 'dpSwitchB' and 'dpSwitchZ'
-- likewise.)
dpSwitch :: Functor col
         => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
         -> SF (a, col c) (Event d) -> (col (SF b c) -> d -> SF a (col c)) -> SF a (col c)
dpSwitch = dpSwitchWith stepperFor
{-# INLINE dpSwitch #-}

dpSwitchWith :: Functor col => Stepper col
             -> (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
             -> SF (a, col c) (Event d) -> (col (SF b c) -> d -> SF a (col c)) -> SF a (col c)
dpSwitchWith stepper rf sfs (SF e0) k = SF (lazyHandoverN (go (fmap sfNode sfs) e0))
  where
    go ns ne = HandoverStep (\dt a -> case stepper dt (rf a ns) of
      (# ns', cs #) ->
        -- Decoupled: the detector is stepped, and its event examined, only
        -- when the successor next steps, so it may read (through a loop)
        -- the output this step is producing.
        let next = case boxStep ne dt (a, cs) of
              Boxed ne' NoEvent -> Stay (go ns' ne')
              Boxed _ (Event d) -> case stepN (sfNode (k (freezeCol ns dt) d)) dt a of (# m, _ #) -> Leave m
        in (# next, cs #))

-- | 'pSwitch' with the input broadcast to every member.
pSwitchB :: Functor col
         => col (SF a b) -> SF (a, col b) (Event c) -> (col (SF a b) -> c -> SF a (col b))
         -> SF a (col b)
pSwitchB = pSwitchWith stepperFor broadcast
{-# INLINE pSwitchB #-}

-- | 'dpSwitch' with the input broadcast to every member.
dpSwitchB :: Functor col
          => col (SF a b) -> SF (a, col b) (Event c) -> (col (SF a b) -> c -> SF a (col b))
          -> SF a (col b)
dpSwitchB = dpSwitchWith stepperFor broadcast
{-# INLINE dpSwitchB #-}

-- | 'pSwitch' with zipped inputs (as 'parZ').
pSwitchZ :: [SF a b] -> SF ([a], [b]) (Event c) -> ([SF a b] -> c -> SF [a] [b]) -> SF [a] [b]
pSwitchZ = pSwitchWith stepColL (zipRoute "pSwitchZ")

-- | 'dpSwitch' with zipped inputs (as 'parZ').
dpSwitchZ :: [SF a b] -> SF ([a], [b]) (Event c) -> ([SF a b] -> c -> SF [a] [b]) -> SF [a] [b]
dpSwitchZ = dpSwitchWith stepColL (zipRoute "dpSwitchZ")

-- | @rpSwitch route sfs@ runs @sfs@ as 'par' does on the first input
-- component, and changes the collection at every event @Event f@ of the
-- second: the collection, frozen just before the current step, is
-- replaced by @f@ of it, started at that instant (so kept members resume
-- seamlessly and new ones start at local time 0). The output at that
-- instant is the new collection's. An event at time 0 changes the
-- collection before it produces any output.
rpSwitch :: Functor col
         => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
         -> SF (a, Event (col (SF b c) -> col (SF b c))) (col c)
rpSwitch = rpSwitchWith stepperFor
{-# INLINE rpSwitch #-}

rpSwitchWith :: Functor col => Stepper col
             -> (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
             -> SF (a, Event (col (SF b c) -> col (SF b c))) (col c)
rpSwitchWith stepper rf sfs = SF (lazyN (go (fmap sfNode sfs)))
  where
    go ns = NStep (\dt (a, e) ->
      let ns0 = event ns (\f -> fmap sfNode (f (freezeCol ns dt))) e
      in case stepper dt (rf a ns0) of (# ns', cs #) -> case go ns' of !n -> (# n, cs #))

-- | Delayed 'rpSwitch': at an event instant the output is still the old
-- collection's; the new collection starts at that instant and supplies
-- the outputs from the next sample on.
--
-- An event at time 0: @f@ receives the unstarted collection, the output at
-- time 0 is the initial collection's, and the changed collection gives
-- the outputs from the next sample on. Kept members keep their local
-- time; new ones start at local time 0 at the event's instant. With
-- events at consecutive samples, each collection gives exactly one output
-- before the next takes over. (As Yampa's @drpSwitch@; 'drpSwitchB' and
-- 'drpSwitchZ' likewise.)
drpSwitch :: Functor col
          => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
          -> SF (a, Event (col (SF b c) -> col (SF b c))) (col c)
drpSwitch = drpSwitchWith stepperFor
{-# INLINE drpSwitch #-}

drpSwitchWith :: Functor col => Stepper col
              -> (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
              -> SF (a, Event (col (SF b c) -> col (SF b c))) (col c)
drpSwitchWith stepper rf sfs = SF (lazyN (go (fmap sfNode sfs)))
  where
    go ns = NStep (\dt ae -> case stepper dt (rf (fst ae) ns) of
      (# ns', cs #) ->
        -- Decoupled: the event is examined when the successor next steps.
        let next = case snd ae of
              NoEvent -> go ns'
              Event f -> case stepper dt (rf (fst ae) (fmap sfNode (f (freezeCol ns dt)))) of
                (# ms', _ #) -> go ms'
        in (# deferN next, cs #))

-- | 'rpSwitch' with the input broadcast to every member.
rpSwitchB :: Functor col
          => col (SF a b) -> SF (a, Event (col (SF a b) -> col (SF a b))) (col b)
rpSwitchB = rpSwitchWith stepperFor broadcast
{-# INLINE rpSwitchB #-}

-- | 'drpSwitch' with the input broadcast to every member.
drpSwitchB :: Functor col
           => col (SF a b) -> SF (a, Event (col (SF a b) -> col (SF a b))) (col b)
drpSwitchB = drpSwitchWith stepperFor broadcast
{-# INLINE drpSwitchB #-}

-- | 'rpSwitch' with zipped inputs (as 'parZ').
rpSwitchZ :: [SF a b] -> SF ([a], Event ([SF a b] -> [SF a b])) [b]
rpSwitchZ = rpSwitchWith stepColL (zipRoute "rpSwitchZ")

-- | 'drpSwitch' with zipped inputs (as 'parZ').
drpSwitchZ :: [SF a b] -> SF ([a], Event ([SF a b] -> [SF a b])) [b]
drpSwitchZ = drpSwitchWith stepColL (zipRoute "drpSwitchZ")

------------------------------------------------------------------------------
-- Helpers

broadcast :: Functor col => a -> col sf -> col (a, sf)
broadcast a = fmap (\sf -> (a, sf))

zipRoute :: String -> [a] -> [sf] -> [(a, sf)]
zipRoute name = go
  where
    go _        []       = []
    go (a : as) (s : ss) = (a, s) : go as ss
    go []       _        = error ("AFRP.Parallel." ++ name
      ++ ": the input list is shorter than the list of signal functions")

-- The stepper of a collection type: 'stepColF', replaced by the rules at
-- the end of the module at lists, maps, int maps and sequences. Never
-- inlined, so that the rules can see it.
stepperFor :: Functor col => Stepper col
stepperFor = stepColF
{-# NOINLINE stepperFor #-}

-- Step every member of any 'Functor': each member is stepped once, when its
-- successor or its output is first demanded (a Functor cannot be walked).
stepColF :: Functor col => DTime -> col (b, Node b c) -> (# col (Node b c), col c #)
stepColF dt routed =
  let stepped = fmap (\(b, n) -> boxStep n dt b) routed
  in (# fmap (\(Boxed n _) -> n) stepped, fmap (\(Boxed _ c) -> c) stepped #)

-- Step every member of a 'Traversable', evaluating every successor node, so
-- that no member accumulates suspended steps. The rules below use it at
-- the containers' 'Map.Map', 'IntMap.IntMap' and 'Seq.Seq', which Yampa
-- programs use as collections; it computes the same collections as
-- 'stepColF', more evaluated.
stepColT :: Traversable col => DTime -> col (b, Node b c) -> (# col (Node b c), col c #)
stepColT dt routed = case stepColF dt routed of
  (# nodes, cs #) -> foldl' (\_ x -> x `seq` ()) () nodes `seq` (# nodes, cs #)

stepMap :: Stepper (Map.Map k)
stepMap = stepColT

stepIntMap :: Stepper IntMap.IntMap
stepIntMap = stepColT

stepSeq :: Stepper Seq.Seq
stepSeq = stepColT

-- 'stepColF' on lists, in one pass: the members are stepped in order, each
-- successor evaluated, the outputs left lazy.
stepColL :: DTime -> [(b, Node b c)] -> (# [Node b c], [c] #)
stepColL dt = go
  where
    go []              = (# [], [] #)
    go ((b, n) : rest) = case stepN n dt b of
      (# !n', c #) -> case go rest of
        (# ns', cs #) -> (# n' : ns', c : cs #)

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
undefElem = error "AFRP.Parallel: an array element that was never written"

freezeCol :: Functor col => col (Node b c) -> DTime -> col (SF b c)
freezeCol ns dt = fmap (\n -> SF (freezeN n dt)) ns

------------------------------------------------------------------------------
-- The strict steppers, chosen by type (see the note at the top).

{-# RULES
"stepperFor/list"   stepperFor = stepColL
"stepperFor/map"    stepperFor = stepMap
"stepperFor/intmap" stepperFor = stepIntMap
"stepperFor/seq"    stepperFor = stepSeq
"parB/list"         parB       = parBL
  #-}
