// tests/support/cgal_mesh.hpp — CGAL references for the mesh layer on a TriangleMesh in
// double: exact point location (Side_of_triangle_mesh with Epick, exact predicates) and
// the exact brute-force test of boundary contact between two meshes.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include <memory>
#include <vector>

#include "mink/mesh/point_in_mesh.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink_test {

/// CGAL's location of points in the solid a TriangleMesh<double> bounds.
class CgalPointLocation {
 public:
  using K = CGAL::Epick;
  using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
  explicit CgalPointLocation(const mink::TriangleMesh<double>& m) {
    std::vector<SurfaceMesh::Vertex_index> vi;
    for (const auto& p : m.vertices()) vi.push_back(mesh_.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
    for (const auto& t : m.triangles()) mesh_.add_face(vi[t[0]], vi[t[1]], vi[t[2]]);
    side_ = std::make_unique<CGAL::Side_of_triangle_mesh<SurfaceMesh, K>>(mesh_);
  }
  mink::PointLocation operator()(const Eigen::Vector3d& p) const {
    switch ((*side_)(K::Point_3(p.x(), p.y(), p.z()))) {
      case CGAL::ON_BOUNDED_SIDE: return mink::PointLocation::Inside;
      case CGAL::ON_BOUNDARY: return mink::PointLocation::OnBoundary;
      default: return mink::PointLocation::Outside;
    }
  }

 private:
  SurfaceMesh mesh_;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<SurfaceMesh, K>> side_;
};

/// Exact: does a triangle of A meet a triangle of B, B's corners given as bPoints (every
/// pair, box prefilter, CGAL's exact predicates)?
inline bool bruteForceBoundariesMeet(const mink::TriangleMesh<double>& A, const std::vector<Eigen::Vector3d>& bPoints,
                                     const mink::TriangleMesh<double>& B) {
  using K = CGAL::Epick;
  auto P = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  std::vector<K::Triangle_3> ta, tb;
  for (const auto& t : A.triangles()) ta.emplace_back(P(A.vertex(t[0])), P(A.vertex(t[1])), P(A.vertex(t[2])));
  for (const auto& t : B.triangles()) tb.emplace_back(P(bPoints[t[0]]), P(bPoints[t[1]]), P(bPoints[t[2]]));
  std::vector<CGAL::Bbox_3> bb;
  for (const auto& t : tb) bb.push_back(t.bbox());
  for (const auto& s : ta) {
    const CGAL::Bbox_3 box = s.bbox();
    for (std::size_t j = 0; j < tb.size(); ++j)
      if (CGAL::do_overlap(box, bb[j]) && CGAL::do_intersect(s, tb[j])) return true;
  }
  return false;
}

}  // namespace mink_test
