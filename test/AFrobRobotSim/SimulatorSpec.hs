{-# LANGUAGE Arrows               #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- Every run of "every core" must be computed where it stands, not shared
-- with an equal expression computed on another number of capabilities.
{-# OPTIONS_GHC -fno-full-laziness -fno-cse #-}
-- | The simulation engine, checked against hand-computed physics.
module AFrobRobotSim.SimulatorSpec (spec) where

import           Control.Concurrent (myThreadId)
import           Control.Exception (ArithException (..), AsyncException (..), ErrorCall (..), Exception (..), evaluate,
                                    SomeException, finally, throw, try)
import           System.Exit       (ExitCode (..))
import qualified Data.ByteString   as BS
import qualified Data.ByteString.Char8 as BC
import           Data.IORef        (atomicModifyIORef', newIORef, readIORef)
import           Data.List         (isInfixOf, isPrefixOf, isSuffixOf, sort, tails)
import           Data.Maybe        (isJust)
import qualified Data.Set          as Set
import           GHC.Conc          (getNumCapabilities)
import           GHC.IO.Handle     (hDuplicate, hDuplicateTo)
import           System.Directory  (createDirectory, listDirectory)
import           System.FilePath   ((</>))
import           System.IO         (IOMode (..), hClose, hFlush, stdout, withFile)
import           System.IO.Unsafe  (unsafePerformIO)
import           System.Mem        (performMajorGC)
import           System.Mem.Weak   (deRefWeak, mkWeakPtr)
import           Test.Hspec        hiding (after)

import           AFrob             hiding (forAll)
import           AFrobRobotSim
import           AFrobRobotSim.Simulator (forceWorldState, keyAtStep)
import           TestUtil (withCaps, withTempDir)

-- | The snapshot at (about) time t of a run with step dt.
at :: DTime -> Double -> [WorldState] -> WorldState
at dt t states = states !! round (t / dt)

robot1 :: WorldState -> RobotState
robot1 = head . wsRobots

px, py :: RobotState -> Double
px r = let Point2 x _ = robotPos r in x
py r = let Point2 _ y = robotPos r in y

driveAt :: Velocity -> Velocity -> SimbotController
driveAt vl vr _ = constant (mrFinalize (ddVelDiff vl vr))

idle :: SimbotController
idle _ = constant (mrFinalize ddBrake)

-- | A controller that prints, at every sample, the show of a reading.
reporting :: Show x => (SimbotInput -> x) -> SimbotController
reporting f _ = arr (\i -> mrFinalize (ddBrake `mrMerge` tcoPrintMessage (Event (show (f i)))))

-- | The reading printed at the first sample by 'reporting'.
firstReading :: Read x => [WorldState] -> x
firstReading states = read (drop 2 (dropWhile (/= ':') (head (wsMessages (head states)))))

within :: Double -> Double -> Double -> Bool
within tol expected x = abs (x - expected) <= tol

spec :: Spec
spec = do
  describe "kinematics" $ do
    let world = [OTSimbotA 1 (Point2 (-4) 0) 0]
        run   = simulate 0.01 world (driveAt 0.5 0.5) idle
    it "ramps up at the maximum acceleration (0.2 m/s^2 for a SimbotA)" $ do
      robotSpeed (robot1 (at 0.01 1 run)) `shouldSatisfy` within 1e-9 0.2
      let speeds = map (robotSpeed . robot1) (take 400 run)
      maximum (zipWith (-) (drop 1 speeds) speeds) `shouldSatisfy` (<= 0.2 * 0.01 + 1e-12)
    it "then covers v * t in a straight line" $ do
      -- ramp: 2.5 s to 0.5 m/s covering 0.625 m; then 0.5 m/s
      px (robot1 (at 0.01 6 run)) `shouldSatisfy` within 1e-6 (-4 + 0.625 + 0.5 * 3.5)
      py (robot1 (at 0.01 6 run)) `shouldSatisfy` within 1e-12 0
    it "clamps each wheel to the maximum wheel speed" $ do
      let fast = simulate 0.01 world (driveAt 10 10) idle
      robotSpeed (robot1 (at 0.01 7 fast)) `shouldSatisfy` within 1e-9 1.0
    it "turns on a circle of radius v / w with ddVelTR" $ do
      let tr    = simulate 0.01 [OTSimbotB 1 (Point2 0 0) 0] idle (\_ -> constant (mrFinalize (ddVelTR 0.5 0.5)))
          after2 = [ robotPos (robot1 s) | s <- take 1300 (drop 200 tr) ]
          (c, r) = circleThrough (after2 !! 0) (after2 !! 400) (after2 !! 800)
      r `shouldSatisfy` within 1e-6 1.0
      all (\p -> within 1e-6 1.0 (norm (p .-. c))) after2 `shouldBe` True
    it "stops the run at a NaN or infinite wheel speed, naming the robot, the time and the command" $ do
      -- (it was taken for 0: the robot stood still, silently)
      let failsWith cmd = evaluate (length (show (take 300 (simulate 0.01 world (driveAt cmd 1) idle))))
            `shouldThrow` (\e -> ceRobotType e == "SimbotA" && ceRobotId e == 1 && ceTime e == 0
                                 && "not finite" `isInfixOf` show (ceCause e))
      failsWith (0 / 0)
      failsWith (1 / 0)
      failsWith (-1 / 0)
    it "startRobotStates gives the robots of the run's state at time 0" $ do
      let w = [ OTSimbotB 2 (Point2 1 1) 4, OTBall (Point2 0 0), OTSimbotA 1 (Point2 (-3) 2) (-7), OTBlock (Point2 3 3) ]
      startRobotStates w `shouldBe` wsRobots (head (simulate 0.01 w (driveAt 1 0.5) idle))
      map robotHeading (startRobotStates w) `shouldSatisfy` all (\h -> h >= -pi && h < pi)
    it "names a command that is not finite by the function that makes it, not by its constructor (it said DriveTR)" $ do
      let says c text = evaluate (length (show (take 3 (simulate 0.01 world c idle))))
            `shouldThrow` (\e -> displayException (ceCause e) == text)
          tr v w _ = constant (mrFinalize (ddVelTR v w))
      says (tr (0 / 0) 0) "its wheel command is not finite: ddVelTR NaN 0.0 (translational and rotational speeds)"
      says (driveAt 0.1 (1 / 0)) "its wheel command is not finite: ddVelDiff 0.1 Infinity (left and right wheel speeds)"
    it "shows a controller's failure as the sentence the run prints, not as a record" $ do
      let e = ControllerError "SimbotB" 3 2.5 (toException (ErrorCall "boom"))
      show e `shouldBe` "the controller of SimbotB 3 failed at t = 2.500 s: boom"
      displayException e `shouldBe` show e

  describe "what a controller's messages and exceptions hold, evaluated in its step" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0]
        saying m _ = constant (mrFinalize (ddVelDiff 0.1 0.1 `mrMerge` tcoPrintMessage (Event m)))
        failing x _ = constant (mrFinalize (ddVelDiff x 0.1))
        failsWith c check = evaluate (length (show (take 3 (simulate 0.01 world c idle))))
          `shouldThrow` (\e -> ceRobotType e == "SimbotA" && ceRobotId e == 1 && ceTime e == 0
                               && check (displayException (ceCause e)))
    it "a message that raises past its first character fails the robot's step, not the run's outputs" $ do
      failsWith (saying ("hello " ++ error "lazy boom")) ("lazy boom" `isInfixOf`)
      failsWith (saying ("bye " ++ throw ExitSuccess)) (== "ExitSuccess")
    it "an endless message is cut after 10,000 characters, with a note" $ do
      let m = concat (wsMessages (head (simulate 0.01 world (saying (cycle "ab")) idle)))
      length (takeWhile (`elem` "ab") (drop (length ("[0.00] SimbotA.1: " :: String)) m)) `shouldBe` 10000
      m `shouldSatisfy` (" ... (cut: longer than 10000 characters)" `isSuffixOf`)
    it "an exception whose message itself raises, or never ends, is shown as far as it can be" $ do
      failsWith (failing (error ("bad: " ++ show (head ([] :: [Int])))))
                (== "an exception whose message itself failed (ErrorCall)")
      failsWith (failing (error (cycle "x")))
                (\t -> take 3 t == "xxx" && " ... (cut: longer than 10000 characters)" `isSuffixOf` t)
      -- (a short one keeps its type: the cause is what was thrown)
      evaluate (length (show (take 3 (simulate 0.01 world (failing (1 `div` (0 :: Int) `seq` 1)) idle))))
        `shouldThrow` (\e -> fmap (== DivideByZero) (fromException (ceCause e)) == Just True)

  describe "collisions" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0, OTVWall (Point2 2 0)]
        ouch _ = proc sbi -> do
          e <- rsStuck -< sbi
          returnA -< mrFinalize (ddVelDiff 1 1 `mrMerge` tcoPrintMessage (tag e "Ouch!!"))
        run = take 1500 (simulate 0.01 world ouch idle)
    it "a robot driving at a wall stops short of it, and stays stuck" $ do
      let r = robot1 (last run)
      px r `shouldSatisfy` (<= 1.95 - 0.25)
      px r `shouldSatisfy` (>= 1.95 - 0.25 - 1e-6)
      robotStuck r `shouldBe` True
      robotSpeed r `shouldBe` 0
    it "with exactly one stuck event" $
      length [ m | s <- run, m <- wsMessages s, "Ouch!!" `isInfixOf` m ] `shouldBe` 1
    it "never tunnels through a thin wall, even with huge time steps" $ do
      let big = take 40 (simulate 0.5 [OTSimbotB 1 (Point2 0 0) 0, OTVWall (Point2 2 0)] idle (driveAt 2 2))
      all (\s -> px (robot1 s) <= 1.95 - 0.25) big `shouldBe` True
    it "two robots driving at each other stop without overlapping" $ do
      let duel = simulate 0.01 [OTSimbotA 1 (Point2 (-1) 0) 0, OTSimbotA 2 (Point2 1 0) pi]
                          (driveAt 1 1) idle
      case wsRobots (at 0.01 8 duel) of
        [a, b] -> do
          norm (robotPos a .-. robotPos b) `shouldSatisfy` (>= 0.5 - 1e-6)
          (robotStuck a, robotStuck b) `shouldBe` (True, True)
        rs -> expectationFailure ("expected two robots, got " ++ show rs)
    it "the boundary walls stop a robot" $ do
      let edge' = simulate 0.01 [OTSimbotB 1 (Point2 3 0) 0] idle (driveAt 2 2)
      px (robot1 (at 0.01 6 edge')) `shouldSatisfy` within 1e-6 4.75

  describe "range finder" $ do
    let world = [ OTSimbotA 1 (Point2 0 0) 0, OTVWall (Point2 2 0), OTBlock (Point2 0 2)
                , OTSimbotB 1 (Point2 0 (-1.5)) 0 ]
        angles = [0, pi / 2, pi, -pi / 2, atan2 1.75 0.2, pi / 4]
        readings = firstReading (simulate 0.01 world (reporting (\i -> map (rfRange i) angles)) idle)
    it "measures from the robot's edge to the true shapes" $
      and (zipWith (within 1e-9) [1.7, 1.5, 3, 1.0, sqrt (0.2 ^ (2 :: Int) + 1.75 ^ (2 :: Int)) - 0.25, 3] readings)
        `shouldBe` True
    it "reports its maximum range" $
      firstReading (simulate 0.01 world (reporting rfMaxRange) idle) `shouldBe` (3 :: Double)
    it "rfFront, rfLeft, rfBack and rfRight look at 0, pi/2, pi and -pi/2" $
      firstReading (simulate 0.01 world (reporting (\i -> [rfFront i, rfLeft i, rfBack i, rfRight i])) idle)
        `shouldBe` take 4 (readings :: [Double])

  describe "animate object tracker" $ do
    let world = [ OTSimbotA 1 (Point2 0 0) (pi / 2), OTSimbotB 7 (Point2 1 1) 0
                , OTBall (Point2 (-2) 0), OTSimbotB 8 (Point2 4.5 4.5) 0 ]
    it "gives other robots within range by relative angle and distance" $ do
      case firstReading (simulate 0.01 world (reporting aotOtherRobots) idle) of
        [(ty, i, a, d)] -> do
          (ty, i) `shouldBe` ("SimbotB", 7 :: Int)
          a `shouldSatisfy` within 1e-12 (-pi / 4)
          d `shouldSatisfy` within 1e-12 (sqrt 2)
        other -> expectationFailure ("expected one robot, got " ++ show other)
    it "gives balls within range" $ do
      case firstReading (simulate 0.01 world (reporting aotBalls) idle) :: [(Double, Double)] of
        [(a, d)] -> do
          a `shouldSatisfy` within 1e-12 (pi / 2)
          d `shouldSatisfy` within 1e-12 2
        other -> expectationFailure ("expected one ball, got " ++ show other)

  describe "balls" $ do
    let world = [OTSimbotB 1 (Point2 (-1) 0) 0, OTBall (Point2 0 0), OTVWall (Point2 2.5 0)]
        kick = take 1000 (simulate 0.01 world idle (\_ -> (constant (mrFinalize (ddVelDiff 1 1)) &&& after 2.0 ())
                                                        `switch` const (constant (mrFinalize ddBrake))))
        ballX s = case wsBalls s of
          Point2 x _ : _ -> x
          []             -> error "no ball"
    it "are kicked by a robot, bounce off a wall and slow down" $ do
      let xs = map ballX kick
          far = maximum xs
      far `shouldSatisfy` (<= 2.45 - 0.15 + 1e-6)       -- never inside the wall
      far `shouldSatisfy` (>= 2.45 - 0.15 - 1e-3)       -- but reached it
      last xs `shouldSatisfy` (< far - 0.1)              -- and came back
    it "collide elastically with each other" $ do
      let two = take 600 (simulate 0.01 [OTSimbotB 1 (Point2 (-1) 0) 0, OTBall (Point2 0 0), OTBall (Point2 1 0)] idle
                            (\_ -> (constant (mrFinalize (ddVelDiff 1 1)) &&& after 2.0 ())
                                     `switch` const (constant (mrFinalize (ddVelDiff (-1) (-1))))))
      case wsBalls (last two) of
        [Point2 x1 _, Point2 x2 _] -> do
          x2 `shouldSatisfy` (> 1.5)          -- the second ball was hit and moved on
          x1 `shouldSatisfy` (< x2 - 0.3)     -- the first stayed behind
        other -> expectationFailure ("expected two balls, got " ++ show other)

    it "are never pushed through a wall by a robot" $ do
      let squeeze = take 300 (simulate 0.02 [OTVWall (Point2 2 0), OTBall (Point2 1.8 0), OTSimbotB 1 (Point2 0 0) 0]
                                       idle (driveAt 2 2))
      maximum [ x | s <- squeeze, Point2 x _ <- wsBalls s ] `shouldSatisfy` (<= 1.95 - 0.15 + 1e-6)
    it "are never pushed out of the world" $ do
      let corner = take 300 (simulate 0.02 [OTBall (Point2 4.84 4.84), OTSimbotB 1 (Point2 3 3) (pi / 4)]
                                      idle (driveAt 2 2))
      maximum [ max x y | s <- corner, Point2 x y <- wsBalls s ] `shouldSatisfy` (<= 5 - 0.15 + 1e-6)

    it "are put where a referee (simBallRule) says, at rest; a rule that loses a ball, puts one outside the world or throws stops the run with a RefereeError saying so" $ do
      let w       = [OTBall (Point2 1 0), OTBall (Point2 (-1) 0), OTSimbotA 1 (Point2 0 3) 0]
          withRule rule = take 20 (simulateWith defaultSimConfig { simDt = 0.1, simBallRule = rule } w idle idle)
          -- from t = 1 the balls go to (2, 2) and (-2, -2)
          moveAt1 t _ = if t >= 0.95 then Just [Point2 2 2, Point2 (-2) (-2)] else Nothing
          failsWith rule msg = do
            r <- try (evaluate (length (show (map wsBalls (withRule rule)))))
            case r of
              Left (e :: RefereeError) -> displayException e `shouldSatisfy` (msg `isInfixOf`)
              Right _                  -> expectationFailure "the run went on"
      map wsBalls (withRule moveAt1) !! 10 `shouldBe` [Point2 2 2, Point2 (-2) (-2)]
      map wsBalls (withRule moveAt1) !! 9 `shouldBe` [Point2 1 0, Point2 (-1) 0]
      failsWith (\t _ -> if t >= 0.95 then Just [Point2 0 0] else Nothing)
                "the ball rule (simBallRule) failed at t = 1.000 s: it gave 1 position for 2 balls (it must give one for each)"
      failsWith (\_ _ -> Just [Point2 0 0, Point2 (0 / 0) 1])
                "the ball rule (simBallRule) failed at t = 0.100 s: it put ball 2 (in the list's order) at (NaN, 1.0), not a point where it lies inside the world [-5.0, 5.0] x [-5.0, 5.0]"
      failsWith (\_ _ -> Just [Point2 4.9 0, Point2 0 0])
                "put ball 1 (in the list's order) at (4.9, 0.0), not a point where it lies inside the world"
      failsWith (\t _ -> if t >= 0.55 then error "no ball here" else Nothing)
                "the ball rule (simBallRule) failed at t = 0.600 s: no ball here"

  describe "scores (simScores)" $ do
    let w = [OTBall (Point2 1 0), OTSimbotA 1 (Point2 0 3) 0]
        scored sf = take 20 (simulateWith defaultSimConfig { simDt = 0.1, simScores = sf } w idle idle)
    it "are none by default" $
      map wsScores (take 20 (simulate 0.1 w idle idle)) `shouldBe` replicate 20 []
    it "are the signal function's output on each snapshot, the first at time 0, stepped at the time step" $ do
      let tenths = localTime >>> arr (\t -> [("tenths", round (t * 10) :: Int), ("zero", 0)])
      map wsScores (scored tenths) `shouldBe` [ [("tenths", k), ("zero", 0)] | k <- [0 .. 19] ]
    it "see each snapshot (its balls, after the ball rule) and may keep state: a goal counted once" $ do
      let toGoal t _ = if t >= 0.95 && t < 1.05 then Just [Point2 4 0] else Nothing
          goals = proc ws -> do
            g <- edge -< any (\(Point2 x _) -> x > 3) (wsBalls ws)
            n <- accumHold 0 -< fmap (const (+ 1)) g
            returnA -< [("goals", n)]
          run = take 20 (simulateWith defaultSimConfig { simDt = 0.1, simBallRule = toGoal, simScores = goals } w idle idle)
      map wsScores run `shouldBe` replicate 10 [("goals", 0)] ++ replicate 10 [("goals", 1)]
      -- (the state the scores see is the snapshot, but for its scores)
      map (\s -> s { wsScores = [] }) run `shouldBe` take 20 (simulateWith defaultSimConfig { simDt = 0.1, simBallRule = toGoal } w idle idle)
    it "that throw, or give a name twice, stop the run with a RefereeError naming the time" $ do
      let failsWith sf msg = do
            r <- try (evaluate (foldr (\s acc -> forceWorldState s `seq` acc) () (scored sf)))
            case r of
              Left (e :: RefereeError) -> displayException e `shouldBe` msg
              Right _                  -> expectationFailure "the run went on"
      failsWith (localTime >>> arr (\t -> if t > 0.25 then errorWithoutStackTrace "no referee" else []))
                "the scores (simScores) failed at t = 0.300 s: no referee"
      failsWith (constant [("a", 1), ("b", 2), ("a", 3)])
                "the scores (simScores) failed at t = 0.000 s: it gave the score \"a\" twice (a name holds one score)"
      failsWith (constant [("big", 2 ^ (53 :: Int) + 1)])
                ("the scores (simScores) failed at t = 0.000 s: it gave the score \"big\" the value 9007199254740993, beyond "
                 ++ "2^53 (9007199254740992): the log and the result line write numbers as JSON's doubles, exact only within it")
      failsWith (constant [("endless", 1), (cycle "ab", 2)])
                ("the scores (simScores) failed at t = 0.000 s: it gave a score whose name is longer than 10000 characters ("
                 ++ show (take 40 (cycle "ab")) ++ "...)")
      map wsScores (scored (constant [("edge", 2 ^ (53 :: Int)), ("low", negate (2 ^ (53 :: Int))), (replicate 10000 'x', 0)]))
        `shouldSatisfy` all ((== 3) . length)
    it "that read a failing controller's messages let its ControllerError through (it was blamed on the scores)" $ do
      let loud _ = localTime >>> arr (\t -> mrFinalize (tcoPrintMessage (if t > 0.95 then Event (error "boom") else NoEvent)))
          run = take 20 (simulateWith defaultSimConfig { simDt = 0.1, simScores = arr (\ws -> [("chars", length (concat (wsMessages ws)))]) }
                                      w loud idle)
      r <- try (evaluate (foldr (\s acc -> foldr seq () (wsScores s) `seq` acc) () run))
      case r of
        Left (e :: SomeException) -> do
          fmap (\ce -> (ceRobotType ce, ceRobotId ce, ceTime ce)) (fromException e) `shouldBe` Just ("SimbotA", 1, 1.0)
          isRunFailure e `shouldBe` True
        Right _ -> expectationFailure "the run went on"
    it "are evaluated at every step, read or not (a run's memory stays bounded)" $ do
      let counted = localTime >>> arr (\t -> [("n", if t > 0.45 then error "evaluated" else 1)])
          run = take 10 (simulateWith defaultSimConfig { simDt = 0.1, simScores = counted } w idle idle)
      r <- try (evaluate (wsTime (last run)))
      case r of
        Left (e :: RefereeError) -> reTime e `shouldBe` 0.5
        Right _                  -> expectationFailure "the scores were left unevaluated"

  describe "battery" $
    it "goes low and then critical on a long run at full effort" $ do
      let run = simulate 0.1 [OTSimbotA 1 (Point2 0 0) 0] (\_ -> constant (mrFinalize (ddVelTR 0 4))) idle
          status t = robotBattery (robot1 (at 0.1 t run))
      map status [190, 210, 250, 265] `shouldBe` [BSHigh, BSLow, BSLow, BSCritical]

  describe "keyboard and console" $ do
    it "delivers scripted keys through tciKey, once per press" $ do
      let keys _ = proc sbi -> do
            k <- tciKeyDown -< sbi
            returnA -< mrFinalize (tcoPrintMessage (fmap (: []) k))
          run = take 200 (simulateWith defaultSimConfig { simKeys = [(0.5, 'a'), (1.0, 'b')] }
                            [OTSimbotA 1 (Point2 0 0) 0] keys idle)
      [ (wsTime s, m) | s <- run, m <- wsMessages s ] `shouldBe`
        [(0.5, "[0.50] SimbotA.1: a"), (1.0, "[1.00] SimbotA.1: b")]
    it "releases a key for a sample between two presses of it in a row, so that each press is an event" $ do
      -- (pressed on two samples running, the two presses read as one key
      -- held: tciKeyDown fired once)
      let keys _ = proc sbi -> do
            k <- tciKeyDown -< sbi
            returnA -< mrFinalize (tcoPrintMessage (fmap (: []) k))
          run = take 10 (simulateWith defaultSimConfig { simDt = 0.1, simKeys = [(0, 'a'), (0, 'a'), (0.1, 'b'), (0.1, 'b')] }
                            [OTSimbotA 1 (Point2 0 0) 0] keys idle)
      [ m | s <- run, m <- wsMessages s ] `shouldBe`
        ["[0.00] SimbotA.1: a", "[0.20] SimbotA.1: a", "[0.30] SimbotA.1: b", "[0.50] SimbotA.1: b"]
    it "keyAtStep presses the earliest due key, one a step, a repeated key after a step released" $ do
      keyAtStep 0.1 0 Nothing [(0, 'a'), (0, 'a')] `shouldBe` (Just 'a', [(0, 'a')])
      keyAtStep 0.1 1 (Just 'a') [(0, 'a')] `shouldBe` (Nothing, [(0, 'a')])
      keyAtStep 0.1 2 Nothing [(0, 'a')] `shouldBe` (Just 'a', [])
      keyAtStep 0.1 1 (Just 'a') [(0, 'b')] `shouldBe` (Just 'b', [])
      keyAtStep 0.1 1 Nothing [(0.2, 'b')] `shouldBe` (Nothing, [(0.2, 'b')])

  describe "odometry" $ do
    let world = [OTSimbotA 1 (Point2 (-3) 0) 0]
        run cfg = simulateWith cfg world (driveAt 0.4 0.5) idle
    it "is exact by default" $
      robotOdometry (robot1 (at 0.01 20 (run defaultSimConfig)))
        `shouldBe` robotPos (robot1 (at 0.01 20 (run defaultSimConfig)))
    it "drifts with noise, reproducibly from the seed" $ do
      let noisy s = robotOdometry (robot1 (at 0.01 20 (run defaultSimConfig { simOdometryNoise = 0.05, simSeed = s })))
          truth   = robotPos (robot1 (at 0.01 20 (run defaultSimConfig)))
      norm (noisy 1 .-. truth) `shouldSatisfy` (> 1e-4)
      noisy 1 `shouldBe` noisy 1
      noisy 1 `shouldNotBe` noisy 2

  describe "determinism" $
    it "a 10-robot, 60-second run repeated gives identical snapshots" $ do
      let world = [ OTSimbotA i (Point2 (fromIntegral i - 3) (-2)) (fromIntegral i) | i <- [1 .. 5] ]
               ++ [ OTSimbotB i (Point2 (fromIntegral i - 3) 2) (negate (fromIntegral i)) | i <- [1 .. 5] ]
               ++ [OTBall (Point2 0 0), OTBlock (Point2 3 3), OTHWall (Point2 (-3) 3.5)]
          wander rps = proc sbi -> do
            t <- localTime -< ()
            returnA -< mrFinalize (ddVelTR (rpWSMax rps / 2) (sin (t + fromIntegral (rpId rps)))
                                   `mrMerge` tcoPrintMessage (tag (if rfFront sbi < 0.3 then Event () else NoEvent) "near"))
          one = take 6001 (simulate 0.01 world wander wander)
          two = take 6001 (simulateWith defaultSimConfig world wander wander)
      one == two `shouldBe` True
      map robotPos (wsRobots (last one)) `shouldNotBe` map robotPos (wsRobots (head one))

  describe "memory" $
    -- (the template is made at run time, from a value read from an
    -- IORef, so that it is no constant of the program, which the
    -- collector never frees; the test is for the runtime's default
    -- collector: under +RTS --nonmoving-gc, whose major collections
    -- finish in the background, it may find them alive)
    it "a run does not keep its world template once it has started" $ do
      side <- newIORef (3 :: Double)
      x <- readIORef side
      let world = [ OTSimbotA i (Point2 (x - fromIntegral i) 0) 0 | i <- [1 .. 3] ] ++ [OTBall (Point2 0 x)]
      -- (watched: every cell of the list, from the first to the last, and
      -- every object in it)
      cells   <- mapM (`mkWeakPtr` Nothing) (init (tails world))
      objects <- mapM (`mkWeakPtr` Nothing) world
      let rest = drop 2 (simulate 0.1 world (const (constant (mrFinalize (ddVelTR 0.1 0)))) (const (constant mrDefault)))
      _ <- evaluate (forceWorldState (head rest))
      performMajorGC >> performMajorGC
      keptCells   <- length . filter isJust <$> mapM deRefWeak cells
      keptObjects <- length . filter isJust <$> mapM deRefWeak objects
      (keptCells, keptObjects, length cells, length objects) `shouldBe` (0, 0, 4, 4)
      -- (the run goes on after the collection: it was alive during it)
      wsTime (rest !! 3) `shouldSatisfy` (> 0.4)

  describe "every core" $ do
    -- 60 robots (four chunks on two capabilities) packed in the 10 m
    -- world with balls, noisy odometry and keys, every controller reading
    -- its range finders, tracker and bumper and printing messages
    let crowd = [ (if even k then OTSimbotA else OTSimbotB) (k `div` 2 + 1)
                    (Point2 (-4.3 + 0.75 * fromIntegral (k `mod` 12)) (-4.3 + 1.4 * fromIntegral (k `div` 12)))
                    (fromIntegral k)
                | k <- [0 .. 59 :: Int] ]
             ++ [ OTBall (Point2 (-3.9 + 0.75 * fromIntegral i) 3.2) | i <- [0 .. 9 :: Int] ]
             ++ [OTBlock (Point2 3 4.4), OTHWall (Point2 (-3) 4.5)]
        sensing rps = proc sbi -> do
          t <- localTime -< ()
          let near = take 3 (aotOtherRobots sbi)
              turn = sum [ if a > 0 then -0.3 else 0.3 | (_, _, a, d) <- near, d < 1 ]
              v    = rpWSMax rps / 3 * min 1 (rfFront sbi)
          ping <- repeatedly 0.5 () -< ()
          returnA -< mrFinalize (ddVelTR (if rsIsStuck sbi then -0.05 else v) (turn + 0.2 * sin (t + rfLeft sbi))
                                 `mrMerge` tcoPrintMessage (tag ping (show (rfRight sbi, near, take 1 (aotBalls sbi), tciKey sbi))))
        cfg = defaultSimConfig { simOdometryNoise = 0.02, simSeed = 7, simKeys = [(0.5, 'a'), (1.5, 'b')] }
        -- the text of a run's first n snapshots, on k capabilities (each
        -- call makes its run anew: the module is compiled without full
        -- laziness and common subexpressions)
        textOn k c world n = withCaps k (let r = show (take n (simulateWith c world sensing sensing))
                                         in evaluate (length r) >> pure r)
        -- on one capability and on two
        onOneAndTwo c world n = (,) <$> textOn (1 :: Int) c world n <*> textOn 2 c world n
        -- the failure of a run whose robots with the given numbers fail
        -- from t = 1, on k capabilities: its robot and time
        firstFailure :: SimConfig -> WorldTemplate -> [RobotId] -> Int -> IO (Maybe (RobotType, RobotId, Time))
        firstFailure c world ids k = do
          let failing rps = proc sbi -> do
                t <- localTime -< ()
                o <- sensing rps -< sbi
                returnA -< if t >= 1 && rpId rps `elem` ids then error "boom" else o
          r <- withCaps k (try (evaluate (length (show (take 200 (simulateWith c world failing failing))))))
          pure (either (\e -> Just (ceRobotType e, ceRobotId e, ceTime e)) (const Nothing) (r :: Either ControllerError Int))
    it "gives the same snapshots, bit for bit, on one capability and on two" $ do
      (one, two) <- onOneAndTwo cfg crowd 400
      length two `shouldBe` length one
      two `shouldBe` one
      length (concatMap wsMessages (take 400 (simulateWith cfg crowd sensing sensing))) `shouldSatisfy` (> 400)
    it "reports the failing controller that comes first in template order, as on one core" $ do
      one <- firstFailure cfg crowd [9, 27] 1
      two <- firstFailure cfg crowd [9, 27] 2
      one `shouldBe` Just ("SimbotA", 9, 1)
      withCaps 2 ((> 1) <$> getNumCapabilities) `shouldReturn` True
      two `shouldBe` one

    -- 130 robots over a 20 m world: on one capability they are stepped
    -- in chunks of 64 (the 60 above are stepped all at once), on two in
    -- chunks of 16
    let many = [ (if even k then OTSimbotA else OTSimbotB) (k `div` 2 + 1)
                   (Point2 (-9 + 1.4 * fromIntegral (k `mod` 13)) (-9 + 1.8 * fromIntegral (k `div` 13)))
                   (fromIntegral k)
               | k <- [0 .. 129 :: Int] ]
        big = cfg { simBounds = Bounds (-10) (-10) 10 10 }
    it "gives the same snapshots on one capability, where many robots are stepped in chunks, as on two" $ do
      (one, two) <- onOneAndTwo big many 250
      length two `shouldBe` length one
      two `shouldBe` one
      let final = wsRobots (last (take 250 (simulateWith big many sensing sensing)))
      length final `shouldBe` 130
      map robotId final `shouldBe` [ k `div` 2 + 1 | k <- [0 .. 129 :: Int] ]
    it "reports the failing controller that comes first in template order when many robots are stepped in chunks" $ do
      -- SimbotA 11 is the 21st robot (the first chunk), SimbotA 51 the
      -- 101st (the second)
      one <- firstFailure big many [51, 11] 1
      two <- firstFailure big many [51, 11] 2
      one `shouldBe` Just ("SimbotA", 11, 1)
      two `shouldBe` one

    it "leaves the positions before a failing step readable, and fails its messages, with any number of robots and capabilities" $ do
      let boom _ = arr (\_ -> error "boom") :: SF SimbotInput SimbotOutput
          check world k = withCaps k $ do
            let s0 = head (simulateWith big world boom boom)
            ps <- evaluate (map robotPos (wsRobots s0))
            ps `shouldBe` [ otPos o | o <- world ]
            r <- try (evaluate (length (wsMessages s0)))
            either (\e -> Just (ceRobotType e, ceRobotId e, ceTime e)) (const Nothing) r
              `shouldBe` Just ("SimbotA", 1, 0)
      mapM_ (uncurry check) [ (w, k) | w <- [take 1 many, take 40 many, many], k <- [1, 2] ]

    it "runSimWith writes the same frames, SVG, log, page, result and summary on one capability and on two" $ do
      let run dir = do
            createDirectory dir
            let opts = defaultSimOptions
                  { optSeconds = 1, optOut = dir, optQuiet = True, optFrames = True, optFps = 10
                  , optScale = Just 20, optOdometryNoise = 0.02, optSeed = 3, optKeys = [(0.5, 'a')]
                  , optSvg = Just (dir </> "run.svg"), optLog = Just (dir </> "run.jsonl")
                  , optReplay = Just (dir </> "run.html"), optResult = Just (dir </> "result.json") }
            summary <- stdoutOf (dir </> "stdout") (runSimWith opts (Just crowd) sensing sensing)
            names <- sort <$> listDirectory dir
            files <- mapM (\f -> (,) f . withoutRunVariables <$> BS.readFile (dir </> f))
                          (filter (/= "stdout") names)
            pure (files, withoutRunVariables (BC.pack (takeWhile (/= ',') summary)))
      withTempDir $ \dir -> do
        one <- withCaps 1 (run (dir </> "one"))
        two <- withCaps 2 (run (dir </> "two"))
        map fst (fst one) `shouldSatisfy` (\fs -> length (filter ("frame-" `isPrefixOf`) fs) == 11
                                                 && all (`elem` fs) ["run.svg", "run.jsonl", "run.html", "result.json"])
        map fst (fst two) `shouldBe` map fst (fst one)
        [ f | ((f, a), (_, b)) <- zip (fst one) (fst two), a /= b ] `shouldBe` []
        snd two `shouldBe` snd one

    -- The threads that computed a run's controller steps, on two
    -- capabilities, in blocks of 100 steps until the given test of them
    -- holds or 3000 steps are done.
    let threadsUntil c enough = withCaps 2 $ do
          seen <- newIORef Set.empty
          let noting rps = proc sbi -> do
                o <- sensing rps -< sbi
                returnA -< unsafePerformIO (myThreadId >>= \t -> atomicModifyIORef' seen (\s -> (Set.insert t s, ()))) `seq` o
              go run done = do
                -- (the positions need every controller's step)
                _ <- evaluate (sum [ x + y | ws <- take 100 run, r <- wsRobots ws, let Point2 x y = robotPos r ])
                ts <- readIORef seen
                if enough ts || done + 100 >= (3000 :: Int) then pure ts else go (drop 100 run) (done + 100)
          go (simulateWith c many noting noting) 0
    it "steps a run on the thread that reads it alone with simParallel False, whatever the capabilities" $ do
      me <- myThreadId
      alone <- threadsUntil big { simParallel = False } ((> 1) . Set.size)
      alone `shouldBe` Set.singleton me
      -- (the same run in parallel uses the workers, within those 3000
      -- steps even on a busy machine: what this test would see if the
      -- setting were ignored)
      shared <- threadsUntil big ((> 1) . Set.size)
      Set.size shared `shouldSatisfy` (> 1)
    it "gives the same snapshots with simParallel False as in parallel" $ do
      alone <- textOn 2 big { simParallel = False } many 250
      shared <- textOn 2 big many 250
      alone `shouldBe` shared

  describe "bad input" $ do
    it "rejects a robot outside the walls, naming it" $
      validateWorld [OTSimbotA 3 (Point2 4.9 0) 0] `shouldSatisfy` mentions "SimbotA 3"
    it "rejects two robots in one place" $
      validateWorld [OTSimbotA 1 (Point2 0 0) 0, OTSimbotB 1 (Point2 0.1 0) 0] `shouldSatisfy` mentions "overlap"
    it "rejects a duplicate id within a type" $
      validateWorld [OTSimbotB 2 (Point2 0 0) 0, OTSimbotB 2 (Point2 2 0) 0] `shouldSatisfy` mentions "SimbotB 2 at (2.0, 0.0) has the same id as SimbotB 2 at (0.0, 0.0)"
    it "rejects a NaN coordinate" $
      validateWorld [OTBall (Point2 (0 / 0) 0)] `shouldSatisfy` mentions "ball"
    it "accepts a good world" $
      validateWorld [OTSimbotA 1 (Point2 0 0) 0, OTSimbotA 2 (Point2 1 0) 0, OTBall (Point2 (-2) 1)] `shouldBe` Right ()
    it "simulate refuses an invalid world with every problem listed" $
      evaluate (head (simulate 0.01 [OTSimbotA 1 (Point2 9 0) 0, OTBlock (Point2 (0 / 0) 0)] idle idle))
        `shouldThrow` (\(ErrorCall msg) -> "SimbotA 1" `isInfixOf` msg && "block" `isInfixOf` msg)
    it "simulate refuses a time step beyond maxTimeStep and odometry noise beyond maxOdometryNoise" $ do
      let one = [OTSimbotA 1 (Point2 0 0) 0]
          cfg = defaultSimConfig
      evaluate (head (simulate (2 * maxTimeStep) one idle idle))
        `shouldThrow` (\(ErrorCall msg) -> "time step" `isInfixOf` msg)
      evaluate (head (simulateWith cfg { simOdometryNoise = 1e308 } one idle idle))
        `shouldThrow` (\(ErrorCall msg) -> "odometry noise" `isInfixOf` msg)
      length (take 3 (simulate maxTimeStep one idle idle)) `shouldBe` 3
    it "reports a controller that throws with its type, id and the time" $ do
      let bad _ = proc _ -> do
            t <- localTime -< ()
            let e = if t >= 1 then merge (Event "a") (Event "b") else NoEvent
            returnA -< mrFinalize (ddBrake `mrMerge` tcoPrintMessage e)
          run = simulate 0.01 [OTSimbotA 1 (Point2 0 0) 0, OTSimbotA 4 (Point2 2 0) 0]
                         (\rps -> if rpId rps == 4 then bad rps else idle rps) idle
      evaluate (length (concatMap wsMessages (take 300 run)))
        `shouldThrow` (\e -> ceRobotType e == "SimbotA" && ceRobotId e == 4 && within 1e-9 1 (ceTime e))
    it "lets an asynchronous exception (Ctrl-C) through as it is, not as the controller's failure" $ do
      let interrupted _ = proc _ -> do
            t <- localTime -< ()
            returnA -< if t >= 0.5 then throw UserInterrupt else mrFinalize ddBrake
          run = simulate 0.01 [OTSimbotA 1 (Point2 0 0) 0] interrupted idle
      evaluate (length (concatMap wsMessages (take 100 run))) `shouldThrow` (== UserInterrupt)
  where
    mentions s = either (any (s `isInfixOf`)) (const False)

-- A file's bytes without what differs between any two runs: the values
-- of \"wallTime\" (the run log's summary records the wall-clock time)
-- and of the replay page's script nonce (random for every page).
withoutRunVariables :: BS.ByteString -> BS.ByteString
withoutRunVariables = blank "\"wallTime\":" (`notElem` (",}" :: String))
                    . blank "nonce-" isHex . blank "nonce=\"" isHex
  where
    isHex c = c `elem` ("0123456789abcdef" :: String)
    blank key value b = case BS.breakSubstring (BC.pack key) b of
      (front, rest)
        | BS.null rest -> front
        | otherwise    -> front <> BC.pack key
                          <> blank key value (BC.dropWhile value (BS.drop (length key) rest))

-- What an action prints on stdout (through a file), as a string.
stdoutOf :: FilePath -> IO () -> IO String
stdoutOf file act = do
  withFile file WriteMode $ \h -> do
    hFlush stdout
    saved <- hDuplicate stdout
    (hDuplicateTo h stdout >> act) `finally` (hFlush stdout >> hDuplicateTo saved stdout >> hClose saved)
  s <- readFile file
  length s `seq` pure s

-- The centre and radius of the circle through three points.
circleThrough :: Point2 Double -> Point2 Double -> Point2 Double -> (Point2 Double, Double)
circleThrough (Point2 ax ay) (Point2 bx by) (Point2 cx cy) =
  let d  = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
      sq x y = x * x + y * y
      ux = (sq ax ay * (by - cy) + sq bx by * (cy - ay) + sq cx cy * (ay - by)) / d
      uy = (sq ax ay * (cx - bx) + sq bx by * (ax - cx) + sq cx cy * (bx - ax)) / d
      c  = Point2 ux uy
  in (c, norm (Point2 ax ay .-. c))
