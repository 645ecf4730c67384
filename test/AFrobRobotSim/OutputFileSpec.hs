-- | "AFrobRobotSim.OutputFile": a file written whole or not at all.
module AFrobRobotSim.OutputFileSpec (spec) where

import           Control.Exception (ErrorCall (..), throwIO, try)
import           System.Directory  (createDirectory, createFileLink, listDirectory, pathIsSymbolicLink)
import           System.FilePath   ((</>))
import           System.IO         (IOMode (..), hClose, hGetContents, openFile)
import           Data.List         (sort)
import           System.Posix.Files (createNamedPipe, fileMode, getFileStatus, isNamedPipe, regularFileMode,
                                     setFileMode)
import           System.Timeout    (timeout)
import           Test.Hspec

import           AFrobRobotSim.OutputFile
import           TestUtil          (withTempDir, withUnsearchable)

spec :: Spec
spec = do
 describe "notAFolder, folderState" $ do
  it "says whether a path can hold files: a folder, nothing there, or a file in its place" $ withTempDir $ \dir -> do
    writeFile (dir </> "afile") ""
    notAFolder dir `shouldReturn` Nothing
    notAFolder (dir </> "none") `shouldReturn` Just "does not exist"
    notAFolder (dir </> "afile") `shouldReturn` Just "is not a folder"
  it "tells a link to nothing, and a loop of links, from nothing there (both were \"does not exist\")" $ withTempDir $ \dir -> do
    createFileLink (dir </> "gone") (dir </> "dangling")
    createFileLink "dangling" (dir </> "twice")
    folderState (dir </> "dangling") `shouldReturn` DanglingLink (dir </> "gone")
    folderState (dir </> "twice") `shouldReturn` DanglingLink (dir </> "gone")
    notAFolder (dir </> "dangling") `shouldReturn` Just ("is a symbolic link to " ++ show (dir </> "gone") ++ ", which does not exist")
    folderState (dir </> "none") `shouldReturn` NothingThere
    folderState (dir </> "none" </> "deeper") `shouldReturn` NothingThere
    createFileLink "loop" (dir </> "loop")
    folderState (dir </> "loop") `shouldReturn` LinkLoop
    createDirectory (dir </> "sub")
    createFileLink "sub" (dir </> "tosub")
    folderState (dir </> "tosub") `shouldReturn` AFolder
  it "tells a file on the way, as written or where a link leads, from a loop of links (a link through a file was \"a loop\")" $ withTempDir $ \dir -> do
    writeFile (dir </> "afile") ""
    createFileLink (dir </> "afile" </> "sub") (dir </> "lnk")
    folderState (dir </> "lnk") `shouldReturn` ThroughAFile (Just (dir </> "afile"))
    folderState (dir </> "afile" </> "sub") `shouldReturn` ThroughAFile (Just (dir </> "afile"))
    notAFolder (dir </> "afile" </> "sub") `shouldReturn`
      Just ("cannot be reached: " ++ show (dir </> "afile") ++ " on its path is not a folder")
  it "says which folder on the way may not be searched (it said \"does not exist\"; as root, every folder may be)" $
    withTempDir $ \dir -> withUnsearchable dir $ \locked -> do
      r <- (,) <$> folderState (locked </> "sub") <*> notAFolder (locked </> "sub" </> "out")
      r `shouldBe` ( Unsearchable (Just locked)
                   , Just ("cannot be reached: the folder " ++ show locked
                           ++ " on its path may not be searched (no x permission)") )
 describe "writeWhole" $ do
  it "writes a new file, and replaces an old one, leaving nothing else in the folder" $ withTempDir $ \dir -> do
    let file = dir </> "run.svg"
    writeWhole file (`writeFile` "first")
    readFile file `shouldReturn` "first"
    writeWhole file (`writeFile` "second")
    readFile file `shouldReturn` "second"
    listDirectory dir `shouldReturn` ["run.svg"]

  it "leaves the old file as it was, and no temporary file, when the writing fails half way" $ withTempDir $ \dir -> do
    let file = dir </> "result.json"
    writeFile file "old"
    r <- try (writeWhole file (\tmp -> writeFile tmp "half of the new" >> throwIO (ErrorCall "disk full")))
    r `shouldBe` Left (ErrorCall "disk full")
    readFile file `shouldReturn` "old"
    listDirectory dir `shouldReturn` ["result.json"]

  it "keeps the permissions of the file it replaces" $ withTempDir $ \dir -> do
    let file = dir </> "private.json"
    writeFile file "old"
    setFileMode file 0o600
    writeWhole file (`writeFile` "new")
    readFile file `shouldReturn` "new"
    (fileMode <$> getFileStatus file) `shouldReturn` (regularFileMode + 0o600)

  it "writes through a symbolic link: the link stays, its target is replaced" $ withTempDir $ \dir -> do
    writeFile (dir </> "target.html") "old"
    createFileLink "target.html" (dir </> "link.html")
    writeWhole (dir </> "link.html") (`writeFile` "new")
    pathIsSymbolicLink (dir </> "link.html") `shouldReturn` True
    readFile (dir </> "target.html") `shouldReturn` "new"

  it "writes in place what is not a regular file (a named pipe): nothing made beside it or put in its place" $
    withTempDir $ \dir -> do
      let pipe = dir </> "pipe"
      createNamedPipe pipe 0o600
      -- (the reading end open first: a pipe is opened for writing only
      -- when something reads it)
      h <- openFile pipe ReadMode
      done <- timeout 5000000 (writeWhole pipe (`writeFile` "through the pipe"))
      done `shouldBe` Just ()
      timeout 5000000 (hGetContents h >>= \t -> length t `seq` pure t) `shouldReturn` Just "through the pipe"
      hClose h
      isNamedPipe <$> getFileStatus pipe `shouldReturn` True
      listDirectory dir `shouldReturn` ["pipe"]

  it "writes in place through a symbolic link to a named pipe (as /dev/stdout may be)" $
    withTempDir $ \dir -> do
      let pipe = dir </> "pipe"
      createNamedPipe pipe 0o600
      createFileLink pipe (dir </> "out")
      h <- openFile pipe ReadMode
      done <- timeout 5000000 (writeWhole (dir </> "out") (`writeFile` "linked"))
      done `shouldBe` Just ()
      timeout 5000000 (hGetContents h >>= \t -> length t `seq` pure t) `shouldReturn` Just "linked"
      hClose h
      sort <$> listDirectory dir `shouldReturn` ["out", "pipe"]
