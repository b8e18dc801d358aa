// benchmarks/peers.hpp — the peers mink's MDD is measured against, as adapters that answer
// (or approximate) the same directional question on the same inputs. Benchmark-only code:
// it links libccd, FCL and Bullet, which the library headers never see.
//
// Conventions (as mink::mdd): P at poseP, Q at poseQ, direction s in the world frame;
// M = P ⊕ −Q; the exact answer is the endpoint nearer 0 of [t_lo, t_hi] = {t : t s ∈ M},
// as a signed length along s/|s| applied to Q.
//
// Support functions. libccd and Bullet take the support mapping from the caller, so they
// get the same one mink uses (mink::extremeVertex on the same ConvexPolyhedron): a
// Dobkin–Kirkpatrick hierarchy for shapes that have one (>= kHierarchyMinVertices), else a
// hill-climb from the vertex the previous support call of the same query returned (vertex
// 0 at the start of a query). The comparison then measures the algorithms, not the
// support code. FCL's fcl::Convexd uses its own support (a scan, or a neighbour walk on
// larger meshes), which is what a planner calling FCL gets.
//
// The adapters:
//   CcdPair::gjkIntersect  ccdGJKIntersect: yes/no only, the floor of any query.
//   CcdPair::mprDirectional  ccdMPRPenetration with its centre functions set so that the
//       portal's interior point v0 = centre1 − centre2 lies on the line {t s}: centre1 =
//       centroid(P), centre2 = centroid(P) − α s, so v0 = α s. Call 1 uses α s = the
//       projection of centroid(P) − centroid(Q) (a point inside M) onto the line; that is
//       inside M in the usual case but not guaranteed (no cheap peer-side test exists;
//       wrong classifications are counted). MPR's ray from v0 through the origin leaves M
//       beyond the origin: the line meets the final portal's plane at t1 = k / (n·s),
//       n the portal normal (the direction of MPR's last support call, which libccd takes
//       along the portal normal), k = n·v for the portal vertices (found among the recorded
//       support points as the three that share n·v). If MPR reports overlap, call 2 starts
//       from v0 = (t1/2) s, on the segment from the origin to that exit, hence inside M,
//       and gives the other exit t2. Answer: the nearer of t1, t2. Separated pairs: MPR
//       stops as soon as it proves the origin outside M, so it has no directional value.
//       Reading the portal (an O(#support calls) scan) is not timed: with access to the
//       portal it would be O(1). mpr_tolerance: 1e-12 (MPR at its most accurate) and
//       libccd's default 1e-4, both measured.
//   fclSignedDistance  fcl::distance with enable_signed_distance on two fcl::Convexd
//       (GST_LIBCCD: GST_INDEP's signed distance can index contacts[-1] on Convex in FCL
//       0.7): Euclidean distance or EPA penetration depth, not a directional value; timed
//       only.
//   BulletCast::directional  btSubsimplexConvexCast or btGjkConvexCast: Q is pulled back
//       to −L ŝ (L = |centroid difference| + radius(P) + radius(Q) + 1 separates them
//       whatever s is) and cast to +L ŝ: the first hit is t_lo. If t_lo > 0 it is the
//       answer (separated along +s); no hit: NoContact. Otherwise a second cast from +L ŝ
//       to −L ŝ gives t_hi; t_hi < 0: separated along −s, else penetrating and the nearer
//       of t_lo, t_hi. Shapes have zero collision margin. The moving shape (Q) is the
//       cast's first shape, as in Bullet's own sweeps. btGjkConvexCast (conservative
//       advancement, at most 64 steps in double, stops within 0.001) often reports no hit
//       on these zero-margin polytopes where there is one: it is measured, but the
//       subsimplex cast is the Bullet peer of the targets.
#pragma once

#include <ccd/ccd.h>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionShapes/btConvexInternalShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkConvexCast.h>
#include <BulletCollision/NarrowPhaseCollision/btSubSimplexConvexCast.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <fcl/narrowphase/distance.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "mink/hierarchy/dk_hierarchy.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink_bench {

using Vec3d = Eigen::Vector3d;
using Mat3d = Eigen::Matrix3d;
using Poly = mink::ConvexPolyhedron<double>;
using PeerClock = std::chrono::steady_clock;

inline double microsSince(PeerClock::time_point t0) {
  return std::chrono::duration<double, std::micro>(PeerClock::now() - t0).count();
}

/// A placed shape with the shared support mapping (see the file comment).
struct PlacedShape {
  const Poly* shape = nullptr;
  bool hierarchy = false;  // the shape has a DK hierarchy: use it for every support call
  Mat3d R = Mat3d::Identity();
  Vec3d t = Vec3d::Zero();
  mutable int hint = 0;

  PlacedShape() = default;
  explicit PlacedShape(const Poly& p) : shape(&p), hierarchy(mink::hierarchyOf(p) != nullptr) {}

  void place(const Mat3d& rotation, const Vec3d& translation) {
    R = rotation;
    t = translation;
    hint = 0;
  }
  /// World-frame vertex maximising d·x.
  Vec3d support(const Vec3d& d) const {
    const Vec3d dl = R.transpose() * d;
    const int v = mink::extremeVertex(*shape, dl, hierarchy ? -1 : hint);
    hint = v;
    return R * shape->vertex(v) + t;
  }
  Vec3d centroid() const { return R * shape->interiorPoint() + t; }
};

/// Largest distance of a vertex from the vertex centroid (shape frame; pose-invariant).
inline double radiusAboutCentroid(const Poly& p) {
  double r = 0;
  for (int i = 0; i < p.numVertices(); ++i) r = std::max(r, (p.vertex(i) - p.interiorPoint()).norm());
  return r;
}

// ---------------------------------------------------------------------------------------
// libccd

/// One libccd body: a placed shape, the point its centre callback reports, and a record
/// of the support calls (for reading MPR's final portal after the call).
struct CcdBody {
  PlacedShape* placed = nullptr;
  Vec3d centre = Vec3d::Zero();
  struct Record {
    std::array<Vec3d, 256> dir, point;
    int count = 0;  // calls since clear(); entries beyond 256 overwrite the oldest
    void clear() { count = 0; }
    void push(const Vec3d& d, const Vec3d& p) {
      dir[count & 255] = d;
      point[count & 255] = p;
      ++count;
    }
  } record;
};

/// Support calls per libccd call beyond which the bench's support function answers the
/// zero vector for both bodies: libccd's MPR portal discovery and refinement loops have no
/// iteration cap (only its penetration phase honours max_iterations), and at
/// mpr_tolerance 1e-12 one P3-P3 query of a 10-orientation run looped forever. A zero
/// support point ends every MPR loop (its dot product with the direction is 0). Converging
/// calls here take a few dozen support calls.
constexpr int kCcdSupportCap = 4096;
/// libccd calls that reached kCcdSupportCap in this program (printed by the benchmarks).
inline long long& ccdSupportCapHits() {
  static long long n = 0;
  return n;
}

inline void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  CcdBody& b = *const_cast<CcdBody*>(static_cast<const CcdBody*>(obj));
  if (b.record.count >= kCcdSupportCap) {
    ++b.record.count;
    ccdVec3Set(out, 0.0, 0.0, 0.0);
    return;
  }
  const Vec3d d(dir->v[0], dir->v[1], dir->v[2]);
  const Vec3d p = b.placed->support(d);
  b.record.push(d, p);
  ccdVec3Set(out, p.x(), p.y(), p.z());
}

inline void ccdCentre(const void* obj, ccd_vec3_t* out) {
  const CcdBody& b = *static_cast<const CcdBody*>(obj);
  ccdVec3Set(out, b.centre.x(), b.centre.y(), b.centre.z());
}

/// libccd's MPR answer read as a directional distance.
struct MprAnswer {
  bool overlap = false;    // MPR (call 1) reported the shapes overlapping
  bool valueValid = false; // a directional value was read (overlap only)
  double translation = 0;  // signed length along s/|s| (nearer exit), when valueValid
  double perpendicular = 0;// libccd's own depth output of call 1 (perpendicular to its portal)
  int portalFallbacks = 0; // portal plane not found among the support points: value taken
                           // from depth·dir projected on s instead (libccd's touch/segment
                           // cases)
  double micros = 0;       // time of the ccdMPRPenetration calls (and their setup)
};

class CcdPair {
 public:
  /// mprTolerance: libccd's mpr_tolerance (its default is 1e-4; 1e-12 asks MPR for its
  /// most accurate answer).
  CcdPair(const Poly& P, const Poly& Q, double mprTolerance = 1e-12) : pP_(P), pQ_(Q) {
    a_.placed = &pP_;
    b_.placed = &pQ_;
    CCD_INIT(&ccd_);
    ccd_.support1 = ccdSupport;
    ccd_.support2 = ccdSupport;
    ccd_.center1 = ccdCentre;
    ccd_.center2 = ccdCentre;
    // libccd's default iteration cap (ULONG_MAX); its MPR loops are bounded by the
    // support-call cap instead (kCcdSupportCap).
    ccd_.mpr_tolerance = mprTolerance;
    ccd_.epa_tolerance = 1e-12;
    ccd_.dist_tolerance = 1e-12;
  }

  void place(const Mat3d& RP, const Vec3d& tP, const Mat3d& RQ, const Vec3d& tQ) {
    pP_.place(RP, tP);
    pQ_.place(RQ, tQ);
  }

  bool gjkIntersect() {
    pP_.hint = pQ_.hint = 0;
    a_.centre = pP_.centroid();
    b_.centre = pQ_.centroid();
    a_.record.clear();
    b_.record.clear();
    const bool hit = ccdGJKIntersect(&a_, &b_, &ccd_) != 0;
    if (a_.record.count > kCcdSupportCap) ++ccdSupportCapHits();
    return hit;
  }

  MprAnswer mprDirectional(const Vec3d& s) {
    MprAnswer out;
    const double s2 = s.squaredNorm();
    auto t0 = PeerClock::now();
    pP_.hint = pQ_.hint = 0;
    const Vec3d cP = pP_.centroid();
    const Vec3d c0 = cP - pQ_.centroid();
    const double alpha = c0.dot(s) / s2;
    ccd_real_t depth = 0;
    ccd_vec3_t dir, pos;
    a_.record.clear();
    b_.record.clear();
    a_.centre = cP;
    b_.centre = cP - alpha * s;
    const int r1 = ccdMPRPenetration(&a_, &b_, &ccd_, &depth, &dir, &pos);
    out.micros += microsSince(t0);
    if (a_.record.count > kCcdSupportCap) ++ccdSupportCapHits();
    if (r1 != 0) return out;
    out.overlap = true;
    out.perpendicular = depth;
    double t1 = 0;
    if (!readExit(s, depth, dir, t1)) ++out.portalFallbacks;
    t0 = PeerClock::now();
    pP_.hint = pQ_.hint = 0;
    a_.record.clear();
    b_.record.clear();
    b_.centre = cP - 0.5 * t1 * s;
    const int r2 = ccdMPRPenetration(&a_, &b_, &ccd_, &depth, &dir, &pos);
    out.micros += microsSince(t0);
    if (a_.record.count > kCcdSupportCap) ++ccdSupportCapHits();
    double t2 = t1;
    if (r2 == 0) {
      if (!readExit(s, depth, dir, t2)) ++out.portalFallbacks;
    }
    const double t = std::abs(t2) < std::abs(t1) ? t2 : t1;
    out.valueValid = true;
    out.translation = t * std::sqrt(s2);
    return out;
  }

 private:
  // The line parameter (multiples of s) where {t s} meets the plane of MPR's final portal.
  bool readExit(const Vec3d& s, double depth, const ccd_vec3_t& dir, double& t) const {
    const auto& ra = a_.record;
    const auto& rb = b_.record;
    const int n = std::min(ra.count, rb.count);
    if (n >= 4) {
      const int last = n - 1;
      const Vec3d nrm = ra.dir[last & 255].normalized();
      const int first = std::max(0, n - 256);
      double scale = 0;
      for (int i = first; i < last; ++i) scale = std::max(scale, (ra.point[i & 255] - rb.point[i & 255]).norm());
      const double tol = 1e-10 * (1.0 + scale);
      bool found = false;
      double best = -std::numeric_limits<double>::infinity();
      for (int i = first; i < last; ++i) {
        const double vi = nrm.dot(ra.point[i & 255] - rb.point[i & 255]);
        if (found && vi <= best) continue;
        int same = 0;
        for (int j = first; j < last; ++j)
          if (std::abs(nrm.dot(ra.point[j & 255] - rb.point[j & 255]) - vi) <= tol) ++same;
        if (same >= 3) {
          found = true;
          best = vi;
        }
      }
      const double ns = nrm.dot(s);
      if (found && ns != 0) {
        t = best / ns;
        return true;
      }
    }
    const Vec3d d(dir.v[0], dir.v[1], dir.v[2]);
    t = depth * d.dot(s) / s.squaredNorm();
    return false;
  }

  PlacedShape pP_, pQ_;
  CcdBody a_, b_;
  ccd_t ccd_;
};

// ---------------------------------------------------------------------------------------
// FCL

/// fcl::distance with signed distance (GST_LIBCCD, default tolerances). NaN when FCL throws
/// (its EPA does on some touching inputs, FCL issues #390, #493).
inline double fclSignedDistance(const fcl::Convexd& A, const Eigen::Isometry3d& ta, const fcl::Convexd& B,
                                const Eigen::Isometry3d& tb) {
  fcl::DistanceRequestd request(false, /*enable_signed_distance=*/true, 0.0, 0.0, 1e-6, fcl::GST_LIBCCD);
  fcl::DistanceResultd result;
  try {
    return fcl::distance(&A, ta, &B, tb, request, result);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

// ---------------------------------------------------------------------------------------
// Bullet

/// A btConvexShape whose support mapping is the shared one. Its shape type is
/// CUSTOM_CONVEX_SHAPE_TYPE, so Bullet's non-virtual support dispatch falls through to the
/// virtual localGetSupportingVertexWithoutMargin below.
class SupportShape : public btConvexInternalShape {
 public:
  explicit SupportShape(const Poly& p) : placed_(p) {
    m_shapeType = CUSTOM_CONVEX_SHAPE_TYPE;
    setMargin(0);
  }
  void resetHint() const { placed_.hint = 0; }

  btVector3 localGetSupportingVertexWithoutMargin(const btVector3& d) const override {
    const int v = mink::extremeVertex(*placed_.shape, Vec3d(d.x(), d.y(), d.z()),
                                      placed_.hierarchy ? -1 : placed_.hint);
    placed_.hint = v;
    const Vec3d& x = placed_.shape->vertex(v);
    return btVector3(x.x(), x.y(), x.z());
  }
  btVector3 localGetSupportingVertex(const btVector3& d) const override {
    return localGetSupportingVertexWithoutMargin(d);
  }
  void batchedUnitVectorGetSupportingVertexWithoutMargin(const btVector3* dirs, btVector3* out,
                                                         int n) const override {
    for (int i = 0; i < n; ++i) out[i] = localGetSupportingVertexWithoutMargin(dirs[i]);
  }
  void getAabb(const btTransform& t, btVector3& lo, btVector3& hi) const override { getAabbSlow(t, lo, hi); }
  void calculateLocalInertia(btScalar, btVector3& inertia) const override { inertia.setValue(0, 0, 0); }
  const char* getName() const override { return "mink_bench::SupportShape"; }

 private:
  mutable PlacedShape placed_;
};

struct CastAnswer {
  bool contact = false;    // some cast hit
  bool penetrating = false;
  double translation = 0;  // signed length along s/|s|
  int casts = 0;
};

/// Directional distance from convex casts (see the file comment). Cast: btGjkConvexCast or
/// btSubsimplexConvexCast.
template <class Cast>
class BulletCast {
 public:
  BulletCast(const Poly& P, const Poly& Q)
      : sP_(P), sQ_(Q), rP_(radiusAboutCentroid(P)), rQ_(radiusAboutCentroid(Q)), cP_(P.interiorPoint()),
        cQ_(Q.interiorPoint()) {}

  CastAnswer directional(const Mat3d& RP, const Vec3d& tP, const Mat3d& RQ, const Vec3d& tQ, const Vec3d& s) {
    CastAnswer out;
    const Vec3d u = s.normalized();
    const Vec3d gap = (RP * cP_ + tP) - (RQ * cQ_ + tQ);
    const double L = gap.norm() + rP_ + rQ_ + 1.0;
    const btTransform a = toBt(RP, tP);
    const btTransform qLo = toBt(RQ, tQ - L * u), qHi = toBt(RQ, tQ + L * u);
    double f = 0;
    ++out.casts;
    if (!cast(a, qLo, qHi, f)) return out;
    out.contact = true;
    const double tLo = -L + 2 * L * f;
    if (tLo > 0) {
      out.translation = tLo;
      return out;
    }
    ++out.casts;
    double g = 0;
    // A miss here cannot happen geometrically (the first cast hit); treat it as touching.
    const double tHi = cast(a, qHi, qLo, g) ? L - 2 * L * g : tLo;
    if (tHi < 0) {
      out.translation = tHi;
      return out;
    }
    out.penetrating = true;
    out.translation = std::abs(tHi) < std::abs(tLo) ? tHi : tLo;
    return out;
  }

 private:
  static btTransform toBt(const Mat3d& R, const Vec3d& t) {
    const btMatrix3x3 b(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
    return btTransform(b, btVector3(t.x(), t.y(), t.z()));
  }
  bool cast(const btTransform& a, const btTransform& from, const btTransform& to, double& fraction) {
    sP_.resetHint();
    sQ_.resetHint();
    btVoronoiSimplexSolver solver;
    // The moving shape first, as Bullet's own sweep tests call the casts
    // (btCollisionWorld::objectQuerySingle): btGjkConvexCast's final normal test assumes it.
    Cast c(&sQ_, &sP_, &solver);
    btConvexCast::CastResult result;
    const bool hit = c.calcTimeOfImpact(from, to, a, a, result);
    fraction = result.m_fraction;
    return hit && fraction <= 1.0;
  }

  SupportShape sP_, sQ_;
  double rP_, rQ_;
  Vec3d cP_, cQ_;
};

}  // namespace mink_bench
