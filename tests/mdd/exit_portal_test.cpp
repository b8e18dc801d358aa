// tests/mdd/exit_portal_test.cpp — the exit portal's collision mode (detail/exit_portal.hpp,
// the first step of mink::intersects): its Inside / Outside verdicts against the exact
// classification of the origin in M (tests/support/mdd_reference.hpp), on the paper's
// pairs, on the degenerate contacts (touching, then moved apart and into each other by a
// little) in double, and in exact rationals, where touching must never be called apart.
#include "mink/mdd/detail/exit_portal.hpp"
#include "mink/mdd/intersects.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "support/degenerate_contacts.hpp"
#include "support/exact_placement.hpp"
#include "support/mdd_reference.hpp"
#include "support/paper_shapes.hpp"

namespace {

using mink::ConvexPolyhedron;
using mink::Pose;
using mink_test::OriginLocation;
using mink_test::Rational;
using mink_test::Vec3r;
using Vec3d = Eigen::Vector3d;
using Verdict = mink::detail::ExitPortal<double>::Verdict;

// The collision-mode portal for P at the identity and Q at (R, t), with the automatic
// touch tolerance of intersects().
template <class T>
typename mink::detail::ExitPortal<T>::Verdict portalVerdict(const ConvexPolyhedron<T>& P, const ConvexPolyhedron<T>& Q,
                                                            const mink::Mat3<T>& R, const mink::Vec3<T>& t) {
  const mink::detail::PairFrame<T> F(P, Q, R, t, true);
  const mink::Vec3<T> c = P.interiorPoint() - (R * Q.interiorPoint() + t);
  T tol = T(0);
  if constexpr (!mink::ScalarTraits<T>::isExact)
    tol = T(mink::defaults::kMddTouchToleranceFactor) * mink::ScalarTraits<T>::epsilon() * F.sceneSize();
  int hp = -1, hq = -1;
  const mink::Vec3<T> towards = mink::detail::unitOrder(mink::Vec3<T>(-c));
  return mink::detail::exitPortal(F, c, towards, hp, hq, &tol).verdict;
}

struct Counts {
  int inside = 0, outside = 0, unknown = 0;
  void add(Verdict v) { (v == Verdict::Inside ? inside : v == Verdict::Outside ? outside : unknown)++; }
};

// A verdict must agree with the exact location; Unknown is allowed (intersects() then runs
// its searches) and counted.
void expectConsistent(Verdict v, OriginLocation where, const std::string& what) {
  if (v == Verdict::Inside) {
    EXPECT_NE(where, OriginLocation::Outside) << what << ": portal said inside";
  } else if (v == Verdict::Outside) {
    EXPECT_EQ(where, OriginLocation::Outside) << what << ": portal said apart";
  }
}

// The secant steps run only where both shapes are large and finely faceted (faces of at
// most defaults::kSecantMaxFaceVertices vertices, degrees at most kSecantMaxDegree): on a
// 512-gon prism's caps or a cone's apex of degree 1,024 they took three to four times the
// portal steps of the plain refinement.
TEST(ExitPortal, SecantStepsOnlyOnLargeFinelyFacetedShapes) {
  using mink_test::paper_shapes_detail::fibonacciEllipsoid;
  const auto E1 = ConvexPolyhedron<double>::fromPoints(fibonacciEllipsoid(2000, 1.0, 0.8, 0.6));
  const auto E2 = ConvexPolyhedron<double>::fromPoints(fibonacciEllipsoid(1500, 0.7, 0.9, 0.5));
  const auto prism = ConvexPolyhedron<double>::fromPoints(mink_test::degenerateScene("cylinders-side", 512, true).P);
  const auto cone = ConvexPolyhedron<double>::fromPoints(mink_test::degenerateScene("cones-apex", 1024, true).P);
  for (const auto* S : {&E1, &E2, &prism, &cone}) ASSERT_NE(mink::hierarchyOf(*S), nullptr);
  EXPECT_LE(mink::hierarchyOf(E1)->shapeMaxFaceVertices(), mink::defaults::kSecantMaxFaceVertices);
  EXPECT_LE(mink::hierarchyOf(E1)->shapeMaxDegree(), mink::defaults::kSecantMaxDegree);
  EXPECT_EQ(mink::hierarchyOf(prism)->shapeMaxFaceVertices(), 512);
  EXPECT_EQ(mink::hierarchyOf(cone)->shapeMaxDegree(), 1024);
  std::mt19937 rng(7);
  struct Case {
    const ConvexPolyhedron<double>* P;
    const ConvexPolyhedron<double>* Q;
    bool useHierarchy, secant;
  };
  for (const Case& k : {Case{&E1, &E2, true, true}, Case{&E1, &E2, false, false}, Case{&E1, &prism, true, false},
                        Case{&prism, &prism, true, false}, Case{&cone, &cone, true, false}}) {
    const mink::Mat3<double> R = Eigen::AngleAxisd(0.3, Vec3d(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3d t(0.2, -0.1, 0.05);
    const mink::detail::PairFrame<double> F(*k.P, *k.Q, R, t, k.useHierarchy);
    EXPECT_EQ(F.finelyFacetedLarge(), k.secant);
    const Vec3d c = k.P->interiorPoint() - (R * k.Q->interiorPoint() + t);
    for (int i = 0; i < 8; ++i) {
      const Vec3d sigma = mink_test::randomUnitVector(rng);
      int hp = -1, hq = -1;
      const auto est = mink::detail::exitPortal(F, c, sigma, hp, hq);
      EXPECT_EQ(est.usedSecant, k.secant) << i;
      EXPECT_GT(est.normal.dot(sigma), 0.0) << i;  // the exit facet faces along the ray
    }
  }
}

TEST(ExitPortal, CollisionVerdictsOnThePaperPairs) {
  std::mt19937 rng(2026);
  Counts counts;
  for (std::size_t pi = 0; pi < mink_test::kPaperPairs.size(); ++pi) {
    const auto& pair = mink_test::kPaperPairs[pi];
    const auto ptsP = mink_test::paperShape(pair.first, rng);
    const auto ptsQ = mink_test::paperShape(pair.second, rng);
    const auto P = ConvexPolyhedron<double>::fromPoints(ptsP);
    const auto Q = ConvexPolyhedron<double>::fromPoints(ptsQ);
    for (int o = 0; o < 2; ++o) {
      const auto rot = mink_test::randomRationalRotation(rng);
      // The reference places the double vertices by the rotation mink uses (rounded).
      Eigen::Matrix<Rational, 3, 3> Rr;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Rr(i, j) = Rational(rot.rounded(i, j));
      const mink_test::MinkowskiDifferenceReference ref(mink_test::toExact(P.vertices()),
                                                        mink_test::placeExact(Q.vertices(), Rr, Vec3r::Zero()));
      for (int k = 0; k < 30; ++k) {
        const Vec3d offset = mink_test::randomUnitVector(rng) * mink_test::uniformIn(rng, 0.0, 11.0);
        const OriginLocation where = ref.classifyOrigin(mink_test::toExact(offset));
        const Verdict v = portalVerdict<double>(P, Q, rot.rounded, offset);
        const std::string what = "pair " + std::to_string(pi) + " orientation " + std::to_string(o) + " k " +
                                 std::to_string(k);
        expectConsistent(v, where, what);
        counts.add(v);
        Pose<double> poseQ;
        poseQ.rotation = rot.rounded;
        poseQ.translation = offset;
        if (where != OriginLocation::Boundary) {
          EXPECT_EQ(mink::intersects(P, Pose<double>(), Q, poseQ), where == OriginLocation::Inside) << what;
        }
      }
    }
  }
  std::printf("[portal/paper] inside %d, outside %d, unknown %d\n", counts.inside, counts.outside, counts.unknown);
  // Generic placements: the portal settles nearly all (it fails only within rounding of
  // touching, or on its step cap).
  EXPECT_GT(counts.inside, 150);
  EXPECT_GT(counts.outside, 150);
  EXPECT_LE(counts.unknown, 9);
}

// The degenerate contacts touch (faces resting on faces, a line contact, apex on apex);
// moved 1e-9 apart along a direction they must be Outside or Unknown, never Inside, and
// 1e-9 into each other never Outside; touching never Outside.
TEST(ExitPortal, CollisionVerdictsOnDegenerateContacts) {
  Counts counts;
  for (const std::string& family : mink_test::degenerateFamilies()) {
    for (int n : {5, 12, 64}) {
      for (bool generic : {false, true}) {
        const mink_test::ContactScene sc = mink_test::degenerateScene(family, n, generic);
        const auto P = ConvexPolyhedron<double>::fromPoints(sc.P);
        const auto Q = ConvexPolyhedron<double>::fromPoints(sc.Q);
        Eigen::Matrix<Rational, 3, 3> Rr;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) Rr(i, j) = Rational(sc.rotQ(i, j));
        const mink_test::MinkowskiDifferenceReference ref(mink_test::toExact(P.vertices()),
                                                          mink_test::placeExact(Q.vertices(), Rr, Vec3r::Zero()));
        std::vector<Vec3d> shifts{Vec3d::Zero()};
        for (const Vec3d& s : sc.dirs) {
          shifts.push_back(1e-9 * s.normalized());
          shifts.push_back(-1e-9 * s.normalized());
        }
        for (std::size_t k = 0; k < shifts.size(); ++k) {
          const Vec3d t = sc.tQ + shifts[k];
          const OriginLocation where = ref.classifyOrigin(mink_test::toExact(t));
          const Verdict v = portalVerdict<double>(P, Q, sc.rotQ, t);
          const std::string what =
              family + " n " + std::to_string(n) + (generic ? " generic" : "") + " shift " + std::to_string(k);
          expectConsistent(v, where, what);
          counts.add(v);
          Pose<double> poseQ;
          poseQ.rotation = sc.rotQ;
          poseQ.translation = t;
          EXPECT_EQ(mink::intersects(P, Pose<double>(), Q, poseQ), where != OriginLocation::Outside) << what;
        }
      }
    }
  }
  std::printf("[portal/degenerate] inside %d, outside %d, unknown %d\n", counts.inside, counts.outside,
              counts.unknown);
  EXPECT_GT(counts.inside + counts.outside, 0);
}

// Exact rationals: tolerance zero, every predicate exact; touching must never be Outside,
// and a verdict is the exact answer.
TEST(ExitPortal, CollisionVerdictsInExactRationals) {
  int decided = 0, total = 0;
  for (const std::string& family : mink_test::degenerateFamilies()) {
    const mink_test::ContactScene sc = mink_test::degenerateScene(family, 8, false);
    ASSERT_TRUE(sc.rotQ == Eigen::Matrix3d::Identity()) << family;
    const auto P = ConvexPolyhedron<Rational>::fromPoints(mink_test::toExact(sc.P));
    const auto Q = ConvexPolyhedron<Rational>::fromPoints(mink_test::toExact(sc.Q));
    const mink_test::MinkowskiDifferenceReference ref(mink_test::toExact(sc.P), mink_test::toExact(sc.Q));
    const Eigen::Matrix<Rational, 3, 3> I = Eigen::Matrix<Rational, 3, 3>::Identity();
    std::vector<Vec3r> shifts{Vec3r::Zero()};
    for (const Vec3d& s : sc.dirs) {
      shifts.push_back(mink_test::toExact(s) * Rational(1, 1000000000));
      shifts.push_back(mink_test::toExact(s) * Rational(-1, 1000000000));
    }
    for (std::size_t k = 0; k < shifts.size(); ++k) {
      const Vec3r t = mink_test::toExact(sc.tQ) + shifts[k];
      const OriginLocation where = ref.classifyOrigin(t);
      const auto v = portalVerdict<Rational>(P, Q, I, t);
      const std::string what = family + " shift " + std::to_string(k);
      using VR = mink::detail::ExitPortal<Rational>::Verdict;
      if (v == VR::Inside) {
        EXPECT_NE(where, OriginLocation::Outside) << what;
      } else if (v == VR::Outside) {
        EXPECT_EQ(where, OriginLocation::Outside) << what;
      }
      decided += v != VR::Unknown;
      ++total;
      Pose<Rational> poseQ;
      poseQ.translation = t;
      EXPECT_EQ(mink::intersects(P, Pose<Rational>(), Q, poseQ), where != OriginLocation::Outside) << what;
    }
  }
  std::printf("[portal/exact] %d of %d decided by the portal\n", decided, total);
  EXPECT_GT(decided, total / 2);
}

}  // namespace
