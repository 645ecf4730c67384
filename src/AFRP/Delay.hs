{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFRP.Delay
-- Description : Delays by one sample and by a fixed time.
--
-- The one-sample delays ('pre', 'iPre', 'fby') never look at their current
-- input when they produce their output, which is what makes them the
-- building block of well-founded feedback ('loop', @rec@ in arrow
-- notation). Their input is stored unevaluated.
module AFRP.Delay
  ( pre
  , iPre
  , fby
  , delay
  ) where

import qualified Data.Sequence       as Seq
import           Data.Sequence       (Seq, ViewL (..), (|>))

import           AFRP.Internal.Clock
import           AFRP.Internal.SF

infixr 0 `fby`

-- | The uninitialised one-sample delay: at every sample after the first,
-- the input of the previous sample. Its output at local time 0 does not
-- exist; demanding it is an error naming 'pre'. Prefer 'iPre'.
pre :: SF a a
pre = iPre (error "AFRP.Delay.pre: pre has no output at local time 0 (use iPre for one)")

-- | The initialised one-sample delay: @a0@ at local time 0, then at every
-- sample the input of the previous sample. The current input is not
-- evaluated.
--
-- > embed (iPre 0) (1, [(1, Just 2), (1, Just 3)])  ==  [0, 1, 2]
iPre :: a -> SF a a
iPre a0 = SF (NPre a0)
-- Inlined only late (phase 1), so that the rule below sees it.
{-# INLINE [1] iPre #-}

-- @loop (second (iPre c) >>> arr g)@ (written so, or as @loopPre c (arr
-- g)@: a counter, an accumulator, a state machine written as a function)
-- is what @loopN@ builds at run time, recognising the delay and the
-- function, as @loopPreG g c@; built directly where GHC can see @g@, the
-- step is compiled with @g@'s body in place, and where @g@ returns its
-- pair as a constructor (@\(a, s) -> (e1, e2)@) the pair and the two
-- selections from it cost nothing (a @g@ that chooses between pairs still
-- builds them lazily, as it must). The same node, the same laziness: @g@
-- is applied lazily and both components are taken lazily. (@pre@, which
-- is already a node in this module's interface, is not seen by the rule:
-- @loop (second pre >>> arr g)@ takes the run-time path.)
{-# RULES
"AFRP loop(second iPre>>>arr)" forall c g.
  loopSF (compSF (arrSF g) (secondSF (iPre c))) = SF (loopPreG (\a -> g a) c)
  #-}

-- | @b0 \`fby\` sf@ ("followed by") outputs @b0@ at local time 0 and then,
-- at every later sample, the output @sf@ had at the previous sample.
fby :: b -> SF a b -> SF a b
b0 `fby` SF n = SF (compN n (sfNode (iPre b0)))

-- | @delay q a0@ delays its input signal by @q@ seconds. At local time @t@
-- it outputs @a0@ while @t < q@, and afterwards the input sample taken at
-- the latest sample time @s@ with @s <= t - q@ (the delayed signal is
-- piecewise constant between samples). This holds for any sequence of
-- time steps, however irregular. @delay 0@ is the identity; a negative
-- delay is an error.
--
-- > embed (delay 1 0) (1, [(0.5, Just 2), (0.5, Just 3), (0.5, Just 4)])  ==  [0, 0, 1, 2]
delay :: forall a. Time -> a -> SF a a
delay q a0
  | q < 0 || isNaN q = error ("AFRP.Delay.delay: negative or NaN delay, got " ++ show q)
  | q == 0           = SF idN
  | otherwise        = SF (initN (\a -> step clockZero (Seq.singleton (0, a))))
  where
    step :: Clock -> Seq (Time, a) -> (# Node a a, a #)
    step clock buf =
      let !target = clockTime clock - q
          buf'    = dropOld target buf
          out     = case Seq.viewl buf' of
            (s, x) :< _ | s <= target -> x
            _                         -> a0
      in (# go clock buf', out #)
    go !clock !buf = NStep (\dt a ->
      let !clock' = tick clock dt
      in step clock' (buf |> (clockTime clock', a)))
    -- Drop every sample that a later sample, itself old enough, supersedes.
    dropOld target buf = case Seq.viewl buf of
      _ :< rest | (s, _) :< _ <- Seq.viewl rest, s <= target -> dropOld target rest
      _                                                        -> buf
