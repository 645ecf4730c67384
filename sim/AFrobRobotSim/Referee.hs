-- |
-- Module      : AFrobRobotSim.Referee
-- Description : What a run does besides its robots: the balls' rule, the
--               scores and the goals a program's runs show.
--
-- A 'Referee' is what 'AFrobRobotSim.runSimRefereed' adds to a run of
-- 'AFrobRobotSim.runSim': a rule that puts the balls back (a goal's
-- kick-off, say), the scores kept over the run, and the goal areas to
-- draw. The scores reach every output: each snapshot's 'wsScores', the
-- log's frames (a rise is a @"score"@ event) and summary, the replay
-- page's score line and events, and the result line's @"scores"@. The
-- goals are drawn on the replay page and listed in the log's header.
--
-- > -- each team's goals: a ball past x = 4 is A's, past x = -4 B's (counted
-- > -- once a crossing: 'edge'), and the referee puts it back on the centre
-- > goals :: SF WorldState [(String, Int)]
-- > goals = proc ws -> do
-- >   a <- edge -< any (\(Point2 x _) -> x > 4) (wsBalls ws)
-- >   b <- edge -< any (\(Point2 x _) -> x < -4) (wsBalls ws)
-- >   na <- accumHold 0 -< fmap (const (+ 1)) a
-- >   nb <- accumHold 0 -< fmap (const (+ 1)) b
-- >   returnA -< [("A", na), ("B", nb)]
-- >
-- > backToCentre :: Time -> [Position2] -> Maybe [Position2]
-- > backToCentre _ bs
-- >   | any (\(Point2 x _) -> abs x > 4.5) bs = Just [Point2 0 0]
-- >   | otherwise                          = Nothing
-- >
-- > main = runSimRefereed noReferee { refereeBalls = backToCentre, refereeScores = goals }
-- >                       (Just pitch) teamA teamB
module AFrobRobotSim.Referee
  ( Referee (..)
  , noReferee
  , refereeConfig
  , checkGoals
  ) where

import           AFRP
import           AFrob.Dimensions          (Position2)
import           AFrobRobotSim.Log.Records (LogRect (..))
import           AFrobRobotSim.Simulator   (SimConfig (..), WorldState)

-- | A run's referee.
data Referee = Referee
  { refereeBalls  :: Time -> [Position2] -> Maybe [Position2]
    -- ^ the balls' rule ('AFrobRobotSim.Simulator.simBallRule'): after
    -- each step, given the time and the balls' new positions, 'Just' new
    -- positions puts the balls there, at rest; 'Nothing' leaves them be
  , refereeScores :: SF WorldState [(String, Int)]
    -- ^ the scores ('AFrobRobotSim.Simulator.simScores'): a signal
    -- function of the snapshots, whose output for each is its scores
    -- (names distinct, at most 10,000 characters; values within 2^53);
    -- it may keep state, to count goals, say
  , refereeGoals  :: [LogRect]
    -- ^ goal areas to draw (centre and size, in metres): the replay page
    -- shades them, and the log's header lists them. Each must have
    -- finite coordinates and sizes that are not negative ('checkGoals').
  }

-- | No rule for the balls, no scores, no goals: a run of
-- 'AFrobRobotSim.runSim'.
noReferee :: Referee
noReferee = Referee (\_ _ -> Nothing) (constant []) []

-- | The simulator's settings with the referee's rules in them
-- ('simBallRule', 'simScores').
refereeConfig :: Referee -> SimConfig -> SimConfig
refereeConfig r cfg = cfg { simBallRule = refereeBalls r, simScores = refereeScores r }

-- | What is wrong with the referee's goals, one line each (@[]@ when
-- nothing is): a coordinate that is not a finite number, a negative
-- width or height. (A goal is only drawn, so one partly or wholly
-- outside the world is allowed.)
checkGoals :: Referee -> [String]
checkGoals r =
  [ "the referee's goal " ++ show i ++ " (refereeGoals, in the list's order) " ++ what
  | (i, LogRect x y w h) <- zip [1 :: Int ..] (refereeGoals r)
  , what <- [ "has a centre that is not a finite point: (" ++ show x ++ ", " ++ show y ++ ")"
            | not (all finiteD [x, y]) ]
            ++ [ "has a size that is not finite and at least 0: " ++ show w ++ " x " ++ show h
               | not (all (\v -> finiteD v && v >= 0) [w, h]) ] ]
  where
    finiteD v = not (isNaN v || isInfinite v)
