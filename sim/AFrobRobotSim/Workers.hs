{-# LANGUAGE ScopedTypeVariables #-}
-- No full laziness: it would float the reading of the number of
-- capabilities out of 'capabilitiesNow' as a constant, read only once.
{-# OPTIONS_GHC -fno-full-laziness #-}
-- |
-- Module      : AFrobRobotSim.Workers
-- Description : A fixed pool of worker threads that evaluate pure values
--               in parallel, for the simulator's step.
--
-- 'readInOrder' gives a list of values back unchanged, for a reader that
-- forces them in order; on several capabilities (@+RTS -N@ in a program
-- built @-threaded@), worker threads evaluate them meanwhile, and the
-- reader, while it waits for one, evaluates others.
--
-- Why threads and not sparks ('GHC.Conc.par'): an idle capability sleeps
-- until the running thread next enters the scheduler, which with a large
-- allocation area can be a whole timer tick (20 ms) away, so most sparks
-- of a step of a few milliseconds fizzle. A worker blocked on an 'MVar'
-- is woken as soon as work is handed to it; but waking a sleeping thread
-- takes the operating system 10-30 microseconds, so a worker that runs
-- out of work first looks for more for a while ('spinTime', 0.2 ms,
-- yielding to the runtime between looks) before it sleeps: the
-- simulator's next step usually comes within that time. (Not when the
-- program has more capabilities than the machine has processors: there
-- a worker that looks for work takes a processor from one that has some,
-- so it sleeps at once.) The reader, likewise, when it needs an element
-- a worker is still evaluating and has nothing else to do, looks for it
-- to be done (for about 'spinTime', yielding between looks: a yield may
-- let another thread run a while) before it waits on the element itself:
-- when the reader blocks on a value another thread computes, its
-- capability's operating-system thread sleeps, and is woken through the
-- operating system when the value is there. On the third machine
-- measured (@bench/README.md@, eighteenth round) this made 300 robots on
-- two cores 6% faster and the 100 packed wanderers 4%, and changed
-- nothing at 100 or 1000 robots.
--
-- The pool is made the first time it is needed: one worker per capability
-- but the caller's, pinned to it ('forkOn'), more when the program enables
-- more capabilities. A worker evaluates values ignoring what they raise:
-- the value stays a thunk that raises the same exception when the reader
-- forces it. A value that the reader forces while a worker is evaluating
-- it is waited for (it is a black hole, when the module that builds it is
-- compiled with @-feager-blackholing@, as "AFrobRobotSim.Simulator" is),
-- not evaluated twice. So the values, and which exception the reader
-- meets first, are those of evaluating the list in order on one thread.
module AFrobRobotSim.Workers
  ( readInOrder
  , capabilitiesNow
  ) where

import           Control.Concurrent      (ThreadId, forkOn, myThreadId, threadCapability, yield)
import           Control.Concurrent.MVar (MVar, modifyMVar, newEmptyMVar, newMVar, putMVar,
                                          takeMVar)
import           Control.Exception       (SomeAsyncException, SomeException, evaluate, fromException,
                                          throwIO, try)
import           Control.Monad           (void, when)
import           Data.IORef              (IORef, atomicModifyIORef', atomicWriteIORef, newIORef,
                                          readIORef)
import           Data.Word               (Word64)
import           GHC.Arr                 (Array, listArray, (!))
import           GHC.Clock               (getMonotonicTimeNSec)
import           GHC.Conc                (getNumCapabilities, getNumProcessors)
import           GHC.IO                  (unsafeDupablePerformIO, unsafePerformIO)

-- The workers started so far: the @i@-th (from 1) is pinned to
-- capability @i@, or to capability 0 if @i@ is the capability of the
-- thread that hands them work.
newtype Pool = Pool (MVar [Worker])

-- A worker thread and its mailbox.
data Worker = Worker ThreadId Mailbox

-- What is handed to a worker: work, or @Nothing@: stop.
type Order = Maybe (IO ())

-- A worker's mailbox: the orders handed to it and not yet taken (the
-- latest first), or that it sleeps, to be woken with an order through the
-- 'MVar'.
data Mailbox = Mailbox (IORef Box) (MVar Order)

data Box = Orders [Order] | Asleep

newMailbox :: IO Mailbox
newMailbox = Mailbox <$> newIORef (Orders []) <*> newEmptyMVar

-- Hand an order to a worker: into its box, or to it if it sleeps.
hand :: Mailbox -> Order -> IO ()
hand (Mailbox box wake) o = do
  asleep <- atomicModifyIORef' box $ \b -> case b of
    Asleep    -> (Orders [], True)
    Orders os -> (Orders (o : os), False)
  when asleep (putMVar wake o)

thePool :: Pool
thePool = unsafePerformIO (Pool <$> newMVar [])
{-# NOINLINE thePool #-}

-- | @readInOrder caps xs@ is @xs@, element for element, for a reader that
-- forces the elements in order (each to weak head normal form).
--
-- With @caps > 1@, when the list itself is first forced, the pool's
-- workers (started as needed, @caps - 1@ of them) are set to evaluate
-- the elements from the front. When the reader forces an element:
--
-- * one no worker has taken, it evaluates itself;
-- * one a worker has finished, it has at once;
-- * one a worker is still evaluating, it does not wait for while any
--   element is left that no one has taken: it evaluates the last of
--   those (ignoring what it raises, which stays with the element), then
--   looks again; when none is left, it looks for the element to be done,
--   for about 'spinTime' (not at all, with more capabilities than
--   processors), then waits for it.
--
-- So the reader can do work of its own between two elements (the
-- simulator moves the robots of one chunk before it reads the next), or
-- before the first (the simulator hands a step's chunks out before its
-- reader has read the snapshot before it), and the workers are not idle
-- meanwhile. With one capability, or fewer than two elements, the list
-- is @xs@ itself.
readInOrder :: forall a. Int -> [a] -> [a]
readInOrder caps xs
  | caps <= 1 = xs
  | otherwise = case xs of
      _ : _ : _ -> unsafePerformIO start
      _         -> xs
  where
    start = do
      let m = length xs
          items = listArray (0, m - 1) xs :: Array Int a
      -- elements [front, back) are those no one has taken
      claims <- newIORef (0 :: Int, m)
      dones <- listArray (0, m - 1) <$> mapM (const (newIORef False)) xs
      let takeFront = atomicModifyIORef' claims $ \c@(f, b) ->
            if f < b then ((f + 1, b), Just f) else (c, Nothing)
          -- element k, if it is the front one
          takeAt k = atomicModifyIORef' claims $ \c@(f, b) ->
            if f == k && f < b then ((f + 1, b), True) else (c, False)
          takeBack = atomicModifyIORef' claims $ \c@(f, b) ->
            if f < b then ((f, b - 1), Just (b - 1)) else (c, Nothing)
          work = takeFront >>= \t -> case t of
            Just k  -> do
              _ <- try (void (evaluate (items ! k))) :: IO (Either SomeException ())
              atomicWriteIORef (dones ! k) True
              work
            Nothing -> pure ()
          -- the reader, before it forces element k
          before k = do
            (f, b) <- readIORef claims
            done <- readIORef (dones ! k)
            if done || k >= b then pure ()        -- finished, or taken by the reader from the back
              else if k == f then takeAt k >>= \t -> if t then pure () else before k
                                                  -- no one's yet: the reader's (k is the front)
              else if k > f then pure ()          -- (read out of order: just force it)
              else takeBack >>= \t -> case t of   -- a worker's, unfinished
                Just j  -> evaluateKeeping (items ! j) >> before k
                Nothing -> void (lookAWhile (readIORef (dones ! k)))
                                                  -- nothing left: look, then wait for it
          view k = unsafePerformIO (before k) `seq` (items ! k)
      queues <- workersFor caps
      mapM_ (`hand` Just work) queues
      pure (map view [0 .. m - 1])

-- Evaluate a value, leaving what it raises with it; an asynchronous
-- exception (Ctrl-C, a timeout) is the caller's and goes on.
evaluateKeeping :: a -> IO ()
evaluateKeeping x = try (void (evaluate x)) >>= \r -> case r of
  Left (e :: SomeException) | Just (_ :: SomeAsyncException) <- fromException e -> throwIO e
  _ -> pure ()

-- The queues of @caps - 1@ workers, one on each capability below @caps@
-- but the caller's: the workers of the pool for capabilities 1 to
-- @caps - 1@, started as needed (the one for the caller's capability is on
-- capability 0). A worker that the runtime has moved to another
-- capability (when the program lowered its number of capabilities) is
-- stopped and started again where it belongs.
workersFor :: Int -> IO [Mailbox]
workersFor caps = do
  let Pool started = thePool
  modifyMVar started $ \ws -> do
    (mine, _) <- threadCapability =<< myThreadId
    let place i = if i == mine then 0 else i
        start i = do q <- newMailbox
                     t <- forkOn (place i) (worker q)
                     pure (Worker t q)
        keep i w@(Worker t q) = do
          (c, _) <- threadCapability t
          if c == place i then pure w else hand q Nothing >> start i
    used <- mapM (\i -> case drop (i - 1) ws of
                           w : _ -> keep i w
                           []    -> start i)
                 [1 .. caps - 1]
    -- (the workers of capabilities above @caps@ stay, idle)
    pure (used ++ drop (caps - 1) ws, [ q | Worker _ q <- used ])

-- Run the orders handed over, in order, until told to stop; out of work,
-- look for more a while ('lookAWhile'), then sleep until woken.
worker :: Mailbox -> IO ()
worker q@(Mailbox box wake) = do
  ready <- lookAWhile (hasOrders <$> readIORef box)
  if ready then takeOrders >>= run else do
    sleep <- atomicModifyIORef' box $ \b -> case b of
      Orders [] -> (Asleep, True)
      _         -> (b, False)
    -- (not asleep: orders came meanwhile)
    if sleep then takeMVar wake >>= \o -> run [o] else takeOrders >>= run
  where
    hasOrders b = case b of
      Orders (_ : _) -> True
      _              -> False
    takeOrders = atomicModifyIORef' box $ \b -> case b of
      Orders os -> (Orders [], reverse os)
      Asleep    -> (b, [])                 -- (only the worker sleeps)
    run [] = worker q
    run (Nothing : _) = pure ()
    -- (the work keeps what its values raise; anything else is dropped)
    run (Just act : os) = (try act :: IO (Either SomeException ())) >> run os

-- How long a worker out of work looks for more before it sleeps, in
-- nanoseconds: 0.2 ms, longer than the simulator's stepping thread takes
-- between two steps' work at 1000 robots (the moves after the last chunk,
-- the next indexes), and short enough not to matter to a program that
-- steps now and then. Also how long the reader looks for an element a
-- worker is finishing (a chunk of robots takes 10-70 microseconds).
spinTime :: Word64
spinTime = 200000

-- Look at a condition until it holds, yielding to the runtime between
-- looks, for about 'spinTime' (a yield may let another thread run a
-- while); not at all (one look) when the program has more capabilities
-- than the machine has processors, where looking takes a processor from
-- a thread that has work. Whether it held.
lookAWhile :: IO Bool -> IO Bool
lookAWhile ready = do
  caps <- getNumCapabilities
  cpus <- getNumProcessors
  t0 <- getMonotonicTimeNSec
  let deadline = if caps <= cpus then t0 + spinTime else t0
      go = ready >>= \r -> if r then pure True else do
        t <- getMonotonicTimeNSec
        if t < deadline then yield >> go else pure False
  go

-- | The number of capabilities now, read each time (a program may change
-- it while it runs): the argument, any value, makes it a function, so
-- that it is not read once as a constant.
capabilitiesNow :: a -> Int
capabilitiesNow k = unsafeDupablePerformIO (k `seq` getNumCapabilities)
{-# NOINLINE capabilitiesNow #-}
