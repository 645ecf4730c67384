{-# LANGUAGE ScopedTypeVariables #-}
-- | "AFrobRobotSim.Pipeline": the consumer takes exactly the elements a
-- one-thread loop would, in order, with their numbers, on one capability
-- and on two; it stops where that loop would when producing or consuming
-- fails (the producer then stops too, on an endless list); and the
-- producer stays at most a few batches ahead; an interrupt while the
-- consumer catches up makes it skip the rest.
module AFrobRobotSim.PipelineSpec (spec) where

import           Control.Concurrent (forkIO, myThreadId, threadDelay, throwTo)
import           Control.Concurrent.MVar
import           Control.Exception (AsyncException (..), ErrorCall (..), fromException, throwIO)
import           Control.Monad     (forM_, when)
import           Data.IORef
import           GHC.Conc          (ThreadStatus (..), threadStatus)
import           Test.Hspec

import           AFrobRobotSim.Pipeline
import           TestUtil (withCaps)

-- | Run 'pipeline' over a list, recording what the consumer took (in the
-- order taken, with the numbers given); the producer counts what it has
-- produced, and each element consumed records how far ahead the producer
-- was. @failAt@ makes producing (Left) or consuming (Right) that element
-- fail; @slow@ makes the consumer take its time.
record :: Int -> Maybe (Either Int Int) -> Bool -> [Int]
       -> IO ((Bool, Maybe String), [(Int, Int)], Int)
record batch failAt slow xs = do
  produced <- newIORef (0 :: Int)
  taken    <- newIORef []
  ahead    <- newIORef 0
  let produce x = do
        when (failAt == Just (Left x)) $ throwIO (ErrorCall ("produce " ++ show x))
        modifyIORef' produced (+ 1)
      consume n x = do
        p <- readIORef produced
        modifyIORef' ahead (max (p - n))
        modifyIORef' taken ((n, x) :)
        when slow (threadDelay 200)
        when (failAt == Just (Right x)) $ throwIO (ErrorCall ("consume " ++ show x))
  (ended, stopped) <- pipeline batch produce consume xs
  t <- reverse <$> readIORef taken
  a <- readIORef ahead
  pure ((either (const False) (const True) ended, fmap show stopped), t, a)

spec :: Spec
spec = do
  forM_ [1, 2] $ \caps -> describe ("on " ++ show caps ++ (if caps == (1 :: Int) then " capability" else " capabilities")) $ do
    it "the consumer takes every element, in order, numbered from 0 (lengths about the batches)" $ withCaps caps $
      forM_ [1, 3, 16] $ \batch -> forM_ [0, 1, 2, 3, 15, 16, 17, 100] $ \len -> do
        let xs = [ 7 * i + 1 | i <- [0 .. len - 1] ]
        (res, taken, _) <- record batch Nothing False xs
        res `shouldBe` (True, Nothing)
        taken `shouldBe` zip [0 ..] xs
    it "a failure producing element k: the consumer takes the k before it, and the failure is returned" $
      withCaps caps $ forM_ [0, 1, 5, 16, 37] $ \k -> do
        (res, taken, _) <- record 16 (Just (Left k)) False [0 .. 99]
        res `shouldBe` (False, Nothing)
        taken `shouldBe` zip [0 ..] [0 .. k - 1]
    it "a failure consuming element k: it is the last taken, and the producer stops (an endless list)" $
      withCaps caps $ forM_ [0, 1, 5, 16, 37] $ \k -> do
        (res, taken, _) <- record 4 (Just (Right k)) False [0 ..]
        res `shouldBe` (True, Just ("consume " ++ show k))
        taken `shouldBe` zip [0 ..] [0 .. k]
    it "the producer is at most four batches ahead of a slow consumer" $ withCaps caps $ do
      (_, taken, ahead) <- record 3 Nothing True [0 .. 199]
      length taken `shouldBe` 200
      ahead `shouldSatisfy` (<= 4 * 3 + 1)
    it "an interrupt of the producer (Ctrl-C) is returned, after what was produced before it" $ withCaps caps $ do
      me <- myThreadId
      taken <- newIORef []
      (ended, stopped) <- pipeline 16 (\x -> when (x == (40 :: Int)) (throwTo me UserInterrupt))
                                   (\n x -> modifyIORef' taken ((n, x) :)) [0 ..]
      either (\e -> fromException e == Just UserInterrupt) (const False) ended `shouldBe` True
      fmap show stopped `shouldBe` Nothing
      reverse <$> readIORef taken `shouldReturn` zip [0 ..] [0 .. 39]

    it "an interrupt while the consumer catches up, the list ended: the consumer skips the rest, and the interrupt is returned" $
      withCaps caps $ do
        -- the consumer holds element 0 until the pipeline's thread,
        -- every element produced, waits for it; then Ctrl-C, and the
        -- consumer goes on once that thread, the interrupt handled,
        -- waits again
        gate     <- newEmptyMVar
        produced <- newIORef (0 :: Int)
        taken    <- newIORef []
        result   <- newEmptyMVar
        tid <- forkIO $
          pipeline 16 (\_ -> modifyIORef' produced (+ 1))
                      (\n x -> do when (n == 0) (readMVar gate)
                                  modifyIORef' taken ((n, x) :))
                      [0 .. 39 :: Int]
            >>= putMVar result
        let waiting = do
              p  <- readIORef produced
              st <- threadStatus tid
              pure (p == 40 && case st of ThreadBlocked _ -> True; _ -> False)
            settle k = do
              w <- waiting
              if w || k <= (0 :: Int) then pure w else threadDelay 1000 >> settle (k - 1)
        settle 10000 `shouldReturn` True
        throwTo tid UserInterrupt
        settle 10000 `shouldReturn` True
        putMVar gate ()
        (ended, stopped) <- takeMVar result
        either (\e -> fromException e == Just UserInterrupt) (const False) ended `shouldBe` True
        fmap show stopped `shouldBe` Nothing
        reverse <$> readIORef taken `shouldReturn` [(0, 0)]

  describe "batchFor" $
    it "16 small elements a batch, about 4096 parts a batch, at least one element" $
      map batchFor [0, 1, 10, 256, 257, 1000, 4096, 10000] `shouldBe` [16, 16, 16, 16, 15, 4, 1, 1]
