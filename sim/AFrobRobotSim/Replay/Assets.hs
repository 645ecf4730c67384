{-# LANGUAGE TemplateHaskell #-}
-- |
-- Module      : AFrobRobotSim.Replay.Assets
-- Description : The replay page's script and style sheet, compiled in.
--
-- The page's JavaScript and CSS live in files of their own beside this
-- module (@replay.js@, @replay.css@), where an editor highlights them,
-- and are read into the library when it is compiled, so that the page
-- needs no file at run time.
module AFrobRobotSim.Replay.Assets
  ( replayScript
  , replayStyle
  ) where

import           Language.Haskell.TH        (Exp (LitE), Lit (StringL), runIO)
import           Language.Haskell.TH.Syntax (addDependentFile)

-- | The page's script (ASCII), @sim/AFrobRobotSim/Replay/replay.js@.
replayScript :: String
replayScript = $(do let path = "sim/AFrobRobotSim/Replay/replay.js"
                    addDependentFile path
                    s <- runIO (readFile path)
                    length s `seq` pure (LitE (StringL s)))

-- | The page's style sheet (ASCII), @sim/AFrobRobotSim/Replay/replay.css@.
replayStyle :: String
replayStyle = $(do let path = "sim/AFrobRobotSim/Replay/replay.css"
                   addDependentFile path
                   s <- runIO (readFile path)
                   length s `seq` pure (LitE (StringL s)))
