-- |
-- Module      : AFrobRobotSim.Shapes
-- Description : Collision and ray-casting kernels of the robot simulator.
--
-- Pure, strict geometric kernels used by the simulator at every step for
-- every robot: ray casts for the range sensors, swept (continuous) collision
-- tests for moving discs, static overlap (penetration) tests and the
-- reflection of a velocity about a contact normal.
--
-- Everything is monomorphic in 'Double', strict, works on the unpacked
-- components of 'AFRP.Geometry.Point2' \/ 'AFRP.Geometry.Vector2' and
-- builds no intermediate lists; the only allocation is the 'Maybe' result.
-- All exported functions are @INLINE@, so a caller that immediately
-- scrutinises the result usually allocates nothing at all.
--
-- = Conventions
--
-- * The world frame is the usual mathematical one (x to the right, y up),
--   lengths in metres, but nothing here depends on the units.
-- * A 'Box' is /closed/: its boundary belongs to it. So does the boundary of
--   a disc. Two shapes whose boundaries merely touch are /in contact/ but do
--   not /overlap/ (penetration depth 0 is reported as no penetration).
-- * Radii are expected to be @>= 0@; a radius of 0 turns a disc into a
--   point. A 'Box' is expected to satisfy @boxMinX <= boxMaxX@ and
--   @boxMinY <= boxMaxY@ ('boxAround' always builds such a box); results for
--   other boxes are unspecified.
-- * Normals are unit vectors pointing /out of the obstacle/, towards the
--   moving (or first) shape.
-- * A contact or hit time returned as 0 is always the positive zero
--   @0.0@, never @-0.0@.
--
-- = Modules
--
-- This module gathers the kernels, and has no code of its own:
-- "AFrobRobotSim.Shapes.Box" (the box), "AFrobRobotSim.Shapes.Ray" (ray
-- casting) and "AFrobRobotSim.Shapes.Collision" (a moving disc's sweeps,
-- static overlap and the response). The helpers a module's kernels share
-- stay in that module: imported from a module of their own, they changed
-- the code GHC made of the simulator's step (see the two modules). The
-- exception is 'AFrobRobotSim.Shapes.Ray.fmax' and
-- 'AFrobRobotSim.Shapes.Ray.fmin', which both modules use: they stay in
-- "AFrobRobotSim.Shapes.Ray", beside the slab method, and
-- "AFrobRobotSim.Shapes.Collision" imports them from there (not
-- re-exported here).
module AFrobRobotSim.Shapes
  ( -- * Axis-aligned boxes
    Box (..)
  , boxAround
  , boxCentre
    -- * Ray casting
  , rayBox
  , rayCircle
    -- * Swept (continuous) collision of a moving disc
  , sweepCircleBox
  , sweepCircleCircle
    -- * Static overlap
  , circleBoxPenetration
  , circleCirclePenetration
    -- * Collision response
  , reflect
  ) where

import AFrobRobotSim.Shapes.Box
import AFrobRobotSim.Shapes.Collision
import AFrobRobotSim.Shapes.Ray
