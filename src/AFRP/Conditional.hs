{-# LANGUAGE UnboxedTuples #-}
-- |
-- Module      : AFRP.Conditional
-- Description : Running signal functions conditionally: while a predicate
--               holds ('provided'), again after each event ('recur'), one
--               after another ('andThen'). Yampa's names.
--
-- 'provided', 'recur' and 'andThen' are built from 'switch' and 'dSwitch',
-- so every signal function they switch in starts afresh (local time 0) at
-- the switching instant; 'pause' keeps one signal function and only stops
-- its time.
module AFRP.Conditional
  ( provided
  , pause
  , recur
  , andThen
  ) where

import           Control.Arrow    ((&&&), (^>>), (>>>), arr)

import           AFRP.Basic       (constant, dup, (-->))
import           AFRP.Event
import           AFRP.EventSource (edge, snap)
import           AFRP.Internal.SF
import           AFRP.Switch      (dSwitch, switch)

infixr 5 `andThen`

-- | @provided p sfT sfF@ runs @sfT@ while the input satisfies @p@ and
-- @sfF@ while it does not. At local time 0 the first input decides which
-- runs. Each time @p@ of the input changes, the other signal function is
-- started afresh at that sample (its local time 0) and gives the output
-- there; the one left is discarded with its state.
--
-- > embed (provided even localTime (constant (-1))) (2, map ((,) 1 . Just) [4, 5, 6, 8])
-- >   ==  [0, 1, -1, 0, 1]
provided :: (a -> Bool) -> SF a b -> SF a b -> SF a b
provided p sfT sfF =
  switch (constant (error "AFRP.Conditional.provided: no output before the first sample") &&& snap)
         (\a0 -> if p a0 then whileT else whileF)
  where
    whileT = switch (sfT &&& ((not . p) ^>> edge)) (const whileF)
    whileF = switch (sfF &&& (p ^>> edge)) (const whileT)

-- | @pause b0 cond sf@ runs @sf@ at the samples where @cond@ (which runs
-- at every sample) is 'False', and freezes it where @cond@ is 'True': then
-- @sf@ is not stepped, the output is its last output (@b0@ if it has not run
-- yet), and the time that passes is not seen by @sf@ (as in Yampa, it
-- resumes with only the time step of the sample that resumes it). If @cond@
-- is 'True' at local time 0, @sf@ starts at the first sample where it is
-- 'False'. Each step waits until its output is demanded (or the next step
-- starts), so @pause@ does not evaluate its input early inside 'loop'.
--
-- > embed (pause 0 (arr id) localTime) (False, map ((,) 1 . Just) [False, True, True, False])
-- >   ==  [0, 1, 1, 1, 2]
pause :: b -> SF a Bool -> SF a b -> SF a b
pause b0 (SF cond0) (SF sf0) = SF (lazyN (go cond0 sf0 b0))
  where
    go cond sf b = NStep (\dt a -> case stepN cond dt a of
      (# cond', paused #)
        | paused    -> (# go cond' sf b, b #)
        | otherwise -> case stepN sf dt a of (# sf', b' #) -> (# go cond' sf' b', b' #))

-- | @recur sfe@ outputs the events of @sfe@, and restarts @sfe@ (at its
-- local time 0) at the instant of each event it outputs. An event of @sfe@
-- at local time 0 is output (as in Yampa). At the first sample of every
-- restarted @sfe@ the output is the event that restarted it, whatever the
-- restarted @sfe@ says there: an event at the restart instant would restart
-- it for ever.
--
-- > embed (recur (after 1 'x')) ((), replicate 4 (0.5, Nothing))
-- >   ==  [NoEvent, NoEvent, Event 'x', NoEvent, Event 'x']
-- > embed (recur (now 'n')) ((), replicate 2 (1, Nothing))
-- >   ==  [Event 'n', NoEvent, NoEvent]
recur :: SF a (Event b) -> SF a (Event b)
recur sfe = go sfe
  where
    -- (each restart masks the first sample of sfe itself, not of the
    -- previous restart's masked sfe: no layer added per restart)
    go s = switch (s >>> arr dup) (\b -> Event b --> go (NoEvent --> sfe))

-- | @sfe1 \`andThen\` sfe2@ outputs the events of @sfe1@ up to and including
-- its first event (which may come at local time 0), then those of @sfe2@,
-- started at the instant of that first event. @sfe2@'s output at that
-- instant is not seen (the switch is delayed), so the two never give
-- simultaneous events. As infix, @infixr 5@ (Yampa's): a chain
-- @a \`andThen\` b \`andThen\` c@ is @a \`andThen\` (b \`andThen\` c)@, each
-- in turn.
--
-- > embed (now 'a' `andThen` after 1 'b') ((), replicate 2 (1, Nothing))
-- >   ==  [Event 'a', Event 'b', NoEvent]
-- > embed (after 1 'a' `andThen` after 1 'b' `andThen` after 1 'c') ((), replicate 4 (1, Nothing))
-- >   ==  [NoEvent, Event 'a', Event 'b', Event 'c', NoEvent]
andThen :: SF a (Event b) -> SF a (Event b) -> SF a (Event b)
andThen sfe1 sfe2 = dSwitch (sfe1 >>> arr dup) (const sfe2)
