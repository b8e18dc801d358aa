// mink/mdd/mdd.hpp — minimum directional distance between two convex polyhedra:
// MDD-DUAL (Y.-K. Choi, X. Li, F. Rong, W. Wang, S. Cameron, "Computing the Minimum
// Directional Distance between Two Convex Polyhedra").
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
//      III-C) and the nearer exit is reported — unless the first exit is nearer than c:
//      the other one lies beyond c.
// The line parameter of a face is t = k / (N·s): all decisions are signs of polynomials
// in the inputs, so with an exact rational T the result is exact.
//
// The steps live in detail/: relative_pose.hpp (poses), centre_of_duality.hpp (step 1),
// exit_face.hpp with exit_portal.hpp, search_fv.hpp and search_ee.hpp (step 2),
// facet_check.hpp (step 3), mdd_fallbacks.hpp (grazing lines and the chord of M),
// cached_exit.hpp (frame coherence: the last query's faces), and mdd_driver.hpp, which
// runs them in order for one query.
#pragma once

#include <cmath>
#include <limits>

#include "mink/mdd/detail/mdd_driver.hpp"

namespace mink {

namespace detail {
/// checkMddInput, poseP not checked again where it matches `checkedP` (a cache's pose
/// that passed before).
template <class T>
[[nodiscard]] Error checkMddInputKept(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                                      const Pose<T>& poseQ, const Vec3<T>& s, const MddOptions<T>& options,
                                      const CheckedPose<T>* checkedP) {
  for (int i = 0; i < 3; ++i)
    if (!ScalarTraits<T>::isFinite(s[i])) return Error("mdd: direction s is not finite");
  if (s == Vec3<T>::Zero()) return Error("mdd: direction s is zero");
  if (!(options.touchTolerance == options.touchTolerance))
    return Error("mdd: options.touchTolerance is NaN (use a negative value for automatic)");
  return checkPlacedPair(P, poseP, Q, poseQ, checkedP);
}
}  // namespace detail

/// The Error for input mdd(), mddExact() and firstContact() do not take, or none: a zero
/// or non-finite s, a NaN options.touchTolerance, a pose that is not a rigid placement, a
/// shape too thin for the Gauss-map tests in its scalar type. mdd() throws it as
/// InvalidInput (without exceptions: answers MddStatus::InvalidInput). Allocates nothing
/// when the input is fine.
template <class T>
[[nodiscard]] Error checkMddInput(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                                  const Pose<T>& poseQ, const Vec3<T>& s, const MddOptions<T>& options = {}) {
  return detail::checkMddInputKept<T>(P, poseP, Q, poseQ, s, options, nullptr);
}

namespace detail {

/// The answer to input that checkMddInput rejects: InvalidInput thrown, or (without
/// exceptions) the status InvalidInput with NaN distance, translation and parameter.
template <class T>
MddResult<T> invalidMddInput(const Error& error) {
#if MINK_EXCEPTIONS
  raise(error);
#else
  (void)error;
  MddResult<T> r;
  r.status = MddStatus::InvalidInput;
  r.path = MddPath::None;
  r.faceType = MddFaceType::None;
  if constexpr (std::numeric_limits<T>::has_quiet_NaN)
    r.distance = r.translation = r.parameter = std::numeric_limits<T>::quiet_NaN();
  return r;
#endif
}

/// mdd() with the input checked here; `bothExits` searches both exits of a penetrating
/// line even where the first is provably the nearer (mddExact certifies both ends).
template <class T>
MddResult<T> mddQuery(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                      const Pose<T>& poseQ, const Vec3<T>& s, MddCache<T>& cache, const MddOptions<T>& options,
                      bool bothExits) {
  if (Error e = checkMddInputKept(P, poseP, Q, poseQ, s, options, &cache.checkedPoseP)) return invalidMddInput<T>(e);
  if constexpr (ScalarTraits<T>::isExact) {
    return MddDriver<T>(P, poseP, Q, poseQ, s, cache, options, bothExits).run();
  } else {
    // Any non-zero length of s is allowed: scale it by a power of two (exact) to unit
    // order, so that |s|^2 and the products with s neither overflow nor underflow, and
    // scale the parameter back (parameter * s is unchanged).
    using std::ilogb;
    const int e = ilogb(s.cwiseAbs().maxCoeff());
    Vec3<T> su = timesPow2(s, -e);
    // A component below the unit roundoff of the largest tilts the line by less than the
    // rounding of any product with s, but it made the 2-D centre-of-duality test call a
    // grazing line (tilted by 1e-21) interior, with c on the boundary of M: it is
    // dropped, and the answer is the one for a direction within one rounding of s
    // (MddResult::directionRounded says so).
    bool rounded = false;
    for (int i = 0; i < 3; ++i)
      if (su[i] != T(0) && absValue(su[i]) < ScalarTraits<T>::epsilon()) su[i] = T(0), rounded = true;
    MddResult<T> r = MddDriver<T>(P, poseP, Q, poseQ, su, cache, options, bothExits).run();
    r.parameter = timesPow2(r.parameter, -e);
    r.directionRounded = rounded;
    return r;
  }
}

}  // namespace detail

/// Minimum directional distance between P (placed by poseP) and Q (placed by poseQ)
/// along s (world frame, any non-zero length): see MddResult for the
/// meaning, unit, frame and sign of every output. Throws InvalidInput for a zero or
/// non-finite s, a non-finite / non-orthonormal pose or a NaN touchTolerance
/// (checkMddInput); never throws otherwise. Built without exceptions, it answers
/// MddStatus::InvalidInput for such input instead.
/// `cache` (optional) carries frame coherence between queries of the same pair.
template <class T>
MddResult<T> mdd(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                 const Pose<T>& poseQ, const Vec3<T>& s, MddCache<T>& cache, const MddOptions<T>& options = {}) {
  return detail::mddQuery(P, poseP, Q, poseQ, s, cache, options, false);
}

/// mdd() without a coherence cache: the answer of a fresh MddCache (no hint from earlier
/// calls), with work buffers kept per thread (detail::scratchCache: no allocation once warm).
template <class T>
MddResult<T> mdd(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                 const Pose<T>& poseQ, const Vec3<T>& s, const MddOptions<T>& options = {}) {
  return mdd(P, poseP, Q, poseQ, s, detail::scratchCache<T>(), options);
}

}  // namespace mink

// MINK_EXTERN_TEMPLATES: the float / double instantiations are compiled elsewhere
// (src/mink_instantiations.cpp; see mink/extern_templates.hpp).
#include "mink/core/detail/instantiation_lists.hpp"
MINK_DETAIL_DECLARE_EXTERN(MDD)

#include "mink/mdd/intersects.hpp"
