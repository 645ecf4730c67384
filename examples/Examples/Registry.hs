-- | Every example, in the order of the notes.
module Examples.Registry
  ( allExamples
  , exampleListing
  , exampleCommand
  ) where

import           Data.List      (intercalate)
import           Text.Printf    (printf)

import           AFrobRobotSim  (Command (..), SimOptions (..), defaultSimOptions, isHelpFlag, parseSimArgs)

import           Examples.Types
import qualified Exercises.Ex01 as Ex01
import qualified Exercises.Ex02 as Ex02
import qualified Exercises.Ex03 as Ex03
import qualified Exercises.Ex04 as Ex04
import qualified Exercises.Ex05 as Ex05
import qualified Exercises.Ex06 as Ex06
import qualified Exercises.Ex07 as Ex07
import qualified Exercises.Ex08 as Ex08
import qualified Exercises.Ex09 as Ex09
import qualified Exercises.Ex10 as Ex10
import qualified Exercises.Ex11 as Ex11
import qualified Exercises.Ex12 as Ex12
import qualified Exercises.Ex13 as Ex13
import qualified Exercises.Ex14 as Ex14
import qualified Exercises.Ex15 as Ex15
import qualified Paper.Section2 as Section2
import qualified Paper.Section3 as Section3

-- | The notes' programs (sections 2 and 3), then the exercises 1 to 15.
allExamples :: [Example]
allExamples = concat
  [ Section2.examples, Section3.examples
  , Ex01.examples, Ex02.examples, Ex03.examples, Ex04.examples, Ex05.examples
  , Ex06.examples, Ex07.examples, Ex08.examples, Ex09.examples, Ex10.examples
  , Ex11.examples, Ex12.examples, Ex13.examples, Ex14.examples, Ex15.examples
  ]

-- | @--list@: every example, one per line, with what it takes: nothing
-- (a signal-function example, which prints a report), the simulator's
-- flags, or the flags and scripted keys (its default @--keys@ shown).
exampleListing :: [Example] -> String
exampleListing es = unlines $
  [ "NAME               TAKES                     WHAT"
  ] ++
  [ printf "%-18s %-25s %s" (exName e) (takes e) (exDescription e) | e <- es ] ++
  [ ""
  , "Robot examples take the simulator's flags (NAME --help lists them); those"
  , "marked keys read the keyboard, scripted with --keys \"TIME:KEY,...\" (the"
  , "default script is shown). Signal-function examples print a report."
  ]
  where
    takes e = case e of
      SignalExample {} -> "-"
      RobotExample {}
        | null (exKeys e) -> "flags"
        | otherwise       -> "flags, keys " ++ intercalate "," [ showKey k | k <- exKeys e ]
    showKey (t, c) = (if t == fromIntegral (round t :: Integer) then show (round t :: Integer) else show t)
                     ++ [':', c]

-- | @exampleCommand prog e flags@: a robot example's command line
-- ('parseSimArgs'), with the example's defaults: its @--seconds@, its
-- scripted keys ('exKeys') when the command line gives no @--keys@ (every
-- @--keys@ adds its presses, so the example's script is not one to add
-- to: @--keys 1:+@ presses + once), and its name in the result line,
-- @prog@ and the example's name ('optProgram': @afrp-examples rcReverse@),
-- so that the result lines of several examples, each in its own world,
-- are told apart. A signal-function example takes no flags: a 'Left'
-- saying so, but for @--help@ or @-h@ first, 'ShowHelp' (as a robot
-- example's command line asks for the usage at @--help@, unless a flag
-- before it is refused: 'AFrobRobotSim.parseSimFlags').
exampleCommand :: String -> Example -> [String] -> Either String Command
exampleCommand prog e flags = case e of
  SignalExample {}
    | flag : _ <- flags, isHelpFlag flag -> Right ShowHelp
    | otherwise -> Left (exName e ++ " is a signal-function example; it takes no flags")
  RobotExample {}  -> fmap (named . scripted)
                           (parseSimArgs defaultSimOptions { optSeconds = exSeconds e } flags)
  where
    scripted (RunWith opt) | "--keys" `notElem` flags = RunWith opt { optKeys = exKeys e }
    scripted c = c
    named (RunWith opt) = RunWith opt { optProgram = Just (prog ++ " " ++ exName e) }
    named c = c

