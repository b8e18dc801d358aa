// tests/examples/planner_test.cpp — the planner example's segment checks
// (examples/planner/segment_check.hpp, fcl_checks.hpp, scene.hpp) against an exact
// reference: for every obstacle, CGAL's exact M = P ⊕ −Q (support/mdd_reference.hpp)
// clipped by the line of s gives the exact interval [t_lo, t_hi] of motions of the robot
// that meet the obstacle; a segment t ∈ [0, 1] is blocked iff some interval meets [0, 1].
// The placements are the double poses as given, applied exactly in rationals, so the
// reference answers for exactly the scene the example hands to mdd().
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "planner/fcl_checks.hpp"
#include "planner/scene.hpp"
#include "planner/segment_check.hpp"
#include "support/mdd_reference.hpp"

namespace {

using mink_test::Rational;
using mink_test::Vec3r;
using planner::Verdict;

Vec3r exact(const planner::Vec3& v) { return Vec3r(Rational(v.x()), Rational(v.y()), Rational(v.z())); }

/// The vertices of `shape` placed by `pose`, R·v + t evaluated exactly.
std::vector<Vec3r> placedExactly(const planner::Polyhedron& shape, const planner::Pose& pose) {
  std::vector<Vec3r> out;
  for (const planner::Vec3& v : shape.vertices()) {
    Vec3r w = exact(pose.translation);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) w[i] += Rational(pose.rotation(i, j)) * Rational(v[j]);
    out.push_back(w);
  }
  return out;
}

struct ExactAabb {
  Vec3r lo, hi;
};

ExactAabb boundsOf(const std::vector<Vec3r>& pts) {
  ExactAabb b{pts[0], pts[0]};
  for (const Vec3r& p : pts)
    for (int i = 0; i < 3; ++i) {
      if (p[i] < b.lo[i]) b.lo[i] = p[i];
      if (b.hi[i] < p[i]) b.hi[i] = p[i];
    }
  return b;
}

/// Exact verdict of one segment. Pairs whose exact boxes (the robot's swept from start to
/// goal) are disjoint cannot meet; every other pair gets CGAL's exact M.
struct ExactSegment {
  Verdict verdict = Verdict::Free;
  int hulls = 0;  // exact Minkowski differences built
};

ExactSegment exactVerdict(const planner::Scene& scene, const planner::Segment& seg) {
  ExactSegment out;
  const std::vector<Vec3r> robot = placedExactly(scene.robot.shape, scene.robot.poseAt(seg.start));
  const Vec3r s = exact(seg.s);
  ExactAabb swept = boundsOf(robot);
  for (int i = 0; i < 3; ++i) {
    if (s[i] < 0) swept.lo[i] += s[i];
    else swept.hi[i] += s[i];
  }
  for (const planner::Obstacle& ob : scene.obstacles) {
    const std::vector<Vec3r> P = placedExactly(ob.shape, ob.pose);
    const ExactAabb box = boundsOf(P);
    bool apart = false;
    for (int i = 0; i < 3; ++i) apart = apart || box.hi[i] < swept.lo[i] || swept.hi[i] < box.lo[i];
    if (apart) continue;
    const mink_test::MinkowskiDifferenceReference ref(P, robot);
    ++out.hulls;
    const mink_test::MddRefResult r = ref.query(s);
    if (r.lineMeetsM && r.tLo <= Rational(1) && r.tHi >= Rational(0)) {
      out.verdict = Verdict::Blocked;
      return out;
    }
  }
  return out;
}

// mink's verdicts (broad phase and checkSegmentMdd, as the example runs them, with and
// without a cache kept across segments) on a small random scene equal the exact ones.
TEST(PlannerExample, MddVerdictsEqualTheExactReference) {
  planner::SceneSize size;
  size.obstacles = 18;
  size.milestones = 30;
  size.neighbours = 3;
  size.shortcuts = 40;
  size.seed = 7;
  const planner::Scene scene = planner::makeRandomScene(size);
  ASSERT_GE(scene.segments.size(), 40u);

  std::vector<mink::MddCache<double>> caches(scene.obstacles.size());
  int blocked = 0, hulls = 0, wronglyFree = 0, wronglyBlocked = 0;
  std::vector<int> near;
  for (std::size_t k = 0; k < scene.segments.size(); ++k) {
    const planner::Segment& seg = scene.segments[k];
    planner::nearbyObstacles(scene, seg, near);
    const Verdict cold = planner::checkSegmentMdd(scene, seg, near).verdict;
    const planner::SegmentCheck warm = planner::checkSegmentMdd(scene, seg, near, &caches);
    const ExactSegment truth = exactVerdict(scene, seg);
    hulls += truth.hulls;
    blocked += truth.verdict == Verdict::Blocked;
    wronglyFree += truth.verdict == Verdict::Blocked && cold == Verdict::Free;
    wronglyBlocked += truth.verdict == Verdict::Free && cold == Verdict::Blocked;
    EXPECT_EQ(cold, truth.verdict) << "seed " << size.seed << ", segment " << k << " (milestones " << seg.from
                                   << " -> " << seg.to << (seg.shortcut ? ", shortcut" : "") << ")";
    EXPECT_EQ(warm.verdict, truth.verdict) << "with MddCache: seed " << size.seed << ", segment " << k;
    EXPECT_EQ(warm.undecided, 0) << "segment " << k;
  }
  std::printf("[planner] %zu segments (%d blocked exactly, %d exact hulls of M): mink wrongly free %d, wrongly "
              "blocked %d\n",
              scene.segments.size(), blocked, hulls, wronglyFree, wronglyBlocked);
  // The scene must exercise both answers.
  EXPECT_GT(blocked, 3);
  EXPECT_GT(static_cast<int>(scene.segments.size()) - blocked, 3);
}

// The thin wall: the segment through the 1 cm panel is blocked (exactly and by mdd()), a
// 1 % sampling (101 poses) calls it free, a 0.1 % sampling finds the contact; the segment
// stopping short of the panel is free for all of them.
TEST(PlannerExample, OnePercentSamplingMissesTheThinWall) {
  const planner::Scene scene = planner::makeThinWallScene();
  const planner::FclScene fcl(scene);
  ASSERT_EQ(scene.segments.size(), 2u);
  std::vector<int> near;

  const planner::Segment& through = scene.segments[0];
  planner::nearbyObstacles(scene, through, near);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(exactVerdict(scene, through).verdict, Verdict::Blocked);
  const planner::SegmentCheck c = planner::checkSegmentMdd(scene, through, near);
  EXPECT_EQ(c.verdict, Verdict::Blocked);
  // Contact starts when the robot's centre is 4.035 − 0.02·cos(22.5°) m along the 8 m
  // segment (scene.hpp), between the samples at 4.00 and 4.08 m.
  EXPECT_NEAR(c.contact, (4.035 - 0.02 * std::cos(std::acos(-1.0) / 8)) / 8.0, 1e-12);
  EXPECT_EQ(planner::checkSegmentSampled(scene, fcl, through, near, 101), Verdict::Free);
  EXPECT_EQ(planner::checkSegmentSampled(scene, fcl, through, near, 1001), Verdict::Blocked);

  const planner::Segment& shortOf = scene.segments[1];
  planner::nearbyObstacles(scene, shortOf, near);
  EXPECT_EQ(exactVerdict(scene, shortOf).verdict, Verdict::Free);
  EXPECT_EQ(planner::checkSegmentMdd(scene, shortOf, near).verdict, Verdict::Free);
  EXPECT_EQ(planner::checkSegmentSampled(scene, fcl, shortOf, near, 101), Verdict::Free);
}

}  // namespace
