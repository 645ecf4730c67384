-- | "AFrobRobotSim.Workers": 'readInOrder' gives the list's own values, on
-- one capability and on several, whether the reader is quicker or slower
-- than the workers (so that it waits for them, or computes elements from
-- the end while they are busy), and the reader meets the exception of
-- the first failing element first, as when evaluating on one thread; and
-- a worker that has gone to sleep for want of work is woken by the next.
module AFrobRobotSim.WorkersSpec (spec) where

import           Control.Concurrent (threadDelay)
import           Control.Exception (ErrorCall (..), evaluate, try)
import           Control.Monad     (forM_)
import           Data.IORef        (IORef, atomicModifyIORef', newIORef, readIORef, writeIORef)
import           Data.List         (foldl')
import           System.IO.Unsafe  (unsafePerformIO)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.Workers
import           TestUtil (withCaps)

-- | Some work that depends on its arguments (so that no two elements, and
-- no two runs, share it): a sum over @n@ numbers.
work :: Int -> Int -> Int
work seed n = foldl' (\acc j -> (acc * 31 + j * seed) `mod` 1000003) seed [1 .. n]
{-# NOINLINE work #-}

-- | 'work', counting in the reference each time it is computed.
counted :: IORef Int -> Int -> Int
counted ref k = unsafePerformIO $ do
  atomicModifyIORef' ref (\c -> (c + 1, ()))
  pure $! work k 1000
{-# NOINLINE counted #-}

-- | Read a list in order, doing @between !! k@ of work after element @k@,
-- and return the values and that work (forced alongside).
readAll :: [Int] -> [Int] -> IO [Int]
readAll between xs = go (zip xs (between ++ repeat 0))
  where
    go [] = pure []
    go ((x, w) : rest) = do
      v <- evaluate x
      _ <- evaluate (work v w)
      (v :) <$> go rest

spec :: Spec
spec = describe "readInOrder" $ do
  it "is the list itself, element for element, on 1 to 3 capabilities, for readers quicker and slower than the workers" $
    property $ \(Positive seed) costs0 between0 ->
      let costs   = map ((* 500) . (`mod` 40) . abs) (costs0 :: [Int])
          between = map ((* 500) . (`mod` 40) . abs) (between0 :: [Int])
          xs s    = [ work (s + k) c | (k, c) <- zip [0 ..] costs ]
      in ioProperty $ do
        expected <- readAll between (xs seed)
        got <- mapM (\caps -> withCaps caps (readAll between (readInOrder caps (xs seed)))) [1, 2, 3]
        pure (conjoin [ g === expected | g <- got ])

  it "raises the first failing element's exception first; later elements keep theirs" $ do
    -- (each element takes a while, element 1 much longer, so that a worker
    -- is busy with it when the reader reaches it, and the reader computes
    -- elements from the end, 7 among them)
    let cost k = if k == 1 then 4000000 else 100000
        xs s = [ if work (s + k) (cost k) >= 0 && (k == 3 || k == 7) then error ("element " ++ show k)
                 else work (s + k) (cost k)
               | k <- [0 .. 11 :: Int] ]
    results <- withCaps 2 $ do
      let ys = readInOrder 2 (xs 5)
      mapM (\y -> try (evaluate y)) ys
    let described = map (either (\(ErrorCall m) -> Left m) Right) results
    described `shouldBe` map (\k -> if k == 3 || k == 7 then Left ("element " ++ show k) else Right (work (5 + k) (cost k)))
                             [0 .. 11 :: Int]
    -- and read in order up to the first failure only, as one thread would
    first <- withCaps 2 (try (readAll [] (readInOrder 2 (xs 6))))
    either (\(ErrorCall m) -> m) show first `shouldBe` "element 3"

  it "gives the same values to a reader that does not read in order" $ do
    let xs s = [ work (s + k) 100000 | k <- [0 .. 11 :: Int] ]
    got <- withCaps 2 $ do
      let ys = readInOrder 2 (xs 9)
      _ <- evaluate (ys !! 6)
      _ <- evaluate (ys !! 2)
      mapM evaluate (reverse ys)
    got `shouldBe` reverse (xs 9)

  it "with one capability, or fewer than two elements, leaves the list as it is" $ do
    let xs = [ work k 10 | k <- [1 .. 5] ]
    readInOrder 1 xs `shouldBe` xs
    readInOrder 4 [work 1 10] `shouldBe` [work 1 10]
    readInOrder 4 ([] :: [Int]) `shouldBe` []

  it "wakes a worker that has gone to sleep: after a pause, the workers compute what the reader does not read" $ do
    computed <- newIORef 0
    withCaps 2 $ forM_ [1 .. 3 :: Int] $ \r -> do
      threadDelay 5000   -- (a worker out of work looks for more for 0.2 ms, then sleeps)
      writeIORef computed 0
      let ys = readInOrder 2 [ counted computed (100 * r + k) | k <- [0 .. 7] ]
      _ <- evaluate (head ys)
      -- elements 1 to 7 are left to the worker: wait for it (a guard
      -- against a worker that never wakes, of at least 30 s: a loaded
      -- machine can keep a thread from running for a while)
      let waitFor :: Int -> IO Int
          waitFor n = do
            c <- readIORef computed
            if c >= 8 || n <= 0 then pure c else threadDelay 1000 >> waitFor (n - 1)
      waitFor 30000 `shouldReturn` 8
