// tests/support/gjk_reference.hpp — GJK-family references (FCL 0.7 and libccd 2.1) for the
// distance and overlap of two convex point sets at given poses. Test/benchmark support only.
//
// Source: the MDD-DUAL paper (Choi et al.), Sec. VII, verifies each MDD by moving the shape
// by the reported translation and measuring the GJK distance, which must be ~0. This header
// supplies those GJK measurements from libraries independent of mink:
//   1. the hull of each point set (vertices + outward CCW triangles) comes from CGAL's
//      convex_hull_3 over Epick: exact predicates on the input doubles, so the hull
//      vertices are exactly the extreme input points;
//   2. FCL: fcl::Convexd from that mesh, fcl::distance / fcl::collide with FCL's own GJK
//      (GST_INDEP, our default) or its libccd-based solver (GST_LIBCCD, FCL's default, but
//      its distance is unreliable, see fclDistance); penetration depth via GST_LIBCCD's EPA;
//   3. libccd: brute-force support over the world-frame vertex list, ccdGJKIntersect,
//      ccdMPRIntersect, ccdGJKPenetration (EPA), ccdMPRPenetration. Debian's libccd 2.1
//      exports no distance function (`nm -D libccd.so.2`: no ccdGJKDist), so
//      ccdDistanceBisection measures the distance as the smallest r for which A and
//      B ⊕ ball(r) intersect (ccdGJKIntersect on a sphere-swept support), by bisection;
//   4. certifiedDistance: FCL's answers checked by brute force (nearest-point distance as
//      upper bound, separating-plane gap along the same direction as lower bound). Use it
//      as THE distance reference: plain FCL was measured wrong on touching paper shapes.
// Poses are any type with members `rotation` (3x3) and `translation` (3-vector), e.g.
// mink::Pose<double> or RigidPose below: x_world = rotation * x_shape + translation.
// All distances are in units of length, all points in the world frame.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <ccd/ccd.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace mink_test {

/// Identity by default; x_world = rotation * x_shape + translation.
struct RigidPose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

template <class PoseLike>
Eigen::Isometry3d toIsometry(const PoseLike& pose) {
  Eigen::Isometry3d tf = Eigen::Isometry3d::Identity();
  tf.linear() = pose.rotation;
  tf.translation() = pose.translation;
  return tf;
}

/// Convex hull of a point set as a closed triangle mesh.
struct ConvexHullMesh {
  std::vector<Eigen::Vector3d> vertices;       // the extreme input points (exact copies), shape frame
  std::vector<std::array<int, 3>> triangles;   // indices into vertices, CCW seen from outside
};

/// Hull with exact predicates (CGAL Epick). Throws std::invalid_argument for fewer than four
/// affinely independent points.
inline ConvexHullMesh convexHullMesh(const std::vector<Eigen::Vector3d>& points) {
  using K = CGAL::Epick;
  using Point = K::Point_3;
  std::vector<Point> pts;
  pts.reserve(points.size());
  for (const auto& p : points) pts.emplace_back(p.x(), p.y(), p.z());
  // convex_hull_3 silently returns a flat or empty mesh for degenerate input.
  std::size_t idx[3] = {0, 0, 0};
  int found = pts.empty() ? 0 : 1;
  bool solid = false;
  for (std::size_t i = 1; i < pts.size() && !solid; ++i) {
    if (found == 1 && pts[i] != pts[idx[0]]) idx[found++] = i;
    else if (found == 2 && !CGAL::collinear(pts[idx[0]], pts[idx[1]], pts[i])) idx[found++] = i;
    else if (found == 3 && !CGAL::coplanar(pts[idx[0]], pts[idx[1]], pts[idx[2]], pts[i]))
      solid = true;
  }
  if (!solid)
    throw std::invalid_argument("convexHullMesh: the points do not span a 3-dimensional hull");

  CGAL::Surface_mesh<Point> mesh;
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
  ConvexHullMesh out;
  std::vector<int> index(mesh.num_vertices(), -1);
  for (auto v : mesh.vertices()) {
    index[v.idx()] = static_cast<int>(out.vertices.size());
    const Point& p = mesh.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto f : mesh.faces()) {
    std::array<int, 3> tri{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k == 3) throw std::logic_error("convexHullMesh: non-triangular facet");
      tri[static_cast<std::size_t>(k++)] = index[v.idx()];
    }
    if (k != 3) throw std::logic_error("convexHullMesh: degenerate facet");
    out.triangles.push_back(tri);
  }
  return out;
}

/// A convex shape ready for FCL and libccd: its hull, and an fcl::Convexd built from it.
class GjkShape {
 public:
  explicit GjkShape(const std::vector<Eigen::Vector3d>& points) : hull_(convexHullMesh(points)) {
    auto verts = std::make_shared<std::vector<fcl::Vector3d>>(hull_.vertices.begin(),
                                                              hull_.vertices.end());
    auto faces = std::make_shared<std::vector<int>>();
    faces->reserve(4 * hull_.triangles.size());
    for (const auto& t : hull_.triangles) {
      faces->push_back(3);  // FCL's face encoding: count, then the indices, CCW from outside
      faces->insert(faces->end(), t.begin(), t.end());
    }
    // throw_if_invalid: FCL checks the mesh is watertight (needed by its hill climbing).
    convex_ = std::make_shared<fcl::Convexd>(verts, static_cast<int>(hull_.triangles.size()),
                                             faces, /*throw_if_invalid=*/true);
  }

  const ConvexHullMesh& hull() const { return hull_; }
  const fcl::Convexd& fclConvex() const { return *convex_; }

 private:
  ConvexHullMesh hull_;
  std::shared_ptr<fcl::Convexd> convex_;
};

struct FclDistanceResult {
  double distance = 0.0;   // > 0 when separated; when colliding FCL's value is
                           // implementation defined (-1 or 0): use `colliding`
  bool colliding = false;  // fcl::collide with the same solver
  Eigen::Vector3d pointOnA = Eigen::Vector3d::Zero();  // nearest points, world frame
  Eigen::Vector3d pointOnB = Eigen::Vector3d::Zero();  // (valid when separated)
};

/// FCL distance between A at poseA and B at poseB. `tolerance` is FCL's GJK stopping
/// threshold (DistanceRequest::distance_tolerance, units of length).
/// Solver choice: FCL 0.7's GST_LIBCCD distance stops early on some separated convex
/// pairs and returns a wrong, too large value (measured here: two unit boxes 2 apart gave
/// sqrt(6), a rotated box at distance 2 from a face gave 2.1213; FCL issue #508, open), so
/// the default is FCL's own GJK (GST_INDEP), which was exact in every such case.
template <class PoseA, class PoseB>
FclDistanceResult fclDistance(const GjkShape& A, const PoseA& poseA, const GjkShape& B,
                              const PoseB& poseB, fcl::GJKSolverType solver = fcl::GST_INDEP,
                              double tolerance = 1e-12) {
  const Eigen::Isometry3d ta = toIsometry(poseA), tb = toIsometry(poseB);
  FclDistanceResult out;
  {
    fcl::DistanceRequestd request(/*enable_nearest_points=*/true, /*enable_signed_distance=*/false,
                                  0.0, 0.0, tolerance, solver);
    fcl::DistanceResultd result;
    out.distance = fcl::distance(&A.fclConvex(), ta, &B.fclConvex(), tb, request, result);
    out.pointOnA = result.nearest_points[0];
    out.pointOnB = result.nearest_points[1];
  }
  {
    fcl::CollisionRequestd request;
    request.gjk_solver_type = solver;
    fcl::CollisionResultd result;
    out.colliding = fcl::collide(&A.fclConvex(), ta, &B.fclConvex(), tb, request, result) > 0;
  }
  return out;
}

namespace gjk_reference_detail {

// A point set in the world frame, optionally swept by a ball of radius `sweep`.
struct CcdBody {
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double sweep = 0.0;
};

template <class Pose>
CcdBody makeBody(const GjkShape& shape, const Pose& pose) {
  CcdBody b;
  const Eigen::Isometry3d tf = toIsometry(pose);
  for (const auto& v : shape.hull().vertices) {
    b.points.push_back(tf * v);
    b.centre += b.points.back();
  }
  b.centre /= static_cast<double>(b.points.size());
  return b;
}

inline void support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const CcdBody& b = *static_cast<const CcdBody*>(obj);
  const Eigen::Vector3d d(dir->v[0], dir->v[1], dir->v[2]);
  std::size_t best = 0;
  double bestDot = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const double x = d.dot(b.points[i]);
    if (x > bestDot) {
      bestDot = x;
      best = i;
    }
  }
  Eigen::Vector3d p = b.points[best];
  const double n = d.norm();
  if (b.sweep > 0.0 && n > 0.0) p += (b.sweep / n) * d;
  ccdVec3Set(out, p.x(), p.y(), p.z());
}

inline void centre(const void* obj, ccd_vec3_t* out) {
  const CcdBody& b = *static_cast<const CcdBody*>(obj);
  ccdVec3Set(out, b.centre.x(), b.centre.y(), b.centre.z());
}

inline ccd_t makeCcd(unsigned long maxIterations = 1000) {
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = support;
  ccd.support2 = support;
  ccd.center1 = centre;
  ccd.center2 = centre;
  ccd.max_iterations = maxIterations;
  ccd.epa_tolerance = 1e-10;
  ccd.mpr_tolerance = 1e-10;
  ccd.dist_tolerance = 1e-12;
  return ccd;
}

}  // namespace gjk_reference_detail

/// libccd GJK overlap test (true: the closed shapes intersect, up to libccd's tolerances).
template <class PoseA, class PoseB>
bool ccdIntersectGJK(const GjkShape& A, const PoseA& poseA, const GjkShape& B, const PoseB& poseB) {
  namespace d = gjk_reference_detail;
  const d::CcdBody a = d::makeBody(A, poseA), b = d::makeBody(B, poseB);
  const ccd_t ccd = d::makeCcd();
  return ccdGJKIntersect(&a, &b, &ccd) != 0;
}

/// libccd MPR overlap test.
template <class PoseA, class PoseB>
bool ccdIntersectMPR(const GjkShape& A, const PoseA& poseA, const GjkShape& B, const PoseB& poseB) {
  namespace d = gjk_reference_detail;
  const d::CcdBody a = d::makeBody(A, poseA), b = d::makeBody(B, poseB);
  const ccd_t ccd = d::makeCcd();
  return ccdMPRIntersect(&a, &b, &ccd) != 0;
}

struct CcdPenetration {
  bool intersecting = false;
  double depth = 0.0;                                   // >= 0, units of length
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit: moving B by depth·direction
                                                        // makes A and B touch (libccd convention)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();   // contact point, world frame
};

namespace gjk_reference_detail {
template <class PoseA, class PoseB, class Fn>
CcdPenetration penetration(const GjkShape& A, const PoseA& poseA, const GjkShape& B,
                           const PoseB& poseB, Fn fn) {
  const CcdBody a = makeBody(A, poseA), b = makeBody(B, poseB);
  const ccd_t ccd = makeCcd();
  ccd_real_t depth = 0;
  ccd_vec3_t dir, pos;
  ccdVec3Set(&dir, 0, 0, 0);
  ccdVec3Set(&pos, 0, 0, 0);
  CcdPenetration out;
  out.intersecting = fn(&a, &b, &ccd, &depth, &dir, &pos) == 0;
  if (out.intersecting) {
    out.depth = depth;
    out.direction = Eigen::Vector3d(dir.v[0], dir.v[1], dir.v[2]);
    out.position = Eigen::Vector3d(pos.v[0], pos.v[1], pos.v[2]);
  }
  return out;
}
}  // namespace gjk_reference_detail

/// Penetration depth by GJK + EPA (approximate to libccd's epa_tolerance, set to 1e-10).
template <class PoseA, class PoseB>
CcdPenetration ccdPenetrationEPA(const GjkShape& A, const PoseA& poseA, const GjkShape& B,
                                 const PoseB& poseB) {
  return gjk_reference_detail::penetration(A, poseA, B, poseB, ccdGJKPenetration);
}

/// Penetration along MPR's portal direction (not the minimum depth in general).
template <class PoseA, class PoseB>
CcdPenetration ccdPenetrationMPR(const GjkShape& A, const PoseA& poseA, const GjkShape& B,
                                 const PoseB& poseB) {
  return gjk_reference_detail::penetration(A, poseA, B, poseB, ccdMPRPenetration);
}

/// Euclidean distance between A and B (0 if they intersect) with libccd only: the smallest
/// r with A ∩ (B ⊕ ball(r)) ≠ ∅, by bisection on ccdGJKIntersect until the bracket is
/// narrower than `tolerance` (units of length). Starts from [0, |centre_A − centre_B|]: the
/// vertex centroids lie inside the shapes, so that bound is at least the distance.
template <class PoseA, class PoseB>
double ccdDistanceBisection(const GjkShape& A, const PoseA& poseA, const GjkShape& B,
                            const PoseB& poseB, double tolerance = 1e-11) {
  namespace d = gjk_reference_detail;
  const d::CcdBody a = d::makeBody(A, poseA);
  d::CcdBody b = d::makeBody(B, poseB);
  const ccd_t ccd = d::makeCcd();
  if (ccdGJKIntersect(&a, &b, &ccd)) return 0.0;
  double lo = 0.0, hi = (a.centre - b.centre).norm();
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    b.sweep = mid;
    (ccdGJKIntersect(&a, &b, &ccd) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

/// A distance with a brute-force certificate. FCL's GJK answers are checked rather than
/// trusted: a pair of nearest points pA ∈ A, pB ∈ B gives the upper bound |pA − pB|, and the
/// unit direction n = (pB − pA)/|pB − pA| gives the lower bound
/// min_{b ∈ B} n·b − max_{a ∈ A} n·a (a separating-plane gap, over all vertices, brute force).
/// When the two meet, the distance is certified; at (near) contact n is ill-defined and the
/// answer falls back to libccd. Measured failures this guards against:
/// FCL 0.7 GST_INDEP reported 8.4e-4 (and "not colliding") for two paper shapes that touch,
/// GST_LIBCCD reported sqrt(6) for two boxes 2 apart.
struct CertifiedDistance {
  double distance = 0.0;    // certified value, else libccd's bisection distance (0 = overlap)
  double lowerBound = -std::numeric_limits<double>::infinity();  // best gap found (< 0: overlap
                                                                 // along that n)
  double upperBound = std::numeric_limits<double>::infinity();   // best |pA − pB| found
  bool certified = false;   // upperBound − lowerBound <= tolerance (absolute, units of length)
  int source = -1;          // what gave the certified pair: 0 FCL GST_INDEP, 1 FCL GST_LIBCCD;
                            // -1: none, `distance` is libccd's (accurate to ~2e-8)
};

/// Distance of A and B, certified when possible (see CertifiedDistance). Overlapping shapes
/// are never certified (no FCL pair is valid then) and get distance 0 from libccd, unless
/// libccd finds them apart.
template <class PoseA, class PoseB>
CertifiedDistance certifiedDistance(const GjkShape& A, const PoseA& poseA, const GjkShape& B,
                                    const PoseB& poseB, double tolerance = 1e-9) {
  const Eigen::Isometry3d ta = toIsometry(poseA), tb = toIsometry(poseB);
  std::vector<Eigen::Vector3d> a, b;
  for (const auto& v : A.hull().vertices) a.push_back(ta * v);
  for (const auto& v : B.hull().vertices) b.push_back(tb * v);
  auto gap = [&](const Eigen::Vector3d& n) {
    double maxA = -std::numeric_limits<double>::infinity();
    double minB = std::numeric_limits<double>::infinity();
    for (const auto& x : a) maxA = std::max(maxA, n.dot(x));
    for (const auto& x : b) minB = std::min(minB, n.dot(x));
    return minB - maxA;
  };
  CertifiedDistance out;
  const fcl::GJKSolverType solvers[2] = {fcl::GST_INDEP, fcl::GST_LIBCCD};
  for (int i = 0; i < 2; ++i) {
    const FclDistanceResult r = fclDistance(A, poseA, B, poseB, solvers[i]);
    if (r.colliding || !(r.distance > 0.0)) continue;
    const Eigen::Vector3d d = r.pointOnB - r.pointOnA;
    const double len = d.norm();
    if (!(len > 0.0)) continue;
    out.upperBound = std::min(out.upperBound, len);
    out.lowerBound = std::max(out.lowerBound, gap(d / len));
    if (out.upperBound - out.lowerBound <= tolerance) {
      out.certified = true;
      out.source = i;
      out.distance = 0.5 * (out.upperBound + out.lowerBound);
      return out;
    }
  }
  out.distance = ccdDistanceBisection(A, poseA, B, poseB);
  return out;
}

/// Signed distance: the certified distance when there is one (separated shapes), otherwise
/// FCL's GST_LIBCCD signed distance, i.e. −(penetration depth) from its EPA (approximate;
/// it may also come out >= 0 near contact). Returns NaN when FCL throws, which its EPA does
/// on some touching inputs (FCL issues #390, #493). GST_INDEP's signed distance is not
/// used: on two Convex shapes FCL 0.7 can index contacts[-1] there (a libfcl assertion).
template <class PoseA, class PoseB>
double fclSignedDistance(const GjkShape& A, const PoseA& poseA, const GjkShape& B,
                         const PoseB& poseB, double tolerance = 1e-12) {
  const CertifiedDistance c = certifiedDistance(A, poseA, B, poseB);
  if (c.certified) return c.distance;
  const Eigen::Isometry3d ta = toIsometry(poseA), tb = toIsometry(poseB);
  fcl::DistanceRequestd request(false, /*enable_signed_distance=*/true, 0.0, 0.0, tolerance,
                                fcl::GST_LIBCCD);
  fcl::DistanceResultd result;
  try {
    return fcl::distance(&A.fclConvex(), ta, &B.fclConvex(), tb, request, result);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace mink_test
