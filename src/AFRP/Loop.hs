-- |
-- Module      : AFRP.Loop
-- Description : Feedback loops closed through a delay or an integral.
--
-- 'Control.Arrow.loop' itself comes from the 'Control.Arrow.ArrowLoop'
-- instance of 'SF' (re-exported by "AFRP"). The two loops here close the
-- feedback path through a primitive that never looks at its current
-- input, so they are always well founded.
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
