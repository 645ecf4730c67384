{-# LANGUAGE BangPatterns #-}
{-# LANGUAGE MultiWayIf   #-}
-- |
-- Module      : AFrobRobotSim.JSON.Bytes.Build
-- Description : The second pass of the parser of bytes: a checked text's
--               value, made as it is used.
--
-- 'valueAt' makes the value of a text that the first pass
-- ("AFrobRobotSim.JSON.Bytes") has checked, each part when it is first
-- looked at: until then a part refers to the bytes. A part's end is
-- found as "AFrobRobotSim.JSON.Bytes.Scan" says (read over at the top
-- level, looked up in an index below it), so that a value used whole
-- costs time in proportion to its bytes, however deeply it nests, and a
-- part never looked at is neither made nor (below the top level)
-- indexed.
--
-- Strings of at most 64 bytes are made once and shared
-- ('sharedStrings'); numbers are rounded as the parser of strings rounds
-- them ('roundDigits', defined here, which "AFrobRobotSim.JSON" imports
-- through "AFrobRobotSim.JSON.Bytes").
module AFrobRobotSim.JSON.Bytes.Build
  ( -- * The value of a checked text
    valueAt
    -- * Numbers, shared with the parser of strings
  , roundDigits
  , significantDigits
  ) where

import qualified Data.ByteString           as B
import qualified Data.ByteString.Unsafe    as BU
import           Data.Char                 (chr)
import           Data.List                 (foldl')
import qualified Data.Map.Strict           as M

import           AFrobRobotSim.JSON.Bytes.Scan
import           AFrobRobotSim.JSON.Encode (JSON (..))
import           AFrobRobotSim.UTF8        (byteAt, charAt)

------------------------------------------------------------------------------
-- The value

-- | The value of a checked text (one the first pass accepts) whose
-- value begins at the given offset (after any whitespace), made as it
-- is used: each member (its name with it) and element when its list's
-- cell is, its value, and each number and string, when it is looked at.
-- The top level's parts are read over to find their ends, once each; a
-- part of the top level that is used indexes its arrays and objects
-- ('containerIndex') when the first of its own parts' ends is asked
-- for, and finds every end below it there.
valueAt :: B.ByteString -> Int -> JSON
valueAt bs start
  | b0 == openBraceW   = JObject (members ReadOver (spaces bs (start + 1)))
  | b0 == openBracketW = JArray (elements ReadOver (spaces bs (start + 1)))
  | otherwise          = value ReadOver start   -- (a string, a number, a keyword)
  where
    b0 = BU.unsafeIndex bs start
    n = B.length bs
    at = BU.unsafeIndex bs
    is i w = i < n && at i == w
    -- the value at @i@, a part among others whose cursor is @c@
    value c i
      | b == openBraceW   = JObject (members (inside bs c i) (spaces bs (i + 1)))
      | b == openBracketW = JArray (elements (inside bs c i) (spaces bs (i + 1)))
      | b == quoteW       = let !s = text (i + 1) (stringEnd bs (i + 1) - 1) in JString s
      | b == 116          = JBool True
      | b == 102          = JBool False
      | b == 110          = JNull
      | otherwise         = JNumber (numberAt bs i)
      where b = at i
    -- (the parts from @i@, after the opening brace or bracket and
    -- whitespace, @c@ the first one's cursor; a member's name made with
    -- its cell, its value when it is looked at)
    members c i
      | is i closeBraceW = []
      | otherwise =
          let j = stringEnd bs (i + 1)
              !k = text (i + 1) (j - 1)
              v = spaces bs (spaces bs j + 1)
              more = case partEnd bs c v of
                Step e c' _ -> let p = spaces bs e
                               in if is p commaW then members c' (spaces bs (p + 1)) else []
          in (k, value c v) : more
    elements c i
      | is i closeBracketW = []
      | otherwise =
          let more = case partEnd bs c i of
                Step e c' _ -> let p = spaces bs e
                               in if is p commaW then elements c' (spaces bs (p + 1)) else []
          in value c i : more
    -- (a string's characters: shared, or made for it)
    text a z = case M.lookup (slice bs a z) table of
      Just s  -> s
      Nothing -> stringText bs a z
    table = sharedStrings bs   -- (made when the first string is)

-- The bytes from @i@ to before @j@.
slice :: B.ByteString -> Int -> Int -> B.ByteString
slice bs i j = B.take (j - i) (B.drop i bs)

-- The strings of a checked text of at most 64 bytes, each made once and
-- shared by every string of its bytes: a log's frame names the same
-- dozen members of every robot, its battery and the types it sees, and a
-- string made for each took a third of the frame's value. At most
-- 'mostShared' strings are kept, the first in the text; any other is
-- made for itself.
sharedStrings :: B.ByteString -> M.Map B.ByteString String
sharedStrings bs = go M.empty 0
  where
    -- (from any place outside a string, the next quote opens one)
    go !m !i
      | M.size m >= mostShared = m
      | otherwise = case B.elemIndex quoteW (B.drop i bs) of
          Nothing -> m
          Just k ->
            let a = i + k + 1
                e = stringEnd bs a
                s = slice bs a (e - 1)
            in if e - 1 - a <= 64 && not (M.member s m)
                 then go (M.insert s (stringText bs a (e - 1)) m) e
                 else go m e

-- The most strings 'sharedStrings' keeps: 4096.
mostShared :: Int
mostShared = 4096

-- The characters of a checked string's bytes from @i@ to before @j@ (its
-- quotes excluded), escapes decoded: at most 64 bytes made now, whole; a
-- longer string made as it is used, of a copy of its bytes.
stringText :: B.ByteString -> Int -> Int -> String
stringText bs i j
  | j - i <= 64 = let s = decodeString bs i j in length s `seq` s
  | otherwise   = let !c = B.copy (slice bs i j) in decodeString c 0 (j - i)

-- The characters of checked string bytes from @i@ to before @j@, made as
-- they are used, each made with its list cell.
decodeString :: B.ByteString -> Int -> Int -> String
decodeString bs = go
  where
    at = BU.unsafeIndex bs
    go !i !j
      | i >= j = []
      | at i == backslashW = escaped (byteAt bs (i + 1))
      | otherwise = case charAt bs i of (!c, i') -> c : go i' j
      where
        escaped e = case e of
          117 -> let h = hex (i + 2)
                 in if h >= 0xD800 && h <= 0xDBFF then surrogate h else let !c = chr h in c : go (i + 6) j
          _   -> let !c = case e of
                        98  -> '\b'
                        102 -> '\f'
                        110 -> '\n'
                        114 -> '\r'
                        116 -> '\t'
                        _   -> chr e   -- (a quote, a backslash, a slash)
                 in c : go (i + 2) j
        -- (a high surrogate, with the low one of its pair when a \u escape
        -- of one follows; else alone, as the parser of strings makes it)
        surrogate h
          | i + 7 < j, at (i + 6) == backslashW, at (i + 7) == 117, l <- hex (i + 8), l >= 0xDC00, l <= 0xDFFF =
              let !c = chr (0x10000 + (h - 0xD800) * 0x400 + (l - 0xDC00)) in c : go (i + 12) j
          | otherwise = let !c = chr h in c : go (i + 6) j
    hex k = foldl' (\a m -> a * 16 + hexValue (byteAt bs m)) 0 [k .. k + 3]
    hexValue w | w <= 57   = w - 48
               | w >= 97   = w - 87
               | otherwise = w - 55

-- The checked number that begins at @i@, as the parser of strings makes
-- it: its digits read from the bytes (however many: none is copied but
-- the 'significantDigits' first), the result 'roundDigits''s.
numberAt :: B.ByteString -> Int -> Double
numberAt bs i0 = roundDigits negative kept dropped sticky (ex - lf)
  where
    n = B.length bs
    at = BU.unsafeIndex bs
    is i w = i < n && at i == w
    negative = at i0 == minusW
    i1 = if negative then i0 + 1 else i0
    i2 = digitsEnd bs i1
    li = i2 - i1
    (f1, f2) = if is i2 dotW then (i2 + 1, digitsEnd bs (i2 + 1)) else (i2, i2)
    lf = f2 - f1
    -- the digits, whole part then fraction, by their index
    digit k = if k < li then at (i1 + k) else at (f1 + k - li)
    total = li + lf
    zeros = length (takeWhile (\k -> digit k == zeroW) [0 .. total - 1])
    significant = total - zeros
    nKept = min significantDigits significant
    kept = [ toEnum (fromIntegral (digit k)) | k <- [zeros .. zeros + nKept - 1] ]
    dropped = significant - nKept
    sticky = any (\k -> digit k /= zeroW) [zeros + nKept .. total - 1]
    -- the exponent: digits beyond 15 (leading zeros aside), more than
    -- any text holds, read as 10^15 (an infinity or zero all the same)
    ex | is f2 lowerEW || is f2 upperEW =
           let s = f2 + 1
               eNeg = is s minusW
               d1 = if is s plusW || eNeg then s + 1 else s
               d2 = digitsEnd bs d1
               z = length (takeWhile (\m -> at m == zeroW) [d1 .. d2 - 1])
               e | d2 - d1 - z > 15 = 10 ^ (15 :: Int)
                 | otherwise = foldl' (\a m -> a * 10 + fromIntegral (at m) - 48) 0 [d1 + z .. d2 - 1]
           in if eNeg then negate e else e
       | otherwise = 0

------------------------------------------------------------------------------
-- Numbers, shared with the parser of strings

-- | @roundDigits negative kept dropped sticky e@: the number whose
-- significant digits (its leading zeros dropped) begin with @kept@ (at
-- most 'significantDigits' of them, as characters) and go on for
-- @dropped@ more, @sticky@ when one of those is not zero, times
-- @10^e@ (the exponent of the last of all the digits), negated if
-- @negative@; rounded to the nearest 'Double' as 'read' rounds it. No
-- digits kept is zero (negative zero when @negative@). At most 15 digits
-- and an exponent within 22 of them are made in one division or product,
-- which is exact then (both operands are); any other number is given to
-- 'read' as the digits kept, a 1 after them when @sticky@ (so a number
-- just above a point halfway between two 'Double's stays above it), and
-- an exponent within 99999 (beyond it a value is an infinity or zero,
-- however written).
roundDigits :: Bool -> String -> Int -> Bool -> Int -> Double
roundDigits negative kept dropped sticky e = signed $ case kept of
  [] -> 0
  _  ->
    let ex = max (-99999) (min 99999 (e + dropped - (if sticky then 1 else 0)))
        whole = foldl' (\a d -> a * 10 + fromIntegral (fromEnum d - fromEnum '0')) 0 kept :: Int
    in if | dropped == 0, length kept <= 15, ex >= 0, ex <= 22 -> fromIntegral whole * 10 ^ ex
          | dropped == 0, length kept <= 15, ex < 0, ex >= -22 -> fromIntegral whole / 10 ^ negate ex
          | otherwise -> read (kept ++ (if sticky then "1" else "") ++ "e" ++ show ex)
  where
    signed x = if negative then negate x else x

-- | The most significant digits of a number that are read: 800. The exact
-- decimal value of a point halfway between two 'Double's has at most 767,
-- so the rest cannot change how a number rounds, save by whether one of
-- them is not zero ('roundDigits''s @sticky@); and 'read' of a million
-- digits takes half a minute.
significantDigits :: Int
significantDigits = 800

