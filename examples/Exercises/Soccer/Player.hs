{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Soccer.Player
-- Description : Exercise 15's players: what a player knows, how it drives,
--               how it gets free.
--
-- A player is three stages: 'perceive' turns the sensors into a 'View',
-- a 'Role' (a plain function, see "Exercises.Soccer.Roles") turns the view
-- into a 'Drive' intention, and 'steer' turns the intention into wheel
-- commands. Only perception has memory; roles are pure, so they can be
-- read (and tested) one decision at a time. 'player' puts the stages
-- together and adds 'unstick'.
--
-- Every view is in the player's /team frame/: team B's coordinates are
-- turned half a turn about the centre mark, so every role is written once,
-- for a team that defends the goal at @x = -4@ and attacks the one at
-- @x = 4@. (Turning by half a turn keeps counter-clockwise counter-clockwise,
-- so the wheel commands need no change.)
--
-- The tracker sees only 4 m, less than the pitch: a player remembers where
-- it last saw the ball for 'ballMemory' seconds, unless it is close enough
-- to that spot to see that the ball has gone (it was kicked, or the
-- referee took it to the centre mark).
module Exercises.Soccer.Player
  ( -- * What a player knows
    View (..)
  , perceive
  , ballMemory
    -- * Driving
  , Drive (..)
  , steer
  , unstick
  , escapeTime
    -- * Players
  , Role
  , player
  , callGoals
    -- * Vectors
  , unit
  , perp
  ) where

import           Data.Maybe             (listToMaybe)

import           AFrob                  hiding (forAll)
import           AFrobRobotSim

import           Exercises.Soccer.Pitch

-- | What a player knows at one instant, in its team frame.
data View = View
  { vwTime     :: Time                           -- ^ how long it has been playing
  , vwPos      :: Position2                      -- ^ where it is (odometry)
  , vwHeading  :: Heading                        -- ^ which way it faces
  , vwBall     :: Maybe (Position2, Velocity2)   -- ^ where it believes the ball is, and its velocity
  , vwFriends  :: [(RobotId, Position2)]         -- ^ its team mates in sight
  , vwFoes     :: [Position2]                    -- ^ its opponents in sight
  , vwMaxSpeed :: Speed                          -- ^ its top speed
  , vwMaxAcc   :: Acceleration                   -- ^ its top acceleration
  } deriving (Show)

-- | How long a player believes in a ball it no longer sees: 2 s.
ballMemory :: Time
ballMemory = 2

-- | The player's view, from its sensors and its memory of the ball. The
-- ball's velocity is the rate of change of its sighted position; a jump
-- faster than any kick (7 m/s: the ball reappearing elsewhere) reads as
-- at rest. A remembered ball is taken to be at rest.
perceive :: SimbotProperties -> SF SimbotInput View
perceive rps = proc sbi -> do
  t <- localTime -< ()
  let team     = teamOfType (rpType rps)
      here     = odometryPosition sbi
      place a d = inFrame team (here .+^ vector2Polar d (odometryHeading sbi + a))
      sighted  = uncurry place <$> listToMaybe (aotBalls sbi)
  lastPlace <- trackAndHold centreMark -< sighted
  lastSeen  <- trackAndHold (-ballMemory) -< t <$ sighted
  rate      <- derivative -< lastPlace .-. origin
  let me        = inFrame team here
      velocity  = case sighted of
        Just _ | norm rate < 7 -> rate
        _                      -> zeroVector
      believed  = case sighted of
        Just b  -> Just (b, velocity)
        Nothing | t - lastSeen < ballMemory && distance me lastPlace > 0.9 * trackerRange
                  -> Just (lastPlace, zeroVector)
                | otherwise -> Nothing
      others    = [ (teamOfType ty == team, (i, place a d)) | (ty, i, a, d) <- aotOtherRobots sbi ]
  returnA -< View
    { vwTime = t
    , vwPos = me
    , vwHeading = normalizeHeading (odometryHeading sbi + turnOf team)
    , vwBall = believed
    , vwFriends = [ p | (True, p) <- others ]
    , vwFoes = [ p | (False, (_, p)) <- others ]
    , vwMaxSpeed = rpWSMax rps
    , vwMaxAcc = rpAccMax rps }

-- A world position in a team's frame (and back: the turn is its own
-- inverse).
inFrame :: Team -> Position2 -> Position2
inFrame TeamA p            = p
inFrame TeamB (Point2 x y) = Point2 (negate x) (negate y)

turnOf :: Team -> Angle
turnOf TeamA = 0
turnOf TeamB = pi

-- | What a role wants the wheels to do.
data Drive
  = Towards Position2 Speed
    -- ^ drive forwards to the point, at most at this speed, slowing down
    -- in time to stop there (a point beyond the ball is driven /through/
    -- the ball)
  | Glide Velocity2 Heading
    -- ^ move with this velocity, forwards or backwards, whichever needs
    -- less turning; when it is (almost) zero, turn on the spot to face
    -- the heading or its opposite
  deriving (Eq, Show)

-- | The wheel commands for an intention. The rotational velocity is 4
-- times the heading error; the speed is cut by the cosine of the heading
-- error, so a robot facing away turns first and drives after. On its way
-- 'Towards' a point a robot sidesteps the robots in front of it.
steer :: View -> Drive -> MR SimbotOutput
steer vw drive = case drive of
  Towards p vMax
    | d < 0.1   -> ddBrake
    | otherwise -> ddVelTR (min vMax (sqrt (2 * vwMaxAcc vw * d)) * max 0 (cos he)) (kTurn * he)
    where
      way = p .-. vwPos vw
      d   = norm way
      he  = normalizeAngle (vector2Theta (sidestep vw d (unit way)) - vwHeading vw)
  Glide v rest
    | speed < 0.05 -> ddVelTR 0 (kTurn * facing rest)
    | otherwise    -> ddVelTR (speed * cos (normalizeAngle (hd - vwHeading vw))) (kTurn * facing hd)
    where
      (speed, hd) = vector2RhoTheta v
  where
    kTurn = 4
    -- The error to the nearer of a heading and its opposite.
    facing h = let e = normalizeAngle (h - vwHeading vw)
               in if abs e > pi / 2 then normalizeAngle (e + pi) else e

-- A direction of travel bent away from the robots ahead: each robot
-- closer than 1 m (and than the destination, at the given distance) and in
-- front pushes the direction sideways, away from itself, the harder the
-- closer it is.
sidestep :: View -> Distance -> Vector2 Double -> Vector2 Double
sidestep vw dist dir = unit (foldr (^+^) dir pushes)
  where
    pushes = [ (2 * (1 - d) * away) *^ perp dir
             | r <- map snd (vwFriends vw) ++ vwFoes vw
             , let off = r .-. vwPos vw
                   d   = norm off
             , d < 1, d < dist, off `dot` dir > 0
             , let away = if cross dir off > 0 then -1 else 1 ]
    cross (Vector2 ax ay) (Vector2 bx by) = ax * by - ay * bx

-- | Get free when stuck: once the robot is stuck, it drives straight the
-- other way from the one its controller asked for (backwards if that was
-- forwards) at half speed for 'escapeTime'. If it is still stuck after
-- that, it tries the opposite way, and so on, turning from the third try
-- on (a robot wedged between two obstacles gets out sideways). Then it
-- hands back to the controller, which has been running all along.
unstick :: SimbotProperties -> SF SimbotInput SimbotOutput -> SF SimbotInput SimbotOutput
unstick rps sf = proc sbi -> do
  out <- sf -< sbi
  t   <- localTime -< ()
  rec let escape = nextEscape t (rsIsStuck sbi) (commandedDirection out) before
      before <- iPre Nothing -< escape
  returnA -< case escape of
    Just (Escape t0 dir tries)
      | t - t0 < escapeTime
      -> mrFinalize (ddVelTR (dir * rpWSMax rps / 2) (if tries >= 2 then 2 else 0))
    _ -> out

-- | How long 'unstick' drives away from an obstacle: 1 s.
escapeTime :: Time
escapeTime = 1

-- One try to get free: when it started, which way it drives (1 forwards,
-- -1 backwards), and how many tries came before it.
data Escape = Escape !Time !Double !Int

-- The escape after this sample, given the one before it.
nextEscape :: Time -> Bool -> Double -> Maybe Escape -> Maybe Escape
nextEscape t stuck asked before = case before of
  Just (Escape t0 dir tries)
    | t - t0 < escapeTime                -> before
    | stuck && t - t0 < escapeTime + 0.1 -> Just (Escape t (negate dir) (tries + 1))
  _ | stuck                              -> Just (Escape t (negate asked) 0)
    | otherwise                          -> before

-- Which way a command drives: -1 backwards, 1 forwards (or not at all).
commandedDirection :: SimbotOutput -> Double
commandedDirection o = case soDrive o of
  DriveTR v _     | v < 0     -> -1
  DriveWheels l r | l + r < 0 -> -1
  _                           -> 1

-- | A role: what to do, given what the player knows.
type Role = View -> Drive

-- | A player of a role: 'perceive', the role, 'steer', 'unstick'.
player :: Role -> SimbotController
player role rps = unstick rps (perceive rps >>> arr (\vw -> mrFinalize (steer vw (role vw))))

-- | A controller that also calls out every goal it sees scored against
-- its team: a console message (@GOAL! Team B scores@) when a ball it
-- sees comes to be in its own goal. In a match with the 'referee' the ball
-- never stays in a goal long enough to be seen there; this is for runs
-- without one.
callGoals :: SimbotController -> SimbotController
callGoals rc rps = proc sbi -> do
  out    <- rc rps -< sbi
  conced <- edge -< any ((== Just team) . goalOf) (sightedBalls sbi)
  returnA -< event out (\m -> out { soMessages = soMessages out ++ [m] }) (call <$ conced)
  where
    team = teamOfType (rpType rps)
    call = if team == TeamA then "GOAL! Team B scores" else "GOAL! Team A scores"

-- Where the balls the robot sees are (in the world).
sightedBalls :: SimbotInput -> [Position2]
sightedBalls sbi =
  [ odometryPosition sbi .+^ vector2Polar d (odometryHeading sbi + a) | (a, d) <- aotBalls sbi ]

------------------------------------------------------------------------------
-- Vectors

-- | The unit vector in a direction (the zero vector stays zero).
unit :: Vector2 Double -> Vector2 Double
unit v = let n = norm v in if n < 1e-9 then zeroVector else (1 / n) *^ v

-- | The vector turned a quarter turn counter-clockwise.
perp :: Vector2 Double -> Vector2 Double
perp (Vector2 vx vy) = Vector2 (negate vy) vx
