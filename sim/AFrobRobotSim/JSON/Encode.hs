-- |
-- Module      : AFrobRobotSim.JSON.Encode
-- Description : The JSON value type and its encoder.
--
-- The value type of "AFrobRobotSim.JSON" and its writing as RFC 8259
-- JSON: a value's text as a 'String' or straight into a 'B.Builder', and
-- the pieces of it (strings, numbers, bounded writes of them) for a
-- writer that makes a value's text without a 'JSON' value, as the run
-- log's frames are written. The parser and the readers of values are in
-- "AFrobRobotSim.JSON", which re-exports all of this module: import that.
--
-- = What the encoder writes
--
-- * Output is pure ASCII: every character outside printable ASCII is
--   written as a @\\uXXXX@ escape (a surrogate pair above U+FFFF), so the
--   text means the same whatever encoding a file is read with.
-- * @\<@, @\>@ and @&@ are written as @\\u003c@, @\\u003e@ and @\\u0026@,
--   and U+2028 and U+2029 as escapes too, so an encoded value can be
--   pasted inside an HTML @\<script\>@ element: no string can close it
--   (@\<\/script\>@) or open a comment there.
-- * Surrogate code points (U+D800 to U+DFFF, which are not characters
--   and cannot be encoded in UTF-8) are written as U+FFFD, the
--   replacement character.
-- * Numbers: an integral value of magnitude below 10^15 is written
--   without a fraction (@3@, not @3.0@); a number of magnitude below 10^9
--   that is a whole number of millionths (as the run log rounds its
--   values) in plain decimals, at most six, no trailing zero (@0.05@,
--   @-1.570796@); any other finite number in Haskell's shortest form that
--   reads back the same 'Double' (@1.0e-7@). Each reads back as the very
--   'Double' written. JSON has no NaN or infinity: __a non-finite number
--   is written as @null@__.
-- * No whitespace between tokens; object members in the order given.
module AFrobRobotSim.JSON.Encode
  ( -- * Values
    JSON (..)
    -- * Encoding
  , encodeJSON
  , encodeJSONBuilder
  , encodeString
  , encodeNumber
  , stringBuilder
  , numberBuilder
  , numberPrim
  , shortString
  , isShortPlain
  , shortStringPrim
  ) where

import qualified Data.ByteString.Builder    as B
import qualified Data.ByteString.Builder.Prim as P
import           Data.ByteString.Builder.Prim.Internal (boundedPrim)
import qualified Data.ByteString.Lazy.Char8 as BLC
import           Data.Char                  (ord)
import           Data.Word                  (Word8)
import           Foreign.Ptr                (Ptr, plusPtr)
import           Foreign.Storable           (pokeByteOff)
import           Numeric                    (showHex)

-- | A JSON value. An object keeps its members in order; a duplicate name
-- is kept as it is (the lookups of "AFrobRobotSim.JSON" take the first).
data JSON
  = JNull
  | JBool !Bool
  | JNumber !Double
  | JString String
  | JArray [JSON]
  | JObject [(String, JSON)]
  deriving (Eq, Show)

-- | The JSON text of a value, on one line (see "AFrobRobotSim.JSON.Encode"
-- for escapes and numbers): the characters of 'encodeJSONBuilder'.
encodeJSON :: JSON -> String
encodeJSON = BLC.unpack . B.toLazyByteString . encodeJSONBuilder

-- | The JSON text of a value, on one line, as the bytes of a
-- 'B.Builder' (ASCII: see "AFrobRobotSim.JSON.Encode"). Writing a log line
-- this way costs a fraction of building it as a 'String' and writing
-- that: a run log of 200 robots wrote 39 MB through 'String's in 3 s.
encodeJSONBuilder :: JSON -> B.Builder
encodeJSONBuilder = go
  where
    go JNull         = B.string7 "null"
    go (JBool b)     = B.string7 (if b then "true" else "false")
    go (JNumber x)   = numberBuilder x
    go (JString str) = stringBuilder str
    go (JArray xs)   = B.char7 '[' <> commaSep (map go xs) <> B.char7 ']'
    go (JObject kvs) = B.char7 '{' <> commaSep [ stringBuilder k <> B.char7 ':' <> go x | (k, x) <- kvs ]
                       <> B.char7 '}'
    commaSep []       = mempty
    commaSep (b : bs) = b <> foldr (\c acc -> B.char7 ',' <> c <> acc) mempty bs

-- | A string's JSON text as a 'B.Builder': the characters of
-- 'encodeString' (a string that needs no escape, the usual case: names,
-- keys, is copied as it is). For a writer that makes a value's text
-- directly, without a 'JSON' value.
stringBuilder :: String -> B.Builder
stringBuilder str
  | isShortPlain str = P.primBounded shortStringPrim str
  | all plain str    = B.char7 '"' <> B.string7 str <> B.char7 '"'
  | otherwise        = B.string7 (encodeString str)

-- | Whether a string is short and plain: at most 'shortString'
-- characters, none of which needs an escape (in JSON or in a page). Such a
-- string's JSON text is its characters in quotes, which
-- 'shortStringPrim' writes in one bounded write (the usual string, a
-- name or a type, is one).
isShortPlain :: String -> Bool
isShortPlain = short 0
  where
    short :: Int -> String -> Bool
    short n (c : cs) = n < shortString && plain c && short (n + 1) cs
    short _ []       = True

-- Whether a character goes into a JSON string as it is.
plain :: Char -> Bool
plain c = c >= ' ' && c < '\DEL' && c /= '"' && c /= '\\' && c /= '<' && c /= '>' && c /= '&'

-- | The most characters of a string 'stringBuilder' writes in one
-- bounded write: 64.
shortString :: Int
shortString = 64

-- | The JSON text of a short plain string ('isShortPlain'): its
-- characters in quotes, at most 'shortString' + 2 bytes. Only for such a
-- string (a longer one would overrun the bound).
shortStringPrim :: P.BoundedPrim String
shortStringPrim = boundedPrim (shortString + 2) $ \str op -> do
  byte op 0 34
  p <- chars (op `plusPtr` 1) str
  byte p 0 34
  pure (p `plusPtr` 1)

-- | A number's JSON text: @null@ for NaN and the infinities; integral
-- values of magnitude below 10^15 without a fraction; whole numbers of
-- millionths below 10^9 in plain decimals (@0.05@); otherwise Haskell's
-- shortest exact form (@1.0e-7@), which is valid JSON.
encodeNumber :: Double -> String
encodeNumber = BLC.unpack . B.toLazyByteString . numberBuilder

-- | A number's JSON text as a 'B.Builder': the characters of
-- 'encodeNumber'. Written straight into the builder's buffer, with
-- comparisons and truncation rather than 'isNaN', 'isInfinite' and
-- 'round' (foreign calls), and no 'String' but for the last case: a run
-- log writes some twenty numbers for each robot at each frame.
numberBuilder :: Double -> B.Builder
numberBuilder = P.primBounded numberPrim

-- | 'numberBuilder' as a bounded primitive (at most 32 bytes), for a
-- writer that puts several numbers and constants in one bounded write
-- (a log frame's robot, say: a builder piece for each costs more than the
-- digits). It writes 25 bytes at most: @null@; a sign and 15 digits; a
-- sign, nine digits, the point and six places; or 'show''s longest, 24
-- characters, as in @-2.2250738585072014e-308@.
numberPrim :: P.BoundedPrim Double
numberPrim = boundedPrim 32 writeNumber

writeNumber :: Double -> Ptr Word8 -> IO (Ptr Word8)
writeNumber x op
  | not (abs x <= 1.7976931348623157e308) = chars op "null"      -- NaN, the infinities
  | abs x < 1e15 && x == fromIntegral t = do
      op1 <- sign op (t < 0)
      let a = abs t
          n = digitsOf a
      decimal op1 n a
      pure (op1 `plusPtr` n)
  | abs x < 1e9 && x == fromIntegral m / 1e6 = do
      -- a whole number of millionths, not a whole number: the digits of
      -- @m / 10^6@ exactly, without trailing zeros. (The decimal is
      -- exactly @m / 10^6@, and @x@ is the 'Double' nearest to it, since
      -- IEEE division of the exact @m@ by @10^6@ rounds to nearest: so it
      -- reads back as @x@.)
      op1 <- sign op (m < 0)
      let a      = abs m
          whole  = a `quot` 1000000
          frac   = a `rem` 1000000
          -- the six places without their trailing zeros (at least one
          -- place is kept): how many are left, and the number they spell
          zeros  = trailingZeros frac 0
          places = 6 - zeros
          kept   = frac `quot` tenTo zeros
          n      = digitsOf whole
      decimal op1 n whole
      byte (op1 `plusPtr` n) 0 46                                     -- '.'
      decimal (op1 `plusPtr` (n + 1)) places kept
      pure (op1 `plusPtr` (n + 1 + places))
  | otherwise = chars op (show x)
  where
    -- (evaluated only below the bounds above, where they are exact; a
    -- whole number is its truncation, and a whole number of millionths
    -- is within far less than half a millionth of @x * 10^6@, so any
    -- rounding to the nearest whole number finds it)
    t = truncate x :: Int
    m = nearest (x * 1e6)
    nearest y = let k = truncate y :: Int
                    d = y - fromIntegral k
                in if d >= 0.5 then k + 1 else if d <= -0.5 then k - 1 else k
    -- (each a loop or a test on plain numbers: no closure or pair is
    -- allocated for a number, of which a log writes some twenty a robot)
    trailingZeros :: Int -> Int -> Int
    trailingZeros f z | z < 5 && f `rem` 10 == 0 = trailingZeros (f `quot` 10) (z + 1)
                      | otherwise                = z
    tenTo :: Int -> Int
    tenTo z = case z of
      0 -> 1
      1 -> 10
      2 -> 100
      3 -> 1000
      4 -> 10000
      _ -> 100000
    digitsOf :: Int -> Int
    digitsOf k | k < 10    = 1
               | otherwise = 1 + digitsOf (k `quot` 10)
    -- a minus sign if asked, and the pointer after it
    sign :: Ptr Word8 -> Bool -> IO (Ptr Word8)
    sign p neg | neg       = p `plusPtr` 1 <$ byte p 0 45
               | otherwise = pure p
    -- the @n@ last decimal digits of @k@ (zeros first if it has fewer), at @p@
    decimal :: Ptr Word8 -> Int -> Int -> IO ()
    decimal p n k
      | n <= 0    = pure ()
      | otherwise = do
          let (q, r) = k `quotRem` 10
          byte p (n - 1) (fromIntegral (48 + r))
          decimal p (n - 1) q

-- A byte at an offset from a pointer.
byte :: Ptr Word8 -> Int -> Word8 -> IO ()
byte = pokeByteOff

-- ASCII characters at a pointer, then the pointer after them.
chars :: Ptr Word8 -> String -> IO (Ptr Word8)
chars p []       = pure p
chars p (c : cs) = byte p 0 (fromIntegral (fromEnum c)) >> chars (p `plusPtr` 1) cs

-- | A string's JSON text, quotes included (see
-- "AFrobRobotSim.JSON.Encode").
encodeString :: String -> String
encodeString s = '"' : foldr esc "\"" s
  where
    esc c rest = case c of
      '"'  -> '\\' : '"' : rest
      '\\' -> '\\' : '\\' : rest
      '\n' -> '\\' : 'n' : rest
      '\r' -> '\\' : 'r' : rest
      '\t' -> '\\' : 't' : rest
      '<'  -> u 0x3c rest
      '>'  -> u 0x3e rest
      '&'  -> u 0x26 rest
      _ | n >= 0xD800 && n <= 0xDFFF -> u 0xFFFD rest
        | n < 0x20 || n >= 0x7f && n <= 0xFFFF -> u n rest
        | n > 0xFFFF -> let m = n - 0x10000
                        in u (0xD800 + m `div` 0x400) (u (0xDC00 + m `mod` 0x400) rest)
        | otherwise  -> c : rest
      where n = ord c
    u :: Int -> String -> String
    u n rest = '\\' : 'u' : pad (showHex n "") ++ rest
    pad h = replicate (4 - length h) '0' ++ h
