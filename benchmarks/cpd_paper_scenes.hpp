// The four scenes of the CPD paper's section 7 (Lee, Behar, Lien, Kim, CAD 2016), shared by
// mink_cpd_bench (Table 2: the local Minkowski sum) and mink_cpd_query_bench (Table 1: the
// query): the meshes, B's start pose and B's motion per frame, at unit scale.
//   cone/axes     axes (60 triangles; paper 36) and a cone of 1000 triangles, apex down in
//                 an arm; the cone slides along the arm while turning.
//   spoon/cup     a cup of 1024 triangles and a spoon of 1316 (paper 1K / 1.3K), the spoon
//                 leaning on the inner wall and turning about its own long axis.
//   duck/torus    a torus of 1600 triangles (paper 1.6K) and the duck, 4212 triangles
//                 (tests/data/duck.obj, Bullet's zlib-licensed mesh, standing in for the
//                 paper's fish of 950), sunk into the hole, turning about the vertical.
//   torus/torus   two interlocked tori of 2000 triangles (paper 2K each), one turning
//                 about the other's axis.
// B's start pose: moved along an approach direction until it touches A (bisection with
// MeshOverlap), then pushed in by a stated depth (placeB). Needs MINK_BENCH_DATA_DIR
// (tests/data) and tests/ on the include path.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "mink/io/triangle_mesh_io.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "support/mesh_shapes.hpp"

namespace mink_bench {

struct CpdScene {
  using M3 = Eigen::Matrix3d;
  using V = Eigen::Vector3d;
  std::string name;
  bool degenerate = false;
  mink_test::MeshShape a, b;  // unit scale
  M3 R0 = M3::Identity();
  V aim = V::Zero();       // B's translation at which it surely overlaps A (auto placement)
  V approach = V::Zero();  // unit: B's way in (placement) and, reversed, out
  bool search = true;      // false: t0 = aim, no placement search
  double reach = 0;        // the search starts at aim − reach·approach (0: far away)
  double push = 0;         // depth pushed in past the touching contact (unit scale)
  // B's pose at frame f from the start pose (R0, t0), unit scale.
  std::function<mink::Pose<double>(int f, const M3& R0, const V& t0)> motion;
  double paper[4] = {NAN, NAN, NAN, NAN};  // Table 2: Full, Brute F., BSH, Gap Fill. (ms)
  double paperQueryMs = NAN;               // Table 1: the query's total per frame (ms)
  bool cgal = false;                       // Table 2: try CGAL minkowski_sum_3 at frame 0
};

inline Eigen::Matrix3d cpdRot(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

inline mink::TriangleMesh<double> cpdMesh(const mink_test::MeshShape& s) {
  return mink::TriangleMesh<double>::fromMesh(s.verticesAs<double>(), s.triangles);
}

inline mink_test::MeshShape shapeFromObj(const std::string& file) {
  const auto m = mink::io::readTriangleMesh<double>(std::string(MINK_BENCH_DATA_DIR) + "/" + file);
  mink_test::MeshShape s;
  s.name = file;
  s.vertices = m.vertices();
  for (int t = 0; t < m.numTriangles(); ++t) s.triangles.push_back(m.triangle(t));
  return s;
}

/// Start translation: from aim − D·approach (separated) along `approach` to the first
/// touching contact (bisection on MeshOverlap), then `push` further.
inline Eigen::Vector3d placeB(const CpdScene& s) {
  using V = Eigen::Vector3d;
  if (!s.search) return s.aim;
  const auto A = cpdMesh(s.a), B = cpdMesh(s.b);
  const double D = s.reach > 0 ? s.reach : 4 * (A.extent() + B.extent()) + 4;
  const V start = s.aim - D * s.approach;
  mink::MeshOverlap<double> ov(A, B, s.R0, start);
  if (ov.overlaps(V::Zero()) || !ov.overlaps(V(D * s.approach))) {
    std::printf("scene %s: placement search needs a separated start and an overlapping aim\n", s.name.c_str());
    std::exit(2);
  }
  double lo = 0, hi = D;
  for (int i = 0; i < 60; ++i) {
    const double m = 0.5 * (lo + hi);
    (ov.overlaps(V(m * s.approach)) ? hi : lo) = m;
  }
  return start + (hi + s.push) * s.approach;
}

/// The four scenes of the paper's section 7, with its Table 1 and Table 2 times.
inline std::vector<CpdScene> cpdPaperScenes() {
  using V = Eigen::Vector3d;
  using M3 = Eigen::Matrix3d;
  using Pose = mink::Pose<double>;
  constexpr double kPi = 3.141592653589793238462643383279502884;
  std::vector<CpdScene> out;
  {
    CpdScene s;
    s.name = "cone/axes";
    s.a = mink_test::axes(3);
    s.b = mink_test::cone(500, 1.0, 2.0);
    s.R0 = cpdRot(kPi, V(1, 0, 0));  // apex down
    s.aim = V(2, 0, 1.5);
    s.approach = V(0, 0, -1);
    s.push = 0.3;
    s.motion = [](int f, const M3& R0, const V& t0) {
      Pose p;
      p.rotation = cpdRot(0.01 * f, V(0.2, 0.3, 1)) * R0;
      p.translation = t0 + f * V(-0.03, 0, 0);
      return p;
    };
    s.paper[0] = 58.91, s.paper[1] = 16.10, s.paper[2] = 24.23, s.paper[3] = 10.33;
    s.paperQueryMs = 1.39;
    s.cgal = true;
    out.push_back(s);
  }
  {
    CpdScene s;
    s.name = "spoon/cup";
    s.a = mink_test::cup(128, 6.0, 5.4, 10.0, 0.6);
    s.b = mink_test::spoon(54, 5);
    s.R0 = cpdRot(-kPi / 3, V(0, 1, 0));  // handle up, leaning
    s.aim = V(4.5, 0, 4.5);
    s.approach = V(1, 0, 0);
    s.reach = 4.5;  // from the cup's axis towards its wall
    s.push = 0.15;
    s.motion = [](int f, const M3& R0, const V& t0) {
      Pose p;
      p.rotation = R0 * cpdRot(0.012 * f, V(1, 0, 0));  // about the spoon's long axis
      p.translation = t0;
      return p;
    };
    s.paper[0] = 1393.61, s.paper[1] = 453.29, s.paper[2] = 69.38, s.paper[3] = 13.91;
    s.paperQueryMs = 4.23;
    out.push_back(s);
  }
  {
    CpdScene s;
    s.name = "duck/torus";
    s.a = mink_test::torus(40, 20, 0.7, 0.3);
    s.b = shapeFromObj("duck.obj");
    s.R0 = cpdRot(kPi / 2, V(1, 0, 0));  // the duck's up (y) along z
    s.aim = V(0.13, 0.03, -0.9);
    s.approach = V(0, 0, -1);
    s.push = 0.05;
    s.motion = [](int f, const M3& R0, const V& t0) {
      Pose p;
      p.rotation = cpdRot(0.02 * f, V(0, 0, 1)) * R0;
      p.translation = t0;
      return p;
    };
    s.paper[0] = 1719.12, s.paper[1] = 584.39, s.paper[2] = 185.82, s.paper[3] = 28.80;
    s.paperQueryMs = 3.33;  // the paper's fish/torus
    out.push_back(s);
  }
  {
    CpdScene s;
    s.name = "torus/torus";
    s.a = mink_test::torus(50, 20, 2.0, 0.75);
    s.b = mink_test::torus(50, 20, 2.0, 0.75);
    s.R0 = cpdRot(kPi / 2, V(1, 0, 0));  // B's ring in the xz plane, through A's hole
    s.aim = V(1, 0, 0);
    s.approach = V(-1, 0, 0);
    s.reach = 1;  // from (2, 0, 0), linked and clear, towards A's inner wall
    s.push = 0.1;
    s.motion = [](int f, const M3& R0, const V& t0) {
      Pose p;
      const M3 Q = cpdRot(0.02 * f, V(0, 0, 1));  // about A's axis: B travels round A's hole
      p.rotation = Q * R0;
      p.translation = Q * t0;
      return p;
    };
    s.paper[0] = 2842.93, s.paper[1] = 1158.74, s.paper[2] = 390.65, s.paper[3] = 36.06;
    s.paperQueryMs = 4.42;
    out.push_back(s);
  }
  return out;
}

}  // namespace mink_bench
