module AFrobRobotSim.Replay.CommandLineSpec (spec) where

import           Test.Hspec

import           AFrobRobotSim.Replay.CommandLine (replayFromArgs)

-- (replayFromMain's messages and exit codes, through simbot's own
-- process: RunSpec's "replayfrom" child)
spec :: Spec
spec =
  describe "replayFromArgs (simbot --replay-from's command line)" $ do
    it "takes the two flags in either order" $ do
      replayFromArgs ["--replay-from", "a.jsonl", "--replay", "a.html"] `shouldBe` Right ("a.jsonl", "a.html")
      replayFromArgs ["--replay", "a.html", "--replay-from", "a.jsonl"] `shouldBe` Right ("a.jsonl", "a.html")
      replayFromArgs ["--replay", "./--replay", "--replay-from", ""] `shouldBe` Right ("", "./--replay")
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
