#!/usr/bin/env bash
# How far apart this machine's processors are: the one-way latency of a
# cache line between processor 0 and each other one (bench/cores/pingpong.c,
# built with the C compiler into a temporary directory, never part of the
# library). The simulator's parallel step passes every robot's state from
# one core to the other at each step, so this number bounds what two cores
# can give it: a few tens of nanoseconds on cores that share a cache, a few
# hundred between chips or on a virtual machine's distant processors.
#   bench/cores.sh [RUNS]     (each pair RUNS times, default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
build=$(mktemp -d /tmp/afrp-cores.XXXXXX)
trap 'rm -rf "$build"' EXIT
cc -O2 -Wall -Wextra -pthread bench/cores/pingpong.c -o "$build/pingpong"
n=$(getconf _NPROCESSORS_ONLN)
if [ "$n" -lt 2 ]; then echo "one processor: nothing to measure" >&2; exit 0; fi
for ((b = 1; b < n; b++)); do
  for ((r = 0; r < runs; r++)); do "$build/pingpong" 0 "$b"; done
done
