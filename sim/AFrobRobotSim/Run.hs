{-# LANGUAGE MultiWayIf          #-}
{-# LANGUAGE BangPatterns        #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Run
-- Description : 'runSim': the headless runner behind every simbot program.
--
-- @runSim (Just world) rcA rcB@ reads its settings from the command line
-- (see "AFrobRobotSim.Options" for the flags), simulates, prints the
-- robots' console messages as they happen, writes the SVG, the replay
-- page, the run log, PPM frames and the result line
-- ("AFrobRobotSim.Result") as asked, and ends with a one-line
-- summary.
--
-- Every fault that can be found before simulating is reported before
-- simulating, on standard error, with exit code 2, in three stages: the
-- command line (its first bad flag, or all the values that do not fit
-- together); else the world (all its faults); else all the other faults,
-- in one message. They are: an unknown flag, a world file that cannot be read or parsed
-- (with its line and column), an invalid world, options that do not fit
-- together ('validateOptions'), an output file or folder whose folder
-- does not exist, cannot be written or cannot be searched (a folder on
-- its path without x permission), an @--out@ that is a file or a
-- symbolic link to nothing, two outputs that are the same file
-- (under any names; devices such as @\/dev\/stdout@ excepted), an output
-- that is the world file, @--video@ without
-- @ffmpeg@ on the PATH. A controller that throws stops the run with a message naming the
-- robot and the simulated time (exit code 1), as does a referee's rule
-- that throws ('runSimRefereed'); so does a controller whose messages
-- raise when printed, whose step overflows the stack (@+RTS -K@), or
-- whose output depends on itself with no delay (@\<\<loop\>\>@, when the
-- runtime sees it: a self-reference that the optimiser turns into a loop
-- that never allocates, such as @rec let o = if c then x else o@ compiled
-- with @-O@, hangs instead, and only the watchdog of @SIGTERM@ and Ctrl-C ends it, see
-- "AFrobRobotSim.Run.Signals"). A write
-- that fails during the run (a full disk) stops it with a message (exit
-- code 1), and so does the heap's limit (@+RTS -M@). Ctrl-C stops the
-- run (exit code 130), and so does @SIGTERM@ (143). In each case the outputs are finished
-- with what was simulated (the log gets its summary, the page and the SVG
-- are written), every frame written is complete (frames are written to a
-- temporary file and renamed; no temporary file is left), and the summary
-- is printed. A Ctrl-C or @SIGTERM@ that comes while the outputs are
-- being written does not stop that: they are finished, the summary is
-- printed, a line on standard error says which signal came, and the exit
-- code is 130 or 143 ("AFrobRobotSim.Run.Signals"; a second Ctrl-C ends
-- the program at once), or 1 when an output could not be written (a
-- video whose ffmpeg the signal stopped too, a Ctrl-C at the terminal
-- reaching both). A video not yet begun when the signal came is not
-- begun: the frames are kept, and the line says so. Two runs with the same world, controllers and flags write
-- byte-identical frames.
--
-- The design that keeps a run's memory independent of its length: the
-- simulation is one lazy list of world states walked once, and each output
-- (the messages, the progress line, the frames with their trails, the SVG,
-- the log, the replay page, the result line) is a sink
-- ("AFrobRobotSim.Run.Sinks"), a strict fold with its own small state
-- that takes every state and is finished at the end; nothing else holds
-- a state. Trails keep only points more than a pixel apart (at most
-- 40,000 a robot, the newest 20,000 drawn), the SVG fewer than 4,000
-- snapshots (at most one every @max 1 (steps `div` 2000)@ steps, as
-- their robots' centres in unboxed arrays, 16 bytes a robot). The
-- replay page's recorder spools each frame's encoded line to temporary
-- files (at most about three pages' worth: it keeps the frames of every
-- thinning the page may still get, for a run that stops early) and
-- streams the page's into it at the end, so its memory is constant too;
-- the page itself grows with the run (about 70 kB per simulated second of
-- the default world) up to its bound ('replayMaxFrames'): leave it out
-- (@--no-replay@) for very long runs and write a log instead.
--
-- On several capabilities (@+RTS -N2@) the sinks take the states on a
-- thread of their own ("AFrobRobotSim.Pipeline"), while the stepping
-- thread computes the next ones; a few batches of states at most wait
-- between them. The sinks take the same states in the same order, and a
-- failing write, a failing controller or referee, or Ctrl-C stops the run at the same
-- step, as on one capability (where one loop does both): the outputs are
-- the same, byte for byte.
module AFrobRobotSim.Run
  ( runSim
  , runSimWith
  , runSimRefereed
  , runSimRefereedWith
  ) where

import           Control.Concurrent        (getNumCapabilities)
import           Control.Exception         (AsyncException (HeapOverflow, UserInterrupt), Exception (..), IOException, SomeException,
                                            evaluate, mask_, onException, throwIO, try)
import           Control.Monad             (forM, forM_, unless, when)
import           Data.Char                 (isPrint, isSpace)
import           Data.IORef
import           Data.List                 (intercalate)
import           Data.Maybe                (catMaybes, isNothing)
import           GHC.Clock                 (getMonotonicTime)
import           System.Directory          (removeFile, renameFile)
import           System.Environment        (getArgs, getProgName)
import           System.Exit               (ExitCode (..), exitWith)
import           System.FilePath           (isAbsolute, takeBaseName, takeDirectory, takeExtension, (</>))
import           System.IO                 (hClose, hIsTerminalDevice, hPutStr, openBinaryTempFileWithDefaultPermissions,
                                            stderr)
import           System.Process            (CreateProcess (..), proc, waitForProcess, withCreateProcess)
import           Text.Printf               (printf)

import           AFrobRobotSim.Console     (displayPath, endOutput, flushStdout, guardOutput, ioErrorText, putErr, quote,
                                            stopProgram, tolerantOutput)
import           AFrobRobotSim.DefaultWorld
import           AFrobRobotSim.Log
import           AFrobRobotSim.Options
import           AFrobRobotSim.Options.Check (printingModesFault, timesText)
import           AFrobRobotSim.Pipeline    (batchFor, pipeline)
import           AFrobRobotSim.Referee
import           AFrobRobotSim.Render
import           AFrobRobotSim.Replay
import           AFrobRobotSim.Params      (unreadParams)
import           AFrobRobotSim.JSON        (encodeJSON)
import           AFrobRobotSim.Result      (WorldSource, programJSON, worldSource)
import           AFrobRobotSim.Robot       (SimbotController)
import           AFrobRobotSim.Run.Preflight (preflight)
import           AFrobRobotSim.Run.Signals
import           AFrobRobotSim.Run.Sinks
import           AFrobRobotSim.Simulator
import           AFrobRobotSim.World
import           AFrobRobotSim.World.Check (validateWorld)
import           AFrobRobotSim.WorldFile

-- | Run a simbot program with the settings of the command line. 'Nothing'
-- runs the built-in default world ("AFrobRobotSim.DefaultWorld").
-- @--help@ prints the usage; a malformed command line is reported on
-- standard error with exit code 2.
runSim :: Maybe WorldTemplate -> SimbotController -> SimbotController -> IO ()
runSim = runSimRefereed noReferee

-- | 'runSim' with a referee: its rule for the balls and its scores are
-- the simulator's ('AFrobRobotSim.Referee'), its goals are drawn on the
-- replay page, and the scores reach the log, the page and the result
-- line (the final ones in their summaries). A referee whose rule or
-- scores fail stops the run as a failing controller does: the outputs
-- are finished with what was simulated, the message names the rule and
-- the time, and the exit code is 1. Goals that cannot be drawn (a
-- coordinate not finite, a negative size) are refused before the run
-- (exit code 2). @runSim = runSimRefereed 'noReferee'@.
runSimRefereed :: Referee -> Maybe WorldTemplate -> SimbotController -> SimbotController -> IO ()
runSimRefereed referee mworld rcA rcB = do
  tolerantOutput
  args <- getArgs
  prog <- getProgName
  case parseSimArgs defaultSimOptions args of
    Left err       -> stopProgram prog 2 err
    Right ShowHelp -> putStrLn (usage prog) >> endOutput prog
    Right (RunWith opts) -> runSimRefereedWith opts referee mworld rcA rcB

-- | Run a simbot program with settings given in code (the command line is
-- not read; the log's header records the program's real arguments).
runSimWith :: SimOptions -> Maybe WorldTemplate -> SimbotController -> SimbotController -> IO ()
runSimWith opts = runSimRefereedWith opts noReferee

-- | 'runSimWith' with a referee ('runSimRefereed').
runSimRefereedWith :: SimOptions -> Referee -> Maybe WorldTemplate -> SimbotController -> SimbotController -> IO ()
runSimRefereedWith opts referee mworld rcA rcB = do
  tolerantOutput   -- (a message the terminal's encoding cannot write must not stop the run)
  prog  <- getProgName
  -- (the two printing modes set together in code: refused before either
  -- prints, with the other faults 'validateOptions' finds, this one among
  -- them; a command line with both is refused where it is read)
  forM_ (printingModesFault opts) $ \_ -> refuse prog "cannot run:" (validateOptions opts)
  if optPrintProgram opts
    -- (the name alone: no world read, nothing written, no warning)
    then putStrLn (encodeJSON (programJSON prog opts)) >> endOutput prog
    else runPrepared prog opts referee mworld rcA rcB

-- 'runSimRefereedWith' of options that ask for a run or a printed world.
runPrepared :: String -> SimOptions -> Referee -> Maybe WorldTemplate -> SimbotController -> SimbotController -> IO ()
runPrepared prog opts referee mworld rcA rcB = do
  -- (the world checked once: a file's by its reader, each problem with
  -- its line; one given in code here; the run does not check it again,
  -- see 'simulateUnchecked')
  world <- case optWorldFile opts of
    Just file -> readWorldFile file >>= either (stopProgram prog 2) pure
    Nothing   -> do
      let world = maybe defaultWorld id mworld
      case validateWorld world of
        Left errs -> refuse prog "the world is invalid:" errs
        Right ()  -> pure world
  if optDumpWorld opts
    then do
      let text = renderWorld world
      guardOutput prog (putStr text)
      -- (a world made in code may say what a file cannot: more objects
      -- than 'maxObjects', a heading beyond 'maxHeading'; said, not
      -- refused: the world is printed, and runs)
      case parseWorld "the printed world" text of
        Left e  -> putErr (prog ++ ": warning: this world does not load back with --world: " ++ e ++ "\n")
        Right _ -> pure ()
      endOutput prog
    else do
      -- (the referee's goals, before the checks of the files, which make
      -- the output folder when nothing else is wrong)
      let cannotRun errs = unless (null errs) (refuse prog "cannot run:" errs)
      cannotRun (checkGoals referee)
      (errs, ffmpeg) <- preflight (worldBounds world) opts
      cannotRun errs
      -- (a flag with one value, or a parameter, given twice: the run uses
      -- the last value, and says so)
      let repeated what shown vs = prog ++ ": warning: " ++ what ++ " is given " ++ timesText (length vs) ++ ", "
            ++ intercalate " then " (map shown vs) ++ ": the last, " ++ shown (last vs) ++ ", is used"
          -- (a flag's value quoted when it is empty or holds a space)
          shownFlag v | not (null v), all (\c -> isPrint c && not (isSpace c)) t = t
                      | otherwise                                                = quote t
            where t = argText v
          shownParam k v = displayPath (k ++ "=" ++ argText v)
      unless (null (optFlagsRepeated opts) && null (optParamsRepeated opts)) $ putErr $ unlines $
        [ repeated flag shownFlag vs | (flag, vs@(_ : _)) <- optFlagsRepeated opts ]
        ++ [ repeated ("--param " ++ displayPath k) (shownParam k) vs | (k, vs@(_ : _)) <- optParamsRepeated opts ]
      -- (a parameter no controller asked for is usually a misspelled name)
      (unread, asked) <- unreadParams opts
      let readsText | null asked = "it reads none"
                    | otherwise  = "it reads " ++ intercalate ", " (map quote asked)
      unless (null unread) $ putErr $ unlines
        [ prog ++ ": warning: --param " ++ displayPath (k ++ "=" ++ v) ++ ": this program has asked for no parameter named "
          ++ quote k ++ " (" ++ readsText ++ ")" | (k, v) <- unread ]
      -- (a key pressed after the last step: a typo in its time, or a run
      -- shorter than meant)
      let nSteps = runSteps opts
          keyName c = case c of { ' ' -> "space"; ',' -> "comma"; _ -> [c] }
          late = keysNeverPressed (optDt opts) nSteps (optKeys opts)
          -- (a time to the microsecond: 3.0, not 3.0000000000000004)
          -- (too large for a millionth to count, as it is: 1.0e308, not Infinity)
          micro x = show (roundTo 1e6 x)
          lastStep = micro (fromIntegral nSteps * optDt opts)
          -- (after the last step, or due by then but left waiting its turn)
          why t | keyDue (optDt opts) t nSteps =
                    "it waits behind the presses due before it (a step presses at most one key, and a key"
                    ++ " pressed again straight after itself waits a step, released between) until after the"
                    ++ " run's last step, at " ++ lastStep ++ " s"
                | otherwise = "the run's last step is at " ++ lastStep ++ " s"
      unless (null late) $ putErr $ unlines
        [ prog ++ ": warning: the key press " ++ keyName c ++ " at " ++ micro t ++ " s is never pressed: " ++ why t
        | (t, c) <- late ]
      -- (an empty world file, or a generator's output that never came,
      -- runs: it is a world, but one the controllers take no part in)
      when (all (isNothing . robotKindOf) world) $ putErr $
        prog ++ ": warning: " ++ maybe "the world" (\f -> "the world " ++ displayPath f) (optWorldFile opts)
        ++ " has no robots: the controllers will not run\n"
      simulateRun prog opts referee ffmpeg (worldSource opts mworld) world rcA rcB

-- How a run's loop ended ('Failed': a controller's 'ControllerError' or
-- the referee's 'RefereeError').
data Ending = Finished | Interrupted | Failed SomeException | WriteFailed IOException | OutOfHeap

-- One pass over the states: every sink takes every state; nothing else
-- keeps a state, so the run's memory is the sinks' (constant but for the
-- replay page's frames).
simulateRun :: String -> SimOptions -> Referee -> Maybe FilePath -> WorldSource -> WorldTemplate -> SimbotController
            -> SimbotController -> IO ()
simulateRun prog opts referee ffmpeg source world rcA rcB = interruptible $ \stopper -> do
  start <- getMonotonicTime
  tty   <- hIsTerminalDevice stderr
  args  <- getArgs
  let dt       = optDt opts
      bounds   = worldBounds world
      scale    = scaleFor bounds opts
      cfg      = refereeConfig referee
                   defaultSimConfig { simDt = dt, simKeys = optKeys opts, simSeed = optSeed opts
                                    , simOdometryNoise = optOdometryNoise opts, simBounds = bounds }
      nSteps   = runSteps opts
      scene    = Scene bounds world
      style    = RenderStyle scale (optRays opts) (optTrails opts)
      logCfg   = defaultLogConfig { lcBounds = bounds, lcWorld = world, lcDt = dt
                                  , lcFps = optFps opts, lcSeed = optSeed opts
                                  , lcCommandLine = map argText (prog : args), lcGoals = refereeGoals referee }
      -- frame f is taken at the step nearest to simulated time f / fps
      -- (the same steps as the log's frames)
      frameAt  = isFrameStep dt (optFps opts)
      -- the replay page shows every frame period's state, or every k-th
      -- in a run that would give it more than 'replayMaxFrames' frames or
      -- 'replayMaxRobotFrames' robot-frames (a page that opens), k for the
      -- length the run turns out to have (a run that stops early is
      -- thinned less)
      replayRun  = replayPlan (optSeconds opts) logCfg
      svgEvery = max 1 (nSteps `div` svgMaxPoints)
      nRobots  = length [ () | o <- world, Just _ <- [robotKindOf o] ]
      states   = take (nSteps + 1) (simulateUnchecked cfg world rcA rcB)
  mrec <- forM (optReplay opts) $ \file -> do
    r <- try (newReplayRecorder replayRun logCfg)
    either (\(e :: IOException) -> stopProgram prog 2 ("--replay " ++ show file ++ ": its temporary file: " ++ ioErrorText e)) pure r
  stepsRef  <- newIORef (0 :: Int)
  scoresRef <- newIORef []   -- (the last simulated state's scores, for the summaries)
  framesRef <- newIORef (0 :: Int)
  frames <- if optFrames opts then Just <$> framesSink opts scale frameAt (renderPPM style scene) framesRef
                              else pure Nothing
  svg <- forM (optSvg opts) (svgSink svgEvery (style, scene))
  result <- forM (optResult opts) (resultSink prog opts source world)
  -- (the log last: opening it replaces the file, so it is opened only once
  -- nothing else can stop the run before its first step; a run refused
  -- here leaves an existing log as it was)
  mlog <- forM (optLog opts) $ \file -> do
    r <- try (openLogWriter logCfg file)
    either (\(e :: IOException) -> stopProgram prog 2 ("--log " ++ show file ++ ": " ++ ioErrorText e)) pure r
  -- (the progress line last: it counts the frames written up to and
  -- including this step's)
  let progress = tty && not (optQuiet opts)
      -- (finished in this order: the lines saying what was written)
      sinks = messages ++ catMaybes (logAndReplay ++ [ frames ]) ++ inMemory ++ progressLine
      messages = [ messagesSink progress | not (optQuiet opts) ]
      progressLine = [ progressSink nSteps framesRef | progress ]
      -- the log and the page, which share each frame's line where the
      -- page has one of every frame period (the same frames)
      logAndReplay = case (mlog, (,) <$> mrec <*> optReplay opts) of
        (Just w, Just (r, file)) -> [ Just (logAndReplaySink w r file) ]
        (ml, mr) -> [ logSink <$> ml, uncurry replaySink <$> mr ]
      -- A step counts as simulated once the sinks that only keep it in
      -- memory (the SVG's track, the result line's tallies, which cannot
      -- fail) have taken it, before those that write it (the log, the
      -- page, the frames, then the messages and the progress line): a
      -- write that fails, at this step, leaves the outputs before it in
      -- the list with this step, and the summary says it was simulated,
      -- so that no output holds a step past the summary's. The files come
      -- before the terminal's lines, which may fail (a closed pipe) or
      -- wait (a pipe nobody reads, where a signal can come in the middle
      -- of the step: 'mask_' holds a signal off only until a write
      -- waits), so that the files have every step the summary counts.
      inMemory = catMaybes [ svg, result ]
      writing  = catMaybes (logAndReplay ++ [ frames ]) ++ messages ++ progressLine
      sinkAll n s = do
        mapM_ (\k -> sinkStep k n s) inMemory
        writeIORef stepsRef $! n + 1
        writeIORef scoresRef (wsScores s)
        mapM_ (\k -> sinkStep k n s) writing
      -- (on one capability, Ctrl-C and SIGTERM come between two steps'
      -- outputs, not in the middle of one's, unless a write waits: then
      -- on the terminal's lines, after the files have the step; every
      -- file then ends at the same step)
      loop !_ [] = pure Finished
      loop !n (s : rest) = do
        _ <- evaluate (forceWorldState s)
        mask_ (sinkAll n s)
        loop (n + 1) rest
      -- how an exception ends the run (any other is thrown on)
      endedBy e
        | Just UserInterrupt <- fromException e       = pure Interrupted
        | isRunFailure e                               = pure (Failed e)
        | Just (io :: IOException) <- fromException e = pure (WriteFailed io)
        -- (the heap limit, +RTS -M: the outputs are then written in
        -- what the run's states held, which they no longer need; were that
        -- too little, the runtime ends the program as before)
        | Just HeapOverflow <- fromException e         = pure OutOfHeap
        | otherwise                                   = throwIO e
  caps <- getNumCapabilities
  ending <- if caps > 1 && not (null sinks)
    -- on several capabilities the sinks take the states on a thread of
    -- their own while the next steps are computed (the same states in the
    -- same order: the same outputs); a sink's failure comes first (it
    -- stopped at an earlier state than the stepping thread)
    then do
      (produced, stopped) <- pipeline (batchFor nRobots) (\s -> () <$ evaluate (forceWorldState s)) sinkAll states
      maybe (either endedBy (const (pure Finished)) produced) endedBy stopped
    else try (loop 0 states) >>= either endedBy pure
  -- (from here neither signal stops the run: it is writing its outputs,
  -- and assembling the video; one that comes is noted, for the exit code)
  (failed, videoSkipped) <- whileFinishing stopper $ do
    when progress (hPutStr stderr eraseProgress)
    steps <- readIORef stepsRef
    scores <- readIORef scoresRef
    nFrames <- readIORef framesRef
    end <- getMonotonicTime
    let simulated = roundTo 1e9 (fromIntegral (max 0 (steps - 1)) * dt)   -- (as the log's frames' times)
        wall      = end - start
        failure   = case ending of
          Failed ce -> Just ce
          _         -> Nothing
        interrupted = case ending of
          Interrupted -> True
          _           -> False
        -- (what stopped the run early, for the log's summary and the result
        -- line: a controller's failure, or a write that failed)
        stoppedText = case ending of
          WriteFailed e -> Just ("the run stopped: a write failed: " ++ ioErrorText e)
          OutOfHeap     -> Just ("the run stopped: it ran out of memory (the heap limit, +RTS -M; a controller "
                                 ++ "that keeps ever more state?)")
          _             -> Nothing
        failureText = case ending of
          Failed ce -> Just (displayException ce)
          _         -> stoppedText
        summary   = LogSummary simulated steps (-1) wall interrupted failureText Nothing scores
    Outcome errs wrote <- mconcat <$> mapM (`sinkFinish` summary) sinks
    let runErrs = maybe [] pure stoppedText
    -- (a write to standard output that fails here, a pipe whose reader
    -- has gone, is one of the run's errors: thrown on, the runtime took
    -- it for success, exit code 0 and nothing said)
    printed <- try $ do
     printf "%s%.2f s simulated in %d steps, %d frames, %.2f s wall time, %.1fx real time\n"
      (case ending of
         Interrupted   -> "interrupted: "
         Failed _      -> "failed: "
         WriteFailed _ -> "stopped: "
         OutOfHeap     -> "stopped: "
         Finished      -> "" :: String)
      simulated steps nFrames wall (if wall > 0 then simulated / wall else 0)
     unless (optQuiet opts) (mapM_ putStrLn wrote)
    -- (the summary written, or said to be lost: a full disk is not success)
    outErrs <- case (ending, printed) of
      (WriteFailed _, _)        -> [] <$ flushStdout   -- (said once: the write that stopped the run)
      (_, Left (e :: IOException)) -> pure ["cannot write to standard output: " ++ ioErrorText e]
      _                         -> maybe [] pure <$> flushStdout
    -- (a signal noted already: the video, which takes a while, is not
    -- begun; the frames are kept, and the signal's line says so)
    noted <- signalReceived stopper
    (videoErrs, unmade) <- case (ending, optVideo opts) of
      -- (the checks before the run made sure ffmpeg is there when --video is given)
      (Finished, Just file) | null errs, Just exe <- ffmpeg -> case noted of
        Nothing -> (\es -> (es, False)) <$> makeVideo opts exe nFrames file
        Just _  -> pure ([], True)
      _                                                      -> pure ([], False)
    let allErrs = map ((prog ++ ": ") ++) (maybe [] (\ce -> [displayException ce]) failure ++ runErrs ++ errs
                                           ++ outErrs ++ videoErrs)
    unless (null allErrs) (putErr (unlines allErrs))
    pure (not (null allErrs), unmade)
  -- (the signal that stopped the run, or that came while the outputs
  -- were written: the run is whole then, but whoever sent it is told that
  -- it came, by the exit code and in words; an output that failed is
  -- said above, and the exit code is then 1)
  signal <- signalReceived stopper
  case (ending, signal) of
    (Interrupted, _) -> pure ()
    (_, Just k)      -> putErr (prog ++ ": " ++ signalName k ++ " received while the outputs were being written: "
                                ++ (if | failed    -> "they were finished, but not all of them could be written (see above)"
                                       | videoSkipped -> "they were written first, but for the video, which was not "
                                                         ++ "begun (the frames are in " ++ displayPath (optOut opts) ++ ")"
                                       | otherwise -> "they were written first") ++ "\n")
    _                -> pure ()
  case ending of
    -- (the shell's code for a program ended by a signal: 128 and its
    -- number, Ctrl-C's 2 when no other came)
    Interrupted -> exitWith (ExitFailure (128 + maybe 2 id signal))
    Failed _    -> exitWith (ExitFailure 1)
    _ | failed           -> exitWith (ExitFailure 1)
    _ | Just k <- signal -> exitWith (ExitFailure (128 + k))
      | otherwise        -> pure ()

-- A signal's name in the run's messages.
signalName :: Int -> String
signalName k = case k of
  2  -> "Ctrl-C (SIGINT)"
  15 -> "SIGTERM"
  _  -> "signal " ++ show k

-- Assemble this run's frames with ffmpeg (the executable found on the PATH
-- before the run); the errors, if any. Only the run's own frames go in:
-- ffmpeg reads numbered files until a gap, and a longer earlier run's
-- frames may follow this run's in the folder. The names are given so
-- that ffmpeg takes them as they are: the video's as a file (not an
-- option, for a name that starts with @-@, nor another protocol, for
-- @http:@), the folder's with any @%@ doubled (the pattern's own is the
-- frame number) and as a path (@./@ before a relative one). A frame side
-- of an odd number of pixels is padded by one (the common encoders, H.264
-- in .mp4, take even sides only). The video is written beside its place
-- under a name of its own (with the same extension, by which ffmpeg picks
-- the format) and renamed there: a failure leaves an earlier video of
-- that name as it was. That name is made afresh for each video
-- (@.NAME.partialNNNN.EXT@, created by this program, so that it is no
-- file's already): ffmpeg writes over the file it is given, and a fixed
-- name was another output's (@--log .v.partial.mp4@ beside @--video
-- v.mp4@), or the world's, which were written over and then renamed away.
makeVideo :: SimOptions -> FilePath -> Int -> FilePath -> IO [String]
makeVideo opts exe nFrames file = do
  made <- try (openBinaryTempFileWithDefaultPermissions (takeDirectory file)
                                                        ("." ++ takeBaseName file ++ ".partial" ++ takeExtension file))
  case made of
    Left e             -> pure ["cannot write " ++ displayPath file ++ ": " ++ ioErrorText e]
    Right (partial, h) -> do
      hClose h
      let removePartial = try (removeFile partial) :: IO (Either IOException ())
      -- (not rawSystem, which ignores Ctrl-C in this program while ffmpeg
      -- runs: one that comes is noted as any other while the outputs are
      -- written, 'whileFinishing')
      code <- withCreateProcess
                (proc exe [ "-y", "-loglevel", "error", "-f", "image2", "-framerate", show (optFps opts)
                          , "-i", inFolder (optOut opts) </> framePattern, "-frames:v", show nFrames
                          , "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", "file:" ++ partial ])
                  { delegate_ctlc = False }
                (\_ _ _ ph -> waitForProcess ph)
                `onException` removePartial
      case code of
        ExitFailure c -> do
          _ <- removePartial
          -- (ended by a signal, which a shell's Ctrl-C or a batch
          -- system's SIGTERM sends ffmpeg too: named here, since this
          -- program's own handler may note it only after the outputs)
          pure [ (if c < 0 then "ffmpeg was stopped by " ++ signalName (negate c)
                           else "ffmpeg failed with exit code " ++ show c)
                 ++ "; the frames are in " ++ displayPath (optOut opts) ]
        ExitSuccess -> try (renameFile partial file) >>= \r -> case r of
          Left e   -> pure ["cannot write " ++ displayPath file ++ ": " ++ ioErrorText e ++ "; the video is in "
                            ++ displayPath partial]
          Right () -> [] <$ unless (optQuiet opts) (putStrLn ("wrote " ++ displayPath file))
  where
    inFolder dir = concatMap (\c -> if c == '%' then "%%" else [c]) (if isAbsolute dir then dir else "." </> dir)

-- @refuse prog heading faults@: the run refused before it began (exit
-- code 2, 'stopProgram'), the heading after the program's name and each
-- fault on a line of its own below it, indented.
refuse :: String -> String -> [String] -> IO a
refuse prog heading faults = stopProgram prog 2 (intercalate "\n" (heading : map ("  " ++) faults))
