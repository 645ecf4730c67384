#!/usr/bin/env bash
# The simulator from 10 to 10,000 simbots (the benchmark world of
# bench/SimBench.hs: 10 m^2 per robot, the notes' density; a wall follower
# reading four range finders and the tracker; dt = 0.01) and the 100 packed
# wanderers, each on one core and on two, timed after the run's start
# (afrp-bench --steady / --steady-packed). Writes bench/scaling.tsv (one
# row per run: what, robots, world side, cores, steps, robot-steps per
# second by the wall clock, x real time, microseconds of CPU per
# robot-step, the 1-minute load average before the run: the machine is
# shared) and draws bench/scaling.svg from it (bench/plot-scaling.py).
#   bench/scaling.sh            (about a minute on the 2-core machine)
# One core runs with the runtime's defaults; two cores with +RTS -N2
# -A16m -qg (a larger allocation area per core and a sequential
# collector: with the defaults every collection stops both cores every
# megabyte of allocation, and two cores are slower than one).
set -euo pipefail
cd "$(dirname "$0")/.."
cabal build -v0 --enable-benchmarks afrp-bench
bin=$(find dist-newstyle -type f -perm -u+x -name afrp-bench | head -1)
out=bench/scaling.tsv
printf 'what\trobots\tside_m\tcores\tsteps\trobot_steps_per_s\tx_real_time\tcpu_us_per_robot_step\tload\n' > "$out"
row() {  # what robots side cores steps -- afrp-bench arguments
  local what=$1 robots=$2 side=$3 cores=$4 steps=$5; shift 6
  local rts=(-N1)
  if [ "$cores" = 2 ]; then rts=(-N2 -A16m -qg); fi
  local line load
  load=$(cut -d' ' -f1 /proc/loadavg)
  line=$("$bin" "$@" +RTS "${rts[@]}" -RTS)
  echo "$line" >&2
  # "... N robot-steps/s (wall), X x real time (...; CPU ...: ..., U us each; ...)"
  local rate x us
  rate=$(sed -E 's/.*: +([0-9]+) robot-steps\/s \(wall\).*/\1/' <<<"$line")
  x=$(sed -E 's/.*, +([0-9.]+)x real time.*/\1/' <<<"$line")
  us=$(sed -E 's/.*, ([0-9.]+) us each.*/\1/' <<<"$line")
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$what" "$robots" "$side" "$cores" "$steps" "$rate" "$x" "$us" "$load" >> "$out"
}
for cores in 1 2; do
  row bench 10 10 "$cores" 20000 -- --steady 10 20000
  row bench 100 31.6 "$cores" 4000 -- --steady 100 4000
  row bench 1000 100 "$cores" 400 -- --steady 1000 400
  row bench 3000 173 "$cores" 100 -- --steady 3000 100
  row bench 10000 316 "$cores" 40 -- --steady 10000 40
  row packed 100 10 "$cores" 3000 -- --steady-packed 100 3000
done
python3 bench/plot-scaling.py "$out" bench/scaling.svg
echo "wrote $out and bench/scaling.svg" >&2
