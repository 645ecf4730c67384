-- | Frames captured and made later: the same frames as made at once, and
-- their bytes read back to every bit.
module AFrobRobotSim.Log.CaptureSpec (spec) where

import qualified Data.ByteString          as BS
import           Test.Hspec

import           AFrob                    (BatteryStatus (..))
import           AFrobRobotSim            (WorldState (..))
import           AFrobRobotSim.Log
import           AFrobRobotSim.LogFixture

spec :: Spec
spec = do
  let cfg = fixtureConfig { lcScores = \s -> [("tenths", floor (wsTime s * 10 + 1e-9))] }
      rates = [(1, 25), (2, 12.5), (3, 25 / 3), (7, 25 / 7)] :: [(Int, Double)]
      stepAll lr (s : ss) = let (lr', ps) = logRatesStepPending cfg lr s in ps : stepAll lr' ss
      stepAll _ []        = []
      captured = stepAll (logRatesStart cfg rates) fixtureStates
      make = pendingFrameMaker cfg
  describe "logRatesStepPending and pendingFrameMaker" $ do
    it "make at each rate exactly logFrames at that rate, events and the hostile message included (fixed)" $
      mapM_ (\(k, fps) -> [ make p | ps <- captured, (ks, p) <- ps, k `elem` ks ]
                            `shouldBe` logFrames cfg { lcFps = fps } fixtureStates)
            rates
    it "group a step's rates as logRatesStep does" $
      map (map fst) captured `shouldBe` map (map fst) (stepAllFrames cfg rates)
    it "make the same lines from the captures' bytes read back (fixed)" $ do
      let ps = [ p | step <- captured, (_, p) <- step ]
      length ps `shouldSatisfy` (> 50)
      map (fmap (encodeLogLineBytes . LineFrame . make) . decodePending . encodePending) ps
        `shouldBe` map (Just . encodeLogLineBytes . LineFrame . make) ps

  describe "encodePending and decodePending" $ do
    let robot = CapturedRobot "Simbot\233" 7 (0 / 0) (-0.0) (1 / 0) (-(1 / 0)) True 5e-324 1.7976931348623157e308
                              (-1e-300) BSCritical 0.1
        odd' = PendingFrame (FrameCapture 0.30000000000000004 [robot, robot { crBattery = BSLow, crStuck = False }]
                                          [(1 / 3, -2)] [("s\1114111", -3), ("", maxBound)])
                            [ LogEvent 2.5 "bump" (Just ("SimbotB", -1)) "line\nbreak \"quoted\" </script>"
                            , LogEvent 0 "score" Nothing "" ]
                            ["[0.50] SimbotA.1: \955", ""]
        bytes = encodePending odd'
    it "read back every number to its bit (NaN, -0, infinities, subnormals) and every character (fixed)" $ do
      fmap encodePending (decodePending bytes) `shouldBe` Just bytes
      let texts (PendingFrame c evs ls) = (map crType (fcRobots c), fcScores c, evs, ls)
      fmap texts (decodePending bytes) `shouldBe` Just (texts odd')
    it "reads nothing from bytes cut short or with bytes left over (fixed)" $ do
      [ k | k <- [0 .. BS.length bytes - 1], decodePending (BS.take k bytes) /= Nothing ] `shouldBe` []
      decodePending (bytes <> BS.singleton 0) `shouldBe` Nothing
  where
    stepAllFrames cfg rates = go (logRatesStart cfg rates) fixtureStates
      where
        go lr (s : ss) = let (lr', fs) = logRatesStep cfg lr s in fs : go lr' ss
        go _ []        = []
