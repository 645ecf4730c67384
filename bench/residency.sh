#!/usr/bin/env bash
# Runs the long-running networks for N and 10 N samples and prints the
# maximum residency that the GHC runtime reports (+RTS -s). Constant space
# means the two figures agree (within GC sampling noise).
#   bench/residency.sh [N]      (default N = 1000000)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-1000000}
cabal build -v0 --enable-benchmarks afrp-bench
bin=$(cabal list-bin --enable-benchmarks afrp-bench)
printf '%-6s %12s %22s\n' network samples "max residency (bytes)"
for key in b d "d'" f g; do
  for m in "$n" "$((n * 10))"; do
    res=$("$bin" --run "$key" "$m" +RTS -s 2>&1 >/dev/null | awk '/maximum residency/ {print $1}')
    printf '%-6s %12s %22s\n' "$key" "$m" "$res"
  done
done
