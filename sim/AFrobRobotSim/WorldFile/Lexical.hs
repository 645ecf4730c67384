{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.WorldFile.Lexical
-- Description : The lexical layer of world files: UTF-8 with error
--               positions, tokens, and number and id literals.
--
-- What "AFrobRobotSim.WorldFile" needs below its grammar, each piece linear
-- in its input: the text of UTF-8 bytes, or the position of the first
-- invalid byte; the tokens of a line with their columns; the
-- literals (decimal numbers, correctly rounded and checked to be finite,
-- and robot ids), each rejecting a token with what was expected instead;
-- and a file's bytes read up to a limit, and the message when it cannot
-- be read ('quote', for messages, is "AFrobRobotSim.Console"'s). See
-- "AFrobRobotSim.WorldFile" for the format.
module AFrobRobotSim.WorldFile.Lexical
  ( -- * UTF-8
    utf8Text
  , utf8TextFrom
  , utf8BytesFrom
    -- * Tokens
  , Tok (..)
  , tokenize
  , tokText
  , tokEnd
    -- * Literals
  , Rejection (..)
  , robotId
  , readNumber
  , decimalLit
  , integerLit
    -- * Messages
  , quote
  , cannotRead
    -- * Files
  , canonicalPath
  , lower
  ) where

import           Control.Exception      (IOException, try)
import           Data.Bits              ((.&.), (.|.), shiftL)
import qualified Data.ByteString        as B
import qualified Data.ByteString.Unsafe as BU
import           Data.Char              (chr, isDigit, isSpace, toLower)
import           GHC.IO.Exception       (IOException (ioe_description))
import           Numeric                (showHex)
import           System.Directory       (canonicalizePath)
import           System.FilePath        (normalise)
import           System.IO.Error        (ioeGetErrorType)

import           AFrobRobotSim.Console  (displayPath, quote)
import           AFrobRobotSim.UTF8     (Utf8, checkUtf8, utf8Bytes)

------------------------------------------------------------------------------
-- UTF-8

-- | The text of a file's bytes, or, when they are not UTF-8, the message
-- every reader of text files gives:
-- @NAME:LINE:COLUMN: invalid UTF-8 (byte 0xNN)@, for the first bad byte
-- (its column counted in characters). The name is used as given (a
-- caller escapes it for display).
--
-- >>> utf8Text "w.world" (B.pack [0x61, 0x0a, 0x62, 0xff])
-- Left "w.world:2:2: invalid UTF-8 (byte 0xff)"
utf8Text :: String -> B.ByteString -> Either String String
utf8Text name = utf8TextFrom name 1

-- | 'utf8Text' of bytes that begin a file's line @n@ (from 1), such as
-- one line of it: the message counts the lines from there.
--
-- >>> utf8TextFrom "run.jsonl" 7 (B.pack [0x61, 0xff])
-- Left "run.jsonl:7:2: invalid UTF-8 (byte 0xff)"
utf8TextFrom :: String -> Int -> B.ByteString -> Either String String
utf8TextFrom name n bytes = decodeUtf8 . utf8Bytes <$> utf8BytesFrom name n bytes

-- | 'utf8TextFrom' that keeps the bytes: them as 'Utf8' (checked, for a
-- reader that parses bytes, such as a run log's, so that they are
-- checked once), or the same message.
--
-- >>> utf8BytesFrom "run.jsonl" 7 (B.pack [0x61, 0xff])
-- Left "run.jsonl:7:2: invalid UTF-8 (byte 0xff)"
utf8BytesFrom :: String -> Int -> B.ByteString -> Either String Utf8
utf8BytesFrom name n bytes = case checkUtf8 bytes of
  Left (l, c, b) -> Left (name ++ ":" ++ show (l + n - 1) ++ ":" ++ show c ++ ": invalid UTF-8 (byte 0x"
                          ++ (if b < 16 then "0" else "") ++ showHex b ")")
  Right u        -> Right u

-- Decode valid UTF-8 (as 'utf8Fault' accepts it), lazily.
decodeUtf8 :: B.ByteString -> String
decodeUtf8 bs = go 0
  where
    n = B.length bs
    at :: Int -> Int
    at i = fromIntegral (BU.unsafeIndex bs i)
    tl i = at i .&. 0x3F
    go i
      | i >= n    = []
      | b < 0x80  = chr b : go (i + 1)
      | b < 0xE0  = chr (((b .&. 0x1F) `shiftL` 6) .|. tl (i + 1)) : go (i + 2)
      | b < 0xF0  = chr (((b .&. 0x0F) `shiftL` 12) .|. (tl (i + 1) `shiftL` 6) .|. tl (i + 2))
                    : go (i + 3)
      | otherwise = chr (((b .&. 0x07) `shiftL` 18) .|. (tl (i + 1) `shiftL` 12)
                         .|. (tl (i + 2) `shiftL` 6) .|. tl (i + 3)) : go (i + 4)
      where b = at i

------------------------------------------------------------------------------
-- Tokens

-- | A token: the column (1-based) of its first character and its text.
data Tok = Tok !Int String

-- | The tokens of a line, comment removed.
tokenize :: String -> [Tok]
tokenize = go 1 . takeWhile (/= '#')
  where
    go _ [] = []
    go c s@(ch : rest)
      | isSpace ch = go (c + 1) rest
      | otherwise  = let (t, rest') = break isSpace s
                     in Tok c t : go (c + length t) rest'

-- | The text of a token.
tokText :: Tok -> String
tokText (Tok _ t) = t

-- | The column just after a token.
tokEnd :: Tok -> Int
tokEnd (Tok c t) = c + length t

-- | Why a token was rejected: what was expected instead, and a note to
-- append to the message (possibly empty).
data Rejection = Rejection String String


-- | A file that could not be read, as a message naming it and why, but
-- not the Haskell function that failed:
-- @FILE: cannot read it: does not exist (No such file or directory)@
-- rather than @FILE: openBinaryFile: does not exist (No such file or directory)@.
cannotRead :: FilePath -> IOException -> String
cannotRead path e = displayPath path ++ ": cannot read it: " ++ show (ioeGetErrorType e) ++ reason
  where
    reason = case ioe_description e of
      "" -> ""
      d  -> " (" ++ d ++ ")"

-- | A path as the file system resolves it ('canonicalizePath': links
-- followed, @.@ and @..@ gone), or, when it cannot be, the path normalised:
-- for telling whether two names are one file.
canonicalPath :: FilePath -> IO FilePath
canonicalPath f = either (\e -> const (normalise f) (e :: IOException)) id <$> try (canonicalizePath f)

-- | A keyword's text in lower case, for comparing case-insensitively.
lower :: String -> String
lower = map toLower

------------------------------------------------------------------------------
-- Literals

-- | A robot id: an optionally signed decimal integer that fits in an 'Int'.
robotId :: String -> Either Rejection Int
robotId s = case integerLit s of
  Just n
    | n >= toInteger (minBound :: Int) && n <= toInteger (maxBound :: Int)
                -> Right (fromInteger n)
    | otherwise -> Left (Rejection "a robot id (an integer)" " (out of range)")
  Nothing       -> Left (Rejection "a robot id (an integer)" "")

-- | An optionally signed decimal integer.
integerLit :: String -> Maybe Integer
integerLit s = case signed s of
  (neg, ds) | not (null ds), all isDigit ds -> Just (applySign neg (digitsValue ds))
  _                                         -> Nothing

-- | Split off an optional sign: whether it was a minus, and the rest.
signed :: String -> (Bool, String)
signed ('-' : r) = (True, r)
signed ('+' : r) = (False, r)
signed r         = (False, r)

-- Negate if the sign was a minus.
applySign :: Num a => Bool -> a -> a
applySign neg x = if neg then negate x else x

-- The value of a string of decimal digits.
digitsValue :: String -> Integer
digitsValue = foldl (\acc d -> acc * 10 + toInteger (fromEnum d - fromEnum '0')) 0

-- | A finite number literal (see "AFrobRobotSim.WorldFile"), converted to
-- the nearest 'Double'.
readNumber :: String -> Either Rejection Double
readNumber s
  | lower (snd (signed s)) `elem` ["nan", "inf", "infinity"] =
      Left (Rejection "a finite number" " (NaN and infinities are not allowed)")
  | otherwise = case decimalLit s of
      Nothing -> Left (Rejection "a number" "")
      Just d
        | isInfinite d -> Left (Rejection "a finite number" " (too large for a Double)")
        | otherwise    -> Right d

-- | @[+-]DIGITS[.DIGITS][(e|E)[+-]DIGITS]@, correctly rounded; infinite if
-- too large.
decimalLit :: String -> Maybe Double
decimalLit s0 = do
  let (neg, s1) = signed s0
      (intPart, s2) = span isDigit s1
  nonEmpty intPart
  (fracPart, s3) <- case s2 of
    '.' : r -> let (f, r') = span isDigit r in nonEmpty f >> Just (f, r')
    _       -> Just ("", s2)
  ex <- case s3 of
    []      -> Just 0
    c : r | c == 'e' || c == 'E' -> integerLit r
    _       -> Nothing
  let mant   = digitsValue (intPart ++ fracPart)
      -- value = mant * 10 ^ p
      p      = ex - toInteger (length fracPart)
      nDigits = toInteger (length (show mant))
  pure . applySign neg $
    if mant == 0 || nDigits + p <= -325
      then 0                            -- below half the smallest denormal
      else if nDigits - 1 + p > 309
        then 1 / 0                      -- at least 1e310: overflows
        else if p >= 0
          then fromRational (fromInteger (mant * 10 ^ p))
          else fromRational (fromInteger mant / fromInteger (10 ^ negate p))
  where
    nonEmpty xs = if null xs then Nothing else Just ()
