// mink/gauss_map/gauss_map.hpp — GaussMap<T>: the Gaussian image G(P) of a convex
// polyhedron, a planar graph on the unit sphere S², as a light view of the polyhedron.
//
// Source: Y.-K. Choi et al., "Computing the Minimum Directional Distance between Two
// Convex Polyhedra" (MDD-DUAL), section II-B (Gaussian image) and II-C (G(P ⊕ −Q) is the
// overlay of G(P) and G(−Q): points of one map inside regions of the other are the FV / VF
// faces of M, arc–arc crossings are the EE faces); section VI-B for the arc test.
//   face f    ↦ point   G(f) = faceNormal(f);
//   edge e    ↦ arc     G(e) from the normal of its left face to that of its right face;
//   vertex v  ↦ region  G(v), the convex spherical polygon with corners the normals of
//                        the faces around v (its closed normal cone).
// Queries: regionContains(v, d) — is v extreme in direction d; locate(d, hint) — the
// region holding d, by walking across arcs from region `hint`; edgeArcsIntersect — the
// section VI-B test between an arc of this map and one of another (possibly negated,
// possibly rotated) map.
//
// Conventions (all in the polyhedron's own frame):
//  * Points are the face normals as stored by ConvexPolyhedron: unit for inexact T, exact
//    Newell normals (not normalised) for exact T. Everything here is invariant under
//    positive scaling of normals and directions; directions d need not be unit.
//  * Arc e runs from from = normal(left face) to to = normal(right face), left/right as in
//    ConvexPolyhedron::edgeFaces(e). Then from × to is a positive multiple of the edge
//    vector x1 − x0, (x0, x1) = edgeVertices(e), and the great circle of the arc is the
//    set of directions orthogonal to the edge.
//  * Region corners are listed as vertexFaces(v): counter-clockwise seen from outside
//    the sphere, the region to the left of each directed side corner(i) → corner(i+1).
//  * G(−Q): the points, arcs and regions of −Q are those of Q negated; the region of
//    vertex v of Q, as a region of −Q (vertex −x_v), holds d iff regionContains(v, −d).
//    With poses, express directions in the shape's frame (d_shape = Rᵀ d_world), or
//    rotate arcs with rotatedArc / the rotation overload of edgeArcsIntersect.
//
// The map holds a pointer to the polyhedron and copies nothing: construction is O(1),
// and the polyhedron must outlive the map.
#pragma once

#include <utility>

#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/gauss_map/arc_intersection.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {

/// The endpoints of an arc, by value (after a rotation or a negation).
template <class T>
struct ArcEndpoints {
  Vec3<T> from;  ///< the left face's normal (transformed)
  Vec3<T> to;    ///< the right face's normal (transformed)
};

template <class T>
class GaussMap {
 public:
  using Scalar = T;

  /// The endpoints of an arc as references into the polyhedron's normals.
  struct ArcRef {
    const Vec3<T>& from;  ///< normal of edgeFaces(e).first (left face)
    const Vec3<T>& to;    ///< normal of edgeFaces(e).second (right face)
  };

  explicit GaussMap(const ConvexPolyhedron<T>& polyhedron) : poly_(&polyhedron) {}
  /// A map of a temporary would dangle.
  explicit GaussMap(const ConvexPolyhedron<T>&& polyhedron) = delete;

  const ConvexPolyhedron<T>& polyhedron() const { return *poly_; }

  // ---- the graph on S² ----
  int numPoints() const { return poly_->numFaces(); }
  int numArcs() const { return poly_->numEdges(); }
  int numRegions() const { return poly_->numVertices(); }

  /// G(f): the outward normal of face f (unit for inexact T, Newell for exact T).
  const Vec3<T>& point(int f) const { return poly_->faceNormal(f); }

  /// G(e): from the left face's normal to the right face's normal.
  ArcRef arc(int e) const {
    const std::pair<int, int> lr = poly_->edgeFaces(e);
    return ArcRef{poly_->faceNormal(lr.first), poly_->faceNormal(lr.second)};
  }

  /// G(e) mapped by the rotation R (shape frame → the frame R maps to), then negated if
  /// `negate` (for G(−Q)): endpoints ±R·from, ±R·to. R: 3 by 3, orthonormal, det +1.
  ArcEndpoints<T> rotatedArc(int e, const Mat3<T>& R, bool negate = false) const {
    const ArcRef a = arc(e);
    ArcEndpoints<T> out{R * a.from, R * a.to};
    if (negate) {
      out.from = -out.from;
      out.to = -out.to;
    }
    return out;
  }

  /// Number of corners of G(v) (= degree of v).
  int regionSize(int v) const { return poly_->degree(v); }
  /// Corner i of G(v): the normal of vertexFaces(v)[i]; counter-clockwise seen from outside.
  const Vec3<T>& regionCorner(int v, int i) const {
    return poly_->faceNormal(poly_->vertexFaces(v)[i]);
  }

  /// Does direction d (any non-zero vector, shape frame) lie in the closed region G(v),
  /// i.e. does v maximise d·x over the polyhedron?
  ///
  /// Implemented as: d·x_w <= d·x_v for every neighbour w of v, a tie (equal in T) broken
  /// by the sign of d·(x_w − x_v) where that is certain (an edge shorter than the rounding
  /// of the values: detail::surelyUphill). Why this is the region:
  /// the edges at v span the tangent cone of the polytope at v, so the closed normal cone
  /// of v — which is G(v) — is { d : d·(x_w − x_v) <= 0 for all neighbours w }; the side
  /// of G(v) between corners i and i+1 lies on the great circle orthogonal to the edge
  /// (v, w_{i+1}). For exact T this is an exact sign test of a polynomial of the inputs.
  /// Why this form rather than the corners (regionContainsByCorners): it makes the very
  /// same comparisons as ConvexPolyhedron::support and locate, so for inexact T the three
  /// agree to the bit — locate(d) always lies in its own region, and a vertex whose
  /// region holds d is one where the hill-climb stops.
  bool regionContains(int v, const Vec3<T>& d) const {
    const Vec3<T>& x = poly_->vertex(v);
    const T here = d.dot(x);
    for (int w : poly_->vertexNeighbors(v)) {
      const T val = d.dot(poly_->vertex(w));
      if (val > here || (val == here && detail::surelyUphill(d, x, poly_->vertex(w)))) return false;
    }
    return true;
  }

  /// The same set tested on the Gauss map itself: d is in G(v) iff
  /// det[corner(i), corner(i+1), d] >= 0 for every side (the region lies to the left of
  /// its counter-clockwise sides). Equal to regionContains for exact T (corner(i) ×
  /// corner(i+1) is a positive multiple of x_v − x_{w_{i+1}}); for inexact T it is the
  /// region bounded by the rounded normals, consistent with edgeArcsIntersect.
  bool regionContainsByCorners(int v, const Vec3<T>& d) const {
    const IndexRange faces = poly_->vertexFaces(v);
    const int m = faces.size();
    for (int i = 0; i < m; ++i) {
      const Vec3<T>& p = poly_->faceNormal(faces[i]);
      const Vec3<T>& q = poly_->faceNormal(faces[i + 1 == m ? 0 : i + 1]);
      if (detail::det3(p, q, d) < T(0)) return false;
    }
    return true;
  }

  /// A vertex v with regionContains(v, d): starting in region `hint` (any vertex index;
  /// out of range means 0), repeatedly cross the side of the current region that d is
  /// beyond into the neighbouring region — the one whose vertex is best in direction d
  /// (steepest ascent of d·x over the vertex graph). The values d·x strictly increase
  /// along the walk, so it never revisits a region and terminates, for inexact T too;
  /// on a convex polytope the region it stops in holds d (see regionContains). This is
  /// the walk of ConvexPolyhedron::support, which it calls. Cost: O(walk length × degree).
  int locate(const Vec3<T>& d, int hint = 0) const { return poly_->support(d, hint); }

  /// Section VI-B test between arc ep of this map and arc eq of `other` (G(Q), or G(−Q)
  /// when negateOther: its arcs are the negated normals of Q). Both maps in one frame.
  /// Evaluated in T (exact for exact T). For inexact T and the exact answer on the same
  /// numbers, pass the endpoints (arc / rotatedArc) to classifyArcsExact.
  ArcIntersection edgeArcsIntersect(int ep, const GaussMap& other, int eq, bool negateOther) const {
    const ArcRef a = arc(ep);
    const ArcRef b = other.arc(eq);
    const ArcVolumes<T> v = arcVolumes(a.from, a.to, b.from, b.to);
    return classifyArcs(negateOther ? v.negatedSecondArc() : v);
  }

  /// As above, with `other` placed by the rotation otherToThis (3 by 3, orthonormal,
  /// det +1, mapping the other shape's frame into this one: R_thisᵀ R_other for world
  /// rotations R_this, R_other). Its arc endpoints become ±otherToThis · normal.
  ArcIntersection edgeArcsIntersect(int ep, const GaussMap& other, int eq, bool negateOther,
                                    const Mat3<T>& otherToThis) const {
    const ArcRef a = arc(ep);
    const ArcEndpoints<T> b = other.rotatedArc(eq, otherToThis);
    const ArcVolumes<T> v = arcVolumes(a.from, a.to, b.from, b.to);
    return classifyArcs(negateOther ? v.negatedSecondArc() : v);
  }

 private:
  const ConvexPolyhedron<T>* poly_;
};

}  // namespace mink
