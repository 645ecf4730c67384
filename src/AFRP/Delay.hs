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
-- it outputs @a0@ until @t@ has 'AFRP.Internal.Clock.reached' @q@, and
-- afterwards the input sample taken at the latest sample time @s@ such
-- that @t@ has reached @s + q@ (the delayed signal is piecewise constant
-- between samples): a sample is due out at @s + q@ and released at the
-- first sample whose 'AFRP.Basic.localTime' has reached that, as every
-- timed event of the library, and never at the sample it came in at (a
-- @q@ below the clock's rounding at that time delays by one sample, and
-- the output never depends on the current input, so the delay can close a
-- 'loop'). This holds for any sequence of time steps, however irregular;
-- at dt 0.05, @delay 1.1@ releases the sample of time 0 at exactly t = 1.1
-- (Yampa, summing floats, may be one sample late), and at dt 0.1 @delay
-- 0.3@ releases every sample exactly three samples later. @delay 0@ is the
-- identity; a negative delay is an error. An infinite delay outputs @a0@
-- for ever, at an infinite local time too (where, by the rule above, the
-- time would have reached @s + q@: the one exception to it).
--
-- > embed (delay 1 0) (1, [(0.5, Just 2), (0.5, Just 3), (0.5, Just 4)])  ==  [0, 0, 1, 2]
delay :: forall a. Time -> a -> SF a a
delay q a0
  | q < 0 || isNaN q = error ("AFRP.Delay.delay: negative or NaN delay, got " ++ show q)
  | q == 0           = SF idN
  | isInfinite q     = SF (constN a0)
  | otherwise        = SF (initN (\a -> step clockZero Seq.empty q a))
  where
    -- The buffer holds each earlier sample with the time it is due out
    -- (its local time plus q): a sample is released at the first sample
    -- whose local time has reached its due time, the rule of every timed
    -- event in the library. The sample of this step is held apart, with
    -- its due time, and joins the buffer at the next step: it is never
    -- released at the step it came in, whatever q (with a q below the
    -- rounding of the local time, its due time would count as reached at
    -- once, and the delay would pass its input through). A held sample
    -- whose due time is the new one's (the time did not move: dt 0, or a
    -- step below the rounding) is superseded by it and never joins the
    -- buffer, unless that due time is reached already (at an infinite
    -- time, or with a q below the rounding): then it is the latest sample
    -- due, and comes out now.
    step :: Clock -> Seq (Time, a) -> Time -> a -> (# Node a a, a #)
    step clock buf due a =
      let !now = clockTime clock
          buf' = dropOld now buf
          out  = case Seq.viewl buf' of
            (d, x) :< _ | reached d now -> x
            _                           -> a0
      in (# go clock buf' due a, out #)
    go !clock !buf !dueNew aNew = NStep (\dt a ->
      let !clock' = tick clock dt
          !due    = clockTime clock' + q
      in if dueNew == due && not (reached due (clockTime clock'))
           then step clock' buf due a                      -- superseded (dt 0)
           else step clock' (buf |> (dueNew, aNew)) due a)
    -- Drop every sample that a later sample, itself due, supersedes.
    dropOld now buf = case Seq.viewl buf of
      _ :< rest | (due, _) :< _ <- Seq.viewl rest, reached due now -> dropOld now rest
      _                                                       -> buf
