#!/usr/bin/env bash
# Builds and runs mink_demo (examples/convex_demo.cpp: convex hulls of two meshes),
# mink_mdd_demo (examples/mdd_demo.cpp: MDD on the paper's ten pairs) and mink_cpd_demo
# (examples/cpd_demo.cpp: a penalty contact loop on the CPD beside the Euclidean depth) and
# mink_physics_step (examples/physics_step/: translational CCD, mdd() as the time of impact
# against FCL and an exact CGAL reference, at its small size, writing
# build-demo/physics_step/physics_step.csv) in build-demo/, then installs mink into
# build-demo/planner-prefix and builds and runs examples/planner (a separate project on the
# installed package: a roadmap's straight-line segments checked with mdd() beside FCL) at
# its small size in build-demo/planner; both plots are drawn when python3 has matplotlib.
# Needs CMake, Ninja, a C++17 compiler, Eigen and, for the physics step and the planner,
# FCL, libccd, CGAL and GMP; on Debian/Ubuntu, when run as root, missing ones are installed
# with apt-get first. Arguments are passed to mink_demo (e.g. --data DIR).
#
# Environment: MINK_BUILD_ROOT (default: the repository) holds build-demo/;
#              MINK_JOBS (default: nproc) is the build parallelism.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="${MINK_BUILD_ROOT:-$repo}"
jobs="${MINK_JOBS:-$(nproc)}"

packages=(cmake ninja-build g++ libeigen3-dev libfcl-dev libccd-dev libcgal-dev libgmp-dev)

# shellcheck source=../cmake/ensure_debian_packages.sh
source "$repo/cmake/ensure_debian_packages.sh"

ensure_debian_packages run_demo.sh "${packages[@]}"

cmake -S "$repo" -B "$root/build-demo" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_BENCHMARKS=OFF -DMINK_BUILD_EXAMPLES=ON
cmake --build "$root/build-demo" -j "$jobs" --target mink_demo mink_mdd_demo mink_cpd_demo mink_physics_step
"$root/build-demo/examples/mink_demo" "$@"
echo
"$root/build-demo/examples/mink_mdd_demo"
echo
"$root/build-demo/examples/mink_cpd_demo"
echo
"$root/build-demo/examples/mink_physics_step" --out "$root/build-demo/physics_step"
echo

# The planner example uses mink as an installed package (README "Using mink from CMake").
cmake -S "$repo" -B "$root/build-demo/planner-install" -G Ninja \
  -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_BENCHMARKS=OFF -DMINK_BUILD_EXAMPLES=OFF
cmake --install "$root/build-demo/planner-install" --prefix "$root/build-demo/planner-prefix"
cmake -S "$repo/examples/planner" -B "$root/build-demo/planner" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$root/build-demo/planner-prefix"
cmake --build "$root/build-demo/planner" -j "$jobs"
"$root/build-demo/planner/planner" --out "$root/build-demo/planner"
plotter=""
for py in python3 /usr/bin/python3; do
  if "$py" -c "import matplotlib" 2>/dev/null; then plotter="$py"; break; fi
done
if [[ -n "$plotter" ]]; then
  "$plotter" "$repo/examples/planner/plot_planner.py" "$root/build-demo/planner"
else
  echo "run_demo.sh: no python3 with matplotlib; skipped examples/planner/plot_planner.py"
fi
if [[ -n "$plotter" ]]; then
  "$plotter" "$repo/examples/physics_step/plot_physics_step.py" "$root/build-demo/physics_step/physics_step.csv"
else
  echo "run_demo.sh: no python3 with matplotlib; skipped examples/physics_step/plot_physics_step.py"
fi
