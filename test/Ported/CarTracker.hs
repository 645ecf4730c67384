{-# LANGUAGE DeriveFunctor #-}
-- | A small car tracker written as a Yampa program would be: the tracks
-- are kept in the program's own collection type, keyed by car id, with
-- only a 'Functor' instance; 'dpSwitch' adds a track for each new car and
-- drops each track lost for 2 s. It uses Yampa's 'dup', 'sscan',
-- 'provided' and 'recur'. Only the import differs from the Yampa version
-- (@import FRP.Yampa@ instead of @import AFRP@).
module Ported.CarTracker
  ( CarId
  , Sighting
  , Status (..)
  , Report (..)
  , Tracks (..)
  , tracker
  ) where

import qualified Data.Map as M
import           Data.Maybe (fromMaybe, isJust)

import           AFRP

type CarId = Int

-- | One sample's sightings: the position of each car seen.
type Sighting = [(CarId, Double)]

data Status = Seen | Coasting | Lost
  deriving (Eq, Show)

-- | What a track says at a sample: the last known position, the status,
-- and whether its once-a-second heartbeat is due.
data Report = Report { position :: Double, status :: Status, heartbeat :: Bool }
  deriving (Eq, Show)

-- | The program's own collection: a map behind a newtype with only Functor.
newtype Tracks a = Tracks (M.Map CarId a)
  deriving (Show, Functor)

-- | One car's track, started where the car was first seen. Seen while
-- sighted; when not, coasting for 2 s, then lost.
track :: Double -> SF (Maybe Double) Report
track p0 = (arr dup >>> (sscan fromMaybe p0 *** statusOf)) &&& recur (after 1 ())
           >>> arr (\((p, s), beat) -> Report p s (isEvent beat))
  where
    statusOf = provided isJust (constant Seen)
                 (switch (constant Coasting &&& after 2 ()) (\() -> constant Lost))

-- | Each track sees its own car's sighting.
route :: Sighting -> Tracks sf -> Tracks (Maybe Double, sf)
route seen (Tracks m) = Tracks (M.mapWithKey (\i sf -> (lookup i seen, sf)) m)

-- | New cars (seen but untracked) and lost tracks, if any.
changes :: (Sighting, Tracks Report) -> Event (Sighting, [CarId])
changes (seen, Tracks rs)
  | null new && null lost = NoEvent
  | otherwise             = Event (new, lost)
  where
    new  = M.toList (M.fromList [(i, p) | (i, p) <- seen, not (M.member i rs)])
    lost = [i | (i, r) <- M.toList rs, status r == Lost]

-- | The tracker: every track runs in parallel; at each change the
-- collection is rebuilt (the tracks kept resume where they were).
tracker :: Tracks (SF (Maybe Double) Report) -> SF Sighting (Tracks Report)
tracker ts = dpSwitch route ts (arr changes) $ \(Tracks sfs) (new, lost) ->
  tracker (Tracks (foldr M.delete (M.union sfs (M.fromList [(i, track p) | (i, p) <- new])) lost))
