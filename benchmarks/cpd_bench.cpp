// mink_cpd_bench — the CPD paper's Table 2 (Lee, Behar, Lien, Kim, CAD 2016, section 7.1):
// the time to build the boundary of M = A ⊕ −B, whole or only inside an ε-ball of radius
// 50 with M's bounding sphere of radius about 250, on four scenes, side by side with the
// paper's numbers, plus a degenerate family (coplanar facets everywhere) beside its
// generic twins.
//
// Scenes (A fixed at the identity, B moving; the four paper scenes in cpd_paper_scenes.hpp,
// shared with mink_cpd_query_bench; procedural shapes: tests/support/mesh_shapes.hpp,
// the duck: tests/data/duck.obj, Bullet's zlib-licensed mesh, standing in for the paper's fish):
//   cone/axes     axes (60 triangles; paper 36) and a cone of 1000 triangles, apex down in
//                 an arm; the cone slides along the arm while turning.
//   spoon/cup     a cup of 1024 triangles and a spoon of 1316 (paper 1K / 1.3K), the spoon
//                 leaning on the inner wall and turning about its own long axis.
//   duck/torus    a torus of 1600 triangles (paper 1.6K) and the duck, 4212 triangles
//                 (the paper's fish has 950), sunk into the hole, turning about the vertical.
//   torus/torus   two interlocked tori of 2000 triangles (paper 2K each), one turning
//                 about the other's axis.
//   degenerate:   an axis-aligned box resting face to face on an L-block and on a larger
//                 box (every contact facet coplanar, integer coordinates after scaling),
//                 sliding; each beside the same scene with the box turned by a small
//                 generic rotation.
// Placement: B's start pose is found by moving it along an approach direction until it
// touches A (bisection with MeshOverlap) and pushing it in by a stated depth; then every
// coordinate is scaled so that the smallest enclosing sphere of the points a_i − b_j (that
// of M) has radius 250 at frame 0 (an integer factor for the degenerate family, so the
// coplanarity stays exact).
// The ball: radius 50, centred on each frame at the exit point of the origin along the
// way B backs out (the least s >= 0 with B moved by s·(−approach) clear of A, by
// bisection with MeshOverlap): a point of ∂M at the contact, which follows it along the
// motion. The centres are computed before any timing, so every method gets the same inputs.
// Columns (per update, double):
//   full         minkowskiBoundary (cpd/minkowski_boundary.hpp) at a few frames;
//   cgal         CGAL minkowski_sum_3 (Nef polyhedra, Epeck; tests/support/minkowski_reference.hpp)
//                at frame 0, run in a child process stopped after --cgal-timeout seconds;
//   brute        LocalMinkowskiSum, LocalSumMethod::BruteForce (every feature pair tested);
//   sphere_tree  LocalSumMethod::SphereTree (Theorem 2 culling, from scratch each frame);
//   convex_maps  LocalSumMethod::ConvexMaps, one object along the motion (coherent: each
//                feature walked from its cell of the last frame); its first call, which
//                also builds the two convex maps, is reported apart (convex_maps_first);
//   box_trees    LocalSumMethod::BoxTrees (the default), one object along the motion: the
//                triangle pairs near the ball from the overlap test's two box trees.
// Agreement: on every frame brute, sphere_tree, convex_maps and box_trees must give the same facet
// count, triangle count and patch area (relative 1e-9); a WARNING line says otherwise.
// On the degenerate scenes mink's whole boundary is also compared with CGAL's area.
// Timing: thread CPU time (CLOCK_THREAD_CPUTIME_ID; the machine is shared), wall time in
// the CSV too. Medians with quartiles over the frames. Each column runs in a child process
// that is stopped after a wall-time limit (a single update can take minutes): the frames
// that finished are kept, and a column with none reads "stopped after S s", a lower bound.
//
// Usage: mink_cpd_bench [out.csv] [--quick] [--frames N] [--full-timeout S]
//                       [--cgal-timeout S] [--method-timeout S] [--only SCENE] [--verbose]
//   out.csv           default benchmarks/results/cpd_table2.csv (directory must exist)
//   --frames          frames of each motion (default 20)
//   --full-timeout    wall-time limit of the whole boundary's child, per scene (default 30)
//   --cgal-timeout    the same for CGAL (default 30)
//   --method-timeout  the same for brute and for sphere_tree (default 20 each)
//   --coherent-timeout  the same for convex_maps and for box_trees (default 40 each)
//   --only            run one scene (its name as printed, e.g. torus/torus)
//   --verbose         every local update's time and sizes on stderr
//   --quick           8 frames, 2 samples of the whole boundary, 10 s limits, CGAL only on
//                     the degenerate family (smoke test, numbers not for publication)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bench_common.hpp"
#include "cpd_paper_scenes.hpp"
#include "mink/cpd/local_minkowski_sum.hpp"
#include "mink/cpd/minkowski_boundary.hpp"
#include "mink/mesh/detail/enclosing_sphere.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "support/mesh_shapes.hpp"
#include "support/minkowski_reference.hpp"
#include "support/patch_measures.hpp"

namespace {

using Mesh = mink::TriangleMesh<double>;
using Patch = mink::MinkowskiPatch<double>;
using Pose = mink::Pose<double>;
using V = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
using mink_test::MeshShape;

constexpr double kPi = 3.141592653589793238462643383279502884;
constexpr double kMRadius = 250;  // M's enclosing sphere at frame 0 (the paper: <= 250)
constexpr double kBall = 50;      // the paper's ε-ball radius

M3 rot(double angle, const V& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

using mink_bench::wallMs;
double cpuMs() { return mink_bench::threadCpuMs(); }

MeshShape scaled(MeshShape s, double k) {
  for (auto& v : s.vertices) v *= k;
  return s;
}

Mesh toMesh(const MeshShape& s) { return Mesh::fromMesh(s.verticesAs<double>(), s.triangles); }

using Scene = mink_bench::CpdScene;
using mink_bench::placeB;

std::vector<Scene> scenes(bool quick) {
  (void)quick;
  std::vector<Scene> out = mink_bench::cpdPaperScenes();
  // The degenerate family: B = the box [-1/2, 1/2]^3 resting on A's top face (z = 1),
  // sliding along x; the twin turns B by a small generic rotation about its centre.
  auto slide = [](double dx) {
    return [dx](int f, const M3& R0, const V& t0) {
      Pose p;
      p.rotation = R0;
      p.translation = t0 + V(dx * f, 0, 0);
      return p;
    };
  };
  const MeshShape cube = mink_test::boxShape(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5));
  for (int generic = 0; generic < 2; ++generic) {
    Scene s;
    s.name = generic ? "box/L-block turned" : "box/L-block";
    s.degenerate = !generic;
    s.a = mink_test::lBlock();
    s.b = cube;
    s.R0 = generic ? rot(0.05, V(1, 2, 3)) : M3::Identity();
    s.aim = V(0.5, 0.5, 1.5);
    s.approach = V(0, 0, -1);
    s.search = false;
    s.motion = slide(1.0 / 64);
    s.cgal = true;
    out.push_back(s);
  }
  for (int generic = 0; generic < 2; ++generic) {
    Scene s;
    s.name = generic ? "box/box turned" : "box/box";
    s.degenerate = !generic;
    s.a = mink_test::boxShape(V(-1, -1, -1), V(1, 1, 1));
    s.b = cube;
    s.R0 = generic ? rot(0.05, V(1, 2, 3)) : M3::Identity();
    s.aim = V(0, 0, 1.5);
    s.approach = V(0, 0, -1);
    s.search = false;
    s.motion = slide(1.0 / 64);
    s.cgal = true;
    out.push_back(s);
  }
  return out;
}

/// The radius of M's enclosing sphere: that of the points a_i − (R b_j + t).
double mRadius(const MeshShape& a, const MeshShape& b, const M3& R, const V& t) {
  std::vector<mink::Vec3<double>> pts;
  pts.reserve(a.vertices.size() * b.vertices.size());
  for (const V& bj : b.vertices) {
    const V pb = R * bj + t;
    for (const V& ai : a.vertices) pts.push_back(ai - pb);
  }
  return mink::detail::enclosingSphere(pts.data(), static_cast<int>(pts.size())).radius;
}

/// One timed call, as the child process reports it (mink_bench::inChild).
struct Record {
  double frame, cpu, wall, facets, pieces, tests, nodes, candidates, triangles, area;
};

Record record(int f, double cpu, double wall, const Patch& P) {
  return {double(f), cpu, wall, double(P.facetsGathered), double(P.pieces), double(P.overlapTests),
          double(P.nodePairs), double(P.candidatePairs), double(P.triangles.size()), mink_test::measure(P).area};
}

struct Stats {
  std::vector<double> cpu, wall, facets, pieces, tests, nodes, candidates, triangles;
  void add(const Record& r) {
    cpu.push_back(r.cpu);
    wall.push_back(r.wall);
    facets.push_back(r.facets);
    pieces.push_back(r.pieces);
    tests.push_back(r.tests);
    nodes.push_back(r.nodes);
    candidates.push_back(r.candidates);
    triangles.push_back(r.triangles);
  }
};

double med(const std::vector<double>& v) { return mink_bench::quantile(v, 0.5); }

/// The exit point along d: y = s d with s >= 0 the end of the first run of overlapping
/// placements "A meets B + s d" (bisection on MeshOverlap), a point of ∂M. The origin if
/// A and B do not overlap.
V exitPoint(const Mesh& A, const Mesh& B, const Pose& poseB, const V& d) {
  const Pose poseA;
  mink::MeshOverlap<double> ov(A, poseA, B, poseB);
  if (!ov.overlaps(V::Zero())) return V::Zero();
  double lo = 0, hi = 1e-3 * (A.extent() + B.extent());
  for (int i = 0; i < 80 && ov.overlaps(hi * d); ++i) lo = hi, hi *= 2;
  for (int i = 0; i < 60; ++i) {
    const double m = 0.5 * (lo + hi);
    (ov.overlaps(m * d) ? lo : hi) = m;
  }
  return lo * d;
}

struct Row {
  std::string scene, method;
  bool degenerate;
  int triA, triB, samples;
  double scale, mradius, q1, median, q3, wall, paper;
  double facets, pieces, tests, nodes, candidates, triangles;
  std::string note;
};

}  // namespace

/// The usage, as in the comment at the top of this file.
constexpr const char* kUsage =
    "Usage: mink_cpd_bench [out.csv] [--quick] [--frames N] [--full-timeout S]\n"
    "                      [--cgal-timeout S] [--method-timeout S] [--only SCENE] [--verbose]\n"
    "  out.csv           default benchmarks/results/cpd_table2.csv (directory must exist)\n"
    "  --frames          frames of each motion (default 20)\n"
    "  --full-timeout    wall-time limit of the whole boundary's child, per scene (default 30)\n"
    "  --cgal-timeout    the same for CGAL (default 30)\n"
    "  --method-timeout  the same for brute and for sphere_tree (default 20 each)\n"
    "  --coherent-timeout  the same for convex_maps and for box_trees (default 40 each)\n"
    "  --only            run one scene (its name as printed, e.g. torus/torus)\n"
    "  --verbose         every local update's time and sizes on stderr\n"
    "  --quick           8 frames, 2 samples of the whole boundary, 10 s limits, CGAL only on\n"
    "                    the degenerate family (smoke test, numbers not for publication)\n";

int main(int argc, char** argv) {
  std::string out = "benchmarks/results/cpd_table2.csv";
  bool quick = false, verbose = false;
  int frames = 20;
  double cgalTimeout = 30, fullTimeout = 30, methodTimeout = 20, coherentTimeout = 40;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else if (std::strcmp(argv[i], "--verbose") == 0)
      verbose = true;
    else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
      only = argv[++i];
    else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc)
      frames = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--cgal-timeout") == 0 && i + 1 < argc)
      cgalTimeout = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--full-timeout") == 0 && i + 1 < argc)
      fullTimeout = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--method-timeout") == 0 && i + 1 < argc)
      methodTimeout = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--coherent-timeout") == 0 && i + 1 < argc)
      coherentTimeout = std::atof(argv[++i]);
    else
      out = mink_bench::pathArgument(argv[i], kUsage);
  }
  if (quick) {
    frames = std::min(frames, 8);
    fullTimeout = std::min(fullTimeout, 10.0);
    cgalTimeout = std::min(cgalTimeout, 10.0);
    methodTimeout = std::min(methodTimeout, 10.0);
    coherentTimeout = std::min(coherentTimeout, 10.0);
  }
  const int fullSamples = quick ? 2 : 3;

  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // line by line through tee
  std::printf("mink_cpd_bench: the CPD paper's Table 2 (Lee et al., CAD 2016), ms per update, double\n");
  std::printf("machine: %s; load average %s\n", mink_bench::machineLine().c_str(), mink_bench::loadAverage().c_str());
  std::printf("M's enclosing sphere radius %.0f at frame 0, ball radius %.0f, %d frames per scene; thread CPU time%s\n",
              kMRadius, kBall, frames, quick ? " (--quick: not for publication)" : "");
  std::printf("time limits (wall, child processes, per scene): whole boundary %.0f s, CGAL %.0f s, brute and "
              "sphere_tree %.0f s each, convex_maps and box_trees %.0f s each\n\n",
              fullTimeout, cgalTimeout, methodTimeout, coherentTimeout);

  std::vector<Row> rows;
  int disagreements = 0;
  for (const Scene& sc : scenes(quick)) {
    if (!only.empty() && sc.name != only) continue;
    const double sceneStart = wallMs();
    const V t0unit = placeB(sc);
    const double m0 = mRadius(sc.a, sc.b, sc.R0, t0unit);
    double k = kMRadius / m0;
    const bool family = sc.degenerate || sc.name.find("turned") != std::string::npos;
    if (family) k = std::round(k);  // integer: the coplanarity stays exact
    const MeshShape as = scaled(sc.a, k), bs = scaled(sc.b, k);
    const Mesh A = toMesh(as), B = toMesh(bs);
    std::vector<Pose> poses;
    for (int f = 0; f < frames; ++f) {
      Pose p = sc.motion(f, sc.R0, t0unit);
      p.translation *= k;
      poses.push_back(p);
    }
    const Pose poseA;
    const double mr = mRadius(as, bs, poses[0].rotation, poses[0].translation);

    // The ball's centres (untimed): on each frame the exit point of the origin along the
    // way B backs out (−approach), a point of ∂M at the contact; the origin when A and B
    // only touch.
    std::vector<V> centres;
    std::vector<double> depth;
    for (int f = 0; f < frames; ++f) {
      centres.push_back(exitPoint(A, B, poses[f], -sc.approach));
      depth.push_back(centres.back().norm());
    }
    mink::MeshOverlap<double> ov(A, poseA, B, poses[0]);
    const bool overlap0 = ov.overlaps();
    std::printf("== %s%s: %d / %d triangles, scale %.4g, M radius %.1f, %s at frame 0, ball centre depth %.2f .. %.2f\n",
                sc.name.c_str(), sc.degenerate ? " [degenerate]" : "", A.numTriangles(), B.numTriangles(), k, mr,
                overlap0 ? "overlapping" : "not overlapping", *std::min_element(depth.begin(), depth.end()),
                *std::max_element(depth.begin(), depth.end()));

    // The whole boundary at a few frames.
    std::vector<int> fullFrames;
    for (int i = 0; i < fullSamples; ++i) fullFrames.push_back(i * (frames - 1) / std::max(1, fullSamples - 1));
    bool fullDone = false;
    double fullChildCpu = 0;
    const std::vector<Record> fullRecs = mink_bench::inChild<Record>(
        fullTimeout,
        [&](const std::function<void(const Record&)>& emit) {
          for (int f : fullFrames) {
            const double c0 = cpuMs(), w0 = wallMs();
            const Patch P = mink::minkowskiBoundary(A, poseA, B, poses[static_cast<std::size_t>(f)]);
            emit(record(f, cpuMs() - c0, wallMs() - w0, P));
          }
        },
        fullDone, &fullChildCpu);
    Stats full;
    double fullArea0 = NAN;
    for (const Record& r : fullRecs) {
      full.add(r);
      if (r.frame == 0) fullArea0 = r.area;
    }

    // The four local methods, each one object along the motion, each in its own child.
    constexpr int kMethods = 4;
    const mink::LocalSumMethod methods[kMethods] = {mink::LocalSumMethod::BruteForce, mink::LocalSumMethod::SphereTree,
                                                    mink::LocalSumMethod::ConvexMaps, mink::LocalSumMethod::BoxTrees};
    const char* names[kMethods] = {"brute", "sphere_tree", "convex_maps", "box_trees"};
    auto limitOf = [&](int m) { return m >= 2 ? coherentTimeout : methodTimeout; };
    Stats st[kMethods], cmFirst;
    std::array<double, kMethods> none{NAN, NAN, NAN, NAN};
    std::vector<std::array<double, kMethods>> tri(frames, none), area(frames, none), fac(frames, none);
    int ran[kMethods] = {0, 0, 0, 0};
    bool methodDone[kMethods] = {false, false, false, false};
    double methodChildCpu[kMethods] = {0, 0, 0, 0};
    for (int m = 0; m < kMethods; ++m) {
      const double limit = limitOf(m);
      const std::vector<Record> recs = mink_bench::inChild<Record>(
          limit,
          [&](const std::function<void(const Record&)>& emit) {
            mink::LocalMinkowskiSumOptions<double> o;
            o.method = methods[m];
            mink::LocalMinkowskiSum<double> local(A, B, o);
            for (int f = 0; f < frames; ++f) {
              const double c0 = cpuMs(), w0 = wallMs();
              const Patch& P = local.update(poseA, poses[f], centres[f], kBall);
              emit(record(f, cpuMs() - c0, wallMs() - w0, P));
            }
          },
          methodDone[m], &methodChildCpu[m]);
      for (const Record& r : recs) {
        const int f = static_cast<int>(r.frame);
        if (verbose)
          std::fprintf(stderr, "%s %s frame %d: %.1f ms, %.0f facets, %.0f pieces, %.0f tests, %.0f triangles\n",
                       sc.name.c_str(), names[m], f, r.cpu, r.facets, r.pieces, r.tests, r.triangles);
        (m == 2 && f == 0 ? cmFirst : st[m]).add(r);
        tri[f][m] = r.triangles;
        area[f][m] = r.area;
        fac[f][m] = r.facets;
        ++ran[m];
      }
    }
    for (int f = 0; f < frames; ++f)
      for (int m = 1; m < kMethods; ++m) {
        if (std::isnan(tri[f][0]) || std::isnan(tri[f][m])) continue;
        const double scale = std::max({area[f][0], area[f][m], kBall * kBall});
        if (tri[f][m] != tri[f][0] || fac[f][m] != fac[f][0] || std::abs(area[f][m] - area[f][0]) > 1e-9 * scale) {
          ++disagreements;
          std::printf("WARNING %s frame %d: %s gives %.0f facets, %.0f triangles, area %.9g; brute %.0f, %.0f, %.9g\n",
                      sc.name.c_str(), f, names[m], fac[f][m], tri[f][m], area[f][m], fac[f][0], tri[f][0], area[f][0]);
        }
      }

    // CGAL's minkowski_sum_3 at frame 0.
    double cgalMs = NAN, cgalArea = NAN;
    std::string cgalNote;
    if (sc.cgal && (!quick || family)) {
      bool ok = false;
      const std::vector<Record> recs = mink_bench::inChild<Record>(
          cgalTimeout,
          [&](const std::function<void(const Record&)>& emit) {
            std::vector<Eigen::Vector3d> placed;
            for (const V& v : bs.vertices) placed.push_back(poses[0].rotation * v + poses[0].translation);
            const double c0 = cpuMs(), w0 = wallMs();
            mink_test::MinkowskiReference ref(as, placed, bs.triangles);
            emit({0, cpuMs() - c0, wallMs() - w0, NAN, NAN, NAN, NAN, NAN, double(ref.triangles().size()), ref.area()});
          },
          ok);
      if (!recs.empty()) {
        cgalMs = recs[0].cpu;
        cgalArea = recs[0].area;
        if (!std::isnan(fullArea0) && std::abs(cgalArea - fullArea0) > 1e-9 * cgalArea) {
          ++disagreements;
          std::printf("WARNING %s frame 0: mink's whole boundary has area %.12g, CGAL's %.12g\n", sc.name.c_str(),
                      fullArea0, cgalArea);
        }
      } else {
        char buf[64];
        std::snprintf(buf, sizeof buf, "stopped after %.0f s", cgalTimeout);
        cgalNote = buf;
      }
    } else {
      cgalNote = quick ? "not run (--quick)"
                       : "not run: non-convex meshes of 1K-4K triangles; CGAL takes 10-17 s already for a "
                         "192-triangle torus with a box or an L-block (DESIGN.md)";
    }

    std::printf("   %-18s %10s %10s %10s %8s %9s %9s %8s %9s %10s %9s  %s\n", "method", "median ms", "q1", "q3",
                "samples", "facets", "pieces", "tests", "triangles", "candidates", "nodes", "paper ms");
    auto print = [&](const char* name, const Stats& s, double paper, const std::string& note) {
      const double q1 = mink_bench::quantile(s.cpu, 0.25), q3 = mink_bench::quantile(s.cpu, 0.75);
      char p[32] = "";
      if (!std::isnan(paper)) std::snprintf(p, sizeof p, "%.2f", paper);
      std::printf("   %-18s %10.3f %10.3f %10.3f %8zu %9.0f %9.0f %8.0f %9.0f %10.0f %9.0f  %s%s%s\n", name, med(s.cpu), q1,
                  q3, s.cpu.size(), med(s.facets), med(s.pieces), med(s.tests), med(s.triangles), med(s.candidates),
                  med(s.nodes), p, note.empty() ? "" : "  ", note.c_str());
      rows.push_back({sc.name, name, sc.degenerate, A.numTriangles(), B.numTriangles(), static_cast<int>(s.cpu.size()), k,
                      mr, q1, med(s.cpu), q3, med(s.wall), paper, med(s.facets), med(s.pieces), med(s.tests),
                      med(s.nodes), med(s.candidates), med(s.triangles), note});
    };
    // A stopped column: with no sample, the child's CPU time bounds its first call's.
    auto stopped = [](bool done, double t, bool none, double childCpu) {
      char b[96] = "";
      if (!done && none)
        std::snprintf(b, sizeof b, "stopped after %.0f s wall; > %.0f ms CPU", t, childCpu);
      else if (!done)
        std::snprintf(b, sizeof b, "stopped after %.0f s", t);
      return std::string(b);
    };
    print("full", full, sc.paper[0], stopped(fullDone, fullTimeout, full.cpu.empty(), fullChildCpu));
    if (!std::isnan(cgalMs)) {
      std::printf("   %-18s %10.3f %10s %10s %8d  area %.12g, mink's whole boundary %.12g\n", "cgal", cgalMs, "", "", 1,
                  cgalArea, fullArea0);
      rows.push_back({sc.name, "cgal", sc.degenerate, A.numTriangles(), B.numTriangles(), 1, k, mr, cgalMs, cgalMs, cgalMs,
                      cgalMs, NAN, NAN, NAN, NAN, NAN, NAN, NAN, ""});
    } else {
      std::printf("   %-18s %s\n", "cgal", cgalNote.c_str());
      rows.push_back({sc.name, "cgal", sc.degenerate, A.numTriangles(), B.numTriangles(), 0, k, mr, NAN, NAN, NAN, NAN,
                      NAN, NAN, NAN, NAN, NAN, NAN, NAN, cgalNote});
    }
    for (int m = 0; m < kMethods; ++m)
      print(names[m], st[m], m < 3 ? sc.paper[m + 1] : NAN,
            stopped(methodDone[m], limitOf(m), ran[m] == 0, methodChildCpu[m]));
    print("convex_maps_first", cmFirst, NAN, "");
    const double fullMs = full.cpu.empty() ? fullChildCpu : med(full.cpu);
    const char* ge = full.cpu.empty() ? ">" : "";
    std::printf("   full / convex_maps = %s%.1fx (paper %.1fx); full / box_trees %s%.1fx; full / brute %s%.1fx; "
                "full / sphere_tree %s%.1fx\n",
                ge, fullMs / med(st[2].cpu), sc.paper[0] / sc.paper[3], ge, fullMs / med(st[3].cpu), ge,
                fullMs / med(st[0].cpu), ge, fullMs / med(st[1].cpu));
    std::printf("   (scene took %.0f s of wall time)\n\n", (wallMs() - sceneStart) * 1e-3);
  }

  std::ofstream csv(out);
  csv << "# mink_cpd_bench; machine: " << mink_bench::machineLine() << "; thread CPU ms per update\n";
  csv << "scene,degenerate,triangles_a,triangles_b,scale,m_radius,ball_radius,method,samples,q1_ms,median_ms,q3_ms,"
         "wall_median_ms,paper_ms,facets,pieces,overlap_tests,node_pairs,candidate_pairs,triangles,note\n";
  for (const Row& r : rows)
    csv << r.scene << ',' << (r.degenerate ? 1 : 0) << ',' << r.triA << ',' << r.triB << ',' << r.scale << ','
        << r.mradius << ',' << kBall << ',' << r.method << ',' << r.samples << ',' << r.q1 << ',' << r.median << ','
        << r.q3 << ',' << r.wall << ',' << r.paper << ',' << r.facets << ',' << r.pieces << ',' << r.tests << ','
        << r.nodes << ',' << r.candidates << ',' << r.triangles << ",\"" << r.note << "\"\n";
  std::printf("%d disagreement%s between methods; CSV: %s\n", disagreements, disagreements == 1 ? "" : "s", out.c_str());
  return 0;
}
