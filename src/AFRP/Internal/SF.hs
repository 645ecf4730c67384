{-# LANGUAGE GADTs        #-}
{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Internal.SF
-- Description : The signal-function type and the Arrow instances (its
--               loops closed by "AFRP.Internal.Loop").
--
-- Internal, not part of the API (exposed for the library's own tests and
-- benchmarks): users import "AFRP", where 'SF' is abstract.
--
-- A signal function is a network of nodes ("AFRP.Internal.Node", whose
-- design notes explain the representation and what keeps it fast); this
-- module wraps a node as an 'SF', closes loops over nodes (by
-- "AFRP.Internal.Loop"), and gives 'SF' its instances, with the rewrite
-- rules that fuse lifted functions composed where GHC can see them. It
-- re-exports "AFRP.Internal.Node" and "AFRP.Internal.Deferred".
module AFRP.Internal.SF
  ( -- * Signal functions
    SF (..)
  , module AFRP.Internal.Node
  , module AFRP.Internal.Deferred
    -- * The instances' composition and lifting (for rewrite rules)
  , compSF
  , arrSF
  , firstSF
  , arrFirstSF
  , arrFirstQSF
  , secondSF
  , loopSF
    -- * Loops (for rewrite rules)
  , loopPreG
    -- * Introspection (for tests)
  , stepSF
  , isPureSF
  , isConstantSF
  , isStepSF
  , sfShape
  ) where

import           Control.Arrow
import           Control.Category (Category (..))
import           Prelude          hiding (id, (.))

import           AFRP.Internal.Deferred
import           AFRP.Internal.Loop
import           AFRP.Internal.Node

------------------------------------------------------------------------------
-- Signal functions

-- | A signal function: conceptually @Signal a -> Signal b@, a causal
-- transformer of time-varying values. 'SF' is abstract; build signal
-- functions with the primitives and combinators of "AFRP", run them with
-- 'AFRP.Run.reactimate' or 'AFRP.Run.embed'.
newtype SF a b = SF { sfNode :: Node a b }

------------------------------------------------------------------------------
-- Introspection

-- | One step of a signal function from the outside: its successor and its
-- output. The first step of a fresh signal function ignores the time step.
-- Used by the tests that watch the network simplify as it runs.
stepSF :: SF a b -> DTime -> a -> (SF a b, b)
stepSF (SF n) dt a = case stepN n dt a of (# n', b #) -> (SF n', b)

-- | Is the signal function (in its current form) stateless? Used by the
-- tests that check the optimiser.
isPureSF :: SF a b -> Bool
isPureSF (SF (NPure _)) = True
isPureSF _              = False

-- | Is the signal function (in its current form) a constant?
isConstantSF :: SF a b -> Bool
isConstantSF (SF (NPure (FDC _))) = True
isConstantSF _                    = False

-- | Is the signal function (in its current form) one opaque stateful
-- node, rather than a composition or another structural node? Used by the
-- tests that check that a rewrite rule made one node of two.
isStepSF :: SF a b -> Bool
isStepSF (SF (NStep _)) = True
isStepSF _              = False

-- | The shape of the network as it is now, for tests that check how it
-- was built: @arr@ (a lifted function), @id@, @const@, @step@ (an opaque
-- stateful node), @pre@ (a delay), @int@ (an integral at 'Double'), and
-- @(f >>> g)@, @(f *** g)@, @(f &&& g)@ around them.
sfShape :: SF a b -> String
sfShape (SF n0) = go n0
  where
    go :: Node x y -> String
    go n = case n of
      NPure FDI     -> "id"
      NPure (FDC _) -> "const"
      NPure (FDG _) -> "arr"
      NComp f g     -> "(" ++ go f ++ " >>> " ++ go g ++ ")"
      NPar f g      -> "(" ++ go f ++ " *** " ++ go g ++ ")"
      NFan f g      -> "(" ++ go f ++ " &&& " ++ go g ++ ")"
      NStep _       -> "step"
      NPre _        -> "pre"
      NIntD _ _     -> "int"

------------------------------------------------------------------------------
-- Composition and lifting, fused at compile time

-- | The instances' composition: @compSF g f@ is @g . f@ ('compN' at run
-- time). A function of its own, inlined only late (phase 1), so that the
-- rewrite rules below (and those of other modules, such as
-- "AFRP.EventSource"'s for @arr p >>> edge@) see compositions written in
-- the source.
compSF :: SF b c -> SF a b -> SF a c
compSF (SF g) (SF f) = SF (compB f g)
{-# INLINE [1] compSF #-}

-- Composition as a signal function is built ('compSF'): 'compN', with
-- the composition on the left taken apart first, so that a network is a
-- spine nested to the right, whatever way the program nested it. Relies
-- on associativity, @(f >>> g) >>> h = f >>> (g >>> h)@ (the same samples
-- through the same nodes, as lazily). Arrow notation nests to the left
-- (@(arr p >>> cmd) >>> arr q@); on a spine nested to the right the
-- lifted functions meet and fuse ('compN''s @arr f >>> (arr g >>> n)@),
-- and the stepper's shapes (a function on either side of a stateful
-- node, chains of integrals) are found. A network changed while it runs
-- (a switch) is rebuilt by 'compN' alone, as before.
--
-- Only the first 'spineReach' nodes of the left operand's spine are taken
-- apart: its spine is already nested to the right (it was built by this),
-- so walking all of it would make every @>>>@ cost the length of its left
-- operand, and a network grown on the right one stage at a time
-- (@foldl (>>>)@, a recursive builder) quadratic to build (40,000 stages:
-- 36 s). A network written in arrow notation and built at run time nests
-- a few nodes deep at each command, well within the reach.
compB :: Node a c -> Node c b -> Node a b
compB = go spineReach
  where
    go :: Int -> Node a c -> Node c b -> Node a b
    go k f g = case f of
      NComp f1 f2 | k > 0 -> compN f1 (go (k - 1) f2 g)
      _                   -> compN f g

-- How deep 'compB' and 'peel' look into a spine.
spineReach :: Int
spineReach = 8

-- @first@ as a signal function is built: 'firstN', with the lifted
-- functions at either end of the composition it wraps moved outside, where
-- they fuse with their neighbours (arrow notation gives a command as
-- @first (arr p >>> cmd)@, and a command ends in a function as often as
-- not). Relies on @first (f >>> g) = first f >>> first g@ and @first (arr
-- p) = arr (\ ~(a, c) -> (p a, c))@: the same values, as lazily (the
-- component not given to @p@ is passed on as it came).
firstB :: Node a b -> Node (a, c) (b, c)
firstB n = case n of
  NComp f@(NPure _) g                -> compB (firstN f) (firstB g)
  NComp _ _ | Just (Peel h q) <- peel n -> compB (firstN h) (firstN (NPure q))
  _                                  -> firstN n

-- The same for @second@ ('secondSF'), by the mirror identities.
secondB :: Node a b -> Node (c, a) (c, b)
secondB n = case n of
  NComp f@(NPure _) g                -> compB (secondN f) (secondB g)
  NComp _ _ | Just (Peel h q) <- peel n -> compB (secondN h) (secondN (NPure q))
  _                                  -> secondN n

-- A composition taken apart as the network before its last node and that
-- last node, when the last is a lifted function.
data Peel a b where
  Peel :: Node a c -> FunD c b -> Peel a b

-- (Looked for within 'spineReach' nodes of the spine, as 'compB' looks.)
peel :: Node a b -> Maybe (Peel a b)
peel = go spineReach
  where
    go :: Int -> Node a b -> Maybe (Peel a b)
    go k n = case n of
      NComp f (NPure q)   -> Just (Peel f q)
      NComp f g | k > 0   -> case go (k - 1) g of
        Just (Peel h q) -> Just (Peel (compN f h) q)
        Nothing         -> Nothing
      _                   -> Nothing

-- | The instances' 'arr': eta-expanded, so that an 'arr' of a partial
-- application (@arr (foldl' (+) 0)@, @arr (uncurry f)@) is compiled, once
-- inlined, as a saturated call that GHC can inline and specialise, instead
-- of a call of the generic function through a PAP at every sample.
-- @\a -> f a@ differs from @f@ only under 'seq', and no node ever
-- evaluates the function of an 'FDG' other than by applying it. Inlined
-- only late (phase 1), for the rules below.
arrSF :: (a -> b) -> SF a b
arrSF f = SF (arrN (\a -> f a))
{-# INLINE [1] arrSF #-}

-- Compositions of lifted functions that GHC can see (written in the
-- source, or exposed by inlining) become one lifted function before the
-- optimiser runs, so that GHC compiles the composed function as a whole
-- (a chain of @arr (+ 1)@ becomes strict, unboxed arithmetic where GHC
-- finds it strict), instead of a function that 'compN' composes from
-- unknown parts when the signal function is built. These are the
-- identities 'compN' applies at run time (@arr f >>> arr g = arr (g . f)@,
-- and the same one step inside a composition), with the same laziness:
-- @g (f a)@ evaluates @f a@ only if @g@ needs it. The rules are active
-- from the first simplifier pass: were they held back to phase 2, full
-- laziness would first float the parts of a composition written inside a
-- function (one that takes an argument or a class dictionary) out to
-- bindings of their own, where no rule can see them.
{-# RULES
"AFRP arr>>>arr" forall f g.
  compSF (arrSF g) (arrSF f) = arrSF (\a -> g (f a))
"AFRP arr>>>arr>>>sf" forall f g h.
  compSF (compSF h (arrSF g)) (arrSF f) = compSF h (arrSF (\a -> g (f a)))
"AFRP sf>>>arr>>>arr" forall f g h.
  compSF (arrSF g) (compSF (arrSF f) h) = compSF (arrSF (\a -> g (f a))) h
  #-}

-- | The instances' 'first': @firstSF sf@ is @first sf@ ('firstB' at run
-- time, which moves the lifted functions at either end of @sf@ outside).
-- A function of its own, inlined only late (phase 1), so that the rewrite
-- rules below see it.
firstSF :: SF a b -> SF (a, c) (b, c)
firstSF (SF f) = SF (firstB f)
{-# INLINE [1] firstSF #-}

-- | @arrFirstSF p sf@ is @arr p >>> first sf@, as one node, made by the
-- rewrite rules below where GHC sees the composition: the shape arrow
-- notation gives every command (@y <- sf -< e@ is @arr (\env -> (e, env))
-- >>> first sf@). Each step applies @p@ to the input, lazily, steps @sf@ on
-- the first component of the result and outputs its output paired with
-- the second component; the same values as the composition, as lazily
-- (nothing is evaluated that the composition does not evaluate), without
-- its nodes. Compiled with @p@'s body in place, the pair @p@ builds is
-- taken apart where it is built (@fst (e, env)@ is @e@) instead of through
-- a thunk of @p a@ and two selector thunks of it, as the composition does
-- with an unknown @p@. Relies on @arr p >>> first sf = arr (\a -> (fst (p
-- a), snd (p a))) >>> first sf@ (the same pair, taken apart lazily). While
-- @sf@ is a lifted function (and after a switch makes it one) the node is
-- the composition, which fuses with its neighbours. A lifted function in
-- front of the node is taken into @p@ by the rules too (@arr q >>>
-- arrFirstSF p sf = arrFirstSF (p . q) sf@), as arrow notation puts one
-- between two commands.
arrFirstSF :: (a -> (b, c)) -> SF b d -> SF a (d, c)
arrFirstSF p (SF s) = SF (arrFirstQN (\a -> p a) s FDI)
{-# INLINE [1] arrFirstSF #-}

{-# RULES
"AFRP arr>>>first" forall p s.
  compSF (firstSF s) (arrSF p) = arrFirstSF p s
"AFRP arr>>>first>>>sf" forall p s h.
  compSF (compSF h (firstSF s)) (arrSF p) = compSF h (arrFirstSF p s)
"AFRP arr>>>arrFirst" forall p q s.
  compSF (arrFirstSF p s) (arrSF q) = arrFirstSF (\a -> p (q a)) s
"AFRP arr>>>arrFirst>>>sf" forall p q s h.
  compSF (compSF h (arrFirstSF p s)) (arrSF q) = compSF h (arrFirstSF (\a -> p (q a)) s)
  #-}

-- | @arrFirstQSF p sf q@ is @arr p >>> first sf >>> arr q@, as one node,
-- made by the rewrite rules below where GHC sees the composition: a
-- command of arrow notation with the function that follows it (the rest
-- of the @proc@ block after a command's last one, the environment rebuilt
-- for the next command). Each step is that of 'arrFirstSF', with the output
-- @q (y, c)@ applied lazily, as the composition node applies the function
-- behind a stateful node: the same value, as lazily, without the
-- composition node (rebuilt at every step by the composition), the pair
-- and the selection of @c@ from @p@'s result (compiled with @q@'s body in
-- place, the pair is taken apart where it is built). Relies on
-- associativity and on @(arr p >>> first sf) >>> arr q@ applying @q@
-- lazily to the pair of @sf@'s output and the part passed on. While @sf@
-- is a lifted function (and after a switch makes it one) the node is the
-- composition, which fuses with its neighbours.
arrFirstQSF :: (a -> (b, c)) -> SF b d -> ((d, c) -> e) -> SF a e
arrFirstQSF p (SF s) q = SF (arrFirstQN (\a -> p a) s (FDG (\x -> q x)))
{-# INLINE [1] arrFirstQSF #-}

-- The node of both: @arr p >>> first s >>> q@, @q@ the identity ('FDI')
-- for 'arrFirstSF', whose pair is then output as it is made (inlined at
-- each use, @fdFun FDI@ is no call, and @compN n (NPure FDI)@ is @n@).
arrFirstQN :: (a -> (b, c)) -> Node b d -> FunD (d, c) e -> Node a e
arrFirstQN p s0 qd = go s0
  where
    q = fdFun qd
    go s = case s of
      NPure _ -> compN (NPure (FDG p)) (compN (firstN s) (NPure qd))
      _       -> NStep (\dt a -> let pa = p a in case stepN s dt (fst pa) of
        (# s', y #) -> case go s' of !n -> (# n, q (y, snd pa) #))
{-# INLINE arrFirstQN #-}

-- The function after a command is taken into its node (@arrFirstSF p sf
-- >>> arr q = arrFirstQSF p sf q@, by associativity on a spine nested to
-- the right), and a function after or before such a node into it:
-- @arrFirstQSF p sf q >>> arr r = arrFirstQSF p sf (r . q)@, @arr r >>>
-- arrFirstQSF p sf q = arrFirstQSF (p . r) sf q@, each applied lazily, as
-- the composition applies it. A lifted function at either end of the
-- command itself is taken out of @first@ into the node's functions, as
-- 'firstB' does at run time (@first (arr f >>> sf) = first (arr f) >>>
-- first sf@, @first (arr f) = arr (\ ~(b, c) -> (f b, c))@, the
-- component not given to @f@ passed on as it came), so that it is applied
-- where @p@ or @q@ builds or takes apart the pair rather than stepped as a
-- composition node inside the command: arrow notation gives every command
-- @sf -< e@ as @first (arr (\(e, ()) -> e) >>> sf)@. The laziness of
-- the new functions is load-bearing: @let (b, c) = p a@ at the front (a
-- @case@ would take @p@'s result apart before @f@ asks for @b@; a test in
-- OptimiserSpec fails on it) and @\ ~(d, c)@ at the back.
{-# RULES
"AFRP arrFirst>>>arr" forall p s q.
  compSF (arrSF q) (arrFirstSF p s) = arrFirstQSF p s q
"AFRP arrFirst>>>arr>>>sf" forall p s q h.
  compSF (compSF h (arrSF q)) (arrFirstSF p s) = compSF h (arrFirstQSF p s q)
"AFRP arrFirstQ>>>arr" forall p s q r.
  compSF (arrSF r) (arrFirstQSF p s q) = arrFirstQSF p s (\x -> r (q x))
"AFRP arrFirstQ>>>arr>>>sf" forall p s q r h.
  compSF (compSF h (arrSF r)) (arrFirstQSF p s q) = compSF h (arrFirstQSF p s (\x -> r (q x)))
"AFRP arr>>>arrFirstQ" forall p s q r.
  compSF (arrFirstQSF p s q) (arrSF r) = arrFirstQSF (\a -> p (r a)) s q
"AFRP arr>>>arrFirstQ>>>sf" forall p s q r h.
  compSF (compSF h (arrFirstQSF p s q)) (arrSF r) = compSF h (arrFirstQSF (\a -> p (r a)) s q)
"AFRP arrFirst/arr>>>sf" forall p f s.
  arrFirstSF p (compSF s (arrSF f)) = arrFirstSF (\a -> let (b, c) = p a in (f b, c)) s
"AFRP arrFirstQ/arr>>>sf" forall p f s q.
  arrFirstQSF p (compSF s (arrSF f)) q = arrFirstQSF (\a -> let (b, c) = p a in (f b, c)) s q
"AFRP arrFirst/sf>>>arr" forall p f s.
  arrFirstSF p (compSF (arrSF f) s) = arrFirstQSF p s (\ ~(d, c) -> (f d, c))
"AFRP arrFirstQ/sf>>>arr" forall p f s q.
  arrFirstQSF p (compSF (arrSF f) s) q = arrFirstQSF p s (\ ~(d, c) -> q (f d, c))
  #-}

-- Compositions GHC can see are nested to the right before the rules above
-- look at them, as 'compB' nests them at run time: @(f >>> g) >>> h = f
-- >>> (g >>> h)@ (associativity: the same samples through the same nodes,
-- as lazily). Every rule of the library matches a spine nested to the
-- right (@arr f >>> (sf >>> rest)@); arrow notation nests its commands to
-- the left (@(cmd1 >>> arr q) >>> (arr p >>> cmd2)@), so without this the
-- functions between two commands (@arr q >>> arr p@, the environment
-- rebuilt and taken apart again) never meet at compile time. The rule
-- only nests to the right, and no rule nests to the left, so rewriting
-- ends.
{-# RULES
"AFRP assoc" forall f g h.
  compSF h (compSF g f) = compSF (compSF h g) f
  #-}

-- | The instances' 'second': @secondSF sf@ is @second sf@ ('secondN' at
-- run time). A function of its own, inlined only late (phase 1), so that
-- rewrite rules ("AFRP.Delay"'s, for @loop (second (iPre c) >>> arr g)@)
-- see it.
secondSF :: SF a b -> SF (c, a) (c, b)
secondSF (SF f) = SF (secondB f)
{-# INLINE [1] secondSF #-}

-- | The instances' 'loop' ('loopN' at run time), inlined only late (phase
-- 1) for the same reason as 'secondSF'.
loopSF :: SF (a, c) (b, c) -> SF a b
loopSF (SF f) = SF (loopN f)
{-# INLINE [1] loopSF #-}

------------------------------------------------------------------------------
-- Instances

-- | 'id' is 'AFRP.Basic.identity'; '.' is composition (right to left).
instance Category SF where
  id = SF idN
  (.) = compSF

-- | 'arr' lifts a function pointwise; 'first', 'second', '***' and '&&&'
-- work sample by sample, all parts seeing the same time step.
instance Arrow SF where
  -- 'arrSF': eta-expanded, and fused with its neighbours at compile time.
  arr = arrSF
  {-# INLINE arr #-}
  -- 'firstSF': seen by rewrite rules.
  first = firstSF
  {-# INLINE first #-}
  -- 'secondSF': seen by rewrite rules.
  second = secondSF
  {-# INLINE second #-}
  SF f *** SF g = SF (parN f g)
  SF f &&& SF g = SF (fanN f g)

-- | 'loop' feeds the second output component back, at the same sample, as
-- the second input component. The feedback must be well founded: the
-- value fed back may only be /used/ after a delay ('AFRP.Delay.iPre',
-- 'AFRP.Integration.integral', the @d@-combinators) or inside a lazy
-- structure; demanding it at the same instant diverges with @<<loop>>@.
-- No signal function of the library demands its input before its own
-- output is demanded (a stateful one folds its input into its state at
-- the next sample), so a stateful signal function may watch the value fed
-- back as long as nothing needs its output at that instant, as in Yampa
-- (see "AFRP.Loop").
instance ArrowLoop SF where
  -- 'loopSF': seen by rewrite rules.
  loop = loopSF
  {-# INLINE loop #-}

-- | Choice. @left sf@ runs @sf@ on the samples that are 'Left' and passes
-- 'Right' samples through unchanged. As in Yampa, @sf@ lives only on its
-- own samples: it starts (local time 0) at the first 'Left' sample, is
-- frozen (not stepped) on 'Right' samples, and when fed again is stepped by
-- the current time step only, so the time spent on the other side is lost
-- to it. For example @left localTime@ on @L, L, R, R, L@ with steps of 1
-- outputs @Left 0, Left 1, Right _, Right _, Left 2@.
instance ArrowChoice SF where
  left (SF f) = SF (leftN f)

leftN :: Node a b -> Node (Either a c) (Either b c)
-- left (arr f) = arr (left f)
leftN (NPure FDI) = NPure FDI
leftN (NPure fd)  = let f = fdFun fd in NPure (FDG (either (Left . f) Right))
-- Stepped lazily ('lazyN'): which side a sample is on is looked at only
-- when the output is demanded, or at the next sample.
leftN n           = lazyN (leftE n)

leftE :: Node a b -> Node (Either a c) (Either b c)
leftE n = self
  where
    self = NStep (\dt e -> case e of
      Right c -> (# self, Right c #)
      Left a  -> case stepN n dt a of
        (# n', b #) -> case n' of
          NPure _ -> case leftN n' of !m -> (# m, Left b #)
          _       -> case leftE n' of !m -> (# m, Left b #))

-- | @fmap f sf = sf >>> arr f@.
instance Functor (SF a) where
  fmap f (SF n) = SF (compN n (arrN f))

-- | @pure = constant@; @sf1 \<*\> sf2@ applies the output of @sf1@ to that
-- of @sf2@ at every sample.
instance Applicative (SF a) where
  pure b = SF (constN b)
  SF f <*> SF x = SF (compN (fanN f x) (arrN (\(g, y) -> g y)))
