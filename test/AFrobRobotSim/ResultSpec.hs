-- | The result line's tallies ("AFrobRobotSim.Result"): what each robot's
-- distance, bumps and stuck time count, on states made by hand, and the
-- same tallies on a real run that drives robots into a wall. (Reading
-- @--param@s and the result line through the runner are
-- "AFrobRobotSim.SweepSpec"'s.)
module AFrobRobotSim.ResultSpec (spec) where

import           Test.Hspec

import           AFRP.Geometry           (Point2 (..))
import           AFrob                   (BatteryStatus (..), RobotType, constant, ddVelDiff, mrFinalize)
import           AFrobRobotSim           (ObjectTemplate (..), simulate)
import           AFrobRobotSim.Options   (SimOptions (..), defaultSimOptions)
import           AFrobRobotSim.Result    (RobotTally (..), WorldSource (..), startTallies, stepTallies, worldSource,
                                          worldSourceName)
import           AFrobRobotSim.Simulator (RobotState (..), WorldState (..))

-- | A robot at @(x, y)@, stuck or not.
robotAt :: RobotType -> Double -> Double -> Bool -> RobotState
robotAt ty x y stuck = RobotState ty 1 (Point2 x y) 0 0 stuck BSHigh 1 (Point2 x y)

-- | The tallies after each of these states of one robot, the first at time
-- 0, at a time step of 0.5 s: distance, bumps and stuck time.
talliesOf :: [RobotState] -> [(Double, Int, Double)]
talliesOf [] = []
talliesOf (r0 : rs) = map view (scanl next (startTallies [r0]) rs)
  where
    next ts r = stepTallies 0.5 (WorldState 0 [r] [] [] []) ts
    view ts = case ts of
      [RobotTally _ d b st] -> (d, b, st)
      _                     -> (-1, -1, -1)

spec :: Spec
spec = do
  describe "worldSource" $ do
    it "tells the built-in default world from the program's own (both were \"default\"), and --world wins" $ do
      let file = defaultSimOptions { optWorldFile = Just "w.world" }
      map (worldSourceName . uncurry worldSource)
          [(defaultSimOptions, Nothing), (defaultSimOptions, Just ()), (file, Nothing), (file, Just ())]
        `shouldBe` ["default", "program", "w.world", "w.world"]
      worldSource file (Just ()) `shouldBe` WorldFile "w.world"
    it "writes a world file named default or program as ./default, ./program (it read as the built-in world, the program's own)" $
      map (worldSourceName . WorldFile) ["default", "program", "./default", "worlds/default", "defaults", "program/"]
        `shouldBe` ["./default", "./program", "./default", "worlds/default", "defaults", "program/"]
  describe "startTallies and stepTallies" $ do
    it "sum the straight-line steps of a robot's centre, not its displacement from the start" $
      -- (1 m out, 1 m back: 2 m travelled, none displaced)
      map (\(d, _, _) -> d) (talliesOf [robotAt "A" 0 0 False, robotAt "A" 1 0 False, robotAt "A" 0 0 False])
        `shouldBe` [0, 1, 2]

    it "count a bump each time a robot becomes stuck, not each step it stays stuck" $
      map (\(_, b, _) -> b) (talliesOf (map (robotAt "A" 0 0) [False, True, True, False, True, True, True]))
        `shouldBe` [0, 1, 1, 1, 2, 2, 2]

    it "count a robot stuck at time 0 as a bump, and its stuck time from the first step after it" $
      map (\(_, b, st) -> (b, st)) (talliesOf (map (robotAt "A" 0 0) [True, True, False]))
        `shouldBe` [(1, 0), (1, 0.5), (1, 0.5)]

    it "add the time step for every step a robot is stuck at" $
      map (\(_, _, st) -> st) (talliesOf (map (robotAt "A" 0 0) [False, True, True, False, True]))
        `shouldBe` [0, 0.5, 1, 1, 1.5]

    it "keep each robot's tally to itself, in template order" $ do
      let s0 = [robotAt "A" 0 0 False, robotAt "B" 5 5 True]
          s1 = WorldState 0.5 [robotAt "A" 3 4 True, robotAt "B" 5 5 True] [] [] []
      [ (robotType (tallyLast t), tallyDistance t, tallyBumps t, tallyStuck t) | t <- stepTallies 0.5 s1 (startTallies s0) ]
        `shouldBe` [("A", 5, 1, 0.5), ("B", 0, 1, 0.5)]

  describe "on a run" $
    it "tally a robot driven into a wall: one bump, and stuck from then to the end" $ do
      -- (one robot 1 m from the east wall, heading east at 0.5 m/s: it
      -- reaches the wall, speeding up, in under 4 s and stays against it
      -- to 10 s)
      let world = [OTSimbotA 1 (Point2 3.5 0) 0]
          states = take 1001 (simulate 0.01 world (const (constant (mrFinalize (ddVelDiff 0.5 0.5)))) (const (constant (mrFinalize (ddVelDiff 0 0)))))
          (first, rest) = case states of
            s : ss -> (s, ss)
            []     -> (WorldState 0 [] [] [] [], [])
          final = foldl (flip (stepTallies 0.01)) (startTallies (wsRobots first)) rest
          stuckSteps = length (filter (any robotStuck . wsRobots) rest)
      case final of
        [RobotTally r d b st] -> do
          b `shouldBe` 1
          robotStuck r `shouldBe` True
          -- (the stuck time is the steps it was stuck at, times the step)
          abs (st - 0.01 * fromIntegral stuckSteps) < 1e-9 `shouldBe` True
          stuckSteps > 500 `shouldBe` True
          -- (its centre travelled from x = 3.5 to the wall at 5 less its
          -- radius of 0.25)
          abs (d - 1.25) < 0.02 `shouldBe` True
        _ -> expectationFailure ("one tally expected, got " ++ show (length final))
