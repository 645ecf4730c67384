{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE RankNTypes    #-}
{-# LANGUAGE BangPatterns  #-}
-- Local bindings not generalised, as when this module had GADTs on (for
-- the bank, now in "AFRP.Internal.Collection"): generalised, the 'go' of
-- 'pSwitchWith' and 'dpSwitchWith' is floated and wrapped otherwise.
{-# LANGUAGE MonoLocalBinds #-}
-- |
-- Module      : AFRP.Parallel
-- Description : Collections of signal functions running side by side, and
--               switching on the whole collection.
--
-- A collection is any 'Functor' container of signal functions (a list, a
-- 'Data.Map.Map', a 'Data.Sequence.Seq', a user's own type with only a
-- 'Functor' instance), as in Yampa. On lists (the common case) and on
-- the containers' 'Data.Map.Map', 'Data.IntMap.IntMap' and
-- 'Data.Sequence.Seq' (rewrite rules pick a specialised stepper), every
-- member is stepped, and its state evaluated, at every sample, even when
-- nobody looks at its output, so the collection never accumulates thunks. Any other collection can only be
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

import           AFRP.Event
import           AFRP.Internal.Collection
import           AFRP.Internal.SF

------------------------------------------------------------------------------
-- Implementation note
--
-- Every combinator below is written once, over a /stepper/ ('Stepper'):
-- the function that steps a routed collection. Those that take any
-- 'Functor' take theirs from 'stepperFor', which rewrite rules replace
-- by a strict stepper wherever the collection's type is a list, a map, an
-- int map or a sequence; and 'parB' on a list is replaced by 'parBL'
-- (the rule at the end of this module). The steppers, the rules that
-- choose them and 'parBL' are in "AFRP.Internal.Collection", whose note
-- gives the identities they rely on.

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

freezeCol :: Functor col => col (Node b c) -> DTime -> col (SF b c)
freezeCol ns dt = fmap (\n -> SF (freezeN n dt)) ns

------------------------------------------------------------------------------
-- 'parB' on a list (see the note at the top).

{-# RULES
"parB/list"         parB       = parBL
  #-}
