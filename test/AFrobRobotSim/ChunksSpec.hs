-- | "AFrobRobotSim.Chunks": 'stepEvery' gives the lists of every robot's
-- step computed in order, whatever the capabilities (one or two), whether
-- it may use them, and the number of robots (around each bound of the
-- chunks: 'minChunk', 'seqChunk', two chunks, many); and a step that fails
-- fails the lists with the first failure in order, the later failing
-- robots' chunks computed or not.
module AFrobRobotSim.ChunksSpec (spec) where

import           Control.Exception (ErrorCall (..), evaluate, try)
import           Control.Monad     (forM_)
import           Test.Hspec

import           AFrobRobotSim.Chunks
import           TestUtil          (withCaps)

-- | The sizes tried: none, one, each side of the bounds, and many.
sizes :: [Int]
sizes = [0, 1, minChunk - 1, minChunk, 2 * minChunk - 1, 2 * minChunk, 2 * minChunk + 1,
         seqChunk, seqChunk + 1, 2 * seqChunk + 3, 1000]

-- | A robot's step, made of its number, its agent and its robot (so that
-- a step given the wrong robot, or the wrong number, shows): its output,
-- its next agent and its bound.
stepOne :: Int -> Int -> Int -> ((Int, Int), Double)
stepOne i a r = ((i * 1000000 + a * 1000 + r, a + 1), fromIntegral (r + i))

-- | A plan, made of all it is given.
planOne :: Double -> Int -> Int -> (Double, Int, Int)
planOne apart r o = (apart, r, o)

-- | Every list of 'stepEvery', its start first.
allLists :: Bool -> Int -> IO ((), [Int], [Int], [(Int, (Double, Int, Int))])
allLists par n = do
  let agents = [0 .. n - 1]
      robots = map (* 3) agents
      (s, os, as, ps) = stepEvery par () agents robots stepOne planOne
  _ <- evaluate s
  _ <- evaluate (sum os + sum as + sum [ r + o | (r, (_, _, o)) <- ps ])
  pure (s, os, as, ps)

spec :: Spec
spec = describe "stepEvery" $ do
  it "gives every robot's output, next agent and plan, in order, on one capability or two, parallel or not" $
    forM_ [1, 2] $ \k -> withCaps k $ forM_ [False, True] $ \par -> forM_ sizes $ \n -> do
      got <- allLists par n
      let want = [ (i * 1000000 + i * 1000 + 3 * i, i + 1, (3 * i, (fromIntegral (4 * i), 3 * i, i * 1000000 + i * 1000 + 3 * i)))
                 | i <- [0 .. n - 1] ]
          (_, os, as, ps) = got
      (k, par, n, os, as, ps)
        `shouldBe` (k, par, n, [ o | (o, _, _) <- want ], [ a | (_, a, _) <- want ], [ p | (_, _, p) <- want ])

  it "fails with the first failing robot's error, in order, whoever computes the later ones" $
    forM_ [1, 2] $ \k -> withCaps k $ forM_ [False, True] $ \par -> do
      let n = 1000
          failing i a r
            | i == 37 || i == 80 || i == 900 = errorWithoutStackTrace ("robot " ++ show i)
            | otherwise                       = stepOne i a r
          (s, os, _, _) = stepEvery par () [0 .. n - 1] (map (* 3) [0 .. n - 1]) failing planOne
      _ <- evaluate s
      r <- try (evaluate (sum os))
      (k, par, either (\(ErrorCall m) -> m) show r) `shouldBe` (k, par, "robot 37")
