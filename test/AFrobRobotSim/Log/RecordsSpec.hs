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

robot :: Gen LogRobot
robot = LogRobot <$> number <*> number <*> number <*> number <*> number <*> number <*> number
                 <*> arbitrary <*> short number
                 <*> short ((,,,) <$> text <*> arbitrary <*> number <*> number)
                 <*> short ((,) <$> number <*> number)
                 <*> text <*> number <*> number <*> number
                 <*> short ((,) <$> number <*> text)
  where short g = resize 4 (listOf g)

frame :: Gen LogFrame
frame = LogFrame <$> number <*> resize 6 (listOf robot) <*> resize 4 (listOf ((,) <$> number <*> number))
                 <*> resize 3 (listOf ((,) <$> text <*> arbitrary))
                 <*> resize 3 (listOf event) <*> resize 3 (listOf text)
  where event = LogEvent <$> number <*> text <*> oneof [pure Nothing, curry Just <$> text <*> arbitrary] <*> text

spec :: Spec
spec = describe "encodeLogLineBytes" $
  it "writes a frame as encodeJSON writes its JSON value, character for character (property)" $
    forAll frame $ \f ->
      encodeLogLineBytes (LineFrame f) === BC.pack (encodeJSON (logLineJSON (LineFrame f)))
