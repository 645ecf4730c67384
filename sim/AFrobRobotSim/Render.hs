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
--                (styleRays only), ending in a dot of         dot: the robot's colour
--                scale \/ 30 pixels radius (at least 2)
-- robot body     disc 0.5 m across                            the robot's colour: the first
--                                                             of a type SimbotA (30, 90, 220)
--                                                             #1e5adc, SimbotB (215, 40, 40)
--                                                             #d72828, other (140, 60, 170)
--                                                             #8c3caa; the next five of a
--                                                             type in other shades of its
--                                                             family ('robotColour')
-- robot rim      scale \/ 30 pixels wide (2 px at 60 px\/m)     body colour at half brightness
-- stuck robot    rim twice as wide, body at 60 % brightness   rim (0, 0, 0)    #000000
-- heading mark   wedge from 0.3 of the radius to the edge,    (255, 255, 255)  #ffffff
--                pointing along the heading
-- robot id       3x5 pixel digits, magnified round(scale\/30)  (20, 20, 20)     #141414
--                times, just above and right of the body
--                (left of it, below it near the world's
--                edge; always inside the world)
-- time           simulated seconds, two decimals, digits as   (20, 20, 20)     #141414
--                the ids, in the world's top-left corner      on (255, 255, 255)
-- @
--
-- The SVG picture uses the same shapes and colours, and adds each robot's
-- trajectory (2 pixels wide, in its body colour), a start marker (a white
-- disc ringed in the body colour) and a legend to the right of the world.
--
-- = Modules
--
-- This module draws PPM frames and gathers the rest: the scene, its
-- colours and the shapes it is drawn as are in
-- "AFrobRobotSim.Render.Scene", the SVG writer in
-- "AFrobRobotSim.Render.SVG", the rasteriser in
-- "AFrobRobotSim.Render.Raster".
module AFrobRobotSim.Render
  ( -- * Scenes and styles
    Scene (..)
  , RenderStyle (..)
  , defaultRenderStyle
  , sceneExtent
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
  ) where

import qualified Data.ByteString            as B

import           AFrob.Dimensions           (Position2)
import           AFrobRobotSim.Render.Raster
import           AFrobRobotSim.Render.Scene
import           AFrobRobotSim.Render.SVG
import           AFrobRobotSim.Simulator    (WorldState (..))

------------------------------------------------------------------------------
-- PPM

-- | @renderPPM style scene trails ws@: the snapshot @ws@ as a whole binary
-- PPM file: the header @\"P6\\n\<w\> \<h\>\\n255\\n\"@ ('frameSize') and
-- then @3 * w * h@ bytes, the pixels' red, green and blue row by row from
-- the top-left. @trails@ holds each robot's path so far, one list per robot
-- in 'wsRobots' order, oldest point first; it is drawn only with
-- 'styleTrails'. See the module documentation for the shapes and colours.
--
-- @renderPPM style scene@, applied once and used for every frame of a run,
-- prepares what the frames share (the view, and the static world the rays
-- are cast against) once.
renderPPM :: RenderStyle -> Scene -> [[Position2]] -> WorldState -> B.ByteString
renderPPM style scene = \trails ws ->
  let shapes = floorShapes v
            ++ (if styleTrails style then trailShapes v (wsRobots ws) trails else [])
            ++ staticShapes v
            ++ snapshotShapes v ws
  in createPPM w h $ \c -> mapM_ (rasterise c (vMap v)) shapes
  where
    v      = viewOf style scene
    (w, h) = vSize v

-- One shape drawn on the canvas.
rasterise :: Canvas -> ImageMap -> Shape -> IO ()
rasterise c im shape = case shape of
  SFill col               -> fillAll c col
  SRect col x0 y0 x1 y1   -> fillRect c col x0 y0 x1 y1
  SDisc col x y r         -> fillDisc c col x y r
  STri col a b q          -> fillTriangle c col a b q
  SLine col t a b         -> drawLine c col t a b
  SPolyline col t ps      -> drawPolyline c col t im ps
  SText col k at str      -> drawText c col k at str
