-- | Tests for "AFRP.Event": the 'Event' type, its instances and every
-- function on events, pinned by fixed cases, plus properties relating
-- 'Event' to 'Maybe'.
module AFRP.EventSpec (spec) where

import           Control.Applicative (Alternative (..))
import           Control.Exception   (ErrorCall (..), evaluate)
import           Data.List           (isInfixOf)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Event

-- | An error call whose message mentions the given text.
errorMentioning :: String -> Selector ErrorCall
errorMentioning s (ErrorCallWithLocation msg _) = s `isInfixOf` msg

ev :: Int -> Event Int
ev = Event

none :: Event Int
none = NoEvent

-- | Random events of small integers, built through 'maybeToEvent'.
genEvent :: Gen (Event Int)
genEvent = maybeToEvent <$> arbitrary

spec :: Spec
spec = do
  describe "instances" $ do
    it "Functor: fmap maps an occurrence and leaves NoEvent alone" $ do
      fmap (+ 1) (ev 1) `shouldBe` ev 2
      fmap (+ 1) none `shouldBe` none
      (show <$> ev 7) `shouldBe` Event "7"

    it "Applicative: pure occurs, <*> occurs only when both sides do" $ do
      (pure 3 :: Event Int) `shouldBe` ev 3
      (Event (* 2) <*> ev 5) `shouldBe` ev 10
      (Event (* 2) <*> none) `shouldBe` none
      ((NoEvent :: Event (Int -> Int)) <*> ev 5) `shouldBe` none
      ((,) <$> ev 1 <*> Event 'x') `shouldBe` Event (1, 'x')

    it "Monad: >>= occurs only when both stages occur" $ do
      (ev 4 >>= \x -> ev (x * 3)) `shouldBe` ev 12
      (ev 4 >>= const none) `shouldBe` none
      (none >>= \x -> ev (x * 3)) `shouldBe` none
      (do { x <- ev 1; y <- ev 2; pure (x + y) }) `shouldBe` ev 3

    it "MonadFail: a failed pattern match gives NoEvent" $ do
      let firstOf :: Event [Int] -> Event Int
          firstOf e = do { (x : _) <- e; pure x }
      firstOf (Event [5, 6]) `shouldBe` ev 5
      firstOf (Event []) `shouldBe` none

    it "Alternative: empty is NoEvent and <|> is left-biased" $ do
      (empty :: Event Int) `shouldBe` none
      (ev 1 <|> ev 2) `shouldBe` ev 1
      (none <|> ev 2) `shouldBe` ev 2
      (ev 1 <|> none) `shouldBe` ev 1
      (none <|> none) `shouldBe` none
      (many none) `shouldBe` (Event [] :: Event [Int])

    it "Semigroup: simultaneous occurrences are combined with <>, left first" $ do
      (Event "ab" <> Event "cd") `shouldBe` Event "abcd"
      (Event "ab" <> NoEvent) `shouldBe` Event "ab"
      (NoEvent <> Event "cd") `shouldBe` Event "cd"
      (NoEvent <> NoEvent :: Event String) `shouldBe` NoEvent

    it "Monoid: mempty is NoEvent" $ do
      (mempty :: Event String) `shouldBe` NoEvent
      mconcat [NoEvent, Event "a", NoEvent, Event "b"] `shouldBe` Event "ab"

    it "Eq distinguishes occurrences and values" $ do
      ev 1 == ev 1 `shouldBe` True
      ev 1 == ev 2 `shouldBe` False
      ev 1 == none `shouldBe` False
      none == none `shouldBe` True

    it "Ord: NoEvent is below any occurrence; occurrences compare by value" $ do
      compare none (ev minBound) `shouldBe` LT
      compare (ev 0) none `shouldBe` GT
      compare (ev 1) (ev 2) `shouldBe` LT
      compare (ev 2) (ev 2) `shouldBe` EQ
      compare none none `shouldBe` EQ
      maximum [ev 3, none, ev 9, ev (-1)] `shouldBe` ev 9
      minimum [ev 3, none, ev 9] `shouldBe` none

    it "Show uses the constructor names, with precedence" $ do
      show none `shouldBe` "NoEvent"
      show (ev 3) `shouldBe` "Event 3"
      show (ev (-3)) `shouldBe` "Event (-3)"
      show (Event (Just 'a')) `shouldBe` "Event (Just 'a')"
      show [ev 1, none] `shouldBe` "[Event 1,NoEvent]"

    it "Foldable and Traversable see the value of an occurrence" $ do
      sum (ev 4) `shouldBe` 4
      length none `shouldBe` 0
      length (ev 4) `shouldBe` 1
      traverse (\x -> [x, x + 1]) (ev 1) `shouldBe` [ev 1, ev 2]
      traverse (\x -> [x, x + 1]) none `shouldBe` [none]

  describe "noEvent, isEvent, isNoEvent" $ do
    it "noEvent is NoEvent" $
      (noEvent :: Event Int) `shouldBe` NoEvent
    it "isEvent / isNoEvent tell the constructor" $ do
      map isEvent [ev 0, none] `shouldBe` [True, False]
      map isNoEvent [ev 0, none] `shouldBe` [False, True]

  describe "event" $ do
    it "is the default on NoEvent and the function on an occurrence" $ do
      event (0 :: Int) (* 10) (ev 4) `shouldBe` 40
      event (0 :: Int) (* 10) none `shouldBe` 0
    it "does not evaluate the default for an occurrence" $
      event undefined (+ 1) (ev 4) `shouldBe` (5 :: Int)

  describe "fromEvent" $ do
    it "is the value of an occurrence" $
      fromEvent (Event "v") `shouldBe` "v"
    it "is an error on NoEvent" $
      evaluate (fromEvent none) `shouldThrow` anyErrorCall
    it "names fromEvent in its error" $
      evaluate (fromEvent none) `shouldThrow` errorMentioning "fromEvent"

  describe "maybeToEvent / eventToMaybe" $ do
    it "convert fixed values both ways" $ do
      maybeToEvent (Just 'q') `shouldBe` Event 'q'
      maybeToEvent (Nothing :: Maybe Char) `shouldBe` NoEvent
      eventToMaybe (Event 'q') `shouldBe` Just 'q'
      eventToMaybe (NoEvent :: Event Char) `shouldBe` Nothing
    it "are inverse to each other" $
      property $ \m -> eventToMaybe (maybeToEvent m) === (m :: Maybe Int)

  describe "tag, tagWith, attach" $ do
    it "tag replaces the value of an occurrence" $ do
      (ev 1 `tag` "x") `shouldBe` Event "x"
      (none `tag` "x") `shouldBe` NoEvent
    it "tagWith is tag with the arguments swapped" $ do
      tagWith 'k' (ev 1) `shouldBe` Event 'k'
      tagWith 'k' none `shouldBe` NoEvent
    it "tag does not need the old value" $
      (Event (undefined :: Int) `tag` 'y') `shouldBe` Event 'y'
    it "attach pairs the value with the given one" $ do
      (ev 1 `attach` 'a') `shouldBe` Event (1, 'a')
      (none `attach` 'a') `shouldBe` NoEvent
    it "tag, attach and gate bind tighter than the merges (infixl 8 vs 6)" $
      -- parsed as (ev 1 `tag` 10) `lMerge` (ev 2 `tag` 20)
      (ev 1 `tag` 10 `lMerge` ev 2 `tag` (20 :: Int)) `shouldBe` Event 10

  describe "lMerge / rMerge" $ do
    it "lMerge prefers the left occurrence" $ do
      lMerge (ev 1) (ev 2) `shouldBe` ev 1
      lMerge none (ev 2) `shouldBe` ev 2
      lMerge (ev 1) none `shouldBe` ev 1
      lMerge none none `shouldBe` none
    it "rMerge prefers the right occurrence" $ do
      rMerge (ev 1) (ev 2) `shouldBe` ev 2
      rMerge none (ev 2) `shouldBe` ev 2
      rMerge (ev 1) none `shouldBe` ev 1
      rMerge none none `shouldBe` none

  describe "merge" $ do
    it "passes a single occurrence through from either side" $ do
      merge (ev 1) none `shouldBe` ev 1
      merge none (ev 2) `shouldBe` ev 2
      merge none none `shouldBe` none
    it "is an error on simultaneous occurrences, when inspected" $
      evaluate (fromEvent (merge (ev 1) (ev 2))) `shouldThrow` anyErrorCall
    it "says that the occurrences were simultaneous" $
      evaluate (event 0 id (merge (ev 1) (ev 2)))
        `shouldThrow` errorMentioning "simultaneous"

  describe "mergeBy" $ do
    it "combines simultaneous occurrences, left value first" $
      mergeBy (-) (ev 10) (ev 3) `shouldBe` ev 7
    it "passes single occurrences through unchanged" $ do
      mergeBy (-) (ev 10) none `shouldBe` ev 10
      mergeBy (-) none (ev 3) `shouldBe` ev 3
      mergeBy (-) none none `shouldBe` none

  describe "mapMerge" $ do
    let mm :: Event Int -> Event Char -> Event String
        mm = mapMerge show (: []) (\i c -> show i ++ [c])
    it "maps the left, the right, or both" $ do
      mm (Event 1) NoEvent `shouldBe` Event "1"
      mm NoEvent (Event 'c') `shouldBe` Event "c"
      mm (Event 1) (Event 'c') `shouldBe` Event "1c"
      mm NoEvent NoEvent `shouldBe` NoEvent

  describe "mergeEvents" $ do
    it "the leftmost occurrence wins" $ do
      mergeEvents [none, ev 2, ev 3] `shouldBe` ev 2
      mergeEvents [ev 1, none, ev 3] `shouldBe` ev 1
    it "is NoEvent for no occurrence and for the empty list" $ do
      mergeEvents [none, none] `shouldBe` none
      mergeEvents [] `shouldBe` none
    it "does not look past the first occurrence" $
      mergeEvents (none : ev 5 : undefined) `shouldBe` ev 5

  describe "catEvents" $ do
    it "collects all occurrences in list order" $
      catEvents [ev 3, none, ev 1, ev 2] `shouldBe` Event [3, 1, 2]
    it "is NoEvent when nothing occurs" $ do
      catEvents [none, none] `shouldBe` NoEvent
      catEvents ([] :: [Event Int]) `shouldBe` NoEvent

  describe "joinE" $ do
    it "occurs only when both occur" $ do
      joinE (ev 1) (Event 'a') `shouldBe` Event (1, 'a')
      joinE (ev 1) (NoEvent :: Event Char) `shouldBe` NoEvent
      joinE none (Event 'a') `shouldBe` NoEvent
    it "binds less tightly than tag and more than the merges (infixl 7, Yampa's)" $ do
      -- ev 1 `joinE` (Event 'b' `tag` 'c'), and (ev 1 `joinE` Event 'b') `lMerge` ...
      (ev 1 `joinE` Event 'b' `tag` 'c') `shouldBe` Event (1, 'c')
      (none `joinE` Event 'b' `lMerge` Event (2, 'd')) `shouldBe` Event (2, 'd')

  describe "splitE" $ do
    it "splits an occurrence of a pair into two occurrences" $
      splitE (Event (1 :: Int, 'a')) `shouldBe` (ev 1, Event 'a')
    it "splits NoEvent into two NoEvents" $
      splitE (NoEvent :: Event (Int, Char)) `shouldBe` (none, NoEvent)

  describe "filterE" $ do
    it "keeps occurrences satisfying the predicate" $ do
      filterE even (ev 4) `shouldBe` ev 4
      filterE even (ev 3) `shouldBe` none
      filterE even none `shouldBe` none

  describe "mapFilterE" $ do
    let half x = if even x then Just (x `div` 2) else Nothing
    it "maps occurrences to Just and drops those mapped to Nothing" $ do
      mapFilterE half (ev 8) `shouldBe` ev 4
      mapFilterE half (ev 7) `shouldBe` none
      mapFilterE half none `shouldBe` none

  describe "gate" $ do
    it "lets an occurrence through only when the condition holds" $ do
      (ev 1 `gate` True) `shouldBe` ev 1
      (ev 1 `gate` False) `shouldBe` none
      (none `gate` True) `shouldBe` none
      (none `gate` False) `shouldBe` none

  describe "properties: Event is Maybe" $ do
    it "fmap commutes with the isomorphism" $
      property $ \(Fun _ f) m ->
        eventToMaybe (fmap f (maybeToEvent m)) === fmap (f :: Int -> Int) (m :: Maybe Int)

    it "<*> commutes with the isomorphism" $
      property $ \mf m ->
        let fs = fmap applyFun mf :: Maybe (Int -> Int)
        in eventToMaybe (maybeToEvent fs <*> maybeToEvent m) === (fs <*> (m :: Maybe Int))

    it ">>= commutes with the isomorphism" $
      property $ \(Fun _ k) m ->
        eventToMaybe (maybeToEvent (m :: Maybe Int) >>= maybeToEvent . k)
          === (m >>= (k :: Int -> Maybe Int))

    it "<|> commutes with the isomorphism" $
      property $ \m1 m2 ->
        eventToMaybe (maybeToEvent m1 <|> maybeToEvent m2) === (m1 <|> (m2 :: Maybe Int))

    it "<> commutes with the isomorphism" $
      property $ \m1 m2 ->
        eventToMaybe (maybeToEvent m1 <> maybeToEvent m2) === (m1 <> (m2 :: Maybe [Int]))

    it "compare commutes with the isomorphism" $
      property $ \m1 m2 ->
        compare (maybeToEvent m1) (maybeToEvent m2) === compare m1 (m2 :: Maybe Int)

    it "lMerge is rMerge flipped" $
      forAll genEvent $ \a -> forAll genEvent $ \b ->
        lMerge a b === rMerge b a

    it "mergeBy agrees with lMerge when the function keeps the left value" $
      forAll genEvent $ \a -> forAll genEvent $ \b ->
        mergeBy const a b === lMerge a b

    it "catEvents keeps exactly the occurrences" $
      forAll (listOf genEvent) $ \es ->
        eventToMaybe (catEvents es)
          === (let xs = [x | Event x <- es] in if null xs then Nothing else Just xs)

    it "filterE p keeps an occurrence iff p holds" $
      forAll genEvent $ \e ->
        filterE even e === (if event False even e then e else NoEvent)

    it "splitE then joinE is the identity" $
      property $ \m ->
        let e = maybeToEvent (m :: Maybe (Int, Char))
        in uncurry joinE (splitE e) === e
