-- | The replay page, as text: the log is embedded intact and safely.
module AFrobRobotSim.ReplaySpec (spec, embeddedData, occurrences) where

import qualified Data.ByteString          as BS
import           Control.Monad            (forM_)
import           Data.List                (isInfixOf, isPrefixOf, sort, tails)
import           System.Directory         (createDirectory, getTemporaryDirectory, listDirectory, removeFile)
import           System.FilePath          (splitFileName, (</>))
import           System.IO                (hClose, hPutStr, openBinaryTempFile, openTempFile)
import           Test.Hspec

import           AFrob                    (constant, ddVelDiff, mrFinalize)
import           AFrobRobotSim            (defaultWorld, simulate)
import           AFrobRobotSim.JSON
import           AFrobRobotSim.Log
import           AFrobRobotSim.LogFixture
import           AFrobRobotSim.Replay
import           TestUtil                 (withTMPDIR, withTempDir)

occurrences :: String -> String -> Int
occurrences needle hay = length (filter (needle `isPrefixOf`) (tails hay))

-- The text of the page's data element.
embeddedData :: String -> Maybe String
embeddedData page = case [ rest | rest <- tails page, openTag `isPrefixOf` rest ] of
  rest : _ -> Just (takeUntil "</script>" (drop (length openTag) rest))
  []       -> Nothing
  where
    openTag = "<script id=\"afrp-log\" type=\"application/json\">"

-- A text up to the first occurrence of @end@ (all of it if none).
takeUntil :: String -> String -> String
takeUntil end s@(c : cs) | end `isPrefixOf` s = ""
                         | otherwise          = c : takeUntil end cs
takeUntil _ [] = ""

-- The page's data elements, in order: each one's id and text (its JSON
-- array, with the newline after its opening tag).
dataElements :: String -> [(String, String)]
dataElements page =
  [ ("afrp-log" ++ takeWhile (/= '"') (drop (length open) rest), takeUntil "</script>" (drop 1 (dropWhile (/= '>') rest)))
  | rest <- tails page, open `isPrefixOf` rest ]
  where
    open = "<script id=\"afrp-log"

-- A list cut into consecutive pieces of the given lengths.
cut :: [Int] -> [a] -> [[a]]
cut (k : ks) xs = take k xs : cut ks (drop k xs)
cut [] _        = []

spec :: Spec
spec = do
  let page = replayPage fixtureLog
  describe "replayPage" $ do
    it "closes exactly its two script elements: no string of the run ends one (fixed)" $ do
      occurrences "</script" page `shouldBe` 2
      occurrences "<script" page `shouldBe` 2
    it "embeds no markup from the hostile message (fixed)" $ do
      page `shouldNotSatisfy` ("<img" `isInfixOf`)
      page `shouldNotSatisfy` ("<!--" `isInfixOf`)
      page `shouldNotSatisfy` ("\x2028" `isInfixOf`)
    it "embeds the log as JSON that reads back to the same records, hostile message included (fixed)" $
      case embeddedData page of
        Nothing  -> expectationFailure "no data element"
        Just txt -> do
          let parsed = parseJSON txt >>= asArray >>= traverse logLineFromJSON
          parsed `shouldBe` Right (LineHeader (rlHeader fixtureLog) : map LineFrame (rlFrames fixtureLog)
                                    ++ maybe [] ((: []) . LineSummary) (rlSummary fixtureLog))
          txt `shouldSatisfy` ("\\u003c/script\\u003e\\u003cimg src=x onerror=\\\"window.__pwned=1\\\"\\u003e'\\\\\\\"\\n\\t\\u0000" `isInfixOf`)
    it "is ASCII, needs no network, and allows only its own script (fixed)" $ do
      page `shouldSatisfy` all (\c -> c < '\DEL')
      page `shouldNotSatisfy` ("http:" `isInfixOf`)
      page `shouldNotSatisfy` ("https:" `isInfixOf`)
      page `shouldSatisfy` ("default-src 'none'; script-src 'nonce-" `isInfixOf`)
      page `shouldNotSatisfy` ("script-src 'unsafe-inline'" `isInfixOf`)
    it "has the controls the brief names (fixed)" $
      mapM_ (\i -> page `shouldSatisfy` (("id=\"" ++ i ++ "\"") `isInfixOf`))
        ["world", "play", "back", "fwd", "slider", "speed", "rays", "trails", "sightings", "info", "time"]

  describe "replayPageChunked (a long log in several data elements)" $ do
    let lns = fixtureLogLines
        edges = fixtureChunkEdges
    it "joins its elements' arrays, in order, into the log's lines; each within the bound unless it is one line" $
      forM_ ([10, 700, 2000, 5000, 20000] ++ edges) $ \n -> do
        let els = dataElements (replayPageChunked n fixtureLog)
        map fst els `shouldBe` take (length els) ("afrp-log" : [ "afrp-log-" ++ show k | k <- [2 :: Int ..] ])
        let arrays = traverse (\(_, txt) -> parseJSON txt >>= asArray) els
        fmap concat arrays `shouldBe` traverse parseJSON lns
        -- the lines of each element, by the counts of its array
        let groups = cut (either (const []) (map length) arrays) lns
            joined g = sum (map length g) + 2 * (length g - 1)
        map (\(_, txt) -> length txt - 4) els `shouldBe` map joined groups
        filter (\g -> joined g > n && length g > 1) groups `shouldBe` []
        -- (an element ends only where the next line would not fit)
        [ () | (g, g') <- zip groups (drop 1 groups), joined g + 2 + sum (map length (take 1 g')) <= n ]
          `shouldBe` []
    it "puts a line longer than the bound in an element of its own" $
      length (dataElements (replayPageChunked 10 fixtureLog)) `shouldBe` length lns
    it "is one element, replayPage's page, when the log fits (fixed)" $ do
      length (dataElements page) `shouldBe` 1
      replayPageChunked (sum (map ((+ 2) . length) lns)) fixtureLog `shouldBe` page
      replayPageChunked replayChunkChars fixtureLog `shouldBe` page

  describe "the page's nonce" $ do
    -- (lines of lengths about the hash's eight-byte words: a character in
    -- a whole word and one in the bytes after the last are both hashed)
    let lns = [ take k (cycle "{\"kind\":\"frame\",\"t\":0.04}") | k <- [0, 1, 7, 8, 9, 15, 16, 17, 23] ]
        pageNonce = takeWhile (/= '\'') . drop (length "nonce-") . head . filter ("nonce-" `isPrefixOf`) . tails
        nonceOf = pageNonce . replayPageFromLines
        changed = [ take i lns ++ [l'] ++ drop (i + 1) lns
                  | (i, l) <- zip [0 :: Int ..] lns, j <- [0 .. length l - 1]
                  , let l' = take j l ++ [if l !! j == 'x' then 'y' else 'x'] ++ drop (j + 1) l ]
    it "changes with any one character of any line" $ do
      length changed `shouldBe` 96
      filter ((== nonceOf lns) . nonceOf) changed `shouldBe` []
    it "is the same from the lines' texts as from the log's records" $
      nonceOf (map encodeLogLine (LineHeader (rlHeader fixtureLog) : map LineFrame (rlFrames fixtureLog)
                                   ++ maybe [] ((: []) . LineSummary) (rlSummary fixtureLog)))
        `shouldBe` pageNonce page

  describe "the page of the default world's 30-second run" $
    it "stays under 3 MB, and its log reads back (fixed)" $ do
      let cfg = defaultLogConfig { lcWorld = defaultWorld, lcDt = 0.01, lcFps = 25 }
          steer _ = constant (mrFinalize (ddVelDiff 0.6 0.8))
          states = take 3001 (simulate 0.01 defaultWorld steer steer)
          runLog = RunLog (logHeader cfg) (logFrames cfg states) Nothing Nothing
          big = replayPage runLog
      length big `shouldSatisfy` (< 3000000)
      readLog (unlines (map encodeLogLine (LineHeader (rlHeader runLog) : map LineFrame (rlFrames runLog))))
        `shouldBe` Right runLog

  describe "writeReplayFromLog" $ do
    it "turns a log file into the same page (fixed)" $ do
      tmp <- getTemporaryDirectory
      (logPath, h) <- openTempFile tmp "afrp-log.jsonl"
      hClose h
      writeFile logPath fixtureLogText
      let out = logPath ++ ".html"
      r <- writeReplayFromLog logPath out
      written <- readFile out
      length written `seq` mapM_ removeFile [logPath, out]
      r `shouldBe` Right (LogEnd (rlSummary fixtureLog) Nothing)
      written `shouldBe` page
    it "refuses a file that is not a log, writing nothing (fixed)" $ do
      tmp <- getTemporaryDirectory
      (logPath, h) <- openTempFile tmp "afrp-log.jsonl"
      hClose h
      writeFile logPath "{\"kind\": \"header\", \"format\": \"other\"}\n"
      r <- writeReplayFromLog logPath (logPath ++ ".html")
      removeFile logPath
      r `shouldSatisfy` either (((logPath ++ ":1: ") `isPrefixOf`) . refusedText) (const False)
    it "reports a log that does not exist and a page that cannot be written as Left, naming the file (fixed)" $ do
      tmp <- getTemporaryDirectory
      let missing = tmp ++ "/afrp-no-such-log.jsonl"
      r1 <- writeReplayFromLog missing (missing ++ ".html")
      r1 `shouldSatisfy` either ((\e -> missing `isInfixOf` e && not ((missing ++ ": " ++ missing) `isInfixOf` e)) . refusedText) (const False)
      (logPath, h) <- openTempFile tmp "afrp-log.jsonl"
      hClose h
      writeFile logPath fixtureLogText
      let out = tmp ++ "/afrp-no-such-folder/page.html"
      r2 <- writeReplayFromLog logPath out
      removeFile logPath
      r2 `shouldSatisfy` either ((\e -> out `isInfixOf` e && not ((out ++ ": " ++ out) `isInfixOf` e)) . refusedText) (const False)
    it "says a page's missing folder before reading the log (and a file in the folder's place)" $ do
      tmp <- getTemporaryDirectory
      let missing = tmp ++ "/afrp-no-such-log.jsonl"
          out = tmp ++ "/afrp-no-such-folder/page.html"
      -- (the log does not exist either: the folder is said first)
      writeReplayFromLog missing out `shouldReturn`
        Left (ReplayRefused ("cannot write the page " ++ out ++ ": " ++ tmp ++ "/afrp-no-such-folder does not exist"))
      (logPath, h) <- openTempFile tmp "afrp-log.jsonl"
      hClose h
      r <- writeReplayFromLog missing (logPath </> "page.html")
      removeFile logPath
      r `shouldBe` Left (ReplayRefused ("cannot write the page " ++ (logPath </> "page.html") ++ ": " ++ logPath ++ " is not a folder"))
    it "says an empty name of the log or the page, and a page that is a folder, as such (it was a bare renameFile error)" $ do
      tmp <- getTemporaryDirectory
      (logPath, h) <- openTempFile tmp "afrp-log.jsonl"
      hClose h
      writeFile logPath fixtureLogText
      r1 <- writeReplayFromLog logPath ""
      r2 <- writeReplayFromLog "" (logPath ++ ".html")
      r3 <- writeReplayFromLog logPath tmp
      removeFile logPath
      (r1, r2) `shouldBe` (Left (ReplayRefused "the page's name (--replay) is empty"), Left (ReplayRefused "the log's name (--replay-from) is empty"))
      r3 `shouldBe` Left (ReplayRefused ("cannot write the page " ++ tmp ++ ": it is a folder"))
    it "refuses a page that is the log itself under another name, keeping the log" $ do
      tmp <- getTemporaryDirectory
      (logPath, h) <- openTempFile tmp "afrp-log.jsonl"
      hClose h
      writeFile logPath fixtureLogText
      let (dir, name) = splitFileName logPath
      r <- writeReplayFromLog logPath (dir </> "." </> name)
      kept <- readFile logPath
      length kept `seq` removeFile logPath
      r `shouldSatisfy` either (("the page would overwrite it" `isInfixOf`) . refusedText) (const False)
      kept `shouldBe` fixtureLogText
    it "reports a log that is not UTF-8 with the line and column of the first bad byte (fixed)" $ do
      tmp <- getTemporaryDirectory
      (logPath, h) <- openBinaryTempFile tmp "afrp-log.jsonl"
      -- (the header, then a line with a bad byte: the first fault, read
      -- a line at a time)
      hPutStr h (head (lines fixtureLogText) ++ "\n")
      BS.hPut h (BS.pack [0x20, 0xff, 0x0a])
      hClose h
      r <- writeReplayFromLog logPath (logPath ++ ".html")
      removeFile logPath
      r `shouldBe` Left (ReplayRefused (logPath ++ ":2:2: invalid UTF-8 (byte 0xff)"))
    it "turns a log cut short (no summary) into the page of what it holds, and says where a later line is bad" $
      withTempDir $ \dir -> do
        let logPath = dir </> "cut.jsonl"
            out = dir </> "cut.html"
            short = unlines (take 10 (lines fixtureLogText))
        writeFile logPath short
        writeReplayFromLog logPath out `shouldReturn` Right (LogEnd Nothing Nothing)
        written <- readFile out
        fmap replayPage (readLog short) `shouldBe` Right written
        -- a bad line after good frames: no page, the old one kept
        writeFile logPath (short ++ "{\"kind\": \"frame\"\n")
        writeReplayFromLog logPath out `shouldReturn` Left (ReplayRefused (logPath ++ ":11:17: expected ',' or '}', found end of input"))
        readFile out `shouldReturn` written
        listDirectory dir >>= (`shouldBe` ["cut.html", "cut.jsonl"]) . sort
    it "makes the page of a log whose last line stops in its middle (a full disk's), and gives that line's number" $
      withTempDir $ \dir -> do
        let logPath = dir </> "full.jsonl"
            out = dir </> "full.html"
            ls = lines fixtureLogText
        writeFile logPath (unlines (take 10 ls) ++ take 40 (ls !! 10))
        writeReplayFromLog logPath out `shouldReturn` Right (LogEnd Nothing (Just 11))
        written <- readFile out
        fmap replayPage (readLog (unlines (take 10 ls))) `shouldBe` Right written
    it "says a temporary folder it cannot use (TMPDIR), writing no page, and leaves no temporary file" $
      withTempDir $ \dir -> do
        let logPath = dir </> "run.jsonl"
            out = dir </> "run.html"
        writeFile logPath fixtureLogText
        r <- withTMPDIR (dir </> "no-such-folder") (writeReplayFromLog logPath out)
        r `shouldSatisfy` either ((("cannot make the page: its temporary file in " ++ (dir </> "no-such-folder")) `isPrefixOf`) . refusedText)
                                 (const False)
        -- (and with a usable one, the frames' file is gone after the page is written)
        createDirectory (dir </> "tmp")
        withTMPDIR (dir </> "tmp") (writeReplayFromLog logPath out) `shouldReturn` Right (LogEnd (rlSummary fixtureLog) Nothing)
        listDirectory (dir </> "tmp") `shouldReturn` []
        listDirectory dir >>= (`shouldBe` ["run.html", "run.jsonl", "tmp"]) . sort
    it "says a page whose write fails (a full disk) as a failed write, not a refusal, keeping no temporary file" $
      withTempDir $ \dir -> do
        let logPath = dir </> "run.jsonl"
        writeFile logPath fixtureLogText
        createDirectory (dir </> "tmp")
        r <- withTMPDIR (dir </> "tmp") (writeReplayFromLog logPath "/dev/full")
        r `shouldSatisfy` \x -> case x of
          Left (ReplayWriteFailed msg) -> "cannot write the page: /dev/full" `isPrefixOf` msg
          _                            -> False
        -- (the frames' temporary file is gone, and nothing else was made)
        listDirectory (dir </> "tmp") `shouldReturn` []
        listDirectory dir >>= (`shouldBe` ["run.jsonl", "tmp"]) . sort

-- The message of a refusal; none ("") for a failed write, which the
-- tests that use it do not expect.
refusedText :: ReplayFault -> String
refusedText f = case f of
  ReplayRefused msg   -> msg
  ReplayWriteFailed _ -> ""
