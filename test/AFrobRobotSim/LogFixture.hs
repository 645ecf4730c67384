-- | A short real run shared by the log, replay and browser tests: two
-- robots, walls, a block, a ball, and a robot that prints a hostile line.
module AFrobRobotSim.LogFixture
  ( hostileMessage
  , fixtureWorld
  , fixtureConfig
  , fixtureSeconds
  , fixtureStates
  , fixtureLog
  , fixtureLogText
  , fixtureLogLines
  , fixtureChunkEdges
  ) where

import           AFrob
import           AFrobRobotSim
import           AFrobRobotSim.Log

-- | What SimbotA 1 prints at 0.5 s: markup that would close a script
-- element and run one, quotes, backslashes and control characters.
hostileMessage :: String
hostileMessage = "</script><img src=x onerror=\"window.__pwned=1\">'\\\"\n\t\0\x1b <!-- \x2028 &amp; caf\233"

-- | SimbotA 1 at (-2, 0) facing +x, SimbotB 2 at (2, 1.5) facing -x, a
-- wall, a block and a ball.
fixtureWorld :: WorldTemplate
fixtureWorld =
  [ OTSimbotA 1 (Point2 (-2) 0) 0, OTSimbotB 2 (Point2 2 1.5) pi
  , OTVWall (Point2 4 (-2)), OTHWall (Point2 0 (-4)), OTBlock (Point2 (-3) 3), OTBall (Point2 0 (-2)) ]

-- | The run's length: 2 s.
fixtureSeconds :: Double
fixtureSeconds = 2

fixtureConfig :: LogConfig
fixtureConfig = defaultLogConfig { lcWorld = fixtureWorld, lcDt = 0.01, lcFps = 25
                                 , lcCommandLine = ["fixture", "--log", "<run>.jsonl"] }

-- | Every step of the run, from time 0 to 'fixtureSeconds'.
fixtureStates :: [WorldState]
fixtureStates = take (round (fixtureSeconds / 0.01) + 1) (simulate 0.01 fixtureWorld ctrlA ctrlB)
  where
    ctrlA _ = after 0.5 hostileMessage >>> arr (\e -> mrFinalize (ddVelDiff 0.4 0.5 `mrMerge` tcoPrintMessage e))
    ctrlB _ = constant (mrFinalize (ddVelDiff 1 1))

-- | The run's log, as records.
fixtureLog :: RunLog
fixtureLog = RunLog (logHeader fixtureConfig) (logFrames fixtureConfig fixtureStates)
  (Just (LogSummary fixtureSeconds (length fixtureStates) (length (logFrames fixtureConfig fixtureStates))
                    0.5 False Nothing Nothing []))
  Nothing

-- | The run's log, as the text of a file.
fixtureLogText :: String
fixtureLogText = unlines fixtureLogLines

-- | The run's log, as its lines (no newlines).
fixtureLogLines :: [String]
fixtureLogLines = map encodeLogLine (LineHeader (rlHeader fixtureLog)
                                     : map LineFrame (rlFrames fixtureLog)
                                     ++ maybe [] ((: []) . LineSummary) (rlSummary fixtureLog))

-- | Bounds of a page's data element about where the log's first lines
-- would end one: the @k@-th line's end, the lines joined by a comma and
-- a newline, and one character either side (@k@ from 1 to 6).
fixtureChunkEdges :: [Int]
fixtureChunkEdges = concat [ [e - 1, e, e + 1] | k <- [1 .. 6], let e = prefixJoined k ]
  where
    prefixJoined k = sum (map length (take k fixtureLogLines)) + 2 * (k - 1)
