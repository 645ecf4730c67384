-- | The laws of 'Category', 'Arrow', 'ArrowLoop', 'ArrowChoice', 'Functor'
-- and 'Applicative' for 'SF', checked on the sampled outputs of random
-- /stateful/ signal functions (integrals, delays, local time, held and
-- accumulated events, time-triggered switches), on random inputs and random
-- time steps.
--
-- Both sides of a law perform the same floating-point operations in the
-- same order, so they should agree exactly; outputs are nevertheless
-- compared with 'approx' (NaN equal to NaN) so that a law is not failed for
-- a last-bit difference that an optimiser rewrite could legitimately cause.
--
-- For 'ArrowChoice' the library's 'left' freezes the signal function on
-- 'Right' samples (as Yampa does); under that semantics every law below
-- holds for stateful signal functions. For 'ArrowLoop', the feedback of
-- every loop body goes through a delay ('iPre', 'integral', 'delay' or
-- 'dHold') inside the body, so every loop is well founded, and the tuple
-- plumbing uses lazy patterns (as the laws require in a lazy language).
module AFRP.LawsSpec (spec) where

import           Control.Category      ((.))
import qualified Control.Category      as C
import           Data.Function         (fix)
import           Prelude               hiding ((.))
import           Test.Hspec            hiding (after)
import           Test.QuickCheck       hiding (once, sample)

import           AFRP                  hiding (forAll)
import           TestUtil

------------------------------------------------------------------------------
-- Comparing outputs

class Show a => Close a where
  close :: a -> a -> Bool

instance Close Double where
  close x y = x == y || (isNaN x && isNaN y) || approx x y

instance Close Int where
  close = (==)

instance (Close a, Close b) => Close (a, b) where
  close (a, b) (c, d) = close a c && close b d

instance (Close a, Close b) => Close (Either a b) where
  close (Left a)  (Left b)  = close a b
  close (Right a) (Right b) = close a b
  close _         _         = False

instance Close a => Close [a] where
  close xs ys = length xs == length ys && and (zipWith close xs ys)

-- | Both sides of a law give the same outputs on the samples.
(=~=) :: Close b => SF a b -> SF a b -> [(DTime, a)] -> Property
(lhs =~= rhs) xs =
  let ys = runSamples lhs xs
      zs = runSamples rhs xs
  in within 30000000 (counterexample ("lhs: " ++ show ys ++ "\nrhs: " ++ show zs) (close ys zs))

infix 4 =~=

------------------------------------------------------------------------------
-- Random ingredients

genD :: Gen Double
genD = choose (-10, 10)

genC :: Gen Double
genC = choose (-3, 3)

genTime :: Gen Time
genTime = oneof [choose (0, 5), (/ 8) . fromIntegral <$> choose (0 :: Int, 40)]

genPeriod :: Gen Time
genPeriod = oneof [choose (0.05, 2), (/ 8) . fromIntegral <$> choose (1 :: Int, 16)]

-- | Samples with uniformly random or dyadic time steps.
samplesOf :: Gen a -> Gen [(DTime, a)]
samplesOf g = oneof [genSamples g, dyadic]
  where
    dyadic = do
      n <- choose (1, 40)
      vectorOf n ((,) <$> elements [0.125, 0.25, 0.5, 1] <*> g)

forSamples :: (Show a, Testable p) => Gen a -> ([(DTime, a)] -> p) -> Property
forSamples g = forAllShrink (samplesOf g) (filter (not . null) . shrinkList (const []))

-- | Pure unary functions.
data UFn = FAdd Double | FMul Double | FSin | FAbs | FMax Double
  deriving Show

appF :: UFn -> Double -> Double
appF f = case f of
  FAdd c -> (+ c)
  FMul c -> (* c)
  FSin   -> sin
  FAbs   -> abs
  FMax c -> max c

genUFn :: Gen UFn
genUFn = oneof [FAdd <$> genC, FMul <$> choose (-2, 2), pure FSin, pure FAbs, FMax <$> genC]

data Op = OAdd | OSub | OMul | OMax
  deriving (Show, Enum, Bounded)

appOp :: Op -> Double -> Double -> Double
appOp o = case o of
  OAdd -> (+)
  OSub -> (-)
  OMul -> \x y -> x * y
  OMax -> max

genOp :: Gen Op
genOp = elements [minBound .. maxBound]

clampD :: Double -> Double
clampD = max (-1000) . min 1000

-- | Random stateful signal functions on Doubles.
data S
  = SIntegral
  | SImIntegral Double
  | SIPre Double
  | STime                      -- ^ local time plus the input
  | SDeriv
  | SArr UFn
  | SDelay Time Double
  | SCountAbove Double         -- ^ how many rising edges of (> c) so far
  | SSampleHold Time
  | SAccumAbove Double         -- ^ accumHold of edges of (> c), doubling
  | SAfter Time S S            -- ^ switch from one to the other after t
  | SDHold Double              -- ^ dHold of edges of (> c), tagged with the input
  | SComp S S
  | SFan Op S S
  deriving Show

genS :: Int -> Gen S
genS n
  | n <= 1    = leaf
  | otherwise = frequency
      [ (3, leaf)
      , (3, SComp <$> half <*> half)
      , (2, SFan <$> genOp <*> half <*> half)
      , (1, SAfter <$> genTime <*> half <*> half)
      ]
  where
    half = genS (n `div` 2)
    leaf = frequency
      [ (3, pure SIntegral), (1, SImIntegral <$> genC), (3, SIPre <$> genC), (2, pure STime)
      , (1, pure SDeriv), (2, SArr <$> genUFn), (1, SDelay <$> genPeriod <*> genC)
      , (1, SCountAbove <$> genC), (1, SSampleHold <$> genPeriod), (1, SAccumAbove <$> genC)
      , (1, SDHold <$> genC) ]

shrinkS :: S -> [S]
shrinkS s = case s of
  SAfter _ a b -> [a, b]
  SComp a b    -> [a, b]
  SFan _ a b   -> [a, b]
  _            -> []

toS :: S -> SF Double Double
toS s = case s of
  SIntegral      -> integral
  SImIntegral c  -> imIntegral c
  SIPre c        -> iPre c
  STime          -> (localTime &&& identity) >>> arr (uncurry (+))
  SDeriv         -> derivative
  SArr f         -> arr (appF f)
  SDelay q c     -> delay q c
  SCountAbove c  -> arr (> c) >>> edge >>> count >>> hold (0 :: Int) >>> arr fromIntegral
  SSampleHold p  -> sample p >>> hold 0
  SAccumAbove c  -> arr (> c) >>> edge >>> arr (`tag` (* 2)) >>> accumHold 1
  SAfter t a b   -> switch (toS a &&& after t ()) (\() -> toS b)
  SDHold c       -> (identity &&& (arr (> c) >>> edge)) >>> arr (\(x, e) -> e `tag` x) >>> dHold 0
  SComp a b      -> toS a >>> toS b
  SFan o a b     -> (toS a &&& toS b) >>> arr (uncurry (appOp o))

genSF :: Gen S
genSF = choose (1, 8) >>= genS

forS :: Testable p => (S -> p) -> Property
forS = forAllShrink genSF shrinkS

-- | A delay on a feedback channel.
data Fb = FbIPre Double | FbIntegral | FbDelay Time Double | FbDHold Double
  deriving Show

genFb :: Gen Fb
genFb = oneof [FbIPre <$> genC, pure FbIntegral, FbDelay <$> genPeriod <*> genC, FbDHold <$> genC]

toFb :: Fb -> SF Double Double
toFb fb = case fb of
  FbIPre c     -> iPre c
  FbIntegral   -> integral
  FbDelay q c  -> delay q c
  FbDHold c    -> arr Event >>> dHold c

-- | A loop body whose fed-back input (second component) goes through a
-- delay before it is used: well founded.
data Body = Body Fb Op S S
  deriving Show

genBody :: Gen Body
genBody = Body <$> genFb <*> genOp <*> genSF <*> genSF

body :: Body -> SF (Double, Double) (Double, Double)
body (Body fb o s1 s2) =
  second (toFb fb)
  >>> ((arr (uncurry (appOp o)) >>> toS s1) &&& (arr (\ ~(b, d) -> b - 0.5 * d) >>> toS s2))
  >>> arr (\ ~(c, d) -> (c, clampD d))

-- | A body with two feedback channels (for the vanishing law).
data Body2 = Body2 Fb Fb S S S
  deriving Show

genBody2 :: Gen Body2
genBody2 = Body2 <$> genFb <*> genFb <*> genSF <*> genSF <*> genSF

body2 :: Body2 -> SF ((Double, Double), Double) ((Double, Double), Double)
body2 (Body2 fb1 fb2 s1 s2 s3) =
  arr (\ ~(~(b, d), e) -> (b, (d, e)))
  >>> second (toFb fb1 *** toFb fb2)
  >>> arr (\ ~(b, ~(d, e)) -> (b + d, (b - e, 0.5 * d + 0.25 * e)))
  >>> (toS s1 *** (toS s2 *** toS s3))
  >>> arr (\ ~(c, ~(d, e)) -> ((c, clampD d), clampD e))

------------------------------------------------------------------------------
-- Tuple and sum plumbing (lazy, as the laws require)

assoc :: ((a, b), c) -> (a, (b, c))
assoc ~(~(a, b), c) = (a, (b, c))

unassoc :: (a, (b, c)) -> ((a, b), c)
unassoc ~(a, ~(b, c)) = ((a, b), c)

assocsum :: Either (Either a b) c -> Either a (Either b c)
assocsum (Left (Left a))  = Left a
assocsum (Left (Right b)) = Right (Left b)
assocsum (Right c)        = Right (Right c)

genEither :: Gen a -> Gen b -> Gen (Either a b)
genEither ga gb = oneof [Left <$> ga, Right <$> gb]

pairs :: Gen (Double, Double)
pairs = (,) <$> genD <*> genD

------------------------------------------------------------------------------
-- The laws

spec :: Spec
spec = do
  categorySpec
  arrowSpec
  loopSpec
  choiceSpec
  functorSpec

categorySpec :: Spec
categorySpec = describe "Category" $ do
  it "left identity: id >>> f = f" $ property $ forS $ \f -> forSamples genD $
    (C.id >>> toS f) =~= toS f
  it "right identity: f >>> id = f" $ property $ forS $ \f -> forSamples genD $
    (toS f >>> C.id) =~= toS f
  it "associativity: (f >>> g) >>> h = f >>> (g >>> h)" $ property $
    forS $ \f -> forS $ \g -> forS $ \h -> forSamples genD $
      ((toS f >>> toS g) >>> toS h) =~= (toS f >>> (toS g >>> toS h))
  it "(.) is (>>>) flipped" $ property $ forS $ \f -> forS $ \g -> forSamples genD $
    (toS g . toS f) =~= (toS f >>> toS g)

arrowSpec :: Spec
arrowSpec = describe "Arrow" $ do
  it "arr id = id" $ property $ forSamples genD $
    arr id =~= (C.id :: SF Double Double)
  it "arr (g . f) = arr f >>> arr g" $ property $ forAll genUFn $ \f -> forAll genUFn $ \g ->
    forSamples genD $ arr (appF g . appF f) =~= (arr (appF f) >>> arr (appF g))
  it "first (arr f) = arr (first f)" $ property $ forAll genUFn $ \f -> forSamples pairs $
    first (arr (appF f)) =~= arr (first (appF f))
  it "first (f >>> g) = first f >>> first g" $ property $ forS $ \f -> forS $ \g ->
    forSamples pairs $ first (toS f >>> toS g) =~= (first (toS f) >>> first (toS g))
  it "first f >>> arr fst = arr fst >>> f" $ property $ forS $ \f -> forSamples pairs $
    (first (toS f) >>> arr fst) =~= (arr fst >>> toS f)
  it "first f >>> arr (id *** g) = arr (id *** g) >>> first f" $ property $
    forS $ \f -> forAll genUFn $ \g -> forSamples pairs $
      (first (toS f) >>> arr (id *** appF g)) =~= (arr (id *** appF g) >>> first (toS f))
  it "first (first f) >>> arr assoc = arr assoc >>> first f" $ property $
    forS $ \f -> forSamples ((,) <$> pairs <*> genD) $
      (first (first (toS f)) >>> arr assoc) =~= (arr assoc >>> first (toS f))
  it "second f = arr swap >>> first f >>> arr swap" $ property $ forS $ \f -> forSamples pairs $
    second (toS f) =~= (arr swap >>> first (toS f) >>> arr swap)
  it "f *** g = first f >>> second g" $ property $ forS $ \f -> forS $ \g -> forSamples pairs $
    (toS f *** toS g) =~= (first (toS f) >>> second (toS g))
  it "f &&& g = arr (\\x -> (x, x)) >>> (f *** g)" $ property $ forS $ \f -> forS $ \g ->
    forSamples genD $ (toS f &&& toS g) =~= (arr (\x -> (x, x)) >>> (toS f *** toS g))
  where
    swap (a, b) = (b, a)

loopSpec :: Spec
loopSpec = describe "ArrowLoop" $ do
  it "extension: loop (arr f) = arr (\\b -> fst (fix (\\(c, d) -> f (b, d))))" $ property $
    forAll genUFn $ \f1 -> forAll genUFn $ \f2 -> forAll genUFn $ \f3 -> forSamples genD $
      let f ~(b, d) = (appF f1 b + appF f2 d, appF f3 b)
      in loop (arr f) =~= arr (\b -> fst (fix (\ ~(_, d) -> f (b, d))))
  it "left tightening: loop (first h >>> f) = h >>> loop f" $ property $
    forS $ \h -> forAll genBody $ \f -> forSamples genD $
      loop (first (toS h) >>> body f) =~= (toS h >>> loop (body f))
  it "right tightening: loop (f >>> first h) = loop f >>> h" $ property $
    forS $ \h -> forAll genBody $ \f -> forSamples genD $
      loop (body f >>> first (toS h)) =~= (loop (body f) >>> toS h)
  it "sliding: loop (f >>> arr (id *** k)) = loop (arr (id *** k) >>> f)" $ property $
    forAll genUFn $ \k -> forAll genBody $ \f -> forSamples genD $
      loop (body f >>> arr (id *** appF k)) =~= loop (arr (id *** appF k) >>> body f)
  it "vanishing: loop (loop f) = loop (arr unassoc >>> f >>> arr assoc)" $ property $
    forAll genBody2 $ \f -> forSamples genD $
      loop (loop (body2 f)) =~= loop (arr unassoc >>> body2 f >>> arr assoc)
  it "superposing: second (loop f) = loop (arr assoc >>> second f >>> arr unassoc)" $ property $
    forAll genBody $ \f -> forSamples pairs $
      second (loop (body f)) =~= loop (arr assoc >>> second (body f) >>> arr unassoc)
  it "loopPre c f = loop (second (iPre c) >>> f)" $ property $
    forAll genC $ \c -> forAll genBody $ \f -> forSamples genD $
      loopPre c (body f) =~= loop (second (iPre c) >>> body f)
  it "loopIntegral f = loop (second integral >>> f)" $ property $
    forAll genBody $ \f -> forSamples genD $
      loopIntegral (body f) =~= loop (second integral >>> body f)

choiceSpec :: Spec
choiceSpec = describe "ArrowChoice" $ do
  it "left (arr f) = arr (left f)" $ property $ forAll genUFn $ \f ->
    forSamples (genEither genD genD) $
      left (arr (appF f)) =~= (arr (left (appF f)) :: SF (Either Double Double) (Either Double Double))
  it "left (f >>> g) = left f >>> left g" $ property $ forS $ \f -> forS $ \g ->
    forSamples (genEither genD genD) $
      (left (toS f >>> toS g) :: SF (Either Double Double) (Either Double Double))
        =~= (left (toS f) >>> left (toS g))
  it "f >>> arr Left = arr Left >>> left f" $ property $ forS $ \f -> forSamples genD $
    (toS f >>> arr Left) =~= (arr Left >>> left (toS f) :: SF Double (Either Double Double))
  it "left f >>> arr (id +++ g) = arr (id +++ g) >>> left f" $ property $
    forS $ \f -> forAll genUFn $ \g -> forSamples (genEither genD genD) $
      (left (toS f) >>> arr (id +++ appF g)) =~= (arr (id +++ appF g) >>> left (toS f))
  it "left (left f) >>> arr assocsum = arr assocsum >>> left f" $ property $
    forS $ \f -> forSamples (genEither (genEither genD genD) genD) $
      (left (left (toS f)) >>> arr assocsum)
        =~= (arr assocsum >>> left (toS f) :: SF (Either (Either Double Double) Double)
                                                  (Either Double (Either Double Double)))
  it "right f = arr mirror >>> left f >>> arr mirror" $ property $ forS $ \f ->
    forSamples (genEither genD genD) $
      (right (toS f) :: SF (Either Double Double) (Either Double Double))
        =~= (arr mirror >>> left (toS f) >>> arr mirror)
  it "f +++ g = left f >>> right g, and f ||| g = (f +++ g) >>> arr untag" $ property $
    forS $ \f -> forS $ \g -> forSamples (genEither genD genD) $ \xs ->
      ((toS f +++ toS g) =~= (left (toS f) >>> right (toS g))) xs
        .&&. ((toS f ||| toS g) =~= ((toS f +++ toS g) >>> arr (either id id))) xs
  where
    mirror :: Either a b -> Either b a
    mirror = either Right Left

functorSpec :: Spec
functorSpec = describe "Functor and Applicative (SF a)" $ do
  it "fmap id = id" $ property $ forS $ \v -> forSamples genD $
    fmap id (toS v) =~= toS v
  it "fmap (f . g) = fmap f . fmap g" $ property $ forS $ \v -> forAll genUFn $ \f -> forAll genUFn $ \g ->
    forSamples genD $ fmap (appF f . appF g) (toS v) =~= fmap (appF f) (fmap (appF g) (toS v))
  it "fmap f v = v >>> arr f" $ property $ forS $ \v -> forAll genUFn $ \f -> forSamples genD $
    fmap (appF f) (toS v) =~= (toS v >>> arr (appF f))
  it "identity: pure id <*> v = v" $ property $ forS $ \v -> forSamples genD $
    (pure id <*> toS v) =~= toS v
  it "composition: pure (.) <*> u <*> v <*> w = u <*> (v <*> w)" $ property $
    forFun $ \u -> forFun $ \v -> forS $ \w -> forSamples genD $
      (pure (.) <*> funSF u <*> funSF v <*> toS w) =~= (funSF u <*> (funSF v <*> toS w))
  it "homomorphism: pure f <*> pure x = pure (f x)" $ property $ forAll genUFn $ \f -> forAll genD $ \x ->
    forSamples genD $ (pure (appF f) <*> pure x) =~= (pure (appF f x) :: SF Double Double)
  it "interchange: u <*> pure y = pure ($ y) <*> u" $ property $ forFun $ \u -> forAll genD $ \y ->
    forSamples genD $ (funSF u <*> pure y) =~= (pure ($ y) <*> funSF u)
  it "liftA2 f u v = (u &&& v) >>> arr (uncurry f)" $ property $ forS $ \u -> forS $ \v -> forAll genOp $ \o ->
    forSamples genD $ (appOp o <$> toS u <*> toS v) =~= ((toS u &&& toS v) >>> arr (uncurry (appOp o)))
  where
    -- A signal of functions: the output of a stateful SF combined with the
    -- argument by an operator.
    forFun :: Testable p => ((Op, S) -> p) -> Property
    forFun = forAllShrink ((,) <$> genOp <*> genSF) (\(o, s) -> [(o, s') | s' <- shrinkS s])
    funSF :: (Op, S) -> SF Double (Double -> Double)
    funSF (o, s) = toS s >>> arr (appOp o)
