// mink/mesh/detail/enclosing_sphere.hpp — conservative enclosing spheres of a few points:
// the spheres of the bounding-sphere hierarchy (mesh/sphere_tree.hpp) and the tight
// sphere of the Minkowski sum of two triangles that CPD's culling needs (9 points).
//
// Source: E. Welzl, "Smallest enclosing disks (balls and ellipsoids)", LNCS 555 (1991),
// move-to-front form as in B. Gärtner, "Fast and robust smallest enclosing balls" (ESA 1999).
//   1. The centre is found in double: Welzl's recursion, the ball of the current support
//      set (1 to 4 points on its boundary) grown by each point that lies outside it.
//   2. The centre is rounded to T (dyadic for exact T, so that later exact arithmetic
//      on it stays cheap).
//   3. The radius is then measured from that centre over every point and rounded up
//      (conservativeRadius): the sphere encloses every point whatever step 1 found, so
//      step 1 only decides how tight it is, never whether it is correct.
// Guarantee: |p − centre| <= radius for every point p, exactly (for exact T, checked in
// exact arithmetic; for floating T, by a forward error bound on the rounded distances).
// Exact T needs coordinates within the double range (every mesh built from doubles).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {

/// A ball: every point it stands for lies within `radius` of `centre` (same frame and
/// length unit as the points). Radii are upper bounds, rounded up, never down.
template <class T>
struct Sphere {
  Vec3<T> centre = Vec3<T>::Zero();
  T radius = T(0);
};

namespace detail {

/// The smallest radius r of the scalar type with |p − centre| <= r for the n points
/// point(0), ..., point(n − 1), or an upper bound within a few ulps of it (floating T:
/// the distances are measured on differences scaled by a power of two, so nothing
/// underflows or overflows, and the square root is rounded up with a forward error
/// bound; exact T: the exact maximal squared distance d², and a dyadic r with r² >= d²
/// checked exactly).
template <class T, class PointAt>
T conservativeRadius(const Vec3<T>& centre, int n, PointAt&& point) {
  if constexpr (ScalarTraits<T>::isExact) {
    T d2 = T(0);
    for (int i = 0; i < n; ++i) {
      const Vec3<T> d = point(i) - centre;
      const T s = d.squaredNorm();
      if (s > d2) d2 = s;
    }
    if (d2 == T(0)) return T(0);
    const double approx = toDouble(d2);
    if (std::isfinite(approx)) {
      // to_double is within an ulp or two of d²; the margin covers that and the sqrt.
      double r = std::nextafter(std::sqrt(approx) * (1.0 + std::ldexp(1.0, -40)), HUGE_VAL);
      for (int attempt = 0; attempt < 64 && std::isfinite(r); ++attempt, r *= 1.0 + std::ldexp(1.0, -20)) {
        const T R(r);
        if (R * R >= d2) return R;
      }
    }
    // Beyond the double range: the L1 distance bounds the Euclidean one, exactly.
    T r1 = T(0);
    for (int i = 0; i < n; ++i) {
      const Vec3<T> d = point(i) - centre;
      const T s = absValue(T(d[0])) + absValue(T(d[1])) + absValue(T(d[2]));
      if (s > r1) r1 = s;
    }
    return r1;
  } else {
    using std::abs;
    // fl(p − c) is 0 only when p == c exactly (Sterbenz), so big == 0 means radius 0.
    T big = T(0);
    for (int i = 0; i < n; ++i) {
      const Vec3<T> p = point(i);
      for (int k = 0; k < 3; ++k) big = std::max(big, T(abs(T(p[k] - centre[k]))));
    }
    if (!(big > T(0))) return T(0);
    const int e = std::ilogb(big);
    T m2 = T(0);
    for (int i = 0; i < n; ++i) {
      const Vec3<T> p = point(i);
      T s = T(0);
      for (int k = 0; k < 3; ++k) {
        const T d = std::ldexp(T(p[k] - centre[k]), -e);  // |d| < 2, the largest >= 1
        s += d * d;
      }
      m2 = std::max(m2, s);
    }
    // Each difference is within one rounding of the true one, the sum of three squares
    // within four more, and components lost to underflow (below 2^-1074 against a
    // largest one >= 1) weigh less than one of them: 16 eps covers all of it, the sqrt
    // and this product; next-up covers ldexp rounding into the denormal range.
    const T eps = std::numeric_limits<T>::epsilon();
    const T r = std::ldexp(std::sqrt(m2) * (T(1) + T(16) * eps), e);
    return std::nextafter(r, std::numeric_limits<T>::infinity());
  }
}

/// Conservative radius of the sphere about `centre` through the listed points.
template <class T>
T conservativeRadius(const Vec3<T>& centre, const Vec3<T>* points, int n) {
  return conservativeRadius(centre, n, [&](int i) -> const Vec3<T>& { return points[i]; });
}

/// A double approximation of x rounded back to T: exact T keeps dyadic centres (cheap
/// exact arithmetic later); floating T is unchanged.
template <class T>
Vec3<T> dyadicCentre(const Vec3<T>& x) {
  if constexpr (ScalarTraits<T>::isExact) {
    Vec3<T> c;
    for (int k = 0; k < 3; ++k) {
      const double d = toDouble(x[k]);
      if (!std::isfinite(d)) return x;
      c[k] = T(d);
    }
    return c;
  } else {
    return x;
  }
}

template <class T>
Vec3<double> toDouble3(const Vec3<T>& x) {
  return Vec3<double>(toDouble(x[0]), toDouble(x[1]), toDouble(x[2]));
}

/// Welzl's smallest enclosing ball in double (centre and squared radius), for the
/// centre only (see the header comment).
class WelzlBall {
 public:
  /// A point within this relative distance of the current ball's boundary counts as
  /// inside it: otherwise rounding alone would put points that lie on the sphere
  /// (coplanar, cocircular) into the support set, whose ball is then ill-conditioned.
  /// It only moves the centre by about that much; the radius is measured afterwards.
  static constexpr double kBoundarySlack = 64 * std::numeric_limits<double>::epsilon();
  /// A support set of three (four) points whose triangle area squared (tetrahedron
  /// volume) is below this relative size is collinear (coplanar) within rounding: its
  /// circumsphere would be meaningless, and the ball of its farthest pair is used.
  static constexpr double kFlatSupport = 1024 * std::numeric_limits<double>::epsilon();

  static void run(const Vec3<double>* pts, int n, Vec3<double>& centre, double& r2) {
    Vec3<double> support[4];
    solve(pts, n, support, 0, centre, r2);
  }

 private:
  static void solve(const Vec3<double>* pts, int n, Vec3<double>* support, int ns, Vec3<double>& c, double& r2) {
    ballOf(support, ns, c, r2);
    if (ns == 4) return;
    for (int i = 0; i < n; ++i) {
      if ((pts[i] - c).squaredNorm() <= r2 * (1.0 + kBoundarySlack)) continue;
      // pts[i] lies on the boundary of the smallest ball of pts[0..i] with the support.
      support[ns] = pts[i];
      solve(pts, i, support, ns + 1, c, r2);
    }
  }

  // The smallest ball with the ns support points on its boundary; an ill-conditioned
  // support set (collinear or coplanar within rounding) falls back to the ball of its
  // two farthest points.
  static void ballOf(const Vec3<double>* s, int ns, Vec3<double>& c, double& r2) {
    if (ns == 0) {
      c = Vec3<double>::Zero();
      r2 = -1.0;
      return;
    }
    if (ns == 1) {
      c = s[0];
      r2 = 0.0;
      return;
    }
    const Vec3<double> u = s[1] - s[0];
    bool ok = true;
    if (ns == 2) {
      c = s[0] + 0.5 * u;
    } else if (ns == 3) {
      const Vec3<double> v = s[2] - s[0], w = u.cross(v);
      const double w2 = w.squaredNorm();
      ok = w2 > kFlatSupport * u.squaredNorm() * v.squaredNorm();
      if (ok) c = s[0] + (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u)) / (2.0 * w2);
    } else {
      const Vec3<double> v = s[2] - s[0], w = s[3] - s[0];
      const double det = u.dot(v.cross(w));
      ok = std::abs(det) > kFlatSupport * u.norm() * v.norm() * w.norm();
      if (ok)
        c = s[0] + (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) + w.squaredNorm() * u.cross(v)) /
                       (2.0 * det);
    }
    if (!ok) {
      int bi = 0, bj = 1;
      double best = -1.0;
      for (int i = 0; i < ns; ++i)
        for (int j = i + 1; j < ns; ++j)
          if ((s[i] - s[j]).squaredNorm() > best) best = (s[i] - s[j]).squaredNorm(), bi = i, bj = j;
      c = 0.5 * (s[bi] + s[bj]);
    }
    r2 = 0.0;
    for (int i = 0; i < ns; ++i) r2 = std::max(r2, (s[i] - c).squaredNorm());
  }
};

/// A tight sphere enclosing the n points (n small: it is meant for up to about 16; the
/// recursion is exponential in the worst case): Welzl's centre in double, then the
/// conservative radius from that centre (see the header comment).
template <class T>
Sphere<T> enclosingSphere(const Vec3<T>* points, int n) {
  Sphere<T> s;
  if (n <= 0) return s;
  constexpr int kStack = 16;
  Vec3<double> local[kStack];
  std::vector<Vec3<double>> heap;
  Vec3<double>* pd = local;
  if (n > kStack) {
    heap.resize(static_cast<std::size_t>(n));
    pd = heap.data();
  }
  for (int i = 0; i < n; ++i) pd[i] = toDouble3(points[i]);
  Vec3<double> c;
  double r2 = 0.0;
  WelzlBall::run(pd, n, c, r2);
  bool finite = std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]);
  s.centre = finite ? Vec3<T>(T(c[0]), T(c[1]), T(c[2])) : points[0];
  s.radius = conservativeRadius(s.centre, points, n);
  return s;
}

/// The smallest sphere of a triangle: its circumsphere when the triangle is acute, else
/// the sphere on its longest side (the angle-based choice is decided in T: exactly for
/// exact T), with a conservative radius. The centre is computed in T (dyadic for exact T).
template <class T>
Sphere<T> triangleSphere(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  const Vec3<T> u = b - a, v = c - a, w = c - b;
  const T lu = u.squaredNorm(), lv = v.squaredNorm(), lw = w.squaredNorm();
  const bool acute = u.dot(v) > T(0) && T(-u.dot(w)) > T(0) && v.dot(w) > T(0);
  Vec3<T> centre;
  const Vec3<T> n = u.cross(v);
  const T n2 = n.squaredNorm();
  if (acute && n2 > T(0)) {
    centre = a + (v.cross(n) * lu + n.cross(u) * lv) / (T(2) * n2);
  } else if (lu >= lv && lu >= lw) {
    centre = (a + b) / T(2);
  } else if (lv >= lw) {
    centre = (a + c) / T(2);
  } else {
    centre = (b + c) / T(2);
  }
  Sphere<T> s;
  s.centre = dyadicCentre(centre);
  const Vec3<T> pts[3] = {a, b, c};
  s.radius = conservativeRadius(s.centre, pts, 3);
  return s;
}

}  // namespace detail
}  // namespace mink
