{-# LANGUAGE BangPatterns        #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- (forAllRuns runs the world it reports twice, once to decide and once
-- for its page, so that the first run is not kept while the page is
-- made: GHC must not share the two runs)
{-# OPTIONS_GHC -fno-full-laziness -fno-cse #-}
-- |
-- Module      : AFrobRobotSim.Test
-- Description : Properties of whole simbot runs: random valid worlds that
--               shrink by losing objects, temporal predicates over the
--               stream of world states, and the failing world written as a
--               world file.
--
-- A property of a controller is a 'TPred' over the world states of a run
-- ('WorldState', one per time step of 'simulateWith'), checked on random
-- worlds:
--
-- > forAllWorlds "failing.world" (genWorld defaultWorldMix notesBounds) $
-- >   runT defaultSimConfig 20 myController myController
-- >        (Always (SP (arr (all (not . robotStuck) . wsRobots))))
--
-- When it fails, QuickCheck removes objects from the world as long as it
-- still fails, prints the smallest world in the world-file format with the
-- instant the predicate was decided false, and writes it to the file, to
-- be run again with @simbot --world failing.world@. 'forAllRuns' does
-- both at once and also writes the failing run's replay page
-- (@failing.world.html@), to watch in a browser: it opens at the instant
-- that decided, and says it.
--
-- Everything here uses the simulator's public API only.
module AFrobRobotSim.Test
  ( -- * Random worlds
    WorldMix (..)
  , defaultWorldMix
  , genWorld
  , genRobotIn
  , shrinkWorld
  , objectBox
  , boxesOverlap
    -- * Runs as streams
  , runStream
  , robotView
  , showWorldState
    -- * Properties
  , forAllWorlds
  , runT
  , onRobot
  , hasRobot
  , forAllRuns
  , runReplayPage
  , writeRunReplayPage
  , writeFalsifiedRunReplayPage
  , worldFileText
    -- * Distances, for predicates
  , robotClearance
  , robotGap
  ) where

import           Control.Exception    (ErrorCall (..), IOException, SomeAsyncException, SomeException, bracketOnError,
                                       displayException, evaluate, fromException, try, throwIO, tryJust)
import           Data.IORef           (IORef, newIORef, readIORef, writeIORef)
import           Data.List            (intercalate, stripPrefix, tails)
import           Data.Maybe           (fromMaybe, isJust)
import           System.IO.Unsafe     (unsafeInterleaveIO)
import           Test.QuickCheck
import           Test.QuickCheck.Property (Callback (PostFinalFailure), CallbackKind (NotCounterexample), callback)
import           Test.QuickCheck.State (terminal)
import           Test.QuickCheck.Text  (putLine)

import           AFRP                 (SF, Time, arr, sscan, (&&&), (>>>))
import           AFRP.Geometry        (Point2 (..))
import           AFrob.Dimensions     (RobotId, RobotType)
import           AFrobRobotSim
import           AFrobRobotSim.Simulator (forceWorldState)
import           AFrobRobotSim.Options.Check (readableNumber)
import           AFrobRobotSim.World  (objectHalfSize, robotKindOf)
import           AFrobRobotSim.Log    (LogConfig (..), LogSummary (..), RunLog (..), defaultLogConfig,
                                       logFrames, logHeader)
import           AFrobRobotSim.Replay (discardReplay, newReplayRecorder, recordReplayState, replayEveryFrame, replayPage,
                                       writeReplay)
import           AFRP.Test.LTL
import           AFRP.Test.Stream

-- | How many objects of each kind 'genWorld' places: a range for each.
data WorldMix = WorldMix
  { mixWalls  :: (Int, Int)   -- ^ wall segments (horizontal or vertical)
  , mixBlocks :: (Int, Int)   -- ^ blocks
  , mixBalls  :: (Int, Int)   -- ^ balls
  , mixRobots :: (Int, Int)   -- ^ simbots (of both types)
  } deriving (Eq, Show)

-- | Up to 12 walls, 4 blocks, 3 balls and 1 to 5 robots.
defaultWorldMix :: WorldMix
defaultWorldMix = WorldMix (0, 12) (0, 4) (0, 3) (1, 5)

-- | @genWorld mix bounds@: a valid world of the given extent (see
-- 'validateWorldIn'), with the numbers of objects @mix@ asks for as far as
-- they fit: each object is placed at a random free spot, where its
-- bounding box ('objectBox') lies inside the world and overlaps no other
-- object's, so that robots start overlapping nothing. The robots are
-- placed first, so a world that has room for a robot gets at least one
-- when @mix@ asks for one (the first always fits), and the robots placed
-- get ids 1, 2, ... per type, in the world's order, and random headings.
-- An object that finds no free spot in 20 tries is left out. Bounds that
-- are not finite numbers with @x0 < x1@ and @y0 < y1@, bounds narrower or
-- lower than a simbot ('simbotDiameter') while @mix@ asks for at least
-- one robot, or a range of the mix whose low end is above its high end,
-- are an error naming them (such a world could hold no robot, and
-- properties of its runs would hold of none).
genWorld :: WorldMix -> Bounds -> Gen WorldTemplate
genWorld mix bounds = case problems of
  p : _ -> error ("AFrobRobotSim.Test.genWorld: " ++ p)
  []    -> generateIn mix bounds
  where
    Bounds bx0 by0 bx1 by1 = bounds
    problems =
      [ "the bounds " ++ show bounds ++ " are no extent (finite, x0 < x1, y0 < y1)"
      | not (all (\v -> not (isNaN v || isInfinite v)) [bx0, by0, bx1, by1] && bx0 < bx1 && by0 < by1) ]
      ++ [ "the range " ++ show r ++ " of " ++ name ++ " is empty"
         | (name, r@(lo, hi)) <- [ ("mixWalls", mixWalls mix), ("mixBlocks", mixBlocks mix)
                                 , ("mixBalls", mixBalls mix), ("mixRobots", mixRobots mix) ]
         , lo > hi ]
      ++ [ "the bounds " ++ show bounds ++ " are too small for a simbot (" ++ show simbotDiameter
           ++ " m across), and mixRobots asks for at least one"
         | fst (mixRobots mix) >= 1, bx1 - bx0 < simbotDiameter || by1 - by0 < simbotDiameter ]

-- 'genWorld' once its parameters are checked.
generateIn :: WorldMix -> Bounds -> Gen WorldTemplate
generateIn mix bounds = do
  let count (lo, hi) = chooseInt (max 0 lo, max 0 hi)
  nWalls  <- count (mixWalls mix)
  nBlocks <- count (mixBlocks mix)
  nBalls  <- count (mixBalls mix)
  nRobots <- count (mixRobots mix)
  let makers = replicate nRobots robotAt ++ replicate nWalls wallAt ++ replicate nBlocks (pure . OTBlock)
               ++ replicate nBalls (pure . OTBall)
  numberRobots <$> placeAll bounds makers []
  where
    wallAt p = elements [OTHWall p, OTVWall p]
    robotAt p = do
      k <- elements [SimbotA, SimbotB]
      h <- choose (-pi, pi)
      pure (case k of
              SimbotA -> OTSimbotA 0 p h
              SimbotB -> OTSimbotB 0 p h)
    -- (ids 1, 2, ... per type, for the robots that found a spot)
    numberRobots = go (0 :: RobotId) (0 :: RobotId)
      where
        go a b (o@OTSimbotA {} : os) = o { otRId = a + 1 } : go (a + 1) b os
        go a b (o@OTSimbotB {} : os) = o { otRId = b + 1 } : go a (b + 1) os
        go a b (o : os)              = o : go a b os
        go _ _ []                    = []

-- Place each object (a maker given its centre) at a free spot: its centre
-- drawn where its box lies inside the bounds, up to 20 times until the box
-- overlaps no object placed before it.
placeAll :: Bounds -> [Point2 Double -> Gen ObjectTemplate] -> WorldTemplate -> Gen WorldTemplate
placeAll _ [] placed = pure (reverse placed)
placeAll bounds (make : rest) placed = do
  mo <- tryPlace (20 :: Int)
  placeAll bounds rest (maybe placed (: placed) mo)
  where
    Bounds x0 y0 x1 y1 = bounds
    tryPlace 0 = pure Nothing
    tryPlace k = do
      -- (the maker's object at the origin: its kind, and so its size)
      shape <- make (Point2 0 0)
      let (hw, hh) = objectHalfSize shape
      if 2 * hw > x1 - x0 || 2 * hh > y1 - y0
        then pure Nothing
        else do
          p <- Point2 <$> choose (x0 + hw, x1 - hw) <*> choose (y0 + hh, y1 - hh)
          let o = movedTo p shape
          if fits o then pure (Just o) else tryPlace (k - 1)
    -- (a size line is no object: nothing overlaps it)
    fits o = inside (objectBox o) && not (any (boxesOverlap (objectBox o) . objectBox) (filter (not . isWorldSize) placed))
    inside (a, b, c, d) = a >= x0 && b >= y0 && c <= x1 && d <= y1
    movedTo p o = case o of
      OTSize {} -> o
      _         -> o { otPos = p }

-- | @genRobotIn bounds world@: a robot of either kind, with the next free
-- id of its kind, at a free spot of @world@ (as 'genWorld' places it), or
-- the world unchanged if there is none. The spot is inside @bounds@, or
-- inside the world's own size when it has one ('OTSize', which wins over
-- @bounds@ as in a run: 'worldBoundsOr').
genRobotIn :: Bounds -> WorldTemplate -> Gen WorldTemplate
genRobotIn given world = do
  k <- elements [SimbotA, SimbotB]
  h <- choose (-pi, pi)
  let i = 1 + maximum (0 : [ otRId o | o <- world, sameKind k o ])
      make p = pure (case k of
                       SimbotA -> OTSimbotA i p h
                       SimbotB -> OTSimbotB i p h)
  placeAll (worldBoundsOr given world) [make] (reverse world)
  where
    sameKind SimbotA OTSimbotA {} = True
    sameKind SimbotB OTSimbotB {} = True
    sameKind _       _            = False

-- | The worlds QuickCheck tries in place of a failing one: the world
-- without one of its objects, each in turn (the first half of its objects
-- first, when it has more than 8). The world's size ('OTSize') is kept:
-- it is no object, and without it the world would be the notes' 10 by 10,
-- in which its objects may not fit. So removing objects keeps a world
-- valid.
--
-- A world with a robot keeps at least one (as 'genWorld' gives one): in
-- a world without a robot, a property of some robot (@any@ over
-- 'wsRobots', a 'robotView') fails for want of one, whatever the world
-- holds, and the counterexample would be a world of no robot. Anything
-- else may go, one of several robots too: a property that needs an
-- object (a ball to reach, a robot by its id among several) should hold
-- of a world without it, or discard it (@==>@ in 'forAllWorlds'), since
-- QuickCheck takes a smaller world for the counterexample only when it
-- fails ('forAllRuns': @\\w -> if hasBall w then p else Always (SP
-- (constant True))@).
shrinkWorld :: WorldTemplate -> [WorldTemplate]
shrinkWorld w =
  map (sizes ++) (filter keepsRobot
    ([ take (n `div` 2) objs | n > 8 ] ++ [ drop (n `div` 2) objs | n > 8 ]
     ++ [ take k objs ++ drop (k + 1) objs | k <- [0 .. n - 1] ]))
  where
    (sizes, objs) = (filter isWorldSize w, filter (not . isWorldSize) w)
    n = length objs
    keepsRobot candidate = not (any isRobotObject objs) || any isRobotObject candidate

-- Whether an object is a simbot.
isRobotObject :: ObjectTemplate -> Bool
isRobotObject OTSimbotA {} = True
isRobotObject OTSimbotB {} = True
isRobotObject _            = False

-- | An object's bounding box, @(xMin, yMin, xMax, yMax)@ in metres, from
-- its centre and the sizes of "AFrobRobotSim.World". A size line
-- ('OTSize'), which is no object, gives the world's extent (centred on the
-- origin, as a world file's size is).
objectBox :: ObjectTemplate -> (Double, Double, Double, Double)
objectBox (OTSize w h) = (-w / 2, -h / 2, w / 2, h / 2)
objectBox o =
  let Point2 x y = otPos o
      (hw, hh)   = objectHalfSize o
  in (x - hw, y - hh, x + hw, y + hh)

-- | Whether two boxes share more than an edge.
boxesOverlap :: (Double, Double, Double, Double) -> (Double, Double, Double, Double) -> Bool
boxesOverlap (a0, b0, a1, b1) (c0, d0, c1, d1) = a0 < c1 && c0 < a1 && b0 < d1 && d0 < b1

-- | @runStream config duration world rcA rcB@: the run of 'simulateWith'
-- as a stream, one world state per time step of @config@ from time 0 to
-- @duration@ (the first sample at time step 0). A duration that is not a
-- finite number >= 0, or a time step ('simDt') that is not a finite
-- number > 0, is an error naming it: a stream of no sample would make
-- every property of the run hold. So is a duration of more than 2^53
-- time steps (which no run reaches; its count of steps would not be
-- exact).
runStream :: SimConfig -> Time -> WorldTemplate -> SimbotController -> SimbotController
          -> SignalSampleStream WorldState
runStream config duration world rcA rcB
  | isNaN duration || isInfinite duration || duration < 0 =
      error ("AFrobRobotSim.Test.runStream: the duration must be a finite number >= 0, got " ++ show duration)
  | isNaN (simDt config) || isInfinite (simDt config) || simDt config <= 0 =
      error ("AFrobRobotSim.Test.runStream: the time step (simDt) must be a finite number > 0, got "
             ++ show (simDt config))
  | duration / simDt config > 2 ^ (53 :: Int) =
      error ("AFrobRobotSim.Test.runStream: a duration of " ++ show duration ++ " s is more than 2^53 time steps of "
             ++ show (simDt config) ++ " s")
  | otherwise = zip (0 : repeat (simDt config)) (take (stepsWithin config duration + 1) (simulateWith config world rcA rcB))

-- The whole time steps of @config@ within a duration (the samples of
-- 'runStream' but the one at time 0): a run of a shorter duration is the
-- start of a longer one's.
stepsWithin :: SimConfig -> Time -> Int
stepsWithin config duration = floor (duration / simDt config + 1e-9)

-- | One robot's view of a run: its state at every sample, found by its
-- type (@\"SimbotA\"@ or @\"SimbotB\"@) and id. A robot that is not in
-- the run (a misspelt type, a wrong id) is an error naming it and the
-- robots there are: an empty view would make every property of it hold.
-- Lazy: each sample is looked at when the view's list gets to it (so a
-- predicate on the view of a long run keeps no more of it than it looks
-- ahead), and a sample without the robot is the error there (a run's
-- robots are the same at every sample; a stream made by hand may lose
-- one).
robotView :: RobotType -> RobotId -> SignalSampleStream WorldState -> SignalSampleStream RobotState
robotView ty i = go (0 :: Int)
  where
    go _ [] = []
    go k ((dt, ws) : rest) = let r = findRobot "robotView" ty i k ws in r `seq` (dt, r) : go (k + 1) rest

-- @findRobot caller ty i k ws@: the robot @ty i@ in @ws@, the sample
-- number @k@ of a run; if it is not there, the error of @caller@ that
-- names it and the robots there are (at sample 0, the run's robots).
findRobot :: String -> RobotType -> RobotId -> Int -> WorldState -> RobotState
findRobot caller ty i k ws = case [ r | r <- wsRobots ws, robotType r == ty, robotId r == i ] of
  r : _ -> r
  []    -> error ("AFrobRobotSim.Test." ++ caller ++ ": no " ++ ty ++ " " ++ show i ++ " in the run"
                  ++ (if k == 0 then "" else " at sample " ++ show k)
                  ++ " (its robots" ++ (if k == 0 then "" else " there") ++ ": " ++ robotsOf ++ ")")
  where
    robotsOf = case [ robotType r ++ " " ++ show (robotId r) | r <- wsRobots ws ] of
      [] -> "none"
      ns -> intercalate ", " ns

-- | A world state in one line: the time (with 2 to 6 decimals, as its
-- time step needs: @t=16.50@, @t=2.001@), then each
-- robot's type, id, position, heading (@h=@, radians) and signed speed
-- along it (@v=@, m/s, negative when it backs; 'robotSpeed'), and
-- @stuck@ if it is, and the balls' positions. A value that is not a
-- finite number is written @NaN@, @Infinity@ or @-Infinity@.
--
-- > t=10.90  SimbotB 1 (-0.930, -1.813) h=0.78 v=0.00 stuck
showWorldState :: WorldState -> String
showWorldState ws =
  "t=" ++ showTime (wsTime ws) ++ concatMap robot (wsRobots ws)
  ++ (if null (wsBalls ws) then "" else "  balls" ++ concatMap pos (wsBalls ws))
  where
    robot r = "  " ++ robotType r ++ " " ++ show (robotId r) ++ pos (robotPos r)
              ++ " h=" ++ fixed 2 (robotHeading r) ++ " v=" ++ fixed 2 (robotSpeed r)
              ++ (if robotStuck r then " stuck" else "")
    pos (Point2 x y) = " (" ++ fixed 3 x ++ ", " ++ fixed 3 y ++ ")"

-- A time with 2 to 6 decimals (6, trailing zeros after the second
-- dropped): @16.50@, @2.001@.
showTime :: Time -> String
showTime t =
  let str = fixed 6 t
      (whole, frac) = break (== '.') str
  in whole ++ take 3 frac ++ reverse (dropWhile (== '0') (reverse (drop 3 frac)))

-- A number with @k@ decimals, rounded (no @-0.00@).
fixed :: Int -> Double -> String
fixed _ v | isNaN v      = "NaN"
          | isInfinite v = if v > 0 then "Infinity" else "-Infinity"
fixed k v = let m = 10 ^ k :: Integer
                r = round (abs v * fromIntegral m) :: Integer
                (q, f) = r `divMod` m
                fs = show f
            in (if v < 0 && r /= 0 then "-" else "") ++ show q ++ "." ++ replicate (k - length fs) '0' ++ fs

-- | @forAllWorlds file gen prop@: @prop@ for worlds from @gen@, shrunk
-- with 'shrinkWorld'. A failing world is printed in the world-file format
-- and, once shrinking is done, written to @file@; the report says so
-- (@(the world is written to failing.world)@), or why it could not be
-- written, and goes on with what @prop@ says of the failure. The world
-- is written as it is ('renderWorld'): one that @prop@ runs in bounds
-- other than the notes' 10 by 10 should carry its 'OTSize' to run again
-- the same way (or be checked with 'forAllRuns', which writes the size
-- line of its config's bounds: 'worldFileText').
forAllWorlds :: Testable prop => FilePath -> Gen WorldTemplate -> (WorldTemplate -> prop) -> Property
forAllWorlds file gen prop =
  forAllShrinkShow gen shrinkWorld renderWorld $ \w ->
    reportingAfter (inParentheses <$> wroteOrNot "the world" file (writeFile file (renderWorld w))) (prop w)
  where inParentheses l = "(" ++ l ++ ")"

-- @reportingAfter write prop@: @prop@; once QuickCheck has its failure
-- (shrinking done), @write@ runs, and the line it gives is printed where
-- 'counterexample' prints, before what @prop@ says of the failure. (A
-- 'whenFail' whose write threw, to a folder that is not there, ended the
-- report there: what @prop@ says, the instant that decided, was lost.)
-- Not a callback of the counterexample's kind, which 'verbose' runs
-- after every test, passed or not: as 'whenFail', only for the failure.
reportingAfter :: Testable prop => IO String -> prop -> Property
reportingAfter write = callback (PostFinalFailure NotCounterexample (\st _ -> write >>= putLine (terminal st)))

-- @wroteOrNot what file write@: @write@ run, and the words that say
-- @what@ is written to @file@, or why it is not (its synchronous
-- exception: an interrupt still stops the test): an I/O failure's
-- message, without the file's name when it begins with it ("could not be
-- written to F: openFile: does not exist ..."), or what else went wrong
-- in making it ("could not be made for F: ...", an error's message
-- without its call stack, which QuickCheck prints with the exception).
wroteOrNot :: String -> FilePath -> IO () -> IO String
wroteOrNot what file write = do
  r <- tryJust synchronous write
  pure $ case r of
    Right () -> what ++ " is written to " ++ file
    Left e | Just (io :: IOException) <- fromException e ->
      let msg = show io
      in what ++ " could not be written to " ++ file ++ ": " ++ fromMaybe msg (stripPrefix (file ++ ": ") msg)
    Left e | Just (ErrorCallWithLocation msg _) <- fromException e -> what ++ " could not be made for " ++ file ++ ": " ++ msg
    Left e -> what ++ " could not be made for " ++ file ++ ": " ++ displayException e

-- An exception that is not asynchronous (a timeout's, Ctrl-C's).
synchronous :: SomeException -> Maybe SomeException
synchronous e = case fromException e of
  Just (_ :: SomeAsyncException) -> Nothing
  Nothing                        -> Just e

-- | @runT config duration rcA rcB p world@: the predicate @p@ holds at
-- time 0 of the run of @world@ ('runStream'). When it does not, the
-- counterexample says at which instant it was decided false, with the
-- world states around it ('showWorldState').
--
-- The run is made once, as it is checked ('explainT'), and kept no
-- more than the predicate owes ('evalT': a predicate like @Always (SP
-- ...)@ holds one world state at a time, so an hour's run costs no more
-- memory than a minute's, whether it fails early, late or not at all).
--
-- The run ends at its last whole time step within @duration@ (at
-- @duration@ when 'simDt' divides it): a deadline beyond it has not
-- passed, so @'eventuallyWithin' 25 p@ holds of a 20 s run in which @p@
-- never holds (see 'eventuallyWithin'). Give a duration of at least the
-- longest bound of @p@ plus one time step.
runT :: SimConfig -> Time -> SimbotController -> SimbotController -> TPred WorldState
     -> WorldTemplate -> Property
runT config duration rcA rcB p world =
  explainedRun (explainT p (runStream config duration world rcA rcB))

-- @explainedRun explanation@: 'runT''s property of a run's 'explainT':
-- a failure printed with the world states around the instant that
-- decided. (The run is read as the property is, once.)
explainedRun :: Maybe (Explanation WorldState) -> Property
explainedRun explanation = case explanation of
  Nothing -> property True
  Just e  -> counterexample (explanationText e) False
  where
    explanationText e = unlines $
      (decidedLine e ++ ":")
      : [ (if j == explFrame e then "  > " else "    ") ++ showWorldState ws | (j, _, ws) <- explAround e ]

-- The first line of what 'runT' prints of a failure: the instant that
-- decided, @decided false at t = 6.76 (step 338)@.
decidedLine :: Explanation WorldState -> String
decidedLine e = "decided false at t = " ++ showTime (explTime e) ++ " (step " ++ show (explFrame e) ++ ")"

-- | @onRobot ty i p@: the predicate @p@ of one robot's states, found by
-- its type (@\"SimbotA\"@ or @\"SimbotB\"@) and id, as a predicate of a
-- run's world states, for 'runT' and 'forAllRuns': their report of a
-- failure is then the instant that decided and the world states around
-- it ('showWorldState', one line each, not @RobotState@ records), and
-- 'forAllRuns' writes the failing run's replay page, as for any
-- predicate of theirs.
--
-- > -- (corridors: random worlds of walls and one SimbotA 1)
-- > forAllRuns "failing.world" defaultSimConfig 20 rcA rcB corridors
-- >   (\_ -> onRobot "SimbotA" 1 (Always (SP (arr (not . robotStuck)))))
--
-- It holds of a run exactly when @p@ holds of the robot's view
-- ('robotView'), and is decided false at the same instant: it is @p@
-- 'tPredOn' the robot's state, so at time 0 @p@'s atoms see the robot's
-- state at time 0, and an atom with state ('previously', an
-- 'AFRP.iPre' of the speed) keeps it from time 0 on, as on the view.
--
-- A robot that is not in the run (a misspelt type, a wrong id) is an
-- error naming it and the robots there are, as for 'robotView': @p@
-- would otherwise hold of nothing. The first sample is always looked at,
-- so a @p@ whose atoms ignore their input finds it out too; the other
-- samples as @p@ reads them (a run's robots are the same at every
-- sample; a hand-made stream that loses the robot is the error at the
-- sample that does, when @p@ reads it there). With 'runT' and
-- 'forAllRuns', QuickCheck reports the error as the failure. So when
-- random worlds need not have the robot ('genWorld' picks each robot's
-- type at random) or have others beside it, give worlds without it a
-- predicate that holds (@\\w -> if 'hasRobot' ty i w then onRobot ty i p
-- else Always (SP (arr (const True)))@): 'shrinkWorld' may remove it while
-- keeping another robot, and the error would then be the
-- counterexample. A world's only robot stays while it shrinks.
onRobot :: RobotType -> RobotId -> TPred RobotState -> TPred WorldState
onRobot ty i p =
  -- (the And's first operand makes the robot's state at time 0, which
  -- finds a missing robot whatever p reads; it is true wherever it is
  -- made, so the And is p, sample by sample)
  tPredOn (robotOf ty i) (And (SP (arr (`seq` True))) p)

-- | @hasRobot ty i world@: whether @world@ has the robot of type @ty@
-- (@\"SimbotA\"@ or @\"SimbotB\"@) and id @i@, the robot that
-- @'onRobot' ty i p@ and 'robotView' find in the world's runs (a run has
-- the robots of its world, from time 0 on). The guard of a predicate of
-- one robot for random worlds that need not have it:
--
-- > forAllRuns "failing.world" defaultSimConfig 20 rcA rcB (genWorld defaultWorldMix notesBounds) $ \w ->
-- >   if hasRobot "SimbotA" 1 w then onRobot "SimbotA" 1 (Always (SP (arr (not . robotStuck))))
-- >   else Always (SP (arr (const True)))
--
-- > hasRobot "SimbotB" 1 [OTSimbotA 1 (Point2 0 0) 0, OTSimbotB 1 (Point2 2 0) 0]  ==  True
-- > hasRobot "SimbotB" 2 [OTSimbotA 1 (Point2 0 0) 0, OTSimbotB 1 (Point2 2 0) 0]  ==  False
-- > hasRobot "SimbotA" 2 [OTSimbotB 2 (Point2 0 0) 0]                               ==  False
hasRobot :: RobotType -> RobotId -> WorldTemplate -> Bool
hasRobot ty i = any (\o -> fmap kindType (robotKindOf o) == Just ty && otRId o == i)

-- The robot's state at each sample, its sample number at hand for the
-- error of a robot not there.
robotOf :: RobotType -> RobotId -> SF WorldState RobotState
robotOf ty i = (sscan (\k _ -> k + 1) (-1) &&& arr id) >>> arr (\(k, ws) -> findRobot "onRobot" ty i k ws)

-- | @forAllRuns file config duration rcA rcB gen p@: the predicate @p w@
-- ('runT') holds for the run of every world @w@ from @gen@. A failing world is
-- shrunk ('shrinkWorld'); the smallest is printed, written to @file@ in the
-- world-file format with the size the run gave it ('worldFileText') and
-- its run's replay page to @file ++ \".html\"@; the report says so
-- (@(the world is written to failing.world; its run's replay page is
-- written to failing.world.html)@), or why one could not be written,
-- and goes on with what 'runT' prints.
-- The page shows the run up to 5 simulated seconds past the instant that
-- decided @p@ false (what 'runT' prints), or up to a controller's
-- failure, if one failed; the whole run when neither ends it sooner. (A
-- failure early in a long run makes a short page: the page of the whole
-- run could take longer than the test.) It opens at that instant, marked
-- on its time slider, and says it (@FAILED: decided false at t = 6.76
-- (step 338)@ in its heading and its summary): 'writeFalsifiedRunReplayPage'.
-- A page of a controller's failure ('writeRunReplayPage') says the failure.
-- A predicate that throws (an 'onRobot' of a robot not there, say)
-- decides nothing: its page ends 5 s past the sample it threw at, and
-- the report shows the exception. Each world is run once to decide and
-- explain it, as by 'runT' and in its memory, and the world QuickCheck
-- reports once more for its page, recorded as the run goes.
--
-- > forAllRuns "failing.world" defaultSimConfig 20 rcA rcB
-- >   (genWorld defaultWorldMix notesBounds)
-- >   (\_ -> Always (SP (arr (all (not . robotStuck) . wsRobots))))
forAllRuns :: FilePath -> SimConfig -> Time -> SimbotController -> SimbotController
           -> Gen WorldTemplate -> (WorldTemplate -> TPred WorldState) -> Property
forAllRuns file config duration rcA rcB gen p =
  forAllShrinkShow gen shrinkWorld (worldFileText config) $ \w -> idempotentIOProperty $ do
    -- (each world is run once to decide and explain it, in the memory
    -- the predicate owes, counting the samples it reads: the page of a
    -- predicate that throws ends 5 s past the last one; the world
    -- QuickCheck reports is run once more, for its page, only as far as
    -- the page shows)
    lastRead <- newIORef (0 :: Int)
    run <- countingSamples lastRead (runStream config duration w rcA rcB)
    let explanation = explainT (p w) run
    pure $
      reportingAfter (do wroteWorld <- wroteOrNot "the world" file (writeFile file (worldFileText config w))
                         wrotePage <- wroteOrNot "its run's replay page" page $ do
                           (upTo, decided) <- pageEnd explanation lastRead
                           -- (the run up to upTo; its first sample at
                           -- least, so that a run runStream refuses, of a
                           -- negative duration, is its error here, not a
                           -- page of no frame)
                           recordRunPage decided page config w
                                         (take (max 1 (stepsWithin config upTo + 1))
                                               (map snd (runStream config duration w rcA rcB)))
                         pure ("(" ++ wroteWorld ++ "; " ++ wrotePage ++ ")"))
                     (explainedRun explanation)
  where
    page = file ++ ".html"
    -- (the instant that decided and the line runT prints of it; a
    -- controller's failure or a predicate that throws leaves no instant,
    -- and the page ends 5 s past the last sample deciding read: after a
    -- controller's failure, the page then ends at the failure; a
    -- predicate that throws at the start of a run of 10^6 s made a page
    -- of the whole run; an asynchronous exception, such as a timeout's,
    -- is not caught)
    pageEnd explanation lastRead = do
      decided <- tryJust synchronous (evaluate (case explanation of
                                                  Nothing -> Nothing
                                                  Just e  -> let d@(t, line) = (explTime e, decidedLine e)
                                                             in t `seq` length line `seq` Just d))
      lastIndex <- readIORef lastRead
      pure $ case decided of
        Right (Just d@(t, _)) -> (min duration (t + 5), Just d)
        _                     -> (min duration (fromIntegral lastIndex * simDt config + 5), Nothing)

-- The stream as it is, keeping in the cell the index of the last sample
-- read from it (0 before any: a sample is read when the list's cell that
-- holds it is first taken apart), so that what a consumer that throws
-- had read is known.
countingSamples :: IORef Int -> SignalSampleStream a -> IO (SignalSampleStream a)
countingSamples lastRead = go 0
  where
    go !k xs = unsafeInterleaveIO $ case xs of
      []       -> pure []
      x : more -> writeIORef lastRead k >> (x :) <$> go (k + 1) more

-- | @worldFileText config world@: @world@ in the world-file format
-- ('renderWorld'), as the run of @config@ saw it: a world without an
-- 'OTSize' is run in the config's 'simBounds', so when those are not the
-- notes' 10 by 10 the text gets the @size@ line that says them, and the
-- file runs again as it ran (@simbot --world@). A world file's size is
-- centred on the origin, each side from 'minWorldSide' to 'maxWorldSide'
-- (1 to 1000 m); bounds that are not get a comment that says them
-- instead.
worldFileText :: SimConfig -> WorldTemplate -> String
worldFileText config world
  | isJust (worldSize world) || bounds == notesBounds = renderWorld world
  | bounds == sizeBounds w h && all sizeSide [w, h] = renderWorld (OTSize w h : world)
  | otherwise = "# the run's world was [" ++ show x0 ++ ", " ++ show x1 ++ "] x [" ++ show y0 ++ ", " ++ show y1
                ++ "] (simBounds), which a size line (centred, each side " ++ readableNumber minWorldSide ++ " to "
                ++ readableNumber maxWorldSide ++ " m) cannot say\n" ++ renderWorld world
  where
    bounds@(Bounds x0 y0 x1 y1) = simBounds config
    (w, h) = (x1 - x0, y1 - y0)
    sizeSide v = v >= minWorldSide && v <= maxWorldSide

-- | @runReplayPage config duration world rcA rcB@: the self-contained
-- HTML replay page ("AFrobRobotSim.Replay") of the run of 'runStream',
-- frames at 25 per simulated second (at every step, for a time step
-- longer than a 25th of a second), as @simbot --replay@ writes it. The
-- page is ASCII text. A controller that fails (throws, or drives with a
-- NaN) raises its 'ControllerError' when the page is evaluated, and a
-- referee's rule that fails ('simBallRule', 'simScores') its
-- 'RefereeError': for such a run, 'writeRunReplayPage' writes the page up
-- to the failure, with the last state's scores in its summary. The page
-- opens with a hash of all its lines (the nonce of its scripts), so its
-- first character comes only once the whole run is made, and the run is
-- held in memory until then: for a long run, 'writeRunReplayPage', which
-- keeps memory constant.
runReplayPage :: SimConfig -> Time -> WorldTemplate -> SimbotController -> SimbotController -> String
runReplayPage config duration world rcA rcB =
  pageOf config world (map snd (runStream config duration world rcA rcB)) Nothing

-- | @writeRunReplayPage file config duration world rcA rcB@ writes the
-- run's replay page ('runReplayPage') to @file@; when a controller fails,
-- the page holds the run up to the step before the failure, and its
-- summary says the failure ("FAILED: ..." on the page), as @simbot@'s page
-- of a failed run does. The page is recorded as the run goes, as
-- @simbot --replay@ records it ("AFrobRobotSim.Replay"'s recorder: each
-- frame's line goes to a temporary file, streamed into the page at the
-- end), so memory stays constant however long the run: it does not hold
-- the run's states or frames. The page is written whole or not at all.
writeRunReplayPage :: FilePath -> SimConfig -> Time -> WorldTemplate -> SimbotController -> SimbotController
                   -> IO ()
writeRunReplayPage = writeRunPage Nothing

-- | @writeFalsifiedRunReplayPage file config duration world rcA rcB (t, line)@:
-- 'writeRunReplayPage' for a run of which a property was decided false
-- at @t@ (seconds from the run's start), @line@ saying so ('forAllRuns'
-- gives the first line of what 'runT' prints: @decided false at t =
-- 6.76 (step 338)@). The page says @FAILED: @ and the line in its heading
-- and its summary, marks the instant on its time slider and opens at the
-- frame nearest it; its log's summary has them as its @falsified@
-- (docs/LOG.md).
writeFalsifiedRunReplayPage :: FilePath -> SimConfig -> Time -> WorldTemplate -> SimbotController
                            -> SimbotController -> (Time, String) -> IO ()
writeFalsifiedRunReplayPage file config duration world rcA rcB decided =
  writeRunPage (Just decided) file config duration world rcA rcB

-- 'writeRunReplayPage', with the instant a property was decided false
-- and its line, if any.
writeRunPage :: Maybe (Time, String) -> FilePath -> SimConfig -> Time -> WorldTemplate -> SimbotController
             -> SimbotController -> IO ()
writeRunPage decided file config duration world rcA rcB =
  recordRunPage decided file config world (map snd (runStream config duration world rcA rcB))

-- 'writeRunPage' of the run's states (made lazily: the run goes as far as
-- they are read, and they are not kept).
recordRunPage :: Maybe (Time, String) -> FilePath -> SimConfig -> WorldTemplate -> [WorldState] -> IO ()
recordRunPage decided file config world states =
  -- (the recorder's temporary file closed whatever stops the run: an
  -- error, a timeout's or Ctrl-C's exception)
  bracketOnError (newReplayRecorder replayEveryFrame (pageConfig config world)) discardReplay $ \recorder -> do
    (steps, simulated, scores, failure) <- record recorder 0 0 [] states
    writeReplay recorder (pageSummary steps simulated (-1) scores failure decided) file
  where
    -- (each state evaluated as simbot evaluates it before recording it;
    -- the steps counted and the last one's time and scores kept,
    -- strictly; a controller's or the referee's failure ends the page)
    record recorder !steps !simulated scores xs = do
      r <- try (evaluate xs >>= \ys -> case ys of
                  []    -> pure Nothing
                  y : _ -> Just y <$ evaluate (forceWorldState y))
      case r of
        Left (e :: SomeException)
          | isRunFailure e          -> pure (steps, simulated, scores, Just (displayException e))
          | otherwise               -> throwIO e
        Right Nothing               -> pure (steps, simulated, scores, Nothing)
        Right (Just y)              -> do
          recordReplayState recorder y
          record recorder (steps + 1 :: Int) (wsTime y) (wsScores y) (drop 1 xs)

-- The page of a run's states, with its failure if it had one.
pageOf :: SimConfig -> WorldTemplate -> [WorldState] -> Maybe String -> String
pageOf config world states failure =
  replayPage (RunLog (logHeader cfg) frames (Just summary) Nothing)
  where
    cfg     = pageConfig config world
    frames  = logFrames cfg states
    summary = pageSummary (length states) (if null states then 0 else wsTime (last states)) (length frames)
                          (if null states then [] else wsScores (last states)) failure Nothing

-- The log's settings for a run's page.
pageConfig :: SimConfig -> WorldTemplate -> LogConfig
pageConfig config world =
  defaultLogConfig { lcBounds = simBounds config, lcWorld = world, lcDt = simDt config
                   , lcSeed = simSeed config, lcCommandLine = ["afrp-test"] }

-- @pageSummary steps simulated frames scores failure decided@: a run's
-- page's summary (steps: the samples, the one at time 0 included, as the
-- log counts them; the time of the last; the frames, or -1 for the
-- recorder's count; the last one's scores ('wsScores'); the instant a
-- property was decided false, and its line).
pageSummary :: Int -> Time -> Int -> [(String, Int)] -> Maybe String -> Maybe (Time, String) -> LogSummary
pageSummary steps simulated frames scores failure decided =
  LogSummary { lsSimulated = simulated, lsSteps = steps, lsFrames = frames
             , lsWallTime = 0, lsInterrupted = False, lsFailure = failure, lsFalsified = decided, lsScores = scores }

-- | @robotClearance world r@: the distance from the edge of robot @r@'s
-- disc to the nearest wall segment or block of @world@ (negative if they
-- overlap). The world's boundary does not count. Infinite if there is
-- none.
robotClearance :: WorldTemplate -> RobotState -> Double
robotClearance world r =
  minimum (1 / 0 : [ boxDistance (robotPos r) (objectBox o) - simbotDiameter / 2 | o <- world, isObstacle o ])
  where
    isObstacle OTBlock {} = True
    isObstacle OTVWall {} = True
    isObstacle OTHWall {} = True
    isObstacle _          = False

-- The distance from a point to a box (0 inside it).
boxDistance :: Point2 Double -> (Double, Double, Double, Double) -> Double
boxDistance (Point2 x y) (x0, y0, x1, y1) =
  let gx = maximum [0, x0 - x, x - x1]
      gy = maximum [0, y0 - y, y - y1]
  in sqrt (gx * gx + gy * gy)

-- | The smallest distance between the edges of two robots' discs in a
-- world state (negative if two overlap); infinite with fewer than two.
robotGap :: WorldState -> Double
robotGap ws = minimum (1 / 0 : [ dist (robotPos a) (robotPos b) - simbotDiameter
                               | (a : rest) <- tails (wsRobots ws), b <- rest ])
  where dist (Point2 ax ay) (Point2 bx by) = sqrt ((ax - bx) ^ (2 :: Int) + (ay - by) ^ (2 :: Int))
