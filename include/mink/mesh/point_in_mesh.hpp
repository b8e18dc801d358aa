// mink/mesh/point_in_mesh.hpp — is a point inside, outside or on a closed triangle mesh
// (the solid it bounds)? Exact, by the parity of ray crossings.
//
// Source: the Jordan–Brouwer separation theorem (a closed surface separates space; a
// generic ray from an interior point crosses it an odd number of times), as in
// "point in polyhedron" by ray casting, made exact with orient3d:
//   1. a point outside the mesh's box is outside;
//   2. otherwise a segment from p to a point q beyond the box along one axis, slanted by
//      fixed irrational-like fractions of the box size in the other two, stands for the ray;
//   3. the sphere tree culls (exactly) every node whose sphere's box misses the segment's
//      box; each triangle left is classified by segmentTriangleContact: a Crossing counts,
//      a Touching contact that holds p means p is on the boundary, any other Touching
//      contact (the ray meets an edge or a corner, or lies in a triangle's plane across
//      it) spoils the ray: the next one is cast (another axis, sign and slant);
//   4. an odd count is Inside.
// After defaults::kPointInMeshMaxRays spoiled rays the answer is Undecided (not observed:
// the rays' slants avoid every edge of any input not built against the sequence).
// Decisions are exact on the given numbers, for every scalar type; no allocation beyond
// the caller's reusable traversal stack.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/mesh/triangle_intersection.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {

enum class PointLocation {
  Outside,
  Inside,      ///< in the interior of the solid
  OnBoundary,  ///< on a triangle
  Undecided,   ///< every ray met an edge or corner exactly (see the header comment)
};

namespace detail {

/// A mesh seen by the point-location and overlap queries: its triangles' corners, its
/// sphere tree's spheres and a box around all corners, possibly after a placement. The
/// guarantee a view keeps: every point of every triangle below a node lies within
/// nodeRadius(node) of nodeCentre(node), and every corner within [boxLo, boxHi].
template <class T>
struct MeshInOwnFrame {
  const TriangleMesh<T>& mesh;
  Vec3<T> corner(int t, int i) const { return mesh.vertex(mesh.triangle(t)[i]); }
  const SphereTree<T>& tree() const { return mesh.sphereTree(); }
  Vec3<T> nodeCentre(int node) const { return mesh.sphereTree().centre(node); }
  T nodeRadius(int node) const { return mesh.sphereTree().radius(node); }
  const Vec3<T>& boxLo() const { return mesh.boxMin(); }
  const Vec3<T>& boxHi() const { return mesh.boxMax(); }
};

/// The k-th ray's slant, two fractions in (−1/2, 1/2): the additive recurrence of the
/// plastic number (R2 sequence), evenly spread and far from simple ratios.
inline void raySlant(int k, double& f1, double& f2) {
  const double a1 = 0.7548776662466927, a2 = 0.5698402909980532;
  f1 = std::fmod(0.5 + a1 * (k + 1), 1.0) - 0.5;
  f2 = std::fmod(0.5 + a2 * (k + 1), 1.0) - 0.5;
}

/// Point location against a view (see MeshInOwnFrame). `stack` is reused between calls.
template <class T, class View>
PointLocation locatePoint(const View& view, const Vec3<T>& p, std::vector<int>& stack, int* raysCast = nullptr) {
  const Vec3<T> lo = view.boxLo(), hi = view.boxHi();
  for (int k = 0; k < 3; ++k)
    if (p[k] < lo[k] || hi[k] < p[k]) return PointLocation::Outside;
  T span = T(0);
  for (int k = 0; k < 3; ++k)
    if (span < T(hi[k] - lo[k])) span = hi[k] - lo[k];
  const SphereTree<T>& tree = view.tree();
  for (int ray = 0; ray < defaults::kPointInMeshMaxRays; ++ray) {
    if (raysCast) ++*raysCast;
    const int axis = ray % 3, o1 = (axis + 1) % 3, o2 = (axis + 2) % 3;
    double f1, f2;
    raySlant(ray, f1, f2);
    // q beyond the box along `axis` (strictly, whatever the rounding: |hi| + span > 0 is
    // added to hi), so q is on no triangle.
    Vec3<T> q;
    q[axis] = (ray / 3) % 2 == 0 ? T(hi[axis] + absValue(hi[axis]) + span) : T(lo[axis] - absValue(lo[axis]) - span);
    q[o1] = p[o1] + T(f1) * span;
    q[o2] = p[o2] + T(f2) * span;
    Vec3<T> slo, shi;
    for (int k = 0; k < 3; ++k) {
      slo[k] = std::min(p[k], q[k]);
      shi[k] = std::max(p[k], q[k]);
    }
    int crossings = 0;
    bool spoiled = false;
    stack.clear();
    stack.push_back(SphereTree<T>::root());
    // A spoiled ray is still followed to its end: a triangle holding p may come later.
    while (!stack.empty()) {
      const int node = stack.back();
      stack.pop_back();
      // Culled when the sphere's box misses the segment's box along some axis. Rounding
      // is monotone, so fl(c − shi) > r implies c − shi > r for the r a view returns.
      const Vec3<T> c = view.nodeCentre(node);
      const T r = view.nodeRadius(node);
      bool miss = false;
      for (int k = 0; k < 3 && !miss; ++k) miss = T(c[k] - shi[k]) > r || T(slo[k] - c[k]) > r;
      if (miss) continue;
      if (!tree.isLeaf(node)) {
        stack.push_back(tree.right(node));
        stack.push_back(tree.left(node));
        continue;
      }
      const int t = tree.triangle(node);
      const Vec3<T> a = view.corner(t, 0), b = view.corner(t, 1), cc = view.corner(t, 2);
      switch (segmentTriangleContact(p, q, a, b, cc)) {
        case SegmentContact::None:
          break;
        case SegmentContact::Crossing:
          ++crossings;
          break;
        case SegmentContact::Touching:
          if (triangleContainsPoint(p, a, b, cc)) return PointLocation::OnBoundary;
          spoiled = true;
          break;
      }
    }
    if (!spoiled) return crossings % 2 ? PointLocation::Inside : PointLocation::Outside;
  }
  return PointLocation::Undecided;
}

}  // namespace detail

/// Where p (in the mesh's frame) lies relative to the solid the closed mesh bounds:
/// exactly, for every scalar type (see the header comment). The mesh must be free of
/// self-intersections. Allocates its traversal stack; repeated queries should go through
/// MeshOverlap or keep a stack and call detail::locatePoint.
template <class T>
PointLocation locatePoint(const TriangleMesh<T>& mesh, const Vec3<T>& p) {
  std::vector<int> stack;
  stack.reserve(static_cast<std::size_t>(2 * mesh.sphereTree().height() + 4));
  return detail::locatePoint(detail::MeshInOwnFrame<T>{mesh}, p, stack);
}

}  // namespace mink
