{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Physics
-- Description : How simbots and balls move: differential drive with
--               translational inertia, collisions, bounces, the battery.
--
-- = Simbots
--
-- A simbot's state is its position, heading and translational speed @v@.
-- Each step of @dt@ seconds, given its wheel command:
--
-- 1. The commanded wheel speeds @(vl, vr)@ (from 'DriveWheels', or
--    @(v - w l/2, v + w l/2)@ from 'DriveTR', or @(0, 0)@ for 'DriveBrake')
--    are each clamped to the maximum wheel speed (halved on a critical
--    battery). A non-finite command counts as 0: a controller cannot
--    corrupt the physics.
-- 2. Translational inertia: @v@ moves towards @(vl + vr) / 2@ by at most
--    @accMax * dt@.
-- 3. No rotational inertia: the rotational velocity is @(vr - vl) / l@,
--    limited so that neither wheel exceeds its maximum at the new speed
--    (the notes' @w_max = 2 (v_max - v) / l@).
-- 4. The robot moves along the exact arc for that rotational velocity and
--    the mean of its old and new speeds (exact for a constant acceleration).
-- 5. Collisions are swept: the robot's disc is moved along the chord of
--    the arc and stops at the first contact with a wall, block, the world's
--    boundary or another robot, whatever the speed (no tunnelling). Its
--    speed becomes 0 and it is /stuck/; it stays stuck until it moves
--    again. Robots move one after the other, in template order, each
--    against the others' current positions, so no two ever overlap.
--
-- = Balls
--
-- Balls roll freely, slowing down by rolling friction ('ballFriction' m/s^2),
-- bounce off walls, blocks and the boundary (restitution 'ballRestitution'),
-- are kicked by robots (a robot counts as immovable: the ball's velocity
-- relative to the robot is reflected), and collide elastically with each
-- other (equal masses). Robots are not stopped by balls.
--
-- = Battery
--
-- The charge starts at 1 and drains at @0.0005 + 0.003 * effort@ per
-- second, where @effort@ is the mean absolute wheel speed over the maximum
-- (0 at rest, 1 at full speed). The status is 'BSHigh' above 0.3, 'BSLow'
-- above 0.1, and 'BSCritical' below, where the maximum wheel speed halves.
-- At full effort a fresh battery is low after 200 s and critical after
-- about 257 s.
module AFrobRobotSim.Physics
  ( -- * State
    Arena (..)
  , arenaOf
  , Robot (..)
  , Ball (..)
  , robotVelocity
    -- * Stepping
  , stepRobots
  , stepBalls
    -- * Parameters
  , ballFriction
  , ballRestitution
  , batteryStatusOf
  , wheelCommand
  ) where

import           AFRP              (DTime)
import           AFRP.Geometry
import           AFrob.Angle             (normalizeHeading)
import           AFrob.Dimensions
import           AFrob.RobotIO           (BatteryStatus (..))
import           AFrobRobotSim.Robot     (DriveCommand (..))
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.World

-- | The static part of a world: its obstacles, the boundary included.
newtype Arena = Arena { arenaBoxes :: [Box] }

-- | The arena of a world: its walls and blocks, and four thick boxes just
-- outside its bounds.
arenaOf :: Bounds -> WorldTemplate -> Arena
arenaOf bounds world = Arena (map boxOf (filter isStatic world) ++ boundaryBoxes bounds)

isStatic :: ObjectTemplate -> Bool
isStatic o = case o of
  OTBlock {} -> True
  OTVWall {} -> True
  OTHWall {} -> True
  _          -> False

boxOf :: ObjectTemplate -> Box
boxOf o = let (hw, hh) = objectHalfSize o in boxAround (otPos o) (2 * hw) (2 * hh)

-- The boundary: four thick boxes just outside the world.
boundaryBoxes :: Bounds -> [Box]
boundaryBoxes (Bounds x0 y0 x1 y1) =
  [ Box (x0 - 1) (y0 - 1) x0 (y1 + 1), Box x1 (y0 - 1) (x1 + 1) (y1 + 1)
  , Box (x0 - 1) (y0 - 1) (x1 + 1) y0, Box (x0 - 1) y1 (x1 + 1) (y1 + 1) ]

-- | A simbot's physical state.
data Robot = Robot
  { rKind    :: !RobotKind
  , rId      :: !RobotId
  , rPos     :: !Position2
  , rHeading :: !Heading
  , rSpeed   :: !Speed      -- ^ actual translational speed (signed)
  , rStuck   :: !Bool
  , rCharge  :: !Double     -- ^ battery charge, 1 = full
  } deriving (Eq, Show)

-- | A ball's physical state.
data Ball = Ball
  { bPos :: !Position2
  , bVel :: !(Vector2 Double)
  } deriving (Eq, Show)

-- | Rolling friction of a ball: 0.3 m/s^2.
ballFriction :: Acceleration
ballFriction = 0.3

-- | Coefficient of restitution of a ball against walls, blocks and robots:
-- 0.8.
ballRestitution :: Double
ballRestitution = 0.8

robotRadius, ballRadius :: Length
robotRadius = simbotDiameter / 2
ballRadius  = ballDiameter / 2

-- | The battery status of a charge.
batteryStatusOf :: Double -> BatteryStatus
batteryStatusOf c
  | c > 0.3   = BSHigh
  | c > 0.1   = BSLow
  | otherwise = BSCritical

-- | A robot's velocity vector (for kicking balls).
robotVelocity :: Robot -> Vector2 Double
robotVelocity r = vector2Polar (rSpeed r) (rHeading r)

-- | The commanded (left, right) wheel speeds of a command, each clamped to
-- the given maximum; non-finite values count as 0.
wheelCommand :: Length -> Speed -> DriveCommand -> (Velocity, Velocity)
wheelCommand l wsMax cmd = case cmd of
  DriveBrake      -> (0, 0)
  DriveWheels a b -> (clampW a, clampW b)
  DriveTR v w     -> (clampW (v - w * l / 2), clampW (v + w * l / 2))
  where
    clampW x | isNaN x || isInfinite x = 0
             | otherwise               = max (-wsMax) (min wsMax x)

-- | Move every robot by one step, in order, each against the obstacles and
-- the other robots' current positions.
stepRobots :: DTime -> Arena -> [(Robot, DriveCommand)] -> [Robot]
stepRobots dt arena cmds = go [] cmds
  where
    go done [] = reverse done
    go done ((r, c) : rest) =
      let others = done ++ map fst rest
          !r'    = stepRobot dt arena others r c
      in go (r' : done) rest

stepRobot :: DTime -> Arena -> [Robot] -> Robot -> DriveCommand -> Robot
stepRobot dt arena others r cmd =
  let k       = rKind r
      l       = kindWheelBase k
      status  = batteryStatusOf (rCharge r)
      wsMax   = kindWSMax k * (if status == BSCritical then 0.5 else 1)
      (vl, vr) = wheelCommand l wsMax cmd
      vCmd    = (vl + vr) / 2
      dv      = kindAccMax k * dt
      v0      = rSpeed r
      v1      = v0 + max (-dv) (min dv (vCmd - v0))
      wLim    = max 0 (2 * (wsMax - abs v1) / l)
      w       = max (-wLim) (min wLim ((vr - vl) / l))
      th0     = rHeading r
      th1     = th0 + w * dt
      vMean   = (v0 + v1) / 2
      disp    | abs (w * dt) < 1e-9 = vector2Polar (vMean * dt) th0
              | otherwise           = vector2 (vMean / w * (sin th1 - sin th0))
                                              (vMean / w * (cos th0 - cos th1))
      p0      = rPos r
      contact = firstContact p0 disp arena others
      (p1, v1', hit) = case contact of
        Nothing -> (p0 .+^ disp, v1, False)
        Just s  ->
          -- Stop just short of the contact point, never behind the start.
          let len = norm disp
              s'  = max 0 (s - 1e-9 / max len 1e-300)
          in (p0 .+^ (s' *^ disp), 0, True)
      moved   = p1 /= p0
      effort  = (abs (v1 - w * l / 2) + abs (v1 + w * l / 2)) / (2 * kindWSMax k)
      charge1 = max 0 (rCharge r - dt * (0.0005 + 0.003 * effort))
  in r { rPos     = p1
       , rHeading = normalizeHeading th1
       , rSpeed   = v1'
       , rStuck   = hit || (rStuck r && not moved)
       , rCharge  = charge1
       }

-- The fraction of the move at which the robot first touches something.
firstContact :: Position2 -> Vector2 Double -> Arena -> [Robot] -> Maybe Double
firstContact p d arena others
  | d == zeroVector = Nothing
  | otherwise       = foldr earliest Nothing (boxHits ++ robotHits)
  where
    boxHits   = [ fst <$> sweepCircleBox p robotRadius d b | b <- arenaBoxes arena ]
    robotHits = [ fst <$> sweepCircleCircle p robotRadius d (rPos o) robotRadius | o <- others ]
    earliest Nothing  acc      = acc
    earliest (Just s) Nothing  = Just s
    earliest (Just s) (Just t) = Just (min s t)

-- | Move every ball by one step: friction, bounces off obstacles and
-- robots (at their new positions, with their velocities), then elastic
-- collisions between balls.
stepBalls :: DTime -> Arena -> [Robot] -> [Ball] -> [Ball]
stepBalls dt arena robots balls = resolvePairs (map (stepBall dt arena robots) balls)

stepBall :: DTime -> Arena -> [Robot] -> Ball -> Ball
stepBall dt arena robots b0 =
  let b1 = foldl pushOut b0 robots          -- a robot that drove into the ball kicks it
      v  = slowDown (bVel b1)
      d  = (dt *^ v)
      hits = [ (s, n, zeroVector) | bx <- arenaBoxes arena, Just (s, n) <- [sweepCircleBox (bPos b1) ballRadius d bx] ]
          ++ [ (s, n, robotVelocity r) | r <- robots, Just (s, n) <- [sweepCircleCircle (bPos b1) ballRadius d (rPos r) robotRadius] ]
  in case hits of
       [] -> b1 { bPos = bPos b1 .+^ d, bVel = v }
       _  -> let (s, n, vo) = minimumOn (\(x, _, _) -> x) hits
                 p  = bPos b1 .+^ (max 0 (s - 1e-9) *^ d)
             in b1 { bPos = p, bVel = vo ^+^ bounce n (v ^-^ vo) }
  where
    slowDown :: Vector2 Double -> Vector2 Double
    slowDown v = let sp = norm v
                     sp' = max 0 (sp - ballFriction * dt)
                 in if sp <= 0 then zeroVector else (sp' / sp) *^ v
    pushOut b r = case circleCirclePenetration (bPos b) ballRadius (rPos r) robotRadius of
      Nothing       -> b
      Just (depth, n) ->
        let vr  = robotVelocity r
            rel = bVel b ^-^ vr
            v'  = if rel `dot` n < 0 then vr ^+^ bounce n rel else bVel b
        in b { bPos = bPos b .+^ ((depth + 1e-9) *^ n), bVel = v' }
    bounce :: Vector2 Double -> Vector2 Double -> Vector2 Double
    bounce n rel = let rn = (rel `dot` n) *^ n
                   in (rel ^-^ rn) ^-^ (ballRestitution *^ rn)

-- Equal-mass elastic collisions between overlapping, approaching balls.
resolvePairs :: [Ball] -> [Ball]
resolvePairs bs0 = foldl resolve bs0 [ (i, j) | i <- [0 .. n - 1], j <- [i + 1 .. n - 1] ]
  where
    n = length bs0
    resolve bs (i, j) =
      let bi = bs !! i
          bj = bs !! j
      in case circleCirclePenetration (bPos bi) ballRadius (bPos bj) ballRadius of
           Nothing -> bs
           Just (depth, nrm) ->
             let relN = (bVel bi ^-^ bVel bj) `dot` nrm
                 half = (depth / 2 + 1e-9) *^ nrm
                 (vi, vj) | relN < 0  = (bVel bi ^-^ (relN *^ nrm), bVel bj ^+^ (relN *^ nrm))
                          | otherwise = (bVel bi, bVel bj)
                 bi' = Ball (bPos bi .+^ half) vi
                 bj' = Ball (bPos bj .-^ half) vj
             in [ if k == i then bi' else if k == j then bj' else b | (k, b) <- zip [0 ..] bs ]

minimumOn :: Ord k => (a -> k) -> [a] -> a
minimumOn f = foldr1 (\x y -> if f x <= f y then x else y)
