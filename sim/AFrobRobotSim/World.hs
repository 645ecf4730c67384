-- |
-- Module      : AFrobRobotSim.World
-- Description : World templates: what a simulated world is made of, and
--               the dimensions of everything in it.
--
-- Their validation is "AFrobRobotSim.World.Check".
--
-- A world is a rectangle centred on the origin, walled in on all four
-- sides: by default the square @[worldXMin, worldXMax] x [worldYMin,
-- worldYMax]@ (10 m by 10 m, as in the notes), or @W@ by @H@ metres when its
-- template holds an @'OTSize' W H@ ('worldBounds'). A 'WorldTemplate' lists
-- the objects in it by their centres.
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
  , worldSize
  , isWorldSize
  , worldBounds
  , worldBoundsOr
  , sizeBounds
  , minWorldSide
  , maxWorldSide
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
    -- * Extents and names
  , Bounds (..)
  , notesBounds
  , objectName
  , objectHalfSize
  , insideBounds
  ) where

import           AFRP.Geometry
import           AFrob.Dimensions

-- | A world: the objects in it, and optionally its size (an 'OTSize';
-- without one, the notes' 10 m by 10 m).
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
  | OTSize    { otWidth :: Length, otHeight :: Length }
    -- ^ not an object but the world's size: the world is @otWidth@ by
    -- @otHeight@ metres, centred on the origin ('worldBounds'), from time 0
    -- on. At most one per template, each side between 'minWorldSide' and
    -- 'maxWorldSide' ('AFrobRobotSim.World.Check.validateWorld'); where it stands in the list does
    -- not matter. It has no 'otPos'.
  deriving (Eq, Show)

-- | The size a template gives its world, width and height in metres: its
-- first 'OTSize', if any.
worldSize :: WorldTemplate -> Maybe (Length, Length)
worldSize objs = case [ (w, h) | OTSize w h <- objs ] of
  wh : _ -> Just wh
  []     -> Nothing

-- | Is this entry of a template the world's size ('OTSize'), not an
-- object?
isWorldSize :: ObjectTemplate -> Bool
isWorldSize OTSize {} = True
isWorldSize _         = False

-- | The extent of a template's world: @'sizeBounds' w h@ for its
-- 'worldSize', the notes' 'notesBounds' without one.
--
-- >>> worldBounds [OTSize 30 10, OTBall (Point2 0 0)]
-- Bounds (-15.0) (-5.0) 15.0 5.0
worldBounds :: WorldTemplate -> Bounds
worldBounds = worldBoundsOr notesBounds

-- | The extent of a template's world, given the extent to use when it has
-- no 'OTSize': a size in the template wins over the bounds given
-- alongside it (in 'AFrobRobotSim.SimConfig', a scene or a log's
-- settings).
worldBoundsOr :: Bounds -> WorldTemplate -> Bounds
worldBoundsOr b = maybe b (uncurry sizeBounds) . worldSize

-- | The extent of a world @w@ by @h@ metres centred on the origin:
-- @Bounds (-w/2) (-h/2) (w/2) (h/2)@.
sizeBounds :: Length -> Length -> Bounds
sizeBounds w h = Bounds (negate (w / 2)) (negate (h / 2)) (w / 2) (h / 2)

-- | The shortest side a world may have: 1 m (room for a simbot, 0.5 m
-- across, to turn).
minWorldSide :: Length
minWorldSide = 1

-- | The longest side a world may have: 1000 m (a hundred times the notes'
-- world; the grids of the physics and sensors coarsen beyond a few
-- hundred metres, and a frame shows a simbot as less than a pixel).
maxWorldSide :: Length
maxWorldSide = 1000

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
objectName (OTSize w h) = "world size " ++ show w ++ " by " ++ show h
objectName o = what o ++ " at " ++ showPos (otPos o)
  where
    what OTBlock {}   = "block"
    what OTVWall {}   = "vertical wall"
    what OTHWall {}   = "horizontal wall"
    what OTBall {}    = "ball"
    what r@OTSimbotA {} = "SimbotA " ++ show (otRId r)
    what r@OTSimbotB {} = "SimbotB " ++ show (otRId r)
    what OTSize {}    = "world size"
    showPos (Point2 x y) = "(" ++ show x ++ ", " ++ show y ++ ")"

-- | The extent of a world: @Bounds xMin yMin xMax yMax@, in metres.
data Bounds = Bounds !Double !Double !Double !Double
  deriving (Eq, Show)

-- | The notes' world: @Bounds (-5) (-5) 5 5@.
notesBounds :: Bounds
notesBounds = Bounds worldXMin worldYMin worldXMax worldYMax

-- | Half the width and height of an object's bounding box, in metres (for
-- an 'OTSize', half the world's).
objectHalfSize :: ObjectTemplate -> (Double, Double)
objectHalfSize o = case o of
  OTBlock {}   -> (blockSide / 2, blockSide / 2)
  OTVWall {}   -> (wallThickness / 2, wallLength / 2)
  OTHWall {}   -> (wallLength / 2, wallThickness / 2)
  OTBall {}    -> (ballDiameter / 2, ballDiameter / 2)
  OTSimbotA {} -> (simbotDiameter / 2, simbotDiameter / 2)
  OTSimbotB {} -> (simbotDiameter / 2, simbotDiameter / 2)
  OTSize w h   -> (w / 2, h / 2)

-- | Does an object's bounding box ('objectHalfSize') lie inside these
-- bounds? Touching their edge is inside; a NaN coordinate is not. An
-- 'OTSize', which is no object, is.
insideBounds :: Bounds -> ObjectTemplate -> Bool
insideBounds _ OTSize {} = True
insideBounds (Bounds x0 y0 x1 y1) o =
  let Point2 x y = otPos o
      (hw, hh)   = objectHalfSize o
  in x - hw >= x0 && x + hw <= x1 && y - hh >= y0 && y + hh <= y1
