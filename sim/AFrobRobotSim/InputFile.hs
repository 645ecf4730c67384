-- |
-- Module      : AFrobRobotSim.InputFile
-- Description : Reading a file the user names: bounded, and a named pipe
--               waited for.
--
-- World files and run logs are read whole, but a path may name something
-- endless (@\/dev\/zero@), huge, or a named pipe another program has not
-- yet opened. 'readFileUpTo' reads at most a given number of bytes;
-- 'openReading' waits for a FIFO's writer instead of reading it as empty.
module AFrobRobotSim.InputFile
  ( readFileUpTo
  , openReading
  ) where

import           Control.Concurrent      (forkIO)
import           Control.Concurrent.MVar (newEmptyMVar, putMVar, takeMVar)
import           Control.Exception       (IOException, bracket, onException, throwIO, try)
import qualified Data.ByteString         as B
import qualified Data.ByteString.Lazy    as BL
import           GHC.IO.Handle.FD        (openFileBlocking)
import           System.IO               (Handle, IOMode (ReadMode), hClose, hFileSize, hSetBinaryMode)

-- | @readFileUpTo cap path@: the file's bytes, 'Nothing' when it is longer
-- than @cap@ bytes (or endless, such as @\/dev\/zero@), 'Left' when it
-- cannot be read ('AFrobRobotSim.WorldFile.Lexical.cannotRead' words the
-- exception). A regular file says
-- its size: one too long is refused unread, one within the limit read in
-- one piece; anything else (a pipe, a device) is read in chunks, up to one
-- byte past the limit. A named pipe (FIFO) is read from its writer, which
-- is waited for ('openReading').
readFileUpTo :: Int -> FilePath -> IO (Either IOException (Maybe B.ByteString))
readFileUpTo cap path = try (bracket (openReading path) hClose $ \h -> do
  size <- either (\e -> const 0 (e :: IOException)) id <$> try (hFileSize h)
  if size > fromIntegral cap
    then pure Nothing
    else do
      s <- if size > 0 then B.hGet h (fromIntegral size) else pure B.empty
      more <- BL.toStrict . BL.take (fromIntegral (cap + 1 - B.length s)) <$> BL.hGetContents h
      let t = if B.null more then s else B.append s more
      B.length t `seq` pure (if B.length t > cap then Nothing else Just t))

-- | A file opened for reading, in binary mode; when it is a named pipe
-- (a FIFO) with no writer yet, once a writer opens it (as @cat@ does).
-- GHC's 'System.IO.openFile' opens without waiting, and such a pipe then
-- reads as empty: a world written by another program into a FIFO would
-- have run as an empty world.
--
-- The open waits on a thread of its own, so that with the threaded
-- runtime (@-threaded@, as @simbot@ and the examples are built) the
-- caller stays interruptible: Ctrl-C, @SIGTERM@, 'System.Timeout.timeout'.
-- A caller that gives up leaves that thread waiting in the system's
-- @open@ until a writer comes, whose handle it then closes (the writer's
-- data is not read). Without the threaded runtime the wait holds the
-- whole program, as @cat@'s would: a first Ctrl-C is not seen, a second
-- ends the program.
openReading :: FilePath -> IO Handle
openReading path = do
  opened <- newEmptyMVar
  _ <- forkIO (try (openFileBlocking path ReadMode) >>= putMVar opened)
  r <- takeMVar opened `onException` forkIO (takeMVar opened >>= either (\e -> const (pure ()) (e :: IOException)) hClose)
  h <- either throwIO pure r
  h <$ hSetBinaryMode h True
