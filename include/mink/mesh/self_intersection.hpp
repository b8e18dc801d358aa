// mink/mesh/self_intersection.hpp — does a closed triangle mesh intersect itself?
//
// TriangleMesh::fromMesh checks topology and local geometry only; the queries of this
// layer (point location, overlap) assume a surface that does not cross or touch itself.
// This check is the O(n log n) typical-case way to establish it, once per shape:
//   1. the mesh's sphere tree is traversed against itself (node pairs culled exactly
//      when their spheres are apart, compared squared);
//   2. two triangles with no common corner must not meet (trianglesIntersect);
//   3. two triangles with one common corner v meet elsewhere iff the edge of one opposite
//      v meets the other (their intersection is convex and contains v, so it holds a
//      segment from v whose far end lies on such an edge);
//   4. two triangles with a common edge meet only along it: across a Convex, Reflex or
//      Flat edge their planes differ or they lie on opposite sides, and fromMesh
//      rejects the rest (folded triangles).
// Distinct vertices at one position count (the surface touches itself there).
#pragma once

#include <utility>
#include <vector>

#include "mink/mesh/triangle_intersection.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {

struct SelfIntersection {
  bool found = false;
  int triangle1 = -1, triangle2 = -1;  ///< the first pair found (triangle1 < triangle2)
};

namespace detail {

/// Do triangles s and t (distinct) of the mesh meet anywhere except along what they share?
template <class T>
bool trianglesCross(const TriangleMesh<T>& mesh, int s, int t) {
  const auto& a = mesh.triangle(s);
  const auto& b = mesh.triangle(t);
  int shared = 0, ia = -1, ib = -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a[i] == b[j]) ++shared, ia = i, ib = j;
  auto P = [&](int v) -> const Vec3<T>& { return mesh.vertex(v); };
  if (shared == 0) return trianglesIntersect(P(a[0]), P(a[1]), P(a[2]), P(b[0]), P(b[1]), P(b[2]));
  if (shared == 1)
    return segmentIntersectsTriangle(P(a[(ia + 1) % 3]), P(a[(ia + 2) % 3]), P(b[0]), P(b[1]), P(b[2])) ||
           segmentIntersectsTriangle(P(b[(ib + 1) % 3]), P(b[(ib + 2) % 3]), P(a[0]), P(a[1]), P(a[2]));
  return false;
}

}  // namespace detail

/// The first pair of triangles of `mesh` that meet other than along a common edge or at a
/// common corner (see the header comment), or found = false. Exact; allocates.
template <class T>
SelfIntersection findSelfIntersection(const TriangleMesh<T>& mesh) {
  const SphereTree<T>& tree = mesh.sphereTree();
  std::vector<std::pair<int, int>> stack{{SphereTree<T>::root(), SphereTree<T>::root()}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (a == b) {
      if (tree.isLeaf(a)) continue;
      stack.push_back({tree.left(a), tree.right(a)});
      stack.push_back({tree.right(a), tree.right(a)});
      stack.push_back({tree.left(a), tree.left(a)});
      continue;
    }
    if (detail::spheresApart(tree.centre(a), tree.radius(a), tree.centre(b), tree.radius(b))) continue;
    const bool leafA = tree.isLeaf(a), leafB = tree.isLeaf(b);
    if (leafA && leafB) {
      const int s1 = tree.triangle(a), s2 = tree.triangle(b);
      if (detail::trianglesCross(mesh, s1, s2)) return {true, std::min(s1, s2), std::max(s1, s2)};
      continue;
    }
    if (leafB || (!leafA && !(tree.radius(a) < tree.radius(b)))) {
      stack.push_back({tree.right(a), b});
      stack.push_back({tree.left(a), b});
    } else {
      stack.push_back({a, tree.right(b)});
      stack.push_back({a, tree.left(b)});
    }
  }
  return {};
}

}  // namespace mink
