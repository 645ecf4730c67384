-- |
-- Module      : AFrobRobotSim.Options.Settings
-- Description : The settings of a simulation run, their defaults, and what
--               they come to: the steps a run takes and the scale it
--               draws at.
--
-- 'SimOptions' is what a run is told, by its command line
-- ("AFrobRobotSim.Options.CommandLine") or in code; 'runSteps' and
-- 'scaleFor' are the two numbers a run derives from it. The flags, their
-- defaults and the scale are described in "AFrobRobotSim.Options", which
-- re-exports this module but for 'stepsBeforeFloor'; the checks of the
-- settings are in "AFrobRobotSim.Options.Check".
module AFrobRobotSim.Options.Settings
  ( -- * The settings
    SimOptions (..)
  , defaultSimOptions
    -- * What they come to
  , runSteps
  , stepsBeforeFloor
  , scaleFor
  , fitScale
  , fitPixels
  ) where

import           System.FilePath ((</>))

import           AFrobRobotSim.World (Bounds (..))

-- | The settings of a run.
data SimOptions = SimOptions
  { optSeconds       :: !Double            -- ^ simulated seconds to run
  , optDt            :: !Double            -- ^ the fixed time step (s)
  , optFps           :: !Double            -- ^ frames per simulated second
  , optOut           :: FilePath           -- ^ the output folder (the frames go there)
  , optFrames        :: !Bool              -- ^ write frames at all
  , optScale         :: !(Maybe Double)    -- ^ pixels per metre; 'Nothing' fits the world ('scaleFor')
  , optKeys          :: [(Double, Char)]   -- ^ scripted key presses
  , optSeed          :: !Int               -- ^ seed of the odometry noise
  , optOdometryNoise :: !Double            -- ^ relative odometry error per step
  , optQuiet         :: !Bool              -- ^ print only the summary
  , optWorldFile     :: Maybe FilePath     -- ^ load the world from this file
  , optDumpWorld     :: !Bool              -- ^ print the world and exit (not with 'optPrintProgram')
  , optPrintProgram  :: !Bool
    -- ^ print the program's name as its result line writes it (its
    -- @program@, a JSON string: 'optProgram' or the executable's name)
    -- and exit, reading no world and writing nothing (@--print-program@:
    -- how @scripts/sweep@ learns the name of the program it runs, for the
    -- lines of runs that write no result); set with 'optDumpWorld' too,
    -- the run is refused (exit code 2) before either prints
    -- ('AFrobRobotSim.Options.Check.printingModesFault')
  , optRays          :: !Bool              -- ^ draw range-finder rays
  , optTrails        :: !Bool              -- ^ draw trails
  , optSvg           :: Maybe FilePath     -- ^ write an SVG of the whole run
  , optVideo         :: Maybe FilePath     -- ^ assemble an mp4 with ffmpeg
  , optLog           :: Maybe FilePath     -- ^ write the JSON-lines run log
  , optReplay        :: Maybe FilePath     -- ^ write the HTML replay page
  , optResult        :: Maybe FilePath     -- ^ write the result line (settings and outcome)
  , optProgram       :: Maybe String
    -- ^ the program's name as the result line writes it (its @program@):
    -- 'Nothing' (the default) for the executable's name
    -- ('System.Environment.getProgName'). No flag sets it: a program that
    -- runs several things under one name sets it in code, as
    -- @afrp-examples@ does for each example (@"afrp-examples rcReverse"@),
    -- so that their result lines are told apart.
  , optParams        :: [(String, String)] -- ^ the @--param@s, in order, one per name
  , optParamsRepeated :: [(String, [String])]
    -- ^ each @--param@ name the command line gives more than once, in the
    -- order first given, with all its values in the order given (the last
    -- is its value in 'optParams'); 'AFrobRobotSim.runSimWith' warns of
    -- each. Set by 'AFrobRobotSim.Options.parseSimArgs'; @[]@ by default.
  , optFlagsRepeated :: [(String, [String])]
    -- ^ each other flag that takes one value (@--seconds@, @--world@,
    -- @--svg@, ...; not @--keys@, whose presses all count) that the
    -- command line gives more than once, in the order first given, with
    -- all its values as given (the last is the one used);
    -- 'AFrobRobotSim.runSimWith' warns of each: @--seconds 2 --seconds 3@
    -- is usually a mistake (a sweep's job line and the flags every run
    -- gets both giving it). Set by 'AFrobRobotSim.Options.parseSimArgs';
    -- @[]@ by default.
  } deriving (Eq, Show)

-- | The defaults listed in "AFrobRobotSim.Options": no frames, the SVG
-- and the replay page in @simbot-out/@ (a 30 s run writes about 2 MB).
defaultSimOptions :: SimOptions
defaultSimOptions = SimOptions
  { optSeconds = 30, optDt = 0.01, optFps = 25, optOut = defaultOut, optFrames = False
  , optScale = Nothing, optKeys = [], optSeed = 0, optOdometryNoise = 0, optQuiet = False
  , optWorldFile = Nothing, optDumpWorld = False, optPrintProgram = False, optRays = False, optTrails = False
  , optSvg = Just (defaultOut </> "run.svg"), optVideo = Nothing, optLog = Nothing
  , optReplay = Just (defaultOut </> "replay.html"), optResult = Nothing, optProgram = Nothing
  , optParams = [], optParamsRepeated = [], optFlagsRepeated = [] }

defaultOut :: FilePath
defaultOut = "simbot-out"

-- | The steps a run of these options takes after its time-0 sample: the
-- whole number nearest @seconds / dt@, a half rounded up (0 at least),
-- with a millionth of a step's slack, as for the key presses
-- ('AFrobRobotSim.Simulator.keyDue'), so that a half written in decimals
-- counts as one whatever its rounding (0.15 / 0.1 is a little under 1.5):
-- @--seconds 0.25 --dt 0.1@ is 3 steps, @--seconds 0.15 --dt 0.1@ 2,
-- @--seconds 0.005@ at the default step 1 (a tie went to the even number
-- before: 2, 1 and 0, the last refused).
runSteps :: SimOptions -> Int
runSteps o = max 0 (floor (stepsBeforeFloor (optSeconds o) (optDt o)))

-- | @seconds / dt@ with a half and the slack added: 'runSteps' is its whole
-- part (the checks before a run compare it, not the rounded count, so
-- that an infinite or huge quotient is not taken whole).
stepsBeforeFloor :: Double -> Double -> Double
stepsBeforeFloor secs dt = secs / dt + 0.5 + 1e-6

-- | The pixels the long side of a world spans at the default scale
-- ('fitScale'): 600.
fitPixels :: Double
fitPixels = 600

-- | The scale, in pixels per metre, at which the long side of a world of
-- this extent spans 'fitPixels': 60 for the notes' 10 m world, 6 for a
-- 100 m one. A frame is then at most 620 pixels on each side (with its
-- margin), whatever the world's size and shape.
fitScale :: Bounds -> Double
fitScale (Bounds x0 y0 x1 y1) = fitPixels / max (x1 - x0) (y1 - y0)

-- | The scale a run draws at, in a world of this extent: @--scale@ if
-- given, else 'fitScale'.
scaleFor :: Bounds -> SimOptions -> Double
scaleFor b o = maybe (fitScale b) id (optScale o)
