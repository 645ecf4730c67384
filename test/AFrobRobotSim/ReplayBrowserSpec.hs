-- | The replay page in a real browser: headless Chromium, driven by
-- playwright-core from test/browser/ (see test/browser/replay.test.js for
-- the checks). Missing tools fail the test with how to install them.
module AFrobRobotSim.ReplayBrowserSpec (spec) where

import           Control.Monad            (unless)
import           System.Directory         (doesDirectoryExist, doesFileExist, findExecutable,
                                           getTemporaryDirectory, removeFile)
import           System.Environment       (lookupEnv)
import           System.Exit              (ExitCode (..))
import           System.FilePath          ((</>))
import           System.IO                (hClose, openTempFile)
import           System.Process           (readProcessWithExitCode)
import           Test.Hspec

import           AFrobRobotSim.LogFixture
import           AFrobRobotSim.Replay

spec :: Spec
spec = it "plays the page of a short run in headless Chromium: drawn where the log says, slider, click, keys, no script from the run (fixed)" $ do
  node     <- findExecutable "node"
  chromium <- lookupEnv "CHROMIUM" >>= maybe (pure "/usr/bin/chromium") pure
  haveChromium <- doesFileExist chromium
  haveModules  <- doesDirectoryExist ("test" </> "browser" </> "node_modules" </> "playwright-core")
  let missing = [ "node (apt-get install -y nodejs npm)" | node == Nothing ]
             ++ [ "Chromium at " ++ chromium ++ " (apt-get install -y chromium, or set CHROMIUM)" | not haveChromium ]
             ++ [ "playwright-core (cd test/browser && npm ci)" | not haveModules ]
  unless (null missing) $
    expectationFailure ("the browser test needs: " ++ concatMap ("\n  - " ++) missing
                        ++ "\n(.ci/run installs them)")
  tmp <- getTemporaryDirectory
  (page, h) <- openTempFile tmp "afrp-replay.html"
  hClose h
  writeFile page (replayPage fixtureLog)
  shot <- lookupEnv "AFRP_REPLAY_SCREENSHOT" >>= maybe (pure (page ++ ".png")) pure
  (code, out, err) <- readProcessWithExitCode (maybe "node" id node)
                        ["test" </> "browser" </> "replay.test.js", page, shot] ""
  removeFile page
  case code of
    ExitSuccess   -> pure ()
    ExitFailure c -> expectationFailure ("node test/browser/replay.test.js exited with " ++ show c
                                         ++ ":\n" ++ out ++ err)
