// mink/mesh/sphere_tree.hpp — SphereTree<T>: the bounding-sphere hierarchy S(X) of a
// triangle mesh (CPD paper, section 5.1, "Bootstrapping using bounding sphere hierarchy").
//
// A binary tree over the triangles, built top-down:
//   1. the triangles of a node are split at the median of their centroids along the
//      longest axis of the centroids' box (ties by triangle index, so the tree is a
//      function of the input alone);
//   2. leaves hold one triangle each and its smallest sphere (circumsphere when acute,
//      else the sphere on its longest side);
//   3. an inner node's centre is the better of two candidates (the midpoint of its
//      triangles' box, the sphere enclosing its children's spheres), its radius measured
//      from that centre over every corner of every triangle below it.
// Guarantee (what culling relies on): every point of every triangle below a node lies
// within radius(node) of centre(node) — radii are rounded up for floating T and exact
// rational upper bounds for exact T (see mesh/detail/enclosing_sphere.hpp).
// Storage is flat arrays in depth-first order: the root is node 0 and a node's left child
// is the next node, so a traversal walks memory forwards.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/mesh/detail/enclosing_sphere.hpp"

namespace mink {

template <class T>
class SphereTree {
 public:
  /// An empty tree (no nodes).
  SphereTree() = default;

  /// The hierarchy of `triangles` (indices into `vertices`, every index in range).
  static SphereTree build(const std::vector<Vec3<T>>& vertices, const std::vector<std::array<int, 3>>& triangles);

  /// 2 · #triangles − 1 (0 for no triangles).
  int numNodes() const { return static_cast<int>(radius_.size()); }
  /// The root, when numNodes() > 0.
  static constexpr int root() { return 0; }
  /// Centre of node's sphere, in the mesh's own frame.
  const Vec3<T>& centre(int node) const { return centre_[node]; }
  /// Radius of node's sphere (length units): an upper bound, see the header comment.
  const T& radius(int node) const { return radius_[node]; }
  bool isLeaf(int node) const { return triangle_[node] >= 0; }
  /// The triangle of a leaf; −1 for an inner node.
  int triangle(int node) const { return triangle_[node]; }
  /// Children of an inner node (left() == node + 1).
  int left(int node) const { return node + 1; }
  int right(int node) const { return right_[node]; }
  /// The leaf that holds triangle t.
  int leafOf(int t) const { return leafOf_[t]; }
  /// Levels on the longest root-to-leaf path (1 for a single triangle, 0 when empty).
  int height() const { return height_; }

 private:
  struct Builder;
  std::vector<Vec3<T>> centre_;
  std::vector<T> radius_;
  std::vector<int> right_, triangle_, leafOf_;
  int height_ = 0;
};

template <class T>
struct SphereTree<T>::Builder {
  const std::vector<Vec3<T>>& V;
  const std::vector<std::array<int, 3>>& F;
  SphereTree& tree;
  std::vector<Vec3<T>> centroid3;  // a + b + c: the centroid times 3, no division
  std::vector<int> order;

  int node(int lo, int hi, int depth) {
    const int id = static_cast<int>(tree.radius_.size());
    tree.centre_.emplace_back(Vec3<T>::Zero());
    tree.radius_.push_back(T(0));
    tree.right_.push_back(-1);
    tree.triangle_.push_back(-1);
    tree.height_ = std::max(tree.height_, depth);
    if (hi - lo == 1) {
      const int t = order[lo];
      const Sphere<T> s = detail::triangleSphere(V[F[t][0]], V[F[t][1]], V[F[t][2]]);
      tree.centre_[id] = s.centre;
      tree.radius_[id] = s.radius;
      tree.triangle_[id] = t;
      tree.leafOf_[t] = id;
      return id;
    }
    Vec3<T> lo3 = centroid3[order[lo]], hi3 = lo3;
    for (int i = lo + 1; i < hi; ++i)
      for (int k = 0; k < 3; ++k) {
        const T& x = centroid3[order[i]][k];
        if (x < lo3[k]) lo3[k] = x;
        if (hi3[k] < x) hi3[k] = x;
      }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (hi3[k] - lo3[k] > hi3[axis] - lo3[axis]) axis = k;
    const int mid = lo + (hi - lo) / 2;
    std::nth_element(order.begin() + lo, order.begin() + mid, order.begin() + hi, [&](int a, int b) {
      const T& xa = centroid3[a][axis];
      const T& xb = centroid3[b][axis];
      return xa < xb || (!(xb < xa) && a < b);
    });
    const int l = node(lo, mid, depth + 1);
    const int r = node(mid, hi, depth + 1);
    tree.right_[id] = r;
    enclose(id, l, r, lo, hi);
    return id;
  }

  // The sphere of an inner node: two candidate centres, each with the radius measured
  // over every corner below; the smaller wins.
  void enclose(int id, int l, int r, int lo, int hi) {
    const int n = 3 * (hi - lo);
    auto corner = [&](int i) -> const Vec3<T>& { return V[F[order[lo + i / 3]][i % 3]]; };
    Vec3<T> bl = corner(0), bh = bl;
    for (int i = 1; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        const T& x = corner(i)[k];
        if (x < bl[k]) bl[k] = x;
        if (bh[k] < x) bh[k] = x;
      }
    Vec3<T> best = detail::dyadicCentre(Vec3<T>((bl + bh) / T(2)));
    T bestR = detail::conservativeRadius(best, n, corner);
    // The sphere around both children's spheres, in double.
    const Vec3<double> c1 = detail::toDouble3(tree.centre_[l]), c2 = detail::toDouble3(tree.centre_[r]);
    const double r1 = detail::toDouble(tree.radius_[l]), r2 = detail::toDouble(tree.radius_[r]);
    const double d = (c2 - c1).norm();
    Vec3<double> m;
    if (d + r2 <= r1) {
      m = c1;
    } else if (d + r1 <= r2) {
      m = c2;
    } else {
      m = c1 + (c2 - c1) * ((0.5 * (d + r1 + r2) - r1) / d);
    }
    if (std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2])) {
      const Vec3<T> alt = Vec3<T>(T(m[0]), T(m[1]), T(m[2]));
      const T altR = detail::conservativeRadius(alt, n, corner);
      if (altR < bestR) best = alt, bestR = altR;
    }
    tree.centre_[id] = best;
    tree.radius_[id] = bestR;
  }
};

namespace detail {

/// Are the balls (ca, ra) and (cb, rb) certainly apart, |ca − cb| > ra + rb? Compared
/// squared (no sqrt); exactly for exact T; for floating T the right side is grown by
/// 16 eps, which covers the rounding of both sides, so `true` is never wrong.
template <class T>
bool spheresApart(const Vec3<T>& ca, const T& ra, const Vec3<T>& cb, const T& rb) {
  const Vec3<T> d = ca - cb;
  const T s = ra + rb;
  if constexpr (ScalarTraits<T>::isExact) {
    return d.squaredNorm() > s * s;
  } else {
    return d.squaredNorm() > s * s * (T(1) + T(16) * ScalarTraits<T>::epsilon());
  }
}

}  // namespace detail

template <class T>
SphereTree<T> SphereTree<T>::build(const std::vector<Vec3<T>>& vertices,
                                   const std::vector<std::array<int, 3>>& triangles) {
  SphereTree tree;
  const int nT = static_cast<int>(triangles.size());
  if (nT == 0) return tree;
  Builder b{vertices, triangles, tree, {}, {}};
  b.centroid3.reserve(triangles.size());
  for (const auto& t : triangles) b.centroid3.push_back(vertices[t[0]] + vertices[t[1]] + vertices[t[2]]);
  b.order.resize(triangles.size());
  for (int t = 0; t < nT; ++t) b.order[t] = t;
  const std::size_t nodes = 2 * triangles.size() - 1;
  tree.centre_.reserve(nodes);
  tree.radius_.reserve(nodes);
  tree.right_.reserve(nodes);
  tree.triangle_.reserve(nodes);
  tree.leafOf_.assign(triangles.size(), -1);
  b.node(0, nT, 1);
  return tree;
}

}  // namespace mink
