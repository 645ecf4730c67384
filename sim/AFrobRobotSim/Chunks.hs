{-# LANGUAGE BangPatterns  #-}
{-# LANGUAGE UnboxedTuples #-}
-- The chunks of a parallel step must be blackholed as soon as a thread
-- enters them, so that a thread that needs a chunk another is computing
-- waits for it instead of computing it again. 'stepEvery' is inlined
-- where it is used, and its chunks' thunks are compiled there: a module
-- that uses it needs this flag too ("AFrobRobotSim.Simulator" has it).
-- Here it covers what is not inlined ('firstChunk').
{-# OPTIONS_GHC -feager-blackholing #-}
-- |
-- Module      : AFrobRobotSim.Chunks
-- Description : A step's robots cut into chunks of consecutive robots,
--               computed in order on one capability and in parallel on
--               several, read in order either way.
--
-- The part of "AFrobRobotSim.Simulator"'s step that depends on nothing but
-- one robot (its sensing, its controller's step, the plan of its move) is
-- computed here, chunk by chunk ('stepEvery'); the simulator moves the
-- robots against each other in template order, reading the chunks' lists
-- in that order. Each chunk is a pure value and the lists are the chunks'
-- lists joined in order, so what the reader sees is the same, bit for bit,
-- on any number of capabilities; only when, and on which thread, each
-- chunk is computed changes (the threads are "AFrobRobotSim.Workers"'s).
-- The types are the simulator's (agents, robots, outputs and plans), kept
-- abstract here.
module AFrobRobotSim.Chunks
  ( stepEvery
  , minChunk
  , seqChunk
  ) where

import           GHC.Conc              (pseq)

import           AFrobRobotSim.Workers

-- | Every robot's controller step (its output and its next agent) and the
-- plan of its move, in template order, given a robot's step by its
-- number, agent and robot (with a lower bound on its distance to the
-- other robots) and the plan of a robot's move under a command, given
-- that bound; and first @()@, which starts the work. Unless the first
-- argument is 'True' (the simulator's @simParallel@), the step is
-- computed as on one capability, whatever their number.
--
-- On one capability the start does nothing, and the robots are cut into
-- chunks of 'seqChunk', each computed when the first of its elements is
-- needed (the reader of the lists, which moves the robots in order, moves
-- a chunk's robots before the next chunk is computed); a world of at most
-- 'seqChunk' robots is one chunk. On several, the robots are cut into
-- chunks computed in parallel (about sixteen per capability, at least
-- 'minChunk' robots each): the start
-- computes @ready@ (what every robot's step shares) and gives the workers
-- the chunks, from the first; a chunk is computed by whoever reaches it
-- first, the reader of the lists (in order) or a worker; each chunk, in
-- weak head normal form, has computed every step in it. So the reader,
-- which moves the robots in order, moves those of a chunk while the
-- workers compute later chunks.
stepEvery :: Bool -> () -> [agent] -> [robot]
          -> (Int -> agent -> robot -> ((output, agent), Double))
          -> (Double -> robot -> output -> plan)
          -> ((), [output], [agent], [(robot, plan)])
stepEvery parallel ready agents robots stepOne planOne
  | caps <= 1 && not (null (drop seqChunk robots)) = lists () (firstChunk () inOrder)
  | caps <= 1 || n < 2 * minChunk = lists () (stepRun 0 maxBound agents robots [] [] [])
  | otherwise = lists started (firstChunk started shared)
  where
    -- the start and the lists of the chunks joined (each list after the
    -- start, which 'firstChunk' takes)
    lists s c = (s, chunkOutputs c, chunkAgents c, chunkPlans c)
    -- the workers given the chunks (once @ready@)
    started = ready `pseq` shared `pseq` ()
    n    = length robots
    caps | parallel  = capabilitiesNow agents   -- (not n: one capability needs no count)
         | otherwise = 1
    size = max minChunk ((n + 16 * caps - 1) `div` (16 * caps))
    -- the chunks as the workers share them with the reader of the lists
    shared = readInOrder caps (cut size 0 agents robots (drop 1 shared))
    -- on one capability, chunks of 'seqChunk' robots, each computed when
    -- the first of its elements is needed
    inOrder = cut seqChunk 0 agents robots (drop 1 inOrder)
    -- Chunks of @k@ consecutive robots. Each chunk's lists end with the
    -- next chunk's (as shared), so the chunks joined are the first one's
    -- lists: no list is copied to cut them apart or to join them.
    cut !k !i as rs nexts
      | null as || null rs = []
      | otherwise = let rest = cut k (i + k) (drop k as) (drop k rs) (drop 1 nexts)
                        -- (lazily: the next chunk is not computed yet)
                        next = firstChunk () nexts
                    in stepRun i k as rs (chunkOutputs next) (chunkAgents next) (chunkPlans next)
                         : rest
    -- Strict loops: a step needs every element, and lazy zips would build
    -- a thunk per robot and list. A chunk's lists end with @tailO@,
    -- @tailA@ and @tailP@.
    stepRun !i !k as rs tailO tailA tailP = case go i k as rs tailO tailA tailP of
      (# os, as', ps #) -> Chunk os as' ps
    go !i !k (a : as) (r : rs) tailO tailA tailP
      | k > (0 :: Int) = case stepOne i a r of
          ((!o, !a'), apart) -> case go (i + 1) (k - 1) as rs tailO tailA tailP of
            (# os, as', ps #) -> case planOne apart r o of
              !pl -> (# o : os, a' : as', (r, pl) : ps #)
    go _ _ _ _ tailO tailA tailP = (# tailO, tailA, tailP #)
-- (inlined at its one use, as when it was the simulator's own: called
-- across modules, its step and plan were unknown calls, and 10 robots
-- took 6% longer a robot-step)
{-# INLINE stepEvery #-}

-- The controller outputs, next agents and move plans of consecutive
-- robots.
data Chunk output agent robot plan = Chunk
  { chunkOutputs :: [output]
  , chunkAgents  :: [agent]
  , chunkPlans   :: [(robot, plan)] }

-- @firstChunk s cs@: the first chunk of @cs@ (an empty one if none),
-- after @s@; so the chunks joined are the first one's lists. Not inlined,
-- so that a chunk's lists are selections from one shared value
-- (@chunkAgents next@), which the collector replaces by the list selected
-- once the value is computed: inlined, each was a closure over the rest of
-- the chunks, and kept every chunk of the step (its plans and outputs
-- included) alive until the step's end.
firstChunk :: () -> [Chunk output agent robot plan] -> Chunk output agent robot plan
firstChunk s cs = s `pseq` case cs of
  c : _ -> c
  []    -> Chunk [] [] []
{-# NOINLINE firstChunk #-}

-- | The fewest robots whose steps are handed to a worker together: 16
-- (handing one over costs about as much as a robot's step; with the 100
-- packed wanderers, 16 a chunk ran as fast as 13, faster than 8).
minChunk :: Int
minChunk = 16

-- | The robots of a chunk on one capability: 64. At 10,000 robots the
-- collector copied 960 MB in 100 steps (1,660 MB when every robot's step
-- was computed before the first move: every robot's output and plan, and
-- a stack one frame deep per robot, were live at each collection); one
-- core's instructions per robot-step fell 17% at 10,000 robots and 3% at
-- 1000.
seqChunk :: Int
seqChunk = 64
