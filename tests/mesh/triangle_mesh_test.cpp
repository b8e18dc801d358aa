// Tests of mink/mesh/triangle_mesh.hpp: adjacency against brute-force searches of the
// input triangles, edge kinds by hand (L-block, cone, tetrahedron) and against CGAL's
// exact predicates (every edge of every procedural and shipped mesh), Euler
// characteristics V - E + F = 2 - 2g, normals against the exact cross product, the shipped
// meshes, and copies.
#include "mink/mesh/triangle_mesh.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "mink/io/triangle_mesh_io.hpp"
#include "support/mesh_shapes.hpp"

namespace {

using mink::EdgeKind;
using mink::TriangleMesh;
using V = mink::Vec3<double>;
using Mesh = TriangleMesh<double>;
using Kq = CGAL::Simple_cartesian<CGAL::Gmpq>;

Mesh build(const mink_test::MeshShape& s) { return Mesh::fromMesh(s.verticesAs<double>(), s.triangles); }

Mesh shipped(const std::string& name) {
  return mink::io::readTriangleMesh<double>(std::string(MINK_TEST_DATA_DIR) + "/" + name);
}

struct Counts {
  int convex = 0, reflex = 0, flat = 0;
};
Counts edgeCounts(const Mesh& m) {
  Counts c;
  for (int e = 0; e < m.numEdges(); ++e) {
    const EdgeKind k = m.edgeKind(e);
    (k == EdgeKind::Convex ? c.convex : k == EdgeKind::Reflex ? c.reflex : c.flat)++;
  }
  return c;
}

// Every adjacency accessor against a search of the input triangles.
void expectAdjacencyMatchesInput(const Mesh& m, const std::string& name) {
  SCOPED_TRACE(name);
  const auto& F = m.triangles();
  // Directed edge -> triangle, from the input alone.
  std::map<std::pair<int, int>, int> owner;
  for (int t = 0; t < m.numTriangles(); ++t)
    for (int i = 0; i < 3; ++i) owner[{F[t][i], F[t][(i + 1) % 3]}] = t;
  ASSERT_EQ(static_cast<int>(owner.size()), 3 * m.numTriangles());
  EXPECT_EQ(2 * m.numEdges(), 3 * m.numTriangles());
  std::set<std::pair<int, int>> seen;
  for (int e = 0; e < m.numEdges(); ++e) {
    const auto [a, b] = m.edgeVertices(e);
    const auto [t1, t2] = m.edgeTriangles(e);
    EXPECT_EQ(owner.at({a, b}), t1) << "edge " << e;
    EXPECT_EQ(owner.at({b, a}), t2) << "edge " << e;
    EXPECT_TRUE(seen.insert({std::min(a, b), std::max(a, b)}).second) << "edge " << e << " listed twice";
  }
  for (int t = 0; t < m.numTriangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = F[t][i], b = F[t][(i + 1) % 3];
      const auto ev = m.edgeVertices(m.triangleEdge(t, i));
      EXPECT_TRUE((ev.first == a && ev.second == b) || (ev.first == b && ev.second == a)) << "triangle " << t;
      EXPECT_EQ(m.triangleNeighbor(t, i), owner.at({b, a})) << "triangle " << t << " side " << i;
    }
  // Stars: neighbours are exactly the vertices joined to v; triangle i of the star is
  // (v, neighbour i, neighbour i + 1) counter-clockwise, as given in the input.
  std::vector<std::set<int>> joined(m.numVertices());
  for (const auto& t : F)
    for (int i = 0; i < 3; ++i) joined[t[i]].insert(t[(i + 1) % 3]), joined[t[(i + 1) % 3]].insert(t[i]);
  for (int v = 0; v < m.numVertices(); ++v) {
    const auto nb = m.vertexNeighbors(v);
    const auto tr = m.vertexTriangles(v);
    const auto ed = m.vertexEdges(v);
    ASSERT_EQ(nb.size(), m.degree(v));
    ASSERT_EQ(tr.size(), nb.size());
    ASSERT_EQ(ed.size(), nb.size());
    EXPECT_EQ(std::set<int>(nb.begin(), nb.end()), joined[v]) << "vertex " << v;
    EXPECT_EQ(static_cast<int>(joined[v].size()), nb.size()) << "vertex " << v << ": a neighbour repeats";
    for (int i = 0; i < nb.size(); ++i) {
      const int w = nb[i], u = nb[(i + 1) % nb.size()];
      EXPECT_EQ(owner.at({v, w}), tr[i]) << "vertex " << v << " position " << i;
      EXPECT_EQ(owner.at({w, u}), tr[i]) << "vertex " << v << " position " << i;
      const auto ev = m.edgeVertices(ed[i]);
      EXPECT_TRUE((ev.first == v && ev.second == w) || (ev.first == w && ev.second == v));
    }
  }
}

// Edge kinds against CGAL's exact orientation and coplanar orientation on Gmpq points.
void expectEdgeKindsMatchCgal(const Mesh& m, const std::string& name) {
  SCOPED_TRACE(name);
  auto P = [&](int v) { return Kq::Point_3(m.vertex(v).x(), m.vertex(v).y(), m.vertex(v).z()); };
  int failures = 0;
  for (int e = 0; e < m.numEdges(); ++e) {
    const auto [a, b] = m.edgeVertices(e);
    const auto [t1, t2] = m.edgeTriangles(e);
    auto far = [&](int t) {
      for (int v : m.triangle(t))
        if (v != a && v != b) return v;
      return -1;
    };
    const int c = far(t1), d = far(t2);
    const CGAL::Orientation o = CGAL::orientation(P(a), P(b), P(c), P(d));
    EdgeKind want = o == CGAL::NEGATIVE ? EdgeKind::Convex : EdgeKind::Reflex;
    if (o == CGAL::COPLANAR) {
      // Both far corners on the same side of the edge would be a fold, which fromMesh rejects.
      EXPECT_NE(CGAL::coplanar_orientation(P(a), P(b), P(c), P(d)), CGAL::POSITIVE) << "edge " << e;
      want = EdgeKind::Flat;
    }
    if (m.edgeKind(e) != want && failures++ < 5)
      ADD_FAILURE() << "edge " << e << " (" << a << "-" << b << "): kind " << static_cast<int>(m.edgeKind(e))
                    << ", CGAL says " << static_cast<int>(want);
  }
  EXPECT_EQ(failures, 0);
}

TEST(TriangleMesh, ProceduralShapesAreValidWithTheirEulerCharacteristic) {
  for (const auto& s : mink_test::allMeshShapes()) {
    SCOPED_TRACE(s.name);
    const Mesh m = build(s);
    EXPECT_EQ(m.numComponents(), 1);
    EXPECT_EQ(m.numVertices() - m.numEdges() + m.numTriangles(), 2 - 2 * s.genus);
    expectAdjacencyMatchesInput(m, s.name);
    expectEdgeKindsMatchCgal(m, s.name);
  }
  EXPECT_TRUE(mink_test::lBlock().integer);
  EXPECT_TRUE(mink_test::uBlock().integer);
  EXPECT_TRUE(mink_test::starPrism().integer);
  EXPECT_TRUE(mink_test::cubeWithHole().integer);
  EXPECT_TRUE(mink_test::axes().integer);
  EXPECT_EQ(mink_test::torus(12, 8).triangles.size(), 192u);
  EXPECT_EQ(mink_test::starPrism().triangles.size(), 36u);
}

TEST(TriangleMesh, LBlockByHand) {
  const Mesh m = build(mink_test::lBlock());
  EXPECT_EQ(m.numVertices(), 12);
  EXPECT_EQ(m.numTriangles(), 20);
  EXPECT_EQ(m.numEdges(), 30);
  // 12 cap rims and 5 vertical outer corners are convex; the vertical edge at the inner
  // corner (1, 1) is reflex; 3 diagonals per cap and one per wall are flat.
  const Counts c = edgeCounts(m);
  EXPECT_EQ(c.convex, 17);
  EXPECT_EQ(c.reflex, 1);
  EXPECT_EQ(c.flat, 12);
  for (int e = 0; e < m.numEdges(); ++e) {
    if (m.edgeKind(e) != EdgeKind::Reflex) continue;
    const V a = m.vertex(m.edgeVertices(e).first), b = m.vertex(m.edgeVertices(e).second);
    EXPECT_EQ(a.head<2>(), Eigen::Vector2d(1, 1));
    EXPECT_EQ(b.head<2>(), Eigen::Vector2d(1, 1));
  }
  // Every vertex has a flat diagonal, so none is all-convex; only the two ends of the
  // reflex edge have a reflex edge.
  int allConvex = 0, noReflex = 0;
  for (int v = 0; v < m.numVertices(); ++v) {
    allConvex += m.vertexAllConvex(v);
    noReflex += m.vertexNoReflex(v);
    if (!m.vertexNoReflex(v)) {
      EXPECT_EQ(m.vertex(v).head<2>(), Eigen::Vector2d(1, 1));
    }
  }
  EXPECT_EQ(allConvex, 0);
  EXPECT_EQ(noReflex, 10);
  EXPECT_EQ(m.boxMin(), V(0, 0, 0));
  EXPECT_EQ(m.boxMax(), V(2, 2, 1));
  EXPECT_EQ(m.extent(), 5.0);
}

TEST(TriangleMesh, UBlockAndAxesReflexEdgesByHand) {
  // U: the two inner vertical corners.
  EXPECT_EQ(edgeCounts(build(mink_test::uBlock())).reflex, 2);
  // Axes: where two arms meet along an edge of the hidden central cube, 12 of them.
  const Counts c = edgeCounts(build(mink_test::axes()));
  EXPECT_EQ(c.reflex, 12);
  // 6 end caps of 4 rims, 6 arms of 4 long corners, all convex; one diagonal per quad flat.
  EXPECT_EQ(c.convex, 6 * 4 + 6 * 4);
  EXPECT_EQ(c.flat, 30);
  // Cube with a hole: where the hole's walls meet, the solid fills 270 degrees: 4 reflex.
  EXPECT_EQ(edgeCounts(build(mink_test::cubeWithHole())).reflex, 4);
}

TEST(TriangleMesh, ConeApexAndTetrahedronAreAllConvex) {
  const Mesh cone = build(mink_test::cone(16));
  int apex = -1;
  for (int v = 0; v < cone.numVertices(); ++v)
    if (cone.vertex(v) == V(0, 0, 2)) apex = v;
  ASSERT_GE(apex, 0);
  EXPECT_EQ(cone.degree(apex), 16);
  EXPECT_TRUE(cone.vertexAllConvex(apex));
  for (int v = 0; v < cone.numVertices(); ++v) {
    EXPECT_TRUE(cone.vertexNoReflex(v));
    if (v != apex) {
      EXPECT_FALSE(cone.vertexAllConvex(v)) << v;  // the base is fanned: flat edges
    }
  }
  const Mesh tet = Mesh::fromMesh({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)},
                                  {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  for (int v = 0; v < 4; ++v) EXPECT_TRUE(tet.vertexAllConvex(v));
  EXPECT_EQ(edgeCounts(tet).convex, 6);
}

TEST(TriangleMesh, NormalsAreTheExactCrossProductWithinAnUlp) {
  const Mesh m = build(mink_test::torus(12, 8));
  for (int t = 0; t < m.numTriangles(); ++t) {
    const auto& f = m.triangle(t);
    const V a = m.vertex(f[0]), b = m.vertex(f[1]), c = m.vertex(f[2]);
    const Kq::Vector_3 exact = CGAL::cross_product(Kq::Point_3(b.x(), b.y(), b.z()) - Kq::Point_3(a.x(), a.y(), a.z()),
                                                   Kq::Point_3(c.x(), c.y(), c.z()) - Kq::Point_3(a.x(), a.y(), a.z()));
    const V n = m.triangleNormal(t);
    const V e(CGAL::to_double(exact.x()), CGAL::to_double(exact.y()), CGAL::to_double(exact.z()));
    EXPECT_LE((n - e).norm(), 4e-16 * e.norm()) << "triangle " << t;
    // Outward: away from the tube's centre line.
    const V centroid = (a + b + c) / 3.0;
    const V axis = V(centroid.x(), centroid.y(), 0).normalized() * 2.0;
    EXPECT_GT(n.dot(centroid - axis), 0.0) << "triangle " << t;
  }
}

TEST(TriangleMesh, ShippedMeshesLoad) {
  struct Expect {
    const char* file;
    int triangles, genus;
  };
  for (const Expect& x : {Expect{"torus.obj", 1002, 1}, Expect{"duck.obj", 4212, 0}, Expect{"bunny.obj", 902, 0},
                          Expect{"concave_box.obj", 334, 0}, Expect{"shape_sorter.obj", 200, 3}}) {
    SCOPED_TRACE(x.file);
    const Mesh m = shipped(x.file);
    EXPECT_EQ(m.numTriangles(), x.triangles);
    EXPECT_EQ(m.numComponents(), 1);
    EXPECT_EQ(m.numVertices() - m.numEdges() + m.numTriangles(), 2 - 2 * x.genus);
    expectAdjacencyMatchesInput(m, x.file);
    expectEdgeKindsMatchCgal(m, x.file);
  }
}

TEST(TriangleMesh, SeveralComponents) {
  // Two boxes apart, and a box inside a larger one turned inside out would be a cavity,
  // which this class rejects (each component must be outward): only the first is valid.
  auto a = mink_test::boxShape(V(0, 0, 0), V(1, 1, 1)), b = mink_test::boxShape(V(3, 0, 0), V(4, 2, 1));
  std::vector<V> verts = a.verticesAs<double>();
  std::vector<std::array<int, 3>> tris = a.triangles;
  const int off = static_cast<int>(verts.size());
  for (const auto& p : b.verticesAs<double>()) verts.push_back(p);
  for (auto t : b.triangles) tris.push_back({t[0] + off, t[1] + off, t[2] + off});
  const Mesh m = Mesh::fromMesh(verts, tris);
  EXPECT_EQ(m.numComponents(), 2);
  EXPECT_EQ(m.numVertices() - m.numEdges() + m.numTriangles(), 4);
  for (int t = 0; t < m.numTriangles(); ++t) EXPECT_EQ(m.triangleComponent(t), t < 12 ? 0 : 1);
  EXPECT_EQ(m.boxMax(), V(4, 2, 1));
}

TEST(TriangleMesh, CopiesShareOneBodyAndOutliveTheOriginal) {
  std::unique_ptr<Mesh> original = std::make_unique<Mesh>(build(mink_test::lBlock()));
  const Mesh copy = *original;
  EXPECT_EQ(&copy.vertices(), &original->vertices());
  EXPECT_EQ(&copy.sphereTree(), &original->sphereTree());
  original.reset();
  EXPECT_EQ(copy.numTriangles(), 20);
  EXPECT_EQ(copy.vertex(1), mink_test::lBlock().vertices[1]);
  EXPECT_EQ(copy.sphereTree().numNodes(), 39);
}

}  // namespace
