#!/usr/bin/env bash
# Builds mink's libFuzzer target (fuzz/mdd_fuzz.cpp, clang, -fsanitize=fuzzer,address,
# undefined) and runs it for a bounded time from the committed seed corpus.
#   1. On Debian, when run as root, installs clang and its runtime (libFuzzer, sanitizers)
#      with apt-get if missing.
#   2. Configures and builds the standalone project fuzz/ in $MINK_FUZZ_BUILD_DIR.
#   3. Replays every seed (fuzz/corpus/) and every saved regression (fuzz/regressions/)
#      once: each must pass.
#   4. Fuzzes for $MINK_FUZZ_SECONDS seconds from a scratch copy of the seed corpus (the
#      committed corpus is never modified) and prints the executions done.
# Exits non-zero on any crash, sanitizer report, timeout, out-of-memory or reference
# mismatch; the failing input is left in <scratch>/artifacts/ and its path printed.
#
# Environment: MINK_FUZZ_BUILD_DIR (default /tmp/mink-fuzz-build), MINK_FUZZ_SECONDS
#              (default 60), MINK_FUZZ_WORK_DIR (scratch; default a fresh mktemp dir),
#              MINK_JOBS (build parallelism, default nproc), MINK_FUZZ_CMAKE_ARGS (extra
#              configure arguments, e.g. -DMINK_FUZZ_INCLUDE_DIR=/other/include),
#              MINK_FUZZ_SEED (fixed seed: a repeatable run).
set -euo pipefail

fuzz_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$fuzz_dir/.." && pwd)"
build="${MINK_FUZZ_BUILD_DIR:-/tmp/mink-fuzz-build}"
seconds="${MINK_FUZZ_SECONDS:-60}"
# MINK_FUZZ_SEED (e.g. 1): a fixed libFuzzer seed, so that the run is a repeatable
# sequence of inputs (CI sets it: tests/run_all.sh); unset: a fresh seed, exploration.
seed_arg=()
if [[ -n "${MINK_FUZZ_SEED:-}" ]]; then seed_arg=(-seed="$MINK_FUZZ_SEED"); fi
# MINK_FUZZ_RUNS: stop after this many inputs (with a fixed seed: exactly the inputs
# a clean run was checked on; MINK_FUZZ_SECONDS still bounds the time).
if [[ -n "${MINK_FUZZ_RUNS:-}" ]]; then seed_arg+=(-runs="$MINK_FUZZ_RUNS"); fi
jobs="${MINK_JOBS:-$(nproc)}"
work="${MINK_FUZZ_WORK_DIR:-$(mktemp -d /tmp/mink-fuzz-run.XXXXXX)}"

# shellcheck source=../cmake/ensure_debian_packages.sh
source "$repo/cmake/ensure_debian_packages.sh"
# Debian 12: clang 14; its libFuzzer and sanitizer runtimes are in libclang-rt-14-dev.
ensure_debian_packages run_fuzz.sh cmake ninja-build clang libclang-rt-14-dev libeigen3-dev

echo "== run_fuzz.sh: building the fuzz target in $build"
# shellcheck disable=SC2086
cmake -S "$fuzz_dir" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ ${MINK_FUZZ_CMAKE_ARGS:-}
cmake --build "$build" -j "$jobs"
fuzzer="$build/mink_mdd_fuzz"

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

mkdir -p "$work/corpus" "$work/artifacts"
cp "$fuzz_dir"/corpus/* "$work/corpus/"

echo "== run_fuzz.sh: replaying $(ls "$fuzz_dir/corpus" | wc -l) seeds and $(ls "$fuzz_dir/regressions" | wc -l) regressions"
# Without a directory argument libFuzzer runs exactly the given files, once each.
"$fuzzer" -artifact_prefix="$work/artifacts/" "$fuzz_dir"/corpus/* "$fuzz_dir"/regressions/* \
  > "$work/replay.log" 2>&1 || {
  tail -n 60 "$work/replay.log"
  echo "== run_fuzz.sh: FAILED while replaying the seeds/regressions (log: $work/replay.log)" >&2
  exit 1
}

echo "== run_fuzz.sh: fuzzing for $seconds s (scratch corpus $work/corpus)"
status=0
"$fuzzer" "$work/corpus" "${seed_arg[@]}" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 -rss_limit_mb=2048 \
  -max_len=4096 -artifact_prefix="$work/artifacts/" > "$work/fuzz.log" 2>&1 || status=$?
grep -E '^stat::' "$work/fuzz.log" || true
execs="$(grep -E '^stat::number_of_executed_units' "$work/fuzz.log" | awk '{print $2}')"
if [[ "$status" != 0 ]] || ls "$work/artifacts/" | grep -q .; then
  grep -E -A40 'mink fuzz mismatch|ERROR: |runtime error|SUMMARY' "$work/fuzz.log" | head -n 80 || tail -n 60 "$work/fuzz.log"
  echo "== run_fuzz.sh: FAILED (exit $status) after ${execs:-?} executions; input(s):" >&2
  ls -1 "$work/artifacts/"* >&2 || true
  echo "   replay one with: $fuzzer <input>   (full log: $work/fuzz.log)" >&2
  exit 1
fi
echo "== run_fuzz.sh: passed, ${execs:-?} executions in $seconds s, no crash, sanitizer report or mismatch"
