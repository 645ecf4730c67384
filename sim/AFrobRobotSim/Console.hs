{-# LANGUAGE ScopedTypeVariables #-}
{-# LANGUAGE ForeignFunctionInterface #-}
{-# LANGUAGE CPP #-}
-- |
-- Module      : AFrobRobotSim.Console
-- Description : What the programs print: text made safe for a terminal,
--               and standard output that cannot fail silently.
--
-- Every program of the simulator (@simbot@, @afrp-examples@,
-- @afrp-sweep-merge@, a user's 'AFrobRobotSim.runSim') prints text it
-- did not write: file names, robots' messages, the operating system's
-- errors. Printed as they are, a newline or an escape sequence in one can
-- forge or hide a line, and a character the terminal's encoding lacks
-- stops the program. And output lost to a full disk is silent when left
-- to the runtime's exit, with exit code 0. This module is the one place
-- that deals with both.
module AFrobRobotSim.Console
  ( -- * Text for a terminal
    quote
  , displayPath
  , printableLine
  , ioErrorText
    -- * Standard output and error
  , tolerantOutput
  , closedAtStart
  , flushStdout
  , endOutput
  , guardOutput
  , stopProgram
  , putErr
  ) where

import           Control.Exception (IOException, catch, throwIO, try)
import           Data.Char         (GeneralCategory (..), generalCategory, isPrint, showLitChar)
import           Data.Bits         (testBit)
import           Data.List         (isInfixOf)
import           Foreign.C.Types   (CInt (..))
import           GHC.IO.Exception  (IOException (ioe_handle))
import           System.Exit       (ExitCode (ExitFailure), exitWith)
import           System.IO         (BufferMode (..), hFlush, hGetEncoding, hPutStr, hSetBuffering, hSetEncoding,
                                    mkTextEncoding, stderr, stdout)

-- | Text in quotes (a world file's token, a file name), the quote, the
-- backslash and every character that does not print escaped as a
-- Haskell literal writes them.
quote :: String -> String
quote s = "\"" ++ foldr esc "" s ++ "\""
  where
    -- (showLitChar leaves a quote as it is: it is escaped here)
    esc '"' rest = '\\' : '"' : rest
    esc ch rest
      | isPrint ch && ch /= '\\' = ch : rest
      | otherwise               = showLitChar ch rest

-- | A file name as a message shows it: as it is when every character of
-- it prints, otherwise in quotes with the others escaped ('quote'), so
-- that a name holding a newline or a terminal's escape sequence cannot
-- forge or hide a line of output.
--
-- >>> displayPath "out/run.svg"
-- "out/run.svg"
-- >>> displayPath "out/a\nb.svg"
-- "\"out/a\\nb.svg\""
displayPath :: FilePath -> String
displayPath f
  | all isPrint f = f
  | otherwise     = quote f

-- | An I/O failure as a message shows it: 'show' of the exception (which
-- names the file or handle as given), with every character that does
-- not print escaped as a Haskell literal would have it, for the reason
-- 'displayPath' gives.
ioErrorText :: IOException -> String
ioErrorText = printableLine . show

-- | Flush standard output; its failure (a full disk, a pipe whose reader
-- has gone) as a message, for the program to report: left to the
-- runtime's exit, the failure is silent and the exit code 0.
flushStdout :: IO (Maybe String)
flushStdout = either (\e -> Just ("cannot write to standard output: " ++ ioErrorText e)) (const Nothing)
                <$> try (hFlush stdout)

-- | Make standard output and standard error write what their encoding
-- cannot (a robot's message with an accent, in the C locale of a batch
-- job; a lone surrogate) as a substitute character instead of failing:
-- left as they are, one such character stops the run with a write
-- error. Handles already set so, or in binary mode, are left alone.
--
-- A handle whose descriptor was closed when the program started
-- ('closedAtStart') is left alone: writing to it fails, as it should.
tolerantOutput :: IO ()
tolerantOutput = do
  closed <- closedAtStart
  mapM_ tolerant [ h | (h, fd) <- [(stdout, 1), (stderr, 2)], fd `notElem` closed ]
  where
    tolerant h = do
      enc <- hGetEncoding h
      case enc of
        Just e | not ("//" `isInfixOf` show e) ->
          (mkTextEncoding (show e ++ "//TRANSLIT") >>= hSetEncoding h)
            `catch` \(_ :: IOException) -> pure ()
        _ -> pure ()

-- | The standard descriptors (0, 1, 2) that were closed when the program
-- started (@prog >&-@). Each is held from the start, before the runtime
-- starts, by @\/dev\/null@ opened for reading (@cbits/std_fds.c@): left
-- free, the number was taken by the runtime's timer, and the first write
-- to standard output waited forever. Writing to such a descriptor fails
-- (@EBADF@), as writing to a closed one does, so the program reports it
-- and exits non-zero; reading standard input gives end of file.
-- (On Windows, where the descriptors are not held, it is always empty.)
closedAtStart :: IO [Int]
closedAtStart = do
  bits <- c_afrp_std_fds_reopened
  pure [ fd | fd <- [0, 1, 2], testBit bits fd ]

#if defined(mingw32_HOST_OS)
c_afrp_std_fds_reopened :: IO CInt
c_afrp_std_fds_reopened = pure 0
#else
foreign import ccall unsafe "afrp_std_fds_reopened"
  c_afrp_std_fds_reopened :: IO CInt
#endif

-- | A line of text as it is safe to print on a terminal: the characters
-- that could forge or hide output (controls such as escape sequences or
-- a newline, line and paragraph separators, the controls that reorder
-- text right to left, lone surrogates, unassigned code points) escaped
-- as a Haskell literal writes them, the rest as it is (accents, emoji
-- and the joiners within them, other scripts).
--
-- >>> printableLine "bump\ESC[2J!"
-- "bump\\ESC[2J!"
printableLine :: String -> String
printableLine = foldr esc ""
  where
    esc ch rest
      | unsafe ch = showLitChar ch rest
      | otherwise = ch : rest
    unsafe ch = case generalCategory ch of
      Control            -> True
      Surrogate          -> True
      LineSeparator      -> True
      ParagraphSeparator -> True
      NotAssigned        -> True
      Format             -> ch `elem` ['\x202A' .. '\x202E'] || ch `elem` ['\x2066' .. '\x2069']
      _                  -> False

-- | @endOutput prog@: 'flushStdout', and on failure the message on
-- standard error, after the program's name, and exit code 1.
endOutput :: String -> IO ()
endOutput prog = flushStdout >>= maybe (pure ()) (stopProgram prog 1)

-- | @guardOutput prog act@: @act@, and a write to standard output that
-- fails in it (a full disk, a pipe whose reader has gone) said as
-- 'endOutput' says one, with exit code 1; any other exception is thrown
-- on. For a text longer than standard output's buffer, which fails in
-- the middle of its writing, before 'endOutput': left to the runtime, a
-- full disk ended the program with the bare exception, and a pipe whose
-- reader had gone with exit code 0 and nothing said (the runtime takes
-- @EPIPE@ on standard output for a reader that has all it wants: a
-- @--dump-world@ cut short passed for one written).
guardOutput :: String -> IO a -> IO a
guardOutput prog act = act `catch` \(e :: IOException) -> case ioe_handle e of
  Just h | h == stdout -> stopProgram prog 1 ("cannot write to standard output: " ++ ioErrorText e)
  _                    -> throwIO e

-- | @stopProgram prog code msg@: the program stopped, @msg@ on standard
-- error after the program's name (@prog: msg@ and a newline; a message of
-- several lines, such as a heading with the faults below it, as it is)
-- and the exit code @code@ (by 'exitWith', so a caller may catch the
-- 'ExitCode').
stopProgram :: String -> Int -> String -> IO a
stopProgram prog code msg = putErr (prog ++ ": " ++ msg ++ "\n") >> exitWith (ExitFailure code)

-- | Write a message to standard error, in one piece (standard error is
-- unbuffered, which would write it a character at a time). A failure to
-- write it is ignored: there is no other place to report it, and what
-- the program does, its outputs and its exit code, must not hang on it
-- (standard error closed, @prog 2>&-@, or a full disk behind it: the
-- message is lost, the run goes on, a fault still exits with its code).
putErr :: String -> IO ()
putErr msg = do
  attempt (hSetBuffering stderr (BlockBuffering Nothing) >> hPutStr stderr msg >> hFlush stderr)
  -- (a write that failed leaves its bytes in the buffer: unbuffering
  -- tries them once more, and then they are dropped)
  attempt (hSetBuffering stderr NoBuffering)
  where
    attempt act = act `catch` \(_ :: IOException) -> pure ()
