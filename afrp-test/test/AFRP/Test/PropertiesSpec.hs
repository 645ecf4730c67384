{-# LANGUAGE Arrows #-}
-- | Properties of the afrp library, written with the kit: each is a
-- temporal predicate checked on random streams, so the kit is tried on
-- things that are true (and, at the end, on a broken combinator).
module AFRP.Test.PropertiesSpec (spec) where

import           Data.List             (isPrefixOf)
import           Test.Hspec             hiding (after)
import           Test.QuickCheck
import           Test.QuickCheck.Random (mkQCGen)

import           AFRP                   hiding (forAll)
import           AFRP.Test.LTL
import           AFRP.Test.QuickCheck
import           AFRP.Test.Stream

-- Streams of optional events: a third of the samples carry one.
eventStreams :: Gen (SignalSampleStream (Maybe Int))
eventStreams = generateStreamWith (\_ _ -> frequency [(2, pure Nothing), (1, Just <$> arbitrary)])
                                  DistRandom (Nothing, Just 2) Nothing

-- | @hold@ (or a stand-in for it) outputs the latest event's value, and
-- before the first event its initial value: at an event the value is the
-- event's, between events it is the previous sample's output.
holdsUntilNextEvent :: (Int -> SF (Event Int) Int) -> TPred (Maybe Int)
holdsUntilNextEvent holdImpl = Always $ SP $ proc me -> do
  let e = maybeToEvent me
  h     <- holdImpl 0 -< e
  hPrev <- iPre 0     -< h
  returnA -< case e of
    Event x -> h == x
    NoEvent -> h == hPrev

-- A broken hold: it forgets the value one second after the last event and
-- goes back to its initial value.
forgetfulHold :: Int -> SF (Event Int) Int
forgetfulHold x0 = proc e -> do
  t <- localTime -< ()
  rec let (v, since') = case e of
            Event x -> (x, t)
            NoEvent -> lastSeen
      lastSeen <- iPre (x0, 0) -< (v, since')
  returnA -< if t - since' > 1 then x0 else v

spec :: Spec
spec = do
  it "the integral of a non-negative signal never decreases (property)" $
    forAllStreams (generateStreamWith (\_ _ -> getNonNegative <$> arbitrary) DistRandom (Nothing, Just 1) Nothing) $
      propT (Always (SP (proc x -> do
        v     <- integral -< (x :: Double)
        vPrev <- iPre 0   -< v
        returnA -< v >= vPrev)))

  it "hold holds until the next event (property)" $
    forAllStreams eventStreams (propT (holdsUntilNextEvent hold))

  it "after d fires exactly once, at the first sample at or past d (property)" $
    forAll (choose (0.1, 3)) $ \d ->
      forAllStreamsWith (Nothing, Just 0.5) shrink
        (generateStream DistRandom (Nothing, Just 0.5) (Just (Right (1.5 * d)))) $ \s ->
        let fires   = after d () >>> arr isEvent
            reached = localTime >>> arr (>= d)
            firstAt = (reached &&& previously reached) >>> arr (\(now', earlier) -> now' && not earlier)
        in propT (And (Always (SP ((fires &&& firstAt) >>> arr (uncurry (==)))))
                      (Implies (Eventually (SP reached)) (Eventually (SP fires))))
                 (s :: SignalSampleStream ())

  it "a switch's output at the switching instant comes from the new signal function (property)" $
    forAllStreams (generateStream DistRandom (Nothing, Just 1) Nothing) $
      let switched :: SF Int (Either Int Int)
          switched = switch (arr (\x -> (Left x, if x > 0 then Event x else NoEvent)))
                            (\x0 -> arr (\x -> Right (x + x0)))
      in propT (Always (SP (proc x -> do
           out  <- switched               -< x
           seen <- hasEverBeen (arr (> 0)) -< x
           returnA -< either (const False) (const True) out == seen)))

  it "a broken hold is caught, with a counterexample of at most 3 samples (property)" $ do
    result <- quickCheckWithResult stdArgs { chatty = False, replay = Just (mkQCGen 17, 0), maxSuccess = 1000 }
                (forAllStreams eventStreams (propT (holdsUntilNextEvent forgetfulHold)))
    case result of
      Failure { failingTestCase = table : _ } -> do
        let sizeLine = head (lines table)
        sizeLine `shouldSatisfy` ("stream of " `isPrefixOf`)
        (read (takeWhile (/= ' ') (drop (length "stream of ") sizeLine)) :: Int) `shouldSatisfy` (<= 3)
      _ -> expectationFailure ("the broken hold was not caught: " ++ output result)
