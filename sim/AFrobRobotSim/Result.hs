{-# LANGUAGE BangPatterns        #-}
-- |
-- Module      : AFrobRobotSim.Result
-- Description : A run's result line (@--result FILE@).
--
-- A sweep runs one program over many seeds, worlds and parameters and
-- compares the outcomes. Each run says what it was and how it ended in
-- one JSON line, written by @--result FILE@ when the run ends, however it
-- ends (a controller or a referee that throws still gets its line, with
-- the failure):
--
-- @
-- {"program":"my-robot","world":"program","seed":3,"dt":0.01,"seconds":30,
--  "odometryNoise":0,"params":{"speed":"0.5"},
--  "outcome":{"simulated":30,"steps":3001,"interrupted":false,"failure":null,
--             "robots":[{"type":"SimbotA","id":1,"x":..,"y":..,"heading":..,
--                        "distance":..,"bumps":2,"stuckTime":1.25,"battery":0.98}],
--             "scores":{}}}
-- @
--
-- (on one line: a run of @my-robot --seed 3 --param speed=0.5 --result
-- FILE@, whose @main@ calls @runSim (Just world)@). @program@ is the
-- executable's name, or the name the options give
-- ('AFrobRobotSim.Options.optProgram': each of @afrp-examples@'s
-- examples writes @"afrp-examples rcReverse"@ and the like). @world@ says where
-- the run's world came from
-- ('WorldSource'): the @--world@ file's name (@"./default"@ for a file
-- named @default@, and so for @program@), else @"program"@ for the
-- world the program gives ('AFrobRobotSim.runSim' @(Just world)@, as
-- @afrp-examples@ and most programs do), else @"default"@ for the
-- built-in default world ('AFrobRobotSim.runSim' 'Nothing', as @simbot@
-- does). @odometryNoise@ is @--odometry-noise@ (so that
-- runs of a sweep over it are told apart). Per robot: the final true pose, the distance its
-- centre travelled (the sum of the steps' displacements), @bumps@ the
-- number of times it became stuck against something (a robot stuck at
-- time 0 counts one), @stuckTime@ the simulated seconds it spent stuck,
-- @battery@ its charge left (1 = full). A run whose controller fails at
-- its first sample, which simulates no state, lists the robots as the
-- world places them (nothing travelled, the battery full). No wall-clock
-- time is written, so
-- two runs with the same flags write the same line.
--
-- The parameters a run got (@--param NAME=VALUE@, which its controllers
-- read: "AFrobRobotSim.Params") are in its line as they were given.
module AFrobRobotSim.Result
  ( WorldSource (..)
  , worldSource
  , worldSourceName
  , RobotTally (..)
  , startTallies
  , stepTallies
  , resultJSON
  , programJSON
  ) where

import           Data.List            (foldl')
import           Data.Maybe           (fromMaybe)

import           AFRP.Geometry        (norm, point2X, point2Y, (.-.))
import           AFrobRobotSim.JSON
import           AFrobRobotSim.Log.Records (LogSummary (..))
import           AFrobRobotSim.Options
import           AFrobRobotSim.Simulator

-- | Where a run's world came from, as its result line names it
-- ('worldSourceName').
data WorldSource
  = BuiltInWorld        -- ^ the built-in default world ("AFrobRobotSim.DefaultWorld"): @runSim Nothing@
  | ProgramWorld        -- ^ the world the program gives: @runSim (Just world)@
  | WorldFile FilePath  -- ^ a world file, @--world FILE@ (whichever world the program gives)
  deriving (Eq, Show)

-- | Where the world of a run with these options, given this world by the
-- program (or 'Nothing', the default), comes from: @--world@ wins.
worldSource :: SimOptions -> Maybe world -> WorldSource
worldSource o mworld = case (optWorldFile o, mworld) of
  (Just file, _) -> WorldFile file
  (_, Just _)    -> ProgramWorld
  _              -> BuiltInWorld

-- | The result line's @world@: @"default"@, @"program"@, or the world
-- file's name (as text: 'AFrobRobotSim.Options.argText'), with @./@
-- before a file named @default@ or @program@ (@--world default@ is
-- @"./default"@), which would otherwise read as the built-in world or the
-- program's own (as @scripts/sweep@ writes it too, for a run with no
-- result).
worldSourceName :: WorldSource -> String
worldSourceName w = case w of
  BuiltInWorld   -> "default"
  ProgramWorld   -> "program"
  WorldFile file
    | name `elem` ["default", "program"] -> "./" ++ name
    | otherwise                          -> name
    where name = argText file

-- | What the result line keeps of one robot while the run goes: strict,
-- so its memory is constant however long the run.
data RobotTally = RobotTally
  { tallyLast     :: !RobotState  -- ^ the robot's latest state
  , tallyDistance :: !Double      -- ^ metres its centre travelled so far
  , tallyBumps    :: !Int         -- ^ times it became stuck
  , tallyStuck    :: !Double      -- ^ simulated seconds spent stuck
  }

-- | The tallies of the robots at time 0 (the state's, or 'startRobotStates'
-- before there is one): nothing travelled, a bump for a robot stuck
-- already.
startTallies :: [RobotState] -> [RobotTally]
startTallies rs = [ RobotTally r 0 (if robotStuck r then 1 else 0) 0 | r <- rs ]

-- | Take the next step's state (@dt@ after the previous one): add the
-- displacement, a bump when a robot becomes stuck, @dt@ of stuck time for
-- a robot stuck at this step.
stepTallies :: Double -> WorldState -> [RobotTally] -> [RobotTally]
stepTallies dt s ts = forceAll (zipWith one ts (wsRobots s))
  where
    one (RobotTally old d b st) r =
      RobotTally r (d + norm (robotPos r .-. robotPos old))
                 (if robotStuck r && not (robotStuck old) then b + 1 else b)
                 (if robotStuck r then st + dt else st)
    forceAll xs = foldl' (\acc x -> x `seq` acc) () xs `seq` xs

-- | The program's name as a result line writes it, its @program@ (a JSON
-- string): the options' name for it ('AFrobRobotSim.Options.optProgram')
-- or else the name given (the executable's). @--print-program@ prints it
-- ('AFrobRobotSim.Options.optPrintProgram').
programJSON :: String -> SimOptions -> JSON
programJSON prog o = JString (argText (fromMaybe prog (optProgram o)))

-- | The result line of a run: its settings (the program's name, its
-- options and where its world came from) and its outcome (the summary
-- and the robots' tallies at the last state simulated). See the module
-- documentation for the fields. The name given (the executable's) is
-- written as @program@ unless the options name the program
-- ('AFrobRobotSim.Options.optProgram').
resultJSON :: String -> SimOptions -> WorldSource -> LogSummary -> [RobotTally] -> JSON
resultJSON prog o source summary tallies = JObject
  [ ("program", programJSON prog o)
  , ("world", JString (worldSourceName source))
  , ("seed", JNumber (fromIntegral (optSeed o)))
  , ("dt", JNumber (optDt o))
  , ("seconds", JNumber (optSeconds o))
  , ("odometryNoise", JNumber (optOdometryNoise o))
  , ("params", JObject [ (k, JString (argText v)) | (k, v) <- optParams o ])
  , ("outcome", JObject
      [ ("simulated", JNumber (lsSimulated summary))
      , ("steps", JNumber (fromIntegral (lsSteps summary)))
      , ("interrupted", JBool (lsInterrupted summary))
      , ("failure", maybe JNull JString (lsFailure summary))
      , ("robots", JArray (map robot tallies))
      , ("scores", JObject [ (k, JNumber (fromIntegral v)) | (k, v) <- lsScores summary ]) ]) ]
  where
    robot (RobotTally r d b st) = JObject
      [ ("type", JString (robotType r)), ("id", JNumber (fromIntegral (robotId r)))
      , ("x", JNumber (point2X (robotPos r))), ("y", JNumber (point2Y (robotPos r)))
      , ("heading", JNumber (robotHeading r)), ("distance", JNumber d)
      , ("bumps", JNumber (fromIntegral b)), ("stuckTime", JNumber st)
      , ("battery", JNumber (robotCharge r)) ]
