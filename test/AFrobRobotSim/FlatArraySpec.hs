-- | "AFrobRobotSim.FlatArray": what is written is read back, bit for bit,
-- before and after freezing (byte arrays once frozen), and a fresh 'Int'
-- array holds its fill value;
-- 'bucketLists' groups the pairs as a plain 'Data.Map' does, each bucket in
-- the order given; 'finite' is 'isNaN' and 'isInfinite' in one test.
--
-- Out of range: the module promises nothing (no bounds checks, and a
-- bucket must lie in @[0, buckets)@), so no test reads, writes or buckets
-- outside the sizes allocated.
module AFrobRobotSim.FlatArraySpec (spec) where

import           Control.Monad.ST        (ST, runST)
import           Data.Either             (lefts, rights)
import qualified Data.Map.Strict         as M
import           Data.Word               (Word64, Word8)
import           GHC.Float               (castDoubleToWord64)
import           Test.Hspec              hiding (after)
import           Test.QuickCheck

import           AFrobRobotSim.FlatArray

------------------------------------------------------------------------------
-- Arrays

-- | Writes to two arrays of @n@ elements, interleaved: @Left (i, x)@ to the
-- first, @Right (i, x)@ to the second, every index in range.
genWrites :: Gen a -> Int -> Gen [Either (Int, a) (Int, a)]
genWrites x n
  | n == 0    = pure []
  | otherwise = listOf (oneof [ Left <$> w, Right <$> w ])
  where w = (,) <$> chooseInt (0, n - 1) <*> x

-- | Every 'Int', the extremes often.
genInt :: Gen Int
genInt = oneof [arbitrary, elements [minBound, maxBound, 0, -1]]

-- | Every 'Double', the awkward ones often: NaN, both infinities, -0, the
-- largest finite number and the smallest denormal.
genDouble :: Gen Double
genDouble = oneof [arbitrary, elements [0 / 0, 1 / 0, -1 / 0, -0, 0, 1.7976931348623157e308, 5e-324, -5e-324]]

-- | The model: a map from index to value, the last write winning.
model :: [(Int, a)] -> [(Int, a)] -> [a]
model initial ws = M.elems (M.fromList (initial ++ ws))

-- | Two 'Int' arrays of @n@ elements, filled with @u@ and @v@: each read
-- before any write, after the writes, and frozen.
runInts :: Int -> Int -> Int -> [Either (Int, Int) (Int, Int)]
        -> (([Int], [Int]), ([Int], [Int]), ([Int], [Int]))
runInts n u v ws = runST $ do
  a <- newIntArr n u
  b <- newIntArr n v
  fresh <- both (readAll a) (readAll b)
  mapM_ (either (uncurry (writeI a)) (uncurry (writeI b))) ws
  written <- both (readAll a) (readAll b)
  fa <- freezeI a
  fb <- freezeI b
  pure (fresh, written, (map (indexI fa) [0 .. n - 1], map (indexI fb) [0 .. n - 1]))
  where
    readAll arr = mapM (readI arr) [0 .. n - 1]

-- | Two 'Double' arrays of @n@ elements, every element written first (a
-- fresh one's values are unspecified), then the writes: each read after
-- the writes, and frozen.
runDoubles :: Int -> [Double] -> [Double] -> [Either (Int, Double) (Int, Double)]
           -> (([Double], [Double]), ([Double], [Double]))
runDoubles n us vs ws = runST $ do
  a <- newDblArr n
  b <- newDblArr n
  mapM_ (uncurry (writeD a)) (zip [0 ..] us)
  mapM_ (uncurry (writeD b)) (zip [0 ..] vs)
  mapM_ (either (uncurry (writeD a)) (uncurry (writeD b))) ws
  written <- both (readAll a) (readAll b)
  fa <- freezeD a
  fb <- freezeD b
  pure (written, (map (indexD fa) [0 .. n - 1], map (indexD fb) [0 .. n - 1]))
  where
    readAll arr = mapM (readD arr) [0 .. n - 1]

both :: ST s a -> ST s b -> ST s (a, b)
both x y = (,) <$> x <*> y

-- | The bits of a number (so that NaN equals itself and -0 differs from 0).
bits :: [Double] -> [Word64]
bits = map castDoubleToWord64

------------------------------------------------------------------------------
-- Buckets

-- | A number of buckets (0 to 30) and pairs @(item, bucket)@ for it: any
-- items, repeated ones among them, crowded into a few buckets or spread
-- over all, so that some buckets are empty and some hold many.
genPairs :: Gen (Int, [(Int, Int)])
genPairs = do
  buckets <- chooseInt (0, 30)
  ps <- if buckets == 0 then pure [] else do
    few <- vectorOf 3 (chooseInt (0, buckets - 1))
    listOf ((,) <$> oneof [arbitrary, chooseInt (0, 5)]
                <*> oneof [chooseInt (0, buckets - 1), elements few])
  pure (buckets, ps)

-- | The pairs as the argument 'bucketLists' takes.
feed :: [(Int, Int)] -> (Int -> Int -> ST s ()) -> ST s ()
feed ps f = mapM_ (uncurry f) ps

-- | The reference: each bucket's items in the order given, from a map.
refBuckets :: Int -> [(Int, Int)] -> [[Int]]
refBuckets buckets ps =
  let m = M.fromListWith (flip (++)) [ (b, [i]) | (i, b) <- ps ]
  in [ M.findWithDefault [] b m | b <- [0 .. buckets - 1] ]

-- | What the arrays say: every start offset, and each bucket's items.
readBuckets :: Int -> (IntArr, IntArr) -> ([Int], [[Int]])
readBuckets buckets (starts, items) =
  ( map (indexI starts) [0 .. buckets]
  , [ map (indexI items) [indexI starts b .. indexI starts (b + 1) - 1] | b <- [0 .. buckets - 1] ] )

------------------------------------------------------------------------------

spec :: Spec
spec = do
  describe "newIntArr, readI, writeI, freezeI, indexI" $ do
    it "hold the fill value when fresh, then the last value written to each element, frozen or not" $
      property $ forAll (chooseInt (0, 40)) $ \n -> forAll genInt $ \u -> forAll genInt $ \v ->
        forAll (genWrites genInt n) $ \ws ->
          let (fresh, written, frozen) = runInts n u v ws
              want = ( model [ (i, u) | i <- [0 .. n - 1] ] (lefts ws)
                     , model [ (i, v) | i <- [0 .. n - 1] ] (rights ws) )
          in fresh === (replicate n u, replicate n v) .&&. written === want .&&. frozen === want

  describe "newIntArrUnset" $
    it "holds, once every element is written, the last value written to each, frozen or not" $
      property $ forAll (chooseInt (0, 40)) $ \n -> forAll (vectorOf n genInt) $ \us ->
        forAll (genWrites genInt n) $ \ws ->
          let (written, frozen) = runST $ do
                a <- newIntArrUnset n
                mapM_ (uncurry (writeI a)) (zip [0 ..] us)
                mapM_ (uncurry (writeI a)) [ w | Left w <- ws ]
                r <- mapM (readI a) [0 .. n - 1]
                f <- freezeI a
                pure (r, map (indexI f) [0 .. n - 1])
              want = model (zip [0 ..] us) (lefts ws)
          in written === want .&&. frozen === want

  describe "newDblArr, readD, writeD, freezeD, indexD" $
    it "hold the last value written to each element, bit for bit (NaN, -0 and infinities too), frozen or not" $
      property $ forAll (chooseInt (0, 40)) $ \n ->
        forAll (vectorOf n genDouble) $ \us -> forAll (vectorOf n genDouble) $ \vs ->
        forAll (genWrites genDouble n) $ \ws ->
          let (written, frozen) = runDoubles n us vs ws
              want = ( model (zip [0 ..] us) (lefts ws), model (zip [0 ..] vs) (rights ws) )
              asBits (xs, ys) = (bits xs, bits ys)
          in asBits written === asBits want .&&. asBits frozen === asBits want

  describe "newW8Arr, writeW8, freezeW8, indexW8" $
    it "hold the last byte written to each element, each array its own, all 256 values" $
      property $ forAll (chooseInt (0, 40)) $ \n ->
        forAll (vectorOf n arbitrary) $ \us -> forAll (vectorOf n arbitrary) $ \vs ->
        forAll (genWrites (elements [minBound .. maxBound :: Word8]) n) $ \ws ->
          let frozen = runST $ do
                a <- newW8Arr n
                b <- newW8Arr n
                mapM_ (uncurry (writeW8 a)) (zip [0 ..] us)
                mapM_ (uncurry (writeW8 b)) (zip [0 ..] vs)
                mapM_ (either (uncurry (writeW8 a)) (uncurry (writeW8 b))) ws
                fa <- freezeW8 a
                fb <- freezeW8 b
                pure (map (indexW8 fa) [0 .. n - 1], map (indexW8 fb) [0 .. n - 1])
          in frozen === (model (zip [0 ..] us) (lefts ws), model (zip [0 ..] vs) (rights ws))

  describe "bucketLists" $ do
    it "lists each bucket's items in the order given, as a map from buckets to lists has them" $
      property $ forAll genPairs $ \(buckets, ps) ->
        snd (readBuckets buckets (runST (bucketLists buckets (feed ps)))) === refBuckets buckets ps
    it "lays the buckets end to end from offset 0, up to the number of pairs" $
      -- (what 'AFrobRobotSim.RayGrid.rayGridEntries' reads at the end)
      property $ forAll genPairs $ \(buckets, ps) ->
        let (starts, _) = readBuckets buckets (runST (bucketLists buckets (feed ps)))
            counts = map length (refBuckets buckets ps)
        in starts === scanl (+) 0 counts

  describe "bucketListsUpTo" $
    it "is bucketLists for at most the limit's pairs, and Nothing for more" $
      property $ forAll genPairs $ \(buckets, ps) ->
        forAll (oneof [ elements [length ps - 1, length ps, length ps + 1], chooseInt (0, 60) ]) $ \limit ->
          let got  = fmap (readBuckets buckets) (runST (bucketListsUpTo buckets limit (feed ps)))
              full = readBuckets buckets (runST (bucketLists buckets (feed ps)))
          in got === (if length ps > limit then Nothing else Just full)

  describe "finite" $ do
    it "is False for NaN and both infinities, True for the extremes of the finite numbers" $
      map finite [0 / 0, 1 / 0, -1 / 0, 1.7976931348623157e308, -1.7976931348623157e308, 5e-324, -0, 0]
        `shouldBe` [False, False, False, True, True, True, True, True]
    it "is neither NaN nor infinite" $
      property $ forAll genDouble $ \v -> finite v === not (isNaN v || isInfinite v)
