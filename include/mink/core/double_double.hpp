// mink/core/double_double.hpp — a midpoint-radius interval whose midpoint is a
// double-double (an unevaluated sum hi + lo of two doubles, about 106 significant bits):
// a filter stage between the double intervals of expansion.hpp and the exact expansions,
// for predicates of high degree whose value is not zero but lies below the rounding of
// their terms in double (a point of a mesh's Minkowski sum off a plane by one rounding of
// its inputs). Such a value is about 2^-53 of its terms; this interval's width is about
// 2^-100 of them, so it names the sign at a few times the cost of a double interval,
// where an expansion of a degree-9 polynomial costs tens of thousands of instructions.
//
// Every operation keeps the exact value inside [hi + lo − r, hi + lo + r]:
//   * TwoSum and TwoProd are error-free (Knuth; Dekker's product by Veltkamp splitting, or
//     one fused multiply-add where the target has it), so the only roundings are those of
//     the few low-order terms added below, bounded in the comments of operator+ and
//     operator* by multiples of u^2 = 2^-106 times the operands' high parts;
//   * the radius is carried in double and rounded upwards by a relative factor
//     (1 + 2^-40) that covers the roundings of its own few operations, plus an absolute
//     4 · DBL_MIN for the products' low parts lost to underflow;
//   * an overflow makes the radius infinite or a part NaN, and certainSign() then says 0
//     (the caller's exact stage decides).
// Needs double arithmetic evaluated in double, as written (FLT_EVAL_METHOD == 0: SSE2,
// AArch64; not -ffast-math); elsewhere kDoubleDoubleExact is false and callers skip this
// stage.
#pragma once

#include <cfloat>
#include <cmath>
#include <limits>

namespace mink {
namespace detail {

/// Whether this target evaluates double operations in double, as written (the error-free
/// transformations below need it: no wider registers, no reassociation by -ffast-math).
inline constexpr bool kDoubleDoubleExact =
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0 && !defined(__FAST_MATH__)
    std::numeric_limits<double>::is_iec559;
#else
    false;
#endif

/// s + e = a + b exactly, s = fl(a + b) (Knuth's TwoSum: no condition on the order).
inline void twoSum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

/// p + e = a · b exactly, p = fl(a · b), unless the product overflows (then a part is not
/// finite) or its low part falls below the subnormal range.
inline void twoProd(double a, double b, double& p, double& e) {
  p = a * b;
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  e = std::fma(a, b, -p);
#else
  // Veltkamp's split into 26 + 27 bits, then Dekker's exact product of the halves.
  constexpr double kSplit = 134217729.0;  // 2^27 + 1
  const double ca = kSplit * a, cb = kSplit * b;
  const double ah = ca - (ca - a), al = a - ah;
  const double bh = cb - (cb - b), bl = b - bh;
  e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
#endif
}

/// A real number known to lie in [mid − r, mid + r], mid = hi + lo a normalised
/// double-double (|lo| <= ulp(hi) / 2). The operations of a predicate's template
/// (construction from a double, +, −, ×, negation) and certainSign().
class DoubleDoubleInterval {
  using DDI = DoubleDoubleInterval;

 public:
  DoubleDoubleInterval() = default;
  DoubleDoubleInterval(double x) : hi_(x) {}  // NOLINT: an exact number is a point interval

  double hi() const { return hi_; }
  double lo() const { return lo_; }
  double radius() const { return r_; }

  /// +1 / −1 when every value in the interval has that sign, 0 otherwise (also for an
  /// interval that overflowed).
  int certainSign() const {
    // |lo| <= 2^-53 |hi|, so |hi| (1 − 2^-40) > r puts hi + lo ± r on hi's side of 0.
    const double m = std::fabs(hi_);
    if (!(m * (1.0 - kInflate) > r_) || !(m <= DBL_MAX)) return 0;
    return hi_ > 0.0 ? 1 : -1;
  }

  friend DDI operator+(const DDI& a, const DDI& b) {
    // Exact: sh + sl = a.hi + b.hi, th + tl = a.lo + b.lo, vh + vl = sh + c, and the final
    // TwoSum. Rounded: c = fl(sl + th), off by <= u (|sl| + |th|) <= 2.01 u^2 M, and
    // w = fl(tl + vl), off by <= u (|tl| + |vl|) <= 1.01 u^2 M, with u = 2^-53 and
    // M = |a.hi| + |b.hi| (|sl| <= u |sh|, |th| <= u (1 + u) M, |vl| <= u |vh|). So the
    // midpoint is off by < 4 u^2 M = 2^-104 M.
    double sh, sl, th, tl, vh, vl;
    twoSum(a.hi_, b.hi_, sh, sl);
    twoSum(a.lo_, b.lo_, th, tl);
    const double c = sl + th;
    twoSum(sh, c, vh, vl);
    const double w = tl + vl;
    DDI z;
    twoSum(vh, w, z.hi_, z.lo_);
    z.r_ = (a.r_ + b.r_ + kU2x4 * (std::fabs(a.hi_) + std::fabs(b.hi_))) * (1.0 + kInflate) + kTiny;
    return z;
  }
  friend DDI operator-(const DDI& a) {
    DDI z;
    z.hi_ = -a.hi_;
    z.lo_ = -a.lo_;
    z.r_ = a.r_;
    return z;
  }
  friend DDI operator-(const DDI& a, const DDI& b) { return a + (-b); }
  DDI& operator+=(const DDI& b) { return *this = *this + b; }
  DDI& operator-=(const DDI& b) { return *this = *this - b; }

  friend DDI operator*(const DDI& a, const DDI& b) {
    // Exact: ph + pl = a.hi · b.hi, and the final TwoSum. With P = |a.hi| |b.hi| and
    // |a.lo| <= u |a.hi|, |b.lo| <= u |b.hi|: the two cross products are each <= u P and
    // rounded by <= u^2 P each, their sum t by <= 2.01 u^2 P more, a.lo · b.lo (<= u^2 P)
    // is left out, and c = fl(pl + t) is off by <= u (|pl| + |t|) <= 3.02 u^2 P: the
    // midpoint is off by <= 8.03 u^2 P, bounded as 16 u^2 P = 2^-102 P (P itself rounded).
    double ph, pl;
    twoProd(a.hi_, b.hi_, ph, pl);
    const double t = a.hi_ * b.lo_ + a.lo_ * b.hi_;
    const double c = pl + t;
    DDI z;
    twoSum(ph, c, z.hi_, z.lo_);
    // |x y − mid(a) mid(b)| <= |mid(a)| b.r + |mid(b)| a.r + a.r b.r, |mid| <= (1 + u) |hi|:
    // the (1 + u) and the radius's own roundings are inside the inflation (1 + 2^-40).
    const double ah = std::fabs(a.hi_), bh = std::fabs(b.hi_);
    z.r_ = (ah * b.r_ + bh * a.r_ + a.r_ * b.r_ + kU2x16 * (ah * bh)) * (1.0 + kInflate) + kTiny;
    return z;
  }

 private:
  static constexpr double kInflate = 0x1p-40;
  static constexpr double kU2x4 = 0x1p-104;
  static constexpr double kU2x16 = 0x1p-102;
  // Products' error terms lost to underflow (a few subnormal units per operation), and a
  // 2^-104 M that underflowed itself.
  static constexpr double kTiny = 4.0 * DBL_MIN;

  double hi_ = 0.0, lo_ = 0.0, r_ = 0.0;
};

}  // namespace detail
}  // namespace mink
