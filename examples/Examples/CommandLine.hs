-- | @afrp-examples@'s command line: @--list@, @--help@, or an example's
-- name and then the simulator's flags ('exampleCommand'). In a module of
-- its own, not in @Main@, so that the tests run it as the executable does.
module Examples.CommandLine
  ( examplesMain
  ) where

import           Data.Char          (toLower)
import           Data.List          (isPrefixOf, sortOn)
import           System.Environment (getArgs, getProgName)
import           System.Exit        (ExitCode (..), exitWith)

import           AFrobRobotSim
import           AFrobRobotSim.Console (endOutput, putErr)
import           Examples.Registry  (allExamples, exampleCommand, exampleListing)
import           Examples.Types

-- | @afrp-examples@ itself: its command line read, the example run (or
-- listed, or the usage printed), and exit code 2 for a command line it
-- refuses, with the message on standard error.
examplesMain :: IO ()
examplesMain = do
  args <- getArgs
  prog <- getProgName
  run prog args
  endOutput prog   -- (what was printed reached standard output, or exit code 1)

run :: String -> [String] -> IO ()
run prog args =
  case args of
    []             -> usageError prog "give an example name, or --list"
    ["--list"]     -> putStr (exampleListing allExamples)
    ["--help"]     -> putStrLn (helpText prog)
    flag : extra
      | flag `elem` ["--list", "--help"] -> usageError prog (flag ++ " takes nothing after it, got " ++ unwords (map show extra))
      | "-" `isPrefixOf` flag -> usageError prog ("the flag " ++ show flag ++ " is not one of " ++ prog ++ "'s own (--list, "
                                                  ++ "--help); a simulator flag comes after an example's name ("
                                                  ++ prog ++ " NAME " ++ flag ++ " ...)")
    name : flags   -> case [ e | e <- allExamples, exName e == name ] of
      e : _ -> runExample prog e flags
      []    -> usageError prog ("no example named " ++ show name ++ suggestion name)

runExample :: String -> Example -> [String] -> IO ()
runExample prog e flags = case (e, flags) of
  (SignalExample {}, []) -> putStr (exReport e)
  -- (a signal-function example with flags is a Left)
  _ -> case exampleCommand prog e flags of
    Left err            -> usageError prog err
    Right ShowHelp      -> putStrLn (usage (prog ++ " " ++ exName e))
    Right (RunWith opt) -> runSimRefereedWith opt (exReferee e) (Just (exWorld e)) (exControllerA e) (exControllerB e)

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

usageError :: String -> String -> IO a
usageError prog msg = putErr (prog ++ ": " ++ msg ++ "\n") >> exitWith (ExitFailure 2)
