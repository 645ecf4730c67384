{-# LANGUAGE UnboxedTuples #-}
-- | The chain node ("AFRP.Internal.Chain", issue 19): a run of integrals,
-- delays and functions before integrals at 'Double' is stepped as one
-- node, and must give the very numbers (bit for bit) the nodes give one by
-- one, with the same laziness.
module AFRP.ChainSpec (spec) where

import           Control.Exception     (evaluate)
import           GHC.Float             (castDoubleToWord64)
import           Test.Hspec
import           Test.QuickCheck       hiding (within)

import           AFRP                  hiding (forAll)
import           AFRP.Internal.SF      (Node (..), SF (..), isStepSF, stepN, stepSF)
import           TestUtil              (genSamples, runDt, runSamples, withoutHanging)

-- | A stage of a random chain.
data Stage = SIntegral | SPre Double | SArr Int | SInitIntegral Double
  deriving Show

instance Arbitrary Stage where
  arbitrary = frequency
    [ (4, pure SIntegral)
    , (2, SPre <$> elements [0, -1, 2.5])
    , (3, SArr <$> choose (0, length funs - 1))
    -- an integral whose first output is replaced ('-->'): after its first
    -- step it is an integral node whose sum is not what it output
    , (1, SInitIntegral <$> elements [5, -3]) ]
  shrink (SArr _) = [SIntegral]
  shrink (SPre _) = [SIntegral]
  shrink SIntegral = []
  shrink (SInitIntegral _) = [SIntegral]

-- The functions a chain may hold, total and cheap.
funs :: [Double -> Double]
funs = [(* 2), (+ 1), negate, sin, \x -> x * x - 0.5]

stageSF :: Stage -> SF Double Double
stageSF SIntegral = integral
stageSF (SPre c)  = iPre c
stageSF (SArr i)  = arr (funs !! i)
stageSF (SInitIntegral c) = c --> integral

-- | A signal function that behaves as its argument but is one opaque node
-- at every step, so that nothing can be fused with it: the stages stepped
-- one by one, as before chains existed.
opaque :: SF a b -> SF a b
opaque (SF n0) = SF (go n0)
  where
    go n = NStep (\dt a -> case stepN n dt a of
      (# n', b #) -> case go n' of m -> m `seq` (# m, b #))

-- | Bit-for-bit equality of two runs.
sameBits :: [Double] -> [Double] -> Bool
sameBits xs ys = length xs == length ys
  && and (zipWith (\x y -> castDoubleToWord64 x == castDoubleToWord64 y) xs ys)

-- | A chain built at run time ('foldr1'), as a user's code builds one.
chainOf :: [Stage] -> SF Double Double
chainOf = foldr1 (>>>) . map stageSF

opaqueChainOf :: [Stage] -> SF Double Double
opaqueChainOf = foldr1 (>>>) . map (opaque . stageSF)

-- | The outputs of a signal function already started, on (dt, input) pairs.
runSamples' :: SF Double Double -> [(DTime, Double)] -> [Double]
runSamples' _ [] = []
runSamples' sf ((dt, x) : rest) = case stepSF sf dt x of
  (sf', y) -> y : runSamples' sf' rest

inputs :: [Double]
inputs = [1, -1, 2, 0, 3, -2, 5, 1, -4, 2, 6, 0]

spec :: Spec
spec = do
  describe "a chain of integrals built at run time" $ do
    it "is one node after its first step (fixed)" $ do
      let sf0 = foldr1 (>>>) (replicate 10 integral) :: SF Double Double
          (sf1, _) = stepSF sf0 0 1
          (sf2, _) = stepSF sf1 0.1 2
      isStepSF sf0 `shouldBe` False
      isStepSF sf2 `shouldBe` True
    it "takes the previous input of an integral behind a replaced first output from the integral (fixed)" $
      -- the first integral outputs 5, 1, 3, 6; the second 0, 5, 6, 9; the
      -- third sums twice those: 0, 0, 10, 22
      runDt 1 ((5 --> integral) >>> integral >>> arr (* 2) >>> integral :: SF Double Double) [1, 2, 3, 4]
        `shouldBe` [0, 0, 10, 22]
    it "gives the numbers of the integrals stepped one by one, bit for bit (fixed)" $
      runDt 0.01 (chainOf (replicate 10 SIntegral)) [0 .. 300]
        `shouldSatisfy` sameBits (runDt 0.01 (opaqueChainOf (replicate 10 SIntegral)) [0 .. 300])
  describe "a run of integrals in a chain (one array of sums)" $ do
    it "is stepped from a kept state as often as asked, the same each time: nothing is written in place (fixed)" $ do
      let sf0 = foldr1 (>>>) (replicate 6 integral) :: SF Double Double
          ref0 = foldr1 (>>>) (replicate 6 (opaque integral)) :: SF Double Double
          upTo sf = foldl (\(s, _) (dt, x) -> stepSF s dt x) (sf, 0) [(0, 1), (0.5, 2), (0.5, 3), (0.5, -1)]
          (kept, _) = upTo sf0
          (keptRef, _) = upTo ref0
          from s = runSamples' s [(0.25, 4), (0.5, 1), (0.5, 7)]
          first1 = from kept
          second1 = from kept
      sameBits first1 (from keptRef) `shouldBe` True
      sameBits second1 first1 `shouldBe` True
      -- and a branch with other inputs does not disturb the kept state
      _ <- evaluate (sum (from (fst (stepSF kept 2 100))))
      sameBits (from kept) (from keptRef) `shouldBe` True
    it "gives the numbers of runs of every length between other stages, bit for bit (fixed)" $
      let stages k = [SArr 3] ++ replicate k SIntegral ++ [SPre 2.5] ++ replicate k SIntegral ++ [SArr 1, SIntegral]
      in mapM_ (\k -> runDt 0.05 (chainOf (stages k)) [0 .. 60]
                         `shouldSatisfy` sameBits (runDt 0.05 (opaqueChainOf (stages k)) [0 .. 60]))
               [1 .. 12]
    it "does the same with functions between the integrals, in any mix, bit for bit (fixed)" $
      let withFs k = [SIntegral] ++ concat (replicate k [SArr (k `mod` 5), SIntegral, SIntegral]) ++ [SArr 4, SIntegral]
      in mapM_ (\k -> runDt 0.05 (chainOf (withFs k)) [0 .. 60]
                         `shouldSatisfy` sameBits (runDt 0.05 (opaqueChainOf (withFs k)) [0 .. 60]))
               [0 .. 8]
  describe "delays fed by integrals, stages of the runs from the chain's second step" $ do
    it "give the numbers of the stages stepped one by one, in runs of every length, bit for bit (fixed)" $
      let stages k = [SIntegral, SPre 1] ++ concat (replicate k [SIntegral, SPre 2.5, SArr 1, SIntegral, SIntegral])
                     ++ [SPre 0]
      in mapM_ (\k -> runDt 0.05 (chainOf (stages k)) [0 .. 60]
                         `shouldSatisfy` sameBits (runDt 0.05 (opaqueChainOf (stages k)) [0 .. 60]))
               [0 .. 8]
    it "do the same with a delay behind a delay, and a chain ending in one (fixed)" $
      let stages k = [SIntegral] ++ replicate k SIntegral ++ [SPre 3, SPre (-1), SIntegral, SPre 2, SIntegral, SIntegral, SPre 0.5]
      in mapM_ (\k -> runDt 0.1 (chainOf (stages k)) [0 .. 40]
                         `shouldSatisfy` sameBits (runDt 0.1 (opaqueChainOf (stages k)) [0 .. 40]))
               [0 .. 4]
    it "are stepped from a kept state as often as asked, the same each time (fixed)" $ do
      let stages = [SIntegral, SPre 1, SIntegral, SArr 0, SIntegral, SPre 0, SIntegral]
          upTo sf = foldl (\(s, _) (dt, x) -> stepSF s dt x) (sf, 0) [(0, 1), (0.5, 2), (0.5, 3), (0.5, -1)]
          (kept, _) = upTo (chainOf stages)
          (keptRef, _) = upTo (opaqueChainOf stages)
          from s = runSamples' s [(0.25, 4), (0.5, 1), (0.5, 7)]
      sameBits (from kept) (from keptRef) `shouldBe` True
      _ <- evaluate (sum (from (fst (stepSF kept 2 100))))
      sameBits (from kept) (from keptRef) `shouldBe` True
    it "never evaluate a value the chain did not store itself: an output of a stage before the chain formed (fixed)" $ do
      -- the delay holds the replaced first output, an error nobody
      -- needs, when the chain forms; it outputs it at the chain's first
      -- step, to a function that ignores it
      let chain = (error "evaluated too early" --> integral) >>> iPre 0 >>> arr (const 1)
                    >>> integral >>> integral >>> iPre 0 >>> integral :: SF Double Double
      s <- evaluate (sum (runDt 0.1 chain (map fromIntegral [1 .. 12 :: Int])))
      s `shouldSatisfy` (not . isNaN)
  describe "a random chain of integrals, delays and functions" $ do
    it "gives the numbers of its stages stepped one by one, bit for bit (property)" $
      property $ forAll (listOf1 arbitrary) $ \stages ->
        forAll (genSamples (choose (-10, 10))) $ \samples ->
          sameBits (runSamples (chainOf stages) samples)
                   (runSamples (opaqueChainOf stages) samples)
    it "does the same between functions and after a stateful node (property)" $
      property $ forAll (listOf1 arbitrary) $ \stages ->
        forAll (genSamples (choose (-10, 10))) $ \samples ->
          let wrap c = localTime &&& identity >>> arr (\(t, x) -> t + x) >>> c >>> arr (* 3)
          in sameBits (runSamples (wrap (chainOf stages)) samples)
                      (runSamples (wrap (opaqueChainOf stages)) samples)
  describe "a chain's laziness (fixed)" $ do
    it "never evaluates its current input: the last input may be an error" $ do
      let chain = foldr1 (>>>) [integral, arr (* 2), integral, iPre 0, integral, integral] :: SF Double Double
          -- (embed evaluates each input sample: the error is made lazily)
          late x = if x > 20 then error "evaluated too early" else x
          ins   = map fromIntegral [1 .. 21 :: Int]
      s <- evaluate (sum (runDt 0.1 (arr late >>> chain) ins))
      s `shouldSatisfy` (not . isNaN)
    it "applies a function before an integral no earlier than the integral needs it" $ do
      -- the first integral outputs 0, 1, ..., 9; f of its last output is
      -- never needed
      let f :: Double -> Double
          f x = if x >= 9 then error "f applied too early" else 2 * x
          chain = foldr1 (>>>) [integral, arr f, integral, integral]
      outs <- evaluate (runDt 1 chain (replicate 10 1))
      s <- evaluate (sum outs)
      (length outs, isNaN s) `shouldBe` (10, False)
    it "closes a loop whose fed-back value it does not need at the instant" $
      withoutHanging (runDt 0.1 (loop (second (foldr1 (>>>) [integral, arr (* 2), integral, iPre 1])
                               >>> arr (\(a, _) -> (a, a)))) inputs)
             inputs
    it "feeds back through its own delay as the nodes one by one do" $
      withoutHanging (runDt 0.1 (loop (arr (uncurry (+)) >>> foldr1 (>>>) [integral, integral, iPre 0]
                               >>> arr (\y -> (y, y)))) inputs)
             (runDt 0.1 (loop (arr (uncurry (+)) >>> foldr1 (>>>) (map opaque [integral, integral, iPre 0])
                               >>> arr (\y -> (y, y)))) inputs)
  describe "integral *** integral at Double, stepped in place" $ do
    it "gives the numbers of the two integrals stepped one by one, bit for bit (property)" $
      property $ forAll (genSamples (choose (-10, 10))) $ \samples ->
        let pairUp = arr (\x -> (x, sin x)) >>> (integral *** integral) >>> arr (\(u, v) -> u - 2 * v)
            opaquePair = arr (\x -> (x, sin x)) >>> (opaque integral *** opaque integral)
                         >>> arr (\(u, v) -> u - 2 * v)
        in sameBits (runSamples pairUp samples) (runSamples opaquePair samples)
    -- (the pair is made by a function that looks at the value fed back:
    -- taking it apart at once would demand that value)
    it "does not evaluate its input pair: it closes a loop (fixed)" $
      withoutHanging (runDt 0.1 (loop (arr (\(a, c) -> (a, c)) >>> second (arr (\c -> if c > 0 then (c, c) else (c, negate c)) >>> (integral *** integral))
                               >>> arr (\(a, _) -> (a, a)))) inputs)
             inputs
  describe "arr p >>> (integral *** integral) at Double, one node" $ do
    let p x = (x * 2, cos x)
        q (u, v) = u - 3 * v
        fused = arr p >>> (integral *** integral) >>> arr q
        opaqueFused = opaque (arr p) >>> (opaque integral *** opaque integral) >>> opaque (arr q)
    it "is one node after its second step (fixed)" $ do
      let sf0 = arr p >>> (integral *** integral) :: SF Double (Double, Double)
          (sf1, _) = stepSF sf0 0 1
          (sf2, _) = stepSF sf1 0.1 2
          (sf3, _) = stepSF sf2 0.1 3
      map isStepSF [sf0, sf1, sf2, sf3] `shouldBe` [False, False, True, True]
    it "takes the function behind it into the node (fixed)" $ do
      let (sf1, _) = stepSF fused 0 1
          (sf2, _) = stepSF sf1 0.1 2
      map isStepSF [fused, sf1, sf2] `shouldBe` [False, False, True]
    it "gives the numbers of its stages with a function and a stateful node behind it (property)" $
      property $ forAll (genSamples (choose (-10, 10))) $ \samples ->
        let behind sf = sf >>> iPre 1 >>> arr (* 2)
        in sameBits (runSamples (behind fused) samples) (runSamples (behind opaqueFused) samples)
    it "gives the numbers of its stages stepped one by one, bit for bit (property)" $
      property $ forAll (genSamples (choose (-10, 10))) $ \samples ->
        sameBits (runSamples fused samples) (runSamples opaqueFused samples)
    it "does the same after a stateful node and in a loop through a delay (property)" $
      property $ forAll (genSamples (choose (-10, 10))) $ \samples ->
        let wrap sf = loop (arr (\(x, c) -> x + c) >>> (localTime &&& identity)
                            >>> arr (\(t, x) -> t + x) >>> sf >>> arr (\y -> (y, y))
                            >>> second (iPre 0))
        in sameBits (runSamples (wrap fused) samples) (runSamples (wrap opaqueFused) samples)
    it "never evaluates its current input: the last input may be an error (fixed)" $ do
      let late x = if x > 20 then error "evaluated too early" else x
          ins   = map fromIntegral [1 .. 21 :: Int]
      s <- evaluate (sum (runDt 0.1 (arr late >>> fused) ins))
      s `shouldSatisfy` (not . isNaN)
    it "applies p no earlier than the sums need it (fixed)" $ do
      let p' :: Double -> (Double, Double)
          p' x = if x >= 9 then error "p applied too early" else (x, 2 * x)
      outs <- evaluate (runDt 1 (integral >>> arr p' >>> (integral *** integral) >>> arr q)
                                (replicate 10 1))
      s <- evaluate (sum outs)
      (length outs, isNaN s) `shouldBe` (10, False)
    it "closes a loop whose fed-back value it does not need at the instant (fixed)" $
      withoutHanging (runDt 0.1 (loop (second (arr (\c -> (c, c + 1)) >>> (integral *** integral)
                                       >>> arr (uncurry (+)))
                               >>> arr (\(a, _) -> (a, a)))) inputs)
             inputs
