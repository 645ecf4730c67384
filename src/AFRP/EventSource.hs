{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE ScopedTypeVariables #-}
{-# LANGUAGE PolyKinds #-}
{-# LANGUAGE KindSignatures #-}
-- |
-- Module      : AFRP.EventSource
-- Description : Signal functions that generate or reshape event streams.
--
-- Timing conventions shared by every time-based source here:
--
-- * Times are /local/: measured from the instant the source started (0 at a
--   run's first sample, or at the sample where it was switched in).
-- * A source scheduled for time @t@ fires at the first sample whose local
--   time is @>= t@ ("at, or as soon after as possible"), or short of @t@ by
--   no more than the rounding of binary fractions
--   ('AFRP.Internal.Clock.reached': a relative 2^-48). With steps of 0.5,
--   @after 1.0@ fires at exactly 1.0; with steps of 0.3 it fires at 1.2;
--   with steps of 0.15, @after 0.9@ fires at the sixth, whose local time
--   reads 0.8999999999999999.
-- * Local time is a compensated sum of the time steps (see
--   "AFRP.Internal.Clock"), so ten steps of 0.1 reach exactly 1.0.
-- * When a sample interval spans several scheduled occurrences, the plain
--   sources deliver only one (no backlog builds up) and the @Cat@ variants
--   deliver all of them, in order, as a list.
-- * This differs from Yampa, whose plain float sums often fall just short
--   of a due time with decimal steps: @afterEach [(3.0, ()), (2.0, ())]@ at
--   dt 0.01 fires at t = 3.00 and 5.00 here, at 3.01 and 5.01 in Yampa, and
--   two events due 0.001 s apart (at 3.0 and 3.001) land in two samples
--   here, in one in Yampa. See docs/YAMPA.md, "Time accounting".
module AFRP.EventSource
  ( -- * Basic sources
    never
  , now
  , after
  , repeatedly
  , afterEach
  , afterEachCat
    -- * Delaying events
  , delayEvent
  , delayEventCat
    -- * Edges
  , edge
  , iEdge
  , edgeTag
  , edgeJust
  , edgeBy
    -- * Reshaping event streams
  , notYet
  , once
  , takeEvents
  , dropEvents
    -- * Sampling the input
  , snap
  , snapAfter
  , sample
  , sampleWindow
  ) where

import           Data.Maybe           (isJust)
import qualified Data.Sequence        as Seq
import           GHC.Exts             (RuntimeRep, TYPE)
import           Data.Sequence        (Seq, (|>))

import           AFRP.Event
import           AFRP.Internal.Clock
import           AFRP.Internal.SF

-- | The event source with no occurrences. The optimiser knows it: a switch
-- whose event comes from 'never' disappears.
never :: SF a (Event b)
never = SF neverN

neverN :: Node a (Event b)
neverN = constN NoEvent

-- | @now x@ occurs once, at local time 0, with value @x@.
--
-- > embed (now 'x') ((), [(1, Nothing)])  ==  [Event 'x', NoEvent]
now :: b -> SF a (Event b)
now x = SF (initN (\_ -> (# neverN, Event x #)))

-- | @after t x@ occurs once, with value @x@, at the first sample whose
-- local time has reached @t@ (see the module's timing conventions);
-- @after 0 x@ is @now x@. A negative @t@ is an error.
--
-- > embed (after 1.0 ()) ((), replicate 3 (0.5, Nothing))
-- >   ==  [NoEvent, NoEvent, Event (), NoEvent]
after :: Time -> b -> SF a (Event b)
after t x
  | t < 0 || isNaN t = errNeg "after" t
  | isInfinite t     = never
  | otherwise        = afterEach [(t, x)]

-- | @repeatedly p x@ occurs with value @x@ at local times @p, 2p, 3p, ...@,
-- each at the first sample whose local time has reached it. No backlog: if a time
-- step spans several periods, one occurrence is produced and the schedule
-- moves on to the first period boundary after the current time. There is
-- no occurrence at time 0. A non-positive period is an error; an
-- infinite one never occurs, as @'after' (1/0)@.
--
-- Where the boundaries cannot be told apart: once an occurrence comes at
-- a local time @t@ with @p <= 2^-53 * t@ (the period no longer than one
-- unit in the last place of @t@, so that any move of the clock's reading
-- is a period or more; @p = 1e-14@ after 1000 s, a subnormal period after
-- a second), every later sample that moves the local time on (as the
-- clock reads it) has an occurrence, and a sample that does not move it
-- has none. (Counting the boundaries there could still skip a move now
-- and then, where the tolerance of 'reached' covers it: this regime is
-- the rule's approximation, not the rule.) Above that, the boundaries
-- are counted exactly, even where several of them count as 'reached' at
-- once (a period within the tolerance of 'reached', @2^-48 * t@):
-- @repeatedly 1e-12@ after 1000 s, sampled every 1e-13 s, occurs about
-- once every ten samples. An occurrence at an infinite local time is the
-- last: no boundary lies after it.
repeatedly :: Time -> b -> SF a (Event b)
repeatedly p x
  | p <= 0 || isNaN p = errPeriod "repeatedly" p
  | isInfinite p      = never
  | otherwise         = SF (initN (\_ -> (# go clockZero 1, NoEvent #)))
  where
    go !clock !n = NStep (\dt _ ->
      let !clock' = tick clock dt
          !t      = clockTime clock'
      in if reached (fromIntegral n * p) t
           then (# after' clock' t n, Event x #)
           else (# go clock' n, NoEvent #))
    -- (what follows an occurrence: the next boundary not reached; once
    -- the period is no longer than one unit in the last place of the
    -- local time, an occurrence at every sample that moves the time on;
    -- after an infinite time, none)
    after' clock' t n
      | isInfinite t       = neverN
      | p * twoTo53 <= t   = fine clock'
      | otherwise          = go clock' (nextIndex t (n + 1))
    fine !clock = NStep (\dt _ ->
      let !clock' = tick clock dt
      in if clockTime clock' > clockTime clock then (# fine clock', Event x #) else (# fine clock', NoEvent #))
    -- The first period boundary from n0 on that t has not reached. The
    -- boundaries reached are those up to about (t + tolerance * t) / p, so the
    -- search starts there and walks, down or up, to the first one not
    -- reached ('reached' of n * p falls as n grows): a few steps, even
    -- after a huge time step, since t / p < 2^53 here.
    nextIndex :: Time -> Integer -> Integer
    nextIndex t n0
      | beyond start = down start
      | otherwise    = up start
      where
        start = max n0 (let q = t / p in floor (q + timeTolerance * q))
        beyond n = not (reached (fromIntegral n * p) t)
        down n | n > n0, beyond (n - 1) = down (n - 1)
               | otherwise               = n
        up n | beyond n  = n
             | otherwise = up (n + 1)
    -- p <= 2^-53 t, tested as p * 2^53 <= t: exact (a power of two), even
    -- where 2^-53 t would be subnormal and rounded; then p is at most one
    -- unit in the last place of t. (Below that test t / p < 2^53, so the
    -- search's q + tolerance * q cannot overflow.)
    twoTo53 = 9007199254740992 :: Double

-- | @afterEach [(q1, x1), (q2, x2), ...]@ occurs with @x1@ at local time
-- @q1@, with @x2@ at @q1 + q2@, and so on: each delay is measured from the
-- previous scheduled occurrence. When one sample interval spans several
-- scheduled occurrences only the first of them is produced (see
-- 'afterEachCat' for all of them). Negative delays are an error, reported
-- when reached (the list may be infinite). A sample reaches every
-- occurrence due by its time: an infinite run of delays summing to no
-- more than that (@repeat (0, x)@) never finishes the sample, as in Yampa.
-- Delays of 0 at the head of the list occur at local time 0:
-- @afterEach [(0, 'a'), (0, 'b'), (1, 'c')]@ gives @Event 'a'@ at time 0
-- and @Event 'c'@ at 1 ('afterEachCat': @Event "ab"@ at 0), as in Yampa.
--
-- A sample that passes many occurrences takes time in their number, but
-- no memory: the occurrences after the first are passed over, not
-- gathered (gathered, a step of 10^4 s over delays of 1 ms took 240 MB).
afterEach :: [(Time, b)] -> SF a (Event b)
afterEach = afterEachBy (\x first -> case first of { Nothing -> Just x; Just _ -> first }) id

-- | Like 'afterEach', but every occurrence scheduled up to the current
-- sample is delivered, in schedule order, in one list.
--
-- > embed (afterEachCat [(0.5, 'a'), (0.1, 'b'), (1, 'c')]) ((), replicate 3 (1, Nothing))
-- >   ==  [NoEvent, Event "ab", Event "c", NoEvent]
afterEachCat :: [(Time, b)] -> SF a (Event [b])
afterEachCat = afterEachBy (\x acc -> case acc of { Nothing -> Just [x]; Just xs -> Just (x : xs) }) reverse

-- The schedule of 'afterEach' and 'afterEachCat': the occurrences due at a
-- sample, in schedule order, gathered by @keep@ as they are passed (from
-- 'Nothing'; only its 'Just' is evaluated, never an occurrence's value),
-- what it kept made the event's value by @done@; no event when none is
-- due.
afterEachBy :: forall a b c. (b -> Maybe c -> Maybe c) -> (c -> c) -> [(Time, b)] -> SF a (Event c)
afterEachBy keep done qxs0 = SF (initN (\_ -> emit clockZero clockZero qxs0))
  where
    -- clock: local time now; due: the schedule time of the last occurrence
    -- already delivered.
    emit :: Clock -> Clock -> [(Time, b)] -> (# Node a (Event c), Event c #)
    emit clock due qxs = collect due qxs Nothing
      where
        now' = clockTime clock
        collect :: Clock -> [(Time, b)] -> Maybe c -> (# Node a (Event c), Event c #)
        collect !d ((q, x) : rest) acc
          | q < 0 || isNaN q                = errNeg "afterEach" q
          | reached (clockTime (tick d q)) now' = case keep x acc of !acc' -> collect (tick d q) rest acc'
        collect !d rest acc =
          (# next clock d rest, maybe NoEvent (Event . done) acc #)
    next :: Clock -> Clock -> [(Time, b)] -> Node a (Event c)
    next _ _ []        = neverN
    next clock due qxs = NStep (\dt _ -> emit (tick clock dt) due qxs)

-- | @delayEvent q@ delays every occurrence by @q@ seconds: an occurrence
-- at local time @t@ is produced at the first sample after it whose local
-- time has reached @t + q@ (the due time is one floating-point addition,
-- and reaching it allows for the rounding, so decimal times and steps
-- give the samples decimal arithmetic gives). When several delayed
-- occurrences fall due at one sample only the first (earliest) is
-- produced ('delayEventCat' gives them all). @delayEvent 0@ is the
-- identity; a negative delay is an error. For @q > 0@ the output at time
-- 0 is 'NoEvent', and an occurrence at time 0 is kept and comes out at
-- @q@, as in Yampa.
delayEvent :: Time -> SF (Event a) (Event a)
delayEvent q
  | q < 0 || isNaN q = errNeg "delayEvent" q
  | q == 0           = SF idN
  | isInfinite q     = SF neverN
  | otherwise        = SF (compN (sfNode (delayEventCat q)) (arrN (fmap head)))

-- | Like 'delayEvent', delivering every occurrence that falls due at a
-- sample, oldest first. The output never depends on the current input, so
-- a delayed event stream can be fed back through a loop (for instance to
-- build a recurring event).
delayEventCat :: forall a. Time -> SF (Event a) (Event [a])
delayEventCat q
  | q < 0 || isNaN q = errNeg "delayEventCat" q
  | q == 0           = SF (arrN (fmap (: [])))
  | isInfinite q     = SF neverN
  | otherwise        = SF (initN (\e -> (# go clockZero Seq.empty e, NoEvent #)))
  where
    -- The input of the previous sample (taken at the clock's previous
    -- reading) is scheduled only now: since q > 0 it cannot be due before
    -- this sample, and the current input is never evaluated, so the delay
    -- can close a feedback loop.
    go :: Clock -> Seq (Time, a) -> Event a -> Node (Event a) (Event [a])
    go !clock !pending ePrev = NStep (\dt e ->
      let !clock'     = tick clock dt
          !now'       = clockTime clock'
          pending'    = event pending (\x -> pending |> (clockTime clock + q, x)) ePrev
          (due, rest) = Seq.spanl (\(tDue, _) -> reached tDue now') pending'
          out         = if Seq.null due then NoEvent else Event (foldr ((:) . snd) [] due)
      in (# go clock' rest e, out #))

-- | Rising edges of a Boolean signal: an occurrence at every sample where
-- the input is 'True' and was 'False' at the previous sample. At time 0
-- the previous value is taken to be 'True', so an input that starts out
-- 'True' produces no event (@edge = iEdge True@).
--
-- > embed edge (True, [(1, Just False), (1, Just True), (1, Nothing)])
-- >   ==  [NoEvent, NoEvent, Event (), NoEvent]
--
-- The edge evaluates its input only when its output is demanded, or at
-- the next sample (to know the previous value), so it may watch a signal
-- fed back through a 'Control.Arrow.loop' whose output nobody needs at
-- this instant. Where @arr p >>> edge@ (or @iEdge@) is written in the
-- source, a rewrite rule makes it one node that applies @p@ in place,
-- which means the same and costs a node a sample less.
edge :: SF Bool (Event ())
edge = iEdge True
{-# INLINE edge #-}

-- | 'edge' with the value assumed for the sample before time 0:
-- @iEdge False@ produces an event at time 0 if the input is 'True' then.
iEdge :: Bool -> SF Bool (Event ())
iEdge b0 = SF (edgeFrom id b0)
{-# NOINLINE [1] iEdge #-}

-- @iEdgeOn b0 p = arr p >>> iEdge b0@, in one node: @p@ is applied
-- where the edge stands, in the one thunk that both the output and the
-- next step read, instead of in a node and a thunk of its own. The common
-- idiom @arr p >>> edge@ (the notes' @arr (> 100) >>> edge@,
-- 'AFrob.rsStuck') becomes this by the rewrite rules below wherever GHC
-- sees it written.
iEdgeOn :: Bool -> (a -> Bool) -> SF a (Event ())
iEdgeOn b0 p = SF (edgeFrom p b0)

{-# RULES
"AFRP arr>>>iEdge" forall p b0.
  compSF (iEdge b0) (arrSF p) = iEdgeOn b0 p
"AFRP arr>>>iEdge>>>sf" forall p b0 h.
  compSF (compSF h (iEdge b0)) (arrSF p) = compSF h (iEdgeOn b0 p)
  #-}

-- An edge of @p@'s value. The state is what the previous step left,
-- unevaluated until this step (when the previous sample is complete):
-- after an output 'NoEvent' that needed no look at the input (the
-- previous value was 'True'), @p@ of the previous input; otherwise the
-- previous output itself, an occurrence exactly when the previous value
-- was 'True'. After 'True' the output is the evaluated 'NoEvent' whatever
-- the input (which a decoupled switch can see without forcing anything);
-- after 'False' it is a thunk on @p@ of the current input, which is also
-- the next state: one thunk and one node a step.
edgeFrom :: (a -> Bool) -> Bool -> Node a (Event ())
edgeFrom p = afterValue
  where
    afterValue prev = NStep (\_ a -> if prev then afterTrue a else afterFalse a)
    afterEvent prev = NStep (\_ a -> case prev of
      Event () -> afterTrue a
      NoEvent  -> afterFalse a)
    afterTrue a  = (# afterValue (p a), NoEvent #)
    afterFalse a = let e = if p a then Event () else NoEvent in (# afterEvent e, e #)
{-# INLINE edgeFrom #-}

-- | 'edge' with a given value: @edgeTag x = edge >>> arr (`tag` x)@.
edgeTag :: a -> SF Bool (Event a)
edgeTag x = SF (compN (sfNode edge) (arrN (`tag` x)))

-- | An occurrence, carrying the value, whenever the input changes from
-- 'Nothing' to 'Just'. At time 0 the previous value is taken to be a
-- 'Just', so a 'Just' there produces no event.
--
-- As in Yampa, an input that follows a 'Just' is not looked at until the
-- next sample: the output is then 'NoEvent' whatever the input, and the
-- input is evaluated (to tell 'Just' from 'Nothing') at the next sample.
-- So an input that is an error at time 0 gives 'NoEvent' there and
-- raises at the next sample.
edgeJust :: SF (Maybe a) (Event a)
edgeJust = SF (mealyN step True)
  where
    step wasJust m
      | wasJust   = (isJust m, NoEvent)
      | otherwise = case m of
          Just x  -> (True, Event x)
          Nothing -> (False, NoEvent)

-- | The general edge detector: @edgeBy f a0@ applies @f@ to the previous
-- and the current input sample and produces an occurrence whenever it
-- returns 'Just'. At time 0 the previous sample is taken to be @a0@. Each
-- input sample is evaluated (to weak head normal form) at the next sample,
-- or earlier if the output is demanded.
edgeBy :: (a -> a -> Maybe b) -> a -> SF a (Event b)
edgeBy f a0 = SF (mealyN (\prev a -> (a, maybeToEvent (f prev a))) a0)

-- | Suppress an occurrence at time 0; pass all later ones through.
notYet :: SF (Event a) (Event a)
notYet = SF (initN (\_ -> (# idN, NoEvent #)))

-- | Only the first occurrence passes: @once = takeEvents 1@. An
-- occurrence at time 0 is the first (it passes), as in Yampa.
once :: SF (Event a) (Event a)
once = takeEvents 1

-- | Let the first @n@ occurrences through, then none (the source then
-- becomes 'never' and can disappear from the network); an occurrence at
-- time 0 counts as the first. For @n <= 0@ it is 'never' from the start,
-- as in Yampa.
takeEvents :: Int -> SF (Event a) (Event a)
takeEvents n0 = SF (lazyN (go n0))
  where
    go n | n <= 0    = neverN
         | otherwise = NStep (\_ e -> case e of
             NoEvent -> (# go n, NoEvent #)
             Event _ -> (# go (n - 1), e #))

-- | Suppress the first @n@ occurrences, then let all through; an
-- occurrence at time 0 is the first suppressed. For @n <= 0@ it lets
-- every occurrence through, as in Yampa.
--
-- Until the @n@-th occurrence has passed, the output is 'NoEvent' whatever
-- the input: whether a sample is an occurrence is looked at in the next
-- step, as Yampa's (a decoupled switch) looks at it. So an input sample
-- there that is an error (bottom) fails the next sample, not its own
-- output, as in Yampa 0.15.
dropEvents :: Int -> SF (Event a) (Event a)
dropEvents n0 = SF (go n0)
  where
    go n | n <= 0    = idN
         | otherwise = NStep (\_ e -> (# counted n e, NoEvent #))
    -- (the sample @e@ counted, at the start of the next step)
    counted n e = NStep (\dt e' -> case e of
      NoEvent -> stepN (go n) dt e'
      Event _ -> stepN (go (n - 1)) dt e')

-- | One occurrence at time 0 carrying the input sample there.
snap :: SF a (Event a)
snap = SF (initN (\a -> (# neverN, Event a #)))

-- | One occurrence, carrying the input sample, at the first sample whose
-- local time has reached @t@ (at time 0 if @t == 0@). A negative @t@ is an
-- error, as for 'after'.
snapAfter :: Time -> SF a (Event a)
snapAfter t
  | t < 0 || isNaN t = errNeg "snapAfter" t
  | otherwise        = SF (compN (fanN (sfNode (after t ())) idN) (arrN (\(e, a) -> e `tag` a)))

-- | @sample p@ occurs at local times @p, 2p, ...@ (as 'repeatedly')
-- carrying the input sample at that instant. No occurrence at time 0. A
-- period that is not positive (or NaN) is an error.
sample :: Time -> SF a (Event a)
sample p
  | p <= 0 || isNaN p = errPeriod "sample" p
  | otherwise = SF (compN (fanN (sfNode (repeatedly p ())) idN) (arrN (\(e, a) -> e `tag` a)))

-- | @sampleWindow w p@ takes a sample of the input every @p@ seconds (as
-- 'sample', but one sample per period even when a time step spans several
-- periods) and, at each sampling instant, produces the last @w@ samples
-- taken, oldest first. No occurrence at time 0. A window size below 1 or a
-- non-positive period is an error (Yampa does not check: there a window of
-- 0 gives empty lists and a period of 0 hangs).
--
-- The sampling instants are those of @afterEachCat (repeat (p, ()))@: each
-- is @p@ after the previous, in the compensated sum of "AFRP.Internal.Clock".
-- Memory and time stay bounded whatever one step spans: the samples of one
-- step are all the same input, so a step that spans more periods than the
-- window holds fills the window with that input and no more. When a step
-- spans more than 4096 periods, the rest of them are counted at once (a
-- multiple of @p@ added to the clock in one sum), so that the following
-- instants may differ from the period-by-period sum by its rounding; a
-- window of any size (@maxBound@ included) costs no more. Where the periods cannot be counted (a step that lands more
-- than @2^53@ periods beyond, an infinite time, or a period too small to
-- move a clock showing that time), the current time is taken as the last
-- instant, and the window is filled with the input. A sample whose time
-- step is 0 passes no instant (elsewhere this is what the count gives; in
-- those cases, where every instant counts as reached, it kept filling
-- the window at samples where no time passed).
sampleWindow :: Int -> Time -> SF a (Event [a])
sampleWindow w p
  | w < 1     = error ("AFRP.EventSource.sampleWindow: window size must be at least 1, got "
                       ++ show w)
  | p <= 0 || isNaN p = errPeriod "sampleWindow" p
  | otherwise = SF (initN (\_ -> (# go clockZero clockZero Seq.empty, NoEvent #)))
  where
    -- clock: local time now; due: the last sampling instant so far.
    go !clock !due !win = NStep (\dt a ->
      let !clock' = tick clock dt
      in if dt == 0 then (# go clock due win, NoEvent #) else case crossings clock' due of
        (# due', k #)
          | k == 0    -> (# go clock' due' win, NoEvent #)
          | otherwise ->
              let n     = min k w
                  -- (the old samples that stay, then the new: no size
                  -- beyond the window's, even at maxBound)
                  old   = Seq.length win - min (Seq.length win) (w - n)
                  !win' = Seq.drop old win Seq.>< Seq.replicate n a
              in (# go clock' due' win', Event (foldr (:) [] win') #))
    -- The instants after @due@ up to the clock's time: the last of them,
    -- and how many there are (one by one up to 'jumpAt', then the rest at
    -- once; where they cannot be counted, at least the window's size: all
    -- the window needs).
    crossings :: Clock -> Clock -> (# Clock, Int #)
    crossings clock = count 0
      where
        t = clockTime clock
        count :: Int -> Clock -> (# Clock, Int #)
        count !k !d
          | not (reached (clockTime d') t) = (# d, k #)
          | k < jumpAt              = count (k + 1) d'
          -- beyond the window: the periods but the last one or two at once
          | r > 2 && r < 9007199254740992 =
              let skipped = floor r - 1 :: Int
              in count (k + skipped) (tick d (fromIntegral skipped * p))
          -- the last one or two, while each is a visible step
          | r <= 2 && clockTime d' > clockTime d = count (k + 1) d'
          -- further than a Double counts, or no visible step: caught up
          | otherwise               = (# clock, max k w #)
          where
            d' = tick d p
            r  = (t - clockTime d) / p
    jumpAt = 4096 :: Int

errNeg :: forall (r :: RuntimeRep) (x :: TYPE r). String -> Double -> x
errNeg f q = error ("AFRP.EventSource." ++ f ++ ": negative or NaN time, got " ++ show q)

errPeriod :: String -> Double -> x
errPeriod f p = error ("AFRP.EventSource." ++ f ++ ": the period must be positive, got " ++ show p)
