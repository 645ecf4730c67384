{-# LANGUAGE UnboxedTuples #-}
{-# LANGUAGE BangPatterns  #-}
-- |
-- Module      : AFRP.Run
-- Description : Running signal functions: in IO against the real world,
--               or purely on a list of samples.
--
-- Every runner takes the first input sample without a time step (the
-- signal function's local time 0) and each later one with the time step
-- since the previous sample. A later sample may omit the input
-- ('Nothing'), meaning "unchanged since the last sample".
--
-- = What the runners evaluate
--
-- As Yampa's, with two exceptions (below): 'reactimate' evaluates each
-- input sample and each output sample to weak head normal form after the
-- output has been actuated (the first ones included, even when @actuate@
-- says stop); 'embed' evaluates a later sample's input when the rest of the
-- list is demanded, after that sample's output is in the list (so the
-- first input is not evaluated unless a 'Nothing' repeats it). A step
-- never evaluates its input itself. So a signal function that ignores its
-- input still runs in constant space, and an input that is an error
-- raises it where Yampa's does:
--
-- > take 2 (embed (iPre 0) (1, [(1, Just (error "no input")), (1, Just 3)]))  ==  [0, 1]
-- > length (embed (iPre 0) (1, [(1, Just (error "no input")), (1, Just 3)]))   -- raises "no input"
--
-- The first exception: 'embed' never evaluates an output (Yampa's evaluates
-- each one but the first when the list goes past it), so @length@ of an
-- embedded run shows what a signal function computes without its outputs
-- being looked at:
--
-- > length (embed (arr (\x -> if x == 2 then error "boom" else x)) (1, [(1, Just 2)]))  ==  2
-- >   -- (Yampa's raises "boom")
--
-- 'react' evaluates neither the input nor the output, as Yampa's, but
-- (the second exception) it looks at whether the sample is 'Nothing',
-- where Yampa's does not, so that a long run of unchanged samples builds
-- no chain of thunks: @react h (dt, error "no sample")@ raises.
-- 'evalAtZero' and 'evalAt' evaluate nothing.
--
-- = Time steps
--
-- A time step must be a number, 0 or more: every runner ('embed',
-- 'reactimate', 'react', 'evalAt', 'evalFuture', 'deltaEncode') refuses
-- a NaN or negative one with an error naming the runner and the step,
-- when it takes that step. (Yampa checks nothing here. A NaN step made
-- the time and every integral NaN from then on, and a delay keep every
-- later input; a negative one ran time backwards; both silently.) A step
-- of 0 is a sample at the same time as the one before; an infinite one
-- passes every finite time (every 'AFRP.EventSource.after' fires, the
-- time is infinite from then on, and an integral of 0 over it is NaN:
-- @0 * Infinity@). The step is checked before it is taken, whether the
-- signal function reads it or not.
module AFRP.Run
  ( -- * Running in a monad
    reactimate
  , ReactHandle
  , reactInit
  , react
    -- * Stepping by hand
  , FutureSF
  , evalAtZero
  , evalAt
  , evalFuture
    -- * Running on lists
  , embed
  , embedSynch
  , deltaEncode
  , deltaEncodeBy
  ) where

import           Data.IORef
import           Data.Maybe       (fromMaybe)
import           GHC.Exts         (build, oneShot)

import           AFRP.Internal.SF

-- | @reactimate initialise sense actuate sf@ runs @sf@ as an interactive
-- loop:
--
-- * @initialise@ gives the first input sample (local time 0);
-- * @sense b@ gives the time step to the next sample and its input
--   ('Nothing' = unchanged); the flag says whether it may block, and is
--   always 'False' here (as in Yampa);
-- * @actuate changed out@ consumes each output sample, the first included,
--   and returns 'True' to stop the loop; @changed@ is always 'True'.
--
-- The signal function's state is evaluated at every step, and each
-- sample's input and output after its actuation (as in Yampa: see "What
-- the runners evaluate" above), so a loop of any length runs in the space
-- its signal function needs.
reactimate :: Monad m => m a -> (Bool -> m (DTime, Maybe a)) -> (Bool -> b -> m Bool) -> SF a b -> m ()
reactimate initialise sense actuate (SF n0) = do
  a0 <- initialise
  case stepN n0 0 a0 of
    (# n1, b0 #) -> loop n1 a0 b0
  where
    -- (the sample's input and output evaluated after the actuation, as
    -- in Yampa: see the module's documentation)
    loop !n a b = do
      stop <- actuate True b
      if a `seq` b `seq` stop then pure () else do
        (dt, ma) <- sense False
        let a' = fromMaybe a ma
        -- (the step checked before it is taken, whether or not the
        -- network reads it)
        case checkDt "reactimate" dt of
          !dt' -> case stepN n dt' a' of
            (# n', b' #) -> loop n' a' b'

-- | The state of a signal function being driven sample by sample from the
-- outside ('reactInit', 'react'): for event loops owned by another library
-- (a GUI toolkit, a game engine) that call back once per frame.
data ReactHandle a b = ReactHandle
  { rhState   :: !(IORef (ReactState a b))
  , rhActuate :: ReactHandle a b -> Bool -> b -> IO Bool
  }

data ReactState a b = ReactState !(Node a b) a

-- | @reactInit initialise actuate sf@ takes the first input sample, runs
-- the first step, passes its output to @actuate@ and returns a handle for
-- 'react'. What that first @actuate@ returns is ignored (as in Yampa);
-- 'react' returns what each later one returns.
reactInit :: IO a -> (ReactHandle a b -> Bool -> b -> IO Bool) -> SF a b -> IO (ReactHandle a b)
reactInit initialise actuate (SF n0) = do
  a0 <- initialise
  case stepN n0 0 a0 of
    (# n1, b0 #) -> do
      ref <- newIORef (ReactState n1 a0)
      let h = ReactHandle ref actuate
      _ <- actuate h True b0
      pure h

-- | @react h (dt, ma)@ performs one step of the time step @dt@ with input
-- @ma@ ('Nothing' = unchanged), passes the output to the handle's actuate
-- action and returns what that action returned.
react :: ReactHandle a b -> (DTime, Maybe a) -> IO Bool
react h (dt, ma) = do
  ReactState n a <- readIORef (rhState h)
  -- (the input not evaluated, as in Yampa; only whether it is new)
  a' <- case ma of
    Nothing -> pure a
    Just x  -> pure x
  case checkDt "react" dt of
    !dt' -> case stepN n dt' a' of
      (# n', b #) -> do
        writeIORef (rhState h) (ReactState n' a')
        rhActuate h h True b

-- | A signal function that has been started: it has seen its first sample
-- and expects each later one with its time step. Produced and consumed by
-- 'evalAtZero' and 'evalAt'.
newtype FutureSF a b = FutureSF (Node a b)

-- | Start a signal function by hand: its output at local time 0 for the
-- given input, and what it has become. For drivers that own their loop
-- (a simulator, a game engine) and want no 'IO'.
evalAtZero :: SF a b -> a -> (b, FutureSF a b)
evalAtZero (SF n) a = case stepN n 0 a of (# n', b #) -> (b, FutureSF n')

-- | One more step by hand: the output after the time step @dt@ with the
-- given input, and what the signal function has become. Its state is
-- evaluated when the result pair is.
evalAt :: FutureSF a b -> DTime -> a -> (b, FutureSF a b)
evalAt (FutureSF n) dt a = case checkDt "evalAt" dt of
  !dt' -> case stepN n dt' a of (# n', b #) -> (b, FutureSF n')

-- | @evalFuture sf a dt@ runs the first sample (local time 0) of @sf@ on
-- input @a@ and returns its output and the rest of @sf@ as a signal
-- function whose first sample comes @dt@ after that one (whatever time step
-- it is later run with). For tests and debugging, as 'evalAt'.
evalFuture :: SF a b -> a -> DTime -> (b, SF a b)
evalFuture (SF n) a dt = case checkDt "evalFuture" dt of
  !dt' -> case stepN n 0 a of (# n', b #) -> (b, SF (freezeN n' dt'))

-- | @embed sf (a0, samples)@ runs @sf@ purely: @a0@ is the input at local
-- time 0, each @(dt, ma)@ a later sample. The result has one output per
-- input sample (the first at time 0), produced lazily; the state is
-- evaluated as the list is consumed, and each later sample's input when
-- the list goes past it; no output is evaluated (see "What the runners
-- evaluate" above).
--
-- > embed integral (1 :: Double, [(0.5, Just 2), (0.5, Nothing)])  ==  [0, 0.5, 1.5]
embed :: SF a b -> (a, [(DTime, Maybe a)]) -> [b]
embed sf input = build (\cons nil -> embedFB cons nil sf input)
{-# INLINE embed #-}

-- 'embed' with the list constructors abstracted, and consuming its samples
-- with 'foldr': 'embed' is then a good consumer of its samples and a good
-- producer of its outputs, so that when the samples come from a list
-- producer (@[(dt, Just x) | x <- ...]@) GHC fuses the two and no input
-- list is built (and, where 'embed' is inlined into a list consumer, no
-- output list either). @embedFB (:) []@ is the direct recursion
-- @go n a ((dt, ma) : rest) = b : (a' \`seq\` go n' a' rest)@: the same
-- step, the same tail, evaluating the sample's input when the tail is
-- demanded, as Yampa's does (and not its output, which Yampa's does).
embedFB :: (b -> r -> r) -> r -> SF a b -> (a, [(DTime, Maybe a)]) -> r
embedFB cons nil (SF n0) (a0, samples) = case stepN n0 0 a0 of
  (# n1, b0 #) -> b0 `cons` foldr (embedStep cons) (\ !_ _ -> nil) samples n1 a0
{-# INLINE embedFB #-}

-- One sample of 'embedFB'.
embedStep :: (b -> r -> r) -> (DTime, Maybe a) -> (Node a b -> a -> r) -> Node a b -> a -> r
embedStep cons (dt, ma) k = oneShot (\n a ->
  let a' = fromMaybe a ma
  in case checkDt "embed" dt of
       !dt' -> case stepN n dt' a' of (# n', b #) -> b `cons` (a' `seq` k n' a'))
{-# INLINE embedStep #-}

-- A time step as a runner takes it: the step itself when it is 0 or more
-- (infinity included), an error naming the runner when it is NaN or
-- negative (see "Time steps" above).
checkDt :: String -> DTime -> DTime
checkDt runner dt
  | dt >= 0   = dt
  | otherwise = badDt runner dt
{-# INLINE checkDt #-}

badDt :: String -> DTime -> a
badDt runner dt = error ("AFRP.Run." ++ runner ++ ": a time step of " ++ show dt
                         ++ " (a time step must be a number, 0 or more)")
{-# NOINLINE badDt #-}

-- | @embedSynch sf (a0, samples)@ is a signal function that replays the
-- run of @sf@ on the given samples at a controllable speed. Its input is
-- the speed ratio (0 pauses, 1 is real time, 2 is twice as fast); the
-- embedded run's clock advances by @ratio * dt@ at each step, and the
-- output is the embedded output of the latest embedded sample at or before
-- that clock (the last one once the samples run out). The clock and the
-- samples' times are sums of floats, compared as they are, as in Yampa
-- (not by the rounding rule of the library's timed events): at a clock of
-- 0.3, samples 0.1 apart have their fourth at 0.30000000000000004, not yet
-- reached, so the output is the third's. A negative or NaN
-- ratio is an error. The ratio at local time 0 is not read (the output
-- there is the embedded output at time 0 whatever it is), as in Yampa;
-- nor is the ratio of a later sample read before the output is demanded
-- (or the next step starts), so the ratio may come through a 'loop'.
-- A ratio of 0 pauses even over an infinite step, and
-- a step of 0 advances nothing even at an infinite ratio (the clock moves
-- by @ratio * dt@ only when both are nonzero, so it never becomes NaN); a
-- step that moves the clock to infinity gives the last sample's output,
-- which for an infinite list of samples never comes.
embedSynch :: SF a b -> (a, [(DTime, Maybe a)]) -> SF Double b
embedSynch sf input@(_, samples) = SF (lazyN (initN (\_ -> start)))
  where
    outputs = embed sf input
    times   = scanl (+) 0 (map fst samples)
    timed   = zip times outputs
    start   = case timed of
      (_, b0) : rest -> (# go 0 b0 rest, b0 #)
      []             -> error "AFRP.Run.embedSynch: impossible: embed produced no output"
    go :: Double -> b -> [(Double, b)] -> Node Double b
    go !clock bLast rest = NStep (\dt ratio ->
      if not (ratio >= 0)
        then error ("AFRP.Run.embedSynch: a speed ratio of " ++ show ratio ++ " (it must be a number, 0 or more)")
        else
          let !clock'       = if ratio == 0 || dt == 0 then clock else clock + ratio * dt
              (done, later) = span ((<= clock') . fst) rest
          in case done of
               [] -> (# go clock' bLast later, bLast #)
               _  -> let bNow = snd (last done) in (# go clock' bNow later, bNow #))

-- | @deltaEncode dt xs@ turns a list of samples taken every @dt@ seconds
-- into the input of 'embed', writing 'Nothing' for a sample equal to the
-- previous one. The list must not be empty, and @dt@ must be a number, 0
-- or more (see "Time steps" above).
deltaEncode :: Eq a => DTime -> [a] -> (a, [(DTime, Maybe a)])
deltaEncode = deltaEncodeNamed "deltaEncode" (==)

-- | 'deltaEncode' with a custom equality: a sample is written 'Nothing'
-- when it is equal to the sample before it (not to the last one written),
-- the new sample given first (@eq new previous@), as in Yampa. With an
-- equality that is not transitive the two rules differ:
--
-- > deltaEncodeBy (\a b -> abs (a - b) < 2) 0.5 [1, 2, 3, 4, 8, 9 :: Double]
-- >   ==  (1, [(0.5, Nothing), (0.5, Nothing), (0.5, Nothing), (0.5, Just 8), (0.5, Nothing)])
deltaEncodeBy :: (a -> a -> Bool) -> DTime -> [a] -> (a, [(DTime, Maybe a)])
deltaEncodeBy = deltaEncodeNamed "deltaEncodeBy"

-- 'deltaEncodeBy', its errors naming the function the user called.
deltaEncodeNamed :: String -> (a -> a -> Bool) -> DTime -> [a] -> (a, [(DTime, Maybe a)])
deltaEncodeNamed name _  _  []       = error ("AFRP.Run." ++ name ++ ": empty list of samples")
deltaEncodeNamed name eq dt0 (x : xs) = (x, zipWith step (x : xs) xs)
  where
    -- (checked once, when the first step is looked at)
    dt = checkDt name dt0
    step prev y = (dt, if eq y prev then Nothing else Just y)
