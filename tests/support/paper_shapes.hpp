// tests/support/paper_shapes.hpp — the six test polyhedra of the MDD-DUAL paper, and
// random rotations (floating and exactly rational) to place them.
//
// Source: Choi, Li, Rong, Wang, Cameron, "Computing the Minimum Directional Distance
// between Two Convex Polyhedra", Sec. VII. The paper names the shapes only by kind and
// vertex count; the parameters below are ours:
//   P1 truncated elliptic cone, 20 vertices   two rings of 10, semi-axes a:b = 1:2, height
//      h = 4a (a = 1.5, b = 3, h = 6); the top ring is the bottom ring scaled by 1/2 (the
//      multiplication by 0.5 is exact, so the 10 lateral quads are EXACTLY planar).
//   P2 truncated elliptic cylinder, 50 vertices   two rings of 25, same a, b, h (the 25
//      lateral rectangles and the two caps are exactly planar).
//   P3 ellipsoid, 200 vertices; P4 ellipsoid, 500 vertices   semi-axes 1.8 : 1.8 : 4.5
//      (the paper's 2:2:5), Fibonacci-sphere points mapped onto the ellipsoid: all points
//      lie on a strictly convex surface, so all are hull vertices.
//   P5 hull of 100 uniform random points in the cube [-2.8, 2.8]^3: only ~25-45 of them are
//      hull vertices (the paper's "100" counts the points, not the hull vertices).
//   P6 solid of revolution, 200 vertices   10 rings x 20 around, ring j at height z_j
//      in [-3.9, 3.9] with radius r(z) = 3.3 (1 - 0.6 (z/3.9)^2) (strictly concave profile,
//      flat 20-gon caps), consecutive rings staggered by half a step so the lateral
//      faces are triangles in general position.
// All shapes are centred near the origin and lie inside the sphere of radius 5.
// Outputs are double point sets in the shape's own frame (units of length); every
// generator is deterministic. Only P5 draws from the std::mt19937 it is given, through
// uniform01() below (the std::*_distribution classes are not portable across libraries).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mink_test {


enum class PaperShape { P1, P2, P3, P4, P5, P6 };

inline constexpr std::array<PaperShape, 6> kPaperShapes = {
    PaperShape::P1, PaperShape::P2, PaperShape::P3,
    PaperShape::P4, PaperShape::P5, PaperShape::P6};

/// The ten pairs of Sec. VII: (P1,P2), (P1,P3), (P4,P5), (P4,P6), (Pi,Pi) i = 1..6.
inline constexpr std::array<std::pair<PaperShape, PaperShape>, 10> kPaperPairs = {{
    {PaperShape::P1, PaperShape::P2},
    {PaperShape::P1, PaperShape::P3},
    {PaperShape::P4, PaperShape::P5},
    {PaperShape::P4, PaperShape::P6},
    {PaperShape::P1, PaperShape::P1},
    {PaperShape::P2, PaperShape::P2},
    {PaperShape::P3, PaperShape::P3},
    {PaperShape::P4, PaperShape::P4},
    {PaperShape::P5, PaperShape::P5},
    {PaperShape::P6, PaperShape::P6},
}};

/// Radius of the sphere (centred at the origin) that holds every paper shape.
inline constexpr double kPaperShapeRadius = 5.0;

inline const char* paperShapeName(PaperShape id) {
  switch (id) {
    case PaperShape::P1: return "P1";
    case PaperShape::P2: return "P2";
    case PaperShape::P3: return "P3";
    case PaperShape::P4: return "P4";
    case PaperShape::P5: return "P5";
    case PaperShape::P6: return "P6";
  }
  return "?";
}

inline const char* paperShapeDescription(PaperShape id) {
  switch (id) {
    case PaperShape::P1: return "truncated elliptic cone, 20 vertices";
    case PaperShape::P2: return "truncated elliptic cylinder, 50 vertices";
    case PaperShape::P3: return "ellipsoid, 200 vertices";
    case PaperShape::P4: return "ellipsoid, 500 vertices";
    case PaperShape::P5: return "hull of 100 random points in a cube";
    case PaperShape::P6: return "solid of revolution of a convex profile, 200 vertices";
  }
  return "?";
}

/// Number of hull vertices of the generated point set, or -1 for P5 (random: fewer than
/// its 100 points, depends on the seed).
inline int paperShapeHullVertexCount(PaperShape id) {
  switch (id) {
    case PaperShape::P1: return 20;
    case PaperShape::P2: return 50;
    case PaperShape::P3: return 200;
    case PaperShape::P4: return 500;
    case PaperShape::P5: return -1;
    case PaperShape::P6: return 200;
  }
  return -1;
}

/// Number of points the generator returns (100 for P5; hull vertex count otherwise).
inline int paperShapePointCount(PaperShape id) {
  return id == PaperShape::P5 ? 100 : paperShapeHullVertexCount(id);
}

/// Uniform double in [0, 1) with 53 random bits, from two raw mt19937 draws. mt19937's
/// output sequence is fixed by the standard, so this is the same on every platform.
inline double uniform01(std::mt19937& rng) {
  const std::uint64_t hi = static_cast<std::uint64_t>(rng()) >> 5;  // 27 bits
  const std::uint64_t lo = static_cast<std::uint64_t>(rng()) >> 6;  // 26 bits
  return static_cast<double>((hi << 26) | lo) * 0x1.0p-53;
}

/// Uniform double in [lo, hi).
inline double uniformIn(std::mt19937& rng, double lo, double hi) {
  return lo + (hi - lo) * uniform01(rng);
}

/// Standard normal deviate (Box-Muller on uniform01, portable).
inline double standardNormal(std::mt19937& rng) {
  constexpr double kTwoPi = 6.283185307179586476925286766559;
  const double u1 = 1.0 - uniform01(rng);  // in (0, 1], log is finite
  const double u2 = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

/// Uniform random unit direction.
inline Eigen::Vector3d randomUnitVector(std::mt19937& rng) {
  for (;;) {
    Eigen::Vector3d v(standardNormal(rng), standardNormal(rng), standardNormal(rng));
    const double n = v.norm();
    if (n > 1e-6) return v / n;
  }
}

namespace paper_shapes_detail {

constexpr double kPi = 3.141592653589793238462643383279502884;

// Semi-axes of the cone/cylinder base ellipse and their height: a : b : h = 1 : 2 : 4.
constexpr double kA = 1.5, kB = 3.0, kH = 6.0;
// Ellipsoid semi-axes: 2 : 2 : 5.
constexpr double kEa = 1.8, kEb = 1.8, kEc = 4.5;

// Points on the ellipse (a cos t, b sin t) at n equally spaced angles, at height z.
inline void ellipseRing(std::vector<Eigen::Vector3d>& out, int n, double a, double b,
                        double z, double phase = 0.0) {
  for (int k = 0; k < n; ++k) {
    const double t = phase + 2.0 * kPi * k / n;
    out.emplace_back(a * std::cos(t), b * std::sin(t), z);
  }
}

inline std::vector<Eigen::Vector3d> fibonacciEllipsoid(int n, double a, double b, double c) {
  // Golden-angle spiral: z uniform in (-1, 1), azimuth advancing by pi (3 - sqrt 5); the
  // points are well spread, and all of them lie on the (strictly convex) ellipsoid.
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  std::vector<Eigen::Vector3d> out;
  out.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * i;
    out.emplace_back(a * r * std::cos(phi), b * r * std::sin(phi), c * z);
  }
  return out;
}

}  // namespace paper_shapes_detail

/// P1: truncated elliptic cone. Bottom ring z = -3 (semi-axes 1.5, 3), top ring z = +3
/// obtained by multiplying the bottom x, y by 0.5 exactly (apex of the cone at z = 9).
inline std::vector<Eigen::Vector3d> paperCone() {
  using namespace paper_shapes_detail;
  std::vector<Eigen::Vector3d> pts;
  ellipseRing(pts, 10, kA, kB, -0.5 * kH);
  for (int k = 0; k < 10; ++k) {
    const Eigen::Vector3d& p = pts[static_cast<std::size_t>(k)];
    pts.emplace_back(0.5 * p.x(), 0.5 * p.y(), 0.5 * kH);
  }
  return pts;
}

/// P2: truncated elliptic cylinder, rings of 25 at z = -3 and z = +3 (same x, y).
inline std::vector<Eigen::Vector3d> paperCylinder() {
  using namespace paper_shapes_detail;
  std::vector<Eigen::Vector3d> pts;
  ellipseRing(pts, 25, kA, kB, -0.5 * kH);
  for (int k = 0; k < 25; ++k) {
    const Eigen::Vector3d& p = pts[static_cast<std::size_t>(k)];
    pts.emplace_back(p.x(), p.y(), 0.5 * kH);
  }
  return pts;
}

/// P3 (n = 200) and P4 (n = 500): ellipsoid with semi-axes 1.8, 1.8, 4.5.
inline std::vector<Eigen::Vector3d> paperEllipsoid(int n) {
  using namespace paper_shapes_detail;
  return fibonacciEllipsoid(n, kEa, kEb, kEc);
}

/// P5: 100 uniform random points in [-2.8, 2.8]^3 (half-diagonal 4.85 < 5). The hull has
/// far fewer than 100 vertices; the interior points are kept on purpose (hull building is
/// part of what is tested).
inline std::vector<Eigen::Vector3d> paperRandomCube(std::mt19937& rng, int n = 100,
                                                    double half = 2.8) {
  std::vector<Eigen::Vector3d> pts;
  pts.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double x = uniformIn(rng, -half, half);
    const double y = uniformIn(rng, -half, half);
    const double z = uniformIn(rng, -half, half);
    pts.emplace_back(x, y, z);
  }
  return pts;
}

/// P6: solid of revolution about z of the profile r(z) = 3.3 (1 - 0.6 (z / 3.9)^2),
/// z in [-3.9, 3.9]: 10 rings of 20, ring j rotated by j * (half a step).
inline std::vector<Eigen::Vector3d> paperRevolution(int rings = 10, int around = 20) {
  using namespace paper_shapes_detail;
  constexpr double kHalfHeight = 3.9, kRadius = 3.3, kBulge = 0.6;
  std::vector<Eigen::Vector3d> pts;
  pts.reserve(static_cast<std::size_t>(rings * around));
  for (int j = 0; j < rings; ++j) {
    const double z = -kHalfHeight + 2.0 * kHalfHeight * j / (rings - 1);
    const double zr = z / kHalfHeight;
    const double r = kRadius * (1.0 - kBulge * zr * zr);
    ellipseRing(pts, around, r, r, z, kPi * j / around);
  }
  return pts;
}

/// The paper shape `id` in its own frame. `rng` is used by P5 only.
inline std::vector<Eigen::Vector3d> paperShape(PaperShape id, std::mt19937& rng) {
  switch (id) {
    case PaperShape::P1: return paperCone();
    case PaperShape::P2: return paperCylinder();
    case PaperShape::P3: return paperEllipsoid(200);
    case PaperShape::P4: return paperEllipsoid(500);
    case PaperShape::P5: return paperRandomCube(rng);
    case PaperShape::P6: return paperRevolution();
  }
  throw std::invalid_argument("paperShape: unknown id");
}

/// Uniform random rotation (Haar measure), Shoemake's method: a uniform unit quaternion
/// from three uniforms.
inline Eigen::Quaterniond randomQuaternion(std::mt19937& rng) {
  constexpr double kTwoPi = 6.283185307179586476925286766559;
  const double u1 = uniform01(rng), u2 = uniform01(rng), u3 = uniform01(rng);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  // Eigen's constructor order is (w, x, y, z).
  return Eigen::Quaterniond(b * std::cos(kTwoPi * u3), a * std::sin(kTwoPi * u2),
                            a * std::cos(kTwoPi * u2), b * std::sin(kTwoPi * u3));
}

inline Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  return randomQuaternion(rng).toRotationMatrix();
}

}  // namespace mink_test
