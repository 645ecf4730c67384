-- |
-- Module      : AFrobRobotSim
-- Description : The simbot simulator: worlds, simbots, and the engine.
--
-- A program in the notes' style is
--
-- > import AFrob
-- > import AFrobRobotSim
-- >
-- > world :: WorldTemplate
-- > world = [OTSimbotA 1 (Point2 (-2) 0) 0, OTVWall (Point2 2 0)]
-- >
-- > rcA, rcB :: SimbotController
-- > rcA rps = constant (mrFinalize (ddVelDiff 0.5 0.5))
-- > rcB = rcA
--
-- > main :: IO ()
-- > main = runSim (Just world) rcA rcB
--
-- 'runSim' runs it headless from the command line (frames, console
-- messages, a summary; see "AFrobRobotSim.Options" for the flags), and
-- 'simulate' runs it purely: @simulate 0.01 world rcA rcB@ is the list of
-- world snapshots, one every 0.01 s from time 0.
module AFrobRobotSim
  ( -- * Running a program
    runSim
  , runSimWith
  , SimOptions (..)
  , defaultSimOptions
  , Command (..)
  , parseSimArgs
  , parseSimFlags
  , parseKeys
  , isHelpFlag
  , validateOptions
  , validateOptionsIn
  , scaleFor
  , fitScale
  , fitPixels
  , maxSteps
  , maxFrameSide
  , usage
  , parseParam
    -- ** Parameters and the result line of a sweep
  , getSimParams
  , simParamsOf
  , lookupSimParam
  , argText
  , paramOr
  , paramOrFrom
  , readSimParam
  , defaultWorld
    -- ** A referee: the balls' rule, scores and goals
  , runSimRefereed
  , runSimRefereedWith
  , Referee (..)
  , noReferee
  , LogRect (..)
    -- * Controllers and their input and output
  , SimbotController
  , SimbotProperties (..)
  , SimbotInput (..)
  , SimbotOutput (..)
  , DriveCommand (..)
    -- * Worlds
  , WorldTemplate
  , ObjectTemplate (..)
  , worldSize
  , isWorldSize
  , worldBounds
  , worldBoundsOr
  , sizeBounds
  , minWorldSide
  , maxWorldSide
  , worldXMin
  , worldYMin
  , worldXMax
  , worldYMax
  , Bounds (..)
  , notesBounds
  , validateWorld
  , validateWorldIn
  , maxRobotId
    -- * Dimensions and robot types
  , wallLength
  , wallThickness
  , blockSide
  , ballDiameter
  , simbotDiameter
  , RobotKind (..)
  , kindType
  , kindWheelBase
  , kindWSMax
  , kindAccMax
    -- * Sensors
  , rangeFinderMax
  , trackerRange
    -- * Physics parameters
  , ballFriction
  , ballRestitution
    -- * The engine
  , simulate
  , simulateWith
  , SimConfig (..)
  , defaultSimConfig
  , maxTimeStep
  , maxOdometryNoise
  , WorldState (..)
  , RobotState (..)
  , startRobotStates
  , ControllerError (..)
  , RefereeError (..)
  , isRunFailure
    -- * World files
  , parseWorld
  , renderWorld
  , readWorldBytes
  , readWorldFile
    -- * Pictures
  , Scene (..)
  , RenderStyle (..)
  , defaultRenderStyle
  , frameSize
  , renderPPM
  , renderSVG
  ) where

import           AFrobRobotSim.DefaultWorld
import           AFrobRobotSim.Options
import           AFrobRobotSim.Params      (getSimParams, lookupSimParam, paramOr, paramOrFrom,
                                            readSimParam, simParamsOf)
import           AFrobRobotSim.Balls     (ballFriction, ballRestitution)
import           AFrobRobotSim.Render    (RenderStyle (..), Scene (..), defaultRenderStyle, frameSize,
                                          renderPPM, renderSVG)
import           AFrobRobotSim.Log.Records (LogRect (..))
import           AFrobRobotSim.Referee   (Referee (..), noReferee)
import           AFrobRobotSim.Run
import           AFrobRobotSim.Robot
import           AFrobRobotSim.Sensors   (rangeFinderMax, trackerRange)
import           AFrobRobotSim.Simulator
import           AFrobRobotSim.World
import           AFrobRobotSim.World.Check
import           AFrobRobotSim.WorldFile
