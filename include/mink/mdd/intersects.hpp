// mink/mdd/intersects.hpp — collision mode of MDD-DUAL (Choi et al., section V): do two
// placed convex polyhedra share a point? From an interior point of M = P ⊕ −Q towards the
// origin: the exit portal in collision mode, then (touching contacts) the exit-face search
// stopped at the first face that puts the origin outside.
#pragma once

#include "mink/mdd/detail/exit_face.hpp"
#include "mink/mdd/detail/relative_pose.hpp"

namespace mink {

/// The Error for input intersects() does not take, or none: a NaN options.touchTolerance,
/// a pose that is not a rigid placement, a shape too thin for the Gauss-map tests in its
/// scalar type. Allocates nothing when the input is fine.
template <class T>
[[nodiscard]] Error checkIntersectsInput(const ConvexPolyhedron<T>& P, const Pose<T>& poseP,
                                         const ConvexPolyhedron<T>& Q, const Pose<T>& poseQ,
                                         const MddOptions<T>& options = {});

namespace detail {

/// checkIntersectsInput, poseP not checked again where it matches `checkedP`.
template <class T>
[[nodiscard]] Error checkIntersectsInputKept(const ConvexPolyhedron<T>& P, const Pose<T>& poseP,
                                             const ConvexPolyhedron<T>& Q, const Pose<T>& poseQ,
                                             const MddOptions<T>& options, const CheckedPose<T>* checkedP) {
  if (!(options.touchTolerance == options.touchTolerance))
    return Error("intersects: options.touchTolerance is NaN (use a negative value for automatic)");
  return checkPlacedPair(P, poseP, Q, poseQ, checkedP);
}

/// intersects() on input that passed checkIntersectsInput.
template <class T>
bool intersectsChecked(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                       const Pose<T>& poseQ, MddCache<T>& cache, const MddOptions<T>& options) {
  const detail::RelativePose<T> rel = detail::relativePose(P, poseP, Q, poseQ, cache);
  const Mat3<T>& R = rel.R;
  const Vec3<T>& t = rel.t;
  detail::PairFrame<T> F(P, Q, R, t, options.useHierarchy);
  const Vec3<T> x0 = P.interiorPoint() - (R * Q.interiorPoint() + t);
  if (x0 == Vec3<T>::Zero()) return true;
  // The search direction at unit order (exact scaling, and the searches compare ratios
  // homogeneous in it): for shapes of 1e-224, x0 times the faces' offsets underflowed and
  // the searches' comparisons were all false (overlap reported for shapes apart).
  const Vec3<T> towards = detail::unitOrder(Vec3<T>(-x0));
  // 1. The exit portal in collision mode (MPR): a handful of support queries settle all
  //    but touching contacts; "inside" by exact predicates, "apart" by a separating axis
  //    beyond the touch tolerance, the same certificate as step 2's.
  {
    const T tol = detail::touchToleranceOf(F, options);
    const detail::ExitPortal<T> portal = detail::exitPortal(F, x0, towards, cache.vertexP, cache.vertexQ, &tol);
    if (portal.verdict == detail::ExitPortal<T>::Verdict::Inside) return true;
    if (portal.verdict == detail::ExitPortal<T>::Verdict::Outside) return false;
  }
  // 2. Else (touching within the tolerance, a degenerate portal, its cap) the paper's
  //    searches towards the origin.
  MddResult<T> res;
  detail::ExitFaceSearch<T> query(F, x0, cache, options, res);
  bool separated = false;
  detail::MFace<T> separator;
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
      if (h < -query.check().tolerance() * N.norm()) return false;
      f = query.exitFace(towards, x0);
    }
  }
  if (!f.valid()) return true;
  // Exit parameter along x0 (x0 itself is at 1): the origin is in M iff it is <= 0.
  const T param = f.k / f.N.dot(x0);
  T tol = T(0);
  if constexpr (!ScalarTraits<T>::isExact) tol = query.check().tolerance() / x0.norm();
  return param <= tol;
}

}  // namespace detail

/// Collision mode (section V): do P and Q (closed sets) share a point? Touching counts.
/// The centre of duality is any interior point of M: interior(P) − interior(Q). The exit
/// portal towards the origin (MPR, detail/exit_portal.hpp) answers first; where it cannot
/// (touching within the tolerance), the search towards the origin stops at the first face
/// with the origin strictly outside.
/// Options as for mdd(): shapes within `touchTolerance` (a length; automatic by default)
/// count as touching, hence intersecting (the portal says "apart" only beyond it);
/// `maxVisits` / `maxExhaustivePairs` cap the search after the portal, and a search that
/// hits a cap answers `true` (the conservative answer for collision detection);
/// `useHierarchy` as in mdd(). Throws InvalidInput for non-finite / non-orthonormal poses
/// and a NaN touchTolerance (checkIntersectsInput; without exceptions, prints its message
/// and aborts: use tryIntersects there).
template <class T>
Error checkIntersectsInput(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                           const Pose<T>& poseQ, const MddOptions<T>& options) {
  return detail::checkIntersectsInputKept<T>(P, poseP, Q, poseQ, options, nullptr);
}

template <class T>
bool intersects(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                const Pose<T>& poseQ, MddCache<T>& cache, const MddOptions<T>& options = {}) {
  detail::raiseIf(detail::checkIntersectsInputKept(P, poseP, Q, poseQ, options, &cache.checkedPoseP));
  return detail::intersectsChecked(P, poseP, Q, poseQ, cache, options);
}

/// intersects() without exceptions: the answer, or the Error for input it does not take.
template <class T>
Result<bool> tryIntersects(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                           const Pose<T>& poseQ, MddCache<T>& cache, const MddOptions<T>& options = {}) {
  if (Error e = detail::checkIntersectsInputKept(P, poseP, Q, poseQ, options, &cache.checkedPoseP)) return e;
  return detail::intersectsChecked(P, poseP, Q, poseQ, cache, options);
}

/// intersects() without a coherence cache (detail::scratchCache: a fresh cache's answer).
template <class T>
bool intersects(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                const Pose<T>& poseQ, const MddOptions<T>& options = {}) {
  return intersects(P, poseP, Q, poseQ, detail::scratchCache<T>(), options);
}

/// tryIntersects() without a coherence cache (detail::scratchCache).
template <class T>
Result<bool> tryIntersects(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                           const Pose<T>& poseQ, const MddOptions<T>& options = {}) {
  return tryIntersects(P, poseP, Q, poseQ, detail::scratchCache<T>(), options);
}

}  // namespace mink

// MINK_EXTERN_TEMPLATES: the float / double instantiations are compiled elsewhere
// (src/mink_instantiations.cpp; see mink/extern_templates.hpp).
#include "mink/core/detail/instantiation_lists.hpp"
MINK_DETAIL_DECLARE_EXTERN(INTERSECTS)
