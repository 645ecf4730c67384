{-# LANGUAGE BangPatterns        #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Params
-- Description : The parameters (@--param NAME=VALUE@) a program's
--               controllers read, and those never read.
--
-- A sweep runs one program over many parameters ("AFrobRobotSim.Result"
-- writes each run's line with the parameters it got).
--
-- The controllers of a program are built before 'AFrobRobotSim.runSim'
-- reads the command line, so a parameter is read in 'IO' first, from the
-- same command line:
--
-- @
-- main = do
--   speed <- 'paramOr' \"speed\" 0.5
--   runSim Nothing (wander speed) (wander speed)
-- @
--
-- A program whose command line is its own, with 'AFrobRobotSim.runSim''s
-- flags after its own arguments (as @afrp-examples NAME [flags]@), reads
-- a parameter of those flags with 'paramOrFrom', which counts it as read
-- as 'paramOr' does:
--
-- @
-- main = do
--   args <- getArgs
--   case args of
--     name : flags -> do
--       speed <- 'paramOrFrom' flags \"speed\" 0.5
--       ...   -- the flags parsed with parseSimArgs, then runSimWith
--     [] -> ...
-- @
--
-- The run warns of a parameter given but never read ('unreadParams'):
-- usually a misspelled name.
module AFrobRobotSim.Params
  ( getSimParams
  , simParamsOf
  , lookupSimParam
  , paramOr
  , paramOrFrom
  , readSimParam
  , unreadParams
  ) where

import           Control.Exception    (SomeException, displayException, evaluate, try)
import           Data.IORef           (IORef, atomicModifyIORef', newIORef, readIORef)
import           Data.List            (nub)
import qualified Data.Map.Strict      as M
import           System.IO.Unsafe     (unsafePerformIO)
import           System.Environment   (getArgs, getProgName)
import           System.Exit          (ExitCode (..), exitWith)
import           Text.Read            (readMaybe)

import           AFrobRobotSim.Console (endOutput, stopProgram, tolerantOutput)
import           AFrobRobotSim.Options

-- | The @--param NAME=VALUE@ pairs of this program's command line, in the
-- order given (a name given twice keeps its last value, in its first
-- place; 'AFrobRobotSim.runSim' warns of it, see
-- 'AFrobRobotSim.Options.optParamsRepeated'). The command line is read
-- as 'AFrobRobotSim.runSim' reads it, flag by flag ('parseSimFlags'),
-- and what it would stop at there stops the program here, at once,
-- before anything else the program does: a flag it refuses (@--param
-- =5@, an unknown flag, @--seconds abc@), with its message on standard error
-- (@prog: --param expects NAME=VALUE, got "=5"@) and exit code 2;
-- @--help@, with the usage on standard output and exit code 0 (by
-- 'exitWith', so a caller may catch the 'ExitCode'). (It gave @[]@, and
-- the program went on with its defaults until 'AFrobRobotSim.runSim'
-- stopped it.) Whether the settings fit together (@--dt@ with the frame
-- rate, the number of steps) is left to the run: a program that runs
-- with 'AFrobRobotSim.runSimWith' may parse its flags over settings of
-- its own, where they fit when the defaults' would not. A program whose command line is not 'AFrobRobotSim.runSim''s
-- (as @afrp-examples NAME [flags]@ is) reads the parameters of its
-- flags with 'paramOrFrom' instead (or 'simParamsOf', which counts none
-- as read).
getSimParams :: IO [(String, String)]
getSimParams = atomicModifyIORef' paramReads (\(_, ns) -> ((True, ns), ())) >> commandLineParams

-- The @--param@s of this program's command line, or the program stopped
-- where 'AFrobRobotSim.runSim' would stop it for a flag of it (see
-- 'getSimParams').
commandLineParams :: IO [(String, String)]
commandLineParams = do
  args <- getArgs
  flagParams args $ do
    tolerantOutput
    prog <- getProgName
    putStrLn (usage prog)
    endOutput prog
    exitWith ExitSuccess

-- The @--param@s of a command line of 'AFrobRobotSim.runSim''s flags; at
-- @--help@, the given action (it gives none); a flag that
-- 'parseSimFlags' refuses stops the program, with its message on
-- standard error and exit code 2.
flagParams :: [String] -> IO [(String, String)] -> IO [(String, String)]
flagParams args atHelp = case parseSimFlags defaultSimOptions args of
  Right (RunWith o) -> pure (optParams o)
  Right ShowHelp    -> atHelp
  Left err -> do
    tolerantOutput
    prog <- getProgName
    stopProgram prog 2 err

-- The parameters this program has asked for: all of them ('getSimParams'),
-- or those named ('lookupSimParam', 'paramOr'), for 'unreadParams'.
paramReads :: IORef (Bool, [String])
paramReads = unsafePerformIO (newIORef (False, []))
{-# NOINLINE paramReads #-}

-- | The @--param@s of these options that the program has not asked for
-- so far (by 'paramOr', 'paramOrFrom' or 'lookupSimParam'; none once it
-- has asked for them all with 'getSimParams'), and the names it has asked
-- for, in order. 'AFrobRobotSim.runSim' warns of the first list, which is usually
-- a misspelled name: a run that ignores a parameter silently is a sweep
-- of identical runs. The record is the process's: a program that reads
-- its parameters otherwise ('simParamsOf' or 'readSimParam' on its own
-- arguments) is warned of them, unless it calls 'getSimParams'; names
-- asked for before an earlier 'AFrobRobotSim.runSim' of the same process
-- still count.
unreadParams :: SimOptions -> IO ([(String, String)], [String])
unreadParams o = do
  (everything, names) <- readIORef paramReads
  let asked = reverse names
  pure (if everything then [] else [ p | p@(k, _) <- optParams o, k `notElem` asked ], nub asked)

-- | The @--param@ pairs of a command line (as 'getSimParams', purely; a
-- command line whose flags 'parseSimFlags' refuses, or @--help@, gives
-- @[]@). No name is counted as asked for ('unreadParams'): a program
-- that reads a parameter of its own arguments, and means
-- 'AFrobRobotSim.runSim' not to warn of it, reads it with 'paramOrFrom'.
simParamsOf :: [String] -> [(String, String)]
simParamsOf args = case parseSimFlags defaultSimOptions args of
  Right (RunWith o) -> optParams o
  _                 -> []

-- | The value of one @--param@ of this program's command line, if given.
-- The name is matched as text in any locale; the value is as
-- 'System.Environment.getArgs' gives it (in a locale that is not UTF-8,
-- with stand-ins for the bytes beyond ASCII, so that a file it names
-- opens: 'AFrobRobotSim.Options.argText' makes it text). A command line
-- that 'AFrobRobotSim.runSim' would refuse, or @--help@, stops the
-- program here, as 'getSimParams' does.
lookupSimParam :: String -> IO (Maybe String)
lookupSimParam name = do
  askedFor name
  lookup name <$> commandLineParams

-- Count a parameter as asked for ('unreadParams').
askedFor :: String -> IO ()
askedFor name = atomicModifyIORef' paramReads (\(e, ns) -> ((e, name : ns), ()))

-- | @paramOr name def@: the @--param name=VALUE@ of this program's
-- command line read with 'Read' (a 'String' parameter must then be
-- quoted), or @def@ when it is not given. A value that does not read, or
-- that the type cannot hold (see 'readSimParam'), stops the program
-- before anything is simulated, as a malformed command line does
-- ('AFrobRobotSim.runSim'): a message naming the parameter on standard
-- error, and exit code 2 (by 'exitWith', so a caller may catch the
-- 'ExitCode'). So does a command line that 'AFrobRobotSim.runSim' would
-- refuse, with its message, and @--help@ prints the usage and ends the
-- program with exit code 0 ('getSimParams'), before the program's own
-- actions.
--
-- > prog: --param speed=fast: cannot read the value "fast" (write it as Haskell's read reads it: 0.5, 3, True, "quoted text")
-- > prog: --param n=99999999999999999999: the value "99999999999999999999" is out of range for this parameter (it would read as 7766279631452241919)
paramOr :: (Read a, Show a) => String -> a -> IO a
paramOr name def = lookupSimParam name >>= maybe (pure def) (readOrStop name)

-- | @paramOrFrom flags name def@: 'paramOr' reading the @--param@s of the
-- given flags, not of the program's command line: for a program whose
-- command line is its own, with 'AFrobRobotSim.runSim''s flags after its
-- own arguments (such as @afrp-examples NAME [flags]@: the flags after
-- the name). The name is counted as asked for, as 'paramOr' counts it, so
-- that a run with these flags ('AFrobRobotSim.runSimWith') does not warn
-- of it ('unreadParams'); 'simParamsOf' counts none. A value that does
-- not read, or that the type cannot hold, stops the program as
-- 'paramOr' stops it (its message, exit code 2), and so does a flag that
-- 'AFrobRobotSim.runSim' would refuse (@--param =5@, an unknown flag),
-- with its message. @--help@ among the flags is left to the program, whose
-- usage is its own (@afrp-examples NAME --help@ names the example): the
-- parameter reads as not given, @def@, and the flags after @--help@ are
-- not read, as 'AFrobRobotSim.runSim' reads none.
--
-- > prog wander --param speed=fast
-- > prog: --param speed=fast: cannot read the value "fast" (write it as Haskell's read reads it: 0.5, 3, True, "quoted text")
paramOrFrom :: (Read a, Show a) => [String] -> String -> a -> IO a
paramOrFrom flags name def = do
  askedFor name
  params <- flagParams flags (pure [])
  maybe (pure def) (readOrStop name) (lookup name params)

-- A parameter's value read ('readSimParam'), or the program stopped with
-- the message, exit code 2.
readOrStop :: (Read a, Show a) => String -> String -> IO a
readOrStop name v = do
  r <- try (evaluate (readSimParam name v))
  case r of
    Right (Right x)  -> pure x
    Right (Left msg) -> refuse msg
    Left (e :: SomeException) ->
      refuse ("--param " ++ name ++ "=" ++ v ++ ": the value " ++ show v ++ " cannot be made: "
              ++ displayException e)
  where
    refuse msg = getProgName >>= \prog -> stopProgram prog 2 msg

-- | @readSimParam name text@: a @--param name=text@'s value, as
-- 'paramOr' reads it, or the message it stops the program with. The
-- value is read with 'Read', and refused when it does not read, or when
-- it reads but the type cannot hold a number written in it: an integer
-- that a bounded type (such as 'Int' or 'Data.Word.Word8') wraps around,
-- or a number too large for a 'Double' or 'Float', which reads as
-- @Infinity@ although the text does not say so. The numbers are checked
-- wherever they are in the value (@[1,2,300]@ for a @[Word8]@,
-- @Just 300@, a record's field): the numbers the value's 'Show' writes
-- are compared with those of the text: every integer (or ratio @a % b@)
-- written back must be one of the text (in any order: a set writes its
-- elements back sorted), infinity only where the text has it, zero only
-- where the text has it (@1e-400@, which a 'Double' reads as @0.0@, is
-- refused). Where 'Show' writes fewer or more numbers than the text has
-- (a 'Data.Set.Set' drops the duplicates, a 'Data.Map.Map' the entries
-- of a repeated key), every integer or ratio written back must still be
-- one of the text's, any number of times, so a number wrapped onto
-- another that the text also holds is not seen (@fromList [44,300]@ as a
-- set of 'Data.Word.Word8' reads as @fromList [44]@), nor is a zero read
-- from a number that a 'Double' cannot hold beside a zero written. A
-- fraction that a 'Double' rounds to another nonzero number is not
-- refused. Reading never wraps silently where the value writes back as
-- many numbers as its text has:
--
-- >>> readSimParam "n" "300" :: Either String Int
-- Right 300
-- >>> either (const "refused") show (readSimParam "n" "[1,2,300]" :: Either String [Word8])
-- "refused"
-- >>> either (const "refused") show (readSimParam "n" "fromList [1,1,300]" :: Either String (Data.Set.Set Word8))
-- "refused"
--
-- The result is evaluated as far as that check needs: a value whose
-- 'Show' raises an exception (@1 % 0@ for a 'Rational') raises it here
-- ('paramOr' reports it).
readSimParam :: (Read a, Show a) => String -> String -> Either String a
readSimParam name v = case readMaybe v of
  Nothing -> Left (flag ++ ": cannot read the value " ++ show v
                   ++ " (write it as Haskell's read reads it: 0.5, 3, True, \"quoted text\")")
  Just x
    | NotANumber `elem` numerals (show x) ->
        Left (flag ++ ": the value " ++ show v ++ " is not a number (NaN), which no parameter may be")
    | not (numeralsHeld (numerals v) (numerals (show x))) ->
        Left (flag ++ ": the value " ++ show v ++ " is out of range for this parameter (it would read as "
              ++ show x ++ ")")
    | otherwise -> Right x
  where
    flag = "--param " ++ name ++ "=" ++ v

-- A number in a text, as Haskell's lexer reads it: an integer (decimal,
-- hexadecimal or octal, with a minus sign before it), a ratio @a % b@,
-- infinity, NaN, or any other floating-point number (whether it is
-- zero).
data Numeral = Whole Integer | Ratio Rational | Infinite | NotANumber | Floating Zero
            | PercentSign   -- (while lexing: the @%@ of a ratio)
  deriving (Eq)

-- Whether a floating-point number is zero (as written: no digit but 0
-- before its exponent).
newtype Zero = Zero Bool
  deriving (Eq)

-- The numbers of a text, in order (nothing inside a quoted string or
-- character counts: those are single tokens that are not numbers).
numerals :: String -> [Numeral]
numerals = ratios . numbersIn . tokens
  where
    tokens t = case lex t of
      [("", _)]    -> []
      [(tok, rest)] -> tok : tokens rest
      _            -> []
    numbersIn ("-" : tok : toks)
      | Just n <- readMaybe tok :: Maybe Integer = Whole (negate n) : numbersIn toks
    numbersIn (tok : toks)
      | Just n <- readMaybe tok :: Maybe Integer = Whole n : numbersIn toks
      | tok == "Infinity"                        = Infinite : numbersIn toks
      | tok == "NaN"                             = NotANumber : numbersIn toks
      | Just _ <- readMaybe tok :: Maybe Double  = Floating (Zero (all (`elem` "0.") (takeWhile (`notElem` "eE") tok)))
                                                   : numbersIn toks
      | tok == "%"                               = PercentSign : numbersIn toks
      | otherwise                                = numbersIn toks
    numbersIn [] = []
    ratios (Whole a : PercentSign : Whole b : ns)
      | b /= 0 = Ratio (fromInteger a / fromInteger b) : ratios ns
    ratios (PercentSign : ns) = ratios ns
    ratios (n : ns)           = n : ratios ns
    ratios []                 = []

-- Whether the numbers written back ('show') hold those written: when
-- there are as many, every integer or ratio written back must be one
-- written (as a multiset: a 'Data.Set.Set' or a 'Data.Map.Map' writes
-- its elements back in order, not as given), infinity only from
-- infinity, and zero only from zero (@1e-400@, which a 'Double' reads as
-- @0.0@, is not held). When there are fewer or more (a set drops its
-- duplicates: @fromList [1,1,300]@ as a set of 'Data.Word.Word8' is
-- written back @fromList [1,44]@), every integer or ratio written back
-- must still be one written, and infinity and zero written back must be
-- written somewhere. A number written back as a floating-point one (a
-- 'Double' written as @3@) is not otherwise compared.
numeralsHeld :: [Numeral] -> [Numeral] -> Bool
numeralsHeld written shown
  | length written /= length shown =
      all (`M.member` tally written) (exact shown)
        && (Infinite `notElem` shown || Infinite `elem` written)
        && (not (any isZero shown) || any isZero written)
  | otherwise = M.isSubmapOfBy (<=) (tally shown) (tally written)
                && count (== Infinite) shown <= count (== Infinite) written
                && count isZero shown <= count isZero written
  where
    -- (each exact number with the times it is there; a parameter's text
    -- may hold tens of thousands)
    tally ns = M.fromListWith (+) [ (r, 1 :: Int) | r <- exact ns ]
    exact ns = [ r | n <- ns, Just r <- [asRational n] ]
    asRational (Whole a) = Just (fromInteger a)
    asRational (Ratio a) = Just a
    asRational _         = Nothing
    count p = length . filter p
    isZero n = case n of
      Floating (Zero z) -> z
      _                 -> asRational n == Just 0
