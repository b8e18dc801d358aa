// mink/polyhedron/convex_polyhedron.hpp — ConvexPolyhedron<T>: a closed convex polyhedron
// with planar convex faces, half-edge adjacency, face planes and support queries.
//
// Built two ways, both ending in the same finishing step:
//   fromPoints: convex hull by quickhull (Barber, Dobkin, Huhdanpaa 1996), every
//               "above this face?" decided exactly (core/orientation.hpp): the result
//               is the exact hull of the given numbers, in any scalar type (for
//               floating-point T, a shape beyond 2^±64 in size is built at unit scale,
//               and coordinates below 2^-1074 of that scale, 1e-300 in a 1e20 shape,
//               are rounded to it first);
//   fromMesh:   validation of a closed, consistently oriented, locally convex mesh
//               (by van Heijenoort's theorem, local convexity of a closed connected
//               surface implies global convexity);
//   finishing:  merge neighbouring faces lying exactly in one plane into one convex
//               face (the MDD paper's "span of faces with the same normal", VI-C), drop
//               vertices that are no longer corners, build the half-edge arrays.
//
// Conventions: faces are counter-clockwise seen from outside; face normals point
// outward; for inexact T they are unit length, for exact T they are Newell normals
// (exact, not normalised); the plane of face f is { x : normal(f) . x == offset(f) }.
// Every structure is in the shape's own frame; poses are applied by the queries.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/error.hpp"
#include "mink/core/index_range.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {

/// Options of shape construction (fromPoints, fromMesh).
template <class T>
struct HullOptions {
  /// Degeneracy tolerance in the input's length unit: fromPoints rejects points that
  /// all lie within it of one point, line or plane; fromMesh allows faces this far from
  /// planar and this much local non-convexity. The hull and the face merging are exact
  /// whatever its value. Negative (default): automatic,
  /// defaults::kHullToleranceFactor * eps * extent for inexact T, exactly 0 for exact T.
  T tolerance = T(-1);
};

namespace detail {
template <class T>
struct PolyhedronBuilder;
template <class T>
struct PolyhedronFinish;

/// Lazily made structures derived from a shape (its Dobkin–Kirkpatrick hierarchy, ...),
/// shared by every copy of the shape and built at most once, thread-safely. The
/// polyhedron layer knows nothing of their types; higher layers fill the slots, and
/// hierarchy/prepare.hpp fills every one of them up front.
struct DerivedSlot {
  std::once_flag once;
  std::shared_ptr<const void> value;
  std::atomic<bool> built{false};

  /// The slot's structure, made by make() (returning a shared_ptr to it) on the first
  /// call. call_once: concurrent first callers wait for one build, and its completion
  /// happens-before every return, so the plain read of value is race-free. A make() that
  /// throws leaves the slot empty and is retried by the next call.
  template <class Make>
  const void* get(Make&& make) {
    std::call_once(once, [&] {
      value = std::static_pointer_cast<const void>(make());
      built.store(true, std::memory_order_release);
    });
    return value.get();
  }
  /// Has get() filled the slot? Never waits and never builds: false while a first build
  /// is still running.
  bool isBuilt() const { return built.load(std::memory_order_acquire); }
};
struct DerivedSlots {
  enum Id { kHierarchy = 0, kSupportSeeds, kCount };
  DerivedSlot slot[kCount];
};
}  // namespace detail

template <class T>
class ConvexPolyhedron {
 public:
  using Scalar = T;

  /// Convex hull of `points` (any number >= 4, duplicates allowed).
  /// Throws InvalidInput: empty input, a non-finite coordinate (names the index),
  /// all points coincident, collinear or coplanar (within the tolerance).
  static ConvexPolyhedron fromPoints(const std::vector<Vec3<T>>& points,
                                     const HullOptions<T>& options = {});

  /// A closed convex mesh: `vertices` (#V points), `faces` (#F index loops,
  /// counter-clockwise seen from outside, each >= 3 distinct in-range indices).
  /// Unreferenced vertices are ignored. Throws InvalidInput when the input is empty,
  /// non-finite, has an index out of range, a degenerate face, is not closed (an edge
  /// with no or several partners), not consistently oriented, oriented inward, not
  /// connected, not a topological sphere, has a non-planar face or is not convex.
  static ConvexPolyhedron fromMesh(const std::vector<Vec3<T>>& vertices,
                                   const std::vector<std::vector<int>>& faces,
                                   const HullOptions<T>& options = {});

  /// fromPoints and fromMesh on coordinates of another scalar type U (float points for a
  /// double shape, double points for an exact one): each coordinate is converted by
  /// static_cast first, exactly when T represents every U (float to double or long double,
  /// any binary floating point to an exact rational), rounded otherwise (double to float).
  /// The hull is then the exact hull of the converted numbers.
  template <class U, class = std::enable_if_t<!std::is_same<U, T>::value>>
  static ConvexPolyhedron fromPoints(const std::vector<Vec3<U>>& points,
                                     const HullOptions<T>& options = {}) {
    return fromPoints(convertPoints(points), options);
  }
  template <class U, class = std::enable_if_t<!std::is_same<U, T>::value>>
  static ConvexPolyhedron fromMesh(const std::vector<Vec3<U>>& vertices,
                                   const std::vector<std::vector<int>>& faces,
                                   const HullOptions<T>& options = {}) {
    return fromMesh(convertPoints(vertices), faces, options);
  }

  /// fromPoints and fromMesh without exceptions: the shape, or the Error whose message is
  /// the what() of the InvalidInput they would throw. The entry points to use in builds
  /// without exceptions (-fno-exceptions), where fromPoints and fromMesh print that message
  /// and abort on bad input.
  static Result<ConvexPolyhedron> tryFromPoints(const std::vector<Vec3<T>>& points,
                                                const HullOptions<T>& options = {});
  static Result<ConvexPolyhedron> tryFromMesh(const std::vector<Vec3<T>>& vertices,
                                              const std::vector<std::vector<int>>& faces,
                                              const HullOptions<T>& options = {});
  template <class U, class = std::enable_if_t<!std::is_same<U, T>::value>>
  static Result<ConvexPolyhedron> tryFromPoints(const std::vector<Vec3<U>>& points,
                                                const HullOptions<T>& options = {}) {
    return tryFromPoints(convertPoints(points), options);
  }
  template <class U, class = std::enable_if_t<!std::is_same<U, T>::value>>
  static Result<ConvexPolyhedron> tryFromMesh(const std::vector<Vec3<U>>& vertices,
                                              const std::vector<std::vector<int>>& faces,
                                              const HullOptions<T>& options = {}) {
    return tryFromMesh(convertPoints(vertices), faces, options);
  }

  // ---- counts (V - E + F == 2) ----
  int numVertices() const { return static_cast<int>(vertices_.size()); }
  int numEdges() const { return static_cast<int>(edgeHalfEdge_.size()); }
  int numFaces() const { return static_cast<int>(faceStart_.size()) - 1; }
  int numHalfEdges() const { return static_cast<int>(heTwin_.size()); }

  // ---- vertices ----
  const Vec3<T>& vertex(int v) const { return vertices_[v]; }
  const std::vector<Vec3<T>>& vertices() const { return vertices_; }
  /// Index of vertex v in the input of fromPoints / fromMesh.
  int inputIndex(int v) const { return inputIndex_[v]; }
  /// Neighbouring vertices of v, in counter-clockwise order seen from outside.
  IndexRange vertexNeighbors(int v) const { return row(vertexStart_, vertexNeighbor_, v); }
  /// Faces around v, counter-clockwise seen from outside; vertexFaces(v)[i] lies
  /// between the edges to vertexNeighbors(v)[i] and vertexNeighbors(v)[i+1].
  IndexRange vertexFaces(int v) const { return row(vertexStart_, vertexFace_, v); }
  /// Outgoing half-edges of v, same order as vertexNeighbors(v).
  IndexRange vertexHalfEdges(int v) const { return row(vertexStart_, vertexHalfEdge_, v); }
  int degree(int v) const { return vertexStart_[v + 1] - vertexStart_[v]; }

  // ---- faces ----
  /// Vertex loop of f, counter-clockwise seen from outside. Its half-edges are
  /// faceStart(f) .. faceStart(f+1)-1 in the same order.
  IndexRange faceVertices(int f) const { return row(faceStart_, heOrigin_, f); }
  int faceStart(int f) const { return faceStart_[f]; }
  int faceSize(int f) const { return faceStart_[f + 1] - faceStart_[f]; }
  /// Outward normal of f (unit for inexact T, exact Newell normal for exact T).
  const Vec3<T>& faceNormal(int f) const { return faceNormal_[f]; }
  /// Plane offset: normal(f) . x == faceOffset(f) on the face.
  const T& faceOffset(int f) const { return faceOffset_[f]; }

  // ---- half-edges: h runs from heOrigin(h) to heOrigin(heNext(h)) on face heFace(h) ----
  int heOrigin(int h) const { return heOrigin_[h]; }
  int heTarget(int h) const { return heOrigin_[heNext(h)]; }
  int heTwin(int h) const { return heTwin_[h]; }
  int heFace(int h) const { return heFace_[h]; }
  int heEdge(int h) const { return heEdge_[h]; }
  int heNext(int h) const {
    const int f = heFace_[h];
    return h + 1 == faceStart_[f + 1] ? faceStart_[f] : h + 1;
  }
  int hePrev(int h) const {
    const int f = heFace_[h];
    return h == faceStart_[f] ? faceStart_[f + 1] - 1 : h - 1;
  }

  // ---- edges: each undirected edge once ----
  /// The half-edge of e whose face is edgeFaces(e).first.
  int edgeHalfEdge(int e) const { return edgeHalfEdge_[e]; }
  /// (origin, target) of edgeHalfEdge(e); read from a table (the hot loops of MDD ask for
  /// it at every EE face).
  std::pair<int, int> edgeVertices(int e) const { return {edgeVertex_[2 * e], edgeVertex_[2 * e + 1]}; }
  /// (left, right) faces of e: left is on the left of edgeVertices' first -> second.
  std::pair<int, int> edgeFaces(int e) const {
    const int h = edgeHalfEdge_[e];
    return {heFace_[h], heFace_[heTwin_[h]]};
  }

  // ---- size and tolerance ----
  /// The tolerance this shape was built with (0 for exact T), in length units.
  const T& tolerance() const { return tolerance_; }
  /// |x|max + |y|max + |z|max over the vertices (the scale tolerances are relative to).
  const T& extent() const { return extent_; }
  /// The average of the vertices: a point strictly inside the polyhedron (exact for
  /// exact T), made once at construction so queries never pay O(n) for one.
  const Vec3<T>& interiorPoint() const { return interior_; }
  /// A lower bound on the radius of a ball around interiorPoint() inside the shape (the
  /// hull of its vertices), in length units: the nearest face plane's distance less the
  /// shape's tolerance and the rounding of the planes; 0 for exact T (not computed).
  const T& interiorDepth() const { return interiorDepth_; }
  /// True when the shape is exactly the convex hull of its vertices, as numbers of T:
  /// always for fromPoints (an exact hull), and for fromMesh with exact T (validated
  /// without slack). A fromMesh shape in floating point is convex within its tolerance
  /// only. Exact questions about the shape (mddExact) are exact questions about the hull
  /// of its vertices; where this is true, a vertex that no neighbour beats along a
  /// direction is exactly the support vertex.
  bool isExactHull() const { return exactHull_; }
  /// False when, for inexact T, some edge's two face normals are opposite within
  /// defaults::kMddParallelEdgeFactor eps (|n_f + n_g| below it: an interior dihedral
  /// angle of about 1e-14 rad in double or less, possible only with a hull tolerance of
  /// 0). The shape is exact, but its unit normals no longer say which way such an edge
  /// turns, so the Gauss-map tests of mdd() and intersects() cannot be trusted on it and
  /// those reject it. Always true for exact T.
  bool edgesResolved() const { return edgesResolved_; }

  // ---- support (extreme vertex) ----
  /// A vertex maximising direction . x. Hill-climbs the vertex graph from `hint`:
  /// on a convex polytope a vertex no neighbour of which is strictly better is a
  /// global maximiser, so the answer is exact for exact T. O(path length * degree).
  int support(const Vec3<T>& direction, int hint = 0) const;
  /// Same by scanning every vertex (reference and tiny shapes). Ties: lowest index.
  int supportBruteForce(const Vec3<T>& direction) const;

  /// Axis-aligned bounding box (lo, hi) of the shape placed at `pose`, in the world frame
  /// (a broad phase's box): the six extreme vertices along the rows of the rotation, by
  /// hill-climbing (support), not a scan of every vertex. Exact for exact T; for floating
  /// point it holds every vertex's world position as pose.apply rounds it (each side is
  /// padded by 8 eps (|translation| + extent), the rounding of that product and more).
  std::pair<Vec3<T>, Vec3<T>> worldBounds(const Pose<T>& pose) const {
    Vec3<T> lo, hi;
    int hint = 0;
    for (int i = 0; i < 3; ++i) {
      const Vec3<T> d = pose.rotation.row(i).transpose();
      hint = support(d, hint);
      hi[i] = pose.apply(vertices_[hint])[i];
      lo[i] = pose.apply(vertices_[support(Vec3<T>(-d), hint)])[i];
      if constexpr (!ScalarTraits<T>::isExact) {
        using std::abs;
        const T pad = T(8) * ScalarTraits<T>::epsilon() * (abs(pose.translation[i]) + extent_);
        hi[i] += pad;
        lo[i] -= pad;
      }
    }
    return {lo, hi};
  }

  /// Slots for lazily built derived structures (see detail::DerivedSlots).
  detail::DerivedSlots& derivedSlots() const { return *derived_; }

 private:
  ConvexPolyhedron() : derived_(std::make_shared<detail::DerivedSlots>()) {}
  static IndexRange row(const std::vector<int>& start, const std::vector<int>& data, int i) {
    return IndexRange(data.data() + start[i], data.data() + start[i + 1]);
  }
  template <class U>
  friend struct detail::PolyhedronBuilder;
  template <class U>
  friend struct detail::PolyhedronFinish;
  template <class U>
  static std::vector<Vec3<T>> convertPoints(const std::vector<Vec3<U>>& points) {
    std::vector<Vec3<T>> out;
    out.reserve(points.size());
    for (const Vec3<U>& p : points)
      out.emplace_back(static_cast<T>(p.x()), static_cast<T>(p.y()), static_cast<T>(p.z()));
    return out;
  }

  std::vector<Vec3<T>> vertices_;
  std::vector<int> inputIndex_;
  std::vector<int> vertexStart_, vertexNeighbor_, vertexFace_, vertexHalfEdge_;
  std::vector<int> faceStart_{0};
  std::vector<Vec3<T>> faceNormal_;
  std::vector<T> faceOffset_;
  std::vector<int> heOrigin_, heTwin_, heFace_, heEdge_;
  std::vector<int> edgeHalfEdge_;
  std::vector<int> edgeVertex_;  // 2e, 2e + 1: edgeVertices(e)
  T tolerance_ = T(0);
  T extent_ = T(0);
  Vec3<T> interior_ = Vec3<T>::Zero();
  T interiorDepth_ = T(0);
  bool edgesResolved_ = true;
  bool exactHull_ = false;
  std::shared_ptr<detail::DerivedSlots> derived_;
};

}  // namespace mink

#include "mink/polyhedron/detail/convex_polyhedron_impl.hpp"

// MINK_EXTERN_TEMPLATES: the float / double instantiations are compiled elsewhere
// (src/mink_instantiations.cpp; see mink/extern_templates.hpp).
#include "mink/core/detail/instantiation_lists.hpp"
MINK_DETAIL_DECLARE_EXTERN(POLYHEDRON)
