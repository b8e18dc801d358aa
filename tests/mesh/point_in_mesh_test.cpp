// Tests of mink/mesh/point_in_mesh.hpp:
//   - shapes that are unions of axis-aligned boxes (box, L-block, U-block, cube with a
//     hole, axes), on a quarter-integer grid where a third of the points lie exactly on
//     faces, edges and corners: against the analytic answer (inside the closed union, and
//     in its interior iff all 8 diagonal neighbours at 1/8 are in it too), in double,
//     float and Gmpq;
//   - the torus, cone, cup, spoon and the shipped meshes: against CGAL's
//     Side_of_triangle_mesh (exact predicates, Epick) on random points, mesh vertices
//     (on the boundary) and edge midpoints.
#include "mink/mesh/point_in_mesh.hpp"
#include "mink/mesh/self_intersection.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <array>
#include <random>
#include <string>
#include <vector>

#include "mink/io/triangle_mesh_io.hpp"
#include "support/cgal_mesh.hpp"
#include "support/mesh_shapes.hpp"

namespace {

using mink::PointLocation;
using V = Eigen::Vector3d;
using Box = std::array<V, 2>;

const char* name(PointLocation p) {
  switch (p) {
    case PointLocation::Outside: return "Outside";
    case PointLocation::Inside: return "Inside";
    case PointLocation::OnBoundary: return "OnBoundary";
    case PointLocation::Undecided: return "Undecided";
  }
  return "?";
}

bool inUnion(const std::vector<Box>& boxes, const V& p) {
  for (const Box& b : boxes)
    if ((p.array() >= b[0].array()).all() && (p.array() <= b[1].array()).all()) return true;
  return false;
}

PointLocation analytic(const std::vector<Box>& boxes, const V& p) {
  if (!inUnion(boxes, p)) return PointLocation::Outside;
  for (int k = 0; k < 8; ++k)
    if (!inUnion(boxes, p + 0.125 * V(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1))) return PointLocation::OnBoundary;
  return PointLocation::Inside;
}

struct BoxUnion {
  mink_test::MeshShape shape;
  std::vector<Box> boxes;
};

std::vector<BoxUnion> boxUnions() {
  return {
      {mink_test::boxShape(), {Box{V(-1, -1, -1), V(1, 1, 1)}}},
      {mink_test::lBlock(), {Box{V(0, 0, 0), V(2, 1, 1)}, Box{V(0, 0, 0), V(1, 2, 1)}}},
      {mink_test::uBlock(), {Box{V(0, 0, 0), V(3, 1, 1)}, Box{V(0, 0, 0), V(1, 2, 1)}, Box{V(2, 0, 0), V(3, 2, 1)}}},
      {mink_test::cubeWithHole(),
       {Box{V(0, 0, 0), V(1, 3, 3)}, Box{V(2, 0, 0), V(3, 3, 3)}, Box{V(0, 0, 0), V(3, 1, 3)}, Box{V(0, 2, 0), V(3, 3, 3)}}},
      {mink_test::axes(3),
       {Box{V(-3, -1, -1), V(3, 1, 1)}, Box{V(-1, -3, -1), V(1, 3, 1)}, Box{V(-1, -1, -3), V(1, 1, 3)}}},
  };
}

template <class T>
void checkBoxUnions(int n, unsigned seed) {
  std::mt19937 rng(seed);
  for (const BoxUnion& u : boxUnions()) {
    SCOPED_TRACE(u.shape.name);
    const auto mesh = mink::TriangleMesh<T>::fromMesh(u.shape.verticesAs<T>(), u.shape.triangles);
    // Quarter-grid points in the shape's box grown by 1/2.
    V lo = u.boxes[0][0], hi = u.boxes[0][1];
    for (const Box& b : u.boxes) lo = lo.cwiseMin(b[0]), hi = hi.cwiseMax(b[1]);
    std::uniform_int_distribution<int> qx(4 * lo.x() - 2, 4 * hi.x() + 2), qy(4 * lo.y() - 2, 4 * hi.y() + 2),
        qz(4 * lo.z() - 2, 4 * hi.z() + 2);
    int counts[4] = {0, 0, 0, 0}, failures = 0;
    for (int i = 0; i < n; ++i) {
      const V p(qx(rng) / 4.0, qy(rng) / 4.0, qz(rng) / 4.0);
      const PointLocation want = analytic(u.boxes, p);
      const PointLocation got = mink::locatePoint(mesh, mink::Vec3<T>(T(p.x()), T(p.y()), T(p.z())));
      ++counts[static_cast<int>(want)];
      if (got != want && failures++ < 5)
        ADD_FAILURE() << "seed " << seed << " #" << i << " p = " << p.transpose() << ": " << name(got) << ", want "
                      << name(want);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(counts[0], 0);
    EXPECT_GT(counts[1], 0);
    EXPECT_GT(counts[2], 0);
  }
}

TEST(PointInMesh, BoxUnionsOnAQuarterGridDouble) { checkBoxUnions<double>(4000, 8101u); }
TEST(PointInMesh, BoxUnionsOnAQuarterGridFloat) { checkBoxUnions<float>(1000, 8102u); }
TEST(PointInMesh, BoxUnionsOnAQuarterGridGmpq) { checkBoxUnions<CGAL::Gmpq>(150, 8103u); }

void checkAgainstCgal(const mink::TriangleMesh<double>& m, const std::string& what, int randomPoints, unsigned seed) {
  SCOPED_TRACE(what);
  const mink_test::CgalPointLocation reference(m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const V lo = m.boxMin(), hi = m.boxMax(), pad = 0.05 * (hi - lo);
  int counts[4] = {0, 0, 0, 0}, failures = 0;
  auto one = [&](const V& p, const std::string& id) {
    const PointLocation want = reference(p), got = mink::locatePoint(m, p);
    ++counts[static_cast<int>(want)];
    if (got != want && failures++ < 5)
      ADD_FAILURE() << id << " p = " << p.transpose() << ": " << name(got) << ", CGAL " << name(want);
  };
  for (int i = 0; i < randomPoints; ++i) {
    const V p = lo - pad + (hi - lo + 2 * pad).cwiseProduct(V(u(rng), u(rng), u(rng)));
    one(p, "seed " + std::to_string(seed) + " #" + std::to_string(i));
  }
  for (int v = 0; v < m.numVertices(); v += 3) one(m.vertex(v), "vertex " + std::to_string(v));
  for (int e = 0; e < m.numEdges(); e += 5) {
    const auto [a, b] = m.edgeVertices(e);
    one(0.5 * (m.vertex(a) + m.vertex(b)), "midpoint of edge " + std::to_string(e));
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

TEST(PointInMesh, CurvedShapesAgainstCgal) {
  for (const auto& s : {mink_test::torus(12, 8), mink_test::cone(16), mink_test::cup(16), mink_test::spoon(),
                        mink_test::starPrism()})
    checkAgainstCgal(mink::TriangleMesh<double>::fromMesh(s.verticesAs<double>(), s.triangles), s.name, 3000, 8104u);
}

TEST(PointInMesh, ShippedMeshesAgainstCgal) {
#ifdef MINK_SANITIZE_BUILD
  const int n = 300;
#else
  const int n = 3000;
#endif
  for (const char* f : {"torus.obj", "bunny.obj", "duck.obj", "concave_box.obj", "shape_sorter.obj"})
    checkAgainstCgal(mink::io::readTriangleMesh<double>(std::string(MINK_TEST_DATA_DIR) + "/" + f), f, n, 8105u);
}

// A point outside the box never casts a ray; a point on the surface is OnBoundary.
TEST(PointInMesh, BoxAndBoundaryShortcuts) {
  const auto s = mink_test::lBlock();
  const auto m = mink::TriangleMesh<double>::fromMesh(s.verticesAs<double>(), s.triangles);
  std::vector<int> stack;
  int rays = 0;
  EXPECT_EQ(mink::detail::locatePoint(mink::detail::MeshInOwnFrame<double>{m}, V(3, 0.5, 0.5), stack, &rays),
            PointLocation::Outside);
  EXPECT_EQ(rays, 0);
  EXPECT_EQ(mink::detail::locatePoint(mink::detail::MeshInOwnFrame<double>{m}, V(0.5, 0.5, 0.5), stack, &rays),
            PointLocation::Inside);
  EXPECT_GE(rays, 1);
  EXPECT_EQ(mink::locatePoint(m, V(1.5, 1.0, 0.25)), PointLocation::OnBoundary);
  EXPECT_EQ(mink::locatePoint(m, V(1.0, 1.0, 1.0)), PointLocation::OnBoundary);
  EXPECT_EQ(mink::locatePoint(m, V(1.5, std::nextafter(1.0, 2.0), 0.25)), PointLocation::Outside);
  EXPECT_EQ(mink::locatePoint(m, V(1.5, std::nextafter(1.0, 0.0), 0.25)), PointLocation::Inside);
}

// A view of a mesh with a box larger than the mesh's own (a box is only a bound), so
// that the test knows where the first ray goes: from p towards
// q = (hi + |hi| + span, p.y + f1 span, p.z + f2 span) with the first slant (f1, f2).
struct WideBoxView {
  const mink::TriangleMesh<double>& mesh;
  mink::Vec3<double> corner(int t, int i) const { return mesh.vertex(mesh.triangle(t)[i]); }
  const mink::SphereTree<double>& tree() const { return mesh.sphereTree(); }
  mink::Vec3<double> nodeCentre(int node) const { return mesh.sphereTree().centre(node); }
  double nodeRadius(int node) const { return mesh.sphereTree().radius(node); }
  V boxLo() const { return V(-8, -8, -8); }
  V boxHi() const { return V(8, 8, 8); }
};

// The first ray from the origin is made to pass exactly through a corner (then through an
// edge) of a convex solid around the origin: it must be cast again (counting the corner
// as a crossing of each triangle around it would give an even count: Outside).
TEST(PointInMesh, RayThroughACornerOrAnEdgeIsCastAgain) {
  double f1, f2;
  mink::detail::raySlant(0, f1, f2);
  const V q(8 + 8 + 16, f1 * 16, f2 * 16);  // the first ray's far end from p = 0
  const V m = q / 4;                        // exactly on the segment from 0 to q
  ASSERT_NE(m.z(), 0.0);
  for (int variant = 0; variant < 2; ++variant) {
    // Variant 0: a corner at m. Variant 1: an edge from (m.x, m.y, 0) to (m.x, m.y, 2 m.z),
    // both exact, whose midpoint is m; the front is fanned from its two ends.
    const V a = variant == 0 ? m : V(m.x(), m.y(), 2 * m.z()), b = variant == 0 ? m : V(m.x(), m.y(), 0.0);
    const V& low = a.z() < b.z() ? a : b;
    const V& high = a.z() < b.z() ? b : a;
    mink_test::mesh_shapes_detail::Builder build("wedge");
    const V ring[4] = {V(0, 2, 0), V(0, 0, 2), V(0, -2, 0), V(0, 0, -2)}, back(-2, 0, 0);
    for (int i = 0; i < 4; ++i) {
      const V& r = ring[i];
      const V& s = ring[(i + 1) % 4];
      build.triangle(back, r, s, (back + r + s) / 3);
      const V& tip = i < 2 ? high : low;  // the upper half of the ring to the upper end
      build.triangle(tip, r, s, (tip + r + s) / 3);
    }
    if (variant == 1) {  // close the two fans along the edge
      build.triangle(high, ring[2], low, (high + low + ring[2]) / 3);
      build.triangle(high, low, ring[0], (high + low + ring[0]) / 3);
    }
    const auto shape = build.finish(0);
    const auto mesh = mink::TriangleMesh<double>::fromMesh(shape.verticesAs<double>(), shape.triangles);
    EXPECT_FALSE(mink::findSelfIntersection(mesh).found) << variant;
    std::vector<int> stack;
    int rays = 0;
    EXPECT_EQ(mink::detail::locatePoint(WideBoxView{mesh}, V(0, 0, 0), stack, &rays), PointLocation::Inside) << variant;
    EXPECT_EQ(rays, 2) << variant;  // the first ray was spoiled
    EXPECT_EQ(mink::detail::locatePoint(WideBoxView{mesh}, V(-3, 0, 0), stack, &rays), PointLocation::Outside)
        << variant;
  }
}

}  // namespace
