-- The notes' rcA template dispatches on a few ids only.
{-# OPTIONS_GHC -Wno-incomplete-patterns #-}
-- |
-- The controller listings of section 3 of the notes (compiled, verbatim,
-- in "Paper.Section3") run in the simulator: each does what the notes say.
module AFrobRobotSim.NotesSection3Spec (spec) where

import           Data.List    (isInfixOf)
import           Test.Hspec   hiding (after)

import           AFrob        hiding (forAll)
import           AFrobRobotSim
import           Paper.Section3

-- The notes' rcA template: dispatch on the robot id.
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
    -- 1 stops, 2 drives blind at half its top speed, 3 turns as fast as it can
    let w  = [OTSimbotA 1 (Point2 0 0) 0, OTSimbotA 2 (Point2 (-4) 2) 0, OTSimbotA 3 (Point2 0 (-2)) 0]
        rs = wsRobots (simulate 0.01 w rcA rcStop !! 400)
        r1 = head rs
        r2 = rs !! 1
        r3 = rs !! 2
    map robotId rs `shouldBe` [1, 2, 3]
    posOf r1 `shouldBe` (0, 0)
    robotHeading r1 `shouldBe` 0
    robotSpeed r2 `shouldSatisfy` (\v -> abs (v - 0.5) < 1e-9)
    fst (posOf r2) `shouldSatisfy` (> -3)
    -- (0.2 m/s at 3.2 rad/s: a circle of 6.25 cm radius)
    posOf r3 `shouldSatisfy` (\(x, y) -> let e = sqrt (x * x + (y + 2) * (y + 2)) in e > 0.01 && e <= 0.13)
    robotHeading r3 `shouldSatisfy` (/= 0)
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
    let wall = [ OTHWall (Point2 wx 1) | wx <- [-3.5, -2.5 .. 3.5] ]
        run  = simulate 0.01 (OTSimbotA 1 (Point2 (-3.5) 0.5) 0 : wall) (rcFollowLeftWall 0.3 0.25) rcStop
        (x, y) = posOf (robotAt 15 run)
    x `shouldSatisfy` (> -0.5)
    -- the wall's face is at y = 0.95; the robot's edge keeps 0.25 from it
    abs (y - (0.95 - 0.25 - 0.25)) `shouldSatisfy` (< 0.05)
  it "rcAlign (with the frame fix of Paper.Section3) makes a group converge on one heading" $ do
    let world = [ OTSimbotB i (Point2 (fromIntegral (i `mod` 3) * 1.5 - 1.5) (fromIntegral (i `div` 3) * 1.5 - 1.5))
                              (fromIntegral i * 0.7) | i <- [0 .. 5] ]
        run = simulate 0.01 world rcStop (rcAlign 0.2)
        spread s = let hs = map robotHeading (wsRobots s) in maximum hs - minimum hs
    spread (run !! 1000) `shouldSatisfy` (< spread (head run))
