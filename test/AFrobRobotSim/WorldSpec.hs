-- | "AFrobRobotSim.World": a world's size and bounds ('worldBounds',
-- 'worldSize'), a robot in a big world, and a robot that can never start
-- inside a block or drive into one. The validation of worlds is tested
-- in "AFrobRobotSim.World.CheckSpec".
module AFrobRobotSim.WorldSpec (spec) where

import           Control.Exception (ErrorCall (..), evaluate)
import           Data.List         (isInfixOf)
import           Test.Hspec
import           Test.QuickCheck

import           AFrob             (constant, ddVelDiff, mrFinalize)
import           AFRP.Geometry
import           AFrobRobotSim

-- | Drive straight on at the given wheel speed.
straight :: Double -> SimbotController
straight v _ = constant (mrFinalize (ddVelDiff v v))

spec :: Spec
spec = do
  describe "world size (OTSize)" $ do
    it "worldBounds: the notes' 10 by 10 without a size, W by H centred on the origin with one" $ do
      worldBounds [] `shouldBe` notesBounds
      worldBounds [OTBall (Point2 0 0), OTSize 30 10] `shouldBe` Bounds (-15) (-5) 15 5
      worldBoundsOr (Bounds 0 0 4 2) [] `shouldBe` Bounds 0 0 4 2
      worldBoundsOr (Bounds 0 0 4 2) [OTSize 100 100] `shouldBe` Bounds (-50) (-50) 50 50
      worldSize [OTSize 100 20, OTBall (Point2 0 0)] `shouldBe` Just (100, 20)
    it "a robot in a 100 m world drives far beyond the notes' walls and stops at its own" $ do
      let far = simulate 0.01 [OTSize 100 100, OTSimbotA 1 (Point2 0 0) 0] (straight 1) (straight 1) !! 3000
          Point2 x _ = robotPos (head (wsRobots far))
      x `shouldSatisfy` (> 20)
      let end = simulate 0.01 [OTSize 100 100, OTSimbotA 1 (Point2 45 0) 0] (straight 1) (straight 1) !! 2000
          Point2 x' _ = robotPos (head (wsRobots end))
      x' `shouldSatisfy` (\v -> v > 49 && v <= 50 - simbotDiameter / 2 + 1e-6)
  describe "robots and blocks" $ do
    it "never starts a robot inside a block: the simulation refuses the world" $
      evaluate (head (simulate 0.01 [OTBlock (Point2 0 0), OTSimbotA 1 (Point2 0.1 0) 0]
                                (straight 1) (straight 1)))
        `shouldThrow` (\(ErrorCall msg) -> "SimbotA 1 at (0.1, 0.0) overlaps block at (0.0, 0.0)" `isInfixOf` msg)
    it "never lets a robot that starts outside a block drive into it" $
      withMaxSuccess 40 $ forAll genStart $ \(p, h) ->
        let world = [OTBlock (Point2 0 0), OTSimbotB 1 p h]
            run   = take 301 (simulate 0.01 world (straight 2) (straight 2))
            gap r = let Point2 x y = robotPos r
                        dx = max 0 (abs x - 0.25)
                        dy = max 0 (abs y - 0.25)
                    in sqrt (dx * dx + dy * dy)
        in validateWorld world == Right () ==>
             minimum [ gap r | s <- run, r <- wsRobots s ] >= 0.25 - 1e-6
  where
    genStart = do
      a <- choose (0, 2 * pi)
      d <- choose (0.5, 1.5)
      h <- choose (-pi, pi)
      pure (Point2 (d * cos a) (d * sin a), a + pi + h / 4)
