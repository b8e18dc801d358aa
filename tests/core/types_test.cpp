// Tests of mink/core/types.hpp: Pose<T> is the identity by default and applies
// x -> R x + t. References are hand-computed rigid motions, exact in every scalar used.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include "mink/core/types.hpp"

namespace {

template <class T>
class PoseTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, double, long double, CGAL::Gmpq>;
TYPED_TEST_SUITE(PoseTest, Scalars);

TYPED_TEST(PoseTest, DefaultIsIdentity) {
  using T = TypeParam;
  const mink::Pose<T> pose;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(pose.rotation(r, c) == T(r == c ? 1 : 0)) << "r=" << r << " c=" << c;
    EXPECT_TRUE(pose.translation[r] == T(0)) << "r=" << r;
  }
  const mink::Pose<T> id = mink::Pose<T>::identity();
  EXPECT_TRUE(id.rotation == pose.rotation);
  EXPECT_TRUE(id.translation == pose.translation);
  // The identity moves nothing, including points with non-integer coordinates.
  const mink::Vec3<T> x(T(3) / T(4), T(-5), T(1) / T(8));
  EXPECT_TRUE(pose.apply(x) == x);
}

TYPED_TEST(PoseTest, ApplyIsRotationThenTranslation) {
  using T = TypeParam;
  // Quarter turn about +z (x -> y, y -> -x): exact in every scalar.
  mink::Pose<T> pose;
  pose.rotation << T(0), T(-1), T(0),  //
      T(1), T(0), T(0),                //
      T(0), T(0), T(1);
  pose.translation = mink::Vec3<T>(T(10), T(-2), T(1) / T(2));
  const mink::Vec3<T> x(T(1), T(2), T(3));
  // R x = (-2, 1, 3); + t = (8, -1, 3.5).
  const mink::Vec3<T> expected(T(8), T(-1), T(7) / T(2));
  const mink::Vec3<T> got = pose.apply(x);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(got[k] == expected[k]) << "k=" << k;
  // Translation is applied after the rotation: a pure translation moves the origin to t.
  EXPECT_TRUE(pose.apply(mink::Vec3<T>::Zero()) == pose.translation);
}

}  // namespace
