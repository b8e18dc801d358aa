// tests/mdd/first_contact_test.cpp — mink::firstContact against the exact chord of M on
// the line of the motion (tests/support/mdd_reference.hpp: CGAL, hull of all vertex
// differences, exact clipping): contact over τ in [0, 1] iff [t_lo, t_hi] meets [0, 1],
// first at max(t_lo, 0).
#include "mink/mdd/first_contact.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/exact_placement.hpp"
#include "support/mdd_reference.hpp"
#include "support/paper_shapes.hpp"

namespace {

using mink::ConvexPolyhedron;
using mink::Pose;
using mink_test::Rational;
using mink_test::Vec3r;
using Vec3d = Eigen::Vector3d;

struct Expected {
  bool hit = false;
  bool approaching = false;  // the interiors overlap just after the first contact
  Rational fraction = Rational(1);
  Rational margin = Rational(1);  // distance of the verdict from a boundary case, in τ
};

Expected expected(const mink_test::MddRefResult& e) {
  Expected x;
  if (!e.lineMeetsM) return x;
  // Clear of the cases that rounding may decide either way: t_lo near 0 or 1, t_hi near 0.
  auto absr = [](const Rational& a) { return a < 0 ? Rational(-a) : a; };
  x.margin = std::min({absr(e.tLo), absr(Rational(e.tLo - 1)), absr(e.tHi), Rational(e.tHi - e.tLo)});
  x.hit = e.tHi >= 0 && e.tLo <= 1;
  if (x.hit) x.fraction = e.tLo > 0 ? e.tLo : Rational(0);
  // The interiors overlap right after the first contact iff the line enters M's interior
  // there: not when the chord ends at the contact (t_hi == max(t_lo, 0)) or runs along a
  // facet plane.
  x.approaching = x.hit && !e.lineInFacetPlane && e.tHi > x.fraction;
  return x;
}

// Paper shapes in double: motions from far apart through overlap, random directions and
// lengths; verdict and fraction against the exact chord.
TEST(FirstContact, PaperPairsAgainstExactChord) {
  const unsigned seed = 20261204;
  std::mt19937 rng(seed);
  int hits = 0, misses = 0, checked = 0;
  for (const auto& pair : {mink_test::kPaperPairs[0], mink_test::kPaperPairs[1], mink_test::kPaperPairs[4],
                           mink_test::kPaperPairs[9]}) {
    const auto ptsP = mink_test::paperShape(pair.first, rng);
    const auto ptsQ = mink_test::paperShape(pair.second, rng);
    const auto P = ConvexPolyhedron<double>::fromPoints(ptsP);
    const auto Q = ConvexPolyhedron<double>::fromPoints(ptsQ);
    const mink_test::MinkowskiDifferenceReference ref(mink_test::toExact(P.vertices()),
                                                      mink_test::toExact(Q.vertices()));
    mink::MddCache<double> cache;
    for (int k = 0; k < 60; ++k) {
      Pose<double> poseQ;
      poseQ.translation = mink_test::randomUnitVector(rng) * (2.0 + 14.0 * mink_test::uniform01(rng));
      // Mostly towards P (so that a good share hit within the motion), some away.
      Vec3d d = -poseQ.translation * (0.2 + 1.3 * mink_test::uniform01(rng)) + 3.0 * mink_test::randomUnitVector(rng);
      if (k % 5 == 0) d = -d;
      const auto r = mink::firstContact(P, Pose<double>(), Q, poseQ, d, cache);
      const Expected x = expected(ref.query(mink_test::toExact(d), mink_test::toExact(poseQ.translation)));
      if (x.margin < Rational(1e-9)) continue;
      std::ostringstream what;
      what << "seed " << seed << " pair " << mink_test::paperShapeName(pair.first) << "-"
           << mink_test::paperShapeName(pair.second) << " k " << k;
      ASSERT_EQ(r.hit, x.hit) << what.str() << " mdd status " << static_cast<int>(r.mdd.status);
      EXPECT_NEAR(r.fraction, CGAL::to_double(x.fraction), 1e-12) << what.str();
      EXPECT_EQ(r.approaching, x.approaching) << what.str();
      (x.hit ? hits : misses) += 1;
      ++checked;
    }
  }
  EXPECT_GT(hits, 30);
  EXPECT_GT(misses, 30);
  EXPECT_GT(checked, 200);
}

// Exact rationals: the verdict and the fraction equal the exact chord's, ties included
// (touching at the start, contact exactly at the end of the motion).
TEST(FirstContact, ExactRationalsAtTheBoundaries) {
  std::vector<Vec3r> cube;
  for (int i = 0; i < 8; ++i)
    cube.emplace_back(Rational((i & 1) ? 1 : -1), Rational((i & 2) ? 1 : -1), Rational((i & 4) ? 1 : -1));
  const auto P = ConvexPolyhedron<Rational>::fromPoints(cube);
  const mink_test::MinkowskiDifferenceReference ref(cube, cube);
  struct Case {
    Vec3r t, d;
    const char* name;
  };
  const std::vector<Case> cases = {
      {Vec3r(Rational(4), Rational(0), Rational(0)), Vec3r(Rational(-2), Rational(0), Rational(0)),
       "contact exactly at the end"},
      {Vec3r(Rational(4), Rational(0), Rational(0)), Vec3r(Rational(-3), Rational(1, 3), Rational(0)),
       "contact at 2/3"},
      {Vec3r(Rational(2), Rational(1, 2), Rational(0)), Vec3r(Rational(1), Rational(0), Rational(0)),
       "touching at the start, moving away"},
      {Vec3r(Rational(2), Rational(1, 2), Rational(0)), Vec3r(Rational(-1), Rational(0), Rational(0)),
       "touching at the start, moving in"},
      {Vec3r(Rational(1), Rational(0), Rational(0)), Vec3r(Rational(0), Rational(0), Rational(5)),
       "overlapping at the start"},
      {Vec3r(Rational(4), Rational(0), Rational(0)), Vec3r(Rational(-2), Rational(2), Rational(0)),
       "a single point of contact at the end: edges meeting edges"},
      {Vec3r(Rational(4), Rational(0), Rational(0)), Vec3r(Rational(-2), Rational(3), Rational(0)),
       "line misses"},
      {Vec3r(Rational(4), Rational(0), Rational(2)), Vec3r(Rational(-3), Rational(0), Rational(0)),
       "sliding onto the top face's plane: touching along it"},
      {Vec3r(Rational(5), Rational(0), Rational(0)), Vec3r(Rational(-2), Rational(0), Rational(0)),
       "stops short"},
      {Vec3r(Rational(1, 2), Rational(0), Rational(2)), Vec3r(Rational(3), Rational(1), Rational(0)),
       "resting on the top face, sliding along it"},
      {Vec3r(Rational(2), Rational(2), Rational(0)), Vec3r(Rational(-1), Rational(-1), Rational(0)),
       "touching along an edge, moving in"},
      {Vec3r(Rational(2), Rational(2), Rational(2)), Vec3r(Rational(1), Rational(-1), Rational(0)),
       "touching at a vertex, moving across"}};
  for (const Case& c : cases) {
    Pose<Rational> poseQ;
    poseQ.translation = c.t;
    const auto r = mink::firstContact(P, Pose<Rational>(), P, poseQ, c.d);
    const Expected x = expected(ref.query(c.d, c.t));
    ASSERT_TRUE(r.hit || !r.approaching) << c.name;
    EXPECT_EQ(r.hit, x.hit) << c.name;
    EXPECT_EQ(r.fraction, x.fraction) << c.name;
    EXPECT_EQ(r.approaching, x.approaching) << c.name;
    // The same numbers in double (all exact there) give the same verdicts.
    std::vector<Vec3d> cubeD;
    for (const Vec3r& v : cube) cubeD.emplace_back(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
    const auto PD = ConvexPolyhedron<double>::fromPoints(cubeD);
    Pose<double> poseQD;
    poseQD.translation = Vec3d(CGAL::to_double(c.t.x()), CGAL::to_double(c.t.y()), CGAL::to_double(c.t.z()));
    const Vec3d dD(CGAL::to_double(c.d.x()), CGAL::to_double(c.d.y()), CGAL::to_double(c.d.z()));
    const auto rd = mink::firstContact(PD, Pose<double>(), PD, poseQD, dD);
    EXPECT_EQ(rd.hit, x.hit) << c.name << " (double)";
    EXPECT_EQ(rd.approaching, x.approaching) << c.name << " (double)";
    EXPECT_NEAR(rd.fraction, CGAL::to_double(x.fraction), 1e-15) << c.name << " (double)";
  }
}

TEST(FirstContact, RejectsAZeroMotion) {
  std::vector<Vec3d> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
  const auto P = ConvexPolyhedron<double>::fromPoints(cube);
  EXPECT_THROW((void)mink::firstContact(P, Pose<double>(), P, Pose<double>(), Vec3d(Vec3d::Zero())), mink::InvalidInput);
}

}  // namespace
