{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.JSON
-- Description : A small JSON value type, its encoder and its parser.
--
-- The run log and the replay page are JSON, and the library depends only
-- on GHC's own packages, so it reads and writes JSON itself. This module
-- knows nothing of robots: a value type, an encoder that writes RFC 8259
-- JSON, and a parser that reports where a text stops being JSON.
--
-- The value type and the encoder are "AFrobRobotSim.JSON.Encode", which
-- says what the encoder writes (its escapes, its numbers) and is
-- re-exported here whole; the parser of strings and the readers of values
-- are this module's own. The seam runs this way round, the encoder below
-- the parser, because a reader's error names a number by its JSON text
-- ('encodeNumber'). The parser of bytes ('parseJSONBytes', for a file's
-- lines: a log's line of 38 MB cost gigabytes as a 'String') is
-- "AFrobRobotSim.JSON.Bytes", re-exported here; it gives what 'parseJSON'
-- gives, value and error alike.
module AFrobRobotSim.JSON
  ( -- * Values and encoding
    module AFrobRobotSim.JSON.Encode
    -- * Parsing
  , parseJSON
  , cutShort
  , maxDepth
  , parseJSONBytes
  , cutShortBytes
  , parseJSONUtf8
  , cutShortUtf8
    -- * Reading values
  , member
  , memberMaybe
  , asNumber
  , asInt
  , asString
  , asBool
  , asArray
  ) where

import           Data.Char                  (chr, isDigit, isHexDigit, ord, digitToInt)
import           Data.List                  (foldl')

import           AFrobRobotSim.JSON.Bytes   (cutShortBytes, cutShortUtf8, lineColumn, maxDepth,
                                             parseJSONBytes, parseJSONUtf8, roundDigits, significantDigits)
import           AFrobRobotSim.JSON.Encode

-- A position in the text: line and column, both from 1.
data Pos = Pos !Int !Int
  deriving Eq

advance :: Pos -> Char -> Pos
advance (Pos l _) '\n' = Pos (l + 1) 1
advance (Pos l c) _    = Pos l (c + 1)

-- The parser's input: the position and the rest of the text.
data Input = Input !Pos String

newtype P a = P { runP :: Input -> Either (Pos, String) (a, Input) }

instance Functor P where
  fmap f (P p) = P (\i -> fmap (\(a, i') -> (f a, i')) (p i))

instance Applicative P where
  pure a = P (\i -> Right (a, i))
  P pf <*> P pa = P (\i -> case pf i of
    Left e        -> Left e
    Right (f, i') -> case pa i' of
      Left e         -> Left e
      Right (a, i'') -> Right (f a, i''))

instance Monad P where
  P p >>= k = P (\i -> case p i of
    Left e        -> Left e
    Right (a, i') -> runP (k a) i')

failHere :: String -> P a
failHere msg = P (\(Input pos _) -> Left (pos, msg))

peek :: P (Maybe Char)
peek = P (\i@(Input _ s) -> Right (case s of { c : _ -> Just c; [] -> Nothing }, i))

next :: P Char
next = P (\(Input pos s) -> case s of
  c : rest -> Right (c, Input (advance pos c) rest)
  []       -> Left (pos, "unexpected end of input"))

skipSpace :: P ()
skipSpace = P (\(Input pos s) -> let go p (c : r) | c `elem` " \t\r\n" = go (advance p c) r
                                     go p r = Input p r
                                 in Right ((), go pos s))

-- What the next character is, for messages.
describeNext :: Maybe Char -> String
describeNext Nothing  = "end of input"
describeNext (Just c) = show c

expect :: Char -> P ()
expect c = do
  m <- peek
  if m == Just c then () <$ next
    else failHere ("expected " ++ show c ++ ", found " ++ describeNext m)

-- | Parse a JSON text (one value, with optional whitespace around it).
-- An error says where, as @line L, column C: what was expected@; a
-- @null@ stays 'JNull' (the readers of this library take it, in a place
-- of a number, for a non-finite number).
parseJSON :: String -> Either String JSON
parseJSON txt = case runP (skipSpace *> value 0 <* skipSpace <* end) (Input (Pos 1 1) txt) of
  Left (Pos l c, msg) -> Left (lineColumn l c msg)
  Right (v, _)        -> Right v
  where
    end = peek >>= \m -> case m of
      Nothing -> pure ()
      Just _  -> failHere ("expected the end of the text, found " ++ describeNext m)

-- | Whether a text is JSON cut short: not JSON, and only because it
-- ends too soon (the parser's first fault is at the text's end, where a
-- value, a string or a name is still open). Every proper prefix of a JSON
-- object or array is; a whole value is not, nor is a text with a fault
-- before its end (a misspelt keyword, a character out of place), nor one
-- with something after a whole value.
--
-- > cutShort "{\"a\": [1, 2"   == True
-- > cutShort "{\"a\": 1}"      == False
-- > cutShort "{\"a\" 1}"       == False   -- (a fault at the 1)
cutShort :: String -> Bool
cutShort txt = case runP (skipSpace *> value 0) (Input (Pos 1 1) txt) of
  Left (pos, _) -> pos == foldl' advance (Pos 1 1) txt
  Right _       -> False

value :: Int -> P JSON
value depth = do
  m <- peek
  case m of
    Just '{' -> nested (JObject <$> (next *> skipSpace *> members))
    Just '[' -> nested (JArray <$> (next *> skipSpace *> elements))
    Just '"' -> JString <$> stringLit
    Just 't' -> JBool True <$ keyword "true"
    Just 'f' -> JBool False <$ keyword "false"
    Just 'n' -> JNull <$ keyword "null"
    Just c | c == '-' || isDigit c -> JNumber <$> number
    _ -> failHere ("expected a JSON value, found " ++ describeNext m)
  where
    nested p | depth >= maxDepth = failHere ("nested more than " ++ show maxDepth ++ " deep")
             | otherwise         = p
    members = peek >>= \m -> case m of
      Just '}' -> [] <$ next
      _        -> let one = do
                        k <- skipSpace *> (peek >>= \q -> if q == Just '"' then stringLit
                                             else failHere ("expected a member name (a string), found "
                                                            ++ describeNext q))
                        skipSpace *> expect ':' *> skipSpace
                        x <- value (depth + 1)
                        skipSpace
                        pure (k, x)
                      more = peek >>= \q -> case q of
                        Just ',' -> next *> ((:) <$> one <*> more)
                        Just '}' -> [] <$ next
                        _        -> failHere ("expected ',' or '}', found " ++ describeNext q)
                  in (:) <$> one <*> more
    elements = peek >>= \m -> case m of
      Just ']' -> [] <$ next
      _        -> let one = skipSpace *> value (depth + 1) <* skipSpace
                      more = peek >>= \q -> case q of
                        Just ',' -> next *> ((:) <$> one <*> more)
                        Just ']' -> [] <$ next
                        _        -> failHere ("expected ',' or ']', found " ++ describeNext q)
                  in (:) <$> one <*> more

keyword :: String -> P ()
keyword w = mapM_ (\c -> peek >>= \m -> if m == Just c then () <$ next
                                        else failHere ("expected " ++ show w ++ ", found " ++ describeNext m)) w

number :: P Double
number = do
  start <- P (\i@(Input pos _) -> Right (pos, i))
  sign <- optionalChar '-'
  int  <- digits1 "a digit"
  case int of
    '0' : _ : _ -> P (\_ -> Left (start, "a number may not have a leading zero"))
    _           -> pure ()
  frac <- peek >>= \m -> if m == Just '.' then next *> digits1 "a digit after '.'" else pure ""
  ex   <- peek >>= \m -> if m == Just 'e' || m == Just 'E'
            then do
              _ <- next
              s <- peek >>= \q -> if q == Just '+' || q == Just '-' then (: []) <$> next else pure ""
              ds <- digits1 "a digit in the exponent"
              pure (exponentOf (s == "-") ds)
            else pure 0
  -- (made now: a number left to make later holds its digits, several
  -- times the Double's size)
  let !x = decimal (not (null sign)) int frac ex
  pure x
  where
    optionalChar c = peek >>= \m -> if m == Just c then (: []) <$> next else pure ""
    digits1 what = do
      m <- peek
      case m of
        Just c | isDigit c -> manyDigits
        _ -> failHere ("expected " ++ what ++ ", found " ++ describeNext m)
    -- (a run of digits, taken in one step: no line break is among them)
    manyDigits = P (\(Input (Pos l c) s) -> case span isDigit s of
                     (ds, rest) -> let !n = length ds in Right (ds, Input (Pos l (c + n)) rest))
    -- (an exponent of more than 15 digits, beyond the count of digits
    -- any text holds, is taken as 10^15: the number is an infinity or
    -- zero all the same)
    exponentOf negative ds = let ds' = dropWhile (== '0') ds
                                 e = if length ds' > 15 then 10 ^ (15 :: Int) else if null ds' then 0 else read ds'
                             in if negative then negate e else e :: Int

-- | @decimal negative int frac e@: the number @int.frac@ times @10^e@
-- (digits, as JSON writes them), negated if @negative@, rounded to the
-- nearest 'Double' as 'read' rounds it ('roundDigits', of the first
-- 'significantDigits' significant digits and whether one after them is
-- not zero: 'read' of a million digits takes half a minute, and the rest
-- cannot change how it rounds).
decimal :: Bool -> String -> String -> Int -> Double
decimal negative int frac e =
  let (kept, dropped) = splitAt significantDigits (dropWhile (== '0') (int ++ frac))
  in roundDigits negative kept (length dropped) (any (/= '0') dropped) (e - length frac)

stringLit :: P String
stringLit = expect '"' *> P (scan [])
  where
    -- (the characters so far, last first: a loop that does not deepen
    -- the stack with the string's length)
    scan !acc (Input pos s) = case s of
      '"' : rest  -> Right (reverse acc, Input (advance pos '"') rest)
      '\\' : rest -> case runP escape (Input (advance pos '\\') rest) of
        Left err      -> Left err
        Right (c, i') -> scan (c : acc) i'
      c : rest
        | ord c < 0x20 -> Left (pos, "a control character (code " ++ show (ord c) ++ ") must be escaped in a string")
        | otherwise    -> scan (c : acc) (Input (advance pos c) rest)
      []          -> Left (pos, "unexpected end of input")
    -- report a character just consumed at its own column
    backOne msg = P (\(Input (Pos l col) _) -> Left (Pos l (col - 1), msg))
    escape = next >>= \c -> case c of
      '"'  -> pure '"'
      '\\' -> pure '\\'
      '/'  -> pure '/'
      'b'  -> pure '\b'
      'f'  -> pure '\f'
      'n'  -> pure '\n'
      'r'  -> pure '\r'
      't'  -> pure '\t'
      'u'  -> hex4 >>= \h ->
        if h >= 0xD800 && h <= 0xDBFF
          then lowSurrogate h
          else pure (chr h)
      _    -> backOne ("unknown escape \\" ++ [c])
    lowSurrogate h = P (\i@(Input _ s) -> case s of
      '\\' : 'u' : _ -> case runP (next *> next *> hex4) i of
        Right (l, i') | l >= 0xDC00 && l <= 0xDFFF ->
          Right (chr (0x10000 + (h - 0xD800) * 0x400 + (l - 0xDC00)), i')
        _ -> Right (chr h, i)
      _ -> Right (chr h, i))
    hex4 = do
      ds <- sequence (replicate 4 (peek >>= \m -> case m of
              Just d | isHexDigit d -> next
              _ -> failHere ("expected four hex digits after \\u, found " ++ describeNext m)))
      pure (foldl (\a d -> a * 16 + digitToInt d) 0 ds)

-- | The value of an object's member (the first of that name), or an error
-- naming the member.
member :: String -> JSON -> Either String JSON
member k (JObject kvs) = maybe (Left ("missing field " ++ show k)) Right (lookup k kvs)
member k _             = Left ("expected an object with field " ++ show k)

-- | The value of an object's member, 'Nothing' when it is absent or
-- @null@.
memberMaybe :: String -> JSON -> Either String (Maybe JSON)
memberMaybe k (JObject kvs) = Right (case lookup k kvs of
                                       Just JNull -> Nothing
                                       other      -> other)
memberMaybe k _             = Left ("expected an object with field " ++ show k)

-- | A number; @null@ reads as NaN (how the encoder writes a non-finite
-- number).
asNumber :: JSON -> Either String Double
asNumber (JNumber x) = Right x
asNumber JNull       = Right (0 / 0)
asNumber v           = Left ("expected a number, found " ++ kind v)

-- | An integral number.
asInt :: JSON -> Either String Int
asInt (JNumber x) | x == fromIntegral (round x :: Int) = Right (round x)
asInt v = Left ("expected an integer, found " ++ kind v)

-- | A string.
asString :: JSON -> Either String String
asString (JString s) = Right s
asString v           = Left ("expected a string, found " ++ kind v)

-- | A Boolean.
asBool :: JSON -> Either String Bool
asBool (JBool b) = Right b
asBool v         = Left ("expected true or false, found " ++ kind v)

-- | An array's elements.
asArray :: JSON -> Either String [JSON]
asArray (JArray xs) = Right xs
asArray v           = Left ("expected an array, found " ++ kind v)

kind :: JSON -> String
kind v = case v of
  JNull     -> "null"
  JBool _   -> "a Boolean"
  JNumber x -> "the number " ++ encodeNumber x
  JString _ -> "a string"
  JArray _  -> "an array"
  JObject _ -> "an object"
