-- | One network per stateful combinator, for the constant-space check of
-- bench/residency.sh (@afrp-bench --loop NAME N@).
--
-- Each combinator watches a signal fed back through a 'loop' (computed
-- from the current input, so the network has no real cycle). In the plain
-- form its output is discarded: nobody ever demands it, which is where a
-- combinator that left its input unevaluated from step to step would
-- build a chain of thunks. In the @+@ form its output is added to the
-- loop's output, and so demanded at every sample.
module Residency
  ( loopNetworks
  , loopNetwork
  ) where

import           AFRP

-- | The combinators, each fed from a 'Double' (the fed-back signal), its
-- output made a 'Double'.
loopNetworks :: [(String, SF Double Double)]
loopNetworks =
  [ ("edge",         arr (\c -> sin c > 0) >>> edge >>> arr evU)
  , ("iEdge",        arr (\c -> sin c > 0) >>> plain (iEdge False) >>> arr evU)
  , ("edgeJust",     arr (\c -> if sin c > 0 then Just c else Nothing) >>> edgeJust >>> arr ev)
  , ("edgeBy",       edgeBy (\x y -> if y > x + 0.5 then Just y else Nothing) 0 >>> arr ev)
  , ("once",         arr tick >>> once >>> arr ev)
  , ("takeEvents",   arr tick >>> takeEvents 1000 >>> arr ev)
  , ("dropEvents",   arr tick >>> dropEvents 1000 >>> arr ev)
  , ("hold",         arr tick >>> hold 0)
  , ("accumHold",    arr (fmap (+) . tick) >>> accumHold 0)
  , ("accumBy",      arr tick >>> accumBy (+) 0 >>> arr ev)
  , ("sampleWindow", sampleWindow 3 0.05 >>> arr (event 0 sum))
  , ("delay",        delay 0.5 0)
  , ("delayEvent",   arr tick >>> delayEvent 0.05 >>> arr ev)
  , ("integral",     integral)
  , ("imIntegral",   imIntegral 0)
  , ("trapezoid",    trapezoidIntegral)
  , ("derivative",   derivative)
  , ("switch",       restart)
  , ("rSwitch",      arr (\c -> (c, fmap (const integral) (tick c))) >>> rSwitch integral)
  , ("kSwitch",      kSwitch integral (arr (tick . fst)) (\sf _ -> sf))
  , ("left",         arr (\c -> if sin c > 0 then Left c else Right c) >>> left integral
                       >>> arr (either id id))
  , ("parZ",         arr (\c -> [c, c]) >>> parZ [integral, derivative] >>> arr sum)
  , ("pSwitchB",     pSwitchB [integral, derivative] (arr (tick . fst)) (\sfs _ -> parB sfs)
                       >>> arr sum)
  , ("rpSwitchB",    arr (\c -> (c, fmap (const reverse) (tick c))) >>> rpSwitchB [integral, derivative]
                       >>> arr sum)
  , ("loopPre",      loopPre 0 (arr (\(c, s) -> (s, 0.5 * s + c))))
  , ("loopIntegral", loopIntegral (arr (\(c, x) -> (x, sin c - x))))
  , ("sscan",        sscan (\b c -> 0.5 * b + c) 0)
  , ("sscanPrim",    sscanPrim (\s c -> if sin c > 0 then Just (0.5 * s + c, s) else Nothing) 0 0)
  , ("iterFrom",     iterFrom (\a a' h v -> 0.5 * v + h * (a + a') / 2) 0)
  , ("pause",        pause 0 (arr (\c -> sin c > 0)) integral)
  , ("parC",         arr (\c -> [c, c]) >>> parC integral >>> arr sum)
  ]
  where
    evU = event 0 (const 1)
    ev = event 0 id
    -- An occurrence every 10 samples.
    tick c = if (truncate c :: Int) `mod` 10 == 0 then Event c else NoEvent
    -- A switch into a fresh integral at every tick (through an edge).
    restart = switch (integral &&& (arr (\c -> (truncate c :: Int) `mod` 10 == 0) >>> iEdge True))
                     (\() -> restart)

-- Out of the rewrite rules' sight: the edge as a node of its own.
plain :: SF a b -> SF a b
plain sf = sf
{-# NOINLINE plain #-}

-- | @loopNetwork used sf@: @sf@ watches the input, fed back through a
-- loop; its output is added to the loop's output if @used@, discarded
-- otherwise.
loopNetwork :: Bool -> SF Double Double -> SF Double Double
loopNetwork used sf = loop (second sf >>> arr out)
  where
    out (a, y) = (if used then a + y else a, a)
