{-# LANGUAGE CPP                      #-}
{-# LANGUAGE ScopedTypeVariables      #-}
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
-- code. A first Ctrl-C that comes then is ignored too ('whileFinishing'),
-- and the run ends with 130; either signal so ignored is said on
-- standard error once the outputs are written. @SIGHUP@ (a closed
-- terminal) is left as it is: a run that can no longer write to its
-- terminal could not say what it wrote, and @nohup@ makes a program
-- ignore it.
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
-- each @SIGTERM@, and by Ctrl-C (@SIGINT@), before the runtime is asked
-- to act, and waits for the runtime to show that it can: the Haskell
-- handler completes a collection, which needs every capability, before
-- it stops the run. A runtime that has not within 'stuckGrace' (10 s) is
-- stuck: the program then writes to standard error that it is, and why
-- that may be, and ends by the signal it was sent (exit status 143 for
-- @SIGTERM@, 130 for Ctrl-C, in a shell), without the run's outputs (the
-- frames and log lines already written are kept; on several
-- capabilities the frame being written then, held up by the collection
-- the loop keeps from starting, is left as its temporary file,
-- @frame-NNNNNN.ppm.tmp@; the replay page's temporary files are gone
-- with the program: each is removed from @TMPDIR@ as soon as it is made).
-- A run that is merely slow to stop (its log written into a pipe nobody
-- reads for a while, a video being assembled) has a runtime that acts,
-- and is not cut short. No other signal is used, and one run is watched
-- at a time (a second run at once in the same program gets no watchdog
-- of its own, and keeps the first's in front of its handler). The
-- runtime is watched until the stop has reached the thread it is thrown
-- to, so a loop entered after the signal has been taken (before the stop
-- arrives, or while that thread holds it off) ends the same way.
--
-- Ctrl-C is the runtime's own: its handler, installed as the program
-- starts, throws 'UserInterrupt' to the main thread, and is called once
-- (the system puts the signal's default action back as it calls it), so
-- that a second Ctrl-C ends the program at once, writing nothing. That is
-- kept: the runtime's Haskell action is run as it was, only watched (its
-- collection first, and until its throw has been delivered), through
-- "GHC.Conc.Signal"'s table of actions, without installing a handler
-- again (which would have made Ctrl-C's handler stay after the first
-- one), and the watchdog's handler in front of the runtime's calls it
-- for the first Ctrl-C only. A second Ctrl-C during a watched run still
-- ends the program at once, by @SIGINT@ (130), without the outputs not
-- yet written, but now says so on standard error. A program that has
-- replaced that handler with its own ('installHandler' of a 'Catch') or
-- removed it ('Ignore', 'Default') gets no watchdog for it, and its own
-- handling (one of its own called once, a 'CatchOnce', is watched as the
-- runtime's is). (A program started with Ctrl-C ignored, as a non-interactive
-- shell starts its background jobs, still takes it: the runtime installs
-- its handler whatever the program started with, where @SIGTERM@ stays
-- ignored.) On several capabilities, a Ctrl-C whose collection cannot
-- complete (a thread other than the main one looping without allocating)
-- ends the program at the grace, as @SIGTERM@ does: before, the main
-- thread was sent its 'UserInterrupt' at once. The watchdog's messages
-- are written only as far as standard error takes them (the stuck run's
-- waiting a second at most for each part it writes, one part in practice;
-- the second Ctrl-C's not waiting): a pipe nobody reads does not keep the
-- program from ending. Neither
-- signal is watched in a program built without @-threaded@: its runtime
-- waits, whole, for a blocking call such as the video's assembly, and
-- could not be told from a stuck one. Code compiled with
-- @-fno-omit-yields@ can be stopped where it loops, and then writes its
-- outputs.
module AFrobRobotSim.Run.Signals
  ( Stopper
  , interruptible
  , signalReceived
  , whileFinishing
  , stuckGrace
  ) where

import           Control.Concurrent (ThreadId, forkIOWithUnmask, killThread, mkWeakThreadId, myThreadId)
import           Control.Concurrent.MVar (newEmptyMVar, putMVar, takeMVar)
import           Control.Exception  (AsyncException (UserInterrupt), SomeException, allowInterrupt, catch, fromException,
                                     mask_, throwIO, try)
import           System.Mem.Weak    (Weak, deRefWeak)
import           Data.IORef
#if !defined(mingw32_HOST_OS)
import           Control.Concurrent (forkIO, rtsSupportsBoundThreads, throwTo)
import           Control.Concurrent.MVar (readMVar)
import           Control.Monad      (unless)
import           Control.Exception  (finally, uninterruptibleMask, uninterruptibleMask_)
import           Data.Dynamic       (toDyn)
import           Foreign.C.String   (CString, withCString)
import           Foreign.C.Types    (CInt (..))
import           GHC.Conc.Signal    (setHandler)
import           System.Environment (getProgName)
import           System.Mem         (performMinorGC)
import           System.Posix.Signals (Handler (Catch), installHandler, sigINT, sigTERM)
import           System.Timeout     (timeout)

-- Whether the system ignores a signal now (cbits/signals.c).
foreign import ccall unsafe "afrp_signal_ignored"
  signalIgnored :: CInt -> IO CInt

-- The watchdogs (cbits/signals.c), one for SIGTERM and one for SIGINT,
-- each function taking the signal first.

-- The signal's watchdog in front of its handler installed now, with its
-- grace, its message, and the message of a second signal to a handler
-- called once (the runtime's SIGINT): 0 when it is armed.
foreign import ccall unsafe "afrp_grace_arm"
  graceArm :: CInt -> CInt -> CString -> CString -> IO CInt

-- A handler at work, the runtime seen to act (a collection completed):
-- the watchdog's countdown begins anew, and the runtime stays expected to
-- act until the handler's 'graceEnd'.
foreign import ccall unsafe "afrp_grace_begin"
  graceBegin :: CInt -> IO ()

-- The runtime seen to act again (the heartbeat's collection): the
-- countdown begins anew.
foreign import ccall unsafe "afrp_grace_renew"
  graceRenew :: CInt -> IO ()

-- A handler's work done: when no other is at work, the watchdog waits for
-- the next signal.
foreign import ccall unsafe "afrp_grace_end"
  graceEnd :: CInt -> IO ()

-- The watchdog put back in front of the runtime's handler, if it is
-- armed and that handler was installed again since.
foreign import ccall unsafe "afrp_grace_rewrap"
  graceRewrap :: CInt -> IO ()

-- The watchdog disarmed, the signal's handler as it was before it (or
-- its default action, should a SIGINT have reset it).
foreign import ccall unsafe "afrp_grace_remove"
  graceRemove :: CInt -> IO ()
#endif

-- | How long the runtime may take to act on a @SIGTERM@ or a Ctrl-C
-- before the program ends without its outputs (see the module's
-- documentation): 10 seconds. A runtime that can act does in milliseconds.
stuckGrace :: Int
stuckGrace = 10

-- | What 'interruptible' gives its action: which thread a signal stops,
-- whether the run is writing its outputs ('whileFinishing'), and the number of
-- the first signal received, if any.
--
-- The thread is held weakly: held strongly (by the signal's handler), a
-- thread blocked for ever (a controller whose output depends on itself
-- with no delay, which the runtime reports as @\<\<loop\>\>@ to a thread
-- nothing else can wake) would never be found so, and the run would hang.
data Stopper = Stopper (Weak ThreadId) (IORef (Bool, Maybe Int))

-- | @interruptible act@ runs @act@ with @SIGTERM@ throwing
-- 'UserInterrupt' to the thread that called it (once 'whileFinishing' has
-- been called, it is noted and ignored), and restores its handler after.
-- A program that was started with @SIGTERM@ ignored keeps ignoring it.
-- Ctrl-C is left to the runtime's handler (which throws 'UserInterrupt'
-- to the main thread), only watched. A program built @-threaded@ ends
-- after 'stuckGrace', with a message, when its runtime cannot act on
-- either signal (see the module's documentation). Elsewhere than on a
-- POSIX system, @act@ runs as it is.
interruptible :: (Stopper -> IO a) -> IO a
interruptible act = do
  me <- myThreadId >>= mkWeakThreadId
  phase <- newIORef (False, Nothing)
  let stopper = Stopper me phase
#if !defined(mingw32_HOST_OS)
  prog <- getProgName
  watchingCtrlC prog $ do
    ignored <- (/= 0) <$> signalIgnored sigTERM
    if ignored then act stopper else do   -- (as the program was started: nohup, a batch system)
      old <- installHandler sigTERM (Catch (received stopper (fromIntegral sigTERM))) Nothing
      -- (no watchdog without -threaded, or while another run has it: the
      -- run is then stopped as before)
      watched <- if not rtsSupportsBoundThreads then pure False
                 else (== 0) <$> arm sigTERM (stuckMessage "SIGTERM" prog) ""
      -- (a run not watched, another being so, keeps the other's watchdog
      -- in front of the handlers it installs)
      unless watched (graceRewrap sigTERM)
      act stopper `finally` (if watched then graceRemove sigTERM >> () <$ installHandler sigTERM old Nothing
                             else installHandler sigTERM old Nothing >> graceRewrap sigTERM)
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
  graceBegin sigTERM
  stop <- atomicModifyIORef' phase $ \(done, got) -> case got of
    Nothing -> ((done, Just k), not done)
    Just _  -> ((done, got), False)
  target <- deRefWeak t
  case target of
    Just thread | stop -> watchedUntilDone sigTERM (throwTo thread UserInterrupt)
    _ -> graceEnd sigTERM

-- @watchedUntilDone sig deliver@, in a handler of @sig@ that has begun
-- ('graceBegin'): @deliver@ (a stop thrown to a thread, which may wait
-- for that thread), with a heartbeat that renews the watchdog's countdown
-- after each collection it completes, every second, until @deliver@ is
-- done; then the handler's 'graceEnd'.
watchedUntilDone :: CInt -> IO () -> IO ()
watchedUntilDone sig deliver = do
  delivered <- newEmptyMVar
  beaten <- newEmptyMVar
  _ <- forkIO (heartbeat delivered `finally` putMVar beaten ())
  deliver `finally` (putMVar delivered () >> takeMVar beaten >> graceEnd sig)
  where
    heartbeat delivered = do
      done <- timeout 1000000 (readMVar delivered)
      case done of
        Just () -> pure ()
        Nothing -> performMinorGC >> graceRenew sig >> heartbeat delivered

-- Ctrl-C watched while @body@ runs, in a program built -threaded: the
-- runtime's Haskell action for SIGINT (the one the program started with,
-- which throws 'UserInterrupt' to the main thread) run as it was, but
-- after a collection and until it is done, as 'received' does its stop,
-- and the watchdog in front of the runtime's handler (cbits/signals.c).
-- The action is swapped in the runtime's table ('setHandler'), not
-- installed again: 'installHandler' would give back the runtime's handler
-- as one that stays after its first signal ('Catch'), and put it back so,
-- where the runtime's is called once (a second Ctrl-C ends the program).
-- The table's entry is swapped first and the watchdog armed after, so
-- that a Ctrl-C between the two is watched whole or not at all; without a
-- watchdog (another run has it, or there is no runtime's handler to stand
-- in front of: one replaced, removed, ignored, or called already) the
-- entry is put back at once and @body@ runs as before. (Masked, so that
-- not even the wait for the table's lock is interrupted, until the entry
-- is sure to be put back: an exception between would leave a wrapper
-- waiting for ever.)
watchingCtrlC :: String -> IO a -> IO a
watchingCtrlC prog body
  | not rtsSupportsBoundThreads = body
  | otherwise = uninterruptibleMask $ \restore -> do
      previous <- newEmptyMVar
      -- (the runtime's action is known once the swap has given it back:
      -- a Ctrl-C that comes between runs its wrapper, which waits for it)
      let watchedAction info = readMVar previous >>= mapM_ (\(action, _) -> do
            performMinorGC
            graceBegin sigINT
            watchedUntilDone sigINT (action info))
      old <- setHandler sigINT (Just (watchedAction, toDyn ()))
      putMVar previous old
      armed <- case old of
        Nothing -> pure False
        Just (_, described) -> do
          -- (described as the runtime's, for an 'installHandler' during the
          -- run, which gives back what it replaces)
          _ <- setHandler sigINT (Just (watchedAction, described))
          (== 0) <$> arm sigINT (stuckMessage "Ctrl-C (SIGINT)" prog) (againMessage prog)
      if not armed then setHandler sigINT old >> restore body
      else restore body `finally` uninterruptibleMask_ (graceRemove sigINT >> () <$ setHandler sigINT old)

-- @arm sig stuck again@: 'graceArm' with the grace and the two messages.
arm :: CInt -> String -> String -> IO CInt
arm sig stuck again =
  withCString stuck $ \stuck' -> withCString again $ \again' -> graceArm sig (fromIntegral stuckGrace) stuck' again'

-- What a second Ctrl-C during a watched run says, @prog@ the program's
-- name.
againMessage :: String -> String
againMessage prog =
  prog ++ ": Ctrl-C (SIGINT) received a second time: ending now, without waiting for the run to stop, "
  ++ "and without writing the outputs not yet written (the frames and log lines written so far are kept). A first "
  ++ "Ctrl-C stops the run and writes its outputs.\n"

-- What a program stuck past the grace says, @signal@ the signal it was
-- sent, @prog@ its name.
stuckMessage :: String -> String -> String
stuckMessage signal prog =
  prog ++ ": " ++ signal ++ " received, but the runtime has not been able to act on it within " ++ show stuckGrace
  ++ " s: a thread, most likely a controller's step, has been computing all that time without allocating "
  ++ "(an endless loop over unboxed numbers?), which keeps the runtime from stopping the run. Ending now, "
  ++ "without the run's outputs (the frames and log lines written so far are kept). A controller compiled "
  ++ "with -fno-omit-yields can be stopped where it loops.\n"
#endif

-- | The number of the first signal received: the one that stopped the
-- run, or one that came while it wrote its outputs ('Nothing' for none,
-- or for a Ctrl-C that stopped the run, which the runtime delivers
-- itself; one that came while the outputs were written, 'whileFinishing',
-- is noted, as 2).
signalReceived :: Stopper -> IO (Maybe Int)
signalReceived (Stopper _ phase) = snd <$> readIORef phase

-- From now on a @SIGTERM@ is noted and ignored: the run is writing its
-- outputs (the first thing 'whileFinishing' does).
finishing :: Stopper -> IO ()
finishing (Stopper _ phase) = atomicModifyIORef' phase (\(_, got) -> ((True, got), ()))

-- | @whileFinishing stopper write@: from now on a @SIGTERM@ is noted and
-- ignored; @write@ (the run's outputs written) is run to its end, a
-- @SIGTERM@ or a first Ctrl-C that comes
-- meanwhile noted and not obeyed, and what it gives; what it throws is
-- thrown on. @write@ runs on a thread of its
-- own while this one waits for it: a Ctrl-C, which the runtime's handler
-- throws to the main thread as 'UserInterrupt', reaches only the waiting
-- thread, which notes it (as 2, Ctrl-C's number, when no signal has been
-- noted: 'signalReceived') and waits on. (Thrown to the thread that
-- writes, it would cut the writing short: the file under way left as it
-- was, the outputs after it not written, an earlier run's files in their
-- place, and no summary.) A second Ctrl-C still ends the program at once
-- (the runtime's handler is called once); any other exception thrown to
-- the waiting thread stops @write@ and is thrown on. Called on a thread
-- other than the main one, it leaves a Ctrl-C to the main thread, as the
-- run's loop does.
whileFinishing :: Stopper -> IO a -> IO a
whileFinishing stopper@(Stopper _ phase) write = mask_ $ do
  finishing stopper
  done <- newEmptyMVar
  writer <- forkIOWithUnmask $ \unmask -> try (unmask write) >>= putMVar done
  let noted = atomicModifyIORef' phase (\(fin, got) -> ((fin, maybe (Just 2) Just got), ()))
      waited = takeMVar done `catch` \(e :: SomeException) -> case fromException e of
        Just UserInterrupt -> noted >> waited
        _                  -> killThread writer >> throwIO e
  result <- waited
  -- (a Ctrl-C that came as the writing ended, held off until now by the
  -- mask: noted, not thrown on after it)
  allowInterrupt `catch` \e -> if e == UserInterrupt then noted else throwIO e
  either (\(e :: SomeException) -> throwIO e) pure result
