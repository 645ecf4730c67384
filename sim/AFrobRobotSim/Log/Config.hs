-- |
-- Module      : AFrobRobotSim.Log.Config
-- Description : What a run log needs besides the states, and the header
--               line made from it.
--
-- A log is made from the simulation's states and a 'LogConfig': the world
-- at time 0, the time step and frame rate, the seed, the command line and
-- the program's goals and scores. The header line ('logHeader') is made
-- from it alone, before the first step. Part of "AFrobRobotSim.Log", which
-- re-exports 'LogConfig', 'defaultLogConfig' and 'logHeader'.
module AFrobRobotSim.Log.Config
  ( LogConfig (..)
  , defaultLogConfig
  , logHeader
  , rangeAngles
  ) where

import           AFRP.Geometry
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.Sensors
import           AFrobRobotSim.Simulator
import           AFrobRobotSim.World

-- | What a log needs besides the states: the world and how it was run.
data LogConfig = LogConfig
  { lcBounds      :: Bounds                    -- ^ the world's extent, unless 'lcWorld' has an 'OTSize' (which wins)
  , lcWorld       :: WorldTemplate             -- ^ the world at time 0
  , lcDt          :: Double                    -- ^ the simulation's time step (s)
  , lcFps         :: Double                    -- ^ frames per simulated second
  , lcSeed        :: Int                       -- ^ the odometry noise's seed
  , lcCommandLine :: [String]                  -- ^ the program's name and arguments
  , lcGoals       :: [LogRect]                 -- ^ goal areas to draw, if any
  , lcScores      :: WorldState -> [(String, Int)]
    -- ^ the program's scores in a state; a rise between two steps is a
    -- @"score"@ event. By default the referee's ('wsScores', which
    -- 'AFrobRobotSim.Simulator.simScores' keeps)
  }

-- | The notes' world bounds, an empty world, dt 0.01 s, 25 fps, seed 0,
-- no command line, no goals, the states' own scores ('wsScores').
defaultLogConfig :: LogConfig
defaultLogConfig = LogConfig notesBounds [] 0.01 25 0 [] [] wsScores

-- | The header line of a run.
logHeader :: LogConfig -> LogHeader
logHeader cfg = LogHeader
  { lhFormat = logFormatName, lhVersion = logFormatVersion
  , lhBounds = let Bounds x0 y0 x1 y1 = worldBoundsOr (lcBounds cfg) (lcWorld cfg)
               in LogRect ((x0 + x1) / 2) ((y0 + y1) / 2) (x1 - x0) (y1 - y0)
  , lhWalls  = [ box o | o <- world, isWall o ]
  , lhBlocks = [ box o | o@OTBlock {} <- world ]
  , lhBalls  = [ (x, y) | o@OTBall {} <- world, let Point2 x y = otPos o ]
  , lhBallRadius = ballDiameter / 2
  , lhGoals  = lcGoals cfg
  , lhRobots = [ LogRobotInfo (kindType k) (otRId o) (simbotDiameter / 2) (kindWheelBase k)
                              (kindWSMax k) sensorNames
               | o <- world, Just k <- [robotKindOf o] ]
  , lhRangeAngles = rangeAngles, lhRangeMax = rangeFinderMax, lhTrackerRange = trackerRange
  , lhDt = lcDt cfg, lhFps = lcFps cfg, lhSeed = lcSeed cfg, lhCommandLine = lcCommandLine cfg }
  where
    world = lcWorld cfg
    isWall o = case o of { OTVWall {} -> True; OTHWall {} -> True; _ -> False }
    box o = let Point2 x y = otPos o
                (hw, hh)   = objectHalfSize o
            in LogRect x y (2 * hw) (2 * hh)
    sensorNames = ["odometry", "bumper", "battery", "rangeFinder", "tracker", "console"]

-- | The angles of the logged range readings: front, left, back, right
-- (0, pi/2, pi, -pi/2), those of 'AFrob.rfFront' and its siblings. The
-- header lists them ('lhRangeAngles'); each robot of a frame has its
-- readings at them, in this order ('lrRange').
rangeAngles :: [Double]
rangeAngles = [0, pi / 2, pi, -pi / 2]
