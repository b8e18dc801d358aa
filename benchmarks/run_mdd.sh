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
# shellcheck source=bench_lib.sh
source "$here/bench_lib.sh"
bench_setup mink-mdd-quick "$@"
bench_build mink_mdd_bench

"$build/benchmarks/mink_mdd_bench" "$results" "$@" | tee "$results/mdd.txt"

py="$(bench_python "the CSVs are in $results")"
"$py" "$here/plot_mdd.py" "$results"
