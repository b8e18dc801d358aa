// mink/mdd/detail/exit_portal.hpp — an estimate of the face of M = P ⊕ −Q through which the ray
// c + u σ (u > 0, c strictly inside M) leaves M, from support queries only. It replaces
// the initial-face heuristic of MDD-DUAL (Choi et al., section VI-A), which
// starts the searches around P's support vertex along σ and so walks far on large or
// elongated shapes.
//
// Minkowski portal refinement (Snethen, "XenoCollide", Game Programming Gems 7, 2008),
// run along the ray c + u σ instead of towards the origin:
//   1. Discovery: support points X1 (along σ), X2, X3 of M whose cone from c holds σ;
//      while σ leaves the cone across one side, replace the opposite point by the support
//      point along that side's outer normal.
//   2. Refinement: the portal triangle X1 X2 X3 is crossed by the ray. Take the support
//      point X4 along the portal's outer normal n; if it is no further along n than the
//      portal, the portal's plane supports M and n is the exit facet's normal; else
//      replace one corner by X4, keeping σ inside the cone, and repeat.
// For a polytope the refinement ends on the exit facet after finitely many steps; it is
// also capped (defaults::kMddExitPortalSteps). The estimate is only a starting point:
// mdd.hpp certifies the face it leads to, or runs the paper's searches from it.
//
// Collision mode (intersects.hpp; Snethen's MPR as a yes/no test): the ray runs from c
// through the origin, and the portal stops as soon as either
//   - a support point of M along a direction d is below the origin along d by more than
//     the touch tolerance (h_M(d) < −tol |d|, from P's and Q's own vertices): d separates;
//   - the origin lies in the tetrahedron (c, X1, X2, X3), a subset of M: decided by exact
//     orientation predicates (core/orientation.hpp) on the corners as computed, so "inside"
//     is exact on those numbers, which are points of M up to one rounding each.
// Neither (a touching contact, the cap, a degenerate portal): Unknown, and intersects()
// runs the paper's searches.
#pragma once

#include <algorithm>
#include <cmath>

#include "mink/core/defaults.hpp"
#include "mink/core/orientation.hpp"
#include "mink/gauss_map/arc_intersection.hpp"  // det3
#include "mink/mdd/detail/contact_set.hpp"       // orthogonalBasis
#include "mink/mdd/detail/pair_frame.hpp"

namespace mink {
namespace detail {

template <class T>
struct ExitPortal {
  /// Outward normal estimate of the exit facet (frame of P, not normalised).
  Vec3<T> normal = Vec3<T>::Zero();
  /// Support vertices of P and of −Q along `normal` (ids on P and on Q).
  int vertexP = -1, vertexQ = -1;
  /// Support queries on M made (each is one on P and one on −Q).
  int steps = 0;
  /// True when the portal's plane was shown to support M (exact for exact T).
  bool converged = false;
  /// Converged: the portal's corners, points of the exit facet as support vertex pairs
  /// (P's, −Q's); ExitFaceSearch::tryAround names an EE face from them.
  int cornerP[3] = {-1, -1, -1}, cornerQ[3] = {-1, -1, -1};
  /// The secant steps ran (both shapes large and finely faceted; exitPortal reruns
  /// without them if not converged).
  bool usedSecant = false;
  /// Collision mode only: what the portal proved about the origin.
  enum class Verdict { Unknown, Inside, Outside } verdict = Verdict::Unknown;
};

/// A portal corner: a support point of M minus c and its vertices; with the secant steps
/// also the direction it is the support point along (an outer normal of M there). Small
/// shapes never take secant steps and copy the narrower corner (1% of a cold query).
template <class T, bool Secant>
struct PortalCorner {
  Vec3<T> a;
  int p, q;
};
template <class T>
struct PortalCorner<T, true> : PortalCorner<T, false> {
  Vec3<T> d;
};

/// One run of the portal (exitPortal below), with the secant steps where `Secant` (the
/// shapes large and finely faceted, inexact T, mdd mode).
template <class T, bool Secant>
ExitPortal<T> exitPortalRun(const PairFrame<T>& F, const Vec3<T>& c, const Vec3<T>& sigma, int& hintP, int& hintQ,
                            const T* separationTol) {
  using Corner = PortalCorner<T, Secant>;
  ExitPortal<T> out;
  // Discovery directions jump across the sphere: the hierarchy or a seeded hill-climb
  // (support_seeds.hpp). Refinement directions move less: on large shapes a climb from
  // each shape's corner vertex furthest along the new direction, capped at
  // defaults::kHierarchyClimbMoves, then the hierarchy; else a hill-climb from the portal
  // corner furthest along the new direction.
  // Corners in units of 2^e for a scene far from unit order (exact; every test below is
  // homogeneous in them): products of two or three coordinates of 1e-224 underflow.
  const int e = F.unitScaleExponent();
  auto support = [&](const Vec3<T>& d, bool far) {
    ++out.steps;
    hintP = far ? F.supportPFar(d, hintP) : F.supportPRefine(d, hintP);
    hintQ = far ? F.supportMinusQFar(d, hintQ) : F.supportMinusQRefine(d, hintQ);
    const Vec3<T> a = F.P().vertex(hintP) - F.q(hintQ) - c;
    Corner y;
    y.a = e != 0 ? timesPow2(a, -e) : a;
    y.p = hintP;
    y.q = hintQ;
    if constexpr (Secant) y.d = d;
    return y;
  };
  auto finish = [&](const Vec3<T>& n, const Corner& at, bool converged) {
    out.normal = n;
    out.vertexP = at.p;
    out.vertexQ = at.q;
    out.converged = converged;
    return out;
  };
  const int cap = defaults::kMddExitPortalSteps;
  const bool large = F.hasHierarchy();
  auto climbFrom = [&](const Vec3<T>& n, const Corner& c1, const Corner& c2, const Corner& c3) {
    const Vec3<T> nq = F.R().transpose() * n;  // n in Q's frame: −Q's best has the least nq·q
    const Corner* cs[3] = {&c1, &c2, &c3};
    T bestP = n.dot(F.P().vertex(c1.p)), bestQ = nq.dot(F.Q().vertex(c1.q));
    hintP = c1.p;
    hintQ = c1.q;
    for (int i = 1; i < 3; ++i) {
      const T hp = n.dot(F.P().vertex(cs[i]->p)), hq = nq.dot(F.Q().vertex(cs[i]->q));
      if (hp > bestP) bestP = hp, hintP = cs[i]->p;
      if (hq < bestQ) bestQ = hq, hintQ = cs[i]->q;
    }
  };
  // Collision mode: does the support point y along d put the origin outside M by more
  // than the tolerance? From the vertices themselves (y.a is relative to c and rounded).
  auto separates = [&](const Vec3<T>& d, const Corner& y) {
    if (!separationTol) return false;
    const T h = d.dot(F.P().vertex(y.p) - F.q(y.q));
    if (!(h < T(0))) return false;
    if constexpr (!ScalarTraits<T>::isExact)
      if (!(h < -*separationTol * d.norm())) return false;
    out.verdict = ExitPortal<T>::Verdict::Outside;
    return true;
  };
  // Collision mode: the origin, relative to c in the corners' units (exact).
  const Vec3<T> origin = e != 0 ? timesPow2(Vec3<T>(-c), -e) : Vec3<T>(-c);
  const Vec3<T> zero = Vec3<T>::Zero();

  Corner b1 = support(sigma, true);
  if (separates(sigma, b1)) return finish(sigma, b1, false);
  const Vec3<T> m = b1.a.cross(sigma);
  if (m == Vec3<T>::Zero()) return finish(sigma, b1, false);  // the ray meets a vertex of M
  Corner x = support(m, true);
  if (separates(m, x)) return finish(m, x, false);
  // det(b1, x, σ) = −m·x < 0, so (x, b1, ·) is the positive order around σ.
  const Vec3<T> m3 = x.a.cross(b1.a);
  Corner b3 = support(m3, true);
  if (separates(m3, b3)) return finish(m3, b3, false);
  Corner b2 = b1;
  b1 = x;
  auto isCorner = [&](const Corner& y) {
    return (y.p == b1.p && y.q == b1.q) || (y.p == b2.p && y.q == b2.q) || (y.p == b3.p && y.q == b3.q);
  };
  // Secant steps (both shapes large and finely faceted, PairFrame::finelyFacetedLarge;
  // inexact T, mdd mode). On a finely tessellated smooth M a step along the portal's
  // normal shrinks the portal by a constant factor only, and its early steps jump far
  // (hierarchy descents). Each corner is the support point along its
  // own direction, an outer normal of M there; the ray's barycentric weights in the
  // portal, det(σ, b_j, b_k), interpolate those normals to an estimate of M's normal
  // where the ray leaves it, and the support point along that lands near the exit.
  constexpr bool secant = Secant && !ScalarTraits<T>::isExact;
  bool reopened = false;
  out.usedSecant = secant;
  auto secantNormal = [&](Vec3<T>& ni) {
    if constexpr (!secant) {
      (void)ni;
      return false;
    } else {
      const T w1 = det3(sigma, b2.a, b3.a), w2 = det3(sigma, b3.a, b1.a), w3 = det3(sigma, b1.a, b2.a);
      if (!(w1 >= T(0) && w2 >= T(0) && w3 >= T(0))) return false;
      ni = w1 * b1.d.normalized() + w2 * b2.d.normalized() + w3 * b3.d.normalized();
      return ni.allFinite() && ni != Vec3<T>::Zero();
    }
  };
  // Once a secant step returns a corner y (the exit is within about a face of it), a small
  // portal around y: the support points along three directions at angle ~ε from the secant
  // normal, climbed from y. ε: three times y's distance from the ray over the curvature
  // radius the corners show (their distance over the angle between their directions), at
  // least 1e-3; doubled until the three points' cone from c holds σ (six tries). The
  // refinement from there takes short climbs. A speed choice only: every answer is
  // certified after the portal (exit_face.hpp).
  auto reopenAround = [&](const Corner& y, const Vec3<T>& ni) {
    if constexpr (!secant) {
      (void)y, (void)ni;
      return false;
    } else {
      using std::acos;
      const Corner* bs[3] = {&b1, &b2, &b3};
      T radius = T(-1), shortest = T(0);
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) {
          const T len = (bs[i]->a - bs[j]->a).norm();
          const T angle = acos(std::max(T(-1), std::min(T(1), bs[i]->d.normalized().dot(bs[j]->d.normalized()))));
          if (len > T(0) && angle > T(0) && (radius < T(0) || len < shortest)) shortest = len, radius = len / angle;
        }
      if (!(radius > T(0)) || !ScalarTraits<T>::isFinite(radius)) return false;
      const Vec3<T> sh = sigma.normalized(), n0 = ni.normalized();
      const auto basis = orthogonalBasis(n0);
      T eps = std::max(T(3) * (y.a - y.a.dot(sh) * sh).norm() / radius, T(1e-3));
      for (int tries = 0; tries < 6 && out.steps + 3 <= cap; ++tries, eps *= T(2)) {
        Corner r[3];
        for (int k = 0; k < 3; ++k) {
          const T cs[3] = {T(1), T(-0.5), T(-0.5)}, sn[3] = {T(0), T(0.8660254037844386), T(-0.8660254037844386)};
          hintP = y.p;
          hintQ = y.q;
          r[k] = support(Vec3<T>(n0 + eps * (cs[k] * basis.first + sn[k] * basis.second)), false);
        }
        const T D = det3(r[0].a, r[1].a, r[2].a);
        if (D == T(0)) continue;
        if (D < T(0)) std::swap(r[1], r[2]);
        if (det3(sigma, r[1].a, r[2].a) >= T(0) && det3(r[0].a, sigma, r[2].a) >= T(0) &&
            det3(r[0].a, r[1].a, sigma) >= T(0)) {
          b1 = r[0], b2 = r[1], b3 = r[2];
          return true;
        }
      }
      return false;
    }
  };
  // Invariant from here: det(b1, b2, b3) > 0 (c strictly inside M makes every support
  // point strictly beyond c along its direction).
  while (out.steps < cap) {
    if (det3(b2.a, b3.a, sigma) < T(0)) {
      const Vec3<T> n = b3.a.cross(b2.a);
      if (n == Vec3<T>::Zero()) return finish(sigma, b1, false);
      const Corner y = support(n, true);
      if (separates(n, y)) return finish(n, y, false);
      b1 = y;
      std::swap(b2, b3);
    } else if (det3(b3.a, b1.a, sigma) < T(0)) {
      const Vec3<T> n = b1.a.cross(b3.a);
      if (n == Vec3<T>::Zero()) return finish(sigma, b1, false);
      const Corner y = support(n, true);
      if (separates(n, y)) return finish(n, y, false);
      const Corner o1 = b1;
      b1 = b3;
      b2 = y;
      b3 = o1;
    } else if (det3(b1.a, b2.a, sigma) < T(0)) {
      const Vec3<T> n = b2.a.cross(b1.a);
      if (n == Vec3<T>::Zero()) return finish(sigma, b1, false);
      const Corner y = support(n, true);
      if (separates(n, y)) return finish(n, y, false);
      std::swap(b1, b2);
      b3 = y;
    } else {
      break;
    }
  }
  while (out.steps < cap) {
    const Vec3<T> n = (b2.a - b1.a).cross(b3.a - b1.a);
    if (n == Vec3<T>::Zero()) return finish(sigma, b1, false);
    // Collision mode: the origin on c's side of the portal, so inside the tetrahedron
    // (c, b1, b2, b3) if the exact predicates agree (the float test only screens).
    if (separationTol && !(n.dot(origin - b1.a) > T(0)) && orient3d(zero, b1.a, b2.a, b3.a) > 0 &&
        orient3d(b1.a, b2.a, b3.a, origin) <= 0 && orient3d(zero, b2.a, b3.a, origin) >= 0 &&
        orient3d(zero, b3.a, b1.a, origin) >= 0 && orient3d(zero, b1.a, b2.a, origin) >= 0) {
      out.verdict = ExitPortal<T>::Verdict::Inside;
      return finish(n, b1, false);
    }
    Corner y;
    bool fromSecant = false;
    Vec3<T> ni;
    if (secant && secantNormal(ni)) {
      climbFrom(ni, b1, b2, b3);
      y = support(ni, false);
      if (isCorner(y)) {
        if (!reopened) {
          reopened = true;
          if (reopenAround(y, ni)) continue;
        }
      } else {
        fromSecant = n.dot(y.a - b1.a) > T(0);  // else the step along n decides
      }
    }
    if (!fromSecant) {
      // Hill-climb from the corner furthest along n: the shortest climb. Where a shape has
      // a hierarchy (a climb's step is a cache miss there, and a climb over the cap a
      // descent) each shape climbs from its own vertex furthest along n of the three.
      if (large) {
        climbFrom(n, b1, b2, b3);
      } else {
        const T h1 = n.dot(b1.a), h2 = n.dot(b2.a), h3 = n.dot(b3.a);
        const Corner& from = h1 >= h2 ? (h1 >= h3 ? b1 : b3) : (h2 >= h3 ? b2 : b3);
        hintP = from.p;
        hintQ = from.q;
      }
      y = support(n, false);
      if (separates(n, y)) return finish(n, y, false);
      if (isCorner(y) || !(n.dot(y.a - b1.a) > T(0))) {
        const Corner* bs[3] = {&b1, &b2, &b3};
        for (int i = 0; i < 3; ++i) out.cornerP[i] = bs[i]->p, out.cornerQ[i] = bs[i]->q;
        return finish(n, y, true);
      }
    }
    // The plane through the ray and y splits the portal; σ lies in the sub-cone on the
    // side where the signs of b_i·(σ × y) change (σ ∈ cone(b1, b2, y) iff b1·m ≥ 0 ≥ b2·m,
    // and cyclically).
    const Vec3<T> m = sigma.cross(y.a);
    const T d1 = b1.a.dot(m), d2 = b2.a.dot(m), d3 = b3.a.dot(m);
    if (d1 >= T(0) && d2 <= T(0)) {
      b3 = y;
    } else if (d2 >= T(0) && d3 <= T(0)) {
      b1 = y;
    } else if (d3 >= T(0) && d1 <= T(0)) {
      b2 = y;
    } else {
      return finish(n, y, false);  // rounding: keep the best normal so far
    }
    if (det3(b1.a, b2.a, b3.a) < T(0)) std::swap(b2, b3);
  }
  const Vec3<T> n = (b2.a - b1.a).cross(b3.a - b1.a);
  return finish(n == Vec3<T>::Zero() ? sigma : n, b1, false);
}

/// The exit-facet estimate for the ray c + u σ (frame of P). hintP / hintQ: support
/// vertex hints (in and out). With `separationTol` (collision mode: σ must point from c
/// at the origin), stops early with `verdict` Inside or Outside (header comment); an
/// Outside verdict's `normal` is the separating direction. On large, finely faceted
/// shapes the secant steps run first; where that portal does not converge (flat faces of thousands of
/// vertices can defeat the curvature estimate), the plain refinement runs again from the
/// start, so that the estimate is never worse than the plain one's.
template <class T>
ExitPortal<T> exitPortal(const PairFrame<T>& F, const Vec3<T>& c, const Vec3<T>& sigma, int& hintP,
                         int& hintQ, const T* separationTol = nullptr) {
  if (ScalarTraits<T>::isExact || separationTol || !F.finelyFacetedLarge())
    return exitPortalRun<T, false>(F, c, sigma, hintP, hintQ, separationTol);
  ExitPortal<T> est = exitPortalRun<T, true>(F, c, sigma, hintP, hintQ, separationTol);
  if (est.converged) return est;
  const int steps = est.steps;
  est = exitPortalRun<T, false>(F, c, sigma, hintP, hintQ, separationTol);
  est.steps += steps;
  return est;
}

}  // namespace detail
}  // namespace mink
