// mink/core/scalar_traits.hpp — what an algorithm may assume about its scalar T.
//
// mink runs one template on float, double, long double and exact rational types
// (CGAL::Gmpq, boost::multiprecision::mpq_rational, ...). Every decision is the sign
// of a polynomial in the input coordinates; tolerances only widen those signs for
// inexact scalars and are exactly zero for exact ones. Following Eigen's NumTraits
// habit, the precision-dependent defaults come from this traits class: specialise it
// for a custom scalar (e.g. an MPFR float: isExact = false, epsilon() = its ulp).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

namespace mink {

template <class T, class Enable = void>
struct ScalarTraits {
  /// Arithmetic is exact: +, -, *, / never round. No sqrt is ever called on such a T.
  static constexpr bool isExact = !std::is_floating_point<T>::value;
  /// Unit roundoff (0 for an exact type).
  static T epsilon() {
    if constexpr (isExact) {
      return T(0);
    } else {
      return Eigen::NumTraits<T>::epsilon();
    }
  }
  /// The largest magnitude of an input coordinate (or translation) that the exact
  /// predicates and the degeneracy tests handle without overflow of any intermediate
  /// value: 2^(0.29 · max_exponent), about 1.3e89 for double and 1.4e11 for float;
  /// exact types have no limit. (Tiny coordinates are accepted: orient3d stays exact
  /// on them, see core/orientation.hpp.)
  static T largestCoordinate() {
    if constexpr (isExact) {
      return T(0);
    } else {
      return std::ldexp(T(1), static_cast<int>(0.29 * std::numeric_limits<T>::max_exponent));
    }
  }
  /// x is finite and at most largestCoordinate() in magnitude.
  static bool inCoordinateRange(const T& x) {
    if constexpr (isExact) {
      (void)x;
      return true;
    } else {
      using std::abs;
      return abs(x) <= largestCoordinate();
    }
  }
  static bool isFinite(const T& x) {
    if constexpr (isExact) {
      (void)x;
      return true;
    } else {
      using std::isfinite;
      return isfinite(x);
    }
  }
};

namespace detail {

template <class T>
T absValue(const T& x) {
  if constexpr (std::is_floating_point<T>::value)
    return std::fabs(x);  // one instruction (the sign bit cleared); +0 for -0
  else
    return x < T(0) ? T(-x) : x;
}

template <class T>
int sign(const T& x) {
  return (T(0) < x) - (x < T(0));
}

/// `x` as a double (rounded): a plain conversion for the built-in scalars and for types
/// with an explicit one, otherwise `to_double(x)` found by argument-dependent lookup
/// (CGAL number types). For reported values and for conservative bounds that are checked
/// exactly afterwards, never for a decision.
template <class T>
double toDouble(const T& x) {
  if constexpr (std::is_constructible<double, const T&>::value) {
    return static_cast<double>(x);
  } else {
    return to_double(x);
  }
}

/// Euclidean length, for inexact scalars only (reported values and tolerance scaling).
template <class Derived>
typename Derived::Scalar norm(const Eigen::MatrixBase<Derived>& v) {
  static_assert(!ScalarTraits<typename Derived::Scalar>::isExact,
                "mink: sqrt must not be taken on an exact scalar");
  return v.norm();
}

/// Is d·(w − v) > 0 beyond its rounding (for exact T: exactly > 0)? For vertices whose
/// values d·v and d·w tie in floating point across an edge shorter than their rounding:
/// the difference of two close vertices is exact and its dot product accurate, while a
/// real tie (d normal to the edge) leaves a difference of pure rounding, which is refused.
template <class T>
bool surelyUphill(const Eigen::Matrix<T, 3, 1>& d, const Eigen::Matrix<T, 3, 1>& v, const Eigen::Matrix<T, 3, 1>& w) {
  const Eigen::Matrix<T, 3, 1> e = w - v;
  const T g = d.dot(e);
  if constexpr (ScalarTraits<T>::isExact) {
    return g > T(0);
  } else {
    const T bound = T(4) * ScalarTraits<T>::epsilon() *
                    (absValue(d[0] * e[0]) + absValue(d[1] * e[1]) + absValue(d[2] * e[2]));
    return g > bound;
  }
}

/// 2^k x for an inexact scalar: the bits of ldexp(x, k). For |k| <= 62 a product with
/// the power of two, which is exact wherever ldexp is and rounds once, to nearest, where
/// the result is subnormal (as ldexp does): no call into libm on the hot path.
template <class T>
T timesPow2(const T& x, int k) {
  static_assert(!ScalarTraits<T>::isExact, "timesPow2(scalar): inexact scalars only");
  if (k == 0) return x;
  if (k >= -62 && k <= 62) {
    // 2^k itself: its IEEE bits for double and float (no division on the hot path), an
    // exact quotient otherwise.
    if constexpr (std::is_same<T, double>::value && std::numeric_limits<double>::is_iec559) {
      const std::uint64_t bits = static_cast<std::uint64_t>(1023 + k) << 52;
      double p;
      std::memcpy(&p, &bits, sizeof p);
      return x * p;
    } else if constexpr (std::is_same<T, float>::value && std::numeric_limits<float>::is_iec559) {
      const std::uint32_t bits = static_cast<std::uint32_t>(127 + k) << 23;
      float p;
      std::memcpy(&p, &bits, sizeof p);
      return x * p;
    } else {
      return k > 0 ? x * T(std::uint64_t(1) << k) : x * (T(1) / T(std::uint64_t(1) << -k));
    }
  }
  using std::ldexp;
  return ldexp(x, k);
}

/// 2^k v, componentwise ldexp (exact unless a component leaves the normal range), for
/// inexact scalars; v itself for exact scalars.
template <class T>
Eigen::Matrix<T, 3, 1> timesPow2(const Eigen::Matrix<T, 3, 1>& v, int k) {
  if constexpr (ScalarTraits<T>::isExact) {
    (void)k;
    return v;
  } else {
    return Eigen::Matrix<T, 3, 1>(timesPow2(v[0], k), timesPow2(v[1], k), timesPow2(v[2], k));
  }
}

/// v scaled by a power of two (exact) so that its largest |component| is in [1, 2), for
/// inexact scalars; v itself for exact scalars and for zero. The direction of a vector
/// of 1e-232 (a portal edge between shapes 1e-236 wide) or of 1e172 (the normal of
/// 1e86-long edges) survives where its norm, dot products or their products would
/// underflow or overflow.
template <class T>
Eigen::Matrix<T, 3, 1> unitOrder(const Eigen::Matrix<T, 3, 1>& v) {
  if constexpr (ScalarTraits<T>::isExact) {
    return v;
  } else {
    const T big = v.cwiseAbs().maxCoeff();
    if (!(big > T(0)) || !ScalarTraits<T>::isFinite(big)) return v;
    using std::ilogb;
    return timesPow2(v, -static_cast<int>(ilogb(big)));
  }
}

}  // namespace detail
}  // namespace mink
