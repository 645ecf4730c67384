-- |
-- Module      : Examples.Types
-- Description : What an example of the notes is, for the @afrp-examples@
--               executable, the tests and the tutorial.
module Examples.Types
  ( Example (..)
  ) where

import           AFrobRobotSim (Referee, SimbotController, WorldTemplate)

-- | One runnable example.
data Example
  = -- | A robot program: a world and the controllers of its two robot types,
    -- run with the simulator (@afrp-examples NAME [runSim flags]@).
    RobotExample
      { exName        :: String            -- ^ the name on the command line (the notes' name, or ex7, ...)
      , exDescription :: String            -- ^ one line for @--list@
      , exWorld       :: WorldTemplate     -- ^ a world that shows it off
      , exControllerA :: SimbotController  -- ^ for the SimbotA robots
      , exControllerB :: SimbotController  -- ^ for the SimbotB robots
      , exSeconds     :: Double            -- ^ how long a run shows it well (default for --seconds)
      , exKeys        :: [(Double, Char)]  -- ^ key presses (time, key) scripted when the command
                                           -- line gives no --keys; [] for a robot that reads no keys
      , exReferee     :: Referee           -- ^ the run's referee ('AFrobRobotSim.runSimRefereed'): balls put
                                           -- back, scores and goals; 'AFrobRobotSim.noReferee' for most
      }
    -- | A signal-function example from section 2: running it prints a
    -- short report (a table of sampled outputs, a property checked, ...).
  | SignalExample
      { exName        :: String
      , exDescription :: String
      , exReport      :: String            -- ^ what running it prints
      }
