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
-- reads the bytes themselves, as UTF-8, in two passes: the first (this
-- module's) checks the whole text and finds its first fault (the very
-- message, at the very line and column, that
-- 'AFrobRobotSim.JSON.parseJSON' gives for the text the bytes are), and
-- makes nothing; the second ("AFrobRobotSim.JSON.Bytes.Build") makes the
-- value from the checked bytes only as it is used, each part when it is
-- first looked at, in time in proportion to the bytes it reads however
-- deeply they nest ("AFrobRobotSim.JSON.Bytes.Scan" says how a part's
-- end is found). A line refused for a member it lacks has cost its
-- bytes; one used whole costs its value, which its user makes anyway.
--
-- The pieces both parsers share (the depth limit, how a number's digits
-- are rounded, how an error says where it is) are exported here too (where bytes stop being UTF-8 is
-- "AFrobRobotSim.UTF8"'s);
-- "AFrobRobotSim.JSON" re-exports what of this module is for its users:
-- import that.
module AFrobRobotSim.JSON.Bytes
  ( -- * Parsing bytes
    parseJSONBytes
  , cutShortBytes
  , maxDepth
    -- * Parsing bytes found to be UTF-8
  , parseJSONUtf8
  , cutShortUtf8
    -- * Shared with the parser of strings
  , roundDigits
  , significantDigits
  , lineColumn
  ) where

import qualified Data.ByteString                as B
import qualified Data.ByteString.Unsafe         as BU
import           Numeric                        (showHex)

import           AFrobRobotSim.JSON.Bytes.Build (roundDigits, significantDigits, valueAt)
import           AFrobRobotSim.JSON.Bytes.Scan
import           AFrobRobotSim.JSON.Encode      (JSON (..))
import           AFrobRobotSim.UTF8             (Utf8, charAt, checkUtf8, lineColumnAt, utf8Bytes)

-- | How deeply arrays and objects may nest in a text 'parseJSONBytes' and
-- 'AFrobRobotSim.JSON.parseJSON' accept: 512 (deeper input is rejected,
-- not a stack to exhaust).
maxDepth :: Int
maxDepth = 512

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
-- Using a value whole costs time in proportion to its bytes, however
-- deeply it nests: each part's end is found once, a part of the top
-- level's by reading over it, a part below by looking it up in an index
-- of the arrays and objects of the top-level part it is in (two 'Int's
-- each, made when that part is first looked into). A part of the top
-- level that is never looked into is read over once and indexes nothing.
-- The index is held while the part is in use: 16 bytes an array or
-- object, at most 8 times the part's bytes (an array is at least the 2
-- bytes of @[]@); a reviewer measured 604 MB for one 64 MiB part of
-- arrays nested 510 deep side by side, its last element read.
parseJSONBytes :: B.ByteString -> Either String JSON
parseJSONBytes bs = case checkUtf8 bs of
  Left (l, c, b) -> Left (lineColumn l c ("invalid UTF-8 (byte 0x" ++ (if b < 16 then "0" else "")
                                          ++ showHex b ")"))
  Right u -> parseJSONUtf8 u

-- | 'parseJSONBytes' of bytes already found to be UTF-8: the same value
-- or error, without checking the bytes' UTF-8 again (a reader that has
-- checked a line to report its faults its own way hands the line on).
parseJSONUtf8 :: Utf8 -> Either String JSON
parseJSONUtf8 u = case checkValue bs 0 start of
  Bad i back msg -> Left (located bs i back msg)
  Ok j
    | k < B.length bs -> Left (located bs k False ("expected the end of the text, found " ++ describeAt bs k))
    | otherwise       -> Right (valueAt bs start)
    where k = spaces bs j
  where
    bs = utf8Bytes u
    start = spaces bs 0

-- | 'AFrobRobotSim.JSON.cutShort' of the text the bytes are, as UTF-8:
-- whether it is not JSON only because it ends too soon. Bytes that are
-- not UTF-8 are not (they are not JSON for another reason). Nothing is
-- made: a long line is checked in its own bytes.
cutShortBytes :: B.ByteString -> Bool
cutShortBytes = either (const False) cutShortUtf8 . checkUtf8

-- | 'cutShortBytes' of bytes already found to be UTF-8, without checking
-- them again.
cutShortUtf8 :: Utf8 -> Bool
cutShortUtf8 u = case checkValue bs 0 (spaces bs 0) of
  Bad i back _ -> not back && i == B.length bs
  Ok _         -> False
  where
    bs = utf8Bytes u

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

-- | @lineColumn l c msg@: an error's message, @msg@, said at line @l@
-- and column @c@ (@line L, column C: msg@), as both parsers say it.
lineColumn :: Int -> Int -> String -> String
lineColumn l c msg = "line " ++ show l ++ ", column " ++ show c ++ ": " ++ msg

-- What is at an offset, for messages, as the parser of strings says it:
-- the character there ('show'n), or @end of input@.
describeAt :: B.ByteString -> Int -> String
describeAt bs i
  | i >= B.length bs = "end of input"
  | otherwise        = show (fst (charAt bs i))

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
