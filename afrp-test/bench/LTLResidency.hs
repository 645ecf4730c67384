-- | The memory 'evalT' takes on long streams, for bench/residency.sh:
-- @afrp-test-residency KIND N@ evaluates one predicate on a stream of
-- @N + 1@ samples made lazily (0.01 s apart, the values 0..N) and prints
-- the answer; run it with @+RTS -s@ and read the maximum residency. The
-- kind @runT@ checks a predicate on every world state of a run of three
-- simbots for N steps of 0.01 s with 'runT', and the kind @onRobot@ one on
-- the states of one of them ('onRobot'), and the kind @runTLate@ one
-- that fails at the run's last step (decided and explained there); the
-- kind @explain@ explains a predicate that fails at the last of @N + 1@
-- samples ('explainT'); the kind @page@ writes that
-- run's replay page ('writeRunReplayPage', to a file in the system's
-- temporary folder, removed after) and prints its size in bytes. With no
-- arguments, every kind on 10^5 samples, the runs on 10^4 steps and the
-- page on 10^3 (what @cabal bench@ runs).
module Main (main) where

import           Control.Exception  (bracket)
import           System.Directory   (getTemporaryDirectory, removeFile)
import           System.Environment (getArgs)
import           System.Exit        (die)
import           System.IO          (IOMode (ReadMode), hClose, hFileSize, openTempFile, withFile)

import           Test.QuickCheck    (chatty, isSuccess, maxSuccess, quickCheckWithResult, stdArgs)

import           AFRP               (arr)
import           AFRP.Geometry      (Point2 (..))
import           AFrob              (constant, ddVelTR, mrFinalize, rpId)
import           AFrobRobotSim      (ObjectTemplate (..), RobotState (..), SimbotController, WorldState (..), defaultSimConfig)
import           AFrobRobotSim.Test (onRobot, runT, writeRunReplayPage)
import           AFRP.Test.LTL
import           AFRP.Test.Stream   (SignalSampleStream, groupDeltas)

-- | The predicates, by name: each looks a bounded way ahead under its
-- outermost operator (the last nests an 'Eventually' whose argument holds
-- at every sample, so that each sample decides it).
predicates :: [(String, TPred Double)]
predicates =
  [ ("always",     Always (is (>= 0)))
  , ("implies",    Always (Implies (is (> 5)) (Next (is (> 5)))))
  , ("eventually", Eventually (is (< 0)))
  , ("until",      Until (is (>= 0)) (is (< 0)))
  , ("window",     Always (alwaysFor 0.05 (is (>= 0))))
  , ("nested",     Always (Implies (is (>= 0)) (Eventually (is (>= 0)))))
    -- (owing one Eventually that never comes: once, however many samples
    -- owe it)
  , ("never",      Always (Implies (is (>= 0)) (Eventually (is (< 0)))))
    -- (a connective whose first operand the end decides)
  , ("both",       And (Eventually (is (< 0))) (Always (is (>= 0))))
  ]
  where is f = SP (arr f)

stream :: Int -> SignalSampleStream Double
stream n = groupDeltas (map fromIntegral [0 .. n]) (repeat 0.01)

-- | 'runT' of "every world state has its three robots" on a run of @n@
-- steps of three wandering simbots: whether it held.
runOf :: Int -> IO Bool
runOf n = isSuccess <$> quickCheckWithResult stdArgs { maxSuccess = 1, chatty = False }
  (runT defaultSimConfig (fromIntegral n / 100) wander wander (Always (SP (arr ((== 3) . length . wsRobots)))) world)

-- | 'runT' of "SimbotA 2 keeps its id" ('onRobot') on that run of @n@
-- steps: whether it held.
onRobotOf :: Int -> IO Bool
onRobotOf n = isSuccess <$> quickCheckWithResult stdArgs { maxSuccess = 1, chatty = False }
  (runT defaultSimConfig (fromIntegral n / 100) wander wander (onRobot "SimbotA" 2 (Always (SP (arr ((== 2) . robotId))))) world)

-- | 'runT' of "the run has not reached its end" on that run of @n@
-- steps: false, decided (and explained) at its last step.
lateOf :: Int -> IO Bool
lateOf n = isSuccess <$> quickCheckWithResult stdArgs { maxSuccess = 1, chatty = False }
  (runT defaultSimConfig duration wander wander (Always (SP (arr ((< duration - 0.005) . wsTime)))) world)
  where duration = fromIntegral n / 100

-- | 'explainT' of "the value is below N" on the stream of @N + 1@
-- samples: false at the last one, where it is explained.
explainedAt :: Int -> Maybe Int
explainedAt n = fmap explFrame (explainT (Always (SP (arr (< fromIntegral n)))) (stream n))

-- | The replay page of that run of @n@ steps, written and removed: its
-- size in bytes.
pageOf :: Int -> IO Integer
pageOf n = do
  tmp <- getTemporaryDirectory
  -- (a file of its own name, so that two runs at once do not meet,
  -- removed whatever happens)
  bracket (openTempFile tmp "afrp-test-residency.html") (\(file, h) -> hClose h >> removeFile file) $ \(file, h) -> do
    hClose h
    writeRunReplayPage file defaultSimConfig (fromIntegral n / 100) world wander wander
    withFile file ReadMode hFileSize

-- | Three simbots, each driving its own circle.
world :: [ObjectTemplate]
world = [OTSimbotA 1 (Point2 0 0) 0, OTSimbotA 2 (Point2 2 2) 1, OTSimbotB 3 (Point2 (-2) (-2)) 2]

wander :: SimbotController
wander props = constant (mrFinalize (ddVelTR 2 (fromIntegral (rpId props `mod` 5 - 2) * 0.6)))

main :: IO ()
main = do
  args <- getArgs
  case args of
    [] -> do
      mapM_ (\(name, p) -> putStrLn (name ++ " " ++ show (evalT p (stream 100000)))) predicates
      runOf 10000 >>= putStrLn . ("runT " ++) . show
      onRobotOf 10000 >>= putStrLn . ("onRobot " ++) . show
      lateOf 10000 >>= putStrLn . ("runTLate " ++) . show
      putStrLn ("explain " ++ show (explainedAt 100000))
      pageOf 1000 >>= putStrLn . ("page " ++) . show
    ["runT", n] | [(k, "")] <- reads n, k >= 0 -> runOf k >>= print
    ["onRobot", n] | [(k, "")] <- reads n, k >= 0 -> onRobotOf k >>= print
    ["page", n] | [(k, "")] <- reads n, k >= 0 -> pageOf k >>= print
    ["runTLate", n] | [(k, "")] <- reads n, k >= 0 -> lateOf k >>= print
    ["explain", n] | [(k, "")] <- reads n, k >= 0 -> print (explainedAt k)
    [name, n] | Just p <- lookup name predicates, [(k, "")] <- reads n, k >= 0 ->
      print (evalT p (stream k))
    _ -> die ("usage: afrp-test-residency [KIND N], KIND one of runT runTLate onRobot page explain "
              ++ unwords (map fst predicates))
