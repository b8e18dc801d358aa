// mink/mdd/detail/facet_check.hpp — the facet check of mdd(): is a face of M = P ⊕ −Q
// where the line {t s} enters or leaves M, and where on it are the contact points?
//
// A face of M found by a search (or kept from the last query) is a supporting plane of M
// by construction; the line leaves M through it iff the line crosses the face's *facet*,
// the Minkowski difference of the support sets of P and −Q along its normal, which also
// covers spans of coplanar faces (Choi et al., section VI-C). The facet is built in its
// 2-D coordinates as a merge of two convex polygons (detail/difference_polygon.hpp), the
// line's crossing located in it (detail/contact_set.hpp), and its barycentric weights give
// the witnesses on P and Q.
//
// Inexact T: the checks carry the rounding slack of the scene (slack(), a length);
// tolerance() is the caller's touch tolerance. For a scene far from unit order the 2-D
// coordinates are taken in exact 2^-e units (PairFrame::unitScaleExponent; inUnits,
// slackUnits), so that their products neither underflow nor overflow.
#pragma once

#include <cmath>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/mdd/detail/contact_set.hpp"
#include "mink/mdd/detail/pair_frame.hpp"

namespace mink {
namespace detail {

/// The automatic touch tolerance of a pair, a length in P's frame: the rounding slack of
/// M's faces, defaults::kMddTouchToleranceFactor · eps · the scene's size (0 for exact T).
template <class T>
T automaticTouchTolerance(const PairFrame<T>& F) {
  if constexpr (ScalarTraits<T>::isExact) {
    return T(0);
  } else {
    return T(defaults::kMddTouchToleranceFactor) * ScalarTraits<T>::epsilon() * F.sceneSize();
  }
}

/// What counts as touching for a query: MddOptions::touchTolerance where the caller set
/// it (non-negative), else the automatic one; 0 for exact T.
template <class T>
T touchToleranceOf(const PairFrame<T>& F, const MddOptions<T>& opt) {
  if constexpr (ScalarTraits<T>::isExact) {
    return T(0);
  } else {
    return opt.touchTolerance >= T(0) ? opt.touchTolerance : automaticTouchTolerance(F);
  }
}

template <class T>
class FacetCheck {
 public:
  /// For the line {t s} (frame of P) in the pair frame F; `cache` holds the work buffers.
  FacetCheck(const PairFrame<T>& F, const Vec3<T>& s, MddCache<T>& cache, const MddOptions<T>& opt)
      : F_(F), s_(s), cache_(cache) {
    if constexpr (ScalarTraits<T>::isExact) {
      tol_ = numTol_ = T(0);
    } else {
      // numTol_: the rounding slack of the facet checks, always automatic; tol_: what
      // counts as touching, the caller's choice (a large touchTolerance must not make
      // the facet checks accept faces the line misses).
      numTol_ = automaticTouchTolerance(F);
      tol_ = touchToleranceOf(F, opt);
      scene_ = F.sceneSize();
      sLength_ = s.norm();
    }
    const auto b = orthogonalBasis(s);
    u1_ = b.first;
    u2_ = b.second;
    if constexpr (!ScalarTraits<T>::isExact) {
      // Unit vectors, so that the facet check's slack is a length; for a scene far from
      // unit order, 2^-e times unit vectors (PairFrame::unitScaleExponent): the facets'
      // 2-D points then have coordinates of unit order (exactly scaled), whose products
      // in the contact set's tests neither underflow nor overflow, and the slacks are
      // scaled with them (slackUnits).
      u1_.normalize();
      u2_.normalize();
      unitExp_ = F.unitScaleExponent();
      u1_ = inUnits(u1_);
      u2_ = inUnits(u2_);
    }
  }

  const Vec3<T>& direction() const { return s_; }

  /// The acceptance of a search's answer: the line crosses the facet in m's plane
  /// (facetHit), and, where it meets that plane at a grazing angle (below
  /// defaults::kMddCertificateSine), the contact point k / (N·s) · s lies on that facet
  /// too (located in the facet's own plane; the witnesses are then there). A centre of
  /// duality within rounding of such a plane (a 1e28 scene whose chord is 5 long) made
  /// it win the search with a k / (N·s) of 1e21, off M by as much.
  bool exitHit(const MFace<T>& m) {
    if (!facetHit(m)) return false;
    if (wellConditioned(m)) return true;
    return witnessesAt(Vec3<T>((m.k / m.N.dot(s_)) * s_), m.N);
  }

  /// May face m be accepted on its certificate alone (faceHit, no search)? Inexact T:
  /// only if the line meets its plane at a sine of at least
  /// defaults::kMddCertificateSine. Nearer grazing, k / (N·s) carries the rounding of the
  /// scene times 1 / sine, and the certificate itself cannot tell a crossing from a line
  /// that passes within rounding of an edge of the face (a 1e59 shape against one of
  /// size 1: the face at a sine of 7e-12 gave t = 1e54 where a face beside it, crossed
  /// at a large angle, ends the chord at 1.7). The searches then decide.
  bool wellConditioned(const MFace<T>& m) const {
    if constexpr (ScalarTraits<T>::isExact) {
      (void)m;
      return true;
    } else {
      return absValue(m.N.dot(s_)) >= T(defaults::kMddCertificateSine) * m.N.norm() * sLength_;
    }
  }

  /// Inexact T: does the line {t s} run within the rounding slack of face m's plane over
  /// the whole scene (every t with |t s| up to the scene size, which holds M's chord)?
  /// Then k / (N·s) is a ratio of two rounding errors, not a place on the line (integer
  /// boxes touching along a face of M once Q is turned by a 3-4-5 rotation: the EE face
  /// there gave t = -0.33 where the exact chord is [-0.2, 0]), and the line meets M only
  /// in that plane's facet: case 2 of section IV-A, answered by grazing(). Exact T:
  /// never (from a strictly interior c the exit face has N·σ > 0 exactly).
  bool lineInPlane(const MFace<T>& m) const {
    if constexpr (ScalarTraits<T>::isExact) {
      (void)m;
      return false;
    } else {
      return absValue(m.k) + scene_ * absValue(m.N.dot(s_)) / sLength_ <= numTol_ * m.N.norm();
    }
  }

  /// May face m be accepted without a search? It is a supporting plane of M by
  /// construction; it must be met at a well-conditioned angle and the line must cross
  /// its own polygon (faceHit) or, failing that, the hull of its facet's support sets
  /// (the vertices whose N·x ties the face's exactly in T) with no slack: a span (the cap of an n-gon prism against another, a box face) is
  /// crossed away from the one face that names it, and without this every such query
  /// ran the searches over the n faces around the cap. Fills the witnesses.
  bool certifies(const MFace<T>& m) {
    if (!wellConditioned(m)) return false;
    return faceHit(m) || (facetSets(m, T(0)) && hitSets(T(0)));
  }

  /// Does the line {t s} cross the face m itself (its own features, no tolerance: FV is
  /// f_p − v_q, VF is v_p − f_q, EE is e_p − e_q)? A stricter test than facetHit (the
  /// face is part of the facet), used where a face is accepted without a search, so that
  /// no tolerance can let a neighbouring face's plane answer. Fills the witnesses.
  bool faceHit(const MFace<T>& m) {
    const ConvexPolyhedron<T>& P = F_.P();
    const ConvexPolyhedron<T>& Q = F_.Q();
    edgePairSolved_ = false;  // also where this face fails: no earlier face's flag survives
    cache_.setP.clear();
    cache_.setQ.clear();
    cache_.points2.clear();
    // The face's polygon in cyclic order; ids index setP × setQ as in hitSets (i·|setQ| + j).
    // Each vertex of P and of Q placed once (y = p − q, as formed from the pair before).
    auto add = [&](const Vec3<T>& y, int id) { cache_.points2.push_back({{y.dot(u1_), y.dot(u2_)}, id}); };
    Vec3<T> placedQ[2];                // setQ's vertices in P's frame, for setWitnesses (FV, EE)
    const Vec3<T>* placed = nullptr;
    switch (m.type) {
      case MddFaceType::FV: {
        for (int v : P.faceVertices(m.a)) cache_.setP.push_back(v);
        cache_.setQ.push_back(m.b);
        placedQ[0] = F_.q(m.b);
        placed = placedQ;
        for (int i = 0; i < static_cast<int>(cache_.setP.size()); ++i) add(P.vertex(cache_.setP[i]) - placedQ[0], i);
        break;
      }
      case MddFaceType::VF: {
        cache_.setP.push_back(m.a);
        for (int v : Q.faceVertices(m.b)) cache_.setQ.push_back(v);
        const Vec3<T>& p = P.vertex(m.a);
        for (int j = 0; j < static_cast<int>(cache_.setQ.size()); ++j) add(p - F_.q(cache_.setQ[j]), j);
        break;
      }
      case MddFaceType::EE: {
        const auto ep = P.edgeVertices(m.a), eq = Q.edgeVertices(m.b);
        cache_.setP.push_back(ep.first);
        cache_.setP.push_back(ep.second);
        cache_.setQ.push_back(eq.first);
        cache_.setQ.push_back(eq.second);
        const Vec3<T>& p0 = P.vertex(ep.first);
        const Vec3<T>& p1 = P.vertex(ep.second);
        placedQ[0] = F_.q(eq.first);
        placedQ[1] = F_.q(eq.second);
        placed = placedQ;
        const Vec3<T>&q0 = placedQ[0], &q1 = placedQ[1];
        add(p0 - q0, 0);  // (0, 0)
        add(p1 - q0, 2);  // (1, 0)
        add(p1 - q1, 3);  // (1, 1)
        add(p0 - q1, 1);  // (0, 1)
        if (insideParallelogram(p0, p1, q0, q1)) return true;
        break;
      }
      default:
        return false;
    }
    OriginLocation<T> loc;
    if (!locateOriginConvex(cache_.points2, loc)) return false;
    setWitnesses(loc, placed);
    return true;
  }

  /// EE face e_p − e_q (ends p0 p1 of P's edge, q0 q1 of Q's, P's frame), its corners in
  /// points2 as faceHit puts them: true when the origin is strictly inside that
  /// parallelogram by the exact signs of its four sides (the common case, where no fan
  /// triangle needs locating), the witnesses then p0 + λ (p1 − p0) and q0 + μ (q1 − q0)
  /// from the 2-D system (clamped to [0, 1]; mdd() solves the same in 3-D for an EE
  /// answer). False otherwise: faceHit's general location decides.
  bool insideParallelogram(const Vec3<T>& p0, const Vec3<T>& p1, const Vec3<T>& q0, const Vec3<T>& q1) {
    const auto& c = cache_.points2;
    const std::pair<T, T> o(T(0), T(0));
    const int s0 = orient2(c[0].first, c[1].first, o);
    if (s0 == 0 || orient2(c[1].first, c[2].first, o) != s0 || orient2(c[2].first, c[3].first, o) != s0 ||
        orient2(c[3].first, c[0].first, o) != s0)
      return false;
    // c0 + λ U + μ V = 0 with U = c1 − c0 (P's edge), V = c3 − c0 (Q's, reversed).
    const std::pair<T, T> A = c[0].first, U = sub2(c[1].first, A), V = sub2(c[3].first, A);
    const T den = cross2(U, V);
    if (!(den != T(0))) return false;
    const T lambda = std::min(T(1), std::max(T(0), T(cross2(V, A) / den)));
    const T mu = std::min(T(1), std::max(T(0), T(cross2(A, U) / den)));
    wP_ = p0 + lambda * (p1 - p0);
    wQ_ = q0 + mu * (q1 - q0);
    edgePairSolved_ = true;
    return true;
  }

  /// Does the line {t s} cross the facet of M in face m's plane? Fills the witnesses
  /// (frame of P) when it does.
  bool facetHit(const MFace<T>& m) { return facetSets(m) && hitSets(numTol_); }

  /// The support sets of face m's normal N in P and in −Q (setP, setQ), from m's own
  /// vertices; false if those do not support N to within the rounding slack. A face of M
  /// declared by rounding (an EE pair of near-parallel edges of two sheets 1e-10 thick)
  /// is no supporting plane: its support sets were every vertex above its own, whose
  /// differences hold the line wherever it crosses M, and its plane, 1.04 off M, was
  /// accepted (and cut the chord of M to nothing).
  bool facetSets(const MFace<T>& m) {
    T eps = T(0);
    if constexpr (!ScalarTraits<T>::isExact) eps = numTol_ * m.N.norm();
    return facetSets(m, eps);
  }
  /// The same with the support sets' slack `eps` (units of N·x).
  bool facetSets(const MFace<T>& m, const T& eps) {
    const ConvexPolyhedron<T>& P = F_.P();
    const ConvexPolyhedron<T>& Q = F_.Q();
    int vp = 0, vq = 0;
    switch (m.type) {
      case MddFaceType::FV:
        vp = P.faceVertices(m.a)[0];
        vq = m.b;
        break;
      case MddFaceType::VF:
        vp = m.a;
        vq = Q.faceVertices(m.b)[0];
        break;
      case MddFaceType::EE:
        vp = P.edgeVertices(m.a).first;
        vq = Q.edgeVertices(m.b).first;
        break;
      default:
        return false;
    }
    const Vec3<T>& N = m.N;
    auto valueP = [&](int v) { return T(N.dot(P.vertex(v))); };
    auto valueQ = [&](int v) { return T(-N.dot(F_.q(v))); };
    const bool okP = supportSet(P, vp, valueP, eps, cache_.marksP, cache_.setP);
    const bool okQ = supportSet(Q, vq, valueQ, eps, cache_.marksQ, cache_.setQ);
    if (okP && okQ) {
      toFaceOrder(P, valueP, eps, cache_.setP);
      toFaceOrder(Q, valueQ, eps, cache_.setQ);
    }
    return okP && okQ;
  }

  /// points2 := the vertices of the hull of setP − setQ − Y in the coordinates
  /// (y·a, y·b), in cyclic order, with ids i·|setQ| + j (setWitnesses reads them): only
  /// the at most |setP| + |setQ| pairs that DifferencePolygon names, each difference
  /// then formed from the vertices themselves. The two sets enter relative to their first
  /// points, so that coordinates far from the origin do not round their shapes.
  void facetPolygon(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& Y) {
    const ConvexPolyhedron<T>& P = F_.P();
    DifferencePolygon<T>& D = cache_.facet;
    D.a.clear();
    D.b.clear();
    const Vec3<T> p0 = P.vertex(cache_.setP[0]), q0 = F_.q(cache_.setQ[0]);
    for (int v : cache_.setP) {
      const Vec3<T> y = P.vertex(v) - p0;
      D.a.push_back({y.dot(a), y.dot(b)});
    }
    for (int v : cache_.setQ) {
      const Vec3<T> y = F_.q(v) - q0;
      D.b.push_back({y.dot(a), y.dot(b)});
    }
    D.compute();
    cache_.points2.clear();
    const int nq = static_cast<int>(cache_.setQ.size());
    for (const auto& ij : D.pairs) {
      const Vec3<T> y = P.vertex(cache_.setP[ij.first]) - F_.q(cache_.setQ[ij.second]) - Y;
      cache_.points2.push_back({{y.dot(a), y.dot(b)}, ij.first * nq + ij.second});
    }
  }

  /// Does the line cross (within `slack`) the hull of setP − setQ? Fills the witnesses.
  bool hitSets(const T& slack) {
    edgePairSolved_ = false;
    facetPolygon(u1_, u2_, Vec3<T>::Zero());
    OriginLocation<T> loc;
    if (!locateOrigin2(cache_.points2, cache_.hull2, loc, slackUnits(slack))) return false;
    setWitnesses(loc);
    return true;
  }

  /// A vector in the units of the 2-D points (see u1_, u2_): 2^-e times it (exact).
  Vec3<T> inUnits(const Vec3<T>& v) const { return unitExp_ != 0 ? timesPow2(v, -unitExp_) : v; }
  /// A length in the units of the 2-D points (see u1_, u2_).
  T slackUnits(const T& length) const {
    if constexpr (!ScalarTraits<T>::isExact) {
      using std::ldexp;
      if (unitExp_ != 0) return ldexp(length, -unitExp_);
    }
    return length;
  }

  /// Witnesses at the point Y (frame of P) of the facet whose support sets the last facet
  /// check left in setP / setQ: Y located in the hull of setP − setQ within the facet's
  /// own plane (a basis orthogonal to its normal N), not by projection along s, so that
  /// a facet met at a grazing angle is no sliver here. False (witnesses unchanged) if Y
  /// lies farther than the facet checks' slack from that hull.
  bool witnessesAt(const Vec3<T>& Y, const Vec3<T>& N) { return witnessesAt(Y, N, numTol_); }
  /// As above with the given slack (a length; any slack above the scene's size takes the
  /// facet's point nearest Y in its plane).
  bool witnessesAt(const Vec3<T>& Y, const Vec3<T>& N, const T& slack) {
    auto basis = orthogonalBasis(N);
    Vec3<T> a = basis.first, b = basis.second;
    if constexpr (!ScalarTraits<T>::isExact) {
      a.normalize();
      b.normalize();
      a = inUnits(a);
      b = inUnits(b);
    }
    facetPolygon(a, b, Y);
    OriginLocation<T> loc;
    if (!locateOrigin2(cache_.points2, cache_.hull2, loc, slackUnits(slack))) return false;
    setWitnesses(loc);
    return true;
  }

  /// The rounding slack of the facet checks (length; 0 for exact T).
  const T& slack() const { return numTol_; }

  /// placedQ: setQ's vertices in P's frame where the caller has them (else computed).
  void setWitnesses(const OriginLocation<T>& loc, const Vec3<T>* placedQ = nullptr) {
    const ConvexPolyhedron<T>& P = F_.P();
    wP_ = Vec3<T>::Zero();
    wQ_ = Vec3<T>::Zero();
    edgePairSolved_ = false;
    const int nq = static_cast<int>(cache_.setQ.size());
    for (int i = 0; i < loc.count; ++i) {
      // ids are i·|setQ| + j >= 0; no division for the common sizes (FV 1, EE 2).
      const int ip = nq == 1 ? loc.id[i] : nq == 2 ? loc.id[i] >> 1 : loc.id[i] / nq;
      const int iq = nq == 1 ? 0 : nq == 2 ? loc.id[i] & 1 : loc.id[i] % nq;
      wP_ += loc.weight[i] * P.vertex(cache_.setP[ip]);
      wQ_ += loc.weight[i] * (placedQ ? placedQ[iq] : F_.q(cache_.setQ[iq]));
    }
  }

  const Vec3<T>& witnessP() const { return wP_; }
  const Vec3<T>& witnessQ() const { return wQ_; }
  /// Do the witnesses come from an EE face's own two edge parameters (faceHit's
  /// insideParallelogram), rather than from fan-triangle weights or a support-set hull?
  bool edgePairSolved() const { return edgePairSolved_; }
  const T& tolerance() const { return tol_; }

  /// A length given in 2^-e units (slackUnits) back in the scene's units.
  T fromUnits(const T& length) const {
    if constexpr (!ScalarTraits<T>::isExact) {
      using std::ldexp;
      if (unitExp_ != 0) return ldexp(length, unitExp_);
    }
    return length;
  }
  /// Replaces the witnesses (frame of P).
  void setWitnessPair(const Vec3<T>& wP, const Vec3<T>& wQ) {
    wP_ = wP;
    wQ_ = wQ;
    edgePairSolved_ = false;
  }

  /// |n| for slack computations; 0 for exact T (whose slack numTol_ is 0).
  static T norm(const Vec3<T>& n) {
    if constexpr (ScalarTraits<T>::isExact) {
      (void)n;
      return T(0);
    } else {
      return n.norm();
    }
  }

 private:
  const PairFrame<T>& F_;
  Vec3<T> s_;
  MddCache<T>& cache_;
  T tol_, numTol_;
  T scene_ = T(0), sLength_ = T(1);  // inexact T: the scene size (as numTol_'s) and |s|
  Vec3<T> u1_, u2_;
  int unitExp_ = 0;  // inexact T: PairFrame::unitScaleExponent (u1_, u2_ are 2^-e units)
  Vec3<T> wP_ = Vec3<T>::Zero(), wQ_ = Vec3<T>::Zero();
  bool edgePairSolved_ = false;  // see edgePairSolved()
};

}  // namespace detail
}  // namespace mink
