// tests/cpd/convex_map_test.cpp — mink/cpd/convex_map.hpp against brute force: the cell a
// direction is located in holds it (every side of its cone faces it); the correspondence
// sets are complete — every vertex v of the mesh with a direction d in its local-maximum
// cone (d · (w − v) <= 0 for all neighbours w, decided exactly in CGAL::Gmpq) is listed in
// the cell of d, and every convex edge whose short Gauss arc crosses a query arc (exact arc
// test in Gmpq) is listed in a cell the arc meets. Random directions and arcs (fixed seed),
// including the face normals themselves (cell corners: the boundary cases). Two shapes
// far from unit scale (2^-1000, 2^280). prepare(TriangleMesh): the map is built once,
// shared by copies, and the local Minkowski sum of prepared meshes is that of unprepared
// twins.
#include "mink/cpd/convex_map.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "mink/cpd/local_minkowski_sum.hpp"
#include "mink/gauss_map/arc_intersection.hpp"
#include "support/mesh_shapes.hpp"

namespace {

using V = Eigen::Vector3d;
using Q = CGAL::Gmpq;
using Vq = mink::Vec3<Q>;
using Mesh = mink::TriangleMesh<double>;

Vq exact(const V& v) { return Vq(Q(v.x()), Q(v.y()), Q(v.z())); }

/// Triangle t's normal in Gmpq (triangleNormal() underflows for a mesh at 2^-1000).
Vq exactNormal(const Mesh& X, int t) {
  const auto& tri = X.triangle(t);
  const Vq a = exact(X.vertex(tri[0]));
  return (exact(X.vertex(tri[1])) - a).cross(exact(X.vertex(tri[2])) - a);
}

bool inLocalMaximumCone(const Mesh& X, int v, const V& d) {
  const Vq dq = exact(d), pv = exact(X.vertex(v));
  for (int w : X.vertexNeighbors(v))
    if (dq.dot(exact(X.vertex(w)) - pv) > 0) return false;
  return true;
}

mink_test::MeshShape scaled(mink_test::MeshShape s, int k) {
  for (auto& v : s.vertices) v *= std::ldexp(1.0, k);
  s.name += " at 2^" + std::to_string(k);
  return s;
}

/// Shapes at unit scale, and two far from it (the squares of their normals and edge
/// vectors over- or underflow double: the map must not lose them).
std::vector<mink_test::MeshShape> shapes() {
  return {mink_test::lBlock(), mink_test::uBlock(), mink_test::torus(16, 12), mink_test::cubeWithHole(),
          mink_test::starPrism(), mink_test::cup(), mink_test::spoon(), mink_test::axes(),
          scaled(mink_test::lBlock(), -1000), scaled(mink_test::torus(16, 12), 280)};
}

TEST(ConvexMap, LocatedCellHoldsTheDirection) {
  std::mt19937 rng(77);
  std::normal_distribution<double> N;
  for (const auto& s : shapes()) {
    SCOPED_TRACE(s.name);
    const Mesh X = Mesh::fromMesh(s.verticesAs<double>(), s.triangles);
    const mink::ConvexMap<double> map(X);
    const auto& H = map.hull();
    int hint = -1;
    for (int k = 0; k < 500; ++k) {
      const V d = V(N(rng), N(rng), N(rng)).normalized();
      hint = map.locate(d, k % 2 ? hint : -1);
      for (int i = 0; i < H.faceSize(hint); ++i) {
        const int h = H.faceStart(hint) + i;
        EXPECT_GE(H.vertex(H.heOrigin(h)).cross(H.vertex(H.heTarget(h))).dot(d), -1e-12);
      }
    }
  }
}

/// The mesh fuzzer's torus (6 sections of 4 corners, ring radius 3, tube radius 1, lifted
/// by 1 along z): its planar quads' two triangles have unit normals equal to rounding, and
/// those that the map's merging of near-equal points does not join become cells whose
/// corners are 4e-16 apart.
mink_test::MeshShape fuzzTorus() {
  mink_test::MeshShape t;
  t.name = "fuzz torus 6x4";
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 4; ++j) {
      const double u = 2 * pi * i / 6, v = 2 * pi * j / 4;
      t.vertices.push_back(V((3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v) + 1));
    }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 4; ++j) {
      const int a = i * 4 + j, b = ((i + 1) % 6) * 4 + j, c = ((i + 1) % 6) * 4 + (j + 1) % 4, d = i * 4 + (j + 1) % 4;
      t.triangles.push_back({a, b, c});
      t.triangles.push_back({a, c, d});
    }
  return t;
}

TEST(ConvexMap, EveryHintLocatesACellThatHoldsTheDirection) {
  // fuzz/regressions_mesh/convex_maps_locate_stuck_in_tiny_cell_torus_68_53: a cell whose
  // corners are equal to rounding passed every side test for a direction 0.012 rad away
  // (its sides' cross products are rounding), so a walk hinted there stayed there and
  // ConvexMaps missed an EE facet. From every cell as hint, the located cell must hold d:
  // each side's exact plane (Gmpq, on the corners as stored) at most 1e-8 from d.
  std::mt19937 rng(80);
  std::normal_distribution<double> N;
  for (const auto& s : {fuzzTorus(), mink_test::lBlock()}) {
    SCOPED_TRACE(s.name);
    const Mesh X = Mesh::fromMesh(s.verticesAs<double>(), s.triangles);
    const mink::ConvexMap<double> map(X);
    const auto& H = map.hull();
    std::vector<V> dirs;
    for (int t = 0; t < X.numTriangles(); ++t) dirs.push_back(mink::ConvexMap<double>::faceUnit(X, t));
    for (int k = 0; k < 60; ++k) dirs.push_back(V(N(rng), N(rng), N(rng)).normalized());
    int tiny = 0;
    for (int f = 0; f < H.numFaces(); ++f) {
      double reach = 0;
      for (int i = 1; i < H.faceSize(f); ++i)
        reach = std::max(reach, (H.vertex(H.heOrigin(H.faceStart(f) + i)) - H.vertex(H.heOrigin(H.faceStart(f)))).norm());
      if (!(reach < 1e-12)) continue;
      ++tiny;
      // Directions around it, 1e-6 to 0.1 away: where its rounded sides mislead.
      const V a = H.vertex(H.heOrigin(H.faceStart(f)));
      for (double r = 1e-6; r < 0.2; r *= 10)
        for (int k = 0; k < 8; ++k) dirs.push_back((a + r * V(N(rng), N(rng), N(rng)).normalized()).normalized());
    }
    if (s.name == "fuzz torus 6x4") {
      EXPECT_GT(tiny, 0) << "the torus no longer makes tiny cells: the test lost its case";
    }
    int wrong = 0;
    for (int hint = 0; hint < H.numFaces(); ++hint)
      for (const V& d : dirs) {
        const int f = map.locate(d, hint);
        for (int i = 0; i < H.faceSize(f); ++i) {
          const int h = H.faceStart(f) + i;
          const Vq c = exact(H.vertex(H.heOrigin(h))).cross(exact(H.vertex(H.heTarget(h))));
          const double side = CGAL::to_double(c.dot(exact(d)));
          const double len = std::sqrt(CGAL::to_double(c.dot(c)));
          if (side < -1e-8 * len) ++wrong;
        }
      }
    EXPECT_EQ(wrong, 0);
  }
}

TEST(ConvexMap, VertexSetsAreComplete) {
  std::mt19937 rng(78);
  std::normal_distribution<double> N;
  for (const auto& s : shapes()) {
    SCOPED_TRACE(s.name);
    const Mesh X = Mesh::fromMesh(s.verticesAs<double>(), s.triangles);
    const mink::ConvexMap<double> map(X);
    std::vector<V> dirs;
    for (int t = 0; t < X.numTriangles(); ++t) dirs.push_back(mink::ConvexMap<double>::faceUnit(X, t));
    for (int k = 0; k < 300; ++k) dirs.push_back(V(N(rng), N(rng), N(rng)).normalized());
    int checked = 0;
    for (const V& d : dirs) {
      const int cell = map.locate(d);
      std::set<int> listed(map.vertices(cell).begin(), map.vertices(cell).end());
      for (int v = 0; v < X.numVertices(); ++v) {
        if (!inLocalMaximumCone(X, v, d)) continue;
        ++checked;
        EXPECT_TRUE(listed.count(v)) << "vertex " << v << " missing";
      }
    }
    EXPECT_GT(checked, 0);
  }
}

TEST(ConvexMap, EdgeSetsAreComplete) {
  std::mt19937 rng(79);
  std::normal_distribution<double> N;
  for (const auto& s : shapes()) {
    SCOPED_TRACE(s.name);
    const Mesh X = Mesh::fromMesh(s.verticesAs<double>(), s.triangles);
    const mink::ConvexMap<double> map(X);
    mink::ConvexMap<double>::Walk walk;
    int crossings = 0;
    for (int k = 0; k < 200; ++k) {
      const V p = V(N(rng), N(rng), N(rng)).normalized();
      V q = (p + 0.6 * V(N(rng), N(rng), N(rng)).normalized()).normalized();
      if (p.dot(q) < -0.9) continue;
      std::set<int> listed;
      int hint = -1;
      map.forCellsOnArc(p, q, hint, walk, [&](int cell) {
        for (int e : map.edges(cell)) listed.insert(e);
      });
      for (int e = 0; e < X.numEdges(); ++e) {
        if (X.edgeKind(e) != mink::EdgeKind::Convex) continue;
        const auto tt = X.edgeTriangles(e);
        const auto c = mink::classifyArcs(exact(p), exact(q), exactNormal(X, tt.first), exactNormal(X, tt.second));
        if (c == mink::ArcIntersection::None) continue;
        ++crossings;
        EXPECT_TRUE(listed.count(e)) << "edge " << e << " missing";
      }
    }
    EXPECT_GT(crossings, 0);
  }
}

TEST(ConvexMap, PrepareBuildsTheMapOnceForEveryCopy) {
  const auto s = mink_test::torus(16, 12);
  const Mesh X = Mesh::fromMesh(s.verticesAs<double>(), s.triangles);
  const Mesh copyBefore = X;
  EXPECT_FALSE(mink::isPrepared(X));
  const auto map = mink::prepare(X);
  ASSERT_NE(map, nullptr);
  EXPECT_TRUE(mink::isPrepared(X));
  EXPECT_TRUE(mink::isPrepared(copyBefore));
  const Mesh copyAfter = X;
  EXPECT_EQ(mink::prepare(copyAfter), map);
  EXPECT_EQ(mink::ConvexMap<double>::of(copyBefore), map);
  // A mesh of the same numbers is another mesh.
  EXPECT_FALSE(mink::isPrepared(Mesh::fromMesh(s.verticesAs<double>(), s.triangles)));
  // The prepared map is a convex map of X: same cells as one built directly.
  EXPECT_EQ(map->numCells(), mink::ConvexMap<double>(X).numCells());
}

TEST(ConvexMap, PreparedMeshesGiveTheSameLocalSum) {
  const auto a = mink_test::cup(), b = mink_test::torus(16, 12);
  const Mesh A = Mesh::fromMesh(a.verticesAs<double>(), a.triangles);
  const Mesh B = Mesh::fromMesh(b.verticesAs<double>(), b.triangles);
  const Mesh Au = Mesh::fromMesh(a.verticesAs<double>(), a.triangles);
  const Mesh Bu = Mesh::fromMesh(b.verticesAs<double>(), b.triangles);
  mink::prepare(A);
  mink::prepare(B);
  mink::Pose<double> poseA, poseB;
  poseB.translation = V(0.4, -0.2, 0.3);
  const V centre(0.2, 0.1, -0.1);
  // The default method (BoxTrees) needs no convex map and builds none.
  mink::LocalMinkowskiSum<double> boxes(Au, Bu);
  const auto pb = boxes.update(poseA, poseB, centre, 0.8);
  EXPECT_FALSE(mink::isPrepared(Au) || mink::isPrepared(Bu));
  // ConvexMaps uses the prepared maps, or builds them in its first update.
  mink::LocalMinkowskiSumOptions<double> maps;
  maps.method = mink::LocalSumMethod::ConvexMaps;
  mink::LocalMinkowskiSum<double> prepared(A, B, maps), unprepared(Au, Bu, maps);
  const auto& pu = unprepared.update(poseA, poseB, centre, 0.8);
  EXPECT_TRUE(mink::isPrepared(Au) && mink::isPrepared(Bu));  // the update built them
  const auto& pp = prepared.update(poseA, poseB, centre, 0.8);
  ASSERT_FALSE(pp.triangles.empty());
  EXPECT_EQ(pp.vertices, pu.vertices);
  EXPECT_EQ(pp.triangles, pu.triangles);
  EXPECT_EQ(pb.triangles.size(), pu.triangles.size());
}

}  // namespace
