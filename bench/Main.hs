-- | @cabal bench@: every network of "Networks" against its hand-written
-- baseline (criterion). See bench/README.md for how to read the results.
--
-- @afrp-bench --run KEY N@ instead runs one network for N samples and
-- prints the sum of its outputs: bench/residency.sh uses it with
-- @+RTS -s@ to measure memory residency.
module Main (main) where

import           Criterion.Main
import           Data.List          (foldl', isPrefixOf)
import           System.Environment (getArgs, withArgs)
import           System.Exit        (exitFailure)
import           System.IO          (hPutStrLn, stderr)

import           Networks

samples :: Int
samples = 100000

main :: IO ()
main = do
  args <- getArgs
  case args of
    ["--run", key, n] -> case [nw | nw <- networks, (key ++ ":") `isPrefixOf` nwName nw] of
      nw : _ -> print (sumNetwork (nwSF nw) (read n))
      []     -> do
        hPutStrLn stderr ("afrp-bench: no network " ++ show key ++ "; the keys are "
                          ++ unwords (map (takeWhile (/= ':') . nwName) networks))
        exitFailure
    _ -> withArgs args (defaultMain
      [ bgroup (nwName nw)
          [ bench "afrp"     (whnf (sumNetwork (nwSF nw)) samples)
          , bench "baseline" (whnf (foldl' (+) 0 . nwBaseline nw) samples)
          ]
      | nw <- networks
      ])
