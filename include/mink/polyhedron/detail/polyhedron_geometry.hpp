// mink/polyhedron/detail/polyhedron_geometry.hpp — the numbers behind shape construction:
// input checks, the hull tolerance, face widths and normals (Newell, accurate cross
// products), exact planarity. Base of PolyhedronFinish and PolyhedronBuilder
// (convex_polyhedron_impl.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "mink/core/detail/input_checks.hpp"
#include "mink/core/orientation.hpp"

namespace mink {
namespace detail {

template <class T>
struct PolyhedronGeometry {
  using Poly = ConvexPolyhedron<T>;
  using Loop = std::vector<int>;

  static std::uint64_t key(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }

  static T extentOf(const std::vector<Vec3<T>>& pts) {
    Vec3<T> m = Vec3<T>::Zero();
    for (const auto& p : pts)
      for (int k = 0; k < 3; ++k) m[k] = std::max(m[k], absValue(p[k]));
    return m[0] + m[1] + m[2];
  }

  /// The tolerance the build uses, in `tol`, or the Error for a bad options.tolerance.
  [[nodiscard]] static Error toleranceFor(const HullOptions<T>& options, const T& extent, const char* who, T& tol) {
    if constexpr (ScalarTraits<T>::isExact) {
      tol = T(0);
      if (options.tolerance > T(0))
        return Error(std::string(who) + ": a positive tolerance needs an inexact scalar type; "
                                        "exact scalars decide exactly (tolerance 0)");
    } else {
      if (!ScalarTraits<T>::isFinite(options.tolerance)) return Error(std::string(who) + ": tolerance is not finite");
      tol = options.tolerance >= T(0) ? options.tolerance
                                      : T(defaults::kHullToleranceFactor) * ScalarTraits<T>::epsilon() * extent;
    }
    return Error();
  }

  [[nodiscard]] static Error checkFinite(const std::vector<Vec3<T>>& pts, const char* who, const char* what) {
    return checkCoordinates(pts, who, what);
  }

  /// |(b − o) × (c − o)| as len · 2^exp, to compare triangles without underflow (the
  /// cross product of a triangle 1e-185 by 1e-300 is below the double range).
  struct Width {
    T len = T(0);
    int exp = 0;
    bool operator>(const Width& w) const {
      if (!(len > T(0))) return false;
      if (!(w.len > T(0))) return true;
      if constexpr (ScalarTraits<T>::isExact) {
        return len > w.len;
      } else {
        return len > std::ldexp(w.len, w.exp - exp);
      }
    }
  };
  /// A key ordering widths as Width::operator> does (exactly, where that rounds).
  static std::pair<int, T> sizeKey(const Width& w) {
    if (!(w.len > T(0))) return {std::numeric_limits<int>::min(), T(0)};
    if constexpr (ScalarTraits<T>::isExact) {
      return {0, w.len};
    } else {
      const int e = std::ilogb(w.len);
      return {w.exp + e, std::ldexp(w.len, -e)};
    }
  }
  static Width width(const Vec3<T>& o, const Vec3<T>& b, const Vec3<T>& c, Vec3<T>* normal = nullptr) {
    Width w;
    Vec3<T> n;
    if constexpr (ScalarTraits<T>::isExact) {
      n = (b - o).cross(c - o);
      w.len = n.squaredNorm();
    } else {
      n = accurateCross(o, b, c, &w.exp);
      w.len = n.stableNorm();
    }
    if (normal) *normal = n;
    return w;
  }

  // Normal of a loop: for exact T its Newell normal; otherwise, for an exactly planar
  // loop, the accurate cross product of its widest fan triangle from the first corner
  // (about one ulp per component, where the textbook Newell sum loses every digit on
  // sliver faces), and for a non-planar loop (fromMesh, within its tolerance) the Newell
  // normal of the whole loop.
  /// `size` (optional): the face's size, to order faces by.
  static Vec3<T> newell(const std::vector<Vec3<T>>& pts, const Loop& loop, Width* size = nullptr) {
    const Vec3<T>& o = pts[loop[0]];
    Width dummy;
    Width& widest = size ? *size : dummy;
    widest = Width();
    if constexpr (ScalarTraits<T>::isExact) {
      // Exact already: the Newell normal (the documented one for exact T).
      Vec3<T> n = Vec3<T>::Zero();
      for (std::size_t i = 1; i + 1 < loop.size(); ++i) n += (pts[loop[i]] - o).cross(pts[loop[i + 1]] - o);
      widest.len = n.squaredNorm();
      return n;
    } else {
      // The widest fan triangle's normal, scaled to order one (a face too small for its
      // normal to be a double, 1e-185 by 1e-300, keeps its direction).
      // The mantissa n is |cross| / (2^-998 |u| |v|) (u, v: the fan triangle's edges at
      // its corner), so a needle seen from its sharp corner can still underflow (a
      // triangle 2^286 long whose short edge is 2^-783: its angle there is 2^-2138, the
      // one at the short edge 2^-1069). Then the fans from the other corners are tried,
      // until one gives n clear of the denormal range (about one ulp per component).
      Vec3<T> best = Vec3<T>::Zero(), n;
      const std::size_t m = loop.size();
      const T reliable = std::ldexp(T(1), std::numeric_limits<T>::min_exponent - 1 + std::numeric_limits<T>::digits);
      for (std::size_t s = 0; s < m; ++s) {
        const Vec3<T>& os = pts[loop[s]];
        Width w0;
        Vec3<T> b0 = Vec3<T>::Zero();
        for (std::size_t i = 1; i + 1 < m; ++i) {
          const Width w = width(os, pts[loop[(s + i) % m]], pts[loop[(s + i + 1) % m]], &n);
          if (w > w0) {
            w0 = w;
            b0 = n;
          }
        }
        if (s == 0 || (!(widest.len > T(0)) && w0.len > T(0))) {
          widest = w0;
          best = b0;
        }
        if (b0.cwiseAbs().maxCoeff() >= reliable) {
          widest = w0;
          best = b0;
          break;
        }
      }
      if (loop.size() == 3) return best;
      Vec3<T> sum = Vec3<T>::Zero();
      for (std::size_t i = 1; i + 1 < loop.size(); ++i) sum += (pts[loop[i]] - o).cross(pts[loop[i + 1]] - o);
      // Prefer the accurate triangle normal when the loop is exactly planar.
      return isExactlyPlanar(pts, loop) ? best : sum;
    }
  }


  static bool isExactlyPlanar(const std::vector<Vec3<T>>& pts, const Loop& loop) {
    // The widest fan triangle spans the plane; every corner must be on it exactly.
    std::size_t k = 2;
    const Vec3<T>& o = pts[loop[0]];
    for (std::size_t i = 2; i < loop.size(); ++i)
      if (width(o, pts[loop[1]], pts[loop[i]]) > width(o, pts[loop[1]], pts[loop[k]])) k = i;
    // The three spanning corners are on it by definition (and would each cost the exact
    // stage, since their determinant is exactly zero).
    for (std::size_t i = 2; i < loop.size(); ++i)
      if (i != k && orient3d(o, pts[loop[1]], pts[loop[k]], pts[loop[i]]) != 0) return false;
    return true;
  }

  // Normal used for distance tests: unit for inexact T, exact Newell normal otherwise.
  static Vec3<T> testNormal(const Vec3<T>& n) {
    if constexpr (ScalarTraits<T>::isExact) {
      return n;
    } else {
      const T len = magnitude(n);
      return len > T(0) ? Vec3<T>(n / len) : n;
    }
  }

  /// An increasing function of |n|: |n| itself, without underflow or overflow, for
  /// inexact T; |n|^2 for exact T.
  static T magnitude(const Vec3<T>& n) {
    if constexpr (ScalarTraits<T>::isExact) {
      return n.squaredNorm();
    } else {
      return n.stableNorm();
    }
  }

};

}  // namespace detail
}  // namespace mink
