{-# LANGUAGE Arrows #-}
module AFRP.LoopSpec (spec) where

import           Control.Arrow     (arr, loop, returnA, second, (>>>))
import           Control.Exception (ErrorCall (..), evaluate)
import           Test.Hspec

import           AFRP.Delay        (iPre, pre)
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (SF)
import           AFRP.Loop
import           AFRP.Run          (embed)
import           TestUtil

spec :: Spec
spec = do
  describe "loop" $ do
    it "loop over a pure function ties the knot lazily" $
      runDt 1 (loop (arr (\(a, c) -> (take 3 c, a : c)))) [1, 2 :: Int]
        `shouldBe` [[1, 1, 1], [2, 2, 2]]
    it "loop with iPre counts samples" $
      runDt 0.1 (loop (arr (\(_, n) -> (n, n + 1)) >>> second (iPre (0 :: Int))))
        (replicate 5 ()) `shouldBe` [0, 1, 2, 3, 4]
    it "rec in arrow notation with an integral solves x' = 1 - x" $
      shouldApproxList (runDt 0.5 relax (replicate 4 ())) [0, 0.5, 0.75, 0.875]

  describe "what a loop evaluates (AFRP.Loop: the body's pair, at the next sample)" $ do
    -- (a rec whose variables come from pre: its pair does not exist at
    -- time 0, and the loop evaluates it at the second sample, read or not;
    -- Yampa, which never does, gives the later outputs)
    let strictRec, lazyRec :: SF Double Double
        strictRec = proc a -> do
          rec (x, y) <- pre -< (a, y)
          returnA -< x
        lazyRec = proc a -> do
          rec ~(x, y) <- pre -< (a, y)
          returnA -< x
        later sf = drop 1 (embed sf (1, [ (1, Just v) | v <- [2, 3, 4] ]))
    it "fails at the second sample when the pair of a rec's strict pattern is undefined at time 0, unread" $
      evaluate (sum (later strictRec)) `shouldThrow` errorCall'
        "AFRP.Delay.pre: pre has no output at local time 0 (use iPre for one)"
    it "goes on with a lazy pattern (~(x, y)), as Yampa does with either" $
      later lazyRec `shouldBe` [1, 2, 3]

  describe "loopPre" $ do
    it "feeds back through a one-sample delay" $
      runDt 1 (loopPre 0 (arr (\(a, acc) -> (acc + a, acc + a)))) [1, 2, 3, 4 :: Int]
        `shouldBe` [1, 3, 6, 10]
    it "the initial value is what the body sees at time 0" $
      runDt 1 (loopPre 'z' (arr (\(_, c) -> (c, 'y')))) [(), ()] `shouldBe` "zy"

  describe "loopIntegral" $ do
    it "integrates the fed-back derivative by the left rectangle rule" $
      -- x' = a - x with a = 1: x_n = x_(n-1) + dt * (1 - x_(n-1)), x_0 = 0
      shouldApproxList
        (runDt 0.25 (loopIntegral (arr (\(a, x) -> (x, a - x)))) (replicate 4 (1 :: Double)))
        [0, 0.25, 0.4375, 0.578125]
    it "grows exponentially for x' = x + 1" $
      shouldApproxList
        (runDt 0.5 (loopIntegral (arr (\(_, x) -> (x, x + 1)))) (replicate 4 ()))
        [0, 0.5, 1.25, 2.375 :: Double]
  where
    relax :: SF () Double
    relax = proc () -> do
      rec x <- integral -< 1 - x
      returnA -< x

-- | An error call with exactly this message (its location aside).
errorCall' :: String -> Selector ErrorCall
errorCall' m (ErrorCallWithLocation msg _) = msg == m
