{-# LANGUAGE GADTs        #-}
{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Internal.Node
-- Description : The nodes that signal functions are made of: their
--               representation, their stepping, their smart constructors.
--
-- Internal, not part of the API (exposed for the library's own tests and
-- benchmarks; users import "AFRP", where 'AFRP.Internal.SF.SF' is
-- abstract). "AFRP.Internal.SF" re-exports this module and holds the
-- signal-function type and its instances; "AFRP.Internal.Loop" the loops
-- over nodes.
--
-- = Design
--
-- A signal function is a /network of nodes/ that is stepped one sample at a
-- time. A node is either one of a handful of structural forms that the
-- library understands ('NPure', 'NComp', 'NPar', 'NFan'), one of two
-- specialised primitives ('NPre', 'NIntD') or an opaque stateful step
-- ('NStep'). Because the structure is visible,
-- the smart constructors ('compN', 'fanN', ...) simplify the network both
-- when it is built and every time a part of it changes while it runs: pure
-- functions fuse across '>>>', identities vanish, constants absorb what
-- feeds them, and a stateful node that has become stateless (an 'after'
-- that has fired, a switch whose event can no longer occur) collapses into
-- a pure one, which in turn fuses with its neighbours.
--
-- There is one node type for the whole life of a signal function. The
-- difference between the very first sample (which has no time step) and
-- later ones is carried by the nodes themselves: /a node that has not yet
-- been stepped ignores the time step it is given/. A freshly built 'AFRP.Internal.SF.SF' is
-- always such an initial node, so starting a signal function (at time 0, or
-- at a switch) is just stepping it. The one exception is the node built by
-- 'AFRP.Internal.Deferred.freezeN', which replays a step that was interrupted by a switch and so
-- deliberately uses the time step it captured.
--
-- A step returns an unboxed pair of the next node and the output. The next
-- node is always evaluated (every structural field is strict, 'stepN'
-- builds every structural successor with @case@ rather than as a lazy
-- application of a smart constructor), and the /output/ stays lazy, which
-- is what makes 'loop' and recursive arrow notation work.
--
-- = Laziness in the input
--
-- /No step evaluates its input sample./ A primitive whose next state
-- depends on its input (an edge, a hold, an accumulator, a switch)
-- keeps that dependency unevaluated in its successor and evaluates it at
-- the start of its /next/ step, when every value of the previous sample
-- is available: 'AFRP.Internal.Deferred.mealyN' and 'AFRP.Internal.Deferred.lazyN' are the two general forms, and the
-- edges, 'AFRP.Hybrid.hold' and 'AFRP.Integration.derivative' do the same
-- by hand. So a stateful node inside a 'loop' whose output nobody needs
-- never demands the value fed back, as in Yampa; and since each step
-- forces what the previous one left, the library's own state keeps no
-- chain of thunks from step to step, however long a network runs (the
-- values a network computes lazily itself may: see "AFRP.Loop").
--
-- = Performance
--
-- Stepping is an interpretation of the node tree, so its cost is the
-- number of nodes stepped and rebuilt, and what they allocate. To keep it
-- low:
--
-- * there are at most seven constructors, so that GHC's pointer tags
--   identify the constructor without reading its info table ('NPar' also
--   stands for @first@ and @second@, with an identity on one side);
-- * a pure node next to a stateful one (@arr f >>> sf@, @sf >>> arr f@,
--   @sf &&& identity@, ...) is applied where it stands rather than stepped
--   as a node of its own;
-- * rebuilding a node whose children are both still stateful skips the
--   smart constructor, none of whose identities can apply;
-- * 'AFRP.Delay.iPre' is a node of its own ('NPre'), so that
--   @loop (second (iPre c) >>> f)@ (the shape of 'AFRP.Loop.loopPre') is
--   recognised and stepped without a knot: the delay never looks at its
--   current input, so the value fed back is only stored, never needed
--   during the step (see @loopPreN@ in "AFRP.Internal.Loop");
-- * any other @loop (second sf >>> f)@ (for example
--   'AFRP.Loop.loopIntegral') ties a knot that allocates one box, not a
--   pair to be taken apart;
-- * 'AFRP.Integration.integral' at 'Double' (by a rewrite rule) is a
--   specialised node with an unboxed running sum ('NIntD');
-- * a run of such integrals in series, with delays and functions before
--   integrals among them, becomes one chain node the first time it is
--   stepped as integral nodes ("AFRP.Internal.Chain", 'chainFromInt'),
--   with the sums passed unboxed from one integral to the next, and three
--   or more integrals in series (with or without functions between them,
--   and, from the chain's second step, with the delays they feed among
--   them) kept as one unboxed array, stepped by one loop;
-- * a network is built as a spine of compositions nested to the right,
--   with the lifted functions at either end of a @first@'s or
--   @second@'s network moved outside it ('AFRP.Internal.SF.compSF',
--   @firstB@ in "AFRP.Internal.SF"), so that the shapes above are found
--   in networks written in arrow notation, which nests to the left;
-- * @integral *** integral@ at 'Double' is stepped in place, both sums
--   at once, and after its first step it is one node
--   ('AFRP.Internal.Node.Fuse.int2On') that
--   holds its input pair unevaluated instead of two integral nodes
--   holding a selector of it each; with a function in front of it
--   (@arr p >>> (integral *** integral)@, the shape of the notes'
--   odometry) the node holds the input as it came and applies @p@ at the
--   next step, where the sums need its value, instead of storing the
--   thunk of @p a@, and a function behind the pair is applied by the
--   node, lazily ('int2OnQ');
-- * lifted functions composed where GHC can see them (@arr f >>> arr g@
--   written in the source, or exposed by inlining) are fused by rewrite
--   rules before GHC optimises the code ('AFRP.Internal.SF.compSF',
--   'AFRP.Internal.SF.arrSF'), so that GHC compiles the composed function
--   as a whole, with its own strictness analysis, instead of 'compN'
--   composing unknown functions lazily when the network is built (see
--   bench/README.md for what that saves); likewise @arr p >>> edge@
--   ("AFRP.EventSource"), the functions next to an 'AFRP.Integration.integral'
--   at 'Double' ("AFRP.Integration"), @loop (second (iPre c) >>> arr g)@
--   ("AFRP.Delay") and a command of arrow notation with the functions
--   around it (@arr p >>> first sf >>> arr q@, 'AFRP.Internal.SF.arrFirstQSF')
--   become one node each, compiled with the functions in
--   place; integrals in series written in the source stay nodes the
--   chains see, with the functions between them composed at compile time
--   (@integralsD@ in "AFRP.Integration").
--
-- Every such case states, next to it, the identity it relies on.
--
-- = Modules
--
-- This module is the one the rest of the library imports: it holds the
-- stepper and re-exports the names of the three it is built on, each of
-- which imports only those before it: "AFRP.Internal.Node.FunD" (the
-- stateless functions a pure node holds, and their algebra),
-- "AFRP.Internal.Node.Build" (the node type and the smart constructors)
-- and "AFRP.Internal.Node.Fuse" (the nodes that stand for several, which
-- the stepper makes of a pair of integrals or of a run of integrals and
-- delays; it finds the runs itself, see 'chainFromInt').
module AFRP.Internal.Node
  ( -- * Time
    Time
  , DTime
    -- * Nodes
  , Node (..)
  , FunD (..)
  , Boxed (..)
  , fdFun
    -- * Stepping
  , stepN
  , stepInline
  , boxStep
    -- * Smart constructors
  , constN
  , arrN
  , idN
  , compN
  , firstN
  , secondN
  , parN
  , fanN
  ) where

import           AFRP.Internal.Chain
import           AFRP.Internal.Node.Build
import           AFRP.Internal.Node.FunD
import           AFRP.Internal.Node.Fuse

------------------------------------------------------------------------------
-- Stepping

-- | A step result in a box, for the places (knots, collections) that need
-- a lifted value.
data Boxed a b = Boxed !(Node a b) b

-- | Step a node: time step, input sample, successor and output.
--
-- Every successor is returned evaluated (the structural ones are built
-- with @case@, never as a lazy application of a smart constructor), so a
-- parent never allocates a thunk for a child it is about to inspect anyway.
stepN :: Node a b -> DTime -> a -> (# Node a b, b #)
stepN n dt a = case n of
  NPure FDI     -> (# n, a #)
  NPure (FDC b) -> (# n, b #)
  NPure (FDG f) -> (# n, f a #)
  NComp f g     -> case f of
    -- arr p >>> (integral *** integral) at Double: one node from now on
    -- (see 'int2On').
    NPure (FDG p) | Just n' <- fuseInt2 p g -> stepN n' dt a
    -- A pure function in front of a stateful node (the usual shape): apply
    -- it (lazily, as its own node would) without a step of its own.
    NPure (FDG p) -> case g of
      -- arr p >>> (h >>> arr q), the usual shape of a stateful node
      -- between two functions (arr p >>> derivative >>> arr q; at Double,
      -- an integral there is one node, by "AFRP.Integration"'s rules,
      -- where GHC sees the composition): h is stepped
      -- on p a and q applied to its output, both lazily, as the two
      -- composition nodes would, without a step of the inner one. The
      -- successor is the one the two steps would build (compNI inside,
      -- then outside).
      NComp h gq@(NPure (FDG q)) -> case stepN h dt (p a) of
        (# h', c #) -> case compNI h' gq of
          !g' -> case compNI f g' of !n' -> (# n', q c #)
      _ -> case stepN g dt (p a) of
        (# g', b #) -> case compNI f g' of !n' -> (# n', b #)
    -- A run of integrals and delays at 'Double' (with functions before
    -- the integrals): one chain node from now on (see 'chainFromInt').
    -- (A failed guard falls through to the general case.)
    NIntD acc prev | Just n' <- chainFromInt acc prev g -> stepN n' dt a
    NPre v         | Just n' <- chainFromPre v g        -> stepN n' dt a
    _ -> case stepN f dt a of
      (# f', c #) -> case g of
        -- ... and one behind it.
        NPure (FDG q) -> case compNI f' g of !n' -> (# n', q c #)
        -- f >>> (arr p >>> h), the usual shape of a chain of stateful
        -- nodes with functions between them: h is stepped on p c (lazily,
        -- as the inner composition would) without a step of its own; the
        -- successor is the one the two steps would build.
        -- (f >>> (arr p >>> (integral *** integral)) at Double: the pair
        -- is made one node with p, see 'int2On')
        NComp (NPure (FDG p)) h | Just h' <- fuseInt2 p h -> case stepN h' dt c of
          (# h'', b #) -> case rebuildComp f' h'' of !n' -> (# n', b #)
        NComp gp@(NPure (FDG p)) h -> case stepN h dt (p c) of
          (# h', b #) -> case compNI gp h' of
            !g' -> case rebuildComp f' g' of !n' -> (# n', b #)
        _             -> case stepN g dt c of
          (# g', b #) -> case rebuildComp f' g' of !n' -> (# n', b #)
  NPar f g      -> case g of
    -- first f
    NPure FDI -> let (x, c) = a in case f of
      -- first (arr p >>> h), the shape arrow notation gives a command
      -- (@y <- h -< e@ is @first (arr (\env -> e) >>> h)@): h is stepped on
      -- p x (lazily, as the inner composition would) without a step of
      -- its own; the successor is the one the two steps would build.
      NComp pf@(NPure (FDG p)) h -> case stepN h dt (p x) of
        (# h', y #) -> case compNI pf h' of
          !f' -> case firstN f' of !n' -> (# n', (y, c) #)
      _ -> case stepN f dt x of
        (# f', y #) -> case firstN f' of !n' -> (# n', (y, c) #)
    _         -> case f of
      -- second g
      NPure FDI -> let (c, x) = a in case stepN g dt x of
        (# g', y #) -> case secondN g' of !n' -> (# n', (c, y) #)
      -- integral *** integral at Double (a vector integrated by
      -- components, as the notes' odometry does): both steps in place,
      -- the sums y_n = y_(n-1) + dt_n * a_(n-1) of 'stepIntD'; the
      -- successor is one node that holds the input pair unevaluated and
      -- takes it apart at the next step, where both sums need its
      -- components ('int2OnPair', 'int2On' with the identity), where the
      -- two nodes would each hold a selector of it, evaluated at that step.
      NIntD acc1 prev1 | NIntD acc2 prev2 <- g ->
        let !acc1' = acc1 + dt * prev1
            !acc2' = acc2 + dt * prev2
        in (# int2OnPair acc1' acc2' a, (acc1', acc2') #)
      _         -> let (x, z) = a in case stepN f dt x of
        (# f', y #) -> case stepN g dt z of
          (# g', w #) -> case rebuildPar f' g' of !n' -> (# n', (y, w) #)
  NFan f g      -> case g of
    -- A pure side (sf &&& identity, sf &&& arr f, sf &&& never) is applied
    -- as its own node would be, without a step of its own.
    NPure gd -> case stepN f dt a of
      (# f', y #) -> case fanN f' g of
        !n' -> case gd of
          FDI   -> (# n', (y, a) #)
          FDC w -> (# n', (y, w) #)
          FDG q -> (# n', (y, q a) #)
    _        -> case f of
      NPure fd -> case stepN g dt a of
        (# g', w #) -> case fanN f g' of
          !n' -> case fd of
            FDI   -> (# n', (a, w) #)
            FDC y -> (# n', (y, w) #)
            FDG p -> (# n', (p a, w) #)
      _        -> case stepN f dt a of
        (# f', y #) -> case stepN g dt a of
          (# g', w #) -> case rebuildFan f' g' of !n' -> (# n', (y, w) #)
  NStep s       -> s dt a
  NPre prev     -> (# NPre a, prev #)
  -- integral: see 'stepIntD'
  NIntD acc prev -> stepIntD acc prev dt a

-- | 'stepN', with the node of an 'AFRP.Integration.integral' at 'Double'
-- (the commonest leaf of the networks that combinators step themselves:
-- the members of a collection, the running part of a switch) stepped in
-- place instead of through a call: the same sum as 'stepN''s case for
-- 'NIntD', @y_n = y_(n-1) + dt_n * a_(n-1)@, and the same successor.
stepInline :: Node a b -> DTime -> a -> (# Node a b, b #)
stepInline n dt a = case n of
  NIntD acc prev -> stepIntD acc prev dt a
  _              -> stepN n dt a
{-# INLINE stepInline #-}

-- The step of an 'NIntD' (running sum @acc@, previous input @prev@) on
-- the input @a@: @y_n = y_(n-1) + dt_n * a_(n-1)@, exactly as the generic
-- 'AFRP.Integration.integral' at 'Double' computes it; the current input
-- is stored unevaluated.
stepIntD :: Double -> Double -> DTime -> Double -> (# Node Double Double, Double #)
stepIntD acc prev dt a = let !acc' = acc + dt * prev in (# NIntD acc' a, acc' #)
{-# INLINE stepIntD #-}

-- Rebuilding a node whose two children were both stateful before the step:
-- as the smart constructor would, but with the common case (both still
-- stateful, where no identity applies) decided by two tests and no call.
-- @rebuildWith smart con@ is @smart@ if either child is now pure, @con@
-- (the bare constructor) otherwise.
rebuildWith :: (Node a b -> Node c d -> r) -> (Node a b -> Node c d -> r)
            -> Node a b -> Node c d -> r
rebuildWith smart con f g = case g of
  NPure _ -> smart f g
  _       -> case f of
    NPure _ -> smart f g
    _       -> con f g
{-# INLINE rebuildWith #-}

rebuildComp :: Node a c -> Node c b -> Node a b
rebuildComp f g = rebuildWith compN NComp f g
{-# INLINE rebuildComp #-}

rebuildPar :: Node a b -> Node c d -> Node (a, c) (b, d)
rebuildPar f g = rebuildWith parN NPar f g
{-# INLINE rebuildPar #-}

rebuildFan :: Node a b -> Node a c -> Node a (b, c)
rebuildFan f g = rebuildWith fanN NFan f g
{-# INLINE rebuildFan #-}

-- | 'stepN' with a boxed result.
boxStep :: Node a b -> DTime -> a -> Boxed a b
boxStep n dt a = case stepN n dt a of (# n', b #) -> Boxed n' b
{-# INLINE boxStep #-}

------------------------------------------------------------------------------
-- Runs of integrals and delays, found where the stepper meets them

-- (These live with the stepper, not with the chain nodes of
-- "AFRP.Internal.Node.Fuse": 'stepN' inlines 'chainFromPre', and only
-- with 'collectI' compiled in the same module does GHC see that the
-- stages it returns are evaluated; from another module, the chain node's
-- stages were built in a thunk, with an evaluation of their own.)

-- | @chainFromInt acc prev g@ is @Just@ the composition @NIntD acc prev
-- >>> g@ with the run of 'Double'-valued stages at its head (integrals,
-- delays, @arr h@ before an integral) made one chain node
-- ("AFRP.Internal.Chain", which states the identity it relies on), if that
-- run has two stages or more, and 'Nothing' otherwise; @chainFromPre@ the
-- same for a delay followed by an integral. Tried where 'stepN' meets a
-- composition whose first node is an integral after its first step or a
-- delay, so the whole run is taken at once (a composition spine is
-- stepped from its head). The rest of the spine follows the chain
-- unchanged.
chainFromInt :: Double -> Double -> Node Double b -> Maybe (Node Double b)
chainFromInt acc prev g = case collectI g of
  ColI IEnd _ -> Nothing
  ColI c rest -> Just (compN (chainN (LInt acc prev c)) rest)

-- (a delay leads a chain only if an integral follows it: that fixes its
-- type)
chainFromPre :: a -> Node a b -> Maybe (Node a b)
chainFromPre v g = case g of
  NIntD acc prev              -> Just (chainN (LPre v (LInt acc prev IEnd)))
  NComp (NIntD acc prev) rest -> case collectI rest of
    ColI c r -> Just (compN (chainN (LPre v (LInt acc prev c))) r)
  _                           -> Nothing

-- The stages of a chain, and the rest of the spine, which the chain's
-- output feeds.
data ColI b = ColI !AfterI !(Node Double b)
data ColL b = ColL !AfterL !(Node Double b)

-- The longest run of chain stages at the head of a node fed by an
-- integral. An integral there keeps the previous input its node holds for
-- the chain's first step only (see "AFRP.Internal.Chain"); an @arr h@ in
-- front of it is kept with it.
collectI :: Node Double b -> ColI b
collectI g = case g of
  NIntD acc prev -> ColI (IIntS acc prev IEnd) idN
  NPre v         -> ColI (IPre v LEnd) idN
  NComp x rest   -> case x of
    NIntD acc prev -> case collectI rest of ColI c r -> ColI (IIntS acc prev c) r
    NPre v         -> case collectL rest of ColL c r -> ColI (IPre v c) r
    NPure (FDG h)  -> case rest of
      NIntD acc prev               -> ColI (IIntFS h acc prev IEnd) idN
      NComp (NIntD acc prev) rest' -> case collectI rest' of ColI c r -> ColI (IIntFS h acc prev c) r
      _                            -> ColI IEnd g
    _             -> ColI IEnd g
  _            -> ColI IEnd g

-- The same, for a node fed by a delay or by the chain's input: an
-- integral there keeps its own previous input.
collectL :: Node Double b -> ColL b
collectL g = case g of
  NIntD acc prev -> ColL (LInt acc prev IEnd) idN
  NPre v         -> ColL (LPre v LEnd) idN
  NComp x rest   -> case x of
    NIntD acc prev -> case collectI rest of ColI c r -> ColL (LInt acc prev c) r
    NPre v         -> case collectL rest of ColL c r -> ColL (LPre v c) r
    -- arr h >>> integral: the integral holds h of its input unevaluated
    NPure (FDG h)  -> case rest of
      NIntD acc prev               -> ColL (LIntF h acc prev IEnd) idN
      NComp (NIntD acc prev) rest' -> case collectI rest' of ColI c r -> ColL (LIntF h acc prev c) r
      _                            -> ColL LEnd g
    _              -> ColL LEnd g
  _              -> ColL LEnd g
