// Tests of mink/io/obj.hpp. References are independent of the reader: hand-written files
// whose meaning is worked out by hand in the test, and randomly generated meshes that
// must come back exactly as they were written (coordinates are compared bit for bit).
#include "mink/io/obj.hpp"

#include "io/io_test_support.hpp"

#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using mink::InvalidInput;
using mink::Vec3;
using mink_io_test::randomFaces;
using mink_io_test::randomVertices;
using ObjFileTest = mink_io_test::TempDirTest;

template <class T>
void expectRoundTrip(const fs::path& path, unsigned seed) {
  std::mt19937 rng(seed);
  const auto vertices = randomVertices<T>(rng, 200);
  const auto faces = randomFaces(rng, 200, 150);
  mink::io::writeObj(path, vertices, faces);
  const auto back = mink::io::readObj<T>(path);
  ASSERT_EQ(back.vertices.size(), vertices.size()) << "seed " << seed;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      // Bit-exact: == on the scalars, not a tolerance.
      ASSERT_TRUE(back.vertices[i][k] == vertices[i][k])
          << "seed " << seed << " vertex " << i << " coordinate " << k;
    }
  }
  EXPECT_EQ(back.faces, faces) << "seed " << seed;
}

TEST_F(ObjFileTest, RoundTripIsBitExactForFloatingTypes) {
  expectRoundTrip<float>(dir_ / "f.obj", 11u);
  expectRoundTrip<double>(dir_ / "d.obj", 12u);
  expectRoundTrip<long double>(dir_ / "ld.obj", 13u);
}

TEST_F(ObjFileTest, RoundTripOfExactRationalsThatAreDoubles) {
  // Dyadic rationals are doubles, so the exact type must survive the double-based text.
  std::mt19937 rng(21u);
  std::uniform_int_distribution<int> num(-1000, 1000);
  std::vector<Vec3<CGAL::Gmpq>> vertices(50);
  for (auto& p : vertices) {
    for (int k = 0; k < 3; ++k) p[k] = CGAL::Gmpq(num(rng), 64);
  }
  const auto faces = randomFaces(rng, 50, 20);
  const fs::path path = dir_ / "q.obj";
  mink::io::writeObj(path, vertices, faces);
  const auto back = mink::io::readObj<CGAL::Gmpq>(path);
  ASSERT_EQ(back.vertices.size(), vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    EXPECT_TRUE(back.vertices[i] == vertices[i]) << "vertex " << i;
  }
  EXPECT_EQ(back.faces, faces);
  // A decimal that is not a double becomes the double nearest to it, exactly.
  std::istringstream in("v 0.1 0 0\n");
  const auto tenth = mink::io::readObj<CGAL::Gmpq>(in, "tenth");
  EXPECT_TRUE(tenth.vertices[0][0] == CGAL::Gmpq(0.1));
  EXPECT_FALSE(tenth.vertices[0][0] == CGAL::Gmpq(1, 10));
}

TEST(ObjReader, IndexFormsCommentsBlankLinesAndIgnoredStatements) {
  std::istringstream in(
      "# a comment line\n"
      "mtllib box.mtl\r\n"
      "o thing\n"
      "\n"
      "v 0 0 0\n"
      "v 1.5 0 0   # trailing comment\n"
      "\tv 0 2 0 1.0\n"          // leading tab, optional w
      "v 0 0 -3e0 0.5 0.5 0.5\n"  // vertex colours
      "vt 0.5 0.5\n"
      "vn 0 0 1\n"
      "usemtl red\n"
      "s off\n"
      "g side\n"
      "f 1 2 3\n"
      "f 1/1 3/1 4/1\r\n"
      "f 1//1 4//1 2//1\n"
      "f 2/1/1 4/1/1 3/1/1\n"
      "l 1 2\n");
  const auto mesh = mink::io::readObj<double>(in, "forms.obj");
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.vertices[1], Vec3<double>(1.5, 0, 0));
  EXPECT_EQ(mesh.vertices[2], Vec3<double>(0, 2, 0));
  EXPECT_EQ(mesh.vertices[3], Vec3<double>(0, 0, -3));
  const std::vector<std::vector<int>> expected = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  EXPECT_EQ(mesh.faces, expected);
}

TEST(ObjReader, NegativeIndicesCountBackFromTheLatestVertex) {
  // Vertices and faces interleave: -1 is the latest vertex *at that line*.
  std::istringstream in(
      "v 0 0 0\n"
      "v 1 0 0\n"
      "v 0 1 0\n"
      "f -3 -2 -1\n"      // 0 1 2
      "v 0 0 1\n"
      "f -4 -1 -3/-1/-1\n"  // 0 3 1
      "f -2//-1 -1 -3\n"  // 2 3 1
      "f 1 3 -1\n");      // 0 2 3
  const auto mesh = mink::io::readObj<float>(in, "neg.obj");
  const std::vector<std::vector<int>> expected = {{0, 1, 2}, {0, 3, 1}, {2, 3, 1}, {0, 2, 3}};
  EXPECT_EQ(mesh.faces, expected);
}

TEST(ObjReader, ForwardReferenceAndContinuationLines) {
  std::istringstream in(
      "f 1 2 \\\n"
      "  3\n"
      "v 0 0 0\n"
      "v 1 \\\n"
      "0 0\n"
      "v 0 1 0\n");
  const auto mesh = mink::io::readObj<double>(in, "cont.obj");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[1], Vec3<double>(1, 0, 0));
  EXPECT_EQ(mesh.faces, (std::vector<std::vector<int>>{{0, 1, 2}}));
}

TEST(ObjReader, ByteOrderMarkBeforeTheFirstLineIsSkipped) {
  std::istringstream in("\xEF\xBB\xBFv 1 2 3\nv 4 5 6\nv 7 8 9\nf 1 2 3\n");
  const auto mesh = mink::io::readObj<double>(in, "bom.obj");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0], Vec3<double>(1, 2, 3));
  // Only before the first line: elsewhere the bytes are not an OBJ keyword.
  std::istringstream late("v 1 2 3\n\xEF\xBB\xBFv 4 5 6\n");
  EXPECT_THROW(mink::io::readObj<double>(late, "late.obj"), InvalidInput);
}

struct BadCase {
  const char* text;
  int line;
  const char* fragment;  // must appear in the message
};

TEST(ObjReader, MalformedInputNamesFileLineAndProblem) {
  const std::string prefix = "v 0 0 0\nv 1 0 0\nv 0 1 0\n# comment\n";  // 4 lines
  const BadCase cases[] = {
      {"v 1 2\n", 5, "found 2 values"},
      {"v 1 x 3\n", 5, "'x' is not a finite number"},
      {"v 1 2 3 4 5 6 7 8\n", 5, "found 8 values"},
      {"v 1 nan 3\n", 5, "'nan' is not a finite number"},
      {"v 1 2 1e999\n", 5, "'1e999' is not a finite number"},
      {"f 1 2\n", 5, "at least 3 vertices, found 2"},
      {"f 1 0 2\n", 5, "vertex index 0"},
      {"f 1 2 4\n", 5, "vertex index 4 is out of range (the file has 3 vertices)"},
      {"f 1 2 -4\n", 5, "relative vertex index -4"},
      {"f 1/x 2 3\n", 5, "malformed texture index"},
      {"f 1/2/ 2 3\n", 5, "malformed normal index"},
      {"f 1/2/3/4 2 3\n", 5, "more than three"},
      {"f a b c\n", 5, "does not start with an integer"},
      {"f 1.5 2 3\n", 5, "does not start with an integer"},
      {"1 2 3\n", 5, "'1' is not an OBJ statement"},
      {"vv 1 2 3\n", 5, "'vv' is not an OBJ statement"},
      {"\n\nf 1 2 99\nv 0 0 1\n", 7, "vertex index 99"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.text);
    std::istringstream in(prefix + c.text);
    try {
      mink::io::readObj<double>(in, "bad.obj");
      ADD_FAILURE() << "no exception";
    } catch (const InvalidInput& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("bad.obj:" + std::to_string(c.line) + ":"), std::string::npos) << what;
      EXPECT_NE(what.find(c.fragment), std::string::npos) << what;
    }
    // The non-throwing twin: the same message as an Error.
    std::istringstream again(prefix + c.text);
    mink_io_test::expectSameError(
        mink::io::tryReadObj<double>(again, "bad.obj"),
        [&] {
          std::istringstream in2(prefix + c.text);
          (void)mink::io::readObj<double>(in2, "bad.obj");
        },
        c.text);
  }
}

TEST(ObjReader, TryReadObjAnswersGoodInputAsReadObj) {
  const std::string text =
      "v 0 0 0\nv 1 0 0 # x\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nf 1 3 2\nf 1/1 2/2 4/4\nf 2//1 3//1 4//1\nf -4 -1 -2\n";
  std::istringstream a(text), b(text);
  const auto r = mink::io::tryReadObj<double>(a, "good.obj");
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_FALSE(r.error());
  const auto mesh = mink::io::readObj<double>(b, "good.obj");
  EXPECT_EQ(r.value().vertices, mesh.vertices);
  EXPECT_EQ(r.value().faces, mesh.faces);
  EXPECT_EQ(r.value().faces.size(), 4u);
}

TEST_F(ObjFileTest, MissingFileThrowsNamingIt) {
  const fs::path missing = dir_ / "no_such_file.obj";
  try {
    mink::io::readObj<double>(missing);
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  mink_io_test::expectSameError(mink::io::tryReadObj<double>(missing),
                                [&] { (void)mink::io::readObj<double>(missing); }, "missing file");
}

TEST_F(ObjFileTest, ErrorFromAFileNamesItsPath) {
  const fs::path path = file("broken.obj", "v 0 0 0\nv 0 0\n");
  try {
    mink::io::readObj<double>(path);
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ":2:"), std::string::npos) << e.what();
  }
  mink_io_test::expectSameError(mink::io::tryReadObj<double>(path), [&] { (void)mink::io::readObj<double>(path); },
                                "broken file");
  const auto good = mink::io::tryReadObj<double>(file("good.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  ASSERT_TRUE(good.ok()) << good.error().message();
  EXPECT_EQ(good.value().faces, (std::vector<std::vector<int>>{{0, 1, 2}}));
}

TEST_F(ObjFileTest, WriterRejectsBadMeshesWithoutTouchingTheFile) {
  const std::vector<Vec3<double>> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const fs::path path = file("keep.obj", "original");
  EXPECT_THROW(mink::io::writeObj(path, v, {{0, 1, 3}}), InvalidInput);
  EXPECT_THROW(mink::io::writeObj(path, v, {{0, 1}}), InvalidInput);
  EXPECT_THROW(mink::io::writeObj(path, v, {{0, -1, 2}}), InvalidInput);
  auto nan = v;
  nan[1][2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(mink::io::writeObj(path, nan, {{0, 1, 2}}), InvalidInput);
  std::ifstream in(path);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "original");
  EXPECT_THROW(mink::io::writeObj(dir_ / "missing_dir" / "x.obj", v, {{0, 1, 2}}), InvalidInput);
  // tryWriteObj: the same messages as Errors, the file again untouched; then a good write
  // that reads back.
  using Faces = std::vector<std::vector<int>>;
  const std::pair<std::vector<Vec3<double>>, Faces> bad[] = {
      {v, {{0, 1, 3}}}, {v, {{0, 1}}}, {v, {{0, -1, 2}}}, {nan, {{0, 1, 2}}}};
  for (const auto& [verts, faces] : bad) {
    mink_io_test::expectSameError(mink::io::tryWriteObj(path, verts, faces),
                                  [&] { mink::io::writeObj(path, verts, faces); }, "path");
    std::ostringstream out;
    mink_io_test::expectSameError(mink::io::tryWriteObj(out, verts, faces), [&] {
      std::ostringstream out2;
      mink::io::writeObj(out2, verts, faces);
    }, "stream");
    EXPECT_TRUE(out.str().empty());
  }
  std::ifstream again(path);
  std::getline(again, content);
  EXPECT_EQ(content, "original");
  const fs::path nowhere = dir_ / "missing_dir" / "x.obj";
  mink_io_test::expectSameError(mink::io::tryWriteObj(nowhere, v, {{0, 1, 2}}),
                                [&] { mink::io::writeObj(nowhere, v, {{0, 1, 2}}); }, "missing directory");
  const fs::path written = dir_ / "written.obj";
  EXPECT_FALSE(mink::io::tryWriteObj(written, mink::io::IndexedMesh<double>{v, {{0, 1, 2}}}));
  EXPECT_EQ(mink::io::readObj<double>(written).faces, (Faces{{0, 1, 2}}));
  std::ostringstream out;
  EXPECT_FALSE(mink::io::tryWriteObj(out, v, {{0, 1, 2}}));
  std::ostringstream reference;
  mink::io::writeObj(reference, v, {{0, 1, 2}});
  EXPECT_EQ(out.str(), reference.str());
}

TEST_F(ObjFileTest, EmptyFileGivesEmptyMesh) {
  const auto mesh = mink::io::readObj<double>(file("empty.obj", "# nothing\n\n"));
  EXPECT_TRUE(mesh.vertices.empty());
  EXPECT_TRUE(mesh.faces.empty());
}

}  // namespace
