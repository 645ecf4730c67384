{-# LANGUAGE BangPatterns        #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Pipeline
-- Description : A list produced on one thread and consumed, in order, on
--               another.
--
-- 'pipeline' walks a lazy list on the calling thread (the /producer/,
-- which computes each element) and hands the elements, in batches and in
-- order, to a thread of its own (the /consumer/), so that on several
-- capabilities the two work at once: "AFrobRobotSim.Run" computes the
-- simulation's next steps while its outputs (the log, the page, the
-- frames) write the last ones. At most a few batches wait between them, so
-- the memory stays bounded however long the list. The consumer sees
-- exactly the elements, in exactly the order, that a loop doing both on
-- one thread would give it, and stops at the same place:
--
-- * when producing an element fails (or the producer is interrupted, by
--   Ctrl-C say), the consumer still takes every element produced before
--   it, then stops;
-- * when consuming an element fails, the consumer takes no other element,
--   and the producer stops at its next element (it may have computed a
--   few more, which nothing sees).
--
-- So nothing the consumer writes depends on how the two threads are
-- scheduled.
module AFrobRobotSim.Pipeline
  ( pipeline
  , batchFor
  ) where

import           Control.Concurrent     (forkFinally)
import           Control.Concurrent.Chan
import           Control.Concurrent.MVar
import           Control.Concurrent.QSem
import           Control.Exception      (SomeAsyncException, SomeException, bracket, mask_, toException, try)
import           Control.Monad          (unless, when)
import           Data.IORef
import           Data.Maybe             (isJust)
import           Foreign.StablePtr      (freeStablePtr, newStablePtr)

-- | @pipeline batch produce consume xs@: for each element of @xs@ in
-- turn, @produce@ it on the calling thread (forcing what its consumer
-- reads, say), then @consume@ it, with its number (from 0), on a thread
-- of the pipeline's own; the elements are handed over @batch@ at a time
-- (at least 1), and at most two batches wait while the consumer works on
-- a third. Returns when the consumer has finished, with:
--
-- * how the producer ended: @Right ()@ at the end of the list, or the
--   exception that stopped it (thrown by @produce@, or an asynchronous
--   one such as Ctrl-C's 'Control.Exception.UserInterrupt'; one that
--   arrives while the pipeline waits for the consumer at the end makes the
--   consumer skip the elements it has not taken yet, and is returned if
--   the list had ended);
-- * the exception that stopped the consumer, if one did.
--
-- The consumer has then taken, in order, every element produced before
-- the producer stopped, unless it stopped first (at its failing element)
-- or was told to skip.
pipeline :: forall a. Int -> (a -> IO ()) -> (Int -> a -> IO ()) -> [a]
         -> IO (Either SomeException (), Maybe SomeException)
pipeline batch produce consume xs = do
  free     <- newQSem 2                    -- batches that may wait
  queue    <- newChan                      -- batches, in order; [] ends
  failed   <- newIORef Nothing             -- what stopped the consumer
  skip     <- newIORef False               -- told to skip what is left
  pending  <- newIORef []                  -- produced, not handed over (newest first)
  done     <- newEmptyMVar
  let size = max 1 batch
      -- the consumer: each batch in order, until the end marker
      consumer = do
        items <- readChan queue
        unless (null items) $ do
          mapM_ consumeOne items
          signalQSem free
          consumer
      consumeOne (n, x) = do
        stop <- (||) <$> (isJust <$> readIORef failed) <*> readIORef skip
        unless stop $ do
          r <- try (consume n x)
          either (writeIORef failed . Just) pure r
      -- the producer: hand a batch over when it is full (waiting for a
      -- place is interruptible and takes nothing; once it has one, the
      -- batch moves to the queue whatever arrives, neither lost nor sent
      -- twice)
      hand = do
        items <- readIORef pending
        unless (null items) $
          mask_ (waitQSem free >> writeChan queue (reverse items) >> writeIORef pending [])
      producer !_ [] = pure ()
      producer !n (x : rest) = do
        stop <- isJust <$> readIORef failed
        unless stop $ do
          produce x
          modifyIORef' pending ((n, x) :)
          when ((n + 1) `mod` size == 0) hand
          producer (n + 1) rest
      -- wait for the consumer; an asynchronous exception meanwhile makes
      -- it skip the rest (and is kept, if nothing stopped the producer)
      finish ended = do
        r <- try (hand >> writeChan queue [] >> takeMVar done)
        case r of
          Right ()                       -> pure ended
          Left (e :: SomeAsyncException) -> do
            writeIORef skip True
            finish (either Left (const (Left (toException e))) ended)
  -- The queue is kept reachable from outside both threads while they run.
  -- When the producer falls into a loop that the runtime detects as
  -- @<<loop>>@ (a value that depends on itself), the collection that
  -- finds it also finds every thread blocked on what only that one
  -- refers to, and wakes each with an exception: the consumer, waiting
  -- for the next batch, would end at once with
  -- 'Control.Exception.BlockedIndefinitelyOnMVar', before the producer
  -- hands over the batch it was filling, and those elements would be lost
  -- (on several capabilities, where the consumer waits more often).
  -- (the pointer freed whatever ends the run)
  ended' <- bracket (newStablePtr queue) freeStablePtr $ \_ -> do
    _ <- forkFinally consumer (\_ -> putMVar done ())
    ended <- try (producer 0 xs)
    finish ended
  stopped <- readIORef failed
  pure (ended', stopped)

-- | A batch size for elements of @k@ parts each (robots in a snapshot,
-- say): 16 elements, or fewer so that a batch holds about 4096 parts (at
-- least one element). Small elements are handed over in batches, so that
-- the hand-over (a thread waking up on another core) costs little beside
-- them; large ones one at a time, so that the few waiting take little
-- memory.
batchFor :: Int -> Int
batchFor k = max 1 (min 16 (4096 `div` max 1 k))
