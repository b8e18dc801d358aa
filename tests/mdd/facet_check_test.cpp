// tests/mdd/facet_check_test.cpp — mdd/detail/facet_check.hpp: FacetCheck::faceHit on
// EE faces, whose common case (the line strictly inside the parallelogram e_P − e_Q by
// the exact signs of its four sides) takes its witnesses from a 2-D solve instead of a
// fan triangle's barycentric weights. Reference: mdd()'s own answer for the same line,
// whose witnesses for an EE face are solved in 3-D from the edges (mdd_driver.hpp,
// finish) — a different computation — and the witnesses' own claims, checked from the
// vertices: on P's edge, on Q's placed edge, their difference along s.
#include "mink/mdd/detail/facet_check.hpp"
#include "mink/mdd/mdd.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "support/paper_shapes.hpp"

namespace {

using Vec3d = Eigen::Vector3d;

// Distance from x to the segment a b.
double toSegment(const Vec3d& x, const Vec3d& a, const Vec3d& b) {
  const Vec3d d = b - a;
  const double l = std::min(1.0, std::max(0.0, (x - a).dot(d) / d.squaredNorm()));
  return (a + l * d - x).norm();
}

TEST(FacetCheck, EdgePairWitnessesLieOnBothEdgesAndOnTheLine) {
  std::mt19937 rng(11u);
  const auto P = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(mink_test::PaperShape::P3, rng));
  const auto Q = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(mink_test::PaperShape::P6, rng));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
    q.normalize();
    mink::Pose<double> poseQ;
    poseQ.rotation = q.toRotationMatrix();
    const Vec3d dir = Vec3d(u(rng), u(rng), u(rng)).normalized();
    poseQ.translation = (6.0 + 8.0 * std::abs(u(rng))) * dir;
    const Vec3d s = (-dir + 0.5 * Vec3d(u(rng), u(rng), u(rng))).normalized();
    const auto r = mink::mdd(P, mink::Pose<double>(), Q, poseQ, s);
    if (r.faceType != mink::MddFaceType::EE ||
        (r.status != mink::MddStatus::Separated && r.status != mink::MddStatus::Penetrating))
      continue;
    // The same face in P's frame (P at the identity), checked on its own.
    const mink::detail::PairFrame<double> F(P, Q, poseQ.rotation, poseQ.translation, true);
    mink::MddCache<double> cache;
    mink::detail::FacetCheck<double> check(F, s, cache, mink::MddOptions<double>());
    const mink::detail::MFace<double> m = F.ee(r.featureP, r.featureQ);
    ASSERT_TRUE(m.valid()) << "query " << k;
    if (!check.faceHit(m)) continue;  // accepted by its facet's support sets instead
    ++checked;
    const auto ep = P.edgeVertices(r.featureP), eq = Q.edgeVertices(r.featureQ);
    const Vec3d wP = check.witnessP(), wQ = check.witnessQ();
    EXPECT_LT(toSegment(wP, P.vertex(ep.first), P.vertex(ep.second)), 1e-12) << "query " << k;
    EXPECT_LT(toSegment(wQ, F.q(eq.first), F.q(eq.second)), 1e-12) << "query " << k;
    EXPECT_LT((wP - wQ).cross(s).norm(), 1e-12) << "query " << k;
    EXPECT_LT((wP - r.witnessP).norm(), 1e-12) << "query " << k;
    EXPECT_LT((wQ - r.witnessQ).norm(), 1e-12) << "query " << k;
  }
  std::printf("[facet check] %d EE answers checked\n", checked);
  EXPECT_GT(checked, 100);
}

}  // namespace
