// Tests of mink/core/types.hpp: Pose<T> is the identity by default and applies
// x -> R x + t. References are hand-computed rigid motions, exact in every scalar used.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include "mink/core/types.hpp"

#include <Eigen/Geometry>

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

// Eigen isometries in and out. Reference: Eigen's own product iso * x, and the exact
// entries of the transform (conversion float -> double and double -> Gmpq is exact).
TEST(PoseIsometry, FromIsometryAppliesLikeEigen) {
  const Eigen::Isometry3d iso = Eigen::Translation3d(1.5, -2.0, 0.25) *
                                Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized());
  const auto pose = mink::Pose<double>::fromIsometry(iso);
  EXPECT_TRUE(pose.rotation == iso.linear());
  EXPECT_TRUE(pose.translation == iso.translation());
  const Eigen::Vector3d x(0.3, -4.0, 2.5);
  EXPECT_LE((pose.apply(x) - iso * x).norm(), 1e-15 * 8.0);
  // And back: the same numbers.
  const Eigen::Isometry3d back = pose.toIsometry();
  EXPECT_TRUE(back.matrix() == iso.matrix());
  // An Affine3d whose linear part is a rotation is accepted as well.
  const Eigen::Affine3d aff(iso.matrix());
  EXPECT_TRUE(mink::Pose<double>::fromIsometry(aff).rotation == pose.rotation);
}

TEST(PoseIsometry, OtherScalarsConvertEntryByEntry) {
  const Eigen::Isometry3f isoF = Eigen::Translation3f(0.1f, 2.0f, -3.0f) *
                                 Eigen::AngleAxisf(1.1f, Eigen::Vector3f::UnitZ());
  const auto pd = mink::Pose<double>::fromIsometry(isoF);
  const auto pe = mink::Pose<CGAL::Gmpq>::fromIsometry(isoF);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(pd.rotation(r, c), static_cast<double>(isoF.linear()(r, c)));
      EXPECT_TRUE(pe.rotation(r, c) == CGAL::Gmpq(static_cast<double>(isoF.linear()(r, c))));
    }
    EXPECT_EQ(pd.translation[r], static_cast<double>(isoF.translation()[r]));
    EXPECT_TRUE(pe.translation[r] == CGAL::Gmpq(static_cast<double>(isoF.translation()[r])));
  }
  // A float query pose from a double isometry rounds each entry once.
  const Eigen::Isometry3d isoD = isoF.cast<double>();
  const auto pf = mink::Pose<float>::fromIsometry(isoD);
  EXPECT_TRUE(pf.rotation == isoF.linear());
  const auto back = pf.toIsometry();
  EXPECT_TRUE(back.matrix() == isoF.matrix());
}

}  // namespace
