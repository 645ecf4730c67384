{-# LANGUAGE UnboxedTuples #-}
-- |
-- Module      : AFRP.EventSource.Reshape
-- Description : Event streams reshaped: the first occurrences let
--               through or held back.
--
-- Part of "AFRP.EventSource". Each of these passes on (some of) the
-- occurrences of its input, unchanged, counted from its own start.
module AFRP.EventSource.Reshape
  ( notYet
  , once
  , takeEvents
  , dropEvents
  ) where

import           AFRP.Event
import           AFRP.EventSource.Timed (never)
import           AFRP.Internal.SF

-- | Suppress an occurrence at time 0; pass all later ones through.
notYet :: SF (Event a) (Event a)
notYet = SF (initN (\_ -> (# idN, NoEvent #)))

-- | Only the first occurrence passes: @once = takeEvents 1@. An
-- occurrence at time 0 is the first (it passes), as in Yampa.
once :: SF (Event a) (Event a)
once = takeEvents 1

-- | Let the first @n@ occurrences through, then none (the source then
-- becomes 'never' and can disappear from the network); an occurrence at
-- time 0 counts as the first. For @n <= 0@ it is 'never' from the start,
-- as in Yampa.
takeEvents :: Int -> SF (Event a) (Event a)
takeEvents n0 = SF (lazyN (go n0))
  where
    go n | n <= 0    = sfNode never
         | otherwise = NStep (\_ e -> case e of
             NoEvent -> (# go n, NoEvent #)
             Event _ -> (# go (n - 1), e #))

-- | Suppress the first @n@ occurrences, then let all through; an
-- occurrence at time 0 is the first suppressed. For @n <= 0@ it lets
-- every occurrence through, as in Yampa.
--
-- Until the @n@-th occurrence has passed, the output is 'NoEvent' whatever
-- the input: whether a sample is an occurrence is looked at in the next
-- step, as Yampa's (a decoupled switch) looks at it. So an input sample
-- there that is an error (bottom) fails the next sample, not its own
-- output, as in Yampa 0.15.
dropEvents :: Int -> SF (Event a) (Event a)
dropEvents n0 = SF (go n0)
  where
    go n | n <= 0    = idN
         | otherwise = NStep (\_ e -> (# counted n e, NoEvent #))
    -- (the sample @e@ counted, at the start of the next step)
    counted n e = NStep (\dt e' -> case e of
      NoEvent -> stepN (go n) dt e'
      Event _ -> stepN (go (n - 1)) dt e')
