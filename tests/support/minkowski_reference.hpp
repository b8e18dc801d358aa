// tests/support/minkowski_reference.hpp — the exact boundary of M = A ⊕ −B by CGAL's
// minkowski_sum_3 (Nef polyhedra over the exact kernel Epeck), and the checks the CPD tests
// make of a MinkowskiPatch against a reference boundary.
//
// The reference takes the very numbers mink works on: A's vertices and B's vertices placed
// in A's frame as mink places them (R b + t in double, ConvolutionFrame::place), each
// converted exactly. Cost: 0.03 s (L-block ⊕ box) to 0.3 s (star ⊕ L) here; ten seconds
// and more for a torus of 192 triangles, which the tests therefore do not compute.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_incremental_builder_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <CGAL/minkowski_sum_3.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "mink/cpd/minkowski_patch.hpp"
#include "support/mesh_shapes.hpp"
#include "support/patch_measures.hpp"

namespace mink_test {

/// The exact boundary of A ⊕ −B (A at the identity, B's points given placed in A's frame).
class MinkowskiReference {
 public:
  using K = CGAL::Epeck;
  using P3 = K::Point_3;

  MinkowskiReference(const MeshShape& a, const std::vector<Eigen::Vector3d>& placedB,
                     const std::vector<std::array<int, 3>>& trianglesB) {
    std::vector<Eigen::Vector3d> negB;
    for (const auto& p : placedB) negB.push_back(-p);
    // −B: negating every point reverses orientation; so do the triangles.
    std::vector<std::array<int, 3>> revB;
    for (const auto& t : trianglesB) revB.push_back({t[0], t[2], t[1]});
    const Nef nefA = toNef(a.vertices, a.triangles), nefB = toNef(negB, revB);
    Nef sum = CGAL::minkowski_sum_3(const_cast<Nef&>(nefA), const_cast<Nef&>(nefB));
    SurfaceMesh sm;
    CGAL::convert_nef_polyhedron_to_polygon_mesh(sum, sm, true);
    for (auto f : sm.faces()) {
      std::vector<P3> p;
      for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) p.push_back(sm.point(v));
      for (std::size_t k = 1; k + 1 < p.size(); ++k) triangles_.push_back({p[0], p[k], p[k + 1]});
    }
    for (const auto& t : triangles_) {
      const auto n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
      area_ += 0.5 * std::sqrt(CGAL::to_double(n.squared_length()));
      volume_ += CGAL::determinant(t[0] - CGAL::ORIGIN, t[1] - CGAL::ORIGIN, t[2] - CGAL::ORIGIN) / 6;
      std::array<Eigen::Vector3d, 3> d;
      for (int c = 0; c < 3; ++c) d[c] = Eigen::Vector3d(CGAL::to_double(t[c].x()), CGAL::to_double(t[c].y()), CGAL::to_double(t[c].z()));
      doubles_.push_back(d);
    }
  }

  double area() const { return area_; }
  const K::FT& volume() const { return volume_; }
  const std::vector<std::array<P3, 3>>& triangles() const { return triangles_; }
  const std::vector<std::array<Eigen::Vector3d, 3>>& trianglesDouble() const { return doubles_; }

  /// Is the exact point p on the boundary (in one of its triangles)?
  bool onBoundary(const P3& p) const {
    for (const auto& t : triangles_)
      if (CGAL::coplanar(t[0], t[1], t[2], p) && inTriangle(t, p)) return true;
    return false;
  }
  /// The distance from x to the boundary (double).
  double distance(const Eigen::Vector3d& x) const {
    double best = INFINITY;
    for (const auto& t : doubles_) best = std::min(best, squaredDistanceToTriangle(x, t[0], t[1], t[2]));
    return std::sqrt(best);
  }

 private:
  using Poly = CGAL::Polyhedron_3<K>;
  using Nef = CGAL::Nef_polyhedron_3<K>;
  using SurfaceMesh = CGAL::Surface_mesh<P3>;

  template <class HDS>
  struct Build : public CGAL::Modifier_base<HDS> {
    const std::vector<Eigen::Vector3d>* v;
    const std::vector<std::array<int, 3>>* t;
    void operator()(HDS& hds) override {
      CGAL::Polyhedron_incremental_builder_3<HDS> b(hds, true);
      b.begin_surface(v->size(), t->size());
      for (const auto& p : *v) b.add_vertex(P3(p.x(), p.y(), p.z()));
      for (const auto& f : *t) {
        b.begin_facet();
        for (int i : f) b.add_vertex_to_facet(static_cast<std::size_t>(i));
        b.end_facet();
      }
      b.end_surface();
    }
  };
  static Nef toNef(const std::vector<Eigen::Vector3d>& v, const std::vector<std::array<int, 3>>& t) {
    Build<Poly::HalfedgeDS> b;
    b.v = &v;
    b.t = &t;
    Poly P;
    P.delegate(b);
    return Nef(P);
  }
  static bool inTriangle(const std::array<P3, 3>& t, const P3& p) {
    const auto n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    for (int c = 0; c < 3; ++c)
      if (CGAL::cross_product(t[(c + 1) % 3] - t[c], p - t[c]) * n < 0) return false;
    return true;
  }

 private:
  std::vector<std::array<P3, 3>> triangles_;
  std::vector<std::array<Eigen::Vector3d, 3>> doubles_;
  double area_ = 0;
  K::FT volume_ = 0;
};

}  // namespace mink_test
