{-# LANGUAGE CPP #-}
-- |
-- Module      : AFrobRobotSim.Run.Signals
-- Description : The signals that end a run taken as Ctrl-C is.
--
-- A run stopped by Ctrl-C writes what it has (the log's summary, the SVG,
-- the page, the result line) and says it was interrupted. A run is also
-- stopped by @SIGTERM@ (@kill@, @timeout@, a batch system's time limit,
-- GNU parallel's halt) and @SIGHUP@ (a closed terminal or SSH session),
-- which by default end a program at once, writing nothing. 'interruptible'
-- makes them stop a run as Ctrl-C does, and ignores them while the run's
-- outputs are being written.
module AFrobRobotSim.Run.Signals
  ( Stopper
  , interruptible
  , stopNow
  , finishing
  ) where

import           Control.Concurrent (ThreadId, myThreadId, throwTo)
import           Control.Exception  (AsyncException (UserInterrupt), finally)
import           Data.IORef
#if !defined(mingw32_HOST_OS)
import           Control.Monad      (zipWithM_)
import           System.Posix.Signals (Handler (Catch), Signal, installHandler, sigHUP, sigTERM)
#endif

-- | What 'interruptible' gives its action: which thread a signal stops,
-- and the signal received so far, if any.
data Stopper = Stopper ThreadId (IORef Phase)

data Phase = Running | Received Int | Finishing (Maybe Int)

-- | @interruptible act@ runs @act@ with @SIGTERM@ and @SIGHUP@ throwing
-- 'UserInterrupt' to the thread that called it (once 'finishing' has
-- been called, they are noted and ignored), and restores their handlers
-- after. Elsewhere than on a POSIX system, @act@ runs as it is.
interruptible :: (Stopper -> IO a) -> IO a
interruptible act = do
  me <- myThreadId
  phase <- newIORef Running
  let stopper = Stopper me phase
#if !defined(mingw32_HOST_OS)
  let signals = [sigTERM, sigHUP] :: [Signal]
      on s = installHandler s (Catch (received stopper (fromIntegral s))) Nothing
  olds <- mapM on signals
  act stopper `finally` zipWithM_ (\s o -> installHandler s o Nothing) signals olds
#else
  act stopper
#endif

-- A signal received: stop the run, or note it while the outputs are
-- written.
received :: Stopper -> Int -> IO ()
received (Stopper t phase) k = do
  stop <- atomicModifyIORef' phase $ \p -> case p of
    Running       -> (Received k, True)
    Received j    -> (Received j, False)   -- (the run is stopping already)
    Finishing got -> (Finishing (maybe (Just k) Just got), False)
  if stop then throwTo t UserInterrupt else pure ()

-- | The number of the signal that stopped the run ('Nothing' for none, or
-- for Ctrl-C, which the runtime delivers itself).
stopNow :: Stopper -> IO (Maybe Int)
stopNow (Stopper _ phase) = readIORef phase >>= \p -> pure $ case p of
  Running       -> Nothing
  Received k    -> Just k
  Finishing got -> got

-- | From now on the signals are noted and ignored: the run is writing its
-- outputs.
finishing :: Stopper -> IO ()
finishing (Stopper _ phase) = atomicModifyIORef' phase $ \p -> case p of
  Running     -> (Finishing Nothing, ())
  Received k  -> (Finishing (Just k), ())
  Finishing g -> (Finishing g, ())
