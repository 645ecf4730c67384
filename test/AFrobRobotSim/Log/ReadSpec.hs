-- | A run log read back ("AFrobRobotSim.Log.Read"): the log of a real run
-- (the fixture) exactly, and each fault refused with its line, column
-- and reason; files read as world files are, at most so many bytes.
module AFrobRobotSim.Log.ReadSpec (spec) where

import qualified Data.ByteString          as BS
import qualified Data.ByteString.Char8    as BC
import           Control.Monad            (forM_)
import           Data.Char                (isDigit, isPrint)
import           Data.List                (isInfixOf, isPrefixOf, isSuffixOf, stripPrefix)
import           System.Directory         (getTemporaryDirectory, removeFile)
import           System.FilePath          ((</>))
import           System.IO                (hClose, openTempFile)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.Log
import           AFrobRobotSim.JSONSpec   (utf8)
import           AFrobRobotSim.LogFixture
import           TestUtil                 (withTempDir)

spec :: Spec
spec = do
  it "reads back exactly the log of a real run (fixed)" $
    readLog fixtureLogText `shouldBe` Right fixtureLog
  it "keeps the hostile message intact on one line (fixed)" $ do
    length (lines fixtureLogText) `shouldBe` 53
    fixtureLogText `shouldNotSatisfy` ("</script" `isInfixOf`)
  it "refuses another version, saying which (fixed)" $ do
    let h = (rlHeader fixtureLog) { lhVersion = 2 }
        txt = unlines (encodeLogLine (LineHeader h) : drop 1 (lines fixtureLogText))
    readLog txt `shouldSatisfy` either ("version 2" `isInfixOf`) (const False)
  it "refuses a log that is not one, or a broken line, with its line number (fixed)" $ do
    readLog "" `shouldSatisfy` either ("line 1" `isInfixOf`) (const False)
    readLog (unlines (take 3 (lines fixtureLogText) ++ ["{\"kind\": \"frame\""]))
      `shouldSatisfy` either ("line 4, column 17:" `isPrefixOf`) (const False)
  it "asks whether a text is a run log when its first line is no header, and only then" $ do
    let hint = " (is it a run log? a run writes one with --log FILE.jsonl)"
        ls = lines fixtureLogText
    readLog "# a README\n" `shouldBe` Left ("line 1, column 1: expected a JSON value, found '#'" ++ hint)
    readLog "{\"a\": 1}\n" `shouldSatisfy` either (\e -> hint `isSuffixOf` e && "line 1: " `isPrefixOf` e) (const False)
    readLog (unlines (drop 1 ls)) `shouldBe` Left ("line 1: expected the header line first" ++ hint)
    readLog (unlines (take 3 ls ++ ["{\"kind\": \"frame\""]))
      `shouldSatisfy` either (not . (hint `isSuffixOf`)) (const False)
  it "refuses a frame whose robots are not the header's, and a header whose dt or fps is not positive" $ do
    let ls = lines fixtureLogText
        h = rlHeader fixtureLog
        f = head (rlFrames fixtureLog)
        withFrame f' = unlines (take 2 ls ++ [encodeLogLine (LineFrame f')] ++ drop 2 ls)
        withHeader h' = unlines (encodeLogLine (LineHeader h') : drop 1 ls)
    length (lfRobots f) `shouldBe` length (lhRobots h)
    readLog (withFrame f { lfRobots = drop 1 (lfRobots f) })
      `shouldSatisfy` either ("line 3: a frame of" `isPrefixOf`) (const False)
    readLog (withFrame f { lfRobots = lfRobots f ++ lfRobots f })
      `shouldSatisfy` either ("line 3: a frame of" `isPrefixOf`) (const False)
    readLog (withHeader h { lhFps = 0 }) `shouldSatisfy` either ("fps" `isInfixOf`) (const False)
    readLog (withHeader h { lhDt = -1 }) `shouldSatisfy` either ("dt" `isInfixOf`) (const False)
    readLog (withHeader h { lhDt = 0 / 0 }) `shouldSatisfy` either ("dt" `isInfixOf`) (const False)
  it "refuses frames out of time order, a negative time, a robot or ball at no number, and bounds of no area" $ do
    let ls = lines fixtureLogText
        h = rlHeader fixtureLog
        f = head (rlFrames fixtureLog)
        r = head (lfRobots f)
        withFrame f' = unlines (take 2 ls ++ [encodeLogLine (LineFrame f')] ++ drop 2 ls)
        withHeader h' = unlines (encodeLogLine (LineHeader h') : drop 1 ls)
        refused what = either (what `isInfixOf`) (const False)
    length (rlFrames fixtureLog) `shouldSatisfy` (> 2)
    -- (a copy of the first frame, at 1000 s, before the second)
    readLog (withFrame f { lfTime = 1000 })
      `shouldSatisfy` refused "line 4: a frame at t = 4.0e-2 s, before the one above it (1000.0 s)"
    readLog (withFrame f { lfTime = -5 }) `shouldSatisfy` refused "line 3: a frame's time must not be negative"
    -- (frames at one time, as after a step of 0, are in order)
    readLog (withFrame f) `shouldSatisfy` either (const False) (const True)
    -- (1e999 is read as infinity)
    readLog (unlines (take 2 ls ++ [setFirst "\"x\":" "1e999" (ls !! 1)] ++ drop 2 ls))
      `shouldSatisfy` refused "robot 1 of the frame at t = 0.0 s: its x, y and heading must be numbers"
    readLog (withFrame f { lfRobots = r { lrHeading = 0 / 0 } : drop 1 (lfRobots f) })
      `shouldSatisfy` refused "robot 1 of the frame at t = 0.0 s"
    readLog (withFrame f { lfBalls = [(0, 1 / 0)] }) `shouldSatisfy` refused "ball 1 of the frame at t = 0.0 s"
    readLog (withHeader h { lhBounds = (lhBounds h) { rectWidth = 0 } }) `shouldSatisfy` refused "positive width and height"
    readLog (withHeader h { lhBounds = (lhBounds h) { rectHeight = -3 } }) `shouldSatisfy` refused "positive width and height"
  it "refuses a frame time or a summary time written as null (the page could not draw it)" $ do
    let ls = lines fixtureLogText
        f = head (rlFrames fixtureLog)
        withFrame f' = unlines (take 2 ls ++ [encodeLogLine (LineFrame f')] ++ drop 2 ls)
        withSummary s' = unlines (init ls ++ [encodeLogLine (LineSummary s')])
    readLog (withFrame f { lfTime = 0 / 0 }) `shouldSatisfy` either ("a frame's time must be a number" `isInfixOf`) (const False)
    case rlSummary fixtureLog of
      Nothing -> expectationFailure "the fixture log has no summary"
      Just sm -> do
        readLog (withSummary sm { lsSimulated = 0 / 0 }) `shouldSatisfy` either ("summary's simulated" `isInfixOf`) (const False)
        readLog (withSummary sm) `shouldSatisfy` either (const False) (const True)
  it "reads back a summary's falsified (a test's property decided false: its instant and line), written only when there is one; a null instant refused" $ do
    let ls = lines fixtureLogText
        withSummary s' = unlines (init ls ++ [encodeLogLine (LineSummary s')])
    case rlSummary fixtureLog of
      Nothing -> expectationFailure "the fixture log has no summary"
      Just sm -> do
        let decided = sm { lsFalsified = Just (4.01, "decided false at t = 4.01 (step 401)") }
        encodeLogLine (LineSummary decided)
          `shouldSatisfy` (",\"falsified\":{\"t\":4.01,\"text\":\"decided false at t = 4.01 (step 401)\"}," `isInfixOf`)
        fmap rlSummary (readLog (withSummary decided)) `shouldBe` Right (Just decided)
        encodeLogLine (LineSummary sm) `shouldNotSatisfy` ("falsified" `isInfixOf`)
        readLog (withSummary decided { lsFalsified = Just (0 / 0, "never") })
          `shouldSatisfy` either ("the summary's falsified time must be a number" `isInfixOf`) (const False)
  it "readLogFile locates an error as FILE:LINE:COLUMN: or FILE:LINE:, like a world file" $ do
    tmp <- getTemporaryDirectory
    (path, h) <- openTempFile tmp "afrp-log.jsonl"
    hClose h
    let ls = lines fixtureLogText
    writeFile path (unlines (take 3 ls ++ ["{\"kind\": \"frame\""]))
    r1 <- readLogFile path
    writeFile path (unlines (take 3 ls ++ [head ls]))
    r2 <- readLogFile path
    removeFile path
    fmap (const ()) r1 `shouldBe` Left (path ++ ":4:17: expected ',' or '}', found end of input")
    fmap (const ()) r2 `shouldBe` Left (path ++ ":4: a second header")
  it "readLogFile refuses a header line, or a line after the summary, that is not UTF-8 with the UTF-8 message alone (fixed)" $
    withTempDir $ \dir -> do
      let path = dir </> "run.jsonl"
          bad = BS.pack [0x7b, 0x22, 0xff]   -- {"<0xff>
          utf8Fault c = Left (path ++ c ++ ": invalid UTF-8 (byte 0xff)")
      -- (a header line: no hint that the file may be no log, whether a
      -- newline ends it or not)
      BS.writeFile path (BS.concat [bad, BC.pack ("\n" ++ unlines (drop 1 (lines fixtureLogText)))])
      fmap (const ()) <$> readLogFile path `shouldReturn` utf8Fault ":1:3"
      BS.writeFile path bad
      fmap (const ()) <$> readLogFile path `shouldReturn` utf8Fault ":1:3"
      -- (after the summary, line 53: the fault, not the line's being there)
      BS.writeFile path (BS.concat [BC.pack fixtureLogText, BS.pack [0x20, 0x20, 0xff, 0x0a]])
      fmap (const ()) <$> readLogFile path `shouldReturn` utf8Fault ":54:3"
  it "readLogFile names a log with control characters in its name escaped, whatever the fault" $ withTempDir $ \dir -> do
    let bad = dir </> "bad\ESC[1mlog\n.jsonl"
    writeFile bad "{\"bad\"\n"
    r1 <- readLogFile bad
    r2 <- readLogFile (dir </> "no\ESC[31msuch.jsonl")
    writeFile bad (replicate 300 'x')
    r3 <- readLogFileUpTo 200 bad
    let printable = either (\m -> all isPrint m && "\\ESC[" `isInfixOf` m) (const False)
    r1 `shouldSatisfy` printable
    r2 `shouldSatisfy` printable
    r3 `shouldSatisfy` printable
  it "readLogFile reads at most so many bytes, and says so of a longer or endless file" $ withTempDir $ \dir -> do
    let path = dir </> "run.jsonl"
    writeFile path (replicate 300 'x')
    r <- readLogFileUpTo 200 path
    r `shouldSatisfy` either ((path ++ ": more than 200 bytes") `isPrefixOf`) (const False)
    z <- readLogFileUpTo 1000 "/dev/zero"
    z `shouldSatisfy` either ("/dev/zero: more than 1000 bytes" `isPrefixOf`) (const False)
    -- an endless line is refused at its limit, not read to the file's
    z' <- readLogFile "/dev/zero"
    fmap (const ()) z' `shouldBe` Left ("/dev/zero:1: a line of more than " ++ show maxLogLineBytes
                                        ++ " bytes, more than this reader takes (a frame of 100,000 robots is about 38 MB; is it a run log?)")
    -- within the limit, the file is read as a log (here: not one)
    s <- readLogFileUpTo 400 path
    s `shouldSatisfy` either (not . ("more than" `isInfixOf`)) (const False)
  it "readLogFile reads a log's bytes as readLog reads its text: the same log, or the same error (property)" $
    -- (the file's lines are parsed as bytes, the text's as a String)
    withMaxSuccess 300 $ forAll brokenLog $ \txt -> ioProperty $ withTempDir $ \dir -> do
      let path = dir </> "run.jsonl"
      BS.writeFile path (utf8 txt)
      r <- readLogFile path
      n <- foldLogFile path (\h -> pure (h, [])) (\(h, fs) f -> pure (h, f : fs))
      let expected = either (Left . asFileError path) Right (readLog txt)
          folded = fmap (\((h, fs), LogEnd sm cut) -> RunLog h (reverse fs) sm cut) n
      -- (shown: a number read as null, NaN, is not equal to itself)
      pure (counterexample txt (show r === show expected .&&. show folded === show expected))
  it "readLogFile says which file it cannot read and why, not which Haskell function failed" $ do
    r <- readLogFile "no-such-dir/run.jsonl"
    fmap (const ()) r `shouldBe` Left "no-such-dir/run.jsonl: cannot read it: does not exist (No such file or directory)"
  it "foldLogFile gives the header, then each frame in order, and returns the summary; a line of more than 64 MiB is refused" $
    withTempDir $ \dir -> do
      let path = dir </> "run.jsonl"
      writeFile path fixtureLogText
      r <- foldLogFile path (\h -> pure (h, [])) (\(h, ts) f -> pure (h, lfTime f : ts))
      fmap (\((h, ts), end) -> (h, reverse ts, end)) r
        `shouldBe` Right (rlHeader fixtureLog, map lfTime (rlFrames fixtureLog), LogEnd (rlSummary fixtureLog) Nothing)
      -- a frame line just over the limit, after the header
      -- (written as bytes: 64 MiB of a String took most of this test's time)
      let withBlankLine n = BS.writeFile path (BC.unlines [BC.pack (head (lines fixtureLogText)), BC.replicate n ' '])
      withBlankLine (maxLogLineBytes + 1)
      r' <- foldLogFile path (const (pure ())) (\_ _ -> pure ())
      fmap (const ()) r' `shouldBe` Left (path ++ ":2: a line of more than 67108864 bytes, more than this reader takes"
                                          ++ " (a frame of 100,000 robots is about 38 MB; is it a run log?)")
      -- and one at the limit is read (here: blank, so skipped)
      withBlankLine maxLogLineBytes
      r'' <- foldLogFile path (const (pure ())) (\_ _ -> pure ())
      fmap (const ()) r'' `shouldBe` Right ()
  it "reads a log cut short (no summary) (fixed)" $
    fmap rlSummary (readLog (unlines (take 10 (lines fixtureLogText)))) `shouldBe` Right Nothing
  describe "a log whose last line stops in its middle (a full disk's)" $ do
    let ls = lines fixtureLogText
        -- ten whole lines (the header and nine frames), then the first
        -- half of the eleventh, with no newline after it
        cut = unlines (take 10 ls) ++ take (length (ls !! 10) `div` 2) (ls !! 10)
        whole10 = readLog (unlines (take 10 ls))
    it "reads as its whole lines, with no summary, and gives the cut line's number" $ do
      fmap rlCutLine whole10 `shouldBe` Right Nothing
      readLog cut `shouldBe` fmap (\l -> l { rlCutLine = Just 11 }) whole10
      fmap (length . rlFrames) (readLog cut) `shouldBe` Right 9
    it "loses only the summary when the summary's line is the one cut" $ do
      let cutSummary = take (length fixtureLogText - 20) fixtureLogText   -- (the summary line is longer)
      readLog cutSummary `shouldBe` Right fixtureLog { rlSummary = Nothing, rlCutLine = Just 53 }
    it "reads a whole last line without a newline as a line, not as cut" $
      readLog (init fixtureLogText) `shouldBe` Right fixtureLog
    it "refuses a last line with no newline that is not JSON cut short: a fault before its end, whole JSON, no log line" $ do
      let refusedAt11 lastLine = readLog (unlines (take 10 ls) ++ lastLine)
            `shouldSatisfy` either ("line 11" `isPrefixOf`) (const False)
      mapM_ refusedAt11
        [ "{\"kind\":\"frmae\"}", "{\"a\": 1}", "[1,2,3]", "{\"kind\":\"frame\",\"t\":9}", "hello world"
        , ls !! 10 ++ "}", "{\"kind\" \"frame\", \"t\": 0.4" ]
    it "refuses a broken last line that a newline ends, and a whole one that is wrong" $ do
      readLog (cut ++ "\n") `shouldSatisfy` either ("line 11, column " `isPrefixOf`) (const False)
      -- (a whole frame with a robot at x = infinity, with no newline: a
      -- fault, not a cut)
      readLog (unlines (take 10 ls) ++ setFirst "\"x\":" "1e999" (ls !! 10))
        `shouldSatisfy` either ("line 11: robot 1 of the frame" `isPrefixOf`) (const False)
    it "refuses a log cut in its header, saying that the line stops with no newline" $ do
      readLog (take 30 fixtureLogText) `shouldSatisfy`
        either ("(the line stops with no newline after it: did the run that wrote the log stop as it began, or its disk fill up?)" `isSuffixOf`)
               (const False)
      -- (a first line with a fault before its end is no log's header cut short)
      readLog "# a README" `shouldSatisfy` either ("(is it a run log? a run writes one with --log FILE.jsonl)" `isSuffixOf`)
                                                  (const False)
    it "is read so from a file too (readLogFile, foldLogFile); a line that is not UTF-8 is refused (a log is ASCII)" $ withTempDir $ \dir -> do
      let path = dir </> "cut.jsonl"
      writeFile path cut
      readLogFile path `shouldReturn` readLog cut
      r <- foldLogFile path (const (pure (0 :: Int))) (\n _ -> pure (n + 1))
      r `shouldBe` Right (9, LogEnd Nothing (Just 11))
      -- (a last line with a byte that is not UTF-8, with or without a
      -- newline after it)
      BS.writeFile path (BS.append (BC.pack (unlines (take 10 ls) ++ "{\"kind\":\"frame\",\"msg\":\"")) (BS.pack [0xc3]))
      fmap rlCutLine <$> readLogFile path `shouldReturn` Left (path ++ ":11:24: invalid UTF-8 (byte 0xc3)")
      BS.writeFile path (BS.append (BC.pack (unlines (take 10 ls) ++ "{\"kind\":\"frame\",\"msg\":\"")) (BS.pack [0xc3, 0x0a]))
      fmap rlCutLine <$> readLogFile path `shouldReturn` Left (path ++ ":11:24: invalid UTF-8 (byte 0xc3)")
      -- (a fault before the end of a last line with no newline: refused)
      writeFile path (unlines (take 10 ls) ++ "{\"kind\":\"frmae\"}")
      fmap rlCutLine <$> readLogFile path `shouldReturn` Left (path ++ ":11: unknown kind of line \"frmae\"")
    it "takes every proper prefix of every line of a real log as cut, as the line after the header" $
      -- (the header's prefixes are the cut header's, refused with that said)
      forM_ (zip [1 :: Int ..] ls) $ \(i, l) -> forM_ [1 .. length l - 1] $ \k ->
        if i == 1
          then readLog (take k l) `shouldSatisfy` either ("or its disk fill up?)" `isSuffixOf`) (const False)
          else fmap rlCutLine (readLog (head ls ++ "\n" ++ take k l)) `shouldBe` Right (Just 2)

-- The fixture log with faults made in it, or none: a line cut short (the
-- log ending there, or going on), a character put in, taken out or put
-- for another (characters of JSON, control characters, characters
-- outside ASCII), a newline taken out or put in, blank lines put in; and
-- lines given a first member whose name is not ASCII.
brokenLog :: Gen String
brokenLog = do
  let ls = lines fixtureLogText
  faults <- choose (0, 3 :: Int)
  ls' <- foldr (=<<) (pure ls) (replicate faults breakOne)
  end <- elements ["\n", "\n", ""]
  pure (concatMap (++ "\n") (init' ls') ++ concat (lastOf ls') ++ if null ls' then "" else end)
  where
    init' xs = if null xs then [] else init xs
    lastOf xs = [ last xs | not (null xs) ]
    breakOne ls = do
      i <- choose (0, length ls - 1)
      let l = ls !! i
      k <- choose (0, length l)
      c <- elements [ "{", "}", "[", "]", ",", ":", "\"", "\\", "-", ".", "0", "9", "e", " ", "\t", "\r", "\0", "\233"
                    , "\x1F600", "null", "1e999", "\"x\":1,", "\n", "  \n \n" ]
      l' <- oneof [ pure (take k l), pure (take k l ++ c ++ drop k l), pure (take k l ++ drop (k + 1) l)
                  , (\m -> take k l ++ c ++ drop (k + m) l) <$> choose (1, 4) ]
      -- (a member first whose name is not ASCII: a fault after it is
      -- at a column of characters, not bytes)
      let wide = "{\"\233\x1F600\":0," ++ drop 1 l
      how <- choose (0, 4 :: Int)
      pure (case how of
              0 -> take i ls ++ [take k l]
              1 -> take i ls ++ [wide] ++ drop (i + 1) ls
              _ -> take i ls ++ [l'] ++ drop (i + 1) ls)

-- An error of 'readLog' (@line L, column C: ...@ or @line L: ...@) as
-- 'readLogFile' of a file of the same text says it.
asFileError :: FilePath -> String -> String
asFileError path e = case span isDigit <$> stripPrefix "line " e of
  Just (l@(_ : _), ',' : ' ' : rest)
    | Just (c@(_ : _), ':' : ' ' : msg) <- span isDigit <$> stripPrefix "column " rest -> path ++ ":" ++ l ++ ":" ++ c ++ ": " ++ msg
  Just (l@(_ : _), ':' : ' ' : msg) -> path ++ ":" ++ l ++ ": " ++ msg
  _ -> e

-- @setFirst key v line@: the number after the first @key@ in @line@
-- written @v@ instead.
setFirst :: String -> String -> String -> String
setFirst key v txt = case txt of
  _ | key `isPrefixOf` txt -> key ++ v ++ dropWhile (`elem` "-+.0123456789eE") (drop (length key) txt)
  c : rest                 -> c : setFirst key v rest
  []                       -> []
