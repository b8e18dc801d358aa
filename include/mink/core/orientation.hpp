// mink/core/orientation.hpp — the exact signs of the 3-D and 2-D orientation determinants
// for floating-point inputs (and for exact scalars, trivially).
//
// orient3d(a, b, c, d) = sign det[b − a, c − a, d − a]: > 0 when d lies on the side of
// the plane (a, b, c) that (b − a) × (c − a) points to.
// orient2d(a, b, c) = sign of (b − a) × (c − a) for points of the plane: > 0 when a, b, c
// turn counter-clockwise. Given as two scalars per point, or as Vec3 with one axis k
// dropped: the points are then read in the axes (k + 1, k + 2) mod 3, so that
// orient2d(a, b, c, k) is the exact sign of component k of (b − a) × (c − a) (the
// orientation of the triangle's projection along axis k, seen from +k).
// For floating-point T the sign is the sign of the determinant of the *given* numbers,
// exactly, by the method of J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates" (DCG 18, 1997):
//   1. Evaluate the determinant in T with a forward error bound; if |det| exceeds it,
//      its sign is right (the common case, a few dozen flops).
//   2. Otherwise redo it exactly: every coordinate difference is an exact two-term
//      expansion (two-sum), every product of three terms an exact expansion (two-product
//      by fma, then scaling), and the sum of all of them an exact non-overlapping
//      expansion whose largest component carries the sign.
//   3. Step 2 is exact while no product underflows: for double, while every non-zero
//      coordinate is at least 2^-306 (about 8e-93) in magnitude (every input, difference
//      and product is then a multiple of a power of two that stays representable). A
//      smaller coordinate (1e-300 beside 1) sends step 2 to long double where it has
//      the exponent range (x87 extended or binary128: 2^-16382), which holds every such
//      product; where long double is double (MSVC), such inputs may get a wrong sign.
//      orient2d multiplies two differences, not three: its bound is 2^-485 (about 1e-146).
// No intermediate value overflows while |coordinates| <= 2^296 (about 1e89), the bound
// mink validates its inputs against (ScalarTraits::largestCoordinate()).
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {

template <class T>
int orient3d(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d);
template <class T>
int orient2d(const T& ax, const T& ay, const T& bx, const T& by, const T& cx, const T& cy);

namespace detail {

// x + y == a + b exactly (Knuth's two-sum).
template <class F>
inline void twoSum(F a, F b, F& x, F& y) {
  x = a + b;
  const F bv = x - a;
  const F av = x - bv;
  y = (a - av) + (b - bv);
}

// 2^e, exactly, at compile time.
template <class F>
constexpr F powerOfTwo(int e) {
  F r = 1;
  for (; e > 0; --e) r *= 2;
  for (; e < 0; ++e) r /= 2;
  return r;
}

// The fma a * b − x out of line: a compiler may evaluate an inline fma on both sides of
// the branch below (clang did: glibc's fmal on every call); a call it cannot see into is
// not evaluated speculatively.
template <class F>
[[gnu::noinline]] F productError(F a, F b, F x) {
  return std::fma(a, b, -x);
}

// x + y == a * b exactly: by fma, or, for a type wider than double (long double, which
// the exact stage uses for the range), by Dekker's product of Veltkamp halves where both
// factors are far enough inside the exponent range for every partial product to be exact
// (within 2^±(emax/2 − digits)): glibc's fmal is software, with floating-point environment
// calls that took half the time of inputs decided in long double.
template <class F>
inline void twoProduct(F a, F b, F& x, F& y) {
  x = a * b;
  using L = std::numeric_limits<F>;
  // (IEEE types only: a double-double long double has no correctly rounded product.)
  if constexpr (L::is_iec559 && L::radix == 2 && L::digits > 53 && L::max_exponent > 2 * L::digits + 2) {
    constexpr F lo = powerOfTwo<F>(L::min_exponent / 2 + L::digits);
    constexpr F hi = powerOfTwo<F>(L::max_exponent / 2 - L::digits);
    constexpr F split = powerOfTwo<F>((L::digits + 1) / 2) + F(1);
    const F aa = std::abs(a), ab = std::abs(b);
    if (aa == F(0) || ab == F(0)) {
      y = F(0);
      return;
    }
    if (aa >= lo && aa <= hi && ab >= lo && ab <= hi) {
      F c = split * a;
      const F ahi = c - (c - a), alo = a - ahi;
      c = split * b;
      const F bhi = c - (c - b), blo = b - bhi;
      y = ((ahi * bhi - x) + ahi * blo + alo * bhi) + alo * blo;
      return;
    }
    y = productError(a, b, x);
  } else {
    y = std::fma(a, b, -x);
  }
}

/// An expansion in storage the caller owns (a stack array of `capacity` numbers), so that
/// an exact predicate allocates nothing; swap exchanges the views, not the numbers. The
/// helpers below take it or a std::vector alike (mesh/detail/signed_volume.hpp sums
/// expansions of unbounded length).
template <class F>
struct ExpansionView {
  using value_type = F;
  F* data;
  std::size_t capacity;
  std::size_t n = 0;
  void clear() { n = 0; }
  void push_back(F x) {
    assert(n < capacity && "ExpansionView: the stated bound on the expansion's length is wrong");
    data[n++] = x;
  }
  void assign(std::size_t count, F x) {
    clear();
    for (std::size_t i = 0; i < count; ++i) push_back(x);
  }
  std::size_t size() const { return n; }
  bool empty() const { return n == 0; }
  F* begin() { return data; }
  F* end() { return data + n; }
  const F* begin() const { return data; }
  const F* end() const { return data + n; }
  const F& operator[](std::size_t i) const { return data[i]; }
  void swap(ExpansionView& o) {
    std::swap(data, o.data);
    std::swap(capacity, o.capacity);
    std::swap(n, o.n);
  }
};

// h = e + b (e non-overlapping, increasing magnitude; zeros dropped). h.size() <= e.size() + 1.
template <class E>
inline void growExpansion(E& e, typename E::value_type b, E& h) {
  using F = typename E::value_type;
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

// h = e * b exactly (Shewchuk's scale-expansion, zeros dropped). h.size() <= 2 e.size().
template <class E>
inline void scaleExpansion(const E& e, typename E::value_type b, E& h) {
  using F = typename E::value_type;
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

/// acc += a * b * c exactly (acc non-overlapping, increasing magnitude; zeros dropped):
/// two-product of a and b, scaled by c, grown into acc term by term. prod, term and tmp
/// are scratch. acc grows by at most 4 terms.
template <class E, class F = typename E::value_type>
inline void addTripleProduct(E& acc, F a, F b, F c, E& prod, E& term, E& tmp) {
  if (a == F(0) || b == F(0) || c == F(0)) return;
  F h, l;
  twoProduct(a, b, h, l);
  prod.clear();
  if (l != F(0)) prod.push_back(l);
  prod.push_back(h);
  scaleExpansion(prod, c, term);
  for (F t : term) {
    growExpansion(acc, t, tmp);
    acc.swap(tmp);
  }
}

/// h = e + f exactly, in one pass over the two merged by magnitude (Shewchuk's
/// Fast-Expansion-Sum with zero elimination: the inputs strongly non-overlapping, as
/// two-product, scale-expansion and this sum leave them under round-to-nearest-even).
/// h.size() <= e.size() + f.size(). Linear, where growing e by each term of f is
/// quadratic: sums of many terms are built as a tree of these.
template <class E>
inline void sumExpansions(const E& e, const E& f, E& h) {
  using F = typename E::value_type;
  h.clear();
  std::size_t i = 0, j = 0;
  const std::size_t m = e.size(), n = f.size();
  if (m + n == 0) return;
  auto next = [&]() {
    if (j == n || (i < m && std::abs(e[i]) < std::abs(f[j]))) return e[i++];
    return f[j++];
  };
  F q = next();
  while (i < m || j < n) {
    F x, y;
    twoSum(q, next(), x, y);
    if (y != F(0)) h.push_back(y);
    q = x;
  }
  if (q != F(0)) h.push_back(q);
}

/// term = a * b * c exactly (at most 4 components; empty if a factor is zero).
template <class E, class F = typename E::value_type>
inline void tripleProduct(F a, F b, F c, E& term) {
  term.clear();
  if (a == F(0) || b == F(0) || c == F(0)) return;
  F h, l, buf[2];
  twoProduct(a, b, h, l);
  E prod{buf, 2};
  if (l != F(0)) prod.push_back(l);
  prod.push_back(h);
  scaleExpansion(prod, c, term);
}

/// The sign of a non-overlapping expansion: that of its largest non-zero component.
template <class E>
inline int expansionSign(const E& e) {
  using F = typename E::value_type;
  for (std::size_t i = e.size(); i-- > 0;)
    if (e[i] != F(0)) return e[i] > F(0) ? 1 : -1;
  return 0;
}

template <class F>
int exactOrient3d(const Vec3<F>& a, const Vec3<F>& b, const Vec3<F>& c, const Vec3<F>& d);

/// Is one of `values` non-zero and below 2^exponent in magnitude, where long double has
/// the exponent range to redo an exact expansion that double would underflow in?
inline bool needsWiderExponent(std::initializer_list<double> values, int exponent) {
  if constexpr (std::numeric_limits<long double>::min_exponent > -4000) {
    (void)values;
    (void)exponent;
    return false;  // long double is no wider than double here: nothing better to do
  } else {
    const double tiny = std::ldexp(1.0, exponent);
    for (double x : values)
      if (x != 0.0 && std::fabs(x) < tiny) return true;
    return false;
  }
}

/// Can exactOrient3d<double> underflow on these points (a non-zero coordinate below
/// 2^-306: see the header comment), and has long double the range to do it instead?
inline bool needsWiderExponent(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                               const Vec3<double>& d) {
  return needsWiderExponent({a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]}, -306);
}

template <class F>
int exactOrient3d(const Vec3<F>& a, const Vec3<F>& b, const Vec3<F>& c, const Vec3<F>& d) {
  if constexpr (std::is_same<F, double>::value) {
    if (needsWiderExponent(a, b, c, d)) {
      // The filter again first, in long double, whose range holds the products that
      // underflowed in double: it settles nearly every such input (a scene of 1e-299
      // otherwise spent seconds in exact expansions, fuzz/README.md).
      using L = long double;
      return orient3d<L>(a.template cast<L>(), b.template cast<L>(), c.template cast<L>(), d.template cast<L>());
    }
  }
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
  // 48 triple products of at most 4 terms each, summed as a tree: the 8 of each
  // permutation (at most 32 terms), then those 6 pairwise (64, 128, 192). Where nothing
  // cancels (coordinates 2^300 beside 2^-1000) the sum keeps every term, and growing one
  // expansion term by term cost 193² two-sums per call.
  using View = ExpansionView<F>;
  F termBuf[4], tmpBuf[32], permBuf[6][32], pairBuf[3][64], fourBuf[128], allBuf[192];
  View term{termBuf, 4}, tmp{tmpBuf, 32};
  View per[6] = {{permBuf[0], 32}, {permBuf[1], 32}, {permBuf[2], 32},
                 {permBuf[3], 32}, {permBuf[4], 32}, {permBuf[5], 32}};
  for (int p = 0; p < 6; ++p)
    for (int x = 0; x < 2; ++x)
      for (int y = 0; y < 2; ++y)
        for (int z = 0; z < 2; ++z) {
          tripleProduct(u[perm[p][0]][x], v[perm[p][1]][y], F(sgn[p] * w[perm[p][2]][z]), term);
          if (term.empty()) continue;
          sumExpansions(per[p], term, tmp);
          per[p].swap(tmp);
        }
  View pairs[3] = {{pairBuf[0], 64}, {pairBuf[1], 64}, {pairBuf[2], 64}};
  for (int k = 0; k < 3; ++k) sumExpansions(per[2 * k], per[2 * k + 1], pairs[k]);
  View four{fourBuf, 128}, all{allBuf, 192};
  sumExpansions(pairs[0], pairs[1], four);
  sumExpansions(four, pairs[2], all);
  return expansionSign(all);
}

/// Exact sign of (bx − ax)(cy − ay) − (by − ay)(cx − ax) by expansion arithmetic: the
/// four differences as exact two-term expansions, their products by two-product, the
/// sum of the sixteen terms as one non-overlapping expansion.
template <class F>
int exactOrient2d(F ax, F ay, F bx, F by, F cx, F cy) {
  if constexpr (std::is_same<F, double>::value) {
    if (needsWiderExponent({ax, ay, bx, by, cx, cy}, -485)) {
      using L = long double;  // filtered first, as in exactOrient3d
      return orient2d<L>(L(ax), L(ay), L(bx), L(by), L(cx), L(cy));
    }
  }
  F ux[2], uy[2], vx[2], vy[2];
  twoSum(bx, F(-ax), ux[1], ux[0]);
  twoSum(by, F(-ay), uy[1], uy[0]);
  twoSum(cx, F(-ax), vx[1], vx[0]);
  twoSum(cy, F(-ay), vy[1], vy[0]);
  // 16 terms grown into {0}: at most 17.
  constexpr std::size_t kTerms = 1 + 16;
  F accBuf[kTerms], tmpBuf[kTerms];
  ExpansionView<F> acc{accBuf, kTerms}, tmp{tmpBuf, kTerms};
  acc.push_back(F(0));
  auto add = [&](F t) {
    if (t == F(0)) return;
    growExpansion(acc, t, tmp);
    acc.swap(tmp);
  };
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      F h, l;
      twoProduct(ux[i], vy[j], h, l);
      add(h);
      add(l);
      twoProduct(uy[i], vx[j], h, l);
      add(F(-h));
      add(F(-l));
    }
  return expansionSign(acc);
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

/// x · 2^k, as std::ldexp (one correctly rounded result) but, for double and k within the
/// normal exponent range, a multiplication by the power of two instead of a libm call.
template <class T>
inline T timesPowerOfTwo(T x, int k) {
  if constexpr (std::is_same<T, double>::value && std::numeric_limits<double>::is_iec559) {
    if (k >= -1022 && k <= 1023) {
      const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
      double p;
      std::memcpy(&p, &bits, sizeof p);
      return x * p;
    }
  }
  return std::ldexp(x, k);
}

/// (uh + ul) × (vh + vl) for two-term expansions of order one, to about one ulp of its
/// length (see accurateCross).
template <class T>
Vec3<T> crossOfExpansions(const Vec3<T>& uh, const Vec3<T>& ul, const Vec3<T>& vh, const Vec3<T>& vl) {
  using std::abs;
  constexpr T eps = std::numeric_limits<T>::epsilon();
  Vec3<T> n, err;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const T main = detail::diffOfProducts(uh[j], vh[k], uh[k], vh[j]);
    const T c1 = uh[j] * vl[k], c2 = ul[j] * vh[k], c3 = uh[k] * vl[j], c4 = ul[k] * vh[j];
    n[i] = main + ((c1 + c2) - (c3 + c4));
    // Rounding of the sums above, plus the second-order terms left out.
    err[i] = T(4) * eps * (abs(main) + abs(c1) + abs(c2) + abs(c3) + abs(c4)) + abs(ul[j] * vl[k]) +
             abs(ul[k] * vl[j]);
  }
  // The corrections can cancel each other far above a tiny result (a face 1e-300 wide
  // beside coordinates of size 1): then every term is summed exactly and rounded.
  const T len = n.cwiseAbs().maxCoeff();
  if (err.maxCoeff() <= T(16) * eps * len) return n;
  // Per component 16 terms grown into {0}: at most 17.
  constexpr std::size_t kTerms = 1 + 16;
  T accBuf[kTerms], tmpBuf[kTerms];
  detail::ExpansionView<T> acc{accBuf, kTerms}, tmp{tmpBuf, kTerms};
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    acc.assign(1, T(0));
    const T us[2] = {uh[j], ul[j]}, vs[2] = {vh[k], vl[k]}, uk[2] = {uh[k], ul[k]}, vj[2] = {vh[j], vl[j]};
    for (int x = 0; x < 2; ++x)
      for (int y = 0; y < 2; ++y) {
        T h, l;
        detail::twoProduct(us[x], vs[y], h, l);
        for (T t : {h, l}) {
          detail::growExpansion(acc, t, tmp);
          acc.swap(tmp);
        }
        detail::twoProduct(uk[x], vj[y], h, l);
        for (T t : {h, l}) {
          detail::growExpansion(acc, T(-t), tmp);
          acc.swap(tmp);
        }
      }
    T sum = T(0);  // components in increasing magnitude, non-overlapping: ~1 ulp
    for (T t : acc) sum += t;
    n[i] = sum;
  }
  return n;
}
}  // namespace detail

/// (b − a) × (c − a), accurate to about one ulp of its length for floating-point T even
/// when the triangle is a sliver (the plain formula loses all digits there); exact for
/// exact T. Float is computed in double (exact products) and rounded once.
/// With `exponent` (inexact T), returns n with (b − a) × (c − a) = n · 2^exponent, n's
/// length about 2^998 times the sine of the triangle's angle at a: the direction of a
/// face too small for its normal to be represented (1e-185 by 1e-300: the product is
/// below the double range) is kept. Without it, the vector itself (which may then
/// underflow).
template <class T>
Vec3<T> accurateCross(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, int* exponent = nullptr) {
  if constexpr (ScalarTraits<T>::isExact) {
    (void)exponent;
    return (b - a).cross(c - a);
  } else if constexpr (std::is_same<T, float>::value) {
    const Vec3<double> ad = a.template cast<double>(), bd = b.template cast<double>(), cd = c.template cast<double>();
    if (!exponent) return accurateCross<double>(ad, bd, cd).template cast<float>();
    // The double result is of order 2^998: brought to order one before rounding to float.
    Vec3<double> n = accurateCross<double>(ad, bd, cd, exponent);
    const double big = n.cwiseAbs().maxCoeff();
    if (big > 0.0) {
      const int k = std::ilogb(big);
      for (int i = 0; i < 3; ++i) n[i] = std::ldexp(n[i], -k);
      *exponent += k;
    }
    return n.template cast<float>();
  } else {
    // Differences as exact two-term expansions u = uh + ul, v = vh + vl; the cross product
    // of the high parts carries the value, the low parts are first-order corrections.
    Vec3<T> uh, ul, vh, vl;
    for (int i = 0; i < 3; ++i) {
      detail::twoSum(b[i], T(-a[i]), uh[i], ul[i]);
      detail::twoSum(c[i], T(-a[i]), vh[i], vl[i]);
    }
    if (uh == Vec3<T>::Zero() || vh == Vec3<T>::Zero()) {
      if (exponent) *exponent = 0;
      return Vec3<T>::Zero();
    }
    // Each difference scaled by a power of two to a largest component in [2^499, 2^500)
    // (exact for every input below 2^499): the products of the high parts stay below
    // 2^1002, and every term the result can consist of stays above the denormal range
    // (the cross product of a triangle 2^-1074 wide is 2^-1074 times order one, and
    // would round away unscaled). Only products of two low parts, far below the
    // rounding of the result, may still underflow.
    int scale = 0;
    for (auto* hl : {&uh, &vh}) {
      const int shift = 499 - std::ilogb(hl->cwiseAbs().maxCoeff());
      Vec3<T>& h = *hl;
      Vec3<T>& l = hl == &uh ? ul : vl;
      for (int i = 0; i < 3; ++i) {
        h[i] = detail::timesPowerOfTwo(h[i], shift);
        l[i] = detail::timesPowerOfTwo(l[i], shift);
      }
      scale -= shift;
    }
    const Vec3<T> n = detail::crossOfExpansions(uh, ul, vh, vl);
    if (exponent) {
      *exponent = scale;
      return n;
    }
    return Vec3<T>(detail::timesPowerOfTwo(n[0], scale), detail::timesPowerOfTwo(n[1], scale),
                   detail::timesPowerOfTwo(n[2], scale));
  }
}

namespace detail {
/// At least denorm_min · s (s >= 1), computed without a denormal result: a product or sum
/// that yields or takes a denormal costs a microcode assist on x86 (about a hundred
/// cycles), and the filters below would pay it on every call. It returns the smallest
/// normal number times s: 2^52 times larger, so still a bound, and it only sends values
/// below about 1e-307 · s (already within the rounding of an underflowed product) to the
/// exact stage. Made at compile time: under -frounding-math GCC would otherwise convert
/// the limit's long double literal on the x87 unit at run time.
template <class T>
inline T denormalErrorBound(const T& s) {
  constexpr T smallestNormal = std::numeric_limits<T>::min();
  return smallestNormal * s;
}
}  // namespace detail

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
    constexpr T eps = std::numeric_limits<T>::epsilon() / T(2);
    // Plus the absolute error of results that fall below the normal range (tiny
    // coordinates): at most half a denormal per rounding, times the factor applied after.
    // Bounded without denormal arithmetic (detail::denormalErrorBound): a denormal product
    // costs a microcode assist on x86 (~75 ns, four times the whole filter), on every call.
    const T bound = (T(7) + T(56) * eps) * eps * perm +
                    detail::denormalErrorBound(T(2) * (abs(u[0]) + abs(u[1]) + abs(u[2])) + T(4));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return detail::exactOrient3d(a, b, c, d);
  }
}

namespace detail {
/// The sign of left − right for two products of rounded differences of inputs in T
/// (u_x v_y and u_y v_x, each difference rounded once): +1 or −1 where Shewchuk's
/// ccwerrboundA, (3 + 16 eps) eps with eps the unit roundoff, plus half a denormal of
/// absolute error for each product that falls below the normal range (bounded without
/// denormal arithmetic, as in orient3d), makes it certain; 0 where it cannot tell.
template <class T>
inline int orient2dFilter(const T& left, const T& right) {
  using std::abs;
  const T det = left - right;
  constexpr T eps = std::numeric_limits<T>::epsilon() / T(2);
  const T bound = (T(3) + T(16) * eps) * eps * (abs(left) + abs(right)) + denormalErrorBound(T(2));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 0;
}
}  // namespace detail

/// Exact sign of (b − a) × (c − a) = (bx − ax)(cy − ay) − (by − ay)(cx − ax) for the
/// plane points a = (ax, ay), b, c: > 0 when they turn counter-clockwise. Same method
/// and range as orient3d (see the header comment).
template <class T>
int orient2d(const T& ax, const T& ay, const T& bx, const T& by, const T& cx, const T& cy) {
  if constexpr (ScalarTraits<T>::isExact) {
    return detail::sign(T((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)));
  } else if constexpr (std::is_same<T, float>::value) {
    return orient2d<double>(ax, ay, bx, by, cx, cy);
  } else {
    const T ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
    if (const int f = detail::orient2dFilter<T>(ux * vy, uy * vx)) return f;
    // Both products exactly 0 (a rounded difference is 0 only where the exact one is):
    // points sharing a coordinate, e.g. a contact plane z = 0 seen along an axis, would
    // otherwise reach the exact stage on every call (43% of a resting 1,024-gon query).
    if ((ux == T(0) || vy == T(0)) && (uy == T(0) || vx == T(0))) return 0;
    return detail::exactOrient2d(ax, ay, bx, by, cx, cy);
  }
}

/// orient2d of the projections of a, b, c along axis `dropped` (0, 1 or 2), read in the
/// axes (dropped + 1, dropped + 2) mod 3: the exact sign of component `dropped` of
/// (b − a) × (c − a). A triangle whose three signs (one per dropped axis) are all 0 is
/// degenerate (its corners are collinear).
template <class T>
int orient2d(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, int dropped) {
  const int i = (dropped + 1) % 3, j = (dropped + 2) % 3;
  return orient2d<T>(a[i], a[j], b[i], b[j], c[i], c[j]);
}

}  // namespace mink
