// tests/support/degenerate_contacts.hpp — the degenerate contacts of a physics scene, each
// with n-gon shapes of any n and a generic twin: the same shapes with Q turned by a small
// rotation about a generic axis, so that no two faces, edges or vertices align. Shared by
// the stress test (small n, against the exact reference) and the worst-case benchmark
// (n up to 1024, degenerate time beside generic time).
//
// Families:
//   resting-slide   an n-gon prism resting on a larger one, face to face; s in the plane
//   resting-tilt    the same, s tilted out of the contact plane
//   caps-overlap    the smaller prism sunk 0.1 into the larger; s tilted
//   cylinders-side  two n-gon prisms lying side by side, parallel axes, touching along a
//                   line (an edge of each); s along the line, across it and tilted
//   cones-apex      two n-gon cones apex to apex, 0.25 apart (apex degree n); s steeply
//                   down, the line meeting M near the apexes' vertex
//   boxes-aligned   axis-aligned boxes, one resting on the other (n is ignored)
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <string>
#include <vector>

namespace mink_test {

struct ContactScene {
  std::string family;
  int n = 0;
  bool generic = false;
  std::vector<Eigen::Vector3d> P, Q;             // points; shapes are their hulls
  Eigen::Matrix3d rotQ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d tQ = Eigen::Vector3d::Zero();  // P sits at the identity pose
  std::vector<Eigen::Vector3d> dirs;             // the query directions s
};

inline std::vector<std::string> degenerateFamilies() {
  return {"resting-slide", "resting-tilt", "caps-overlap", "cylinders-side", "cones-apex", "boxes-aligned"};
}

namespace detail_contacts {

constexpr double kPi = 3.14159265358979323846;

/// Ring of n points of radius r at height z (angles phase + 2πi/n), as a prism's
/// cross-section: along z from z0 to z1.
inline std::vector<Eigen::Vector3d> prismZ(int n, double r, double z0, double z1, double phase) {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * kPi * i / n;
    p.emplace_back(r * std::cos(a), r * std::sin(a), z0);
    p.emplace_back(r * std::cos(a), r * std::sin(a), z1);
  }
  return p;
}

/// A prism along x (from x0 to x1) with an n-gon cross-section in the yz-plane.
inline std::vector<Eigen::Vector3d> prismX(int n, double r, double x0, double x1, double phase) {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * kPi * i / n;
    p.emplace_back(x0, r * std::cos(a), r * std::sin(a));
    p.emplace_back(x1, r * std::cos(a), r * std::sin(a));
  }
  return p;
}

/// A cone: n-gon base of radius r at height zBase, apex at the origin.
inline std::vector<Eigen::Vector3d> cone(int n, double r, double zBase, double phase) {
  std::vector<Eigen::Vector3d> p{Eigen::Vector3d::Zero()};
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * kPi * i / n;
    p.emplace_back(r * std::cos(a), r * std::sin(a), zBase);
  }
  return p;
}

inline std::vector<Eigen::Vector3d> box(double a, double b, double c) {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? a : -a, i & 2 ? b : -b, i & 4 ? c : -c);
  return p;
}

/// `count` directions at elevation `elev` (radians) above the xy-plane, evenly around z.
inline void ring(std::vector<Eigen::Vector3d>& out, int count, double elev, double phase) {
  for (int i = 0; i < count; ++i) {
    const double a = phase + 2 * kPi * i / count;
    out.emplace_back(std::cos(elev) * std::cos(a), std::cos(elev) * std::sin(a), std::sin(elev));
  }
}

}  // namespace detail_contacts

/// The scene of `family` with n-gons (n >= 3), degenerate or its generic twin.
inline ContactScene degenerateScene(const std::string& family, int n, bool generic) {
  using namespace detail_contacts;
  ContactScene sc;
  sc.family = family;
  sc.n = n;
  sc.generic = generic;
  if (family == "resting-slide" || family == "resting-tilt" || family == "caps-overlap") {
    sc.P = prismZ(n, 2.0, -1.0, 0.0, 0.0);
    sc.Q = prismZ(n, 1.0, 0.0, 1.0, 0.1);
    sc.tQ = Eigen::Vector3d(0.25, -0.125, family == "caps-overlap" ? -0.125 : 0.0);
    if (family == "resting-slide") {
      ring(sc.dirs, 8, 0.0, 0.05);
    } else {
      ring(sc.dirs, 4, 0.5, 0.05);
      ring(sc.dirs, 4, -0.5, 0.3);
    }
  } else if (family == "cylinders-side") {
    // A vertex of P's section at the top (angle π/2), one of Q's at the bottom: the two
    // prisms touch along a segment of an edge of each.
    sc.P = prismX(n, 1.0, -2.0, 2.0, kPi / 2);
    sc.Q = prismX(n, 1.0, -1.5, 1.5, -kPi / 2);
    sc.tQ = Eigen::Vector3d(0.25, 0.0, 2.0);
    sc.dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {1, 1, 0}, {1, 0, -1}, {0, 1, -1}, {1, 2, 3}};
  } else if (family == "cones-apex") {
    // Q's apex 0.25 above P's: the lines that meet M near its apex-apex vertex (degree
    // n + n faces of M and n² edge pairs around it), steeply downwards.
    sc.P = cone(n, 1.0, -1.0, 0.0);
    sc.Q = cone(n, 1.0, 1.0, 0.5 / n);
    sc.tQ = Eigen::Vector3d(0.0, 0.0, 0.25);
    ring(sc.dirs, 4, -1.2, 0.05);
    ring(sc.dirs, 3, -1.45, 0.3);
    sc.dirs.emplace_back(0.0, 0.0, -1.0);
  } else if (family == "boxes-aligned") {
    sc.P = box(2.0, 2.0, 1.0);
    sc.Q = box(0.5, 0.5, 0.5);
    sc.tQ = Eigen::Vector3d(0.5, 0.25, 1.5);
    sc.dirs = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 0}, {1, 0, 1}, {0, 1, -1}, {1, 1, 1}};
  }
  if (generic) sc.rotQ = Eigen::AngleAxisd(0.01, Eigen::Vector3d(0.36, 0.48, 0.8)).toRotationMatrix();
  return sc;
}

}  // namespace mink_test
