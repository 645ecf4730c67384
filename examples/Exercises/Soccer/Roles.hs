-- |
-- Module      : Exercises.Soccer.Roles
-- Description : Exercise 15's role controllers: goalkeeper, defender,
--               attacker, and their naive counterparts.
--
-- Each role is a plain function from what a player knows (a 'View', in
-- its team frame: it defends the goal at @x = -4@) to what it wants the
-- wheels to do (a 'Drive'); 'player' in "Exercises.Soccer.Player" makes a
-- controller of it. The smart roles share 'kickTowards', which gets behind
-- the ball before kicking it, and go round the ball rather than through
-- it; the naive ones just run at the ball.
module Exercises.Soccer.Roles
  ( -- * The smart roles
    goalkeeper
  , defender
  , attacker
  , kickTowards
    -- * The naive roles
  , parkedKeeper
  , chaser
  ) where

import           AFrob                  hiding (forAll)
import           AFrobRobotSim

import           Exercises.Soccer.Pitch
import           Exercises.Soccer.Player

------------------------------------------------------------------------------
-- The smart roles

-- Where things are, in the team frame.
ownGoal, theirGoal :: Position2
ownGoal   = Point2 (negate goalLineX) 0
theirGoal = Point2 (goalLineX + 0.5) 0

-- | The goalkeeper: keeps to a line 0.35 m in front of its goal, facing
-- along it, and slides to where the ball would cross the line if it is
-- coming, or else to where the line meets the bisector of the angle the
-- goal mouth makes at the ball; never beyond the posts, and never faster
-- than it can stop in time. A slow ball within 1 m in front of it, close
-- to the goal and with no opponent near it, it clears (kicks straight away
-- from the goal with 'kickTowards'). With no ball in sight it waits in the
-- middle of the goal.
goalkeeper :: Role
goalkeeper vw = case vwBall vw of
  Just ball@(b, vb)
    | distance b me < 1 && point2X b < negate goalLineX + 1.2 && point2X b > lineX + 0.3
      && norm vb < 0.5 && all (\f -> distance f b > 1) (vwFoes vw)
    -> kickTowards (clearing b) vw ball
  _ | abs (x - lineX) > 0.3 -> Towards (Point2 lineX targetY) (vwMaxSpeed vw)
    | otherwise -> Glide (vector2 (2 * (lineX - x)) (braking (targetY - y))) (pi / 2)
  where
    me@(Point2 x y) = vwPos vw
    lineX   = negate goalLineX + 0.35
    targetY = limit (goalHalfWidth - 0.2) guarding
    guarding = case vwBall vw of
      Just (b@(Point2 bx by), Vector2 vx vy)
        | vx < -0.2 && bx > lineX -> by + vy * (bx - lineX) / negate vx
        | otherwise               -> bisecting b
      Nothing -> 0
    bisecting b@(Point2 bx by) =
      let Vector2 dx dy = unit (post 1 .-. b) ^+^ unit (post (-1) .-. b)
      in if bx <= lineX || dx > -1e-3 then by else by + dy * (lineX - bx) / dx
    post s = Point2 (negate goalLineX) (s * goalHalfWidth)
    -- The speed towards a point this far off from which the robot can
    -- still brake to a stop there.
    braking e = signum e * min (vwMaxSpeed vw) (sqrt (2 * vwMaxAcc vw * abs e))

-- | The defender: clears the ball (kicks it straight away from its goal
-- with 'kickTowards') when it is deep in its own half (2 m or less from the goal line), or in its own
-- half (or just beyond) and no other field player of its team is nearer
-- to it. Otherwise it stands between the ball and its goal, halfway out to
-- the ball but at most 2 m out and never past @x = -1@, going round the
-- ball, never through it, on its way there. With no ball in sight it
-- patrols 1.5 m out from its goal line, where it sees the corners of its
-- half in turn.
defender :: Role
defender vw = case vwBall vw of
  Nothing -> Towards (patrol [ Point2 (negate goalLineX + 1.5) y | y <- [1.5, -1.5] ] vw)
                     (vwMaxSpeed vw)
  Just ball@(b, _)
    | deep b || (point2X b < 0.5 && nearestToBall vw b)
    -> kickTowards (clearing b) vw ball
    | otherwise
    -> let out   = min 2 (0.5 * distance b ownGoal)
           guard = ownGoal .+^ (out *^ unit (b .-. ownGoal))
           spot  = Point2 (min (-1) (point2X guard)) (point2Y guard)
       in Towards (roundBall b (vwPos vw) spot) (vwMaxSpeed vw)

-- | The attacker: when no other field player of its team is nearer the
-- ball, it goes for it: 'kickTowards' the far goal, aiming at the half of
-- the mouth away from the goalkeeper it sees (the nearest opponent to the
-- goal), or away from the ball if it sees none. Otherwise it waits for a
-- pass 1.5 m further upfield and 1.5 m nearer the middle than the ball. A
-- ball deep in its own half it leaves to the defence, waiting level with
-- it 2 m further out. With no ball in sight it patrols the far half, whose
-- corners it then sees in turn.
attacker :: Role
attacker vw = case vwBall vw of
  Nothing -> Towards (patrol [Point2 1 2.5, Point2 1 (-2.5)] vw) (vwMaxSpeed vw)
  Just ball@(b@(Point2 bx by), _)
    | deep b             -> Towards (roundBall b me (Point2 (negate goalLineX + 4) (limit 2 by))) vMax
    | nearestToBall vw b -> kickTowards aim vw ball
    | otherwise          -> Towards (roundBall b me (reachable support)) vMax
    where
      support = Point2 (bx + 1.5) (if by > 0 then by - 1.5 else by + 1.5)
  where
    me   = vwPos vw
    vMax = vwMaxSpeed vw
    -- the far half of the mouth from the goalkeeper, or from the ball if
    -- the goalkeeper is out of sight
    aim  = Point2 (point2X theirGoal) (if keeperY > 0 then -0.5 else 0.5)
    keeperY = case [ p | p <- vwFoes vw, distance p theirGoal < 1.5 ] of
      Point2 _ ky : _ -> ky
      []              -> maybe 0 (point2Y . fst) (vwBall vw)

-- Where to kick a ball to clear it: straight away from the player's own
-- goal.
clearing :: Position2 -> Position2
clearing b = b .+^ (3 *^ unit (b .-. ownGoal))

-- Whether a ball is deep in the player's own half: 2 m or less from its
-- goal line.
deep :: Position2 -> Bool
deep b = point2X b < negate goalLineX + 2

-- Whether no field player of the player's team that it sees (its
-- goalkeeper does not count) is nearer the ball than it is.
nearestToBall :: View -> Position2 -> Bool
nearestToBall vw b =
  and [ distance (vwPos vw) b <= distance f b | (i, f) <- vwFriends vw, i /= goalkeeperId ]

-- | Kick the ball towards a point: aim at where the ball will be when the
-- player gets there; if the player is behind the ball and lined up with
-- the point (or as near to that as the walls let it get), drive through
-- the ball at full speed; otherwise drive to the spot 0.55 m behind the
-- ball on the line, going round the ball if it is in the way.
kickTowards :: Position2 -> View -> (Position2, Velocity2) -> Drive
kickTowards target vw (b, vb)
  | lined || distance me behind < 0.15 = Towards (bp .+^ (1.5 *^ u)) (vwMaxSpeed vw)
  | otherwise                          = Towards (roundBall bp me behind) (vwMaxSpeed vw)
  where
    behind = reachable (bp .-^ (0.55 *^ u))
    me     = vwPos vw
    lead   = min 1 (distance me b / vwMaxSpeed vw)
    bp     = inside (ballDiameter / 2) (b .+^ (lead *^ vb))
    u      = kickable bp (unit (target .-. bp))
    rel    = me .-. bp
    along  = rel `dot` u
    across = rel `dot` perp u
    lined  = along < negate 0.3 && abs across < 0.1 + 0.3 * (negate along - 0.3)

-- The direction a ball here can be kicked in, nearest to the one wanted:
-- a robot cannot get behind a ball lying against a wall (within 0.35 m to
-- spare), so the part of the direction that points away from such a wall
-- is dropped, and the ball is pushed along the wall instead.
kickable :: Position2 -> Vector2 Double -> Vector2 Double
kickable (Point2 bx by) (Vector2 ux uy) = unit (Vector2 ux' uy')
  where
    room = ballDiameter / 2 + 0.35
    ux' | abs by > goalHalfWidth && abs bx > goalLineX - room && ux * signum bx < 0 = 0
        | otherwise = ux
    uy' | abs by > worldYMax - room && uy * signum by < 0 = 0
        | otherwise = uy

-- A point on the way to a spot that keeps clear of the ball: the spot
-- itself, or, if the ball is within 0.6 m of the straight way there, a
-- point 0.8 m beside the ball on the player's side (unless the player is
-- already there, as near as the walls let it get).
roundBall :: Position2 -> Position2 -> Position2 -> Position2
roundBall b me spot
  | clear || distance me aside < 0.3 = spot
  | otherwise                        = aside
  where
    aside = reachable (b .+^ (0.8 * side) *^ perp dir)
    way   = spot .-. me
    len   = norm way
    dir   = unit way
    s     = max 0 (min len ((b .-. me) `dot` dir))
    clear = len < 1e-6 || distance b (me .+^ (s *^ dir)) > 0.6 || s >= len
    side  = if (me .-. b) `dot` perp dir >= 0 then 1 else -1

-- The point of a round that a player patrols: each point in turn, for 8 s.
patrol :: [Position2] -> View -> Position2
patrol points vw = points !! (floor (vwTime vw / 8) `mod` length points)

------------------------------------------------------------------------------
-- The naive roles

-- | A naive goalkeeper: goes to the middle of its goal and stays there.
parkedKeeper :: Role
parkedKeeper vw = Towards (Point2 (negate goalLineX + 0.35) 0) (vwMaxSpeed vw)

-- | A naive field player: drives straight at the ball, through it, at full
-- speed, whichever way that kicks it. With no ball in sight it goes back
-- to a spot in its own half.
chaser :: Position2 -> Role
chaser home vw = case vwBall vw of
  Just (b, _) -> Towards (b .+^ (0.3 *^ unit (b .-. vwPos vw))) (vwMaxSpeed vw)
  Nothing     -> Towards home (vwMaxSpeed vw)

------------------------------------------------------------------------------
-- Helpers

-- A number limited to [-m, m].
limit :: Double -> Double -> Double
limit m v = max (negate m) (min m v)

-- The nearest point to a point where a disc of the given radius fits: on
-- the pitch, or inside a goal.
inside :: Distance -> Position2 -> Position2
inside r (Point2 x y)
  | abs y <= goalHalfWidth - r = Point2 (limit (worldXMax - r) x) y
  | otherwise                  = Point2 (limit (goalLineX - r) x) (limit (worldYMax - r) y)

-- Where a robot can go (with a little room to spare).
reachable :: Position2 -> Position2
reachable = inside (simbotDiameter / 2 + 0.1)
