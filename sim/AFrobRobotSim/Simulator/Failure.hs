{-# LANGUAGE BangPatterns         #-}
{-# LANGUAGE UnboxedTuples       #-}
{-# LANGUAGE ScopedTypeVariables #-}
-- |
-- Module      : AFrobRobotSim.Simulator.Failure
-- Description : A controller's failure, found in its own step and named;
--               the referee's, found in its rules.
--
-- A controller fails when evaluating its step raises an exception (its
-- own, or an error in a message it prints), overflows the stack, or gives
-- a wheel command with a NaN or infinite speed. "AFrobRobotSim.Simulator"
-- evaluates each robot's output, messages included, inside 'blaming', so
-- that the failure names the robot and the time ('ControllerError')
-- rather than surface later, unnamed, where the run's outputs are
-- written. The referee's rules ('AFrobRobotSim.Simulator.simBallRule'
-- and 'AFrobRobotSim.Simulator.simScores') are evaluated so too, and
-- their failure is a 'RefereeError' naming the rule and the time. What a
-- run keeps of a message or of an exception's text is cut at
-- 'maxTextChars' characters.
module AFrobRobotSim.Simulator.Failure
  ( ControllerError (..)
  , RefereeError (..)
  , isRunFailure
  , blaming
  , capMessage
  , maxTextChars
  , finiteDrive
  ) where

import           Control.Exception       (AsyncException (StackOverflow), ErrorCall (..), Exception (..),
                                          SomeAsyncException, SomeException (..), catch, evaluate, throwIO, try)
import           Data.Maybe              (isJust)
import           Data.Typeable           (typeOf)
import           GHC.IO                  (IO (..), unsafeDupablePerformIO)
import           Text.Printf             (printf)

import           AFRP                    (Time)
import           AFrob.Dimensions        (RobotId, RobotType)
import           AFrobRobotSim.Robot     (DriveCommand (..))
import           AFrobRobotSim.SpatialIndex (finite)

-- | A controller failed while the simulation ran: it threw an exception,
-- or gave a wheel command with a NaN or infinite speed.
--
-- 'show' and 'displayException' give the same sentence, which is what a
-- test framework prints for an uncaught one:
--
-- > the controller of SimbotA 1 failed at t = 2.500 s: Prelude.head: empty list
data ControllerError = ControllerError
  { ceRobotType :: RobotType
  , ceRobotId   :: RobotId
  , ceTime      :: Time
  , ceCause     :: SomeException
  }

-- | The sentence of 'displayException' (not a record: an uncaught
-- failure in a test reads as the run's message does), with no
-- parentheses whatever the precedence: @show (Just e)@ is
-- @Just the controller of ...@.
instance Show ControllerError where
  showsPrec _ e = showString (describe e)

instance Exception ControllerError where
  displayException = describe

describe :: ControllerError -> String
describe e = printf "the controller of %s %d failed at t = %.3f s: %s"
  (ceRobotType e) (ceRobotId e) (ceTime e) (displayException (ceCause e))

-- | A rule of the referee failed while the simulation ran: the ball rule
-- ('AFrobRobotSim.Simulator.simBallRule') or the scores
-- ('AFrobRobotSim.Simulator.simScores') threw an exception, or gave an
-- answer that cannot be (a ball lost or put outside the world, a score's
-- name twice). As for 'ControllerError', 'show' and 'displayException'
-- give the same sentence:
--
-- > the ball rule (simBallRule) failed at t = 1.000 s: it gave 1 position for 2 balls (it must give one for each)
data RefereeError = RefereeError
  { reRule  :: String          -- ^ which rule: @"the ball rule (simBallRule)"@ or @"the scores (simScores)"@
  , reTime  :: Time            -- ^ the time of the state it was given
  , reCause :: SomeException   -- ^ what it raised
  }

-- | The sentence of 'displayException', as for 'ControllerError'.
instance Show RefereeError where
  showsPrec _ e = showString (describeReferee e)

instance Exception RefereeError where
  displayException = describeReferee

describeReferee :: RefereeError -> String
describeReferee e = printf "%s failed at t = %.3f s: %s" (reRule e) (reTime e) (displayException (reCause e))

-- | Whether an exception is a run's failure, a 'ControllerError' or a
-- 'RefereeError': what stops a run with a message naming who failed and
-- when (the runner, "AFrobRobotSim.Run", and the testing kit's pages
-- sort exceptions by it).
isRunFailure :: SomeException -> Bool
isRunFailure e = isJust (fromException e :: Maybe ControllerError) || isJust (fromException e :: Maybe RefereeError)

-- | @blaming f v@ is @v@, with an exception that its evaluation raises
-- turned into @f e@ (a 'ControllerError' or a 'RefereeError'), unless it
-- is already a run's failure ('isRunFailure': a controller's, met by the
-- referee's rule reading the snapshot, say), which goes through as it is: 'Control.Exception.mapException', but leaving
-- asynchronous exceptions (Ctrl-C, a timeout, the heap's limit; not a
-- stack overflow, which is @v@'s) as they are, so that an
-- interrupted run is not reported as a failing controller; and without
-- 'unsafePerformIO''s guard against two threads evaluating @v@ at once
-- (a walk of the stack at every step of every robot), which a pure @v@
-- does not need.
--
-- The cause is kept as it was thrown when its text ('displayException')
-- is whole and at most 'maxTextChars' characters long; otherwise it
-- becomes an 'ErrorCall' of the text cut there, or saying that the text
-- itself failed: a cause whose message raises another exception, or never
-- ends, would fail (or hang) the run where its outputs are written,
-- without naming the robot.
blaming :: Exception e => (SomeException -> e) -> a -> a
blaming f v = unsafeDupablePerformIO (IO (\s -> case v of !r -> (# s, r #)) `catch` handler)
  where
    handler e = case fromException e of
      _ | isRunFailure e -> throwIO e
      -- (a stack overflow is raised where the controller's evaluation
      -- went too deep: its failure, as with +RTS -K)
      _ | Just StackOverflow <- fromException e -> throwIO (f e)
      Just (_ :: SomeAsyncException) -> throwIO e
      Nothing                        -> tameCause e >>= throwIO . f
{-# INLINE blaming #-}

-- A controller's exception whose text can be shown: see 'blaming'.
tameCause :: SomeException -> IO SomeException
tameCause e = do
  r <- try (evaluate (capText (displayException e)))
  case r of
    Right (_, False) -> pure e
    Right (txt, True) -> pure (toException (ErrorCall (txt ++ cutNote)))
    Left (e2 :: SomeException)
      | Just (_ :: SomeAsyncException) <- fromException e2 -> throwIO e2
      | otherwise -> pure (toException (ErrorCall ("an exception whose message itself failed ("
                                                   ++ takeWhile (/= ' ') (show (typeOfCause e)) ++ ")")))
  where
    typeOfCause (SomeException x) = typeOf x

-- | The longest console message, and the longest text of a controller's
-- exception, that a run keeps: 10,000 characters. A longer one is cut
-- there, with a note saying so (an endless one would fill the memory, the
-- log and the page).
maxTextChars :: Int
maxTextChars = 10000

-- A text's first 'maxTextChars' characters, every one evaluated, and
-- whether there were more. Evaluating it raises what the text raises in
-- those characters (or where the one after them is looked for).
capText :: String -> (String, Bool)
capText = go maxTextChars
  where
    go 0 rest     = case rest of
      [] -> ([], False)
      _  -> ([], True)
    go _ []       = ([], False)
    go k (c : cs) = case go (k - 1) cs of
      (t, more) -> c `seq` (c : t, more)

-- | A console message as the run keeps it: evaluated whole (whatever it
-- raises is raised here), and cut after 'maxTextChars' characters with a
-- note.
capMessage :: String -> String
capMessage m = case capText m of
  (t, False) -> t
  (t, True)  -> t ++ cutNote

cutNote :: String
cutNote = " ... (cut: longer than " ++ show maxTextChars ++ " characters)"

-- | The command evaluated, or an error if one of its speeds is NaN or
-- infinite: a controller that computes such a command (a division by
-- zero, say) has failed, and its run stops with a 'ControllerError' naming
-- the robot and the time, as for a controller that throws, rather than
-- drive on with the bad number taken for 0.
finiteDrive :: DriveCommand -> ()
finiteDrive c = case c of
  DriveBrake      -> ()
  DriveWheels l r -> both "ddVelDiff" "left and right wheel speeds" l r
  DriveTR v w     -> both "ddVelTR" "translational and rotational speeds" v w
  where
    -- (named by the notes' function that makes such a command, not by
    -- the constructor: "ddVelTR NaN 0.0 (translational and rotational
    -- speeds)")
    both name what a b
      | finite a && finite b = ()
      | otherwise = errorWithoutStackTrace ("its wheel command is not finite: " ++ name ++ " " ++ show a ++ " "
                                            ++ show b ++ " (" ++ what ++ ")")
