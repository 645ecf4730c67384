-- | @afrp-examples@'s command line ("Examples.CommandLine"), run as the
-- executable runs it: the test binary started with 'childVariable' set
-- runs 'examplesMain' under the name @afrp-examples@ ('child'), so that
-- its exit codes and its output are the executable's.
module Examples.CommandLineSpec (spec, childVariable, child) where

import           Data.List          (isInfixOf, isPrefixOf)
import           System.Environment (getEnvironment, getExecutablePath, withProgName)
import           System.Exit        (ExitCode (..))
import           System.Process     (CreateProcess (..), proc, readCreateProcessWithExitCode)
import           Test.Hspec

import           AFrobRobotSim        (usage)
import           Examples.CommandLine (examplesMain)

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
spec =
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
