{-# LANGUAGE Arrows #-}
-- | The bouncing ball every Yampa tutorial starts with, written as a Yampa
-- program: a falling ball as integrals in arrow notation, a bounce as a
-- 'switch' on an 'edge', the ball restarted with its velocity reversed and
-- damped. Only the import differs from the Yampa version (@import
-- FRP.Yampa@ instead of @import AFRP@).
module Ported.BouncingBall
  ( Pos
  , Vel
  , fallingBall
  , bouncingBall
  ) where

import           AFRP

type Pos = Double
type Vel = Double

-- | A ball dropped from height @y0@ with vertical speed @v0@.
fallingBall :: Pos -> Vel -> SF () (Pos, Vel)
fallingBall y0 v0 = proc () -> do
  v <- (v0 +) ^<< integral -< -9.81
  y <- (y0 +) ^<< integral -< v
  returnA -< (y, v)

-- | The falling ball and the event of its hitting the floor.
fallingBall' :: Pos -> Vel -> SF () ((Pos, Vel), Event (Pos, Vel))
fallingBall' y0 v0 = proc () -> do
  yv@(y, _) <- fallingBall y0 v0 -< ()
  hit       <- edge -< y <= 0
  returnA -< (yv, hit `tag` yv)

-- | A ball dropped from @y0@ that bounces, losing a tenth of its speed at
-- each bounce.
bouncingBall :: Pos -> SF () (Pos, Vel)
bouncingBall y0 = bbAux y0 0
  where
    bbAux y v = switch (fallingBall' y v) $ \(y', v') -> bbAux y' (-v' * 0.9)
