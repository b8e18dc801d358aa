// mink/mdd/mdd.hpp — minimum directional distance between two convex polyhedra:
// MDD-DUAL (Y.-K. Choi, X. Li, F. Rong, W. Wang, S. Cameron, "Computing the Minimum
// Directional Distance between Two Convex Polyhedra", seed 000).
//
//   1. Centre of duality (section IV-A, centre_of_duality.hpp): the line {t s} misses
//      M = P ⊕ −Q (NoContact), grazes it (case 2: the interval is read off the facet of M
//      containing the line), or a point c = α s strictly inside M is found.
//   2. From c, towards the origin first: SEARCH-FV, SEARCH-VF, SEARCH-EE (section IV-B)
//      find the face of M the ray c + u σ leaves through (σ = ±s): the maximum of the
//      linear function σ·N/(k − N·c) over the dual polytope M* (section III-B, Lemma 1).
//   3. The answer is checked: the line must cross the facet of M in that face's plane
//      (the Minkowski difference of the support sets of P and Q, which also covers spans
//      of faces with one normal, section VI-C); if not, every FV, VF and EE face is
//      examined (never seen on the paper's shapes; counted in MddResult::usedFallback).
//   4. If the origin is inside M, the other direction is searched too (d_min, section
//      III-C) and the nearer exit is reported.
// The line parameter of a face is t = k / (N·s): all decisions are signs of polynomials
// in the inputs, so with an exact rational T the result is exact.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/mdd/centre_of_duality.hpp"
#include "mink/mdd/exit_portal.hpp"
#include "mink/mdd/detail/contact_set.hpp"
#include "mink/mdd/search_ee.hpp"
#include "mink/mdd/search_fv.hpp"

namespace mink {
namespace detail {

template <class T>
void checkPose(const Pose<T>& pose, const char* name) {
  for (int i = 0; i < 3; ++i) {
    if (!ScalarTraits<T>::isFinite(pose.translation[i]))
      throw InvalidInput(std::string("mdd: ") + name + ".translation is not finite");
    if constexpr (!ScalarTraits<T>::isExact)
      if (absValue(pose.translation[i]) > ScalarTraits<T>::largestCoordinate())
        throw InvalidInput(std::string("mdd: ") + name +
                           ".translation is out of range (above ScalarTraits::largestCoordinate())");
    for (int j = 0; j < 3; ++j)
      if (!ScalarTraits<T>::isFinite(pose.rotation(i, j)))
        throw InvalidInput(std::string("mdd: ") + name + ".rotation is not finite");
  }
  const Mat3<T> E = pose.rotation.transpose() * pose.rotation - Mat3<T>::Identity();
  T tol = T(0);
  if constexpr (!ScalarTraits<T>::isExact)
    tol = std::max(T(defaults::kRotationTolerance), T(100) * ScalarTraits<T>::epsilon());
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (absValue(E(i, j)) > tol)
        throw InvalidInput(std::string("mdd: ") + name + ".rotation is not orthonormal");
  if (!(pose.rotation.determinant() > T(0)))
    throw InvalidInput(std::string("mdd: ") + name + ".rotation is a reflection (determinant < 0)");
}

/// Q's placement in P's frame (R, t) and P's world-to-local rotation RPt, after checking
/// both poses; resets the cache's hints when it last served another pair of shapes.
template <class T>
struct RelativePose {
  Mat3<T> RPt, R;
  Vec3<T> t;
};

template <class T>
RelativePose<T> relativePose(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                             const Pose<T>& poseQ, MddCache<T>& cache) {
  checkPose(poseP, "poseP");
  checkPose(poseQ, "poseQ");
  for (const auto* X : {&P, &Q})
    if (!X->edgesResolved())
      throw InvalidInput(std::string("mdd: ") + (X == &P ? "P" : "Q") +
                         " has an edge whose two face normals are opposite to rounding (a dihedral angle "
                         "below about 64 eps, built with a hull tolerance of 0): too thin for the Gauss-map "
                         "tests in this scalar type");
  if (cache.shapeP != &P || cache.shapeQ != &Q) {
    cache.faceP = cache.vertexP = cache.vertexQ = -1;
    cache.exitFaces[0] = cache.exitFaces[1] = MddCachedFace{};
    cache.shapeP = &P;
    cache.shapeQ = &Q;
  }
  RelativePose<T> rel;
  // P's inverse rotation, not its transpose: the two differ when the matrix is a rotation
  // only up to rounding, and the inverse keeps the answer the exact one for the shapes
  // as placed by the matrices given.
  rel.RPt = poseP.rotation.inverse();
  rel.R = rel.RPt * poseQ.rotation;
  rel.t = rel.RPt * (poseQ.translation - poseP.translation);
  return rel;
}

template <class T>
class MddQuery {
 public:
  MddQuery(const PairFrame<T>& F, const Vec3<T>& s, MddCache<T>& cache, const MddOptions<T>& opt, MddResult<T>& res)
      : F_(F), s_(s), cache_(cache), res_(res) {
    const ConvexPolyhedron<T>& P = F.P();
    const ConvexPolyhedron<T>& Q = F.Q();
    if constexpr (ScalarTraits<T>::isExact) {
      tol_ = numTol_ = T(0);
    } else {
      const T scene = F.sceneSize();
      // numTol_: the rounding slack of the facet checks, always automatic; tol_: what
      // counts as touching, the caller's choice (a large touchTolerance must not make
      // the facet checks accept faces the line misses).
      numTol_ = T(defaults::kMddTouchToleranceFactor) * ScalarTraits<T>::epsilon() * scene;
      tol_ = opt.touchTolerance >= T(0) ? opt.touchTolerance : numTol_;
      scene_ = scene;
      sLength_ = s.norm();
    }
    const long long faces = P.numFaces() + Q.numFaces() + 64;
    cap_ = opt.maxVisits >= 0 ? opt.maxVisits : defaults::kMddVisitFactor * faces;
    autoCap_ = opt.maxVisits < 0;
    const long long pairs = static_cast<long long>(P.numEdges()) * static_cast<long long>(Q.numEdges());
    exhaustiveAllowed_ = pairs <= (opt.maxExhaustivePairs >= 0 ? opt.maxExhaustivePairs : defaults::kMddExhaustivePairs);
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

  /// The face of M through which the ray c + u σ (u > 0) leaves M. Invalid on a cap.
  /// With `earlyExit` (collision mode), stops with an invalid face and `separated` set as
  /// soon as a face proves the origin outside M.
  ///
  /// Directional mode: the exit-portal estimate (exit_portal.hpp) names a normal close to
  /// the exit facet's; the FV and VF faces best aligned with it at its support vertices,
  /// then the EE faces of the edges at those vertices, are tried first, and the first
  /// that passes the facet check is the answer (a supporting plane of M whose facet the
  /// line crosses is where the ray leaves M: no search can do better). Otherwise the
  /// paper's three searches run from those faces.
  MFace<T> exitFace(const Vec3<T>& sigma, const Vec3<T>& c, bool earlyExit = false, bool* separated = nullptr,
                    MFace<T>* separator = nullptr) {
    const ConvexPolyhedron<T>& P = F_.P();
    const ConvexPolyhedron<T>& Q = F_.Q();
    RayObjective<T> obj{sigma, c, false, false, MFace<T>()};
    obj.earlyExit = earlyExit;
    auto stopped = [&]() {
      if (!obj.separated) return false;
      if (separated) *separated = true;
      if (separator) *separator = obj.separator;
      return true;
    };
    SearchBudget budget{cap_, false};
    int& hintP = cache_.vertexP;
    int& hintQ = cache_.vertexQ;
    int f0 = -1, g0 = -1;
    if (!earlyExit) {
      // 1. A face kept from the last query, on this side of the line: when the pair moved
      //    a little, the exit face is it or one of its neighbours.
      ExitPortal<T> est;
      for (const MddCachedFace& cf : cache_.exitFaces) {
        const MFace<T> m = rebuild(cf);
        if (!m.valid() || !(obj.num(m) > T(0))) continue;
        est.normal = m.N;
        est.vertexP = m.type == MddFaceType::FV ? P.faceVertices(m.a)[0]
                      : m.type == MddFaceType::VF ? m.a : P.edgeVertices(m.a).first;
        est.vertexQ = m.type == MddFaceType::FV ? m.b
                      : m.type == MddFaceType::VF ? Q.faceVertices(m.b)[0] : Q.edgeVertices(m.b).first;
        break;
      }
      if (est.vertexP >= 0) {
        MFace<T> hit;
        if (!tryAround(est, obj, budget, f0, g0, hit)) return MFace<T>();
        if (hit.valid()) return remember(hit, MddPath::Certificate);
      }
      // 2. Else the exit portal, unless the shapes are large and a kept face gave a start:
      //    then the searches walk from there, a few faces instead of dozens of
      //    hierarchy queries (benchmarks/README.md, coherence).
      const bool large = F_.hasHierarchy();
      if (est.vertexP < 0 || !large) {
        est = exitPortal(F_, c, sigma, hintP, hintQ);
        res_.portalSteps += est.steps;
        MFace<T> hit;
        if (!tryAround(est, obj, budget, f0, g0, hit)) return MFace<T>();
        if (hit.valid()) return remember(hit, MddPath::Certificate);
      }
    } else {
      // Initial face (section VI-A): around P's support vertex along σ, or the cached one.
      f0 = cache_.faceP;
      if (f0 < 0 || f0 >= P.numFaces()) {
        hintP = F_.supportP(sigma, hintP);
        f0 = P.vertexFaces(hintP)[0];
      }
    }
    const MFace<T> fv = searchFV(F_, obj, f0, hintQ, cache_.marksP, budget, res_.visitedFV);
    if (stopped()) return MFace<T>();
    if (g0 < 0) g0 = Q.vertexFaces(fv.b)[0];
    const MFace<T> vf = searchVF(F_, obj, g0, hintP, cache_.marksQ, budget, res_.visitedVF);
    if (stopped()) return MFace<T>();
    const MFace<T>& start = obj.better(vf, fv) ? vf : fv;
    MFace<T> best = searchEE(F_, obj, start, cache_.marksEE, cache_.crossings, budget,
                             res_.visitedEE, res_.usedPairScan);
    if (stopped()) return MFace<T>();
    if (budget.exhausted) {
      // The automatic cap ended a walk (through faces tied to rounding: a line through a
      // vertex of M where two cones' apexes meet, every face around it an exit, each step
      // a few ulps better than the last). Its best face still answers if the line crosses
      // its facet: a supporting plane of M whose facet the line crosses is where the ray
      // leaves M, however the face was found. A cap the caller set is respected.
      if (!autoCap_ || !(obj.num(best) > T(0)) || !exitHit(best)) return MFace<T>();
      cache_.faceP = best.type == MddFaceType::FV ? best.a : fv.a;
      return remember(best, MddPath::Search);
    }
    MddPath path = MddPath::Search;
    if (!(obj.num(best) > T(0)) || !exitHit(best)) {
      res_.usedFallback = true;
      path = MddPath::Exhaustive;
      if (!exhaustiveAllowed_) return MFace<T>();  // too many edge pairs: IterationLimit
      best = exhaustive(obj);
      if (stopped()) return MFace<T>();
      if (!best.valid()) {
        checkFailed_ = true;
        return MFace<T>();
      }
    }
    cache_.faceP = best.type == MddFaceType::FV ? best.a : fv.a;
    return remember(best, path);
  }

  /// The face of M named by a cached (type, a, b), rebuilt for the current pose (its
  /// support vertex re-found from the cached one); invalid if it is no face of M now.
  MFace<T> rebuild(const MddCachedFace& cf) {
    int h;
    switch (cf.type) {
      case MddFaceType::FV:
        if (cf.a < 0 || cf.a >= F_.P().numFaces() || cf.b < 0 || cf.b >= F_.Q().numVertices()) break;
        h = cf.b;
        return F_.fv(cf.a, h);
      case MddFaceType::VF:
        if (cf.b < 0 || cf.b >= F_.Q().numFaces() || cf.a < 0 || cf.a >= F_.P().numVertices()) break;
        h = cf.a;
        return F_.vf(cf.b, h);
      case MddFaceType::EE:
        if (cf.a < 0 || cf.a >= F_.P().numEdges() || cf.b < 0 || cf.b >= F_.Q().numEdges()) break;
        return F_.ee(cf.a, cf.b);
      default:
        break;
    }
    return MFace<T>();
  }

  /// The faces at the estimate's support vertices: the FV and VF faces best aligned with
  /// its normal (f0, g0: the searches' starts), then the EE faces of the edges there. `hit`
  /// is the first that the line crosses (faceHit), else invalid. False on the visit cap.
  bool tryAround(const ExitPortal<T>& est, const RayObjective<T>& obj, SearchBudget& budget, int& f0, int& g0,
                 MFace<T>& hit) {
    f0 = alignedFaceP(est.vertexP, est.normal);
    g0 = alignedFaceQ(est.vertexQ, est.normal);
    int hq = est.vertexQ, hp = est.vertexP;
    if (!budget.take() || !budget.take()) return false;
    const MFace<T> fv = F_.fv(f0, hq);
    const MFace<T> vf = F_.vf(g0, hp);
    res_.visitedFV += 1;
    res_.visitedVF += 1;
    const MFace<T> best = obj.better(vf, fv) ? vf : fv;
    if (obj.num(best) > T(0) && certifies(best)) {
      hit = best;
      return true;
    }
    nearestArcs(F_.P(), est.vertexP, unitOrder(est.normal), cache_.edgesP);
    nearestArcs(F_.Q(), est.vertexQ, unitOrder(Vec3<T>(F_.R().transpose() * est.normal)), cache_.edgesQ);
    MFace<T> bestEE;
    for (int ep : cache_.edgesP)
      for (int eq : cache_.edgesQ) {
        if (!budget.take()) return false;
        const MFace<T> m = F_.ee(ep, eq);
        if (!m.valid()) continue;
        ++res_.visitedEE;
        if (obj.better(m, bestEE)) bestEE = m;
      }
    if (obj.num(bestEE) > T(0) && obj.better(bestEE, best) && certifies(bestEE))
      hit = bestEE;
    return true;
  }

  /// out := the edges of X at vertex v whose Gauss arcs pass nearest the direction n (X's
  /// frame), at most defaults::kMddPortalEdgeCandidates of them, in O(degree): an arc
  /// lies on the great circle orthogonal to its edge d, at the angle whose sine is
  /// |n·d| / (|n| |d|) from n, compared squared and cross-multiplied. An EE face whose
  /// normal the estimate n approximates pairs two such arcs crossing near n.
  static void nearestArcs(const ConvexPolyhedron<T>& X, int v, const Vec3<T>& n, std::vector<int>& out) {
    constexpr int K = defaults::kMddPortalEdgeCandidates;
    out.clear();
    T num[K], den[K];
    for (int h : X.vertexHalfEdges(v)) {
      const int e = X.heEdge(h);
      const auto ends = X.edgeVertices(e);
      // At unit order (exactly scaled; the ratio is scale-free): edges of a 2^-300 shape
      // would square to 2^-600 and their products underflow.
      const Vec3<T> d = unitOrder(Vec3<T>(X.vertex(ends.second) - X.vertex(ends.first)));
      const T a = n.dot(d);
      const T na = a * a, da = d.squaredNorm();
      // Insertion into the K nearest so far (na / da smallest), kept sorted.
      int k = static_cast<int>(out.size());
      if (k == K) {
        if (!(na * den[K - 1] < num[K - 1] * da)) continue;
        --k;
      } else {
        out.push_back(e);
      }
      for (; k > 0 && na * den[k - 1] < num[k - 1] * da; --k) {
        out[k] = out[k - 1];
        num[k] = num[k - 1];
        den[k] = den[k - 1];
      }
      out[k] = e;
      num[k] = na;
      den[k] = da;
    }
  }

  /// Every FV, VF and EE face of M (each facet of M is one of them: its support sets are
  /// a face of P, a face of Q, or two non-parallel edges whose arcs cross properly): the
  /// exit face whose facet the line crosses (facetHit, witnesses filled), else invalid.
  ///
  /// The exit is the face of least ray parameter u = (k − N·c) / (N·σ), but faces of M
  /// within rounding of coplanar (a sheet 1e-12 thick, near-integer shapes) have u equal
  /// up to rounding while their facets lie apart in the plane: the least computed u may
  /// name a neighbour of the facet the line crosses. Every face whose u is within the
  /// rounding slack of the least is an exit to that accuracy, so the first of those
  /// (in order of u) that the line crosses answers. Exact T: exact ties only.
  MFace<T> exhaustive(const RayObjective<T>& obj) {
    MFace<T> best;
    forEachFace([&](const MFace<T>& m) {
      if (obj.num(m) > T(0) && obj.better(m, best)) best = m;
    });
    if (!best.valid() || exitHit(best)) return best;
    // u_m − u_best ≤ slack(m) + slack(best), slack(x) = numTol_ |N_x| / (N_x·σ); times
    // both (positive) numerators.
    const T nb = obj.num(best), db = obj.den(best), lb = norm(best.N);
    std::vector<std::pair<T, MFace<T>>>& ties = tiesScratch_;
    ties.clear();
    forEachFace([&](const MFace<T>& m) {
      const T nm = obj.num(m);
      if (!(nm > T(0))) return;
      const T gap = obj.den(m) * nb - db * nm;
      if (gap <= numTol_ * (norm(m.N) * nb + lb * nm)) ties.push_back({obj.den(m) / nm, m});
    });
    std::sort(ties.begin(), ties.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& tie : ties)
      if (exitHit(tie.second)) return tie.second;
    return MFace<T>();
  }

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

  /// Visits every FV, VF and EE face of M once, in a fixed order.
  template <class Visit>
  void forEachFace(Visit&& visit) {
    const ConvexPolyhedron<T>& P = F_.P();
    const ConvexPolyhedron<T>& Q = F_.Q();
    int hq = cache_.vertexQ, hp = cache_.vertexP;
    for (int f = 0; f < P.numFaces(); ++f) {
      ++res_.visitedFV;
      visit(F_.fv(f, hq));
    }
    for (int f = 0; f < Q.numFaces(); ++f) {
      ++res_.visitedVF;
      visit(F_.vf(f, hp));
    }
    for (int ep = 0; ep < P.numEdges(); ++ep)
      for (int eq = 0; eq < Q.numEdges(); ++eq) {
        const MFace<T> m = F_.ee(ep, eq);
        if (!m.valid()) continue;
        ++res_.visitedEE;
        visit(m);
      }
  }

  /// True after a search whose every candidate failed the facet check, the exhaustive
  /// fallback's included (not after the visit cap).
  bool checkFailed() const { return checkFailed_; }

  /// May the fallbacks that visit every face of M (exhaustive, chord) run? False when
  /// edges(P) * edges(Q) exceeds MddOptions::maxExhaustivePairs.
  bool exhaustiveAllowed() const { return exhaustiveAllowed_; }

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


  /// The line's chord of M, [tlo, thi] in parameters of s, by clipping the line against
  /// the plane of every FV, VF and EE face (M is the intersection of their half-spaces),
  /// and the faces that bound it: the last resort for lines that graze M within the
  /// rounding of the centre of duality (which is then not reliably inside M). False if
  /// the line misses M by more than the rounding slack.
  bool chord(T& tlo, T& thi, MFace<T>& lo, MFace<T>& hi) {
    bool outside = false;
    forEachFace([&](const MFace<T>& m) {
      const T ns = m.N.dot(s_);
      // A plane holding the line to rounding bounds nothing along it (its k / (N·s) is
      // noise); the line is in its half-space.
      if (lineInPlane(m)) return;
      // Only planes that support M (a face declared by rounding cuts M).
      if (!facetSets(m)) return;
      // Each plane pushed out by the rounding slack: a plane the line meets at a grazing
      // angle, whose k / (N·s) is rounding over a tiny N·s, then bounds nothing near M
      // instead of cutting the chord at a point far off M; the others move by the slack
      // over their sine. The chord's ends are then within the slack of M's boundary.
      const T k = m.k + numTol_ * norm(m.N);
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

  /// Witnesses on the facet of M in face m's plane nearest the line (chord()'s faces,
  /// which the line may miss by rounding).
  void nearestWitnesses(const MFace<T>& m) {
    if (facetHit(m)) return;
    // facetHit left the facet's support sets in setP / setQ: the point of their
    // difference's hull nearest the line (any slack above the scene's size accepts it).
    hitSets(T(4) * F_.sceneSize());
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
    cache_.setP.clear();
    cache_.setQ.clear();
    cache_.points2.clear();
    // The face's polygon in cyclic order; ids index setP × setQ as in hitSets.
    auto add = [&](int ip, int iq) {
      const Vec3<T> y = P.vertex(cache_.setP[ip]) - F_.q(cache_.setQ[iq]);
      cache_.points2.push_back({{y.dot(u1_), y.dot(u2_)}, ip * static_cast<int>(cache_.setQ.size()) + iq});
    };
    switch (m.type) {
      case MddFaceType::FV:
        for (int v : P.faceVertices(m.a)) cache_.setP.push_back(v);
        cache_.setQ.push_back(m.b);
        for (int i = 0; i < static_cast<int>(cache_.setP.size()); ++i) add(i, 0);
        break;
      case MddFaceType::VF:
        cache_.setP.push_back(m.a);
        for (int v : Q.faceVertices(m.b)) cache_.setQ.push_back(v);
        for (int j = 0; j < static_cast<int>(cache_.setQ.size()); ++j) add(0, j);
        break;
      case MddFaceType::EE:
        cache_.setP.push_back(P.edgeVertices(m.a).first);
        cache_.setP.push_back(P.edgeVertices(m.a).second);
        cache_.setQ.push_back(Q.edgeVertices(m.b).first);
        cache_.setQ.push_back(Q.edgeVertices(m.b).second);
        add(0, 0);
        add(1, 0);
        add(1, 1);
        add(0, 1);
        break;
      default:
        return false;
    }
    OriginLocation<T> loc;
    if (!locateOriginConvex(cache_.points2, loc)) return false;
    setWitnesses(loc);
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
    const bool okP = supportSet(P, vp, [&](int v) { return T(N.dot(P.vertex(v))); }, eps, cache_.marksP, cache_.setP);
    const bool okQ = supportSet(Q, vq, [&](int v) { return T(-N.dot(F_.q(v))); }, eps, cache_.marksQ, cache_.setQ);
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
    Vec3<T> bestP = wP_, bestQ = wQ_;
    forEachFace([&](const MFace<T>& m) {
      const T n = norm(m.N);
      if (!(n > T(0)) || !(slackUnits(T(absValue(T(m.N.dot(X) - m.k)) / n)) < best)) return;  // its plane is farther
      if (!facetSets(m) || !witnessesAt(X, m.N, T(4) * F_.sceneSize())) return;
      const T dist = norm(inUnits(Vec3<T>(wP_ - wQ_ - X)));
      if (dist < best) best = dist, nearest = m, bestP = wP_, bestQ = wQ_;
    });
    wP_ = bestP;
    wQ_ = bestQ;
    if (!nearest.valid()) return false;
    facetSets(nearest);
    return true;
  }

  /// The rounding slack of the facet checks (length; 0 for exact T).
  const T& slack() const { return numTol_; }

  void setWitnesses(const OriginLocation<T>& loc) {
    const ConvexPolyhedron<T>& P = F_.P();
    wP_ = Vec3<T>::Zero();
    wQ_ = Vec3<T>::Zero();
    for (int i = 0; i < loc.count; ++i) {
      const int ip = loc.id[i] / static_cast<int>(cache_.setQ.size());
      const int iq = loc.id[i] % static_cast<int>(cache_.setQ.size());
      wP_ += loc.weight[i] * P.vertex(cache_.setP[ip]);
      wQ_ += loc.weight[i] * F_.q(cache_.setQ[iq]);
    }
  }

  /// Grazing (case 2): the plane w·x = 0 supports M and holds the line. The line meets
  /// M in [tlo, thi] (parameters of s) iff it meets the facet F_P(w) − F_Q(w).
  bool grazing(const Vec3<T>& w, T& tlo, T& thi, int& vp, int& vq) {
    const ConvexPolyhedron<T>& P = F_.P();
    const ConvexPolyhedron<T>& Q = F_.Q();
    vp = F_.supportP(w, cache_.vertexP);
    vq = F_.supportMinusQ(w, cache_.vertexQ);
    T eps = T(0);
    if constexpr (!ScalarTraits<T>::isExact) eps = numTol_ * w.norm();
    supportSet(P, vp, [&](int v) { return T(w.dot(P.vertex(v))); }, eps, cache_.marksP, cache_.setP);
    supportSet(Q, vq, [&](int v) { return T(-w.dot(F_.q(v))); }, eps, cache_.marksQ, cache_.setQ);
    // In the plane: coordinate a along s, b along e = w × s; the line is b == 0. In 2^e
    // units (see u1_): the crossings below multiply two coordinates. The facet's polygon
    // (its vertices in cyclic order) meets the line where its edges cross b == 0.
    facetPolygon(inUnits(s_), inUnits(Vec3<T>(w.cross(s_))), Vec3<T>::Zero());
    const auto& ab = cache_.points2;
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
    const T ss = s_.squaredNorm();
    tlo = amin / ss;
    thi = amax / ss;
    if constexpr (!ScalarTraits<T>::isExact) {
      using std::ldexp;
      if (unitExp_ != 0) tlo = ldexp(tlo, unitExp_), thi = ldexp(thi, unitExp_);
    }
    return true;
  }

  /// The face of P at vertex v whose normal is closest in angle to n, and of Q at
  /// vertex w whose VF face normal (−R n_q) is: the start faces for FV and VF.
  int alignedFaceP(int v, const Vec3<T>& n) const {
    int best = -1;
    T bd = T(0), bl = T(1);
    for (int f : F_.P().vertexFaces(v)) {
      const Vec3<T>& nf = F_.P().faceNormal(f);
      const T d = nf.dot(n), l = nf.squaredNorm();
      if (best < 0 || cosineGreater(d, l, bd, bl)) best = f, bd = d, bl = l;
    }
    return best;
  }
  int alignedFaceQ(int w, const Vec3<T>& n) const {
    const Vec3<T> nl = F_.R().transpose() * n;
    int best = -1;
    T bd = T(0), bl = T(1);
    for (int g : F_.Q().vertexFaces(w)) {
      const Vec3<T>& ng = F_.Q().faceNormal(g);
      const T d = -ng.dot(nl), l = ng.squaredNorm();
      if (best < 0 || cosineGreater(d, l, bd, bl)) best = g, bd = d, bl = l;
    }
    return best;
  }

  const Vec3<T>& witnessP() const { return wP_; }
  const Vec3<T>& witnessQ() const { return wQ_; }
  const T& tolerance() const { return tol_; }

 private:
  /// |n| for slack computations; 0 for exact T (whose slack numTol_ is 0).
  static T norm(const Vec3<T>& n) {
    if constexpr (ScalarTraits<T>::isExact) {
      (void)n;
      return T(0);
    } else {
      return n.norm();
    }
  }
  /// d1/√l1 > d2/√l2 without square roots (l1, l2 > 0).
  static bool cosineGreater(const T& d1, const T& l1, const T& d2, const T& l2) {
    if ((d1 >= T(0)) != (d2 >= T(0))) return d1 >= T(0);
    const T a = d1 * d1 * l2, b = d2 * d2 * l1;
    return d1 >= T(0) ? a > b : a < b;
  }
  /// Keeps the last two exit faces in the cache (a penetrating query has two), to be
  /// certified first by the next query of the pair; `path` found f (the result keeps the
  /// costliest path of its exits).
  const MFace<T>& remember(const MFace<T>& f, MddPath path) {
    if (static_cast<int>(path) > static_cast<int>(res_.path)) res_.path = path;
    cache_.exitFaces[1] = cache_.exitFaces[0];
    cache_.exitFaces[0] = MddCachedFace{f.type, f.a, f.b};
    return f;
  }

  const PairFrame<T>& F_;
  Vec3<T> s_;
  MddCache<T>& cache_;
  MddResult<T>& res_;
  T tol_, numTol_;
  T scene_ = T(0), sLength_ = T(1);  // inexact T: the scene size (as numTol_'s) and |s|
  long long cap_;
  Vec3<T> u1_, u2_;
  int unitExp_ = 0;  // inexact T: PairFrame::unitScaleExponent (u1_, u2_ are 2^-e units)
  Vec3<T> wP_ = Vec3<T>::Zero(), wQ_ = Vec3<T>::Zero();
  std::vector<std::pair<T, MFace<T>>> tiesScratch_;
  bool checkFailed_ = false;
  bool exhaustiveAllowed_ = true;
  bool autoCap_ = true;  // the visit cap is the automatic one (MddOptions::maxVisits < 0)
};

/// |s| for reporting. Exact T has no sqrt: exact when |s|^2 == 1, otherwise a Newton
/// iterate accurate far beyond double precision (reported values only, never decisions).
template <class T>
T lengthOf(const Vec3<T>& s) {
  if constexpr (ScalarTraits<T>::isExact) {
    const T n2 = s.squaredNorm();
    if (n2 == T(1)) return T(1);
    T x = std::max({absValue(s[0]), absValue(s[1]), absValue(s[2])});
    for (int i = 0; i < 5; ++i) x = (x + n2 / x) / T(2);
    return x;
  } else {
    return s.norm();
  }
}

template <class T>
Vec3<T> unitOrExact(const Vec3<T>& n) {
  if constexpr (ScalarTraits<T>::isExact) {
    return n;
  } else {
    const Vec3<T> m = unitOrder(n);
    const T len = m.norm();
    return len > T(0) ? Vec3<T>(m / len) : m;
  }
}

}  // namespace detail

namespace detail {
/// mdd() for a direction already checked (and, for inexact T, scaled to unit order).
template <class T>
MddResult<T> mddChecked(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                        const Pose<T>& poseQ, const Vec3<T>& s, MddCache<T>& cache, const MddOptions<T>& options) {
  const detail::RelativePose<T> rel = detail::relativePose(P, poseP, Q, poseQ, cache);
  const Mat3<T>& RPt = rel.RPt;
  const Mat3<T>& R = rel.R;
  const Vec3<T>& t = rel.t;
  const Vec3<T> sl = RPt * s;
  detail::PairFrame<T> F(P, Q, R, t, options.useHierarchy);
  MddResult<T> res;
  detail::MddQuery<T> query(F, sl, cache, options, res);
  const T slen = detail::lengthOf(s);
  auto toWorld = [&](const Vec3<T>& x) { return Vec3<T>(poseP.rotation * x + poseP.translation); };
  auto noContact = [&]() {
    res.status = MddStatus::NoContact;
    res.faceType = MddFaceType::None;
    if constexpr (std::numeric_limits<T>::has_infinity) {
      res.distance = res.translation = res.parameter = std::numeric_limits<T>::infinity();
    }
    return res;
  };
  auto finish = [&](const T& param) {
    res.parameter = param;
    res.translation = param * slen;
    // witnessP − witnessQ = parameter · s by construction where one side of the facet is
    // a single vertex (FV, VF): the other witness is that vertex moved by the motion.
    // Barycentric weights in a sliver fan triangle of the face would leave it 1e-5 off.
    if constexpr (!ScalarTraits<T>::isExact) {
      if (res.faceType == MddFaceType::EE && res.featureP >= 0 && res.featureQ >= 0) {
        // An EE face is a parallelogram e_P − e_Q, as long and thin as its edges are
        // unequal (a 3-unit edge against a 1e12 one): its fan triangles' barycentric
        // weights are ill-conditioned there. Solve p0 + λ dp − (q0 + μ dq) = param s in
        // the face's plane directly instead (Lagrange's identity; the edges are not
        // parallel, or the face would not exist).
        const auto ep = P.edgeVertices(res.featureP);
        const auto eq = Q.edgeVertices(res.featureQ);
        const Vec3<T> p0 = toWorld(P.vertex(ep.first)), dp = toWorld(P.vertex(ep.second)) - p0;
        const Vec3<T> q0 = poseQ.rotation * Q.vertex(eq.first) + poseQ.translation;
        const Vec3<T> dq = poseQ.rotation * Vec3<T>(Q.vertex(eq.second) - Q.vertex(eq.first));
        // lambda and mu are ratios of degree 0 in lengths: solved in the query's 2^e units
        // (scene far from unit order), where |N|^2, of degree 4, neither underflows nor
        // overflows.
        const Vec3<T> dpu = query.inUnits(dp), dqu = query.inUnits(dq);
        const Vec3<T> N = dpu.cross(dqu), d = query.inUnits(Vec3<T>(param * s - (p0 - q0)));
        const T n2 = N.squaredNorm();
        if (n2 > T(0) && std::isfinite(n2)) {
          const T lambda = N.dot(d.cross(dqu)) / n2, mu = -N.dot(dpu.cross(d)) / n2;
          // Only where the line crosses this parallelogram (not a coplanar neighbour of
          // the facet that the facet check accepted).
          const T slack = T(1e-6);
          if (lambda >= -slack && lambda <= T(1) + slack && mu >= -slack && mu <= T(1) + slack) {
            res.witnessP = p0 + std::min(T(1), std::max(T(0), lambda)) * dp;
            res.witnessQ = q0 + std::min(T(1), std::max(T(0), mu)) * dq;
          }
        }
      }
      const Vec3<T> r = res.witnessP - res.witnessQ - param * s;
      if (cache.setQ.size() == 1 && cache.setP.size() > 1) res.witnessP -= r;
      if (cache.setP.size() == 1 && cache.setQ.size() > 1) res.witnessQ += r;
      // Both sides spans (or a single pair) and the witnesses still off the motion: the
      // line met the facet at a grazing angle, where locating its crossing along s is
      // ill-conditioned (0.52 off on a face met at a sine of 1.5e-11). The contact point
      // param * s is located in the facet's own plane instead.
      const Vec3<T> r2 = res.witnessP - res.witnessQ - param * s;
      // Only if the contact point lies on that facet: where the parameter itself is off
      // along a grazing line (1e-7 of a 1e26 scene), the crossing found along s, on the
      // line and on the facet, is the better pair.
      if (res.faceType != MddFaceType::Grazing && query.inUnits(r2).norm() > query.slackUnits(query.slack()) &&
          query.witnessesAt(Vec3<T>(param * sl), Vec3<T>(RPt * res.normal))) {
        res.witnessP = toWorld(query.witnessP());
        res.witnessQ = toWorld(query.witnessQ());
      }
    }
    if (detail::absValue(res.translation) <= query.tolerance()) {
      res.status = MddStatus::Touching;
      res.distance = T(0);
    } else if (res.status != MddStatus::Penetrating) {
      res.status = MddStatus::Separated;
      res.distance = detail::absValue(res.translation);
    } else {
      res.distance = -detail::absValue(res.translation);
    }
    return res;
  };

  // Frame coherence: if the faces that ended the last query still bound the line (each
  // a supporting plane of M whose facet the line crosses), they give the answer.
  {
    detail::MFace<T> lo, hi;
    T tlo = T(0), thi = T(0);
    for (const MddCachedFace& cf : cache.exitFaces) {
      const detail::MFace<T> m = query.rebuild(cf);
      if (!m.valid()) continue;
      const T ns = m.N.dot(sl);
      if (ns == T(0) || (ns > T(0) ? hi.valid() : lo.valid())) continue;
      (m.type == MddFaceType::FV ? res.visitedFV : m.type == MddFaceType::VF ? res.visitedVF : res.visitedEE) += 1;
      if (!query.certifies(m)) continue;
      if (query.lineInPlane(m)) {
        lo = hi = detail::MFace<T>();  // a grazing line: the cold path decides
        break;
      }
      (ns > T(0) ? hi : lo) = m;
      (ns > T(0) ? thi : tlo) = m.k / ns;
    }
    const detail::MFace<T>* answer = nullptr;
    if (lo.valid() && tlo > T(0)) {
      answer = &lo;  // the whole line's stretch in M lies ahead: separated
      res.status = MddStatus::Separated;
    } else if (hi.valid() && thi < T(0)) {
      answer = &hi;
      res.status = MddStatus::Separated;
    } else if (lo.valid() && hi.valid()) {
      answer = detail::absValue(tlo) < detail::absValue(thi) ? &lo : &hi;  // tie: +s
      res.status = MddStatus::Penetrating;
    }
    if (answer) {
      query.certifies(*answer);  // its witnesses
      res.faceType = answer->type;
      res.featureP = answer->a;
      res.featureQ = answer->b;
      res.normal = detail::unitOrExact(Vec3<T>(RPt.transpose() * answer->N));
      res.witnessP = toWorld(query.witnessP());
      res.witnessQ = toWorld(query.witnessQ());
      res.fromCache = true;
      res.path = MddPath::Cache;
      return finish(answer->k / answer->N.dot(sl));
    }
    res.visitedFV = res.visitedVF = res.visitedEE = 0;
  }

  auto record = [&](const detail::MFace<T>& f) {
    res.faceType = f.type;
    res.featureP = f.a;
    res.featureQ = f.b;
    res.normal = detail::unitOrExact(Vec3<T>(RPt.transpose() * f.N));
    res.witnessP = toWorld(query.witnessP());
    res.witnessQ = toWorld(query.witnessQ());
  };
  // The last resort (inexact T) when a search cannot answer: no face passed its facet
  // check (a line grazing M within the rounding of c), or, with the automatic caps, a
  // cap was hit (shapes far below the rounding of their distance, 100 apart 1e20 along
  // s, round M to a few points). The chord of M along the line, by clipping it against
  // every face plane, answers; it needs no centre of duality. A cap the caller set
  // (options.maxVisits) is respected: IterationLimit; so is the cap on the edge pairs the
  // chord visits (options.maxExhaustivePairs).
  auto fromChord = [&]() {
    if constexpr (!ScalarTraits<T>::isExact) {
      if (query.exhaustiveAllowed() && (query.checkFailed() || options.maxVisits < 0)) {
        res.usedFallback = true;  // the chord visits every edge pair
        res.path = MddPath::Chord;
        detail::MFace<T> lo, hi;
        T tlo = T(0), thi = T(0);
        if (!query.chord(tlo, thi, lo, hi)) return noContact();
        const detail::MFace<T>* answer = &hi;
        T tAns = thi;
        if (tlo > T(0)) {
          answer = &lo, tAns = tlo;
          res.status = MddStatus::Separated;
        } else if (thi < T(0)) {
          res.status = MddStatus::Separated;
        } else {
          if (detail::absValue(tlo) < detail::absValue(thi)) answer = &lo, tAns = tlo;  // tie: +s
          res.status = MddStatus::Penetrating;
        }
        query.nearestWitnesses(*answer);
        record(*answer);
        // The witnesses are the facet's point nearest the line; at a grazing angle the
        // contact's place along the line is ill-conditioned, so it is read off them (a
        // face met at a sine of 5e-12: 0.92 by its plane, 0.50 by its facet, 2.6e-12 from
        // the line). A face met at a larger angle has an accurate crossing: read off its
        // facet only where that reaches the line, to the slack. One it misses (by 1.4 on
        // a needle's M, the line meeting facets lost to rounding) says nothing about the
        // contact; the plane's crossing stands, the witnesses are the nearest point of any
        // facet to it.
        const Vec3<T> d = query.witnessP() - query.witnessQ();
        const T ss = sl.squaredNorm();
        if (ss > T(0)) {
          const T tW = d.dot(sl) / ss;
          if (!query.wellConditioned(*answer) ||
              query.inUnits(Vec3<T>(d - tW * sl)).norm() <= query.slackUnits(query.slack())) {
            tAns = tW;
          } else {
            T best = query.inUnits(Vec3<T>(d - tAns * sl)).norm();
            if (query.nearestFacetPoint(Vec3<T>(tAns * sl), best)) {
              res.witnessP = toWorld(query.witnessP());
              res.witnessQ = toWorld(query.witnessQ());
            }
          }
        }
        return finish(tAns);
      }
    }
    res.status = MddStatus::IterationLimit;
    res.path = MddPath::None;
    return res;
  };
  // The line lies in the supporting plane w·x = k of M (k = 0 up to rounding): it meets
  // M only in that plane's facet, in [tlo, thi] (case 2 of section IV-A).
  auto fromGrazing = [&](const Vec3<T>& wIn) {
    // To unit order: w's norm scales the support sets' slack.
    const Vec3<T> w = detail::unitOrder(wIn);
    res.path = MddPath::Grazing;
    T tlo, thi;
    int vp, vq;
    if (!query.grazing(w, tlo, thi, vp, vq)) return noContact();
    res.faceType = MddFaceType::Grazing;
    res.featureP = vp;
    res.featureQ = vq;
    res.normal = detail::unitOrExact(Vec3<T>(RPt.transpose() * w));
    const T param = (tlo <= T(0) && thi >= T(0)) ? T(0) : (tlo > T(0) ? tlo : thi);
    // Witnesses: the contact is on the facet; report the support vertices' pair moved
    // onto the line (exact contact points need the segment, which a caller rarely uses).
    res.witnessP = toWorld(P.vertex(vp));
    res.witnessQ = res.witnessP - param * s;
    res.status = MddStatus::Separated;
    return finish(param);
  };
  int hp = cache.vertexP, hq = cache.vertexQ;
  const CentreOfDuality<T> cd = centreOfDuality(F, sl, hp, hq);
  cache.vertexP = hp;
  cache.vertexQ = hq;
  using Kind = typename CentreOfDuality<T>::Kind;
  if (cd.kind == Kind::Outside) {
    // The separating direction and its support vertices: why the line misses (and what
    // mddExact certifies a NoContact with).
    res.normal = RPt.transpose() * cd.w;  // w . (RPt s) == (RPt^T w) . s: still orthogonal to s
    if constexpr (!ScalarTraits<T>::isExact) {
      const T len = res.normal.stableNorm();
      if (len > T(0)) res.normal /= len;
    }
    res.featureP = hp;
    res.featureQ = hq;
    return noContact();
  }
  if (cd.kind == Kind::Limit) return fromChord();
  if (cd.kind == Kind::Boundary) return fromGrazing(cd.w);
  // Interior: c = alpha * s strictly inside M.
  const Vec3<T>& c = cd.c;
  const T alphaNum = c.dot(sl);  // sign of alpha
  // Towards the origin first: it decides separated (the exit is the answer) or not.
  const Vec3<T> first = alphaNum > T(0) ? Vec3<T>(-sl) : Vec3<T>(sl);
  const detail::MFace<T> f1 = query.exitFace(first, c);
  if (!f1.valid()) return fromChord();
  // An exit face whose plane holds the line to rounding: c is on M's boundary, not
  // inside it, and the line grazes M along that face.
  if (query.lineInPlane(f1)) return fromGrazing(f1.N);
  const T t1 = f1.k / f1.N.dot(sl);
  record(f1);
  const bool originInside = alphaNum > T(0) ? t1 < T(0) : (alphaNum < T(0) ? t1 > T(0) : true);
  if (!originInside) {
    res.status = MddStatus::Separated;
    return finish(t1);
  }
  // Penetrating (or touching): the exit the other way, then the nearer one (d_min).
  const detail::MFace<T> f2 = query.exitFace(Vec3<T>(-first), c);
  if (!f2.valid()) return fromChord();
  if (query.lineInPlane(f2)) return fromGrazing(f2.N);
  const T t2 = f2.k / f2.N.dot(sl);
  res.status = MddStatus::Penetrating;
  if constexpr (!ScalarTraits<T>::isExact) {
    // The origin, inside M, within the rounding slack of the supporting plane of an exit
    // face that the line meets at a grazing angle: it is that close to M's boundary, so P
    // and Q touch to rounding. Said so (0), rather than through that face's k / (N·s),
    // rounding over a tiny N·s (a 6e59 scene: 1.9e56 where the other exit was 2e-11).
    // A face met at a larger angle gives an accurate k / (N·s) itself.
    for (const detail::MFace<T>* f : {&f1, &f2}) {
      if (query.wellConditioned(*f) || !(detail::absValue(f->k) <= query.slack() * f->N.norm())) continue;
      if (!query.facetHit(*f)) query.faceHit(*f);  // its support sets and witnesses
      record(*f);
      return finish(T(0));
    }
  }
  // Tie: the exit along +s is reported.
  const bool takeSecond = detail::absValue(t2) < detail::absValue(t1) ||
                          (detail::absValue(t2) == detail::absValue(t1) && t2 > t1);
  if (takeSecond) {
    record(f2);
    return finish(t2);
  }
  // f1's witnesses were overwritten by the second facet check: recompute them.
  // (f1 may have been accepted by its own polygon, faceHit, which the facet check with
  // its support sets can then miss by rounding.)
  if (!query.facetHit(f1)) query.faceHit(f1);
  record(f1);
  return finish(t1);
}

}  // namespace detail

/// Minimum directional distance between P (placed by poseP) and Q (placed by poseQ)
/// along s (world frame, any non-zero length), per DESIGN.md: see MddResult for the
/// meaning, unit, frame and sign of every output. Throws InvalidInput for a zero or
/// non-finite s, a non-finite / non-orthonormal pose or a NaN touchTolerance; never
/// throws otherwise.
/// `cache` (optional) carries frame coherence between queries of the same pair.
template <class T>
MddResult<T> mdd(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                 const Pose<T>& poseQ, const Vec3<T>& s, MddCache<T>& cache, const MddOptions<T>& options = {}) {
  for (int i = 0; i < 3; ++i)
    if (!ScalarTraits<T>::isFinite(s[i])) throw InvalidInput("mdd: direction s is not finite");
  if (s == Vec3<T>::Zero()) throw InvalidInput("mdd: direction s is zero");
  if (!(options.touchTolerance == options.touchTolerance))
    throw InvalidInput("mdd: options.touchTolerance is NaN (use a negative value for automatic)");
  if constexpr (ScalarTraits<T>::isExact) {
    return detail::mddChecked(P, poseP, Q, poseQ, s, cache, options);
  } else {
    // Any non-zero length of s is allowed: scale it by a power of two (exact) to unit
    // order, so that |s|^2 and the products with s neither overflow nor underflow, and
    // scale the parameter back (parameter * s is unchanged).
    using std::ilogb;
    using std::ldexp;
    const int e = ilogb(s.cwiseAbs().maxCoeff());
    Vec3<T> su(ldexp(s[0], -e), ldexp(s[1], -e), ldexp(s[2], -e));
    // A component below the unit roundoff of the largest tilts the line by less than the
    // rounding of any product with s, but it made the 2-D centre-of-duality test call a
    // grazing line (tilted by 1e-21) interior, with c on the boundary of M: it is
    // dropped, and the answer is the one for a direction within one rounding of s.
    for (int i = 0; i < 3; ++i)
      if (detail::absValue(su[i]) < ScalarTraits<T>::epsilon()) su[i] = T(0);
    MddResult<T> r = detail::mddChecked(P, poseP, Q, poseQ, su, cache, options);
    r.parameter = ldexp(r.parameter, -e);
    return r;
  }
}

/// mdd() without a coherence cache (allocates its small work buffers per call).
template <class T>
MddResult<T> mdd(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                 const Pose<T>& poseQ, const Vec3<T>& s, const MddOptions<T>& options = {}) {
  MddCache<T> cache;
  return mdd(P, poseP, Q, poseQ, s, cache, options);
}

/// Collision mode (section V): do P and Q (closed sets) share a point? Touching counts.
/// The centre of duality is any interior point of M: interior(P) − interior(Q); the
/// search towards the origin stops at the first face with the origin strictly outside.
/// Throws InvalidInput for non-finite / non-orthonormal poses. Should a search ever hit
/// its cap, the answer is `true` (the conservative one for collision detection).
template <class T>
bool intersects(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                const Pose<T>& poseQ, MddCache<T>& cache) {
  const detail::RelativePose<T> rel = detail::relativePose(P, poseP, Q, poseQ, cache);
  const Mat3<T>& R = rel.R;
  const Vec3<T>& t = rel.t;
  detail::PairFrame<T> F(P, Q, R, t, true);
  const Vec3<T> x0 = P.interiorPoint() - (R * Q.interiorPoint() + t);
  if (x0 == Vec3<T>::Zero()) return true;
  MddResult<T> res;
  MddOptions<T> options;
  detail::MddQuery<T> query(F, x0, cache, options, res);
  bool separated = false;
  detail::MFace<T> separator;
  // The search direction at unit order (exact scaling, and the searches compare ratios
  // homogeneous in it): for shapes of 1e-224, x0 times the faces' offsets underflowed and
  // the searches' comparisons were all false (overlap reported for shapes apart).
  const Vec3<T> towards = detail::unitOrder(Vec3<T>(-x0));
  detail::MFace<T> f = query.exitFace(towards, x0, true, &separated, &separator);
  if (separated) {
    if constexpr (ScalarTraits<T>::isExact) {
      return false;
    } else {
      // "Apart" is certified by the separating-axis test along the stopping face's normal
      // N: the support of M along N, from support queries (not from the face's own k,
      // which is only as good as the face: an EE face declared by rounding had a plane
      // through the origin and k = -9e-236, for shapes overlapping by 2e25), must be
      // below -tolerance. Otherwise the search is run to its end.
      const Vec3<T> N = separator.N;
      const int vp = F.supportP(N, cache.vertexP), vq = F.supportMinusQ(N, cache.vertexQ);
      const T h = N.dot(P.vertex(vp) - F.q(vq));
      if (h < -query.tolerance() * N.norm()) return false;
      f = query.exitFace(towards, x0);
    }
  }
  if (!f.valid()) return true;
  // Exit parameter along x0 (x0 itself is at 1): the origin is in M iff it is <= 0.
  const T param = f.k / f.N.dot(x0);
  T tol = T(0);
  if constexpr (!ScalarTraits<T>::isExact) tol = query.tolerance() / x0.norm();
  return param <= tol;
}

template <class T>
bool intersects(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                const Pose<T>& poseQ) {
  MddCache<T> cache;
  return intersects(P, poseP, Q, poseQ, cache);
}

}  // namespace mink
