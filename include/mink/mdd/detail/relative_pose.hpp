// mink/mdd/detail/relative_pose.hpp — the numeric preliminaries of an MDD query: the poses
// checked (finite, orthonormal to rounding, proper), Q's pose relative to P's (the query
// runs in P's frame), and |s| and unit normals for reporting (exact T has no sqrt).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "mink/mdd/detail/pair_frame.hpp"

namespace mink {
namespace detail {

/// The Error that names what is wrong with a pose that checkPose refuses.
template <class T>
[[nodiscard]] Error poseError(const Pose<T>& pose, const char* name) {
  for (int i = 0; i < 3; ++i) {
    if (!ScalarTraits<T>::isFinite(pose.translation[i]))
      return Error(std::string("mdd: ") + name + ".translation is not finite");
    if constexpr (!ScalarTraits<T>::isExact)
      if (absValue(pose.translation[i]) > ScalarTraits<T>::largestCoordinate())
        return Error(std::string("mdd: ") + name +
                     ".translation is out of range (above ScalarTraits::largestCoordinate())");
    for (int j = 0; j < 3; ++j)
      if (!ScalarTraits<T>::isFinite(pose.rotation(i, j)))
        return Error(std::string("mdd: ") + name + ".rotation is not finite");
  }
  // R^T R - I, symmetric: the six products of columns.
  T tol = T(0);
  if constexpr (!ScalarTraits<T>::isExact)
    tol = std::max(T(defaults::kRotationTolerance), T(100) * ScalarTraits<T>::epsilon());
  const Mat3<T>& R = pose.rotation;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      const T e = R(0, i) * R(0, j) + R(1, i) * R(1, j) + R(2, i) * R(2, j) - (i == j ? T(1) : T(0));
      if (absValue(e) > tol) return Error(std::string("mdd: ") + name + ".rotation is not orthonormal");
    }
  if (!(pose.rotation.determinant() > T(0)))
    return Error(std::string("mdd: ") + name + ".rotation is a reflection (determinant < 0)");
  return Error();
}

/// The Error for a pose that is not a rigid placement (non-finite, out of range, not
/// orthonormal to rounding, a reflection), or none. The same verdicts as poseError in one
/// pass and without the twelve finiteness tests: a NaN or infinite entry fails a
/// comparison it takes part in (|t_i| <= bound for the translation, |column_i · column_i
/// − 1| <= tol for the rotation); poseError then says which.
template <class T>
[[nodiscard]] Error checkPose(const Pose<T>& pose, const char* name) {
  if constexpr (ScalarTraits<T>::isExact) {
    return poseError(pose, name);
  } else {
    const T bound = ScalarTraits<T>::largestCoordinate();
    const T tol = std::max(T(defaults::kRotationTolerance), T(100) * ScalarTraits<T>::epsilon());
    const Mat3<T>& R = pose.rotation;
    bool ok = absValue(pose.translation[0]) <= bound && absValue(pose.translation[1]) <= bound &&
              absValue(pose.translation[2]) <= bound;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) {
        const T e = R(0, i) * R(0, j) + R(1, i) * R(1, j) + R(2, i) * R(2, j) - (i == j ? T(1) : T(0));
        ok = ok && absValue(e) <= tol;
      }
    if (ok && R.determinant() > T(0)) return Error();
    return poseError(pose, name);
  }
}

/// The Error for placed shapes an MDD query cannot take (checkPose on both poses; a shape
/// too thin for the Gauss-map tests in its scalar type), or none. poseP is not checked
/// again where it matches `checked` (a cache's pose that passed these checks before).
template <class T>
[[nodiscard]] Error checkPlacedPair(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                                    const Pose<T>& poseQ, const CheckedPose<T>* checked = nullptr) {
  if (!(checked && checked->matches(poseP)))
    if (Error e = checkPose(poseP, "poseP")) return e;
  if (Error e = checkPose(poseQ, "poseQ")) return e;
  for (const auto* X : {&P, &Q})
    if (!X->edgesResolved())
      return Error(std::string("mdd: ") + (X == &P ? "P" : "Q") +
                   " has an edge whose two face normals are opposite to rounding (a dihedral angle "
                   "below about 64 eps, built with a hull tolerance of 0): too thin for the Gauss-map "
                   "tests in this scalar type");
  return Error();
}

/// Q's placement in P's frame (R, t) and P's world-to-local rotation RPt, for a pair that
/// passed checkPlacedPair; resets the cache's hints when it last served another pair of
/// shapes. `identityP`: P's rotation is exactly the identity (a shape placed in world
/// coordinates), so products with RPt are skipped: x, not 1·x + 0·y + 0·z, which is the
/// same number (but for the sign of a zero).
template <class T>
struct RelativePose {
  Mat3<T> RPt, R;
  Vec3<T> t;
  bool identityP = false;
  Vec3<T> directionToLocal(const Vec3<T>& world) const { return identityP ? world : Vec3<T>(RPt * world); }
  Vec3<T> directionToWorld(const Vec3<T>& local) const { return identityP ? local : Vec3<T>(RPt.transpose() * local); }
};

template <class T>
RelativePose<T> relativePose(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                             const Pose<T>& poseQ, MddCache<T>& cache) {
  if (cache.shapeP != &P || cache.shapeQ != &Q) {
    cache.faceP = cache.vertexP = cache.vertexQ = -1;
    cache.exitFaces[0] = cache.exitFaces[1] = MddCachedFace{};
    cache.shapeP = &P;
    cache.shapeQ = &Q;
  }
  RelativePose<T> rel;
  // P's inverse rotation, not its transpose: the two differ when the matrix is a rotation
  // only up to rounding, and the inverse keeps the answer the exact one for the shapes
  // as placed by the matrices given. Kept in the cache with the pose (checked by now).
  if (cache.checkedPoseP.matches(poseP)) {
    rel.RPt = cache.checkedPoseP.inverseRotation;
  } else {
    rel.RPt = poseP.rotation.inverse();
    cache.checkedPoseP.keep(poseP, rel.RPt);
  }
  rel.identityP = cache.checkedPoseP.identityRotation;
  if (rel.identityP) {
    rel.R = poseQ.rotation;
    rel.t = poseQ.translation - poseP.translation;
  } else {
    rel.R = rel.RPt * poseQ.rotation;
    rel.t = rel.RPt * (poseQ.translation - poseP.translation);
  }
  return rel;
}

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
    // Scaling by a power of two changes nothing in n / |n| unless |n|'s squares would
    // leave the exponent range: skip it (an ilogb and three ldexp calls) for a vector of
    // moderate size, the common case, and get the same bits (but for a subnormal output
    // component, which may differ by its last ulp: the unscaled quotient is the closer).
    const T big = n.cwiseAbs().maxCoeff();
    constexpr int kSafe = std::numeric_limits<T>::max_exponent / 4;
    const bool moderate = big >= std::ldexp(T(1), -kSafe) && big <= std::ldexp(T(1), kSafe);
    const Vec3<T> m = moderate ? n : unitOrder(n);
    const T len = m.norm();
    return len > T(0) ? Vec3<T>(m / len) : m;
  }
}

}  // namespace detail
}  // namespace mink
