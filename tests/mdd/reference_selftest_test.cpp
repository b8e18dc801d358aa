// Self-tests of the MDD test references in tests/support/ (they do not test mink itself):
//  * mdd_reference.hpp against analytic answers on unit cubes (separated, penetrating,
//    touching, edge and vertex grazes, tie, no contact), against brute-force support
//    functions of P and Q, and its interval filter against pure Gmpq evaluation;
//  * paper_shapes.hpp: advertised hull vertex counts (exact CGAL hull), radius 5,
//    determinism, exactness of the rational rotations;
//  * gjk_reference.hpp: FCL (both solvers) and libccd against analytic box distances and
//    depths, and the paper's own check (Sec. VII) applied to the exact reference: moving Q
//    by the reference translation gives GJK distance ~0, moving it less or more does not.
// The FCL/libccd parts need the test target to link fcl and ccd and to define
// MINK_TEST_WITH_FCL; without it they are reported as skipped.
#include "support/mdd_reference.hpp"
#include "support/exact_placement.hpp"
#include "support/paper_shapes.hpp"
#ifdef MINK_TEST_WITH_FCL
#include "support/gjk_reference.hpp"
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace {

using mink_test::MddRefResult;
using mink_test::MddRefStatus;
using mink_test::MinkowskiDifferenceReference;
using mink_test::OriginLocation;
using mink_test::PaperShape;
using mink_test::Rational;
using mink_test::Vec3r;

Vec3r vr(const Rational& x, const Rational& y, const Rational& z) { return Vec3r(x, y, z); }

std::vector<Eigen::Vector3d> unitCube(const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(offset + Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  return v;
}

// Normals as a sorted list of strings, for order-free comparison.
std::vector<std::string> normalSet(const std::vector<Vec3r>& ns) {
  std::vector<std::string> out;
  for (const auto& n : ns) {
    std::ostringstream os;
    os << n.x() << ' ' << n.y() << ' ' << n.z();
    out.push_back(os.str());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Unit cube P = [0,1]^3, Q = the unit cube displaced by d: M = [-1,1]^3 - d.
MddRefResult cubes(const Eigen::Vector3d& d, const Vec3r& s) {
  return MinkowskiDifferenceReference(unitCube(), unitCube(d)).query(s);
}

// ---------------------------------------------------------------- analytic cubes

TEST(MddReferenceSelfTest, SeparatedCubesAlongAxis) {
  // M = [-4,-2] x [-1,1]^2; the line t(-1,0,0) meets it for t in [2, 4].
  const MddRefResult r = cubes({3, 0, 0}, vr(-1, 0, 0));
  EXPECT_EQ(r.status, MddRefStatus::Separated);
  EXPECT_EQ(r.origin, OriginLocation::Outside);
  ASSERT_TRUE(r.lineMeetsM);
  EXPECT_EQ(r.tLo, Rational(2));
  EXPECT_EQ(r.tHi, Rational(4));
  EXPECT_EQ(r.t, Rational(2));
  EXPECT_EQ(r.translation, 2.0);
  EXPECT_EQ(r.distance, 2.0);
  EXPECT_FALSE(r.tie);
  EXPECT_EQ(normalSet(r.contact.normals), normalSet({vr(1, 0, 0)}));
  EXPECT_EQ(normalSet(r.hi.normals), normalSet({vr(-1, 0, 0)}));
  ASSERT_EQ(r.contact.unitNormals.size(), 1u);
  EXPECT_EQ(r.contact.unitNormals[0], Eigen::Vector3d(1, 0, 0));

  // |s| = 2: the parameter halves, the length does not.
  const MddRefResult r2 = cubes({3, 0, 0}, vr(-2, 0, 0));
  EXPECT_EQ(r2.status, MddRefStatus::Separated);
  EXPECT_EQ(r2.t, Rational(1));
  EXPECT_EQ(r2.translation, 2.0);

  // Opposite direction: the line meets M behind the origin, t in [-4, -2].
  const MddRefResult r3 = cubes({3, 0, 0}, vr(1, 0, 0));
  EXPECT_EQ(r3.status, MddRefStatus::Separated);
  EXPECT_EQ(r3.t, Rational(-2));
  EXPECT_EQ(r3.translation, -2.0);
  EXPECT_EQ(r3.distance, 2.0);
}

TEST(MddReferenceSelfTest, SeparatedCubesObliqueRational) {
  // Points (-3t, t, 0): 3t in [2,4] and t in [-1,1] -> t in [2/3, 1].
  const Vec3r s = vr(-3, 1, 0);
  const MddRefResult r = cubes({3, 0, 0}, s);
  EXPECT_EQ(r.status, MddRefStatus::Separated);
  EXPECT_EQ(r.tLo, Rational(2, 3));
  EXPECT_EQ(r.tHi, Rational(1));
  EXPECT_EQ(r.t, Rational(2, 3));
  EXPECT_NEAR(r.translation, 2.0 / 3.0 * std::sqrt(10.0), 1e-15);
  EXPECT_NEAR(r.distance, 2.0 / 3.0 * std::sqrt(10.0), 1e-15);
  EXPECT_EQ(normalSet(r.lo.normals), normalSet({vr(1, 0, 0)}));   // face x = -2 of M
  EXPECT_EQ(normalSet(r.hi.normals), normalSet({vr(0, 1, 0)}));   // face y = 1 of M
}

TEST(MddReferenceSelfTest, PenetratingCubes) {
  // M = [-1.5, 0.5] x [-1.25, 0.75] x [-1, 1].
  const Eigen::Vector3d d(0.5, 0.25, 0.0);
  {
    const MddRefResult r = cubes(d, vr(1, 0, 0));
    EXPECT_EQ(r.status, MddRefStatus::Penetrating);
    EXPECT_EQ(r.origin, OriginLocation::Inside);
    EXPECT_EQ(r.tLo, Rational(-3, 2));
    EXPECT_EQ(r.tHi, Rational(1, 2));
    EXPECT_EQ(r.t, Rational(1, 2));
    EXPECT_EQ(r.translation, 0.5);
    EXPECT_EQ(r.distance, -0.5);
    EXPECT_EQ(normalSet(r.contact.normals), normalSet({vr(1, 0, 0)}));
  }
  {
    const MddRefResult r = cubes(d, vr(0, -1, 0));  // y = -t in [-1.25, 0.75]
    EXPECT_EQ(r.status, MddRefStatus::Penetrating);
    EXPECT_EQ(r.tLo, Rational(-3, 4));
    EXPECT_EQ(r.tHi, Rational(5, 4));
    EXPECT_EQ(r.t, Rational(-3, 4));
    EXPECT_EQ(r.translation, -0.75);
    EXPECT_EQ(r.distance, -0.75);
    EXPECT_EQ(normalSet(r.contact.normals), normalSet({vr(0, 1, 0)}));
  }
  {
    const MddRefResult r = cubes(d, vr(1, 1, 0));  // t in [-1.5,0.5] ∩ [-1.25,0.75]
    EXPECT_EQ(r.status, MddRefStatus::Penetrating);
    EXPECT_EQ(r.tLo, Rational(-5, 4));
    EXPECT_EQ(r.tHi, Rational(1, 2));
    EXPECT_EQ(r.t, Rational(1, 2));
    EXPECT_NEAR(r.translation, 0.5 * std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(r.distance, -0.5 * std::sqrt(2.0), 1e-15);
  }
}

TEST(MddReferenceSelfTest, TieIsReportedAsUpperEnd) {
  // Coincident cubes: M = [-1,1]^3, t in [-1, 1], both ends equally near.
  const MddRefResult r = cubes({0, 0, 0}, vr(1, 0, 0));
  EXPECT_EQ(r.status, MddRefStatus::Penetrating);
  EXPECT_TRUE(r.tie);
  EXPECT_EQ(r.t, Rational(1));
  EXPECT_EQ(r.distance, -1.0);
  const MddRefResult r2 = cubes({0.5, 0, 0}, vr(1, 0, 0));  // t in [-1.5, 0.5]: no tie
  EXPECT_FALSE(r2.tie);
}

TEST(MddReferenceSelfTest, TouchingCubes) {
  // Q = P + (1,0,0): M = [-2,0] x [-1,1]^2, the origin on the facet x = 0.
  EXPECT_EQ(MinkowskiDifferenceReference(unitCube(), unitCube({1, 0, 0})).classifyOrigin(),
            OriginLocation::Boundary);
  for (const Vec3r& s : {vr(-1, 0, 0), vr(1, 0, 0), vr(-1, 1, 1), vr(0, 1, 0), vr(0, 2, -3)}) {
    const MddRefResult r = cubes({1, 0, 0}, s);
    SCOPED_TRACE(testing::Message() << "s = " << s.transpose());
    EXPECT_EQ(r.status, MddRefStatus::Touching);
    EXPECT_EQ(r.origin, OriginLocation::Boundary);
    EXPECT_EQ(r.t, Rational(0));
    EXPECT_EQ(r.translation, 0.0);
    EXPECT_EQ(r.distance, 0.0);
    EXPECT_EQ(normalSet(r.contact.normals), normalSet({vr(1, 0, 0)}));
  }
  // s = (0,1,0) runs inside the facet plane: t_lo < 0 < t_hi, yet P and Q only touch.
  const MddRefResult r = cubes({1, 0, 0}, vr(0, 1, 0));
  EXPECT_TRUE(r.lineInFacetPlane);
  EXPECT_EQ(r.tLo, Rational(-1));
  EXPECT_EQ(r.tHi, Rational(1));
  // Touching at an edge of M: Q = P + (1,1,0), origin on the edge x = y = 0.
  const MddRefResult e = cubes({1, 1, 0}, vr(1, -1, 0));
  EXPECT_EQ(e.status, MddRefStatus::Touching);
  EXPECT_EQ(normalSet(e.contact.normals), normalSet({vr(1, 0, 0), vr(0, 1, 0)}));
}

TEST(MddReferenceSelfTest, EdgeGraze) {
  // Q = P + (2,-2,0): M = [-3,-1] x [1,3] x [-1,1]. The line t(-1,3,0) meets M only at the
  // edge point (-1,3,0) (t = 1): the plane 3x + y = 0 through the origin supports M there.
  const MddRefResult r = cubes({2, -2, 0}, vr(-1, 3, 0));
  EXPECT_EQ(r.status, MddRefStatus::Separated);
  EXPECT_EQ(r.tLo, Rational(1));
  EXPECT_EQ(r.tHi, Rational(1));
  EXPECT_EQ(r.t, Rational(1));
  EXPECT_NEAR(r.translation, std::sqrt(10.0), 1e-15);
  EXPECT_EQ(normalSet(r.contact.normals), normalSet({vr(1, 0, 0), vr(0, 1, 0)}));
  // A slightly steeper line misses M entirely, a slightly shallower one cuts it.
  EXPECT_EQ(cubes({2, -2, 0}, vr(-100, 301, 0)).status, MddRefStatus::NoContact);
  const MddRefResult cut = cubes({2, -2, 0}, vr(-100, 299, 0));
  EXPECT_EQ(cut.status, MddRefStatus::Separated);
  EXPECT_LT(cut.tLo, cut.tHi);
}

TEST(MddReferenceSelfTest, VertexGraze) {
  // M = [-4,-2] x [-1,1]^2, vertex (-2,1,1); the plane x + y + z = 0 supports M there only.
  const MddRefResult r = cubes({3, 0, 0}, vr(-2, 1, 1));
  EXPECT_EQ(r.status, MddRefStatus::Separated);
  EXPECT_EQ(r.tLo, Rational(1));
  EXPECT_EQ(r.tHi, Rational(1));
  EXPECT_NEAR(r.translation, std::sqrt(6.0), 1e-15);
  EXPECT_EQ(normalSet(r.contact.normals),
            normalSet({vr(1, 0, 0), vr(0, 1, 0), vr(0, 0, 1)}));
}

TEST(MddReferenceSelfTest, NoContact) {
  for (const Vec3r& s : {vr(0, 1, 0), vr(-1, 1, 0), vr(0, 0, -1)}) {
    const MddRefResult r = cubes({3, 0, 0}, s);
    SCOPED_TRACE(testing::Message() << "s = " << s.transpose());
    EXPECT_EQ(r.status, MddRefStatus::NoContact);
    EXPECT_FALSE(r.lineMeetsM);
    EXPECT_TRUE(std::isinf(r.distance));
  }
}

TEST(MddReferenceSelfTest, QueryOffsetMovesQ) {
  // Querying with Q moved by u equals building with Q moved by u.
  const MinkowskiDifferenceReference ref(unitCube(), unitCube());
  const MddRefResult a = ref.query(vr(-3, 1, 0), vr(3, 0, 0));
  const MddRefResult b = cubes({3, 0, 0}, vr(-3, 1, 0));
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.tLo, b.tLo);
  EXPECT_EQ(a.tHi, b.tHi);
  EXPECT_EQ(ref.classifyOrigin(vr(3, 0, 0)), OriginLocation::Outside);
  EXPECT_EQ(ref.classifyOrigin(vr(1, 0, 0)), OriginLocation::Boundary);
  EXPECT_EQ(ref.classifyOrigin(vr(1, 1, -1)), OriginLocation::Boundary);
  EXPECT_EQ(ref.classifyOrigin(vr(Rational(1, 3), 0, 0)), OriginLocation::Inside);
}

TEST(MddReferenceSelfTest, CubeFacetsAreMerged) {
  // M of two unit cubes is a cube: 6 planes after merging CGAL's 12 triangles.
  const MinkowskiDifferenceReference ref(unitCube(), unitCube({3, 0, 0}));
  EXPECT_EQ(ref.facets().size(), 6u);
  EXPECT_EQ(ref.triangleCount(), 12u);
  EXPECT_EQ(ref.vertices().size(), 8u);
}

TEST(MddReferenceSelfTest, RejectsFlatDifference) {
  // Two unit squares in parallel planes: M is a flat square.
  std::vector<Eigen::Vector3d> a = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  std::vector<Eigen::Vector3d> b = {{0, 0, 2}, {1, 0, 2}, {0, 1, 2}, {1, 1, 2}};
  EXPECT_THROW(MinkowskiDifferenceReference(a, b), std::invalid_argument);
  EXPECT_THROW(MinkowskiDifferenceReference(a, std::vector<Eigen::Vector3d>{}),
               std::invalid_argument);
  EXPECT_THROW(MinkowskiDifferenceReference(unitCube(), unitCube()).query(vr(0, 0, 0)),
               std::invalid_argument);
}

// ---------------------------------------------------------------- paper shapes

// Exact number of hull vertices: CGAL's Epick hull decides with exact predicates.
std::size_t hullVertexCount(const std::vector<Eigen::Vector3d>& pts) {
  using Point = CGAL::Epick::Point_3;
  std::vector<Point> p;
  for (const auto& v : pts) p.emplace_back(v.x(), v.y(), v.z());
  CGAL::Surface_mesh<Point> mesh;
  CGAL::convex_hull_3(p.begin(), p.end(), mesh);
  return mesh.number_of_vertices();
}

TEST(PaperShapesSelfTest, VertexCountsAndRadius) {
  for (int seed : {1, 2, 3}) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    for (PaperShape id : mink_test::kPaperShapes) {
      SCOPED_TRACE(testing::Message() << mink_test::paperShapeName(id) << " seed " << seed);
      const auto pts = mink_test::paperShape(id, rng);
      EXPECT_EQ(static_cast<int>(pts.size()), mink_test::paperShapePointCount(id));
      const std::size_t hv = hullVertexCount(pts);
      if (id == PaperShape::P5) {
        EXPECT_LT(hv, 100u);  // interior points exist: the point count is not the vertex count
        EXPECT_GE(hv, 15u);
      } else {
        EXPECT_EQ(static_cast<int>(hv), mink_test::paperShapeHullVertexCount(id));
      }
      double rmax = 0;
      for (const auto& p : pts) rmax = std::max(rmax, p.norm());
      EXPECT_LT(rmax, mink_test::kPaperShapeRadius);
      EXPECT_GT(rmax, 0.8 * mink_test::kPaperShapeRadius);  // sizes comparable, as in the paper
    }
  }
  EXPECT_EQ(mink_test::kPaperPairs.size(), 10u);
}

TEST(PaperShapesSelfTest, Deterministic) {
  for (PaperShape id : mink_test::kPaperShapes) {
    std::mt19937 a(7), b(7);
    EXPECT_EQ(mink_test::paperShape(id, a), mink_test::paperShape(id, b))
        << mink_test::paperShapeName(id);
  }
  std::mt19937 a(11), b(11);
  EXPECT_EQ(mink_test::randomRotation(a), mink_test::randomRotation(b));
}

TEST(PaperShapesSelfTest, ConeAndCylinderSidesAreExactlyPlanar) {
  // The property the generators promise: lateral quads are exactly planar in the doubles.
  for (PaperShape id : {PaperShape::P1, PaperShape::P2}) {
    std::mt19937 rng(1);
    const auto pts = mink_test::toExact(mink_test::paperShape(id, rng));
    const std::size_t n = pts.size() / 2;
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3r& a = pts[k];
      const Vec3r& b = pts[(k + 1) % n];
      const Vec3r& c = pts[n + (k + 1) % n];
      const Vec3r& d = pts[n + k];
      const Vec3r e1 = b - a, e2 = c - a, e3 = d - a;
      const Rational vol = e1.x() * (e2.y() * e3.z() - e2.z() * e3.y()) -
                           e1.y() * (e2.x() * e3.z() - e2.z() * e3.x()) +
                           e1.z() * (e2.x() * e3.y() - e2.y() * e3.x());
      EXPECT_EQ(vol, Rational(0)) << mink_test::paperShapeName(id) << " quad " << k;
    }
  }
}

TEST(PaperShapesSelfTest, RationalRotationsAreExact) {
  std::mt19937 rng(5);
  for (int i = 0; i < 50; ++i) {
    const auto rot = mink_test::randomRationalRotation(rng, 64 + i);
    SCOPED_TRACE(testing::Message() << "case " << i);
    const mink_test::Mat3r rtr = rot.exact.transpose() * rot.exact;
    EXPECT_TRUE(rtr == mink_test::Mat3r::Identity());
    const auto& m = rot.exact;
    const Rational det = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
                         m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
                         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
    EXPECT_EQ(det, Rational(1));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(rot.rounded(r, c) - CGAL::to_double(m(r, c))), 0x1.0p-53);
    const Eigen::Matrix3d q = mink_test::randomRotation(rng);
    EXPECT_LT((q.transpose() * q - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    EXPECT_NEAR(q.determinant(), 1.0, 1e-14);
  }
  // w = 0 (half-turn about z) and the Cayley form for w != 0.
  const auto half = mink_test::rationalRotationFromQuaternion(0, 0, 0, 1);
  EXPECT_EQ(half.exact(0, 0), Rational(-1));
  EXPECT_EQ(half.exact(2, 2), Rational(1));
  const auto c = mink_test::rationalRotationFromQuaternion(2, 1, 0, 0);  // K = [(1/2,0,0)]x
  EXPECT_EQ(c.exact(1, 1), Rational(3, 5));
  EXPECT_EQ(c.exact(2, 1), Rational(4, 5));
}

// ------------------------------------------------- reference on the paper shapes

struct PlacedPair {
  std::vector<Eigen::Vector3d> pBody, qBody;
  std::vector<Vec3r> pWorld, qWorld;  // P at identity, Q rotated (exactly) and translated
};

PlacedPair placePair(PaperShape a, PaperShape b, std::mt19937& rng, double maxOffset) {
  PlacedPair pp;
  pp.pBody = mink_test::paperShape(a, rng);
  pp.qBody = mink_test::paperShape(b, rng);
  const auto rot = mink_test::randomRationalRotation(rng);
  const Eigen::Vector3d offset = mink_test::randomUnitVector(rng) * mink_test::uniformIn(rng, 0, maxOffset);
  pp.pWorld = mink_test::toExact(pp.pBody);
  pp.qWorld = mink_test::placeExact(pp.qBody, rot.exact, mink_test::toExact(offset));
  return pp;
}

// Brute-force support values: for every facet n·x <= c of M, c must equal
// max_p n·p − min_q n·q exactly (the facet is a supporting plane of P ⊕ −Q), and every
// vertex of M must be a difference of input points lying on at least three facet planes.
TEST(MddReferenceSelfTest, FacetsAreSupportingPlanesOfPMinusQ) {
  std::mt19937 rng(21);
  for (auto pr : {std::make_pair(PaperShape::P1, PaperShape::P2),
                  std::make_pair(PaperShape::P1, PaperShape::P1),
                  std::make_pair(PaperShape::P5, PaperShape::P5)}) {
    const PlacedPair pp = placePair(pr.first, pr.second, rng, 6.0);
    SCOPED_TRACE(testing::Message() << mink_test::paperShapeName(pr.first) << ","
                                    << mink_test::paperShapeName(pr.second));
    const MinkowskiDifferenceReference ref(pp.pWorld, pp.qWorld);
    ASSERT_GE(ref.facets().size(), 4u);
    for (const auto& f : ref.facets()) {
      Rational hp = f.normal.dot(pp.pWorld[0]), lq = f.normal.dot(pp.qWorld[0]);
      for (const auto& p : pp.pWorld) hp = std::max(hp, Rational(f.normal.dot(p)));
      for (const auto& q : pp.qWorld) lq = std::min(lq, Rational(f.normal.dot(q)));
      ASSERT_EQ(f.offset, hp - lq);
    }
    for (const auto& v : ref.vertices()) {
      EXPECT_GE(ref.facetNormalsThrough(v).size(), 3u);
      bool isDifference = false;
      for (const auto& p : pp.pWorld) {
        for (const auto& q : pp.qWorld)
          if (p - q == v) { isDifference = true; break; }
        if (isDifference) break;
      }
      EXPECT_TRUE(isDifference);
    }
  }
}

TEST(MddReferenceSelfTest, IntervalFilterMatchesPureExact) {
  std::mt19937 rng(33);
  int statusCount[4] = {0, 0, 0, 0};
  for (auto pr : mink_test::kPaperPairs) {
    // P4 (500 vertices) pairs are left to the GJK test below: the unfiltered exact path
    // costs seconds on their thousands of facets, minutes under sanitizers.
    if (pr.first == PaperShape::P4) continue;
    const PlacedPair pp = placePair(pr.first, pr.second, rng, 9.0);
    MinkowskiDifferenceReference ref(pp.pWorld, pp.qWorld);
    for (int k = 0; k < 12; ++k) {
      const Vec3r s = mink_test::toExact(mink_test::randomUnitVector(rng));
      // Offsets along s and across it, so all statuses and grazes near the boundary occur.
      Vec3r u = mink_test::toExact(mink_test::randomUnitVector(rng) * mink_test::uniformIn(rng, 0, 3));
      SCOPED_TRACE(testing::Message() << mink_test::paperShapeName(pr.first) << ","
                                      << mink_test::paperShapeName(pr.second) << " dir " << k);
      ref.setFiltered(true);
      const MddRefResult a = ref.query(s, u);
      ref.setFiltered(false);
      const MddRefResult b = ref.query(s, u);
      ASSERT_EQ(a.status, b.status);
      ++statusCount[static_cast<int>(a.status)];
      EXPECT_EQ(a.origin, b.origin);
      ASSERT_EQ(a.lineMeetsM, b.lineMeetsM);
      if (!a.lineMeetsM) continue;
      EXPECT_EQ(a.tLo, b.tLo);
      EXPECT_EQ(a.tHi, b.tHi);
      EXPECT_EQ(a.t, b.t);
      EXPECT_EQ(a.translation, b.translation);
      EXPECT_EQ(normalSet(a.contact.normals), normalSet(b.contact.normals));
      EXPECT_EQ(normalSet(a.lo.normals), normalSet(b.lo.normals));
      EXPECT_FALSE(a.lo.normals.empty());
      EXPECT_FALSE(a.hi.normals.empty());
      // The ends are on ∂M, points in between strictly inside (unless the line grazes).
      EXPECT_EQ(ref.classifyOrigin(Vec3r(u + s * a.tLo)), OriginLocation::Boundary);
      EXPECT_EQ(ref.classifyOrigin(Vec3r(u + s * a.tHi)), OriginLocation::Boundary);
      if (a.tLo < a.tHi && !a.lineInFacetPlane) {
        const Rational mid = (a.tLo + a.tHi) / 2;
        EXPECT_EQ(ref.classifyOrigin(Vec3r(u + s * mid)), OriginLocation::Inside);
      }
    }
    // A touching configuration by construction: Q moved onto the exit point.
    const Vec3r s = mink_test::toExact(mink_test::randomUnitVector(rng));
    ref.setFiltered(true);
    const MddRefResult r = ref.query(s);
    if (r.lineMeetsM) {
      const MddRefResult t = ref.query(s, Vec3r(s * r.tHi));
      EXPECT_EQ(t.status, MddRefStatus::Touching);
      EXPECT_EQ(t.tHi, Rational(0));
      ++statusCount[static_cast<int>(t.status)];
    }
  }
  // The random cases must exercise every status, or the comparison above proves little.
  for (int i = 0; i < 4; ++i) EXPECT_GT(statusCount[i], 0) << "status " << i;
}

// ---------------------------------------------------------------- FCL / libccd

#ifdef MINK_TEST_WITH_FCL

using mink_test::GjkShape;
using mink_test::RigidPose;

RigidPose at(const Eigen::Vector3d& t, const Eigen::Matrix3d& r = Eigen::Matrix3d::Identity()) {
  RigidPose p;
  p.rotation = r;
  p.translation = t;
  return p;
}

TEST(GjkReferenceSelfTest, SeparatedBoxesMatchAnalyticDistance) {
  const GjkShape box(unitCube());
  const Eigen::Matrix3d rzm45 =
      Eigen::AngleAxisd(-M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  struct Case {
    RigidPose pose;
    double distance;
  };
  // B's own frame: the unit cube [0,1]^3, rotations act about B's corner at its origin.
  // FCL's GST_LIBCCD distance is wrong on several of these (FCL issue #508), so only
  // GST_INDEP and libccd are checked.
  const std::vector<Case> axisAligned = {
      {at({3, 0, 0}), 2.0},                             // face-face
      {at({3, 2, 0}), std::sqrt(5.0)},                  // edge-edge
      {at({2.5, 3, 4}), std::sqrt(1.5 * 1.5 + 4 + 9)},  // vertex-vertex
      {at({4.0, 0.5, 0.0}, rzm45), 3.0},                // B's corner edge x = 4, y = 0.5 nearest
      {at({1.0 + 1e-3, 0.2, 0.3}), 1e-3},               // nearly touching, face-face
  };
  for (std::size_t i = 0; i < axisAligned.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "axis-aligned case " << i);
    const auto& c = axisAligned[i];
    const auto r = mink_test::fclDistance(box, RigidPose{}, box, c.pose, fcl::GST_INDEP);
    EXPECT_NEAR(r.distance, c.distance, 1e-9);
    EXPECT_FALSE(r.colliding);
    EXPECT_NEAR((r.pointOnA - r.pointOnB).norm(), c.distance, 1e-9);
    EXPECT_NEAR(mink_test::fclSignedDistance(box, RigidPose{}, box, c.pose), c.distance, 1e-9);
    // libccd decides "intersects" from squared lengths against its epsilon, so its distance
    // is good to about sqrt(DBL_EPSILON) ~ 1.5e-8 (measured: up to 2.2e-8 here).
    EXPECT_NEAR(mink_test::ccdDistanceBisection(box, RigidPose{}, box, c.pose), c.distance, 1e-7);
    EXPECT_FALSE(mink_test::ccdIntersectGJK(box, RigidPose{}, box, c.pose));
    EXPECT_FALSE(mink_test::ccdIntersectMPR(box, RigidPose{}, box, c.pose));
    const auto cd = mink_test::certifiedDistance(box, RigidPose{}, box, c.pose);
    EXPECT_TRUE(cd.certified);
    EXPECT_NEAR(cd.distance, c.distance, 1e-9);
  }
  // General position: B randomly rotated, its lowest-x vertex placed at x = 1 + d above the
  // interior point (1, 0.5, 0.5) of A's face x = 1. The half-space x <= 1 holds A and is at
  // distance d from B, and that vertex realises it: the distance is exactly d.
  std::mt19937 rng(8);
  for (int i = 0; i < 12; ++i) {
    const double d = i % 3 == 0 ? 2.0 : (i % 3 == 1 ? 0.25 : 1e-3);
    const Eigen::Matrix3d R = mink_test::randomRotation(rng);
    Eigen::Vector3d low = R * unitCube()[0];
    for (const auto& v : unitCube())
      if ((R * v).x() < low.x()) low = R * v;
    const RigidPose pose = at(Eigen::Vector3d(1.0 + d, 0.5, 0.5) - low, R);
    SCOPED_TRACE(testing::Message() << "rotated case " << i << " d = " << d);
    // GST_LIBCCD's distance is not checked: it is wrong on some of these (see fclDistance).
    const auto r = mink_test::fclDistance(box, RigidPose{}, box, pose, fcl::GST_INDEP);
    EXPECT_NEAR(r.distance, d, 1e-9);
    EXPECT_FALSE(r.colliding);
    EXPECT_NEAR((r.pointOnA - r.pointOnB).norm(), d, 1e-9);
    EXPECT_FALSE(mink_test::fclDistance(box, RigidPose{}, box, pose, fcl::GST_LIBCCD).colliding);
    EXPECT_NEAR(mink_test::fclSignedDistance(box, RigidPose{}, box, pose), d, 1e-9);
    EXPECT_NEAR(mink_test::ccdDistanceBisection(box, RigidPose{}, box, pose), d, 1e-7);
    const auto cd = mink_test::certifiedDistance(box, RigidPose{}, box, pose);
    EXPECT_TRUE(cd.certified);
    EXPECT_NEAR(cd.distance, d, 1e-9);
    EXPECT_LE(cd.lowerBound, d + 1e-12);
    EXPECT_GE(cd.upperBound, d - 1e-12);
    EXPECT_FALSE(mink_test::ccdIntersectGJK(box, RigidPose{}, box, pose));
    EXPECT_FALSE(mink_test::ccdIntersectMPR(box, RigidPose{}, box, pose));
  }
}

TEST(GjkReferenceSelfTest, OverlappingBoxesMatchAnalyticDepth) {
  const GjkShape box(unitCube());
  // Overlaps 0.3, 0.8, 0.9 along x, y, z: the penetration depth is 0.3 along x.
  const RigidPose b = at({0.7, 0.2, 0.1});
  EXPECT_TRUE(mink_test::ccdIntersectGJK(box, RigidPose{}, box, b));
  EXPECT_TRUE(mink_test::ccdIntersectMPR(box, RigidPose{}, box, b));
  EXPECT_EQ(mink_test::ccdDistanceBisection(box, RigidPose{}, box, b), 0.0);
  const auto epa = mink_test::ccdPenetrationEPA(box, RigidPose{}, box, b);
  ASSERT_TRUE(epa.intersecting);
  EXPECT_NEAR(epa.depth, 0.3, 1e-6);
  EXPECT_NEAR(epa.direction.x(), 1.0, 1e-6);  // moving B by +0.3 x separates
  const auto mpr = mink_test::ccdPenetrationMPR(box, RigidPose{}, box, b);
  ASSERT_TRUE(mpr.intersecting);
  EXPECT_GE(mpr.depth, 0.3 - 1e-6);  // MPR: a valid but not necessarily minimal depth
  for (auto solver : {fcl::GST_LIBCCD, fcl::GST_INDEP})
    EXPECT_TRUE(mink_test::fclDistance(box, RigidPose{}, box, b, solver).colliding) << solver;
  EXPECT_NEAR(mink_test::fclSignedDistance(box, RigidPose{}, box, b), -0.3, 1e-6);
  const auto cd = mink_test::certifiedDistance(box, RigidPose{}, box, b);
  EXPECT_FALSE(cd.certified);
  EXPECT_EQ(cd.distance, 0.0);
}

TEST(GjkReferenceSelfTest, HullMeshIsClosedAndOutward) {
  std::mt19937 rng(3);
  const auto pts = mink_test::paperShape(PaperShape::P5, rng);
  const auto mesh = mink_test::convexHullMesh(pts);
  EXPECT_EQ(mesh.vertices.size(), hullVertexCount(pts));
  EXPECT_EQ(mesh.triangles.size(), 2 * mesh.vertices.size() - 4);  // Euler, triangulated sphere
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                  .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    for (const auto& v : mesh.vertices) EXPECT_LE(n.dot(v - mesh.vertices[t[0]]), 1e-9);
  }
  EXPECT_THROW(mink_test::convexHullMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}),
               std::invalid_argument);
}

// The paper's verification (Sec. VII) run on the exact reference: after moving Q by the
// reference translation along s, the GJK distance is ~0; the ends of [t_lo, t_hi] are
// touching placements, a little outside them the shapes separate, their midpoint overlaps.
TEST(GjkReferenceSelfTest, ReferenceTranslationGivesGjkContact) {
  std::mt19937 rng(44);
  int statusCount[4] = {0, 0, 0, 0};
  int touchingChecks = 0, fclIndepWrong = 0, epaFailures = 0;
  for (auto pr : mink_test::kPaperPairs) {
    const PlacedPair pp = placePair(pr.first, pr.second, rng, 8.0);
    std::vector<Eigen::Vector3d> pw, qw;  // world points rounded to double, identity pose
    for (const auto& v : pp.pWorld)
      pw.emplace_back(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
    for (const auto& v : pp.qWorld)
      qw.emplace_back(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
    const GjkShape P(pw), Q(qw);
    const MinkowskiDifferenceReference ref(pp.pWorld, pp.qWorld);
    const std::string name = std::string(mink_test::paperShapeName(pr.first)) + "," +
                             mink_test::paperShapeName(pr.second);

    // Overlap without any motion: exact origin classification against GJK.
    const OriginLocation o = ref.classifyOrigin();
    if (o == OriginLocation::Outside) {
      EXPECT_GT(mink_test::certifiedDistance(P, RigidPose{}, Q, RigidPose{}).distance, 0.0) << name;
      EXPECT_FALSE(mink_test::ccdIntersectMPR(P, RigidPose{}, Q, RigidPose{})) << name;
    } else {
      EXPECT_TRUE(mink_test::ccdIntersectGJK(P, RigidPose{}, Q, RigidPose{})) << name;
      EXPECT_TRUE(mink_test::ccdIntersectMPR(P, RigidPose{}, Q, RigidPose{})) << name;
    }

    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3d sd = mink_test::randomUnitVector(rng);
      const MddRefResult r = ref.query(mink_test::toExact(sd));
      SCOPED_TRACE(testing::Message() << name << " dir " << k << " status " << toString(r.status));
      ++statusCount[static_cast<int>(r.status)];
      if (!r.lineMeetsM) {
        // Q never meets P along this line: sample it, there must always be a gap.
        for (double t = -12; t <= 12; t += 1.5) {
          const auto d = mink_test::certifiedDistance(P, RigidPose{}, Q, at(t * sd));
          EXPECT_GT(d.distance, 0.0) << "t = " << t;
        }
        continue;
      }
      const double tLo = CGAL::to_double(r.tLo), tHi = CGAL::to_double(r.tHi);
      EXPECT_NEAR(r.translation, CGAL::to_double(r.t), 1e-12);  // |sd| = 1 up to rounding
      for (double t : {r.translation, tLo, tHi}) {
        // Exactly touching in the reals; after rounding barely apart or barely overlapping.
        ++touchingChecks;
        const auto d = mink_test::certifiedDistance(P, RigidPose{}, Q, at(t * sd));
        EXPECT_LT(d.distance, 1e-7) << "t = " << t;
        EXPECT_LT(d.lowerBound, 1e-7) << "t = " << t;  // no plane separates them by more
        const auto raw = mink_test::fclDistance(P, RigidPose{}, Q, at(t * sd));
        if (!raw.colliding && raw.distance > 1e-7) ++fclIndepWrong;  // plain FCL, unchecked
        const double sdist = mink_test::fclSignedDistance(P, RigidPose{}, Q, at(t * sd));
        if (std::isnan(sdist)) ++epaFailures;
        else EXPECT_LT(sdist, 1e-7) << "t = " << t;
      }
      // Just outside [t_lo, t_hi] the shapes are apart (certified), at its middle they overlap.
      constexpr double kStep = 1e-3;
      for (double t : {tLo - kStep, tHi + kStep}) {
        const auto d = mink_test::certifiedDistance(P, RigidPose{}, Q, at(t * sd));
        EXPECT_TRUE(d.certified) << "t = " << t;
        EXPECT_GT(d.distance, 0.0) << "t = " << t;
        EXPECT_FALSE(mink_test::ccdIntersectMPR(P, RigidPose{}, Q, at(t * sd))) << "t = " << t;
      }
      if (tHi - tLo > 4 * kStep) {
        const Eigen::Vector3d mid = 0.5 * (tLo + tHi) * sd;
        EXPECT_TRUE(mink_test::ccdIntersectGJK(P, RigidPose{}, Q, at(mid)));
        EXPECT_TRUE(mink_test::fclDistance(P, RigidPose{}, Q, at(mid), fcl::GST_LIBCCD).colliding);
      }
    }
  }
  EXPECT_GT(statusCount[static_cast<int>(MddRefStatus::Separated)], 0);
  EXPECT_GT(statusCount[static_cast<int>(MddRefStatus::Penetrating)], 0);
  EXPECT_GT(statusCount[static_cast<int>(MddRefStatus::NoContact)], 0);
  std::printf("[ info     ] %d touching placements: plain FCL GST_INDEP distance > 1e-7 on %d, "
              "FCL signed distance (EPA) threw on %d\n",
              touchingChecks, fclIndepWrong, epaFailures);
}

#else

TEST(GjkReferenceSelfTest, SkippedWithoutFcl) {
  GTEST_SKIP() << "built without MINK_TEST_WITH_FCL: the FCL/libccd reference self-tests need "
                  "fcl and ccd linked into this target (see tests/support/gjk_reference.hpp)";
}

#endif

}  // namespace
