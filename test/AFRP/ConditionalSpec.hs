module AFRP.ConditionalSpec (spec) where

import           Control.Arrow    (arr, (>>>))
import           Test.Hspec       hiding (after)
import           Test.QuickCheck

import           AFRP.Basic       (constant, localTime)
import           AFRP.Conditional
import           AFRP.Event       (Event (..), isEvent)
import           AFRP.EventSource (after, never, now, repeatedly)
import           AFRP.Internal.SF (SF)
import           AFRP.Scan        (sscan)
import           TestUtil

-- | Counts the samples since it started: 1 at its local time 0.
counter :: SF a Int
counter = sscan (\n _ -> n + 1) 0

-- | Fires at its k-th sample (counting its local time 0 as the first).
atSample :: Int -> SF a (Event Int)
atSample k = counter >>> arr (\n -> if n == k then Event k else NoEvent)

spec :: Spec
spec = do
  describe "provided" $ do
    it "lets the first input choose, and restarts the other branch at each change" $
      runDt 1 (provided even localTime (constant (-1))) [2, 4, 5, 6, 8 :: Int]
        `shouldBe` [0, 1, -1, 0, 1]
    it "starts with the false branch when the first input fails the predicate" $
      runDt 1 (provided (> 0) (constant 'T') (constant 'F')) [0, 1, 1, 0 :: Int]
        `shouldBe` "FTTF"
    it "counts from 1 in each run of inputs satisfying the predicate (property)" $
      property $ forAll (genSamples (arbitrary :: Gen Int)) $ \samples ->
        let ref _ []      = []
            ref k (x : r) | even x    = (k + 1) : ref (k + 1) r
                          | otherwise = -1 : ref (0 :: Int) r
        in runSamples (provided even counter (constant (-1))) samples
             === ref 0 (map snd samples)

  describe "recur" $ do
    it "restarts its event source at each event" $
      runDt 0.5 (recur (after 1 'x')) (replicate 5 ())
        `shouldBe` [NoEvent, NoEvent, Event 'x', NoEvent, Event 'x']
    it "outputs an event at time 0, as Yampa does, and suppresses the restarted source's at each restart" $
      -- (the event at time 0 was suppressed; Yampa outputs it)
      runDt 1 (recur (now 'n')) (replicate 4 ()) `shouldBe` (Event 'n' : replicate 3 NoEvent)
    it "a source firing at its k-th sample fires every k-1 samples after time 0 (property)" $
      property $ forAll (choose (2, 6)) $ \k -> forAll (choose (1, 30)) $ \n ->
        map isEvent (runDt 1 (recur (atSample k)) (replicate n ()))
          === [i > 0 && i `mod` (k - 1) == 0 | i <- [0 .. n - 1]]

  describe "andThen" $ do
    it "passes the first source's first event, then the second source's events" $
      runDt 1 (after 1 'a' `andThen` after 1 'b') (replicate 4 ())
        `shouldBe` [NoEvent, Event 'a', Event 'b', NoEvent]
    it "hides the second source's output at the switching instant" $
      runDt 1 (now 'a' `andThen` now 'b') (replicate 3 ())
        `shouldBe` [Event 'a', NoEvent, NoEvent]
    it "the first source's later events are not seen" $
      runDt 1 (repeatedly 1 'a' `andThen` never) (replicate 4 ())
        `shouldBe` [NoEvent, Event 'a', NoEvent, NoEvent]
    it "chains to the right, as Yampa's infixr 5: each source in turn (left-nested, b was lost)" $
      runDt 1 (after 1 'a' `andThen` after 1 'b' `andThen` after 1 'c') (replicate 5 ())
        `shouldBe` [NoEvent, Event 'a', Event 'b', Event 'c', NoEvent]
