{-# LANGUAGE UnboxedTuples #-}
-- | Shared by the specs of "AFRP.Internal.Chain", its modules and
-- "AFRP.Internal.Node.Fuse": random chains of integrals, delays and
-- functions at 'Double', and the reference they are checked against, the
-- same stages stepped one by one as opaque nodes, compared bit for bit.
module AFRP.ChainFixture
  ( -- * Random chains
    Stage (..)
  , stageSF
  , chainOf
    -- * The reference: the stages stepped one by one
  , opaque
  , opaqueChainOf
    -- * Comparing and running
  , sameBits
  , runSamples'
  , inputs
  ) where

import           Control.Arrow    (arr, (>>>))
import           GHC.Float        (castDoubleToWord64)
import           Test.QuickCheck  (Arbitrary (..), choose, elements, frequency)

import           AFRP.Basic       ((-->))
import           AFRP.Delay       (iPre)
import           AFRP.Integration (integral)
import           AFRP.Internal.SF (DTime, Node (..), SF (..), stepN, stepSF)

-- | A stage of a random chain.
data Stage = SIntegral | SPre Double | SArr Int | SInitIntegral Double
  deriving Show

instance Arbitrary Stage where
  arbitrary = frequency
    [ (4, pure SIntegral)
    , (2, SPre <$> elements [0, -1, 2.5])
    , (3, SArr <$> choose (0, length funs - 1))
    -- an integral whose first output is replaced ('-->'): after its first
    -- step it is an integral node whose sum is not what it output
    , (1, SInitIntegral <$> elements [5, -3]) ]
  shrink (SArr _) = [SIntegral]
  shrink (SPre _) = [SIntegral]
  shrink SIntegral = []
  shrink (SInitIntegral _) = [SIntegral]

-- The functions a chain may hold, total and cheap.
funs :: [Double -> Double]
funs = [(* 2), (+ 1), negate, sin, \x -> x * x - 0.5]

stageSF :: Stage -> SF Double Double
stageSF SIntegral = integral
stageSF (SPre c)  = iPre c
stageSF (SArr i)  = arr (funs !! i)
stageSF (SInitIntegral c) = c --> integral

-- | A signal function that behaves as its argument but is one opaque node
-- at every step, so that nothing can be fused with it: the stages stepped
-- one by one, as before chains existed.
opaque :: SF a b -> SF a b
opaque (SF n0) = SF (go n0)
  where
    go n = NStep (\dt a -> case stepN n dt a of
      (# n', b #) -> case go n' of m -> m `seq` (# m, b #))

-- | Bit-for-bit equality of two runs.
sameBits :: [Double] -> [Double] -> Bool
sameBits xs ys = length xs == length ys
  && and (zipWith (\x y -> castDoubleToWord64 x == castDoubleToWord64 y) xs ys)

-- | A chain built at run time ('foldr1'), as a user's code builds one.
chainOf :: [Stage] -> SF Double Double
chainOf = foldr1 (>>>) . map stageSF

opaqueChainOf :: [Stage] -> SF Double Double
opaqueChainOf = foldr1 (>>>) . map (opaque . stageSF)

-- | The outputs of a signal function already started, on (dt, input) pairs.
runSamples' :: SF Double Double -> [(DTime, Double)] -> [Double]
runSamples' _ [] = []
runSamples' sf ((dt, x) : rest) = case stepSF sf dt x of
  (sf', y) -> y : runSamples' sf' rest

inputs :: [Double]
inputs = [1, -1, 2, 0, 3, -2, 5, 1, -4, 2, 6, 0]
