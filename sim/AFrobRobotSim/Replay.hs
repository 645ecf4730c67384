{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Replay
-- Description : A self-contained HTML page that replays a run log.
--
-- One HTML file holds the log, the script and the style: it needs no
-- network and no server, and opens from @file://@. The log goes in as
-- JSON inside a @\<script type="application/json"\>@ element, which the
-- browser does not run; 'AFrobRobotSim.JSON.encodeJSON' writes no @<@,
-- @>@ or @&@, so no string of the run (a robot's message, the command
-- line) can end that element or become markup, and the script shows
-- every such string with @textContent@. A Content-Security-Policy allows
-- only the page's own script (by a nonce), its own style and no network,
-- so that even markup that got in could run nothing.
--
-- The page draws the world like the frames ("AFrobRobotSim.Render":
-- same colours, shapes and robot shades), and has play/pause (space),
-- one frame back and forth (arrow keys), a time slider, a speed, toggles
-- for range rays, trails and tracker sightings, and a panel with the
-- readings, wheel speeds and messages of the robot last clicked.
--
-- For tests and tools the page exposes @window.afrpReplay@: @frameCount()@,
-- @frame()@, @frameData(i)@, @setFrame(i)@, @play()@, @pause()@,
-- @playing()@, @selectRobot(i)@, @selected()@, @worldToCanvas(x, y)@ (in
-- the canvas's pixels), @header@ and @summary@. Element ids: @world@
-- (the canvas), @play@, @back@, @fwd@, @slider@, @speed@, @rays@,
-- @trails@, @sightings@, @time@, @info@, @events@, @meta@, @afrp-log@.
module AFrobRobotSim.Replay
  ( -- * Pages
    replayPage
  , replayPageFromLines
  , writeReplayFromLog
    -- * Recording a run as it goes
  , ReplayRecorder
  , newReplayRecorder
  , recordReplayState
  , writeReplay
  ) where

import qualified Data.ByteString.Char8     as BC
import           Data.Bits                 (xor)
import           Data.Char                 (ord)
import           Data.IORef
import           Data.List                 (foldl', intercalate)
import           Data.Word                 (Word64)
import           Numeric                   (showHex)
import           System.IO

import           AFrobRobotSim.Log
import           AFrobRobotSim.Replay.Assets
import           AFrobRobotSim.Simulator   (WorldState)

-- | The page of a log.
replayPage :: RunLog -> String
replayPage l = replayPageFromLines (map encodeLogLine (LineHeader (rlHeader l) : map LineFrame (rlFrames l)
                                                      ++ maybe [] ((: []) . LineSummary) (rlSummary l)))

-- | The page of a log given as its lines' JSON texts (as 'encodeLogLine'
-- writes them: a header first). The lines are embedded as they are, so
-- they must come from 'encodeLogLine' (which writes no @<@).
replayPageFromLines :: [String] -> String
replayPageFromLines ls = concat
  [ "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
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
  , "<label><input id=\"rays\" type=\"checkbox\" checked> range rays</label>\n"
  , "<label><input id=\"trails\" type=\"checkbox\" checked> trails</label>\n"
  , "<label><input id=\"sightings\" type=\"checkbox\"> tracker sightings</label>\n"
  , "</div>\n</div>\n<div id=\"side\">\n<pre id=\"info\"></pre>\n<h1>events</h1>\n<pre id=\"events\"></pre>\n"
  , "</div>\n</div>\n"
  , "<script id=\"afrp-log\" type=\"application/json\">\n[", intercalate ",\n" ls, "]\n</script>\n"
  , "<script nonce=\"", nonce, "\">\n", replayScript, "</script>\n</body>\n</html>\n" ]
  where
    -- a nonce that depends on the page's data (FNV-1a), so pages differ
    nonce = showHex (foldl' (\h c -> (h `xor` fromIntegral (ord c)) * 1099511628211)
                            (14695981039346656037 :: Word64) (concat ls)) ""

-- | Read a log file and write its page: what @simbot --replay-from
-- FILE.jsonl --replay OUT.html@ does. A log that does not read is a
-- 'Left' with the reader's message (nothing is written then).
writeReplayFromLog :: FilePath -> FilePath -> IO (Either String ())
writeReplayFromLog logPath out = do
  r <- readLogFile logPath
  case r of
    Left e  -> pure (Left e)
    Right l -> Right <$> writeAscii out (replayPage l)

-- | A page being recorded as a run goes: it keeps each frame's line,
-- encoded at once (so no state of the simulation is held), and writes the
-- page at the end.
data ReplayRecorder = ReplayRecorder LogConfig (IORef (LogState, [BC.ByteString]))

-- | Start recording a run.
newReplayRecorder :: LogConfig -> IO ReplayRecorder
newReplayRecorder cfg = ReplayRecorder cfg <$> newIORef (logStart cfg, [])

-- | Give the recorder the next step's state (every step, the first at
-- time 0).
recordReplayState :: ReplayRecorder -> WorldState -> IO ()
recordReplayState (ReplayRecorder cfg ref) s = do
  (st, acc) <- readIORef ref
  case logStep cfg st s of
    (st', Just f)  -> let !line = BC.pack (encodeLogLine (LineFrame f))
                      in writeIORef ref (st', line : acc)
    (st', Nothing) -> st' `seq` writeIORef ref (st', acc)

-- | Write the page of the run recorded so far, with its summary
-- ('lsFrames' is the recorder's count when it is negative).
writeReplay :: ReplayRecorder -> LogSummary -> FilePath -> IO ()
writeReplay (ReplayRecorder cfg ref) s out = do
  (_, acc) <- readIORef ref
  let s' = if lsFrames s < 0 then s { lsFrames = length acc } else s
  writeAscii out (replayPageFromLines (encodeLogLine (LineHeader (logHeader cfg))
                                       : map BC.unpack (reverse acc)
                                       ++ [encodeLogLine (LineSummary s')]))

-- The page is ASCII (the encoder escapes everything else, the assets are
-- ASCII), written as UTF-8 whatever the locale.
writeAscii :: FilePath -> String -> IO ()
writeAscii path txt = withFile path WriteMode (\h -> hSetEncoding h utf8 >> hPutStr h txt)
