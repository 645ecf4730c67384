{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Run
-- Description : 'runSim': the headless runner behind every simbot program.
--
-- @runSim (Just world) rcA rcB@ reads its settings from the command line
-- (see "AFrobRobotSim.Options" for the flags), simulates, prints the
-- robots' console messages as they happen, writes PPM frames, and ends with
-- a one-line summary.
--
-- Faults are reported before anything is simulated when possible: an
-- unknown flag, a world file that cannot be read or parsed (with its line
-- and column), an invalid world, an output folder that cannot be written
-- all print a message to standard error and exit with code 2. A controller
-- that throws stops the run with a message naming the robot and the
-- simulated time (exit code 1). Ctrl-C stops the run: every frame written
-- so far is complete (frames are written to a temporary file and renamed),
-- the summary is printed, and the exit code is 130. Two runs with the same
-- world, controllers and flags write byte-identical frames.
module AFrobRobotSim.Run
  ( runSim
  , runSimWith
  ) where

import           Control.Exception         (AsyncException (UserInterrupt), Exception (..), IOException, catch,
                                            evaluate, throwIO, try)
import           Control.Monad             (forM_, unless, when)
import qualified Data.ByteString           as BS
import           Data.IORef
import           Data.List                 (foldl')
import           GHC.Clock                 (getMonotonicTime)
import           System.Directory          (createDirectoryIfMissing, findExecutable, removeFile,
                                            renameFile)
import           System.Environment        (getArgs, getProgName)
import           System.Exit               (ExitCode (..), exitWith)
import           System.FilePath           ((</>))
import           System.IO                 (hFlush, hIsTerminalDevice, hPutStr, hPutStrLn, stderr,
                                            stdout)
import           System.Process            (rawSystem)
import           Text.Printf               (printf)

import           AFRP.Geometry             (Point2)
import           AFrobRobotSim.DefaultWorld
import           AFrobRobotSim.Options
import           AFrobRobotSim.Render
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
-- not read).
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
      when (optFrames opts) (prepareFolder prog (optOut opts))
      when (optVideo opts /= Nothing && not (optFrames opts)) $
        failWith 2 (prog ++ ": --video needs the frames (drop --no-frames)")
      simulateRun prog opts world rcA rcB

-- Create the output folder and prove it writable, before simulating.
prepareFolder :: String -> FilePath -> IO ()
prepareFolder prog dir = do
  r <- try (do createDirectoryIfMissing True dir
               let probe = dir </> ".afrp-write-test"
               writeFile probe "ok"
               removeFile probe)
  case r of
    Left (e :: IOException) ->
      failWith 2 (prog ++ ": cannot write frames to " ++ show dir ++ ": " ++ show e)
    Right () -> pure ()

data Progress = Progress
  { prSteps  :: !Int
  , prFrames :: !Int
  , prTrails :: [[Point2 Double]]   -- newest first, one list per robot
  , prKept   :: [WorldState]        -- snapshots kept for the SVG, newest first
  }

simulateRun :: String -> SimOptions -> WorldTemplate -> SimbotController -> SimbotController -> IO ()
simulateRun prog opts world rcA rcB = do
  start <- getMonotonicTime
  tty   <- hIsTerminalDevice stderr
  let dt       = optDt opts
      cfg      = defaultSimConfig { simDt = dt, simKeys = optKeys opts, simSeed = optSeed opts
                                  , simOdometryNoise = optOdometryNoise opts }
      nSteps   = max 0 (round (optSeconds opts / dt)) :: Int
      scene    = Scene notesBounds world
      style    = RenderStyle (optScale opts) (optRays opts) (optTrails opts)
      render   = renderPPM style scene   -- once: what every frame shares
      -- frame f is taken at the step nearest to simulated time f / fps
      frameAt n = let f = fromIntegral n * dt * optFps opts
                  in abs (f - fromIntegral (round f :: Int)) * 2 < dt * optFps opts
                     || n == 0
      svgEvery = max 1 (nSteps `div` 2000)
      states   = take (nSteps + 1) (simulateWith cfg world rcA rcB)
  ref <- newIORef (Progress 0 0 [] [])
  let loop [] = pure False
      loop (s : rest) = do
        _ <- evaluate (forceState s)
        unless (optQuiet opts) (mapM_ putStrLn (wsMessages s) >> hFlush stdout)
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
  interrupted <- (loop states `catch` \e -> case e of
                     UserInterrupt -> pure True
                     _             -> throwIO e)
                 `catch` \(ce :: ControllerError) -> do
                   when tty (hPutStr stderr "\r")
                   failWith 1 (prog ++ ": " ++ displayException ce)
  when tty (hPutStr stderr "\r                         \r")
  p <- readIORef ref
  -- An interrupted write leaves at most the next frame's temporary file.
  when (interrupted && optFrames opts) $
    () <$ (try (removeFile (frameTemp (optOut opts) (prFrames p))) :: IO (Either IOException ()))
  forM_ (optSvg opts) $ \file -> do
    r <- try (writeFile file (renderSVG style scene (reverse (prKept p))))
    case r of
      Left (e :: IOException) -> hPutStrLn stderr (prog ++ ": cannot write " ++ show file ++ ": " ++ show e)
      Right ()                -> pure ()
  end <- getMonotonicTime
  let simulated = fromIntegral (max 0 (prSteps p - 1)) * dt
      wall      = end - start
  printf "%s%.2f s simulated in %d steps, %d frames, %.2f s wall time, %.1fx real time\n"
    (if interrupted then "interrupted: " else "" :: String)
    simulated (prSteps p) (prFrames p) wall (if wall > 0 then simulated / wall else 0)
  unless interrupted $ forM_ (optVideo opts) (makeVideo prog opts)
  when interrupted (exitWith (ExitFailure 130))
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

makeVideo :: String -> SimOptions -> FilePath -> IO ()
makeVideo prog opts file = do
  ffmpeg <- findExecutable "ffmpeg"
  case ffmpeg of
    Nothing -> hPutStrLn stderr (prog ++ ": --video needs ffmpeg on the PATH (on Debian: apt-get install ffmpeg); the frames are in "
                                 ++ optOut opts)
    Just exe -> do
      code <- rawSystem exe [ "-y", "-loglevel", "error", "-framerate", show (optFps opts)
                            , "-i", optOut opts </> "frame-%06d.ppm", "-pix_fmt", "yuv420p", file ]
      case code of
        ExitSuccess   -> putStrLn ("wrote " ++ file)
        ExitFailure c -> hPutStrLn stderr (prog ++ ": ffmpeg failed with exit code " ++ show c)

failWith :: Int -> String -> IO a
failWith code msg = hPutStrLn stderr msg >> exitWith (ExitFailure code)
