-- |
-- Module      : AFRP.Internal.Chain.Regroup
-- Description : A chain's stages regrouped after its first and second
--               steps: integrals and delays in series made runs.
--
-- Internal, part of "AFRP.Internal.Chain": its stepper regroups the
-- integrals behind each first-step stage ('consInt'), and the chain node
-- ("AFRP.Internal.Node.Fuse") settles the delays at the chain's second
-- step ('settleL').
--
-- = After the first step
--
-- An integral fed by an integral keeps the previous input its node held
-- for the chain's first step only ('AFRP.Internal.Chain.Stage.IIntS',
-- 'AFRP.Internal.Chain.Stage.IIntFS'); after that step it is grouped
-- with the integrals in series behind it, three or more as one run
-- ("AFRP.Internal.Chain.Sums"), fewer as cells of their own.
--
-- = Delays among the integrals
--
-- A delay fed by an integral ('AFRP.Internal.Chain.Stage.IPre') stores
-- the integral's sum as its input, evaluated, and outputs it at the next
-- step: its output at step @n@ is the integral's sum at step @n-1@, which
-- is the @old@ the chain's stepper is given at step @n@. So, like an
-- integral fed by an integral, it need not store its input; what the
-- stages behind it need is its output at the last step, the value they
-- stored as their input. From the chain's second step on, such a delay
-- is a stage that keeps its output at the last step
-- ('AFRP.Internal.Chain.Stage.IPreI'; 'FPre' in a run): at each step its
-- output is its predecessor's output at the last step, and the stages
-- behind it see it as they see an integral, @old@ being its last output
-- and @new@ its output now. In a run, where each entry holds its stage's
-- output at the last step, a delay's new entry is its predecessor's old
-- one. The change is made once, at the chain's second step ('settleL'),
-- because only then is every delay's output one the chain itself stored,
-- evaluated: at the first step a delay outputs the value its node held,
-- which may be unevaluated (an initial value, or an output of a stage
-- before the chain formed), and making it an entry would evaluate it one
-- step earlier than the integral behind it would. A delay behind a delay
-- stays as it is for the same reason. The same values in the same order:
-- the same bits, nothing evaluated earlier.
module AFRP.Internal.Chain.Regroup
  ( consInt
  , hasDelayI
  , settleL
  ) where

import           AFRP.Internal.Chain.Stage
import           AFRP.Internal.Chain.Sums (Funs (..), kindsList, packKinds, sumsFromList, sumsList)

-- | An integral (its running sum, and the function before it, if any) in
-- front of the stages that follow it, after the chain's first step:
-- grouped with the integrals in series behind it (@groupEntries@, as
-- 'settleL' groups them; the delays wait for the second step), three or
-- more as one run, fewer as cells of their own. (A run starts at three
-- integrals: for two, the array and the run's cell allocate more than the
-- two cells they replace.)
consInt :: Maybe (Double -> Double) -> Double -> AfterI -> AfterI
consInt mf acc c = case entriesI Nothing c of
  (es, rest) -> groupEntries (maybe (EInt acc) (\f -> EIntF f acc) mf : es) rest

-- | Whether a chain has a delay fed by an integral ('IPre'), which
-- 'settleL' makes a stage of its own kind at the chain's second step.
hasDelayI :: AfterL -> Bool
hasDelayI c = case c of
  LEnd          -> False
  LInt _ _ r    -> afterI r
  LIntF _ _ _ r -> afterI r
  LPre _ r      -> hasDelayI r
  where
    afterI x = case x of
      IEnd           -> False
      IPre _ _       -> True
      IInt _ r       -> afterI r
      IIntF _ _ r    -> afterI r
      IIntS _ _ r    -> afterI r
      IIntFS _ _ _ r -> afterI r
      IRun _ r       -> afterI r
      IRunF _ _ r    -> afterI r
      IPreI _ r      -> afterI r

-- | @settleL pre post@, where @post@ is the successor of @pre@ at the
-- chain's second step: @post@ with each delay fed by an integral made an
-- 'IPreI' (its output at this step is what @pre@ held), the stages it
-- feeds (which stored that output as their input) made stages fed by it
-- ('IInt', 'IIntF', 'IPre'), and the integrals and delays in series
-- regrouped, three or more as one run ('IRun', 'IRunF'). The same
-- stages, so the same steps (see "Delays among the integrals").
settleL :: AfterL -> AfterL -> AfterL
settleL pre post = case (pre, post) of
  (LInt _ _ p, LInt acc prev q)       -> LInt acc prev (settleI p q)
  (LIntF _ _ _ p, LIntF f acc prev q) -> LIntF f acc prev (settleI p q)
  (LPre _ p, LPre v q)                -> LPre v (settleL p q)
  _                                   -> post

-- The stages after an integral, settled.
settleI :: AfterI -> AfterI -> AfterI
settleI pre post = case entriesI (Just pre) post of
  (es, rest) -> groupEntries es rest

-- A stage of a run, as 'settleL' collects them: its output at the last
-- step and what it is.
data Entry = EInt !Double | EIntF !(Double -> Double) !Double | EPre !Double

-- The longest series of integrals and delays at the head of the stages
-- after an integral (before and after this step), and what follows it.
entriesI :: Maybe AfterI -> AfterI -> ([Entry], AfterI)
entriesI mpre post = case post of
  IInt acc q    -> more [EInt acc] q
  IIntF f acc q -> more [EIntF f acc] q
  IRun s q      -> more (map EInt (sumsList s)) q
  IRunF s ks q  -> more (funEntries (sumsList s) (kindsList ks)) q
  IPreI out q   -> more [EPre out] q
  -- given the state before the chain's second step: the delay's output
  -- at this step is what it held before it, which the chain's first step
  -- stored there, evaluated
  IPre _ q | Just (IPre out p) <- mpre -> withEntries [EPre out] (entriesL p q)
  _             -> ([], post)
  where
    more es q = withEntries es (entriesI (mpre >>= restOf) q)
    restOf pre = case pre of
      IInt _ p    -> Just p
      IIntF _ _ p -> Just p
      IRun _ p    -> Just p
      IRunF _ _ p -> Just p
      IPreI _ p   -> Just p
      _           -> Nothing
    funEntries ss fs = case (ss, fs) of
      (x : xs, FNone r)   -> EInt x : funEntries xs r
      (x : xs, FSome f r) -> EIntF f x : funEntries xs r
      (x : xs, FPre r)    -> EPre x : funEntries xs r
      _                   -> []

-- The same for the stages after a delay that 'settleL' makes an 'IPreI':
-- each held that delay's output at this step as its input, which the
-- 'IPreI' gives them as its last output.
entriesL :: AfterL -> AfterL -> ([Entry], AfterI)
entriesL pre post = case (pre, post) of
  (LInt _ _ p, LInt acc _ q)       -> withEntries [EInt acc] (entriesI (Just p) q)
  (LIntF _ _ _ p, LIntF f acc _ q) -> withEntries [EIntF f acc] (entriesI (Just p) q)
  _                                -> ([], fedByDelay post)
  where
    -- (a delay behind a delay keeps its value: what it output at this
    -- step, which it would report as its last output, may still be
    -- unevaluated)
    fedByDelay c = case c of
      LEnd             -> IEnd
      LInt acc _ q     -> IInt acc q
      LIntF f acc _ q  -> IIntF f acc q
      LPre v q         -> IPre v q

withEntries :: [Entry] -> ([Entry], AfterI) -> ([Entry], AfterI)
withEntries es (es', rest) = (es ++ es', rest)

-- Stages in series: three or more as one run, fewer as cells.
groupEntries :: [Entry] -> AfterI -> AfterI
groupEntries es rest = case es of
  (_ : _ : _ : _)
    | all plain es -> IRun (sumsFromList (map out es)) rest
    | otherwise    -> IRunF (sumsFromList (map out es)) (packKinds (foldr kind FNil es)) rest
  _                -> foldr cell rest es
  where
    plain e = case e of
      EInt _ -> True
      _      -> False
    out e = case e of
      EInt x    -> x
      EIntF _ x -> x
      EPre x    -> x
    kind e r = case e of
      EInt _    -> FNone r
      EIntF f _ -> FSome f r
      EPre _    -> FPre r
    cell e r = case e of
      EInt x    -> IInt x r
      EIntF f x -> IIntF f x r
      EPre x    -> IPreI x r
