{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE GADTs         #-}
{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE MagicHash     #-}
-- Full laziness would float the per-step decisions of the switches out of
-- the closures that make them, as thunks allocated at every step.
{-# OPTIONS_GHC -fno-full-laziness #-}
-- |
-- Module      : AFRP.Switch
-- Description : Switching: a signal function that becomes another one at
--               an event.
--
-- The names follow the notes and Yampa: a @d@ prefix means /delayed/ (at
-- the switching instant the output is still the old signal function's; the
-- new one takes over from the next sample), an @r@ prefix means
-- /recurring/ (every event switches, not only the first), a @k@ prefix
-- means the continuation receives the signal function being switched out
-- of.
--
-- In every case the signal function switched in /starts/ at the switching
-- instant: it sees the input sample of that instant as its first sample,
-- and (for the immediate switches) its first output is the switch's output
-- at that instant. A delayed switch also starts the new signal function at
-- the switching instant, but discards its first output: the new one
-- supplies the outputs from the next sample on.
--
-- Whatever the continuation builds afresh has local time 0 at the
-- switching instant. A /frozen/ signal function that 'kSwitch', 'dkSwitch'
-- or a collection switch ("AFRP.Parallel") hands on is different: when it
-- is started, it repeats the step that the switch interrupted and then
-- goes on from the local time it had, whenever it is started (time spent
-- switched out does not count). So in @kSwitch localTime (after 1 ())
-- (\s _ -> s)@ the output at 1 s is 1, not 0.
--
-- An event at time 0 switches at time 0.
--
-- A signal function switched in at an instant whose own event occurs at
-- that same instant switches again, at once: so a switch into itself on
-- an event that is always there at time 0 (@switch (sf &&& now ()) (\_ ->
-- that same switch)@, or 'after' 0) never finishes its sample, as in
-- Yampa: the program runs until memory runs out, or (depending on how it
-- is built and run) hangs or is stopped by GHC's runtime with
-- @\<\<loop\>\>@. The event has to wait for time to
-- pass ('after' with a positive time, or an event that is not there at
-- the new signal function's first sample). 'kSwitch' and
-- 'AFRP.Parallel.pSwitch' into themselves on such an event never finish
-- their sample either. A delayed switch does not help when its event,
-- too, is there at every first sample: @dSwitch (sf &&& now ()) (\_ ->
-- that same switch)@ gives its first output, then switches again at once
-- at the next sample's start, for ever (as in Yampa); and so do
-- 'dkSwitch' and 'AFRP.Parallel.dpSwitch' into themselves on such an
-- event.
--
-- The delayed switches are /decoupled/: their output at an instant never
-- depends on whether their event occurs at that instant. They decide
-- whether to switch only when they are next stepped, so the event may
-- depend, through a 'Control.Arrow.loop' or @rec@, on the switch's own
-- output at the same instant (the immediate switches cannot allow that).
-- What is fed back must reach the event from outside the running signal
-- function: the event input of 'drSwitch', the detector of 'dkSwitch' and
-- 'AFRP.Parallel.dpSwitch', or (for 'dSwitch') an event computed outside
-- and merged in. The running signal function itself is stepped in full at
-- every sample, so, as everywhere in a loop ('Control.Arrow.loop'), it may
-- only delay a fed-back value, never inspect it at the same instant.
--
-- The immediate switches ('switch', 'rSwitch', 'kSwitch') look at their
-- event only when their output is demanded, or at the next sample (unless
-- it is already the evaluated 'NoEvent'). So a switch
-- whose event is computed from a fed-back signal may sit inside a
-- 'Control.Arrow.loop' that does not use its output at that instant, as
-- in Yampa; the network is still stepped, and its thunks forced, once a
-- sample.
--
-- A switch whose event source has become 'AFRP.EventSource.never' (for
-- example @sf &&& never@, or an 'AFRP.EventSource.after' that cannot fire
-- again) removes itself from the network.
module AFRP.Switch
  ( switch
  , dSwitch
  , rSwitch
  , drSwitch
  , kSwitch
  , dkSwitch
  ) where

import           GHC.Exts         (isTrue#, reallyUnsafePtrEquality#)

import           AFRP.Event
import           AFRP.Internal.SF

-- | @switch sf k@ behaves as @sf@ (ignoring the event part of its output)
-- until the first occurrence @Event c@ of that event part, and from then
-- on as @k c@, started at the instant of the event. At that instant the
-- output is @k c@'s first output.
--
-- > embed (switch (constant 1 &&& after 1 ()) (\() -> localTime))
-- >       ((), replicate 3 (0.5, Nothing))  ==  [1, 1, 0, 0.5]
switch :: SF a (b, Event c) -> (c -> SF a b) -> SF a b
switch (SF n0) k = SF (go n0)
  where
    go n = NStep (step n)
    -- sf &&& e, the usual shape: the two sides are stepped apart, so that
    -- the event is seen as it stands. If it is already the evaluated
    -- 'NoEvent' (as an edge after 'True' or 'never' returns it) the switch
    -- continues at once, and a switch on 'never' removes itself.
    step n dt a = case n of
      NFan f g -> case stepN f dt a of
        (# f', b #) -> case stepN g dt a of
          (# g', e #)
            | evaluatedNoEvent e -> case fanN f' g' of !n' -> case watch n' go of !m -> (# m, b #)
            | otherwise          -> decide (fanN f' g') b e dt a
      _        -> case stepN n dt a of (# n', be #) -> decide n' (fst be) (snd be) dt a
    -- Otherwise the event may depend on the input (through a loop, on a
    -- value this very step produces): whether it occurred is looked at
    -- only when the output is demanded, or at the next step.
    decide n' b e dt a =
      let r = case e of
            NoEvent -> Boxed (watch n' go) b
            Event c -> boxStep (sfNode (k c)) dt a
      in (# deferN (case r of Boxed m _ -> m), case r of Boxed _ o -> o #)

-- | @dSwitch sf k@ is 'switch' except at the switching instant, where the
-- output is still @sf@'s; @k c@ is started at that instant (its first
-- output discarded) and supplies every output after it. Needed when the
-- switched-in signal function depends on the switch's own output (a
-- recursive definition such as the notes' @rcReverse@).
dSwitch :: SF a (b, Event c) -> (c -> SF a b) -> SF a b
dSwitch (SF n0) k = SF (go n0)
  where
    go n = NStep (step n)
    step n dt a = case n of
      NFan f g -> stepFan f g dt a
      _        -> case stepN n dt a of
        (# n', be #) -> (# NStep (resume n' (snd be) dt a), fst be #)
    -- sf &&& e, the usual shape: stepped exactly as 'stepN' steps the fan
    -- (f, then g), but its output and its event are kept apart instead of
    -- being paired and then selected from, and while both sides stay
    -- stateful the fan is not rebuilt: the switch keeps its two sides.
    goFan f g = NStep (stepFan f g)
    stepFan f g dt a = case stepInline f dt a of
      (# f', b #) -> case stepN g dt a of
        (# g', e #)
          -- The event is already the evaluated constructor 'NoEvent' (as
          -- an edge or 'never' returns it; found by pointer equality,
          -- which forces nothing): 'resume' would take its 'NoEvent'
          -- branch at the next step, and what that branch does can be
          -- decided now, by looking only at evaluated values (the nodes
          -- and their strict fields; a constant event only if it is
          -- itself the evaluated 'NoEvent'), so it is not deferred. This
          -- is @resume n' e dt0 a0 = stepN (watch n' go)@ with @n' =
          -- fanN f' g'@, case by case:
          | evaluatedNoEvent e -> case g' of
              NPure _ -> case fanN f' g' of
                m@(NFan f'' g'') -> case g'' of
                  NPure (FDC x)
                    -- sf &&& never: the switch can never fire ('unwatched')
                    | evaluatedNoEvent x      -> (# f'', b #)
                    -- a constant event that may occur: left to 'resume'
                    | otherwise               -> defer m e dt a b
                  _                           -> (# goFan f'' g'', b #)
                -- a constant pair: 'unwatched' would look at its lazy
                -- value, so that is left to 'resume'
                m@(NPure (FDC _))             -> defer m e dt a b
                m                             -> (# go m, b #)
              -- a stateful event part: fanN f' g' is the fan of the two,
              -- kept as the switch's two sides
              _ -> (# goFan f' g', b #)
          -- An event that is still a thunk (it may depend, through a
          -- loop, on the output of this very step) is left to 'resume',
          -- as are the event occurrences. While the event part stays
          -- stateful, @fanN f' g'@ is @NFan f' g'@, which 'unwatched'
          -- leaves watched, so 'resume' would step the two sides again
          -- on 'NoEvent': 'resumeFan' does that without building the fan.
          | otherwise -> case g' of
              NPure _ -> defer (fanN f' g') e dt a b
              _       -> (# NStep (resumeFan f' g' e dt a), b #)
    defer n' e dt a b = case n' of !m -> (# NStep (resume m e dt a), b #)
    -- Decoupled: whether the event @e@ occurred at the step that produced
    -- it is examined only at the next step (this is @deferN next@ with
    -- @next = watch n' go@ or @k c@ started then, stepped at once).
    resume n' e dt0 a0 dt a = case e of
      NoEvent -> case unwatched n' of
        Just m  -> stepN m dt a
        Nothing -> step n' dt a
      Event c -> case stepN (sfNode (k c)) dt0 a0 of (# m, _ #) -> stepN m dt a
    -- 'resume' on @NFan f' g'@ with @g'@ stateful.
    resumeFan f' g' e dt0 a0 dt a = case e of
      NoEvent -> stepFan f' g' dt a
      Event c -> case stepN (sfNode (k c)) dt0 a0 of (# m, _ #) -> stepN m dt a

-- Is the value, as it stands, the evaluated constructor 'NoEvent'? It is
-- never evaluated: a thunk (even one that would evaluate to 'NoEvent')
-- gives 'False'. A nullary constructor has a single static closure, and
-- compiled code refers to it by one (tagged) pointer; anything else that
-- denotes 'NoEvent' (an indirection, say) gives 'False' too, which only
-- means that the decision is deferred as it would have been anyway.
evaluatedNoEvent :: Event c -> Bool
evaluatedNoEvent e = isTrue# (reallyUnsafePtrEquality# e NoEvent)
{-# INLINE evaluatedNoEvent #-}

-- Continue watching a stepped node, unless its event can no longer occur.
-- Both patterns inspect only values that the step just evaluated.
watch :: Node a (b, Event c) -> (Node a (b, Event c) -> Node a b) -> Node a b
watch n go = case unwatched n of
  Just m  -> m
  Nothing -> go n

-- The node a switch on @n@ becomes if @n@'s event can no longer occur.
unwatched :: Node a (b, Event c) -> Maybe (Node a b)
unwatched n = case n of
  -- sf &&& never = the switch can never fire
  NFan f (NPure (FDC NoEvent)) -> Just f
  -- constant (b, NoEvent) likewise
  NPure (FDC (b, NoEvent))     -> Just (constN b)
  _                            -> Nothing
{-# INLINE unwatched #-}

-- | @rSwitch sf@ behaves as @sf@ on the first input component, and switches
-- into the signal function carried by each event of the second component,
-- at the instant of the event (its first output is the output there). An
-- event at time 0 replaces @sf@ before it produces any output.
--
-- The step, and so the look at the event, is performed when the output is
-- demanded, or at the next sample. Where @arr p >>> rSwitch sf@ is written
-- in the source, a rewrite rule makes it one node that applies @p@ in that
-- deferred step, which means the same and allocates less.
rSwitch :: SF a b -> SF (a, Event (SF a b)) b
rSwitch sf = SF (rSwitchFrom (\ae -> ae) sf)
{-# NOINLINE [1] rSwitch #-}

-- @rSwitchOn p sf = arr p >>> rSwitch sf@, in one node: @p@ is applied in
-- the thunk of the step, instead of in a thunk of its own. The usual shape
-- (the input and the event computed by one function) becomes this by the
-- rewrite rules below wherever GHC sees it written.
rSwitchOn :: (c -> (a, Event (SF a b))) -> SF a b -> SF c b
rSwitchOn p sf = SF (rSwitchFrom p sf)

{-# RULES
"AFRP arr>>>rSwitch" forall p sf.
  compSF (rSwitch sf) (arrSF p) = rSwitchOn p sf
"AFRP arr>>>rSwitch>>>sf" forall p sf h.
  compSF (compSF h (rSwitch sf)) (arrSF p) = compSF h (rSwitchOn p sf)
  #-}

rSwitchFrom :: (c -> (a, Event (SF a b))) -> SF a b -> Node c b
rSwitchFrom p (SF n0) = NStep (step n0)
  where
    -- Lazy: the step (and so the look at the event) is performed when the
    -- output is demanded, or at the start of the next step.
    step n dt c =
      let r = case p c of
            (a, NoEvent)      -> case stepInline n dt a of (# n', b #) -> Boxed n' b
            (a, Event (SF m)) -> case stepInline m dt a of (# m', b #) -> Boxed m' b
      in (# NStep (\dt' c' -> case r of Boxed n' _ -> step n' dt' c'), case r of Boxed _ b -> b #)
{-# INLINE rSwitchFrom #-}

-- | Delayed 'rSwitch': at an event instant the output is still the current
-- signal function's; the new one starts at that instant and supplies the
-- outputs from the next sample on. Used by the notes' @vel@, where the new
-- signal function is built from the switch's own output.
--
-- An event at time 0 switches at time 0: the output there is still
-- @sf@'s, and the new signal function, started at time 0, gives the
-- outputs from the next sample on. With events at consecutive samples,
-- each signal function switched in gives exactly one output before the
-- next takes over. (As Yampa's @drSwitch@.)
drSwitch :: SF a b -> SF (a, Event (SF a b)) b
drSwitch (SF n0) = SF (lazyN (go n0))
  where
    go n = NStep (\dt ae -> case stepN n dt (fst ae) of
      (# n', b #) ->
        let next = case snd ae of
              NoEvent      -> go n'
              Event (SF m) -> case stepN m dt (fst ae) of (# m', _ #) -> go m'
        in (# deferN next, b #))

-- | @kSwitch sf sfe k@: run @sf@; the event source @sfe@ watches its input
-- and output. At the first occurrence @Event c@, switch to @k sf' c@, where
-- @sf'@ is @sf@ /frozen/ just before the current step: starting @sf'@
-- replays that step exactly, so @k (\\s _ -> s)@ resumes @sf@ without
-- losing or repeating any time. The output at the switching instant is the
-- new signal function's first output. An event at time 0 passes the
-- original, unstarted @sf@.
kSwitch :: SF a b -> SF (a, b) (Event c) -> (SF a b -> c -> SF a b) -> SF a b
kSwitch (SF n0) (SF e0) k = SF (lazyHandoverN (go n0 e0))
  where
    go n ne = HandoverStep (\dt a -> case stepN n dt a of
      (# n', b #) -> case stepN ne dt (a, b) of
        (# ne', NoEvent #) -> (# Stay (go n' ne'), b #)
        (# _, Event c #)   -> case stepN (sfNode (k (SF (freezeN n dt)) c)) dt a of
          (# m, b' #) -> (# Leave m, b' #))

-- | Delayed 'kSwitch': at the switching instant the output is still
-- @sf@'s; @k sf' c@ starts there (first output discarded) and supplies the
-- outputs from the next sample on.
--
-- An event at time 0 passes the original, unstarted @sf@, and the output
-- at time 0 is still @sf@'s. As for 'kSwitch', the frozen @sf'@ goes on
-- from its own local time when started, while what @k@ builds afresh
-- starts at local time 0 at the switching instant; if @k sf' c@ switches
-- at its own first sample, that switch too happens at this instant.
-- (As Yampa's @dkSwitch@.)
dkSwitch :: SF a b -> SF (a, b) (Event c) -> (SF a b -> c -> SF a b) -> SF a b
dkSwitch (SF n0) (SF e0) k = SF (lazyHandoverN (go n0 e0))
  where
    -- (what follows is decided at the next step: decoupled)
    go n ne = HandoverStep (\dt a -> case stepN n dt a of
      (# n', b #) ->
        let next = case boxStep ne dt (a, b) of
              Boxed ne' NoEvent -> Stay (go n' ne')
              Boxed _ (Event c) -> case stepN (sfNode (k (SF (freezeN n dt)) c)) dt a of
                (# m, _ #) -> Leave m
        in (# next, b #))
