# shellcheck shell=bash
# Shared by scripts/sweep and scripts/sweep-merge (sourced from the
# folder they are in).

# newest_build NAME: the path of the executable NAME as cabal builds it
# into dist-newstyle, found without cabal (which a cluster's nodes may
# lack), in this project and in the current folder's dist-newstyle (the
# root of a user's own project beside an afrp checkout, whose
# cabal.project names it: run from there); the
# newest if there are several (a tree built before may hold an older
# layout's), nothing if there is none.
newest_build() {
  local root
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  find "$root/dist-newstyle" "$PWD/dist-newstyle" -path "*/build/$1/$1" -type f -printf '%T@ %p\n' 2>/dev/null |
    sort -rn | head -n 1 | cut -d' ' -f2- || true
}
