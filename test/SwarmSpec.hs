-- | The swarm of the Enki comparison (bench/Swarm.hs, bench/enki.sh): its
-- worlds are valid, at the coverage asked for, with no two robots
-- touching; its controller turns away from what it senses; and a run
-- keeps the robots moving.
module SwarmSpec (spec) where

import           Data.List             (foldl')
import           Test.Hspec

import           AFrob
import           AFrobRobotSim
import           Swarm

-- The three cases of bench/enki.sh.
cases :: [(Int, Double)]
cases = [(10, 0.02), (100, 0.2), (1000, 0.02)]

spec :: Spec
spec = do
  describe "swarmWorld" $ do
    mapM_ (\(n, c) -> it (show n ++ " robots at coverage " ++ show c ++ ": valid, apart, at that coverage") $
      case swarmWorld n c of
        Nothing -> expectationFailure "no world"
        Just w  -> do
          length w `shouldBe` n
          validateWorldIn (swarmBounds n c) w `shouldBe` Right ()
          let r    = simbotDiameter / 2
              side = swarmSide n c
          abs (fromIntegral n * pi * r * r / (side * side) - c) `shouldSatisfy` (< 1e-9)
          minimum (pairDistances (map otPos w)) `shouldSatisfy` (> simbotDiameter))
      cases
    it "is Nothing when the lattice cannot hold the robots apart" $
      fmap length (swarmWorld 100 0.75) `shouldBe` Nothing

  describe "swarmController" $ do
    let wheels ranges = case embed (swarmController (SimbotProperties SimbotA 1)) (input ranges, []) of
          SimbotOutput (DriveWheels l r) _ : _ -> Just (l, r)
          _                                    -> Nothing
        withWheels ranges k = maybe (expectationFailure "no wheel command") k (wheels ranges)
        free = const rangeFinderMax
    it "drives straight ahead at the same speed on both wheels when nothing is near" $
      withWheels free $ \(l, r) -> do
        l `shouldBe` r
        l `shouldSatisfy` (> 0)
    it "turns left, away from an obstacle at its front right" $
      withWheels (\a -> if a == -pi / 4 then 0.2 else rangeFinderMax) $ \(l, r) ->
        r - l `shouldSatisfy` (> 0.1)
    it "turns right, away from an obstacle at its front left" $
      withWheels (\a -> if a == pi / 4 then 0.2 else rangeFinderMax) $ \(l, r) ->
        l - r `shouldSatisfy` (> 0.1)
    it "turns on the spot, backing the left wheel, before a wall dead ahead" $
      withWheels (\a -> if abs a < 0.3 then 0 else rangeFinderMax) $ \(l, r) -> do
        l `shouldSatisfy` (< 0)
        r `shouldSatisfy` (> 0)
    it "ignores what is beyond its reach" $
      wheels (\a -> if abs a < 0.3 then 0.9 else rangeFinderMax) `shouldBe` wheels free

  describe "a run of the 100-robot case" $
    it "keeps most robots moving for 10 s" $
      case swarmWorld 100 0.2 of
        Nothing -> expectationFailure "no world"
        Just w  -> do
          let cfg   = defaultSimConfig { simDt = 0.01, simBounds = swarmBounds 100 0.2 }
              final = simulateWith cfg w swarmController swarmController !! 1000
              moved = length [ () | (o, rs) <- zip w (wsRobots final)
                                  , norm (robotPos rs .-. otPos o) > 0.5 ]
          moved `shouldSatisfy` (> 50)

-- Every distance between two of the points.
pairDistances :: [Position2] -> [Double]
pairDistances ps = go ps
  where
    go []       = []
    go (p : qs) = foldl' (\acc q -> norm (p .-. q) : acc) [] qs ++ go qs

-- A sample with the given range finder and nothing else of note.
input :: (Angle -> Distance) -> SimbotInput
input ranges = SimbotInput
  { siBattery  = BSHigh
  , siStuck    = False
  , siPosition = Point2 0 0
  , siHeading  = 0
  , siRange    = ranges
  , siMaxRange = rangeFinderMax
  , siRobots   = []
  , siBalls    = []
  , siKey      = Nothing
  }
