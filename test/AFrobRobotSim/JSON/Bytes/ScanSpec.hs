-- | Where the parts of a checked text end ("AFrobRobotSim.JSON.Bytes.Scan"):
-- the index of an array's or object's arrays and objects against a
-- simple reading of the text, and how many bytes the second pass reads
-- to find every part's end when a value is used whole: a count of bytes,
-- not a time, that grows with the text and not with its depth.
module AFrobRobotSim.JSON.Bytes.ScanSpec (spec) where

import qualified Data.ByteString          as BS
import           Data.List                (intercalate)
import           Data.Word                (Word8)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.JSON       (encodeJSON, maxDepth, JSON (..))
import           AFrobRobotSim.JSON.Bytes.Scan
import           AFrobRobotSim.JSON.EncodeSpec (AnyJSON (..))
import           AFrobRobotSim.JSONSpec   (utf8)

spec :: Spec
spec = do
  describe "containerIndex" $ do
    it "gives every array's and object's end, and the next one after it, in the order they open (fixed)" $ do
      let t = utf8 "[[1,{\"]\":[]}],{},\"[\",[[]]]"
      entries t 0 `shouldBe` reference t 0
      entries t 0 `shouldBe` [(26, 7), (13, 4), (12, 4), (11, 4), (16, 5), (25, 7), (24, 7)]
    it "agrees with a simple reading of the text, for any value in an array or object (property)" $
      property $ \(AnyJSON v) wrapInObject ->
        let t = utf8 (encodeJSON (if wrapInObject then JObject [("v", v), ("w", JArray [v])] else JArray [v, v]))
        in entries t 0 === reference t 0
    it "indexes the array or object at any offset, from itself on (fixed)" $ do
      let t = utf8 "{\"a\": [1, [2]], \"b\": {\"c\": []}}"
      entries t 6 `shouldBe` reference t 6
      entries t 21 `shouldBe` reference t 21

  describe "partEnd and inside: the bytes read to find every part's end, for a value used whole" $ do
    it "are at most 4 times the text's bytes, however deeply it nests, up to the depth limit (fixed)" $
      mapM_ (\d -> let t = utf8 (nestedNumbers d 400) in readToUseWhole t `shouldSatisfy` (<= 4 * BS.length t))
            [1, 2, 3, 10, 100, 300, maxDepth - 1]
    it "are at most 4 times the text's bytes for any value, and nested deep with parts beside (property)" $
      property $ \(AnyJSON v) (Small d) ->
        let t = utf8 (replicate (d `mod` 200) '[' ++ encodeJSON (JArray [v, JObject [("v", v)], v])
                      ++ replicate (d `mod` 200) ']')
        in counterexample (show (readToUseWhole t, BS.length t)) (readToUseWhole t <= 4 * BS.length t)
    it "read a part of the top level over once, and look up the ends of the parts inside it (fixed)" $ do
      -- (the top level's two parts: the array read over, 7 bytes, its
      -- index made in two passes, 14; the number at the bottom, 1)
      readToUseWhole (utf8 "[[[[1]]],2]") `shouldBe` 7 + 14 + 1 + 1
  where
    entries t i = let ix = containerIndex t i
                  in [ (indexEnd ix k, indexAfter ix k) | k <- [0 .. length (reference t i) - 1] ]

-- Numbers nested @d@ deep: @n@ ones in the innermost array.
nestedNumbers :: Int -> Int -> String
nestedNumbers d n = replicate d '[' ++ intercalate "," (replicate n "1") ++ replicate d ']'

-- The index of the array or object that opens at @i@, read simply: a
-- byte at a time, keeping a stack of the open ones; for each, in the
-- order they open, the offset after it and the count opened before that.
reference :: BS.ByteString -> Int -> [(Int, Int)]
reference t i0 = map snd (foldr insertEnd [] closes)
  where
    bytes = drop i0 (BS.unpack t)
    -- (ordinal, (end, opened before the end)) of each, as each closes
    closes = go (0 :: Int) [] False False (zip [i0 ..] bytes)
    go next stack inString escaped ((j, b) : rest)
      | inString = if escaped then go next stack True False rest
                   else if b == 92 then go next stack True True rest
                   else go next stack (b /= 34) False rest
      | b == 34 = go next stack True False rest
      | isOpen b = go (next + 1) (next : stack) False False rest
      | isClose b, k : outer <- stack =
          (k, (j + 1, next)) : (if null outer then [] else go next outer False False rest)
      | otherwise = go next stack False False rest
    go _ _ _ _ [] = []
    insertEnd e acc = let (lo, hi) = span ((< fst e) . fst) acc in lo ++ e : hi
    isOpen b = b == 91 || b == (123 :: Word8)
    isClose b = b == 93 || b == (125 :: Word8)

-- The bytes the second pass reads to find where each part ends, when
-- the value of a checked text is used whole, found as
-- "AFrobRobotSim.JSON.Bytes.Build" finds them: the top level's parts
-- with 'ReadOver', each part's cursor by 'inside', each end by
-- 'partEnd' (its 'stepRead'); and, for each part of the top level that
-- is an array or object, its bytes twice, for the two passes that make
-- its index ('containerIndex').
readToUseWhole :: BS.ByteString -> Int
readToUseWhole t = valueOf ReadOver (spaces t 0)
  where
    at = BS.index t
    -- (the value at @i@, its parts' cursor @c@)
    valueOf c i
      | at i == openBraceW   = partsFrom True c (spaces t (i + 1))
      | at i == openBracketW = partsFrom False c (spaces t (i + 1))
      | otherwise = 0
    -- (the parts from @i@, of an object or an array)
    partsFrom object c i
      | at i == closeBraceW || at i == closeBracketW = 0
      | otherwise =
          let v | object    = spaces t (spaces t (stringEnd t (i + 1)) + 1)   -- (after the name and colon)
                | otherwise = i
              Step e c' r = partEnd t c v
              indexing = case c of
                ReadOver | at v == openBraceW || at v == openBracketW -> 2 * (e - v)
                _ -> 0
              p = spaces t e
              rest = if at p == commaW then partsFrom object c' (spaces t (p + 1)) else 0
          in r + indexing + valueOf (inside t c v) v + rest
