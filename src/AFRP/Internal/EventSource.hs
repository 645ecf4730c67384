{-# LANGUAGE PolyKinds      #-}
{-# LANGUAGE KindSignatures #-}
{-# LANGUAGE ExplicitForAll #-}
-- |
-- Module      : AFRP.Internal.EventSource
-- Description : What the modules of "AFRP.EventSource" share: the errors
--               of their argument checks, and the count of periods a
--               'Double' tells apart.
--
-- Internal, not part of the API (neither "AFRP.EventSource" nor "AFRP"
-- re-exports it): "AFRP.EventSource.Timed" and "AFRP.EventSource.Sample"
-- check their times and periods alike and say so in one wording, and
-- both stop counting periods one by one at the same bound.
module AFRP.Internal.EventSource
  ( -- * Argument checks
    errNeg
  , errPeriod
    -- * Counting periods
  , twoTo53
  ) where

import GHC.Exts (RuntimeRep, TYPE)

-- | @errNeg f q@: the error of the source @f@ given a time @q@ that is
-- negative or NaN. Of any result type, unboxed ones included (a source's
-- step returns an unboxed pair).
errNeg :: forall (r :: RuntimeRep) (x :: TYPE r). String -> Double -> x
errNeg f q = error ("AFRP.EventSource." ++ f ++ ": negative or NaN time, got " ++ show q)

-- | @errPeriod f p@: the error of the source @f@ given a period @p@ that
-- is not positive (or NaN).
errPeriod :: String -> Double -> x
errPeriod f p = error ("AFRP.EventSource." ++ f ++ ": the period must be positive, got " ++ show p)

-- | 2^53 (9007199254740992), as a 'Double': the number of periods beyond
-- which a time divided by its period no longer tells one period from the
-- next (a 'Double' holds every integer up to it, and not every one
-- beyond). 'AFRP.EventSource.repeatedly' stops counting its boundaries
-- once a period is no longer than @2^-53@ of the local time, and
-- 'AFRP.EventSource.sampleWindow' counts the periods a step spans at once
-- only below it.
twoTo53 :: Double
twoTo53 = 9007199254740992
