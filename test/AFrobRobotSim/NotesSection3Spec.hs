{-# LANGUAGE Arrows #-}
-- The listings are the notes' own code: they shadow Prelude's max, match
-- partially in a let (rcAlign) and dispatch on a few ids (rcA).
{-# OPTIONS_GHC -Wno-name-shadowing -Wno-incomplete-uni-patterns
                -Wno-incomplete-patterns -Wno-missing-signatures -Wno-unused-top-binds
                -Wno-type-defaults #-}
-- |
-- Every controller listing of section 3 of the notes, compiled against
-- "AFrob" and "AFrobRobotSim" and run in the simulator. The code is the
-- notes' own, re-indented where the typesetting lost the layout; the two
-- places where the printed code itself does not compile are marked.
module AFrobRobotSim.NotesSection3Spec (spec) where

import           Data.List    (isInfixOf, sortBy)
import           Test.Hspec   hiding (after)

import           AFrob        hiding (forAll)
import           AFrobRobotSim

------------------------------------------------------------------------------
-- 3.2 Robot controllers

rcA :: SimbotController
rcA rProps =
  case rpId rProps of
    1 -> rcA1 rProps
    2 -> rcA2 rProps
    3 -> rcA3 rProps

rcA1, rcA2, rcA3 :: SimbotController
rcA1 = rcStop
rcA2 = rcBlind2
rcA3 = rcTurn 0.2

------------------------------------------------------------------------------
-- 3.3 Basic robot movement

rcStop :: SimbotController
rcStop _ = constant (mrFinalize ddBrake)

rcBlind1 _ = constant (mrFinalize $ ddVelDiff 10 10)

rcBlind2 rps =
  let max = rpWSMax rps
  in constant (mrFinalize $ ddVelDiff (max/2) (max/2))

rcTurn :: Velocity -> SimbotController
rcTurn vel rps =
  let vMax = rpWSMax rps
      rMax = 2 * (vMax - vel) / rpDiameter rps
  in constant (mrFinalize $ ddVelTR vel rMax)

rcReverse :: Velocity -> SimbotController
rcReverse v rps = beh `dSwitch` const (rcReverse (-v) rps)
  where beh = proc sbi -> do
          stuckE <- rsStuck -< sbi
          let mr = ddVelDiff v v `mrMerge`
                   tcoPrintMessage (tag stuckE "Ouch!!")
          returnA -< (mrFinalize mr, stuckE)

-- The notes write @rcReverse' v _ = ...@ and then use @rps@, which that
-- pattern does not bind; we name the argument.
rcReverse' v rps =
  (rsStuck >>> arr fun) `dSwitch` const (rcReverse' (-v) rps)
  where fun stuckE =
          let mr = ddVelDiff v v `mrMerge`
                   tcoPrintMessage (tag stuckE "Ouch!!")
          in (mrFinalize mr, stuckE)

rcHeading :: Velocity -> Heading -> SimbotController
rcHeading vel hd rps =
  let vMax = rpWSMax rps
      vel' = lim vMax vel
      k    = 2
  in proc sbi -> do
    let he = normalizeAngle (hd - odometryHeading sbi)
    --     vel'' = (1 - abs he / pi) * vel'
    --     returnA -< mrFinalize (ddVelTR vel'' (k*he))
    returnA -< mrFinalize (ddVelTR vel' (k*he))

lim m y = max (-m) (min m y)

rcHeading' :: Velocity -> Heading -> SimbotController
rcHeading' vel hd rps =
  proc sbi -> do
    rcHeadingAux rps -< (sbi, vel, hd)

rcHeadingAux :: SimbotProperties ->
              SF (SimbotInput,Velocity,Heading) SimbotOutput
rcHeadingAux rps =
  let vMax = rpWSMax rps
      k    = 2
  in proc (sbi,vel,hd) -> do
    let vel' = lim vMax vel
        he   = normalizeAngle (hd - odometryHeading sbi)
    --      vel'' = (1 - abs he / pi) * vel'
    --      returnA -< mrFinalize (ddVelTR vel'' (k*he))
    returnA -< mrFinalize (ddVelTR vel' (k*he))

rcMoveTo :: Velocity -> Position2 -> SimbotController
rcMoveTo vd pd rps = proc sbi -> do
  let (d,h) = vector2RhoTheta (pd .-. odometryPosition sbi)
      vel   = if d>2 then vd else vd*(d/2)
  rcHeadingAux rps -< (sbi, vel, h)

rcFollowLeftWall :: Velocity -> Distance -> SimbotController
rcFollowLeftWall v d _ = proc sbi -> do
  let r = rfLeft sbi
  dr <- derivative -< r
  let omega = kp*(r-d) + kd*dr
      kd     = 5
      kp     = v*(kd^2)/4
  returnA -< mrFinalize (ddVelTR v (lim 0.2 omega))

rcAlign :: Velocity -> SimbotController
rcAlign v rps = proc sbi -> do
  let neighbors = sortBy (\(_,_,_,d1) (_,_,_,d2) -> compare d1 d2)
                        (aotOtherRobots sbi)
      (l1:l2:l3:_) = map (\(_,_,a,d) -> vector2Polar d a) neighbors
      vhat = vector2Polar v (odometryHeading sbi)
      heading l = vector2Theta (vhat ^+^ l)
  d11 <- derivative -< l1
  d12 <- derivative -< l2
  d13 <- derivative -< l3
  let hAvg = sum (map heading [d11,d12,d13]) / 3
  rcHeadingAux rps -< (sbi, v, hAvg)

------------------------------------------------------------------------------

robotAt :: Double -> [WorldState] -> RobotState
robotAt t states = head (wsRobots (states !! round (t / 0.01)))

posOf :: RobotState -> (Double, Double)
posOf r = let Point2 x y = robotPos r in (x, y)

spec :: Spec
spec = do
  it "rcStop keeps a simbot where it is" $
    posOf (robotAt 3 (simulate 0.01 [OTSimbotA 1 (Point2 0 0) 0] rcStop rcStop)) `shouldBe` (0, 0)
  it "rcBlind1 drives at the (clamped) maximum wheel speed" $
    robotSpeed (robotAt 8 (simulate 0.01 [OTSimbotA 1 (Point2 (-4) 0) 0] rcBlind1 rcStop))
      `shouldSatisfy` (\s -> abs (s - 1) < 1e-9)
  it "rcBlind2 drives at half the maximum wheel speed" $
    robotSpeed (robotAt 8 (simulate 0.01 [OTSimbotB 1 (Point2 (-4) 0) 0] rcStop rcBlind2))
      `shouldSatisfy` (\s -> abs (s - 1) < 1e-9)
  it "rcTurn turns as fast as it can at the given speed" $ do
    -- w_max = 2 (1.0 - 0.2) / 0.5 = 3.2 rad/s
    let r = robotAt 0.25 (simulate 0.01 [OTSimbotA 1 (Point2 0 0) 0] (rcTurn 0.2) rcStop)
    robotHeading r `shouldSatisfy` (\h -> abs (h - 3.2 * 0.25) < 1e-6)
  it "rcA dispatches on the robot id" $ do
    let s = robotAt 4 (simulate 0.01 [OTSimbotA 1 (Point2 0 0) 0, OTSimbotA 2 (Point2 0 2) 0] rcA rcStop)
    posOf s `shouldBe` (0, 0)
  it "rcReverse backs off and says Ouch!! every time it gets stuck" $ do
    let run = take 4000 (simulate 0.01 [OTSimbotA 1 (Point2 0 0) 0, OTVWall (Point2 1.5 0), OTVWall (Point2 (-1.5) 0)]
                                  (rcReverse 0.5) rcStop)
        ouches = [ m | s <- run, m <- wsMessages s, "Ouch!!" `isInfixOf` m ]
    length ouches `shouldSatisfy` (>= 2)
    all (\s -> let (x, _) = posOf (head (wsRobots s)) in abs x <= 1.45 - 0.25 + 1e-6) run `shouldBe` True
  it "rcReverse' behaves as rcReverse" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0, OTVWall (Point2 1.5 0)]
    map (map robotPos . wsRobots) (take 1500 (simulate 0.01 world (rcReverse' 0.5) rcStop))
      `shouldBe` map (map robotPos . wsRobots) (take 1500 (simulate 0.01 world (rcReverse 0.5) rcStop))
  it "rcHeading and rcHeading' turn to the desired heading" $ do
    let h1 = robotHeading (robotAt 10 (simulate 0.01 [OTSimbotA 1 (Point2 (-3) (-3)) 0] (rcHeading 0.3 1) rcStop))
        h2 = robotHeading (robotAt 10 (simulate 0.01 [OTSimbotA 1 (Point2 (-3) (-3)) 0] (rcHeading' 0.3 1) rcStop))
    abs (h1 - 1) `shouldSatisfy` (< 0.01)
    h2 `shouldBe` h1
  it "rcMoveTo approaches its target" $ do
    let (x, y) = posOf (robotAt 30 (simulate 0.01 [OTSimbotB 1 (Point2 (-3) (-3)) 0] rcStop (rcMoveTo 1 (Point2 2 1))))
    sqrt ((x - 2) ^ (2 :: Int) + (y - 1) ^ (2 :: Int)) `shouldSatisfy` (< 0.3)
  it "rcFollowLeftWall follows a wall on its left" $ do
    let wall = [ OTHWall (Point2 x 1) | x <- [-3.5, -2.5 .. 3.5] ]
        run  = simulate 0.01 (OTSimbotA 1 (Point2 (-3.5) 0.5) 0 : wall) (rcFollowLeftWall 0.3 0.25) rcStop
        (x, y) = posOf (robotAt 15 run)
    x `shouldSatisfy` (> -0.5)
    -- the wall's face is at y = 0.95; the robot's edge keeps 0.25 from it
    abs (y - (0.95 - 0.25 - 0.25)) `shouldSatisfy` (< 0.05)
  it "rcAlign makes a group of simbots converge on one heading" $ do
    let world = [ OTSimbotB i (Point2 (fromIntegral (i `mod` 3) * 1.5 - 1.5) (fromIntegral (i `div` 3) * 1.5 - 1.5))
                              (fromIntegral i * 0.7) | i <- [0 .. 5] ]
        run = simulate 0.01 world rcStop (rcAlign 0.2)
        spread s = let hs = map robotHeading (wsRobots s) in maximum hs - minimum hs
    spread (run !! 1000) `shouldSatisfy` (< spread (head run))
