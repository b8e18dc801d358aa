// mink/mdd/detail/difference_polygon.hpp — the vertices of conv(A) ⊕ −conv(B) for two
// finite sets A, B of 2-D points, as index pairs (i, j) with a_i − b_j a vertex, in
// counter-clockwise order, in O(m log m + n log n) time:
//   1. the convex hull of each set (A. M. Andrew's monotone chain, collinear points
//      dropped), counter-clockwise from its lowest vertex;
//   2. the merge of the two edge sequences by polar angle (the Minkowski sum of two
//      convex polygons: de Berg, Cheong, van Kreveld, Overmars, "Computational
//      Geometry", 3rd ed., section 13.3), which visits every vertex of the sum once.
// A facet of M = P ⊕ −Q is the difference of the support sets of P and Q; two resting
// n-gons give sets of n points each. The hull of all n² differences cost n² log n, and
// the grazing interval read off all pairs of them n⁴ (seconds at n = 256): the candidate
// vertices are at most m + n.
// Every decision is exact on the coordinates given (the hulls' turns are orient2d signs,
// the merge's order of two edges the exact sign of their cross product): with rounded
// products, nearly parallel edges of the two polygons were misordered and the pairs
// named points inside the sum, missing some of its vertices.
// A set already in cyclic order around a strictly convex polygon (a support set that is
// one face of a shape, in the face's order) skips step 1's sort: convexCycleOrientation
// checks the order with exact turns in O(m), so two resting faces cost O(m + n).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/difference_orientation.hpp"
#include "mink/core/orientation.hpp"
#include "mink/core/scalar_traits.hpp"

namespace mink {
namespace detail {

/// Exact sign of (p1 − p0) × (q1 − q0) for points of the plane (coordinate pairs): the
/// order of two edges' directions, decided on the points given (the rounded differences
/// would misorder nearly parallel edges). For double, orient2d's filter first (its bound
/// holds for any two rows of rounded differences of inputs); where it cannot tell,
/// orientDiff with the unit z vector as its third difference.
template <class T>
int crossOfDifferencesSign(const std::pair<T, T>& p0, const std::pair<T, T>& p1, const std::pair<T, T>& q0,
                           const std::pair<T, T>& q1) {
  if constexpr (std::is_same<T, double>::value) {
    if (const int f = orient2dFilter<T>((p1.first - p0.first) * (q1.second - q0.second),
                                     (p1.second - p0.second) * (q1.first - q0.first)))
      return f;
  }
  auto lift = [](const std::pair<T, T>& x) { return Vec3<T>(x.first, x.second, T(0)); };
  return orientDiff<T>(lift(p0), lift(p1), lift(q0), lift(q1), Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(0), T(0), T(1)));
}

/// 0 for a direction (dx, dy) with polar angle in [0, π), 1 for [π, 2π) (the zero vector:
/// 1). Exact for a rounded difference q − p, whose signs (and zeros) are the exact one's.
template <class T>
int halfPlaneOf(const T& dx, const T& dy) {
  return (dy > T(0) || (dy == T(0) && dx > T(0))) ? 0 : 1;
}

/// The orientation of the closed polygon p_0 ... p_{n-1} (point(k) returns p_k as a pair of
/// coordinates) if it is strictly convex in that order: +1 counter-clockwise, -1 clockwise;
/// 0 if it is not (fewer than three points, a straight or reversed turn, or turns all one
/// way that wind round the polygon more than once, as a star does). Exact on the
/// coordinates given: each turn is an orient2d sign; the winding is the number of edges
/// whose direction passes from the upper half-plane [0, pi) to the lower one, read off the
/// signs of the edges' rounded differences (rounding keeps a difference's sign, and its
/// zero). A polygon it accepts is its own convex hull, so a caller holding points in
/// cyclic order (a face's vertices) gets the hull in O(n), without sorting.
template <class T, class PointAt>
int convexCycleOrientation(std::size_t n, const PointAt& point) {
  if (n < 3) return 0;
  auto a = point(n - 1), b = point(0);
  int before = halfPlaneOf(T(b.first - a.first), T(b.second - a.second));
  int orientation = 0, wraps = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const auto c = point(k + 1 < n ? k + 1 : 0);
    // Each step turns by less than pi, so it cannot pass over a whole half-plane: with
    // every turn one way, the half changes 0 -> 1 exactly once per turn round.
    const int o = orient2d<T>(a.first, a.second, b.first, b.second, c.first, c.second);
    if (o == 0 || (orientation != 0 && o != orientation)) return 0;
    orientation = o;
    const int after = halfPlaneOf(T(c.first - b.first), T(c.second - b.second));
    wraps += before == 0 && after == 1;
    before = after;
    a = b;
    b = c;
  }
  return wraps == 1 ? orientation : 0;
}

template <class T>
class DifferencePolygon {
 public:
  using P2 = std::pair<T, T>;

  /// The two point sets; the caller fills them (coordinates relative to any common
  /// origin per set: the result depends only on the shapes of the sets).
  std::vector<P2> a, b;

  /// pairs := (i, j) such that a_i − b_j are the vertices of conv(a) ⊕ −conv(b),
  /// counter-clockwise (one pair for two single points, two for segments). Both sets
  /// must be non-empty.
  void compute() {
    hull(a, false, ha_);
    hull(b, true, hb_);
    pairs.clear();
    const std::size_t m = ha_.size(), n = hb_.size();
    // A polygon of one vertex has no edge; one of two (a segment) has two, there and back.
    const std::size_t ea = m > 1 ? m : 0, eb = n > 1 ? n : 0;
    std::size_t i = 0, j = 0, ci = 0, cj = 0;
    while (ci < ea || cj < eb) {
      pairs.push_back({ha_[i], hb_[j]});
      bool advanceA, advanceB;
      if (ci == ea) {
        advanceA = false, advanceB = true;
      } else if (cj == eb) {
        advanceA = true, advanceB = false;
      } else {
        const int c = angleCompare(a, ha_, i, b, hb_, j);
        advanceA = c >= 0;  // A's edge comes first (or both, when parallel)
        advanceB = c <= 0;
      }
      if (advanceA) i = (i + 1) % m, ++ci;
      if (advanceB) j = (j + 1) % n, ++cj;
    }
    if (pairs.empty()) pairs.push_back({ha_[0], hb_[0]});
  }

  std::vector<std::pair<int, int>> pairs;

 private:
  // The point of set s at index k; the second set negated (its points enter as −b).
  static P2 at(const std::vector<P2>& s, bool negate, int k) {
    return negate ? P2(T(-s[k].first), T(-s[k].second)) : s[k];
  }
  // The half-plane of the direction from p to q (halfPlaneOf).
  static int half(const P2& p, const P2& q) { return halfPlaneOf(T(q.first - p.first), T(q.second - p.second)); }
  // Sign of angle(v) − angle(u) over [0, 2π) for u the edge of A's hull from its vertex i
  // and v that of −B's hull from its vertex j: > 0 when u comes first. Exact.
  static int angleCompare(const std::vector<P2>& a, const std::vector<int>& ha, std::size_t i, const std::vector<P2>& b,
                          const std::vector<int>& hb, std::size_t j) {
    const P2 u0 = at(a, false, ha[i]), u1 = at(a, false, ha[(i + 1) % ha.size()]);
    const P2 v0 = at(b, true, hb[j]), v1 = at(b, true, hb[(j + 1) % hb.size()]);
    const int hu = half(u0, u1), hv = half(v0, v1);
    if (hu != hv) return hu < hv ? 1 : -1;
    return crossOfDifferencesSign(u0, u1, v0, v1);
  }

  // out := indices of the hull's vertices of set s (negated if asked), counter-clockwise
  // from the lowest (least y, then least x): where the edges' polar angles start at 0.
  void hull(const std::vector<P2>& s, bool negate, std::vector<int>& out) {
    if (s.size() >= static_cast<std::size_t>(defaults::kConvexCycleMinPoints)) {
      // Points in cyclic order around a strictly convex polygon are their hull: O(n).
      const int n = static_cast<int>(s.size());
      const int o = convexCycleOrientation<T>(s.size(), [&](std::size_t k) { return at(s, negate, int(k)); });
      if (o != 0) {
        int low = 0;
        for (int i = 1; i < n; ++i) {
          const P2 p = at(s, negate, i), q = at(s, negate, low);
          if (p.second < q.second || (p.second == q.second && p.first < q.first)) low = i;
        }
        out.resize(s.size());
        for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = o > 0 ? (low + i) % n : (low - i + n) % n;
        return;
      }
    }
    order_.resize(s.size());
    for (std::size_t k = 0; k < s.size(); ++k) order_[k] = static_cast<int>(k);
    auto less = [&](int x, int y) {
      const P2 p = at(s, negate, x), q = at(s, negate, y);
      return p.first < q.first || (p.first == q.first && p.second < q.second);
    };
    std::sort(order_.begin(), order_.end(), less);
    std::size_t n = 0;
    for (std::size_t k = 0; k < order_.size(); ++k)
      if (n == 0 || less(order_[n - 1], order_[k])) order_[n++] = order_[k];
    out.assign(2 * n + 1, -1);
    std::size_t k = 0;
    auto turnsLeft = [&](int o, int p, int q) {
      const P2 x = at(s, negate, o), y = at(s, negate, p), z = at(s, negate, q);
      return orient2d<T>(x.first, x.second, y.first, y.second, z.first, z.second) > 0;
    };
    for (std::size_t i = 0; i < n; ++i) {
      while (k >= 2 && !turnsLeft(out[k - 2], out[k - 1], order_[i])) --k;
      out[k++] = order_[i];
    }
    for (std::size_t i = n - 1, lo = k + 1; i-- > 0;) {
      while (k >= lo && !turnsLeft(out[k - 2], out[k - 1], order_[i])) --k;
      out[k++] = order_[i];
    }
    if (k > 1) --k;  // the chain came back to its first point
    out.resize(k);
    // Rotate to the lowest vertex (least y, then least x).
    std::size_t low = 0;
    for (std::size_t i = 1; i < out.size(); ++i) {
      const P2 p = at(s, negate, out[i]), q = at(s, negate, out[low]);
      if (p.second < q.second || (p.second == q.second && p.first < q.first)) low = i;
    }
    std::rotate(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(low), out.end());
  }

  std::vector<int> ha_, hb_, order_;
};

}  // namespace detail
}  // namespace mink
