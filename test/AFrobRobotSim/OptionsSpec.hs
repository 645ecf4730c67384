-- | The command line of every 'runSim' program ("AFrobRobotSim.Options"):
-- output files and the output folder, in any order.
module AFrobRobotSim.OptionsSpec (spec) where

import           Data.List        (isInfixOf, isPrefixOf, permutations, tails)
import           Test.Hspec
import           Test.QuickCheck  (conjoin, counterexample, elements, forAll, property, (===))

import           AFrobRobotSim.Options
import           AFrobRobotSim.Options.Check (readableNumber)
import           AFrobRobotSim.World (Bounds (..))
import           TestUtil         (cLocale)

-- The SVG, the page and the output folder a command line gives.
outputs :: [String] -> Either String (Maybe FilePath, Maybe FilePath, FilePath)
outputs args = case parseSimArgs defaultSimOptions args of
  Right (RunWith o) -> Right (optSvg o, optReplay o, optOut o)
  Right ShowHelp    -> Left "help"
  Left err          -> Left err

spec :: Spec
spec = do
  describe "validateOptions" $
    it "suggests, for a --dt that does not divide the frame period, two --fps that work as written" $
      property $ forAll ((,) <$> elements [0.001, 0.003, 0.007, 0.01, 0.02, 0.03, 0.04, 0.06, 0.1, 0.3, 0.6, 0.9]
                             <*> elements [0.7, 0.98, 1, 3, 7, 13, 24, 25, 29.97, 30, 60]) $ \(dt, fps) ->
        let faults o = [ m | m <- validateOptions o, "does not divide" `isInfixOf` m ]
            base = defaultSimOptions { optDt = dt, optFps = fps }
        in case faults base of
             [] -> property True
             m : _ -> case words (takeWhile (/= 'w') (snd (breakOn "--fps " m))) of
               ["--fps", a, "or", b] ->
                 counterexample m (conjoin [ counterexample f (faults base { optFps = read f } === []) | f <- [a, b] ])
               other -> counterexample ("no two rates in: " ++ m ++ " " ++ show other) False
  describe "validateOptions, numbers set in code" $ do
    it "refuses what each flag refuses, for options that no flag made (runSimWith's), naming the record's field (it named the flag)" $ do
      let d = defaultSimOptions
          faults o = [ m | m <- validateOptions o, m `notElem` validateOptions d ]
      faults d { optSeconds = -1 } `shouldBe` ["optSeconds must be a finite number >= 0, got -1.0"]
      faults d { optOdometryNoise = 0 / 0 } `shouldBe` ["optOdometryNoise must be a number from 0 to 1, got NaN"]
      faults d { optOdometryNoise = -0.1 } `shouldBe` ["optOdometryNoise must be a number from 0 to 1, got -0.1"]
      faults d { optScale = Just 0 }
        `shouldBe` ["optScale must be Nothing (the scale that fits the world) or Just a finite number > 0, got Just 0.0"]
      faults d { optSeed = 2 ^ (60 :: Int) } `shouldBe` ["optSeed must be a whole number from -2^53 to 2^53, got 1152921504606846976"]
      faults d { optKeys = [(1, 'a'), (-2, 'b')] } `shouldBe` ["optKeys: a key press's time must be a finite number >= 0, got -2.0 for 'b'"]
      faults d { optDt = 2e6, optSeconds = 4e6, optFps = 1e-7 } `shouldSatisfy` elem "optDt must be a positive number up to 1000000, got 2000000.0"
      -- (a parameter's name twice in optParams: the result line would hold the key twice)
      faults d { optParams = [("a", "1"), ("b", "2"), ("a", "3")] }
        `shouldBe` ["optParams names the parameter \"a\" twice; a name holds one value"]
      faults d { optOut = "" } `shouldBe` ["optOut must not be empty"]
      -- (and the limits themselves are fine)
      faults d { optOdometryNoise = 1, optSeed = 2 ^ (53 :: Int), optKeys = [(0, 'a')], optSeconds = 0 } `shouldBe` []
    it "names the field that is not finite or not positive, each alone (a frame rate or a scale set to infinity, a negative frame rate, was \"--seconds and --dt must be finite numbers\")" $ do
      let d = defaultSimOptions
      validateOptions d { optFps = 1 / 0 } `shouldBe` ["optFps must be a finite number > 0, got Infinity"]
      validateOptions d { optFps = -25 } `shouldBe` ["optFps must be a finite number > 0, got -25.0"]
      validateOptions d { optScale = Just (1 / 0) }
        `shouldBe` ["optScale must be Nothing (the scale that fits the world) or Just a finite number > 0, got Just Infinity"]
      validateOptions d { optDt = 0 } `shouldBe` ["optDt must be a positive number up to 1000000, got 0.0"]
      validateOptions d { optDt = -0.04, optFps = -25 }
        `shouldBe` ["optDt must be a positive number up to 1000000, got -0.04", "optFps must be a finite number > 0, got -25.0"]
      validateOptions d { optSeconds = 0 / 0 } `shouldBe` ["optSeconds must be a finite number >= 0, got NaN"]
      validateOptions d { optSeconds = 1 / 0 } `shouldBe` ["optSeconds must be a finite number >= 0, got Infinity"]
      validateOptions d { optDumpWorld = True, optPrintProgram = True }
        `shouldBe` ["--dump-world and --print-program (optDumpWorld and optPrintProgram) each print something and exit: ask for one"]
      validateOptions d { optPrintProgram = True } `shouldBe` []
      -- (the settings a command line starts from are set in code: so named)
      parseSimArgs d { optFps = 0 } ["--seconds", "2"] `shouldBe` Left "optFps must be a finite number > 0, got 0.0"
    it "leaves the command line's messages naming its flags (its values are refused by the flags, or found together)" $ do
      let refusal args = either id (const "") (parseSimArgs defaultSimOptions args)
      map refusal [ ["--seconds", "-1"], ["--dt", "0"], ["--fps", "0"], ["--scale", "0"], ["--odometry-noise", "2"]
                  , ["--seed", "1e20"], ["--keys", "-1:a"], ["--out", ""], ["--svg", ""]
                  , ["--seconds", "1e20", "--dt", "0.01"], ["--fps", "30"] ]
        `shouldSatisfy` all (\m -> "--" `isPrefixOf` m && not ("opt" `isInfixOf` m))
    it "refuses both printing modes with one message, naming both flags and both fields, however they were set (by the flags it was one text, in code another)" $ do
      let d = defaultSimOptions
          both = "--dump-world and --print-program (optDumpWorld and optPrintProgram) each print something and exit: ask for one"
      parseSimArgs d ["--dump-world", "--print-program"] `shouldBe` Left both
      parseSimFlags d ["--print-program", "--dump-world", "--svg", ""] `shouldBe` Left both
      parseSimArgs d { optDumpWorld = True } ["--print-program"] `shouldBe` Left both
      validateOptions d { optDumpWorld = True, optPrintProgram = True } `shouldBe` [both]
  describe "readableNumber (the helper once exported as num)" $
    it "writes a number as the messages do: three decimals at most, no trailing zeros, an exponent when far from 1" $
      map readableNumber [25, 0.01, 100 / 3, 0, -2.5, 1e20, 2.5e-4, 1e6]
        `shouldBe` ["25", "0.01", "33.333", "0", "-2.5", "1.000e20", "2.500e-4", "1000000"]
  describe "validateOptions, file names" $ do
    it "refuses an empty file name for every output, before the run" $ do
      let named f o = [ m | m <- validateOptions o, (f ++ " must not be empty") `isPrefixOf` m ]
          d = defaultSimOptions
      map (\(f, o) -> named f o)
          [ ("--svg", d { optSvg = Just "" }), ("--replay", d { optReplay = Just "" })
          , ("--log", d { optLog = Just "" }), ("--result", d { optResult = Just "" })
          , ("--video", d { optVideo = Just "" }) ]
        `shouldSatisfy` all ((== 1) . length)
      [ m | m <- validateOptions d, "must not be empty" `isInfixOf` m ] `shouldBe` []
    it "refuses an empty --world when parsing (it is read before the other checks)" $
      parseSimArgs defaultSimOptions ["--world", ""] `shouldBe` Left "--world must not be empty (a world file's name)"
    it "refuses a --video whose name is no video format's (an image's would write frames), before the run" $ do
      let video v = [ m | m <- validateOptions defaultSimOptions { optVideo = Just v }, "--video" `isPrefixOf` m ]
      video "out/frame-%06d.ppm" `shouldBe`
        [ "--video \"out/frame-%06d.ppm\": a video's name ends in .mp4, .m4v, .mkv, .webm, .mov, .avi, .gif"
          ++ " (ffmpeg picks the format by it; an image's, such as .ppm or .png, would write frames)" ]
      map (length . video) ["run.png", "run.xyz", "run", "mp4", "run.mp4.ppm"] `shouldBe` [1, 1, 1, 1, 1]
      map video ["run.mp4", "RUN.MP4", "a/b.c/run.webm", "x%d.mkv", "-v.gif", "v.m4v", "v.mov", "v.avi"]
        `shouldSatisfy` all null
  describe "parseSimArgs" $ do
    it "moves the default SVG and page into the folder --out names" $
      outputs ["--out", "x"] `shouldBe` Right (Just "x/run.svg", Just "x/replay.html", "x")
    it "keeps a file the command line names where it says, before or after --out" $ do
      outputs ["--svg", "a.svg", "--out", "x"] `shouldBe` Right (Just "a.svg", Just "x/replay.html", "x")
      outputs ["--out", "x", "--svg", "a.svg"] `shouldBe` Right (Just "a.svg", Just "x/replay.html", "x")
    it "keeps a named file even when it is the default folder's default name" $
      outputs ["--svg", "simbot-out/run.svg", "--replay", "simbot-out/replay.html", "--out", "x"]
        `shouldBe` Right (Just "simbot-out/run.svg", Just "simbot-out/replay.html", "x")
    it "--no-svg and --no-replay hold in any order with --out" $
      outputs ["--no-svg", "--out", "x", "--no-replay"] `shouldBe` Right (Nothing, Nothing, "x")
    it "gives the same outputs for every order of the flags" $ do
      let groups = [["--out", "x"], ["--svg", "p/a.svg"], ["--no-replay"], ["--seconds", "2"], ["--out", "y"]]
          -- the later --out wins, so keep the two in their order
          ordered g = let outs = [ v | ["--out", v] <- g ] in outs == ["x", "y"]
          results = [ outputs (concat g) | g <- permutations groups, ordered g ]
      length results `shouldBe` 60
      results `shouldSatisfy` all (== Right (Just "p/a.svg", Nothing, "y"))
    it "takes no flag as the value of a flag that needs one" $ do
      outputs ["--out", "--no-svg"] `shouldSatisfy` either ("--out needs a value" `isInfixOf`) (const False)
      outputs ["--svg", "--quiet"] `shouldSatisfy` either ("--svg needs a value" `isInfixOf`) (const False)
      outputs ["--seconds", "--dt", "0.02"] `shouldSatisfy` either ("--seconds needs a value" `isInfixOf`) (const False)
      outputs ["--out", "./--no-svg"] `shouldBe` Right (Just "./--no-svg/run.svg", Just "./--no-svg/replay.html", "./--no-svg")
      fmap (const ()) (parseSimArgs defaultSimOptions ["--seconds", "-1"]) `shouldSatisfy` either ("non-negative" `isInfixOf`) (const False)
    it "reads numbers as a world file writes them, not in Haskell's other forms" $ do
      let secs args = case parseSimArgs defaultSimOptions ("--seconds" : args) of
            Right (RunWith o) -> Right (optSeconds o)
            Right ShowHelp    -> Left "help"
            Left err          -> Left err
      map (\v -> secs [v]) ["+5", "2.5", "1e2", "1.5E-1", " 3 ", "0"]
        `shouldBe` map Right [5, 2.5, 100, 0.15, 3, 0]
      mapM_ (\v -> secs [v] `shouldSatisfy` either ("--seconds expects a non-negative number (written as in a world file" `isInfixOf`) (const False))
            ["0x10", ".5", "5.", ".", "+", "1e", "1e+", "NaN", "Infinity", "1..2", "5 s", "-1", "--5"]
      let seedOf v = case parseSimArgs defaultSimOptions ["--seed", v] of
            Right (RunWith o) -> Just (optSeed o)
            _                 -> Nothing
      map seedOf ["7", "+7", "-7", "0x10", "1.0", "07"] `shouldBe` [Just 7, Just 7, Just (-7), Nothing, Nothing, Just 7]
      let keysOf v = case parseSimArgs defaultSimOptions ["--keys", v] of
            Right (RunWith o) -> Just (optKeys o)
            _                 -> Nothing
      keysOf "0.5:a,2:b" `shouldBe` Just [(0.5, 'a'), (2, 'b')]
      keysOf "0x1:a" `shouldBe` Nothing
    it "takes a --seed up to 2^53 either way and refuses a larger one rather than wrap it round" $ do
      let seed args = case parseSimArgs defaultSimOptions args of
            Right (RunWith o) -> Right (optSeed o)
            Right ShowHelp    -> Left "help"
            Left err          -> Left err
      seed ["--seed", "9007199254740992"] `shouldBe` Right 9007199254740992
      seed ["--seed", "-9007199254740992"] `shouldBe` Right (-9007199254740992)
      seed ["--seed", "9007199254740993"] `shouldSatisfy` either ("--seed" `isInfixOf`) (const False)
      seed ["--seed", "18446744073709551617"] `shouldSatisfy` either ("--seed" `isInfixOf`) (const False)
    it "refuses --seconds greater than 0 that is less than half a step: a run of no step after time 0" $ do
      let run args = fmap (const ()) (parseSimArgs defaultSimOptions args)
      run ["--seconds", "0.004", "--dt", "0.01"] `shouldSatisfy` either ("less than half a step" `isInfixOf`) (const False)
      run ["--seconds", "0.0049", "--dt", "0.01"] `shouldSatisfy` either ("give --seconds 0.005 or more" `isInfixOf`) (const False)
      -- (exactly half a step was refused: a tie rounded to the even 0)
      run ["--seconds", "0.005", "--dt", "0.01"] `shouldBe` Right ()
      run ["--seconds", "0.006", "--dt", "0.01"] `shouldBe` Right ()
      run ["--seconds", "0", "--dt", "0.01"] `shouldBe` Right ()
    it "runSteps takes the whole number of steps nearest seconds / dt, a half rounded up, written in decimals too" $ do
      let steps secs dt = runSteps defaultSimOptions { optSeconds = secs, optDt = dt }
      -- (0.15 / 0.1 and 0.35 / 0.1 are a little under 1.5 and 3.5 as computed)
      map (uncurry steps) [(0.005, 0.01), (0.25, 0.1), (0.15, 0.1), (0.35, 0.1), (0.95, 0.1), (1.45, 0.1), (0.145, 0.01)]
        `shouldBe` [1, 3, 2, 4, 10, 15, 15]
      map (uncurry steps) [(0.0049, 0.01), (0.14, 0.1), (30, 0.01), (0, 0.01), (0.3, 0.1)]
        `shouldBe` [0, 1, 3000, 0, 3]
      -- (every half of a step written in decimals, from 0.05 to 99.95 at dt 0.1)
      [ k | k <- [0 .. 999 :: Int], steps (read (show k ++ ".5") / 10) 0.1 /= k + 1 ] `shouldBe` []
    it "suggests a --seconds it takes, written in full" $ do
      let run args = fmap (const ()) (parseSimArgs defaultSimOptions args)
      run ["--seconds", "0.001", "--dt", "0.0025", "--fps", "400"]
        `shouldSatisfy` either ("--seconds 0.001 with --dt 0.0025 is less than half a step" `isInfixOf`) (const False)
      run ["--seconds", "0.001", "--dt", "0.0025", "--fps", "400"]
        `shouldSatisfy` either ("give --seconds 0.00125 or more" `isInfixOf`) (const False)
      run ["--seconds", "1e-301", "--dt", "1e-300", "--fps", "1e299"]
        `shouldSatisfy` either ("give --seconds 5.0e-301 or more" `isInfixOf`) (const False)
    it "takes a run of exactly maxSteps steps however its quotient rounds (900000 s at dt 0.009)" $ do
      let run args = fmap (const ()) (parseSimArgs defaultSimOptions args)
      run ["--seconds", "900000", "--dt", "0.009", "--fps", "111.111"] `shouldBe` Right ()
      run ["--seconds", "900010", "--dt", "0.009", "--fps", "111.111"]
        `shouldSatisfy` either ("more than the" `isInfixOf`) (const False)
      run ["--seconds", "0.00125", "--dt", "0.0025", "--fps", "400"] `shouldBe` Right ()
    it "refuses a --dt beyond maxTimeStep and an --odometry-noise beyond maxOdometryNoise (a robot's pose became NaN)" $ do
      let run args = fmap (const ()) (parseSimArgs defaultSimOptions args)
      run ["--dt", "1e6", "--fps", "1e-6", "--seconds", "1e7"] `shouldBe` Right ()
      run ["--dt", "1.5e6", "--fps", "1e-7", "--seconds", "1e7"] `shouldSatisfy` either ("--dt expects a positive number up to" `isInfixOf`) (const False)
      run ["--odometry-noise", "1"] `shouldBe` Right ()
      mapM_ (\v -> run ["--odometry-noise", v] `shouldSatisfy` either ("--odometry-noise expects a number from 0 to 1" `isInfixOf`) (const False))
            ["1.01", "1e308", "-0.5"]
    it "refuses a --keys time that is not a finite number (Infinity, 1e400, NaN)" $ do
      parseKeys "1.5:a,3:b" `shouldBe` Right [(1.5, 'a'), (3, 'b')]
      mapM_ (\k -> parseKeys k `shouldSatisfy` either ("--keys" `isInfixOf`) (const False))
            ["Infinity:a", "1e400:a", "1:a,NaN:b"]
    it "takes the presses of every --keys given, not only the last one's" $
      fmap (\c -> case c of { RunWith o -> optKeys o; ShowHelp -> [] })
           (parseSimArgs defaultSimOptions ["--keys", "3:b", "--seed", "1", "--keys", "1:a,2:space"])
        `shouldBe` Right [(3, 'b'), (1, 'a'), (2, ' ')]
    it "says a step count too large for a number as that, not as Infinity steps" $
      validateOptions defaultSimOptions { optSeconds = 1e300, optDt = 1e-300 }
        `shouldSatisfy` any ("--seconds 1.000e300 with --dt 1.000e-300 is more steps than a number holds, more than the" `isPrefixOf`)
    it "refuses a --scale that draws the world less than minWorldPixels across, and takes one just enough" $ do
      let notes = Bounds (-5) (-5) 5 5
          small o = [ m | m <- validateOptionsIn notes o, "too small" `isInfixOf` m ]
      small defaultSimOptions { optScale = Just 0.001 } `shouldBe`
        [ "--scale 0.001 draws this 10 by 10 m world 0.01 pixels across, too small to show it (at least 10;"
          ++ " without --scale it is 600)" ]
      small defaultSimOptions { optScale = Just 0.999 } `shouldSatisfy` ((== 1) . length)
      small defaultSimOptions { optScale = Just 1 } `shouldBe` []
      small defaultSimOptions `shouldBe` []
      -- (the long side counts: a world 100 m by 1 m at 0.1 pixels a metre is 10 pixels wide)
      [ m | m <- validateOptionsIn (Bounds 0 0 100 1) defaultSimOptions { optScale = Just 0.1 }, "too small" `isInfixOf` m ]
        `shouldBe` []
    it "reads a --param's name given in a locale that is not UTF-8 as the text it spells (it was no parameter the controller asks for); keeps its value as given (a file's name opens)" $
      fmap' optParams (parseSimArgs defaultSimOptions ["--param", cLocale "naïve=∑ 1", "--param", "a\56575=b"])
        `shouldBe` Right [("naïve", cLocale "∑ 1"), ("a\56575", "b")]
    it "keeps each --param name the command line repeats with all its values (it kept the last alone, the repeat unseen)" $ do
      let parsed' args = case parseSimArgs defaultSimOptions args of
            Right (RunWith o) -> Right (optParams o, optParamsRepeated o)
            other             -> Left (show other)
      parsed' ["--param", "a=1", "--param", "b=2", "--param", "a=3", "--param", "b=2", "--param", "a=4", "--param", "c="]
        `shouldBe` Right ([("a", "4"), ("b", "2"), ("c", "")], [("a", ["1", "3", "4"]), ("b", ["2", "2"])])
      parsed' ["--param", "a=1", "--param", "b=2"] `shouldBe` Right ([("a", "1"), ("b", "2")], [])
      -- (a value of the given settings that the command line replaces is no repeat)
      fmap' optParamsRepeated (parseSimArgs defaultSimOptions { optParams = [("a", "0")] } ["--param", "a=1"])
        `shouldBe` Right []
    it "keeps each flag with one value that the command line repeats, with all its values (the last was used, the repeat unseen)" $ do
      let repeated o args = fmap' (\o' -> (optFlagsRepeated o', optSeconds o', optWorldFile o')) (parseSimArgs o args)
      repeated defaultSimOptions ["--seconds", "2", "--world", "a.world", "--seconds", "3", "--world", "b.world", "--seconds", "2"]
        `shouldBe` Right ([("--seconds", ["2", "3", "2"]), ("--world", ["a.world", "b.world"])], 2, Just "b.world")
      -- (--keys adds its presses, --param has its own list, a flag
      -- without a value is no repeat)
      fmap' optFlagsRepeated (parseSimArgs defaultSimOptions
        ["--keys", "1:a", "--keys", "2:b", "--param", "a=1", "--param", "a=2", "--no-svg", "--svg", "x.svg", "--quiet", "--quiet"])
        `shouldBe` Right []
      fmap' optFlagsRepeated (parseSimArgs defaultSimOptions ["--svg", "a.svg", "--no-svg", "--svg", "b.svg", "--out", "", "--out", "o"])
        `shouldSatisfy` either ("--out expects a folder name" `isInfixOf`) (const False)
      fmap' optFlagsRepeated (parseSimArgs defaultSimOptions ["--svg", "a.svg", "--no-svg", "--svg", "b.svg"])
        `shouldBe` Right [("--svg", ["a.svg", "b.svg"])]
      -- (undone by a last --no-svg or --no-replay, no value is used: none
      -- is said to be; it said the last was)
      fmap' optFlagsRepeated (parseSimArgs defaultSimOptions
        ["--svg", "a.svg", "--svg", "b.svg", "--no-svg", "--replay", "p.html", "--replay", "q.html", "--no-replay"])
        `shouldBe` Right []
      -- (a value of the given settings that the command line replaces is no repeat)
      repeated defaultSimOptions { optSeconds = 5, optFlagsRepeated = [("--dt", ["1", "2"])] } ["--seconds", "1"]
        `shouldBe` Right ([("--dt", ["1", "2"])], 1, Nothing)
    it "says a --param without = as text, in a locale that is not UTF-8 too" $
      parseParam (cLocale "naïve") `shouldBe` Left ("--param expects NAME=VALUE, got " ++ show "naïve")
  describe "argText" $ do
    it "decodes the stand-ins of UTF-8 bytes (the C locale's) as the characters they spell" $ do
      argText (cLocale "wé.world") `shouldBe` "wé.world"
      argText (cLocale "€ and 𝄞, plain ASCII") `shouldBe` "€ and 𝄞, plain ASCII"
    it "leaves text without stand-ins as it is" $
      property $ \t -> let s = filter (not . standIn) t in argText s === s
    it "round-trips any text through its UTF-8 bytes as stand-ins" $
      property $ \t -> let s = filter (\c -> not (standIn c) && (c < '\xD800' || c > '\xDFFF')) t
                      in argText (cLocale s) === s
    it "keeps a stand-in that is no UTF-8: a lone continuation byte, an overlong form, a surrogate, a cut sequence" $
      mapM_ (\bytes -> let s = map (toEnum . (0xDC00 +)) bytes in argText ("x" ++ s ++ "y") `shouldBe` "x" ++ s ++ "y")
        [ [0x80], [0xFF], [0xC0, 0x80], [0xC1, 0xBF], [0xE0, 0x80, 0x80], [0xED, 0xA0, 0x80]
        , [0xF4, 0x90, 0x80, 0x80], [0xF0, 0x9D, 0x84], [0xC3] ]
    it "decodes the well-formed part of a run and keeps the rest" $
      argText ("a" ++ cLocale "é" ++ "\56575" ++ cLocale "ü") `shouldBe` "aé\56575ü"
  describe "parseKeys" $
    it "scripts the space and comma keys by name (the list cannot hold them), any other key as one character" $ do
      parseKeys "1:space, 2:COMMA,3::,4:s" `shouldBe` Right [(1, ' '), (2, ','), (3, ':'), (4, 's')]
      mapM_ (\k -> parseKeys k `shouldSatisfy` either ("a KEY is one character, or space or comma" `isInfixOf`) (const False))
            ["1:", "1:ab", "1:spacebar", "1: "]

-- | A stand-in of a byte (U+DC80 to U+DCFF).
standIn :: Char -> Bool
standIn c = c >= '\xDC80' && c <= '\xDCFF'

-- | 'fmap' on the options a command line runs with.
fmap' :: (SimOptions -> a) -> Either String Command -> Either String a
fmap' f r = case r of
  Right (RunWith o) -> Right (f o)
  Right ShowHelp    -> Left "help"
  Left err          -> Left err

-- | The text from the last occurrence of a pattern on (and what is before
-- it), or the whole text and nothing when it does not occur.
breakOn :: String -> String -> (String, String)
breakOn pat txt = case [ i | (i, t) <- zip [0 ..] (tails txt), pat `isPrefixOf` t ] of
  [] -> (txt, "")
  is -> splitAt (last is) txt
