// planner — straight-line motion checks of a probabilistic roadmap with mink::mdd(),
// beside FCL's sampled and continuous checks.
//
// Builds the random scene of scene.hpp, checks every roadmap edge with each method, and
// prints per method the median and mean time per segment (broad phase included) and how
// many segments it calls wrongly free or wrongly blocked against mink's mdd() answer
// (exact up to rounding; tests/examples/planner_test.cpp checks it against CGAL's exact
// reference). Writes planner_segments.csv and planner_obstacles.csv for plot_planner.py.
//
// Usage: planner [--full] [--seed N] [--out DIR]
//   default: 36 obstacles, 150 milestones, k = 5, 150 shortcuts (a second or two);
//   --full: 80 obstacles, 1000 milestones, k = 6, 1000 shortcuts.
// Exits non-zero when mink's own answers disagree (mdd with and without MddCache), when an
// mdd() query hits its iteration limit, or when the thin-wall segment is not blocked.
#include "fcl_checks.hpp"
#include "scene.hpp"
#include "segment_check.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double microseconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::micro>(b - a).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::string cpuName() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

const char* name(planner::Verdict v) { return v == planner::Verdict::Free ? "free" : "blocked"; }

struct Method {
  const char* label;
  std::vector<planner::Verdict> verdict;
  std::vector<double> micros;
};

}  // namespace

int main(int argc, char** argv) {
  planner::SceneSize size;
  std::string outDir = ".";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--full")) {
      size.obstacles = 80;
      size.milestones = 1000;
      size.shortcuts = 1000;
      size.neighbours = 6;
    } else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) {
      size.seed = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    } else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) {
      outDir = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--full] [--seed N] [--out DIR]\n", argv[0]);
      return 2;
    }
  }
  int failures = 0;

  // The case sampling misses by construction (scene.hpp): mink must block it.
  {
    const planner::Scene wall = planner::makeThinWallScene();
    const planner::FclScene fclWall(wall);
    std::vector<int> near;
    planner::nearbyObstacles(wall, wall.segments[0], near);
    const planner::SegmentCheck c = planner::checkSegmentMdd(wall, wall.segments[0], near);
    std::printf("thin wall (1 cm panel, 8 m segment): mink mdd %s (contact at t = %.5f), FCL 101 poses %s, "
                "1001 poses %s; FCL conservative advancement: libccd %s, indep %s\n",
                name(c.verdict), c.contact, name(planner::checkSegmentSampled(wall, fclWall, wall.segments[0], near, 101)),
                name(planner::checkSegmentSampled(wall, fclWall, wall.segments[0], near, 1001)),
                name(planner::checkSegmentConservativeAdvancement(wall, fclWall, wall.segments[0], near)),
                name(planner::checkSegmentConservativeAdvancement(wall, fclWall, wall.segments[0], near, fcl::GST_INDEP)));
    if (c.verdict != planner::Verdict::Blocked) {
      std::printf("FAIL: mink calls the thin-wall segment free\n");
      ++failures;
    }
  }

  const planner::Scene scene = planner::makeRandomScene(size);
  const planner::FclScene fcl(scene);
  const std::size_t n = scene.segments.size();

  std::vector<std::vector<int>> candidates(n);
  for (std::size_t k = 0; k < n; ++k) planner::nearbyObstacles(scene, scene.segments[k], candidates[k]);

  std::vector<Method> methods = {{"mink mdd", {}, {}},
                                 {"mink mdd + MddCache per obstacle", {}, {}},
                                 {"FCL collide, 101 poses (1 %)", {}, {}},
                                 {"FCL collide, 1001 poses (0.1 %)", {}, {}},
                                 {"FCL continuousCollide, CA, libccd", {}, {}},
                                 {"FCL continuousCollide, CA, indep", {}, {}}};
  // Each pass checks every segment with every method; a segment's time is its fastest of
  // kPasses (the caches are emptied before each pass, so every pass runs the same queries).
  constexpr int kPasses = 3;
  std::vector<int> queries(n), undecided(n);
  std::vector<double> contact(n);
  for (Method& m : methods) m.micros.assign(n, 1e300), m.verdict.assign(n, planner::Verdict::Free);
  for (int pass = 0; pass < kPasses; ++pass) {
    std::vector<mink::MddCache<double>> caches(scene.obstacles.size());
    for (std::size_t k = 0; k < n; ++k) {
      const planner::Segment& seg = scene.segments[k];
      for (std::size_t m = 0; m < methods.size(); ++m) {
        const auto t0 = Clock::now();
        std::vector<int>& near = candidates[k];
        planner::nearbyObstacles(scene, seg, near);
        planner::Verdict v;
        if (m == 0 || m == 1) {
          const planner::SegmentCheck c = planner::checkSegmentMdd(scene, seg, near, m == 1 ? &caches : nullptr);
          v = c.verdict;
          if (m == 0) queries[k] = c.queries, undecided[k] = c.undecided, contact[k] = c.contact;
        } else if (m == 2 || m == 3) {
          v = planner::checkSegmentSampled(scene, fcl, seg, near, m == 2 ? 101 : 1001);
        } else {
          v = planner::checkSegmentConservativeAdvancement(scene, fcl, seg, near,
                                                           m == 4 ? fcl::GST_LIBCCD : fcl::GST_INDEP);
        }
        methods[m].micros[k] = std::min(methods[m].micros[k], microseconds(t0, Clock::now()));
        methods[m].verdict[k] = v;
      }
    }
  }

  const std::vector<planner::Verdict>& truth = methods[0].verdict;
  int totalQueries = 0, totalUndecided = 0;
  for (std::size_t k = 0; k < n; ++k) totalQueries += queries[k], totalUndecided += undecided[k];
  std::printf("\nscene: seed %u, %zu obstacles (boxes, 1-2 cm panels, 14-point hulls), robot: octagonal rod "
              "1 m x 4 cm (%d vertices)\n",
              size.seed, scene.obstacles.size(), scene.robot.shape.numVertices());
  std::printf("roadmap: %zu milestones (free by mink::intersects), k = %d; %d mdd queries after the broad phase, "
              "%d IterationLimit\n",
              scene.milestones.size(), size.neighbours, totalQueries, totalUndecided);
  std::printf("machine: %s; one thread; time per segment = AABB broad phase + the method, fastest of %d passes;\n"
              "median over the segments with an obstacle near (the others cost only the broad phase), mean over all\n",
              cpuName().c_str(), kPasses);
  for (int shortcut = 0; shortcut < 2; ++shortcut) {
    std::vector<std::size_t> all, narrow;
    for (std::size_t k = 0; k < n; ++k)
      if (scene.segments[k].shortcut == (shortcut == 1)) {
        all.push_back(k);
        if (!candidates[k].empty()) narrow.push_back(k);
      }
    double length = 0;
    long blocked = 0;
    for (std::size_t k : all) length += scene.segments[k].s.norm(), blocked += truth[k] == planner::Verdict::Blocked;
    std::printf("\n%s: %zu segments, mean length %.2f m, %zu with an obstacle near; mink mdd: %ld blocked, %ld free\n",
                shortcut ? "shortcuts (random milestone pairs)" : "roadmap edges (k nearest)", all.size(),
                all.empty() ? 0.0 : length / all.size(), narrow.size(), blocked, static_cast<long>(all.size()) - blocked);
    std::printf("%-36s %12s %12s %14s %17s\n", "method", "median us", "mean us", "wrongly free", "wrongly blocked");
    for (const Method& m : methods) {
      int wrongFree = 0, wrongBlocked = 0;
      double sum = 0;
      for (std::size_t k : all) {
        wrongFree += truth[k] == planner::Verdict::Blocked && m.verdict[k] == planner::Verdict::Free;
        wrongBlocked += truth[k] == planner::Verdict::Free && m.verdict[k] == planner::Verdict::Blocked;
        sum += m.micros[k];
      }
      std::vector<double> narrowMicros;
      for (std::size_t k : narrow) narrowMicros.push_back(m.micros[k]);
      std::printf("%-36s %12.2f %12.2f %14d %17d\n", m.label, median(narrowMicros), all.empty() ? 0.0 : sum / all.size(),
                  wrongFree, wrongBlocked);
      if (&m == &methods[1] && (wrongFree || wrongBlocked)) {
        std::printf("FAIL: mdd with MddCache disagrees with mdd without it\n");
        ++failures;
      }
    }
  }
  // FCL's own witness: a pose where fcl::collide reports overlap is a contact whatever
  // mink says, so a segment conservative advancement calls free while sampling finds a
  // colliding pose is an error of conservative advancement by FCL's own account.
  for (std::size_t m = 4; m < methods.size(); ++m) {
    int caFreeSampledBlocked = 0;
    for (std::size_t k = 0; k < n; ++k)
      caFreeSampledBlocked += methods[m].verdict[k] == planner::Verdict::Free &&
                              (methods[2].verdict[k] == planner::Verdict::Blocked ||
                               methods[3].verdict[k] == planner::Verdict::Blocked);
    std::printf("%ssegments \"%s\" calls free although fcl::collide finds a colliding sampled pose: %d\n",
                m == 4 ? "\n" : "", methods[m].label, caFreeSampledBlocked);
  }
  if (totalUndecided) {
    std::printf("FAIL: %d mdd queries hit the iteration limit\n", totalUndecided);
    ++failures;
  }

  const std::string segPath = outDir + "/planner_segments.csv", obPath = outDir + "/planner_obstacles.csv";
  {
    std::ofstream csv(segPath);
    csv << "segment,shortcut,from,to,x0,y0,z0,x1,y1,z1,mdd_queries,mdd_contact_t,truth_mink_mdd,mink_mdd_cache,fcl_101,"
           "fcl_1001,fcl_ca_libccd,fcl_ca_indep,us_mink_mdd,us_mink_mdd_cache,us_fcl_101,us_fcl_1001,us_fcl_ca_libccd,"
           "us_fcl_ca_indep\n";
    csv.precision(17);
    for (std::size_t k = 0; k < n; ++k) {
      const planner::Segment& s = scene.segments[k];
      const planner::Vec3 g = s.start + s.s;
      csv << k << ',' << s.shortcut << ',' << s.from << ',' << s.to << ',' << s.start.x() << ',' << s.start.y() << ',' << s.start.z()
          << ',' << g.x() << ',' << g.y() << ',' << g.z() << ',' << queries[k] << ',' << contact[k];
      for (const Method& m : methods) csv << ',' << name(m.verdict[k]);
      for (const Method& m : methods) csv << ',' << m.micros[k];
      csv << '\n';
    }
  }
  {
    std::ofstream csv(obPath);
    csv << "obstacle,x,y,z\n";
    csv.precision(17);
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
      for (const planner::Vec3& v : scene.obstacles[i].shape.vertices()) {
        const planner::Vec3 w = scene.obstacles[i].pose.apply(v);
        csv << i << ',' << w.x() << ',' << w.y() << ',' << w.z() << '\n';
      }
  }
  std::printf("\nwrote %s and %s (plot: python3 examples/planner/plot_planner.py %s)\n", segPath.c_str(), obPath.c_str(),
              outDir.c_str());
  return failures ? 1 : 0;
}
