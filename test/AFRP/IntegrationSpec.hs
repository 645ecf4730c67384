-- | Tests for "AFRP.Integration": the integrals, counting events and the
-- derivative, on hand-computed cases and by properties.
module AFRP.IntegrationSpec (spec) where

import           Control.Arrow    (arr, (>>>))
import           Data.Maybe       (fromMaybe)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Basic       (localTime)
import           AFRP.Event       (Event (..))
import           AFRP.Geometry    (Vector2 (..))
import           AFRP.Integration
import           AFRP.Internal.SF (DTime, SF, Time)
import           AFRP.Run         (embed)
import           TestUtil

-- | Feed the signal function a bottom wherever the outer input is
-- 'Nothing'. The runner may force each outer sample, but not what the
-- inner signal function receives, so this observes whether the signal
-- function under test evaluates its current input.
bottomWhereNothing :: SF a b -> SF (Maybe a) b
bottomWhereNothing sf = arr (fromMaybe (error "the current input was evaluated")) >>> sf

-- | The sample times of a list of samples (the first step ignored).
sampleTimes :: [(DTime, a)] -> [Time]
sampleTimes []             = []
sampleTimes ((_, _) : rest) = scanl (+) 0 (map fst rest)

-- | Samples with dyadic time steps (multiples of 1/64) and integer-valued
-- inputs, so that sums are exact.
genDyadic :: Gen [(DTime, Double)]
genDyadic = do
  k  <- choose (1, 30)
  vectorOf k ((,) <$> ((/ 64) . fromIntegral <$> (choose (1, 64) :: Gen Int))
                  <*> (fromIntegral <$> (choose (-50, 50) :: Gen Int)))

v2 :: Double -> Double -> Vector2 Double
v2 = Vector2

spec :: Spec
spec = do
  describe "integral" $ do
    it "follows the documented example" $
      embed integral (1, [(0.5, Just 2), (0.5, Just 3)]) `shouldBe` [0, 0.5, 1.5 :: Double]
    it "is 0 at time 0, then the left-rectangle sum (constant steps)" $
      runDt 0.5 integral [1, 2, 3, 4] `shouldBe` [0, 0.5, 1.5, 3.0 :: Double]
    it "uses each step with the previous input (irregular steps)" $
      -- 0 + .5*2 = 1; 1 + .25*4 = 2; 2 + 1*(-8) = -6
      runSamples integral [(9, 2), (0.5, 4), (0.25, -8), (1, 1)] `shouldBe` [0, 1, 2, -6 :: Double]
    it "integrates a constant into a ramp" $
      runDt 0.25 integral (replicate 5 (2 :: Double)) `shouldBe` [0, 0.5, 1, 1.5, 2]
    it "integrates Vector2 componentwise" $
      runDt 0.5 integral [v2 1 2, v2 3 (-1), v2 0 0] `shouldBe` [v2 0 0, v2 0.5 1, v2 2 0.5]
    it "integrates pairs componentwise" $
      runSamples integral [(0, (1, -2)), (2, (4, 0)), (0.5, (0, 0))]
        `shouldBe` [(0, 0), (2, -4), (4, -4 :: Double)]
    it "does not evaluate its current input" $
      runDt 1 (bottomWhereNothing integral) [Just 1, Just 2, Nothing] `shouldBe` [0, 1, 3 :: Double]
    it "of a constant c is c times the elapsed time" $
      property $ \c -> forAll (genSamples (pure ())) $ \samples ->
        let out = runSamples integral [(dt, c) | (dt, ()) <- samples]
        in conjoin [ counterexample (show (y, c * t)) (approx y (c * t))
                   | (y, t) <- zip out (sampleTimes samples) ]
    it "is the left-rectangle sum of the inputs" $
      forAll genDyadic $ \samples ->
        let xs  = map snd samples
            dts = drop 1 (map fst samples)
        in runSamples integral samples === scanl (+) 0 (zipWith (*) dts xs)

  describe "imIntegral" $ do
    it "follows the documented example" $
      embed (imIntegral 10) (1, [(0.5, Just 2), (0.5, Just 3)]) `shouldBe` [10, 11, 12.5 :: Double]
    it "is y0 at time 0 (ignoring the input there), then the right-rectangle sum" $
      runSamples (imIntegral 0) [(1, 5), (0.5, 2), (0.25, 4)] `shouldBe` [0, 1, 2 :: Double]
    it "integrates Vector2 componentwise" $
      runDt 0.5 (imIntegral (v2 1 1)) [v2 9 9, v2 2 (-2), v2 4 0] `shouldBe` [v2 1 1, v2 2 0, v2 4 0]
    it "is the right-rectangle sum of the inputs" $
      forAll genDyadic $ \samples ->
        let xs  = drop 1 (map snd samples)
            dts = drop 1 (map fst samples)
        in runSamples (imIntegral 3) samples === scanl (+) 3 (zipWith (*) dts xs)

  describe "trapezoidIntegral" $ do
    it "is 0 at time 0, then adds the step times the mean of both ends" $
      -- 0 + 1*(0+2)/2 = 1; 1 + 1*(2+2)/2 = 3; 3 + 1*(2+(-4))/2 = 2
      runDt 1 trapezoidIntegral [0, 2, 2, -4] `shouldBe` [0, 1, 3, 2 :: Double]
    it "is exact on a linear ramp (t^2 / 2), with irregular steps" $
      -- input t at times 0 .5 .75 1.5 2
      runSamples (localTime >>> trapezoidIntegral) (zip [0, 0.5, 0.25, 0.75, 0.5] (repeat ()))
        `shouldBe` [0, 0.125, 0.28125, 1.125, 2 :: Double]
    it "integrates Vector2 componentwise" $
      runDt 0.5 trapezoidIntegral [v2 0 2, v2 2 2, v2 4 0] `shouldBe` [v2 0 0, v2 0.5 1, v2 2 1.5]
    it "is exact on any linear ramp a + b t" $
      property $ \a b -> forAll (genSamples (pure ())) $ \samples ->
        let out = runSamples (localTime >>> arr (\t -> a + b * t) >>> trapezoidIntegral) samples
        in conjoin [ counterexample (show (y, t)) (approxWith 1e-7 y (a * t + b * t * t / 2))
                   | (y, t) <- zip out (sampleTimes samples) ]

  describe "impulseIntegral" $ do
    it "adds each impulse at the instant of its event" $
      -- integral of the first part: 0 .5 1 1.5 2 3; impulses +10 at t=1, -5 at t=2
      runDt 0.5 impulseIntegral
        [(1, NoEvent), (1, NoEvent), (1, Event 10), (1, NoEvent), (2, Event (-5)), (0, NoEvent)]
        `shouldBe` [0, 0.5, 11, 11.5, 7, 8 :: Double]
    it "adds an impulse at time 0 at once" $
      runDt 1 impulseIntegral [(0, Event 3), (0, NoEvent)] `shouldBe` [3, 3 :: Double]
    it "works on Vector2" $
      runDt 1 impulseIntegral [(v2 1 0, Event (v2 0 5)), (v2 1 0, NoEvent), (v2 0 0, Event (v2 1 1))]
        `shouldBe` [v2 0 5, v2 1 5, v2 3 6]

  describe "count" $ do
    it "occurs with the number of each occurrence" $
      runDt 1 count [NoEvent, Event 'a', NoEvent, Event 'b', Event 'c']
        `shouldBe` [NoEvent, Event 1, NoEvent, Event 2, Event (3 :: Int)]
    it "counts an occurrence at time 0" $
      runDt 1 count [Event (), Event ()] `shouldBe` [Event 1, Event (2 :: Integer)]
    it "the n-th occurrence carries n" $
      property $ \bs ->
        let input = [if b then Event () else NoEvent | b <- bs :: [Bool]]
        in [x | Event x <- runDt 1 count input] === [1 .. length (filter id bs)]

  describe "derivative" $ do
    it "follows the documented example" $
      embed derivative (1, [(0.5, Just 2), (0.5, Just 2)]) `shouldBe` [0, 2, 0 :: Double]
    it "is 0 at time 0, then the difference quotient" $
      runDt 0.5 derivative [1, 2, 2, 0] `shouldBe` [0, 2, 0, -4 :: Double]
    it "divides by each irregular step" $
      runSamples derivative [(7, 3), (0.25, 4), (2, 0)] `shouldBe` [0, 4, -2 :: Double]
    it "is 0 at time 0 whatever the input" $
      head (runDt 1 derivative [v2 5 7]) `shouldBe` v2 0 0
    it "differentiates Vector2 componentwise" $
      runDt 0.5 derivative [v2 5 7, v2 6 5] `shouldBe` [v2 0 0, v2 2 (-4)]
    it "of the integral recovers the previous input" $
      forAll (genSamples (choose (-100, 100 :: Double))) $ \samples ->
        let out = runSamples (integral >>> derivative) samples
        in conjoin [ counterexample (show (d, a)) (approxWith 1e-6 d a)
                   | (d, a) <- zip (drop 1 out) (map snd samples) ]
    it "followed by imIntegral from the first input recovers the input" $
      forAll (genSamples (choose (-100, 100 :: Double))) $ \samples ->
        let a0  = snd (head samples)
            out = runSamples (derivative >>> imIntegral a0) samples
        in conjoin [ counterexample (show (y, a)) (approxWith 1e-6 y a)
                   | (y, a) <- zip out (map snd samples) ]
