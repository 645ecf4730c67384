{-# LANGUAGE BangPatterns #-}
{-# LANGUAGE MultiWayIf   #-}
-- |
-- Module      : AFrobRobotSim.JSON.Bytes
-- Description : The JSON parser over UTF-8 bytes, which makes a value as
--               it is used.
--
-- 'AFrobRobotSim.JSON.parseJSON' reads a 'String', and a 'String' takes
-- some 24 bytes a character: a run log's line of 38 MB (a frame of
-- 100,000 robots) read through one took gigabytes. 'parseJSONBytes'
-- reads the bytes themselves, as UTF-8, in two passes: the first checks
-- the whole text and finds its first fault (the very message, at the
-- very line and column, that 'AFrobRobotSim.JSON.parseJSON' gives for
-- the text the bytes are), and makes nothing; the second makes the value
-- from the checked bytes only as it is used, each part when it is first
-- looked at. A line refused for a member it lacks has cost its bytes;
-- one used whole costs its value, which its user makes anyway.
--
-- The pieces both parsers share (the depth limit, how a number's digits
-- are rounded) are here too (where bytes stop being UTF-8 is
-- "AFrobRobotSim.UTF8"'s);
-- "AFrobRobotSim.JSON" re-exports what of this module is for its users:
-- import that.
module AFrobRobotSim.JSON.Bytes
  ( -- * Parsing bytes
    parseJSONBytes
  , cutShortBytes
  , maxDepth
    -- * Shared with the parser of strings
  , roundDigits
  , significantDigits
  ) where

import qualified Data.ByteString           as B
import qualified Data.ByteString.Unsafe    as BU
import           Data.Char                 (chr)
import           Data.List                 (foldl')
import qualified Data.Map.Strict           as M
import           Data.Word                 (Word8)
import           Numeric                   (showHex)

import           AFrobRobotSim.JSON.Encode (JSON (..))
import           AFrobRobotSim.UTF8        (charAt, lineColumnAt, utf8Fault)

-- | How deeply arrays and objects may nest in a text 'parseJSONBytes' and
-- 'AFrobRobotSim.JSON.parseJSON' accept: 512 (deeper input is rejected,
-- not a stack to exhaust).
maxDepth :: Int
maxDepth = 512

------------------------------------------------------------------------------
-- The two parsers' shared pieces

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

------------------------------------------------------------------------------
-- Parsing

-- | Parse a JSON text given as UTF-8 bytes: the same value, or the same
-- error (@line L, column C: what was expected@, the column counted in
-- characters), as 'AFrobRobotSim.JSON.parseJSON' of the text the bytes
-- are. Bytes that are not UTF-8 are refused before anything else, at the
-- first bad one: @line L, column C: invalid UTF-8 (byte 0xNN)@.
--
-- The whole text is checked before 'Right' is given, but the value is
-- made as it is used: each member (its name with it), element, number
-- and string when it is first looked at. Until then its parts refer to
-- the bytes. A string of more than 64 bytes is made, when it is looked
-- at, of a copy of its own bytes (one byte a character until its
-- characters are used); a shorter one is made whole, and shared by the
-- strings of the same bytes (of the first 4096 such strings of the text,
-- found in a pass of its own when the first string is made).
--
-- The cost of using a value whole grows with its depth: an array or an
-- object finds where each of its parts ends by reading over it, and a
-- part that is itself an array or object is read over again when it is
-- used, so a text nested @d@ deep costs up to @d@ times its bytes (a
-- review measured 6.1 s against 'AFrobRobotSim.JSON.parseJSON''s 0.9 s
-- for 4 MB of numbers 511 arrays deep). A run log's lines nest a few
-- levels, and are read in about their bytes' time.
parseJSONBytes :: B.ByteString -> Either String JSON
parseJSONBytes bs = case utf8Fault bs of
  Just (l, c, b) -> Left (lineColumn l c ("invalid UTF-8 (byte 0x" ++ (if b < 16 then "0" else "")
                                          ++ showHex b ")"))
  Nothing -> case checkValue bs 0 start of
    Bad i back msg -> Left (located bs i back msg)
    Ok j
      | k < B.length bs -> Left (located bs k False ("expected the end of the text, found " ++ describeAt bs k))
      | otherwise       -> Right (valueAt bs start)
      where k = spaces bs j
  where
    start = spaces bs 0

-- | 'AFrobRobotSim.JSON.cutShort' of the text the bytes are, as UTF-8:
-- whether it is not JSON only because it ends too soon. Bytes that are
-- not UTF-8 are not (they are not JSON for another reason). Nothing is
-- made: a long line is checked in its own bytes.
cutShortBytes :: B.ByteString -> Bool
cutShortBytes bs = case utf8Fault bs of
  Just _  -> False
  Nothing -> case checkValue bs 0 (spaces bs 0) of
    Bad i back _ -> not back && i == B.length bs
    Ok _         -> False

-- An error's message, from the offset of its place: @line L, column C:
-- msg@. @back@: the place is one column before the end of the character
-- at the offset (as the parser of strings reports the character of an
-- unknown escape, which is that character's own column, save for a line
-- break: column 0 of the next line).
located :: B.ByteString -> Int -> Bool -> String -> String
located bs i back msg
  | back && i < B.length bs && BU.unsafeIndex bs i == 10 = lineColumn (l + 1) 0 msg
  | otherwise = lineColumn l c msg
  where
    (l, c) = lineColumnAt bs i

lineColumn :: Int -> Int -> String -> String
lineColumn l c msg = "line " ++ show l ++ ", column " ++ show c ++ ": " ++ msg

-- What is at an offset, for messages, as the parser of strings says it:
-- the character there ('show'n), or @end of input@.
describeAt :: B.ByteString -> Int -> String
describeAt bs i
  | i >= B.length bs = "end of input"
  | otherwise        = show (fst (charAt bs i))

-- A byte as an 'Int'.
byteAt :: B.ByteString -> Int -> Int
byteAt bs i = fromIntegral (BU.unsafeIndex bs i)
{-# INLINE byteAt #-}

-- The offset of the first byte from @i@ on that is not JSON whitespace.
spaces :: B.ByteString -> Int -> Int
spaces = skipping isSpaceW

-- The offset of the first byte from @i@ on that the test does not take
-- (or the text's end).
skipping :: (Word8 -> Bool) -> B.ByteString -> Int -> Int
skipping ok bs = go
  where
    n = B.length bs
    go !i | i < n, ok (BU.unsafeIndex bs i) = go (i + 1)
          | otherwise = i
{-# INLINE skipping #-}

isSpaceW, isDigitW, isHexW :: Word8 -> Bool
isSpaceW w = w == 32 || w == 9 || w == 13 || w == 10
isDigitW w = w >= 48 && w <= 57
isHexW w = isDigitW w || (w >= 97 && w <= 102) || (w >= 65 && w <= 70)

-- Named bytes.
quoteW, backslashW, openBraceW, closeBraceW, openBracketW, closeBracketW, commaW, colonW, minusW, plusW,
  dotW, zeroW, lowerEW, upperEW :: Word8
quoteW = 34
backslashW = 92
openBraceW = 123
closeBraceW = 125
openBracketW = 91
closeBracketW = 93
commaW = 44
colonW = 58
minusW = 45
plusW = 43
dotW = 46
zeroW = 48
lowerEW = 101
upperEW = 69

------------------------------------------------------------------------------
-- The first pass: the text checked, nothing made

-- How a check ends: at the offset after what was checked, or at a fault
-- (its offset, whether it is reported one column back from the end of the
-- character there, and what was expected).
data Check = Ok !Int | Bad !Int !Bool String

-- @checkValue bs depth i@: the value that should begin at offset @i@,
-- nested @depth@ deep, checked as the parser of strings parses it: the
-- same first fault, at the same place.
checkValue :: B.ByteString -> Int -> Int -> Check
checkValue bs = value
  where
    n = B.length bs
    at = BU.unsafeIndex bs
    is i w = i < n && at i == w
    bad i msg = Bad i False msg
    found what i = bad i ("expected " ++ what ++ ", found " ++ describeAt bs i)
    value !d !i
      | i >= n = found "a JSON value" i
      | b == openBraceW   = nested (members d (spaces bs (i + 1)))
      | b == openBracketW = nested (elements d (spaces bs (i + 1)))
      | b == quoteW       = string (i + 1)
      | b == 116          = keyword "true" i
      | b == 102          = keyword "false" i
      | b == 110          = keyword "null" i
      | b == minusW || isDigitW b = number i
      | otherwise = found "a JSON value" i
      where
        b = at i
        nested k | d >= maxDepth = bad i ("nested more than " ++ show maxDepth ++ " deep")
                 | otherwise     = k
    -- (after the brace and whitespace)
    members d i | is i closeBraceW = Ok (i + 1)
                | otherwise        = member d i
    member d i0
      | not (is i quoteW) = found "a member name (a string)" i
      | otherwise = case string (i + 1) of
          Ok j | is k colonW -> case value (d + 1) (spaces bs (k + 1)) of
                   Ok m -> let p = spaces bs m
                           in if | is p commaW      -> member d (p + 1)
                                 | is p closeBraceW -> Ok (p + 1)
                                 | otherwise        -> found "',' or '}'" p
                   fault -> fault
               | otherwise -> found "':'" k
            where k = spaces bs j
          fault -> fault
      where i = spaces bs i0
    -- (after the bracket and whitespace)
    elements d i | is i closeBracketW = Ok (i + 1)
                 | otherwise          = element d i
    element d i = case value (d + 1) (spaces bs i) of
      Ok m -> let p = spaces bs m
              in if | is p commaW        -> element d (p + 1)
                    | is p closeBracketW -> Ok (p + 1)
                    | otherwise          -> found "',' or ']'" p
      fault -> fault
    keyword w i0 = go w i0
      where go [] i = Ok i
            go (c : cs) i | is i (fromIntegral (fromEnum c)) = go cs (i + 1)
                          | otherwise = found (show w) i
    -- (after the opening quote; the bytes up to the next quote, backslash
    -- or control character taken in one step)
    string !i0
      | i >= n = bad i "unexpected end of input"
      | b == quoteW     = Ok (i + 1)
      | b == backslashW = escape (i + 1)
      | b < 0x20        = bad i ("a control character (code " ++ show (fromIntegral b :: Int)
                                 ++ ") must be escaped in a string")
      | otherwise       = string (i + 1)
      where b = at i
            i = maybe n (i0 +) (B.findIndex (\w -> w == quoteW || w == backslashW || w < 0x20) (B.drop i0 bs))
    -- (after the backslash)
    escape j
      | j >= n = bad j "unexpected end of input"
      | b `elem` [quoteW, backslashW, 47, 98, 102, 110, 114, 116] = string (j + 1)
      | b == 117 = hex4 (j + 1) (4 :: Int)
      | otherwise = Bad j True ("unknown escape \\" ++ [fst (charAt bs j)])
      where b = at j
    hex4 k 0 = string k
    hex4 k r | k < n && isHexW (at k) = hex4 (k + 1) (r - 1)
             | otherwise = found "four hex digits after \\u" k
    number i0 = case digits1 "a digit" i1 of
      Ok i2
        | i2 - i1 > 1 && at i1 == zeroW -> bad i0 "a number may not have a leading zero"
        | otherwise -> case (if is i2 dotW then digits1 "a digit after '.'" (i2 + 1) else Ok i2) of
            Ok i3
              | is i3 lowerEW || is i3 upperEW ->
                  let i4 = i3 + 1
                  in digits1 "a digit in the exponent" (if is i4 plusW || is i4 minusW then i4 + 1 else i4)
              | otherwise -> Ok i3
            fault -> fault
      fault -> fault
      where i1 = if at i0 == minusW then i0 + 1 else i0
    digits1 what i | i < n && isDigitW (at i) = Ok (digitsEnd bs (i + 1))
                   | otherwise = found what i

-- The offset after a run of digits from @i@.
digitsEnd :: B.ByteString -> Int -> Int
digitsEnd = skipping isDigitW

------------------------------------------------------------------------------
-- The second pass: the value made from checked bytes, as it is used

-- The value that begins at offset @i@ of a checked text.
valueAt :: B.ByteString -> Int -> JSON
valueAt bs = value
  where
    n = B.length bs
    at = BU.unsafeIndex bs
    is i w = i < n && at i == w
    value i
      | b == openBraceW   = JObject (members (spaces bs (i + 1)))
      | b == openBracketW = JArray (elements (spaces bs (i + 1)))
      | b == quoteW       = let !s = text (i + 1) (stringEnd bs (i + 1) - 1) in JString s
      | b == 116          = JBool True
      | b == 102          = JBool False
      | b == 110          = JNull
      | otherwise         = JNumber (numberAt bs i)
      where b = at i
    -- (each member and element made when its list's cell is: a member's
    -- name then, its value when it is looked at)
    members i
      | is i closeBraceW = []
      | otherwise =
          let j = stringEnd bs (i + 1)
              !k = text (i + 1) (j - 1)
              v = spaces bs (spaces bs j + 1)
          in (k, value v) : after members closeBraceW (spaces bs (skipValue bs v))
    elements i
      | is i closeBracketW = []
      | otherwise = value i : after elements closeBracketW (spaces bs (skipValue bs i))
    -- (at a comma, the next; else at the closing one)
    after more _ p | is p commaW = more (spaces bs (p + 1))
    after _ _ _ = []
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
-- 'sharedStrings' strings are kept, the first in the text; any other is
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

-- The offset after the string whose opening quote is before @i@.
stringEnd :: B.ByteString -> Int -> Int
stringEnd bs = go
  where
    go !i0 = case B.findIndex (\w -> w == quoteW || w == backslashW) (B.drop i0 bs) of
      Just k | BU.unsafeIndex bs (i0 + k) == quoteW -> i0 + k + 1
             | otherwise                            -> go (i0 + k + 2)
      Nothing -> B.length bs   -- (not in a checked text)

-- The offset after the checked value that begins at @i@.
skipValue :: B.ByteString -> Int -> Int
skipValue bs i
  | b == quoteW = stringEnd bs (i + 1)
  | b == openBraceW || b == openBracketW = nested (i + 1) (1 :: Int)
  | b == 116 || b == 110 = i + 4
  | b == 102 = i + 5
  | otherwise = numberEnd (i + 1)
  where
    n = B.length bs
    at = BU.unsafeIndex bs
    b = at i
    -- (from one quote, bracket or brace to the next)
    nested !j0 !d
      | c == quoteW = nested (stringEnd bs (j + 1)) d
      | c == openBraceW || c == openBracketW = nested (j + 1) (d + 1)
      | d == 1 = j + 1
      | otherwise = nested (j + 1) (d - 1)
      where j = maybe n (j0 +) (B.findIndex (\w -> w == quoteW || w == openBraceW || w == openBracketW
                                                   || w == closeBraceW || w == closeBracketW) (B.drop j0 bs))
            c = at j
    numberEnd !j
      | j < n, c <- at j, isDigitW c || c == dotW || c == lowerEW || c == upperEW || c == plusW || c == minusW =
          numberEnd (j + 1)
      | otherwise = j

-- The characters of a checked string's bytes from @i@ to before @j@ (its
-- quotes excluded), escapes decoded: at most 64 bytes made now, whole; a
-- longer string made as it is used, of a copy of its bytes.
stringText :: B.ByteString -> Int -> Int -> String
stringText bs i j
  | j - i <= 64 = let s = decodeString bs i j in length s `seq` s
  | otherwise   = let !c = B.copy (B.take (j - i) (B.drop i bs)) in decodeString c 0 (j - i)

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
