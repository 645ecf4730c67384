-- |
-- Module      : AFrobRobotSim.DefaultWorld
-- Description : The world 'AFrobRobotSim.runSim' uses when given 'Nothing'.
module AFrobRobotSim.DefaultWorld
  ( defaultWorld
  ) where

import           AFRP.Geometry         (Point2 (..))
import           AFrobRobotSim.World

-- | A lively default world in the notes' 10 m square: a long wall to
-- follow, a corridor between two walls to bounce in, a few blocks and
-- balls, three SimbotA and four SimbotB.
defaultWorld :: WorldTemplate
defaultWorld =
  -- a long horizontal wall across the top half
  [ OTHWall (Point2 x 3) | x <- [-3.5, -2.5 .. 2.5] ]
  -- a corridor of two vertical walls on the left
  ++ [ OTVWall (Point2 (-3.6) y) | y <- [-3.5, -2.5, -1.5] ]
  ++ [ OTVWall (Point2 (-1.4) y) | y <- [-3.5, -2.5, -1.5] ]
  ++ [ OTBlock (Point2 2.5 (-2.5)), OTBlock (Point2 3.5 0), OTBlock (Point2 0.5 (-3.8)) ]
  ++ [ OTBall (Point2 1 0), OTBall (Point2 (-0.3) (-1.2)), OTBall (Point2 3 2) ]
  ++ [ OTSimbotA 1 (Point2 (-2.5) (-2.5)) 0            -- bounces in the corridor
     , OTSimbotA 2 (Point2 (-3) 2.45) 0                -- follows the wall on its left
     , OTSimbotA 3 (Point2 (-2.5) (-0.5)) 0.3
     , OTSimbotB 1 (Point2 0.5 1.5) 0.4                -- four that align their headings
     , OTSimbotB 2 (Point2 1.5 (-1)) 2.1
     , OTSimbotB 3 (Point2 (-0.2) (-2.2)) (-1.9)
     , OTSimbotB 4 (Point2 2.2 1.2) 3.0
     ]
