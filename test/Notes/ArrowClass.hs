-- | The notes' section 2.2 presents Hughes's 'Arrow' class; here it is,
-- verbatim, compiled on its own (it would clash with "Control.Arrow"
-- anywhere else). "AFRP" re-exports the real class from "Control.Arrow".
module Notes.ArrowClass (Arrow (..), firstfun) where

class Arrow a where
  arr    :: (b -> c) -> a b c
  (>>>) :: a b c -> a c d -> a b d
  first :: a b c -> a (b,d) (c,d)

firstfun :: (t -> a) -> (t, b) -> (a, b)
firstfun f = \ (x,y) -> (f x, y)
