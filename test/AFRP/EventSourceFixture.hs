-- | What the specs of "AFRP.EventSource"'s modules share: short names for
-- the two event constructors, to write expected streams on one line, and a
-- way to force every occurrence of a run (where an error is expected).
module AFRP.EventSourceFixture
  ( e
  , n
  , forceEvents
  ) where

import           Control.Exception (evaluate)

import           AFRP.Event        (Event (..), isEvent)

e :: a -> Event a
e = Event

n :: Event a
n = NoEvent

-- | Force every output constructor of a run of an event stream.
forceEvents :: [Event a] -> IO Int
forceEvents = evaluate . length . filter isEvent
