module AFRP.RunSpec (spec) where

import           Control.Arrow     (arr, loop, second, (>>>))
import           Control.Exception (ErrorCall (..), evaluate)
import           Data.IORef
import           Data.List         (isPrefixOf)
import           Test.Hspec

import           AFRP.Basic        (constant, identity, localTime, time)
import           AFRP.Delay        (iPre)
import           AFRP.Integration  (integral)
import           AFRP.Internal.SF  (SF)
import           AFRP.Run
import           TestUtil

spec :: Spec
spec = do
  describe "embed" $ do
    it "gives one output per sample, the first at time 0" $
      embed integral (1, [(0.5, Just 2), (0.5, Nothing)]) `shouldBe` [0, 0.5, 1.5 :: Double]
    it "Nothing means the input is unchanged" $
      embed identity ('a', [(1, Nothing), (1, Just 'b'), (1, Nothing)]) `shouldBe` "aabb"
    it "runs 10^6 samples of an integral without trouble" $
      last (embed integral (1, replicate 1000000 (0.001, Nothing))) `shouldApprox` (1000 :: Double)
    it "evaluates a later sample's input when the list goes past it, as Yampa's, and no output" $ do
      -- the input of sample 1 is not needed for its own output (a delay)
      take 2 (embed (iPre 0) (1, [(1, Just undefined), (1, Just (3 :: Int))])) `shouldBe` [0, 1]
      -- ... but is evaluated before the list goes on
      evaluate (length (embed (iPre 0) (1, [(1, Just undefined), (1, Just (3 :: Int))])))
        `shouldThrow` errorCall "Prelude.undefined"
      -- no output is (where Yampa's evaluates all but the first)
      length (embed (arr (\x -> if x == 2 then error "boom" else x)) (1, [(1, Just 2), (1, Just (3 :: Int))]))
        `shouldBe` 3

  describe "reactimate" $ do
    it "senses, steps and actuates until actuate says stop" $ do
      inputs <- newIORef [(0.5, Just 2), (0.5, Nothing), (0.5, Just 4)]
      outs <- newIORef []
      let sense _ = atomicModifyIORef' inputs (\xs -> (drop 1 xs, head' xs))
          head' (x : _) = x
          head' []      = (0.5, Nothing)
          actuate _ b = do
            modifyIORef outs (b :)
            pure (b >= (2 :: Double))
      reactimate (pure 1) sense actuate integral
      reverse <$> readIORef outs `shouldReturn` [0, 0.5, 1.5, 2.5]
    it "evaluates each sample's input and output after actuating it, as Yampa's" $ do
      actuated <- newIORef (0 :: Int)
      let actuate _ _ = modifyIORef actuated (+ 1) >> (>= 3) <$> readIORef actuated
      reactimate (pure 1) (\_ -> pure (1, Just 2)) actuate (arr (\x -> if x == 2 then error "boom" else x :: Int))
        `shouldThrow` errorCall "boom"
      readIORef actuated `shouldReturn` 2
      -- the first input and output too, even when the first actuation stops the loop
      reactimate (pure (error "input")) (\_ -> pure (1, Nothing)) (\_ _ -> pure True) (constant 'c')
        `shouldThrow` errorCall "input"
      reactimate (pure 'i') (\_ -> pure (1, Nothing)) (\_ _ -> pure True) (arr (\_ -> error "output" :: Char))
        `shouldThrow` errorCall "output"
    it "stops before any step when the first actuate says so" $ do
      steps <- newIORef (0 :: Int)
      reactimate (pure ()) (\_ -> modifyIORef steps (+ 1) >> pure (1, Nothing))
                 (\_ _ -> pure True) (constant ())
      readIORef steps `shouldReturn` 0

  describe "reactInit and react" $ do
    it "drive a signal function one step at a time" $ do
      outs <- newIORef []
      h <- reactInit (pure (1 :: Double)) (\_ _ b -> modifyIORef outs (b :) >> pure False) integral
      _ <- react h (0.5, Nothing)
      stop <- react h (0.5, Just 3)
      stop `shouldBe` False
      reverse <$> readIORef outs `shouldReturn` [0, 0.5, 1]
    it "react evaluates neither the input nor the output, as Yampa's" $ do
      h <- reactInit (pure (1 :: Int)) (\_ _ _ -> pure False) (arr (\x -> if x == 2 then error "unused" else 'c'))
      react h (1, Just undefined) `shouldReturn` False
      react h (1, Just 2) `shouldReturn` False

  describe "evalAtZero and evalAt" $
    it "step a signal function by hand exactly as embed does" $ do
      let (b0, f0) = evalAtZero integral (1 :: Double)
          (b1, f1) = evalAt f0 0.5 2
          (b2, _)  = evalAt f1 0.5 2
      [b0, b1, b2] `shouldBe` embed integral (1, [(0.5, Just 2), (0.5, Nothing)])

  describe "embedSynch" $ do
    let inner = embed localTime ((), replicate 10 (0.5, Nothing))
    it "replays at ratio 1 in step with the outer time" $
      runDt 0.5 (embedSynch localTime ((), replicate 10 (0.5, Nothing))) (replicate 4 1)
        `shouldBe` take 4 inner
    it "pauses at ratio 0 and runs faster at ratio 2" $
      runDt 0.5 (embedSynch localTime ((), replicate 10 (0.5, Nothing))) [1, 0, 0, 2, 2]
        `shouldBe` [0, 0, 0, 1, 2]
    it "holds the last output after the embedded samples run out" $
      last (runDt 1 (embedSynch localTime ((), replicate 2 (0.5, Nothing))) (replicate 5 1))
        `shouldBe` 1
    it "rejects a negative ratio" $
      evaluate (last (runDt 1 (embedSynch identity ('a', [])) [1, -1]))
        `shouldThrow` anyErrorCall
    it "rejects a NaN ratio (it froze the replay silently)" $
      evaluate (last (runDt 1 (embedSynch identity ('a', [])) [1, 0 / 0]))
        `shouldThrow` anyErrorCall
    it "does not read its ratio before its output is demanded: the ratio may come through a loop (it was <<loop>>)" $
      withoutHanging (embed (loop (second (embedSynch localTime ((), replicate 4 (0.5, Nothing)))
                                   >>> arr (\(a, b) -> ((a, b), a))))
                            (1 :: Double, [(0.5, Just 2), (0.5, Just 2)]))
                     [(1, 0), (2, 1), (2, 2)]
    it "does not read its ratio at local time 0 (as Yampa)" $
      embed (embedSynch localTime ((), [(1, Nothing)])) (-1, [(1, Just 1)]) `shouldBe` [0, 1]
    it "pauses at ratio 0 over an infinite step, and resumes (0 * Infinity froze it for good)" $
      embed (embedSynch localTime ((), replicate 10 (0.5, Nothing)))
            (1, [(1, Just 1), (1 / 0, Just 0), (1, Just 1), (1, Just 1)])
        `shouldBe` [0, 1, 1, 2, 3]
    it "advances nothing over a step of 0 at an infinite ratio, then jumps to the end" $
      embed (embedSynch localTime ((), replicate 10 (0.5, Nothing)))
            (1, [(1, Just 1), (0, Just (1 / 0)), (1, Just 1), (1, Just (1 / 0))])
        `shouldBe` [0, 1, 1, 2, 5]

  describe "time steps" $ do
    -- (a NaN step made the time NaN for ever, silently; a negative one ran
    -- time backwards)
    let refused runner dt = \(ErrorCall msg) ->
          msg == "AFRP.Run." ++ runner ++ ": a time step of " ++ show (dt :: Double)
                 ++ " (a time step must be a number, 0 or more)"
        bad = [0 / 0, -1, -1e-300, -(1 / 0)]
    it "embed refuses a time step that is NaN or negative, at that step" $
      mapM_ (\dt -> do
               let out = embed time ((), [(1, Nothing), (dt, Nothing), (1, Nothing)])
               take 2 out `shouldBe` [0, 1]
               evaluate (out !! 2) `shouldThrow` refused "embed" dt)
            bad
    it "the runners check the step even when the signal function does not read it" $
      mapM_ (\dt -> do
               evaluate (embed identity (0 :: Int, [(1, Just 1), (dt, Just 2), (1, Just 3)]) !! 2)
                 `shouldThrow` refused "embed" dt
               let (_, future) = evalAtZero identity (1 :: Int)
               evaluate (fst (evalAt future dt 2)) `shouldThrow` refused "evalAt" dt
               evaluate (snd (evalFuture (constant 'c') () dt)) `shouldThrow` refused "evalFuture" dt)
            bad
    it "embed takes a step of 0, the smallest and largest finite steps, and an infinite one" $ do
      embed time ((), [(0, Nothing), (0, Nothing), (1, Nothing)]) `shouldBe` [0, 0, 0, 1]
      embed time ((), [(5e-324, Nothing), (1.7976931348623157e308, Nothing), (1 / 0, Nothing)])
        `shouldBe` [0, 5e-324, 1.7976931348623157e308, 1 / 0]
    it "reactimate, react, evalAt, evalFuture and deltaEncode refuse one too" $
      mapM_ (\dt -> do
               steps <- newIORef [(1, Nothing), (dt, Nothing)]
               let sense _ = atomicModifyIORef' steps (\ss -> case ss of
                               s : rest -> (rest, s)
                               []       -> ([], (1, Nothing)))
               reactimate (pure ()) sense (\_ _ -> pure False) time `shouldThrow` refused "reactimate" dt
               h <- reactInit (pure ()) (\_ _ _ -> pure False) time
               _ <- react h (1, Nothing)
               react h (dt, Nothing) `shouldThrow` refused "react" dt
               let (_, future) = evalAtZero time ()
               evaluate (fst (evalAt future dt ())) `shouldThrow` refused "evalAt" dt
               evaluate (fst (embedFirst (snd (evalFuture time () dt))))
                 `shouldThrow` refused "evalFuture" dt
               evaluate (fst (head (snd (deltaEncode dt "ab")))) `shouldThrow` refused "deltaEncode" dt)
            bad

  describe "deltaEncode" $ do
    it "writes Nothing for repeated samples" $
      deltaEncode 0.1 "aabca" `shouldBe` ('a', [(0.1, Nothing), (0.1, Just 'b'), (0.1, Just 'c'), (0.1, Just 'a')])
    it "round-trips through embed" $
      embed identity (deltaEncode 0.1 "aabca") `shouldBe` "aabca"
    it "names the function called in its errors (deltaEncodeBy's named deltaEncode, and the other way round)" $ do
      evaluate (deltaEncode 0.5 "") `shouldThrow` errorCall "AFRP.Run.deltaEncode: empty list of samples"
      evaluate (deltaEncodeBy (==) 0.5 "") `shouldThrow` errorCall "AFRP.Run.deltaEncodeBy: empty list of samples"
      evaluate (fst (head (snd (deltaEncodeBy (==) (-1) "ab"))))
        `shouldThrow` (\(ErrorCall m) -> "AFRP.Run.deltaEncodeBy: a time step of -1.0" `isPrefixOf` m)
    it "deltaEncodeBy compares each sample with the one before it, as Yampa does (not with the last written)" $
      deltaEncodeBy (\a b -> abs (a - b) < 2) 0.5 [1, 2, 3, 4, 8, 9 :: Double]
        `shouldBe` (1, [(0.5, Nothing), (0.5, Nothing), (0.5, Nothing), (0.5, Just 8), (0.5, Nothing)])
    it "deltaEncodeBy gives the new sample first to the equality, as Yampa does" $
      deltaEncodeBy (<) 1 [1, 2, 3, 1 :: Int] `shouldBe` (1, [(1, Just 2), (1, Just 3), (1, Nothing)])
    it "deltaEncodeBy uses the given equality" $
      snd (deltaEncodeBy (\x y -> abs (x - y) < 1) 1 [1, 1.5, 3 :: Double])
        `shouldBe` [(1, Nothing), (1, Just 3)]
    it "rejects an empty list" $
      evaluate (deltaEncode 0.1 ([] :: [Int])) `shouldThrow` anyErrorCall

-- The first output of a signal function on unit input, and the rest.
embedFirst :: SF () b -> (b, [b])
embedFirst sf = case embed sf ((), []) of
  b : bs -> (b, bs)
  []     -> error "embed gave no output"
