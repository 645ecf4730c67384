{-# LANGUAGE Arrows #-}
-- |
-- Module      : Exercises.Ex14
-- Description : Exercise 14: two simbots whose paths braid like a rope.
--
-- /Exercise 14./ Write a program for two simbots that are traveling in a
-- straight path, except that their paths continually interleave each
-- other, as in a braid of rope.
--
-- Following the hint, velocities are vectors. Two robots that circle their
-- midpoint @m@ at the angular rate @omega@ while keeping the distance @d@
-- each have the circling velocity @omega * perp (p - m)@ (@perp@ turns a
-- vector a quarter turn counter-clockwise), of speed @omega * d / 2@, and
-- the two are opposite, so the midpoint stays put. Adding the common
-- forward velocity @vf * u@ moves the midpoint along the straight line
-- @u@ while the robots keep circling it: each robot's path is a trochoid,
-- and the two trochoids cross twice per turn, a braid.
--
-- Each robot finds the other with the animate object tracker (the
-- partner's vector @l = p' - p@ is its distance in the direction of the
-- tracked angle plus the robot's own heading), so the midpoint is
-- @p + l / 2@. Two feedback terms keep the braid in shape: a radial term
-- that closes or opens the gap towards @d@, and a lane term that pulls the
-- midpoint back onto the line. The forward speed fades out over the last
-- metre; the pair then keeps circling on the spot.
--
-- The desired velocity vector is followed with 'rcVelocityAux', this
-- module's version of the notes' @rcHeadingAux@: the heading error is fed
-- back proportionally, the turning of the vector itself is fed forward, and
-- the speed is cut while the robot is still facing the wrong way.
--
-- The forward speed must exceed the circling speed (@vf > omega d / 2@), or
-- the paths grow loops and the robots drive backwards part of each turn.
module Exercises.Ex14
  ( -- * The example
    examples
    -- * The braid
  , Braid (..)
  , notesBraid
  , braidWorld
  , rcBraid
  , braidVelocity
    -- * Following a velocity vector
  , rcVelocityAux
  ) where

import           Data.List     (sortOn)

import           AFrob         hiding (forAll)
import           AFrobRobotSim

import           Examples.Types

-- | The shape of a braid.
data Braid = Braid
  { brStart      :: Position2  -- ^ where the pair's midpoint starts
  , brHeading    :: Heading    -- ^ the direction of travel
  , brLength     :: Distance   -- ^ how far the midpoint travels
  , brSeparation :: Distance   -- ^ the distance kept between the robots' centres
  , brSpeed      :: Velocity   -- ^ the common forward speed
  , brSpin       :: RotVel     -- ^ the angular rate at which the pair circles (counter-clockwise)
  } deriving (Eq, Show)

-- | Along the long diagonal of the world, from (-3.6, -3.6) for 10 m, 1 m
-- apart, at 0.5 m/s forward, circling at 0.8 rad/s (a circling speed of
-- 0.4 m/s): one turn every 7.9 s, about 2.5 turns, 5 crossings.
notesBraid :: Braid
notesBraid = Braid
  { brStart = Point2 (-3.6) (-3.6), brHeading = pi / 4, brLength = 10
  , brSeparation = 1, brSpeed = 0.5, brSpin = 0.8 }

-- | The two simbots (both 'SimbotB', ids 1 and 2) side by side across the
-- start of the braid, facing along it.
braidWorld :: Braid -> WorldTemplate
braidWorld b =
  [ OTSimbotB i (brStart b .+^ (s * brSeparation b / 2) *^ across b) (brHeading b)
  | (i, s) <- [(1, 1), (2, -1)] ]

-- | The controller of both braiding robots: follow 'braidVelocity'.
rcBraid :: Braid -> SimbotController
rcBraid b rps = proc sbi -> rcVelocityAux rps -< (sbi, braidVelocity b rps sbi)

-- | The velocity a braiding robot wants now: forward along the braid plus
-- circling the midpoint of itself and its partner (the nearest other robot
-- of its own type), with the radial and lane corrections. With no partner
-- in sight it just travels along the line.
braidVelocity :: Braid -> SimbotProperties -> SimbotInput -> Velocity2
braidVelocity b rps sbi = forward ^+^ pairTerms
  where
    p = odometryPosition sbi
    u = along b
    -- (the tracker lists the robots in no particular order: nearest first)
    partners = [ vector2Polar d (odometryHeading sbi + a)
               | (ty, _, a, d) <- sortOn (\(_, _, _, d') -> d') (aotOtherRobots sbi), ty == rpType rps ]
    (mid, pairTerms) = case partners of
      l : _ ->
        let gap      = norm l
            circling = brSpin b *^ perp ((-0.5) *^ l)
            radial   = (kRadial * (gap - brSeparation b) / (2 * max gap 1e-6)) *^ l
        in (p .+^ (0.5 *^ l), circling ^+^ radial ^+^ lane (p .+^ (0.5 *^ l)))
      [] -> (p, lane p)
    progress = (mid .-. brStart b) `dot` u
    forward  = (brSpeed b * max 0 (min 1 (brLength b - progress))) *^ u
    lane q   = (negate kLane * ((q .-. brStart b) `dot` across b)) *^ across b
    kRadial  = 1
    kLane    = 0.5

-- | Follow a desired velocity vector (a signal): turn towards its
-- direction and drive at its length, slowed by the cosine of the heading
-- error (not at all while facing more than a quarter turn away). The
-- rotational velocity is the rate at which the vector itself turns (fed
-- forward) plus a gain of 3 times the heading error. At time 0 the vector
-- is taken to be not turning.
rcVelocityAux :: SimbotProperties -> SF (SimbotInput, Velocity2) SimbotOutput
rcVelocityAux rps = proc (sbi, vd) -> do
  dvd <- derivative -< vd
  let (speed, hd) = vector2RhoTheta vd
      he      = normalizeAngle (hd - odometryHeading sbi)
      turning | speed > 1e-3 = cross vd dvd / (speed * speed)
              | otherwise    = 0
      vMax    = rpWSMax rps
      v       = max 0 (min vMax (speed * cos he))
  returnA -< mrFinalize (ddVelTR v (turning + 3 * he))

-- | The Exercise 14 example: 'notesBraid' for 30 s.
examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex14"
      , exDescription = "Exercise 14: two simbots travel the diagonal, their paths braided"
      , exWorld       = braidWorld notesBraid
      , exControllerA = rcBraid notesBraid
      , exControllerB = rcBraid notesBraid
      , exSeconds     = 30
      , exKeys        = []
      , exReferee     = noReferee
      } ]

-- The unit vector along the braid and the one a quarter turn to its left.
along, across :: Braid -> Vector2 Double
along b  = vector2Polar 1 (brHeading b)
across b = vector2Polar 1 (brHeading b + pi / 2)

perp :: Vector2 Double -> Vector2 Double
perp (Vector2 x y) = Vector2 (negate y) x

cross :: Vector2 Double -> Vector2 Double -> Double
cross (Vector2 ax ay) (Vector2 bx by) = ax * by - ay * bx
