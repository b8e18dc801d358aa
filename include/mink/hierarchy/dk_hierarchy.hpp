// mink/hierarchy/dk_hierarchy.hpp — DKHierarchy<T>: the Dobkin–Kirkpatrick hierarchy of a
// convex polyhedron, for extreme-vertex (support) queries in O(log n) levels.
//
// Source: D. P. Dobkin, D. G. Kirkpatrick, "A linear algorithm for determining the
// separation of convex polyhedra", J. Algorithms 6(3), 1985 (the hierarchical
// representation); used by the MDD paper (section IV-B.1) to find the supporting vertex
// of -Q for every face visited by SEARCH-FV.
//
// Build (levels L0 .. Lk), every level the graph of a triangulation of its hull's surface:
//   1. L0 is the shape's vertex graph with each polygonal face split into triangles
//      (zigzag: no corner gets more than three of a face's triangles).
//   2. Greedily pick an independent set of vertices of L(i) of degree <= maxRemovedDegree
//      (lowest degree first; four "anchor" vertices spanning a tetrahedron are never picked).
//   3. L(i+1) = L(i) without them, each one's hole filled (the true Dobkin–Kirkpatrick
//      step, O(degree^2) per hole, O(|L(i)|) per level): the hole of a removed vertex v is
//      bounded by its ring of neighbours, and the faces the removal uncovers on the hull of
//      the rest are facets of the hull of that ring, all corners on it. Ear clipping cuts
//      only ears (r[j-1], r[j], r[j+1]) with every ring point on or below their plane,
//      decided by the exact orient3d, so the fill is exact for any T whenever the level
//      is exactly convex (every shape fromPoints builds, every exact shape). Record, per
//      vertex w of L(i+1), its index in L(i) and in L0, and its "pocket": the neighbours
//      of w in L(i) that are not in L(i+1).
//      A hole with no such ear, or a fill that would repeat an edge, happens only on a
//      shape convex within its tolerance but not exactly (floating-point fromMesh): that
//      level is then the hull of the kept points (ConvexPolyhedron::fromPoints with the
//      shape's tolerance), rehulledLevels() counts it.
//   4. Stop when L(i+1) has <= topVertices vertices, or when a round removes nothing.
// Query support(d):
//   1. Scan the top level Lk for the vertex maximising d.x.
//   2. For i = k .. 1: go down to L(i-1). This is the hill-climb on L(i-1) from the image
//      of the answer, cut to the only steps that can matter: move to the best vertex of
//      the answer's pocket if it is strictly better, and stop there (lemma below).
//   3. Inexact T only: hill-climb on L0 (move to the strictly best neighbour while one is
//      strictly better) as a certificate; it repairs rounding and tolerance effects.
//   4. Return the L0 vertex = an index of the original shape.
//
// Lemma (exact arithmetic): let v maximise d.x on L(i). A neighbour of v in L(i-1) is
// either in L(i) — no better than v — or in v's pocket. If no pocket vertex beats v, v has
// no strictly better neighbour in L(i-1) and, L(i-1) being the graph of a convex polytope,
// v maximises d.x on L(i-1) (a vertex with no strictly better neighbour is a global
// maximiser: the edges at a vertex span a cone containing the polytope). If a pocket
// vertex u beats v, u was removed (every kept point is in L(i): a subset of extreme points
// stays extreme); by independence all of u's neighbours were kept, hence are in L(i) and
// no better than v < u, so u maximises L(i-1). Induction from the top scan gives the
// answer on L0 with at most one move per level. (Diagonals of flat faces are edges too:
// a vertex of a triangulated convex surface that no neighbour beats is still a maximiser.)
// With inexact T a tolerant re-hull may drop a kept point lying within the tolerance of a
// face (it then sits in its neighbours' pockets, so it is still considered), and
// comparisons round; step 3 makes the answer a vertex no neighbour of which is better
// in computed arithmetic, the same guarantee as ConvexPolyhedron::support.
//
// Cost: O(topVertices + sum over levels of the pocket size of the visited vertex
// [+ the L0 climb]) = O(log n * max degree on the descent path). On triangulated point
// clouds pockets hold ~2 vertices and a query evaluates ~70 vertices at n = 100k. Degrees
// are not bounded in general: a cone apex of degree m has pockets of size ~m/2, and every
// visit to it costs that scan.
//
// Build cost: each round removes a constant fraction of the vertices (a planar graph has
// average degree < 6, so more than n(D-5)/(D+1) vertices have degree <= D, and a greedy
// independent set among them, each pick blocking at most D+1 candidates, holds more than
// n(D-5)/(D+1)^2 - 4 of them: n/27 - 4 for D = 8), so there are O(log n) levels of
// geometrically shrinking size, each made in O(size * D^2) by the hole fills: O(n D^2) in
// all (a fifth of the hull build at n = 100k, benchmarks/run_foundation.sh). Before the
// fills every level was re-hulled, O(n log n) expected and 2 - 2.5 hull builds.
//
// Conventions: every vertex index returned or taken by the public interface is an index
// of the ORIGINAL shape (0 .. shape.numVertices()-1) unless it is explicitly a level
// index (the level accessors). Coordinates are in the shape's own frame.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/error.hpp"
#include "mink/core/types.hpp"
#include "mink/hierarchy/support_seeds.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {
namespace detail {
class DkPolygonFill;
}  // namespace detail

/// Construction parameters of DKHierarchy.
struct DKHierarchyOptions {
  /// Only vertices of at most this degree (in their level) are removed. Unit: edges.
  /// Must be >= 3 (every vertex of a 3-polytope has degree >= 3); safe range 6 .. 12.
  int maxRemovedDegree = defaults::kHierarchyMaxRemovedDegree;
  /// A level with at most this many vertices is the top, scanned by every query.
  /// Unit: vertices. Must be >= 4; safe range 4 .. 64.
  int topVertices = defaults::kHierarchyTopVertices;
};

/// Why the construction stopped adding levels.
enum class DKBuildStop {
  /// The top level has at most topVertices vertices (the normal end).
  ReachedTop,
  /// Every vertex of the top level has degree > maxRemovedDegree (D) or is an anchor.
  /// For D >= 6 only possible at <= (4D - 8) / (D - 5) vertices (a planar graph with
  /// more has more than four vertices of degree <= D); otherwise a sign of small D.
  NoRemovableVertex,
  /// Re-hulling the kept vertices threw (inexact T only: the kept points were judged
  /// flat within the tolerance). Queries stay correct; they scan a larger top level.
  HullFailed,
};

/// Work done by one DKHierarchy::support query (for tests and benchmarks).
struct DKSupportStats {
  /// Moves to a strictly better vertex: pocket moves between levels plus moves of the L0
  /// certificate climb (inexact T). In exact arithmetic at most one per level below the
  /// top (the lemma in the header comment).
  int moves = 0;
  /// Vertices whose d.x was evaluated (top scan, pockets, L0 climb).
  int evaluations = 0;
};

template <class T>
class DKHierarchy {
 public:
  using Scalar = T;

  /// Builds the hierarchy of `shape` (any size; a shape with at most topVertices
  /// vertices gets a single level). The hierarchy copies what it needs: it does not
  /// refer to `shape` afterwards. Throws InvalidInput for out-of-range options (see
  /// checkOptions; without exceptions, prints its message and aborts).
  explicit DKHierarchy(const ConvexPolyhedron<T>& shape, const DKHierarchyOptions& options = {});

  /// The Error the constructor raises for `options`, or none: maxRemovedDegree < 3 or
  /// topVertices < 4.
  [[nodiscard]] static Error checkOptions(const DKHierarchyOptions& options);

  /// An ORIGINAL vertex index maximising direction . x (direction need not be unit;
  /// a zero direction returns some vertex). Exact for exact T. No allocation.
  int support(const Vec3<T>& direction) const { return supportImpl<false>(direction, nullptr); }
  /// Same, and reports the work done in `stats` (overwritten).
  int support(const Vec3<T>& direction, DKSupportStats& stats) const {
    stats = DKSupportStats();
    return supportImpl<true>(direction, &stats);
  }

  /// As support(direction), warm-started: a hill-climb on L0 from the ORIGINAL vertex
  /// `hint` (moving to the strictly best neighbour while one is strictly better, the
  /// descent's own last step) if it stops within `maxMoves` moves; else the descent from
  /// the top (so at most maxMoves climbing moves are lost). For a direction near the one
  /// that gave `hint` (an iterative method's next step, the next frame) the climb is a
  /// few moves over neighbouring memory, against the descent's reads on every level
  /// (memory-bound on large shapes). hint out of range: the descent; maxMoves < 0 as 0.
  int supportFrom(const Vec3<T>& direction, int hint, int maxMoves) const;

  // ---- statistics ----
  /// Number of levels, >= 1; level 0 is the shape itself, level numLevels()-1 the top.
  int numLevels() const { return static_cast<int>(levels_.size()); }
  /// Number of vertices of level i.
  int levelSize(int i) const { return static_cast<int>(levels_[i].point.size()); }
  /// Sum of levelSize(i) over all levels (vertices stored).
  std::size_t totalSize() const;
  /// Bytes held by the hierarchy's arrays (all levels, including its copy of level 0).
  std::size_t memoryBytes() const;
  /// Why the construction stopped (ReachedTop unless the shape or options are unusual).
  DKBuildStop stopReason() const { return stop_; }
  /// Levels made by re-hulling the kept points (fromPoints) because some hole had no
  /// exact fill: only on shapes that are convex within their tolerance but not exactly
  /// (floating-point fromMesh). 0 for every exact hull (fromPoints, exact T).
  int rehulledLevels() const { return rehulled_; }
  /// The shape's most vertices on one face (its merged coplanar faces as built).
  int shapeMaxFaceVertices() const { return maxFaceVertices_; }
  /// The shape's highest vertex degree (edges of the shape, not of the triangulation).
  int shapeMaxDegree() const { return maxDegree_; }

  // ---- level structure (level-local vertex indices) ----
  /// Position of vertex v of level i (shape frame).
  const Vec3<T>& levelPoint(int i, int v) const { return levels_[i].point[v]; }
  /// Neighbours of vertex v in the graph of level i (level-i indices, CCW from outside):
  /// the edges of a triangulation of the level's hull (level 0: the shape's edges and the
  /// diagonals that split its polygonal faces).
  IndexRange levelNeighbors(int i, int v) const {
    const Level& L = levels_[i];
    return IndexRange(L.neighbor.data() + L.start[v], L.neighbor.data() + L.start[v + 1]);
  }
  /// Original-shape index of vertex v of level i.
  int originalIndex(int i, int v) const { return i == 0 ? v : levels_[i].original[v]; }
  /// Index in level i-1 of vertex v of level i (i >= 1).
  int belowIndex(int i, int v) const { return levels_[i].below[v]; }

 private:
  struct Level {
    std::vector<Vec3<T>> point;
    std::vector<int> start;     // CSR row starts, size levelSize + 1
    std::vector<int> neighbor;  // CSR neighbour lists, level-local indices
    std::vector<int> original;  // level vertex -> original vertex (empty for level 0)
    std::vector<int> below;     // level vertex -> vertex of the level below (empty for 0)
    // Pocket of w (levels >= 1): neighbours of below[w] in the level below that are not
    // in this level, as indices of the level below, CSR by pocketStart.
    std::vector<int> pocketStart, pocket;
  };

  template <bool kCount>
  int supportImpl(const Vec3<T>& direction, DKSupportStats* stats) const;
  /// The climb on L0 from v (value best) to a vertex no neighbour of which is strictly
  /// better, returned; -1 when that takes more than maxMoves moves.
  template <bool kCount>
  int climbL0(const Vec3<T>& d, int v, T best, long long maxMoves, DKSupportStats* stats) const;
  /// Level of P's vertex graph with each polygonal face split into triangles (pockets,
  /// below and original left empty).
  static Level triangulatedGraph(const ConvexPolyhedron<T>& P, detail::DkPolygonFill& fill);
  /// L(i+1) = L(i) without the removed vertices (blocked == 2), each hole filled by the
  /// exact ear clipping of DkPolygonFill (point, start, neighbor, below). False when a
  /// hole has no qualifying ear or the result is not a simple graph.
  static bool fillHoles(const Level& cur, const std::vector<char>& blocked, const std::vector<int>& kept,
                        detail::DkPolygonFill& fill, Level& next);
  /// L(i+1) = the hull of the kept points (fromPoints with `tolerance`), triangulated.
  /// False when the kept points have no hull (flat within `tolerance`).
  static bool rehull(const Level& cur, const std::vector<int>& kept, const T& tolerance,
                     detail::DkPolygonFill& fill, Level& next);

  std::vector<Level> levels_;
  DKBuildStop stop_ = DKBuildStop::ReachedTop;
  int rehulled_ = 0;
  int maxFaceVertices_ = 0, maxDegree_ = 0;
};

/// The shape's hierarchy, built on first use (or up front by prepare(), prepare.hpp) and
/// shared by every copy of the shape, or nullptr when the shape has fewer than
/// defaults::kHierarchyMinVertices vertices (below that a cold hill-climb is nearly as
/// fast; benchmarks/README.md has the measurement).
/// Thread-safe: concurrent first calls build it once; later calls cost one atomic load.
/// A build that throws (it cannot for valid shapes) propagates and is retried next call.
template <class T>
const DKHierarchy<T>* hierarchyOf(const ConvexPolyhedron<T>& P);

/// An ORIGINAL vertex of P maximising d.x. With hint >= 0: hill-climb from that vertex
/// (warm start, best when d changes little between calls); otherwise the hierarchy when
/// P has one (see hierarchyOf), else a hill-climb from the nearest of 26 precomputed
/// directions' support vertices (support_seeds.hpp).
template <class T>
int extremeVertex(const ConvexPolyhedron<T>& P, const Vec3<T>& d, int hint = -1);

}  // namespace mink

#include "mink/hierarchy/detail/dk_hierarchy_impl.hpp"
