-- | Tests for "AFRP.Task": tasks, their sequencing, and the task
-- combinators. Every expected output below was computed by hand from the
-- functions' documentation.
module AFRP.TaskSpec (spec) where

import           Control.Arrow     (arr, (&&&), (>>>))
import           Control.Exception (evaluate)
import           Test.Hspec        hiding (after)
import qualified Test.QuickCheck   as QC

import           AFRP.Basic        (constant, localTime)
import           AFRP.Event        (Event (..))
import           AFRP.EventSource  (after, never, now)
import           AFRP.Internal.SF  (DTime)
import           AFRP.Run          (embed)
import           AFRP.Switch       (switch)
import           AFRP.Task
import           TestUtil

-- | The sample index as input: 0, 1, 2, ...
indices :: Int -> [Double]
indices n = map fromIntegral [0 .. n - 1]

units :: Int -> [()]
units n = replicate n ()

spec :: Spec
spec = do
  basicsSpec
  sleepSnapSpec
  timeOutAbortSpec
  loopsSpec
  lawsSpec
  propertiesSpec
  documentedSpec

------------------------------------------------------------------------------

basicsSpec :: Spec
basicsSpec = do
  describe "mkTask / runTask" $ do
    it "is Left while running and Right from the ending instant" $
      runDt 0.5 (runTask (mkTask (localTime &&& after 1 'z'))) (units 4)
        `shouldBe` [Left 0, Left 0.5, Right 'z', Right 'z']

    it "ends with the event's value and holds it" $ do
      let t = mkTask (arr (* 2) &&& arr (\x -> if x >= 3 then Event (x * 10) else NoEvent))
      runDt 1 (runTask t) [1, 2, 3, 4, 1 :: Double]
        `shouldBe` [Left 2, Left 4, Right 30, Right 30, Right (30 :: Double)]

    it "an end at time 0 gives Right at time 0" $
      runDt 1 (runTask (mkTask (constant 'a' &&& now (5 :: Int)))) (units 3)
        `shouldBe` [Right 5, Right 5, Right 5]

    it "pure ends at once, taking no time" $
      runDt 1 (runTask (pure 'p' :: Task () Int Char)) (units 2) `shouldBe` [Right 'p', Right 'p']

    it "starts the next task at the ending instant, with its local time at 0" $ do
      let t = mkTask (localTime &&& after 1 ()) >> mkTask ((localTime >>> arr (+ 100)) &&& never)
      runDt 0.5 (runTask (t :: Task () Double ())) (units 5)
        `shouldBe` [Left 0, Left 0.5, Left 100, Left 100.5, Left 101]

    it "passes the result on to the next task" $ do
      let t = do
            x <- mkTask (constant 0 &&& arr (\a -> if a >= 2 then Event a else NoEvent))
            mkTask (arr (+ x) &&& never)
      runDt 1 (runTask (t :: Task Double Double ())) [0, 1, 2, 3, 4]
        `shouldBe` [Left 0, Left 0, Left 4, Left 5, Left 6]

  describe "runTask_" $ do
    it "outputs the running task's output" $ do
      let t = mkTask (localTime &&& after 1 ()) >> mkTask ((localTime >>> arr negate) &&& never)
      runDt 0.5 (runTask_ (t :: Task () Double ())) (units 5)
        `shouldApproxList` [0, 0.5, 0, -0.5, -1]

    it "has an error as output from the ending instant (only if demanded)" $ do
      let outs = runDt 0.5 (runTask_ (sleepT 1 'a')) (units 4)
      length outs `shouldBe` 4
      take 2 outs `shouldBe` "aa"
      evaluate (outs !! 2) `shouldThrow` anyErrorCall
      evaluate (outs !! 3) `shouldThrow` anyErrorCall

  describe "taskToSF" $ do
    it "has the event exactly at the ending instant" $ do
      let outs = runDt 0.5 (taskToSF (sleepT 1 'a' >> sleepT 0.5 'b' >> pure (7 :: Int))) (units 5)
      map snd outs `shouldBe` [NoEvent, NoEvent, NoEvent, Event 7, NoEvent]
      map fst (take 3 outs) `shouldBe` "aab"

    it "has no output value from the ending instant on" $ do
      let outs = runDt 0.5 (taskToSF (sleepT 1 'a')) (units 4)
      evaluate (fst (outs !! 2)) `shouldThrow` anyErrorCall
      evaluate (fst (outs !! 3)) `shouldThrow` anyErrorCall

    it "has the event at time 0 for a task that ends at time 0" $ do
      map snd (runDt 1 (taskToSF (pure 'r' :: Task () Int Char)) (units 3))
        `shouldBe` [Event 'r', NoEvent, NoEvent]
      map snd (runDt 1 (taskToSF (snapT :: Task Double Int Double)) [5, 6, 7])
        `shouldBe` [Event 5, NoEvent, NoEvent]
      map snd (runDt 1 (taskToSF (sleepT 0 'x')) (units 2)) `shouldBe` [Event (), NoEvent]

    it "can drive a switch that abandons the task at its end" $
      runDt 0.5 (switch (taskToSF (sleepT 1 'a')) (\() -> constant 'b')) (units 4) `shouldBe` "aabb"

  describe "constT" $ do
    it "outputs a constant and never ends" $ do
      runDt 1 (runTask (constT 'c' :: Task () Char ())) (units 4) `shouldBe` replicate 4 (Left 'c')
      runDt 1 (runTask (constT 'c' >> pure () :: Task () Char ())) (units 4)
        `shouldBe` replicate 4 (Left 'c')

------------------------------------------------------------------------------

sleepSnapSpec :: Spec
sleepSnapSpec = do
  describe "sleepT" $ do
    it "refuses a negative or NaN time, naming itself (it named after)" $ do
      let ran t = evaluate (foldr seq () (embed (runTask_ t) ((), [(1, Nothing)])))
      ran (sleepT (-1) 'a' :: Task () Char ()) `shouldThrow` errorCall "AFRP.Task.sleepT: negative or NaN time, got -1.0"
      ran (sleepT 1 'a' `timeOut` (0 / 0) :: Task () Char (Maybe ()))
        `shouldThrow` errorCall "AFRP.Task.timeOut: negative or NaN time, got NaN"
    it "ends at the first sample at or after t (exact hit)" $
      runDt 0.25 (runTask_ (sleepT 1 'a' >> constT 'b' :: Task () Char ())) (units 6) `shouldBe` "aaaabb"

    it "ends at the first sample at or after t (irregular steps)" $
      -- times 0, 0.4, 0.8, 1.2, 1.6: ends at 1.2
      runSamples (runTask_ (sleepT 1 'a' >> constT 'b' :: Task () Char ()))
                 [(0, ()), (0.4, ()), (0.4, ()), (0.4, ()), (0.4, ())]
        `shouldBe` "aaabb"

    it "ends after ten steps of 0.1 (time is not eroded by rounding)" $
      runDt 0.1 (runTask (sleepT 1 'a')) (units 12)
        `shouldBe` replicate 10 (Left 'a') ++ [Right (), Right ()]

    it "sleepT 0 ends at once and never shows its output" $ do
      runDt 1 (runTask_ (sleepT 0 'x' >> constT 'y' :: Task () Char ())) (units 3) `shouldBe` "yyy"
      runDt 1 (runTask (sleepT 0 'x')) (units 2) `shouldBe` [Right (), Right ()]

  describe "snapT" $ do
    it "ends with the input of the instant it runs at" $
      runDt 0.25 (runTask (sleepT 0.5 (-1 :: Int) >> snapT)) [0, 10, 20, 30, 40 :: Double]
        `shouldBe` [Left (-1), Left (-1), Right 20, Right 20, Right (20 :: Double)]

    it "snapT >> snapT takes no time (both see the same input)" $ do
      runDt 1 (runTask ((,) <$> snapT <*> snapT :: Task Double Int (Double, Double))) [3, 4, 5]
        `shouldBe` replicate 3 (Right (3, 3))
      runDt 0.25 (runTask (sleepT 0.5 'w' >> ((,) <$> snapT <*> snapT))) [0, 10, 20, 30 :: Double]
        `shouldBe` [Left 'w', Left 'w', Right (20, 20), Right (20, 20 :: Double)]

    it "its own output is never shown" $
      runDt 1 (runTask (snapT >>= constT :: Task Double Double ())) [7, 8, 9]
        `shouldBe` [Left 7, Left 7, Left 7]

    it "snaps at the instant a previous task ends" $ do
      let t = do
            x <- snapT
            sleepT 0.5 x
            y <- snapT
            pure (x, y)
      runDt 0.25 (runTask t) [1, 2, 3, 4 :: Double]
        `shouldBe` [Left 1, Left 1, Right (1, 3), Right (1, 3 :: Double)]

------------------------------------------------------------------------------

timeOutAbortSpec :: Spec
timeOutAbortSpec = do
  describe "timeOut" $ do
    it "gives Just the result when the task ends first" $
      runDt 0.5 (runTask (sleepT 1 'a' `timeOut` 2)) (units 4)
        `shouldBe` [Left 'a', Left 'a', Right (Just ()), Right (Just ())]

    it "gives Nothing when the time runs out first" $
      runDt 0.5 (runTask (sleepT 2 'a' `timeOut` 1)) (units 4)
        `shouldBe` [Left 'a', Left 'a', Right Nothing, Right Nothing]

    it "the task wins a tie" $
      runDt 0.5 (runTask (sleepT 1 'a' `timeOut` 1)) (units 3)
        `shouldBe` [Left 'a', Left 'a', Right (Just ())]

    it "carries the task's result" $
      runDt 0.5 (runTask ((sleepT 1 'a' >> snapT) `timeOut` 3)) [0, 1, 2, 3 :: Double]
        `shouldBe` [Left 'a', Left 'a', Right (Just 2), Right (Just 2)]

    it "counts the time from when the timeOut task starts" $
      runDt 0.5 (runTask (sleepT 1 'x' >> (constT 'y' `timeOut` 0.5 :: Task () Char (Maybe ()))))
                (units 5)
        `shouldBe` [Left 'x', Left 'x', Left 'y', Right Nothing, Right Nothing]

    it "at time 0: a task ending at once, a zero timeout, and a tie" $ do
      runDt 1 (runTask (pure 'r' `timeOut` 1 :: Task () Int (Maybe Char))) (units 2)
        `shouldBe` [Right (Just 'r'), Right (Just 'r')]
      runDt 1 (runTask (constT 'c' `timeOut` 0 :: Task () Char (Maybe ()))) (units 2)
        `shouldBe` [Right Nothing, Right Nothing]
      runDt 1 (runTask (pure 'r' `timeOut` 0 :: Task () Int (Maybe Char))) (units 2)
        `shouldBe` [Right (Just 'r'), Right (Just 'r')]

  describe "abortWhen" $ do
    it "gives Left the result when the task ends first" $
      runDt 0.5 (runTask (sleepT 1 'a' `abortWhen` after 2 'z')) (units 4)
        `shouldBe` [Left 'a', Left 'a', Right (Left ()), Right (Left ())]

    it "gives Right the event value when the event comes first" $
      runDt 0.5 (runTask (sleepT 2 'a' `abortWhen` after 1 'z')) (units 4)
        `shouldBe` [Left 'a', Left 'a', Right (Right 'z'), Right (Right 'z')]

    it "the task wins a tie" $
      runDt 0.5 (runTask (sleepT 1 'a' `abortWhen` after 1 'z')) (units 3)
        `shouldBe` [Left 'a', Left 'a', Right (Left ())]

    it "the event source sees the input" $ do
      let t = constT 'a' `abortWhen` arr (\x -> if x >= 3 then Event (x * 2) else NoEvent)
      runDt 1 (runTask (t :: Task Double Char (Either () Double))) (indices 5)
        `shouldBe` [Left 'a', Left 'a', Left 'a', Right (Right 6), Right (Right 6)]

    it "starts the event source together with the task" $
      runDt 0.5 (runTask (sleepT 1 'x' >> (constT 'y' `abortWhen` after 0.5 'z' :: Task () Char (Either () Char))))
                (units 5)
        `shouldBe` [Left 'x', Left 'x', Left 'y', Right (Right 'z'), Right (Right 'z')]

    it "at time 0: an event aborts at once; a task ending at once wins" $ do
      runDt 1 (runTask (constT 'a' `abortWhen` now 'z' :: Task () Char (Either () Char))) (units 2)
        `shouldBe` [Right (Right 'z'), Right (Right 'z')]
      runDt 1 (runTask (pure 'r' `abortWhen` now 'z' :: Task () Int (Either Char Char))) (units 2)
        `shouldBe` [Right (Left 'r'), Right (Left 'r')]

------------------------------------------------------------------------------

loopsSpec :: Spec
loopsSpec = do
  describe "repeatUntil" $ do
    it "repeats a task until its result satisfies the predicate" $
      -- Each round sleeps 0.5 then snaps the input (the sample index).
      runDt 0.5 (runTask ((sleepT 0.5 'w' >> snapT) `repeatUntil` (>= 3))) (indices 5)
        `shouldBe` [Left 'w', Left 'w', Left 'w', Right 3, Right 3]

    it "returns the first result that satisfies the predicate" $
      runDt 0.5 (runTask ((sleepT 0.5 'w' >> snapT) `repeatUntil` (> 6))) [5, 1, 9, 2, 7, 8]
        `shouldBe` [Left 'w', Left 'w', Right 9, Right 9, Right 9, Right (9 :: Double)]

    it "stops after one round when the predicate holds at once" $
      runDt 0.5 (runTask ((sleepT 0.5 'w' >> snapT) `repeatUntil` const True)) [5, 1, 9 :: Double]
        `shouldBe` [Left 'w', Right 1, Right 1]

  describe "forAll" $ do
    it "runs the body for each element in turn" $
      runDt 0.25 (runTask (forAll [10, 20, 30] (\x -> sleepT 0.5 x))) (units 7)
        `shouldBe` [Left 10, Left 10, Left 20, Left 20, Left 30, Left (30 :: Int), Right ()]

    it "on an empty list ends at once" $
      runDt 1 (runTask (forAll [] (\x -> sleepT 1 (x :: Int)))) (units 2) `shouldBe` [Right (), Right ()]

  describe "forEver" $ do
    it "repeats a body that takes time, without end" $
      -- a for 0.5, b for 0.25, and again: a a b a a b a a
      runDt 0.25 (runTask_ (forEver (sleepT 0.5 'a' >> sleepT 0.25 'b') :: Task () Char ())) (units 8)
        `shouldBe` "aabaabaa"

    it "restarts the body's local time at every round" $
      runDt 0.25 (runTask_ (forEver (mkTask (localTime &&& after 0.75 ())) :: Task () Double ()))
                 (units 8)
        `shouldApproxList` [0, 0.25, 0.5, 0, 0.25, 0.5, 0, 0.25]

------------------------------------------------------------------------------

type T = Task Double Char Double

-- Three tasks: one that takes time and snaps its input, one that ends on
-- its input, one that ends at once.
tasks :: [(String, T)]
tasks =
  [ ("sleep then snap", sleepT 0.5 'a' >> snapT)
  , ("end on input", mkTask (constant 'm' &&& arr (\x -> if x >= 4 then Event (x / 2) else NoEvent)))
  , ("pure", pure 1.5)
  ]

kf :: Double -> T
kf x = sleepT (x * 0.25) 'f' >> fmap (+ x) snapT

kg :: Double -> T
kg y = mkTask (constant 'g' &&& after (y * 0.1) (y * 10))

runT :: T -> [Either Char Double]
runT t = runDt 0.25 (runTask t) (indices 24)

lawsSpec :: Spec
lawsSpec = describe "Functor / Applicative / Monad laws (sampled outputs)" $ do
  it "the law tasks end where expected (the laws compare real behaviours)" $ do
    -- sleep then snap: Right 2 from sample 2; end on input: Right 2 from
    -- sample 4; kf 2 >>= kg: sleeps 0.5, snaps 2 (+2 = 4), then after 0.4
    -- (sample 4 at t = 1.0) ends with 40.
    runT (snd (head tasks)) `shouldBe` [Left 'a', Left 'a'] ++ replicate 22 (Right 2)
    runT (snd (tasks !! 1)) `shouldBe` replicate 4 (Left 'm') ++ replicate 20 (Right 2)
    runT (kf 2 >>= kg) `shouldBe` [Left 'f', Left 'f', Left 'g', Left 'g'] ++ replicate 20 (Right 40)
  mapM_ lawsFor tasks
  it "left identity: pure x >>= f = f x" $
    mapM_ (\x -> runT (pure x >>= kf) `shouldBe` runT (kf x)) [0, 1, 3]
  where
    lawsFor (name, m) = describe name $ do
      it "fmap id = id" $ runT (fmap id m) `shouldBe` runT m
      it "fmap (f . g) = fmap f . fmap g" $
        runT (fmap ((* 3) . (+ 1)) m) `shouldBe` runT (fmap (* 3) (fmap (+ 1) m))
      it "right identity: m >>= pure = m" $ runT (m >>= pure) `shouldBe` runT m
      it "associativity" $
        runT ((m >>= kf) >>= kg) `shouldBe` runT (m >>= (\x -> kf x >>= kg))
      it "pure f <*> m = fmap f m" $ runT (pure (+ 7) <*> m) `shouldBe` runT (fmap (+ 7) m)

------------------------------------------------------------------------------

-- Time steps that add up exactly in floating point.
genExactSteps :: QC.Gen [DTime]
genExactSteps = do
  n <- QC.choose (1, 30)
  QC.vectorOf n (QC.elements [0.125, 0.25, 0.5, 1])

propertiesSpec :: Spec
propertiesSpec = describe "properties" $ do
  it "sleepT t ends at the first sample whose local time is >= t" $
    QC.property $ QC.forAll genExactSteps $ \dts -> QC.forAll (QC.elements [0, 0.125 .. 4]) $ \t ->
      let times = scanl (+) 0 dts
          outs  = runSamples (runTask (sleepT t 'a')) (zip (0 : dts) (repeat ()))
          expected = [if s >= t then Right () else Left 'a' | s <- times]
      in outs QC.=== expected

  it "taskToSF (sleepT t) has exactly one event, at the first sample with time >= t" $
    QC.property $ QC.forAll genExactSteps $ \dts -> QC.forAll (QC.elements [0, 0.125 .. 4]) $ \t ->
      let times = scanl (+) 0 dts
          outs  = map snd (runSamples (taskToSF (sleepT t 'a')) (zip (0 : dts) (repeat ())))
          firstIx = length (takeWhile (< t) times)
          expected = [if i == firstIx then Event () else NoEvent | i <- [0 .. length times - 1]]
      in outs QC.=== expected

------------------------------------------------------------------------------
-- The cases the docs state: a task that ends at once, and the clocks of
-- the time-bounded tasks, which start with the task (each checked against
-- Yampa 0.15, which gives the same outputs). Samples every 0.5 s.

documentedSpec :: Spec
documentedSpec = describe "as documented: tasks that end at once, and clocks that start with the task" $ do
  it "taskToSF of a task that ends at once: its occurrence at the first sample, and no output" $ do
    let outs = runDt 0.5 (taskToSF (pure 5 :: Task () Double Int)) (units 5)
    map snd outs `shouldBe` [Event 5, NoEvent, NoEvent, NoEvent, NoEvent]
    evaluate (fst (head outs)) `shouldThrow` anyErrorCall
  it "runTask_: the output at the ending instant is already an error" $ do
    let outs = runDt 0.5 (runTask_ (sleepT 1 7 :: Task () Double ())) (units 5)
    take 2 outs `shouldBe` [7, 7]
    evaluate (outs !! 2) `shouldThrow` anyErrorCall
  it "abortWhen's event source counts from the task's start" $
    runDt 0.5 (runTask (sleepT 1 (-1) >> ((constT 7 :: Task () Double Int) `abortWhen` after 0.5 'x'))) (units 5)
      `shouldBe` [Left (-1), Left (-1), Left 7, Right (Right 'x'), Right (Right 'x')]
  it "timeOut counts from the task's start; timeOut 0 ends at once" $ do
    runDt 0.5 (runTask (sleepT 1 (-1) >> ((sleepT 2 7 :: Task () Double ()) `timeOut` 0.5))) (units 5)
      `shouldBe` [Left (-1), Left (-1), Left 7, Right Nothing, Right Nothing]
    runDt 0.5 (runTask ((pure 5 :: Task () Double Int) `timeOut` 0)) (units 2)
      `shouldBe` [Right (Just 5), Right (Just 5)]
    runDt 0.5 (runTask (sleepT 1 (-1) >> ((constT 7 :: Task () Double Int) `timeOut` 0))) (units 3)
      `shouldBe` [Left (-1), Left (-1), Right Nothing]
