// tests/support/bumpy_cube.hpp — a closed mesh that is convex only within a tolerance:
// the cube [-1, 1]^3, each face a g x g grid of squares split into triangles
// (counter-clockwise from outside), every grid point inside a face moved off its plane
// by up to `delta` (uniform, seeded). fromMesh<double> accepts it for delta up to about
// 1e-14 (its automatic tolerance is ~2e-14 here); the DK hierarchy then has holes with
// no exact fill. Used by tests/hierarchy/dk_hierarchy_test.cpp and the foundation
// benchmark.
#pragma once

#include <random>
#include <utility>
#include <vector>

#include "mink/core/types.hpp"

namespace mink_test {

inline std::pair<std::vector<mink::Vec3<double>>, std::vector<std::vector<int>>> bumpyCube(int g, double delta,
                                                                                           unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> bump(-delta, delta);
  std::vector<mink::Vec3<double>> vertices;
  std::vector<std::vector<int>> faces;
  std::vector<int> id((g + 1) * (g + 1) * (g + 1), -1);
  const auto vertex = [&](int a, int b, int c) {
    int& slot = id[(a * (g + 1) + b) * (g + 1) + c];
    if (slot >= 0) return slot;
    mink::Vec3<double> p(2.0 * a / g - 1, 2.0 * b / g - 1, 2.0 * c / g - 1);
    const int inside = (a > 0 && a < g) + (b > 0 && b < g) + (c > 0 && c < g);
    if (inside == 2) {
      for (int k = 0; k < 3; ++k)
        if (p[k] == 1.0 || p[k] == -1.0) p[k] += bump(rng);
    }
    slot = static_cast<int>(vertices.size());
    vertices.push_back(p);
    return slot;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < g; ++i) {
        for (int j = 0; j < g; ++j) {
          const auto at = [&](int a, int b) {
            int c[3];
            c[axis] = side ? g : 0;
            c[(axis + 1) % 3] = a;
            c[(axis + 2) % 3] = b;
            return vertex(c[0], c[1], c[2]);
          };
          const int q0 = at(i, j), q1 = at(i + 1, j), q2 = at(i + 1, j + 1), q3 = at(i, j + 1);
          if (side) {
            faces.push_back({q0, q1, q2});
            faces.push_back({q0, q2, q3});
          } else {
            faces.push_back({q0, q2, q1});
            faces.push_back({q0, q3, q2});
          }
        }
      }
    }
  }
  return {vertices, faces};
}

}  // namespace mink_test
