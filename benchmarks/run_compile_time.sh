#!/usr/bin/env bash
# Times the compilation of a translation unit that includes <mink/mink.hpp> and calls
# mdd / intersects / firstContact in double (benchmarks/compile_time/engine_tu.cpp):
#   header-only (every such unit instantiates the queries), with MINK_EXTERN_TEMPLATES
#   (the entry points declared extern), and src/mink_instantiations.cpp (compiled once per
#   program); each REPEAT times (default 3), median wall time, at -O0 and -O2.
# Prints a table and writes benchmarks/results/compile_time.txt.
# environment: CXX (default g++), REPEAT, EIGEN_INCLUDE (default /usr/include/eigen3).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
cxx="${CXX:-g++}"
repeat="${REPEAT:-3}"
eigen="${EIGEN_INCLUDE:-/usr/include/eigen3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

median_seconds() {  # median wall time of $repeat runs of the command
  local times=()
  for _ in $(seq "$repeat"); do
    local t0 t1
    t0=$(date +%s.%N)
    "$@"
    t1=$(date +%s.%N)
    times+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }')")
  done
  printf '%s\n' "${times[@]}" | sort -n | awk '{a[NR]=$1} END {printf "%.1f", (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'
}

out="$here/results/compile_time.txt"
mkdir -p "$here/results"
{
  echo "# $(uname -m), $("$cxx" --version | head -1), $(nproc) hardware threads, load $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# median of $repeat compilations (-c, -std=c++17), wall seconds"
  printf '%-60s %8s %8s\n' "translation unit" "-O0" "-O2"
  for variant in header-only extern instantiations; do
    case "$variant" in
      header-only) src="$here/compile_time/engine_tu.cpp"; defs=(); label="engine_tu.cpp, header-only" ;;
      extern) src="$here/compile_time/engine_tu.cpp"; defs=(-DMINK_EXTERN_TEMPLATES); label="engine_tu.cpp, -DMINK_EXTERN_TEMPLATES" ;;
      instantiations) src="$root/src/mink_instantiations.cpp"; defs=(); label="src/mink_instantiations.cpp (once per program)" ;;
    esac
    row=()
    for opt in -O0 -O2; do
      row+=("$(median_seconds "$cxx" -std=c++17 "$opt" "${defs[@]}" -I"$root/include" -isystem "$eigen" -c "$src" -o "$work/out.o")")
    done
    printf '%-60s %8s %8s\n' "$label" "${row[@]}"
  done
} | tee "$out"
