{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Ex03
-- Description : Exercise 3: ySF and thetaSF in arrow syntax, and their
--               signal flow diagrams.
--
-- Exercise 3 of the notes: rewrite the @ySF@ and @thetaSF@ of Exercise 2
-- ("Exercises.Ex02") in arrow syntax, and draw their signal flow diagrams.
-- The signal functions are the same as Exercise 2's, sample for sample;
-- the wheel speeds are those of "Paper.Section2", @l@ its 'wheelBase'.
--
-- The diagrams, like the notes' Fig. 2(a): a box @+--+@ is a signal
-- function, a name in parentheses a lifted function ('arr'), and each
-- wire is named after the variable of the arrow-syntax definition it
-- carries. The same figures, drawn (with the unsugared definitions'
-- groups outlined), are @docs\/diagrams\/thetaSF.svg@ and
-- @docs\/diagrams\/ySF.svg@.
--
-- > thetaSF:
-- >
-- >               +------+  vr
-- >          .--->| vrSF |------.
-- >          |    +------+      v                +----------+
-- >   inp ---+                 (-)-- vr - vl --->| integral |--- i --->(/l)----> theta
-- >          |    +------+      ^                +----------+
-- >          '--->| vlSF |------'
-- >               +------+  vl
-- >
-- > ySF:
-- >
-- >               +---------+  vr
-- >          .--->|  vrSF   |-----.
-- >          |    +---------+     v
-- >          |                   (+)----------.
-- >          |    +---------+     ^           |  vr + vl
-- >   inp ---+--->|  vlSF   |-----'           v               +----------+
-- >          |    +---------+  vl            (*)------------->| integral |--- i --->(/2)----> y
-- >          |                                ^               +----------+
-- >          |    +---------+  theta          |
-- >          '--->| thetaSF |------->(sin)----'
-- >               +---------+          sin theta
--
-- Here @thetaSF@ in the second diagram is the first diagram.
module Exercises.Ex03
  ( thetaSF
  , ySF
  , examples
  ) where

import           Data.List       (zip6)
import           Text.Printf     (printf)

import           AFrob
import           AFrobRobotSim   (SimbotInput)

import           Examples.Types  (Example (..))
import qualified Exercises.Ex02  as Ex02
import           Paper.Section2  (arcPath, formatTable, runEvery, showD, vlSF, vrSF, wheelBase)

-- | 'Exercises.Ex02.thetaSF' in arrow syntax: the angle the simbot has
-- turned through since time 0, @(1\/l) (integral (vr - vl))@. 0 at time 0.
thetaSF :: SF SimbotInput Angle
thetaSF = proc inp -> do
  vr <- vrSF     -< inp
  vl <- vlSF     -< inp
  i  <- integral -< vr - vl
  returnA -< i / wheelBase

-- | 'Exercises.Ex02.ySF' in arrow syntax: the distance the simbot has
-- moved to the left of its heading at time 0,
-- @(1\/2) (integral ((vr + vl) * sin theta))@. 0 at time 0.
ySF :: SF SimbotInput Distance
ySF = proc inp -> do
  vr    <- vrSF     -< inp
  vl    <- vlSF     -< inp
  theta <- thetaSF  -< inp
  i     <- integral -< (vr+vl) * sin theta
  returnA -< (i/2)

-- | One report: the arrow-syntax and the unsugared definitions side by
-- side on a circle.
examples :: [Example]
examples =
  [ SignalExample "ex3"
      "Exercise 3: ySF and thetaSF in arrow syntax: the same as Exercise 2's"
      report
  ]

report :: String
report =
  "Exercises 2 and 3 on a circle from the origin, heading 0 (v = 0.5 m/s,\n"
  ++ "w = 0.5 rad/s), sampled every 0.1 s.\n\n"
  ++ formatTable ["t", "thetaSF (ex2)", "thetaSF (ex3)", "ySF (ex2)", "ySF (ex3)"]
       [ [showD t, showD a, showD b, showD c, showD d]
       | (k, t, a, b, c, d) <- zip6 [0 :: Int ..] times th2 th3 y2 y3, k `mod` 10 == 0 ]
  ++ printf "\nlargest differences over all %d samples: %g (thetaSF), %g (ySF)\n"
       (length times) (maxDiff th2 th3) (maxDiff y2 y3)
  where
    dt     = 0.1
    times  = [ fromIntegral n * dt | n <- [0 .. 80 :: Int] ] :: [Time]
    inputs = arcPath 0.5 0.5 times
    run s  = runEvery dt s inputs
    th2    = run Ex02.thetaSF
    th3    = run thetaSF
    y2     = run Ex02.ySF
    y3     = run ySF
    maxDiff xs ys = maximum (zipWith (\x y -> abs (x - y)) xs ys) :: Double
