{-# LANGUAGE Arrows #-}
-- The listings are the notes' own code, kept as printed: several have no
-- type signature (rcBlind1, rcBlind2, rcReverse', lim); rcBlind2 binds a
-- variable named max (shadowing Prelude's); rcAlign matches a list
-- partially in a let (it needs three robots in tracking range; its world
-- makes sure there always are); and rcFollowLeftWall's kd^2 leaves the
-- exponent's type to defaulting.
{-# OPTIONS_GHC -Wno-missing-signatures -Wno-name-shadowing
                -Wno-incomplete-uni-patterns -Wno-type-defaults #-}
-- |
-- Module      : Paper.Section3
-- Description : Every controller listing of section 3 of the notes, with a
--               world that shows each one off.
--
-- Section 3.3 of \"Arrows, Robots, and Functional Reactive Programming\"
-- (\"Basic Robot Movement\") builds up a series of simbot controllers.
-- They are given here exactly as printed, re-indented where the typesetting
-- lost the layout. Two changes are marked @FIX@: 'rcReverse'' uses an
-- argument its pattern does not bind, and 'rcAlign' mixes the robot's own
-- frame with the world's (the printed version is kept as
-- 'rcAlignAsPrinted').
--
-- 'examples' pairs each controller with a world and a running time, under
-- the name the notes give it.
module Paper.Section3
  ( -- * Basic movement
    rcStop
  , rcBlind1
  , rcBlind2
  , rcTurn
    -- * The simbot talks (sort of)
  , rcReverse
  , rcReverse'
    -- * Finding our way using odometry
  , rcHeading
  , rcHeading'
  , rcHeadingAux
  , lim
  , rcMoveTo
    -- * Home on the range
  , rcFollowLeftWall
    -- * Mass hysteria
  , rcAlign
  , rcAlignAsPrinted
    -- * The examples
  , examples
    -- * Their worlds
  , stopWorld
  , blind1World
  , blind2World
  , turnWorld
  , reverseWorld
  , headingWorld
  , moveToWorld
  , followWallWorld
  , alignWorld
  ) where

import           Data.List     (sortBy)

import           AFrob
import           AFrobRobotSim
import           Examples.Types

------------------------------------------------------------------------------
-- Basic movement

rcStop :: SimbotController
rcStop _ = constant (mrFinalize ddBrake)

rcBlind1 _ = constant (mrFinalize $ ddVelDiff 10 10)

rcBlind2 rps =
  let max = rpWSMax rps
  in constant (mrFinalize $ ddVelDiff (max/2) (max/2))

rcTurn :: Velocity -> SimbotController
rcTurn vel rps =
  let vMax = rpWSMax rps
      rMax = 2 * (vMax - vel) / rpDiameter rps
  in constant (mrFinalize $ ddVelTR vel rMax)

------------------------------------------------------------------------------
-- The simbot talks (sort of)

rcReverse :: Velocity -> SimbotController
rcReverse v rps = beh `dSwitch` const (rcReverse (-v) rps)
  where beh = proc sbi -> do
          stuckE <- rsStuck -< sbi
          let mr = ddVelDiff v v `mrMerge`
                   tcoPrintMessage (tag stuckE "Ouch!!")
          returnA -< (mrFinalize mr, stuckE)

-- FIX: the notes write @rcReverse' v _ = ...@ but then use @rps@ in the
-- body, which that pattern does not bind; the argument is named @rps@.
rcReverse' v rps =
  (rsStuck >>> arr fun) `dSwitch` const (rcReverse' (-v) rps)
  where fun stuckE =
          let mr = ddVelDiff v v `mrMerge`
                   tcoPrintMessage (tag stuckE "Ouch!!")
          in (mrFinalize mr, stuckE)

------------------------------------------------------------------------------
-- Finding our way using odometry

rcHeading :: Velocity -> Heading -> SimbotController
rcHeading vel hd rps =
  let vMax = rpWSMax rps
      vel' = lim vMax vel
      k    = 2
  in proc sbi -> do
    let he = normalizeAngle (hd - odometryHeading sbi)
    --     vel'' = (1 - abs he / pi) * vel'
    --     returnA -< mrFinalize (ddVelTR vel'' (k*he))
    returnA -< mrFinalize (ddVelTR vel' (k*he))

lim m y = max (-m) (min m y)

rcHeading' :: Velocity -> Heading -> SimbotController
rcHeading' vel hd rps =
  proc sbi -> do
    rcHeadingAux rps -< (sbi, vel, hd)

rcHeadingAux :: SimbotProperties ->
              SF (SimbotInput,Velocity,Heading) SimbotOutput
rcHeadingAux rps =
  let vMax = rpWSMax rps
      k    = 2
  in proc (sbi,vel,hd) -> do
    let vel' = lim vMax vel
        he   = normalizeAngle (hd - odometryHeading sbi)
    --      vel'' = (1 - abs he / pi) * vel'
    --      returnA -< mrFinalize (ddVelTR vel'' (k*he))
    returnA -< mrFinalize (ddVelTR vel' (k*he))

rcMoveTo :: Velocity -> Position2 -> SimbotController
rcMoveTo vd pd rps = proc sbi -> do
  let (d,h) = vector2RhoTheta (pd .-. odometryPosition sbi)
      vel   = if d>2 then vd else vd*(d/2)
  rcHeadingAux rps -< (sbi, vel, h)

------------------------------------------------------------------------------
-- Home on the range

rcFollowLeftWall :: Velocity -> Distance -> SimbotController
rcFollowLeftWall v d _ = proc sbi -> do
  let r = rfLeft sbi
  dr <- derivative -< r
  let omega = kp*(r-d) + kd*dr
      kd     = 5
      kp     = v*(kd^2)/4
  returnA -< mrFinalize (ddVelTR v (lim 0.2 omega))

------------------------------------------------------------------------------
-- Mass hysteria

-- FIX: the notes build each neighbour's relative position as
-- @vector2Polar d a@, but the tracker's angle @a@ is relative to the
-- robot's own heading (an 'Angle', \"a relative measure\"), while the
-- derivation (dp/dt = v + dl/dt, with @vhat@ in world coordinates) needs @l@
-- in world coordinates. Mixing the two frames makes the robot's own turning
-- show up as its neighbours' motion, and the group never settles (see
-- 'rcAlignAsPrinted'). The fix adds the robot's heading to the angle.
rcAlign :: Velocity -> SimbotController
rcAlign v rps = proc sbi -> do
  let neighbors = sortBy (\(_,_,_,d1) (_,_,_,d2) -> compare d1 d2)
                        (aotOtherRobots sbi)
      (l1:l2:l3:_) = map (\(_,_,a,d) -> vector2Polar d (a + odometryHeading sbi)) neighbors  -- FIX
      vhat = vector2Polar v (odometryHeading sbi)
      heading l = vector2Theta (vhat ^+^ l)
  d11 <- derivative -< l1
  d12 <- derivative -< l2
  d13 <- derivative -< l3
  let hAvg = sum (map heading [d11,d12,d13]) / 3
  rcHeadingAux rps -< (sbi, v, hAvg)

-- | 'rcAlign' exactly as printed in the notes, the neighbours' positions
-- taken in the robot's own frame. In this simulator it does not converge:
-- the robots weave, bump into each other and drift apart until one has
-- fewer than three neighbours in range and the pattern @(l1:l2:l3:_)@
-- fails.
rcAlignAsPrinted :: Velocity -> SimbotController
rcAlignAsPrinted v rps = proc sbi -> do
  let neighbors = sortBy (\(_,_,_,d1) (_,_,_,d2) -> compare d1 d2)
                        (aotOtherRobots sbi)
      (l1:l2:l3:_) = map (\(_,_,a,d) -> vector2Polar d a) neighbors
      vhat = vector2Polar v (odometryHeading sbi)
      heading l = vector2Theta (vhat ^+^ l)
  d11 <- derivative -< l1
  d12 <- derivative -< l2
  d13 <- derivative -< l3
  let hAvg = sum (map heading [d11,d12,d13]) / 3
  rcHeadingAux rps -< (sbi, v, hAvg)

------------------------------------------------------------------------------
-- The examples

-- | One example per controller, named as in the notes.
examples :: [Example]
examples =
  [ robot "rcStop"
      "a stationary simbot of each type: the world's dumbest controller"
      stopWorld rcStop rcStop 5
  , robot "rcBlind1"
      "drive blindly forward at 10 m/s (clamped to the maximum wheel speed) into a wall"
      blind1World rcBlind1 rcBlind1 15
  , robot "rcBlind2"
      "drive blindly forward at half the maximum wheel speed: SimbotB is twice as fast as SimbotA"
      blind2World rcBlind2 rcBlind2 18
  , robot "rcTurn"
      "turn as fast as possible at a given speed: circles of about 1 m radius"
      turnWorld (rcTurn 0.8) (rcTurn 1.6) 20
  , robot "rcReverse"
      "bounce between two walls, reversing and saying Ouch!! whenever stuck"
      reverseWorld (rcReverse 0.5) (rcReverse 1) 40
  , robot "rcReverse'"
      "rcReverse without the arrow syntax: the same bouncing between two walls"
      reverseWorld (rcReverse' 0.5) (rcReverse' 1) 40
  , robot "rcHeading"
      "simbots starting in every direction all turn to the heading pi/4"
      headingWorld (rcHeading 0.4 (pi/4)) (rcHeading 0.6 (pi/4)) 12
  , robot "rcHeading'"
      "rcHeading through rcHeadingAux: the same turn to the heading pi/4"
      headingWorld (rcHeading' 0.4 (pi/4)) (rcHeading' 0.6 (pi/4)) 12
  , robot "rcMoveTo"
      "drive to a target point (marked by a block just north of it), slowing down on the last 2 m"
      moveToWorld (rcMoveTo 0.6 moveToTargetA) (rcMoveTo 1.2 moveToTargetB) 25
  , robot "rcFollowLeftWall"
      "follow a long wall on the left at 0.25 m with the PD controller"
      followWallWorld (rcFollowLeftWall 0.3 0.25) (rcFollowLeftWall 0.5 0.4) 28
  , robot "rcAlign"
      "twelve simbots with scattered headings steer by their three nearest neighbours and converge on one heading"
      alignWorld rcStop (rcAlign 0.3) 18
  ]
  where
    robot name desc world ca cb secs = RobotExample
      { exName = name, exDescription = desc, exWorld = world
      , exControllerA = ca, exControllerB = cb, exSeconds = secs, exKeys = [], exReferee = noReferee }

------------------------------------------------------------------------------
-- The worlds

-- | Two simbots, one of each type, doing nothing.
stopWorld :: WorldTemplate
stopWorld = [OTSimbotA 1 (Point2 (-1) 0) 0, OTSimbotB 1 (Point2 1 0) (pi/2)]

-- | A SimbotA and a SimbotB facing a wall of three segments 7 m ahead.
blind1World :: WorldTemplate
blind1World =
  [OTSimbotA 1 (Point2 (-4) (-0.6)) 0, OTSimbotB 1 (Point2 (-4) 0.6) 0]
  ++ vWall 3.5 (-1.5) 1.5

-- | A SimbotA and a SimbotB side by side, facing the far side of the world.
blind2World :: WorldTemplate
blind2World = [OTSimbotA 1 (Point2 (-4.2) (-1)) 0, OTSimbotB 1 (Point2 (-4.2) 1) 0]

-- | A SimbotA and a SimbotB with room to circle.
turnWorld :: WorldTemplate
turnWorld = [OTSimbotA 1 (Point2 (-2.5) (-1)) 0, OTSimbotB 1 (Point2 2.5 (-1)) 0]

-- | Two simbots in two lanes, each between two short walls 6 m apart.
reverseWorld :: WorldTemplate
reverseWorld =
  [OTSimbotA 1 (Point2 0 (-1.5)) 0, OTSimbotB 1 (Point2 0 1.5) 0]
  ++ [ OTVWall (Point2 x y) | x <- [-3, 3], y <- [-1.5, 1.5] ]
  ++ hWall 0 (-2.5) 2.5

-- | Four simbots of each type in the lower-left corner of the world, facing
-- every which way.
headingWorld :: WorldTemplate
headingWorld =
  [ OTSimbotA i (Point2 (-4) (fromIntegral i - 4.5)) (fromIntegral i * 1.6) | i <- [1 .. 4] ]
  ++ [ OTSimbotB i (Point2 (-2.5) (fromIntegral i - 4.5)) (fromIntegral i * 2.3) | i <- [1 .. 4] ]

moveToTargetA, moveToTargetB :: Position2
moveToTargetA = Point2 (-1) 2
moveToTargetB = Point2 2 1

-- | A SimbotA and a SimbotB in two corners; a block 1.2 m north of each
-- target marks it (out of the robots' way).
moveToWorld :: WorldTemplate
moveToWorld =
  [ OTSimbotA 1 (Point2 (-4) (-4)) (pi/2), OTSimbotB 1 (Point2 4 (-4)) pi
  , OTBlock (moveToTargetA .+^ vector2 0 1.2), OTBlock (moveToTargetB .+^ vector2 0 1.2) ]

-- | A long horizontal wall across the world, a SimbotA below it heading
-- east (the wall on its left, 0.2 m away) and a SimbotB above it heading
-- west (the wall on its left too, 0.6 m away).
followWallWorld :: WorldTemplate
followWallWorld =
  [ OTSimbotA 1 (Point2 (-4.2) 0.5) 0, OTSimbotB 1 (Point2 4.2 1.8) pi ]
  ++ hWall 1 (-4.5) 4.5

-- | Twelve SimbotBs in a loose 4 by 3 grid in the lower left of the world,
-- with fixed, random-looking headings (the flock they form heads north-east).
alignWorld :: WorldTemplate
alignWorld =
  [ OTSimbotB i (Point2 (fromIntegral c * 1.2 - 3.5 + jx) (fromIntegral r * 1.2 - 3.2 + jy)) h
  | (i, (c, r), h, (jx, jy)) <- zip4' [1 ..] [ (c, r) | r <- [0 .. 2 :: Int], c <- [0 .. 3 :: Int] ]
                                      headings jitter ]
  where
    headings = [2.1, -0.4, 2.9, 1.2, -2.6, 0.3, -1.3, 2.4, -0.9, 1.7, -2.0, 0.8]
    jitter   = [ (0.1, -0.05), (-0.1, 0.1), (0.05, 0), (0, -0.1), (-0.05, 0.05), (0.1, 0.1)
               , (0, 0), (-0.1, -0.05), (0.05, 0.1), (-0.05, -0.1), (0.1, 0), (0, 0.05) ]
    zip4' (a : as) (b : bs) (c : cs) (d : ds) = (a, b, c, d) : zip4' as bs cs ds
    zip4' _ _ _ _ = []

-- | A vertical wall of unit segments at @x@ from @y0@ to @y1@.
vWall :: Double -> Double -> Double -> WorldTemplate
vWall x y0 y1 = [ OTVWall (Point2 x (y + 0.5)) | y <- [y0 .. y1 - 1] ]

-- | A horizontal wall of unit segments at @y@ from @x0@ to @x1@.
hWall :: Double -> Double -> Double -> WorldTemplate
hWall y x0 x1 = [ OTHWall (Point2 (x + 0.5) y) | x <- [x0 .. x1 - 1] ]
