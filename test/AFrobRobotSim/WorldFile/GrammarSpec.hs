-- | The grammar of one line ("AFrobRobotSim.WorldFile.Grammar"), on the
-- tokens of a line rather than through a file: the column and reason of
-- every way a complete line can stop too soon or run on, columns taken
-- from the tokens as given, the bounds of a heading, and random lines
-- checked against a reference written as patterns over the words. The
-- file's side (line numbers, limits, one size line, the world checked)
-- is "AFrobRobotSim.WorldFileSpec"'s.
module AFrobRobotSim.WorldFile.GrammarSpec (spec) where

import           Data.List                       (isInfixOf, isPrefixOf, isSuffixOf)
import           Test.Hspec
import           Test.QuickCheck                 hiding (Failure)

import           AFRP.Geometry                   (Point2 (..))
import           AFrobRobotSim.World             (ObjectTemplate (..))
import           AFrobRobotSim.WorldFile.Grammar
import           AFrobRobotSim.WorldFile.Lexical (Tok (..), lower, readNumber, robotId, tokEnd,
                                                  tokenize)

-- | 'parseLine' with its 'Failure' as a pair, to compare and show.
parseToks :: [Tok] -> Either (Int, String) (Maybe ObjectTemplate)
parseToks = either (\(Failure c m) -> Left (c, m)) Right . parseLine

-- | 'parseToks' on the tokens of a text.
parseText :: String -> Either (Int, String) (Maybe ObjectTemplate)
parseText = parseToks . tokenize

-- | Complete lines, and for each of their proper prefixes (by number of
-- tokens) that is not complete itself, what the rejection expects next.
completeLines :: [(String, [(Int, String)])]
completeLines =
  [ ("simbotA 7 at 1 2 heading 90 deg"
    , [ (1, "a robot id (an integer)"), (2, "\"at\""), (3, number), (4, number), (6, number)
      , (7, unit) ])
  , ("SIMBOTB -3 AT 0 0", [ (1, "a robot id (an integer)"), (2, "\"at\""), (3, number), (4, number) ])
  , ("wall horizontal at -1 2.5"
    , [ (1, "a wall orientation (v, vertical, h or horizontal)"), (2, "\"at\""), (3, number)
      , (4, number) ])
  , ("block at 0 0", [ (1, "\"at\""), (2, number), (3, number) ])
  , ("ball at 0 0", [ (1, "\"at\""), (2, number), (3, number) ])
  , ("size 10 20", [ (1, side), (2, side) ])
  ]
  where
    number = "a number"
    unit   = "a heading unit (deg, degrees, rad or radians)"
    side   = "a world side from 1 to 1000 metres"

-- | The reference: a line's words matched against the grammar's rules
-- written out as patterns, the literals read by the lexical layer.
reference :: [String] -> Maybe ObjectTemplate
reference ws = case map lower ws of
  ["size", a, b]                      -> OTSize <$> sideOf a <*> sideOf b
  ["wall", o, "at", x, y]
    | o `elem` ["v", "vertical"]      -> OTVWall <$> pointOf x y
    | o `elem` ["h", "horizontal"]    -> OTHWall <$> pointOf x y
  ["block", "at", x, y]               -> OTBlock <$> pointOf x y
  ["ball", "at", x, y]                -> OTBall <$> pointOf x y
  [k, i, "at", x, y]                  -> robotOf k i x y (Just 0)
  [k, i, "at", x, y, "heading", h, u] -> robotOf k i x y (headingOf h u)
  _                                   -> Nothing
  where
    num = either (const Nothing) Just . readNumber
    pointOf x y = Point2 <$> num x <*> num y
    sideOf t = num t >>= \v -> if v >= 1 && v <= 1000 then Just v else Nothing
    robotOf k i x y mh = do
      mk <- lookup k [("simbota", OTSimbotA), ("simbotb", OTSimbotB)]
      n  <- either (const Nothing) Just (robotId i)
      mk n <$> pointOf x y <*> mh
    headingOf h u = do
      v <- num h
      f <- lookup u [ ("deg", \d -> d * pi / 180), ("degrees", \d -> d * pi / 180)
                    , ("rad", id), ("radians", id) ]
      if abs v <= 1e6 then Just (f v) else Nothing

-- | The words of a line: a line of one of the rules, its literals mostly
-- good, then, half of the time, one or two tokens dropped, inserted or
-- replaced by others of the format's vocabulary.
genWords :: Gen [String]
genWords = do
  base <- oneof
    [ (\k i a (x, y) -> [k, i, a, x, y]) <$> elements ["simbotA", "SimbotB"] <*> anId <*> at <*> point
    , (\k i a (x, y) hk h u -> [k, i, a, x, y, hk, h, u])
        <$> elements ["simbota", "simbotB"] <*> anId <*> at <*> point
        <*> elements ["heading", "Heading"] <*> aHeading <*> aUnit
    , (\o a (x, y) -> ["wall", o, a, x, y])
        <$> mostly ["v", "H", "vertical", "Horizontal"] ["d", "at"] <*> at <*> point
    , (\k a (x, y) -> [k, a, x, y]) <$> elements ["block", "BALL", "Wall", "SIZE"] <*> at <*> point
    , (\a b -> ["size", a, b]) <$> aSide <*> aSide
    ]
  k <- frequency [(1, pure (0 :: Int)), (1, choose (1, 2))]
  mutate k base
  where
    mostly good bad = frequency [(9, elements good), (1, elements bad)]
    at       = elements ["at", "AT"]
    anId     = mostly ["1", "-3", "+7", "0"] ["1.0", "99999999999999999999", "one"]
    aNumber  = mostly ["0", "-2.5", "1", "1000", "1e-3", "+0.5"] ["1e400", "NaN", "x", ".5"]
    point    = (,) <$> aNumber <*> aNumber
    aSide    = mostly ["1", "1000", "12.5", "1e2"] ["0.99", "1000.5", "-5", "inf"]
    aHeading = mostly ["90", "-1e6", "1000000", "0.25"] ["1000000.5", "-2e6", "Infinity"]
    aUnit    = mostly ["deg", "DEGREES", "rad", "radians"] ["grad"]
    vocab    = [ "simbotA", "simbotB", "wall", "v", "h", "block", "ball", "size", "at", "heading"
               , "deg", "rad", "0", "7", "x" ]
    mutate :: Int -> [String] -> Gen [String]
    mutate 0 ws = pure ws
    mutate n ws = do
      i <- choose (0, length ws)
      w <- elements vocab
      ws' <- elements [ take i ws ++ drop (i + 1) ws, take i ws ++ [w] ++ drop i ws
                      , take i ws ++ [w] ++ drop (i + 1) ws ]
      mutate (n - 1) ws'

-- | Words laid out as a line, one to three spaces or tabs before each.
genLine :: [String] -> Gen String
genLine ws = concat <$> mapM (\w -> (++ w) <$> (choose (1, 3) >>= \n -> vectorOf n (elements " \t"))) ws

spec :: Spec
spec = do
  it "gives Nothing for a line without tokens, and only for one (fixed)" $ do
    parseToks [] `shouldBe` Right Nothing
    parseText "   # only a comment" `shouldBe` Right Nothing
    parseText "ball at 0 0 # and a comment" `shouldBe` Right (Just (OTBall (Point2 0 0)))

  it "stops every incomplete prefix of a line just after its last token, saying what comes next (fixed)" $
    sequence_
      [ (prefix, parseToks ts) `shouldBe`
          (prefix, Left (tokEnd lastTok, "expected " ++ what ++ " after \"" ++ lastText ++ "\", found end of line"))
      | (line, cuts) <- completeLines
      , let toks = tokenize line
      , (n, what) <- cuts
      , let ts = take n toks
            prefix = unwords [ t | Tok _ t <- ts ]
            lastTok@(Tok _ lastText) = last ts ]

  it "accepts each complete line, and rejects one more token at that token's column (fixed)" $
    sequence_ $ concat
      [ [ (line, fmap (fmap (const ())) (parseText line)) `shouldBe` (line, Right (Just ()))
        , (line ++ " extra", parseText (line ++ " extra")) `shouldBe`
            (line ++ " extra", Left (length line + 2, "expected " ++ next ++ " after \"" ++ lastWord
                                                       ++ "\", found \"extra\""))
        ]
      | (line, _) <- completeLines ++ [("simbotB 2 at 1 1 heading 1 rad", [])]
      , let lastWord = last (words line)
            next | length (words line) == 5 && "simbot" `isPrefixOf` lower line = "\"heading\" or end of line"
                 | otherwise = "end of line or a comment" ]

  it "reports the columns of the tokens it is given, not of any text (fixed)" $ do
    parseToks [Tok 5 "ball", Tok 12 "at", Tok 20 "0", Tok 30 "q"]
      `shouldBe` Left (30, "expected a number after \"0\", found \"q\"")
    parseToks [Tok 5 "ball", Tok 12 "at", Tok 20 "0.25"]
      `shouldBe` Left (24, "expected a number after \"0.25\", found end of line")
    parseToks [Tok 3 "Wall", Tok 40 "V", Tok 41 "AT", Tok 50 "1", Tok 60 "2"]
      `shouldBe` Right (Just (OTVWall (Point2 1 2)))

  it "accepts a heading up to maxHeading in magnitude, in either unit, and no further (fixed)" $ do
    maxHeading `shouldBe` 1e6
    parseText "simbotA 1 at 0 0 heading 1000000 deg"
      `shouldBe` Right (Just (OTSimbotA 1 (Point2 0 0) (1e6 * pi / 180)))
    parseText "simbotB 1 at 0 0 heading -1e6 radians"
      `shouldBe` Right (Just (OTSimbotB 1 (Point2 0 0) (-1e6)))
    parseText "simbotA 1 at 0 0 heading 1000000.5 deg"
      `shouldBe` Left (26, "expected a heading within +-1000000 after \"heading\", found \"1000000.5\" (out of range)")

  it "accepts exactly the lines the reference accepts, with the same object (property)" $
    withMaxSuccess 2000 $ forAll genWords $ \ws -> forAll (genLine ws) $ \l ->
      let expected = reference ws
      in cover 25 (expected /= Nothing) "accepted" $
         cover 25 (expected == Nothing) "rejected" $
         counterexample l $
         either (const Nothing) id (parseText l) === expected

  it "rejects at a token it quotes, or just after the last one at the end of the line (property)" $
    withMaxSuccess 2000 $ forAll genWords $ \ws -> forAll (genLine ws) $ \l ->
      let ts = tokenize l
      in counterexample l $ case parseToks ts of
        Right _ -> property True
        Left (c, m) -> counterexample m $
          "expected " `isPrefixOf` m
          && (or [ c == col && ("found " ++ show t) `isInfixOf` m | Tok col t <- ts ]
              || (c == tokEnd (last ts) && "found end of line" `isSuffixOf` m))
