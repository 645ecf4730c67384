-- |
-- Module      : AFrobRobotSim.World.Check
-- Description : The validation of a world template: what a world must be
--               for the simulator to run it.
--
-- Every object inside the world and with finite coordinates, robot ids in
-- range and unique per type, nothing overlapping at time 0 where the
-- physics could not part it, the balls' discs within the floor the robots
-- leave, and the objects not crowded past 'maxClosePairs' pairs; one
-- message per problem, capped at 'maxProblems'. "AFrobRobotSim.WorldFile"
-- reports the same problems with each object's line.
module AFrobRobotSim.World.Check
  ( validateWorld
  , validateWorldIn
  , worldProblems
    -- * Limits
  , maxRobotId
  , maxClosePairs
  , densestPacking
  , maxProblems
  , capProblems
  ) where

import           Data.List       (find, foldl', scanl')
import qualified Data.Map.Strict as M
import qualified Data.Set        as S
import           Numeric         (showFFloat)

import           AFRP.Geometry
import           AFrob.Dimensions (Length)
import           AFrobRobotSim.World

-- | The largest magnitude of a robot id in a world that runs: 2^53, the
-- largest up to which every whole number is a 'Double'. The log, the
-- result line and the replay page write ids as JSON numbers, which most
-- readers (JavaScript's among them) take as 'Double's: two larger ids
-- could be read as one.
maxRobotId :: Integer
maxRobotId = 2 ^ (53 :: Int)

-- | Check a world template: it has at most one 'OTSize', whose sides are
-- finite and between 'minWorldSide' and 'maxWorldSide'; every coordinate
-- and heading is a finite number; every object lies inside the world
-- (of the template's size, else the notes' 10 m); every robot id is
-- within 'maxRobotId' of 0, and no two robots of one type share an id;
-- nothing overlaps at time 0 where the physics could not
-- untangle it: a robot with a wall, block, ball or another robot, a ball
-- with a wall or block (touching is allowed, to within a nanometre for
-- rounding; walls and blocks may overlap each other, and balls each
-- other); and the balls' discs cover no more than the floor that the
-- robots leave (the world's area less the robots' discs), and the discs
-- of all balls but one no more than 'densestPacking' of the world's
-- floor (more balls could never all lie apart, and the physics would
-- push at their pile at every step, for ever; reported at the first ball
-- past either bound, with the figures). Returns the problems, each naming the object(s), in the order
-- of the objects (a problem between two objects comes with the later
-- one), or @Right ()@. A world whose objects make more than
-- 'maxClosePairs' pairs that the check of overlaps would compare is
-- refused as too crowded, at the object that passes that bound (the
-- objects from there on are not checked for overlaps). At most 'maxProblems' are
-- listed, then one line saying how many more there are.
validateWorld :: WorldTemplate -> Either [String] ()
validateWorld = validateWorldIn notesBounds

-- | 'validateWorld' for a world of the given extent, unless the template
-- gives its own ('OTSize'), which wins ('worldBoundsOr').
validateWorldIn :: Bounds -> WorldTemplate -> Either [String] ()
validateWorldIn bounds objs =
  case capProblems (map snd (worldProblems bounds (zip (repeat "") objs))) of
    [] -> Right ()
    ps -> Left ps

-- | How many problems 'validateWorld' lists before it only counts the
-- rest: 20.
maxProblems :: Int
maxProblems = 20

-- | At most 'maxProblems' messages, then (if there are more) one line
-- @... and N more problems@ (N counted up to 100000, beyond which it says
-- @at least 100000@).
capProblems :: [String] -> [String]
capProblems ps = case splitAt maxProblems ps of
  (shown, [])   -> shown
  (shown, rest) ->
    let limit = 100000 :: Int
        k     = length (take limit rest)
    in shown ++ [ "... and " ++ (if k >= limit then "at least " else "") ++ show k
                  ++ " more problem" ++ (if k == 1 then "" else "s") ]

-- | The problems of a world whose objects carry a label (appended to the
-- names of the other objects a message names, such as @" (line 3)"@; the
-- object a problem is reported at is named without it), in the order of
-- the objects, each with the position in the list of the object it is
-- reported at: for a pair, the later one. The objects must lie inside the template's
-- 'OTSize' if it has one that is valid, else inside the given bounds.
worldProblems :: Bounds -> [(String, ObjectTemplate)] -> [(Int, String)]
worldProblems bounds labelled = concatMap problemsOf indexed
  where
    indexed = zip [0 :: Int ..] labelled
    name (lbl, o) = objectName o ++ lbl
    -- (the object a problem is reported at is known by its position: its
    -- label would say it twice, as in w.world:3: ... (line 3): ...)
    subject (_, o) = objectName o
    sizes = [ (i, lo) | (i, lo@(_, OTSize {})) <- indexed ]
    Bounds x0 y0 x1 y1 = case sizes of
      (_, (_, OTSize w h)) : _ | goodSide w && goodSide h -> sizeBounds w h
      _                                                   -> bounds
    goodSide v = isFinite v && v >= minWorldSide && v <= maxWorldSide
    problemsOf (i, lo@(_, OTSize w h)) = case sizes of
      (j, first) : _ | j < i ->
        [(i, subject lo ++ ": a world has one size, and it was given by " ++ name first)]
      _ | not (isFinite w && isFinite h) ->
            [(i, subject lo ++ ": the width and height must be finite numbers")]
        | not (goodSide w && goodSide h) ->
            [(i, subject lo ++ ": each side must be between " ++ show minWorldSide ++ " and "
                   ++ show maxWorldSide ++ " metres")]
        | otherwise -> []
    problemsOf (i, lo@(_, o))
      | not (all isFinite (coords o)) =
          [(i, subject lo ++ ": coordinates and heading must be finite numbers")]
      | not (insideWorld o) =
          [(i, subject lo ++ ": lies (partly) outside the world [" ++ show x0 ++ ", " ++ show x1
                 ++ "] x [" ++ show y0 ++ ", " ++ show y1 ++ "]")]
      | otherwise =
          [ (i, subject lo ++ ": a robot id must be from -2^53 to 2^53 (a JSON reader, the replay page's among them, "
                  ++ "reads a larger one as a nearby number)")
          | Just _ <- [robotKindOf o], abs (toInteger (otRId o)) > maxRobotId ]
          ++ [ (i, subject lo ++ " has the same id as " ++ name (labelledAt j))
          | Just k <- [robotKindOf o], Just j <- [M.lookup (k, otRId o) firstWithId], j < i ]
          ++ (if beforeCrowd i then [ (i, subject lo ++ " overlaps " ++ name (labelledAt j)) | j <- overlapsBefore i o ]
                               else [ (i, subject lo ++ ": " ++ crowdMessage w) | Just (j, w) <- [crowd], j == i ])
          ++ [ (i, subject lo ++ ": " ++ overfullMessage n) | Just (j, n) <- [overfull], j == i ]
    coords o = let Point2 x y = otPos o
               in x : y : maybe [] (const [otHdng o]) (robotKindOf o)
    isFinite v = not (isNaN v || isInfinite v)
    insideWorld = insideBounds (Bounds x0 y0 x1 y1)
    placed = [ (i, o) | (i, (_, o)) <- indexed, not (isWorldSize o), all isFinite (coords o), insideWorld o ]
    arr = M.fromList [ (i, lo) | (i, lo) <- indexed ]
    -- The balls cannot all lie apart once their discs' area exceeds the
    -- floor's less the robots' (robots overlap nothing, so theirs is a
    -- plain sum; robots that do overlap are reported, and the floor they
    -- leave is then taken as no less than 0), nor once the discs of all
    -- but one exceed 'densestPacking' of the floor (Groemer's bound for n
    -- equal discs in a convex region: its area is at least 2 sqrt 3 (n - 1)
    -- r^2, so n - 1 discs cover at most pi / sqrt 12 of it): the first
    -- placed ball past either, and how many balls that makes. (A pile
    -- that can never spread keeps nearly every pair in contact at every
    -- step: 10,000 balls on one spot of the notes' world took 8.5 minutes
    -- a simulated second, and 1,350, 95% of the floor, which only the
    -- first bound let through, ran at 0.2x real time, still a pile after
    -- 5 s.) Both are bounds that a world can pass and still not hold its
    -- balls apart.
    floorArea  = (x1 - x0) * (y1 - y0)
    robotsArea = fromIntegral (length [ () | (_, o) <- placed, robotKindOf o /= Nothing ])
                 * discArea simbotDiameter
    floorLeft  = max 0 (floorArea - robotsArea)
    packable   = densestPacking * floorArea
    overfull   = case [ (i, n) | (n, i) <- zip [1 :: Int ..] [ i | (i, OTBall {}) <- placed ]
                               , fromIntegral n * discArea ballDiameter > floorLeft
                                 || fromIntegral (n - 1) * discArea ballDiameter > packable ] of
                   first : _ -> Just first
                   []        -> Nothing
    overfullMessage n
      | fromIntegral n * discArea ballDiameter > floorLeft =
          (if n == 1 then "this ball covers " else "the " ++ show n ++ " balls up to this one cover ")
          ++ squareMetres (fromIntegral n * discArea ballDiameter)
          ++ ", more than the " ++ squareMetres floorLeft ++ " of floor "
          ++ (if robotsArea > 0 then "that the robots leave (the world's " ++ squareMetres floorArea
                                     ++ " less the robots' " ++ squareMetres robotsArea ++ ")"
                                else "the world has")
          ++ cannotSpread
      | otherwise =
          "the " ++ show n ++ " balls up to this one cover " ++ squareMetres (fromIntegral n * discArea ballDiameter)
          ++ ", and all but one of them " ++ squareMetres (fromIntegral (n - 1) * discArea ballDiameter)
          ++ ", more than the " ++ squareMetres packable ++ " that equal discs can cover of the world's "
          ++ squareMetres floorArea ++ " (at most pi / sqrt 12, about 90.69%, of a floor)" ++ cannotSpread
    cannotSpread = ": they can never all lie apart, and a pile that cannot spread stalls the simulation"
    labelledAt j = arr M.! j
    firstWithId = M.fromListWith min [ ((k, otRId o), i) | (i, o) <- placed, Just k <- [robotKindOf o] ]
    -- The placed objects on a grid of 1 m cells (no object is larger), each
    -- in every cell its bounding box meets: a pair can only overlap if they
    -- share a cell. Each cell is split by class (robots, balls, walls and
    -- blocks), and an object is looked for only among the classes it can
    -- overlap ('overlapAtStart': two balls bounce apart, walls and blocks
    -- may overlap), so that a pile of 10000 balls on one spot is not
    -- checked pair by pair (it took minutes).
    grid = M.map reverse (M.fromListWith (++) [ ((classOf o, c), [(i, o)]) | (i, o) <- placed, c <- cellsOf o ])
    classOf o | robotKindOf o /= Nothing = 0
              | OTBall {} <- o           = 1
              | otherwise                = 2 :: Int
    against k = case k of
      0 -> [0, 1, 2]
      1 -> [0, 2]
      _ -> [0, 1]
    cellsOf o =
      let Point2 x y = otPos o
          (hw, hh)   = objectHalfSize o
      in [ (cx, cy) | cx <- [cell (x - hw) .. cell (x + hw)], cy <- [cell (y - hh) .. cell (y + hh)] ]
    cell v = floor (max (-1e9) (min 1e9 v)) :: Int
    -- (each cell's lists are in the order of the objects: only the part
    -- before this one is read)
    overlapsBefore i o =
      S.toAscList (S.fromList [ j | c <- cellsOf o, k <- against (classOf o)
                                  , (j, p) <- takeWhile ((< i) . fst) (M.findWithDefault [] (k, c) grid)
                                  , overlapAtStart o p ])
    -- How many pairs that check, or the physics, compares up to each
    -- placed object (the earlier objects of the classes it is looked for
    -- among, and for a ball the earlier balls too, in each of its cells),
    -- and the first object at which the running total passes
    -- 'maxClosePairs', with that total: that object and the ones after it
    -- are not checked for overlaps, so that the check's work is bounded
    -- (a file of 50,000 walls and 50,000 balls side by side in one square
    -- metre took more than 400 s), and a world whose physics would crawl
    -- is refused (100,000 balls piled on one spot took 7 minutes a step).
    counted k = if k == 1 then [0, 1, 2] else against k
    crowd =
      let step (counts, total) (_, o) =
            let k       = classOf o
                cs      = cellsOf o
                w       = sum [ M.findWithDefault 0 (k', c) counts | c <- cs, k' <- counted k ]
                counts' = foldl' (\m c -> M.insertWith (+) (k, c) (1 :: Int) m) counts cs
            in counts' `seq` total `seq` (counts', total + w)
      in find ((> maxClosePairs) . snd)
              [ (i, total) | ((i, _), (_, total)) <- zip placed (drop 1 (scanl' step (M.empty, 0) placed)) ]
    beforeCrowd i = maybe True ((i <) . fst) crowd
    crowdMessage w =
      "too crowded: the objects up to this one make " ++ show w ++ " pairs that share a 1 m square "
      ++ "(a robot and any object, a ball and a ball, wall or block; counted once for each square they "
      ++ "share), more than the " ++ show maxClosePairs ++ " that a world may have (the physics and "
      ++ "the check of overlaps compare such pairs one by one)"

-- | The most pairs of objects that may share a cell of 1 m by 1 m in a
-- world, among the pairs that the physics tests for contact at each step
-- or that could overlap where it cannot part them: a robot and any object,
-- a ball and a ball, wall or block (two walls or blocks are not counted):
-- 25,000,000, counted cell by cell (a pair that shares several cells
-- counts once in each), an object in each cell its bounding box meets.
-- 'validateWorld' compares the pairs that could overlap once each (two
-- balls may), and the physics those that touch at each step; past this
-- many, a world is refused as too crowded (reported at the object that
-- passes the bound), which keeps the check of a world file of
-- 'AFrobRobotSim.WorldFile.maxObjects' objects within seconds, and a
-- simulation step within minutes (5,000 walls beside 3,660 balls piled
-- on one spot, just below the bound, take 80 s a step; 7,071 balls on
-- one spot, 0.8 s; 100,000, which the floor's area let through, took 7
-- minutes). A world whose
-- objects lie apart, however many, has few: the 10,000 robots and 7,938
-- obstacles of the benchmarks' 316 m world make 1,091.
maxClosePairs :: Int
maxClosePairs = 25000000

-- | The largest share of a floor that equal discs lying apart can cover:
-- @pi / sqrt 12@, about 0.9069 (their hexagonal packing; Fejes Toth's
-- and Groemer's bound, which holds in any convex region for all discs
-- but one). 'validateWorld' refuses more balls than that.
densestPacking :: Double
densestPacking = pi / sqrt 12

-- | The area of a disc of the given diameter, in square metres.
discArea :: Length -> Double
discArea d = pi * (d / 2) * (d / 2)

-- | An area for a message: @"100.02 m^2"@.
squareMetres :: Double -> String
squareMetres a = showFFloat (Just 2) a " m^2"

-- | Do two objects overlap (more than touch) where the physics could not
-- separate them: a robot and anything, or a ball and a wall or block?
overlapAtStart :: ObjectTemplate -> ObjectTemplate -> Bool
overlapAtStart a b = case (discRadius a, discRadius b) of
  (Just ra, Just rb)
    | isRobot a || isRobot b -> norm (otPos a .-. otPos b) < ra + rb - touchSlack
    | otherwise              -> False            -- two balls: they bounce apart
  (Just ra, Nothing) -> discInBox (otPos a) ra b
  (Nothing, Just rb) -> discInBox (otPos b) rb a
  (Nothing, Nothing) -> False                    -- walls and blocks may overlap
  where
    isRobot o = robotKindOf o /= Nothing
    discRadius o = case o of
      OTBall {}    -> Just (ballDiameter / 2)
      OTSimbotA {} -> Just (simbotDiameter / 2)
      OTSimbotB {} -> Just (simbotDiameter / 2)
      _            -> Nothing
    discInBox (Point2 cx cy) r box =
      let Point2 bx by = otPos box
          (hw, hh)     = objectHalfSize box
          dx = max 0 (abs (cx - bx) - hw)
          dy = max 0 (abs (cy - by) - hh)
      in dx * dx + dy * dy < (r - touchSlack) * (r - touchSlack)
    -- objects placed to touch exactly may overlap by a rounding error
    touchSlack = 1e-9
