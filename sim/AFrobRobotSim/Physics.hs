{-# LANGUAGE BangPatterns     #-}
{-# LANGUAGE PatternSynonyms #-}
-- |
-- Module      : AFrobRobotSim.Physics
-- Description : How simbots move: differential drive with translational
--               inertia, collisions, the battery.
--
-- = Simbots
--
-- A simbot's state is its position, heading and translational speed @v@.
-- Each step of @dt@ seconds, given its wheel command:
--
-- 1. The commanded wheel speeds @(vl, vr)@ (from 'DriveWheels', or
--    @(v - w l/2, v + w l/2)@ from 'DriveTR', or @(0, 0)@ for 'DriveBrake')
--    are each clamped to the maximum wheel speed (halved on a critical
--    battery). A non-finite command counts as 0 here, so that the physics
--    stays finite whoever calls it; the simulator never passes one on: a
--    controller that gives one has failed
--    ('AFrobRobotSim.Simulator.ControllerError').
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
--    again, that is, until its centre moves: turning on the spot does not
--    free it (a disc that turns keeps touching what it touches), driving
--    away from the contact does. Robots move one after the other, in template order, each
--    against the others' current positions, so no two ever overlap.
--
-- = Indexing
--
-- Nothing here compares every robot with every other: the arena's boxes
-- are indexed once on a grid ("AFrobRobotSim.SpatialIndex"), and each step
-- indexes the robots' centres. A robot's sweep is tested only against the
-- boxes and robots that the grid finds near its path; the results are
-- exactly those of testing everything (the grid query is a superset of what can touch, and
-- every rule that depends on order, such as which of two equally early
-- contacts counts, is applied in the original order).
--
-- A step is split in two ('stepRobotsNear' is the two in a row): each
-- robot's 'Plan' (its motion and its earliest contact with a box, which
-- depend on nothing but the robot, its command and the arena: pure, and
-- computed in parallel by "AFrobRobotSim.Simulator" on several cores),
-- then the moves in order against the other robots ('stepRobotsPlanned').
--
-- = Balls
--
-- Balls are moved after the robots, by "AFrobRobotSim.Balls".
--
-- = Battery
--
-- The charge starts at 1 and drains at @0.0005 + 0.003 * effort@ per
-- second, where @effort@ is the mean absolute wheel speed over the maximum
-- (0 at rest, 1 at full speed). The status is 'BSHigh' above 0.3, 'BSLow'
-- above 0.1, and 'BSCritical' below, where the maximum wheel speed halves.
-- At full effort a fresh battery is low after 200 s and critical after
-- about 257 s (a robot that accelerates from rest to full speed spends a
-- little less effort at first: about 202 s and 259 s).
module AFrobRobotSim.Physics
  ( -- * State
    Robot (..)
  , mkRobot
  , withHeading
  , robotVelocity
  , robotIndex
    -- * Stepping
  , stepRobots
  , stepRobotsNear
  , Plan
  , planMove
  , planMoveApart
  , stepRobotsPlanned
    -- * Parameters
  , robotRadius
  , querySlack
  , batteryStatusOf
  , wheelCommand
  ) where

import           Control.Monad.ST        (ST, runST)

import           AFRP              (DTime)
import           AFRP.Geometry
import           AFrob.Angle             (normalizeHeading)
import           AFrob.Dimensions
import           AFrob.RobotIO           (BatteryStatus (..))
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Clearance
import           AFrobRobotSim.FlatArray (MDblArr, newDblArr, readD, writeD)
import           AFrobRobotSim.Robot     (DriveCommand (..))
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World

-- | A simbot's physical state.
data Robot = Robot
  { rKind    :: !RobotKind
  , rId      :: !RobotId
  , rPos     :: {-# UNPACK #-} !Position2
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

-- | The radius of a simbot's disc (both kinds are the same size).
robotRadius :: Length
robotRadius = simbotDiameter / 2

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
-- the given maximum; non-finite values count as 0. For 'DriveTR', that is
-- a non-finite @v@ or @w@ (both wheels 0): the wheel speeds of finite ones
-- are clamped even where @v -/+ w l/2@ overflows to an infinity (it
-- counted as 0, so that @DriveTR 1.7e308 1.7e308@ drove one wheel at full
-- speed and stopped the other).
wheelCommand :: Length -> Speed -> DriveCommand -> (Velocity, Velocity)
wheelCommand l wsMax cmd = case cmd of
  DriveBrake      -> (0, 0)
  DriveWheels a b -> let !vl = clampW a
                         !vr = clampW b
                     in (vl, vr)
  DriveTR v w
    | finite v && finite w ->
                     let !vl = clampI (v - w * l / 2)
                         !vr = clampI (v + w * l / 2)
                     in (vl, vr)
    | otherwise   -> (0, 0)
  where
    clampW x | not (finite x) = 0
             | otherwise      = clampI x
    -- (an infinity, from finite numbers, is clamped like any number)
    clampI x = max (-wsMax) (min wsMax x)

-- | Move every robot by one step, in order, each against the obstacles and
-- the other robots' current positions.
stepRobots :: DTime -> Arena -> [(Robot, DriveCommand)] -> [Robot]
stepRobots dt arena cmds = stepRobotsNear (robotIndex arena (map fst cmds)) dt arena cmds

-- | 'stepRobots' given the robots' centres on a grid over the arena, as
-- 'pointsOver' indexes them (for a caller that has indexed them already,
-- such as the sensors of the same step): the same result.
stepRobotsNear :: PointIndex -> DTime -> Arena -> [(Robot, DriveCommand)] -> [Robot]
stepRobotsNear near dt arena cmds = stepRobotsPlanned near [ (r, planMove dt arena r c) | (r, c) <- cmds ]

-- | What a robot's move in one step is before the other robots are
-- considered: its motion, the fraction of it at which it first touches
-- a box (infinity for none), and a lower bound on the distance from its
-- centre to the other robots' centres before the step (0 if none is
-- known).
data Plan = Plan {-# UNPACK #-} !Motion {-# UNPACK #-} !Double {-# UNPACK #-} !Double

-- | The plan of a robot's move under a command, in an arena (evaluated to
-- weak head normal form, it is computed).
planMove :: DTime -> Arena -> Robot -> DriveCommand -> Plan
planMove dt arena = planMoveApart dt arena 0

-- | 'planMove', given a lower bound on the distance from the robot's
-- centre to every other robot's centre before the step (the one the
-- robot index given to 'stepRobotsPlanned' holds), kept in the plan:
-- 'stepRobotsPlanned' then moves a robot whose move cannot bring it
-- within touching distance of any other (the bound is more than twice the
-- radius plus its move, the furthest any robot before it has moved, and a
-- margin for rounding) without looking for the others. The same moves as
-- 'planMove''s, and as fast for a robot near others.
planMoveApart :: DTime -> Arena -> Double -> Robot -> DriveCommand -> Plan
planMoveApart dt arena apart r c =
  let mv = robotMotion dt r c
  in Plan mv (boxesFirstContact arena (rPos r) (mvDisp mv)) apart

-- | Move every robot by one step, in order, as planned, each against the
-- other robots' current positions ('stepRobotsNear' with the plans made),
-- given the 'robotIndex' of the robots before their move (the plans'
-- robots, in order). The plans are read in order, one at a time: a plan
-- is not needed before the robots before it have moved (the simulator's
-- parallel step computes later plans meanwhile). An error if there are
-- more plans than indexed robots.
stepRobotsPlanned :: PointIndex -> [(Robot, Plan)] -> [Robot]
stepRobotsPlanned near plans = runST $ do
  -- the current centres: the old ones (as indexed, the robots' positions),
  -- replaced as the robots move
  xs <- newDblArr (max 1 n)
  ys <- newDblArr (max 1 n)
  let start !i | i >= n    = pure ()
               | otherwise = writeD xs i (pointX near i) >> writeD ys i (pointY near i) >> start (i + 1)
  start 0
  let go !_ !_ [] = pure []
      go !i !drift ((r, Plan mv boxHit apart) : rest)
        | i >= n = error ("AFrobRobotSim.Physics.stepRobotsPlanned: more plans than the "
                          ++ show n ++ " robots indexed")
        | otherwise = do
          contact <- firstContactST near xs ys i drift apart (rPos r) (mvDisp mv) boxHit
          let !r' = finishMove mv r contact
              Point2 x1 y1 = rPos r'
              !moved = norm (rPos r' .-. rPos r)
          writeD xs i x1
          writeD ys i y1
          rs <- go (i + 1) (max drift moved) rest
          pure (r' : rs)
  go (0 :: Int) 0 plans
  where
    n = pointIndexCount near

-- | The robots' centres on a grid over the arena ('pointsOver'): point
-- @i@ of the index is the centre of the @i@-th robot of the list.
robotIndex :: Arena -> [Robot] -> PointIndex
robotIndex = pointsOverOn (\r -> let Point2 x _ = rPos r in x) (\r -> let Point2 _ y = rPos r in y)

-- | The motion a robot attempts in one step, before collisions.
data Motion = Motion
  { mvV1     :: !Double      -- speed at the end of the step, unobstructed
  , mvTh1    :: !Double      -- heading at the end of the step
  , mvCos1   :: !Double      -- cos mvTh1
  , mvSin1   :: !Double      -- sin mvTh1
  , mvDx     :: !Double      -- the displacement, unobstructed (see 'mvDisp')
  , mvDy     :: !Double
  , mvCharge :: !Double      -- battery charge at the end of the step
  }

-- The displacement a motion attempts. (Kept as two numbers in the record,
-- not a vector: a plan is then one flat record, which lives from a
-- robot's controller step to its move, across collections in a large
-- world.)
mvDisp :: Motion -> Vector2 Double
mvDisp mv = Vector2 (mvDx mv) (mvDy mv)
{-# INLINE mvDisp #-}

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
      Vector2 dx dy = disp
  in Motion v1 th1 c1 s1 dx dy charge1

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

-- | The margin, 1 mm, added around every rectangle in which the grids
-- are asked for what a move could touch, for rounding: a query never
-- misses a box or a disc that the exact test would find.
querySlack :: Double
querySlack = 1e-3

-- The fraction of a move from @p@ by @d@ at which the robot first touches
-- a box (infinity for none), as 'sweepCircleBox' has it: only the boxes
-- that meet the path's bounding box widened by the radius are tested, and
-- none when the clearance at the start exceeds the move and the radius.
boxesFirstContact :: Arena -> Position2 -> Vector2 Double -> Double
boxesFirstContact arena (Point2 px py) d@(Vector2 dx dy)
  | d == zeroVector = 1 / 0
  | clear > 0 && clear * clear > dx * dx + dy * dy = 1 / 0
  | otherwise =
      foldBoxesIn (arenaIndex arena) (min px qx - rb) (min py qy - rb)
                                     (max px qx + rb) (max py qy + rb)
        (\acc _ b -> boxContact px py dx dy b acc) (1 / 0)
  where
    qx = px + dx
    qy = py + dy
    rb = robotRadius + querySlack
    -- (with room for rounding)
    clear = clearanceAt (arenaClearance arena) px py - rb - querySlack

-- The fraction of the move at which the robot @i@ first touches something:
-- the earliest of its first contact with a box (given) and with every
-- other robot (at its current centre), as 'sweepCircleCircle' has it.
-- Only the robots the grid finds near the path are tested: a robot if its
-- centre is within twice the radius of the path, and a robot's current
-- centre is at most @drift@ from the centre it was indexed with (the
-- furthest any robot has moved this step). None is tested when the
-- robot's centre was at least @apart@ from every other's (its plan's
-- bound) and that is more than twice the radius, the move, the drift and
-- a margin: then no robot is near the path, and the grid would find none
-- that touches.
firstContactST :: PointIndex -> MDblArr s -> MDblArr s -> Int -> Double -> Double
               -> Position2 -> Vector2 Double -> Double -> ST s (Maybe Double)
firstContactST near xs ys i drift apart p d@(Vector2 dx dy) boxHit
  | d == zeroVector = pure Nothing
  | apart > 2 * robotRadius + norm d + drift + 2 * querySlack =
      pure (if boxHit == 1 / 0 then Nothing else Just boxHit)
  | otherwise = do
      let Point2 px py = p
          qx = px + dx
          qy = py + dy
          rr = 2 * robotRadius + drift + querySlack
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
