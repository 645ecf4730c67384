-- | Memory of long runs where part of a network is never read.
--
-- /A delay inside 'loop' whose output nobody reads./ A delay stores the
-- value fed back to it unevaluated (its semantics: a delay never looks at
-- what it stores), and when its output is discarded nothing ever
-- evaluates those values, so whatever each of them refers to lives as
-- long as the delay keeps it. A fed-back value that referred to the whole
-- step of the loop (its successor nodes, and through them the values
-- stored at earlier steps) made a chain as long as the run: 307 MB at
-- 10^6 samples for @delay@. The loop now takes the fed-back value from
-- the step's output pair only ('AFRP.Internal.Loop.loopK').
--
-- /The same delay, its output read once a second./ Reading the output at
-- one sample evaluated that sample's pair only; the values fed back at
-- the samples nobody read still referred to their steps, and so to the
-- values before them: 300 MB at 10^6 samples. The loop now evaluates the
-- pair of each step at the next one, and the fed-back value is a
-- selection the garbage collector resolves.
--
-- /A collection member whose output nobody reads./ On lists, 'Map.Map',
-- 'IntMap.IntMap' and 'Seq.Seq' every member is stepped, and its state
-- evaluated, at every sample ("AFRP.Parallel" picks a strict stepper for
-- those types by rewrite rules); a member left to be stepped on demand
-- would pile up one suspended step per sample.
--
-- /A switch that calls itself again./ 'kSwitch', 'dkSwitch' and the
-- collection switches are lazy ('AFRP.Internal.Deferred.lazyN'); their
-- continuation, a lazy switch again, was wrapped once more at every
-- switch, so that each step cost one more layer.
--
-- Each case runs a child process (this test binary, started again with
-- 'childVariable' set) for 10^6 samples under a 16 MB heap limit
-- (@+RTS -M16m@), or 10^5 switches under 2 MB; a leak ends it with a
-- heap overflow.
module AFRP.ResidencySpec
  ( spec
  , childVariable
  , child
  ) where

import           Data.List          (foldl')
import qualified Data.IntMap        as IntMap
import qualified Data.Map           as Map
import qualified Data.Sequence      as Seq
import           System.Environment (getEnvironment, getExecutablePath)
import           System.Exit        (ExitCode (..))
import           System.Process     (env, proc, readCreateProcessWithExitCode)
import           Test.Hspec          hiding (after)

import           AFRP

-- | The environment variable that makes the test binary run 'child'.
childVariable :: String
childVariable = "AFRP_SPEC_RESIDENCY_CHILD"

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
    -- nothing ever falls due: nothing need be kept
  , ("delay by infinity", delay (1 / 0) 0)
  , ("delayEvent by infinity", arr (\c -> if c > 0 then Event c else NoEvent) >>> delayEvent (1 / 0)
                                 >>> arr (event 0 id))
  , ("delayEventCat by infinity", arr (\c -> if c > 0 then Event c else NoEvent) >>> delayEventCat (1 / 0)
                                    >>> arr (event 0 sum))
  ]

-- The collections: two integrals of the input, only the first one read
-- (the loop outputs the input plus a hundred-millionth of it, so that
-- the expected sum stays exact).
collections :: [(String, SF Double Double)]
collections =
  [ ("parB on a list",       parB [integral, integral] >>> arr (read1 . head))
  , ("parB on a Map",        parB (Map.fromList [(1 :: Int, integral), (2, integral)]) >>> arr (read1 . (Map.! 1)))
  , ("par on an IntMap",     par (\a -> fmap (\sf -> (a, sf))) (IntMap.fromList [(1, integral), (2, integral)])
                               >>> arr (read1 . (IntMap.! 1)))
  , ("rpSwitchB on a Seq",   arr (\a -> (a, NoEvent)) >>> rpSwitchB (Seq.fromList [integral, integral])
                               >>> arr (read1 . (`Seq.index` 0)))
  , ("dpSwitchB on a list",  dpSwitchB [integral, integral] never (\sfs () -> parB sfs) >>> arr (read1 . head))
  ]
  where read1 x = x * 0

-- The network for a delay: it watches the input, fed back through the
-- loop, and its output is discarded (the loop outputs its input).
delayNetwork :: SF Double Double -> SF Double Double
delayNetwork sf = loop (second sf >>> arr (\(a, _) -> (a, a)))

-- The network for a delay whose output is read once a second: the loop
-- outputs what the delay outputs, and a 'hold' of 'sample' reads it
-- there; the network outputs its input (and none of the hold's value,
-- which it evaluates at every sample).
readNowAndThen :: SF Double Double -> SF Double Double
readNowAndThen sf =
  (identity &&& (loop (second sf >>> arr (\(a, y) -> (y, a))) >>> sample 1 >>> hold 0))
    >>> arr (\(a, h) -> a + 0 * h)

-- The network for a collection: the input plus the read output (zero).
collectionNetwork :: SF Double Double -> SF Double Double
collectionNetwork sf = (identity &&& sf) >>> arr (uncurry (+))

samples :: Int
samples = 1000000

-- Switches whose continuation calls the same switch again, the usual way
-- of writing a switch that recurs: each switches at every sample (dt = 1,
-- an event after 0.5 s), resuming the signal function it froze, so the
-- output is the time, 0, 1, 2, ... A wrapper added at every switch made
-- each later step cost one layer more: quadratic time, and 56 bytes a
-- switch kept.
selfSwitching :: [(String, SF () Double)]
selfSwitching =
  [ ("kSwitch",   ks localTime)
  , ("dkSwitch",  dks localTime)
  , ("pSwitchB",  psw [localTime] >>> arr sum)
  , ("dpSwitchB", dpsw [localTime] >>> arr sum)
  ]
  where
    ks sf = kSwitch sf (arr fst >>> after 0.5 ()) (\sf' _ -> ks sf')
    dks sf = dkSwitch sf (arr fst >>> after 0.5 ()) (\sf' _ -> dks sf')
    psw sfs = pSwitchB sfs (arr fst >>> after 0.5 ()) (\sfs' _ -> psw sfs')
    dpsw sfs = dpSwitchB sfs (arr fst >>> after 0.5 ()) (\sfs' _ -> dpsw sfs')

-- How many samples (and switches) the self-switching cases run.
switchSamples :: Int
switchSamples = 100000

-- | Runs the named case's network for 10^6 samples at dt = 0.01 on the
-- inputs 0, 1, 2, ... and prints the sum of its outputs.
-- A self-switching case (named @self NAME@) runs 10^5 samples at dt = 1.
child :: String -> IO ()
child name = case (lookup name cases, lookup name [ ("self " ++ n, sf) | (n, sf) <- selfSwitching ]) of
  (Just sf, _) -> print (foldl' (+) 0 (embed sf (0, [ (0.01, Just (fromIntegral i)) | i <- [1 .. samples - 1] ])))
  (_, Just sf) -> print (foldl' (+) 0 (embed sf ((), replicate (switchSamples - 1) (1, Nothing))))
  _ | name == "afterEach over one long step" ->
        -- (10^7 occurrences of 1 ms passed in one step of 10^4 s)
        print (map (event 0 id) (embed (afterEach (repeat (0.001, 1 :: Double))) ((), [(1e4, Nothing), (0.001, Nothing)])))
  _            -> ioError (userError ("unknown child " ++ show name))

cases :: [(String, SF Double Double)]
cases = [ (n, delayNetwork sf) | (n, sf) <- delays ]
     ++ [ (n ++ " read once a second", readNowAndThen sf) | (n, sf) <- delays ]
     ++ [ (n, collectionNetwork sf) | (n, sf) <- collections ]

spec :: Spec
spec = do
  describe "a delay in a loop, its output discarded, for 10^6 samples" $
    mapM_ (\(name, _) -> it (name ++ " runs in 16 MB of heap (+RTS -M16m)") (bounded name)) delays
  describe "a delay in a loop, its output read once a second, for 10^6 samples" $
    mapM_ (\(name, _) -> it (name ++ " runs in 16 MB of heap (+RTS -M16m)") (bounded (name ++ " read once a second"))) delays
  describe "a collection with a member nobody reads, for 10^6 samples" $
    mapM_ (\(name, _) -> it (name ++ " runs in 16 MB of heap (+RTS -M16m)") (bounded name)) collections
  describe "afterEach, a step that passes 10^7 occurrences" $
    it "passes them in 2 MB of heap (+RTS -M2m; gathered, they took 240 MB)" $ do
      (code, out, err) <- run "2m" "afterEach over one long step"
      (code, err, out) `shouldBe` (ExitSuccess, "", "[0.0,1.0,1.0]\n")
  describe "a switch whose continuation calls it again, switching at each of 10^5 samples" $
    mapM_ (\(name, _) -> it (name ++ " runs in 2 MB of heap (+RTS -M2m)") (selfBounded name)) selfSwitching
  where
    run limit name = do
      self <- getExecutablePath
      environment <- getEnvironment
      readCreateProcessWithExitCode
        (proc self ["+RTS", "-M" ++ limit, "-RTS"]) { env = Just ((childVariable, name) : environment) } ""
    bounded name = do
      (code, out, err) <- run "16m" name
      (code, err) `shouldBe` (ExitSuccess, "")
      -- every network outputs its input: 0 + 1 + ... + (10^6 - 1)
      read out `shouldBe` (fromIntegral (samples * (samples - 1) `div` 2) :: Double)
    selfBounded name = do
      (code, out, err) <- run "2m" ("self " ++ name)
      (code, err) `shouldBe` (ExitSuccess, "")
      -- the time at each sample: 0 + 1 + ... + (10^5 - 1)
      read out `shouldBe` (fromIntegral (switchSamples * (switchSamples - 1) `div` 2) :: Double)
