{-# LANGUAGE UnboxedTuples #-}
-- | The nodes built from a step, and the steps deferred
-- ("AFRP.Internal.Deferred"): what each evaluates, and when. The
-- combinators built on them are tested in their own specs; these pin the
-- building blocks' own promises.
module AFRP.DeferredSpec (spec) where

import           Control.Exception (ErrorCall (..), evaluate)
import           Test.Hspec

import           AFRP.Internal.SF  (HandoverStep (..), Next (..), Node (..), arrN, deferN, freezeN, lazyHandoverN,
                                    lazyN, mealyN, stepN)

-- | Step a node along a list of (time step, input), collecting the outputs.
steps :: Node a b -> [(Double, a)] -> [b]
steps _ [] = []
steps n ((dt, a) : rest) = case stepN n dt a of (# n', b #) -> b : steps n' rest

-- | A node that outputs the time step it was given, and counts its steps.
dtNode :: Int -> Node a (Int, Double)
dtNode k = NStep (\dt _ -> (# dtNode (k + 1), (k, dt) #))

-- | A node whose step evaluates its input (as a switch deciding whether its
-- event occurred does).
strictNode :: Node Int Int
strictNode = NStep (\_ a -> a `seq` (# strictNode, a #))

-- | The successor after one step (of 0 s), the output left alone.
next :: Node a b -> a -> Node a b
next n a = case stepN n 0 a of (# n', _ #) -> n'

-- | One step performed and its successor evaluated, the output not.
successor :: Node a b -> a -> IO (Node a b)
successor n a = evaluate (next n a)

-- | The error "no input".
noInput :: ErrorCall -> Bool
noInput (ErrorCall m) = m == "no input"

spec :: Spec
spec = do
  describe "mealyN" $ do
    let counter = mealyN (\s a -> (s + a, s)) (0 :: Int)
    it "outputs what its transition gives, the state carried from step to step" $
      steps counter [ (1, a) | a <- [1, 2, 3, 4] ] `shouldBe` [0, 1, 3, 6]
    it "does not evaluate its input at the step, and forces the state at the next one" $ do
      n1 <- successor counter (error "no input")
      -- (the state made of that input is forced when the next step starts)
      successor n1 1 `shouldThrow` noInput

  describe "lazyN" $ do
    it "steps a node that evaluates its input only when its output is demanded" $ do
      n1 <- successor (lazyN strictNode) (error "no input")
      case stepN (lazyN strictNode) 0 (error "no input") of
        (# _, b #) -> evaluate b `shouldThrow` noInput
      -- (or, at the latest, when the next step starts)
      successor n1 1 `shouldThrow` noInput
      -- (without the wrapper, the step itself evaluates the input)
      successor strictNode (error "no input") `shouldThrow` noInput
    it "gives the outputs of the node it wraps" $
      steps (lazyN strictNode) [ (1, a) | a <- [4, 5, 6] ] `shouldBe` [4, 5, 6]
    it "is the node itself when that is pure" $
      case lazyN (arrN (+ (1 :: Int))) of
        NPure _ -> pure ()
        _       -> expectationFailure "a pure node was wrapped"

  describe "lazyHandoverN" $ do
    -- stays for two steps (outputting -1), then leaves for a pure node
    let switchAt :: Int -> HandoverStep Int Int
        switchAt k = HandoverStep (\_ a ->
          if k >= 2 then (# Leave (arrN (* 10)), a * 10 #) else (# Stay (switchAt (k + 1)), -1 #))
    it "gives its own outputs while it stays, then those of the node it left for" $
      steps (lazyHandoverN (switchAt 0)) [ (1, a) | a <- [1 .. 5] ] `shouldBe` [-1, -1, 30, 40, 50]
    it "is the node it left for from the step after it left: not wrapped again" $ do
      n1 <- successor (lazyHandoverN (switchAt 2)) 1
      n2 <- successor n1 2
      case n2 of
        NPure _ -> pure ()
        _       -> expectationFailure "the node left for is still wrapped"
    it "does not perform its step before its output is demanded" $ do
      let strict :: HandoverStep Int Int
          strict = HandoverStep (\_ a -> a `seq` (# Stay strict, a #))
      n1 <- successor (lazyHandoverN strict) (error "no input")
      successor n1 1 `shouldThrow` noInput

  describe "deferN" $ do
    it "evaluates the node it is given only when stepped" $ do
      _ <- evaluate (deferN (error "not yet" :: Node Int Int))
      n1 <- successor (deferN (arrN (+ (1 :: Int)))) 1
      steps n1 [(1, 2)] `shouldBe` [3]
      successor (deferN (error "not yet" :: Node Int Int)) 1 `shouldThrow` (\(ErrorCall m) -> m == "not yet")

  describe "freezeN" $
    it "performs the captured step once, whatever time step it is given, then continues as the node" $
      steps (freezeN (dtNode 0) 0.5) [(99, ()), (7, ()), (3, ())] `shouldBe` [(0, 0.5), (1, 7), (2, 3)]
