-- | "AFrobRobotSim.Physics": what its other claims do not cover elsewhere
-- (the motion itself is checked against the all-pairs reference in
-- "AFrobRobotSim.SpatialIndexSpec", and its laws in
-- "AFrobRobotSim.SimulatorSpec").
module AFrobRobotSim.PhysicsSpec (spec) where

import           GHC.Float             (castDoubleToWord64)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Geometry
import           AFrobRobotSim.Physics
import           AFrobRobotSim.Robot    (DriveCommand (..))
import           AFrobRobotSim.World
import           AFrobRobotSim.WorldGen (emptyArena, genCommand)

-- | The bits of a number: tells -0 from 0, which '==' does not.
bits :: Double -> Word
bits = fromIntegral . castDoubleToWord64

-- | A robot's cached cos and sin are, bit for bit, those of its heading.
cacheAgrees :: Robot -> Property
cacheAgrees r =
  counterexample (show r) $
    (bits (rCos r), bits (rSin r)) === (bits (cos (rHeading r)), bits (sin (rHeading r)))

-- | Headings that stress the cache: zeros of both signs, the wrap-around
-- at pi, and anything in between.
genHeading :: Gen Double
genHeading = oneof
  [ elements [0, -0, pi, -pi, pi - 1e-12, -pi + 1e-12, pi / 2]
  , choose (-pi, pi) ]

-- | A robot alone in the middle of an empty 10 m world.
genLoneRobot :: Gen Robot
genLoneRobot = do
  k  <- elements [SimbotA, SimbotB]
  h  <- genHeading
  v  <- choose (-0.5, 0.5)
  pure (mkRobot k 1 (Point2 0 0) h v False 1)

spec :: Spec
spec = do
  describe "mkRobot" $
    it "caches the cos and sin of the heading" $
      property $ forAll genLoneRobot cacheAgrees

  describe "withHeading" $
    it "turns the robot and its cached cos and sin together" $
      property $ forAll genLoneRobot $ \r -> forAll genHeading $ \h ->
        let r' = withHeading h r in rHeading r' === h .&&. cacheAgrees r'

  describe "wheelCommand" $ do
    it "counts a non-finite command as 0" $ do
      wheelCommand 0.5 2 (DriveWheels (0 / 0) (1 / 0)) `shouldBe` (0, 0)
      wheelCommand 0.5 2 (DriveTR (0 / 0) 1) `shouldBe` (0, 0)
      wheelCommand 0.5 2 (DriveTR 1 (1 / 0)) `shouldBe` (0, 0)
    it "clamps the wheels of a finite DriveTR whose v -/+ w l/2 overflows" $ do
      -- (the overflowing wheel counted as 0: full speed on one wheel only)
      wheelCommand 0.5 2 (DriveTR 1.7e308 1.7e308) `shouldBe` (2, 2)
      wheelCommand 0.5 2 (DriveTR (-1.7e308) 1.7e308) `shouldBe` (-2, -2)

  describe "stepRobots" $
    it "keeps every robot's cached cos and sin those of its heading, step after step" $
      property $ forAll genLoneRobot $ \r0 -> forAll (vectorOf 40 genCommand) $ \cs ->
        let rs = scanl (\r c -> head' (stepRobots 0.05 emptyArena [(r, c)])) r0 cs
        in conjoin (map cacheAgrees rs)
  where
    head' rs = case rs of
      [r] -> r
      _   -> error ("stepRobots: expected one robot, got " ++ show (length rs))
