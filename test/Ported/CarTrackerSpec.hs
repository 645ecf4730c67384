-- | The ported Yampa car tracker ("Ported.CarTracker"), run on a script of
-- sightings. Expected reports worked out by hand from the program.
module Ported.CarTrackerSpec (spec) where

import qualified Data.Map as M
import           Test.Hspec

import           Ported.CarTracker
import           TestUtil

-- | The tracks' reports at each sample, as plain maps.
run :: [Sighting] -> [M.Map CarId Report]
run = map (\(Tracks m) -> m) . runDt 0.5 (tracker (Tracks M.empty))

spec :: Spec
spec = describe "a Yampa car tracker over a Functor-only collection" $ do
  let script = [ [(1, 0)], [(1, 1)], [(1, 2), (2, 10)], [(2, 11)], [], [], [], [], [], [] ]
      out    = run script
  it "starts a track one sample after a car is first seen (delayed switch)" $ do
    M.keys (head out) `shouldBe` []
    M.keys (out !! 1) `shouldBe` [1]
    M.keys (out !! 3) `shouldBe` [1, 2]
  it "follows the sightings and holds the last position when unseen" $
    map (fmap position . M.lookup 1) (take 5 out)
      `shouldBe` [Nothing, Just 1, Just 2, Just 2, Just 2]
  it "coasts for 2 s after the last sighting, then reports lost, then drops the track" $ do
    map (fmap status . M.lookup 1) out
      `shouldBe` [ Nothing, Just Seen, Just Seen, Just Coasting, Just Coasting, Just Coasting
                 , Just Coasting, Just Lost, Nothing, Nothing ]
    map (fmap status . M.lookup 2) out
      `shouldBe` [ Nothing, Nothing, Nothing, Just Seen, Just Coasting, Just Coasting
                 , Just Coasting, Just Coasting, Just Lost, Nothing ]
  it "beats once a second from the instant its car was first seen (t = 0 here)" $
    map (fmap heartbeat . M.lookup 1) (take 6 out)
      `shouldBe` [Nothing, Just False, Just True, Just False, Just True, Just False]
