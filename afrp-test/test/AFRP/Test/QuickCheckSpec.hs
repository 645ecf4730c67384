module AFRP.Test.QuickCheckSpec (spec) where

import           Control.Exception (ErrorCall (..), evaluate)
import           Control.Monad    (forM_)
import           Data.List        (isInfixOf, isPrefixOf)
import           Test.Hspec
import           Test.QuickCheck
import           Test.QuickCheck.Random (mkQCGen)

import           AFRP             (arr)
import           AFRP.Test.LTL
import           AFRP.Test.QuickCheck
import           AFRP.Test.Stream

-- Every time step after the first is positive, the first is 0.
wellFormed :: SignalSampleStream a -> Bool
wellFormed []             = False
wellFormed ((dt0, _) : s) = dt0 == 0 && all ((> 0) . fst) s

spec :: Spec
spec = do
  describe "generators (property)" $ do
    it "generateStream keeps the time steps inside the range" $
      forAll (generateStream DistRandom (Just 0.1, Just 0.3) Nothing) $ \s ->
        wellFormed (s :: SignalSampleStream Int) && all (\(dt, _) -> dt >= 0.1 && dt <= 0.3) (drop 1 s)
    it "DistNormal keeps the time steps inside the range" $
      forAll (generateStream (DistNormal (0.2, 0.1)) (Just 0.05, Just 0.5) (Just (Left 50))) $ \s ->
        length (s :: SignalSampleStream ()) == 51 && all (\(dt, _) -> dt >= 0.05 && dt <= 0.5) (drop 1 s)
    it "DistConstant uses one time step" $
      forAll (generateStream DistConstant (Just 0.01, Just 1) Nothing) $ \s ->
        length (nubDts (s :: SignalSampleStream Bool)) <= 1
    it "a length in time reaches that time" $
      forAll (generateStream DistRandom (Nothing, Just 0.5) (Just (Right 3))) $ \s ->
        wellFormed (s :: SignalSampleStream ()) && last (sampleTimes s) >= 3
    it "fixedDelayStreamWith gives each sample the value at its time" $
      forAll (fixedDelayStreamWith (* 2) 0.25) $ \s ->
        all (\(t, x) -> abs (x - 2 * t) < 1e-9) (zip (sampleTimes s) (samples (s :: SignalSampleStream Double)))
    it "a bound of the range below a millionth is kept (steps were raised to 1e-6)" $
      conjoin
        [ forAll (uniDistStreamMaxDT 1e-9) $ \s ->
            wellFormed (s :: SignalSampleStream ()) && all ((<= 1e-9) . fst) s
        , forAll (generateStream DistRandom (Just 0, Just 1e-9) (Just (Left 20))) $ \s ->
            wellFormed (s :: SignalSampleStream ()) && all ((<= 1e-9) . fst) s
        , forAll (fixedDelayStream 1e-7) $ \s ->
            all ((== 1e-7) . fst) (drop 1 (s :: SignalSampleStream ())) ]
    it "DistConstant with a length in time draws a step that reaches it (a draw near a lower bound of 0 was an error)" $
      -- (steps below 1e-8 take more than 10^8 to reach 1 s: half the range)
      -- (only the first two samples shown on a failure: the stream is long)
      conjoin
        [ forAll (take 2 <$> generateStream DistConstant (Just 0, Just 2e-8) (Just (Right 1))) $ \s ->
            case s :: SignalSampleStream () of
              [_, (dt, _)] -> dt >= 1 / fromIntegral (maxStreamSteps - 1) && dt <= 2e-8
              _            -> False
          -- (without an upper bound: the draw as for any length, short
          -- streams even at size 0, where the least step was the draw)
        , forAll (take 3 <$> resize 0 (generateStream DistConstant (Just 0, Nothing) (Just (Right 1)))) $ \s ->
            case s :: SignalSampleStream () of
              [_, (dt, _), _] -> dt > 2 / fromIntegral (maxStreamSteps - 1)
              _               -> True
          -- (and far above: a step at least the least one, at most the
          -- length; as many steps as reach the length, counted up to 1000
          -- only, since a step drawn uniformly is below 10^-3 of the
          -- length once in a thousand draws)
        , forAll (generateStream DistConstant (Nothing, Nothing) (Just (Right 1e300))) $ \s ->
            case s :: SignalSampleStream () of
              _ : (dt, _) : _ ->
                dt >= 1e300 / fromIntegral (maxStreamSteps - 1) && dt <= 1e300
                  && length (take 1001 s) == min 1001 (1 + ceiling (1e300 / dt))
              _ -> False ]
    it "uniDistStreamMaxDT streams are well formed" $
      forAll (uniDistStreamMaxDT 0.5) $ \s ->
        wellFormed (s :: SignalSampleStream ()) && all ((<= 0.5) . fst) s
  describe "generators refuse parameters that cannot give a stream" $ do
    let refused dist range len = do
          let gen = generateStream dist range len :: Gen (SignalSampleStream ())
          generate gen >>= evaluate . sum . map fst   -- (every time step made)
        fails = (`shouldThrow` errorCall' "AFRP.Test.QuickCheck.generateStream: ")
    it "an empty, negative or infinite range; a length in time that is not finite" $ do
      fails (refused DistRandom (Just 1, Just (1 / 0)) (Just (Left 3)))
      fails (refused DistRandom (Just 2, Just 1) (Just (Left 3)))
      fails (refused DistRandom (Just (-1), Nothing) (Just (Left 3)))
      fails (refused DistRandom (Nothing, Nothing) (Just (Right (1 / 0))))
      fails (refused DistConstant (Nothing, Nothing) (Just (Right (0 / 0))))
      fails (refused DistRandom (Nothing, Nothing) (Just (Right (-1))))
    it "a range with no positive step; a length in time the steps cannot reach (it hung or came out short)" $ do
      fails (refused DistConstant (Just 0, Just 0) (Just (Left 3)))
      fails (refused DistRandom (Nothing, Just 0) Nothing)
      fails (refused DistConstant (Just 1, Just 1) (Just (Right 1e300)))
      fails (refused DistRandom (Just 0.5, Just 1) (Just (Right 1e17)))
      -- (at once, from the upper bound: it made 10^8 steps first)
      fails (refused DistRandom (Nothing, Just 1e-9) (Just (Right 1)))
      -- (at once, from the steps' mean: the upper bound allowed the length,
      -- and the steps, half of it on average, made 10^8 steps first)
      fails (refused DistRandom (Nothing, Just 1) (Just (Right 7e7)))
      fails (refused DistRandom (Just 0.2, Just 1) (Just (Right 7e7)))
      fails (refused (DistNormal (0.5, 0.1)) (Nothing, Just 1) (Just (Right 7e7)))
      -- (a normal distribution cut to (0, 2]: its mean is
      -- (phi(0) - phi(2)) / (Phi(2) - Phi(0)) = 0.72276...)
      refused (DistNormal (0, 1)) (Nothing, Just 2) (Just (Right 8e7))
        `shouldThrow` (\(ErrorCall m) -> "average 0.7227" `isInfixOf` m && "about 110682" `isInfixOf` m)
      -- (steps too small to count: said so, not as a number of 309 digits)
      refused (DistNormal (0, 1e-300)) (Nothing, Just 1e300) (Just (Right 1e10))
        `shouldThrow` (\(ErrorCall m) -> "would need more steps than a number holds" `isInfixOf` m)
    it "a normal distribution that is not one, or that misses the range (instead of drawing forever)" $ do
      fails (refused (DistNormal (1, 0)) (Just 2, Nothing) (Just (Left 3)))
      fails (refused (DistNormal (0.1, -1)) (Nothing, Nothing) (Just (Left 3)))
      fails (refused (DistNormal (0 / 0, 1)) (Nothing, Nothing) (Just (Left 3)))
    it "what is possible still generates" $ do
      generate (generateStream (DistNormal (1, 0)) (Just 0.5, Just 2) (Just (Left 3)) :: Gen (SignalSampleStream ()))
        >>= (`shouldBe` [(0, ()), (1, ()), (1, ()), (1, ())])
      (length <$> generate (generateStream DistRandom (Just 0, Just 0.5) (Just (Right 0)) :: Gen (SignalSampleStream ())))
        `shouldReturn` 1
  describe "propT" $
    it "fails on an empty stream (no sample tested), holds on a stream where the predicate does" $ do
      r0 <- quickCheckWithResult stdArgs { chatty = False } (propT (Always (SP (arr not))) ([] :: SignalSampleStream Bool))
      isSuccess r0 `shouldBe` False
      r1 <- quickCheckWithResult stdArgs { chatty = False } (propT (Always (SP (arr not))) [(0, False), (1, False)])
      isSuccess r1 `shouldBe` True
  describe "shrinkStream (property)" $ do
    it "offers only well-formed streams, each smaller than the original" $
      forAll (generateStream DistRandom (Nothing, Just 2) (Just (Left 6))) $ \s ->
        all (\s' -> wellFormed s' && smaller s' s) (shrinkStream (s :: SignalSampleStream Int))
    it "keeps the other samples' times when it removes one" $
      let s = [(0, 'a'), (0.5, 'b'), (0.25, 'c'), (1, 'd')] :: SignalSampleStream Char
      in shrinkStreamWith (Nothing, Nothing) (const []) s `shouldContain` [[(0, 'a'), (0.75, 'c'), (1, 'd')]]
    it "rounds time steps, never to 0 nor out of the range" $
      shrinkStreamWith (Just 0.1, Nothing) (const []) [(0, ()), (0.137, ())]
        `shouldBe` [[(0, ())], [(0, ()), (0.1, ())], [(0, ()), (0.14, ())]]
    it "never merges two time steps into one beyond the range, and still removes where it can" $ do
      shrinkStreamWith (Just 0.05, Just 0.2) (const []) [(0, 'a'), (0.15, 'b'), (0.15, 'c'), (0.15, 'd')]
        `shouldSatisfy` all (all (\(dt, _) -> dt >= 0.05 && dt <= 0.2) . drop 1)
      -- (a step outside the range elsewhere does not stop a removal)
      shrinkStreamWith (Just 0.05, Just 0.2) (const []) [(0, 'a'), (0.3, 'b'), (0.1, 'c'), (0.1, 'd'), (0.1, 'e')]
        `shouldContain` [[(0, 'a'), (0.3, 'b'), (0.2, 'd'), (0.1, 'e')]]
    it "shrinkStreamIn offers only streams the generator could make: range and length kept" $
      forAll (elements [Just (Left 5), Just (Right 1.5)]) $ \len ->
        forAll (generateStream DistRandom (Just 0.05, Just 0.2) len) $ \s ->
          let ok s' = wellFormed s' && all (\(dt, _) -> dt >= 0.05 && dt <= 0.2) (drop 1 s')
                      && case len of
                           Just (Left n)  -> length s' == n + 1
                           Just (Right t) -> last (sampleTimes s') >= t - 1e-9
                           Nothing        -> True
              cands = shrinkStreamIn (Just 0.05, Just 0.2) len shrink (s :: SignalSampleStream Int)
          in counterexample (show (filter (not . ok) cands)) (all ok cands)
    it "forAllStreamsIn shrinks a failure to a stream of the generator's length (not one too short to hold)" $ do
      -- (fails at any stream that reaches t = 2.5; a stream shorter than
      -- 2 s, which the generator never makes, would fail 'eventually
      -- t >= 2' only for being short)
      let p = forAllStreamsIn DistRandom (Just 0.05, Just 0.2) (Just (Right 3)) shrink $ \s ->
                propT (And (Eventually (SP (arr (>= 2)))) (Always (SP (arr (< 2.5)))))
                      (zip (map fst (s :: SignalSampleStream ())) (sampleTimes s))
      r <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen 7, 0) } p
      isSuccess r `shouldBe` False
      case r of
        Failure { failingTestCase = shown : _ } -> do
          let times = [ read (words l !! 2) :: Double | l <- drop 2 (lines shown) ]
          last times `shouldSatisfy` (>= 3 - 1e-9)
        _ -> expectationFailure "no counterexample shown"
    it "forAllStreamsIn DistConstant shrinks to streams of one time step (it rounded the steps one by one, to a stream DistConstant never makes)" $ do
      -- (a filter for a fixed rate that fails at steps between 0.05 and
      -- 0.1 s, and at any stream whose steps differ; every counterexample
      -- DistConstant could make has steps all equal, in the range, and
      -- the generator's length)
      let fixedRate s = let dts = map fst (drop 1 s)
                        in and (zipWith (==) dts (drop 1 dts)) && not (any (\dt -> dt > 0.05 && dt < 0.1) dts)
          -- (the table's time steps, the first sample's 0 left out)
          stepsOf shown = [ read (words l !! 1) :: Double | l <- drop 2 (lines shown) ]
      forM_ [(Nothing, const True), (Just (Left 5), (== 5)), (Just (Right 0.5), const True)] $ \(len, countOk) ->
        forM_ [1 .. 4] $ \seed -> do
          r <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen seed, 0) } $
            forAllStreamsIn DistConstant (Just 0.01, Just 0.1) len shrink (fixedRate :: SignalSampleStream Int -> Bool)
          case r of
            Failure { failingTestCase = shown : _ } -> do
              let dts = drop 1 (stepsOf shown)
              (len, seed, dts) `shouldSatisfy` (\(_, _, ds) -> and (zipWith (==) ds (drop 1 ds)) && countOk (length ds))
              (len, seed, dts) `shouldSatisfy` (\(_, _, ds) -> all (\d -> d >= 0.01 && d <= 0.1) ds)
              case len of
                Just (Right t) -> (len, seed, sum dts) `shouldSatisfy` (\(_, _, reached) -> reached >= t - 1e-9)
                _              -> pure ()
            _ -> expectationFailure ("no counterexample: " ++ output r)
    it "showStream prints a stream with a step no run takes (it raised the runner's error)" $
      drop 2 (lines (showStream [(0, 'a'), (0.5, 'b'), (-1, 'c'), (0 / 0, 'd')]))
        `shouldBe` [ "    0    0.0         0.0         'a'", "    1    0.5         0.5         'b'"
                   , "    2    -1.0        -           'c'", "    3    NaN         -           'd'" ]
    it "showStream keeps its columns apart when a value is wider than its column" $
      lines (showStream [(0, 'a'), (2.0321708771485576, 'b')]) !! 3
        `shouldBe` "    1    2.0321708771485576 2.0321708771485576 'b'"
  where
    errorCall' prefix (ErrorCall m) = prefix `isPrefixOf` m
    nubDts s = foldr (\dt acc -> if dt `elem` acc then acc else dt : acc) [] (map fst (drop 1 s))
    -- Fewer samples, or as many with rounder steps or simpler values: the
    -- total of samples, decimals and value sizes goes down.
    smaller s' s = measure s' < measure s
    measure s = (length s, sum (map (decimals . fst) s) + sum (map (valueSize . snd) s))
    valueSize x = 2 * abs x + (if x < 0 then 1 else 0)
    decimals :: Double -> Int
    decimals x = head ([k | k <- [0 .. 8], fromIntegral (round (x * 10 ^ k) :: Integer) / 10 ^ k == x] ++ [9])
