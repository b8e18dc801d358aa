// tests/support/mesh_shapes.hpp — procedural closed triangle meshes for the mesh layer's
// tests and benchmarks (Eigen only: no CGAL, no gtest). Every shape is closed, 2-manifold,
// outward-oriented and free of self-intersection (the tests check all of it).
//
// Shapes are written as faces given by their corner *positions*; a builder merges equal
// positions into one vertex and orients each face against an outward hint, so a shape is
// closed as soon as its faces meet corner to corner (no T-junctions). Shapes with flat
// faces and axis-aligned or rounded corners have integer coordinates, so they convert
// exactly to float and to exact rationals: box, L-block, U-block, cube with a hole, star
// prism, axes.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mink/core/types.hpp"

namespace mink_test {

struct MeshShape {
  std::string name;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
  int genus = 0;                              // of its one component
  bool integer = false;                       // every coordinate an integer

  /// The vertices in scalar type T (exact for every double when T is an exact rational;
  /// for float, exact for the integer shapes).
  template <class T>
  std::vector<mink::Vec3<T>> verticesAs() const {
    std::vector<mink::Vec3<T>> out;
    out.reserve(vertices.size());
    for (const auto& p : vertices) out.emplace_back(T(p.x()), T(p.y()), T(p.z()));
    return out;
  }
};

namespace mesh_shapes_detail {

constexpr double kPi = 3.141592653589793238462643383279502884;

class Builder {
 public:
  explicit Builder(std::string name) { shape_.name = std::move(name); }

  int vertex(const Eigen::Vector3d& p) {
    const std::array<double, 3> key{p.x(), p.y(), p.z()};
    const auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    const int id = static_cast<int>(shape_.vertices.size());
    index_.emplace(key, id);
    shape_.vertices.push_back(p);
    return id;
  }

  /// Triangle (p, q, r), flipped if its normal points against `outward`.
  void triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r,
                const Eigen::Vector3d& outward) {
    const double s = (q - p).cross(r - p).dot(outward);
    if (s == 0.0) throw std::logic_error(shape_.name + ": triangle normal perpendicular to its outward hint");
    if (s > 0)
      shape_.triangles.push_back({vertex(p), vertex(q), vertex(r)});
    else
      shape_.triangles.push_back({vertex(p), vertex(r), vertex(q)});
  }

  /// Quad p, q, r, s (a loop) as triangles (p, q, r) and (p, r, s).
  void quad(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r, const Eigen::Vector3d& s,
            const Eigen::Vector3d& outward) {
    triangle(p, q, r, outward);
    triangle(p, r, s, outward);
  }

  MeshShape finish(int genus) {
    shape_.genus = genus;
    shape_.integer = true;
    for (const auto& p : shape_.vertices)
      for (int k = 0; k < 3; ++k) shape_.integer = shape_.integer && p[k] == std::floor(p[k]);
    return std::move(shape_);
  }

 private:
  MeshShape shape_;
  std::map<std::array<double, 3>, int> index_;
};

/// A prism: the counter-clockwise polygon `outline` (x, y) between z0 < z1, caps split
/// into `capTriangles` (indices into outline, no new corners).
inline MeshShape extrude(const std::string& name, const std::vector<Eigen::Vector2d>& outline,
                         const std::vector<std::array<int, 3>>& capTriangles, double z0, double z1) {
  Builder b(name);
  auto at = [&](int i, double z) { return Eigen::Vector3d(outline[i].x(), outline[i].y(), z); };
  for (const auto& t : capTriangles) {
    b.triangle(at(t[0], z1), at(t[1], z1), at(t[2], z1), Eigen::Vector3d(0, 0, 1));
    b.triangle(at(t[0], z0), at(t[1], z0), at(t[2], z0), Eigen::Vector3d(0, 0, -1));
  }
  const int n = static_cast<int>(outline.size());
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const Eigen::Vector2d d = outline[j] - outline[i];
    b.quad(at(i, z0), at(j, z0), at(j, z1), at(i, z1), Eigen::Vector3d(d.y(), -d.x(), 0));  // right of the edge
  }
  return b.finish(0);
}

}  // namespace mesh_shapes_detail

/// Axis-aligned box [lo, hi] (12 triangles).
inline MeshShape boxShape(const Eigen::Vector3d& lo = Eigen::Vector3d(-1, -1, -1),
                          const Eigen::Vector3d& hi = Eigen::Vector3d(1, 1, 1)) {
  mesh_shapes_detail::Builder b("box");
  auto c = [&](int i) { return Eigen::Vector3d(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()); };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      // The four corners with bit `axis` == side, in a loop.
      const int bit = 1 << axis, u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3), base = side ? bit : 0;
      Eigen::Vector3d out = Eigen::Vector3d::Zero();
      out[axis] = side ? 1 : -1;
      b.quad(c(base), c(base | u), c(base | u | v), c(base | v), out);
    }
  return b.finish(0);
}

/// L-block: the L of [0,2]x[0,1] and [0,1]x[0,2], extruded over z in [0,1]: 12 vertices,
/// 20 triangles, 30 edges. By hand: 17 Convex edges (12 around the caps, 5 vertical corners),
/// 1 Reflex (the vertical edge at (1,1)), 12 Flat (3 cap diagonals per cap, 1 per wall).
inline MeshShape lBlock() {
  const std::vector<Eigen::Vector2d> L = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  return mesh_shapes_detail::extrude("L-block", L, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}, 0, 1);
}

/// U-block: [0,3]x[0,1] with two arms [0,1]x[1,2] and [2,3]x[1,2], over z in [0,1]
/// (16 vertices, 28 triangles; two Reflex edges).
inline MeshShape uBlock() {
  const std::vector<Eigen::Vector2d> U = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  return mesh_shapes_detail::extrude("U-block", U, {{0, 1, 4}, {0, 4, 5}, {0, 5, 6}, {0, 6, 7}, {1, 2, 3}, {1, 3, 4}},
                                     0, 1);
}

/// A k-pointed star (outer radius R, inner r, corners rounded to integers) extruded over
/// z in [0, h]. Caps: the inner k-gon fanned from its first corner plus one triangle per
/// point, no centre vertex (k = 5: 20 vertices, 36 triangles).
inline MeshShape starPrism(int k = 5, double R = 20, double r = 8, double h = 6) {
  using mesh_shapes_detail::kPi;
  std::vector<Eigen::Vector2d> outline;
  for (int i = 0; i < 2 * k; ++i) {
    const double a = kPi / 2 + kPi * i / k, rad = i % 2 ? r : R;
    outline.emplace_back(std::round(rad * std::cos(a)), std::round(rad * std::sin(a)));
  }
  std::vector<std::array<int, 3>> caps;
  for (int i = 0; i < k; ++i) caps.push_back({(2 * i + 2 * k - 1) % (2 * k), 2 * i, 2 * i + 1});  // the points
  for (int i = 1; i + 1 < k; ++i) caps.push_back({1, 2 * i + 1, 2 * i + 3});                  // inner k-gon
  MeshShape s = mesh_shapes_detail::extrude("star prism", outline, caps, 0, h);
  return s;
}

/// The cube [0,3]^3 with the square hole [1,2]x[1,2] through it along z: genus 1,
/// 16 vertices, 32 triangles.
inline MeshShape cubeWithHole() {
  mesh_shapes_detail::Builder b("cube with hole");
  const Eigen::Vector2d O[4] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}}, I[4] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  auto P = [](const Eigen::Vector2d& q, double z) { return Eigen::Vector3d(q.x(), q.y(), z); };
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    b.quad(P(O[i], 3), P(O[j], 3), P(I[j], 3), P(I[i], 3), Eigen::Vector3d(0, 0, 1));
    b.quad(P(O[i], 0), P(O[j], 0), P(I[j], 0), P(I[i], 0), Eigen::Vector3d(0, 0, -1));
    const Eigen::Vector2d mo = 0.5 * (O[i] + O[j]) - Eigen::Vector2d(1.5, 1.5);
    b.quad(P(O[i], 0), P(O[j], 0), P(O[j], 3), P(O[i], 3), Eigen::Vector3d(mo.x(), mo.y(), 0));
    const Eigen::Vector2d mi = Eigen::Vector2d(1.5, 1.5) - 0.5 * (I[i] + I[j]);  // into the hole
    b.quad(P(I[i], 0), P(I[j], 0), P(I[j], 3), P(I[i], 3), Eigen::Vector3d(mi.x(), mi.y(), 0));
  }
  return b.finish(1);
}

/// Torus about the z axis: tube centre radius R, tube radius r, `major` segments around z
/// and `minor` around the tube (2 major minor triangles: 12 x 8 gives 192).
inline MeshShape torus(int major = 12, int minor = 8, double R = 2.0, double r = 0.75) {
  using mesh_shapes_detail::kPi;
  mesh_shapes_detail::Builder b("torus " + std::to_string(major) + "x" + std::to_string(minor));
  auto P = [&](int i, int j) {
    const double u = 2 * kPi * (i % major) / major, v = 2 * kPi * (j % minor) / minor;
    return Eigen::Vector3d((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
  };
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      const Eigen::Vector3d c = 0.25 * (P(i, j) + P(i + 1, j) + P(i + 1, j + 1) + P(i, j + 1));
      const Eigen::Vector3d axis = Eigen::Vector3d(c.x(), c.y(), 0).normalized() * R;
      b.quad(P(i, j), P(i + 1, j), P(i + 1, j + 1), P(i, j + 1), c - axis);
    }
  return b.finish(1);
}

/// Cone: base circle of radius `radius` at z = 0 with `n` segments and a centre vertex,
/// apex at z = height (n + 2 vertices, 2 n triangles).
inline MeshShape cone(int n = 16, double radius = 1.0, double height = 2.0) {
  using mesh_shapes_detail::kPi;
  mesh_shapes_detail::Builder b("cone " + std::to_string(n));
  auto P = [&](int i) {
    const double a = 2 * kPi * (i % n) / n;
    return Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), 0);
  };
  const Eigen::Vector3d apex(0, 0, height), centre(0, 0, 0);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d m = 0.5 * (P(i) + P(i + 1));
    b.triangle(P(i), P(i + 1), apex, Eigen::Vector3d(m.x(), m.y(), 0));
    b.triangle(centre, P(i), P(i + 1), Eigen::Vector3d(0, 0, -1));
  }
  return b.finish(0);
}

/// "Axes": the union of the three boxes [-L,L]x[-1,1]x[-1,1], [-1,1]x[-L,L]x[-1,1] and
/// [-1,1]x[-1,1]x[-L,L] (a 3-D cross, a jack): six arms around the hidden central cube,
/// 32 vertices, 60 triangles, 12 Reflex edges where the arms meet.
inline MeshShape axes(double L = 3) {
  mesh_shapes_detail::Builder b("axes");
  for (int a = 0; a < 3; ++a)
    for (int s = -1; s <= 1; s += 2) {
      const int u = (a + 1) % 3, v = (a + 2) % 3;
      auto P = [&](double ta, double tu, double tv) {
        Eigen::Vector3d p;
        p[a] = ta;
        p[u] = tu;
        p[v] = tv;
        return p;
      };
      Eigen::Vector3d out = Eigen::Vector3d::Zero();
      out[a] = s;
      b.quad(P(s * L, -1, -1), P(s * L, 1, -1), P(s * L, 1, 1), P(s * L, -1, 1), out);  // end cap
      for (int side = -1; side <= 1; side += 2) {
        Eigen::Vector3d nu = Eigen::Vector3d::Zero(), nv = Eigen::Vector3d::Zero();
        nu[u] = side;
        nv[v] = side;
        b.quad(P(s, side, -1), P(s * L, side, -1), P(s * L, side, 1), P(s, side, 1), nu);
        b.quad(P(s, -1, side), P(s * L, -1, side), P(s * L, 1, side), P(s, 1, side), nv);
      }
    }
  return b.finish(0);
}

/// A closed cup: a thick-walled cylinder open at the top — outer wall (radius outer, z in
/// [0, height]), rim at z = height, inner wall (radius inner, z in [bottom, height]),
/// inner bottom at z = bottom, outer bottom at z = 0; n segments (4 n + 2 vertices, 8 n
/// triangles).
inline MeshShape cup(int n = 16, double outer = 1.0, double inner = 0.8, double height = 1.5, double bottom = 0.2) {
  using mesh_shapes_detail::kPi;
  mesh_shapes_detail::Builder b("cup " + std::to_string(n));
  auto P = [&](int i, double rad, double z) {
    const double a = 2 * kPi * (i % n) / n;
    return Eigen::Vector3d(rad * std::cos(a), rad * std::sin(a), z);
  };
  const Eigen::Vector3d up(0, 0, 1), down(0, 0, -1);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d m = 0.5 * (P(i, 1, 0) + P(i + 1, 1, 0));
    b.quad(P(i, outer, 0), P(i + 1, outer, 0), P(i + 1, outer, height), P(i, outer, height), m);
    b.quad(P(i, outer, height), P(i + 1, outer, height), P(i + 1, inner, height), P(i, inner, height), up);
    b.quad(P(i, inner, height), P(i + 1, inner, height), P(i + 1, inner, bottom), P(i, inner, bottom), -m);
    b.triangle(Eigen::Vector3d(0, 0, bottom), P(i, inner, bottom), P(i + 1, inner, bottom), up);
    b.triangle(Eigen::Vector3d(0, 0, 0), P(i, outer, 0), P(i + 1, outer, 0), down);
  }
  return b.finish(0);
}

/// A spoon: a sheet of constant thickness over the outline of a bowl (an ellipse 8 x 5)
/// and a handle (1 wide), its top dipped into a shallow bowl and the handle bent upwards;
/// the bottom is the top lowered by `thickness` (a height field over a thicker one never
/// meets it). `nx` x `ny` quads on top and bottom, plus the side and end walls.
inline MeshShape spoon(int nx = 28, int ny = 6, double thickness = 0.3) {
  mesh_shapes_detail::Builder b("spoon");
  const double x0 = -3.8, x1 = 10.0, a = 4.0, halfWidth = 2.5, handle = 0.5, depth = 1.2;
  auto width = [&](double x) {
    const double e = 1.0 - (x / a) * (x / a);
    return std::max(handle, e > 0 ? halfWidth * std::sqrt(e) : 0.0);
  };
  auto top = [&](int i, int j) {
    const double x = x0 + (x1 - x0) * i / nx;
    const double y = width(x) * (2.0 * j / ny - 1.0);
    const double q = 1.0 - (x / a) * (x / a) - (y / halfWidth) * (y / halfWidth);
    const double z = -depth * std::max(0.0, q) + 0.08 * std::max(0.0, x - a) * std::max(0.0, x - a);
    return Eigen::Vector3d(x, y, z);
  };
  auto bot = [&](int i, int j) { return Eigen::Vector3d(top(i, j) - Eigen::Vector3d(0, 0, thickness)); };
  const Eigen::Vector3d up(0, 0, 1), down(0, 0, -1), xm(-1, 0, 0), xp(1, 0, 0), ym(0, -1, 0), yp(0, 1, 0);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      b.quad(top(i, j), top(i + 1, j), top(i + 1, j + 1), top(i, j + 1), up);
      b.quad(bot(i, j), bot(i + 1, j), bot(i + 1, j + 1), bot(i, j + 1), down);
    }
  for (int i = 0; i < nx; ++i) {
    b.quad(bot(i, 0), bot(i + 1, 0), top(i + 1, 0), top(i, 0), ym);
    b.quad(bot(i, ny), bot(i + 1, ny), top(i + 1, ny), top(i, ny), yp);
  }
  for (int j = 0; j < ny; ++j) {
    b.quad(bot(0, j), bot(0, j + 1), top(0, j + 1), top(0, j), xm);
    b.quad(bot(nx, j), bot(nx, j + 1), top(nx, j + 1), top(nx, j), xp);
  }
  return b.finish(0);
}

/// Every procedural shape with its default parameters.
inline std::vector<MeshShape> allMeshShapes() {
  return {boxShape(), lBlock(), uBlock(), starPrism(), cubeWithHole(), torus(), cone(), axes(), cup(), spoon()};
}

}  // namespace mink_test
