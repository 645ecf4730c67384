-- | Reading the files a user names ("AFrobRobotSim.InputFile"): the
-- bounds of 'readFileUpTo' and of the line reader, and a named pipe
-- waited for rather than read as empty. (The world file's and the log's
-- readers, which use these, are "AFrobRobotSim.WorldFileSpec"'s and
-- "AFrobRobotSim.Log.ReadSpec"'s.)
module AFrobRobotSim.InputFileSpec (spec) where

import           Control.Concurrent     (forkIO, threadDelay)
import           Control.Exception      (bracket)
import qualified Data.ByteString.Char8  as BC
import           System.FilePath        ((</>))
import           GHC.IO.Handle.FD       (openFileBlocking)
import           System.IO              (IOMode (..), hClose, withBinaryFile)
import           System.Posix.Files     (createNamedPipe, ownerReadMode, ownerWriteMode, unionFileModes)
import           System.Timeout         (timeout)
import           Test.Hspec

import           AFrobRobotSim.InputFile
import           TestUtil               (withTempDir)

-- | The lines of a file of these bytes, read with these limits (in all,
-- in a line), up to the first fault, which ends the list: each line with
-- its number and whether it ended with a newline.
linesOf :: BC.ByteString -> Int -> Int -> IO ([(Int, String, Bool)], Maybe String)
linesOf bytes cap lineCap = withTempDir $ \dir -> do
  let path = dir </> "lines.txt"
  BC.writeFile path bytes
  withBinaryFile path ReadMode $ \h -> do
    src <- newLineReader h cap lineCap
    let go acc = nextLineEnded src >>= \r -> case r of
          Right (Just (n, l, ended)) -> go ((n, BC.unpack l, ended) : acc)
          Right Nothing              -> pure (reverse acc, Nothing)
          Left fault                 -> pure (reverse acc, Just (faultName fault))
    go []
  where
    faultName TooManyBytes   = "too many bytes"
    faultName (LongLine n)   = "long line " ++ show n
    faultName (Unreadable _) = "unreadable"

spec :: Spec
spec = do
  describe "readFileUpTo" $ do
    it "reads a file of at most the limit's bytes whole, and refuses one a byte longer" $
      withTempDir $ \dir -> do
        let path = dir </> "ten.txt"
        BC.writeFile path (BC.pack "0123456789")
        fmap (fmap (fmap BC.unpack)) (either (const Nothing) Just <$> readFileUpTo 10 path)
          `shouldReturn` Just (Just "0123456789")
        fmap (fmap (fmap BC.unpack)) (either (const Nothing) Just <$> readFileUpTo 9 path)
          `shouldReturn` Just Nothing

    it "says that a file it cannot open cannot be read" $
      withTempDir $ \dir -> do
        r <- readFileUpTo 100 (dir </> "absent.txt")
        either (const True) (const False) r `shouldBe` True

    it "refuses an endless device at its limit instead of reading on" $ do
      r <- timeout 20000000 (readFileUpTo 100000 "/dev/zero")
      fmap (either (const "unreadable") (maybe "refused" (const "read"))) r `shouldBe` Just "refused"

    it "waits for a named pipe's writer and reads what it writes, not an empty file" $
      withTempDir $ \dir -> do
        let fifo = dir </> "world.fifo"
        createNamedPipe fifo (ownerReadMode `unionFileModes` ownerWriteMode)
        -- (the writer opens the pipe after the reader has begun, most
        -- likely; its open waits for the reader's either way, whereas
        -- GHC's usual open for writing fails at once without a reader)
        _ <- forkIO $ do
          threadDelay 200000
          bracket (openFileBlocking fifo WriteMode) hClose $ \h -> BC.hPut h (BC.pack "robot 1 1 0\n")
        r <- timeout 20000000 (readFileUpTo 1000 fifo)
        fmap (either (const Nothing) (fmap BC.unpack)) r `shouldBe` Just (Just "robot 1 1 0\n")

  describe "openReading" $
    it "opens a regular file at once, in binary mode (bytes beyond ASCII as they are)" $
      withTempDir $ \dir -> do
        let path = dir </> "bytes.bin"
        BC.writeFile path (BC.pack "\255\0\r\n")
        got <- bracket (openReading path) hClose (fmap BC.unpack . flip BC.hGetSome 16)
        got `shouldBe` "\255\0\r\n"

  describe "the line reader (newLineReader, nextLine, nextLineEnded)" $ do
    it "gives the lines numbered from 1, the last one without a newline marked so" $
      linesOf (BC.pack "one\n\nthree\nfour") maxBound maxBound
        `shouldReturn` ([(1, "one", True), (2, "", True), (3, "three", True), (4, "four", False)], Nothing)

    it "ends at the file's end with a last newline, with no empty line after it" $
      linesOf (BC.pack "a\nb\n") maxBound maxBound `shouldReturn` ([(1, "a", True), (2, "b", True)], Nothing)

    it "takes a line of exactly the line limit (its newline not counted) and refuses one a byte longer" $ do
      linesOf (BC.pack "abcd\nabcde\nx\n") maxBound 4
        `shouldReturn` ([(1, "abcd", True)], Just "long line 2")
      -- (a last line without a newline is held to the same limit)
      linesOf (BC.pack "ab\nabcde") maxBound 4
        `shouldReturn` ([(1, "ab", True)], Just "long line 2")

    it "finds a line too long within chunks of the file, however many" $
      -- (the reader reads 64 KiB at a time: the long line spans three)
      linesOf (BC.pack ("ok\n" ++ replicate 150000 'x' ++ "\n")) maxBound 140000
        `shouldReturn` ([(1, "ok", True)], Just "long line 2")

    it "refuses a file of more bytes in all than its limit" $
      -- (the limit in all is counted on the chunks read: a file of 200 KiB
      -- goes past a limit of 100 KiB)
      linesOf (BC.pack (concat (replicate 20000 "0123456789\n"))) 100000 maxBound
        >>= \(ls, fault) -> (length ls < 20000, fault) `shouldBe` (True, Just "too many bytes")

    it "stops an endless device's line at the limit" $ do
      r <- timeout 20000000 $ withBinaryFile "/dev/zero" ReadMode $ \h -> do
        src <- newLineReader h maxBound 100000
        either (const "fault") (maybe "end" (const "line")) <$> nextLine src
      r `shouldBe` Just "fault"
