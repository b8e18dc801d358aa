// tests/polyhedron/hostile_input_test.cpp — hostile input to ConvexPolyhedron<T>::fromPoints
// and fromMesh (issue 5) that convex_polyhedron_test.cpp does not already cover: meshes
// with no volume, many copies of too few points, and input at the edges of the double
// range. Each rejection must be a mink::InvalidInput whose message names the problem.
// "Regression" tests reproduce library bugs the fuzzer found (fuzz/regressions/).
#include "mink/polyhedron/convex_polyhedron.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/expect_rejected.hpp"

namespace {

using mink::ConvexPolyhedron;
using V = mink::Vec3<double>;

using mink_test::expectRejected;

std::vector<V> box(double a) {
  std::vector<V> p;
  for (int i = 0; i < 8; ++i) p.push_back(V(i & 1 ? a : -a, i & 2 ? a : -a, i & 4 ? a : -a));
  return p;
}

// A closed, consistently oriented, planar mesh of zero volume: one polygon covered from
// both sides. It passes every topological check (V - E + F = 2), so only the volume
// test can reject it.
TEST(PolyhedronHostile, FromMeshRejectsZeroVolume) {
  const std::vector<V> tri = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
  expectRejected([&] { (void)ConvexPolyhedron<double>::fromMesh(tri, {{0, 1, 2}, {0, 2, 1}}); }, {"no volume"},
                 "triangle covered from both sides");
  const std::vector<V> quad = {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)};
  expectRejected([&] { (void)ConvexPolyhedron<double>::fromMesh(quad, {{0, 1, 2, 3}, {0, 3, 2, 1}}); }, {"no volume"},
                 "square covered from both sides");
}

// Only exact duplicates of three (two) points: too few distinct points, whatever the count.
TEST(PolyhedronHostile, FromPointsRejectsManyCopiesOfAFewPoints) {
  std::vector<V> three;
  for (int k = 0; k < 40; ++k) three.push_back(k % 3 == 0 ? V(0, 0, 0) : (k % 3 == 1 ? V(1, 0, 0) : V(0, 1, 0)));
  expectRejected([&] { (void)ConvexPolyhedron<double>::fromPoints(three); }, {"coplanar"}, "40 copies of 3 points");
  std::vector<V> two;
  for (int k = 0; k < 40; ++k) two.push_back(k % 2 ? V(1, 2, 3) : V(-1, 5, 0));
  expectRejected([&] { (void)ConvexPolyhedron<double>::fromPoints(two); }, {"collinear"}, "40 copies of 2 points");
}

// Regression (fuzzer probe): a box is a box at any scale, but from about 1e60 up (and
// 1e-60 down) fromPoints called it "coplanar" or "collinear" (squared distances in the
// degeneracy tests over/underflowed; they now run on differences scaled by a power of
// two). Build it, or reject it with a message about the range of the coordinates (above
// ScalarTraits::largestCoordinate()); never misname the problem.
TEST(PolyhedronHostile, ScaledBoxIsNotCalledDegenerate) {
  for (double a : {1e-300, 1e-100, 1e-70, 1e70, 1e80}) {
    SCOPED_TRACE("box of half-size " + std::to_string(a));
    // Shapes beyond 2^±64 are built at unit scale (fromPoints and fromMesh), so even a
    // 1e-300 box merges its coplanar triangles into 6 faces with unit normals, and its
    // vertices are the input points exactly.
    const auto P = ConvexPolyhedron<double>::fromPoints(box(a));
    EXPECT_EQ(P.numFaces(), 6);
    EXPECT_EQ(P.numVertices(), 8);
    for (int f = 0; f < P.numFaces(); ++f)
      EXPECT_NEAR(P.faceNormal(f).cwiseAbs().maxCoeff(), 1.0, 1e-12) << "face " << f;
    for (int v = 0; v < P.numVertices(); ++v) EXPECT_EQ(P.vertex(v).cwiseAbs(), V(a, a, a)) << "vertex " << v;
    // fromMesh on the same faces (a fuzzer regression: fuzz/regressions/
    // from_mesh_tiny_shape_zero_area, where a 1e-294 shape's faces were "zero area").
    std::vector<std::vector<int>> faces;
    for (int f = 0; f < P.numFaces(); ++f)
      faces.push_back(std::vector<int>(P.faceVertices(f).begin(), P.faceVertices(f).end()));
    const auto M = ConvexPolyhedron<double>::fromMesh(P.vertices(), faces);
    EXPECT_EQ(M.numFaces(), 6);
    for (int f = 0; f < M.numFaces(); ++f) EXPECT_EQ(M.faceNormal(f), P.faceNormal(f)) << "face " << f;
    EXPECT_EQ(M.vertices(), P.vertices());
  }
}

// Regression (fuzzer, fuzz/regressions/rescaled_shape_vertex_not_input_point and
// _hull_of_rounded_copy): a shape of size 1e70 is built at unit scale, where a 1e-250
// coordinate becomes a denormal with a few bits. Its vertex was then neither the input
// point nor consistent with the planes (a vertex 6e21 above a face of a 7e27 shape
// built with tolerance 0). The contract now: the hull is the exact hull of the points
// rounded to multiples of 2^(e - 1074), e the exponent of the largest coordinate, and
// every input point is on or below every face plane within that.
TEST(PolyhedronHostile, RescaledShapeIsTheHullOfItsRoundedPoints) {
  const std::vector<V> pts = {V(1e70, 0, 0), V(0, 1e70, 0), V(0, 0, 1e70), V(1e-250, -3e-300, 1e-250)};
  const double grid = std::ldexp(1.0, std::ilogb(1e70) - 1074);
  for (const auto& P : {ConvexPolyhedron<double>::fromPoints(pts),
                        ConvexPolyhedron<double>::fromMesh(pts, {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}})}) {
    ASSERT_EQ(P.numVertices(), 4);
    for (int v = 0; v < 4; ++v)
      EXPECT_LE((P.vertex(v) - pts[P.inputIndex(v)]).cwiseAbs().maxCoeff(), grid) << "vertex " << v;
    for (int f = 0; f < P.numFaces(); ++f)
      for (const V& p : pts) EXPECT_LE(P.faceNormal(f).dot(p) - P.faceOffset(f), 4 * grid) << "face " << f;
  }
  // The 7e27 needle of the fuzzer's input, hull with tolerance 0.
  const std::vector<V> needle = {
      V(0x1.1010101010101p-1007, 0x1.1010103010103p-975, 0x1.1010301030301p-1007),
      V(0x1.1010303010301p-975, 0x1.0000300000303p-1007, 0x1.dd10101000004p-995),
      V(-0x1.7b70103010301p-132, -0x1.7b7b7b7b7b7b7p-132, -0x1.7b7b7b7b7b7b7p-132),
      V(-0x1.7b7b7b7b7b7b7p-132, -0x1.7b7b7b7b7b7b7p-132, 0x1.3b7b7b7b7b7b7p-1007),
      V(0x1.1030103010101p-975, 0x0.0030303010103p-1022, 0x0.00401000003ap-1022),
      V(0x1.1012001cdd101p-975, 0x1.7b7b7b7010301p+92, -0x1.7b7b7b7b7b7b7p-132),
      V(-0x1.7b7b7b7b7b7b7p-132, -0x1.7b7b7b7b7b7b7p-132, 0x1.1030101b7b7b7p-975)};
  mink::HullOptions<double> exact;
  exact.tolerance = 0;
  const auto N = ConvexPolyhedron<double>::fromPoints(needle, exact);
  const double L = 0x1.7b7b7b7010301p+92;
  for (int f = 0; f < N.numFaces(); ++f)
    for (const V& p : needle) EXPECT_LE(N.faceNormal(f).dot(p) - N.faceOffset(f), 1e-9 * L) << "face " << f;
}

// Regression (fuzzer, fuzz/regressions/tiny_coordinate_zero_normal_faces): a coordinate of
// 1e-300 next to coordinates of size 1 made orient3d's exact expansion underflow (its
// products of three differences fall below the double range); an exact duplicate of a
// hull vertex then became a fifth vertex and the hull got faces with a zero normal.
// orient3d now evaluates such inputs in long double. The hull is the tetrahedron of the
// first four points.
TEST(PolyhedronHostile, TinyCoordinateKeepsDuplicateAsVertex) {
  const double up = std::nextafter(1.0, 2.0);
  const std::vector<V> pts = {V(1, up, 0), V(up, 1e-300, 1e-300), V(-1, 0, -1), V(0.5, -2, -2), V(1, up, 0)};
  const auto P = ConvexPolyhedron<double>::fromPoints(pts);
  EXPECT_EQ(P.numVertices(), 4);
  EXPECT_EQ(P.numFaces(), 4);
  for (int f = 0; f < P.numFaces(); ++f) EXPECT_NEAR(P.faceNormal(f).norm(), 1.0, 1e-12) << "face " << f;
}

// Regression (fuzzer, fuzz/regressions/sliver_face_normal_underflows): two points 1e-301
// from the origin and 1e-301 apart, with eight of size 1. Their hull (exact) has faces
// only 1e-301 wide; fromMesh rejected those faces of the hull as "zero area" because the
// squared length of their normals underflows, and would have divided by it. Normals are
// now measured without underflow, and fromMesh accepts what fromPoints built.
TEST(PolyhedronHostile, FacesNarrowerThanTheSquareRootOfTheDoubleRangeHaveNormals) {
  const std::vector<V> pts = {
      V(-0x1.41825e1e3ea03p+0, 0x1.406d2f7d717bcp+1, 0x1.5f3ae866fdb18p+0),
      V(-0x1.700500965177p+1, -0x1.222fc551c874p-1, 0x1.17ecad275411ep+1),
      V(0x1.a6d68e02354c8p+0, 0x1.73e7356be1a44p+1, -0x1.08e8dd20f48bp-2),
      V(-0x1.6ce8f66f86334p+1, 0x1.2f526b579be1ap+1, 0x1.45f596ec5d138p-992),
      V(-0x1.7745fab79263fp+1, 0x1.0edb5b8ca1b54p+1, 0x1.400000000046ep-975),
      V(0x1.001020201p-1022, 0x1.1030103030101p-1007, 0x1.3030103010301p-1007),
      V(0x1.0010000030303p-1007, 0x1.4020202p-1007, 0x1.1c4beb82fp-998),
      V(0x1.2a17fe1f7741ep+1, 0x1.031e12e3d4e34p+0, 0x1.16a2bf94cc3ep-4),
      V(0x1.ed36e24a01c6p-3, 0x1.5116986e1e538p+0, 0x1.37c1280c2fc18p+1)};
  const auto P = ConvexPolyhedron<double>::fromPoints(pts);
  for (int f = 0; f < P.numFaces(); ++f) EXPECT_NEAR(P.faceNormal(f).norm(), 1.0, 1e-12) << "face " << f;
  std::vector<V> verts;
  for (int v = 0; v < P.numVertices(); ++v) verts.push_back(P.vertex(v));
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < P.numFaces(); ++f) faces.push_back(std::vector<int>(P.faceVertices(f).begin(), P.faceVertices(f).end()));
  const auto M = ConvexPolyhedron<double>::fromMesh(verts, faces);
  EXPECT_EQ(M.numFaces(), P.numFaces());
  for (int f = 0; f < M.numFaces(); ++f) EXPECT_NEAR(M.faceNormal(f).norm(), 1.0, 1e-12) << "face " << f;
}

// tryFromPoints and tryFromMesh, the entry points of builds without exceptions: on every
// kind of input fromPoints / fromMesh reject, they return the Error whose message is the
// what() thrown; on good input, the same shape.
TEST(PolyhedronHostile, TryTwinsReturnTheMessageThatIsThrown) {
  const double nan = std::nan("");
  std::vector<V> withNaN = box(1);
  withNaN[5] = V(0, nan, 0);
  std::vector<V> flat = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(1, 1, 0), V(2, 3, 0)};
  std::vector<V> line = {V(0, 0, 0), V(1, 1, 1), V(2, 2, 2), V(3, 3, 3)};
  std::vector<V> same(6, V(1, 2, 3));
  mink::HullOptions<double> badTol;
  badTol.tolerance = std::numeric_limits<double>::infinity();
  struct Case {
    const char* name;
    std::vector<V> points;
    mink::HullOptions<double> options;
    const char* words;
  };
  const std::vector<Case> cases = {
      {"no points", {}, {}, "no points given"},
      {"three points", {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {}, "need at least 4 points, got 3"},
      {"NaN", withNaN, {}, "point 5 has a non-finite coordinate"},
      {"coplanar", flat, {}, "coplanar"},
      {"collinear", line, {}, "collinear"},
      {"coincident", same, {}, "coincide"},
      {"infinite tolerance", box(1), badTol, "tolerance is not finite"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const auto r = ConvexPolyhedron<double>::tryFromPoints(c.points, c.options);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message().find(c.words), std::string::npos) << r.error().message();
    expectRejected([&] { (void)ConvexPolyhedron<double>::fromPoints(c.points, c.options); }, r.error().message(),
                   std::string("fromPoints: ") + c.name);
    try {
      (void)ConvexPolyhedron<double>::fromPoints(c.points, c.options);
    } catch (const mink::InvalidInput& e) {
      EXPECT_EQ(r.error().message(), std::string(e.what()));
    }
    // value() on the error throws that InvalidInput.
    expectRejected([&] { (void)r.value(); }, r.error().message(), std::string("value(): ") + c.name);
  }
  const auto good = ConvexPolyhedron<double>::tryFromPoints(box(2));
  ASSERT_TRUE(good.ok()) << good.error().message();
  EXPECT_FALSE(good.error());
  EXPECT_EQ(good.value().numVertices(), 8);
  EXPECT_EQ(good.value().numFaces(), 6);
  // fromMesh's twin: a cube with a face missing, and the cube itself.
  const auto cube = ConvexPolyhedron<double>::fromPoints(box(1));
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < cube.numFaces(); ++f) {
    std::vector<int> L;
    for (int v : cube.faceVertices(f)) L.push_back(v);
    faces.push_back(L);
  }
  const auto whole = ConvexPolyhedron<double>::tryFromMesh(cube.vertices(), faces);
  ASSERT_TRUE(whole.ok()) << whole.error().message();
  EXPECT_EQ(whole.value().numFaces(), 6);
  faces.pop_back();
  const auto open = ConvexPolyhedron<double>::tryFromMesh(cube.vertices(), faces);
  ASSERT_FALSE(open.ok());
  EXPECT_NE(open.error().message().find("not closed"), std::string::npos) << open.error().message();
  expectRejected([&] { (void)ConvexPolyhedron<double>::fromMesh(cube.vertices(), faces); }, open.error().message(),
                 "fromMesh: open cube");
}

}  // namespace
