{-# LANGUAGE BangPatterns #-}
{-# LANGUAGE GADTs        #-}
-- |
-- Module      : AFRP.Test.LTL
-- Description : Linear temporal logic over signal functions on finite
--               sample streams: yampa-test's future operators, time
--               bounds, past operators, and explanations of failures.
--
-- A temporal predicate ('TPred') is evaluated at time 0 of a finite
-- 'SignalSampleStream'. Its atoms are signal functions from the input to
-- 'Bool' ('SP'); each atom runs once over the whole stream from time 0, so
-- an atom under 'Always' or 'Eventually' keeps its state from sample to
-- sample, and the truth of @SP sf@ at a sample is @sf@'s output there. This
-- is yampa-test's meaning. afrp reads the stream once, from time 0,
-- carrying forward what the formula still owes the samples to come, and
-- stops at the sample that decides: a predicate costs time linear in the
-- stream (times the windows open at once, for the time-bounded forms) and
-- keeps no sample (see 'evalT').
--
-- A finite stream ends: each operator says below what it means at the last
-- sample, where there is no next one. The rule, as in yampa-test, is that
-- the missing future does not count against a predicate ('Next' is true at
-- the end), except for 'Eventually', which must be seen to happen.
--
-- Design note: 'TPred' exports exactly yampa-test's nine constructors. The
-- time-bounded forms 'eventuallyWithin' and 'alwaysFor' measure time from
-- the sample the enclosing operator is at, which no atom can see (an atom
-- runs from time 0), so they are two further constructors that are not
-- exported. Past-time operators need no constructor: the past is what a
-- signal function sees, so they are signal functions to use inside 'SP'.
-- For the same reason a predicate over a view of the samples (one robot
-- of a world, a field of a record) needs no constructor either: 'tPredOn'
-- puts the view in front of every atom, and since every atom runs from
-- time 0 the view does too, which is exactly the view's stream.
module AFRP.Test.LTL
  ( -- * Temporal predicates
    TPred (SP, And, Or, Not, Implies, Always, Eventually, Next, Until)
  , evalT
    -- * Time-bounded future
  , eventuallyWithin
  , alwaysFor
    -- * Explaining a failure
  , Explanation (..)
  , explainT
  , showExplanation
    -- * Past time, as signal functions
  , previously
  , hasAlwaysBeen
  , hasEverBeen
  , since
    -- ** yampa-test's names
  , andSF
  , orSF
  , notSF
  , impliesSF
  , sofarSF
  , everSF
  , lastSF
  , untilSF
    -- * Rewriting predicates
  , tPredMap
  , tPredOn
  ) where

import           Data.IntMap      (IntMap)
import qualified Data.IntMap      as IntMap
import           Data.IntSet      (IntSet)
import qualified Data.IntSet      as IntSet
import           Data.Set         (Set)
import qualified Data.Set         as Set

import           AFRP             (DTime, SF, arr, evalAt, evalAtZero, iPre, localTime, sscan,
                                   (&&&), (>>>))

import           AFRP.Test.Stream

-- | A temporal predicate over a signal of @a@.
data TPred a where
  -- | A signal predicate: true at a sample when the signal function's
  -- output there is 'True'. The signal function starts at time 0 of the
  -- stream, wherever the atom sits in the formula.
  SP         :: SF a Bool -> TPred a
  -- | Both hold at this sample.
  And        :: TPred a -> TPred a -> TPred a
  -- | Either holds at this sample.
  Or         :: TPred a -> TPred a -> TPred a
  -- | It does not hold at this sample.
  Not        :: TPred a -> TPred a
  -- | If the first holds at this sample, so does the second.
  Implies    :: TPred a -> TPred a -> TPred a
  -- | It holds at this sample and at every later one. At the last sample:
  -- it holds there.
  Always     :: TPred a -> TPred a
  -- | It holds at this sample or at a later one. At the last sample: it
  -- holds there (a stream that ends before it happens fails it).
  Eventually :: TPred a -> TPred a
  -- | It holds at the next sample. At the last sample: true (nothing is
  -- known against it).
  Next       :: TPred a -> TPred a
  -- | @Until p q@: @q@ holds at this sample, or @p@ does and @Until p q@
  -- holds at the next sample. At the last sample: @p@ or @q@ holds there
  -- (a weak until: @p@ holding to the end of the stream is enough).
  Until      :: TPred a -> TPred a -> TPred a
  -- Not exported: built by 'eventuallyWithin' and 'alwaysFor'.
  EventuallyWithin :: DTime -> TPred a -> TPred a
  AlwaysFor        :: DTime -> TPred a -> TPred a

-- | @eventuallyWithin d p@: @p@ holds at some sample no more than @d@
-- seconds after this one (this one included; up to a relative rounding
-- slack of 1e-9, so that three steps of 0.1 are within 0.3).
--
-- At the end of the stream: if the stream ends less than @d@ after this
-- sample and @p@ has not held, true (the deadline has not passed; as for
-- 'Next', the missing future does not count against it). So a 'False' is a
-- real miss of the deadline. A stream whose last sample is @d@ after this
-- one (within the slack) has shown the whole window: there a @p@ that never
-- held is 'False'.
--
-- A bound that is negative or NaN is an error naming it. An infinite bound
-- is a deadline that never passes: on a stream that ends it is true
-- where @p@ never held ('Eventually' is false there).
eventuallyWithin :: DTime -> TPred a -> TPred a
eventuallyWithin d = EventuallyWithin (checkBound "eventuallyWithin" d)

-- | @alwaysFor d p@: @p@ holds at this sample and at every sample no more
-- than @d@ seconds after it (with the slack of 'eventuallyWithin').
--
-- At the end of the stream: the samples there are must hold (the missing
-- ones do not count against it). A bound that is negative or NaN is an
-- error naming it, as for 'eventuallyWithin'.
alwaysFor :: DTime -> TPred a -> TPred a
alwaysFor d = AlwaysFor (checkBound "alwaysFor" d)

-- A time bound, or the error of one that is negative or NaN (when the
-- predicate is evaluated).
checkBound :: String -> DTime -> DTime
checkBound name d
  | isNaN d || d < 0 = error ("AFRP.Test.LTL." ++ name ++ ": the time bound must be a number >= 0, got " ++ show d)
  | otherwise        = d

-- | Whether the predicate holds at time 0 of the stream, with the meaning
-- at the end of the stream given for each constructor. The empty stream
-- has no time 0: every predicate is true on it (so there @Not p@ is not
-- the complement of @p@); the generators never produce it.
--
-- How it is decided: the stream is read once, from time 0, and reading
-- stops at the first sample after which the answer is known whatever
-- samples follow: an 'Always' broken, an 'Eventually' met, at any depth
-- of the formula and in either operand of a connective (so @And (Always
-- p) (Eventually q)@ stops where @p@ first fails, even if @q@ never
-- holds). Memory: no sample is kept, only what the formula still owes
-- the samples to come, each obligation once however often it arose:
-- @Always (Implies p (Eventually q))@ owes one @Eventually q@ however
-- many samples of @p@ wait for it, so it runs in constant memory whether
-- @q@ holds now and then or never. A time-bounded form owes one window
-- for each sample whose window is still open (@Always (eventuallyWithin
-- d p)@: the samples of the last @d@ seconds, at most; a window that
-- never ends, of an infinite bound, is one obligation). Time: linear in
-- the stream, times the size of what is owed at once: under a microsecond
-- a sample for the usual properties, tens of microseconds for windows
-- nested under 'Always' or 'Eventually' or future operators nested in
-- 'Until' (see bench/README.md, the forty-third round).
--
-- Atoms: every atom runs from time 0 of the stream. It is stepped at each
-- sample while some part of the formula containing it is undecided (its
-- state is evaluated there, so that it holds no samples), and dropped
-- once none is; its output at a sample is evaluated where the formula
-- reads it. Both operands of a connective are read from time 0 (yampa-test
-- and the kit before read the second only if the first did not decide):
-- an atom that throws in either throws from 'evalT' unless the samples
-- decided the formula first.
evalT :: TPred a -> SignalSampleStream a -> Bool
evalT p s = case monitor p s of
  Nothing -> True
  Just _  -> False

-- | Where a predicate failed on a stream.
data Explanation a = Explanation
  { explFrame   :: Int
    -- ^ the index of the sample (0 = time 0) at which the predicate was
    -- decided false: the samples up to it already falsify it, whatever
    -- follows (or it is the last sample, for a failure the end decides)
  , explTime    :: DTime
    -- ^ that sample's time since the start of the stream
  , explAround  :: [(Int, DTime, a)]
    -- ^ the samples around it (up to three before and two after), with
    -- their index and time
  } deriving (Show)

-- | @explainT p s@ is 'Nothing' when @'evalT' p s@ holds, and otherwise
-- the first sample at which the predicate was decided false: the
-- shortest prefix of the stream after which the formula, operator by
-- operator, is false whatever samples follow (the whole stream, when only
-- its end decides, as for 'Eventually'). A formula false by logic alone
-- (@And p (Not p)@ of an 'Eventually') is decided where the samples
-- decide its parts, not at time 0.
--
-- It is 'evalT' with the samples around the deciding one kept: it reads
-- the stream up to that sample and two more, in 'evalT''s memory, so a
-- failure late in a long run made lazily is explained in the memory of
-- an early one.
explainT :: TPred a -> SignalSampleStream a -> Maybe (Explanation a)
explainT = monitor

-- The monitor behind 'evalT' and 'explainT': the formula is carried
-- forward sample by sample ("formula progression"). At each sample every
-- temporal operator is split into what the sample decides now and what
-- it owes the next samples ('Always a' is 'a' now and 'Always a' owed,
-- 'Next a' is 'a' owed, 'eventuallyWithin d a' is 'a' now or its window
-- owed while the window lasts); what is owed is a combination of
-- obligations ('Res'), simplified ('combine'): the answer is known when
-- it is a constant.
--
-- This is exactly Kleene's three-valued reading of the formula on the
-- samples seen so far, the samples beyond unknown: the combination is
-- never a constant while an unknown could change it, because constants
-- are simplified away wherever they occur and an obligation is unknown
-- until its samples come. At the end of the stream the obligations
-- left meet the end as each operator says ('closeRes').
monitor :: TPred a -> SignalSampleStream a -> Maybe (Explanation a)
monitor _ [] = Nothing
monitor p ((_, a0) : rest0) = go 0 0 a0 res0 atoms0 clockAtStart [] rest0
  where
    (root, sfs) = compileT p
    atoms0 = IntMap.fromDistinctAscList (zip [0 ..] [ evalAtZero sf a0 | sf <- sfs ])
    res0 = now (Here 0 (fmap fst atoms0)) root
    -- @go j t a res atoms clock recent rest@: at sample @j@ (time @t@,
    -- value @a@), with @res@ what the formula is there; @atoms@ the atoms
    -- started or stepped there, @clock@ the stream's clock, @recent@ up
    -- to three samples before, newest first.
    go !j !t a res atoms clock !recent rest = case res of
      RConst True  -> Nothing
      RConst False -> Just (explanation j t a recent clock rest)
      _ -> case rest of
        [] | closeRes res -> Nothing
           | otherwise    -> Just (explanation j t a recent clock [])
        (dt, a') : rest' ->
          let !atoms' = stepAtoms (liveAtoms res) atoms dt a'
              (t', clock') = evalAt clock dt ()
              res' = advance (Here (j + 1) (fmap fst atoms')) dt res
          in t' `seq` go (j + 1) t' a' res' atoms' clock' (keep3 (j, t, a) recent) rest'
    keep3 x r = case r of
      y : z : _ -> [x, y, z]
      _         -> x : r
    -- (the two samples after the deciding one, timed by the stream's clock)
    explanation j t a recent clock rest = Explanation
      { explFrame  = j
      , explTime   = t
      , explAround = reverse recent ++ (j, t, a) : after (j + 1) (2 :: Int) clock rest
      }
    after k n clock xs
      | n <= 0    = []
      | otherwise = case xs of
          (dt, x) : xs' -> let (tk, clock') = evalAt clock dt () in (k, tk, x) : after (k + 1) (n - 1) clock' xs'
          []            -> []

-- The live atoms stepped by one sample (each state evaluated, so that an
-- atom holds no chain of samples), the others dropped.
stepAtoms :: IntSet -> IntMap (Bool, FutureSF a Bool) -> DTime -> a -> IntMap (Bool, FutureSF a Bool)
stepAtoms live atoms dt a = IntMap.fromDistinctAscList
  [ r | k <- IntSet.toAscList live
      , Just (_, sf) <- [IntMap.lookup k atoms]
      , let r = (k, evalAt sf dt a)
      , snd (snd r) `seq` True ]

-- A formula compiled for the monitor: each node numbered (the number
-- names what a node owes, see 'Pending'), with the atoms below it; the
-- atoms are numbered in the order of their signal functions.
data Node = Node !Int !IntSet Shape

data Shape
  = NAtom !Int
  | NAnd Node Node
  | NOr Node Node
  | NNot Node
  | NImplies Node Node
  | NAlways Node
  | NEventually Node
  | NNext Node
  | NUntil Node Node
  | NWithin !DTime Node
  | NFor !DTime Node

nodeAtoms :: Node -> IntSet
nodeAtoms (Node _ atoms _) = atoms

-- The formula as nodes, and its atoms' signal functions by number.
compileT :: TPred a -> (Node, [SF a Bool])
compileT p0 = case build p0 0 [] of
  (node, _, sfs) -> (node, reverse sfs)
  where
    -- @build p n sfs@: @p@ with its nodes numbered from @n@, its atoms
    -- from @length sfs@ (@sfs@ the atoms so far, newest first); the next
    -- free node number and the atoms after it.
    build :: TPred a -> Int -> [SF a Bool] -> (Node, Int, [SF a Bool])
    build p n sfs = case p of
      SP sf                -> let k = length sfs in (Node n (IntSet.singleton k) (NAtom k), n + 1, sf : sfs)
      And a b              -> two NAnd a b
      Or a b               -> two NOr a b
      Implies a b          -> two NImplies a b
      Until a b            -> two NUntil a b
      Not a                -> one NNot a
      Always a             -> one NAlways a
      Eventually a         -> one NEventually a
      Next a               -> one NNext a
      EventuallyWithin d a -> one (NWithin d) a
      AlwaysFor d a        -> one (NFor d) a
      where
        one f a = let (na, n', sfs') = build a (n + 1) sfs
                  in (Node n (nodeAtoms na) (f na), n', sfs')
        two f a b = let (na, n', sfs')   = build a (n + 1) sfs
                        (nb, n'', sfs'') = build b n' sfs'
                    in (Node n (IntSet.union (nodeAtoms na) (nodeAtoms nb)) (f na nb), n'', sfs'')

-- What a formula is at a sample: a constant once decided, otherwise a
-- combination of obligations on the samples to come, each obligation
-- owed ('RLit' 'True') or its negation owed ('RLit' 'False'): negations
-- are pushed down to the obligations (De Morgan's laws hold in Kleene's
-- logic). 'RAll' and 'RAny' hold two or more parts, none a constant nor
-- a combination of their own kind (see 'combine'); equal parts are one
-- ('Pending''s order), which is what keeps memory bounded.
data Res
  = RConst !Bool
  | RAll !(Set Res)
  | RAny !(Set Res)
  | RLit !Bool !Pending
  deriving (Eq, Ord)

-- An obligation: what the node numbered 'pendNode' owes from the next
-- sample on. Two are the same obligation when they have the same node and
-- start: a window's start is the sample it opened at (its clock and
-- whether it reached its bound follow from it), the others' is -1 (what
-- 'Always a' owes does not depend on when it was owed, nor what a window
-- that never ends owes).
data Pending = Pending
  { pendNode  :: !Int
  , pendStart :: !Int
  , pendOwed  :: Owed
  }

instance Eq Pending where
  x == y = pendNode x == pendNode y && pendStart x == pendStart y

instance Ord Pending where
  compare x y = compare (pendNode x) (pendNode y) <> compare (pendStart x) (pendStart y)

data Owed
  = OwesAlways Node
  | OwesEventually Node
  | OwesNext Node
  | OwesUntil Node Node
    -- (a window: its bound, its clock from where it opened, and whether a
    -- sample in it was at the bound, within the slack)
  | OwesWithin !DTime (FutureSF () DTime) !Bool Node
  | OwesFor !DTime (FutureSF () DTime) !Bool Node

-- A sample as the monitor sees it: its index, and the atoms' outputs there
-- (evaluated only where read).
data Here = Here !Int (IntMap Bool)

atomAt :: Here -> Int -> Bool
atomAt (Here j outs) k = IntMap.findWithDefault missing k outs
  where missing = error ("AFRP.Test.LTL: atom " ++ show k ++ " was not stepped to sample " ++ show j
                         ++ " (a fault of afrp-test; please report it)")

-- What a node is at this sample.
now :: Here -> Node -> Res
now here@(Here j _) (Node n _ shape) = case shape of
  NAtom k       -> RConst (atomAt here k)
  NAnd a b      -> allOf [now here a, now here b]
  NOr a b       -> anyOf [now here a, now here b]
  NNot a        -> rNot (now here a)
  NImplies a b  -> anyOf [rNot (now here a), now here b]
  NAlways a     -> allOf [now here a, owes (OwesAlways a)]
  NEventually a -> anyOf [now here a, owes (OwesEventually a)]
  NNext a       -> owes (OwesNext a)
  NUntil a b    -> anyOf [now here b, allOf [now here a, owes (OwesUntil a b)]]
  NWithin d a   -> anyOf [now here a, window d (OwesWithin d clockAtStart (atBound d 0) a)]
  NFor d a      -> allOf [now here a, window d (OwesFor d clockAtStart (atBound d 0) a)]
  where
    owes = RLit True . Pending n (-1)
    -- (a window that never ends owes the same whenever it opened: one
    -- obligation, as for 'Always' and 'Eventually')
    window d | isInfinite d = owes
             | otherwise    = RLit True . Pending n j

-- A clock where it starts (at 0): the stream's, and each window's.
clockAtStart :: FutureSF () DTime
clockAtStart = snd (evalAtZero localTime ())

-- Whether a window of bound @d@ is at its bound @e@ seconds after it
-- opened, within the relative slack of 'timeSlack'. An infinite window
-- never is.
atBound :: DTime -> DTime -> Bool
atBound d e = not (isInfinite d) && e >= d - timeSlack d

-- What a combination is at the next sample (its index and atoms given),
-- @dt@ after this one.
advance :: Here -> DTime -> Res -> Res
advance here dt res = case res of
  RConst b        -> RConst b
  RAll xs         -> allOf (map (advance here dt) (Set.toList xs))
  RAny xs         -> anyOf (map (advance here dt) (Set.toList xs))
  RLit True pend  -> paid here dt pend
  RLit False pend -> rNot (paid here dt pend)

-- What an obligation comes to at the sample it is owed to.
paid :: Here -> DTime -> Pending -> Res
paid here dt pend@(Pending _ _ owed) = case owed of
  OwesAlways a      -> allOf [now here a, RLit True pend]
  OwesEventually a  -> anyOf [now here a, RLit True pend]
  OwesNext a        -> now here a
  OwesUntil a b     -> anyOf [now here b, allOf [now here a, RLit True pend]]
  OwesWithin d clock reachedBound a -> case evalAt clock dt () of
    (e, clock') | e <= d + timeSlack d -> anyOf [now here a, RLit True pend { pendOwed = OwesWithin d clock' (reachedBound || atBound d e) a }]
                | otherwise            -> RConst False   -- (the window has passed: missed)
  OwesFor d clock reachedBound a -> case evalAt clock dt () of
    (e, clock') | e <= d + timeSlack d -> allOf [now here a, RLit True pend { pendOwed = OwesFor d clock' (reachedBound || atBound d e) a }]
                | otherwise            -> RConst True

-- The conjunction and the disjunction of parts, stopping at the first
-- part that decides (the later ones are not evaluated).
allOf, anyOf :: [Res] -> Res
allOf = combine False
anyOf = combine True

-- @combine decisive parts@: the conjunction ('False' decides it) or the
-- disjunction ('True' decides it) of the parts, simplified by the laws
-- that hold in Kleene's logic (a distributive lattice), so that a
-- combination owed for many samples stays small:
--
-- * constants: a decisive one is the answer, the other is dropped;
-- * a combination of the same kind is flattened into this one, equal
--   parts are one;
-- * a part is, inside the other parts, the constant it would have to be
--   for them to matter (absorption: @x or (x and y)@ is @x@, @x or (y and
--   (x or z))@ is @x or (y and z)@, for any parts @x@, obligations or
--   combinations: @x or f(x)@ is @x or f(false)@ for every @f@ made of
--   'and' and 'or').
--
-- None of these changes the value of the combination when the
-- obligations are unknown, nor makes a combination a constant while they
-- are: the result is decided exactly when Kleene's reading of the formula
-- on the samples seen so far is. (Each part is rewritten with the others
-- as they were: a part is only ever found inside a larger one, so the
-- rewriting is the same as one part after another, largest first.)
combine :: Bool -> [Res] -> Res
combine decisive parts = case gather Set.empty parts of
  Nothing -> RConst decisive
  Just acc
    | all isLiteral acc -> made acc
    | otherwise ->
        maybe (RConst decisive) made
          (gather Set.empty [ absorbed (Set.delete part acc) part | part <- Set.toList acc ])
  where
    -- (the parts as a set, or Nothing when one decides)
    gather !acc [] = Just acc
    gather !acc (r : rs) = case r of
      RConst b | b == decisive -> Nothing
               | otherwise     -> gather acc rs
      RAll xs | not decisive   -> gather (Set.union xs acc) rs
      RAny xs | decisive       -> gather (Set.union xs acc) rs
      _                        -> gather (Set.insert r acc) rs
    made acc = case Set.size acc of
      0 -> RConst (not decisive)
      1 -> Set.findMin acc
      _ | decisive  -> RAny acc
        | otherwise -> RAll acc
    isLiteral r = case r of
      RLit _ _ -> True
      _        -> False
    -- (a part's own parts, the others taken to be the constant that
    -- does not decide)
    absorbed others part
      | contains others part = case part of
          RAll xs -> allOf (map (assume others (not decisive)) (Set.toList xs))
          RAny xs -> anyOf (map (assume others (not decisive)) (Set.toList xs))
          _       -> part
      | otherwise = part

-- @assume parts b r@: @r@ with each of @parts@ found in it taken to be
-- @b@, simplified (only where one is found: the rest is kept as it is).
assume :: Set Res -> Bool -> Res -> Res
assume parts b r
  | Set.member r parts    = RConst b
  | not (contains parts r) = r
  | otherwise = case r of
      RAll xs -> allOf (map (assume parts b) (Set.toList xs))
      RAny xs -> anyOf (map (assume parts b) (Set.toList xs))
      _       -> r

-- Whether one of @parts@ is found inside @r@ (not @r@ itself).
contains :: Set Res -> Res -> Bool
contains parts r = case r of
  RAll xs -> any found (Set.toList xs)
  RAny xs -> any found (Set.toList xs)
  _       -> False
  where found x = Set.member x parts || contains parts x

-- The negation, pushed down to the obligations.
rNot :: Res -> Res
rNot r = case r of
  RConst b   -> RConst (not b)
  RLit s p   -> RLit (not s) p
  RAll xs    -> anyOf (map rNot (Set.toList xs))
  RAny xs    -> allOf (map rNot (Set.toList xs))

-- The atoms a combination's obligations read.
liveAtoms :: Res -> IntSet
liveAtoms r = case r of
  RConst _ -> IntSet.empty
  RAll xs  -> IntSet.unions (map liveAtoms (Set.toList xs))
  RAny xs  -> IntSet.unions (map liveAtoms (Set.toList xs))
  RLit _ (Pending _ _ owed) -> case owed of
    OwesAlways a       -> nodeAtoms a
    OwesEventually a   -> nodeAtoms a
    OwesNext a         -> nodeAtoms a
    OwesUntil a b      -> IntSet.union (nodeAtoms a) (nodeAtoms b)
    OwesWithin _ _ _ a -> nodeAtoms a
    OwesFor _ _ _ a    -> nodeAtoms a

-- What a combination is at the end of the stream: each obligation meets
-- the end as its operator says ('Always', 'Next', 'Until' and 'alwaysFor'
-- true, 'Eventually' false, 'eventuallyWithin' false if a sample was at
-- its bound, true if the stream ended before it).
closeRes :: Res -> Bool
closeRes r = case r of
  RConst b -> b
  RAll xs  -> all closeRes (Set.toList xs)
  RAny xs  -> any closeRes (Set.toList xs)
  RLit s (Pending _ _ owed) -> s == case owed of
    OwesAlways _                  -> True
    OwesEventually _              -> False
    OwesNext _                    -> True
    OwesUntil _ _                 -> True
    OwesWithin _ _ reachedBound _ -> not reachedBound
    OwesFor _ _ _ _               -> True
-- | The explanation as a small table: index, time, value, with the sample
-- that decided marked with @>@.
showExplanation :: Show a => Explanation a -> String
showExplanation e = unlines $
  ("decided false at sample " ++ show (explFrame e) ++ ", t = " ++ show (explTime e) ++ ":")
  : [ (if j == explFrame e then "  > " else "    ") ++ pad 5 (show j) ++ pad 12 (show t) ++ show a
    | (j, t, a) <- explAround e ]
  where pad w str = str ++ replicate (max 1 (w - length str)) ' '

-- | @previously p@: @p@ held at the previous sample. False at time 0.
previously :: SF a Bool -> SF a Bool
previously p = p >>> lastSF

-- | @hasAlwaysBeen p@: @p@ has held at every sample so far, this one
-- included.
hasAlwaysBeen :: SF a Bool -> SF a Bool
hasAlwaysBeen p = p >>> sofarSF

-- | @hasEverBeen p@: @p@ has held at some sample so far, this one included.
hasEverBeen :: SF a Bool -> SF a Bool
hasEverBeen p = p >>> everSF

-- | @p \`since\` q@: @q@ has held at some sample so far (this one
-- included), and @p@ at every sample after the latest such one (this one
-- included). At time 0: @q@ holds.
since :: SF a Bool -> SF a Bool -> SF a Bool
since p q = (p &&& q) >>> sscan (\before (vp, vq) -> vq || (vp && before)) False

-- | Conjunction of two boolean signals, sample by sample.
andSF :: SF (Bool, Bool) Bool
andSF = arr (uncurry (&&))

-- | Disjunction of two boolean signals, sample by sample.
orSF :: SF (Bool, Bool) Bool
orSF = arr (uncurry (||))

-- | Negation of a boolean signal, sample by sample.
notSF :: SF Bool Bool
notSF = arr not

-- | Implication between two boolean signals, sample by sample.
impliesSF :: SF (Bool, Bool) Bool
impliesSF = arr (\(a, b) -> not a || b)

-- | True while the input has been true at every sample so far (this one
-- included); false from the first false input on.
sofarSF :: SF Bool Bool
sofarSF = sscan (&&) True

-- | True from the first true input on (this one included).
everSF :: SF Bool Bool
everSF = sscan (||) False

-- | The input at the previous sample; false at time 0.
lastSF :: SF Bool Bool
lastSF = iPre False

-- | yampa-test's past until of @(i, u)@: true while @i@ has held at every
-- sample so far; from the first sample at which @u@ holds while the output
-- so far was true (at time 0: while nothing was false yet), it is instead
-- whether @u@ has held at every sample since that one (this one included).
untilSF :: SF (Bool, Bool) Bool
untilSF = sscan step (True, False) >>> arr fst
  where
    -- The state: the output, and whether the switch to @u@ has happened.
    step (prev, switched) (i, u)
      | switched  = (u && prev, True)
      | prev && u = (True, True)
      | otherwise = (prev && i, False)

-- | Apply a function to every atom of a predicate, keeping its shape and
-- time bounds.
tPredMap :: (SF a Bool -> SF a Bool) -> TPred a -> TPred a
tPredMap = atomsWith

-- | @tPredOn view p@: @p@ over what the signal function @view@ makes of
-- the samples (one robot's state out of a world's, a field of a record).
-- It holds of a stream exactly when @p@ holds of the stream of @view@'s
-- outputs:
--
-- > evalT (tPredOn view p) s  ==  evalT p (fst (evalSF view s))
--
-- and 'explainT' decides it false at the same sample and time as @p@ on
-- that stream (its 'explAround' shows the samples of @s@, not @view@'s
-- outputs: a failure is reported in the terms of the whole stream).
--
-- Each atom @SP sf@ becomes @SP (view >>> sf)@; operators and time
-- bounds are kept. An atom runs from time 0 of the stream wherever it
-- sits in the formula, so @view@ does too, which is why this is the
-- predicate on the mapped stream:
--
-- * at time 0 (the first sample), the atoms see @view@'s output at time
--   0, made from the first sample (whose time step, like 'evalSF', it
--   ignores);
-- * a @view@ with state (an 'iPre', an integral, a clock) starts at
--   time 0 and keeps its state from sample to sample: under 'Always',
--   'Next' or a time bound it is never restarted where the operator
--   looks, so @tPredOn (iPre x) p@ is @p@ of the stream delayed by one
--   sample, with @x@ at time 0;
-- * the time bounds ('eventuallyWithin', 'alwaysFor') count the same
--   seconds: @view@'s outputs come at the stream's own times.
--
-- Cost, not meaning: each atom runs a copy of @view@ of its own, so a
-- view costs once per atom of @p@; and lazily, a sample's output of
-- @view@ being made only when an atom reads it (an atom that ignores its
-- input, @arr (const True)@, never makes it).
tPredOn :: SF b a -> TPred a -> TPred b
tPredOn view = atomsWith (view >>>)

-- Every atom of a predicate changed by @f@ (its type too), the operators
-- and time bounds kept: 'tPredMap' and 'tPredOn'.
atomsWith :: (SF a Bool -> SF b Bool) -> TPred a -> TPred b
atomsWith f p = case p of
  SP sf                -> SP (f sf)
  And a b              -> And (atomsWith f a) (atomsWith f b)
  Or a b               -> Or (atomsWith f a) (atomsWith f b)
  Not a                -> Not (atomsWith f a)
  Implies a b          -> Implies (atomsWith f a) (atomsWith f b)
  Always a             -> Always (atomsWith f a)
  Eventually a         -> Eventually (atomsWith f a)
  Next a               -> Next (atomsWith f a)
  Until a b            -> Until (atomsWith f a) (atomsWith f b)
  EventuallyWithin d a -> EventuallyWithin d (atomsWith f a)
  AlwaysFor d a        -> AlwaysFor d (atomsWith f a)
