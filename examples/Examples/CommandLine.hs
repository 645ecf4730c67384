-- | @afrp-examples@'s command line: @--list@, @--help@, or an example's
-- name and then the simulator's flags ('exampleCommand'). In a module of
-- its own, not in @Main@, so that the tests run it as the executable does.
--
-- @--help@ (or @-h@) is read as a simulation's command line reads it
-- ('AFrobRobotSim.parseSimFlags'): from the left, the first argument that
-- is @--help@ or a fault decides. So @afrp-examples --help ...@,
-- @afrp-examples --list --help@ and @afrp-examples NAME --seconds 3
-- --help@ print a usage and exit with 0, and @afrp-examples nosuch
-- --help@ and @afrp-examples NAME --frobnicate --help@ are refused (exit
-- 2).
module Examples.CommandLine
  ( examplesMain
  ) where

import           Data.Char          (toLower)
import           Data.List          (intercalate, isPrefixOf, sortOn)
import           System.Environment (getArgs, getProgName)

import           AFrobRobotSim
import           AFrobRobotSim.Console (endOutput, guardOutput, stopProgram)
import           Examples.Registry  (allExamples, exampleCommand, exampleListing)
import           Examples.Types

-- | @afrp-examples@ itself: its command line read, the example run (or
-- listed, or a usage printed: the program's, the simulator's named for a
-- robot example, a line on what a signal-function example is), and exit
-- code 2 for a command line it refuses, with the message on standard
-- error.
examplesMain :: IO ()
examplesMain = do
  args <- getArgs
  prog <- getProgName
  guardOutput prog (run prog args)
  endOutput prog   -- (what was printed reached standard output, or exit code 1)

run :: String -> [String] -> IO ()
run prog args =
  case args of
    []             -> stopProgram prog 2 "give an example name, or --list"
    flag : _
      | isHelpFlag flag -> putStr (helpText prog)
    ["--list"]     -> putStr (exampleListing allExamples)
    "--list" : flag : _
      | isHelpFlag flag -> putStr (helpText prog)
    flag : extra
      | flag == "--list" -> stopProgram prog 2 (flag ++ " takes nothing after it, got " ++ unwords (map show extra))
      | "-" `isPrefixOf` flag -> stopProgram prog 2 ("the flag " ++ show flag ++ " is not one of " ++ prog ++ "'s own (--list, "
                                                  ++ "--help); a simulator flag comes after an example's name ("
                                                  ++ prog ++ " NAME " ++ flag ++ " ...)")
    name : flags   -> case [ e | e <- allExamples, exName e == name ] of
      e : _ -> runExample prog e flags
      []    -> stopProgram prog 2 ("no example named " ++ show name ++ suggestion name)

runExample :: String -> Example -> [String] -> IO ()
runExample prog e flags = case (e, flags) of
  (SignalExample {}, []) -> putStr (exReport e)
  -- (a signal-function example with flags is a Left)
  _ -> case exampleCommand prog e flags of
    Left err            -> stopProgram prog 2 err
    Right ShowHelp      -> putStrLn (exampleHelp prog e)
    Right (RunWith opt) -> runSimRefereedWith opt (exReferee e) (Just (exWorld e)) (exControllerA e) (exControllerB e)


-- @NAME --help@: the simulator's usage named for a robot example; what a
-- signal-function example is.
exampleHelp :: String -> Example -> String
exampleHelp prog e = case e of
  RobotExample {}  -> usage (prog ++ " " ++ exName e)
  SignalExample {} -> intercalate "\n"
    [ "usage: " ++ prog ++ " " ++ exName e
    , ""
    , exDescription e
    , "A signal-function example: it prints a short report, and takes no flags." ]

suggestion :: String -> String
suggestion name = case sortOn length [ exName e | e <- allExamples, lower name `isPrefixOf` lower (exName e) ] of
  n : _ -> " (did you mean " ++ n ++ "?)"
  []    -> " (--list shows them all)"
  where lower = map toLower

helpText :: String -> String
helpText prog = unlines
  [ "usage: " ++ prog ++ " --list"
  , "       " ++ prog ++ " NAME [simulator flags]"
  , ""
  , "Runs one example of the notes headless. Robot examples take every flag of"
  , "the simulator (" ++ prog ++ " NAME --help lists them); those that read the"
  , "keyboard take scripted key presses with --keys \"1.5:+,3:+\" (--list shows"
  , "which, with their default script). Signal-function examples print a short"
  , "report."
  ]
