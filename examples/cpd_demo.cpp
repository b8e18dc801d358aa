// cpd_demo — a penalty contact loop on the continuous penetration depth (CPD), as a haptic
// or penalty-based physics loop would call it, beside the Euclidean penetration depth.
//
// A is an L-block (non-convex: a reflex edge where its arms meet), B a box held by a
// "device" that drags it through A, along one arm, past the reflex edge and into the
// other arm (the motion of the query benchmark's L-block/box scene). Every frame:
//   1. one ContinuousPenetrationDepth query (kept for the pair: it starts from the last
//      frame's answer) and one penetrationDepth() (the Euclidean depth, from scratch);
//   2. the penalty force on B, F = stiffness * depth * direction (B moved by
//      depth * direction just touches A, where a haptic renderer would draw it).
// Prints a row every few frames and a summary: how far the force's direction turns from
// one frame to the next (the CPD's turns smoothly; the Euclidean one jumps where the
// nearest point of ∂M switches face), the depths, and the time per query. The CPD follows
// the branch of ∂M it started on: here B entered through the side y = 0 of A's arm, and
// the CPD keeps pushing it back out that way as it goes deeper (no pop-through: the
// Euclidean direction flips to the far side, pulling B through A), so its depth grows
// past the Euclidean one; reset() restarts a pair from the Euclidean depth.
//
// Usage: mink_cpd_demo [--frames N]   (default 60)
#include <mink/mink.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "support/mesh_shapes.hpp"

namespace {

using V = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

/// The angle in degrees between two force directions (0 when either force is zero).
double turnDegrees(const V& a, const V& b) {
  if (a.isZero() || b.isZero()) return 0;
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

double median(std::vector<double> x) {
  if (x.empty()) return 0;
  std::nth_element(x.begin(), x.begin() + static_cast<long>(x.size() / 2), x.end());
  return x[x.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 60;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--frames N]\n", argv[0]);
      return 2;
    }
  }
  if (frames < 2) {
    std::fprintf(stderr, "--frames must be at least 2\n");
    return 2;
  }

  // The meshes: built once, shared by every query of the pair.
  const mink_test::MeshShape l = mink_test::lBlock();
  const mink_test::MeshShape box = mink_test::boxShape(V(-0.3, -0.3, -0.75), V(0.3, 0.3, 0.75));
  const auto A = mink::TriangleMesh<double>::fromMesh(l.verticesAs<double>(), l.triangles);
  const auto B = mink::TriangleMesh<double>::fromMesh(box.verticesAs<double>(), box.triangles);

  mink::Pose<double> poseA;  // A at the origin
  const M3 G = Eigen::AngleAxisd(0.3, V(1, 2, 3).normalized()).toRotationMatrix();
  auto device = [&](double u) {  // B's pose held by the device, u in [0, 1]
    mink::Pose<double> p;
    p.rotation = G;
    p.translation = V(1.4 - u, 0.4 + u, 0.5);
    return p;
  };

  const double stiffness = 1000.0;  // N per unit of depth
  mink::ContinuousPenetrationDepth<double> cpd(A, B);
  V lastCpd = V::Zero(), lastPd = V::Zero();
  std::vector<double> cpdTurns, pdTurns, cpdMs, pdMs;
  int approximate = 0;
  double worstRatio = 1;

  std::printf("A: L-block (%d triangles); B: box (%d triangles), dragged from (1.4, 0.4, 0.5) to (0.4, 1.4, 0.5)\n",
              A.numTriangles(), B.numTriangles());
  std::printf("%5s  %-11s %7s  %-26s %7s   %-11s %7s %7s\n", "frame", "CPD", "depth", "force (N)", "turn", "Euclidean",
              "depth", "turn");
  for (int f = 0; f < frames; ++f) {
    const double u = static_cast<double>(f) / (frames - 1);
    const mink::Pose<double> poseB = device(u);

    auto t0 = std::chrono::steady_clock::now();
    const mink::CpdResult<double> r = cpd.query(poseA, poseB);
    auto t1 = std::chrono::steady_clock::now();
    const mink::CpdResult<double> e = mink::penetrationDepth(A, poseA, B, poseB);
    auto t2 = std::chrono::steady_clock::now();
    cpdMs.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    pdMs.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    if (r.status == mink::CpdStatus::Approximate) ++approximate;
    if (e.depth > 0) worstRatio = std::max(worstRatio, r.depth / e.depth);

    // The penalty force. (A renderer would draw B at poseB.translation + r.point: out of
    // A, just touching it.)
    const V force = stiffness * r.depth * r.direction;
    const double turnCpd = f > 0 ? turnDegrees(lastCpd, r.direction) : 0;
    const double turnPd = f > 0 ? turnDegrees(lastPd, e.direction) : 0;
    if (f > 0) {
      cpdTurns.push_back(turnCpd);
      pdTurns.push_back(turnPd);
    }
    lastCpd = r.direction;
    lastPd = e.direction;
    if (f % std::max(1, frames / 12) == 0 || f == frames - 1 || turnPd > 30)
      std::printf("%5d  %-11s %7.4f  (%7.1f, %7.1f, %7.1f) %6.2f°   %-11s %7.4f %6.2f°%s\n", f, mink::toString(r.status),
                  r.depth, force.x(), force.y(), force.z(), turnCpd, mink::toString(e.status), e.depth, turnPd,
                  turnPd > 30 ? "   <- the Euclidean direction jumps" : "");
  }

  std::printf("\nforce direction, turn per frame over %d frames: CPD median %.2f°, max %.2f°; Euclidean median %.2f°, max %.2f°\n",
              frames, median(cpdTurns), *std::max_element(cpdTurns.begin(), cpdTurns.end()), median(pdTurns),
              *std::max_element(pdTurns.begin(), pdTurns.end()));
  std::printf("time per query (median, wall): CPD %.3f ms (coherent: starts from the last frame), Euclidean %.3f ms (from scratch)\n",
              median(cpdMs), median(pdMs));
  std::printf("depth: CPD at most %.2f x the Euclidean one (it follows the side B entered by; no pop-through)\n",
              worstRatio);
  std::printf("CPD answers Approximate (best point of ∂M within the caps): %d of %d frames\n", approximate, frames);
  return 0;
}
