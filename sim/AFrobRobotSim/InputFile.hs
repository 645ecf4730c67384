{-# LANGUAGE MultiWayIf #-}
-- |
-- Module      : AFrobRobotSim.InputFile
-- Description : Reading a file the user names: bounded, and a named pipe
--               waited for.
--
-- World files are read whole, run logs and result files a line at a
-- time, but a path may name something endless (@\/dev\/zero@), huge, or
-- a named pipe another program has not yet opened. 'readFileUpTo' reads
-- at most a given number of bytes; 'nextLine' a line of at most so many;
-- 'openReading' waits for a FIFO's writer instead of reading it as empty.
module AFrobRobotSim.InputFile
  ( readFileUpTo
  , openReading
    -- * Lines, bounded
  , LineReader
  , LineFault (..)
  , newLineReader
  , nextLine
  , nextLineEnded
  ) where

import           Control.Concurrent      (forkIO)
import           Control.Concurrent.MVar (newEmptyMVar, putMVar, takeMVar)
import           Control.Exception       (IOException, bracket, onException, throwIO, try)
import qualified Data.ByteString         as B
import qualified Data.ByteString.Lazy    as BL
import           Data.IORef
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

-- | A file's lines, read in chunks, with limits: at most so many bytes in
-- all, and in a line ('newLineReader', 'nextLine'). Only the line being
-- read is held, however long the file: a reader of logs and result files
-- that takes a line at a time needs no more.
data LineReader = LineReader Handle (IORef B.ByteString) (IORef Int) (IORef Int) Int Int

-- | Why 'nextLine' gives no line: more than the limit of bytes in all
-- ('TooManyBytes'), more than the limit in the line of this number
-- ('LongLine', from 1), or a read that failed ('Unreadable').
data LineFault = TooManyBytes | LongLine Int | Unreadable IOException

-- | @newLineReader h cap lineCap@ reads the lines of @h@ (opened in binary
-- mode), at most @cap@ bytes in all (@maxBound@: no limit) and
-- @lineCap@ in a line (its newline not counted).
newLineReader :: Handle -> Int -> Int -> IO LineReader
newLineReader h cap lineCap =
  LineReader h <$> newIORef B.empty <*> newIORef 0 <*> newIORef 1 <*> pure cap <*> pure lineCap

-- | The next line (without its newline) and its number, from 1;
-- 'Nothing' at the end of the file (a last line without a newline is a
-- line). Reading stops at the first fault: a line longer than the limit
-- is not read to its end (an endless one, @\/dev\/zero@'s, ends at the
-- limit).
nextLine :: LineReader -> IO (Either LineFault (Maybe (Int, B.ByteString)))
nextLine src = fmap (fmap (\(n, l, _) -> (n, l))) <$> nextLineEnded src

-- | 'nextLine', and whether the line ended with a newline: 'False' only
-- for a last line that the file ends in the middle of (a file whose
-- writer was killed while writing it ends so, or one written without a
-- final newline).
nextLineEnded :: LineReader -> IO (Either LineFault (Maybe (Int, B.ByteString, Bool)))
nextLineEnded (LineReader h restRef totalRef numRef cap lineCap) = do
  n <- readIORef numRef
  rest <- readIORef restRef
  let done line left ended = do
        writeIORef restRef left
        writeIORef numRef (n + 1)
        pure (Right (Just (n, line, ended)))
      -- the line's chunks so far (last first) and their length, then the
      -- bytes still to look at
      go acc len buf = case B.elemIndex 10 buf of
        Just k | len + k > lineCap -> pure (Left (LongLine n))
               | otherwise         -> done (B.concat (reverse (B.take k buf : acc))) (B.drop (k + 1) buf) True
        Nothing
          | len + B.length buf > lineCap -> pure (Left (LongLine n))
          | otherwise -> do
              got <- try (B.hGetSome h 65536)
              let chunk = either (const B.empty) id got
              total <- (+ B.length chunk) <$> readIORef totalRef
              writeIORef totalRef total
              if | Left e <- got -> pure (Left (Unreadable e))
                 | total > cap   -> pure (Left TooManyBytes)
                 | B.null chunk  -> if len + B.length buf == 0 then pure (Right Nothing)
                                    else done (B.concat (reverse (buf : acc))) B.empty False
                 | otherwise     -> go (buf : acc) (len + B.length buf) chunk
  go [] 0 rest
