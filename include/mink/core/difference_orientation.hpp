// mink/core/difference_orientation.hpp — the exact sign of det[p1 − p0, q1 − q0, r1 − r0]
// for three vectors each given as the difference of two input points.
//
// orient3d(a, b, c, d) is the case p0 = q0 = r0 = a; the general form is what the
// compatibility tests of a convolution ask (the normal of a face of one mesh, (b − a) ×
// (c − a), against an edge w − v of the other: det[b − a, c − a, w − v]). The method is
// that of orient3d (core/orientation.hpp, after J. R. Shewchuk, DCG 18, 1997):
//   1. the determinant of the rounded differences with Shewchuk's forward error bound
//      for orient3d, which holds for any three rows that are rounded differences of
//      inputs (each entry carries one rounding, each monomial three more);
//   2. when the filter cannot tell, every difference as an exact two-term expansion and
//      the determinant summed exactly in a fixed-size expansion (no heap allocation):
//      6 permutations x 8 choices of high or low parts x up to 4 terms per triple
//      product, at most 192 components.
// Exact for double while every non-zero coordinate is at least 2^-306 in magnitude and at
// most ScalarTraits::largestCoordinate() (as orient3d); smaller coordinates go to long
// double where it has the range. Float inputs are evaluated exactly in double. Exact
// scalar types evaluate the determinant directly.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "mink/core/orientation.hpp"

namespace mink {
namespace detail {

/// A non-overlapping expansion of at most N components, increasing magnitude, on the stack.
template <class F, int N>
struct FixedExpansion {
  F c[N];
  int n = 0;
  /// this += b, exactly (Shewchuk's Grow-Expansion with zero elimination). Returns false
  /// if the capacity would be exceeded (cannot happen for the sizes used here).
  bool add(F b) {
    F q = b;
    int k = 0;
    for (int i = 0; i < n; ++i) {
      F x, y;
      twoSum(q, c[i], x, y);
      if (y != F(0)) c[k++] = y;
      q = x;
    }
    if (q != F(0)) {
      if (k >= N) return false;
      c[k++] = q;
    }
    n = k;
    return true;
  }
  int sign() const {
    for (int i = n; i-- > 0;)
      if (c[i] != F(0)) return c[i] > F(0) ? 1 : -1;
    return 0;
  }
};

inline bool tinyCoordinate(double x) { return x != 0.0 && std::fabs(x) < std::ldexp(1.0, -306); }

/// Exact sign of the determinant of three rows, each a two-term expansion per entry:
/// row[r][i][0] + row[r][i][1] (high, low).
template <class F>
int exactDet3OfExpansions(const F (&u)[3][2], const F (&v)[3][2], const F (&w)[3][2]) {
  static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  static const int sgn[6] = {1, 1, 1, -1, -1, -1};
  FixedExpansion<F, 200> acc;
  for (int p = 0; p < 6; ++p)
    for (int x = 0; x < 2; ++x)
      for (int y = 0; y < 2; ++y)
        for (int z = 0; z < 2; ++z) {
          const F ux = u[perm[p][0]][x], vy = v[perm[p][1]][y], wz = F(sgn[p]) * w[perm[p][2]][z];
          if (ux == F(0) || vy == F(0) || wz == F(0)) continue;
          F h, l;
          twoProduct(ux, vy, h, l);
          F hh, hl;
          twoProduct(h, wz, hh, hl);
          acc.add(hl);
          acc.add(hh);
          if (l != F(0)) {
            F lh, ll;
            twoProduct(l, wz, lh, ll);
            acc.add(ll);
            acc.add(lh);
          }
        }
  return acc.sign();
}

template <class F>
int exactOrientDiff(const Vec3<F>& p0, const Vec3<F>& p1, const Vec3<F>& q0, const Vec3<F>& q1, const Vec3<F>& r0,
                    const Vec3<F>& r1) {
  if constexpr (std::is_same<F, double>::value && std::numeric_limits<long double>::min_exponent < -4000) {
    for (const Vec3<double>* p : {&p0, &p1, &q0, &q1, &r0, &r1})
      for (int i = 0; i < 3; ++i)
        if (tinyCoordinate((*p)[i])) {
          using L = long double;
          return exactOrientDiff<L>(p0.template cast<L>(), p1.template cast<L>(), q0.template cast<L>(),
                                    q1.template cast<L>(), r0.template cast<L>(), r1.template cast<L>());
        }
  }
  F u[3][2], v[3][2], w[3][2];
  for (int i = 0; i < 3; ++i) {
    twoSum(p1[i], F(-p0[i]), u[i][0], u[i][1]);
    twoSum(q1[i], F(-q0[i]), v[i][0], v[i][1]);
    twoSum(r1[i], F(-r0[i]), w[i][0], w[i][1]);
  }
  return exactDet3OfExpansions(u, v, w);
}

/// Exact sign of x · y by expansion arithmetic: three two-products summed exactly.
/// Exact while no product underflows (every non-zero coordinate at least 2^-306 for
/// double; smaller ones go to long double where it has the range, as above).
template <class F>
int exactDotSign(const Vec3<F>& x, const Vec3<F>& y) {
  if constexpr (std::is_same<F, double>::value && std::numeric_limits<long double>::min_exponent < -4000) {
    for (int i = 0; i < 3; ++i)
      if (tinyCoordinate(x[i]) || tinyCoordinate(y[i])) {
        using L = long double;
        return exactDotSign<L>(x.template cast<L>(), y.template cast<L>());
      }
  }
  FixedExpansion<F, 6> acc;
  for (int i = 0; i < 3; ++i) {
    F h, l;
    twoProduct(x[i], y[i], h, l);
    acc.add(l);
    acc.add(h);
  }
  return acc.sign();
}

}  // namespace detail

/// Exact sign of the dot product x · y of the given numbers: the rounded sum with its
/// forward error bound (three roundings per term, plus the absolute error of products
/// below the normal range), then, when that cannot tell, the exact sum of the
/// two-products. Float is evaluated exactly in double.
template <class T>
int dotSign(const Vec3<T>& x, const Vec3<T>& y) {
  if constexpr (ScalarTraits<T>::isExact) {
    return detail::sign(T(x.dot(y)));
  } else if constexpr (std::is_same<T, float>::value) {
    return dotSign<double>(x.template cast<double>(), y.template cast<double>());
  } else {
    using std::abs;
    const T p0 = x[0] * y[0], p1 = x[1] * y[1], p2 = x[2] * y[2];
    const T dot = (p0 + p1) + p2;
    constexpr T eps = std::numeric_limits<T>::epsilon() / T(2);
    // γ3 = 3 eps / (1 − 3 eps) < (3 + 16 eps) eps, for each of the three terms.
    const T bound = (T(3) + T(16) * eps) * eps * (abs(p0) + abs(p1) + abs(p2)) + detail::denormalErrorBound(T(4));
    if (dot > bound) return 1;
    if (-dot > bound) return -1;
    // Every product exactly 0 (a factor 0 in each term): the dot product is 0.
    if ((x[0] == T(0) || y[0] == T(0)) && (x[1] == T(0) || y[1] == T(0)) && (x[2] == T(0) || y[2] == T(0))) return 0;
    return detail::exactDotSign(x, y);
  }
}

/// Exact sign of det[x y z] = x · (y × z) of the given numbers (orientDiff of the three
/// vectors from the origin: a filter, then expansion arithmetic; exact T directly).
template <class T>
int det3Sign(const Vec3<T>& x, const Vec3<T>& y, const Vec3<T>& z);

/// Exact sign of det[p1 − p0, q1 − q0, r1 − r0] (see the header comment): > 0 when the
/// three difference vectors form a right-handed basis.
template <class T>
int orientDiff(const Vec3<T>& p0, const Vec3<T>& p1, const Vec3<T>& q0, const Vec3<T>& q1, const Vec3<T>& r0,
               const Vec3<T>& r1) {
  if constexpr (ScalarTraits<T>::isExact) {
    return detail::sign(T((p1 - p0).dot((q1 - q0).cross(r1 - r0))));
  } else if constexpr (std::is_same<T, float>::value) {
    using D = double;
    return orientDiff<D>(p0.template cast<D>(), p1.template cast<D>(), q0.template cast<D>(), q1.template cast<D>(),
                         r0.template cast<D>(), r1.template cast<D>());
  } else {
    const Vec3<T> u = p1 - p0, v = q1 - q0, w = r1 - r0;
    const T m0 = v[1] * w[2] - v[2] * w[1];
    const T m1 = v[2] * w[0] - v[0] * w[2];
    const T m2 = v[0] * w[1] - v[1] * w[0];
    const T det = u[0] * m0 + u[1] * m1 + u[2] * m2;
    using std::abs;
    const T perm = abs(u[0]) * (abs(v[1] * w[2]) + abs(v[2] * w[1])) +
                   abs(u[1]) * (abs(v[2] * w[0]) + abs(v[0] * w[2])) +
                   abs(u[2]) * (abs(v[0] * w[1]) + abs(v[1] * w[0]));
    constexpr T eps = std::numeric_limits<T>::epsilon() / T(2);
    constexpr T dm = std::numeric_limits<T>::min();  // not denorm_min: see orient3d
    const T bound =
        (T(7) + T(56) * eps) * eps * perm + dm * (T(2) * (abs(u[0]) + abs(u[1]) + abs(u[2])) + T(4));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    // A coordinate that is 0 in all three differences, or a difference that is 0 (a
    // rounded difference is 0 exactly where the exact one is): the determinant is exactly
    // 0 without the expansions. Normals of faces parallel to one axis (the side faces of
    // two upright cylinders, z = 0) reached the exact stage on every call otherwise.
    for (int k = 0; k < 3; ++k)
      if (u[k] == T(0) && v[k] == T(0) && w[k] == T(0)) return 0;
    const Vec3<T> zero = Vec3<T>::Zero();
    if (u == zero || v == zero || w == zero) return 0;
    return detail::exactOrientDiff(p0, p1, q0, q1, r0, r1);
  }
}

template <class T>
int det3Sign(const Vec3<T>& x, const Vec3<T>& y, const Vec3<T>& z) {
  if constexpr (ScalarTraits<T>::isExact) {
    return detail::sign(T(x.dot(y.cross(z))));
  } else {
    const Vec3<T> o = Vec3<T>::Zero();
    return orientDiff(o, x, o, y, o, z);
  }
}

}  // namespace mink
