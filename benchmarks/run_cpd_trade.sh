#!/usr/bin/env bash
# The speed–accuracy trade of the CPD query's parameters (CpdOptions alpha, beta):
# mink_cpd_query_bench once per (alpha, beta) of a grid, FCL's column skipped, then
# cpd_trade_table.py gathers the coherent query's figures per pair into
#   benchmarks/results/cpd_trade.csv and cpd_trade.txt (a Markdown table).
# usage: benchmarks/run_cpd_trade.sh [--quick] [other mink_cpd_query_bench options]
#   --quick: a smoke run (fewer frames) into $MINK_BENCH_QUICK_DIR (default
#            ${TMPDIR:-/tmp}/mink-cpd-trade-quick).
# environment: ALPHAS (default "0.1 0.3 0.6"), BETAS (default "1.5 2 4"),
#              MINK_BENCH_BUILD_DIR, JOBS (see bench_lib.sh).
# Needs: Eigen, python3 (no matplotlib).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=bench_lib.sh
source "$here/bench_lib.sh"
bench_setup mink-cpd-trade-quick "$@"
bench_build mink_cpd_query_bench

runs="$(mktemp -d "${TMPDIR:-/tmp}/mink-cpd-trade.XXXXXX")"
for a in ${ALPHAS:-0.1 0.3 0.6}; do
  for b in ${BETAS:-1.5 2 4}; do
    echo "== run_cpd_trade.sh: alpha $a, beta $b"
    "$build/benchmarks/mink_cpd_query_bench" "$runs/alpha${a}_beta${b}.csv" --alpha "$a" --beta "$b" --no-fcl --no-full-sum "$@" \
      > "$runs/alpha${a}_beta${b}.txt"
    tail -n 1 "$runs/alpha${a}_beta${b}.txt"
  done
done
python3 "$here/cpd_trade_table.py" "$runs" "$results/cpd_trade.csv" | tee "$results/cpd_trade.txt"
