-- |
-- Module      : AFrobRobotSim.World
-- Description : World templates: what a simulated world is made of, the
--               dimensions of everything in it, and their validation.
--
-- A world is the square @[worldXMin, worldXMax] x [worldYMin, worldYMax]@
-- (10 m by 10 m, centred on the origin, as in the notes), walled in on all
-- four sides. A 'WorldTemplate' lists the objects in it by their centres.
--
-- = Dimensions
--
-- @
-- object            shape                       size
-- OTVWall           rectangle, vertical         0.1 m wide, 1.0 m tall
-- OTHWall           rectangle, horizontal       1.0 m wide, 0.1 m tall
-- OTBlock           square                      0.5 m by 0.5 m
-- OTBall            disc                        0.3 m across
-- OTSimbotA/B       disc                        0.5 m across
-- @
--
-- = Robot types
--
-- @
-- type      rpType     wheel base   max wheel speed   max acceleration
-- SimbotA   "SimbotA"  0.5 m        1.0 m/s           0.2 m/s^2
-- SimbotB   "SimbotB"  0.5 m        2.0 m/s           0.5 m/s^2
-- @
module AFrobRobotSim.World
  ( -- * Templates
    WorldTemplate
  , ObjectTemplate (..)
    -- * The world's extent
  , worldXMin
  , worldYMin
  , worldXMax
  , worldYMax
    -- * Dimensions
  , wallLength
  , wallThickness
  , blockSide
  , ballDiameter
  , simbotDiameter
    -- * Robot types
  , RobotKind (..)
  , robotKindOf
  , kindType
  , kindWheelBase
  , kindWSMax
  , kindAccMax
    -- * Validation
  , Bounds (..)
  , notesBounds
  , validateWorld
  , validateWorldIn
  , objectName
  , objectHalfSize
  ) where

import           Data.List      (sort, tails)

import           AFRP.Geometry
import           AFrob.Dimensions

-- | A world: the objects in it.
type WorldTemplate = [ObjectTemplate]

-- | One object of a world, placed by its centre. Headings are in radians
-- (0 = +x, counter-clockwise).
data ObjectTemplate
  = OTBlock   { otPos :: Position2 }                                 -- ^ a 0.5 m square obstacle
  | OTVWall   { otPos :: Position2 }                                 -- ^ a vertical wall, 0.1 by 1.0 m
  | OTHWall   { otPos :: Position2 }                                 -- ^ a horizontal wall, 1.0 by 0.1 m
  | OTBall    { otPos :: Position2 }                                 -- ^ a ball, 0.3 m across
  | OTSimbotA { otRId :: RobotId, otPos :: Position2, otHdng :: Heading } -- ^ a simbot of type A
  | OTSimbotB { otRId :: RobotId, otPos :: Position2, otHdng :: Heading } -- ^ a simbot of type B
  deriving (Eq, Show)

-- | The world's left edge, in metres: -5.
worldXMin :: Position
worldXMin = -5

-- | The world's bottom edge, in metres: -5.
worldYMin :: Position
worldYMin = -5

-- | The world's right edge, in metres: 5.
worldXMax :: Position
worldXMax = 5

-- | The world's top edge, in metres: 5.
worldYMax :: Position
worldYMax = 5

-- | The length of a wall segment: 1.0 m.
wallLength :: Length
wallLength = 1.0

-- | The thickness of a wall segment: 0.1 m.
wallThickness :: Length
wallThickness = 0.1

-- | The side of a block: 0.5 m.
blockSide :: Length
blockSide = 0.5

-- | The diameter of a ball: 0.3 m.
ballDiameter :: Length
ballDiameter = 0.3

-- | The diameter of a simbot's body: 0.5 m.
simbotDiameter :: Length
simbotDiameter = 0.5

-- | The two kinds of simbot.
data RobotKind = SimbotA | SimbotB
  deriving (Eq, Ord, Show, Enum, Bounded)

-- | The kind of a robot template, if it is one.
robotKindOf :: ObjectTemplate -> Maybe RobotKind
robotKindOf OTSimbotA {} = Just SimbotA
robotKindOf OTSimbotB {} = Just SimbotB
robotKindOf _            = Nothing

-- | The 'RobotType' string of a kind: @"SimbotA"@ or @"SimbotB"@.
kindType :: RobotKind -> RobotType
kindType = show

-- | Distance between the wheels: 0.5 m for both kinds.
kindWheelBase :: RobotKind -> Length
kindWheelBase _ = 0.5

-- | Maximum wheel speed: 1.0 m/s (A), 2.0 m/s (B).
kindWSMax :: RobotKind -> Speed
kindWSMax SimbotA = 1.0
kindWSMax SimbotB = 2.0

-- | Maximum translational acceleration: 0.2 m/s^2 (A), 0.5 m/s^2 (B).
kindAccMax :: RobotKind -> Acceleration
kindAccMax SimbotA = 0.2
kindAccMax SimbotB = 0.5

-- | A short human-readable name for an object, used in error messages:
-- @"SimbotA 3 at (1.0, 2.0)"@, @"ball at (0.0, 0.0)"@.
objectName :: ObjectTemplate -> String
objectName o = what o ++ " at " ++ showPos (otPos o)
  where
    what OTBlock {}   = "block"
    what OTVWall {}   = "vertical wall"
    what OTHWall {}   = "horizontal wall"
    what OTBall {}    = "ball"
    what r@OTSimbotA {} = "SimbotA " ++ show (otRId r)
    what r@OTSimbotB {} = "SimbotB " ++ show (otRId r)
    showPos (Point2 x y) = "(" ++ show x ++ ", " ++ show y ++ ")"

-- | The extent of a world: @Bounds xMin yMin xMax yMax@, in metres.
data Bounds = Bounds !Double !Double !Double !Double
  deriving (Eq, Show)

-- | The notes' world: @Bounds (-5) (-5) 5 5@.
notesBounds :: Bounds
notesBounds = Bounds worldXMin worldYMin worldXMax worldYMax

-- | Check a world template: every coordinate and heading is a finite
-- number; every object lies inside the world; no two robots of one type
-- share an id; no two robots overlap. Returns every problem found, each
-- naming the object(s), or @Right ()@.
validateWorld :: WorldTemplate -> Either [String] ()
validateWorld = validateWorldIn notesBounds

-- | 'validateWorld' for a world of the given extent.
validateWorldIn :: Bounds -> WorldTemplate -> Either [String] ()
validateWorldIn (Bounds x0 y0 x1 y1) objs = case problems of
  [] -> Right ()
  ps -> Left ps
  where
    problems = concatMap finite objs ++ concatMap inside objs ++ duplicates ++ overlaps
    finite o =
      [ objectName o ++ ": coordinates and heading must be finite numbers"
      | not (all isFinite (coords o)) ]
    coords o = let Point2 x y = otPos o
               in x : y : maybe [] (const [otHdng o]) (robotKindOf o)
    isFinite v = not (isNaN v || isInfinite v)
    inside o
      | not (all isFinite (coords o)) = []
      | otherwise =
          let Point2 x y = otPos o
              (hw, hh)   = objectHalfSize o
          in [ objectName o ++ ": lies (partly) outside the world [" ++ show x0 ++ ", " ++ show x1
                 ++ "] x [" ++ show y0 ++ ", " ++ show y1 ++ "]"
             | x - hw < x0 || x + hw > x1 || y - hh < y0 || y + hh > y1 ]
    robots = [ (k, o) | o <- objs, Just k <- [robotKindOf o] ]
    duplicates =
      [ "two " ++ kindType k ++ " robots have the id " ++ show i
      | (k, i) <- dupes (sort [ (k, otRId o) | (k, o) <- robots ]) ]
    dupes xs = [ a | (a, b) <- zip xs (drop 1 xs), a == b ]
    overlaps =
      [ objectName a ++ " and " ++ objectName b ++ " overlap"
      | ((_, a) : rest) <- tails robots, (_, b) <- rest
      , all isFinite (coords a ++ coords b)
      , norm (otPos a .-. otPos b) < simbotDiameter ]

-- | Half the width and height of an object's bounding box, in metres.
objectHalfSize :: ObjectTemplate -> (Double, Double)
objectHalfSize o = case o of
  OTBlock {}   -> (blockSide / 2, blockSide / 2)
  OTVWall {}   -> (wallThickness / 2, wallLength / 2)
  OTHWall {}   -> (wallLength / 2, wallThickness / 2)
  OTBall {}    -> (ballDiameter / 2, ballDiameter / 2)
  OTSimbotA {} -> (simbotDiameter / 2, simbotDiameter / 2)
  OTSimbotB {} -> (simbotDiameter / 2, simbotDiameter / 2)
