// examples/planner/scene.hpp — the planner example's scenes, from a fixed seed.
//
// Random scene: a 20 × 20 × 2 workspace (metres) with boxes, thin panels (1–2 cm walls)
// and random convex hulls standing on the floor, a rod-like robot link (an octagonal prism
// 1 m long, 4 cm across) at one fixed orientation, and a probabilistic roadmap: milestones
// drawn uniformly and kept when mink::intersects() says the robot there is clear of every
// obstacle, each joined to its k nearest milestones by a straight segment (short edges),
// and path-smoothing shortcuts between random pairs of milestones (long segments).
// Thin-wall scene: one panel 1 cm thick and one segment through it placed between two of
// the 101 poses a 1 % sampling checks (the case sampling misses by construction).
#pragma once

#include "segment_check.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace planner {

struct SceneSize {
  int obstacles = 36;
  int milestones = 150;
  int neighbours = 5;  // roadmap: each milestone joined to this many nearest ones
  int shortcuts = 150;  // path-smoothing attempts: segments between random milestone pairs
  unsigned seed = 2024;
};

inline mink::Mat3<double> yawRotation(double yaw) {
  mink::Mat3<double> R;
  const double c = std::cos(yaw), s = std::sin(yaw);
  R << c, -s, 0, s, c, 0, 0, 0, 1;
  return R;
}

/// Box with half extents h, centred at the origin of its frame.
inline std::vector<Vec3> boxPoints(const Vec3& h) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i)
    pts.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
  return pts;
}

/// The robot link: an octagonal prism along x, `length` long, `radius` to its corners.
inline std::vector<Vec3> rodPoints(double length, double radius) {
  std::vector<Vec3> pts;
  const double pi = std::acos(-1.0);
  for (int end = 0; end < 2; ++end)
    for (int k = 0; k < 8; ++k) {
      const double a = (k + 0.5) * pi / 4;
      pts.emplace_back(end ? length / 2 : -length / 2, radius * std::cos(a), radius * std::sin(a));
    }
  return pts;
}

inline Obstacle makeObstacle(const std::vector<Vec3>& localPoints, const Pose& pose) {
  Obstacle ob{Polyhedron::fromPoints(localPoints), pose, {}};
  ob.box = worldAabb(ob.shape, ob.pose);
  return ob;
}

inline bool poseIsFree(const Scene& scene, const Vec3& position) {
  const Pose q = scene.robot.poseAt(position);
  const Aabb box = worldAabb(scene.robot.shape, q);
  for (const Obstacle& ob : scene.obstacles)
    if (ob.box.overlaps(box) && mink::intersects(ob.shape, ob.pose, scene.robot.shape, q)) return false;
  return true;
}

/// Roadmap edges: each milestone to its `k` nearest (each undirected edge once, i < j).
inline void connectRoadmap(Scene& scene, int k) {
  const int n = static_cast<int>(scene.milestones.size());
  std::vector<std::pair<int, int>> edges;
  for (int i = 0; i < n; ++i) {
    std::vector<std::pair<double, int>> byDistance;
    for (int j = 0; j < n; ++j)
      if (j != i) byDistance.emplace_back((scene.milestones[j] - scene.milestones[i]).squaredNorm(), j);
    const int m = std::min(k, n - 1);
    std::partial_sort(byDistance.begin(), byDistance.begin() + m, byDistance.end());
    for (int q = 0; q < m; ++q) edges.emplace_back(std::min(i, byDistance[q].second), std::max(i, byDistance[q].second));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) {
    Segment seg;
    seg.start = scene.milestones[a];
    seg.s = scene.milestones[b] - scene.milestones[a];  // rounded once; the motion is start + t s
    seg.from = a;
    seg.to = b;
    scene.segments.push_back(seg);
  }
}

inline Scene makeRandomScene(const SceneSize& size) {
  std::mt19937 rng(size.seed);
  auto uniform = [&rng](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  const double pi = std::acos(-1.0);

  Scene scene{Robot{Polyhedron::fromPoints(rodPoints(1.0, 0.02)), yawRotation(0.35)}, {}, {}, {}};
  for (int i = 0; i < size.obstacles; ++i) {
    Pose pose;
    pose.rotation = yawRotation(uniform(0.0, pi));
    const int kind = i % 3;
    std::vector<Vec3> pts;
    if (kind == 0) {  // box
      pts = boxPoints(Vec3(uniform(0.2, 0.9), uniform(0.2, 0.9), uniform(0.4, 1.0)));
    } else if (kind == 1) {  // thin panel: a wall 1–2 cm thick
      pts = boxPoints(Vec3(uniform(0.6, 2.0), uniform(0.005, 0.01), uniform(0.6, 1.0)));
    } else {  // random convex hull of 14 points in an ellipsoid
      const Vec3 radii(uniform(0.3, 1.0), uniform(0.3, 1.0), uniform(0.4, 1.0));
      for (int p = 0; p < 14; ++p) {
        Vec3 u;
        do u = Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        while (u.squaredNorm() > 1.0);
        pts.push_back(u.cwiseProduct(radii));
      }
    }
    double zmin = 1e300;
    for (const Vec3& p : pts) zmin = std::min(zmin, p.z());
    pose.translation = Vec3(uniform(1.0, 19.0), uniform(1.0, 19.0), -zmin);  // on the floor z = 0
    scene.obstacles.push_back(makeObstacle(pts, pose));
  }
  for (int tries = 0; static_cast<int>(scene.milestones.size()) < size.milestones && tries < 100 * size.milestones;
       ++tries) {
    const Vec3 p(uniform(0.5, 19.5), uniform(0.5, 19.5), uniform(0.3, 1.2));
    if (poseIsFree(scene, p)) scene.milestones.push_back(p);
  }
  connectRoadmap(scene, size.neighbours);
  const int n = static_cast<int>(scene.milestones.size());
  for (int i = 0; i < size.shortcuts && n >= 2; ++i) {
    const int a = std::uniform_int_distribution<int>(0, n - 1)(rng);
    int b = std::uniform_int_distribution<int>(0, n - 2)(rng);
    b += b >= a;
    Segment seg;
    seg.start = scene.milestones[a];
    seg.s = scene.milestones[b] - scene.milestones[a];
    seg.from = a;
    seg.to = b;
    seg.shortcut = true;
    scene.segments.push_back(seg);
  }
  return scene;
}

/// One 1 cm panel across the x axis and one 8 m segment through it, robot turned across
/// the motion. The robot meets the panel only while its centre is about 4.017–4.063 m from
/// the start (below); a 1 % sampling looks at 4.00 and 4.08 m. A second segment stops
/// 0.2 m short of the panel (free).
inline Scene makeThinWallScene() {
  Scene scene{Robot{Polyhedron::fromPoints(rodPoints(1.0, 0.02)), yawRotation(0.5 * std::acos(-1.0))}, {}, {}, {}};
  Pose wall;
  wall.translation = Vec3(4.04, 0.0, 1.0);
  scene.obstacles.push_back(makeObstacle(boxPoints(Vec3(0.005, 2.0, 1.0)), wall));
  // rodPoints puts octagon corners at ±radius·cos(22.5°) along x after the 90° yaw: the
  // robot's extent along x is 2 · 0.02 · cos(22.5°) = 0.037 m, so contact is for centre
  // positions in (4.035 − 0.0185, 4.045 + 0.0185) = (4.0165, 4.0635): between the samples.
  Segment through;
  through.start = Vec3(0.0, 0.0, 1.0);
  through.s = Vec3(8.0, 0.0, 0.0);
  scene.segments.push_back(through);
  Segment shortOf;
  shortOf.start = Vec3(0.0, 0.3, 1.0);
  shortOf.s = Vec3(3.8, 0.0, 0.0);
  scene.segments.push_back(shortOf);
  return scene;
}

}  // namespace planner
