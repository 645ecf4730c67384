{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Replay
-- Description : A self-contained HTML page that replays a run log.
--
-- One HTML file holds the log, the script and the style: it needs no
-- network and no server, and opens from @file://@. The log goes in as
-- JSON inside a @\<script type="application/json"\>@ element, which the
-- browser does not run (a long log in several such elements: see "Long
-- logs" below); 'AFrobRobotSim.JSON.encodeJSON' writes no @<@, @>@ or
-- @&@, so no string of the run (a robot's message, the command line) can
-- end that element or become markup, and the script shows
-- every such string with @textContent@. A Content-Security-Policy allows
-- only the page's own script (by a nonce), its own style and no network,
-- so that even markup that got in could run nothing.
--
-- The page draws the world like the frames ("AFrobRobotSim.Render":
-- same colours, shapes and robot shades), and has play/pause (space),
-- one frame back and forth (arrow keys), a time slider (held while
-- playing, it keeps the frame; playing goes on from where it is let
-- go), a speed (0.25x to 32x; frames that cannot be shown so fast are
-- passed over, the time running at the speed), toggles for range rays,
-- trails and tracker sightings, and beside the canvas (below it in a
-- window narrower than about 980 pixels) a panel with the readings and
-- wheel speeds of the robot last clicked, then its messages up to the
-- frame, newest first (the last 50), and the run's
-- events: bumps, scores, the robots' messages and the other console
-- lines, the last 30 up to the frame, newest last and scrolled into
-- view. Keys with Ctrl, Meta or Alt are left to the browser (its zoom:
-- Ctrl+0, Ctrl+plus, Ctrl+minus); Space plays or pauses, except on a
-- button or a tick box reached with Tab, which it presses or ticks. Its
-- title and its heading name the run (as text): the program
-- (and the example) and the world file, from the log's command line
-- (@simbot, world maze.world - afrp replay@). It
-- zooms (the mouse wheel, or a touchpad's pinch, about the point under
-- it; two fingers' pinch on a touch screen, about their midpoint; the
-- @+@ and @-@ buttons and keys, about the middle; up to 250 pixels a
-- metre) and moves (a drag, with the mouse, a pen or a finger; a pinch's
-- midpoint) within the world; @0@ or "Fit" shows the whole world
-- again; with "follow" ticked (the default), a zoomed view keeps the
-- selected robot in view, centring on it again when it leaves the
-- view's middle 60% (a drag or a pinch that moves the view, which the
-- next frame would undo, unticks it). A tap selects, as a click does (a
-- finger may move up to 10 CSS pixels in it, the mouse 4): a click
-- selects the robot within 3 canvas pixels, a finger's tap the robot
-- within 16 CSS pixels (a pen's, 8), the nearest if several are, when
-- the finger is lifted (also the tap right after a flick, for which the
-- browser may fire no click); on a narrow screen the canvas is shown
-- scaled to fit; in the whole world's view a finger's vertical swipe on
-- the canvas scrolls the page (a zoomed view takes every touch). In a big
-- world a robot is drawn at least 1.5 pixels in radius, and the ids are
-- drawn when they can be read: when at most 200 robots are in view, or
-- the robots are at least 8 pixels across; when a SimbotA and a
-- SimbotB share an id, every id drawn has its type's letter (A1, B1).
-- An id goes above its robot on the right, on the left where it would
-- leave the canvas (zoomed in, the world's rectangle) on the right, and
-- below the robot where it would leave it at the top. The text panels
-- break their lines between words. The page of a test's failing run,
-- whose summary has the instant the test's property was decided false
-- (@falsified@: afrp-test's @forAllRuns@ writes it), says its line in the
-- heading and the summary line (@FAILED: decided false at t = 6.76 (step
-- 338)@, as a controller's failure is said there), opens at the frame
-- nearest the instant and marks it on the time slider.
-- The canvas has the screen's pixels: its @devicePixelRatio@ (from 1 to
-- 2, taken again when the browser's zoom or another screen changes it,
-- the view and the frame kept) a CSS pixel, shown at its size in CSS pixels;
-- the sizes above are CSS pixels, a click's 3 canvas pixels too (those
-- of the canvas shown at its own size, not scaled to fit).
--
-- For tests and tools the page exposes @window.afrpReplay@: @frameCount()@,
-- @frame()@, @frameData(i)@, @setFrame(i)@, @play()@, @pause()@,
-- @playing()@, @selectRobot(i)@, @selected()@, @selections()@ (how many
-- clicks and taps have selected, a robot or none), @worldToCanvas(x,
-- y)@ and @canvasToWorld(px, py)@ (in the canvas's pixels, in the view:
-- twice the CSS pixels at a @devicePixelRatio@ of 2),
-- @view()@ (@{zoom, cx, cy}@: the zoom, 1 for the whole world, and the
-- world point in the middle), @setView(zoom, cx, cy)@, @maxZoom@,
-- @drawn()@ (@{robots, labels, labelBoxes, roughTrails}@: how many robots the last
-- frame drew, those in view, how many of their ids, each id's box
-- (@{robot, x, y, width, height}@ in the canvas's pixels, @y@ its top),
-- and whether its trails were the layer moved and scaled while the view
-- changed), @falsifiedFrame@ (the frame nearest the instant a property
-- was decided false, which the page opens at, or -1),
-- @roughAbove@ (the page's paths, in robots times frames, above which
-- the trails are so moved while the wheel, a drag or a pinch changes
-- the view, and drawn afresh 0.25 s after the last change: 200,000),
-- @header@ and @summary@.
-- Element ids: @world@ (the canvas), @play@, @back@, @fwd@, @slider@,
-- @speed@, @rays@, @trails@, @sightings@, @follow@, @zoomin@, @zoomout@,
-- @fit@, @time@, @info@, @events@, @meta@, @slider-marks@ (the
-- slider's mark, on the page of a failing test), @afrp-log@ (the log's lines,
-- a JSON array), and @afrp-log-2@, @afrp-log-3@, ...
-- (the lines that follow, when there are more).
--
-- = Long logs
--
-- A browser reads a data element's text as one string, and Chromium's
-- strings hold at most 2^29 - 24 characters (about 512 MiB): a page of
-- 10,000 robots for 10 s (about 1 GB) opened, but its script met
-- "Unexpected end of JSON input" and never drew a frame. So the lines go
-- into elements of at most 'replayChunkChars' characters each (64 MiB; a
-- line is never split, so an element holds at least one, however long),
-- and the page's script joins the elements' arrays in order. A log
-- shorter than that is one element, as before. (The page is ASCII, so
-- its characters are its bytes.)
--
-- = Modules
--
-- This module gathers the page's: "AFrobRobotSim.Replay.Page" (the HTML
-- around a log's lines, whole or streamed), "AFrobRobotSim.Replay.Recorder"
-- (a page recorded as a run goes, thinned for the length the run has),
-- "AFrobRobotSim.Replay.Spool" (their temporary files) and
-- "AFrobRobotSim.Replay.Assets" (the script and the style); and makes the
-- page of a log file ('writeReplayFromLog'; @simbot --replay-from@'s
-- command line is "AFrobRobotSim.Replay.CommandLine").
module AFrobRobotSim.Replay
  ( -- * Pages
    replayPage
  , replayPageFromLines
  , replayPageChunked
  , replayChunkChars
    -- * How many frames a run's page keeps
  , replayFrameStep
  , replayMaxFrames
  , replayMaxRobotFrames
    -- * The page of a log file
  , writeReplayFromLog
  , ReplayFault (..)
  , replayFaultText
    -- * Recording a run as it goes
  , ReplayPlan (..)
  , replayPlan
  , replayEveryFrame
  , ReplayRecorder
  , newReplayRecorder
  , recordReplayState
  , recordReplayStateWith
  , replayPageStride
  , replaySpooled
  , writeReplay
  , writeReplayChunked
  , discardReplay
  ) where

import qualified Data.ByteString.Char8     as BC
import           Control.Exception         (finally, mask, try)
import           System.Directory          (doesDirectoryExist, getTemporaryDirectory)
import           System.FilePath           (takeDirectory)

import           AFrobRobotSim.Log
import           AFrobRobotSim.Console     (displayPath, ioErrorText)
import           AFrobRobotSim.OutputFile  (notAFolder)
import           AFrobRobotSim.Replay.Page
import           AFrobRobotSim.Replay.Recorder
import           AFrobRobotSim.Replay.Spool
import           AFrobRobotSim.WorldFile.Lexical (canonicalPath)

-- | Read a log file and write its page: what @simbot --replay-from
-- FILE.jsonl --replay OUT.html@ does, giving how the log ends ('LogEnd':
-- its summary, if any, and the number of its last line if that line was
-- cut off, as a full disk leaves it: the page then shows the frames
-- before it; see "AFrobRobotSim.Log.Read"). What makes no page is a
-- 'Left', refused before anything is written ('ReplayRefused'): a log
-- that does not read (the reader's message: nothing is written then), a
-- page that is the log itself (under any name: the log is kept), an
-- empty name, a page that is a folder or in a folder that does not exist
-- (said before the log is read), a temporary folder that cannot be
-- used; or a write that fails on the way ('ReplayWriteFailed', naming
-- the page or the temporary file: a full disk), which leaves an earlier
-- page of that name as it was.
--
-- The page keeps every frame of the log: it is not thinned to
-- 'replayMaxFrames' as a run's own page is (a log of a long run makes a
-- page about as big as the log).
--
-- The page is 'replayPage' of the log ('readLogFile'), made as a run's
-- page is: the log is read a line at a time ('foldLogFile'), each frame's
-- line written to a temporary file (in the system's temporary folder,
-- removed from it as soon as it is made, and read back through its open
-- handle) and streamed into the page. Its memory is one line's,
-- however long the log: the page of a 37 MB log (ten minutes of the
-- default world) took 16 MB and 2.8 s; read whole, it took 410 MB and
-- 15 s (and a one-hour log 2.5 GB).
writeReplayFromLog :: FilePath -> FilePath -> IO (Either ReplayFault LogEnd)
writeReplayFromLog logPath out = do
  same <- (==) <$> canonicalPath logPath <*> canonicalPath out
  isFolder <- doesDirectoryExist out
  let folder = takeDirectory out
      refused :: String -> IO (Either ReplayFault LogEnd)
      refused = pure . Left . ReplayRefused
  why <- notAFolder folder
  case why of
    _ | null logPath -> refused "the log's name (--replay-from) is empty"
      | null out -> refused "the page's name (--replay) is empty"
      | isFolder -> refused ("cannot write the page " ++ displayPath out ++ ": it is a folder")
      | same     -> refused (displayPath out ++ ": is the log being read; the page would overwrite it")
    Just w   -> refused ("cannot write the page " ++ displayPath out ++ ": " ++ displayPath folder ++ " " ++ w)
    Nothing  -> do
      tmp <- getTemporaryDirectory
      -- (the frames' temporary file: a fault there, a missing or full
      -- temporary folder, is said as such, and the file is removed
      -- whatever happens)
      let spoolFault e = "cannot make the page: its temporary file in " ++ displayPath tmp ++ ": " ++ ioErrorText e
      -- (masked from the open to the cleanup's installing: a Ctrl-C
      -- between them would leave the file)
      mask $ \restore -> do
       opened <- try (openSpool tmp)
       case opened of
        Left e          -> refused (spoolFault e)
        Right (left, h) -> flip finally (closeSpool left h) $ restore $ do
          let start hd = let line = encodeLogLineBytes (LineHeader hd) in pure (line, fnvBytes fnvBasis line)
              step (header, !hash) f = do
                let !line = encodeLogLineBytes (LineFrame f)
                BC.hPutStrLn h line
                pure (header, fnvBytes hash line)
          -- (what the reading throws is the temporary file's: a fault
          -- of the log's own is a Left)
          spooled <- try (foldLogFile logPath start step <* rewind h)
          case spooled of
            Left e                                  -> pure (Left (ReplayWriteFailed (spoolFault e)))
            Right (Left e)                          -> refused e
            Right (Right ((header, hash), end)) -> do
              let summary = encodeLogLineBytes . LineSummary <$> leSummary end
              either (\e -> Left (ReplayWriteFailed ("cannot write the page: " ++ ioErrorText e)))   -- (it names the page)
                     (const (Right end))
                <$> try (writePage replayChunkChars header h summary (maybe hash (fnvBytes hash) summary) out)

-- | Why 'writeReplayFromLog' made no page: refused before anything was
-- written, or a write that failed. @simbot --replay-from@ exits with
-- code 2 for the first, as a run does for what it refuses before it
-- simulates, and 1 for the second, as a run does for a write that fails
-- ('AFrobRobotSim.Replay.CommandLine.replayFromMain').
data ReplayFault
  = ReplayRefused String
    -- ^ refused before anything was written: an empty name, a page that
    -- is a folder, is the log or is in a folder that does not exist, a
    -- log that does not read (the reader's message, with the line), a
    -- temporary folder that cannot be used (a folder that exists but may
    -- not be written to is found when the page is written: a
    -- 'ReplayWriteFailed')
  | ReplayWriteFailed String
    -- ^ a write that failed on the way (a full disk): of the frames'
    -- temporary file, or of the page, which is then not written (an
    -- earlier page of that name is kept)
  deriving (Eq, Show)

-- | The message of a 'ReplayFault' (it names the file).
replayFaultText :: ReplayFault -> String
replayFaultText (ReplayRefused msg)     = msg
replayFaultText (ReplayWriteFailed msg) = msg
