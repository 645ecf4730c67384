-- |
-- Module      : AFRP.Test.Stream
-- Description : Finite streams of input samples, and running a signal
--               function on them.
--
-- A stream is a plain list of samples, each with the time step since the
-- previous one; the first sample's time step is 0 (it is the signal
-- function's local time 0). The names are yampa-test's, so that property
-- files written for it port over; the one difference is the type: yampa-test
-- keeps the first sample apart (@(a, [(DTime, a)])@), afrp keeps it in the
-- list, with time step 0, so that every list function applies. 'groupDeltas'
-- builds a stream the yampa-test way.
--
-- A stream should have at least one sample: the functions here treat the
-- empty list as a stream that has not started (no output, no time).
module AFRP.Test.Stream
  ( -- * Streams
    SignalSampleStream
  , FutureSampleStream
  , groupDeltas
  , samples
  , sampleTimes
  , firstSample
  , lastSample
    -- * Combining and cutting
  , sMerge
  , sConcat
  , sRefine
  , sRefineWith
  , sClipAfterFrame
  , sClipAfterTime
  , sClipBeforeFrame
  , sClipBeforeTime
  , sRestart
  , sampleAt
  , timeSlack
    -- * Running signal functions
  , FutureSF
  , evalSF
  , evalFutureSF
  ) where

import AFRP (DTime, FutureSF, SF, evalAt, evalAtZero, localTime)

-- | A finite signal: samples with the time step since the previous sample;
-- the first sample's time step is 0 (its value is ignored by 'evalSF').
type SignalSampleStream a = [(DTime, a)]

-- | The samples after the first of a stream: each time step is since the
-- previous sample, and none is time 0.
type FutureSampleStream a = [(DTime, a)]

-- | @groupDeltas xs dts@: the stream whose first sample is @head xs@ at
-- time 0 and whose later samples are @tail xs@, each after the matching
-- time step of @dts@ (the shorter list decides the length).
groupDeltas :: [a] -> [DTime] -> SignalSampleStream a
groupDeltas []       _   = []
groupDeltas (x : xs) dts = (0, x) : zip dts xs

-- | The values of the samples, in order.
samples :: SignalSampleStream a -> [a]
samples = map snd

-- | The time of each sample since the start: the first is 0, each later
-- one the sum of the time steps so far, as the library's 'localTime'
-- measures it (a compensated sum: ten steps of 0.1 are exactly 1.0).
sampleTimes :: SignalSampleStream a -> [DTime]
sampleTimes s = samples (fst (evalSF localTime s))

-- | The value at time 0. Partial: an error on the empty stream.
firstSample :: SignalSampleStream a -> a
firstSample []           = error "AFRP.Test.Stream.firstSample: empty stream"
firstSample ((_, a) : _) = a

-- | The value of the last sample. Partial: an error on the empty stream.
lastSample :: SignalSampleStream a -> a
lastSample [] = error "AFRP.Test.Stream.lastSample: empty stream"
lastSample ss = snd (last ss)

-- | @sMerge f s1 s2@ merges two streams by time: samples at the same time
-- are combined with @f@ (the first stream's value as first argument), at
-- the earlier of their two times; others are kept as they are, so the
-- result samples at every time either stream does (a combined pair at the
-- earlier of its two). Two times within 'timeSlack' of each other are the
-- same time (as for 'sClipAfterTime'): three steps of 0.1 end at
-- 0.30000000000000004, one of 0.3 at 0.3, and the two samples there are
-- one, at 0.3, not two 5.6e-17 s apart. Each sample of the result is taken
-- at the earlier of the two streams' next times, so its time steps are
-- never negative.
--
-- > map snd (sMerge (+) [(0, 1), (0.1, 1), (0.1, 1), (0.1, 1)] [(0, 10), (0.3, 10)])
-- >   == [11, 1, 1, 11]
sMerge :: (a -> a -> a) -> SignalSampleStream a -> SignalSampleStream a -> SignalSampleStream a
sMerge f s1 s2 = fromTimed (mergeTimed (toTimed s1) (toTimed s2))
  where
    mergeTimed [] ys = ys
    mergeTimed xs [] = xs
    mergeTimed xs@((t1, x) : xs') ys@((t2, y) : ys')
      | abs (t1 - t2) <= timeSlack (max (abs t1) (abs t2)) = (min t1 t2, f x y) : mergeTimed xs' ys'
      | t1 < t2   = (t1, x) : mergeTimed xs' ys
      | otherwise = (t2, y) : mergeTimed xs ys'

-- | @sConcat s1 dt s2@: @s1@, then @s2@ starting @dt@ after @s1@'s last
-- sample. A @dt@ that is negative or NaN (no run takes such a step) is an
-- error naming it.
sConcat :: SignalSampleStream a -> DTime -> SignalSampleStream a -> SignalSampleStream a
sConcat _  dt _ | isNaN dt || dt < 0 =
  error ("AFRP.Test.Stream.sConcat: the time step must be a number >= 0, got " ++ show dt)
sConcat s1 _  []             = s1
sConcat s1 dt ((_, a) : s2') = s1 ++ ((dt, a) : s2')

-- | @sRefine maxDT s@ splits every time step longer than @maxDT@ into
-- equal steps no longer than @maxDT@, repeating the later sample's value
-- (a zero-order hold looking forward: the new samples already see the
-- value the step leads to). The original sample times are kept. A
-- @maxDT@ that is not a positive number is an error naming it.
sRefine :: DTime -> SignalSampleStream a -> SignalSampleStream a
sRefine = sRefineWith (\_ new -> new)

-- | @sRefineWith interpolate maxDT s@: like 'sRefine', with each new
-- sample's value @interpolate previous next@ (the original samples keep
-- their own values).
sRefineWith :: (a -> a -> a) -> DTime -> SignalSampleStream a -> SignalSampleStream a
sRefineWith interpolate maxDT s0
  | isNaN maxDT || maxDT <= 0 =
      error ("AFRP.Test.Stream.sRefine: the longest time step must be a number > 0, got " ++ show maxDT)
  | otherwise = case s0 of
      []         -> []
      first : ss -> first : go (snd first) ss
  where
    go _ [] = []
    go prev ((dt, a) : rest)
      | dt > maxDT =
          let ratio  = dt / maxDT
              fewest | ratio <= fromIntegral maxPieces = ceiling ratio :: Int
                     | otherwise = error ("AFRP.Test.Stream.sRefine: a time step of " ++ show dt
                                          ++ " cut into steps of at most " ++ show maxDT ++ " would be more than "
                                          ++ show maxPieces ++ " samples")
              -- (the steps of n pieces: n - 1 equal ones and the rest,
              -- which sum to dt exactly; rounding may leave the rest or
              -- the step just above maxDT, and then a piece more does)
              stepsOf n = let d = dt / fromIntegral n in (d, dt - d * fromIntegral (n - 1))
              pieces = until (\n -> let (d, r) = stepsOf n in d <= maxDT && r <= maxDT) (+ 1) fewest
              (step, rest') = stepsOf pieces
              filler = replicate (pieces - 1) (step, interpolate prev a)
          in filler ++ (rest', a) : go a rest
      | otherwise = (dt, a) : go a rest

-- The most samples 'sRefineWith' makes of one time step: 10^8 (more than
-- memory holds as a list).
maxPieces :: Int
maxPieces = 100000000

-- | @sClipAfterFrame n s@ keeps the first @n@ samples (at least the first).
sClipAfterFrame :: Int -> SignalSampleStream a -> SignalSampleStream a
sClipAfterFrame n = take (max 1 n)

-- | @sClipAfterTime t s@ keeps the samples at times up to @t@ (the first
-- always), with the relative slack of 'timeSlack': three steps of 0.1 end
-- at 0.30000000000000004, which is at time 0.3 here, as for
-- 'AFRP.Test.LTL.eventuallyWithin'. A NaN time is an error naming it.
sClipAfterTime :: DTime -> SignalSampleStream a -> SignalSampleStream a
sClipAfterTime t _ | isNaN t = error "AFRP.Test.Stream.sClipAfterTime: the time is NaN"
sClipAfterTime t s = case zip (sampleTimes s) s of
  []            -> []
  (_, x0) : xs  -> x0 : map snd (takeWhile ((<= t + timeSlack t) . fst) xs)

-- | @sampleAt t s@: the value of the last sample at or before time @t@
-- (with the slack of 'sClipAfterTime'), which is the value a sampled
-- signal holds at @t@; 'Nothing' for the empty stream. A time before 0
-- gives the first sample's value.
--
-- > sampleAt 0.3 (fst (evalSF (after 0.3 () >>> arr isEvent) (replicate 5 (0.1, ()))))
-- >   == Just True
sampleAt :: DTime -> SignalSampleStream a -> Maybe a
sampleAt t s = case sClipAfterTime t s of
  []   -> Nothing
  kept -> Just (snd (last kept))

-- | The rounding slack of a time @t@ in the comparisons here and in
-- "AFRP.Test.LTL": @1e-9 * max 1e-3 |t|@, relative to @t@ (1 ms at
-- t = 10^6 s), above the rounding of sums of time steps and below the
-- time steps of a stream whose times are not beyond 10^6 of its steps.
timeSlack :: DTime -> DTime
timeSlack t = 1e-9 * max 1e-3 (abs t)

-- | @sClipBeforeFrame n s@ drops the first @n@ samples, keeping at least
-- the last; the first kept sample becomes time 0.
sClipBeforeFrame :: Int -> SignalSampleStream a -> SignalSampleStream a
sClipBeforeFrame n s = sRestart (drop (min (max 0 n) (length s - 1)) s)

-- | @sClipBeforeTime t s@ drops the samples before time @t@, keeping at
-- least the last; the first kept sample becomes time 0. A sample within
-- 'timeSlack' of @t@ is at @t@ (kept), as for 'sClipAfterTime': the two
-- agree on which sample is at @t@. A NaN time is an error naming it.
sClipBeforeTime :: DTime -> SignalSampleStream a -> SignalSampleStream a
sClipBeforeTime t _ | isNaN t = error "AFRP.Test.Stream.sClipBeforeTime: the time is NaN"
sClipBeforeTime t s = sClipBeforeFrame (length (takeWhile (< lower) (sampleTimes s))) s
  where lower | isInfinite t = t   -- (its slack is infinite too: no NaN bound)
              | otherwise    = t - timeSlack t

-- | The stream timed from its own first sample: that sample's time step
-- becomes 0, the others are kept. A suffix of a stream (@drop n s@) is a
-- stream of its own this way; it reads only the first sample, so it is
-- lazy in the rest.
--
-- > sRestart [(0.5, 'a'), (0.25, 'b')]  ==  [(0, 'a'), (0.25, 'b')]
sRestart :: SignalSampleStream a -> SignalSampleStream a
sRestart []            = []
sRestart ((_, a) : ss) = (0, a) : ss

-- | @evalSF sf s@ runs @sf@ on the stream: its outputs, each with the time
-- step of the input sample it answers (the first at time 0), and what @sf@
-- has become after the last sample, to go on with 'evalFutureSF'. Lazy in
-- the outputs. The empty stream has no time 0: 'evalSF' then gives no
-- output and a signal function started (at time 0) on an input that is an
-- error if used.
evalSF :: SF a b -> SignalSampleStream a -> (SignalSampleStream b, FutureSF a b)
evalSF sf [] = ([], snd (evalAtZero sf (error "AFRP.Test.Stream.evalSF: empty stream")))
evalSF sf ((_, a0) : ss) =
  let (b0, fsf)    = evalAtZero sf a0
      (bs, fsfEnd) = evalFutureSF fsf ss
  in ((0, b0) : bs, fsfEnd)

-- | @evalFutureSF fsf s@ goes on with a started signal function: every
-- sample of @s@ (the first included) is a step of its time step.
evalFutureSF :: FutureSF a b -> FutureSampleStream a -> (FutureSampleStream b, FutureSF a b)
evalFutureSF fsf [] = ([], fsf)
evalFutureSF fsf ((dt, a) : ss) =
  let (b, fsf')     = evalAt fsf dt a
      (bs, fsfEnd)  = evalFutureSF fsf' ss
  in ((dt, b) : bs, fsfEnd)

-- The stream with absolute times, and back.
toTimed :: SignalSampleStream a -> [(DTime, a)]
toTimed s = zip (sampleTimes s) (samples s)

fromTimed :: [(DTime, a)] -> SignalSampleStream a
fromTimed xs = zipWith (\tPrev (t, a) -> (t - tPrev, a)) (0 : map fst xs) xs
