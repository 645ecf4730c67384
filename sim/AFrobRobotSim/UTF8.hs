{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.UTF8
-- Description : UTF-8 bytes: where they stop being UTF-8, the line and
--               column of an offset, the character and the byte at an
--               offset.
--
-- What every reader of the simulator's files (world files, run logs,
-- result lines) needs of UTF-8, on strict 'B.ByteString's; and 'Utf8',
-- bytes found to be UTF-8, so that a reader that checks a line once can
-- hand it on checked.
module AFrobRobotSim.UTF8
  ( utf8Fault
  , lineColumnAt
  , charAt
  , byteAt
    -- * Bytes checked once
  , Utf8
  , checkUtf8
  , utf8Bytes
  ) where

import           Data.Bits              ((.&.), (.|.), shiftL)
import qualified Data.ByteString        as B
import qualified Data.ByteString.Unsafe as BU
import           Data.Char              (chr)
import           Data.Word              (Word8)

-- | The first byte of a text that is not UTF-8, if any: its line and
-- column (both from 1; the column counted in characters, a line ended by
-- byte 10) and its value. Overlong forms, surrogates (U+D800 to U+DFFF)
-- and code points above U+10FFFF are not UTF-8.
utf8Fault :: B.ByteString -> Maybe (Int, Int, Word8)
utf8Fault bs = go 0
  where
    n = B.length bs
    at i = BU.unsafeIndex bs i
    cont i lo hi = i < n && at i >= lo && at i <= hi
    -- (from one byte outside ASCII to the next: the bytes between are
    -- characters, and are only counted, if there is a fault)
    go !i = case B.findIndex (>= 0x80) (B.drop i bs) of
      Nothing -> Nothing
      Just k  -> let j = i + k in maybe (Just (line j, column j, at j)) (\m -> go (j + 1 + m)) (sequenceAt j)
    -- the continuation bytes after a first byte that begin a character,
    -- if they do
    sequenceAt j
      | b >= 0xC2 && b <= 0xDF = need 1 0x80 0xBF
      | b == 0xE0 = need 2 0xA0 0xBF
      | b == 0xED = need 2 0x80 0x9F
      | b >= 0xE1 && b <= 0xEF = need 2 0x80 0xBF
      | b == 0xF0 = need 3 0x90 0xBF
      | b >= 0xF1 && b <= 0xF3 = need 3 0x80 0xBF
      | b == 0xF4 = need 3 0x80 0x8F
      | otherwise = Nothing
      where
        b = at j
        -- the second byte in [lo, hi], the others continuation bytes
        need k lo hi
          | not (cont (j + 1) lo hi) = Nothing
          | k >= 2 && not (cont (j + 2) 0x80 0xBF) = Nothing
          | k >= 3 && not (cont (j + 3) 0x80 0xBF) = Nothing
          | otherwise = Just (k :: Int)
    line j = fst (lineColumnAt bs j)
    column j = snd (lineColumnAt bs j)

-- | Bytes in which 'utf8Fault' finds no fault. Only 'checkUtf8' makes
-- one, so a function that takes 'Utf8' need not check its bytes again
-- (such as 'AFrobRobotSim.JSON.parseJSONUtf8').
newtype Utf8 = Utf8 B.ByteString

-- | The bytes as 'Utf8', or their first fault, as 'utf8Fault' gives it.
checkUtf8 :: B.ByteString -> Either (Int, Int, Word8) Utf8
checkUtf8 bs = maybe (Right (Utf8 bs)) Left (utf8Fault bs)

-- | The bytes themselves.
utf8Bytes :: Utf8 -> B.ByteString
utf8Bytes (Utf8 bs) = bs

-- | The line and column (both from 1, the column in characters) of an
-- offset of UTF-8 bytes, which are UTF-8 up to it (a line ended by byte 10).
lineColumnAt :: B.ByteString -> Int -> (Int, Int)
lineColumnAt bs i = (1 + B.count 10 before, 1 + B.foldl' character 0 (B.drop lineStart before))
  where
    before = B.take i bs
    lineStart = maybe 0 (+ 1) (B.elemIndexEnd 10 before)
    -- (characters: the bytes that are not a continuation byte)
    character a w = if w .&. 0xC0 == 0x80 then a else a + 1 :: Int

-- | The character that begins at an offset of UTF-8 bytes, and the offset
-- after it. The bytes there must be UTF-8 (checked by 'utf8Fault'):
-- their bounds are not checked.
charAt :: B.ByteString -> Int -> (Char, Int)
charAt bs i
  | b < 0x80  = (chr b, i + 1)
  | b < 0xE0  = (chr (((b .&. 0x1F) `shiftL` 6) .|. tl 1), i + 2)
  | b < 0xF0  = (chr (((b .&. 0x0F) `shiftL` 12) .|. (tl 1 `shiftL` 6) .|. tl 2), i + 3)
  | otherwise = (chr (((b .&. 0x07) `shiftL` 18) .|. (tl 1 `shiftL` 12) .|. (tl 2 `shiftL` 6) .|. tl 3), i + 4)
  where
    b = byteAt bs i
    tl k = byteAt bs (i + k) .&. 0x3F

-- | The byte at an offset, as an 'Int' (not bounds-checked): for
-- arithmetic on it, as 'charAt' and the JSON parser's decoding of
-- escapes do.
byteAt :: B.ByteString -> Int -> Int
byteAt bs i = fromIntegral (BU.unsafeIndex bs i)
{-# INLINE byteAt #-}
