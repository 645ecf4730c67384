{-# LANGUAGE BangPatterns        #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- The chunks of a parallel step ("AFrobRobotSim.Chunks"'s 'stepEvery',
-- inlined here, so that their thunks are compiled in this module) and
-- each robot's step in them are blackholed as soon as a thread enters
-- them, so that a thread that needs a chunk another is computing waits
-- for it instead of computing it again. Do not drop this flag.
{-# OPTIONS_GHC -feager-blackholing #-}
-- |
-- Module      : AFrobRobotSim.Simulator
-- Description : The pure, deterministic simulation engine.
--
-- 'simulate' turns a world template and the two controllers into a lazy
-- list of snapshots, one per fixed time step, the first at time 0. At each
-- step every robot's controller sees the same sample of the world (taken
-- before anything moves), then the robots move (in template order), then
-- the balls. The engine is pure Haskell: the same inputs give the same
-- snapshots, bit for bit.
--
-- = Every core
--
-- When the program runs on several capabilities (@+RTS -N@, in a program
-- built @-threaded@), the bulk of each step's work is computed in
-- parallel: every robot's sensing and controller step, and the part of
-- its move that depends on nothing but the robot, its command and the
-- arena ('AFrobRobotSim.Physics.planMove': its motion and its first
-- contact with a box). The robots are cut into consecutive chunks (about
-- sixteen per capability, at least 16 robots each), evaluated by a fixed
-- pool of worker threads from the first, and by the stepping thread
-- ("AFrobRobotSim.Chunks"; the threads are "AFrobRobotSim.Workers"'s).
-- The sensors' indexes are built and the chunks handed out before the
-- snapshot before the step is given to its reader, so that the workers
-- compute while the snapshot is read (by a log writer, say). The stepping thread moves the robots against
-- each other in template order (a robot's move depends on the moves of
-- those before it), reading each chunk as it reaches it: a chunk no
-- worker has taken, it computes; while it would wait for one a worker is
-- computing, it computes chunks from the last instead. So the moves are
-- made while the workers compute the later chunks. Each chunk is a pure
-- value, and the step's lists are the chunks' lists concatenated in
-- order, so the snapshots are the same, bit for bit, on any number of
-- cores; a failing controller fails the step with the error of the first
-- failing robot in template order, as on one core. The balls move after
-- the robots, on the stepping thread. On one capability the steps are
-- computed in order, by the stepping thread alone, in chunks too: a chunk
-- of 64 robots when the move of its first robot needs it (so that few
-- robots' outputs and plans wait for their move, and the stack stays
-- shallow: at 10,000 robots the collector copied 42% less than when every
-- robot's step was computed before the first move). A run with
-- 'simParallel' 'False' is stepped so whatever the capabilities: several
-- such runs side by side, each on a thread pinned to its own capability,
-- each keep to one core (@bench/side-by-side.sh@ compares two such runs
-- with one run in parallel: @bench/README.md@, its nineteenth round).
--
-- A larger allocation area than the runtime's 1 MB matters: each minor
-- collection copies the robots' live state, and on several cores every
-- collection stops them all. The project's programs (@simbot@,
-- @afrp-examples@, @my-robot-show@) are linked with
-- @-with-rtsopts=-A8m@: on one core 1000 robots ran about 9% faster than
-- with @-A4m@ (the collector's time halved), and with @-A4m@ @+RTS -N2@
-- ran them 1.65-1.7x as fast as one core on an otherwise idle machine
-- (@bench/README.md@); with the 1 MB area, two cores ran slower than one. When other work
-- holds the second core, @+RTS -N2 -qg@ (a sequential collector) loses
-- less. They are linked with @-qb0@ too: the parallel collector's threads
-- then share the work of the minor collections as well as the major ones
-- (the runtime's default balances only the major ones), which at 10,000
-- robots on two cores raised its work balance from about 50% to 75% and
-- the run from 0.43x to 0.50x real time (medians of ten alternating
-- runs); at 1000 robots and in small worlds it changed nothing measurable.
module AFrobRobotSim.Simulator
  ( -- * Running
    simulate
  , simulateWith
  , simulateUnchecked
  , SimConfig (..)
  , defaultSimConfig
  , maxTimeStep
  , maxOdometryNoise
  , keyDue
  , keyAtStep
  , keysNeverPressed
    -- * Snapshots
  , WorldState (..)
  , forceWorldState
  , RobotState (..)
  , startRobotStates
    -- * Failures
  , ControllerError (..)
  , RefereeError (..)
  , isRunFailure
  ) where

import           Control.Exception       (ErrorCall (..), throw)
import           GHC.Arr                 (Array, listArray, (!))
import           Data.Bits               (shiftR, xor)
import           Data.List               (foldl', sortOn)
import qualified Data.Set                as Set
import           Data.Word               (Word64)
import           Text.Printf             (printf)

import           AFRP
import           AFrob.Angle             (normalizeAngle, normalizeHeading)
import           AFrob.Dimensions
import           AFrob.RobotIO           (BatteryStatus, HasRobotProperties (..))
import           AFrobRobotSim.Arena
import           AFrobRobotSim.Balls
import           AFrobRobotSim.Chunks
import           AFrobRobotSim.Physics
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Sensors
import           AFrobRobotSim.Simulator.Failure
import           AFrobRobotSim.World
import           AFrobRobotSim.World.Check (validateWorldIn)

-- | Settings of a simulation run.
data SimConfig = SimConfig
  { simDt             :: !DTime         -- ^ the fixed time step (s), positive and at most 'maxTimeStep'
  , simKeys           :: [(Time, Char)] -- ^ scripted key presses: each is down for one sample, the first at or after its time that is free ('keyAtStep': one key a sample, and a key pressed again straight after itself is released for a sample first)
  , simSeed           :: !Int           -- ^ seed of the odometry noise
  , simOdometryNoise  :: !Double        -- ^ relative odometry error per step (0 = exact odometry), at most 'maxOdometryNoise'
  , simBounds         :: !Bounds        -- ^ the world's extent, unless the template has an 'OTSize' (which wins)
  , simBallRule       :: Time -> [Position2] -> Maybe [Position2]
    -- ^ a referee: after each step, given the time and the balls' new
    -- positions, 'Just' new positions puts the balls there, at rest (for
    -- example the centre mark after a goal); 'Nothing' leaves them be.
    -- It must give one position for each ball, in the same order, each
    -- where the ball lies inside the world; otherwise, or if it throws,
    -- the run stops there with a 'RefereeError' that says so. (Whether a
    -- ball so placed overlaps a wall, block or robot is not checked.)
  , simScores         :: SF WorldState [(String, Int)]
    -- ^ the scores a referee keeps: a signal function of the snapshots,
    -- stepped once a snapshot at the time step, whose output for a
    -- snapshot is that snapshot's 'wsScores' (the first, at time 0, is
    -- its output at time 0 on the first snapshot). It sees each snapshot
    -- as it is but for its scores (@[]@ there), so it may keep state
    -- ('accumHold', 'edge', ...) to count goals, say. Its output for each
    -- snapshot is evaluated whole at that step (so that a run's memory
    -- stays bounded); names must be distinct and at most 'maxTextChars'
    -- characters long, values within 2^53 (the log writes them as JSON's
    -- doubles). If it throws, or gives a name twice, one too long or a
    -- value beyond, the run stops there with a 'RefereeError'. The
    -- default, @'constant' []@, keeps none.
  , simParallel       :: !Bool
    -- ^ whether a step may use the program's other capabilities (see
    -- "Every core" above): 'True' (the default) computes it in parallel
    -- when the program runs on several; 'False' computes it on the thread
    -- that reads the snapshots alone, whatever the capabilities. The
    -- snapshots are the same either way, bit for bit. 'False' is for a
    -- program that runs several simulations side by side (a sweep's runs
    -- in one program, say), each read by a thread pinned to its own
    -- capability ('Control.Concurrent.forkOn'): each run then keeps to
    -- that capability instead of sharing the workers with the others.
    -- (The runtime's collections still stop every capability.)
  }

-- The balls' positions that a referee ('simBallRule') gave, checked: as
-- many as there are balls, each a finite point where its disc lies
-- inside the world ('insideBounds'); otherwise an error that says
-- what the rule did (a NaN or a ball beyond the walls was carried on into
-- every later step, and a missing ball was silently lost).
refereed :: Bounds -> Int -> [Position2] -> [Position2]
refereed bounds@(Bounds x0 y0 x1 y1) n ps
  | k /= n = bad ("it gave " ++ show k ++ " position" ++ plural k ++ " for " ++ show n ++ " ball" ++ plural n
                  ++ " (it must give one for each)")
  | (i, Point2 x y) : _ <- outside =
      bad ("it put ball " ++ show (i :: Int) ++ " (in the list's order) at (" ++ show x ++ ", " ++ show y
           ++ "), not a point where it lies inside the world [" ++ show x0 ++ ", " ++ show x1 ++ "] x ["
           ++ show y0 ++ ", " ++ show y1 ++ "]")
  | otherwise = ps
  where
    k = length ps
    outside = [ ip | ip@(_, p) <- zip [1 ..] ps, not (insideBounds bounds (OTBall p)) ]
    plural m = if m == 1 then "" else "s"
    -- (raised inside the rule's 'blaming': a 'RefereeError' at its time)
    bad what = throw (ErrorCall what)

-- | The longest time step 'simulate' takes: 10^6 s (about 11 days). The
-- motion's arithmetic stays finite far beyond (a robot's turn overflows
-- near 10^307 s, and its position became NaN), but no run needs a step
-- this long, and a mistyped one is better refused than simulated.
maxTimeStep :: DTime
maxTimeStep = 1e6

-- | The largest relative odometry error per step 'simulate' takes: 1
-- (100%). Beyond it a step's error can reverse the distance it reads, and
-- near 10^308 the reading overflowed to NaN.
maxOdometryNoise :: Double
maxOdometryNoise = 1

-- | A time step of 0.01 s, no keys, exact odometry, the notes' 10 m world,
-- no referee (no ball rule, no scores), the step in parallel on several
-- capabilities.
defaultSimConfig :: SimConfig
defaultSimConfig = SimConfig 0.01 [] 0 0 notesBounds (\_ _ -> Nothing) (constant []) True

-- | The state of the world at one instant.
data WorldState = WorldState
  { wsTime     :: !Time          -- ^ simulated time (step number times the time step)
  , wsRobots   :: [RobotState]   -- ^ every robot, in template order
  , wsBalls    :: [Position2]    -- ^ every ball's centre, in template order
  , wsMessages :: [String]       -- ^ the console lines printed at this step
  , wsScores   :: [(String, Int)] -- ^ the referee's scores at this instant ('simScores'), by name; @[]@ when it keeps none
  } deriving (Eq, Show)

-- | Evaluate a snapshot as 'AFrobRobotSim.runSim' does before it writes
-- it: every robot's and ball's record, every message whole, and the
-- scores (a controller's failure at that step, a 'ControllerError', or
-- the scores', a 'RefereeError', is raised here).
forceWorldState :: WorldState -> ()
forceWorldState s = foldl' (flip seq) () (wsRobots s) `seq` foldl' (flip seq) () (wsBalls s)
                    `seq` foldl' (flip seq) () (map length (wsMessages s)) `seq` foldl' (flip seq) () (wsScores s)

-- | The state of one robot at one instant.
data RobotState = RobotState
  { robotType     :: !RobotType
  , robotId       :: !RobotId
  , robotPos      :: {-# UNPACK #-} !Position2  -- ^ true position of its centre
  , robotHeading  :: !Heading        -- ^ true heading
  , robotSpeed    :: !Velocity       -- ^ translational velocity along the heading (m/s): negative when the robot backs
  , robotStuck    :: !Bool
  , robotBattery  :: !BatteryStatus
  , robotCharge   :: !Double         -- ^ battery charge, 1 = full
  , robotOdometry :: {-# UNPACK #-} !Position2  -- ^ what its odometry reads
  } deriving (Eq, Show)

-- | @simulate dt world rcA rcB@: the run of @world@ with controller @rcA@
-- for every SimbotA and @rcB@ for every SimbotB, at the fixed time step
-- @dt@, with the defaults of 'defaultSimConfig' otherwise. An invalid
-- world (see 'validateWorld') is an error listing its problems (the
-- first 20, and how many more).
simulate :: DTime -> WorldTemplate -> SimbotController -> SimbotController -> [WorldState]
simulate dt = simulateWith defaultSimConfig { simDt = dt }

-- The robots of a template as a run starts them: at rest, not stuck, the
-- battery full, in template order.
startRobots :: WorldTemplate -> [Robot]
startRobots world = [ mkRobot k (otRId o) (otPos o) (normalizeHeading (otHdng o)) 0 False 1
                    | o <- world, Just k <- [robotKindOf o] ]

-- | The robots of a template as a run starts them, before their
-- controllers' first sample: where the template places them (the heading
-- normalised), at rest, not stuck, the battery full, odometry reading the
-- true pose; in template order. The robots of a run's state at time 0
-- ('wsRobots'), when the controllers' first sample gives one.
startRobotStates :: WorldTemplate -> [RobotState]
startRobotStates world = [ robotStateOf r (rPos r) | r <- startRobots world ]

-- A robot's snapshot, with what its odometry reads.
robotStateOf :: Robot -> Position2 -> RobotState
robotStateOf r o = RobotState
  { robotType = kindType (rKind r), robotId = rId r, robotPos = rPos r
  , robotHeading = rHeading r, robotSpeed = rSpeed r, robotStuck = rStuck r
  , robotBattery = batteryStatusOf (rCharge r), robotCharge = rCharge r
  , robotOdometry = o }
{-# INLINE robotStateOf #-}

-- A robot's controller, before its first sample or as it continues. One
-- record per robot and step, made where the controller is stepped (in the
-- parallel chunks on several capabilities), with no box around the
-- controller: it is part of what the collector copies for every robot at
-- every step.
data Agent
  = AgentNew { agProps :: !SimbotProperties
             , agStart :: SF SimbotInput SimbotOutput }
  | Agent    { agProps :: !SimbotProperties
             , agFut   :: FutureSF SimbotInput SimbotOutput }

-- What a robot's odometry reads, when it is noisy (exact odometry reads
-- the robot's true pose, and is not kept apart).
data Odometry = Odometry !Position2 {-# UNPACK #-} !Heading

-- The referee's scores, before their first snapshot or as they continue.
data Scores
  = ScoresNew (SF WorldState [(String, Int)])
  | Scores    (FutureSF WorldState [(String, Int)])

data Engine = Engine
  { enStep   :: !Int
  , enRobots :: [Robot]
  , enBalls  :: [Ball]
  , enAgents :: [Agent]
  , enOdo    :: [Odometry]   -- ^ noisy odometry, in template order; [] when exact
  , enKeys   :: [(Time, Char)]
  , enKey    :: !(Maybe Char) -- ^ the key down at the previous step
  , enRng    :: !Word64
  , enScores :: !Scores
  }

-- | 'simulate' with explicit settings.
simulateWith :: SimConfig -> WorldTemplate -> SimbotController -> SimbotController -> [WorldState]
simulateWith cfg world rcA rcB = case validateWorldIn (simBounds cfg) world of
  Left errs -> error ("AFrobRobotSim.simulate: invalid world:\n  " ++ unlinesIndented errs)
  Right ()  -> simulateUnchecked cfg world rcA rcB

-- | 'simulateWith' of a world that its caller has already found valid
-- with @'validateWorldIn' ('simBounds' cfg)@, which is not checked again
-- (the time step and odometry noise are): the runner
-- ("AFrobRobotSim.Run") checks a world once, before its outputs are
-- made, and a check of a world of 100,000 objects takes up to a second
-- or so. A world that is not valid runs as it is, with whatever the
-- physics makes of its overlaps: call 'simulateWith' unless the world
-- was checked. (Not re-exported by "AFrobRobotSim".)
simulateUnchecked :: SimConfig -> WorldTemplate -> SimbotController -> SimbotController -> [WorldState]
simulateUnchecked cfg world rcA rcB
  | not (simDt cfg > 0 && simDt cfg <= maxTimeStep) =
      error ("AFrobRobotSim.simulate: the time step must be positive and at most "
             ++ show maxTimeStep ++ " s, got " ++ show (simDt cfg))
  | not (simOdometryNoise cfg >= 0 && simOdometryNoise cfg <= maxOdometryNoise) =
      error ("AFrobRobotSim.simulate: the odometry noise must be from 0 to "
             ++ show maxOdometryNoise ++ ", got " ++ show (simOdometryNoise cfg))
  -- (the world's bounds are computed now: left a thunk, read only when a
  -- ball rule places balls, they kept the whole template alive for the
  -- run, about 150 bytes a robot at 10,000 robots, copied by every major
  -- collection)
  | otherwise = bounds `seq` run engine0
  where
    dt = simDt cfg
    bounds = worldBoundsOr (simBounds cfg) world
    arena = arenaOf (simBounds cfg) world
    robots0 = startRobots world
    agents0 = [ AgentNew props ((if rKind r == SimbotA then rcA else rcB) props)
              | r <- robots0, let props = SimbotProperties (rKind r) (rId r) ]
    odo0    | noise == 0 = []
            | otherwise  = [ Odometry (rPos r) (rHeading r) | r <- robots0 ]
    balls0  = [ Ball (otPos o) zeroVector | o@OTBall {} <- world ]
    engine0 = Engine 0 robots0 balls0 agents0 odo0 (sortOn fst (simKeys cfg)) Nothing (fromIntegral (simSeed cfg))
                     (ScoresNew (simScores cfg))

    -- (on several capabilities, the workers are given the step's chunks
    -- before the snapshot is: they compute while the snapshot's reader,
    -- a log writer say, reads it)
    run en = started `seq` (snapshot : run en')
      where
        n      = enStep en
        t      = fromIntegral n * dt
        ctx    = SenseContext arena (enRobots en) (enBalls en)
        (key, keys') = keyAtStep dt n (enKey en) (enKeys en)
        -- noisy odometry, by robot number (only made when noisy, before
        -- the parallel work, as the sensors' indexes are)
        odoArr = listArray (0, length (enOdo en) - 1) (enOdo en) :: Array Int Odometry
        odoReady = if noise == 0 then () else odoArr `seq` ()
        odometry i r
          | noise == 0 = (rPos r, rHeading r)
          | otherwise  = case odoArr ! i of Odometry p h -> (p, h)
        -- Every controller's step, in template order, chunk by chunk as
        -- the moves need them (a failing controller fails the step: its
        -- messages and the next state, never the robots' positions now):
        -- its output and continued controller, with each robot and the
        -- plan of its move.
        (started, outputs, agents', plans) = stepEvery (simParallel cfg) (senseReady ctx `seq` odoReady) (enAgents en) (enRobots en)
          (\i a r -> case senseRobotApart ctx i (odometry i r) key of
                       (input, apart) -> (stepAgent t a input, apart))
          (\apart r o -> planMoveApart dt arena apart r (soDrive o))
        unscored = WorldState
          { wsTime     = t
          , wsRobots   = robotStates (enRobots en) (enOdo en)
          , wsBalls    = map bPos (enBalls en)
          , wsMessages = [ printf "[%.2f] %s.%d: %s" t (rpType (agProps a)) (rpId (agProps a)) m
                         | (a, o) <- zip (enAgents en) outputs, m <- soMessages o ]
          , wsScores   = []
          }
        -- (the scores of this snapshot, evaluated whole with the next
        -- step's state)
        (scores, scores') = stepScores t (enScores en) unscored
        snapshot = unscored { wsScores = scores }
        robots' = stepRobotsPlanned (scRobotIndex ctx) plans
        moved   = stepBalls dt arena robots' (enBalls en)
        balls'  = blaming (RefereeError "the ball rule (simBallRule)" (t + dt)) $
          case simBallRule cfg (t + dt) (map bPos moved) of
            Nothing -> moved
            Just ps -> let placed = [ Ball q zeroVector | q <- refereed bounds (length moved) ps ]
                       in forceList placed `seq` placed
        (odo', rng') = nextOdometry (enRng en) (enRobots en) robots' (enOdo en)
        -- keys' is forced too: left lazy, it would hold the previous
        -- engine (and so the whole run) when no controller reads its input
        en' = forceList robots' `seq` forceList balls' `seq` forceList agents' `seq`
              forceList odo' `seq` keys' `seq` scores' `seq`
              en { enStep = n + 1, enRobots = robots', enBalls = balls', enAgents = agents'
                 , enOdo = odo', enKeys = keys', enKey = key, enRng = rng', enScores = scores' }

    -- (the input is made with the bound on the robot's distance to the
    -- others that its move's plan takes, from one gathering of the robots
    -- near it; the rays and the tracker's lists are computed when read)
    stepAgent t a input = blaming (blame (agProps a) t) (stepController a input)
    stepController a input =
      case (case a of
              AgentNew { agStart = sf } -> evalAtZero sf input
              Agent { agFut = fut }     -> evalAt fut dt input) of
        (o, fut) -> fut `seq` finiteDrive (soDrive o) `seq` case soMessages o of
          []   -> (o, Agent (agProps a) fut)   -- (most steps: the output as it is)
          msgs -> let kept = map capMessage msgs
                  in forceList kept `seq` (o { soMessages = kept }, Agent (agProps a) fut)

    blame props t = ControllerError (rpType props) (rpId props) t

    -- The referee's scores of a snapshot, evaluated whole (names distinct,
    -- at most 'maxTextChars' characters long; values within 2^53), and how
    -- they continue.
    stepScores t sc ws = blaming (RefereeError "the scores (simScores)" t) $
      case (case sc of
              ScoresNew sf -> evalAtZero sf ws
              Scores fut   -> evalAt fut dt ws) of
        (out, fut) -> fut `seq` checkScores out `seq` (out, Scores fut)
    checkScores = go Set.empty
      where
        go _ [] = ()
        go seen ((k, v) : more)
          | not (null (drop maxTextChars k)) =
              bad ("it gave a score whose name is longer than " ++ show maxTextChars ++ " characters ("
                   ++ show (take 40 k) ++ "...)")
          | foldr seq () k `seq` Set.member k seen = bad ("it gave the score " ++ show k ++ " twice (a name holds one score)")
          | abs (toInteger v) > maxScore =
              bad ("it gave the score " ++ show k ++ " the value " ++ show v ++ ", beyond 2^53 (" ++ show maxScore
                   ++ "): the log and the result line write numbers as JSON's doubles, exact only within it")
          | otherwise = go (Set.insert k seen) more
        bad = throw . ErrorCall
        maxScore = 2 ^ (53 :: Int) :: Integer

    -- every robot's state, all at once when the list is first needed
    -- (with the noisy odometry's readings, or none when it is exact)
    robotStates (r : rs) os = case os of
      Odometry p _ : more -> states p more
      []                  -> states (rPos r) []
      where states o more = let !rest = robotStates rs more
                                !st   = robotStateOf r o
                            in st : rest
    robotStates [] _ = []

    noise = simOdometryNoise cfg
    -- Noisy odometry after the move: it integrates the true motion with a
    -- random relative error on each step's distance and turn. (Exact
    -- odometry is the true pose, read from the robots: no list, and no
    -- pass over them here.)
    nextOdometry rng olds news odos
      | noise == 0 = ([], rng)
      | otherwise  = go rng olds news odos []
      where
        go g (r0 : rs0) (r1 : rs1) (Odometry p h : os) acc =
          let (u1, g1) = uniform g
              (u2, g2) = uniform g1
              dTrue    = rPos r1 .-. rPos r0
              turn     = normalizeAngle (rHeading r1 - rHeading r0)
              h'       = normalizeHeading (h + turn * (1 + noise * u2))
              d'       = vector2Rotate (h - rHeading r0) ((1 + noise * u1) *^ dTrue)
          in go g2 rs0 rs1 os (Odometry (p .+^ d') h' : acc)
        go g _ _ _ acc = (reverse acc, g)

forceList :: [a] -> ()
forceList = foldr seq ()

unlinesIndented :: [String] -> String
unlinesIndented = foldr1 (\a b -> a ++ "\n  " ++ b)

-- SplitMix64: a uniform Double in [-1, 1) and the next state.
uniform :: Word64 -> (Double, Word64)
uniform s =
  let s' = s + 0x9E3779B97F4A7C15
      z1 = (s' `xor` (s' `shiftR` 30)) * 0xBF58476D1CE4E5B9
      z2 = (z1 `xor` (z1 `shiftR` 27)) * 0x94D049BB133111EB
      z3 = z2 `xor` (z2 `shiftR` 31)
  in (fromIntegral (z3 `shiftR` 11) / 4503599627370496 - 1, s')

-- | @keyDue dt tk n@: whether a scripted key press at time @tk@ is due at
-- step @n@ of a run of step @dt@ (the step's time @n * dt@, with a
-- millionth of a step's slack for times written in decimals). The
-- simulator presses the earliest key left at each step where it is due,
-- one key a step ('keyAtStep').
keyDue :: Time -> Time -> Int -> Bool
keyDue dt tk n = tk <= fromIntegral n * dt + dt * 1e-6
{-# INLINE keyDue #-}

-- | @keyAtStep dt n previous presses@: the key down at step @n@ of a run
-- of step @dt@, given the key down at the step before and the scripted
-- presses not yet made (in time order), and the presses left after it.
-- The earliest press left is made at this step if it is due ('keyDue'),
-- one key a step; but a press of the key that was down at the step before
-- waits one step, with no key down, so that the controller sees the key
-- released and pressed again ('AFrob.RobotIO.tciKeyDown' fires once a
-- press, not once for two presses run together).
--
-- > keyAtStep 0.1 0 Nothing [(0, 'a'), (0, 'a')]   == (Just 'a', [(0, 'a')])
-- > keyAtStep 0.1 1 (Just 'a') [(0, 'a')]          == (Nothing, [(0, 'a')])
-- > keyAtStep 0.1 2 Nothing [(0, 'a')]             == (Just 'a', [])
keyAtStep :: Time -> Int -> Maybe Char -> [(Time, Char)] -> (Maybe Char, [(Time, Char)])
keyAtStep dt n previous presses = case presses of
  (tk, c) : rest | keyDue dt tk n, previous /= Just c -> (Just c, rest)
  _                                                   -> (Nothing, presses)
{-# INLINE keyAtStep #-}

-- | The scripted key presses ('simKeys') that a run of @n@ steps of @dt@
-- (after its time-0 sample) never makes, in time order, by the
-- simulator's own rule ('keyAtStep', one key a step, a repeated key
-- released for a step between): a press after the last step, or one left
-- waiting behind others due at the same steps.
keysNeverPressed :: Time -> Int -> [(Time, Char)] -> [(Time, Char)]
keysNeverPressed dt n = go 0 Nothing . sortOn fst
  where
    go _ _ [] = []
    go k previous ks@((tk, _) : _)
      | k > n          = ks
      | keyDue dt tk k = case keyAtStep dt k previous ks of
          (pressed, rest) -> go (k + 1) pressed rest
      -- (on to the step it falls due, near enough; 'keyDue' decides; no
      -- key is down at the steps skipped)
      | otherwise      = go (max (k + 1) (min (n + 1) (floor ((tk - dt * 1e-6) / dt)))) Nothing ks
