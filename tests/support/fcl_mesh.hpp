// tests/support/fcl_mesh.hpp — FCL's mesh BVH as the reference for mesh overlap (tests
// and benchmarks; FCL only, no CGAL): an fcl::BVHModel<OBBRSSd> of a TriangleMesh, and
// collide / distance of two such models with B placed in A's frame.
#pragma once

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <memory>
#include <vector>

#include "mink/mesh/triangle_mesh.hpp"

namespace mink_test {

using FclMesh = fcl::BVHModel<fcl::OBBRSSd>;

inline std::shared_ptr<FclMesh> fclModel(const mink::TriangleMesh<double>& m) {
  auto model = std::make_shared<FclMesh>();
  std::vector<fcl::Vector3d> pts(m.vertices().begin(), m.vertices().end());
  std::vector<fcl::Triangle> tris;
  for (const auto& t : m.triangles()) tris.emplace_back(t[0], t[1], t[2]);
  model->beginModel();
  model->addSubModel(pts, tris);
  model->endModel();
  return model;
}

/// Two FCL mesh models, A at the identity and B placed by (R, t) in A's frame.
class FclPair {
 public:
  FclPair(const mink::TriangleMesh<double>& A, const mink::TriangleMesh<double>& B)
      : a_(fclModel(A), fcl::Transform3d::Identity()), b_(fclModel(B), fcl::Transform3d::Identity()) {}

  /// fcl::collide: do the boundaries meet (FCL sees no containment)?
  bool collide(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
    place(R, t);
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    fcl::collide(&a_, &b_, request, result);
    return result.isCollision();
  }
  /// fcl::distance between the boundaries (FCL's value when they meet: 0 or negative).
  double distance(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
    place(R, t);
    fcl::DistanceRequestd request;
    fcl::DistanceResultd result;
    fcl::distance(&a_, &b_, request, result);
    return result.min_distance;
  }

 private:
  void place(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.linear() = R;
    tf.translation() = t;
    b_.setTransform(tf);
    b_.computeAABB();
  }
  fcl::CollisionObjectd a_, b_;
};

}  // namespace mink_test
