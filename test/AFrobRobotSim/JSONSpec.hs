-- | The JSON parser, and the encoder and parser together: round trips on
-- random values and hostile strings, and the parser's positioned errors.
-- The encoder's own properties are "AFrobRobotSim.JSON.EncodeSpec"'s; the
-- parser of bytes, checked against this parser, is
-- "AFrobRobotSim.JSON.BytesSpec"'s.
module AFrobRobotSim.JSONSpec (spec, utf8, numberText) where

import qualified Data.ByteString          as BS
import qualified Data.ByteString.Builder  as BB
import qualified Data.ByteString.Lazy     as BL
import           Data.List             (isInfixOf, isPrefixOf)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.JSON
import           AFrobRobotSim.JSON.EncodeSpec (AnyJSON (..), hostile)

spec :: Spec
spec = do
  describe "encodeJSON and parseJSON" $ do
    it "round trip any value (property)" $ property $ \(AnyJSON v) ->
      parseJSON (encodeJSON v) === Right v
    it "round trip a hostile string (fixed)" $
      parseJSON (encodeJSON (JString hostile)) `shouldBe` Right (JString hostile)
    it "write characters above U+FFFF as surrogate pairs, and read them back (fixed)" $ do
      encodeJSON (JString "\x1F600") `shouldBe` "\"\\ud83d\\ude00\""
      parseJSON "\"\\uD83D\\uDE00\"" `shouldBe` Right (JString "\x1F600")

  describe "cutShort" $ do
    it "holds of every proper prefix of an encoded object or array, and of no whole value (property)" $
      property $ \(AnyJSON v) ->
        let t = encodeJSON (JObject [("v", v)])
            u = encodeJSON (JArray [v, v])
        in conjoin [ cutShort (take k x) | x <- [t, u], k <- [0 .. length x - 1] ]
           .&&. not (cutShort t) .&&. not (cutShort u) .&&. not (cutShort (encodeJSON v))
    it "does not hold of a text with a fault before its end, or with more after a whole value (fixed)" $ do
      map cutShort ["{\"a\" 1", "[1,, 2", "{\"a\": tru", "{\"a\": 1}}", "[1] [", "hello", "{\"a\": nul"]
        `shouldBe` [False, False, True, False, False, False, True]
      map cutShort ["{\"a\": \"b", "{\"a\": 1.", "[-", "{\"a\": \"\\u00", "  ", ""]
        `shouldBe` [True, True, True, True, True, True]

  describe "parseJSON" $ do
    it "accepts whitespace and the escapes of RFC 8259 (fixed)" $
      parseJSON " { \"a\" : [1, -0.5e1, true, false, null, \"\\/\\b\\f\\u00e9\"] } \n"
        `shouldBe` Right (JObject [("a", JArray [ JNumber 1, JNumber (-5), JBool True, JBool False
                                                , JNull, JString "/\b\f\233" ])])
    let errorAt txt l c = case parseJSON txt of
          Left e  -> e `shouldSatisfy` (("line " ++ show l ++ ", column " ++ show (c :: Int) ++ ": ") `isPrefixOf`)
          Right v -> expectationFailure ("parsed " ++ show v)
    it "reports a missing comma with its line and column (fixed)" $
      errorAt "{\"a\": 1,\n \"b\": 2 \"c\": 3}" (2 :: Int) 9
    it "rejects a raw control character in a string, at its column (fixed)" $
      errorAt "[\"ab\tc\"]" (1 :: Int) 5
    it "rejects trailing text, NaN, leading zeros, single quotes, trailing commas (fixed)" $ do
      errorAt "1 2" (1 :: Int) 3
      errorAt "NaN" (1 :: Int) 1
      errorAt "[012]" (1 :: Int) 2
      errorAt "'a'" (1 :: Int) 1
      errorAt "[1,]" (1 :: Int) 4
      errorAt "" (1 :: Int) 1
      errorAt "\"abc" (1 :: Int) 5
    it "rejects nesting deeper than maxDepth, and accepts it up to there (fixed)" $ do
      parseJSON (replicate maxDepth '[' ++ replicate maxDepth ']') `shouldSatisfy` either (const False) (const True)
      parseJSON (replicate (maxDepth + 1) '[' ++ replicate (maxDepth + 1) ']')
        `shouldSatisfy` either ("deep" `isInfixOf`) (const False)
    it "reads any number as read reads it, rounded alike (property)" $
      forAll numberText $ \txt -> parseJSON txt === Right (JNumber (read txt))
    it "reads a number of many digits as read would, the digits past 800 kept by their trace (fixed)" $ do
      -- the point halfway between 1 and the next Double: even rounds down,
      -- a 1 far past the 800th digit rounds up
      let halfway = "1.00000000000000011102230246251565404236316680908203125"
      parseJSON halfway `shouldBe` Right (JNumber 1)
      parseJSON (halfway ++ replicate 2000 '0' ++ "1") `shouldBe` Right (JNumber (1 + 2 ^^ (-52 :: Int)))
      parseJSON (halfway ++ replicate 2000 '0') `shouldBe` Right (JNumber 1)
      -- long integers and fractions, and leading zeros of a fraction
      let long = "123456789" ++ concat (replicate 150 "9876543210")
      parseJSON long `shouldBe` Right (JNumber (read long))
      parseJSON ("-0." ++ long) `shouldBe` Right (JNumber (read ("-0." ++ long)))
      parseJSON ("0." ++ replicate 1200 '0' ++ long ++ "e1300") `shouldBe` Right (JNumber (read ("0." ++ long ++ "e100")))
      parseJSON ("0." ++ replicate 1000000 '0' ++ "1") `shouldBe` Right (JNumber 0)
      parseJSON ("1." ++ replicate 1000000 '7') `shouldBe` Right (JNumber (read ("1." ++ replicate 30 '7')))
      -- an exponent of more digits than any count of digits
      parseJSON ("0." ++ replicate 100 '0' ++ "1e" ++ replicate 20 '9') `shouldBe` Right (JNumber (1 / 0))
      parseJSON ("-0.0e-" ++ replicate 20 '9') `shouldSatisfy` either (const False) (\v -> v == JNumber 0 && isNegativeZeroOf v)
    it "reads a huge exponent quickly, as an infinity or zero (fixed)" $ do
      parseJSON ("1e" ++ replicate 100000 '9') `shouldSatisfy` either (const False) (== JNumber (1 / 0))
      parseJSON ("1e-" ++ replicate 100000 '9') `shouldBe` Right (JNumber 0)

-- | A text's UTF-8 bytes.
utf8 :: String -> BS.ByteString
utf8 = BL.toStrict . BB.toLazyByteString . BB.stringUtf8

-- | A JSON number's text, which is also one that 'read' reads as a
-- 'Double': a sign, digits (often many, some with leading zeros in the
-- fraction), a fraction, an exponent (the sign of both kinds), from the
-- small to beyond the Double's range.
numberText :: Gen String
numberText = do
  neg  <- elements ["", "-"]
  int  <- oneof [pure "0", (:) <$> elements ['1' .. '9'] <*> digitsUpTo 25]
  frac <- oneof [pure "", ('.' :) <$> ((++) <$> (flip replicate '0' <$> choose (0, 30)) <*> digits1UpTo 25)]
  ex   <- oneof [ pure "", (\e k -> e ++ show (k :: Int)) <$> elements ["e", "e-", "E", "E-"] <*> choose (0, 400)
                , (\e k -> e ++ show (k :: Int)) <$> elements ["e", "e-"] <*> choose (0, 25) ]
  pure (neg ++ int ++ frac ++ ex)
  where
    digitsUpTo n = choose (0, n) >>= \k -> vectorOf k (elements ['0' .. '9'])
    digits1UpTo n = (:) <$> elements ['0' .. '9'] <*> digitsUpTo (n - 1)

-- Whether a value is the number -0.
isNegativeZeroOf :: JSON -> Bool
isNegativeZeroOf (JNumber x) = isNegativeZero x
isNegativeZeroOf _           = False
