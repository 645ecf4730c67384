-- | Differential tests: every combinator of the library, run on random
-- inputs and random time steps, must agree with the naive model in
-- "Reference" — exactly for discrete outputs (events, counts, held
-- values), and within a tolerance for continuous ones.
--
-- Besides one or more properties per combinator, a small random expression
-- language of signal functions ('E') is interpreted both as a library 'SF'
-- and as a reference 'R', so that random /networks/ (where the library's
-- optimiser fuses, drops and collapses nodes, and removes switches that can
-- no longer fire) are checked too.
--
-- Tolerances. The reference computes local time exactly (a 'Rational' sum
-- of the time steps, rounded once), while the library keeps a compensated
-- floating-point sum; the two agree to the last bit except in rare cases.
-- Integrals and derivatives are written with the same floating-point
-- formula in both, so single combinators are compared with 'approx'
-- (1e-9, relative and absolute). Random networks are compared within 1e-6:
-- a one-ulp difference in a local time can be amplified by a chain of
-- derivatives (division by steps down to 0.001) and products, and 1e-6
-- still catches any semantic difference (a sample shifted, an event lost,
-- a frozen signal function resumed with the wrong step), which changes
-- values at the percent level.
--
-- Time-triggered events are compared exactly. Random time steps are drawn
-- either uniformly from [0.001, 1] (no exact ties with thresholds) or from
-- {1/8, 1/4, 1/2, 1} with thresholds that are multiples of 1/8 (exact ties,
-- computed exactly by both sides), so the inclusive @>=@ of the timing
-- rules is exercised.
--
-- Further groups check that the primitives documented as not evaluating
-- their current input (and the decoupled switches) can close feedback
-- loops, and that the library and the reference both reproduce the
-- examples of the library's documentation and Yampa's regression examples.
--
-- Every property is guarded by a 5 s timeout ('within'), so a signal
-- function stuck on its own output fails instead of hanging the suite.
module AFRP.ReferenceSpec (spec) where

import           Test.Hspec            hiding (after)
import           Test.Hspec.QuickCheck (modifyMaxSuccess)
import           Test.QuickCheck       hiding (once, sample)

import           AFRP                  hiding (forAll)
import           Reference             (R (..))
import qualified Reference             as Ref
import           TestUtil

------------------------------------------------------------------------------
-- Comparing outputs

-- | Equality up to a relative-and-absolute tolerance, componentwise.
class Show a => Close a where
  closeWith :: Double -> a -> a -> Bool

instance Close Double where
  closeWith tol x y
    | x == y             = True
    | isNaN x && isNaN y = True
    | otherwise          = approxWith tol x y

instance Close Int where
  closeWith _ = (==)

instance Close Bool where
  closeWith _ = (==)

instance Close () where
  closeWith _ _ _ = True

instance Close Char where
  closeWith _ = (==)

instance (Close a, Close b) => Close (a, b) where
  closeWith tol (a, b) (c, d) = closeWith tol a c && closeWith tol b d

instance (Close a, Close b) => Close (Either a b) where
  closeWith tol (Left a)  (Left b)  = closeWith tol a b
  closeWith tol (Right a) (Right b) = closeWith tol a b
  closeWith _   _         _         = False

instance Close a => Close (Event a) where
  closeWith tol (Event a) (Event b) = closeWith tol a b
  closeWith _   NoEvent   NoEvent   = True
  closeWith _   _         _         = False

instance Close a => Close [a] where
  closeWith tol xs ys = length xs == length ys && and (zipWith (closeWith tol) xs ys)

-- | The library and the reference give exactly the same outputs.
agree :: (Eq b, Show b) => SF a b -> R a b -> [(DTime, a)] -> Property
agree sf r xs = guarded (runSamples sf xs === runR r xs)

-- | A run that does not finish within 30 s fails instead of hanging the
-- suite (a signal function stuck on its own value, @<<loop>>@, is not
-- always detected while other threads are alive).
guarded :: Testable p => p -> Property
guarded = within 30000000

-- | The outputs agree within the tolerance of 'approx'.
agreeApprox :: Close b => SF a b -> R a b -> [(DTime, a)] -> Property
agreeApprox = agreeWithin 1e-9

agreeWithin :: Close b => Double -> SF a b -> R a b -> [(DTime, a)] -> Property
agreeWithin tol sf r xs =
  let ys = runSamples sf xs
      zs = runR r xs
  in guarded (counterexample ("library:   " ++ show ys ++ "\nreference: " ++ show zs
                              ++ "\nfirst difference at sample " ++ show (firstDiff ys zs))
                             (closeWith tol ys zs))
  where
    firstDiff ys zs = length (takeWhile id (zipWith (closeWith tol) ys zs))

------------------------------------------------------------------------------
-- Generators of inputs

-- | Samples with either uniformly random time steps or dyadic ones.
genSamplesT :: Gen a -> Gen [(DTime, a)]
genSamplesT g = oneof [genSamples g, dyadic]
  where
    dyadic = do
      n <- choose (1, 40)
      vectorOf n ((,) <$> elements [0.125, 0.25, 0.5, 1] <*> g)

-- | Drop samples (keeping at least one) and shrink the values.
shrinkSamples :: (a -> [a]) -> [(DTime, a)] -> [[(DTime, a)]]
shrinkSamples shr xs =
  filter (not . null) (shrinkList (\(dt, a) -> [(dt, a') | a' <- shr a]) xs)

forSamples :: (Show a, Testable p) => Gen a -> ([(DTime, a)] -> p) -> Property
forSamples g = forAllShrink (genSamplesT g) (shrinkSamples (const []))

-- | A time (threshold): uniform, or a multiple of 1/8.
genTime :: Gen Time
genTime = oneof [choose (0, 5), (/ 8) . fromIntegral <$> choose (0 :: Int, 40)]

-- | A positive period or delay.
genPeriod :: Gen Time
genPeriod = oneof [choose (0.05, 2), (/ 8) . fromIntegral <$> choose (1 :: Int, 16)]

genD :: Gen Double
genD = choose (-10, 10)

genC :: Gen Double
genC = choose (-3, 3)

genSmallInt :: Gen Int
genSmallInt = choose (-5, 5)

-- | Events with a random density (chosen once per list).
genEventsOf :: Gen a -> Gen [(DTime, Event a)]
genEventsOf g = do
  w <- elements [1, 2, 4, 8, 16]
  genSamplesT (frequency [(w, pure NoEvent), (2, Event <$> g)])

forEvents :: (Show a, Testable p) => Gen a -> ([(DTime, Event a)] -> p) -> Property
forEvents g = forAllShrink (genEventsOf g) (shrinkSamples shrinkEv)
  where
    shrinkEv (Event _) = [NoEvent]
    shrinkEv NoEvent   = []

-- | A Double input with an event component.
genWithEvents :: Gen b -> Gen [(DTime, (Double, Event b))]
genWithEvents g = do
  w <- elements [2, 4, 8, 16]
  genSamplesT ((,) <$> genD <*> frequency [(w, pure NoEvent), (2, Event <$> g)])

------------------------------------------------------------------------------
-- Small function languages (so that inputs are showable)

-- | Unary functions on Doubles.
data UFn = FAdd Double | FMul Double | FSin | FTanh | FAbs | FNeg | FMax Double
  deriving Show

appF :: UFn -> Double -> Double
appF f = case f of
  FAdd c -> (+ c)
  FMul c -> (* c)
  FSin   -> sin
  FTanh  -> tanh
  FAbs   -> abs
  FNeg   -> negate
  FMax c -> max c

genUFn :: Gen UFn
genUFn = oneof [ FAdd <$> genC, FMul <$> choose (-2, 2), pure FSin, pure FTanh
               , pure FAbs, pure FNeg, FMax <$> genC ]

-- | Binary operators.
data Op = OAdd | OSub | OMul | OMax
  deriving (Show, Eq, Enum, Bounded)

appOp :: Op -> Double -> Double -> Double
appOp o = case o of
  OAdd -> (+)
  OSub -> (-)
  OMul -> \x y -> x * y
  OMax -> max

genOp :: Gen Op
genOp = elements [minBound .. maxBound]

-- | Functions on Int (for 'accum').
data IFn = IAdd Int | IMul Int | INeg | ISquareMod
  deriving Show

appI :: IFn -> Int -> Int
appI f = case f of
  IAdd k     -> (+ k)
  IMul k     -> (* k)
  INeg       -> negate
  ISquareMod -> \n -> (n * n) `mod` 97

genIFn :: Gen IFn
genIFn = oneof [IAdd <$> genSmallInt, IMul <$> choose (-3, 3), pure INeg, pure ISquareMod]

-- | Changes of a collection (for the recurring parallel switches).
-- 'OpLater' puts every member on hold for a while: a member frozen by the
-- switch then resumes later than the switching instant, with the time step
-- it was frozen with.
data ColOp = OpCons Int | OpTail | OpRev | OpKeep | OpSwap | OpLater Time
  deriving Show

genColOp :: Gen ColOp
genColOp = oneof [ OpCons <$> choose (0, 5), pure OpTail, pure OpRev, pure OpKeep, pure OpSwap
                 , OpLater <$> genPeriod ]

-- | @appColOp mk later op@: @mk i@ builds a new member, @later t s@ holds
-- member @s@ back for @t@ seconds.
appColOp :: (Int -> s) -> (Time -> s -> s) -> ColOp -> [s] -> [s]
appColOp mk later op sfs = case op of
  OpCons i  -> mk i : sfs
  OpTail    -> drop 1 sfs
  OpRev     -> reverse sfs
  OpKeep    -> sfs
  OpSwap    -> case sfs of
    (a : b : rest) -> b : a : rest
    _              -> sfs
  OpLater t -> map (later t) sfs

-- | Output 0 for t seconds, then run the given signal function (started
-- then).
laterL :: Time -> SF a Double -> SF a Double
laterL t sf = switch (constant 0 &&& after t ()) (const sf)

laterR :: Time -> R a Double -> R a Double
laterR t sf = Ref.switch (Ref.constant 0 Ref.&&& Ref.after t ()) (const sf)

clampD :: Double -> Double
clampD = max (-1000) . min 1000

------------------------------------------------------------------------------
-- Random event sources (input: a Double signal)

data Ev
  = EvNever
  | EvNow
  | EvAfter Time
  | EvRepeatedly Time
  | EvAbove Double              -- ^ rising edge of (> c)
  | EvAboveNotYet Double        -- ^ iEdge False of (> c), not at time 0
  | EvOnceDrop Double           -- ^ edge >>> once >>> dropEvents 1: never fires
  | EvTake Int Double
  | EvDrop Int Double
  | EvDelayed Time Double       -- ^ iEdge False of (> c), delayed
  | EvAfterEach [Time]
  | EvSnapAfter Time
  | EvSample Time Double        -- ^ samples of the input above c
  deriving Show

genEv :: Gen Ev
genEv = frequency
  [ (1, pure EvNever), (1, pure EvNow), (2, EvAfter <$> genTime)
  , (2, EvRepeatedly <$> genPeriod), (3, EvAbove <$> genC), (1, EvAboveNotYet <$> genC)
  , (1, EvOnceDrop <$> genC), (1, EvTake <$> choose (0, 3) <*> genC)
  , (1, EvDrop <$> choose (0, 3) <*> genC), (1, EvDelayed <$> genPeriod <*> genC)
  , (1, EvAfterEach <$> listOf (oneof [pure 0, choose (0, 1.5)]))
  , (1, EvSnapAfter <$> genTime), (1, EvSample <$> genPeriod <*> genC)
  ]

evSF :: Ev -> SF Double (Event ())
evSF ev = case ev of
  EvNever         -> never
  EvNow           -> now ()
  EvAfter t       -> after t ()
  EvRepeatedly p  -> repeatedly p ()
  EvAbove c       -> arr (> c) >>> edge
  EvAboveNotYet c -> arr (> c) >>> iEdge False >>> notYet
  EvOnceDrop c    -> arr (> c) >>> edge >>> once >>> dropEvents 1
  EvTake n c      -> arr (> c) >>> iEdge False >>> takeEvents n
  EvDrop n c      -> arr (> c) >>> edge >>> dropEvents n
  EvDelayed q c   -> arr (> c) >>> iEdge False >>> delayEvent q
  EvAfterEach qs  -> afterEach [(q, ()) | q <- qs]
  EvSnapAfter t   -> snapAfter t >>> arr (fmap (const ()))
  EvSample p c    -> sample p >>> arr (aboveE c)

evR :: Ev -> R Double (Event ())
evR ev = case ev of
  EvNever         -> Ref.never
  EvNow           -> Ref.now ()
  EvAfter t       -> Ref.after t ()
  EvRepeatedly p  -> Ref.repeatedly p ()
  EvAbove c       -> Ref.arr (> c) Ref.>>> Ref.edge
  EvAboveNotYet c -> Ref.arr (> c) Ref.>>> Ref.iEdge False Ref.>>> Ref.notYet
  EvOnceDrop c    -> Ref.arr (> c) Ref.>>> Ref.edge Ref.>>> Ref.once Ref.>>> Ref.dropEvents 1
  EvTake n c      -> Ref.arr (> c) Ref.>>> Ref.iEdge False Ref.>>> Ref.takeEvents n
  EvDrop n c      -> Ref.arr (> c) Ref.>>> Ref.edge Ref.>>> Ref.dropEvents n
  EvDelayed q c   -> Ref.arr (> c) Ref.>>> Ref.iEdge False Ref.>>> Ref.delayEvent q
  EvAfterEach qs  -> Ref.afterEach [(q, ()) | q <- qs]
  EvSnapAfter t   -> Ref.snapAfter t Ref.>>> Ref.arr (fmap (const ()))
  EvSample p c    -> Ref.sample p Ref.>>> Ref.arr (aboveE c)

aboveE :: Double -> Event Double -> Event ()
aboveE c (Event x) | x > c = Event ()
aboveE _ _                 = NoEvent

------------------------------------------------------------------------------
-- Random signal functions SF Double Double

data E
  = EId
  | EConst Double
  | EArr UFn
  | ETime
  | EIntegral
  | EImIntegral Double
  | ETrap
  | EDeriv
  | EIPre Double
  | EDelay Time Double
  | EComp E E
  | EFan Op E E
  | EPar Op E E
  | EFirst Op E
  | ESecond Op E
  | EInit Double E
  | EInInit Double E
  | EOutMap UFn E
  | EInMap UFn E
  | EFby Double E
  | ESwitch Bool Ev E E          -- ^ (d)switch on (e &&& ev), continuation fixed
  | ESwitchV Bool Ev E E         -- ^ (d)switch passing the output value at the event
  | ERSwitch Bool Ev E E         -- ^ (d)rSwitch, events carrying the second SF
  | EKSwitch Bool Bool Ev E E    -- ^ (d)kSwitch, detector on input or output
  | EHold Bool Ev E              -- ^ (d)hold of the output, sampled at the events
  | ESampleHold Time E
  | ECount Ev
  | ELeft Double E
  | ELoopPre Double E
  | ELoopInt E
  | EParB [E]
  | EPSwitch Bool Double [E] E   -- ^ (d)pSwitchB on the sum crossing c
  | ERPSwitch Bool Ev [E] E      -- ^ (d)rpSwitchB, each event consing the SF
  | EParZ [E]
  deriving Show

-- | The library's interpretation.
toSF :: E -> SF Double Double
toSF expr = case expr of
  EId               -> identity
  EConst c          -> constant c
  EArr f            -> arr (appF f)
  ETime             -> localTime
  EIntegral         -> integral
  EImIntegral c     -> imIntegral c
  ETrap             -> trapezoidIntegral
  EDeriv            -> derivative
  EIPre c           -> iPre c
  EDelay q c        -> delay q c
  EComp a b         -> toSF a >>> toSF b
  EFan o a b        -> (toSF a &&& toSF b) >>> arr (uncurry (appOp o))
  EPar o a b        -> arr (\x -> (x, negate x)) >>> (toSF a *** toSF b) >>> arr (uncurry (appOp o))
  EFirst o a        -> arr (\x -> (x, 2 * x)) >>> first (toSF a) >>> arr (uncurry (appOp o))
  ESecond o a       -> arr (\x -> (x, 2 * x)) >>> second (toSF a) >>> arr (uncurry (appOp o))
  EInit c a         -> c --> toSF a
  EInInit c a       -> c >-- toSF a
  EOutMap f a       -> appF f -=> toSF a
  EInMap f a        -> appF f >=- toSF a
  EFby c a          -> c `fby` toSF a
  ESwitch d ev a b  -> (if d then dSwitch else switch) (toSF a &&& evSF ev) (\() -> toSF b)
  ESwitchV d ev a b -> (if d then dSwitch else switch)
                         ((toSF a &&& evSF ev) >>> arr (\(y, e) -> (y, e `tag` y)))
                         (\y -> toSF b >>> arr (+ y))
  ERSwitch d ev a b -> (identity &&& (evSF ev >>> arr (`tag` toSF b)))
                       >>> (if d then drSwitch else rSwitch) (toSF a)
  EKSwitch d onOut ev a b ->
    (if d then dkSwitch else kSwitch) (toSF a)
      (arr (if onOut then snd else fst) >>> evSF ev)
      (\frozen () -> (frozen &&& toSF b) >>> arr (uncurry (+)))
  EHold d ev a      -> (toSF a &&& evSF ev) >>> arr (\(y, e) -> e `tag` y)
                       >>> (if d then dHold 0 else hold 0)
  ESampleHold p a   -> toSF a >>> sample p >>> hold 0
  ECount ev         -> evSF ev >>> count >>> hold (0 :: Int) >>> arr fromIntegral
  ELeft c a         -> arr (\x -> if x > c then Left x else Right x) >>> left (toSF a)
                       >>> arr (either id negate)
  ELoopPre c a      -> loopPre c (arr (\(x, y) -> x + 0.5 * y) >>> toSF a >>> arr (\z -> (z, clampD z)))
  ELoopInt a        -> loopIntegral (arr (\(x, i) -> x - 0.5 * i) >>> toSF a >>> arr (\z -> (z, clampD z)))
  EParB as          -> parB (map toSF as) >>> arr sum
  EPSwitch d c as b -> (if d then dpSwitchB else pSwitchB) (map toSF as)
                         (arr (\(_, ys) -> sum ys > c) >>> iEdge False)
                         (\sfs () -> parB (toSF b : reverse sfs))
                       >>> arr sum
  ERPSwitch d ev as b -> (identity &&& (evSF ev >>> arr (`tag` (\sfs -> toSF b : reverse sfs))))
                         >>> (if d then drpSwitchB else rpSwitchB) (map toSF as) >>> arr sum
  EParZ as          -> arr (\x -> [x * fromIntegral i | i <- [1 .. length as + 1]])
                       >>> parZ (map toSF as) >>> arr sum

-- | The reference interpretation (the same network, built from "Reference").
toR :: E -> R Double Double
toR expr = case expr of
  EId               -> Ref.identity
  EConst c          -> Ref.constant c
  EArr f            -> Ref.arr (appF f)
  ETime             -> Ref.localTime
  EIntegral         -> Ref.integral
  EImIntegral c     -> Ref.imIntegral c
  ETrap             -> Ref.trapezoidIntegral
  EDeriv            -> Ref.derivative
  EIPre c           -> Ref.iPre c
  EDelay q c        -> Ref.delay q c
  EComp a b         -> toR a Ref.>>> toR b
  EFan o a b        -> (toR a Ref.&&& toR b) Ref.>>> Ref.arr (uncurry (appOp o))
  EPar o a b        -> Ref.arr (\x -> (x, negate x)) Ref.>>> (toR a Ref.*** toR b)
                       Ref.>>> Ref.arr (uncurry (appOp o))
  EFirst o a        -> Ref.arr (\x -> (x, 2 * x)) Ref.>>> Ref.first (toR a)
                       Ref.>>> Ref.arr (uncurry (appOp o))
  ESecond o a       -> Ref.arr (\x -> (x, 2 * x)) Ref.>>> Ref.second (toR a)
                       Ref.>>> Ref.arr (uncurry (appOp o))
  EInit c a         -> c Ref.--> toR a
  EInInit c a       -> c Ref.>-- toR a
  EOutMap f a       -> appF f Ref.-=> toR a
  EInMap f a        -> appF f Ref.>=- toR a
  EFby c a          -> c `Ref.fby` toR a
  ESwitch d ev a b  -> (if d then Ref.dSwitch else Ref.switch) (toR a Ref.&&& evR ev) (\() -> toR b)
  ESwitchV d ev a b -> (if d then Ref.dSwitch else Ref.switch)
                         ((toR a Ref.&&& evR ev) Ref.>>> Ref.arr (\(y, e) -> (y, fmap (const y) e)))
                         (\y -> toR b Ref.>>> Ref.arr (+ y))
  ERSwitch d ev a b -> (Ref.identity Ref.&&& (evR ev Ref.>>> Ref.arr (fmap (const (toR b)))))
                       Ref.>>> (if d then Ref.drSwitch else Ref.rSwitch) (toR a)
  EKSwitch d onOut ev a b ->
    (if d then Ref.dkSwitch else Ref.kSwitch) (toR a)
      (Ref.arr (if onOut then snd else fst) Ref.>>> evR ev)
      (\frozen () -> (frozen Ref.&&& toR b) Ref.>>> Ref.arr (uncurry (+)))
  EHold d ev a      -> (toR a Ref.&&& evR ev) Ref.>>> Ref.arr (\(y, e) -> fmap (const y) e)
                       Ref.>>> (if d then Ref.dHold 0 else Ref.hold 0)
  ESampleHold p a   -> toR a Ref.>>> Ref.sample p Ref.>>> Ref.hold 0
  ECount ev         -> evR ev Ref.>>> Ref.count Ref.>>> Ref.hold (0 :: Int) Ref.>>> Ref.arr fromIntegral
  ELeft c a         -> Ref.arr (\x -> if x > c then Left x else Right x) Ref.>>> Ref.left (toR a)
                       Ref.>>> Ref.arr (either id negate)
  ELoopPre c a      -> Ref.loopPre c (Ref.arr (\(x, y) -> x + 0.5 * y) Ref.>>> toR a
                                      Ref.>>> Ref.arr (\z -> (z, clampD z)))
  ELoopInt a        -> Ref.loopIntegral (Ref.arr (\(x, i) -> x - 0.5 * i) Ref.>>> toR a
                                         Ref.>>> Ref.arr (\z -> (z, clampD z)))
  EParB as          -> Ref.parB (map toR as) Ref.>>> Ref.arr sum
  EPSwitch d c as b -> (if d then Ref.dpSwitchB else Ref.pSwitchB) (map toR as)
                         (Ref.arr (\(_, ys) -> sum ys > c) Ref.>>> Ref.iEdge False)
                         (\rs () -> Ref.parB (toR b : reverse rs))
                       Ref.>>> Ref.arr sum
  ERPSwitch d ev as b -> (Ref.identity Ref.&&& (evR ev Ref.>>> Ref.arr (fmap (const (\rs -> toR b : reverse rs)))))
                         Ref.>>> (if d then Ref.drpSwitchB else Ref.rpSwitchB) (map toR as) Ref.>>> Ref.arr sum
  EParZ as          -> Ref.arr (\x -> [x * fromIntegral i | i <- [1 .. length as + 1]])
                       Ref.>>> Ref.parZ (map toR as) Ref.>>> Ref.arr sum

genLeaf :: Gen E
genLeaf = frequency
  [ (1, pure EId), (1, EConst <$> genC), (4, EArr <$> genUFn), (2, pure ETime)
  , (2, pure EIntegral), (1, EImIntegral <$> genC), (1, pure ETrap), (1, pure EDeriv)
  , (2, EIPre <$> genC), (1, EDelay <$> oneof [pure 0, genPeriod] <*> genC), (1, ECount <$> genEv) ]

-- | A random network with a size budget.
genE :: Int -> Gen E
genE n
  | n <= 1    = genLeaf
  | otherwise = frequency
      [ (3, genLeaf)
      , (6, EComp <$> half <*> half)
      , (3, EFan <$> genOp <*> half <*> half)
      , (1, EPar <$> genOp <*> half <*> half)
      , (1, EFirst <$> genOp <*> sub)
      , (1, ESecond <$> genOp <*> sub)
      , (1, EInit <$> genC <*> sub)
      , (1, EInInit <$> genC <*> sub)
      , (1, EOutMap <$> genUFn <*> sub)
      , (1, EInMap <$> genUFn <*> sub)
      , (1, EFby <$> genC <*> sub)
      , (2, ESwitch <$> arbitrary <*> genEv <*> half <*> half)
      , (1, ESwitchV <$> arbitrary <*> genEv <*> half <*> half)
      , (2, ERSwitch <$> arbitrary <*> genEv <*> half <*> half)
      , (2, EKSwitch <$> arbitrary <*> arbitrary <*> genEv <*> half <*> half)
      , (1, EHold <$> arbitrary <*> genEv <*> sub)
      , (1, ESampleHold <$> genPeriod <*> sub)
      , (1, ELeft <$> genC <*> sub)
      , (1, ELoopPre <$> genC <*> sub)
      , (1, ELoopInt <$> sub)
      , (1, EParB <$> smallList)
      , (1, EPSwitch <$> arbitrary <*> genC <*> smallList <*> third)
      , (1, ERPSwitch <$> arbitrary <*> genEv <*> smallList <*> third)
      , (1, EParZ <$> smallList)
      ]
  where
    sub       = genE (n - 1)
    half      = genE (n `div` 2)
    third     = genE (n `div` 3)
    smallList = do
      k <- choose (0, 3)
      vectorOf k (genE (n `div` max 1 k))

-- | Shrink to sub-networks (all have the same type).
shrinkE :: E -> [E]
shrinkE expr = case expr of
  EComp a b           -> [a, b]
  EFan _ a b          -> [a, b]
  EPar _ a b          -> [a, b]
  EFirst _ a          -> [a]
  ESecond _ a         -> [a]
  EInit _ a           -> [a]
  EInInit _ a         -> [a]
  EOutMap _ a         -> [a]
  EInMap _ a          -> [a]
  EFby _ a            -> [a]
  ESwitch _ _ a b     -> [a, b]
  ESwitchV _ _ a b    -> [a, b]
  ERSwitch _ _ a b    -> [a, b]
  EKSwitch _ _ _ a b  -> [a, b]
  EHold _ _ a         -> [a]
  ESampleHold _ a     -> [a]
  ELeft _ a           -> [a]
  ELoopPre _ a        -> [a]
  ELoopInt a          -> [a]
  EParB as            -> as
  EPSwitch _ _ as b   -> b : as
  ERPSwitch _ _ as b  -> b : as
  EParZ as            -> as
  _                   -> []

genNet :: Gen E
genNet = choose (1, 12) >>= genE

-- | A few candidate networks, and a way to pick one by an arbitrary Int.
genCands :: Gen [E]
genCands = vectorOf 3 (choose (1, 5) >>= genE)

pick :: [E] -> Int -> E
pick cs i = cs !! (i `mod` length cs)

------------------------------------------------------------------------------
-- The spec

spec :: Spec
spec = do
  basicSpec
  eventSourceSpec
  hybridSpec
  delaySpec
  integrationSpec
  loopSpec
  decoupledSpec
  switchSpec
  parallelSpec
  networkSpec
  examplesSpec

basicSpec :: Spec
basicSpec = describe "arrow combinators and basic signal functions" $ do
  it "arr" $ property $ forAll genUFn $ \f -> forSamples genD $ \xs ->
    agree (arr (appF f)) (Ref.arr (appF f)) xs

  it ">>> (stateful on both sides)" $ property $ forAll genC $ \c -> forSamples genD $ \xs ->
    agreeApprox (integral >>> iPre c >>> derivative) (Ref.integral Ref.>>> Ref.iPre c Ref.>>> Ref.derivative) xs

  it "first" $ property $ forSamples ((,) <$> genD <*> genSmallInt) $ \xs ->
    agreeApprox (first integral) (Ref.first Ref.integral) xs

  it "second" $ property $ forSamples ((,) <$> genSmallInt <*> genD) $ \xs ->
    agreeApprox (second (localTime &&& integral)) (Ref.second (Ref.localTime Ref.&&& Ref.integral)) xs

  it "***" $ property $ forAll genC $ \c -> forSamples ((,) <$> genD <*> genD) $ \xs ->
    agreeApprox (integral *** iPre c) (Ref.integral Ref.*** Ref.iPre c) xs

  it "&&&" $ property $ forSamples genD $ \xs ->
    agreeApprox (derivative &&& trapezoidIntegral) (Ref.derivative Ref.&&& Ref.trapezoidIntegral) xs

  it "loop (fed back through iPre)" $ property $ forAll genC $ \c -> forSamples genD $ \xs ->
    agreeApprox (loop (second (iPre c) >>> arr (\(x, y) -> (x + y, 0.5 * x - 0.25 * y))))
                (Ref.loop (Ref.second (Ref.iPre c) Ref.>>> Ref.arr (\(x, y) -> (x + y, 0.5 * x - 0.25 * y))))
                xs

  it "loop (fed back through integral, stateful body)" $ property $ forSamples genD $ \xs ->
    agreeApprox (loop (second integral >>> arr (\(x, i) -> (i, x - i)) >>> first localTime'))
                (Ref.loop (Ref.second Ref.integral Ref.>>> Ref.arr (\(x, i) -> (i, x - i))
                           Ref.>>> Ref.first refLocalTime'))
                xs

  it "loop (pure: extension)" $ property $ forSamples genD $ \xs ->
    agreeApprox (loop (arr (\(x, d) -> (x + d, 2 * x))))
                (Ref.loop (Ref.arr (\(x, d) -> (x + d, 2 * x)))) xs

  it "left (integral): frozen while not fed" $ property $
    forSamples (oneof [Left <$> genD, Right <$> genSmallInt]) $ \xs ->
      agreeApprox (left integral) (Ref.left Ref.integral) xs

  it "left (localTime)" $ property $
    forSamples (oneof [Left <$> genD, Right <$> genSmallInt]) $ \xs ->
      agreeApprox (left localTime) (Ref.left Ref.localTime) xs

  it "left (after t), left (repeatedly p): exact event times" $ property $
    forAll genTime $ \t -> forAll genPeriod $ \p ->
    forSamples (oneof [Left <$> genSmallInt, Right <$> arbitrary]) $ \xs ->
      agree (left (after t () &&& repeatedly p ()))
            (Ref.left (Ref.after t () Ref.&&& Ref.repeatedly p ())) (xs :: [(DTime, Either Int Bool)])

  it "left (random network)" $ property $ forAllShrink genNet shrinkE $ \e ->
    forSamples (oneof [Left <$> genD, Right <$> genSmallInt]) $ \xs ->
      agreeWithin 1e-6 (left (toSF e)) (Ref.left (toR e)) xs

  it "identity" $ property $ forSamples genD $ \xs -> agree identity Ref.identity xs

  it "constant" $ property $ forAll genC $ \c -> forSamples genD $ \xs ->
    agree (constant c) (Ref.constant c) xs

  it "localTime" $ property $ forSamples genD $ \xs -> agreeApprox localTime Ref.localTime xs

  it "-->" $ property $ forAll genC $ \c -> forAllShrink genNet shrinkE $ \e -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (c --> toSF e) (c Ref.--> toR e) xs

  it ">--" $ property $ forAll genC $ \c -> forAllShrink genNet shrinkE $ \e -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (c >-- toSF e) (c Ref.>-- toR e) xs

  it "-=>" $ property $ forAll genUFn $ \f -> forAllShrink genNet shrinkE $ \e -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (appF f -=> toSF e) (appF f Ref.-=> toR e) xs

  it ">=-" $ property $ forAll genUFn $ \f -> forAllShrink genNet shrinkE $ \e -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (appF f >=- toSF e) (appF f Ref.>=- toR e) xs
  where
    localTime' = localTime :: SF Double Time
    refLocalTime' = Ref.localTime :: R Double Time

eventSourceSpec :: Spec
eventSourceSpec = describe "event sources" $ do
  it "never" $ property $ forSamples genD $ \xs ->
    agree (never :: SF Double (Event Int)) Ref.never xs

  it "now" $ property $ forAll genSmallInt $ \x -> forSamples genD $ \xs ->
    agree (now x) (Ref.now x) xs

  it "after" $ property $ forAll genTime $ \t -> forAll genSmallInt $ \x -> forSamples genD $ \xs ->
    agree (after t x) (Ref.after t x) xs

  it "after 0 fires at time 0" $ property $ forSamples genD $ \xs ->
    agree (after 0 'x') (Ref.after 0 'x') xs

  it "repeatedly" $ property $ forAll genPeriod $ \p -> forSamples genD $ \xs ->
    agree (repeatedly p 'r') (Ref.repeatedly p 'r') xs

  it "repeatedly with a small period (several periods per step)" $ property $
    forAll (choose (0.01, 0.3)) $ \p -> forSamples genD $ \xs ->
      agree (repeatedly p ()) (Ref.repeatedly p ()) xs

  it "afterEach" $ property $ forAll genSchedule $ \qxs -> forSamples genD $ \xs ->
    agree (afterEach qxs) (Ref.afterEach qxs) xs

  it "afterEachCat" $ property $ forAll genSchedule $ \qxs -> forSamples genD $ \xs ->
    agree (afterEachCat qxs) (Ref.afterEachCat qxs) xs

  it "afterEach / afterEachCat on an infinite schedule" $ property $
    forAll (listOf1 ((,) <$> genPeriod <*> genSmallInt)) $ \cyc -> forSamples genD $ \xs ->
      agree (afterEach (cycle cyc) &&& afterEachCat (cycle cyc))
            (Ref.afterEach (cycle cyc) Ref.&&& Ref.afterEachCat (cycle cyc)) xs

  it "delayEvent" $ property $ forAll genDelay $ \q -> forEvents genSmallInt $ \xs ->
    agree (delayEvent q) (Ref.delayEvent q) xs

  it "delayEventCat" $ property $ forAll genDelay $ \q -> forEvents genSmallInt $ \xs ->
    agree (delayEventCat q) (Ref.delayEventCat q) xs

  it "edge" $ property $ forSamples arbitrary $ \xs -> agree edge Ref.edge xs

  it "iEdge" $ property $ forAll arbitrary $ \b -> forSamples arbitrary $ \xs ->
    agree (iEdge b) (Ref.iEdge b) xs

  it "edgeBy" $ property $ forAll genSmallInt $ \a0 -> forSamples genSmallInt $ \xs ->
    agree (edgeBy rises a0) (Ref.edgeBy rises a0) xs

  it "edgeJust" $ property $ forSamples (oneof [pure Nothing, Just <$> genSmallInt]) $ \xs ->
    agree edgeJust Ref.edgeJust xs

  it "notYet" $ property $ forEvents genSmallInt $ \xs -> agree notYet Ref.notYet xs

  it "once" $ property $ forEvents genSmallInt $ \xs -> agree once Ref.once xs

  it "takeEvents" $ property $ forAll (choose (-1, 6)) $ \n -> forEvents genSmallInt $ \xs ->
    agree (takeEvents n) (Ref.takeEvents n) xs

  it "dropEvents" $ property $ forAll (choose (-1, 6)) $ \n -> forEvents genSmallInt $ \xs ->
    agree (dropEvents n) (Ref.dropEvents n) xs

  it "snap" $ property $ forSamples genSmallInt $ \xs -> agree snap Ref.snap xs

  it "snapAfter" $ property $ forAll genTime $ \t -> forSamples genSmallInt $ \xs ->
    agree (snapAfter t) (Ref.snapAfter t) xs

  it "sample" $ property $ forAll genPeriod $ \p -> forSamples genSmallInt $ \xs ->
    agree (sample p) (Ref.sample p) xs

  it "sampleWindow" $ property $ forAll (choose (1, 5)) $ \w ->
    forAll (oneof [genPeriod, choose (0.02, 0.3)]) $ \p -> forSamples genSmallInt $ \xs ->
      agree (sampleWindow w p) (Ref.sampleWindow w p) xs
  where
    genSchedule = listOf ((,) <$> oneof [pure 0, choose (0, 1.5), (/ 8) . fromIntegral <$> choose (0 :: Int, 12)]
                              <*> genSmallInt)
    genDelay = oneof [pure 0, genPeriod, choose (0.001, 0.1)]
    rises p c = if c > p then Just (c - p) else Nothing

hybridSpec :: Spec
hybridSpec = describe "hold and accumulate" $ do
  it "hold" $ property $ forAll genSmallInt $ \a0 -> forEvents genSmallInt $ \xs ->
    agree (hold a0) (Ref.hold a0) xs

  it "dHold" $ property $ forAll genSmallInt $ \a0 -> forEvents genSmallInt $ \xs ->
    agree (dHold a0) (Ref.dHold a0) xs

  it "trackAndHold" $ property $ forAll genSmallInt $ \a0 -> forSamples genMaybe $ \xs ->
    agree (trackAndHold a0) (Ref.trackAndHold a0) xs

  it "dTrackAndHold" $ property $ forAll genSmallInt $ \a0 -> forSamples genMaybe $ \xs ->
    agree (dTrackAndHold a0) (Ref.dTrackAndHold a0) xs

  it "accum" $ property $ forAll genSmallInt $ \a0 -> forEvents genIFn $ \xs ->
    agree (accum a0) (Ref.accum a0) (funs xs)

  it "accumHold" $ property $ forAll genSmallInt $ \a0 -> forEvents genIFn $ \xs ->
    agree (accumHold a0) (Ref.accumHold a0) (funs xs)

  it "dAccumHold" $ property $ forAll genSmallInt $ \a0 -> forEvents genIFn $ \xs ->
    agree (dAccumHold a0) (Ref.dAccumHold a0) (funs xs)

  it "accumBy" $ property $ forAll genSmallInt $ \b0 -> forEvents genSmallInt $ \xs ->
    agree (accumBy step b0) (Ref.accumBy step b0) xs

  it "accumHoldBy" $ property $ forAll genSmallInt $ \b0 -> forEvents genSmallInt $ \xs ->
    agree (accumHoldBy step b0) (Ref.accumHoldBy step b0) xs

  it "dAccumHoldBy" $ property $ forAll genSmallInt $ \b0 -> forEvents genSmallInt $ \xs ->
    agree (dAccumHoldBy step b0) (Ref.dAccumHoldBy step b0) xs

  it "accumFilter" $ property $ forAll genSmallInt $ \c0 -> forEvents genSmallInt $ \xs ->
    agree (accumFilter filt c0) (Ref.accumFilter filt c0) xs
  where
    genMaybe = frequency [(1, pure Nothing), (2, Just <$> genSmallInt)]
    funs = map (fmap (fmap appI))
    step b a = (b * 3 + a) `mod` 101
    filt c a = let c' = c + a in (c', if even c' then Just (show c') else Nothing)

delaySpec :: Spec
delaySpec = describe "delays" $ do
  it "iPre" $ property $ forAll genSmallInt $ \a0 -> forSamples genSmallInt $ \xs ->
    agree (iPre a0) (Ref.iPre a0) xs

  it "fby" $ property $ forAll genC $ \c -> forAllShrink genNet shrinkE $ \e -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (c `fby` toSF e) (c `Ref.fby` toR e) xs

  it "delay" $ property $ forAll (oneof [pure 0, genPeriod, choose (0.001, 0.2), choose (1, 8)]) $ \q ->
    forAll genSmallInt $ \a0 -> forSamples genSmallInt $ \xs ->
      agree (delay q a0) (Ref.delay q a0) xs

integrationSpec :: Spec
integrationSpec = describe "integration" $ do
  it "integral" $ property $ forSamples genD $ \xs -> agreeApprox integral Ref.integral xs

  it "imIntegral" $ property $ forAll genC $ \y0 -> forSamples genD $ \xs ->
    agreeApprox (imIntegral y0) (Ref.imIntegral y0) xs

  it "trapezoidIntegral" $ property $ forSamples genD $ \xs ->
    agreeApprox trapezoidIntegral Ref.trapezoidIntegral xs

  it "impulseIntegral" $ property $
    forAllShrink (genSamplesT ((,) <$> genD <*> frequency [(3, pure NoEvent), (1, Event <$> genD)]))
                 (shrinkSamples (const [])) $ \xs ->
      agreeApprox impulseIntegral Ref.impulseIntegral xs

  it "count" $ property $ forEvents genSmallInt $ \xs ->
    agree (count :: SF (Event Int) (Event Int)) Ref.count xs

  it "derivative" $ property $ forSamples genD $ \xs -> agreeApprox derivative Ref.derivative xs

loopSpec :: Spec
loopSpec = describe "feedback loops" $ do
  it "loopPre (running sum)" $ property $ forAll genSmallInt $ \c0 -> forSamples genSmallInt $ \xs ->
    agree (loopPre c0 (arr (\(x, s) -> (s, s + x)))) (Ref.loopPre c0 (Ref.arr (\(x, s) -> (s, s + x)))) xs

  it "loopPre (random body)" $ property $ forAll genC $ \c0 -> forAllShrink genNet shrinkE $ \e ->
    forSamples genD $ \xs ->
      agreeWithin 1e-6 (loopPre c0 (arr (uncurry (+)) >>> toSF e >>> arr (\y -> (y, clampD y))))
                       (Ref.loopPre c0 (Ref.arr (uncurry (+)) Ref.>>> toR e Ref.>>> Ref.arr (\y -> (y, clampD y))))
                       xs

  it "loopIntegral (x' = u - x)" $ property $ forSamples genD $ \xs ->
    agreeApprox (loopIntegral (arr (\(u, x) -> (x, u - x))))
                (Ref.loopIntegral (Ref.arr (\(u, x) -> (x, u - x)))) xs

  it "loopIntegral (random body)" $ property $ forAllShrink genNet shrinkE $ \e -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (loopIntegral (arr (\(u, x) -> u - 0.5 * x) >>> toSF e >>> arr (\y -> (y, clampD y))))
                     (Ref.loopIntegral (Ref.arr (\(u, x) -> u - 0.5 * x) Ref.>>> toR e
                                        Ref.>>> Ref.arr (\y -> (y, clampD y))))
                     xs

-- | The primitives documented as not evaluating their current input can
-- close a feedback loop on their own: the loop's fed-back value reaches
-- the body only through them.
decoupledSpec :: Spec
decoupledSpec = describe "decoupled primitives close feedback loops" $ do
  it "dHold" $ property $ forAll genC $ \c0 -> forSamples genD $ \xs ->
    agreeApprox (loop (second (dHold c0) >>> arr (\(x, h) -> (x + h, ev x (0.5 * x + 0.5 * h)))))
                (Ref.loop (Ref.second (Ref.dHold c0) Ref.>>> Ref.arr (\(x, h) -> (x + h, ev x (0.5 * x + 0.5 * h)))))
                xs

  it "dTrackAndHold" $ property $ forAll genC $ \c0 -> forSamples genD $ \xs ->
    agreeApprox (loop (second (dTrackAndHold c0) >>> arr (\(x, h) -> (x - h, mb x (x + 0.5 * h)))))
                (Ref.loop (Ref.second (Ref.dTrackAndHold c0) Ref.>>> Ref.arr (\(x, h) -> (x - h, mb x (x + 0.5 * h)))))
                xs

  it "dAccumHold" $ property $ forAll genC $ \c0 -> forSamples genD $ \xs ->
    agreeApprox (loop (second (dAccumHold c0) >>> arr (\(x, h) -> (h, ev x (\a -> clampD (a + x + 0.1 * h))))))
                (Ref.loop (Ref.second (Ref.dAccumHold c0)
                           Ref.>>> Ref.arr (\(x, h) -> (h, ev x (\a -> clampD (a + x + 0.1 * h))))))
                xs

  it "dAccumHoldBy" $ property $ forAll genC $ \c0 -> forSamples genD $ \xs ->
    agreeApprox (loop (second (dAccumHoldBy (\a d -> clampD (a + d)) c0) >>> arr (\(x, h) -> (h, ev x (x - 0.5 * h)))))
                (Ref.loop (Ref.second (Ref.dAccumHoldBy (\a d -> clampD (a + d)) c0)
                           Ref.>>> Ref.arr (\(x, h) -> (h, ev x (x - 0.5 * h)))))
                xs

  it "delay" $ property $ forAll genPeriod $ \q -> forAll genC $ \c0 -> forSamples genD $ \xs ->
    agreeApprox (loop (second (delay q c0) >>> arr (\(x, d) -> (x + d, clampD (x - 0.5 * d)))))
                (Ref.loop (Ref.second (Ref.delay q c0) Ref.>>> Ref.arr (\(x, d) -> (x + d, clampD (x - 0.5 * d)))))
                xs

  it "delayEventCat" $ property $ forAll genPeriod $ \q -> forSamples genD $ \xs ->
    agreeApprox (loop (second (delayEventCat q >>> arr (fmap sum) >>> hold 0)
                       >>> arr (\(x, h) -> (h, ev x (clampD (x + 0.5 * h))))))
                (Ref.loop (Ref.second (Ref.delayEventCat q Ref.>>> Ref.arr (fmap sum) Ref.>>> Ref.hold 0)
                           Ref.>>> Ref.arr (\(x, h) -> (h, ev x (clampD (x + 0.5 * h))))))
                xs

  it "delayEvent: a recurring event from now () fed back (Yampa's idiom)" $ property $
    forAll genPeriod $ \q -> forSamples genD $ \xs ->
      agree (now () >>> loop (arr (uncurry orElse) >>> delayEvent q >>> arr (\e -> (e, e))))
            (Ref.now () Ref.>>> Ref.loop (Ref.arr (uncurry orElse) Ref.>>> Ref.delayEvent q
                                          Ref.>>> Ref.arr (\e -> (e, e))))
            xs

  it "fby" $ property $ forAll genC $ \c0 -> forSamples genD $ \xs ->
    agreeApprox (loop (second (c0 `fby` arr (* 0.5)) >>> arr (\(x, d) -> (x + d, clampD (x - d)))))
                (Ref.loop (Ref.second (c0 `Ref.fby` Ref.arr (* 0.5)) Ref.>>> Ref.arr (\(x, d) -> (x + d, clampD (x - d)))))
                xs
  where
    ev :: Double -> b -> Event b
    ev x b = if x > 0 then Event b else NoEvent
    orElse :: Event a -> Event a -> Event a
    orElse NoEvent e = e
    orElse e       _ = e
    mb :: Double -> b -> Maybe b
    mb x b = if x > 0 then Just b else Nothing

switchSpec :: Spec
switchSpec = describe "switches" $ do
  it "switch (on input events)" $ property $ forCands $ \e0 cs -> forInputEvents $ \xs ->
    agreeWithin 1e-6 (switch (first (toSF e0)) (\i -> arr fst >>> toSF (pick cs i)))
                     (Ref.switch (Ref.first (toR e0)) (\i -> Ref.arr fst Ref.>>> toR (pick cs i))) xs

  it "switch (recurring, through a chain of switches)" $ property $ forCands $ \e0 cs -> forInputEvents $ \xs ->
    let sw e = switch (first (toSF e) >>> second notYet) (sw . pick cs)
        rw e = Ref.switch (Ref.first (toR e) Ref.>>> Ref.second Ref.notYet) (rw . pick cs)
    in agreeWithin 1e-6 (switch (first (toSF e0)) (sw . pick cs))
                        (Ref.switch (Ref.first (toR e0)) (rw . pick cs)) xs

  it "switch (time-triggered)" $ property $ forCands $ \e0 cs -> forAll genTime $ \t -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (switch (toSF e0 &&& after t ()) (\() -> toSF (pick cs 0)))
                     (Ref.switch (toR e0 Ref.&&& Ref.after t ()) (\() -> toR (pick cs 0))) xs

  it "dSwitch (on input events)" $ property $ forCands $ \e0 cs -> forInputEvents $ \xs ->
    agreeWithin 1e-6 (dSwitch (first (toSF e0)) (\i -> arr fst >>> toSF (pick cs i)))
                     (Ref.dSwitch (Ref.first (toR e0)) (\i -> Ref.arr fst Ref.>>> toR (pick cs i))) xs

  it "dSwitch (recurring)" $ property $ forCands $ \e0 cs -> forInputEvents $ \xs ->
    let sw e = dSwitch (first (toSF e) >>> second notYet) (sw . pick cs)
        rw e = Ref.dSwitch (Ref.first (toR e) Ref.>>> Ref.second Ref.notYet) (rw . pick cs)
    in agreeWithin 1e-6 (dSwitch (first (toSF e0)) (sw . pick cs))
                        (Ref.dSwitch (Ref.first (toR e0)) (rw . pick cs)) xs

  it "rSwitch" $ property $ forCands $ \e0 cs -> forInputEvents $ \xs ->
    agreeWithin 1e-6 (arr (\(x, ev) -> (x, fmap (toSF . pick cs) ev)) >>> rSwitch (toSF e0))
                     (Ref.arr (\(x, ev) -> (x, fmap (toR . pick cs) ev)) Ref.>>> Ref.rSwitch (toR e0)) xs

  it "drSwitch" $ property $ forCands $ \e0 cs -> forInputEvents $ \xs ->
    agreeWithin 1e-6 (arr (\(x, ev) -> (x, fmap (toSF . pick cs) ev)) >>> drSwitch (toSF e0))
                     (Ref.arr (\(x, ev) -> (x, fmap (toR . pick cs) ev)) Ref.>>> Ref.drSwitch (toR e0)) xs

  it "kSwitch (recurring, continuations built from the frozen SF)" $ property $
    forCands $ \e0 cs -> forInputEvents $ \xs ->
      agreeWithin 1e-6 (kswL kSwitch True cs (arr fst >>> toSF e0))
                       (kswR Ref.kSwitch True cs (Ref.arr fst Ref.>>> toR e0)) xs

  it "dkSwitch (recurring, continuations built from the frozen SF)" $ property $
    forCands $ \e0 cs -> forInputEvents $ \xs ->
      agreeWithin 1e-6 (kswL dkSwitch True cs (arr fst >>> toSF e0))
                       (kswR Ref.dkSwitch True cs (Ref.arr fst Ref.>>> toR e0)) xs

  it "kSwitch / dkSwitch (detector on the output)" $ property $
    forCands $ \e0 cs -> forAll genC $ \c -> forAll arbitrary $ \d -> forSamples genD $ \xs ->
      let detL = arr (\(_, y) -> y > c) >>> edge
          detR = Ref.arr (\(_, y) -> y > c) Ref.>>> Ref.edge
      in agreeWithin 1e-6
           ((if d then dkSwitch else kSwitch) (toSF e0) detL
              (\fr () -> (fr &&& toSF (pick cs 0)) >>> arr (uncurry (-))))
           ((if d then Ref.dkSwitch else Ref.kSwitch) (toR e0) detR
              (\fr () -> (fr Ref.&&& toR (pick cs 0)) Ref.>>> Ref.arr (uncurry (-))))
           xs

  -- The delayed switches are decoupled: their event may depend, through a
  -- loop, on their own output at the same instant.
  it "dSwitch in a loop, event computed from its own output at the same instant" $ property $
    forCands $ \e0 cs -> forAll genC $ \c -> forSamples genD $ \xs ->
      agreeWithin 1e-6
        (loop (arr (\(x, y) -> (x, if y > c then Event () else NoEvent))
               >>> dSwitch (first (toSF e0)) (\() -> arr fst >>> toSF (pick cs 0))
               >>> arr (\y -> (y, y))))
        (Ref.loop (Ref.arr (\(x, y) -> (x, if y > c then Event () else NoEvent))
                   Ref.>>> Ref.dSwitch (Ref.first (toR e0)) (\() -> Ref.arr fst Ref.>>> toR (pick cs 0))
                   Ref.>>> Ref.arr (\y -> (y, y))))
        xs

  it "drSwitch in a loop, event computed from its own output at the same instant" $ property $
    forCands $ \e0 cs -> forAll genC $ \c -> forSamples genD $ \xs ->
      agreeWithin 1e-6
        (loop (arr (\(x, y) -> (x, if y > c then Event (toSF (pick cs (floor y))) else NoEvent))
               >>> drSwitch (toSF e0) >>> arr (\y -> (y, y))))
        (Ref.loop (Ref.arr (\(x, y) -> (x, if y > c then Event (toR (pick cs (floor y))) else NoEvent))
                   Ref.>>> Ref.drSwitch (toR e0) Ref.>>> Ref.arr (\y -> (y, y))))
        xs

  it "dkSwitch in a loop, detector reading its own output at the same instant" $ property $
    forCands $ \e0 cs -> forAll genC $ \c -> forSamples genD $ \xs ->
      agreeWithin 1e-6
        (loop (dkSwitch (arr fst >>> toSF e0) (arr (\((_, y), _) -> y > c) >>> edge)
                        (\fr () -> (fr &&& (arr fst >>> toSF (pick cs 0))) >>> arr (uncurry (+)))
               >>> arr (\y -> (y, y))))
        (Ref.loop (Ref.dkSwitch (Ref.arr fst Ref.>>> toR e0) (Ref.arr (\((_, y), _) -> y > c) Ref.>>> Ref.edge)
                                (\fr () -> (fr Ref.&&& (Ref.arr fst Ref.>>> toR (pick cs 0)))
                                           Ref.>>> Ref.arr (uncurry (+)))
                   Ref.>>> Ref.arr (\y -> (y, y))))
        xs
  where
    forCands :: Testable p => (E -> [E] -> p) -> Property
    forCands k = forAllShrink ((,) <$> genNet <*> genCands) shrinkPair (uncurry k)
    shrinkPair (e, cs) = [(e', cs) | e' <- shrinkE e]
    -- k-switches that switch again at every later input event; the
    -- continuation chosen by the event's value.
    kswL ks isFirst cs s =
      ks s (arr (snd . fst) >>> (if isFirst then identity else notYet))
         (\fr i -> kswL ks False cs (contL cs i fr))
    kswR ks isFirst cs s =
      ks s (Ref.arr (snd . fst) Ref.>>> (if isFirst then Ref.identity else Ref.notYet))
         (\fr i -> kswR ks False cs (contR cs i fr))
    -- (4: run a candidate until the next input event, then resume the
    -- frozen signal function: it replays its pending step only then.)
    contL cs i fr = case i `mod` 5 of
      0 -> fr
      1 -> (fr &&& (arr fst >>> toSF (pick cs i))) >>> arr (uncurry (+))
      2 -> arr fst >>> toSF (pick cs i)
      3 -> fr >>> toSF (pick cs i)
      _ -> switch ((arr fst >>> toSF (pick cs i)) &&& (arr snd >>> notYet)) (const fr)
    contR cs i fr = case i `mod` 5 of
      0 -> fr
      1 -> (fr Ref.&&& (Ref.arr fst Ref.>>> toR (pick cs i))) Ref.>>> Ref.arr (uncurry (+))
      2 -> Ref.arr fst Ref.>>> toR (pick cs i)
      3 -> fr Ref.>>> toR (pick cs i)
      _ -> Ref.switch ((Ref.arr fst Ref.>>> toR (pick cs i)) Ref.&&& (Ref.arr snd Ref.>>> Ref.notYet))
                      (const fr)

forInputEvents :: Testable p => ([(DTime, (Double, Event Int))] -> p) -> Property
forInputEvents = forAllShrink (genWithEvents (choose (0, 20))) (shrinkSamples shrinkIn)
  where
    shrinkIn (x, Event _) = [(x, NoEvent)]
    shrinkIn _            = []

parallelSpec :: Spec
parallelSpec = describe "parallel composition and collection switches" $ do
  it "parB" $ property $ forMembers $ \es -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (parB (map toSF es)) (Ref.parB (map toR es)) xs

  it "parZ" $ property $ forMembers $ \es -> forAll (choose (0, 2)) $ \extra ->
    forSamples (vectorOf (length es + extra) genD) $ \xs ->
      agreeWithin 1e-6 (parZ (map toSF es)) (Ref.parZ (map toR es)) xs

  it "pSwitchB (on input events, recurring through frozen collections)" $ property $
    forMembers $ \es -> forAll genCands $ \cs -> forInputEvents $ \xs ->
      agreeWithin 1e-6 (pswL pSwitchB True cs (map memberL es)) (pswR Ref.pSwitchB True cs (map memberR es)) xs

  it "dpSwitchB (on input events, recurring through frozen collections)" $ property $
    forMembers $ \es -> forAll genCands $ \cs -> forInputEvents $ \xs ->
      agreeWithin 1e-6 (pswL dpSwitchB True cs (map memberL es)) (pswR Ref.dpSwitchB True cs (map memberR es)) xs

  it "rpSwitchB" $ property $ forMembers $ \es -> forAll genCands $ \cs ->
    forAllShrink (genWithEvents genColOp) (shrinkSamples (const [])) $ \xs ->
      agreeWithin 1e-6
        (arr (\(x, ev) -> (x, fmap (appColOp (toSF . pick cs) laterL) ev)) >>> rpSwitchB (map toSF es))
        (Ref.arr (\(x, ev) -> (x, fmap (appColOp (toR . pick cs) laterR) ev)) Ref.>>> Ref.rpSwitchB (map toR es))
        xs

  it "drpSwitchB" $ property $ forMembers $ \es -> forAll genCands $ \cs ->
    forAllShrink (genWithEvents genColOp) (shrinkSamples (const [])) $ \xs ->
      agreeWithin 1e-6
        (arr (\(x, ev) -> (x, fmap (appColOp (toSF . pick cs) laterL) ev)) >>> drpSwitchB (map toSF es))
        (Ref.arr (\(x, ev) -> (x, fmap (appColOp (toR . pick cs) laterR) ev)) Ref.>>> Ref.drpSwitchB (map toR es))
        xs

  it "dpSwitchB in a loop, detector reading the collection's output through the loop" $ property $
    forMembers $ \es -> forAll genCands $ \cs -> forAll genC $ \c -> forSamples genD $ \xs ->
      agreeWithin 1e-6
        (loop (dpSwitchB (map memberL es) (arr (\((_, s), _) -> s > c) >>> iEdge False)
                         (\frozen () -> parB (memberL (pick cs 0) : reverse frozen))
               >>> arr (\ys -> (ys, sum ys))))
        (Ref.loop (Ref.dpSwitchB (map memberR es) (Ref.arr (\((_, s), _) -> s > c) Ref.>>> Ref.iEdge False)
                                 (\frozen () -> Ref.parB (memberR (pick cs 0) : reverse frozen))
                   Ref.>>> Ref.arr (\ys -> (ys, sum ys))))
        xs

  it "drpSwitchB in a loop, event computed from its own output at the same instant" $ property $
    forMembers $ \es -> forAll genCands $ \cs -> forAll genC $ \c -> forAll genColOp $ \op ->
      forSamples genD $ \xs ->
        agreeWithin 1e-6
          (loop (arr (\(x, s) -> (x, if s > c then Event (appColOp (toSF . pick cs) laterL op) else NoEvent))
                 >>> drpSwitchB (map toSF es) >>> arr (\ys -> (ys, sum ys))))
          (Ref.loop (Ref.arr (\(x, s) -> (x, if s > c then Event (appColOp (toR . pick cs) laterR op) else NoEvent))
                     Ref.>>> Ref.drpSwitchB (map toR es) Ref.>>> Ref.arr (\ys -> (ys, sum ys))))
          xs
  where
    forMembers :: Testable p => ([E] -> p) -> Property
    forMembers = forAllShrink (choose (0, 4) >>= \k -> vectorOf k (choose (1, 6) >>= genE))
                              (shrinkList shrinkE)
    memberL e = arr fst >>> toSF e
    memberR e = Ref.arr fst Ref.>>> toR e
    pswL ps isFirst cs sfs =
      ps sfs (arr (snd . fst) >>> (if isFirst then identity else notYet))
         (\frozen i -> colL ps cs i frozen)
    pswR ps isFirst cs sfs =
      ps sfs (Ref.arr (snd . fst) Ref.>>> (if isFirst then Ref.identity else Ref.notYet))
         (\frozen i -> colR ps cs i frozen)
    colL ps cs i frozen = case i `mod` 5 of
      0 -> parB (reverse frozen)
      1 -> parB (memberL (pick cs i) : frozen)
      2 -> pswL ps False cs (drop 1 frozen)
      3 -> pswL ps False cs (memberL (pick cs i) : frozen)
      _ -> pswL ps False cs (map (laterL (fromIntegral i / 8)) frozen)
    colR ps cs i frozen = case i `mod` 5 of
      0 -> Ref.parB (reverse frozen)
      1 -> Ref.parB (memberR (pick cs i) : frozen)
      2 -> pswR ps False cs (drop 1 frozen)
      3 -> pswR ps False cs (memberR (pick cs i) : frozen)
      _ -> pswR ps False cs (map (laterR (fromIntegral i / 8)) frozen)

networkSpec :: Spec
networkSpec = describe "random networks" $ modifyMaxSuccess (const 600) $ do
  it "agree with the reference" $ property $ forAllShrink genNet shrinkE $ \e -> forSamples genD $ \xs ->
    agreeWithin 1e-6 (toSF e) (toR e) xs

  it "agree with the reference on dyadic time steps (exact time ties)" $ property $
    forAllShrink genNet shrinkE $ \e ->
      forAllShrink (choose (1, 40) >>= \n -> vectorOf n ((,) <$> elements [0.125, 0.25, 0.5] <*> genD))
                   (shrinkSamples (const [])) $ \xs ->
        agreeWithin 1e-6 (toSF e) (toR e) xs

  it "agree with the reference when run twice on the same SF value" $ property $
    forAllShrink genNet shrinkE $ \e -> forSamples genD $ \xs ->
      let sf = toSF e
          r  = toR e
      in agreeWithin 1e-6 sf r xs .&&. agreeWithin 1e-6 sf r (reverse xs)

------------------------------------------------------------------------------
-- Concrete examples: the examples in the library's documentation. Both the
-- library and the reference must reproduce them.

-- | Run both on an 'embed'-style input ('Nothing' repeats the previous
-- input) and compare with the expected outputs.
bothGive :: Close b => SF a b -> R a b -> (a, [(DTime, Maybe a)]) -> [b] -> Expectation
bothGive sf r input@(a0, rest) expected = do
  check "library" (embed sf input)
  check "reference" (runR r ((0, a0) : expand a0 rest))
  where
    expand _    []                = []
    expand prev ((dt, ma) : more) = let a = maybe prev id ma in (dt, a) : expand a more
    check who ys
      | closeWith 1e-9 ys expected = pure ()
      | otherwise = expectationFailure (who ++ ":\n expected " ++ show expected ++ "\n but got  " ++ show ys)

-- | A constant time step: the first input at time 0, one more every dt.
every :: DTime -> [a] -> (a, [(DTime, Maybe a)])
every _  []       = error "every: no samples"
every dt (a : as) = (a, [(dt, Just x) | x <- as])

examplesSpec :: Spec
examplesSpec = describe "documented examples" $ do
  describe "from the library's documentation" $ do
    it "localTime" $
      bothGive localTime Ref.localTime ((), [(0.5, Nothing), (0.25, Nothing)]) [0, 0.5, 0.75]
    it "-->" $
      bothGive (0 --> identity) (0 Ref.--> Ref.identity) (5 :: Int, [(1, Just 6), (1, Just 7)]) [0, 6, 7]
    it "iPre" $
      bothGive (iPre 0) (Ref.iPre 0) (1 :: Int, [(1, Just 2), (1, Just 3)]) [0, 1, 2]
    it "delay" $
      bothGive (delay 1 0) (Ref.delay 1 0) (1 :: Int, [(0.5, Just 2), (0.5, Just 3), (0.5, Just 4)]) [0, 0, 1, 2]
    it "now" $
      bothGive (now 'x') (Ref.now 'x') ((), [(1, Nothing)]) [Event 'x', NoEvent]
    it "after" $
      bothGive (after 1.0 ()) (Ref.after 1.0 ()) ((), replicate 3 (0.5, Nothing))
              [NoEvent, NoEvent, Event (), NoEvent]
    it "afterEachCat" $
      bothGive (afterEachCat [(0.5, 'a'), (0.1, 'b'), (1, 'c')]) (Ref.afterEachCat [(0.5, 'a'), (0.1, 'b'), (1, 'c')])
              ((), replicate 3 (1, Nothing)) [NoEvent, Event "ab", Event "c", NoEvent]
    it "edge" $
      bothGive edge Ref.edge (True, [(1, Just False), (1, Just True), (1, Nothing)])
              [NoEvent, NoEvent, Event (), NoEvent]
    it "hold" $
      bothGive (hold 0) (Ref.hold 0) (NoEvent, [(1, Just (Event (5 :: Int))), (1, Just NoEvent)]) [0, 5, 5]
    it "accum" $
      bothGive (accum 0) (Ref.accum 0) (Event (+ 1), [(1, Just NoEvent), (1, Just (Event (* 10)))])
              [Event (1 :: Int), NoEvent, Event 10]
    it "integral (and embed's Nothing)" $ do
      bothGive integral Ref.integral (1, [(0.5, Just 2), (0.5, Just 3)]) [0, 0.5, 1.5]
      bothGive integral Ref.integral (1, [(0.5, Just 2), (0.5, Nothing)]) [0, 0.5, 1.5]
    it "imIntegral" $
      bothGive (imIntegral 10) (Ref.imIntegral 10) (1, [(0.5, Just 2), (0.5, Just 3)]) [10, 11, 12.5]
    it "derivative" $
      bothGive derivative Ref.derivative (1, [(0.5, Just 2), (0.5, Just 2)]) [0, 2, 0]
    it "loopPre (a counter)" $
      bothGive (loopPre 0 (arr (\(_, n) -> (n, n + 1)))) (Ref.loopPre 0 (Ref.arr (\(_, n) -> (n, n + 1))))
              ((), replicate 4 (1, Nothing)) [0, 1, 2, 3, 4 :: Int]
    it "parB" $
      bothGive (parB [constant 1, localTime]) (Ref.parB [Ref.constant 1, Ref.localTime])
              ((), [(0.5, Nothing)]) [[1, 0], [1, 0.5]]
    it "switch" $
      bothGive (switch (constant 1 &&& after 1 ()) (\() -> localTime))
              (Ref.switch (Ref.constant 1 Ref.&&& Ref.after 1 ()) (\() -> Ref.localTime))
              ((), replicate 3 (0.5, Nothing)) [1, 1, 0, 0.5]
    it "left localTime on L, L, R, R, L (steps of 1)" $
      bothGive (left localTime) (Ref.left Ref.localTime)
              (every 1 [Left (), Left (), Right 'a', Right 'b', Left ()])
              [Left 0, Left 1, Right 'a', Right 'b', Left 2]
