{-# LANGUAGE BangPatterns        #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Run.Sinks
-- Description : The outputs of a run, each a strict fold over its world
--               states with a small state of its own.
--
-- "AFrobRobotSim.Run" walks a run's lazy list of world states once and
-- gives every state to each of its outputs: the console messages, the
-- progress line, the PPM frames with their trails, the SVG, the run log,
-- the replay page and the result line. Each is a 'Sink': what it does
-- with a state ('sinkStep', which keeps no world state, only what it
-- needs of it: trails of at most 40,000 points a robot, the newest 20,000
-- drawn; the SVG's snapshots, one every so many steps, as their robots'
-- centres in unboxed arrays) and
-- what it writes when the run ends ('sinkFinish', with the run's summary,
-- however the run ended). So a run's memory does not grow with its length
-- (but for the replay page's frames, which its recorder spools to a
-- temporary file). A write that fails at the end is reported in the
-- 'Outcome', not thrown, so that the other outputs are still written.
module AFrobRobotSim.Run.Sinks
  ( -- * Sinks
    Sink (..)
  , Outcome (..)
    -- * The outputs
  , messagesSink
  , progressSink
  , eraseProgress
  , framesSink
  , framePattern
  , isFrameName
  , svgSink
  , logSink
  , logAndReplaySink
  , replaySink
  , resultSink
  ) where

import           Control.Exception         (IOException, evaluate, try)
import           Control.Monad             (unless, when)
import           Control.Monad.ST          (runST)
import qualified Data.ByteString           as BS
import           Data.IORef
import           Data.Char                 (isDigit)
import           Data.List                 (foldl', stripPrefix)
import           System.Directory          (doesFileExist, removeFile, renameFile)
import           System.FilePath           (takeFileName, (</>))
import           System.IO                 (hFlush, hPutStr, stderr, stdout)
import           Text.Printf               (printf)

import           AFRP.Geometry             (Point2 (..), norm, (.-.))
import           AFrob.Dimensions          (Position2)
import           AFrobRobotSim.Console     (displayPath, ioErrorText, printableLine)
import           AFrobRobotSim.FlatArray   (DblArr, freezeD, indexD, newDblArr, writeD)
import           AFrobRobotSim.JSON        (encodeJSON)
import           AFrobRobotSim.Log
import           AFrobRobotSim.Options
import           AFrobRobotSim.OutputFile  (writeWhole)
import           AFrobRobotSim.Render
import           AFrobRobotSim.Render.SVG  (svgOf)
import           AFrobRobotSim.Replay
import           AFrobRobotSim.Result      (WorldSource, resultJSON, startTallies, stepTallies)
import           AFrobRobotSim.Simulator
import           AFrobRobotSim.World       (WorldTemplate)

-- | One output of a run: a consumer of the stream of world states (every
-- step's, from time 0) with its own small strict state, and what it does
-- when the run ends.
data Sink = Sink
  { sinkStep   :: Int -> WorldState -> IO ()
  , sinkFinish :: LogSummary -> IO Outcome
  }

-- | What a sink's end did: the messages of the writes that failed, and the
-- lines to tell the user (\"wrote FILE\") of those that succeeded.
data Outcome = Outcome [String] [String]

instance Semigroup Outcome where
  Outcome a b <> Outcome c d = Outcome (a ++ c) (b ++ d)

instance Monoid Outcome where
  mempty = Outcome [] []

-- A sink with nothing to finish.
stepOnly :: (Int -> WorldState -> IO ()) -> Sink
stepOnly f = Sink f (const (pure mempty))

-- | The robots' console messages, printed as they happen, each on its own
-- line with what does not print (an escape sequence, a newline) escaped
-- ('AFrobRobotSim.Console.printableLine'; the log and the replay page
-- keep them as they are). With 'True' ('progressSink' shows its line on
-- the terminal), the progress line is erased first, so that a message
-- starts a line of its own ('progressSink' draws it again).
messagesSink :: Bool -> Sink
messagesSink progress = stepOnly $ \_ s -> unless (null (wsMessages s)) $ do
  when progress (hPutStr stderr eraseProgress >> hFlush stderr)
  mapM_ (putStrLn . printableLine) (wsMessages s)
  hFlush stdout

-- | The progress line on a terminal: every 100 steps, and after a step
-- whose console messages erased it ('messagesSink'), the share of the
-- @nSteps@ steps done and the count of frames written so far (this
-- step's included when the frames' sink comes before it).
progressSink :: Int -> IORef Int -> Sink
progressSink nSteps framesRef = stepOnly $ \n s -> when (n `mod` 100 == 0 || not (null (wsMessages s))) $ do
  frames <- readIORef framesRef
  hPutStr stderr (printf "\r%3d%%  %d frames " ((100 * n) `div` max 1 nSteps) frames)

-- | What erases the progress line: a carriage return, spaces over the
-- longest line 'progressSink' draws for a run of fewer than 10^15
-- frames, and a carriage return.
eraseProgress :: String
eraseProgress = "\r" ++ replicate 30 ' ' ++ "\r"

-- A trail: the points of a robot's path that are more than a pixel from
-- the previous one, newest first: at most twice 'trailMax' (trimmed to
-- 'trailMax' when it reaches that), the newest 'trailMax' drawn.
data Trail = Trail !Int ![Position2]

trailMax :: Int
trailMax = 20000

-- Add a point to a trail when it moved more than @px@ metres.
extendTrail :: Double -> Position2 -> Trail -> Trail
extendTrail px p t@(Trail k ps) = case ps of
  q : _ | near q -> t
  _ | k >= 2 * trailMax -> Trail (trailMax + 1) (p : take trailMax ps)   -- amortised trimming
    | otherwise         -> Trail (k + 1) (p : ps)
  where near q = norm (p .-. q) <= px

trailPoints :: Trail -> [Position2]
trailPoints (Trail _ ps) = reverse (take trailMax ps)

-- | @framesSink opts scale frameAt render count@: the PPM frames of the
-- steps @frameAt@ picks (with the trails, when drawn), each rendered by
-- @render@ and written atomically into the output folder as the run goes
-- (a temporary file, then a rename: a frame whose writing fails leaves
-- its temporary file, which the sink's end removes); the count is shared
-- with the progress line and the summary.
framesSink :: SimOptions -> Double -> (Int -> Bool) -> ([[Position2]] -> WorldState -> BS.ByteString) -> IORef Int
           -> IO Sink
framesSink opts scale frameAt render countRef = do
  trailsRef <- newIORef []
  let px = 1 / scale
      step n s = do
        trails <- if optTrails opts
          then do
            old <- readIORef trailsRef
            let new = zipWith (extendTrail px) (map robotPos (wsRobots s)) (old ++ repeat (Trail 0 []))
            _ <- evaluate (foldl' (\acc (Trail k _) -> acc + k) 0 new)
            new <$ writeIORef trailsRef new
          else pure []
        when (frameAt n) $ do
          k <- readIORef countRef
          writeFrame (optOut opts) k (render (map trailPoints trails) s)
          writeIORef countRef $! k + 1
      -- A stopped run leaves at most the next frame's temporary file. The
      -- frames of a longer earlier run into the same folder stay (nothing
      -- already written is removed), and are said to be there.
      finish _ = do
        k <- readIORef countRef
        _ <- try (removeFile (frameTemp (optOut opts) k)) :: IO (Either IOException ())
        stale <- doesFileExist (framePath (optOut opts) k)
        pure (Outcome [] [ staleFramesNote (optOut opts) k | stale ])
  pure (Sink step finish)

-- | The SVG: snapshots taken every @every@ steps when a robot moved more
-- than a pixel since the last one, and the last state; written at the
-- end. The first snapshot and the last state
-- are kept whole; the others only as their robots' centres (in unboxed
-- arrays), which is all the picture draws of them, and each robot's
-- track is made as it is drawn ('AFrobRobotSim.Render.SVG.svgOf'). (Kept
-- whole, a 1000-robot world's 100 s had 53 MB alive as the picture was
-- drawn, and the snapshots, alive all run long, were copied by every
-- major collection.)
svgSink :: Int -> (RenderStyle, Scene) -> FilePath -> IO Sink
svgSink every (style, scene) file = do
  ref <- newIORef (Nothing, [], Nothing)
  let px = 1 / styleScale style
      moved a b = or (zipWith (\p q -> norm (p .-. q) > px) (centreList a) (map robotPos (wsRobots b)))
                  || centresCount a /= length (wsRobots b)
      step n s = do
        (first, kept, _) <- readIORef ref
        let kept' = case kept of
              k : _ | n `mod` every /= 0 || not (moved k s) -> kept
              _ | n `mod` every == 0 -> centresOf s : kept
              _                      -> kept
            first' = case first of
              Nothing | not (null kept') -> Just s
              _                          -> first
        kept' `seq` first' `seq` writeIORef ref (first', kept', Just s)
      finish _ = do
        (first, kept, final) <- readIORef ref
        let picture = case (first, reverse kept, final) of
              (Just s0, c0 : middle, Just f) ->
                -- the snapshots' centres in time order: the first (s0's),
                -- those kept, and the last state's (unless it is the
                -- newest kept); each track made as it is drawn, from the
                -- arrays
                let cs = c0 : [ c | c <- middle, centresTime c /= wsTime f ]
                         ++ [ centresOf f | wsTime f /= wsTime s0 ]
                    track i = [ centreAt c i | c <- cs, i < centresCount c ]
                    robots = [0 .. maximum (map centresCount cs) - 1]
                in svgOf style scene (Just (s0, f)) (map track robots) [ p | i <- robots, p : _ <- [track i] ]
              _ -> renderSVG style scene []
        attempt (show file) (Just ("wrote " ++ displayPath file)) (writeWhole file (`writeFile` picture))
  pure (Sink step finish)

-- A snapshot's time and its robots' centres, unboxed (x and y of robot
-- @i@ at @2 i@ and @2 i + 1@).
data Centres = Centres { centresTime :: !Double, centresCount :: !Int, _centresXY :: !DblArr }

centresOf :: WorldState -> Centres
centresOf s = runST $ do
  let rs = wsRobots s
      n  = length rs
  xy <- newDblArr (max 1 (2 * n))
  let fill !_ []       = pure ()
      fill !i (r : more) = do
        let Point2 x y = robotPos r
        writeD xy (2 * i) x
        writeD xy (2 * i + 1) y
        fill (i + 1) more
  fill 0 rs
  Centres (wsTime s) n <$> freezeD xy

-- The centre of robot @i@.
centreAt :: Centres -> Int -> Position2
centreAt (Centres _ _ xy) i = Point2 (indexD xy (2 * i)) (indexD xy (2 * i + 1))

-- The centres, in robot order.
centreList :: Centres -> [Position2]
centreList c = map (centreAt c) [0 .. centresCount c - 1]

-- | The run log, written as the run goes, closed with the summary.
logSink :: LogWriter -> Sink
logSink w = Sink (const (writeLogState w)) (\summary -> attempt "the log" Nothing (closeLogWriter w summary))

-- | The run log and a replay page ('logSink' then 'replaySink', as two
-- sinks would be), each frame of every frame period encoded once: the
-- page records the line the log wrote (for the frames it keeps at every
-- frame period: 'recordReplayStateWith'; the recorder's 'LogConfig' must
-- be the log's).
logAndReplaySink :: LogWriter -> ReplayRecorder -> FilePath -> Sink
logAndReplaySink w r file = Sink
  (\_ s -> writeLogStateLine w s >>= \line -> recordReplayStateWith r line s)
  (\summary -> (<>) <$> sinkFinish (logSink w) summary <*> sinkFinish (replaySink r file) summary)

-- | The replay page, written at the end from the recorder's temporary
-- files (constant memory; the page grows with the run's length, about 70
-- kB per simulated second of the default world, up to its bound). Its
-- \"wrote\" line says how thinned it is, when it is: one frame period in
-- k ('replayPageStride': for the length the run had).
replaySink :: ReplayRecorder -> FilePath -> Sink
replaySink r file =
  Sink (const (recordReplayState r))
       (\summary -> do
          k <- replayPageStride r summary
          let note | k > 1     = "; this run's page keeps one frame period in " ++ show k
                   | otherwise = ""
          attempt (show file) (Just ("wrote " ++ displayPath file ++ " (open it in a browser)" ++ note))
                  (writeReplay r summary file))

-- | The result line (settings and outcome), written at the end however the
-- run ended, naming the world by where it came from; the robots' tallies
-- are its only state. Before the first
-- state (a controller that fails at its first sample) they are the
-- robots as the world places them ('startRobotStates'), not none.
resultSink :: String -> SimOptions -> WorldSource -> WorldTemplate -> FilePath -> IO Sink
resultSink prog opts source world file = do
  ref <- newIORef (startTallies (startRobotStates world))
  let step n s = do
        old <- readIORef ref
        writeIORef ref $! if n == 0 then startTallies (wsRobots s) else stepTallies (optDt opts) s old
      finish summary = do
        tallies <- readIORef ref
        attempt (show file) Nothing
          (writeWhole file (`writeFile` (encodeJSON (resultJSON prog opts source summary tallies) ++ "\n")))
  pure (Sink step finish)

-- Run a write: its failure as a message, or its success as the line given
-- (if any).
attempt :: String -> Maybe String -> IO () -> IO Outcome
attempt what done act = do
  r <- try act
  pure $ case r of
    Left (e :: IOException) -> Outcome [ "cannot write " ++ what ++ ": " ++ ioErrorText e ] []
    Right ()                -> Outcome [] (maybe [] pure done)

-- Write frame number k atomically: a temporary file, then a rename.
writeFrame :: FilePath -> Int -> BS.ByteString -> IO ()
writeFrame dir k bytes = do
  let tmp = frameTemp dir k
  BS.writeFile tmp bytes
  renameFile tmp (framePath dir k)

-- | The name of frame number k, as a @printf@ (and ffmpeg) pattern:
-- @frame-%06d.ppm@, numbered from 0.
framePattern :: String
framePattern = "frame-%06d.ppm"

-- | Whether a file name is one the frames take in their folder: a
-- frame's (@frame-@, six digits or more, @.ppm@, as 'framePattern'
-- writes them) or the temporary file a frame is written to before it is
-- renamed (the same, then @.tmp@). The run refuses to read or write any
-- other file by such a name in that folder.
isFrameName :: String -> Bool
isFrameName name = case stripPrefix "frame-" name of
  Just rest | (ds, ext) <- span isDigit rest -> length ds >= 6 && ext `elem` [".ppm", ".ppm.tmp"]
  _                                          -> False

-- The file of frame number k.
framePath :: FilePath -> Int -> FilePath
framePath dir k = dir </> printf framePattern k

-- What the run says when the folder holds frames after its last one (an
-- earlier, longer run's): they are not this run's, and a video made from
-- the folder's files would show them.
staleFramesNote :: FilePath -> Int -> String
staleFramesNote dir k =
  "note: " ++ displayPath dir ++ " also holds " ++ takeFileName (framePath dir k)
  ++ " and on, from an earlier run, left as they were: this run wrote "
  ++ show k ++ " frames (--video takes only those)"

-- The temporary file of frame k, which an interrupted write leaves behind.
frameTemp :: FilePath -> Int -> FilePath
frameTemp dir k = framePath dir k ++ ".tmp"
