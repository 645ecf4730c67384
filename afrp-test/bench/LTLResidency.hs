-- | The memory 'evalT' takes on long streams, for bench/residency.sh:
-- @afrp-test-residency KIND N@ evaluates one predicate on a stream of
-- @N + 1@ samples made lazily (0.01 s apart, the values 0..N) and prints
-- the answer; run it with @+RTS -s@ and read the maximum residency. With
-- no arguments, every kind on 10^5 samples (what @cabal bench@ runs).
module Main (main) where

import           System.Environment (getArgs)
import           System.Exit        (die)

import           AFRP               (arr)
import           AFRP.Test.LTL
import           AFRP.Test.Stream   (SignalSampleStream, groupDeltas)

-- | The predicates, by name: the first five look a bounded way ahead
-- under their outermost operator; the last nests a future operator.
predicates :: [(String, TPred Double)]
predicates =
  [ ("always",     Always (is (>= 0)))
  , ("implies",    Always (Implies (is (> 5)) (Next (is (> 5)))))
  , ("eventually", Eventually (is (< 0)))
  , ("until",      Until (is (>= 0)) (is (< 0)))
  , ("window",     Always (alwaysFor 0.05 (is (>= 0))))
  , ("nested",     Always (Implies (is (>= 0)) (Eventually (is (>= 0)))))
  ]
  where is f = SP (arr f)

stream :: Int -> SignalSampleStream Double
stream n = groupDeltas (map fromIntegral [0 .. n]) (repeat 0.01)

main :: IO ()
main = do
  args <- getArgs
  case args of
    [] -> mapM_ (\(name, p) -> putStrLn (name ++ " " ++ show (evalT p (stream 100000)))) predicates
    [name, n] | Just p <- lookup name predicates, [(k, "")] <- reads n, k >= 0 ->
      print (evalT p (stream k))
    _ -> die ("usage: afrp-test-residency [KIND N], KIND one of " ++ unwords (map fst predicates))
