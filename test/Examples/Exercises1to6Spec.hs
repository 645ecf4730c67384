-- |
-- The answers to Exercises 1 to 6 ("Exercises.Ex01" ... "Exercises.Ex06")
-- against the library, the notes' equations and the notes' own
-- definitions: fixed cases and properties on random inputs and time
-- steps.
module Examples.Exercises1to6Spec (spec) where

import           Data.List        (findIndex, zip4)

import           Test.Hspec       hiding (after)
import           Test.QuickCheck

import           AFrob            hiding (forAll)
import           AFrobRobotSim

import qualified Exercises.Ex01   as Ex01
import qualified Exercises.Ex02   as Ex02
import qualified Exercises.Ex03   as Ex03
import qualified Exercises.Ex04   as Ex04
import qualified Exercises.Ex05   as Ex05
import qualified Exercises.Ex06   as Ex06
import           Examples.Registry (allExamples, exampleListing)
import           Examples.Types   (Example (..))
import qualified Paper.Section2   as S2
import           Paper.Section2   (arcPath, scriptedInput, wheelBase)
import           TestUtil

------------------------------------------------------------------------------
-- Stateful signal functions to plug into the combinators of Exercise 1.

data Stateful = Stateful String (SF Double Double)

instance Show Stateful where
  show (Stateful name _) = name

statefuls :: [Stateful]
statefuls =
  [ Stateful "integral" integral
  , Stateful "iPre 7" (iPre 7)
  , Stateful "derivative" derivative
  , Stateful "count rising edges (accumHold)" (arr (> 0) >>> edge >>> arr (`tag` (+ 1)) >>> accumHold 0)
  , Stateful "input plus localTime" ((identity &&& localTime) >>> arr2 (+))
  , Stateful "identity, switching into integral" ((identity &&& (arr (> 0.5) >>> edge)) `switch` \() -> integral)
  ]

genStateful :: Gen Stateful
genStateful = elements statefuls

run :: SF a b -> [(DTime, a)] -> [b]
run = runSamples

------------------------------------------------------------------------------
-- Exercises 2 and 3: the notes' equations summed by hand.

-- | The Euler sums of theta = (1/l) (integral (vr - vl)) and
-- y = (1/2) (integral ((vr + vl) * sin theta)), left rectangle rule: the
-- value at sample n uses the inputs up to sample n - 1.
eulerThetaY :: [DTime] -> [Double] -> [Double] -> ([Double], [Double])
eulerThetaY dts vrs vls = (thetas, ys)
  where
    steps   = drop 1 dts
    iThetas = scanl (\acc (dt, r, l) -> acc + dt * (r - l)) 0 (zip3 steps vrs vls)
    thetas  = map (/ wheelBase) iThetas
    iYs     = scanl (\acc (dt, r, l, th) -> acc + dt * ((r + l) * sin th)) 0 (zip4 steps vrs vls thetas)
    ys      = map (/ 2) iYs

-- Random poses (x, y, heading) with random time steps, and the inputs at
-- those poses.
genPoseSamples :: Gen [(DTime, (Double, Double, Heading))]
genPoseSamples = genSamples ((,,) <$> choose (-5, 5) <*> choose (-5, 5) <*> choose (-pi, pi))

atPoses :: [(DTime, (Double, Double, Heading))] -> [(DTime, SimbotInput)]
atPoses samples = [ (dt, scriptedInput (Point2 x y) h False Nothing) | (dt, (x, y, h)) <- samples ]

shouldAllApprox :: [Double] -> [Double] -> Property
shouldAllApprox xs ys = counterexample (show xs ++ "\n /= " ++ show ys)
                                       (length xs == length ys && and (zipWith (approxWith 1e-7) xs ys))

------------------------------------------------------------------------------
-- Exercise 5: a robot status with a scripted velocity.

data Probe = Probe
  { probeSpeed :: Double
  , probeStuck :: Bool
  } deriving (Show)

instance HasRobotStatus Probe where
  rsBattStat _ = BSHigh
  rsIsStuck    = probeStuck

-- The alarm by hand: distances d_n = d_(n-1) + dt_n |v_(n-1)|; an event
-- TravelledFar where d_n > d first holds, GotStuck where the robot gets
-- stuck (not at sample 0), TravelledFar if both.
referenceAlarm :: Double -> [(DTime, Probe)] -> [Event Ex05.AlarmCause]
referenceAlarm d samples = zipWith lMerge far (NoEvent : stuckEs)
  where
    probes  = map snd samples
    dists   = scanl (\acc (dt, p) -> acc + dt * abs (probeSpeed p)) 0
                    (zip (drop 1 (map fst samples)) probes)
    over    = map (> d) dists
    far     = zipWith (\was is -> if is && not was then Event Ex05.TravelledFar else NoEvent)
                      (False : over) over
    stucks  = map probeStuck probes
    stuckEs = zipWith (\was is -> if is && not was then Event Ex05.GotStuck else NoEvent)
                      stucks (drop 1 stucks)

genProbes :: Gen [(DTime, Probe)]
genProbes = genSamples (Probe <$> choose (-1, 1) <*> frequency [(4, pure False), (1, pure True)])

------------------------------------------------------------------------------

spec :: Spec
spec = do
  describe "Exercise 1" $ do
    it "(a) firstA sf = first sf for stateful sf (property)" $
      property $ forAll genStateful $ \(Stateful _ sf) ->
        forAll (genSamples ((,) <$> arbitrary <*> (arbitrary :: Gen Int))) $ \samples ->
          run (Ex01.firstA sf) samples === run (first sf) samples
    it "(b) parA f g = f *** g for stateful f, g (property)" $
      property $ forAll genStateful $ \(Stateful _ f) -> forAll genStateful $ \(Stateful _ g) ->
        forAll (genSamples ((,) <$> arbitrary <*> arbitrary)) $ \samples ->
          run (Ex01.parA f g) samples === run (f *** g) samples
    it "(c) fanA f g = f &&& g for stateful f, g (property)" $
      property $ forAll genStateful $ \(Stateful _ f) -> forAll genStateful $ \(Stateful _ g) ->
        forAll (genSamples arbitrary) $ \samples ->
          run (Ex01.fanA f g) samples === run (f &&& g) samples
    it "are the plain-function combinators for (->) (fixed)" $ do
      Ex01.firstA (+ 1) (1 :: Int, 'x') `shouldBe` (2, 'x')
      Ex01.parA (+ 1) not (1 :: Int, True) `shouldBe` (2, False)
      Ex01.fanA (+ 1) show (1 :: Int) `shouldBe` (2, "1")

  describe "Exercises 2 and 3" $ do
    it "thetaSF is (n - 1) w dt on a circle, past pi (fixed)" $ do
      -- The estimate of w is 0 at time 0 and w after; the integral lags one sample.
      let ins      = arcPath 0.5 0.5 [ 0.1 * fromIntegral k | k <- [0 .. 80 :: Int] ]
          expected = 0 : [ 0.05 * fromIntegral (k - 1) | k <- [1 .. 80 :: Int] ]
      runDt 0.1 Ex02.thetaSF ins `shouldApproxList` expected
      runDt 0.1 Ex03.thetaSF ins `shouldApproxList` expected
    it "ySF follows the circle's y to within 1.5 cm (fixed)" $ do
      let ts  = [ 0.01 * fromIntegral k | k <- [0 .. 1200 :: Int] ]
          ins = arcPath 0.5 0.5 ts
          ys  = map (point2Y . odometryPosition) ins
      maximum (zipWith (\a b -> abs (a - b)) (runDt 0.01 Ex02.ySF ins) ys) < 0.015 `shouldBe` True
    it "the unsugared and the arrow-syntax definitions agree (property)" $
      property $ forAll genPoseSamples $ \poses -> let ins = atPoses poses in
        run Ex02.thetaSF ins === run Ex03.thetaSF ins .&&. run Ex02.ySF ins === run Ex03.ySF ins
    it "are the Euler sums of the notes' equations (property)" $
      property $ forAll genPoseSamples $ \poses ->
        let ins          = atPoses poses
            (thetas, ys) = eulerThetaY (map fst ins) (run S2.vrSF ins) (run S2.vlSF ins)
        in run Ex02.thetaSF ins `shouldAllApprox` thetas .&&. run Ex02.ySF ins `shouldAllApprox` ys
          .&&. run Ex03.thetaSF ins `shouldAllApprox` thetas .&&. run Ex03.ySF ins `shouldAllApprox` ys

  describe "Exercise 4" $ do
    it "xspdNegated negates the speed once (fixed)" $
      runDt 0.5 (Ex04.xspdNegated 0.5) (stuckIns [False, True, False, True, False])
        `shouldBe` [0.5, -0.5, -0.5, -0.5, -0.5]
    it "xspd negates the speed at every stuck event (fixed)" $
      runDt 0.5 (Ex04.xspd 0.5) (stuckIns [True, False, True, True, False, True, False])
        `shouldBe` [0.5, 0.5, -0.5, -0.5, -0.5, 0.5, 0.5]
    it "bounces a simbot between two walls, turning round at every stuck event (simulated)" $ do
      let dt     = 0.01
          states = take 4001 (simulate dt Ex04.bounceWorld Ex04.bounceController Ex04.bounceController)
          robots = map (head . wsRobots) states
          -- what the controller saw, sample by sample
          ins    = [ scriptedInput (robotOdometry r) (robotHeading r) (robotStuck r) Nothing | r <- robots ]
          speeds = runDt dt (Ex04.xspd 0.5) ins
          events = [ k | (k, Event ()) <- zip [0 :: Int ..] (runDt dt rsStuck ins) ]
          flips  = [ k | (k, a, b) <- zip3 [1 :: Int ..] speeds (drop 1 speeds), a /= b ]
          wallXs = [ point2X (robotPos (robots !! k)) | k <- events ]
      length events `shouldSatisfy` (>= 4)
      head speeds `shouldBe` 0.5
      flips `shouldBe` events
      and [ b == negate a | (a, b) <- zip speeds (drop 1 speeds), a /= b ] `shouldBe` True
      -- stuck alternately at the right wall and the left one, right first
      map signum wallXs `shouldBe` take (length events) (cycle [1, -1])
      all (\x -> abs x > 1.6) wallXs `shouldBe` True
      -- and the robot really moves with the sign of the commanded speed
      -- once it has had 3 s to turn round
      and [ signum (robotSpeed r) == signum s
          | (k, r, s) <- zip3 [0 :: Int ..] robots speeds
          , all (\e -> k < e || k > e + 300) events, k > 300 ]
        `shouldBe` True

  describe "Exercise 5" $ do
    it "matches the alarm computed by hand on random runs (property)" $
      property $ forAll (choose (0.01, 3)) $ \d -> forAll genProbes $ \samples ->
        run (Ex05.alarmCause d (arr probeSpeed)) samples === referenceAlarm d samples
    it "fires for the distance exactly once, iff the distance exceeds d (property)" $
      property $ forAll (choose (0.01, 3)) $ \d -> forAll genProbes $ \samples ->
        let outs  = run (Ex05.alarmCause d (arr probeSpeed)) samples
            dists = run (Ex05.travelled (arr probeSpeed)) samples
            fars  = length [ () | Event Ex05.TravelledFar <- outs ]
            far   = any (> d) dists
        in cover 20 far "travels more than d" $ cover 20 (not far) "travels d or less" $
             fars === (if far then 1 else 0)
    it "firstAlarm is the first alarm only, whichever its cause (property)" $
      property $ forAll (choose (0.01, 3)) $ \d -> forAll genProbes $ \samples ->
        let expected = referenceAlarm d samples
            firstIx  = findIndex isEvent expected
        in run (Ex05.firstAlarm d (arr probeSpeed)) samples
             === [ if Just k == firstIx then e else NoEvent | (k, e) <- zip [0 ..] expected ]
    it "alarm is alarmCause without the cause (property)" $
      property $ forAll (choose (0.01, 3)) $ \d -> forAll genProbes $ \samples ->
        run (Ex05.alarm d (arr probeSpeed)) samples
          === map (`tag` ()) (run (Ex05.alarmCause d (arr probeSpeed)) samples)
    it "travelled too far first: at the first sample past d, then when stuck (fixed)" $ do
      -- 0.5 m/s, samples every 0.25 s: 0.125 m per step, exact sums
      let ins = [ scriptedInput (Point2 (0.125 * fromIntegral (min k 10)) 0) 0 (k >= 11) Nothing
                | k <- [0 .. 13 :: Int] ]
          outs = runDt 0.25 (Ex05.alarmCause 1 S2.forwardVelSF) ins
      [ (k, e) | (k, Event e) <- zip [0 :: Int ..] outs ]
        `shouldBe` [(10, Ex05.TravelledFar), (11, Ex05.GotStuck)]
    it "stuck first: the distance still fires later; firstAlarm only once (fixed)" $ do
      -- stuck at samples 3 and 4, not moving in the step to 4
      let ins = [ scriptedInput (Point2 (0.125 * fromIntegral (if k >= 4 then k - 1 else k)) 0) 0
                                (k == 3 || k == 4) Nothing
                | k <- [0 .. 14 :: Int] ]
          outs  = runDt 0.25 (Ex05.alarmCause 1 S2.forwardVelSF) ins
          firstOnly = runDt 0.25 (Ex05.firstAlarm 1 S2.forwardVelSF) ins
      [ (k, e) | (k, Event e) <- zip [0 :: Int ..] outs ]
        `shouldBe` [(3, Ex05.GotStuck), (11, Ex05.TravelledFar)]
      [ (k, e) | (k, Event e) <- zip [0 :: Int ..] firstOnly ] `shouldBe` [(3, Ex05.GotStuck)]

  describe "Exercise 6" $ do
    it "vel with dSwitch equals the notes' rec/drSwitch vel on random key streams (property)" $
      property $ forAll (choose (-5, 5)) $ \v0 -> forAll (genSamples genKey) $ \samples ->
        let ins = [ (dt, scriptedInput origin 0 False k) | (dt, k) <- samples ]
        in run (Ex06.vel v0) ins === run (S2.vel v0) ins
    it "is v0 plus the presses strictly before each sample (property)" $
      property $ forAll (choose (-5, 5)) $ \v0 -> forAll (genSamples genKey) $ \samples ->
        let ins     = [ (dt, scriptedInput origin 0 False k) | (dt, k) <- samples ]
            presses = map (\e -> if isEvent e then 1 else 0) (run S2.incrVelEvs ins)
        in run (Ex06.vel v0) ins `shouldAllApprox` map (v0 +) (scanl (+) 0 (init presses))
    it "ex6-robot is driven by the keyboard: still without keys, faster after each +" $ do
      let e = head [ x | x@RobotExample {} <- Ex06.examples ]
          runWith ks = simulateWith defaultSimConfig { simKeys = ks } (exWorld e)
                                    (exControllerA e) (exControllerB e)
          xAt :: [(Double, Char)] -> Double -> Double
          xAt ks t = let Point2 x _ = robotPos (head (wsRobots (runWith ks !! round (t / 0.01)))) in x
          keyed = exKeys e
      keyed `shouldBe` [(1, '+'), (3, '+'), (5, '+')]
      xAt [] 6 `shouldBe` xAt [] 0
      -- metres covered in each 2 s after a press grow with the presses
      let legs = [ xAt keyed (t + 2) - xAt keyed t | t <- [1, 3, 5] ]
      legs `shouldSatisfy` (\ls -> and (zipWith (<) ls (drop 1 ls)) && head ls > 0)
      concatMap wsMessages (take 601 (runWith keyed))
        `shouldBe` [ "[" ++ t ++ "] SimbotA.1: t = " ++ t ++ " s: + pressed, speed " ++ v ++ " m/s from now on"
                   | (t, v) <- [("1.00", "0.25"), ("3.00", "0.50"), ("5.00", "0.75")] ]
    it "--list says what each example takes: nothing, flags, or flags and keys" $ do
      let ls = lines (exampleListing allExamples)
          rowOf n = head [ l | l <- ls, takeWhile (/= ' ') l == n ]
      words (rowOf "ex6") !! 1 `shouldBe` "-"
      words (rowOf "ex7") !! 1 `shouldBe` "flags"
      take 3 (words (rowOf "ex6-robot")) `shouldBe` ["ex6-robot", "flags,", "keys"]
      length [ () | e@RobotExample {} <- allExamples, not (null (exKeys e)) ] `shouldSatisfy` (>= 1)
  where
    stuckIns bs = [ scriptedInput origin 0 b Nothing | b <- bs ]
    genKey = frequency [(3, pure Nothing), (2, pure (Just '+')), (1, pure (Just 'a'))]
