{-# LANGUAGE CPP                 #-}
{-# LANGUAGE MultiWayIf          #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Run.Preflight
-- Description : What a run checks of its options and the file system
--               before it simulates.
--
-- 'AFrobRobotSim.runSim' simulates only when 'preflight' finds nothing
-- wrong: the options together ('validateOptionsIn'), every output's folder
-- (it exists and may be written and searched; through a symbolic link,
-- the target's; what is wrong said as 'folderState' tells it: a folder
-- on the way that may not be searched is not \"does not exist\"),
-- an output named as a folder (@x\/@, @foo\/..@), an output in the
-- kernel's @\/proc@ or @\/sys@ that is no link, device or pipe,
-- two outputs that are one file under two names (a path, a link, a hard
-- link), an output named as the output folder that the run makes, an
-- output that is the world file or that a frame would replace (a name
-- like @frame-000001.ppm@ in the frames' folder), @--video@
-- without ffmpeg, and the output folder, which it creates, proving it
-- writable with a file of a new name that it removes. What is wrong with
-- the output folder that can be told without making it (a file or a link
-- to nothing in its place, a parent not there, a folder on its path that
-- may not be searched, no permission to write) is listed with the other
-- faults.
module AFrobRobotSim.Run.Preflight
  ( preflight
  ) where

import           Control.Exception         (IOException, catch, finally, mask, try)
import           Control.Monad             (forM, unless)
import           Data.List                 (isPrefixOf)
import           Data.Maybe                (catMaybes, fromMaybe, isJust)
import           System.Directory          (createDirectory, doesDirectoryExist, doesFileExist,
                                            findExecutable, getPermissions, getSymbolicLinkTarget,
                                            pathIsSymbolicLink, removeFile, searchable, writable)
import           System.FilePath           (dropTrailingPathSeparator, normalise, takeDirectory, takeFileName, (</>))
import           System.IO                 (hClose, hPutStr, openTempFile)
#if !defined(mingw32_HOST_OS)
import           System.Posix.Files        (FileStatus, getFileStatus, getSymbolicLinkStatus, isCharacterDevice,
                                            isNamedPipe, isSocket, isSymbolicLink)
#endif

import           AFrobRobotSim.Console     (ioErrorText)
import           AFrobRobotSim.Options
import           AFrobRobotSim.OutputFile  (FolderState (..), fileIdentity, folderState, folderStateText, notAFolder)
import           AFrobRobotSim.Run.Sinks   (framePattern, isFrameName)
import           AFrobRobotSim.World       (Bounds)
import           AFrobRobotSim.WorldFile.Lexical (canonicalPath)

-- | Every check of the options and the file system that can be made before
-- simulating, in a world of the given extent; creates the output folder
-- when something goes there (and nothing is wrong). With the faults, one
-- message each, ffmpeg's path when @--video@ asks for it.
preflight :: Bounds -> SimOptions -> IO ([String], Maybe FilePath)
preflight bounds opts = do
  let out   = folder (optOut opts)
      files = catMaybes [ (,) "--svg" <$> optSvg opts, (,) "--log" <$> optLog opts
                        , (,) "--replay" <$> optReplay opts, (,) "--video" <$> optVideo opts
                        , (,) "--result" <$> optResult opts ]
  -- where each file is written: through a symbolic link, its target
  -- (Nothing: a loop of links, or too long a chain)
  targets <- forM files $ \(flag, f) ->
    (,,) flag f <$> if device f then pure (Just f) else linkTarget (40 :: Int) f
  let inOut = optFrames opts
              || any ((== out) . folder . takeDirectory)
                     (concat [ f : maybe [] pure t | (_, f, t) <- targets ])
  ffmpeg <- maybe (pure Nothing) (const (findExecutable "ffmpeg")) (optVideo opts)
  -- the same file under two names (a.svg and ./a.svg, or a link) is caught
  -- by comparing the canonical paths of where the files are written;
  -- devices are not files to keep (--log /dev/stdout --result /dev/stderr
  -- may be one terminal)
  -- (and a file already there by its device and number, which a hard
  -- link shares)
  canon <- forM [ tf | tf@(_, f, _) <- targets, not (device f) ] $ \(flag, f, t) ->
             (,,) flag f <$> fileKey (maybe f id t)
  world <- forM (filter (not . device) (maybe [] pure (optWorldFile opts))) $ \w -> (,) w <$> fileKey w
  -- (where the frames go, as a canonical path: a file there named as a
  -- frame is replaced by one)
  outCanon <- canonicalPath out
  -- a file is written in its folder, or through a link in its target's:
  -- the output folder is created by the run, any other must exist
  let checkIn flag f dir
        | folder dir == out && inOut = pure []
        | otherwise                  = folderWritable flag f dir
  -- the outputs named as the output folder that the run makes (said as
  -- such below, and not also as a folder)
  let asOut = [ (flag, f) | inOut, (flag, f, (c, _)) <- canon, folder c == folder outCanon ]
  fileErrs <- forM targets $ \(flag, f, t) -> do
    isDir <- doesDirectoryExist f
    kernel <- kernelFile f
    if | isDir && (flag, f) `elem` asOut -> pure []
       | isDir -> pure [ flag ++ " " ++ show f ++ " is a folder" ]
       -- (foo/.. with --out foo is a folder only once the run has made
       -- foo: it failed after the run)
       | namesFolder f -> pure [ flag ++ " " ++ show f ++ " names a folder, not a file" ]
       | Just what <- kernel ->
           pure [ flag ++ " " ++ show f ++ ": " ++ what ++ " (to write to a terminal or a pipe, name"
                  ++ " /dev/stdout or /proc/self/fd/N)" ]
       | otherwise -> do
           dirErr <- checkIn flag f (takeDirectory f)
           linkErr <- case t of
             Nothing -> pure [ flag ++ " " ++ show f ++ ": a loop of symbolic links (or a chain of more than 40)" ]
             Just target
               | target /= f -> checkIn flag f (takeDirectory target)
               | otherwise   -> pure []
           pure (dirErr ++ linkErr)
  let pre = validateOptionsIn bounds opts
            ++ [ "--video needs the frames (add --frames)" | optVideo opts /= Nothing, not (optFrames opts) ]
            ++ [ "--video needs ffmpeg on the PATH (on Debian: apt-get install ffmpeg)"
               | optVideo opts /= Nothing, ffmpeg == Nothing ]
            ++ [ "two outputs go to the same file: " ++ flag1 ++ " " ++ show f1 ++ " and " ++ flag2 ++ " " ++ show f2
               | ((flag1, f1, c1), i) <- zip canon [0 :: Int ..], ((flag2, f2, c2), j) <- zip canon [0 ..]
               , i < j, sameFile c1 c2 ]
            -- (a file named as the output folder that the run is to make:
            -- it failed only after the run, with the folder made)
            ++ [ flag ++ " " ++ show f ++ " is the output folder (--out " ++ show (optOut opts)
                 ++ "), where the run writes " ++ (if optFrames opts then "the frames" else "its files")
                 ++ ": choose another name"
               | (flag, f) <- asOut ]
            ++ [ flag ++ " " ++ show f ++ " would overwrite the world file " ++ show w
               | (w, cw) <- world, (flag, f, c) <- canon, sameFile c cw ]
            ++ [ what ++ " " ++ show f ++ " would be overwritten by a frame: --frames writes "
                 ++ show (out </> framePattern) ++ " (choose another name or folder)"
               | optFrames opts, (what, f, (c, _)) <- [ (flag, f, c) | (flag, f, c) <- canon ]
                                                     ++ [ ("--world", w, cw) | (w, cw) <- world ]
               , takeDirectory c == outCanon, isFrameName (takeFileName c) ]
            ++ concat fileErrs
  -- the output folder is created only when nothing else is wrong; with
  -- other faults, what can be told of it without making it is said too
  errs <- if | not inOut -> pure pre
             | null pre  -> checkFolder out
             | otherwise -> (pre ++) <$> folderFaults out
  pure (errs, ffmpeg)
  where
    device f = any (`isPrefixOf` normalise f) ["/dev/", "/proc/"]
    -- a path whose last part is . or .., or that ends in a slash
    namesFolder f = takeFileName f `elem` ["", ".", ".."]
    -- A path under /proc or /sys that is not a link, a terminal or other
    -- device, a pipe or a socket: the kernel's files and folders, where
    -- no new file can be made and a write fails (/proc/version: after the
    -- run, with \"does not exist\"); what it is, in words.
    kernelFile :: FilePath -> IO (Maybe String)
#if defined(mingw32_HOST_OS)
    kernelFile _ = pure Nothing
#else
    kernelFile f
      | not (any (`isPrefixOf` normalise f) ["/proc/", "/sys/"]) = pure Nothing
      | otherwise = do
          l  <- try (getSymbolicLinkStatus f) :: IO (Either IOException FileStatus)
          st <- try (getFileStatus f)         :: IO (Either IOException FileStatus)
          pure $ case (l, st) of
            (Right ls, _) | isSymbolicLink ls -> Nothing
            (_, Right s') | isCharacterDevice s' || isNamedPipe s' || isSocket s' -> Nothing
            (_, Left _) -> Just "no file can be made there: /proc and /sys hold the kernel's own"
            _           -> Just "a file of the kernel's /proc or /sys, which takes no output"
#endif
    fileKey f = (,) <$> canonicalPath f <*> fileIdentity f
    sameFile (c1, i1) (c2, i2) = c1 == c2 || (isJust i1 && i1 == i2)
    -- a folder as one name (--out x/ and --out ./x are the folder x, which
    -- the run creates; with the slash its parent was taken to be x itself)
    folder = dropTrailingPathSeparator . normalise
    -- where a file that is a symbolic link (perhaps to a file not there
    -- yet) is written: the run writes through it, into the folder of the
    -- link's target, which must exist too (Nothing: a loop of links)
    linkTarget k f
      | k <= 0    = pure Nothing
      | otherwise = do
          isLink <- either (\(_ :: IOException) -> False) id <$> try (pathIsSymbolicLink f)
          if not isLink
            then pure (Just f)
            else do
              t <- try (getSymbolicLinkTarget f)
              case t of
                Left (_ :: IOException) -> pure (Just f)
                Right target -> linkTarget (k - 1) (takeDirectory f </> target)
    folderWritable flag f dir = do
      why <- notAFolder dir
      case why of
        Just w -> pure [ flag ++ " " ++ show f ++ ": its folder, " ++ show dir ++ ", " ++ w ]
        Nothing -> do
          p <- getPermissions dir
          exists <- doesFileExist f
          fw <- if exists then writable <$> getPermissions f else pure True
          pure $ if | not (searchable p) -> [ flag ++ " " ++ show f ++ ": its folder, " ++ show dir ++ ", " ++ noSearch ]
                    | otherwise -> [ flag ++ " " ++ show f ++ ": cannot write there" | not (writable p || (exists && fw)) ]
    noSearch = "may not be searched (no x permission)"
    quietly act = act `catch` \(_ :: IOException) -> pure ()
    -- the output folder: created if its parent exists, then proven writable
    -- (without --frames only the SVG, page, log or result go there)
    writeTo | optFrames opts = "cannot write frames to "
            | otherwise      = "cannot write to the output folder (--out) "
    -- (what is wrong with the output folder that can be told without
    -- making it or writing into it, said with the other faults: its name
    -- taken by a file, a parent not there, or, as the system's access
    -- check tells it, no writing where it is or would be made, which
    -- does not say whether for want of permission or on a read-only
    -- file system; with no other fault, 'checkFolder' tries, and says
    -- the system's reason)
    folderFaults dir = do
      early <- folderShape dir
      if | not (null early) -> pure early
         | otherwise -> do
             there <- doesDirectoryExist dir
             let at = if there then dir else takeDirectory dir
                 whereTo = if there then "cannot write there" else "cannot make it in " ++ show at
             p <- either (\(_ :: IOException) -> Nothing) Just <$> try (getPermissions at)
             pure $ case p of
               Just ps | not (searchable ps) ->
                 [ writeTo ++ show dir ++ ": " ++ whereTo ++ ": " ++ show at ++ " " ++ noSearch ]
               Just ps | not (writable ps) ->
                 [ writeTo ++ show dir ++ ": " ++ whereTo ++ " (no permission, or a read-only file system)" ]
               _ -> []
    -- (its name taken by a file or by a link to nothing, a folder on its
    -- path that may not be searched, or its parent not there)
    folderShape dir = do
      here <- folderState dir
      let parentDir = takeDirectory dir
      parent <- folderState parentDir
      pure $ case here of
        AFolder -> []
        NotAFolder -> [ writeTo ++ show dir ++ ": it is a file, not a folder" ]
        NothingThere -> case parent of
          AFolder      -> []
          NotAFolder   -> [ writeTo ++ show dir ++ ": " ++ show parentDir ++ " is a file, not a folder" ]
          _            -> [ writeTo ++ show dir ++ ": the folder " ++ show parentDir ++ " "
                            ++ fromMaybe "" (folderStateText parent) ]
        _ -> [ writeTo ++ show dir ++ ": it " ++ fromMaybe "" (folderStateText here) ]
    checkFolder dir = do
      early <- folderShape dir
      if | not (null early) -> pure early
         | otherwise -> do
          there <- doesDirectoryExist dir
          -- (a hidden file of a new name, so that no file already there is
          -- touched, removed whatever happens)
          r <- try (do unless there (createDirectory dir)
                       mask $ \restore -> do
                         (probe, h) <- openTempFile dir ".afrp-write-test.tmp"
                         restore (hPutStr h "ok" >> hClose h)
                           `finally` (quietly (hClose h) >> removeFile probe))
          pure $ case r of
            Left (e :: IOException) -> [ writeTo ++ show dir ++ ": " ++ ioErrorText e ]
            Right ()                -> []
