-- | The examples' registry: a robot example's command line, with the
-- example's own defaults.
module Examples.RegistrySpec (spec) where

import           Test.Hspec

import           AFrobRobotSim     (Command (..), SimOptions (..))
import           Examples.Registry (allExamples, exampleCommand)
import           Examples.Types

spec :: Spec
spec =
  describe "exampleCommand" $ do
    let named n = head [ e | e <- allExamples, exName e == n ]
        keysOf flags = case exampleCommand "afrp-examples" (named "ex6-robot") flags of
          Right (RunWith o) -> Right (optKeys o, optSeconds o)
          Right ShowHelp    -> Left "help"
          Left err          -> Left err
    it "scripts the example's own keys, and its seconds, when the command line gives none" $
      keysOf [] `shouldBe` Right (exKeys (named "ex6-robot"), exSeconds (named "ex6-robot"))
    it "takes the command line's --keys instead of the example's script, all of them, and its --seconds" $ do
      keysOf ["--keys", "1:+"] `shouldBe` Right ([(1, '+')], exSeconds (named "ex6-robot"))
      keysOf ["--keys", "1:+", "--seconds", "4", "--keys", "2:x"] `shouldBe` Right ([(1, '+'), (2, 'x')], 4)
      keysOf ["--keys", ""] `shouldBe` Right ([], exSeconds (named "ex6-robot"))
    it "names the example in the result line (optProgram), so that two examples' lines are told apart (both were \"afrp-examples\")" $ do
      let programOf e flags = case exampleCommand "afrp-examples" e flags of
            Right (RunWith o) -> optProgram o
            _                 -> Nothing
          robots = [ e | e@RobotExample {} <- allExamples ]
      programOf (named "rcReverse") ["--seconds", "1"] `shouldBe` Just "afrp-examples rcReverse"
      map (\e -> programOf e []) robots `shouldBe` [ Just ("afrp-examples " ++ exName e) | e <- robots ]
    it "refuses flags for a signal-function example, and passes a malformed command line's fault on" $ do
      fmap (const ()) (exampleCommand "afrp-examples" (named "xSF") ["--seconds", "3"])
        `shouldBe` Left "xSF is a signal-function example; it takes no flags"
      fmap (const ()) (exampleCommand "afrp-examples" (named "ex6-robot") ["--frobnicate"]) `shouldSatisfy` either (const True) (const False)
    it "asks for the usage at --help or -h first for a signal-function example (it refused it as a flag), not after another flag" $ do
      exampleCommand "afrp-examples" (named "xSF") ["--help"] `shouldBe` Right ShowHelp
      exampleCommand "afrp-examples" (named "xSF") ["-h", "--seconds", "3"] `shouldBe` Right ShowHelp
      exampleCommand "afrp-examples" (named "xSF") ["--seconds", "3", "--help"]
        `shouldBe` Left "xSF is a signal-function example; it takes no flags"
