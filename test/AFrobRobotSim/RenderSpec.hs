-- | The renderer: PPM frames checked pixel by pixel, and the SVG picture.
module AFrobRobotSim.RenderSpec (spec) where

import qualified Data.ByteString       as B
import qualified Data.ByteString.Char8 as BC
import           Data.List             (isInfixOf, isPrefixOf, isSuffixOf, tails)
import           Test.Hspec            hiding (after)
import           Test.QuickCheck

import           AFrob                 hiding (forAll)
import           AFrobRobotSim
import           AFrobRobotSim.Render

scene :: WorldTemplate -> Scene
scene = Scene notesBounds

style :: RenderStyle
style = defaultRenderStyle

-- | A snapshot with the given robots and balls, at time 0.
snapshot :: [RobotState] -> [Position2] -> WorldState
snapshot rs bs = WorldState { wsTime = 0, wsRobots = rs, wsBalls = bs, wsMessages = [], wsScores = [] }

-- | A robot at rest.
robotAt :: RobotType -> RobotId -> Position2 -> Heading -> Bool -> RobotState
robotAt ty i p h stuck = RobotState
  { robotType = ty, robotId = i, robotPos = p, robotHeading = h, robotSpeed = 0
  , robotStuck = stuck, robotBattery = BSHigh, robotCharge = 1, robotOdometry = p }

-- | The colour of the pixel containing a world point.
pixelAtWorld :: RenderStyle -> Scene -> B.ByteString -> Position2 -> Maybe Colour
pixelAtWorld st sc img p = let (x, y) = worldToPixel st sc p in ppmPixel img (floor x) (floor y)

-- | The pixels of a rectangle of pixels (inclusive corners).
pixelsIn :: B.ByteString -> (Int, Int) -> (Int, Int) -> [Maybe Colour]
pixelsIn img (i0, j0) (i1, j1) = [ ppmPixel img i j | j <- [j0 .. j1], i <- [i0 .. i1] ]

occurrences :: String -> String -> Int
occurrences needle hay = length (filter (needle `isPrefixOf`) (tails hay))

driveAt :: Velocity -> Velocity -> SimbotController
driveAt vl vr _ = constant (mrFinalize (ddVelDiff vl vr))

spec :: Spec
spec = do
  describe "worlds of any size" $ do
    let wide = Scene notesBounds [OTSize 30 10, OTSimbotA 1 (Point2 12 0) 0]
        wideStyle = style { styleScale = fitScale (sceneExtent wide) }
    it "fitScale keeps the long side at 600 pixels: 60 px/m for the notes' world, 6 for 100 m, 20 for 30 by 10" $ do
      fitScale notesBounds `shouldBe` 60
      fitScale (sizeBounds 100 100) `shouldBe` 6
      fitScale (sizeBounds 30 10) `shouldBe` 20
      fitScale (sizeBounds 10 1000) `shouldBe` 0.6
    it "a 30 by 10 world's frame is 620 by 220 pixels (its size wins over the scene's bounds)" $ do
      sceneExtent wide `shouldBe` Bounds (-15) (-5) 15 5
      frameSize wideStyle wide `shouldBe` (620, 220)
      BC.take 15 (renderPPM wideStyle wide [] (snapshot [] [])) `shouldBe` BC.pack "P6\n620 220\n255\n"
    it "draws a robot near the far end of a 30 by 10 world" $ do
      let img = renderPPM wideStyle wide [] (snapshot [robotAt "SimbotA" 1 (Point2 12 0) 0 False] [])
      pixelAtWorld wideStyle wide img (Point2 11.9 0.1) `shouldBe` Just (robotColour "SimbotA" 0)
      pixelAtWorld wideStyle wide img (Point2 14.9 4.9) `shouldBe` Just backgroundColour
    it "start markers shrink to a robot's size in a big world (at least 2 pixels), 5 pixels otherwise" $ do
      let marker w st = renderSVG st (Scene notesBounds w) (take 2 (simulate 0.01 w (driveAt 0 0) (driveAt 0 0)))
          big   = [OTSize 100 100, OTSimbotA 1 (Point2 0 0) 0]
          small = [OTSimbotA 1 (Point2 0 0) 0]
          at r  = "r=\"" ++ r ++ "\" fill=\"" ++ hexOf (typeColour "SimbotA") ++ "\""
      occurrences (at "2.0") (marker big style { styleScale = 6 }) `shouldBe` 1
      occurrences (at "3.0") (marker big style { styleScale = 12 }) `shouldBe` 1
      occurrences (at "5.0") (marker small style) `shouldBe` 1
    it "a 30 by 10 world's SVG has the frame's height and a viewBox 170 pixels wider" $
      renderSVG wideStyle wide [] `shouldSatisfy` ("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"790\" height=\"220\" viewBox=\"0 0 790 220\">" `isPrefixOf`)
  describe "frameSize" $ do
    it "is 600 by 600 plus a 10-pixel margin for the notes' world at 60 px/m" $
      frameSize style (scene []) `shouldBe` (620, 620)
    it "follows the world's extent and the scale" $
      frameSize (RenderStyle 50 False False) (Scene (Bounds 0 0 4 2) []) `shouldBe` (220, 120)

  describe "renderPPM" $ do
    let world = [ OTVWall (Point2 2 1), OTHWall (Point2 (-2) (-3)), OTBlock (Point2 3 (-3)) ]
        sc    = scene world
        ws    = snapshot [ robotAt "SimbotA" 1 (Point2 1.03 (-0.77)) 0.4 False
                         , robotAt "SimbotB" 2 (Point2 (-3) 2.5) 2 False
                         , robotAt "SimbotA" 3 (Point2 (-1) (-1)) 0 True ]
                         [Point2 0 3]
        img   = renderPPM style sc [] ws
        at    = pixelAtWorld style sc img
    it "is a P6 header and exactly 3 * w * h bytes of pixels" $ do
      let header = "P6\n620 620\n255\n"
      BC.unpack (B.take (length header) img) `shouldBe` header
      B.length img `shouldBe` length header + 3 * 620 * 620
    it "draws the floor inside the world and the boundary in the margin" $ do
      ppmPixel img frameMargin (619 - frameMargin) `shouldBe` Just backgroundColour
      ppmPixel img (619 - frameMargin) (619 - frameMargin) `shouldBe` Just backgroundColour
      ppmPixel img 0 0 `shouldBe` Just boundaryColour
      ppmPixel img 619 619 `shouldBe` Just boundaryColour
    it "draws a robot's body colour at its centre pixel" $ do
      at (Point2 1.03 (-0.77)) `shouldBe` Just (typeColour "SimbotA")
      at (Point2 (-3) 2.5) `shouldBe` Just (typeColour "SimbotB")
      typeColour "SimbotA" `shouldNotBe` typeColour "SimbotB"
    it "draws a stuck robot darker, with a black rim" $ do
      -- the second SimbotA of the list
      at (Point2 (-1) (-1)) `shouldBe` Just (robotBodyColour "SimbotA" 1 True)
      robotBodyColour "SimbotA" 1 True `shouldNotBe` robotColour "SimbotA" 1
      bodyColour "SimbotA" True `shouldNotBe` typeColour "SimbotA"
      at (Point2 (-1) (-1.24)) `shouldBe` Just (robotOutlineColour "SimbotA" 1 True)
    it "draws walls, blocks and balls in their colours at their centres" $ do
      at (Point2 2 1) `shouldBe` Just wallColour
      at (Point2 (-2) (-3)) `shouldBe` Just wallColour
      at (Point2 3 (-3)) `shouldBe` Just blockColour
      at (Point2 0 3) `shouldBe` Just ballColour
    it "y grows upwards: a wall at the top of the world is near the top of the image" $ do
      let top = renderPPM style (scene [OTHWall (Point2 0 4.9)]) [] (snapshot [] [])
      ppmPixel top 310 (frameMargin + 3) `shouldBe` Just wallColour
      ppmPixel top 310 (619 - frameMargin - 3) `shouldBe` Just backgroundColour
    it "marks the heading with a wedge towards the front edge" $ do
      let hd h = renderPPM style (scene []) [] (snapshot [robotAt "SimbotA" 1 (Point2 0 0) h False] [])
          front h = pixelAtWorld style (scene []) (hd h) (Point2 (0.15 * cos h) (0.15 * sin h))
          back h  = pixelAtWorld style (scene []) (hd h) (Point2 (-0.15 * cos h) (-0.15 * sin h))
      front 0 `shouldBe` Just headingColour
      front (pi / 2) `shouldBe` Just headingColour
      back (pi / 2) `shouldBe` Just (typeColour "SimbotA")
    it "writes each robot's id in digits next to it" $ do
      let (x, y) = worldToPixel style sc (Point2 1.03 (-0.77))
          near   = pixelsIn img (floor x + 5, floor y - 30) (floor x + 30, floor y - 5)
      Just labelColour `elem` near `shouldBe` True
    it "shows a robot moving: the pixels change at both its old and new places" $ do
      let world1 = [OTSimbotA 1 (Point2 (-2) 0) 0]
          run    = simulate 0.01 world1 (driveAt 0.5 0.5) (driveAt 0.5 0.5)
          s0     = head run
          s1     = run !! 500
          p0     = robotPos (head (wsRobots s0))
          p1     = robotPos (head (wsRobots s1))
          f0     = renderPPM style (scene world1) [] s0
          f1     = renderPPM style (scene world1) [] s1
      norm (p1 .-. p0) `shouldSatisfy` (> 1)
      pixelAtWorld style (scene world1) f0 p0 `shouldBe` Just (typeColour "SimbotA")
      pixelAtWorld style (scene world1) f1 p0 `shouldBe` Just backgroundColour
      pixelAtWorld style (scene world1) f0 p1 `shouldBe` Just backgroundColour
      pixelAtWorld style (scene world1) f1 p1 `shouldBe` Just (typeColour "SimbotA")
    it "tells robots of one type apart: six shades per type, each robot in its own" $ do
      let shadesOf t = map (robotColour t) [0 .. 5]
          distinct xs = and [ a /= b | (i, a) <- zip [0 :: Int ..] xs, (j, b) <- zip [0 ..] xs, i < j ]
      distinct (shadesOf "SimbotA" ++ shadesOf "SimbotB") `shouldBe` True
      typeRanks (wsRobots ws) `shouldBe` [0, 0, 1]
      let many = snapshot [ robotAt "SimbotB" i (Point2 (fromIntegral i - 3.5) 0) 0 False | i <- [1 .. 6] ] []
          imgM = renderPPM style sc [] many
      [ pixelAtWorld style sc imgM (Point2 (fromIntegral i - 3.5) 0.1) | i <- [1 .. 6 :: Int] ]
        `shouldBe` map Just (shadesOf "SimbotB")
    it "writes every id whole and inside the world, also at the world's edges" $ do
      let labelPixels p = length (filter (== Just labelColour)
                            (pixelsIn (renderPPM style (scene []) [] (snapshot [robotAt "SimbotA" 12345 p 0 False] []))
                                      (0, 0) (619, 619)))
          inMargin p = let f = renderPPM style (scene []) [] (snapshot [robotAt "SimbotA" 12345 p 0 False] [])
                       in filter (== Just labelColour)
                            [ ppmPixel f i j | j <- [0 .. 619], i <- [0 .. 619]
                            , i < frameMargin || j < frameMargin || i >= 620 - frameMargin || j >= 620 - frameMargin ]
          corners = [Point2 4.74 4.74, Point2 (-4.74) 4.74, Point2 4.74 (-4.74), Point2 (-4.74) (-4.74), Point2 4.74 0]
      map labelPixels corners `shouldBe` replicate 5 (labelPixels (Point2 0 0))
      map inMargin corners `shouldBe` replicate 5 []
    it "carries the simulated time, in the world's top-left corner" $ do
      let frameAt t = renderPPM style sc [] ws { wsTime = t }
          corner f = pixelsIn f (frameMargin, frameMargin) (frameMargin + 60, frameMargin + 14)
      corner (frameAt 0) `shouldNotBe` corner (frameAt 12.34)
      corner (frameAt 12.34) `shouldBe` corner (frameAt 12.34)
      Just labelColour `elem` corner (frameAt 12.34) `shouldBe` True
      Just headingColour `elem` corner (frameAt 12.34) `shouldBe` True
      -- the rest of the frame is the same
      B.drop (3 * 620 * 40) (frameAt 0) `shouldBe` B.drop (3 * 620 * 40) (frameAt 12.34)
    it "ends each ray in a dot of its robot's colour" $ do
      let world2 = [OTVWall (Point2 2 0)]
          sc2    = scene world2
          two    = snapshot [ robotAt "SimbotB" 1 (Point2 (-3) (-3)) 0 False
                            , robotAt "SimbotB" 2 (Point2 0 0) 0 False ] []
          rays   = renderPPM style { styleRays = True } sc2 [] two
      -- the second SimbotB's front ray ends at the wall, x = 1.95
      pixelAtWorld style sc2 rays (Point2 1.94 0) `shouldBe` Just (robotColour "SimbotB" 1)
      pixelAtWorld style sc2 rays (Point2 1 0) `shouldBe` Just rayColour
    it "is deterministic: the same inputs give the same bytes" $ do
      let st     = RenderStyle 60 True True
          trails = [[Point2 0 0, Point2 1 1], [Point2 (-3) 2, Point2 (-3) 2.5]]
      renderPPM st sc trails ws `shouldBe` renderPPM st sc trails ws
      renderPPM st sc trails ws `shouldNotBe` img
    it "with styleRays, draws the front ray in the ray colour up to the wall it meets" $ do
      let world2 = [OTVWall (Point2 2 0)]
          sc2    = scene world2
          ws2    = snapshot [robotAt "SimbotB" 1 (Point2 0 0) 0 False] []
          rays   = renderPPM style { styleRays = True } sc2 [] ws2
          plain  = renderPPM style sc2 [] ws2
      -- the front ray runs from the edge (x = 0.25) to the wall (x = 1.95)
      [ pixelAtWorld style sc2 rays (Point2 x 0) | x <- [0.4, 1, 1.5, 1.9] ]
        `shouldBe` replicate 4 (Just rayColour)
      [ pixelAtWorld style sc2 plain (Point2 x 0) | x <- [0.4, 1, 1.5, 1.9] ]
        `shouldBe` replicate 4 (Just backgroundColour)
      pixelAtWorld style sc2 rays (Point2 2.5 0) `shouldBe` Just backgroundColour
      -- the left ray is not blocked: 3 m from the edge
      pixelAtWorld style sc2 rays (Point2 0 3) `shouldBe` Just rayColour
      pixelAtWorld style sc2 rays (Point2 0 3.5) `shouldBe` Just backgroundColour
    it "with styleTrails, draws each robot's path in its trail colour" $ do
      let trails = [[Point2 (-4) 4, Point2 4 4], []]
          with   = renderPPM style { styleTrails = True } sc trails ws
          plain  = renderPPM style sc trails ws
      pixelAtWorld style sc with (Point2 0 4) `shouldBe` Just (trailColour "SimbotA")
      pixelAtWorld style sc plain (Point2 0 4) `shouldBe` Just backgroundColour
    it "puts a lone robot's body colour at its centre, wherever it is" $
      property $ forAll ((,,) <$> choose (-4.7, 4.7) <*> choose (-4.7, 4.7) <*> choose (-4, 4)) $
        \(x, y, h) ->
          let img1 = renderPPM style (scene []) [] (snapshot [robotAt "SimbotB" 7 (Point2 x y) h False] [])
          in pixelAtWorld style (scene []) img1 (Point2 x y) === Just (typeColour "SimbotB")
    it "ppmPixel reads nothing outside the image" $ do
      ppmPixel img 620 0 `shouldBe` Nothing
      ppmPixel img 0 (-1) `shouldBe` Nothing

  describe "renderSVG" $ do
    let world = [ OTSimbotA 1 (Point2 (-2) 0) 0, OTSimbotB 2 (Point2 2 2) 1
                , OTSimbotB 5 (Point2 0 (-3)) 3, OTVWall (Point2 3 0), OTBall (Point2 0 1) ]
        run   = take 3001 (simulate 0.01 world (driveAt 0.4 0.5) (driveAt 0.7 0.3))
        svg   = renderSVG style { styleRays = True } (scene world) run
    it "is an <svg> element from start to end" $ do
      svg `shouldSatisfy` ("<svg" `isPrefixOf`)
      svg `shouldSatisfy` ("</svg>\n" `isSuffixOf`)
      occurrences "<svg" svg `shouldBe` 1
    it "has one polyline per robot, in the robot's own colour" $ do
      occurrences "<polyline" svg `shouldBe` 3
      occurrences ("<polyline fill=\"none\" stroke=\"" ++ hexOf (typeColour "SimbotB")) svg `shouldBe` 1
      occurrences ("<polyline fill=\"none\" stroke=\"" ++ hexOf (robotColour "SimbotB" 1)) svg `shouldBe` 1
    it "shows each robot's colour in the legend, and the time of the last snapshot" $ do
      occurrences ("<circle cx=\"" ++ show (620 + 12 + 12 :: Int)) svg `shouldBe` 4
      occurrences ("r=\"6\" fill=\"" ++ hexOf (robotColour "SimbotB" 1)) svg `shouldBe` 1
      svg `shouldSatisfy` (">30.00</text>" `isInfixOf`)
    it "keeps each trajectory to at most 2000 points" $ do
      let polylines = filter ("<polyline" `isPrefixOf`) (lines svg)
          points l  = length (words (takeWhile (/= '"') (drop 1 (dropWhile (/= '"')
                        (snd (breakOn "points=" l))))))
      length polylines `shouldBe` 3
      map points polylines `shouldSatisfy` all (\n -> n > 1000 && n <= 2000)
    it "names every robot in the legend" $ do
      svg `shouldSatisfy` ("SimbotA 1<" `isInfixOf`)
      svg `shouldSatisfy` ("SimbotB 2<" `isInfixOf`)
      svg `shouldSatisfy` ("SimbotB 5<" `isInfixOf`)
    it "is deterministic, and draws just the world without snapshots" $ do
      renderSVG style (scene world) run `shouldBe` renderSVG style (scene world) run
      let empty = renderSVG style (scene world) []
      empty `shouldSatisfy` ("<svg" `isPrefixOf`)
      occurrences "<polyline" empty `shouldBe` 0
  where
    hexOf (Colour r g b) = '#' : concatMap hex2 [r, g, b]
    hex2 v = [digits !! (fromIntegral v `div` 16), digits !! (fromIntegral v `mod` 16)]
    digits = "0123456789abcdef"
    breakOn key str = case str of
      _ | key `isPrefixOf` str -> ("", str)
      []                       -> ("", "")
      ch : rest                -> let (a, b) = breakOn key rest in (ch : a, b)
