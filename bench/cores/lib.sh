# Shared by bench/cores.sh, bench/side-by-side.sh and bench/scaling.sh
# (sourced, from the repository's root).

# allowed_cpus: the processors this program may run on (a cpuset or
# taskset may leave some out), from a list such as 0-3,6, into the array
# cpus.
allowed_cpus() {
  allowed=$(grep '^Cpus_allowed_list:' /proc/self/status | cut -f2)
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

# build_pingpong DIR: bench/cores/pingpong.c built with the C compiler
# ($CC or cc) as DIR/pingpong.
build_pingpong() {
  "${CC:-cc}" -O2 -Wall -Wextra -pthread bench/cores/pingpong.c -o "$1/pingpong"
}

# latency_ns PINGPONG A B: the one-way latency between processors A and
# B, in nanoseconds, as PINGPONG measures it.
latency_ns() {
  "$1" "$2" "$3" | sed -E 's/.*one-way ([0-9]+) ns.*/\1/'
}
