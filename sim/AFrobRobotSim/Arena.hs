{-# LANGUAGE PatternSynonyms #-}
-- |
-- Module      : AFrobRobotSim.Arena
-- Description : The static part of a world: walls, blocks and the boundary,
--               as boxes, with what is computed once about them.
--
-- The obstacles never move, so everything the physics and the sensors ask
-- of them is prepared once per run, each part the first time it is
-- needed: the boxes on a grid ("AFrobRobotSim.SpatialIndex", with the ray
-- lists of "AFrobRobotSim.RayGrid" inside it), their extent (over which
-- the moving objects are indexed at every step, see 'pointsOver') and
-- their clearance ("AFrobRobotSim.Clearance").
module AFrobRobotSim.Arena
  ( Arena (Arena, arenaBoxes)
  , arenaOf
  , arenaIndex
  , arenaClearance
  , pointsOver
  , pointsOverOn
  ) where

import           AFrobRobotSim.Clearance
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World

-- | The static part of a world: its obstacles, the boundary included, and
-- (computed when first needed) their grid index, their extent and their
-- clearance. @Arena boxes@ builds one and matches one, as if it were a
-- plain record of 'arenaBoxes'.
data Arena = MkArena [Box] BoxIndex (Double, Double, Double, Double) Clearance
  -- the boxes, their index, their bounding box and their clearance (all
  -- lazy)

-- | The arena's boxes on a grid.
arenaIndex :: Arena -> BoxIndex
arenaIndex (MkArena _ bi _ _) = bi

-- | The bounding box of the arena's boxes (the boundary included): min x,
-- min y, max x, max y.
arenaExtent :: Arena -> (Double, Double, Double, Double)
arenaExtent (MkArena _ _ e _) = e

-- | The clearance of the arena's boxes (see "AFrobRobotSim.Clearance").
arenaClearance :: Arena -> Clearance
arenaClearance (MkArena _ _ _ cl) = cl

-- | The arena of a list of boxes.
pattern Arena :: [Box] -> Arena
pattern Arena { arenaBoxes } <- MkArena arenaBoxes _ _ _
  where Arena bs = let bi = boxIndex bs
                       e  = boxesExtent bs
                   in MkArena bs bi e (clearanceOf bi e)
{-# COMPLETE Arena #-}

-- | The arena of a world: its walls and blocks, and four thick boxes just
-- outside its bounds (the template's 'OTSize' if it has one, else the
-- bounds given: 'worldBoundsOr').
arenaOf :: Bounds -> WorldTemplate -> Arena
arenaOf bounds world = Arena (map boxOf (filter isStatic world) ++ boundaryBoxes (worldBoundsOr bounds world))

isStatic :: ObjectTemplate -> Bool
isStatic o = case o of
  OTBlock {} -> True
  OTVWall {} -> True
  OTHWall {} -> True
  _          -> False

boxOf :: ObjectTemplate -> Box
boxOf o = let (hw, hh) = objectHalfSize o in boxAround (otPos o) (2 * hw) (2 * hh)

-- The boundary: four thick boxes just outside the world.
boundaryBoxes :: Bounds -> [Box]
boundaryBoxes (Bounds x0 y0 x1 y1) =
  [ Box (x0 - 1) (y0 - 1) x0 (y1 + 1), Box x1 (y0 - 1) (x1 + 1) (y1 + 1)
  , Box (x0 - 1) (y0 - 1) (x1 + 1) y0, Box (x0 - 1) y1 (x1 + 1) (y1 + 1) ]

-- | Points on a grid over the arena (its boxes' bounding box).
pointsOver :: Arena -> [(Double, Double)] -> PointIndex
pointsOver = pointsOverOn fst snd

-- | @pointsOverOn px py@: 'pointsOver' of the points @(px e, py e)@ of the
-- elements @e@ of a list ('pointIndexOn').
pointsOverOn :: (e -> Double) -> (e -> Double) -> Arena -> [e] -> PointIndex
pointsOverOn px py arena es = case arenaExtent arena of
  (x0, y0, x1, y1) -> pointIndexOn px py x0 y0 x1 y1 es
{-# INLINE pointsOverOn #-}

boxesExtent :: [Box] -> (Double, Double, Double, Double)
boxesExtent [] = (0, 0, 0, 0)
boxesExtent (b : bs) = foldr grow (boxMinX b, boxMinY b, boxMaxX b, boxMaxY b) bs
  where grow (Box a c d e) (x0, y0, x1, y1) = (min a x0, min c y0, max d x1, max e y1)
