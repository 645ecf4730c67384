{-# LANGUAGE RankNTypes #-}
-- |
-- Module      : AFRP.Task
-- Description : Tasks: signal functions that end, sequenced in a monad.
--
-- A @Task a b c@ is a signal function from @a@ to @b@ that may /end/ with a
-- result of type @c@. Tasks sequence with @do@: when one ends, the next
-- starts at that same instant (so its first output is the output at the
-- ending instant), with its local time at 0. A task that ends at the
-- instant it starts (at any time, not only at time 0) takes no time: its
-- output is never seen, and the next task's first output is the output
-- at that instant. Time-bounded tasks ('sleepT', 'timeOut', the event
-- source of 'abortWhen') count their time from the instant they start.
--
-- Tasks are built in continuation-passing style on top of
-- 'AFRP.Switch.switch', so a sequence of tasks costs one switch per step.
module AFRP.Task
  ( Task
  , mkTask
  , runTask
  , runTask_
  , taskToSF
  , constT
  , sleepT
  , snapT
  , timeOut
  , abortWhen
  , repeatUntil
  , forAll
  , forEver
  ) where

import           Control.Arrow       (arr, first, (&&&), (>>>))
import           Control.Monad       (ap, liftM)

import           AFRP.Basic          (constant)
import           AFRP.Event
import           AFRP.EventSource    (after, edgeBy, never, snap)
import           AFRP.Internal.SF    (SF, Time)
import           AFRP.Switch         (switch)

infixl 0 `timeOut`, `abortWhen`, `repeatUntil`

-- | A signal function from @a@ to @b@ that may end with a result @c@.
newtype Task a b c = Task (forall d. (c -> SF a (Either b d)) -> SF a (Either b d))

unTask :: Task a b c -> (c -> SF a (Either b d)) -> SF a (Either b d)
unTask (Task f) = f

-- | @fmap@ changes the result.
instance Functor (Task a b) where
  fmap = liftM

-- | @pure c@ ends at once with @c@.
instance Applicative (Task a b) where
  pure c = Task (\k -> k c)
  (<*>) = ap

-- | @t >>= f@ runs @t@; at the instant it ends with @c@, @f c@ starts.
instance Monad (Task a b) where
  t >>= f = Task (\k -> unTask t (\c -> unTask (f c) k))

-- | @mkTask sf@ runs @sf@, outputting its first component, and ends at the
-- first occurrence of its second component, with the event's value. At
-- that instant the output is already the next task's. An occurrence at
-- the task's own first sample ends it at once: its output is never seen.
mkTask :: SF a (b, Event c) -> Task a b c
mkTask sf = Task (switch (sf >>> first (arr Left)))

-- | Run a task as a signal function: 'Left' outputs while it runs, then
-- 'Right' its result forever, from the instant it ends.
runTask :: Task a b c -> SF a (Either b c)
runTask t = unTask t (constant . Right)

-- | Run a task whose end is not expected. Its output from the instant it
-- ends, that instant included, is an error (raised only if that output is
-- demanded).
runTask_ :: Task a b c -> SF a b
runTask_ t = runTask t >>> arr (either id (const (error
  "AFRP.Task.runTask_: the output of a task that has ended was demanded")))

-- | A task as a signal function with an ending event: the output while it
-- runs, and one occurrence carrying the result at the instant it ends.
-- From that instant on the first component has no value; demanding it is
-- an error. A task that ends at the instant it starts (@pure c@) gives its
-- occurrence at that first sample, and so never has an output.
taskToSF :: Task a b c -> SF a (b, Event c)
taskToSF t = runTask t >>> (arr outputOf &&& (arr result >>> edgeBy ended Nothing))
  where
    outputOf = either id (const (error
      "AFRP.Task.taskToSF: the output of a task that has ended was demanded"))
    result = either (const Nothing) Just
    -- Before time 0 the task counts as running, so an end at time 0 is seen.
    ended Nothing (Just c) = Just c
    ended _       _        = Nothing

-- | A task that outputs a constant and never ends.
constT :: b -> Task a b c
constT b = mkTask (constant b &&& never)

-- | @sleepT t b@ outputs @b@ and ends, with @()@, at the first sample at or
-- after local time @t@, within the rounding of the time accounting (as
-- 'AFRP.EventSource.after', which it uses: six steps of 0.15 end
-- @sleepT 0.9@, at a local time of 0.8999999999999999). The time counts
-- from the instant the task starts; @sleepT 0 b@ ends there, and never
-- outputs @b@. A negative or NaN time is an error.
sleepT :: Time -> b -> Task a b ()
sleepT t b
  | t < 0 || isNaN t = error ("AFRP.Task.sleepT: negative or NaN time, got " ++ show t)
  | otherwise        = mkTask (constant b &&& after t ())

-- | A task that ends at once, with the input sample of that instant.
snapT :: Task a b a
snapT = mkTask (constant (error "AFRP.Task.snapT: no output (it ends at once)") &&& snap)

-- | @t \`timeOut\` d@ runs @t@ for at most @d@ seconds: it ends with
-- @Just c@ if @t@ ends with @c@ first (or at the same instant), and with
-- 'Nothing' at the timeout. The @d@ seconds count from the instant the
-- @timeOut@ task starts (not from time 0 of the whole signal function),
-- and @t@ starts at that same instant. @t \`timeOut\` 0@ ends at once:
-- with @Just c@ if @t@ ends at once too, with 'Nothing' otherwise. A
-- negative or NaN @d@ is an error.
timeOut :: Task a b c -> Time -> Task a b (Maybe c)
timeOut t d
  | d < 0 || isNaN d = error ("AFRP.Task.timeOut: negative or NaN time, got " ++ show d)
  | otherwise = mkTask ((taskToSF t &&& after d ()) >>> arr pick)
  where
    pick ((b, ec), et) = (b, fmap Just ec `lMerge` tag et Nothing)

-- | @t \`abortWhen\` sfe@ runs @t@ until it ends (result 'Left') or until
-- @sfe@ occurs (result 'Right'); if both happen at one instant, the task's
-- own end wins. @sfe@ starts together with the task, so its local time
-- (for 'AFRP.EventSource.after', 'AFRP.EventSource.now' ...) counts from
-- the task's start; an occurrence at that first sample aborts the task at
-- once (its output is never seen), unless the task ends there too.
abortWhen :: Task a b c -> SF a (Event d) -> Task a b (Either c d)
abortWhen t sfe = mkTask ((taskToSF t &&& sfe) >>> arr pick)
  where
    pick ((b, ec), ed) = (b, fmap Left ec `lMerge` fmap Right ed)

-- | @repeatUntil m p@ runs @m@ again and again until its result satisfies
-- @p@, and returns that result. A task that ends at the instant it starts
-- (@pure x@, a 'AFRP.Task.sleepT' of 0) and never satisfies @p@ repeats
-- at that instant for ever: the sample never finishes (the program hangs,
-- or GHC's runtime stops it with @\<\<loop\>\>@). Some time must pass in
-- each round. ('repeatUntil', 'forAll' and 'forEver' are as Yampa's
-- @FRP.Yampa.Task@ had them up to its version 0.12; later versions
-- dropped them.)
repeatUntil :: Monad m => m a -> (a -> Bool) -> m a
repeatUntil m p = go
  where
    go = m >>= \x -> if p x then pure x else go

-- | @forAll xs f@ runs @f x@ for each @x@ in turn.
forAll :: Monad m => [a] -> (a -> m b) -> m ()
forAll xs f = mapM_ f xs

-- | Run an action forever. As for 'repeatUntil', a task that ends at the
-- instant it starts (@forEver (pure ())@) never lets the sample finish.
forEver :: Monad m => m a -> m b
forEver m = m >> forEver m
