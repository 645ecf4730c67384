-- | "AFrobRobotSim.Console": names, messages and errors made safe to print
-- (nothing that forges or hides a line reaches the terminal, what prints
-- is kept). Standard output's failures are tested through the programs
-- ("AFrobRobotSim.RunSpec", "AFrobRobotSim.SweepSpec").
module AFrobRobotSim.ConsoleSpec (spec) where

import           Control.Exception (try)
import           Data.Char         (isPrint)
import           Data.List         (isInfixOf)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.Console

spec :: Spec
spec = do
  describe "displayPath" $ do
    it "shows a printable name as it is, any other quoted with its controls escaped" $ do
      displayPath "simbot-out/run.svg" `shouldBe` "simbot-out/run.svg"
      displayPath "out/\228 b.svg" `shouldBe` "out/\228 b.svg"
      displayPath "a\nwrote b" `shouldBe` "\"a\\nwrote b\""
      displayPath "x\ESC[2Jy" `shouldBe` "\"x\\ESC[2Jy\""
    it "never lets a character that does not print through (property)" $ property $ \f ->
      all isPrint (displayPath f)
  describe "quote" $ do
    it "escapes the quote, the backslash and what does not print (a quote was left bare)" $ do
      quote "say \"hi\"" `shouldBe` "\"say \\\"hi\\\"\""
      quote "a\\n\n" `shouldBe` "\"a\\\\n\\n\""
    it "reads back, as a Haskell literal, as the text it quotes (property)" $ property $ \t ->
      read (quote t) == t
  describe "printableLine" $
    it "escapes what could forge or hide output, and keeps accents, emoji and joiners" $ do
      printableLine "caf\233 \128104\8205\128187" `shouldBe` "caf\233 \128104\8205\128187"
      printableLine "a\ESC[2Jb\nc" `shouldBe` "a\\ESC[2Jb\\nc"
      printableLine "x\8238y\8232z\55296" `shouldBe` "x\\8238y\\8232z\\55296"
  describe "ioErrorText" $
    it "makes an I/O failure naming a file with a newline one printable line" $ do
      r <- try (readFile "/no/such/dir/a\nb")
      case r of
        Left e  -> do
          let t = ioErrorText e
          t `shouldSatisfy` all isPrint
          t `shouldSatisfy` ("a\\nb" `isInfixOf`)
        Right _ -> expectationFailure "read a file that cannot exist"
