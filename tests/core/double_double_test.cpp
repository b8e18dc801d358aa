// tests/core/double_double_test.cpp — the double-double interval (the trimmer's second
// filter, cpd/detail/trim_corners.hpp namedSign) against CGAL::Gmpq: every operation's
// interval holds the exact value, over the whole range of doubles; a sign it certifies is
// the exact sign; it certifies the near-cancellations of degree 9 that double and long
// double intervals leave to the expansions; an overflow certifies nothing.
#include "mink/core/double_double.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "mink/core/expansion.hpp"
#include "support/random_doubles.hpp"

namespace {

using DDI = mink::detail::DoubleDoubleInterval;
using Q = CGAL::Gmpq;

// Does [hi + lo − r, hi + lo + r] hold x? Only asked of finite intervals.
bool holds(const DDI& i, const Q& x) {
  const Q mid = Q(i.hi()) + Q(i.lo());
  return mid - Q(i.radius()) <= x && x <= mid + Q(i.radius());
}

bool finite(const DDI& i) { return std::isfinite(i.hi()) && std::isfinite(i.lo()) && std::isfinite(i.radius()); }

using mink_test::anyDouble;

TEST(DoubleDouble, TwoSumAndTwoProdAreExact) {
  ASSERT_TRUE(mink::detail::kDoubleDoubleExact) << "this target evaluates doubles in a wider format";
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    // Products inside the range where Dekker's product is exact (no overflow of the split,
    // no low part below the subnormals).
    const double a = std::ldexp(unit(rng), static_cast<int>(rng() % 400) - 200);
    const double b = std::ldexp(unit(rng), static_cast<int>(rng() % 400) - 200);
    double s, e, p, f;
    mink::detail::twoSum(a, b, s, e);
    mink::detail::twoProd(a, b, p, f);
    ASSERT_EQ(Q(s) + Q(e), Q(a) + Q(b)) << a << " " << b;
    ASSERT_EQ(Q(p) + Q(f), Q(a) * Q(b)) << a << " " << b;
    ASSERT_EQ(s, a + b);
    ASSERT_EQ(p, a * b);
  }
}

// Sums, differences and products of random values over the whole range, chained: each
// result holds the exact result of the same operations on the exact inputs (where it is
// finite), and a certified sign is the exact sign.
TEST(DoubleDouble, HoldsEveryOperationOverTheRange) {
  std::mt19937 rng(7);
  int decided = 0, checked = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const double a = anyDouble(rng), b = anyDouble(rng), c = anyDouble(rng), d = anyDouble(rng);
    const DDI ia(a), ib(b), ic(c), id(d);
    const Q qa(a), qb(b), qc(c), qd(d);
    const DDI r[4] = {ia * ib - ic * id, (ia + ib) * (ic - id), (ia * ib - ic * id) * ((ia + ib) * (ic - id)) + ia,
                      -(ia - ib) * (ia - ib) * (ic + id)};
    const Q e1 = qa * qb - qc * qd, e2 = (qa + qb) * (qc - qd);
    const Q e[4] = {e1, e2, e1 * e2 + qa, -(qa - qb) * (qa - qb) * (qc + qd)};
    for (int k = 0; k < 4; ++k) {
      if (!finite(r[k])) {
        EXPECT_EQ(r[k].certainSign(), 0) << a << " " << b << " " << c << " " << d;
        continue;
      }
      ++checked;
      ASSERT_TRUE(holds(r[k], e[k])) << k << ": " << a << " " << b << " " << c << " " << d;
      if (const int sg = r[k].certainSign()) {
        ++decided;
        ASSERT_EQ(sg, CGAL::sign(e[k])) << k << ": " << a << " " << b << " " << c << " " << d;
      }
    }
  }
  EXPECT_GT(checked, 15000);
  EXPECT_GT(decided, 8000);
}

// Values of degree 9 that cancel to about 2^-drop of their terms (drop up to 110), as at
// a corner of the trimming within a rounding of a cut: never a wrong sign, and every one
// above 2^-90 of its terms is told, the many the double and long double intervals leave to
// the expansions among them.
TEST(DoubleDouble, TellsDegreeNineCancellationsTheOtherIntervalsCannot) {
  using IL = mink::detail::IntervalOf<long double>;
  using IV = mink::detail::Interval;
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int decided = 0, onlyHere = 0, above = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<double> v(9);
    for (double& x : v) x = std::ldexp(unit(rng), static_cast<int>(rng() % 60) - 30);
    const int drop = static_cast<int>(rng() % 110);
    const double tiny = std::ldexp(v[8], std::ilogb(v[0]) + std::ilogb(v[1]) + std::ilogb(v[2]) - drop);
    auto poly = [&](auto tag) {
      using N = decltype(tag);
      const N a(v[0]), b(v[1]), c(v[2]), d(v[3]), e(v[4]), f(v[5]), g(v[6]), h(v[7]);
      const N cancel = a * b * c - N(v[0]) * N(v[1]) * N(v[2]) + N(tiny) * (a * a + N(1.0));
      return cancel * (d * e * f - g * h * a) * (b + c) + N(tiny) * e;
    };
    // The size of the terms (their absolute values added up).
    const double F =
        (std::fabs(v[3] * v[4] * v[5]) + std::fabs(v[6] * v[7] * v[0])) * (std::fabs(v[1]) + std::fabs(v[2]));
    const double terms =
        (2 * std::fabs(v[0] * v[1] * v[2]) + std::fabs(tiny) * (v[0] * v[0] + 1)) * F + std::fabs(tiny * v[4]);
    const DDI r = poly(DDI());
    const Q exact = poly(Q());
    ASSERT_TRUE(finite(r));
    ASSERT_TRUE(holds(r, exact)) << trial;
    const int sg = r.certainSign();
    if (sg != 0) {
      ++decided;
      ASSERT_EQ(sg, CGAL::sign(exact)) << trial;
      if (!poly(IV()).excludesZero() && !poly(IL()).excludesZero()) ++onlyHere;
    }
    if (CGAL::abs(exact) >= Q(std::ldexp(terms, -90))) {
      ++above;
      EXPECT_NE(sg, 0) << "a value " << CGAL::to_double(exact) << " of terms " << terms << ", trial " << trial;
    }
  }
  EXPECT_GT(decided, 2000);
  EXPECT_GT(onlyHere, 500);
  EXPECT_GT(above, 2000);
}

// An exact zero is never given a sign; an overflow, an infinity or a NaN certifies nothing.
TEST(DoubleDouble, ZeroOverflowAndNanCertifyNothing) {
  const DDI a(3.0), b(1.0 / 3.0);
  EXPECT_EQ((a * b - a * b).certainSign(), 0);
  EXPECT_EQ((DDI(0.1) * DDI(0.3) - DDI(0.3) * DDI(0.1)).certainSign(), 0);
  EXPECT_EQ((DDI(1e300) * DDI(1e300)).certainSign(), 0);
  EXPECT_EQ((DDI(1e300) * DDI(1e300) - DDI(1e300) * DDI(1e300)).certainSign(), 0);
  EXPECT_EQ((DDI(1e308) + DDI(1e308)).certainSign(), 0);
  EXPECT_EQ(DDI(std::numeric_limits<double>::infinity()).certainSign(), 0);
  EXPECT_EQ((DDI(std::numeric_limits<double>::quiet_NaN()) + DDI(1.0)).certainSign(), 0);
  EXPECT_EQ((DDI(std::numeric_limits<double>::infinity()) * DDI(0.0)).certainSign(), 0);
  // A sign is still told where the value is far from the limits.
  EXPECT_EQ((DDI(1e150) * DDI(1e150) - DDI(1.0)).certainSign(), 1);
  EXPECT_EQ((DDI(0.1) * DDI(0.3) - DDI(0.03)).certainSign(), CGAL::sign(Q(0.1) * Q(0.3) - Q(0.03)));
}

}  // namespace
