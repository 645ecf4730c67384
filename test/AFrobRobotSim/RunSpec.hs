{-# LANGUAGE ScopedTypeVariables #-}
-- | 'runSimWith' run headless into temporary folders: frames, the world
-- file round trip, every reported fault, determinism.
module AFrobRobotSim.RunSpec (spec) where

import           Control.Exception   (bracket, finally, try)
import qualified Data.ByteString     as BS
import           Data.Word           (Word8)
import           Data.List           (isInfixOf, isPrefixOf, sort)
import           GHC.IO.Handle       (hDuplicate, hDuplicateTo)
import           System.Directory    (createDirectory, getTemporaryDirectory, listDirectory,
                                      removeDirectoryRecursive)
import           System.Exit         (ExitCode (..))
import           System.FilePath     ((</>))
import           System.IO
import           Test.Hspec          hiding (after)

import           AFrob               hiding (forAll)
import           AFrobRobotSim

world :: WorldTemplate
world = [OTSimbotA 1 (Point2 (-3) 0) 0, OTVWall (Point2 3 0), OTBall (Point2 0 2)]

drive :: SimbotController
drive _ = constant (mrFinalize (ddVelDiff 1 1))

quick :: FilePath -> SimOptions
quick dir = defaultSimOptions { optSeconds = 2, optOut = dir, optQuiet = True }

-- | Run an action with stdout and stderr captured into files; return what
-- they received and how the action ended.
captured :: IO a -> IO (String, String, Either ExitCode a)
captured act = withTempDir $ \dir -> do
  let outF = dir </> "out"
      errF = dir </> "err"
  r <- withFile outF WriteMode $ \ho -> withFile errF WriteMode $ \he ->
         redirect stdout ho (redirect stderr he (try act))
  o <- readAll outF
  e <- readAll errF
  pure (o, e, r)
  where
    redirect h to act' = do
      hFlush h
      saved <- hDuplicate h
      (hDuplicateTo to h >> act') `finally` (hFlush h >> hDuplicateTo saved h >> hClose saved)
    readAll f = do
      s <- readFile f
      length s `seq` pure s

withTempDir :: (FilePath -> IO a) -> IO a
withTempDir act = do
  tmp <- getTemporaryDirectory
  let go k = do
        let d = tmp </> ("afrp-runspec-" ++ show (k :: Int))
        r <- try (createDirectory d)
        case r of
          Right ()                -> pure d
          Left (_ :: IOError)     -> go (k + 1)
  bracket (go 0) removeDirectoryRecursive act

framesIn :: FilePath -> IO [BS.ByteString]
framesIn dir = do
  names <- sort . filter ("frame-" `isPrefixOf`) <$> listDirectory dir
  mapM (BS.readFile . (dir </>)) names

spec :: Spec
spec = do
  describe "frames" $ do
    it "writes one P6 frame per 1/fps of simulated time, time 0 included" $ withTempDir $ \dir -> do
      (_, _, r) <- captured (runSimWith (quick (dir </> "f")) (Just world) drive drive)
      r `shouldBe` Right ()
      frames <- framesIn (dir </> "f")
      length frames `shouldBe` 51
      let header = "P6\n620 620\n255\n"
      all ((BS.pack (map (toEnum . fromEnum) header) `BS.isPrefixOf`)) frames `shouldBe` True
      map BS.length frames `shouldBe` replicate 51 (length header + 3 * 620 * 620)
    it "shows the robot moving" $ withTempDir $ \dir -> do
      _ <- captured (runSimWith (quick dir) (Just world) drive drive)
      frames <- framesIn dir
      -- the robot has left its start
      pixel (head frames) (-3) 0 `shouldNotBe` pixel (last frames) (-3) 0
      pixel (head frames) (-3) 0 `shouldNotBe` Nothing
    it "writes byte-identical frames on two runs with the same flags" $ withTempDir $ \dir -> do
      _ <- captured (runSimWith (quick (dir </> "a")) (Just world) drive drive)
      _ <- captured (runSimWith (quick (dir </> "b")) (Just world) drive drive)
      a <- framesIn (dir </> "a")
      b <- framesIn (dir </> "b")
      (length a, a == b) `shouldBe` (51, True)
    it "writes an SVG of the run" $ withTempDir $ \dir -> do
      _ <- captured (runSimWith (quick dir) { optFrames = False, optSvg = Just (dir </> "run.svg") }
                                (Just world) drive drive)
      svg <- readFile (dir </> "run.svg")
      ("<svg" `isPrefixOf` svg, "polyline" `isInfixOf` svg) `shouldBe` (True, True)

  describe "console" $ do
    it "prints the robots' messages and a summary" $ withTempDir $ \dir -> do
      let talk _ = proc' (after 1 "hello")
          proc' e = e >>> arr (\m -> mrFinalize (ddBrake `mrMerge` tcoPrintMessage m))
      (out, _, _) <- captured (runSimWith (quick dir) { optQuiet = False, optFrames = False }
                                          (Just world) talk talk)
      lines out `shouldSatisfy` elem "[1.00] SimbotA.1: hello"
      last (lines out) `shouldSatisfy` ("2.00 s simulated in 201 steps, 0 frames" `isPrefixOf`)

  describe "world files" $
    it "--dump-world then --world gives the same simulation" $ withTempDir $ \dir -> do
      (dumped, _, _) <- captured (runSimWith defaultSimOptions { optDumpWorld = True } (Just world) drive drive)
      writeFile (dir </> "w.world") dumped
      _ <- captured (runSimWith (quick (dir </> "a")) (Just world) drive drive)
      _ <- captured (runSimWith (quick (dir </> "b")) { optWorldFile = Just (dir </> "w.world") } Nothing drive drive)
      a <- framesIn (dir </> "a")
      b <- framesIn (dir </> "b")
      (length a, a == b) `shouldBe` (51, True)

  describe "faults" $ do
    it "rejects an unknown flag and a bad value, naming them" $ do
      parseSimArgs defaultSimOptions ["--frobnicate"] `shouldSatisfy` either ("--frobnicate" `isInfixOf`) (const False)
      parseSimArgs defaultSimOptions ["--dt", "fast"] `shouldSatisfy` either ("--dt" `isInfixOf`) (const False)
      parseSimArgs defaultSimOptions ["--seconds"] `shouldSatisfy` either ("needs a value" `isInfixOf`) (const False)
      parseSimArgs defaultSimOptions ["--keys", "1.5a"] `shouldSatisfy` either ("--keys" `isInfixOf`) (const False)
    it "parses every documented flag" $
      parseSimArgs defaultSimOptions ["--seconds", "5", "--dt", "0.02", "--fps", "10", "--out", "x", "--scale", "30"
                                     , "--keys", "1.5:a,3:b", "--seed", "7", "--quiet", "--rays", "--trails"]
        `shouldBe` Right (RunWith defaultSimOptions
          { optSeconds = 5, optDt = 0.02, optFps = 10, optOut = "x", optScale = 30
          , optKeys = [(1.5, 'a'), (3, 'b')], optSeed = 7, optQuiet = True, optRays = True, optTrails = True })
    it "reports an invalid world, naming the object, with exit code 2" $ do
      (_, err, r) <- captured (runSimWith defaultSimOptions { optFrames = False } (Just [OTSimbotB 9 (Point2 7 0) 0]) drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ("SimbotB 9" `isInfixOf`)
    it "reports a malformed world file with its line and column, simulating nothing" $ withTempDir $ \dir -> do
      writeFile (dir </> "bad.world") "ball at 0 0\nwall v at 1 x2\n"
      (_, err, r) <- captured (runSimWith (quick (dir </> "f")) { optWorldFile = Just (dir </> "bad.world") } Nothing drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ((dir </> "bad.world:2:13:") `isInfixOf`)
      listDirectory dir `shouldReturn` ["bad.world"]
    it "reports an output folder that cannot be written, before simulating" $ withTempDir $ \dir -> do
      writeFile (dir </> "file") "not a folder"
      (out, err, r) <- captured (runSimWith (quick (dir </> "file" </> "frames")) (Just world) drive drive)
      r `shouldBe` Left (ExitFailure 2)
      err `shouldSatisfy` ("cannot write frames" `isInfixOf`)
      out `shouldBe` ""
    it "reports a controller that throws with the robot and the time, exit code 1" $ withTempDir $ \dir -> do
      let bad _ = localTime >>> arr (\t -> mrFinalize (tcoPrintMessage
                    (if t >= 0.5 then merge (Event "a") (Event "b") else NoEvent)))
      (_, err, r) <- captured (runSimWith (quick dir) (Just world) bad drive)
      r `shouldBe` Left (ExitFailure 1)
      err `shouldSatisfy` ("SimbotA 1" `isInfixOf`)
      err `shouldSatisfy` ("0.500" `isInfixOf`)
      err `shouldSatisfy` ("simultaneous" `isInfixOf`)
  where
    pixel :: BS.ByteString -> Double -> Double -> Maybe (Word8, Word8, Word8)
    pixel bytes x y = ppmAt bytes (worldPx x) (worldPy y)
    worldPx x = round ((x + 5) * 60 + 10) :: Int
    worldPy y = round ((5 - y) * 60 + 10) :: Int
    ppmAt bytes px py =
      let off = length "P6\n620 620\n255\n" + 3 * (py * 620 + px)
      in if off + 2 < BS.length bytes then Just (BS.index bytes off, BS.index bytes (off + 1), BS.index bytes (off + 2)) else Nothing
