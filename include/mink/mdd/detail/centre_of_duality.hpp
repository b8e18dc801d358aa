// mink/mdd/detail/centre_of_duality.hpp — Step 1 of MDD-DUAL (Choi et al., section
// IV-A): does the line {t s} meet M = P ⊕ −Q, and if so, a point c of it strictly
// inside M.
//
// The paper projects both polyhedra along s and builds the 2-D Minkowski difference of
// their silhouettes, O(n) per query. mink instead asks M's projection M' only for support
// points (support of P and of −Q along directions orthogonal to s, from the hierarchies
// or warm hill-climbs), with a 2-D portal refinement (Minkowski portal refinement,
// Snethen 2008, cut down to the plane):
//   1. v0: projection of x0 = interior(P) − interior(Q), a point strictly inside M'.
//   2. Find a portal v1–v2 of support points whose cone from v0 holds the origin.
//   3. Origin strictly on v0's side of the portal: inside M'. Lift its barycentric
//      coordinates in (v0, v1, v2) to 3-D: c = λ0 x0 + λ1 X1 + λ2 X2 lies on the line and,
//      as λ0 > 0 and x0 is interior, strictly inside M (the paper's tetrahedron trick
//      serves the same end).
//   4. Otherwise take the support point X3 along the portal's outer normal: if it is not
//      beyond the origin, the origin is outside M' (case 1, NoContact) or on its boundary
//      (case 2: the line only grazes M); else replace v1 or v2 by v3 and repeat.
// Every decision is the sign of a polynomial in the inputs (no division), so the result
// is exact for exact T; the number of steps is bounded by M' having finitely many
// vertices, and capped by defaults::kMddPortalFactor for inexact T.
#pragma once

#include <cmath>
#include <limits>
#include <utility>

#include "mink/core/defaults.hpp"
#include "mink/core/difference_orientation.hpp"
#include "mink/mdd/detail/contact_set.hpp"

namespace mink {
namespace detail {

template <class T>
struct CentreOfDuality {
  enum class Kind { Interior, Boundary, Outside, Limit };
  Kind kind = Kind::Outside;
  /// Interior: a point of the line, strictly inside M (frame of P).
  Vec3<T> c = Vec3<T>::Zero();
  /// Interior: the weight of the interior point x0 = interiorPoint(P) − interiorPoint(Q)
  /// in c, a convex combination of x0 and points of M (1: c = x0; 1 − λ on a segment;
  /// 1 − l1 − l2 in a triangle); negative where the computed weights are not all ≥ 0.
  /// With the shapes' interiorDepth(), it bounds how deep c lies inside M.
  T weightX0 = T(-1);
  /// Boundary: a direction orthogonal to s whose supporting plane of M contains the line.
  /// Outside: a direction orthogonal to s along which M's support is below 0 (the line
  /// is strictly beyond that supporting plane); the hints are then M's support there.
  Vec3<T> w = Vec3<T>::Zero();
};


/// Inexact T: does the line {t s} miss M, strictly beyond M's supporting plane normal to
/// D = s × a, a = w × s as rounded? D is exactly orthogonal to s (and close to |s|² w),
/// and the answer is exact on the numbers given (P's vertices, Q's in P's frame): each
/// shape's support vertex along D is reached by a hill-climb from the hint with exact
/// comparisons (D·(x − y) = det[s, a, x − y], core/difference_orientation.hpp), a vertex
/// no neighbour beats being the support on a convex polytope, then the sign of D·(p − q).
/// A rounded support value below 0 is not enough: on a line grazing a face of M (two
/// cylinders side by side, the line along their contact) the value is 0 exactly, and a
/// tied support vertex from the hierarchy rounded it below. The hints end at the two
/// support vertices, the certificate mddExact checks a NoContact with. Usually no move
/// and one determinant per neighbour of the two vertices, a filter deciding each.
template <class T>
bool missesExactly(const PairFrame<T>& F, const Vec3<T>& s, const Vec3<T>& w, int& hintP, int& hintQ) {
  using std::abs;
  const Vec3<T> a = w.cross(s);
  const Vec3<T> o = Vec3<T>::Zero();
  // D·x > D·y? A filter first: D and its magnitudes |s_i a_j| + |s_j a_i| rounded once,
  // z = x − y rounded; the error of D·z against det[s, a, x − y] is below 6u Σ A_k |z_k|
  // (u = eps / 2) plus the absolute error of products below the normal range.
  const Vec3<T> D = s.cross(a);
  const Vec3<T> A(abs(s[1] * a[2]) + abs(s[2] * a[1]), abs(s[2] * a[0]) + abs(s[0] * a[2]),
                  abs(s[0] * a[1]) + abs(s[1] * a[0]));
  constexpr T u = std::numeric_limits<T>::epsilon() / T(2);
  auto above = [&](const Vec3<T>& x, const Vec3<T>& y) {
    const Vec3<T> z = x - y;
    const T value = D.dot(z);
    const Vec3<T> za = z.cwiseAbs();
    const T bound = T(8) * u * A.dot(za) + T(4) * std::numeric_limits<T>::denorm_min() * (za[0] + za[1] + za[2]) +
                    T(64) * std::numeric_limits<T>::min();
    if (value > bound) return true;
    if (-value > bound) return false;
    return orientDiff(o, s, o, a, y, x) > 0;
  };
  const ConvexPolyhedron<T>& P = F.P();
  const ConvexPolyhedron<T>& Q = F.Q();
  for (bool moved = true; moved;) {
    moved = false;
    const Vec3<T> p = P.vertex(hintP);
    for (int v : P.vertexNeighbors(hintP))
      if (above(P.vertex(v), p)) {
        hintP = v;
        moved = true;
        break;
      }
  }
  for (bool moved = true; moved;) {
    moved = false;
    const Vec3<T> q = F.q(hintQ);
    for (int v : Q.vertexNeighbors(hintQ))
      if (above(q, F.q(v))) {
        hintQ = v;
        moved = true;
        break;
      }
  }
  return above(F.q(hintQ), P.vertex(hintP));
}

/// Step 1 for direction s (frame of P). hintP / hintQ: support vertex hints (in and out).
template <class T>
CentreOfDuality<T> centreOfDuality(const PairFrame<T>& F, const Vec3<T>& s, int& hintP, int& hintQ) {
  using Kind = typename CentreOfDuality<T>::Kind;
  CentreOfDuality<T> out;
  const auto basis = orthogonalBasis(s);
  const Vec3<T>& u1 = basis.first;
  const Vec3<T>& u2 = basis.second;
  // In units of 2^e for a scene far from unit order (PairFrame::unitScaleExponent;
  // exact, and every test below is homogeneous in the coordinates).
  const int e = F.unitScaleExponent();
  auto proj = [&](const Vec3<T>& x) {
    if constexpr (!ScalarTraits<T>::isExact) {
      using std::ldexp;
      if (e != 0) return Pt2<T>(ldexp(T(x.dot(u1)), -e), ldexp(T(x.dot(u2)), -e));
    }
    return Pt2<T>(x.dot(u1), x.dot(u2));
  };
  auto lift = [&](const Pt2<T>& d) { return Vec3<T>(d.first * u1 + d.second * u2); };
  // Support point of M along the 3-D direction of the 2-D direction d.
  auto support = [&](const Pt2<T>& d) {
    const Vec3<T> D = lift(d);
    // The portal's directions jump around the circle: on large shapes the hierarchy's
    // O(log n) beats a hill-climb from the last vertex.
    hintP = F.supportPFar(D, hintP);
    hintQ = F.supportMinusQFar(D, hintQ);
    return Vec3<T>(F.P().vertex(hintP) - F.q(hintQ));
  };
  auto boundary = [&](const Pt2<T>& d) {
    out.kind = Kind::Boundary;
    out.w = lift(d);
    return out;
  };
  // Outside only where certified exactly (inexact T); a line within rounding of M's
  // supporting plane grazes it (the facet then says whether the line meets M).
  auto outside = [&](const Pt2<T>& d) {
    out.w = lift(d);
    if constexpr (!ScalarTraits<T>::isExact) {
      if (!missesExactly(F, s, out.w, hintP, hintQ)) return boundary(d);
    }
    out.kind = Kind::Outside;
    return out;
  };

  const Vec3<T> x0 = F.P().interiorPoint() - (F.R() * F.Q().interiorPoint() + F.t());
  const Pt2<T> v0 = proj(x0);
  const Pt2<T> zero(T(0), T(0));
  if (v0 == zero) {
    out.kind = Kind::Interior;
    out.c = x0;
    out.weightX0 = T(1);
    return out;
  }
  const Pt2<T> r(-v0.first, -v0.second);  // from v0 towards the origin
  Vec3<T> X1 = support(r);
  Pt2<T> v1 = proj(X1);
  {
    const T h = dot2(r, v1);  // support value; the origin's value is 0
    if (h < T(0)) return outside(r);
    if (h == T(0)) return boundary(r);
  }
  // Origin on the segment v0–v1: inside (v1 is in M', v0 interior).
  const Pt2<T> d01 = sub2(v1, v0);
  const T side = cross2(d01, r);
  if (side == T(0)) {
    // origin = v0 + λ (v1 − v0) with λ = |v0|² / (r·(v1 − v0)) in (0, 1)
    const T lambda = dot2(r, r) / dot2(r, d01);
    out.kind = Kind::Interior;
    out.c = x0 + lambda * (X1 - x0);
    if (lambda >= T(0) && lambda <= T(1)) out.weightX0 = T(1) - lambda;
    return out;
  }
  // Second support point on the origin's side of line v0 v1; keep (v1, v2) counter-
  // clockwise around v0.
  Pt2<T> n = side > T(0) ? Pt2<T>(-d01.second, d01.first) : Pt2<T>(d01.second, -d01.first);
  Vec3<T> X2 = support(n);
  Pt2<T> v2 = proj(X2);
  {
    const T h = dot2(n, v2);
    if (h < T(0)) return outside(n);
    if (h == T(0)) return boundary(n);
  }
  if (side < T(0)) {
    std::swap(v1, v2);
    std::swap(X1, X2);
  }
  const long long cap =
      defaults::kMddPortalFactor * (F.P().numVertices() + F.Q().numVertices() + 16);
  for (long long it = 0; it < cap; ++it) {
    // Keep the origin inside the cone (v0; v1, v2): rotate the portal until it is.
    const T o1 = cross2(sub2(v1, v0), r);  // >= 0: origin left of v0->v1
    const T o2 = cross2(r, sub2(v2, v0));  // >= 0: origin right of v0->v2
    if (o1 < T(0)) {
      // Origin clockwise of v1: new v1 from the outer normal of v0 -> v1 (right side).
      const Pt2<T> d = sub2(v1, v0);
      const Pt2<T> nn(d.second, -d.first);
      const Vec3<T> X = support(nn);
      const Pt2<T> v = proj(X);
      const T h = dot2(nn, v);
      if (h < T(0)) return outside(nn);
      if (h == T(0)) return boundary(nn);
      v2 = v1;
      X2 = X1;
      v1 = v;
      X1 = X;
      continue;
    }
    if (o2 < T(0)) {
      const Pt2<T> d = sub2(v2, v0);
      const Pt2<T> nn(-d.second, d.first);
      const Vec3<T> X = support(nn);
      const Pt2<T> v = proj(X);
      const T h = dot2(nn, v);
      if (h < T(0)) return outside(nn);
      if (h == T(0)) return boundary(nn);
      v1 = v2;
      X1 = X2;
      v2 = v;
      X2 = X;
      continue;
    }
    // Portal v1 -> v2, outer normal (away from v0).
    const Pt2<T> e = sub2(v2, v1);
    const Pt2<T> np(e.second, -e.first);
    const T originBeyond = -dot2(np, v1);  // np·(0 − v1)
    if (originBeyond < T(0)) {
      // Strictly inside the triangle's portal side: barycentric lift.
      const T A = cross2(sub2(v1, v0), sub2(v2, v0));
      const T l1 = cross2(sub2(zero, v0), sub2(v2, v0)) / A;
      const T l2 = cross2(sub2(v1, v0), sub2(zero, v0)) / A;
      out.kind = Kind::Interior;
      out.c = (T(1) - l1 - l2) * x0 + l1 * X1 + l2 * X2;
      if (l1 >= T(0) && l2 >= T(0) && T(1) - l1 - l2 >= T(0)) out.weightX0 = T(1) - l1 - l2;
      return out;
    }
    const Vec3<T> X3 = support(np);
    const Pt2<T> v3 = proj(X3);
    const T h = dot2(np, v3);
    if (h < T(0)) return outside(np);  // the whole of M' is short of the origin
    // h == 0: the supporting line of M' along np passes through the origin (then, as
    // the origin is not strictly inside, it is on M' only if on that edge or vertex).
    if (h == T(0) || !(dot2(np, sub2(v3, v1)) > T(0))) return boundary(np);
    // Replace the portal end on the same side of the ray v0 -> origin as v3.
    if (cross2(sub2(v3, v0), r) >= T(0)) {
      v1 = v3;
      X1 = X3;
    } else {
      v2 = v3;
      X2 = X3;
    }
  }
  out.kind = Kind::Limit;
  return out;
}

}  // namespace detail
}  // namespace mink
