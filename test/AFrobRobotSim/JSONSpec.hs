-- | The JSON parser, and the encoder and parser together: round trips on
-- random values and hostile strings, and the parser's positioned errors.
-- The encoder's own properties are "AFrobRobotSim.JSON.EncodeSpec"'s.
module AFrobRobotSim.JSONSpec (spec) where

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
    it "reads a huge exponent quickly, as an infinity or zero (fixed)" $ do
      parseJSON ("1e" ++ replicate 100000 '9') `shouldSatisfy` either (const False) (== JNumber (1 / 0))
      parseJSON ("1e-" ++ replicate 100000 '9') `shouldBe` Right (JNumber 0)
