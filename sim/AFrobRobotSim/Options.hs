-- |
-- Module      : AFrobRobotSim.Options
-- Description : The settings of a simulation run and the command line that
--               sets them.
--
-- Every program built on 'AFrobRobotSim.runSim' accepts these flags:
--
-- @
-- --seconds T        simulated time to run                 (default 30)
-- --dt D             fixed time step, seconds, at most 1e6 (default 0.01)
-- --fps F            frames per simulated second           (default 25)
-- --out DIR          output folder (frames, default SVG and page) (default simbot-out)
-- --frames           also write PPM frames into the output folder
-- --no-frames        write no frames (the default)
-- --scale PX         pixels per metre  (default: the world's long side 600 px, 'fitScale')
-- --keys "1.5:a,3:b" scripted key presses (time:key, ...; 2:space and 4:comma name those keys;
--                    repeatable)
-- --seed N           seed of the odometry noise, |N| <= 2^53 (default 0)
-- --odometry-noise X relative odometry error per step, 0-1 (default 0 = exact)
-- --quiet            print only the summary line
-- --world FILE       load the world from FILE instead of the program's
-- --dump-world       print the world in the world-file format and exit
-- --print-program    print the program's name as its result line writes it (JSON) and exit
-- --rays             draw the four range-finder rays
-- --trails           draw each robot's path so far
-- --svg FILE         write one SVG picture of the whole run  (default simbot-out/run.svg)
-- --no-svg           write no SVG
-- --replay FILE      write the HTML replay page              (default simbot-out/replay.html)
-- --no-replay        write no replay page
-- --log FILE.jsonl   write the JSON-lines run log (docs/LOG.md)
-- --video FILE.mp4   assemble the frames into a video (needs ffmpeg and --frames;
--                    also .m4v .mkv .webm .mov .avi .gif)
-- --result FILE      write the run's settings and outcome as one JSON line
-- --param NAME=VALUE a parameter for the controllers (repeatable; see
--                    'AFrobRobotSim.Params.getSimParams')
-- --help             print this usage and exit
-- @
--
-- A flag that takes a value, given twice on one command line, takes its
-- last value and is warned of when the run starts (not with
-- @--dump-world@ or @--print-program@, which run nothing) ('optFlagsRepeated',
-- 'optParamsRepeated'), but for @--keys@, whose presses all count.
--
-- 'validateOptions' checks the numbers together before anything is
-- simulated: the step count @seconds / dt@ is finite and at most
-- 'maxSteps' (a run takes the whole number of steps nearest to it, a half
-- rounded up, with a millionth of a step's slack for times written in
-- decimals, so @--seconds@ greater than 0 must be at least half of
-- @--dt@), the frame period @1 / fps@ is a whole number of steps;
-- 'validateOptionsIn', once the world is known, also that the frame is at
-- most 'maxFrameSide' pixels wide and tall. A @--video@'s name must end
-- in one of 'videoExtensions'. Options set in code are held to what the
-- flags hold them to, and 'optParams' to one value a name (a command line
-- keeps a repeated @--param@'s last value, and warns); a fault only they
-- can have is named by the record's field (@optSeconds must be a finite
-- number >= 0, got -1.0@), one a command line can have too by its flags.
--
-- = Scale
--
-- Frames, the SVG and the replay page show the whole world. Without
-- @--scale@ the scale fits the world ('fitScale'): its long side is
-- 'fitPixels' (600) pixels, so the notes' 10 m world is drawn at 60
-- pixels per metre (a 620 by 620 frame with the margin), a 100 m world
-- at 6, a 30 by 10 m world at 20 (a 620 by 220 frame).
--
-- = Modules
--
-- This module gathers the options', and has no code of its own:
-- "AFrobRobotSim.Options.Settings" (the settings, their defaults, the
-- steps and the scale they come to), "AFrobRobotSim.Options.Check" (the
-- checks and the limits) and "AFrobRobotSim.Options.CommandLine" (the
-- flags parsed, and the usage text).
module AFrobRobotSim.Options
  ( -- * Settings
    SimOptions (..)
  , defaultSimOptions
    -- * The command line
  , Command (..)
  , parseSimArgs
  , parseSimFlags
  , parseKeys
  , parseParam
  , isHelpFlag
  , argText
  , usage
    -- * Checks
  , validateOptions
  , validateOptionsIn
  , videoExtensions
  , maxSteps
  , maxFrameSide
  , minWorldPixels
    -- * Steps and scale
  , runSteps
  , scaleFor
  , fitScale
  , fitPixels
  ) where

import           AFrobRobotSim.Options.Check       (maxFrameSide, maxSteps, minWorldPixels, validateOptions,
                                                    validateOptionsIn, videoExtensions)
import           AFrobRobotSim.Options.CommandLine
import           AFrobRobotSim.Options.Settings    (SimOptions (..), defaultSimOptions, fitPixels, fitScale,
                                                    runSteps, scaleFor)
