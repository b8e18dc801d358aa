// mink_mdd_degenerate_bench — MDD on the degenerate contacts of a physics scene, beside
// their generic twins (issue 16): n-gon prisms resting face to face (s sliding in the
// contact plane, s tilted), their caps overlapping, cylinders side by side touching along
// a line, cones apex to apex (apex degree n), axis-aligned boxes; n = 16 .. 1024. Each
// family's generic twin is the same shapes with Q turned by 0.01 rad about a generic axis
// (tests/support/degenerate_contacts.hpp), so the two columns differ in the degeneracy
// alone. Targets: every degenerate median within 20x its twin's, and under 1 ms at n = 1024.
//
// Timing: each query (one direction) is repeated until 200 us have passed and timed as a
// whole (steady_clock); its time is the minimum over 3 such passes, the family's figure the
// median over its directions. Queries call mdd() without a cache (cold: the first query of
// a pair, the worst case a physics engine meets), with the shapes built beforehand.
// Reported beside the times: how many queries used the exhaustive fallback (usedFallback)
// or an edge-pair scan quadratic in two vertex degrees (usedPairScan), and the faces of M
// each visited (median). intersects() (no cache) is timed the same way on the same
// placements, degenerate and generic (one query per scene: it has no direction), with
// the same targets.
//
// Usage: mink_mdd_degenerate_bench [outdir] [--max-n N]
//   writes <outdir>/mdd_degenerate.csv (default outdir benchmarks/results); the table goes
//   to stdout. About a minute here.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "mink/mink.hpp"
#include "bench_common.hpp"
#include "support/degenerate_contacts.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using mink::ConvexPolyhedron;
using mink::Pose;

volatile double gSink = 0;

struct Row {
  std::string family;
  int n = 0;
  double degenerate = 0, generic = 0;  // median us per query
  double degenerateMax = 0;
  int fallbacks = 0;                    // degenerate queries that used the exhaustive fallback
  int pairScans = 0;                    // degenerate queries with a deg x deg edge-pair scan
  int visited = 0;                      // median faces of M visited, degenerate
  double intDegenerate = 0, intGeneric = 0;  // intersects(), us per query
};

struct Measured {
  double median = 0, max = 0;
  int fallbacks = 0, pairScans = 0, visited = 0;
  double intersectsUs = 0;
};

/// us per call of f: repeated until 200 us have passed, the minimum over 3 such passes.
template <class F>
double timeQuery(F&& f) {
  double best = 1e300;
  for (int pass = 0; pass < 3; ++pass) {
    const Clock::time_point t0 = Clock::now();
    int reps = 0;
    double us = 0;
    do {
      f();
      ++reps;
      us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
    } while (us < 200.0);
    best = std::min(best, us / reps);
  }
  return best;
}

Measured measure(const mink_test::ContactScene& sc) {
  const auto P = ConvexPolyhedron<double>::fromPoints(sc.P);
  const auto Q = ConvexPolyhedron<double>::fromPoints(sc.Q);
  Pose<double> poseP, poseQ;
  poseQ.rotation = sc.rotQ;
  poseQ.translation = sc.tQ;
  std::vector<double> times, visits;
  Measured m;
  for (const Eigen::Vector3d& s : sc.dirs) {
    const mink::MddResult<double> r = mink::mdd(P, poseP, Q, poseQ, s);  // warm-up
    m.fallbacks += r.usedFallback;
    m.pairScans += r.usedPairScan;
    visits.push_back(r.visitedFV + r.visitedVF + r.visitedEE);
    times.push_back(timeQuery([&] { gSink = gSink + mink::mdd(P, poseP, Q, poseQ, s).parameter; }));
  }
  m.intersectsUs = timeQuery([&] { gSink = gSink + (mink::intersects(P, poseP, Q, poseQ) ? 1.0 : 0.0); });
  m.median = mink_bench::quantile(times, 0.5);
  m.max = *std::max_element(times.begin(), times.end());
  m.visited = static_cast<int>(mink_bench::quantile(visits, 0.5));
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  std::string outdir = "benchmarks/results";
  int maxN = 1024;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--max-n") && i + 1 < argc) {
      maxN = std::atoi(argv[++i]);
    } else if (argv[i][0] != '-') {
      outdir = argv[i];
    } else {
      std::fprintf(stderr, "usage: %s [outdir] [--max-n N]\n", argv[0]);
      return 2;
    }
  }
  const Clock::time_point start = Clock::now();
  std::printf("MDD on degenerate contacts beside their generic twins (Q turned by 0.01 rad)\n");
  std::printf("  machine: %s, load %s\n", mink_bench::machineLine().c_str(), mink_bench::loadAverage().c_str());
  std::printf("  us per query: median over the family's directions of the minimum of 3 timed passes; mdd() without cache\n\n");
  std::printf("%-15s %5s %12s %12s %8s %12s %9s %10s %8s | %11s %11s %8s\n", "family", "n", "degenerate", "generic",
              "ratio", "degen. max", "fallbacks", "pair scans", "visited", "int. degen.", "int. gener.", "ratio");
  std::vector<Row> rows;
  for (const std::string& fam : mink_test::degenerateFamilies()) {
    for (int n = 16; n <= maxN; n *= 2) {
      const Measured d = measure(mink_test::degenerateScene(fam, n, false));
      const Measured g = measure(mink_test::degenerateScene(fam, n, true));
      Row r{fam, fam == "boxes-aligned" ? 4 : n, d.median, g.median, d.max, d.fallbacks, d.pairScans,
            d.visited, d.intersectsUs, g.intersectsUs};
      rows.push_back(r);
      std::printf("%-15s %5d %12.2f %12.2f %7.2fx %12.2f %9d %10d %8d | %11.2f %11.2f %7.2fx\n", r.family.c_str(), r.n,
                  r.degenerate, r.generic, r.degenerate / r.generic, r.degenerateMax, r.fallbacks, r.pairScans,
                  r.visited, r.intDegenerate, r.intGeneric, r.intDegenerate / r.intGeneric);
      std::fflush(stdout);
      if (fam == "boxes-aligned") break;  // no n
    }
  }
  double worstRatio = 0, worstAtMax = 0, worstQueryAtMax = 0, worstIntRatio = 0, worstIntAtMax = 0;
  for (const Row& r : rows) {
    worstRatio = std::max(worstRatio, r.degenerate / r.generic);
    worstIntRatio = std::max(worstIntRatio, r.intDegenerate / r.intGeneric);
    if (r.n == maxN || r.family == "boxes-aligned") {
      worstAtMax = std::max(worstAtMax, r.degenerate);
      worstQueryAtMax = std::max(worstQueryAtMax, r.degenerateMax);
      worstIntAtMax = std::max(worstIntAtMax, r.intDegenerate);
    }
  }
  std::printf("\ntargets: degenerate / generic <= 20x: worst %.2fx (%s); degenerate median < 1000 us at n = %d: worst %.1f us (%s)\n",
              worstRatio, worstRatio <= 20 ? "met" : "SHORT", maxN, worstAtMax, worstAtMax < 1000 ? "met" : "SHORT");
  std::printf("         slowest single degenerate query at n = %d: %.1f us (%s)\n", maxN, worstQueryAtMax,
              worstQueryAtMax < 1000 ? "under 1 ms" : "over 1 ms");
  std::printf("         intersects(): degenerate / generic worst %.2fx (%s); degenerate at n = %d: worst %.1f us (%s)\n",
              worstIntRatio, worstIntRatio <= 20 ? "met" : "SHORT", maxN, worstIntAtMax,
              worstIntAtMax < 1000 ? "met" : "SHORT");
  const std::string csv = outdir + "/mdd_degenerate.csv";
  std::ofstream out(csv);
  out << "# " << mink_bench::machineLine() << "\n";
  out << "family,n,degenerate_us,generic_us,degenerate_max_us,fallbacks,pair_scans,visited,intersects_degenerate_us,"
         "intersects_generic_us\n";
  for (const Row& r : rows)
    out << r.family << "," << r.n << "," << r.degenerate << "," << r.generic << "," << r.degenerateMax << ","
        << r.fallbacks << "," << r.pairScans << "," << r.visited << "," << r.intDegenerate << "," << r.intGeneric
        << "\n";
  std::printf("wrote %s; wall time %.0f s\n", csv.c_str(),
              std::chrono::duration<double>(Clock::now() - start).count());
  return 0;
}
