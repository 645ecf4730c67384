-- |
-- Exercises 14 (the braid) and 15 (robocup soccer), run in the pure
-- simulator.
module Examples.Exercises14and15Spec (spec) where

import           Data.Maybe             (isJust, isNothing, listToMaybe, mapMaybe)
import           Test.Hspec             hiding (after)
import           Test.QuickCheck        (choose, forAll)

import           AFrob                  hiding (forAll)
import           AFrobRobotSim

import           Examples.Types
import qualified Exercises.Ex14         as Ex14
import           Exercises.Ex14         (Braid (..), braidWorld, notesBraid, rcBraid)
import qualified Exercises.Ex15         as Ex15
import           Exercises.Ex15         (teamNaive, teamSmart)
import           Exercises.Soccer.Pitch
import           Exercises.Soccer.Player (player)
import           Exercises.Soccer.Roles  (attacker)

spec :: Spec
spec = do
  describe "Exercise 14: the braid" braidSpec
  describe "Exercise 15: robocup soccer" soccerSpec

------------------------------------------------------------------------------
-- Exercise 14

braidSpec :: Spec
braidSpec = do
  let b      = notesBraid
      run    = takeWhile ((<= 40) . wsTime) (simulate 0.01 (braidWorld b) (rcBraid b) (rcBraid b))
      pair w = case wsRobots w of
        [r1, r2] -> (robotPos r1, robotPos r2)
        rs       -> error ("expected two robots, got " ++ show (length rs))
      along  = vector2Polar 1 (brHeading b)
      across = vector2Polar 1 (brHeading b + pi / 2)
      progress p = (p .-. brStart b) `dot` along
      -- while travelling: until the pair's midpoint is 1 m from the end
      travelling = [ w | w <- run, wsTime w <= 18 ]
      everySecond = [ w | (i, w) <- zip [0 :: Int ..] travelling, i `mod` 100 == 0 ]

  it "is the example ex14, with a valid world" $ do
    map exName Ex14.examples `shouldBe` ["ex14"]
    validateWorld (braidWorld b) `shouldBe` Right ()

  it "crosses the two paths again and again while travelling" $ do
    let lateral  = [ (p1 .-. p2) `dot` across | w <- travelling, let (p1, p2) = pair w ]
        signs    = filter (/= 0) (map signum lateral)
        crossings = length (filter id (zipWith (/=) signs (drop 1 signs)))
    crossings `shouldSatisfy` (>= 3)

  it "advances steadily: each robot gets further along every second" $ do
    let steps f = zipWith (\w0 w1 -> progress (f (pair w1)) - progress (f (pair w0)))
                          everySecond (drop 1 everySecond)
    steps fst `shouldSatisfy` all (> 0.05)
    steps snd `shouldSatisfy` all (> 0.05)
    let (p1, p2) = pair (last travelling)
    progress (p1 .+^ (0.5 *^ (p2 .-. p1))) `shouldSatisfy` (> 8)

  it "never collides, and keeps the robots about the separation apart" $ do
    [ r | w <- run, r <- wsRobots w, robotStuck r ] `shouldBe` []
    let gaps = [ distance p1 p2 | w <- run, let (p1, p2) = pair w ]
    minimum gaps `shouldSatisfy` (> 0.8 * brSeparation b)
    maximum gaps `shouldSatisfy` (< 1.2 * brSeparation b)

------------------------------------------------------------------------------
-- Exercise 15

soccerSpec :: Spec
soccerSpec = do
  describe "the pitch" $ do
    it "is a valid world for every seed, the same for the same seed" $ do
      mapM_ (\s -> validateWorld (soccerWorld s) `shouldBe` Right ()) [0 .. 30]
      soccerWorld 7 `shouldBe` soccerWorld 7
      soccerWorld 7 `shouldNotBe` soccerWorld 8

    it "has the ball on the centre mark and every player on side, outside the centre circle" $
      mapM_ (\s -> do
        let w = soccerWorld s
        [ p | OTBall p <- w ] `shouldBe` [centreMark]
        [ p | OTSimbotA _ p _ <- w, not (point2X p < 0) ] `shouldBe` []
        [ p | OTSimbotB _ p _ <- w, not (point2X p > 0) ] `shouldBe` []
        [ p | o <- w, isJust (robotOf o), let p = otPos o
            , distance p centreMark <= centreCircleRadius + simbotDiameter / 2 ] `shouldBe` []
        length [ () | OTSimbotA {} <- w ] `shouldBe` 3
        length [ () | OTSimbotB {} <- w ] `shouldBe` 3) [0 .. 30]

    it "knows which goal a ball is in" $ do
      goalOf centreMark `shouldBe` Nothing
      goalOf (Point2 4.5 0.3) `shouldBe` Just TeamB
      goalOf (Point2 (-4.6) (-0.5)) `shouldBe` Just TeamA
      goalOf (Point2 4.05 0) `shouldBe` Nothing          -- on the line, not over it
      goalOf (Point2 4.5 2) `shouldBe` Nothing           -- beside the goal

  describe "the referee" $ do
    it "puts a ball in a goal back on the centre mark, and lets a ball in play be" $ do
      referee 10 [Point2 4.5 0] `shouldBe` Just [centreMark]
      referee 10 [Point2 (-4.4) 0.5] `shouldBe` Just [centreMark]
      referee 10 [Point2 1 2] `shouldBe` Nothing

    it "always leaves the ball in play, outside the goals, where it has nothing more to say" $
      forAll ((,) <$> choose (-5.5, 5.5) <*> choose (-5.5, 5.5)) $ \(x, y) ->
        case referee 0 [Point2 x y] of
          Nothing  -> inPlay (Point2 x y) && isNothing (goalOf (Point2 x y))
          Just [q] -> inPlay q && isNothing (goalOf q) && referee 0 [q] == Nothing
          Just _   -> False

    it "counts a lone striker's goals into the empty goal, each followed by a restart" $ do
      let world = pitchWalls ++ [OTBall centreMark, OTSimbotA 3 (Point2 (-1.5) 0.3) 0]
          run   = takeWhile ((<= 60) . wsTime) (simulateWith matchConfig world (player attacker) teamNaive)
          gs    = goalsIn run
      gs `shouldSatisfy` (not . null)
      map snd gs `shouldSatisfy` all (== TeamA)
      fst (head gs) `shouldSatisfy` (< 30)
      show (matchResult run) `shouldBe` "A " ++ show (length gs) ++ " - 0 B"
      -- just before each goal the ball was at the goal mouth; then it is
      -- at rest on the centre mark
      let aroundGoal t = [ (wsBalls w0, wsBalls w1, wsBalls w2)
                     | (w0, w1, w2) <- zip3 run (drop 1 run) (drop 2 run), wsTime w1 == t ]
      mapM_ (\(t, _) -> case aroundGoal t of
                [([Point2 x y], [b1], [b2])] -> do
                  x `shouldSatisfy` (> goalLineX - 0.5)
                  abs y `shouldSatisfy` (< goalHalfWidth)
                  b1 `shouldBe` centreMark
                  b2 `shouldBe` centreMark
                other -> expectationFailure ("no ball around the goal at " ++ show t ++ ": " ++ show other))
            gs
      -- and the ball is never left in a goal
      [ b | w <- run, b <- wsBalls w, isJust (goalOf b) ] `shouldBe` []

  describe "a match" $ do
    it "shows its result as A n - m B" $
      show (MatchResult 3 1 [(10, TeamA), (20, TeamB), (30, TeamA), (40, TeamA)]) `shouldBe` "A 3 - 1 B"

    it "is the example ex15: the smart team against the naive one, and ex15-match with the match's referee" $ do
      map exName Ex15.examples `shouldBe` ["ex15", "ex15-match"]
      map exWorld Ex15.examples `shouldBe` [soccerWorld 10, soccerWorld 10]
      map (\e -> length (refereeGoals (exReferee e))) Ex15.examples `shouldBe` [0, 2]

    it "goalScores counts the goals goalsIn finds, at the snapshots where they are scored (the lone striker's run)" $ do
      let world = pitchWalls ++ [OTBall centreMark, OTSimbotA 3 (Point2 (-1.5) 0.3) 0]
          run   = takeWhile ((<= 60) . wsTime) (simulateWith matchConfig world (player attacker) teamNaive)
          r     = matchResult run
      goalsA r `shouldSatisfy` (> 1)
      wsScores (head run) `shouldBe` [("A", 0), ("B", 0)]
      wsScores (last run) `shouldBe` [("A", goalsA r), ("B", goalsB r)]
      [ wsTime w1 | (w0, w1) <- zip run (drop 1 run), wsScores w1 /= wsScores w0 ] `shouldBe` map fst (goalTimes r)

    it "goalAreas are the two goals behind the goal lines, each inside the world" $ do
      goalAreas `shouldBe` [LogRect (-4.5) 0 1 1.8, LogRect 4.5 0 1 1.8]
      map (\(LogRect x y _ _) -> isJust (goalOf (Point2 x y))) goalAreas `shouldBe` [True, True]

    it "ex15's run: team A scores after about 13 s, team B after about 55 s (as its Haddock and the tutorial say)" $ do
      -- (unrefereed: the first sample of each spell of the ball in a goal;
      -- goalOf names the team whose goal it is in)
      let ex   = head Ex15.examples
          run  = takeWhile ((<= 120) . wsTime) (simulate 0.01 (exWorld ex) (exControllerA ex) (exControllerB ex))
          ins  = [ (wsTime w, listToMaybe (mapMaybe goalOf (wsBalls w))) | w <- run ]
          goals = [ (t, g) | ((_, prev), (t, Just g)) <- zip ((0, Nothing) : ins) ins, prev /= Just g ]
      map (\(t, g) -> (round t :: Int, g)) goals `shouldBe` [(13, TeamB), (55, TeamA)]

    it "lasts 5 minutes and ends with a score, every goal inside the match" $ do
      -- (seed 1: the smart team wins 2-0; robots that stand still score none)
      let r = playMatch 1 300 teamSmart teamNaive
      (goalsA r, goalsB r) `shouldBe` (2, 0)
      map snd (goalTimes r) `shouldBe` [TeamA, TeamA]
      map fst (goalTimes r) `shouldSatisfy` all (\t -> t > 0 && t <= 300)
      map fst (goalTimes r) `shouldSatisfy` (\ts -> and (zipWith (<) ts (drop 1 ts)))
      let still _ = constant (mrFinalize ddBrake)
      playMatch 1 300 still still `shouldBe` MatchResult 0 0 []

    it "gives the figures that Ex15's Haddock and the tutorial state (seeds 1 to 12, 300 s, each side)" $ do
      let asA = [ (goalsA r, goalsB r) | s <- [1 .. 12], let r = playMatch s 300 teamSmart teamNaive ]
          asB = [ (goalsB r, goalsA r) | s <- [1 .. 12], let r = playMatch s 300 teamNaive teamSmart ]
          -- (goals for the smart team, against it, wins, draws, losses)
          table rs = ( sum (map fst rs), sum (map snd rs), length [ () | (m, n) <- rs, m > n ]
                     , length [ () | (m, n) <- rs, m == n ], length [ () | (m, n) <- rs, m < n ] )
      table asA `shouldBe` (22, 3, 8, 4, 0)
      table asB `shouldBe` (15, 1, 8, 4, 0)
      table (take 5 asA ++ take 5 asB) `shouldBe` (21, 4, 9, 1, 0)

  where
    robotOf o = case o of
      OTSimbotA {} -> Just ()
      OTSimbotB {} -> Just ()
      _            -> Nothing
