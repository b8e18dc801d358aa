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

  /// The pose of an Eigen rigid transform (`Eigen::Isometry3d`, `Eigen::Isometry3f`, or an
  /// `Affine3d` whose linear part is a rotation), in any scalar: entries are converted by
  /// static_cast, exact from float to double or long double, rounded the other way. No
  /// check here; the queries reject a linear part that is not a rotation (InvalidInput).
  template <class U, int Mode, int Options>
  static Pose fromIsometry(const Eigen::Transform<U, 3, Mode, Options>& x) {
    static_assert(Mode != int(Eigen::Projective), "Pose::fromIsometry: a projective transform is not rigid");
    Pose pose;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) pose.rotation(r, c) = static_cast<T>(x.matrix()(r, c));
      pose.translation[r] = static_cast<T>(x.matrix()(r, 3));
    }
    return pose;
  }

  /// The same placement as an Eigen isometry (x_world = iso * x_shape).
  Eigen::Transform<T, 3, Eigen::Isometry> toIsometry() const {
    Eigen::Transform<T, 3, Eigen::Isometry> x = Eigen::Transform<T, 3, Eigen::Isometry>::Identity();
    x.linear() = rotation;
    x.translation() = translation;
    return x;
  }
};

}  // namespace mink
