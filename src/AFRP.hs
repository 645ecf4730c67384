-- |
-- Module      : AFRP
-- Description : Arrowized functional reactive programming: the whole core.
--
-- @import AFRP@ is all a program needs to write and run signal functions:
-- it re-exports the arrow combinators of "Control.Arrow", so the code of
-- the notes "Arrows, Robots, and Functional Reactive Programming" (Hudak,
-- Courtney, Nilsson, Peterson) compiles with this one import, arrow
-- notation (@proc@, @rec@) included.
--
-- The semantics follow Yampa, the reference implementation of this design;
-- each function's documentation says what it outputs at local time 0, at
-- the instant of an event and after a switch. Where this library differs
-- from Yampa, the function's documentation says so.
--
-- Operator cheat sheet:
--
-- @
-- sf1 >>> sf2     serial composition          sf1 &&& sf2   fan-out to a pair
-- sf1 *** sf2     parallel on pairs            first sf      act on the first component
-- b0 --> sf       replace the output at t=0    a0 >-- sf     replace the input at t=0
-- f -=> sf        map the output at t=0        f >=- sf      map the input at t=0
-- @
--
-- Naming grammar: @d@ delayed, @r@ recurring, @k@ continuation, @p@
-- parallel, @B@ broadcast, @Z@ zip, @i@ initialised, @Cat@ all
-- simultaneous events, @By@ with a custom function.
module AFRP
  ( -- * Signal functions
    SF
  , Time
  , DTime
    -- * Arrow combinators (re-exported from "Control.Arrow")
  , Arrow (..)
  , ArrowLoop (..)
  , ArrowChoice (..)
  , (>>>)
  , (<<<)
  , (^>>)
  , (>>^)
  , (<<^)
  , (^<<)
  , returnA
    -- * Basic signal functions
  , module AFRP.Basic
    -- * Events
  , module AFRP.Event
    -- * Event sources
  , module AFRP.EventSource
    -- * Hybrid: holding and accumulating
  , module AFRP.Hybrid
    -- * Scanning: step-by-step accumulation
  , module AFRP.Scan
    -- * Delays
  , module AFRP.Delay
    -- * Integration and differentiation
  , module AFRP.Integration
    -- * Feedback loops
  , module AFRP.Loop
    -- * Switching
  , module AFRP.Switch
    -- * Conditional and sequenced signal functions
  , module AFRP.Conditional
    -- * Parallel composition and collections
  , module AFRP.Parallel
    -- * Noise
  , module AFRP.Noise
    -- * Running
  , module AFRP.Run
    -- * Tasks
  , module AFRP.Task
    -- * Vector spaces and geometry
  , module AFRP.VectorSpace
  , module AFRP.Geometry
  ) where

import           Control.Arrow

import           AFRP.Basic
import           AFRP.Conditional
import           AFRP.Delay
import           AFRP.Event
import           AFRP.EventSource
import           AFRP.Geometry
import           AFRP.Hybrid
import           AFRP.Integration
import           AFRP.Internal.SF (DTime, SF, Time)
import           AFRP.Loop
import           AFRP.Noise
import           AFRP.Parallel
import           AFRP.Run
import           AFRP.Scan
import           AFRP.Switch
import           AFRP.Task
import           AFRP.VectorSpace
