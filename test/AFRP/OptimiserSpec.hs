{-# LANGUAGE Arrows #-}
{-# OPTIONS_GHC -O #-}
-- | The network simplifies itself: these tests look at the internal form
-- of signal functions (through "AFRP.Internal.SF") as they are built and
-- as they run. Compiled with optimisation whatever the build's setting, so
-- that the library's rewrite rules run on the compositions written here.
module AFRP.OptimiserSpec (spec) where

import           Test.Hspec hiding (after)

import           AFRP
import           AFRP.Internal.SF (isConstantSF, isPureSF, isStepSF, sfShape, stepSF)
import           TestUtil         (runDt, withoutHanging)

-- | @arr (> x) >>> edge@ inside a function of @x@: the shape in which the
-- parts of a composition could be floated apart before a rule saw them.
edgeAbove :: Int -> SF Int (Event ())
edgeAbove x = arr (> x) >>> edge
{-# NOINLINE edgeAbove #-}

-- | @loopPre@ of a function inside a function of the initial value: a
-- counter from @k@ that outputs the count before the current sample.
countFrom :: Int -> SF () Int
countFrom k = loopPre k (arr (\(_, n) -> (n, n + 1)))
{-# NOINLINE countFrom #-}

-- | The signal function as it is, hidden from the rewrite rules: what a
-- composition with it is built of at run time.
unfused :: SF a b -> SF a b
unfused sf = sf
{-# NOINLINE unfused #-}

-- | An integral at Double bound to a name used more than once (below): the
-- functions next to each use still join it.
namedIntegral :: SF Double Double
namedIntegral = integral

-- | Negative zero, out of GHC's sight (so that no test's arithmetic on it
-- is folded at compile time).
negZero :: Double
negZero = -0
{-# NOINLINE negZero #-}

-- | A switch of the given kind on @arr (* 2) &&& never@ is stateful when
-- built and, after one step, the pure @arr (* 2)@.
disappearsOnNever :: (SF Int (Int, Event ()) -> (() -> SF Int Int) -> SF Int Int) -> Expectation
disappearsOnNever sw = do
  let sf = sw (arr (* 2) &&& never) (\() -> constant 0)
  isPureSF sf `shouldBe` False
  let sf' = runTo sf [(0, 1)]
  isPureSF sf' `shouldBe` True
  snd (stepSF sf' 1 21) `shouldBe` 42

-- | Step a signal function through the given runDt 1 (the first one's
-- time step is ignored) and return what it has become.
runTo :: SF a b -> [(DTime, a)] -> SF a b
runTo = foldl (\sf (dt, a) -> fst (stepSF sf dt a))

spec :: Spec
spec = do
  describe "at construction" $ do
    it "fuses a chain of pure functions into one" $
      isPureSF (foldr1 (>>>) (replicate 100 (arr (+ 1))) :: SF Int Int) `shouldBe` True
    it "removes identities" $
      isPureSF (identity >>> arr not >>> identity) `shouldBe` True
    it "lets a constant absorb what feeds it" $
      isConstantSF (integral >>> constant 'c' :: SF Double Char) `shouldBe` True
    it "fuses first, second, *** and &&& of pure functions" $ do
      isPureSF (first (arr (+ 1)) :: SF (Int, Char) (Int, Char)) `shouldBe` True
      isPureSF (second (arr (+ 1)) :: SF (Char, Int) (Char, Int)) `shouldBe` True
      isPureSF (arr (+ 1) *** arr not :: SF (Int, Bool) (Int, Bool)) `shouldBe` True
      isPureSF (arr (+ 1) &&& arr show :: SF Int (Int, String)) `shouldBe` True
    it "fuses a loop over a pure function" $
      isPureSF (loop (arr (\(a, c) -> (a + 1, c))) :: SF Int Int) `shouldBe` True
    it "keeps stateful parts stateful" $
      isPureSF (arr (+ 1) >>> integral :: SF Double Double) `shouldBe` False

  -- Built at run time (the parts hidden from the rewrite rules): the
  -- spine nested to the right, the functions of a command moved out of its
  -- @first@ and fused with their neighbours.
  describe "at construction, the shape of the spine" $ do
    let pre0 = unfused (iPre 0) :: SF Int Int
        inc  = unfused (arr (+ 1)) :: SF Int Int
        dbl  = unfused (arr (* 2)) :: SF Int Int
    it "nests compositions to the right, however they were written" $ do
      sfShape (((pre0 >>> pre0) >>> pre0) >>> pre0) `shouldBe` "(pre >>> (pre >>> (pre >>> pre)))"
      sfShape ((inc >>> pre0) >>> dbl) `shouldBe` "(arr >>> (pre >>> arr))"
    it "fuses functions that meet once the spine is nested to the right" $
      sfShape ((inc >>> pre0 >>> inc) >>> (dbl >>> pre0)) `shouldBe` "(arr >>> (pre >>> (arr >>> pre)))"
    it "moves the functions at either end of first's and second's network out" $ do
      sfShape (first (inc >>> pre0 >>> dbl) :: SF (Int, Char) (Int, Char))
        `shouldBe` "(arr >>> ((pre *** id) >>> arr))"
      sfShape (second (inc >>> pre0 >>> dbl) :: SF (Char, Int) (Char, Int))
        `shouldBe` "(arr >>> ((id *** pre) >>> arr))"
      sfShape (unfused (arr (\x -> (x, x))) >>> first (inc >>> pre0 >>> dbl) >>> unfused (arr (uncurry (+))))
        `shouldBe` "(arr >>> ((pre *** id) >>> arr))"
    it "makes each command of arrow notation one node, the functions between commands taken into them" $ do
      -- (@arr p >>> first sf@, the shape of every command, is one node by
      -- a rewrite rule, see below, and so is the function after it; the
      -- compositions are nested to the right by another, so the
      -- environment a command rebuilds and the next takes apart meet in
      -- one function, and the last command takes the block's result in)
      let sf = proc x -> do
                 y <- pre0 -< x + 1
                 z <- pre0 -< y * 2
                 returnA -< z + x
      sfShape sf `shouldBe` "(step >>> step)"
      embed sf (1, [(1, Just 2), (1, Just 3), (1, Just 4)]) `shouldBe` [1, 2, 7, 10]
    it "builds a network grown on the right one stage at a time in time linear in its length (fixed)" $
      -- 100,000 stages by foldl: a walk of the whole spine at every >>>
      -- (quadratic) takes minutes; re-association looks a few nodes deep
      let stage = pre0 >>> inc
          sf = foldl (>>>) identity (replicate 100000 stage)
      in withoutHanging (embed sf (5, replicate 3 (1, Just 5))) [1, 2, 3, 4]
    it "outputs what the network as written outputs, as lazily" $ do
      let sf = first (inc >>> pre0 >>> dbl) :: SF (Int, Char) (Int, Char)
      embed sf ((1, 'a'), [(1, Just (2, 'b')), (1, Just (3, 'c'))]) `shouldBe` [(0, 'a'), (4, 'b'), (6, 'c')]
      -- the component that first does not touch is never evaluated
      map fst (embed sf ((1, undefined), [(1, Just (2, undefined))])) `shouldBe` [0, 4]
      -- nor is second's
      map fst (embed (second (inc >>> pre0 >>> dbl) :: SF (Char, Int) (Char, Int))
                     (('a', undefined), [(1, Just ('b', 2))])) `shouldBe` "ab"

  -- arr p >>> first sf, written in the source (as arrow notation writes
  -- every command), is one node (arrFirstSF) by a rewrite rule.
  describe "arr p >>> first sf, one node" $ do
    let p x = (x + 1, x * 10) :: (Int, Int)
        sw :: SF Int Int
        sw = switch (iPre 0 &&& after 2 ()) (\_ -> arr (* 3))
        runs :: SF Int (Int, Int) -> [(Int, Int)]
        runs sf = embed sf (1, [(1, Just x) | x <- [2 .. 6]])
    it "gives the outputs of the composition, before and after a switch inside it" $
      runs (arr p >>> first sw) `shouldBe` runs (unfused (arr p) >>> first sw)
    it "is the composition's outputs with functions on both sides" $
      runs (arr (* 2) >>> arr p >>> first sw >>> arr (\(a, b) -> (b, a)))
        `shouldBe` runs (unfused (arr (* 2)) >>> unfused (arr p) >>> first sw >>> unfused (arr (\(a, b) -> (b, a))))
    it "is one stateful node, and a pure function while sf is one" $ do
      sfShape (arr p >>> first (iPre 0)) `shouldBe` "step"
      isPureSF (arr p >>> first (arr (* 2))) `shouldBe` True
    it "does not evaluate the input, p's result or the part sf is not given before they are needed" $ do
      let q :: Int -> (Int, Int)
          q = const undefined
      -- a delay's first output does not look at its input
      map fst (take 1 (embed (arr q >>> first (iPre 7)) (1, []))) `shouldBe` [7]
      map fst (embed (arr (\x -> (x, undefined :: Int)) >>> first (iPre 0)) (1 :: Int, [(1, Just 2)])) `shouldBe` [0, 1]
    it "closes a loop through the part it passes on" $
      -- y_0 = 0, y_k = 1 + y_(k-1): the value fed back is needed only a
      -- sample later, through the delay
      embed (loop (arr (\(x, c) -> (x + c, c)) >>> first (iPre 0) >>> arr (\(y, _) -> (y, y))))
            (1 :: Int, [(1, Just 1), (1, Just 1), (1, Just 1)])
        `shouldBe` [0, 1, 2, 3]

  -- arr p >>> first sf >>> arr q, written in the source (a command and
  -- the function after it), is one node (arrFirstQSF) by a rewrite rule,
  -- and so are the functions at either end of sf.
  describe "arr p >>> first sf >>> arr q, one node" $ do
    let p x = (x + 1, x * 10) :: (Int, Int)
        q (a, b) = a - b :: Int
        sw :: SF Int Int
        sw = switch (iPre 0 &&& after 2 ()) (\_ -> arr (* 3))
        runs :: SF Int b -> [b]
        runs sf = embed sf (1, [(1, Just x) | x <- [2 .. 6]])
    it "gives the outputs of the composition, before and after a switch inside it" $ do
      runs (arr p >>> first sw >>> arr q) `shouldBe` runs (unfused (arr p) >>> first sw >>> unfused (arr q))
      runs (arr (* 2) >>> arr p >>> first sw >>> arr q >>> arr (+ 1))
        `shouldBe` runs (unfused (arr (* 2)) >>> unfused (arr p) >>> first sw >>> unfused (arr q) >>> unfused (arr (+ 1)))
    it "gives the outputs of the composition with functions at either end of sf" $ do
      runs (arr p >>> first (arr (* 2) >>> sw) >>> arr q)
        `shouldBe` runs (unfused (arr p) >>> first (unfused (arr (* 2)) >>> sw) >>> unfused (arr q))
      runs (arr p >>> first (sw >>> arr (+ 7)) >>> arr q)
        `shouldBe` runs (unfused (arr p) >>> first (sw >>> unfused (arr (+ 7))) >>> unfused (arr q))
      runs (arr p >>> first (arr (* 2) >>> sw >>> arr (+ 7)))
        `shouldBe` runs (unfused (arr p) >>> first (unfused (arr (* 2)) >>> sw >>> unfused (arr (+ 7))))
      runs (arr p >>> first (arr (* 2) >>> iPre 5 >>> arr (+ 7)) >>> arr q)
        `shouldBe` [2, -9, -17, -25, -33, -41]
    it "is one stateful node, and a pure function while sf is one" $ do
      sfShape (arr p >>> first (iPre 0) >>> arr q) `shouldBe` "step"
      sfShape (arr p >>> first (arr (* 2) >>> iPre 0 >>> arr (+ 1)) >>> arr q) `shouldBe` "step"
      isPureSF (arr p >>> first (arr (* 2)) >>> arr q) `shouldBe` True
      -- (sw becomes a function after its switch, and the node with it,
      -- at the step the composition does)
      let pureAfter sf = map (isPureSF . fst) (tail (scanl (\(n, _) (dt, x) -> stepSF n dt x) (sf, 0)
                                                          [(0, 1), (1, 2), (1, 3), (1, 4)]))
      pureAfter (arr p >>> first sw >>> arr q) `shouldBe` [False, False, False, True]
      pureAfter (unfused (arr p) >>> first sw >>> unfused (arr q)) `shouldBe` [False, False, False, True]
    it "does not evaluate the input, p's result, the part passed on or q's result before they are needed" $ do
      let bottom :: a
          bottom = error "evaluated before it was needed"
          bad :: Int -> (Int, Int)
          bad = const bottom
      -- a delay's first output does not look at its input
      take 1 (embed (arr bad >>> first (iPre 7) >>> arr fst) (1, [])) `shouldBe` [7]
      embed (arr (\x -> (x, bottom :: Int)) >>> first (iPre 0) >>> arr fst) (1 :: Int, [(1, Just 2)])
        `shouldBe` [0, 1]
      embed (arr (\x -> (x, x)) >>> first (arr (const (bottom :: Int)) >>> iPre 0) >>> arr snd)
        (1 :: Int, [(1, Just 2)]) `shouldBe` [1, 2]
      length (embed (arr p >>> first (iPre 0) >>> arr (\_ -> bottom :: Int)) (1, [(1, Just 2)]))
        `shouldBe` 2
      map fst (embed (arr p >>> first (iPre 0 >>> arr (\_ -> bottom :: Int)) >>> arr (\(a, c) -> (c, a)))
                     (1, [(1, Just 2)])) `shouldBe` [10, 20]
      -- a function at the front of sf, taken into p, does not take p's
      -- result apart before it is needed (a review's case: the stateful
      -- pass-through looks at its input at once, as iPre does not)
      let passS = loopPre () (arr id) :: SF Int Int
      take 2 (embed (arr (\_ -> bottom :: (Int, Int)) >>> first (arr (const 5) >>> passS) >>> arr fst)
                    (1 :: Int, [(1, Just 2)])) `shouldBe` [5, 5]
    it "closes a loop through the part it passes on" $
      -- y_0 = 0, y_k = 1 + y_(k-1): the value fed back is needed only a
      -- sample later, through the delay
      embed (loop (arr (\(x, c) -> (x + c, c)) >>> first (arr (* 1) >>> iPre 0) >>> arr (\(y, _) -> (y, y))))
            (1 :: Int, [(1, Just 1), (1, Just 1), (1, Just 1)])
        `shouldBe` [0, 1, 2, 3]

  -- These compositions are written in the source, so the library's
  -- rewrite rules fuse them at compile time (this module is compiled with
  -- optimisation, as cabal compiles the test suite); each is the left-hand
  -- side of one of the rules. A rule that composed in the wrong order, or
  -- that evaluated the inner function's result before the outer one asks
  -- for it, fails here.
  describe "at compile time (the rewrite rules)" $ do
    it "arr f >>> arr g: f first, then g" $
      embed (arr (+ 1) >>> arr (* 2) :: SF Int Int) (3, [(1, Just 4)]) `shouldBe` [8, 10]
    it "arr f >>> (arr g >>> sf): f, g, then sf" $
      embed (arr (+ 1) >>> arr (* 2) >>> iPre 0 :: SF Int Int) (3, [(1, Just 4)]) `shouldBe` [0, 8]
    it "(sf >>> arr f) >>> arr g: sf, f, then g" $
      embed ((iPre 0 >>> arr (+ 1)) >>> arr (* 2) :: SF Int Int) (3, [(1, Just 4)]) `shouldBe` [2, 8]
    it "keeps each of them lazy: g's argument is evaluated only if g needs it" $ do
      embed (arr (const undefined) >>> arr (const 'x') :: SF Int Char) (3, [(1, Just 4)])
        `shouldBe` "xx"
      embed (arr (const undefined) >>> arr (const 'x') >>> iPre 'z' :: SF Int Char) (3, [(1, Just 4)])
        `shouldBe` "zx"
      embed ((iPre 0 >>> arr (const undefined)) >>> arr (const 'x') :: SF Int Char) (3, [(1, Just 4)])
        `shouldBe` "xx"
    it "arr p >>> edge: an edge of p's value, no event at time 0 for True" $
      embed (arr (> 2) >>> edge :: SF Int (Event ())) (3, map (\x -> (1, Just x)) [1, 5, 5, 0, 4])
        `shouldBe` [NoEvent, NoEvent, Event (), NoEvent, NoEvent, Event ()]
    it "arr p >>> iEdge False: an event at time 0 for True" $
      embed (arr (> 2) >>> iEdge False :: SF Int (Event ())) (3, map (\x -> (1, Just x)) [1, 5])
        `shouldBe` [Event (), NoEvent, Event ()]
    it "arr p >>> (edge >>> sf): the edge, then sf" $
      embed (arr (> 2) >>> edge >>> arr isEvent :: SF Int Bool) (3, map (\x -> (1, Just x)) [1, 5, 5, 0, 4])
        `shouldBe` [False, False, True, False, False, True]
    it "makes arr p >>> edge one node, also inside a function of p's parameter" $ do
      -- (the composition node is what 'compN' would build at run time)
      isStepSF (edgeAbove 2) `shouldBe` True
      isStepSF (arr (> (2 :: Int)) >>> edge) `shouldBe` True
      embed (edgeAbove 2) (3, map (\x -> (1, Just x)) [1, 5]) `shouldBe` [NoEvent, NoEvent, Event ()]
    it "loopPre c (arr g): g sees the input and the stored value; it outputs the first component and stores the second" $ do
      embed (loopPre 0 (arr (\(a, acc) -> (acc, acc + a))) :: SF Int Int) (1, map (\x -> (1, Just x)) [2, 3, 4])
        `shouldBe` [0, 1, 3, 6]
      embed (countFrom 5) ((), replicate 3 (1, Nothing)) `shouldBe` [5, 6, 7, 8]
    it "loop (second (iPre c) >>> arr g), written out: the same as loopPre c (arr g)" $
      embed (loop (second (iPre 0) >>> arr (\(a, acc) -> (acc, acc + a))) :: SF Int Int)
        (1, map (\x -> (1, Just x)) [2, 3, 4]) `shouldBe` [0, 1, 3, 6]
    it "keeps loopPre c (arr g) lazy: neither the stored value nor the output is evaluated unless needed" $ do
      -- the initial value is never needed: g ignores what it is given back
      embed (loopPre undefined (arr (\(a, _) -> (a, a))) :: SF Char Char) ('x', [(1, Just 'y')])
        `shouldBe` "xy"
      -- an output never looked at is never evaluated
      length (embed (loopPre 'c' (arr (\(_, c) -> (undefined :: Int, c)))) ((), [(1, Nothing)]))
        `shouldBe` 2
      -- a stored value that is never needed is never evaluated
      embed (loopPre 'c' (arr (\(a, _) -> (a, undefined))) :: SF Int Int) (1, [(1, Just 2)])
        `shouldBe` [1, 2]

    describe "integral at Double with the functions next to it" $ do
      -- inputs 1, 2, 3, 4 at steps of 1: integral gives 0, 1, 3, 6
      let ins = [1, 2, 3, 4] :: [Double]
      it "arr f >>> integral: f applied to each sample, then summed" $
        runDt 1 (arr (* 2) >>> integral) ins `shouldBe` [0, 2, 6, 12]
      it "integral >>> arr g: g applied to the sum, also at time 0" $
        runDt 1 (integral >>> arr (+ 1)) ins `shouldBe` [1, 2, 4, 7]
      it "arr f >>> integral >>> arr g" $
        runDt 1 (arr (* 2) >>> integral >>> arr (+ 1)) ins `shouldBe` [1, 3, 7, 13]
      it "arr f >>> (arr f' >>> integral >>> arr g) >>> arr g': both functions on each side" $
        runDt 1 (arr (+ 1) >>> (arr (* 2) >>> integral >>> arr (+ 1)) >>> arr (* 3)) ins
          `shouldBe` [3, 15, 33, 57]
      it "at the head of a chain: arr f >>> integral >>> sf, integral >>> arr g >>> sf" $ do
        runDt 1 (arr (* 2) >>> integral >>> iPre (-1)) ins `shouldBe` [-1, 0, 2, 6]
        runDt 1 (integral >>> arr (+ 1) >>> iPre (-1)) ins `shouldBe` [-1, 1, 2, 4]
        runDt 1 (arr (+ 1) >>> (arr (* 2) >>> integral) >>> iPre (-1)) ins `shouldBe` [-1, 0, 4, 10]
        runDt 1 ((arr (* 2) >>> integral) >>> arr (+ 1) >>> iPre (-1)) ins `shouldBe` [-1, 1, 3, 7]
      it "applies f to a sample only at the next step, where the sum needs it" $
        -- f fails on the last sample, which the integral never needs
        runDt 1 (arr (\x -> if x < 0 then error "evaluated too early" else 2 * x) >>> integral >>> arr (+ 1))
          [1, 2, -1 :: Double] `shouldBe` [1, 3, 7]
      it "leaves its output unevaluated until it is needed" $
        length (runDt 1 (integral >>> arr (\_ -> undefined :: Int)) ins) `shouldBe` 4
      it "integralDOn >>> (arr g >>> sf): g after the node's own function" $
        runDt 1 ((arr (* 2) >>> integral >>> arr (+ 1)) >>> arr (* 3) >>> iPre (-1)) ins
          `shouldBe` [-1, 3, 9, 21]
      it "keeps the sign of a zero at time 0 (no folding of 0 + k)" $
        -- 1 / (0 + (-0)) is +Infinity: 0 + (-0) is +0
        head (runDt 1 (integral >>> arr (\c -> 1 / (c + negZero))) ins) `shouldBe` (1 / 0)
      it "makes each shape one node (the composition would be a composition node)" $ do
        isStepSF (arr (* 2) >>> integral :: SF Double Double) `shouldBe` True
        isStepSF (integral >>> arr (+ 1) :: SF Double Double) `shouldBe` True
        isStepSF (arr (* 2) >>> integral >>> arr (+ 1) :: SF Double Double) `shouldBe` True
        isStepSF (arr (+ 1) >>> (arr (* 2) >>> integral >>> arr (+ 1)) >>> arr (* 3) :: SF Double Double)
          `shouldBe` True
        isStepSF (unfused integral >>> arr (+ 1) :: SF Double Double) `shouldBe` False
      it "does the same for an integral bound to a name used more than once" $ do
        isStepSF (arr (* 3) >>> namedIntegral) `shouldBe` True
        isStepSF (namedIntegral >>> arr (+ 1)) `shouldBe` True
        runDt 1 (arr (* 3) >>> namedIntegral >>> arr (+ 1)) ins `shouldBe` [1, 4, 10, 19]

    describe "integrals at Double in series, written out, with functions between them" $ do
      let ins = map fromIntegral [1 .. 30 :: Int] :: [Double]
          opaque1 :: SF Double Double -> SF Double Double
          opaque1 = unfused
      it "are the composition built as nodes, where the run-time chains see every integral" $ do
        -- one integral with a function next to it is one node; two are
        -- the composition (each an integral node after a step), not two
        -- opaque nodes
        sfShape (fst (stepSF (integral >>> arr (* 2) >>> integral :: SF Double Double) 0 1))
          `shouldBe` "(int >>> (arr >>> int))"
        sfShape (fst (stepSF (arr (+ 1) >>> integral >>> arr (* 2) >>> integral >>> arr (subtract 1)
                                :: SF Double Double) 0 1))
          `shouldBe` "(arr >>> (int >>> (arr >>> (int >>> arr))))"
        sfShape (fst (stepSF (integral >>> integral >>> integral :: SF Double Double) 0 1))
          `shouldBe` "(int >>> (int >>> int))"
        -- and a chain of them, after its second step, is one node
        let twice sf = fst (stepSF (fst (stepSF sf 0 1)) 1 2)
        isStepSF (twice (integral >>> arr (* 2) >>> integral >>> arr (* 2) >>> integral :: SF Double Double))
          `shouldBe` True
      it "give the numbers of their stages stepped one by one" $ do
        runDt 0.1 (integral >>> arr (* 2) >>> integral >>> arr (* 2) >>> integral >>> arr (* 2) >>> integral) ins
          `shouldBe` runDt 0.1 (opaque1 integral >>> arr (* 2) >>> opaque1 integral >>> arr (* 2)
                                >>> opaque1 integral >>> arr (* 2) >>> opaque1 integral) ins
        runDt 0.1 (arr (+ 1) >>> integral >>> iPre 0 >>> arr (* 0.5) >>> integral >>> arr (+ 1) >>> integral
                     >>> iPre 1 >>> integral >>> integral >>> arr sin) ins
          `shouldBe` runDt 0.1 (arr (+ 1) >>> opaque1 integral >>> iPre 0 >>> arr (* 0.5) >>> opaque1 integral
                                >>> arr (+ 1) >>> opaque1 integral >>> iPre 1 >>> opaque1 integral
                                >>> opaque1 integral >>> arr sin) ins
        -- grouped either way in the source
        runDt 0.1 ((integral >>> arr (* 3)) >>> (integral >>> (arr negate >>> integral))) ins
          `shouldBe` runDt 0.1 (opaque1 integral >>> arr (* 3) >>> opaque1 integral >>> arr negate
                                >>> opaque1 integral) ins
      it "apply a function between two integrals no earlier than the second one needs it" $
        -- the first integral outputs 0, 1, ..., 9; f of its last output is
        -- never needed
        runDt 1 (integral >>> arr (\x -> if x >= (9 :: Double) then error "evaluated too early" else 2 * x)
                 >>> integral >>> integral) (replicate 10 1)
          `shouldBe` [0, 0, 0, 2, 8, 20, 40, 70, 112, 168]
      it "apply the last function to the time-0 zero lazily, without folding 0 + k" $ do
        length (runDt 1 (integral >>> arr (* 2) >>> integral >>> arr (\_ -> undefined :: Int)) ins)
          `shouldBe` 30
        head (runDt 1 (integral >>> arr (* 2) >>> integral >>> arr (\c -> 1 / (c + negZero))) ins)
          `shouldBe` (1 / 0)

  describe "while running" $ do
    it "an after that has fired becomes a constant" $ do
      let sf = runTo (after 1 'x') [(0, ()), (0.5, ()), (0.5, ())]
      isConstantSF sf `shouldBe` True
      snd (stepSF sf 0.5 ()) `shouldBe` NoEvent
    -- (takeEvents looks at its input event only at the next step, so that
    -- it may sit in a loop; it becomes never then.)
    it "takeEvents that has let its events through becomes never" $
      isConstantSF (runTo (takeEvents 1) [(0, Event 'a'), (1, NoEvent)] :: SF (Event Char) (Event Char))
        `shouldBe` True
    it "a switch on never disappears after one step" $
      disappearsOnNever switch
    it "a dSwitch on never disappears after one step (its NoEvent is not deferred)" $
      disappearsOnNever dSwitch
    it "a dSwitch on an edge still switches one step after the edge" $ do
      -- edge returns the evaluated NoEvent, decided at once; its
      -- occurrence is decided at the next step.
      let sf = dSwitch (identity &&& (arr (> 1) >>> edge)) (\() -> constant (-1)) :: SF Int Int
          sf1 = runTo sf [(0, 0)]
      map (snd . stepSF sf1 1) [0, 1, 2] `shouldBe` [0, 1, 2]
      isPureSF (runTo sf1 [(1, 2), (1, 5)]) `shouldBe` True
      snd (stepSF (runTo sf1 [(1, 2), (1, 5)]) 1 7) `shouldBe` (-1)
    -- (an occurrence is looked at when the output is demanded, or at the
    -- next step: the switch is the constant from then on)
    it "a switch that has switched into a constant is that constant" $ do
      let sf = switch (constant 'a' &&& after 1 ()) (\() -> constant 'b') :: SF () Char
          sf' = runTo sf [(0, ()), (1, ()), (1, ())]
      isConstantSF sf' `shouldBe` True
      snd (stepSF sf' 1 ()) `shouldBe` 'b'
    it "a stateful part that becomes stateless fuses with its neighbours" $ do
      let sf = arr (+ 1) >>> (arr (> 0) &&& now ()) >>> arr (\(b, e) -> event 0 (const 1) e + fromEnum b) :: SF Int Int
      isPureSF sf `shouldBe` False
      let sf' = runTo sf [(0, 5)]
      isPureSF sf' `shouldBe` True
      snd (stepSF sf' 1 5) `shouldBe` 1

  -- The stateful nodes here are 'unfused', so that these compositions
  -- are the run-time ones that the stepper's shortcuts step (written
  -- next to an integral at Double, they would be one node by a rule).
  describe "shortcuts of the stepper" $ do
    it "steps first (arr p >>> sf), as arrow notation builds it, as its two nodes would" $ do
      let sf = first (arr (* 2) >>> unfused integral) :: SF (Double, Char) (Double, Char)
      embed sf ((1, 'a'), [(0.5, Just (2, 'b')), (0.5, Just (3, 'c')), (1, Just (0, 'd'))])
        `shouldBe` [(0, 'a'), (1, 'b'), (3, 'c'), (9, 'd')]
    it "keeps first (arr p >>> sf) lazy in both components" $ do
      -- p's result reaches the delay unevaluated, and the second component
      -- is passed on without being looked at
      let sf = first (arr (\x -> x `seq` 'p') >>> iPre 'z') :: SF (Int, Int) (Char, Int)
      map fst (embed sf ((1, undefined), [(1, Just (undefined, undefined))])) `shouldBe` "zp"
      map snd (embed sf ((undefined, 7), [(1, Just (undefined, 8))])) `shouldBe` [7, 8]
    it "steps sf >>> (arr p >>> sf') as its nodes would" $ do
      let sf = unfused integral >>> (arr (* 2) >>> unfused integral) :: SF Double Double
      embed sf (1, [(0.5, Just 2), (0.5, Just 3), (1, Just 0)]) `shouldBe` [0, 0, 0.5, 3.5]
    it "keeps sf >>> (arr p >>> sf') lazy in what sf passes on" $ do
      -- the first delay's initial output is never evaluated: p ignores it
      let sf = iPre undefined >>> (arr (const 'x') >>> iPre 'z') :: SF Char Char
      embed sf ('a', [(1, Just 'b'), (1, Just 'c')]) `shouldBe` "zxx"
