// tests/core/difference_orientation_test.cpp — mink/core/difference_orientation.hpp and
// mink/core/expansion.hpp against exact rationals (CGAL::Gmpq): the sign of
// det[p1 − p0, q1 − q0, r1 − r0] on random, integer-grid, near-degenerate (one ulp off a
// zero determinant), tiny (1e-300) and large coordinates; the interval type encloses the
// exact value of random polynomials, and the expansion type equals it.
#include "mink/core/difference_orientation.hpp"
#include "mink/core/expansion.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <cmath>
#include <random>

namespace {

using Q = CGAL::Gmpq;
using V = mink::Vec3<double>;
using Vq = mink::Vec3<Q>;

Vq exact(const V& v) { return Vq(Q(v.x()), Q(v.y()), Q(v.z())); }

int exactSign(const V& p0, const V& p1, const V& q0, const V& q1, const V& r0, const V& r1) {
  const Q d = (exact(p1) - exact(p0)).dot((exact(q1) - exact(q0)).cross(exact(r1) - exact(r0)));
  return (d > 0) - (d < 0);
}

TEST(DifferenceOrientation, AgreesWithRationalsOnRandomAndDegenerateInputs) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> U(-1, 1);
  std::uniform_int_distribution<int> G(-4, 4);
  int zeros = 0;
  for (int k = 0; k < 20000; ++k) {
    V p[6];
    const int kind = k % 5;
    for (auto& x : p) {
      if (kind == 0) x = V(U(rng), U(rng), U(rng));
      if (kind == 1) x = V(G(rng), G(rng), G(rng));
      if (kind == 2) x = V(G(rng), G(rng), G(rng)) * 1e-300;
      if (kind == 3) x = V(U(rng), U(rng), U(rng)) * 1e80;
      if (kind == 4) x = V(G(rng), G(rng), G(rng)) * 0.1;  // decimal: rounded grid
    }
    if (k % 3 == 0) {
      // r1 − r0 a combination of the others (a zero determinant), then one ulp off.
      p[5] = p[4] + (p[1] - p[0]) * 2.0 - (p[3] - p[2]);
      if (k % 2) p[5][k % 3] = std::nextafter(p[5][k % 3], 1e300);
    }
    const int s = mink::orientDiff(p[0], p[1], p[2], p[3], p[4], p[5]);
    ASSERT_EQ(s, exactSign(p[0], p[1], p[2], p[3], p[4], p[5])) << "case " << k;
    zeros += s == 0;
  }
  EXPECT_GT(zeros, 100);
}

// dotSign and det3Sign, the arc test's predicates (gauss_map/arc_intersection.hpp, the EE
// faces of mdd/detail/pair_frame.hpp): random, integer-grid, tiny and large vectors, and
// vectors one ulp off orthogonal / off a zero determinant.
TEST(DifferenceOrientation, DotAndDeterminantSignsAgreeWithRationals) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> U(-1, 1);
  std::uniform_int_distribution<int> G(-4, 4);
  int zeros = 0, roundedWrong = 0;
  for (int k = 0; k < 20000; ++k) {
    V x, y, z;
    const int kind = k % 5;
    for (V* v : {&x, &y, &z}) {
      if (kind == 0) *v = V(U(rng), U(rng), U(rng));
      if (kind == 1) *v = V(G(rng), G(rng), G(rng));
      if (kind == 2) *v = V(U(rng), G(rng), U(rng)) * 1e-300;
      if (kind == 3) *v = V(U(rng), U(rng), U(rng)) * 1e20;  // y = x × z stays below 2^296
      if (kind == 4) *v = V(G(rng), G(rng), G(rng)) * 0.1;
    }
    if (k % 3 == 0) {
      // y orthogonal to x in the rounded sense, z a combination of x and y; then an ulp off.
      y = x.cross(z);
      z = x * 3.0 - y * 0.5;
      if (k % 2) z[k % 3] = std::nextafter(z[k % 3], 1e300), y[(k + 1) % 3] = std::nextafter(y[(k + 1) % 3], -1e300);
    }
    const Q dot = exact(x).dot(exact(y));
    const int ds = (dot > 0) - (dot < 0);
    ASSERT_EQ(mink::dotSign(x, y), ds) << "case " << k;
    roundedWrong += ((x.dot(y) > 0) - (x.dot(y) < 0)) != ds;
    const Q det = exact(x).dot(exact(y).cross(exact(z)));
    const int es = (det > 0) - (det < 0);
    ASSERT_EQ(mink::det3Sign(x, y, z), es) << "case " << k;
    if (kind != 2 && kind != 3) {  // float: evaluated exactly in double
      ASSERT_EQ(mink::det3Sign(x.cast<float>().eval(), y.cast<float>().eval(), z.cast<float>().eval()),
                mink::det3Sign(x.cast<float>().cast<double>().eval(), y.cast<float>().cast<double>().eval(),
                               z.cast<float>().cast<double>().eval()))
          << "case " << k;
    }
    zeros += (ds == 0) + (es == 0);
  }
  std::printf("[dotSign / det3Sign] 20000 cases, %d exact zeros, %d rounded dot products of the wrong sign\n", zeros,
              roundedWrong);
  EXPECT_GT(zeros, 100);
  EXPECT_GT(roundedWrong, 0);  // the family reaches where rounding alone would decide wrongly
}

// A coordinate 0 in all three differences, or a zero difference, gives exactly 0 without
// the expansions; a column that is 0 in two rows only, or tiny, still decides (against
// rationals): vectors in a coordinate plane (normals of faces parallel to an axis), each
// with one row nudged out of it.
TEST(DifferenceOrientation, ZeroColumnsAndZeroDifferencesAreExactlyZero) {
  std::mt19937 rng(2027);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 3000; ++k) {
    const int axis = k % 3;
    V x(U(rng), U(rng), U(rng)), y(U(rng), U(rng), U(rng)), z(U(rng), U(rng), U(rng));
    x[axis] = y[axis] = z[axis] = 0.0;
    if (k % 4 == 1) z[axis] = std::ldexp(U(rng), -1000);  // a tiny column entry: not zero
    if (k % 4 == 2) y = V::Zero();
    const V o = V::Zero(), p0(U(rng), U(rng), U(rng));
    const int want = exactSign(o, x, o, y, o, z);
    ASSERT_EQ(mink::det3Sign(x, y, z), want) << "case " << k;
    // The same as differences of points away from the origin (p0 + x − p0 rounds: compare
    // with the exact sign of those numbers).
    const V px = p0 + x, py = p0 + y, pz = p0 + z;
    ASSERT_EQ(mink::orientDiff(p0, px, p0, py, p0, pz), exactSign(p0, px, p0, py, p0, pz)) << "case " << k;
    if (k % 4 != 1) {
      EXPECT_EQ(want, 0) << "case " << k;
    }
    // Dot products whose every term has a zero factor are 0; one non-zero term decides.
    V a(U(rng), 0.0, U(rng)), b(0.0, U(rng), 0.0);
    ASSERT_EQ(mink::dotSign(a, b), 0) << "case " << k;
    b[2] = std::ldexp(1.0, -1000);
    const Q dot = exact(a).dot(exact(b));
    ASSERT_EQ(mink::dotSign(a, b), (dot > 0) - (dot < 0)) << "case " << k;
  }
}

TEST(DifferenceOrientation, Orient3dIsTheSpecialCase) {
  std::mt19937 rng(2025);
  std::uniform_int_distribution<int> G(-3, 3);
  for (int k = 0; k < 2000; ++k) {
    const V a(G(rng), G(rng), G(rng)), b(G(rng), G(rng), G(rng)), c(G(rng), G(rng), G(rng)), d(G(rng), G(rng), G(rng));
    EXPECT_EQ(mink::orientDiff(a, b, a, c, a, d), mink::orient3d(a, b, c, d));
  }
}

TEST(Expansion, IntervalEnclosesAndExpansionEqualsTheExactValue) {
  using mink::detail::Expansion;
  using mink::detail::Interval;
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 5000; ++k) {
    double x[6];
    for (double& v : x) v = U(rng) * std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
    // (x0 x1 − x2 x3)(x4 + x5) − x0 x5 x3: cancellation-prone on purpose.
    auto f = [&](auto tag) {
      using N = decltype(tag);
      N a[6];
      for (int i = 0; i < 6; ++i) a[i] = N(x[i]);
      return (a[0] * a[1] - a[2] * a[3]) * (a[4] + a[5]) - a[0] * a[5] * a[3];
    };
    Q q[6];
    for (int i = 0; i < 6; ++i) q[i] = Q(x[i]);
    const Q exactValue = (q[0] * q[1] - q[2] * q[3]) * (q[4] + q[5]) - q[0] * q[5] * q[3];
    const Interval iv = f(Interval());
    EXPECT_LE(Q(iv.lo()), exactValue);
    EXPECT_GE(Q(iv.hi()), exactValue);
    const Expansion e = f(Expansion());
    EXPECT_EQ(e.sign(), (exactValue > 0) - (exactValue < 0));
    const double approx = e.approx();
    EXPECT_LE(std::abs(CGAL::to_double(exactValue) - approx), 1e-15 * std::abs(approx) + 1e-300);
  }
}

// Degree 9 as the trimming evaluates it: a product of three 3x3-style cross terms, once
// factored and once expanded term by term. The two expansions must be equal exactly (their
// difference has sign 0), and adding one ulp of the smallest input changes the sign as
// the rationals say. Inputs spread over 2^-30 .. 2^30 so that components do not overlap.
TEST(Expansion, ExactOnIdentitiesOfDegreeNine) {
  using mink::detail::Expansion;
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    double x[9];
    for (double& v : x) v = U(rng) * std::ldexp(1.0, static_cast<int>(rng() % 60) - 30);
    Expansion a[9];
    for (int i = 0; i < 9; ++i) a[i] = Expansion(x[i]);
    const Expansion factored = (a[0] + a[1] + a[2]) * (a[3] - a[4] + a[5]) * (a[6] + a[7] - a[8]);
    Expansion expanded;
    const double s1[3] = {1, 1, 1}, s2[3] = {1, -1, 1}, s3[3] = {1, 1, -1};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int l = 0; l < 3; ++l) {
          const Expansion term = a[i] * a[3 + j] * a[6 + l];
          if (s1[i] * s2[j] * s3[l] > 0)
            expanded += term;
          else
            expanded -= term;
        }
    EXPECT_EQ((factored - expanded).sign(), 0);
    const double tiny = std::ldexp(1.0, -200);
    Q q[9];
    for (int i = 0; i < 9; ++i) q[i] = Q(x[i]);
    const Q exactValue = (q[0] + q[1] + q[2]) * (q[3] - q[4] + q[5]) * (q[6] + q[7] - q[8]);
    const Q shifted = exactValue - Q(tiny);
    const Expansion e = factored - Expansion(tiny);
    EXPECT_EQ(e.sign(), (shifted > 0) - (shifted < 0));
  }
}

}  // namespace
