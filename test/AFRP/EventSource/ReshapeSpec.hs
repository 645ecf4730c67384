-- | Tests for "AFRP.EventSource.Reshape": the first occurrences of a
-- stream let through or held back, on fixed input lists with
-- hand-computed outputs.
module AFRP.EventSource.ReshapeSpec (spec) where

import           Test.Hspec

import           AFRP.Event               (Event)
import           AFRP.EventSource.Reshape
import           AFRP.EventSourceFixture
import           TestUtil                 (runDt)

spec :: Spec
spec = do
  describe "notYet" $ do
    it "suppresses an occurrence at time 0 and passes later ones" $
      runDt 1 notYet [e 1, e 2, n, e (3 :: Int)] `shouldBe` [n, e 2, n, e 3]
    it "passes occurrences from the second sample on" $
      runDt 1 notYet [n, e 'a'] `shouldBe` [n, e 'a']

  describe "once" $ do
    it "passes only the first occurrence" $
      runDt 1 once [n, e 1, e 2, n, e (3 :: Int)] `shouldBe` [n, e 1, n, n, n]
    it "passes an occurrence at time 0 and nothing after" $
      runDt 1 once [e 'a', e 'b', e 'c'] `shouldBe` [e 'a', n, n]

  describe "takeEvents" $ do
    it "passes the first n occurrences" $
      runDt 1 (takeEvents 2) [e 1, n, e 2, e 3, e (4 :: Int)] `shouldBe` [e 1, n, e 2, n, n]
    it "with 0 (or less) passes nothing" $ do
      runDt 1 (takeEvents 0) [e 'a', e 'b'] `shouldBe` [n, n]
      runDt 1 (takeEvents (-3)) [e 'a', e 'b'] `shouldBe` [n, n]

  describe "dropEvents" $ do
    it "suppresses the first n occurrences, then passes all" $
      runDt 1 (dropEvents 2) [e 1, n, e 2, e 3, n, e (4 :: Int)] `shouldBe` [n, n, n, e 3, n, e 4]
    it "with 0 is the identity" $
      runDt 1 (dropEvents 0) [e 'a', n, e 'b'] `shouldBe` [e 'a', n, e 'b']
    it "does not look at an input sample before the next sample while it drops (as Yampa)" $ do
      let bad = error "input" :: Event Int
      take 2 (runDt 1 (dropEvents 1) [n, bad, e 1]) `shouldBe` [n, n]
      take 3 (runDt 1 (dropEvents 2) [e 1, n, bad, e 2]) `shouldBe` [n, n, n]
      forceEvents (runDt 1 (dropEvents 1) [n, bad, e 1]) `shouldThrow` errorCall "input"
      -- (once the occurrences are dropped, the input is the output)
      forceEvents (take 2 (runDt 1 (dropEvents 1) [e 0, bad])) `shouldThrow` errorCall "input"
