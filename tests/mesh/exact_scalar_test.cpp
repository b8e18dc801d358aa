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
#include <utility>
#include <vector>

#include "mink/mesh/mesh_overlap.hpp"
#include "support/exact_placement.hpp"
#include "support/mesh_shapes.hpp"
#include "support/to_rational.hpp"

namespace {

using Q = CGAL::Gmpq;
using K = CGAL::Simple_cartesian<Q>;

using mink_test::toQ;

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

// Torus (A) against L-block (B) in scalar T: `poses` placements from nextPose(i) ->
// (R, t), `ys` translations each from nextY(); every answer against the exact brute
// force on the points the query used; check(v, y) may check those points further.
template <class T, class NextPose, class NextY, class Check>
void compareWithBruteForce(int poses, int ys, NextPose&& nextPose, NextY&& nextY, Check&& check,
                           const std::string& id) {
  const auto ts = mink_test::torus(12, 8), ls = mink_test::lBlock();
  const auto torus = mink::TriangleMesh<T>::fromMesh(ts.template verticesAs<T>(), ts.triangles);
  const auto L = mink::TriangleMesh<T>::fromMesh(ls.template verticesAs<T>(), ls.triangles);
  int hits = 0, misses = 0;
  for (int i = 0; i < poses; ++i) {
    const std::pair<mink::Mat3<T>, mink::Vec3<T>> pose = nextPose(i);
    mink::MeshOverlap<T> o(torus, L, pose.first, pose.second);
    for (int k = 0; k < ys; ++k) {
      const mink::Vec3<T> y = nextY();
      const bool ours = o.overlaps(y);
      std::vector<mink::Vec3<T>> placed;
      for (int v = 0; v < L.numVertices(); ++v) {
        placed.push_back(o.placedVertexB(v));
        check(i, v, L.vertex(v), y, placed.back());
      }
      EXPECT_EQ(ours, bruteForce(torus, placed, L)) << id << " pose " << i << " y " << k;
      EXPECT_NE(o.result().status, mink::OverlapStatus::Undecided);
      (ours ? hits : misses)++;
    }
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(misses, 0);
}

// MeshOverlap<Gmpq> with exactly orthonormal rational rotations: every B point placed
// exactly; the brute force runs on those same points.
TEST(ExactAndFloatOverlap, GmpqAgainstExactBruteForce) {
  std::mt19937 rng(5201u);
  std::uniform_int_distribution<int> num(-40, 40);
#ifdef MINK_SANITIZE_BUILD
  const int poses = 4;
#else
  const int poses = 20;
#endif
  std::vector<std::pair<mink::Mat3<Q>, mink::Vec3<Q>>> placements;
  compareWithBruteForce<Q>(
      poses, 3,
      [&](int) {
        placements.push_back({mink_test::randomRationalRotation(rng, 16).exact,
                              mink::Vec3<Q>(Q(num(rng), 16), Q(num(rng), 16), Q(num(rng), 32))});
        return placements.back();
      },
      [&] { return mink::Vec3<Q>(Q(num(rng), 64), Q(num(rng), 64), Q(num(rng), 64)); },
      [&](int i, int v, const mink::Vec3<Q>& x, const mink::Vec3<Q>& y, const mink::Vec3<Q>& placed) {
        EXPECT_EQ(placed, mink::Vec3<Q>(placements[i].first * x + placements[i].second + y)) << "vertex " << v;
      },
      "seed 5201");
  // Exact touching: the L's face x = 2 against a unit box's face x = 2, and 2^-200 apart.
  const auto ls = mink_test::lBlock();
  const auto L = mink::TriangleMesh<Q>::fromMesh(ls.verticesAs<Q>(), ls.triangles);
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
  std::mt19937 rng(5202u);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  compareWithBruteForce<float>(
      40, 4,
      [&](int) {
        const Eigen::Matrix3f R = mink_test::randomRotation(rng).cast<float>();
        return std::make_pair(R, mink::Vec3<float>(u(rng), u(rng), u(rng) / 3));
      },
      [&] { return mink::Vec3<float>(mink::Vec3<float>(u(rng), u(rng), u(rng)) * 0.25f); },
      [](int, int, const mink::Vec3<float>&, const mink::Vec3<float>&, const mink::Vec3<float>&) {}, "seed 5202");
}

}  // namespace
