{-# LANGUAGE Arrows #-}
-- | Tests for "AFrob.RobotIO", with a small robot of our own: an input type
-- that is an instance of every input class, an output type that is an
-- instance of both output classes, and a properties type. The derived
-- event sources are run with 'embed' on fixed sample lists and checked
-- against list models on random ones.
module AFrob.RobotIOSpec (spec) where

import           Data.List       (sortOn)
import           Test.Hspec      hiding (after)
import           Test.QuickCheck

import           AFrob           hiding (forAll)

------------------------------------------------------------------------------
-- The test robot

-- | A test input sample.
data In = In
  { inBatt  :: BatteryStatus
  , inStuck :: Bool
  , inKey   :: Maybe Char
  } deriving (Eq, Show)

instance HasRobotStatus In where
  rsBattStat = inBatt
  rsIsStuck  = inStuck

instance HasTextualConsoleInput In where
  tciKey = inKey

-- | The range finder reports the angle it was asked about plus 10, so the
-- tests see which angle a derived range finder queries.
instance HasRangeFinder In where
  rfRange _ a = a + 10
  rfMaxRange _ = 20

instance HasOdometry In where
  odometryPosition _ = Point2 1 2
  odometryHeading _  = pi / 2

instance HasAnimateObjectTracker In where
  aotOtherRobots _ = [("SimbotB", 7, 0.5, 3), ("SimbotA", 2, -1, 1.5), ("SimbotA", 4, pi / 2, 2)]
  aotBalls _       = [(0, 1)]

-- | A test output: wheel velocities (left, right) and console messages.
data Out = Out
  { outWheels :: (Velocity, Velocity)
  , outMsgs   :: [String]
  } deriving (Eq, Show)

-- | The wheel base of the test robot, in metres.
wheelBase :: Length
wheelBase = 0.5

instance MergeableRecord Out where
  mrDefault = Out (0, 0) []

instance HasDiffDrive Out where
  ddBrake         = mrMake (\o -> o { outWheels = (0, 0) })
  ddVelDiff vl vr = mrMake (\o -> o { outWheels = (vl, vr) })
  ddVelTR v w     = ddVelDiff (v - w * wheelBase / 2) (v + w * wheelBase / 2)

instance HasTextConsoleOutput Out where
  tcoPrintMessage e = mrMake (\o -> o { outMsgs = foldr (:) [] e ++ outMsgs o })

-- | Test robot properties.
data Props = Props

instance HasRobotProperties Props where
  rpType _     = "TestBot"
  rpId _       = 3
  rpDiameter _ = wheelBase
  rpAccMax _   = 1
  rpWSMax _    = 2

-- | A status-only sample.
status :: BatteryStatus -> Bool -> In
status b s = In b s Nothing

-- | A key-only sample.
key :: Maybe Char -> In
key = In BSHigh False

-- | Run with time steps of 0.1; the first sample is at time 0.
run :: SF a b -> [a] -> [b]
run _  []       = []
run sf (x : xs) = embed sf (x, [(0.1, Just y) | y <- xs])

-- | The notes' @rcReverse@ (section 3.3), over the test robot: drive at
-- @v@, and when stuck say "Ouch!!" and reverse.
rcReverse :: Velocity -> Props -> SF In Out
rcReverse v rps = beh `dSwitch` const (rcReverse (-v) rps)
  where
    beh = proc sbi -> do
      stuckE <- rsStuck -< sbi
      let mr = ddVelDiff v v `mrMerge` tcoPrintMessage (tag stuckE "Ouch!!")
      returnA -< (mrFinalize mr, stuckE)

------------------------------------------------------------------------------
-- List models of the event sources

-- | Pairs each sample with the one before it (the given value before the first).
withPrev :: a -> [a] -> [(a, a)]
withPrev a0 xs = zip (a0 : xs) xs

stuckModel :: [Bool] -> [Event ()]
stuckModel = map (\(p, c) -> if c && not p then Event () else NoEvent) . withPrev True

changedModel :: [BatteryStatus] -> [Event BatteryStatus]
changedModel []       = []
changedModel (b : bs) = NoEvent : map (\(p, c) -> if c /= p then Event c else NoEvent) (withPrev b bs)

keyModel :: Maybe Char -> [Maybe Char] -> [Event Char]
keyModel k0 = map step . withPrev k0
  where step (p, c) = case c of
          Just ch | c /= p -> Event ch
          _                -> NoEvent

genBatt :: Gen [BatteryStatus]
genBatt = listOf1 (elements [minBound .. maxBound])

genKeys :: Gen [Maybe Char]
genKeys = listOf1 (elements [Nothing, Just 'a', Just 'b'])

------------------------------------------------------------------------------

spec :: Spec
spec = do
  describe "rsStuck" $ do
    it "gives no event for a robot stuck at time 0, then one each time it gets stuck again" $
      run rsStuck (map (status BSHigh) [True, True, False, True, True, False, False, True])
        `shouldBe` [NoEvent, NoEvent, NoEvent, Event (), NoEvent, NoEvent, NoEvent, Event ()]
    it "gives an event when a free robot gets stuck" $
      run rsStuck (map (status BSHigh) [False, True, True])
        `shouldBe` [NoEvent, Event (), NoEvent]
    it "agrees with the edge model on random runs" $
      property $ forAll (listOf1 arbitrary) $ \ss ->
        run rsStuck (map (status BSHigh) ss) === stuckModel ss

  describe "battery status events" $ do
    let bs = [BSLow, BSLow, BSHigh, BSLow, BSCritical, BSCritical, BSLow, BSHigh]
    it "rsBattStatChanged: the new status at each change, none at time 0" $
      run rsBattStatChanged (map (`status` False) bs)
        `shouldBe` [ NoEvent, NoEvent, Event BSHigh, Event BSLow, Event BSCritical
                   , NoEvent, Event BSLow, Event BSHigh ]
    it "rsBattStatLow: whenever it becomes BSLow, not at time 0" $
      run rsBattStatLow (map (`status` False) bs)
        `shouldBe` [NoEvent, NoEvent, NoEvent, Event (), NoEvent, NoEvent, Event (), NoEvent]
    it "rsBattStatCritical: whenever it becomes BSCritical, not at time 0" $ do
      run rsBattStatCritical (map (`status` False) bs)
        `shouldBe` [NoEvent, NoEvent, NoEvent, NoEvent, Event (), NoEvent, NoEvent, NoEvent]
      run rsBattStatCritical (map (`status` False) [BSCritical, BSCritical])
        `shouldBe` [NoEvent, NoEvent]
    it "rsBattStatChanged agrees with the change model on random runs" $
      property $ forAll genBatt $ \xs ->
        run rsBattStatChanged (map (`status` False) xs) === changedModel xs
    it "rsBattStatLow and rsBattStatCritical filter rsBattStatChanged" $
      property $ forAll genBatt $ \xs ->
        let ins = map (`status` False) xs
            only s = map (\e -> filterE (== s) e `tag` ()) (changedModel xs)
        in run rsBattStatLow ins === only BSLow .&&. run rsBattStatCritical ins === only BSCritical

  describe "console keys" $ do
    let ks = [Just 'a', Just 'a', Nothing, Just 'b', Just 'c', Nothing, Nothing, Just 'c']
    it "tciKeyDown: each new key, including one pressed at time 0" $
      run tciKeyDown (map key ks)
        `shouldBe` [Event 'a', NoEvent, NoEvent, Event 'b', Event 'c', NoEvent, NoEvent, Event 'c']
    it "tciNewKeyDown k0: no event at time 0 for the key k0" $
      run (tciNewKeyDown (Just 'a')) (map key ks)
        `shouldBe` [NoEvent, NoEvent, NoEvent, Event 'b', Event 'c', NoEvent, NoEvent, Event 'c']
    it "tciNewKeyDown k0: an event at time 0 for another key" $
      run (tciNewKeyDown (Just 'x')) (map key [Just 'a', Nothing])
        `shouldBe` [Event 'a', NoEvent]
    it "releasing a key gives no event" $
      run tciKeyDown (map key [Nothing, Just 'q', Nothing, Nothing])
        `shouldBe` [NoEvent, Event 'q', NoEvent, NoEvent]
    it "agrees with the key model on random runs" $
      property $ forAll genKeys $ \xs -> forAll (elements [Nothing, Just 'a', Just 'b']) $ \k0 ->
        run (tciNewKeyDown k0) (map key xs) === keyModel k0 xs

  describe "derived range finders" $ do
    let i = key Nothing
    it "rfFront queries angle 0" $ rfFront i `shouldBe` 10
    it "rfBack queries angle pi" $ rfBack i `shouldBe` pi + 10
    it "rfLeft queries angle pi/2 (counter-clockwise)" $ rfLeft i `shouldBe` pi / 2 + 10
    it "rfRight queries angle -pi/2" $ rfRight i `shouldBe` -pi / 2 + 10

  describe "other input classes" $ do
    let i = key Nothing
    it "aotOtherRobots gives 4-tuples, sortable by distance as in the notes' rcAlign" $
      map (\(_, rid, _, _) -> rid) (sortOn (\(_, _, _, d) -> d) (aotOtherRobots i))
        `shouldBe` [2, 4, 7]
    it "odometry and balls" $ do
      odometryPosition i `shouldBe` Point2 1 2
      odometryHeading i `shouldBe` pi / 2
      aotBalls i `shouldBe` [(0, 1)]
      rfMaxRange i `shouldBe` 20

  describe "output classes" $ do
    it "merges a wheel setting with a console message (the notes' sbo)" $
      mrFinalize (ddVelDiff 1 2 `mrMerge` tcoPrintMessage (Event "hello"))
        `shouldBe` Out (1, 2) ["hello"]
    it "ddVelTR v w gives wheels (v - w*l/2, v + w*l/2)" $
      mrFinalize (ddVelTR 1 2 :: MR Out) `shouldBe` Out (0.5, 1.5) []
    it "a message without occurrence prints nothing; messages accumulate, left first" $ do
      mrFinalize (tcoPrintMessage NoEvent :: MR Out) `shouldBe` mrDefault
      mrFinalize (tcoPrintMessage (Event "a") `mrMerge` ddBrake `mrMerge` tcoPrintMessage (Event "b"))
        `shouldBe` Out (0, 0) ["a", "b"]
    it "the left drive command wins" $
      mrFinalize (ddVelDiff 1 1 `mrMerge` (ddBrake :: MR Out)) `shouldBe` Out (1, 1) []

  describe "a controller from the notes" $ do
    it "robot properties are readable" $
      (rpType Props, rpId Props, rpDiameter Props, rpAccMax Props, rpWSMax Props)
        `shouldBe` ("TestBot", 3, 0.5, 1, 2)
    it "rcReverse says Ouch!! and reverses each time it gets stuck" $
      run (rcReverse 1 Props) (map (status BSHigh) [False, False, True, True, False, True, True])
        `shouldBe` [ Out (1, 1) [], Out (1, 1) [], Out (1, 1) ["Ouch!!"], Out (-1, -1) []
                   , Out (-1, -1) [], Out (-1, -1) ["Ouch!!"], Out (1, 1) [] ]
