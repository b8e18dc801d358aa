#!/usr/bin/env bash
# Builds and runs mink_demo (examples/convex_demo.cpp: convex hulls of two meshes) and
# mink_mdd_demo (examples/mdd_demo.cpp: MDD on the paper's ten pairs) in build-demo/. Needs only CMake,
# Ninja, a C++17 compiler and Eigen; on Debian/Ubuntu, when run as root, missing ones are
# installed with apt-get first. Arguments are passed to mink_demo (e.g. --data DIR).
#
# Environment: MINK_BUILD_ROOT (default: the repository) holds build-demo/;
#              MINK_JOBS (default: nproc) is the build parallelism.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="${MINK_BUILD_ROOT:-$repo}"
jobs="${MINK_JOBS:-$(nproc)}"

packages=(cmake ninja-build g++ libeigen3-dev)

ensure_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "run_demo.sh: not a Debian system; make sure these are installed: ${packages[*]}" >&2
    return 0
  fi
  local missing=() p
  for p in "${packages[@]}"; do
    if [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)" != "install ok installed" ]]; then
      missing+=("$p")
    fi
  done
  ((${#missing[@]} == 0)) && return 0
  if [[ "$(id -u)" == 0 ]]; then
    echo "run_demo.sh: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update
    apt-get install -y --no-install-recommends "${missing[@]}"
  else
    echo "run_demo.sh: missing packages: ${missing[*]}" >&2
    echo "run_demo.sh: install them with: sudo apt-get install ${missing[*]}" >&2
    echo "run_demo.sh: trying anyway (they may be installed outside dpkg)" >&2
  fi
}

ensure_packages

cmake -S "$repo" -B "$root/build-demo" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_BENCHMARKS=OFF -DMINK_BUILD_EXAMPLES=ON
cmake --build "$root/build-demo" -j "$jobs" --target mink_demo mink_mdd_demo
"$root/build-demo/examples/mink_demo" "$@"
echo
"$root/build-demo/examples/mink_mdd_demo"
