-- | The afrp test suite: one spec module per library module.
module Main (main) where

import           Test.Hspec

import qualified AFRP.BasicSpec
import qualified AFRP.ChainSpec
import qualified AFRP.Chain.RegroupSpec
import qualified AFRP.Chain.SumsSpec
import qualified AFRP.CollectionSpec
import qualified AFRP.ConditionalSpec
import qualified AFRP.DeferredSpec
import qualified AFRP.DelaySpec
import qualified AFRP.EventSource.EdgeSpec
import qualified AFRP.EventSource.ReshapeSpec
import qualified AFRP.EventSource.SampleSpec
import qualified AFRP.EventSource.TimedSpec
import qualified AFRP.EventSpec
import qualified AFRP.GeometrySpec
import qualified AFRP.HybridSpec
import qualified AFRP.IntegrationSpec
import qualified AFRP.LawsSpec
import qualified AFRP.LoopSpec
import qualified AFRP.LoopLazinessSpec
import qualified AFRP.NoiseSpec
import qualified AFRP.Node.FuseSpec
import qualified AFRP.NotesSpec
import qualified AFRP.OptimiserSpec
import qualified AFRP.ParallelFunctorSpec
import qualified AFRP.ParallelSpec
import qualified AFRP.ReferenceSpec
import qualified AFRP.ResidencySpec
import qualified AFRP.RunSpec
import qualified AFRP.ScanSpec
import qualified AFRP.SwitchSpec
import qualified AFRP.TaskSpec
import qualified AFRP.TimeAccountingSpec
import qualified AFRP.VectorSpaceSpec
import qualified AFRP.YampaNamesSpec
import qualified AFrob.AngleSpec
import qualified AFrob.MergeableRecordSpec
import qualified AFrob.RobotIOSpec
import qualified AFrobRobotSim.ArenaSpec
import qualified AFrobRobotSim.ClearanceSpec
import qualified AFrobRobotSim.ConsoleSpec
import qualified AFrobRobotSim.FlatArraySpec
import qualified AFrobRobotSim.InputFileSpec
import qualified AFrobRobotSim.JSONSpec
import qualified AFrobRobotSim.JSON.BytesSpec
import qualified AFrobRobotSim.JSON.Bytes.ScanSpec
import qualified AFrobRobotSim.JSON.EncodeSpec
import qualified AFrobRobotSim.LogSpec
import qualified AFrobRobotSim.Log.ReadSpec
import qualified AFrobRobotSim.Log.RecordsSpec
import qualified AFrobRobotSim.ReplayBrowserSpec
import qualified AFrobRobotSim.ReplaySpec
import qualified AFrobRobotSim.ResultSpec
import qualified AFrobRobotSim.Replay.CommandLineSpec
import qualified AFrobRobotSim.Replay.RecorderSpec
import qualified AFrobRobotSim.NearbySpec
import qualified AFrobRobotSim.NotesSection3Spec
import qualified AFrobRobotSim.OptionsSpec
import qualified AFrobRobotSim.OutputFileSpec
import qualified AFrobRobotSim.PhysicsSpec
import qualified AFrobRobotSim.BallsSpec
import qualified AFrobRobotSim.ChunksSpec
import qualified AFrobRobotSim.RayCastSpec
import qualified AFrobRobotSim.Run.SinksSpec
import qualified AFrobRobotSim.RayGridSpec
import qualified AFrobRobotSim.RefereeSpec
import qualified AFrobRobotSim.RenderSpec
import qualified AFrobRobotSim.RunSpec
import qualified AFrobRobotSim.SensorsSpec
import qualified AFrobRobotSim.Shapes.BoxSpec
import qualified AFrobRobotSim.Shapes.CollisionSpec
import qualified AFrobRobotSim.Shapes.RaySpec
import qualified AFrobRobotSim.SweepSpec
import qualified Examples.CommandLineSpec
import qualified Examples.Exercises14and15Spec
import qualified Examples.Exercises1to6Spec
import qualified Examples.Exercises7to13Spec
import qualified Examples.Section2Spec
import qualified Examples.RegistrySpec
import qualified Examples.Section3Spec
import qualified AFrobRobotSim.SimulatorSpec
import qualified AFrobRobotSim.SpatialIndexSpec
import qualified AFrobRobotSim.UTF8Spec
import qualified AFrobRobotSim.WorldFileSpec
import qualified AFrobRobotSim.WorldFile.GrammarSpec
import qualified AFrobRobotSim.WorldSpec
import qualified AFrobRobotSim.World.CheckSpec
import qualified AFrobRobotSim.WorkersSpec
import qualified AFrobRobotSim.PipelineSpec
import qualified NetworksSpec
import qualified SwarmSpec
import qualified Ported.BouncingBallSpec
import qualified Ported.CarTrackerSpec
import           System.Environment (lookupEnv)

main :: IO ()
main = lookupEnv AFrobRobotSim.SweepSpec.childVariable >>= maybe runChild AFrobRobotSim.SweepSpec.child
  where runChild = lookupEnv AFrobRobotSim.RunSpec.childVariable >>= maybe loopChild AFrobRobotSim.RunSpec.child
        loopChild = lookupEnv AFRP.ResidencySpec.childVariable >>= maybe examplesChild AFRP.ResidencySpec.child
        examplesChild = lookupEnv Examples.CommandLineSpec.childVariable >>= maybe specs Examples.CommandLineSpec.child

specs :: IO ()
specs = hspec $ do
  describe "AFRP.Basic"       AFRP.BasicSpec.spec
  describe "AFRP.Internal.Chain" AFRP.ChainSpec.spec
  describe "AFRP.Internal.Chain.Sums" AFRP.Chain.SumsSpec.spec
  describe "AFRP.Internal.Chain.Regroup" AFRP.Chain.RegroupSpec.spec
  describe "AFRP.Internal.Node.Fuse" AFRP.Node.FuseSpec.spec
  describe "AFRP.Conditional" AFRP.ConditionalSpec.spec
  describe "AFRP.Internal.Deferred" AFRP.DeferredSpec.spec
  describe "AFRP.Event"       AFRP.EventSpec.spec
  describe "AFRP.EventSource.Timed" AFRP.EventSource.TimedSpec.spec
  describe "AFRP.EventSource.Edge" AFRP.EventSource.EdgeSpec.spec
  describe "AFRP.EventSource.Reshape" AFRP.EventSource.ReshapeSpec.spec
  describe "AFRP.EventSource.Sample" AFRP.EventSource.SampleSpec.spec
  describe "AFRP.Hybrid"      AFRP.HybridSpec.spec
  describe "AFRP.Delay"       AFRP.DelaySpec.spec
  describe "AFRP.Integration" AFRP.IntegrationSpec.spec
  describe "AFRP.Loop"        AFRP.LoopSpec.spec
  describe "AFRP.Loop laziness" AFRP.LoopLazinessSpec.spec
  describe "AFRP residency" AFRP.ResidencySpec.spec
  describe "AFRP.Switch"      AFRP.SwitchSpec.spec
  describe "AFRP.Parallel"    AFRP.ParallelSpec.spec
  describe "AFRP.Parallel"    AFRP.ParallelFunctorSpec.spec
  describe "AFRP.Internal.Collection" AFRP.CollectionSpec.spec
  describe "AFRP.Noise"       AFRP.NoiseSpec.spec
  describe "AFRP.Run"         AFRP.RunSpec.spec
  describe "AFRP.Scan"        AFRP.ScanSpec.spec
  describe "AFRP.Task"        AFRP.TaskSpec.spec
  describe "time accounting"  AFRP.TimeAccountingSpec.spec
  describe "AFRP.VectorSpace" AFRP.VectorSpaceSpec.spec
  describe "Yampa names"      AFRP.YampaNamesSpec.spec
  describe "AFRP.Geometry"    AFRP.GeometrySpec.spec
  describe "optimiser"        AFRP.OptimiserSpec.spec
  describe "reference model"  AFRP.ReferenceSpec.spec
  describe "arrow laws"       AFRP.LawsSpec.spec
  describe "the notes, section 2" AFRP.NotesSpec.spec
  describe "benchmark networks" NetworksSpec.spec
  describe "Swarm (the Enki comparison)" SwarmSpec.spec
  describe "AFrob.Angle"             AFrob.AngleSpec.spec
  describe "AFrob.MergeableRecord"   AFrob.MergeableRecordSpec.spec
  describe "AFrob.RobotIO"           AFrob.RobotIOSpec.spec
  describe "AFrobRobotSim.Shapes.Box" AFrobRobotSim.Shapes.BoxSpec.spec
  describe "AFrobRobotSim.Shapes.Ray" AFrobRobotSim.Shapes.RaySpec.spec
  describe "AFrobRobotSim.Shapes.Collision" AFrobRobotSim.Shapes.CollisionSpec.spec
  describe "AFrobRobotSim.Simulator" AFrobRobotSim.SimulatorSpec.spec
  describe "AFrobRobotSim.FlatArray" AFrobRobotSim.FlatArraySpec.spec
  describe "AFrobRobotSim.JSON"      AFrobRobotSim.JSONSpec.spec
  describe "AFrobRobotSim.JSON.Bytes" AFrobRobotSim.JSON.BytesSpec.spec
  describe "AFrobRobotSim.JSON.Bytes.Scan" AFrobRobotSim.JSON.Bytes.ScanSpec.spec
  describe "AFrobRobotSim.JSON.Encode" AFrobRobotSim.JSON.EncodeSpec.spec
  describe "AFrobRobotSim.Log"       AFrobRobotSim.LogSpec.spec
  describe "AFrobRobotSim.Log.Read"  AFrobRobotSim.Log.ReadSpec.spec
  describe "AFrobRobotSim.Log.Records" AFrobRobotSim.Log.RecordsSpec.spec
  describe "AFrobRobotSim.Replay"    AFrobRobotSim.ReplaySpec.spec
  describe "AFrobRobotSim.Replay.CommandLine" AFrobRobotSim.Replay.CommandLineSpec.spec
  describe "AFrobRobotSim.Replay.Recorder" AFrobRobotSim.Replay.RecorderSpec.spec
  describe "AFrobRobotSim.Result"    AFrobRobotSim.ResultSpec.spec
  describe "AFrobRobotSim.Replay in Chromium" AFrobRobotSim.ReplayBrowserSpec.spec
  describe "AFrobRobotSim.Arena"     AFrobRobotSim.ArenaSpec.spec
  describe "AFrobRobotSim.Clearance" AFrobRobotSim.ClearanceSpec.spec
  describe "AFrobRobotSim.Console"   AFrobRobotSim.ConsoleSpec.spec
  describe "AFrobRobotSim.InputFile" AFrobRobotSim.InputFileSpec.spec
  describe "AFrobRobotSim.Nearby" AFrobRobotSim.NearbySpec.spec
  describe "AFrobRobotSim.Options" AFrobRobotSim.OptionsSpec.spec
  describe "AFrobRobotSim.OutputFile" AFrobRobotSim.OutputFileSpec.spec
  describe "AFrobRobotSim.Physics" AFrobRobotSim.PhysicsSpec.spec
  describe "AFrobRobotSim.Balls" AFrobRobotSim.BallsSpec.spec
  describe "AFrobRobotSim.Chunks" AFrobRobotSim.ChunksSpec.spec
  describe "AFrobRobotSim.RayGrid" AFrobRobotSim.RayGridSpec.spec
  describe "AFrobRobotSim.RayCast" AFrobRobotSim.RayCastSpec.spec
  describe "AFrobRobotSim.SpatialIndex" AFrobRobotSim.SpatialIndexSpec.spec
  describe "AFrobRobotSim.Sensors" AFrobRobotSim.SensorsSpec.spec
  describe "AFrobRobotSim.UTF8" AFrobRobotSim.UTF8Spec.spec
  describe "the notes, section 3"    AFrobRobotSim.NotesSection3Spec.spec
  describe "AFrobRobotSim.WorldFile" AFrobRobotSim.WorldFileSpec.spec
  describe "AFrobRobotSim.WorldFile.Grammar" AFrobRobotSim.WorldFile.GrammarSpec.spec
  describe "AFrobRobotSim.World" AFrobRobotSim.WorldSpec.spec
  describe "AFrobRobotSim.World.Check" AFrobRobotSim.World.CheckSpec.spec
  describe "AFrobRobotSim.Workers" AFrobRobotSim.WorkersSpec.spec
  describe "AFrobRobotSim.Pipeline" AFrobRobotSim.PipelineSpec.spec
  describe "AFrobRobotSim.Referee"   AFrobRobotSim.RefereeSpec.spec
  describe "AFrobRobotSim.Render"    AFrobRobotSim.RenderSpec.spec
  describe "AFrobRobotSim.Run"       AFrobRobotSim.RunSpec.spec
  describe "AFrobRobotSim.Run.Sinks" AFrobRobotSim.Run.SinksSpec.spec
  describe "AFrobRobotSim.Sweep"     AFrobRobotSim.SweepSpec.spec
  describe "examples: section 2"     Examples.Section2Spec.spec
  describe "examples: section 3"     Examples.Section3Spec.spec
  describe "examples: the registry"  Examples.RegistrySpec.spec
  describe "examples: the command line" Examples.CommandLineSpec.spec
  describe "exercises 1-6"           Examples.Exercises1to6Spec.spec
  describe "exercises 7-13"          Examples.Exercises7to13Spec.spec
  describe "exercises 14 and 15"     Examples.Exercises14and15Spec.spec
  describe "ported Yampa programs"   Ported.CarTrackerSpec.spec
  describe "ported Yampa programs"   Ported.BouncingBallSpec.spec
