-- |
-- Module      : Exercises.Ex07
-- Description : Exercise 7 of the notes: rcBlind2, then rcTurn, then rcStop.
--
-- \"Link @rcBlind2@, @rcTurn@, and @rcStop@ together in the following way:
-- Perform @rcBlind2@ for 2 seconds, then @rcTurn@ for three seconds, and
-- then do @rcStop@. (Hint: use @after@ to generate an event after a given
-- time interval.)\"
--
-- Each stage runs beside an @after@ event source, and 'switch' moves on to
-- the next stage when it fires. Time starts afresh in every stage, so the
-- second @after 3@ counts from the end of the first stage: the turn is
-- from 2 s to 5 s.
module Exercises.Ex07
  ( rcBlindTurnStop
  , ex7World
  , examples
  ) where

import           AFrob
import           AFrobRobotSim
import           Examples.Types
import           Paper.Section3 (rcBlind2, rcStop, rcTurn)

-- | @rcBlindTurnStop v@: 'rcBlind2' for 2 s, then @'rcTurn' v@ for 3 s,
-- then 'rcStop'.
rcBlindTurnStop :: Velocity -> SimbotController
rcBlindTurnStop v rps =
  switch (rcBlind2 rps &&& after 2 ()) $ \() ->
  switch (rcTurn v rps &&& after 3 ()) $ \() ->
  rcStop rps

-- | A SimbotA and a SimbotB heading east, side by side.
ex7World :: WorldTemplate
ex7World = [OTSimbotA 1 (Point2 (-3) 1.5) 0, OTSimbotB 1 (Point2 (-3) (-1.5)) 0]

-- | @ex7@: the SimbotA turns at 0.6 m/s (1.6 rad/s), the SimbotB at
-- 1.5 m/s (2 rad/s).
examples :: [Example]
examples =
  [ RobotExample
      { exName        = "ex7"
      , exDescription = "rcBlind2 for 2 s, then rcTurn for 3 s, then rcStop (switches on after events)"
      , exWorld       = ex7World
      , exControllerA = rcBlindTurnStop 0.6
      , exControllerB = rcBlindTurnStop 1.5
      , exSeconds     = 10
      , exKeys        = []
      , exReferee     = noReferee
      }
  ]
