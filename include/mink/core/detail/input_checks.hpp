// mink/core/detail/input_checks.hpp — the checks every shape constructor and query set-up
// makes on its input, with one wording for every layer: a coordinate that is NaN or
// infinite, or above ScalarTraits<T>::largestCoordinate() (where the exact predicates of
// core/orientation.hpp could overflow); a placement whose rotation is not a rotation.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/error.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {
namespace detail {

/// The Error "<who>: <what> <i> has a non-finite coordinate (NaN or Inf)" or "... has a
/// coordinate out of range (...)" for the first point i that has one; none if all are fine.
template <class T>
[[nodiscard]] Error checkCoordinates(const std::vector<Vec3<T>>& pts, const char* who, const char* what) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!ScalarTraits<T>::isFinite(pts[i][k]))
        return Error(std::string(who) + ": " + what + " " + std::to_string(i) +
                     " has a non-finite coordinate (NaN or Inf)");
      if constexpr (!ScalarTraits<T>::isExact) {
        if (ScalarTraits<T>::inCoordinateRange(pts[i][k])) continue;
        char msg[256];
        std::snprintf(msg, sizeof msg,
                      " has a coordinate out of range (%.3g; coordinates must be at most %.3g in magnitude, "
                      "where the exact predicates cannot overflow)",
                      static_cast<double>(pts[i][k]), static_cast<double>(ScalarTraits<T>::largestCoordinate()));
        return Error(std::string(who) + ": " + what + " " + std::to_string(i) + msg);
      }
    }
  }
  return Error();
}

/// Checks a rigid placement x -> rotation x + translation: finite entries, a translation
/// within ScalarTraits<T>::largestCoordinate(), R^T R = I within
/// defaults::kRotationTolerance (or 100 eps, if larger; exactly for exact T) and det R > 0.
/// The Error "<who>: <name>.rotation is not orthonormal" and the like, or none; allocates
/// nothing when the placement is fine (it runs on every re-placement of a query object).
template <class T>
[[nodiscard]] Error checkRigidPlacement(const Mat3<T>& rotation, const Vec3<T>& translation, const char* who,
                                        const char* name) {
  auto fail = [&](const char* problem) { return Error(std::string(who) + ": " + name + problem); };
  for (int i = 0; i < 3; ++i) {
    if (!ScalarTraits<T>::isFinite(translation[i])) return fail(".translation is not finite");
    if (!ScalarTraits<T>::inCoordinateRange(translation[i]))
      return fail(".translation is out of range (above ScalarTraits::largestCoordinate())");
    for (int j = 0; j < 3; ++j)
      if (!ScalarTraits<T>::isFinite(rotation(i, j))) return fail(".rotation is not finite");
  }
  const Mat3<T> E = rotation.transpose() * rotation - Mat3<T>::Identity();
  T tol = T(0);
  if constexpr (!ScalarTraits<T>::isExact)
    tol = std::max(T(defaults::kRotationTolerance), T(100) * ScalarTraits<T>::epsilon());
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (absValue(T(E(i, j))) > tol) return fail(".rotation is not orthonormal");
  if (!(rotation.determinant() > T(0))) return fail(".rotation is a reflection (determinant < 0)");
  return Error();
}

}  // namespace detail
}  // namespace mink
