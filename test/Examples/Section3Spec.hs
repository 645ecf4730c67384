-- |
-- The examples of "Paper.Section3": every world is valid, and a short run
-- of each in the pure simulator shows the behaviour its name promises.
-- Positions are in metres, headings in radians, speeds in m/s; each
-- tolerance is stated where it is used.
module Examples.Section3Spec (spec) where

import           Control.Exception (evaluate)
import           Data.List      (isInfixOf)
import           Test.Hspec     hiding (Example, after)

import           AFrob          hiding (forAll)
import           AFrobRobotSim
import           Examples.SimUtil
import           Examples.Types
import           Paper.Section3

------------------------------------------------------------------------------
-- Running the examples

-- | The example of that name.
paperExample :: String -> Example
paperExample name = case [ e | e <- examples, exName e == name ] of
  [e] -> e
  _   -> error ("no single example named " ++ name)

-- | How far apart the headings are: 1 - the length of their mean unit
-- vector (0 when all equal, 1 when they cancel out).
headingSpread :: [Heading] -> Double
headingSpread hs =
  let n = fromIntegral (length hs)
      c = sum (map cos hs) / n
      s = sum (map sin hs) / n
  in 1 - sqrt (c * c + s * s)

spec :: Spec
spec = do
  describe "the examples" $ do
    it "are the eleven controllers of section 3, named as in the notes" $
      map exName examples `shouldBe`
        [ "rcStop", "rcBlind1", "rcBlind2", "rcTurn", "rcReverse", "rcReverse'"
        , "rcHeading", "rcHeading'", "rcMoveTo", "rcFollowLeftWall", "rcAlign" ]
    it "all have valid worlds with robots in them and a positive running time" $
      mapM_ (\e -> do
               (exName e, validateWorld (exWorld e)) `shouldBe` (exName e, Right ())
               exSeconds e `shouldSatisfy` (> 0)
               any isRobot (exWorld e) `shouldBe` True)
            examples

  it "rcStop: the robots stay exactly where they are" $ do
    let e = paperExample "rcStop"
        run = runExample 0.05 3 e
    map (map robotPos . wsRobots) run `shouldSatisfy` all (== map robotPos (wsRobots (head run)))

  it "rcBlind1: full speed (10 m/s clamped to the maximum) straight into the wall, and stuck there" $ do
    let dt = 0.05
        run = runExample dt 14 (paperExample "rcBlind1")
    -- speeds to 1e-9: 1 m/s reached after 5 s (0.2 m/s^2), 2 m/s after 4 s (0.5 m/s^2)
    robotSpeed (robotA (at dt 5.5 run)) `shouldSatisfy` near 1e-9 1
    robotSpeed (robotB (at dt 4.5 run)) `shouldSatisfy` near 1e-9 2
    -- the wall's face is at x = 3.45; the robots' edges stop on it (1 mm)
    let end = last run
    map robotStuck (wsRobots end) `shouldBe` [True, True]
    map (fst . xy) (wsRobots end) `shouldSatisfy` all (near 1e-3 3.2)
    map robotHeading (wsRobots end) `shouldSatisfy` all (== 0)

  it "rcBlind2: half the maximum wheel speed, so the SimbotB is twice as fast" $ do
    let dt = 0.05
        s = at dt 6 (runExample dt 6 (paperExample "rcBlind2"))
    robotSpeed (robotA s) `shouldSatisfy` near 1e-9 0.5
    robotSpeed (robotB s) `shouldSatisfy` near 1e-9 1.0
    map (snd . xy) (wsRobots s) `shouldBe` [-1, 1]

  it "rcTurn: the fastest turn at the given speed, w = 2 (vmax - v) / l, on circles of 1 m" $ do
    let dt = 0.02
        run = runExample dt 20 (paperExample "rcTurn")
        turned f t0 t1 = normalizeAngle (robotHeading (f (at dt t1 run)) - robotHeading (f (at dt t0 run)))
    -- at full speed (A 0.8 m/s after 4 s, B 1.6 m/s after 3.2 s):
    -- A turns at 2 (1 - 0.8) / 0.5 = 0.8 rad/s, B at 2 (2 - 1.6) / 0.5 = 1.6 rad/s (1e-6)
    turned robotA 10 11 `shouldSatisfy` near 1e-6 0.8
    turned robotB 10 11 `shouldSatisfy` near 1e-6 1.6
    -- on circles: never further than 2.5 m from the start
    let start = head run
    run `shouldSatisfy` all (\s -> and (zipWith (\r r0 -> dist (robotPos r) (robotPos r0) < 2.5)
                                              (wsRobots s) (wsRobots start)))

  it "rcReverse: bounces between its walls, saying Ouch!! at every bump" $ do
    let dt = 0.05
        run = runExample dt 25 (paperExample "rcReverse")
        ouches ty = length [ m | s <- run, m <- wsMessages s, ty `isInfixOf` m, "Ouch!!" `isInfixOf` m ]
    -- SimbotA (0.5 m/s) bumps at about 6.7 and 18.7 s, SimbotB (1 m/s) every 6.4 s
    ouches "SimbotA.1" `shouldBe` 2
    ouches "SimbotB.1" `shouldBe` 4
    -- it backs off after a bump: at full speed backwards 3.3 s after the first one
    robotSpeed (robotA (at dt 10 run)) `shouldSatisfy` near 1e-9 (-0.5)
    -- and never gets past the walls (faces at x = -2.95 and 2.95; 1 mm)
    run `shouldSatisfy` all (all (\r -> abs (fst (xy r)) <= 2.95 - 0.25 + 1e-3) . wsRobots)

  it "rcReverse': the same run as rcReverse" $ do
    let states name = map wsRobots (runExample 0.05 25 (paperExample name))
    states "rcReverse'" `shouldBe` states "rcReverse"

  it "rcHeading: every robot turns to the heading pi/4 and drives on at its speed" $ do
    let dt = 0.05
        s = at dt 8 (runExample dt 8 (paperExample "rcHeading"))
    -- headings within 0.01 rad; speeds 0.4 (A) and 0.6 (B) to 1e-9
    map robotHeading (wsRobots s) `shouldSatisfy` all (near 0.01 (pi / 4))
    [ robotSpeed r | r <- wsRobots s, robotType r == "SimbotA" ] `shouldSatisfy` all (near 1e-9 0.4)
    [ robotSpeed r | r <- wsRobots s, robotType r == "SimbotB" ] `shouldSatisfy` all (near 1e-9 0.6)

  it "rcHeading': the same run as rcHeading" $ do
    let states name = map wsRobots (runExample 0.05 8 (paperExample name))
    states "rcHeading'" `shouldBe` states "rcHeading"

  it "rcMoveTo: both robots end up at their targets, slowing down as they arrive" $ do
    let dt = 0.05
        run = runExample dt 25 (paperExample "rcMoveTo")
        end = last run
    -- within 5 cm of the targets, and crawling (under 1 cm/s)
    dist (robotPos (robotA end)) (Point2 (-1) 2) `shouldSatisfy` (< 0.05)
    dist (robotPos (robotB end)) (Point2 2 1) `shouldSatisfy` (< 0.05)
    map robotSpeed (wsRobots end) `shouldSatisfy` all ((< 0.01) . abs)
    -- the SimbotB drives at its 1.2 m/s while more than 2 m away
    robotSpeed (robotB (at dt 4 run)) `shouldSatisfy` near 1e-9 1.2

  it "rcFollowLeftWall: both robots settle at the set distance from the wall on their left" $ do
    let dt = 0.05
        run = runExample dt 16 (paperExample "rcFollowLeftWall")
    -- the wall's faces are at y = 0.95 and 1.05; the robot's edge keeps
    -- 0.25 (A, below) and 0.4 (B, above) from them: centres at y = 0.45
    -- and y = 1.70 (2 cm), driving parallel to the wall (0.01 rad)
    mapM_ (\t -> do
             let s = at dt t run
             snd (xy (robotA s)) `shouldSatisfy` near 0.02 0.45
             snd (xy (robotB s)) `shouldSatisfy` near 0.02 1.70
             robotHeading (robotA s) `shouldSatisfy` near 0.01 0
             abs (robotHeading (robotB s)) `shouldSatisfy` near 0.01 pi)
          [8, 12, 16]
    fst (xy (robotA (last run))) `shouldSatisfy` (> 0)

  it "rcAlign: twelve robots with scattered headings converge on one heading" $ do
    -- (at dt = 0.02: the heading the flock settles on depends on the
    -- transient, and so on the time step; at 0.05 it is more easterly and
    -- the flock reaches the world's edge before 18 s)
    let dt = 0.02
        run = runExample dt 18 (paperExample "rcAlign")
        spread s = headingSpread (map robotHeading (wsRobots s))
    length (wsRobots (head run)) `shouldBe` 12
    spread (head run) `shouldSatisfy` (> 0.5)
    -- after 10 s the headings agree to within a few hundredths of a radian
    spread (at dt 10 run) `shouldSatisfy` (< 1e-3)
    spread (last run) `shouldSatisfy` (< 1e-3)
    -- without bumping into each other
    run `shouldSatisfy` all (not . any robotStuck . wsRobots)

  it "rcAlignAsPrinted (the listing before the fix) breaks the flock up in the same world" $ do
    -- the robots wander apart until one has fewer than three neighbours in
    -- tracking range and the listing's pattern (l1:l2:l3:_) fails
    let run = take 901 (simulate 0.02 alignWorld rcStop (rcAlignAsPrinted 0.3))
    evaluate (sum [ robotHeading r | st <- run, r <- wsRobots st ])
      `shouldThrow` (\e -> ceRobotType e == "SimbotB" && ceTime e < 18)
  where
    isRobot o = case o of
      OTSimbotA {} -> True
      OTSimbotB {} -> True
      _            -> False
