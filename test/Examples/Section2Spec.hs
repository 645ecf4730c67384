-- |
-- The section-2 definitions of "Paper.Section2" on fixed scripted inputs:
-- the odometry estimates of the wheel speeds, the notes' xSF and xSF',
-- the conditional sf, xspd, alarmSF, alarmCountSF and vel, each pinned to
-- its outputs (fixed), and xSF = xSF' on random motions (property).
module Examples.Section2Spec (spec) where

import           Test.Hspec      hiding (after)
import           Test.QuickCheck

import           AFrob           hiding (forAll)
import           AFrobRobotSim   (SimbotInput)

import           Paper.Section2
import           TestUtil

-- Inputs at the given poses, not stuck, no key.
poses :: [(Double, Double, Heading)] -> [SimbotInput]
poses ps = [ scriptedInput (Point2 x y) h False Nothing | (x, y, h) <- ps ]

-- A straight line from the origin along the heading h at 1 m/s, sampled
-- every 0.5 s.
line :: Heading -> Int -> [SimbotInput]
line h n = poses [ (s * cos h, s * sin h, h) | k <- [0 .. n - 1], let s = 0.5 * fromIntegral k ]

stuckIns :: [Bool] -> [SimbotInput]
stuckIns bs = [ scriptedInput origin 0 b Nothing | b <- bs ]

keyIns :: [Maybe Char] -> [SimbotInput]
keyIns ks = [ scriptedInput origin 0 False k | k <- ks ]

-- Inputs at the given distances from the radiator (on the x axis).
atDistances :: [Double] -> [SimbotInput]
atDistances rs = [ scriptedInput (Point2 r 0) 0 False Nothing | r <- rs ]

spec :: Spec
spec = do
  describe "vrSF and vlSF (odometry estimates)" $ do
    it "are the forward speed on a straight line (fixed)" $ do
      runDt 0.5 vrSF (line 0 4) `shouldApproxList` [0, 1, 1, 1]
      runDt 0.5 vlSF (line 0 4) `shouldApproxList` [0, 1, 1, 1]
    it "are negative when reversing (fixed)" $ do
      let back = poses [ (0, -0.5 * k, pi / 2) | k <- [0 .. 3] ]
      runDt 0.5 vrSF back `shouldApproxList` [0, -1, -1, -1]
      runDt 0.5 vlSF back `shouldApproxList` [0, -1, -1, -1]
    it "are v + w l/2 and v - w l/2 when turning in place, across the heading's cut at pi (fixed)" $ do
      -- 0.1 rad every 0.5 s: w = 0.2 rad/s, so the wheels run at +-0.05 m/s.
      let turn = poses [ (0, 0, 3.0 + 0.1 * k) | k <- [0 .. 4] ]
      map (\i -> odometryHeading i < 0) turn `shouldBe` [False, False, True, True, True]
      runDt 0.5 vrSF turn `shouldApproxList` [0, 0.05, 0.05, 0.05, 0.05]
      runDt 0.5 vlSF turn `shouldApproxList` [0, -0.05, -0.05, -0.05, -0.05]
    it "recover the wheel speeds of a circle to within 1e-3 (fixed)" $ do
      let outs f = drop 1 (runDt 0.01 f (arcPath 0.5 0.5 [ 0.01 * fromIntegral k | k <- [0 .. 700 :: Int] ]))
      all (\v -> abs (v - 0.625) < 1e-3) (outs vrSF) `shouldBe` True
      all (\v -> abs (v - 0.375) < 1e-3) (outs vlSF) `shouldBe` True
    it "unwrapAngle makes the heading continuous (fixed)" $
      runDt 1 unwrapAngle [3.0, 3.1, normalizeAngle 3.2, normalizeAngle 3.3, 3.1, -3.1]
        `shouldApproxList` [3.0, 3.1, 3.2, 3.3, 3.1, 2 * pi - 3.1]

  describe "xSF and xSF'" $ do
    it "integrate the speed along x, one sample behind the estimate (fixed)" $ do
      runDt 0.5 xSF  (line 0 5) `shouldApproxList` [0, 0, 0.5, 1.0, 1.5]
      runDt 0.5 xSF' (line 0 5) `shouldApproxList` [0, 0, 0.5, 1.0, 1.5]
    it "take the cosine of the heading (fixed)" $ do
      runDt 0.5 xSF  (line (pi / 3) 5) `shouldApproxList` [0, 0, 0.25, 0.5, 0.75]
      runDt 0.5 xSF' (line (pi / 3) 5) `shouldApproxList` [0, 0, 0.25, 0.5, 0.75]
    it "are 0 when turning in place (fixed)" $
      runDt 0.5 xSF (poses [ (0, 0, 0.3 * k) | k <- [0 .. 4] ]) `shouldApproxList` [0, 0, 0, 0, 0]
    it "agree on random motions and time steps (property)" $
      property $ forAll (genSamples genPose) $ \samples ->
        let ins = [ (dt, scriptedInput (Point2 x y) h False Nothing) | (dt, (x, y, h)) <- samples ]
        in runSamples xSF ins === runSamples xSF' ins

  describe "sf (the conditional)" $ do
    it "chooses at every sample, all three running all the time (fixed)" $
      runDt 0.5 (sf (arr rsIsStuck) (constant 0) time) (stuckIns [False, False, True, True, False])
        `shouldApproxList` [0, 0.5, 0, 0, 2.0]
    it "keeps the state of the branch not chosen (fixed)" $
      -- integral of 1 runs on while the flag chooses the constant.
      runDt 0.5 (sf (arr rsIsStuck) (constant (-1)) (constant 1 >>> integral))
                (stuckIns [False, True, True, False, False])
        `shouldApproxList` [0, -1, -1, 1.5, 2.0]

  describe "sinAfresh (time begins afresh at a switch)" $
    it "is sin t until the first stuck event, then sin of the time since it: 0 at the event's sample" $
      -- (the samples every 0.5 s; stuck from the third, at t = 1)
      runDt 0.5 sinAfresh (stuckIns [False, False, True, True, False, True])
        `shouldBe` [sin 0, sin 0.5, sin 0, sin 0.5, sin 1, sin 1.5]
  describe "xspd" $ do
    it "switches to 0 at the first stuck event, for good (fixed)" $
      runDt 0.5 (xspd 0.5) (stuckIns [False, False, True, True, False, True])
        `shouldBe` [0.5, 0.5, 0, 0, 0, 0]
    it "ignores being stuck at time 0 (fixed)" $
      runDt 0.5 (xspd 0.5) (stuckIns [True, True, False, True])
        `shouldBe` [0.5, 0.5, 0.5, 0]

  describe "tempSF, alarmSF, alarmCountSF" $ do
    let rs = [2, 1, 0.3, 0, 0.3, 1, 0.2, 2]
    it "tempSF is 120 C at the radiator, 20 + 100/e at 1 m (fixed)" $
      runDt 1 tempSF (atDistances [0, 1, 10]) `shouldApproxList` [120, 20 + 100 / exp 1, 20]
    it "alarmSF fires when the temperature rises above 100 (fixed)" $
      runDt 1 alarmSF (atDistances rs)
        `shouldBe` [NoEvent, NoEvent, Event (), NoEvent, NoEvent, NoEvent, Event (), NoEvent]
    it "alarmSF does not fire at time 0, even if hot then (fixed)" $
      runDt 1 alarmSF (atDistances [0, 0, 2, 0]) `shouldBe` [NoEvent, NoEvent, NoEvent, Event ()]
    it "alarmCountSF counts the alarms, from their instant (fixed)" $
      runDt 1 alarmCountSF (atDistances rs) `shouldBe` [0, 0, 1, 1, 1, 1, 2, 2]

  describe "incrVelEvs and vel" $ do
    it "incrVelEvs fires at every + press, not at a held + (fixed)" $
      runDt 0.5 incrVelEvs (keyIns [Nothing, Just '+', Just '+', Just 'a', Just '+', Nothing])
        `shouldBe` [NoEvent, Event (), NoEvent, NoEvent, Event (), NoEvent]
    it "vel adds 1 from the sample after each press (fixed)" $
      runDt 0.5 (vel 0) (keyIns [Nothing, Just '+', Nothing, Just '+', Just '+', Just 'a', Just '+', Nothing])
        `shouldBe` [0, 0, 1, 1, 2, 2, 2, 3]
    it "vel ignores a + already down at time 0 (fixed)" $
      runDt 0.5 (vel 3.5) (keyIns [Just '+', Nothing, Just '+', Nothing])
        `shouldBe` [3.5, 3.5, 3.5, 4.5]
  where
    genPose = (,,) <$> choose (-5, 5) <*> choose (-5, 5) <*> choose (-pi, pi)
