-- | "AFrobRobotSim.Log.Records": a frame's bytes, which the run log and
-- the replay page write member by member, are the characters of the
-- frame's 'JSON' value as 'AFrobRobotSim.JSON.encodeJSON' writes it, for
-- any frame: numbers of every kind (whole, millionths, others, not
-- finite), strings that need escapes, empty and long lists, events with
-- and without a robot.
module AFrobRobotSim.Log.RecordsSpec (spec) where

import qualified Data.ByteString.Char8 as BC
import           Data.Char             (ord)
import           Test.Hspec
import           Test.QuickCheck

import           AFrobRobotSim.JSON         (encodeJSON)
import           AFrobRobotSim.Log.Records

-- | A number as a run log has them, and others.
number :: Gen Double
number = oneof
  [ (/ 1e6) . fromIntegral <$> (choose (-5000000000, 5000000000) :: Gen Int)   -- millionths
  , fromIntegral <$> (arbitrary :: Gen Int)
  , arbitrary
  , elements [0, -0.0, 1 / 0, -1 / 0, 0 / 0, 1e15, 1e9, 123456789.5, 5e-324, 1e300, 0.1] ]

-- | Text, with the characters that need escaping in JSON or in a page.
text :: Gen String
text = listOf (oneof [ arbitrary `suchThat` (\c -> ord c < 0xD800 || ord c > 0xDFFF)
                     , elements "\"\\/<>&\n\r\t\0\DEL\x2028\x1F600 abcxyz" ])

-- | Plain text of at most 64 characters, as a simulator's robot types and
-- battery states are, and some longer.
plainText :: Gen String
plainText = oneof [ elements ["SimbotA", "SimbotB", "high", "low", "critical", ""]
                  , listOf (elements "abcxyz019 _-.:/")
                  , (\k -> replicate k 'p') <$> elements [63, 64, 65] ]

-- | A robot, its seen robots' types and its battery drawn from @names@.
robotWith :: Gen String -> Gen LogRobot
robotWith names =
  LogRobot <$> number <*> number <*> number <*> number <*> number <*> number <*> number
           <*> arbitrary <*> short number
           <*> short ((,,,) <$> names <*> arbitrary <*> number <*> number)
           <*> short ((,) <$> number <*> number)
           <*> names <*> number <*> number <*> number
           <*> short ((,) <$> number <*> text)
  where short g = resize 4 (listOf g)

robot :: Gen LogRobot
robot = robotWith text

frameOf :: Gen LogRobot -> Gen LogFrame
frameOf robots =
  LogFrame <$> number <*> resize 6 (listOf robots) <*> resize 4 (listOf ((,) <$> number <*> number))
                 <*> resize 3 (listOf ((,) <$> text <*> arbitrary))
                 <*> resize 3 (listOf event) <*> resize 3 (listOf text)
  where event = LogEvent <$> number <*> text <*> oneof [pure Nothing, curry Just <$> text <*> arbitrary] <*> text

frame :: Gen LogFrame
frame = frameOf robot

spec :: Spec
spec = describe "encodeLogLineBytes" $ do
  it "writes a frame as encodeJSON writes its JSON value, character for character (property)" $
    forAll frame $ \f ->
      encodeLogLineBytes (LineFrame f) === BC.pack (encodeJSON (logLineJSON (LineFrame f)))
  it "and so with plain types and batteries, up to and beyond 64 characters (one write a robot) (property)" $
    forAll (frameOf (robotWith plainText)) $ \f ->
      encodeLogLineBytes (LineFrame f) === BC.pack (encodeJSON (logLineJSON (LineFrame f)))
