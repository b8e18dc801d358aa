// examples/planner/segment_check.hpp — is a straight-line translation of a convex robot
// through convex obstacles free? One mink::firstContact() (one mdd()) per obstacle near
// the segment.
//
// The robot Q is at its start pose and translates by t·s, t ∈ [0, 1] (s = goal − start,
// world frame; its orientation does not change along the segment). For one obstacle P,
// mink::firstContact(P, poseP, Q, poseQ, s) reads the first contact over t ∈ [0, 1] off one
// mdd() along s (the set of t for which Q moved by t·s meets P is an interval [t_lo, t_hi]
// of the line): a contact anywhere on the segment, touching at the start or at the goal
// included, blocks it; an mdd() IterationLimit counts as a contact at the start (the
// conservative call, counted in SegmentCheck::undecided).
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

/// World AABB of `shape` placed by `pose`: ConvexPolyhedron::worldBounds (six support
/// queries, padded by the rounding of pose.apply), not a scan of every vertex.
inline Aabb worldAabb(const Polyhedron& shape, const Pose& pose) {
  const auto bounds = shape.worldBounds(pose);
  return {bounds.first, bounds.second};
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

struct SegmentCheck {
  Verdict verdict = Verdict::Free;
  int blocker = -1;    // first obstacle found blocking (-1 when free)
  double contact = 0;  // where along the segment (0..1) the robot first meets it
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
    const mink::FirstContact<double> c =
        caches ? mink::firstContact(ob.shape, ob.pose, scene.robot.shape, poseQ, seg.s,
                                    (*caches)[static_cast<std::size_t>(i)])
               : mink::firstContact(ob.shape, ob.pose, scene.robot.shape, poseQ, seg.s);
    ++out.queries;
    if (c.mdd.status == mink::MddStatus::IterationLimit) ++out.undecided;
    if (c.hit) {
      out.verdict = Verdict::Blocked;
      out.blocker = i;
      out.contact = c.fraction;
      return out;
    }
  }
  return out;
}

}  // namespace planner
