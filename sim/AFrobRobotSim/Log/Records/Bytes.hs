{-# LANGUAGE MagicHash #-}
-- |
-- Module      : AFrobRobotSim.Log.Records.Bytes
-- Description : A run log's line written as bytes, a frame straight into
--               the buffer.
--
-- 'encodeLogLineBytes' writes the characters of
-- 'AFrobRobotSim.Log.Records.Encode.encodeLogLine' as bytes. A header and
-- a summary go through their 'JSON' value; a frame, the line a log and a
-- replay page write many of, is written member by member with bounded
-- writes, and the usual robot in one write, with no 'JSON' value and no
-- 'String'. Part of "AFrobRobotSim.Log.Records", which re-exports
-- 'encodeLogLineBytes'.
module AFrobRobotSim.Log.Records.Bytes
  ( encodeLogLineBytes
  ) where

import qualified Data.ByteString          as BS
import qualified Data.ByteString.Char8    as BC
import qualified Data.ByteString.Builder  as B
import qualified Data.ByteString.Builder.Internal as BI
import qualified Data.ByteString.Builder.Prim as P
import           Data.ByteString.Builder.Prim.Internal (boundedPrim, runB)
import qualified Data.ByteString.Lazy     as BL
import           Data.Word                (Word8)
import           Foreign.Marshal.Utils    (copyBytes)
import           Foreign.Ptr              (Ptr, plusPtr)
import           Foreign.Storable         (pokeByteOff)
import           GHC.Exts                 (Addr#, Int (I#), Ptr (Ptr), cstringLength#)

import           AFrobRobotSim.JSON
import           AFrobRobotSim.Log.Records.Encode (logLineJSON)
import           AFrobRobotSim.Log.Records.Types

-- | One line's JSON text as bytes (ASCII), evaluated to the last one: the
-- characters of 'AFrobRobotSim.Log.Records.Encode.encodeLogLine', made
-- without a 'String'; a frame's made without its 'JSON' value too (a run
-- log and a replay page write 25 frames a simulated second by default,
-- with some twenty numbers a robot in each).
encodeLogLineBytes :: LogLine -> BS.ByteString
encodeLogLineBytes l = BL.toStrict (B.toLazyByteString (case l of
  LineFrame f -> frameBuilder f
  _           -> encodeJSONBuilder (logLineJSON l)))

-- A frame's JSON text, written member by member: the characters of
-- 'encodeJSONBuilder' of its 'logLineJSON' (the members in that order).
frameBuilder :: LogFrame -> B.Builder
frameBuilder f =
  lit "{\"kind\":\"frame\",\"t\":" <> numB (lfTime f)
  <> lit ",\"robots\":[" <> commas robot (lfRobots f)
  <> lit "],\"balls\":[" <> pairs (lfBalls f)
  <> lit "],\"scores\":{" <> commas score (lfScores f)
  <> lit "},\"events\":[" <> commas event (lfEvents f)
  <> lit "],\"console\":[" <> commas strB (lfConsole f)
  <> lit "]}"
  where
    -- (the literal pieces are packed once: each is a constant)
    lit = B.byteString . BC.pack
    numB = numberBuilder
    intB = numberBuilder . fromIntegral   -- (as the 'JSON' value has it: a number)
    strB = stringBuilder
    comma = B.char7 ','
    commas _ []       = mempty
    commas g (x : xs) = g x <> foldr (\y acc -> comma <> g y <> acc) mempty xs
    score (k, n) = strB k <> B.char7 ':' <> intB n
    -- A robot: the usual one (short plain types and battery) in one
    -- write ('writeRobot'), then its messages. Any other: its members up
    -- to the range finders' readings as one bounded write, the lists as
    -- loops of bounded writes, and the members between and after them
    -- likewise.
    robot r
      | all (isShortPlain . (\(ty, _, _, _) -> ty)) (lrSeenRobots r) && isShortPlain (lrBattery r) =
          writeAtMost (robotBound r) (writeRobot r) <> commas message (lrMessages r) <> lit "]}"
      | otherwise =
      P.primBounded robotHead r <> numbers (lrRange r)
      <> lit "],\"seenRobots\":[" <> commas seen (lrSeenRobots r)
      <> lit "],\"seenBalls\":[" <> pairs (lrSeenBalls r)
      <> lit "],\"battery\":" <> strB (lrBattery r)
      <> P.primBounded robotTail r
      <> commas message (lrMessages r)
      <> lit "]}"
    seen e@(ty, _, _, _) = B.char7 '[' <> strB ty <> P.primBounded seenRest e
    numbers []       = mempty
    numbers (x : xs) = P.primBounded numberPrim x <> P.primMapListBounded commaNumber xs
    pairs []       = mempty
    pairs (p : ps) = P.primBounded pairPrim p <> P.primMapListBounded commaPair ps
    message (t, m) = B.char7 '[' <> numB t <> comma <> strB m <> B.char7 ']'
    event e = lit "{\"t\":" <> numB (evTime e) <> lit ",\"kind\":" <> strB (evKind e)
              <> maybe mempty (\(ty, i) -> lit ",\"robot\":[" <> strB ty <> comma <> intB i <> B.char7 ']')
                       (evRobot e)
              <> lit ",\"text\":" <> strB (evText e) <> B.char7 '}'

-- A robot's members up to its messages (the opening bracket of
-- @messages@), when its seen robots' types and its battery are short
-- plain strings (always, in a simulator's log), in one write of at most
-- 'robotBound' bytes: the bytes of 'frameBuilder''s general case (the
-- same writes, one after the other, with no builder piece between them).
-- With a builder piece for each member and list element, a page of 1000
-- robots spent about 26,400 instructions a robot-frame encoding (and
-- allocated 6.8 KB); about 21,700 so.
writeRobot :: LogRobot -> Ptr Word8 -> IO (Ptr Word8)
writeRobot r op0 =
  runB robotHead r op0 >>= numbersAt (lrRange r)
  >>= litAt "],\"seenRobots\":["# >>= listAt seenAt (lrSeenRobots r)
  >>= litAt "],\"seenBalls\":["# >>= listAt (runB pairPrim) (lrSeenBalls r)
  >>= litAt "],\"battery\":"# >>= runB shortStringPrim (lrBattery r)
  >>= runB robotTail r
  where
    numbersAt []       op = pure op
    numbersAt (x : xs) op = numAt x op >>= listRest numAt xs
    seenAt e@(ty, _, _, _) op = charAt '[' op >>= runB shortStringPrim ty >>= runB seenRest e
    listAt _ []       op = pure op
    listAt w (x : xs) op = w x op >>= listRest w xs
    listRest _ []       op = pure op
    listRest w (x : xs) op = charAt ',' op >>= w x >>= listRest w xs

-- The most bytes 'writeRobot' writes: its constants (73 before the range
-- readings, 16, 15 and 12 between the lists, 38 after the battery), 10
-- numbers of at most 32 bytes, and for each reading a comma and a number,
-- for each seen robot a comma, a bracket, a quoted short string and
-- 'seenRest', for each seen ball a comma and 'pairPrim', for the battery
-- a quoted short string.
robotBound :: LogRobot -> Int
robotBound r = 73 + 16 + 15 + 12 + 38 + 10 * 32
               + 33 * length (lrRange r)
               + (2 + shortString + 2 + 4 + 3 * 32) * length (lrSeenRobots r)
               + (1 + 3 + 2 * 32) * length (lrSeenBalls r)
               + (shortString + 2)

-- A write of at most @n@ bytes, @n@ known when it is written (a
-- 'P.BoundedPrim' needs it before): room for @n@ bytes is made, then the
-- write is run in it.
writeAtMost :: Int -> (Ptr Word8 -> IO (Ptr Word8)) -> B.Builder
writeAtMost n w = BI.ensureFree n <> BI.builder step
  where
    step k (BI.BufferRange op ope) = w op >>= \op' -> k (BI.BufferRange op' ope)

-- The bounded writes of 'frameBuilder'. Each writes constants (ASCII
-- literals, copied whole) and numbers ('numberPrim', at most 32 bytes
-- each) straight into the buffer, within its bound.

-- A robot's members before its range finders' readings, to the opening
-- bracket of @range@: 73 bytes of constants and 7 numbers.
robotHead :: P.BoundedPrim LogRobot
robotHead = boundedPrim (73 + 7 * 32) $ \r op ->
  litAt "{\"x\":"# op >>= numAt (lrX r) >>= litAt ",\"y\":"# >>= numAt (lrY r)
  >>= litAt ",\"heading\":"# >>= numAt (lrHeading r)
  >>= litAt ",\"wheels\":["# >>= numAt (lrWheelLeft r) >>= charAt ',' >>= numAt (lrWheelRight r)
  >>= litAt "],\"v\":"# >>= numAt (lrSpeed r) >>= litAt ",\"omega\":"# >>= numAt (lrRotVel r)
  >>= (if lrBumper r then litAt ",\"bumper\":true"# else litAt ",\"bumper\":false"#)
  >>= litAt ",\"range\":["#

-- A robot's members after its battery, to the opening bracket of
-- @messages@: 38 bytes of constants and 3 numbers.
robotTail :: P.BoundedPrim LogRobot
robotTail = boundedPrim (38 + 3 * 32) $ \r op ->
  litAt ",\"charge\":"# op >>= numAt (lrCharge r)
  >>= litAt ",\"odometry\":["# >>= numAt (lrOdoX r) >>= charAt ',' >>= numAt (lrOdoY r)
  >>= litAt "],\"messages\":["#

-- A seen robot after its type: its number, bearing and distance, and the
-- closing bracket.
seenRest :: P.BoundedPrim (String, Int, Double, Double)
seenRest = boundedPrim (4 + 3 * 32) $ \(_, i, a, d) op ->
  charAt ',' op >>= numAt (fromIntegral i) >>= charAt ',' >>= numAt a >>= charAt ',' >>= numAt d
  >>= charAt ']'

-- A pair of numbers in brackets, and the same after a comma.
pairPrim, commaPair :: P.BoundedPrim (Double, Double)
pairPrim = boundedPrim (3 + 2 * 32) $ \(x, y) op ->
  charAt '[' op >>= numAt x >>= charAt ',' >>= numAt y >>= charAt ']'
commaPair = boundedPrim (4 + 2 * 32) $ \p op -> charAt ',' op >>= runB pairPrim p

-- A number after a comma.
commaNumber :: P.BoundedPrim Double
commaNumber = boundedPrim (1 + 32) $ \x op -> charAt ',' op >>= numAt x

-- An ASCII literal's bytes (its length is a constant GHC folds), then the
-- pointer after them.
litAt :: Addr# -> Ptr Word8 -> IO (Ptr Word8)
litAt a op = let n = I# (cstringLength# a) in copyBytes op (Ptr a) n >> pure (op `plusPtr` n)
{-# INLINE litAt #-}

-- One ASCII character.
charAt :: Char -> Ptr Word8 -> IO (Ptr Word8)
charAt c op = pokeByteOff op 0 (fromIntegral (fromEnum c) :: Word8) >> pure (op `plusPtr` 1)
{-# INLINE charAt #-}

-- A number ('numberPrim').
numAt :: Double -> Ptr Word8 -> IO (Ptr Word8)
numAt = runB numberPrim
{-# INLINE numAt #-}
