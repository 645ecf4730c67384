{-# LANGUAGE BangPatterns        #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Sweep
-- Description : Merging the result lines of a sweep into one table.
--
-- A sweep (@scripts/sweep@, @scripts/sweep.sbatch@) writes one result line
-- per run ("AFrobRobotSim.Result"), in shards, in whatever order the runs
-- finished. 'mergeResults' groups the runs by their setting (the program,
-- the world and the parameters; the program is named only when the lines
-- name more than one) and prints, per group, the mean, minimum and maximum of
-- every outcome over its runs; when two or more settings vary (two
-- parameters, or a parameter and the world), it then prints the same per
-- value of each setting, over all the values of the others. A run that
-- failed (a controller error, or a line the sweep wrote for a run that
-- wrote none) is counted and listed under its group, never dropped; its
-- outcome, as far as it got, still counts. A line that is neither a run's
-- result line nor the sweep's line for a run with no result (a run log
-- given by mistake, @{}@) is refused with its number and what it lacks,
-- never counted as a failed run.
--
-- The design trade-off is memory: the lines are read one at a time and
-- each is folded into its group's tallies (a count, an exact sum, the
-- least and the greatest value of each outcome) and dropped, so the
-- memory is the table's, whatever the number of lines: 10^6 lines of 8
-- settings take no more than 10^3 do. Two things grow with the runs: the
-- seeds seen per setting (a set of integers, for refusing a run merged
-- twice; a few bytes per run, less for consecutive seeds), and the failed
-- runs listed, at most 'maxListedFailures' per group. A line is read up
-- to 'maxLineBytes' bytes: a longer one (an endless line of
-- @\/dev\/zero@) is refused once that much is read.
--
-- The table does not depend on the order of the lines: the sums are
-- exact (a 'Double' is a binary fraction, and binary fractions add
-- exactly as integers times a power of two; the mean is rounded once, at
-- the end), and everything else is ordered by seed, so shards merged in
-- any order give the same table.
module AFrobRobotSim.Sweep
  ( mergeResults
  , maxLineBytes
  , maxListedFailures
  , sweepMergeMain
  ) where

import           Control.Exception   (IOException, throwIO, try)
import           Control.Monad       (foldM, when)
import           Data.List           (intercalate, isPrefixOf, tails)
import           System.Environment  (getArgs, getProgName)
import           System.Exit         (exitWith, ExitCode (..))
import           System.IO           (Handle, IOMode (ReadMode), hClose, hIsTerminalDevice,
                                      hSetBinaryMode, openBinaryFile, stdin)

import           AFrobRobotSim.Console (displayPath, endOutput, guardOutput, stopProgram, tolerantOutput)
import           AFrobRobotSim.InputFile (LineFault (..), newLineReader, nextLine)
import           AFrobRobotSim.OutputFile (fileIdentity)
import           AFrobRobotSim.Sweep.Merge
import           AFrobRobotSim.WorldFile.Lexical (canonicalPath, cannotRead, utf8BytesFrom)

-- | The longest line 'sweepMergeMain' reads: 16 MiB (16,777,216 bytes).
-- A run's result line is about 250 bytes a robot at most (every number
-- at its longest, @-2.2250738585072014e-308@), 2.4 MiB for the 10,000
-- robots a world file may hold; what else it holds comes from the run's
-- command line (the world's name, the parameters), at most 2 MiB of
-- arguments on Linux, 12 MiB were every character escaped (@\\u001b@).
-- A line is parsed as its bytes ('addLineUtf8'), not as a 'String' of
-- its text: a line at the limit of arrays and numbers is read in about
-- 40 MB (it took 500 MB and 7.7 s; 0.9 s now). What is kept as text (the
-- world's name, the parameters' names and values, a failure's message)
-- still costs a 'String''s 24 to 40 bytes a character: a line at the
-- limit that is one parameter's value takes about 960 MB and 6 s (1.2 GB
-- and 11 s before), a value no command line can give (Linux takes at
-- most 128 KiB for one argument): the most memory a hostile input can
-- take.
maxLineBytes :: Int
maxLineBytes = 16 * 1024 * 1024

------------------------------------------------------------------------------
-- The program

-- A fault: the exit code, and the message.
data Fault = Fault !Int String

-- Fold the lines of one input into the merge, a line at a time
-- ('nextLine'): a line is kept whole only up to 'maxLineBytes'. A read
-- that fails is thrown.
mergeHandle :: String -> Handle -> Merge -> IO (Either Fault Merge)
mergeHandle name h m0 = newLineReader h maxBound maxLineBytes >>= \src -> go src m0
  where
    go src !m = nextLine src >>= \r -> case r of
      Left (Unreadable e)     -> throwIO e
      Left (LongLine k)       -> pure (Left (tooLong k))
      Left TooManyBytes       -> pure (Left (tooLong (1 :: Int)))   -- (no limit in all: never met)
      Right Nothing           -> pure (Right m)
      Right (Just (k, bytes)) -> case one k bytes m of
        Left f   -> pure (Left f)
        Right m' -> m' `seq` go src m'
    one k bytes m = case utf8BytesFrom name k bytes of
      Left msg -> Left (Fault 1 msg)
      Right u  -> either (\e -> Left (Fault 1 (name ++ ": line " ++ show k ++ ": " ++ e))) Right (addLineUtf8 m u)
    tooLong k = Fault 2 (name ++ ": line " ++ show k ++ ": longer than " ++ show maxLineBytes
                         ++ " bytes (16 MiB), more than any result line: not a result file of a sweep?")

-- | The @afrp-sweep-merge [FILE...]@ program (and @scripts/sweep-merge@):
-- print the table of the result files, read in the order given, or of
-- standard input when none is given (refused when standard input is a
-- terminal). Exit code 0 with the table; otherwise nothing on standard
-- output, a message on standard error signed with the name the program
-- was run by (@sweep-merge:@ when run by the script), and
--
-- * 1 when the lines are not a sweep's results: no result line at all
--   (@no result lines in FILE, ...@), a line that is not UTF-8
--   (@FILE:LINE:COLUMN: invalid UTF-8@), a line that is not a result line
--   of a sweep (@FILE: line N: not a result line of a sweep (...)@: not
--   JSON, its fault placed at @column C of the line@ (a line cut short:
--   at its end), or JSON that is neither a run's result line nor the sweep's
--   line for a run with no result, such as a run log given by mistake),
--   or a line that repeats a run (@FILE: line N: the run ... is on an
--   earlier line too@); and, once every line is read, a run on the
--   sweep's line for a run with no result and without @--world@ that a
--   result line has too (@the run ... is on a line for a run with no
--   result and on a result line too ...@: no file or line is named, the
--   two lines having been filed under one world only then);
--
-- * 2 when they cannot be read: a file that cannot be read, one given
--   twice (under any name: the same canonical path, or the same device
--   and inode; not @\/dev\/...@ or @\/proc\/...@), a line longer than
--   'maxLineBytes', standard input a terminal.
sweepMergeMain :: IO ()
sweepMergeMain = do
  tolerantOutput
  -- (the name it was called by signs its messages: scripts/sweep-merge
  -- runs it as sweep-merge)
  prog <- getProgName
  let usage = "usage: " ++ prog ++ " RESULTS...   (the result lines of a sweep; standard input when none is given)"
      stop (Fault code msg) = endOutput prog >> stopProgram prog code msg
      -- (a file by its path, standard input by that name)
      readAll path h m = do
        r <- try (mergeHandle (displayPath path) h m)
        case r of
          Left e                -> stop (Fault 2 (cannotRead path (e :: IOException)))
          Right (Left fault)    -> stop fault
          Right (Right merged') -> pure merged'
  args <- getArgs
  when (any (`elem` ["-h", "--help"]) args) $ do
    putStrLn usage
    endOutput prog
    exitWith ExitSuccess
  merged <- if null args
    then do
      tty <- either (\(_ :: IOException) -> False) id <$> try (hIsTerminalDevice stdin)
      when tty $ stop (Fault 2 ("no result files given, and standard input is a terminal\n" ++ usage))
      hSetBinaryMode stdin True
      readAll "standard input" stdin emptyMerge
    else do
      sameFiles args >>= mapM_ stop
      foldM (\m f -> do
               opened <- try (openBinaryFile f ReadMode)
               case opened of
                 Left e  -> stop (Fault 2 (cannotRead f e))
                 Right h -> readAll f h m <* hClose h)
            emptyMerge args
  case renderMerge merged of
    Right out -> guardOutput prog (putStr out) >> endOutput prog
    Left e
      | mergedRuns merged == 0 -> stop (Fault 1 ("no result lines in " ++ (if null args then "standard input" else intercalate ", " (map displayPath args))))
      | otherwise              -> stop (Fault 1 e)

-- The first file given twice, as a fault.
sameFiles :: [FilePath] -> IO (Maybe Fault)
sameFiles files = do
  keys <- mapM (\f -> do
                  c <- canonicalPath f
                  i <- fileIdentity f
                  pure (f, c, i))
               files
  let special (f, c, _) = any (\p -> any (p `isPrefixOf`) [f, c]) ["/dev/", "/proc/"]
      same (_, c1, i1) (_, c2, i2) = c1 == c2 || (i1 /= Nothing && i1 == i2)
  pure $ case [ (a, b) | (a : rest) <- tails (filter (not . special) keys), b <- rest, same a b ] of
    ((f1, _, _), (f2, _, _)) : _
      | f1 == f2  -> Just (Fault 2 (displayPath f1 ++ " is given twice: its runs would be counted twice"))
      | otherwise -> Just (Fault 2 (displayPath f1 ++ " and " ++ displayPath f2
                                    ++ " are the same file: its runs would be counted twice"))
    [] -> Nothing
