#!/usr/bin/env bash
# afrp against Enki on this machine (issue #18): the same swarm of
# Braitenberg obstacle avoiders (8 range sensors, dt = 0.01, a square
# walled world) in both engines, three cases, one table.
#   bench/enki.sh                 (each case run REPEAT times, best kept)
# Environment: REPEAT (default 3); SECONDS_SMALL, SECONDS_PACKED,
# SECONDS_LARGE: simulated seconds of the three cases (60, 5, 2).
# Installs Debian's libenki-dev and g++ if they are missing (apt-get, as
# root or via sudo) and builds bench/enki/swarm.cpp with g++ into a temporary
# directory: Enki is never a dependency of the library or of cabal.
set -euo pipefail
cd "$(dirname "$0")/.."
repeat=${REPEAT:-3}

missing=()
[ -f /usr/include/enki/PhysicalEngine.h ] || missing+=(libenki-dev)
command -v g++ >/dev/null || missing+=(g++)
if [ ${#missing[@]} -gt 0 ]; then
  sudo=(); [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  echo "== installing ${missing[*]}" >&2
  "${sudo[@]}" apt-get install -y "${missing[@]}" >&2 \
    || { "${sudo[@]}" apt-get update >&2 && "${sudo[@]}" apt-get install -y "${missing[@]}" >&2; }
fi
build=$(mktemp -d /tmp/afrp-enki.XXXXXX)
trap 'rm -rf "$build"' EXIT
g++ -O2 -std=c++17 -Wall -Wextra bench/enki/swarm.cpp -o "$build/enki-swarm" -lenki

cabal build -v0 --enable-benchmarks afrp-bench
afrp=$(cabal list-bin -v0 --enable-benchmarks afrp-bench)

# field NAME LINE: the value of NAME=... in a result line
field() { sed -n "s/.*[[:space:]]$1=\([^[:space:]]*\).*/\1/p" <<<" $2"; }

# best RUNNER ARGS...: the result line with the least CPU time of $repeat runs
best() {
  local line cpu bestline="" bestcpu=""
  for _ in $(seq "$repeat"); do
    line=$("$@")
    cpu=$(field cpu "$line")
    if [ -z "$bestcpu" ] || awk -v a="$cpu" -v b="$bestcpu" 'BEGIN { exit !(a < b) }'; then
      bestline=$line; bestcpu=$cpu
    fi
  done
  printf '%s\n' "$bestline"
}

printf '%7s %8s %8s %12s %12s %10s %18s %18s\n' \
  robots coverage seconds "Enki xRT" "afrp xRT" afrp/Enki "Enki steps/s" "afrp steps/s"
for c in "10 0.02 ${SECONDS_SMALL:-60}" "100 0.20 ${SECONDS_PACKED:-5}" "1000 0.02 ${SECONDS_LARGE:-2}"; do
  read -r n cov secs <<<"$c"
  e=$(best "$build/enki-swarm" "$n" "$cov" "$secs")
  a=$(best "$afrp" --swarm "$n" "$cov" "$secs")
  ex=$(field xrt "$e"); ax=$(field xrt "$a")
  printf '%7s %7.0f%% %8s %11sx %11sx %9.2fx %18s %18s\n' "$n" "$(awk -v c="$cov" 'BEGIN { print 100 * c }')" \
    "$secs" "$ex" "$ax" "$(awk -v a="$ax" -v e="$ex" 'BEGIN { print a / e }')" \
    "$(field robot_steps_per_s "$e")" "$(field robot_steps_per_s "$a")"
done
