// tests/io/hostile_input_test.cpp — hostile input to the OBJ/OFF readers and writers
// (issue 5) not covered by obj_test.cpp / off_test.cpp: non-finite and overflowing
// coordinates in OFF, empty input, bad counts, and the writers' messages. Every rejection
// is a mink::InvalidInput naming the source, line and problem. The regression test is a
// library bug found by the fuzzer (a tiny header made the OFF reader allocate by its
// counts), fixed since.
#include "mink/io/obj.hpp"
#include "mink/io/off.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io/io_test_support.hpp"
#include "support/expect_rejected.hpp"

namespace {

using V = mink::Vec3<double>;

using mink_test::expectRejected;

TEST(IoHostile, OffRejectsNonFiniteAndOverflowingCoordinates) {
  const char* tokens[] = {"nan", "NaN", "inf", "-inf", "1e999", "-1e400"};
  for (const char* tok : tokens) {
    const std::string text = std::string("OFF\n3 1 0\n0 0 0\n") + tok + " 0 0\n0 1 0\n3 0 1 2\n";
    expectRejected(
        [&] {
          std::istringstream in(text);
          (void)mink::io::readOff<double>(in, "h.off");
        },
        std::string("h.off:4: '") + tok + "' is not a finite number", tok);
  }
  // Finite in double, but not in float.
  expectRejected(
      [] {
        std::istringstream in("OFF\n3 1 0\n0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n");
        (void)mink::io::readOff<float>(in, "f.off");
      },
      "f.off:4: '1e39' is not a finite number", "OFF float overflow");
  expectRejected(
      [] {
        std::istringstream in("v 0 0 0\nv 0 -1e39 0\n");
        (void)mink::io::readObj<float>(in, "f.obj");
      },
      "f.obj:2: '-1e39' is not a finite number", "OBJ float overflow");
}

TEST(IoHostile, OffRejectsEmptyInputAndBadCounts) {
  auto readOff = [](const std::string& text) {
    std::istringstream in(text);
    (void)mink::io::readOff<double>(in, "c.off");
  };
  expectRejected([&] { readOff(""); }, "c.off:0: empty file", "empty");
  expectRejected([&] { readOff("OFF\n-3 1 0\n"); }, "c.off:2: '-3' is not a valid vertex count", "negative count");
  expectRejected([&] { readOff("OFF\n4 1 0\n0 0 0\n"); }, "file ends after 1 of 4 vertices", "truncated vertices");
}

TEST(IoHostile, WritersNameTheBadVertexOrFace) {
  const std::vector<V> v = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
  auto nanV = v;
  nanV[1][2] = std::numeric_limits<double>::quiet_NaN();
  auto infV = v;
  infV[2][0] = -std::numeric_limits<double>::infinity();
  for (const std::string w : {"writeObj", "writeOff"}) {
    auto write = [&](const std::vector<V>& verts, const std::vector<std::vector<int>>& faces) {
      std::ostringstream out;
      if (w == "writeObj") mink::io::writeObj(out, verts, faces);
      else mink::io::writeOff(out, verts, faces);
    };
    expectRejected([&] { write(nanV, {{0, 1, 2}}); }, w + ": vertex 1 has a non-finite coordinate", w + " NaN");
    expectRejected([&] { write(infV, {{0, 1, 2}}); }, w + ": vertex 2 has a non-finite coordinate", w + " -Inf");
    expectRejected([&] { write(v, {{0, 1, 2}, {0, 1, 3}}); }, w + ": face 1 has index 3 outside [0, 3)", w + " index");
    expectRejected([&] { write(v, {{0, -1, 2}}); }, w + ": face 0 has index -1 outside [0, 3)", w + " negative");
    expectRejected([&] { write(v, {{0, 1}}); }, w + ": face 0 has 2 indices (at least 3 needed)", w + " short face");
  }
}

// The non-throwing twins (the entry points of builds without exceptions) on the same input:
// an Error with the very message thrown, and nothing written.
TEST(IoHostile, TryTwinsReportWhatTheThrowingOnesThrow) {
  const std::vector<V> v = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
  auto nanV = v;
  nanV[1][2] = std::numeric_limits<double>::quiet_NaN();
  using Faces = std::vector<std::vector<int>>;
  const std::pair<std::vector<V>, Faces> bad[] = {{nanV, {{0, 1, 2}}}, {v, {{0, 1, 2}, {0, 1, 3}}},
                                                  {v, {{0, -1, 2}}}, {v, {{0, 1}}}};
  for (const auto& [verts, faces] : bad) {
    std::ostringstream a, b, unused;
    mink_io_test::expectSameError(mink::io::tryWriteObj(a, verts, faces),
                                  [&] { mink::io::writeObj(unused, verts, faces); }, "writeObj");
    mink_io_test::expectSameError(mink::io::tryWriteOff(b, verts, faces),
                                  [&] { mink::io::writeOff(unused, verts, faces); }, "writeOff");
    EXPECT_TRUE(a.str().empty() && b.str().empty());
  }
  const char* offTexts[] = {"", "OFF\n-3 1 0\n", "OFF\n4 1 0\n0 0 0\n", "OFF\n2000000000 2000000000 0\n",
                            "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"};
  for (const char* text : offTexts) {
    std::istringstream in(text);
    mink_io_test::expectSameError(
        mink::io::tryReadOff<double>(in, "c.off"),
        [&] {
          std::istringstream again(text);
          (void)mink::io::readOff<double>(again, "c.off");
        },
        text);
  }
  std::istringstream objIn("v 0 0 0\nv 0 -1e39 0\n");
  mink_io_test::expectSameError(
      mink::io::tryReadObj<float>(objIn, "f.obj"),
      [] {
        std::istringstream again("v 0 0 0\nv 0 -1e39 0\n");
        (void)mink::io::readObj<float>(again, "f.obj");
      },
      "OBJ float overflow");
}

// Regression: a 30-byte OFF header announcing 2e9 vertices makes readOff reserve 48 GB up front
// (off.hpp: mesh.vertices.reserve(numVertices)); std::bad_alloc escapes instead of
// InvalidInput (and with ~1e8 the reserve succeeds and wastes gigabytes before "file
// ends"). Expected: InvalidInput "file ends after 0 of 2000000000 vertices".
TEST(IoHostile, OffHugeCountsAreInvalidInputNotBadAlloc) {
  expectRejected(
      [] {
        std::istringstream in("OFF\n2000000000 2000000000 0\n");
        (void)mink::io::readOff<double>(in, "big.off");
      },
      "file ends after 0 of 2000000000 vertices", "2e9 vertices announced");
}

}  // namespace
