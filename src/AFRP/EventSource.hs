-- |
-- Module      : AFRP.EventSource
-- Description : Signal functions that generate or reshape event streams.
--
-- Timing conventions shared by every time-based source here:
--
-- * Times are /local/: measured from the instant the source started (0 at a
--   run's first sample, or at the sample where it was switched in).
-- * A source scheduled for time @t@ fires at the first sample whose local
--   time is @>= t@ ("at, or as soon after as possible"), or short of @t@ by
--   no more than the rounding of binary fractions
--   ('AFRP.Internal.Clock.reached': a relative 2^-48). With steps of 0.5,
--   @after 1.0@ fires at exactly 1.0; with steps of 0.3 it fires at 1.2;
--   with steps of 0.15, @after 0.9@ fires at the sixth, whose local time
--   reads 0.8999999999999999.
-- * Local time is a compensated sum of the time steps (see
--   "AFRP.Internal.Clock"), so ten steps of 0.1 reach exactly 1.0.
-- * When a sample interval spans several scheduled occurrences, the plain
--   sources deliver only one (no backlog builds up) and the @Cat@ variants
--   deliver all of them, in order, as a list.
-- * This differs from Yampa, whose plain float sums often fall just short
--   of a due time with decimal steps: @afterEach [(3.0, ()), (2.0, ())]@ at
--   dt 0.01 fires at t = 3.00 and 5.00 here, at 3.01 and 5.01 in Yampa, and
--   two events due 0.001 s apart (at 3.0 and 3.001) land in two samples
--   here, in one in Yampa. See docs/YAMPA.md, "Time accounting".
--
-- = Modules
--
-- This module gathers the sources, and has no code of its own:
-- "AFRP.EventSource.Timed" (the sources scheduled in local time, and
-- delayed events), "AFRP.EventSource.Edge" (edges),
-- "AFRP.EventSource.Reshape" (the first occurrences let through or held
-- back) and "AFRP.EventSource.Sample" (samples of the input).
module AFRP.EventSource
  ( -- * Basic sources
    never
  , now
  , after
  , repeatedly
  , afterEach
  , afterEachCat
    -- * Delaying events
  , delayEvent
  , delayEventCat
    -- * Edges
  , edge
  , iEdge
  , edgeTag
  , edgeJust
  , edgeBy
    -- * Reshaping event streams
  , notYet
  , once
  , takeEvents
  , dropEvents
    -- * Sampling the input
  , snap
  , snapAfter
  , sample
  , sampleWindow
  ) where

import           AFRP.EventSource.Edge
import           AFRP.EventSource.Reshape
import           AFRP.EventSource.Sample
import           AFRP.EventSource.Timed
