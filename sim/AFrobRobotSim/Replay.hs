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
-- window narrower than about 980 pixels) a panel with the readings,
-- wheel speeds and messages of the robot last clicked, and the run's
-- events: bumps, scores, the robots' messages and the other console
-- lines, the last 30 up to the frame, newest last and scrolled into
-- view. Keys with Ctrl, Meta or Alt are left to the browser (its zoom:
-- Ctrl+0, Ctrl+plus, Ctrl+minus). Its title names the run: the program
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
-- The canvas has the screen's pixels: its @devicePixelRatio@ (from 1 to
-- 2, as the page opened) a CSS pixel, shown at its size in CSS pixels;
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
-- @drawn()@ (@{robots, labels, roughTrails}@: how many robots the last
-- frame drew, those in view, how many of their ids, and whether its
-- trails were the layer moved and scaled while the view changed),
-- @roughAbove@ (the page's paths, in robots times frames, above which
-- the trails are so moved while the wheel, a drag or a pinch changes
-- the view, and drawn afresh 0.25 s after the last change: 200,000),
-- @header@ and @summary@.
-- Element ids: @world@ (the canvas), @play@, @back@, @fwd@, @slider@,
-- @speed@, @rays@, @trails@, @sightings@, @follow@, @zoomin@, @zoomout@,
-- @fit@, @time@, @info@, @events@, @meta@, @afrp-log@ (the log's lines,
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
  , writeReplayFromLog
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
import           Data.Bits                 (setBit, testBit, xor)
import           Data.IORef
import           Data.List                 (find, foldl')
import           Data.Maybe                (catMaybes, fromMaybe, isNothing, listToMaybe)
import           Data.Word                 (Word64, Word8, byteSwap64)
import           Foreign.Storable          (peekByteOff)
import qualified Data.ByteString.Internal  as BU (accursedUnutterablePerformIO)
import qualified Data.ByteString.Unsafe    as BU (unsafeUseAsCStringLen)
import           GHC.ByteOrder             (ByteOrder (..), targetByteOrder)
import           Numeric                   (showHex)
import           Control.Exception         (IOException, catch, evaluate, finally, mask, mask_, onException, try,
                                            uninterruptibleMask_)
import           System.Directory          (doesDirectoryExist, getTemporaryDirectory, removeFile)
import           System.FilePath           (takeDirectory)
import           System.IO

import           AFrobRobotSim.Log
import           AFrobRobotSim.Replay.Assets
import           AFrobRobotSim.Console     (displayPath, ioErrorText)
import           AFrobRobotSim.OutputFile  (notAFolder, writeWhole)
import           AFrobRobotSim.WorldFile.Lexical (canonicalPath)
import           AFrobRobotSim.Simulator   (WorldState (..))
import           AFrobRobotSim.World       (robotKindOf)

-- | The page of a log.
replayPage :: RunLog -> String
replayPage = replayPageChunked replayChunkChars

-- | 'replayPage' with the log's lines in data elements of at most @n@
-- characters each (at least one line each, however long it is): the
-- same page as 'replayPage' when the log is shorter than @n@.
replayPageChunked :: Int -> RunLog -> String
replayPageChunked n l = pre ++ joinChunked n (map encodeLogLine lns) ++ post
  where
    lns = LineHeader (rlHeader l) : map LineFrame (rlFrames l) ++ maybe [] ((: []) . LineSummary) (rlSummary l)
    -- The nonce, which comes first, hashes every line: in a pass of its
    -- own, which lets each encoded line go, so that the page is made as
    -- it is written, the lines encoded again, rather than held whole (a
    -- one-hour log's page is over 200 MB; held, it took 11 GB of memory).
    (pre, post) = replayPageParts (showHex (foldl' (\h x -> fnvBytes h (encodeLogLineBytes x)) fnvBasis lns) "")

-- | The page of a log given as its lines' JSON texts (as 'encodeLogLine'
-- writes them: a header first). The lines are embedded as they are, so
-- they must come from 'encodeLogLine' (which writes no @<@).
replayPageFromLines :: [String] -> String
replayPageFromLines ls = pre ++ joinChunked replayChunkChars ls ++ post
  where
    (pre, post) = replayPageParts (showHex (foldl' fnv fnvBasis ls) "")

-- The page around the log's lines, for a given nonce: what comes before
-- the first line and what comes after the last.
replayPageParts :: String -> (String, String)
replayPageParts nonce = (concat
  [ "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
  , "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
  , "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'nonce-"
  , nonce, "'; style-src 'unsafe-inline'; img-src data:\">\n"
  , "<link rel=\"icon\" href=\"data:,\">\n<title>afrp replay</title>\n<style>\n", replayStyle, "</style>\n"
  , "</head>\n<body>\n<h1>afrp replay</h1>\n<p id=\"meta\"></p>\n<div id=\"main\">\n<div>\n"
  , "<canvas id=\"world\" width=\"640\" height=\"640\"></canvas>\n<div id=\"controls\">\n"
  , "<button id=\"back\" title=\"one frame back (left arrow)\">&#9664;</button>\n"
  , "<button id=\"play\" title=\"play or pause (space)\">Play</button>\n"
  , "<button id=\"fwd\" title=\"one frame forward (right arrow)\">&#9654;</button>\n"
  , "<input id=\"slider\" type=\"range\" min=\"0\" max=\"0\" step=\"1\" value=\"0\" aria-label=\"time\">\n"
  , "<select id=\"speed\" aria-label=\"speed\"><option value=\"0.25\">0.25x</option>"
  , "<option value=\"0.5\">0.5x</option><option value=\"1\" selected>1x</option>"
  , "<option value=\"2\">2x</option><option value=\"4\">4x</option></select>\n"
  , "<span id=\"time\"></span>\n</div>\n<div id=\"toggles\">\n"
  , "<button id=\"zoomout\" title=\"zoom out (-)\">&minus;</button>\n"
  , "<button id=\"zoomin\" title=\"zoom in (+, or the wheel)\">+</button>\n"
  , "<button id=\"fit\" title=\"the whole world (0)\">Fit</button>\n"
  , "<label><input id=\"rays\" type=\"checkbox\" checked> range rays</label>\n"
  , "<label><input id=\"trails\" type=\"checkbox\" checked> trails</label>\n"
  , "<label><input id=\"sightings\" type=\"checkbox\"> tracker sightings</label>\n"
  , "<label title=\"keep the selected robot in a zoomed view\"><input id=\"follow\" type=\"checkbox\" checked> follow</label>\n"
  , "</div>\n</div>\n<div id=\"side\">\n<pre id=\"info\"></pre>\n<h1>events</h1>\n<pre id=\"events\"></pre>\n"
  , "</div>\n</div>\n"
  , dataOpen 1 ]
  , concat [ "]\n</script>\n"
           , "<script nonce=\"", nonce, "\">\n", replayScript, "</script>\n</body>\n</html>\n" ])

-- | The most characters of the log's lines that one of the page's data
-- elements holds (see "Long logs" above): 64 MiB, an eighth of what
-- Chromium reads as one string.
replayChunkChars :: Int
replayChunkChars = 64 * 1024 * 1024

-- | The most frames a run's page holds: 9000 (6 minutes at 25 frames a
-- second, about 25 MB for the default world). See 'replayFrameStep'.
replayMaxFrames :: Int
replayMaxFrames = 9000

-- | The most robot-frames (robots times frames) a run's page holds: 1.25
-- million, about 0.5 to 1 GB of page: some 420 bytes each, and up to some
-- 840 in a crowded world, where each robot's tracker sees many others.
-- Chromium (Debian's 156) opened the page of 10,000 robots for 10 s (2.5
-- million robot-frames, 1.06 GB) in 25-33 s, and crashed on their 30 s
-- (7.5 million, 3.2 GB); the page of 2,500 robots 2 m apart for 40 s (2.5
-- million, 2.1 GB) took 161 s and 3.7 GB of script memory to open, so the
-- bound, which was 2.5 million, is now half that. See 'replayFrameStep'.
replayMaxRobotFrames :: Int
replayMaxRobotFrames = 1250000

-- | @replayFrameStep seconds fps robots@: the page of a run of that many
-- simulated seconds, frames a second and robots keeps one frame period
-- in this many (at least 1): the fewest that keep it within
-- 'replayMaxFrames' frames and 'replayMaxRobotFrames' robot-frames
-- (counting @seconds * fps@ frame periods). So a long run or a big world
-- gets a page that still opens, its frames thinned evenly; the run's log
-- keeps every frame. A run's page is thinned by this for the length the
-- run had: a run that went its planned length by its stride, one that
-- stopped early (interrupted, failed) at @t@ by the first of 1, 2, 4, ...
-- and that stride that is at least @replayFrameStep t fps robots@ (see
-- 'ReplayRecorder' and 'replayPlan').
--
-- > replayFrameStep 30 25 6      == 1   -- the default world
-- > replayFrameStep 400 25 6     == 2   -- 10,000 periods
-- > replayFrameStep 30 25 10000  == 6   -- 7.5 million robot-frames
replayFrameStep :: Double -> Double -> Int -> Int
replayFrameStep seconds fps robots = maximum [1, over replayMaxFrames 1, over replayMaxRobotFrames (max 1 robots)]
  where
    periods = seconds * fps
    over :: Int -> Int -> Int
    over limit per = ceiling (periods * fromIntegral per / fromIntegral limit)

-- The opening of the page's @k@-th data element (from 1), up to its
-- array's @[@.
dataOpen :: Int -> String
dataOpen k = "<script id=\"afrp-log" ++ (if k == 1 then "" else '-' : show k) ++ "\" type=\"application/json\">\n["

-- What ends the @k@-th data element and opens the next.
dataBreak :: Int -> String
dataBreak k = "]\n</script>\n" ++ dataOpen (k + 1)

-- The lines of the page's data, for elements of at most @n@ characters:
-- separated as 'placeLine' places them (an element holds at least one
-- line).
joinChunked :: Int -> [String] -> String
joinChunked _ [] = ""
joinChunked n (l0 : ls0) = l0 ++ go (1, length l0) ls0
  where
    go _ [] = ""
    go at (l : ls) = case placeLine n at (length l) of
      (before, at') -> before ++ l ++ go at' ls

-- @placeLine n (k, used) len@: what goes before a line of @len@
-- characters that follows the others in data element @k@ (which holds
-- @used@ characters so far), in elements of at most @n@ characters, and
-- the element and its count after it: a comma, or, where the line would
-- take its element beyond @n@, that element's end and the next one's
-- opening. The one rule of 'joinChunked' and 'writeReplayChunked'.
placeLine :: Int -> (Int, Int) -> Int -> (String, (Int, Int))
placeLine n (!k, !used) len
  | used + 2 + len > n = (dataBreak k, (k + 1, len))
  | otherwise          = (",\n", (k, used + 2 + len))

-- The page's nonce depends on its data, so that pages differ: a hash of
-- the log's lines, one after the other, each line's bytes taken eight at
-- a time (FNV-1a's step on 64-bit little-endian words, then on its last
-- bytes one by one). A byte at a time, it cost about 11 instructions a
-- byte, a tenth of a 1000-robot page's cost; a word at a time, it costs
-- well under one.
fnv :: Word64 -> String -> Word64
fnv h = fnvBytes h . BC.pack

-- 'fnv' of a line's bytes (ASCII: the same as of its characters).
fnvBytes :: Word64 -> BC.ByteString -> Word64
fnvBytes h0 bs = BU.accursedUnutterablePerformIO $ BU.unsafeUseAsCStringLen bs $ \(p, n) ->
  let mix h w = (h `xor` w) * 1099511628211
      words8 !h !i
        | i + 8 <= n = peekByteOff p i >>= \w -> words8 (mix h (fromLE w)) (i + 8)
        | otherwise  = bytes1 h i
      bytes1 !h !i
        | i < n     = peekByteOff p i >>= \b -> bytes1 (mix h (fromIntegral (b :: Word8))) (i + 1)
        | otherwise = pure h
  in words8 h0 0
  where
    -- (the words as little-endian numbers on any machine)
    fromLE :: Word64 -> Word64
    fromLE = case targetByteOrder of
      LittleEndian -> id
      BigEndian    -> byteSwap64

fnvBasis :: Word64
fnvBasis = 14695981039346656037

-- | Read a log file and write its page: what @simbot --replay-from
-- FILE.jsonl --replay OUT.html@ does, giving how the log ends ('LogEnd':
-- its summary, if any, and the number of its last line if that line was
-- cut off, as a full disk leaves it: the page then shows the frames
-- before it; see "AFrobRobotSim.Log.Read"). A log that does not
-- read is a 'Left' with the reader's message (nothing is written then); a page that
-- cannot be written is a 'Left' naming it, and so is a page that is the
-- log itself (under any name: the log is kept), an empty name, a
-- folder, or in a folder that does not exist (said before the log is
-- read).
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
writeReplayFromLog :: FilePath -> FilePath -> IO (Either String LogEnd)
writeReplayFromLog logPath out = do
  same <- (==) <$> canonicalPath logPath <*> canonicalPath out
  isFolder <- doesDirectoryExist out
  let folder = takeDirectory out
  why <- notAFolder folder
  case why of
    _ | null logPath -> pure (Left "the log's name (--replay-from) is empty")
      | null out -> pure (Left "the page's name (--replay) is empty")
      | isFolder -> pure (Left ("cannot write the page " ++ displayPath out ++ ": it is a folder"))
      | same     -> pure (Left (displayPath out ++ ": is the log being read; the page would overwrite it"))
    Just w   -> pure (Left ("cannot write the page " ++ displayPath out ++ ": " ++ displayPath folder ++ " " ++ w))
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
        Left e          -> pure (Left (spoolFault e))
        Right (left, h) -> flip finally (closeSpool left h) $ restore $ do
          let start hd = let line = encodeLogLineBytes (LineHeader hd) in pure (line, fnvBytes fnvBasis line)
              step (header, !hash) f = do
                let !line = encodeLogLineBytes (LineFrame f)
                BC.hPutStrLn h line
                pure (header, fnvBytes hash line)
          spooled <- try (foldLogFile logPath start step <* rewind h)
          case spooled of
            Left e                                  -> pure (Left (spoolFault e))
            Right (Left e)                          -> pure (Left e)
            Right (Right ((header, hash), end)) -> do
              let summary = encodeLogLineBytes . LineSummary <$> leSummary end
              either (\e -> Left ("cannot write the page: " ++ ioErrorText e)) (const (Right end))   -- (it names the page)
                <$> try (writePage replayChunkChars header h summary (maybe hash (fnvBytes hash) summary) out)

-- | What a recorder needs to thin its page: the run's planned length, and
-- the stride (frame periods per page frame) of the page of a run planned
-- for any length.
data ReplayPlan = ReplayPlan
  { planSeconds :: !Double
    -- ^ the run's planned length (simulated seconds)
  , planStride  :: Double -> Int
    -- ^ @planStride t@: one frame period in how many the page of a run
    -- planned for @t@ seconds keeps; at least 1, and never smaller for a
    -- longer @t@ ('replayFrameStep', in 'replayPlan')
  }

-- | @replayPlan seconds cfg@: the plan of a @simbot@ run of that many
-- seconds whose frames are @cfg@'s: a page within 'replayMaxFrames' and
-- 'replayMaxRobotFrames', 'replayFrameStep' at 'lcFps' @cfg@ for the
-- robots of 'lcWorld' @cfg@.
replayPlan :: Double -> LogConfig -> ReplayPlan
replayPlan seconds cfg = ReplayPlan seconds (\t -> replayFrameStep t (lcFps cfg) robots)
  where
    robots = length [ () | o <- lcWorld cfg, Just _ <- [robotKindOf o] ]

-- | The plan of a page that keeps every frame period, however long the run
-- (the testing kit's; its size is not bounded).
replayEveryFrame :: ReplayPlan
replayEveryFrame = ReplayPlan 0 (const 1)

-- | A page being recorded as a run goes, thinned for the length the run
-- turns out to have. Each frame's line is encoded at once and appended to
-- a temporary file (in the system's temporary folder), so recording holds
-- neither the simulation's states nor the frames: memory stays constant
-- however long the run. 'writeReplay' streams the lines of the page into
-- it. The files are removed from their folder as soon as they are made
-- (each lives on through the recorder's handle), so that a run that is
-- killed (@SIGKILL@) leaves nothing in the temporary folder; where a file
-- cannot be removed while open, the recorder removes it when it closes it.
--
-- = Thinning for the run's actual length
--
-- A run planned for @T@ seconds gets the page of one frame period in
-- @S = planStride T@ ('replayFrameStep': within 'replayMaxFrames' and
-- 'replayMaxRobotFrames'), as when the recorder took only those frames. A
-- run that stops at @t@ (interrupted, or failed: what the summary given
-- to 'writeReplay' says) would be thinned as much, and its page would
-- keep 13 frames of the five seconds a controller ran before it failed in
-- a planned hour. It gets instead the page of a run planned for @t@,
-- within a factor 2: one frame period in @d@, the first of 1, 2, 4, 8, ...
-- and @S@ that is at least @planStride t@. So @d@ is @planStride t@ itself
-- when that is a power of 2 (1 included: a run short enough to need no
-- thinning gets every frame period) or @S@, and less than twice it
-- otherwise; it is never more than @S@ (never fewer frames than the
-- planned thinning kept) and the page stays within the bounds.
--
-- A run does not know when it will stop, so the recorder keeps the frames
-- of every stride it may still be asked for: from the one a stop at the
-- last state's time would get (which only grows) up to @S@. Each
-- stride's frames are 'AFrobRobotSim.Log.logStep''s at @fps \/ d@
-- ('AFrobRobotSim.Log.LogRates'), so the page of any stride is exactly
-- the run's page thinned by that frame rate: a frame carries the events,
-- console lines and messages of its whole period, those of the frame
-- periods left out included. A step that is a frame of several strides
-- whose periods hold the same events and lines (nothing happened between)
-- is encoded once for them all. (A line for each stride rather than one
-- for the finest, merged at the end: a merge would parse each kept frame
-- again and write it anew, at the cost of a frame's making, and only as
-- exact as a number's text reads back.)
--
-- Each line goes to the temporary file of the coarsest stride it serves,
-- tagged with its step and its strides, and a stride's file is closed,
-- and so removed, once the run has outgrown it (a stop would get a
-- coarser stride). A stride @d@'s file holds at most one line for each of
-- its frames so far; the strides alive at a time are @d@, @2 d@, ... and
-- @S@, where @d@'s frames are within the page's bounds; so the files hold
-- at most about three pages' worth of lines (@d@'s, half as many for
-- @2 d@, a quarter for @4 d@, ..., and @S@'s), in frames and in
-- robot-frames (tested: at most three pages of frames and a line for each
-- stride). Why not the divisors of @S@: a chain of them (9 gives 1,
-- 3, 9) leaves a stop where 4 would do with 9; powers of 2 keep the
-- factor 2, and need not divide @S@ since each stride is kept whole on
-- its own. Why a file for each stride rather than one: a stride the run
-- has outgrown leaves with its file, where one file would keep about a
-- page's worth of such lines for each doubling of the run's length.
--
-- The price: the frames of the finer strides are made (sensed and
-- encoded) though a run that goes its length keeps none of them, about
-- half a page's worth for each doubling of the run beyond a page, and the
-- planned stride's; a step that is a frame of several strides whose
-- periods differ (a message or an event came between) is encoded once
-- for each. A 1-hour run of the default world (@S = 10@) makes the
-- frames of 27,901 steps for its page of 9001, and took 10.0 s against
-- 7.9 s (the same page); a 10-hour run, 43,921 (a review counted 39,930
-- and 67,530 encodings when a robot prints a line every 0.12 s). It costs
-- most just past a bound, where nearly every frame period is encoded for
-- a page of half of them, and where encoding is most of the run: the
-- review's 200-robot world at 100 frames a second for 70 s (@S = 2@) took
-- 16.75 s against 10.19 s.
data ReplayRecorder = ReplayRecorder LogConfig !Int (Double -> Int) (IORef Recording)
  -- (the frames at every frame period; the planned stride; the stride of
  -- a page of a run that stops at a time; what is recorded)

-- What the recorder carries from step to step: each live stride's
-- periods ('LogRates', keyed by the stride's bit), the live strides,
-- finest first (the first is the stride of a stop now), and the steps
-- taken.
data Recording = Recording !(LogRates Int) [Level] !Int

-- A stride the page may still be thinned to, and its temporary file,
-- which holds the lines whose coarsest stride it is.
data Level = Level
  { lvStride :: !Int
  , lvBit    :: !Int            -- its bit in the tag of a line (from 0, the finest)
  , lvLeft   :: Maybe FilePath  -- its file's path, if the system kept it in its folder
  , lvHandle :: Handle
  , lvLines  :: !Int            -- the lines its file holds
  , lvFrames :: !Int            -- the frames of its page so far
  , lvHash   :: !Word64         -- the nonce hash of its page's lines so far (its header's first)
  }

-- | Start recording a run of the given plan, whose frame periods are the
-- config's ('lcFps': the page's frame rate is that divided by its stride):
-- makes the temporary files, one for each stride the page may get (1, 2,
-- 4, ... below the planned stride, and that). With 'replayEveryFrame',
-- one, and the page keeps every frame period.
newReplayRecorder :: ReplayPlan -> LogConfig -> IO ReplayRecorder
newReplayRecorder plan cfg = do
  tmp <- getTemporaryDirectory
  spools <- openSpools tmp (length strides)
  let levels = [ Level d b left h 0 0 (fnvBytes fnvBasis (headerAt cfg d))
               | (b, d, (left, h)) <- zip3 [0 ..] strides spools ]
      rates  = logRatesStart cfg [ (b, lcFps cfg / fromIntegral d) | (b, d) <- zip [0 ..] strides ]
  ReplayRecorder cfg planned strideAt <$> newIORef (Recording rates levels 0)
  where
    planned = max 1 (planStride plan (planSeconds plan))
    strides = takeWhile (\d -> d > 0 && d < planned) (iterate (* 2) 1) ++ [planned]
    strideAt t = let x = planStride plan t in fromMaybe planned (find (>= x) strides)

-- The header line of the page of one frame period in @d@.
headerAt :: LogConfig -> Int -> BC.ByteString
headerAt cfg d = encodeLogLineBytes (LineHeader (logHeader cfg { lcFps = lcFps cfg / fromIntegral d }))

-- @k@ temporary files ('openSpool'), all or none.
openSpools :: FilePath -> Int -> IO [(Maybe FilePath, Handle)]
openSpools tmp k0 = mask_ (go k0 [])
  where
    go k acc
      | k <= 0    = pure (reverse acc)
      | otherwise = do
          sp <- openSpool tmp `onException` mapM_ (uncurry closeSpool) acc
          go (k - 1) (sp : acc)

-- The frames' temporary file, made in the folder given, open for
-- writing and then reading back ('rewind'), block-buffered, and removed
-- from the folder at once: the path still to remove at the end, if the
-- system would not remove an open file. (Masked: a signal cannot come
-- between making the file and removing it, and leave it behind.)
openSpool :: FilePath -> IO (Maybe FilePath, Handle)
openSpool tmp = mask_ $ do
  (path, h) <- openBinaryTempFile tmp "afrp-replay.frames"
  hSetBuffering h (BlockBuffering Nothing)
  removed <- try (removeFile path)
  pure (either (\e -> const (Just path) (e :: IOException)) (const Nothing) removed, h)

-- The spool written: read it from its start.
rewind :: Handle -> IO ()
rewind h = hFlush h >> hSeek h AbsoluteSeek 0

-- | Give the recorder the next step's state (every step, the first at
-- time 0).
recordReplayState :: ReplayRecorder -> WorldState -> IO ()
recordReplayState r = recordReplayStateWith r Nothing

-- | 'recordReplayState', given the frame line that a run log whose
-- 'LogConfig' is the recorder's made of this state, if any
-- ('AFrobRobotSim.Log.writeLogStateLine': a frame of every frame
-- period, which is the finest stride's while the run is short enough to
-- keep them all). The recorder then writes that line instead of encoding
-- that frame again (at 1000 robots a frame's encoding costs several times
-- the step it shows); the page is the same. With 'Nothing', or at a step
-- that is not a frame's, it is 'recordReplayState'.
--
-- At each step the strides the run has outgrown (finer than a stop at
-- this state's time would get) are dropped with their files, then the
-- state's frames are written: a whole step or none, whatever the moment
-- of a Ctrl-C.
recordReplayStateWith :: ReplayRecorder -> Maybe BC.ByteString -> WorldState -> IO ()
recordReplayStateWith (ReplayRecorder cfg _ strideAt ref) made s = do
  Recording rates levels step <- readIORef ref
  let t = wsTime s
      (gone, live) = span ((< strideAt t) . lvStride) levels
      kept | null gone = rates
           | otherwise = logRatesKeep (\b -> any ((== b) . lvBit) live) rates
      (rates', frames) = logRatesStep cfg kept s
  lns <- mapM (\(bits, f) -> (,) bits <$> case made of
                 Just l | 0 `elem` bits -> pure l   -- (bit 0: every frame period, the log's)
                 _                      -> evaluate (encodeLogLineBytes (LineFrame f))) frames
  let live' = foldl' (\lvs ln -> map (spooled ln) lvs) live lns
  -- (the lines, then the new state, then the files outgrown: a write that
  -- fails leaves the recording as it was before the step)
  uninterruptibleMask_ $ do
    mapM_ (\(bits, l) -> mapM_ (\lv -> writeTagged (lvHandle lv) step bits l) (holder bits live)) lns
    forceLevels live' `seq` writeIORef ref (Recording rates' live' (step + 1))
    mapM_ closeLevel gone
  where
    -- (the file of a line: its coarsest stride's)
    holder bits lvs = take 1 [ lv | lv <- lvs, lvBit lv == maximum bits ]
    spooled (bits, l) lv =
      let lv1 = if lvBit lv == maximum bits then lv { lvLines = lvLines lv + 1 } else lv
      in if lvBit lv `elem` bits then lv1 { lvFrames = lvFrames lv1 + 1, lvHash = fnvBytes (lvHash lv1) l } else lv1
    forceLevels = foldr seq ()

-- A frame line in a temporary file: its step, its strides' bits and the
-- line, on one line.
writeTagged :: Handle -> Int -> [Int] -> BC.ByteString -> IO ()
writeTagged h step bits l = do
  BC.hPut h (BC.pack (shows step (' ' : shows (foldl' setBit (0 :: Int) bits) " ")))
  BC.hPutStrLn h l

-- A line of a temporary file taken apart: its step, its strides' bits and
-- the frame's line.
untag :: BC.ByteString -> Maybe (Int, Int, BC.ByteString)
untag raw = do
  (step, r1) <- BC.readInt raw
  (bits, r2) <- BC.readInt (BC.drop 1 r1)
  pure (step, bits, BC.drop 1 r2)

-- A stride's temporary file closed (and removed).
closeLevel :: Level -> IO ()
closeLevel lv = closeSpool (lvLeft lv) (lvHandle lv)

-- | One frame period in how many the page 'writeReplay' writes with this
-- summary keeps: the planned stride when the summary says that the run
-- went its planned length (neither 'lsInterrupted' nor a 'lsFailure');
-- else the stride of a run planned for the time of the last state
-- recorded (within a factor 2: see 'ReplayRecorder').
replayPageStride :: ReplayRecorder -> LogSummary -> IO Int
replayPageStride r s = maybe 1 lvStride <$> pageLevel r s

-- The stride of the page of a summary ('replayPageStride'), if it is
-- still recorded (it is, until 'writeReplay' or 'discardReplay').
pageLevel :: ReplayRecorder -> LogSummary -> IO (Maybe Level)
pageLevel (ReplayRecorder _ planned _ ref) s = do
  Recording _ levels _ <- readIORef ref
  pure $ if not (lsInterrupted s) && isNothing (lsFailure s)
           then find ((== planned) . lvStride) levels
           else listToMaybe levels

-- | How many frame lines the recorder's temporary files hold now: those of
-- the strides the page may still get (see 'ReplayRecorder': at most
-- about three pages' worth).
replaySpooled :: ReplayRecorder -> IO Int
replaySpooled (ReplayRecorder _ _ _ ref) = do
  Recording _ levels _ <- readIORef ref
  pure (sum (map lvLines levels))

-- | Write the page of the run recorded so far, with its summary
-- ('lsFrames' is the page's count of frames when it is negative), and
-- close the recorder's temporary files (also when the page cannot be
-- written). Call it once, at the end of the run.
--
-- A run that went its planned length (the summary says it was neither
-- interrupted nor failed) gets one frame period in the planned stride: the
-- page of a recorder that took only those frames, byte for byte, as
-- before. One that
-- stopped early gets the page of a run planned for the time it stopped,
-- within a factor 2 ('replayPageStride', 'ReplayRecorder'): the page of
-- its states thinned by that frame rate, its header's @fps@ the page's.
-- Either way its steps after its last kept frame show in no frame, as in
-- the log (a frame is written at its step).
writeReplay :: ReplayRecorder -> LogSummary -> FilePath -> IO ()
writeReplay = writeReplayChunked replayChunkChars

-- | 'writeReplay' with the log's lines in data elements of at most @n@
-- characters each, as 'replayPageChunked' writes them.
writeReplayChunked :: Int -> ReplayRecorder -> LogSummary -> FilePath -> IO ()
writeReplayChunked chunk r@(ReplayRecorder cfg _ _ ref) s out =
  (do Recording _ levels _ <- readIORef ref
      mlv <- pageLevel r s
      case mlv of
        Nothing -> ioError (userError "the replay's recording was closed before its page was written")
        Just lv -> do
          let s'      = if lsFrames s < 0 then s { lsFrames = lvFrames lv } else s
              summary = encodeLogLineBytes (LineSummary s')
              -- (the files that hold its lines: its own and the coarser strides')
              files   = [ l | l <- levels, lvStride l >= lvStride lv ]
          mapM_ (rewind . lvHandle) files
          next <- strideLines (lvBit lv) files
          writePageFrom chunk (headerAt cfg (lvStride lv)) next (Just summary) (fnvBytes (lvHash lv) summary) out)
  `finally` discardReplay r

-- A temporary file's next line of a stride, read: its step, the line, the
-- file and how many of its lines are left to read.
data Next = Next !Int BC.ByteString Handle !Int

-- @strideLines b files@: the frame lines of the stride of bit @b@, one
-- at a time, in step order, from its temporary files (rewound), each read
-- up to its count of lines (a line of a write that failed is not one).
strideLines :: Int -> [Level] -> IO (IO (Maybe BC.ByteString))
strideLines b files = do
  firsts <- mapM (\lv -> readNext (lvHandle lv) (lvLines lv)) files
  cur <- newIORef (catMaybes firsts)
  pure $ do
    pending <- readIORef cur
    case earliest pending of
      Nothing -> pure Nothing
      Just (Next _ l h left, others) -> do
        after <- readNext h left
        writeIORef cur (maybe others (: others) after)
        pure (Just l)
  where
    readNext h left
      | left <= 0 = pure Nothing
      | otherwise = do
          raw <- BC.hGetLine h
          case untag raw of
            Just (step, bits, l) | testBit bits b -> pure (Just (Next step l h (left - 1)))
                                 | otherwise      -> readNext h (left - 1)
            Nothing -> ioError (userError "a damaged line in the replay's temporary file")
    earliest [] = Nothing
    earliest (x : xs) = Just (go x [] xs)
      where
        go best acc [] = (best, acc)
        go best@(Next sb _ _ _) acc (y@(Next sy _ _ _) : ys)
          | sy < sb   = go y (best : acc) ys
          | otherwise = go best (y : acc) ys

-- @writePage chunk header frames summary hash out@ writes the page of a
-- log whose header line is @header@, whose frames' lines are what is left
-- to read of the handle @frames@ and whose summary line, if any, is @summary@, with the
-- nonce of @hash@ (all its lines' 'fnvBytes'), the lines in data elements
-- of at most @chunk@ characters (as 'joinChunked' joins them): the page of
-- 'replayPageChunked', streamed (whole or not at all: 'writeWhole').
writePage :: Int -> BC.ByteString -> Handle -> Maybe BC.ByteString -> Word64 -> FilePath -> IO ()
writePage chunk header fh = writePageFrom chunk header (hIsEOF fh >>= \eof -> if eof then pure Nothing else Just <$> BC.hGetLine fh)

-- 'writePage' with the frames' lines given one at a time by an action
-- ('Nothing' after the last).
writePageFrom :: Int -> BC.ByteString -> IO (Maybe BC.ByteString) -> Maybe BC.ByteString -> Word64 -> FilePath -> IO ()
writePageFrom chunk header nextFrame summary hash out =
    writeWhole out $ \whole -> withBinaryFile whole WriteMode $ \oh -> do
      hSetBuffering oh (BlockBuffering Nothing)
      let (pre, post) = replayPageParts (showHex hash "")
          -- a line after the others, as 'joinChunked' joins them
          next at l = case placeLine chunk at (BC.length l) of
            (before, at') -> at' <$ (BC.hPutStr oh (BC.pack before) >> BC.hPutStr oh l)
          copy at = nextFrame >>= maybe (pure at) (\l -> next at l >>= copy)
      BC.hPutStr oh (BC.pack pre)
      BC.hPutStr oh header
      at <- copy (1 :: Int, BC.length header)
      mapM_ (next at) summary
      BC.hPutStr oh (BC.pack post)

-- | Throw a recording away: close its temporary files (and remove them,
-- where the system kept them in their folder), writing no page. For a run
-- that stops with an exception before its page is written; harmless after
-- 'writeReplay', and when called twice.
discardReplay :: ReplayRecorder -> IO ()
discardReplay (ReplayRecorder _ _ _ ref) = readIORef ref >>= \(Recording _ levels _) -> mapM_ closeLevel levels

-- The frames' temporary file ('openSpool') closed, and removed if the
-- system kept it in its folder; quietly, and harmless when done twice.
closeSpool :: Maybe FilePath -> Handle -> IO ()
closeSpool left h = (hClose h `catch` \e -> const (pure ()) (e :: IOException)) >> mapM_ removeIfExists left

-- A temporary file removed, if it is still there.
removeIfExists :: FilePath -> IO ()
removeIfExists p = removeFile p `catch` \e -> const (pure ()) (e :: IOException)
