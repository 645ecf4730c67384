-- | The JSON encoder's own promises: pure printable ASCII that no page
-- can take for markup, strings as 'encodeString' writes them, numbers
-- that read back exactly, in plain decimals where they can be. The round
-- trips of whole values are "AFrobRobotSim.JSONSpec"'s, which takes its
-- random values and its hostile string from here.
module AFrobRobotSim.JSON.EncodeSpec
  ( spec
  , AnyJSON (..)
  , hostile
  ) where

import           Data.Char             (ord)
import           Data.List             (isInfixOf, (\\))
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.JSON        (parseJSON)
import           AFrobRobotSim.JSON.Encode

-- | Random values, a few levels deep; strings without surrogate code
-- points (which the encoder replaces, see "AFrobRobotSim.JSON.Encode").
newtype AnyJSON = AnyJSON JSON
  deriving (Show)

instance Arbitrary AnyJSON where
  arbitrary = AnyJSON <$> sized (gen . min 4 . (`div` 8))
    where
      gen :: Int -> Gen JSON
      gen d = oneof (leaves ++ if d <= 0 then [] else
        [ JArray <$> resize 5 (listOf (gen (d - 1)))
        , JObject <$> resize 5 (listOf ((,) <$> str <*> gen (d - 1))) ])
      leaves = [ pure JNull, JBool <$> arbitrary, JNumber <$> num, JString <$> str ]
      num = oneof [ arbitrary, fromIntegral <$> (arbitrary :: Gen Int), pure 1e300, pure 5e-324
                  , pure (-0.5), pure 1e15, pure 123456789012345678 ]
      str = listOf (oneof [ arbitrary `suchThat` notSurrogate
                          , elements "\"\\/<>&\n\r\t\b\f\0\DEL\x2028\x2029\x1F600\xFFFF" ])
      notSurrogate c = ord c < 0xD800 || ord c > 0xDFFF
  shrink (AnyJSON v) = map AnyJSON (case v of
    JArray xs  -> xs ++ map JArray (shrinkList (: []) xs)
    JObject kv -> map snd kv ++ map JObject (shrinkList (: []) kv)
    JString s  -> map JString (shrink s)
    _          -> [])

-- | A string with every way to close a page's @<script>@ or open a
-- comment in it, and characters that need escapes.
hostile :: String
hostile = "</script><img src=x onerror=\"alert('x')\">\\\"\n\r\t\0\x1b<!-- -->\x2028]]>&amp;"

spec :: Spec
spec = do
  describe "encodeJSON" $ do
    it "writes a string as encodeString does, short or long, plain or not (property)" $
      -- (mostly plain ASCII, the usual case, of every length around the
      -- short strings written in one piece)
      let plainChar = elements ([' ' .. '~'] \\ "\"\\<>&")
          str = oneof [ listOf plainChar, vectorOf 63 plainChar, vectorOf 64 plainChar, vectorOf 65 plainChar
                      , (++) <$> listOf plainChar <*> ((:) <$> elements "\"\\<>&\n\DEL\x2028" <*> listOf plainChar) ]
      in forAll str $ \t -> encodeJSON (JString t) === encodeString t .&&. parseJSON (encodeJSON (JString t)) === Right (JString t)
    it "writes pure printable ASCII, one line (property)" $ property $ \(AnyJSON v) ->
      all (\c -> c >= ' ' && c <= '~') (encodeJSON v)
    it "never writes '<', '>' or '&' (so no string closes a <script>) (property)" $ property $ \(AnyJSON v) ->
      not (any (`elem` "<>&") (encodeJSON v))
    it "escapes a hostile string so that no markup survives (fixed)" $ do
      let t = encodeJSON (JString hostile)
      t `shouldNotSatisfy` ("</" `isInfixOf`)
      t `shouldNotSatisfy` ("<!--" `isInfixOf`)
      t `shouldSatisfy` ("\\u003c/script\\u003e" `isInfixOf`)
      t `shouldSatisfy` ("\\u0000" `isInfixOf`)
      t `shouldSatisfy` ("\\u2028" `isInfixOf`)
    it "replaces surrogate code points by U+FFFD (fixed)" $
      encodeJSON (JString "a\xD800z") `shouldBe` "\"a\\ufffdz\""

  describe "encodeNumber" $ do
    it "writes non-finite numbers as null (fixed)" $
      map encodeNumber [0 / 0, 1 / 0, -1 / 0] `shouldBe` ["null", "null", "null"]
    it "writes integral values without a fraction, others exactly (fixed)" $
      map encodeNumber [3, -2, 0.1, 1e15, 2.5e-3, -1.570796, 1e-7, 123456.000001, 1e9 + 0.5]
        `shouldBe` ["3", "-2", "0.1", "1.0e15", "0.0025", "-1.570796", "1.0e-7", "123456.000001", "1.0000000005e9"]
    it "reads back every finite Double exactly (property)" $ property $ \x ->
      parseJSON (encodeNumber x) === Right (JNumber x)
    it "writes whole numbers of millionths in plain decimals that read back exactly (property)" $
      forAll (oneof [choose (-1000000, 1000000), choose (-1000000000000000, 1000000000000000)]) $ \n ->
                       let x = fromIntegral (n :: Int) / 1e6 :: Double
                           txt = encodeNumber x
                       in (all (`notElem` "eE") txt, parseJSON txt) === (True, Right (JNumber x))

    it "writes them as the shortest such decimal, digit for digit (property)" $
      -- (below 10^9, as 'encodeNumber' writes them; some with trailing
      -- zeros among the six places, some whole)
      forAll (oneof [ choose (-1000000, 1000000), choose (-999999999999999, 999999999999999)
                    , (* 1000) <$> choose (-999999999999, 999999999999) ]) $ \n ->
        let x = fromIntegral (n :: Int) / 1e6 :: Double
            (w, f) = abs n `quotRem` 1000000
            places = reverse (dropWhile (== '0') (reverse (replicate (6 - length (show f)) '0' ++ show f)))
        in encodeNumber x === (if n < 0 then "-" else "") ++ show w ++ (if f == 0 then "" else '.' : places)
