{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Ex10
-- Description : Exercise 10 of the notes: a sinusoidal path.
--
-- \"Define a controller to cause a robot to follow a sinusoidal path.
-- (Hint: feed a sinusoidal signal into @rcHeadingAux@.)\"
--
-- The desired heading swings sinusoidally about a mean direction,
-- @h0 + a sin (2 pi t / T)@, and 'rcHeadingAux' steers the robot after it
-- at a constant speed. The robot's sideways velocity is then (for small
-- swings) @v a sin (2 pi t / T)@, so its path is a wave of wavelength
-- about @v T@ and amplitude about @v a T / (2 pi)@ (a little less:
-- 'rcHeadingAux' is a proportional controller with gain 2, so the heading
-- lags the command and swings slightly less). For larger swings the
-- forward progress is @v cos@ of the heading's offset, so a wave is
-- shorter: the example's SimbotA (0.4 m/s, a swing of 1 rad, T = 8 s)
-- advances about 2.5 m a period, not 3.2.
module Exercises.Ex10
  ( rcSine
  , ex10World
  , examples
  ) where

import           AFrob
import           AFrobRobotSim
import           Examples.Types
import           Paper.Section3 (rcHeadingAux)

-- | @rcSine v h0 a period@: drive at @v@ with the heading
-- @h0 + a sin (2 pi t / period)@.
rcSine :: Velocity -> Heading -> Angle -> Time -> SimbotController
rcSine v h0 a period rps = proc sbi -> do
  t <- time -< ()
  let hd = h0 + a * sin (2 * pi * t / period)
  rcHeadingAux rps -< (sbi, v, hd)

-- | A SimbotA and a SimbotB at the west side of the world, heading east.
ex10World :: WorldTemplate
ex10World = [OTSimbotA 1 (Point2 (-4.5) 1.5) 0, OTSimbotB 1 (Point2 (-4.5) (-2)) 0]

examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex10"
      , exDescription = "a sinusoidal heading fed into rcHeadingAux: wavy paths across the world"
      , exWorld       = ex10World
      , exControllerA = rcSine 0.4 0 1.0 8
      , exControllerB = rcSine 0.45 0 1.2 5
      , exSeconds     = 24
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]
