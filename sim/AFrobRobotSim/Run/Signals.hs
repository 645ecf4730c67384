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
-- loop over unboxed numbers) keeps its capability from the runtime: no
-- collection can start, and with one capability no handler can run, so
-- the run could not be stopped. In a program built @-threaded@ (the
-- project's are), a watchdog thread in C (@cbits/signals.c@) is woken by
-- each @SIGTERM@, before the runtime is asked to act, and waits for the
-- runtime to show that it can: the Haskell handler completes a
-- collection, which needs every capability, before it stops the run. A
-- runtime that has not within 'stuckGrace' (10 s) is stuck: the program
-- then writes to standard error that it is, and why that may be, and
-- ends by @SIGTERM@ (exit status 143 in a shell), without the run's
-- outputs (the frames and log lines already written are kept; on several
-- capabilities the frame being written then, held up by the collection
-- the loop keeps from starting, is left as its temporary file,
-- @frame-NNNNNN.ppm.tmp@; the replay page's temporary files are gone
-- with the program: each is removed from @TMPDIR@ as soon as it is made).
-- A run that is merely slow to stop (its log written into a pipe nobody
-- reads for a while, a video being assembled) has a runtime that acts,
-- and is not cut short. No other signal is used, and one run is watched at a time (a
-- second run at once in the same program gets no watchdog of its own,
-- and keeps the first's in front of its handler). The runtime is watched
-- until the stop has reached the run's thread, so a loop entered after
-- the signal has been taken (before the stop arrives, or while the run's
-- thread holds it off) ends the same way. A program built without
-- @-threaded@ gets no watchdog: its runtime waits, whole,
-- for a blocking call such as the video's assembly, and could not be
-- told from a stuck one. Ctrl-C (@SIGINT@) has no watchdog, in any
-- program: a first Ctrl-C does not stop such a loop; a second ends the
-- program at once, writing nothing, as the runtime does (use @SIGTERM@,
-- @kill@, to get the message and exit status 143). Code compiled with
-- @-fno-omit-yields@ can be stopped where it loops, and then writes its
-- outputs.
module AFrobRobotSim.Run.Signals
  ( Stopper
  , interruptible
  , signalReceived
  , finishing
  , stuckGrace
  ) where

import           Control.Concurrent (ThreadId, mkWeakThreadId, myThreadId)
import           System.Mem.Weak    (Weak, deRefWeak)
import           Data.IORef
#if !defined(mingw32_HOST_OS)
import           Control.Concurrent (forkIO, rtsSupportsBoundThreads, throwTo)
import           Control.Concurrent.MVar (newEmptyMVar, putMVar, readMVar, takeMVar)
import           Control.Monad      (unless)
import           Control.Exception  (AsyncException (UserInterrupt), finally)
import           Foreign.C.String   (CString, withCString)
import           Foreign.C.Types    (CInt (..))
import           System.Environment (getProgName)
import           System.Mem         (performMinorGC)
import           System.Posix.Signals (Handler (Catch), installHandler, sigTERM)
import           System.Timeout     (timeout)

-- Whether the system ignores a signal now (cbits/signals.c).
foreign import ccall unsafe "afrp_signal_ignored"
  signalIgnored :: CInt -> IO CInt

-- The watchdog in front of the SIGTERM handler installed now, with its
-- grace and message (cbits/signals.c): 0 when it is armed.
foreign import ccall unsafe "afrp_term_grace_arm"
  graceArm :: CInt -> CString -> IO CInt

-- A handler at work, the runtime seen to act (a collection completed):
-- the watchdog's countdown begins anew, and the runtime stays expected to
-- act until the handler's 'graceEnd'.
foreign import ccall unsafe "afrp_term_grace_begin"
  graceBegin :: IO ()

-- The runtime seen to act again (the heartbeat's collection): the
-- countdown begins anew.
foreign import ccall unsafe "afrp_term_grace_renew"
  graceRenew :: IO ()

-- A handler's work done: when no other is at work, the watchdog waits for
-- the next signal.
foreign import ccall unsafe "afrp_term_grace_end"
  graceEnd :: IO ()

-- The watchdog put back in front of the runtime's handler, if it is
-- armed and that handler was installed again since.
foreign import ccall unsafe "afrp_term_grace_rewrap"
  graceRewrap :: IO ()

-- The watchdog disarmed, SIGTERM's handler as it was before it.
foreign import ccall unsafe "afrp_term_grace_remove"
  graceRemove :: IO ()
#endif

-- | How long the runtime may take to act on a @SIGTERM@ before the
-- program ends without its outputs (see the module's documentation): 10
-- seconds. A runtime that can act does in milliseconds.
stuckGrace :: Int
stuckGrace = 10

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
    prog <- getProgName
    -- (no watchdog without -threaded, or while another run has it: the
    -- run is then stopped as before)
    watched <- if not rtsSupportsBoundThreads then pure False
               else (== 0) <$> withCString (stuckMessage prog) (graceArm (fromIntegral stuckGrace))
    -- (a run not watched, another being so, keeps the other's watchdog
    -- in front of the handlers it installs)
    unless watched graceRewrap
    act stopper `finally` (if watched then graceRemove >> () <$ installHandler sigTERM old Nothing
                           else installHandler sigTERM old Nothing >> graceRewrap)
#else
  act stopper
#endif

#if !defined(mingw32_HOST_OS)
-- A signal received: noted (the first one), and the run stopped unless it
-- is writing its outputs or a signal has stopped it already.
--
-- The watchdog is told that the runtime has acted once a collection has
-- completed: it has stopped every capability, so none is held by a loop.
-- A stop is then watched until it has reached the run's thread: a loop
-- entered after that collection (or a thread that takes the stop only
-- once it unmasks, and loops) would keep 'throwTo' waiting for ever. So
-- the runtime stays expected to act from before the stop is decided (the
-- run's thread may see it decided at once) until it has been delivered,
-- with a heartbeat that renews the countdown after each collection it
-- completes, every second; a runtime held by a loop completes none, and
-- the grace runs out. A later signal's handler, which stops nothing, does
-- not end that watch ('graceEnd' ends it when no handler is at work).
received :: Stopper -> Int -> IO ()
received (Stopper t phase) k = do
  performMinorGC
  graceBegin
  stop <- atomicModifyIORef' phase $ \(done, got) -> case got of
    Nothing -> ((done, Just k), not done)
    Just _  -> ((done, got), False)
  target <- deRefWeak t
  case target of
    Just thread | stop -> do
      delivered <- newEmptyMVar
      beaten <- newEmptyMVar
      _ <- forkIO (heartbeat delivered `finally` putMVar beaten ())
      throwTo thread UserInterrupt
        `finally` (putMVar delivered () >> takeMVar beaten >> graceEnd)
    _ -> graceEnd
  where
    heartbeat delivered = do
      done <- timeout 1000000 (readMVar delivered)
      case done of
        Just () -> pure ()
        Nothing -> performMinorGC >> graceRenew >> heartbeat delivered

-- What a program stuck past the grace says, @prog@ its name.
stuckMessage :: String -> String
stuckMessage prog =
  prog ++ ": SIGTERM received, but the runtime has not been able to act on it within " ++ show stuckGrace
  ++ " s: a thread, most likely a controller's step, has been computing all that time without allocating "
  ++ "(an endless loop over unboxed numbers?), which keeps the runtime from stopping the run. Ending now, "
  ++ "without the run's outputs (the frames and log lines written so far are kept). A controller compiled "
  ++ "with -fno-omit-yields can be stopped where it loops.\n"
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
