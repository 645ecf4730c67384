{-# LANGUAGE ExistentialQuantification #-}
-- No full laziness: it would float the reading of the number of
-- capabilities out of 'capabilitiesNow' as a constant, read only once.
{-# OPTIONS_GHC -fno-full-laziness #-}
-- |
-- Module      : AFrobRobotSim.Workers
-- Description : A fixed pool of worker threads that evaluate pure values
--               in parallel, for the simulator's step.
--
-- 'forceAll' evaluates a list of values (to weak head normal form) in
-- order, and, on several capabilities (@+RTS -N@ in a program built
-- @-threaded@), lets worker threads evaluate the later ones meanwhile.
--
-- Why threads and not sparks ('GHC.Conc.par'): an idle capability sleeps
-- until the running thread next enters the scheduler, which with a large
-- allocation area can be a whole timer tick (20 ms) away, so most sparks
-- of a step of a few milliseconds fizzle. A worker blocked on an 'MVar'
-- is woken as soon as a value is handed to it.
--
-- The pool is made the first time it is needed: one worker per capability
-- but the caller's, pinned to it ('forkOn'), more when the program enables
-- more capabilities. Each worker takes values from one queue and
-- evaluates them, ignoring what they raise: the value stays a thunk that
-- raises the same exception when 'forceAll' (or anyone) forces it. A
-- value that the calling thread reaches while a worker is evaluating it
-- is waited for (it is a black hole, when the module that builds it is
-- compiled with @-feager-blackholing@, as "AFrobRobotSim.Simulator" is),
-- not evaluated twice; one it reaches first is evaluated by the caller,
-- and the worker then finds it evaluated. So the result, and which
-- exception is raised first, are those of evaluating the list in order
-- on one thread.
module AFrobRobotSim.Workers
  ( forceAll
  , capabilitiesNow
  ) where

import           Control.Concurrent      (forkOn, myThreadId, threadCapability)
import           Control.Concurrent.Chan (Chan, newChan, readChan, writeChan)
import           Control.Concurrent.MVar (MVar, modifyMVar_, newMVar)
import           Control.Exception       (SomeException, evaluate, try)
import           Control.Monad           (forM_, forever, void)
import           GHC.Conc                (getNumCapabilities)
import           GHC.IO                  (unsafeDupablePerformIO, unsafePerformIO)

-- A value to evaluate, whatever its type.
data Job = forall a. Job a

-- The queue of values and how many workers have been started.
data Pool = Pool (Chan Job) (MVar Int)

thePool :: Pool
thePool = unsafePerformIO (Pool <$> newChan <*> newMVar 0)
{-# NOINLINE thePool #-}

-- | @forceAll caps xs@ evaluates every element of @xs@ to weak head normal
-- form, in order, and is then @()@; with @caps > 1@ it first hands every
-- element but the first, the last first, to the pool's workers (started
-- as needed, @caps - 1@ of them), so that the caller and the workers
-- meet in the middle. An exception is that of the first element that
-- raises one, as when evaluating in order on one thread.
forceAll :: Int -> [a] -> ()
forceAll caps xs
  | caps <= 1 = inOrder xs
  | otherwise = handOut caps (reverse (drop 1 xs)) `seq` inOrder xs
  where
    inOrder = foldr seq ()

-- Hand values to the workers (once per call: not duplicated).
handOut :: Int -> [a] -> ()
handOut caps xs = unsafePerformIO $ do
  let Pool q started = thePool
  modifyMVar_ started $ \k -> do
    -- pinned to the capabilities other than the caller's (the caller, the
    -- main thread usually, stays where it is)
    (mine, _) <- threadCapability =<< myThreadId
    forM_ [k + 1 .. caps - 1] $ \i -> forkOn (if i == mine then 0 else i) (worker q)
    pure (max k (caps - 1))
  mapM_ (writeChan q . Job) xs
{-# NOINLINE handOut #-}

worker :: Chan Job -> IO ()
worker q = forever $ do
  Job x <- readChan q
  -- what the value raises, it keeps, for whoever forces it next
  (try (void (evaluate x)) :: IO (Either SomeException ())) >> pure ()

-- | The number of capabilities now, read each time (a program may change
-- it while it runs): the argument, any value, makes it a function, so
-- that it is not read once as a constant.
capabilitiesNow :: a -> Int
capabilitiesNow k = unsafeDupablePerformIO (k `seq` getNumCapabilities)
{-# NOINLINE capabilitiesNow #-}
