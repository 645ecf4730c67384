module AFRP.Test.LTLSpec (spec) where

import           Control.Exception (evaluate)
import           System.Timeout   (timeout)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP             (DTime, SF, arr, iPre, localTime, sscan, (>>>))
import           AFRP.Test.LTL
import           AFRP.Test.QuickCheck
import           AFRP.Test.Stream

-- A formula, as data that can be shown, over four atoms (two of them with
-- state, to see that atoms keep their state from time 0). 'genF' makes
-- no time bounds (the reference has none); 'genFBounded' does.
data F = Atom Int | FAnd F F | FOr F F | FNot F | FImplies F F | FAlways F
       | FEventually F | FNext F | FUntil F F | FWithin DTime F | FFor DTime F
  deriving (Show)

genF :: Int -> Gen F
genF 0 = Atom <$> chooseInt (0, 3)
genF k = oneof
  [ Atom <$> chooseInt (0, 3), FAnd <$> sub <*> sub, FOr <$> sub <*> sub, FNot <$> sub
  , FImplies <$> sub <*> sub, FAlways <$> sub, FEventually <$> sub, FNext <$> sub, FUntil <$> sub <*> sub ]
  where sub = genF (k - 1)

genFBounded :: Int -> Gen F
genFBounded 0 = genF 0
genFBounded k = frequency
  [ (4, genF k), (1, FWithin <$> bound <*> sub), (1, FFor <$> bound <*> sub)
  , (2, FAnd <$> sub <*> sub), (2, FAlways <$> sub), (1, FNext <$> sub), (1, FUntil <$> sub <*> sub) ]
  where
    sub = genFBounded (k - 1)
    bound = elements [0, 0.25, 0.5, 1, 2]

atom :: Int -> SF Int Bool
atom 0 = arr even
atom 1 = arr (> 0)
atom 2 = iPre 0 >>> arr (< 0)
atom _ = localTime >>> arr (< 1)

toTPred :: F -> TPred Int
toTPred f = case f of
  Atom k        -> SP (atom k)
  FAnd a b      -> And (toTPred a) (toTPred b)
  FOr a b       -> Or (toTPred a) (toTPred b)
  FNot a        -> Not (toTPred a)
  FImplies a b  -> Implies (toTPred a) (toTPred b)
  FAlways a     -> Always (toTPred a)
  FEventually a -> Eventually (toTPred a)
  FNext a       -> Next (toTPred a)
  FUntil a b    -> Until (toTPred a) (toTPred b)
  FWithin d a   -> eventuallyWithin d (toTPred a)
  FFor d a      -> alwaysFor d (toTPred a)

-- The reference: yampa-test's recursive definition read at sample i of
-- a stream of n samples, each atom run over the whole stream.
reference :: F -> SignalSampleStream Int -> Bool
reference f0 s = at f0 0
  where
    n = length s
    at f i = case f of
      Atom k        -> samples (fst (evalSF (atom k) s)) !! i
      FAnd a b      -> at a i && at b i
      FOr a b       -> at a i || at b i
      FNot a        -> not (at a i)
      FImplies a b  -> not (at a i) || at b i
      FAlways a     -> at a i && next (FAlways a) i
      FEventually a -> if i == n - 1 then at a i else at a i || at (FEventually a) (i + 1)
      FNext a       -> next a i
      FUntil a b    -> (at a i && next (FUntil a b) i) || at b i
      FWithin _ _   -> error "the reference has no time bounds (genF makes none)"
      FFor _ _      -> error "the reference has no time bounds (genF makes none)"
    next f i = i == n - 1 || at f (i + 1)

-- The reference for 'explainT' (and 'evalT') with the time bounds:
-- Kleene's three-valued reading of the formula at time 0 of the first k
-- samples, the samples beyond unknown (or, for the whole stream, the
-- end's meaning), computed from the end of the samples for each k; the
-- failure is at the first k on which it is false. (This was the kit's
-- own explainT, a search over prefixes that kept the stream; explainT is
-- now a monitor that reads the stream once, and must agree with it.)
data Tri = TF | TU | TT
  deriving (Eq, Ord, Show)

-- @truthsOn closed m f s@: the truth of @f@ at each of the first @m@
-- samples of @s@, the samples beyond the m-th unknown unless @closed@
-- (then @m@ is the whole stream).
truthsOn :: Bool -> Int -> F -> SignalSampleStream Int -> [Tri]
truthsOn closed m f0 s = go f0
  where
    prefix = take m s
    tri b = if b then TT else TF
    notT v = case v of { TT -> TF; TF -> TT; TU -> TU }
    beyond = if closed then TT else TU
    go f = case f of
      Atom k        -> map tri (take m (samples (fst (evalSF (atom k) s))))
      FAnd a b      -> zipWith min (go a) (go b)
      FOr a b       -> zipWith max (go a) (go b)
      FNot a        -> map notT (go a)
      FImplies a b  -> zipWith max (map notT (go a)) (go b)
      FNext a       -> drop 1 (go a) ++ [beyond]
      FAlways a     -> scanr1' min beyond (go a)
      FEventually a -> scanr1' max (if closed then TF else TU) (go a)
      FUntil a b    -> let step (va, vb) next = max vb (min va next)
                       in init (scanr step beyond (zip (go a) (go b)))
      FWithin d a   -> windows d (go a) max TF
      FFor d a      -> windows d (go a) min TT
    scanr1' op end vs = init (scanr op end vs)
    -- (the window from each sample to d seconds after it, its times
    -- counted from that sample by the library's clock, with the slack of
    -- timeSlack: complete when a sample beyond it was seen, or on a
    -- closed stream when a sample in it is at d; otherwise the end
    -- decides, true when closed, unknown when not)
    windows d vs combine unit =
      [ let elapsed = sampleTimes (sRestart suffix)
            slack = timeSlack d
            (inWindow, after') = span ((<= d + slack) . fst) (zip elapsed vsFrom)
            reachedBound = not (isInfinite d) && any ((>= d - slack) . fst) inWindow
            end | not (null after') = unit
                | closed            = if reachedBound then unit else TT
                | otherwise         = TU
        in foldr (combine . snd) end inWindow
      | (suffix, vsFrom) <- zip (tails' prefix) (tails' vs) ]
    tails' xs = case xs of
      []       -> []
      _ : rest -> xs : tails' rest

-- The reference's failure: the index and time of the sample at which the
-- formula was decided false, or Nothing when it holds.
referenceFailure :: F -> SignalSampleStream Int -> Maybe (Int, DTime)
referenceFailure f s
  | null s || atZero (truthsOn True n f s) == TT = Nothing
  | otherwise = Just (k - 1, sampleTimes s !! (k - 1))
  where
    n = length s
    atZero vs = case vs of { v : _ -> v; [] -> TT }
    k = head ([ j | j <- [1 .. n - 1], atZero (truthsOn False j f s) == TF ] ++ [n])

-- Streams of up to 12 samples whose time steps are 0, 0.25, 0.3 or a
-- random one up to 0.6: steps of 0 (two samples at one time) and sums
-- that land near a bound (0.25 + 0.25 = 0.5; three steps of 0.3 are not
-- 0.9 in binary) are where windows go wrong.
windowStreams :: Gen (SignalSampleStream Int)
windowStreams = do
  n <- chooseInt (1, 12)
  values <- vectorOf n (chooseInt (-3, 3))
  dts <- vectorOf (n - 1) (oneof [pure 0, pure 0.25, pure 0.3, choose (0, 0.6)])
  pure (groupDeltas values dts)

-- A predicate on the current sample only.
is :: (a -> Bool) -> TPred a
is f = SP (arr f)

-- The first n samples of a stream, and an error past them.
readNoFurther :: Int -> SignalSampleStream a -> SignalSampleStream a
readNoFurther n s = take n s ++ error ("the stream was read past sample " ++ show n)

-- Views of a stream of Int for tPredOn: without state, with state (a
-- running sum, a delay whose time 0 is its initial value), and of the
-- clock.
view :: Int -> SF Int Int
view 0 = arr negate
view 1 = sscan (+) 0
view 2 = iPre 5
view _ = localTime >>> arr (\t -> floor (t * 3))

-- Ten samples 0.1 s apart with the values 0..9.
count :: SignalSampleStream Int
count = groupDeltas [0 .. 9] (repeat 0.1)

spec :: Spec
spec = do
  describe "evalT against yampa-test's recursive definition (property)" $ do
    it "agrees on random formulas and streams" $
      forAll (genF 3) $ \f -> forAllStreams (generateStream DistRandom (Nothing, Just 0.5) (Just (Left 12))) $ \s ->
        evalT (toTPred f) s === reference f s
    it "explainT explains exactly the failures" $
      forAll (genF 3) $ \f -> forAllStreams (generateStream DistRandom (Nothing, Just 0.5) (Just (Left 12))) $ \s ->
        fmap (const ()) (explainT (toTPred f) s) === (if evalT (toTPred f) s then Nothing else Just ())
    it "explainT decides at the first prefix on which Kleene's reading of the formula is false, time bounds included" $
      forAllShow ((,) <$> genFBounded 4 <*> windowStreams) show $ \(f, s) ->
        let explained = fmap (\e -> (explFrame e, explTime e)) (explainT (toTPred f) s)
            shown = fmap (map (\(j, t, _) -> (j, t)) . explAround) (explainT (toTPred f) s)
            expectedAround = fmap (\(i, _) -> [ (j, t) | (j, t) <- zip [0 ..] (sampleTimes s), j >= i - 3, j <= i + 2 ]) explained
        in explained === referenceFailure f s
           .&&. evalT (toTPred f) s === (referenceFailure f s == Nothing)
           .&&. shown === expectedAround
  describe "tPredOn, a predicate on a view of the samples" $ do
    it "is the predicate on the stream of the view's outputs, and explained at the same instant (property)" $
      forAll (genFBounded 3) $ \f -> forAll (chooseInt (0, 3)) $ \v ->
        forAllStreams (generateStream DistRandom (Nothing, Just 0.5) (Just (Left 12))) $ \s ->
          let viewed = fst (evalSF (view v) s)
              instant = fmap (\e -> (explFrame e, explTime e))
          in evalT (tPredOn (view v) (toTPred f)) s === evalT (toTPred f) viewed
             .&&. instant (explainT (tPredOn (view v) (toTPred f)) s) === instant (explainT (toTPred f) viewed)
    it "sees the view's output at time 0 at the first sample (a delay's initial value) (fixed)" $ do
      evalT (tPredOn (iPre 7) (is (== 7))) count `shouldBe` True
      evalT (tPredOn (iPre 7) (is (== 0))) count `shouldBe` False
      evalT (tPredOn (iPre 7) (Next (is (== 0)))) count `shouldBe` True
      -- (the stream's first time step plays no part, as for evalSF)
      evalT (tPredOn localTime (is (== 0))) ((0.5, 0) : drop 1 count) `shouldBe` True
    it "runs a view with state from time 0, never restarted where an operator looks (fixed)" $ do
      -- (running sums of 0..9: 0, 1, 3, 6, 10, 15, 21, 28, 36, 45; a sum
      -- restarted at the sample Next or Eventually looks at would be 2 there,
      -- and never 45)
      let runningSum = sscan (+) 0
      evalT (tPredOn runningSum (Next (Next (is (== 3))))) count `shouldBe` True
      evalT (Next (Next (tPredOn runningSum (is (== 3))))) count `shouldBe` True
      evalT (tPredOn runningSum (Eventually (is (== 45)))) count `shouldBe` True
      evalT (tPredOn runningSum (Always (Implies (is (> 20)) (alwaysFor 0.2 (is (> 20)))))) count `shouldBe` True
      evalT (tPredOn runningSum (Always (eventuallyWithin 0.1 (is (== 10))))) count `shouldBe` False
      -- (a view of the clock keeps counting under Always)
      evalT (tPredOn localTime (Always (eventuallyWithin 0.3 (SP (arr (> 0.55)))))) count `shouldBe` False
      evalT (tPredOn localTime (Eventually (SP (arr (> 0.85))))) count `shouldBe` True
    it "explains a failure with the stream's own samples, at the instant the view decided (fixed)" $ do
      let e = explainT (tPredOn (sscan (+) 0) (Always (is (< 10)))) count
      fmap explFrame e `shouldBe` Just 4
      fmap (map (\(j, _, a) -> (j, a)) . explAround) e `shouldBe` Just [(j, j) | j <- [1 .. 6]]
  describe "evalT, yampa-test's operators (fixed)" $ do
    it "SP is the signal function's output at time 0" $ do
      evalT (is (== 0)) count `shouldBe` True
      evalT (is (== 1)) count `shouldBe` False
    it "Always and Eventually range over the later samples" $ do
      evalT (Always (is (< 10))) count `shouldBe` True
      evalT (Always (is (< 9))) count `shouldBe` False
      evalT (Eventually (is (== 9))) count `shouldBe` True
      evalT (Eventually (is (== 10))) count `shouldBe` False
    it "atoms keep their state under Always (the clock is the stream's)" $
      evalT (Always (SP (localTime >>> arr (< 0.95)))) count `shouldBe` True
    it "Next is true at the last sample, Eventually is its argument there" $ do
      let one = [(0, 5 :: Int)]
      evalT (Next (is (const False))) one `shouldBe` True
      evalT (Eventually (is (== 6))) one `shouldBe` False
    it "Until is weak: holding to the end is enough" $ do
      evalT (Until (is (< 10)) (is (== 42))) count `shouldBe` True
      evalT (Until (is (< 5)) (is (== 5))) count `shouldBe` True
      evalT (Until (is (< 4)) (is (== 5))) count `shouldBe` False
    it "Not, And, Or, Implies combine at the same sample" $ do
      evalT (Not (is (== 0))) count `shouldBe` False
      evalT (Always (Implies (is (> 5)) (is (> 4)))) count `shouldBe` True
      evalT (Or (is (== 1)) (And (is (== 0)) (Next (is (== 1))))) count `shouldBe` True
  describe "time-bounded operators (fixed)" $ do
    it "eventuallyWithin sees the samples up to the bound" $ do
      evalT (eventuallyWithin 0.3 (is (== 3))) count `shouldBe` True
      evalT (eventuallyWithin 0.25 (is (== 3))) count `shouldBe` False
    it "eventuallyWithin is true when the stream ends before the deadline" $
      evalT (Always (Implies (is (== 8)) (eventuallyWithin 1 (is (== 20))))) count `shouldBe` True
    it "eventuallyWithin is false when the stream's last sample is at the deadline and p never held (it was true)" $ do
      -- count ends at 0.9 (three steps of 0.3 after 0, within the slack)
      evalT (eventuallyWithin 0.9 (is (== 20))) count `shouldBe` False
      evalT (eventuallyWithin 0.9 (is (== 9))) count `shouldBe` True
      evalT (eventuallyWithin 0.3 (is (== 20))) (take 4 count) `shouldBe` False
      evalT (eventuallyWithin 0.3 (is (== 20))) (take 3 count) `shouldBe` True
      evalT (eventuallyWithin 0 (is (== 20))) (take 1 count) `shouldBe` False
      evalT (Always (Implies (is (== 6)) (eventuallyWithin 0.3 (is (== 20))))) count `shouldBe` False
      evalT (Always (Implies (is (== 7)) (eventuallyWithin 0.3 (is (== 20))))) count `shouldBe` True
      fmap explFrame (explainT (eventuallyWithin 0.3 (is (== 20))) (take 4 count)) `shouldBe` Just 3
    it "explainT of a window that a sample of a step of 0 completes: the instant of the real miss (it named one that held)" $ do
      -- times 0, 1, 1, 2, 3: p holds only at the second sample at t = 1, so
      -- the window from 0 holds; the one from t = 2 misses, decided at t = 3
      let s = [(0, 0), (1, 0), (0, 1), (1, 0), (1, 0)] :: SignalSampleStream Int
          p = Always (eventuallyWithin 1 (is (== 1)))
      evalT p s `shouldBe` False
      fmap (\e -> (explFrame e, explTime e)) (explainT p s) `shouldBe` Just (4, 3)
    it "eventuallyWithin of an infinite bound is a deadline that never passes (true at the end, where Eventually is false)" $ do
      evalT (eventuallyWithin (1 / 0) (is (== 20))) count `shouldBe` True
      evalT (Eventually (is (== 20))) count `shouldBe` False
      evalT (eventuallyWithin (1 / 0) (is (== 9))) count `shouldBe` True
    it "alwaysFor is true at the end of the stream when the samples there hold, whether the window was seen whole or not" $ do
      evalT (alwaysFor 0.9 (is (< 10))) count `shouldBe` True
      evalT (alwaysFor 2 (is (< 10))) count `shouldBe` True
      evalT (alwaysFor 0.9 (is (< 9))) count `shouldBe` False
    it "eventuallyWithin and alwaysFor refuse a negative or NaN bound" $ do
      evaluate (evalT (eventuallyWithin (-1) (is (== 3))) count) `shouldThrow`
        errorCall "AFRP.Test.LTL.eventuallyWithin: the time bound must be a number >= 0, got -1.0"
      evaluate (evalT (alwaysFor (0 / 0) (is (< 5))) count) `shouldThrow`
        errorCall "AFRP.Test.LTL.alwaysFor: the time bound must be a number >= 0, got NaN"
      evalT (alwaysFor (1 / 0) (is (< 10))) count `shouldBe` True
    it "a window reads only its own samples: 200,000 samples are no hang (each window counted the whole rest)" $ do
      let long = (0, 0) : [ (0.01, k) | k <- [1 .. 200000 :: Int] ]
      r <- timeout (120 * 1000000) (evaluate (evalT (Always (eventuallyWithin 0.05 (SP (arr (>= 0))))) long))
      r `shouldBe` Just True
    it "Always, Eventually and Until stop at the sample that decides, outermost or nested (the whole stream was read first: an infinite one hung)" $ do
      -- (a stream that is an error past sample 5000: reading on fails at once)
      let endless = readNoFurther 5000 (groupDeltas [0 :: Int ..] (repeat 0.01))
          decided p = timeout (60 * 1000000) (evaluate (evalT p endless))
      decided (Always (Implies (is (> 5)) (Next (is (< 1000))))) `shouldReturn` Just False
      decided (Eventually (And (is (> 500)) (eventuallyWithin 0.05 (is even)))) `shouldReturn` Just True
      decided (Until (is (< 300)) (is (== 200))) `shouldReturn` Just True
      decided (Until (is (< 300)) (is (== 400))) `shouldReturn` Just False
      decided (Not (Always (is (/= 77)))) `shouldReturn` Just True
      -- (a connective decides its second operand only if the first does not:
      -- a second operand with a nested future operator that never decides
      -- reads the whole stream at its first sample)
      decided (And (Always (is (< 10))) (Eventually (is (< 0)))) `shouldReturn` Just False
      decided (And (SP (arr (const False))) (Always (Eventually (is (< 0))))) `shouldReturn` Just False
      decided (Or (SP (arr (const True))) (Next (Eventually (is (< 0))))) `shouldReturn` Just True
      decided (And (Always (is (< 5))) (Always (Eventually (is (< 0))))) `shouldReturn` Just False
      -- (nested: each decided at the sample that decides it, 700 and 900,
      -- without the end of the stream)
      decided (Always (Implies (is (> 500)) (Not (Eventually (is (== 700)))))) `shouldReturn` Just False
      decided (Eventually (And (is (== 1)) (Until (is (> 0)) (is (== 900))))) `shouldReturn` Just True
      decided (Eventually (And (is (== 1)) (Not (Always (is (< 950)))))) `shouldReturn` Just True
    it "keeps what a nested Until owes small: 40,000 samples are no hang (it owed one level more at each sample, the time quadratic)" $ do
      let long = groupDeltas [0 .. 39999 :: Int] (repeat 0.01)
          never = is (< 0)
          always' = is (>= 0)
          -- (what each owes is unfolded inside itself at every sample)
          p1 = Until (Eventually (Eventually never)) (Always (Next (Not never)))
          p2 = Until (Or (Eventually never) (Eventually (Not always'))) (And (Always always') (Eventually never))
          -- (a window that never ends, opened at every sample)
          p3 = Until (alwaysFor (1 / 0) (Eventually (is even))) (Always (is (< 0)))
      -- (each answer evaluated whole inside the timeout)
      r <- timeout (60 * 1000000) $ do
        a <- evaluate (evalT p1 long)
        b <- evaluate (fmap explFrame (explainT p2 long))
        _ <- evaluate (maybe 0 id b)
        c <- evaluate (evalT p3 long)
        pure (a, b, c)
      r `shouldBe` Just (True, Just 39999, False)
    it "alwaysFor looks only inside its window" $ do
      evalT (alwaysFor 0.45 (is (< 5))) count `shouldBe` True
      evalT (alwaysFor 0.5 (is (< 5))) count `shouldBe` False
  describe "past operators (fixed)" $ do
    let run :: SF Int Bool -> [Bool]
        run sf = samples (fst (evalSF sf count))
    it "previously is the last sample's value, false at time 0" $
      run (previously (arr even)) `shouldBe` [False, True, False, True, False, True, False, True, False, True]
    it "hasAlwaysBeen and hasEverBeen" $ do
      run (hasAlwaysBeen (arr (< 3))) `shouldBe` map (< 3) [0 .. 9 :: Int]
      run (hasEverBeen (arr (== 3))) `shouldBe` map (>= 3) [0 .. 9 :: Int]
    it "since: q at some sample, p at every one after it" $
      run (since (arr (< 6)) (arr (== 2))) `shouldBe` map (\x -> x >= 2 && x < 6) [0 .. 9 :: Int]
    it "untilSF: i until u holds, then u at every sample since" $ do
      run (arr (\x -> (x < 5, x >= 3 && x /= 6)) >>> untilSF)
        `shouldBe` map (< 6) [0 .. 9 :: Int]
      run (arr (\x -> (x < 2, x == 4)) >>> untilSF)
        `shouldBe` map (< 2) [0 .. 9 :: Int]
  describe "explainT (fixed)" $ do
    it "is Nothing when the predicate holds" $
      fmap explFrame (explainT (Always (is (< 10))) count) `shouldBe` Nothing
    it "gives the first sample that breaks Always, and its neighbours" $ do
      let e = explainT (Always (is (< 6))) count
      fmap explFrame e `shouldBe` Just 6
      fmap (\x -> abs (explTime x - 0.6) < 1e-9) e `shouldBe` Just True
      fmap (map (\(j, _, a) -> (j, a)) . explAround) e `shouldBe` Just [(j, j) | j <- [3 .. 8]]
    it "gives the sample where a deadline passed" $
      fmap explFrame (explainT (eventuallyWithin 0.25 (is (== 3))) count) `shouldBe` Just 3
    it "gives the last sample when only the end decides" $
      fmap explFrame (explainT (Eventually (is (== 10))) count) `shouldBe` Just 9
    it "reads the stream up to the sample that decides and the two it shows after it, no further (it read up to twice as far, and counted it whole before: an endless one hung)" $ do
      let endless n = readNoFurther n (groupDeltas [0 :: Int ..] (repeat 0.01))
      r <- timeout (60 * 1000000) (evaluate (fmap explFrame (explainT (Always (Implies (is (> 5)) (Next (is (< 1234))))) (endless 1237))))
      r `shouldBe` Just (Just 1234)   -- (false at 1233, decided when 1234 is seen)
      fmap (map (\(j, _, a) -> (j, a)) . explAround) (explainT (Always (is (< 70))) (endless 73))
        `shouldBe` Just [(j, j) | j <- [67 .. 72]]
      -- (decided at the last sample there is: nothing after it to show)
      fmap (map (\(j, _, a) -> (j, a)) . explAround) (explainT (Always (is (< 70))) (take 71 (endless 71)))
        `shouldBe` Just [(j, j) | j <- [67 .. 70]]
    it "decides a connective at the first sample that decides either operand, and a formula that owes one thing for ever at the end (evalT kept the stream for the first operand)" $ do
      let endless n = readNoFurther n (groupDeltas [0 :: Int ..] (repeat 0.01))
      fmap explFrame (explainT (And (Eventually (is (< 0))) (Always (is (< 300)))) (endless 303)) `shouldBe` Just 300
      evalT (Or (Eventually (is (< 0))) (Eventually (is (== 300)))) (endless 301) `shouldBe` True
      -- (one Eventually owed from every sample: false at the end)
      fmap explFrame (explainT (Always (Implies (is (>= 0)) (Eventually (is (< 0))))) (take 400 (endless 400))) `shouldBe` Just 399
