# benchmarks/bench_lib.sh — the steps the run_*.sh scripts share; source it after setting
# `here` (this folder). Defines:
#   bench_setup QUICK_NAME "$@"  sets root, build (MINK_BENCH_BUILD_DIR, default
#                                ${TMPDIR:-/tmp}/mink-bench-build) and results
#                                (benchmarks/results, or with --quick among the arguments
#                                $MINK_BENCH_QUICK_DIR, default ${TMPDIR:-/tmp}/QUICK_NAME),
#                                and creates the results folder;
#   bench_build TARGET           configures the Release build (benchmarks only) and builds
#                                TARGET with JOBS (default 2) jobs;
#   bench_python WHAT            prints an interpreter that has matplotlib (PYTHON, python3,
#                                /usr/bin/python3), or says where WHAT is and fails.
bench_setup() {
  local quick_name="$1"
  shift
  root="$(dirname "$here")"
  build="${MINK_BENCH_BUILD_DIR:-${TMPDIR:-/tmp}/mink-bench-build}"
  results="$here/results"
  local arg
  for arg in "$@"; do
    if [ "$arg" = "--quick" ]; then
      results="${MINK_BENCH_QUICK_DIR:-${TMPDIR:-/tmp}/$quick_name}"
    fi
  done
  mkdir -p "$results"
}

bench_build() {
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_EXAMPLES=OFF -DMINK_BUILD_BENCHMARKS=ON >/dev/null
  cmake --build "$build" --target "$1" -j "${JOBS:-2}"
}

bench_python() {
  local candidate
  for candidate in ${PYTHON:-} python3 /usr/bin/python3; do
    if command -v "$candidate" >/dev/null 2>&1 && "$candidate" -c "import matplotlib" >/dev/null 2>&1; then
      echo "$candidate"
      return 0
    fi
  done
  echo "no python with matplotlib found (apt-get install python3-matplotlib); $1" >&2
  return 1
}
