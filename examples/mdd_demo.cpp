// mdd_demo — minimum directional distance on the MDD-DUAL paper's ten pairs (section VII).
//
// For each pair: P at the origin, Q at random orientations and at centre distances from
// deep overlap to clear separation, queried along random directions. Prints one row per
// pair (how many queries ended in each status, the mean faces of M visited per phase, the
// median time per query) and, first, a few single queries in full.
//
// Usage: mink_mdd_demo [--queries N]   (N directions per placement, default 10)
#include <mink/mink.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "support/paper_shapes.hpp"

namespace {

void printOne(const char* title, const mink::MddResult<double>& r, const Eigen::Vector3d& s) {
  std::printf("  %s\n", title);
  std::printf("    s = (%.3f, %.3f, %.3f)  status %-11s distance %+.12f  translation %+.12f\n", s.x(), s.y(), s.z(),
              mink::toString(r.status), r.distance, r.translation);
  if (r.status == mink::MddStatus::NoContact) return;
  std::printf("    face of M: %s (P feature %d, Q feature %d), normal (%.4f, %.4f, %.4f)\n", mink::toString(r.faceType),
              r.featureP, r.featureQ, r.normal.x(), r.normal.y(), r.normal.z());
  std::printf("    witness on P (%.4f, %.4f, %.4f), on Q (%.4f, %.4f, %.4f); faces visited FV %d VF %d EE %d\n",
              r.witnessP.x(), r.witnessP.y(), r.witnessP.z(), r.witnessQ.x(), r.witnessQ.y(), r.witnessQ.z(),
              r.visitedFV, r.visitedVF, r.visitedEE);
}

}  // namespace

int main(int argc, char** argv) {
  int perPlacement = 10;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--queries") && i + 1 < argc) {
      perPlacement = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: %s [--queries N]\n", argv[0]);
      return 2;
    }
  }
  std::printf("mink MDD demo: minimum directional distance, MDD-DUAL (Choi et al.), double precision\n\n");

  // A few single queries on two unit boxes, to show the sign convention.
  {
    std::vector<mink::Vec3<double>> corners;
    for (int i = 0; i < 8; ++i) corners.emplace_back((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    const auto box = mink::ConvexPolyhedron<double>::fromPoints(corners);
    mink::Pose<double> I, q;
    std::printf("Two boxes [-1,1]^3; Q's centre at (3, 0.5, 0): moving Q by translation * s/|s| makes them touch.\n");
    q.translation = {3, 0.5, 0};
    printOne("towards P", mink::mdd(box, I, box, q, mink::Vec3<double>(-1, 0, 0)), {-1, 0, 0});
    printOne("away from P (negative translation: move the other way)",
             mink::mdd(box, I, box, q, mink::Vec3<double>(1, 0, 0)), {1, 0, 0});
    printOne("sideways (the line of s never meets M)", mink::mdd(box, I, box, q, mink::Vec3<double>(0, 1, 0)),
             {0, 1, 0});
    q.translation = {1.5, 0.25, 0};
    printOne("overlapping by 0.5 along x (negative distance: penetration depth along s)",
             mink::mdd(box, I, box, q, mink::Vec3<double>(1, 0.2, 0)), {1, 0.2, 0});
    std::printf("\n");
  }

  std::mt19937 rng(2026);
  std::printf("The paper's ten pairs: Q at 4 orientations x 21 centre distances (1 .. 10) x %d directions.\n",
              perPlacement);
  std::printf("%-8s %5s %5s %7s %6s %6s %6s %6s %8s %8s %8s %10s\n", "pair", "V(P)", "V(Q)", "queries", "sep", "touch",
              "pen", "none", "FV vis", "VF vis", "EE vis", "median us");
  for (const auto& pair : mink_test::kPaperPairs) {
    const auto P = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(pair.first, rng));
    const auto Q = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(pair.second, rng));
    int counts[5] = {0, 0, 0, 0, 0};
    long long fv = 0, vf = 0, ee = 0;
    std::vector<double> micros;
    for (int orient = 0; orient < 4; ++orient) {
      mink::Pose<double> poseQ;
      poseQ.rotation = mink_test::randomRotation(rng);
      const Eigen::Vector3d axis = mink_test::randomUnitVector(rng);
      for (int step = 0; step <= 20; ++step) {
        poseQ.translation = axis * (1.0 + 9.0 * step / 20.0);
        for (int k = 0; k < perPlacement; ++k) {
          const Eigen::Vector3d s = mink_test::randomUnitVector(rng);
          const auto t0 = std::chrono::steady_clock::now();
          const auto r = mink::mdd(P, mink::Pose<double>(), Q, poseQ, s);
          const auto t1 = std::chrono::steady_clock::now();
          micros.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
          ++counts[static_cast<int>(r.status)];
          fv += r.visitedFV;
          vf += r.visitedVF;
          ee += r.visitedEE;
        }
      }
    }
    std::nth_element(micros.begin(), micros.begin() + micros.size() / 2, micros.end());
    const double n = static_cast<double>(micros.size());
    const std::string name =
        std::string(mink_test::paperShapeName(pair.first)) + "-" + mink_test::paperShapeName(pair.second);
    std::printf("%-8s %5d %5d %7zu %6d %6d %6d %6d %8.1f %8.1f %8.1f %10.1f\n", name.c_str(), P.numVertices(),
                Q.numVertices(), micros.size(), counts[0], counts[1], counts[2], counts[3], fv / n, vf / n, ee / n,
                micros[micros.size() / 2]);
    if (counts[4] > 0) std::printf("  (%d queries hit the iteration cap)\n", counts[4]);
  }
  std::printf("\nsep/touch/pen/none: Separated, Touching, Penetrating, NoContact. 'vis': mean faces of M evaluated\n"
              "per query in each phase (SEARCH-FV, SEARCH-VF, SEARCH-EE; penetrating queries search both ways).\n");
  return 0;
}
