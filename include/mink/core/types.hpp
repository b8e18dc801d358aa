// mink/core/types.hpp — the vector and pose types every layer speaks.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mink {

/// A point or direction in R^3, in whatever frame the caller states.
template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

/// 3 by 3 matrix (row-major meaning irrelevant: Eigen stores column-major).
template <class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;

/// Rigid placement of a shape: x_world = rotation * x_shape + translation.
/// `rotation` must be orthonormal with determinant +1; identity by default.
template <class T>
struct Pose {
  Mat3<T> rotation = Mat3<T>::Identity();
  Vec3<T> translation = Vec3<T>::Zero();

  static Pose identity() { return Pose(); }
  Vec3<T> apply(const Vec3<T>& x) const { return rotation * x + translation; }
};

}  // namespace mink
