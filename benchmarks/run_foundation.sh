#!/usr/bin/env bash
# Builds mink_foundation_bench in Release, runs it and plots its CSV:
#   benchmarks/results/foundation.csv, benchmarks/results/foundation.txt (the printed
#   table), benchmarks/results/foundation.png.
# usage: benchmarks/run_foundation.sh [--quick]
# environment: MINK_BENCH_BUILD_DIR (default ${TMPDIR:-/tmp}/mink-bench-build),
#              PYTHON (an interpreter with matplotlib; default: the first of python3,
#              /usr/bin/python3 that has it), JOBS (build parallelism, default 2).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
build="${MINK_BENCH_BUILD_DIR:-${TMPDIR:-/tmp}/mink-bench-build}"
results="$here/results"
mkdir -p "$results"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_EXAMPLES=OFF -DMINK_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target mink_foundation_bench -j "${JOBS:-2}"

"$build/benchmarks/mink_foundation_bench" "$results/foundation.csv" "$@" | tee "$results/foundation.txt"

py=""
for candidate in ${PYTHON:-} python3 /usr/bin/python3; do
  if command -v "$candidate" >/dev/null 2>&1 && "$candidate" -c "import matplotlib" >/dev/null 2>&1; then
    py="$candidate"
    break
  fi
done
if [ -z "$py" ]; then
  echo "no python with matplotlib found (apt-get install python3-matplotlib, or pip install matplotlib);" \
       "the CSV is in $results/foundation.csv" >&2
  exit 1
fi
"$py" "$here/plot_foundation.py" "$results/foundation.csv" "$results/foundation.png"
