-- |
-- Module      : AFrobRobotSim.Log.Rates
-- Description : A run log's frames at several frame rates at once.
--
-- The frames a run log would have at each of several frame rates, made
-- in one pass over the states ('LogRates'): for the replay page's
-- recorder ("AFrobRobotSim.Replay.Recorder"), which keeps the rate that
-- suits the run's length once it is known. Built on
-- "AFrobRobotSim.Log.Step" and "AFrobRobotSim.Log.Frame"; part of
-- "AFrobRobotSim.Log", which re-exports it.
module AFrobRobotSim.Log.Rates
  ( LogRates
  , logRatesStart
  , logRatesStep
  , logRatesKeep
  ) where

import           AFrobRobotSim.Log.Config
import           AFrobRobotSim.Log.Frame
import           AFrobRobotSim.Log.Records
import           AFrobRobotSim.Log.Step
import           AFrobRobotSim.Simulator

-- | 'logStep' at several frame rates at once, each named by a key of the
-- caller's: for a writer that cannot yet tell which rate it will keep (the
-- replay page's recorder, which thins its page for the length the run
-- turns out to have: "AFrobRobotSim.Replay"). The frames of the rate
-- @fps@ are exactly those of 'logStep' with that 'lcFps': the same steps
-- ('isFrameStep' at @fps@) and the same records, each with the events,
-- console lines and messages of its own period (the steps after that
-- rate's previous frame, up to and including its own). What a step makes
-- for every rate, its events, its console lines and its frame's instant
-- (the robots' readings, the costly part), is made once.
data LogRates k = LogRates !LogState !Int [RatePeriod k]
  -- (the step count, the previous step and the arena, the state's own
  -- period left empty; how many events and console lines the run has
  -- made; each rate's period)

-- One rate's period so far: its key, its frames a second, its events and
-- console lines (newest first), and how many events and lines the run had
-- made when it began. Two rates whose periods began at the same count hold
-- the same events and lines: whatever was made since.
data RatePeriod k = RatePeriod k !Double [LogEvent] [String] !Int

-- | The rates, as (key, frames a second), before the first step.
logRatesStart :: LogConfig -> [(k, Double)] -> LogRates k
logRatesStart cfg rates = LogRates (logStart cfg) 0 [ RatePeriod k fps [] [] 0 | (k, fps) <- rates ]

-- | Only the rates whose keys pass the test, from now on (a rate dropped
-- costs nothing more; its period is forgotten).
logRatesKeep :: (k -> Bool) -> LogRates k -> LogRates k
logRatesKeep keep (LogRates st made rates) = LogRates st made [ r | r@(RatePeriod k _ _ _ _) <- rates, keep k ]

-- | Take the next step's state (the first call gets the state at time 0):
-- the new 'LogRates', and this step's frames, one for each group of the
-- rates whose frame the step is and whose periods hold the same events and
-- lines, with the keys of the group's rates (in the order the rates were
-- given; the groups by their first rate). So each frame is
-- that of 'logStep' at each of its rates.
logRatesStep :: LogConfig -> LogRates k -> WorldState -> (LogRates k, [([k], LogFrame)])
logRatesStep cfg (LogRates st made rates) s = (next, frames)
  where
    n        = stStep st
    scores   = lcScores cfg s
    -- (made now, as 'logStep' makes them, so that nothing keeps the state)
    new      = newEvents (stPrev st) s scores
    newLines = reverse (wsMessages s)
    made'    = made + length new + length newLines
    grown | made' == made = rates
          | otherwise     = map grow rates
    grow (RatePeriod k fps evs ls since) =
      let evs' = new ++ evs
          ls'  = newLines ++ ls
      in evs' `seq` ls' `seq` RatePeriod k fps evs' ls' since
    isFrame (RatePeriod _ fps _ _ _) = isFrameStep (lcDt cfg) fps n
    -- (each rate asked once; most steps are no rate's frame)
    framed = [ (r, isFrame r) | r <- grown ]
    firing = [ r | (r, True) <- framed ]
    rates' | null firing = grown
           | otherwise   = [ if f then RatePeriod k fps [] [] made' else r | (r@(RatePeriod k fps _ _ _), f) <- framed ]
    st'    = st { stStep = n + 1, stPrev = Just $! prevOf s scores }
    next   = foldr seq () new `seq` foldr seq () rates' `seq` LogRates st' made' rates'
    instant = frameInstant cfg (stArena st) (stPrev st) s scores
    frames = [ (keys, periodFrame instant (reverse evs) (reverse ls))
             | (keys, evs, ls) <- samePeriods firing ]
    -- (the rates grouped by the count their periods began at)
    samePeriods [] = []
    samePeriods (RatePeriod k _ evs ls since : rest) =
      (k : [ k' | RatePeriod k' _ _ _ since' <- rest, since' == since ], evs, ls)
      : samePeriods [ r | r@(RatePeriod _ _ _ _ since') <- rest, since' /= since ]
