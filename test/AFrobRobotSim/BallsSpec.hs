-- | "AFrobRobotSim.Balls": the laws of a ball's step (friction, bounces,
-- kicks, collisions) on single cases, and the whole step, bit for bit,
-- against the straightforward all-pairs version below (the simulator's
-- original code, kept here as the specification).
module AFrobRobotSim.BallsSpec (spec) where

import           Control.Exception     (evaluate)
import           System.Timeout        (timeout)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Geometry
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Balls
import           AFrobRobotSim.Physics
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.World
import           AFrobRobotSim.WorldGen
import           SimBench              (runBallBench)
import           TestUtil              (shouldApprox)

------------------------------------------------------------------------------
-- The reference: the original all-pairs code

refStepBalls :: Double -> Arena -> [Robot] -> [Ball] -> [Ball]
refStepBalls dt arena robots balls = refResolvePairs arena robots (map (refStepBall dt arena robots) balls)

refStepBall :: Double -> Arena -> [Robot] -> Ball -> Ball
refStepBall dt arena robots b0 =
  let b1 = foldl pushOut b0 robots
      v  = slowDown (bVel b1)
      d  = (dt *^ v)
      hits = [ (s, n, zeroVector) | bx <- arenaBoxes arena, Just (s, n) <- [sweepCircleBox (bPos b1) ballRadius' d bx] ]
          ++ [ (s, n, robotVelocity r) | r <- robots, Just (s, n) <- [sweepCircleCircle (bPos b1) ballRadius' d (rPos r) robotRadius'] ]
  in case hits of
       [] -> b1 { bPos = bPos b1 .+^ d, bVel = v }
       _  -> let (s, n, vo) = minimumOn (\(x, _, _) -> x) hits
                 p  = bPos b1 .+^ (max 0 (s - 1e-9) *^ d)
             in b1 { bPos = p, bVel = vo ^+^ bounce n (v ^-^ vo) }
  where
    slowDown :: Vector2 Double -> Vector2 Double
    slowDown v = let sp = norm v
                     sp' = max 0 (sp - ballFriction * dt)
                 in if sp <= 0 then zeroVector else (sp' / sp) *^ v
    pushOut b r = case circleCirclePenetration (bPos b) ballRadius' (rPos r) robotRadius' of
      Nothing       -> b
      Just (depth, n) ->
        let vr  = robotVelocity r
            rel = bVel b ^-^ vr
            v'  = if rel `dot` n < 0 then vr ^+^ bounce n rel else bVel b
        in b { bPos = refPushedTo arena robots (bPos b) ((depth + 1e-9) *^ n), bVel = v' }
    bounce :: Vector2 Double -> Vector2 Double -> Vector2 Double
    bounce n rel = let rn = (rel `dot` n) *^ n
                   in (rel ^-^ rn) ^-^ (ballRestitution *^ rn)
    minimumOn f = foldr1 (\x y -> if f x <= f y then x else y)

refResolvePairs :: Arena -> [Robot] -> [Ball] -> [Ball]
refResolvePairs arena robots bs0 = foldl resolve bs0 [ (i, j) | i <- [0 .. n - 1], j <- [i + 1 .. n - 1] ]
  where
    n = length bs0
    resolve bs (i, j) =
      let bi = bs !! i
          bj = bs !! j
      in case ballPairPenetration j (bPos bi) (bPos bj) of
           Nothing -> bs
           Just (depth, nrm) ->
             let relN = (bVel bi ^-^ bVel bj) `dot` nrm
                 half = (depth / 2 + 1e-9) *^ nrm
                 (vi, vj) | relN < 0  = (bVel bi ^-^ (relN *^ nrm), bVel bj ^+^ (relN *^ nrm))
                          | otherwise = (bVel bi, bVel bj)
                 bi' = Ball (refPushedTo arena robots (bPos bi) half) vi
                 bj' = Ball (refPushedTo arena robots (bPos bj) (negateVector half)) vj
             in [ if k == i then bi' else if k == j then bj' else b | (k, b) <- zip [0 ..] bs ]

-- | A push, swept against every box and every robot: it stops at the
-- first.
refPushedTo :: Arena -> [Robot] -> Point2 Double -> Vector2 Double -> Point2 Double
refPushedTo arena robots p push =
  let s = minimum (1 : [ s' | bx <- arenaBoxes arena, Just (s', _) <- [sweepCircleBox p ballRadius' push bx] ]
                    ++ [ s' | r <- robots, Just (s', _) <- [sweepCircleCircle p ballRadius' push (rPos r) robotRadius'] ])
  in if s >= 1 then p .+^ push else p .+^ (max 0 (s - 1e-9) *^ push)

------------------------------------------------------------------------------
-- Single cases

-- | How deep a ball lies in the arena's deepest box (0 if in none).
maxPenetration :: Arena -> Ball -> Double
maxPenetration arena b =
  maximum (0 : [ d | bx <- arenaBoxes arena, Just (d, _) <- [circleBoxPenetration (bPos b) ballRadius' bx] ])

-- | A pile of 2 to 12 balls around a point next to one of the world's
-- boxes (a wall, a block or the boundary), clear of every box, at rest or
-- moving.
genPileByBox :: World -> Gen [Ball]
genPileByBox w = do
  let arena = arenaFor w
  Box x0 y0 x1 y1 <- elements (arenaBoxes arena)
  -- a point just outside one side of the box
  side <- chooseInt (0, 3)
  t <- choose (0, 1)
  let gap = ballRadius' + 0.02
      (cx, cy) = case side of
        0 -> (x0 - gap, y0 + t * (y1 - y0))
        1 -> (x1 + gap, y0 + t * (y1 - y0))
        2 -> (x0 + t * (x1 - x0), y0 - gap)
        _ -> (x0 + t * (x1 - x0), y1 + gap)
  n <- chooseInt (2, 12)
  bs <- vectorOf n $ do
    dx <- choose (-0.05, 0.05)
    dy <- choose (-0.05, 0.05)
    v  <- elements [zeroVector, Vector2 0.5 0, Vector2 0 (-0.5)]
    pure (Ball (Point2 (cx + dx) (cy + dy)) v)
  pure (filter (\b -> maxPenetration arena b == 0) bs)

-- | Velocity and position of a ball, as plain numbers.
state :: Ball -> (Double, Double, Double, Double)
state (Ball (Point2 x y) (Vector2 vx vy)) = (x, y, vx, vy)

-- | One step of a lone ball in the empty world.
alone :: Double -> Ball -> Ball
alone dt b = case stepBalls dt emptyArena [] [b] of
  [b'] -> b'
  bs   -> error ("one ball in, " ++ show (length bs) ++ " out")

spec :: Spec
spec = do
  describe "stepBalls" $ do
    it "rolls a free ball on, its speed falling by ballFriction per second" $ do
      let (x, y, vx, vy) = state (alone 0.1 (Ball (Point2 0 0) (Vector2 0.6 0.8)))
          v' = 1 - ballFriction * 0.1
      vx `shouldApprox` (0.6 * v')
      vy `shouldApprox` (0.8 * v')
      x `shouldApprox` (0.1 * 0.6 * v')
      y `shouldApprox` (0.1 * 0.8 * v')

    it "stops a slow ball where it is, without turning it round" $
      state (alone 1 (Ball (Point2 1 2) (Vector2 0 (-0.1)))) `shouldBe` (1, 2, 0, 0)

    it "bounces a ball off the boundary, keeping ballRestitution of its normal speed" $ do
      let (x, _, vx, vy) = state (alone 0.1 (Ball (Point2 4.8 0) (Vector2 1 0)))
      vx `shouldApprox` (-(ballRestitution * (1 - ballFriction * 0.1)))
      vy `shouldBe` 0
      x + ballRadius <= worldXMax `shouldBe` True

    it "lets a driving robot kick a ball it overlaps, away at more than its own speed" $ do
      let robot = mkRobot SimbotA 1 (Point2 0 0) 0 1 False 1
          dt = 0.01
      case stepBalls dt emptyArena [robot] [Ball (Point2 0.3 0) (Vector2 0 0)] of
        [Ball (Point2 x y) (Vector2 vx vy)] -> do
          -- relative velocity (-1, 0) reflected: 1 + ballRestitution * 1,
          -- then friction
          vx `shouldApprox` (1 + ballRestitution - ballFriction * dt)
          (vy, y) `shouldBe` (0, 0)
          x >= robotRadius + ballRadius - 1e-6 `shouldBe` True
        bs -> expectationFailure ("one ball in, " ++ show (length bs) ++ " out")

    it "collides two balls head on elastically: they exchange velocities and part" $
      case stepBalls 0.001 emptyArena [] [Ball (Point2 (-0.14) 0) (Vector2 1 0), Ball (Point2 0.14 0) (Vector2 (-1) 0)] of
        [Ball (Point2 x0 _) (Vector2 v0 _), Ball (Point2 x1 _) (Vector2 v1 _)] -> do
          let v = 1 - ballFriction * 0.001
          v0 `shouldApprox` (-v)
          v1 `shouldApprox` v
          x1 - x0 >= 2 * ballRadius `shouldBe` True
        bs -> expectationFailure ("two balls in, " ++ show (length bs) ++ " out")

    it "resolves a dense crowd of balls exactly as testing every pair does, step after step" $
      withMaxSuccess 20 $ forAll (chooseInt (60, 150)) $ \n -> forAll (vectorOf n (genBall 1.2)) $ \bs ->
        let arena = arenaFor (World notesBounds [])
            steps f = take 4 (iterate (f 0.01 arena []) bs)
        in steps stepBalls === steps refStepBalls
    it "resolves balls stacked on one spot, and piles of them, exactly as testing every pair does" $
      withMaxSuccess 20 $ forAll (chooseInt (2, 60)) $ \n -> forAll (chooseInt (1, 4)) $ \spots ->
        forAll (vectorOf spots (genBall 0.3)) $ \centres ->
          let bs = take n (cycle centres)
              arena = arenaFor (World notesBounds [])
              steps f = take 4 (iterate (f 0.01 arena []) bs)
          in steps stepBalls === steps refStepBalls
    it "spreads a pile laid on one spot over the floor, not along a line (it spread along x alone)" $ do
      let arena = arenaFor (World notesBounds [])
          pile  = replicate 40 (Ball (Point2 0 0) zeroVector)
          settled = iterate (stepBalls 0.01 arena []) pile !! 100
          spread f = maximum (map f settled) - minimum (map f settled)
      spread (\b -> let Point2 x _ = bPos b in x) `shouldSatisfy` (> 1)
      spread (\b -> let Point2 _ y = bPos b in y) `shouldSatisfy` (> 1)
      -- and no two left on one spot
      length [ () | (i, a) <- zip [0 :: Int ..] settled, (j, b) <- zip [0 ..] settled, i < j, bPos a == bPos b ] `shouldBe` 0
    it "never pushes a ball into a wall: two overlapping balls against the boundary stay inside" $ do
      -- (a pushed ball went 0.07 m into the boundary, and three stacked
      -- ones out of the world)
      let pair = stepBalls 0.01 emptyArena [] [Ball (Point2 4.84 0) zeroVector, Ball (Point2 4.70 0) zeroVector]
      map (maxPenetration emptyArena) pair `shouldSatisfy` all (<= 1e-9)
      let stacked = iterate (stepBalls 0.01 emptyArena []) (replicate 3 (Ball (Point2 4.84 0) zeroVector)
                                                             ++ [Ball (Point2 4.84 0.01) zeroVector])
      concatMap (map (maxPenetration emptyArena)) (take 20 stacked) `shouldSatisfy` all (<= 1e-9)
    it "never pushes a ball into a robot: a ball parted from another stops at a robot at rest" $ do
      -- (the push that parts two balls went 0.1 m into the robot the
      -- first one touched, and a robot that did not move overlapped it)
      let robot = mkRobot SimbotA 1 (Point2 0 0) 0 0 False 1
          overlapOf b = maybe 0 fst (circleCirclePenetration (bPos b) ballRadius' (rPos robot) robotRadius')
          steps = take 20 (iterate (stepBalls 0.01 emptyArena [robot])
                                   [Ball (Point2 0.4 0) zeroVector, Ball (Point2 0.5 0) zeroVector])
      concatMap (map overlapOf) steps `shouldSatisfy` all (<= 1e-9)
    it "leaves every ball of a pile against walls and blocks no deeper in a box than it was" $
      withMaxSuccess 100 $ forAll genWorld $ \w -> forAll (genPileByBox w) $ \bs ->
        let arena = arenaFor w
            depthsBefore = map (maxPenetration arena) bs
            depthsAfter  = map (maxPenetration arena) (stepBalls 0.01 arena [] bs)
        in counterexample (show (depthsBefore, depthsAfter)) $
             and (zipWith (\b a -> a <= max b 0 + 1e-9) depthsBefore depthsAfter)
    it "simulates 1000 balls in a crowd to finite positions (its speed: bench/, afrp-bench --balls)" $ do
      -- (0.5 s of simulated time, about 0.05 s of work; the minute is a
      -- guard against a hang on a loaded machine, not a measure of speed)
      r <- timeout 60000000 (evaluate (runBallBench 1000 50))
      r `shouldSatisfy` maybe False (\v -> not (isNaN v || isInfinite v))
    it "moves the balls exactly as testing every box, robot and pair of balls does" $
      property $ forAll genWorld $ \w -> forAll genDt $ \dt ->
        forAll (genRobots (halfSide w)) $ \rs -> forAll (genBalls (halfSide w)) $ \bs ->
          let arena = arenaFor w
          in stepBalls dt arena rs bs === refStepBalls dt arena rs bs
