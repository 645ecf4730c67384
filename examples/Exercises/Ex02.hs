-- |
-- Module      : Exercises.Ex02
-- Description : Exercise 2: ySF and thetaSF from the wheel speeds, unsugared.
--
-- Exercise 2 of the notes: define @ySF@ and @thetaSF@, the AFRP versions of
-- the notes' equations
--
-- > y     = (1/2) (integral ((vr + vl) * sin theta))
-- > theta = (1/l) (integral (vr - vl))
--
-- written, like the notes' @xSF@, with the arrow combinators alone. The
-- wheel speeds are those of "Paper.Section2" (estimated from the
-- odometry), @l@ is its 'wheelBase'.
--
-- Both integrals start at 0, so 'thetaSF' is the heading relative to the
-- heading at time 0 (and, unlike the odometry heading, it is never
-- normalised: a simbot that has turned twice round reads 4 pi), and 'ySF'
-- is the displacement since time 0 across that initial heading, to the
-- left. Both use 'integral', the left rectangle rule: the output at a
-- sample uses the wheel speeds up to the previous sample.
--
-- The wiring, with the groups of the unsugared definitions outlined by
-- dashes, like the notes' Fig. 2(b): a box @+--+@ is a signal function, a
-- name in parentheses a lifted function ('arr'). The same figures, drawn,
-- are @docs\/diagrams\/thetaSF.svg@ and @docs\/diagrams\/ySF.svg@;
-- "Exercises.Ex03" has the plain wiring of the arrow-syntax versions.
--
-- > thetaSF = let v = (vrSF &&& vlSF) >>> arr2 (-) in v >>> integral >>> arr (/ wheelBase)
-- >
-- >              v = (vrSF &&& vlSF) >>> arr2 (-)
-- >          .- - - - - - - - - - - - - - - - - .
-- >          :          +------+  vr            :
-- >          :     .--->| vrSF |------.         :
-- >          :     |    +------+      v         :     +----------+
-- >   inp ---:-----+                 (-)--------:---->| integral |---->(/l)----> theta
-- >          :     |    +------+      ^         :     +----------+
-- >          :     '--->| vlSF |------'         :
-- >          :          +------+  vl            :
-- >          '- - - - - - - - - - - - - - - - - '
-- >
-- > ySF = let v = (vrSF &&& vlSF) >>> arr2 (+)
-- >           t = thetaSF >>> arr sin
-- >       in (v &&& t) >>> arr2 (*) >>> integral >>> arr (/2)
-- >
-- >                    v = (vrSF &&& vlSF) >>> arr2 (+)
-- >              .- - - - - - - - - - - - - - - - - - .
-- >              :           +---------+  vr          :
-- >              :      .--->|  vrSF   |-----.        :
-- >              :      |    +---------+     v        :  vr + vl
-- >              :      |                   (+)-------:----------.
-- >              :      |    +---------+     ^        :          |
-- >          .---:------+--->|  vlSF   |-----'        :          |
-- >          |   :           +---------+  vl          :          v      +----------+
-- >   inp ---+   '- - - - - - - - - - - - - - - - - - '         (*)---->| integral |---->(/2)----> y
-- >          |   .- - - - - - - - - - - - - - - - - - .          ^      +----------+
-- >          |   :           +---------+  theta       :          |
-- >          '---:---------->| thetaSF |------>(sin)--:----------'
-- >              :           +---------+              :  sin theta
-- >              '- - - - - - - - - - - - - - - - - - '
-- >                    t = thetaSF >>> arr sin
module Exercises.Ex02
  ( thetaSF
  , ySF
  , examples
  ) where

import           Data.List       (zip4)

import           AFrob
import           AFrobRobotSim   (SimbotInput)

import           Examples.Types  (Example (..))
import           Paper.Section2  (arcPath, formatTable, runEvery, showD, vlSF, vrSF, wheelBase)

-- | The simbot's orientation by the notes' equation
-- @theta = (1\/l) (integral (vr - vl))@: the angle it has turned through
-- since time 0 (radians, counter-clockwise positive, not normalised). 0 at
-- time 0.
thetaSF :: SF SimbotInput Angle
thetaSF = let v = (vrSF &&& vlSF) >>> arr2 (-)
          in v >>> integral >>> arr (/ wheelBase)

-- | The y coordinate by the notes' equation
-- @y = (1\/2) (integral ((vr + vl) * sin theta))@, with 'thetaSF' for
-- @theta@: the distance the simbot has moved to the left of its heading
-- at time 0. 0 at time 0.
ySF :: SF SimbotInput Distance
ySF = let v = (vrSF &&& vlSF) >>> arr2 (+)
          t = thetaSF >>> arr sin
      in (v &&& t) >>> arr2 (*) >>> integral >>> arr (/2)

-- | One report: 'thetaSF' and 'ySF' beside the odometry on a circle.
examples :: [Example]
examples =
  [ SignalExample "ex2"
      "Exercise 2: ySF and thetaSF from the wheel speeds, unsugared, on a circle"
      report
  ]

report :: String
report =
  "A simbot on a circle from the origin, heading 0 (v = 0.5 m/s, w = 0.5 rad/s),\n"
  ++ "sampled every 0.1 s: thetaSF and ySF follow the odometry two samples late (one\n"
  ++ "for the derivatives that estimate the wheel speeds, one for the integral), and\n"
  ++ "thetaSF goes on past pi where the odometry heading wraps round.\n\n"
  ++ formatTable ["t", "odometry heading", "thetaSF", "odometry y", "ySF"]
       [ [showD t, showD (odometryHeading i), showD th, showD (point2Y (odometryPosition i)), showD y]
       | (k, (t, i, th, y)) <- zip [0 :: Int ..] (zip4 times inputs (run thetaSF) (run ySF))
       , k `mod` 10 == 0 ]
  where
    dt     = 0.1
    times  = [ fromIntegral n * dt | n <- [0 .. 80 :: Int] ]
    inputs = arcPath 0.5 0.5 times
    run s  = runEvery dt s inputs
