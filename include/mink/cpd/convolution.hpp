// mink/cpd/convolution.hpp — the convolution A ⊗ −B of two closed triangle meshes: the
// facets a − b of compatible feature pairs, a superset of the boundary of M = A ⊕ −B.
//
// Source: Y. Lee, E. Behar, J.-M. Lien, Y. J. Kim, "Continuous penetration depth
// computation for rigid models using dynamic Minkowski sums", CAD 2016, section 3.2, after
// J.-M. Lien, "A simple method for computing Minkowski sum boundary in 3D using collision
// detection" (WAFR 2008): a pair of features is compatible when their Gauss images
// overlap, and every point of ∂M is a point a − b of a compatible face–vertex, vertex–face
// or edge–edge pair.
//
// mink states compatibility as the local condition that a point of ∂M needs (A and B + x
// touch there with disjoint interiors), each decided exactly from vertex coordinates:
//   FV (face f of A, vertex v of B): v is a local minimum of n_f · x over its star in B
//       (every neighbour w: det[f1 − f0, f2 − f0, w − v] >= 0): −v supports −B along n_f.
//   VF (vertex u of A, face g of B): u is a local maximum of −n_g · x over its star in A.
//   EE (edge e of A, edge e' of B, both convex, not parallel): a plane through both edge
//       directions has A's two faces at e on one side and B's two faces at e' on the
//       other (signs of det[d, d', r − p] for the far vertices r): the short Gauss arcs of
//       e and −e' cross. A reflex edge is never on such a plane's one side (its wedge is
//       wider than a half-space), so reflex edges form no EE facet of ∂M; the long arc of
//       a reflex edge (section 4.1) matters only to the convex map.
// The conditions are closed (ties count), so that the facets also cover ∂M where features
// are parallel or coplanar; a degenerate facet (zero area) is dropped. For a convex vertex
// the FV condition is "−n_f lies in the Gauss region of v": the paper's compatibility.
// The facets are oriented outward: their normal is M's outward normal wherever they lie on
// ∂M (n_f for FV, −n_g for VF, the EE plane's normal pointing from A to B).
//
// Frames: A's own frame; B's vertices are given already placed in it (R b + t), so that
// every predicate is exact on the same numbers.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mink/core/difference_orientation.hpp"
#include "mink/core/orientation.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {

/// Which features of A and B a facet of the convolution (and of the Minkowski patch) comes
/// from: FV (triangle of A, vertex of B), VF (vertex of A, triangle of B), EE (edge of A,
/// edge of B).
enum class ConvolutionType : std::uint8_t { FV, VF, EE };

/// A facet of A ⊗ −B named by its features: featureA / featureB are a triangle / vertex
/// (FV), a vertex / triangle (VF) or an edge / edge (EE) of A / B.
struct ConvolutionPair {
  ConvolutionType type = ConvolutionType::FV;
  int featureA = -1, featureB = -1;
  /// EE only: +1 when the outward normal is d_A × d_B (d = the edges' directions from
  /// edgeVertices' first to second), −1 when it is −(d_A × d_B).
  int orientation = 0;

  friend bool operator==(const ConvolutionPair& x, const ConvolutionPair& y) {
    return x.type == y.type && x.featureA == y.featureA && x.featureB == y.featureB;
  }
  /// A 64-bit key (type, featureA, featureB) for hashing and ordering.
  std::uint64_t key() const {
    return (static_cast<std::uint64_t>(type) << 62) | (static_cast<std::uint64_t>(static_cast<std::uint32_t>(featureA)) << 31) |
           static_cast<std::uint64_t>(static_cast<std::uint32_t>(featureB) & 0x7fffffffu);
  }
};

namespace detail {

/// The vertex of triangle t of X that is not an endpoint of edge (a, b).
template <class T>
int apexOf(const TriangleMesh<T>& X, int t, int a, int b) {
  const auto& tri = X.triangle(t);
  for (int k = 0; k < 3; ++k)
    if (tri[k] != a && tri[k] != b) return tri[k];
  return tri[0];
}

}  // namespace detail

/// The two meshes and B's vertices placed in A's frame: the operands of every test.
template <class T>
class ConvolutionFrame {
 public:
  ConvolutionFrame(const TriangleMesh<T>& A, const TriangleMesh<T>& B) : A_(A), B_(B) {}

  /// Places B in A's frame: b ↦ R b + t (R, t: B's pose relative to A's).
  void place(const Mat3<T>& R, const Vec3<T>& t) {
    R_ = R;
    t_ = t;
    bv_.resize(static_cast<std::size_t>(B_.numVertices()));
    for (int j = 0; j < B_.numVertices(); ++j) bv_[static_cast<std::size_t>(j)] = R * B_.vertex(j) + t;
  }

  const TriangleMesh<T>& A() const { return A_; }
  const TriangleMesh<T>& B() const { return B_; }
  const Mat3<T>& R() const { return R_; }
  const Vec3<T>& t() const { return t_; }
  const Vec3<T>& a(int i) const { return A_.vertex(i); }
  /// B's vertex j placed in A's frame.
  const Vec3<T>& b(int j) const { return bv_[static_cast<std::size_t>(j)]; }
  /// The point a_i − b_j of M (rounded once for inexact T; the same bits every time).
  Vec3<T> m(int i, int j) const { return a(i) - b(j); }

  /// FV: is vertex v of B a local minimum of n_f · x over its star (f a triangle of A)?
  bool compatibleFV(int f, int v) const {
    const auto& tri = A_.triangle(f);
    const Vec3<T>&p0 = a(tri[0]), &p1 = a(tri[1]), &p2 = a(tri[2]);
    for (int w : B_.vertexNeighbors(v))
      if (orientDiff(p0, p1, p0, p2, b(v), b(w)) < 0) return false;
    return true;
  }

  /// VF: is vertex u of A a local maximum of −n_g · x over its star (g a triangle of B)?
  bool compatibleVF(int u, int g) const {
    const auto& tri = B_.triangle(g);
    const Vec3<T>&q0 = b(tri[0]), &q1 = b(tri[1]), &q2 = b(tri[2]);
    for (int w : A_.vertexNeighbors(u))
      if (orientDiff(q0, q1, q0, q2, a(u), a(w)) < 0) return false;
    return true;
  }

  /// EE: 0 if edges e (of A) and e' (of B) are not compatible (either not convex — B's
  /// also as placed —, the edges parallel, or the faces not on the two sides of a plane
  /// through both), else the
  /// orientation (+1 / −1) of the facet's outward normal relative to d_A × d_B.
  int compatibleEE(int e, int ep) const {
    if (A_.edgeKind(e) != EdgeKind::Convex || B_.edgeKind(ep) != EdgeKind::Convex) return 0;
    const auto ea = A_.edgeVertices(e);
    const auto eb = B_.edgeVertices(ep);
    const auto ta = A_.edgeTriangles(e);
    const auto tb = B_.edgeTriangles(ep);
    const Vec3<T>&p = a(ea.first), &q = a(ea.second), &u = b(eb.first), &v = b(eb.second);
    const Vec3<T>& r1 = a(detail::apexOf(A_, ta.first, ea.first, ea.second));
    const Vec3<T>& r2 = a(detail::apexOf(A_, ta.second, ea.first, ea.second));
    const Vec3<T>& s1 = b(detail::apexOf(B_, tb.first, eb.first, eb.second));
    const Vec3<T>& s2 = b(detail::apexOf(B_, tb.second, eb.first, eb.second));
    // N = ε (d × d'): A's far vertices need ε·det[d, d', r − p] <= 0, B's ε·det[d, d', s − u] >= 0.
    const int a1 = orientDiff(p, q, u, v, p, r1), a2 = orientDiff(p, q, u, v, p, r2);
    if (a1 * a2 < 0) return 0;   // A's faces on both sides: no plane through both edges
    const int sideA = a1 != 0 ? a1 : a2;
    if (sideA == 0) return 0;    // parallel edges (or a flat wedge): no facet of positive area
    const int b1 = orientDiff(p, q, u, v, u, s1), b2 = orientDiff(p, q, u, v, u, s2);
    // B's far vertices must be on the other side (or on the plane).
    if (b1 == sideA || b2 == sideA) return 0;
    // B is placed by a rounded rotation: a nearly flat convex edge of B (a planar quad's
    // diagonal) can come out flat or reflex, and then both far vertices lie beyond a plane
    // through it without B being supported there. The edge must be convex as placed too
    // (the test of TriangleMesh's classification, on the placed corners).
    if (orient3d(u, v, s1, s2) >= 0) return 0;
    return -sideA;  // ε: ε · sideA < 0
  }

  /// Compatibility of a candidate pair (the orientation filled for EE). False if not.
  bool compatible(ConvolutionPair& c) const {
    switch (c.type) {
      case ConvolutionType::FV:
        return compatibleFV(c.featureA, c.featureB);
      case ConvolutionType::VF:
        return compatibleVF(c.featureA, c.featureB);
      case ConvolutionType::EE:
        c.orientation = compatibleEE(c.featureA, c.featureB);
        return c.orientation != 0;
    }
    return false;
  }

  /// The facet's polygon as pairs (i, j) of M-vertices a_i − b_j, counter-clockwise seen
  /// from outside: a triangle for FV / VF, the parallelogram p − u, q − u, q − v, p − v
  /// for EE. Returns the count of corners (3 or 4).
  int facetPolygon(const ConvolutionPair& c, std::array<int, 2>* out) const {
    std::array<std::array<int, 2>, 3> tris[2];
    const int n = facetTriangles(c, tris);
    for (int k = 0; k < 3; ++k) out[k] = tris[0][k];
    if (n == 2) out[3] = tris[1][2];
    return n == 2 ? 4 : 3;
  }

  /// The facet's triangles as pairs (i, j) of M-vertices a_i − b_j, counter-clockwise seen
  /// from outside (along the facet's outward normal): one for FV / VF, two for EE (the
  /// parallelogram p − u, q − u, q − v, p − v cut along a diagonal). Returns the count.
  int facetTriangles(const ConvolutionPair& c, std::array<std::array<int, 2>, 3>* out) const {
    switch (c.type) {
      case ConvolutionType::FV: {
        const auto& t = A_.triangle(c.featureA);
        out[0] = {{{t[0], c.featureB}, {t[1], c.featureB}, {t[2], c.featureB}}};
        return 1;
      }
      case ConvolutionType::VF: {
        // −B reverses orientation: the triangle's order is reversed to face along −n_g.
        const auto& t = B_.triangle(c.featureB);
        out[0] = {{{c.featureA, t[0]}, {c.featureA, t[2]}, {c.featureA, t[1]}}};
        return 1;
      }
      case ConvolutionType::EE: {
        const auto ea = A_.edgeVertices(c.featureA);
        const auto eb = B_.edgeVertices(c.featureB);
        // Corners p−u, q−u, q−v, p−v turn around −(d × d'): counter-clockwise for ε = −1.
        std::array<int, 2> k[4] = {{ea.first, eb.first}, {ea.second, eb.first}, {ea.second, eb.second}, {ea.first, eb.second}};
        if (c.orientation > 0) std::swap(k[1], k[3]);
        out[0] = {{k[0], k[1], k[2]}};
        out[1] = {{k[0], k[2], k[3]}};
        return 2;
      }
    }
    return 0;
  }

 private:
  const TriangleMesh<T>& A_;
  const TriangleMesh<T>& B_;
  Mat3<T> R_ = Mat3<T>::Identity();
  Vec3<T> t_ = Vec3<T>::Zero();
  std::vector<Vec3<T>> bv_;
};

/// Every compatible pair of A ⊗ −B, by testing all |F_A|·|V_B| + |V_A|·|F_B| + |E_A|·|E_B|
/// candidates: the reference enumeration (tests, and the "brute force" column of the
/// benchmark). `frame` must have been placed.
template <class T>
std::vector<ConvolutionPair> allCompatiblePairs(const ConvolutionFrame<T>& frame) {
  std::vector<ConvolutionPair> out;
  const TriangleMesh<T>& A = frame.A();
  const TriangleMesh<T>& B = frame.B();
  for (int f = 0; f < A.numTriangles(); ++f)
    for (int v = 0; v < B.numVertices(); ++v)
      if (frame.compatibleFV(f, v)) out.push_back({ConvolutionType::FV, f, v, 0});
  for (int u = 0; u < A.numVertices(); ++u)
    for (int g = 0; g < B.numTriangles(); ++g)
      if (frame.compatibleVF(u, g)) out.push_back({ConvolutionType::VF, u, g, 0});
  for (int e = 0; e < A.numEdges(); ++e) {
    if (A.edgeKind(e) != EdgeKind::Convex) continue;
    for (int ep = 0; ep < B.numEdges(); ++ep)
      if (const int o = frame.compatibleEE(e, ep)) out.push_back({ConvolutionType::EE, e, ep, o});
  }
  return out;
}

}  // namespace mink
