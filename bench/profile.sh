#!/usr/bin/env bash
# Where afrp-bench's time goes, by source line: a sampling profile by the
# kernel's software clock (perf record -e cpu-clock), which works on a
# virtual machine without performance counters, of afrp-bench built with
# line tables (-g1, in its own build folder, dist-profile/, so the usual
# build is untouched). GHC gives most of its code no symbol of its own
# (perf would put those samples under whatever symbol comes before them),
# so every sampled address in afrp-bench is named with addr2line from the
# line tables instead, and GHC's encoded names are decoded
# (afrp...AFrobRobotSimziPhysics_planMoveApart_info becomes
# AFrobRobotSim.Physics.planMoveApart_info).
#
#   bench/profile.sh [--top N] [--delay MS] -- AFRP-BENCH-ARGUMENTS
#
# prints the N (default 25) hottest source lines (and, under them, the
# hottest symbols), each with its share of the samples and its count: the
# same line listed for several addresses is one row. The file and line
# are the line table's; the symbol beside them is the nearest one the
# binary names, which for GHC's local code is often a neighbour's (a
# step of Simulator.hs named after an Exception instance, say), so read
# the line, not the symbol. --delay MS
# starts sampling MS milliseconds after the program starts (perf record
# -D), to leave out a world's construction. Needs perf (Debian package
# linux-perf) and addr2line and readelf (binutils), and a kernel that
# lets the user sample (root, or kernel.perf_event_paranoid at most 2;
# Debian's default, 3, allows root only). afrp-bench runs from the
# repository's root: a relative path among its arguments (criterion's
# --csv, say) is taken from there. For example:
#
#   bench/profile.sh -- --steady-with bench 10000 200 +RTS -N1
#
# The twentieth round of bench/README.md was measured this way.
set -euo pipefail
export LC_ALL=C
cd "$(dirname "$0")/.."
source bench/cores/lib.sh
top=25
delay=
while [ $# -gt 0 ]; do
  case $1 in
    --top) positive_int bench/profile.sh N "${2-}"; top=$2; shift 2 ;;
    --delay) positive_int bench/profile.sh MS "${2-}"; delay=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "bench/profile.sh: unknown option '$1' (usage: bench/profile.sh [--top N] [--delay MS] -- AFRP-BENCH-ARGUMENTS)" >&2; exit 2 ;;
  esac
done
if [ $# -eq 0 ]; then
  echo "bench/profile.sh: no afrp-bench arguments (usage: bench/profile.sh [--top N] [--delay MS] -- AFRP-BENCH-ARGUMENTS)" >&2
  exit 2
fi
for tool in perf addr2line readelf; do
  command -v "$tool" >/dev/null || { echo "bench/profile.sh: $tool not found (Debian: apt-get install -y linux-perf binutils)" >&2; exit 2; }
done
opts=(-v0 --enable-benchmarks --builddir dist-profile --ghc-options=-g1)
cabal build "${opts[@]}" afrp-bench
bin=$(cabal list-bin "${opts[@]}" afrp-bench)
# (perf script prints the addresses a program ran at, which addr2line
# takes as they are only for a program loaded where it was linked)
if ! readelf -h "$bin" | grep -q 'Type: *EXEC'; then
  echo "bench/profile.sh: $bin is position-independent; its sampled addresses cannot be named (build it without -pie)" >&2
  exit 1
fi
work=$(mktemp -d /tmp/afrp-profile.XXXXXX)
trap 'rm -rf "$work"' EXIT
record=(perf record -q -e cpu-clock -F 4000 -o "$work/perf.data")
if [ -n "$delay" ]; then record+=(-D "$delay"); fi
"${record[@]}" -- "$bin" "$@" >&2
# every sample: its address, and the object it is in
perf script -i "$work/perf.data" -F ip,dso | awk '{print $1, $2}' > "$work/samples"
total=$(wc -l < "$work/samples")
if [ "$total" -eq 0 ]; then echo "bench/profile.sh: perf recorded no samples" >&2; exit 1; fi
# afrp-bench's addresses named by addr2line (function and file:line), the
# others by their object; then counted by name
awk -v bin="$bin" '$2 == "(" bin ")" {print $1}' "$work/samples" | sort -u > "$work/ips"
if [ ! -s "$work/ips" ]; then
  echo "bench/profile.sh: none of the $total samples is in $bin (perf script names it otherwise?)" >&2
  exit 1
fi
sed 's/^/0x/' "$work/ips" | addr2line -f -e "$bin" | paste - - > "$work/names"
paste "$work/ips" "$work/names" > "$work/table"
awk -v bin="$bin" -v top="$top" -v total="$total" -v root="$(pwd -P)/" '
  # GHC'"'"'s z-encoding of names, decoded (the common cases)
  function decode(s,   out, i, c, d) {
    out = ""
    for (i = 1; i <= length(s); i++) {
      c = substr(s, i, 1)
      if ((c == "z" || c == "Z") && i < length(s)) {
        d = substr(s, ++i, 1)
        if (c == "z") {
          if (d == "i") out = out "."; else if (d == "m") out = out "-"; else if (d == "d") out = out "$";
          else if (d == "u") out = out "_"; else if (d == "z") out = out "z"; else if (d == "h") out = out "#";
          else if (d == "l") out = out "<"; else if (d == "g") out = out ">"; else if (d == "p") out = out "+";
          else if (d == "q") out = out "'"'"'"; else if (d == "e") out = out "="; else if (d == "a") out = out "&";
          else if (d == "b") out = out "|"; else if (d == "c") out = out "^"; else if (d == "s") out = out "\\";
          else if (d == "r") out = out "/"; else if (d == "t") out = out "*"; else if (d == "n") out = out "!";
          else if (d ~ /[0-9]/) { while (i < length(s) && substr(s, i + 1, 1) ~ /[0-9]/) i++; i++ }
          else out = out c d
        } else {
          if (d == "Z") out = out "Z"; else if (d == "L") out = out "("; else if (d == "R") out = out ")";
          else if (d == "M") out = out "["; else if (d == "N") out = out "]"; else if (d == "C") out = out ":";
          else out = out c d
        }
      } else out = out c
    }
    # the package prefix (afrp-0.1.0.0-inplace_), kept short
    sub(/^[a-z][a-z0-9-]*-[0-9.]+(-inplace|-[A-Za-z0-9]+)?_/, "", out)
    return out
  }
  FILENAME == ARGV[1] { fn[$1] = decode($2); line[$1] = $3; next }
  {
    if ($2 == "(" bin ")" && ($1 in fn)) {
      where = line[$1]
      if (index(where, root) == 1) { where = substr(where, length(root) + 1); sub(/^\/+/, "", where) }
      key = fn[$1] "  " where; f = fn[$1]
    } else {
      obj = $2; gsub(/[()]/, "", obj); n = split(obj, parts, "/")
      key = "(" parts[n] ")"; f = key
    }
    byline[key]++; byfn[f]++
  }
  END {
    printf "%d samples (asked for at 4000 a second)\n\nhottest source lines (nearest symbol, file:line):\n", total
    for (k in byline) printf "%6.2f%% %7d  %s\n", 100 * byline[k] / total, byline[k], k | "sort -rn | head -" top
    close("sort -rn | head -" top)
    printf "\nhottest symbols:\n"
    for (k in byfn) printf "%6.2f%% %7d  %s\n", 100 * byfn[k] / total, byfn[k], k | "sort -rn | head -" top
    close("sort -rn | head -" top)
  }' "$work/table" "$work/samples"
