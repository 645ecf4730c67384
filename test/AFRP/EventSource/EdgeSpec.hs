-- | Tests for "AFRP.EventSource.Edge": the edges of a Boolean or Maybe
-- input, on fixed input lists with hand-computed outputs.
module AFRP.EventSource.EdgeSpec (spec) where

import           Control.Arrow         (arr, (>>>))
import           Data.Maybe            (fromMaybe)
import           Test.Hspec

import           AFRP.EventSource.Edge
import           AFRP.EventSourceFixture
import           AFRP.Internal.SF      (SF)
import           AFRP.Run              (embed)
import           TestUtil              (runDt)

-- | Feed the signal function a bottom wherever the outer input is
-- 'Nothing'. The runner may force each outer sample, but not what the
-- inner signal function receives, so this observes whether the signal
-- function under test evaluates its current input.
bottomWhereNothing :: SF a b -> SF (Maybe a) b
bottomWhereNothing sf = arr (fromMaybe (error "the current input was evaluated")) >>> sf

spec :: Spec
spec = do
  describe "edge" $ do
    it "occurs on rising edges only" $
      runDt 1 edge [False, True, True, False, True] `shouldBe` [n, e (), n, n, e ()]
    it "does not occur for True at time 0" $
      runDt 1 edge [True, True, False, True] `shouldBe` [n, n, n, e ()]
    it "follows the documented example" $
      embed edge (True, [(1, Just False), (1, Just True), (1, Nothing)])
        `shouldBe` [n, n, e (), n]

  describe "iEdge" $ do
    it "iEdge False occurs for True at time 0" $
      runDt 1 (iEdge False) [True, True, False, True] `shouldBe` [e (), n, n, e ()]
    it "iEdge False does not occur for False at time 0" $
      runDt 1 (iEdge False) [False, True] `shouldBe` [n, e ()]
    it "iEdge True does not occur for True at time 0" $
      runDt 1 (iEdge True) [True, False, True] `shouldBe` [n, n, e ()]

  describe "edgeTag" $ do
    it "is edge carrying the given value" $
      runDt 1 (edgeTag 'k') [True, False, True, True] `shouldBe` [n, n, e 'k', n]
    it "does not occur for True at time 0" $
      runDt 1 (edgeTag 'k') [True] `shouldBe` [n]

  describe "edgeJust" $ do
    it "occurs, with the value, on each change from Nothing to Just" $
      runDt 1 edgeJust [Just 1, Nothing, Just 2, Just 3, Nothing, Nothing, Just (4 :: Int)]
        `shouldBe` [n, n, e 2, n, n, n, e 4]
    it "occurs right after a Nothing at time 0" $
      runDt 1 edgeJust [Nothing, Just 'v', Just 'w'] `shouldBe` [n, e 'v', n]
    it "does not look at an input that follows a Just until the next sample (as Yampa)" $ do
      let bad = error "input" :: Maybe Int
      take 1 (runDt 1 edgeJust [bad, Just 1]) `shouldBe` [n]
      take 2 (runDt 1 edgeJust [Just 1, bad, Nothing]) `shouldBe` [n, n]
      forceEvents (runDt 1 edgeJust [bad, Just 1]) `shouldThrow` errorCall "input"

  describe "edgeBy" $ do
    let rise prev cur = if cur > prev then Just (cur - prev) else Nothing
    it "applies the function to the previous and current samples" $
      runDt 1 (edgeBy rise 0) [3, 2, 5, 5, 7 :: Int] `shouldBe` [e 3, n, e 3, n, e 2]
    it "uses the initial value as the previous sample at time 0" $
      runDt 1 (edgeBy rise 10) [3, 4 :: Int] `shouldBe` [n, e 1]
    it "evaluates each input sample at the next sample" $
      forceEvents (runDt 1 (bottomWhereNothing (edgeBy (\_ _ -> Nothing :: Maybe ()) (0 :: Int))) [Just 1, Nothing, Just 2])
        `shouldThrow` anyErrorCall
