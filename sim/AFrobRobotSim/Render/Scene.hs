-- |
-- Module      : AFrobRobotSim.Render.Scene
-- Description : What a picture of the simulated world shows: its size, its
--               colours and its shapes.
--
-- The part of "AFrobRobotSim.Render" that both back ends share: the
-- coordinates (see "AFrobRobotSim.Render" for the mapping and for the table
-- of what is drawn), the colours, and the list of shapes, in image
-- coordinates, that a snapshot is drawn as.
module AFrobRobotSim.Render.Scene
  ( -- * Scenes and styles
    Scene (..)
  , RenderStyle (..)
  , defaultRenderStyle
  , sceneExtent
  , frameSize
  , frameMargin
  , worldToPixel
    -- * Colours
  , Colour (..)
  , backgroundColour
  , boundaryColour
  , wallColour
  , blockColour
  , ballColour
  , ballRimColour
  , rayColour
  , headingColour
  , labelColour
  , typeColour
  , robotColour
  , typeRanks
  , bodyColour
  , outlineColour
  , robotBodyColour
  , robotOutlineColour
  , trailColour
    -- * Shapes, for the back ends
  , Shape (..)
  , View (..)
  , viewOf
  , vScale
  , validScale
  , toImg
  , floorShapes
  , staticShapes
  , trailShapes
  , snapshotShapes
  ) where

import qualified Data.Map.Strict            as M
import           Numeric                    (showFFloat)

import           AFRP.Geometry
import           AFrob.Dimensions
import           AFrobRobotSim.Arena        (Arena, arenaOf)
import           AFrobRobotSim.Balls        (ballRadius)
import           AFrobRobotSim.Physics      (robotRadius)
import           AFrobRobotSim.Render.Raster
import           AFrobRobotSim.Sensors      (rangeReading)
import           AFrobRobotSim.Simulator    (RobotState (..), WorldState (..))
import           AFrobRobotSim.World
-- | What is pictured: the world's extent and its template. The walls and
-- blocks are taken from the template; the robots and balls (and anything
-- else that moves) from each 'WorldState'.
data Scene = Scene
  { sceneBounds :: Bounds          -- ^ the world's extent (as in 'AFrobRobotSim.SimConfig'), unless the template has an 'OTSize', which wins ('sceneExtent')
  , sceneWorld  :: WorldTemplate   -- ^ the world that was simulated
  } deriving (Eq, Show)

-- | How to draw.
data RenderStyle = RenderStyle
  { styleScale  :: Double   -- ^ pixels per metre; must be positive and finite, else only the boundary is drawn
  , styleRays   :: Bool     -- ^ draw each robot's four range-finder rays
  , styleTrails :: Bool     -- ^ draw each robot's path so far (frames only; the SVG always has trajectories)
  } deriving (Eq, Show)

-- | 60 pixels per metre, no rays, no trails: 620 by 620 pixel frames of the
-- notes' 10 m world.
defaultRenderStyle :: RenderStyle
defaultRenderStyle = RenderStyle 60 False False

-- | The margin around the world, in pixels, on every side: 10. It shows the
-- boundary wall.
frameMargin :: Int
frameMargin = 10

-- The world's extent in pixels along one axis: at least 0, at most 16384.
worldPixels :: Double -> Double -> Int
worldPixels s len
  | isNaN v || v <= 0 = 0
  | otherwise         = round (min 16384 v)
  where v = s * len

-- | The width and height of a frame in pixels: the world's extent times
-- the scale, rounded, plus 'frameMargin' on each side (each world extent
-- counts as at most 16384 pixels). 620 by 620 for the notes' world at 60
-- pixels per metre.
frameSize :: RenderStyle -> Scene -> (Int, Int)
frameSize style scene =
  (2 * frameMargin + worldPixels s (x1 - x0), 2 * frameMargin + worldPixels s (y1 - y0))
  where
    Bounds x0 y0 x1 y1 = sceneExtent scene
    s = styleScale style

-- | The extent of the world pictured: the template's 'OTSize' if it has
-- one, else 'sceneBounds' ('worldBoundsOr').
sceneExtent :: Scene -> Bounds
sceneExtent scene = worldBoundsOr (sceneBounds scene) (sceneWorld scene)

-- | The image point of a world point (see the module documentation): the
-- point lies in the pixel @(floor px, floor py)@.
worldToPixel :: RenderStyle -> Scene -> Position2 -> (Double, Double)
worldToPixel style scene = applyMap (imageMapOf style scene)

imageMapOf :: RenderStyle -> Scene -> ImageMap
imageMapOf style scene = ImageMap s (m - x0 * s) (m + y1 * s)
  where
    Bounds x0 _ _ y1 = sceneExtent scene
    s = styleScale style
    m = fromIntegral frameMargin

------------------------------------------------------------------------------
-- Colours

-- | The floor: (240, 240, 230).
backgroundColour :: Colour
backgroundColour = Colour 240 240 230

-- | The boundary wall (the frame's margin): (45, 45, 45).
boundaryColour :: Colour
boundaryColour = Colour 45 45 45

-- | Walls: (90, 90, 90).
wallColour :: Colour
wallColour = Colour 90 90 90

-- | Blocks: (139, 90, 43).
blockColour :: Colour
blockColour = Colour 139 90 43

-- | Balls: (255, 140, 0); their rim is (170, 90, 0).
ballColour :: Colour
ballColour = Colour 255 140 0

-- | The rim of a ball: (170, 90, 0).
ballRimColour :: Colour
ballRimColour = Colour 170 90 0

-- | Range-finder rays: (0, 170, 60).
rayColour :: Colour
rayColour = Colour 0 170 60

-- | The heading mark: white, (255, 255, 255).
headingColour :: Colour
headingColour = Colour 255 255 255

-- | Robot ids: (20, 20, 20).
labelColour :: Colour
labelColour = Colour 20 20 20

-- | The colour of a robot type: @"SimbotA"@ blue (30, 90, 220),
-- @"SimbotB"@ red (215, 40, 40), anything else purple (140, 60, 170).
typeColour :: RobotType -> Colour
typeColour t
  | t == kindType SimbotA = Colour 30 90 220
  | t == kindType SimbotB = Colour 215 40 40
  | otherwise             = Colour 140 60 170

-- | The colour of a robot that is the @k@-th of its type (from 0, in the
-- order of the robots): its 'typeColour' for the first, then five other
-- shades of the same family (blues for SimbotA, reds for SimbotB, purples
-- for other types), over again from the seventh. Robots of one type are
-- told apart by it, and by the id written next to each.
robotColour :: RobotType -> Int -> Colour
robotColour t k
  | k <= 0    = typeColour t
  | otherwise = shades !! ((k - 1) `mod` length shades)
  where
    shades
      | t == kindType SimbotA = [ Colour 0 150 200, Colour 90 50 200, Colour 20 50 130
                                , Colour 110 170 255, Colour 0 110 140 ]
      -- no orange: that is the balls' colour
      | t == kindType SimbotB = [ Colour 230 90 170, Colour 150 20 90, Colour 120 20 20
                                , Colour 245 130 110, Colour 170 90 60 ]
      | otherwise             = [ Colour 190 90 210, Colour 100 30 130, Colour 210 140 230
                                , Colour 120 60 100, Colour 160 40 120 ]

-- | For each robot of a list, how many robots of its type come before it:
-- the @k@ of its 'robotColour'.
typeRanks :: [RobotState] -> [Int]
typeRanks = go M.empty
  where
    go _ [] = []
    go seen (r : rs) = let k = M.findWithDefault 0 (robotType r) seen
                       in k : go (M.insert (robotType r) (k + 1) seen) rs

-- | The body colour of the first robot of a type, stuck or not:
-- @'robotBodyColour' t 0@.
bodyColour :: RobotType -> Bool -> Colour
bodyColour t = robotBodyColour t 0

-- | The rim colour of the first robot of a type, stuck or not:
-- @'robotOutlineColour' t 0@.
outlineColour :: RobotType -> Bool -> Colour
outlineColour t = robotOutlineColour t 0

-- | The body colour of the @k@-th robot of a type ('robotColour'), at 60 %
-- brightness when stuck.
robotBodyColour :: RobotType -> Int -> Bool -> Colour
robotBodyColour t k stuck
  | stuck     = darken 0.6 (robotColour t k)
  | otherwise = robotColour t k

-- | The rim colour of the @k@-th robot of a type: its 'robotColour' at
-- half brightness, or black when stuck.
robotOutlineColour :: RobotType -> Int -> Bool -> Colour
robotOutlineColour t k stuck
  | stuck     = Colour 0 0 0
  | otherwise = darken 0.5 (robotColour t k)

-- | The colour of a robot type's trail: its 'typeColour' mixed half and half
-- with the 'backgroundColour'.
trailColour :: RobotType -> Colour
trailColour t = blend 0.5 (typeColour t) backgroundColour

------------------------------------------------------------------------------
-- Shapes, in image coordinates

-- | What a picture is made of, in image coordinates (pixels; see
-- 'worldToPixel'): the back ends ("AFrobRobotSim.Render" for PPM frames,
-- "AFrobRobotSim.Render.SVG") draw a list of them in order, each over the
-- ones before.
data Shape
  = SFill Colour
    -- ^ the whole picture
  | SRect Colour Double Double Double Double
    -- ^ the rectangle @[x0, x1) x [y0, y1)@
  | SDisc Colour Double Double Double
    -- ^ the disc of the given centre and radius
  | STri Colour (Double, Double) (Double, Double) (Double, Double)
    -- ^ the triangle of the three corners
  | SLine Colour Int (Double, Double) (Double, Double)
    -- ^ the segment between two points, the given number of pixels wide
  | SPolyline Colour Int [Position2]
    -- ^ a line through /world/ points (mapped by the back end), so many
    -- pixels wide
  | SText Colour Int (Int, Int) String
    -- ^ digits magnified so many times, the top-left corner at the point

-- | One picture's style and scene, with what follows from them. A view
-- is the same for every snapshot of a run: a back end that draws many
-- builds it once (see 'AFrobRobotSim.Render.renderPPM').
data View = View
  { vStyle :: RenderStyle
    -- ^ how to draw
  , vScene :: Scene
    -- ^ what is drawn
  , vSize  :: (Int, Int)
    -- ^ the frame's size in pixels ('frameSize')
  , vMap   :: ImageMap
    -- ^ world to image coordinates ('worldToPixel')
  , vArena :: Arena
    -- ^ the scene's static world, for the range-finder rays (built when
    -- first needed)
  }

-- | The view of a scene drawn in a style.
viewOf :: RenderStyle -> Scene -> View
viewOf style scene =
  View style scene (frameSize style scene) (imageMapOf style scene)
       (arenaOf (sceneBounds scene) (sceneWorld scene))

-- | Pixels per metre ('styleScale').
vScale :: View -> Double
vScale = styleScale . vStyle

-- | Is the scale positive and finite? Otherwise a picture shows only the
-- boundary ('floorShapes' gives just the fill, the others nothing).
validScale :: View -> Bool
validScale v = let s = vScale v in s > 0 && not (isInfinite s)

-- | The image point of a world point ('worldToPixel').
toImg :: View -> Position2 -> (Double, Double)
toImg v = applyMap (vMap v)

-- | The boundary (the whole picture) and, over it, the floor.
floorShapes :: View -> [Shape]
floorShapes v = SFill boundaryColour : [ SRect backgroundColour m m (fromIntegral w - m) (fromIntegral h - m) | validScale v ]
  where
    (w, h) = vSize v
    m = fromIntegral frameMargin

-- | The walls and blocks of the scene's template.
staticShapes :: View -> [Shape]
staticShapes v = [ SRect col x0 y0 x1 y1 | validScale v, o <- sceneWorld (vScene v), Just col <- [colourOf o]
                 , let Point2 x y = otPos o
                       (hw, hh)   = objectHalfSize o
                       (x0, y0)   = toImg v (Point2 (x - hw) (y + hh))
                       (x1, y1)   = toImg v (Point2 (x + hw) (y - hh)) ]
  where
    colourOf o = case o of
      OTBlock {} -> Just blockColour
      OTVWall {} -> Just wallColour
      OTHWall {} -> Just wallColour
      _          -> Nothing

-- | Each robot's path so far as a 1-pixel polyline in its 'robotColour'
-- mixed half and half with the floor (the 'trailColour' for the first of a
-- type), one list of world points per robot, in the robots' order.
trailShapes :: View -> [RobotState] -> [[Position2]] -> [Shape]
trailShapes v robots trails =
  [ SPolyline col 1 ps | validScale v, (col, ps) <- zip cols trails ]
  where cols = [ blend 0.5 (robotColour (robotType r) k) backgroundColour
               | (r, k) <- zip robots (typeRanks robots) ] ++ repeat (trailColour "")

-- | The balls, range-finder rays (with 'styleRays'), robots, ids and the
-- simulated time of a snapshot, bottom to top. Each robot is drawn in its
-- 'robotColour'; each ray ends in a dot of its robot's colour, so that
-- with many robots one sees whose reading is where. An id is written
-- above and right of its robot, or left of it or below it where that
-- would leave the world, and never outside the world's rectangle. The
-- time (seconds, two decimals) is in the world's top-left corner on a
-- white ground.
snapshotShapes :: View -> WorldState -> [Shape]
snapshotShapes v ws
  | not (validScale v) = []
  | otherwise = concatMap ball (wsBalls ws) ++ rays ++ concatMap robot ranked ++ map label robots
                ++ clock
  where
    s      = vScale v
    robots = wsRobots ws
    ranked = zip robots (typeRanks robots)
    ballR  = ballRadius * s
    ball p = let (cx, cy) = toImg v p
             in [SDisc ballRimColour cx cy ballR, SDisc ballColour cx cy (ballR - max 1 (s / 60))]
    arena  = vArena v
    rayW   = max 1 (round (s / 60))
    rays
      | styleRays (vStyle v) =
          concat
          [ [ SLine rayColour rayW (toImg v (p .+^ vector2Polar robotRadius dir)) (ex, ey)
            , SDisc (robotColour (robotType r) rank) ex ey (max 2 (s / 30)) ]
          | (i, (r, rank)) <- zip [0 :: Int ..] ranked
          , let p = robotPos r
                others = [ robotPos o | (j, o) <- zip [0 ..] robots, j /= i ]
          , a <- [0, pi / 2, pi, -pi / 2]
          , let d   = rangeReading arena others p (robotHeading r) a
                dir = robotHeading r + a
                (ex, ey) = toImg v (p .+^ vector2Polar (robotRadius + d) dir) ]
      | otherwise = []
    rPx = robotRadius * s
    robot (r, rank) =
      let (cx, cy) = toImg v (robotPos r)
          stuck    = robotStuck r
          rim      = max 1 (s / 30) * (if stuck then 2 else 1)
          hd       = robotHeading r
          (ux, uy) = (cos hd, negate (sin hd))
          (nx, ny) = (negate uy, ux)
          (bx, by) = (cx + 0.3 * rPx * ux, cy + 0.3 * rPx * uy)
          half     = 0.3 * rPx
      in [ SDisc (robotOutlineColour (robotType r) rank stuck) cx cy rPx
         , SDisc (robotBodyColour (robotType r) rank stuck) cx cy (rPx - rim)
         , STri headingColour (cx + rPx * ux, cy + rPx * uy)
                (bx + half * nx, by + half * ny) (bx - half * nx, by - half * ny) ]
    k = max 1 (round (s / 30))
    (fw, fh) = vSize v
    m = frameMargin
    label r =
      let (cx, cy) = toImg v (robotPos r)
          str = show (robotId r)
          tw  = textWidth k str
          th  = 5 * k
          right = floorInt (cx + 0.72 * rPx) + 1
          left  = floorInt (cx - 0.72 * rPx) - 1 - tw
          above = floorInt (cy - 0.72 * rPx) - th
          below = floorInt (cy + 0.72 * rPx) + 1
          x0 = if right + tw > fw - m then left else right
          y0 = if above < m then below else above
      in SText labelColour k (clampTo m (fw - m - tw) x0, clampTo m (fh - m - th) y0) str
    clampTo lo hi x = max lo (min (max lo hi) x)
    clock =
      let str = showFFloat (Just 2) (max 0 (wsTime ws)) ""
          tw  = textWidth k str
      in [ SRect headingColour (fromIntegral m) (fromIntegral m)
                 (fromIntegral (m + tw + 2 * k)) (fromIntegral (m + 7 * k))
         , SText labelColour k (m + k, m + k) str ]

-- | A pixel coordinate rounded down, NaN as 0 and anything else clamped
-- to 10^7 either way.
floorInt :: Double -> Int
floorInt x
  | isNaN x   = 0
  | otherwise = floor (max (-1e7) (min 1e7 x))
