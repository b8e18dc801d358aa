// Tests examples/physics_step/scene.hpp: the claim of the physics_step example, that
// mink::mdd() as a time of impact misses no impact, calls no false one and places each
// one within kToiBound of the step, checked on every pair query of a small fixed scene
// against the exact reference (tests/support/mdd_reference.hpp: CGAL hull of all vertex
// differences in Gmpq, the line of d clipped exactly) on the same world vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics_step/exact_impact.hpp"
#include "physics_step/scene.hpp"
#include "support/mdd_reference.hpp"
#include "support/paper_shapes.hpp"

namespace {

using physics_step::Impact;
using physics_step::Vec3;

// |TOI error| allowed, as a fraction of the sweep's motion d. mink answers for the poses;
// the reference for world vertices rounded once (pose.apply), so the two problems differ
// by ~eps * extent, and the TOI by that over |d| (>= g dt^2 ~ 2.7e-3 m for a step; the
// slide sweeps can be shorter). `mink_physics_step --full` measured at most 2.2e-12 over 14,457
// impacts (examples/physics_step/results/physics_step_full.txt).
constexpr double kToiBound = 1e-9;

std::vector<Vec3> scaled(std::vector<Vec3> pts, double k) {
  for (Vec3& p : pts) p *= k;
  return pts;
}

std::vector<physics_step::ShapeDef> shapes() {
  std::vector<Vec3> box;
  for (int i = 0; i < 8; ++i) box.emplace_back(i & 1 ? 0.3 : -0.3, i & 2 ? 0.2 : -0.2, i & 4 ? 0.15 : -0.15);
  return {{"box", box},
          {"P1-cone", scaled(mink_test::paperCone(), 0.08)},
          {"P2-cylinder", scaled(mink_test::paperCylinder(), 0.08)}};
}

TEST(PhysicsStep, MddToiMatchesExactReference) {
  physics_step::SceneConfig config;
  config.bodies = 9;
  config.steps = 60;
  config.seed = 18;
  config.spawnHalfWidth = 5.0;  // low and over the terrain: most of the 60 steps in contact
  config.spawnLow = 1.0;
  config.spawnHigh = 3.0;
  physics_step::Scene scene(shapes(), config);

  int queries = 0, impacts = 0, clear = 0;
  double maxError = 0.0;
  for (int s = 0; s < config.steps; ++s) {
    scene.step(s, [&](const physics_step::PairQuery& q) {
      const physics_step::MinkAnswer a = physics_step::minkToi(q);
      const Impact e = physics_step::exactImpact(q);
      ++queries;
      impacts += e.hit;
      clear += !e.hit;
      EXPECT_NE(a.result.status, mink::MddStatus::IterationLimit)
          << "seed " << config.seed << " step " << s << " sweep " << q.sweep << " body " << q.body << " piece " << q.piece;
      EXPECT_EQ(a.impact.hit, e.hit) << "seed " << config.seed << " step " << s << " sweep " << q.sweep << " body "
                                     << q.body << " piece " << q.piece << ": mink parameter " << a.result.parameter
                                     << ", exact toi " << e.toi;
      if (a.impact.hit && e.hit) {
        const double err = std::abs(a.impact.toi - e.toi);
        maxError = std::max(maxError, err);
        EXPECT_LE(err, kToiBound) << "seed " << config.seed << " step " << s << " sweep " << q.sweep << " body "
                                  << q.body << " piece " << q.piece;
      }
      return a;
    });
  }
  std::printf("[physics_step] %d pair queries, %d impacts, %d without; max |TOI error| %.2e of the step\n", queries,
              impacts, clear, maxError);
  // The scene must exercise both answers, or the test proves nothing.
  EXPECT_GE(impacts, 50);
  EXPECT_GE(clear, 20);
  EXPECT_EQ(scene.counters().iterationLimits, 0);
}

}  // namespace
