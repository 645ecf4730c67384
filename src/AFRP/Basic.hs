{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Basic
-- Description : The basic signal functions: identity, constants, time, and
--               operators that act on the first sample.
--
-- Everything here is stateless except 'localTime' / 'time'. The operators
-- '-->', '>--', '-=>' and '>=-' change only what happens at the very first
-- sample (local time 0) of a signal function and leave every later sample
-- untouched.
module AFRP.Basic
  ( -- * Lifting
    arr2
  , arr3
  , arr4
  , arr5
  , dup
  , identity
  , constant
    -- * Time
  , localTime
  , time
    -- * Initialisation
  , (-->)
  , (-:>)
  , (>--)
  , (-=>)
  , (>=-)
  , initially
  ) where

import           Control.Arrow     (Arrow, arr)
import           AFRP.Internal.Clock
import           AFRP.Internal.SF

infixr 0 -->, -:>, >--, -=>, >=-

-- | Lift a binary function to a signal function on pairs:
-- @arr2 f = arr (uncurry f)@, in any arrow as in Yampa. For example
-- @arr2 (+) :: Num a => SF (a, a) a@.
arr2 :: Arrow r => (a -> b -> c) -> r (a, b) c
arr2 f = arr (uncurry f)
{-# INLINE arr2 #-}

-- | Lift a ternary function to a signal function on triples.
arr3 :: Arrow r => (a -> b -> c -> d) -> r (a, b, c) d
arr3 f = arr (\(a, b, c) -> f a b c)
{-# INLINE arr3 #-}

-- | Lift a function of four arguments to a signal function on 4-tuples.
arr4 :: Arrow r => (a -> b -> c -> d -> e) -> r (a, b, c, d) e
arr4 f = arr (\(a, b, c, d) -> f a b c d)
{-# INLINE arr4 #-}

-- | Lift a function of five arguments to a signal function on 5-tuples.
arr5 :: Arrow r => (a -> b -> c -> d -> e -> f) -> r (a, b, c, d, e) f
arr5 f = arr (\(a, b, c, d, e) -> f a b c d e)
{-# INLINE arr5 #-}

-- | Duplicate a value: @dup x = (x, x)@. As Yampa's; handy as
-- @arr dup@ to feed one signal to both halves of '***'.
dup :: a -> (a, a)
dup x = (x, x)
{-# INLINE dup #-}

-- | The identity signal function: output equals input at every sample.
-- Equal to @arr id@ and to 'Control.Category.id', but recognised by the
-- optimiser, so @identity >>> sf@ and @sf >>> identity@ cost nothing.
identity :: SF a a
identity = SF idN

-- | @constant b@ outputs @b@ at every sample, whatever its input
-- (@arr (const b)@). Recognised by the optimiser: @sf >>> constant b@ is
-- simplified to @constant b@.
constant :: b -> SF a b
constant b = SF (constN b)
{-# INLINE constant #-}

-- | Local time: the time since this signal function started. It is 0 at
-- the first sample, and afterwards the sum of the time steps seen so far
-- (kept as a compensated sum, so that ten steps of 0.1 read exactly 1.0).
-- It restarts at 0 in a signal function that is switched in.
--
-- > embed localTime ((), [(0.5, Nothing), (0.25, Nothing)])  ==  [0, 0.5, 0.75]
localTime :: SF a Time
localTime = SF (initN (\_ -> (# go (tick clockZero 0), 0 #)))
  where
    go !c = NStep (\dt _ -> let !c' = tick c dt
                                !t  = clockTime c'
                            in (# go c', t #))

-- | The time since the signal function started: the same as 'localTime'.
-- The notes define it as @constant 1.0 >>> integral@, which it equals up to
-- floating-point rounding (it is more exact).
time :: SF a Time
time = localTime

-- | @b0 --> sf@ outputs @b0@ at the first sample (local time 0) and the
-- output of @sf@ at every later sample. @sf@ does run at the first sample;
-- only its output there is replaced.
--
-- > embed (0 --> identity) (5, [(1, Just 6), (1, Just 7)])  ==  [0, 6, 7]
(-->) :: b -> SF a b -> SF a b
b0 --> SF n = SF (initN (\a -> case stepN n 0 a of (# n', _ #) -> (# n', b0 #)))

-- | @initially a0@ outputs @a0@ at the first sample (local time 0) and its
-- input at every later sample: @initially a0 = a0 --> identity@, Yampa's
-- type. (afrp's earlier @initially b0 sf@ was a synonym of '-->'; write
-- @b0 --> sf@ for that.)
--
-- > embed (initially 0) (5, [(1, Just 6), (1, Just 7)])  ==  [0, 6, 7]
initially :: a -> SF a a
initially a0 = a0 --> identity

-- | @b0 -:> sf@ inserts @b0@ as the first output and delays @sf@ by one
-- sample: @sf@ does not run at the first sample (local time 0); it starts
-- (its own local time 0) at the second sample, with that sample's input,
-- and supplies every later output. Unlike '-->', nothing of @sf@ is lost.
--
-- > embed (0 -:> identity) (5, [(1, Just 6), (1, Just 7)])  ==  [0, 6, 7]
-- > embed (0 -:> localTime) ((), [(1, Nothing), (1, Nothing)])  ==  [0, 0, 1]
(-:>) :: b -> SF a b -> SF a b
b0 -:> SF n = SF (initN (\_ -> (# n, b0 #)))

-- | @a0 >-- sf@ gives @sf@ the input @a0@ at the first sample instead of
-- the real one; later samples are passed unchanged.
(>--) :: a -> SF a b -> SF a b
a0 >-- SF n = SF (initN (\_ -> stepN n 0 a0))

-- | @f -=> sf@ applies @f@ to the output of @sf@ at the first sample only.
(-=>) :: (b -> b) -> SF a b -> SF a b
f -=> SF n = SF (initN (\a -> case stepN n 0 a of (# n', b #) -> (# n', f b #)))

-- | @f >=- sf@ applies @f@ to the input of @sf@ at the first sample only.
(>=-) :: (a -> a) -> SF a b -> SF a b
f >=- SF n = SF (initN (\a -> stepN n 0 (f a)))
