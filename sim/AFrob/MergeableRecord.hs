{-# OPTIONS_GHC -Wno-redundant-constraints #-}
-- The only constraint this disables the warning for is the one on
-- 'mrMerge': the notes fix its type as
-- @MergeableRecord a => MR a -> MR a -> MR a@, and user code is written
-- against that type, although merging two updates needs no default record.

-- |
-- Module      : AFrob.MergeableRecord
-- Description : Robot outputs built up field by field from mergeable updates.
--
-- A robot's output is a record with one field per actuator (wheel speeds,
-- console messages, ...). A controller rarely wants to set all of them in
-- one place: the drive logic sets the wheels, a monitor prints a message.
-- A /mergeable record/ lets each part describe just the fields it cares
-- about, as an update of type @'MR' o@, and merges the parts at the end:
--
-- > mrFinalize (ddVelDiff 1 1 `mrMerge` tcoPrintMessage (tag stuckE "Ouch!!"))
--
-- An output type @o@ takes part by
--
-- * being an instance of 'MergeableRecord': 'mrDefault' is the record with
--   every field unset (wheels braking, no messages, ...);
-- * offering setters, functions returning @'MR' o@ (normally the methods of
--   classes such as @HasDiffDrive@), each built with 'mrMake' from a
--   function that changes one field.
--
-- = Merging
--
-- @'mrMerge' l r@ applies @r@'s update and then @l@'s, so for a field that
-- both set, the /left/ operand wins. Fields that hold collections are the
-- exception by design: their setters /accumulate/ (a message setter
-- prepends its messages to those already there) instead of overwriting, so
-- both operands' entries are kept, the left operand's first. A setter for
-- such a field is written
--
-- > printMsgs :: [String] -> MR Out
-- > printMsgs ms = mrMake (\o -> o { outMsgs = ms ++ outMsgs o })
--
-- Merging is associative with the empty update as unit; '<>' and 'mempty'
-- of the 'Semigroup' and 'Monoid' instances are 'mrMerge' and the empty
-- update, so 'mconcat' merges a list with its head winning.
module AFrob.MergeableRecord
  ( -- * Mergeable records
    MergeableRecord (..)
    -- * Updates
  , MR
  , mrMake
  , mrMerge
  , mrFinalize
  ) where

-- | Record types that can be built up from partial updates ('MR').
class MergeableRecord a where
  -- | The record with every field unset: each field holds its neutral
  -- value (no motion requested, no messages, ...). 'mrFinalize' applies
  -- the merged updates to it.
  mrDefault :: a

-- | An update of a record of type @a@: a description of the fields some
-- part of a controller sets. Abstract: build with 'mrMake' (setters),
-- combine with 'mrMerge' (or '<>'), turn into a record with 'mrFinalize'.
newtype MR a = MR (a -> a)

-- | The update that applies the given function to the record. This is how
-- an output type defines its field setters; the function should change
-- only its own field, overwriting it for a plain field and adding to it
-- for a collection field (see the module header).
mrMake :: (a -> a) -> MR a
mrMake = MR
{-# INLINE mrMake #-}

-- | Merge two updates. @mrMerge l r@ applies @r@'s update first and then
-- @l@'s, so where both set the same plain field the /left/ one wins, and
-- in an accumulating field (messages) the left one's entries come first.
-- Associative, with the empty update ('mempty') as unit on both sides.
mrMerge :: MergeableRecord a => MR a -> MR a -> MR a
mrMerge (MR l) (MR r) = MR (l . r)
{-# INLINE mrMerge #-}

-- | The record described by an update: the update applied to 'mrDefault'.
-- Fields no part of the update sets keep their default. In particular
-- @mrFinalize mempty == mrDefault@.
mrFinalize :: MergeableRecord a => MR a -> a
mrFinalize (MR f) = f mrDefault
{-# INLINE mrFinalize #-}

-- | '<>' is 'mrMerge': the left operand wins.
instance Semigroup (MR a) where
  MR l <> MR r = MR (l . r)
  {-# INLINE (<>) #-}

-- | 'mempty' is the empty update: it sets no field.
instance Monoid (MR a) where
  mempty = MR id
  {-# INLINE mempty #-}
