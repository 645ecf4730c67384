-- |
-- Module      : Reference
-- Description : A deliberately naive executable model of afrp's signal
--               functions, for differential testing.
--
-- A reference signal function is a plain function on a /finite list of
-- samples/: @runR r [(dt0, a0), (dt1, a1), ...]@ is the list of outputs,
-- one per sample. The first time step (@dt0@) is ignored: the first sample
-- is at local time 0, and sample @k@ is at local time @dt1 + ... + dtk@.
--
-- Nothing here is shared with the library (only the 'Event' data type is
-- imported, to compare outputs). The definitions favour obviousness over
-- speed: many are quadratic. Wherever an output depends on /when/ a sample
-- is (time-triggered events, 'delay'), local time is computed exactly as a
-- 'Rational' sum of the time steps and compared exactly, so the reference
-- states the intended semantics without floating-point drift.
--
-- A signal function that is /started/ later (by a switch) is simply run on
-- the suffix of the sample list that begins at the switching sample: its
-- first time step is then ignored, which makes that sample its local time
-- 0. A signal function that is /frozen/ by a k-switch or a parallel switch
-- is modelled by replaying its whole history ('freeze').
--
-- Every definition is causal and /productive/: output @k@ needs only
-- samples @0..k@ (their spine and, where the semantics says so, their
-- values), so reference networks can be closed into feedback loops
-- ('loop', 'loopPre', 'loopIntegral') exactly where the library's can. In
-- particular the one-sample and time delays, the d-forms of the hybrid
-- combinators and 'delayEventCat' never look at the current input, and the
-- delayed switches emit their output before looking at their event.
--
-- Integrals and derivatives are computed in 'Double' with the textbook
-- formula of the library's documentation (left / right rectangle,
-- trapezoid, difference quotient), so on a single combinator they agree
-- with the library to the last bit or nearly.
--
-- Names are those of the library; import this module qualified.
module Reference
  ( -- * The model
    R (..)
  , DTime
  , Time
  , localTimes
  , freeze
    -- * Arrow combinators
  , arr
  , (>>>)
  , first
  , second
  , (***)
  , (&&&)
  , loop
  , left
    -- * Basic
  , identity
  , constant
  , localTime
  , (-->)
  , (>--)
  , (-=>)
  , (>=-)
    -- * Event sources
  , never
  , now
  , after
  , repeatedly
  , afterEach
  , afterEachCat
  , delayEvent
  , delayEventCat
  , edge
  , iEdge
  , edgeBy
  , edgeJust
  , notYet
  , once
  , takeEvents
  , dropEvents
  , snap
  , snapAfter
  , sample
  , sampleWindow
    -- * Hybrid
  , hold
  , dHold
  , trackAndHold
  , dTrackAndHold
  , accum
  , accumHold
  , dAccumHold
  , accumBy
  , accumHoldBy
  , dAccumHoldBy
  , accumFilter
    -- * Delays
  , iPre
  , fby
  , delay
    -- * Integration
  , integral
  , imIntegral
  , trapezoidIntegral
  , impulseIntegral
  , count
  , derivative
    -- * Loops
  , loopPre
  , loopIntegral
    -- * Switches
  , switch
  , dSwitch
  , rSwitch
  , drSwitch
  , kSwitch
  , dkSwitch
    -- * Collections
  , parB
  , parZ
  , pSwitchB
  , dpSwitchB
  , rpSwitchB
  , drpSwitchB
  ) where

import           Data.List  (partition)
import           Data.Maybe (fromMaybe, isJust)

import           AFRP.Event (Event (..))

infixr 1 >>>
infixr 3 ***, &&&
infixr 0 -->, >--, -=>, >=-, `fby`

-- | Time in seconds.
type Time = Double

-- | A time step in seconds.
type DTime = Double

-- | A reference signal function: the outputs (one per sample) of a finite
-- list of samples (time step, input). The first time step is ignored.
newtype R a b = R { runR :: [(DTime, a)] -> [b] }

------------------------------------------------------------------------------
-- Helpers (all private except 'localTimes' and 'freeze')

-- | The exact local time of every sample: 0 for the first, then the
-- running sum of the (exact values of the) time steps.
localTimes :: [(DTime, a)] -> [Rational]
localTimes []         = []
localTimes (_ : rest) = scanl (\t (dt, _) -> t + toRational dt) 0 rest

values :: [(DTime, a)] -> [a]
values = map snd

-- | The samples with their exact local times.
timed :: [(DTime, a)] -> [(Rational, a)]
timed xs = zip (localTimes xs) (values xs)

-- | Replace the values of the samples, keeping the time steps. Lazy in the
-- spine of the new values (needed to tie feedback knots).
relabel :: [(DTime, a)] -> [b] -> [(DTime, b)]
relabel []              _  = []
relabel ((dt, _) : xs) bs = (dt, headOf bs) : relabel xs (drop 1 bs)
  where
    headOf (b : _) = b
    headOf []      = error "Reference: fewer values than samples"

-- | The first component of every input (time steps kept).
firsts :: [(DTime, (a, c))] -> [(DTime, a)]
firsts = map (\(dt, p) -> (dt, fst p))

-- | The second component of every input.
seconds :: [(DTime, (c, a))] -> [(DTime, a)]
seconds = map (\(dt, p) -> (dt, snd p))

-- | One sample later: @x0@ first, then every element but the last.
shiftedBy :: x -> [y] -> [x] -> [x]
shiftedBy x0 spine xs = zipWith const (x0 : xs) spine

-- | The i-th element of every list, for every sample (following the spine
-- of the samples lazily, so that output i needs only samples 0..i).
columns :: [x] -> [[b]] -> [[b]]
columns spine outss = zipWith const [map (!! i) outss | i <- [0 ..]] spine

isOccurrence :: Event a -> Bool
isOccurrence (Event _) = True
isOccurrence NoEvent   = False

fromMaybeE :: Maybe a -> Event a
fromMaybeE (Just x) = Event x
fromMaybeE Nothing  = NoEvent

-- | @freeze r hist dt@ is @r@ paused after having seen the samples @hist@,
-- with a pending step of @dt@: when it is started, its first sample is
-- taken @dt@ after the last sample of @hist@ (whatever time step it is
-- given), and it continues as @r@ would. With an empty history it is @r@
-- itself, unstarted.
freeze :: R a b -> [(DTime, a)] -> DTime -> R a b
freeze (R f) hist dt = R g
  where
    g []              = []
    g ((_, a) : rest) = drop (length hist) (f (hist ++ (dt, a) : rest))

------------------------------------------------------------------------------
-- Arrow combinators

-- | Pointwise function.
arr :: (a -> b) -> R a b
arr f = R (map (f . snd))

-- | Serial composition: the second sees the outputs of the first, with the
-- same time steps.
(>>>) :: R a b -> R b c -> R a c
R f >>> R g = R (\xs -> g (relabel xs (f xs)))

-- | Act on the first component.
first :: R a b -> R (a, c) (b, c)
first (R f) = R (\xs -> zip (f (firsts xs)) (map (snd . snd) xs))

-- | Act on the second component.
second :: R a b -> R (c, a) (c, b)
second (R f) = R (\xs -> zip (map (fst . snd) xs) (f (seconds xs)))

-- | Parallel composition on pairs.
(***) :: R a b -> R c d -> R (a, c) (b, d)
R f *** R g = R (\xs -> zip (f (firsts xs)) (g (seconds xs)))

-- | Fan-out.
(&&&) :: R a b -> R a c -> R a (b, c)
R f &&& R g = R (\xs -> zip (f xs) (g xs))

-- | Feedback at the same sample: the second output component is the second
-- input component. Only meaningful when the feedback is well founded.
loop :: R (a, c) (b, c) -> R a b
loop (R f) = R (\xs ->
  let ys = f (relabel xs (zip (values xs) (map snd ys)))
  in map fst ys)

-- | Choice, with the library's semantics (Yampa's): @left r@ runs @r@ on
-- the 'Left' samples only. @r@ starts at the first 'Left' sample (its local
-- time 0) and is frozen on 'Right' samples: at each later 'Left' sample it
-- is stepped by that sample's own time step, so the time spent on the
-- 'Right' side is lost to it. 'Right' samples pass through.
left :: R a b -> R (Either a c) (Either b c)
left (R f) = R (\xs ->
  let fIn = [(dt, a) | (dt, Left a) <- xs]
      merge (Left _ : es)  (b : bs) = Left b : merge es bs
      merge (Right c : es) bs       = Right c : merge es bs
      merge _              _        = []
  in merge (values xs) (f fIn))

------------------------------------------------------------------------------
-- Basic

identity :: R a a
identity = R values

constant :: b -> R a b
constant b = R (map (const b))

-- | The exact local time, rounded once.
localTime :: R a Time
localTime = R (map fromRational . localTimes)

-- | Replace the first output.
(-->) :: b -> R a b -> R a b
b0 --> R f = R (\xs -> case f xs of
  []       -> []
  (_ : ys) -> b0 : ys)

-- | Replace the first input.
(>--) :: a -> R a b -> R a b
a0 >-- R f = R (\xs -> f (case xs of
  []            -> []
  ((dt, _) : r) -> (dt, a0) : r))

-- | Map the first output.
(-=>) :: (b -> b) -> R a b -> R a b
g -=> R f = R (\xs -> case f xs of
  []       -> []
  (y : ys) -> g y : ys)

-- | Map the first input.
(>=-) :: (a -> a) -> R a b -> R a b
g >=- R f = R (\xs -> f (case xs of
  []            -> []
  ((dt, a) : r) -> (dt, g a) : r))

------------------------------------------------------------------------------
-- Event sources

never :: R a (Event b)
never = constant NoEvent

-- | An occurrence at the first sample only.
now :: b -> R a (Event b)
now x = R (zipWith (\i _ -> if i == 0 then Event x else NoEvent) [0 :: Int ..])

-- | The absolute schedule of a list of (delay after the previous scheduled
-- occurrence, value).
schedule :: [(Time, b)] -> [(Rational, b)]
schedule = go 0
  where
    go _ [] = []
    go t ((q, x) : rest)
      | q < 0 || isNaN q = error "Reference.schedule: negative delay"
      | otherwise        = let t' = t + toRational q in (t', x) : go t' rest

-- | For each sample, the scheduled occurrences that fall due there: those
-- scheduled at or before it and after the previous sample.
dueLists :: [(Rational, b)] -> [Rational] -> [[b]]
dueLists _     []       = []
dueLists sched (t : ts) =
  let (due, later) = span ((<= t) . fst) sched
  in map snd due : dueLists later ts

afterEachCat :: [(Time, b)] -> R a (Event [b])
afterEachCat qxs = R (\xs ->
  [if null due then NoEvent else Event due | due <- dueLists (schedule qxs) (localTimes xs)])

afterEach :: [(Time, b)] -> R a (Event b)
afterEach qxs = R (\xs ->
  [case due of { [] -> NoEvent; (d : _) -> Event d } | due <- dueLists (schedule qxs) (localTimes xs)])

-- | One occurrence at the first sample whose local time is >= t.
after :: Time -> b -> R a (Event b)
after t x
  | t < 0 || isNaN t = error "Reference.after: negative time"
  | otherwise = R (\xs -> go (localTimes xs))
  where
    go [] = []
    go (tk : ts)
      | tk >= toRational t = Event x : map (const NoEvent) ts
      | otherwise          = NoEvent : go ts

-- | An occurrence at every sample (after the first) such that some
-- multiple @m * p@ (m >= 1) lies in (previous sample time, sample time].
repeatedly :: Time -> b -> R a (Event b)
repeatedly p x
  | p <= 0 || isNaN p = error "Reference.repeatedly: non-positive period"
  | otherwise = R (\xs ->
      let ts = localTimes xs
      in zipWith (\tp t -> if periods t > periods tp then Event x else NoEvent) (0 : ts) ts)
  where
    periods :: Rational -> Integer
    periods t = floor (t / toRational p)

-- | Every input occurrence at local time t comes out, in arrival order,
-- at the first sample at or after t + q.
delayEventCat :: Time -> R (Event a) (Event [a])
delayEventCat q
  | q < 0 || isNaN q = error "Reference.delayEventCat: negative delay"
  | q == 0           = arr (fmap (: []))
  | otherwise        = R (\xs -> go [] (timed xs))
  where
    go _ [] = []
    -- The current input is scheduled after the output is decided: with
    -- q > 0 it cannot be due at once (and is never evaluated early).
    go pending ((t, e) : rest) =
      let (due, later) = partition ((<= t) . fst) pending
          out          = if null due then NoEvent else Event (map snd due)
      in out : go (later ++ [(t + toRational q, x) | Event x <- [e]]) rest

delayEvent :: Time -> R (Event a) (Event a)
delayEvent q
  | q == 0    = identity
  | otherwise = R (map (fmap head) . runR (delayEventCat q))

-- | @f previous current@ at every sample; @a0@ is the previous of the first.
edgeBy :: (a -> a -> Maybe b) -> a -> R a (Event b)
edgeBy f a0 = R (\xs ->
  let as = values xs in zipWith (\p c -> fromMaybeE (f p c)) (a0 : as) as)

iEdge :: Bool -> R Bool (Event ())
iEdge b0 = R (\xs ->
  let bs = values xs
  in zipWith (\p c -> if c && not p then Event () else NoEvent) (b0 : bs) bs)

edge :: R Bool (Event ())
edge = iEdge True

edgeJust :: R (Maybe a) (Event a)
edgeJust = R (\xs ->
  let ms = values xs
  in zipWith (\wasJust m -> case m of
                 Just x | not wasJust -> Event x
                 _                    -> NoEvent)
             (True : map isJust ms) ms)

notYet :: R (Event a) (Event a)
notYet = R (zipWith (\i (_, e) -> if i == 0 then NoEvent else e) [0 :: Int ..])

takeEvents :: Int -> R (Event a) (Event a)
takeEvents n0 = R (go n0 . values)
  where
    go _ [] = []
    go n (e : es)
      | isOccurrence e && n > 0 = e : go (n - 1) es
      | otherwise               = NoEvent : go n es

once :: R (Event a) (Event a)
once = takeEvents 1

dropEvents :: Int -> R (Event a) (Event a)
dropEvents n0 = R (go n0 . values)
  where
    go _ [] = []
    go n (e : es)
      | isOccurrence e && n > 0 = NoEvent : go (n - 1) es
      | otherwise               = e : go n es

snap :: R a (Event a)
snap = R (zipWith (\i (_, a) -> if i == 0 then Event a else NoEvent) [0 :: Int ..])

-- | One occurrence, carrying the input, at the first sample whose local
-- time is >= t. A negative t is an error.
snapAfter :: Time -> R a (Event a)
snapAfter t
  | t < 0 || isNaN t = error "Reference.snapAfter: negative time"
  | otherwise        = R (go . timed)
  where
    go [] = []
    go ((tk, a) : rest)
      | tk >= toRational t = Event a : map (const NoEvent) rest
      | otherwise          = NoEvent : go rest

sample :: Time -> R a (Event a)
sample p = R (\xs ->
  zipWith (\e a -> fmap (const a) e) (runR (repeatedly p ()) xs) (values xs))

-- | At each sample, the number k of multiples of p in (previous sample
-- time, sample time]; when k > 0 the current input joins the window k
-- times and the last w window entries are output.
sampleWindow :: Int -> Time -> R a (Event [a])
sampleWindow w p
  | w < 1 || p <= 0 || isNaN p = error "Reference.sampleWindow: bad arguments"
  | otherwise = R (\xs ->
      let ts = localTimes xs
          ks = zipWith (\tp t -> periods t - periods tp) (0 : ts) ts
      in go [] (zip ks (values xs)))
  where
    periods :: Rational -> Int
    periods t = floor (t / toRational p)
    go _ [] = []
    go win ((k, a) : rest)
      | k > 0     = let grown = win ++ replicate k a
                        win'  = drop (length grown - w) grown
                    in Event win' : go win' rest
      | otherwise = NoEvent : go win rest

------------------------------------------------------------------------------
-- Hybrid

hold :: a -> R (Event a) a
hold a0 = R (drop 1 . scanl (\h e -> case e of { Event x -> x; NoEvent -> h }) a0 . values)

dHold :: a -> R (Event a) a
dHold a0 = R (\xs -> shiftedBy a0 xs (runR (hold a0) xs))

trackAndHold :: a -> R (Maybe a) a
trackAndHold a0 = R (drop 1 . scanl fromMaybe a0 . values)

dTrackAndHold :: a -> R (Maybe a) a
dTrackAndHold a0 = R (\xs -> shiftedBy a0 xs (runR (trackAndHold a0) xs))

accumBy :: (b -> a -> b) -> b -> R (Event a) (Event b)
accumBy f b0 = R (go b0 . values)
  where
    go _ [] = []
    go b (NoEvent : es) = NoEvent : go b es
    go b (Event a : es) = let b' = f b a in Event b' : go b' es

accum :: a -> R (Event (a -> a)) (Event a)
accum = accumBy (\a g -> g a)

accumHoldBy :: (b -> a -> b) -> b -> R (Event a) b
accumHoldBy f b0 = R (drop 1 . scanl step b0 . values)
  where
    step b NoEvent   = b
    step b (Event a) = f b a

accumHold :: a -> R (Event (a -> a)) a
accumHold = accumHoldBy (\a g -> g a)

dAccumHold :: a -> R (Event (a -> a)) a
dAccumHold a0 = R (\xs -> shiftedBy a0 xs (runR (accumHold a0) xs))

dAccumHoldBy :: (b -> a -> b) -> b -> R (Event a) b
dAccumHoldBy f b0 = R (\xs -> shiftedBy b0 xs (runR (accumHoldBy f b0) xs))

accumFilter :: (c -> a -> (c, Maybe b)) -> c -> R (Event a) (Event b)
accumFilter f c0 = R (go c0 . values)
  where
    go _ [] = []
    go c (NoEvent : es) = NoEvent : go c es
    go c (Event a : es) = let (c', mb) = f c a in fromMaybeE mb : go c' es

------------------------------------------------------------------------------
-- Delays

iPre :: a -> R a a
iPre a0 = R (\xs -> shiftedBy a0 xs (values xs))

fby :: b -> R a b -> R a b
fby b0 (R f) = R (\xs -> shiftedBy b0 xs (f xs))

-- | At local time t: a0 while t < q, else the input of the latest sample
-- at a time s <= t - q (exact arithmetic).
delay :: Time -> a -> R a a
delay q a0
  | q < 0 || isNaN q = error "Reference.delay: negative delay"
  | q == 0           = identity
  | otherwise        = R (go [] . timed)
  where
    -- earlier: the samples so far, newest first (the current one included)
    go _ [] = []
    go earlier ((t, a) : rest) =
      let earlier' = (t, a) : earlier
          out      = case [x | (s, x) <- earlier', s <= t - toRational q] of
            []      -> a0
            (x : _) -> x
      in out : go earlier' rest

------------------------------------------------------------------------------
-- Integration

-- | Left rectangle rule: y0 = 0, yk = y(k-1) + dtk * a(k-1).
integral :: R Double Double
integral = R (\xs -> case xs of
  [] -> []
  _  -> scanl (\acc ((dt, _), (_, aPrev)) -> acc + dt * aPrev) 0 (zip (drop 1 xs) xs))

-- | Right rectangle rule: y0 given, yk = y(k-1) + dtk * ak.
imIntegral :: Double -> R Double Double
imIntegral y0 = R (\xs -> case xs of
  []         -> []
  (_ : rest) -> scanl (\acc (dt, a) -> acc + dt * a) y0 rest)

-- | Trapezoid rule: y0 = 0, yk = y(k-1) + dtk/2 * (a(k-1) + ak).
trapezoidIntegral :: R Double Double
trapezoidIntegral = R (\xs -> case xs of
  [] -> []
  _  -> scanl (\acc ((dt, a), (_, aPrev)) -> acc + (dt / 2) * (aPrev + a)) 0 (zip (drop 1 xs) xs))

-- | The integral of the first component plus the sum of all event values
-- of the second so far (the current one included).
impulseIntegral :: R (Double, Event Double) Double
impulseIntegral = R (\xs ->
  let flow    = runR integral (firsts xs)
      impulses = drop 1 (scanl (\s e -> case e of { Event v -> s + v; NoEvent -> s }) 0
                                (map (snd . snd) xs))
  in zipWith (+) flow impulses)

-- | The n-th occurrence becomes an occurrence of n.
count :: Integral n => R (Event a) (Event n)
count = R (go 1 . values)
  where
    go _ [] = []
    go n (NoEvent : es) = NoEvent : go n es
    go n (Event _ : es) = Event n : go (n + 1) es

-- | 0 at the first sample, then (ak - a(k-1)) / dtk.
derivative :: R Double Double
derivative = R (\xs -> case xs of
  [] -> []
  _  -> 0 : zipWith (\(dt, a) (_, aPrev) -> (a - aPrev) / dt) (drop 1 xs) xs)

------------------------------------------------------------------------------
-- Loops

-- | The second output fed back, one sample later, as the second input;
-- c0 at the first sample.
loopPre :: c -> R (a, c) (b, c) -> R a b
loopPre c0 (R f) = R (\xs ->
  let ys = f (relabel xs (zip (values xs) (c0 : map snd ys)))
  in map fst ys)

-- | The second output integrated (left rectangle rule) and fed back as the
-- second input.
loopIntegral :: R (a, Double) (b, Double) -> R a b
loopIntegral (R f) = R (\xs ->
  let fedBack = runR integral (relabel xs (map snd ys))
      ys      = f (relabel xs (zip (values xs) fedBack))
  in map fst ys)

------------------------------------------------------------------------------
-- Switches
--
-- All switches walk along the samples, deciding at each sample only from
-- what is known at that sample, so that they can sit inside a feedback
-- loop. The running signal function is run on the whole remaining suffix
-- (lazily; by causality its outputs up to the switching sample do not
-- depend on the samples after it). The delayed (d) forms emit their output
-- before looking at the event, as the library's decoupled switches do.

switch :: R a (b, Event c) -> (c -> R a b) -> R a b
switch (R sf) k = R (\xs -> walk xs (sf xs))
  where
    walk rest@(_ : rest') (out : outs) = case snd out of
      NoEvent -> fst out : walk rest' outs
      Event c -> runR (k c) rest
    walk _ _ = []

dSwitch :: R a (b, Event c) -> (c -> R a b) -> R a b
dSwitch (R sf) k = R (\xs -> walk xs (sf xs))
  where
    walk rest@(_ : rest') (out : outs) = fst out : case snd out of
      NoEvent -> walk rest' outs
      Event c -> drop 1 (runR (k c) rest)
    walk _ _ = []

-- | The running signal function sees the first input component; an event
-- in the second replaces it, at that sample, by the one it carries, which
-- starts there (seeing the event masked).
rSwitch :: R a b -> R (a, Event (R a b)) b
rSwitch sf0 = R (go sf0)
  where
    go sf xs = walk xs (runR sf (firsts xs))
    walk ((dt, (a, e)) : rest) (b : bs) = case e of
      NoEvent   -> b : walk rest bs
      Event sf' -> go sf' ((dt, (a, NoEvent)) : rest)
    walk _ _ = []

drSwitch :: R a b -> R (a, Event (R a b)) b
drSwitch sf0 = R (go sf0)
  where
    go sf xs = walk xs (runR sf (firsts xs))
    walk ((dt, ae) : rest) (b : bs) = b : case snd ae of
      NoEvent   -> walk rest bs
      Event sf' -> drop 1 (go sf' ((dt, (fst ae, NoEvent)) : rest))
    walk _ _ = []

-- | The event source sees the input and the output of the running signal
-- function; at its first occurrence, @k@ gets that signal function frozen
-- just before the switching sample.
kSwitch :: R a b -> R (a, b) (Event c) -> (R a b -> c -> R a b) -> R a b
kSwitch sf (R sfe) k = R (\xs ->
  let bs = runR sf xs
      es = sfe (relabel xs (zip (values xs) bs))
      walk hist (x : rest) (b : bs') (e : es') = case e of
        NoEvent -> b : walk (hist ++ [x]) rest bs' es'
        Event c -> runR (k (freeze sf hist (fst x)) c) (x : rest)
      walk _ _ _ _ = []
  in walk [] xs bs es)

dkSwitch :: R a b -> R (a, b) (Event c) -> (R a b -> c -> R a b) -> R a b
dkSwitch sf (R sfe) k = R (\xs ->
  let bs = runR sf xs
      es = sfe (relabel xs (zip (values xs) bs))
      walk hist (x : rest) (b : bs') (e : es') = b : case e of
        NoEvent -> walk (hist ++ [x]) rest bs' es'
        Event c -> drop 1 (runR (k (freeze sf hist (fst x)) c) (x : rest))
      walk _ _ _ _ = []
  in walk [] xs bs es)

------------------------------------------------------------------------------
-- Collections (lists only)

-- | Every member sees the whole input.
parB :: [R a b] -> R a [b]
parB sfs = R (\xs -> columns xs [runR sf xs | sf <- sfs])

-- | The i-th member sees the i-th element of the input list.
parZ :: [R a b] -> R [a] [b]
parZ sfs = R (\xs ->
  columns xs [runR sf [(dt, as !! i) | (dt, as) <- xs] | (i, sf) <- zip [0 ..] sfs])

-- | The event source sees the input and the members' outputs; at its first
-- occurrence, @k@ gets the members frozen just before that sample.
pSwitchB :: [R a b] -> R (a, [b]) (Event c) -> ([R a b] -> c -> R a [b]) -> R a [b]
pSwitchB sfs (R sfe) k = R (\xs ->
  let cs = runR (parB sfs) xs
      es = sfe (relabel xs (zip (values xs) cs))
      walk hist (x : rest) (c : cs') (e : es') = case e of
        NoEvent -> c : walk (hist ++ [x]) rest cs' es'
        Event d -> runR (k [freeze sf hist (fst x) | sf <- sfs] d) (x : rest)
      walk _ _ _ _ = []
  in walk [] xs cs es)

dpSwitchB :: [R a b] -> R (a, [b]) (Event c) -> ([R a b] -> c -> R a [b]) -> R a [b]
dpSwitchB sfs (R sfe) k = R (\xs ->
  let cs = runR (parB sfs) xs
      es = sfe (relabel xs (zip (values xs) cs))
      walk hist (x : rest) (c : cs') (e : es') = c : case e of
        NoEvent -> walk (hist ++ [x]) rest cs' es'
        Event d -> drop 1 (runR (k [freeze sf hist (fst x) | sf <- sfs] d) (x : rest))
      walk _ _ _ _ = []
  in walk [] xs cs es)

-- | At each event @Event f@, the members (frozen just before that sample)
-- are replaced by @f@ of them, started at that sample.
rpSwitchB :: [R a b] -> R (a, Event ([R a b] -> [R a b])) [b]
rpSwitchB sfs0 = R (go sfs0)
  where
    go sfs xs = walk [] sfs xs (runR (parB sfs) (firsts xs))
    walk hist sfs ((dt, (a, e)) : rest) (c : cs) = case e of
      NoEvent -> c : walk (hist ++ [(dt, a)]) sfs rest cs
      Event f -> go (f [freeze sf hist dt | sf <- sfs]) ((dt, (a, NoEvent)) : rest)
    walk _ _ _ _ = []

drpSwitchB :: [R a b] -> R (a, Event ([R a b] -> [R a b])) [b]
drpSwitchB sfs0 = R (go sfs0)
  where
    go sfs xs = walk [] sfs xs (runR (parB sfs) (firsts xs))
    walk hist sfs ((dt, ae) : rest) (c : cs) = c : case snd ae of
      NoEvent -> walk (hist ++ [(dt, fst ae)]) sfs rest cs
      Event f -> drop 1 (go (f [freeze sf hist dt | sf <- sfs]) ((dt, (fst ae, NoEvent)) : rest))
    walk _ _ _ _ = []
