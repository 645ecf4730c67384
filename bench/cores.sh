#!/usr/bin/env bash
# How far apart this machine's processors are: the one-way latency of a
# cache line between the first processor this program may use and each
# other one (bench/cores/pingpong.c, built with the C compiler, $CC or cc,
# into a temporary directory, never part of the library). The simulator's
# parallel step passes robots' state from one core to the other at every
# step, so this number indicates what two cores can give it: a few tens of
# nanoseconds between cores that share a cache, a few hundred between
# chips or on a virtual machine's distant processors. (A program run with
# +RTS -N2 may land on any pair; only pairs with the first are measured.)
#   bench/cores.sh [RUNS]     (each pair RUNS times, default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/cores/lib.sh
runs=${1:-3}
positive_int bench/cores.sh RUNS "$runs"
allowed_cpus
if [ "${#cpus[@]}" -lt 2 ]; then
  echo "bench/cores.sh: one processor to run on (${allowed}): nothing to measure" >&2
  exit 0
fi
build=$(mktemp -d /tmp/afrp-cores.XXXXXX)
trap 'rm -rf "$build"' EXIT
build_pingpong "$build"
first=${cpus[0]}
status=0
for other in "${cpus[@]:1}"; do
  for ((r = 0; r < runs; r++)); do
    "$build/pingpong" "$first" "$other" || { status=1; break; }
  done
done
exit $status
