{-# LANGUAGE ScopedTypeVariables #-}
-- | Helpers shared by the specs: running signal functions on sample lists
-- and comparing floating-point outputs; laziness checks; temporary folders;
-- a number of capabilities; a program's output captured.
module TestUtil
  ( runDt
  , runSamples
  , approx
  , approxWith
  , shouldApprox
  , shouldApproxList
  , PositiveDt (..)
  , genSamples
  , withoutHanging
  , withTempDir
  , withTMPDIR
  , captured
  , withUnsearchable
  , writeScript
  , withCaps
  , cLocale
  ) where

import           Control.Exception (NonTermination (..), bracket, bracket_, evaluate, finally, try)
import           System.Posix.Files (setFileMode)
import           System.Posix.User (getEffectiveUserID)
import           GHC.IO.Handle     (hDuplicate, hDuplicateTo)
import           System.Exit       (ExitCode)
import           System.IO         (IOMode (..), hClose, hFlush, stderr, stdout, withFile)
import qualified Data.ByteString.Builder as B
import qualified Data.ByteString.Lazy as BL
import           GHC.Conc          (getNumCapabilities, setNumCapabilities)
import           System.Directory  (createDirectory, getPermissions, getTemporaryDirectory, removeDirectoryRecursive,
                                    setOwnerExecutable, setPermissions)
import           System.Environment (lookupEnv, setEnv, unsetEnv)
import           System.FilePath   ((</>))
import           System.IO.Error   (isAlreadyExistsError)
import           System.Timeout    (timeout)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP

-- | Run with a constant time step: the first input is the sample at local
-- time 0, each later one comes @dt@ after the previous.
runDt :: DTime -> SF a b -> [a] -> [b]
runDt _  _  []       = []
runDt dt sf (a : as) = embed sf (a, [(dt, Just x) | x <- as])

-- | Run on explicit samples; the time step of the first is ignored (it is
-- the sample at local time 0).
runSamples :: SF a b -> [(DTime, a)] -> [b]
runSamples _  []            = []
runSamples sf ((_, a) : as) = embed sf (a, [(dt, Just x) | (dt, x) <- as])

-- | Equal within a relative and absolute tolerance of 1e-9.
approx :: Double -> Double -> Bool
approx = approxWith 1e-9

-- | Equal within the given relative-and-absolute tolerance.
approxWith :: Double -> Double -> Double -> Bool
approxWith tol x y = abs (x - y) <= tol * max 1 (max (abs x) (abs y))

-- | Expectation: two numbers are 'approx'.
shouldApprox :: Double -> Double -> Expectation
shouldApprox x y
  | approx x y = pure ()
  | otherwise  = expectationFailure ("expected " ++ show y ++ " but got " ++ show x)

-- | Expectation: two lists of numbers have the same length and are
-- pointwise 'approx'.
shouldApproxList :: [Double] -> [Double] -> Expectation
shouldApproxList xs ys
  | length xs == length ys && and (zipWith approx xs ys) = pure ()
  | otherwise = expectationFailure ("expected " ++ show ys ++ "\n but got " ++ show xs)

-- | A random positive time step, between 0.001 and 1.
newtype PositiveDt = PositiveDt DTime
  deriving Show

instance Arbitrary PositiveDt where
  arbitrary = PositiveDt <$> choose (0.001, 1)
  shrink (PositiveDt d) = [PositiveDt d' | d' <- [0.5, 0.25, 0.1], d' < d]

-- | Random samples (time step, input), at least one, the first time step
-- being irrelevant.
genSamples :: Gen a -> Gen [(DTime, a)]
genSamples g = do
  n  <- choose (1, 40)
  vectorOf n ((,) <$> choose (0.001, 1) <*> g)

-- | The actual outputs, all evaluated, must be the expected ones; a
-- @\<\<loop\>\>@ or a hang fails (for the laziness specs, where a wrong
-- implementation diverges, and the optimiser's, where a quadratic one
-- takes minutes). The bound, 30 s, is only that guard, generous for a
-- loaded machine: every use takes well under a second here, and speed is
-- measured in bench/, not by tests.
withoutHanging :: (Eq a, Show a) => [a] -> [a] -> Expectation
withoutHanging actual expected = do
  r <- timeout 30000000 (try (evaluate (foldr seq () actual)))
  case r of
    Nothing                    -> expectationFailure "no result within 30 s (a hang?)"
    Just (Left NonTermination) -> expectationFailure "<<loop>>"
    Just (Right ())            -> actual `shouldBe` expected

-- | An action in a new, empty temporary folder, removed (with what the
-- action left in it) afterwards.
withTempDir :: (FilePath -> IO a) -> IO a
withTempDir act = do
  tmp <- getTemporaryDirectory
  let go k = do
        let d = tmp </> ("afrp-spec-" ++ show (k :: Int))
        r <- try (createDirectory d)
        case r of
          Right () -> pure d
          -- (taken: the next name; any other error, such as a TMPDIR that
          -- does not exist, is the test's failure, not a reason to loop)
          Left e | isAlreadyExistsError e && k < 100000 -> go (k + 1)
                 | otherwise -> ioError e
  bracket (go 0) removeDirectoryRecursive act

-- | An action with the environment's @TMPDIR@ (where
-- 'System.Directory.getTemporaryDirectory' looks) set to a folder, and
-- restored afterwards: for a test that counts the files a library makes
-- there, which another program's in the shared folder would disturb. (The
-- suite runs one test at a time.)
withTMPDIR :: FilePath -> IO a -> IO a
withTMPDIR dir act = bracket (lookupEnv "TMPDIR") (maybe (unsetEnv "TMPDIR") (setEnv "TMPDIR"))
                             (\_ -> setEnv "TMPDIR" dir >> act)

-- | Run an action on @k@ capabilities (the program's number restored
-- afterwards).
withCaps :: Int -> IO a -> IO a
withCaps k act = bracket getNumCapabilities setNumCapabilities (\_ -> setNumCapabilities k >> act)

-- | Text as GHC decodes it from a command line (or a file's name) in the
-- C locale: each UTF-8 byte above 127 as the stand-in character
-- U+DC00 + the byte. Passed to a child process or to a file operation, it
-- gives those very bytes in any locale.
cLocale :: String -> String
cLocale = map (\b -> if b < 0x80 then toEnum (fromIntegral b) else toEnum (0xDC00 + fromIntegral b))
          . BL.unpack . B.toLazyByteString . B.stringUtf8

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

-- | @writeScript file text@: an executable script, @file@ holding
-- @text@, its owner allowed to run it.
writeScript :: FilePath -> String -> IO ()
writeScript file text = do
  writeFile file text
  p <- getPermissions file
  setPermissions file (setOwnerExecutable True p)

-- | @withUnsearchable dir check@: @check@ given @dir/locked@, a folder
-- holding a folder @sub@, while @locked@ may not be searched (mode 600,
-- no x permission); its mode is put back afterwards, whatever @check@
-- does. Pending as root, who searches every folder (CI runs these tests
-- once more as @nobody@).
withUnsearchable :: FilePath -> (FilePath -> Expectation) -> Expectation
withUnsearchable dir check = do
  uid <- getEffectiveUserID
  if uid == 0 then pendingWith "root searches every folder: run as another user (see the test)" else do
    let locked = dir </> "locked"
    createDirectory locked
    createDirectory (locked </> "sub")
    bracket_ (setFileMode locked 0o600) (setFileMode locked 0o700) (check locked)
