{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.RayCast
-- Description : The static boxes near a short segment, and the nearest one
--               a ray meets, from the ray grid.
--
-- The range finder's rays are short, and the obstacles never move: the
-- 'BoxIndex' of an arena keeps, for every place and quarter of
-- directions, the boxes a segment of up to 'AFrobRobotSim.RayGrid.rayGridReach' from there can
-- come near ("AFrobRobotSim.RayGrid"). A ray reads one such list instead
-- of walking the grid cells its bounding box covers and looking at
-- everything listed there (on the 10-robot benchmark, where the world's
-- boundary walls are listed in every border cell, that walk was most of
-- a ray's cost). A segment the ray grid does not answer for (too long,
-- starting outside the boxes' bounding box, or not finite) is answered by
-- 'foldBoxesIn'.
module AFrobRobotSim.RayCast
  ( foldBoxesAlong
  , rayCastBoxes
  ) where

import           AFRP.Geometry              (Point2 (..), Vector2 (..))
import           AFrobRobotSim.FlatArray    (indexI)
import           AFrobRobotSim.RayGrid      (rayGridLineItem, rayGridList, rayGridLookup,
                                             rayGridTolerance)
import           AFrobRobotSim.Shapes       (Box (..), rayBox)
import           AFrobRobotSim.SpatialIndex

-- | @foldBoxesAlong bi px py qx qy f z@ folds @f@ (strictly) over the boxes
-- near the segment from @(px, py)@ to @(qx, qy)@, giving it the box's
-- position in the original list and the box: every box that comes within
-- 'rayGridTolerance' (1 mm) of the segment, and perhaps others that meet
-- the segment's bounding rectangle widened by that much; boxes with
-- non-finite coordinates are always visited.
--
-- A segment that starts within the boxes' bounding box and is at most
-- 'AFrobRobotSim.RayGrid.rayGridReach' (3.3 m) long, such as a range finder's ray, reads one
-- list of the ray grid, where every box is at most once; any other is
-- 'foldBoxesIn' over the widened rectangle (so a segment that is not
-- finite visits every box).
foldBoxesAlong :: BoxIndex -> Double -> Double -> Double -> Double
               -> (a -> Int -> Box -> a) -> a -> a
foldBoxesAlong bi px py qx qy f z0 =
  rayGridList (boxIndexRays bi) px py qx qy
    (\items s e -> let !x0 = min px qx - rayGridTolerance
                       !y0 = min py qy - rayGridTolerance
                       !x1 = max px qx + rayGridTolerance
                       !y1 = max py qy + rayGridTolerance
                   in go items x0 y0 x1 y1 s e z0)
    (foldBoxesIn bi (min px qx - rayGridTolerance) (min py qy - rayGridTolerance)
                    (max px qx + rayGridTolerance) (max py qy + rayGridTolerance) f z0)
  where
    -- one loop of tail calls over the list (the bounds strict: lazily
    -- shared, they were allocated as thunks on every query), then the
    -- wild boxes
    go items !x0 !y0 !x1 !y1 !k !e !z
      | k >= e    = wild (boxIndexWild bi) z
      | otherwise =
          let i = indexI items k
              box@(Box a b c d) = boxAt bi i
          in -- only the boxes that meet the widened rectangle (the list
             -- holds everything near the cell, in the segment's quadrant)
             if a <= x1 && c >= x0 && b <= y1 && d >= y0
               then go items x0 y0 x1 y1 (k + 1) e (f z i box)
               else go items x0 y0 x1 y1 (k + 1) e z
    wild [] !z       = z
    wild (i : is) !z = wild is (f z i (boxAt bi i))
{-# INLINE foldBoxesAlong #-}

-- | @rayCastBoxes bi px py ux uy len@: the nearest hit of the ray from
-- @(px, py)@ in the direction @(ux, uy)@ (a unit vector) on a box within
-- @len@, as 'rayBox' has it, or @len@ if there is none nearer; that is,
--
-- @
-- foldBoxesAlong bi px py (px + len * ux) (py + len * uy)
--   (\\m _ b -> maybe m (\\t -> min t m) (rayBox (Point2 px py) (Vector2 ux uy) b)) len
-- @
--
-- which is the same for every box as for the boxes near the segment (a
-- hit within the length is on it, up to rounding far below the fold's
-- 1 mm). Written as one strict loop: the range finder casts up to four of
-- these per robot and step, and the general fold's closures and lazily
-- boxed bounds cost more than the one or two boxes a ray tests.
rayCastBoxes :: BoxIndex -> Double -> Double -> Double -> Double -> Double -> Double
rayCastBoxes bi !px !py !ux !uy !len =
  rayGridLookup (boxIndexRays bi) px py qx qy
    (\ls w s e -> wild (boxIndexWild bi) (goLine ls w s e len))
    (\items s e -> wild (boxIndexWild bi) (go items s e len))
    (rayCastBoxesIn bi x0 y0 x1 y1 px py ux uy len)
  where
    !qx = px + len * ux
    !qy = py + len * uy
    !x0 = min px qx - rayGridTolerance
    !y0 = min py qy - rayGridTolerance
    !x1 = max px qx + rayGridTolerance
    !y1 = max py qy + rayGridTolerance
    go items !k !e !m
      | k >= e    = m
      | otherwise =
          let box@(Box a b c d) = boxAt bi (indexI items k)
          in if a <= x1 && c >= x0 && b <= y1 && d >= y0
               then go items (k + 1) e (hitBox px py ux uy m box)
               else go items (k + 1) e m
    -- the same over a list held in its cell's line
    goLine ls !w !k !e !m
      | k >= e    = m
      | otherwise =
          let box@(Box a b c d) = boxAt bi (rayGridLineItem ls w k)
          in if a <= x1 && c >= x0 && b <= y1 && d >= y0
               then goLine ls w (k + 1) e (hitBox px py ux uy m box)
               else goLine ls w (k + 1) e m
    wild [] !m       = m
    wild (i : is) !m = wild is (hitBox px py ux uy m (boxAt bi i))
{-# INLINE rayCastBoxes #-}

-- The nearest hit within @len@ of the ray on the boxes that meet the
-- rectangle, the other way of 'rayCastBoxes' (a segment the ray grid does
-- not answer for). Not inlined: taken for almost no ray, but inlined into
-- every ray cast it made the common path read and keep the box index's
-- grid and bounds, and save a dozen more values across every evaluation.
rayCastBoxesIn :: BoxIndex -> Double -> Double -> Double -> Double
               -> Double -> Double -> Double -> Double -> Double -> Double
rayCastBoxesIn bi x0 y0 x1 y1 px py ux uy len =
  foldBoxesIn bi x0 y0 x1 y1 (\m _ b -> hitBox px py ux uy m b) len
{-# NOINLINE rayCastBoxesIn #-}

-- The nearer of @m@ and the ray's hit on a box. Not inlined: a ray tests
-- about one box, and inlined into 'rayCastBoxes' the tests for a zero
-- direction component were floated out of the loop as lazily shared
-- thunks, allocated and evaluated (with an update) on every ray.
hitBox :: Double -> Double -> Double -> Double -> Double -> Box -> Double
hitBox px py ux uy m b = case rayBox (Point2 px py) (Vector2 ux uy) b of
  Just t  -> min t m
  Nothing -> m
{-# NOINLINE hitBox #-}
