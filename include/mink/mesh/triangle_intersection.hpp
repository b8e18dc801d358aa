// mink/mesh/triangle_intersection.hpp — exact intersection tests of closed triangles and
// segments in 3-D (touching at a single point counts).
//
// Source: the orientation-predicate formulation of O. Devillers and P. Guigue, "Faster
// triangle-triangle intersection tests" (INRIA RR-4488, 2002), reworked as an interval
// test on the line L = plane(T1) ∩ plane(T2):
//   1. the side of each corner of T1 of plane(T2), and of T2 of plane(T1) (orient3d):
//      all strictly on one side means no contact;
//   2. all of them on the plane: the coplanar case, decided in 2-D (orient2d) on an axis
//      along which the triangles project to proper triangles: an edge of one meets the
//      other, or a corner of one lies in the other;
//   3. otherwise T1 ∩ L is the segment between the points where the two edges from an
//      "apex" of T1 (a corner alone on its side of plane(T2), or on it with the other two
//      strictly on one side) meet plane(T2), likewise T2 ∩ L; the order along L of a
//      point of T1's edge (a1, b1) and one of T2's edge (a2, b2) is the sign of
//      orient3d(a1, b1, a2, b2) times a factor common to all such pairs (derivation in
//      the comment "Order along L" below); the intervals are disjoint iff the four
//      orders of the ends agree strictly.
// Every decision is the exact sign of a determinant of the given coordinates: exact on
// the given numbers for float / double / long double, and for exact T. Triangles must be
// non-degenerate (corners not collinear; TriangleMesh guarantees it).
#pragma once

#include <algorithm>

#include "mink/core/orientation.hpp"
#include "mink/core/types.hpp"

namespace mink {

/// How a closed segment meets a closed triangle.
enum class SegmentContact {
  None,      ///< no common point
  Crossing,  ///< one common point, interior to both, the segment crossing the plane there
  Touching,  ///< any other contact: at an end of the segment, on an edge or corner of the
             ///< triangle, or the segment lying in the triangle's plane across it
};

namespace detail {

/// An axis along which (a, b, c) projects to a proper triangle (see orient2d's dropped
/// axis), or −1 for collinear corners.
template <class T>
int properAxis(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  for (int k = 0; k < 3; ++k)
    if (orient2d(a, b, c, k) != 0) return k;
  return -1;
}

/// 2-D (projection along axis k): is x, collinear with [a, b], within its box?
template <class T>
bool withinSegmentBox(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& x, int k) {
  for (int j = 1; j <= 2; ++j) {
    const int i = (k + j) % 3;
    if (x[i] < std::min(a[i], b[i]) || std::max(a[i], b[i]) < x[i]) return false;
  }
  return true;
}

/// 2-D (projection along axis k): do the closed segments [p1, p2] and [p3, p4] meet?
template <class T>
bool segmentsMeet2d(const Vec3<T>& p1, const Vec3<T>& p2, const Vec3<T>& p3, const Vec3<T>& p4, int k) {
  const int d1 = orient2d(p3, p4, p1, k), d2 = orient2d(p3, p4, p2, k);
  const int d3 = orient2d(p1, p2, p3, k), d4 = orient2d(p1, p2, p4, k);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && withinSegmentBox(p3, p4, p1, k)) || (d2 == 0 && withinSegmentBox(p3, p4, p2, k)) ||
         (d3 == 0 && withinSegmentBox(p1, p2, p3, k)) || (d4 == 0 && withinSegmentBox(p1, p2, p4, k));
}

/// 2-D (projection along axis k, in which (a, b, c) is proper): x in the closed triangle?
template <class T>
bool pointInTriangle2d(const Vec3<T>& x, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, int k) {
  const int o = orient2d(a, b, c, k);
  return orient2d(a, b, x, k) * o >= 0 && orient2d(b, c, x, k) * o >= 0 && orient2d(c, a, x, k) * o >= 0;
}

/// 2-D: does the closed segment [s, e] meet the closed triangle (a, b, c)?
template <class T>
bool segmentMeetsTriangle2d(const Vec3<T>& s, const Vec3<T>& e, const Vec3<T>& a, const Vec3<T>& b,
                            const Vec3<T>& c, int k) {
  return pointInTriangle2d(s, a, b, c, k) || pointInTriangle2d(e, a, b, c, k) || segmentsMeet2d(s, e, a, b, k) ||
         segmentsMeet2d(s, e, b, c, k) || segmentsMeet2d(s, e, c, a, k);
}

/// The closed triangles are coplanar: do they meet? (An edge of one meets the other, or
/// one lies inside the other, which puts its corners in it.)
template <class T>
bool coplanarTrianglesMeet(const Vec3<T>* t1, const Vec3<T>* t2) {
  const int k = properAxis(t1[0], t1[1], t1[2]);
  for (int i = 0; i < 3; ++i) {
    if (pointInTriangle2d(t1[i], t2[0], t2[1], t2[2], k) || pointInTriangle2d(t2[i], t1[0], t1[1], t1[2], k))
      return true;
    for (int j = 0; j < 3; ++j)
      if (segmentsMeet2d(t1[i], t1[(i + 1) % 3], t2[j], t2[(j + 1) % 3], k)) return true;
  }
  return false;
}

/// Closed axis-aligned boxes of the two point triples are disjoint (exact comparisons).
template <class T>
bool boxesDisjoint(const Vec3<T>* t1, const Vec3<T>* t2) {
  for (int k = 0; k < 3; ++k) {
    if (std::max({t2[0][k], t2[1][k], t2[2][k]}) < std::min({t1[0][k], t1[1][k], t1[2][k]})) return true;
    if (std::max({t1[0][k], t1[1][k], t1[2][k]}) < std::min({t2[0][k], t2[1][k], t2[2][k]})) return true;
  }
  return false;
}

/// Given the sides s[0..2] of a triangle's corners of the other triangle's plane (not all
/// zero, not all strictly on one side), the corner from which both edges reach the other
/// side: alone strictly on its side with the others on the other side or on the plane;
/// or, when the two others lie strictly on one side, the corner on the plane.
inline int apexCorner(const int* s) {
  for (int i = 0; i < 3; ++i)
    if (s[i] != 0 && s[(i + 1) % 3] != s[i] && s[(i + 2) % 3] != s[i]) return i;
  for (int i = 0; i < 3; ++i)
    if (s[i] == 0) return i;
  return 0;
}

// Order along L. For an edge (a1, b1) of T1 reaching plane(T2) at X and an edge (a2, b2) of
// T2 reaching plane(T1) at Y (both on L, the edges not lying in the planes), with n1, n2
// the triangles' normals and u1 = b1 − a1, u2 = b2 − a2: since a2 − a1 = (a2 − Y) + (Y − X)
// + (X − a1) with the first and last parallel to u2 and u1,
//   orient3d(a1, b1, a2, b2) = det[u1, a2 − a1, b2 − a1] = det[u1, Y − X, u2] = −λ det[u1, u2, d]
// for Y − X = λ d, d = n1 × n2; and det[u1, u2, n1 × n2] = (u1·n1)(u2·n2) − (u1·n2)(u2·n1)
// = −(u1·n2)(u2·n1) as u1 lies in plane(T1). With τ1 = sign((a1 − b1)·n2) and
// τ2 = sign((a2 − b2)·n1): sign λ = sign orient3d(a1, b1, a2, b2) · τ1 · τ2. Both edges
// from an apex have the same τ (its side, or minus the side of the other two corners
// when it lies on the plane), so τ1 τ2 is common to the four pairs compared.

}  // namespace detail

/// Do the closed triangles (p1, q1, r1) and (p2, q2, r2) share a point? Exact (see the
/// header comment); both triangles non-degenerate.
template <class T>
bool trianglesIntersect(const Vec3<T>& p1, const Vec3<T>& q1, const Vec3<T>& r1, const Vec3<T>& p2,
                        const Vec3<T>& q2, const Vec3<T>& r2) {
  const Vec3<T> t1[3] = {p1, q1, r1}, t2[3] = {p2, q2, r2};
  if (detail::boxesDisjoint(t1, t2)) return false;
  int s1[3], s2[3];  // sides of T1's corners of plane(T2), and of T2's of plane(T1)
  for (int i = 0; i < 3; ++i) s1[i] = orient3d(p2, q2, r2, t1[i]);
  if (s1[0] == s1[1] && s1[1] == s1[2] && s1[0] != 0) return false;
  for (int i = 0; i < 3; ++i) s2[i] = orient3d(p1, q1, r1, t2[i]);
  if (s2[0] == s2[1] && s2[1] == s2[2] && s2[0] != 0) return false;
  if ((s1[0] == 0 && s1[1] == 0 && s1[2] == 0) || (s2[0] == 0 && s2[1] == 0 && s2[2] == 0))
    return detail::coplanarTrianglesMeet(t1, t2);
  const int i1 = detail::apexCorner(s1), i2 = detail::apexCorner(s2);
  const Vec3<T>& a1 = t1[i1];
  const Vec3<T>& a2 = t2[i2];
  // The orders along L of the four pairs of ends: disjoint iff all agree strictly. Each is
  // orient3d times τ1 τ2, a factor common to all four, so the signs of orient3d decide.
  int seen = 0;
  for (int j1 = 1; j1 <= 2; ++j1)
    for (int j2 = 1; j2 <= 2; ++j2) {
      const int order = orient3d(a1, t1[(i1 + j1) % 3], a2, t2[(i2 + j2) % 3]);
      if (order == 0) return true;
      if (seen != 0 && order != seen) return true;
      seen = order;
    }
  return false;
}

/// How the closed segment [s, e] meets the closed, non-degenerate triangle (a, b, c),
/// exactly (see SegmentContact).
template <class T>
SegmentContact segmentTriangleContact(const Vec3<T>& s, const Vec3<T>& e, const Vec3<T>& a, const Vec3<T>& b,
                                      const Vec3<T>& c) {
  const int os = orient3d(a, b, c, s), oe = orient3d(a, b, c, e);
  if (os == oe && os != 0) return SegmentContact::None;
  if (os == 0 && oe == 0) {
    const int k = detail::properAxis(a, b, c);
    return detail::segmentMeetsTriangle2d(s, e, a, b, c, k) ? SegmentContact::Touching : SegmentContact::None;
  }
  // The segment meets the plane at one point X. With s = X − σ u, e = X + (1 − σ) u
  // (u = e − s), orient3d(a, b, s, e) = det[b − a, X − a, u] = κ (n · u), where
  // (b − a) × (X − a) = κ n and n = (b − a) × (c − a): the side of X of the edge (a, b)
  // within the plane (κ > 0 towards c), times the sign of n · u, the same for all three
  // edges (and non-zero: the segment is not parallel to the plane).
  const int g[3] = {orient3d(a, b, s, e), orient3d(b, c, s, e), orient3d(c, a, s, e)};
  const bool pos = g[0] > 0 || g[1] > 0 || g[2] > 0, neg = g[0] < 0 || g[1] < 0 || g[2] < 0;
  if (pos && neg) return SegmentContact::None;
  if (os == 0 || oe == 0 || g[0] == 0 || g[1] == 0 || g[2] == 0) return SegmentContact::Touching;
  return SegmentContact::Crossing;
}

/// Does the closed segment [s, e] meet the closed, non-degenerate triangle (a, b, c)?
template <class T>
bool segmentIntersectsTriangle(const Vec3<T>& s, const Vec3<T>& e, const Vec3<T>& a, const Vec3<T>& b,
                               const Vec3<T>& c) {
  return segmentTriangleContact(s, e, a, b, c) != SegmentContact::None;
}

/// Does the closed triangle (a, b, c) contain the point x (exactly)?
template <class T>
bool triangleContainsPoint(const Vec3<T>& x, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  if (orient3d(a, b, c, x) != 0) return false;
  return detail::pointInTriangle2d(x, a, b, c, detail::properAxis(a, b, c));
}

}  // namespace mink
