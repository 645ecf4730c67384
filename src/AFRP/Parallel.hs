{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE RankNTypes    #-}
-- |
-- Module      : AFRP.Parallel
-- Description : Collections of signal functions running side by side, and
--               switching on the whole collection.
--
-- A collection is any 'Traversable' container of signal functions (a list,
-- a 'Data.Map.Map', a 'Data.Sequence.Seq', ...). Yampa asks only for
-- 'Functor'; we ask for 'Traversable' so that every member is stepped, and
-- its state evaluated, at every sample, even when nobody looks at its
-- output: a collection never accumulates thunks.
--
-- Naming, as in Yampa: no suffix takes a /routing function/
-- @forall sf. a -> col sf -> col (b, sf)@ that decides what input each
-- member sees (the @forall@ guarantees it can only route, never invent or
-- drop members it does not know); @B@ /broadcasts/ the same input to every
-- member; @Z@ /zips/ a list of inputs with a list of members. The @p@
-- switches and their @d@ / @r@ forms mirror 'AFRP.Switch.kSwitch',
-- 'AFRP.Switch.dkSwitch', 'AFRP.Switch.rSwitch' and 'AFRP.Switch.drSwitch':
-- at a switching instant the collection is /frozen/ just before the
-- current step, so members carried over into the new collection resume
-- without losing or repeating time, and new members start at that instant.
-- As with the basic switches, the delayed forms are decoupled: their output
-- never depends on their event at the same instant, so the event may be
-- computed, through a loop, from the collection's own output.
module AFRP.Parallel
  ( -- * Parallel composition
    par
  , parB
  , parZ
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

import           Data.Foldable    (foldl')

import           AFRP.Event
import           AFRP.Internal.SF

-- | @par route sfs@ runs every member of @sfs@ at every sample; @route@
-- gives each member its input sample. The output is the collection of the
-- members' outputs, in the same shape.
par :: Traversable col => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c) -> SF a (col c)
par rf sfs = SF (parN' rf (fmap sfNode sfs))

-- | @parB sfs@ runs every member on the same input.
--
-- > embed (parB [constant 1, localTime]) ((), [(0.5, Nothing)])  ==  [[1, 0], [1, 0.5]]
parB :: Traversable col => col (SF a b) -> SF a (col b)
parB = par broadcast

-- | @parZ sfs@ runs the i-th member on the i-th element of the input list.
-- An input list shorter than @sfs@ is an error (raised when that sample is
-- stepped, naming the function); extra inputs are ignored.
parZ :: [SF a b] -> SF [a] [b]
parZ = par (zipRoute "parZ")

parN' :: Traversable col => (forall sf. a -> col sf -> col (b, sf)) -> col (Node b c) -> Node a (col c)
parN' rf ns = NStep (\dt a -> case stepCol dt (rf a ns) of
  (ns', cs) -> (# parN' rf ns', cs #))

-- | @pSwitch route sfs sfe k@ runs @sfs@ as 'par' does. The event source
-- @sfe@ sees the input and the collection's output; at its first
-- occurrence @Event d@ the whole thing becomes @k sfs' d@, where @sfs'@ is
-- the collection frozen just before the current step. The output at that
-- instant is the new signal function's first output.
pSwitch :: Traversable col
        => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
        -> SF (a, col c) (Event d) -> (col (SF b c) -> d -> SF a (col c)) -> SF a (col c)
pSwitch rf sfs (SF e0) k = SF (go (fmap sfNode sfs) e0)
  where
    go ns ne = NStep (\dt a -> case stepCol dt (rf a ns) of
      (ns', cs) -> case stepN ne dt (a, cs) of
        (# ne', NoEvent #) -> (# go ns' ne', cs #)
        (# _, Event d #)   -> stepN (sfNode (k (freezeCol ns dt) d)) dt a)

-- | Delayed 'pSwitch': at the switching instant the output is still the
-- old collection's; @k sfs' d@ starts at that instant (its first output
-- discarded).
dpSwitch :: Traversable col
         => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
         -> SF (a, col c) (Event d) -> (col (SF b c) -> d -> SF a (col c)) -> SF a (col c)
dpSwitch rf sfs (SF e0) k = SF (go (fmap sfNode sfs) e0)
  where
    go ns ne = NStep (\dt a -> case stepCol dt (rf a ns) of
      (ns', cs) ->
        -- Decoupled: the detector is stepped, and its event examined, only
        -- when the successor next steps, so it may read (through a loop)
        -- the output this step is producing.
        let next = case boxStep ne dt (a, cs) of
              Boxed ne' NoEvent -> go ns' ne'
              Boxed _ (Event d) -> case stepN (sfNode (k (freezeCol ns dt) d)) dt a of (# m, _ #) -> m
        in (# deferN next, cs #))

-- | 'pSwitch' with the input broadcast to every member.
pSwitchB :: Traversable col
         => col (SF a b) -> SF (a, col b) (Event c) -> (col (SF a b) -> c -> SF a (col b))
         -> SF a (col b)
pSwitchB = pSwitch broadcast

-- | 'dpSwitch' with the input broadcast to every member.
dpSwitchB :: Traversable col
          => col (SF a b) -> SF (a, col b) (Event c) -> (col (SF a b) -> c -> SF a (col b))
          -> SF a (col b)
dpSwitchB = dpSwitch broadcast

-- | 'pSwitch' with zipped inputs (as 'parZ').
pSwitchZ :: [SF a b] -> SF ([a], [b]) (Event c) -> ([SF a b] -> c -> SF [a] [b]) -> SF [a] [b]
pSwitchZ = pSwitch (zipRoute "pSwitchZ")

-- | 'dpSwitch' with zipped inputs (as 'parZ').
dpSwitchZ :: [SF a b] -> SF ([a], [b]) (Event c) -> ([SF a b] -> c -> SF [a] [b]) -> SF [a] [b]
dpSwitchZ = dpSwitch (zipRoute "dpSwitchZ")

-- | @rpSwitch route sfs@ runs @sfs@ as 'par' does on the first input
-- component, and changes the collection at every event @Event f@ of the
-- second: the collection, frozen just before the current step, is
-- replaced by @f@ of it, started at that instant (so kept members resume
-- seamlessly and new ones start at local time 0). The output at that
-- instant is the new collection's. An event at time 0 changes the
-- collection before it produces any output.
rpSwitch :: Traversable col
         => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
         -> SF (a, Event (col (SF b c) -> col (SF b c))) (col c)
rpSwitch rf sfs = SF (go (fmap sfNode sfs))
  where
    go ns = NStep (\dt (a, e) ->
      let ns0 = event ns (\f -> fmap sfNode (f (freezeCol ns dt))) e
      in case stepCol dt (rf a ns0) of (ns', cs) -> (# go ns', cs #))

-- | Delayed 'rpSwitch': at an event instant the output is still the old
-- collection's; the new collection starts at that instant and supplies
-- the outputs from the next sample on.
drpSwitch :: Traversable col
          => (forall sf. a -> col sf -> col (b, sf)) -> col (SF b c)
          -> SF (a, Event (col (SF b c) -> col (SF b c))) (col c)
drpSwitch rf sfs = SF (go (fmap sfNode sfs))
  where
    go ns = NStep (\dt ae -> case stepCol dt (rf (fst ae) ns) of
      (ns', cs) ->
        -- Decoupled: the event is examined when the successor next steps.
        let next = case snd ae of
              NoEvent -> go ns'
              Event f -> case stepCol dt (rf (fst ae) (fmap sfNode (f (freezeCol ns dt)))) of
                (ms', _) -> go ms'
        in (# deferN next, cs #))

-- | 'rpSwitch' with the input broadcast to every member.
rpSwitchB :: Traversable col
          => col (SF a b) -> SF (a, Event (col (SF a b) -> col (SF a b))) (col b)
rpSwitchB = rpSwitch broadcast

-- | 'drpSwitch' with the input broadcast to every member.
drpSwitchB :: Traversable col
           => col (SF a b) -> SF (a, Event (col (SF a b) -> col (SF a b))) (col b)
drpSwitchB = drpSwitch broadcast

-- | 'rpSwitch' with zipped inputs (as 'parZ').
rpSwitchZ :: [SF a b] -> SF ([a], Event ([SF a b] -> [SF a b])) [b]
rpSwitchZ = rpSwitch (zipRoute "rpSwitchZ")

-- | 'drpSwitch' with zipped inputs (as 'parZ').
drpSwitchZ :: [SF a b] -> SF ([a], Event ([SF a b] -> [SF a b])) [b]
drpSwitchZ = drpSwitch (zipRoute "drpSwitchZ")

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

-- Step every member, evaluating every successor node.
stepCol :: Traversable col => DTime -> col (b, Node b c) -> (col (Node b c), col c)
stepCol dt routed =
  let stepped = fmap (\(b, n) -> boxStep n dt b) routed
      nodes   = fmap (\(Boxed n _) -> n) stepped
  in forceAll nodes `seq` (nodes, fmap (\(Boxed _ c) -> c) stepped)

forceAll :: Foldable t => t a -> ()
forceAll = foldl' (\_ x -> x `seq` ()) ()

freezeCol :: Functor col => col (Node b c) -> DTime -> col (SF b c)
freezeCol ns dt = fmap (\n -> SF (freezeN n dt)) ns
