-- | @afrp-examples@'s command line ("Examples.CommandLine"), run as the
-- executable runs it: the test binary started with 'childVariable' set
-- runs 'examplesMain' under the name @afrp-examples@ ('child'), so that
-- its exit codes and its output are the executable's.
module Examples.CommandLineSpec (spec, childVariable, child) where

import           Control.Monad      (forM_)
import           Data.List          (isInfixOf, isPrefixOf, isSuffixOf)
import           System.Environment (getEnvironment, getExecutablePath, withProgName)
import           System.Exit        (ExitCode (..))
import           System.Process     (CreateProcess (..), proc, readCreateProcessWithExitCode)
import           Test.Hspec

import           AFrobRobotSim        (usage)
import           Examples.CommandLine (examplesMain)
import           Examples.Registry    (allExamples)
import           Examples.Types       (Example (..))

-- | The environment variable that makes the test binary run 'child'.
childVariable :: String
childVariable = "AFRP_SPEC_EXAMPLES_CHILD"

-- | The test binary as a child: @afrp-examples@ with the child's
-- arguments.
child :: String -> IO ()
child _ = withProgName "afrp-examples" examplesMain

-- @afrp-examples ARGS@: the exit code, standard output and standard error.
examples :: [String] -> IO (ExitCode, String, String)
examples args = do
  self <- getExecutablePath
  environment <- getEnvironment
  readCreateProcessWithExitCode (proc self args) { env = Just ((childVariable, "afrp-examples") : environment) } ""

spec :: Spec
spec = do
  describe "afrp-examples' --print-program" $
    it "NAME --print-program prints the example's name as its result line writes it, a JSON string, and runs nothing (scripts/sweep asks it so)" $ do
      examples ["rcReverse", "--print-program"] `shouldReturn` (ExitSuccess, "\"afrp-examples rcReverse\"\n", "")
      -- (no world read, and nothing written: a world file that is not there)
      examples ["rcReverse", "--seconds", "3", "--log", "/nonexistent/x.jsonl", "--world", "/nonexistent/w.world", "--print-program"]
        `shouldReturn` (ExitSuccess, "\"afrp-examples rcReverse\"\n", "")
      -- (with --dump-world, which prints too: refused, neither printed)
      examples ["rcReverse", "--dump-world", "--print-program"] `shouldReturn`
        (ExitFailure 2, "", "afrp-examples: --dump-world and --print-program (optDumpWorld and optPrintProgram) each print something and exit: ask for one\n")
  describe "afrp-examples' --help" $ do
    it "--help prints the program's usage, exit 0" $ do
      (code, out, err) <- examples ["--help"]
      (code, err) `shouldBe` (ExitSuccess, "")
      out `shouldSatisfy` ("usage: afrp-examples --list\n       afrp-examples NAME [simulator flags]\n" `isPrefixOf`)
      out `shouldSatisfy` ("afrp-examples NAME --help lists them" `isInfixOf`)
    it "NAME --help prints the simulator's usage named for the example, exit 0, after flags it takes; a fault before it is refused (exit 2)" $ do
      examples ["rcReverse", "--seconds", "3", "--help"] `shouldReturn` (ExitSuccess, usage "afrp-examples rcReverse" ++ "\n", "")
      examples ["rcReverse", "-h", "--frobnicate"] `shouldReturn` (ExitSuccess, usage "afrp-examples rcReverse" ++ "\n", "")
      examples ["rcReverse", "--frobnicate", "--help"] `shouldReturn`
        (ExitFailure 2, "", "afrp-examples: unknown argument \"--frobnicate\" (see --help)\n")
      examples ["nosuch", "--help"] `shouldReturn`
        (ExitFailure 2, "", "afrp-examples: no example named \"nosuch\" (--list shows them all)\n")
    it "--help or -h first prints the usage, exit 0, whatever follows, as a simulation's --help does (-h was refused, and anything after --help; exit 2)" $ do
      (_, help, _) <- examples ["--help"]
      forM_ [["-h"], ["--help", "rcReverse"], ["-h", "--list"], ["--help", "--frobnicate"]] $ \args ->
        examples args `shouldReturn` (ExitSuccess, help, "")
    it "--list then --help or -h prints the usage, exit 0 (it was refused); --list then anything else is refused" $ do
      (_, help, _) <- examples ["--help"]
      examples ["--list", "--help"] `shouldReturn` (ExitSuccess, help, "")
      examples ["--list", "-h", "rcReverse"] `shouldReturn` (ExitSuccess, help, "")
      examples ["--list", "rcReverse", "--help"] `shouldReturn`
        (ExitFailure 2, "", "afrp-examples: --list takes nothing after it, got \"rcReverse\" \"--help\"\n")
    it "a signal-function example's --help says what it is and that it takes no flags, exit 0 (it was refused: exit 2); a flag before it is refused" $ do
      let described = head [ exDescription e | e <- allExamples, exName e == "xSF" ]
          help = "usage: afrp-examples xSF\n\n" ++ described ++ "\nA signal-function example: it prints a short report, and takes no flags.\n"
      examples ["xSF", "--help"] `shouldReturn` (ExitSuccess, help, "")
      examples ["xSF", "-h", "--seconds", "3"] `shouldReturn` (ExitSuccess, help, "")
      examples ["xSF", "--seconds", "3", "--help"] `shouldReturn`
        (ExitFailure 2, "", "afrp-examples: xSF is a signal-function example; it takes no flags\n")
    it "the usage ends with its last line, as the simulator's does (it ended with a blank line)" $ do
      (_, help, _) <- examples ["--help"]
      help `shouldSatisfy` ("report.\n" `isSuffixOf`)
