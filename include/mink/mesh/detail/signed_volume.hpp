// mink/mesh/detail/signed_volume.hpp — the exact sign of the signed volume of a closed,
// consistently oriented triangulated surface (one connected component of a mesh).
//
// 6 · volume = Σ over its triangles (a, b, c) of det[a, b, c] = a · (b × c) (divergence
// theorem with the origin as apex; the sum does not depend on the apex for a closed
// surface). Positive: the triangles are counter-clockwise seen from outside.
//   1. Floating-point filter: the sum of the 6 products per triangle in T, with a forward
//      error bound of (N + 2) eps times the sum of their magnitudes (N products); a sum
//      beyond it has the right sign (the common case).
//   2. Otherwise every product a_i b_j c_k is expanded exactly (two-product, then
//      scale-expansion) and all are summed into one non-overlapping expansion
//      (Shewchuk 1997, as orient3d): its largest component carries the sign.
//   3. Underflow, as orient3d: a non-zero coordinate below 2^-306 sends step 2 to long
//      double; float inputs are summed as doubles (exact, they are doubles).
// Exact T sums the determinants directly.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "mink/core/orientation.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {
namespace detail {

/// Exact sign of Σ det[a, b, c] over triangles tris[which[i]] (F: double or long double).
template <class F, class PointAt>
int exactVolumeSign(const std::vector<std::array<int, 3>>& tris, const std::vector<int>& which, PointAt&& point) {
  static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  static const int sgn[6] = {1, 1, 1, -1, -1, -1};
  // Filter.
  F sum = F(0), mag = F(0);
  for (int t : which) {
    const Vec3<F> a = point(tris[t][0]), b = point(tris[t][1]), c = point(tris[t][2]);
    for (int p = 0; p < 6; ++p) {
      const F x = a[perm[p][0]] * b[perm[p][1]] * c[perm[p][2]];
      sum += sgn[p] > 0 ? x : F(-x);
      mag += std::fabs(x);
    }
  }
  const F n = F(6) * F(static_cast<double>(which.size()));
  const F bound = (n + F(2)) * std::numeric_limits<F>::epsilon() * mag + F(3) * n * std::numeric_limits<F>::min();  // a normal bound: see orient3d
  if (sum > bound) return 1;
  if (-sum > bound) return -1;
  // Exact expansion.
  std::vector<F> acc{F(0)}, tmp, prod, term;
  for (int t : which) {
    const Vec3<F> a = point(tris[t][0]), b = point(tris[t][1]), c = point(tris[t][2]);
    for (int p = 0; p < 6; ++p)
      addTripleProduct(acc, a[perm[p][0]], b[perm[p][1]], F(sgn[p] * c[perm[p][2]]), prod, term, tmp);
  }
  return expansionSign(acc);
}

/// Exact sign of 6 · the signed volume of the closed surface made of triangles
/// tris[which[i]] over `vertices`.
template <class T>
int signedVolumeSign(const std::vector<Vec3<T>>& vertices, const std::vector<std::array<int, 3>>& tris,
                     const std::vector<int>& which) {
  if constexpr (ScalarTraits<T>::isExact) {
    T sum = T(0);
    for (int t : which) {
      const Vec3<T>& a = vertices[tris[t][0]];
      sum += a.dot(vertices[tris[t][1]].cross(vertices[tris[t][2]]));
    }
    return detail::sign(sum);
  } else {
    using F = std::conditional_t<std::is_same<T, float>::value, double, T>;
    if constexpr (std::is_same<F, double>::value) {
      bool tiny = false;
      for (int t : which)
        for (int v : tris[t])
          for (int k = 0; k < 3 && !tiny; ++k)
            tiny = needsWiderExponent({static_cast<double>(vertices[v][k])}, -306);
      if (tiny) {
        using L = long double;
        return exactVolumeSign<L>(tris, which, [&](int v) { return Vec3<L>(vertices[v].template cast<L>()); });
      }
    }
    return exactVolumeSign<F>(tris, which, [&](int v) { return Vec3<F>(vertices[v].template cast<F>()); });
  }
}

}  // namespace detail
}  // namespace mink
