// tests/cpd/minkowski_boundary_test.cpp — mink/cpd/minkowski_boundary.hpp (the convolution
// of cpd/convolution.hpp trimmed by cpd/detail/trimming.hpp, no ball) against CGAL's
// minkowski_sum_3 on Nef polyhedra over the exact kernel (tests/support/minkowski_reference.hpp):
//   - double, on small non-convex pairs (L-block, U-block, star prism, cube with a
//     through-hole, each against a box and some against each other), axis-aligned (ties
//     and coplanar facets everywhere) and turned by a generic rotation: area and volume to
//     1e-9 relative; every triangle of mink's patch on CGAL's boundary (its centroid within
//     1e-9 of the scene) and facing outward; CGAL's boundary covered by mink's (points
//     sampled on each CGAL triangle within 1e-9);
//   - CGAL::Gmpq, exact: the L-block against a box, aligned: the volume equal as a
//     rational, every triangle's centroid exactly on CGAL's boundary, the area (all faces
//     axis-aligned) equal as a rational;
//   - the Euclidean penetration depth (cpd/continuous_penetration_depth.hpp) equal to the
//     distance from o to CGAL's boundary, to 1e-9 of the scene; the CPD's q on CGAL's
//     boundary, no nearer to o, and Definition 1 where Penetrating;
//   - a superset of the convolution (every face–vertex pair, compatible or not) trims to
//     the same boundary: the trimming classifies, it does not rely on the facets given.
// (A torus of 192 triangles takes CGAL ten seconds and more: kept out of the suite; the
// benchmark compares on it.)
#include "mink/cpd/continuous_penetration_depth.hpp"
#include "mink/cpd/minkowski_boundary.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <Eigen/Geometry>

#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "support/mesh_shapes.hpp"
#include "support/minkowski_reference.hpp"

namespace {

using V = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
using mink_test::MeshShape;
using mink_test::MinkowskiReference;

#ifdef MINK_SANITIZE_BUILD
constexpr bool kSanitize = true;
#else
constexpr bool kSanitize = false;
#endif

struct Case {
  std::string name;
  MeshShape a, b;
  M3 R;
  V t;
};

MeshShape smallBox() { return mink_test::boxShape(V(-0.5, -0.25, -0.75), V(0.5, 0.25, 0.75)); }

std::vector<Case> cases() {
  const M3 I = M3::Identity();
  const M3 turn = Eigen::AngleAxisd(0.4, V(1, 2, 3).normalized()).toRotationMatrix();
  const M3 turn2 = Eigen::AngleAxisd(1.1, V(-2, 1, 0.5).normalized()).toRotationMatrix();
  std::vector<Case> c = {
      {"L-block + box, aligned", mink_test::lBlock(), smallBox(), I, V(0.3, 0.1, 0.2)},
      {"L-block + box, turned", mink_test::lBlock(), smallBox(), turn, V(0.2, -0.1, 0.3)},
      {"U-block + box, aligned", mink_test::uBlock(), smallBox(), I, V(1.5, 0.75, 0.5)},
      {"U-block + box, turned", mink_test::uBlock(), smallBox(), turn2, V(1.25, 1.0, 0.5)},
      {"L-block + L-block, turned", mink_test::lBlock(), mink_test::lBlock(), turn, V(0.2, -0.1, 0.3)},
      {"cube with hole + box, aligned", mink_test::cubeWithHole(), mink_test::boxShape(V(-0.25, -0.25, -0.25), V(0.25, 0.25, 0.25)), I, V(0.0, 0.0, 0.5)},
  };
  if (!kSanitize) {
    c.push_back({"star prism + box, turned", mink_test::starPrism(), mink_test::boxShape(V(-2, -3, -1), V(2, 3, 1)), turn, V(1, 2, 3)});
    c.push_back({"star prism + L-block, turned", mink_test::starPrism(), mink_test::lBlock(), turn2, V(0.5, 0.5, 2)});
  }
  return c;
}

std::vector<V> placed(const MeshShape& b, const M3& R, const V& t) {
  std::vector<V> out;
  for (const V& p : b.vertices) out.push_back(R * p + t);  // as ConvolutionFrame::place
  return out;
}

double sceneSize(const MeshShape& a, const std::vector<V>& pb) {
  double s = 0;
  for (const V& p : a.vertices) s = std::max(s, p.cwiseAbs().maxCoeff());
  for (const V& p : pb) s = std::max(s, p.cwiseAbs().maxCoeff());
  return s;
}

TEST(MinkowskiBoundary, AgainstCgalMinkowskiSum) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const auto A = mink::TriangleMesh<double>::fromMesh(c.a.verticesAs<double>(), c.a.triangles);
    const auto B = mink::TriangleMesh<double>::fromMesh(c.b.verticesAs<double>(), c.b.triangles);
    mink::Pose<double> poseA, poseB;
    poseB.rotation = c.R;
    poseB.translation = c.t;
    const mink::MinkowskiPatch<double> P = mink::minkowskiBoundary(A, poseA, B, poseB);
    const std::vector<V> pb = placed(c.b, c.R, c.t);
    const MinkowskiReference ref(c.a, pb, c.b.triangles);
    const auto m = mink_test::measure(P);
    const double L = sceneSize(c.a, pb);
    std::printf("[cpd] %-32s facets %4d pieces %5d tests %4d triangles %5zu area %.12f (CGAL %.12f) volume %.12f (CGAL %.12f)\n",
                c.name.c_str(), P.facetsGathered, P.pieces, P.overlapTests, P.triangles.size(), m.area, ref.area(), m.volume,
                CGAL::to_double(ref.volume()));
    EXPECT_NEAR(m.area, ref.area(), 1e-9 * ref.area());
    EXPECT_NEAR(m.volume, CGAL::to_double(ref.volume()), 1e-9 * std::abs(CGAL::to_double(ref.volume())));
    EXPECT_LT(m.areaVector.norm(), 1e-9 * m.area) << "the patch is not closed";
    // Every triangle on CGAL's boundary, facing outward (its centroid moved out leaves M:
    // the reference's nearest triangle has the same orientation).
    int off = 0;
    for (std::size_t i = 0; i < P.triangles.size(); ++i) {
      const auto& t = P.triangles[i];
      const V x = (P.vertices[t[0]] + P.vertices[t[1]] + P.vertices[t[2]]) / 3;
      if (ref.distance(x) > 1e-9 * L) ++off;
    }
    EXPECT_EQ(off, 0) << "triangles off CGAL's boundary";
    // CGAL's boundary covered: points sampled on each of its triangles near mink's patch.
    int uncovered = 0, samples = 0;
    for (const auto& t : ref.trianglesDouble())
      for (int i = 1; i < 4; ++i)
        for (int j = 1; i + j < 4; ++j) {
          const V x = t[0] + (t[1] - t[0]) * (i / 4.0) + (t[2] - t[0]) * (j / 4.0);
          ++samples;
          if (mink_test::distanceToPatch(P, x) > 1e-9 * L) ++uncovered;
        }
    EXPECT_EQ(uncovered, 0) << "of " << samples << " points sampled on CGAL's boundary";
    // The Euclidean penetration depth is the distance from o to CGAL's boundary (every
    // case overlaps), and the CPD's point of ∂M is no nearer.
    const mink::CpdResult<double> e = mink::penetrationDepth(A, poseA, B, poseB);
    const mink::CpdResult<double> r = mink::ContinuousPenetrationDepth<double>(A, B).query(poseA, poseB);
    const double pd = ref.distance(V::Zero());
    std::printf("[cpd] %-32s Euclidean depth %.12f (CGAL %.12f), CPD %.12f\n", c.name.c_str(), e.depth, pd, r.depth);
    EXPECT_EQ(e.status, mink::CpdStatus::Penetrating);
    EXPECT_NEAR(e.depth, pd, 1e-9 * L);
    EXPECT_LT(ref.distance(e.point), 1e-9 * L);
    EXPECT_NE(r.status, mink::CpdStatus::Separated);
    EXPECT_GE(r.depth, pd - 1e-9 * L);
    EXPECT_LT(ref.distance(r.point), 1e-9 * L) << "the CPD's q is off CGAL's boundary";
    if (r.status == mink::CpdStatus::Penetrating) {
      EXPECT_LE(r.normal.cross(r.point).norm(), 1e-9 * r.depth);
    }
  }
}

TEST(MinkowskiBoundary, OrientedOutward) {
  // The volume enclosed by the patch is positive: triangles face out of M.
  const Case c = cases()[1];
  const auto A = mink::TriangleMesh<double>::fromMesh(c.a.verticesAs<double>(), c.a.triangles);
  const auto B = mink::TriangleMesh<double>::fromMesh(c.b.verticesAs<double>(), c.b.triangles);
  mink::Pose<double> poseA, poseB;
  poseB.rotation = c.R;
  poseB.translation = c.t;
  const auto P = mink::minkowskiBoundary(A, poseA, B, poseB);
  EXPECT_GT(mink_test::measure(P).volume, 0.0);
}

// tryMinkowskiBoundary, the entry point of builds without exceptions: a pose that is not
// rigid is an Error with the message minkowskiBoundary throws; a good one gives its patch.
TEST(MinkowskiBoundary, TryMinkowskiBoundary) {
  const Case c = cases()[1];
  const auto A = mink::TriangleMesh<double>::fromMesh(c.a.verticesAs<double>(), c.a.triangles);
  const auto B = mink::TriangleMesh<double>::fromMesh(c.b.verticesAs<double>(), c.b.triangles);
  mink::Pose<double> poseA, poseB, nanPose, mirror;
  poseB.rotation = c.R;
  poseB.translation = c.t;
  nanPose.translation[1] = std::numeric_limits<double>::quiet_NaN();
  mirror.rotation(0, 0) = -1;
  const std::pair<mink::Pose<double>, mink::Pose<double>> bad[] = {{nanPose, poseB}, {poseA, mirror}};
  for (const auto& [pa, pb] : bad) {
    const auto r = mink::tryMinkowskiBoundary(A, pa, B, pb);
    ASSERT_FALSE(r.ok());
    try {
      (void)mink::minkowskiBoundary(A, pa, B, pb);
      ADD_FAILURE() << "accepted";
    } catch (const mink::InvalidInput& e) {
      EXPECT_EQ(r.error().message(), std::string(e.what()));
    }
  }
  const auto r = mink::tryMinkowskiBoundary(A, poseA, B, poseB);
  ASSERT_TRUE(r.ok()) << r.error().message();
  const auto P = mink::minkowskiBoundary(A, poseA, B, poseB);
  EXPECT_GT(P.triangles.size(), 0u);
  EXPECT_EQ(r.value().triangles, P.triangles);
  EXPECT_EQ(r.value().vertices, P.vertices);
}

TEST(MinkowskiBoundary, ExactRationalsLBlockAndBox) {
  using Q = CGAL::Gmpq;
  const MeshShape a = mink_test::lBlock(), b = smallBox();
  const auto A = mink::TriangleMesh<Q>::fromMesh(a.verticesAs<Q>(), a.triangles);
  const auto B = mink::TriangleMesh<Q>::fromMesh(b.verticesAs<Q>(), b.triangles);
  mink::Pose<Q> poseA, poseB;
  poseB.translation = mink::Vec3<Q>(Q(3, 8), Q(1, 16), Q(1, 4));  // dyadic: the same numbers as in double
  const auto P = mink::minkowskiBoundary(A, poseA, B, poseB);
  const std::vector<V> pb = placed(b, M3::Identity(), V(0.375, 0.0625, 0.25));
  const MinkowskiReference ref(a, pb, b.triangles);
  using K = MinkowskiReference::K;
  // Gmpq to the kernel's number type (Epeck's lazy rational): via its exact mpq value.
  auto ft = [](const Q& x) { return K::FT(K::FT::ET(x.mpq())); };
  K::FT volume = 0, area = 0;
  int off = 0;
  for (const auto& t : P.triangles) {
    K::Point_3 p[3];
    for (int c = 0; c < 3; ++c) {
      const auto& v = P.vertices[static_cast<std::size_t>(t[c])];
      p[c] = K::Point_3(ft(v[0]), ft(v[1]), ft(v[2]));
    }
    volume += CGAL::determinant(p[0] - CGAL::ORIGIN, p[1] - CGAL::ORIGIN, p[2] - CGAL::ORIGIN) / 6;
    const auto n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    // Every face of this M is axis-aligned: its area is |the one non-zero component| / 2.
    ASSERT_TRUE((n.x() == 0) + (n.y() == 0) + (n.z() == 0) >= 2);
    area += (CGAL::abs(n.x()) + CGAL::abs(n.y()) + CGAL::abs(n.z())) / 2;
    const K::Point_3 centroid = CGAL::centroid(p[0], p[1], p[2]);
    if (!ref.onBoundary(centroid)) ++off;
  }
  EXPECT_EQ(volume, ref.volume());
  K::FT refArea = 0;
  for (const auto& t : ref.triangles()) {
    const auto n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    refArea += (CGAL::abs(n.x()) + CGAL::abs(n.y()) + CGAL::abs(n.z())) / 2;
  }
  EXPECT_EQ(area, refArea);
  EXPECT_EQ(off, 0);
}

TEST(MinkowskiBoundary, SupersetOfTheConvolutionTrimsToTheSameBoundary) {
  const Case c = cases()[1];
  const auto A = mink::TriangleMesh<double>::fromMesh(c.a.verticesAs<double>(), c.a.triangles);
  const auto B = mink::TriangleMesh<double>::fromMesh(c.b.verticesAs<double>(), c.b.triangles);
  mink::ConvolutionFrame<double> frame(A, B);
  frame.place(c.R, c.t);
  mink::MeshOverlap<double> overlap(A, B, c.R, c.t);
  std::vector<mink::ConvolutionPair> facets = mink::allCompatiblePairs(frame);
  const std::size_t compatible = facets.size();
  for (int f = 0; f < A.numTriangles(); ++f)
    for (int v = 0; v < B.numVertices(); ++v)
      if (!frame.compatibleFV(f, v)) facets.push_back({mink::ConvolutionType::FV, f, v, 0});
  ASSERT_GT(facets.size(), compatible);
  mink::MinkowskiPatch<double> P;
  mink::detail::Trimmer<double> trimmer;
  trimmer.run(frame, facets, mink::detail::Trimmer<double>::Region(), overlap, P);
  const MinkowskiReference ref(c.a, placed(c.b, c.R, c.t), c.b.triangles);
  EXPECT_NEAR(mink_test::measure(P).area, ref.area(), 1e-9 * ref.area());
}

}  // namespace
