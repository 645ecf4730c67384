{-# LANGUAGE Arrows              #-}
{-# LANGUAGE ScopedTypeVariables #-}
module AFrobRobotSim.RefereeSpec (spec) where

import           Data.List          (isInfixOf)
import           System.Directory   (doesPathExist)
import           System.Exit        (ExitCode (..))
import           System.FilePath    ((</>))
import           Test.Hspec         hiding (after)

import           AFrob              hiding (forAll)
import           AFrobRobotSim
import           AFrobRobotSim.JSON (JSON (..), member, parseJSON)
import           AFrobRobotSim.Log  (LogEvent (..), LogFrame (..), LogHeader (..), LogSummary (..), RunLog (..),
                                     readLogFile)
import           AFrobRobotSim.Referee (checkGoals)
import           TestUtil           (captured, withCaps, withTempDir)

-- A robot that pushes the ball east: the ball crosses x = 2 after about
-- 2 s, and the referee puts it back at its start, a goal.
pitch :: WorldTemplate
pitch = [OTBall (Point2 0 0), OTSimbotA 1 (Point2 (-0.5) 0) 0]

push :: SimbotController
push _ = constant (mrFinalize (ddVelDiff 0.6 0.6))

kickOff :: Time -> [Position2] -> Maybe [Position2]
kickOff _ bs = if any (\(Point2 x _) -> x > 2) bs then Just [Point2 (-3) 3] else Nothing

-- The goals: one each time the ball is put back (a jump of over a metre).
goals :: SF WorldState [(String, Int)]
goals = proc ws -> do
  let x = sum [ bx | Point2 bx _ <- wsBalls ws ]
  x' <- iPre 0 -< x
  g <- edge -< abs (x - x') > 1
  n <- accumHold 0 -< fmap (const (+ 1)) g
  returnA -< [("A", n), ("B", 0)]

referee :: Referee
referee = noReferee { refereeBalls = kickOff, refereeScores = goals, refereeGoals = [LogRect 2.5 0 1 2] }

opts :: FilePath -> SimOptions
opts dir = defaultSimOptions { optSeconds = 5, optOut = dir, optQuiet = True, optSvg = Nothing
                             , optReplay = Just (dir </> "page.html"), optLog = Just (dir </> "run.jsonl")
                             , optResult = Just (dir </> "result.jsonl") }

spec :: Spec
spec = do
  describe "runSimRefereedWith" $ do
    it "puts the referee's scores in the log (frames, a score event, the summary), the result line and the page, and its goals in the log's header" $
      withTempDir $ \dir -> do
        (_, err, r) <- captured (runSimRefereedWith (opts dir) referee (Just pitch) push push)
        r `shouldBe` Right ()
        err `shouldBe` ""
        Right lg <- readLogFile (dir </> "run.jsonl")
        lhGoals (rlHeader lg) `shouldBe` [LogRect 2.5 0 1 2]
        let frames = rlFrames lg
        lfScores (head frames) `shouldBe` [("A", 0), ("B", 0)]
        lfScores (last frames) `shouldBe` [("A", 1), ("B", 0)]
        [ (evKind e, evText e) | f <- frames, e <- lfEvents f, evKind e == "score" ] `shouldBe` [("score", "A scores: 1")]
        fmap lsScores (rlSummary lg) `shouldBe` Just [("A", 1), ("B", 0)]
        resultLine <- readFile (dir </> "result.jsonl")
        case parseJSON resultLine of
          Right j -> (member "outcome" j >>= member "scores") `shouldBe` Right (JObject [("A", JNumber 1), ("B", JNumber 0)])
          Left e  -> expectationFailure e
        page <- readFile (dir </> "page.html")
        page `shouldSatisfy` ("A scores: 1" `isInfixOf`)
    it "runSimWith keeps no scores and no goals (noReferee)" $ withTempDir $ \dir -> do
      (_, _, r) <- captured (runSimWith (opts dir) (Just pitch) push push)
      r `shouldBe` Right ()
      Right lg <- readLogFile (dir </> "run.jsonl")
      lhGoals (rlHeader lg) `shouldBe` []
      map lfScores (rlFrames lg) `shouldSatisfy` all null
      fmap lsScores (rlSummary lg) `shouldBe` Just []
    it "a referee whose scores fail stops the run as a failing controller does: named, exit 1, the outputs finished, on one capability and on two" $
      mapM_ (\caps -> withCaps caps $ withTempDir $ \dir -> do
        let failing = referee { refereeScores = localTime >>> arr (\t -> if t > 1.5 then errorWithoutStackTrace "no score"
                                                                         else [("A", 0)]) }
        (_, err, r) <- captured (runSimRefereedWith (opts dir) failing (Just pitch) push push)
        r `shouldBe` Left (ExitFailure 1)
        err `shouldSatisfy` ("the scores (simScores) failed at t = 1.510 s: no score" `isInfixOf`)
        Right lg <- readLogFile (dir </> "run.jsonl")
        fmap lsFailure (rlSummary lg) `shouldBe` Just (Just "the scores (simScores) failed at t = 1.510 s: no score")
        fmap lsScores (rlSummary lg) `shouldBe` Just [("A", 0)]
        page <- readFile (dir </> "page.html")
        page `shouldSatisfy` ("no score" `isInfixOf`)) [1, 2]
    it "goals that cannot be drawn are refused before the run (exit 2, nothing written)" $ withTempDir $ \dir -> do
      let bad = referee { refereeGoals = [LogRect 0 0 1 1, LogRect (0 / 0) 0 1 1, LogRect 0 0 (-1) 1] }
      (_, err, r) <- captured (runSimRefereedWith (opts (dir </> "out")) bad (Just pitch) push push)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ("goal 2 (refereeGoals, in the list's order) has a centre that is not a finite point: (NaN, 0.0)" `isInfixOf`)
      err `shouldSatisfy` ("goal 3 (refereeGoals, in the list's order) has a size that is not finite and at least 0: -1.0 x 1.0" `isInfixOf`)
      doesPathExist (dir </> "out") `shouldReturn` False

  describe "checkGoals" $
    it "passes goals with finite centres and sizes of at least 0, anywhere" $ do
      checkGoals noReferee { refereeGoals = [LogRect 100 (-100) 0 0, LogRect 0 0 1 2] } `shouldBe` []
      length (checkGoals noReferee { refereeGoals = [LogRect (1 / 0) 0 1 1, LogRect 0 0 1 (0 / 0)] }) `shouldBe` 2
