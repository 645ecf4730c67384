-- |
-- Module      : AFrobRobotSim.Render.SVG
-- Description : An SVG picture of a whole run.
--
-- The second back end of "AFrobRobotSim.Render": the shapes of
-- "AFrobRobotSim.Render.Scene" as SVG elements, with each robot's
-- trajectory, its start and a legend.
module AFrobRobotSim.Render.SVG
  ( renderSVG
  , svgOf
  , svgMaxPoints
  ) where

import           Data.List                  (transpose)
import           Text.Printf                (printf)

import           AFrobRobotSim.Render.Raster
import           AFrobRobotSim.Render.Scene
import           AFrobRobotSim.Simulator    (RobotState (..), WorldState (..))
import           AFrobRobotSim.World        (simbotDiameter)
import           AFrob.Dimensions           (Position2)

-- | The most points of a trajectory in 'renderSVG': 2000. Longer ones are
-- thinned to evenly spaced snapshots, always keeping the first and last.
svgMaxPoints :: Int
svgMaxPoints = 2000

-- | @renderSVG style scene states@: one SVG picture of a run, @states@
-- being its snapshots in time order (e.g. 'AFrobRobotSim.simulate' cut to
-- length). The world is drawn as in 'AFrobRobotSim.Render.renderPPM' at
-- the /last/ snapshot (rays with 'styleRays'; 'styleTrails' is ignored),
-- with, below the balls
-- and robots, each robot's whole trajectory as one @\<polyline\>@ in its
-- 'typeColour' (at most 'svgMaxPoints' points) and a start marker at its
-- first position (a disc of radius 5 pixels, or a robot's radius where
-- that is smaller, but at least 2); a legend (colour, type and id of each robot) is to the
-- right of the world. The legend lists as many robots as fit beside the
-- world (at least 10), then how many more there are, so that a picture of
-- many robots is no taller than its frame. The picture's coordinates are the frame's pixels
-- (see 'worldToPixel'); it is 170 pixels wider than a frame. The text
-- starts with @\"\<svg\"@ and ends with @\"\<\/svg\>\\n\"@. With no snapshots,
-- only the walls and blocks are drawn.
renderSVG :: RenderStyle -> Scene -> [WorldState] -> String
renderSVG style scene states = case states of
  []     -> svgOf style scene Nothing [] []
  s0 : _ -> svgOf style scene (Just (s0, last states)) tracks [ p | p : _ <- tracks ]
  where
    tracks = transpose (map (map robotPos . wsRobots) states)

-- | 'renderSVG' given the first and the last snapshots (none for a run
-- with none), each robot's track (in the order of the first snapshot's
-- robots, each at most 'svgMaxPoints' points once thinned) and each
-- one's start: for a writer that keeps a long run's tracks more compactly
-- than as snapshots, and makes each track only as it is drawn (the
-- tracks are read once, in order; the starts after them).
svgOf :: RenderStyle -> Scene -> Maybe (WorldState, WorldState) -> [[Position2]] -> [Position2] -> String
svgOf style scene ends tracks starts = concat $
  [ printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n"
      totalW totalH totalW totalH
  , printf "<rect x=\"0\" y=\"0\" width=\"%d\" height=\"%d\" fill=\"%s\"/>\n" totalW totalH (hex backgroundColour) ]
  ++ map (svgShape v) (floorShapes v ++ staticShapes v)
  ++ [ svgShape v (SPolyline col 2 (thin track))
     | ok, (col, track) <- zip colours0 tracks ]
  ++ [ svgShape v sh
     | ok, (col, p) <- zip colours0 starts
     , let (x, y) = toImg v p
     , sh <- [SDisc col x y startR, SDisc headingColour x y (0.6 * startR)] ]
  ++ map (svgShape v) (maybe [] (snapshotShapes v . snd) ends)
  ++ legend
  ++ ["</svg>\n"]
  where
    v        = viewOf style scene
    -- a start marker's radius: 5 pixels, or a robot's radius where that is
    -- smaller (big worlds), at least 2
    startR   = min 5 (max 2 (vScale v * simbotDiameter / 2))
    ok       = validScale v
    (w, h)   = vSize v
    robots0  = maybe [] (wsRobots . fst) ends
    colours0 = [ robotColour (robotType r) k | (r, k) <- zip robots0 (typeRanks robots0) ]
    legendW  = 170 :: Int
    rowH     = 18 :: Int
    totalW   = w + legendW
    nRobots  = length robots0
    listed   = if nRobots <= fits then nRobots else fits - 1
    fits     = max 10 ((h - 40) `div` rowH - 1)
    rows     = if listed < nRobots then listed + 1 else listed
    totalH   = max h (40 + rowH * (rows + 1))
    lx       = w + 12
    legend   =
      printf "<text x=\"%d\" y=\"%d\" font-family=\"sans-serif\" font-size=\"14\" font-weight=\"bold\" fill=\"%s\">Robots</text>\n"
        lx (24 :: Int) (hex labelColour)
      : concat
        [ [ printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"%s\" stroke-width=\"2\"/>\n"
              lx y (lx + 24) y (hex col)
          , printf "<circle cx=\"%d\" cy=\"%d\" r=\"6\" fill=\"%s\" stroke=\"%s\" stroke-width=\"1\"/>\n"
              (lx + 12) y (hex col) (hex (darken 0.5 col))
          , printf "<text x=\"%d\" y=\"%d\" font-family=\"sans-serif\" font-size=\"12\" fill=\"%s\">%s %d</text>\n"
              (lx + 32) (y + 4) (hex labelColour) (escape (robotType r)) (robotId r) ]
        | (n, r, col) <- take listed (zip3 [1 ..] robots0 colours0), let y = 24 + rowH * n ]
      ++ [ printf "<text x=\"%d\" y=\"%d\" font-family=\"sans-serif\" font-size=\"12\" fill=\"%s\">... and %d more</text>\n"
             (lx + 32) (24 + rowH * rows + 4) (hex labelColour) (nRobots - listed)
         | listed < nRobots ]
      ++ (let y = 24 + rowH * (rows + 1) in
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
