-- | Tests for "AFRP.EventSource.Sample": samples of the input, on fixed
-- input lists with hand-computed outputs.
module AFRP.EventSource.SampleSpec (spec) where

import           Control.Exception       (ErrorCall (..), evaluate)
import           Data.List               (isInfixOf, isPrefixOf)
import           Test.Hspec

import           AFRP.Event              (Event)
import           AFRP.EventSource.Sample
import           AFRP.EventSourceFixture
import           AFRP.Internal.SF        (SF)
import           TestUtil                (runDt, runSamples, withoutHanging)

-- | An error call whose message (not its location) mentions the text.
errorMentioning :: String -> Selector ErrorCall
errorMentioning s (ErrorCallWithLocation msg _) = s `isInfixOf` msg

spec :: Spec
spec = do
  describe "snap" $ do
    it "occurs at time 0 only, carrying the input there" $
      runDt 1 snap [10, 11, 12 :: Int] `shouldBe` [e 10, n, n]

  describe "snapAfter" $ do
    it "occurs once at the first sample at or after t, with that input" $
      runDt 0.5 (snapAfter 1.0) [10, 11, 12, 13 :: Int] `shouldBe` [n, n, e 12, n]
    it "occurs past t when no sample falls on it" $
      runDt 0.4 (snapAfter 1.0) [10, 11, 12, 13, 14 :: Int] `shouldBe` [n, n, n, e 13, n]
    it "with t = 0 occurs at time 0" $
      runDt 1 (snapAfter 0) "ab" `shouldBe` [e 'a', n]
    it "rejects a negative t, as after does" $
      evaluate (length (runDt 1 (snapAfter (-2)) "ab")) `shouldThrow` anyErrorCall

  describe "sample" $ do
    it "refuses a period that is not positive, naming itself (it named repeatedly)" $
      mapM_ (\p -> evaluate (sample p :: SF () (Event ()))
                     `shouldThrow` (\(ErrorCall m) -> "AFRP.EventSource.sample: the period must be positive" `isPrefixOf` m))
            [0, -1, 0 / 0]
    it "occurs every p seconds (not at 0) with the input at that instant" $
      runDt 0.25 (sample 0.5) [0 .. 6 :: Int] `shouldBe` [n, n, e 2, n, e 4, n, e 6]
    it "produces one occurrence when a step spans several periods" $
      runSamples (sample 0.5) [(0, 'a'), (2, 'b'), (0.25, 'c'), (0.25, 'd')]
        `shouldBe` [n, e 'b', n, e 'd']

  describe "sampleWindow" $ do
    it "produces the last w samples, oldest first, at each sampling instant" $
      runDt 0.25 (sampleWindow 2 0.5) [0 .. 8 :: Int]
        `shouldBe` [n, n, e [2], n, e [2, 4], n, e [4, 6], n, e [6, 8]]
    it "takes one sample per period when a step spans several periods" $
      -- times 0, .5, 2.0, 2.5: the step to 2.0 spans 1.0, 1.5 and 2.0
      runSamples (sampleWindow 3 0.5) [(0, 0), (0.5, 1), (1.5, 2), (0.5, 3 :: Int)]
        `shouldBe` [n, e [1], e [2, 2, 2], e [2, 2, 3]]
    it "a step spanning more periods than the window fills it with that step's input" $
      runSamples (sampleWindow 3 0.5) [(0, 0), (0.5, 1), (10, 2), (0.5, 3 :: Int)]
        `shouldBe` [n, e [1], e [2, 2, 2], e [2, 2, 3]]
    it "a step spanning billions of periods ends at once, in bounded memory (it built a list of every period)" $ do
      runSamples (sampleWindow 3 1e-6) [(0, 'a'), (1e6, 'b'), (0.5, 'c'), (1e-6, 'd')]
        `withoutHanging` [n, e "bbb", e "ccc", e "ccd"]
      -- more periods than a Double counts, a period below the clock's
      -- resolution, and an infinite time: every sample fills the window
      runSamples (sampleWindow 2 1e-300) [(0, 'a'), (1, 'b'), (1, 'c')]
        `withoutHanging` [n, e "bb", e "cc"]
      runSamples (sampleWindow 2 1e-9) [(0, 'a'), (1e9, 'b'), (1e-9, 'c')]
        `withoutHanging` [n, e "bb", e "cc"]
      runSamples (sampleWindow 2 1) [(0, 'a'), (1 / 0, 'b'), (1, 'c')]
        `withoutHanging` [n, e "bb", e "cc"]
    it "has no instant at a sample where no time passes (it filled the window where every instant counts as reached)" $ do
      runSamples (sampleWindow 2 1e-13) [(0, 'a'), (1000, 'b'), (0, 'c'), (0, 'd'), (1, 'e')]
        `withoutHanging` [n, e "bb", n, n, e "ee"]
      runSamples (sampleWindow 2 1) [(0, 'a'), (1 / 0, 'b'), (0, 'c'), (1, 'd')]
        `withoutHanging` [n, e "bb", n, e "dd"]
      runSamples (sampleWindow 2 0.5) [(0, 'a'), (0.5, 'b'), (0, 'c'), (0.5, 'd')]
        `shouldBe` [n, e "b", n, e "bd"]
    it "a huge window costs no more than a small one (it counted the periods one by one up to its size)" $ do
      let lens = map (fmap length) . drop 1
      lens (runSamples (sampleWindow 5000 1) [(0, 'a'), (4500.5, 'b'), (2, 'c')]) `shouldBe` [e 4500, e 4502]
      fmap (fmap (take 2)) (runSamples (sampleWindow maxBound 1) [(0, 'a'), (1e12, 'b'), (1e300, 'c')])
        `withoutHanging` [n, e "bb", e "cc"]
      fmap (fmap (take 2)) (runSamples (sampleWindow maxBound 1e-300) [(0, 'a'), (1, 'b')])
        `withoutHanging` [n, e "bb"]
    it "after a step spanning many periods, the instants stay on the multiples of the period" $
      -- 20,000 periods of 0.5 in one step (counted at once), then steps of 0.25
      runSamples (sampleWindow 2 0.5) ((0, 0) : (10000.25, 1) : [ (0.25, k) | k <- [2 .. 6 :: Int] ])
        `shouldBe` [n, e [1, 1], e [1, 2], n, e [2, 4], n, e [4, 6]]
    it "with a window of 1 is sample with singleton lists" $
      runDt 0.5 (sampleWindow 1 1) "abcde" `shouldBe` [n, n, e "c", n, e "e"]
    it "with a window below 1 is an error" $
      forceEvents (runDt 1 (sampleWindow 0 1) [(), ()]) `shouldThrow` errorMentioning "window"
    it "with a zero period is an error" $
      forceEvents (runDt 1 (sampleWindow 2 0) [(), ()]) `shouldThrow` anyErrorCall
    it "with a negative period is an error" $
      forceEvents (runDt 1 (sampleWindow 2 (-1)) [(), ()]) `shouldThrow` anyErrorCall
