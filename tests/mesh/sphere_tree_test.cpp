// Tests of mink/mesh/sphere_tree.hpp and mesh/detail/enclosing_sphere.hpp:
//   - the guarantee, checked in exact arithmetic (Gmpq): every corner of every triangle
//     below a node lies within the node's radius of its centre — for trees in double
//     (procedural and shipped meshes) and in Gmpq (L-block, torus);
//   - the tree's shape: 2n - 1 nodes in depth-first order, one leaf per triangle, a
//     median split (height ceil(log2 n) + 1);
//   - tightness: leaf spheres against the exact smallest circle of their triangle, and
//     enclosingSphere against CGAL's exact Min_sphere_d (random, degenerate and
//     Minkowski-sum point sets), conservative exactly as well.
#include "mink/mesh/sphere_tree.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Min_sphere_annulus_d_traits_3.h>
#include <CGAL/Min_sphere_d.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "mink/io/triangle_mesh_io.hpp"
#include "mink/mesh/triangle_mesh.hpp"
#include "support/mesh_shapes.hpp"
#include "support/to_rational.hpp"

namespace {

using Q = CGAL::Gmpq;
using Kq = CGAL::Simple_cartesian<Q>;
using V = mink::Vec3<double>;

using mink_test::toQ;
using mink_test::toQ3;

// Exactly: |p - c|^2 <= r^2.
template <class T>
bool within(const mink::Vec3<T>& p, const mink::Vec3<T>& c, const T& r) {
  const mink::Vec3<Q> d = toQ3(p) - toQ3(c);
  return d.squaredNorm() <= toQ(r) * toQ(r);
}

// Every node's sphere holds every corner below it (exact), and the tree's shape.
template <class T>
void expectTreeEnclosesItsTriangles(const mink::TriangleMesh<T>& m, const std::string& name) {
  SCOPED_TRACE(name);
  const mink::SphereTree<T>& tree = m.sphereTree();
  const int n = m.numTriangles();
  ASSERT_EQ(tree.numNodes(), 2 * n - 1);
  EXPECT_EQ(tree.height(), static_cast<int>(std::ceil(std::log2(n))) + 1);
  std::vector<int> leafCount(n, 0);
  int failures = 0;
  // Depth-first: node i's subtree is [i, end(i)); left = i + 1.
  std::vector<int> end(tree.numNodes());
  for (int i = tree.numNodes(); i-- > 0;) end[i] = tree.isLeaf(i) ? i + 1 : end[tree.right(i)];
  for (int i = 0; i < tree.numNodes(); ++i) {
    if (tree.isLeaf(i)) {
      ++leafCount[tree.triangle(i)];
      EXPECT_EQ(tree.leafOf(tree.triangle(i)), i);
    } else {
      EXPECT_EQ(tree.left(i), i + 1);
      EXPECT_EQ(end[i + 1], tree.right(i));
    }
    for (int j = i; j < end[i]; ++j) {
      if (!tree.isLeaf(j)) continue;
      for (int v : m.triangle(tree.triangle(j)))
        if (!within(m.vertex(v), tree.centre(i), tree.radius(i)) && failures++ < 5)
          ADD_FAILURE() << "vertex " << v << " of triangle " << tree.triangle(j) << " outside node " << i;
    }
  }
  EXPECT_EQ(failures, 0);
  for (int t = 0; t < n; ++t) EXPECT_EQ(leafCount[t], 1) << "triangle " << t;
}

// The exact smallest enclosing circle's squared radius of a triangle: the circumradius
// |a-b|^2 |b-c|^2 |c-a|^2 / (4 |n|^2) when no angle is obtuse, else (longest side / 2)^2.
Q triangleMinRadius2(const mink::Vec3<Q>& a, const mink::Vec3<Q>& b, const mink::Vec3<Q>& c) {
  const Q ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  const Q longest = std::max({ab, bc, ca});
  if (2 * longest >= ab + bc + ca) return longest / 4;  // right or obtuse
  return ab * bc * ca / (4 * (b - a).cross(c - a).squaredNorm());
}

TEST(SphereTree, DoubleTreesEncloseTheirTriangles) {
  for (const auto& s : mink_test::allMeshShapes())
    expectTreeEnclosesItsTriangles(mink::TriangleMesh<double>::fromMesh(s.verticesAs<double>(), s.triangles), s.name);
  for (const char* f : {"torus.obj", "bunny.obj", "concave_box.obj", "shape_sorter.obj"})
    expectTreeEnclosesItsTriangles(mink::io::readTriangleMesh<double>(std::string(MINK_TEST_DATA_DIR) + "/" + f), f);
}

TEST(SphereTree, ExactTreesEncloseTheirTriangles) {
  for (const auto& s : {mink_test::lBlock(), mink_test::torus(12, 8)}) {
    const auto m = mink::TriangleMesh<Q>::fromMesh(s.verticesAs<Q>(), s.triangles);
    expectTreeEnclosesItsTriangles(m, s.name + " (Gmpq)");
    // Exact radii are dyadic upper bounds within 2^-30 of the exact smallest circle.
    for (int t = 0; t < m.numTriangles(); ++t) {
      const auto& f = m.triangle(t);
      const Q r = m.sphereTree().radius(m.sphereTree().leafOf(t));
      const Q r2min = triangleMinRadius2(m.vertex(f[0]), m.vertex(f[1]), m.vertex(f[2]));
      EXPECT_GE(r * r, r2min);
      EXPECT_LE(CGAL::to_double(r * r / r2min), 1.0 + 1e-9) << "triangle " << t;
    }
  }
}

TEST(SphereTree, LeavesAreTheSmallestSphereOfTheirTriangle) {
  for (const auto& s : mink_test::allMeshShapes()) {
    SCOPED_TRACE(s.name);
    const auto m = mink::TriangleMesh<double>::fromMesh(s.verticesAs<double>(), s.triangles);
    for (int t = 0; t < m.numTriangles(); ++t) {
      const auto& f = m.triangle(t);
      const Q r2min = triangleMinRadius2(toQ3(m.vertex(f[0])), toQ3(m.vertex(f[1])), toQ3(m.vertex(f[2])));
      const double r = m.sphereTree().radius(m.sphereTree().leafOf(t));
      EXPECT_LE(r * r, CGAL::to_double(r2min) * (1 + 1e-13)) << "triangle " << t;
    }
  }
}

// CGAL's exact smallest enclosing sphere of the points: squared radius, exact.
Q cgalMinSphere2(const std::vector<V>& pts) {
  using Traits = CGAL::Min_sphere_annulus_d_traits_3<Kq>;
  std::vector<Kq::Point_3> q;
  for (const V& p : pts) q.emplace_back(p.x(), p.y(), p.z());
  CGAL::Min_sphere_d<Traits> ms(q.begin(), q.end());
  return ms.squared_radius();
}

void expectTightAndConservative(const std::vector<V>& pts, const std::string& what, int& failures) {
  const mink::Sphere<double> s = mink::detail::enclosingSphere(pts.data(), static_cast<int>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!within(pts[i], s.centre, s.radius) && failures++ < 5) ADD_FAILURE() << what << ": point " << i << " outside";
  const double exact = std::sqrt(CGAL::to_double(cgalMinSphere2(pts)));
  if (!(s.radius <= exact * (1 + 1e-12) + 1e-300) && failures++ < 5)
    ADD_FAILURE() << what << ": radius " << s.radius << ", smallest " << exact;
}

TEST(EnclosingSphere, RandomAndDegeneratePointSetsAgainstCgal) {
  std::mt19937 rng(7301u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> count(1, 12), grid(-2, 2);
  int failures = 0;
  for (int i = 0; i < 400; ++i) {
    const int n = count(rng);
    std::vector<V> general, coplanar, collinear, integer;
    for (int k = 0; k < n; ++k) {
      general.emplace_back(u(rng), u(rng), u(rng));
      coplanar.emplace_back(u(rng), u(rng), 0.25);
      const double t = u(rng);
      collinear.emplace_back(1 + 2 * t, -t, 3 * t);
      integer.emplace_back(grid(rng), grid(rng), grid(rng));  // duplicates, cospherical sets
    }
    const std::string id = "seed 7301 #" + std::to_string(i) + " n=" + std::to_string(n);
    expectTightAndConservative(general, id + " general", failures);
    expectTightAndConservative(coplanar, id + " coplanar", failures);
    expectTightAndConservative(collinear, id + " collinear", failures);
    expectTightAndConservative(integer, id + " integer", failures);
  }
  EXPECT_EQ(failures, 0);
}

// The CPD use: the 9 points a_i + b_j of two triangles' Minkowski sum. For two long
// slivers at right angles, the tight sphere is far smaller than the two spheres' sum.
TEST(EnclosingSphere, MinkowskiSumOfTwoTriangles) {
  std::mt19937 rng(7302u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int failures = 0;
  for (int i = 0; i < 300; ++i) {
    V a[3], b[3];
    for (auto& p : a) p = V(u(rng), u(rng), u(rng));
    for (auto& p : b) p = V(u(rng), u(rng), u(rng)) * 0.1 + V(3, 0, 0);
    std::vector<V> sum;
    for (const V& p : a)
      for (const V& q : b) sum.push_back(p + q);
    expectTightAndConservative(sum, "seed 7302 #" + std::to_string(i), failures);
  }
  EXPECT_EQ(failures, 0);
  const V a[3] = {V(-5, 0, 0), V(5, 0, 0), V(0, 0.1, 0)}, b[3] = {V(0, -5, 0), V(0, 5, 0), V(0.1, 0, 0.05)};
  std::vector<V> sum;
  for (const V& p : a)
    for (const V& q : b) sum.push_back(p + q);
  const auto ta = mink::detail::triangleSphere(a[0], a[1], a[2]);
  const auto tb = mink::detail::triangleSphere(b[0], b[1], b[2]);
  const auto s = mink::detail::enclosingSphere(sum.data(), 9);
  EXPECT_NEAR(ta.radius, 5.0, 1e-12);
  EXPECT_NEAR(tb.radius, 5.0, 1e-12);
  EXPECT_LT(s.radius, 0.75 * (ta.radius + tb.radius));  // sqrt(50) + a little, against 10
  expectTightAndConservative(sum, "perpendicular slivers", failures);
  EXPECT_EQ(failures, 0);
}

TEST(EnclosingSphere, ExactScalarIsConservativeExactly) {
  std::mt19937 rng(7303u);
  std::uniform_int_distribution<int> num(-1000, 1000), den(1, 97);
  for (int i = 0; i < 200; ++i) {
    std::vector<mink::Vec3<Q>> pts;
    for (int k = 0; k < 9; ++k) pts.emplace_back(Q(num(rng), den(rng)), Q(num(rng), den(rng)), Q(num(rng), den(rng)));
    const auto s = mink::detail::enclosingSphere(pts.data(), 9);
    std::vector<V> d;
    for (const auto& p : pts) {
      EXPECT_TRUE(within(p, s.centre, s.radius)) << "seed 7303 #" << i;
      d.emplace_back(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]));
    }
    EXPECT_LE(CGAL::to_double(s.radius), std::sqrt(CGAL::to_double(cgalMinSphere2(d))) * (1 + 1e-9)) << i;
  }
}

// Floating-point radii at the edges of the range: points 1e-300 apart (squares
// underflow) and 1e80 apart (they would overflow double's squares without scaling).
TEST(EnclosingSphere, ConservativeAtExtremeScales) {
  for (double scale : {1e-300, 1e-160, 1.0, 1e80}) {
    std::mt19937 rng(7304u);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<V> pts;
    for (int k = 0; k < 9; ++k) pts.push_back(V(u(rng), u(rng), u(rng)) * scale + V(1, 1, 1) * (scale < 1 ? 1.0 : 0.0));
    const auto s = mink::detail::enclosingSphere(pts.data(), 9);
    for (const V& p : pts) EXPECT_TRUE(within(p, s.centre, s.radius)) << "scale " << scale;
    const auto f = mink::detail::conservativeRadius(pts[0], pts.data(), 9);
    for (const V& p : pts) EXPECT_TRUE(within(p, pts[0], f)) << "scale " << scale;
  }
}

}  // namespace
