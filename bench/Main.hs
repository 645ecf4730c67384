{-# OPTIONS_GHC -fno-full-laziness #-}
-- | @cabal bench@: every network of "Networks" against its hand-written
-- baseline, and the simulator at 1, 10, 100 and 1000 robots (criterion).
-- See bench/README.md for how to read the results.
--
-- Other modes (used by bench/residency.sh and to fill in bench/README.md):
--
-- * @afrp-bench --run KEY N@ runs one network for N samples and prints
--   the sum of its outputs (@--run floor N@: the network @arr id@, i.e.
--   what 'AFRP.Run.embed' and the input list cost on their own);
-- * @afrp-bench --base KEY N@ does the same for the network's baseline;
-- * @afrp-bench --sim ROBOTS STEPS@ runs the simulator benchmark world
--   with that many robots for that many steps and prints the robot-steps
--   per second and the speed relative to real time;
-- * @afrp-bench --sim-table@ does that for 1, 10, 100 and 1000 robots;
-- * @afrp-bench --balls N STEPS@ runs N balls in a crowd ('ballCrowd')
--   for that many steps and prints the speed relative to real time;
-- * @afrp-bench --swarm N COVERAGE SECONDS@ runs N Braitenberg avoiders
--   covering that fraction of the floor for that many simulated seconds
--   ("Swarm", the afrp side of bench/enki.sh);
-- * @afrp-bench --packed N STEPS@ runs N wanderers packed in the 10 m
--   world ('packedWorld') and prints robot-steps per second and the speed
--   relative to real time, by the wall clock (all cores with @+RTS -N@);
-- * @afrp-bench --steady ROBOTS STEPS@ and @--steady-packed N STEPS@
--   time the steps of those runs after their first two (the world's
--   validation, the arena's grids and the first indexes are built then),
--   by the wall clock and the CPU time (of every core), and print
--   robot-steps per second by both;
-- * @afrp-bench --steady-with CONTROLLER ROBOTS STEPS@ is @--steady@ with
--   every robot driven by @idle@, @rays@, @tracker@ or @bench@ (the
--   controllers of 'benchRunWith'; @bench@ is @--steady@'s own): their
--   differences split a robot-step's cost (bench/README.md, "Fifteenth
--   round");
-- * @afrp-bench --side-by-side ROBOTS STEPS@ times, as @--steady@ does,
--   one run of @--steady@'s world on each capability at once, each
--   stepped alone ('AFrobRobotSim.simParallel' 'False'), and prints their
--   robot-steps per second together: what the program's capabilities
--   give work that shares nothing but the runtime (bench/README.md,
--   "Nineteenth round");
-- * @afrp-bench --render FRAMES@ renders that many 600x600 PPM frames of
--   the 10-robot world and prints the frames per second;
-- * @afrp-bench --pairs R@ times every network and its baseline R times,
--   alternately (CPU time), and prints the best times and the median of
--   the R ratios: steadier than separate runs on a busy machine.
-- * @afrp-bench --loop NAME N@ runs the combinator NAME of "Residency"
--   inside a loop, its output discarded (@NAME+@: used), for N samples,
--   and prints the sum of the outputs.
module Main (main) where

import           Control.Concurrent (forkOn, getNumCapabilities, newEmptyMVar, putMVar, takeMVar)
import           Control.Exception  (SomeException, evaluate, throwIO, try)
import           Criterion.Main
import           Criterion.Types    (Config (..))
import           Data.List          (foldl', isPrefixOf, sort)
import           GHC.Clock          (getMonotonicTime)
import           System.CPUTime     (getCPUTime)
import           System.Environment (getArgs, withArgs)
import           System.Exit        (exitFailure)
import           System.IO          (hPutStrLn, stderr)
import           Text.Printf        (printf)

import           AFRP               (SF, arr)
import           AFrobRobotSim      (SimbotController, WorldState)
import           Networks
import           Residency          (loopNetwork, loopNetworks)
import           RenderBench        (prepareFrames, renderFrames)
import           SimBench
import           Swarm              (swarmReport)

samples :: Int
samples = 100000

-- | 8 s per benchmark (criterion's default is 5): about 4 minutes in all.
config :: Config
config = defaultConfig { timeLimit = 8 }

-- | Robots and steps of the simulator benchmarks (each run takes from a
-- few tens to a few hundred milliseconds).
simSizes :: [(Int, Int)]
simSizes = [(1, 20000), (10, 2000), (100, 500), (1000, 50)]

main :: IO ()
main = do
  args <- getArgs
  case args of
    ["--run", "floor", n] -> print (sumNetwork (arr id) (read n))
    ["--base", key, n] -> withNetwork key $ \nw -> print (foldl' (+) 0 (nwBaseline nw (read n)))
    ["--run", key, n] -> withNetwork key $ \nw -> print (sumNetwork (nwSF nw) (read n))
    ["--sim", n, steps] -> simReport (read n) (read steps)
    ["--sim-table"] -> mapM_ (\(n, steps) -> simReport n (steps * 5)) simSizes
    ["--render", frames] -> renderReport (read frames)
    ["--balls", n, steps] -> ballReport (read n) (read steps)
    ["--swarm", n, cov, secs] -> swarmReport (read n) (read cov) (read secs)
    ["--packed", n, steps] -> packedReport (read n) (read steps)
    ["--steady", n, steps] -> steadyReport "robots" (read n) (benchRun (read n)) (read steps)
    ["--side-by-side", n, steps] -> sideBySideReport (read n) (read steps)
    ["--steady-with", c, n, steps] -> withController c $ \ctl ->
      steadyReport "robots" (read n) (benchRunWith ctl (read n)) (read steps)
    ["--steady-packed", n, steps] -> steadyReport "packed wanderers" (packedRobots (read n)) (packedRun (read n)) (read steps)
    ["--pairs", r] -> mapM_ (pairsReport (read r)) networks
    ["--loop", name, n] -> withLoopNetwork name $ \nw -> print (sumNetwork nw (read n))
    _ -> withArgs args (defaultMainWith config
      ([ bgroup (nwName nw)
           [ bench "afrp"     (whnf (sumNetwork (nwSF nw)) samples)
           , bench "baseline" (whnf (foldl' (+) 0 . nwBaseline nw) samples)
           ]
       | nw <- networks
       ] ++
       [ bgroup "simulator"
           [ bench (show n ++ " robots x " ++ show steps ++ " steps") (whnf (runBench n) steps)
           | (n, steps) <- simSizes ]
       , bgroup "balls"
           [ bench "1000 balls in a crowd x 50 steps" (whnf (runBallBench 1000) 50) ]
       , bgroup "render"
           [ env (evaluate (prepareFrames 10)) $ \_ ->
               bench "10 robots, 600x600 PPM x 10 frames" (whnf renderFrames 10) ]
       ]))

-- The controllers of @--steady-with@, by name.
withController :: String -> (SimbotController -> IO ()) -> IO ()
withController name k = case lookup name controllers of
  Just c  -> k c
  Nothing -> do
    hPutStrLn stderr ("afrp-bench: no controller " ++ show name ++ "; the names are "
                      ++ unwords (map fst controllers))
    exitFailure
  where
    controllers = [ ("idle", idleController), ("rays", raysController)
                  , ("tracker", trackerController), ("bench", benchController) ]

withNetwork :: String -> (Network -> IO ()) -> IO ()
withNetwork key k = case [nw | nw <- networks, (key ++ ":") `isPrefixOf` nwName nw] of
  nw : _ -> k nw
  []     -> do
    hPutStrLn stderr ("afrp-bench: no network " ++ show key ++ "; the keys are "
                      ++ unwords (map (takeWhile (/= ':') . nwName) networks))
    exitFailure

-- | Time one simulator run (wall clock and CPU) and report robot-steps per
-- second and the speed relative to real time.
simReport :: Int -> Int -> IO ()
simReport n steps = do
  _  <- evaluate (worldChecksum n)   -- build the world outside the timed run
  w0 <- getMonotonicTime
  c0 <- getCPUTime
  s  <- evaluate (runBench n steps)
  c1 <- getCPUTime
  w1 <- getMonotonicTime
  let cpu  = fromIntegral (c1 - c0) / 1e12 :: Double
      wall = w1 - w0
      simT = fromIntegral steps * simDtBench
  printf "%5d robots x %6d steps: %10.0f robot-steps/s, %8.1fx real time (CPU %.3f s, wall %.3f s, checksum %.6g)\n"
    n steps (fromIntegral (n * steps) / cpu) (simT / cpu) cpu wall s

-- | Time the steps of a run after its first two (see the module header).
steadyReport :: String -> Int -> [WorldState] -> Int -> IO ()
steadyReport what n run steps = do
  rest <- afterStart run
  w0 <- getMonotonicTime
  c0 <- getCPUTime
  s  <- evaluate (snapshotsChecksum (take steps rest))
  c1 <- getCPUTime
  w1 <- getMonotonicTime
  let cpu  = fromIntegral (c1 - c0) / 1e12 :: Double
      wall = w1 - w0
      simT = fromIntegral steps * simDtBench
      rs   = fromIntegral (n * steps) :: Double
  printf "%5d %s x %6d steps: %10.0f robot-steps/s (wall), %8.2fx real time (wall %.3f s; CPU %.3f s: %.0f robot-steps per CPU second, %.2f us each; checksum %.6g)\n"
    n what steps (rs / wall) (simT / wall) wall cpu (rs / cpu) (cpu / rs * 1e6) s

-- | A run's snapshots after its first two, which are computed first
-- (the world's validation, the arena's grids and the first indexes are
-- built then).
afterStart :: [WorldState] -> IO [WorldState]
afterStart run = let (warm, rest) = splitAt 2 run
                 in evaluate (snapshotsChecksum warm) >> pure rest

-- | Time, as 'steadyReport' does by the wall clock, one run of
-- 'benchRunAlone' on each capability, all at once (each run's thread
-- pinned to its capability), from the start of the first to the end of
-- the last.
sideBySideReport :: Int -> Int -> IO ()
sideBySideReport n steps = do
  caps <- getNumCapabilities
  runs <- mapM (\_ -> afterStart (benchRunAlone n)) [1 .. caps]   -- (a run each: no full laziness here)
  dones <- mapM (const newEmptyMVar) runs
  w0 <- getMonotonicTime
  sequence_ [ forkOn c (try (evaluate (snapshotsChecksum (take steps run))) >>= putMVar done)
            | (c, run, done) <- zip3 [0 ..] runs dones ]
  sums <- mapM (\d -> takeMVar d >>= either (\e -> throwIO (e :: SomeException)) pure) dones
  w1 <- getMonotonicTime
  let wall = w1 - w0
      simT = fromIntegral steps * simDtBench
      rs   = fromIntegral (caps * n * steps) :: Double
  printf "%d run%s of %5d robots x %6d steps side by side: %10.0f robot-steps/s (wall) together, %8.2fx real time each (wall %.3f s; checksum %.6g)\n"
    caps (if caps == 1 then "" else "s") n steps (rs / wall) (simT / wall) wall (sum sums)

-- | Time @n@ wanderers of 'packedWorld' for @steps@ steps.
packedReport :: Int -> Int -> IO ()
packedReport n steps = do
  robots <- evaluate (packedRobots n)
  w0 <- getMonotonicTime
  c0 <- getCPUTime
  s  <- evaluate (runPacked n steps)
  c1 <- getCPUTime
  w1 <- getMonotonicTime
  let cpu  = fromIntegral (c1 - c0) / 1e12 :: Double
      wall = w1 - w0
      simT = fromIntegral steps * simDtBench
  printf "%5d packed wanderers x %6d steps: %10.0f robot-steps/s, %8.1fx real time (CPU %.3f s, wall %.3f s, checksum %.6g)\n"
    robots steps (fromIntegral (robots * steps) / wall) (simT / wall) cpu wall s

-- | Time @n@ balls of 'ballCrowd' for @steps@ steps.
ballReport :: Int -> Int -> IO ()
ballReport n steps = do
  c0 <- getCPUTime
  s  <- evaluate (runBallBench n steps)
  c1 <- getCPUTime
  let cpu  = fromIntegral (c1 - c0) / 1e12 :: Double
      simT = fromIntegral steps * simDtBench
  printf "%5d balls x %6d steps: %8.1fx real time (CPU %.3f s, checksum %.6g)\n"
    n steps (simT / cpu) cpu s

-- | Alternate timings of a network and its baseline.
pairsReport :: Int -> Network -> IO ()
pairsReport r nw = do
  let key = takeWhile (/= ':') (nwName nw)
      n   = if key `elem` ["c", "e"] then samples `div` 10 else samples
  ts <- mapM (const ((,) <$> cpuPerSample (sumNetwork (nwSF nw)) n
                         <*> cpuPerSample (foldl' (+) 0 . nwBaseline nw) n)) [1 .. max 1 r]
  let as = map fst ts
      bs = map snd ts
      ratios = sort (zipWith (/) as bs)
  printf "%-36s %10.1f ns/sample  baseline %8.1f  median ratio %6.2f\n"
    (nwName nw) (minimum as) (minimum bs) (ratios !! (length ratios `div` 2))

-- | CPU time per sample of one evaluation, in nanoseconds.
cpuPerSample :: (Int -> Double) -> Int -> IO Double
cpuPerSample f n = do
  c0 <- getCPUTime
  _  <- evaluate (f n)
  c1 <- getCPUTime
  pure (fromIntegral (c1 - c0) / 1000 / fromIntegral n)
{-# NOINLINE cpuPerSample #-}

-- | Time the rendering of some frames.
renderReport :: Int -> IO ()
renderReport frames = do
  _  <- evaluate (prepareFrames frames)   -- simulate outside the timed run
  c0 <- getCPUTime
  s  <- evaluate (renderFrames frames)
  c1 <- getCPUTime
  let cpu = fromIntegral (c1 - c0) / 1e12 :: Double
  printf "%d frames of 600x600: %.1f frames/s (CPU %.3f s)\n"
    s (fromIntegral s / cpu) cpu

-- The network of "Residency" named (with a final @+@: its output used).
withLoopNetwork :: String -> (SF Double Double -> IO ()) -> IO ()
withLoopNetwork name k =
  let (base, used) = case reverse name of
        '+' : rest -> (reverse rest, True)
        _          -> (name, False)
  in case lookup base loopNetworks of
       Just sf -> k (loopNetwork used sf)
       Nothing -> do
         hPutStrLn stderr ("no such network: " ++ name ++ "; one of "
                           ++ unwords (map fst loopNetworks))
         exitFailure
