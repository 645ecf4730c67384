-- | UTF-8 bytes ("AFrobRobotSim.UTF8"): where bytes stop being UTF-8
-- (overlong forms, surrogates, code points past U+10FFFF, sequences cut
-- short or broken, stray continuation bytes), the line and column of an
-- offset (the column in characters), the character at an offset, and
-- bytes checked once ('checkUtf8').
module AFrobRobotSim.UTF8Spec (spec) where

import qualified Data.ByteString    as BS
import           Data.Word          (Word8)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.JSONSpec (utf8)
import           AFrobRobotSim.UTF8

spec :: Spec
spec = do
  describe "utf8Fault" $ do
    it "finds none in ASCII, in characters of 2, 3 and 4 bytes, or at U+10FFFF, the last (fixed)" $ do
      utf8Fault (BS.pack []) `shouldBe` Nothing
      utf8Fault (utf8 "plain ASCII\n\t~\DEL\NUL") `shouldBe` Nothing
      utf8Fault (BS.pack [0xc3, 0xa9, 0xe2, 0x82, 0xac, 0xf0, 0x9f, 0x98, 0x80]) `shouldBe` Nothing   -- é € 😀
      utf8Fault (BS.pack [0xc2, 0x80, 0xdf, 0xbf]) `shouldBe` Nothing                   -- U+0080, U+07FF
      utf8Fault (BS.pack [0xe0, 0xa0, 0x80, 0xef, 0xbf, 0xbf]) `shouldBe` Nothing       -- U+0800, U+FFFF
      utf8Fault (BS.pack [0xed, 0x9f, 0xbf, 0xee, 0x80, 0x80]) `shouldBe` Nothing       -- U+D7FF, U+E000
      utf8Fault (BS.pack [0xf0, 0x90, 0x80, 0x80, 0xf4, 0x8f, 0xbf, 0xbf]) `shouldBe` Nothing   -- U+10000, U+10FFFF
    it "refuses overlong forms, at their first byte (fixed)" $ do
      faultOf [0xc0, 0x80] `shouldBe` Just (1, 1, 0xc0)             -- NUL in two bytes
      faultOf [0x61, 0xc1, 0xbf] `shouldBe` Just (1, 2, 0xc1)       -- U+007F in two
      faultOf [0xe0, 0x9f, 0xbf] `shouldBe` Just (1, 1, 0xe0)       -- U+07FF in three
      faultOf [0xf0, 0x8f, 0xbf, 0xbf] `shouldBe` Just (1, 1, 0xf0) -- U+FFFF in four
    it "refuses surrogates, U+D800 to U+DFFF (fixed)" $ do
      faultOf [0xed, 0xa0, 0x80] `shouldBe` Just (1, 1, 0xed)
      faultOf [0x22, 0xed, 0xbf, 0xbf, 0x22] `shouldBe` Just (1, 2, 0xed)
    it "refuses code points past U+10FFFF, and bytes that begin nothing (fixed)" $ do
      faultOf [0xf4, 0x90, 0x80, 0x80] `shouldBe` Just (1, 1, 0xf4)
      faultOf [0xf5, 0x80, 0x80, 0x80] `shouldBe` Just (1, 1, 0xf5)
      faultOf [0x61, 0xff] `shouldBe` Just (1, 2, 0xff)
      faultOf [0x61, 0x80] `shouldBe` Just (1, 2, 0x80)             -- a continuation byte alone
      faultOf [0xc3, 0xa9, 0xa9] `shouldBe` Just (1, 2, 0xa9)       -- one too many
    it "refuses a sequence cut short, at the text's end or by another byte (fixed)" $ do
      faultOf [0x61, 0xc3] `shouldBe` Just (1, 2, 0xc3)
      faultOf [0xe2, 0x82] `shouldBe` Just (1, 1, 0xe2)
      faultOf [0xf0, 0x9f, 0x98] `shouldBe` Just (1, 1, 0xf0)
      faultOf [0xe2, 0x82, 0x41] `shouldBe` Just (1, 1, 0xe2)
      faultOf [0xf0, 0x9f, 0x0a, 0x80] `shouldBe` Just (1, 1, 0xf0)
    it "gives the first fault's line and column, the column counted in characters (fixed)" $ do
      -- "a\nbé€😀c" then 0xff: line 2, column 6
      faultOf ([0x61, 0x0a, 0x62, 0xc3, 0xa9, 0xe2, 0x82, 0xac, 0xf0, 0x9f, 0x98, 0x80, 0x63, 0xff, 0xc0])
        `shouldBe` Just (2, 6, 0xff)
      faultOf [0x0a, 0x0a, 0x0a, 0x80] `shouldBe` Just (4, 1, 0x80)
    it "finds none in the UTF-8 of any text without surrogates (property)" $
      forAll textWithoutSurrogates $ \s -> utf8Fault (utf8 s) === Nothing

  describe "lineColumnAt" $ do
    let t = utf8 "ab\ncé€😀x\n"   -- offsets: a 0, b 1, \n 2, c 3, é 4, € 6, 😀 9, x 13, \n 14
    it "counts lines from 1 and columns from 1 in characters, a line ended by byte 10 (fixed)" $ do
      map (lineColumnAt t) [0, 1, 2, 3, 4, 6, 9, 13, 14, 15]
        `shouldBe` [(1, 1), (1, 2), (1, 3), (2, 1), (2, 2), (2, 3), (2, 4), (2, 5), (2, 6), (3, 1)]
    it "gives the line and column of every character of a text as a walk over its characters does (property)" $
      forAll textWithoutSurrogates $ \s ->
        let b = utf8 s
        in [ lineColumnAt b i | i <- charOffsets b ] === take (length s) (positions s)

  describe "charAt" $ do
    it "reads characters of 1 to 4 bytes, and gives the offset after each (fixed)" $ do
      let t = utf8 "aé€😀\xFFFD\x10FFFF"
      map (charAt t) [0, 1, 3, 6, 10, 13]
        `shouldBe` [ ('a', 1), ('\233', 3), ('\x20ac', 6), ('\x1F600', 10), ('\xFFFD', 13)
                   , ('\x10FFFF', 17) ]
      BS.length t `shouldBe` 17
    it "reads back every character of a text's UTF-8 (property)" $
      forAll textWithoutSurrogates $ \s -> decodeAll (utf8 s) === s

  describe "checkUtf8" $ do
    it "gives the bytes themselves, or utf8Fault's fault (fixed)" $ do
      fmap utf8Bytes (checkUtf8 (utf8 "né😀")) `shouldBe` Right (utf8 "né😀")
      fmap utf8Bytes (checkUtf8 (BS.pack [0x0a, 0x61, 0xed, 0xa0, 0x80])) `shouldBe` Left (2, 2, 0xed)
  where
    faultOf :: [Word8] -> Maybe (Int, Int, Word8)
    faultOf = utf8Fault . BS.pack

-- A text of any characters but surrogates (which UTF-8 cannot hold),
-- line breaks among them.
textWithoutSurrogates :: Gen String
textWithoutSurrogates = listOf $ frequency
  [ (4, elements "ab z~\DEL\NUL")
  , (1, pure '\n')
  , (2, elements "\128\233\2047\2048\x20ac\xD7FF\xE000\xFFFF\x10000\x1F600\x10FFFF")
  , (2, arbitrary `suchThat` (\c -> c < '\xD800' || c > '\xDFFF')) ]

-- The offsets at which the characters of UTF-8 bytes begin.
charOffsets :: BS.ByteString -> [Int]
charOffsets b = go 0
  where
    go i | i >= BS.length b = []
         | otherwise        = i : go (snd (charAt b i))

-- Every character of UTF-8 bytes, read with 'charAt'.
decodeAll :: BS.ByteString -> String
decodeAll b = [ fst (charAt b i) | i <- charOffsets b ]

-- The line and column of each character of a text, and of its end.
positions :: String -> [(Int, Int)]
positions = scanl step (1, 1)
  where
    step (l, _) '\n' = (l + 1, 1)
    step (l, c) _    = (l, c + 1)
