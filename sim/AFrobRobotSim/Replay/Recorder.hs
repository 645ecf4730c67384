{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Replay.Recorder
-- Description : A run's replay page, recorded as the run goes and thinned for its length.
--
-- The recorder takes a run's states one step at a time and keeps, in
-- temporary files ("AFrobRobotSim.Replay.Spool"), what the page of the
-- run will need, however long the run turns out to be; at the end it
-- writes the page ("AFrobRobotSim.Replay.Page") of the thinning the run's
-- length calls for. How many frames a page keeps ('replayFrameStep') is
-- decided here too. The page itself is described in "AFrobRobotSim.Replay",
-- which re-exports this module.
module AFrobRobotSim.Replay.Recorder
  ( -- * How many frames a run's page keeps
    replayFrameStep
  , replayMaxFrames
  , replayMaxRobotFrames
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
import           Data.Bits                 (setBit, testBit)
import           Data.IORef
import           Data.List                 (find, foldl')
import           Data.Maybe                (catMaybes, fromMaybe, isNothing, listToMaybe)
import           Data.Word                 (Word64)
import           Control.Exception         (evaluate, finally, uninterruptibleMask_)
import           System.Directory          (getTemporaryDirectory)
import           System.IO

import           AFrobRobotSim.Log
import           AFrobRobotSim.Replay.Page
import           AFrobRobotSim.Replay.Spool
import           AFrobRobotSim.Simulator   (WorldState (..))
import           AFrobRobotSim.World       (robotKindOf)

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

-- | Throw a recording away: close its temporary files (and remove them,
-- where the system kept them in their folder), writing no page. For a run
-- that stops with an exception before its page is written; harmless after
-- 'writeReplay', and when called twice.
discardReplay :: ReplayRecorder -> IO ()
discardReplay (ReplayRecorder _ _ _ ref) = readIORef ref >>= \(Recording _ levels _) -> mapM_ closeLevel levels

