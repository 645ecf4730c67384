{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Shapes.Collision
-- Description : A moving disc against a box or a disc: swept contact,
--               static overlap, and the reflection of a velocity.
--
-- A sweep gives the fraction of a straight move at which a moving disc
-- first touches a static shape, and the contact normal there, exactly for
-- any length of move, so that nothing tunnels through a thin wall. A
-- penetration test gives how deep a disc is in a shape and the normal
-- along which to move it out; 'reflect' turns a velocity about such a
-- normal, for a ball that bounces. Part of "AFrobRobotSim.Shapes", which
-- re-exports all of it.
--
-- The sweeps and the penetration tests share their pieces: a candidate
-- contact (@Hit@), the entry of a moving point into a circle (a disc, or a
-- box's rounded corner) and the nearest way out of a box from inside it.
-- They are one module with those pieces, not several that import them:
-- imported, the pieces reached the kernels already optimised, and GHC
-- compiled their callers ("AFrobRobotSim.Physics",
-- "AFrobRobotSim.Balls") differently.
module AFrobRobotSim.Shapes.Collision
  ( -- * Swept (continuous) collision of a moving disc
    sweepCircleBox
  , sweepCircleCircle
    -- * Static overlap
  , circleBoxPenetration
  , circleCirclePenetration
    -- * Collision response
  , reflect
  ) where

import AFRP.Geometry (Point2 (..), Vector2 (..))
import AFrobRobotSim.FlatArray (finite)
import AFrobRobotSim.Shapes.Box (Box (..))
import AFrobRobotSim.Shapes.Ray (fmax, fmin)

------------------------------------------------------------------------------
-- Small strict helpers (all inlined)

-- | Clamp a value into a closed interval @[lo, hi]@ (with @lo <= hi@).
clamp :: Double -> Double -> Double -> Double
clamp lo hi x
  | x < lo    = lo
  | x > hi    = hi
  | otherwise = x
{-# INLINE clamp #-}

-- | A candidate contact of a sweep: fraction and unit normal. A fraction
-- above 1 means "no contact" (see @noHit@).
data Hit = Hit {-# UNPACK #-} !Double {-# UNPACK #-} !Double
               {-# UNPACK #-} !Double

noHit :: Hit
noHit = Hit 2 0 0
{-# INLINE noHit #-}

-- | The earlier of two candidate contacts (the first one on a tie).
earlier :: Hit -> Hit -> Hit
earlier h1@(Hit s1 _ _) h2@(Hit s2 _ _) = if s1 <= s2 then h1 else h2
{-# INLINE earlier #-}

-- | First time @s@ in @(0, 1]@ at which the moving point @p + s*d@ (with @p@
-- strictly outside the circle) enters the circle of centre @c@ and radius
-- @r@, with the outward unit normal there. Tangential (grazing) paths do not
-- enter and give 'noHit'.
--
-- A displacement so long that its squared length or the discriminant
-- overflows (beyond about 1e150 in world units: a step of 1e150 s and
-- more) is scaled down to its largest component first, and the fraction
-- scaled back: without that, the infinite or NaN discriminant read as a
-- miss, and a disc moved that far passed through the circle. Every other
-- displacement takes the unscaled path, bit for bit as before.
enterCircle :: Double -> Double -> Double -> Double
            -> Double -> Double -> Double -> Hit
enterCircle px py dx dy cx cy r
  | finite a && finite disc = enter 1 noHit dx dy b disc
  | not (finite k) || k == 0 = noHit   -- (a non-finite move)
  | otherwise =
      case enter k (Hit (1 / 0) 0 0) ex ey b' disc' of
        Hit s nx ny | s <= k    -> Hit (s / k) nx ny
                    | otherwise -> noHit
  where
    !mx   = px - cx
    !my   = py - cy
    !a    = dx * dx + dy * dy
    !b    = mx * dx + my * dy
    !c    = mx * mx + my * my - r * r
    !disc = b * b - a * c
    -- the scaled displacement, of largest component 1
    k     = max (abs dx) (abs dy)
    ex    = dx / k
    ey    = dy / k
    a'    = ex * ex + ey * ey
    b'    = mx * ex + my * ey
    disc' = b' * b' - a' * c
    -- the contact along @(ux, uy)@, at most @smax@ of it, or @miss@
    enter smax miss ux uy b0 disc0
      | b0 >= 0 || disc0 <= 0 = miss
      | s < 0 || s > smax     = miss
      | l > 0                 = Hit s (hx / l) (hy / l)
      | otherwise             = miss
      where
        -- (-b - sqrt disc) / a, in the cancellation-free form (b < 0 here).
        !s  = c / (sqrt disc0 - b0)
        !hx = mx + s * ux
        !hy = my + s * uy
        !l  = sqrt (hx * hx + hy * hy)
    {-# INLINE enter #-}
{-# INLINE enterCircle #-}

-- | Distance from a point inside the (closed) box to the nearest side, and
-- that side's outward normal. Ties are broken in the order left (-x), right
-- (+x), bottom (-y), top (+y).
insideExit :: Double -> Double -> Box -> Hit
insideExit px py (Box x0 y0 x1 y1) =
  earlier (earlier (Hit (px - x0) (-1) 0) (Hit (x1 - px) 1 0))
          (earlier (Hit (py - y0) 0 (-1)) (Hit (y1 - py) 0 1))
{-# INLINE insideExit #-}

------------------------------------------------------------------------------
-- Sweeps

-- | @sweepCircleBox p r d box@: continuous collision of a disc of centre @p@
-- and radius @r >= 0@ moving in a straight line by the displacement @d@ (from
-- @p@ to @p .+^ d@) against a static box.
--
-- Returns @'Just' (s, n)@ where @s@ in @[0, 1]@ is the fraction of the move
-- at which the disc first touches the box (its centre is then at
-- @p .+^ (s *^ d)@) and @n@ is the unit contact normal, pointing from the box
-- towards the disc's centre; 'Nothing' if the disc does not touch the box
-- during the move.
--
-- The test is exact (up to rounding) for any displacement length, so there
-- is no tunnelling through thin walls: the path of the centre is intersected
-- with the Minkowski sum of the box and the disc, a rounded rectangle made of
-- four straight sides (normals ±x, ±y) and four quarter circles of radius @r@
-- around the box corners (normal from the corner to the centre).
--
-- Edge cases:
--
-- * @d = 0@: 'Nothing'.
-- * The disc already touches or overlaps the box at @s = 0@: let @n@ be the
--   normal 'circleBoxPenetration' would use (for a centre inside the box:
--   towards the nearest side, ties broken left, right, bottom, top). The
--   result is @'Just' (0, n)@ if the move goes into the box (@d · n < 0@),
--   and 'Nothing' if it goes away or tangentially (@d · n >= 0@), so
--   that a robot pressed against a wall can back away or slide along it.
--   (Moving away never increases the penetration depth.)
-- * A path that only grazes the rounded rectangle (touches it tangentially,
--   e.g. sliding exactly along a side at distance @r@) does not enter it and
--   gives 'Nothing', consistently with the previous rule.
-- * @r = 0@ sweeps a point; the corners are then not rounded and a point
--   path through exactly a corner of the box may be reported as a miss.
sweepCircleBox :: Point2 Double -> Double -> Vector2 Double -> Box
               -> Maybe (Double, Vector2 Double)
sweepCircleBox (Point2 px py) r (Vector2 dx dy) box@(Box x0 y0 x1 y1)
  | dx == 0 && dy == 0 = Nothing
  | dist2 > r * r      = sweeping
  | otherwise          = initial
  where
    -- Closest point of the box to the centre.
    !ex    = px - clamp x0 x1 px
    !ey    = py - clamp y0 y1 py
    !dist2 = ex * ex + ey * ey

    -- Touching or overlapping at s = 0.
    initial
      | dist2 > 0 =
          let !dist = sqrt dist2
              !nx   = ex / dist
              !ny   = ey / dist
          in into nx ny
      | otherwise = case insideExit px py box of
          Hit _ nx ny -> into nx ny
    into nx ny
      | dx * nx + dy * ny < 0 = Just (0, Vector2 nx ny)
      | otherwise             = Nothing

    -- Strictly outside the rounded rectangle at s = 0.
    !qx = px + dx
    !qy = py + dy
    sweeping
      | fmax px qx < x0 - r || fmin px qx > x1 + r
        || fmax py qy < y0 - r || fmin py qy > y1 + r = Nothing
      | otherwise =
          case earlier (earlier sideX sideY) corners of
            Hit s nx ny
              | s <= 1    -> Just (s, Vector2 nx ny)
              | otherwise -> Nothing

    -- The straight side facing the motion along x (left side when moving
    -- right, right side when moving left), and likewise along y. The side
    -- is only tested if the centre starts on its outer side of the box
    -- (px <= x0 for the left side, ...); a crossing "in the past" (s < 0)
    -- then only arises from rounding for a centre that touches the side, and
    -- is clamped to 0.
    sideX
      | dx > 0 && px <= x0 = side (x0 - r - px) dx py dy y0 y1 (-1) 0
      | dx < 0 && px >= x1 = side (x1 + r - px) dx py dy y0 y1 1 0
      | otherwise          = noHit
    sideY
      | dy > 0 && py <= y0 = side (y0 - r - py) dy px dx x0 x1 0 (-1)
      | dy < 0 && py >= y1 = side (y1 + r - py) dy px dx x0 x1 0 1
      | otherwise          = noHit

    corners
      | r > 0 =
          earlier (earlier (enterCircle px py dx dy x0 y0 r)
                           (enterCircle px py dx dy x1 y0 r))
                  (earlier (enterCircle px py dx dy x0 y1 r)
                           (enterCircle px py dx dy x1 y1 r))
      | otherwise = noHit
{-# INLINE sweepCircleBox #-}

-- | Crossing of one straight side of the rounded rectangle: @gap@ is the
-- signed distance along the axis from the centre to the side's line, @da@
-- the displacement along that axis (non-zero, same sign as a forward
-- crossing), @u@ / @du@ the centre coordinate and displacement along the
-- other axis, @[u0, u1]@ the extent of the side, @(nx, ny)@ its normal.
side :: Double -> Double -> Double -> Double -> Double -> Double
     -> Double -> Double -> Hit
side gap da u du u0 u1 nx ny
  | s > 1            = noHit
  | w < u0 || w > u1 = noHit
  | otherwise        = Hit s nx ny
  where
    !s = fmax (gap / da) 0
    !w = u + s * du
{-# INLINE side #-}

-- | @sweepCircleCircle p r d q rq@: continuous collision of a disc of centre
-- @p@ and radius @r@ moving by the displacement @d@ against a static disc of
-- centre @q@ and radius @rq@ (both radii @>= 0@).
--
-- Same contract as 'sweepCircleBox': @'Just' (s, n)@ with the first contact
-- fraction @s@ in @[0, 1]@ and the unit normal @n@ from @q@ towards the
-- moving centre at contact, or 'Nothing'. Exact for any displacement length
-- (the centre's path is intersected with the circle of radius @r + rq@
-- around @q@). @d = 0@ gives 'Nothing'; discs already touching or
-- overlapping give @'Just' (0, n)@ if @d · n < 0@ and 'Nothing'
-- otherwise, where @n@ is the 'circleCirclePenetration' normal (@+x@ for
-- coincident centres); tangential grazing is not a contact.
sweepCircleCircle :: Point2 Double -> Double -> Vector2 Double
                  -> Point2 Double -> Double
                  -> Maybe (Double, Vector2 Double)
sweepCircleCircle (Point2 px py) r (Vector2 dx dy) (Point2 cx cy) rq
  | dx == 0 && dy == 0 = Nothing
  | c > 0 = case enterCircle px py dx dy cx cy rr of
      Hit s nx ny
        | s <= 1    -> Just (s, Vector2 nx ny)
        | otherwise -> Nothing
  | otherwise =
      let !dist = sqrt (mx * mx + my * my)
          !nx   = if dist > 0 then mx / dist else 1
          !ny   = if dist > 0 then my / dist else 0
      in if dx * nx + dy * ny < 0 then Just (0, Vector2 nx ny) else Nothing
  where
    !rr = r + rq
    !mx = px - cx
    !my = py - cy
    -- Same expression as in 'enterCircle', so both agree on "outside".
    !c  = mx * mx + my * my - rr * rr
{-# INLINE sweepCircleCircle #-}

------------------------------------------------------------------------------
-- Penetration

-- | @circleBoxPenetration p r box@: if the disc of centre @p@ and radius @r@
-- overlaps the box, @'Just' (depth, n)@ with @depth > 0@ and @n@ the unit
-- normal along which to move the disc by @depth@ to separate it (so that it
-- just touches); 'Nothing' if they do not overlap (merely touching is not an
-- overlap).
--
-- * Centre outside the box: @n@ points from the nearest point of the box to
--   the centre, and @depth = r - distance@.
-- * Centre inside the box or on its boundary: @n@ is the outward normal of
--   the nearest side (the shortest way out; ties broken left, right, bottom,
--   top) and @depth = r + distance to that side@. So @r = 0@ with the point
--   on the boundary gives 'Nothing'.
circleBoxPenetration :: Point2 Double -> Double -> Box
                     -> Maybe (Double, Vector2 Double)
circleBoxPenetration (Point2 px py) r box@(Box x0 y0 x1 y1)
  | dist2 >= r * r, dist2 > 0 = Nothing
  | dist2 > 0 =
      let !dist  = sqrt dist2
          !depth = r - dist
      in if depth > 0
           then Just (depth, Vector2 (ex / dist) (ey / dist))
           else Nothing
  | otherwise = case insideExit px py box of
      Hit e nx ny ->
        let !depth = r + e
        in if depth > 0 then Just (depth, Vector2 nx ny) else Nothing
  where
    !ex    = px - clamp x0 x1 px
    !ey    = py - clamp y0 y1 py
    !dist2 = ex * ex + ey * ey
{-# INLINE circleBoxPenetration #-}

-- | @circleCirclePenetration p rp q rq@: if the discs @(p, rp)@ and
-- @(q, rq)@ overlap, @'Just' (depth, n)@ with @depth = rp + rq - |p - q| > 0@
-- and @n@ the unit normal from @q@ towards @p@ (the direction in which to
-- push the first disc out of the second). For coincident centres the normal
-- is the fixed vector @+x@ (@Vector2 1 0@). 'Nothing' if the discs do not
-- overlap (merely touching is not an overlap).
circleCirclePenetration :: Point2 Double -> Double -> Point2 Double -> Double
                        -> Maybe (Double, Vector2 Double)
circleCirclePenetration (Point2 px py) rp (Point2 qx qy) rq
  | dist2 >= rr * rr = Nothing
  | depth <= 0       = Nothing
  | dist > 0         = Just (depth, Vector2 (mx / dist) (my / dist))
  | otherwise        = Just (depth, Vector2 1 0)
  where
    !rr    = rp + rq
    !mx    = px - qx
    !my    = py - qy
    !dist2 = mx * mx + my * my
    dist   = sqrt dist2
    depth  = rr - dist
{-# INLINE circleCirclePenetration #-}

------------------------------------------------------------------------------
-- Response

-- | @reflect v n@ reflects the velocity @v@ about the plane with unit normal
-- @n@: @v - 2 (v·n) n@. The component along @n@ is reversed and the
-- tangential one kept, so the speed is preserved and reflecting twice gives
-- back @v@ (up to rounding). @n@ must be a unit vector (its sign does not
-- matter).
reflect :: Vector2 Double -> Vector2 Double -> Vector2 Double
reflect (Vector2 vx vy) (Vector2 nx ny) = Vector2 (vx - k * nx) (vy - k * ny)
  where
    !k = 2 * (vx * nx + vy * ny)
{-# INLINE reflect #-}
