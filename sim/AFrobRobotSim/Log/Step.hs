-- |
-- Module      : AFrobRobotSim.Log.Step
-- Description : A run log's frames made step by step from a simulation's
--               states.
--
-- 'logStep' takes the states one at a time, as 'simulate' gives them
-- (what a streaming writer needs), and gives a frame record at each
-- frame's step; 'logFrames' does it for a whole list. Frames are the
-- runner's: frame @f@ is the step nearest simulated time @f / fps@
-- ('isFrameStep'; the first step is frame 0), and a frame carries the
-- events and the console lines of its period: the steps after the
-- previous frame, up to and including its own. Part of
-- "AFrobRobotSim.Log", which re-exports it with 'LogState' kept
-- abstract; the frame's record itself is made by
-- "AFrobRobotSim.Log.Frame".
module AFrobRobotSim.Log.Step
  ( LogState (..)
  , logStart
  , logStep
  , logFrames
  , isFrameStep
  ) where

import           AFrobRobotSim.Arena       (Arena, arenaOf)
import           AFrobRobotSim.Log.Config
import           AFrobRobotSim.Log.Frame
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.Simulator

-- | What 'logStep' remembers between steps. Its fields are for
-- "AFrobRobotSim.Log.Rates", which steps the same way; a user of the log
-- has only 'logStart' and 'logStep'.
data LogState = LogState
  { stStep    :: !Int                 -- ^ the steps taken so far
  , stPrev    :: !(Maybe Prev)        -- ^ what the events and a frame need of the previous step
  , stEvents  :: [LogEvent]           -- ^ the events of the period so far, newest first
  , stLines   :: [String]             -- ^ the console lines of the period so far, newest first
  , stArena   :: Arena                -- ^ the world's walls, blocks and boundary, for the sensors
  }

-- | The state before the first step.
logStart :: LogConfig -> LogState
logStart cfg = LogState 0 Nothing [] [] (arenaOf (lcBounds cfg) (lcWorld cfg))

-- | Is step @n@ (from 0) a frame's step, at @fps@ frames per second and
-- time step @dt@: the step nearest a multiple of @1 / fps@ (and step 0)?
isFrameStep :: Double -> Double -> Int -> Bool
isFrameStep dt fps n =
  let f = fromIntegral n * dt * fps
  in n == 0 || abs (f - fromIntegral (nearest f)) * 2 < dt * fps
  where
    -- ('round', by plain arithmetic where 'roundHalfEven' is exact: the
    -- replay page's recorder asks at every step for each frame rate it
    -- keeps, and 'round' is a foreign call)
    nearest f | abs f < 1e15 = roundHalfEven f
              | otherwise    = round f :: Int

-- | Take the next step's state (the first call gets the state at time 0):
-- the new 'LogState', and the frame record when this step is a frame's.
logStep :: LogConfig -> LogState -> WorldState -> (LogState, Maybe LogFrame)
logStep cfg st s
  | isFrameStep (lcDt cfg) (lcFps cfg) n =
      ( st' { stEvents = [], stLines = [] }
      , Just (frameOf cfg (stArena st) (stPrev st) s scores (reverse events) (reverse lines')) )
  | otherwise = (st', Nothing)
  where
    n       = stStep st
    scores  = lcScores cfg s
    -- (the step's events and console lines made now, so that nothing
    -- keeps the state: left lazy until the frame, they kept every state
    -- of the frame period)
    new     = newEvents (stPrev st) s scores
    events  = foldr seq () new `seq` (new ++ stEvents st)
    lines'  = reverse (wsMessages s) ++ stLines st
    st'     = events `seq` lines' `seq`
              st { stStep = n + 1, stPrev = Just $! prevOf s scores, stEvents = events, stLines = lines' }

-- | The frames of a list of states (every step, from time 0), lazily.
logFrames :: LogConfig -> [WorldState] -> [LogFrame]
logFrames cfg = go (logStart cfg)
  where
    go _ []       = []
    go st (s : ss) = case logStep cfg st s of
      (st', Just f)  -> f : go st' ss
      (st', Nothing) -> go st' ss
