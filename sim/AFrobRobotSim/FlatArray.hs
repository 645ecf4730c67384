{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE MagicHash     #-}
{-# LANGUAGE UnboxedTuples #-}
-- |
-- Module      : AFrobRobotSim.FlatArray
-- Description : Flat unboxed arrays of numbers, just what the spatial
--               indexes need.
--
-- The grids of "AFrobRobotSim.SpatialIndex", "AFrobRobotSim.RayGrid" and
-- "AFrobRobotSim.Clearance" keep their cells and numbers in flat unboxed
-- arrays (byte arrays, read without bounds checks or boxing), and the
-- physics moves robots' centres in mutable ones; a module of their own so
-- that all of them use one representation. No bounds checks: callers index
-- within the sizes they allocated. (And 'finite', the test for finite
-- numbers that the indexes, their users and the checks of a run's
-- settings and of a log share: this module imports none of the
-- simulator's, so any of them can import it.)
module AFrobRobotSim.FlatArray
  ( -- * Immutable
    IntArr
  , DblArr
  , W8Arr
  , indexI
  , indexD
  , indexW8
    -- * Mutable
  , MIntArr
  , MDblArr
  , MW8Arr
  , newIntArr
  , newIntArrUnset
  , newLineIntArr
  , newDblArr
  , newW8Arr
  , readI
  , writeI
  , readD
  , writeD
  , writeW8
  , freezeI
  , freezeD
  , freezeW8
  , bucketLists
  , bucketListsUpTo
    -- * Numbers
  , finite
  ) where

import           GHC.Exts
import           GHC.ST   (ST (..))
import           GHC.Word (Word8 (..))

-- | An immutable array of 'Int's.
data IntArr = IntArr ByteArray#
-- | An immutable array of 'Double's.
data DblArr = DblArr ByteArray#
-- | An immutable array of bytes ('Word8's): an eighth of the room of
-- 'Int's or 'Double's, for a large table read at random (a cache line
-- holds 64 of its entries).
data W8Arr = W8Arr ByteArray#
-- | A mutable array of 'Int's.
data MIntArr s = MIntArr (MutableByteArray# s)
-- | A mutable array of 'Double's.
data MDblArr s = MDblArr (MutableByteArray# s)
-- | A mutable array of bytes.
data MW8Arr s = MW8Arr (MutableByteArray# s)

-- | A new array of @n@ 'Int's, all @v@.
newIntArr :: Int -> Int -> ST s (MIntArr s)
newIntArr (I# n) (I# v) = ST $ \s -> case newByteArray# (n *# 8#) s of
  (# s1, a #) -> case fillInts a n v s1 of s2 -> (# s2, MIntArr a #)

-- | A new array of @n@ 'Int's whose contents are unspecified, for a
-- caller that writes every entry before it reads it (no pass to set them).
newIntArrUnset :: Int -> ST s (MIntArr s)
newIntArrUnset (I# n) = ST $ \s -> case newByteArray# (n *# 8#) s of
  (# s1, a #) -> (# s1, MIntArr a #)

-- | 'newIntArr', its first element at the start of a 64-byte cache line
-- (pinned: it never moves), so that each run of 8 elements from a multiple
-- of 8 is one cache line.
newLineIntArr :: Int -> Int -> ST s (MIntArr s)
newLineIntArr (I# n) (I# v) = ST $ \s -> case newAlignedPinnedByteArray# (n *# 8#) 64# s of
  (# s1, a #) -> case fillInts a n v s1 of s2 -> (# s2, MIntArr a #)

-- The first @n@ 'Int's of an array set to @v@.
fillInts :: MutableByteArray# s -> Int# -> Int# -> State# s -> State# s
fillInts a n v = go 0#
  where
    go i s
      | isTrue# (i >=# n) = s
      | otherwise         = go (i +# 1#) (writeIntArray# a i v s)

-- | A new array of @n@ numbers (their values unspecified).
newDblArr :: Int -> ST s (MDblArr s)
newDblArr (I# n) = ST $ \s -> case newByteArray# (n *# 8#) s of
  (# s1, a #) -> (# s1, MDblArr a #)

-- | A new array of @n@ bytes (their values unspecified).
newW8Arr :: Int -> ST s (MW8Arr s)
newW8Arr (I# n) = ST $ \s -> case newByteArray# n s of
  (# s1, a #) -> (# s1, MW8Arr a #)

-- | Read a 'Double' element (no bounds checks).
readD :: MDblArr s -> Int -> ST s Double
readD (MDblArr a) (I# i) = ST $ \s -> case readDoubleArray# a i s of (# s1, x #) -> (# s1, D# x #)
{-# INLINE readD #-}

-- | Read an 'Int' element (no bounds checks).
readI :: MIntArr s -> Int -> ST s Int
readI (MIntArr a) (I# i) = ST $ \s -> case readIntArray# a i s of (# s1, x #) -> (# s1, I# x #)
{-# INLINE readI #-}

-- | Write an 'Int' element (no bounds checks).
writeI :: MIntArr s -> Int -> Int -> ST s ()
writeI (MIntArr a) (I# i) (I# x) = ST $ \s -> case writeIntArray# a i x s of s1 -> (# s1, () #)
{-# INLINE writeI #-}

-- | Write a Double element (no bounds checks).
writeD :: MDblArr s -> Int -> Double -> ST s ()
writeD (MDblArr a) (I# i) (D# x) = ST $ \s -> case writeDoubleArray# a i x s of s1 -> (# s1, () #)
{-# INLINE writeD #-}

-- | Write a byte (no bounds checks).
writeW8 :: MW8Arr s -> Int -> Word8 -> ST s ()
writeW8 (MW8Arr a) (I# i) (W8# x) = ST $ \s -> case writeWord8Array# a i x s of s1 -> (# s1, () #)
{-# INLINE writeW8 #-}

-- | The array, immutable from now on (not copied: write no more to it).
freezeI :: MIntArr s -> ST s IntArr
freezeI (MIntArr a) = ST $ \s -> case unsafeFreezeByteArray# a s of (# s1, b #) -> (# s1, IntArr b #)

-- | The array, immutable from now on (not copied: write no more to it).
freezeD :: MDblArr s -> ST s DblArr
freezeD (MDblArr a) = ST $ \s -> case unsafeFreezeByteArray# a s of (# s1, b #) -> (# s1, DblArr b #)

-- | The array, immutable from now on (not copied: write no more to it).
freezeW8 :: MW8Arr s -> ST s W8Arr
freezeW8 (MW8Arr a) = ST $ \s -> case unsafeFreezeByteArray# a s of (# s1, b #) -> (# s1, W8Arr b #)

-- | An element (no bounds checks).
indexW8 :: W8Arr -> Int -> Word8
indexW8 (W8Arr a) (I# i) = W8# (indexWord8Array# a i)
{-# INLINE indexW8 #-}

-- | An element (no bounds checks).
indexI :: IntArr -> Int -> Int
indexI (IntArr a) (I# i) = I# (indexIntArray# a i)
{-# INLINE indexI #-}

-- | An element (no bounds checks).
indexD :: DblArr -> Int -> Double
indexD (DblArr a) (I# i) = D# (indexDoubleArray# a i)
{-# INLINE indexD #-}

-- | @prefixSums starts cells@ turns the counts @starts[0 .. cells]@ into
-- start offsets (an exclusive prefix sum: each cell's items then run from
-- its start to the next cell's) and returns the total.
prefixSums :: MIntArr s -> Int -> ST s Int
prefixSums starts cells = go 0 0
  where
    go !i !acc
      | i > cells = pure acc
      | otherwise = do
          c <- readI starts i
          writeI starts i acc
          go (i + 1) (acc + c)

-- | @bucketLists buckets pairs@ groups items by bucket (a counting sort),
-- the layout of every grid's cell lists: @(starts, items)@, where bucket
-- @b@ lists @items[starts b .. starts (b + 1) - 1]@. @pairs f@ must call
-- @f item bucket@ (with @0 <= bucket < buckets@) for every pair, the same
-- pairs in the same order each time: it runs twice, once to count, once to
-- place, so each bucket lists its items in the order given.
bucketLists :: Int -> ((Int -> Int -> ST s ()) -> ST s ()) -> ST s (IntArr, IntArr)
bucketLists buckets pairs = do
  (starts, total) <- countBuckets buckets pairs
  placeBuckets buckets starts total pairs
{-# INLINE bucketLists #-}

-- | 'bucketLists', or 'Nothing' (and nothing placed) when there are more
-- than @limit@ pairs.
bucketListsUpTo :: Int -> Int -> ((Int -> Int -> ST s ()) -> ST s ()) -> ST s (Maybe (IntArr, IntArr))
bucketListsUpTo buckets limit pairs = do
  (starts, total) <- countBuckets buckets pairs
  if total > limit then pure Nothing else Just <$> placeBuckets buckets starts total pairs
{-# INLINE bucketListsUpTo #-}

-- Every bucket's start offset, and the number of pairs.
countBuckets :: Int -> ((Int -> Int -> ST s ()) -> ST s ()) -> ST s (MIntArr s, Int)
countBuckets buckets pairs = do
  starts <- newIntArr (buckets + 1) 0
  pairs (\_ b -> readI starts b >>= writeI starts b . (+ 1))
  total <- prefixSums starts buckets
  pure (starts, total)
{-# INLINE countBuckets #-}

-- Every item in its bucket's run, in the order given.
placeBuckets :: Int -> MIntArr s -> Int -> ((Int -> Int -> ST s ()) -> ST s ()) -> ST s (IntArr, IntArr)
placeBuckets buckets starts total pairs = do
  items <- newIntArr (max 1 total) 0
  fill  <- newIntArr (buckets + 1) 0
  pairs (\i b -> do
    s0 <- readI starts b
    k  <- readI fill b
    writeI items (s0 + k) i
    writeI fill b (k + 1))
  st <- freezeI starts
  it <- freezeI items
  pure (st, it)
{-# INLINE placeBuckets #-}

-- | Is a number finite (neither NaN nor infinite)? @v - v@ is 0 exactly
-- for finite @v@ and NaN otherwise (cheaper than 'isNaN' and
-- 'isInfinite', which are foreign calls).
finite :: Double -> Bool
finite v = v - v == 0
{-# INLINE finite #-}
