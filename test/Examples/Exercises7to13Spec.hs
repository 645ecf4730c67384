-- |
-- The solutions of exercises 7 to 13 ("Exercises.Ex07" ... "Exercises.Ex13"),
-- run in the pure simulator. Positions are in metres, headings in radians,
-- speeds in m/s; each tolerance is stated where it is used.
module Examples.Exercises7to13Spec (spec) where

import           Data.List        (findIndex, isInfixOf, tails)
import           Data.Maybe       (mapMaybe)
import           Test.Hspec       hiding (Example, after)

import           AFrob            hiding (forAll)
import           AFrobRobotSim
import           Examples.SimUtil
import           Examples.Types
import qualified Exercises.Ex07   as Ex07
import qualified Exercises.Ex08   as Ex08
import qualified Exercises.Ex09   as Ex09
import qualified Exercises.Ex10   as Ex10
import qualified Exercises.Ex11   as Ex11
import qualified Exercises.Ex12   as Ex12
import qualified Exercises.Ex13   as Ex13

------------------------------------------------------------------------------
-- Helpers

-- | The indices at which a signal changes sign (from negative to
-- non-negative or back).
signChanges :: [Double] -> [Int]
signChanges xs = [ i | (i, a, b) <- zip3 [1 ..] xs (drop 1 xs), (a < 0) /= (b < 0) ]

-- | Make a controller also print its range readings, @probe LEFT FRONT@,
-- at every sample, so that a test can see what the robot saw.
probe :: SimbotController -> SimbotController
probe rc rps = (rc rps &&& arr (\i -> (rfLeft i, rfFront i))) >>> arr addReading
  where
    addReading (o, (l, f)) = o { soMessages = soMessages o ++ ["probe " ++ show l ++ " " ++ show f] }

-- | The (left, front) readings a probed robot printed at each sample.
probed :: String -> [WorldState] -> [(Double, Double)]
probed who = map reading
  where
    reading s = case mapMaybe parse (wsMessages s) of
      [lf] -> lf
      _    -> error ("no single probe reading at " ++ show (wsTime s))
    parse m
      | (who ++ ": ") `isInfixOf` m = case dropWhile (/= "probe") (words m) of
          [_, l, f] -> Just (read l, read f)
          _         -> Nothing
      | otherwise = Nothing

-- | The index of the first snapshot at or after @from@ where the robot's
-- centre is within @tol@ of @p@.
firstNear :: (WorldState -> RobotState) -> Double -> Position2 -> Int -> [WorldState] -> Maybe Int
firstNear who tol p from run =
  fmap (+ from) (findIndex (\s -> dist (robotPos (who s)) p <= tol) (drop from run))

-- | Visit the points in order: the index at which each is first reached
-- after the previous one (Nothing for a point never reached).
visits :: (WorldState -> RobotState) -> Double -> [Position2] -> [WorldState] -> [Maybe Int]
visits who tol = go 0
  where
    go _ [] _ = []
    go from (p : ps) run = case firstNear who tol p from run of
      Nothing -> Nothing : map (const Nothing) ps
      Just i  -> Just i : go i ps run

spec :: Spec
spec = do
  describe "the examples" $ do
    let exs = concat [ Ex07.examples, Ex08.examples, Ex09.examples, Ex10.examples
                     , Ex11.examples, Ex12.examples, Ex13.examples ]
    it "are named ex7 ... ex13" $
      map exName exs `shouldBe` ["ex7", "ex8", "ex9", "ex10", "ex11", "ex12", "ex13"]
    it "all have valid worlds" $
      mapM_ (\e -> (exName e, validateWorld (exWorld e)) `shouldBe` (exName e, Right ())) exs

  ----------------------------------------------------------------------------
  describe "exercise 7: rcBlind2 for 2 s, rcTurn for 3 s, then rcStop" $ do
    let dt  = 0.02
        run = runExample dt 10 (head Ex07.examples)
        b t = robotB (at dt t run)
        a t = robotA (at dt t run)
    it "drives straight ahead, speeding up towards half its maximum speed, until 2 s" $ do
      -- SimbotB from (-3, -1.5) at 0.5 m/s^2: x = -3 + t^2/4 (1 cm), speed t/2 (1e-6)
      mapM_ (\t -> do
               xy (b t) `shouldSatisfy` (\(x, y) -> near 0.01 (-3 + t * t / 4) x && y == -1.5)
               robotSpeed (b t) `shouldSatisfy` near 1e-6 (t / 2)
               robotHeading (b t) `shouldBe` 0)
            [0.5, 1, 1.5, 2]
      robotSpeed (a 2) `shouldSatisfy` near 1e-6 0.4
    it "turns at rcTurn's rate between 2 and 5 s" $ do
      -- SimbotB: rcTurn 1.5 turns at 2 (2 - 1.5) / 0.5 = 2 rad/s; SimbotA:
      -- rcTurn 0.6 at 1.6 rad/s (0.02 rad over each second)
      mapM_ (\t -> do
               normalizeAngle (robotHeading (b (t + 1)) - robotHeading (b t)) `shouldSatisfy` near 0.02 2
               normalizeAngle (robotHeading (a (t + 1)) - robotHeading (a t)) `shouldSatisfy` near 0.02 1.6)
            [2.1, 3, 3.9]
      robotSpeed (b 5) `shouldSatisfy` near 0.02 1.5
      robotSpeed (a 5) `shouldSatisfy` near 0.02 0.6
    it "brakes to a standstill after 5 s, without turning any more" $ do
      robotHeading (b 9) `shouldBe` robotHeading (b 5.1)
      robotHeading (a 9) `shouldBe` robotHeading (a 5.1)
      -- braking at 0.5 (B) and 0.2 (A) m/s^2 from 1.5 and 0.6 m/s takes 3 s
      map (robotSpeed . ($ 8.5)) [a, b] `shouldBe` [0, 0]
      map (robotPos . ($ 10)) [a, b] `shouldBe` map (robotPos . ($ 8.5)) [a, b]

  ----------------------------------------------------------------------------
  describe "exercise 8: rcReverse with a snapshot of the velocity" $ do
    let dt  = 0.02
        run = runExample dt 40 (head Ex08.examples)
        stuckAt who = [ i | (i, s0, s1) <- zip3 [1 :: Int ..] run (drop 1 run)
                          , not (robotStuck (who s0)), robotStuck (who s1) ]
        speed who i = robotSpeed (who (run !! i))
    it "keeps bouncing, saying Ouch!! at every bump" $ do
      length (stuckAt robotB) `shouldSatisfy` (>= 5)
      length (stuckAt robotA) `shouldSatisfy` (>= 3)
      let ouches = length [ m | s <- run, m <- wsMessages s, "SimbotB.1" `isInfixOf` m, "Ouch!!" `isInfixOf` m ]
      ouches `shouldBe` length (stuckAt robotB)
    it "moves away from each bump at the negation of the speed it had when it hit" $ do
      -- the SimbotB ramps its velocity up at 0.2 m/s^2: it hits the wall at
      -- about 1.37 m/s, not its ramp's cap of 1.5 m/s
      let bumps = stuckAt robotB
          hitSpeed = speed robotB (head bumps - 1)
      hitSpeed `shouldSatisfy` (\v -> v > 1.2 && v < 1.45)
      -- between two bumps it reaches the negation of the speed before the
      -- first, to 0.01 m/s, alternately backwards and forwards
      mapM_ (\(k, (i, j)) -> do
               let speeds = [ speed robotB n | n <- [i + 1 .. j - 1] ]
                   extreme = if even k then minimum speeds else maximum speeds
               extreme `shouldSatisfy` near 0.01 (if even k then negate hitSpeed else hitSpeed))
            (zip [0 :: Int ..] (zip bumps (drop 1 bumps)))
    it "at a constant start velocity, bounces at that speed (SimbotA, 0.5 m/s)" $ do
      let bumps = stuckAt robotA
      speed robotA (head bumps - 1) `shouldSatisfy` near 1e-9 0.5
      minimum [ speed robotA n | n <- [head bumps + 1 .. bumps !! 1 - 1] ] `shouldSatisfy` near 1e-9 (-0.5)

  ----------------------------------------------------------------------------
  describe "exercise 9: rcMoveTo that stops at its target" $ do
    let dt  = 0.05
        run = runExample dt 25 (head Ex09.examples)
        end = last run
    it "ends close to its target, at a standstill" $ do
      -- targets (-1, 2) and (2, 1); stopping radius 0.1 m, plus at most 1 cm of braking
      dist (robotPos (robotA end)) (Point2 (-1) 2) `shouldSatisfy` (< 0.11)
      dist (robotPos (robotB end)) (Point2 2 1) `shouldSatisfy` (< 0.11)
      map robotSpeed (wsRobots end) `shouldBe` [0, 0]
    it "stays put once it has stopped" $ do
      -- the SimbotB arrives within about 10 s
      let s = at dt 15 run
      robotPos (robotB end) `shouldBe` robotPos (robotB s)
      robotHeading (robotB end) `shouldBe` robotHeading (robotB s)

  ----------------------------------------------------------------------------
  describe "exercise 10: a sinusoidal path" $ do
    let dt  = 0.05
        run = runExample dt 24 (head Ex10.examples)
        -- rcSine 0.4 0 1.0 8 (SimbotA) and rcSine 0.45 0 1.2 5 (SimbotB)
        check who period amp = do
          let hs = map (robotHeading . who) run
              crossings = map ((* dt) . fromIntegral) (signChanges hs)
              gaps = zipWith (-) (drop 1 crossings) crossings
          -- at least four half-periods, each within 0.1 s of period / 2
          length gaps `shouldSatisfy` (>= 4)
          gaps `shouldSatisfy` all (near 0.1 (period / 2))
          -- the heading swings by nearly the commanded amplitude (the
          -- proportional controller lags and damps it a little)
          let swing = maximum (map abs (drop (round (period / dt)) hs))
          swing `shouldSatisfy` (\s -> s > 0.75 * amp && s <= amp)
    it "makes the heading oscillate with the commanded period (SimbotA, 8 s)" $
      check robotA 8 1.0
    it "makes the heading oscillate with the commanded period (SimbotB, 5 s)" $
      check robotB 5 1.2
    it "so the robots weave along a mean direction (east)" $ do
      let ys who = map (snd . xy . who) run
      fst (xy (robotA (last run))) `shouldSatisfy` (> 2)
      -- the path swings either side of its mean line by 0.2 to 0.8 m
      let swing who = maximum (ys who) - minimum (ys who)
      swing robotA `shouldSatisfy` (\s -> s > 0.4 && s < 1.6)
      swing robotB `shouldSatisfy` (\s -> s > 0.4 && s < 1.6)

  ----------------------------------------------------------------------------
  describe "exercise 11: visiting a list of points in turn" $ do
    let dt  = 0.05
        run = runExample dt 50 (head Ex11.examples)
    it "reaches every point (within 0.25 m), in order, then stops at the last" $ do
      -- the arrival radius is 0.2 m; the robots still coast a little
      let va = visits robotA 0.25 Ex11.tourA run
          vb = visits robotB 0.25 Ex11.tourB run
      va `shouldSatisfy` all (/= Nothing)
      vb `shouldSatisfy` all (/= Nothing)
      dist (robotPos (robotA (last run))) (last Ex11.tourA) `shouldSatisfy` (< 0.25)
      dist (robotPos (robotB (last run))) (last Ex11.tourB) `shouldSatisfy` (< 0.25)
      map robotSpeed (wsRobots (last run)) `shouldBe` [0, 0]
    it "does not go to a later point first" $ do
      -- the SimbotA does not pass the third corner before the second
      let v = visits robotA 0.25 Ex11.tourA run
      v `shouldSatisfy` (\is -> and (zipWith (<) is (drop 1 is)))
      firstNear robotA 0.25 (Ex11.tourA !! 2) 0 run
        `shouldSatisfy` (> firstNear robotA 0.25 (Ex11.tourA !! 1) 0 run)

  ----------------------------------------------------------------------------
  describe "exercise 12: a wall follower for mazes" $ do
    let dt  = 0.05
        run = runWorld dt 95 Ex12.mazeWorld (Ex12.rcMazeFollower 0.3 0.4) (Ex12.rcMazeFollower 0.5 0.4)
        -- one point on every stretch of the lap, the wall on the robot's
        -- left 0.65 m from its centre (0.4 m from its edge)
        checkpoints =
          [ Point2 (-3.3) 2      -- up the west wall
          , Point2 (-1.5) 3.3    -- along the north wall (after an inside corner)
          , Point2 0.3 2.5       -- down the cut-out's west side (inside corner)
          , Point2 2.5 0.3       -- along its south side (outside corner)
          , Point2 3.3 (-1.5)    -- down the east wall (inside corner)
          , Point2 2.5 (-3.3)    -- along the south wall (inside corner)
          , Point2 1.7 (-2.5)    -- up the bump's east side (inside corner)
          , Point2 0 (-1.3)      -- over the bump (outside corner)
          , Point2 (-1.7) (-2.5) -- down its west side (outside corner)
          , Point2 (-2.5) (-3.3) -- along the south wall (inside corner)
          , Point2 (-3.3) (-1.5) -- back up the west wall (inside corner)
          ]
    it "never gets stuck" $
      run `shouldSatisfy` all (not . any robotStuck . wsRobots)
    it "goes round the whole maze, through every checkpoint in order (within 0.1 m)" $ do
      let v = visits robotB 0.1 checkpoints run
      v `shouldSatisfy` all (/= Nothing)
    it "stops at distance d from the wall ahead before each inside-corner (right) turn" $ do
      let run'   = runWorld dt 95 Ex12.mazeWorld (Ex12.rcMazeFollower 0.3 0.4) (probe (Ex12.rcMazeFollower 0.5 0.4))
          fronts = map snd (probed "SimbotB.1" run')
          hs     = map (robotHeading . robotB) run'
          -- the samples of a right turn: the heading falling fast
          turning = [ normalizeAngle (h' - h) < -0.5 * dt | (h, h') <- zip hs (drop 1 hs) ]
          -- the front reading and speed at the first sample of each
          starts = [ (f, robotSpeed (robotB w)) | (f, w, (wasTurning, isTurning)) <- zip3 fronts run' (zip (False : turning) turning)
                                                , isTurning, not wasTurning ]
      -- the lap's seven inside corners, each met with the front 1 cm from
      -- d, slowed from 0.5 m/s to under 0.1 (the last of the braking: the
      -- translational inertia stops it within 0.15 s and 6 mm)
      length starts `shouldBe` 7
      map fst starts `shouldSatisfy` all (near 0.01 0.4)
      map snd starts `shouldSatisfy` all (< 0.1)
    it "keeps its distance from the walls on the straights" $ do
      -- on the west wall, the north wall and the east wall the centre stays
      -- 0.65 m from the wall face (2 cm)
      fst (xy (robotB (at dt 6 run))) `shouldSatisfy` near 0.02 (-3.3)
      snd (xy (robotB (at dt 18 run))) `shouldSatisfy` near 0.02 3.3
      fst (xy (robotB (at dt 46 run))) `shouldSatisfy` near 0.02 3.3

  ----------------------------------------------------------------------------
  describe "exercise 13: a robust, multi-mode wall follower" $ do
    let dt  = 0.05
        d   = 0.4
        run = runWorld dt 60 Ex13.ex13World (probe (Ex13.rcRobustFollower 0.3 d)) (probe (Ex13.rcRobustFollower 0.5 d))
        check who = do
          let readings = probed who run
              lefts = map fst readings
          -- it starts far from every wall: nothing in range ahead or to the left
          head readings `shouldBe` (3, 3)
          -- later, rfLeft stays within 2 cm of d for at least 10 s on end
          let window = round (10 / dt)
              steady = [ i | (i, w) <- zip [0 :: Int ..] (tails lefts)
                           , length (take window w) == window
                           , all (near 0.02 d) (take window w) ]
          steady `shouldSatisfy` (not . null)
          -- having first gone to a wall (seek and align take over 8 s)
          head steady `shouldSatisfy` (> round (8 / dt))
    it "starts far from the walls, finds one and follows it at the desired distance (SimbotB)" $
      check "SimbotB.1"
    it "... and so does the SimbotA, which meets its wall in a corner" $
      check "SimbotA.1"
    it "never gets stuck" $
      run `shouldSatisfy` all (not . any robotStuck . wsRobots)
    it "finds and follows a wall met at a glancing angle, or in a corner, never stuck (the seek watched the front alone and pushed against it)" $
      mapM_ (\(p, h) -> do
               let w  = [ o | o <- Ex13.ex13World, case o of { OTSimbotA {} -> False; OTSimbotB {} -> False; _ -> True } ] ++ [OTSimbotA 1 p h]
                   r  = runWorld dt 80 w (Ex13.rcRobustFollower 0.3 d) (Ex13.rcRobustFollower 0.5 d)
                   -- the centre 0.65 m from a wall face: 3.3 m from the middle, across or along
                   onWall ws = let (x, y) = xy (robotA ws) in near 0.02 3.3 (abs x) || near 0.02 3.3 (abs y)
               (p, h, length (filter (any robotStuck . wsRobots) r)) `shouldBe` (p, h, 0)
               -- following a wall for the last 20 s
               (p, h, all onWall (drop (round (60 / dt)) r)) `shouldBe` (p, h, True))
        [(Point2 (-2) 3.3, 0.3), (Point2 (-2) 3.3, 0.08), (Point2 (-2) (-3), 1.85)]
    it "goes on round the room" $ do
      -- the SimbotB follows the east wall south, then the south wall west
      let b = robotB (at dt 30 run)
      snd (xy b) `shouldSatisfy` near 0.02 (-3.3)
