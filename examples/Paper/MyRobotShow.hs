module MyRobotShow where

import AFrob
import AFrobRobotSim

main :: IO ()
main = runSim (Just world) rcA rcB

world :: WorldTemplate
world =
  [ OTSimbotA 1 (Point2 (-4.2) 0.5) 0       -- below a long wall, the wall on its left
  , OTSimbotB 1 (Point2 0 (-2)) 0 ]         -- in a lane between two walls
  ++ [ OTHWall (Point2 x 1) | x <- [-4.5, -3.5 .. 4.5] ]
  ++ [ OTVWall (Point2 x (-2)) | x <- [-3, 3] ]

rcA :: SimbotController -- controller for simbot A's
rcA _ = arr rfLeft >>> (identity &&& derivative) >>> arr steer
  where
    -- the notes' PD wall follower (rcFollowLeftWall 0.3 0.25)
    steer (r, dr) = mrFinalize (ddVelTR v (max (-0.2) (min 0.2 (kp * (r - d) + kd * dr))))
    v  = 0.3
    d  = 0.25
    kd = 5
    kp = v * kd * kd / 4

rcB :: SimbotController -- controller for simbot B's
rcB rps = bounce (rpWSMax rps / 2)
  where
    -- the notes' rcReverse: back off and say "Ouch!!" whenever stuck
    bounce v = (rsStuck >>> arr (out v)) `dSwitch` \() -> bounce (negate v)
    out v stuckE =
      (mrFinalize (ddVelDiff v v `mrMerge` tcoPrintMessage (stuckE `tag` "Ouch!!")), stuckE)
