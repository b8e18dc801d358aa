// mink/mdd/detail/pair_frame.hpp — a pair (P, Q) seen in P's frame, and the faces of
// M = P ⊕ −Q built on demand from it (MDD paper section II-C).
//
// Everything is computed in P's own frame: Q's vertices and normals are mapped by the
// relative pose (R, t) when needed, so no shape is copied or rebuilt per query. A face of
// M is a plane N·x = k with outward N (never normalised here) and k = h_P(N) + h_{−Q}(N):
//   FV (f_p, v_q): N = n(f_p),            k = offset(f_p) − N·q(v_q),  v_q = argmin N·q
//   VF (v_p, f_q): N = −R n(f_q),         k = N·p(v_p) + R n(f_q)·q(f_q), v_p = argmax N·p
//   EE (e_p, e_q): N = ±(e_p × e_q), the sign that points where the arcs of G(P) and
//                  G(−Q) cross, k = N·(p_0 − q_0).
// For the search with centre of duality c (strictly inside M) and direction σ, the dual
// point of a face is N / (k − N·c); its height along σ, (N·σ)/(k − N·c), is the linear
// function the search maximises; comparisons cross-multiply (denominators are > 0).
#pragma once

#include <cmath>
#include <limits>
#include <utility>

#include "mink/core/defaults.hpp"
#include "mink/core/difference_orientation.hpp"
#include "mink/gauss_map/arc_intersection.hpp"
#include "mink/hierarchy/dk_hierarchy.hpp"
#include "mink/mdd/mdd_types.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {
namespace detail {

template <class T>
struct MFace {
  MddFaceType type = MddFaceType::None;
  int a = -1;  // FV: face of P; VF: vertex of P; EE: edge of P
  int b = -1;  // FV: vertex of Q; VF: face of Q; EE: edge of Q
  Vec3<T> N = Vec3<T>::Zero();
  T k = T(0);
  bool valid() const { return type != MddFaceType::None; }
};

template <class T>
class PairFrame {
 public:
  /// Lengths within 2^±kUnitBand are "of unit order": products of three of them neither
  /// overflow nor underflow (a sixteenth of the exponent range of T). Inexact T only.
  static constexpr int kUnitBand = std::numeric_limits<T>::max_exponent / 16;

  PairFrame(const ConvexPolyhedron<T>& P, const ConvexPolyhedron<T>& Q, const Mat3<T>& R,
            const Vec3<T>& t, bool useHierarchy)
      : P_(P), Q_(Q), R_(R), t_(t), useHierarchy_(useHierarchy) {
    // Normals map by the cofactor matrix det(R) R^{-T}: equal to R for a rotation, and
    // still exactly perpendicular to the mapped faces when R is a rotation only up to
    // rounding, so planes and vertices stay consistent (det(R) > 0 is checked).
    C_.col(0) = R.col(1).cross(R.col(2));
    C_.col(1) = R.col(2).cross(R.col(0));
    C_.col(2) = R.col(0).cross(R.col(1));
    if constexpr (!ScalarTraits<T>::isExact) {
      // The arc test's filter (ee()): a volume det[x y z] of three normals, evaluated as
      // x · (y × z), is off by at most γ5 · Σ|x_i| (|y_j z_k| + |y_k z_j|) <= γ5 √2 |x||y||z|
      // (Cauchy–Schwarz), plus 4 (|x|_1 + 2) min_normal from products below the normal
      // range (arc_intersection.hpp, filteredSign). P's normals are unit to rounding; Q's
      // are C n with |C n| <= |C|_F |n|. 12 u > γ5 √2 with room for the rounding of the
      // norms (u the unit roundoff).
      using std::sqrt;
      const T u = std::numeric_limits<T>::epsilon() / T(2);
      const T nP = T(1) + T(16) * u;
      const T nQ = sqrt(C_.squaredNorm()) * (T(1) + T(16) * u);
      arcBoundPPQ_ = T(12) * u * nP * nP * nQ + detail::denormalErrorBound(T(32));
      arcBoundPQQ_ = T(12) * u * nP * nQ * nQ + detail::denormalErrorBound(T(32));
      // An edge plane (edgePlaneP / edgePlaneQ) is an edge scaled to |e|_max in [1, 2), so
      // |e| < 3.5; its volumes are dot products x · e, off by at most γ3 |x||e| < 4 u · 3.5 |x|.
      edgeBoundP_ = T(14) * u * nQ + detail::denormalErrorBound(T(32));  // c · e_P, d · e_P
      edgeBoundQ_ = T(14) * u * nP + detail::denormalErrorBound(T(32));  // a · e_Q, b · e_Q
      unitLo_ = detail::timesPowerOfTwo(T(1), -kUnitBand);
      unitHi_ = detail::timesPowerOfTwo(T(1), kUnitBand);
      scene_ = P.extent() + Q.extent() + t.template lpNorm<1>();
      if (scene_ > T(0) && ScalarTraits<T>::isFinite(scene_)) {
        using std::ilogb;
        const int e = ilogb(scene_);
        unitExp_ = (e >= -kUnitBand && e <= kUnitBand) ? 0 : e;
      }
    }
  }

  const ConvexPolyhedron<T>& P() const { return P_; }
  const ConvexPolyhedron<T>& Q() const { return Q_; }
  const Mat3<T>& R() const { return R_; }
  const Vec3<T>& t() const { return t_; }

  Vec3<T> q(int j) const { return R_ * Q_.vertex(j) + t_; }
  /// Outward normal of Q's face f in P's frame.
  Vec3<T> qNormal(int f) const { return C_ * Q_.faceNormal(f); }

  /// argmax d·p over P's vertices (hint < 0: cold query, hierarchy if worth it).
  int supportP(const Vec3<T>& d, int hint) const {
    if (hint >= 0 || !useHierarchy_) return P_.support(d, hint < 0 ? 0 : hint);
    return extremeVertex(P_, d);
  }
  /// argmin d·q over Q's vertices (in P's frame), i.e. the support of −Q along d.
  int supportMinusQ(const Vec3<T>& d, int hint) const {
    const Vec3<T> dl = -(R_.transpose() * d);
    if (hint >= 0 || !useHierarchy_) return Q_.support(dl, hint < 0 ? 0 : hint);
    return extremeVertex(Q_, dl);
  }
  /// As supportP / supportMinusQ, for a direction far from the hint's: the hierarchy
  /// when the shape has one (O(log n) whatever the distance), else a hill-climb from the
  /// nearest seed direction's vertex (support_seeds.hpp); a plain hill-climb from the
  /// hint when hierarchies are switched off.
  int supportPFar(const Vec3<T>& d, int hint) const {
    if (!useHierarchy_) return P_.support(d, hint < 0 ? 0 : hint);
    return extremeVertex(P_, d);
  }
  /// Does either shape have a hierarchy that the queries may use?
  bool hasHierarchy() const { return useHierarchy_ && (hierarchyOf(P_) || hierarchyOf(Q_)); }
  /// Do both shapes have a hierarchy, and small faces and vertex degrees (finely faceted,
  /// like a tessellated smooth surface)? Where the exit portal takes secant steps
  /// (defaults::kSecantMaxFaceVertices, kSecantMaxDegree).
  bool finelyFacetedLarge() const {
    if (!useHierarchy_) return false;
    auto fine = [](const DKHierarchy<T>* H) {
      return H && H->shapeMaxFaceVertices() <= defaults::kSecantMaxFaceVertices &&
             H->shapeMaxDegree() <= defaults::kSecantMaxDegree;
    };
    return fine(hierarchyOf(P_)) && fine(hierarchyOf(Q_));
  }
  /// Inexact T: for a scene far from unit order (size beyond 2^±kUnitBand: 2^±64 in
  /// double, 2^±8 in float, a sixteenth of the exponent range), the exponent e of
  /// its size, so that coordinates of M taken in units of 2^e are of unit order; else 0.
  /// Tests that multiply two or three coordinates of M (the 2-D and 3-D portals) work in
  /// those units: a scene of 1e-224 gave products of 1e-448, zero in double, and every
  /// such test decided by underflow (mdd said NoContact for an overlap of 16% of it).
  int unitScaleExponent() const { return unitExp_; }
  /// The scene's size, P.extent() + Q.extent() + |t|_1 (the rounding slacks scale with
  /// it): made once per pair; for exact T (no slacks) computed when asked.
  T sceneSize() const {
    if constexpr (ScalarTraits<T>::isExact) {
      return P_.extent() + Q_.extent() + t_.template lpNorm<1>();
    } else {
      return scene_;
    }
  }
  /// For a direction near the hint's: on a shape with a hierarchy, a hill-climb from the
  /// hint capped at defaults::kHierarchyClimbMoves moves, then the descent (a long climb
  /// on a fine mesh misses the cache at every step; the hierarchy's levels are compact);
  /// else a hill-climb from the hint.
  int supportPRefine(const Vec3<T>& d, int hint) const {
    if (useHierarchy_)
      if (const DKHierarchy<T>* H = hierarchyOf(P_)) return H->supportFrom(d, hint, defaults::kHierarchyClimbMoves);
    return P_.support(d, hint < 0 ? 0 : hint);
  }
  int supportMinusQRefine(const Vec3<T>& d, int hint) const {
    const Vec3<T> dl = -(R_.transpose() * d);
    if (useHierarchy_)
      if (const DKHierarchy<T>* H = hierarchyOf(Q_)) return H->supportFrom(dl, hint, defaults::kHierarchyClimbMoves);
    return Q_.support(dl, hint < 0 ? 0 : hint);
  }

  int supportMinusQFar(const Vec3<T>& d, int hint) const {
    const Vec3<T> dl = -(R_.transpose() * d);
    if (!useHierarchy_) return Q_.support(dl, hint < 0 ? 0 : hint);
    return extremeVertex(Q_, dl);
  }

  MFace<T> fv(int fp, int& hintQ) const {
    MFace<T> m;
    m.type = MddFaceType::FV;
    m.a = fp;
    m.N = P_.faceNormal(fp);
    m.b = hintQ = supportMinusQ(m.N, hintQ);
    m.k = P_.faceOffset(fp) - m.N.dot(q(m.b));
    return m;
  }

  /// Inexact T: n = b × a for the unit normals a, b of P's edge ep; where it is shorter
  /// than kMddSharpEdgeCross, n becomes the edge itself, scaled to unit order and oriented
  /// as n (true returned). The plane of a sharp edge's arc (normals nearly opposite) or a
  /// flat edge's (nearly equal) through two rounded normals is tilted by up to
  /// 2 eps / |n| (4e-6 rad for a sheet 5e-11 thick: the arc of an edge of Q passed 1e-11
  /// from one of its normals, the arc test was then exact on normals that misplace the arc,
  /// and M lost the facet the line left by); the edge is its exact normal. The orientation
  /// is that of n, whose length edgesResolved() keeps above 64 eps, so that its sign
  /// against the edge is never in doubt. The volumes' signs and the crossing's direction
  /// do not depend on the planes' lengths.
  bool edgePlaneP(Vec3<T>& n, int ep) const {
    if constexpr (!ScalarTraits<T>::isExact) {
      if (n.squaredNorm() < T(defaults::kMddSharpEdgeCross) * T(defaults::kMddSharpEdgeCross)) return edgeAsPlaneP(n, ep);
    }
    (void)n, (void)ep;
    return false;
  }
  /// As edgePlaneP, for Q's edge eq (n = d × c of its normals in P's frame).
  bool edgePlaneQ(Vec3<T>& n, int eq) const {
    if constexpr (!ScalarTraits<T>::isExact) {
      if (n.squaredNorm() < T(defaults::kMddSharpEdgeCross) * T(defaults::kMddSharpEdgeCross)) return edgeAsPlaneQ(n, eq);
    }
    (void)n, (void)eq;
    return false;
  }
  bool edgeAsPlaneP(Vec3<T>& n, int ep) const {
    const auto v = P_.edgeVertices(ep);
    return orientAlong(n, unitOrder(Vec3<T>(P_.vertex(v.second) - P_.vertex(v.first))));
  }
  bool edgeAsPlaneQ(Vec3<T>& n, int eq) const {
    const auto v = Q_.edgeVertices(eq);
    return orientAlong(n, unitOrder(Vec3<T>(R_ * Vec3<T>(Q_.vertex(v.second) - Q_.vertex(v.first)))));
  }
  static bool orientAlong(Vec3<T>& n, const Vec3<T>& e) {
    const T side = e.dot(n);
    if (side == T(0)) return false;
    n = side > T(0) ? e : Vec3<T>(-e);
    return true;
  }

  /// ee()'s four signs where the filter cannot tell, exact (dotSign / det3Sign), packed as
  /// 2 bits each (sign + 1: cba, dba, adc, bdc from the low bits). Out of line and from the
  /// edge ids alone: rare, and large, so that ee()'s common path keeps its registers.
#if defined(__GNUC__)
  __attribute__((noinline, cold))
#endif
  int exactArcSigns(int ep, int eq) const {
    const Vec3<T>& a = P_.faceNormal(P_.edgeFaces(ep).first);
    const Vec3<T>& b = P_.faceNormal(P_.edgeFaces(ep).second);
    const Vec3<T> c = qNormal(Q_.edgeFaces(eq).first), d = qNormal(Q_.edgeFaces(eq).second);
    Vec3<T> nP = b.cross(a), nQ = d.cross(c);
    const bool eP = edgePlaneP(nP, ep), eQ = edgePlaneQ(nQ, eq);
    const ArcVolumes<T> raw{c.dot(nP), d.dot(nP), a.dot(nQ), b.dot(nQ)};
    const T bP = eP ? edgeBoundP_ : arcBoundPPQ_, bQ = eQ ? edgeBoundQ_ : arcBoundPQQ_;
    int s[4] = {detail::sign(raw.cba), detail::sign(raw.dba), detail::sign(raw.adc), detail::sign(raw.bdc)};
    if (!(absValue(raw.cba) > bP)) s[0] = eP ? dotSign(c, nP) : det3Sign(c, b, a);
    if (!(absValue(raw.dba) > bP)) s[1] = eP ? dotSign(d, nP) : det3Sign(d, b, a);
    if (!(absValue(raw.adc) > bQ)) s[2] = eQ ? dotSign(a, nQ) : det3Sign(a, d, c);
    if (!(absValue(raw.bdc) > bQ)) s[3] = eQ ? dotSign(b, nQ) : det3Sign(b, d, c);
    return (s[0] + 1) | ((s[1] + 1) << 2) | ((s[2] + 1) << 4) | ((s[3] + 1) << 6);
  }

  MFace<T> vf(int fq, int& hintP) const {
    MFace<T> m;
    m.type = MddFaceType::VF;
    m.b = fq;
    const Vec3<T> nq = qNormal(fq);
    m.N = -nq;
    m.a = hintP = supportP(m.N, hintP);
    m.k = m.N.dot(P_.vertex(m.a) - q(Q_.faceVertices(fq)[0]));
    return m;
  }

  /// The EE face of edges ep (of P) and eq (of Q) if their arcs on G(P) and G(−Q) cross
  /// properly; otherwise an invalid face. Touching arcs (Degenerate) are skipped: a facet
  /// of M whose support sets are not two crossing edges is an FV or VF face, or a span of
  /// them, which the facet check covers.
  /// The crossing is decided by the exact signs of the four volumes of the given normals
  /// (arc_intersection.hpp): the rounded volumes where they exceed the filter's bound (made
  /// once per pair), det3Sign / dotSign on the same vectors where they do not.
  MFace<T> ee(int ep, int eq) const {
    MFace<T> m;
    const Vec3<T>& a = P_.faceNormal(P_.edgeFaces(ep).first);
    const Vec3<T>& b = P_.faceNormal(P_.edgeFaces(ep).second);
    const Vec3<T> c = qNormal(Q_.edgeFaces(eq).first), d = qNormal(Q_.edgeFaces(eq).second);
    const auto vp = P_.edgeVertices(ep);
    const auto vq = Q_.edgeVertices(eq);
    // The four volumes of arc_intersection.hpp: det[c b a] = c · (b × a) and
    // det[a d c] = a · (d × c), the arcs' great-circle planes taken once each (or the
    // edges themselves: edgePlaneP / edgePlaneQ).
    Vec3<T> nP = b.cross(a);
    const bool eP = edgePlaneP(nP, ep);
    const T cba = c.dot(nP), dba = d.dot(nP);
    // Most pairs end here: c and d certainly on one side of P's arc plane (so are −c and
    // −d), and the arcs are disjoint whatever the other two signs (classifyArcSigns).
    const T bP = ScalarTraits<T>::isExact ? T(0) : (eP ? edgeBoundP_ : arcBoundPPQ_);
    if ((cba > bP && dba > bP) || (cba < -bP && dba < -bP)) return m;
    Vec3<T> nQ = d.cross(c);
    const bool eQ = edgePlaneQ(nQ, eq);
    const ArcVolumes<T> raw{cba, dba, a.dot(nQ), b.dot(nQ)};
    int sCba = detail::sign(raw.cba), sDba = detail::sign(raw.dba);
    int sAdc = detail::sign(raw.adc), sBdc = detail::sign(raw.bdc);
    if constexpr (!ScalarTraits<T>::isExact) {
      // The common case costs four comparisons: every volume beyond the filter's bound.
      const T bQ = eQ ? edgeBoundQ_ : arcBoundPQQ_;
      const bool certain = (absValue(raw.cba) > bP) & (absValue(raw.dba) > bP) & (absValue(raw.adc) > bQ) &
                           (absValue(raw.bdc) > bQ);
      if (!certain) {
        const int packed = exactArcSigns(ep, eq);
        sCba = (packed & 3) - 1, sDba = ((packed >> 2) & 3) - 1;
        sAdc = ((packed >> 4) & 3) - 1, sBdc = ((packed >> 6) & 3) - 1;
      }
    }
    // G(−Q)'s arc is (−c)–(−d): the first two volumes change sign (negatedSecondArc).
    if (detail::classifyArcSigns(-sCba, -sDba, sAdc, sBdc) != ArcIntersection::Proper) return m;
    const ArcVolumes<T> vol = raw.negatedSecondArc();
    // The crossing direction is a positive combination of a and b (arc_intersection.hpp).
    const Vec3<T> dir = arcIntersectionDirection(a, b, vol);
    if constexpr (!ScalarTraits<T>::isExact) {
      // The signs are exact, so the arcs do cross; but dir's weights are the rounded
      // volumes, which carry no digit where the four normals are nearly on one great
      // circle (a flat edge of Q in the plane of P's arc), and dir may then be anywhere
      // on the arc a–b. It orients the face's normal below, so it must agree with the
      // crossing seen on the arc of −Q, −(|dba| c + |cba| d); both are accurate in
      // direction when the arcs meet at a clear angle. Where they disagree the face is
      // not declared: its plane could not be oriented.
      const Vec3<T> onQ = -(absValue(vol.dba) * c + absValue(vol.cba) * d);
      if (!(onQ.dot(dir) > T(0))) return m;
    }
    const Vec3<T> p0 = P_.vertex(vp.first);
    const Vec3<T> q0 = q(vq.first);
    // Q's edge direction from its own coordinates, then rotated: q(b) − q(a) would lose
    // it entirely when Q is small against its offset (a 1e-29 shape placed at 2).
    Vec3<T> dp = P_.vertex(vp.second) - p0, dq = R_ * Vec3<T>(Q_.vertex(vq.second) - Q_.vertex(vq.first));
    if constexpr (!ScalarTraits<T>::isExact) {
      // Each edge direction scaled by a power of two (exact) to unit order: the normal of
      // 1e86-long edges is 1e172 and its k 1e258, and the searches' cross-multiplied
      // comparisons (and |N|^2 |dp|^2 |dq|^2 below) overflowed, so that no EE face of two
      // such shapes existed; 1e-200-long edges underflowed the same way.
      // Only outside 2^±64 (a test of two maxima on the hot path of SEARCH-EE): the ratio
      // the searches compare does not depend on N's length.
      // The same band as unitScaleExponent(): 2^±64 in double, 2^±8 in float.
      for (Vec3<T>* d : {&dp, &dq}) {
        const T big = d->cwiseAbs().maxCoeff();
        if (big > unitHi_ || big < unitLo_) *d = unitOrder(*d);
      }
    }
    Vec3<T> N = dp.cross(dq);
    if constexpr (!ScalarTraits<T>::isExact) {
      // Edges parallel up to rounding (exact quarter turns of symmetric shapes make them
      // so): N is rounding noise, and so would be the face's plane and its place in the
      // search order. Such a pair spans no facet of M worth its name; the facets beside
      // it (FV, VF, or their spans) answer, within the facet check's slack.
      const T floor = T(defaults::kMddParallelEdgeFactor) * ScalarTraits<T>::epsilon();
      if (N.squaredNorm() <= floor * floor * dp.squaredNorm() * dq.squaredNorm()) return m;
    }
    const T orient = N.dot(dir);
    if (orient == T(0)) return m;
    if (orient < T(0)) N = -N;
    m.type = MddFaceType::EE;
    m.a = ep;
    m.b = eq;
    m.N = N;
    m.k = N.dot(p0 - q0);
    return m;
  }

 private:
  const ConvexPolyhedron<T>& P_;
  const ConvexPolyhedron<T>& Q_;
  Mat3<T> R_, C_;
  Vec3<T> t_;
  bool useHierarchy_;
  T scene_ = T(0);   // inexact T: sceneSize()
  T arcBoundPPQ_ = T(0), arcBoundPQQ_ = T(0);  // inexact T: the arc test's filter (ee())
  T edgeBoundP_ = T(0), edgeBoundQ_ = T(0);    // ... where an arc's plane is its edge
  T unitLo_ = T(0), unitHi_ = T(0);              // inexact T: 2^-kUnitBand, 2^kUnitBand
  int unitExp_ = 0;  // inexact T: unitScaleExponent()
};

/// The search's objective: face f is better than g along σ for centre c when
/// (N_f·σ)/(k_f − N_f·c) > (N_g·σ)/(k_g − N_g·c).
/// Collision mode (section V): with `earlyExit`, any face with k < 0 — a supporting plane
/// of M with the origin strictly outside — proves separation and stops the search.
template <class T>
struct RayObjective {
  Vec3<T> sigma;
  Vec3<T> c;
  bool earlyExit = false;
  mutable bool separated = false;
  mutable MFace<T> separator;  ///< the face that set `separated`
  T num(const MFace<T>& f) const { return f.N.dot(sigma); }
  T den(const MFace<T>& f) const { return f.k - f.N.dot(c); }
  bool better(const MFace<T>& f, const MFace<T>& g) const {
    if (earlyExit && !separated && f.valid() && f.k < T(0)) separated = true, separator = f;
    if (!g.valid()) return f.valid();
    if (!f.valid()) return false;
    return num(f) * den(g) > num(g) * den(f);
  }
};

}  // namespace detail
}  // namespace mink
