// Tests of mink/hierarchy/prepare.hpp: prepare(P) fills every derived slot a query could
// fill (the Dobkin–Kirkpatrick hierarchy from defaults::kHierarchyMinVertices vertices on,
// the support seeds always), copies made before or after share them, a second call builds
// nothing new, concurrent calls (also beside queries) build each structure once, and
// mdd() answers the same on a prepared shape as on an unprepared twin.
//
// References: the exact CGAL brute force (tests/support/mdd_reference.hpp) for the MDD
// answers, a scan of all vertices for support queries; the unprepared twin's answer must
// equal the prepared one bit for bit (the structures are the same, only built earlier).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "mink/hierarchy/prepare.hpp"
#include "mink/mdd/mdd.hpp"
#include "support/exact_placement.hpp"
#include "support/mdd_reference.hpp"
#include "support/mdd_status.hpp"

namespace mink {
namespace {

using Vec = Vec3<double>;

#if defined(MINK_SANITIZE_BUILD) || defined(__SANITIZE_ADDRESS__)
constexpr int kConcurrentN = 2500;  // the sanitizers make the builds ~10x slower
#else
constexpr int kConcurrentN = 6000;
#endif

/// n points on the ellipsoid with semi-axes 2, 2, 5 (every point a hull vertex).
std::vector<Vec> ellipsoidPoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Vec> pts;
  while (static_cast<int>(pts.size()) < n) {
    const Vec p(g(rng), g(rng), g(rng));
    const double r = p.norm();
    if (r > 0) pts.emplace_back(2 * p.x() / r, 2 * p.y() / r, 5 * p.z() / r);
  }
  return pts;
}

std::vector<Vec> cubePoints(double half) {
  std::vector<Vec> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half);
  return pts;
}

bool slotBuilt(const ConvexPolyhedron<double>& P, detail::DerivedSlots::Id id) {
  return P.derivedSlots().slot[id].isBuilt();
}

TEST(Prepare, LargeShapeGetsHierarchyAndSeedsSharedByCopies) {
  const int n = defaults::kHierarchyMinVertices + 200;
  const auto P = ConvexPolyhedron<double>::fromPoints(ellipsoidPoints(n, 101u));
  ASSERT_EQ(P.numVertices(), n);
  const ConvexPolyhedron<double> copyBefore = P;
  EXPECT_FALSE(isPrepared(P));
  EXPECT_FALSE(slotBuilt(P, detail::DerivedSlots::kHierarchy));
  EXPECT_FALSE(slotBuilt(P, detail::DerivedSlots::kSupportSeeds));

  const DKHierarchy<double>* H = prepare(P);
  ASSERT_NE(H, nullptr);
  EXPECT_EQ(H->levelSize(0), n);
  EXPECT_GT(H->numLevels(), 1);
  EXPECT_TRUE(slotBuilt(P, detail::DerivedSlots::kHierarchy));
  EXPECT_TRUE(slotBuilt(P, detail::DerivedSlots::kSupportSeeds));
  EXPECT_TRUE(isPrepared(P));
  EXPECT_TRUE(isPrepared(copyBefore));
  const ConvexPolyhedron<double> copyAfter = P;
  EXPECT_TRUE(isPrepared(copyAfter));

  // The same structures, not rebuilt ones: the pointers stay.
  const SupportSeeds* seeds = &supportSeedsOf(P);
  EXPECT_EQ(prepare(P), H);
  EXPECT_EQ(prepare(copyBefore), H);
  EXPECT_EQ(hierarchyOf(copyAfter), H);
  EXPECT_EQ(&supportSeedsOf(copyBefore), seeds);
  EXPECT_EQ(&supportSeedsOf(copyAfter), seeds);

  // The seeds are the support vertices of their 26 directions (against a scan).
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b)
      for (int c = -1; c <= 1; ++c) {
        if (!(a | b | c)) continue;
        const Vec d(a, b, c);
        double best = -1e300;
        for (const Vec& x : P.vertices()) best = std::max(best, d.dot(x));
        EXPECT_EQ(d.dot(P.vertex(seeds->vertex[(a + 1) * 9 + (b + 1) * 3 + (c + 1)])), best)
            << "direction " << a << ' ' << b << ' ' << c;
      }

  // Another shape of the same points is not prepared by this one.
  const auto other = ConvexPolyhedron<double>::fromPoints(ellipsoidPoints(n, 101u));
  EXPECT_FALSE(isPrepared(other));
}

TEST(Prepare, SmallShapeGetsSeedsButNoHierarchy) {
  const int n = defaults::kHierarchyMinVertices - 1;
  const auto P = ConvexPolyhedron<double>::fromPoints(ellipsoidPoints(n, 202u));
  ASSERT_EQ(P.numVertices(), n);
  EXPECT_FALSE(isPrepared(P));
  EXPECT_EQ(prepare(P), nullptr);
  EXPECT_TRUE(isPrepared(P));
  EXPECT_TRUE(slotBuilt(P, detail::DerivedSlots::kSupportSeeds));
  EXPECT_FALSE(slotBuilt(P, detail::DerivedSlots::kHierarchy));
  EXPECT_EQ(hierarchyOf(P), nullptr);

  const auto cube = ConvexPolyhedron<double>::fromPoints(cubePoints(1.0));
  EXPECT_EQ(prepare(cube), nullptr);
  EXPECT_TRUE(isPrepared(cube));
  EXPECT_FALSE(slotBuilt(cube, detail::DerivedSlots::kHierarchy));
}

/// mdd() on prepared shapes and on unprepared twins built from the same points: the same
/// answer bit for bit, and the exact reference's status and translation.
TEST(Prepare, MddAnswersAlikePreparedOrNot) {
  struct Pair {
    const char* name;
    std::vector<Vec> P, Q;
  };
  const std::vector<Pair> pairs = {
      {"ellipsoid 1500 / cube", ellipsoidPoints(1500, 303u), cubePoints(0.5)},
      {"cube / ellipsoid 1100", cubePoints(1.0), ellipsoidPoints(1100, 304u)},
      {"ellipsoid 300 / ellipsoid 200", ellipsoidPoints(300, 305u), ellipsoidPoints(200, 306u)},
      {"cube / cube", cubePoints(1.0), cubePoints(0.75)},
  };
  std::mt19937 rng(307u);
  std::normal_distribution<double> g;
  for (const Pair& pr : pairs) {
    SCOPED_TRACE(pr.name);
    const auto P = ConvexPolyhedron<double>::fromPoints(pr.P), Q = ConvexPolyhedron<double>::fromPoints(pr.Q);
    const auto Pu = ConvexPolyhedron<double>::fromPoints(pr.P), Qu = ConvexPolyhedron<double>::fromPoints(pr.Q);
    prepare(P);
    prepare(Q);
    ASSERT_TRUE(isPrepared(P) && isPrepared(Q));
    ASSERT_FALSE(isPrepared(Pu) || isPrepared(Qu));
    const auto rot = mink_test::randomRationalRotation(rng);
    Pose<double> poseQ;
    poseQ.rotation = rot.rounded;
    int contacts = 0;
    for (int k = 0; k < 6; ++k) {
      SCOPED_TRACE("query " + std::to_string(k));
      // Offsets from deep overlap to clear separation; s roughly towards P, so that most
      // lines meet M.
      poseQ.translation = Vec(g(rng), g(rng), g(rng)).normalized() * (1.5 * k);
      const Vec s = Vec(g(rng), g(rng), g(rng)) - poseQ.translation;
      // The unprepared twins first: their first query is the one that builds.
      const MddResult<double> ru = mdd(Pu, Pose<double>(), Qu, poseQ, s);
      const MddResult<double> rp = mdd(P, Pose<double>(), Q, poseQ, s);
      EXPECT_EQ(rp.status, ru.status);
      EXPECT_EQ(rp.translation, ru.translation);
      EXPECT_EQ(rp.normal, ru.normal);
      EXPECT_EQ(rp.faceType, ru.faceType);
      EXPECT_EQ(rp.featureP, ru.featureP);
      EXPECT_EQ(rp.featureQ, ru.featureQ);

      const auto e = mink_test::mddReference(
          mink_test::toExact(pr.P),
          mink_test::placeExact(pr.Q, rot.exact, mink_test::toExact(poseQ.translation)), mink_test::toExact(s));
      EXPECT_EQ(rp.status, mink_test::toMinkStatus(e.status));
      if (e.status == mink_test::MddRefStatus::NoContact) continue;
      ++contacts;
      const double err = e.tie ? std::min(std::abs(rp.translation - e.translation),
                                          std::abs(rp.translation + e.translation))
                               : std::abs(rp.translation - e.translation);
      EXPECT_LE(err, 1e-10);
    }
    EXPECT_GE(contacts, 4) << "too few lines met M for the translations to be compared";
  }
}

/// Several threads prepare one shape (some through a copy) while others query it: each
/// structure is built once, every caller gets it, and the answers are right.
TEST(Prepare, ConcurrentPrepareAndQueries) {
  for (unsigned round = 0; round < 3; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const auto P = ConvexPolyhedron<double>::fromPoints(ellipsoidPoints(kConcurrentN, 404u + round));
    const ConvexPolyhedron<double> copy = P;
    const auto Q = ConvexPolyhedron<double>::fromPoints(cubePoints(0.5));
    constexpr int kThreads = 4;
    std::atomic<bool> go{false};
    std::atomic<int> ready{0};
    std::vector<const DKHierarchy<double>*> got(kThreads, nullptr);
    std::vector<int> support(kThreads, -1);
    std::vector<MddResult<double>> answers(kThreads);
    const Vec d(0.3, -0.5, 0.8), s(-1.0, 0.2, 0.1);
    Pose<double> poseQ;
    poseQ.translation = Vec(4.0, 0.0, 0.0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([&, t] {
        ++ready;
        while (!go.load()) std::this_thread::yield();
        const ConvexPolyhedron<double>& X = t % 2 ? copy : P;
        if (t < 2) {
          got[t] = prepare(X);
        } else {
          // A query racing the preparation: it waits for, or makes, the same hierarchy.
          answers[t] = mdd(X, Pose<double>(), Q, poseQ, s);
          got[t] = hierarchyOf(X);
        }
        support[t] = got[t]->support(d);
      });
    }
    while (ready.load() < kThreads) std::this_thread::yield();
    go = true;
    for (auto& th : threads) th.join();

    EXPECT_TRUE(isPrepared(P));
    EXPECT_TRUE(isPrepared(copy));
    double best = -1e300;
    for (const Vec& x : P.vertices()) best = std::max(best, d.dot(x));
    const double slack = 4 * (P.tolerance() + 1e-15 * P.extent()) * d.norm();
    for (int t = 0; t < kThreads; ++t) {
      SCOPED_TRACE("thread " + std::to_string(t));
      ASSERT_NE(got[t], nullptr);
      EXPECT_EQ(got[t], got[0]);
      EXPECT_GE(d.dot(P.vertex(support[t])), best - slack);
    }
    // The racing queries against the exact reference.
    const auto e = mink_test::mddReference(
        mink_test::toExact(P.vertices()),
        mink_test::placeExact(cubePoints(0.5), mink_test::Mat3r::Identity(), mink_test::toExact(poseQ.translation)),
        mink_test::toExact(s));
    for (int t = 2; t < kThreads; ++t) {
      EXPECT_EQ(answers[t].status, mink_test::toMinkStatus(e.status));
      EXPECT_NEAR(answers[t].translation, e.translation, 1e-10);
    }
  }
}

}  // namespace
}  // namespace mink
