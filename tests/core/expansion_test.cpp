// tests/core/expansion_test.cpp — the filter's interval and the exact expansion against
// CGAL::Gmpq: an interval encloses the exact value of every operation, whatever the
// magnitudes (zeros, denormals, huge); an expansion's exactValue is the exact value.
#include "mink/core/expansion.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "support/random_doubles.hpp"

namespace {

using mink::detail::Expansion;
using mink::detail::Interval;
using Q = CGAL::Gmpq;

bool encloses(const Interval& i, const Q& x) {
  auto le = [](double a, const Q& b) { return std::isinf(a) ? a < 0 : Q(a) <= b; };
  auto ge = [](double a, const Q& b) { return std::isinf(a) ? a > 0 : Q(a) >= b; };
  return le(i.lo(), x) && ge(i.hi(), x);
}

using mink_test::anyDouble;

// Sums, differences and products of random values, chained: each interval result
// encloses the exact result of the same operations on its exact inputs.
TEST(Interval, EnclosesEveryOperationOverTheRange) {
  std::mt19937 rng(7);
  int decided = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const double a = anyDouble(rng), b = anyDouble(rng), c = anyDouble(rng), d = anyDouble(rng);
    const Interval ia(a), ib(b), ic(c), id(d);
    const Q qa(a), qb(b), qc(c), qd(d);
    const Interval r1 = ia * ib - ic * id, r2 = (ia + ib) * (ic - id), r3 = r1 * r2 + ia;
    const Q e1 = qa * qb - qc * qd, e2 = (qa + qb) * (qc - qd), e3 = e1 * e2 + qa;
    ASSERT_TRUE(encloses(r1, e1)) << a << " " << b << " " << c << " " << d;
    ASSERT_TRUE(encloses(r2, e2)) << a << " " << b << " " << c << " " << d;
    ASSERT_TRUE(encloses(r3, e3)) << a << " " << b << " " << c << " " << d;
    if (r1.excludesZero()) {
      ++decided;
      EXPECT_EQ(r1.certainSign(), CGAL::sign(e1));
    }
    if (ic.excludesZero()) {
      const Q e4 = qa / qc;
      EXPECT_TRUE(encloses(ia / ic, e4));
    }
  }
  EXPECT_GT(decided, 1000);  // the filter decides the generic signs
}

// The long double interval (the trimmer's second filter, core of cpd/detail/trim_corners.hpp
// namedSign): on doubles of the range the trimmer meets, chained products and sums to degree
// 9 enclose the exact value, and a sign it certifies is the exact sign. Its bounds are
// turned into rationals exactly: a long double of this range is the sum of two doubles.
Q exactLongDouble(long double x) {
  const double hi = static_cast<double>(x), lo = static_cast<double>(x - static_cast<long double>(hi));
  EXPECT_EQ(static_cast<long double>(hi) + static_cast<long double>(lo), x);
  return Q(hi) + Q(lo);
}

TEST(Interval, LongDoubleEnclosesDegreeNinePolynomials) {
  using IL = mink::detail::IntervalOf<long double>;
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int decided = 0, decidedOnlyByLongDouble = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<double> v(9);
    for (double& x : v) x = std::ldexp(unit(rng), static_cast<int>(rng() % 60) - 30);
    // Near cancellation, as at a corner close to a cut: v0 v1 v2 against itself plus a
    // perturbation 2^-e smaller (e up to 80), times a degree-6 factor.
    const double tiny = std::ldexp(v[8], -static_cast<int>(rng() % 80));
    auto poly = [&](auto tag) {
      using N = decltype(tag);
      const N a(v[0]), b(v[1]), c(v[2]), d(v[3]), e(v[4]), f(v[5]), g(v[6]), h(v[7]);
      const N cancel = a * b * c - N(v[0]) * N(v[1]) * N(v[2]) + N(tiny) * (a * a + N(1.0));
      return cancel * (d * e * f - g * h * a) * (b + c) + N(tiny) * e;
    };
    const IL r = poly(IL());
    const Q exact = poly(Q());
    ASSERT_LE(exactLongDouble(r.lo()), exact) << trial;
    ASSERT_GE(exactLongDouble(r.hi()), exact) << trial;
    if (r.excludesZero()) {
      ++decided;
      ASSERT_EQ(r.certainSign(), CGAL::sign(exact)) << trial;
      if (!poly(Interval()).excludesZero()) ++decidedOnlyByLongDouble;
    }
  }
  EXPECT_GT(decided, 1000);
  if (std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits) {
    EXPECT_GT(decidedOnlyByLongDouble, 50);  // where long double is wider, it decides more
  }
}

// The product by the signs of the bounds (nine cases, four products only when both hold 0):
// every product of points of the two intervals is inside, and the bounds are the extreme
// endpoint products rounded outward by about an ulp, not wider. Intervals of every sign
// pattern, zeros and infinite bounds included; 0 times an infinite bound is the whole line.
TEST(Interval, ProductOfEverySignPatternIsTheEndpointHull) {
  std::mt19937 rng(23);
  const double inf = std::numeric_limits<double>::infinity();
  auto bound = [&]() {
    switch (rng() % 8) {
      case 0:
        return 0.0;
      case 1:
        return (rng() & 1) ? inf : -inf;
      default:
        return ((rng() & 1) ? 1.0 : -1.0) * std::ldexp(0.5 + (rng() % 1000) / 2000.0, static_cast<int>(rng() % 40) - 20);
    }
  };
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int cases[3][3] = {};
  for (int trial = 0; trial < 20000; ++trial) {
    double a0 = bound(), a1 = bound(), b0 = bound(), b1 = bound();
    if (a0 > a1) std::swap(a0, a1);
    if (b0 > b1) std::swap(b0, b1);
    const Interval a(a0, a1), b(b0, b1), r = a * b;
    const double p[4] = {a0 * b0, a0 * b1, a1 * b0, a1 * b1};
    bool nan = false;
    double lo = inf, hi = -inf;
    for (double x : p) {
      nan = nan || std::isnan(x);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    if (nan) {
      // 0 times an infinite bound: the whole line, or (when the other products settle
      // it) an interval still holding every finite product.
      ASSERT_LE(r.lo(), 0.0) << a0 << " " << a1 << " " << b0 << " " << b1;
      ASSERT_GE(r.hi(), 0.0) << a0 << " " << a1 << " " << b0 << " " << b1;
      continue;
    }
    ++cases[a0 >= 0 ? 0 : (a1 <= 0 ? 1 : 2)][b0 >= 0 ? 0 : (b1 <= 0 ? 1 : 2)];
    const double slack = std::ldexp(1.0, -51);
    ASSERT_LE(r.lo(), lo) << a0 << " " << a1 << " " << b0 << " " << b1;
    ASSERT_GE(r.hi(), hi) << a0 << " " << a1 << " " << b0 << " " << b1;
    if (std::isfinite(lo)) {
      ASSERT_GE(r.lo(), lo - std::abs(lo) * slack - 1e-300) << a0 << " " << a1 << " " << b0 << " " << b1;
    }
    if (std::isfinite(hi)) {
      ASSERT_LE(r.hi(), hi + std::abs(hi) * slack + 1e-300) << a0 << " " << a1 << " " << b0 << " " << b1;
    }
    // Points inside, multiplied exactly: inside the product.
    if (std::isfinite(a0) && std::isfinite(a1) && std::isfinite(b0) && std::isfinite(b1)) {
      const double x = a0 + (a1 - a0) * unit(rng), y = b0 + (b1 - b0) * unit(rng);
      if (x >= a0 && x <= a1 && y >= b0 && y <= b1) {
        ASSERT_TRUE(encloses(r, Q(x) * Q(y))) << x << " " << y;
      }
    }
  }
  for (auto& row : cases)
    for (int n : row) EXPECT_GT(n, 100);  // every sign pattern was met
}

// A tie is never decided: a value that is exactly 0 gives an interval holding 0.
TEST(Interval, NeverDecidesAnExactZero) {
  const Interval x(0.1), y(0.3), z(0.7);
  const Interval zero = x * y * z - z * y * x;
  EXPECT_FALSE(zero.excludesZero());
  EXPECT_EQ(zero.certainSign(), 0);
}

// Exact zeros stay exact: x − x and products with a zero factor are the point 0, not
// ±(least normal), so that the planes of axis-aligned meshes (normals and coordinates
// with zeros, in double and in long double) never carry a bound whose products are
// denormal (a microcode assist each on x86). The same enclosure holds: a zero that is
// not exact (an underflowed product) is still widened.
template <class F>
void expectExactZerosStayExact() {
  using I = mink::detail::IntervalOf<F>;
  auto isPointZero = [](const I& x) { return x.lo() == F(0) && x.hi() == F(0); };
  auto noDenormalBound = [](const I& x) {
    return std::fpclassify(x.lo()) != FP_SUBNORMAL && std::fpclassify(x.hi()) != FP_SUBNORMAL;
  };
  const I x(F(0.3)), y(F(-0.7)), z(F(0.1)), zero(F(0));
  EXPECT_TRUE(isPointZero(x - x));
  EXPECT_TRUE(isPointZero(x + (-x)));
  EXPECT_TRUE(isPointZero(zero * y));
  EXPECT_TRUE(isPointZero((x - x) * y));
  EXPECT_TRUE(isPointZero(zero + zero));
  // A cross product of axis-aligned edges, its components dotted with a point: where the
  // widened zeros met numbers below 1, every bound of the chain was denormal.
  const I d1[3] = {x - x, y - z, zero}, d2[3] = {z, zero, x - x};
  const I c[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  for (const I& ci : c) EXPECT_TRUE(noDenormalBound(ci * z * z));
  EXPECT_TRUE(isPointZero(c[0]));
  EXPECT_TRUE(isPointZero(c[1]));
  // Underflow is not exact: a product of two tiny numbers rounded to 0 is still widened.
  const F tiny = std::numeric_limits<F>::min();
  const I under = I(tiny) * I(tiny);
  EXPECT_LT(under.lo(), F(0));
  EXPECT_GT(under.hi(), F(0));
  // Nor is a sum that is 0 only because its operands are not opposite: none is, with
  // gradual underflow; x − y for x != y is never 0 then, so the test is of the rule's form.
  const I near = I(F(1.5) * tiny) - I(tiny);
  EXPECT_GT(near.hi(), F(0));
}

TEST(Interval, ExactZerosStayExact) {
  expectExactZerosStayExact<double>();
  expectExactZerosStayExact<long double>();
}

#if defined(__SSE2__)
// With flush-to-zero on (engines set it for speed), a difference of two different
// numbers can come out 0: that zero is not exact, and the interval still holds the value.
TEST(Interval, FlushToZeroDifferenceIsNotTakenForAnExactZero) {
  const unsigned saved = _MM_GET_FLUSH_ZERO_MODE();
  _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
  volatile double a = 1.5 * std::numeric_limits<double>::min(), b = std::numeric_limits<double>::min();
  const Interval d = Interval(a) - Interval(b), s = Interval(a) + Interval(-b);
  _MM_SET_FLUSH_ZERO_MODE(saved);
  const Q exact = Q(1.5 * std::numeric_limits<double>::min()) - Q(std::numeric_limits<double>::min());
  EXPECT_TRUE(encloses(d, exact));
  EXPECT_TRUE(encloses(s, exact));
}
#endif

// dotSignByRadius (the trimming's first filter) claims a sign only where every choice of
// values in the intervals has it: Σ a_i b_i is multilinear, so its extremes over the box
// of intervals are at the box's corners, each checked in Q. Inputs: narrow intervals (the
// filter's use) and points, over the whole range (denormal to huge), half of them made to
// cancel to within a few ulps; with flush-to-zero on as well as off (SSE2). The filter
// must also decide: most clear cases, and never an exact zero.
void expectDotSignByRadiusIsSound(bool flushToZero) {
  using mink::detail::dotSignByRadius;
  std::mt19937 rng(flushToZero ? 29 : 23);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int claimed = 0, clear = 0, clearClaimed = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const int n = 1 + trial % 4;
    const int scale = trial % 5 == 0 ? static_cast<int>(rng() % 2000) - 1000 : static_cast<int>(rng() % 60) - 30;
    double m[8];
    for (int i = 0; i < 2 * n; ++i) m[i] = trial % 7 == 0 ? anyDouble(rng) : std::ldexp(unit(rng), scale);
    const bool cancel = trial % 2 == 1 && n > 1;
    if (cancel) {  // the last product cancels the others to within a few ulps
      double rest = 0;
      for (int i = 0; i + 1 < n; ++i) rest += m[i] * m[n + i];
      if (m[n - 1] != 0) m[2 * n - 1] = -rest / m[n - 1] * (1 + std::ldexp(double(rng() % 9) - 4, -52));
    }
    Interval a[4], b[4];
    for (int i = 0; i < n; ++i) {
      const int wa = static_cast<int>(rng() % 60), wb = static_cast<int>(rng() % 60);
      const double da = wa < 8 ? 0 : std::abs(m[i]) * std::ldexp(unit(rng), -wa);
      const double db = wb < 8 ? 0 : std::abs(m[n + i]) * std::ldexp(unit(rng), -wb);
      a[i] = Interval(std::min(m[i], m[i] + da), std::max(m[i], m[i] + da));
      b[i] = Interval(std::min(m[n + i], m[n + i] - db), std::max(m[n + i], m[n + i] - db));
    }
    bool finite = true;
    for (int i = 0; i < n; ++i)
      finite = finite && std::isfinite(a[i].lo()) && std::isfinite(a[i].hi()) && std::isfinite(b[i].lo()) && std::isfinite(b[i].hi());
    if (!finite) continue;  // (the rational reference takes finite numbers)
#if defined(__SSE2__)
    const unsigned saved = _MM_GET_FLUSH_ZERO_MODE();
    if (flushToZero) _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
#endif
    const int s = dotSignByRadius(a, b, n);
#if defined(__SSE2__)
    _MM_SET_FLUSH_ZERO_MODE(saved);
#endif
    int lo = 2, hi = -2;  // the least and greatest sign over the corners
    for (int c = 0; c < (1 << (2 * n)); ++c) {
      Q v(0);
      for (int i = 0; i < n; ++i)
        v += Q((c >> i) & 1 ? a[i].hi() : a[i].lo()) * Q((c >> (n + i)) & 1 ? b[i].hi() : b[i].lo());
      lo = std::min(lo, static_cast<int>(CGAL::sign(v)));
      hi = std::max(hi, static_cast<int>(CGAL::sign(v)));
    }
    if (s != 0) {
      ++claimed;
      ASSERT_TRUE(lo == s && hi == s) << "trial " << trial << ": claimed " << s << ", corners " << lo << " .. " << hi;
    }
    if (!cancel && lo == hi && lo != 0 && trial % 7 != 0) {
      ++clear;
      clearClaimed += s != 0;
    }
  }
  EXPECT_GT(claimed, 300);
  EXPECT_GT(clearClaimed, clear * 4 / 5) << clearClaimed << " of " << clear << " clear cases decided";
  const Interval z[2] = {Interval(0.1), Interval(0.3)}, w[2] = {Interval(0.3), Interval(-0.1)};
  EXPECT_EQ(dotSignByRadius(z, w, 2), 0);  // 0.1 · 0.3 − 0.3 · 0.1 = 0 exactly
}

TEST(Interval, DotSignByRadiusIsTheSignAtEveryCorner) {
  expectDotSignByRadiusIsSound(false);
#if defined(__SSE2__)
  expectDotSignByRadiusIsSound(true);
#endif
}

// exactValue: the compressed expansion, summed in Q, equals the value of the same
// polynomial evaluated in Q; its sign is the expansion's.
TEST(Expansion, ExactValueMatchesRationalArithmetic) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> v(6);
    for (double& x : v) x = std::ldexp(unit(rng), static_cast<int>(rng() % 200) - 100);
    Expansion e(0.0);
    Q q(0);
    // A degree-6 sum of products with cancellation: (v0 v1 v2 − v3 v4 v5)(v0 + v3) + v1 v4.
    e = (Expansion(v[0]) * v[1] * v[2] - Expansion(v[3]) * v[4] * v[5]) * (Expansion(v[0]) + v[3]) +
        Expansion(v[1]) * v[4];
    q = (Q(v[0]) * v[1] * v[2] - Q(v[3]) * v[4] * v[5]) * (Q(v[0]) + v[3]) + Q(v[1]) * v[4];
    ASSERT_EQ(e.exactValue<Q>(), q) << trial;
    EXPECT_EQ(e.sign(), CGAL::sign(q));
  }
  // Exact cancellation to 0 and a value of one component.
  const Expansion zero = Expansion(0.1) * 0.3 - Expansion(0.3) * 0.1;
  EXPECT_EQ(zero.exactValue<Q>(), Q(0));
  EXPECT_EQ(Expansion(0.25).exactValue<Q>(), Q(0.25));
}

// Expansions longer than the inline buffer (kExpansionInline components) move to the
// heap and stay exact: sums of numbers 2^54 apart in exponent keep one component each, so
// products of such sums have many (within the exponent range: no overflow or underflow);
// copies, moves and swaps of long and short expansions keep their values.
TEST(Expansion, LongExpansionsLeaveTheInlineBufferAndStayExact) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> mant(1.0, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    Expansion a(0.0), b(0.0);
    Q qa(0), qb(0);
    for (int k = 0; k < 16; ++k) {
      const double x = std::ldexp(mant(rng), 54 * k - 432), y = std::ldexp(mant(rng), 54 * k - 430);
      a = a + x;
      b = b - y;
      qa = qa + x;
      qb = qb - y;
    }
    ASSERT_EQ(a.exactValue<Q>(), qa);
    const Expansion p = a * b, sq = p * (Expansion(0.1) + 0.3);  // hundreds of components
    const Q qp = qa * qb, qsq = qp * (Q(0.1) + Q(0.3));
    ASSERT_EQ(p.exactValue<Q>(), qp) << trial;
    ASSERT_EQ(sq.exactValue<Q>(), qsq) << trial;
    Expansion c = sq;           // copy of a long one
    Expansion d = std::move(c);  // move of a long one
    Expansion e(0.5);
    e = d;                       // a short one assigned a long one
    d = Expansion(0.25);         // a long one assigned a short one
    EXPECT_EQ(e.exactValue<Q>(), qsq);
    EXPECT_EQ(d.exactValue<Q>(), Q(0.25));
    EXPECT_EQ((e - sq).sign(), 0);
    EXPECT_EQ((a + 0.0).exactValue<Q>(), qa);
  }
  mink::detail::SmallBuffer<double, 4> s, t;
  for (int i = 0; i < 10; ++i) s.push_back(i);
  t.push_back(-1);
  s.swap(t);
  ASSERT_EQ(s.size(), 1u);
  ASSERT_EQ(t.size(), 10u);
  EXPECT_EQ(s[0], -1.0);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(t[static_cast<std::size_t>(i)], double(i));
  t.resize(3);
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(t.back(), 2.0);
  t.clear();
  EXPECT_TRUE(t.empty());
}

}  // namespace
