{-# LANGUAGE BangPatterns     #-}
{-# LANGUAGE PatternSynonyms #-}
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
-- = Indexing
--
-- Nothing here compares every robot with every other: the arena's boxes
-- are indexed once on a grid ("AFrobRobotSim.SpatialIndex"), and each step
-- indexes the robots' (and balls') centres. A robot's sweep is tested only
-- against the boxes and robots that the grid finds near its path, a ball's
-- only against what is near its own; the results are exactly those of
-- testing everything (the grid query is a superset of what can touch, and
-- every rule that depends on order, such as which of two equally early
-- contacts counts, is applied in the original order).
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
    Arena (Arena, arenaBoxes)
  , arenaIndex
  , arenaOf
  , pointsOver
  , Robot (..)
  , mkRobot
  , withHeading
  , Ball (..)
  , robotVelocity
    -- * Stepping
  , stepRobots
  , stepRobotsNear
  , stepBalls
    -- * Parameters
  , ballFriction
  , ballRestitution
  , batteryStatusOf
  , wheelCommand
  ) where

import           Control.Monad.ST        (ST, runST)
import           Data.STRef              (newSTRef, readSTRef, writeSTRef)
import           GHC.Arr                 (Array, listArray, newSTArray, unsafeAt,
                                          unsafeReadSTArray, unsafeWriteSTArray)

import           AFRP              (DTime)
import           AFRP.Geometry
import           AFrob.Angle             (normalizeHeading)
import           AFrob.Dimensions
import           AFrob.RobotIO           (BatteryStatus (..))
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Clearance
import           AFrobRobotSim.Robot     (DriveCommand (..))
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World

-- | A simbot's physical state.
data Robot = Robot
  { rKind    :: !RobotKind
  , rId      :: !RobotId
  , rPos     :: !Position2
  , rHeading :: !Heading
  , rSpeed   :: !Speed      -- ^ actual translational speed (signed)
  , rStuck   :: !Bool
  , rCharge  :: !Double     -- ^ battery charge, 1 = full
  , rCos     :: {-# UNPACK #-} !Double  -- ^ @cos rHeading@, kept with the heading
  , rSin     :: {-# UNPACK #-} !Double  -- ^ @sin rHeading@, kept with the heading
  } deriving (Eq, Show)

-- | A robot of the given kind and id at a position and (normalised)
-- heading, with its speed, stuckness and charge; 'rCos' and 'rSin' are
-- computed from the heading. Build robots with this (or 'withHeading'), so
-- that the two always agree: the physics and the sensors read the
-- heading's unit vector from them instead of calling @cos@ and @sin@ again
-- at every step.
mkRobot :: RobotKind -> RobotId -> Position2 -> Heading -> Speed -> Bool -> Double -> Robot
mkRobot k i p h v stuck c = Robot k i p h v stuck c (cos h) (sin h)

-- | The robot turned to a new (normalised) heading, 'rCos' and 'rSin'
-- with it.
withHeading :: Heading -> Robot -> Robot
withHeading h r = r { rHeading = h, rCos = cos h, rSin = sin h }

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
robotVelocity r = Vector2 (rSpeed r * rCos r) (rSpeed r * rSin r)
  -- vector2Polar (rSpeed r) (rHeading r), with the cached cos and sin

-- | The commanded (left, right) wheel speeds of a command, each clamped to
-- the given maximum; non-finite values count as 0.
wheelCommand :: Length -> Speed -> DriveCommand -> (Velocity, Velocity)
wheelCommand l wsMax cmd = case cmd of
  DriveBrake      -> (0, 0)
  DriveWheels a b -> let !vl = clampW a
                         !vr = clampW b
                     in (vl, vr)
  DriveTR v w     -> let !vl = clampW (v - w * l / 2)
                         !vr = clampW (v + w * l / 2)
                     in (vl, vr)
  where
    clampW x | not (finite x) = 0
             | otherwise      = max (-wsMax) (min wsMax x)

-- | Move every robot by one step, in order, each against the obstacles and
-- the other robots' current positions.
stepRobots :: DTime -> Arena -> [(Robot, DriveCommand)] -> [Robot]
stepRobots dt arena cmds = stepRobotsNear (robotIndex arena (map fst cmds)) dt arena cmds

-- | 'stepRobots' given the robots' centres on a grid over the arena, as
-- 'pointsOver' indexes them (for a caller that has indexed them already,
-- such as the sensors of the same step): the same result.
stepRobotsNear :: PointIndex -> DTime -> Arena -> [(Robot, DriveCommand)] -> [Robot]
stepRobotsNear near dt arena cmds = runST $ do
  -- the current centres: the old ones, replaced as the robots move
  xs <- newDblArr (max 1 n)
  ys <- newDblArr (max 1 n)
  let start !_ []                                 = pure ()
      start !i ((Robot { rPos = Point2 x y }, _) : rest) = writeD xs i x >> writeD ys i y >> start (i + 1) rest
  start 0 cmds
  let go !_ !_ [] = pure []
      go !i !drift ((r, c) : rest) = do
        let mv = robotMotion dt r c
        contact <- firstContactST arena near xs ys i drift (rPos r) (mvDisp mv)
        let !r' = finishMove mv r contact
            Point2 x1 y1 = rPos r'
            !moved = norm (rPos r' .-. rPos r)
        writeD xs i x1
        writeD ys i y1
        rs <- go (i + 1) (max drift moved) rest
        pure (r' : rs)
  go (0 :: Int) 0 cmds
  where
    n = length cmds

-- The centres of robots (or of anything) on a grid over the arena.
robotIndex :: Arena -> [Robot] -> PointIndex
robotIndex arena rs = pointsOver arena [ (x, y) | Robot { rPos = Point2 x y } <- rs ]

-- | The motion a robot attempts in one step, before collisions.
data Motion = Motion
  { mvV1     :: !Double      -- speed at the end of the step, unobstructed
  , mvTh1    :: !Double      -- heading at the end of the step
  , mvCos1   :: !Double      -- cos mvTh1
  , mvSin1   :: !Double      -- sin mvTh1
  , mvDisp   :: !(Vector2 Double)
  , mvCharge :: !Double      -- battery charge at the end of the step
  }

robotMotion :: DTime -> Robot -> DriveCommand -> Motion
robotMotion dt r cmd =
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
      -- cos th0 and sin th0 are the robot's cached ones: the same numbers
      c0      = rCos r
      s0      = rSin r
      straight = abs (w * dt) < 1e-9
      -- a step with no turn keeps the heading, and its cos and sin (-0 + 0
      -- is 0, whose sine is not that of -0, hence 'identical')
      unturned = identical th1 th0
      !c1     = if unturned then c0 else cos th1
      !s1     = if unturned then s0 else sin th1
      vMean   = (v0 + v1) / 2
      disp    | straight  = Vector2 (vMean * dt * c0) (vMean * dt * s0)
                            -- vector2Polar (vMean * dt) th0
              | otherwise = vector2 (vMean / w * (s1 - s0)) (vMean / w * (c0 - c1))
      effort  = (abs (v1 - w * l / 2) + abs (v1 + w * l / 2)) / (2 * kindWSMax k)
      charge1 = max 0 (rCharge r - dt * (0.0005 + 0.003 * effort))
  in Motion v1 th1 c1 s1 disp charge1

-- The robot after its move, given the fraction of the move at which it
-- first touches something (if it does).
finishMove :: Motion -> Robot -> Maybe Double -> Robot
finishMove mv r contact =
  let p0   = rPos r
      disp = mvDisp mv
      (p1, v1', hit) = case contact of
        Nothing -> (p0 .+^ disp, mvV1 mv, False)
        Just s  ->
          -- Stop just short of the contact point, never behind the start.
          let len = norm disp
              s'  = max 0 (s - 1e-9 / max len 1e-300)
          in (p0 .+^ (s' *^ disp), 0, True)
      moved = p1 /= p0
      th1  = mvTh1 mv
      h1   = normalizeHeading th1
      -- The new heading's cos and sin are those of the motion when the
      -- normalisation left it as it was, and computed again when it
      -- wrapped around.
      same = identical h1 th1
  in r { rPos     = p1
       , rHeading = h1
       , rSpeed   = v1'
       , rStuck   = hit || (rStuck r && not moved)
       , rCharge  = mvCharge mv
       , rCos     = if same then mvCos1 mv else cos h1
       , rSin     = if same then mvSin1 mv else sin h1
       }

-- Two numbers that are the same number, zeros of the same sign included
-- (so that their sines are the same bits; NaN is never identical): a
-- cheaper test than comparing their bits, which is a foreign call.
identical :: Double -> Double -> Bool
identical a b = a == b && (a /= 0 || recip a == recip b)
{-# INLINE identical #-}

-- Some margin around every query rectangle, for rounding.
slack :: Double
slack = 1e-3

-- The fraction of the move at which the robot @i@ first touches something:
-- the earliest contact over every box and every other robot (at its
-- current centre), as 'sweepCircleBox' and 'sweepCircleCircle' have it.
-- Only the boxes and robots the grids find near the path are tested: a
-- box can only be touched if it meets the path's bounding box widened by
-- the radius, a robot if its centre is within twice the radius of the
-- path, and a robot's current centre is at most @drift@ from the centre it
-- was indexed with (the furthest any robot has moved this step).
firstContactST :: Arena -> PointIndex -> MDblArr s -> MDblArr s -> Int -> Double
               -> Position2 -> Vector2 Double -> ST s (Maybe Double)
firstContactST arena near xs ys i drift p d@(Vector2 dx dy)
  | d == zeroVector = pure Nothing
  | otherwise = do
      let Point2 px py = p
          qx = px + dx
          qy = py + dy
          rb = robotRadius + slack
          -- No box is within reach when the clearance at the start exceeds
          -- the move and the radius (with room for rounding): testing the
          -- boxes would find no contact.
          clear = clearanceAt (arenaClearance arena) px py - rb - slack
          -- the earliest contact so far (contacts are fractions in [0, 1];
          -- infinity for none)
          boxHit
            | clear > 0 && clear * clear > dx * dx + dy * dy = 1 / 0
            | otherwise =
                foldBoxesIn (arenaIndex arena) (min px qx - rb) (min py qy - rb)
                                               (max px qx + rb) (max py qy + rb)
                  (\acc _ b -> boxContact px py dx dy b acc) (1 / 0)
          rr = 2 * robotRadius + drift + slack
      hit <- foldPointsInM near (min px qx - rr) (min py qy - rr) (max px qx + rr) (max py qy + rr)
               (\acc j -> if j == i then pure acc else do
                   ox <- readD xs j
                   oy <- readD ys j
                   pure (robotContact px py dx dy ox oy acc)) boxHit
      pure (if hit == 1 / 0 then Nothing else Just hit)

-- The earlier of @acc@ and the contact of a robot at @(px, py)@ moving by
-- @(dx, dy)@ with a box (as 'sweepCircleBox' has it), and with another
-- robot at @(ox, oy)@ ('sweepCircleCircle'). Functions of their own, not
-- inlined into the folds that call them: inlined, GHC floated their
-- tests on the move out of the fold's callback as thunks, allocated and
-- evaluated at every query.
boxContact :: Double -> Double -> Double -> Double -> Box -> Double -> Double
boxContact px py dx dy b acc = case sweepCircleBox (Point2 px py) robotRadius (Vector2 dx dy) b of
  Just (s, _) -> min s acc
  Nothing     -> acc
{-# NOINLINE boxContact #-}

robotContact :: Double -> Double -> Double -> Double -> Double -> Double -> Double -> Double
robotContact px py dx dy ox oy acc =
  case sweepCircleCircle (Point2 px py) robotRadius (Vector2 dx dy) (Point2 ox oy) robotRadius of
    Just (s, _) -> min s acc
    Nothing     -> acc
{-# NOINLINE robotContact #-}

foldST :: (b -> a -> ST s b) -> b -> [a] -> ST s b
foldST _ z []       = pure z
foldST f z (x : xs) = do
  !z' <- f z x
  foldST f z' xs

-- | Move every ball by one step: friction, bounces off obstacles and
-- robots (at their new positions, with their velocities), then elastic
-- collisions between balls.
stepBalls :: DTime -> Arena -> [Robot] -> [Ball] -> [Ball]
stepBalls _ _ _ [] = []
stepBalls dt arena robots balls =
  resolvePairs arena (map (stepBall dt arena robotArr near) balls)
  where
    robotArr = listArray (0, length robots - 1) robots
    near     = robotIndex arena robots

stepBall :: DTime -> Arena -> Array Int Robot -> PointIndex -> Ball -> Ball
stepBall dt arena robots near b0 =
  let -- a robot that drove into the ball kicks it
      b1 = pushOuts b0 (-1)
      v  = slowDown (bVel b1)
      d@(Vector2 dx dy) = (dt *^ v)
      Point2 px py = bPos b1
      qx = px + dx
      qy = py + dy
      nBoxes = boxIndexCount (arenaIndex arena)
      -- the earliest contact; on a tie the first in the order boxes (as
      -- listed), then robots (as listed), as a scan of everything would
      -- find it
      rb = ballRadius + slack
      boxHit = foldBoxesIn (arenaIndex arena) (min px qx - rb) (min py qy - rb) (max px qx + rb) (max py qy + rb)
        (\acc k bx -> case sweepCircleBox (bPos b1) ballRadius d bx of
            Just (s, n) -> better (Hit s k n zeroVector) acc
            Nothing     -> acc) NoHit
      rr = ballRadius + robotRadius + slack
      hit = foldPointsIn near (min px qx - rr) (min py qy - rr) (max px qx + rr) (max py qy + rr)
        (\acc j -> let r = unsafeAt robots j
                   in case sweepCircleCircle (bPos b1) ballRadius d (rPos r) robotRadius of
                        Just (s, n) -> better (Hit s (nBoxes + j) n (robotVelocity r)) acc
                        Nothing     -> acc) boxHit
  in case hit of
       NoHit -> b1 { bPos = bPos b1 .+^ d, bVel = v }
       Hit s _ n vo ->
         let p  = bPos b1 .+^ (max 0 (s - 1e-9) *^ d)
         in b1 { bPos = p, bVel = vo ^+^ bounce n (v ^-^ vo) }
  where
    slowDown :: Vector2 Double -> Vector2 Double
    slowDown v = let sp = norm v
                     sp' = max 0 (sp - ballFriction * dt)
                 in if sp <= 0 then zeroVector else (sp' / sp) *^ v
    -- The robots push the ball out in order: the next robot (after the
    -- last one that pushed) that overlaps the ball where it now is.
    pushOuts b lastJ =
      let Point2 px py = bPos b
          rr = ballRadius + robotRadius + slack
          next = foldPointsIn near (px - rr) (py - rr) (px + rr) (py + rr)
                   (\acc j -> if j > lastJ && j < acc
                                 && overlaps (circleCirclePenetration (bPos b) ballRadius (rPos (unsafeAt robots j)) robotRadius)
                              then j else acc) maxBound
      in if next == maxBound then b else pushOuts (pushOut b (unsafeAt robots next)) next
    overlaps = maybe False (const True)
    pushOut b r = case circleCirclePenetration (bPos b) ballRadius (rPos r) robotRadius of
      Nothing       -> b
      Just (depth, n) ->
        let vr  = robotVelocity r
            rel = bVel b ^-^ vr
            v'  = if rel `dot` n < 0 then vr ^+^ bounce n rel else bVel b
        in b { bPos = pushedTo b ((depth + 1e-9) *^ n), bVel = v' }
    -- The push out of a robot is swept like any move and stops at a wall
    -- or block: a ball squeezed between a robot and a wall stays pinned
    -- there, overlapping the robot, and never passes through the wall.
    pushedTo b push =
      let Point2 px py = bPos b
          Vector2 ux uy = push
          rb = ballRadius + slack
          s = foldBoxesIn (arenaIndex arena) (min px (px + ux) - rb) (min py (py + uy) - rb)
                          (max px (px + ux) + rb) (max py (py + uy) + rb)
                (\acc _ bx -> case sweepCircleBox (bPos b) ballRadius push bx of
                    Just (s', _) -> min acc s'
                    Nothing      -> acc) 1
      in if s >= 1 then bPos b .+^ push else bPos b .+^ (max 0 (s - 1e-9) *^ push)
    bounce :: Vector2 Double -> Vector2 Double -> Vector2 Double
    bounce n rel = let rn = (rel `dot` n) *^ n
                   in (rel ^-^ rn) ^-^ (ballRestitution *^ rn)

-- A candidate contact of a ball: fraction, order (boxes first, then
-- robots), normal, velocity of what it hits.
data Hit = NoHit | Hit !Double !Int !(Vector2 Double) !(Vector2 Double)

better :: Hit -> Hit -> Hit
better h NoHit = h
better NoHit h = h
better h1@(Hit s1 k1 _ _) h2@(Hit s2 k2 _ _)
  | s1 < s2 || (s1 == s2 && k1 < k2) = h1
  | s2 < s1 || (s1 == s2 && k2 < k1) = h2
  | otherwise                        = h1   -- the same box, seen from two cells

-- Equal-mass elastic collisions between overlapping, approaching balls,
-- pair by pair in the order (0, 1), (0, 2), ..., (1, 2), ...: for each
-- ball, the next ball after the last one it met that overlaps it where
-- both now are. Candidates come from a grid of the balls' centres before
-- this, widened by the furthest any ball has been moved since.
resolvePairs :: Arena -> [Ball] -> [Ball]
resolvePairs arena bs0 = runST $ do
  arr <- newSTArray (0, n - 1) (Ball origin zeroVector)
  mapM_ (\(k, b) -> unsafeWriteSTArray arr k b) (zip [0 ..] bs0)
  drift <- newSTRef 0
  let forBall !i
        | i >= n = pure ()
        | otherwise = pairs i i >> forBall (i + 1)
      pairs !i !lastJ = do
        bi <- unsafeReadSTArray arr i
        d0 <- readSTRef drift
        let Point2 px py = bPos bi
            rr = 2 * ballRadius + d0 + slack
            cands = foldPointsIn grid (px - rr) (py - rr) (px + rr) (py + rr)
                      (\acc j -> if j > lastJ then j : acc else acc) []
        next <- foldST (\acc j -> if j >= acc then pure acc else do
                          bj <- unsafeReadSTArray arr j
                          pure (case circleCirclePenetration (bPos bi) ballRadius (bPos bj) ballRadius of
                                  Just _  -> j
                                  Nothing -> acc)) maxBound cands
        if next == maxBound then pure () else do
          bj <- unsafeReadSTArray arr next
          case circleCirclePenetration (bPos bi) ballRadius (bPos bj) ballRadius of
            Nothing -> pure ()
            Just (depth, nrm) -> do
              let relN = (bVel bi ^-^ bVel bj) `dot` nrm
                  half = (depth / 2 + 1e-9) *^ nrm
                  (vi, vj) | relN < 0  = (bVel bi ^-^ (relN *^ nrm), bVel bj ^+^ (relN *^ nrm))
                           | otherwise = (bVel bi, bVel bj)
                  !bi' = Ball (bPos bi .+^ half) vi
                  !bj' = Ball (bPos bj .-^ half) vj
              unsafeWriteSTArray arr i bi'
              unsafeWriteSTArray arr next bj'
              writeSTRef drift (d0 + norm half)
          pairs i next
  forBall 0
  mapM (unsafeReadSTArray arr) [0 .. n - 1]
  where
    n    = length bs0
    grid = pointsOver arena [ (x, y) | Ball (Point2 x y) _ <- bs0 ]
