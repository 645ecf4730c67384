-- | The JSON parser, and the encoder and parser together: round trips on
-- random values and hostile strings, and the parser's positioned errors;
-- the parser of bytes against the parser of strings, on random texts and
-- random faults in them. The encoder's own properties are
-- "AFrobRobotSim.JSON.EncodeSpec"'s.
module AFrobRobotSim.JSONSpec (spec, utf8) where

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

  describe "parseJSONBytes and cutShortBytes" $ do
    it "give what parseJSON and cutShort give of the text the bytes are: the value, or the very error (property)" $
      withMaxSuccess 2000 $ forAll jsonish $ \t ->
        let b = utf8 t
        in counterexample (show b) (parseJSONBytes b === parseJSON t .&&. cutShortBytes b === cutShort t)
    it "read back any value encoded, and every proper prefix of one as cut short (property)" $
      property $ \(AnyJSON v) ->
        let t = encodeJSON (JObject [("v", v), ("s", JString (replicate 70 'x' ++ hostile ++ "\233\x1F600"))])
        in parseJSONBytes (utf8 t) === Right (JObject [("v", v), ("s", JString (replicate 70 'x' ++ hostile ++ "\233\x1F600"))])
           .&&. conjoin [ cutShortBytes (utf8 (take k t)) | k <- [0, 7 .. length t - 1] ]
    it "count columns in characters, not bytes, as parseJSON does (fixed)" $ do
      let t = "[\"\233\x20ac\x1F600\", \233]"
      parseJSONBytes (utf8 t) `shouldBe` Left "line 1, column 9: expected a JSON value, found '\\233'"
      parseJSONBytes (utf8 t) `shouldBe` parseJSON t
      -- (an unknown escape of a line break: parseJSON says column 0 of the next line)
      parseJSONBytes (utf8 "\n[\"\\\n\"]") `shouldBe` Left "line 3, column 0: unknown escape \\\n"
      parseJSONBytes (utf8 "\n[\"\\\n\"]") `shouldBe` parseJSON "\n[\"\\\n\"]"
    it "refuse bytes that are not UTF-8 at the first bad one, before any other fault (fixed)" $ do
      parseJSONBytes (BS.pack [0x5b, 0x0a, 0x22, 0xc3, 0xa9, 0xff, 0x22]) `shouldBe` Left "line 2, column 3: invalid UTF-8 (byte 0xff)"
      parseJSONBytes (BS.pack [0x7d, 0xc3]) `shouldBe` Left "line 1, column 2: invalid UTF-8 (byte 0xc3)"
      parseJSONBytes (BS.pack [0x22, 0xed, 0xa0, 0x80, 0x22]) `shouldBe` Left "line 1, column 2: invalid UTF-8 (byte 0xed)"
      cutShortBytes (BS.pack [0x5b, 0x22, 0xc3]) `shouldBe` False
    it "make a long string from its bytes alike, escapes, pairs and lone surrogates included (fixed)" $ do
      let long = concat (replicate 40 "a\\u00e9\\ud83d\\ude00\\ud800\\n\x20ac")
      parseJSONBytes (utf8 ("[\"" ++ long ++ "\", \"" ++ long ++ "\"]")) `shouldBe` parseJSON ("[\"" ++ long ++ "\", \"" ++ long ++ "\"]")
      fmap (\v -> case v of { JArray [JString s, _] -> length s; _ -> 0 }) (parseJSONBytes (utf8 ("[\"" ++ long ++ "\", 1]")))
        `shouldBe` Right (40 * 6)

-- | A text's UTF-8 bytes.
utf8 :: String -> BS.ByteString
utf8 = BL.toStrict . BB.toLazyByteString . BB.stringUtf8

-- A text for the two parsers: mostly JSON (values written with
-- whitespace between their tokens, strings with escapes of every kind,
-- surrogates paired and lone, characters outside ASCII, numbers of many
-- digits and of every form), often with a fault made in it: cut short,
-- a character put in or taken out, or nested near 'maxDepth' (both sides
-- of it).
jsonish :: Gen String
jsonish = do
  t <- (++) <$> ws <*> ((++) <$> sized (valueText . min 4 . (`div` 10)) <*> ws)
  frequency [(2, pure t), (5, mutate t), (2, mutate t >>= mutate), (1, deep t)]
  where
    ws = elements ["", "", " ", "\n", "\t ", "\r\n  "]
    valueText :: Int -> Gen String
    valueText d = frequency $
      [ (2, elements ["true", "false", "null", "tru", "nul", "True"])
      , (3, numberish)
      , (3, (\x -> "\"" ++ x ++ "\"") <$> stringBody) ] ++
      (if d > 0 then [(2, array), (2, object)] else [])
      where
        array = do
          xs <- resize 5 (listOf (valueText (d - 1)))
          sp <- ws
          pure ("[" ++ sp ++ commas sp xs ++ "]")
        object = do
          xs <- resize 5 (listOf ((\k sp v -> "\"" ++ k ++ "\"" ++ sp ++ ":" ++ sp ++ v)
                                    <$> stringBody <*> ws <*> valueText (d - 1)))
          sp <- ws
          pure ("{" ++ sp ++ commas sp xs ++ "}")
    commas sp = foldr (\x acc -> if null acc then x else x ++ sp ++ "," ++ sp ++ acc) ""
    stringBody = concat <$> resize 12 (listOf (frequency
      [ (6, (: []) <$> elements "abc xyz019 ~")
      , (3, elements [ "\\n", "\\\"", "\\\\", "\\/", "\\b\\f\\r\\t", "\\u00e9", "\\u0000", "\\uFFFF"
                     , "\\ud83d\\ude00", "\\uD800", "\\udc00", "\\ud83d\\u0041", "\\ud83dx", "\\ud83d\\" ])
      , (2, (: []) <$> elements "\233\x20ac\x1F600\x7f\x80\x2028\xFFFD")
      , (1, (: []) <$> elements "\t\n\0\x1f")
      , (1, (`replicate` 'q') <$> choose (60, 70)) ]))
    numberish = oneof
      [ show <$> (arbitrary :: Gen Int)
      , show <$> (arbitrary :: Gen Double)
      , numberText
      , (\k -> "0." ++ replicate k '0' ++ "1") <$> choose (790, 820)
      , (\k -> "1" ++ replicate k '3' ++ "e-" ++ show k) <$> choose (10, 900)
      , elements ["-", "-0", "00", "01", "1.", "1.e3", ".5", "1e", "1e+", "1E-0", "-01.5", "1e0000000000000000000001"] ]
    mutate t = do
      k <- choose (0, length t)
      c <- elements [ "{", "}", "[", "]", ",", ":", "\"", "\\", "u", "e", "-", ".", "0", " ", "\n", "\t", "\r"
                    , "\0", "\x1f", "\233", "\x1F600", "x", "tru", "\\u12", "\\\n", "\\\233" ]
      oneof [ pure (take k t)
            , pure (take k t ++ c ++ drop k t)
            , pure (take k t ++ drop (k + 1) t)
            , (\m -> take k t ++ c ++ drop (k + m) t) <$> choose (1, 3) ]
    deep t = do
      k <- choose (maxDepth - 2, maxDepth + 2)
      closing <- choose (k - 1, k)
      pure (replicate k '[' ++ t ++ replicate closing ']')

-- A JSON number's text, which is also one that 'read' reads as a
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
