#!/usr/bin/env bash
# What two cores give the simulator, against what they give work that
# shares nothing, in alternating rounds (the machine is shared, and on a
# virtual machine where the host puts its two processors changes from
# minute to minute). Each round measures, one after the other:
#   latency   the one-way latency of a cache line between the two
#             processors (bench/cores/pingpong.c, as bench/cores.sh);
#   one       afrp-bench --steady N S +RTS -N1: one run on one core;
#   side      afrp-bench --side-by-side N S +RTS -N2: two runs at once in
#             one program, each stepped alone on its own capability
#             (what the program's runtime allows, its collector shared);
#   parallel  afrp-bench --steady N S +RTS -N2: one run, its step in
#             parallel (what the issue's "two cores" figure measures);
#   programs  two programs of afrp-bench --steady N S +RTS -N1 at once
#             (what the machine allows), counted as side is: their work
#             over the longer of their two timed windows;
# and prints each as robot-steps per second by the wall clock, with its
# ratio to 'one', then the medians of the ratios, and of parallel over
# programs (how much of what the machine gives the step takes), over the
# rounds in each band of latency (below 70 ns, 70-149, 150 and above).
# Every run is kept to the first two processors this program may use
# (taskset), the pair whose latency is measured; each of the two
# programs to one of them.
#   bench/side-by-side.sh [ROUNDS [ROBOTS [STEPS]]]   (default 8 1000 400)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/cores/lib.sh
rounds=${1:-8}
robots=${2:-1000}
steps=${3:-400}
positive_int bench/side-by-side.sh ROUNDS "$rounds"
positive_int bench/side-by-side.sh ROBOTS "$robots"
positive_int bench/side-by-side.sh STEPS "$steps"
allowed_cpus
if [ "${#cpus[@]}" -lt 2 ]; then
  echo "bench/side-by-side.sh: one processor to run on (${allowed}): nothing to compare" >&2
  exit 0
fi
first=${cpus[0]}
second=${cpus[1]}
cabal build -v0 --enable-benchmarks afrp-bench
bin=$(cabal list-bin -v0 --enable-benchmarks afrp-bench)
build=$(mktemp -d /tmp/afrp-side.XXXXXX)
other=
trap 'if [ -n "$other" ]; then kill "$other" 2>/dev/null || true; fi; rm -rf "$build"' EXIT
trap 'exit 143' TERM HUP
build_pingpong "$build"
# every run on the two processors measured (the runtime's threads may
# move between them, as on any two)
on2() { taskset -c "$first,$second" "$@"; }
# robot-steps per second from a file of afrp-bench's output (a message
# and a failure if it has none)
rate() { wall_rate bench/side-by-side.sh < "$1"; }
out=$build/rounds
for ((r = 1; r <= rounds; r++)); do
  lat=$(latency_ns bench/side-by-side.sh "$build/pingpong" "$first" "$second")
  on2 "$bin" --steady "$robots" "$steps" +RTS -N1 -RTS > "$build/one"
  on2 "$bin" --side-by-side "$robots" "$steps" +RTS -N2 -RTS > "$build/side"
  on2 "$bin" --steady "$robots" "$steps" +RTS -N2 -RTS > "$build/par"
  taskset -c "$first" "$bin" --steady "$robots" "$steps" +RTS -N1 -RTS > "$build/a" &
  other=$!
  taskset -c "$second" "$bin" --steady "$robots" "$steps" +RTS -N1 -RTS > "$build/b"
  wait "$other"
  other=
  one=$(rate "$build/one")
  side=$(rate "$build/side")
  par=$(rate "$build/par")
  pa=$(rate "$build/a")
  pb=$(rate "$build/b")
  # both programs' work over the longer of their two timed windows (the
  # basis of --side-by-side's figure: work over the time until the last
  # run ends), that is twice the slower program's rate
  progs=$(( 2 * (pa < pb ? pa : pb) ))
  echo "$lat $one $side $par $progs" >> "$out"
  awk -v l="$lat" -v o="$one" -v s="$side" -v p="$par" -v q="$progs" 'BEGIN {
    printf "latency %4d ns  one %8d  side %8d (%.2f)  parallel %8d (%.2f)  programs %8d (%.2f)\n",
           l, o, s, s / o, p, p / o, q, q / o }'
done
python3 - "$out" "$robots" <<'EOF'
import statistics, sys
rows = [list(map(int, l.split())) for l in open(sys.argv[1])]
bands = (("below 70 ns", 0, 70), ("70-149 ns", 70, 150), ("150 ns and above", 150, 10 ** 9))
for name, lo, hi in bands:
    rs = [r for r in rows if lo <= r[0] < hi]
    if not rs:
        continue
    med = lambda f: statistics.median(f(r) for r in rs)
    print("%s robots, %d round%s with the latency %s: medians side %.2f, parallel %.2f, programs %.2f;"
          " parallel / programs %.2f"
          % (sys.argv[2], len(rs), "" if len(rs) == 1 else "s", name,
             med(lambda r: r[2] / r[1]), med(lambda r: r[3] / r[1]), med(lambda r: r[4] / r[1]),
             med(lambda r: r[3] / r[4])))
EOF
