-- | The spatial index ("AFrobRobotSim.SpatialIndex") finds exactly what a
-- scan of everything finds, and the robots' physics that uses it
-- ("AFrobRobotSim.Physics") computes what the straightforward all-pairs
-- version below computes ('===': bit for bit, except that 0 and -0 count
-- as equal). The reference version is the simulator's original code, kept
-- here as the specification, with one piece of the implementation in it:
-- 'withHeading' (the heading's cached cos and sin, checked on their own in
-- "AFrobRobotSim.PhysicsSpec"). The sensors' reference is in
-- "AFrobRobotSim.SensorsSpec", the balls' in "AFrobRobotSim.BallsSpec".
module AFrobRobotSim.SpatialIndexSpec (spec) where

import           Data.Functor.Identity (Identity (..))
import           Data.List             (nub, sort, zip4)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Geometry
import           AFrob.Angle           (normalizeHeading)
import           AFrob.Dimensions      (Position2)
import           AFrob.RobotIO         (BatteryStatus (..))
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Physics
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Sensors
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World
import           AFrobRobotSim.WorldGen

------------------------------------------------------------------------------
-- The reference: the original all-pairs code (worlds, robots, wheel
-- commands and time steps come from AFrobRobotSim.WorldGen)

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

------------------------------------------------------------------------------

-- The robots' centres, each coordinate replaced, at random, by one of the
-- given values (@Nothing@ keeps it): an even-numbered robot's x, an odd one's y.
spoiled :: [Maybe Double] -> [Robot] -> Gen [(Double, Double)]
spoiled choices rs = do
  bad <- vectorOf (length rs) (elements choices)
  pure [ maybe (x, y) (\v -> if even k then (v, y) else (x, v)) b
       | (k, Robot { rPos = Point2 x y }, b) <- zip3 [0 :: Int ..] rs bad ]

-- A rectangle over and around a world of half-side @h@; one in ten
-- inverted (its far side before its near one, in x, y or both: empty).
genRect :: Double -> Gen (Double, Double, Double, Double)
genRect h = do
  x0 <- choose (-h - 2, h + 2)
  y0 <- choose (-h - 2, h + 2)
  wd <- choose (0, h)
  ht <- choose (0, h)
  frequency [ (9, pure (x0, y0, x0 + wd, y0 + ht))
            , (1, elements [(x0 + wd, y0, x0, y0 + ht), (x0, y0 + ht, x0 + wd, y0), (x0 + wd, y0 + ht, x0, y0)]) ]

-- A world's rectangle, its robots' centres spoiled with the given values
-- ('spoiled'), and those centres on an index over the world.
forSpoiledIndex :: Testable t => [Maybe Double]
                -> ((Double, Double, Double, Double) -> [(Double, Double)] -> PointIndex -> t) -> Property
forSpoiledIndex choices k =
  forAll genWorld $ \w -> forAll (genRect (halfSide w)) $ \rect ->
    forAll (genRobots (halfSide w)) $ \rs -> forAll (spoiled choices rs) $ \pts ->
      let h = halfSide w in k rect pts (pointIndex (-h) (-h) h h pts)

spec :: Spec
spec = do
  describe "foldBoxesIn" $
    it "visits exactly the boxes that meet the rectangle (each at least once; none for an empty one)" $
      property $ forAll genWorld $ \w -> forAll (genRect (halfSide w)) $ \(x0, y0, x1, y1) ->
        let Arena boxes = arenaFor w
            bi = boxIndex boxes
            got = nub (sort (foldBoxesIn bi x0 y0 x1 y1 (\acc k _ -> k : acc) []))
            want = [ k | x0 <= x1, y0 <= y1, (k, Box a b c d) <- zip [0 ..] boxes, a <= x1, c >= x0, b <= y1, d >= y0 ]
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
      property $ forSpoiledIndex [Nothing, Nothing, Just (0 / 0), Just (1 / 0), Just (-1 / 0)] $ \(x0, y0, x1, y1) pts pix ->
          let got = sort (foldPointsIn pix x0 y0 x1 y1 (flip (:)) [])
              finitePt (x, y) = not (isNaN x || isInfinite x || isNaN y || isInfinite y)
              want = [ k | (k, p@(x, y)) <- zip [0 ..] pts
                         , not (finitePt p) || (x >= x0 && x <= x1 && y >= y0 && y <= y1) ]
          in got === want

  describe "pointsInCellsOf" $
    it "counts at least the points foldPointsIn visits (a buffer's size), and at most all of them" $
      property $ forSpoiledIndex [Nothing, Nothing, Nothing, Just (0 / 0), Just (1 / 0)] $ \(x0, y0, x1, y1) pts pix ->
          let visited = foldPointsIn pix x0 y0 x1 y1 (\c _ -> c + 1) (0 :: Int)
              counted = pointsInCellsOf pix x0 y0 x1 y1
          in counterexample (show (visited, counted)) (visited <= counted && counted <= length pts)

  describe "foldWindowCellsM" $
    it "visits windowSize points, each once with its coordinates, among them every point foldPointsIn visits" $
      property $ forSpoiledIndex [Nothing, Nothing, Nothing, Just (0 / 0), Just (1 / 0)] $ \(x0, y0, x1, y1) pts pix ->
          let win = pointWindow pix x0 y0 x1 y1
              seen = runIdentity (foldWindowCellsM win (\acc k x y -> Identity ((k, x, y) : acc)) [])
              ks = sort [ k | (k, _, _) <- seen ]
              inRect = sort (foldPointsIn pix x0 y0 x1 y1 (flip (:)) [])
              same a b = a == b || (isNaN a && isNaN b)
          in conjoin
               [ length seen === windowSize win
               , windowSize win === pointsInCellsOf pix x0 y0 x1 y1
               , nub ks === ks
               , counterexample "a point's coordinates" (and [ same x px && same y py | (k, x, y) <- seen, let (px, py) = pts !! k ])
               , counterexample "a point in the rectangle not visited" (all (`elem` ks) inRect) ]

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

  describe "planMoveApart" $
    it "moves the robots as planMove does, given the sensors' bound on each one's distance to the others, or any lower one" $
      property $ forAll genWorld $ \w -> forAll genDt $ \dt ->
        forAll (genRobots (halfSide w)) $ \rs -> forAll (vectorOf (length rs) genCommand) $ \cs ->
          forAll (vectorOf (length rs) (elements [1, 1, 1, 0.999, 0.5, 0])) $ \factors ->
            let arena = arenaFor w
                ctx   = SenseContext arena rs []
                near  = scRobotIndex ctx
                apart i = snd (senseRobotApart ctx i (origin, 0) Nothing)
                plans = [ (r, planMoveApart dt arena (f * apart i) r c)
                        | (i, r, c, f) <- zip4 [0 ..] rs cs factors ]
                -- (the bound is one: at most the distance to each other robot)
                exact i = minimum ((1 / 0) : [ norm (rPos o .-. rPos (rs !! i)) | (j, o) <- zip [0 ..] rs, j /= i ])
            in conjoin [ counterexample ("robot " ++ show i) (apart i <= exact i) | i <- [0 .. length rs - 1] ]
               .&&. stepRobotsPlanned near plans === refStepRobots dt arena (zip rs cs)

