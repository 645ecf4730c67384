-- |
-- Module      : AFrobRobotSim.Render
-- Description : Pictures of a simulated world: binary PPM frames and an SVG
--               picture of a whole run.
--
-- A pure software renderer: the same inputs always give byte-identical
-- output. 'renderPPM' draws one snapshot as a binary PPM (P6) file, fast
-- enough to write every frame of a run (a 620 by 620 frame takes about a
-- millisecond); 'renderSVG' draws the end of a run with every robot's
-- whole trajectory.
--
-- = Coordinates
--
-- The world is drawn at 'styleScale' pixels per metre inside a margin of
-- 'frameMargin' pixels on every side, which shows the boundary wall. World
-- @x@ grows to the right and world @y@ /upwards/; image columns grow to the
-- right and image rows /downwards/, so the world point @(x, y)@ is at the
-- image point
--
-- @
-- (frameMargin + (x - xMin) * scale,  frameMargin + (yMax - y) * scale)
-- @
--
-- ('worldToPixel'), and lies in the pixel whose column and row are those
-- coordinates rounded down. The world's corner @(xMin, yMax)@ is the
-- top-left corner of pixel @(frameMargin, frameMargin)@. Headings are
-- counter-clockwise from world @+x@, so they turn clockwise in the image.
-- A shape covers the pixels whose centres lie inside it (see
-- "AFrobRobotSim.Render.Raster").
--
-- = What is drawn, bottom to top
--
-- @
-- thing          shape                                        colour (R, G, B)
-- boundary wall  the whole margin around the world            (45, 45, 45)     #2d2d2d
-- floor          the world's rectangle                        (240, 240, 230)  #f0f0e6
-- trail          1-pixel polyline of each robot's path        robot colour mixed half and
--                (frames with styleTrails only)               half with the floor colour
-- wall           filled 0.1 by 1.0 m rectangle                (90, 90, 90)     #5a5a5a
-- block          filled 0.5 by 0.5 m square                   (139, 90, 43)    #8b5a2b
-- ball           disc 0.3 m across, 1-pixel rim at 60 px\/m    (255, 140, 0)    #ff8c00
--                                                             rim (170, 90, 0) #aa5a00
-- range ray      line from the robot's edge to its reading    (0, 170, 60)     #00aa3c
--                (styleRays only)
-- robot body     disc 0.5 m across                            SimbotA (30, 90, 220)  #1e5adc
--                                                             SimbotB (215, 40, 40)  #d72828
--                                                             other   (140, 60, 170) #8c3caa
-- robot rim      scale \/ 30 pixels wide (2 px at 60 px\/m)     body colour at half brightness
-- stuck robot    rim twice as wide, body at 60 % brightness   rim (0, 0, 0)    #000000
-- heading mark   wedge from 0.3 of the radius to the edge,    (255, 255, 255)  #ffffff
--                pointing along the heading
-- robot id       3x5 pixel digits, magnified round(scale\/30)  (20, 20, 20)     #141414
--                times, just above and right of the body
-- @
--
-- The SVG picture uses the same shapes and colours, and adds each robot's
-- trajectory (2 pixels wide, in its body colour), a start marker (a white
-- disc ringed in the body colour) and a legend to the right of the world.
module AFrobRobotSim.Render
  ( -- * Scenes and styles
    Scene (..)
  , RenderStyle (..)
  , defaultRenderStyle
  , frameSize
  , frameMargin
  , worldToPixel
    -- * PPM frames
  , renderPPM
  , ppmPixel
    -- * SVG pictures
  , renderSVG
  , svgMaxPoints
    -- * Colours
  , Colour (..)
  , backgroundColour
  , boundaryColour
  , wallColour
  , blockColour
  , ballColour
  , rayColour
  , headingColour
  , labelColour
  , typeColour
  , bodyColour
  , outlineColour
  , trailColour
  ) where

import           Data.List                  (transpose)
import qualified Data.ByteString            as B
import           Text.Printf                (printf)

import           AFRP.Geometry
import           AFrob.Dimensions
import           AFrobRobotSim.Physics      (arenaOf)
import           AFrobRobotSim.Render.Raster
import           AFrobRobotSim.Sensors      (rangeReading)
import           AFrobRobotSim.Simulator    (RobotState (..), WorldState (..))
import           AFrobRobotSim.World

-- | What is pictured: the world's extent and its template. The walls and
-- blocks are taken from the template; the robots and balls (and anything
-- else that moves) from each 'WorldState'.
data Scene = Scene
  { sceneBounds :: Bounds          -- ^ the world's extent (as in 'AFrobRobotSim.SimConfig')
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
    Bounds x0 y0 x1 y1 = sceneBounds scene
    s = styleScale style

-- | The image point of a world point (see the module documentation): the
-- point lies in the pixel @(floor px, floor py)@.
worldToPixel :: RenderStyle -> Scene -> Position2 -> (Double, Double)
worldToPixel style scene = applyMap (imageMapOf style scene)

imageMapOf :: RenderStyle -> Scene -> ImageMap
imageMapOf style scene = ImageMap s (m - x0 * s) (m + y1 * s)
  where
    Bounds x0 _ _ y1 = sceneBounds scene
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

-- | The body colour of a robot of a type, stuck or not: the 'typeColour',
-- at 60 % brightness when stuck.
bodyColour :: RobotType -> Bool -> Colour
bodyColour t stuck
  | stuck     = darken 0.6 (typeColour t)
  | otherwise = typeColour t

-- | The rim colour of a robot of a type, stuck or not: the 'typeColour' at
-- half brightness, or black when stuck.
outlineColour :: RobotType -> Bool -> Colour
outlineColour t stuck
  | stuck     = Colour 0 0 0
  | otherwise = darken 0.5 (typeColour t)

-- | The colour of a robot type's trail: its 'typeColour' mixed half and half
-- with the 'backgroundColour'.
trailColour :: RobotType -> Colour
trailColour t = blend 0.5 (typeColour t) backgroundColour

------------------------------------------------------------------------------
-- Shapes, in image coordinates

-- What a picture is made of; drawn in list order by both back ends.
data Shape
  = SFill Colour                                                  -- the whole picture
  | SRect Colour Double Double Double Double                      -- [x0, x1) x [y0, y1)
  | SDisc Colour Double Double Double                             -- centre, radius
  | STri Colour (Double, Double) (Double, Double) (Double, Double)
  | SLine Colour Int (Double, Double) (Double, Double)            -- width in pixels
  | SPolyline Colour Int [Position2]                              -- world points
  | SText Colour Int (Int, Int) String                            -- magnification, top-left

-- The world-to-image mapping and sizes of one picture.
data View = View
  { vStyle :: RenderStyle
  , vScene :: Scene
  , vScale :: Double
  , vSize  :: (Int, Int)
  , vMap   :: ImageMap
  }

viewOf :: RenderStyle -> Scene -> View
viewOf style scene =
  View style scene (styleScale style) (frameSize style scene) (imageMapOf style scene)

validScale :: View -> Bool
validScale v = let s = vScale v in s > 0 && not (isInfinite s)

toImg :: View -> Position2 -> (Double, Double)
toImg v = applyMap (vMap v)

robotRadius :: Double
robotRadius = simbotDiameter / 2

-- The boundary and the floor.
floorShapes :: View -> [Shape]
floorShapes v = SFill boundaryColour : [ SRect backgroundColour m m (fromIntegral w - m) (fromIntegral h - m) | validScale v ]
  where
    (w, h) = vSize v
    m = fromIntegral frameMargin

-- The walls and blocks of the template.
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

-- Each robot's path, one list per robot.
trailShapes :: View -> [RobotState] -> [[Position2]] -> [Shape]
trailShapes v robots trails =
  [ SPolyline col 1 ps | validScale v, (col, ps) <- zip cols trails ]
  where cols = map (trailColour . robotType) robots ++ repeat (blend 0.5 (typeColour "") backgroundColour)

-- The balls, rays, robots and ids of a snapshot.
snapshotShapes :: View -> WorldState -> [Shape]
snapshotShapes v ws
  | not (validScale v) = []
  | otherwise = concatMap ball (wsBalls ws) ++ rays ++ concatMap robot robots ++ map label robots
  where
    s      = vScale v
    robots = wsRobots ws
    ballR  = ballDiameter / 2 * s
    ball p = let (cx, cy) = toImg v p
             in [SDisc ballRimColour cx cy ballR, SDisc ballColour cx cy (ballR - max 1 (s / 60))]
    arena  = arenaOf (sceneBounds (vScene v)) (sceneWorld (vScene v))
    rayW   = max 1 (round (s / 60))
    rays
      | styleRays (vStyle v) =
          [ SLine rayColour rayW (toImg v (p .+^ vector2Polar robotRadius dir))
                                 (toImg v (p .+^ vector2Polar (robotRadius + d) dir))
          | (i, r) <- zip [0 :: Int ..] robots
          , let p = robotPos r
                others = [ robotPos o | (j, o) <- zip [0 ..] robots, j /= i ]
          , a <- [0, pi / 2, pi, -pi / 2]
          , let d   = rangeReading arena others p (robotHeading r) a
                dir = robotHeading r + a ]
      | otherwise = []
    rPx = robotRadius * s
    robot r =
      let (cx, cy) = toImg v (robotPos r)
          stuck    = robotStuck r
          rim      = max 1 (s / 30) * (if stuck then 2 else 1)
          hd       = robotHeading r
          (ux, uy) = (cos hd, negate (sin hd))
          (nx, ny) = (negate uy, ux)
          (bx, by) = (cx + 0.3 * rPx * ux, cy + 0.3 * rPx * uy)
          half     = 0.3 * rPx
      in [ SDisc (outlineColour (robotType r) stuck) cx cy rPx
         , SDisc (bodyColour (robotType r) stuck) cx cy (rPx - rim)
         , STri headingColour (cx + rPx * ux, cy + rPx * uy)
                (bx + half * nx, by + half * ny) (bx - half * nx, by - half * ny) ]
    k = max 1 (round (s / 30))
    label r =
      let (cx, cy) = toImg v (robotPos r)
      in SText labelColour k (floorInt (cx + 0.72 * rPx) + 1, floorInt (cy - 0.72 * rPx) - 5 * k)
               (show (robotId r))

floorInt :: Double -> Int
floorInt x
  | isNaN x   = 0
  | otherwise = floor (max (-1e7) (min 1e7 x))

------------------------------------------------------------------------------
-- PPM

-- | @renderPPM style scene trails ws@: the snapshot @ws@ as a whole binary
-- PPM file: the header @\"P6\\n\<w\> \<h\>\\n255\\n\"@ ('frameSize') and
-- then @3 * w * h@ bytes, the pixels' red, green and blue row by row from
-- the top-left. @trails@ holds each robot's path so far, one list per robot
-- in 'wsRobots' order, oldest point first; it is drawn only with
-- 'styleTrails'. See the module documentation for the shapes and colours.
renderPPM :: RenderStyle -> Scene -> [[Position2]] -> WorldState -> B.ByteString
renderPPM style scene trails ws = createPPM w h $ \c -> mapM_ (rasterise c (vMap v)) shapes
  where
    v      = viewOf style scene
    (w, h) = vSize v
    shapes = floorShapes v
          ++ (if styleTrails style then trailShapes v (wsRobots ws) trails else [])
          ++ staticShapes v
          ++ snapshotShapes v ws

rasterise :: Canvas -> ImageMap -> Shape -> IO ()
rasterise c im shape = case shape of
  SFill col               -> fillAll c col
  SRect col x0 y0 x1 y1   -> fillRect c col x0 y0 x1 y1
  SDisc col x y r         -> fillDisc c col x y r
  STri col a b q          -> fillTriangle c col a b q
  SLine col t a b         -> drawLine c col t a b
  SPolyline col t ps      -> drawPolyline c col t im ps
  SText col k at str      -> drawText c col k at str

------------------------------------------------------------------------------
-- SVG

-- | The most points of a trajectory in 'renderSVG': 2000. Longer ones are
-- thinned to evenly spaced snapshots, always keeping the first and last.
svgMaxPoints :: Int
svgMaxPoints = 2000

-- | @renderSVG style scene states@: one SVG picture of a run, @states@
-- being its snapshots in time order (e.g. 'AFrobRobotSim.simulate' cut to
-- length). The world is drawn as in 'renderPPM' at the /last/ snapshot
-- (rays with 'styleRays'; 'styleTrails' is ignored), with, below the balls
-- and robots, each robot's whole trajectory as one @\<polyline\>@ in its
-- 'typeColour' (at most 'svgMaxPoints' points) and a start marker at its
-- first position; a legend (colour, type and id of each robot) is to the
-- right of the world. The picture's coordinates are the frame's pixels
-- (see 'worldToPixel'); it is 170 pixels wider than a frame. The text
-- starts with @\"\<svg\"@ and ends with @\"\<\/svg\>\\n\"@. With no snapshots,
-- only the walls and blocks are drawn.
renderSVG :: RenderStyle -> Scene -> [WorldState] -> String
renderSVG style scene states = concat $
  [ printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n"
      totalW totalH totalW totalH
  , printf "<rect x=\"0\" y=\"0\" width=\"%d\" height=\"%d\" fill=\"%s\"/>\n" totalW totalH (hex backgroundColour) ]
  ++ map (svgShape v) (floorShapes v ++ staticShapes v)
  ++ [ svgShape v (SPolyline (typeColour (robotType r)) 2 (thin track))
     | ok, (r, track) <- zip robots0 tracks ]
  ++ [ svgShape v sh
     | ok, (r, p : _) <- zip robots0 tracks
     , let (x, y) = toImg v p
     , sh <- [SDisc (typeColour (robotType r)) x y 5, SDisc headingColour x y 3] ]
  ++ map (svgShape v) (maybe [] (snapshotShapes v) final)
  ++ legend
  ++ ["</svg>\n"]
  where
    v        = viewOf style scene
    ok       = validScale v
    (w, h)   = vSize v
    final    = if null states then Nothing else Just (last states)
    robots0  = case states of
      s0 : _ -> wsRobots s0
      []     -> []
    tracks   = transpose (map (map robotPos . wsRobots) states)
    legendW  = 170 :: Int
    rowH     = 18 :: Int
    totalW   = w + legendW
    totalH   = max h (40 + rowH * (length robots0 + 1))
    lx       = w + 12
    legend   =
      printf "<text x=\"%d\" y=\"%d\" font-family=\"sans-serif\" font-size=\"14\" font-weight=\"bold\" fill=\"%s\">Robots</text>\n"
        lx (24 :: Int) (hex labelColour)
      : concat
        [ [ printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"%s\" stroke-width=\"2\"/>\n"
              lx y (lx + 24) y (hex (typeColour (robotType r)))
          , printf "<circle cx=\"%d\" cy=\"%d\" r=\"6\" fill=\"%s\" stroke=\"%s\" stroke-width=\"1\"/>\n"
              (lx + 12) y (hex (typeColour (robotType r))) (hex (outlineColour (robotType r) False))
          , printf "<text x=\"%d\" y=\"%d\" font-family=\"sans-serif\" font-size=\"12\" fill=\"%s\">%s %d</text>\n"
              (lx + 32) (y + 4) (hex labelColour) (escape (robotType r)) (robotId r) ]
        | (n, r) <- zip [1 ..] robots0, let y = 24 + rowH * n ]
      ++ (let y = 24 + rowH * (length robots0 + 1) in
          [ printf "<circle cx=\"%d\" cy=\"%d\" r=\"4\" fill=\"%s\" stroke=\"%s\" stroke-width=\"2\"/>\n"
              (lx + 12) y (hex headingColour) (hex labelColour)
          , printf "<text x=\"%d\" y=\"%d\" font-family=\"sans-serif\" font-size=\"12\" fill=\"%s\">start</text>\n"
              (lx + 32) (y + 4) (hex labelColour) ])

-- At most svgMaxPoints evenly spaced elements, the first and last kept.
thin :: [a] -> [a]
thin xs
  | n <= svgMaxPoints = xs
  | otherwise         = every xs ++ [ last xs | (n - 1) `mod` step /= 0 ]
  where
    n    = length xs
    step = (n - 2) `div` (svgMaxPoints - 2) + 1
    every ys = case ys of
      []     -> []
      y : _  -> y : every (drop step ys)

-- One shape as an SVG element (the picture's size for 'SFill').
svgShape :: View -> Shape -> String
svgShape v shape = case shape of
  SFill col -> printf "<rect x=\"0\" y=\"0\" width=\"%d\" height=\"%d\" fill=\"%s\"/>\n" w h (hex col)
  SRect col x0 y0 x1 y1
    | allFinite [x0, y0, x1, y1] ->
        printf "<rect x=\"%s\" y=\"%s\" width=\"%s\" height=\"%s\" fill=\"%s\"/>\n"
          (num x0) (num y0) (num (x1 - x0)) (num (y1 - y0)) (hex col)
  SDisc col x y r
    | allFinite [x, y, r] && r > 0 ->
        printf "<circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"%s\"/>\n" (num x) (num y) (num r) (hex col)
  STri col a b q
    | all finitePt [a, b, q] ->
        printf "<polygon points=\"%s\" fill=\"%s\"/>\n" (unwords (map pt [a, b, q])) (hex col)
  SLine col t (x0, y0) (x1, y1)
    | allFinite [x0, y0, x1, y1] ->
        printf "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"%s\" stroke-width=\"%d\"/>\n"
          (num x0) (num y0) (num x1) (num y1) (hex col) t
  SPolyline col t ps ->
    printf "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"%d\" stroke-linejoin=\"round\" points=\"%s\"/>\n"
      (hex col) t (unwords (dedupe (map pt (filter finitePt (map (toImg v) ps)))))
  SText col k (x, y) str ->
    printf "<text x=\"%d\" y=\"%d\" font-family=\"monospace\" font-size=\"%d\" fill=\"%s\">%s</text>\n"
      x (y + 5 * k) (7 * k) (hex col) (escape str)
  _ -> ""
  where
    (w, h) = vSize v
    allFinite = all (\d -> not (isNaN d || isInfinite d))
    finitePt (x, y) = allFinite [x, y]
    pt (x, y) = num x ++ "," ++ num y

-- Drop the elements equal to the one before (a resting robot's points).
dedupe :: [String] -> [String]
dedupe (a : rest@(b : _)) | a == b = dedupe rest
dedupe (a : rest)                  = a : dedupe rest
dedupe []                          = []

num :: Double -> String
num = printf "%.1f"

hex :: Colour -> String
hex (Colour r g b) = printf "#%02x%02x%02x" r g b

escape :: String -> String
escape = concatMap esc
  where
    esc '<'  = "&lt;"
    esc '>'  = "&gt;"
    esc '&'  = "&amp;"
    esc '"'  = "&quot;"
    esc ch   = [ch]
