{-# LANGUAGE GADTs        #-}
{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Internal.Loop
-- Description : Loops closed over nodes: without a knot where the shape
--               allows (a pure loop, a delay fed back), by a knot
--               otherwise.
--
-- Internal, not part of the API (re-exported, 'loopPreG', by
-- "AFRP.Internal.SF", whose 'Control.Arrow.loop' is 'loopN'). A loop
-- feeds the second component of a network's output back as the second
-- component of its input at the same sample. The usual shapes are
-- recognised and stepped without a knot (@loopPreN@, 'loopPreG'); the
-- others are closed by a knot whose fed-back value is a selector thunk,
-- so that a value fed back and never read holds on to nothing else
-- (@loopOut@).
module AFRP.Internal.Loop
  ( loopN
  , loopPreG
  ) where

import           AFRP.Internal.Node

-- | @loop@: feed the second output component back as the second input
-- component of the same sample.
loopN :: Node (a, c) (b, c) -> Node a b
-- loop (arr f) = arr (\a -> fst (fix (\ ~(_, c) -> f (a, c))))
loopN (NPure fd) =
  let f = fdFun fd
  in NPure (FDG (\a -> let (b, c) = f (a, c) in b))
-- loop (second d >>> f): the usual shape (loopPre, loopIntegral), kept
-- apart so that no pair (a, c) is built and taken apart at every step
loopN (NComp (NPar (NPure FDI) d) f) = loopN2 d f
loopN n = loopK idN n

-- @loop (second d >>> f)@, simplified: pure if both parts are, without a
-- knot if @d@ is a delay, and otherwise the general knot.
loopN2 :: Node c d -> Node (a, d) (b, c) -> Node a b
loopN2 = loopN2After ()

-- 'loopN2' for the successor of a knot's step, which holds the pair the
-- step produced, to be evaluated at the next step ('loopKAfter').
loopN2After :: x -> Node c d -> Node (a, d) (b, c) -> Node a b
loopN2After prev d f = case d of
  NPre c  -> loopPreN c f
  NPure _ -> case f of
    NPure _ -> loopN (compN (secondN d) f)
    _       -> loopKAfter prev d f
  _       -> loopKAfter prev d f

-- | @loopPreN c f = loop (second (iPre c) >>> f)@, stepped without a knot.
-- It relies on the delay's output at this step being @c@ whatever its
-- input: @f@ is stepped on @(a, c)@, its output @(b, c')@ gives the
-- output @b@, and the delay now holds @c'@ (both taken lazily, exactly as
-- the knot would: the delay stores its input unevaluated). So the loop is
-- @loopPreN c' f'@ afterwards; it never becomes pure (the delay is state).
loopPreN :: c -> Node (a, c) (b, c) -> Node a b
-- loop (second (iPre c) >>> arr g), the shape of 'AFRP.Loop.loopPre' on a
-- function: @f@ stays that function forever, so it is applied where it
-- stands (lazily, as its node would: 'stepN' of @arr g@ on @(a, c)@ is
-- @g (a, c)@ unevaluated) rather than stepped and rebuilt at every step.
loopPreN c (NPure (FDG g)) = loopPreG g c
loopPreN c f = NStep (\dt a -> case stepN f dt (a, c) of
  (# f', bc #) -> case loopPreN (snd bc) f' of !m -> (# m, fst bc #))

-- | @loopPreG g c@ is @loop (second (iPre c) >>> arr g)@, stepped without
-- a knot (@loopPreN c (arrN g)@): at each step @g@ is applied, lazily, to
-- the input and the stored value; the first component of the result is
-- the output, the second is stored, both unevaluated. Inlined, so that
-- where @g@ is known (the rewrite rule on @loop (second (iPre c) >>> arr
-- g)@ in "AFRP.Delay", which 'AFRP.Loop.loopPre' meets) GHC compiles the
-- step with @g@'s body in place: where @g@ returns its pair as a
-- constructor, the pair and the two selections from it then cost
-- nothing.
loopPreG :: ((a, c) -> (b, c)) -> c -> Node a b
loopPreG g = go
  where
    go c = NStep (\_ a -> let bc = g (a, c) in case go (snd bc) of !m -> (# m, fst bc #))
{-# INLINE loopPreG #-}

-- | @loopK d f = loop (second d >>> f)@, by a knot: @d@ sees, as its
-- input, the second component of the output that @f@ is producing at this
-- very step (through a lazy reference to the step's result); @f@ sees the
-- input and @d@'s output.
loopK :: Node c d -> Node (a, d) (b, c) -> Node a b
loopK = loopKAfter ()

-- | @loopKAfter prev d f@ is @loopK d f@ that first evaluates @prev@, the
-- pair @f@ output at the previous step (to weak head normal form: the
-- pair, not its components), as every stateful node evaluates what the
-- previous sample left at the start of its next step. See 'loopOut' for
-- why.
loopKAfter :: x -> Node c d -> Node (a, d) (b, c) -> Node a b
loopKAfter prev d f = NStep (\dt a -> prev `seq`
  let r = case stepN d dt c of
        (# d', y #) -> case stepN f dt (a, y) of
          (# f', out #) -> Loop d' f' out
      bc = loopOut r
      c  = case bc of (_, x) -> x
  in case r of Loop d' f' _ -> case loopN2After bc d' f' of !m -> (# m, case bc of (b, _) -> b #))

-- The result of a loop's step, in a box (the knot needs a lifted value).
data Loop c d a b x = Loop !(Node c d) !(Node (a, d) x) x

-- The pair @f@ produced is taken as @bc = loopOut r@, and the fed-back
-- value and the output are each a selection from @bc@ alone, of the form
-- @case bc of (_, x) -> x@, which GHC compiles as a selector thunk: once
-- @bc@ is evaluated, the garbage collector replaces the selection by the
-- component itself. The next step evaluates @bc@ ('loopKAfter'). So a
-- fed-back value nobody reads refers, after that, to its own value
-- alone, not to the pair (whose other component is the loop's output),
-- the step, its successor nodes or the values they hold.
--
-- Without it, a value fed back into a node that keeps it for several
-- samples ('AFRP.Delay.delay') referred to the step that produced it,
-- whose successor held the values fed back before, and so on: memory grew
-- with every sample at which nobody read the loop's output (307 MB at
-- 10^6 samples with the output never read, 300 MB read once a second;
-- tested by "AFRP.ResidencySpec"). Taken from the step in one pattern,
-- @case r of Loop _ _ (_, c') -> c'@, the selection is not a selector
-- thunk. 'loopOut' is NOINLINE: inlined, GHC merges the selections from
-- it into one pattern on the step.
loopOut :: Loop c d a b x -> x
loopOut (Loop _ _ x) = x
{-# NOINLINE loopOut #-}
