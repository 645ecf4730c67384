{-# LANGUAGE BangPatterns    #-}
{-# LANGUAGE PatternSynonyms #-}
{-# LANGUAGE RankNTypes      #-}
-- |
-- Module      : AFrobRobotSim.Sensors
-- Description : What a simbot senses: range finder, animate object
--               tracker, bumper, battery, odometry, keyboard.
--
-- = Range finder
--
-- @rfRange i a@ casts a ray from the robot's centre in the direction of its
-- heading plus @a@ and returns the distance from the robot's /edge/ (its
-- radius, 0.25 m, subtracted) to the first wall, block, boundary or other
-- robot it meets, exactly, against the true shapes. Nothing further than
-- 'rangeFinderMax' (3 m) is seen: the reading is then 'rangeFinderMax'.
-- The ray's direction is the heading's unit vector turned by @a@, exactly
-- for the quarter turns of 'AFrob.rfFront', 'AFrob.rfLeft', 'AFrob.rfBack'
-- and 'AFrob.rfRight' (see 'rayDirection'). Rays are cast only when a
-- controller asks for them, and those four at most once per sample.
--
-- = Animate object tracker
--
-- Every other robot and every ball whose centre is within 'trackerRange'
-- (4 m) of the robot's centre, with its angle relative to the robot's
-- heading (normalised to [-pi, pi)) and its centre-to-centre distance,
-- nearest first (in template order among equally near ones).
--
-- = Indexing
--
-- A 'SenseContext' indexes the robots' and balls' centres on a grid
-- ("AFrobRobotSim.SpatialIndex") the first time a sensor needs it, and the
-- arena's boxes are indexed once, with the lists of boxes a ray from each
-- place can reach ("AFrobRobotSim.RayGrid"): a ray is tested only against
-- the boxes near its 3.25 m segment. The other robots within the
-- tracker's range of a robot are gathered once per sample, into unboxed
-- arrays (index and squared distance), and shared by its
-- tracker and its rays (every robot a ray can hit is among them). The
-- tracker's lists are sorted in unboxed arrays (by distance, then
-- template order: a merge sort, no list or thunk per point), and the lists
-- are made as the controller reads them: with many robots in range, a
-- band of distances at a time, so that a controller that reads the nearest
-- few sorts only the nearest bands. The readings are exactly those of
-- testing everything.
module AFrobRobotSim.Sensors
  ( senseRobot
  , senseRobotApart
  , rangeReading
  , rayDirection
  , rangeFinderMax
  , trackerRange
  , SenseContext (SenseContext, scArena, scRobots, scBalls)
  , scRobotIndex
  , senseReady
  ) where

import           Control.Monad.ST       (ST, runST)
import           GHC.Arr                (Array, listArray, unsafeAt)

import           AFRP.Geometry
import           AFrob.Angle            (normalizeAngle)
import           AFrob.Dimensions
import           AFrobRobotSim.Balls    (Ball (..), ballIndex)
import           AFrobRobotSim.Arena
import           AFrobRobotSim.FlatArray
import           AFrobRobotSim.Physics
import           AFrobRobotSim.RayCast  (rayCastBoxes)
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Shapes
import           AFrobRobotSim.SpatialIndex
import           AFrobRobotSim.World

-- | The range finder's maximum range: 3 m (the original simulator's was
-- about 2 m).
rangeFinderMax :: Distance
rangeFinderMax = 3

-- | The tracker's range: 4 m, centre to centre.
trackerRange :: Distance
trackerRange = 4

-- | What every robot senses from at one sample: the arena, every robot and
-- every ball. @SenseContext arena robots balls@ builds one (and matches
-- one, as if it were a plain record).
data SenseContext = MkSenseContext Arena [Robot] [Ball] Indexes

-- The robots and balls as arrays and on grids, each computed when first
-- needed and shared by every robot's sensors.
data Indexes = Indexes
  { ixRobots    :: Array Int Robot
  , ixNRobots   :: Int
  , ixRobotGrid :: PointIndex
  , ixBalls     :: Array Int Ball
  , ixBallGrid  :: PointIndex
  }

pattern SenseContext :: Arena -> [Robot] -> [Ball] -> SenseContext
pattern SenseContext { scArena, scRobots, scBalls } <- MkSenseContext scArena scRobots scBalls _
  where SenseContext a rs bs = MkSenseContext a rs bs (indexes a rs bs)
{-# COMPLETE SenseContext #-}

-- | The robots' centres on a grid over the arena
-- ('AFrobRobotSim.Physics.robotIndex'), built when first needed.
scRobotIndex :: SenseContext -> PointIndex
scRobotIndex (MkSenseContext _ _ _ ix) = ixRobotGrid ix

-- | @()@, once every index of the context that 'senseRobot' shares between
-- robots is built (the robots' and balls' arrays and grids): for a caller
-- that senses for several robots in parallel, so that no two threads
-- build one.
senseReady :: SenseContext -> ()
senseReady (MkSenseContext _ _ _ ix) =
  ixRobots ix `seq` ixRobotGrid ix `seq` ixBalls ix `seq` ixBallGrid ix `seq` ()

indexes :: Arena -> [Robot] -> [Ball] -> Indexes
indexes arena rs bs = Indexes
  { ixRobots    = listArray (0, nr - 1) rs
  , ixNRobots   = nr
  , ixRobotGrid = robotIndex arena rs
  , ixBalls     = listArray (0, length bs - 1) bs
  , ixBallGrid  = ballIndex arena bs
  }
  where nr = length rs

-- | The input of one robot (by its index in the context's robot list),
-- given its odometry reading and the key pressed now.
senseRobot :: SenseContext -> Int -> (Position2, Heading) -> Maybe Char -> SimbotInput
senseRobot ctx i odo key = fst (senseRobotApart ctx i odo key)

-- | 'senseRobot', and a lower bound on the distance from the robot's
-- centre to every other robot's centre (as the context has them): the
-- distance to the nearest one within the tracker's range (a millimetre
-- more: 4.001 m), or that range if none is that near; 0 when more than 16
-- are that near (a crowd, where a bound is seldom of use). Both made
-- from one gathering of the robots near it, done when the bound, the
-- tracker or a ray is first read
-- ('AFrobRobotSim.Physics.planMoveApart' takes the bound); the rays and
-- the tracker's lists are computed when read.
senseRobotApart :: SenseContext -> Int -> (Position2, Heading) -> Maybe Char -> (SimbotInput, Double)
senseRobotApart (MkSenseContext arena _ _ ix) i (odoPos, odoHead) key = (input, nearestOf others)
  where
    -- (the input record, the robot and its position are made at the call,
    -- not as thunks: a controller's step reads its input, so the thunks
    -- only cost; one that reads nothing of it pays a little more)
    !input = SimbotInput
      { siBattery  = batteryStatusOf (rCharge me)
      , siStuck    = rStuck me
      , siPosition = odoPos
      , siHeading  = odoHead
      , siRange    = range
      , siMaxRange = rangeFinderMax
      , siRobots   = inRangeSorted tracked others
      , siBalls    = inRangeSorted (\d _ bx by -> (angleTo bx by, d))
                                   (gatherNear (ixBallGrid ix) (-1) px py)
      , siKey      = key
      }
    !me | i >= 0 && i < ixNRobots ix = robotAt i
        | otherwise                  = error ("AFrobRobotSim.Sensors.senseRobot: no robot number " ++ show i)
    robotAt j = unsafeAt (ixRobots ix) j
    !p@(Point2 px py) = rPos me
    -- The other robots near this one, gathered once per sample and shared
    -- by the tracker and every ray: all within 'gatherRange', which covers
    -- the tracker's range and every robot a ray can hit.
    others = gatherNear (ixRobotGrid ix) i px py
    -- Those a quarter-turn ray can hit: a ray meets a disc only if the
    -- disc's centre is within a radius of the ray's line (the
    -- discriminant is negative otherwise, by far more than rounding), and
    -- the four quarter-turn rays lie on the heading's axis and its
    -- perpendicular; and only within the ray's reach (the cast ignores
    -- the others anyway). Usually none of the others is that near either
    -- line, and those four rays then test no robot at all.
    crossing = let Vector2 c s = headingDir
               in selectNear (\qx qy d2 ->
                    let x = qx - px
                        y = qy - py
                    in d2 <= rayReach * rayReach
                       && (abs (y * c - x * s) <= robotRadius + querySlack
                           || abs (x * c + y * s) <= robotRadius + querySlack))
                  others
    -- a robot the tracker sees: its type and number taken out as the
    -- element is made, the bearing computed when it is read
    tracked d j ox oy = let o    = robotAt j
                            !ty  = kindType (rKind o)
                            !rid = rId o
                        in (ty, rid, angleTo ox oy, d)
    -- the bearing of a point relative to the heading
    angleTo qx qy = let (_, th) = vector2RhoTheta (Point2 qx qy .-. p)
                    in normalizeAngle (th - rHeading me)
    -- The four quarter-turn rays (rfFront, rfLeft, rfBack, rfRight) are
    -- cast at most once per sample however often they are read: a
    -- controller typically reads one in several places.
    range a = case quarterTurn a of
      Just QFront -> rangeFront
      Just QLeft  -> rangeLeft
      Just QRight -> rangeRight
      Just QBack  -> rangeBack
      Nothing     -> rangeAt a
    rangeFront = rangeQuarter QFront
    rangeLeft  = rangeQuarter QLeft
    rangeRight = rangeQuarter QRight
    rangeBack  = rangeQuarter QBack
    rangeQuarter q = let Vector2 ux uy = quarterDir q headingDir in cast crossing ux uy
    -- any other angle (as 'rayDirection' turns it)
    rangeAt a
      | not (finite a) = rangeFinderMax
      | otherwise      = let Vector2 ux uy = vector2Polar 1 (rHeading me + a)
                         in cast (allNear others) ux uy
    -- a ray: the nearest box, then any nearer robot among the given ones
    cast near ux uy =
      reading (foldNear (\m qx qy d2 -> if d2 > rayReach * rayReach then m
                                        else rayToRobot px py ux uy m qx qy)
                        (rayCastBoxes (arenaIndex arena) px py ux uy rayLength) others near)
    -- the heading's unit vector, for all of this robot's rays: the cos and
    -- sin the robot keeps with its heading, the numbers of 'headingVector'
    headingDir = Vector2 (rCos me) (rSin me)

-- The points of an index (all but number @skip@) within 'gatherRange' of
-- @(px, py)@, in unboxed arrays (no list or box per point: a packed world
-- puts 50 robots within range of each): their indexes and squared
-- distances; their coordinates are read from the index itself. An index
-- of a few points is scanned, which costs less than walking the cells of
-- the square around the range (in the 10-robot benchmark, that square
-- covers most of the world); a larger one is walked cell by cell, into
-- arrays as large as the points listed in those cells. The order of the
-- points is the walk's: nothing read from them depends on it (a ray takes
-- the nearest hit, the tracker sorts).
gatherNear :: PointIndex -> Int -> Double -> Double -> Gathered
gatherNear grid skip px py
  | n <= 32   = gatherBy n (\add -> let scan !j !c
                                          | j >= n    = pure c
                                          | otherwise = add c j (pointX grid j) (pointY grid j) >>= scan (j + 1)
                                   in scan 0 0)
  | otherwise =
      -- (the window is taken apart here, before the two loops that read
      -- it: bound lazily for both, it was a record allocated for every
      -- robot and step; the points of its cells are tested by distance
      -- alone)
      case pointWindow grid (px - tr) (py - tr) (px + tr) (py + tr) of
        !win -> gatherBy (windowSize win) (\add -> foldWindowCellsM win add 0)
  where
    n  = pointIndexCount grid
    tr = gatherRange
    -- the points a walk gives, into arrays of the given size
    gatherBy :: Int -> (forall s. (Int -> Int -> Double -> Double -> ST s Int) -> ST s Int) -> Gathered
    gatherBy cap walk = runST $ do
      js  <- newIntArrUnset (max 1 cap)
      d2s <- newDblArr (max 1 cap)
      let add !c j qx qy
            | j == skip = pure c
            | otherwise =
                let x  = qx - px
                    y  = qy - py
                    d2 = x * x + y * y
                in if d2 <= tr * tr
                     then writeI js c j >> writeD d2s c d2 >> pure (c + 1)
                     else pure c
      k <- walk add
      Gathered grid k <$> freezeI js <*> freezeD d2s
    {-# INLINE gatherBy #-}

-- Points of an index near a robot: the index, how many, and for the k-th
-- its number in the index and its squared distance from the robot.
data Gathered = Gathered !PointIndex {-# UNPACK #-} !Int !IntArr !DblArr

-- A lower bound on the distance to every point of the index but the one
-- skipped: the distance to the nearest gathered point, or 'gatherRange'
-- if there is none; 0 when more than 'bandsAbove' are gathered (in such
-- a crowd a robot is seldom far from all the others, and the bound is
-- not worth its pass over them).
nearestOf :: Gathered -> Double
nearestOf (Gathered _ k _ d2s)
  | k > bandsAbove = 0
  | otherwise      = go 0 (gatherRange * gatherRange)
  where
    go !p !m | p >= k    = sqrt m
             | otherwise = go (p + 1) (min m (indexD d2s p))

-- Some of the gathered points, by their positions in the arrays.
data Some = None | Some {-# UNPACK #-} !Int !Some
          | All  -- every one

allNear :: Gathered -> Some
allNear _ = All

-- The gathered points that pass a test of their coordinates and squared
-- distance.
selectNear :: (Double -> Double -> Double -> Bool) -> Gathered -> Some
selectNear keep (Gathered grid k js d2s) = go (k - 1) None
  where
    go !p acc
      | p < 0     = acc
      | let j = indexI js p, keep (pointX grid j) (pointY grid j) (indexD d2s p) = go (p - 1) (Some p acc)
      | otherwise = go (p - 1) acc
{-# INLINE selectNear #-}

-- A strict left fold over some gathered points (coordinates, squared
-- distance).
foldNear :: (a -> Double -> Double -> Double -> a) -> a -> Gathered -> Some -> a
foldNear f z0 (Gathered grid k js d2s) sel = case sel of
  All -> every 0 z0
  _   -> some sel z0
  where
    -- (the coordinates read before the call: passed unread, each would be
    -- a box allocated for a function that may not look at it)
    at z p = let j   = indexI js p
                 !qx = pointX grid j
                 !qy = pointY grid j
                 !d2 = indexD d2s p
             in f z qx qy d2
    {-# INLINE at #-}
    every !p !z | p >= k    = z
                | otherwise = every (p + 1) (at z p)
    some None !z       = z
    some All !z        = every 0 z
    some (Some p r) !z = some r (at z p)
{-# INLINE foldNear #-}

-- The points (of an index) within the tracker's range, centre to centre
-- (the distance as 'vector2RhoTheta' has it: the square root of the same
-- sum of squares), nearest first, in index order among equally near ones
-- (as a stable sort of all of them by distance would have them), each
-- made by @mk d j x y@ from its distance, its number in the index and its
-- coordinates there, evaluated as its list cell is made. Sorted in
-- unboxed arrays, with no list or thunk per point: a packed world puts
-- 50 robots within range of each, and sorting them as a list (an
-- insertion sort, then a lazy merge sort) was most of a sample's cost.
--
-- The list is made as it is read, and so is the sorting: more than
-- 'bandsAbove' points are first put into bands of distance ('bandOf':
-- below 1 m, 2 m, 3 m, and the rest of the range), and a band is sorted
-- when the list reaches it.
-- A band holds only distances above the previous band's, so the bands'
-- sorted runs one after the other are the whole list sorted; a
-- controller that reads the nearest few robots (the usual case) sorts
-- the nearest bands only, about a tenth of the points in a packed world.
inRangeSorted :: (Double -> Int -> Double -> Double -> r) -> Gathered -> [r]
inRangeSorted mk (Gathered grid n gjs gd2s)
  | n <= bandsAbove = run (sortedInRange n gjs gd2s) []
  | otherwise = case banded n gjs gd2s of
  Banded starts bds bjs ->
    let band b
          | b >= bandCount = []
          | otherwise =
              let lo = indexI starts b
                  hi = indexI starts (b + 1)
              in if lo >= hi then band (b + 1)
                 else run (sortedRun lo hi bds bjs) (band (b + 1))
    in band 0
  where
    -- a sorted run's elements, then @rest@
    run (Sorted k ds js) rest = build 0
      where
        build i
          | i >= k    = rest
          | otherwise = let j = indexI js i
                        in case mk (indexD ds i) j (pointX grid j) (pointY grid j) of
                             !e -> e : build (i + 1)
{-# INLINE inRangeSorted #-}

-- Up to how many gathered points 'inRangeSorted' sorts all at once (in
-- the 1000-robot benchmark world about 5 are gathered; bands there cost
-- 620 instructions a robot-step more than they save).
bandsAbove :: Int
bandsAbove = 16

-- The numbers and distances of 'inRangeSorted' sorted all at once.
sortedInRange :: Int -> IntArr -> DblArr -> Sorted
sortedInRange n gjs gd2s = runST $ do
  ds <- newDblArr (max 1 n)
  js <- newIntArrUnset (max 1 n)
  let fill !p !c
        | p >= n    = pure c
        | otherwise =
            let d = sqrt (indexD gd2s p)
            in if d <= trackerRange then writeD ds c d >> writeI js c (indexI gjs p) >> fill (p + 1) (c + 1)
                                    else fill (p + 1) c
  k <- fill 0 0
  sortedFrom k ds js

-- The gathered points within the tracker's range, their distances and
-- numbers grouped by band ('bandOf'), each band in the gathered order:
-- band @b@ is positions @[starts b, starts (b + 1))@ of the arrays.
data Banded = Banded !IntArr !DblArr !IntArr

-- How many bands of distance 'inRangeSorted' sorts one at a time.
bandCount :: Int
bandCount = 4

-- The band of a distance (centre to centre), or -1 beyond the tracker's
-- range. Bands are in the order of the distances they hold.
bandOf :: Double -> Int
bandOf d
  | d < 1            = 0
  | d < 2            = 1
  | d < 3            = 2
  | d <= trackerRange = 3
  | otherwise        = -1
{-# INLINE bandOf #-}

-- The gathered points in bands (a counting sort by band: stable).
banded :: Int -> IntArr -> DblArr -> Banded
banded n gjs gd2s = runST $ do
  counts <- newIntArr (bandCount + 1) 0
  let count !p
        | p >= n    = pure ()
        | otherwise = do
            let b = bandOf (sqrt (indexD gd2s p))
            if b >= 0 then readI counts (b + 1) >>= writeI counts (b + 1) . (+ 1) else pure ()
            count (p + 1)
  count 0
  let sums !b !acc
        | b > bandCount = pure acc
        | otherwise     = do c <- readI counts b
                             writeI counts b (acc + c)
                             sums (b + 1) (acc + c)
  total <- sums 0 0
  -- counts b is now where band b starts; 'next' is where its next point goes
  next <- newIntArr bandCount 0
  let copyStarts !b | b >= bandCount = pure ()
                    | otherwise      = readI counts b >>= writeI next b >> copyStarts (b + 1)
  copyStarts 0
  ds <- newDblArr (max 1 total)
  js <- newIntArrUnset (max 1 total)
  let place !p
        | p >= n    = pure ()
        | otherwise = do
            let d = sqrt (indexD gd2s p)
                b = bandOf d
            if b >= 0
              then do o <- readI next b
                      writeD ds o d
                      writeI js o (indexI gjs p)
                      writeI next b (o + 1)
              else pure ()
            place (p + 1)
  place 0
  Banded <$> freezeI counts <*> freezeD ds <*> freezeI js

-- Positions @[lo, hi)@ of the banded arrays, sorted by distance then
-- number, in arrays of their own.
sortedRun :: Int -> Int -> DblArr -> IntArr -> Sorted
sortedRun lo hi bds bjs = runST $ do
  let k = hi - lo
  ds <- newDblArr (max 1 k)
  js <- newIntArrUnset (max 1 k)
  let copy !i | i >= k    = pure ()
              | otherwise = writeD ds i (indexD bds (lo + i)) >> writeI js i (indexI bjs (lo + i)) >> copy (i + 1)
  copy 0
  sortedFrom k ds js

data Sorted = Sorted !Int !DblArr !IntArr

-- The first @k@ keys of two arrays, sorted ('sortKeys'), as a 'Sorted'.
sortedFrom :: Int -> MDblArr s -> MIntArr s -> ST s Sorted
sortedFrom k ds js = do
  (ds', js') <- sortKeys k ds js
  Sorted k <$> freezeD ds' <*> freezeI js'
{-# INLINE sortedFrom #-}

-- Sort the first @k@ keys (distance, index) of two arrays, by distance
-- then index: runs of 8 by insertion, then merged bottom-up through a
-- second pair of arrays. Gives the arrays that hold the result.
sortKeys :: Int -> MDblArr s -> MIntArr s -> ST s (MDblArr s, MIntArr s)
sortKeys k ds js = do
  let runs !lo | lo >= k   = pure ()
               | otherwise = insertion ds js lo (min k (lo + 8)) >> runs (lo + 8)
  runs 0
  if k <= 8 then pure (ds, js) else do
    ds2 <- newDblArr k
    js2 <- newIntArrUnset k
    let pass !w sd sj td tj
          | w >= k    = pure (sd, sj)
          | otherwise = do
              let merges !lo | lo >= k   = pure ()
                             | otherwise = do
                                 let mid = min k (lo + w)
                                     hi  = min k (lo + 2 * w)
                                 merge sd sj td tj lo mid hi
                                 merges hi
              merges 0
              pass (2 * w) td tj sd sj
    pass 8 ds js ds2 js2

-- Is the key (d, j) before the key (e, k)?
before :: Double -> Int -> Double -> Int -> Bool
before d j e k = d < e || (d == e && j < k)
{-# INLINE before #-}

-- Insertion sort of the keys in [lo, hi).
insertion :: MDblArr s -> MIntArr s -> Int -> Int -> ST s ()
insertion ds js lo hi = outer (lo + 1)
  where
    outer !i
      | i >= hi   = pure ()
      | otherwise = do
          d <- readD ds i
          j <- readI js i
          let shift !p
                | p <= lo   = pure p
                | otherwise = do
                    e <- readD ds (p - 1)
                    k <- readI js (p - 1)
                    if before d j e k
                      then writeD ds p e >> writeI js p k >> shift (p - 1)
                      else pure p
          p <- shift i
          writeD ds p d
          writeI js p j
          outer (i + 1)

-- Merge the sorted runs [lo, mid) and [mid, hi) of the first arrays into
-- [lo, hi) of the second (stable: the left run first among equal keys).
merge :: MDblArr s -> MIntArr s -> MDblArr s -> MIntArr s -> Int -> Int -> Int -> ST s ()
merge sd sj td tj lo mid hi = go lo mid lo
  where
    go !a !b !o
      | o >= hi   = pure ()
      | a >= mid  = copy b o
      | b >= hi   = copy a o
      | otherwise = do
          d <- readD sd a
          j <- readI sj a
          e <- readD sd b
          k <- readI sj b
          if before e k d j
            then writeD td o e >> writeI tj o k >> go a (b + 1) (o + 1)
            else writeD td o d >> writeI tj o j >> go (a + 1) b (o + 1)
    copy !x !o
      | o >= hi   = pure ()
      | otherwise = do
          readD sd x >>= writeD td o
          readI sj x >>= writeI tj o
          copy (x + 1) (o + 1)

-- | The range finder's reading for a robot at a position and heading,
-- among the given other robots' centres, in the direction @a@ relative to
-- the heading (see the module documentation). A non-finite angle reads
-- 'rangeFinderMax'.
rangeReading :: Arena -> [Position2] -> Position2 -> Heading -> Angle -> Distance
rangeReading arena others (Point2 px py) heading a
  | not (finite a) = rangeFinderMax
  | otherwise      = let Vector2 ux uy = rayDirection heading a
                     in reading (foldl (\m (Point2 qx qy) -> rayToRobot px py ux uy m qx qy)
                                       (rayCastBoxes (arenaIndex arena) px py ux uy rayLength) others)

-- | The direction (a unit vector) of the range finder's ray at angle @a@
-- for a robot with heading @h@: the heading's unit vector @(cos h, sin h)@
-- turned by @a@. A quarter turn (@a@ = 0, @pi \/ 2@, @-pi \/ 2@, @pi@ or
-- @-pi@, the angles of 'AFrob.rfFront', 'AFrob.rfLeft', 'AFrob.rfRight'
-- and 'AFrob.rfBack') turns it exactly, by swapping and negating its
-- components; any other angle gives @(cos (h + a), sin (h + a))@.
rayDirection :: Heading -> Angle -> Vector2 Double
rayDirection h = turnedBy h (headingVector h)
{-# INLINE rayDirection #-}

-- The unit vector of a heading.
headingVector :: Heading -> Vector2 Double
headingVector h = Vector2 (cos h) (sin h)
{-# INLINE headingVector #-}

-- A heading's unit vector turned by an angle (see 'rayDirection'): the
-- lazily shared heading vector is only needed for the quarter turns.
turnedBy :: Heading -> Vector2 Double -> Angle -> Vector2 Double
turnedBy h hv a = case quarterTurn a of
  Just q  -> quarterDir q hv
  Nothing -> vector2Polar 1 (h + a)
{-# INLINE turnedBy #-}

-- A heading's unit vector turned exactly by a quarter turn: its
-- components swapped and negated.
quarterDir :: QuarterTurn -> Vector2 Double -> Vector2 Double
quarterDir q hv@(Vector2 c s) = case q of
  QFront -> hv
  QLeft  -> Vector2 (negate s) c
  QRight -> Vector2 s (negate c)
  QBack  -> Vector2 (negate c) (negate s)
{-# INLINE quarterDir #-}

-- The range finder's quarter turns, relative to the heading.
data QuarterTurn = QFront | QLeft | QRight | QBack

-- The quarter turn an angle is exactly (0, pi/2, -pi/2, pi or -pi, as
-- 'AFrob.rfFront', 'AFrob.rfLeft', 'AFrob.rfRight' and 'AFrob.rfBack'
-- write them), if it is one.
quarterTurn :: Angle -> Maybe QuarterTurn
quarterTurn a
  | a == 0                    = Just QFront
  | a == pi / 2               = Just QLeft
  | a == -pi / 2              = Just QRight
  | a == pi || a == -pi       = Just QBack
  | otherwise                 = Nothing
{-# INLINE quarterTurn #-}

-- How far from the robot's centre the centre of a robot it hits can be:
-- the ray's length and a radius, and some slack.
rayReach :: Double
rayReach = rayLength + robotRadius + querySlack

rayLength :: Double
rayLength = rangeFinderMax + robotRadius

-- How far from a robot's centre the robots and balls gathered for its
-- tracker and its rays (one gather for both) can be: a little more than
-- the tracker's range, and in any case as far as a ray can reach a robot.
gatherRange :: Double
gatherRange = max (trackerRange + querySlack) rayReach

-- The nearer of a distance and the robot (centre) the ray from @(px, py)@
-- in the direction @(ux, uy)@ may hit.
rayToRobot :: Double -> Double -> Double -> Double -> Double -> Double -> Double -> Double
rayToRobot px py ux uy m qx qy =
  case rayCircle (Point2 px py) (Vector2 ux uy) (Point2 qx qy) robotRadius of
    Just t  -> min t m
    Nothing -> m
{-# INLINE rayToRobot #-}

-- The reading for the nearest hit (centre to obstacle): from the robot's
-- edge, within the range.
reading :: Double -> Distance
reading nearest = max 0 (min rangeFinderMax (nearest - robotRadius))
