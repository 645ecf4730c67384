-- |
-- Module      : Exercises.Ex15
-- Description : Exercise 15: robocup soccer.
--
-- /Exercise 15./ Write a program to play \"robocup soccer\": two goals
-- made of wall segments, a ball on the centre mark, a team of players on
-- each side, positioned strategically and on-side, with controllers for
-- each of them.
--
-- The pitch, the teams, the kick-off and the referee are in
-- "Exercises.Soccer.Pitch"; how a player perceives and drives in
-- "Exercises.Soccer.Player"; the roles in "Exercises.Soccer.Roles". Here
-- are the two team controllers that can be pitted against each other:
--
-- * 'teamSmart': a goalkeeper that slides along its goal line to where the
--   ball will cross it, a defender that stays between the ball and its goal
--   and clears the ball away from the goal, and an attacker that gets
--   behind the ball before kicking it at the open half of the goal. Of the
--   two field players only the one nearer the ball goes for it; the other
--   keeps its position.
--
-- * 'teamNaive': a goalkeeper parked in the middle of its goal and two
--   players that run straight at the ball, whichever way that kicks it.
--
-- The smart team wins. In 5-minute matches ('playMatch') with seeds 1 to
-- 12 it beat the naive team 22-3 in goals playing with the slow SimbotA
-- robots (8 wins, 4 draws) and 15-1 with the fast SimbotB robots (8 wins,
-- 4 draws); a test checks these figures.
--
-- A team controller is a 'SimbotController' that works for either team
-- (it reads the robot type to know which goal it attacks), so
-- @playMatch seed seconds teamSmart teamNaive@ and
-- @playMatch seed seconds teamNaive teamSmart@ are both matches.
--
-- The @ex15@ example runs a match with the plain simulator, which has no
-- referee: the goalkeepers call out the goals they concede on the
-- console, but the ball stays in the goal (or rolls out of it) and the
-- score is not kept. 'playMatch' runs matches with the referee and returns
-- the score.
module Exercises.Ex15
  ( -- * The example
    examples
    -- * Teams
  , teamSmart
  , teamNaive
    -- * Matches
  , soccerWorld
  , playMatch
  , MatchResult (..)
  , Team (..)
  , goalOf
  ) where

import           AFrob                  hiding (forAll)
import           AFrobRobotSim

import           Examples.Types
import           Exercises.Soccer.Pitch
import           Exercises.Soccer.Player
import           Exercises.Soccer.Roles

-- | The smart team: the 'goalkeeper' (id 1, which also 'callGoals'), the
-- 'defender' (id 2), and an 'attacker' (any other id).
teamSmart :: SimbotController
teamSmart rps
  | rpId rps == goalkeeperId = callGoals (player goalkeeper) rps
  | rpId rps == 2            = player defender rps
  | otherwise                = player attacker rps

-- | The naive team: the 'parkedKeeper' (id 1, which also 'callGoals'), and
-- 'chaser's (any other id) that wait in their own half when they do not
-- see the ball.
teamNaive :: SimbotController
teamNaive rps
  | rpId rps == goalkeeperId = callGoals (player parkedKeeper) rps
  | otherwise                = player (chaser (Point2 (-1.5) 0)) rps

-- | The Exercise 15 example: 'teamSmart' (team A, the SimbotA robots,
-- playing west to east) against 'teamNaive' (team B, the faster SimbotB
-- robots) in @soccerWorld 10@, for two minutes: team A scores after about
-- 13 s (team B's keeper calls it out). With no referee the ball is not put
-- back on the centre mark; it rolls out of the goal, and team B scores
-- after about 55 s. And @ex15-match@: the same with the match's referee
-- ('matchReferee'), whose replay page shows the goals and the score.
examples :: [Example]
examples =
  [ match "ex15" "Exercise 15: robocup soccer, a smart team (SimbotA) against a naive one (SimbotB)" noReferee
  , match "ex15-match" "Exercise 15 refereed: the same teams, goals counted and the ball put back on the centre mark"
          matchReferee ]
  where
    match name description referee' = RobotExample
      { exName        = name
      , exDescription = description
      , exWorld       = soccerWorld 10
      , exControllerA = teamSmart
      , exControllerB = teamNaive
      , exSeconds     = 120
      , exKeys        = []
      , exReferee     = referee'
      }
