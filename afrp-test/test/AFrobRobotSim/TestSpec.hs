{-# LANGUAGE Arrows #-}
-- | Properties of whole simbot runs, written with "AFrobRobotSim.Test".
module AFrobRobotSim.TestSpec (spec) where

import           Control.Exception     (ErrorCall (..), evaluate, try)
import           Control.Monad         (forM_)
import           Data.IORef            (IORef, modifyIORef', newIORef, readIORef)
import           Data.List             (isInfixOf, isPrefixOf, tails)
import           Numeric               (showFFloat)
import           System.Directory      (createDirectory, doesDirectoryExist, doesFileExist, getTemporaryDirectory, listDirectory,
                                        removeDirectory, removeFile)
import           System.IO.Error       (isAlreadyExistsError)
import           System.IO.Unsafe      (unsafePerformIO)
import           System.Timeout        (timeout)
import           System.FilePath       ((</>))
import           Test.Hspec            hiding (after)
import           Test.QuickCheck
import           Test.QuickCheck.Random (mkQCGen)

import           AFrob                 hiding (forAll)
import           AFrobRobotSim
import           AFrobRobotSim.Test
import           AFRP.Test.LTL

-- Every robot drives at full speed on a circle of its own (by its id), so
-- robots meet each other and the walls.
wander :: SimbotController
wander props = constant (mrFinalize (ddVelTR 2 (fromIntegral (rpId props `mod` 5 - 2) * 0.6)))

-- The notes' wall follower (section 3.3, "Home on the range"): a PD
-- controller keeping the left range finder's reading at d.
rcFollowLeftWall :: Velocity -> Distance -> SimbotController
rcFollowLeftWall v d _ = proc sbi -> do
  let r = rfLeft sbi
  dr <- derivative -< r
  let omega = kp * (r - d) + kd * dr
      kd    = 5
      kp    = v * kd * kd / 4
  returnA -< mrFinalize (ddVelTR v (max (-0.2) (min 0.2 omega)))

-- The wall follower with the sign of its steering flipped: it turns
-- towards the wall it should keep its distance from.
rcFollowLeftWallBroken :: Velocity -> Distance -> SimbotController
rcFollowLeftWallBroken v d _ = proc sbi -> do
  let r = rfLeft sbi
  dr <- derivative -< r
  let omega = negate (v * 25 / 4 * (r - d) + 5 * dr)
  returnA -< mrFinalize (ddVelTR v (max (-0.2) (min 0.2 omega)))

-- A straight corridor of unit wall segments running east, 1.2 to 2.5 m
-- wide, 5 to 8 m long, somewhere in the notes' world; one SimbotA at its
-- west end, heading roughly east, its left edge 0.1 to 0.5 m from the
-- northern wall.
genCorridor :: Gen WorldTemplate
genCorridor = do
  width  <- choose (1.2, 2.5)
  len    <- chooseInt (5, 8)
  yc     <- choose (-3, 3)
  gap    <- choose (0.1, 0.5)
  h      <- choose (-0.2, 0.2)
  let x0    = -4.5
      north = yc + width / 2
      south = yc - width / 2
      walls = [ OTHWall (Point2 (x0 + 0.5 + fromIntegral k) y) | y <- [north, south], k <- [0 .. len - 1] ]
      robotY = north - wallThickness / 2 - gap - simbotDiameter / 2
  pure (OTSimbotA 1 (Point2 (x0 + 0.5) robotY) h : walls)

-- How long a corridor's robot is watched. The property is false beyond
-- the corridor: where the wall on its left ends or has a gap, the notes'
-- follower turns left towards where it expects the wall and drives into the
-- end of the next segment (shrunk to a robot and one wall segment ahead on
-- its left: docs/TESTING.md). So the robot is watched for 12 s, in which
-- at 0.3 m/s it drives at most 3.6 m and stays in the shortest corridor
-- (5 m). A fixed time, so that a world that loses objects while shrinking
-- runs as long.
corridorTime :: Double
corridorTime = 12

-- The robot in the corridor never comes closer to a wall than the given
-- clearance. (The physics stops a robot at contact, within a nanometre of
-- the wall, so overlapping is impossible; touching is the failure.)
keepsClear :: Double -> WorldTemplate -> TPred WorldState
keepsClear margin w = Always (SP (arr (all ((> margin) . robotClearance w) . wsRobots)))

-- A ball's speed (from its positions at the last three samples, the time
-- step apart) grows only when something was near enough to touch it at
-- one of the last two samples: a robot, another ball, or (for a bounce,
-- which can turn a slowing ball around) a wall, block or the world's edge.
ballsSpeedUpOnlyOnContact :: DTime -> WorldTemplate -> TPred WorldState
ballsSpeedUpOnlyOnContact dt world = Always $ SP $ proc ws -> do
  prev  <- iPre Nothing -< Just ws
  prev2 <- iPre Nothing -< prev
  returnA -< case (prev2, prev) of
    (Just w0, Just w1) -> and
      [ speed b1 b2 <= speed b0 b1 + 1e-9 || near w1 b1 || near ws b2
      | (b0, b1, b2) <- zip3 (wsBalls w0) (wsBalls w1) (wsBalls ws) ]
    _ -> True
  where
    speed (Point2 ax ay) (Point2 bx by) = sqrt ((bx - ax) ^ (2 :: Int) + (by - ay) ^ (2 :: Int)) / dt
    reach = 0.15
    near w b =
      any (\r -> dist (robotPos r) b < (simbotDiameter + ballDiameter) / 2 + reach) (wsRobots w)
      || length (filter (\o -> dist o b < ballDiameter + reach) (wsBalls w)) > 1
      || any (\o -> boxDist b (objectBox o) < ballDiameter / 2 + reach) (filter isObstacle world)
      || nearEdge b
    nearEdge (Point2 x y) = minimum [x - worldXMin, worldXMax - x, y - worldYMin, worldYMax - y] < ballDiameter / 2 + reach
    isObstacle OTBlock {} = True
    isObstacle OTVWall {} = True
    isObstacle OTHWall {} = True
    isObstacle _          = False
    dist (Point2 ax ay) (Point2 bx by) = sqrt ((bx - ax) ^ (2 :: Int) + (by - ay) ^ (2 :: Int))
    boxDist (Point2 x y) (x0, y0, x1, y1) =
      let gx = maximum [0, x0 - x, x - x1]
          gy = maximum [0, y0 - y, y - y1]
      in sqrt (gx * gx + gy * gy)

spec :: Spec
spec = do
  specWithoutFiles
  -- (the failing worlds and pages the properties write go into a folder
  -- of this run's own, not under fixed names in the shared TMPDIR, made
  -- only if one of these tests runs; it is removed at the end only if
  -- empty: a property that fails leaves its shrunk world there, where its
  -- message says)
  beforeAll privateTempDir $ afterAll (\tmp -> () <$ (try (removeDirectory tmp) :: IO (Either IOError ())))
    specWithFiles

-- A new, empty folder in the temporary directory.
privateTempDir :: IO FilePath
privateTempDir = do
  tmp <- getTemporaryDirectory
  let go k = do
        let d = tmp </> ("afrp-test-spec-" ++ show (k :: Int))
        r <- try (createDirectory d)
        case r of
          Right () -> pure d
          Left e | isAlreadyExistsError e && k < 100000 -> go (k + 1)
                 | otherwise -> ioError e
  go 0

-- The tests that write no file.
specWithoutFiles :: Spec
specWithoutFiles = do
  it "random worlds are valid (property)" $
    forAll (genWorld defaultWorldMix notesBounds) $ \w ->
      counterexample (renderWorld w) (validateWorld w === Right ())

  it "robotView follows one robot through a run (fixed)" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0, OTSimbotB 1 (Point2 2 2) 0]
        run   = runStream defaultSimConfig { simDt = 0.1 } 2 world wander rcBrake
        viewB = robotView "SimbotB" 1 run
    length run `shouldBe` 21
    map fst viewB `shouldBe` map fst run
    evalT (Always (SP (arr ((== Point2 2 2) . robotPos)))) viewB `shouldBe` True
    evalT (Eventually (SP (arr ((/= Point2 0 0) . robotPos)))) (robotView "SimbotA" 1 run) `shouldBe` True
    -- a robot that is not in the run is an error naming it, never an
    -- empty view every property would hold of
    evaluate (length (robotView "SimbotA" 2 run))
      `shouldThrow` errorCall "AFrobRobotSim.Test.robotView: no SimbotA 2 in the run (its robots: SimbotA 1, SimbotB 1)"
    evaluate (length (robotView "SimbotC" 1 run)) `shouldThrow` anyErrorCall
    -- lazy: the view of a run of 10^6 s starts at once (it looked at every
    -- sample first), and a hand-made stream that loses the robot is the
    -- error where it does
    let long = runStream defaultSimConfig 1e6 world wander rcBrake
    r <- timeout (60 * 1000000) (evaluate (length (take 3 (robotView "SimbotA" 1 long))))
    r `shouldBe` Just 3
    let emptied = [ (dt, ws { wsRobots = [] }) | (dt, ws) <- take 1 (drop 2 run) ]
    evaluate (length (robotView "SimbotB" 1 (take 2 run ++ emptied)))
      `shouldThrow` errorCall "AFrobRobotSim.Test.robotView: no SimbotB 1 in the run at sample 2 (its robots there: none)"

  it "onRobot is the predicate of the robot's view: it holds and is decided false as there (fixed)" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0, OTSimbotB 1 (Point2 2 2) 0]
        run   = runStream defaultSimConfig { simDt = 0.1 } 2 world wander rcBrake
        xOf r = let Point2 x _ = robotPos r in x
        -- (one of them with state: the robot's x never falls back)
        preds = [ Always (SP (arr ((== Point2 2 2) . robotPos)))
                , Always (SP (arr ((< 0.5) . xOf)))
                , Eventually (SP (arr ((> 0.3) . xOf)))
                , eventuallyWithin 0.5 (SP (arr ((> 0.3) . xOf)))
                , Always (SP (proc r -> do { x0 <- iPre 0 -< xOf r; returnA -< xOf r >= x0 })) ]
        instant = fmap (\e -> (explFrame e, explTime e))
    forM_ [("SimbotA", 1), ("SimbotB", 1)] $ \(ty, i) -> forM_ preds $ \p -> do
      evalT (onRobot ty i p) run `shouldBe` evalT p (robotView ty i run)
      instant (explainT (onRobot ty i p) run) `shouldBe` instant (explainT p (robotView ty i run))
    -- (a property of robot B that robot A breaks, and the other way round)
    map (\ty -> evalT (onRobot ty 1 (head preds)) run) ["SimbotA", "SimbotB"] `shouldBe` [False, True]
    map (\ty -> evalT (onRobot ty 1 (Always (SP (arr ((/= Point2 2 2) . robotPos))))) run) ["SimbotA", "SimbotB"]
      `shouldBe` [True, False]

  it "onRobot of a robot not in the run is an error naming it and the robots there, whatever the predicate reads" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0, OTSimbotB 1 (Point2 2 2) 0]
        run   = runStream defaultSimConfig { simDt = 0.1 } 2 world wander wander
        anything = Always (SP (arr (const True)))
    evaluate (evalT (onRobot "SimbotA" 2 anything) run)
      `shouldThrow` errorCall "AFrobRobotSim.Test.onRobot: no SimbotA 2 in the run (its robots: SimbotA 1, SimbotB 1)"
    evaluate (evalT (onRobot "simbotA" 1 (Eventually (SP (arr robotStuck)))) run)
      `shouldThrow` errorCall "AFrobRobotSim.Test.onRobot: no simbotA 1 in the run (its robots: SimbotA 1, SimbotB 1)"
    evaluate (fmap explFrame (explainT (onRobot "SimbotB" 3 (Not anything)) run)) `shouldThrow` anyErrorCall
    -- (a hand-made stream that loses the robot: the error at that sample)
    let emptied = [ (dt, ws { wsRobots = [] }) | (dt, ws) <- take 1 (drop 2 run) ]
    evaluate (evalT (onRobot "SimbotB" 1 (Always (SP (arr ((== 1) . robotId))))) (take 2 run ++ emptied))
      `shouldThrow` errorCall "AFrobRobotSim.Test.onRobot: no SimbotB 1 in the run at sample 2 (its robots there: none)"
    -- (runT reports it as the failure)
    result <- quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
      runT defaultSimConfig 1 wander wander (onRobot "SimbotB" 2 anything) world
    isSuccess result `shouldBe` False
    output result `shouldSatisfy` ("no SimbotB 2 in the run (its robots: SimbotA 1, SimbotB 1)" `isInfixOf`)

  it "hasRobot says whether a world has the robot of a type and id, the one onRobot finds in its runs" $ do
    let robotA = OTSimbotA 1 (Point2 0 0) 0
        robotB = OTSimbotB 2 (Point2 2 2) 0
        others = [OTSize 12 12, OTBlock (Point2 (-3) (-3)), OTBall (Point2 3 3)]
        world = robotA : robotB : others
    map (\(ty, i) -> hasRobot ty i world) [("SimbotA", 1), ("SimbotB", 2)] `shouldBe` [True, True]
    -- (without it; a robot of the other type with its id; a type misspelt)
    map (\(ty, i) -> hasRobot ty i world) [("SimbotA", 2), ("SimbotB", 1), ("simbotA", 1), ("SimbotC", 1)]
      `shouldBe` [False, False, False, False]
    hasRobot "SimbotA" 1 (robotB : others) `shouldBe` False
    hasRobot "SimbotB" 2 [robotA] `shouldBe` False
    hasRobot "SimbotA" 1 [] `shouldBe` False
    -- (the robots it finds are those onRobot finds in the world's run)
    let run = runStream defaultSimConfig { simDt = 0.1 } 0.5 world wander wander
        found ty i = try (evaluate (evalT (onRobot ty i (Always (SP (arr (const True))))) run))
                       :: IO (Either ErrorCall Bool)
    forM_ [ (ty, i) | ty <- ["SimbotA", "SimbotB"], i <- [1, 2] ] $ \(ty, i) ->
      (either (const False) id <$> found ty i) `shouldReturn` hasRobot ty i world

  it "runReplayPage counts the samples as the log does, the one at time 0 included" $ do
    let page = runReplayPage defaultSimConfig { simDt = 0.1 } 1 [OTSimbotA 1 (Point2 0 0) 0] wander wander
    pageSummary page `shouldSatisfy` ("\"steps\":11," `isInfixOf`)

  it "runT of a run as long as a deadline decides it (a 20 s run passed eventuallyWithin 20 of a p that never held)" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0]
        neverTrue = SP (arr (const False))
        check d bound = quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
          runT defaultSimConfig { simDt = 0.05 } d rcBrake rcBrake (eventuallyWithin bound neverTrue) world
    atDeadline <- check 20 20
    case atDeadline of
      Failure {} -> output atDeadline `shouldSatisfy` ("decided false at t = 20.00" `isInfixOf`)
      _          -> expectationFailure ("a run as long as the deadline passed: " ++ output atDeadline)
    -- a run that ends before the deadline has not missed it
    beforeDeadline <- check 19.9 20
    isSuccess beforeDeadline `shouldBe` True

  it "runStream refuses a duration that is negative or not finite; 0 is the sample at time 0" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0]
        run d = runStream defaultSimConfig { simDt = 0.1 } d world wander wander
    length (run 0) `shouldBe` 1
    evaluate (length (run (-1))) `shouldThrow` anyErrorCall
    evaluate (length (run (0 / 0))) `shouldThrow` anyErrorCall
    evaluate (length (run (1 / 0))) `shouldThrow` anyErrorCall
    -- a count of steps past an Int's range made an empty stream
    evaluate (length (run 1e20)) `shouldThrow`
      errorCall "AFrobRobotSim.Test.runStream: a duration of 1.0e20 s is more than 2^53 time steps of 0.1 s"
    take 2 (map fst (run 9e14)) `shouldBe` [0, 0.1]

  it "runStream refuses a time step that is 0, negative or not finite (every property would hold of no sample)" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0]
        run dt = runStream defaultSimConfig { simDt = dt } 30 world wander wander
        refused dt = evaluate (length (run dt)) `shouldThrow` errorCall
          ("AFrobRobotSim.Test.runStream: the time step (simDt) must be a finite number > 0, got " ++ show dt)
    mapM_ refused [0, -0.01, 0 / 0, 1 / 0]
    length (run 0.5) `shouldBe` 61

  it "shrinkWorld removes objects, never the world's size (without it the objects may not fit)" $ do
    let w = [OTSize 20 20, OTSimbotB 1 (Point2 7 0) 0, OTBlock (Point2 (-8) (-8))]
        isSize o = case o of { OTSize {} -> True; _ -> False }
    shrinkWorld w `shouldBe` [[OTSize 20 20, OTSimbotB 1 (Point2 7 0) 0]]
    all (\c -> validateWorld c == Right ()) (shrinkWorld w) `shouldBe` True
    let big = OTSize 30 30 : [ OTBall (Point2 (fromIntegral k) 0) | k <- [-6 .. 6 :: Int] ]
    shrinkWorld big `shouldSatisfy` all (\c -> length (filter isSize c) == 1 && head c == OTSize 30 30)
    length (shrinkWorld big) `shouldBe` 2 + 13

  it "shrinkWorld keeps a world's last robot (a property of any robot failed for want of one, shrunk to no object)" $ do
    let robotA = OTSimbotA 1 (Point2 0 0) 0
        robotB = OTSimbotB 1 (Point2 2 2) 0
        others = [OTBlock (Point2 (-3) (-3)), OTHWall (Point2 3 (-3)), OTBall (Point2 (-3) 3)]
    shrinkWorld (robotA : others) `shouldSatisfy` all (elem robotA)
    length (shrinkWorld (robotA : others)) `shouldBe` 3
    -- (one of two robots may go, not both; a world of no robot loses
    -- anything, as before)
    shrinkWorld [robotA, robotB] `shouldBe` [[robotB], [robotA]]
    shrinkWorld others `shouldBe` [drop 1 others, [head others, others !! 2], take 2 others]
    let many = robotA : [ OTBall (Point2 (fromIntegral k) 0) | k <- [-4 .. 4 :: Int] ]
    shrinkWorld many `shouldSatisfy` all (any isRobot)
    -- a property of some robot that no world satisfies shrinks to the
    -- robot alone, never to the empty world (or to robotView's error of
    -- a robot gone)
    result <- quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
      forAllShrinkShow (pure (robotA : others)) shrinkWorld renderWorld $ \world ->
        let run = runStream defaultSimConfig { simDt = 0.1 } 1 world wander wander
        in evalT (Eventually (SP (arr ((> 100) . (\(Point2 x _) -> x) . robotPos)))) (robotView "SimbotA" 1 run)
    case result of
      Failure { failingTestCase = shown : _ } -> shown `shouldBe` renderWorld [robotA]
      _ -> expectationFailure ("not a falsified property: " ++ output result)

  it "worldFileText gives a world run in other bounds the size line that says them" $ do
    let w = [OTSimbotB 1 (Point2 7 0) 0]
        wide = defaultSimConfig { simBounds = Bounds (-10) (-10) 10 10 }
    parseWorld "w" (worldFileText wide w) `shouldBe` Right (OTSize 20 20 : w)
    worldFileText defaultSimConfig w `shouldBe` renderWorld w
    worldFileText wide (OTSize 30 30 : w) `shouldBe` renderWorld (OTSize 30 30 : w)
    -- (bounds not centred: said in a comment, the objects as they are)
    let offset = defaultSimConfig { simBounds = Bounds 0 0 20 20 }
    worldFileText offset w `shouldSatisfy` ("# the run's world was [0.0, 20.0] x [0.0, 20.0]" `isPrefixOf`)
    parseWorld "w" (worldFileText offset w) `shouldBe` Right w

  it "worldFileText says centred bounds with a side a world file refuses (below 1 m, above 1000 m) in a comment (it wrote a size line no world file reads)" $ do
    let w = [OTSimbotA 1 (Point2 0 0) 0]
    forM_ [(2000, 2000), (0.8, 0.8), (1500, 10), (10, 0.9)] $ \(width, height) -> do
      let config = defaultSimConfig { simBounds = sizeBounds width height }
          text = worldFileText config w
      -- (a run in them is made)
      length (runStream config 0.1 w wander wander) `shouldBe` 11
      text `shouldSatisfy` (("# the run's world was [" ++ show (negate width / 2) ++ ", " ++ show (width / 2) ++ "]") `isPrefixOf`)
      text `shouldSatisfy` ("(centred, each side 1 to 1000 m) cannot say\n" `isInfixOf`)
      parseWorld "w" text `shouldBe` Right w
    -- (the sides a size line says, 1 and 1000 m, still get one)
    forM_ [(1, 1000), (1000, 1)] $ \(width, height) ->
      parseWorld "w" (worldFileText defaultSimConfig { simBounds = sizeBounds width height } w) `shouldBe` Right (OTSize width height : w)

  it "showWorldState writes the time with the decimals its step needs (at least 2)" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0]
        times dt = map (takeWhile (/= ' ') . showWorldState . snd)
                       (runStream defaultSimConfig { simDt = dt } (3 * dt) world wander wander)
    times 0.02 `shouldBe` ["t=0.00", "t=0.02", "t=0.04", "t=0.06"]
    times 0.001 `shouldBe` ["t=0.00", "t=0.001", "t=0.002", "t=0.003"]

  it "showWorldState writes each robot's signed speed (v=, negative when it backs)" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0]
        backs = const (arr (const (mrFinalize (ddVelTR (-0.3) 0))))
        (_, final) = last (runStream defaultSimConfig 1 world backs backs)
        v = robotSpeed (head (wsRobots final))
    v `shouldSatisfy` (< -0.05)
    showWorldState final `shouldSatisfy` ((" h=0.00 v=" ++ showFFloat (Just 2) v "") `isInfixOf`)

  it "genWorld refuses bounds that are no extent and an empty range of the mix (it gave an empty world)" $ do
    let gen m b = generate (genWorld m b) >>= evaluate . length
    gen defaultWorldMix (Bounds 5 5 (-5) (-5)) `shouldThrow`
      errorCall "AFrobRobotSim.Test.genWorld: the bounds Bounds 5.0 5.0 (-5.0) (-5.0) are no extent (finite, x0 < x1, y0 < y1)"
    gen defaultWorldMix (Bounds (0 / 0) 0 1 1) `shouldThrow` anyErrorCall
    gen defaultWorldMix { mixRobots = (5, 1) } notesBounds `shouldThrow`
      errorCall "AFrobRobotSim.Test.genWorld: the range (5,1) of mixRobots is empty"
    gen defaultWorldMix { mixRobots = (1, 1) } notesBounds `shouldNotReturn` 0

  it "genWorld refuses bounds too small for a simbot when the mix asks for a robot" $ do
    let gen m b = generate (genWorld m b) >>= evaluate . length
    gen defaultWorldMix (sizeBounds 0.4 3) `shouldThrow`
      errorCall "AFrobRobotSim.Test.genWorld: the bounds Bounds (-0.2) (-1.5) 0.2 1.5 are too small for a simbot (0.5 m across), and mixRobots asks for at least one"
    -- (a mix that may have no robot gets the objects that fit)
    w <- generate (genWorld defaultWorldMix { mixRobots = (0, 2), mixBalls = (3, 3) } (sizeBounds 0.4 3))
    filter isRobot w `shouldBe` []
    validateWorldIn (sizeBounds 0.4 3) w `shouldBe` Right ()

  it "genWorld places the robots first: a small world gets one when the mix asks for one (it got none in half of 2 m worlds) (property)" $
    forAll (elements [0.5, 0.6, 1, 2, 3]) $ \side ->
      forAll (genWorld defaultWorldMix (sizeBounds side side)) $ \w ->
        counterexample (renderWorld w) $
          not (null [ () | o <- w, isRobot o ]) .&&. validateWorldIn (sizeBounds side side) w === Right ()

  it "genWorld numbers the robots placed 1, 2, ... per type (it skipped the ids of robots that found no spot) (property)" $
    forAll (elements [1, 2, 10]) $ \side ->
      forAll (genWorld defaultWorldMix { mixRobots = (1, 12) } (sizeBounds side side)) $ \w ->
        counterexample (renderWorld w) $
          [ i | OTSimbotA i _ _ <- w ] === [1 .. fromIntegral (length [ () | OTSimbotA {} <- w ])]
          .&&. [ i | OTSimbotB i _ _ <- w ] === [1 .. fromIntegral (length [ () | OTSimbotB {} <- w ])]

  it "genRobotIn places a robot in a world with a size line, inside that size (it failed on otPos)" $
    forAll (genRobotIn notesBounds [OTSize 30 4, OTSimbotA 1 (Point2 0 0) 0]) $ \w ->
      counterexample (renderWorld w) $
        length [ () | o <- w, isRobot o ] === 2 .&&. validateWorld w === Right ()
        .&&. all (\o -> not (isRobot o) || let (x0, y0, x1, y1) = objectBox o in x0 >= -15 && x1 <= 15 && y0 >= -2 && y1 <= 2) w

  it "showWorldState writes a value that is not a finite number as such (it wrote hundreds of digits)" $ do
    let world = [OTSimbotA 1 (Point2 0 0) 0]
        (_, ws) = head (runStream defaultSimConfig 0 world wander wander)
        r = head (wsRobots ws)
        odd' = ws { wsTime = 0 / 0, wsRobots = [r { robotHeading = 1 / 0, robotPos = Point2 (-1 / 0) 0 }] }
    showWorldState odd' `shouldBe` "t=NaN  SimbotA 1 (-Infinity, 0.000) h=Infinity v=0.00"

-- The tests that write files, each given the run's own folder.
specWithFiles :: SpecWith FilePath
specWithFiles = do
  it "robots never overlap each other (property)" $ \tmp ->
    forAllWorlds (tmp </> "afrp-test-robots.world") (genWorld defaultWorldMix { mixRobots = (2, 8) } notesBounds) $
      runT defaultSimConfig { simDt = 0.05 } 10 wander wander
           (Always (SP (arr (\ws -> robotGap ws >= -1e-9))))

  it "a ball speeds up only when something touches it (property)" $ \tmp ->
    forAllWorlds (tmp </> "afrp-test-balls.world")
                 (genWorld defaultWorldMix { mixBalls = (1, 4), mixRobots = (1, 5) } notesBounds) $ \w ->
      runT defaultSimConfig { simDt = 0.05 } 15 wander wander (ballsSpeedUpOnlyOnContact 0.05 w) w

  it "the notes' wall follower never comes within 1 mm of a wall in random corridors (property)" $ \tmp ->
    forAllWorlds (tmp </> "afrp-test-corridor.world") genCorridor $ \w ->
      runT defaultSimConfig { simDt = 0.02 } corridorTime (rcFollowLeftWall 0.3 0.25) wander
           (keepsClear 1e-3 w) w

  it "a wall follower steering the wrong way is caught, in a world of at most 3 objects (property)" $ \tmp -> do
    let file = tmp </> "afrp-test-broken.world"
    result <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen 3, 0) } $
      forAllWorlds file genCorridor $ \w ->
        runT defaultSimConfig { simDt = 0.02 } corridorTime (rcFollowLeftWallBroken 0.3 0.25) wander
             (keepsClear 1e-3 w) w
    case result of
      Failure { failingTestCase = shown : _ } -> do
        written <- readWorldFile file
        removeFile file
        fmap length written `shouldSatisfy` either (const False) (<= 3)
        fmap renderWorld written `shouldBe` Right shown
        output result `shouldSatisfy` ("decided false at t = " `isInfixOf`)
      _ -> expectationFailure ("the broken wall follower was not caught: " ++ output result)

  it "runT of a failure early in a very long run runs and explains only the start of it (it ran the whole run)" $ \_ -> do
    -- (a robot that drives off at 2 m/s leaves its place within the first
    -- second of a run of 10^6 s)
    let world = [OTSimbotA 1 (Point2 0 0) 0]
    r <- timeout (60 * 1000000) $ quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
      runT defaultSimConfig 1e6 wander wander (Always (SP (arr (all ((== Point2 0 0) . robotPos) . wsRobots)))) world
    case r of
      Just result@Failure {} -> output result `shouldSatisfy` ("decided false at t = 0.01 (step 1)" `isInfixOf`)
      Just result            -> expectationFailure ("the run was not found to fail: " ++ output result)
      Nothing                -> expectationFailure "runT did not end within 60 s"

  it "forAllRuns of a failure in a very long run writes a page up to 5 s past the instant that decided (it made the whole run's page)" $ \tmp -> do
    -- (the run is 10^6 s, 10^8 steps of 0.01 s: its whole page, or a
    -- decision or explanation that reads the run to its end, would not
    -- end within the timeout. The world is one robot, which shrinking
    -- keeps, so no world smaller that passes, and so is run whole, is
    -- tried. The robot stands still for 3 s, then drives off: decided at
    -- 3.01 s, the page's 5 s reach to 8.01 s, which a page ending 5 s
    -- after the run's start, or at the instant, or where explaining
    -- stopped reading, does not)
    let file = tmp </> "afrp-test-early.world"
        world = [OTSimbotA 1 (Point2 0 0) 0]
        drivesAt3 _ = localTime >>> arr (\t -> mrFinalize (ddVelTR (if t < 3 then 0 else 1) 0))
    r <- timeout (60 * 1000000) $ quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
      forAllRuns file defaultSimConfig 1e6 drivesAt3 drivesAt3 (pure world)
        (\_ -> Always (SP (arr (all ((== Point2 0 0) . robotPos) . wsRobots))))
    case r of
      Just result@Failure {} -> do
        page <- readFile (file ++ ".html")
        length page `seq` mapM_ removeFile [file, file ++ ".html"]
        decidedLines result `shouldBe` ["decided false at t = 3.01 (step 301):"]
        pageSummary page `shouldSatisfy` ("\"falsified\":{\"t\":3.01" `isInfixOf`)
        -- (frames at 25 a second from time 0 to 8.00 s)
        occurrences "\"frame\"" page `shouldBe` 201
      Just result -> expectationFailure ("the run was not found to fail: " ++ output result)
      Nothing     -> expectationFailure "forAllRuns did not end within 60 s"

  it "forAllWorlds and forAllRuns that cannot write the world or page still report the failure and say so (the write's exception hid it)" $ \tmp -> do
    let missing = tmp </> "no-such-folder" </> "afrp-test-unwritable.world"
        world = [OTSimbotA 1 (Point2 0 0) 0]
        staysPut = Always (SP (arr (all ((== Point2 0 0) . robotPos) . wsRobots)))
        check = quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 }
    viaWorlds <- check (forAllWorlds missing (pure world) (runT defaultSimConfig 1 wander wander staysPut))
    viaRuns <- check (forAllRuns missing defaultSimConfig 1 wander wander (pure world) (const staysPut))
    doesDirectoryExist (tmp </> "no-such-folder") `shouldReturn` False
    forM_ [viaWorlds, viaRuns] $ \result -> do
      (case result of { Failure {} -> True; _ -> False }) `shouldBe` True
      output result `shouldSatisfy` ("decided false at t = 0.01 (step 1)" `isInfixOf`)
      output result `shouldSatisfy` (("(the world could not be written to " ++ missing ++ ": openFile: does not exist") `isInfixOf`)
      output result `shouldNotSatisfy` ("Exception running callback" `isInfixOf`)
      output result `shouldNotSatisfy` ("the world is written to" `isInfixOf`)
    output viaRuns `shouldSatisfy` (("its run's replay page could not be written to " ++ missing ++ ".html: ") `isInfixOf`)
    -- (the file's name once: the I/O failure's message begins with it)
    output viaRuns `shouldNotSatisfy` ((missing ++ ": " ++ missing) `isInfixOf`)
    -- (only the failure's: a verbose check that passes writes nothing)
    let quiet = tmp </> "afrp-test-verbose.world"
        stays = Always (SP (arr (const True)))
    passed <- check (verbose (forAllWorlds quiet (pure world) (runT defaultSimConfig 1 wander wander stays)))
    passedRuns <- check (verbose (forAllRuns quiet defaultSimConfig 1 wander wander (pure world) (const stays)))
    map isSuccess [passed, passedRuns] `shouldBe` [True, True]
    mapM doesFileExist [quiet, quiet ++ ".html"] `shouldReturn` [False, False]

  it "forAllRuns that cannot make the page for a reason other than the write's says it could not be made, and why" $ \tmp -> do
    -- (a world the simulator refuses, its robot on a block: the run's
    -- error is no I/O failure. The property fails with it; shrinking
    -- finds the robot alone, which passes, so this world is reported,
    -- and its file is written, the page not)
    let file = tmp </> "afrp-test-unmade.world"
        world = [OTSimbotA 1 (Point2 0 0) 0, OTBlock (Point2 0 0)]
    refused <- try (evaluate (null (simulateWith defaultSimConfig world wander wander))) :: IO (Either ErrorCall Bool)
    result <- quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
      forAllRuns file defaultSimConfig 1 wander wander (pure world) (const (Always (SP (arr (const True)))))
    -- (parsed, not read with readWorldFile, which refuses it too)
    written <- readFile file
    length written `seq` removeFile file
    parseWorld file written `shouldBe` Right world
    doesFileExist (file ++ ".html") `shouldReturn` False
    case (refused, result) of
      (Left (ErrorCallWithLocation message _), Failure {}) -> do
        message `shouldSatisfy` ("AFrobRobotSim.simulate: invalid world:" `isPrefixOf`)
        -- (the error's message, without the call stack that QuickCheck
        -- prints with the exception)
        output result `shouldSatisfy` (("(the world is written to " ++ file ++ "; its run's replay page could not be made for "
                                        ++ file ++ ".html: " ++ message ++ ")") `isInfixOf`)
        output result `shouldNotSatisfy` ("could not be written" `isInfixOf`)
        output result `shouldNotSatisfy` ("Exception running callback" `isInfixOf`)
      (Right _, _) -> expectationFailure "the simulator ran a robot on a block"
      (_, _)       -> expectationFailure ("the world the simulator refuses passed: " ++ output result)

  it "forAllRuns of a duration or time step runStream refuses writes no page (it wrote a page of no frame, and said it was written)" $ \tmp -> do
    let file = tmp </> "afrp-test-refused.world"
        world = [OTSimbotA 1 (Point2 0 0) 0]
        refusedBy config duration = do
          result <- quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
            forAllRuns file config duration wander wander (pure world) (const (Always (SP (arr (const True)))))
          pageMade <- doesFileExist (file ++ ".html")
          mapM_ removeFile ([file] ++ [ file ++ ".html" | pageMade ])
          pure (result, pageMade)
    forM_ [ (defaultSimConfig, -1, "the duration must be a finite number >= 0, got -1.0")
          , (defaultSimConfig, 0 / 0, "the duration must be a finite number >= 0, got NaN")
          , (defaultSimConfig, 1e20, "a duration of 1.0e20 s is more than 2^53 time steps")
          , (defaultSimConfig { simDt = 0 }, 1, "the time step (simDt) must be a finite number > 0, got 0.0") ] $
      \(config, duration, why) -> do
        (result, pageMade) <- refusedBy config duration
        (case result of { Failure {} -> True; _ -> False }) `shouldBe` True
        pageMade `shouldBe` False
        output result `shouldSatisfy` (("its run's replay page could not be made for " ++ file ++ ".html: AFrobRobotSim.Test.runStream: "
                                        ++ why) `isInfixOf`)

  it "writeRunReplayPage, which records the run as it goes, writes the page runReplayPage gives" $ \tmp -> do
    let file = tmp </> "afrp-test-page.html"
        config = defaultSimConfig { simDt = 0.03 }
        world = [OTSimbotA 1 (Point2 0 0) 0, OTSimbotB 2 (Point2 2 2) 1, OTBall (Point2 (-2) 1)]
    writeRunReplayPage file config 7 world wander straight
    page <- readFile file
    length page `seq` removeFile file
    page `shouldBe` runReplayPage config 7 world wander straight
    -- (the samples, the one at time 0 included)
    pageSummary page `shouldSatisfy` (("\"steps\":" ++ show (length (runStream config 7 world wander straight)) ++ ",") `isInfixOf`)

  it "writeRunReplayPage and runReplayPage put the referee's last scores in the summary, and end at its failure with its message" $ \tmp -> do
    let file = tmp </> "afrp-test-scores.html"
        world = [OTSimbotA 1 (Point2 0 0) 0]
        counting = defaultSimConfig { simDt = 0.1, simScores = localTime >>> arr (\t -> [("tenths", round (t * 10))]) }
        failing = counting { simScores = localTime >>> arr (\t -> if t > 0.45 then error "no score" else [("n", 1)]) }
    writeRunReplayPage file counting 2 world wander wander
    page <- readFile file
    length page `seq` removeFile file
    pageSummary page `shouldSatisfy` ("\"scores\":{\"tenths\":20" `isInfixOf`)
    pageSummary (runReplayPage counting 2 world wander wander) `shouldSatisfy` ("\"scores\":{\"tenths\":20" `isInfixOf`)
    writeRunReplayPage file failing 2 world wander wander
    failed <- readFile file
    length failed `seq` removeFile file
    pageSummary failed `shouldSatisfy` ("the scores (simScores) failed at t = 0.500 s: no score" `isInfixOf`)
    pageSummary failed `shouldSatisfy` ("\"scores\":{\"n\":1" `isInfixOf`)

  it "writeFalsifiedRunReplayPage writes writeRunReplayPage's page, its summary with the instant a property was decided false and its line" $ \tmp -> do
    let file = tmp </> "afrp-test-falsified.html"
        plainFile = tmp </> "afrp-test-plain.html"
        config = defaultSimConfig { simDt = 0.03 }
        world = [OTSimbotA 1 (Point2 0 0) 0, OTSimbotB 2 (Point2 2 2) 1]
    writeFalsifiedRunReplayPage file config 7 world wander straight (3.5, "decided false at t = 3.50 (step 117)")
    writeRunReplayPage plainFile config 7 world wander straight
    page <- readFile file
    plain <- readFile plainFile
    length page `seq` length plain `seq` mapM_ removeFile [file, plainFile]
    pageSummary page `shouldSatisfy` ("\"falsified\":{\"t\":3.5,\"text\":\"decided false at t = 3.50 (step 117)\"" `isInfixOf`)
    pageSummary plain `shouldNotSatisfy` ("falsified" `isInfixOf`)
    -- (the same header and frames)
    let logLines p = filter ("{\"kind\":\"" `isPrefixOf`) (lines p)
    init (logLines page) `shouldBe` init (logLines plain)
    length (logLines page) `shouldSatisfy` (> 100)

  it "writeRunReplayPage closes its temporary file when the run stops with an exception (it was left open)" $ \tmp -> do
    let world = [OTSimbotA 1 (Point2 0 0) 0]
        file = tmp </> "afrp-test-leak.html"
        openFiles = length <$> listDirectory "/proc/self/fd"
    linux <- doesDirectoryExist "/proc/self/fd"
    if not linux then pendingWith "needs /proc/self/fd" else do
      opened <- openFiles
      -- an error from the run (a negative duration), and a timeout's
      -- exception in the middle of a long run
      mapM_ (\_ -> (try (writeRunReplayPage file defaultSimConfig (-1) world wander wander) :: IO (Either ErrorCall ()))
                     >>= either (const (pure ())) (const (expectationFailure "a negative duration ran")))
            [1 .. 10 :: Int]
      mapM_ (\_ -> timeout 20000 (writeRunReplayPage file defaultSimConfig 1e5 world wander wander)) [1 .. 10 :: Int]
      after' <- openFiles
      after' `shouldBe` opened

  it "forAllRuns writes the shrunk world and its run's replay page (property)" $ \tmp -> do
    let file = tmp </> "afrp-test-broken-runs.world"
    result <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen 3, 0) } $
      forAllRuns file defaultSimConfig { simDt = 0.02 } corridorTime (rcFollowLeftWallBroken 0.3 0.25) wander
        genCorridor (keepsClear 1e-3)
    case result of
      Failure { failingTestCase = shown : _ } -> do
        written <- readWorldFile file
        page <- readFile (file ++ ".html")
        length page `seq` removeFile (file ++ ".html")
        removeFile file
        page `shouldSatisfy` ("<!DOCTYPE html>" `isPrefixOf`)
        page `shouldSatisfy` ("id=\"afrp-log\"" `isInfixOf`)
        occurrences "\"frame\"" page `shouldSatisfy` (> 1)
        fmap length written `shouldSatisfy` either (const False) (<= 3)
        fmap renderWorld written `shouldBe` Right shown
        output result `shouldSatisfy` ("decided false at t = " `isInfixOf`)
        -- (the page's summary has the instant that decided and the line
        -- the output says it with, without its colon: the page says it)
        case ( [ takeWhile (/= ':') l | l <- lines (output result), "decided false at t = " `isPrefixOf` l ]
             , [ takeWhile (/= ',') rest | rest <- tails (pageSummary page), "\"falsified\":{\"t\":" `isPrefixOf` rest ] ) of
          (decided : _, t : _) -> do
            pageSummary page `shouldSatisfy` (("\"text\":\"" ++ decided ++ "\"") `isInfixOf`)
            decided `shouldSatisfy` (("decided false at t = " ++ showFFloat (Just 2) (read (drop 17 t) :: Double) " ") `isPrefixOf`)
          _ -> expectationFailure ("no instant in the output or the page: " ++ output result ++ "\n" ++ pageSummary page)
      _ -> expectationFailure ("the broken wall follower was not caught: " ++ output result)

  it "forAllRuns keeps a world's size while shrinking: the failure found is the one shrunk, in a world file that runs again" $ \tmp -> do
    -- (the size was shrunk away like an object: the robot then ran into
    -- the edge of a 10 m world, or the world became invalid)
    let file = tmp </> "afrp-test-sized.world"
        gen = do x <- choose (6, 8)
                 pure [OTSize 20 20, OTSimbotB 1 (Point2 x 0) 0, OTBlock (Point2 (-8) (-8))]
    result <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen 5, 0) } $
      forAllRuns file defaultSimConfig { simDt = 0.05 } 10 straight straight gen (const neverStuck)
    case result of
      Failure {} -> do
        written <- readWorldFile file
        page <- readFile (file ++ ".html")
        length page `seq` removeFile (file ++ ".html")
        removeFile file
        fmap (filter (\o -> case o of { OTSize {} -> True; _ -> False })) written `shouldBe` Right [OTSize 20 20]
        fmap length written `shouldBe` Right 2
        fmap validateWorld written `shouldBe` Right (Right ())
        output result `shouldSatisfy` ("decided false at t = " `isInfixOf`)
        occurrences "\"frame\"" page `shouldSatisfy` (> 1)
      _ -> expectationFailure ("the robot at the edge was not caught: " ++ output result)

  it "forAllRuns writes a world run in a config's bounds with its size line" $ \tmp -> do
    let file = tmp </> "afrp-test-bounds.world"
        gen = do x <- choose (6, 8)
                 pure [OTSimbotB 1 (Point2 x 0) 0]
        config = defaultSimConfig { simDt = 0.05, simBounds = Bounds (-10) (-10) 10 10 }
    result <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen 5, 0) } $
      forAllRuns file config 10 straight straight gen (const neverStuck)
    case result of
      Failure {} -> do
        written <- readWorldFile file
        removeFile (file ++ ".html")
        removeFile file
        fmap head written `shouldBe` Right (OTSize 20 20)
        fmap validateWorld written `shouldBe` Right (Right ())
      _ -> expectationFailure ("the robot at the edge was not caught: " ++ output result)

  it "forAllRuns writes the page of a run whose controller fails, up to the failure" $ \tmp -> do
    let file = tmp </> "afrp-test-throws.world"
        throwsAt3 _ = proc _ -> do
          t <- localTime -< ()
          returnA -< if t >= 3 then error "gave up" else mrFinalize (ddVelTR 0.2 0)
        nanDrive _ = proc _ -> do
          t <- localTime -< ()
          returnA -< mrFinalize (ddVelTR (if t >= 3 then 0 / 0 else 0.2) 0)
    mapM_ (\(rc, what) -> do
            result <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen 5, 0) } $
              forAllRuns file defaultSimConfig { simDt = 0.05 } 10 rc rc
                (pure [OTSimbotA 1 (Point2 0 0) 0]) (const neverStuck)
            case result of
              Failure {} -> do
                page <- readFile (file ++ ".html")
                length page `seq` removeFile (file ++ ".html")
                removeFile file
                pageSummary page `shouldSatisfy` (what `isInfixOf`)
                -- (the run up to 3 s: a frame at every step of 0.05 s, a step
                -- being longer than a 25th of a second; 60, from time 0 to 2.95)
                occurrences "\"frame\"" page `shouldBe` 60
                output result `shouldSatisfy` (not . ("Exception running callback" `isInfixOf`))
              _ -> expectationFailure ("the failing controller passed: " ++ output result))
          [(throwsAt3, "gave up"), (nanDrive, "NaN")]

  it "forAllRuns: a predicate that throws ends the page 5 s past the last sample it read (the page was of the whole run: of 10^6 s, it never ended)" $ \tmp -> do
    let file = tmp </> "afrp-test-pred-throws.world"
        oops = Always (SP (arr (\ws -> wsTime ws < 1 || error "the predicate gave up")))
    -- (the page of the whole run of 10^6 s would take hours: a timeout
    -- makes that a failure)
    r <- timeout (60 * 1000000) $ quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
      forAllRuns file defaultSimConfig { simDt = 0.05 } 1e6 rcBrake rcBrake (pure [OTSimbotA 1 (Point2 0 0) 0]) (const oops)
    case r of
      Nothing -> expectationFailure "the property did not end within 60 s"
      Just result@Failure {} -> do
        page <- readFile (file ++ ".html")
        length page `seq` mapM_ removeFile [file, file ++ ".html"]
        output result `shouldSatisfy` ("the predicate gave up" `isInfixOf`)
        -- (explaining read up to the sample that threw, at 1 s: a frame
        -- at every step of 0.05 s from time 0 to 6 s)
        occurrences "\"frame\"" page `shouldBe` 121
      Just result -> expectationFailure ("the predicate that throws passed: " ++ output result)

  it "forAllRuns: a controller that fails soon after the instant that decided ends the page there (it gave a page of no frame)" $ \tmp -> do
    -- (decided false at 1 s; the controller fails at 1.2 s, within the
    -- stretch that explaining reads)
    let file = tmp </> "afrp-test-fails-after.world"
        gaveUp _ = localTime >>> arr (\t -> if t >= 1.2 then error "gave up" else mrFinalize (ddVelTR 0.2 0))
    result <- quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
      forAllRuns file defaultSimConfig 10 gaveUp gaveUp (pure [OTSimbotA 1 (Point2 0 0) 0])
        (\_ -> Always (SP (arr ((< 1) . wsTime))))
    case result of
      Failure {} -> do
        page <- readFile (file ++ ".html")
        length page `seq` mapM_ removeFile [file, file ++ ".html"]
        pageSummary page `shouldSatisfy` ("gave up" `isInfixOf`)
        -- (frames at 25 a second up to the step before 1.2 s: 0 to 1.16)
        occurrences "\"frame\"" page `shouldBe` 30
      _ -> expectationFailure ("the run was not found to fail: " ++ output result)

  it "forAllRuns runs the world it reports twice, once to decide and explain it and once for its page (it ran it four times)" $ \tmp -> do
    -- (one robot, so that a start of its controller is a run; shrinking
    -- keeps a world's only robot, so it tries no other world)
    let file = tmp </> "afrp-test-runs.world"
        world = pure [OTSimbotA 1 (Point2 0 0) 0]
        runsOf rc p = do
          starts <- newIORef 0
          result <- quickCheckWithResult stdArgs { chatty = False, maxSuccess = 3 } $
            forAllRuns file defaultSimConfig { simDt = 0.05 } 10 (countingStarts starts rc) (countingStarts starts rc)
              world (const p)
          n <- readIORef starts
          pure (isSuccess result, n)
        throwsAt3 _ = localTime >>> arr (\t -> if t >= 3 then error "gave up" else mrFinalize (ddVelTR 0.2 0))
    -- (a robot driving into the world's edge gets stuck after about 4 s)
    runsOf straight neverStuck `shouldReturn` (False, 2)
    -- (a controller that fails: deciding stops at the failure, which
    -- the page then shows; it ran it three times)
    runsOf throwsAt3 neverStuck `shouldReturn` (False, 2)
    -- (a predicate that throws: the page ends 5 s past where deciding
    -- stopped)
    runsOf straight (Always (SP (arr (\ws -> wsTime ws < 1 || error "the predicate gave up")))) `shouldReturn` (False, 2)
    mapM_ removeFile [file, file ++ ".html"]
    -- (three worlds that pass, each run once)
    runsOf straight (Always (SP (arr (const True)))) `shouldReturn` (True, 3)

  it "forAllRuns of a predicate on one robot (onRobot) reports and writes the page as of the world's predicate" $ \tmp -> do
    -- (a world of one robot, so that "no robot is stuck" and "SimbotB 1 is
    -- not stuck" are one property: the same failure, report and page)
    let file = tmp </> "afrp-test-one-robot.world"
        gen = do x <- choose (0, 3)
                 pure [OTSimbotB 1 (Point2 x 0) 0, OTBall (Point2 (-3) (-3))]
        check p = do
          result <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen 5, 0) } $
            forAllRuns file defaultSimConfig { simDt = 0.05 } 10 straight straight gen (const p)
          page <- readFile (file ++ ".html")
          length page `seq` mapM_ removeFile [file, file ++ ".html"]
          pure (result, page)
    (viaWorld, worldPage) <- check neverStuck
    (viaRobot, robotPage) <- check (onRobot "SimbotB" 1 (Always (SP (arr (not . robotStuck)))))
    isSuccess viaRobot `shouldBe` False
    output viaRobot `shouldBe` output viaWorld
    robotPage `shouldBe` worldPage
    -- (the time in runT's words, the world states in showWorldState's)
    output viaRobot `shouldSatisfy` ("decided false at t = " `isInfixOf`)
    [ l | l <- lines (output viaRobot), "  > t=" `isPrefixOf` l ] `shouldSatisfy` (\ls -> length ls == 1 && all ("SimbotB 1 (" `isInfixOf`) ls)
    output viaRobot `shouldNotSatisfy` ("RobotState" `isInfixOf`)
    pageSummary robotPage `shouldSatisfy` ("\"falsified\":{\"t\":" `isInfixOf`)

  it "forAllRuns of one robot among several names the instant that robot decided, and shrinks to a world with it" $ \tmp -> do
    -- (SimbotA drives into the world's edge; SimbotB stands still: only
    -- a property of SimbotA fails. Worlds without SimbotA, which
    -- shrinking tries, get a predicate that holds)
    let file = tmp </> "afrp-test-robot-of-two.world"
        world = [OTSimbotB 1 (Point2 (-2) 2) 0, OTSimbotA 1 (Point2 3 0) 0, OTBlock (Point2 (-3) (-3))]
        notStuck = Always (SP (arr (not . robotStuck)))
        ofRobot ty w = if hasRobot ty 1 w then onRobot ty 1 notStuck else Always (SP (arr (const True)))
        check ty = quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
          forAllRuns file defaultSimConfig { simDt = 0.05 } 10 straight rcBrake (pure world) (ofRobot ty)
    passes <- check "SimbotB"
    isSuccess passes `shouldBe` True
    fails <- check "SimbotA"
    case fails of
      Failure { failingTestCase = shown : _ } -> do
        written <- readWorldFile file
        page <- readFile (file ++ ".html")
        length page `seq` mapM_ removeFile [file, file ++ ".html"]
        fmap renderWorld written `shouldBe` Right shown
        written `shouldBe` Right [OTSimbotA 1 (Point2 3 0) 0]
        -- (the instant runT names for the world of SimbotA alone, in
        -- which it is the only robot that can get stuck)
        alone <- quickCheckWithResult stdArgs { chatty = False, maxSuccess = 1 } $
          runT defaultSimConfig { simDt = 0.05 } 10 straight rcBrake neverStuck [OTSimbotA 1 (Point2 3 0) 0]
        case (decidedLines fails, decidedLines alone) of
          (l : _, [expected]) -> do
            l `shouldBe` expected
            pageSummary page `shouldSatisfy` (("\"text\":\"" ++ takeWhile (/= ':') l ++ "\"") `isInfixOf`)
          _ -> expectationFailure ("no instant in the output: " ++ output fails ++ "\n" ++ output alone)
      _ -> expectationFailure ("SimbotA's failure was not caught: " ++ output fails)

-- @countingStarts starts rc@: the controller @rc@, counting in @starts@
-- each time it is started for a robot (once per robot and run: the
-- simulator starts a robot's controller in each run its robot moves in).
countingStarts :: IORef Int -> SimbotController -> SimbotController
countingStarts starts rc props = unsafePerformIO (modifyIORef' starts (+ 1) >> pure (rc props))
{-# NOINLINE countingStarts #-}

-- Whether an object of a template is a robot.
isRobot :: ObjectTemplate -> Bool
isRobot OTSimbotA {} = True
isRobot OTSimbotB {} = True
isRobot _            = False

-- A robot that drives straight at full speed: in a world without walls it
-- ends up against the world's edge, stuck.
straight :: SimbotController
straight _ = constant (mrFinalize (ddVelTR 1 0))

-- A robot that stands still.
rcBrake :: SimbotController
rcBrake _ = constant (mrFinalize (ddVelTR 0 0))

-- Nobody is ever stuck.
neverStuck :: TPred WorldState
neverStuck = Always (SP (arr (not . any robotStuck . wsRobots)))

-- The lines of a result's output that say the instant a predicate was
-- decided false.
decidedLines :: Result -> [String]
decidedLines result = [ l | l <- lines (output result), "decided false at t = " `isPrefixOf` l ]

-- The run's summary as the page holds it: its JSON object's text.
pageSummary :: String -> String
pageSummary page = case [ rest | rest <- tails page, "\"kind\":\"summary\"" `isPrefixOf` rest ] of
  (rest : _) -> takeWhile (/= '}') rest
  []         -> ""

-- How many times a text occurs in another.
occurrences :: String -> String -> Int
occurrences needle hay = length (filter (needle `isPrefixOf`) (tails hay))
