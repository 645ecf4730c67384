{-# LANGUAGE Arrows #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- The listings below are the notes' own code, kept verbatim, and some of
-- them shadow Prelude names (init) or each other's local names.
{-# OPTIONS_GHC -Wno-name-shadowing -Wno-unused-top-binds -Wno-missing-signatures #-}
-- |
-- Every listing of sections 2.1 to 2.7 of "Arrows, Robots, and Functional
-- Reactive Programming" that needs no robot type, compiled against "AFRP"
-- and checked against the library's own definitions. (The listings that
-- use SimbotInput come with AFrob.) Listings that redefine a library name
-- are compiled here with that name hidden from the import.
module AFRP.NotesSpec (spec) where

import           Test.Hspec hiding (after)
import           Test.QuickCheck

import           AFRP              hiding (accumHold, arr2, forAll, second, tag, (&&&), (***))
import qualified AFRP              as L
import           Notes.ArrowClass  (firstfun)
import           TestUtil

------------------------------------------------------------------------------
-- 2.1 Arrowized FRP: point-free style

data A = A Int deriving (Eq, Show)
data B = B Int deriving (Eq, Show)
data C = C Int deriving (Eq, Show)

section21g = (g 1, g2 1, g')
  where
    f1 :: Int -> A
    f1 = A
    f2 :: A -> B
    f2 (A n) = B (n + 1)

    g :: Int -> B
    g x = f2 (f1 x)

    g2 = f2 . f1

    g' :: SF Int B
    g' = arr f1 >>> arr f2

section21h = (h (A 1), h')
  where
    f1 :: A -> B
    f1 (A n) = B (2 * n)
    f2 :: A -> C
    f2 (A n) = C (n - 1)

    h :: A -> (B,C)
    h x = (f1 x, f2 x)

    h' :: SF A (B,C)
    h' = arr f1 &&& arr f2

(&) :: (a->b) -> (a->c) -> a -> (b,c)
(f1 & f2) x = (f1 x, f2 x)

section21i = (i (A 1, B 2), i2 (A 1, B 2), i', i'')
  where
    f1 :: A -> C
    f1 (A n) = C (n * 10)
    f2 :: B -> A
    f2 (B n) = A (n + 100)

    i :: (A,B) -> (C,A)
    i (x,y) = (f1 x, f2 y)

    i2 = (f1 . fst) & (f2 . snd)

    i' :: SF (A,B) (C,A)
    i' = (arr fst >>> arr f1) &&& (arr snd >>> arr f2)

    i'' = arr (f1 . fst) &&& arr (f2 . snd)

(***) :: SF b c -> SF b' c' -> SF (b,b') (c,c')
f *** g = (arr fst >>> f) &&& (arr snd >>> g)

------------------------------------------------------------------------------
-- 2.2 The Arrow class

-- The notes write @swap ~ (x,y)@; since GHC 9.0 a @~@ with spaces on both
-- sides is an infix operator, so the lazy pattern must touch its pattern.
second :: Arrow a => a b c -> a (d,b) (d,c)
second f = arr swap >>> first f >>> arr swap
          where swap ~(x,y) = (y,x)

(&&&) :: Arrow a => a b c -> a b d -> a b (c,d)
f &&& g = arr (\b -> (b,b)) >>> (first f >>> second g)

------------------------------------------------------------------------------
-- 2.3 Commonly used combinators: the signatures of Fig. 1 and the text

arr'    :: Arrow a => (b -> c) -> a b c
arr'    = arr
(>>>!)  :: Arrow a => a b c -> a c d -> a b d
(>>>!)  = (>>>)
(<<<!)  :: Arrow a => a c d -> a b c -> a b d
(<<<!)  = (<<<)
first'  :: Arrow a => a b c -> a (b,d) (c,d)
first'  = first
second' :: Arrow a => a b c -> a (d,b) (d,c)
second' = L.second
par'    :: Arrow a => a b c -> a b' c' -> a (b,b') (c,c')
par'    = (L.***)
fan'    :: Arrow a => a b c -> a b c' -> a b (c,c')
fan'    = (L.&&&)
loop'   :: ArrowLoop a => a (b,d) (c,d) -> a b c
loop'   = loop

identity' :: SF a a
identity' = identity
constant' :: b -> SF a b
constant' = constant
time'     :: SF a Time
time'     = time
integral' :: SF Double Double
integral' = integral

arr2 :: (a->b->c) -> SF (a,b) c
arr2 = arr . uncurry

------------------------------------------------------------------------------
-- 2.6 Discrete events and switching

conditional :: forall a b. SF a Bool -> SF a b -> SF a b -> SF a b
conditional flag sfx sfy = sf
  where
    sf :: SF a b
    sf = proc i -> do
      x <- sfx -< i
      y <- sfy -< i
      b <- flag -< i
      returnA -< if b then x else y

switch', dSwitch' :: SF a (b, Event c) -> (c -> SF a b) -> SF a b
switch' = switch
dSwitch' = dSwitch
rSwitch', drSwitch' :: SF a b -> SF (a, Event (SF a b)) b
rSwitch' = rSwitch
drSwitch' = drSwitch

tag :: Event a -> b -> Event b
e `tag` b = fmap (const b) e

mergeBy' :: (a -> a -> a) -> Event a -> Event a -> Event a
mergeBy' = mergeBy
lMerge' :: Event a -> Event a -> Event a
lMerge' = lMerge
rMerge' :: Event a -> Event a -> Event a
rMerge' = rMerge
merge' :: Event a -> Event a -> Event a
merge' = merge

edge' :: SF Bool (Event ())
edge' = edge
never'      :: SF a (Event b)
never'      = never
now'        :: b -> SF a (Event b)
now'        = now
after'      :: Time -> b -> SF a (Event b)
after'      = after
repeatedly' :: Time -> b -> SF a (Event b)
repeatedly' = repeatedly
hold'  :: a -> SF (Event a) a
hold'  = hold
accum' :: a -> SF (Event (a -> a)) (Event a)
accum' = accum

accumHold :: a -> SF (Event (a -> a)) a
accumHold init = accum init >>> hold init

------------------------------------------------------------------------------
-- 2.7 Recursive signals

ones :: [Int]
ones = 1 : ones

------------------------------------------------------------------------------

eventsOf :: [Bool] -> [Event ()]
eventsOf = map (\b -> if b then Event () else NoEvent)

spec :: Spec
spec = do
  describe "2.1" $ do
    it "g, its point-free form and g' agree" $ do
      let (x, y, g') = section21g
      x `shouldBe` B 2
      y `shouldBe` B 2
      runDt 1 g' [1, 5] `shouldBe` [B 2, B 6]
    it "h and h' agree" $ do
      let (x, h') = section21h
      x `shouldBe` (B 2, C 0)
      runDt 1 h' [A 1, A 4] `shouldBe` [(B 2, C 0), (B 8, C 3)]
    it "i, (&), i' and its fused form agree" $ do
      let (x, y, i', i'') = section21i
      x `shouldBe` (C 10, A 102)
      y `shouldBe` x
      runDt 1 i' [(A 1, B 2)] `shouldBe` [x]
      runDt 1 i'' [(A 1, B 2)] `shouldBe` [x]
    it "the notes' *** equals the library's on stateful arguments" $ property $
      forAll (genSamples ((,) <$> arbitrary <*> arbitrary)) $ \s ->
        runSamples (integral *** iPre 0) s
          == runSamples (integral L.*** iPre (0 :: Int)) (s :: [(DTime, (Double, Int))])
  describe "2.2" $ do
    it "second and &&& defined from first agree with the library's" $ property $
      forAll (genSamples arbitrary) $ \s ->
        runSamples (iPre (0, 0) &&& second integral) s
          == runSamples (iPre (0, 0) L.&&& L.second integral) (s :: [(DTime, (Double, Double))])
    it "firstfun is first on functions" $
      firstfun (+ 1) (1 :: Int, 'c') `shouldBe` (2, 'c')
  describe "2.3" $ do
    it "the notes' arr2 equals the library's" $
      runDt 1 (arr2 (-)) [(5, 3 :: Int)] `shouldBe` runDt 1 (L.arr2 (-)) [(5, 3)]
    it "time is constant 1.0 >>> integral, up to rounding" $
      shouldApproxList (runDt 0.1 time (replicate 30 ()))
                       (runDt 0.1 (constant 1.0 >>> integral) (replicate 30 ()))
  describe "2.6" $ do
    it "the conditional sf follows sfx while flag is True, sfy otherwise" $
      runDt 1 (conditional (arr even) (arr (* 10)) (arr negate)) [1, 2, 3, 4 :: Int]
        `shouldBe` [-1, 20, -3, 40]
    it "the notes' tag equals the library's" $ do
      (Event 'a' `tag` True) `shouldBe` L.tag (Event 'a') True
      (NoEvent `tag` True) `shouldBe` L.tag (NoEvent :: Event Char) True
    it "the notes' accumHold equals the library's" $ property $ \bs ->
      let es = map (`L.tag` (+ 1)) (eventsOf bs)
      in not (null bs) ==> runDt 1 (accumHold (0 :: Int)) es == runDt 1 (L.accumHold 0) es
    it "alarmCountSF's idiom counts rising edges" $
      runDt 1 (edge >>> arr (`L.tag` (+ 1)) >>> accum 0 >>> hold (0 :: Int))
        [False, True, True, False, True, False, False, True]
        `shouldBe` [0, 1, 1, 1, 2, 2, 2, 3]
  describe "2.7" $
    it "ones is a well-founded stream" $
      take 3 ones `shouldBe` [1, 1, 1]
