// tests/support/exact_placement.hpp — exact rational placements for the reference tests:
// rational rotations (exactly orthonormal) and exact conversion / placement of the paper
// shapes' double points. Needs CGAL (Gmpq); the shapes themselves (paper_shapes.hpp) do not,
// so examples and benchmarks can use them with Eigen alone.
#pragma once

#include <CGAL/Gmpq.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdlib>
#include <random>
#include <stdexcept>
#include <vector>

#include "support/paper_shapes.hpp"

namespace mink_test {

using Rational = CGAL::Gmpq;
using Vec3r = Eigen::Matrix<Rational, 3, 1>;
using Mat3r = Eigen::Matrix<Rational, 3, 3>;

/// An exactly orthonormal rotation with rational entries, and its rounding to double.
struct RationalRotation {
  Mat3r exact;             // R, exactly R^T R = I and det R = 1
  Eigen::Matrix3d rounded; // each entry of `exact` rounded to nearest double
  std::array<long, 4> quaternion;  // integer (w, x, y, z) it was built from
};

/// Rotation of the integer quaternion (w, x, y, z) (not normalised): R = M / (w²+x²+y²+z²)
/// with M the usual quadratic form. For w != 0 this is the Cayley transform
/// (I + K)(I - K)^{-1} of the skew matrix K = [v]_x, v = (x, y, z) / w, so it is exactly
/// orthonormal; w = 0 gives the half-turns the Cayley form misses. Throws on (0,0,0,0).
inline RationalRotation rationalRotationFromQuaternion(long w, long x, long y, long z) {
  const long n2 = w * w + x * x + y * y + z * z;
  if (n2 == 0) throw std::invalid_argument("rationalRotationFromQuaternion: zero quaternion");
  const long m[3][3] = {
      {w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
      {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
      {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  RationalRotation r;
  r.quaternion = {w, x, y, z};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      r.exact(i, j) = Rational(m[i][j]) / Rational(n2);
      // |m| and n2 are integers far below 2^53, so the double quotient is the correctly
      // rounded value of the exact entry.
      r.rounded(i, j) = static_cast<double>(m[i][j]) / static_cast<double>(n2);
    }
  }
  return r;
}

/// Random rational rotation, close to Haar-uniform: a uniform unit quaternion scaled by
/// `resolution` and rounded to integers. Entries have denominators <= resolution² (+2),
/// keeping exact arithmetic on rotated points cheap. resolution must be in [1, 2^20].
inline RationalRotation randomRationalRotation(std::mt19937& rng, long resolution = 64) {
  if (resolution < 1 || resolution > (1L << 20))
    throw std::invalid_argument("randomRationalRotation: resolution out of range");
  for (;;) {
    const Eigen::Quaterniond q = randomQuaternion(rng);
    const double s = static_cast<double>(resolution);
    const long w = std::lround(s * q.w()), x = std::lround(s * q.x());
    const long y = std::lround(s * q.y()), z = std::lround(s * q.z());
    if (w != 0 || x != 0 || y != 0 || z != 0) return rationalRotationFromQuaternion(w, x, y, z);
  }
}

/// Exact rational copy of a double vector (every finite double is a rational).
inline Vec3r toExact(const Eigen::Vector3d& v) {
  return Vec3r(Rational(v.x()), Rational(v.y()), Rational(v.z()));
}

inline std::vector<Vec3r> toExact(const std::vector<Eigen::Vector3d>& pts) {
  std::vector<Vec3r> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.push_back(toExact(p));
  return out;
}

/// World coordinates R x + t of every point, computed exactly.
inline std::vector<Vec3r> placeExact(const std::vector<Vec3r>& pts, const Mat3r& rotation,
                                     const Vec3r& translation) {
  std::vector<Vec3r> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.push_back(rotation * p + translation);
  return out;
}

inline std::vector<Vec3r> placeExact(const std::vector<Eigen::Vector3d>& pts,
                                     const Mat3r& rotation, const Vec3r& translation) {
  return placeExact(toExact(pts), rotation, translation);
}

/// World coordinates R x + t computed in double (as a double-precision implementation
/// would), then converted exactly: the reference then answers for these rounded points.
inline std::vector<Vec3r> placeRounded(const std::vector<Eigen::Vector3d>& pts,
                                       const Eigen::Matrix3d& rotation,
                                       const Eigen::Vector3d& translation) {
  std::vector<Vec3r> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.push_back(toExact(Eigen::Vector3d(rotation * p + translation)));
  return out;
}

}  // namespace mink_test
