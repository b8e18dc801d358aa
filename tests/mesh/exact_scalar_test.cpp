// The mesh layer instantiated with float and with CGAL::Gmpq (exact rationals) on the
// L-block and the torus 12x8: construction (counts, edge kinds equal to double's on the
// same numbers), and MeshOverlap with exact rational rotations (Gmpq) or float placements,
// against the exact brute force (CGAL do_intersect on Simple_cartesian<Gmpq>, every
// triangle pair, on the very points the query used). Neither shape fits inside the
// other (the L-block's 1 x 2 x 2 does not fit the tube of radius 0.75, the torus is
// larger than the L), so boundary contact is the whole answer.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <random>
#include <string>
#include <vector>

#include "mink/mesh/mesh_overlap.hpp"
#include "support/exact_placement.hpp"
#include "support/mesh_shapes.hpp"

namespace {

using Q = CGAL::Gmpq;
using K = CGAL::Simple_cartesian<Q>;

Q toQ(const Q& x) { return x; }
Q toQ(float x) { return Q(static_cast<double>(x)); }

template <class T>
K::Point_3 P(const mink::Vec3<T>& p) {
  return K::Point_3(toQ(p[0]), toQ(p[1]), toQ(p[2]));
}

// Exact: does a triangle of A meet a triangle of B, B's corners given?
template <class T>
bool bruteForce(const mink::TriangleMesh<T>& A, const std::vector<mink::Vec3<T>>& b, const mink::TriangleMesh<T>& B) {
  std::vector<K::Triangle_3> tb;
  for (const auto& t : B.triangles()) tb.emplace_back(P(b[t[0]]), P(b[t[1]]), P(b[t[2]]));
  for (const auto& t : A.triangles()) {
    const K::Triangle_3 ta(P(A.vertex(t[0])), P(A.vertex(t[1])), P(A.vertex(t[2])));
    for (const auto& u : tb)
      if (CGAL::do_overlap(ta.bbox(), u.bbox()) && CGAL::do_intersect(ta, u)) return true;
  }
  return false;
}

template <class T>
class ExactAndFloat : public ::testing::Test {};
using Scalars = ::testing::Types<float, Q>;
TYPED_TEST_SUITE(ExactAndFloat, Scalars);

TYPED_TEST(ExactAndFloat, ConstructionMatchesDouble) {
  using T = TypeParam;
  for (const auto& s : {mink_test::lBlock(), mink_test::torus(12, 8)}) {
    SCOPED_TRACE(s.name);
    const auto m = mink::TriangleMesh<T>::fromMesh(s.template verticesAs<T>(), s.triangles);
    const auto d = mink::TriangleMesh<double>::fromMesh(s.template verticesAs<double>(), s.triangles);
    EXPECT_EQ(m.numEdges(), d.numEdges());
    EXPECT_EQ(m.numVertices() - m.numEdges() + m.numTriangles(), 2 - 2 * s.genus);
    // Same input numbers (Gmpq: the doubles exactly; float: the L's integers exactly) give
    // the same exact decisions.
    if (std::is_same<T, Q>::value || s.integer) {
      for (int e = 0; e < m.numEdges(); ++e) EXPECT_EQ(m.edgeKind(e), d.edgeKind(e)) << "edge " << e;
    }
    if constexpr (std::is_same<T, Q>::value) {
      for (int t = 0; t < m.numTriangles(); ++t) {
        const auto& f = m.triangle(t);
        EXPECT_EQ(m.triangleNormal(t), mink::Vec3<T>((m.vertex(f[1]) - m.vertex(f[0])).cross(m.vertex(f[2]) - m.vertex(f[0]))));
      }
    }
  }
}

// MeshOverlap<Gmpq> with exactly orthonormal rational rotations: every B point placed
// exactly; the brute force runs on those same points.
TEST(ExactAndFloatOverlap, GmpqAgainstExactBruteForce) {
  const auto ts = mink_test::torus(12, 8), ls = mink_test::lBlock();
  const auto torus = mink::TriangleMesh<Q>::fromMesh(ts.verticesAs<Q>(), ts.triangles);
  const auto L = mink::TriangleMesh<Q>::fromMesh(ls.verticesAs<Q>(), ls.triangles);
  std::mt19937 rng(5201u);
  std::uniform_int_distribution<int> num(-40, 40);
  int hits = 0, misses = 0;
#ifdef MINK_SANITIZE_BUILD
  const int poses = 4;
#else
  const int poses = 20;
#endif
  for (int i = 0; i < poses; ++i) {
    const auto rot = mink_test::randomRationalRotation(rng, 16);
    const mink::Vec3<Q> t(Q(num(rng), 16), Q(num(rng), 16), Q(num(rng), 32));
    mink::MeshOverlap<Q> o(torus, L, rot.exact, t);
    for (int k = 0; k < 3; ++k) {
      const mink::Vec3<Q> y(Q(num(rng), 64), Q(num(rng), 64), Q(num(rng), 64));
      const bool ours = o.overlaps(y);
      std::vector<mink::Vec3<Q>> placed;
      for (int v = 0; v < L.numVertices(); ++v) {
        placed.push_back(o.placedVertexB(v));
        EXPECT_EQ(placed.back(), mink::Vec3<Q>(rot.exact * L.vertex(v) + t + y));  // exact placement
      }
      EXPECT_EQ(ours, bruteForce(torus, placed, L)) << "seed 5201 pose " << i << " y " << k;
      EXPECT_NE(o.result().status, mink::OverlapStatus::Undecided);
      (ours ? hits : misses)++;
    }
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(misses, 0);
  // Exact touching: the L's face x = 2 against a unit box's face x = 2, and 2^-200 apart.
  const auto bs = mink_test::boxShape(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  const auto box = mink::TriangleMesh<Q>::fromMesh(bs.verticesAs<Q>(), bs.triangles);
  mink::MeshOverlap<Q> c(L, box, mink::Mat3<Q>::Identity(), mink::Vec3<Q>(Q(2), Q(0), Q(0)));
  EXPECT_TRUE(c.overlaps());
  Q tiny(1);
  for (int i = 0; i < 200; ++i) tiny /= 2;
  EXPECT_FALSE(c.overlaps(mink::Vec3<Q>(tiny, Q(0), Q(0))));
  EXPECT_TRUE(c.overlaps(mink::Vec3<Q>(-tiny, Q(0), Q(0))));
}

// MeshOverlap<float>: decisions exact on the float placements.
TEST(ExactAndFloatOverlap, FloatAgainstExactBruteForce) {
  const auto ts = mink_test::torus(12, 8), ls = mink_test::lBlock();
  const auto torus = mink::TriangleMesh<float>::fromMesh(ts.verticesAs<float>(), ts.triangles);
  const auto L = mink::TriangleMesh<float>::fromMesh(ls.verticesAs<float>(), ls.triangles);
  std::mt19937 rng(5202u);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  int hits = 0, misses = 0;
  for (int i = 0; i < 40; ++i) {
    const Eigen::Matrix3f R = mink_test::randomRotation(rng).cast<float>();
    mink::MeshOverlap<float> o(torus, L, R, mink::Vec3<float>(u(rng), u(rng), u(rng) / 3));
    for (int k = 0; k < 4; ++k) {
      const bool ours = o.overlaps(mink::Vec3<float>(u(rng), u(rng), u(rng)) * 0.25f);
      std::vector<mink::Vec3<float>> placed;
      for (int v = 0; v < L.numVertices(); ++v) placed.push_back(o.placedVertexB(v));
      EXPECT_EQ(ours, bruteForce(torus, placed, L)) << "seed 5202 pose " << i << " y " << k;
      (ours ? hits : misses)++;
    }
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(misses, 0);
}

}  // namespace
