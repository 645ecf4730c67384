{-# LANGUAGE MultiWayIf #-}
{-# LANGUAGE CPP #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.OutputFile
-- Description : An output file written whole or not at all.
--
-- The runner writes its picture, replay page and result line at the end
-- of a run, when a second Ctrl-C, a full disk or a crash can stop it half
-- way. Written in place, such a file would be left cut short, and the
-- good file of an earlier run at that path would be gone. 'writeWhole'
-- writes a regular file (or a new one) beside its final place and renames
-- it there once it is complete, so the path holds the old file or the new
-- one, never a part (an error names the path, not the temporary file).
--
-- Written in place, as before: a path that names something else than a
-- regular file (a terminal, @\/dev\/stdout@, @\/dev\/full@, a pipe, a
-- process substitution's @\/dev\/fd\/N@), where there is nothing to keep
-- and no file to rename over; a file in a folder this program may not
-- write to (the file itself writable), where no file can be made beside
-- it; and every path on Windows. A file replaced keeps its permissions
-- (and, where this program may set them, its owner and group); another
-- hard link to the old file keeps the old contents.
module AFrobRobotSim.OutputFile
  ( writeWhole
  , fileIdentity
  , notAFolder
  ) where

import           System.Directory  (doesDirectoryExist, doesPathExist)

#if !defined(mingw32_HOST_OS)
import           Control.Exception (IOException, catch, onException, try)
import           System.Directory  (canonicalizePath, getPermissions, removeFile, renameFile, writable)
import           System.FilePath   (takeDirectory, takeFileName, (</>))
import           System.IO.Error   (ioeSetFileName)
import           System.Posix.Files (FileStatus, deviceID, fileGroup, fileID, fileMode, fileOwner, getFileStatus,
                                     isRegularFile, setFileMode, setOwnerAndGroup)
import           System.Posix.Process (getProcessID)
#endif

-- | @writeWhole path write@ runs @write@ on a path where it writes the
-- whole file. For a regular file, or a path where nothing is yet, in a
-- folder this program may write to, that is a temporary file in the same
-- folder (named after the file and this process), renamed to @path@ (a
-- symbolic link's target, when @path@ is one) once @write@ has returned;
-- if @write@ throws, the temporary file is removed and @path@ is as it
-- was. Otherwise (see the module's documentation) @write@ is given @path@
-- itself. What @write@ or the rename throws is thrown on.
writeWhole :: FilePath -> (FilePath -> IO ()) -> IO ()
#if !defined(mingw32_HOST_OS)
writeWhole path write = do
  -- (the status of what the path names, links followed: a pipe behind
  -- /dev/stdout is not a path canonicalizePath can give)
  status <- try (getFileStatus path)
  case status of
    Right st | not (isRegularFile st) -> write path
    _ -> do
      real <- canonicalizePath path
      folderOk <- either (\(_ :: IOException) -> False) writable <$> try (getPermissions (takeDirectory real))
      if not folderOk then write path else do
        tmp <- temporaryFor real
        let old = either (\(_ :: IOException) -> Nothing) Just status
        ((write tmp >> keepAttributes old tmp >> renameFile tmp real) `onException` removeQuietly tmp)
          `catch` \(e :: IOException) -> ioError (ioeSetFileName e path)
  where
    removeQuietly f = removeFile f `catch` \(_ :: IOException) -> pure ()

-- The old file's permissions, owner and group on its replacement (what
-- this program may not set is left as it is).
keepAttributes :: Maybe FileStatus -> FilePath -> IO ()
keepAttributes old tmp = case old of
  Nothing -> pure ()
  Just st -> do
    quietly (setFileMode tmp (fileMode st))
    quietly (setOwnerAndGroup tmp (fileOwner st) (fileGroup st))
  where
    quietly act = act `catch` \(_ :: IOException) -> pure ()

-- A temporary file's name beside a file: hidden, with this process's
-- number, so that two programs writing the same file do not share it.
temporaryFor :: FilePath -> IO FilePath
temporaryFor real = do
  pid <- show <$> getProcessID
  pure (takeDirectory real </> ("." ++ takeFileName real ++ ".afrp-" ++ pid ++ ".tmp"))
#else
writeWhole path write = write path
#endif

-- | Which file a path names, links followed: its device and file number,
-- the same for every name of one file (a hard link too, which no
-- comparison of paths can tell); 'Nothing' when there is no file there
-- yet, when it cannot be read, and on Windows.
fileIdentity :: FilePath -> IO (Maybe (Integer, Integer))
#if !defined(mingw32_HOST_OS)
fileIdentity path = either (\(_ :: IOException) -> Nothing) (\st -> Just (key st)) <$> try (getFileStatus path)
  where
    key st = (fromIntegral (deviceID st), fromIntegral (fileID st))
#else
fileIdentity _ = pure Nothing
#endif

-- | Why files cannot be written into a path taken as a folder, in words
-- that follow its name: @Just \"does not exist\"@, @Just \"is not a
-- folder\"@ (a file is there), or 'Nothing' for a folder.
notAFolder :: FilePath -> IO (Maybe String)
notAFolder dir = do
  isFolder <- doesDirectoryExist dir
  taken <- doesPathExist dir
  pure $ if | isFolder  -> Nothing
            | taken     -> Just "is not a folder"
            | otherwise -> Just "does not exist"
