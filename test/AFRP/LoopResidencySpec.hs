-- | Memory of delays inside 'loop' whose output nobody reads.
--
-- A delay stores the value fed back to it unevaluated (its semantics: a
-- delay never looks at what it stores). When its output is discarded,
-- nothing ever evaluates those values, so what each of them refers to is
-- kept as long as the delay keeps the value. A fed-back value that
-- referred to the whole step of the loop (its successor nodes, and
-- through them the values stored at earlier steps) made a chain as long
-- as the run: 307 MB at 10^6 samples for @delay@. The loop now takes the
-- fed-back value from the step's output pair only ("AFRP.Internal.SF",
-- 'loopK'), so the delay holds what it stores and no more.
--
-- Each case runs a child process (this test binary, started again with
-- 'childVariable' set) for 10^6 samples under a 16 MB heap limit
-- (@+RTS -M16m@); a leak ends it with a heap overflow.
module AFRP.LoopResidencySpec
  ( spec
  , childVariable
  , child
  ) where

import           Data.List          (foldl')
import           System.Environment (getEnvironment, getExecutablePath)
import           System.Exit        (ExitCode (..))
import           System.Process     (proc, readCreateProcessWithExitCode, env)
import           Test.Hspec

import           AFRP

-- | The environment variable that makes the test binary run 'child'.
childVariable :: String
childVariable = "AFRP_SPEC_LOOP_CHILD"

-- The delays, each fed from a 'Double', their output made a 'Double'.
delays :: [(String, SF Double Double)]
delays =
  [ ("delay",         delay 0.5 0)
  , ("sampleWindow",  sampleWindow 3 0.05 >>> arr (event 0 sum))
  , ("iPre",          iPre 0)
  , ("pre",           pre)
  , ("delayEvent",    arr (\c -> if c > 0 then Event c else NoEvent) >>> delayEvent 0.05
                        >>> arr (event 0 id))
  , ("fby",           0 `fby` identity)
  ]

-- The network: the delay watches the input, fed back through the loop,
-- and its output is discarded (the loop outputs its input).
network :: SF Double Double -> SF Double Double
network sf = loop (second sf >>> arr (\(a, _) -> (a, a)))

samples :: Int
samples = 1000000

-- | Runs the named delay's network for 10^6 samples at dt = 0.01 and
-- prints the sum of its outputs.
child :: String -> IO ()
child name = case lookup name delays of
  Just sf -> print (foldl' (+) 0 (embed (network sf) (0, [ (0.01, Just (fromIntegral i)) | i <- [1 .. samples - 1] ])))
  Nothing -> ioError (userError ("unknown child " ++ show name))

spec :: Spec
spec = describe "a delay in a loop, its output discarded, for 10^6 samples" $
  mapM_ (\(name, _) -> it (name ++ " runs in 16 MB of heap (+RTS -M16m)") (bounded name)) delays
  where
    bounded name = do
      self <- getExecutablePath
      environment <- getEnvironment
      (code, out, err) <- readCreateProcessWithExitCode
        (proc self ["+RTS", "-M16m", "-RTS"]) { env = Just ((childVariable, name) : environment) } ""
      (code, err) `shouldBe` (ExitSuccess, "")
      -- the loop outputs its input: 0 + 1 + ... + (10^6 - 1)
      read out `shouldBe` (fromIntegral (samples * (samples - 1) `div` 2) :: Double)
