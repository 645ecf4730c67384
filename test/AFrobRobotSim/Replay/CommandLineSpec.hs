module AFrobRobotSim.Replay.CommandLineSpec (spec) where

import           Test.Hspec

import           AFrobRobotSim.Replay.CommandLine (ReplayCommand (..), replayFromArgs)

-- (replayFromMain's messages and exit codes, through simbot's own
-- process: RunSpec's "replayfrom" child)
spec :: Spec
spec =
  describe "replayFromArgs (simbot --replay-from's command line)" $ do
    it "takes the two flags in either order" $ do
      replayFromArgs ["--replay-from", "a.jsonl", "--replay", "a.html"] `shouldBe` Right (ReplayFrom "a.jsonl" "a.html")
      replayFromArgs ["--replay", "a.html", "--replay-from", "a.jsonl"] `shouldBe` Right (ReplayFrom "a.jsonl" "a.html")
      replayFromArgs ["--replay", "./--replay", "--replay-from", ""] `shouldBe` Right (ReplayFrom "" "./--replay")
    it "asks for the usage at --help or -h, read from the left as a simulation's command line is: unless a fault comes first (it refused --help as another argument)" $ do
      -- (as parseSimFlags: simbot --seconds 3 --help prints the usage,
      -- simbot --frobnicate --help is refused for --frobnicate)
      mapM_ (\args -> replayFromArgs args `shouldBe` Right ReplayHelp)
        [ ["--replay-from", "a.jsonl", "--replay", "a.html", "--help"]
        , ["--replay-from", "a.jsonl", "--replay", "a.html", "-h"]
        , ["--replay-from", "a.jsonl", "--help"]
        , ["--replay", "a.html", "--help", "--frobnicate"]
        , ["--help", "--replay-from", "a.jsonl", "--replay-from", "b.jsonl"] ]
      replayFromArgs ["--replay-from", "a.jsonl", "--frobnicate", "--help"] `shouldBe`
        Left "--replay-from FILE.jsonl --replay OUT.html takes no other argument, got \"--frobnicate\""
      replayFromArgs ["--replay-from", "a.jsonl", "--replay-from", "b.jsonl", "--help"] `shouldBe`
        Left "--replay-from is given twice: --replay-from FILE.jsonl --replay OUT.html"
      -- (a flag for a value is a value left out, as in a simulation's
      -- command line: --help was read as the log's name)
      replayFromArgs ["--replay-from", "--help", "--replay", "a.html"] `shouldBe`
        Left "--replay-from needs the name of the run log to read (written with --log), found the flag --help"
      replayFromArgs ["--replay-from", "./--help", "--replay", "a.html"] `shouldBe` Right (ReplayFrom "./--help" "a.html")
    it "says what is missing: a flag's value, or the other flag (it said \"needs --replay OUT.html and no other flag\")" $ do
      replayFromArgs ["--replay-from"] `shouldBe`
        Left "--replay-from needs the name of the run log to read (written with --log): --replay-from FILE.jsonl --replay OUT.html"
      replayFromArgs ["--replay", "a.html", "--replay-from"] `shouldBe`
        Left "--replay-from needs the name of the run log to read (written with --log): --replay-from FILE.jsonl --replay OUT.html"
      replayFromArgs ["--replay-from", "a.jsonl", "--replay"] `shouldBe`
        Left "--replay needs the name of the page to write: --replay-from FILE.jsonl --replay OUT.html"
      replayFromArgs ["--replay-from", "--replay", "a.html"] `shouldBe`
        Left "--replay-from needs the name of the run log to read (written with --log), found the flag --replay"
      replayFromArgs ["--replay-from", "a.jsonl"] `shouldBe`
        Left "--replay-from needs --replay OUT.html, the page to write: --replay-from FILE.jsonl --replay OUT.html"
      replayFromArgs ["--replay", "a.html"] `shouldBe`
        Left "--replay needs --replay-from FILE.jsonl, the run log to read: --replay-from FILE.jsonl --replay OUT.html"
    it "refuses a flag given twice and any other argument, naming it" $ do
      replayFromArgs ["--replay-from", "a.jsonl", "--replay", "a.html", "--replay-from", "b.jsonl"] `shouldBe`
        Left "--replay-from is given twice: --replay-from FILE.jsonl --replay OUT.html"
      replayFromArgs ["--replay-from", "a.jsonl", "--seconds", "3", "--replay", "a.html"] `shouldBe`
        Left "--replay-from FILE.jsonl --replay OUT.html takes no other argument, got \"--seconds\""
