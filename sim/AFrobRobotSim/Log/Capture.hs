-- |
-- Module      : AFrobRobotSim.Log.Capture
-- Description : What a frame needs of a state, kept as plain values and as bytes.
--
-- A frame's robots' readings (range finders, tracker) are the costly part
-- of a frame: the sensors run again at the frame's instant. A
-- 'FrameCapture' is what they and the rest of the frame need of the
-- state, and nothing more (positions, headings, speeds, charges,
-- odometry, the balls, the scores, each robot's rotational velocity over
-- the step), so that the frame can be made later, exactly as it would have
-- been made at once ('AFrobRobotSim.Log.pendingFrameMaker'). The replay
-- page's recorder keeps the frames of the strides its page may still get
-- so, in its temporary files ('encodePending', 'decodePending'), and makes
-- only those of the page it writes.
--
-- The bytes keep every number's bits (a 'Double' as its IEEE 754 word),
-- so a frame made from a capture read back is the frame made from the
-- capture itself, byte for byte.
module AFrobRobotSim.Log.Capture
  ( -- * Captures
    FrameCapture (..)
  , CapturedRobot (..)
  , PendingFrame (..)
    -- * As bytes
  , encodePending
  , decodePending
  ) where

import qualified Data.ByteString           as BS
import qualified Data.ByteString.Builder   as B
import qualified Data.ByteString.Builder.Extra as BE
import qualified Data.ByteString.Lazy      as BL
import qualified Data.ByteString.Unsafe    as BU
import           Data.Bits                 (shiftL, (.|.))
import           Data.Char                 (chr, ord)
import           Data.Word                 (Word64)
import           GHC.Float                 (castDoubleToWord64, castWord64ToDouble)

import           AFrob.Dimensions          (RobotId, RobotType)
import           AFrob.RobotIO             (BatteryStatus (..))
import           AFrobRobotSim.Log.Records (LogEvent (..))

-- | A frame's instant as its state had it: the simulated time (not yet
-- rounded), the robots (in the state's order), the balls' centres and the
-- program's scores.
data FrameCapture = FrameCapture
  { fcTime   :: !Double
  , fcRobots :: [CapturedRobot]
  , fcBalls  :: [(Double, Double)]
  , fcScores :: [(String, Int)]
  } deriving (Eq, Show)

-- | One robot of a 'FrameCapture': what its sensors and its frame record
-- need, unrounded.
data CapturedRobot = CapturedRobot
  { crType    :: RobotType
  , crId      :: !RobotId
  , crX       :: !Double
  , crY       :: !Double
  , crHeading :: !Double
  , crSpeed   :: !Double
  , crStuck   :: !Bool
  , crCharge  :: !Double
  , crOdoX    :: !Double
  , crOdoY    :: !Double
  , crBattery :: !BatteryStatus
  , crOmega   :: !Double   -- ^ the rotational velocity over the step that ended at the instant
  } deriving (Eq, Show)

-- | A frame not made yet: its instant, and the events and console lines
-- of its period (oldest first).
data PendingFrame = PendingFrame FrameCapture [LogEvent] [String]
  deriving (Eq, Show)

-- | A pending frame's bytes (any bytes: not text), which 'decodePending'
-- reads back to the same frame, every number to its bit.
encodePending :: PendingFrame -> BS.ByteString
encodePending (PendingFrame c evs ls) = BL.toStrict (BE.toLazyByteStringWith strategy BL.empty b)
  where
    strategy = BE.untrimmedStrategy 512 BE.smallChunkSize
    b = dbl (fcTime c) <> list robot (fcRobots c) <> list (\(x, y) -> dbl x <> dbl y) (fcBalls c)
        <> list (\(k, v) -> str k <> int v) (fcScores c)
        <> list event evs <> list str ls
    robot r = str (crType r) <> int (crId r) <> dbl (crX r) <> dbl (crY r) <> dbl (crHeading r)
              <> dbl (crSpeed r) <> B.word8 (if crStuck r then 1 else 0) <> dbl (crCharge r)
              <> dbl (crOdoX r) <> dbl (crOdoY r) <> B.word8 (battery (crBattery r)) <> dbl (crOmega r)
    event e = dbl (evTime e) <> str (evKind e)
              <> maybe (B.word8 0) (\(ty, i) -> B.word8 1 <> str ty <> int i) (evRobot e)
              <> str (evText e)
    battery s = case s of { BSHigh -> 0; BSLow -> 1; BSCritical -> 2 }
    dbl = B.word64LE . castDoubleToWord64
    int = B.int64LE . fromIntegral
    list f xs = int (length xs) <> foldMap f xs
    str s = list (B.word32LE . fromIntegral . ord) s

-- | The pending frame of bytes 'encodePending' wrote ('Nothing' for any
-- other bytes, as far as they can be told apart: a count that runs past
-- the end, a flag that is neither 0 nor 1, bytes left over).
decodePending :: BS.ByteString -> Maybe PendingFrame
decodePending bs = case runGet pending 0 of
  Just (p, end) | end == BS.length bs -> Just p
  _                                   -> Nothing
  where
    pending = do
      c <- FrameCapture <$> dbl <*> list robot <*> list ((,) <$> dbl <*> dbl) <*> list ((,) <$> str <*> int)
      PendingFrame c <$> list event <*> list str
    robot = CapturedRobot <$> str <*> int <*> dbl <*> dbl <*> dbl <*> dbl <*> flag <*> dbl <*> dbl <*> dbl
                          <*> battery <*> dbl
    event = LogEvent <$> dbl <*> str <*> (flag >>= \f -> if f then Just <$> ((,) <$> str <*> int) else pure Nothing)
                     <*> str
    battery = byte >>= \w -> case w of
      0 -> pure BSHigh
      1 -> pure BSLow
      2 -> pure BSCritical
      _ -> failed
    flag = byte >>= \w -> case w of
      0 -> pure False
      1 -> pure True
      _ -> failed
    dbl = castWord64ToDouble <$> word 8
    int = fromIntegral <$> word 8
    str = list (word 4 >>= \w -> if w <= 0x10FFFF then pure (chr (fromIntegral w)) else failed)
    list g = int >>= \n -> if n < 0 || n > BS.length bs then failed else sequence (replicate n g)
    byte = Get $ \i -> if i < BS.length bs then Just (BU.unsafeIndex bs i, i + 1) else Nothing
    -- a little-endian word of @k@ bytes
    word k = Get $ \i ->
      if i + k <= BS.length bs
        then Just (foldr (\j acc -> (acc `shiftL` 8) .|. fromIntegral (BU.unsafeIndex bs (i + j))) (0 :: Word64) [0 .. k - 1], i + k)
        else Nothing
    failed = Get (const Nothing)
    runGet (Get g) = g

-- A reader of bytes from an offset: the value and the offset after it.
newtype Get a = Get (Int -> Maybe (a, Int))

instance Functor Get where
  fmap f (Get g) = Get (fmap (\(a, i) -> (f a, i)) . g)

instance Applicative Get where
  pure a = Get (\i -> Just (a, i))
  Get gf <*> Get ga = Get $ \i -> case gf i of
    Nothing      -> Nothing
    Just (f, i') -> fmap (\(a, i'') -> (f a, i'')) (ga i')

instance Monad Get where
  Get g >>= k = Get $ \i -> case g i of
    Nothing      -> Nothing
    Just (a, i') -> let Get h = k a in h i'
