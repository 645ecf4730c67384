{-# LANGUAGE CPP                      #-}
{-# LANGUAGE ForeignFunctionInterface #-}
-- |
-- Module      : AFrobRobotSim.Run.Signals
-- Description : The signal that ends a run taken as Ctrl-C is.
--
-- A run stopped by Ctrl-C writes what it has (the log's summary, the SVG,
-- the page, the result line) and says it was interrupted. A run is also
-- stopped by @SIGTERM@ (@kill@, @timeout@, a batch system's time limit,
-- GNU parallel's halt), which by default ends a program at once, writing
-- nothing. 'interruptible' makes it stop a run as Ctrl-C does, and
-- ignores it while the run's outputs are being written (the video's
-- assembly by ffmpeg included), after which the run ends with its exit
-- code. @SIGHUP@ (a closed terminal) is left as it is: a run that can no
-- longer write to its terminal could not say what it wrote, and @nohup@
-- makes a program ignore it.
--
-- One window remains: a @SIGTERM@ that comes after a run's last step and
-- before its outputs are begun (a few instructions), or while the run is
-- being set up, ends the program as Ctrl-C would there.
--
-- A controller caught in an endless loop that never allocates (a tight
-- loop over unboxed numbers) keeps its processor from the runtime, which
-- then runs no handler: neither @SIGTERM@ nor a first Ctrl-C stops it (a
-- second Ctrl-C ends the program at once, writing nothing; @SIGKILL@
-- too). Code compiled with @-fno-omit-yields@ can be stopped.
module AFrobRobotSim.Run.Signals
  ( Stopper
  , interruptible
  , signalReceived
  , finishing
  ) where

import           Control.Concurrent (ThreadId, mkWeakThreadId, myThreadId)
import           System.Mem.Weak    (Weak, deRefWeak)
import           Data.IORef
#if !defined(mingw32_HOST_OS)
import           Control.Concurrent (throwTo)
import           Control.Exception  (AsyncException (UserInterrupt), finally)
import           Foreign.C.Types    (CInt (..))
import           System.Posix.Signals (Handler (Catch), installHandler, sigTERM)

-- Whether the system ignores a signal now (cbits/signals.c).
foreign import ccall unsafe "afrp_signal_ignored"
  signalIgnored :: CInt -> IO CInt
#endif

-- | What 'interruptible' gives its action: which thread a signal stops,
-- whether the run is writing its outputs ('finishing'), and the number of
-- the first signal received, if any.
--
-- The thread is held weakly: held strongly (by the signal's handler), a
-- thread blocked for ever (a controller whose output depends on itself
-- with no delay, which the runtime reports as @\<\<loop\>\>@ to a thread
-- nothing else can wake) would never be found so, and the run would hang.
data Stopper = Stopper (Weak ThreadId) (IORef (Bool, Maybe Int))

-- | @interruptible act@ runs @act@ with @SIGTERM@ throwing
-- 'UserInterrupt' to the thread that called it (once 'finishing' has
-- been called, it is noted and ignored), and restores its handler after.
-- A program that was started with @SIGTERM@ ignored keeps ignoring it.
-- Elsewhere than on a POSIX system, @act@ runs as it is.
interruptible :: (Stopper -> IO a) -> IO a
interruptible act = do
  me <- myThreadId >>= mkWeakThreadId
  phase <- newIORef (False, Nothing)
  let stopper = Stopper me phase
#if !defined(mingw32_HOST_OS)
  ignored <- (/= 0) <$> signalIgnored sigTERM
  if ignored then act stopper else do   -- (as the program was started: nohup, a batch system)
    old <- installHandler sigTERM (Catch (received stopper (fromIntegral sigTERM))) Nothing
    act stopper `finally` installHandler sigTERM old Nothing
#else
  act stopper
#endif

#if !defined(mingw32_HOST_OS)
-- A signal received: noted (the first one), and the run stopped unless it
-- is writing its outputs or a signal has stopped it already.
received :: Stopper -> Int -> IO ()
received (Stopper t phase) k = do
  stop <- atomicModifyIORef' phase $ \(done, got) -> case got of
    Nothing -> ((done, Just k), not done)
    Just _  -> ((done, got), False)
  target <- deRefWeak t
  case target of
    Just thread | stop -> throwTo thread UserInterrupt
    _                  -> pure ()
#endif

-- | The number of the first signal received: the one that stopped the
-- run, or one that came while it wrote its outputs ('Nothing' for none,
-- or for Ctrl-C, which the runtime delivers itself).
signalReceived :: Stopper -> IO (Maybe Int)
signalReceived (Stopper _ phase) = snd <$> readIORef phase

-- | From now on a signal is noted and ignored: the run is writing its
-- outputs.
finishing :: Stopper -> IO ()
finishing (Stopper _ phase) = atomicModifyIORef' phase (\(_, got) -> ((True, got), ()))
