-- |
-- Module      : AFRP.Loop
-- Description : Feedback loops closed through a delay or an integral.
--
-- 'Control.Arrow.loop' itself comes from the 'Control.Arrow.ArrowLoop'
-- instance of 'SF' (re-exported by "AFRP"). The two loops here close the
-- feedback path through a primitive that never looks at its current
-- input, so they are always well founded.
--
-- = Laziness inside a loop
--
-- No signal function of the library evaluates its input, or the output of
-- a signal function it runs, before that value is demanded downstream at
-- the same sample: a stateful one (an edge, a hold, an accumulator, a
-- switch, a collection, 'AFRP.Integration.derivative', ...) keeps what it
-- needs of its input unevaluated and folds it into its state at the start
-- of the next sample, when every value of the previous sample exists. So
-- the knot of a loop is tied whenever the network is causal, as in Yampa:
--
-- > -- outputs its input at every sample; the edge watches the fed-back
-- > -- flag, and nobody needs the edge's output
-- > loop (second edge >>> arr (\(a, _) -> (a, a > 0)))
--
-- and a stateful signal function's output may be fed back through a delay
-- ('AFRP.Delay.iPre', 'loopPre'). Since each sample forces what the
-- previous one left, no thunk outlives one sample: a network runs in
-- constant space (bench/residency.sh measures it for each combinator;
-- for a collection of signal functions whose outputs are not all read,
-- in optimised code where the collection's type is known: see
-- "AFRP.Parallel").
--
-- One known exception: a 'AFRP.Delay.delay' (or another delay that
-- keeps several samples, not 'AFRP.Delay.iPre') fed back through a loop
-- whose output is read only now and then (@sample 1 >>> hold 0@ after
-- it, or @length@ of an 'AFRP.Run.embed'): the values it keeps refer to
-- the samples before them until someone reads them, so memory grows with
-- the samples not read (31 MB at 10^5 samples read once a second). Read
-- the loop's output at every sample (a strict fold, an actuation), or
-- feed back through 'AFRP.Delay.iPre', and it is constant again.
module AFRP.Loop
  ( loopPre
  , loopIntegral
  ) where

import           Control.Arrow    (loop, second, (>>>))
import           AFRP.Delay       (iPre)
import           AFRP.Integration (integral)
import           AFRP.Internal.SF
import           AFRP.VectorSpace

-- | @loopPre c0 sf@ feeds the second output of @sf@ back to its second
-- input through a one-sample delay initialised to @c0@: at time 0 @sf@
-- sees @c0@, at every later sample the value it output one sample
-- earlier.
--
-- > -- a counter: 0, 1, 2, ...
-- > loopPre 0 (arr (\(_, n) -> (n, n + 1)))
loopPre :: c -> SF (a, c) (b, c) -> SF a b
loopPre c0 sf = loop (second (iPre c0) >>> sf)
{-# INLINE loopPre #-}

-- 'loopPre' is inlined, so that @loopPre c (arr g)@ meets the rewrite
-- rule on @loop (second (iPre c) >>> arr g)@ ("AFRP.Delay").

-- | @loopIntegral sf@ feeds the second output of @sf@ back to its second
-- input through an 'integral': @sf@ outputs a derivative and sees its
-- integral (0 at time 0).
loopIntegral :: VectorSpace c s => SF (a, c) (b, c) -> SF a b
loopIntegral sf = loop (second integral >>> sf)
