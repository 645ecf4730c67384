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
-- the boxes and robots near its 3.25 m segment, the tracker only against
-- what is within range of the robot. The readings are exactly those of
-- testing everything.
module AFrobRobotSim.Sensors
  ( senseRobot
  , rangeReading
  , rayDirection
  , rangeFinderMax
  , trackerRange
  , SenseContext (SenseContext, scArena, scRobots, scBalls)
  , scRobotIndex
  ) where

import           GHC.Arr                (Array, listArray, unsafeAt)

import           AFRP.Geometry
import           AFrob.Angle            (normalizeAngle)
import           AFrob.Dimensions
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

-- | The robots' centres on a grid over the arena (as
-- 'AFrobRobotSim.Physics.pointsOver' indexes them), built when first needed.
scRobotIndex :: SenseContext -> PointIndex
scRobotIndex (MkSenseContext _ _ _ ix) = ixRobotGrid ix

indexes :: Arena -> [Robot] -> [Ball] -> Indexes
indexes arena rs bs = Indexes
  { ixRobots    = listArray (0, nr - 1) rs
  , ixNRobots   = nr
  , ixRobotGrid = pointsOver arena [ (x, y) | Robot { rPos = Point2 x y } <- rs ]
  , ixBalls     = listArray (0, length bs - 1) bs
  , ixBallGrid  = pointsOver arena [ (x, y) | Ball (Point2 x y) _ <- bs ]
  }
  where nr = length rs

-- Some margin around every query rectangle, for rounding.
slack :: Double
slack = 1e-3

-- | The input of one robot (by its index in the context's robot list),
-- given its odometry reading and the key pressed now.
senseRobot :: SenseContext -> Int -> (Position2, Heading) -> Maybe Char -> SimbotInput
senseRobot (MkSenseContext arena _ _ ix) i (odoPos, odoHead) key = SimbotInput
  { siBattery  = batteryStatusOf (rCharge me)
  , siStuck    = rStuck me
  , siPosition = odoPos
  , siHeading  = odoHead
  , siRange    = range
  , siMaxRange = rangeFinderMax
  , siRobots   = [ (kindType (rKind o), rId o, angleTo ox oy, d)
                 | Near d j <- nearest (ixRobotGrid ix) (\j -> j /= i)
                 , let o  = robotAt j
                       ox = pointX (ixRobotGrid ix) j
                       oy = pointY (ixRobotGrid ix) j ]
  , siBalls    = [ (angleTo bx by, d)
                 | Near d j <- nearest (ixBallGrid ix) (const True)
                 , let bx = pointX (ixBallGrid ix) j
                       by = pointY (ixBallGrid ix) j ]
  , siKey      = key
  }
  where
    me | i >= 0 && i < ixNRobots ix = robotAt i
       | otherwise                  = error ("AFrobRobotSim.Sensors.senseRobot: no robot number " ++ show i)
    robotAt j = unsafeAt (ixRobots ix) j
    p@(Point2 px py) = rPos me
    tr = trackerRange + slack
    -- The points of an index within the tracker's range (centre to
    -- centre, the distance as 'vector2RhoTheta' has it), nearest first,
    -- in index order among equally near ones (as a stable sort of all of
    -- them by distance would have them).
    nearest grid keep = sortNear
      (foldPointsIn grid (px - tr) (py - tr) (px + tr) (py + tr)
         (\acc j -> if keep j
                      then let qx = pointX grid j
                               qy = pointY grid j
                               (d, _) = vector2RhoTheta (Point2 qx qy .-. p)
                           in if d <= trackerRange then Near d j : acc else acc
                      else acc) [])
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
    rangeFront = rangeAt 0
    rangeLeft  = rangeAt (pi / 2)
    rangeRight = rangeAt (-pi / 2)
    rangeBack  = rangeAt pi
    -- a ray: the nearest box, then the nearest other robot near the
    -- ray's segment
    rangeAt a
      | not (finite a) = rangeFinderMax
      | otherwise =
          let ray@(Ray _ _ ux uy) = rayFrom p (turnedBy (rHeading me) headingDir a)
              -- the nearest box first; then only a robot whose centre is
              -- within a radius of the ray up to that box can be nearer
              boxT = rayToBoxes arena ray
              ex = px + boxT * ux
              ey = py + boxT * uy
              rr = radius + slack
          in reading (foldPointsIn (ixRobotGrid ix) (min px ex - rr) (min py ey - rr) (max px ex + rr) (max py ey + rr)
                        (\m j -> if j == i then m
                                 else rayToRobot ray m (Point2 (pointX (ixRobotGrid ix) j) (pointY (ixRobotGrid ix) j)))
                        boxT)
    radius = simbotDiameter / 2
    -- the heading's unit vector, computed once for all of this robot's rays
    headingDir = headingVector (rHeading me)

-- A point of an index near a robot: its distance and its index.
data Near = Near !Double !Int

-- Sort by distance, then index (an insertion sort: the lists are short).
sortNear :: [Near] -> [Near]
sortNear = foldr insert []
  where
    insert x [] = [x]
    insert x@(Near d j) (y@(Near e k) : ys)
      | d < e || (d == e && j < k) = x : y : ys
      | otherwise                  = y : insert x ys

-- | The range finder's reading for a robot at a position and heading,
-- among the given other robots' centres, in the direction @a@ relative to
-- the heading (see the module documentation). A non-finite angle reads
-- 'rangeFinderMax'.
rangeReading :: Arena -> [Position2] -> Position2 -> Heading -> Angle -> Distance
rangeReading arena others p heading a
  | not (finite a) = rangeFinderMax
  | otherwise      = let ray = rayFrom p (rayDirection heading a)
                     in reading (foldl (rayToRobot ray) (rayToBoxes arena ray) others)

-- A ray: its origin and its direction (a unit vector).
data Ray = Ray !Double !Double !Double !Double

rayFrom :: Position2 -> Vector2 Double -> Ray
rayFrom (Point2 px py) (Vector2 ux uy) = Ray px py ux uy
{-# INLINE rayFrom #-}

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
  Just QFront -> hv
  Just QLeft  -> let Vector2 c s = hv in Vector2 (negate s) c
  Just QRight -> let Vector2 c s = hv in Vector2 s (negate c)
  Just QBack  -> let Vector2 c s = hv in Vector2 (negate c) (negate s)
  Nothing     -> vector2Polar 1 (h + a)
{-# INLINE turnedBy #-}

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

rayLength :: Double
rayLength = rangeFinderMax + simbotDiameter / 2

-- The nearest box the ray hits within its length (the range plus a
-- robot's radius: nothing further away can be the nearest hit), or that
-- length if none is nearer.
rayToBoxes :: Arena -> Ray -> Double
rayToBoxes arena (Ray px py ux uy) = rayCastBoxes (arenaIndex arena) px py ux uy rayLength

-- The nearer of a distance and the robot (centre) the ray may hit.
rayToRobot :: Ray -> Double -> Position2 -> Double
rayToRobot (Ray px py ux uy) m q =
  case rayCircle (Point2 px py) (Vector2 ux uy) q (simbotDiameter / 2) of
    Just t  -> min t m
    Nothing -> m
{-# INLINE rayToRobot #-}

-- The reading for the nearest hit (centre to obstacle): from the robot's
-- edge, within the range.
reading :: Double -> Distance
reading nearest = max 0 (min rangeFinderMax (nearest - simbotDiameter / 2))
