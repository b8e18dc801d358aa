#!/usr/bin/env bash
# Builds mink_mdd_bench in Release, runs it and plots its CSVs:
#   benchmarks/results/mdd_{paper,scaling,coherence,precision,targets}.csv,
#   benchmarks/results/mdd.txt (the printed tables),
#   benchmarks/results/mdd_{paper,scaling,precision}.png.
# usage: benchmarks/run_mdd.sh [--quick] [other mink_mdd_bench options]
#   --quick: a ~1-minute smoke run (plus the build) whose numbers are not for publication;
#            it writes into $MINK_BENCH_QUICK_DIR (default ${TMPDIR:-/tmp}/mink-mdd-quick)
#            so the committed results are not overwritten.
# environment: MINK_BENCH_BUILD_DIR (default ${TMPDIR:-/tmp}/mink-bench-build),
#              PYTHON (an interpreter with matplotlib; default: the first of python3,
#              /usr/bin/python3 that has it), JOBS (build parallelism, default 2).
# Needs (Debian 12): libcgal-dev libgmp-dev libmpfr-dev libfcl-dev libccd-dev libbullet-dev
# python3-matplotlib, as tests/run_all.sh installs.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
build="${MINK_BENCH_BUILD_DIR:-${TMPDIR:-/tmp}/mink-bench-build}"
results="$here/results"
for arg in "$@"; do
  if [ "$arg" = "--quick" ]; then
    results="${MINK_BENCH_QUICK_DIR:-${TMPDIR:-/tmp}/mink-mdd-quick}"
  fi
done
mkdir -p "$results"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_EXAMPLES=OFF -DMINK_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target mink_mdd_bench -j "${JOBS:-2}"

"$build/benchmarks/mink_mdd_bench" "$results" "$@" | tee "$results/mdd.txt"

py=""
for candidate in ${PYTHON:-} python3 /usr/bin/python3; do
  if command -v "$candidate" >/dev/null 2>&1 && "$candidate" -c "import matplotlib" >/dev/null 2>&1; then
    py="$candidate"
    break
  fi
done
if [ -z "$py" ]; then
  echo "no python with matplotlib found (apt-get install python3-matplotlib);" \
       "the CSVs are in $results" >&2
  exit 1
fi
"$py" "$here/plot_mdd.py" "$results"
