// mink/hierarchy/detail/dk_hierarchy_impl.hpp — template bodies of dk_hierarchy.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {
namespace detail {

template <class T>
inline T dkDot(const Vec3<T>& a, const Vec3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Four vertices spanning a tetrahedron of (near) maximal size: the two extremes along
/// the axis of largest spread, the vertex farthest from their line, the vertex farthest
/// from the plane of the three. They are kept on every level so that no level can
/// collapse to a plane. Every comparison is of a polynomial (squared cross product, |det|
/// against a fixed base), so the choice is exact for exact T.
template <class T>
std::array<int, 4> dkAnchors(const std::vector<Vec3<T>>& p) {
  const int n = static_cast<int>(p.size());
  std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0};
  for (int v = 1; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      if (p[v][k] < p[lo[k]][k]) lo[k] = v;
      if (p[hi[k]][k] < p[v][k]) hi[k] = v;
    }
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (p[hi[axis]][axis] - p[lo[axis]][axis] < p[hi[k]][k] - p[lo[k]][k]) axis = k;
  }
  const int a = lo[axis], b = hi[axis];
  const Vec3<T> ab = p[b] - p[a];
  int c = a;
  T bestLine = T(0);
  for (int v = 0; v < n; ++v) {
    const Vec3<T> x = (p[v] - p[a]).cross(ab);
    const T q = dkDot(x, x);
    if (bestLine < q) {
      bestLine = q;
      c = v;
    }
  }
  const Vec3<T> normal = ab.cross(Vec3<T>(p[c] - p[a]));
  int d = a;
  T bestPlane = T(0);
  for (int v = 0; v < n; ++v) {
    T s = dkDot(normal, Vec3<T>(p[v] - p[a]));
    if (s < T(0)) s = -s;
    if (bestPlane < s) {
      bestPlane = s;
      d = v;
    }
  }
  return {a, b, c, d};
}

}  // namespace detail

template <class T>
DKHierarchy<T>::DKHierarchy(const ConvexPolyhedron<T>& shape, const DKHierarchyOptions& options) {
  if (options.maxRemovedDegree < 3) {
    throw InvalidInput("DKHierarchyOptions::maxRemovedDegree must be >= 3, got " +
                       std::to_string(options.maxRemovedDegree));
  }
  if (options.topVertices < 4) {
    throw InvalidInput("DKHierarchyOptions::topVertices must be >= 4, got " +
                       std::to_string(options.topVertices));
  }
  const int n = shape.numVertices();
  {
    Level L0;
    L0.point = shape.vertices();
    L0.start.resize(n + 1);
    L0.start[0] = 0;
    for (int v = 0; v < n; ++v) L0.start[v + 1] = L0.start[v] + shape.degree(v);
    L0.neighbor.reserve(L0.start[n]);
    for (int v = 0; v < n; ++v) {
      for (int u : shape.vertexNeighbors(v)) L0.neighbor.push_back(u);
    }
    levels_.push_back(std::move(L0));
  }
  const std::array<int, 4> anchors = detail::dkAnchors(levels_[0].point);
  const HullOptions<T> hullOptions{shape.tolerance()};

  std::vector<char> isAnchor, blocked, inNext;
  std::vector<int> byDegree, bucketStart, kept;
  std::vector<Vec3<T>> keptPoints;
  while (levelSize(numLevels() - 1) > options.topVertices) {
    const Level& cur = levels_.back();
    const int m = static_cast<int>(cur.point.size());
    const bool isBase = numLevels() == 1;

    isAnchor.assign(m, 0);
    for (int v = 0; v < m; ++v) {
      const int orig = isBase ? v : cur.original[v];
      for (int a : anchors) isAnchor[v] |= static_cast<char>(orig == a);
    }
    // Lowest degree first (counting sort): low-degree picks block fewer candidates, so
    // the set grows larger and the hierarchy shallower.
    const int maxDeg = options.maxRemovedDegree;
    bucketStart.assign(maxDeg + 2, 0);
    for (int v = 0; v < m; ++v) {
      const int deg = cur.start[v + 1] - cur.start[v];
      if (deg <= maxDeg && !isAnchor[v]) ++bucketStart[deg + 1];
    }
    for (int k = 0; k <= maxDeg; ++k) bucketStart[k + 1] += bucketStart[k];
    byDegree.resize(bucketStart[maxDeg + 1]);
    for (int v = 0; v < m; ++v) {
      const int deg = cur.start[v + 1] - cur.start[v];
      if (deg <= maxDeg && !isAnchor[v]) byDegree[bucketStart[deg]++] = v;
    }
    blocked.assign(m, 0);  // 1: kept because a neighbour is removed; 2: removed
    for (int v : byDegree) {
      if (blocked[v]) continue;
      blocked[v] = 2;
      for (int j = cur.start[v]; j < cur.start[v + 1]; ++j) {
        if (!blocked[cur.neighbor[j]]) blocked[cur.neighbor[j]] = 1;
      }
    }
    kept.clear();
    keptPoints.clear();
    for (int v = 0; v < m; ++v) {
      if (blocked[v] != 2) {
        kept.push_back(v);
        keptPoints.push_back(cur.point[v]);
      }
    }
    if (static_cast<int>(kept.size()) == m) {
      stop_ = DKBuildStop::NoRemovableVertex;
      break;
    }

    // Every kept vertex is extreme in L(i), hence in the hull of any subset containing it,
    // and the anchors keep that subset full-dimensional, so this cannot throw for exact T.
    // With a tolerance, near-degenerate shapes might still be judged flat: then the
    // current level stays the top and stopReason() says so (queries remain correct).
    std::unique_ptr<ConvexPolyhedron<T>> hull;
    try {
      hull = std::make_unique<ConvexPolyhedron<T>>(
          ConvexPolyhedron<T>::fromPoints(keptPoints, hullOptions));
    } catch (const InvalidInput&) {
      stop_ = DKBuildStop::HullFailed;
      break;
    }
    const int h = hull->numVertices();  // <= kept.size() < m: every round shrinks

    Level next;
    next.point = hull->vertices();
    next.start.resize(h + 1);
    next.start[0] = 0;
    for (int w = 0; w < h; ++w) next.start[w + 1] = next.start[w] + hull->degree(w);
    next.neighbor.reserve(next.start[h]);
    next.original.resize(h);
    next.below.resize(h);
    for (int w = 0; w < h; ++w) {
      for (int u : hull->vertexNeighbors(w)) next.neighbor.push_back(u);
      const int v = kept[hull->inputIndex(w)];
      next.below[w] = v;
      next.original[w] = isBase ? v : cur.original[v];
    }
    // Pockets: the neighbours in L(i) of each vertex that did not survive into L(i+1)
    // (the removed ones, and for inexact T kept ones the re-hull dropped). Only they can
    // beat the image of L(i+1)'s maximiser. (Copying their points next to the indices
    // measured no faster and cost ~40% more memory.)
    inNext.assign(m, 0);
    for (int w = 0; w < h; ++w) inNext[next.below[w]] = 1;
    next.pocketStart.resize(h + 1);
    next.pocketStart[0] = 0;
    for (int w = 0; w < h; ++w) {
      const int v = next.below[w];
      int count = 0;
      for (int j = cur.start[v]; j < cur.start[v + 1]; ++j) count += !inNext[cur.neighbor[j]];
      next.pocketStart[w + 1] = next.pocketStart[w] + count;
    }
    next.pocket.reserve(next.pocketStart[h]);
    for (int w = 0; w < h; ++w) {
      const int v = next.below[w];
      for (int j = cur.start[v]; j < cur.start[v + 1]; ++j)
        if (!inNext[cur.neighbor[j]]) next.pocket.push_back(cur.neighbor[j]);
    }
    levels_.push_back(std::move(next));
  }
}

template <class T>
std::size_t DKHierarchy<T>::totalSize() const {
  std::size_t total = 0;
  for (const Level& L : levels_) total += L.point.size();
  return total;
}

template <class T>
std::size_t DKHierarchy<T>::memoryBytes() const {
  std::size_t bytes = sizeof(*this) + levels_.capacity() * sizeof(Level);
  for (const Level& L : levels_) {
    bytes += L.point.capacity() * sizeof(Vec3<T>);
    bytes += (L.start.capacity() + L.neighbor.capacity() + L.original.capacity() + L.below.capacity() +
              L.pocketStart.capacity() + L.pocket.capacity()) *
             sizeof(int);
  }
  return bytes;
}

template <class T>
template <bool kCount>
int DKHierarchy<T>::supportImpl(const Vec3<T>& d, DKSupportStats* stats) const {
  const Level& top = levels_.back();
  int v = 0;
  T best = detail::dkDot(d, top.point[0]);
  const int m = static_cast<int>(top.point.size());
  for (int w = 1; w < m; ++w) {
    const T s = detail::dkDot(d, top.point[w]);
    if (best < s) {
      best = s;
      v = w;
    }
  }
  if constexpr (kCount) stats->evaluations += m;
  if (numLevels() == 1) return v;  // the scan covered every vertex
  for (int i = numLevels() - 1; i > 0; --i) {
    // Only a pocket vertex can beat v on L(i-1); the best of them, if better, is the
    // maximiser of L(i-1) (exact arithmetic, header lemma), so no further climbing here.
    const Level& up = levels_[i];
    const std::vector<Vec3<T>>& below = levels_[i - 1].point;
    int next = -1;
    const int b = up.pocketStart[v], e = up.pocketStart[v + 1];
    for (int j = b; j < e; ++j) {
      const T s = detail::dkDot(d, below[up.pocket[j]]);
      if (best < s) {
        best = s;
        next = up.pocket[j];
      }
    }
    if constexpr (kCount) stats->evaluations += e - b;
    if (next >= 0) {
      v = next;
      if constexpr (kCount) ++stats->moves;
    } else {
      v = up.below[v];
    }
  }
  // Certificate on L0 for inexact T: a vertex of the polytope with no strictly better
  // neighbour is a global maximiser. Exact T needs none (the lemma is exact there), which
  // also keeps a high-degree answer (a cone apex) from costing its degree once more.
  if constexpr (ScalarTraits<T>::isExact) return v;
  const Level& L = levels_[0];
  const int* nb = L.neighbor.data();
  for (;;) {
    int next = -1;
    const int b = L.start[v], e = L.start[v + 1];
    for (int j = b; j < e; ++j) {
      const T s = detail::dkDot(d, L.point[nb[j]]);
      if (best < s) {
        best = s;
        next = nb[j];
      }
    }
    if constexpr (kCount) stats->evaluations += e - b;
    if (next < 0) break;
    if constexpr (kCount) ++stats->moves;
    v = next;
  }
  return v;
}

template <class T>
const DKHierarchy<T>* hierarchyOf(const ConvexPolyhedron<T>& P) {
  if (P.numVertices() < defaults::kHierarchyMinVertices) return nullptr;
  detail::DerivedSlot& slot = P.derivedSlots().slot[detail::DerivedSlots::kHierarchy];
  return static_cast<const DKHierarchy<T>*>(slot.get([&] { return std::make_shared<const DKHierarchy<T>>(P); }));
}

template <class T>
int extremeVertex(const ConvexPolyhedron<T>& P, const Vec3<T>& d, int hint) {
  if (hint >= 0) return P.support(d, hint);
  if (const DKHierarchy<T>* H = hierarchyOf(P)) return H->support(d);
  return P.support(d, seedVertex(P, d));
}

}  // namespace mink
