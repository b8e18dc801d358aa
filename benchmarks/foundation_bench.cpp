// mink_foundation_bench — costs of the foundation layers on ellipsoid point clouds:
// hull build (ConvexPolyhedron::fromPoints), Dobkin–Kirkpatrick hierarchy build, and
// support queries by the hierarchy, by hill-climbing (cold from vertex 0, and warm from
// the previous answer while the direction turns slowly) and by a brute-force scan.
// Then degenerate shapes (flat caps, a high-degree apex, a fromMesh cube convex only
// within its tolerance: builds and DK against the scan), the crossover size where the
// hierarchy beats a cold hill-climb (the value of defaults::kHierarchyMinVertices) and a
// sweep of the hierarchy's two parameters.
// Anchors for the builds, timed in the same run on the same points (when found at
// configure time): CGAL's convex_hull_3 over Epick into a Surface_mesh (a hull with its
// half-edge adjacency: what fromPoints builds), and FCL's fcl::Convexd made from that
// hull (tests/support/gjk_reference.hpp's GjkShape, as mdd_bench uses it).
//
// Inputs: points on the ellipsoid with semi-axes 2, 2, 5 (isotropic Gaussian directions,
// normalised, scaled), so that every point is a hull vertex; random query directions
// (isotropic Gaussian, not normalised); all with fixed seeds. Scalar: double.
// Every time is a median over repetitions, with min, max and quartiles; a repetition of
// a query figure is one batch of queries, divided by the batch size.
//
// Usage: mink_foundation_bench [out.csv] [--quick] [--builds]
//   out.csv   default benchmarks/results/foundation.csv (directory must exist)
//   --quick   fewer repetitions and sizes (smoke test, numbers not for publication)
//   --builds  the build rows of section 1 (hull, anchors, hierarchy) and the degenerate
//             shapes only
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#ifdef MINK_BENCH_HAVE_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#endif
#ifdef MINK_BENCH_HAVE_FCL
#include "support/gjk_reference.hpp"
#endif

#include "bench_common.hpp"
#include "support/bumpy_cube.hpp"
#include "mink/core/defaults.hpp"
#include "mink/hierarchy/dk_hierarchy.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace {

using mink::ConvexPolyhedron;
using mink::DKHierarchy;
using mink::DKHierarchyOptions;
using Vec = mink::Vec3<double>;
using Clock = std::chrono::steady_clock;
using mink_bench::cpuModel;
using mink_bench::loadAverage;
using mink_bench::quantile;

volatile long long gSink = 0;  // keeps query results alive

struct Stats {
  double median = 0, min = 0, max = 0, q1 = 0, q3 = 0;
  int reps = 0;
};

Stats summarize(const std::vector<double>& v) {
  Stats s;
  s.median = quantile(v, 0.5);
  s.q1 = quantile(v, 0.25);
  s.q3 = quantile(v, 0.75);
  s.min = *std::min_element(v.begin(), v.end());
  s.max = *std::max_element(v.begin(), v.end());
  s.reps = static_cast<int>(v.size());
  return s;
}

/// CPU time of the calling thread, in microseconds. The machines this runs on are often
/// shared: wall time would also count the time the thread waits for a core.
double threadCpuMicros() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e6 + ts.tv_nsec * 1e-3;
}

/// Stats of thread CPU time per unit, plus the median wall time per unit.
struct Timing : Stats {
  double wallMedian = 0;
};

/// Runs `body` `reps` times; microseconds per unit (one run of body does `units` units).
Timing timeIt(int reps, double units, const std::function<void()>& body) {
  std::vector<double> cpu, wall;
  for (int r = 0; r < reps; ++r) {
    const double c0 = threadCpuMicros();
    const auto w0 = Clock::now();
    body();
    const auto w1 = Clock::now();
    const double c1 = threadCpuMicros();
    cpu.push_back((c1 - c0) / units);
    wall.push_back(std::chrono::duration<double, std::micro>(w1 - w0).count() / units);
  }
  Timing t;
  static_cast<Stats&>(t) = summarize(cpu);
  t.wallMedian = quantile(wall, 0.5);
  return t;
}

std::vector<Vec> ellipsoidPoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Vec> pts;
  pts.reserve(n);
  while (static_cast<int>(pts.size()) < n) {
    Vec p(g(rng), g(rng), g(rng));
    const double r = p.norm();
    if (r == 0) continue;
    pts.push_back(Vec(2 * p.x() / r, 2 * p.y() / r, 5 * p.z() / r));
  }
  return pts;
}

std::vector<Vec> randomDirections(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Vec> d(count);
  for (Vec& v : d) v = Vec(g(rng), g(rng), g(rng));
  return d;
}

/// A slowly turning direction: each is the previous plus an isotropic Gaussian step of
/// sigma `step` per component (unit directions; step 0.01 is about 1 degree).
std::vector<Vec> slowDirections(int count, double step, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Vec> d(count);
  Vec cur(g(rng), g(rng), g(rng));
  cur.normalize();
  for (Vec& v : d) {
    cur = (cur + step * Vec(g(rng), g(rng), g(rng))).normalized();
    v = cur;
  }
  return d;
}

struct Csv {
  std::ofstream out;
  explicit Csv(const std::string& path) : out(path) {
    out << "section,n,vertices,method,param,median_us,min_us,max_us,q1_us,q3_us,reps,wall_median_us,note\n";
  }
  void row(const std::string& section, int n, int vertices, const std::string& method, const std::string& param,
           const Stats& s, double wallMedian, const std::string& note = "") {
    out << section << ',' << n << ',' << vertices << ',' << method << ',' << param << ',' << s.median << ','
        << s.min << ',' << s.max << ',' << s.q1 << ',' << s.q3 << ',' << s.reps << ',' << wallMedian << ','
        << note << '\n';
  }
  void row(const std::string& section, int n, int vertices, const std::string& method, const std::string& param,
           const Timing& t, const std::string& note = "") {
    row(section, n, vertices, method, param, t, t.wallMedian, note);
  }
  /// A single derived number (ratio, fit, size) in the median column.
  void value(const std::string& section, int n, const std::string& method, double v, const std::string& note = "") {
    Stats s;
    s.median = s.min = s.max = s.q1 = s.q3 = v;
    s.reps = 1;
    row(section, n, n, method, "", s, v, note);
  }
};

void printRow(const std::string& what, const Timing& s, const char* unit, double scale) {
  std::printf("    %-38s median %10.3f %s  [min %10.3f, max %10.3f, IQR %10.3f .. %10.3f] wall %10.3f (%d reps)\n",
              what.c_str(), s.median * scale, unit, s.min * scale, s.max * scale, s.q1 * scale, s.q3 * scale,
              s.wallMedian * scale, s.reps);
}

}  // namespace

// Degenerate shapes, the builds' worst cases: a cylinder (two flat m-gon caps, points on
// the caps and the rulings that are not vertices), a cone whose apex has degree m, and a
// cube whose faces are 100 x 100 grids given to fromMesh with the grid points moved up to
// 1e-14 off their planes (convex only within the tolerance: the hierarchy re-hulls the
// levels where a hole has no exact fill). Hull (or fromMesh) build, hierarchy build,
// re-hulled levels, and DK support against the scan on 10,000 random directions.
void degenerateBuilds(Csv& csv, bool quick) {
  const int m = quick ? 5000 : 50000;
  std::vector<Vec> cylinder, cone;
  {
    std::mt19937 rng(21u);
    std::uniform_int_distribution<int> pick(0, m - 1), level(-15, 15);
    const double pi = std::acos(-1.0);
    for (int k = 0; k < m; ++k) {
      const double a = 2 * pi * k / m;
      cylinder.emplace_back(std::cos(a), std::sin(a), -1.0);
      cylinder.emplace_back(std::cos(a), std::sin(a), 1.0);
      cone.emplace_back(std::cos(a), std::sin(a), 0.0);
    }
    cone.emplace_back(0.0, 0.0, 3.0);
    for (int i = 0; i < m; ++i) {
      const double a = 2 * pi * pick(rng) / m, r = (level(rng) + 16) / 33.0;
      cylinder.emplace_back(std::cos(a), std::sin(a), level(rng) / 16.0);         // on a ruling
      cylinder.emplace_back(r * std::cos(a), r * std::sin(a), i % 2 ? 1.0 : -1.0);  // inside a cap
    }
  }
  const int g = quick ? 30 : 100;
  const auto grid = mink_test::bumpyCube(g, 1e-14, 22u);
  const std::vector<Vec>& gridV = grid.first;
  const std::vector<std::vector<int>>& gridF = grid.second;
  struct Shape {
    const char* name;  // also the CSV's param column: no commas
    std::function<ConvexPolyhedron<double>()> make;
  };
  const Shape shapes[] = {
      {"cylinder_flat_caps", [&] { return ConvexPolyhedron<double>::fromPoints(cylinder); }},
      {"cone_apex_degree_m", [&] { return ConvexPolyhedron<double>::fromPoints(cone); }},
      {"bumpy_grid_cube_fromMesh", [&] { return ConvexPolyhedron<double>::fromMesh(gridV, gridF); }},
  };

  const std::vector<Vec> dirs = randomDirections(10000, 23u);
  for (const Shape& shape : shapes) {
    const std::string name = shape.name;
    const auto& make = shape.make;
    std::printf("\n  degenerate: %s\n", shape.name);
    try {
      const ConvexPolyhedron<double> P = make();
      const int V = P.numVertices();
      const int reps = quick ? 2 : 5;
      const Timing hull = timeIt(reps, 1, [&] { gSink += make().numVertices(); });
      printRow("shape build (fromPoints / fromMesh)", hull, "ms", 1e-3);
      const Timing hier = timeIt(reps, 1, [&] { gSink += DKHierarchy<double>(P).numLevels(); });
      printRow("hierarchy build", hier, "ms", 1e-3);
      const DKHierarchy<double> H(P);
      std::printf("    %d vertices, %d faces; hierarchy / shape build %.2f; %d levels, %d re-hulled\n", V,
                  P.numFaces(), hier.median / hull.median, H.numLevels(), H.rehulledLevels());
      const Timing dk = timeIt(quick ? 3 : 9, static_cast<int>(dirs.size()), [&] {
        long long s = 0;
        for (const Vec& d : dirs) s += H.support(d);
        gSink += s;
      });
      printRow("support: DK hierarchy", dk, "us", 1);
      const int bruteQueries = 200;
      const Timing brute = timeIt(quick ? 2 : 5, bruteQueries, [&] {
        long long s = 0;
        for (int k = 0; k < bruteQueries; ++k) s += P.supportBruteForce(dirs[k]);
        gSink += s;
      });
      printRow("support: brute-force scan", brute, "us", 1);
      std::ostringstream note;
      note << name << "; levels=" << H.numLevels() << " rehulled=" << H.rehulledLevels();
      csv.row("degenerate_build", V, V, "shape", name, hull, note.str());
      csv.row("degenerate_build", V, V, "hierarchy", name, hier, note.str());
      csv.row("degenerate_query", V, V, "dk", name, dk, note.str());
      csv.row("degenerate_query", V, V, "brute", name, brute, note.str());
    } catch (const std::exception& e) {
      std::printf("    skipped: %s\n", e.what());
    }
  }
}

/// The usage, as in the comment at the top of this file.
constexpr const char* kUsage =
    "Usage: mink_foundation_bench [out.csv] [--quick] [--builds]\n"
    "  out.csv   default benchmarks/results/foundation.csv (directory must exist)\n"
    "  --quick   fewer repetitions and sizes (smoke test, numbers not for publication)\n"
    "  --builds  the build rows of section 1 (hull, anchors, hierarchy) and the degenerate\n"
    "            shapes only\n";

int main(int argc, char** argv) {
  std::string csvPath = "benchmarks/results/foundation.csv";
  bool quick = false, buildsOnly = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else if (std::strcmp(argv[i], "--builds") == 0) {
      buildsOnly = true;
    } else {
      csvPath = mink_bench::pathArgument(argv[i], kUsage);
    }
  }
  Csv csv(csvPath);
  if (!csv.out) {
    std::fprintf(stderr, "cannot write %s (does its directory exist?)\n", csvPath.c_str());
    return 1;
  }

  std::printf("mink foundation benchmark (double)\n");
  std::printf("  machine: %s, %u hardware threads; load average at start: %s\n", cpuModel().c_str(),
              std::thread::hardware_concurrency(), loadAverage().c_str());
  std::printf("  compiler: %s; defaults: kHierarchyMinVertices=%d kHierarchyMaxRemovedDegree=%d "
              "kHierarchyTopVertices=%d\n",
              __VERSION__, mink::defaults::kHierarchyMinVertices, mink::defaults::kHierarchyMaxRemovedDegree,
              mink::defaults::kHierarchyTopVertices);
  csv.out << "# machine: " << cpuModel() << ", " << std::thread::hardware_concurrency() << " threads\n";
  csv.out << "# defaults: kHierarchyMinVertices=" << mink::defaults::kHierarchyMinVertices
          << " kHierarchyMaxRemovedDegree=" << mink::defaults::kHierarchyMaxRemovedDegree
          << " kHierarchyTopVertices=" << mink::defaults::kHierarchyTopVertices << "\n";
  csv.out << "# load average at start: " << loadAverage() << (quick ? " (--quick)" : "") << (buildsOnly ? " (--builds)" : "") << "\n";

  // ---------------------------------------------------------------------------------
  // 1. Builds and queries at 1k, 10k, 100k.
  const std::vector<int> sizes = quick ? std::vector<int>{1000, 10000} : std::vector<int>{1000, 10000, 100000};
  const int numQueries = 10000;
  const std::vector<Vec> dirs = randomDirections(numQueries, 11u);
  const std::vector<Vec> slow = slowDirections(numQueries, 0.01, 12u);
  double dk100k = 0, brute100k = 0;
  std::vector<double> fitN, fitT;
  for (int n : sizes) {
    const std::vector<Vec> pts = ellipsoidPoints(n, 1000u + n);
    const int buildReps = quick ? 2 : (n >= 100000 ? 5 : 9);
    const int queryReps = quick ? 3 : 15;
    std::printf("\n  ellipsoid 2:2:5, n = %d points\n", n);

    ConvexPolyhedron<double> P = ConvexPolyhedron<double>::fromPoints(pts);
    const int V = P.numVertices();
    const Timing hull = timeIt(buildReps, 1, [&] { gSink += ConvexPolyhedron<double>::fromPoints(pts).numVertices(); });
    printRow("hull build (fromPoints)", hull, "ms", 1e-3);
    csv.row("build", n, V, "hull", "", hull);

#ifdef MINK_BENCH_HAVE_CGAL
    {
      // The points converted once, outside the timing (mink takes its own input as is).
      using Point = CGAL::Epick::Point_3;
      std::vector<Point> cp;
      cp.reserve(pts.size());
      for (const Vec& p : pts) cp.emplace_back(p.x(), p.y(), p.z());
      const Timing cgal = timeIt(buildReps, 1, [&] {
        CGAL::Surface_mesh<Point> mesh;
        CGAL::convex_hull_3(cp.begin(), cp.end(), mesh);
        gSink += static_cast<long long>(mesh.number_of_vertices());
      });
      printRow("CGAL convex_hull_3 (Epick, Surface_mesh)", cgal, "ms", 1e-3);
      csv.row("build", n, V, "cgal_hull", "", cgal, "CGAL::convex_hull_3 Epick into Surface_mesh");
      std::printf("    fromPoints / CGAL hull: %.2f\n", hull.median / cgal.median);
      csv.value("build_ratio", n, "hull_over_cgal", hull.median / cgal.median);
    }
#endif
#ifdef MINK_BENCH_HAVE_FCL
    {
      const Timing fcl = timeIt(buildReps, 1, [&] {
        const mink_test::GjkShape g(pts);
        gSink += g.fclConvex().getFaceCount();
      });
      printRow("FCL Convex (CGAL hull + fcl::Convexd)", fcl, "ms", 1e-3);
      csv.row("build", n, V, "fcl_convex", "", fcl, "CGAL Epick hull + fcl::Convexd (gjk_reference.hpp)");
    }
#endif

    const Timing hier = timeIt(buildReps, 1, [&] { gSink += DKHierarchy<double>(P).numLevels(); });
    printRow("hierarchy build", hier, "ms", 1e-3);
    std::printf("    hierarchy build / hull build: %.2f\n", hier.median / hull.median);
    csv.row("build", n, V, "hierarchy", "", hier);
    csv.value("build_ratio", n, "hierarchy_over_hull", hier.median / hull.median);
    fitN.push_back(n);
    fitT.push_back(hier.median);
    if (buildsOnly) continue;

    const DKHierarchy<double> H(P);
    long long evals = 0;
    for (const Vec& d : dirs) {
      mink::DKSupportStats st;
      gSink += H.support(d, st);
      evals += st.evaluations;
    }
    std::printf("    hierarchy: %d levels, %zu vertices stored (%.2f n), %.1f MB (%.0f bytes per vertex), "
                "%.1f vertices evaluated per query\n",
                H.numLevels(), H.totalSize(), static_cast<double>(H.totalSize()) / V, H.memoryBytes() / 1e6,
                static_cast<double>(H.memoryBytes()) / V, static_cast<double>(evals) / numQueries);
    std::ostringstream note;
    note << "levels=" << H.numLevels() << " total=" << H.totalSize() << " bytes=" << H.memoryBytes()
         << " evals_per_query=" << static_cast<double>(evals) / numQueries;

    const Timing dk = timeIt(queryReps, numQueries, [&] {
      long long s = 0;
      for (const Vec& d : dirs) s += H.support(d);
      gSink += s;
    });
    printRow("support: DK hierarchy", dk, "us", 1);
    csv.row("query", n, V, "dk", "random", dk, note.str());

    const Timing cold = timeIt(queryReps, numQueries, [&] {
      long long s = 0;
      for (const Vec& d : dirs) s += P.support(d, 0);
      gSink += s;
    });
    printRow("support: hill-climb cold (from 0)", cold, "us", 1);
    csv.row("query", n, V, "cold", "random", cold);

    const Timing warm = timeIt(queryReps, numQueries, [&] {
      int v = 0;
      long long s = 0;
      for (const Vec& d : slow) s += (v = P.support(d, v));
      gSink += s;
    });
    printRow("support: hill-climb warm (slow dirs)", warm, "us", 1);
    csv.row("query", n, V, "warm", "slow", warm);

    const Timing dkSlow = timeIt(queryReps, numQueries, [&] {
      long long s = 0;
      for (const Vec& d : slow) s += H.support(d);
      gSink += s;
    });
    printRow("support: DK hierarchy (slow dirs)", dkSlow, "us", 1);
    csv.row("query", n, V, "dk", "slow", dkSlow);

    const int bruteQueries = n >= 100000 ? 1000 : numQueries;
    const Timing brute = timeIt(quick ? 2 : 7, bruteQueries, [&] {
      long long s = 0;
      for (int k = 0; k < bruteQueries; ++k) s += P.supportBruteForce(dirs[k]);
      gSink += s;
    });
    printRow("support: brute-force scan", brute, "us", 1);
    csv.row("query", n, V, "brute", "random", brute);
    std::printf("    ratios of medians: brute/DK %.1fx, cold/DK %.2fx, cold/warm %.1fx\n", brute.median / dk.median,
                cold.median / dk.median, cold.median / warm.median);
    if (n == 100000) {
      dk100k = dk.median;
      brute100k = brute.median;
    }
  }
  if (brute100k > 0) {
    std::printf("\n  brute/DK at 100k: %.1fx (target >= 50x)\n", brute100k / dk100k);
    csv.value("ratio", 100000, "brute_over_dk", brute100k / dk100k);
  }
  {
    // Least-squares fit t = a * n log2 n through the origin.
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < fitN.size(); ++i) {
      const double x = fitN[i] * std::log2(fitN[i]);
      sxy += x * fitT[i];
      sxx += x * x;
    }
    const double a = sxy / sxx;
    std::printf("  hierarchy build fit: t = %.4g us * n log2 n;", a);
    for (std::size_t i = 0; i < fitN.size(); ++i)
      std::printf("  n=%g: measured/fit %.2f", fitN[i], fitT[i] / (a * fitN[i] * std::log2(fitN[i])));
    std::printf("\n");
    csv.value("fit", 0, "hierarchy_us_per_nlog2n", a);
  }

  degenerateBuilds(csv, quick);

  if (buildsOnly) {
    std::printf("\n  load average at end: %s\n  CSV written to %s (--builds: section 1's builds and the degenerate shapes only)\n",
                loadAverage().c_str(), csvPath.c_str());
    return gSink == 42 ? 1 : 0;
  }

  // ---------------------------------------------------------------------------------
  // 2. Crossover: DK against a cold hill-climb from vertex 0 on small shapes. Several
  // shapes per size (different seeds) so that one lucky vertex 0 does not decide.
  std::printf("\n  crossover: DK hierarchy vs cold hill-climb (median per query over %s)\n",
              quick ? "3 shapes" : "8 shapes x 9 batches");
  const std::vector<int> small = quick ? std::vector<int>{32, 128, 512, 2048}
                                       : std::vector<int>{16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768, 1024, 2048, 4096};
  const int shapes = quick ? 3 : 8;
  const int smallQueries = 20000;
  const std::vector<Vec> smallDirs = randomDirections(smallQueries, 13u);
  // A clear win: DK at least this many times faster than the cold climb.
  const double clearMargin = 1.25;
  int crossover = -1, clearWin = -1;
  for (int n : small) {
    std::vector<double> dkT, coldT, dkW, coldW, buildT;
    for (int s = 0; s < shapes; ++s) {
      const ConvexPolyhedron<double> P = ConvexPolyhedron<double>::fromPoints(ellipsoidPoints(n, 5000u + 97 * s + n));
      std::unique_ptr<DKHierarchy<double>> built;
      buildT.push_back(timeIt(1, 1, [&] { built = std::make_unique<DKHierarchy<double>>(P); }).median);
      const DKHierarchy<double>& H = *built;
      for (int r = 0; r < (quick ? 2 : 9); ++r) {
        // Interleave the two so that load changes on a shared machine hit both alike.
        const Timing a = timeIt(1, smallQueries, [&] {
          long long x = 0;
          for (const Vec& d : smallDirs) x += H.support(d);
          gSink += x;
        });
        const Timing b = timeIt(1, smallQueries, [&] {
          long long x = 0;
          for (const Vec& d : smallDirs) x += P.support(d, 0);
          gSink += x;
        });
        dkT.push_back(a.median);
        dkW.push_back(a.wallMedian);
        coldT.push_back(b.median);
        coldW.push_back(b.wallMedian);
      }
    }
    const Stats dk = summarize(dkT), cold = summarize(coldT), build = summarize(buildT);
    const double saving = cold.median - dk.median;
    std::printf("    n=%5d  DK %7.4f us [IQR %.4f..%.4f]  cold %7.4f us [IQR %.4f..%.4f]  cold/DK %.2f  "
                "build %8.1f us, pays back after %s queries\n",
                n, dk.median, dk.q1, dk.q3, cold.median, cold.q1, cold.q3, cold.median / dk.median, build.median,
                saving > 0 ? std::to_string(static_cast<long long>(build.median / saving)).c_str() : "no");
    csv.row("crossover", n, n, "dk", "random", dk, quantile(dkW, 0.5));
    csv.row("crossover", n, n, "cold", "random", cold, quantile(coldW, 0.5));
    csv.row("crossover_build", n, n, "hierarchy", "", build, build.median);
    // Each threshold must hold from its size on, at every larger measured size.
    if (dk.median < cold.median) {
      if (crossover < 0) crossover = n;
    } else {
      crossover = -1;
    }
    if (cold.median >= clearMargin * dk.median) {
      if (clearWin < 0) clearWin = n;
    } else {
      clearWin = -1;
    }
  }
  std::printf("  DK beats the cold climb from n = %d on (at every larger measured size)\n", crossover);
  std::printf("  DK is >= %.2fx faster than the cold climb from n = %d on\n", clearMargin, clearWin);
  csv.value("crossover_n", crossover, "dk_beats_cold_from", crossover);
  csv.value("clear_win_n", clearWin, "dk_1.25x_faster_from", clearWin);

  // ---------------------------------------------------------------------------------
  // 3. Parameter sweep at the largest size: removed-degree bound D and top size.
  const int sweepN = quick ? 10000 : 100000;
  std::printf("\n  parameter sweep at n = %d (DK query median, build median; configurations interleaved)\n", sweepN);
  const ConvexPolyhedron<double> S = ConvexPolyhedron<double>::fromPoints(ellipsoidPoints(sweepN, 7000u));
  std::vector<DKHierarchyOptions> configs;
  for (int D : {6, 8, 10, 12}) {
    for (int top : {8, 16, 32, 64}) {
      DKHierarchyOptions opt;
      opt.maxRemovedDegree = D;
      opt.topVertices = top;
      configs.push_back(opt);
    }
  }
  std::vector<std::unique_ptr<DKHierarchy<double>>> built(configs.size());
  std::vector<std::vector<double>> buildT(configs.size()), buildW(configs.size()), queryT(configs.size()),
      queryW(configs.size());
  for (int round = 0; round < (quick ? 1 : 3); ++round) {
    for (std::size_t c = 0; c < configs.size(); ++c) {
      const Timing t = timeIt(1, 1, [&] { built[c] = std::make_unique<DKHierarchy<double>>(S, configs[c]); });
      buildT[c].push_back(t.median);
      buildW[c].push_back(t.wallMedian);
    }
  }
  for (int round = 0; round < (quick ? 3 : 11); ++round) {
    for (std::size_t c = 0; c < configs.size(); ++c) {
      const DKHierarchy<double>& H = *built[c];
      const Timing t = timeIt(1, numQueries, [&] {
        long long x = 0;
        for (const Vec& d : dirs) x += H.support(d);
        gSink += x;
      });
      queryT[c].push_back(t.median);
      queryW[c].push_back(t.wallMedian);
    }
  }
  for (std::size_t c = 0; c < configs.size(); ++c) {
    const DKHierarchy<double>& H = *built[c];
    const Stats q = summarize(queryT[c]), b = summarize(buildT[c]);
    std::printf("    D=%2d top=%2d: levels %2d, total %.2f n, %5.1f MB, query %.3f us [IQR %.3f..%.3f], build %.0f ms\n",
                configs[c].maxRemovedDegree, configs[c].topVertices, H.numLevels(),
                static_cast<double>(H.totalSize()) / sweepN, H.memoryBytes() / 1e6, q.median, q.q1, q.q3,
                b.median * 1e-3);
    std::ostringstream param;
    param << "D=" << configs[c].maxRemovedDegree << " top=" << configs[c].topVertices;
    std::ostringstream note;
    note << "levels=" << H.numLevels() << " total=" << H.totalSize() << " bytes=" << H.memoryBytes();
    csv.row("sweep_query", sweepN, S.numVertices(), "dk", param.str(), q, quantile(queryW[c], 0.5), note.str());
    csv.row("sweep_build", sweepN, S.numVertices(), "hierarchy", param.str(), b, quantile(buildW[c], 0.5), note.str());
  }
  std::printf("\n  load average at end: %s\n  CSV written to %s\n", loadAverage().c_str(), csvPath.c_str());
  return gSink == 42 ? 1 : 0;
}
