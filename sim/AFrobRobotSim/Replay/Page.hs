{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Replay.Page
-- Description : The replay page's HTML around a log's lines, made whole or streamed.
--
-- The page itself (what it shows and how it is used: see
-- "AFrobRobotSim.Replay"): its template around the log's lines, the
-- lines in data elements of at most 'replayChunkChars' characters, and
-- the nonce of its Content-Security-Policy, a hash of the lines. Made as
-- a 'String' of a log in memory ('replayPage'), or streamed into a file
-- from lines read one at a time ('writePageFrom'), for a run's recorder
-- ("AFrobRobotSim.Replay.Recorder") and a log file's page
-- ('AFrobRobotSim.Replay.writeReplayFromLog'): the same bytes either way.
module AFrobRobotSim.Replay.Page
  ( -- * Pages
    replayPage
  , replayPageFromLines
  , replayPageChunked
  , replayChunkChars
    -- * Streamed
  , writePage
  , writePageFrom
    -- * The nonce's hash
  , fnvBytes
  , fnvBasis
  ) where

import qualified Data.ByteString.Char8     as BC
import           Data.Bits                 (xor)
import           Data.List                 (foldl')
import           Data.Word                 (Word64, Word8, byteSwap64)
import           Foreign.Storable          (peekByteOff)
import qualified Data.ByteString.Internal  as BU (accursedUnutterablePerformIO)
import qualified Data.ByteString.Unsafe    as BU (unsafeUseAsCStringLen)
import           GHC.ByteOrder             (ByteOrder (..), targetByteOrder)
import           Numeric                   (showHex)
import           System.IO

import           AFrobRobotSim.Log
import           AFrobRobotSim.Replay.Assets
import           AFrobRobotSim.OutputFile  (writeWhole)

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
-- elements holds (see "Long logs" in "AFrobRobotSim.Replay"): 64 MiB, an eighth of what
-- Chromium reads as one string.
replayChunkChars :: Int
replayChunkChars = 64 * 1024 * 1024

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

-- | 'fnv' of a line's bytes (ASCII: the same as of its characters): the
-- hash @h@ so far, then these bytes. A page's nonce is the hex digits
-- of the hash from 'fnvBasis' of its lines, one after the other.
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

-- | The hash of no bytes (FNV-1a's offset basis).
fnvBasis :: Word64
fnvBasis = 14695981039346656037

-- | @writePage chunk header frames summary hash out@ writes the page of a
-- log whose header line is @header@, whose frames' lines are what is left
-- to read of the handle @frames@ and whose summary line, if any, is @summary@, with the
-- nonce of @hash@ (all its lines' 'fnvBytes'), the lines in data elements
-- of at most @chunk@ characters (as 'joinChunked' joins them): the page of
-- 'replayPageChunked', streamed (whole or not at all: 'writeWhole').
writePage :: Int -> BC.ByteString -> Handle -> Maybe BC.ByteString -> Word64 -> FilePath -> IO ()
writePage chunk header fh = writePageFrom chunk header (hIsEOF fh >>= \eof -> if eof then pure Nothing else Just <$> BC.hGetLine fh)

-- | 'writePage' with the frames' lines given one at a time by an action
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
