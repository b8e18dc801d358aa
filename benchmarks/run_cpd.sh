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
# shellcheck source=bench_lib.sh
source "$here/bench_lib.sh"
bench_setup mink-cpd-quick "$@"
bench_build mink_cpd_bench

"$build/benchmarks/mink_cpd_bench" "$results/cpd_table2.csv" "$@" | tee "$results/cpd_table2.txt"

py="$(bench_python "the CSV is in $results/cpd_table2.csv")"
"$py" "$here/plot_cpd.py" "$results/cpd_table2.csv" "$results/cpd_table2.png"
