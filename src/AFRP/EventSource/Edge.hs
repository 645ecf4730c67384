{-# LANGUAGE UnboxedTuples #-}
-- |
-- Module      : AFRP.EventSource.Edge
-- Description : Events at the changes of a signal: rising edges, and
--               edges by any test of the previous and current samples.
--
-- Part of "AFRP.EventSource". Every detector here compares a sample with
-- the one before it, and looks at its input no earlier than its output
-- needs it or the next sample comes, so it may watch a signal fed back
-- through a 'Control.Arrow.loop'.
module AFRP.EventSource.Edge
  ( edge
  , iEdge
  , edgeTag
  , edgeJust
  , edgeBy
  ) where

import           Data.Maybe           (isJust)

import           AFRP.Event
import           AFRP.Internal.SF

-- | Rising edges of a Boolean signal: an occurrence at every sample where
-- the input is 'True' and was 'False' at the previous sample. At time 0
-- the previous value is taken to be 'True', so an input that starts out
-- 'True' produces no event (@edge = iEdge True@).
--
-- > embed edge (True, [(1, Just False), (1, Just True), (1, Nothing)])
-- >   ==  [NoEvent, NoEvent, Event (), NoEvent]
--
-- The edge evaluates its input only when its output is demanded, or at
-- the next sample (to know the previous value), so it may watch a signal
-- fed back through a 'Control.Arrow.loop' whose output nobody needs at
-- this instant. Where @arr p >>> edge@ (or @iEdge@) is written in the
-- source, a rewrite rule makes it one node that applies @p@ in place,
-- which means the same and costs a node a sample less.
edge :: SF Bool (Event ())
edge = iEdge True
{-# INLINE edge #-}

-- | 'edge' with the value assumed for the sample before time 0:
-- @iEdge False@ produces an event at time 0 if the input is 'True' then.
iEdge :: Bool -> SF Bool (Event ())
iEdge b0 = SF (edgeFrom id b0)
{-# NOINLINE [1] iEdge #-}

-- @iEdgeOn b0 p = arr p >>> iEdge b0@, in one node: @p@ is applied
-- where the edge stands, in the one thunk that both the output and the
-- next step read, instead of in a node and a thunk of its own. The common
-- idiom @arr p >>> edge@ (the notes' @arr (> 100) >>> edge@,
-- 'AFrob.rsStuck') becomes this by the rewrite rules below wherever GHC
-- sees it written.
iEdgeOn :: Bool -> (a -> Bool) -> SF a (Event ())
iEdgeOn b0 p = SF (edgeFrom p b0)

{-# RULES
"AFRP arr>>>iEdge" forall p b0.
  compSF (iEdge b0) (arrSF p) = iEdgeOn b0 p
"AFRP arr>>>iEdge>>>sf" forall p b0 h.
  compSF (compSF h (iEdge b0)) (arrSF p) = compSF h (iEdgeOn b0 p)
  #-}

-- An edge of @p@'s value. The state is what the previous step left,
-- unevaluated until this step (when the previous sample is complete):
-- after an output 'NoEvent' that needed no look at the input (the
-- previous value was 'True'), @p@ of the previous input; otherwise the
-- previous output itself, an occurrence exactly when the previous value
-- was 'True'. After 'True' the output is the evaluated 'NoEvent' whatever
-- the input (which a decoupled switch can see without forcing anything);
-- after 'False' it is a thunk on @p@ of the current input, which is also
-- the next state: one thunk and one node a step.
edgeFrom :: (a -> Bool) -> Bool -> Node a (Event ())
edgeFrom p = afterValue
  where
    afterValue prev = NStep (\_ a -> if prev then afterTrue a else afterFalse a)
    afterEvent prev = NStep (\_ a -> case prev of
      Event () -> afterTrue a
      NoEvent  -> afterFalse a)
    afterTrue a  = (# afterValue (p a), NoEvent #)
    afterFalse a = let e = if p a then Event () else NoEvent in (# afterEvent e, e #)
{-# INLINE edgeFrom #-}

-- | 'edge' with a given value: @edgeTag x = edge >>> arr (`tag` x)@.
edgeTag :: a -> SF Bool (Event a)
edgeTag x = SF (compN (sfNode edge) (arrN (`tag` x)))

-- | An occurrence, carrying the value, whenever the input changes from
-- 'Nothing' to 'Just'. At time 0 the previous value is taken to be a
-- 'Just', so a 'Just' there produces no event.
--
-- As in Yampa, an input that follows a 'Just' is not looked at until the
-- next sample: the output is then 'NoEvent' whatever the input, and the
-- input is evaluated (to tell 'Just' from 'Nothing') at the next sample.
-- So an input that is an error at time 0 gives 'NoEvent' there and
-- raises at the next sample.
edgeJust :: SF (Maybe a) (Event a)
edgeJust = SF (mealyN step True)
  where
    step wasJust m
      | wasJust   = (isJust m, NoEvent)
      | otherwise = case m of
          Just x  -> (True, Event x)
          Nothing -> (False, NoEvent)

-- | The general edge detector: @edgeBy f a0@ applies @f@ to the previous
-- and the current input sample and produces an occurrence whenever it
-- returns 'Just'. At time 0 the previous sample is taken to be @a0@. Each
-- input sample is evaluated (to weak head normal form) at the next sample,
-- or earlier if the output is demanded.
edgeBy :: (a -> a -> Maybe b) -> a -> SF a (Event b)
edgeBy f a0 = SF (mealyN (\prev a -> (a, maybeToEvent (f prev a))) a0)
