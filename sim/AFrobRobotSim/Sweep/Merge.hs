{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.Sweep.Merge
-- Description : A sweep's result lines folded, one at a time, into the
--               tallies of its settings, and the table of them.
--
-- The pure part of "AFrobRobotSim.Sweep" (which re-exports 'mergeResults'
-- and 'maxListedFailures'; see it for the design): a line read ('addLine':
-- a run's result line, or the sweep's line for a run that wrote none;
-- 'addLineUtf8' the same from the line's bytes),
-- read by "AFrobRobotSim.Sweep.Line",
-- added to its setting's tallies ("AFrobRobotSim.Sweep.Tally": a count,
-- an exact sum, the least and the greatest of each outcome; the seeds
-- seen, to refuse a run merged twice), and the table of the tallies
-- ('renderMerge').
--
-- A setting is the program, the world and the parameters' values: the
-- lines of two programs (@"afrp-examples rcReverse"@ and
-- @"afrp-examples rcStop"@, each in its own world) are two settings,
-- even with the same world, parameters and seed. The table names the
-- program only when the lines name more than one, so that the table of
-- one program's lines is as it was before the program counted.
module AFrobRobotSim.Sweep.Merge
  ( -- * Merging
    Merge
  , emptyMerge
  , mergedRuns
  , addLine
  , addLineUtf8
  , renderMerge
  , mergeResults
  , maxListedFailures
  ) where

import           Control.Monad       (foldM)
import           Data.Char           (isDigit, isPrint, isSpace)
import qualified Data.ByteString     as B
import qualified Data.IntMap.Strict  as IM
import qualified Data.Map.Strict     as M
import           Data.List           (stripPrefix)
import qualified Data.Set            as S

import           AFrobRobotSim.Console (printableLine, quote)
import           AFrobRobotSim.JSON
import           AFrobRobotSim.Sweep.Line
import           AFrobRobotSim.Sweep.Tally
import           AFrobRobotSim.UTF8  (Utf8, utf8Bytes)
import           AFrobRobotSim.WorldFile.Lexical (utf8Text)

------------------------------------------------------------------------------
-- Merging

-- | The merged lines so far: the numbers of the outcomes' names, each
-- group's tallies, the programs that lines name as their result lines
-- do ('runNamed'), the programs each file the sweep ran is named by
-- ('runExecutable'), and the runs counted.
data Merge = Merge !(M.Map String Int) !(M.Map Setting Group) !(S.Set String) !(M.Map String (S.Set String)) !Int

-- | No line merged yet.
emptyMerge :: Merge
emptyMerge = Merge M.empty M.empty S.empty M.empty 0

-- | How many runs are merged so far (lines, blank ones not counted): 0
-- is the one case 'renderMerge' refuses for having nothing to show.
mergedRuns :: Merge -> Int
mergedRuns (Merge _ _ _ _ n) = n

-- Add a run, or say why not: a run of the same setting and seed (and,
-- both being result lines, time step and duration) is there already.
addRun :: Merge -> Run -> Either String Merge
addRun (Merge names groups named exes n) run
  | repeated  = Left ("the run " ++ showSetting programsSoFar (runSetting run) ++ " seed " ++ seedText ++ steps
                      ++ " is on an earlier line too (a result file merged twice, a run merged with its"
                      ++ " rerun, or runs told apart only by flags a result line does not record, such as"
                      ++ " --keys: give each such run a --param that names its setting):"
                      ++ " each run may be merged once")
  | otherwise = Right (Merge names' (M.insert (runSetting run) g' groups) named' exes' (n + 1))
  where
    seed@(Seed seedText _) = runSeed run
    named' = if runNamed run then S.insert (programOf (runSetting run)) named else named
    exes' = maybe exes (\e -> M.insertWith S.union e (S.singleton (programOf (runSetting run))) exes) (runExecutable run)
    g = M.findWithDefault emptyGroup (runSetting run) groups
    -- (the program named when the lines so far name more than one)
    programsSoFar = any ((/= programOf (runSetting run)) . programOf) (M.keys groups)
    repeated = hasSeed seed (gNoRes g) || case runSteps run of
      Nothing -> hasSeed seed (gResults g)
      Just ds -> hasSeed seed (M.findWithDefault noSeeds ds (gBySteps g))
    steps = maybe "" (\(dt, s, noise) -> " (dt " ++ dt ++ ", seconds " ++ s
                                         ++ (if noise == "0" then "" else ", odometry noise " ++ noise) ++ ")")
                  (runSteps run)
    (names', numbered) = foldr number (names, []) (runValues run)
    number (k, x) (ns, acc) = case M.lookup k ns of
      Just i  -> (ns, (i, x) : acc)
      Nothing -> let i = M.size ns in (M.insert k i ns, (i, x) : acc)
    g' = g { gRuns = gRuns g + 1
           , gFailed = gFailed g + maybe 0 (const 1) (runFailure run)
           , gListed = maybe (gListed g) (\f -> listAdd (seedText, cutMessage f) (gListed g)) (runFailure run)
           , gStats = foldr (\(place, (i, x)) -> IM.insertWith addStat i (statOf (seedText, place) x))
                            (gStats g) (zip [0 ..] numbered)
           , gNoRes = maybe (withSeed seed (gNoRes g)) (const (gNoRes g)) (runSteps run)
           , gResults = maybe (gResults g) (const (withSeed seed (gResults g))) (runSteps run)
           , gBySteps = maybe (gBySteps g) (\ds -> M.insertWith (\_ old -> withSeed seed old) ds (withSeed seed noSeeds)
                                                                (gBySteps g))
                              (runSteps run) }
    -- (a message is listed up to 2000 characters)
    cutMessage f = case splitAt 2000 f of
      (short, [])   -> short
      (short, _)    -> short ++ " (cut)"

-- | Merge one line of text (a blank one is skipped): a result line of a
-- sweep, or the sweep's line for a run that wrote none; any other line,
-- or one that repeats a run (the same setting and seed, and for two
-- result lines the same @dt@ and @seconds@), is a 'Left' saying why.
addLine :: Merge -> String -> Either String Merge
addLine m l
  | all isSpace l = Right m
  | otherwise = either (Left . notJSON) Right (parseJSON l) >>= readRun >>= addRun m

-- The message of a line that is not JSON (the parser's message given). The
-- parser places its fault at @line 1, column C@ of the text it parsed,
-- which is this one line (its first and only line): said as @column C of
-- the line@, so that the only line a message numbers is the file's
-- (@line 2: ... (not JSON: line 1, column 151 ...)@ read as two lines).
notJSON :: String -> String
notJSON e = "not a result line of a sweep (not JSON: " ++ ofTheLine e ++ ")"
  where
    ofTheLine m = case stripPrefix "line 1, column " m of
      Just rest | (c@(_ : _), ':' : msg) <- span isDigit rest -> "column " ++ c ++ " of the line:" ++ msg
      _                                                       -> m

-- | 'addLine' of a line's bytes, found to be UTF-8: the same merge, or the
-- same message, as 'addLine' of its text. The bytes are parsed as they
-- are ('parseJSONUtf8'), without the text of the whole line, which would
-- take about 30 times the line's bytes (a 16 MiB line, 550 MB).
addLineUtf8 :: Merge -> Utf8 -> Either String Merge
addLineUtf8 m u
  | B.all asciiSpace bs = Right m
  | otherwise = case parseJSONUtf8 u of
      Right v -> readRun v >>= addRun m
      Left e
        -- (a line blank but for spaces beyond ASCII, U+00A0 and the like,
        -- is blank to 'isSpace' too)
        | B.any (>= 0x80) bs, Right l <- utf8Text "" bs, all isSpace l -> Right m
        | otherwise -> Left (notJSON e)
  where
    bs = utf8Bytes u
    asciiSpace b = b == 0x20 || (b >= 0x09 && b <= 0x0d)

------------------------------------------------------------------------------
-- The table

-- | The table of a sweep's result lines (the text of one or more result
-- files, one JSON object a line; blank lines are skipped), or the first
-- line that is not a result line of a sweep, or repeats a run (the same
-- setting and seed, and for two result lines the same @dt@ and
-- @seconds@), with its number; or, when there is no line,
-- @no result lines@.
mergeResults :: String -> Either String String
mergeResults text = do
  m <- foldM (\acc (k, l) -> either (\e -> Left ("line " ++ show k ++ ": " ++ e)) Right (addLine acc l))
             emptyMerge (zip [1 :: Int ..] (lines text))
  renderMerge m

-- | The table of the merged lines: per setting, the mean, least and
-- greatest of every outcome and the failed runs, then (when two or more
-- settings vary) the same per value of each ('Left' when no line was
-- merged). A sweep's line for a run with no result is under the program
-- it names, as the program's result lines name it; one that names only
-- the file the sweep ran (no @executable@: an older sweep's) is first
-- filed under the program of the other lines (@filePrograms@). Then,
-- those that got no @--world@ (@"world": null@) are filed under the world
-- the result lines of their program name for such runs (@"program"@ or
-- @"default"@), when they name one; otherwise under @world=(not given)@
-- ('Left' when a run so filed is a result line's too).
renderMerge :: Merge -> Either String String
renderMerge (Merge names groups0 named exes n)
  | n == 0    = Left "no result lines"
  | otherwise = tableOf names <$> (filePrograms named exes groups0 >>= fileUnnamed)

-- Whether the groups name more than one program (and the table names
-- the program of each setting).
manyPrograms :: M.Map Setting Group -> Bool
manyPrograms groups = S.size (S.fromList (map programOf (M.keys groups))) > 1

-- The table of the groups (see 'renderMerge').
tableOf :: M.Map String Int -> M.Map Setting Group -> String
tableOf names groups = unlines (map printableLine
      (  concatMap (\(s, g) -> groupTable nameOf (showSetting many s) g) (M.toList groups)
      ++ concatMap (\(kv, g) -> groupTable nameOf (showSetting True [kv] ++ " over all other settings") g) marginal
      ++ mixed))
  where
    many = manyPrograms groups
    nameOf = IM.fromList [ (i, k) | (k, i) <- M.toList names ]
    values = M.fromListWith (+) [ (k, 1 :: Int) | (k, _) <- S.toList (S.fromList (concat (M.keys groups))) ]
    varying = [ k | (k, c) <- M.toList values, c > 1 ]
    -- with two or more settings varying, also each value of each over all
    -- the others (the program among them, when the lines name several)
    marginal
      | length varying > 1 =
          M.toList (M.fromListWith (flip (joinGroups False)) [ (kv, g) | (s, g) <- M.toList groups, kv@(k, _) <- s, k `elem` varying ])
      | otherwise = []
    nMixed = length [ () | g <- M.elems groups, M.size (gBySteps g) > 1 ]
    mixed = [ "== note: " ++ show nMixed ++ (if nMixed == 1 then " setting mixes" else " settings mix")
              ++ " runs of different dt, seconds or odometry noise, which the table does not tell apart (give"
              ++ " each a --param to tell them apart)" | nMixed > 0 ]

-- The groups, given the programs that lines name as their result lines do
-- ('runNamed') and the programs each file the sweep ran is named by
-- ('runExecutable'), with the sweep's lines for runs with no result that
-- name no such program filed under their program. Such a line names only
-- the file the sweep ran (a wrapper script's, say, @rev.sh@), which the
-- program's result lines may name otherwise ('optProgram':
-- @afrp-examples rcReverse@): it has no @executable@, being an older
-- sweep's, or one whose program did not print its name for the sweep's
-- @--print-program@. It is filed under the program that other lines say
-- its file is named by (their @executable@), when they say one; when
-- they say several, it is a setting of its own; when none says, it is
-- filed under the one program that result lines name, when they name one
-- alone, and is a setting of its own otherwise. The groups of a program so
-- named stay as they are. A run so filed that a line has too (the same
-- setting and seed) is refused, as 'addRun' refuses a run merged twice.
-- (When no line says which program its file is, the lines of a program
-- whose every run wrote no result and that name only its file, merged
-- with one other program's result lines, are filed under that other
-- program. A line with @executable@ is never filed so.)
filePrograms :: S.Set String -> M.Map String (S.Set String) -> M.Map Setting Group -> Either String (M.Map Setting Group)
filePrograms named exes groups = foldM file kept (M.toList strays)
  where
    (strays, kept) = M.partitionWithKey (\s _ -> programOf s `S.notMember` named) groups
    withResults = S.fromList [ programOf s | (s, g) <- M.toList kept, not (M.null (gBySteps g)) ]
    file acc (setting, g) = case (fmap S.toList (M.lookup (programOf setting) exes), S.toList withResults) of
      (Just [program], _) -> joinFiled False (withProgram program setting) g acc
      (Nothing, [only])   -> joinFiled False (withProgram only setting) g acc
      _                   -> Right (M.insert setting g acc)

-- The groups with the runs of an unnamed world ('unnamedWorld') filed
-- under the world the result lines of their program name for a run
-- without @--world@, when they name one ('ownWorlds'); left as they are
-- when they name none (every such run failed) or both (two sweeps
-- merged, of the program's own world and of the default one). A run so
-- filed that a result line has too (the same setting and seed) is
-- refused, as 'addRun' refuses a run merged twice.
fileUnnamed :: M.Map Setting Group -> Either String (M.Map Setting Group)
fileUnnamed groups = foldM file named (M.toList unnamed)
  where
    (unnamed, named) = M.partitionWithKey (\k _ -> worldOf k == Just unnamedWorld) groups
    many = manyPrograms groups
    worldOf setting = case setting of
      _ : (k, w) : _ | k == worldKey -> Just w
      _                    -> Nothing
    -- (the worlds of each program's own that its lines name)
    owns = M.fromListWith S.union [ (programOf k, S.singleton w) | k <- M.keys named, Just w <- [worldOf k]
                                                                  , w `elem` ownWorlds ]
    file acc (setting, g) = case maybe [] S.toList (M.lookup (programOf setting) owns) of
      [own] -> joinFiled many (withWorld own setting) g acc
      _     -> Right (M.insert setting g acc)
    withWorld w setting = case setting of
      p : (k, _) : rest | k == worldKey -> p : (k, w) : rest
      _                                 -> setting

-- A group filed under a setting (with @many@: the lines name more than
-- one program), joined with the group there, if any; refused when a run
-- of the group filed is there already (its seed's line for a run with no
-- result being on a result line there, or on another such line).
joinFiled :: Bool -> Setting -> Group -> M.Map Setting Group -> Either String (M.Map Setting Group)
joinFiled many setting g acc = case M.lookup setting acc of
  Nothing -> Right (M.insert setting g acc)
  Just g0 -> case (commonSeed (gNoRes g) (seedsUnion (gNoRes g0) (gResults g0)), commonSeed (gNoRes g) (gResults g0)) of
    (Just seed, Just _) -> twice seed "on a line for a run with no result and on a result line too (a result file merged"
                                      " with the sweep's line for the same run)"
    (Just seed, Nothing) -> twice seed "on two lines for a run with no result (the sweep's lines for the same run merged"
                                       " twice, under two programs' names)"
    _ -> Right (M.insert setting (joinGroups True g0 g) acc)
  where
    twice seed what why = Left ("the run " ++ showSetting many setting ++ " seed " ++ seed ++ " is " ++ what ++ why
                                ++ ": each run may be merged once")

-- A setting as the table names it: @world=default speed=0.1@, each name
-- and value as it is when it is plain (not empty; no space, @=@, quote,
-- backslash or character that does not print), otherwise in quotes with
-- the quote, the backslash and the characters that do not print escaped
-- ('quote'): @mode="1 b=2"@, @note="x\ny"@. So two settings never read
-- alike: unquoted, a value @1 b=2@ read as two parameters, and a value
-- with a newline as one with a backslash and an @n@. The world of a run
-- with no result and no @--world@ that 'fileUnnamed' could not file is
-- @world=(not given)@. The program is named first, @program=my-robot@,
-- when @many@ holds (the lines name more than one program), and left out
-- otherwise. A parameter named @world@ or @program@ has its name in
-- quotes, @"world"=3@, so that it never reads as the run's world or
-- program.
showSetting :: Bool -> Setting -> String
showSetting many g = unwords (map pair (filter shownPair g))
  where
    shownPair (k, _) = many || k /= programKey
    pair (k, v)
      | k == programKey                     = "program=" ++ shown v
      | k == worldKey && v == unnamedWorld  = "world=(not given)"
      | k == worldKey                       = "world=" ++ shown v
      | k `elem` ["world", "program"]       = quote k ++ "=" ++ shown v
      | otherwise                           = shown k ++ "=" ++ shown v
    shown t | not (null t) && all plain t = t
            | otherwise                   = quote t
    plain c = isPrint c && not (isSpace c) && c `notElem` "=\"\\"

