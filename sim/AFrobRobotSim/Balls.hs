{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Balls
-- Description : How balls move: rolling friction, bounces, kicks by the
--               simbots and collisions between balls.
--
-- Balls are moved after the robots, each step, against the robots' new
-- positions:
--
-- 1. A robot that now overlaps a ball kicks it: the ball is pushed out of
--    the robot (along the line of centres, swept, so that it stops at a
--    wall or block rather than pass through it), and its velocity relative
--    to the robot, if it was approaching, is reflected with restitution
--    'ballRestitution'. A robot counts as immovable; robots are not
--    stopped by balls. Robots kick in template order.
-- 2. Rolling friction: the ball's speed falls by 'ballFriction' times the
--    time step (to 0 at most, never reversing).
-- 3. The ball moves in a straight line and stops at its first contact with
--    a wall, block, the world's boundary or a robot (the earliest; on a tie
--    boxes before robots, each in their listed order), where its velocity
--    relative to what it hit is reflected with restitution
--    'ballRestitution'.
-- 4. Balls that now overlap and approach each other collide elastically
--    (equal masses: the normal components of their velocities are
--    exchanged) and are pushed apart, pair by pair in the order (0, 1),
--    (0, 2), ..., (1, 2), ... (two balls on the very same spot are
--    parted along a direction set by the later one's number,
--    'ballPairPenetration', so that a pile laid on one spot spreads over
--    the floor). Each push is swept, as a robot's is, and
--    stops at a wall, block or robot: a ball pressed against a wall or a
--    robot by another stays there, overlapping it, instead of being
--    pushed into the wall (or, in a pile, out of the world) or into the
--    robot (robots are immovable: a ball overlaps a robot only where
--    that robot drove into it and the ball could not get away). A
--    robot's push in step 1 is swept likewise: a ball squeezed between
--    two robots stays overlapping the one that pushed it, as one squeezed
--    between a robot and a wall.
--
-- As for the robots ("AFrobRobotSim.Physics"), nothing compares every ball
-- with everything: the boxes, the robots and the balls are found on grids,
-- with the same results as testing every pair.
module AFrobRobotSim.Balls
  ( -- * State
    Ball (..)
    -- * Stepping
  , stepBalls
  , ballIndex
  , ballPairPenetration
    -- * Parameters
  , ballFriction
  , ballRestitution
  , ballRadius
  ) where

import           Control.Monad.ST        (runST)
import           Data.List               (sort)
import           Data.Maybe              (isJust)
import           Data.STRef              (newSTRef, readSTRef, writeSTRef)
import           GHC.Arr                 (Array, listArray, newSTArray, unsafeAt,
                                          unsafeReadSTArray, unsafeWriteSTArray)

import           AFRP                    (DTime)
import           AFRP.Geometry
import           AFrob.Dimensions
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Clearance (clearanceAt)
import           AFrobRobotSim.FlatArray (freezeI, indexI, newDblArr, newIntArr, readD, writeD, writeI)
import           AFrobRobotSim.Physics
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World     (ballDiameter)

-- | A ball's physical state.
data Ball = Ball
  { bPos :: !Position2
  , bVel :: !(Vector2 Double)
  } deriving (Eq, Show)

-- | Rolling friction of a ball: 0.3 m/s^2.
ballFriction :: Acceleration
ballFriction = 0.3

-- | Coefficient of restitution of a ball against walls, blocks and robots:
-- 0.8.
ballRestitution :: Double
ballRestitution = 0.8

-- | The radius of a ball.
ballRadius :: Length
ballRadius = ballDiameter / 2

-- | Move every ball by one step: friction, bounces off obstacles and
-- robots (at their new positions, with their velocities), then elastic
-- collisions between balls.
stepBalls :: DTime -> Arena -> [Robot] -> [Ball] -> [Ball]
stepBalls _ _ _ [] = []
stepBalls dt arena robots balls =
  resolvePairs arena robotArr near (map (stepBall dt arena robotArr near) balls)
  where
    robotArr = listArray (0, length robots - 1) robots
    near     = robotIndex arena robots

-- | The balls' centres on a grid over the arena ('pointsOver'): point @i@
-- of the index is the centre of the @i@-th ball of the list.
ballIndex :: Arena -> [Ball] -> PointIndex
ballIndex = pointsOverOn (\(Ball (Point2 x _) _) -> x) (\(Ball (Point2 _ y) _) -> y)

stepBall :: DTime -> Arena -> Array Int Robot -> PointIndex -> Ball -> Ball
stepBall dt arena robots near b0 =
  let -- a robot that drove into the ball kicks it
      b1 = pushOuts b0 (-1)
      v  = slowDown (bVel b1)
      d@(Vector2 dx dy) = (dt *^ v)
      Point2 px py = bPos b1
      qx = px + dx
      qy = py + dy
      nBoxes = boxIndexCount (arenaIndex arena)
      -- the earliest contact; on a tie the first in the order boxes (as
      -- listed), then robots (as listed), as a scan of everything would
      -- find it
      rb = ballRadius + querySlack
      boxHit = foldBoxesIn (arenaIndex arena) (min px qx - rb) (min py qy - rb) (max px qx + rb) (max py qy + rb)
        (\acc k bx -> case sweepCircleBox (bPos b1) ballRadius d bx of
            Just (s, n) -> better (Hit s k n zeroVector) acc
            Nothing     -> acc) NoHit
      rr = ballRadius + robotRadius + querySlack
      hit = foldPointsIn near (min px qx - rr) (min py qy - rr) (max px qx + rr) (max py qy + rr)
        (\acc j -> let r = unsafeAt robots j
                   in case sweepCircleCircle (bPos b1) ballRadius d (rPos r) robotRadius of
                        Just (s, n) -> better (Hit s (nBoxes + j) n (robotVelocity r)) acc
                        Nothing     -> acc) boxHit
  in case hit of
       NoHit -> b1 { bPos = bPos b1 .+^ d, bVel = v }
       Hit s _ n vo ->
         let p  = bPos b1 .+^ (max 0 (s - 1e-9) *^ d)
         in b1 { bPos = p, bVel = vo ^+^ bounce n (v ^-^ vo) }
  where
    slowDown :: Vector2 Double -> Vector2 Double
    slowDown v = let sp = norm v
                     sp' = max 0 (sp - ballFriction * dt)
                 in if sp <= 0 then zeroVector else (sp' / sp) *^ v
    -- The robots push the ball out in order: the next robot (after the
    -- last one that pushed) that overlaps the ball where it now is.
    pushOuts b lastJ =
      let Point2 px py = bPos b
          rr = ballRadius + robotRadius + querySlack
          next = foldPointsIn near (px - rr) (py - rr) (px + rr) (py + rr)
                   (\acc j -> if j > lastJ && j < acc
                                 && isJust (circleCirclePenetration (bPos b) ballRadius (rPos (unsafeAt robots j)) robotRadius)
                              then j else acc) maxBound
      in if next == maxBound then b else pushOuts (pushOut b (unsafeAt robots next)) next
    pushOut b r = case circleCirclePenetration (bPos b) ballRadius (rPos r) robotRadius of
      Nothing       -> b
      Just (depth, n) ->
        let vr  = robotVelocity r
            rel = bVel b ^-^ vr
            v'  = if rel `dot` n < 0 then vr ^+^ bounce n rel else bVel b
        in b { bPos = pushedTo arena robots near True (bPos b) ((depth + 1e-9) *^ n), bVel = v' }
    bounce :: Vector2 Double -> Vector2 Double -> Vector2 Double
    bounce n rel = let rn = (rel `dot` n) *^ n
                   in (rel ^-^ rn) ^-^ (ballRestitution *^ rn)

-- Where a ball at @p@ pushed by @push@ ends: the push is swept like any
-- move and stops at a wall, block or robot (the robots where they now
-- are, given as an array and on a grid), so that a ball squeezed between
-- a robot or another ball and a wall or a robot stays pinned there,
-- overlapping what pushed it, and never passes into or through the wall
-- or the robot. (A robot the ball already overlaps stops the push only if
-- the push goes further into it, as 'sweepCircleCircle' has it: the robot
-- that pushes does not.) Without a box or robot in the way it is
-- @p .+^ push@. The boxes are taken to be out of the way, without a look
-- at them, where the clearance at @p@ exceeds the push and the radius
-- (most pushes, in a crowd away from the walls), and so are the robots
-- when the caller knows none to be near (the 'Bool' is 'False').
pushedTo :: Arena -> Array Int Robot -> PointIndex -> Bool -> Position2 -> Vector2 Double -> Position2
pushedTo arena robots near robotsNear p@(Point2 px py) push@(Vector2 ux uy) =
  if s >= 1 then p .+^ push else p .+^ (max 0 (s - 1e-9) *^ push)
  where
    x0 = min px (px + ux)
    y0 = min py (py + uy)
    x1 = max px (px + ux)
    y1 = max py (py + uy)
    sBoxes
      | clear > 0 && clear * clear > ux * ux + uy * uy = 1
      | otherwise =
          foldBoxesIn (arenaIndex arena) (x0 - rb) (y0 - rb) (x1 + rb) (y1 + rb)
            (\acc _ bx -> case sweepCircleBox p ballRadius push bx of
                Just (s', _) -> min acc s'
                Nothing      -> acc) 1
    s | not robotsNear = sBoxes
      | otherwise =
          foldPointsIn near (x0 - rr) (y0 - rr) (x1 + rr) (y1 + rr)
            (\acc j -> case sweepCircleCircle p ballRadius push (rPos (unsafeAt robots j)) robotRadius of
                Just (s', _) -> min acc s'
                Nothing      -> acc) sBoxes
    rb = ballRadius + querySlack
    rr = ballRadius + robotRadius + querySlack
    -- (with room for rounding)
    clear = clearanceAt (arenaClearance arena) px py - rb - querySlack

-- A candidate contact of a ball: fraction, order (boxes first, then
-- robots), normal, velocity of what it hits.
data Hit = NoHit | Hit !Double !Int !(Vector2 Double) !(Vector2 Double)

better :: Hit -> Hit -> Hit
better h NoHit = h
better NoHit h = h
better h1@(Hit s1 k1 _ _) h2@(Hit s2 k2 _ _)
  | s1 < s2 || (s1 == s2 && k1 < k2) = h1
  | s2 < s1 || (s1 == s2 && k2 < k1) = h2
  | otherwise                        = h1   -- the same box, seen from two cells

-- | @ballPairPenetration j p q@: how deep two balls centred at @p@ and @q@
-- overlap, the second of them number @j@ in the list's order, and the
-- unit normal from @q@ towards @p@ ('circleCirclePenetration'); except that two balls
-- on the very same spot, which have no line of centres, are parted along
-- the direction at @j@ times the golden angle (about 137.5 degrees), not
-- always along x: a pile of balls laid on one spot spreads over the floor,
-- where it used to spread along a line.
ballPairPenetration :: Int -> Point2 Double -> Point2 Double -> Maybe (Double, Vector2 Double)
ballPairPenetration j p q = case circleCirclePenetration p ballRadius q ballRadius of
  Just (depth, _) | p == q -> let a = goldenAngle * fromIntegral j in Just (depth, Vector2 (cos a) (sin a))
  other                    -> other
  where
    goldenAngle = pi * (3 - sqrt 5)
{-# INLINE ballPairPenetration #-}

-- Equal-mass elastic collisions between overlapping, approaching balls,
-- pair by pair in the order (0, 1), (0, 2), ..., (1, 2), ...: for each
-- ball, the next ball after the last one it met that overlaps it where
-- both now are. Candidates come from a grid of the balls' centres before
-- this, widened by the furthest any one ball has been pushed since (the
-- sum of its pushes bounds how far it is from where it was indexed).
-- Widening by the sum of all pushes instead, as this once did, grew the
-- query to the whole world in a crowd of balls: all pairs again.
resolvePairs :: Arena -> Array Int Robot -> PointIndex -> [Ball] -> [Ball]
resolvePairs arena robots near bs0 = runST $ do
  arr <- newSTArray (0, n - 1) (Ball origin zeroVector)
  mapM_ (\(k, b) -> unsafeWriteSTArray arr k b) (zip [0 ..] bs0)
  -- how far each ball has been pushed in all (an upper bound of its
  -- distance from where it was indexed), and the largest of these
  pushed <- newDblArr (max 1 n)
  mapM_ (\k -> writeD pushed k 0) [0 .. n - 1]
  drift <- newSTRef 0
  let forBall !i
        | i >= n = pure ()
        | otherwise = pairs i i noCands >> forBall (i + 1)
      pairs !i !lastJ cached = do
        bi <- unsafeReadSTArray arr i
        d0 <- readSTRef drift
        let Point2 px py = bPos bi
            rr = 2 * ballRadius + d0 + querySlack
            -- the candidates in hand serve while their rectangle holds
            -- this query's (the ball moves, and the drift grows, as it is
            -- pushed); else a new query, with a margin twice as wide
            cur | holds cached px py rr = cached { cdJs = dropWhile (<= lastJ) (cdJs cached) }
                | otherwise =
                    let m  = max (2 * cdMargin cached) (2 * ballRadius)
                        r' = rr + m
                    in Cands px py r' m (sort (foldPointsIn grid (px - r') (py - r') (px + r') (py + r')
                                                 (\acc j -> if j > lastJ then j : acc else acc) []))
        (next, rest) <- firstOverlap bi (cdJs cur)
        if next == maxBound then pure () else do
          bj <- unsafeReadSTArray arr next
          case ballPairPenetration next (bPos bi) (bPos bj) of
            Nothing -> pure ()
            Just (depth, nrm) -> do
              pi' <- readD pushed i
              pj' <- readD pushed next
              let relN = (bVel bi ^-^ bVel bj) `dot` nrm
                  half = (depth / 2 + 1e-9) *^ nrm
                  step = norm half
                  (vi, vj) | relN < 0  = (bVel bi ^-^ (relN *^ nrm), bVel bj ^+^ (relN *^ nrm))
                           | otherwise = (bVel bi, bVel bj)
                  -- Each push is swept: it stops at a wall, block or robot.
                  -- A ball is within its pushes so far of where it was
                  -- indexed, so the push cannot reach a robot when no robot
                  -- was within 'robotMargin' of that and the pushes,
                  -- this one included, come to less.
                  robotsNear k pk = indexI robotClose k /= 0 || pk + step >= robotMargin
                  !bi' = Ball (pushedTo arena robots near (robotsNear i pi') (bPos bi) half) vi
                  !bj' = Ball (pushedTo arena robots near (robotsNear next pj') (bPos bj) (negateVector half)) vj
              unsafeWriteSTArray arr i bi'
              unsafeWriteSTArray arr next bj'
              writeD pushed i (pi' + step)
              writeD pushed next (pj' + step)
              writeSTRef drift (max d0 (max (pi' + step) (pj' + step)))
          pairs i next cur { cdJs = rest }
      -- the first (smallest) candidate that overlaps ball i where both now
      -- are, and the candidates after it
      firstOverlap bi js = case js of
        []       -> pure (maxBound, [])
        j : rest -> do
          bj <- unsafeReadSTArray arr j
          case circleCirclePenetration (bPos bi) ballRadius (bPos bj) ballRadius of
            Just _  -> pure (j, rest)
            Nothing -> firstOverlap bi rest
  forBall 0
  mapM (unsafeReadSTArray arr) [0 .. n - 1]
  where
    n    = length bs0
    grid = ballIndex arena bs0
    -- For each ball, 1 if a robot's centre is within 'robotMargin' (and
    -- the two radii) of the ball's indexed centre along x and y, else 0:
    -- one query of the robots' grid for each ball, instead of one for each
    -- push (a crowd of balls pushes each several times a step).
    robotClose = runST $ do
      cl <- newIntArr (max 1 n) 0
      let reach = ballRadius + robotRadius + querySlack + robotMargin
          mark !k
            | k >= n    = pure ()
            | otherwise = do
                let x = pointX grid k
                    y = pointY grid k
                    close = foldPointsIn near (x - reach) (y - reach) (x + reach) (y + reach)
                              (\_ _ -> True) False
                writeI cl k (if close then 1 else 0)
                mark (k + 1)
      mark 0
      freezeI cl

-- How far beyond touching a robot must be from where a ball was indexed
-- for 'resolvePairs' to know, without a look at the robots, that the
-- ball's pushes in this step cannot reach it: 0.5 m (far more than the
-- pushes that part overlapping balls add up to in a step).
robotMargin :: Double
robotMargin = 0.5

-- The candidates of 'resolvePairs' for one ball: the rectangle they were
-- gathered from (centre, half-side), the margin it was widened by, and
-- the balls listed in the cells it meets, in ascending order.
data Cands = Cands
  { cdX      :: !Double
  , cdY      :: !Double
  , cdR      :: !Double
  , cdMargin :: !Double
  , cdJs     :: [Int]
  }

-- No candidates yet (a rectangle that holds no query).
noCands :: Cands
noCands = Cands 0 0 (-1) 0 []

-- Does the candidates' rectangle hold the query of half-side @rr@ around
-- @(px, py)@?
holds :: Cands -> Double -> Double -> Double -> Bool
holds c px py rr = max (abs (px - cdX c)) (abs (py - cdY c)) + rr <= cdR c
