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
// Per scene, three queries per frame, each timed alone:
//   cpd     one ContinuousPenetrationDepth along the motion (coherent: each query starts
//           from the last frame's q, section 6.2);
//   fresh   a second ContinuousPenetrationDepth, reset() before every query (its convex
//           maps are kept; only the start is forgotten);
//   pd      penetrationDepth(), the free function: it builds its search (convex maps and
//           overlap scratch) on every call, and that is in its time.
// Figures per frame: status; depth; the turn of the direction since the previous frame
// (degrees, when both frames overlap); depth ratio cpd / pd and fresh / pd; iterations
// (balls built) and patch triangles built. Check: every answer that is not Separated
// must lie on ∂M — B moved by q + δ·normal clears A and moved by q − δ·normal meets it
// (MeshOverlap, δ = 1e-7); a WARNING line reports any that does not.
// Timing: thread CPU time (CLOCK_THREAD_CPUTIME_ID; the machine is shared), wall time in
// the CSV. Medians and maxima over the frames. Each scene runs in a child process stopped
// after a wall-time limit; the frames that finished are kept.
//
// Usage: mink_cpd_query_bench [out.csv] [--quick] [--frames N] [--scene-timeout S] [--only SCENE]
//   out.csv           default benchmarks/results/cpd_query.csv (directory must exist); the
//                     per-frame rows go beside it, to <out>_frames.csv
//   --frames          frames per motion (default 60)
//   --scene-timeout   wall-time limit of a scene's child, seconds (default 90)
//   --only            run one scene (its name as printed, e.g. "torus/box")
//   --quick           12 frames, 20 s limits (smoke test, numbers not for publication)
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
#include "mink/cpd/continuous_penetration_depth.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "support/mesh_shapes.hpp"

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
  double frame;
  Answer q[kMethods];
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

int main(int argc, char** argv) {
  std::string out = "benchmarks/results/cpd_query.csv";
  bool quick = false;
  int frames = 60;
  double sceneTimeout = 90;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
      only = argv[++i];
    else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc)
      frames = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--scene-timeout") == 0 && i + 1 < argc)
      sceneTimeout = std::atof(argv[++i]);
    else
      out = argv[i];
  }
  if (quick) {
    frames = std::min(frames, 12);
    sceneTimeout = std::min(sceneTimeout, 20.0);
  }
  frames = std::max(frames, 2);
  const std::string framesOut =
      (out.size() > 4 && out.compare(out.size() - 4, 4, ".csv") == 0 ? out.substr(0, out.size() - 4) : out) +
      "_frames.csv";

  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // line by line through tee
  const double runStart = mink_bench::wallMs();
  std::printf("mink_cpd_query_bench: the CPD query along motions beside the Euclidean PD, double\n");
  std::printf("machine: %s; load average %s\n", mink_bench::machineLine().c_str(), mink_bench::loadAverage().c_str());
  std::printf("%d frames per scene; thread CPU time per query; scene time limit %.0f s (wall, child process)%s\n",
              frames, sceneTimeout, quick ? "; --quick: not for publication" : "");
  std::printf("cpd: one ContinuousPenetrationDepth along the motion; fresh: reset() before each query; "
              "pd: penetrationDepth() (builds its search per call)\n\n");

  struct Row {
    std::string scene;
    bool degenerate;
    int triA, triB, frames, done;
    double setupMs;
    MethodSummary m[kMethods];
    std::string note;
  };
  std::vector<Row> rows;
  std::ofstream fcsv(framesOut);
  fcsv << "# mink_cpd_query_bench; machine: " << mink_bench::machineLine() << "; thread CPU ms per query\n";
  fcsv << "scene,frame,u,method,status,depth,dir_x,dir_y,dir_z,turn_deg,depth_ratio_to_pd,residual,cpu_ms,wall_ms,"
          "iterations,triangles_built,from_previous_frame,on_boundary\n";
  int warnings = 0;

  for (const Scene& sc : scenes()) {
    if (!only.empty() && sc.name != only) continue;
    const double sceneStart = mink_bench::wallMs();
    const Mesh A = toMesh(sc.a), B = toMesh(sc.b);
    const Pose poseA;
    std::vector<Pose> poses;
    for (int f = 0; f < frames; ++f) poses.push_back(sc.motion(double(f) / (frames - 1)));

    // The setup of a ContinuousPenetrationDepth (convex maps, overlap scratch), apart.
    double setupMs = NAN;
    {
      const double c0 = mink_bench::threadCpuMs();
      mink::ContinuousPenetrationDepth<double> probe(A, B);
      setupMs = mink_bench::threadCpuMs() - c0;
    }

    bool finished = false;
    double childCpu = 0;
    const std::vector<FrameRecord> recs = mink_bench::inChild<FrameRecord>(
        sceneTimeout,
        [&](const std::function<void(const FrameRecord&)>& emit) {
          mink::ContinuousPenetrationDepth<double> cpd(A, B), fresh(A, B);
          mink::MeshOverlap<double> ov(A, B, M3::Identity(), V::Zero());
          for (int f = 0; f < frames; ++f) {
            const Pose& pb = poses[static_cast<std::size_t>(f)];
            FrameRecord rec{};
            rec.frame = f;
            mink::CpdResult<double> r[kMethods];
            for (int m = 0; m < kMethods; ++m) {
              if (m == 1) fresh.reset();  // untimed: it only clears a flag
              const double c0 = mink_bench::threadCpuMs(), w0 = mink_bench::wallMs();
              r[m] = m == 0 ? cpd.query(poseA, pb) : m == 1 ? fresh.query(poseA, pb) : mink::penetrationDepth(A, poseA, B, pb);
              rec.q[m] = answer(r[m], mink_bench::threadCpuMs() - c0, mink_bench::wallMs() - w0);
            }
            ov.setPlacement(pb.rotation, pb.translation);
            for (int m = 0; m < kMethods; ++m)
              if (r[m].status != mink::CpdStatus::Separated) rec.q[m].onBoundary = onBoundary(ov, r[m]) ? 1 : 0;
            emit(rec);
          }
        },
        finished, &childCpu);

    Row row{sc.name, sc.degenerate, A.numTriangles(), B.numTriangles(), frames, static_cast<int>(recs.size()), setupMs,
            {}, ""};
    if (!finished) {
      char b[128];
      std::snprintf(b, sizeof b, "stopped after %.0f s: %zu of %d frames (child CPU %.0f ms)", sceneTimeout, recs.size(),
                    frames, childCpu);
      row.note = b;
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
                sc.degenerate ? " [degenerate]" : "", row.triA, row.triB, row.done, frames, setupMs,
                (mink_bench::wallMs() - sceneStart) * 1e-3, row.note.empty() ? "" : "; ", row.note.c_str());
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
    std::printf("\n");
  }

  // The summary, as a Markdown table (README).
  std::printf("Summary (turn: degrees between consecutive frames' directions; ratio: depth / PD depth; "
              "ms: thread CPU per query, median / max; P/A/S: Penetrating / Approximate / Separated frames):\n\n");
  std::printf("| scene | frames | CPD P/A/S | PD P/A/S | CPD turn med / max | PD turn med / max | CPD / PD depth med / max "
              "| CPD ms med / max | fresh ms med / max | PD ms med / max | CPD iterations | CPD triangles |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (const Row& r : rows) {
    const MethodSummary &c = r.m[0], &fr = r.m[1], &p = r.m[2];
    std::printf("| %s%s | %d | %d/%d/%d | %d/%d/%d | %s / %s | %s / %s | %s / %s | %s / %s | %s / %s | %s / %s | %s | %s |\n",
                r.scene.c_str(), r.degenerate ? " (degenerate)" : "", r.done, c.penetrating, c.approximate, c.separated,
                p.penetrating, p.approximate, p.separated, fmt("%.2f", med(c.turn)).c_str(),
                fmt("%.2f", maxOf(c.turn)).c_str(), fmt("%.2f", med(p.turn)).c_str(), fmt("%.2f", maxOf(p.turn)).c_str(),
                fmt("%.3f", med(c.ratio)).c_str(), fmt("%.3f", maxOf(c.ratio)).c_str(), fmt("%.3f", med(c.cpu)).c_str(),
                fmt("%.3f", maxOf(c.cpu)).c_str(), fmt("%.3f", med(fr.cpu)).c_str(), fmt("%.3f", maxOf(fr.cpu)).c_str(),
                fmt("%.3f", med(p.cpu)).c_str(), fmt("%.3f", maxOf(p.cpu)).c_str(),
                fmt("%.0f", med(c.iterations)).c_str(), fmt("%.0f", med(c.triangles)).c_str());
  }
  std::printf("\n");

  std::ofstream csv(out);
  csv << "# mink_cpd_query_bench; machine: " << mink_bench::machineLine() << "; thread CPU ms per query\n";
  csv << "scene,degenerate,triangles_a,triangles_b,frames,frames_done,setup_ms,method,penetrating,approximate,separated,"
         "from_previous_frame,off_boundary,turn_median_deg,turn_max_deg,depth_ratio_median,depth_ratio_max,depth_median,"
         "depth_max,q1_ms,median_ms,q3_ms,max_ms,wall_median_ms,iterations_median,iterations_max,triangles_median,"
         "triangles_max,note\n";
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
          << ",\"" << r.note << "\"\n";
    }
  std::printf("%d answer%s off ∂M; CSV: %s, %s; the run took %.0f s of wall time\n", warnings, warnings == 1 ? "" : "s",
              out.c_str(), framesOut.c_str(), (mink_bench::wallMs() - runStart) * 1e-3);
  return 0;
}
