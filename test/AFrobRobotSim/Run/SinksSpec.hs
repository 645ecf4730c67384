-- | The outputs of a run ("AFrobRobotSim.Run.Sinks"), each fed the states
-- of a short run of the default world by hand, as "AFrobRobotSim.Run"
-- feeds them: what each writes, and that a write that fails at the end is
-- reported in the outcome, not thrown. (The runner's whole path, with the
-- command line, is "AFrobRobotSim.RunSpec"'s.)
module AFrobRobotSim.Run.SinksSpec (spec) where

import           Control.Exception       (ErrorCall, finally, try)
import qualified Data.ByteString.Char8   as BC
import           Data.IORef
import           Data.List               (isInfixOf, isPrefixOf, sort, tails)
import           GHC.IO.Handle           (hDuplicate, hDuplicateTo)
import           System.Directory        (listDirectory)
import           System.FilePath         ((</>))
import           System.IO               (BufferMode (..), Handle, IOMode (..), hClose, hFlush, hSetBuffering,
                                          stderr, stdout, withFile)
import           Test.Hspec
import           Text.Printf             (printf)

import           AFRP.Geometry           (Point2 (..), norm, (.-.))
import           AFrob                   (constant, ddVelDiff, mrFinalize)
import           AFrobRobotSim           (defaultWorld, simulate)
import           AFrobRobotSim.JSON      (JSON (..), asArray, asNumber, member, parseJSON)
import           AFrobRobotSim.Log       (LogSummary (..))
import           AFrobRobotSim.Options
import           AFrobRobotSim.Result    (WorldSource (..))
import           AFrobRobotSim.Render
import           AFrobRobotSim.Run.Sinks
import           AFrobRobotSim.Simulator (RobotState (..), WorldState (..))
import           AFrobRobotSim.World     (notesBounds)
import           TestUtil                (withTempDir)

-- | 101 states (1 s) of the default world, every robot driving a curve.
states :: [WorldState]
states = take 101 (simulate 0.01 defaultWorld ctl ctl)
  where ctl _ = constant (mrFinalize (ddVelDiff 0.3 0.5))

-- | A summary of that run.
summary :: LogSummary
summary = LogSummary 1 101 0 0.1 False Nothing Nothing []

-- | Every state to the sink, in order, then its end.
feed :: Sink -> IO Outcome
feed sink = mapM_ (uncurry (sinkStep sink)) (zip [0 ..] states) >> sinkFinish sink summary

-- | The name of frame @k@.
frameName :: Int -> FilePath
frameName = printf "frame-%06d.ppm"

-- | A frame that is the text of its trails (as pairs) and its time.
trailsFrame :: [[Point2 Double]] -> WorldState -> BC.ByteString
trailsFrame trails s = BC.pack (show (map (map (\(Point2 x y) -> (x, y))) trails, wsTime s))

spec :: Spec
spec = do
  describe "Outcome" $
    it "joins the failures and the lines written, each in order" $ do
      let Outcome errs wrote = Outcome ["a"] ["1"] <> mempty <> Outcome ["b"] ["2", "3"]
      (errs, wrote) `shouldBe` (["a", "b"], ["1", "2", "3"])

  describe "messagesSink and progressSink" $
    it "put a message on a line of its own: the progress line erased before it, drawn again after" $
      withTempDir $ \dir -> do
        frames <- newIORef (0 :: Int)
        let file = dir </> "terminal"
            sinks = [messagesSink True, progressSink 4 frames]
            said k s = s { wsMessages = [ "hello" | k == (2 :: Int) ] }
        withFile file WriteMode $ \h -> redirect stdout h $ redirect stderr h $ do
          hSetBuffering stderr NoBuffering   -- (as on a terminal)
          mapM_ (\(k, s) -> writeIORef frames k >> mapM_ (\sk -> sinkStep sk k (said k s)) sinks)
                (zip [0 .. 3] states)
        text <- readFile file
        length text `seq` text `shouldBe` ("\r  0%  0 frames " ++ eraseProgress ++ "hello\n" ++ "\r 50%  2 frames ")

  describe "framesSink" $ do
    it "writes the frames of the steps picked, numbered from 0, and leaves no temporary file" $
      withTempDir $ \dir -> do
        count <- newIORef 0
        sink <- framesSink defaultSimOptions { optOut = dir } 60 (\n -> n `mod` 25 == 0)
                           (\_ s -> BC.pack (show (wsTime s))) count
        Outcome errs _ <- feed sink
        errs `shouldBe` []
        readIORef count `shouldReturn` 5
        files <- sort <$> listDirectory dir
        files `shouldBe` map frameName [0 .. 4]
        contents <- mapM (\f -> BC.unpack <$> BC.readFile (dir </> f)) files
        contents `shouldBe` [ show (wsTime s) | (n, s) <- zip [0 :: Int ..] states, n `mod` 25 == 0 ]
    it "removes, once finished, the temporary file a failed frame left" $
      withTempDir $ \dir -> do
        count <- newIORef 0
        -- (the frame of 0.75 s fails as it is written: its temporary file
        -- is open by then)
        sink <- framesSink defaultSimOptions { optOut = dir } 60 (\n -> n `mod` 25 == 0)
                           (\_ s -> if wsTime s > 0.7 then errorWithoutStackTrace "no frame" else BC.pack (show (wsTime s))) count
        r <- try (mapM_ (uncurry (sinkStep sink)) (zip [0 ..] states))
        either (\e -> show (e :: ErrorCall)) (const "no failure") r `shouldBe` "no frame"
        left <- sort <$> listDirectory dir
        left `shouldBe` map frameName [0 .. 2] ++ [frameName 3 ++ ".tmp"]
        Outcome errs _ <- sinkFinish sink summary
        errs `shouldBe` []
        kept <- sort <$> listDirectory dir
        kept `shouldBe` take 3 left
    it "gives the render each robot's trail: its start, then points more than a pixel apart" $
      withTempDir $ \dir -> do
        count <- newIORef 0
        let scale = 60
            px = 1 / scale
        sink <- framesSink defaultSimOptions { optOut = dir, optTrails = True } scale (const True)
                           trailsFrame count
        _ <- feed sink
        files <- sort <$> listDirectory dir
        length files `shouldBe` length states
        text <- BC.unpack <$> BC.readFile (dir </> last files)
        let (trails, t) = read text :: ([[(Double, Double)]], Double)
            final = last states
            start = head states
            pos r = let Point2 x y = robotPos r in (x, y)
            dist (a, b) (c, d) = norm (Point2 a b .-. Point2 c d)
        t `shouldBe` wsTime final
        length trails `shouldBe` length (wsRobots final)
        map (take 1) trails `shouldBe` [ [pos r] | r <- wsRobots start ]
        -- consecutive points more than a pixel apart, and the robot now
        -- within a pixel of its trail's newest point (or it would be added)
        and [ dist a b > px | tr <- trails, (a, b) <- zip tr (drop 1 tr) ] `shouldBe` True
        and [ dist (last tr) (pos r) <= px | (tr, r) <- zip trails (wsRobots final) ] `shouldBe` True
        -- every robot moved several pixels in the second: the trails grew
        map length trails `shouldSatisfy` all (> 2)

  describe "svgSink" $
    it "writes the picture at the end and says so" $
      withTempDir $ \dir -> do
        let file = dir </> "run.svg"
        sink <- svgSink 10 (RenderStyle 60 False False, Scene notesBounds defaultWorld) file
        Outcome errs wrote <- feed sink
        errs `shouldBe` []
        map ("wrote " `isPrefixOf`) wrote `shouldBe` [True]
        picture <- readFile file
        ("<svg" `isInfixOf` picture) `shouldBe` True
        -- each robot's track, one polyline each
        length (filter ("<polyline" `isPrefixOf`) (tails picture)) `shouldBe` length (wsRobots (last states))

  describe "resultSink" $ do
    it "writes one line of JSON at the end" $
      withTempDir $ \dir -> do
        let file = dir </> "result.jsonl"
        sink <- resultSink "sinks-spec" defaultSimOptions BuiltInWorld defaultWorld file
        Outcome errs _ <- feed sink
        errs `shouldBe` []
        ls <- lines <$> readFile file
        length ls `shouldBe` 1
        -- each robot's tally: where it ended and how far it went, step by step
        let robotsOf txt = parseJSON txt >>= member "outcome" >>= member "robots" >>= asArray
            field k v = member k v >>= asNumber
            final = last states
            travelled i = sum [ norm (robotPos (wsRobots b !! i) .-. robotPos (wsRobots a !! i))
                              | (a, b) <- zip states (drop 1 states) ]
        case robotsOf (concat ls) of
          Left err -> expectationFailure err
          Right rs -> do
            map (field "x") rs `shouldBe` [ Right (let Point2 x _ = robotPos r in x) | r <- wsRobots final ]
            [ either (const False) (\d -> abs (d - travelled i) < 1e-12) (field "distance" v)
              | (i, v) <- zip [0 ..] rs ] `shouldBe` map (const True) (wsRobots final)
    it "names the program as the options do (optProgram: afrp-examples' examples were all \"afrp-examples\"), else by the name given" $
      withTempDir $ \dir -> do
        let file = dir </> "result.jsonl"
            programOf o = do
              sink <- resultSink "sinks-spec" o BuiltInWorld defaultWorld file
              Outcome errs _ <- feed sink
              errs `shouldBe` []
              txt <- readFile file
              length txt `seq` pure (parseJSON txt >>= member "program")
        programOf defaultSimOptions { optProgram = Just "afrp-examples rcReverse" }
          `shouldReturn` Right (JString "afrp-examples rcReverse")
        programOf defaultSimOptions `shouldReturn` Right (JString "sinks-spec")
    it "reports a write that fails at the end in the outcome, and does not throw" $
      withTempDir $ \dir -> do
        let file = dir </> "no-such-folder" </> "result.jsonl"
        sink <- resultSink "sinks-spec" defaultSimOptions BuiltInWorld defaultWorld file
        Outcome errs wrote <- feed sink
        wrote `shouldBe` []
        map (("cannot write " ++ show file) `isPrefixOf`) errs `shouldBe` [True]

-- | Run an action with a handle's output sent to another handle.
redirect :: Handle -> Handle -> IO a -> IO a
redirect h to act = do
  hFlush h
  saved <- hDuplicate h
  (hDuplicateTo to h >> act) `finally` (hFlush h >> hDuplicateTo saved h >> hClose saved)
