-- | @afrp-examples@: every program of the notes and a solution to each of
-- its exercises. (The fragments of sections 2.1 to 2.3, which are not
-- programs but single expressions, and the @rcA@ template of section 3,
-- which dispatches on ids a world must supply, are compiled and run in
-- the tests instead: @test/AFRP/NotesSpec.hs@ and
-- @test/AFrobRobotSim/NotesSection3Spec.hs@.) Its command line is
-- "Examples.CommandLine"'s.
--
-- > cabal run afrp-examples -- --list
-- > cabal run afrp-examples -- rcReverse --seconds 20 --svg reverse.svg
module Main (main) where

import           Examples.CommandLine (examplesMain)

main :: IO ()
main = examplesMain
