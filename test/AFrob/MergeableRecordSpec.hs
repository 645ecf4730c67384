-- | Tests for "AFrob.MergeableRecord", on a small record of our own with
-- a plain field (overwritten by its setter) and a message list
-- (accumulated by its setter).
module AFrob.MergeableRecordSpec (spec) where

import           Test.Hspec            hiding (after)
import           Test.QuickCheck

import           AFrob.MergeableRecord

-- | A test output record.
data Out = Out
  { outSpeed :: Int       -- ^ a plain field
  , outMsgs  :: [String]  -- ^ an accumulating field
  } deriving (Eq, Show)

instance MergeableRecord Out where
  mrDefault = Out { outSpeed = 0, outMsgs = [] }

-- | Overwrites the speed.
setSpeed :: Int -> MR Out
setSpeed v = mrMake (\o -> o { outSpeed = v })

-- | Adds messages in front of those already there.
say :: [String] -> MR Out
say ms = mrMake (\o -> o { outMsgs = ms ++ outMsgs o })

-- | A random update, with a description for counterexamples.
data Update = Update String (MR Out)

instance Show Update where
  show (Update d _) = d

instance Arbitrary Update where
  arbitrary = do
    parts <- listOf part
    pure (Update (show (map fst parts)) (mconcat (map snd parts)))
    where
      part = oneof
        [ (\v -> ("speed " ++ show v, setSpeed v)) <$> arbitrary
        , (\ms -> ("say " ++ show ms, say ms)) <$> listOf (elements ["a", "b", "c"])
        ]

spec :: Spec
spec = do
  describe "mrFinalize" $ do
    it "of the empty update is mrDefault" $
      mrFinalize (mempty :: MR Out) `shouldBe` mrDefault
    it "keeps the default of fields no update sets" $
      mrFinalize (say ["hi"]) `shouldBe` Out 0 ["hi"]
    it "applies a setter" $
      mrFinalize (setSpeed 3) `shouldBe` Out 3 []

  describe "mrMerge" $ do
    it "left wins when both set the same field" $ do
      mrFinalize (setSpeed 1 `mrMerge` setSpeed 2) `shouldBe` Out 1 []
      mrFinalize (setSpeed 2 `mrMerge` setSpeed 1) `shouldBe` Out 2 []
    it "combines different fields" $
      mrFinalize (setSpeed 5 `mrMerge` say ["x"]) `shouldBe` Out 5 ["x"]
    it "keeps the messages of both sides, left's first" $
      mrFinalize (say ["l1", "l2"] `mrMerge` say ["r1"]) `shouldBe` Out 0 ["l1", "l2", "r1"]
    it "keeps messages in order across a chain of merges" $
      mrFinalize (say ["a"] `mrMerge` (setSpeed 1 `mrMerge` say ["b"]) `mrMerge` say ["c"])
        `shouldBe` Out 1 ["a", "b", "c"]
    it "applies the right update first, then the left one" $
      mrFinalize (mrMake (\o -> o { outSpeed = outSpeed o * 10 }) `mrMerge` setSpeed 4)
        `shouldBe` Out 40 []
    it "is <> of the Semigroup instance" $
      property $ \(Update _ l) (Update _ r) ->
        mrFinalize (l `mrMerge` r) === mrFinalize (l <> r)

  describe "laws" $ do
    it "associativity" $
      property $ \(Update _ a) (Update _ b) (Update _ c) ->
        mrFinalize ((a <> b) <> c) === mrFinalize (a <> (b <> c))
    it "mempty is a left and right unit" $
      property $ \(Update _ a) ->
        mrFinalize (mempty <> a) === mrFinalize a .&&. mrFinalize (a <> mempty) === mrFinalize a
    it "mconcat: the first plain setter wins, all messages kept in order" $
      mrFinalize (mconcat [say ["1"], setSpeed 7, say ["2"], setSpeed 8, say ["3"]])
        `shouldBe` Out 7 ["1", "2", "3"]
