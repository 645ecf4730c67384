#!/usr/bin/env bash
# The simulator from 10 to 10,000 simbots (the benchmark world of
# bench/SimBench.hs: 10 m^2 per robot, the notes' density; a wall follower
# reading four range finders and the tracker; dt = 0.01) and the 100 packed
# wanderers, each on one core and on two, timed after the run's start
# (afrp-bench --steady / --steady-packed). Writes bench/scaling.tsv and
# draws bench/scaling.svg from it (bench/plot-scaling.py). One row per
# run, its columns:
#   what, robots, world side, cores, steps; robot-steps per second by the
#   wall clock; x real time; microseconds of CPU per robot-step;
#   load: the 1-minute load average before the run (the machine is
#     shared);
#   latency_ns: the one-way latency between the first two processors this
#     program may use just before the run, as bench/cores.sh measures it
#     (- with one processor). On a virtual machine the host moves its
#     processors from minute to minute, and two cores give the step much
#     less when they are far apart. The runs are kept to those two
#     processors (taskset).
#   bench/scaling.sh [R]        (R runs of each, the fastest kept: the
#                                machine is shared; default 3, about three
#                                minutes on the 2-core machine)
# Both run with the settings afrp-bench is linked with, as the project's
# executables are (-A8m -qb0: an 8 MB allocation area, and on two cores
# the parallel collector sharing the minor collections' work too); two
# cores with +RTS -N2. (Until the eighteenth round of bench/README.md two
# cores ran with -N2 -A8m -qg, a sequential collector, chosen when the
# parallel one made two cores slower than one; with -qb0 the parallel one
# is the faster, as that round measured.)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/cores/lib.sh
repeats=${1:-3}
positive_int bench/scaling.sh R "$repeats"
cabal build -v0 --enable-benchmarks afrp-bench
bin=$(cabal list-bin -v0 --enable-benchmarks afrp-bench)
allowed_cpus
two=no
if [ "${#cpus[@]}" -ge 2 ]; then
  build=$(mktemp -d /tmp/afrp-scaling.XXXXXX)
  trap 'rm -rf "$build"' EXIT
  if build_pingpong "$build"; then two=yes; fi
fi
latency() {
  if [ $two = yes ]; then latency_ns bench/scaling.sh "$build/pingpong" "${cpus[0]}" "${cpus[1]}" || echo -; else echo -; fi
}
# a run on the first two processors (all of them with fewer)
on2() {
  if [ "${#cpus[@]}" -ge 2 ]; then taskset -c "${cpus[0]},${cpus[1]}" "$@"; else "$@"; fi
}
out=bench/scaling.tsv
printf 'what\trobots\tside_m\tcores\tsteps\trobot_steps_per_s\tx_real_time\tcpu_us_per_robot_step\tload\tlatency_ns\n' > "$out"
row() {  # what robots side cores steps -- afrp-bench arguments
  local what=$1 robots=$2 side=$3 cores=$4 steps=$5; shift 6
  local rts=(-N1)
  if [ "$cores" = 2 ]; then rts=(-N2); fi
  local line load lat best=0 try r
  load=$(cut -d' ' -f1 /proc/loadavg)
  lat=$(latency)
  for ((r = 0; r < repeats; r++)); do
    try=$(on2 "$bin" "$@" +RTS "${rts[@]}" -RTS)
    echo "$try" >&2
    local tr
    tr=$(wall_rate bench/scaling.sh <<<"$try")
    if [ "$tr" -gt "$best" ]; then best=$tr; line=$try; fi
  done
  # "... N robot-steps/s (wall), X x real time (...; CPU ...: ..., U us each; ...)"
  local rate x us
  rate=$(wall_rate bench/scaling.sh <<<"$line")
  x=$(sed -E 's/.*, +([0-9.]+)x real time.*/\1/' <<<"$line")
  us=$(sed -E 's/.*, ([0-9.]+) us each.*/\1/' <<<"$line")
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$what" "$robots" "$side" "$cores" "$steps" "$rate" "$x" "$us" "$load" "$lat" >> "$out"
}
# one core and two cores one after the other for each size, so that both
# see about the same load
for size in "10 10 20000" "100 31.6 4000" "1000 100 400" "3000 173 100" "10000 316 40"; do
  read -r n side steps <<<"$size"
  for cores in 1 2; do row bench "$n" "$side" "$cores" "$steps" -- --steady "$n" "$steps"; done
done
for cores in 1 2; do row packed 100 10 "$cores" 3000 -- --steady-packed 100 3000; done
python3 bench/plot-scaling.py "$out" bench/scaling.svg
echo "wrote $out and bench/scaling.svg" >&2
