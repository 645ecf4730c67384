{-# LANGUAGE BangPatterns #-}
-- |
-- Module      : AFrobRobotSim.WorldFile
-- Description : A plain-text file format for world templates: parser,
--               printer and file reader.
--
-- A world file describes a 'WorldTemplate' as plain text, one object per
-- line, for example:
--
-- @
-- # A small arena, 12 m by 8 m: [-6, 6] x [-4, 4], walled in on all sides.
-- size 12 8                  # without a size line: 10 by 10, [-5, 5] x [-5, 5]
-- wall v at 0 3              # a vertical wall segment centred on (0, 3)
-- wall h at -1 2.5           # a horizontal one centred on (-1, 2.5)
-- block at 2 -2
-- ball  at 0 0
-- simbotA 1 at -2.0 -2.0 heading 45 deg
-- simbotB 2 at 1 1 heading 1.5708 rad
-- SIMBOTB 3 at 3 3           # no heading: facing +x (heading 0)
-- @
--
-- = Lines, tokens and comments
--
-- * A file is split into lines at each @\\n@, @\\r\\n@ or lone @\\r@, so
--   Unix, Windows (CRLF) and classic Mac line ends are all read. Lines are
--   numbered from 1. (Only the position of an invalid UTF-8 byte is
--   counted in @\\n@ lines, as in every other file the simulator reads.)
--   A UTF-8 byte order mark at the start of the file is ignored.
--
-- * Limits, so that any file is read in time linear in its size: a line
--   has at most 'maxLineLength' (4096) characters, a token at most
--   'maxTokenLength' (100); a file describes at most 'maxObjects' (100,000)
--   objects, and 'readWorldFile' reads at most 'maxFileBytes' (16 MiB). A NUL character anywhere is an error (the file
--   is probably not text). A file read with 'readWorldFile' or
--   'readWorldBytes' must be valid UTF-8; the first invalid byte is
--   reported with its line and column.
--
-- * A @#@ starts a comment, which runs to the end of the line; it may
--   appear anywhere, also right after a token (@ball at 0 0# centre@).
--
-- * What is left of a line is split into tokens at whitespace (spaces,
--   tabs, ...); tokens must be separated by whitespace (@at0@ is one
--   token, not @at 0@). A line without tokens (blank, or only a comment)
--   is ignored; every other line describes exactly one object, or the
--   world's size.
--
-- * Keywords (@size@, @simbotA@, @simbotB@, @wall@, @v@, @h@, @block@,
--   @ball@, @at@, @heading@ and the units) are case-insensitive: @SimbotA@,
--   @SIMBOTA@ and @simbota@ are the same keyword.
--
-- = Grammar
--
-- @
-- line    ::= [ object | size ] [ comment ]
-- size    ::= \"size\" NUMBER NUMBER                          (at most one per file)
-- object  ::= robot | wall | block | ball
-- robot   ::= ( \"simbotA\" | \"simbotB\" ) ID \"at\" NUMBER NUMBER [ heading ]
-- heading ::= \"heading\" NUMBER unit
-- unit    ::= \"deg\" | \"degrees\" | \"rad\" | \"radians\"
-- wall    ::= \"wall\" ( \"v\" | \"vertical\" | \"h\" | \"horizontal\" ) \"at\" NUMBER NUMBER
-- block   ::= \"block\" \"at\" NUMBER NUMBER
-- ball    ::= \"ball\" \"at\" NUMBER NUMBER
-- comment ::= \"#\" any characters up to the end of the line
--
-- ID      ::= [ \"+\" | \"-\" ] DIGITS    (must fit in an Int; a world runs with ids from -2^53 to 2^53)
-- NUMBER  ::= [ \"+\" | \"-\" ] DIGITS [ \".\" DIGITS ] [ ( \"e\" | \"E\" ) [ \"+\" | \"-\" ] DIGITS ]
-- DIGITS  ::= one or more of 0-9
-- @
--
-- Each line is parsed on its own, by "AFrobRobotSim.WorldFile.Grammar";
-- the line numbers and the rules of a whole file (at most one @size@ line,
-- at most 'maxObjects' objects) are this module's.
--
-- The two numbers after @at@ are the x and y coordinates of the object's
-- centre, in metres. The objects and their sizes are those of
-- "AFrobRobotSim.World": @wall v@ is an 'OTVWall', @wall h@ an 'OTHWall',
-- @block@ an 'OTBlock', @ball@ an 'OTBall', @simbotA@ \/ @simbotB@ an
-- 'OTSimbotA' \/ 'OTSimbotB' with the given robot id.
--
-- == The world's size
--
-- @size W H@ makes the world @W@ metres wide (along x) and @H@ metres
-- tall (along y), centred on the origin: @[-W\/2, W\/2] x [-H\/2, H\/2]@,
-- walled in on all four sides. It is an 'OTSize' in the template. Without
-- a @size@ line the world is the notes' 10 by 10
-- ('AFrobRobotSim.World.notesBounds'). A file has at most one @size@
-- line, anywhere in it (the objects are checked against it wherever it
-- stands); each side is a number from 'AFrobRobotSim.World.minWorldSide'
-- (1) to 'AFrobRobotSim.World.maxWorldSide' (1000) metres. The frames,
-- the SVG and the replay page of a run picture the whole world, at a
-- default scale that keeps them about 600 pixels on the long side
-- (see "AFrobRobotSim.Options").
--
-- == Numbers
--
-- Numbers are decimal: an optional sign, digits, an optional fraction and
-- an optional exponent, e.g. @-2@, @+0.5@, @3.0@, @1e-3@, @-2.5E+2@.
-- Rejected are a missing integer part or fraction (@.5@, @5.@), hex and
-- other bases, underscores, and the non-finite literals @NaN@, @Infinity@
-- and @inf@ (in any case, with or without a sign). A literal whose value
-- is too large for a 'Double' (e.g. @1e400@) is an error as well; one too
-- small to be represented rounds to zero, as usual. Every other literal is
-- converted to the nearest 'Double' (ties to even), so the output of
-- 'show' is read back exactly.
--
-- == Headings
--
-- A heading is an absolute direction, 0 along +x, growing
-- counter-clockwise (see "AFrob.Dimensions"). Its unit is mandatory, so
-- degrees and radians are never confused: @heading 90 deg@ and
-- @heading 1.5707963267948966 rad@ both face +y. The number must lie
-- within +-'maxHeading' (10^6) in its unit, so that it is finite and still
-- precise in radians. Degrees are converted
-- with @d * pi / 180@. Headings are /not/ normalised: @heading 450 deg@
-- is stored as @5 * pi / 2@. The whole @heading@ clause may be omitted;
-- the robot then faces +x (heading 0).
--
-- = Errors
--
-- 'parseWorld' reports every malformed line (up to
-- 'AFrobRobotSim.World.Check.maxProblems' of them; one more stops the
-- reading, and a last line says from where), each as
--
-- @
-- FILE:LINE:COLUMN: expected WHAT [after \"PREVIOUS TOKEN\"], found \"TOKEN\"
-- @
--
-- for instance @w.world:3:15: expected a number after \"at\", found \"x1\"@.
-- COLUMN is the 1-based column (in characters; a tab counts as one) where
-- the offending token starts; when a token is missing, it is the column
-- just after the preceding token, and the message says
-- @found end of line@. Nothing is returned for the lines that are right.
-- The limits give messages of the same shape:
--
-- @
-- FILE:LINE:4097: line longer than 4096 characters
-- FILE:LINE:COLUMN: token longer than 100 characters, starting \"...\"
-- FILE:LINE:COLUMN: found a NUL character (is this a text file?)
-- FILE:LINE:COLUMN: invalid UTF-8 (byte 0xff)
-- FILE:LINE: too many objects (at most 100000)
-- FILE:LINE: the world's size is given twice (first on line N)
-- @
--
-- A side of @size@ out of range is reported like any other bad token:
-- @w.world:1:6: expected a world side from 1 to 1000 metres after \"size\", found \"0\" (out of range)@.
--
-- Characters that cannot be printed are shown escaped in messages (as
-- Haskell writes them, @\\NUL@, @\\ESC@, ...), so a message never sends
-- control codes to a terminal.
--
-- 'parseWorld' checks the syntax only. 'readWorldFile' and
-- 'readWorldBytes' also check the world with
-- 'AFrobRobotSim.World.Check.validateWorld' (objects inside the world, ids
-- unique, nothing overlapping at time 0, the balls' discs no larger in
-- all than the floor the robots leave), each problem reported as
-- @FILE:LINE: ...@ with the lines of the objects involved.
--
-- = Printing
--
-- 'renderWorld' writes a header comment and then one object per line, in
-- the order of the template, coordinates and headings printed with 'show'
-- and headings in radians, so that
-- @'parseWorld' f ('renderWorld' w) == 'Right' w@ for every world whose
-- coordinates are finite and whose headings lie within +-'maxHeading',
-- with at most one size (each side from 1 to 1000 metres) and at most
-- 'maxObjects' objects: what a world file can say.
module AFrobRobotSim.WorldFile
  ( -- * Parsing
    parseWorld
  , readWorldBytes
  , readWorldFile
    -- * Limits
  , maxLineLength
  , maxTokenLength
  , maxHeading
  , maxObjects
  , maxFileBytes
    -- * Printing
  , renderWorld
  ) where

import qualified Data.ByteString   as B
import           Data.List         (intercalate)
import qualified Data.Map.Strict   as M

import           AFRP.Geometry     (Point2 (..))
import           AFrobRobotSim.World (ObjectTemplate (..), WorldTemplate, isWorldSize, notesBounds)
import           AFrobRobotSim.World.Check (capProblems, maxProblems, worldProblems)
import           AFrobRobotSim.Console          (displayPath)
import           AFrobRobotSim.WorldFile.Grammar (Failure (..), maxHeading, parseLine)
import           AFrobRobotSim.InputFile (readFileUpTo)
import           AFrobRobotSim.WorldFile.Lexical

------------------------------------------------------------------------------
-- Public interface

-- | Parse the text of a world file (see the module documentation for the
-- format). The first argument is the file name, used only in error
-- messages.
--
-- On success, the objects in the order of their lines. Otherwise a
-- message for every malformed line, one a line,
-- @FILE:LINE:COLUMN: expected ..., found ...@, and nothing else: the
-- first 'AFrobRobotSim.World.Check.maxProblems' (20); one more ends the
-- reading, said in a last line (@... and more problems from line L on@).
-- A file of more than 'maxObjects' objects stops at the first object too
-- many, said after the faults before it.
--
-- >>> parseWorld "w.world" "ball at 0 0\nsimbotA 1 at 1 2 heading 90 deg\n"
-- Right [OTBall {otPos = Point2 0.0 0.0},OTSimbotA {otRId = 1, otPos = Point2 1.0 2.0, otHdng = 1.5707963267948966}]
--
-- >>> parseWorld "w.world" "\n\nwall v at x1 2"
-- Left "w.world:3:11: expected a number after \"at\", found \"x1\""
parseWorld :: FilePath -> String -> Either String WorldTemplate
parseWorld file = fmap (map snd) . parseNumbered file

-- | 'parseWorld', each object with its line number.
parseNumbered :: FilePath -> String -> Either String [(Int, ObjectTemplate)]
parseNumbered name = go (0 :: Int) Nothing [] (Faults []) . numberedFrom 1 . textLines . dropBom
  where
    -- lines ended by \n, \r\n or a lone \r (a file with no line end at
    -- all is one line; a final line end does not start another)
    textLines t = case break (\ch -> ch == '\n' || ch == '\r') t of
      (l, [])                 -> [l | not (null l)]
      (l, '\r' : '\n' : rest) -> l : textLines rest
      (l, _ : rest)           -> l : textLines rest
    -- (numbered by a counter, not zipped with @[1 ..]@: that list, a
    -- constant, was floated out as a top-level value, which kept a cell
    -- for every line of the largest file read so far for as long as the
    -- program could parse another: 315 MB of heap (771 MB of memory in
    -- all) after a file of 8 million comment lines)
    numberedFrom :: Int -> [String] -> [(Int, String)]
    numberedFrom !n (l : ls) = (n, l) : numberedFrom (n + 1) ls
    numberedFrom _ []        = []
    file = displayPath name   -- (control characters escaped in messages)
    dropBom ('\xFEFF' : r) = r
    dropBom r              = r
    -- k objects so far; the line of the size, if one was given; the
    -- faults so far (at most 'maxProblems', last first)
    go _ _ acc (Faults []) [] = Right (reverse acc)
    go _ _ _ faults [] = Left (faultsText faults [])
    go _ _ _ faults@Stopped {} _ = Left (faultsText faults [])
    go k sizeLine acc faults ((n, l) : ls) = case checkLine l >>= parseLine of
      Right Nothing  -> go k sizeLine acc faults ls
      Right (Just o@OTSize {}) -> case sizeLine of
        Just first -> go k sizeLine acc (faults `with` (file ++ ":" ++ show n ++ ": the world's size is given twice (first on line "
                                                        ++ show first ++ ")")) ls
        Nothing    -> go k (Just n) ((n, o) : acc) faults ls
      Right (Just o)
        | k >= maxObjects -> Left (faultsText faults [file ++ ":" ++ show n ++ ": too many objects (at most "
                                                      ++ show maxObjects ++ ")"])
        | otherwise       -> go (k + 1) sizeLine ((n, o) : acc) faults ls
      Left (Failure col msg) ->
        go k sizeLine acc (faults `with` (file ++ ":" ++ show n ++ ":" ++ show col ++ ": " ++ msg)) ls
      where
        -- (one fault more than 'maxProblems' ends the reading: the rest
        -- of a file of millions of bad lines is not read)
        with (Faults shown) msg
          | length shown < maxProblems = Faults (msg : shown)
          | otherwise                  = Stopped shown n
        with stopped _ = stopped
    -- (a last message, the reason the reading stopped, after the faults)
    faultsText (Faults shown) final = intercalate "\n" (reverse shown ++ final)
    faultsText (Stopped shown n) final =
      intercalate "\n" (reverse shown ++ final ++ ["... and more problems from line " ++ show n
                                                  ++ " on (the reading stopped there)"])

-- The faults of a world file's lines so far: at most 'maxProblems'
-- messages (the last first); or, once one more is found, those and the
-- line where it was, which ends the reading.
data Faults = Faults [String] | Stopped [String] !Int

-- | The most objects a world file may describe: 100,000 (the notes' world
-- holds about 1100 balls, or 400 blocks, side by side; the benchmarks'
-- 316 m world holds 10,000 robots and 7,938 obstacles, 1.2 MB as
-- 'renderWorld' writes it). However
-- many objects it has, a world whose objects crowd together is refused
-- by 'AFrobRobotSim.World.Check.maxClosePairs', which bounds the time its check
-- takes. The @size@ line is not an object.
maxObjects :: Int
maxObjects = 100000

-- | The longest line accepted, in characters: 4096.
maxLineLength :: Int
maxLineLength = 4096

-- | The longest token accepted, in characters: 100 (the longest number
-- 'renderWorld' writes has 24).
maxTokenLength :: Int
maxTokenLength = 100

-- | The limits on a line: no NUL, at most 'maxLineLength' characters,
-- tokens of at most 'maxTokenLength'; its tokens if it keeps them.
checkLine :: String -> Either Failure [Tok]
checkLine l = case [ c | (c, ch) <- zip [1 ..] (take (maxLineLength + 1) l), ch == '\NUL' ] of
  c : _ -> Left (Failure c "found a NUL character (is this a text file?)")
  []
    | not (null (drop maxLineLength l)) ->
        Left (Failure (maxLineLength + 1) ("line longer than " ++ show maxLineLength ++ " characters"))
    | otherwise -> case [ t | t@(Tok _ s) <- ts, length s > maxTokenLength ] of
        Tok c s : _ -> Left (Failure c ("token longer than " ++ show maxTokenLength
                                        ++ " characters, starting " ++ quote (take 20 s)))
        []          -> Right ts
  where
    ts = tokenize l

-- | Decode the bytes of a world file as UTF-8, parse them with
-- 'parseWorld' and check the world with
-- 'AFrobRobotSim.World.Check.validateWorld', naming each
-- object's line. The first byte that is not valid UTF-8 (a stray
-- continuation byte, a truncated or overlong sequence, a surrogate, a code
-- point beyond U+10FFFF) is an error
-- @FILE:LINE:COLUMN: invalid UTF-8 (byte 0xNN)@, its column counted in the
-- characters before it on its line, plus one. The problems of an invalid
-- world come one per line, each as @FILE:LINE: problem@ (the line of the
-- later object of a pair, whose message names the other's line), at most
-- 'AFrobRobotSim.World.Check.maxProblems' of them and then a count of the rest.
--
-- >>> readWorldBytes "w.world" (B.pack [98,97,108,108,32,97,116,32,48,32,255])
-- Left "w.world:1:11: invalid UTF-8 (byte 0xff)"
--
-- The file @block at 0 0@, @simbotA 1 at 0.1 0@ (two lines) gives
--
-- @
-- w.world:2: SimbotA 1 at (0.1, 0.0) overlaps block at (0.0, 0.0) (line 1)
-- @
readWorldBytes :: FilePath -> B.ByteString -> Either String WorldTemplate
readWorldBytes name bytes =
  utf8Text file bytes >>= parseNumbered name >>= check   -- (parseNumbered displays the name itself)
  where
    file = displayPath name   -- (control characters escaped in messages)
    check numbered =
      let lineOf = M.fromList (zip [0 :: Int ..] (map fst numbered))
          labelled = [ (" (line " ++ show n ++ ")", o) | (n, o) <- numbered ]
          located = [ file ++ ":" ++ show (M.findWithDefault 0 i lineOf) ++ ": " ++ msg
                    | (i, msg) <- worldProblems notesBounds labelled ]
      in case capProblems located of
           [] -> Right (map snd numbered)
           ps -> Left (intercalate "\n" ps)

-- | Read, parse and check a world file ('readWorldBytes'). A file that cannot be
-- read (missing, no permission, a directory, ...) gives 'Left' with the
-- operating system's message rather than throwing an exception; a
-- malformed file gives 'Left' with the message of 'readWorldBytes'. At
-- most 'maxFileBytes' are read: a longer file (or an endless one, such as
-- @\/dev\/zero@) gives @FILE: more than N bytes (is this a world file?)@.
readWorldFile :: FilePath -> IO (Either String WorldTemplate)
readWorldFile path = do
  r <- readFileUpTo maxFileBytes path
  pure $ case r of
    Left e         -> Left (cannotRead path e)
    Right Nothing  -> Left (displayPath path ++ ": more than " ++ show maxFileBytes ++ " bytes (is this a world file?)")
    Right (Just s) -> readWorldBytes path s

-- | The longest file 'readWorldFile' reads, in bytes: 16 MiB ('renderWorld'
-- writes 'maxObjects' objects in at most about 11 MB).
maxFileBytes :: Int
maxFileBytes = 16 * 1024 * 1024

-- | Print a world in the world-file format: a header comment, then one
-- line per object, in order. Coordinates are printed with 'show', headings
-- in radians with 'show' followed by @rad@, so that
-- @'parseWorld' f ('renderWorld' w) == 'Right' w@ whenever all coordinates
-- of @w@ are finite and its headings lie within +-'maxHeading' (a NaN, an
-- infinity or a larger heading is printed, but does not parse back), and
-- it has at most one size, each side from 1 to 1000 metres, and at most
-- 'maxObjects' objects (a world beyond those limits is printed, and its
-- file refused with the line that passes them).
--
-- >>> putStr (renderWorld [OTVWall (Point2 0 3), OTSimbotB 2 (Point2 1 (-1)) 0.5])
-- # afrp world file: 2 objects (positions in metres, headings in radians)
-- wall v at 0.0 3.0
-- simbotB 2 at 1.0 -1.0 heading 0.5 rad
renderWorld :: WorldTemplate -> String
renderWorld w = unlines (header : map renderObject w)
  where
    k = length [ () | o <- w, not (isWorldSize o) ]
    header = "# afrp world file: " ++ show k ++ " object"
             ++ (if k == 1 then "" else "s")
             ++ " (positions in metres, headings in radians)"

-- | One object as one line (without the newline).
renderObject :: ObjectTemplate -> String
renderObject o = case o of
  OTBlock p         -> "block" ++ at p
  OTVWall p         -> "wall v" ++ at p
  OTHWall p         -> "wall h" ++ at p
  OTBall p          -> "ball" ++ at p
  OTSimbotA i p hd  -> robotLine "simbotA" i p hd
  OTSimbotB i p hd  -> robotLine "simbotB" i p hd
  OTSize wd ht      -> "size " ++ show wd ++ " " ++ show ht
  where
    at (Point2 x y) = " at " ++ show x ++ " " ++ show y
    robotLine kw i p hd = kw ++ " " ++ show i ++ at p ++ " heading " ++ show hd ++ " rad"
