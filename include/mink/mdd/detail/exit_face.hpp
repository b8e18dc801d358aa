// mink/mdd/detail/exit_face.hpp — the exit face: the face of M = P ⊕ −Q through which the
// ray c + u σ (u > 0, c strictly inside M) leaves M, step 2 of MDD-DUAL (Choi et al.,
// section IV-B): the maximum of σ·N / (k − N·c) over the faces of M (Lemma 1).
//
//   1. A face kept from the last query of the pair, or the exit-portal estimate
//      (detail/exit_portal.hpp): the EE face that a converged portal's corners name,
//      then the FV / VF faces best aligned with its normal at its support vertices, and
//      the EE faces of the edges whose arcs pass nearest it, are tried first; a
//      supporting plane whose facet the line crosses is the exit.
//   2. Else SEARCH-FV, SEARCH-VF, SEARCH-EE from those faces (detail/search_fv.hpp,
//      detail/search_ee.hpp), the answer accepted by the facet check (facet_check.hpp).
//   3. Else every face of M (exhaustive), within MddOptions::maxExhaustivePairs.
// Collision mode (earlyExit) starts from the paper's initial face (section VI-A) and stops
// at the first face that puts the origin outside M.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/mdd/detail/exit_portal.hpp"
#include "mink/mdd/detail/facet_check.hpp"
#include "mink/mdd/detail/search_ee.hpp"
#include "mink/mdd/detail/search_fv.hpp"

namespace mink {
namespace detail {

template <class T>
class ExitFaceSearch {
 public:
  ExitFaceSearch(const PairFrame<T>& F, const Vec3<T>& s, MddCache<T>& cache, const MddOptions<T>& opt,
                 MddResult<T>& res)
      : F_(F), s_(s), cache_(cache), res_(res), check_(F, s, cache, opt) {
    const ConvexPolyhedron<T>& P = F.P();
    const ConvexPolyhedron<T>& Q = F.Q();
    const long long faces = P.numFaces() + Q.numFaces() + 64;
    cap_ = opt.maxVisits >= 0 ? opt.maxVisits : defaults::kMddVisitFactor * faces;
    autoCap_ = opt.maxVisits < 0;
    const long long pairs = static_cast<long long>(P.numEdges()) * static_cast<long long>(Q.numEdges());
    exhaustiveAllowed_ = pairs <= (opt.maxExhaustivePairs >= 0 ? opt.maxExhaustivePairs : defaults::kMddExhaustivePairs);
  }

  /// The facet check of this query's line (its witnesses, slack and units).
  FacetCheck<T>& check() { return check_; }
  const FacetCheck<T>& check() const { return check_; }

  /// The face of M through which the ray c + u σ (u > 0) leaves M. Invalid on a cap.
  /// With `earlyExit` (collision mode), stops with an invalid face and `separated` set as
  /// soon as a face proves the origin outside M.
  ///
  /// Directional mode: the exit-portal estimate (exit_portal.hpp) names a normal close to
  /// the exit facet's (and, converged, corners on that facet: see tryAround); the FV and
  /// VF faces best aligned with it at its support vertices,
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
      const int side = sigma.dot(s_) > T(0) ? 0 : 1;  // the kept face on this side first
      for (int i = 0; i < 2 && est.vertexP < 0; ++i) {
        const MddCachedFace& kept = cache_.exitFaces[i == 0 ? side : 1 - side];
        const MFace<T> m = rebuild(kept);
        if (m.valid()) {
          if (!(obj.num(m) > T(0))) continue;
          est.normal = m.N;
          est.vertexP = m.type == MddFaceType::FV ? P.faceVertices(m.a)[0]
                        : m.type == MddFaceType::VF ? m.a : P.edgeVertices(m.a).first;
          est.vertexQ = m.type == MddFaceType::FV ? m.b
                        : m.type == MddFaceType::VF ? Q.faceVertices(m.b)[0] : Q.edgeVertices(m.b).first;
        } else {
          lostEdgePair(kept, obj, est);
        }
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
      if (!autoCap_ || !(obj.num(best) > T(0)) || !check_.exitHit(best)) return MFace<T>();
      cache_.faceP = best.type == MddFaceType::FV ? best.a : fv.a;
      return remember(best, MddPath::Search);
    }
    MddPath path = MddPath::Search;
    if (!(obj.num(best) > T(0)) || !check_.exitHit(best)) {
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

  /// A kept EE face whose two edges no longer form a face of M (their Gauss arcs stopped
  /// crossing as the pair moved: on a fine mesh that happens every few frames): the exit
  /// is still near them, so est starts there (their first vertices; the normal between
  /// the two arcs' midpoints, a + b − c − d for the unit face normals a, b of P's edge and
  /// c, d of Q's, in P's frame), instead of a cold portal. est is untouched when the kept
  /// face is not such a pair or that normal faces away from the ray.
  void lostEdgePair(const MddCachedFace& kept, const RayObjective<T>& obj, ExitPortal<T>& est) const {
    const ConvexPolyhedron<T>& P = F_.P();
    const ConvexPolyhedron<T>& Q = F_.Q();
    if (kept.type != MddFaceType::EE || kept.a < 0 || kept.a >= P.numEdges() || kept.b < 0 ||
        kept.b >= Q.numEdges())
      return;
    const auto fp = P.edgeFaces(kept.a);
    const auto fq = Q.edgeFaces(kept.b);
    const Vec3<T> n = P.faceNormal(fp.first) + P.faceNormal(fp.second) -
                      F_.qNormal(fq.first) - F_.qNormal(fq.second);
    if (!(n.dot(obj.sigma) > T(0))) return;
    est.normal = n;
    est.vertexP = P.edgeVertices(kept.a).first;
    est.vertexQ = Q.edgeVertices(kept.b).first;
  }

  /// The faces at the estimate's support vertices: the FV and VF faces best aligned with
  /// its normal (f0, g0: the searches' starts), then the EE faces of the edges there. `hit`
  /// is the first that the line crosses (faceHit), else invalid. False on the visit cap.
  bool tryAround(const ExitPortal<T>& est, const RayObjective<T>& obj, SearchBudget& budget, int& f0, int& g0,
                 MFace<T>& hit) {
    // A converged portal's corners are points of the exit facet: two vertices of P and
    // two of −Q among them name its EE face, tried first (certified as any other).
    int ep = -1, eq = -1;
    if (est.converged && cornerEdge(F_.P(), est.cornerP, ep) && cornerEdge(F_.Q(), est.cornerQ, eq)) {
      if (!budget.take()) return false;
      const MFace<T> m = F_.ee(ep, eq);
      if (m.valid()) {
        ++res_.visitedEE;
        if (obj.num(m) > T(0) && check_.certifies(m)) {
          hit = m;
          return true;
        }
      }
    }
    f0 = alignedFaceP(est.vertexP, est.normal);
    g0 = alignedFaceQ(est.vertexQ, est.normal);
    int hq = est.vertexQ, hp = est.vertexP;
    if (!budget.take() || !budget.take()) return false;
    const MFace<T> fv = F_.fv(f0, hq);
    const MFace<T> vf = F_.vf(g0, hp);
    res_.visitedFV += 1;
    res_.visitedVF += 1;
    const MFace<T> best = obj.better(vf, fv) ? vf : fv;
    if (obj.num(best) > T(0) && check_.certifies(best)) {
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
    if (obj.num(bestEE) > T(0) && obj.better(bestEE, best) && check_.certifies(bestEE))
      hit = bestEE;
    return true;
  }

  /// The edge of X joining the two distinct vertices among v[0..2] (e), if there are
  /// exactly two and they are adjacent.
  static bool cornerEdge(const ConvexPolyhedron<T>& X, const int* v, int& e) {
    int a = v[0], b = v[1] != a ? v[1] : v[2];
    if (b == a || (v[2] != a && v[2] != b)) return false;
    const auto nb = X.vertexNeighbors(a);
    const auto he = X.vertexHalfEdges(a);
    for (int i = 0; i < nb.size(); ++i)
      if (nb[i] == b) {
        e = X.heEdge(he[i]);
        return true;
      }
    return false;
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
    if (!best.valid() || check_.exitHit(best)) return best;
    // u_m − u_best ≤ slack(m) + slack(best), slack(x) = check_.slack() |N_x| / (N_x·σ); times
    // both (positive) numerators.
    const T nb = obj.num(best), db = obj.den(best), lb = FacetCheck<T>::norm(best.N);
    std::vector<std::pair<T, MFace<T>>>& ties = tiesScratch_;
    ties.clear();
    forEachFace([&](const MFace<T>& m) {
      const T nm = obj.num(m);
      if (!(nm > T(0))) return;
      const T gap = obj.den(m) * nb - db * nm;
      if (gap <= check_.slack() * (FacetCheck<T>::norm(m.N) * nb + lb * nm)) ties.push_back({obj.den(m) / nm, m});
    });
    std::sort(ties.begin(), ties.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& tie : ties)
      if (check_.exitHit(tie.second)) return tie.second;
    return MFace<T>();
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

 private:
  /// d1/√l1 > d2/√l2 without square roots (l1, l2 > 0).
  static bool cosineGreater(const T& d1, const T& l1, const T& d2, const T& l2) {
    if ((d1 >= T(0)) != (d2 >= T(0))) return d1 >= T(0);
    const T a = d1 * d1 * l2, b = d2 * d2 * l1;
    return d1 >= T(0) ? a > b : a < b;
  }
  /// Keeps the exit face in the cache by its side of the line (MddCache::exitFaces: [0]
  /// the exit along +s, [1] along −s; a penetrating query has both), to be certified
  /// first by the next query of the pair; `path` found f (the result keeps the costliest
  /// path of its exits).
  const MFace<T>& remember(const MFace<T>& f, MddPath path) {
    if (static_cast<int>(path) > static_cast<int>(res_.path)) res_.path = path;
    cache_.exitFaces[f.N.dot(s_) > T(0) ? 0 : 1] = MddCachedFace{f.type, f.a, f.b};
    return f;
  }

  const PairFrame<T>& F_;
  const Vec3<T> s_;  // the line's direction (P's frame)
  MddCache<T>& cache_;
  MddResult<T>& res_;
  FacetCheck<T> check_;
  long long cap_;
  std::vector<std::pair<T, MFace<T>>> tiesScratch_;
  bool checkFailed_ = false;
  bool exhaustiveAllowed_ = true;
  bool autoCap_ = true;  // the visit cap is the automatic one (MddOptions::maxVisits < 0)
};

}  // namespace detail
}  // namespace mink
