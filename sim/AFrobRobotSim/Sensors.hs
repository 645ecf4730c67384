{-# LANGUAGE BangPatterns    #-}
{-# LANGUAGE PatternSynonyms #-}
-- |
-- Module      : AFrobRobotSim.Sensors
-- Description : What a simbot senses: range finder, animate object
--               tracker, bumper, battery, odometry, keyboard.
--
-- = Range finder
--
-- @rfRange i a@ casts a ray from the robot's centre in the direction of its
-- heading plus @a@ and returns the distance from the robot's /edge/ (its
-- radius, 0.25 m, subtracted) to the first wall, block, boundary or other
-- robot it meets, exactly, against the true shapes. Nothing further than
-- 'rangeFinderMax' (3 m) is seen: the reading is then 'rangeFinderMax'.
-- The ray's direction is the heading's unit vector turned by @a@, exactly
-- for the quarter turns of 'AFrob.rfFront', 'AFrob.rfLeft', 'AFrob.rfBack'
-- and 'AFrob.rfRight' (see 'rayDirection'). Rays are cast only when a
-- controller asks for them, and those four at most once per sample.
--
-- = Animate object tracker
--
-- Every other robot and every ball whose centre is within 'trackerRange'
-- (4 m) of the robot's centre, with its angle relative to the robot's
-- heading (normalised to [-pi, pi)) and its centre-to-centre distance,
-- nearest first (in template order among equally near ones).
--
-- = Indexing
--
-- A 'SenseContext' indexes the robots' and balls' centres on a grid
-- ("AFrobRobotSim.SpatialIndex") the first time a sensor needs it, and the
-- arena's boxes are indexed once, with the lists of boxes a ray from each
-- place can reach ("AFrobRobotSim.RayGrid"): a ray is tested only against
-- the boxes near its 3.25 m segment. The other robots within the
-- tracker's range of a robot (and a millimetre more) are gathered once
-- per sample, into unboxed arrays (index and squared distance), and
-- shared by its tracker and its rays (every robot a ray can hit is among
-- them). The tracker's lists are sorted in unboxed arrays (by distance, then
-- template order: a merge sort, no list or thunk per point), and the lists
-- are made as the controller reads them: with many robots in range, a
-- band of distances at a time, so that a controller that reads the nearest
-- few sorts only the nearest bands ("AFrobRobotSim.Nearby" gathers and
-- sorts them). The readings are exactly those of testing everything.
module AFrobRobotSim.Sensors
  ( senseRobot
  , senseRobotApart
  , rangeReading
  , rayDirection
  , rangeFinderMax
  , trackerRange
  , SenseContext (SenseContext, scArena, scRobots, scBalls)
  , scRobotIndex
  , senseReady
  ) where

import           GHC.Arr                (Array, listArray, unsafeAt)

import           AFRP.Geometry
import           AFrob.Angle            (normalizeAngle)
import           AFrob.Dimensions
import           AFrobRobotSim.Balls    (Ball (..), ballIndex)
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Nearby
import           AFrobRobotSim.Physics
import           AFrobRobotSim.RayCast  (rayCastBoxes)
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World

-- | The range finder's maximum range: 3 m (the original simulator's was
-- about 2 m).
rangeFinderMax :: Distance
rangeFinderMax = 3

-- | The tracker's range: 4 m, centre to centre.
trackerRange :: Distance
trackerRange = 4

-- | What every robot senses from at one sample: the arena, every robot and
-- every ball. @SenseContext arena robots balls@ builds one (and matches
-- one, as if it were a plain record).
data SenseContext = MkSenseContext Arena [Robot] [Ball] Indexes

-- The robots and balls as arrays and on grids, each computed when first
-- needed and shared by every robot's sensors.
data Indexes = Indexes
  { ixRobots    :: Array Int Robot
  , ixNRobots   :: Int
  , ixRobotGrid :: PointIndex
  , ixBalls     :: Array Int Ball
  , ixBallGrid  :: PointIndex
  }

pattern SenseContext :: Arena -> [Robot] -> [Ball] -> SenseContext
pattern SenseContext { scArena, scRobots, scBalls } <- MkSenseContext scArena scRobots scBalls _
  where SenseContext a rs bs = MkSenseContext a rs bs (indexes a rs bs)
{-# COMPLETE SenseContext #-}

-- | The robots' centres on a grid over the arena
-- ('AFrobRobotSim.Physics.robotIndex'), built when first needed.
scRobotIndex :: SenseContext -> PointIndex
scRobotIndex (MkSenseContext _ _ _ ix) = ixRobotGrid ix

-- | @()@, once every index of the context that 'senseRobot' shares between
-- robots is built (the robots' and balls' arrays and grids): for a caller
-- that senses for several robots in parallel, so that no two threads
-- build one.
senseReady :: SenseContext -> ()
senseReady (MkSenseContext _ _ _ ix) =
  ixRobots ix `seq` ixRobotGrid ix `seq` ixBalls ix `seq` ixBallGrid ix `seq` ()

indexes :: Arena -> [Robot] -> [Ball] -> Indexes
indexes arena rs bs = Indexes
  { ixRobots    = listArray (0, nr - 1) rs
  , ixNRobots   = nr
  , ixRobotGrid = robotIndex arena rs
  , ixBalls     = listArray (0, length bs - 1) bs
  , ixBallGrid  = ballIndex arena bs
  }
  where nr = length rs

-- | The input of one robot (by its index in the context's robot list),
-- given its odometry reading and the key pressed now.
senseRobot :: SenseContext -> Int -> (Position2, Heading) -> Maybe Char -> SimbotInput
senseRobot ctx i odo key = fst (senseRobotApart ctx i odo key)

-- | 'senseRobot', and a lower bound on the distance from the robot's
-- centre to every other robot's centre (as the context has them): the
-- distance to the nearest one within the tracker's range (a millimetre
-- more: 4.001 m), or that range if none is that near; 0 when more than 16
-- are that near (a crowd, where a bound is seldom of use). Both made
-- from one gathering of the robots near it, done when the bound, the
-- tracker or a ray is first read
-- ('AFrobRobotSim.Physics.planMoveApart' takes the bound); the rays and
-- the tracker's lists are computed when read.
senseRobotApart :: SenseContext -> Int -> (Position2, Heading) -> Maybe Char -> (SimbotInput, Double)
senseRobotApart (MkSenseContext arena _ _ ix) i (odoPos, odoHead) key = (input, nearestOf others)
  where
    -- (the input record, the robot and its position are made at the call,
    -- not as thunks: a controller's step reads its input, so the thunks
    -- only cost; one that reads nothing of it pays a little more)
    !input = SimbotInput
      { siBattery  = batteryStatusOf (rCharge me)
      , siStuck    = rStuck me
      , siPosition = odoPos
      , siHeading  = odoHead
      , siRange    = range
      , siMaxRange = rangeFinderMax
      , siRobots   = inRangeSorted trackerRange tracked others
      , siBalls    = inRangeSorted trackerRange (\d _ bx by -> (angleTo bx by, d))
                                   (gatherNear gatherRange (ixBallGrid ix) (-1) px py)
      , siKey      = key
      }
    !me | i >= 0 && i < ixNRobots ix = robotAt i
        | otherwise                  = error ("AFrobRobotSim.Sensors.senseRobot: no robot number " ++ show i)
    robotAt j = unsafeAt (ixRobots ix) j
    !p@(Point2 px py) = rPos me
    -- The other robots near this one, gathered once per sample and shared
    -- by the tracker and every ray: all within 'gatherRange', which covers
    -- the tracker's range and every robot a ray can hit.
    others = gatherNear gatherRange (ixRobotGrid ix) i px py
    -- Those a quarter-turn ray can hit: a ray meets a disc only if the
    -- disc's centre is within a radius of the ray's line (the
    -- discriminant is negative otherwise, by far more than rounding), and
    -- the four quarter-turn rays lie on the heading's axis and its
    -- perpendicular; and only within the ray's reach (the cast ignores
    -- the others anyway). Usually none of the others is that near either
    -- line, and those four rays then test no robot at all.
    crossing = let Vector2 c s = headingDir
               in selectNear (\qx qy d2 ->
                    let x = qx - px
                        y = qy - py
                    in d2 <= rayReach * rayReach
                       && (abs (y * c - x * s) <= robotRadius + querySlack
                           || abs (x * c + y * s) <= robotRadius + querySlack))
                  others
    -- a robot the tracker sees: its type and number taken out as the
    -- element is made, the bearing computed when it is read
    tracked d j ox oy = let o    = robotAt j
                            !ty  = kindType (rKind o)
                            !rid = rId o
                        in (ty, rid, angleTo ox oy, d)
    -- the bearing of a point relative to the heading
    angleTo qx qy = let (_, th) = vector2RhoTheta (Point2 qx qy .-. p)
                    in normalizeAngle (th - rHeading me)
    -- The four quarter-turn rays (rfFront, rfLeft, rfBack, rfRight) are
    -- cast at most once per sample however often they are read: a
    -- controller typically reads one in several places.
    range a = case quarterTurn a of
      Just QFront -> rangeFront
      Just QLeft  -> rangeLeft
      Just QRight -> rangeRight
      Just QBack  -> rangeBack
      Nothing     -> rangeAt a
    rangeFront = rangeQuarter QFront
    rangeLeft  = rangeQuarter QLeft
    rangeRight = rangeQuarter QRight
    rangeBack  = rangeQuarter QBack
    rangeQuarter q = let Vector2 ux uy = quarterDir q headingDir in cast crossing ux uy
    -- any other angle (as 'rayDirection' turns it)
    rangeAt a
      | not (finite a) = rangeFinderMax
      | otherwise      = let Vector2 ux uy = vector2Polar 1 (rHeading me + a)
                         in cast (allNear others) ux uy
    -- a ray: the nearest box, then any nearer robot among the given ones
    cast near ux uy =
      reading (foldNear (\m qx qy d2 -> if d2 > rayReach * rayReach then m
                                        else rayToRobot px py ux uy m qx qy)
                        (rayCastBoxes (arenaIndex arena) px py ux uy rayLength) others near)
    -- the heading's unit vector, for all of this robot's rays: the cos and
    -- sin the robot keeps with its heading, the numbers of 'headingVector'
    headingDir = Vector2 (rCos me) (rSin me)

-- | The range finder's reading for a robot at a position and heading,
-- among the given other robots' centres, in the direction @a@ relative to
-- the heading (see the module documentation). A non-finite angle reads
-- 'rangeFinderMax'.
rangeReading :: Arena -> [Position2] -> Position2 -> Heading -> Angle -> Distance
rangeReading arena others (Point2 px py) heading a
  | not (finite a) = rangeFinderMax
  | otherwise      = let Vector2 ux uy = rayDirection heading a
                     in reading (foldl (\m (Point2 qx qy) -> rayToRobot px py ux uy m qx qy)
                                       (rayCastBoxes (arenaIndex arena) px py ux uy rayLength) others)

-- | The direction (a unit vector) of the range finder's ray at angle @a@
-- for a robot with heading @h@: the heading's unit vector @(cos h, sin h)@
-- turned by @a@. A quarter turn (@a@ = 0, @pi \/ 2@, @-pi \/ 2@, @pi@ or
-- @-pi@, the angles of 'AFrob.rfFront', 'AFrob.rfLeft', 'AFrob.rfRight'
-- and 'AFrob.rfBack') turns it exactly, by swapping and negating its
-- components; any other angle gives @(cos (h + a), sin (h + a))@.
rayDirection :: Heading -> Angle -> Vector2 Double
rayDirection h = turnedBy h (headingVector h)
{-# INLINE rayDirection #-}

-- The unit vector of a heading.
headingVector :: Heading -> Vector2 Double
headingVector h = Vector2 (cos h) (sin h)
{-# INLINE headingVector #-}

-- A heading's unit vector turned by an angle (see 'rayDirection'): the
-- lazily shared heading vector is only needed for the quarter turns.
turnedBy :: Heading -> Vector2 Double -> Angle -> Vector2 Double
turnedBy h hv a = case quarterTurn a of
  Just q  -> quarterDir q hv
  Nothing -> vector2Polar 1 (h + a)
{-# INLINE turnedBy #-}

-- A heading's unit vector turned exactly by a quarter turn: its
-- components swapped and negated.
quarterDir :: QuarterTurn -> Vector2 Double -> Vector2 Double
quarterDir q hv@(Vector2 c s) = case q of
  QFront -> hv
  QLeft  -> Vector2 (negate s) c
  QRight -> Vector2 s (negate c)
  QBack  -> Vector2 (negate c) (negate s)
{-# INLINE quarterDir #-}

-- The range finder's quarter turns, relative to the heading.
data QuarterTurn = QFront | QLeft | QRight | QBack

-- The quarter turn an angle is exactly (0, pi/2, -pi/2, pi or -pi, as
-- 'AFrob.rfFront', 'AFrob.rfLeft', 'AFrob.rfRight' and 'AFrob.rfBack'
-- write them), if it is one.
quarterTurn :: Angle -> Maybe QuarterTurn
quarterTurn a
  | a == 0                    = Just QFront
  | a == pi / 2               = Just QLeft
  | a == -pi / 2              = Just QRight
  | a == pi || a == -pi       = Just QBack
  | otherwise                 = Nothing
{-# INLINE quarterTurn #-}

-- How far from the robot's centre the centre of a robot it hits can be:
-- the ray's length and a radius, and some slack.
rayReach :: Double
rayReach = rayLength + robotRadius + querySlack

rayLength :: Double
rayLength = rangeFinderMax + robotRadius

-- How far from a robot's centre the robots and balls gathered for its
-- tracker and its rays (one gather for both) can be: a little more than
-- the tracker's range, and in any case as far as a ray can reach a robot.
gatherRange :: Double
gatherRange = max (trackerRange + querySlack) rayReach

-- The nearer of a distance and the robot (centre) the ray from @(px, py)@
-- in the direction @(ux, uy)@ may hit.
rayToRobot :: Double -> Double -> Double -> Double -> Double -> Double -> Double -> Double
rayToRobot px py ux uy m qx qy =
  case rayCircle (Point2 px py) (Vector2 ux uy) (Point2 qx qy) robotRadius of
    Just t  -> min t m
    Nothing -> m
{-# INLINE rayToRobot #-}

-- The reading for the nearest hit (centre to obstacle): from the robot's
-- edge, within the range.
reading :: Double -> Distance
reading nearest = max 0 (min rangeFinderMax (nearest - robotRadius))
