-- | "AFrobRobotSim.Sensors": the range finder, the tracker and the robot's
-- status on single cases whose readings are worked out by hand from the
-- documented geometry (a simbot is a disc of radius 0.25 m; a ray starts
-- at its centre and reads from its edge, at most 'rangeFinderMax' = 3 m;
-- the tracker gives centre-to-centre distances up to 'trackerRange' = 4 m
-- and bearings in [-pi, pi) from the heading, nearest first); and every
-- reading, bit for bit, against the straightforward all-pairs versions
-- below (the simulator's original code, kept here as the specification,
-- with one piece of the implementation in it: 'rayDirection', checked on
-- its own here), with the arena's ray grid and without one.
module AFrobRobotSim.SensorsSpec (spec) where

import           Control.Exception     (evaluate)
import           Data.List             (sortOn)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Geometry
import           AFrob.Angle           (normalizeAngle)
import           AFrob.Dimensions      (Heading, RobotId, RobotType)
import           AFrob.RobotIO         (BatteryStatus (..), rfBack, rfFront, rfLeft, rfMaxRange, rfRight)
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Balls   (Ball (..))
import           AFrobRobotSim.Physics
import           AFrobRobotSim.RayGrid (rayGridEntries)
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Sensors
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex (boxIndexRays, pointIndexCount, pointX, pointY)
import           AFrobRobotSim.World
import           AFrobRobotSim.WorldGen
import           TestUtil              (shouldApprox, shouldApproxList)

------------------------------------------------------------------------------
-- The reference: the original all-pairs code (worlds, robots and balls come
-- from AFrobRobotSim.WorldGen)

refRange :: Arena -> [Robot] -> Int -> Double -> Double
refRange arena robots i a
  | isNaN a || isInfinite a = rangeFinderMax
  | otherwise = max 0 (min rangeFinderMax (nearest - robotRadius'))
  where
    me      = robots !! i
    p       = rPos me
    others  = [ o | (j, o) <- zip [0 :: Int ..] robots, j /= i ]
    dir     = rayDirection (rHeading me) a
    hits    = [ t | b <- arenaBoxes arena, Just t <- [rayBox p dir b] ]
           ++ [ t | o <- others, Just t <- [rayCircle p dir (rPos o) robotRadius'] ]
    nearest = minimum (rangeFinderMax + robotRadius' : hits)

-- Places 0.5 m apart over a 4.5 m square.
lattice :: [Point2 Double]
lattice = [ Point2 (0.5 * fromIntegral x) (0.5 * fromIntegral y) | x <- [-4 .. 4 :: Int], y <- [-4 .. 4 :: Int] ]

refTracker :: [Robot] -> [Ball] -> Int -> ([(RobotType, RobotId, Double, Double)], [(Double, Double)])
refTracker robots balls i =
  ( [ (kindType (rKind o), rId o, a, d)
    | (o, (a, d)) <- sortOn (snd . snd) [ (o, polar (rPos o)) | o <- others ]
    , d <= trackerRange ]
  , sortOn snd [ (a, d) | b <- balls, let (a, d) = polar (bPos b), d <= trackerRange ] )
  where
    me     = robots !! i
    p      = rPos me
    others = [ o | (j, o) <- zip [0 :: Int ..] robots, j /= i ]
    polar q = let (d, th) = vector2RhoTheta (q .-. p)
              in (normalizeAngle (th - rHeading me), d)

------------------------------------------------------------------------------
-- Single cases

-- | A SimbotA with the given id at @(x, y)@ and heading, at rest, not
-- stuck, fully charged.
simbot :: RobotId -> Double -> Double -> Heading -> Robot
simbot i x y h = mkRobot SimbotA i (Point2 x y) h 0 False 1

-- | What robot number @i@ senses among the robots and balls in an arena
-- (with the odometry at the origin and no key pressed).
senseIn :: Arena -> [Robot] -> [Ball] -> Int -> SimbotInput
senseIn arena rs bs i = senseRobot (SenseContext arena rs bs) i (origin, 0) Nothing

-- | The notes' 10 m world with the given obstacles.
notesArena :: WorldTemplate -> Arena
notesArena = arenaOf notesBounds

-- | The four quarter-turn readings: front, left, back, right.
quarters :: SimbotInput -> [Double]
quarters si = [rfFront si, rfLeft si, rfBack si, rfRight si]

-- | Three blocks (0.5 m squares) around the origin: one ahead along +x
-- (its near face at x = 1.75), one along +y (near face at y = 1.25), one
-- along -y (near face at y = -2.25); nothing along -x nearer than the
-- boundary at x = -5.
threeBlocks :: Arena
threeBlocks = notesArena [OTBlock (Point2 2 0), OTBlock (Point2 0 1.5), OTBlock (Point2 0 (-2.5))]

-- | The tracked robots: their (type, id), and their bearings and distances
-- in turn.
tracked :: SimbotInput -> ([(RobotType, RobotId)], [Double])
tracked si = ( [ (t, i) | (t, i, _, _) <- siRobots si ]
             , concat [ [a, d] | (_, _, a, d) <- siRobots si ] )

-- | The tracked balls' bearings and distances, in turn.
trackedBalls :: SimbotInput -> [Double]
trackedBalls si = concat [ [a, d] | (a, d) <- siBalls si ]

-- | A ball at rest at @(x, y)@.
ballAt :: Double -> Double -> Ball
ballAt x y = Ball (Point2 x y) zeroVector

-- | The arena with two boxes added at opposite ends of the numbers
-- (degenerate, as far away as a finite box can be): the boxes' extent
-- overflows, so the arena has no ray grid and every ray is cast by the
-- fallback over the grid of boxes; nothing a sensor can reach changes.
withoutRayGrid :: Arena -> Arena
withoutRayGrid (Arena bs) = Arena (bs ++ [Box (-1e308) (-1e308) (-1e308) (-1e308), Box 1e308 1e308 1e308 1e308])

-- | The arena's boxes have a ray grid.
hasRayGrid :: Arena -> Bool
hasRayGrid arena = rayGridEntries (boxIndexRays (arenaIndex arena)) > 0

-- | An angle for a range finder: any, or a quarter turn, or not finite.
genRayAngle :: Gen Double
genRayAngle = oneof [choose (-7, 7), elements [0, pi / 2, pi, -pi / 2, 0 / 0, 1 / 0]]

------------------------------------------------------------------------------

spec :: Spec
spec = do
  describe "range finder" $ do
    it "reads the distance from the robot's edge to the obstacle, and rangeFinderMax where there is none" $
      -- front: 1.75 - 0.25; left: 1.25 - 0.25; back: the boundary, 5 - 0.25,
      -- beyond the range; right: 2.25 - 0.25
      quarters (senseIn threeBlocks [simbot 1 0 0 0] [] 0) `shouldApproxList` [1.5, 1, 3, 2]

    it "turns its finders with the robot: left is a quarter turn counter-clockwise" $ do
      let at h = quarters (senseIn threeBlocks [simbot 1 0 0 h] [] 0)
      -- facing +y, the block along +x is on the right
      at (pi / 2)  `shouldApproxList` [1, 3, 2, 1.5]
      -- facing -x
      at pi        `shouldApproxList` [3, 2, 1.5, 1]
      at (-pi)     `shouldApproxList` [3, 2, 1.5, 1]
      -- facing -y, the block along +x is on the left
      at (-pi / 2) `shouldApproxList` [2, 1.5, 1, 3]

    it "casts any other angle from the robot's centre, relative to the heading" $ do
      -- a horizontal wall (x in [1.5, 2.5], y in [2.0, 2.1]) on the
      -- diagonal: the ray along it meets the near face at (2, 2), 2 sqrt 2
      -- from the centre
      let wall = notesArena [OTHWall (Point2 2 2.05)]
          diag h a = siRange (senseIn wall [simbot 1 0 0 h] [] 0) a
          want = 2 * sqrt 2 - 0.25
      diag 0 (pi / 4) `shouldApprox` want
      diag (pi / 4) 0 `shouldApprox` want
      diag (pi / 2) (-pi / 4) `shouldApprox` want
      diag pi (-3 * pi / 4) `shouldApprox` want
      diag (-pi / 4) (pi / 2) `shouldApprox` want
      -- and misses it a little to either side, where the boundary is
      -- more than 5 m away
      diag 0 (pi / 4 + 0.3) `shouldBe` rangeFinderMax
      diag 0 (pi / 4 - 0.3) `shouldBe` rangeFinderMax

    it "reads rangeFinderMax (3 m), exactly, when nothing is nearer than that to its edge" $ do
      let front x = rfFront (senseIn emptyArena [simbot 1 x 0 0] [] 0)
          si = senseIn emptyArena [simbot 1 0 0 0.3] [] 0
      quarters si `shouldBe` [3, 3, 3, 3]
      rfMaxRange si `shouldBe` 3
      rangeFinderMax `shouldBe` 3
      -- the boundary at x = 5: 3 m from the edge, 3.25 m (clamped), 2.75 m
      front 1.75 `shouldBe` 3
      front 1.5 `shouldBe` 3
      front 2 `shouldBe` 2.75

    it "reads 0 touching an obstacle, and inside one" $ do
      -- touching the boundary
      rfFront (senseIn emptyArena [simbot 1 4.75 0 0] [] 0) `shouldBe` 0
      -- the centre inside a block: every ray starts in it
      quarters (senseIn threeBlocks [simbot 1 2 0 0.5] [] 0) `shouldBe` [0, 0, 0, 0]
      -- overlapping another robot: its disc is 0.05 m from the centre
      rfFront (senseIn emptyArena [simbot 1 0 0 0, simbot 2 0.3 0 0] [] 0) `shouldBe` 0

    it "is blocked by another robot, at the other's near edge, in every direction" $ do
      -- others at 2 m ahead, 1.5 m left, 1 m behind, 2.5 m right: edge to
      -- edge, each 0.5 m less
      let others = [simbot 2 2 0 0, simbot 3 0 1.5 0, simbot 4 (-1) 0 0, simbot 5 0 (-2.5) 0]
          facing h = senseIn emptyArena (simbot 1 0 0 h : others) [] 0
      quarters (facing 0) `shouldApproxList` [1.5, 1, 0.5, 2]
      -- the one ahead sees the first from 2 m behind it
      rfBack (senseIn emptyArena (simbot 1 0 0 0 : others) [] 1) `shouldApprox` 1.5
      -- turned a quarter, the robot sees them one finder round
      quarters (facing (pi / 2)) `shouldApproxList` [1, 0.5, 2, 1.5]
      -- along other angles too: the one 1.5 m along +y, from facing -x
      siRange (facing pi) (-pi / 2 + 1e-9) `shouldApprox` 1

    it "is blocked by a robot whose disc the ray grazes, and not by one just off it" $ do
      -- centre 0.25 m off the ray: tangent at 2 m from the centre
      rfFront (senseIn emptyArena [simbot 1 0 0 0, simbot 2 2 0.25 0] [] 0) `shouldBe` 1.75
      rfLeft (senseIn emptyArena [simbot 1 0 0 0, simbot 2 (-0.25) 2 0] [] 0) `shouldBe` 1.75
      rfFront (senseIn emptyArena [simbot 1 0 0 0, simbot 2 2 0.26 0] [] 0) `shouldBe` 3
      rfLeft (senseIn emptyArena [simbot 1 0 0 0, simbot 2 (-0.26) 2 0] [] 0) `shouldBe` 3

    it "does not see balls, however near" $ do
      let balls = [ballAt 0.5 0, ballAt 0 1, ballAt (-2) 0, ballAt 0 (-0.45)]
      quarters (senseIn emptyArena [simbot 1 0 0 0] balls 0) `shouldBe` [3, 3, 3, 3]
      quarters (senseIn emptyArena [simbot 1 0 0 0, simbot 2 2 0 0] balls 0) `shouldBe` [1.5, 3, 3, 3]

    it "reads rangeFinderMax for an angle that is not a number" $ do
      let si = senseIn threeBlocks [simbot 1 0 0 0, simbot 2 0.3 0 0] [] 0
      map (siRange si) [0 / 0, 1 / 0, -1 / 0] `shouldBe` [3, 3, 3]

    it "casts from the robot's true position and heading, not its odometry's" $ do
      let si = senseRobot (SenseContext threeBlocks [simbot 1 0 0 0] []) 0 (Point2 3 (-1), 2) Nothing
      quarters si `shouldApproxList` [1.5, 1, 3, 2]

  describe "rangeReading" $
    it "reads as a robot's range finder, given the other robots' centres" $ do
      rangeReading threeBlocks [] origin 0 0 `shouldBe` 1.5
      rangeReading threeBlocks [] origin (pi / 2) 0 `shouldApprox` 1
      -- left, and just off it (not a quarter turn), of a robot facing +x
      rangeReading threeBlocks [] origin 0 (pi / 2) `shouldBe` 1
      rangeReading emptyArena [Point2 0 1.5] origin 0 (pi / 2 - 1e-9) `shouldApprox` 1
      rangeReading emptyArena [Point2 (-1) 0] origin 0 pi `shouldBe` 0.5
      rangeReading emptyArena [Point2 (-1) 0] origin 0 (0 / 0) `shouldBe` 3
      rangeReading emptyArena [] (Point2 1.5 0) 0 0 `shouldBe` 3

  describe "tracker" $ do
    -- around a robot at the origin: one 2 m along -x, one 3 m along +y,
    -- one exactly 4 m along -y, and two just beyond the range
    let crowd h = [ simbot 1 0 0 h
                  , mkRobot SimbotB 7 (Point2 0 3) 1 0 False 1
                  , simbot 2 (-2) 0 0
                  , simbot 3 0 (-4) 0
                  , mkRobot SimbotB 4 (Point2 4.5 0) 0 0 False 1
                  , simbot 5 (-3) (sqrt 7 + 1e-9) 0 ]
        others = [("SimbotA", 2), ("SimbotB", 7), ("SimbotA", 3)]

    it "lists the other robots within trackerRange, nearest first, by bearing and centre distance" $ do
      let (ids, nums) = tracked (senseIn emptyArena (crowd 0) [] 0)
      ids `shouldBe` others
      -- the bearing of -x is -pi: bearings are in [-pi, pi)
      nums `shouldApproxList` [-pi, 2, pi / 2, 3, -pi / 2, 4]

    it "gives bearings relative to the heading, in [-pi, pi)" $ do
      let bearings h = let (ids, nums) = tracked (senseIn emptyArena (crowd h) [] 0)
                       in (ids, [ a | (a, _) <- pairs nums ])
          pairs (a : d : rest) = (a, d) : pairs rest
          pairs _              = []
      fst (bearings (pi / 2)) `shouldBe` others
      snd (bearings (pi / 2)) `shouldApproxList` [pi / 2, 0, -pi]
      snd (bearings (-pi / 2)) `shouldApproxList` [-pi / 2, -pi, 0]
      snd (bearings pi) `shouldApproxList` [0, -pi / 2, pi / 2]

    it "lists equally near robots in template order" $ do
      -- 2 m away each, below, above and ahead: by bearing they would be
      -- 1, 3, 2
      let rs = [simbot 9 0 0 0, simbot 1 0 (-2) 0, simbot 2 0 2 0, simbot 3 2 0 0]
      fst (tracked (senseIn emptyArena rs [] 0)) `shouldBe` [("SimbotA", 1), ("SimbotA", 2), ("SimbotA", 3)]
      -- and from the last: the first is 2 m away, the others further
      fst (tracked (senseIn emptyArena rs [] 3)) `shouldBe` [("SimbotA", 9), ("SimbotA", 1), ("SimbotA", 2)]

    it "lists the balls within trackerRange, nearest first, by bearing and centre distance" $ do
      let balls = [ballAt 3 0, ballAt 1 1, ballAt 0 (-4), ballAt (-4.5) 0, ballAt 0 (4 + 1e-9)]
      trackedBalls (senseIn emptyArena [simbot 1 0 0 0] balls 0)
        `shouldApproxList` [pi / 4, sqrt 2, 0, 3, -pi / 2, 4]
      trackedBalls (senseIn emptyArena [simbot 1 0 0 pi] balls 0)
        `shouldApproxList` [-3 * pi / 4, sqrt 2, -pi, 3, pi / 2, 4]

    it "sees through walls, and sees nothing beyond its range" $ do
      let si = senseIn threeBlocks [simbot 1 0 0 0, simbot 2 3 0 0, simbot 3 0 4.01 0] [ballAt 0 (-3)] 0
      tracked si `shouldBe` ([("SimbotA", 2)], [0, 3])
      trackedBalls si `shouldApproxList` [-pi / 2, 3]
      tracked (senseIn emptyArena [simbot 1 0 0 0] [] 0) `shouldBe` ([], [])
      trackerRange `shouldBe` 4

  describe "status" $ do
    it "reports the robot's bumper (stuck) and its battery, and nothing of the others'" $ do
      let robot stuck charge x = mkRobot SimbotB 1 (Point2 x 0) 0 0 stuck charge
          rs = [robot True 1 0, robot False 0.2 1, robot True 0.05 2, robot False 0.31 3]
          status i = let si = senseIn emptyArena rs [] i in (siStuck si, siBattery si)
      map status [0 .. 3] `shouldBe`
        [(True, BSHigh), (False, BSLow), (True, BSCritical), (False, BSHigh)]

    it "passes the odometry reading and the key on as given" $ do
      let si = senseRobot (SenseContext emptyArena [simbot 1 0 0 0] []) 0 (Point2 3 (-1), 2) (Just 'k')
      (siPosition si, siHeading si, siKey si) `shouldBe` (Point2 3 (-1), 2, Just 'k')
      siKey (senseIn emptyArena [simbot 1 0 0 0] [] 0) `shouldBe` Nothing

    it "fails, naming the number, for a robot that is not in the context" $ do
      let ctx = SenseContext emptyArena [simbot 1 0 0 0, simbot 2 1 0 0] []
      evaluate (senseRobot ctx 2 (origin, 0) Nothing)
        `shouldThrow` errorCall "AFrobRobotSim.Sensors.senseRobot: no robot number 2"
      evaluate (senseRobot ctx (-1) (origin, 0) Nothing)
        `shouldThrow` errorCall "AFrobRobotSim.Sensors.senseRobot: no robot number -1"

  describe "SenseContext" $
    it "gives back what it was built of, and indexes the robots' centres in order" $ do
      let rs = [simbot 1 0 0 0, simbot 2 1 2 0]
          ctx = SenseContext threeBlocks rs [ballAt 1 1]
      (scRobots ctx, scBalls ctx) `shouldBe` (rs, [ballAt 1 1])
      length (arenaBoxes (scArena ctx)) `shouldBe` 7
      let ix = scRobotIndex ctx
      [ (pointX ix j, pointY ix j) | j <- [0 .. pointIndexCount ix - 1] ] `shouldBe` [(0, 0), (1, 2)]

  describe "without the ray grid" $ do
    it "reads only the robots in an arena with no boxes at all" $ do
      let rs = [simbot 1 0 0 0, simbot 2 2 0 0]
      quarters (senseIn (Arena []) rs [] 0) `shouldBe` [1.5, 3, 3, 3]
      rangeReading (Arena []) [] origin 0 0.3 `shouldBe` 3
    it "reads every range finder and tracks as with it, on random worlds whose extent is too large for one" $
      property $ forAll genWorld $ \w -> forAll (genRobots (halfSide w)) $ \rs ->
        forAll (genBalls (halfSide w)) $ \bs ->
        not (null rs) ==>
        forAll (chooseInt (0, length rs - 1)) $ \i -> forAll (listOf1 genRayAngle) $ \as ->
          let arena = arenaFor w
              bare  = withoutRayGrid arena
              readAll a = let si = senseIn a rs bs i
                          in (map (siRange si) as, siRobots si, siBalls si)
          in hasRayGrid arena .&&. not (hasRayGrid bare) .&&. readAll bare === readAll arena

  describe "rayDirection" $ do
    it "turns the heading's unit vector exactly by a quarter turn" $
      property $ forAll (choose (-pi, pi)) $ \h ->
        let c = cos h
            s = sin h
        in [ rayDirection h a | a <- [0, pi / 2, -pi / 2, pi, -pi] ]
             === [Vector2 c s, Vector2 (-s) c, Vector2 s (-c), Vector2 (-c) (-s), Vector2 (-c) (-s)]
    it "is (cos (h + a), sin (h + a)) for any other angle" $
      property $ forAll (choose (-pi, pi)) $ \h -> forAll (choose (-7, 7)) $ \a ->
        a `notElem` [0, pi / 2, -pi / 2, pi, -pi] ==>
        rayDirection h a === Vector2 (cos (h + a)) (sin (h + a))

  describe "senseRobot" $ do
    it "reads every range finder exactly as casting at everything does" $
      property $ forAll genWorld $ \w -> forAll (genRobots (halfSide w)) $ \rs ->
        not (null rs) ==>
        forAll (chooseInt (0, length rs - 1)) $ \i ->
        forAll (listOf1 genRayAngle) $ \as ->
          let arena = arenaFor w
              si = senseRobot (SenseContext arena rs []) i (origin, 0) Nothing
          in map (siRange si) as === map (refRange arena rs i) as
    it "reads the quarter-turn range finders exactly with robots a radius from their lines" $
      -- the quarter-turn rays test only the robots within a radius (and
      -- some slack) of the heading's axis or its perpendicular
      property $ forAll genWorld $ \w -> forAll (genRobot (halfSide w)) $ \me ->
        forAll (listOf1 (genGrazing me)) $ \rs0 ->
          let rs = me : rs0
              arena = arenaFor w
              si = senseRobot (SenseContext arena rs []) 0 (origin, 0) Nothing
              quarterTurns = [0, pi / 2, pi, -pi / 2]
          in map (siRange si) quarterTurns === map (refRange arena rs 0) quarterTurns
    it "tracks exactly the robots and balls in range, nearest first" $
      property $ forAll genWorld $ \w -> forAll (genRobots (halfSide w)) $ \rs ->
        forAll (genBalls (halfSide w)) $ \bs ->
        not (null rs) ==>
        forAll (chooseInt (0, length rs - 1)) $ \i ->
          let arena = arenaFor w
              si = senseRobot (SenseContext arena rs bs) i (origin, 0) Nothing
          in (siRobots si, siBalls si) === refTracker rs bs i
    it "tracks exactly, in template order among equally near ones, robots and balls packed on a lattice" $
      -- up to 80 robots and 80 balls on a 0.5 m lattice, in a random
      -- order: dozens in range, many of them equally far
      property $ forAll (sublistOf lattice >>= shuffle) $ \ps -> forAll (sublistOf lattice >>= shuffle) $ \qs ->
        not (null ps) ==> forAll (chooseInt (0, length ps - 1)) $ \i -> forAll (choose (-4, 4)) $ \h ->
          let rs = [ mkRobot SimbotA k p h 0 False 1 | (k, p) <- zip [1 ..] ps ]
              bs = [ Ball q zeroVector | q <- qs ]
              si = senseRobot (SenseContext emptyArena rs bs) i (origin, 0) Nothing
          in (siRobots si, siBalls si) === refTracker rs bs i
    it "reads the same as rangeReading given the other robots' centres" $
      property $ forAll genWorld $ \w -> forAll (genRobots (halfSide w)) $ \rs ->
        not (null rs) ==>
        forAll (chooseInt (0, length rs - 1)) $ \i -> forAll (choose (-7, 7)) $ \a ->
          let arena = arenaFor w
              others = [ rPos o | (j, o) <- zip [0 ..] rs, j /= i ]
              me = rs !! i
          in rangeReading arena others (rPos me) (rHeading me) a === refRange arena rs i a
  where
    -- A robot whose centre is about a radius (0.25 m) from the heading's
    -- axis or its perpendicular through another robot's centre, within
    -- the reach of its range finder, heading anywhere.
    genGrazing me = do
      let Point2 px py = rPos me
          c = cos (rHeading me)
          s = sin (rHeading me)
      along <- choose (-3.6, 3.6)
      off   <- elements [0.25, 0.25 + 1e-12, 0.25 - 1e-12, 0.25 + 1e-9, 0.2501, 0.2499, 0.251, 0.249]
      side  <- elements [1, -1]
      axis  <- arbitrary
      let (a, b) = if axis then (along, side * off) else (side * off, along)
      r <- genRobot 1
      pure r { rPos = Point2 (px + a * c - b * s) (py + a * s + b * c) }
