// mink/mdd/detail/mdd_fallbacks.hpp — the answers of mdd() that need no centre of
// duality strictly inside M = P ⊕ −Q (inexact T, near the limits of rounding):
//   - grazing(): case 2 of section IV-A (Choi et al.): the line lies in a supporting plane
//     of M and meets M only in that plane's facet, an interval read off the facet;
//   - chord(): the line's chord of M by clipping it against the plane of every face of M,
//     for a line that grazes M within the rounding of the centre of duality, or after a
//     search that hit the automatic visit cap (visits every edge pair: only within
//     MddOptions::maxExhaustivePairs, and MddResult::usedFallback says so);
//   - nearestWitnesses(), nearestFacetPoint(): witnesses for the chord's answer.
#pragma once

#include <cmath>

#include "mink/mdd/detail/exit_face.hpp"

namespace mink {
namespace detail {

template <class T>
class MddFallbacks {
 public:
  explicit MddFallbacks(ExitFaceSearch<T>& search, MddCache<T>& cache, const PairFrame<T>& F)
      : search_(search), check_(search.check()), cache_(cache), F_(F) {}

  /// The line's chord of M, [tlo, thi] in parameters of s, by clipping the line against
  /// the plane of every FV, VF and EE face (M is the intersection of their half-spaces),
  /// and the faces that bound it: the last resort for lines that graze M within the
  /// rounding of the centre of duality (which is then not reliably inside M). False if
  /// the line misses M by more than the rounding slack.
  bool chord(T& tlo, T& thi, MFace<T>& lo, MFace<T>& hi) {
    bool outside = false;
    search_.forEachFace([&](const MFace<T>& m) {
      const T ns = m.N.dot(check_.direction());
      // A plane holding the line to rounding bounds nothing along it (its k / (N·s) is
      // noise); the line is in its half-space.
      if (check_.lineInPlane(m)) return;
      // Only planes that support M (a face declared by rounding cuts M).
      if (!check_.facetSets(m)) return;
      // Each plane pushed out by the rounding slack: a plane the line meets at a grazing
      // angle, whose k / (N·s) is rounding over a tiny N·s, then bounds nothing near M
      // instead of cutting the chord at a point far off M; the others move by the slack
      // over their sine. The chord's ends are then within the slack of M's boundary.
      const T k = m.k + check_.slack() * FacetCheck<T>::norm(m.N);
      if (ns == T(0)) {
        if (k < T(0)) outside = true;
        return;
      }
      const T t = k / ns;
      if (ns > T(0) && (!hi.valid() || t < thi)) thi = t, hi = m;
      if (ns < T(0) && (!lo.valid() || t > tlo)) tlo = t, lo = m;
    });
    if (outside || !lo.valid() || !hi.valid()) return false;
    // Empty even with every plane pushed out by the slack: the line misses M.
    return !(tlo > thi);
  }

  /// A slack no distance between points of M exceeds (every point of M lies within the
  /// scene size of the origin in P's frame: a slack of twice that accepts any point): the
  /// nearest point is wanted, however far.
  T anyDistance() const { return T(4) * F_.sceneSize(); }

  /// Witnesses on the facet of M in face m's plane nearest the line (chord()'s faces,
  /// which the line may miss by rounding).
  void nearestWitnesses(const MFace<T>& m) {
    if (check_.facetHit(m)) return;
    // facetHit left the facet's support sets in setP / setQ: the point of their
    // difference's hull nearest the line (any slack above the scene's size accepts it).
    check_.hitSets(anyDistance());
  }

  /// Witnesses for a contact point X (frame of P) that the chord's face does not reach:
  /// of the facets of all faces of M that support their normals (as chord() takes them),
  /// the point nearest X, each facet's located in its own plane. Replaces the witnesses,
  /// and leaves that facet's support sets in setP / setQ, only if it is nearer X than
  /// `best` (updated; lengths in the units of slackUnits, so that a scene of 1e200 does
  /// not overflow them). A needle (a tetrahedron with an edge of 1e-10) loses the tiny
  /// facets of M around its short edge to rounding; the line met M there, the chord's
  /// plane bounded it right (to 1e-11), but that plane's own facet ended 1.4 from it.
  bool nearestFacetPoint(const Vec3<T>& X, T& best) {
    MFace<T> nearest;
    Vec3<T> bestP = check_.witnessP(), bestQ = check_.witnessQ();
    search_.forEachFace([&](const MFace<T>& m) {
      const T n = FacetCheck<T>::norm(m.N);
      if (!(n > T(0)) || !(check_.slackUnits(T(absValue(T(m.N.dot(X) - m.k)) / n)) < best)) return;  // its plane is farther
      if (!check_.facetSets(m) || !check_.witnessesAt(X, m.N, anyDistance())) return;
      const T dist = FacetCheck<T>::norm(check_.inUnits(Vec3<T>(check_.witnessP() - check_.witnessQ() - X)));
      if (dist < best) best = dist, nearest = m, bestP = check_.witnessP(), bestQ = check_.witnessQ();
    });
    check_.setWitnessPair(bestP, bestQ);
    if (!nearest.valid()) return false;
    check_.facetSets(nearest);
    return true;
  }

  /// Grazing (case 2): the plane w·x = 0 supports M and holds the line. The line meets
  /// M in [tlo, thi] (parameters of s) iff it meets the facet F_P(w) − F_Q(w).
  bool grazing(const Vec3<T>& w, T& tlo, T& thi, int& vp, int& vq) {
    const ConvexPolyhedron<T>& P = F_.P();
    const ConvexPolyhedron<T>& Q = F_.Q();
    vp = F_.supportP(w, cache_.vertexP);
    vq = F_.supportMinusQ(w, cache_.vertexQ);
    T eps = T(0);
    if constexpr (!ScalarTraits<T>::isExact) eps = check_.slack() * w.norm();
    auto valueP = [&](int v) { return T(w.dot(P.vertex(v))); };
    auto valueQ = [&](int v) { return T(-w.dot(F_.q(v))); };
    if (supportSet(P, vp, valueP, eps, cache_.marksP, cache_.setP)) toFaceOrder(P, valueP, eps, cache_.setP);
    if (supportSet(Q, vq, valueQ, eps, cache_.marksQ, cache_.setQ)) toFaceOrder(Q, valueQ, eps, cache_.setQ);
    // In the plane: coordinate a along s, b along e = w × s; the line is b == 0. In 2^e
    // units (see u1_): the crossings below multiply two coordinates. The facet's polygon
    // (its vertices in cyclic order) meets the line where its edges cross b == 0.
    const Vec3<T>& s = check_.direction();
    check_.facetPolygon(check_.inUnits(s), check_.inUnits(Vec3<T>(w.cross(s))), Vec3<T>::Zero());
    // A vertex y of the facet lies on the line iff y × s = 0: decided exactly on the
    // numbers given (the three 2-D orientations of 0, s, y), not by its b, which carries
    // the rounding of w. Integer shapes touching at one point (y = s exactly) had b =
    // 2e-16, no crossing, and the contact was missed (NoContact for Separated at 1).
    auto& ab = cache_.points2;
    const int nq = static_cast<int>(cache_.setQ.size());
    for (auto& vertex : ab) {
      const Vec3<T> y = P.vertex(cache_.setP[vertex.second / nq]) - F_.q(cache_.setQ[vertex.second % nq]);
      if (onLine(y, s)) vertex.first.second = T(0);
    }
    bool any = false;
    T amin = T(0), amax = T(0);
    auto take = [&](const T& a) {
      if (!any || a < amin) amin = a;
      if (!any || a > amax) amax = a;
      any = true;
    };
    for (std::size_t i = 0; i < ab.size(); ++i) {
      const auto& pi = ab[i].first;
      const auto& pj = ab[(i + 1) % ab.size()].first;
      if (pi.second == T(0)) take(pi.first);
      if ((pi.second < T(0) && pj.second > T(0)) || (pi.second > T(0) && pj.second < T(0)))
        take((pi.first * pj.second - pj.first * pi.second) / (pj.second - pi.second));
    }
    if (!any) return false;
    const T ss = s.squaredNorm();
    tlo = amin / ss;
    thi = amax / ss;
    if constexpr (!ScalarTraits<T>::isExact) {
      tlo = check_.fromUnits(tlo);
      thi = check_.fromUnits(thi);
    }
    return true;
  }

 private:
  /// Is y on the line {t s}, exactly (y × s = 0: its three components' signs)?
  static bool onLine(const Vec3<T>& y, const Vec3<T>& s) {
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      if (orient2d<T>(T(0), T(0), s[i], s[j], y[i], y[j]) != 0) return false;
    }
    return true;
  }

  ExitFaceSearch<T>& search_;
  FacetCheck<T>& check_;
  MddCache<T>& cache_;
  const PairFrame<T>& F_;
};

}  // namespace detail
}  // namespace mink
