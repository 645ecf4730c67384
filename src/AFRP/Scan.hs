-- |
-- Module      : AFRP.Scan
-- Description : Step-by-step accumulation over a signal: Yampa's 'sscan'
--               and 'sscanPrim'.
--
-- A scan folds a pure function over the samples of its input, one sample
-- at a time, ignoring the time steps. Unlike 'AFRP.Hybrid.accumHold' it
-- consumes a continuous signal, not events: the function is applied at every
-- sample, the first (local time 0) included.
module AFRP.Scan
  ( sscan
  , sscanPrim
  ) where

import           AFRP.Internal.SF

-- | @sscan f b0@ outputs @f b0 a0@ at the first sample (local time 0) and
-- @f b a@ at every later sample, where @b@ is its previous output and @a@
-- the current input. The time steps play no part.
--
-- > embed (sscan (+) 10) (1, [(1, Just 2), (1, Just 3)])  ==  [11, 13, 16]
sscan :: (b -> a -> b) -> b -> SF a b
sscan f b0 = SF (mealyN (\b a -> let b' = f b a in (b', b')) b0)

-- | @sscanPrim f c0 b0@ is a scan with a hidden accumulator @c@ and a held
-- output: at each sample, the first (local time 0) included, @f c a@ either
-- gives @Just (c', b')@, and then @b'@ is output and @c'@ is the new
-- accumulator, or @Nothing@, and then the accumulator is kept and the last
-- output is repeated (@b0@ if @f@ has never given @Just@). Like every
-- stateful signal function here it does not evaluate its input before its
-- output is demanded; the accumulator is evaluated at the start of the
-- next sample, so it never builds up a chain of thunks.
sscanPrim :: (c -> a -> Maybe (c, b)) -> c -> b -> SF a b
sscanPrim f c0 b0 = SF (mealyN step (c0, b0))
  where
    step s@(c, b) a = case f c a of
      Nothing       -> (s, b)
      -- the state's pair is built only once c' is evaluated: 'mealyN'
      -- forces the state, and so c', at the next step
      Just (c', b') -> (c' `seq` (c', b'), b')
