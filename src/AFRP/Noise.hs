{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Noise
-- Description : Random signals and events, from any generator.
--
-- No random-number package is needed: each function takes the generator's
-- own step function, so it works with "System.Random" (pass @random@ or
-- @randomR@), with SplitMix, or with a hand-written generator. The same
-- generator state always gives the same signal: runs are reproducible.
module AFRP.Noise
  ( noiseWith
  , noiseRWith
  , occasionallyWith
  ) where

import           AFRP.Event
import           AFRP.Internal.SF

-- | @noiseWith next g@ outputs a fresh value drawn with @next@ at every
-- sample, starting with the first draw from @g@ at time 0.
--
-- > noiseWith random (mkStdGen 42) :: SF a Double
noiseWith :: (g -> (b, g)) -> g -> SF a b
noiseWith next = SF . go
  where
    go g = NStep (\_ _ -> case next g of (b, !g') -> (# go g', b #))

-- | @noiseRWith nextR range g@: like 'noiseWith', with values drawn in
-- @range@ by a range-taking step function such as 'System.Random.randomR'.
noiseRWith :: ((b, b) -> g -> (b, g)) -> (b, b) -> g -> SF a b
noiseRWith nextR range = noiseWith (nextR range)

-- | @occasionallyWith next g tAvg x@: a random event source whose
-- occurrences (all carrying @x@) form a Poisson process with mean interval
-- @tAvg@ seconds. At each sample after the first, one uniform draw @r@ in
-- [0, 1) is taken with @next@, and the event occurs when
-- @r < 1 - exp (-dt / tAvg)@. There is never an occurrence at time 0. A
-- non-positive @tAvg@ is an error.
occasionallyWith :: (g -> (Double, g)) -> g -> Time -> b -> SF a (Event b)
occasionallyWith next g0 tAvg x
  | not (tAvg > 0) = error ("AFRP.Noise.occasionallyWith: the mean interval must be positive, got "
                            ++ show tAvg)
  | otherwise      = SF (initN (\_ -> (# go g0, NoEvent #)))
  where
    go g = NStep (\dt _ -> case next g of
      (r, !g') -> (# go g', if r < 1 - exp (negate dt / tAvg) then Event x else NoEvent #))
