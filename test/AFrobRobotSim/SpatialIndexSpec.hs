-- | The spatial index ("AFrobRobotSim.SpatialIndex") finds exactly what a
-- scan of everything finds, and the robots' physics and the sensors that
-- use it ("AFrobRobotSim.Physics", "AFrobRobotSim.Sensors") compute what
-- the straightforward all-pairs versions below compute ('===': bit for
-- bit, except that 0 and -0 count as equal). The reference versions are
-- the simulator's original code, kept here as the specification, with two
-- pieces of the implementation in them: 'rayDirection' (the exact
-- quarter turns of the rays) and 'withHeading' (the heading's cached cos
-- and sin, checked on their own in "AFrobRobotSim.PhysicsSpec"). The
-- balls' reference is in "AFrobRobotSim.BallsSpec".
module AFrobRobotSim.SpatialIndexSpec (spec) where

import           Data.List             (nub, sort, sortOn)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Geometry
import           AFrob.Angle           (normalizeAngle, normalizeHeading)
import           AFrob.Dimensions      (Position2, RobotId, RobotType)
import           AFrob.RobotIO         (BatteryStatus (..))
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Balls   (Ball (..))
import           AFrobRobotSim.Physics
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Sensors
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World
import           AFrobRobotSim.WorldGen

------------------------------------------------------------------------------
-- The reference: the original all-pairs code (worlds, robots, balls and
-- time steps come from AFrobRobotSim.WorldGen)

refStepRobots :: Double -> Arena -> [(Robot, DriveCommand)] -> [Robot]
refStepRobots dt arena cmds = go [] cmds
  where
    go done [] = reverse done
    go done ((r, c) : rest) =
      let others = done ++ map fst rest
          r'     = refStepRobot dt arena others r c
      in r' `seq` go (r' : done) rest

refStepRobot :: Double -> Arena -> [Robot] -> Robot -> DriveCommand -> Robot
refStepRobot dt arena others r cmd =
  let k       = rKind r
      l       = kindWheelBase k
      status  = batteryStatusOf (rCharge r)
      wsMax   = kindWSMax k * (if status == BSCritical then 0.5 else 1)
      (vl, vr) = wheelCommand l wsMax cmd
      vCmd    = (vl + vr) / 2
      dv      = kindAccMax k * dt
      v0      = rSpeed r
      v1      = v0 + max (-dv) (min dv (vCmd - v0))
      wLim    = max 0 (2 * (wsMax - abs v1) / l)
      w       = max (-wLim) (min wLim ((vr - vl) / l))
      th0     = rHeading r
      th1     = th0 + w * dt
      vMean   = (v0 + v1) / 2
      disp    | abs (w * dt) < 1e-9 = vector2Polar (vMean * dt) th0
              | otherwise           = vector2 (vMean / w * (sin th1 - sin th0))
                                              (vMean / w * (cos th0 - cos th1))
      p0      = rPos r
      contact = refFirstContact p0 disp arena others
      (p1, v1', hit) = case contact of
        Nothing -> (p0 .+^ disp, v1, False)
        Just s  ->
          let len = norm disp
              s'  = max 0 (s - 1e-9 / max len 1e-300)
          in (p0 .+^ (s' *^ disp), 0, True)
      moved   = p1 /= p0
      effort  = (abs (v1 - w * l / 2) + abs (v1 + w * l / 2)) / (2 * kindWSMax k)
      charge1 = max 0 (rCharge r - dt * (0.0005 + 0.003 * effort))
  in withHeading (normalizeHeading th1)
       r { rPos = p1, rSpeed = v1', rStuck = hit || (rStuck r && not moved), rCharge = charge1 }

refFirstContact :: Position2 -> Vector2 Double -> Arena -> [Robot] -> Maybe Double
refFirstContact p d arena others
  | d == zeroVector = Nothing
  | otherwise       = foldr earliest Nothing (boxHits ++ robotHits)
  where
    boxHits   = [ fst <$> sweepCircleBox p robotRadius' d b | b <- arenaBoxes arena ]
    robotHits = [ fst <$> sweepCircleCircle p robotRadius' d (rPos o) robotRadius' | o <- others ]
    earliest Nothing  acc      = acc
    earliest (Just s) Nothing  = Just s
    earliest (Just s) (Just t) = Just (min s t)

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

spec :: Spec
spec = do
  describe "foldBoxesIn" $
    it "visits exactly the boxes that meet the rectangle (each at least once)" $
      property $ forAll genWorld $ \w -> forAll (genRect (halfSide w)) $ \(x0, y0, x1, y1) ->
        let Arena boxes = arenaFor w
            bi = boxIndex boxes
            got = nub (sort (foldBoxesIn bi x0 y0 x1 y1 (\acc k _ -> k : acc) []))
            want = [ k | (k, Box a b c d) <- zip [0 ..] boxes, a <= x1, c >= x0, b <= y1, d >= y0 ]
        in got === want

  describe "foldPointsIn" $ do
    it "visits exactly the points in the rectangle, once each" $
      property $ forAll genWorld $ \w -> forAll (genRect (halfSide w)) $ \(x0, y0, x1, y1) ->
        forAll (genRobots (halfSide w)) $ \rs ->
          let h = halfSide w
              pts = [ (x, y) | Robot { rPos = Point2 x y } <- rs ]
              pix = pointIndex (-h) (-h) h h pts
              got = sort (foldPointsIn pix x0 y0 x1 y1 (flip (:)) [])
              want = [ k | (k, (x, y)) <- zip [0 ..] pts, x >= x0, x <= x1, y >= y0, y <= y1 ]
          in got === want

    it "visits every point that is not finite, whatever the rectangle, and the others as before" $
      property $ forAll genWorld $ \w -> forAll (genRect (halfSide w)) $ \(x0, y0, x1, y1) ->
        forAll (genRobots (halfSide w)) $ \rs ->
        forAll (vectorOf (length rs) (elements [Nothing, Nothing, Just (0 / 0), Just (1 / 0), Just (-1 / 0)])) $ \bad ->
          let h = halfSide w
              pts = [ maybe (x, y) (\v -> if even k then (v, y) else (x, v)) b
                    | (k, Robot { rPos = Point2 x y }, b) <- zip3 [0 :: Int ..] rs bad ]
              pix = pointIndex (-h) (-h) h h pts
              got = sort (foldPointsIn pix x0 y0 x1 y1 (flip (:)) [])
              finitePt (x, y) = not (isNaN x || isInfinite x || isNaN y || isInfinite y)
              want = [ k | (k, p@(x, y)) <- zip [0 ..] pts
                         , not (finitePt p) || (x >= x0 && x <= x1 && y >= y0 && y <= y1) ]
          in got === want

  describe "stepRobots" $
    it "moves the robots exactly as testing every box and every other robot does" $
      property $ forAll genWorld $ \w -> forAll genDt $ \dt ->
        forAll (genRobots (halfSide w)) $ \rs -> forAll (vectorOf (length rs) genCommand) $ \cs ->
          let arena = arenaFor w
              cmds = zip rs cs
          in stepRobots dt arena cmds === refStepRobots dt arena cmds

  describe "stepRobotsNear" $
    it "moves the robots as stepRobots does, given the sensors' index of their centres" $
      property $ forAll genWorld $ \w -> forAll genDt $ \dt ->
        forAll (genRobots (halfSide w)) $ \rs -> forAll (vectorOf (length rs) genCommand) $ \cs ->
          let arena = arenaFor w
              cmds = zip rs cs
              near = scRobotIndex (SenseContext arena rs [])
          in stepRobotsNear near dt arena cmds === refStepRobots dt arena cmds

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
        forAll (listOf1 (oneof [choose (-7, 7), elements [0, pi / 2, pi, -pi / 2, 0 / 0, 1 / 0]])) $ \as ->
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
              quarters = [0, pi / 2, pi, -pi / 2]
          in map (siRange si) quarters === map (refRange arena rs 0) quarters
    it "tracks exactly the robots and balls in range, nearest first" $
      property $ forAll genWorld $ \w -> forAll (genRobots (halfSide w)) $ \rs ->
        forAll (genBalls (halfSide w)) $ \bs ->
        not (null rs) ==>
        forAll (chooseInt (0, length rs - 1)) $ \i ->
          let arena = arenaFor w
              si = senseRobot (SenseContext arena rs bs) i (origin, 0) Nothing
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
    genRect h = do
      x0 <- choose (-h - 2, h + 2)
      y0 <- choose (-h - 2, h + 2)
      wd <- choose (0, h)
      ht <- choose (0, h)
      pure (x0, y0, x0 + wd, y0 + ht)
