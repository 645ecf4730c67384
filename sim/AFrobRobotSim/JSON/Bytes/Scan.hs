{-# LANGUAGE BangPatterns #-}
{-# LANGUAGE MultiWayIf   #-}
-- |
-- Module      : AFrobRobotSim.JSON.Bytes.Scan
-- Description : JSON's bytes, and where the parts of a checked text end:
--               read over, or looked up in an index of its arrays and
--               objects.
--
-- What both passes of "AFrobRobotSim.JSON.Bytes" read the bytes with
-- (their names, whitespace, digits), and what the second pass, which
-- makes a checked text's value as it is used, finds the parts' ends
-- with. An array or object makes the cell of its next part only when
-- the one before it ends, and a part is not made to find its end: it
-- is read over. Read over at every level, a part nested @d@ deep would
-- be read @d@ times when the value is used whole (a review measured
-- 6.1 s for a text of 4 MB nested 511 deep, against 0.9 s for the
-- parser of strings). So only the top-level value's parts are read over
-- (once each: the top level is read once); a part of the top level that
-- is looked into makes, the first time one of its own parts' ends is
-- asked for, an 'Index' of the arrays and objects in it (two passes over
-- its bytes), and every end below it is looked up there: a value used
-- whole costs time in proportion to its bytes. A part of the top level
-- that is never looked into costs the one reading over it, and no index:
-- a log's line refused for a member it lacks indexes nothing.
--
-- 'spaces' and 'digitsEnd' take any text (the first pass's too) and stop
-- at its end. Every other function on offsets takes a checked text (one
-- that 'AFrobRobotSim.JSON.Bytes.parseJSONBytes' accepts) and the offset
-- of one of its values, and does not check it.
module AFrobRobotSim.JSON.Bytes.Scan
  ( -- * JSON's bytes
    quoteW, backslashW, openBraceW, closeBraceW, openBracketW, closeBracketW, commaW, colonW
  , minusW, plusW, dotW, zeroW, lowerEW, upperEW
  , isDigitW
  , isHexW
    -- * Reading over bytes
  , spaces
  , digitsEnd
  , stringEnd
    -- * Where the parts of arrays and objects end
  , Cursor (..)
  , Index
  , containerIndex
  , indexEnd
  , indexAfter
  , inside
  , Step (..)
  , partEnd
  ) where

import           Control.Monad.ST        (stToIO)
import           Data.Bits               ((.&.))
import qualified Data.ByteString         as B
import qualified Data.ByteString.Unsafe  as BU
import           Data.Word               (Word8)
import           Foreign.Ptr             (Ptr, castPtr)
import           Foreign.Storable        (peekByteOff)
import           System.IO.Unsafe        (unsafeDupablePerformIO)

import           AFrobRobotSim.FlatArray (IntArr, freezeI, indexI, newIntArrUnset, readI, writeI)

------------------------------------------------------------------------------
-- JSON's bytes

-- | The bytes JSON's grammar names: @\"@, @\\@, @{@, @}@, @[@, @]@, @,@,
-- @:@, @-@, @+@, @.@, @0@, @e@ and @E@.
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

-- | Whether a byte is an ASCII digit, @0@ to @9@.
isDigitW :: Word8 -> Bool
isDigitW w = w >= 48 && w <= 57

-- | Whether a byte is a hexadecimal digit (@0@ to @9@, @a@ to @f@, @A@ to
-- @F@).
isHexW :: Word8 -> Bool
isHexW w = isDigitW w || (w >= 97 && w <= 102) || (w >= 65 && w <= 70)

------------------------------------------------------------------------------
-- Reading over bytes

-- | The offset of the first byte from an offset on that is not JSON
-- whitespace (space, tab, carriage return, line feed), or the text's
-- length.
spaces :: B.ByteString -> Int -> Int
spaces bs i = skipping (\w -> w == 32 || w == 9 || w == 13 || w == 10) bs i

-- | The offset after the run of digits from an offset on (that offset
-- when there are none).
digitsEnd :: B.ByteString -> Int -> Int
digitsEnd bs i = skipping isDigitW bs i

-- The offset of the first byte from @i@ on that the test does not take
-- (or the text's end), a byte at a time: for the short runs between
-- tokens and of digits.
skipping :: (Word8 -> Bool) -> B.ByteString -> Int -> Int
skipping ok bs = go
  where
    n = B.length bs
    go !i | i < n, ok (BU.unsafeIndex bs i) = go (i + 1)
          | otherwise = i
{-# INLINE skipping #-}

-- | The offset after the checked string whose opening quote is just
-- before the given offset: after its closing quote, escapes read over.
stringEnd :: B.ByteString -> Int -> Int
stringEnd bs i = reading bs (\p n -> stringEndP p n i)

-- The offset after the checked value that begins at an offset, found
-- by reading over it: an array or object to its matching bracket or
-- brace (every part in it read over), a string to its closing quote, a
-- keyword or number to its last byte.
skipValue :: B.ByteString -> Int -> Int
skipValue bs i = reading bs $ \p n -> do
  b <- peekW p i
  if | b == quoteW            -> stringEndP p n (i + 1)
     | opens b                -> fst <$> containerP p n i
     | b == 116 || b == 110   -> pure (i + 4)
     | b == 102               -> pure (i + 5)
     | otherwise              -> numberEnd p n (i + 1)
  where
    numberEnd p n !j
      | j >= n = pure j
      | otherwise = peekW p j >>= \c ->
          if isDigitW c || c == dotW || c == lowerEW || c == upperEW || c == plusW || c == minusW
            then numberEnd p n (j + 1) else pure j

------------------------------------------------------------------------------
-- Reading through a pointer

-- The bytes read through a pointer to them (and their length), valid
-- while the reading runs. The passes that read over many bytes read so:
-- under GHC 9.0's bytestring, 'BU.unsafeIndex' allocates 16 bytes for
-- each byte it reads (1 GB, and twice the time, for reading over 64
-- MiB), and a 'B.findIndex' for each mark (a quote, a bracket) some 48,
-- and a log's line has many marks.
reading :: B.ByteString -> (Ptr Word8 -> Int -> IO a) -> a
reading bs k = unsafeDupablePerformIO (BU.unsafeUseAsCStringLen bs (\(p, n) -> k (castPtr p) n))
{-# INLINE reading #-}

peekW :: Ptr Word8 -> Int -> IO Word8
peekW = peekByteOff
{-# INLINE peekW #-}

-- 'stringEnd' through a pointer to the @n@ bytes.
stringEndP :: Ptr Word8 -> Int -> Int -> IO Int
stringEndP p n = go
  where
    go !j | j >= n    = pure n   -- (not in a checked text)
          | otherwise = peekW p j >>= \w -> if | w == quoteW     -> pure (j + 1)
                                               | w == backslashW -> go (j + 2)
                                               | otherwise       -> go (j + 1)

-- The offset of the first quote, bracket or brace from @j@ on (@n@ if
-- none).
markP :: Ptr Word8 -> Int -> Int -> IO Int
markP p n = go
  where
    go !j | j >= n    = pure n
          | otherwise = peekW p j >>= \w -> if isMark w then pure j else go (j + 1)

-- Whether a byte is a quote, a bracket or a brace (@[@ and @{@, @]@ and
-- @}@, differ in the bit 0x20 alone).
isMark :: Word8 -> Bool
isMark w = w == quoteW || u == openBracketW || u == closeBracketW
  where u = w .&. 0xDF
{-# INLINE isMark #-}

-- The offset after the array or object that opens at @i@, and the number
-- of arrays and objects in it, itself included.
containerP :: Ptr Word8 -> Int -> Int -> IO (Int, Int)
containerP p n = go (0 :: Int) (0 :: Int)
  where
    -- (@d@ open at @j0@, @count@ opened before it)
    go !d !count !j0 = do
      j <- markP p n j0
      if j >= n then pure (n, count) else do   -- (not in a checked text)
        w <- peekW p j
        if | w == quoteW -> stringEndP p n (j + 1) >>= go d count
           | opens w     -> go (d + 1) (count + 1) (j + 1)
           | d == 1      -> pure (j + 1, count)
           | otherwise   -> go (d - 1) count (j + 1)

-- Whether a byte opens an array or object.
opens :: Word8 -> Bool
opens w = w == openBracketW || w == openBraceW
{-# INLINE opens #-}

------------------------------------------------------------------------------
-- Where the parts of arrays and objects end

-- | How the second pass finds where the parts of an array or object end,
-- carried from one part to the next ('partEnd' gives the next one's).
data Cursor
  = ReadOver
    -- ^ each part read over ('skipValue'): the top-level value's parts
  | At Index !Int
    -- ^ an array's or object's end looked up in the index (made when
    -- first looked in) of the top-level part it is in: the number, in
    -- that index, of the first array or object at or after the next part

-- | The ends of an array or object of a checked text and of every array
-- and object in it, numbered from 0 (itself) in the order they open;
-- for each, the offset after it and the number of the first one after
-- it (after those inside it). Two 'Int's each.
newtype Index = Index IntArr

-- | The 'Index' of the array or object that opens at an offset of a
-- checked text, made in two passes over its bytes (one counts, one
-- fills).
containerIndex :: B.ByteString -> Int -> Index
containerIndex bs i0 = reading bs $ \p n -> do
  (_, count) <- containerP p n i0
  a <- stToIO (newIntArrUnset (2 * count))
  let -- (@top@: the number of the innermost one open, -1 before the
      -- first; @next@: the number of the next to open. An open one's
      -- second slot holds the one around it until it closes)
      fill !j0 !top !next = do
        j <- markP p n j0
        if j >= n then pure () else do   -- (not in a checked text)
          w <- peekW p j
          if | w == quoteW -> stringEndP p n (j + 1) >>= \j' -> fill j' top next
             | opens w     -> stToIO (writeI a (2 * next + 1) top) >> fill (j + 1) next (next + 1)
             | otherwise   -> do
                 around <- stToIO (readI a (2 * top + 1))
                 stToIO (writeI a (2 * top) (j + 1) >> writeI a (2 * top + 1) next)
                 if around >= 0 then fill (j + 1) around next else pure ()
  fill i0 (-1 :: Int) (0 :: Int)
  Index <$> stToIO (freezeI a)

-- | The offset after the array or object of the given number.
indexEnd :: Index -> Int -> Int
indexEnd (Index a) k = indexI a (2 * k)

-- | The number of the first array or object after the one of the given
-- number (after every one inside it); the count of them in the index
-- after the last.
indexAfter :: Index -> Int -> Int
indexAfter (Index a) k = indexI a (2 * k + 1)

-- | The 'Cursor' of the parts of the array or object that opens at an
-- offset, given the 'Cursor' of the parts it is among: a part of the
-- top level ('ReadOver') gets an index of its own, made when first
-- looked in; a part of an indexed one looks in the same index.
inside :: B.ByteString -> Cursor -> Int -> Cursor
inside bs ReadOver i = At (containerIndex bs i) 1
inside _ (At ix k) _ = At ix (k + 1)

-- | Where a part ends ('partEnd').
data Step = Step
  { stepEnd    :: !Int     -- ^ the offset after the part
  , stepCursor :: !Cursor  -- ^ the cursor of the parts after it
  , stepRead   :: !Int
    -- ^ the bytes read to find the end: the part's own when it is read
    -- over, none when its end is looked up
  }

-- | Where the part that begins at an offset ends, its 'Cursor' the one
-- of the parts it is among: an array or object with an index looks its
-- end up there; any other part is read over.
partEnd :: B.ByteString -> Cursor -> Int -> Step
partEnd bs c i = case c of
  At ix k | opens (BU.unsafeIndex bs i) -> Step (indexEnd ix k) (At ix (indexAfter ix k)) 0
  _ -> let e = skipValue bs i in Step e c (e - i)
