-- | The ported Yampa bouncing ball ("Ported.BouncingBall"), checked against
-- the physics worked out by hand (g = 9.81, dropped from 10 m, speed
-- damped by 0.9 at each bounce), within the error of Euler steps of 0.01 s.
module Ported.BouncingBallSpec (spec) where

import           Test.Hspec

import           Ported.BouncingBall
import           TestUtil

-- | Five seconds of the ball, sampled every 0.01 s.
run5s :: [(Pos, Vel)]
run5s = runDt 0.01 (bouncingBall 10) (replicate 501 ())

-- | The sample indices where the velocity turns from downwards to upwards.
bounces :: [(Pos, Vel)] -> [Int]
bounces yvs = [i | (i, (_, v0), (_, v1)) <- zip3 [1 ..] yvs (drop 1 yvs), v0 < 0, v1 > 0]

spec :: Spec
spec = describe "the Yampa bouncing ball" $ do
  it "never sinks below the floor by more than one step of motion" $
    minimum (map fst run5s) `shouldSatisfy` (> -0.15)
  it "bounces twice in five seconds, first at about sqrt (20 / 9.81) = 1.43 s, then 2.57 s later" $ do
    let bs = bounces run5s
    length bs `shouldBe` 2
    map ((* 0.01) . (fromIntegral :: Int -> Double)) bs `shouldSatisfy` \ts ->
      and (zipWith (\t e -> abs (t - e) < 0.05) ts [1.43, 1.43 + 2.57])
  it "rises to about 0.81 of its previous height after a bounce" $ do
    let afterFirst = drop (head (bounces run5s)) run5s
        peak = maximum (map fst (take 250 afterFirst))
    peak `shouldSatisfy` (\p -> abs (p - 8.1) < 0.2)
