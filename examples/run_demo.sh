#!/usr/bin/env bash
# Builds and runs mink_demo (examples/convex_demo.cpp: convex hulls of two meshes),
# mink_mdd_demo (examples/mdd_demo.cpp: MDD on the paper's ten pairs) and mink_cpd_demo
# (examples/cpd_demo.cpp: a penalty contact loop on the CPD beside the Euclidean depth) in build-demo/. Needs only CMake,
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

# shellcheck source=../cmake/ensure_debian_packages.sh
source "$repo/cmake/ensure_debian_packages.sh"

ensure_debian_packages run_demo.sh "${packages[@]}"

cmake -S "$repo" -B "$root/build-demo" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_BENCHMARKS=OFF -DMINK_BUILD_EXAMPLES=ON
cmake --build "$root/build-demo" -j "$jobs" --target mink_demo mink_mdd_demo mink_cpd_demo
"$root/build-demo/examples/mink_demo" "$@"
echo
"$root/build-demo/examples/mink_mdd_demo"
echo
"$root/build-demo/examples/mink_cpd_demo"
