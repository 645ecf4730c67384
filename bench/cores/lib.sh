# Shared by bench/cores.sh, bench/side-by-side.sh and bench/scaling.sh
# (sourced, from the repository's root).

# allowed_cpus: the processors this program may run on (a cpuset or
# taskset may leave some out), from a list such as 0-3,6: the list as
# written in the variable allowed, one processor an element in the array
# cpus. Without the list (not Linux), the first $(nproc).
allowed_cpus() {
  allowed=$(grep '^Cpus_allowed_list:' /proc/self/status 2>/dev/null | cut -f2 || true)
  if [ -z "$allowed" ]; then allowed="0-$(($(nproc) - 1))"; fi
  cpus=()
  local ranges r c
  IFS=, read -ra ranges <<<"$allowed"
  for r in "${ranges[@]}"; do
    if [[ $r == *-* ]]; then
      for ((c = ${r%-*}; c <= ${r#*-}; c++)); do cpus+=("$c"); done
    else
      cpus+=("$r")
    fi
  done
}

# positive_int SCRIPT NAME VALUE: exits 2 with a message unless VALUE is
# a positive whole number of at most nine digits, written without leading
# zeros.
positive_int() {
  case "$3" in
    [1-9] | [1-9]*[0-9]) case "$3" in *[!0-9]*) ;; *) [ "${#3}" -le 9 ] && return 0 ;; esac ;;
  esac
  echo "$1: $2 must be a positive whole number of at most nine digits, got '$3'" >&2
  exit 2
}

# build_pingpong DIR: bench/cores/pingpong.c built with the C compiler
# ($CC or cc) as DIR/pingpong.
build_pingpong() {
  "${CC:-cc}" -O2 -Wall -Wextra -pthread bench/cores/pingpong.c -o "$1/pingpong"
}

# whole_number SCRIPT WHAT TEXT: prints TEXT if it is a whole number;
# otherwise says that SCRIPT found no WHAT and returns 1.
whole_number() {
  case "$3" in
    '' | *[!0-9]*) echo "$1: no $2 (got '$3')" >&2; return 1 ;;
  esac
  echo "$3"
}

# latency_ns SCRIPT PINGPONG A B: the one-way latency between processors
# A and B, in nanoseconds, as PINGPONG measures it; returns 1, with a
# message, when PINGPONG gives none.
latency_ns() {
  whole_number "$1" "latency from pingpong" "$("$2" "$3" "$4" | sed -E 's/.*one-way ([0-9]+) ns.*/\1/')"
}

# wall_rate SCRIPT: the robot-steps per second by the wall clock of an
# afrp-bench --steady or --side-by-side line on standard input; returns
# 1, with a message, when the line has none.
wall_rate() {
  local line
  line=$(cat)
  whole_number "$1" "robot-steps per second in afrp-bench's output: $line" \
    "$(sed -E 's/^.*: +([0-9]+) robot-steps\/s \(wall\).*/\1/' <<<"$line")"
}
