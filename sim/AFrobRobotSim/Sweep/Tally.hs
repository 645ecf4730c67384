-- |
-- Module      : AFrobRobotSim.Sweep.Tally
-- Description : The tallies of a group of a sweep's runs (a setting's, or
--               a value's over the others), and the group's lines of the
--               table.
--
-- What "AFrobRobotSim.Sweep.Merge" keeps of each group while the lines
-- are read, a line at a time: the runs and the failed ones, the failures
-- listed (at most 'maxListedFailures', the least by seed), each outcome's
-- count, exact sum, least and greatest value ('Stat'), and the seeds seen
-- ('Seeds', to refuse a run merged twice). Everything is strict and its
-- size does not grow with the runs but for the seeds (a set of integers)
-- and the failures listed. The sums are exact, so the table does not
-- depend on the order of the lines (see "AFrobRobotSim.Sweep").
--
-- Internal: "AFrobRobotSim.Sweep.Merge" alone uses it; exposed, as every
-- module of the library is, but not part of the API that
-- "AFrobRobotSim.Sweep" gives, and free to change.
module AFrobRobotSim.Sweep.Tally
  ( -- * Seeds
    Seed (..)
  , Seeds
  , noSeeds
  , hasSeed
  , withSeed
  , seedsUnion
  , commonSeed
    -- * Outcomes
  , Stat
  , statOf
  , addStat
    -- * Failed runs listed
  , Listed
  , listAdd
  , maxListedFailures
    -- * Groups
  , Group (..)
  , emptyGroup
  , joinGroups
  , groupTable
  ) where

import           Data.Bits           (shiftL)
import qualified Data.IntMap.Strict  as IM
import qualified Data.IntSet         as IS
import qualified Data.Map.Strict     as M
import           Data.List           (sortOn)
import           Data.Ratio          ((%))
import qualified Data.Set            as S
import           Text.Printf         (printf)

-- | The failed runs a group of the table lists, at most: 1000, the least
-- by seed (then by message); the others are counted in a line of their
-- own. (Every failed run is counted in the group's heading.)
maxListedFailures :: Int
maxListedFailures = 1000

-- | A run's seed: as the table writes it (a whole number as such, any
-- other seed as its JSON text), and the key that tells runs apart (an
-- integer, or the text of any other seed).
data Seed = Seed !String !(Either String Int)

-- A sum of doubles, exactly: @m * 2^e@.
data ExactSum = ExactSum !Integer !Int

addExact :: ExactSum -> ExactSum -> ExactSum
addExact a@(ExactSum m1 e1) b@(ExactSum m2 e2)
  | m1 == 0   = b
  | m2 == 0   = a
  | e1 <= e2  = ExactSum (m1 + m2 `shiftL` (e2 - e1)) e1
  | otherwise = addExact b a

exactOf :: Double -> ExactSum
exactOf x = uncurry ExactSum (decodeFloat x)

-- The sum divided by n, rounded once.
exactMean :: ExactSum -> Int -> Double
exactMean (ExactSum m e) n
  | e >= 0    = fromRational ((m `shiftL` e) % fromIntegral n)
  | otherwise = fromRational (m % (fromIntegral n `shiftL` negate e))

-- | One outcome over a group's runs: where it is first named (the least
-- seed, as text, and its place in that run's line: the table's order),
-- how many runs gave a finite value and how many @null@, their exact sum,
-- least and greatest.
data Stat = Stat !(String, Int) !Int !Int !ExactSum !Double !Double

-- | The tally of one run's value ('Nothing': @null@), first named at
-- the given place.
statOf :: (String, Int) -> Maybe Double -> Stat
statOf at (Just x) = Stat at 1 0 (exactOf x) x x
statOf at Nothing  = Stat at 0 1 (ExactSum 0 0) 0 0

-- | Two tallies of one outcome as one.
addStat :: Stat -> Stat -> Stat
addStat (Stat f1 n1 z1 s1 lo1 hi1) (Stat f2 n2 z2 s2 lo2 hi2) =
  Stat (min f1 f2) (n1 + n2) (z1 + z2) (addExact s1 s2) lo hi
  where
    (lo, hi) | n1 == 0   = (lo2, hi2)
             | n2 == 0   = (lo1, hi1)
             | otherwise = (min lo1 lo2, max hi1 hi2)

-- | Seeds seen: the integers, and the text of any other.
data Seeds = Seeds !IS.IntSet !(S.Set String)

-- | No seed seen.
noSeeds :: Seeds
noSeeds = Seeds IS.empty S.empty

-- | Whether a seed is among those seen.
hasSeed :: Seed -> Seeds -> Bool
hasSeed (Seed _ k) (Seeds is ts) = either (`S.member` ts) (`IS.member` is) k

-- | The seeds seen in either.
seedsUnion :: Seeds -> Seeds -> Seeds
seedsUnion (Seeds is1 ts1) (Seeds is2 ts2) = Seeds (IS.union is1 is2) (S.union ts1 ts2)

-- | The seeds seen, and this one.
withSeed :: Seed -> Seeds -> Seeds
withSeed (Seed _ k) (Seeds is ts) = either (\t -> Seeds is (S.insert t ts)) (\i -> Seeds (IS.insert i is) ts) k

-- | A group's tallies: its runs, its failed runs (those listed, by seed and
-- message, with how many of each), each outcome's 'Stat' (by the number
-- of its name), and the seeds of its runs: of the sweep's lines for runs
-- with no result, of all result lines, and of the result lines of each
-- time step and duration.
data Group = Group
  { gRuns    :: !Int                                   -- ^ runs
  , gFailed  :: !Int                                   -- ^ failed runs
  , gListed  :: !Listed                                -- ^ failed runs listed
  , gStats   :: !(IM.IntMap Stat)                      -- ^ each outcome's tally, by its name's number
  , gNoRes   :: !Seeds                                 -- ^ seeds of the sweep's lines for runs with no result
  , gResults :: !Seeds                                 -- ^ seeds of the result lines
  , gBySteps :: !(M.Map (String, String, String) Seeds) -- ^ seeds of the result lines by dt, seconds and noise
  }

-- | The tallies of no run.
emptyGroup :: Group
emptyGroup = Group 0 0 (Listed 0 M.empty) IM.empty noSeeds noSeeds M.empty

-- | The failed runs a group lists: how many, and by seed and message, with
-- how many of each; the least ones, at most 'maxListedFailures'.
data Listed = Listed !Int !(M.Map (String, String) Int)

-- | Add a failed run (its seed and message) to the list.
listAdd :: (String, String) -> Listed -> Listed
listAdd key (Listed n m)
  | n < maxListedFailures = Listed (n + 1) (M.insertWith (+) key 1 m)
  | otherwise = case M.lookupMax m of
      Just (top, _) | key < top -> Listed n (M.insertWith (+) key 1 (M.updateMax (\k -> if k > 1 then Just (k - 1) else Nothing) m))
      _                         -> Listed n m

-- The listed failed runs, by seed and message.
listedRuns :: Listed -> [(String, String)]
listedRuns (Listed _ m) = [ key | (key, k) <- M.toList m, _ <- [1 .. k] ]

-- | The least seed in both (as the table writes it), if any: a run
-- merged twice when two groups are filed as one.
commonSeed :: Seeds -> Seeds -> Maybe String
commonSeed (Seeds is1 ts1) (Seeds is2 ts2) =
  case (fst <$> IS.minView (IS.intersection is1 is2), S.lookupMin (S.intersection ts1 ts2)) of
    (Just i, _) -> Just (show i)
    (_, Just t) -> Just t
    _           -> Nothing

-- | Two groups' runs as one: the runs and failures counted, the failures
-- listed and the outcomes' tallies added; with @keepSeeds@ the seeds seen
-- too (a setting's group, which a mixed run or a run merged twice is
-- told by), otherwise none (a group of the per-value lines, whose seeds
-- are never asked).
joinGroups :: Bool -> Group -> Group -> Group
joinGroups keepSeeds a b =
  Group (gRuns a + gRuns b) (gFailed a + gFailed b) (foldr listAdd (gListed a) (listedRuns (gListed b)))
        (IM.unionWith addStat (gStats a) (gStats b)) (seeds gNoRes) (seeds gResults)
        (if keepSeeds then M.unionWith seedsUnion (gBySteps a) (gBySteps b) else M.empty)
  where
    seeds f = if keepSeeds then seedsUnion (f a) (f b) else noSeeds

-- | One group's lines of the table (given the outcomes' names by their
-- numbers, and the group's name): its heading, its outcomes (in the
-- order the runs, by seed, first name them), its failed runs by seed.
groupTable :: IM.IntMap String -> String -> Group -> [String]
groupTable nameOf heading g =
  [ "== " ++ heading ++ printf "  (%d runs, %d failed)" (gRuns g) (gFailed g) ]
  ++ [ printf "  %-28s %14s %14s %14s" ("outcome" :: String) ("mean" :: String) ("min" :: String) ("max" :: String)
     | not (IM.null (gStats g)) ]
  ++ map row (sortOn (\(k, Stat at _ _ _ _ _) -> (at, k)) [ (IM.findWithDefault "?" i nameOf, s) | (i, s) <- IM.toList (gStats g) ])
  ++ [ "  FAILED seed " ++ seed ++ ": " ++ f | (seed, f) <- listedRuns (gListed g) ]
  ++ [ printf "  and %d more failed runs (the first %d by seed are listed)" unlisted listed | unlisted > 0 ]
  where
    Listed listed _ = gListed g
    unlisted = gFailed g - listed
    row (name, Stat _ have other total lo hi) =
      printf "  %-28s %14s %14s %14s" name (orNA (exactMean total have)) (orNA lo) (orNA hi)
      ++ (if other > 0 then printf "  (%d runs; %d not a finite number)" have other
          else if have < gRuns g then printf "  (%d runs)" have else "")
      where orNA x = if have == 0 then "n/a" else number x
    number :: Double -> String
    number x
      | x /= 0 && (abs x < 1e-3 || abs x >= 1e7) = printf "%.4e" x
      | otherwise                                 = printf "%.4f" x
