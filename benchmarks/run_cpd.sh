#!/usr/bin/env bash
# Builds mink_cpd_bench in Release, runs it and plots its CSV:
#   benchmarks/results/cpd_table2.csv, benchmarks/results/cpd_table2.txt (the printed
#   tables), benchmarks/results/cpd_table2.png.
# usage: benchmarks/run_cpd.sh [--quick] [other mink_cpd_bench options]
#   --quick: a smoke run whose numbers are not for publication; it writes into
#            $MINK_BENCH_QUICK_DIR (default ${TMPDIR:-/tmp}/mink-cpd-quick) so the committed
#            results are not overwritten.
# The full run takes about 10 minutes: every column runs in a child process stopped after a
# wall-time limit (--full-timeout 30, --cgal-timeout 30, --method-timeout 20,
# --coherent-timeout 40 seconds per scene), because single updates on the paper-size scenes
# take seconds and the whole boundary minutes.
# environment: MINK_BENCH_BUILD_DIR (default ${TMPDIR:-/tmp}/mink-bench-build),
#              PYTHON (an interpreter with matplotlib; default: the first of python3,
#              /usr/bin/python3 that has it), JOBS (build parallelism, default 2).
# Needs (Debian 12): libcgal-dev libgmp-dev libmpfr-dev python3-matplotlib.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
build="${MINK_BENCH_BUILD_DIR:-${TMPDIR:-/tmp}/mink-bench-build}"
results="$here/results"
for arg in "$@"; do
  if [ "$arg" = "--quick" ]; then
    results="${MINK_BENCH_QUICK_DIR:-${TMPDIR:-/tmp}/mink-cpd-quick}"
  fi
done
mkdir -p "$results"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_EXAMPLES=OFF -DMINK_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target mink_cpd_bench -j "${JOBS:-2}"

"$build/benchmarks/mink_cpd_bench" "$results/cpd_table2.csv" "$@" | tee "$results/cpd_table2.txt"

py=""
for candidate in ${PYTHON:-} python3 /usr/bin/python3; do
  if command -v "$candidate" >/dev/null 2>&1 && "$candidate" -c "import matplotlib" >/dev/null 2>&1; then
    py="$candidate"
    break
  fi
done
if [ -z "$py" ]; then
  echo "no python with matplotlib found (apt-get install python3-matplotlib);" \
       "the CSV is in $results/cpd_table2.csv" >&2
  exit 1
fi
"$py" "$here/plot_cpd.py" "$results/cpd_table2.csv" "$results/cpd_table2.png"
