{-# LANGUAGE DeriveTraversable #-}
-- |
-- Module      : AFRP.Event
-- Description : Events: values that exist only at isolated instants.
--
-- A signal of type @Event a@ is an /event stream/: at each sample it either
-- carries an occurrence ('Event' @x@) or nothing ('NoEvent'). 'Event' is
-- isomorphic to 'Maybe', and has the instances of 'Maybe' that signal code
-- uses ('Eq', 'Ord', 'Show', 'Functor', 'Foldable', 'Traversable',
-- 'Applicative', 'Monad', 'MonadFail', 'Alternative', 'MonadPlus',
-- 'Semigroup', 'Monoid' and 'Control.DeepSeq.NFData'; not 'Read' nor the
-- lifted classes). The constructors are
-- exported, as Yampa does, for scalar code (collision detection, say) that
-- builds events directly; signal-function code should prefer the
-- functions here.
module AFRP.Event
  ( -- * The type
    Event (..)
  , noEvent
  , noEventFst
  , noEventSnd
  , event
  , fromEvent
  , isEvent
  , isNoEvent
  , maybeToEvent
  , eventToMaybe
    -- * Changing the value
  , tag
  , tagWith
  , attach
    -- * Merging
  , lMerge
  , rMerge
  , merge
  , mergeBy
  , mapMerge
  , mergeEvents
  , catEvents
    -- * Combining and splitting
  , joinE
  , splitE
    -- * Filtering
  , filterE
  , mapFilterE
  , gate
  ) where

import           Control.Applicative (Alternative (..))
import           Control.DeepSeq     (NFData (..))
import           Control.Monad       (MonadPlus)

infixl 8 `tag`, `attach`, `gate`
infixl 7 `joinE`
infixl 6 `lMerge`, `rMerge`, `merge`

-- | An event occurrence ('Event' @x@) or the absence of one ('NoEvent').
--
-- Instances follow 'Maybe': 'fmap' changes the value of an occurrence;
-- '<*>' and '>>=' occur only when both sides do; '<|>' is 'lMerge';
-- 'NoEvent' compares less than any occurrence.
data Event a = NoEvent | Event a
  deriving (Eq, Ord, Show, Functor, Foldable, Traversable)

instance Applicative Event where
  pure = Event
  Event f <*> Event x = Event (f x)
  _       <*> _       = NoEvent

instance Monad Event where
  Event x >>= f = f x
  NoEvent >>= _ = NoEvent

instance MonadFail Event where
  fail _ = NoEvent

-- | 'empty' is 'NoEvent'; '<|>' prefers the left occurrence ('lMerge').
instance Alternative Event where
  empty = NoEvent
  (<|>) = lMerge

instance MonadPlus Event

-- | Combines simultaneous occurrences with '<>' (like 'Maybe').
instance Semigroup a => Semigroup (Event a) where
  (<>) = mergeBy (<>)

instance Semigroup a => Monoid (Event a) where
  mempty = NoEvent

instance NFData a => NFData (Event a) where
  rnf NoEvent   = ()
  rnf (Event a) = rnf a

-- | The absence of an occurrence: 'NoEvent'.
noEvent :: Event a
noEvent = NoEvent

-- | Replace the event in the first component of a pair by 'NoEvent' (handy
-- to suppress the event that caused a switch in the continuation's input).
noEventFst :: (Event a, b) -> (Event c, b)
noEventFst (_, b) = (NoEvent, b)

-- | Replace the event in the second component of a pair by 'NoEvent'.
noEventSnd :: (a, Event b) -> (a, Event c)
noEventSnd (a, _) = (a, NoEvent)

-- | The eliminator, like 'maybe': @event d f NoEvent = d@ and
-- @event d f (Event x) = f x@.
event :: a -> (b -> a) -> Event b -> a
event d _ NoEvent   = d
event _ f (Event x) = f x
{-# INLINE event #-}

-- | The value of an occurrence. It is an error (naming this function) to
-- apply it to 'NoEvent'.
fromEvent :: Event a -> a
fromEvent (Event x) = x
fromEvent NoEvent   = error "AFRP.Event.fromEvent: NoEvent has no value"

-- | Is there an occurrence?
isEvent :: Event a -> Bool
isEvent (Event _) = True
isEvent NoEvent   = False

-- | Is there no occurrence?
isNoEvent :: Event a -> Bool
isNoEvent = not . isEvent

-- | 'Just' becomes an occurrence, 'Nothing' becomes 'NoEvent'.
maybeToEvent :: Maybe a -> Event a
maybeToEvent = maybe NoEvent Event

-- | The inverse of 'maybeToEvent'.
eventToMaybe :: Event a -> Maybe a
eventToMaybe = event Nothing Just

-- | Replace the value of an occurrence: @e \`tag\` b = fmap (const b) e@.
tag :: Event a -> b -> Event b
tag e b = fmap (const b) e
{-# INLINE tag #-}

-- | 'tag' with the arguments swapped: @tagWith b e = e \`tag\` b@.
tagWith :: b -> Event a -> Event b
tagWith = flip tag

-- | Pair the value of an occurrence with a given value:
-- @Event a \`attach\` b = Event (a, b)@.
attach :: Event a -> b -> Event (a, b)
attach e b = fmap (\a -> (a, b)) e

-- | Left-biased merge: the left occurrence wins when both occur.
lMerge :: Event a -> Event a -> Event a
lMerge NoEvent r = r
lMerge l       _ = l

-- | Right-biased merge: the right occurrence wins when both occur.
rMerge :: Event a -> Event a -> Event a
rMerge = flip lMerge

-- | Merge two event streams that are never expected to occur together.
-- Simultaneous occurrences are a programming error, reported as such. As
-- in Yampa the merged event still occurs; the error is raised when its
-- /value/ is demanded.
merge :: Event a -> Event a -> Event a
merge = mergeBy (\_ _ -> error
  "AFRP.Event.merge: simultaneous event occurrences (use lMerge, rMerge or mergeBy to choose)")

-- | Merge, combining simultaneous occurrences with the given function
-- (left value first).
mergeBy :: (a -> a -> a) -> Event a -> Event a -> Event a
mergeBy _ NoEvent   r         = r
mergeBy _ l         NoEvent   = l
mergeBy f (Event l) (Event r) = Event (f l r)

-- | Merge events of different types, mapping each side (and both, when
-- they occur together) into a common type.
mapMerge :: (a -> c) -> (b -> c) -> (a -> b -> c) -> Event a -> Event b -> Event c
mapMerge _  _  _  NoEvent   NoEvent   = NoEvent
mapMerge lf _  _  (Event l) NoEvent   = Event (lf l)
mapMerge _  rf _  NoEvent   (Event r) = Event (rf r)
mapMerge _  _  bf (Event l) (Event r) = Event (bf l r)

-- | Merge a list of event streams; the leftmost occurrence wins.
mergeEvents :: [Event a] -> Event a
mergeEvents = foldr lMerge NoEvent

-- | Collect all simultaneous occurrences, in list order; 'NoEvent' when
-- none occurs.
catEvents :: [Event a] -> Event [a]
catEvents es = case [x | Event x <- es] of
  [] -> NoEvent
  xs -> Event xs

-- | Occurs when both occur, with both values. As infix, @infixl 7@
-- (Yampa's): it binds less tightly than 'tag' and more than 'merge', so
-- @e1 \`joinE\` e2 \`tag\` x@ is @e1 \`joinE\` (e2 \`tag\` x)@.
joinE :: Event a -> Event b -> Event (a, b)
joinE (Event a) (Event b) = Event (a, b)
joinE _         _         = NoEvent

-- | Split an event of pairs into a pair of events.
splitE :: Event (a, b) -> (Event a, Event b)
splitE NoEvent        = (NoEvent, NoEvent)
splitE (Event (a, b)) = (Event a, Event b)

-- | Keep only the occurrences whose value satisfies the predicate.
filterE :: (a -> Bool) -> Event a -> Event a
filterE p e@(Event a) | p a = e
filterE _ _                 = NoEvent

-- | Map and filter in one: occurrences mapped to 'Nothing' are dropped.
mapFilterE :: (a -> Maybe b) -> Event a -> Event b
mapFilterE f e = e >>= maybeToEvent . f

-- | Let an occurrence through only when the condition holds.
gate :: Event a -> Bool -> Event a
gate e True = e
gate _ _    = NoEvent
