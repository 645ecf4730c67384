-- |
-- Module      : AFrobRobotSim.WorldFile.Grammar
-- Description : The grammar of one line of a world file: its tokens parsed
--               into one object, or the column and reason of the rejection.
--
-- The middle layer of "AFrobRobotSim.WorldFile": between the tokens of a
-- line ("AFrobRobotSim.WorldFile.Lexical") and the file (line numbers, one
-- @size@ line, at most so many objects, the world checked), the @line@
-- rule of the format's grammar ('parseLine'), which sees one line's tokens
-- and nothing else. See "AFrobRobotSim.WorldFile" for the format.
--
-- The parser is a small state monad over the line's tokens, written out
-- rather than taken from a parser library: a line is a handful of tokens,
-- parsed without backtracking (its first keyword decides the rest; the one
-- optional part, a robot's heading, is decided by a look at the next
-- token), and each step keeps the token before it, so that every rejection
-- names what was expected, after which token, at which column.
module AFrobRobotSim.WorldFile.Grammar
  ( -- * One line
    parseLine
  , Failure (..)
    -- * Limits
  , maxHeading
  ) where

import           AFRP.Geometry     (Point2 (..))
import           AFrobRobotSim.World (ObjectTemplate (..), maxWorldSide, minWorldSide)
import           AFrobRobotSim.WorldFile.Lexical (Rejection (..), Tok (..), lower, quote, readNumber,
                                                  robotId, tokEnd, tokText)

------------------------------------------------------------------------------
-- Limits

-- | The largest magnitude of a heading's number, in degrees or radians:
-- 10^6. A heading within it is accepted (@heading 1000000 deg@ is), one
-- beyond it rejected as out of range; it keeps a heading finite and
-- still precise in radians.
maxHeading :: Double
maxHeading = 1e6

------------------------------------------------------------------------------
-- A small parser over the tokens of one line

-- | A rejected line: the column and the message, without the location.
--
-- The column is 1-based, in characters: where the offending token starts,
-- or, when a token is missing, just after the line's last token. The
-- message is
-- @expected WHAT [after \"PREVIOUS TOKEN\"], found \"TOKEN\"[ (NOTE)]@, or
-- @..., found end of line@; "AFrobRobotSim.WorldFile" puts
-- @FILE:LINE:COLUMN: @ before it, and also words the limits of a line
-- (its length, a NUL, a token's length) as a 'Failure'.
data Failure = Failure !Int String

-- | The parser state: the last token consumed (if any) and the rest.
data PState = PState (Maybe Tok) [Tok]

newtype P a = P (PState -> Either Failure (a, PState))

instance Functor P where
  fmap f (P p) = P $ \s -> case p s of
    Left e        -> Left e
    Right (a, s') -> Right (f a, s')

instance Applicative P where
  pure a = P $ \s -> Right (a, s)
  P pf <*> P pa = P $ \s -> case pf s of
    Left e        -> Left e
    Right (f, s') -> case pa s' of
      Left e         -> Left e
      Right (a, s'') -> Right (f a, s'')

instance Monad P where
  P p >>= k = P $ \s -> case p s of
    Left e        -> Left e
    Right (a, s') -> let P q = k a in q s'

-- | Consume the next token if the check accepts it; otherwise fail with
-- @expected WHAT after "PREV", found "TOKEN"@ (WHAT and a note from the
-- check), or @..., found end of line@ (WHAT from the first argument) when
-- there is no token left.
token :: String -> (String -> Either Rejection a) -> P a
token what check = P $ \(PState prev ts) -> case ts of
  [] -> Left (Failure (maybe 1 tokEnd prev) (expected what prev "end of line" ""))
  t : ts' -> case check (tokText t) of
    Right a -> Right (a, PState (Just t) ts')
    Left (Rejection what' note) ->
      Left (Failure (col t) (expected what' prev (quote (tokText t)) note))
  where
    col (Tok c _) = c

-- | The next token, if any, without consuming it.
peek :: P (Maybe String)
peek = P $ \s@(PState _ ts) -> Right (fmap tokText (safeHead ts), s)
  where
    safeHead (t : _) = Just t
    safeHead []      = Nothing

-- | The error message proper.
expected :: String -> Maybe Tok -> String -> String -> String
expected what prev found note =
  "expected " ++ what
  ++ maybe "" (\p -> " after " ++ quote (tokText p)) prev
  ++ ", found " ++ found ++ note

-- | One of the given keywords (case-insensitively), returning its value.
keywordOf :: String -> [(String, a)] -> P a
keywordOf what table = token what $ \t -> case lookup (lower t) table of
  Just a  -> Right a
  Nothing -> Left (Rejection what "")

-- | A single keyword.
keyword :: String -> P ()
keyword kw = keywordOf (quote kw) [(lower kw, ())]

-- | The end of the line (a comment may follow).
endOfLine :: String -> P ()
endOfLine what = P $ \s@(PState prev ts) -> case ts of
  []    -> Right ((), s)
  t : _ -> Left (Failure (col t) (expected what prev (quote (tokText t)) ""))
  where
    col (Tok c _) = c

------------------------------------------------------------------------------
-- The grammar

-- | Parse the tokens of one line: 'Nothing' for a line without tokens,
-- the object for a line of the grammar's @object@ or @size@ rule (a
-- @size@ line as an 'OTSize'), or the 'Failure' at the first token that
-- does not fit, or at the end of the line when it stops too soon. The
-- tokens are a line's ('AFrobRobotSim.WorldFile.Lexical.tokenize'), with
-- their columns; the columns of a 'Failure' are theirs. Whether a @size@
-- line comes twice, or a file holds too many objects, is the file's
-- business: each line is parsed on its own.
--
-- The tokens of @ball at 1 x@ give the 'Failure' at column 11
-- @expected a number after \"1\", found \"x\"@, those of @ball at 1@ the
-- one at column 10 @expected a number after \"1\", found end of line@.
parseLine :: [Tok] -> Either Failure (Maybe ObjectTemplate)
parseLine [] = Right Nothing
parseLine ts = case p (PState Nothing ts) of
  Left e       -> Left e
  Right (o, _) -> Right (Just o)
  where
    P p = object

data Kind = KSimbotA | KSimbotB | KWall | KBlock | KBall | KSize

object :: P ObjectTemplate
object = do
  k <- keywordOf "an object keyword (simbotA, simbotB, wall, block or ball) or size"
         [ ("simbota", KSimbotA), ("simbotb", KSimbotB), ("wall", KWall)
         , ("block", KBlock), ("ball", KBall), ("size", KSize) ]
  o <- case k of
    KSize    -> OTSize <$> side <*> side
    KSimbotA -> robot OTSimbotA
    KSimbotB -> robot OTSimbotB
    KWall    -> do
      mk <- keywordOf "a wall orientation (v, vertical, h or horizontal)"
              [ ("v", OTVWall), ("vertical", OTVWall)
              , ("h", OTHWall), ("horizontal", OTHWall) ]
      mk <$> position
    KBlock   -> OTBlock <$> position
    KBall    -> OTBall <$> position
  endOfLine "end of line or a comment"
  pure o

-- | @at X Y@.
position :: P (Point2 Double)
position = do
  keyword "at"
  Point2 <$> number <*> number

-- | The rest of a robot line, after its keyword.
robot :: (Int -> Point2 Double -> Double -> ObjectTemplate) -> P ObjectTemplate
robot mk = do
  i <- token "a robot id (an integer)" robotId
  p <- position
  next <- peek
  h <- case fmap lower next of
    Nothing        -> pure 0
    Just "heading" -> keyword "heading" >> heading
    Just _         -> endOfLine "\"heading\" or end of line" >> pure 0
  pure (mk i p h)

-- | @NUMBER unit@, in radians.
heading :: P Double
heading = do
  v <- token "a number" headingNumber
  f <- keywordOf "a heading unit (deg, degrees, rad or radians)"
         [ ("deg", degToRad), ("degrees", degToRad)
         , ("rad", id), ("radians", id) ]
  pure (f v)
  where
    degToRad d = d * pi / 180

number :: P Double
number = token "a number" readNumber

-- | A side of the world: a number from 'minWorldSide' to 'maxWorldSide'.
side :: P Double
side = token what $ \t -> case readNumber t of
  Right v
    | v < minWorldSide || v > maxWorldSide -> Left (Rejection what " (out of range)")
  r -> r
  where
    what = "a world side from " ++ metres minWorldSide ++ " to " ++ metres maxWorldSide ++ " metres"
    metres v = let n = round v :: Int
               in if fromIntegral n == v then show n else show v

-- | A heading's number: finite, and within +-'maxHeading'.
headingNumber :: String -> Either Rejection Double
headingNumber s = case readNumber s of
  Right v
    | abs v > maxHeading ->
        Left (Rejection ("a heading within +-" ++ show (round maxHeading :: Int)) " (out of range)")
  r -> r

