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
-- Rays are cast only when a controller asks for them.
--
-- = Animate object tracker
--
-- Every other robot and every ball whose centre is within 'trackerRange'
-- (4 m) of the robot's centre, with its angle relative to the robot's
-- heading (normalised to [-pi, pi)) and its centre-to-centre distance,
-- nearest first.
module AFrobRobotSim.Sensors
  ( senseRobot
  , rangeReading
  , rangeFinderMax
  , trackerRange
  , SenseContext (..)
  ) where

import           Data.List              (sortOn)

import           AFRP.Geometry
import           AFrob.Angle            (normalizeAngle)
import           AFrob.Dimensions
import           AFrobRobotSim.Physics
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.World

-- | The range finder's maximum range: 3 m (the original simulator's was
-- about 2 m).
rangeFinderMax :: Distance
rangeFinderMax = 3

-- | The tracker's range: 4 m, centre to centre.
trackerRange :: Distance
trackerRange = 4

-- | What every robot senses from at one sample.
data SenseContext = SenseContext
  { scArena  :: Arena
  , scRobots :: [Robot]
  , scBalls  :: [Ball]
  }

-- | The input of one robot (by its index in the context's robot list),
-- given its odometry reading and the key pressed now.
senseRobot :: SenseContext -> Int -> (Position2, Heading) -> Maybe Char -> SimbotInput
senseRobot ctx i (odoPos, odoHead) key = SimbotInput
  { siBattery  = batteryStatusOf (rCharge me)
  , siStuck    = rStuck me
  , siPosition = odoPos
  , siHeading  = odoHead
  , siRange    = rangeAt
  , siMaxRange = rangeFinderMax
  , siRobots   = [ (kindType (rKind o), rId o, a, d)
                 | (o, (a, d)) <- sortOn (snd . snd) [ (o, polar (rPos o)) | o <- others ]
                 , d <= trackerRange ]
  , siBalls    = sortOn snd [ (a, d) | b <- scBalls ctx, let (a, d) = polar (bPos b), d <= trackerRange ]
  , siKey      = key
  }
  where
    robots = scRobots ctx
    me     = robots !! i
    others = [ o | (j, o) <- zip [0 :: Int ..] robots, j /= i ]
    p      = rPos me
    polar q = let (d, th) = vector2RhoTheta (q .-. p)
              in (normalizeAngle (th - rHeading me), d)
    rangeAt = rangeReading (scArena ctx) (map rPos others) p (rHeading me)

-- | The range finder's reading for a robot at a position and heading,
-- among the given other robots' centres, in the direction @a@ relative to
-- the heading (see the module documentation). A non-finite angle reads
-- 'rangeFinderMax'.
rangeReading :: Arena -> [Position2] -> Position2 -> Heading -> Angle -> Distance
rangeReading arena others p heading a
  | isNaN a || isInfinite a = rangeFinderMax
  | otherwise               = max 0 (min rangeFinderMax (nearest - radius))
  where
    radius  = simbotDiameter / 2
    dir     = vector2Polar 1 (heading + a)
    hits    = [ t | b <- arenaBoxes arena, Just t <- [rayBox p dir b] ]
           ++ [ t | q <- others, Just t <- [rayCircle p dir q radius] ]
    nearest = minimum (rangeFinderMax + radius : hits)
