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
-- A path that names something else than a regular
-- file (a terminal, @\/dev\/stdout@, @\/dev\/full@, a pipe) is written in
-- place, as before: there is nothing to keep, and no file to rename over.
module AFrobRobotSim.OutputFile
  ( writeWhole
  ) where

import           Control.Exception (IOException, catch, onException)
import           System.Directory  (canonicalizePath, doesPathExist, removeFile, renameFile)
import           System.FilePath   (takeDirectory, takeFileName, (</>))
import           System.IO.Error   (ioeSetFileName)
#if !defined(mingw32_HOST_OS)
import           System.Posix.Files (getFileStatus, isRegularFile)
import           System.Posix.Process (getProcessID)
#endif

-- | @writeWhole path write@ runs @write@ on a path where it writes the
-- whole file. For a regular file, or a path where nothing is yet, that is
-- a temporary file in the same folder (named after the file and this
-- process), renamed to @path@ (a symbolic link's target, when @path@ is
-- one) once @write@ has returned; if @write@ throws, the temporary file is
-- removed and @path@ is as it was. Any other existing path is given to
-- @write@ itself. What @write@ or the rename throws is thrown on.
writeWhole :: FilePath -> (FilePath -> IO ()) -> IO ()
writeWhole path write = do
  real <- canonicalizePath path
  exists <- doesPathExist real
  regular <- if exists then isRegular real else pure True
  if not regular then write path else do
    tmp <- temporaryFor real
    ((write tmp >> renameFile tmp real) `onException` removeQuietly tmp)
      `catch` \(e :: IOException) -> ioError (ioeSetFileName e path)
  where
    removeQuietly f = removeFile f `catch` \(_ :: IOException) -> pure ()

-- Whether an existing path is a regular file.
isRegular :: FilePath -> IO Bool
#if !defined(mingw32_HOST_OS)
isRegular p = isRegularFile <$> getFileStatus p
#else
isRegular _ = pure True
#endif

-- A temporary file's name beside a file: hidden, with this process's
-- number, so that two programs writing the same file do not share it.
temporaryFor :: FilePath -> IO FilePath
temporaryFor real = do
#if !defined(mingw32_HOST_OS)
  pid <- show <$> getProcessID
#else
  let pid = "0"
#endif
  pure (takeDirectory real </> ("." ++ takeFileName real ++ ".afrp-" ++ pid ++ ".tmp"))
