// mink/hierarchy/support_seeds.hpp — starting vertices for hill-climbing support queries
// on shapes too small for a Dobkin–Kirkpatrick hierarchy.
//
// A hill-climb from an arbitrary vertex walks across the shape: O(√n) steps for a
// direction a quarter turn away, and MDD's portal steps ask for such directions several
// times per query. The seeds are the support vertices of the 26 directions (a, b, c) ∈
// {−1, 0, 1}³ \ {0}; a query climbs from the seed whose direction is nearest its own
// (within about 35°), so the walk is short.
//   1. Built once per shape on first use (26 scans, O(n)), shared by its copies.
//   2. Nearest seed direction: each axis takes the sign of d's component; the best of the
//      three classes (one, two or three non-zero axes) by d·u/|u|, with 1/√2 and 1/√3 as
//      constants of T (a heuristic choice: any seed gives the exact support).
#pragma once

#include <array>
#include <memory>
#include <mutex>

#include "mink/core/scalar_traits.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {

/// Support vertices of the 26 directions of {−1, 0, 1}³ \ {0}, by (a+1)·9 + (b+1)·3 + (c+1).
struct SupportSeeds {
  std::array<int, 27> vertex{};
};

template <class T>
const SupportSeeds& supportSeedsOf(const ConvexPolyhedron<T>& P) {
  detail::DerivedSlot& slot = P.derivedSlots().slot[detail::DerivedSlots::kSupportSeeds];
  return *static_cast<const SupportSeeds*>(slot.get([&] {
    auto seeds = std::make_shared<SupportSeeds>();
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c) {
          const int i = (a + 1) * 9 + (b + 1) * 3 + (c + 1);
          seeds->vertex[i] = (a | b | c) ? P.supportBruteForce(Vec3<T>(T(a), T(b), T(c))) : 0;
        }
    return std::shared_ptr<const SupportSeeds>(seeds);
  }));
}

/// The seed vertex whose direction is nearest d's.
template <class T>
int seedVertex(const ConvexPolyhedron<T>& P, const Vec3<T>& d) {
  int sign[3], order[3] = {0, 1, 2};
  T mag[3];
  for (int i = 0; i < 3; ++i) {
    sign[i] = d[i] > T(0) ? 1 : (d[i] < T(0) ? -1 : 0);
    mag[i] = detail::absValue(d[i]);
  }
  // order: axes by decreasing |d_i|
  if (mag[order[0]] < mag[order[1]]) std::swap(order[0], order[1]);
  if (mag[order[1]] < mag[order[2]]) std::swap(order[1], order[2]);
  if (mag[order[0]] < mag[order[1]]) std::swap(order[0], order[1]);
  const T one = mag[order[0]];
  const T two = (mag[order[0]] + mag[order[1]]) * T(0.7071067811865476);
  const T three = (mag[0] + mag[1] + mag[2]) * T(0.5773502691896258);
  int use = 1;
  if (two > one) use = 2;
  if (three > (use == 2 ? two : one)) use = 3;
  int u[3] = {0, 0, 0};
  for (int k = 0; k < use; ++k) u[order[k]] = sign[order[k]];
  if (!(u[0] | u[1] | u[2])) return 0;
  return supportSeedsOf(P).vertex[(u[0] + 1) * 9 + (u[1] + 1) * 3 + (u[2] + 1)];
}

}  // namespace mink
