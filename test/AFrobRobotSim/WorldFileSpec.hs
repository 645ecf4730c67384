-- | Tests for "AFrobRobotSim.WorldFile": every object kind, comments,
-- units, case, exact error locations, the parse/render round trip and the
-- example worlds in @worlds/@.
module AFrobRobotSim.WorldFileSpec (spec) where

import           Control.Concurrent      (forkIO, threadDelay)
import           Control.Exception      (evaluate)
import qualified Data.ByteString        as B
import qualified Data.ByteString.Char8  as BC
import           Data.Char              (isDigit, isPrint)
import           Data.List              (intercalate, isInfixOf, isPrefixOf, tails)
import           System.Posix.Files     (createNamedPipe)
import           System.Timeout         (timeout)
import           System.FilePath        ((</>))
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Geometry          (Point2 (..))
import           AFrobRobotSim.World
import           AFrobRobotSim.World.Check
import           AFrobRobotSim.WorldFile
import           TestUtil (withTempDir)

------------------------------------------------------------------------------
-- Helpers

-- | Parse under the file name @w.world@.
parse :: String -> Either String WorldTemplate
parse = parseWorld "w.world"

-- | Parse a single object.
parse1 :: String -> Either String ObjectTemplate
parse1 s = case parse s of
  Right [o] -> Right o
  Right os  -> Left ("expected one object, got " ++ show os)
  Left e    -> Left e

-- | The parse fails with exactly this message.
failsWith :: HasCallStack => String -> String -> Expectation
failsWith input msg = parse input `shouldBe` Left msg

------------------------------------------------------------------------------
-- Generators

-- | Finite doubles of every kind: ordinary, negative, tiny (down to the
-- denormals), huge (up to the largest finite double), signed zeros and
-- awkward decimals.
genDouble :: Gen Double
genDouble = frequency
  [ (3, arbitrary)
  , (2, choose (-5, 5))
  , (2, bits)
  , (1, elements specials)
  , (1, (/ 10) . fromInteger <$> choose (-1000, 1000))
  ]
  where
    bits = (do m <- choose (-(2 ^ (53 :: Int)), 2 ^ (53 :: Int))
               e <- choose (-1130, 971)
               pure (encodeFloat m e)) `suchThat` finite
    specials = [ 0, -0.0, 5.0e-324, -5.0e-324, 2.2250738585072014e-308
               , 1.7976931348623157e308, -1.7976931348623157e308
               , 0.1, 1 / 3, pi, -pi, 1e22, 1e23, 123456789.125, 9007199254740993 ]
    finite x = not (isNaN x || isInfinite x)

genId :: Gen Int
genId = frequency
  [ (4, arbitrary), (1, elements [minBound, maxBound, 0, -1]) ]

genObject :: Gen ObjectTemplate
genObject = do
  p <- Point2 <$> genDouble <*> genDouble
  oneof
    [ pure (OTBlock p), pure (OTVWall p), pure (OTHWall p), pure (OTBall p)
    , OTSimbotA <$> genId <*> pure p <*> genHeading
    , OTSimbotB <$> genId <*> pure p <*> genHeading
    ]
  where
    genHeading = genDouble `suchThat` (\h -> abs h <= maxHeading)

newtype AWorld = AWorld WorldTemplate
  deriving Show

instance Arbitrary AWorld where
  arbitrary = AWorld <$> listOf genObject
  shrink (AWorld w) = AWorld <$> shrinkList (const []) w

------------------------------------------------------------------------------
-- Geometry of the example worlds

-- | The bounding boxes of two objects overlap by more than a nanometre.
boxesOverlap :: ObjectTemplate -> ObjectTemplate -> Bool
boxesOverlap a b =
  let Point2 ax ay = otPos a
      Point2 bx by = otPos b
      (ahw, ahh)   = objectHalfSize a
      (bhw, bhh)   = objectHalfSize b
      eps          = 1e-9
  in abs (ax - bx) < ahw + bhw - eps && abs (ay - by) < ahh + bhh - eps

-- | Anything but the world's size (which has no position).
placedObject :: ObjectTemplate -> Bool
placedObject o = case o of
  OTSize {} -> False
  _         -> True

exampleFiles :: [FilePath]
exampleFiles = ["worlds/arena.world", "worlds/soccer.world", "worlds/corridor.world", "worlds/big.world"]

------------------------------------------------------------------------------
-- Hostile files

-- | Parse bytes under the file name @h.world@.
parseB :: B.ByteString -> Either String WorldTemplate
parseB = readWorldBytes "h.world"

-- | The result, fully evaluated, or 'Nothing' if that took more than 30
-- seconds: a guard against a parser that hangs or is quadratic (minutes
-- on these inputs), generous for a loaded machine (each input takes well
-- under a second here). Speed is measured in bench/, not by tests.
forcedSoon :: Either String WorldTemplate -> IO (Maybe (Either String WorldTemplate))
forcedSoon r = timeout 30000000 (evaluate (force r))
  where
    force x = case x of
      Left e  -> length e `seq` x
      Right w -> length (show w) `seq` x

isRight', isLeft' :: Maybe (Either String WorldTemplate) -> Bool
isRight' = maybe False (either (const False) (const True))
isLeft'  = maybe False (either (const True) (const False))

-- | A message starting @h.world:LINE:@ (and a column or more text).
positioned :: String -> Bool
positioned e = case stripPrefix' "h.world:" e of
  Just rest -> let (l, rest') = span isDigit rest
               in not (null l) && read l >= (1 :: Integer) && take 1 rest' == ":" && length rest' > 2
  Nothing   -> False
  where
    stripPrefix' p x = if p `isPrefixOf` x then Just (drop (length p) x) else Nothing

-- | A world file, valid or broken: the rendering of a world of small
-- coordinates, then a few mutations (bytes inserted, deleted or repeated,
-- long digit runs, NULs, invalid UTF-8, BOMs, CRs, non-finite literals).
genHostile :: Gen B.ByteString
genHostile = do
  objs <- resize 8 (listOf genSmall)
  let base = BC.pack (renderWorld objs)
  k <- frequency [(1, pure 0), (4, choose (1, 4))]
  mutations k base
  where
    genSmall = do
      p <- Point2 <$> choose (-5.5, 5.5) <*> choose (-5.5, 5.5)
      i <- choose (-3, 300)
      h <- choose (-10, 10)
      elements [OTBlock p, OTVWall p, OTHWall p, OTBall p, OTSimbotA i p h, OTSimbotB i p h]
    mutations :: Int -> B.ByteString -> Gen B.ByteString
    mutations 0 b = pure b
    mutations k b = mutate b >>= mutations (k - 1)
    mutate b = do
      pos <- choose (0, B.length b)
      let (front, back) = B.splitAt pos b
      ins <- oneof
        [ B.pack <$> listOf1 arbitrary
        , pure (BC.replicate 5000 '7')
        , pure (BC.pack "1e308")
        , pure (BC.pack " heading 1e308 deg")
        , pure (BC.pack " NaN Infinity -inf")
        , pure (B.pack [0])
        , pure (B.pack [0xff, 0xfe])
        , pure (B.pack [0xe2, 0x82])
        , pure (B.pack [0xef, 0xbb, 0xbf])
        , pure (BC.pack "\r\n")
        , pure (BC.pack "simbotA 1 at 0 0\n")
        , pure (BC.pack "   \t ")
        ]
      choice <- choose (0 :: Int, 3)
      cut <- choose (0, 20)
      pure $ case choice of
        0 -> B.concat [front, B.drop cut back]              -- delete
        1 -> B.concat [front, B.take cut back, back]        -- repeat
        _ -> B.concat [front, ins, back]                    -- insert

spec :: Spec
spec = do
  describe "the world's size (size W H)" $ do
    it "parses a size line anywhere, in any case, into an OTSize" $ do
      parse "size 100 100\nball at 40 40\n" `shouldBe` Right [OTSize 100 100, OTBall (Point2 40 40)]
      parse "ball at 0 0\nSIZE 30.5 1e1   # wide\n" `shouldBe` Right [OTBall (Point2 0 0), OTSize 30.5 10]
    it "rejects sides out of range, non-finite or missing, with FILE:LINE:COLUMN" $ do
      "size 0 10" `failsWith`
        "w.world:1:6: expected a world side from 1 to 1000 metres after \"size\", found \"0\" (out of range)"
      "\nsize 10 1001" `failsWith`
        "w.world:2:9: expected a world side from 1 to 1000 metres after \"10\", found \"1001\" (out of range)"
      "size -5 5" `failsWith`
        "w.world:1:6: expected a world side from 1 to 1000 metres after \"size\", found \"-5\" (out of range)"
      "size 0.99 5" `failsWith`
        "w.world:1:6: expected a world side from 1 to 1000 metres after \"size\", found \"0.99\" (out of range)"
      "size inf 5" `failsWith`
        "w.world:1:6: expected a finite number after \"size\", found \"inf\" (NaN and infinities are not allowed)"
      "size 10" `failsWith`
        "w.world:1:8: expected a world side from 1 to 1000 metres after \"10\", found end of line"
      "size 10 10 10" `failsWith` "w.world:1:12: expected end of line or a comment after \"10\", found \"10\""
      "size ten 10" `failsWith`
        "w.world:1:6: expected a number after \"size\", found \"ten\""
    it "accepts the limits 1 and 1000" $
      parse "size 1 1000" `shouldBe` Right [OTSize 1 1000]
    it "rejects a second size line, naming the first" $
      "size 20 20\nball at 0 0\n size 30 30\n" `failsWith` "w.world:3: the world's size is given twice (first on line 1)"
    it "defaults to the notes' 10 by 10: an object beyond 5 m is outside without a size, inside with one" $ do
      readWorldBytes "w.world" (BC.pack "ball at 7 0\n")
        `shouldBe` Left "w.world:1: ball at (7.0, 0.0): lies (partly) outside the world [-5.0, 5.0] x [-5.0, 5.0]"
      readWorldBytes "w.world" (BC.pack "ball at 7 0\nsize 20 20\n") `shouldBe` Right [OTBall (Point2 7 0), OTSize 20 20]
      readWorldBytes "w.world" (BC.pack "size 20 12\nball at 7 0\nsimbotA 1 at 0 5.9\n")
        `shouldBe` Left "w.world:3: SimbotA 1 at (0.0, 5.9): lies (partly) outside the world [-10.0, 10.0] x [-6.0, 6.0]"
    it "does not count the size line among the objects" $
      fmap length (parse (unlines ("size 200 200" : replicate maxObjects "ball at 0 0"))) `shouldBe` Right (maxObjects + 1)
    it "renders a size as a size line" $
      lines (renderWorld [OTSize 100 50, OTBall (Point2 1 2)])
        `shouldBe` ["# afrp world file: 1 object (positions in metres, headings in radians)", "size 100.0 50.0", "ball at 1.0 2.0"]
    it "round-trips worlds with a size exactly" $
      withMaxSuccess 200 $ \(AWorld w) -> forAll ((,,) <$> choose (1, 1000) <*> choose (1, 1000) <*> choose (0, length w)) $
        \(sw, sh, k) -> let w' = take k w ++ [OTSize sw sh] ++ drop k w
                       in parseWorld "r.world" (renderWorld w') === Right w'
  describe "hostile world files" $ do
    it "rejects a number of a million digits at once (not read whole), with its position" $ do
      r <- forcedSoon (parseB (BC.pack ("ball at 0 0\nball at " ++ replicate 1000000 '9' ++ " 0\n")))
      r `shouldBe` Just (Left ("h.world:2:" ++ show (maxLineLength + 1) ++ ": line longer than "
                               ++ show maxLineLength ++ " characters"))
    it "rejects a token longer than maxTokenLength, naming its start" $
      parseB (BC.pack ("ball at 0 " ++ replicate 200 '1'))
        `shouldBe` Left ("h.world:1:11: token longer than " ++ show maxTokenLength
                         ++ " characters, starting \"" ++ replicate 20 '1' ++ "\"")
    it "parses a large file in time linear in its size" $ do
      -- 200,000 lines: a quadratic parser would not finish (a 30 m world,
      -- whose floor holds the 5000 balls' 353 m^2)
      let chunk = concat (replicate 39 "# a comment line\n") ++ "ball at 1.25 -3.5\n"
          big = BC.pack ("size 30 30\n" ++ concat (replicate 5000 chunk))
      r <- forcedSoon (parseB big)
      fmap (fmap length) r `shouldBe` Just (Right 5001)
    it "rejects more than maxObjects objects, at the first one too many" $
      parseB (BC.pack (concat (replicate (maxObjects + 1) "block at 0 0\n")))
        `shouldBe` Left ("h.world:" ++ show (maxObjects + 1) ++ ": too many objects (at most "
                         ++ show maxObjects ++ ")")
    it "reports invalid UTF-8 with its line and column" $ do
      parseB (B.concat [BC.pack "ball at 0 0\n# caf", B.pack [0xc3, 0xa9], BC.pack " ", B.pack [0xff], BC.pack "\n"])
        `shouldBe` Left "h.world:2:8: invalid UTF-8 (byte 0xff)"
      parseB (B.concat [BC.pack "ball at 0 0 # ", B.pack [0xe2, 0x82]])
        `shouldBe` Left "h.world:1:15: invalid UTF-8 (byte 0xe2)"
      parseB (B.pack [0xc0, 0xaf]) `shouldBe` Left "h.world:1:1: invalid UTF-8 (byte 0xc0)"
      parseB (B.pack [0xed, 0xa0, 0x80]) `shouldBe` Left "h.world:1:1: invalid UTF-8 (byte 0xed)"
      parseB (B.pack [0xf4, 0x90, 0x80, 0x80]) `shouldBe` Left "h.world:1:1: invalid UTF-8 (byte 0xf4)"
    it "accepts valid UTF-8 in comments" $
      parseB (B.concat [BC.pack "# caf", B.pack [0xc3, 0xa9, 0xe2, 0x82, 0xac, 0xf0, 0x9f, 0x98, 0x80], BC.pack "\nball at 1 2\n"])
        `shouldBe` Right [OTBall (Point2 1 2)]
    it "accepts a UTF-8 byte order mark, CRLF line ends and trailing whitespace" $
      parseB (B.concat [B.pack [0xef, 0xbb, 0xbf], BC.pack "ball at 1 2 \t \r\nblock at -1 -2\r\n\r\n"])
        `shouldBe` Right [OTBall (Point2 1 2), OTBlock (Point2 (-1) (-2))]
    it "reads classic Mac line ends (a lone CR), and counts its lines" $ do
      parseB (BC.pack "# a comment\rball at 1 2\rblock at -1 -2\r")
        `shouldBe` Right [OTBall (Point2 1 2), OTBlock (Point2 (-1) (-2))]
      parseB (BC.pack "ball at 1 2\r\r\nwall v at x1 2\r")
        `shouldBe` Left "h.world:3:11: expected a number after \"at\", found \"x1\""
    it "reports a NUL byte with its position" $
      parseB (BC.pack "ball at 0 0\nblock at 1\NUL 2\n")
        `shouldBe` Left "h.world:2:11: found a NUL character (is this a text file?)"
    it "escapes control characters in messages" $
      parseB (BC.pack "ball at \ESC[2J 0")
        `shouldBe` Left "h.world:1:9: expected a number after \"at\", found \"\\ESC[2J\""
    it "checks every number: huge headings, NaN, infinities" $ do
      parseB (BC.pack "\nsimbotA 1 at 0 0 heading 1e308 deg")
        `shouldBe` Left "h.world:2:26: expected a heading within +-1000000 after \"heading\", found \"1e308\" (out of range)"
      parseB (BC.pack "simbotB 1 at 0 0 heading -2e6 rad")
        `shouldSatisfy` either ("h.world:1:26: " `isPrefixOf`) (const False)
      parseB (BC.pack "ball at nan 0") `shouldSatisfy` either ("h.world:1:9: " `isPrefixOf`) (const False)
      parseB (BC.pack "ball at 0 +Infinity") `shouldSatisfy` either ("h.world:1:11: " `isPrefixOf`) (const False)
      parseB (BC.pack "block at 1e309 0") `shouldSatisfy` either ("h.world:1:10: " `isPrefixOf`) (const False)
    it "rejects objects overlapping at time 0, naming both and their lines" $ do
      parseB (BC.pack "# arena\nblock at 0 0\n\nsimbotA 1 at 0.1 0 heading 90 deg\n")
        `shouldBe` Left "h.world:4: SimbotA 1 at (0.1, 0.0) overlaps block at (0.0, 0.0) (line 2)"
      parseB (BC.pack "ball at 1 1\nwall v at 1.1 1\n")
        `shouldBe` Left "h.world:2: vertical wall at (1.1, 1.0) overlaps ball at (1.0, 1.0) (line 1)"
    it "reports objects outside the world and duplicate ids with their lines" $
      parseB (BC.pack "simbotA 1 at 0 0\nball at 4.9 0\nsimbotA 1 at 2 2\n")
        `shouldBe` Left (intercalate "\n"
          [ "h.world:2: ball at (4.9, 0.0): lies (partly) outside the world [-5.0, 5.0] x [-5.0, 5.0]"
          , "h.world:3: SimbotA 1 at (2.0, 2.0) has the same id as SimbotA 1 at (0.0, 0.0) (line 1)" ])
    it "gives 300 overlapping robots a short message, with a count of the rest" $ do
      let pile = BC.pack (concat [ "simbotB " ++ show i ++ " at 1 1\n" | i <- [1 .. 300 :: Int] ])
      r <- forcedSoon (parseB pile)
      case r of
        Just (Left e) -> do
          length (lines e) `shouldBe` maxProblems + 1
          lines e `shouldSatisfy` all ("h.world:" `isPrefixOf`) . take maxProblems
          last (lines e) `shouldBe` "... and 44830 more problems"
        other -> expectationFailure (show other)
    it "checks a file of maxObjects objects in one place, not pair by pair" $ do
      let pile = BC.pack (concat [ "simbotA " ++ show i ++ " at 1 1\nblock at 1.2 1\n"
                                 | i <- [1 .. maxObjects `div` 2] ])
      r <- forcedSoon (parseB pile)
      fmap (either (length . lines) (const 0)) r `shouldBe` Just (maxProblems + 1)
    it "refuses 50,000 walls beside 50,000 balls in one square metre as too crowded, at the line that passes maxClosePairs" $ do
      -- (with the limit at 100,000 objects and no bound on the pairs, such
      -- a file of 1.8 MB took more than 400 s to check)
      -- (the 498th ball makes 498 * 50000 + 498 * 497 / 2 = 25023753 pairs)
      let crowd = BC.pack ("size 1000 1000\n" ++ concat (replicate 50000 "wall v at 0.5 0.5\n")
                           ++ concat (replicate 50000 "ball at 0.75 0.5\n"))
      r <- forcedSoon (parseB crowd)
      fmap (either (take 1 . lines) (const [])) r
        `shouldBe` Just [ "h.world:50499: ball at (0.75, 0.5): too crowded: the objects up to "
                          ++ "this one make 25023753 pairs that share a 1 m square (a robot and any object, a ball and "
                          ++ "a ball, wall or block; counted once for each square they share), more than the "
                          ++ show maxClosePairs ++ " that a world may have (the physics and the check of overlaps "
                          ++ "compare such pairs one by one)" ]
    it "loads a file of maxObjects objects that lie apart: robots, blocks, balls and walls in a 1000 m world" $ do
      let spot k = let (gx, gy) = k `divMod` 250 in (-490 + 9.8 * fromIntegral gx, -490 + 3.9 * fromIntegral gy) :: (Double, Double)
          four k = let (x, y) = spot k
                   in concat [ "simbotA ", show k, " at ", show x, " ", show y, " heading 0.5 rad\n"
                             , "block at ", show (x + 1), " ", show y, "\n"
                             , "ball at ", show (x + 2), " ", show y, "\n"
                             , "wall v at ", show (x + 3), " ", show y, "\n" ]
          file = BC.pack ("size 1000 1000\n" ++ concatMap four [0 .. maxObjects `div` 4 - 1])
      r <- forcedSoon (parseB file)
      fmap (either Left (Right . length)) r `shouldBe` Just (Right (maxObjects + 1))
    it "has no sizes to give: a size after an object is an error at its position" $
      parseB (BC.pack "block at 0 0 size -1")
        `shouldBe` Left "h.world:1:14: expected end of line or a comment after \"0\", found \"size\""
    it "fuzz: any file, valid or broken, loads or gives an error with a position, in time" $
      withMaxSuccess 300 $ forAll genHostile $ \bytes -> ioProperty $ do
        r <- forcedSoon (parseB bytes)
        pure $ counterexample (show r)
             $ cover 10 (isRight' r) "loads"
             $ cover 30 (isLeft' r) "gives an error"
             $ case r of
          Nothing        -> False
          Just (Left e)  -> positioned e
          Just (Right _) -> True

  describe "parseWorld: objects" $ do
    it "parses a block" $
      parse1 "block at 2 -2" `shouldBe` Right (OTBlock (Point2 2 (-2)))
    it "parses a ball" $
      parse1 "ball at 0 0" `shouldBe` Right (OTBall (Point2 0 0))
    it "parses a vertical wall (v and vertical)" $ do
      parse1 "wall v at 0 3" `shouldBe` Right (OTVWall (Point2 0 3))
      parse1 "wall vertical at 0 3" `shouldBe` Right (OTVWall (Point2 0 3))
    it "parses a horizontal wall (h and horizontal)" $ do
      parse1 "wall h at -1 2.5" `shouldBe` Right (OTHWall (Point2 (-1) 2.5))
      parse1 "wall horizontal at -1 2.5" `shouldBe` Right (OTHWall (Point2 (-1) 2.5))
    it "parses a SimbotA" $
      parse1 "simbotA 1 at -2.0 -2.0 heading 45 deg"
        `shouldBe` Right (OTSimbotA 1 (Point2 (-2) (-2)) (45 * pi / 180))
    it "parses a SimbotB" $
      parse1 "simbotB 2 at 1 1 heading 1.5708 rad"
        `shouldBe` Right (OTSimbotB 2 (Point2 1 1) 1.5708)
    it "parses negative and explicitly positive robot ids" $ do
      parse1 "simbotA -7 at 0 0" `shouldBe` Right (OTSimbotA (-7) (Point2 0 0) 0)
      parse1 "simbotB +7 at 0 0" `shouldBe` Right (OTSimbotB 7 (Point2 0 0) 0)
    it "keeps the objects in the order of their lines" $
      parse "ball at 1 1\nblock at 2 2\nwall v at 3 3\n"
        `shouldBe` Right [OTBall (Point2 1 1), OTBlock (Point2 2 2), OTVWall (Point2 3 3)]
    it "parses an empty file to the empty world" $ do
      parse "" `shouldBe` Right []
      parse "\n\n" `shouldBe` Right []

  describe "parseWorld: comments and layout" $ do
    it "ignores blank lines, comment lines and trailing comments" $
      parse (unlines
        [ "# a world"
        , ""
        , "   "
        , "\t# indented comment"
        , "ball at 0 0   # the ball"
        , "block at 1 1# no space before the comment"
        ])
        `shouldBe` Right [OTBall (Point2 0 0), OTBlock (Point2 1 1)]
    it "accepts any whitespace between tokens, and CRLF line ends" $
      parse "  wall\tv   at\t1  2 \r\nball at 3 4\r\n"
        `shouldBe` Right [OTVWall (Point2 1 2), OTBall (Point2 3 4)]
    it "accepts a file without a final newline" $
      parse "ball at 0 0" `shouldBe` Right [OTBall (Point2 0 0)]

  describe "parseWorld: headings" $ do
    it "converts degrees to radians" $ do
      fmap otHdng (parse1 "simbotA 1 at 0 0 heading 90 deg") `shouldBe` Right (pi / 2)
      fmap otHdng (parse1 "simbotA 1 at 0 0 heading 180 degrees") `shouldBe` Right pi
      fmap otHdng (parse1 "simbotA 1 at 0 0 heading -45 deg") `shouldBe` Right (-(pi / 4))
    it "takes radians as they are" $ do
      fmap otHdng (parse1 "simbotB 1 at 0 0 heading 1 rad") `shouldBe` Right 1
      fmap otHdng (parse1 "simbotB 1 at 0 0 heading 0.25 radians") `shouldBe` Right 0.25
    it "distinguishes the same number in degrees and in radians" $
      fmap otHdng (parse1 "simbotA 1 at 0 0 heading 2 deg")
        `shouldNotBe` fmap otHdng (parse1 "simbotA 1 at 0 0 heading 2 rad")
    it "does not normalise headings" $
      fmap otHdng (parse1 "simbotA 1 at 0 0 heading 450 deg") `shouldBe` Right (450 * pi / 180)
    it "defaults an omitted heading to 0" $ do
      parse1 "simbotA 3 at 1 2" `shouldBe` Right (OTSimbotA 3 (Point2 1 2) 0)
      parse1 "simbotB 3 at 1 2 # facing east" `shouldBe` Right (OTSimbotB 3 (Point2 1 2) 0)

  describe "parseWorld: case-insensitivity" $
    it "accepts keywords in any case" $
      parse (unlines
        [ "SIMBOTA 1 AT 0 0 HEADING 90 DEG"
        , "SimbotB 2 At 1 1 Heading 1 Rad"
        , "simbota 3 at 2 2 heading 1 RADIANS"
        , "Wall V at 0 3"
        , "WALL Horizontal at 0 4"
        , "Block at 1 1"
        , "bAlL at 2 2"
        ])
        `shouldBe` Right
          [ OTSimbotA 1 (Point2 0 0) (pi / 2)
          , OTSimbotB 2 (Point2 1 1) 1
          , OTSimbotA 3 (Point2 2 2) 1
          , OTVWall (Point2 0 3)
          , OTHWall (Point2 0 4)
          , OTBlock (Point2 1 1)
          , OTBall (Point2 2 2)
          ]

  describe "parseWorld: numbers" $ do
    it "accepts signs, fractions and exponents" $ do
      parse1 "ball at -2 +0.5" `shouldBe` Right (OTBall (Point2 (-2) 0.5))
      parse1 "ball at 1e-3 2.5E+2" `shouldBe` Right (OTBall (Point2 1e-3 250))
      parse1 "ball at 007 -0.0" `shouldBe` Right (OTBall (Point2 7 0))
    it "reads numbers exactly (correctly rounded)" $ do
      parse1 "ball at 0.1 4.9406564584124654e-324"
        `shouldBe` Right (OTBall (Point2 0.1 5.0e-324))
      parse1 "ball at 1.7976931348623157e308 9007199254740993"
        `shouldBe` Right (OTBall (Point2 1.7976931348623157e308 9007199254740992))
    it "rounds literals too small for a Double to zero" $
      parse1 "ball at 1e-400 -1e-99999999999" `shouldBe` Right (OTBall (Point2 0 0))
    it "rejects a missing integer part or fraction" $ do
      "ball at .5 0" `failsWith` "w.world:1:9: expected a number after \"at\", found \".5\""
      "ball at 5. 0" `failsWith` "w.world:1:9: expected a number after \"at\", found \"5.\""

  describe "parseWorld: errors" $ do
    it "reports an unknown keyword" $
      "\nrobot 1 at 0 0" `failsWith`
        "w.world:2:1: expected an object keyword (simbotA, simbotB, wall, block or ball) or size, found \"robot\""
    it "reports an unknown keyword after leading whitespace" $
      "   Blocks at 0 0" `failsWith`
        "w.world:1:4: expected an object keyword (simbotA, simbotB, wall, block or ball) or size, found \"Blocks\""
    it "reports a bad wall orientation" $
      "wall d at 0 0" `failsWith`
        "w.world:1:6: expected a wall orientation (v, vertical, h or horizontal) after \"wall\", found \"d\""
    it "reports a missing \"at\"" $
      "block 1 2" `failsWith` "w.world:1:7: expected \"at\" after \"block\", found \"1\""
    it "reports a missing number at the end of the line" $
      "ball at 1.5" `failsWith` "w.world:1:12: expected a number after \"1.5\", found end of line"
    it "reports a missing number before a comment" $
      "# c\n\nball at # where?" `failsWith`
        "w.world:3:8: expected a number after \"at\", found end of line"
    it "reports a bad number (the example of the documentation)" $
      "# one\n# two\nsimbotA 1 at  x1 0" `failsWith`
        "w.world:3:15: expected a number after \"at\", found \"x1\""
    it "reports a malformed number" $ do
      "ball at 1.2.3 0" `failsWith` "w.world:1:9: expected a number after \"at\", found \"1.2.3\""
      "ball at 0 1e" `failsWith` "w.world:1:11: expected a number after \"0\", found \"1e\""
      "ball at 0x10 0" `failsWith` "w.world:1:9: expected a number after \"at\", found \"0x10\""
    it "reports a bad robot id" $ do
      "simbotA one at 0 0" `failsWith`
        "w.world:1:9: expected a robot id (an integer) after \"simbotA\", found \"one\""
      "simbotB 1.0 at 0 0" `failsWith`
        "w.world:1:9: expected a robot id (an integer) after \"simbotB\", found \"1.0\""
      "simbotB 99999999999999999999 at 0 0" `failsWith`
        "w.world:1:9: expected a robot id (an integer) after \"simbotB\", found \"99999999999999999999\" (out of range)"
    it "reports a missing heading unit" $ do
      "simbotA 1 at 0 0 heading 45" `failsWith`
        "w.world:1:28: expected a heading unit (deg, degrees, rad or radians) after \"45\", found end of line"
      "simbotA 1 at 0 0 heading 45 # degrees" `failsWith`
        "w.world:1:28: expected a heading unit (deg, degrees, rad or radians) after \"45\", found end of line"
      "simbotA 1 at 0 0 heading 45 grad" `failsWith`
        "w.world:1:29: expected a heading unit (deg, degrees, rad or radians) after \"45\", found \"grad\""
    it "reports a missing heading value" $
      "simbotA 1 at 0 0 heading deg" `failsWith`
        "w.world:1:26: expected a number after \"heading\", found \"deg\""
    it "reports trailing garbage" $ do
      "ball at 0 0 0" `failsWith`
        "w.world:1:13: expected end of line or a comment after \"0\", found \"0\""
      "wall h at 0 0 extra # comment" `failsWith`
        "w.world:1:15: expected end of line or a comment after \"0\", found \"extra\""
      "simbotA 1 at 0 0 heading 1 rad more" `failsWith`
        "w.world:1:32: expected end of line or a comment after \"rad\", found \"more\""
      "simbotA 1 at 0 0 facing 1 rad" `failsWith`
        "w.world:1:18: expected \"heading\" or end of line after \"0\", found \"facing\""
    it "reports NaN and infinities" $ do
      "ball at NaN 0" `failsWith`
        "w.world:1:9: expected a finite number after \"at\", found \"NaN\" (NaN and infinities are not allowed)"
      "ball at 0 -Infinity" `failsWith`
        "w.world:1:11: expected a finite number after \"0\", found \"-Infinity\" (NaN and infinities are not allowed)"
      "simbotA 1 at 0 0 heading inf rad" `failsWith`
        "w.world:1:26: expected a finite number after \"heading\", found \"inf\" (NaN and infinities are not allowed)"
    it "reports numbers too large for a Double" $
      "ball at 1e400 0" `failsWith`
        "w.world:1:9: expected a finite number after \"at\", found \"1e400\" (too large for a Double)"
    it "counts a tab as one column" $
      "ball\tat\tq 0" `failsWith` "w.world:1:9: expected a number after \"at\", found \"q\""
    it "reports every malformed line, in order, and nothing partial (it reported only the first)" $
      parse "ball at 0 0\nblock at 1\nwall at 2 2\nsize 10 10\nsize 20 20\n"
        `shouldBe` Left (intercalate "\n"
                       [ "w.world:2:11: expected a number after \"1\", found end of line"
                       , "w.world:3:6: expected a wall orientation (v, vertical, h or horizontal) after \"wall\", found \"at\""
                       , "w.world:5: the world's size is given twice (first on line 4)" ])
    it "lists the first maxProblems malformed lines, and stops reading at the next, saying where" $ do
      let bad = 25 + maxProblems
      case parse (concat (replicate bad "bal at 0 0\n")) of
        Left msg -> do
          length (lines msg) `shouldBe` maxProblems + 1
          last (lines msg) `shouldBe` ("... and more problems from line " ++ show (maxProblems + 1) ++ " on (the reading stopped there)")
          take 1 (lines msg) `shouldBe` ["w.world:1:1: expected an object keyword (simbotA, simbotB, wall, block or ball) or size, found \"bal\""]
        Right _ -> expectationFailure "parsed"
    it "says too many objects after the faults before them, however many (it was only counted)" $
      case parse (concat (replicate maxProblems "bal at 0 0\n") ++ concat (replicate (maxObjects + 1) "ball at 0 0\n")) of
        Left msg -> do
          length (lines msg) `shouldBe` maxProblems + 1
          last (lines msg) `shouldBe` ("w.world:" ++ show (maxProblems + maxObjects + 1) ++ ": too many objects (at most "
                                       ++ show maxObjects ++ ")")
        Right _ -> expectationFailure "parsed"
    it "uses the given file name" $
      parseWorld "dir/my.world" "bal at 0 0" `shouldSatisfy` either ("dir/my.world:1:1: " `isPrefixOf`) (const False)

  describe "renderWorld" $ do
    it "starts with a header comment and prints one object per line" $ do
      let w = [OTVWall (Point2 0 3), OTSimbotB 2 (Point2 1 (-1)) 0.5, OTBall (Point2 0 0)]
          ls = lines (renderWorld w)
      length ls `shouldBe` 4
      take 1 ls `shouldSatisfy` all ("#" `isPrefixOf`)
      drop 1 ls `shouldBe`
        [ "wall v at 0.0 3.0", "simbotB 2 at 1.0 -1.0 heading 0.5 rad", "ball at 0.0 0.0" ]
    it "renders the empty world as a comment only" $
      parse (renderWorld []) `shouldBe` Right []
    it "round-trips every finite world (headings within maxHeading) exactly" $
      withMaxSuccess 500 $ \(AWorld w) -> parseWorld "r.world" (renderWorld w) === Right w
    it "round-trips signed zeros" $
      fmap (map otPos) (parse (renderWorld [OTBall (Point2 (-0.0) 0)]))
        `shouldSatisfy` either (const False)
                               (\ps -> [ isNegativeZero x | Point2 x _ <- ps ] == [True])

  describe "readWorldFile" $ do
    it "reports a missing file as a Left naming it" $ do
      r <- readWorldFile "worlds/no-such-file.world"
      r `shouldBe` Left "worlds/no-such-file.world: cannot read it: does not exist (No such file or directory)"
    it "reports a directory as a Left, not an exception" $ do
      r <- readWorldFile "worlds"
      r `shouldBe` Left "worlds: cannot read it: inappropriate type (is a directory)"
    it "reads at most maxFileBytes: a longer file, or an endless one, is a Left naming it" $ withTempDir $ \tmp -> do
      let file = tmp </> "afrp-long.world"
          line = BC.pack "# a comment line of a world file that is far too long\n"
      B.writeFile file (B.concat (replicate (maxFileBytes `div` B.length line + 1) line))
      r <- readWorldFile file
      r `shouldSatisfy` either ((file ++ ": more than") `isPrefixOf`) (const False)
      z <- timeout 10000000 (readWorldFile "/dev/zero")
      z `shouldSatisfy` maybe False (either ("/dev/zero: more than" `isPrefixOf`) (const False))
    it "reads a named pipe (FIFO) from its writer, waiting for one to open it (not as an empty world)" $
      withTempDir $ \dir -> do
        let fifo = dir </> "w.fifo"
        createNamedPipe fifo 0o600
        _ <- forkIO (threadDelay 300000 >> writeFile fifo "ball at 1 2\nsimbota 1 at 0 0 heading 0 rad\n")
        r <- timeout 20000000 (readWorldFile fifo)
        r `shouldBe` Just (Right [OTBall (Point2 1 2), OTSimbotA 1 (Point2 0 0) 0])
    it "a reader waiting for a FIFO's writer can be stopped (timeout, Ctrl-C), and stops waiting" $
      withTempDir $ \dir -> do
        let fifo = dir </> "w.fifo"
        createNamedPipe fifo 0o600
        timeout 300000 (readWorldFile fifo) `shouldReturn` Nothing
        -- (the abandoned open is closed once a writer comes: the writer
        -- does not wait forever for a reader)
        done <- timeout 20000000 (writeFile fifo "")
        done `shouldBe` Just ()
    it "reports syntax errors with the file's path" $ withTempDir $ \tmp -> do
      let file = tmp </> "afrp-bad-syntax.world"
      writeFile file "# a comment\nball at 0 0\nrobot at 1 1\n"
      r <- readWorldFile file
      r `shouldSatisfy` either ((file ++ ":3:1: expected an object keyword") `isPrefixOf`) (const False)

  describe "file names in messages" $
    it "readWorldFile: a file that cannot be read, or does not parse, is named with its controls escaped" $
      withTempDir $ \dir -> do
        r <- readWorldFile "no\ESC[31msuch\nfile"
        r `shouldSatisfy` either (\m -> all isPrint m && "\\ESC[31msuch\\nfile" `isInfixOf` m) (const False)
        let bad = dir </> "bad\ESC[1mworld"
        writeFile bad "block 1\n"
        r2 <- readWorldFile bad
        r2 `shouldSatisfy` either (\m -> all (\c -> isPrint c || c == '\n') m && "\\ESC[1mworld" `isInfixOf` m) (const False)

  describe "the example worlds" $ do
    mapM_ exampleWorld exampleFiles
    it "worlds/big.world is 100 m by 100 m with 100 robots of each type" $ do
      r <- readWorldFile "worlds/big.world"
      case r of
        Left e  -> expectationFailure e
        Right w -> do
          worldSize w `shouldBe` Just (100, 100)
          length [ () | OTSimbotA {} <- w ] `shouldBe` 100
          length [ () | OTSimbotB {} <- w ] `shouldBe` 100
    it "worlds/arena.world has three robots of each type" $ do
      r <- readWorldFile "worlds/arena.world"
      case r of
        Left e  -> expectationFailure e
        Right w -> do
          length [ () | OTSimbotA {} <- w ] `shouldBe` 3
          length [ () | OTSimbotB {} <- w ] `shouldBe` 3
  where
    exampleWorld path = describe path $ do
      it "parses, passes validateWorld and round-trips" $ do
        r <- readWorldFile path
        case r of
          Left e  -> expectationFailure e
          Right w -> do
            validateWorld w `shouldBe` Right ()
            parseWorld path (renderWorld w) `shouldBe` Right w
      it "has no two objects overlapping" $ do
        r <- readWorldFile path
        case r of
          Left e  -> expectationFailure e
          Right w ->
            [ (objectName a, objectName b) | (a : rest) <- tails (filter placedObject w), b <- rest
                                           , boxesOverlap a b ]
              `shouldBe` []
