{-# OPTIONS_GHC -fno-full-laziness #-}
-- |
-- The rendering benchmark: 600x600 PPM frames ("AFrobRobotSim.Render") of
-- the 10-robot simulator benchmark world, with the range-finder rays
-- drawn. The snapshots are simulated once (a shared list); only the
-- rendering is timed.
module RenderBench
  ( renderFrames
  , renderStyle600
  , prepareFrames
  ) where

import           Data.List             (foldl')

import           AFrobRobotSim
import           SimBench

-- | 58 pixels per metre: the 10 m world and its 10 pixel margins make a
-- 600x600 frame.
renderStyle600 :: RenderStyle
renderStyle600 = defaultRenderStyle { styleScale = 58, styleRays = True }

scene10 :: Scene
scene10 = Scene (benchBounds 10) (benchWorld 10)

-- The snapshots of the 10-robot world, every 10th of the first 10000 steps.
snapshots :: [WorldState]
snapshots = every 10 (take 10000 (simulateWith (benchConfig 10) (benchWorld 10) benchController benchController))
  where every k xs = case xs of
          []      -> []
          x : xs' -> x : every k (drop (k - 1) xs')
{-# NOINLINE snapshots #-}

-- | Render the first @k@ snapshots (at most 1000) and return how many
-- frames were rendered. A frame is a strict @ByteString@: evaluating it
-- renders it.
renderFrames :: Int -> Int
renderFrames k = foldl' (\acc ws -> render [] ws `seq` acc + 1) 0 (take k snapshots)
  where render = renderPPM renderStyle600 scene10   -- once, as the runner does

-- | Simulate (outside any timing) the snapshots that @renderFrames k@
-- renders; returns a number that depends on all of them.
prepareFrames :: Int -> Double
prepareFrames k = foldl' (\acc ws -> acc + wsTime ws + fromIntegral (length (wsRobots ws))) 0
                         (take k snapshots)
