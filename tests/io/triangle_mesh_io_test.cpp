// Tests of mink/io/triangle_mesh_io.hpp: fan triangulation and exact welding by hand,
// reading the shipped meshes (OBJ, and OFF written from them) into TriangleMesh, and the
// shipped meshes that must be rejected: mug.obj (open) and lego.obj (open as read: a
// stray triangle; non-manifold once its equal positions are welded).
#include "mink/io/triangle_mesh_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/io_test_support.hpp"
#include "support/expect_rejected.hpp"

namespace {

using mink::io::IndexedMesh;
using mink::io::TriangleSoup;
using V = mink::Vec3<double>;
using mink_test::expectRejected;

std::string data(const std::string& f) { return std::string(MINK_TEST_DATA_DIR) + "/" + f; }

TEST(TriangleMeshIo, FanTriangulation) {
  IndexedMesh<double> m;
  m.vertices = {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0), V(-1, 0.5, 0)};
  m.faces = {{0, 1, 2}, {0, 1, 2, 3}, {4, 0, 1, 2, 3}};
  const TriangleSoup<double> s = mink::io::fanTriangulate(m);
  EXPECT_EQ(s.vertices, m.vertices);
  const std::vector<std::array<int, 3>> want = {{0, 1, 2}, {0, 1, 2}, {0, 2, 3}, {4, 0, 1}, {4, 1, 2}, {4, 2, 3}};
  EXPECT_EQ(s.triangles, want);
}

TEST(TriangleMeshIo, WeldMergesExactlyEqualPositionsOnly) {
  TriangleSoup<double> s;
  const double up = std::nextafter(1.0, 2.0);
  s.vertices = {V(0, 0, 0), V(1, 0, 0), V(0, 0, 0), V(1, 0, 0), V(up, 0, 0), V(-0.0, 0, 0), V(2, 2, 2)};
  s.triangles = {{0, 1, 6}, {2, 3, 4}, {5, 4, 6}};
  std::vector<int> map;
  const TriangleSoup<double> w = mink::io::weldExactDuplicates(s, &map);
  // 0, 2 and 5 (-0 == 0) merge into 0; 1 and 3 into 1; 4 (one ulp off) stays; renumbered.
  EXPECT_EQ(map, (std::vector<int>{0, 1, 0, 1, 2, 0, 3}));
  EXPECT_EQ(w.vertices, (std::vector<V>{V(0, 0, 0), V(1, 0, 0), V(up, 0, 0), V(2, 2, 2)}));
  EXPECT_EQ(w.triangles, (std::vector<std::array<int, 3>>{{0, 1, 3}, {0, 1, 2}, {0, 2, 3}}));
  // Out-of-range indices are left for fromMesh to report.
  s.triangles.push_back({0, 1, 99});
  EXPECT_EQ(mink::io::weldExactDuplicates(s).triangles.back()[2], 99);
}

TEST(TriangleMeshIo, ShippedMeshesReadAsObjAndAsOff) {
  for (const char* f : {"torus.obj", "duck.obj", "bunny.obj", "concave_box.obj", "shape_sorter.obj"}) {
    SCOPED_TRACE(f);
    const auto fromObj = mink::io::readTriangleMesh<double>(data(f));
    const auto welded = mink::io::readTriangleMesh<double>(data(f), {true});
    EXPECT_EQ(welded.numVertices(), fromObj.numVertices());  // these need no welding
    EXPECT_EQ(welded.triangles(), fromObj.triangles());
    // Float reads the same file.
    const auto f32 = mink::io::readTriangleMesh<float>(data(f));
    EXPECT_EQ(f32.numEdges(), fromObj.numEdges());
  }
}

class TriangleMeshIoFiles : public mink_io_test::TempDirTest {};

TEST_F(TriangleMeshIoFiles, OffRoundTripAndUnknownExtension) {
  const auto torus = mink::io::readTriangleMesh<double>(data("torus.obj"));
  std::vector<std::vector<int>> faces;
  for (const auto& t : torus.triangles()) faces.push_back({t[0], t[1], t[2]});
  const auto path = dir_ / "torus.OFF";
  mink::io::writeOff(path, torus.vertices(), faces);
  const auto back = mink::io::readTriangleMesh<double>(path);
  EXPECT_EQ(back.vertices(), torus.vertices());
  EXPECT_EQ(back.triangles(), torus.triangles());
  const auto stl = file("shape.stl", "solid x\nendsolid x\n");
  expectRejected([&] { (void)mink::io::readTriangleMesh<double>(stl); }, {"shape.stl", "neither .obj nor .off"}, "stl");
  // A quad mesh is fan-triangulated: a cube of six quads.
  const auto cube = file("cube.obj",
                         "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                         "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const auto c = mink::io::readTriangleMesh<double>(cube);
  EXPECT_EQ(c.numTriangles(), 12);
  EXPECT_EQ(c.numEdges(), 18);
}

TEST(TriangleMeshIo, MugAndLegoAreRejected) {
  expectRejected([&] { (void)mink::io::readTriangleMesh<double>(data("mug.obj")); },
                 {"mug.obj: TriangleMesh::fromMesh", "is open", "not closed"}, "mug");
  // As read, lego.obj has a stray triangle (2430) whose three edges nothing else uses.
  expectRejected([&] { (void)mink::io::readTriangleMesh<double>(data("lego.obj")); },
                 {"lego.obj: TriangleMesh::fromMesh", "triangle 2430", "is open"}, "lego as read");
  // Its duplicated positions welded, edges come to be shared by four triangles.
  expectRejected([&] { (void)mink::io::readTriangleMesh<double>(data("lego.obj"), {true}); },
                 {"lego.obj: TriangleMesh::fromMesh", "non-manifold (used by 4 triangles"}, "lego welded");
}

// tryReadTriangleMesh, the entry point of builds without exceptions: each rejection of
// readTriangleMesh as an Error with the very message thrown (reader, extension, fromMesh
// with the path prefixed), and the same mesh for a good file.
TEST_F(TriangleMeshIoFiles, TryReadTriangleMeshAnswersAsReadTriangleMesh) {
  struct Case {
    std::filesystem::path path;
    mink::io::TriangleMeshReadOptions options;
  };
  const Case bad[] = {{data("mug.obj"), {}},
                      {data("lego.obj"), {}},
                      {data("lego.obj"), {true}},
                      {file("shape.stl", "solid x\nendsolid x\n"), {}},
                      {file("broken.obj", "v 0 0 0\nv 1 0\n"), {}},
                      {file("broken.off", "OFF\n3 1 0\n0 0 0\n"), {}},
                      {dir_ / "absent.off", {}},
                      {file("flat.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n"), {}}};
  for (const Case& c : bad) {
    mink_io_test::expectSameError(mink::io::tryReadTriangleMesh<double>(c.path, c.options),
                                  [&] { (void)mink::io::readTriangleMesh<double>(c.path, c.options); },
                                  c.path.string());
  }
  const auto r = mink::io::tryReadTriangleMesh<double>(data("torus.obj"));
  ASSERT_TRUE(r.ok()) << r.error().message();
  const auto torus = mink::io::readTriangleMesh<double>(data("torus.obj"));
  EXPECT_EQ(r.value().vertices(), torus.vertices());
  EXPECT_EQ(r.value().triangles(), torus.triangles());
}

}  // namespace
