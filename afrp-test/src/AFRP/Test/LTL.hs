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
-- is yampa-test's meaning; afrp evaluates each atom once and combines the
-- truth values sample by sample from the end, so a predicate costs time
-- linear in the stream (times the window for the time-bounded forms).
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

import           AFRP             (DTime, SF, arr, iPre, sscan, (&&&), (>>>))

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
-- Memory: the outermost 'Always', 'Eventually' and 'Until' are folded
-- from time 0 on, stopping as soon as the answer is known. Connectives
-- above them ('And', 'Or', 'Implies') decide their operands one after the
-- other, the second only when the first does not decide: the stream is
-- kept while the first is decided, as far as it reads (so @And (Always
-- p) (Eventually q)@ keeps what @Always p@ reads; give two such
-- properties as two checks to keep memory bounded). Under them, what a
-- predicate keeps of a stream made lazily is what it must look ahead:
-- 'Next' one sample, a time-bounded form its window, and a nested
-- 'Always', 'Eventually' or 'Until' the samples up to the next one that
-- decides it whatever follows ('Always' a false, 'Eventually' a true,
-- 'Until' its second argument true or its first false). So @Always (Implies p (Eventually
-- q))@ keeps the samples between two where @q@ holds: constant memory
-- when @q@ holds now and then, the whole stream when it never does. (The
-- stream itself is kept only by whoever else holds it.)
evalT :: TPred a -> SignalSampleStream a -> Bool
evalT _ [] = True
evalT p0 s = atStart p0 == T
  where
    -- (the truth at time 0; every truth list is as long as the stream,
    -- which is not empty)
    atStart p = case p of
      -- (the second operand only when the first does not decide)
      And a b      -> case atStart a of { F -> F; va -> min va (atStart b) }
      Or a b       -> case atStart a of { T -> T; va -> max va (atStart b) }
      Not a        -> notTri (atStart a)
      Implies a b  -> case atStart a of { F -> T; va -> max (notTri va) (atStart b) }
      -- (at the end of the closed stream: 'Always' meets true, 'Eventually' false)
      Always a     -> foldStoppingAt F min T (everywhere a)
      Eventually a -> foldStoppingAt T max F (everywhere a)
      Until a b    -> untilFromStart T F (zip (everywhere a) (everywhere b))
      _            -> case everywhere p of
        v : _ -> v
        []    -> T
    everywhere p = truths Closed maxBound p s
    foldStoppingAt stop op = go
      where go !acc (v : vs) | acc /= stop = go (op acc v) vs
            go acc _                       = acc
    -- @a `Until` b@ at time 0 is the disjunction, over the samples i, of
    -- b at i with a at every sample before i, and of a everywhere with
    -- the end's true: left to right, with @before@ the conjunction of a
    -- so far and @acc@ the disjunction so far.
    untilFromStart !before !acc vs = case vs of
      _ | acc == T || before == F -> acc
      []                          -> max acc before
      (va, vb) : rest             -> untilFromStart (min before va) (max acc (min before vb)) rest

-- Three truth values: false, unknown (decided by samples not yet seen),
-- true; 'min' is conjunction and 'max' disjunction (Kleene's logic).
data Tri = F | U | T
  deriving (Eq, Ord, Show)

notTri :: Tri -> Tri
notTri F = T
notTri U = U
notTri T = F

-- Whether the stream ends after the samples seen (the meaning at the end
-- applies) or may go on (what is beyond is unknown).
data Ending = Closed | Open

-- | @truths ending m p s@: the truth of @p@ at each of the first @m@
-- samples of @s@. Times in a window are measured from its first sample
-- with the library's clock, and a sample within a billionth of the bound
-- (relative) counts as inside it: sums of steps like 0.1 round either way
-- (three steps of 0.1 read 0.30000000000000004), and a window of 0.3
-- should see them.
truths :: Ending -> Int -> TPred a -> SignalSampleStream a -> [Tri]
truths ending m p0 s = go p0
  where
    beyond = case ending of
      Closed -> T
      Open   -> U
    go p = case p of
      SP sf            -> map (\(_, b) -> if b then T else F) (take m (fst (evalSF sf s)))
      And a b          -> zipWith min (go a) (go b)
      Or a b           -> zipWith max (go a) (go b)
      Not a            -> map notTri (go a)
      Implies a b      -> zipWith max (map notTri (go a)) (go b)
      Next a           -> drop 1 (go a) ++ [beyond | m > 0]
      Always a         -> fromEnd (\v -> if v == F then Just F else Nothing) min beyond (go a)
      Eventually a     -> fromEnd (\v -> if v == T then Just T else Nothing) max endEventually (go a)
      Until a b        -> fromEnd (\(va, vb) -> if vb == T then Just T else if va == F then Just vb else Nothing)
                                  (\(va, vb) next -> max vb (min va next)) beyond (zip (go a) (go b))
      EventuallyWithin d a -> windowed d (go a) max F
      AlwaysFor d a    -> windowed d (go a) min T
    -- 'Eventually' at the last sample of a closed stream is its argument
    -- there: the next value is false, not true.
    endEventually = case ending of
      Closed -> F
      Open   -> U
    -- Each value combined with the one at the next sample, from the end;
    -- the last sample combines with the value beyond the end. A sample
    -- whose value the next cannot change (@decided@: 'Always' at a false,
    -- 'Eventually' at a true) ends a stretch: the stretch before it is
    -- combined from it, without looking further, so the list comes out
    -- lazily, holding one stretch at a time (memory bounded by the
    -- distance between two such samples, not by the stream).
    fromEnd :: (x -> Maybe Tri) -> (x -> Tri -> Tri) -> Tri -> [x] -> [Tri]
    fromEnd decided f end = stretches
      where
        stretches vs = case untilDecided vs of
          (before, Just (d, rest)) -> init (scanr f d before) ++ d : stretches rest
          (before, Nothing)        -> init (scanr f end before)
        untilDecided [] = ([], Nothing)
        untilDecided (v : rest) = case decided v of
          Just d  -> ([], Just (d, rest))
          Nothing -> let (before, after') = untilDecided rest in (v : before, after')
    -- The window of samples from each one to d seconds after it, folded;
    -- if the stream seen so far reaches past the window, the window is
    -- complete; if it is closed and its last sample is at the window's end
    -- (at d, within the slack), too; otherwise the samples beyond decide
    -- (unknown while the stream is open, since a sample of a step of 0
    -- may still come at d; at the end of a closed stream the value given).
    -- An infinite window never ends.
    windowed d vs combine unit =
      [ let elapsed = sampleTimes (sRestart suffix)  -- times from the suffix's start (read lazily: a
                                                      -- predicate costs time linear in the stream times the window)
            (inWindow, after') = span ((<= d + slack) . fst) (zip elapsed vsFrom)
            slack = timeSlack d
            reached = not (isInfinite d) && any ((>= d - slack) . fst) inWindow
            end | not (null after') = unit
                | otherwise         = case ending of
                    Closed | reached   -> unit
                           | otherwise -> T
                    Open -> U
        in foldr (combine . snd) end inWindow
      | (suffix, vsFrom) <- zip (suffixes (take m s)) (suffixes vs) ]

suffixes :: [x] -> [[x]]
suffixes [] = []
suffixes xs@(_ : xs') = xs : suffixes xs'

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
-- the first sample at which the predicate was decided false: the shortest
-- prefix of the stream that falsifies it whatever samples followed (the
-- whole stream, when only its end decides, as for 'Eventually'). It reads
-- the stream up to about twice that prefix (and what 'evalT' reads), so
-- a failure early in a long stream made lazily is explained without the
-- rest.
explainT :: TPred a -> SignalSampleStream a -> Maybe (Explanation a)
explainT p s
  | evalT p s = Nothing
  | otherwise = Just (explanationAt (grow 1))
  where
    ts = sampleTimes s
    falseOpen k = case truths Open k p s of
      (F : _) -> True
      _       -> False
    -- More samples only resolve unknowns (Kleene's logic is monotone), so
    -- the prefixes that falsify are all those from some length on. The
    -- lengths 1, 2, 4 ... are tried until one falsifies (or the stream
    -- ends: the closed stream is the last resort), then a binary search
    -- between the last two: only the samples up to twice the answer are
    -- read, so a failure early in a long stream made lazily (a long run)
    -- is explained without the rest.
    grow k
      | longerThan k = if falseOpen k then search (k `div` 2 + 1) k else grow (2 * k)
      | otherwise    = search (k `div` 2 + 1) (length s)
    longerThan k = not (null (drop k s))
    search lo hi
      | lo >= hi  = lo
      | falseOpen mid = search lo mid
      | otherwise = search (mid + 1) hi
      where mid = (lo + hi) `div` 2
    explanationAt k =
      let i = k - 1
      in Explanation
           { explFrame  = i
           , explTime   = ts !! i
           , explAround = [ (j, t, a) | (j, t, a) <- takeWhile (\(j, _, _) -> j <= i + 2) (zip3 [0 ..] ts (samples s))
                                      , j >= i - 3 ]
           }

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
