-- | The parser of bytes ("AFrobRobotSim.JSON.Bytes") against the parser
-- of strings ('parseJSON'), on random texts and random faults in them,
-- on texts nested deep with parts beside the deep one at every level,
-- and on bytes that are not UTF-8; and the same of bytes checked once
-- ('parseJSONUtf8', 'cutShortUtf8'). The two passes behind it,
-- "AFrobRobotSim.JSON.Bytes.Build" and "AFrobRobotSim.JSON.Bytes.Scan",
-- are tested through it; how the second finds the parts' ends (an index,
-- and what it costs) is "AFrobRobotSim.JSON.Bytes.ScanSpec"'s.
module AFrobRobotSim.JSON.BytesSpec (spec) where

import qualified Data.ByteString          as BS
import           Data.List                (intercalate)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.JSON
import           AFrobRobotSim.JSON.EncodeSpec (AnyJSON (..), hostile)
import           AFrobRobotSim.JSONSpec   (numberText, utf8)
import           AFrobRobotSim.UTF8       (checkUtf8)

spec :: Spec
spec = do
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
    it "give, of bytes found to be UTF-8, what parseJSON and cutShort give too (parseJSONUtf8, cutShortUtf8) (property)" $
      withMaxSuccess 500 $ forAll jsonish $ \t ->
        case checkUtf8 (utf8 t) of
          Right u -> parseJSONUtf8 u === parseJSON t .&&. cutShortUtf8 u === cutShort t
          Left _  -> counterexample "the UTF-8 of a String without surrogates is UTF-8" False

  describe "parseJSONBytes of texts nested deep" $ do
    it "gives parseJSON's value of a text with parts beside the deep one at every level (property)" $
      forAll (choose (1, 60) >>= spine) $ \t -> parseJSONBytes (utf8 t) === parseJSON t
    it "gives parseJSON's value at the depth limit, with parts beside at every level (property)" $
      -- (nested up to 512 deep, all of it taken)
      withMaxSuccess 10 $ forAll (spine (maxDepth - 4)) $ \t ->
        either (const False) (const True) (parseJSON t) .&&. parseJSONBytes (utf8 t) === parseJSON t
    it "gives parseJSON's value of numbers nested 511 deep, and the whole of it (fixed)" $ do
      let t = replicate 511 '[' ++ intercalate "," (replicate 2000 "1") ++ replicate 511 ']'
      parseJSONBytes (utf8 t) `shouldBe` parseJSON t
      fmap depthAndCount (parseJSONBytes (utf8 t)) `shouldBe` Right (511, 2000)

-- | A text for the two parsers: mostly JSON (values written with
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

-- | A text nested @d@ deep or a little more, with parts beside the deep
-- one at every level (before it and after it, in arrays and objects; some
-- of them arrays and objects of their own, some strings holding brackets
-- and quotes), for the second pass's index of where the parts end.
spine :: Int -> Gen String
spine 0 = elements ["1", "\"s\"", "[]", "{}", "[[]]", "null", "[1, {\"a\": [2]}]"]
spine d = do
  ahead  <- resize 3 (listOf beside)
  behind <- resize 3 (listOf beside)
  inner  <- spine (d - 1)
  asObject <- arbitrary
  sp <- elements ["", " ", "\n "]
  let parts = ahead ++ [inner] ++ behind
      names = [ show ("k" ++ show k) ++ ":" ++ sp | k <- [0 :: Int ..] ]
  pure $ if asObject then "{" ++ sp ++ intercalate ("," ++ sp) (zipWith (++) names parts) ++ sp ++ "}"
                     else "[" ++ sp ++ intercalate ("," ++ sp) parts ++ sp ++ "]"
  where
    beside = elements [ "0", "-1.5e3", "\"a\\\"]}\"", "[]", "{}", "[1,[2,{\"x\":[3]}]]", "{\"y\":{\"z\":[]}}"
                      , "true", "\"[{\"", "\"\\u005b\"" ]

-- The depth of a value's first element at each level, and the count of
-- numbers at the bottom.
depthAndCount :: JSON -> (Int, Int)
depthAndCount = go 0
  where
    go d (JArray [x@(JArray _)]) = go (d + 1) x
    go d (JArray xs)             = (d + 1, length [ () | JNumber _ <- xs ])
    go d _                       = (d, 0)
