{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Soccer.Pitch
-- Description : Exercise 15's pitch, kick-off, referee and match runner.
--
-- = The pitch
--
-- The whole 10 m world is the pitch, 8 m between the goal lines
-- (@x = -4@ and @x = 4@) and 10 m wide. Each goal line is a row of
-- vertical wall segments with a gap, the goal mouth, of 1.8 m
-- (@|y| < 0.9@). Behind each mouth a goal 1 m deep is closed by two
-- horizontal wall segments (its side walls) and the world's boundary (its
-- back wall); the strips behind the goal lines beside the goals are sealed
-- off.
--
-- @
--    y=5 +--+-------------------------------------------+--+
--        |##|                                           |##|
--        |##|                                           |##|
--  y=0.9 +--|                                           |--+
--   goal :  :  1      2     3       o       3     2      1  :  : goal
-- y=-0.9 +--|                                           |--+
--        |##|                                           |##|
--   y=-5 +--+-------------------------------------------+--+
--      x=-5 -4                      0                    4  5
-- @
--
-- (@##@: sealed off; the numbers are the players' ids at the kick-off:
-- team A on the left, team B on the right.)
--
-- = Teams
--
-- Team A is the 'SimbotA' robots: it defends the west goal (@x < 0@) and
-- attacks the east one. Team B is the 'SimbotB' robots, the other way
-- round. A robot tells friend from foe by the 'RobotType' the tracker
-- reports. Within a team the ids give the roles: 1 the goalkeeper, 2 the
-- defender, 3 the attacker. (SimbotB robots are twice as fast as SimbotA
-- ones, so team A starts with a handicap.)
--
-- = The referee
--
-- The simulator's 'simBallRule' hook lets 'referee' look at the ball after
-- every step. When the whole ball is over a goal line inside the goal
-- ('goalOf'), it is a goal, and the ball goes back to the centre mark, at
-- rest. A ball out of play (through a wall or the boundary, which a robot
-- pinning the ball against a wall can do in this simulator) is put back at
-- the nearest point well inside the pitch, and a ball in a corner, where
-- no robot can get behind it, 1 m out of the corner. The hook has no
-- memory, so the goals are read back from the run ('goalsIn'): a goal is
-- the ball jumping to the centre mark from the far end of the pitch in one
-- step, something no kick and no other ruling does.
module Exercises.Soccer.Pitch
  ( -- * The pitch
    goalLineX
  , goalHalfWidth
  , centreMark
  , centreCircleRadius
  , pitchWalls
    -- * Teams
  , Team (..)
  , teamOfType
  , goalOf
  , inPlay
    -- * Kick-off
  , goalkeeperId
  , soccerWorld
  , kickOffPositions
    -- * Refereeing and matches
  , referee
  , goalScores
  , goalAreas
  , matchReferee
  , matchConfig
  , matchDt
  , goalsIn
  , MatchResult (..)
  , matchResult
  , playMatch
  ) where

import           Data.Bits     (shiftR, xor)
import           Data.Maybe    (isJust)
import           Data.Word     (Word64)

import           AFrob         hiding (forAll)
import           AFrobRobotSim

-- | The goal lines are at @x = -goalLineX@ (team A's goal) and
-- @x = goalLineX@ (team B's): 4 m.
goalLineX :: Position
goalLineX = 4

-- | Half the width of a goal mouth: 0.9 m (the mouth is 1.8 m wide).
goalHalfWidth :: Distance
goalHalfWidth = 0.9

-- | Where the ball starts, and restarts after a goal: the origin.
centreMark :: Position2
centreMark = Point2 0 0

-- | The radius of the centre circle, which no player enters before the
-- kick-off: 1 m.
centreCircleRadius :: Distance
centreCircleRadius = 1

-- | The walls of the pitch: at each end the goal line (vertical segments
-- from the goal mouth to the world's edge, both sides) and the goal's two
-- side walls (horizontal segments from the goal line to the world's edge).
pitchWalls :: WorldTemplate
pitchWalls =
  [ OTVWall (Point2 (sx * (goalLineX + wallThickness / 2)) (sy * y))
  | sx <- [-1, 1], sy <- [-1, 1], y <- lineCentres ]
  ++
  [ OTHWall (Point2 (sx * (goalLineX + wallLength / 2)) (sy * (goalHalfWidth + wallThickness / 2)))
  | sx <- [-1, 1], sy <- [-1, 1] ]
  where
    -- Segments from the mouth outwards; the last one is flush with the
    -- world's edge (it may overlap its neighbour).
    lineCentres = takeWhile (< outermost) [goalHalfWidth + wallLength / 2, goalHalfWidth + 3 * wallLength / 2 ..]
                  ++ [outermost]
    outermost = worldYMax - wallLength / 2

-- | The two teams (see the module documentation).
data Team = TeamA | TeamB
  deriving (Eq, Ord, Show, Enum, Bounded)

-- | The team of a robot type: 'TeamA' for @\"SimbotA\"@, 'TeamB' for
-- anything else.
teamOfType :: RobotType -> Team
teamOfType ty
  | ty == kindType SimbotA = TeamA
  | otherwise              = TeamB

-- | The team whose goal a ball centred here is in, if it is in one: the
-- whole ball (radius 0.15 m) over the goal line, between the posts.
goalOf :: Position2 -> Maybe Team
goalOf (Point2 x y)
  | abs y >= goalHalfWidth || abs x < goalLineX + ballDiameter / 2 = Nothing
  | x < 0     = Just TeamA
  | otherwise = Just TeamB

-- | Whether a ball centred here is where a ball can be in play: on the
-- pitch or inside a goal, clear of the walls (up to 1 cm of overlap,
-- rounding) and inside the world.
inPlay :: Position2 -> Bool
inPlay (Point2 x y) = ax <= worldXMax - r && ay <= worldYMax - r && (onPitch || inMouth || byPost)
  where
    (ax, ay) = (abs x, abs y)
    r        = ballDiameter / 2 - 0.01
    onPitch  = ax <= goalLineX - r
    inMouth  = ay <= goalHalfWidth - r
    -- beside a post, clear of its corner
    byPost   = ay < goalHalfWidth && ax < goalLineX
               && distance (Point2 ax ay) (Point2 goalLineX goalHalfWidth) >= r

-- | The id of each team's goalkeeper: 1.
goalkeeperId :: RobotId
goalkeeperId = 1

-- | The kick-off positions of team A (ids 1, 2, 3: goalkeeper, defender,
-- attacker) with their headings, in its own half facing the other goal,
-- all outside the centre circle. Team B's are these turned half a turn
-- about the centre mark.
kickOffPositions :: [(RobotId, Position2, Heading)]
kickOffPositions =
  [ (1, Point2 (-3.6) 0, 0)
  , (2, Point2 (-2.4) 1.0, 0)
  , (3, Point2 (-1.6) (-0.3), 0) ]

-- | The pitch, the ball on the centre mark and both teams at their
-- kick-off positions, each robot moved by up to 0.2 m in x and y and
-- turned by up to 0.3 rad, pseudo-randomly from the seed (the same seed
-- gives the same world).
soccerWorld :: Int -> WorldTemplate
soccerWorld seed = pitchWalls ++ [OTBall centreMark] ++ team OTSimbotA 1 0 ++ team OTSimbotB (-1) 1
  where
    team make s k =
      [ make i (Point2 (s * x + 0.2 * jitter 0) (s * y + 0.2 * jitter 1))
               (h + (if s > 0 then 0 else pi) + 0.3 * jitter 2)
      | (i, Point2 x y, h) <- kickOffPositions
      , let jitter j = unitNoise seed (k * 100 + i * 10 + j) ]

-- A number in [-1, 1) from a seed and an index (a SplitMix64 step).
unitNoise :: Int -> Int -> Double
unitNoise seed j =
  let s  = fromIntegral seed * 0x9E3779B97F4A7C15 + fromIntegral j * 0xD1B54A32D192ED03 :: Word64
      z1 = (s `xor` (s `shiftR` 30)) * 0xBF58476D1CE4E5B9
      z2 = (z1 `xor` (z1 `shiftR` 27)) * 0x94D049BB133111EB
      z3 = z2 `xor` (z2 `shiftR` 31)
  in fromIntegral (z3 `shiftR` 11) / 4503599627370496 - 1

-- | The referee, for 'simBallRule'. A ball in a goal goes to the centre
-- mark. A ball out of play goes to the nearest point 0.7 m inside the
-- pitch's walls, and a ball in a corner (within 0.3 m of both walls, where
-- no robot can get behind it) to the point 1 m out from both. If any of
-- this happens, every ball is put down at rest; otherwise ('Nothing') play
-- goes on.
referee :: Time -> [Position2] -> Maybe [Position2]
referee _ balls
  | all (\b -> rule b == b) balls = Nothing
  | otherwise                     = Just (map rule balls)
  where
    rule b@(Point2 x y)
      | isJust (goalOf b) = centreMark
      | not (inPlay b)    = Point2 (limit (goalLineX - 0.7) x) (limit (worldYMax - 0.7) y)
      | abs x >= goalLineX - ballDiameter / 2 - 0.3 && abs y >= worldYMax - ballDiameter / 2 - 0.3
                          = Point2 (signum x * (goalLineX - 1)) (signum y * (worldYMax - 1))
      | otherwise         = b
    limit m v = max (negate m) (min m v)

-- | The score of a run made with the 'referee', snapshot by snapshot: each
-- team's goals so far, as @[(\"A\", a), (\"B\", b)]@, a goal counted at
-- the snapshot where the ball is back on the centre mark ('goalsIn''s
-- rule, so that the last snapshot's score is 'matchResult''s). For the
-- simulator's 'simScores' and a 'Referee''s 'refereeScores'.
goalScores :: SF WorldState [(String, Int)]
goalScores = proc ws -> do
  let ball = case wsBalls ws of
        [b] -> Just b
        _   -> Nothing
  before <- iPre Nothing -< ball
  let goal = maybe NoEvent Event (goalBetween =<< ((,) <$> before <*> ball))
  a <- accumHold 0 -< (+ 1) <$ filterE (== TeamA) goal
  b <- accumHold 0 -< (+ 1) <$ filterE (== TeamB) goal
  returnA -< [("A", a), ("B", b)]

-- | The two goals, for the replay page: from each goal line to the
-- world's boundary, as wide as the mouth.
goalAreas :: [LogRect]
goalAreas = [ LogRect (s * (goalLineX + worldXMax) / 2) 0 (worldXMax - goalLineX) (2 * goalHalfWidth) | s <- [-1, 1] ]

-- | The 'referee', 'goalScores' and 'goalAreas' as a run's 'Referee', for
-- 'runSimRefereed': a match whose replay page shows the goals and the
-- score.
matchReferee :: Referee
matchReferee = Referee { refereeBalls = referee, refereeScores = goalScores, refereeGoals = goalAreas }

-- | The time step of a match: 0.05 s.
matchDt :: DTime
matchDt = 0.05

-- | The settings of a match: the time step 'matchDt', exact odometry, the
-- 'referee' and its 'goalScores'.
matchConfig :: SimConfig
matchConfig = defaultSimConfig { simDt = matchDt, simBallRule = referee, simScores = goalScores }

-- | The goals of a run made with the 'referee': the time of each and the
-- team that scored it, in order. A goal shows as the (single) ball at
-- the centre mark one snapshot after being at least 3 m from it.
goalsIn :: [WorldState] -> [(Time, Team)]
goalsIn ws =
  [ (wsTime w1, team)
  | (w0, w1) <- zip ws (drop 1 ws)
  , [b0] <- [wsBalls w0], [b1] <- [wsBalls w1]
  , Just team <- [goalBetween (b0, b1)] ]

-- The team that scored between two snapshots of the (single) ball: its
-- jump back to the centre mark from at least 3 m away, from the half
-- that team attacks.
goalBetween :: (Position2, Position2) -> Maybe Team
goalBetween (b0, b1)
  | b1 == centreMark, distance b0 centreMark >= 3 = Just (if point2X b0 > 0 then TeamA else TeamB)
  | otherwise                                      = Nothing

-- | The outcome of a match.
data MatchResult = MatchResult
  { goalsA    :: !Int              -- ^ goals scored by team A
  , goalsB    :: !Int              -- ^ goals scored by team B
  , goalTimes :: [(Time, Team)]    -- ^ every goal in order: when, and who scored
  } deriving (Eq)

-- | The score, as @A 3 - 1 B@.
instance Show MatchResult where
  show r = "A " ++ show (goalsA r) ++ " - " ++ show (goalsB r) ++ " B"

-- | The result of a run made with the 'referee', from its 'goalsIn'.
matchResult :: [WorldState] -> MatchResult
matchResult ws = MatchResult (scoredBy TeamA) (scoredBy TeamB) gs
  where
    gs         = goalsIn ws
    scoredBy t = length (filter ((== t) . snd) gs)

-- | @playMatch seed seconds teamA teamB@: a match of the given length in
-- @soccerWorld seed@ with 'matchConfig', team A's robots run by @teamA@
-- and team B's by @teamB@.
playMatch :: Int -> Double -> SimbotController -> SimbotController -> MatchResult
playMatch seed seconds rcA rcB =
  matchResult (takeWhile ((<= seconds + matchDt / 2) . wsTime)
                         (simulateWith matchConfig (soccerWorld seed) rcA rcB))
