// examples/planner/segment_check.hpp — is a straight-line translation of a convex robot
// through convex obstacles free? One mink::mdd() per obstacle near the segment.
//
// The robot Q is at its start pose and translates by t·s, t ∈ [0, 1] (s = goal − start,
// world frame; its orientation does not change along the segment). For one obstacle P,
// mdd(P, poseP, Q, poseQ, s) looks at the whole line of s: the set of t for which Q moved
// by t·s meets P is an interval [t_lo, t_hi] (empty when the line of s misses M = P ⊕ −Q),
// and mdd() reports (README "Minimum directional distance", motion applied to Q along s):
//   NoContact               the interval is empty                          → free
//   Separated, parameter p  0 ∉ [t_lo, t_hi]; p is the end nearer 0:
//                           p > 1   the contact lies beyond the goal         → free
//                           p < 0   the interval lies behind the start       → free
//                           0 ≤ p ≤ 1 the robot reaches P on the segment    → blocked
//   Touching, Penetrating   the robot meets P at the start                   → blocked
//   IterationLimit          no answer                                        → blocked (the
//                           conservative call, counted in SegmentCheck::undecided)
// Contact at the goal (p == 1) counts as blocked, as intersects() counts touching.
// The segment is free iff every obstacle is free. Obstacles whose world AABB misses the
// AABB swept by the robot cannot meet it (broad phase) and are not queried.
#pragma once

#include <mink/mink.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace planner {

using Vec3 = mink::Vec3<double>;
using Pose = mink::Pose<double>;
using Polyhedron = mink::ConvexPolyhedron<double>;

/// Closed axis-aligned box, world frame.
struct Aabb {
  Vec3 lo = Vec3::Constant(0.0);
  Vec3 hi = Vec3::Constant(0.0);

  bool overlaps(const Aabb& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
  Aabb merged(const Aabb& o) const { return {lo.cwiseMin(o.lo), hi.cwiseMax(o.hi)}; }
};

/// World AABB of `shape` placed by `pose` (from its vertices; exact up to the rounding of
/// pose.apply, which is far below the gaps a broad phase needs to resolve).
inline Aabb worldAabb(const Polyhedron& shape, const Pose& pose) {
  Aabb box{Vec3::Constant(1e300), Vec3::Constant(-1e300)};
  for (const Vec3& v : shape.vertices()) {
    const Vec3 w = pose.apply(v);
    box.lo = box.lo.cwiseMin(w);
    box.hi = box.hi.cwiseMax(w);
  }
  return box;
}

/// A convex obstacle: its hull in its own frame, its pose and its world AABB.
struct Obstacle {
  Polyhedron shape;
  Pose pose;
  Aabb box;
};

/// The robot link: one convex hull in its own frame and one orientation for the whole
/// scene (a translating body; a segment changes only its position).
struct Robot {
  Polyhedron shape;
  mink::Mat3<double> rotation = mink::Mat3<double>::Identity();

  Pose poseAt(const Vec3& position) const {
    Pose p;
    p.rotation = rotation;
    p.translation = position;
    return p;
  }
};

/// Straight-line motion of the robot's origin from `start` by `s` (goal = start + s).
struct Segment {
  Vec3 start = Vec3::Zero();
  Vec3 s = Vec3::UnitX();
  int from = -1, to = -1;  // the milestones it joins (-1: none)
  bool shortcut = false;   // a path-smoothing shortcut, not a roadmap edge
};

struct Scene {
  Robot robot;
  std::vector<Obstacle> obstacles;
  std::vector<Vec3> milestones;  // robot origin positions, each collision-free
  std::vector<Segment> segments;
};

/// The AABB swept by the robot along the segment: the hull of its boxes at both ends
/// (a translated box sweeps exactly the box spanned by its two end copies' corners).
inline Aabb sweptAabb(const Robot& robot, const Segment& seg) {
  const Aabb a = worldAabb(robot.shape, robot.poseAt(seg.start));
  return a.merged({a.lo + seg.s, a.hi + seg.s});
}

/// Broad phase: indices of the obstacles whose AABB meets the swept AABB, into `out`.
inline void nearbyObstacles(const Scene& scene, const Segment& seg, std::vector<int>& out) {
  out.clear();
  const Aabb swept = sweptAabb(scene.robot, seg);
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
    if (scene.obstacles[i].box.overlaps(swept)) out.push_back(static_cast<int>(i));
}

enum class Verdict { Free, Blocked };

/// The rule of the header comment for one obstacle's mdd() result.
inline Verdict verdictOf(const mink::MddResult<double>& r) {
  switch (r.status) {
    case mink::MddStatus::NoContact:
      return Verdict::Free;
    case mink::MddStatus::Separated:
      return (r.parameter >= 0.0 && r.parameter <= 1.0) ? Verdict::Blocked : Verdict::Free;
    default:  // Touching, Penetrating, IterationLimit
      return Verdict::Blocked;
  }
}

struct SegmentCheck {
  Verdict verdict = Verdict::Free;
  int blocker = -1;    // first obstacle found blocking (-1 when free)
  double contact = 0;  // its mdd parameter: where along the segment (0..1) the robot meets it
  int queries = 0;     // mdd() calls made
  int undecided = 0;   // IterationLimit answers (treated as blocked)
};

/// Exact-up-to-rounding validity of one segment: mdd() against every obstacle in
/// `candidates` (from nearbyObstacles), stopping at the first blocking one.
/// `caches`: null, or one MddCache per obstacle of the scene (index = obstacle), kept by
/// the caller across segments so that successive queries of a pair start warm.
inline SegmentCheck checkSegmentMdd(const Scene& scene, const Segment& seg,
                                    const std::vector<int>& candidates,
                                    std::vector<mink::MddCache<double>>* caches = nullptr) {
  SegmentCheck out;
  const Pose poseQ = scene.robot.poseAt(seg.start);
  for (int i : candidates) {
    const Obstacle& ob = scene.obstacles[static_cast<std::size_t>(i)];
    const mink::MddResult<double> r =
        caches ? mink::mdd(ob.shape, ob.pose, scene.robot.shape, poseQ, seg.s, (*caches)[static_cast<std::size_t>(i)])
               : mink::mdd(ob.shape, ob.pose, scene.robot.shape, poseQ, seg.s);
    ++out.queries;
    if (r.status == mink::MddStatus::IterationLimit) ++out.undecided;
    if (verdictOf(r) == Verdict::Blocked) {
      out.verdict = Verdict::Blocked;
      out.blocker = i;
      out.contact = r.status == mink::MddStatus::Separated ? r.parameter : 0.0;
      return out;
    }
  }
  return out;
}

}  // namespace planner
