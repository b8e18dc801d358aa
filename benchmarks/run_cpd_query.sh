#!/usr/bin/env bash
# Builds mink_cpd_query_bench in Release, runs it and plots its CSV:
#   benchmarks/results/cpd_query.csv (per scene and method), cpd_query_frames.csv (per
#   frame), cpd_query.txt (the printed tables), cpd_query.png.
# usage: benchmarks/run_cpd_query.sh [--quick] [other mink_cpd_query_bench options]
#   --quick: a smoke run whose numbers are not for publication; it writes into
#            $MINK_BENCH_QUICK_DIR (default ${TMPDIR:-/tmp}/mink-cpd-query-quick) so the
#            committed results are not overwritten.
# The small motions take seconds (60 frames each); the paper's four scenes (20 frames,
# --paper-frames) take up to a second per query. Every scene runs in a child process stopped
# after --scene-timeout seconds of wall time (default 90; FCL's column in a second child with
# the same limit); the README's run used --scene-timeout 60.
# environment: MINK_BENCH_BUILD_DIR (default ${TMPDIR:-/tmp}/mink-bench-build),
#              PYTHON (an interpreter with matplotlib; default: the first of python3,
#              /usr/bin/python3 that has it), JOBS (build parallelism, default 2).
# Needs: Eigen (the library's only dependency), python3-matplotlib for the plot.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=bench_lib.sh
source "$here/bench_lib.sh"
bench_setup mink-cpd-query-quick "$@"
bench_build mink_cpd_query_bench

"$build/benchmarks/mink_cpd_query_bench" "$results/cpd_query.csv" "$@" | tee "$results/cpd_query.txt"

py="$(bench_python "the CSV is in $results/cpd_query.csv")"
"$py" "$here/plot_cpd_query.py" "$results/cpd_query_frames.csv" "$results/cpd_query.png"
