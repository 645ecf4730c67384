#!/usr/bin/env bash
# Runs the long-running networks for N and 10 N samples, the simulator
# (10 simbots, the benchmark world, dt = 0.01) for N/10 and N steps, and
# each stateful combinator inside a loop, the testing kit's evalT, runT (of the
# world states and, with onRobot, of one robot's) and
# writeRunReplayPage, and
# prints the maximum residency that the GHC runtime reports (+RTS -s).
# Constant space means the two figures of a row agree (within GC sampling
# noise).
#   bench/residency.sh [N]      (default N = 1000000: 10^7 samples of each
#                                network, 10^6 simulator steps)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-1000000}
cabal build -v0 --enable-benchmarks afrp-bench
bin=$(cabal list-bin -v0 --enable-benchmarks afrp-bench)
residency() {
  "$bin" "$@" +RTS -s 2>&1 >/dev/null | awk '/maximum residency/ {print $1}'
}
printf '%-17s %12s %22s\n' run length "max residency (bytes)"
for key in b d "d'" f g; do
  for m in "$n" "$((n * 10))"; do
    printf '%-17s %12s %22s\n' "network $key" "$m" "$(residency --run "$key" "$m")"
  done
done
for m in "$((n / 10))" "$n"; do
  printf '%-17s %12s %22s\n' "10 simbots" "$m" "$(residency --sim 10 "$m")"
done
# Every stateful combinator watching a signal fed back through a loop
# (bench/Residency.hs): its output discarded, and used (NAME+). loopPre's
# body here is a lazy accumulator (each state a thunk of the previous one):
# with its output discarded nobody evaluates it, so it grows without bound
# (as in Yampa; see bench/README.md) and is run with its output used only.
for key in edge iEdge edgeJust edgeBy once takeEvents dropEvents hold accumHold accumBy delayEvent \
           integral imIntegral trapezoid derivative switch rSwitch kSwitch left parZ \
           pSwitchB rpSwitchB loopIntegral sscan sscanPrim iterFrom pause parC \
           delay sampleWindow loopPre; do
  case $key in
    loopPre) variants="$key+" ;;
    *)                          variants="$key $key+" ;;
  esac
  for v in $variants; do
    for m in "$n" "$((n * 10))"; do
      printf '%-17s %12s %22s\n' "loop $v" "$m" "$(residency --loop "$v" "$m")"
    done
  done
done
# The testing kit's evalT on a stream made lazily (afrp-test/bench/LTLResidency.hs):
# each predicate owes a bounded number of obligations (nested: an Eventually
# whose argument holds at every sample; never: one that never holds; both:
# a conjunction whose first operand only the end decides), and explainT of
# a predicate that fails at the last sample.
cabal build -v0 --enable-benchmarks afrp-test:bench:afrp-test-residency
kit=$(cabal list-bin -v0 --enable-benchmarks afrp-test-residency)
for key in always implies eventually until window nested never both explain; do
  for m in "$n" "$((n * 10))"; do
    printf '%-17s %12s %22s\n' "$( [ "$key" = explain ] && echo explainT || echo "evalT $key")" "$m" \
      "$("$kit" "$key" "$m" +RTS -s 2>&1 >/dev/null | awk '/maximum residency/ {print $1}')"
  done
done
# runT on a run of three simbots (the predicate holds), N/10 and N steps of
# 0.01 s; onRobot: runT of a predicate on one of them; runTLate: runT of a
# predicate that fails at the run's last step (decided and explained there)
for key in runT onRobot runTLate; do
  for m in "$((n / 10))" "$n"; do
    printf '%-17s %12s %22s\n' "$key" "$m" \
      "$("$kit" "$key" "$m" +RTS -s 2>&1 >/dev/null | awk '/maximum residency/ {print $1}')"
  done
done
# writeRunReplayPage on that run (recorded as it goes), N/10 and N steps
for m in "$((n / 10))" "$n"; do
  printf '%-17s %12s %22s\n' "page" "$m" \
    "$("$kit" page "$m" +RTS -s 2>&1 >/dev/null | awk '/maximum residency/ {print $1}')"
done
