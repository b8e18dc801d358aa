// mink/core/detail/spatial_order.hpp — a memory order for points: Morton (Z-curve) order
// of their bounding box, so that points near in space get indices near each other.
//
// Why: the support queries of large shapes (hill-climbs, Dobkin–Kirkpatrick descents) are
// bound by memory reads, not arithmetic. With vertices numbered in the hull's order,
// neighbours sit at random places in the arrays (mean index gap ~n/4 over the edges of a
// 100k-vertex ellipsoid) and every step misses the cache; in this order a walk over the
// surface reads neighbouring cache lines. Any order is correct: this only decides where
// the arrays put things.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {
namespace detail {

/// A permutation (new index -> old index) of `points` in Morton order of their bounding
/// box, 21 bits per axis (coordinates converted to double for the key only). Ties keep
/// the input order. O(n log n).
template <class T>
std::vector<int> mortonOrder(const std::vector<Vec3<T>>& points) {
  const int n = static_cast<int>(points.size());
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const double c = toDouble(points[i][k]);
      lo[k] = i == 0 ? c : std::min(lo[k], c);
      hi[k] = i == 0 ? c : std::max(hi[k], c);
    }
  auto spread = [](std::uint64_t v) {  // bit i of v (i < 21) to bit 3i
    v &= 0x1fffffULL;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  std::vector<std::pair<std::uint64_t, int>> key(n);
  for (int i = 0; i < n; ++i) {
    std::uint64_t code = 0;
    for (int k = 0; k < 3; ++k) {
      const double w = hi[k] - lo[k];
      double u = w > 0 ? (toDouble(points[i][k]) - lo[k]) / w : 0.0;
      if (!(u == u)) u = 0.0;  // inf - inf from an exact value beyond double's range
      code |= spread(static_cast<std::uint64_t>(std::min(std::max(u, 0.0), 1.0) * 2097151.0)) << k;
    }
    key[i] = {code, i};
  }
  std::sort(key.begin(), key.end());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = key[i].second;
  return order;
}

}  // namespace detail
}  // namespace mink
