{-# LANGUAGE BangPatterns #-}
{-# LANGUAGE Arrows       #-}
-- |
-- The benchmark networks, each an @SF Double Double@ run with 'embed' at
-- dt = 0.01 on the input samples 0, 1, 2, ..., and each with a hand-written
-- strict loop that computes the same numbers. The test suite checks that
-- every network agrees with its baseline; the benchmarks time both.
module Networks
  ( Network (..)
  , networks
  , dt
  , runNetwork
  , sumNetwork
  ) where

import           Data.List (foldl', intersperse)

import           AFRP

-- | A named network and its baseline: the baseline maps a sample count to
-- the list of outputs it computes.
data Network = Network
  { nwName     :: String
  , nwSF       :: SF Double Double
  , nwBaseline :: Int -> [Double]
  }

-- | The time step of every run.
dt :: DTime
dt = 0.01

-- | The outputs of a network on @n@ samples (inputs 0 .. n-1).
runNetwork :: SF Double Double -> Int -> [Double]
runNetwork sf n = embed sf (0, [(dt, Just (fromIntegral i)) | i <- [1 .. n - 1]])

-- | The strict sum of a network's outputs on @n@ samples.
sumNetwork :: SF Double Double -> Int -> Double
sumNetwork sf n = foldl' (+) 0 (runNetwork sf n)

networks :: [Network]
networks =
  [ Network "a: 100 x arr (+1)"            chain100      (\n -> [fromIntegral i + 100 | i <- [0 .. n - 1]])
  , Network "a': one arr of the composition" chainFused  (\n -> [fromIntegral i + 100 | i <- [0 .. n - 1]])
  , Network "as: (a) written out in the source" chainSource (\n -> [fromIntegral i + 100 | i <- [0 .. n - 1]])
  , Network "b: 10 integrals in series"    integrals10   baseIntegrals10
  , Network "c: 100 integrals, &&&, summed" fan100       baseFan100
  , Network "d: rSwitch every 10 samples"  rswitch10     baseRSwitch10
  , Network "d': recursive dSwitch on edge" dswitchRec   baseDSwitchRec
  , Network "e: parB of 1000 integrals"    parB1000      baseParB1000
  , Network "f: edge and accumHold count"  upCrossings   baseUpCrossings
  , Network "g: loop with an iPre counter" loopCounter   (\n -> map fromIntegral [0 .. n - 1])
  , Network "h: the notes' odometry"       odometry      baseOdometry
  -- issue 19: variants a user would write of (b) and (h), and the shapes
  -- of ../shared/bench/Throughput.hs that differ from the ones above
  , Network "bs: (b) written out in the source" integrals10Source baseIntegrals10
  , Network "bi: (b) with arr (* 2) between, built at run time" integralsTimes2 (baseStages stagesTimes2)
  , Network "bis: (bi) written out in the source" integralsTimes2Source (baseStages stagesTimes2)
  , Network "bm: integral, iPre and arr in series, built at run time" mixedChain (baseStages stagesMixed)
  , Network "bms: (bm) written out in the source" mixedChainSource (baseStages stagesMixed)
  , Network "hp: (h) in proc notation"     odometryProc  baseOdometry
  , Network "ht: Throughput.hs's odometry" odometryTP    baseOdometryTP
  , Network "td': Throughput.hs's recursive dSwitch" dswitchTP baseDSwitchTP
  , Network "tg: Throughput.hs's loop counter" loopCounterTP (\n -> [fromIntegral i + fromIntegral (i + 1) | i <- [0 .. n - 1 :: Int]])
  ]

------------------------------------------------------------------------------
-- (a) a chain of pure functions

chain100 :: SF Double Double
chain100 = foldr1 (>>>) (replicate 100 (arr (+ 1)))

chainFused :: SF Double Double
chainFused = arr (foldr (.) id (replicate 100 (+ 1)))

-- (a) as a user writes it: the hundred stages in the source, where the
-- library's rewrite rules fuse them at compile time. (a) itself builds the
-- chain at run time, where they are fused by 'compN' into a composition of
-- unknown functions.
chainSource :: SF Double Double
chainSource =
      arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)
  >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1) >>> arr (+ 1)

------------------------------------------------------------------------------
-- (b) ten integrals in series

integrals10 :: SF Double Double
integrals10 = foldr1 (>>>) (replicate 10 integral)

-- Integral k sees the previous output of integral k-1: every accumulator
-- is advanced from the previous sample's values.
baseIntegrals10 :: Int -> [Double]
baseIntegrals10 n = go 0 0 0 0 0 0 0 0 0 0 0 0
  where
    go :: Int -> Double -> Double -> Double -> Double -> Double -> Double
       -> Double -> Double -> Double -> Double -> Double -> [Double]
    go !i !x !y1 !y2 !y3 !y4 !y5 !y6 !y7 !y8 !y9 !y10
      | i >= n    = []
      | i == 0    = 0 : go 1 0 0 0 0 0 0 0 0 0 0 0
      | otherwise =
          let x' = fromIntegral i
              y1' = y1 + dt * x
              y2' = y2 + dt * y1
              y3' = y3 + dt * y2
              y4' = y4 + dt * y3
              y5' = y5 + dt * y4
              y6' = y6 + dt * y5
              y7' = y7 + dt * y6
              y8' = y8 + dt * y7
              y9' = y9 + dt * y8
              y10' = y10 + dt * y9
          in y10' : go (i + 1) x' y1' y2' y3' y4' y5' y6' y7' y8' y9' y10'

------------------------------------------------------------------------------
-- (c) 100 integrals of one input, fanned out and summed pairwise

fan100 :: SF Double Double
fan100 = foldr1 (\a b -> (a &&& b) >>> arr (uncurry (+))) (replicate 100 integral)

baseFan100 :: Int -> [Double]
baseFan100 n = map (\y -> foldr1 (+) (replicate 100 y)) (integralOf n)

-- The integral of the input samples 0, 1, 2, ...
integralOf :: Int -> [Double]
integralOf n = take n (go 0 0)
  where go !i !y = y : go (i + 1) (y + dt * fromIntegral (i :: Int))

------------------------------------------------------------------------------
-- (d) rSwitch into a fresh integral every 10 samples

rswitch10 :: SF Double Double
rswitch10 = (identity &&& arr every10) >>> rSwitch integral
  where
    every10 x | x > 0 && truncate x `mod` (10 :: Int) == 0 = Event integral
              | otherwise                                  = NoEvent

baseRSwitch10 :: Int -> [Double]
baseRSwitch10 n = go 0 0 0
  where
    go :: Int -> Double -> Double -> [Double]
    go !i !y !prev
      | i >= n                       = []
      | i == 0 || i `mod` 10 == 0    = 0 : go (i + 1) 0 (fromIntegral i)
      | otherwise                    =
          let y' = y + dt * prev in y' : go (i + 1) y' (fromIntegral i)

-- (d') a signal function that restarts itself, through a delayed switch,
-- on the rising edge of "10 samples have passed"
dswitchRec :: SF Double Double
dswitchRec = dSwitch (integral &&& (sampleCount >>> arr (>= 10) >>> edge)) (const dswitchRec)
  where
    sampleCount = loopPre (0 :: Int) (arr (\(_, k) -> (k + 1, k + 1)))

-- The integral restarts at local sample 0 of each period of 9 samples: the
-- edge comes at local sample 9, where the new one starts (its output at
-- that sample discarded).
baseDSwitchRec :: Int -> [Double]
baseDSwitchRec n = go 0 0 0 0
  where
    go :: Int -> Int -> Double -> Double -> [Double]
    go !i !k !y !prev
      | i >= n    = []
      | k == 0    = 0 : go (i + 1) 1 0 (fromIntegral i)
      | k == 9    = let y' = y + dt * prev in y' : go (i + 1) 1 0 (fromIntegral i)
      | otherwise = let y' = y + dt * prev in y' : go (i + 1) (k + 1) y' (fromIntegral i)

------------------------------------------------------------------------------
-- (e) parB over 1000 integrals

parB1000 :: SF Double Double
parB1000 = parB (replicate 1000 integral) >>> arr (foldl' (+) 0)

baseParB1000 :: Int -> [Double]
baseParB1000 n = map (\y -> foldl' (+) 0 (replicate 1000 y)) (integralOf n)

------------------------------------------------------------------------------
-- (f) up-crossings of 0.5 by sin (10 t)

upCrossings :: SF Double Double
upCrossings = localTime >>> arr (\t -> sin (10 * t) > 0.5) >>> edge >>> arr (`tag` (+ 1)) >>> accumHold 0

baseUpCrossings :: Int -> [Double]
baseUpCrossings n = go 0 True 0
  where
    go :: Int -> Bool -> Double -> [Double]
    go !i !prevAbove !c
      | i >= n    = []
      | otherwise =
          let above = sin (10 * fromIntegral i * dt) > 0.5
              c' = if above && not prevAbove then c + 1 else c
          in c' : go (i + 1) above c'

------------------------------------------------------------------------------
-- (g) a loop with an iPre counter

loopCounter :: SF Double Double
loopCounter = loop (second (iPre 0) >>> arr (\(_, c) -> (c, c + 1)))

------------------------------------------------------------------------------
-- (h) the notes' odometry equations

odometry :: SF Double Double
odometry = network
  where
    network = localTime >>> arr wheels >>> (thetaSF &&& identity) >>> xy >>> arr (uncurry (+))
    wheels t = (1 + 0.5 * sin t, 1 + 0.5 * cos t)
    l = 0.5
    thetaSF = arr (\(vr, vl) -> vr - vl) >>> integral >>> arr (/ l)
    xy = (arr (\(th, (vr, vl)) -> (vr + vl) * cos th) >>> integral >>> arr (/ 2))
         &&& (arr (\(th, (vr, vl)) -> (vr + vl) * sin th) >>> integral >>> arr (/ 2))

baseOdometry :: Int -> [Double]
baseOdometry n = go 0 0 0 0 0 0 0
  where
    l = 0.5
    go :: Int -> Double -> Double -> Double -> Double -> Double -> Double -> [Double]
    go !i !ith !ix !iy !pd !pcs !psn
      | i >= n    = []
      | otherwise =
          let t = fromIntegral i * dt
              vr = 1 + 0.5 * sin t
              vl = 1 + 0.5 * cos t
              (ith', ix', iy') | i == 0    = (0, 0, 0)
                               | otherwise = (ith + dt * pd, ix + dt * pcs, iy + dt * psn)
              th = ith' / l
          in ix' / 2 + iy' / 2
               : go (i + 1) ith' ix' iy' (vr - vl) ((vr + vl) * cos th) ((vr + vl) * sin th)

------------------------------------------------------------------------------
-- Issue 19's variants of (b) and (h)

-- (b) as a user writes it in the source (no function next to the
-- integrals, so no rewrite rule applies: the same nodes as (b)).
integrals10Source :: SF Double Double
integrals10Source =
  integral >>> integral >>> integral >>> integral >>> integral
  >>> integral >>> integral >>> integral >>> integral >>> integral

-- The stages of a chain, for the baselines: an integral, a delay with its
-- initial output, a function.
data BStage = BInt !Double !Double | BPre !Double | BArr (Double -> Double)

-- Ten integrals with @arr (* 2)@ between them.
stagesTimes2 :: [BStage]
stagesTimes2 = intersperse (BArr (* 2)) (replicate 10 (BInt 0 0))

integralsTimes2 :: SF Double Double
integralsTimes2 = foldr1 (>>>) (intersperse (arr (* 2)) (replicate 10 integral))

integralsTimes2Source :: SF Double Double
integralsTimes2Source =
  integral >>> arr (* 2) >>> integral >>> arr (* 2) >>> integral >>> arr (* 2)
  >>> integral >>> arr (* 2) >>> integral >>> arr (* 2) >>> integral >>> arr (* 2)
  >>> integral >>> arr (* 2) >>> integral >>> arr (* 2) >>> integral >>> arr (* 2)
  >>> integral

-- Integrals, delays and functions in series.
stagesMixed :: [BStage]
stagesMixed =
  [ BInt 0 0, BPre 0, BArr (* 0.5), BInt 0 0, BArr (+ 1), BInt 0 0, BPre 1
  , BInt 0 0, BInt 0 0, BArr (* 2), BInt 0 0, BPre 0, BInt 0 0 ]

mixedChain :: SF Double Double
mixedChain = foldr1 (>>>)
  [ integral, iPre 0, arr (* 0.5), integral, arr (+ 1), integral, iPre 1
  , integral, integral, arr (* 2), integral, iPre 0, integral ]

mixedChainSource :: SF Double Double
mixedChainSource =
  integral >>> iPre 0 >>> arr (* 0.5) >>> integral >>> arr (+ 1) >>> integral >>> iPre 1
  >>> integral >>> integral >>> arr (* 2) >>> integral >>> iPre 0 >>> integral

-- A chain of stages sample by sample (a strict loop over the stages'
-- states: the numbers the network must give, not a tuned hand loop).
baseStages :: [BStage] -> Int -> [Double]
baseStages stages0 n = go 0 stages0
  where
    go !i stages
      | i >= n    = []
      | otherwise = case run (i == 0) (fromIntegral i) stages of
          (stages', y) -> y : go (i + 1) stages'
    run :: Bool -> Double -> [BStage] -> ([BStage], Double)
    run _ !x [] = ([], x)
    run start !x (st : rest) = case st of
      BInt acc prev ->
        let !acc' = if start then 0 else acc + dt * prev
            (rest', y) = run start acc' rest
        in rest' `seq` (BInt acc' x : rest', y)
      BPre v -> let (rest', y) = run start v rest in rest' `seq` (BPre x : rest', y)
      BArr f -> let !fx = f x
                    (rest', y) = run start fx rest
                in rest' `seq` (BArr f : rest', y)

-- (h) in arrow notation, as the notes write their robots.
odometryProc :: SF Double Double
odometryProc = proc _ -> do
  t <- localTime -< ()
  let vr = 1 + 0.5 * sin t
      vl = 1 + 0.5 * cos t
  thI <- integral -< vr - vl
  let th = thI / l
  x <- integral -< (vr + vl) * cos th
  y <- integral -< (vr + vl) * sin th
  returnA -< x / 2 + y / 2
  where
    l = 0.5

-- The odometry of ../shared/bench/Throughput.hs (its network h): the
-- integral of the turning rate fanned out beside the wheel speeds, then
-- the two position integrals side by side.
odometryTP :: SF Double Double
odometryTP =
  localTime
  >>> arr wheelsTP
  >>> (identity &&& (arr (\(vr, vl) -> (vr - vl) / 0.5) >>> integral))
  >>> arr (\((vr, vl), th) -> let v = vr + vl in (v * cos th, v * sin th))
  >>> (integral *** integral)
  >>> arr (\(x, y) -> 0.5 * x + 0.5 * y)

wheelsTP :: Double -> (Double, Double)
wheelsTP t = (1 + 0.5 * sin t, 1 + 0.5 * cos t)

baseOdometryTP :: Int -> [Double]
baseOdometryTP n = go 0 0 0 0
  where
    go :: Int -> Double -> Double -> Double -> [Double]
    go !i !th !x !y
      | i >= n    = []
      | otherwise =
          let (vr, vl) = wheelsTP (fromIntegral i * dt)
              v        = vr + vl
          in (0.5 * x + 0.5 * y)
               : go (i + 1) (th + dt * ((vr - vl) / 0.5)) (x + dt * (v * cos th)) (y + dt * (v * sin th))

-- Throughput.hs's (d'): an integral restarted, through 'dSwitch', by the
-- rising edge of "the input is a multiple of 10".
dswitchTP :: SF Double Double
dswitchTP = restart
  where
    restart = dSwitch (integral &&& (arr tickTP >>> edge)) (\_ -> restart)

tickTP :: Double -> Bool
tickTP x = (truncate x :: Int) `mod` 10 == 0

-- The edge does not fire at a (re)start's first sample, so the first
-- instance runs until input 10 and every later one for 10 samples; at the
-- edge the new integral starts (its output there discarded).
baseDSwitchTP :: Int -> [Double]
baseDSwitchTP n = go 0 0 0
  where
    go :: Int -> Double -> Double -> [Double]
    go !i !y !prev
      | i >= n                    = []
      | i == 0                    = 0 : go 1 0 0
      | i `mod` 10 == 0           = let y' = y + dt * prev in y' : go (i + 1) 0 (fromIntegral i)
      | otherwise                 = let y' = y + dt * prev in y' : go (i + 1) y' (fromIntegral i)

-- Throughput.hs's (g): a counter through 'loop' and 'iPre', added to the
-- input.
loopCounterTP :: SF Double Double
loopCounterTP = loop (second (iPre 0) >>> arr step)
  where
    step (x, c) = let c' = c + 1 in (x + c', c')
