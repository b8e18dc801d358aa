// examples/planner/fcl_checks.hpp — the same segment checks done the usual ways with FCL
// 0.7, for comparison with checkSegmentMdd (segment_check.hpp):
//   * sampling: fcl::collide at n evenly spaced poses t = i/(n−1), i = 0..n−1 (101 poses:
//     a step of 1 % of the segment; 1001: 0.1 %); misses contacts between two samples;
//   * conservative advancement: fcl::continuousCollide with CCDC_CONSERVATIVE_ADVANCEMENT
//     and CCDM_TRANS (translation motion; FCL 0.7 has it for shape pairs, here Convex ×
//     Convex), its distances from libccd's GJK (GST_LIBCCD, FCL's default) or FCL's own
//     (GST_INDEP). It advances by distance / motion bound and stops when the step falls
//     below its time tolerance, so a near miss can be called a contact, and a distance
//     that is too large lets it step over a contact.
// Every shape is an fcl::Convex built from the faces of the same mink hull, so all
// methods see the same polyhedra. Broad phase: the candidates of nearbyObstacles().
#pragma once

#include "segment_check.hpp"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/geometry/shape/convex.h>

#include <memory>
#include <vector>

namespace planner {

/// fcl::Convex with the vertices and face loops of a mink hull (its own frame).
inline std::shared_ptr<fcl::Convex<double>> toFcl(const Polyhedron& shape) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(shape.vertices().begin(), shape.vertices().end());
  auto faces = std::make_shared<std::vector<int>>();
  for (int f = 0; f < shape.numFaces(); ++f) {
    faces->push_back(shape.faceSize(f));
    for (int v : shape.faceVertices(f)) faces->push_back(v);
  }
  return std::make_shared<fcl::Convex<double>>(vertices, shape.numFaces(), faces);
}

/// mink::Pose → FCL's transform (fcl::Transform3d is Eigen::Isometry3d).
inline fcl::Transform3d toFcl(const Pose& pose) { return pose.toIsometry(); }

/// The scene's shapes and obstacle transforms as FCL sees them.
struct FclScene {
  std::shared_ptr<fcl::Convex<double>> robot;
  std::vector<std::shared_ptr<fcl::Convex<double>>> obstacles;
  std::vector<fcl::Transform3d> obstaclePoses;

  explicit FclScene(const Scene& scene) : robot(toFcl(scene.robot.shape)) {
    for (const Obstacle& ob : scene.obstacles) {
      obstacles.push_back(toFcl(ob.shape));
      obstaclePoses.push_back(toFcl(ob.pose));
    }
  }
};

/// fcl::collide at `poses` evenly spaced poses (>= 2) along the segment, from the start.
inline Verdict checkSegmentSampled(const Scene& scene, const FclScene& fcl, const Segment& seg,
                                   const std::vector<int>& candidates, int poses) {
  const fcl::CollisionRequestd request;  // boolean query, one contact
  fcl::Transform3d tf = toFcl(scene.robot.poseAt(seg.start));
  for (int k = 0; k < poses; ++k) {
    tf.translation() = seg.start + (static_cast<double>(k) / (poses - 1)) * seg.s;
    for (int i : candidates) {
      fcl::CollisionResultd result;
      if (fcl::collide(fcl.obstacles[static_cast<std::size_t>(i)].get(), fcl.obstaclePoses[static_cast<std::size_t>(i)],
                       fcl.robot.get(), tf, request, result))
        return Verdict::Blocked;
    }
  }
  return Verdict::Free;
}

/// fcl::continuousCollide, conservative advancement on translation motion, per candidate,
/// with the GJK of `solver` (fcl::GST_LIBCCD or fcl::GST_INDEP).
inline Verdict checkSegmentConservativeAdvancement(const Scene& scene, const FclScene& fcl, const Segment& seg,
                                                   const std::vector<int>& candidates,
                                                   fcl::GJKSolverType solver = fcl::GST_LIBCCD) {
  fcl::ContinuousCollisionRequestd request;
  request.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
  request.ccd_motion_type = fcl::CCDM_TRANS;
  request.gjk_solver_type = solver;
  const fcl::Transform3d begin = toFcl(scene.robot.poseAt(seg.start));
  fcl::Transform3d end = begin;
  end.translation() += seg.s;
  for (int i : candidates) {
    const fcl::Transform3d& tfP = fcl.obstaclePoses[static_cast<std::size_t>(i)];
    fcl::ContinuousCollisionResultd result;
    fcl::continuousCollide(fcl.obstacles[static_cast<std::size_t>(i)].get(), tfP, tfP, fcl.robot.get(), begin, end,
                           request, result);
    if (result.is_collide) return Verdict::Blocked;
  }
  return Verdict::Free;
}

}  // namespace planner
