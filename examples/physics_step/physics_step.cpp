// physics_step — translational continuous collision detection in a falling-bodies scene
// (scene.hpp), with mink::mdd() as the time-of-impact (TOI) method, measured against FCL.
//
// Every candidate (terrain piece, body) pair of every sweep is answered by:
//   mink          mink::mdd(piece, body, s = d) with one MddCache per pair (the scene
//                 moves by this answer, so all methods get the same questions);
//   mink no cache the same query with a fresh MddCache (what the pair's cache saves);
//   fcl-CA/libccd fcl::continuousCollide, CCDC_CONSERVATIVE_ADVANCEMENT, CCDM_TRANS,
//                 GST_LIBCCD (FCL's default solver), toc_err 1e-4 (FCL's default);
//   fcl-CA/indep  the same with FCL's own GJK (GST_INDEP);
//   fcl-discrete  fcl::collide at the end of the motion only (blind to tunnelling);
//   exact         MinkowskiDifferenceReference (tests/support/mdd_reference.hpp): the exact
//                 hull of all vertex differences (CGAL, Gmpq), the line of d clipped exactly.
// The impact rule (scene.hpp, mink::firstContact) turns each answer into "impact at t in [0,1]"
// or "no impact"; missed / false impacts and |TOI error| (fraction of the step) are counted
// against the exact one. FCL sees the same hull vertices as fcl::Convexd.
//
// Usage: mink_physics_step [--full] [--out DIR] [--seed N]
//   default: 12 bodies, 90 steps (seconds); --full: 300 bodies, 120 steps (minutes: the
//   exact reference, a CGAL hull of up to 4,304 points per query, takes most of the time).
//   Writes DIR/physics_step.csv (one row per pair query); plot_physics_step.py draws it.
#include <mink/mink.hpp>

#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "physics_step/exact_impact.hpp"
#include "physics_step/scene.hpp"
#include "support/gjk_reference.hpp"
#include "support/mdd_reference.hpp"
#include "support/paper_shapes.hpp"

namespace {

using physics_step::Impact;
using physics_step::Vec3;
using Clock = std::chrono::steady_clock;

double microseconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::micro>(b - a).count();
}

// Points scaled (about their bounding-box centre) to fit a sphere of `radius`.
std::vector<Vec3> fitToRadius(std::vector<Vec3> pts, double radius) {
  Vec3 lo = pts[0], hi = pts[0];
  for (const Vec3& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec3 c = 0.5 * (lo + hi);
  double r = 0.0;
  for (const Vec3& p : pts) r = std::max(r, (p - c).norm());
  for (Vec3& p : pts) p = (p - c) * (radius / r);
  return pts;
}

std::vector<physics_step::ShapeDef> bodyShapes(const std::string& dataDir) {
  std::vector<physics_step::ShapeDef> out;
  auto box = [](double a, double b, double c) {
    std::vector<Vec3> p;
    for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? a : -a, i & 2 ? b : -b, i & 4 ? c : -c);
    return p;
  };
  const double r = 0.4;  // m, body size
  // Pebbles thrown down at 12 m/s move 0.2 m per step: more than their size (8 cm) and the
  // shelf's thickness (5 cm) together, so a discrete check at the step's end can miss them.
  out.push_back({"pebble", box(0.04, 0.04, 0.04), 12.0});
  out.push_back({"box", box(0.3, 0.2, 0.15)});
  out.push_back({"cube", box(0.25, 0.25, 0.25)});
  out.push_back({"P1-cone", fitToRadius(mink_test::paperCone(), r)});
  out.push_back({"P2-cylinder", fitToRadius(mink_test::paperCylinder(), r)});
  out.push_back({"P3-ellipsoid", fitToRadius(mink_test::paperEllipsoid(200), r)});
  out.push_back({"P6-revolution", fitToRadius(mink_test::paperRevolution(), r)});
  for (const char* name : {"duck", "lego"}) {
    const auto mesh = mink::io::readObj<double>(std::filesystem::path(dataDir) / (std::string(name) + ".obj"));
    out.push_back({std::string(name) + "-hull", fitToRadius(mesh.vertices, r)});
  }
  return out;
}

std::shared_ptr<fcl::Convexd> fclConvex(const mink::ConvexPolyhedron<double>& shape) {
  // fcl::Convexd wants a triangulated closed hull: tests/support/gjk_reference.hpp builds
  // it from the same vertices with CGAL's exact-predicate hull.
  mink_test::GjkShape g(shape.vertices());
  return std::make_shared<fcl::Convexd>(g.fclConvex());
}

enum Method { kMink, kMinkCold, kCaLibccd, kCaIndep, kDiscrete, kExact, kMethods };
const char* kMethodNames[kMethods] = {"mink mdd",     "mink no cache", "fcl CA libccd",
                                      "fcl CA indep", "fcl discrete",  "exact (CGAL)"};

struct Row {
  int step, sweep, body, piece;
  std::string shape;
  double dLength;
  const char* exactStatus;
  Impact answer[kMethods];
  double us[kMethods];
  const char* minkStatus;
  const char* minkPath;
};

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

}  // namespace

int main(int argc, char** argv) {
  physics_step::SceneConfig config;
  config.bodies = 12;
  config.steps = 90;
  std::string outDir = ".";
  std::string dataDir = MINK_EXAMPLES_DATA_DIR;
  bool full = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--full")) {
      full = true;
    } else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) {
      outDir = argv[++i];
    } else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) {
      config.seed = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    } else if (!std::strcmp(argv[i], "--data") && i + 1 < argc) {
      dataDir = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--full] [--out DIR] [--seed N] [--data DIR]\n", argv[0]);
      return 2;
    }
  }
  if (full) {
    config.bodies = 300;
    config.steps = 120;
    config.spawnHalfWidth = 8.0;
    config.spawnHigh = 16.0;
  }

  physics_step::Scene scene(bodyShapes(dataDir), config);
  std::vector<std::shared_ptr<fcl::Convexd>> fclBodies, fclTerrain;
  for (const auto& s : scene.bodyShapes()) fclBodies.push_back(fclConvex(s));
  for (const auto& s : scene.terrainShapes()) fclTerrain.push_back(fclConvex(s));

  std::printf("physics_step: %d bodies (", config.bodies);
  for (std::size_t i = 0; i < scene.bodyShapes().size(); ++i)
    std::printf("%s%s %d v", i ? ", " : "", scene.bodyShapeNames()[i].c_str(), scene.bodyShapes()[i].numVertices());
  std::printf("), %zu terrain boxes, %d steps of %.4f s, seed %u\n", scene.pieces().size(), config.steps,
              config.dt, config.seed);

  fcl::ContinuousCollisionRequestd caLibccd, caIndep;
  caLibccd.ccd_solver_type = caIndep.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
  caLibccd.ccd_motion_type = caIndep.ccd_motion_type = fcl::CCDM_TRANS;
  caLibccd.gjk_solver_type = fcl::GST_LIBCCD;
  caIndep.gjk_solver_type = fcl::GST_INDEP;

  // The scene runs first, driven by mink, and records every pair query; then each method
  // answers all of them in its own loop, timed call by call. (Timed inside the scene, a
  // method paid for the CPU caches the previous query's exact reference had flushed.)
  std::vector<physics_step::PairQuery> queries;
  std::vector<Impact> driven;
  auto toi = [&](const physics_step::PairQuery& q) {
    physics_step::MinkAnswer a = physics_step::minkToi(q);
    queries.push_back(q);
    driven.push_back(a.impact);
    return a;
  };
  const auto wall0 = Clock::now();
  for (int s = 0; s < config.steps; ++s) scene.step(s, toi);
  const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();

  std::vector<Row> rows(queries.size());
  const std::size_t pieces = scene.pieces().size();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const physics_step::PairQuery& q = queries[i];
    Row& row = rows[i];
    row.step = q.step;
    row.sweep = q.sweep;
    row.body = q.body;
    row.piece = q.piece;
    const int shape = scene.bodies()[static_cast<std::size_t>(q.body)].shape;
    row.shape = scene.bodyShapeNames()[static_cast<std::size_t>(shape)];
    row.dLength = q.d.norm();
  }

  // mink, one MddCache per pair replayed in the scene's order (so each query sees the cache
  // state it saw in the scene), and with a fresh cache per query.
  long long replayMismatches = 0;
  {
    std::vector<mink::MddCache<double>> caches(scene.bodies().size() * pieces);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      physics_step::PairQuery q = queries[i];
      q.cache = &caches[static_cast<std::size_t>(q.body) * pieces + static_cast<std::size_t>(q.piece)];
      const auto t0 = Clock::now();
      const physics_step::MinkAnswer a = physics_step::minkToi(q);
      const auto t1 = Clock::now();
      rows[i].us[kMink] = microseconds(t0, t1);
      rows[i].answer[kMink] = a.impact;
      rows[i].minkStatus = mink::toString(a.result.status);
      rows[i].minkPath = mink::toString(a.result.path);
      replayMismatches += a.impact.hit != driven[i].hit || a.impact.toi != driven[i].toi;
    }
  }
  for (std::size_t i = 0; i < queries.size(); ++i) {
    mink::MddCache<double> fresh;  // cold start: allocates its buffers
    physics_step::PairQuery q = queries[i];
    q.cache = &fresh;
    const auto t0 = Clock::now();
    const physics_step::MinkAnswer a = physics_step::minkToi(q);
    const auto t1 = Clock::now();
    rows[i].us[kMinkCold] = microseconds(t0, t1);
    rows[i].answer[kMinkCold] = a.impact;
  }

  for (Method m : {kCaLibccd, kCaIndep, kDiscrete}) {
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const physics_step::PairQuery& q = queries[i];
      const int shape = scene.bodies()[static_cast<std::size_t>(q.body)].shape;
      const Eigen::Isometry3d tfP = q.poseP.toIsometry(), tfQ0 = q.poseQ.toIsometry();
      Eigen::Isometry3d tfQ1 = tfQ0;
      tfQ1.translation() += q.d;
      const fcl::Convexd* gP =
          fclTerrain[static_cast<std::size_t>(scene.pieces()[static_cast<std::size_t>(q.piece)].shape)].get();
      const fcl::Convexd* gQ = fclBodies[static_cast<std::size_t>(shape)].get();
      if (m == kDiscrete) {
        fcl::CollisionRequestd req;
        fcl::CollisionResultd res;
        const auto t0 = Clock::now();
        const bool hit = fcl::collide(gP, tfP, gQ, tfQ1, req, res) > 0;
        const auto t1 = Clock::now();
        rows[i].us[m] = microseconds(t0, t1);
        rows[i].answer[m].hit = hit;
        rows[i].answer[m].toi = 1.0;  // discrete: no time of impact
      } else {
        fcl::ContinuousCollisionResultd res;
        const auto t0 = Clock::now();
        fcl::continuousCollide(gP, tfP, tfP, gQ, tfQ0, tfQ1, m == kCaLibccd ? caLibccd : caIndep, res);
        const auto t1 = Clock::now();
        rows[i].us[m] = microseconds(t0, t1);
        rows[i].answer[m].hit = res.is_collide;
        rows[i].answer[m].toi = res.is_collide ? res.time_of_contact : 1.0;
      }
    }
  }

  for (std::size_t i = 0; i < queries.size(); ++i) {
    const physics_step::PairQuery& q = queries[i];
    mink_test::MddRefResult r;
    const auto t0 = Clock::now();
    const Impact e = physics_step::exactImpact(q, &r);
    const auto t1 = Clock::now();
    rows[i].us[kExact] = microseconds(t0, t1);
    rows[i].exactStatus = mink_test::toString(r.status);
    rows[i].answer[kExact] = e;
  }

  int resting = 0, active = 0;
  for (const auto& b : scene.bodies()) {
    if (!b.active) continue;
    ++active;
    if (b.pose.translation.z() < 1.0 && b.velocity.norm() < 0.5) ++resting;
  }
  long long exactHits = 0, penetratingAtStart = 0;
  for (const Row& r : rows) {
    exactHits += r.answer[kExact].hit;
    penetratingAtStart += !std::strcmp(r.exactStatus, "Penetrating");
  }
  std::printf("%zu pair queries (%lld impacts by the exact reference, %lld of them overlapping at the start), "
              "%lld impacts applied, %lld IterationLimit; %d of %d bodies on the scene at the end below z = 1 m "
              "and slower than 0.5 m/s; scene %.1f s wall time; mink's replay differs from the scene in %lld\n\n",
              rows.size(), exactHits, penetratingAtStart, scene.counters().impacts, scene.counters().iterationLimits,
              resting, active, wall, replayMismatches);

  std::printf("%-14s %12s %12s %8s %8s %8s %14s %14s\n", "method", "median us", "p90 us", "impacts", "missed",
              "false", "max |TOI err|", "median |err|");
  for (int m = 0; m < kMethods; ++m) {
    std::vector<double> us, err;
    long long hits = 0, missed = 0, falseHits = 0;
    for (const Row& r : rows) {
      us.push_back(r.us[m]);
      const Impact& a = r.answer[m];
      const Impact& e = r.answer[kExact];
      hits += a.hit;
      if (e.hit && !a.hit) ++missed;
      if (!e.hit && a.hit) ++falseHits;
      if (e.hit && a.hit) err.push_back(std::abs(a.toi - e.toi));
    }
    char maxErr[32] = "n/a", medErr[32] = "n/a";
    if (m != kDiscrete && !err.empty()) {
      std::snprintf(maxErr, sizeof maxErr, "%.2e", *std::max_element(err.begin(), err.end()));
      std::snprintf(medErr, sizeof medErr, "%.2e", median(err));
    }
    std::printf("%-14s %12.2f %12.2f %8lld %8lld %8lld %14s %14s\n", kMethodNames[m], median(us), quantile(us, 0.9),
                hits, missed, falseHits, maxErr, medErr);
  }

  std::filesystem::create_directories(outDir);
  const std::string csvPath = (std::filesystem::path(outDir) / "physics_step.csv").string();
  std::ofstream csv(csvPath);
  csv << "step,sweep,body,piece,shape,d_length,exact_status,mink_status,mink_path";
  const char* keys[kMethods] = {"mink", "mink_cold", "fcl_ca_libccd", "fcl_ca_indep", "fcl_discrete", "exact"};
  for (int m = 0; m < kMethods; ++m) csv << ',' << keys[m] << "_hit," << keys[m] << "_toi," << keys[m] << "_us";
  csv << '\n';
  csv.precision(17);
  for (const Row& r : rows) {
    csv << r.step << ',' << r.sweep << ',' << r.body << ',' << r.piece << ',' << r.shape << ',' << r.dLength << ','
        << r.exactStatus << ',' << r.minkStatus << ',' << r.minkPath;
    for (int m = 0; m < kMethods; ++m)
      csv << ',' << (r.answer[m].hit ? 1 : 0) << ',' << r.answer[m].toi << ',' << r.us[m];
    csv << '\n';
  }
  std::printf("\nwrote %s (plot: python3 examples/physics_step/plot_physics_step.py %s)\n", csvPath.c_str(),
              csvPath.c_str());
  return 0;
}
