-- |
-- Module      : Exercises.Ex01
-- Description : Exercise 1: first, (***) and (&&&) from other combinators.
--
-- Exercise 1 of the notes: define
--
-- (a) @first@ in terms of just @arr@, @(>>>)@ and @(&&&)@,
--
-- (b) @(***)@ in terms of just @first@, @second@ and @(>>>)@,
--
-- (c) @(&&&)@ in terms of just @arr@, @(>>>)@ and @(***)@.
--
-- Each answer is written for any 'Arrow', so it works for plain functions
-- as well as for signal functions. For signal functions each one equals
-- the library's combinator at every sample, also when the argument signal
-- functions have state (an 'integral', an 'iPre', ...): the argument is
-- run exactly once, on the component it is given.
module Exercises.Ex01
  ( firstA
  , parA
  , fanA
  , examples
  ) where

import           Data.List       (zip4)

import           AFrob

import           Examples.Types  (Example (..))
import           Paper.Section2  (formatTable, runEvery, showD)

-- | (a) @first@ from @arr@, @(>>>)@ and @(&&&)@: @firstA f@ runs @f@ on the
-- first component of its input and passes the second one through, so
-- @firstA f = first f@.
--
-- > firstA (arr (+1)) (1, 'x')  ==  (2, 'x')
firstA :: Arrow a => a b c -> a (b, d) (c, d)
firstA f = (arr fst >>> f) &&& arr snd

-- | (b) @(***)@ from @first@, @second@ and @(>>>)@: @parA f g@ runs @f@ on
-- the first component and @g@ on the second, so @parA f g = f *** g@.
--
-- > parA (arr (+1)) (arr not) (1, True)  ==  (2, False)
parA :: Arrow a => a b c -> a b' c' -> a (b, b') (c, c')
parA f g = first f >>> second g

-- | (c) @(&&&)@ from @arr@, @(>>>)@ and @(***)@: @fanA f g@ runs both @f@
-- and @g@ on its input (duplicated), so @fanA f g = f &&& g@.
--
-- > fanA (arr (+1)) (arr show) 1  ==  (2, "1")
fanA :: Arrow a => a b c -> a b c' -> a b (c, c')
fanA f g = arr (\b -> (b, b)) >>> (f *** g)

-- | One report per part: the answer and the library's combinator, with
-- stateful signal functions as arguments, on the same scripted input.
examples :: [Example]
examples =
  [ SignalExample "ex1a" "Exercise 1(a): first from arr, >>> and &&&" reportA
  , SignalExample "ex1b" "Exercise 1(b): *** from first, second and >>>" reportB
  , SignalExample "ex1c" "Exercise 1(c): &&& from arr, >>> and ***" reportC
  ]

-- The scripted input: samples every 0.5 s.
dt :: DTime
dt = 0.5

inputs :: [Double]
inputs = [1, 2, 2, -1, 0, 3, 1, 1]

pairs :: [(Double, Double)]
pairs = zip inputs (reverse inputs)

times :: [Time]
times = [ fromIntegral n * dt | n <- [0 :: Int ..] ]

showP :: (Double, Double) -> String
showP (x, y) = "(" ++ showD x ++ ", " ++ showD y ++ ")"

reportA :: String
reportA =
  "firstA integral and first integral on pairs, sampled every 0.5 s.\n\n"
  ++ formatTable ["t", "input", "firstA integral", "first integral"]
       [ [showD t, showP i, showP a, showP b]
       | (t, i, a, b) <- zip4 times pairs (runEvery dt (firstA integral) pairs)
                                           (runEvery dt (first integral) pairs) ]

reportB :: String
reportB =
  "parA integral (iPre 0) and integral *** iPre 0 on pairs, sampled every 0.5 s.\n\n"
  ++ formatTable ["t", "input", "parA", "***"]
       [ [showD t, showP i, showP a, showP b]
       | (t, i, a, b) <- zip4 times pairs (runEvery dt (parA integral (iPre 0)) pairs)
                                           (runEvery dt (integral *** iPre 0) pairs) ]

reportC :: String
reportC =
  "fanA integral derivative and integral &&& derivative, sampled every 0.5 s.\n\n"
  ++ formatTable ["t", "input", "fanA", "&&&"]
       [ [showD t, showD i, showP a, showP b]
       | (t, i, a, b) <- zip4 times inputs (runEvery dt (fanA integral derivative) inputs)
                                            (runEvery dt (integral &&& derivative) inputs) ]
