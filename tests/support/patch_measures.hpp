// tests/support/patch_measures.hpp — measures of a MinkowskiPatch in double for the CPD
// tests: area, enclosed volume and area vector (zero for a closed patch), and the distance
// from a point to the patch.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

#include "mink/cpd/minkowski_patch.hpp"

namespace mink_test {

/// Squared distance from p to the triangle a b c (C. Ericson, Real-Time Collision
/// Detection, 5.1.5).
inline double squaredDistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + (d1 / (d1 - d3)) * ab)).squaredNorm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + (d2 / (d2 - d6)) * ac)).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b))).squaredNorm();
  const double den = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * den) + ac * (vc * den))).squaredNorm();
}


/// Area, volume (for a closed patch) and area vector of a patch in double.
template <class T>
struct PatchMeasures {
  double area = 0, volume = 0;
  Eigen::Vector3d areaVector = Eigen::Vector3d::Zero();
};
template <class T>
PatchMeasures<T> measure(const mink::MinkowskiPatch<T>& p) {
  PatchMeasures<T> m;
  for (const auto& t : p.triangles) {
    Eigen::Vector3d v[3];
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 3; ++a) v[c][a] = mink::detail::toDouble(p.vertices[static_cast<std::size_t>(t[c])][a]);
    const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
    m.area += 0.5 * n.norm();
    m.areaVector += 0.5 * n;
    m.volume += v[0].dot(v[1].cross(v[2])) / 6;
  }
  return m;
}

/// The distance from x to a patch (double).
template <class T>
double distanceToPatch(const mink::MinkowskiPatch<T>& p, const Eigen::Vector3d& x) {
  double best = INFINITY;
  auto d = [&](int i) {
    const auto& v = p.vertices[static_cast<std::size_t>(i)];
    return Eigen::Vector3d(mink::detail::toDouble(v[0]), mink::detail::toDouble(v[1]), mink::detail::toDouble(v[2]));
  };
  for (const auto& t : p.triangles)
    best = std::min(best, squaredDistanceToTriangle(x, d(t[0]), d(t[1]), d(t[2])));
  return std::sqrt(best);
}

}  // namespace mink_test
