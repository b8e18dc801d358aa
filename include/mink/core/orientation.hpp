// mink/core/orientation.hpp — the exact sign of the 3-D orientation determinant for
// floating-point inputs (and for exact scalars, trivially).
//
// orient3d(a, b, c, d) = sign det[b − a, c − a, d − a]: > 0 when d lies on the side of
// the plane (a, b, c) that (b − a) × (c − a) points to.
// For floating-point T the sign is the sign of the determinant of the *given* numbers,
// exactly, by the method of J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates" (DCG 18, 1997):
//   1. Evaluate the determinant in T with a forward error bound; if |det| exceeds it,
//      its sign is right (the common case, a few dozen flops).
//   2. Otherwise redo it exactly: every coordinate difference is an exact two-term
//      expansion (two-sum), every product of three terms an exact expansion (two-product
//      by fma, then scaling), and the sum of all of them an exact non-overlapping
//      expansion whose largest component carries the sign.
// Valid while no intermediate value overflows or underflows (|coordinates| within about
// 1e-90 .. 1e90 for double); mink's inputs are validated as finite.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {
namespace detail {

// x + y == a + b exactly (Knuth's two-sum).
template <class F>
inline void twoSum(F a, F b, F& x, F& y) {
  x = a + b;
  const F bv = x - a;
  const F av = x - bv;
  y = (a - av) + (b - bv);
}

// x + y == a * b exactly.
template <class F>
inline void twoProduct(F a, F b, F& x, F& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

// h = e + b (e non-overlapping, increasing magnitude; zeros dropped).
template <class F>
inline void growExpansion(std::vector<F>& e, F b, std::vector<F>& h) {
  h.clear();
  F q = b;
  for (F ei : e) {
    F x, y;
    twoSum(q, ei, x, y);
    if (y != F(0)) h.push_back(y);
    q = x;
  }
  if (q != F(0) || h.empty()) h.push_back(q);
}

// h = e * b exactly (Shewchuk's scale-expansion, zeros dropped).
template <class F>
inline void scaleExpansion(const std::vector<F>& e, F b, std::vector<F>& h) {
  h.clear();
  F q, hh;
  twoProduct(e[0], b, q, hh);
  if (hh != F(0)) h.push_back(hh);
  for (std::size_t i = 1; i < e.size(); ++i) {
    F t1, t0, s, r;
    twoProduct(e[i], b, t1, t0);
    twoSum(q, t0, s, r);
    if (r != F(0)) h.push_back(r);
    F q2;
    twoSum(t1, s, q2, r);  // t1 is larger than s: fast-two-sum would do, two-sum is safe
    if (r != F(0)) h.push_back(r);
    q = q2;
  }
  if (q != F(0) || h.empty()) h.push_back(q);
}

template <class F>
int exactOrient3d(const Vec3<F>& a, const Vec3<F>& b, const Vec3<F>& c, const Vec3<F>& d) {
  // Rows u = b − a, v = c − a, w = d − a as exact two-term expansions.
  F u[3][2], v[3][2], w[3][2];
  for (int i = 0; i < 3; ++i) {
    twoSum(b[i], F(-a[i]), u[i][1], u[i][0]);
    twoSum(c[i], F(-a[i]), v[i][1], v[i][0]);
    twoSum(d[i], F(-a[i]), w[i][1], w[i][0]);
  }
  // det = sum over permutations (i, j, k) of sign * u_i v_j w_k.
  static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  static const int sgn[6] = {1, 1, 1, -1, -1, -1};
  std::vector<F> acc{F(0)}, tmp, prod, term;
  for (int p = 0; p < 6; ++p) {
    for (int x = 0; x < 2; ++x)
      for (int y = 0; y < 2; ++y)
        for (int z = 0; z < 2; ++z) {
          const F ux = u[perm[p][0]][x], vy = v[perm[p][1]][y], wz = w[perm[p][2]][z];
          if (ux == F(0) || vy == F(0) || wz == F(0)) continue;
          F h, l;
          twoProduct(ux, vy, h, l);
          prod.clear();
          if (l != F(0)) prod.push_back(l);
          prod.push_back(h);
          scaleExpansion(prod, F(sgn[p] * wz), term);
          for (F t : term) {
            growExpansion(acc, t, tmp);
            acc.swap(tmp);
          }
        }
  }
  for (std::size_t i = acc.size(); i-- > 0;)
    if (acc[i] != F(0)) return acc[i] > F(0) ? 1 : -1;
  return 0;
}

// a*b - c*d, each product exact, the difference rounded once (up to one more rounding
// of the tiny correction terms): accurate to about 1 ulp even under cancellation.
template <class F>
inline F diffOfProducts(F a, F b, F c, F d) {
  F p, pe, q, qe;
  twoProduct(a, b, p, pe);
  twoProduct(c, d, q, qe);
  F s, se;
  twoSum(p, F(-q), s, se);
  return s + (se + (pe - qe));
}

}  // namespace detail

/// (b − a) × (c − a), accurate to about one ulp per component for floating-point T even
/// when the triangle is a sliver (the plain formula loses all digits there); exact for
/// exact T. Float is computed in double (exact products) and rounded once.
template <class T>
Vec3<T> accurateCross(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  if constexpr (ScalarTraits<T>::isExact) {
    return (b - a).cross(c - a);
  } else if constexpr (std::is_same<T, float>::value) {
    return accurateCross<double>(a.template cast<double>(), b.template cast<double>(), c.template cast<double>())
        .template cast<float>();
  } else {
    // Differences as exact two-term expansions u = uh + ul, v = vh + vl; the cross product
    // of the high parts carries the value, the low parts are first-order corrections.
    Vec3<T> uh, ul, vh, vl;
    for (int i = 0; i < 3; ++i) {
      detail::twoSum(b[i], T(-a[i]), uh[i], ul[i]);
      detail::twoSum(c[i], T(-a[i]), vh[i], vl[i]);
    }
    Vec3<T> n;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const T main = detail::diffOfProducts(uh[j], vh[k], uh[k], vh[j]);
      const T corr = (uh[j] * vl[k] + ul[j] * vh[k]) - (uh[k] * vl[j] + ul[k] * vh[j]);
      n[i] = main + corr;
    }
    return n;
  }
}

/// Exact sign of det[b − a, c − a, d − a] (see the header comment).
template <class T>
int orient3d(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
  if constexpr (ScalarTraits<T>::isExact) {
    return detail::sign(T((b - a).dot((c - a).cross(d - a))));
  } else if constexpr (std::is_same<T, float>::value) {
    // Floats are exact doubles; the double predicate is then exact for them.
    return orient3d<double>(a.template cast<double>(), b.template cast<double>(), c.template cast<double>(),
                            d.template cast<double>());
  } else {
    const Vec3<T> u = b - a, v = c - a, w = d - a;
    const T m0 = v[1] * w[2] - v[2] * w[1];
    const T m1 = v[2] * w[0] - v[0] * w[2];
    const T m2 = v[0] * w[1] - v[1] * w[0];
    const T det = u[0] * m0 + u[1] * m1 + u[2] * m2;
    using std::abs;
    const T perm = abs(u[0]) * (abs(v[1] * w[2]) + abs(v[2] * w[1])) +
                   abs(u[1]) * (abs(v[2] * w[0]) + abs(v[0] * w[2])) +
                   abs(u[2]) * (abs(v[0] * w[1]) + abs(v[1] * w[0]));
    // Shewchuk's o3derrboundA for the rounded differences and products: (7 + 56 eps) eps.
    const T eps = std::numeric_limits<T>::epsilon() / T(2);
    const T bound = (T(7) + T(56) * eps) * eps * perm;
    if (det > bound) return 1;
    if (-det > bound) return -1;
    if (perm == T(0)) return 0;
    return detail::exactOrient3d(a, b, c, d);
  }
}

}  // namespace mink
