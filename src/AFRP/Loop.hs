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
-- previous one left of the library's own state, the library keeps no
-- chain of thunks from sample to sample: a network whose own values are
-- not lazy accumulations runs in constant space (bench/residency.sh
-- measures it for each combinator; for a collection of signal functions
-- whose outputs are not all read, in optimised code where the
-- collection's type is known: see "AFRP.Parallel"; the exception below).
--
-- = What a loop evaluates
--
-- Every loop other than @loop (second (iPre c) >>> f)@ ('loopPre' is one)
-- and @loop@ of a pure function (so every @rec@ block of arrow notation
-- that is not of that shape, and every loop through a 'AFRP.Delay.delay',
-- an integral or a switch) evaluates, at the start of each sample, the
-- pair its body output at the sample before: to the pair, not its
-- components. The value it fed back then refers to itself alone, not to
-- the rest of that sample, so a 'AFRP.Delay.delay' that keeps many
-- samples of the fed-back signal runs in constant space whether or not
-- anybody reads the loop's output, or reads it now and then
-- ("AFRP.ResidencySpec").
--
-- What this asks of a network: the body's output pair must exist at every
-- sample, also at one whose output nobody reads; a body whose pair is an
-- error (bottom) at some sample fails the run at the next, whether or not
-- that output is read, as in Yampa, whose loop matches the pair together
-- with the body's next step (the loops above that evaluate nothing are
-- the difference: @loop (second (iPre 0) >>> pre)@ goes on in afrp and
-- stops in Yampa 0.15, found by a differential fuzz). A pair written as a tuple (@arr (\(a, c) -> (e1, e2))@) always
-- exists. In a @rec@ block the pair is made of the block's result and its
-- variables, in the shape GHC's translation of the arrow notation gives
-- it, and a pattern binding them is matched strictly: after
-- @rec (x, y) <- sf -< e@ the pair may exist only where @sf@'s output
-- pair does, so a 'AFRP.Delay.pre' there (no output at time 0), or an
-- @sf@ whose output is an error at some sample, may fail the run. Whether
-- it does depends on that shape, and so may differ from Yampa in either
-- direction: with a 'AFRP.Delay.delay' after the pair
-- (@rec (x, y) <- pre -< (a, z); z <- delay 1 0 -< x + y@) both fail;
-- with an 'AFRP.Delay.iPre' after an @sf@ that errs at one sample, afrp
-- went on where Yampa 0.15 failed. To be sure of neither, use
-- 'AFRP.Delay.iPre' rather than 'AFRP.Delay.pre', and a lazy pattern
-- (@~(x, y) <- sf -< e@).
--
-- = The exception: a lazy value kept by a delay
--
-- A value fed back that is itself an unevaluated computation on earlier
-- values of the loop (a lazy accumulator, or the input a stateful node
-- such as 'AFRP.Delay.iPre' keeps, sitting between a 'AFRP.Delay.delay''s
-- output and the value fed back), kept by a delay for many samples,
-- refers to the samples before it until somebody evaluates it, as in
-- Yampa: when the loop's output is read only now and then, memory grows
-- with the run (25 MB at 10^5 samples, 196 MB at 10^6, for @loop (second
-- (delay 0.5 0) >>> arr swap >>> second (iPre 0))@ read once a second).
-- Read the loop's output at every sample (a strict fold, an actuation),
-- and it runs in constant space again.
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
--
-- (A lazy accumulation, as this counter is: read its output at every
-- sample, or it keeps a chain of additions; see the module's header.)
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
