-- fixedDelayStreamWith keeps yampa-test's type, whose Arbitrary constraint
-- it does not use.
{-# OPTIONS_GHC -Wno-redundant-constraints #-}
-- |
-- Module      : AFRP.Test.QuickCheck
-- Description : QuickCheck generators of sample streams, shrinking them
--               to short counterexamples, and printing them as tables.
--
-- The generators have yampa-test's names and types. What yampa-test lacks
-- is shrinking: QuickCheck reports the first random stream that fails,
-- often hundreds of samples with time steps like 0.0137. 'shrinkStream'
-- makes a failing stream shorter (fewer samples), its values simpler (with
-- the values' own shrinker) and its time steps rounder, and 'forAllStreams'
-- prints the result as a table, one sample a line:
--
-- > stream of 3 samples:
-- >     #    dt          t           value
-- >     0    0.0         0.0         0
-- >     1    0.5         0.5         1
-- >     2    1.0         1.5         -1
module AFRP.Test.QuickCheck
  ( -- * Random stream generation
    generateStream
  , generateStreamWith
    -- ** Parameters used to generate random input streams
  , Distribution (..)
  , Range
  , Length
  , maxStreamSteps
    -- ** Helpers for common cases
  , uniDistStream
  , uniDistStreamMaxDT
  , fixedDelayStream
  , fixedDelayStreamWith
    -- * Shrinking and showing
  , shrinkStream
  , shrinkStreamWith
  , shrinkStreamIn
  , showStream
  , forAllStreams
  , forAllStreamsWith
  , forAllStreamsIn
    -- * Temporal predicates as properties
  , propT
  ) where

import           Data.List        (nub)
import           Data.Maybe       (fromMaybe)
import           Test.QuickCheck

import           AFRP             (DTime)
import           AFRP.Test.LTL
import           AFRP.Test.Stream

-- | How the time steps of a generated stream are distributed.
data Distribution
  = DistConstant
    -- ^ one time step, drawn from the range, for the whole stream (every
    -- generated time step is positive: a lower bound of 0 means steps
    -- just above 0; with a length in time, it is one that reaches it in
    -- fewer than 'maxStreamSteps' steps)
  | DistNormal (DTime, DTime)
    -- ^ each time step drawn from a normal distribution with this mean and
    -- standard deviation, kept inside the range and positive
  | DistRandom
    -- ^ each time step drawn uniformly from the range (any positive
    -- 'Double' when the range is open)
  deriving (Eq, Show)

-- | The smallest and largest time step, each optional.
type Range = (Maybe DTime, Maybe DTime)

-- | The length of a stream: @Nothing@ for one that grows with QuickCheck's
-- size parameter, @Left n@ for @n@ time steps (so @n + 1@ samples), @Right
-- t@ for time steps until the stream reaches (or passes) time @t@.
type Length = Maybe (Either Int DTime)

-- | @generateStream dist range len@: a stream with time steps as @dist@
-- and @range@ say, @len@ long, and arbitrary values. The first sample is at
-- time 0. Parameters that cannot give a stream are an error (a call of
-- 'error' with a message naming the parameter), rather than a generator
-- that never ends or a stream that is not what was asked for: a bound of
-- the range that is negative or not finite, a lower bound above the upper
-- one, an upper bound of 0 (no positive time step), a length in time that
-- is negative or not finite or that the time steps cannot reach in
-- 'maxStreamSteps' steps (at once: steps of the upper bound, or random
-- steps from a range with an upper bound whose mean, the middle of the
-- range for 'DistRandom', would need more; other random steps, after
-- that many, or after 1000 steps in a row lost in the rounding of the
-- time so far), a normal
-- distribution whose mean or deviation is not finite or whose deviation
-- is negative, or one that almost never (not once in 1000 draws) gives a
-- time step inside the range.
generateStream :: Arbitrary a => Distribution -> Range -> Length -> Gen (SignalSampleStream a)
generateStream = generateStreamWith (\_ _ -> arbitrary)

-- | @generateStreamWith value dist range len@: as 'generateStream', with
-- the sample number @k@ (0 at time 0) having the value @value k dt@, where
-- @dt@ is its time step (0 for the first sample).
generateStreamWith :: (Int -> DTime -> Gen a) -> Distribution -> Range -> Length -> Gen (SignalSampleStream a)
generateStreamWith value dist range len = checked `seq` do
  dts <- case dist of
    DistConstant -> do
      dt <- constantStep
      case len of
        Just (Right t) -> pure (replicate (stepsToReach dt t) dt)
        _              -> (`replicate` dt) <$> stepCount
    DistRandom             -> deltas (deltaIn range)
    DistNormal (mean, dev) -> deltas (normalDelta mean dev range)
  xs <- sequence (zipWith value [0 ..] (0 : dts))
  pure (zip (0 : dts) xs)
  where
    checked = case problems of
      []    -> ()
      p : _ -> error ("AFRP.Test.QuickCheck.generateStream: " ++ p)
    problems =
      [ "the range's bound " ++ show b ++ " is not a finite number >= 0"
      | Just b <- [fst range, snd range], not (finiteD b && b >= 0) ]
      ++ [ "the range " ++ show range ++ " is empty" | (Just lo, Just hi) <- [range], lo > hi ]
      ++ [ "the range " ++ show range ++ " holds no positive time step" | Just 0 <- [snd range] ]
      ++ [ "the length in time " ++ show t ++ " is not a finite number >= 0"
         | Just (Right t) <- [len], not (finiteD t && t >= 0) ]
      ++ [ "the normal distribution " ++ show md ++ " needs a finite mean and a finite deviation >= 0"
         | DistNormal md@(mean, dev) <- [dist], not (finiteD mean && finiteD dev && dev >= 0) ]
      ++ [ "time steps of at most " ++ show hi ++ " cannot reach the length " ++ show t ++ " in "
           ++ show maxStreamSteps ++ " steps"
         | Just (Right t) <- [len], Just hi <- [snd range], hi > 0, t / hi > fromIntegral maxStreamSteps ]
      ++ [ "time steps drawn as " ++ show dist ++ " from the range " ++ show range ++ " average "
           ++ show m ++ ": they would need " ++ aboutSteps (t / m) ++ " to reach the length "
           ++ show t ++ ", more than " ++ show maxStreamSteps
         | Just (Right t) <- [len], Just hi <- [snd range], hi > 0, t / hi <= fromIntegral maxStreamSteps
         , Just m <- [meanStep dist range], m > 0, t / m > fromIntegral maxStreamSteps ]
    -- (one step for the whole stream; with a length in time, one that
    -- reaches it in fewer than 'maxStreamSteps' steps, so that a draw near
    -- a lower bound of 0 is not an error: with an upper bound, drawn from
    -- the range above that least step; without one, drawn as for any
    -- length, and a draw below the least step drawn again uniformly
    -- between it and the length)
    constantStep = case len of
      Just (Right t) | t > 0 ->
        let least = t / fromIntegral (maxStreamSteps - 1)
        in case range of
             (lo, Just hi) -> deltaIn (Just (max (fromMaybe 0 lo) (min hi least)), Just hi)
             (_, Nothing)  -> deltaIn range >>= \dt -> if dt >= least then pure dt else choose (least, t)
      _ -> deltaIn range
    stepCount = case len of
      Just (Left n) -> pure (max 0 n)
      _             -> sized (\n -> choose (0, n))
    deltas gen = case len of
      Just (Right t) -> untilTime gen t
      _              -> stepCount >>= (`vectorOf` gen)
    stepsToReach dt t
      | t / dt > fromIntegral maxStreamSteps = tooLong dt t
      | otherwise                            = max 0 (ceiling (t / dt))

-- The mean of the time steps a random distribution draws from a range
-- with an upper bound, when it can be told before drawing: the middle of
-- the range for 'DistRandom' (uniform draws), the mean of the normal
-- distribution cut to the range's positive part for 'DistNormal'
-- (Simpson's rule over the part within 12 deviations of its mean, to a
-- relative error far below what a length near 'maxStreamSteps' steps
-- needs). A sum of @n@ such steps strays from @n@ times the mean by about
-- the square root of @n@ steps, so a length of more than 'maxStreamSteps'
-- mean steps is reached in that many only when it is within a few
-- ten-thousandths of it (just above, about as often as not), and one
-- further above, never in practice.
meanStep :: Distribution -> Range -> Maybe DTime
meanStep dist (lo, mhi) = case (dist, mhi) of
  (DistRandom, Just hi)        -> Just ((a + hi) / 2)
  (DistNormal (mu, dev), Just hi)
    | dev == 0                 -> if mu > 0 && a <= mu && mu <= hi then Just mu else Nothing
    | otherwise ->
        let x0 = max a (mu - 12 * dev)
            x1 = min hi (mu + 12 * dev)
            n  = 4000 :: Int
            h  = (x1 - x0) / fromIntegral n
            w k | k == 0 || k == n = 1
                | odd k            = 4
                | otherwise        = 2 :: Double
            xs = [ (w k, x0 + fromIntegral k * h) | k <- [0 .. n] ]
            density x = exp (-0.5 * ((x - mu) / dev) ^ (2 :: Int))
            mass  = sum [ c * density x | (c, x) <- xs ]
            moment = sum [ c * x * density x | (c, x) <- xs ]
        in if x1 > x0 && mass > 0 then Just (moment / mass) else Nothing
  _                            -> Nothing
  where
    a = max 0 (fromMaybe 0 lo)

-- A count of steps as a message says it: whole below 10^15, in
-- scientific notation above, and past a 'Double' said so.
aboutSteps :: Double -> String
aboutSteps n
  | isInfinite n = "more steps than a number holds"
  | n < 1e15     = "about " ++ show (round n :: Integer) ++ " steps"
  | otherwise    = "about " ++ show n ++ " steps"

-- | The most time steps a generator makes to reach a length in time: 10^8
-- (more than memory holds as a list). Asking for more is an error.
maxStreamSteps :: Int
maxStreamSteps = 100000000

-- The error of a length in time the steps cannot reach.
tooLong :: DTime -> DTime -> x
tooLong dt t = error ("AFRP.Test.QuickCheck.generateStream: time steps like " ++ show dt ++ " cannot reach the length "
                      ++ show t ++ " in " ++ show maxStreamSteps ++ " steps")

-- Time steps until their sum reaches t (the last one may pass it); an
-- error after 'maxStreamSteps' steps, or after 1000 steps in a row that
-- the sum so far loses in its rounding (steps that would never reach t;
-- one such step now and then, a draw near a lower bound of 0, is kept).
untilTime :: Gen DTime -> DTime -> Gen [DTime]
untilTime gen t = go (0 :: Int) (0 :: Int) 0
  where
    go k lost elapsed
      | elapsed >= t         = pure []
      | k >= maxStreamSteps  = tooLong (elapsed / fromIntegral k) t
      | otherwise = do
          dt <- gen
          let elapsed' = elapsed + dt
              lost' = if elapsed' == elapsed then lost + 1 else 0
          if lost' >= 1000 then tooLong dt t else (dt :) <$> go (k + 1) lost' elapsed'

-- Neither NaN nor infinite.
finiteD :: Double -> Bool
finiteD x = not (isNaN x || isInfinite x)

-- A positive time step inside the range, uniformly (a draw of 0, from a
-- lower bound of 0, is drawn again).
deltaIn :: Range -> Gen DTime
deltaIn range = case range of
  (Just lo, Just hi) -> choose (lo, hi) `suchThat` (> 0)
  (Just lo, Nothing)
    | lo > 0         -> (lo +) . getNonNegative <$> arbitrary
    | otherwise      -> getPositive <$> arbitrary
  (Nothing, Just hi) -> choose (0, hi) `suchThat` (> 0)
  (Nothing, Nothing) -> getPositive <$> arbitrary

-- A normally distributed time step, redrawn until positive and inside the
-- range (Box-Muller).
normalDelta :: DTime -> DTime -> Range -> Gen DTime
normalDelta mean dev (lo, hi) = tries (1000 :: Int)
  where
    tries 0 = error ("AFRP.Test.QuickCheck.generateStream: the normal distribution " ++ show (mean, dev)
                     ++ " gave no time step inside the range " ++ show (lo, hi) ++ " in 1000 draws")
    tries k = draw >>= \x -> if inside x then pure x else tries (k - 1)
    draw = do
      u1 <- choose (1e-12, 1)
      u2 <- choose (0, 1)
      pure (mean + dev * sqrt (-2 * log u1) * cos (2 * pi * u2))
    inside x = x > 0 && maybe True (<= x) lo && maybe True (x <=) hi

-- | Streams of any length with time steps of any positive size, uniformly
-- distributed, and arbitrary values.
uniDistStream :: Arbitrary a => Gen (SignalSampleStream a)
uniDistStream = generateStream DistRandom (Nothing, Nothing) Nothing

-- | @uniDistStreamMaxDT maxDT@: as 'uniDistStream', with time steps no
-- longer than @maxDT@.
uniDistStreamMaxDT :: Arbitrary a => DTime -> Gen (SignalSampleStream a)
uniDistStreamMaxDT maxDT = generateStream DistRandom (Nothing, Just maxDT) Nothing

-- | @fixedDelayStream dt@: streams of any length, every time step @dt@.
fixedDelayStream :: Arbitrary a => DTime -> Gen (SignalSampleStream a)
fixedDelayStream dt = generateStream DistConstant (Just dt, Just dt) Nothing

-- | @fixedDelayStreamWith f dt@: streams of any length, every time step
-- @dt@, the sample at time @t@ having the value @f t@. (The constraint is
-- yampa-test's; no value is arbitrary.)
fixedDelayStreamWith :: Arbitrary a => (DTime -> a) -> DTime -> Gen (SignalSampleStream a)
fixedDelayStreamWith f dt =
  generateStreamWith (\k _ -> pure (f (fromIntegral k * dt))) DistConstant (Just dt, Just dt) Nothing

-- | Shrink a stream with the values' 'shrink', keeping every time step
-- positive. See 'shrinkStreamWith'.
shrinkStream :: Arbitrary a => SignalSampleStream a -> [SignalSampleStream a]
shrinkStream = shrinkStreamWith (Nothing, Nothing) shrink

-- | @shrinkStreamWith range shrinkValue s@: the streams QuickCheck tries in
-- place of a failing @s@, simplest first:
--
-- * fewer samples: the first half, all but the last sample, and @s@
--   without one of its later samples (whose time step goes to the next
--   sample, so the others keep their times);
-- * rounder time steps: each step rounded to fewer decimals (at least
--   one significant digit kept, never 0), kept inside @range@;
-- * simpler values: one value at a time, with @shrinkValue@.
--
-- The first sample always stays, at time step 0. Each candidate is smaller
-- (fewer samples, fewer decimals, or a simpler value), so shrinking ends.
--
-- A sample is removed only where the merged time step stays inside
-- @range@, and a step is rounded only to a value inside it.
shrinkStreamWith :: Range -> (a -> [a]) -> SignalSampleStream a -> [SignalSampleStream a]
shrinkStreamWith range = shrinkStreamIn range Nothing

-- | @shrinkStreamIn range len shrinkValue s@: 'shrinkStreamWith', keeping
-- also the length @len@ that 'generateStream' was given, so that every
-- candidate is a stream the generator could have made: with @Left n@ no
-- sample is removed; with @Right t@ a stream keeps reaching time @t@
-- (samples are removed from within, their time steps merged, and the
-- stream is cut only where it still reaches @t@). With 'Nothing', as
-- 'shrinkStreamWith'. A counterexample is then never one that fails only
-- because it is shorter than any generated stream. (It rounds each time
-- step on its own: for a stream of 'DistConstant', 'forAllStreamsIn'
-- rounds the one step of the whole stream instead.)
shrinkStreamIn :: Range -> Length -> (a -> [a]) -> SignalSampleStream a -> [SignalSampleStream a]
shrinkStreamIn range len shrinkValue s = filter lengthKept fewer ++ filter reaches rounder ++ simpler
  where
    n = length s
    fewer =
      [take (n `div` 2) s | n >= 4] ++ [take (n - 1) s | n >= 2]
      ++ [ removeAt k s | (k, (dt, _), (dt', _)) <- zip3 [1 .. n - 2] (drop 1 s) (drop 2 s), inRange (dt + dt') ]
    lengthKept s' = case len of
      Just (Left _) -> False
      _             -> reaches s'
    -- (a rounded time step may end the stream short of t; sums are
    -- compared with the slack of 'timeSlack')
    reaches s' = case len of
      Just (Right t) -> sum (map fst s') >= t - timeSlack t
      _              -> True
    rounder =
      [ replaceAt k (dt', a)
      | (k, (dt, a)) <- zip [1 ..] (drop 1 s)
      , dt' <- roundings dt
      , inRange dt' ]
    simpler =
      [ replaceAt k (dt, a')
      | (k, (dt, a)) <- zip [0 ..] s
      , a' <- shrinkValue a ]
    replaceAt k x = take k s ++ x : drop (k + 1) s
    inRange x = maybe True (<= x) (fst range) && maybe True (x <=) (snd range)

-- Without the sample number k (k >= 1): its time step is added to the
-- next one's.
removeAt :: Int -> SignalSampleStream a -> SignalSampleStream a
removeAt k s = case splitAt k s of
  (before, (dt, _) : (dt', b) : rest) -> before ++ (dt + dt', b) : rest
  (before, _)                         -> before

-- A time step rounded to fewer decimals: the candidates, roundest first.
roundings :: DTime -> [DTime]
roundings dt = nub [ r | k <- [0 .. decimals dt - 1], let r = roundTo k dt, r > 0, r /= dt ]
  where
    roundTo :: Int -> DTime -> DTime
    roundTo k x = fromIntegral (round (x * 10 ^ k) :: Integer) / 10 ^ k
    decimals x = head ([k | k <- [0 .. 8], roundTo k x == x] ++ [9])

-- | A stream as a table, one sample a line: number, time step, time since
-- the start, value; headed by its number of samples. From a time step
-- that no run can take (negative or NaN) on, the time is shown as @-@, so
-- that such a stream (written by hand) is still printed, not an error.
showStream :: Show a => SignalSampleStream a -> String
showStream s = unlines $
  ("stream of " ++ show (length s) ++ " samples:")
  : ("    " ++ pad 5 "#" ++ pad 12 "dt" ++ pad 12 "t" ++ "value")
  : [ "    " ++ pad 5 (show k) ++ pad 12 (show dt) ++ pad 12 t ++ show a
    | (k, (dt, a), t) <- zip3 [0 :: Int ..] s (map show (sampleTimes runnable) ++ repeat "-") ]
  where
    pad w str = str ++ replicate (max 1 (w - length str)) ' '
    runnable = case s of
      []         -> []
      first : ss -> first : takeWhile (\(dt, _) -> not (isNaN dt) && dt >= 0) ss

-- | @forAllStreams gen prop@: @prop@ for streams from @gen@, shrunk with
-- 'shrinkStream' and printed with 'showStream' when one fails.
forAllStreams :: (Arbitrary a, Show a, Testable prop)
              => Gen (SignalSampleStream a) -> (SignalSampleStream a -> prop) -> Property
forAllStreams gen = forAllShrinkShow gen shrinkStream showStream

-- | @forAllStreamsWith range shrinkValue gen prop@: 'forAllStreams' with a
-- range the shrunk time steps must keep (the generator's) and the values'
-- own shrinker.
forAllStreamsWith :: (Show a, Testable prop)
                  => Range -> (a -> [a]) -> Gen (SignalSampleStream a)
                  -> (SignalSampleStream a -> prop) -> Property
forAllStreamsWith range shrinkValue gen =
  forAllShrinkShow gen (shrinkStreamWith range shrinkValue) showStream

-- | @forAllStreamsIn dist range len shrinkValue prop@: @prop@ for streams
-- of @'generateStream' dist range len@, shrunk with 'shrinkStreamIn' to
-- streams that generator could make (time steps in @range@, the length
-- @len@; for 'DistConstant', one time step for the whole stream, rounded
-- for every sample at once), printed with 'showStream' when one fails.
--
-- > forAllStreamsIn DistRandom (Just 0.01, Just 0.1) (Just (Right 3)) shrink $
-- >   propT (eventuallyWithin 2.5 (SP (arr (> (0 :: Int)))))
forAllStreamsIn :: (Arbitrary a, Show a, Testable prop)
                => Distribution -> Range -> Length -> (a -> [a])
                -> (SignalSampleStream a -> prop) -> Property
forAllStreamsIn dist range len shrinkValue =
  forAllShrinkShow (generateStream dist range len) shrinker showStream
  where
    shrinker = case dist of
      DistConstant -> shrinkConstantIn range len shrinkValue
      _            -> shrinkStreamIn range len shrinkValue

-- 'shrinkStreamIn' for a stream of 'DistConstant', one time step for the
-- whole stream: the step is rounded for all samples at once (rounding
-- one at a time made streams of two steps, which 'DistConstant' never
-- makes, and a failure of those hid the one found), a stream of a
-- number of steps is cut only at its end (when its length is
-- 'Nothing'), and one of a length in time gets as many steps of the
-- rounded step as 'generateStream' gives to reach it (never more than
-- it has).
shrinkConstantIn :: Range -> Length -> (a -> [a]) -> SignalSampleStream a -> [SignalSampleStream a]
shrinkConstantIn range len shrinkValue s = fewer ++ rounder ++ simpler
  where
    n = length s
    fewer = case len of
      Nothing -> [take (n `div` 2) s | n >= 4] ++ [take (n - 1) s | n >= 2]
      Just _  -> []
    rounder = case drop 1 s of
      []          -> []
      (dt, _) : _ ->
        [ s'
        | dt' <- roundings dt
        , maybe True (<= dt') (fst range) && maybe True (dt' <=) (snd range)
        , let kept = case len of
                Just (Right t) -> max 0 (ceiling (t / dt')) + 1
                _              -> n
        , kept <= n
        , let s' = zipWith (\k (_, a) -> (if k == (0 :: Int) then 0 else dt', a)) [0 ..] (take kept s) ]
    simpler =
      [ take k s ++ (dt, a') : drop (k + 1) s
      | (k, (dt, a)) <- zip [0 ..] s
      , a' <- shrinkValue a ]

-- | @propT p s@: 'evalT' as a property; when it fails, 'explainT' says at
-- which sample it was decided false and shows the samples around it.
--
-- An empty stream fails: no sample was tested, and 'evalT' would hold of
-- it vacuously (a property that cannot fail).
propT :: Show a => TPred a -> SignalSampleStream a -> Property
propT _ [] = counterexample "the stream is empty: there is no sample to test" False
propT p s = case explainT p s of
  Nothing -> property True
  Just e  -> counterexample (showExplanation e) False
