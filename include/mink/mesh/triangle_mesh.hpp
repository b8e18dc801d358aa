// mink/mesh/triangle_mesh.hpp — TriangleMesh<T>: a closed, 2-manifold, outward-oriented
// triangle mesh of any genus (several connected components allowed), the input shape of
// CPD (CPD paper, sections 3.2 and 5: the surfaces whose Minkowski sum it builds).
//
// fromMesh validates the input and builds, once:
//   1. index checks (range, repeated corners) and coordinate checks (finite, within
//      ScalarTraits<T>::largestCoordinate());
//   2. the half-edges of every triangle, grouped by undirected edge (sorting): each edge
//      must be used by exactly two triangles, once in each direction;
//   3. the triangles around each vertex must form one fan (a disc), every vertex used;
//   4. geometry, decided exactly (core/orientation.hpp): no triangle with collinear
//      corners; every edge Convex, Reflex or Flat (two triangles folded onto each other
//      across an edge, a dihedral angle of 0, are rejected); every connected component
//      with a positive signed volume (mesh/detail/signed_volume.hpp);
//   5. adjacency in compressed arrays (edges, triangle neighbours, vertex stars in cyclic
//      order), triangle normals, the bounding box and the sphere tree (sphere_tree.hpp).
// The object is immutable afterwards; copies share one body (copying is cheap).
//
// Conventions: triangles are counter-clockwise seen from outside; triangleNormal(t) =
// (b − a) × (c − a) points outward and is not normalised (exact for exact T). Side i of
// a triangle runs from its corner i to corner i + 1 (mod 3). Everything is in the mesh's
// own frame. Not checked (O(n log n) by findSelfIntersection in self_intersection.hpp):
// that the surface does not intersect itself; the queries of this layer assume it.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <typeindex>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/index_range.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/mesh/sphere_tree.hpp"

namespace mink {

/// The interior angle of the solid at an edge, decided exactly from its two triangles.
enum class EdgeKind {
  Convex,  ///< interior angle < π: the far corner of either triangle lies strictly below the other's plane
  Reflex,  ///< interior angle > π: strictly above
  Flat,    ///< interior angle = π: the two triangles are coplanar, on opposite sides of the edge
};

namespace detail {
template <class T>
struct TriangleMeshBuilder;
template <class T>
struct TriangleMeshData;
}  // namespace detail

template <class T>
class TriangleMesh {
 public:
  using Scalar = T;

  /// A closed, 2-manifold, outward-oriented mesh: `vertices` (#V points), `triangles`
  /// (#F index triples, counter-clockwise seen from outside). Throws InvalidInput naming
  /// the problem and the offending element: empty input; a non-finite vertex; a
  /// coordinate above ScalarTraits<T>::largestCoordinate(); an index out of range; a
  /// degenerate triangle (repeated index, or collinear corners); an open edge (one
  /// triangle); a non-manifold edge (more than two); inconsistent orientation (an edge
  /// used twice in one direction); a non-manifold vertex (more than one fan); an
  /// unreferenced vertex; two triangles folded onto each other across an edge; a
  /// component oriented inward (negative signed volume) or of zero volume.
  static TriangleMesh fromMesh(const std::vector<Vec3<T>>& vertices,
                               const std::vector<std::array<int, 3>>& triangles);
  /// fromMesh without exceptions: the mesh, or the Error whose message is the what() of
  /// the InvalidInput fromMesh would throw (the entry point of builds without exceptions,
  /// where fromMesh prints that message and aborts).
  static Result<TriangleMesh> tryFromMesh(const std::vector<Vec3<T>>& vertices,
                                          const std::vector<std::array<int, 3>>& triangles);

  // ---- counts: V − E + F = 2 (#components − genus) ----
  int numVertices() const { return static_cast<int>(d_->vertices.size()); }
  int numTriangles() const { return static_cast<int>(d_->triangles.size()); }
  int numEdges() const { return static_cast<int>(d_->edgeVertices.size()); }
  int numComponents() const { return d_->numComponents; }

  // ---- vertices ----
  const Vec3<T>& vertex(int v) const { return d_->vertices[v]; }
  const std::vector<Vec3<T>>& vertices() const { return d_->vertices; }
  /// Neighbouring vertices of v in counter-clockwise order seen from outside.
  IndexRange vertexNeighbors(int v) const { return row(d_->vertexNeighbor, v); }
  /// Triangles around v, counter-clockwise; vertexTriangles(v)[i] lies between the edges
  /// to vertexNeighbors(v)[i] and vertexNeighbors(v)[i + 1].
  IndexRange vertexTriangles(int v) const { return row(d_->vertexTriangle, v); }
  /// Edges around v: vertexEdges(v)[i] joins v and vertexNeighbors(v)[i].
  IndexRange vertexEdges(int v) const { return row(d_->vertexEdge, v); }
  int degree(int v) const { return d_->vertexStart[v + 1] - d_->vertexStart[v]; }
  /// Every edge at v is Convex (v is a strictly convex corner; a Flat edge makes this false).
  bool vertexAllConvex(int v) const { return d_->vertexFlags[v] & kAllConvex; }
  /// No edge at v is Reflex (every edge Convex or Flat: the surface is locally convex at v).
  bool vertexNoReflex(int v) const { return d_->vertexFlags[v] & kNoReflex; }

  // ---- triangles ----
  /// The 3 corners of t, counter-clockwise seen from outside.
  const std::array<int, 3>& triangle(int t) const { return d_->triangles[t]; }
  const std::vector<std::array<int, 3>>& triangles() const { return d_->triangles; }
  /// (b − a) × (c − a) of t = (a, b, c): outward, twice the area long. Exact for exact T;
  /// for floating T within about one ulp of its length (core/orientation.hpp accurateCross).
  const Vec3<T>& triangleNormal(int t) const { return d_->normals[t]; }
  /// The edge of side i of t (corner i to corner i + 1).
  int triangleEdge(int t, int i) const { return d_->triangleEdge[3 * t + i]; }
  /// The triangle across side i of t.
  int triangleNeighbor(int t, int i) const { return d_->triangleNeighbor[3 * t + i]; }
  /// The connected component of t (0 .. numComponents() − 1).
  int triangleComponent(int t) const { return d_->component[t]; }

  // ---- edges: each undirected edge once ----
  /// (a, b): edgeTriangles(e).first runs a -> b, .second runs b -> a.
  std::pair<int, int> edgeVertices(int e) const { return d_->edgeVertices[e]; }
  std::pair<int, int> edgeTriangles(int e) const { return d_->edgeTriangles[e]; }
  EdgeKind edgeKind(int e) const { return d_->edgeKind[e]; }

  // ---- size ----
  /// Componentwise minimum and maximum of the vertices (exact).
  const Vec3<T>& boxMin() const { return d_->boxMin; }
  const Vec3<T>& boxMax() const { return d_->boxMax; }
  /// |x|max + |y|max + |z|max over the vertices (the scale of rounding bounds).
  const T& extent() const { return d_->extent; }

  /// The bounding-sphere hierarchy of the triangles, built by fromMesh.
  const SphereTree<T>& sphereTree() const { return d_->tree; }

  /// A structure of type D derived from this mesh by a higher layer (CPD's convex map):
  /// made by make() on the first request, then shared by every copy of the mesh and every
  /// caller (thread-safe; make runs at most once per type).
  template <class D, class Make>
  std::shared_ptr<const D> derived(Make&& make) const {
    auto& slot = *d_->derived;
    std::lock_guard<std::mutex> lock(slot.mutex);
    std::shared_ptr<const void>& p = slot.items[std::type_index(typeid(D))];
    if (!p) p = std::shared_ptr<const D>(make());
    return std::static_pointer_cast<const D>(p);
  }
  /// Has derived<D>() made its structure yet? Never builds; while another thread's first
  /// derived() call runs a make(), it waits for that call to finish.
  template <class D>
  bool hasDerived() const {
    auto& slot = *d_->derived;
    std::lock_guard<std::mutex> lock(slot.mutex);
    const auto it = slot.items.find(std::type_index(typeid(D)));
    return it != slot.items.end() && it->second != nullptr;
  }

 private:
  static constexpr unsigned char kAllConvex = 1, kNoReflex = 2;
  explicit TriangleMesh(std::shared_ptr<const detail::TriangleMeshData<T>> d) : d_(std::move(d)) {}
  IndexRange row(const std::vector<int>& data, int v) const {
    return IndexRange(data.data() + d_->vertexStart[v], data.data() + d_->vertexStart[v + 1]);
  }
  template <class U>
  friend struct detail::TriangleMeshBuilder;

  std::shared_ptr<const detail::TriangleMeshData<T>> d_;
};

namespace detail {
template <class T>
struct TriangleMeshData {
  std::vector<Vec3<T>> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Vec3<T>> normals;
  std::vector<int> triangleEdge, triangleNeighbor, component;
  std::vector<std::pair<int, int>> edgeVertices, edgeTriangles;
  std::vector<EdgeKind> edgeKind;
  std::vector<int> vertexStart, vertexNeighbor, vertexTriangle, vertexEdge;
  std::vector<unsigned char> vertexFlags;
  int numComponents = 0;
  Vec3<T> boxMin = Vec3<T>::Zero(), boxMax = Vec3<T>::Zero();
  T extent = T(0);
  SphereTree<T> tree;
  // Structures derived on request (TriangleMesh::derived), shared by all copies.
  struct Derived {
    std::mutex mutex;
    std::unordered_map<std::type_index, std::shared_ptr<const void>> items;
  };
  std::shared_ptr<Derived> derived = std::make_shared<Derived>();
};
}  // namespace detail

}  // namespace mink

#include "mink/mesh/detail/triangle_mesh_impl.hpp"
