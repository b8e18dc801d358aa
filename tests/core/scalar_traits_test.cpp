// Tests of mink/core/scalar_traits.hpp: which scalars are exact, their unit roundoff,
// finiteness, and the sign / absolute-value helpers. References: <limits> and
// hand-picked values.
#include <gtest/gtest.h>

#include <cfloat>
#include <limits>

#include <CGAL/Gmpq.h>

#include "mink/core/scalar_traits.hpp"

namespace {

using mink::ScalarTraits;

static_assert(!ScalarTraits<float>::isExact, "float is not exact");
static_assert(!ScalarTraits<double>::isExact, "double is not exact");
static_assert(!ScalarTraits<long double>::isExact, "long double is not exact");
static_assert(ScalarTraits<CGAL::Gmpq>::isExact, "Gmpq is exact");

TEST(ScalarTraits, IsExact) {
  EXPECT_FALSE(ScalarTraits<float>::isExact);
  EXPECT_FALSE(ScalarTraits<double>::isExact);
  EXPECT_FALSE(ScalarTraits<long double>::isExact);
  EXPECT_TRUE(ScalarTraits<CGAL::Gmpq>::isExact);
}

TEST(ScalarTraits, Epsilon) {
  EXPECT_EQ(ScalarTraits<float>::epsilon(), FLT_EPSILON);
  EXPECT_EQ(ScalarTraits<double>::epsilon(), DBL_EPSILON);
  EXPECT_EQ(ScalarTraits<long double>::epsilon(), LDBL_EPSILON);
  EXPECT_TRUE(ScalarTraits<CGAL::Gmpq>::epsilon() == CGAL::Gmpq(0));
}

template <class T>
void expectFiniteness() {
  SCOPED_TRACE(typeid(T).name());
  EXPECT_TRUE(ScalarTraits<T>::isFinite(T(0)));
  EXPECT_TRUE(ScalarTraits<T>::isFinite(T(-1.5)));
  EXPECT_TRUE(ScalarTraits<T>::isFinite(std::numeric_limits<T>::max()));
  EXPECT_TRUE(ScalarTraits<T>::isFinite(std::numeric_limits<T>::denorm_min()));
  EXPECT_FALSE(ScalarTraits<T>::isFinite(std::numeric_limits<T>::quiet_NaN()));
  EXPECT_FALSE(ScalarTraits<T>::isFinite(std::numeric_limits<T>::infinity()));
  EXPECT_FALSE(ScalarTraits<T>::isFinite(-std::numeric_limits<T>::infinity()));
}

TEST(ScalarTraits, IsFinite) {
  expectFiniteness<float>();
  expectFiniteness<double>();
  expectFiniteness<long double>();
  EXPECT_TRUE(ScalarTraits<CGAL::Gmpq>::isFinite(CGAL::Gmpq(-7, 3)));
}

TEST(ScalarTraits, SignAndAbs) {
  // Qualified calls: CGAL::sign would make an unqualified call on Gmpq ambiguous (ADL).
  using mink::detail::absValue;
  namespace md = mink::detail;
  EXPECT_EQ(md::sign(-2.5), -1);
  EXPECT_EQ(md::sign(0.0), 0);
  EXPECT_EQ(md::sign(-0.0), 0);
  EXPECT_EQ(md::sign(1e-300), 1);
  EXPECT_EQ(md::sign(3.0f), 1);
  EXPECT_EQ(md::sign(CGAL::Gmpq(-1, 1000000007)), -1);
  EXPECT_EQ(md::sign(CGAL::Gmpq(0)), 0);
  EXPECT_EQ(md::sign(CGAL::Gmpq(5, 7)), 1);
  EXPECT_EQ(absValue(-2.5), 2.5);
  EXPECT_EQ(absValue(2.5f), 2.5f);
  EXPECT_EQ(absValue(-3.0L), 3.0L);
  EXPECT_TRUE(absValue(CGAL::Gmpq(-5, 7)) == CGAL::Gmpq(5, 7));
  EXPECT_TRUE(absValue(CGAL::Gmpq(5, 7)) == CGAL::Gmpq(5, 7));
}

}  // namespace
