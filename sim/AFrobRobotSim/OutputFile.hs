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
  , FolderState (..)
  , folderState
  , folderStateText
  , notAFolder
  ) where

#if defined(mingw32_HOST_OS)
import           System.Directory  (doesDirectoryExist, doesPathExist)
#else
import           Control.Exception (IOException, catch, onException, try)
import           Control.Monad     (filterM)
import           Data.Maybe        (listToMaybe)
import           System.Directory  (canonicalizePath, getPermissions, getSymbolicLinkTarget, removeFile, renameFile,
                                    searchable, writable)
import           System.FilePath   (normalise, splitDirectories, takeDirectory, takeFileName, (</>))
import           Foreign.C.Error   (Errno (..), eLOOP, eNOTDIR)
import           GHC.IO.Exception  (IOException (ioe_errno))
import           System.IO.Error   (ioeSetFileName, isDoesNotExistError, isPermissionError)
import           System.Posix.Files (FileStatus, deviceID, fileGroup, fileID, fileMode, fileOwner, getFileStatus,
                                     getSymbolicLinkStatus, isDirectory, isRegularFile, isSymbolicLink, setFileMode,
                                     setOwnerAndGroup)
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

-- | What a path taken as a folder is, symbolic links followed: what
-- @stat@ says, with its failures told apart (nothing there, a folder on
-- the way that may not be searched, a file where a folder on the way
-- would be, a loop of links) and a link to nothing told from nothing.
data FolderState
  = AFolder                       -- ^ a folder (whether it may be written is not asked)
  | NotAFolder                    -- ^ something else: a file, a device
  | NothingThere                  -- ^ nothing, not even a link
  | DanglingLink FilePath         -- ^ a symbolic link (perhaps through others) to nothing: the path not there
  | LinkLoop                      -- ^ a loop of symbolic links (or a chain too long to follow)
  | ThroughAFile (Maybe FilePath) -- ^ a file (not a folder) on its path, or on its links' path: which, when found
  | Unsearchable (Maybe FilePath) -- ^ a folder on its path may not be searched (no x permission): which, when found
  deriving (Eq, Show)

-- | The 'FolderState' of a path. 'Unsearchable' names the first folder
-- of the path (as written) that exists but may not be searched by this
-- process; the path itself, a folder that may not be searched, is
-- 'AFolder' (what is in it cannot be reached, but it is there). On
-- Windows, only 'AFolder', 'NotAFolder' and 'NothingThere'.
folderState :: FilePath -> IO FolderState
#if !defined(mingw32_HOST_OS)
folderState dir = do
  st <- try (getFileStatus dir)
  case st of
    Right s | isDirectory s -> pure AFolder
            | otherwise     -> pure NotAFolder
    Left (e :: IOException)
      | isPermissionError e -> Unsearchable <$> unsearchable
      | ioe_errno e == Just (let Errno c = eLOOP in c) -> pure LinkLoop
      | otherwise -> do
          -- (a link, which stat follows, to nothing: lstat sees it)
          l <- try (getSymbolicLinkStatus dir) :: IO (Either IOException FileStatus)
          let link = case l of
                Right ls -> isSymbolicLink ls
                Left _   -> False
          if | ioe_errno e == Just (let Errno c = eNOTDIR in c) ->
                 -- (a file where a folder of the path, as written or as
                 -- its links lead, would be)
                 (\end -> ThroughAFile <$> firstFile end) =<< (if link then lastTarget (40 :: Int) dir else pure dir)
             | link && isDoesNotExistError e -> DanglingLink <$> lastTarget (40 :: Int) dir
             | link                          -> pure LinkLoop
             | otherwise                     -> pure NothingThere
  where
    -- (the first part of a path that is there and is not a folder)
    firstFile p = listToMaybe <$> filterM isFile (init (scanl1 (</>) (splitDirectories (normalise p))))
    isFile d = either (\(_ :: IOException) -> False) (not . isDirectory) <$> try (getFileStatus d)
    -- (the end of a chain of links: the path that is not there)
    lastTarget k f = do
      t <- try (getSymbolicLinkTarget f)
      case t of
        Left (_ :: IOException) -> pure f
        Right target -> do
          let next = takeDirectory f </> target
          l <- try (getSymbolicLinkStatus next) :: IO (Either IOException FileStatus)
          case l of
            Right ls | isSymbolicLink ls, k > 0 -> lastTarget (k - 1) next
            _                                   -> pure next
    -- (the first folder on the path that is there and may not be searched)
    unsearchable = listToMaybe <$> filterM closed (init (scanl1 (</>) (splitDirectories dir)))
    closed d = do
      s <- try (getFileStatus d) :: IO (Either IOException FileStatus)
      case s of
        Right st' | isDirectory st' ->
          either (\(_ :: IOException) -> False) (not . searchable) <$> try (getPermissions d)
        _ -> pure False
#else
folderState dir = do
  isFolder <- doesDirectoryExist dir
  taken <- doesPathExist dir
  pure $ if | isFolder  -> AFolder
            | taken     -> NotAFolder
            | otherwise -> NothingThere
#endif

-- | Why files cannot be written into a path of this 'FolderState', in
-- words that follow its name, or 'Nothing' for a folder:
--
-- >>> folderStateText NothingThere
-- Just "does not exist"
-- >>> folderStateText (DanglingLink "gone")
-- Just "is a symbolic link to \"gone\", which does not exist"
-- >>> folderStateText (Unsearchable (Just "/srv/locked"))
-- Just "cannot be reached: the folder \"/srv/locked\" on its path may not be searched (no x permission)"
folderStateText :: FolderState -> Maybe String
folderStateText st = case st of
  AFolder        -> Nothing
  NotAFolder     -> Just "is not a folder"
  NothingThere   -> Just "does not exist"
  DanglingLink t -> Just ("is a symbolic link to " ++ show t ++ ", which does not exist")
  LinkLoop       -> Just "is a loop of symbolic links (or a chain too long to follow)"
  ThroughAFile f -> Just ("cannot be reached: " ++ maybe "a part of its path" show f ++ " on its path is not a folder")
  Unsearchable d -> Just ("cannot be reached: " ++ maybe "a folder on its path" (\f -> "the folder " ++ show f ++ " on its path") d
                          ++ " may not be searched (no x permission)")

-- | Why files cannot be written into a path taken as a folder, in words
-- that follow its name ('folderStateText' of its 'folderState'):
-- @Just \"does not exist\"@, @Just \"is not a folder\"@ (a file is
-- there), a link to nothing, a folder on the way that may not be
-- searched, or 'Nothing' for a folder.
notAFolder :: FilePath -> IO (Maybe String)
notAFolder dir = folderStateText <$> folderState dir
