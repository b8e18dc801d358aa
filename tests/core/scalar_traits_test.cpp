// Tests of mink/core/scalar_traits.hpp: which scalars are exact, their unit roundoff,
// finiteness, and the sign / absolute-value helpers. References: <limits> and
// hand-picked values.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>
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

// timesPow2 multiplies by the power of two for |k| <= 62 instead of calling ldexp: the
// bits must be ldexp's everywhere, including results that round into the subnormal
// range, overflow, and the inputs +-0, +-inf, NaN.
template <class T>
void expectTimesPow2IsLdexp() {
  using L = std::numeric_limits<T>;
  std::mt19937_64 rng(17u);
  std::uniform_real_distribution<double> mant(1.0, 2.0);
  std::uniform_int_distribution<int> ex(L::min_exponent - L::digits - 4, L::max_exponent + 2);
  std::vector<T> xs = {T(0), -T(0), T(1), -T(1), L::min(), L::denorm_min(), L::max(), -L::max(), L::epsilon(),
                       L::infinity(), -L::infinity()};
  for (int i = 0; i < 4000; ++i) {
    const T x = std::ldexp(T(mant(rng)), ex(rng));  // saturates to 0 or inf at the ends
    xs.push_back(i % 2 ? x : -x);
  }
  int checked = 0;
  for (const T& x : xs)
    for (int k = -80; k <= 80; ++k) {
      const T got = mink::detail::timesPow2(x, k), want = std::ldexp(x, k);
      ASSERT_EQ(std::memcmp(&got, &want, sizeof(T) > 10 ? 10 : sizeof(T)), 0)
          << "x = " << static_cast<long double>(x) << ", k = " << k;
      ++checked;
    }
  const T nan = mink::detail::timesPow2(L::quiet_NaN(), 5);
  EXPECT_TRUE(nan != nan);
  EXPECT_GT(checked, 600000);
}

TEST(ScalarTraits, TimesPow2HasTheBitsOfLdexp) {
  expectTimesPow2IsLdexp<float>();
  expectTimesPow2IsLdexp<double>();
  expectTimesPow2IsLdexp<long double>();  // x87: 10 significant bytes
}

}  // namespace
