// tests/mesh/hostile_input_test.cpp — one test per rejection of TriangleMesh<T>::fromMesh:
// each must be a mink::InvalidInput whose message names the problem and the offending
// element (expectRejected), and each problem must have its own message.
#include "mink/mesh/triangle_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/expect_rejected.hpp"
#include "support/mesh_shapes.hpp"

namespace {

using mink::TriangleMesh;
using mink_test::expectRejected;
using V = mink::Vec3<double>;
using Tris = std::vector<std::array<int, 3>>;

// A valid tetrahedron, outward: the starting point of most hostile variants.
const std::vector<V> kTet = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)};
const Tris kTetTris = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// Also checks the non-throwing twin: tryFromMesh fails with the very message thrown.
void reject(const std::vector<V>& v, const Tris& t, std::initializer_list<std::string> needles,
            const std::string& context) {
  expectRejected([&] { (void)TriangleMesh<double>::fromMesh(v, t); }, needles, context);
  const mink::Result<TriangleMesh<double>> r = TriangleMesh<double>::tryFromMesh(v, t);
  ASSERT_FALSE(r.ok()) << context;
  try {
    (void)TriangleMesh<double>::fromMesh(v, t);
  } catch (const mink::InvalidInput& e) {
    EXPECT_EQ(r.error().message(), std::string(e.what())) << context;
  }
}

TEST(MeshHostile, TheTetrahedronItselfIsAccepted) {
  const auto m = TriangleMesh<double>::fromMesh(kTet, kTetTris);
  EXPECT_EQ(m.numEdges(), 6);
  const auto r = TriangleMesh<double>::tryFromMesh(kTet, kTetTris);
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(r.value().numEdges(), 6);
}

TEST(MeshHostile, EmptyInput) {
  reject({}, kTetTris, {"empty input", "no vertices"}, "no vertices");
  reject(kTet, {}, {"empty input", "no triangles"}, "no triangles");
}

TEST(MeshHostile, NonFiniteVertex) {
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    auto v = kTet;
    v[2][1] = bad;
    reject(v, kTetTris, {"vertex 2", "non-finite"}, "coordinate " + std::to_string(bad));
  }
}

TEST(MeshHostile, CoordinateAboveTheLargestCoordinate) {
  auto v = kTet;
  v[3][2] = 1e100;  // above 2^296 ~ 1.3e89
  reject(v, kTetTris, {"vertex 3", "out of range"}, "1e100");
  auto f = std::vector<mink::Vec3<float>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1e12f}};  // float: 2^37
  expectRejected([&] { (void)TriangleMesh<float>::fromMesh(f, kTetTris); }, {"vertex 3", "out of range"}, "float 1e12");
}

TEST(MeshHostile, IndexOutOfRange) {
  reject(kTet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 4}}, {"triangle 3", "index 4", "out of range"}, "index 4");
  reject(kTet, {{0, 2, -1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}, {"triangle 0", "index -1", "out of range"}, "index -1");
}

TEST(MeshHostile, DegenerateTriangleRepeatedIndex) {
  reject(kTet, {{0, 2, 1}, {0, 1, 3}, {3, 3, 2}, {1, 2, 3}}, {"triangle 2", "degenerate", "repeats vertex 3"},
         "repeated index");
}

// A closed mesh one of whose triangles has collinear corners: a square pyramid whose base
// is split through a point on its edge... exactly: the base (0,0,0)-(2,0,0)-(2,2,0)-(0,2,0)
// with the extra vertex (1,0,0) on its first side, used by a zero-area triangle.
TEST(MeshHostile, DegenerateTriangleCollinearCorners) {
  const std::vector<V> v = {V(0, 0, 0), V(2, 0, 0), V(2, 2, 0), V(0, 2, 0), V(1, 1, 2), V(1, 0, 0)};
  // Side faces of the pyramid (apex 4); the front face 0-5-1 is split at 5, and the base
  // is fanned so that triangle (0, 5, 1) — collinear — closes the hole left at 5.
  const Tris t = {{0, 5, 4}, {5, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4},  // sides
                  {0, 3, 2}, {0, 2, 1}, {0, 1, 5}};                       // base + sliver
  reject(v, t, {"triangle 7", "degenerate", "collinear"}, "collinear");
  // A corner off the line by one ulp is accepted (decided exactly).
  auto w = v;
  w[5][1] = -std::numeric_limits<double>::denorm_min();
  EXPECT_NO_THROW((void)TriangleMesh<double>::fromMesh(w, t));
}

TEST(MeshHostile, OpenEdge) {
  reject(kTet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}}, {"edge", "open", "not closed"}, "missing face");
}

TEST(MeshHostile, NonManifoldEdge) {
  // Three tetrahedra-like fins on edge 0-1: triangles (0,1,2), (1,0,3), (0,1,4), (1,0,5) ...
  // simplest: the tetrahedron plus a second one glued along edge 0-1 only.
  std::vector<V> v = kTet;
  v.push_back(V(1, -1, -1));
  v.push_back(V(0, -1, -1));
  Tris t = kTetTris;
  for (auto f : Tris{{0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}}) t.push_back(f);
  reject(v, t, {"edge 0-1", "non-manifold", "4 triangles"}, "two tetrahedra on one edge");
}

TEST(MeshHostile, InconsistentOrientation) {
  reject(kTet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 3, 2}}, {"same direction", "inconsistent orientation"},
         "one face flipped");
}

TEST(MeshHostile, NonManifoldVertex) {
  // Two tetrahedra sharing only vertex 0.
  std::vector<V> v = kTet;
  for (const V& p : {V(-1, 0, 0), V(0, -1, 0), V(0, 0, -1)}) v.push_back(p);
  Tris t = kTetTris;
  for (auto f : Tris{{0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}}) t.push_back(f);
  reject(v, t, {"vertex 0", "non-manifold", "more than one fan"}, "two cones at a vertex");
}

TEST(MeshHostile, UnreferencedVertex) {
  auto v = kTet;
  v.push_back(V(5, 5, 5));
  reject(v, kTetTris, {"vertex 4", "unreferenced"}, "extra vertex");
}

// Two triangles on the same three corners, facing each other: a dihedral angle of 0 at
// every edge, and a closed, consistent, manifold mesh otherwise.
TEST(MeshHostile, FoldedTriangles) {
  reject({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {{0, 1, 2}, {0, 2, 1}}, {"folded", "dihedral angle of 0"},
         "one triangle covered from both sides");
  // A fold inside a larger mesh: a square pyramid whose apex sits in the base plane,
  // over the base: the side triangles lie on the base, on the same side of its edges.
  const std::vector<V> v = {V(0, 0, 0), V(2, 0, 0), V(2, 2, 0), V(0, 2, 0), V(1, 1, 0)};
  reject(v, {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2}, {0, 2, 1}}, {"folded", "across edge"},
         "flat pyramid");
}

TEST(MeshHostile, InwardOrientation) {
  Tris t = kTetTris;
  for (auto& f : t) std::swap(f[1], f[2]);
  reject(kTet, t, {"component 0", "inward", "negative"}, "tetrahedron inside out");
  // The second of two components inside out (a cavity is not a valid TriangleMesh).
  auto box = mink_test::boxShape(V(-3, -3, -3), V(3, 3, 3));
  std::vector<V> verts = box.verticesAs<double>();
  Tris tris = box.triangles;
  for (const V& p : kTet) verts.push_back(p);
  for (auto f : t) tris.push_back({f[0] + 8, f[1] + 8, f[2] + 8});
  reject(verts, tris, {"component 1", "inward"}, "cavity");
}

// A bipyramid over the triangle (0,0,0), (1,0,0), (0,1,0) whose two apexes are both above
// the base at the same height: the upper cone counts +, the other (reached through the
// base from below) -, and the volumes cancel exactly. Every edge is a proper dihedral;
// only the exact volume sum can tell (its floating-point value is rounding noise).
TEST(MeshHostile, ZeroVolume) {
  const std::vector<V> v = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0.25, 0.25, 1), V(0.125, 0.1875, 1)};
  const Tris t = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};
  reject(v, t, {"component 0", "zero volume"}, "cancelling cones");
  // One apex an ulp higher: now the volume is negative (and is told exactly).
  auto w = v;
  w[4][2] = std::nextafter(1.0, 2.0);
  reject(w, t, {"inward", "negative"}, "lower cone an ulp taller");
  w[4][2] = std::nextafter(1.0, 0.0);
  EXPECT_NO_THROW((void)TriangleMesh<double>::fromMesh(w, t));
  // The same far from the origin: the determinants are about 1e26 and their floating-point
  // sum is rounding noise of about 1e10, of either sign; the exact sum is still 0, and
  // the apex 2^-20 higher or lower still decides.
  const V far(1e8, -3e8, 5e8);  // every coordinate below plus these is a double exactly
  std::vector<V> moved = v;
  for (V& p : moved) p += far;
  reject(moved, t, {"zero volume"}, "cancelling cones far from the origin");
  moved[4][2] = far[2] + 1 + std::ldexp(1.0, -20);
  reject(moved, t, {"inward"}, "far, lower cone taller");
  moved[4][2] = far[2] + 1 - std::ldexp(1.0, -20);
  EXPECT_NO_THROW((void)TriangleMesh<double>::fromMesh(moved, t));
}

TEST(MeshHostile, EveryKindHasItsOwnMessage) {
  // The distinguishing phrases used above are mutually exclusive: a message with one of
  // them has none of the others (checked on one message per kind).
  const std::vector<std::string> phrases = {"empty input",     "non-finite",   "out of range (",  "out of range [",
                                            "repeats vertex",  "collinear",    "is open",         "non-manifold (used",
                                            "same direction",  "more than one fan", "unreferenced", "folded",
                                            "inward",          "zero volume"};
  std::vector<std::string> messages;
  auto capture = [&](const std::vector<V>& v, const Tris& t) {
    try {
      (void)TriangleMesh<double>::fromMesh(v, t);
      messages.push_back("accepted");
    } catch (const mink::InvalidInput& e) {
      messages.push_back(e.what());
    }
  };
  auto big = kTet;
  big[3][2] = 1e100;
  auto nan = kTet;
  nan[0][0] = std::nan("");
  auto extra = kTet;
  extra.push_back(V(9, 9, 9));
  Tris inward = kTetTris;
  for (auto& f : inward) std::swap(f[1], f[2]);
  capture({}, kTetTris);
  capture(nan, kTetTris);
  capture(big, kTetTris);
  capture(kTet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 7}});
  capture(kTet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 3}, {1, 2, 3}});
  capture({V(0, 0, 0), V(2, 0, 0), V(2, 2, 0), V(0, 2, 0), V(1, 1, 2), V(1, 0, 0)},
          {{0, 5, 4}, {5, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2}, {0, 2, 1}, {0, 1, 5}});
  capture(kTet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}});
  {
    std::vector<V> v = kTet;
    v.push_back(V(1, -1, -1));
    v.push_back(V(0, -1, -1));
    Tris t = kTetTris;
    for (auto f : Tris{{0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}}) t.push_back(f);
    capture(v, t);
  }
  capture(kTet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 3, 2}});
  {
    std::vector<V> v = kTet;
    for (const V& p : {V(-1, 0, 0), V(0, -1, 0), V(0, 0, -1)}) v.push_back(p);
    Tris t = kTetTris;
    for (auto f : Tris{{0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}}) t.push_back(f);
    capture(v, t);
  }
  capture(extra, kTetTris);
  capture({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {{0, 1, 2}, {0, 2, 1}});
  capture(kTet, inward);
  capture({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0.25, 0.25, 1), V(0.125, 0.1875, 1)},
          {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}});
  ASSERT_EQ(messages.size(), phrases.size());
  for (std::size_t i = 0; i < phrases.size(); ++i)
    for (std::size_t j = 0; j < phrases.size(); ++j)
      EXPECT_EQ(messages[i].find(phrases[j]) != std::string::npos, i == j)
          << "message " << i << " '" << messages[i] << "' and phrase '" << phrases[j] << "'";
}

}  // namespace
