// mink_cpd_query_bench — the CPD query (cpd/continuous_penetration_depth.hpp) along
// motions, side by side with the Euclidean penetration depth (PD) from the same machinery:
// the point of CPD (issue 15) is that its direction turns continuously as the shapes move,
// where PD's jumps when o crosses the medial axis of ∂M. Per frame, the turn of each
// direction since the last frame, the depths, and the time of each query.
//
// Scenes (A fixed at the identity, B moving along N frames, u = f / (N − 1) in [0, 1];
// procedural shapes of tests/support/mesh_shapes.hpp, unit scale; "turned": B carries the
// fixed rotation G = 0.01 rad about (1, 2, 3)):
//   box/box          A = [-1, 1]^3, B = [-1/2, 1/2]^3 at (0.6 + s, 0.6 − s, 0.05),
//                    s = −0.2 + 0.4 u: across the plane x = y, the medial axis of M between
//                    its faces x = 1.5 and y = 1.5 (the test CoherentAcrossTheMedialAxis…).
//                    Degenerate: B axis-aligned, every facet of M coplanar with others.
//   box/box turned   the same, B turned by G: the generic twin.
//   L-block/box      A = L-block (z in [0, 1]), B = [±0.3, ±0.3, ±0.75] turned by G (taller
//                    than the L, so the nearest exits stay in the xy plane), its centre from
//                    (1.4, 0.4, 0.5) to (0.4, 1.4, 0.5): along one arm, past the reflex
//                    edge, into the other.
//   U-block/L-block  A = U-block, B = L-block turned by G at (−0.4 + 1.2 u, 0.4, 0.35 − 0.7 u):
//                    sliding along the U's base while sinking through z = 0, where the
//                    nearest exits up and down tie.
//   torus/box        A = torus 12 x 8 (R 2, r 0.75, 192 triangles), B = [±0.4, ±0.3, ±0.5]
//                    turned by G at (1.75 + 0.5 u, 0.1, 0.05): radially across the tube's
//                    centre line, where the exits inward and outward tie.
//   torus/box deep   A = torus 16 x 12 (384 triangles), B = [±0.2]^3 turned by G, its centre
//                    circling the tube's centre line at 0.3 (2 + 0.3 cos 6u, 0.3 sin 6u,
//                    0.1): o stays ~0.5 inside ∂M, farther than the facets are wide, where
//                    Phong projections are many and close (Theorem 3 asks for o near ∂M).
//   L-block/box turning  A = L-block, B = [±0.45, ±0.2, ±0.75], turning by 1.2 u rad
//                    (69°) about (0.2, 0.3, 1) after G, along the L-block/box path.
//   The CPD paper's section 7 (Table 1 times the query on these; cpd_paper_scenes.hpp, shared
//   with mink_cpd_bench, states the meshes, B's start pose and the motions), unit scale,
//   --paper-frames frames of the paper's per-frame steps:
//   cone/axes        the cone (1000 triangles) sliding along an arm of the axes while turning;
//   spoon/cup        the spoon (1316) turning about its long axis, leaning on the cup's wall;
//   duck/torus       the duck (4212; the paper's fish) turning in the hole of a torus (1600);
//   torus/torus      a torus (2000) travelling round the hole of the interlocked other.
// Per scene, three queries per frame, each timed alone:
//   cpd     one ContinuousPenetrationDepth along the motion (coherent: each query starts
//           from the last frame's q, section 6.2);
//   fresh   a second ContinuousPenetrationDepth, reset() before every query (its convex
//           maps are kept; only the start is forgotten);
//   pd      penetrationDepth(), the free function: it builds its search (convex maps and
//           overlap scratch) on every call, and that is in its time.
// And FCL's mesh–mesh contact (what users have today), in its own child on the same frames:
//   fcl     fcl::collide on BVHModel<OBBRSSd> (tests/support/fcl_mesh.hpp), enable_contact,
//           num_max_contacts 1e6; the largest contact penetration_depth and its normal
//           (FCL's depth is that of a triangle pair, not a translation that separates the
//           meshes), the contact count, the time of setTransform + collide. Compiled out
//           (MINK_BENCH_HAVE_FCL unset) when CMake finds no FCL.
// Figures per frame: status; depth; the turn of the direction since the previous frame
// (degrees, when both frames overlap); depth ratio cpd / pd and fresh / pd; iterations
// (balls built) and patch triangles built. Check: every answer that is not Separated
// must lie on ∂M — B moved by q + δ·normal clears A and moved by q − δ·normal meets it
// (MeshOverlap, δ = 1e-7); a WARNING line reports any that does not.
// Timing: thread CPU time (CLOCK_THREAD_CPUTIME_ID; the machine is shared), wall time in
// the CSV. Medians and maxima over the frames. Each scene runs in a child process stopped
// after a wall-time limit; the frames that finished are kept.
//
// Usage: mink_cpd_query_bench [out.csv] [--quick] [--frames N] [--paper-frames N]
//                             [--scene-timeout S] [--only SCENE]
//                             [--alpha A] [--beta B] (CpdOptions; defaults 0.3, 2)
//                             [--no-fcl] (FCL's column left empty)
//                             [--no-full-sum] (skip torus/torus's whole Minkowski sum)
//   out.csv           default benchmarks/results/cpd_query.csv (directory must exist); the
//                     per-frame rows go beside it, to <out>_frames.csv
//   --frames          frames per motion (default 60)
//   --paper-frames    frames of the paper's motions (default 20, the paper's steps per frame)
//   --scene-timeout   wall-time limit of a scene's child, seconds (default 90)
//   --only            run one scene (its name as printed, e.g. "torus/box")
//   --quick           12 frames (paper scenes 4), 20 s limits (smoke test, numbers not for
//                     publication)
// The summary closes with Table 1: the coherent query's median beside the paper's time per
// frame (its Table 1 totals) and a quarter of it, the target of issue 15; then the whole
// Minkowski sum of torus/torus at frame 0 (minkowskiBoundary, its own child) against it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bench_common.hpp"
#include "cpd_paper_scenes.hpp"
#include "mink/cpd/continuous_penetration_depth.hpp"
#include "mink/cpd/minkowski_boundary.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "support/mesh_shapes.hpp"
#ifdef MINK_BENCH_HAVE_FCL
#include "support/fcl_mesh.hpp"
#endif

namespace {

using Mesh = mink::TriangleMesh<double>;
using Pose = mink::Pose<double>;
using V = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
using mink_test::MeshShape;

constexpr double kPi = 3.141592653589793238462643383279502884;
constexpr double kDelta = 1e-7;  // the on-∂M check's step along the normal (unit scale)

M3 rot(double angle, const V& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

Pose pose(const M3& R, const V& t) {
  Pose p;
  p.rotation = R;
  p.translation = t;
  return p;
}

Mesh toMesh(const MeshShape& s) { return Mesh::fromMesh(s.verticesAs<double>(), s.triangles); }

struct Scene {
  std::string name;
  bool degenerate = false;
  MeshShape a, b;
  std::function<Pose(double u)> motion;  // B's pose, u in [0, 1]
  bool paper = false;                    // a scene of the paper: B's pose per frame below
  std::function<Pose(int f)> step;       // B's pose at frame f (paper scenes)
  double paperMs = NAN;                  // the paper's Table 1 time per frame
};

std::vector<Scene> scenes() {
  const M3 G = rot(0.01, V(1, 2, 3));  // the small generic turn
  std::vector<Scene> out;
  for (int turned = 0; turned < 2; ++turned) {
    Scene s;
    s.name = turned ? "box/box turned" : "box/box";
    s.degenerate = !turned;
    s.a = mink_test::boxShape();
    s.b = mink_test::boxShape(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5));
    const M3 R = turned ? G : M3::Identity();
    s.motion = [R](double u) {
      const double sl = -0.2 + 0.4 * u;
      return pose(R, V(0.6 + sl, 0.6 - sl, 0.05));
    };
    out.push_back(s);
  }
  {
    Scene s;
    s.name = "L-block/box";
    s.a = mink_test::lBlock();
    s.b = mink_test::boxShape(V(-0.3, -0.3, -0.75), V(0.3, 0.3, 0.75));
    s.motion = [G](double u) { return pose(G, V(1.4 - u, 0.4 + u, 0.5)); };
    out.push_back(s);
  }
  {
    Scene s;
    s.name = "U-block/L-block";
    s.a = mink_test::uBlock();
    s.b = mink_test::lBlock();
    s.motion = [G](double u) { return pose(G, V(-0.4 + 1.2 * u, 0.4, 0.35 - 0.7 * u)); };
    out.push_back(s);
  }
  {
    Scene s;
    s.name = "torus/box";
    s.a = mink_test::torus(12, 8);
    s.b = mink_test::boxShape(V(-0.4, -0.3, -0.5), V(0.4, 0.3, 0.5));
    s.motion = [G](double u) { return pose(G, V(1.75 + 0.5 * u, 0.1, 0.05)); };
    out.push_back(s);
  }
  {
    Scene s;
    s.name = "torus/box deep";
    s.a = mink_test::torus(16, 12);
    s.b = mink_test::boxShape(V(-0.2, -0.2, -0.2), V(0.2, 0.2, 0.2));
    s.motion = [G](double u) { return pose(G, V(2.0 + 0.3 * std::cos(6 * u), 0.3 * std::sin(6 * u), 0.1)); };
    out.push_back(s);
  }
  {
    Scene s;
    s.name = "L-block/box turning";
    s.a = mink_test::lBlock();
    s.b = mink_test::boxShape(V(-0.45, -0.2, -0.75), V(0.45, 0.2, 0.75));
    s.motion = [G](double u) { return pose(rot(1.2 * u, V(0.2, 0.3, 1)) * G, V(1.4 - u, 0.4 + u, 0.5)); };
    out.push_back(s);
  }
  for (const mink_bench::CpdScene& p : mink_bench::cpdPaperScenes()) {
    Scene s;
    s.name = p.name;
    s.a = p.a;
    s.b = p.b;
    s.paper = true;
    s.paperMs = p.paperQueryMs;
    const V t0 = mink_bench::placeB(p);
    s.step = [p, t0](int f) { return p.motion(f, p.R0, t0); };
    out.push_back(s);
  }
  return out;
}

constexpr int kMethods = 3;
const char* const kMethodNames[kMethods] = {"cpd", "fresh", "pd"};

/// One query's answer and cost, as the child reports it.
struct Answer {
  double status;  // CpdStatus as a number: 0 Separated, 1 Penetrating, 2 Approximate
  double depth, dx, dy, dz, residual, cpu, wall, iterations, triangles, fromPrevious;
  double onBoundary;  // 1: q checked on ∂M, 0: the check failed, NaN: Separated
};

/// One frame: the three queries.
struct FrameRecord {
  double frame, setupMs;  // setupMs: building the coherent query's object (frame 0's record)
  Answer q[kMethods];
};

/// One frame of FCL's contact query.
struct FclRecord {
  double frame, collided, contacts, depth, nx, ny, nz, cpu, wall;
};

/// The whole boundary of M at one frame (cpd/minkowski_boundary.hpp): what recomputing the
/// Minkowski sum every frame would cost.
struct FullSumRecord {
  double cpu, triangles;
};

Answer answer(const mink::CpdResult<double>& r, double cpu, double wall) {
  Answer a{};
  a.status = static_cast<double>(static_cast<int>(r.status));
  a.depth = r.depth;
  a.dx = r.direction.x(), a.dy = r.direction.y(), a.dz = r.direction.z();
  a.residual = r.residual;
  a.cpu = cpu;
  a.wall = wall;
  a.iterations = r.iterations;
  a.triangles = static_cast<double>(r.trianglesBuilt);
  a.fromPrevious = r.fromPreviousFrame ? 1 : 0;
  a.onBoundary = NAN;
  return a;
}

/// Is q on ∂M: B moved by q + δn clear of A, moved by q − δn meeting it? (A at the identity.)
bool onBoundary(mink::MeshOverlap<double>& ov, const mink::CpdResult<double>& r) {
  return !ov.overlaps(V(r.point + kDelta * r.normal)) && ov.overlaps(V(r.point - kDelta * r.normal));
}

double med(const std::vector<double>& v) { return mink_bench::quantile(v, 0.5); }
double maxOf(const std::vector<double>& v) { return v.empty() ? NAN : *std::max_element(v.begin(), v.end()); }

struct MethodSummary {
  int penetrating = 0, approximate = 0, separated = 0, fromPrevious = 0, offBoundary = 0;
  std::vector<double> turn, ratio, depth, cpu, wall, iterations, triangles;
};

std::string fmt(const char* f, double x) {
  if (std::isnan(x)) return "–";
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace

/// The usage, as in the comment at the top of this file.
constexpr const char* kUsage =
    "Usage: mink_cpd_query_bench [out.csv] [--quick] [--frames N] [--paper-frames N]\n"
    "                            [--scene-timeout S] [--only SCENE]\n"
    "                            [--alpha A] [--beta B] (CpdOptions; defaults 0.3, 2)\n"
    "                            [--no-fcl] (FCL's column left empty)\n"
    "                            [--no-full-sum] (skip torus/torus's whole Minkowski sum)\n"
    "  out.csv           default benchmarks/results/cpd_query.csv (directory must exist); the\n"
    "                    per-frame rows go beside it, to <out>_frames.csv\n"
    "  --frames          frames per motion (default 60)\n"
    "  --paper-frames    frames of the paper's motions (default 20, the paper's steps per frame)\n"
    "  --scene-timeout   wall-time limit of a scene's child, seconds (default 90)\n"
    "  --only            run one scene (its name as printed, e.g. \"torus/box\")\n"
    "  --quick           12 frames (paper scenes 4), 20 s limits (smoke test, numbers not for\n"
    "                    publication)\n"
    "The summary closes with Table 1: the coherent query's median beside the paper's time per\n"
    "frame (its Table 1 totals) and a quarter of it, the target of issue 15; then the whole\n"
    "Minkowski sum of torus/torus at frame 0 (minkowskiBoundary, its own child) against it.\n";

int main(int argc, char** argv) {
  std::string out = "benchmarks/results/cpd_query.csv";
  bool quick = false;
  int frames = 60, paperFrames = 20;
  double sceneTimeout = 90;
  std::string only;
  mink::CpdOptions<double> options;  // --alpha, --beta: the trade of benchmarks/run_cpd_trade.sh
  bool withFcl = true;
  bool withFullSum = true;  // torus/torus: the whole boundary of M at frame 0, once
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
      only = argv[++i];
    else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc)
      frames = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--paper-frames") == 0 && i + 1 < argc)
      paperFrames = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--scene-timeout") == 0 && i + 1 < argc)
      sceneTimeout = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--alpha") == 0 && i + 1 < argc)
      options.alpha = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--beta") == 0 && i + 1 < argc)
      options.beta = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--no-fcl") == 0)
      withFcl = false;
    else if (std::strcmp(argv[i], "--no-full-sum") == 0)
      withFullSum = false;
    else
      out = mink_bench::pathArgument(argv[i], kUsage);
  }
  if (quick) {
    frames = std::min(frames, 12);
    paperFrames = std::min(paperFrames, 4);
    sceneTimeout = std::min(sceneTimeout, 20.0);
  }
  frames = std::max(frames, 2);
  paperFrames = std::max(paperFrames, 2);
  const std::string framesOut =
      (out.size() > 4 && out.compare(out.size() - 4, 4, ".csv") == 0 ? out.substr(0, out.size() - 4) : out) +
      "_frames.csv";

  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // line by line through tee
  const double runStart = mink_bench::wallMs();
  std::printf("mink_cpd_query_bench: the CPD query along motions beside the Euclidean PD, double\n");
  std::printf("machine: %s; load average %s\n", mink_bench::machineLine().c_str(), mink_bench::loadAverage().c_str());
  std::printf("%d frames per scene (the paper's scenes %d); thread CPU time per query; scene time limit %.0f s "
              "(wall, child process; FCL in a second child with the same limit)%s\n",
              frames, paperFrames, sceneTimeout, quick ? "; --quick: not for publication" : "");
  std::printf("cpd: one ContinuousPenetrationDepth along the motion; fresh: reset() before each query; "
              "pd: penetrationDepth() (builds its search per call); options: alpha %g, beta %g\n",
              options.alpha, options.beta);
#ifdef MINK_BENCH_HAVE_FCL
  std::printf("fcl: fcl::collide on BVHModel<OBBRSSd>, enable_contact, the largest contact penetration_depth\n\n");
#else
  std::printf("fcl: not built (CMake found no FCL)\n\n");
#endif

  struct Row {
    std::string scene;
    bool degenerate;
    int triA, triB, frames, done;
    double setupMs;
    MethodSummary m[kMethods];
    std::string note;
    bool paper;
    double paperMs;
    int fclDone, fclCollided;
    std::vector<double> fclContacts, fclDepth, fclTurn, fclCpu;
    std::string fclNote;
    double fullSumMs = NAN, fullSumTriangles = NAN;
    std::string fullSumNote;
  };
  std::vector<Row> rows;
  std::ofstream fcsv(framesOut);
  fcsv << "# mink_cpd_query_bench; machine: " << mink_bench::machineLine() << "; thread CPU ms per query\n";
  fcsv << "scene,frame,u,method,status,depth,dir_x,dir_y,dir_z,turn_deg,depth_ratio_to_pd,residual,cpu_ms,wall_ms,"
          "iterations,triangles_built,from_previous_frame,on_boundary\n";
  int warnings = 0;

  const int framesAll = frames;
  for (const Scene& sc : scenes()) {
    if (!only.empty() && sc.name != only) continue;
    const double sceneStart = mink_bench::wallMs();
    const Mesh A = toMesh(sc.a), B = toMesh(sc.b);
    const Pose poseA;
    const int frames = sc.paper ? paperFrames : framesAll;
    std::vector<Pose> poses;
    for (int f = 0; f < frames; ++f) poses.push_back(sc.paper ? sc.step(f) : sc.motion(double(f) / (frames - 1)));

    bool finished = false;
    double childCpu = 0;
    const std::vector<FrameRecord> recs = mink_bench::inChild<FrameRecord>(
        sceneTimeout,
        [&](const std::function<void(const FrameRecord&)>& emit) {
          // The setup of a ContinuousPenetrationDepth (convex maps, overlap scratch), apart.
          const double s0 = mink_bench::threadCpuMs();
          mink::ContinuousPenetrationDepth<double> cpd(A, B, options);
          const double setupMs = mink_bench::threadCpuMs() - s0;
          mink::ContinuousPenetrationDepth<double> fresh(A, B, options);
          mink::MeshOverlap<double> ov(A, B, M3::Identity(), V::Zero());
          for (int f = 0; f < frames; ++f) {
            const Pose& pb = poses[static_cast<std::size_t>(f)];
            FrameRecord rec{};
            rec.frame = f;
            rec.setupMs = setupMs;
            mink::CpdResult<double> r[kMethods];
            for (int m = 0; m < kMethods; ++m) {
              if (m == 1) fresh.reset();  // untimed: it only clears a flag
              const double c0 = mink_bench::threadCpuMs(), w0 = mink_bench::wallMs();
              r[m] = m == 0   ? cpd.query(poseA, pb)
                     : m == 1 ? fresh.query(poseA, pb)
                              : mink::penetrationDepth(A, poseA, B, pb, options);
              rec.q[m] = answer(r[m], mink_bench::threadCpuMs() - c0, mink_bench::wallMs() - w0);
            }
            ov.setPlacement(pb.rotation, pb.translation);
            for (int m = 0; m < kMethods; ++m)
              if (r[m].status != mink::CpdStatus::Separated) rec.q[m].onBoundary = onBoundary(ov, r[m]) ? 1 : 0;
            emit(rec);
          }
        },
        finished, &childCpu);

    Row row{sc.name, sc.degenerate, A.numTriangles(), B.numTriangles(), frames, static_cast<int>(recs.size()),
            recs.empty() ? NAN : recs[0].setupMs, {}, "", sc.paper, sc.paperMs, 0, 0, {}, {}, {}, {}, "", NAN, NAN, ""};
    if (!finished) {
      char b[160];
      std::snprintf(b, sizeof b, "stopped after %zu frames, limit %.0f s (of %d; child CPU %.0f ms)", recs.size(),
                    sceneTimeout, frames, childCpu);
      row.note = b;
    }

    // FCL's contact on the same frames, in its own child.
#ifdef MINK_BENCH_HAVE_FCL
    bool fclFinished = false;
    double fclChildCpu = 0;
    const std::vector<FclRecord> frecs = mink_bench::inChild<FclRecord>(
        sceneTimeout,
        [&](const std::function<void(const FclRecord&)>& emit) {
          if (!withFcl) return;  // an empty column
          fcl::CollisionObjectd oa(mink_test::fclModel(A), fcl::Transform3d::Identity());
          fcl::CollisionObjectd ob(mink_test::fclModel(B), fcl::Transform3d::Identity());
          oa.computeAABB();
          for (int f = 0; f < frames; ++f) {
            const Pose& pb = poses[static_cast<std::size_t>(f)];
            const double c0 = mink_bench::threadCpuMs(), w0 = mink_bench::wallMs();
            fcl::Transform3d tf = fcl::Transform3d::Identity();
            tf.linear() = pb.rotation;
            tf.translation() = pb.translation;
            ob.setTransform(tf);
            ob.computeAABB();
            fcl::CollisionRequestd request(1000000, true);
            fcl::CollisionResultd result;
            fcl::collide(&oa, &ob, request, result);
            FclRecord r{};
            r.frame = f;
            r.collided = result.isCollision() ? 1 : 0;
            r.contacts = static_cast<double>(result.numContacts());
            r.depth = NAN;
            for (std::size_t i = 0; i < result.numContacts(); ++i) {
              const fcl::Contactd& c = result.getContact(i);
              if (std::isnan(r.depth) || c.penetration_depth > r.depth) {
                r.depth = c.penetration_depth;
                r.nx = c.normal.x(), r.ny = c.normal.y(), r.nz = c.normal.z();
              }
            }
            r.cpu = mink_bench::threadCpuMs() - c0;
            r.wall = mink_bench::wallMs() - w0;
            emit(r);
          }
        },
        fclFinished, &fclChildCpu);
#else
    const std::vector<FclRecord> frecs;
#endif
    row.fclDone = static_cast<int>(frecs.size());
    // The whole boundary of M (no ball) at frame 0, in its own child: issue 15 asks the
    // coherent query to be 500 times faster than recomputing it every frame (paper: 643x).
    if (withFullSum && sc.name == "torus/torus") {
      bool fullFinished = false;
      const std::vector<FullSumRecord> full = mink_bench::inChild<FullSumRecord>(
          sceneTimeout,
          [&](const std::function<void(const FullSumRecord&)>& emit) {
            const double c0 = mink_bench::threadCpuMs();
            const mink::MinkowskiPatch<double> whole = mink::minkowskiBoundary(A, poseA, B, poses[0]);
            emit({mink_bench::threadCpuMs() - c0, static_cast<double>(whole.triangles.size())});
          },
          fullFinished);
      if (!full.empty()) {
        row.fullSumMs = full[0].cpu;
        row.fullSumTriangles = full[0].triangles;
      } else {
        char b[96];
        std::snprintf(b, sizeof b, "not done within the %.0f s limit", sceneTimeout);
        row.fullSumNote = b;
      }
    }
#ifdef MINK_BENCH_HAVE_FCL
    if (!fclFinished) {
      char b[160];
      std::snprintf(b, sizeof b, "fcl stopped after %zu frames, limit %.0f s (child CPU %.0f ms)", frecs.size(),
                    sceneTimeout, fclChildCpu);
      row.fclNote = b;
    }
#endif
    {
      V last = V::Zero();
      bool lastValid = false;
      for (const FclRecord& r : frecs) {
        row.fclCollided += r.collided != 0;
        row.fclContacts.push_back(r.contacts);
        row.fclCpu.push_back(r.cpu);
        const V n(r.nx, r.ny, r.nz);
        double turn = NAN;
        const bool valid = r.collided != 0 && !std::isnan(r.depth);
        if (valid) {
          row.fclDepth.push_back(r.depth);
          if (lastValid) {
            turn = std::acos(std::clamp(n.dot(last), -1.0, 1.0)) * 180 / kPi;
            row.fclTurn.push_back(turn);
          }
        }
        lastValid = valid;
        last = n;
        fcsv << '"' << sc.name << "\"," << r.frame << ',' << r.frame / (frames - 1) << ",fcl,"
             << (valid ? "Penetrating" : "Separated") << ',' << r.depth << ',' << r.nx << ',' << r.ny << ',' << r.nz
             << ',' << turn << ",,," << r.cpu << ',' << r.wall << ",," << r.contacts << ",0,\n";
      }
    }
    std::array<V, kMethods> lastDir;
    std::array<bool, kMethods> lastValid{};
    for (const FrameRecord& rec : recs) {
      const int f = static_cast<int>(rec.frame);
      const double pdDepth = rec.q[2].status != 0 ? rec.q[2].depth : NAN;
      for (int m = 0; m < kMethods; ++m) {
        const Answer& a = rec.q[m];
        MethodSummary& s = row.m[m];
        const int st = static_cast<int>(a.status);
        (st == 1 ? s.penetrating : st == 2 ? s.approximate : s.separated)++;
        s.fromPrevious += a.fromPrevious != 0;
        s.cpu.push_back(a.cpu);
        s.wall.push_back(a.wall);
        s.iterations.push_back(a.iterations);
        s.triangles.push_back(a.triangles);
        double turn = NAN, ratio = NAN;
        const V dir(a.dx, a.dy, a.dz);
        const bool valid = st != 0 && a.depth > 0;
        if (valid) {
          s.depth.push_back(a.depth);
          if (lastValid[m]) {
            turn = std::acos(std::clamp(dir.dot(lastDir[m]), -1.0, 1.0)) * 180 / kPi;
            s.turn.push_back(turn);
          }
          if (pdDepth > 0) {
            ratio = a.depth / pdDepth;
            s.ratio.push_back(ratio);
          }
        }
        lastValid[m] = valid;
        lastDir[m] = dir;
        if (a.onBoundary == 0) {
          ++s.offBoundary;
          ++warnings;
          std::printf("WARNING %s frame %d %s: q = %.17g (%.6f, %.6f, %.6f) is not on ∂M by MeshOverlap (δ = %g)\n",
                      sc.name.c_str(), f, kMethodNames[m], a.depth, a.dx, a.dy, a.dz, kDelta);
        }
        fcsv << '"' << sc.name << "\"," << f << ',' << double(f) / (frames - 1) << ',' << kMethodNames[m] << ','
             << (st == 1 ? "Penetrating" : st == 2 ? "Approximate" : "Separated") << ',' << a.depth << ',' << a.dx
             << ',' << a.dy << ',' << a.dz << ',' << turn << ',' << ratio << ',' << a.residual << ',' << a.cpu << ','
             << a.wall << ',' << a.iterations << ',' << a.triangles << ',' << a.fromPrevious << ',' << a.onBoundary
             << '\n';
      }
    }
    rows.push_back(row);

    std::printf("== %s%s: %d / %d triangles, %d of %d frames, setup %.3f ms, %.1f s wall%s%s\n", sc.name.c_str(),
                sc.degenerate ? " [degenerate]" : "", row.triA, row.triB, row.done, frames, row.setupMs,
                (mink_bench::wallMs() - sceneStart) * 1e-3, row.note.empty() ? "" : "; ", row.note.c_str());
    if (!row.note.empty()) std::printf("   %s: %s\n", sc.name.c_str(), row.note.c_str());
    std::printf("   %-6s %5s %5s %5s %5s  %9s %9s  %9s %9s  %9s %9s  %9s %9s %9s  %6s %9s\n", "method", "Pen", "Appr",
                "Sep", "prev", "turn med", "turn max", "ratio med", "ratio max", "depth med", "depth max", "ms med",
                "ms q3", "ms max", "iters", "triangles");
    for (int m = 0; m < kMethods; ++m) {
      const MethodSummary& s = row.m[m];
      std::printf("   %-6s %5d %5d %5d %5d  %9.3f %9.3f  %9.4f %9.4f  %9.4f %9.4f  %9.3f %9.3f %9.3f  %6.0f %9.0f\n",
                  kMethodNames[m], s.penetrating, s.approximate, s.separated, s.fromPrevious, med(s.turn),
                  maxOf(s.turn), med(s.ratio), maxOf(s.ratio), med(s.depth), maxOf(s.depth), med(s.cpu),
                  mink_bench::quantile(s.cpu, 0.75), maxOf(s.cpu), med(s.iterations), med(s.triangles));
    }
#ifdef MINK_BENCH_HAVE_FCL
    std::printf("   %-6s %5d %5s %5d %5s  %9.3f %9.3f  %9s %9s  %9.4f %9.4f  %9.3f %9.3f %9.3f  contacts med %.0f, max %.0f"
                "%s%s\n",
                "fcl", row.fclCollided, "", row.fclDone - row.fclCollided, "", med(row.fclTurn), maxOf(row.fclTurn), "",
                "", med(row.fclDepth), maxOf(row.fclDepth), med(row.fclCpu), mink_bench::quantile(row.fclCpu, 0.75),
                maxOf(row.fclCpu), med(row.fclContacts), maxOf(row.fclContacts), row.fclNote.empty() ? "" : "; ",
                row.fclNote.c_str());
#endif
    std::printf("\n");
  }

  // The summary, as a Markdown table (README).
  std::printf("Summary (turn: degrees between consecutive frames' directions; ratio: depth / PD depth; "
              "ms: thread CPU per query, median / max; P/A/S: Penetrating / Approximate / Separated frames):\n\n");
  std::printf("| scene | frames | CPD P/A/S | PD P/A/S | CPD turn med / max | PD turn med / max | CPD / PD depth med / max "
              "| CPD ms med / max | fresh ms med / max | PD ms med / max | CPD iterations | CPD triangles "
              "| CPD depth med | FCL depth med / max | FCL turn med / max | FCL ms med / max |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: "
              "| ---: |\n");
  for (const Row& r : rows) {
    const MethodSummary &c = r.m[0], &fr = r.m[1], &p = r.m[2];
    std::string doneCell = std::to_string(r.done);
    if (r.done < r.frames) doneCell += " of " + std::to_string(r.frames) + " (stopped)";
    std::printf("| %s%s | %s | %d/%d/%d | %d/%d/%d | %s / %s | %s / %s | %s / %s | %s / %s | %s / %s | %s / %s | %s | %s "
                "| %s | %s / %s | %s / %s | %s / %s |\n",
                r.scene.c_str(), r.degenerate ? " (degenerate)" : "", doneCell.c_str(), c.penetrating, c.approximate, c.separated,
                p.penetrating, p.approximate, p.separated, fmt("%.2f", med(c.turn)).c_str(),
                fmt("%.2f", maxOf(c.turn)).c_str(), fmt("%.2f", med(p.turn)).c_str(), fmt("%.2f", maxOf(p.turn)).c_str(),
                fmt("%.3f", med(c.ratio)).c_str(), fmt("%.3f", maxOf(c.ratio)).c_str(), fmt("%.3f", med(c.cpu)).c_str(),
                fmt("%.3f", maxOf(c.cpu)).c_str(), fmt("%.3f", med(fr.cpu)).c_str(), fmt("%.3f", maxOf(fr.cpu)).c_str(),
                fmt("%.3f", med(p.cpu)).c_str(), fmt("%.3f", maxOf(p.cpu)).c_str(),
                fmt("%.0f", med(c.iterations)).c_str(), fmt("%.0f", med(c.triangles)).c_str(),
                fmt("%.4f", med(c.depth)).c_str(), fmt("%.4f", med(r.fclDepth)).c_str(),
                fmt("%.4f", maxOf(r.fclDepth)).c_str(), fmt("%.2f", med(r.fclTurn)).c_str(),
                fmt("%.2f", maxOf(r.fclTurn)).c_str(), fmt("%.3f", med(r.fclCpu)).c_str(),
                fmt("%.3f", maxOf(r.fclCpu)).c_str());
  }
  std::printf("\n");

  // Table 1 of the paper: its query's time per frame beside mink's coherent query.
  std::printf("Table 1 (the paper's scenes; paper: its Table 1 total per frame, ms, on its machine; target: a "
              "quarter of it; ms: thread CPU per query, median):\n\n");
  std::printf("| scene | triangles A / B | frames done | CPD setup ms | CPD ms med | CPD ms max | paper ms | target ms "
              "| CPD / paper | fresh ms med | PD ms med | FCL ms med | FCL contacts med | note |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n");
  for (const Row& r : rows) {
    if (!r.paper) continue;
    const MethodSummary &c = r.m[0], &fr = r.m[1], &p = r.m[2];
    std::printf("| %s | %d / %d | %d of %d | %s | %s | %s | %.2f | %.2f | %s | %s | %s | %s | %s | %s |\n",
                r.scene.c_str(), r.triA, r.triB, r.done, r.frames, fmt("%.1f", r.setupMs).c_str(),
                fmt("%.3f", med(c.cpu)).c_str(), fmt("%.3f", maxOf(c.cpu)).c_str(), r.paperMs, r.paperMs / 4,
                fmt("%.2f", med(c.cpu) / r.paperMs).c_str(), fmt("%.3f", med(fr.cpu)).c_str(),
                fmt("%.3f", med(p.cpu)).c_str(), fmt("%.3f", med(r.fclCpu)).c_str(),
                fmt("%.0f", med(r.fclContacts)).c_str(), r.note.c_str());
  }
  std::printf("\n");
  for (const Row& r : rows) {
    if (std::isnan(r.fullSumMs) && r.fullSumNote.empty()) continue;
    if (std::isnan(r.fullSumMs)) {
      std::printf("Whole Minkowski sum, %s frame 0: %s\n\n", r.scene.c_str(), r.fullSumNote.c_str());
      continue;
    }
    std::printf("Whole Minkowski sum, %s frame 0 (minkowskiBoundary, thread CPU): %.1f ms, %.0f triangles; the coherent "
                "CPD query's median is %.1fx faster (target >= 500x; paper 643x)\n\n",
                r.scene.c_str(), r.fullSumMs, r.fullSumTriangles, r.fullSumMs / med(r.m[0].cpu));
  }

  std::ofstream csv(out);
  csv << "# mink_cpd_query_bench; machine: " << mink_bench::machineLine() << "; thread CPU ms per query\n";
  csv << "scene,degenerate,triangles_a,triangles_b,frames,frames_done,setup_ms,method,penetrating,approximate,separated,"
         "from_previous_frame,off_boundary,turn_median_deg,turn_max_deg,depth_ratio_median,depth_ratio_max,depth_median,"
         "depth_max,q1_ms,median_ms,q3_ms,max_ms,wall_median_ms,iterations_median,iterations_max,triangles_median,"
         "triangles_max,paper_ms,note\n";
  for (const Row& r : rows)
    for (int m = 0; m < kMethods; ++m) {
      const MethodSummary& s = r.m[m];
      csv << '"' << r.scene << "\"," << (r.degenerate ? 1 : 0) << ',' << r.triA << ',' << r.triB << ',' << r.frames
          << ',' << r.done << ',' << r.setupMs << ',' << kMethodNames[m] << ',' << s.penetrating << ',' << s.approximate
          << ',' << s.separated << ',' << s.fromPrevious << ',' << s.offBoundary << ',' << med(s.turn) << ','
          << maxOf(s.turn) << ',' << med(s.ratio) << ',' << maxOf(s.ratio) << ',' << med(s.depth) << ','
          << maxOf(s.depth) << ',' << mink_bench::quantile(s.cpu, 0.25) << ',' << med(s.cpu) << ','
          << mink_bench::quantile(s.cpu, 0.75) << ',' << maxOf(s.cpu) << ',' << med(s.wall) << ','
          << med(s.iterations) << ',' << maxOf(s.iterations) << ',' << med(s.triangles) << ',' << maxOf(s.triangles)
          << ',' << r.paperMs << ",\"" << r.note << "\"\n";
    }
  for (const Row& r : rows) {
    if (r.fclCpu.empty()) continue;
    csv << '"' << r.scene << "\"," << (r.degenerate ? 1 : 0) << ',' << r.triA << ',' << r.triB << ',' << r.frames << ','
        << r.fclDone << ",,fcl," << r.fclCollided << ",0," << r.fclDone - r.fclCollided << ",0,0," << med(r.fclTurn)
        << ',' << maxOf(r.fclTurn) << ",,," << med(r.fclDepth) << ',' << maxOf(r.fclDepth) << ','
        << mink_bench::quantile(r.fclCpu, 0.25) << ',' << med(r.fclCpu) << ',' << mink_bench::quantile(r.fclCpu, 0.75)
        << ',' << maxOf(r.fclCpu) << ",," << med(r.fclContacts) << ',' << maxOf(r.fclContacts) << ",,," << r.paperMs
        << ",\"" << r.fclNote << "\"\n";
  }
  std::printf("%d answer%s off ∂M; CSV: %s, %s; the run took %.0f s of wall time\n", warnings, warnings == 1 ? "" : "s",
              out.c_str(), framesOut.c_str(), (mink_bench::wallMs() - runStart) * 1e-3);
  return 0;
}
