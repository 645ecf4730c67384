-- | "AFrobRobotSim.World.Check": 'validateWorld' checks objects against
-- the world's size and refuses a second size or sides out of range;
-- rejects what overlaps at time 0 (each pair named once, with both
-- objects), accepts what only touches, caps long lists of problems,
-- bounds the crowding it checks ('maxClosePairs'), and checks balls'
-- area and robots' ids.
module AFrobRobotSim.World.CheckSpec (spec) where

import           Control.Exception (evaluate)
import           Data.List         (isInfixOf)
import           System.Timeout    (timeout)
import           Test.Hspec
import           Test.QuickCheck

import           AFRP.Geometry
import           AFrobRobotSim
import           AFrobRobotSim.World (objectHalfSize, objectName)
import           AFrobRobotSim.World.Check (densestPacking, maxClosePairs, maxProblems, worldProblems)

-- | The problems of a world ([] for a valid one).
problems :: WorldTemplate -> [String]
problems = either id (const []) . validateWorld

spec :: Spec
spec = do
  describe "validateWorld: the world's size" $ do
    it "objects are checked against the size: inside a 100 m world, outside a 20 m one" $ do
      problems [OTSize 100 100, OTSimbotA 1 (Point2 40 (-40)) 0] `shouldBe` []
      problems [OTSimbotA 1 (Point2 40 (-40)) 0] `shouldSatisfy` any ("outside the world [-5.0, 5.0]" `isInfixOf`)
      problems [OTSize 20 20, OTBall (Point2 11 0)]
        `shouldBe` ["ball at (11.0, 0.0): lies (partly) outside the world [-10.0, 10.0] x [-10.0, 10.0]"]
      problems [OTSize 30 10, OTBall (Point2 14 0), OTBall (Point2 0 4.9)]
        `shouldSatisfy` (\ps -> length ps == 1 && "(0.0, 4.9)" `isInfixOf` head ps)
    it "a size wins over the bounds validateWorldIn is given" $
      validateWorldIn (Bounds 0 0 1 1) [OTSize 10 10, OTBall (Point2 (-3) 3)] `shouldBe` Right ()
    it "rejects a second size, naming both" $
      problems [OTSize 20 20, OTBall (Point2 0 0), OTSize 30 30]
        `shouldBe` ["world size 30.0 by 30.0: a world has one size, and it was given by world size 20.0 by 20.0"]
    it "rejects sides that are not finite or not from 1 to 1000 m, and accepts 1 and 1000" $ do
      let badSize w h = problems [OTSize w h] `shouldSatisfy` (\ps -> length ps == 1)
      mapM_ (uncurry badSize) [ (0, 10), (10, -5), (0.5, 10), (10, 1000.5), (1 / 0, 10), (10, 0 / 0), (-(1 / 0), 10) ]
      problems [OTSize 1 1000] `shouldBe` []
      problems [OTSize 0 10] `shouldBe` ["world size 0.0 by 10.0: each side must be between 1.0 and 1000.0 metres"]
  describe "validateWorld: overlaps at time 0" $ do
    let robot = OTSimbotA 1 (Point2 0 0) 0
        pairs =
          [ ("a wall (vertical)",   OTVWall (Point2 0.2 0))
          , ("a wall (horizontal)", OTHWall (Point2 0 0.25))
          , ("a block",             OTBlock (Point2 0.4 0.4))
          , ("a ball",              OTBall (Point2 (-0.35) 0))
          , ("another robot",       OTSimbotB 1 (Point2 0 (-0.45)) 0)
          ]
    mapM_ (\(what, o) -> it ("rejects a robot inside " ++ what ++ ", naming both") $
             problems [robot, o] `shouldBe` [objectName o ++ " overlaps " ++ objectName robot])
          pairs
    it "rejects a ball inside a wall or a block" $ do
      problems [OTBall (Point2 1 1), OTBlock (Point2 1.3 1.3)]
        `shouldBe` ["block at (1.3, 1.3) overlaps ball at (1.0, 1.0)"]
      problems [OTVWall (Point2 1 1), OTBall (Point2 1.1 1.4)]
        `shouldBe` ["ball at (1.1, 1.4) overlaps vertical wall at (1.0, 1.0)"]
    it "accepts objects that only touch (to within rounding)" $
      problems [ robot, OTSimbotB 1 (Point2 0.5 0) 0, OTBlock (Point2 0 (-0.5))
               , OTBall (Point2 (-0.4) 0), OTVWall (Point2 (-0.6) 0), OTBall (Point2 2 2)
               , OTBlock (Point2 2 2.4) ]
        `shouldBe` []
    it "accepts walls and blocks overlapping each other, and balls overlapping balls" $
      problems [ OTVWall (Point2 1 1), OTHWall (Point2 1 1), OTBlock (Point2 1.2 1)
               , OTBall (Point2 (-2) (-2)), OTBall (Point2 (-2.1) (-2)) ]
        `shouldBe` []
    it "finds the same pairs as testing every pair, on random worlds" $
      forAll (listOf genObject) $ \objs ->
        let overlapping = length [ () | (_, m) <- worldProblems notesBounds (map ((,) "") objs)
                                      , " overlaps " `isInfixOf` m ]
            expected    = length [ () | (i, a) <- zip [0 :: Int ..] objs, (j, b) <- zip [0 ..] objs
                                      , i < j, placed a, placed b, bad a b ]
        in overlapping === expected
    it "gives 300 robots in one place a short message: 20 problems and a count" $ do
      let pile = [ OTSimbotA i (Point2 0 0) 0 | i <- [1 .. 300] ]
          ps   = problems pile
      length ps `shouldBe` maxProblems + 1
      last ps `shouldBe` ("... and " ++ show (300 * 299 `div` 2 - maxProblems) ++ " more problems")
      sum (map length ps) `shouldSatisfy` (< 3000)
    it "checks a pile of 5000 balls and one of 5000 blocks, not pair by pair (they may overlap their own kind)" $ do
      -- (about 0.1 s; pair by pair it took minutes: the bound is that
      -- guard, generous for a loaded machine, not a measure of speed)
      -- (each pile in one 1 m cell: 12.5 million pairs of balls, below
      -- maxClosePairs; at a cell's corner they would count four times)
      let piles = OTSize 30 30 : replicate 5000 (OTBall (Point2 (-2.5) (-2.5))) ++ replicate 5000 (OTBlock (Point2 2.5 2.5))
      r <- timeout 30000000 (evaluate (length (problems piles)))
      r `shouldBe` Just 0
    it "refuses objects crowding a square metre past maxClosePairs pairs, at the object that passes it; below, accepts" $ do
      -- 5000 walls, then m balls piled beside them, all in one cell: the
      -- m-th ball adds a pair with each wall and each ball before it
      let crowd m = OTSize 1000 1000 : replicate 5000 (OTVWall (Point2 0.5 0.5)) ++ replicate m (OTBall (Point2 0.75 0.5))
          closePairs m = sum [ 5000 + (j - 1) | j <- [1 .. m] ] :: Int
          m0      = head [ m | m <- [1 ..], closePairs m > maxClosePairs ]
      (m0, closePairs m0) `shouldBe` (3661, 25004630)
      r <- timeout 30000000 (evaluate (problems (crowd m0)))
      r `shouldBe` Just [ "ball at (0.75, 0.5): too crowded: the objects up to this one make "
                          ++ show (closePairs m0) ++ " pairs that share a 1 m square (a robot and any object, "
                          ++ "a ball and a ball, wall or block; counted once for each square they share), more "
                          ++ "than the 25000000 that a world may have (the physics and the check of overlaps "
                          ++ "compare such pairs one by one)" ]
      r' <- timeout 30000000 (evaluate (problems (crowd (m0 - 1))))
      r' `shouldBe` Just []
    it "reports the overlaps before a crowd, and checks the objects after it for all but overlaps" $ do
      let crowd = replicate 5000 (OTVWall (Point2 0.5 0.5)) ++ replicate 3661 (OTBall (Point2 0.75 0.5))
          w     = OTSize 1000 1000 : OTSimbotA 1 (Point2 3.5 3.5) 0 : OTSimbotA 2 (Point2 3.5 3.5) 0 : crowd
                  ++ [OTSimbotA 3 (Point2 (-3) (-3)) 0, OTBlock (Point2 (-3) (-3)), OTBall (Point2 600 0)]
      r <- timeout 30000000 (evaluate (problems w))
      -- the two robots share one cell: one pair more than the walls and
      -- balls alone make, which pass the bound at the 3661st ball; the
      -- robot and the block after it overlap, unreported; the ball far out
      -- is reported
      fmap (map (takeWhile (/= ':'))) r
        `shouldBe` Just [ "SimbotA 2 at (3.5, 3.5) overlaps SimbotA 1 at (3.5, 3.5)"
                        , "ball at (0.75, 0.5)"
                        , "ball at (600.0, 0.0)" ]
      fmap (map ("make 25004631 pairs" `isInfixOf`)) r `shouldBe` Just [False, True, False]
    it "refuses a pile of balls on one spot past maxClosePairs pairs of balls (the floor's area let 100,000 through, 7 minutes a step)" $ do
      -- the n-th ball adds n - 1 pairs: 7071 balls make 24,995,985, the 7072nd 25,003,056
      let pile n = OTSize 1000 1000 : replicate n (OTBall (Point2 0.5 0.5))
      r <- timeout 30000000 (evaluate (problems (pile 7072)))
      fmap (map (takeWhile (/= ','))) r `shouldBe` Just ["ball at (0.5"]
      fmap (map ("make 25003056 pairs" `isInfixOf`)) r `shouldBe` Just [True]
      r' <- timeout 30000000 (evaluate (problems (pile 7071)))
      r' `shouldBe` Just []
  describe "validateWorld: the balls' discs no larger in all than the floor the robots leave, nor than equal discs can cover" $ do
    let ball  = OTBall (Point2 0 0)
        -- 60 robots in rows along the south wall: 11.78 m^2 of discs
        robots = [ OTSimbotA k (Point2 (-4.5 + fromIntegral (k `mod` 18) * 0.52) (-4.5 + fromIntegral (k `div` 18) * 0.52)) 0
                 | k <- [0 .. 59] ]
        corner = OTBall (Point2 4.5 4.5)
    it "accepts 1284 balls piled in the notes' 100 m^2 (all but one: 90.69 m^2 of discs) and refuses the 1285th (it took 1414, 99.95 m^2, which can never lie apart)" $ do
      problems (replicate 1284 ball) `shouldBe` []
      problems (replicate 1285 ball)
        `shouldBe` [ "ball at (0.0, 0.0): the 1285 balls up to this one cover 90.83 m^2, and all but one of them "
                     ++ "90.76 m^2, more than the 90.69 m^2 that equal discs can cover of the world's 100.00 m^2 "
                     ++ "(at most pi / sqrt 12, about 90.69%, of a floor): they can never all lie apart, and a pile "
                     ++ "that cannot spread stalls the simulation" ]
    it "is pi / sqrt 12, the hexagonal packing's share: 1283 discs of a ball in 100 m^2 fit, 1284 do not" $ do
      densestPacking `shouldSatisfy` (\d -> abs (d - 0.9069) < 1e-4)
      let discOfBall = pi * 0.15 * 0.15 :: Double in (1283 * discOfBall <= densestPacking * 100, 1284 * discOfBall <= densestPacking * 100) `shouldBe` (True, False)
    it "reports the first ball past the area, once, however many follow" $
      map fst (worldProblems notesBounds (map ((,) "") (OTBlock (Point2 4 4) : replicate 3000 ball)))
        `shouldBe` [1285]
    it "takes the robots' discs off the floor, wherever they stand in the list" $ do
      -- 60 robots: 11.78 m^2, so 88.22 m^2 for the balls: 1248 (88.22) fit, 1249 (88.29) do not
      problems (robots ++ replicate 1248 corner) `shouldBe` []
      map fst (worldProblems notesBounds (map ((,) "") (replicate 1249 corner ++ robots)))
        `shouldBe` [1248]
      problems (robots ++ replicate 1249 corner)
        `shouldSatisfy` (\ps -> case ps of
                           [p] -> "the 1249 balls up to this one cover 88.29 m^2, more than the 88.22 m^2 of floor that the robots leave (the world's 100.00 m^2 less the robots' 11.78 m^2)" `isInfixOf` p
                           _   -> False)
    it "measures the floor by the world's size" $ do
      -- (200 m^2: all but one of 2567 balls cover 181.39, of 2568 181.46; 181.38 fit)
      problems (OTSize 20 10 : replicate 2567 ball) `shouldBe` []
      map fst (worldProblems notesBounds (map ((,) "") (OTSize 20 10 : replicate 2568 ball)))
        `shouldBe` [2568]
    it "takes robots that overlap (reported) as leaving no floor, and says one ball in the singular" $
      map snd (worldProblems notesBounds (map ((,) "") (replicate 600 (OTSimbotA 1 (Point2 0 0) 0) ++ [ball])))
        `shouldSatisfy` (any ("ball at (0.0, 0.0): this ball covers 0.07 m^2, more than the 0.00 m^2 of floor that the robots leave (the world's 100.00 m^2 less the robots' 117.81 m^2)" `isInfixOf`))
    it "counts only the balls inside the world" $
      problems (replicate 1284 ball ++ [OTBall (Point2 20 0)])
        `shouldBe` ["ball at (20.0, 0.0): lies (partly) outside the world [-5.0, 5.0] x [-5.0, 5.0]"]
  describe "validateWorld: ids" $ do
    it "names both robots that share an id" $
      problems [OTSimbotB 2 (Point2 0 0) 0, OTSimbotB 2 (Point2 2 0) 0]
        `shouldBe` ["SimbotB 2 at (2.0, 0.0) has the same id as SimbotB 2 at (0.0, 0.0)"]
    it "takes ids from -2^53 to 2^53, and refuses larger ones (JSON readers took 2^53 + 1 as 2^53)" $ do
      let big = fromInteger maxRobotId :: Int
      problems [OTSimbotA big (Point2 0 0) 0, OTSimbotB (negate big) (Point2 2 0) 0] `shouldBe` []
      map (takeWhile (/= ':')) (problems [ OTSimbotA (big + 1) (Point2 0 0) 0, OTSimbotB maxBound (Point2 2 0) 0
                                         , OTSimbotA (negate big - 1) (Point2 (-2) 0) 0, OTSimbotB minBound (Point2 0 2) 0 ])
        `shouldBe` [ "SimbotA 9007199254740993 at (0.0, 0.0)", "SimbotB 9223372036854775807 at (2.0, 0.0)"
                   , "SimbotA -9007199254740993 at (-2.0, 0.0)", "SimbotB -9223372036854775808 at (0.0, 2.0)" ]
      problems [OTSimbotA (big + 1) (Point2 0 0) 0]
        `shouldSatisfy` all ("a robot id must be from -2^53 to 2^53" `isInfixOf`)

  where
    placed o = let Point2 x y = otPos o
                   (hw, hh) = objectHalfSize o
               in x - hw >= -5 && x + hw <= 5 && y - hh >= -5 && y + hh <= 5
    bad a b = case (radius a, radius b) of
      (Just ra, Just rb) -> (isRobot a || isRobot b) && norm (otPos a .-. otPos b) < ra + rb - 1e-9
      (Just ra, Nothing) -> discBox (otPos a) ra b
      (Nothing, Just rb) -> discBox (otPos b) rb a
      _                  -> False
    isRobot o = case o of { OTSimbotA {} -> True; OTSimbotB {} -> True; _ -> False }
    radius o = case o of
      OTBall {}    -> Just 0.15
      OTSimbotA {} -> Just 0.25
      OTSimbotB {} -> Just 0.25
      _            -> Nothing
    -- the distance from the disc's centre to the rectangle, below its radius
    discBox (Point2 cx cy) r box =
      let Point2 bx by = otPos box
          (hw, hh) = objectHalfSize box
          dx = max 0 (abs (cx - bx) - hw)
          dy = max 0 (abs (cy - by) - hh)
      in dx * dx + dy * dy < (r - 1e-9) * (r - 1e-9)
    genObject = do
      p <- Point2 <$> choose (-3, 3) <*> choose (-3, 3)
      i <- choose (1, 1000)
      elements [OTBlock p, OTVWall p, OTHWall p, OTBall p, OTSimbotA i p 0, OTSimbotB i p 0]

