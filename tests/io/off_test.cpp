// Tests of mink/io/off.hpp against hand-worked files and exact round trips of random meshes.
#include "mink/io/off.hpp"

#include "io/io_test_support.hpp"
#include "mink/io/obj.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using mink::InvalidInput;
using mink::Vec3;
using OffFileTest = mink_io_test::TempDirTest;

template <class T>
void expectRoundTrip(const fs::path& path, unsigned seed) {
  std::mt19937 rng(seed);
  const auto vertices = mink_io_test::randomVertices<T>(rng, 120);
  const auto faces = mink_io_test::randomFaces(rng, 120, 90);
  mink::io::writeOff(path, vertices, faces);
  const auto back = mink::io::readOff<T>(path);
  ASSERT_EQ(back.vertices.size(), vertices.size()) << "seed " << seed;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(back.vertices[i][k] == vertices[i][k])
          << "seed " << seed << " vertex " << i << " coordinate " << k;
    }
  }
  EXPECT_EQ(back.faces, faces) << "seed " << seed;
}

TEST_F(OffFileTest, RoundTripIsBitExactForFloatingTypes) {
  expectRoundTrip<float>(dir_ / "f.off", 31u);
  expectRoundTrip<double>(dir_ / "d.off", 32u);
  expectRoundTrip<long double>(dir_ / "ld.off", 33u);
}

TEST_F(OffFileTest, HeaderEdgeCountIsTheNumberOfDistinctEdges) {
  // A square pyramid: 8 edges, counted by hand.
  const std::vector<Vec3<double>> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  const std::vector<std::vector<int>> f = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  std::ostringstream out;
  mink::io::writeOff(out, v, f);
  std::istringstream in(out.str());
  std::string header, comment, counts;
  std::getline(in, header);
  std::getline(in, comment);
  std::getline(in, counts);
  EXPECT_EQ(header, "OFF");
  EXPECT_EQ(counts, "5 5 8");
}

TEST(OffReader, CommentsVariantsAndCountsOnTheHeaderLine) {
  std::istringstream in(
      "# leading comment\n"
      "COFF 4 2 0\n"
      "\n"
      "0 0 0  255 0 0 255\n"
      "1 0 0  0 255 0 255   # colour after coordinates\n"
      "0 1 0  0 0 255 255\n"
      "0 0 1.25 1 1 1 1\r\n"
      "3 0 2 1\n"
      "4 0 1 3 2 0.5 0.5 0.5\n");
  const auto mesh = mink::io::readOff<double>(in, "c.off");
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.vertices[3], Vec3<double>(0, 0, 1.25));
  EXPECT_EQ(mesh.faces, (std::vector<std::vector<int>>{{0, 2, 1}, {0, 1, 3, 2}}));
}

TEST(OffReader, ByteOrderMarkBeforeTheHeaderIsSkipped) {
  std::istringstream in("\xEF\xBB\xBFOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const auto mesh = mink::io::readOff<double>(in, "bom.off");
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.faces, (std::vector<std::vector<int>>{{0, 1, 2}}));
}

TEST(OffReader, MalformedInputNamesFileLineAndProblem) {
  struct BadCase {
    const char* text;
    int line;
    const char* fragment;
  };
  const BadCase cases[] = {
      {"", 0, "empty file"},
      {"PLY\n3 1 0\n", 1, "expected an OFF header"},
      {"4OFF\n3 1 0\n", 1, "expected an OFF header"},
      {"OFF\n3\n", 2, "expected the counts"},
      {"OFF\n-3 1 0\n", 2, "vertex count"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n", 4, "file ends after 2 of 3 vertices"},
      {"OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 4, "needs 3 coordinates"},
      {"OFF\n3 1 0\n0 0 0\n1 y 0\n0 1 0\n3 0 1 2\n", 4, "'y' is not a finite number"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n", 5, "file ends after 0 of 1 faces"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 6, "at least 3 needed"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", 6, "announces 4 vertices but lists 3"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 6, "'3' is not a vertex index in [0, 3)"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 6, "'-1' is not a vertex index"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n", 6, "not a colour value"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", 7, "after the last face"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.text);
    std::istringstream in(c.text);
    try {
      mink::io::readOff<double>(in, "bad.off");
      ADD_FAILURE() << "no exception";
    } catch (const InvalidInput& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("bad.off:" + std::to_string(c.line) + ":"), std::string::npos) << what;
      EXPECT_NE(what.find(c.fragment), std::string::npos) << what;
    }
    // The non-throwing twin: the same message as an Error.
    std::istringstream again(c.text);
    mink_io_test::expectSameError(
        mink::io::tryReadOff<double>(again, "bad.off"),
        [&] {
          std::istringstream in2(c.text);
          (void)mink::io::readOff<double>(in2, "bad.off");
        },
        c.text);
  }
}

TEST_F(OffFileTest, MissingFileThrowsNamingIt) {
  const fs::path missing = dir_ / "absent.off";
  try {
    mink::io::readOff<float>(missing);
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  mink_io_test::expectSameError(mink::io::tryReadOff<float>(missing), [&] { (void)mink::io::readOff<float>(missing); },
                                "missing file");
}

TEST_F(OffFileTest, TryTwinsAnswerAsTheThrowingOnes) {
  const std::vector<Vec3<double>> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::vector<int>> faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  const fs::path path = dir_ / "t.off";
  EXPECT_FALSE(mink::io::tryWriteOff(path, v, faces));
  const auto r = mink::io::tryReadOff<double>(path);
  ASSERT_TRUE(r.ok()) << r.error().message();
  const auto mesh = mink::io::readOff<double>(path);
  EXPECT_EQ(r.value().vertices, mesh.vertices);
  EXPECT_EQ(r.value().faces, faces);
  std::ostringstream out, reference;
  EXPECT_FALSE(mink::io::tryWriteOff(out, v, faces));
  mink::io::writeOff(reference, v, faces);
  EXPECT_EQ(out.str(), reference.str());
  std::istringstream in(out.str());
  const auto fromStream = mink::io::tryReadOff<double>(in, "s.off");
  ASSERT_TRUE(fromStream.ok()) << fromStream.error().message();
  EXPECT_EQ(fromStream.value().faces, faces);
  // Rejected meshes, as Errors with the thrown messages; the file is not created.
  const fs::path refused = dir_ / "refused.off";
  std::ostringstream unused;
  mink_io_test::expectSameError(mink::io::tryWriteOff(refused, v, {{0, 1, 4}}),
                                [&] { mink::io::writeOff(refused, v, {{0, 1, 4}}); }, "index");
  mink_io_test::expectSameError(mink::io::tryWriteOff(unused, v, {{0, 1}}),
                                [&] { mink::io::writeOff(unused, v, {{0, 1}}); }, "short face");
  EXPECT_FALSE(fs::exists(refused));
  const fs::path nowhere = dir_ / "missing_dir" / "t.off";
  mink_io_test::expectSameError(mink::io::tryWriteOff(nowhere, mink::io::IndexedMesh<double>{v, faces}),
                                [&] { mink::io::writeOff(nowhere, mink::io::IndexedMesh<double>{v, faces}); },
                                "missing directory");
}

TEST_F(OffFileTest, ObjAndOffDescribeTheSameMesh) {
  // The same hand-written tetrahedron in both formats must read to identical data.
  const auto obj = mink::io::readObj<double>(
      file("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"));
  const auto off = mink::io::readOff<double>(
      file("t.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n"));
  ASSERT_EQ(obj.vertices.size(), off.vertices.size());
  for (std::size_t i = 0; i < obj.vertices.size(); ++i) EXPECT_EQ(obj.vertices[i], off.vertices[i]);
  EXPECT_EQ(obj.faces, off.faces);
}

}  // namespace
