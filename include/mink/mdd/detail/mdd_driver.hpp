// mink/mdd/detail/mdd_driver.hpp — one mdd() query as named steps (MDD-DUAL, Choi et al.):
//   1. cached(): the faces that ended the last query of the pair, if they still bound the
//      line (frame coherence, section VI-E; detail/cached_exit.hpp);
//   2. the centre of duality (section IV-A, detail/centre_of_duality.hpp): the line misses
//      M (noContact), grazes it (fromGrazing), or c strictly inside M is found;
//   3. fromInterior(): the exit face towards the origin first (detail/exit_face.hpp); if
//      the origin is inside M, the other exit too, and the nearer one (section III-C),
//      unless the first is nearer than c, which the other exit is beyond;
//   4. fromChord(): the last resort when no search can answer (detail/mdd_fallbacks.hpp);
//   5. finish(): status, distance, translation and witnesses of the exit face.
// Everything runs in P's frame (PairFrame); results are reported in the world frame.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "mink/core/defaults.hpp"
#include "mink/mdd/detail/cached_exit.hpp"
#include "mink/mdd/detail/centre_of_duality.hpp"
#include "mink/mdd/detail/mdd_fallbacks.hpp"
#include "mink/mdd/detail/relative_pose.hpp"

namespace mink {
namespace detail {

/// mdd() for a direction already checked (and, for inexact T, scaled to unit order).
template <class T>
class MddDriver {
 public:
  MddDriver(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q, const Pose<T>& poseQ,
            const Vec3<T>& s, MddCache<T>& cache, const MddOptions<T>& options, bool bothExits = false)
      : P_(P),
        Q_(Q),
        poseP_(poseP),
        poseQ_(poseQ),
        s_(s),
        cache_(cache),
        options_(options),
        rel_(relativePose(P, poseP, Q, poseQ, cache)),
        sl_(rel_.directionToLocal(s)),
        F_(P, Q, rel_.R, rel_.t, options.useHierarchy),
        search_(F_, sl_, cache, options, res_),
        check_(search_.check()),
        fallbacks_(search_, cache, F_),
        slen_(lengthOf(s)),
        bothExits_(bothExits || cache.exitFaces[0].type != MddFaceType::None ||
                   cache.exitFaces[1].type != MddFaceType::None) {}

  MddResult<T> run() {
    if (cached()) return res_;
    int hp = cache_.vertexP, hq = cache_.vertexQ;
    const CentreOfDuality<T> cd = centreOfDuality(F_, sl_, hp, hq);
    cache_.vertexP = hp;
    cache_.vertexQ = hq;
    using Kind = typename CentreOfDuality<T>::Kind;
    if (cd.kind == Kind::Outside) {
      // The separating direction and its support vertices: why the line misses (and what
      // mddExact certifies a NoContact with).
      res_.normal = rel_.directionToWorld(cd.w);  // w . (RPt s) == (RPt^T w) . s: still orthogonal to s
      if constexpr (!ScalarTraits<T>::isExact) {
        const T len = res_.normal.stableNorm();
        if (len > T(0)) res_.normal /= len;
      }
      res_.featureP = hp;
      res_.featureQ = hq;
      return noContact();
    }
    if (cd.kind == Kind::Limit) return fromChord();
    if (cd.kind == Kind::Boundary) return fromGrazing(cd.w);
    return fromInterior(cd);
  }

  /// c = α s strictly inside M: the exit towards the origin first (it decides separated:
  /// the exit is the answer), then, the origin inside M, the exit the other way and the
  /// nearer of the two (d_min, section III-C).
  const MddResult<T>& fromInterior(const CentreOfDuality<T>& cd) {
    const Vec3<T>& c = cd.c;
    const T alphaNum = c.dot(sl_);  // sign of alpha
    // Towards the origin first: it decides separated (the exit is the answer) or not.
    const Vec3<T> first = alphaNum > T(0) ? Vec3<T>(-sl_) : Vec3<T>(sl_);
    const MFace<T> f1 = search_.exitFace(first, c);
    if (!f1.valid()) return fromChord();
    // An exit face whose plane holds the line to rounding: c is on M's boundary, not
    // inside it, and the line grazes M along that face.
    if (check_.lineInPlane(f1)) return fromGrazing(f1.N);
    const T t1 = f1.k / f1.N.dot(sl_);
    record(f1);
    const bool originInside = alphaNum > T(0) ? t1 < T(0) : (alphaNum < T(0) ? t1 > T(0) : true);
    if (!originInside) {
      res_.status = MddStatus::Separated;
      return finish(t1);
    }
    // Penetrating (or touching). The exit the other way is beyond c (c is strictly inside
    // M), at |t2| > |α|: where |t1| < |α|, f1 is the nearer exit and the second search is
    // not needed (for inexact T, by more than the facet check's slack, so that rounding
    // in t1 cannot swap the two or their tie). Only for a pair with no kept faces (a
    // one-off query): a pair queried again keeps both ends, which lets the next query of
    // a resting or slowly moving contact be answered by cached().
    if (!bothExits_ && firstIsNearer(t1, alphaNum) && centreIsDeep(cd, alphaNum)) {
      res_.status = MddStatus::Penetrating;
      if constexpr (!ScalarTraits<T>::isExact) {
        if (touchesToRounding(f1)) return finish(T(0));
      }
      return finish(t1);
    }
    // Else the exit the other way, then the nearer one (d_min).
    const MFace<T> f2 = search_.exitFace(Vec3<T>(-first), c);
    if (!f2.valid()) return fromChord();
    if (check_.lineInPlane(f2)) return fromGrazing(f2.N);
    const T t2 = f2.k / f2.N.dot(sl_);
    res_.status = MddStatus::Penetrating;
    if constexpr (!ScalarTraits<T>::isExact) {
      for (const MFace<T>* f : {&f1, &f2})
        if (touchesToRounding(*f)) return finish(T(0));
    }
    // Tie: the exit along +s is reported.
    const bool takeSecond = absValue(t2) < absValue(t1) ||
                            (absValue(t2) == absValue(t1) && t2 > t1);
    if (takeSecond) {
      record(f2);
      return finish(t2);
    }
    // f1's witnesses were overwritten by the second facet check: recompute them.
    // (f1 may have been accepted by its own polygon, faceHit, which the facet check with
    // its support sets can then miss by rounding.)
    if (!check_.facetHit(f1)) check_.faceHit(f1);
    record(f1);
    return finish(t1);
  }

 private:
  Vec3<T> toWorld(const Vec3<T>& x) const {
    return rel_.identityP ? Vec3<T>(x + poseP_.translation) : Vec3<T>(poseP_.rotation * x + poseP_.translation);
  }

  const MddResult<T>& noContact() {
    res_.status = MddStatus::NoContact;
    res_.faceType = MddFaceType::None;
    if constexpr (std::numeric_limits<T>::has_infinity) {
      res_.distance = res_.translation = res_.parameter = std::numeric_limits<T>::infinity();
    }
    return res_;
  }

  /// |t1| < |α| for the exit t1 = f1.k / (f1.N·s) and the centre c = α s (alphaNum = c·s):
  /// exactly for exact T; for inexact T by more than the facet check's slack along s.
  bool firstIsNearer(const T& t1, const T& alphaNum) const {
    const T ss = sl_.squaredNorm();
    if constexpr (ScalarTraits<T>::isExact) {
      return absValue(t1) * ss < absValue(alphaNum);
    } else {
      const T alpha = alphaNum / ss;
      return (absValue(alpha) - absValue(t1)) * std::sqrt(ss) > check_.slack();
    }
  }

  /// Is the line's point at c's parameter α inside M, so that the exit beyond c is at
  /// |t2| ≥ |α|? Exact T: c is (exactly on the line and strictly inside M). Inexact T: c
  /// is computed as a convex combination of points of M with weight w0 on x0, around
  /// which a ball of radius D = interiorDepth(P) + interiorDepth(Q) lies in M; so a ball
  /// of radius w0·D around that exact combination does, and the line's point α s is
  /// within |c − α s| (c's distance to the line) plus the rounding of c of it. The
  /// rounding is bounded by the facet check's slack. A centre lifted near M's boundary
  /// (w0 tiny: c close to the facet through the support points) is no proof: the exit
  /// beyond it may be nearer than α by the rounding of c over the sine at which the line
  /// meets that facet.
  bool centreIsDeep(const CentreOfDuality<T>& cd, const T& alphaNum) const {
    if constexpr (ScalarTraits<T>::isExact) {
      return true;
    } else {
      if (!(cd.weightX0 > T(0))) return false;
      const T depth = P_.interiorDepth() + Q_.interiorDepth();
      // |offLine| ≤ 2 max |component| (no underflow in a scene of 1e-224).
      const Vec3<T> offLine = cd.c - (alphaNum / sl_.squaredNorm()) * sl_;
      return cd.weightX0 * depth > T(2) * offLine.cwiseAbs().maxCoeff() + T(2) * check_.slack();
    }
  }

  /// The origin, inside M, within the rounding slack of the supporting plane of an exit
  /// face f that the line meets at a grazing angle: it is that close to M's boundary, so
  /// P and Q touch to rounding; f is recorded and true returned. Said so (0), rather than
  /// through that face's k / (N·s), rounding over a tiny N·s (a 6e59 scene: 1.9e56 where
  /// the other exit was 2e-11). A face met at a larger angle gives an accurate k / (N·s).
  bool touchesToRounding(const MFace<T>& f) {
    if (check_.wellConditioned(f) || !(absValue(f.k) <= check_.slack() * f.N.norm())) return false;
    if (!check_.facetHit(f)) check_.faceHit(f);  // its support sets and witnesses
    record(f);
    return true;
  }

  /// No answer within the caps: IterationLimit, with NaN distance, translation and
  /// parameter for floating-point T (never a value a caller could take for a contact);
  /// exact T has no NaN and leaves them 0.
  const MddResult<T>& iterationLimit() {
    res_.status = MddStatus::IterationLimit;
    res_.path = MddPath::None;
    res_.faceType = MddFaceType::None;
    if constexpr (std::numeric_limits<T>::has_quiet_NaN) {
      res_.distance = res_.translation = res_.parameter = std::numeric_limits<T>::quiet_NaN();
    }
    return res_;
  }

  /// The answer at line parameter `param` (of s): translation, witnesses, status.
  const MddResult<T>& finish(const T& param) {
    res_.parameter = param;
    res_.translation = param * slen_;
    // witnessP − witnessQ = parameter · s by construction where one side of the facet is
    // a single vertex (FV, VF): the other witness is that vertex moved by the motion.
    // Barycentric weights in a sliver fan triangle of the face would leave it 1e-5 off.
    if constexpr (!ScalarTraits<T>::isExact) {
      if (res_.faceType == MddFaceType::EE && res_.featureP >= 0 && res_.featureQ >= 0 && !check_.edgePairSolved()) {
        // An EE face is a parallelogram e_P − e_Q, as long and thin as its edges are
        // unequal (a 3-unit edge against a 1e12 one): its fan triangles' barycentric
        // weights are ill-conditioned there. Solve p0 + λ dp − (q0 + μ dq) = param s in
        // the face's plane directly instead (Lagrange's identity; the edges are not
        // parallel, or the face would not exist). Not where the facet check solved the
        // same two edge parameters already (its four exact side signs put the line inside
        // the parallelogram: FacetCheck::insideParallelogram).
        const auto ep = P_.edgeVertices(res_.featureP);
        const auto eq = Q_.edgeVertices(res_.featureQ);
        const Vec3<T> p0 = toWorld(P_.vertex(ep.first)), dp = toWorld(P_.vertex(ep.second)) - p0;
        const Vec3<T> q0 = poseQ_.rotation * Q_.vertex(eq.first) + poseQ_.translation;
        const Vec3<T> dq = poseQ_.rotation * Vec3<T>(Q_.vertex(eq.second) - Q_.vertex(eq.first));
        // lambda and mu are ratios of degree 0 in lengths: solved in the query's 2^e units
        // (scene far from unit order), where |N|^2, of degree 4, neither underflows nor
        // overflows.
        const Vec3<T> dpu = check_.inUnits(dp), dqu = check_.inUnits(dq);
        const Vec3<T> N = dpu.cross(dqu), d = check_.inUnits(Vec3<T>(param * s_ - (p0 - q0)));
        const T n2 = N.squaredNorm();
        if (n2 > T(0) && std::isfinite(n2)) {
          const T lambda = N.dot(d.cross(dqu)) / n2, mu = -N.dot(dpu.cross(d)) / n2;
          // Only where the line crosses this parallelogram (not a coplanar neighbour of
          // the facet that the facet check accepted).
          const T slack = T(defaults::kMddEdgeWitnessSlack);
          if (lambda >= -slack && lambda <= T(1) + slack && mu >= -slack && mu <= T(1) + slack) {
            res_.witnessP = p0 + std::min(T(1), std::max(T(0), lambda)) * dp;
            res_.witnessQ = q0 + std::min(T(1), std::max(T(0), mu)) * dq;
          }
        }
      }
      const Vec3<T> r = res_.witnessP - res_.witnessQ - param * s_;
      if (cache_.setQ.size() == 1 && cache_.setP.size() > 1) res_.witnessP -= r;
      if (cache_.setP.size() == 1 && cache_.setQ.size() > 1) res_.witnessQ += r;
      // Both sides spans (or a single pair) and the witnesses still off the motion: the
      // line met the facet at a grazing angle, where locating its crossing along s is
      // ill-conditioned (0.52 off on a face met at a sine of 1.5e-11). The contact point
      // param * s is located in the facet's own plane instead.
      const Vec3<T> r2 = res_.witnessP - res_.witnessQ - param * s_;
      // Only if the contact point lies on that facet: where the parameter itself is off
      // along a grazing line (1e-7 of a 1e26 scene), the crossing found along s, on the
      // line and on the facet, is the better pair.
      if (res_.faceType != MddFaceType::Grazing && check_.inUnits(r2).norm() > check_.slackUnits(check_.slack()) &&
          check_.witnessesAt(Vec3<T>(param * sl_), rel_.directionToLocal(res_.normal))) {
        res_.witnessP = toWorld(check_.witnessP());
        res_.witnessQ = toWorld(check_.witnessQ());
      }
    }
    if (absValue(res_.translation) <= check_.tolerance()) {
      res_.status = MddStatus::Touching;
      res_.distance = T(0);
    } else if (res_.status != MddStatus::Penetrating) {
      res_.status = MddStatus::Separated;
      res_.distance = absValue(res_.translation);
    } else {
      res_.distance = -absValue(res_.translation);
    }
    return res_;
  }

  /// The exit face f's type, features, normal and witnesses into the result.
  void record(const MFace<T>& f) {
    res_.faceType = f.type;
    res_.featureP = f.a;
    res_.featureQ = f.b;
    res_.normal = unitOrExact(rel_.directionToWorld(f.N));
    res_.witnessP = toWorld(check_.witnessP());
    res_.witnessQ = toWorld(check_.witnessQ());
  }

  /// Frame coherence (detail/cached_exit.hpp): the faces that ended the last query, if
  /// they still bound the line, give the answer (true).
  bool cached() {
    const CachedExit<T> c = cachedExit(search_, cache_, sl_, res_);
    if (!c.face.valid()) return false;
    record(c.face);
    res_.status = c.status;
    res_.fromCache = true;
    res_.path = MddPath::Cache;
    finish(c.parameter);
    return true;
  }

  /// The last resort (inexact T) when a search cannot answer: no face passed its facet
  // check (a line grazing M within the rounding of c), or, with the automatic caps, a
  // cap was hit (shapes far below the rounding of their distance, 100 apart 1e20 along
  // s, round M to a few points). The chord of M along the line, by clipping it against
  // every face plane, answers; it needs no centre of duality. A cap the caller set
  // (options.maxVisits) is respected: IterationLimit; so is the cap on the edge pairs the
  // chord visits (options.maxExhaustivePairs).
  const MddResult<T>& fromChord() {
    if constexpr (!ScalarTraits<T>::isExact) {
      if (search_.exhaustiveAllowed() && (search_.checkFailed() || options_.maxVisits < 0)) {
        res_.usedFallback = true;  // the chord visits every edge pair
        res_.path = MddPath::Chord;
        MFace<T> lo, hi;
        T tlo = T(0), thi = T(0);
        if (!fallbacks_.chord(tlo, thi, lo, hi)) return noContact();
        const MFace<T>* answer = &hi;
        T tAns = thi;
        if (tlo > T(0)) {
          answer = &lo, tAns = tlo;
          res_.status = MddStatus::Separated;
        } else if (thi < T(0)) {
          res_.status = MddStatus::Separated;
        } else {
          if (absValue(tlo) < absValue(thi)) answer = &lo, tAns = tlo;  // tie: +s
          res_.status = MddStatus::Penetrating;
        }
        fallbacks_.nearestWitnesses(*answer);
        record(*answer);
        // The witnesses are the facet's point nearest the line; at a grazing angle the
        // contact's place along the line is ill-conditioned, so it is read off them (a
        // face met at a sine of 5e-12: 0.92 by its plane, 0.50 by its facet, 2.6e-12 from
        // the line). A face met at a larger angle has an accurate crossing: read off its
        // facet only where that reaches the line, to the slack. One it misses (by 1.4 on
        // a needle's M, the line meeting facets lost to rounding) says nothing about the
        // contact; the plane's crossing stands, the witnesses are the nearest point of any
        // facet to it.
        const Vec3<T> d = check_.witnessP() - check_.witnessQ();
        const T ss = sl_.squaredNorm();
        if (ss > T(0)) {
          const T tW = d.dot(sl_) / ss;
          if (!check_.wellConditioned(*answer) ||
              check_.inUnits(Vec3<T>(d - tW * sl_)).norm() <= check_.slackUnits(check_.slack())) {
            tAns = tW;
          } else {
            T best = check_.inUnits(Vec3<T>(d - tAns * sl_)).norm();
            if (fallbacks_.nearestFacetPoint(Vec3<T>(tAns * sl_), best)) {
              res_.witnessP = toWorld(check_.witnessP());
              res_.witnessQ = toWorld(check_.witnessQ());
            }
          }
        }
        return finish(tAns);
      }
    }
    return iterationLimit();
  }

  // The line lies in the supporting plane w·x = k of M (k = 0 up to rounding): it meets
  // M only in that plane's facet, in [tlo, thi] (case 2 of section IV-A).
  const MddResult<T>& fromGrazing(const Vec3<T>& wIn) {
    // To unit order: w's norm scales the support sets' slack.
    const Vec3<T> w = unitOrder(wIn);
    res_.path = MddPath::Grazing;
    T tlo, thi;
    int vp, vq;
    if (!fallbacks_.grazing(w, tlo, thi, vp, vq)) return noContact();
    res_.faceType = MddFaceType::Grazing;
    res_.featureP = vp;
    res_.featureQ = vq;
    res_.normal = unitOrExact(rel_.directionToWorld(w));
    const T param = (tlo <= T(0) && thi >= T(0)) ? T(0) : (tlo > T(0) ? tlo : thi);
    // Witnesses: the contact is on the facet; report the support vertices' pair moved
    // onto the line (exact contact points need the segment, which a caller rarely uses).
    res_.witnessP = toWorld(P_.vertex(vp));
    res_.witnessQ = res_.witnessP - param * s_;
    res_.status = MddStatus::Separated;
    return finish(param);
  }

  const ConvexPolyhedron<T>& P_;
  const ConvexPolyhedron<T>& Q_;
  const Pose<T>& poseP_;
  const Pose<T>& poseQ_;
  const Vec3<T> s_;
  MddCache<T>& cache_;
  const MddOptions<T>& options_;
  const RelativePose<T> rel_;
  const Vec3<T> sl_;  // s in P's frame
  PairFrame<T> F_;
  MddResult<T> res_;
  ExitFaceSearch<T> search_;
  FacetCheck<T>& check_;
  MddFallbacks<T> fallbacks_;
  const T slen_;  // |s|, for reporting
  // Search the second exit even where the first is provably the nearer one: mddExact
  // certifies the chord of M from both ends; a pair with kept faces (a coherent caller)
  // keeps both ends for cached().
  const bool bothExits_;
};

}  // namespace detail
}  // namespace mink
