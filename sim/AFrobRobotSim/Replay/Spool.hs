-- |
-- Module      : AFrobRobotSim.Replay.Spool
-- Description : The replay page's temporary files, gone from their folder at once.
--
-- A page is written from lines kept in temporary files as they are made
-- (a run's recorder, "AFrobRobotSim.Replay.Recorder"; a log file's page,
-- 'AFrobRobotSim.Replay.writeReplayFromLog'), so that making it holds
-- one line in memory at a time. Each file is removed from its folder as
-- soon as it is made and lives on through its handle, so that a process
-- that is killed (@SIGKILL@) leaves nothing behind; where the system
-- will not remove an open file, it is removed when it is closed.
module AFrobRobotSim.Replay.Spool
  ( openSpool
  , openSpools
  , rewind
  , closeSpool
  ) where

import           Control.Exception         (IOException, catch, mask_, onException, try)
import           System.Directory          (removeFile)
import           System.IO

-- | @k@ temporary files ('openSpool'), all or none.
openSpools :: FilePath -> Int -> IO [(Maybe FilePath, Handle)]
openSpools tmp k0 = mask_ (go k0 [])
  where
    go k acc
      | k <= 0    = pure (reverse acc)
      | otherwise = do
          sp <- openSpool tmp `onException` mapM_ (uncurry closeSpool) acc
          go (k - 1) (sp : acc)

-- | A temporary file, made in the folder given, open for
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

-- | A temporary file written: read it from its start (what was
-- buffered is written first).
rewind :: Handle -> IO ()
rewind h = hFlush h >> hSeek h AbsoluteSeek 0

-- | A temporary file ('openSpool') closed, and removed if the
-- system kept it in its folder; quietly, and harmless when done twice.
closeSpool :: Maybe FilePath -> Handle -> IO ()
closeSpool left h = (hClose h `catch` \e -> const (pure ()) (e :: IOException)) >> mapM_ removeIfExists left

-- A temporary file removed, if it is still there.
removeIfExists :: FilePath -> IO ()
removeIfExists p = removeFile p `catch` \e -> const (pure ()) (e :: IOException)

