// mink/hierarchy/detail/dk_hierarchy_impl.hpp — template bodies of dk_hierarchy.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/index_range.hpp"
#include "mink/core/orientation.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {
namespace detail {

/// A hint to the processor that *p will be read soon (no effect on results; none on
/// compilers without the builtin).
inline void prefetch(const void* p) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

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


/// Triangulates polygons (a mesh face, or the hole a removed vertex leaves) and lists,
/// per corner, the diagonals the triangulation adds there. Corners are local positions
/// 0 .. k-1 of a loop counter-clockwise seen from outside; triangles are emitted with
/// the same orientation. diagonals(j) holds the far corners of the new edges at corner j
/// in counter-clockwise order from corner j+1 to corner j-1 (exclusive): exactly what
/// replaces, in the neighbour list of corner j, the removed vertex (a hole) or the face
/// (a mesh face) lying between those two corners. Scratch vectors are reused: no
/// allocation once they have grown to the largest polygon.
class DkPolygonFill {
 public:
  /// Zigzag triangulation (ends alternately advanced): no geometry, every corner gets at
  /// most three triangles. For flat convex faces any triangulation is exact.
  void zigzag(int k) {
    tris_.clear();
    int i = 0, j = k - 1;
    bool left = true;
    while (j - i >= 2) {
      if (left) {
        tris_.push_back({i, i + 1, j});
        ++i;
      } else {
        tris_.push_back({i, j - 1, j});
        --j;
      }
      left = !left;
    }
  }

  /// The hole of a removed vertex, its ring `ring` (k >= 3 points, counter-clockwise seen
  /// from outside): ear clipping that cuts only an ear (r[j-1], r[j], r[j+1]) with every
  /// ring point on or below its plane (orient3d <= 0, exact), i.e. a piece of a facet of
  /// the hull of the ring facing the removed vertex. When the points are the extreme
  /// points of a convex polytope and the ring is the link of one of them, those facets
  /// are exactly the faces the removal uncovers (all their corners are ring points), so
  /// such an ear always exists and the fill is a triangulation of the new hull's
  /// surface there. False when no ear qualifies (the shape is not exactly convex: a
  /// floating-point fromMesh shape within its tolerance); the caller then re-hulls.
  template <class T, class PointOf>
  bool earClip(int k, PointOf&& point) {
    tris_.clear();
    prev_.resize(k);
    next_.resize(k);
    state_.assign(k, kUnknown);
    for (int j = 0; j < k; ++j) {
      prev_[j] = j == 0 ? k - 1 : j - 1;
      next_[j] = j == k - 1 ? 0 : j + 1;
    }
    int remaining = k, j = 0, misses = 0;
    while (remaining > 3) {
      if (state_[j] == kUnknown) state_[j] = qualifies<T>(k, prev_[j], j, next_[j], point) ? kYes : kNo;
      if (state_[j] == kNo) {
        if (++misses >= remaining) return false;
        j = next_[j];
        continue;
      }
      const int a = prev_[j], c = next_[j];
      tris_.push_back({a, j, c});
      next_[a] = c;
      prev_[c] = a;
      state_[a] = state_[c] = kUnknown;
      --remaining;
      misses = 0;
      j = c;
    }
    if (!qualifies<T>(k, prev_[j], j, next_[j], point)) return false;
    tris_.push_back({prev_[j], j, next_[j]});
    return true;
  }

  /// Fills diagonals from the last triangulation of a k-gon. False if the triangles do
  /// not form a triangulation of the loop (cannot happen for the two methods above).
  bool diagonals(int k) {
    stepStart_.assign(k + 1, 0);
    for (const auto& t : tris_)
      for (int c : t) ++stepStart_[c + 1];
    for (int c = 0; c < k; ++c) stepStart_[c + 1] += stepStart_[c];
    stepFrom_.resize(stepStart_[k]);
    stepTo_.resize(stepStart_[k]);
    fillAt_.assign(stepStart_.begin(), stepStart_.end() - 1);
    // At corner a of the counter-clockwise triangle (a, b, c) the edges turn from b to c.
    for (const auto& t : tris_) {
      for (int r = 0; r < 3; ++r) {
        const int at = t[r], s = fillAt_[at]++;
        stepFrom_[s] = t[(r + 1) % 3];
        stepTo_[s] = t[(r + 2) % 3];
      }
    }
    diagStart_.assign(k + 1, 0);
    diag_.clear();
    for (int j = 0; j < k; ++j) {
      const int last = j == 0 ? k - 1 : j - 1;
      int x = j == k - 1 ? 0 : j + 1;
      const int b = stepStart_[j], e = stepStart_[j + 1];
      for (int guard = b; x != last; ++guard) {
        if (guard == e) return false;
        int s = b;
        while (s < e && stepFrom_[s] != x) ++s;
        if (s == e) return false;
        x = stepTo_[s];
        if (x != last) diag_.push_back(x);
      }
      diagStart_[j + 1] = static_cast<int>(diag_.size());
    }
    return true;
  }

  IndexRange diagonalsAt(int j) const {
    return IndexRange(diag_.data() + diagStart_[j], diag_.data() + diagStart_[j + 1]);
  }

 private:
  static constexpr char kUnknown = 0, kYes = 1, kNo = 2;

  template <class T, class PointOf>
  static bool qualifies(int k, int a, int j, int c, PointOf& point) {
    const Vec3<T>& pa = point(a);
    const Vec3<T>& pj = point(j);
    const Vec3<T>& pc = point(c);
    for (int q = 0; q < k; ++q) {
      if (q == a || q == j || q == c) continue;
      if (orient3d(pa, pj, pc, point(q)) > 0) return false;
    }
    return true;
  }

  std::vector<std::array<int, 3>> tris_;
  std::vector<int> prev_, next_, stepStart_, stepFrom_, stepTo_, fillAt_, diagStart_, diag_;
  std::vector<char> state_;
};

}  // namespace detail

template <class T>
Error DKHierarchy<T>::checkOptions(const DKHierarchyOptions& options) {
  if (options.maxRemovedDegree < 3)
    return Error("DKHierarchyOptions::maxRemovedDegree must be >= 3, got " + std::to_string(options.maxRemovedDegree));
  if (options.topVertices < 4)
    return Error("DKHierarchyOptions::topVertices must be >= 4, got " + std::to_string(options.topVertices));
  return Error();
}

template <class T>
DKHierarchy<T>::DKHierarchy(const ConvexPolyhedron<T>& shape, const DKHierarchyOptions& options) {
  detail::raiseIf(checkOptions(options));
  detail::DkPolygonFill fill;
  for (int f = 0; f < shape.numFaces(); ++f)
    maxFaceVertices_ = std::max(maxFaceVertices_, static_cast<int>(shape.faceVertices(f).size()));
  for (int v = 0; v < shape.numVertices(); ++v) maxDegree_ = std::max(maxDegree_, shape.degree(v));
  levels_.push_back(triangulatedGraph(shape, fill));
  const std::array<int, 4> anchors = detail::dkAnchors(levels_[0].point);

  std::vector<char> isAnchor, blocked, inNext;
  std::vector<int> byDegree, bucketStart, kept;
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
    for (int v = 0; v < m; ++v)
      if (blocked[v] != 2) kept.push_back(v);
    if (static_cast<int>(kept.size()) == m) {
      stop_ = DKBuildStop::NoRemovableVertex;
      break;
    }

    Level next;
    if (!fillHoles(cur, blocked, kept, fill, next)) {
      // Not exactly convex (a floating-point fromMesh shape): the hull of the kept points.
      if (!rehull(cur, kept, shape.tolerance(), fill, next)) {
        stop_ = DKBuildStop::HullFailed;
        break;
      }
      ++rehulled_;
    }
    const int h = static_cast<int>(next.point.size());
    next.original.resize(h);
    for (int w = 0; w < h; ++w) next.original[w] = isBase ? next.below[w] : cur.original[next.below[w]];
    // Pockets: the neighbours in L(i) of each vertex that did not survive into L(i+1)
    // (the removed ones, and after a re-hull kept ones it dropped). Only they can beat
    // the image of L(i+1)'s maximiser. (Copying their points next to the indices
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
typename DKHierarchy<T>::Level DKHierarchy<T>::triangulatedGraph(const ConvexPolyhedron<T>& P,
                                                                 detail::DkPolygonFill& fill) {
  // Diagonals per half-edge (a face's corner at the half-edge's origin), CSR in half-edge
  // order, which is face order; triangles add none.
  const int numHe = P.numHalfEdges();
  std::vector<int> diagStart(numHe + 1, 0), diag;
  for (int f = 0; f < P.numFaces(); ++f) {
    const int k = P.faceSize(f), h0 = P.faceStart(f);
    if (k == 3) {
      for (int t = 0; t < 3; ++t) diagStart[h0 + t + 1] = static_cast<int>(diag.size());
      continue;
    }
    fill.zigzag(k);
    fill.diagonals(k);  // a zigzag is a triangulation: cannot fail
    const IndexRange loop = P.faceVertices(f);
    for (int t = 0; t < k; ++t) {
      for (int x : fill.diagonalsAt(t)) diag.push_back(loop[x]);
      diagStart[h0 + t + 1] = static_cast<int>(diag.size());
    }
  }
  Level L;
  L.point = P.vertices();
  const int n = P.numVertices();
  L.start.resize(n + 1);
  L.start[0] = 0;
  L.neighbor.reserve(numHe + diag.size());
  for (int v = 0; v < n; ++v) {
    // Around v: neighbour i, then the face between neighbours i and i+1, whose loop runs
    // v -> neighbour i: its diagonals at v, counter-clockwise from neighbour i on.
    const IndexRange nb = P.vertexNeighbors(v), out = P.vertexHalfEdges(v);
    for (int i = 0; i < nb.size(); ++i) {
      L.neighbor.push_back(nb[i]);
      const int h = out[i];
      for (int j = diagStart[h]; j < diagStart[h + 1]; ++j) L.neighbor.push_back(diag[j]);
    }
    L.start[v + 1] = static_cast<int>(L.neighbor.size());
  }
  return L;
}

template <class T>
bool DKHierarchy<T>::fillHoles(const Level& cur, const std::vector<char>& blocked, const std::vector<int>& kept,
                               detail::DkPolygonFill& fill, Level& next) {
  const int m = static_cast<int>(cur.point.size());
  // Per slot s of a removed vertex's neighbour list (ring corner j = s - start[v]): the
  // diagonals its fill adds at that corner, as vertices of L(i), in seq[seqStart[s] ..
  // seqStart[s + 1]). Slots of kept vertices get empty ranges.
  std::vector<int> seqStart(cur.neighbor.size() + 1, 0), seq;
  for (int v = 0; v < m; ++v) {
    const int b = cur.start[v], e = cur.start[v + 1];
    if (blocked[v] == 2) {
      const int k = e - b;
      const int* ring = cur.neighbor.data() + b;
      const auto pointOf = [&](int j) -> const Vec3<T>& { return cur.point[ring[j]]; };
      if (!fill.template earClip<T>(k, pointOf) || !fill.diagonals(k)) return false;
      for (int j = 0; j < k; ++j) {
        for (int x : fill.diagonalsAt(j)) seq.push_back(ring[x]);
        seqStart[b + j + 1] = static_cast<int>(seq.size());
      }
    } else {
      for (int s = b; s < e; ++s) seqStart[s + 1] = static_cast<int>(seq.size());
    }
  }
  std::vector<int> newIndex(m, -1);
  const int h = static_cast<int>(kept.size());
  for (int w = 0; w < h; ++w) newIndex[kept[w]] = w;
  next.point.resize(h);
  next.below = kept;
  next.start.resize(h + 1);
  next.start[0] = 0;
  next.neighbor.reserve(cur.neighbor.size());
  // A removed neighbour x of u sits between u's neighbours r[j+1] and r[j-1] (u = r[j]
  // on x's ring): the fill's diagonals at corner j replace it, in the same order. The
  // stamps check that no list repeats a vertex or holds its owner (a fill that is not a
  // triangulation of the new hull: only on shapes that are not exactly convex).
  std::vector<int> stamp(h, -1);
  for (int w = 0; w < h; ++w) {
    const int u = kept[w];
    next.point[w] = cur.point[u];
    stamp[w] = w;
    for (int t = cur.start[u]; t < cur.start[u + 1]; ++t) {
      const int x = cur.neighbor[t];
      const auto add = [&](int y) {
        const int ny = newIndex[y];
        if (stamp[ny] == w) return false;
        stamp[ny] = w;
        next.neighbor.push_back(ny);
        return true;
      };
      if (newIndex[x] >= 0) {
        if (!add(x)) return false;
        continue;
      }
      int s = cur.start[x];
      while (s < cur.start[x + 1] && cur.neighbor[s] != u) ++s;
      if (s == cur.start[x + 1]) return false;  // not a symmetric graph: cannot happen
      for (int j = seqStart[s]; j < seqStart[s + 1]; ++j)
        if (!add(seq[j])) return false;
    }
    next.start[w + 1] = static_cast<int>(next.neighbor.size());
    if (next.start[w + 1] - next.start[w] < 3) return false;
  }
  return true;
}

template <class T>
bool DKHierarchy<T>::rehull(const Level& cur, const std::vector<int>& kept, const T& tolerance,
                            detail::DkPolygonFill& fill, Level& next) {
  std::vector<Vec3<T>> keptPoints;
  keptPoints.reserve(kept.size());
  for (int v : kept) keptPoints.push_back(cur.point[v]);
  // With a tolerance, near-degenerate shapes might be judged flat: then the current level
  // stays the top and stopReason() says so (queries remain correct).
  Result<ConvexPolyhedron<T>> built = ConvexPolyhedron<T>::tryFromPoints(keptPoints, HullOptions<T>{tolerance});
  if (!built.ok()) return false;
  const ConvexPolyhedron<T>* hull = &built.value();
  next = triangulatedGraph(*hull, fill);
  const int h = hull->numVertices();  // <= kept.size() < m: every round shrinks
  next.below.resize(h);
  for (int w = 0; w < h; ++w) next.below[w] = kept[hull->inputIndex(w)];
  return true;
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
    // The next level's vertex is one of the pocket's or v's image: ask for their rows
    // now, while the pocket's points are read (a level's reads otherwise wait on the last
    // level's answer; at 100k vertices the descent is bound by those reads).
    if (i > 1) {
      const Level& down = levels_[i - 1];
      detail::prefetch(down.pocketStart.data() + up.below[v]);
      detail::prefetch(down.below.data() + up.below[v]);
      for (int j = b; j < e; ++j) {
        detail::prefetch(down.pocketStart.data() + up.pocket[j]);
        detail::prefetch(down.below.data() + up.pocket[j]);
      }
    }
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
  return climbL0<kCount>(d, v, best, std::numeric_limits<long long>::max(), stats);
}

template <class T>
template <bool kCount>
int DKHierarchy<T>::climbL0(const Vec3<T>& d, int v, T best, long long maxMoves, DKSupportStats* stats) const {
  const Level& L = levels_[0];
  const int* nb = L.neighbor.data();
  for (long long moves = 0;; ++moves) {
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
    if (next < 0) return v;
    if (moves >= maxMoves) return -1;
    if constexpr (kCount) ++stats->moves;
    v = next;
  }
}

template <class T>
int DKHierarchy<T>::supportFrom(const Vec3<T>& d, int hint, int maxMoves) const {
  if (hint >= 0 && hint < levelSize(0)) {
    const int v = climbL0<false>(d, hint, detail::dkDot(d, levels_[0].point[hint]), maxMoves, nullptr);
    if (v >= 0) return v;
  }
  return support(d);
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
