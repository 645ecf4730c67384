{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Render.Raster
-- Description : A tiny software rasteriser writing binary PPM (P6) images
--               straight into a byte buffer.
--
-- The drawing primitives of "AFrobRobotSim.Render". An image is built in
-- one mutable buffer holding the whole P6 file (header and RGB bytes); every
-- shape is filled by scanning only its bounding box, clipped to the image.
--
-- = Coordinates
--
-- Image coordinates are continuous: @x@ grows to the right, @y@ /downwards/,
-- and the pixel in column @i@ and row @j@ is the unit square
-- @[i, i+1) x [j, j+1)@, whose centre is @(i + 0.5, j + 0.5)@. A filled shape
-- covers exactly the pixels whose centres lie inside it (half-open on the
-- right and bottom edges for rectangles), except that a rectangle or disc
-- too small to cover any pixel centre still covers the pixel its centre is
-- in (a disc always covers that pixel). A line
-- covers the pixels containing @n + 1@ evenly spaced points along it, where
-- @n@ is its length along its longer axis rounded up. Everything is
-- clipped to the image; non-finite coordinates draw nothing.
module AFrobRobotSim.Render.Raster
  ( -- * Colours
    Colour (..)
  , darken
  , blend
    -- * Canvases
  , Canvas
  , createPPM
  , ppmPixel
    -- * Filled shapes
  , fillAll
  , fillRectI
  , fillRect
  , fillDisc
  , fillTriangle
    -- * Lines
  , drawLine
  , ImageMap (..)
  , applyMap
  , drawPolyline
    -- * Text
  , drawText
  , textWidth
  ) where

import           Control.Monad            (forM_, when, zipWithM_)
import qualified Data.ByteString          as B
import qualified Data.ByteString.Char8    as BC
import qualified Data.ByteString.Internal as BI
import qualified Data.ByteString.Unsafe   as BU
import           Data.Char                (isSpace)
import           Data.Word                (Word8)
import           Foreign.Marshal.Utils    (copyBytes)
import           Foreign.Ptr              (Ptr, plusPtr)
import           Foreign.Storable         (pokeByteOff)

import           AFRP.Geometry.Point      (Point2 (..))
import           AFrobRobotSim.FlatArray  (finite)

-- | An RGB colour, one byte per channel.
data Colour = Colour !Word8 !Word8 !Word8
  deriving (Eq, Ord, Show)

-- | @darken f c@ scales every channel of @c@ by @f@ (in @[0, 1]@).
darken :: Double -> Colour -> Colour
darken f (Colour r g b) = Colour (sc r) (sc g) (sc b)
  where sc v = fromIntegral (round (max 0 (min 255 (f * fromIntegral v))) :: Int)

-- | @blend f a b@ is @a@ mixed with @b@, @f@ of @a@ and @1 - f@ of @b@.
blend :: Double -> Colour -> Colour -> Colour
blend f (Colour r1 g1 b1) (Colour r2 g2 b2) = Colour (mix r1 r2) (mix g1 g2) (mix b1 b2)
  where
    mix u v = fromIntegral (round (max 0 (min 255 (f * fromIntegral u + (1 - f) * fromIntegral v))) :: Int)

-- | A drawing surface: the first pixel's address, the width and height.
data Canvas = Canvas !(Ptr Word8) !Int !Int

-- | @createPPM w h draw@ is the whole binary PPM file
-- (@"P6\\n\<w\> \<h\>\\n255\\n"@ then @3 * w * h@ RGB bytes, row by row from
-- the top) of a @w@ by @h@ image drawn by @draw@ on a canvas whose pixels
-- start out black. Negative sizes count as 0.
createPPM :: Int -> Int -> (Canvas -> IO ()) -> B.ByteString
createPPM w0 h0 draw = BI.unsafeCreate (hlen + 3 * w * h) $ \p -> do
  zipWithM_ (\k ch -> pokeByteOff p k (BI.c2w ch)) [0 ..] header
  _ <- BI.memset (p `plusPtr` hlen) 0 (fromIntegral (3 * w * h))
  draw (Canvas (p `plusPtr` hlen) w h)
  where
    w      = max 0 w0
    h      = max 0 h0
    header = "P6\n" ++ show w ++ " " ++ show h ++ "\n255\n"
    hlen   = length header

-- | The colour of the pixel in column @i@, row @j@ (from the top-left) of a
-- binary PPM file with maximum value 255, if it has one there.
ppmPixel :: B.ByteString -> Int -> Int -> Maybe Colour
ppmPixel bs i j = do
  rest0      <- B.stripPrefix (BC.pack "P6") bs
  (w, rest1) <- field rest0
  (h, rest2) <- field rest1
  (m, rest3) <- field rest2
  when (m /= 255 || i < 0 || j < 0 || i >= w || j >= h) Nothing
  (_, pixels) <- BC.uncons rest3
  let o = 3 * (j * w + i)
  when (B.length pixels < o + 3) Nothing
  return (Colour (BU.unsafeIndex pixels o) (BU.unsafeIndex pixels (o + 1)) (BU.unsafeIndex pixels (o + 2)))
  where
    field s = BC.readInt (BC.dropWhile isSpace s)

-- | Fill one row's pixels @i0 .. i1@ (inclusive), clipped.
fillSpan :: Canvas -> Colour -> Int -> Int -> Int -> IO ()
fillSpan (Canvas p w h) (Colour r g b) j i0 i1 =
  when (j >= 0 && j < h) $ go (3 * (j * w + max 0 i0)) (3 * (j * w + min (w - 1) i1))
  where
    go !o !z
      | o > z     = return ()
      | otherwise = do
          pokeByteOff p o r
          pokeByteOff p (o + 1) g
          pokeByteOff p (o + 2) b
          go (o + 3) z
{-# INLINE fillSpan #-}

-- | Fill the whole canvas with one colour.
fillAll :: Canvas -> Colour -> IO ()
fillAll c@(Canvas p w h) col = when (w > 0 && h > 0) $ do
  fillSpan c col 0 0 (w - 1)
  forM_ [1 .. h - 1] $ \j -> copyBytes (p `plusPtr` (3 * j * w)) p (3 * w)

-- | @fillRectI c col i0 j0 i1 j1@ fills columns @i0 .. i1@ of rows
-- @j0 .. j1@ (inclusive), clipped.
fillRectI :: Canvas -> Colour -> Int -> Int -> Int -> Int -> IO ()
fillRectI c@(Canvas _ _ h) col i0 j0 i1 j1 =
  forM_ [max 0 j0 .. min (h - 1) j1] $ \j -> fillSpan c col j i0 i1

-- Keep a coordinate within a range where converting to Int is safe.
clampD :: Double -> Double
clampD = max (-1e7) . min 1e7

-- The pixels whose centres lie in [a, b), or the one containing the
-- midpoint if there are none.
pixelRange :: Double -> Double -> (Int, Int)
pixelRange a b
  | lo <= hi  = (lo, hi)
  | otherwise = (mid, mid)
  where
    lo  = ceiling (clampD a - 0.5)
    hi  = ceiling (clampD b - 0.5) - 1
    mid = floor (clampD ((a + b) / 2))

-- | @fillRect c col x0 y0 x1 y1@ fills the rectangle @[x0, x1) x [y0, y1)@
-- (image coordinates, @x0 <= x1@, @y0 <= y1@).
fillRect :: Canvas -> Colour -> Double -> Double -> Double -> Double -> IO ()
fillRect c col x0 y0 x1 y1 = when (all finite [x0, y0, x1, y1]) $ do
  let (i0, i1) = pixelRange x0 x1
      (j0, j1) = pixelRange y0 y1
  fillRectI c col i0 j0 i1 j1

-- | @fillDisc c col cx cy r@ fills the disc of radius @r@ around
-- @(cx, cy)@.
fillDisc :: Canvas -> Colour -> Double -> Double -> Double -> IO ()
fillDisc c@(Canvas _ _ h) col cx cy r = when (all finite [cx, cy, r]) $ do
  let j0 = max 0 (ceiling (clampD (cy - r - 0.5)))
      j1 = min (h - 1) (floor (clampD (cy + r - 0.5)))
  forM_ [j0 .. j1] $ \j -> do
    let dy = fromIntegral j + 0.5 - cy
        d2 = r * r - dy * dy
    when (d2 >= 0) $ do
      let dx = sqrt d2
      fillSpan c col j (ceiling (clampD (cx - dx - 0.5))) (floor (clampD (cx + dx - 0.5)))
  let ci = floor (clampD cx)
  fillSpan c col (floor (clampD cy)) ci ci

-- | Fill the triangle with the given corners (in either orientation).
fillTriangle :: Canvas -> Colour -> (Double, Double) -> (Double, Double) -> (Double, Double) -> IO ()
fillTriangle c@(Canvas _ w h) col (ax, ay) (bx, by) (qx, qy)
  | not (all finite [ax, ay, bx, by, qx, qy]) = return ()
  | otherwise =
      forM_ [j0 .. j1] $ \j -> forM_ [i0 .. i1] $ \i -> do
        let px = fromIntegral i + 0.5
            py = fromIntegral j + 0.5
            e1 = edge ax ay bx by px py
            e2 = edge bx by qx qy px py
            e3 = edge qx qy ax ay px py
        when ((e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0)) $
          fillSpan c col j i i
  where
    i0 = max 0 (floor (clampD (minimum [ax, bx, qx])))
    i1 = min (w - 1) (floor (clampD (maximum [ax, bx, qx])))
    j0 = max 0 (floor (clampD (minimum [ay, by, qy])))
    j1 = min (h - 1) (floor (clampD (maximum [ay, by, qy])))
    edge x1 y1 x2 y2 px py = (x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)

-- Clip the segment to the rectangle [lo, hiX] x [lo, hiY] (Liang-Barsky)
-- and draw what is left with the continuation.
clipSegment :: Double -> Double -> Double -> (Double, Double) -> (Double, Double)
            -> (Double -> Double -> Double -> Double -> IO ()) -> IO ()
clipSegment lo hiX hiY (ax, ay) (bx, by) k =
  step (-dx) (ax - lo) 0 1 $ \t0 t1 ->
  step dx (hiX - ax) t0 t1 $ \t2 t3 ->
  step (-dy) (ay - lo) t2 t3 $ \t4 t5 ->
  step dy (hiY - ay) t4 t5 $ \t6 t7 ->
  k (ax + t6 * dx) (ay + t6 * dy) (ax + t7 * dx) (ay + t7 * dy)
  where
    dx = bx - ax
    dy = by - ay
    step pk qk t0 t1 next
      | pk == 0   = if qk < 0 then return () else next t0 t1
      | otherwise =
          let r   = qk / pk
              t0' = if pk < 0 then max t0 r else t0
              t1' = if pk < 0 then t1 else min t1 r
          in if t0' <= t1' then next t0' t1' else return ()
{-# INLINE clipSegment #-}

-- | @drawLine c col t a b@ draws the segment from @a@ to @b@ with squares of
-- @t@ by @t@ pixels (@t >= 1@) centred on the pixels it covers.
drawLine :: Canvas -> Colour -> Int -> (Double, Double) -> (Double, Double) -> IO ()
drawLine c@(Canvas _ w h) col !t0 a@(!ax, !ay) b@(!bx, !by)
  | not (finite ax && finite ay && finite bx && finite by) = return ()
  | otherwise = clipSegment (-m) (fromIntegral w + m) (fromIntegral h + m) a b (lineSteps c col t)
  where
    !t = max 1 t0
    !m = fromIntegral t + 1

-- The squares of a clipped line.
lineSteps :: Canvas -> Colour -> Int -> Double -> Double -> Double -> Double -> IO ()
lineSteps c col !t !sx !sy !ex !ey = go 0
  where
    !dx  = ex - sx
    !dy  = ey - sy
    !n   = max 1 (ceiling (max (abs dx) (abs dy))) :: Int
    !nd  = fromIntegral n :: Double
    !off = (t - 1) `quot` 2
    go :: Int -> IO ()
    go !k
      | k > n     = return ()
      | otherwise = do
          let !f = fromIntegral k / nd
              !i = floor (sx + f * dx) - off
              !j = floor (sy + f * dy) - off
          if t == 1 then fillSpan c col j i i else fillRectI c col i j (i + t - 1) (j + t - 1)
          go (k + 1)

-- | A map from world to image coordinates that flips @y@:
-- @ImageMap s ox oy@ takes @(x, y)@ to @(ox + s x, oy - s y)@.
data ImageMap = ImageMap !Double !Double !Double

-- | The image point of a world point under a map.
applyMap :: ImageMap -> Point2 Double -> (Double, Double)
applyMap (ImageMap s ox oy) (Point2 x y) = (ox + s * x, oy - s * y)

-- | Draw a polyline through the images of the (world) points under the
-- map, like 'drawLine' for each segment; points closer than one pixel to
-- the last point drawn are skipped (the last point of the list never is).
-- A single point draws one square.
drawPolyline :: Canvas -> Colour -> Int -> ImageMap -> [Point2 Double] -> IO ()
drawPolyline c col t im@(ImageMap s ox oy) pts = case pts of
  []                -> return ()
  [p]               -> let q = applyMap im p in drawLine c col t q q
  Point2 x y : rest -> go (ox + s * x) (oy - s * y) rest
  where
    go !px !py qs = case qs of
      [] -> return ()
      Point2 x y : more -> do
        let qx = ox + s * x
            qy = oy - s * y
            dx = qx - px
            dy = qy - py
        if not (null more) && dx * dx + dy * dy < 1
          then go px py more
          else drawLine c col t (px, py) (qx, qy) >> go qx qy more

-- | A 3 by 5 glyph, top row first: the digits, @\'-\'@, and blank for
-- anything else.
glyph :: Char -> [String]
glyph ch = case ch of
  '0' -> ["###", "#.#", "#.#", "#.#", "###"]
  '1' -> [".#.", "##.", ".#.", ".#.", "###"]
  '2' -> ["###", "..#", "###", "#..", "###"]
  '3' -> ["###", "..#", ".##", "..#", "###"]
  '4' -> ["#.#", "#.#", "###", "..#", "..#"]
  '5' -> ["###", "#..", "###", "..#", "###"]
  '6' -> ["###", "#..", "###", "#.#", "###"]
  '7' -> ["###", "..#", ".#.", ".#.", ".#."]
  '8' -> ["###", "#.#", "###", "#.#", "###"]
  '9' -> ["###", "#.#", "###", "..#", "###"]
  '-' -> ["...", "...", "###", "...", "..."]
  '.' -> ["...", "...", "...", "...", ".#."]
  _   -> replicate 5 "..."

-- | @drawText c col k (i, j) s@ draws @s@ in the built-in 3 by 5 font
-- (digits, @\'-\'@ and @\'.\'@ only) magnified @k@ times, its top-left corner at
-- pixel @(i, j)@, one glyph pixel between characters.
drawText :: Canvas -> Colour -> Int -> (Int, Int) -> String -> IO ()
drawText c col k0 (i0, j0) s =
  forM_ (zip [0 ..] s) $ \(n, ch) ->
    forM_ (zip [0 ..] (glyph ch)) $ \(row, bits) ->
      forM_ (zip [0 ..] bits) $ \(colm, bit) ->
        when (bit == '#') $ do
          let i = i0 + (4 * n + colm) * k
              j = j0 + row * k
          fillRectI c col i j (i + k - 1) (j + k - 1)
  where
    k = max 1 k0

-- | The width in pixels of a string drawn by 'drawText' at magnification
-- @k@ (its height is @5 k@).
textWidth :: Int -> String -> Int
textWidth k s = max 0 (max 1 k * (4 * length s - 1))
