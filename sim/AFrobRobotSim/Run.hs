{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Run
-- Description : 'runSim': the headless runner behind every simbot program.
--
-- @runSim (Just world) rcA rcB@ reads its settings from the command line
-- (see "AFrobRobotSim.Options" for the flags), simulates, prints the
-- robots' console messages as they happen, writes the SVG, the replay
-- page, the run log and PPM frames as asked, and ends with a one-line
-- summary.
--
-- Every fault that can be found before simulating is reported before
-- simulating, all of them in one message on standard error, with exit
-- code 2: an unknown flag, a world file that cannot be read or parsed
-- (with its line and column), an invalid world, options that do not fit
-- together ('validateOptions'), an output file or folder whose folder
-- does not exist or cannot be written, @--video@ without @ffmpeg@ on the
-- PATH. A controller that throws stops the run with a message naming the
-- robot and the simulated time (exit code 1). A write that fails during
-- the run (a full disk) stops it with a message (exit code 1). Ctrl-C
-- stops the run (exit code 130). In each case the outputs are finished
-- with what was simulated (the log gets its summary, the page and the SVG
-- are written), every frame written is complete (frames are written to a
-- temporary file and renamed; no temporary file is left), and the summary
-- is printed. Two runs with the same world, controllers and flags write
-- byte-identical frames.
module AFrobRobotSim.Run
  ( runSim
  , runSimWith
  ) where

import           Control.Exception         (AsyncException (UserInterrupt), Exception (..), IOException, catch,
                                            evaluate, throwIO, try)
import           Control.Monad             (forM, forM_, unless, when)
import qualified Data.ByteString           as BS
import           Data.IORef
import           Data.List                 (foldl', nub)
import           Data.Maybe                (catMaybes)
import           GHC.Clock                 (getMonotonicTime)
import           System.Directory          (createDirectory, doesDirectoryExist, doesFileExist,
                                            findExecutable, getPermissions, removeFile, renameFile,
                                            writable)
import           System.Environment        (getArgs, getProgName)
import           System.Exit               (ExitCode (..), exitWith)
import           System.FilePath           (takeDirectory, (</>))
import           System.IO                 (BufferMode (..), hFlush, hIsTerminalDevice, hPutStr,
                                            hSetBuffering, stderr, stdout)
import           System.Process            (rawSystem)
import           Text.Printf               (printf)

import           AFRP.Geometry             (Point2)
import           AFrobRobotSim.DefaultWorld
import           AFrobRobotSim.Log
import           AFrobRobotSim.Options
import           AFrobRobotSim.Render
import           AFrobRobotSim.Replay
import           AFrobRobotSim.Robot       (SimbotController)
import           AFrobRobotSim.Simulator
import           AFrobRobotSim.World
import           AFrobRobotSim.WorldFile

-- | Run a simbot program with the settings of the command line. 'Nothing'
-- runs the built-in default world ("AFrobRobotSim.DefaultWorld").
-- @--help@ prints the usage; a malformed command line is reported on
-- standard error with exit code 2.
runSim :: Maybe WorldTemplate -> SimbotController -> SimbotController -> IO ()
runSim mworld rcA rcB = do
  args <- getArgs
  prog <- getProgName
  case parseSimArgs defaultSimOptions args of
    Left err       -> failWith 2 (prog ++ ": " ++ err)
    Right ShowHelp -> putStrLn (usage prog)
    Right (RunWith opts) -> runSimWith opts mworld rcA rcB

-- | Run a simbot program with settings given in code (the command line is
-- not read; the log's header records the program's real arguments).
runSimWith :: SimOptions -> Maybe WorldTemplate -> SimbotController -> SimbotController -> IO ()
runSimWith opts mworld rcA rcB = do
  prog  <- getProgName
  world <- case optWorldFile opts of
    Just file -> readWorldFile file >>= either (\e -> failWith 2 (prog ++ ": " ++ e)) pure
    Nothing   -> pure (maybe defaultWorld id mworld)
  case validateWorld world of
    Left errs -> failWith 2 (unlines ((prog ++ ": the world is invalid:") : map ("  " ++) errs))
    Right ()  -> pure ()
  if optDumpWorld opts
    then putStr (renderWorld world)
    else do
      errs <- preflight opts
      unless (null errs) $
        failWith 2 (unlines ((prog ++ ": cannot run:") : map ("  " ++) errs))
      simulateRun prog opts world rcA rcB

-- Every check of the options and the file system that can be made before
-- simulating; creates the output folder when something goes there.
preflight :: SimOptions -> IO [String]
preflight opts = do
  let out   = optOut opts
      files = catMaybes [ (,) "--svg" <$> optSvg opts, (,) "--log" <$> optLog opts
                        , (,) "--replay" <$> optReplay opts, (,) "--video" <$> optVideo opts ]
      inOut = optFrames opts || any ((== out) . takeDirectory . snd) files
  ffmpeg <- maybe (pure Nothing) (const (findExecutable "ffmpeg")) (optVideo opts)
  fileErrs <- forM files $ \(flag, f) ->
    if takeDirectory f == out && inOut then checkTarget flag f Nothing else checkTarget flag f (Just (takeDirectory f))
  let pre = validateOptions opts
            ++ [ "--video needs the frames (add --frames)" | optVideo opts /= Nothing, not (optFrames opts) ]
            ++ [ "--video needs ffmpeg on the PATH (on Debian: apt-get install ffmpeg)"
               | optVideo opts /= Nothing, ffmpeg == Nothing ]
            ++ [ "two outputs go to the same file" | let fs = map snd files, length (nub fs) /= length fs ]
            ++ concat fileErrs
  -- the output folder is created only when nothing else is wrong
  if inOut && null pre then checkFolder out else pure pre
  where
    -- a file to write: not a folder, and its folder exists and is writable
    checkTarget flag f mdir = do
      isDir <- doesDirectoryExist f
      dirErr <- case mdir of
        Nothing  -> pure []
        Just dir -> folderWritable flag f dir
      pure ([ flag ++ " " ++ show f ++ " is a folder" | isDir ] ++ dirErr)
    folderWritable flag f dir = do
      there <- doesDirectoryExist dir
      if not there
        then pure [ flag ++ " " ++ show f ++ ": the folder " ++ show dir ++ " does not exist" ]
        else do
          w <- writable <$> getPermissions dir
          exists <- doesFileExist f
          fw <- if exists then writable <$> getPermissions f else pure True
          pure [ flag ++ " " ++ show f ++ ": cannot write there" | not (w || (exists && fw)) ]
    -- the output folder: created if its parent exists, then proven writable
    checkFolder dir = do
      there <- doesDirectoryExist dir
      parentThere <- doesDirectoryExist (takeDirectory dir)
      if not there && not parentThere
        then pure [ "cannot write frames to " ++ show dir ++ ": the folder " ++ show (takeDirectory dir)
                    ++ " does not exist" ]
        else do
          r <- try (do unless there (createDirectory dir)
                       let probe = dir </> ".afrp-write-test"
                       writeFile probe "ok"
                       removeFile probe)
          pure $ case r of
            Left (e :: IOException) -> [ "cannot write frames to " ++ show dir ++ ": " ++ show e ]
            Right ()                -> []

data Progress = Progress
  { prSteps  :: !Int
  , prFrames :: !Int
  , prTrails :: [[Point2 Double]]   -- newest first, one list per robot
  , prKept   :: [WorldState]        -- snapshots kept for the SVG, newest first
  }

-- How a run's loop ended.
data Ending = Finished | Interrupted | Failed ControllerError | WriteFailed IOException

simulateRun :: String -> SimOptions -> WorldTemplate -> SimbotController -> SimbotController -> IO ()
simulateRun prog opts world rcA rcB = do
  start <- getMonotonicTime
  tty   <- hIsTerminalDevice stderr
  args  <- getArgs
  let dt       = optDt opts
      cfg      = defaultSimConfig { simDt = dt, simKeys = optKeys opts, simSeed = optSeed opts
                                  , simOdometryNoise = optOdometryNoise opts }
      nSteps   = max 0 (round (optSeconds opts / dt)) :: Int
      scene    = Scene notesBounds world
      style    = RenderStyle (optScale opts) (optRays opts) (optTrails opts)
      render   = renderPPM style scene   -- once: what every frame shares
      logCfg   = defaultLogConfig { lcBounds = notesBounds, lcWorld = world, lcDt = dt
                                  , lcFps = optFps opts, lcSeed = optSeed opts
                                  , lcCommandLine = prog : args }
      -- frame f is taken at the step nearest to simulated time f / fps
      frameAt n = let f = fromIntegral n * dt * optFps opts
                  in abs (f - fromIntegral (round f :: Int)) * 2 < dt * optFps opts
                     || n == 0
      svgEvery = max 1 (nSteps `div` 2000)
      states   = take (nSteps + 1) (simulateWith cfg world rcA rcB)
  mlog <- forM (optLog opts) $ \file -> do
    r <- try (openLogWriter logCfg file)
    either (\(e :: IOException) -> failWith 2 (prog ++ ": --log " ++ show file ++ ": " ++ show e)) pure r
  mrec <- forM (optReplay opts) (const (newReplayRecorder logCfg))
  ref <- newIORef (Progress 0 0 [] [])
  let loop [] = pure Finished
      loop (s : rest) = do
        _ <- evaluate (forceState s)
        unless (optQuiet opts) (mapM_ putStrLn (wsMessages s) >> hFlush stdout)
        forM_ mlog (`writeLogState` s)
        forM_ mrec (`recordReplayState` s)
        p <- readIORef ref
        let trails = if optTrails opts
                       then zipWith (:) (map robotPos (wsRobots s)) (padTo (length (wsRobots s)) (prTrails p))
                       else []
            n = prSteps p
        frames <- if optFrames opts && frameAt n
          then do
            writeFrame (optOut opts) (prFrames p)
              (render (map reverse trails) s)
            pure (prFrames p + 1)
          else pure (prFrames p)
        let kept = if optSvg opts /= Nothing && n `mod` svgEvery == 0 then s : prKept p else prKept p
        writeIORef ref (Progress (n + 1) frames trails kept)
        when (tty && not (optQuiet opts) && n `mod` 100 == 0) $
          hPutStr stderr (printf "\r%3d%%  %d frames " ((100 * n) `div` max 1 nSteps) frames)
        loop rest
  ending <- ((loop states `catch` \e -> case e of
                     UserInterrupt -> pure Interrupted
                     _             -> throwIO e)
             `catch` (pure . Failed))
            `catch` (pure . WriteFailed)
  when tty (hPutStr stderr "\r                         \r")
  p <- readIORef ref
  -- A stopped run leaves at most the next frame's temporary file.
  when (optFrames opts) $
    () <$ (try (removeFile (frameTemp (optOut opts) (prFrames p))) :: IO (Either IOException ()))
  end <- getMonotonicTime
  let simulated = fromIntegral (max 0 (prSteps p - 1)) * dt
      wall      = end - start
      failure   = case ending of
        Failed ce -> Just ce
        _         -> Nothing
      interrupted = case ending of
        Interrupted -> True
        _           -> False
      summary   = LogSummary simulated (prSteps p) (-1) wall interrupted (displayException <$> failure) []
      attempt what act = do
        r <- try act
        pure $ case r of
          Left (e :: IOException) -> [ "cannot write " ++ what ++ ": " ++ show e ]
          Right ()                -> []
  logErrs <- maybe (pure []) (\w -> attempt "the log" (closeLogWriter w summary)) mlog
  pageErrs <- case (mrec, optReplay opts) of
    (Just r, Just file) -> attempt (show file) (writeReplay r summary file)
    _                   -> pure []
  svgErrs <- case optSvg opts of
    Just file -> attempt (show file) (writeFile file (renderSVG style scene (reverse (prKept p))))
    Nothing   -> pure []
  let runErrs = case ending of
        WriteFailed e -> [ "the run stopped: a write failed: " ++ show e ]
        _             -> []
      errs = runErrs ++ logErrs ++ pageErrs ++ svgErrs
  printf "%s%.2f s simulated in %d steps, %d frames, %.2f s wall time, %.1fx real time\n"
    (case ending of
       Interrupted   -> "interrupted: "
       Failed _      -> "failed: "
       WriteFailed _ -> "stopped: "
       Finished      -> "" :: String)
    simulated (prSteps p) (prFrames p) wall (if wall > 0 then simulated / wall else 0)
  forM_ (optSvg opts) $ \file -> when (null svgErrs && not (optQuiet opts)) (putStrLn ("wrote " ++ file))
  forM_ (optReplay opts) $ \file -> when (null pageErrs && not (optQuiet opts)) (putStrLn ("wrote " ++ file ++ " (open it in a browser)"))
  hFlush stdout
  videoErrs <- case (ending, optVideo opts) of
    (Finished, Just file) | null errs -> makeVideo opts file
    _                                 -> pure []
  let allErrs = map ((prog ++ ": ") ++) (maybe [] (\ce -> [displayException ce]) failure ++ errs ++ videoErrs)
  unless (null allErrs) (putErr (unlines allErrs))
  case ending of
    Interrupted -> exitWith (ExitFailure 130)
    Failed _    -> exitWith (ExitFailure 1)
    _ | not (null allErrs) -> exitWith (ExitFailure 1)
      | otherwise          -> pure ()
  where
    padTo k xs = take k (xs ++ repeat [])

forceState :: WorldState -> ()
forceState s = foldl' (flip seq) () (wsRobots s) `seq` foldl' (flip seq) () (wsBalls s)
               `seq` foldl' (flip seq) () (map length (wsMessages s))

-- Write frame number k atomically: a temporary file, then a rename.
writeFrame :: FilePath -> Int -> BS.ByteString -> IO ()
writeFrame dir k bytes = do
  let name = dir </> printf "frame-%06d.ppm" k
      tmp  = frameTemp dir k
  BS.writeFile tmp bytes
  renameFile tmp name

-- The temporary file of frame k, which an interrupted write leaves behind.
frameTemp :: FilePath -> Int -> FilePath
frameTemp dir k = dir </> printf "frame-%06d.ppm.tmp" k

-- Assemble the frames with ffmpeg (found on the PATH before the run); the
-- errors, if any.
makeVideo :: SimOptions -> FilePath -> IO [String]
makeVideo opts file = do
  ffmpeg <- findExecutable "ffmpeg"
  case ffmpeg of
    Nothing -> pure ["--video needs ffmpeg on the PATH; the frames are in " ++ optOut opts]
    Just exe -> do
      code <- rawSystem exe [ "-y", "-loglevel", "error", "-framerate", show (optFps opts)
                            , "-i", optOut opts </> "frame-%06d.ppm", "-pix_fmt", "yuv420p", file ]
      case code of
        ExitSuccess   -> [] <$ putStrLn ("wrote " ++ file)
        ExitFailure c -> pure ["ffmpeg failed with exit code " ++ show c ++ "; the frames are in " ++ optOut opts]

-- Write a message to standard error in one piece (stderr is unbuffered,
-- which would write it a character at a time).
putErr :: String -> IO ()
putErr msg = do
  hSetBuffering stderr (BlockBuffering Nothing)
  hPutStr stderr msg
  hFlush stderr
  hSetBuffering stderr NoBuffering

failWith :: Int -> String -> IO a
failWith code msg = putErr (if null msg || last msg /= '\n' then msg ++ "\n" else msg) >> exitWith (ExitFailure code)
