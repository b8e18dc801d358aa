#!/usr/bin/env bash
# Builds mink's libFuzzer targets (clang, -fsanitize=fuzzer,address,undefined) and runs each
# for a bounded time from its committed seed corpus:
#   mdd   fuzz/mdd_fuzz.cpp:  convex shapes, mdd(), intersects()       corpus/       regressions/
#   mesh  fuzz/mesh_fuzz.cpp: TriangleMesh::fromMesh, LocalMinkowskiSum corpus_mesh/  regressions_mesh/
#   1. On Debian, when run as root, installs clang and its runtime (libFuzzer, sanitizers)
#      with apt-get if missing.
#   2. Configures and builds the standalone project fuzz/ in $MINK_FUZZ_BUILD_DIR.
#   3. Per target: replays every seed and every saved regression once (each must pass),
#      then fuzzes from a scratch copy of its seed corpus (the committed corpus is never
#      modified) for its share of $MINK_FUZZ_SECONDS and prints the executions done.
# Exits non-zero on any crash, sanitizer report, timeout, out-of-memory or reference
# mismatch; the failing input is left in <scratch>/<target>/artifacts/ and its path printed.
#
# Environment: MINK_FUZZ_BUILD_DIR (default /tmp/mink-fuzz-build), MINK_FUZZ_SECONDS
#              (default 60: the total, split evenly between the targets), MINK_FUZZ_TARGETS
#              (default "mdd mesh"), MINK_FUZZ_WORK_DIR (scratch; default a fresh mktemp
#              dir), MINK_JOBS (build parallelism, default nproc), MINK_FUZZ_CMAKE_ARGS
#              (extra configure arguments, e.g. -DMINK_FUZZ_INCLUDE_DIR=/other/include),
#              MINK_FUZZ_SEED (fixed seed: a repeatable run), MINK_FUZZ_RUNS (inputs per
#              target).
set -euo pipefail

fuzz_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$fuzz_dir/.." && pwd)"
build="${MINK_FUZZ_BUILD_DIR:-/tmp/mink-fuzz-build}"
seconds="${MINK_FUZZ_SECONDS:-60}"
read -r -a targets <<< "${MINK_FUZZ_TARGETS:-mdd mesh}"
# Each target gets an equal share of the time (at least 1 s).
share=$(( seconds / ${#targets[@]} ))
if (( share < 1 )); then share=1; fi
# MINK_FUZZ_SEED (e.g. 1): a fixed libFuzzer seed, so that the run is a repeatable
# sequence of inputs (CI sets it: tests/run_all.sh); unset: a fresh seed, exploration.
seed_arg=()
if [[ -n "${MINK_FUZZ_SEED:-}" ]]; then seed_arg=(-seed="$MINK_FUZZ_SEED"); fi
# MINK_FUZZ_RUNS: stop each target after this many inputs (with a fixed seed: exactly the inputs
# a clean run was checked on; MINK_FUZZ_SECONDS still bounds the time).
if [[ -n "${MINK_FUZZ_RUNS:-}" ]]; then seed_arg+=(-runs="$MINK_FUZZ_RUNS"); fi
jobs="${MINK_JOBS:-$(nproc)}"
work="${MINK_FUZZ_WORK_DIR:-$(mktemp -d /tmp/mink-fuzz-run.XXXXXX)}"

# shellcheck source=../cmake/ensure_debian_packages.sh
source "$repo/cmake/ensure_debian_packages.sh"
# Debian 12: clang 14; its libFuzzer and sanitizer runtimes are in libclang-rt-14-dev.
ensure_debian_packages run_fuzz.sh cmake ninja-build clang libclang-rt-14-dev libeigen3-dev

echo "== run_fuzz.sh: building the fuzz targets (${targets[*]}) in $build"
# shellcheck disable=SC2086
cmake -S "$fuzz_dir" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ ${MINK_FUZZ_CMAKE_ARGS:-}
build_targets=()
for t in "${targets[@]}"; do build_targets+=("mink_${t}_fuzz"); done
cmake --build "$build" -j "$jobs" --target "${build_targets[@]}"

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
shopt -s nullglob

# run_target NAME CORPUS_DIR REGRESSIONS_DIR TIMEOUT: replay, then fuzz for $share seconds;
# an input running longer than TIMEOUT seconds fails (a hang).
run_target() {
  local name="$1" corpus="$fuzz_dir/$2" regressions="$fuzz_dir/$3" timeout="$4"
  local fuzzer="$build/mink_${name}_fuzz" dir="$work/$name"
  mkdir -p "$dir/corpus" "$dir/artifacts"
  cp "$corpus"/* "$dir/corpus/"
  local seeds=("$corpus"/*) saved=("$regressions"/*)
  echo "== run_fuzz.sh [$name]: replaying ${#seeds[@]} seeds and ${#saved[@]} regressions"
  # Without a directory argument libFuzzer runs exactly the given files, once each.
  "$fuzzer" -artifact_prefix="$dir/artifacts/" "${seeds[@]}" "${saved[@]}" > "$dir/replay.log" 2>&1 || {
    tail -n 60 "$dir/replay.log"
    echo "== run_fuzz.sh [$name]: FAILED while replaying the seeds/regressions (log: $dir/replay.log)" >&2
    return 1
  }
  echo "== run_fuzz.sh [$name]: fuzzing for $share s (scratch corpus $dir/corpus)"
  local status=0
  "$fuzzer" "$dir/corpus" "${seed_arg[@]}" -max_total_time="$share" -print_final_stats=1 -timeout="$timeout" \
    -report_slow_units="$timeout" \
    -rss_limit_mb=2048 -max_len=4096 -artifact_prefix="$dir/artifacts/" > "$dir/fuzz.log" 2>&1 || status=$?
  grep -E '^stat::' "$dir/fuzz.log" || true
  local execs
  execs="$(grep -E '^stat::number_of_executed_units' "$dir/fuzz.log" | awk '{print $2}')"
  if [[ "$status" != 0 ]] || ls "$dir/artifacts/" | grep -q .; then
    grep -E -A40 'mink fuzz mismatch|ERROR: |runtime error|SUMMARY' "$dir/fuzz.log" | head -n 80 || tail -n 60 "$dir/fuzz.log"
    echo "== run_fuzz.sh [$name]: FAILED (exit $status) after ${execs:-?} executions; input(s):" >&2
    ls -1 "$dir/artifacts/"* >&2 || true
    echo "   replay one with: $fuzzer <input>   (full log: $dir/fuzz.log)" >&2
    return 1
  fi
  echo "== run_fuzz.sh [$name]: passed, ${execs:-?} executions in $share s, no crash, sanitizer report or mismatch"
}

failed=0
for t in "${targets[@]}"; do
  case "$t" in
    mdd) run_target mdd corpus regressions 10 || failed=1 ;;
    # Five update() calls per input, each up to a few seconds under ASan on near-degenerate
    # poses (fuzz/README.md, open bugs): a longer bound, so that such an input is no hang.
    mesh) run_target mesh corpus_mesh regressions_mesh 30 || failed=1 ;;
    *) echo "run_fuzz.sh: unknown target '$t' (mdd, mesh)" >&2; exit 2 ;;
  esac
done
exit "$failed"
