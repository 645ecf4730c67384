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

import qualified Data.ByteString           as BS
import qualified Data.ByteString.Builder   as B
import qualified Data.ByteString.Char8     as BC
import           Data.Bits                 (setBit, shiftL, testBit, (.|.))
import           Data.IORef
import           Data.List                 (find, foldl')
import           Data.Maybe                (catMaybes, fromMaybe, isNothing, listToMaybe)
import           Data.Word                 (Word64)
import           Control.Exception         (bracket, evaluate, finally, uninterruptibleMask_)
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
-- turns out to have. Each frame is appended at once to a temporary file
-- (in the system's temporary folder), as its line or as its capture (see
-- the price, below), so recording holds neither the simulation's states
-- nor the frames: memory stays constant however long the run.
-- 'writeReplay' streams the lines of the page into it. The files are removed from their folder as soon as they are made
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
-- is captured or made once for them all. (A line for each stride rather than one
-- for the finest, merged at the end: a merge would parse each kept frame
-- again and write it anew, at the cost of a frame's making, and only as
-- exact as a number's text reads back.)
--
-- Each frame goes to the temporary file of the coarsest stride it serves,
-- tagged with its step and its strides, and a stride's file is closed,
-- and so removed, once the run has outgrown it (a stop would get a
-- coarser stride). A stride @d@'s file holds at most one frame for each of
-- its frames so far; the strides alive at a time are @d@, @2 d@, ... and
-- @S@, where @d@'s frames are within the page's bounds; so the files hold
-- at most about three pages' worth of frames (@d@'s, half as many for
-- @2 d@, a quarter for @4 d@, ..., and @S@'s), in frames and in
-- robot-frames (tested: at most three pages of frames and a line for each
-- stride). Why not the divisors of @S@: a chain of them (9 gives 1,
-- 3, 9) leaves a stop where 4 would do with 9; powers of 2 keep the
-- factor 2, and need not divide @S@ since each stride is kept whole on
-- its own. Why a file for each stride rather than one: a stride the run
-- has outgrown leaves with its file, where one file would keep about a
-- page's worth of such frames for each doubling of the run's length.
--
-- The price, and how it is kept down: the frames of the planned stride
-- are made (sensed and encoded) as the run goes, as a recorder of that
-- stride alone made them; those of the finer strides, which a run that
-- goes its length never shows, are only captured
-- ('AFrobRobotSim.Log.logRatesStepPending': the values of the state that
-- their frames need, a few dozen bytes a robot, without the sensing) and
-- made when their page is written, only those of the page written. A
-- step that is a frame of several strides whose periods differ (a message
-- or an event came between) is captured or made once for each. A 1-hour
-- run of the default world (@S = 10@) captures the frames of 27,901 steps
-- for its page of 9001 (a 10-hour run, 43,921); making them all, as the
-- recorder did at first, took 9.98 s against 7.89 s for a recorder of the
-- planned stride alone (MUT, a quiet machine); capturing them takes 0.91
-- of the time of making them all (the median of five alternating pairs
-- on a loaded machine, 0.83-0.95: 10.8-13.1 s against 11.8-14.4 s). The
-- 200-robot world at 100 frames a second for 70 s (@S = 2@, where nearly
-- every frame period is a frame of a finer stride) took 16.75 s against
-- 10.19 s making them all; capturing them takes 0.76 of that time (0.74-0.81:
-- 11.5-18.2 s against 15.5-22.8 s). A run that stops early
-- pays for its page's frames when the page is written, as many as a run
-- planned for that length made as it went, and writes its lines to one
-- more temporary file, for the nonce that comes before them.
data ReplayRecorder = ReplayRecorder LogConfig !Int !Int (Double -> Int) (PendingFrame -> LogFrame) (IORef Recording)
  -- (the frames at every frame period; the planned stride and its bit; the
  -- stride of a page of a run that stops at a time; the maker of the
  -- frames captured; what is recorded)

-- What the recorder carries from step to step: each live stride's
-- periods ('LogRates', keyed by the stride's bit), the live strides,
-- finest first (the first is the stride of a stop now), and the steps
-- taken.
data Recording = Recording !(LogRates Int) [Level] !Int

-- A stride the page may still be thinned to, and its temporary file,
-- which holds the frames whose coarsest stride it is.
data Level = Level
  { lvStride :: !Int
  , lvBit    :: !Int            -- its bit in the tag of a frame (from 0, the finest)
  , lvLeft   :: Maybe FilePath  -- its file's path, if the system kept it in its folder
  , lvHandle :: Handle
  , lvLines  :: !Int            -- the frames its file holds
  , lvFrames :: !Int            -- the frames of its page so far
  , lvHash   :: !Word64         -- the nonce hash of its page's lines so far (its header's first), while 'lvMade'
  , lvMade   :: !Bool           -- whether every frame of its page so far is made (none only captured)
  }

-- A frame in a temporary file: its line, or its capture ('encodePending').
data Spooled = Made BC.ByteString | Captured BS.ByteString

-- | Start recording a run of the given plan, whose frame periods are the
-- config's ('lcFps': the page's frame rate is that divided by its stride):
-- makes the temporary files, one for each stride the page may get (1, 2,
-- 4, ... below the planned stride, and that). With 'replayEveryFrame',
-- one, and the page keeps every frame period.
newReplayRecorder :: ReplayPlan -> LogConfig -> IO ReplayRecorder
newReplayRecorder plan cfg = do
  tmp <- getTemporaryDirectory
  spools <- openSpools tmp (length strides)
  let levels = [ Level d b left h 0 0 (fnvBytes fnvBasis (headerAt cfg d)) True
               | (b, d, (left, h)) <- zip3 [0 ..] strides spools ]
      rates  = logRatesStart cfg [ (b, lcFps cfg / fromIntegral d) | (b, d) <- zip [0 ..] strides ]
  ReplayRecorder cfg planned (length strides - 1) strideAt (pendingFrameMaker cfg)
    <$> newIORef (Recording rates levels 0)
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
-- keep them all). The recorder then keeps that line instead of making
-- that frame again (at 1000 robots a frame's encoding costs several times
-- the step it shows); the page is the same. With 'Nothing', or at a step
-- that is not a frame's, it is 'recordReplayState'.
--
-- At each step the strides the run has outgrown (finer than a stop at
-- this state's time would get) are dropped with their files, then the
-- state's frames are written: a whole step or none, whatever the moment
-- of a Ctrl-C.
recordReplayStateWith :: ReplayRecorder -> Maybe BC.ByteString -> WorldState -> IO ()
recordReplayStateWith (ReplayRecorder cfg _ top strideAt maker ref) made s = do
  Recording rates levels step <- readIORef ref
  let t = wsTime s
      (gone, live) = span ((< strideAt t) . lvStride) levels
      kept | null gone = rates
           | otherwise = logRatesKeep (\b -> any ((== b) . lvBit) live) rates
      (rates', frames) = logRatesStepPending cfg kept s
  recs <- mapM (\(bits, p) -> (,) bits <$> case made of
                  Just l | 0 `elem` bits -> pure (Made l)   -- (bit 0: every frame period, the log's)
                  _ | top `elem` bits -> Made <$> evaluate (encodeLogLineBytes (LineFrame (maker p)))
                    | otherwise       -> Captured <$> evaluate (encodePending p)) frames
  let live' = foldl' (\lvs rc -> map (spooled rc) lvs) live recs
  -- (the frames, then the new state, then the files outgrown: a write that
  -- fails leaves the recording as it was before the step)
  uninterruptibleMask_ $ do
    mapM_ (\(bits, rc) -> mapM_ (\lv -> writeSpooled (lvHandle lv) step bits rc) (holder bits live)) recs
    forceLevels live' `seq` writeIORef ref (Recording rates' live' (step + 1))
    mapM_ closeLevel gone
  where
    -- (the file of a frame: its coarsest stride's)
    holder bits lvs = take 1 [ lv | lv <- lvs, lvBit lv == maximum bits ]
    spooled (bits, rc) lv =
      let lv1 = if lvBit lv == maximum bits then lv { lvLines = lvLines lv + 1 } else lv
      in if lvBit lv `notElem` bits then lv1 else case rc of
           Made l     -> lv1 { lvFrames = lvFrames lv1 + 1, lvHash = fnvBytes (lvHash lv1) l }
           Captured _ -> lv1 { lvFrames = lvFrames lv1 + 1, lvMade = False }
    forceLevels = foldr seq ()

-- A frame in a temporary file: its size, its step, its strides' bits, a
-- byte saying whether it is a line (1) or a capture (0), and its bytes.
writeSpooled :: Handle -> Int -> [Int] -> Spooled -> IO ()
writeSpooled h step bits rc = B.hPutBuilder h $
  B.int64LE (fromIntegral (BS.length bytes)) <> B.int64LE (fromIntegral step)
  <> B.int64LE (fromIntegral (foldl' setBit (0 :: Int) bits)) <> B.word8 tag <> B.byteString bytes
  where
    (tag, bytes) = case rc of
      Made l     -> (1, l)
      Captured c -> (0, c)

-- The next frame of a temporary file: its step, its strides' bits and
-- the frame ('Nothing' for a file cut short or damaged).
readSpooled :: Handle -> IO (Maybe (Int, Int, Spooled))
readSpooled h = do
  hd <- BS.hGet h 25
  if BS.length hd /= 25 then pure Nothing else do
    let word i = foldr (\j acc -> (acc `shiftL` 8) .|. fromIntegral (BS.index hd (i + j))) (0 :: Int) [0 .. 7]
        size = word 0
    bytes <- if size < 0 then pure BS.empty else BS.hGet h size
    pure $ if size < 0 || BS.length bytes /= size then Nothing else case BS.index hd 24 of
      1 -> Just (word 8, word 16, Made bytes)
      0 -> Just (word 8, word 16, Captured bytes)
      _ -> Nothing

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
pageLevel (ReplayRecorder _ planned _ _ _ ref) s = do
  Recording _ levels _ <- readIORef ref
  pure $ if not (lsInterrupted s) && isNothing (lsFailure s)
           then find ((== planned) . lvStride) levels
           else listToMaybe levels

-- | How many frames the recorder's temporary files hold now (lines, or
-- captures of lines not made yet): those of the strides the page may
-- still get (see 'ReplayRecorder': at most about three pages' worth).
replaySpooled :: ReplayRecorder -> IO Int
replaySpooled (ReplayRecorder _ _ _ _ _ ref) = do
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
writeReplayChunked chunk r@(ReplayRecorder cfg _ _ _ maker ref) s out =
  (do Recording _ levels _ <- readIORef ref
      mlv <- pageLevel r s
      case mlv of
        Nothing -> ioError (userError "the replay's recording was closed before its page was written")
        Just lv -> do
          let s'      = if lsFrames s < 0 then s { lsFrames = lvFrames lv } else s
              summary = encodeLogLineBytes (LineSummary s')
              header  = headerAt cfg (lvStride lv)
              -- (the files that hold its frames: its own and the coarser strides')
              files   = [ l | l <- levels, lvStride l >= lvStride lv ]
          mapM_ (rewind . lvHandle) files
          next <- strideFrames (lvBit lv) files
          let nextLine = next >>= traverse lineOf
          if lvMade lv
            then writePageFrom chunk header nextLine (Just summary) (fnvBytes (lvHash lv) summary) out
            else do
              -- (the lines made first, into a temporary file of their own:
              -- the nonce, which comes before them, hashes them all)
              tmp <- getTemporaryDirectory
              bracket (openSpool tmp) (uncurry closeSpool) $ \(_, h) -> do
                let copy !hash = nextLine >>= maybe (pure hash) (\l -> BC.hPutStrLn h l >> copy (fnvBytes hash l))
                hash <- copy (fnvBytes fnvBasis header)
                rewind h
                writePage chunk header h (Just summary) (fnvBytes hash summary) out)
  `finally` discardReplay r
  where
    lineOf (Made l)     = pure l
    lineOf (Captured c) = case decodePending c of
      Just p  -> evaluate (encodeLogLineBytes (LineFrame (maker p)))
      Nothing -> ioError (userError "a damaged frame in the replay's temporary file")

-- A temporary file's next frame of a stride, read: its step, the frame,
-- the file and how many of its frames are left to read.
data Next = Next !Int Spooled Handle !Int

-- @strideFrames b files@: the frames of the stride of bit @b@, one at a
-- time, in step order, from its temporary files (rewound), each read up
-- to its count of frames (a frame of a write that failed is not one).
strideFrames :: Int -> [Level] -> IO (IO (Maybe Spooled))
strideFrames b files = do
  firsts <- mapM (\lv -> readNext (lvHandle lv) (lvLines lv)) files
  cur <- newIORef (catMaybes firsts)
  pure $ do
    pending <- readIORef cur
    case earliest pending of
      Nothing -> pure Nothing
      Just (Next _ f h left, others) -> do
        after <- readNext h left
        writeIORef cur (maybe others (: others) after)
        pure (Just f)
  where
    readNext h left
      | left <= 0 = pure Nothing
      | otherwise = do
          rd <- readSpooled h
          case rd of
            Just (step, bits, f) | testBit bits b -> pure (Just (Next step f h (left - 1)))
                                 | otherwise      -> readNext h (left - 1)
            Nothing -> ioError (userError "a damaged frame in the replay's temporary file")
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
discardReplay (ReplayRecorder _ _ _ _ _ ref) = readIORef ref >>= \(Recording _ levels _) -> mapM_ closeLevel levels
