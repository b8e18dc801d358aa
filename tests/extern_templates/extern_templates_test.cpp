// tests/extern_templates/extern_templates_test.cpp — include/mink/extern_templates.hpp:
// this file is compiled with MINK_EXTERN_TEMPLATES (it links mink::instantiations), so
// every float / double entry point it calls comes from src/mink_instantiations.cpp, and
// the answers must be those of the header-only build. The test
// extern_templates.not_instantiated_here checks with nm that this object file defines
// none of them (tests/extern_templates/check_symbols.cmake).
#include "mink/mink.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#ifndef MINK_EXTERN_TEMPLATES
#error "this test must be compiled with MINK_EXTERN_TEMPLATES (link mink::instantiations)"
#endif

namespace {

template <class T>
std::vector<mink::Vec3<T>> boxPoints(T a) {
  std::vector<mink::Vec3<T>> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1 ? a : -a, i & 2 ? a : -a, i & 4 ? a : -a);
  return pts;
}

template <class T>
void checkBoxes() {
  using mink::MddStatus;
  const auto B = mink::ConvexPolyhedron<T>::fromPoints(boxPoints<T>(T(1)));
  EXPECT_EQ(B.numVertices(), 8);
  mink::Pose<T> p, q;
  q.translation = mink::Vec3<T>(T(3), T(0.25), T(0));
  // Q's box spans x in [2, 4]: along -x it touches P's after 1.
  const auto r = mink::mdd(B, p, B, q, mink::Vec3<T>(T(-1), T(0), T(0)));
  EXPECT_EQ(r.status, MddStatus::Separated);
  EXPECT_NEAR(double(r.translation), 1.0, 1e-5);
  mink::MddCache<T> cache;
  const auto rc = mink::mdd(B, p, B, q, mink::Vec3<T>(T(1), T(0), T(0)), cache);
  EXPECT_EQ(rc.status, MddStatus::Separated);
  EXPECT_NEAR(double(rc.translation), -1.0, 1e-5);
  EXPECT_FALSE(mink::intersects(B, p, B, q));
  EXPECT_FALSE(mink::intersects(B, p, B, q, cache));
  q.translation = mink::Vec3<T>(T(1.5), T(0), T(0));
  EXPECT_TRUE(mink::intersects(B, p, B, q));
  const auto hit = mink::firstContact(B, p, B, q, mink::Vec3<T>(T(-1), T(0), T(0)));
  EXPECT_TRUE(hit.hit);
  EXPECT_EQ(hit.mdd.status, MddStatus::Penetrating);
  EXPECT_NEAR(double(hit.mdd.translation), -0.5, 1e-5);
  const auto miss = mink::firstContact(B, p, B, q, mink::Vec3<T>(T(0), T(0), T(1)), cache);
  EXPECT_TRUE(miss.hit);  // already overlapping: contact at the start
  EXPECT_EQ(miss.fraction, T(0));
  // fromMesh on the hull's own faces, and prepare() (no hierarchy for 8 vertices).
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < B.numFaces(); ++f) {
    std::vector<int> face;
    for (int v : B.faceVertices(f)) face.push_back(v);
    faces.push_back(face);
  }
  std::vector<mink::Vec3<T>> verts;
  for (int v = 0; v < B.numVertices(); ++v) verts.push_back(B.vertex(v));
  const auto M = mink::ConvexPolyhedron<T>::fromMesh(verts, faces);
  EXPECT_EQ(M.numFaces(), B.numFaces());
  EXPECT_EQ(mink::prepare(M), nullptr);
  EXPECT_TRUE(mink::isPrepared(M));
}

TEST(ExternTemplates, DoubleEntryPointsAnswerAsHeaderOnly) { checkBoxes<double>(); }
TEST(ExternTemplates, FloatEntryPointsAnswerAsHeaderOnly) { checkBoxes<float>(); }

}  // namespace
