// Tests of mink/core/orientation.hpp: orient3d(a, b, c, d) is the exact sign of
// det[b - a, c - a, d - a] of the given numbers, orient2d(a, b, c) that of
// (b - a) x (c - a) in the plane. References: the 3-D determinant in exact rational
// arithmetic (CGAL::Gmpq) from the exact values of the inputs; for orient2d, CGAL's own
// exact predicate CGAL::orientation on Simple_cartesian<Gmpq> points.
// Inputs are chosen to reach the exact fallback: points on (or within a few ulps of) a
// plane through three others (a line through two others), collinear and coincident
// points, at extreme scales.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include "mink/core/orientation.hpp"
#include "support/to_rational.hpp"

namespace {

using mink::Vec3;
using Q = CGAL::Gmpq;

using mink_test::toQ;
using mink_test::toQ3;

template <class T>
int exactSign(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
  const Vec3<Q> A = toQ3(a), B = toQ3(b), C = toQ3(c), D = toQ3(d);
  const Q det = (B - A).dot((C - A).cross(D - A));
  return CGAL::sign(det);
}

long double ld(const Q& x) { return CGAL::to_double(x); }
template <class T>
long double ld(const T& x) {
  return static_cast<long double>(x);
}
template <class T>
std::string str(const Vec3<T>& p) {
  std::ostringstream os;
  os.precision(21);
  os << "(" << ld(p[0]) << ", " << ld(p[1]) << ", " << ld(p[2]) << ")";
  return os.str();
}

// Compares orient3d with the exact sign and with the sign rules of a determinant (odd
// permutations flip it). Returns the exact sign.
template <class T>
int expectExact(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d, const std::string& what,
                int& failures) {
  const int want = exactSign(a, b, c, d);
  const int got = mink::orient3d(a, b, c, d);
  const int swapped = mink::orient3d(b, a, c, d);
  // The expansion-arithmetic fallback on its own (the filter decides most inputs
  // before reaching it).
  int expansion = want;
  if constexpr (std::is_same<T, double>::value || std::is_same<T, long double>::value)
    expansion = mink::detail::exactOrient3d(a, b, c, d);
  if ((got != want || swapped != -want || expansion != want) && failures++ < 8)
    ADD_FAILURE() << what << ": orient3d = " << got << ", swapped " << swapped << ", exactOrient3d " << expansion
                  << ", exact sign " << want << "\n  a=" << str(a) << "\n  b=" << str(b) << "\n  c=" << str(c)
                  << "\n  d=" << str(d);
  return want;
}

template <class T>
T randomValue(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  if constexpr (std::is_same<T, long double>::value) {
    // Use all 64 mantissa bits.
    return static_cast<long double>(u(rng)) + static_cast<long double>(u(rng)) * std::ldexp(1.0L, -40);
  } else {
    return static_cast<T>(u(rng));
  }
}

template <class T>
Vec3<T> randomPoint(std::mt19937& rng, double lo = -1.0, double hi = 1.0) {
  return Vec3<T>(randomValue<T>(rng, lo, hi), randomValue<T>(rng, lo, hi), randomValue<T>(rng, lo, hi));
}

template <class T>
class Orient3d : public ::testing::Test {};
using Floats = ::testing::Types<float, double, long double>;
TYPED_TEST_SUITE(Orient3d, Floats);

TYPED_TEST(Orient3d, GenericPoints) {
  using T = TypeParam;
  const unsigned seed = 9101u;
  std::mt19937 rng(seed);
  int failures = 0;
  for (int i = 0; i < 10000; ++i) {
    const auto a = randomPoint<T>(rng), b = randomPoint<T>(rng), c = randomPoint<T>(rng), d = randomPoint<T>(rng);
    expectExact(a, b, c, d, "seed 9101 generic #" + std::to_string(i), failures);
  }
  EXPECT_EQ(failures, 0);
}

TYPED_TEST(Orient3d, NearlyCoplanar) {
  using T = TypeParam;
  const unsigned seed = 9102u;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> st(-2.0, 2.0);
  int failures = 0, zeros = 0, nonzeros = 0;
  for (int i = 0; i < 10000; ++i) {
    const auto a = randomPoint<T>(rng, -10, 10), b = randomPoint<T>(rng, -10, 10), c = randomPoint<T>(rng, -10, 10);
    const T s = T(st(rng)), t = T(st(rng));
    // d on the plane up to the rounding of this expression: |det| tiny or zero.
    const Vec3<T> d = a + (b - a) * s + (c - a) * t;
    const int e = expectExact(a, b, c, d, "seed 9102 nearly coplanar #" + std::to_string(i), failures);
    (e == 0 ? zeros : nonzeros)++;
  }
  EXPECT_EQ(failures, 0);
  // Rounding d almost always leaves it just off the plane (|det| far below the fast
  // filter's error bound, so the exact path decides); exact zeros are covered by the
  // degenerate and ulp-grid tests.
  std::printf("    nearly coplanar: %d exact zeros, %d non-zero\n", zeros, nonzeros);
  EXPECT_GT(nonzeros, 0);
}

TYPED_TEST(Orient3d, UlpPerturbationsOfAPlane) {
  using T = TypeParam;
  int failures = 0, signs[3] = {0, 0, 0};
  // Plane x + y + z = 1 through three exactly representable points; d = an exact point
  // of it, then moved by -3..3 ulps in each coordinate (Shewchuk's test pattern).
  const Vec3<T> a(T(1), T(0), T(0)), b(T(0), T(1), T(0)), c(T(0), T(0), T(1));
  for (const Vec3<T>& base : {Vec3<T>(T(0.25), T(0.5), T(0.25)), Vec3<T>(T(0.375), T(0.125), T(0.5)),
                             Vec3<T>(T(-3), T(2.5), T(1.5)), Vec3<T>(T(1024), T(-1000), T(-23))}) {
    for (int i = -3; i <= 3; ++i)
      for (int j = -3; j <= 3; ++j)
        for (int k = -3; k <= 3; ++k) {
          Vec3<T> d = base;
          const int steps[3] = {i, j, k};
          for (int q = 0; q < 3; ++q)
            for (int n = 0; n < std::abs(steps[q]); ++n)
              d[q] = std::nextafter(d[q], steps[q] > 0 ? std::numeric_limits<T>::infinity()
                                                       : -std::numeric_limits<T>::infinity());
          const int e = expectExact(a, b, c, d, "ulp grid (" + std::to_string(i) + "," + std::to_string(j) + "," +
                                                    std::to_string(k) + ") around " + str(base),
                                    failures);
          ++signs[e + 1];
        }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(signs[0], 0);
  EXPECT_GT(signs[1], 0);
  EXPECT_GT(signs[2], 0);
}

TYPED_TEST(Orient3d, DegenerateConfigurations) {
  using T = TypeParam;
  const unsigned seed = 9104u;
  std::mt19937 rng(seed);
  int failures = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto a = randomPoint<T>(rng), b = randomPoint<T>(rng);
    // Coincident points and exact dyadic points on the line ab (midpoint, reflection
    // when exact): the determinant is 0 whatever c is.
    const auto c = randomPoint<T>(rng);
    EXPECT_EQ(mink::orient3d(a, a, c, b), 0);
    EXPECT_EQ(mink::orient3d(a, b, c, c), 0);
    EXPECT_EQ(mink::orient3d(a, b, a, c), 0);
    const Vec3<T> m = (a + b) / T(2);  // rounded: usually off the line by an ulp
    expectExact(a, b, m, c, "seed 9104 midpoint #" + std::to_string(i), failures);
    expectExact(a, m, b, c, "seed 9104 midpoint (2) #" + std::to_string(i), failures);
  }
  // Integer points exactly on a plane, at a scale where the naive determinant
  // cancels catastrophically: 2^k (x, y, 3x - 2y + 5) with large k.
  std::uniform_int_distribution<int> small(-1000, 1000);
  for (int i = 0; i < 2000; ++i) {
    Vec3<T> p[4];
    for (auto& q : p) {
      const int x = small(rng), y = small(rng);
      q = Vec3<T>(T(x), T(y), T(3 * x - 2 * y + 5));
    }
    EXPECT_EQ(exactSign(p[0], p[1], p[2], p[3]), 0);
    expectExact(p[0], p[1], p[2], p[3], "seed 9104 integer coplanar #" + std::to_string(i), failures);
  }
  EXPECT_EQ(failures, 0);
}

TYPED_TEST(Orient3d, ExtremeScales) {
  using T = TypeParam;
  const unsigned seed = 9105u;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> st(-2.0, 2.0);
  int failures = 0;
  // Scaling by a power of two is exact and keeps the sign; stay inside the documented
  // range (about 1e-90 .. 1e90 for double; float's own range for float).
  const int emax = std::is_same<T, float>::value ? 30 : 250;
  for (int e : {-emax, -emax / 2, 0, emax / 2, emax}) {
    for (int i = 0; i < 2000; ++i) {
      const auto a = randomPoint<T>(rng), b = randomPoint<T>(rng), c = randomPoint<T>(rng);
      const T s = T(st(rng)), t = T(st(rng));
      Vec3<T> d = a + (b - a) * s + (c - a) * t;
      Vec3<T> pts[4] = {a, b, c, d};
      for (auto& q : pts)
        for (int k = 0; k < 3; ++k) q[k] = std::ldexp(q[k], e);
      expectExact(pts[0], pts[1], pts[2], pts[3], "seed 9105 scale 2^" + std::to_string(e) + " #" + std::to_string(i),
                  failures);
    }
  }
  EXPECT_EQ(failures, 0);
}

// Coordinates far below the others (1e-300, DBL_MIN, denormals beside coordinates of size
// 1): the double expansion's products of three differences underflow, and orient3d must
// still give the exact sign (it then works in long double; see the header). Points on the
// plane z = 0 (exactly, in random coordinates), with tiny z's put on some of them so that
// the sign is decided by those alone. Regression of fuzz/regressions/tiny_coordinate_*.
TEST(Orient3dExact, TinyCoordinatesBesideUnitOnes) {
  std::mt19937 rng(9107u);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const double tiny[] = {1e-300, -3e-305, std::numeric_limits<double>::min(), 1e-310,
                         std::numeric_limits<double>::denorm_min(), 7e-200, -1e-95, 0.0};
  std::uniform_int_distribution<int> pick(0, 7), axis(0, 2);
  int failures = 0;
  for (int i = 0; i < 4000; ++i) {
    Vec3<double> p[4];
    const int k = axis(rng);  // the plane x_k = 0
    for (auto& q : p) {
      q = Vec3<double>(u(rng), u(rng), u(rng));
      q[k] = tiny[pick(rng)];
    }
    if (i % 3 == 0) p[3] = p[0];  // duplicates too
    expectExact(p[0], p[1], p[2], p[3], "seed 9107 #" + std::to_string(i), failures);
  }
  EXPECT_EQ(failures, 0);
}

// Coordinates spread over the whole double range at once (2^-1074 beside 2^290, the mesh
// fuzzer's needle boxes: fuzz/regressions_mesh/needle_box_2e81_subnormal_exact_stage),
// where nothing cancels and the exact stage keeps nearly all of its 192 terms: in double
// (which moves to long double for the range) and in long double, generic, coplanar
// (z = 0), repeated and one-ulp-off points, against Gmpq. The terms are summed as a tree of
// linear merges (the same signs as growing one expansion term by term, 5x faster here).
TEST(Orient3dExact, CoordinatesAcrossTheWholeRange) {
  std::mt19937 rng(9110u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> ex(-1074, 290), mode(0, 4);
  int failures = 0;
  for (int i = 0; i < 3000; ++i) {
    Vec3<double> p[4];
    const int m = mode(rng);
    for (auto& q : p)
      for (int k = 0; k < 3; ++k) q[k] = m == 1 && k == 2 ? 0.0 : std::ldexp(u(rng), ex(rng));
    if (m == 2) p[3] = p[i % 3];
    if (m == 3) p[3][0] = std::nextafter(p[1][0], 1.0), p[3][1] = p[1][1], p[3][2] = p[1][2];
    if (m == 4) p[3] = p[0] + 0.5 * (p[1] - p[0]);  // near the line, rounded
    const std::string what = "seed 9110 mode " + std::to_string(m) + " #" + std::to_string(i);
    expectExact(p[0], p[1], p[2], p[3], what, failures);
    Vec3<long double> l[4];
    for (int k = 0; k < 4; ++k) l[k] = p[k].cast<long double>();
    expectExact(l[0], l[1], l[2], l[3], what + " in long double", failures);
  }
  EXPECT_EQ(failures, 0);
}

// twoProduct in long double: Dekker's product of halves inside 2^±(emax/2 - digits), the
// fma outside (glibc's fmal: exact, and the reference here), zero where a factor is zero.
TEST(TwoProduct, LongDoubleIsExactAcrossItsExponentRange) {
  using L = long double;
  std::mt19937 rng(9111u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int emax = std::numeric_limits<L>::max_exponent, emin = std::numeric_limits<L>::min_exponent;
  std::uniform_int_distribution<int> ex(emin, emax - 2);
  int failures = 0;
  for (int i = 0; i < 20000; ++i) {
    const L a = std::ldexp(static_cast<L>(u(rng)) + static_cast<L>(u(rng)) * 0x1p-40L, ex(rng));
    // b's exponent keeps a * b inside the normal range (edges included).
    const int ea = std::ilogb(a);
    int lo = std::max(emin, emin + 70 - ea), hi = std::min(emax - 2, emax - 3 - ea);
    if (i % 4 == 0) lo = hi = emax / 2 - std::numeric_limits<L>::digits + (i % 8 == 0 ? 1 : 0);  // at the guard
    if (lo > hi) continue;
    const L b = i % 97 == 0 ? L(0) : std::ldexp(static_cast<L>(u(rng)), std::uniform_int_distribution<int>(lo, hi)(rng));
    L x, y;
    mink::detail::twoProduct(a, b, x, y);
    const L want = std::fma(a, b, -x);
    if ((x != a * b || y != want) && failures++ < 8)
      ADD_FAILURE() << "exponents " << std::ilogb(a) << ", " << std::ilogb(b) << ": low part " << static_cast<double>(y) << " vs fma " << static_cast<double>(want);
  }
  EXPECT_EQ(failures, 0);
}

// accurateCross: the direction of (b - a) x (c - a) to about one ulp of its length, for
// sliver triangles whose width is far below the rounding of their coordinates' low parts
// (a 2^-1022-wide face beside coordinates of size 1 came out with the normal (0, 1, 0)
// instead of (-3, 1, 0)/sqrt(10); fuzz/regressions/sliver_face_normal_lost_in_corrections).
// Reference: the exact cross product in Gmpq.
TEST(AccurateCross, SliverTrianglesKeepTheirDirection) {
  std::mt19937 rng(9108u);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  const double widths[] = {1e-3, 1e-12, 1e-20, 1e-100, 1e-300, std::numeric_limits<double>::min(), 1e-310,
                           std::numeric_limits<double>::denorm_min()};
  int failures = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3<double> a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    // c: b nudged off the line a-b by a tiny width along a random axis.
    Vec3<double> c = b;
    c[i % 3] += widths[(i / 3) % 8];
    if (c == b) continue;
    // With the exponent: the vector itself is below the double range for the last ones.
    int e = 0;
    const Vec3<double> n = mink::accurateCross(a, b, c, &e);
    const Vec3<Q> x = (toQ3(b) - toQ3(a)).cross(toQ3(c) - toQ3(a));
    // Scaled exactly to a largest component of 1 first (it may be below the double range).
    Q big(0);
    for (int k = 0; k < 3; ++k) big = std::max(big, CGAL::abs(x[k]));
    const Vec3<double> ed(CGAL::to_double(x[0] / big), CGAL::to_double(x[1] / big), CGAL::to_double(x[2] / big));
    // Compare directions, each scaled to unit length without underflow.
    const double err = (n / n.stableNorm() - ed / ed.stableNorm()).norm();
    if (!(err <= 1e-14) && failures++ < 5)
      ADD_FAILURE() << "seed 9108 #" << i << ": direction off by " << err << "; n " << n.transpose() << ", exact "
                    << ed.transpose();
  }
  EXPECT_EQ(failures, 0);
  // The fuzzer's case, by hand: (b - a) x (c - a) = d (-3 - 2^-52, 1, 0) for d = 2^-1022.
  const double d = std::numeric_limits<double>::min();
  const Vec3<double> n =
      mink::accurateCross(Vec3<double>(-1, 1 + std::ldexp(1.0, -52), -2), Vec3<double>(-2, -2, 0), Vec3<double>(-2, -2, d));
  EXPECT_EQ(n[2], 0.0);
  EXPECT_NEAR(n[0] / n[1], -3.0, 1e-15);
  // A triangle one denormal wide (fuzz/regressions/face_normal_of_denormal_width): the
  // cross product is denorm_min * (0, 1 + dm, 0.5 - dm), below the double range unless
  // scaled; its direction must be (0, 2, 1) / sqrt(5).
  const double dm = std::numeric_limits<double>::denorm_min();
  int e = 0;
  const Vec3<double> m = mink::accurateCross(Vec3<double>(-2, 0.5, -1), Vec3<double>(0, dm, dm), Vec3<double>(dm, dm, dm), &e);
  EXPECT_LT((m / m.stableNorm() - Vec3<double>(0, 2, 1) / std::sqrt(5.0)).norm(), 1e-15) << m.transpose() << " 2^" << e;
}

TEST(Orient3dExact, Gmpq) {
  const unsigned seed = 9106u;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> num(-1000, 1000), den(1, 99);
  auto rnd = [&] { return Q(num(rng), den(rng)); };
  int failures = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3<Q> a(rnd(), rnd(), rnd()), b(rnd(), rnd(), rnd()), c(rnd(), rnd(), rnd());
    const Vec3<Q> d(rnd(), rnd(), rnd());
    expectExact(a, b, c, d, "seed 9106 generic #" + std::to_string(i), failures);
    // Exactly on the plane: 0.
    const Vec3<Q> e = a + (b - a) * rnd() + (c - a) * rnd();
    EXPECT_EQ(mink::orient3d(a, b, c, e), 0) << "seed 9106 coplanar #" << i;
    expectExact(a, b, c, Vec3<Q>(e + Vec3<Q>(Q(0), Q(0), Q(1, 1000000007))), "seed 9106 just off #" + std::to_string(i),
                failures);
  }
  EXPECT_EQ(failures, 0);
}

TEST(Orient3dExact, SignConvention) {
  // d on the side (b - a) x (c - a) points to is positive.
  const Vec3<double> a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(mink::orient3d(a, b, c, Vec3<double>(0.3, 0.3, 1e-30)), 1);
  EXPECT_EQ(mink::orient3d(a, b, c, Vec3<double>(0.3, 0.3, -2.0)), -1);
  EXPECT_EQ(mink::orient3d(a, b, c, Vec3<double>(5.0, -7.0, 0.0)), 0);
}

// ---------------------------------------------------------------------------------------
// orient2d

using K2 = CGAL::Simple_cartesian<Q>;

template <class T>
int cgalOrientation(const T& ax, const T& ay, const T& bx, const T& by, const T& cx, const T& cy) {
  const K2::Point_2 a(toQ(ax), toQ(ay)), b(toQ(bx), toQ(by)), c(toQ(cx), toQ(cy));
  return static_cast<int>(CGAL::orientation(a, b, c));  // LEFT_TURN = 1, RIGHT_TURN = -1
}

// orient2d against CGAL, plus the sign rules (a swap flips it, a rotation keeps it) and
// the expansion stage alone. Returns the exact sign.
template <class T>
int expectExact2d(const T& ax, const T& ay, const T& bx, const T& by, const T& cx, const T& cy,
                  const std::string& what, int& failures) {
  const int want = cgalOrientation(ax, ay, bx, by, cx, cy);
  const int got = mink::orient2d(ax, ay, bx, by, cx, cy);
  const int swapped = mink::orient2d(bx, by, ax, ay, cx, cy);
  const int rotated = mink::orient2d(bx, by, cx, cy, ax, ay);
  int expansion = want;
  if constexpr (std::is_same<T, double>::value || std::is_same<T, long double>::value)
    expansion = mink::detail::exactOrient2d(ax, ay, bx, by, cx, cy);
  if ((got != want || swapped != -want || rotated != want || expansion != want) && failures++ < 8) {
    std::ostringstream os;
    os.precision(21);
    os << what << ": orient2d = " << got << ", swapped " << swapped << ", rotated " << rotated
       << ", exactOrient2d " << expansion << ", CGAL " << want << "\n  a=(" << ld(ax) << ", " << ld(ay) << ") b=("
       << ld(bx) << ", " << ld(by) << ") c=(" << ld(cx) << ", " << ld(cy) << ")";
    ADD_FAILURE() << os.str();
  }
  return want;
}

template <class T>
class Orient2d : public ::testing::Test {};
TYPED_TEST_SUITE(Orient2d, Floats);

TYPED_TEST(Orient2d, GenericPoints) {
  using T = TypeParam;
  std::mt19937 rng(9201u);
  int failures = 0;
  for (int i = 0; i < 10000; ++i) {
    const T ax = randomValue<T>(rng, -1, 1), ay = randomValue<T>(rng, -1, 1), bx = randomValue<T>(rng, -1, 1),
            by = randomValue<T>(rng, -1, 1), cx = randomValue<T>(rng, -1, 1), cy = randomValue<T>(rng, -1, 1);
    expectExact2d(ax, ay, bx, by, cx, cy, "seed 9201 generic #" + std::to_string(i), failures);
  }
  EXPECT_EQ(failures, 0);
}

// c = a + s (b - a), rounded: on the line up to the rounding, so the filter cannot decide.
TYPED_TEST(Orient2d, NearlyCollinear) {
  using T = TypeParam;
  std::mt19937 rng(9202u);
  std::uniform_real_distribution<double> st(-3.0, 3.0);
  int failures = 0, signs[3] = {0, 0, 0};
  for (int i = 0; i < 10000; ++i) {
    const T ax = randomValue<T>(rng, -10, 10), ay = randomValue<T>(rng, -10, 10), bx = randomValue<T>(rng, -10, 10),
            by = randomValue<T>(rng, -10, 10);
    const T s = T(st(rng));
    const T cx = ax + s * (bx - ax), cy = ay + s * (by - ay);
    ++signs[expectExact2d(ax, ay, bx, by, cx, cy, "seed 9202 nearly collinear #" + std::to_string(i), failures) + 1];
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(signs[0] + signs[2], 0);  // the exact stage decided non-zero signs too
}

// Shewchuk's pattern: points of the line y = x moved by -4..4 ulps in each coordinate.
TYPED_TEST(Orient2d, UlpPerturbationsOfALine) {
  using T = TypeParam;
  int failures = 0, signs[3] = {0, 0, 0};
  const T inf = std::numeric_limits<T>::infinity();
  for (T base : {T(0.5), T(12), T(24), T(-1023.75)}) {
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j) {
        T cx = base, cy = base;
        for (int n = 0; n < std::abs(i); ++n) cx = std::nextafter(cx, i > 0 ? inf : -inf);
        for (int n = 0; n < std::abs(j); ++n) cy = std::nextafter(cy, j > 0 ? inf : -inf);
        const int e = expectExact2d(T(12), T(12), T(24), T(24), cx, cy,
                                    "ulp grid (" + std::to_string(i) + "," + std::to_string(j) + ")", failures);
        ++signs[e + 1];
      }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(signs[0], 0);
  EXPECT_GT(signs[1], 0);
  EXPECT_GT(signs[2], 0);
}

TYPED_TEST(Orient2d, DegenerateConfigurations) {
  using T = TypeParam;
  std::mt19937 rng(9203u);
  int failures = 0;
  std::uniform_int_distribution<int> small(-1000, 1000);
  for (int i = 0; i < 2000; ++i) {
    const T ax = randomValue<T>(rng, -1, 1), ay = randomValue<T>(rng, -1, 1), bx = randomValue<T>(rng, -1, 1),
            by = randomValue<T>(rng, -1, 1);
    EXPECT_EQ(mink::orient2d(ax, ay, ax, ay, bx, by), 0);
    EXPECT_EQ(mink::orient2d(ax, ay, bx, by, bx, by), 0);
    // Midpoints are rounded: usually an ulp off the line.
    expectExact2d(ax, ay, bx, by, T((ax + bx) / 2), T((ay + by) / 2), "seed 9203 midpoint #" + std::to_string(i),
                  failures);
    // Integer points on the line y = 3x - 7, scaled to where the naive formula cancels.
    const int x0 = small(rng), x1 = small(rng), x2 = small(rng);
    const T s = std::ldexp(T(1), 20);
    const T px = T(x0) * s, py = T(3 * x0 - 7) * s, qx = T(x1) * s, qy = T(3 * x1 - 7) * s, rx = T(x2) * s,
            ry = T(3 * x2 - 7) * s;
    EXPECT_EQ(expectExact2d(px, py, qx, qy, rx, ry, "seed 9203 integer collinear #" + std::to_string(i), failures), 0);
  }
  EXPECT_EQ(failures, 0);
}

TYPED_TEST(Orient2d, ExtremeScales) {
  using T = TypeParam;
  std::mt19937 rng(9204u);
  std::uniform_real_distribution<double> st(-2.0, 2.0);
  int failures = 0;
  const int emax = std::is_same<T, float>::value ? 30 : 250;
  for (int e : {-emax, -emax / 2, 0, emax / 2, emax}) {
    for (int i = 0; i < 2000; ++i) {
      T v[6];
      for (int k = 0; k < 4; ++k) v[k] = randomValue<T>(rng, -1, 1);
      const T s = T(st(rng));
      v[4] = v[0] + s * (v[2] - v[0]);
      v[5] = v[1] + s * (v[3] - v[1]);
      for (T& x : v) x = std::ldexp(x, e);
      expectExact2d(v[0], v[1], v[2], v[3], v[4], v[5], "seed 9204 scale 2^" + std::to_string(e) + " #" + std::to_string(i),
                    failures);
    }
  }
  EXPECT_EQ(failures, 0);
}

// Coordinates below 2^-485 beside coordinates of size 1: the double expansion would
// underflow; orient2d must still be exact (it then works in long double).
TEST(Orient2dExact, TinyCoordinatesBesideUnitOnes) {
  std::mt19937 rng(9205u);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const double tiny[] = {1e-300, -3e-305, std::numeric_limits<double>::min(), 1e-310,
                         std::numeric_limits<double>::denorm_min(), 7e-150, -1e-200, 0.0};
  std::uniform_int_distribution<int> pick(0, 7);
  int failures = 0;
  for (int i = 0; i < 4000; ++i) {
    // Three points on the x axis, with tiny y's: the sign is decided by those alone.
    const double ax = u(rng), bx = u(rng), cx = u(rng);
    const double ay = tiny[pick(rng)], by = tiny[pick(rng)], cy = tiny[pick(rng)];
    expectExact2d(ax, ay, bx, by, cx, cy, "seed 9205 #" + std::to_string(i), failures);
    expectExact2d(ay, ax, by, bx, cy, cx, "seed 9205 transposed #" + std::to_string(i), failures);
  }
  EXPECT_EQ(failures, 0);
}

// Points drawn from a few values (0, tiny, denormal, unit): shared coordinates make many
// differences exactly 0, where orient2d answers 0 without the exact stage if both
// products vanish; a product that only underflows (1e-300 x 1e-300) must still count.
TEST(Orient2dExact, SharedCoordinatesAndUnderflowingProducts) {
  std::mt19937 rng(9208u);
  const double values[] = {0.0, 1e-300, -1e-300, std::numeric_limits<double>::denorm_min(), 1.0, -3.0, 1e-160};
  std::uniform_int_distribution<int> pick(0, 6);
  int failures = 0;
  for (int i = 0; i < 20000; ++i) {
    const double a[6] = {values[pick(rng)], values[pick(rng)], values[pick(rng)],
                         values[pick(rng)], values[pick(rng)], values[pick(rng)]};
    expectExact2d(a[0], a[1], a[2], a[3], a[4], a[5], "seed 9208 #" + std::to_string(i), failures);
  }
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(mink::orient2d(0.0, 0.0, 1.0, 0.0, 5.0, 0.0), 0);         // on one axis
  EXPECT_EQ(mink::orient2d(0.0, 0.0, 0.0, 1e-300, 1e-300, 0.0), -1);  // both products underflow
}

TEST(Orient2dExact, Gmpq) {
  std::mt19937 rng(9206u);
  std::uniform_int_distribution<int> num(-1000, 1000), den(1, 99);
  auto rnd = [&] { return Q(num(rng), den(rng)); };
  int failures = 0;
  for (int i = 0; i < 3000; ++i) {
    const Q ax = rnd(), ay = rnd(), bx = rnd(), by = rnd();
    expectExact2d(ax, ay, bx, by, rnd(), rnd(), "seed 9206 generic #" + std::to_string(i), failures);
    const Q s = rnd();
    const Q cx = ax + s * (bx - ax), cy = ay + s * (by - ay);
    EXPECT_EQ(mink::orient2d(ax, ay, bx, by, cx, cy), 0) << "seed 9206 collinear #" << i;
    expectExact2d(ax, ay, bx, by, cx, Q(cy + Q(1, 1000000007)), "seed 9206 just off #" + std::to_string(i), failures);
  }
  EXPECT_EQ(failures, 0);
}

// The Vec3 form: orient2d(a, b, c, k) is the exact sign of component k of (b - a) x (c - a),
// on near-degenerate triangles (c close to the line ab), checked against the exact cross
// product in Gmpq.
TEST(Orient2dExact, DroppedAxisIsTheSignOfThatCrossComponent) {
  std::mt19937 rng(9207u);
  std::uniform_real_distribution<double> st(-2.0, 2.0);
  int failures = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3<double> a = randomPoint<double>(rng), b = randomPoint<double>(rng);
    const Vec3<double> c = i % 2 ? Vec3<double>(a + st(rng) * (b - a)) : randomPoint<double>(rng);
    const Vec3<Q> n = (toQ3(b) - toQ3(a)).cross(toQ3(c) - toQ3(a));
    for (int k = 0; k < 3; ++k) {
      const int got = mink::orient2d(a, b, c, k);
      if (got != CGAL::sign(n[k]) && failures++ < 8)
        ADD_FAILURE() << "seed 9207 #" << i << " axis " << k << ": orient2d " << got << ", exact "
                      << CGAL::sign(n[k]) << "\n  a=" << str(a) << " b=" << str(b) << " c=" << str(c);
    }
  }
  EXPECT_EQ(failures, 0);
  // Sign convention: counter-clockwise is positive; dropping z reads (x, y).
  EXPECT_EQ(mink::orient2d(0.0, 0.0, 1.0, 0.0, 0.0, 1.0), 1);
  EXPECT_EQ(mink::orient2d(Vec3<double>(0, 0, 5), Vec3<double>(1, 0, 5), Vec3<double>(0, 1, 5), 2), 1);
  EXPECT_EQ(mink::orient2d(Vec3<double>(0, 0, 5), Vec3<double>(1, 0, 5), Vec3<double>(0, 1, 5), 0), 0);
}

}  // namespace
