// tests/mdd/hostile_input_test.cpp — hostile arguments to mink::mdd and mink::intersects
// (issue 5): every rejection (non-finite or zero direction, non-finite, non-orthonormal or
// reflecting pose, for P and for Q, in both entry points) is a mink::InvalidInput whose
// message names the argument and the problem; valid corner cases (exact 90° rotations,
// rotations just inside the tolerance) are accepted and answered right; the visit cap
// yields a status, not an exception. References are worked by hand (boxes). The
// "Regression" tests reproduce library bugs the fuzzer found (fuzz/regressions/), fixed
// since.
#include "mink/mdd/mdd.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/expect_rejected.hpp"

namespace {

using mink::ConvexPolyhedron;
using mink::MddStatus;
using mink::Pose;
using V = mink::Vec3<double>;
using M3 = mink::Mat3<double>;

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

ConvexPolyhedron<double> box(double a) {
  std::vector<V> p;
  for (int i = 0; i < 8; ++i) p.push_back(V(i & 1 ? a : -a, i & 2 ? a : -a, i & 4 ? a : -a));
  return ConvexPolyhedron<double>::fromPoints(p);
}

using mink_test::expectRejected;

struct BadPose {
  const char* name;
  Pose<double> pose;
  const char* problem;  // the message after "<poseP|poseQ>."
};

std::vector<BadPose> badPoses() {
  std::vector<BadPose> out;
  Pose<double> p;
  p.translation = V(0, kNaN, 0);
  out.push_back({"NaN translation", p, "translation is not finite"});
  p = Pose<double>();
  p.translation = V(0, 0, -kInf);
  out.push_back({"-Inf translation", p, "translation is not finite"});
  p = Pose<double>();
  p.rotation(1, 2) = kNaN;
  out.push_back({"NaN rotation entry", p, "rotation is not finite"});
  p = Pose<double>();
  p.rotation(0, 0) = kInf;
  out.push_back({"Inf rotation entry", p, "rotation is not finite"});
  p = Pose<double>();
  p.rotation *= 1.01;
  out.push_back({"rotation scaled by 1.01", p, "rotation is not orthonormal"});
  p = Pose<double>();
  p.rotation(0, 1) = 1e-3;
  out.push_back({"sheared rotation", p, "rotation is not orthonormal"});
  p = Pose<double>();
  p.rotation = M3::Zero();
  out.push_back({"zero rotation", p, "rotation is not orthonormal"});
  p = Pose<double>();
  p.rotation = Eigen::Quaterniond(1, 2, 3, 4).toRotationMatrix();  // unnormalised quaternion
  out.push_back({"unnormalised quaternion", p, "rotation is not orthonormal"});
  p = Pose<double>();
  p.rotation(2, 2) = -1;
  out.push_back({"mirror z", p, "rotation is a reflection"});
  p = Pose<double>();
  p.rotation = -M3::Identity();
  out.push_back({"point reflection", p, "rotation is a reflection"});
  return out;
}

TEST(MddHostile, BadPosesNameTheArgumentInMddAndIntersects) {
  const auto B = box(1);
  Pose<double> ok;
  ok.translation = V(3, 0, 0);
  for (const BadPose& b : badPoses()) {
    expectRejected([&] { (void)mink::mdd(B, b.pose, B, ok, V(-1, 0, 0)); }, std::string("poseP.") + b.problem,
                   std::string("mdd, poseP: ") + b.name);
    expectRejected([&] { (void)mink::mdd(B, Pose<double>(), B, b.pose, V(-1, 0, 0)); },
                   std::string("poseQ.") + b.problem, std::string("mdd, poseQ: ") + b.name);
    expectRejected([&] { (void)mink::intersects(B, b.pose, B, ok); }, std::string("poseP.") + b.problem,
                   std::string("intersects, poseP: ") + b.name);
    expectRejected([&] { (void)mink::intersects(B, Pose<double>(), B, b.pose); }, std::string("poseQ.") + b.problem,
                   std::string("intersects, poseQ: ") + b.name);
    mink::MddCache<double> cache;
    expectRejected([&] { (void)mink::mdd(B, Pose<double>(), B, b.pose, V(-1, 0, 0), cache); },
                   std::string("poseQ.") + b.problem, std::string("mdd with cache, poseQ: ") + b.name);
  }
}

TEST(MddHostile, APoseKeptInTheCacheLetsNoOtherPoseThroughUnchecked) {
  // The cache keeps poseP once checked (with its inverse rotation), so that a shape that
  // stays put is not checked again: only the same pose, bit for bit, may skip the check.
  const auto B = box(1);
  Pose<double> q;
  q.translation = V(3, 0.25, 0);
  mink::MddCache<double> cache;
  const auto fresh = [&](const Pose<double>& p) {
    mink::MddCache<double> c;
    return mink::mdd(B, p, B, q, V(-1, 0, 0), c);
  };
  for (const BadPose& b : badPoses()) {
    (void)mink::mdd(B, Pose<double>(), B, q, V(-1, 0, 0), cache);
    expectRejected([&] { (void)mink::mdd(B, b.pose, B, q, V(-1, 0, 0), cache); }, std::string("poseP.") + b.problem,
                   std::string("mdd after a good poseP: ") + b.name);
    expectRejected([&] { (void)mink::intersects(B, b.pose, B, q, cache); }, std::string("poseP.") + b.problem,
                   std::string("intersects after a good poseP: ") + b.name);
  }
  // A good pose after another, and the kept one again: each answered as by a fresh cache.
  Pose<double> turned;
  turned.rotation = Eigen::AngleAxisd(0.3, V(0, 0, 1)).toRotationMatrix();
  turned.translation = V(-0.5, 0, 0);
  for (const Pose<double>& p : {turned, Pose<double>(), turned}) {
    const auto r = mink::mdd(B, p, B, q, V(-1, 0, 0), cache), f = fresh(p);
    EXPECT_EQ(r.status, f.status);
    EXPECT_EQ(r.translation, f.translation);
    EXPECT_EQ(r.normal, f.normal);
  }
}

TEST(MddHostile, BadDirectionsAreNamed) {
  const auto B = box(1);
  Pose<double> q;
  q.translation = V(3, 0, 0);
  struct Case {
    V s;
    const char* words;
  };
  for (const Case& c : {Case{V(0, 0, 0), "direction s is zero"}, Case{V(-0.0, 0.0, -0.0), "direction s is zero"},
                        Case{V(0, kNaN, 0), "direction s is not finite"}, Case{V(1, 0, -kInf), "direction s is not finite"},
                        Case{V(kInf, kInf, kInf), "direction s is not finite"}}) {
    expectRejected([&] { (void)mink::mdd(B, Pose<double>(), B, q, c.s); }, c.words,
                   ::testing::PrintToString(std::vector<double>{c.s[0], c.s[1], c.s[2]}));
  }
  // A direction is checked before the poses: both bad, the direction is named.
  Pose<double> bad;
  bad.rotation *= 2;
  expectRejected([&] { (void)mink::mdd(B, Pose<double>(), B, bad, V(0, 0, 0)); }, "direction s is zero",
                 "zero s and bad pose");
}

// Exact 90° rotations (signed permutation matrices with det +1) are orthonormal exactly;
// rotations off by 1e-7 (inside the documented 1e-6) are accepted too. Box [-1,1]^3
// against the same box centred at (3,0,0) along -x: they touch after moving 1.
TEST(MddHostile, Exact90DegreeAndNearlyOrthonormalRotationsAreAccepted) {
  const auto B = box(1);
  std::vector<M3> rotations;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& pm : perms)
    for (int signs = 0; signs < 8; ++signs) {
      M3 R = M3::Zero();
      for (int r = 0; r < 3; ++r) R(r, pm[r]) = (signs >> r) & 1 ? -1.0 : 1.0;
      if (R.determinant() > 0) rotations.push_back(R);
    }
  ASSERT_EQ(rotations.size(), 24u);
  M3 nearly = M3::Identity();
  nearly(0, 1) = 1e-7;
  rotations.push_back(nearly);
  for (std::size_t i = 0; i < rotations.size(); ++i) {
    SCOPED_TRACE("rotation " + std::to_string(i));
    Pose<double> p, q;
    p.rotation = rotations[i];
    q.rotation = rotations[(i * 7) % rotations.size()];
    q.translation = V(3, 0, 0);
    mink::MddResult<double> r;
    ASSERT_NO_THROW(r = mink::mdd(B, p, B, q, V(-2, 0, 0)));
    EXPECT_EQ(r.status, MddStatus::Separated);
    EXPECT_NEAR(r.translation, 1.0, 1e-5);
    EXPECT_NEAR(r.parameter, 0.5, 1e-5);
    EXPECT_FALSE(mink::intersects(B, p, B, q));
  }
}

// The visit cap: maxVisits = 0 stops every search at once. Whatever the configuration
// the answer is a status, never an exception or a hang; with the automatic cap the same
// queries are answered (hand-worked: boxes of half-size 1, Q centred at x along -x).
TEST(MddHostile, VisitCapZeroYieldsIterationLimitNotException) {
  const auto B = box(1);
  struct Case {
    double x;           // Q's centre on the x axis
    MddStatus status;   // with the automatic cap
    double translation; // x-distance Q moves along -x
  };
  // Overlapping at x = 1.5: the short way out moves Q by +0.5 in x, i.e. against s.
  for (const Case& c : {Case{3.0, MddStatus::Separated, 1.0}, Case{1.5, MddStatus::Penetrating, -0.5},
                        Case{-1.25, MddStatus::Penetrating, 0.75}}) {
    SCOPED_TRACE("Q at x = " + std::to_string(c.x));
    Pose<double> q;
    q.translation = V(c.x, 0, 0);
    // Slightly tilted so the line of s is in general position with respect to the faces.
    const V s(-1, 1e-3, 2e-3);
    mink::MddOptions<double> capped;
    capped.maxVisits = 0;
    mink::MddResult<double> r;
    ASSERT_NO_THROW(r = mink::mdd(B, Pose<double>(), B, q, s, capped));
    EXPECT_EQ(r.status, MddStatus::IterationLimit);
    EXPECT_EQ(r.faceType, mink::MddFaceType::None);
    // No answer reads as no answer: a caller who forgets the status must not see 0
    // (touching) or a finite distance.
    EXPECT_TRUE(std::isnan(r.distance));
    EXPECT_TRUE(std::isnan(r.translation));
    EXPECT_TRUE(std::isnan(r.parameter));
    const auto full = mink::mdd(B, Pose<double>(), B, q, s);
    EXPECT_EQ(full.status, c.status);
    // Along s (tilted), the contact distance is the x-distance divided by |s_x|/|s|.
    EXPECT_NEAR(full.translation, c.translation * s.norm(), 1e-12);
  }
}

// intersects() takes the same options as mdd(): a touch tolerance (a length) makes a gap
// below it count as contact; NaN is rejected. Boxes of half-size 1, Q's centre at x = 2 + gap.
TEST(MddHostile, IntersectsHonoursItsOptions) {
  const auto B = box(1);
  Pose<double> q;
  q.translation = V(2.001, 0.3, -0.2);
  EXPECT_FALSE(mink::intersects(B, Pose<double>(), B, q));
  mink::MddOptions<double> loose;
  loose.touchTolerance = 0.01;  // 1 cm against a 1 mm gap
  EXPECT_TRUE(mink::intersects(B, Pose<double>(), B, q, loose));
  loose.touchTolerance = 0.0005;
  EXPECT_FALSE(mink::intersects(B, Pose<double>(), B, q, loose));
  mink::MddCache<double> cache;
  EXPECT_TRUE(mink::intersects(B, Pose<double>(), B, q, cache, mink::MddOptions<double>{0.01}));
  // The same answer as mdd() with that tolerance.
  EXPECT_EQ(mink::mdd(B, Pose<double>(), B, q, V(-1, 0, 0), mink::MddOptions<double>{0.01}).status,
            MddStatus::Touching);
  mink::MddOptions<double> nan;
  nan.touchTolerance = std::numeric_limits<double>::quiet_NaN();
  expectRejected([&] { (void)mink::intersects(B, Pose<double>(), B, q, nan); }, "touchTolerance",
                 "intersects touchTolerance NaN");
}

// mdd() answers for s as given, or says it did not: a component below the unit roundoff
// of the largest is taken as 0 (directionRounded). Boxes of half-size 1, Q at x = 3.
TEST(MddHostile, RoundedDirectionIsReported) {
  const auto B = box(1);
  Pose<double> q;
  q.translation = V(3, 0, 0);
  const auto exact = mink::mdd(B, Pose<double>(), B, q, V(-1, 0, 0));
  EXPECT_FALSE(exact.directionRounded);
  const auto tilted = mink::mdd(B, Pose<double>(), B, q, V(-1, 1e-3, 0));
  EXPECT_FALSE(tilted.directionRounded);
  const auto rounded = mink::mdd(B, Pose<double>(), B, q, V(-1, 1e-20, 0));
  EXPECT_TRUE(rounded.directionRounded);
  EXPECT_EQ(rounded.status, MddStatus::Separated);
  EXPECT_DOUBLE_EQ(rounded.translation, 1.0);
}

// Regression (fuzzer): MddOptions::touchTolerance = NaN is silently replaced by the automatic
// tolerance (the test `touchTolerance >= 0` is false for NaN). Every public entry point
// should reject NaN input naming it.
TEST(MddHostile, NaNTouchToleranceIsRejected) {
  const auto B = box(1);
  Pose<double> q;
  q.translation = V(3, 0, 0);
  mink::MddOptions<double> o;
  o.touchTolerance = kNaN;
  expectRejected([&] { (void)mink::mdd(B, Pose<double>(), B, q, V(-1, 0, 0), o); }, "touchTolerance",
                 "touchTolerance NaN");
}

// Regression (fuzzer): the answer depends on |s|, which the contract says may be any non-zero
// length. With |s| <= ~1e-160 mdd() returns Touching or IterationLimit (or a translation
// off by 6e-6 at 1e-160), with |s| >= ~1e160 NoContact (|s|^2 over/underflows). Expected
// for every scale: Separated, translation 1 (boxes of half-size 1, Q at x = 3, s along -x).
TEST(MddHostile, DirectionScaleDoesNotChangeTheAnswer) {
  const auto B = box(1);
  Pose<double> q;
  q.translation = V(3, 0, 0);
  for (double k : {1e-300, 1e-200, 1e-160, 1e160, 1e200, 1e300}) {
    SCOPED_TRACE("|s| = " + std::to_string(k));
    const auto r = mink::mdd(B, Pose<double>(), B, q, V(-k, 0, 0));
    EXPECT_EQ(r.status, MddStatus::Separated);
    EXPECT_NEAR(r.translation, 1.0, 1e-12);
    const auto d = mink::mdd(B, Pose<double>(), B, q, V(-k, k, 0));  // diagonal: sqrt(2)
    EXPECT_EQ(d.status, MddStatus::Separated);
    EXPECT_NEAR(d.translation, std::sqrt(2.0), 1e-12);
  }
}

// A huge s against tiny shapes (fuzzer: |s| = 5e302, shapes of 2e-131): parameter =
// translation / |s| is below the double range and comes out 0 (documented in
// MddResult::parameter), while translation and the witnesses stay accurate.
TEST(MddHostile, HugeDirectionAgainstTinyShapesKeepsTheTranslation) {
  const auto B = box(1e-131);
  Pose<double> q;
  q.translation = V(3e-131, 0, 0);
  const auto r = mink::mdd(B, Pose<double>(), B, q, V(-5e302, 0, 0));
  ASSERT_EQ(r.status, MddStatus::Separated);
  EXPECT_NEAR(r.translation, 1e-131, 1e-143);
  EXPECT_EQ(r.parameter, 0.0);
  EXPECT_NEAR((r.witnessP - r.witnessQ).x(), -1e-131, 1e-143);
}

// Regression (fuzzer, fuzz/regressions/iteration_limit_after_fallback_{1,2}): valid inputs with
// the default caps end in IterationLimit (usedFallback is set: the facet check failed and
// the exhaustive fallback did not answer). Tetrahedra with integer vertices; P rotated by
// a rotation from a normalised quaternion (orthonormal to 2e-16 in case 2, 7e-9 in case 1,
// both well inside the accepted 1e-6). Expected answers from the fuzzer's brute-force
// reference (slab clipping of the line against P ⊕ −Q over all SAT axes); with the
// rotation re-orthonormalised by SVD mink itself gives them (case 2: -1.9999999999999993).
TEST(MddHostile, RotatedTetrahedraDoNotHitTheIterationCap) {
  {
    SCOPED_TRACE("case 2: penetrating, exit through t = -2");
    const auto P = ConvexPolyhedron<double>::fromPoints({V(3, 3, 76), V(-13, -6, 9), V(0, 6, -13), V(0, 0, 0)});
    Pose<double> pp, pq;
    pp.translation = V(-2, 0, -2);
    pp.rotation << -0.36945052116844712, -0.26122764123021497, 0.89177712006176812, 0.89177712006176812,
        -0.36945052116844712, 0.26122764123021497, 0.26122764123021497, 0.89177712006176812, 0.36945052116844712;
    pq.translation = V(-2, -2, -2);
    const auto r = mink::mdd(P, pp, P, pq, V(0, -2, 0));
    EXPECT_EQ(r.status, MddStatus::Penetrating);
    EXPECT_NEAR(r.translation, -2.0, 1e-9);
  }
  {
    SCOPED_TRACE("case 1: separated, contact at t = 43.896...");
    const auto P = ConvexPolyhedron<double>::fromPoints({V(11, 1, 71), V(71, 6, 67), V(-72, 1, 11), V(6, 64, -86)});
    Pose<double> pp, pq;
    pp.rotation << 0.88734835355285968, 0.057192374350086651, 0.45753899480069321, 0.057192374350086651,
        -0.99826689774696686, 0.013864818024263429, 0.45753899480069321, 0.013864825474844026, -0.88908145580589237;
    pq.translation = V(-2, -2, -2);
    const auto r = mink::mdd(P, pp, P, pq, V(-2, -2, -2));
    EXPECT_EQ(r.status, MddStatus::Separated);
    EXPECT_NEAR(r.translation, 43.8962, 1e-3);  // rotation 7e-9 off orthonormal: ~1e-6 slack
  }
}

// Regression (fuzzer, fuzz/regressions/intersects_flat_edge_arc_antipode, reduced): shapes
// of 5e25 whose other corners sit within 1e-79 of one point, both placed at (-2, -2, -2),
// hull tolerance 0; they overlap by 2e25. Q has an edge whose two face normals are 1e-16
// apart, in the plane of the arc of an edge of P: the arc test's signs were rounding,
// declared an EE face whose arcs are 180 degrees apart, its plane through the origin
// (k = -9e-236), and intersects() answered false. Now the crossing must be the same
// point on both arcs, and "apart" is certified by support queries along the normal.
TEST(MddHostile, IntersectsOfHugeShapesMeetingAtATinyCluster) {
  mink::HullOptions<double> exact;
  exact.tolerance = 0;
  const auto P = ConvexPolyhedron<double>::fromPoints(
      {V(-0x1.f0f0f0f0f0f0fp+17, 0x1.f0f0f0f0f0f0fp-783, 0x1.f0f0f0f0f0f0fp-783),
       V(0x1.f0f0f0f0f0f0fp-783, 0x1.f0f0f0f0f0f0fp-1007, 0x1.1010301030301p-1007),
       V(0x1.5454545454545p+85, 0x1.5454545450545p+85, 0x1.5454545454545p+85),
       V(0x1.5454545454545p+85, 0x1.5454545454545p+85, 0x1.5454545454545p+85),
       V(0x1.7373737374545p-140, 0x1.7373737373737p-140, 0x1.5454545454537p+85)},
      exact);
  const auto Q = ConvexPolyhedron<double>::fromPoints(
      {V(0x1p-79, 0x1.2012af8ffp-991, 0x1.f0f0102040201p-783),
       V(0x1.e151515151515p-685, 0x1.5151515151515p-782, 0x0.10f0f0f0f0f0fp-1022),
       V(0x1.f0f070f0f0f0fp+81, 0x1.5454545454545p+85, 0x1.5450000000e45p+85),
       V(0x1.5454545454545p+85, -0x1.ababafabe4545p-84, 0x1.545454545babap+85),
       V(0x1.5454545454545p+85, 0x1.5454545454545p+85, 0x1.5454545454545p+85),
       V(0x1.030008c275045p-1017, 0x1.f0f0f454545p-783, 0x1.f0f0f0f0f0f0fp-783)},
      exact);
  Pose<double> pose;
  pose.translation = V(-2, -2, -2);
  EXPECT_TRUE(mink::intersects(P, pose, Q, pose));
  mink::MddCache<double> cache;
  EXPECT_TRUE(mink::intersects(P, pose, Q, pose, cache));
  const auto r = mink::mdd(P, pose, Q, pose, V(55, 55, 55));
  EXPECT_EQ(r.status, MddStatus::Penetrating);
  EXPECT_LT(r.translation, -1e24);
}

// Regression (fuzzer, fuzz/regressions/sheets_near_parallel_edges_spurious_face): P = Q, a
// tetrahedron 1e-10 thick (a sheet), placed so that moving Q by -s puts it exactly on P.
// An EE face of two near-parallel rim edges was declared by rounding; its plane is no
// supporting plane of M but the facet check's support sets (every vertex above the face's
// own) held the line, and mdd() said Separated at parameter -1.000456 (1.04 off M, the
// witnesses 0.2 off parameter * s). Faces whose own vertices do not support their
// normal are now refused by the facet check and by the chord of M.
TEST(MddHostile, CoincidingSheetsAreMetWhereTheyCoincide) {
  const std::vector<V> pts = {V(-0x1.ffffffff4p-1, -0x1p+0, -0x1.000000003c8p+1),
                              V(-0x1.ffffffffffp+0, 0x1.0000000017p+0, 0x1.000000000dp+0),
                              V(-0x1.00000000008p+1, -0x1.00000000008p+1, -0x1.00000000008p+1),
                              V(-0x1.fffffffff8p-1, 0x1.fffffffffbp+0, 0x1.0000000001p+0)};
  mink::HullOptions<double> exact;
  exact.tolerance = 0;
  const auto P = ConvexPolyhedron<double>::fromPoints(pts, exact);
  const auto Q = ConvexPolyhedron<double>::fromPoints(pts);
  Pose<double> pp, pq;
  pp.translation = V(12, 2048, 1024);
  pq.translation = V(-2, -2, -2);
  const V s(-14, -2050, -1026);
  const auto r = mink::mdd(P, pp, Q, pq, s);
  ASSERT_EQ(r.status, MddStatus::Separated);
  EXPECT_NEAR(r.parameter, -1.0, 1e-12);
  EXPECT_LT((r.witnessP - r.witnessQ - r.parameter * s).norm(), 1e-10);
  EXPECT_FALSE(mink::intersects(P, pp, Q, pq));
}

// The scene of fuzz/regressions/iteration_limit_sliver_chord (see below).
struct SheetScene {
  ConvexPolyhedron<double> P = ConvexPolyhedron<double>::fromPoints(
      {V(-0x1p+1, -0x1p+1, 0x0p+0), V(-0x1.fffffffffep+0, -0x1.ffffffffffp+0, 0x1p+0),
       V(-0x1.00000000008p+1, -0x1.ffffffffcp+0, -0x1.ffffffff81p+0), V(-0x1.ffffffffffp+0, 0x0p+0, 0x1p+0),
       V(-0x1.fffffffffep+0, -0x1.fffffffffdp+0, -0x1.fffffffffcp-1)});
  Pose<double> pp = translated(V(-2, 0, -2)), pq = translated(V(-1, 1, -2));
  V s = V(1, 1, 0);
  static Pose<double> translated(const V& t) {
    Pose<double> p;
    p.translation = t;
    return p;
  }
};

// Regression (fuzzer, fuzz/regressions/iteration_limit_sliver_chord; _integer_boxes is the
// same bug with 39 near-integer points and is replayed by the fuzz run): P is five points
// within 1e-12 of the plane x = -2, so M = P ⊕ −P (+ the offset of the poses) is a sheet
// 2e-12 thick, symmetric about (-1, -1, 0), and the line t (1, 1, 0) crosses it there, at
// t = -1 within 1e-11. Several faces of M on the sheet's side have the same ray
// parameter up to rounding; the least computed one was a neighbour of the facet the line
// crosses, its facet check failed, and mdd() answered IterationLimit after the
// exhaustive fallback. The fallback now tries every face tied within rounding.
TEST(MddHostile, SheetThinAsRoundingIsCrossed) {
  const SheetScene sc;
  const auto& P = sc.P;
  const auto& pp = sc.pp;
  const auto& pq = sc.pq;
  const V& s = sc.s;
  mink::MddCache<double> cache;
  for (int reps = 0; reps < 2; ++reps) {  // cold, then warm from the cache
    const auto r = mink::mdd(P, pp, P, pq, s, cache);
    ASSERT_EQ(r.status, MddStatus::Separated) << "usedFallback " << r.usedFallback;
    EXPECT_NEAR(r.parameter, -1.0, 1e-11);
    EXPECT_LT((r.witnessP - r.witnessQ - r.parameter * s).norm(), 1e-12);
    // Both witnesses are near the sheet's centre: P's copy of it at (-2 + x, ...) etc.
    EXPECT_NEAR(r.witnessP.x(), -4.0, 1e-11);
    EXPECT_NEAR(r.witnessQ.x(), -3.0, 1e-11);
  }
}

// The fallbacks that visit every face of M (exhaustive check, chord) are quadratic in the
// shapes' sizes; above MddOptions::maxExhaustivePairs a query that needs them reports
// IterationLimit rather than running for minutes (two 100k-vertex shapes: 9e10 pairs).
// A sheet like the one above (five points within 1e-12 of x = -2, found by a random
// search; the one above no longer needs the fallback since the exit portal's corners
// name its EE face) needs it; with the cap below its 9 x 9 edge pairs it stops.
TEST(MddHostile, FallbackOverTooManyEdgePairsGivesIterationLimit) {
  const auto P = ConvexPolyhedron<double>::fromPoints(
      {V(-0x1.00000000002c4p+1, 0x1.4772f15935aap-2, 0x1.c9e21ff1edb7ep+0),
       V(-0x1.0000000000373p+1, 0x1.de2ed1f35444p-1, -0x1.a0b08be8f81f2p-1),
       V(-0x1.ffffffffff3bep+0, 0x1.254cdc407efep-4, 0x1.c2a21a43ecc92p+0),
       V(-0x1.000000000002p+1, -0x1.1c1425c65b5bp+0, -0x1.5d80bdc5ed51p-3),
       V(-0x1.000000000037ep+1, -0x1.b0f9c46eade6ep+0, 0x1.3780c02780486p+0)});
  const Pose<double> pp = SheetScene::translated(V(-2, 0, -2));
  const Pose<double> pq = SheetScene::translated(V(-0x1p+0, 0x1.f30868b2fcdb9p-1, -0x1.0bf15b0127068p+1));
  const V s(0x1p+0, 0x1.494d97ca111p+0, 0x1.48203d12c2446p-5);
  const auto r = mink::mdd(P, pp, P, pq, s);
  ASSERT_TRUE(r.usedFallback);
  EXPECT_EQ(r.status, MddStatus::Separated);
  const long long pairs = static_cast<long long>(P.numEdges()) * P.numEdges();
  mink::MddOptions<double> opt;
  opt.maxExhaustivePairs = pairs;  // at the cap: allowed
  EXPECT_EQ(mink::mdd(P, pp, P, pq, s, opt).status, MddStatus::Separated);
  opt.maxExhaustivePairs = pairs - 1;
  const auto c = mink::mdd(P, pp, P, pq, s, opt);
  EXPECT_EQ(c.status, MddStatus::IterationLimit);
  EXPECT_TRUE(c.usedFallback);
}

// Regression (fuzzer, fuzz/regressions/iteration_limit_grazing_centre_off_line): the line
// of s grazes M (the fuzzer's slab clipping of the line against P ⊕ −Q over all
// separating axes gives a chord of length ~1e-8 at translation -0.19959, parameter
// -0.11523), and the poses are 5e-10 off orthonormal. The centre of duality, a
// combination of support points of a nearly degenerate portal, came out 1e-7 off the
// line; no face passed the facet check from it, and mdd() said IterationLimit. The last
// resort is now the chord itself: the line clipped against every face plane of M.
TEST(MddHostile, GrazingLineWithAnInaccurateCentreIsAnswered) {
  const auto P = ConvexPolyhedron<double>::fromPoints({V(0, 0, 0), V(1, 0, 0), V(0, 1, 2), V(2, 2, 2)});
  const auto Q = ConvexPolyhedron<double>::fromPoints(
      {V(49, 49, 49), V(49, 2, 8), V(3, 3, 2), V(2, -35, -35), V(-35, -35, -35)});
  Pose<double> pp, pq;
  pp.rotation << 0.72527472527472536, -0.32967032967032961, 0.60439560439560436, 0.60439560439560436,
      0.72527472527472536, -0.32967032967032961, -0.32967032967032961, 0.60439560486126565, 0.72527472527472536;
  pp.translation = V(-1.0000000000318323, -1.0000000000318323, -1.0000000000854925);
  pq.rotation << 0, 0, 1, 1, 0, 0, 0, 1.0000000004656613, 0;
  pq.translation = V(-1.0000000000318323, -1.0000000000318323, -1.0000000000318323);
  const V s(-1.0000000000318323, -1.0000000000318323, -1.0000000000318323);
  const auto r = mink::mdd(P, pp, Q, pq, s);
  ASSERT_NE(r.status, MddStatus::IterationLimit);
  ASSERT_NE(r.status, MddStatus::NoContact);
  // At this grazing angle the place along the line is ill-conditioned (the fuzzer's
  // check is the distance to M's boundary, 6e-7 here); the witnesses must keep their
  // contract within that.
  EXPECT_NEAR(r.parameter, -0.11523, 1e-4);
  EXPECT_LT((r.witnessP - r.witnessQ - r.parameter * s).norm(), 6e-7);
}

// Regression: found by the fuzzer (fuzz/regressions/witness_mismatch_tiny_direction) in an
// intermediate, uncommitted state of the MDD search changes (witnessP - witnessQ was off
// parameter * s by 1.125 along z); HEAD f5e3147 passes. A tiny direction (|s| ~ 2e-11) along
// (1,1,1), Q a tetrahedron grazing a box; the witnesses must satisfy their contract
// witnessP - witnessQ == parameter * s and lie on P and on Q (checked by hand: P is the
// box [-1,1]^3 turned 90° about x, Q's placement is a pure translation).
TEST(MddHostile, WitnessesKeepTheirContractForATinyDirection) {
  std::vector<V> b;
  for (int i = 0; i < 8; ++i) b.push_back(V(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1));
  const auto P = ConvexPolyhedron<double>::fromPoints(b);
  const std::vector<V> q = {V(0, 0, 2), V(2, 3, 2), V(0, 0, -42), V(0, 0, 2), V(2, 2, 0)};
  const auto Q = ConvexPolyhedron<double>::fromPoints(q);
  Pose<double> pp, pq;
  pp.rotation << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  pp.translation = V(-1.0000000000454747, -1.0000000000454747, -1.0000000000454747);
  pq.translation = V(-1.1185719017703377e-11, -1.1185719017703377e-11, -1.1185719017703377e-11);
  const V s = pq.translation;
  const auto r = mink::mdd(P, pp, Q, pq, s);
  ASSERT_EQ(r.status, MddStatus::Separated);
  EXPECT_LT((r.witnessP - r.witnessQ - r.parameter * s).norm(), 1e-9)
      << "witnessP " << r.witnessP.transpose() << ", witnessQ " << r.witnessQ.transpose() << ", parameter "
      << r.parameter;
  // witnessP in P: back in P's frame every coordinate is within [-1, 1].
  const V local = pp.rotation.transpose() * (r.witnessP - pp.translation);
  EXPECT_LE(local.cwiseAbs().maxCoeff(), 1 + 1e-9) << local.transpose();
  // witnessQ in Q: inside the tetrahedron of q[0], q[1], q[2], q[4] (barycentric >= 0).
  const V w = r.witnessQ - pq.translation;
  Eigen::Matrix3d A;
  A << q[1] - q[0], q[2] - q[0], q[4] - q[0];
  const V l = A.colPivHouseholderQr().solve(w - q[0]);
  EXPECT_GE(l.minCoeff(), -1e-9) << l.transpose();
  EXPECT_LE(l.sum(), 1 + 1e-9) << l.transpose();
}

// Regression (fuzzer, fuzz/regressions/intersects_false_for_overlapping_copies): Q is P shifted
// by (-2, -2, -2), P a tetrahedron with coordinates up to 3.2e16 (beyond 2^53: doubles are
// 4 apart there). A shift of 3.5 is far below P's inradius (computed here from the four
// vertices in long double), so P and Q overlap deeply, and mdd() says Penetrating, but
// intersects() answers false. With the shift 1e6 it answers true.
TEST(MddHostile, IntersectsSeesOverlapOfShiftedCopyWithLargeCoordinates) {
  const std::vector<V> p = {V(-1099511627776.0, 24205748485488640.0, 24018831508766720.0),
                            V(-936783906865152.0, 31569177856704512.0, 61572651155456.0),
                            V(11258999068426240.0, 6597069766656000.0, 15824171346952192.0),
                            V(1099511627776.0, 61572651155456.0, 281474976710656.0)};
  using VL = Eigen::Matrix<long double, 3, 1>;
  VL centroid = VL::Zero();
  for (const V& x : p) centroid += x.cast<long double>() / 4;
  long double inradius = std::numeric_limits<long double>::infinity();
  for (int f = 0; f < 4; ++f) {
    const VL a = p[(f + 1) % 4].cast<long double>(), b = p[(f + 2) % 4].cast<long double>(),
             c = p[(f + 3) % 4].cast<long double>();
    const VL n = (b - a).cross(c - a).normalized();
    inradius = std::min(inradius, std::fabs(n.dot(centroid - a)));  // centroid to face
  }
  ASSERT_GT(inradius, 1e12L);  // the shift (length 3.5) is nothing next to this
  const auto P = ConvexPolyhedron<double>::fromPoints(p);
  Pose<double> q;
  q.translation = V(-2, -2, -2);
  EXPECT_TRUE(mink::intersects(P, Pose<double>(), P, q));
  EXPECT_EQ(mink::mdd(P, Pose<double>(), P, q, V(-2, -2, -2)).status, MddStatus::Penetrating);
}

// A cache recognises its pair by the shapes' addresses. Assigning a new shape to the same
// object leaves hints (faces, vertices) that may be out of range for the new shape; they
// must be ignored or clamped, never used to index (ASan catches that in the sanitizer run).
// Hand-worked answer: boxes of half-size 1, Q at (0.3, 2.5, 0.1), s = -y: touch after 0.5.
TEST(MddHostile, StaleCacheAfterShapeReassignment) {
  std::mt19937 rng(5005u);
  std::normal_distribution<double> g;
  std::vector<V> sphere;
  for (int i = 0; i < 200; ++i) sphere.push_back(V(g(rng), g(rng), g(rng)).normalized());
  auto P = ConvexPolyhedron<double>::fromPoints(sphere);
  auto Q = ConvexPolyhedron<double>::fromPoints(sphere);
  mink::MddCache<double> cache;
  Pose<double> q;
  q.translation = V(0.3, 2.5, 0.1);
  for (int k = 0; k < 20; ++k)
    (void)mink::mdd(P, Pose<double>(), Q, q, V(std::sin(0.3 * k), -1, std::cos(0.7 * k)), cache);
  P = box(1);  // same objects, now 8 vertices and 6 faces
  Q = box(1);
  const auto r = mink::mdd(P, Pose<double>(), Q, q, V(0, -1, 0), cache);
  EXPECT_EQ(r.status, MddStatus::Separated);
  EXPECT_NEAR(r.translation, 0.5, 1e-12);
  EXPECT_FALSE(mink::intersects(P, Pose<double>(), Q, q, cache));
  q.translation = V(0.3, 1.5, 0.1);
  EXPECT_TRUE(mink::intersects(P, Pose<double>(), Q, q, cache));
}

// Regression (fuzzer, fuzz/regressions/intersects_false_deep_overlap): a speck Q (13 points
// within 1e-28 of its origin) placed at (-1, 1, 1), P (13 integer points, extent ~130) at
// (1, 1, 1): Q lies around (-2, 0, 0) in P's frame, deep inside P, and mdd() says
// Penetrating, but intersects() answers false. Scaling Q up to extent >= 1e-8 gives true.
// Reference: (-2, 0, 0) has barycentric coordinates >= 0.01 in a tetrahedron of P's
// input points (found by brute force here), so Q is inside P whatever mink computes.
TEST(MddHostile, IntersectsSeesTinyShapeInsideLargeOne) {
  const std::vector<V> p = {V(1, 42, 2),   V(1, 0, 1),    V(12, 50, -30),  V(20, -11, 25),   V(0, 45, -53),
                            V(20, -11, 42), V(-30, 1, 20), V(25, 1, 18),    V(1, 20, -11),    V(1, -58, 127),
                            V(127, 127, -54), V(-5, -58, -58)};
  const V x(-2, 0, 0);
  bool inside = false;
  const int n = static_cast<int>(p.size());
  for (int a = 0; a < n && !inside; ++a)
    for (int b = a + 1; b < n && !inside; ++b)
      for (int c = b + 1; c < n && !inside; ++c)
        for (int d = c + 1; d < n && !inside; ++d) {
          M3 A;
          A << p[b] - p[a], p[c] - p[a], p[d] - p[a];
          if (std::fabs(A.determinant()) < 1e-6) continue;
          const V l = A.inverse() * (x - p[a]);
          inside = l.minCoeff() >= 0.01 && 1 - l.sum() >= 0.01;
        }
  ASSERT_TRUE(inside);
  const std::vector<V> q = {
      V(-4.5418050320517551e-29, -4.5143797896436808e-29, -4.5143797896436808e-29),
      V(-4.5143797896436808e-29, -4.5143797896436808e-29, -4.5143797896436808e-29),
      V(4.7152928014421573e-29, 3.8475458056990443e-29, 4.5143797896436808e-29),
      V(2.5422275265911513e-30, -4.5143797896436808e-29, -4.5143797896436808e-29),
      V(-4.5143797896436808e-29, -4.5168449799724965e-29, -4.5143797896436808e-29),
      V(3.2164570815222349e-29, -4.5143797896436808e-29, -4.5143797896436808e-29),
      V(-4.5143797896436808e-29, -4.5753932502818685e-29, -5.1454685138204903e-29),
      V(-4.5553635788602412e-29, -4.5143797896436808e-29, -4.5143797896436808e-29),
      V(-4.5143797896436808e-29, -4.5143797896436808e-29, 1.3989955116028881e-30),
      V(2.4621088409046423e-30, -2.4451606573940346e-29, -2.8901275117452616e-29),
      V(9.5957533549149639e-30, 7.9194239313203138e-31, 1.9077491657122203e-29),
      V(7.8886090522101181e-31, 3.1616065967060864e-30, 7.9502388104305096e-31)};
  const auto P = ConvexPolyhedron<double>::fromPoints(p);
  const auto Q = ConvexPolyhedron<double>::fromPoints(q);
  Pose<double> pp, pq;
  pp.translation = V(1, 1, 1);
  pq.translation = V(-1, 1, 1);
  EXPECT_TRUE(mink::intersects(P, pp, Q, pq));
  EXPECT_EQ(mink::mdd(P, pp, Q, pq, V(1, 1, 1)).status, MddStatus::Penetrating);
}

// Regression (fuzzer seed box_touch_tolerance_inf): when a user touchTolerance >= |translation|
// turns a penetrating answer into Touching, the witnesses break their contract
// witnessP - witnessQ == parameter * s. Boxes of half-size 1, Q at (1, 1, 0), s = -x:
// penetrating, parameter -1 (Q moves +1 in x); with touchTolerance 2 mink reports
// witnessP (0.5, 0.5, 0), witnessQ (1, 0.5, 0): difference (-0.5, 0, 0), not (1, 0, 0).
TEST(MddHostile, TouchingWitnessesKeepTheirContract) {
  const auto B = box(1);
  Pose<double> q;
  q.translation = V(1, 1, 0);
  const V s(-1, 0, 0);
  for (double tol : {-1.0, 0.5, 2.0, kInf}) {
    SCOPED_TRACE("touchTolerance " + std::to_string(tol));
    mink::MddOptions<double> o;
    o.touchTolerance = tol;
    const auto r = mink::mdd(B, Pose<double>(), B, q, s, o);
    EXPECT_EQ(r.status, tol >= 1 ? MddStatus::Touching : MddStatus::Penetrating);
    EXPECT_DOUBLE_EQ(r.parameter, -1.0);
    EXPECT_LT((r.witnessP - r.witnessQ - r.parameter * s).norm(), 1e-12)
        << "witnessP " << r.witnessP.transpose() << ", witnessQ " << r.witnessQ.transpose();
  }
}

}  // namespace

namespace {

// A shape built with hull tolerance 0 may have an edge so sharp that its two unit face
// normals are opposite to rounding: a lens 2 wide and 1e-20 thick (interior dihedral
// 1e-20 rad). Its Gauss-map arcs then cannot say which way the edge turns (the fuzzer's
// fuzz/regressions/sharp_edge_normals_opposite_rejected: a sliver 5e25 wide and 1e-103
// thick lost its EE faces and mdd() answered 3e24 inside M). The hull is exact and kept;
// mdd() and intersects() reject it, naming the shape. Reference: the lens's faces, known
// by construction (two triangles back to back), and a lens 1e-6 thick that is accepted.
TEST(MddHostile, ShapesTooThinForTheirNormalsAreRejected) {
  mink::HullOptions<double> zero;
  zero.tolerance = 0.0;
  auto lens = [&](double h) {
    return ConvexPolyhedron<double>::fromPoints({V(-1, 0, 0), V(1, 0.5, 0), V(1, -0.5, 0), V(0.2, 0.1, h)}, zero);
  };
  const auto thin = lens(1e-20);
  ASSERT_EQ(thin.numFaces(), 4);
  EXPECT_FALSE(thin.edgesResolved());
  const auto ok = lens(1e-6);
  EXPECT_TRUE(ok.edgesResolved());
  EXPECT_TRUE(box(1).edgesResolved());
  Pose<double> far;
  far.translation = V(5, 0, 0);
  const auto B = box(1);
  expectRejected([&] { (void)mink::mdd(thin, Pose<double>(), B, far, V(1, 0, 0)); }, "mdd: P has an edge",
                 "mdd, thin P");
  expectRejected([&] { (void)mink::mdd(B, Pose<double>(), thin, far, V(1, 0, 0)); }, "mdd: Q has an edge",
                 "mdd, thin Q");
  expectRejected([&] { (void)mink::intersects(thin, Pose<double>(), B, far); }, "opposite to rounding",
                 "intersects, thin P");
  const auto r = mink::mdd(ok, Pose<double>(), B, far, V(1, 0, 0));
  EXPECT_EQ(r.status, MddStatus::Separated);
  EXPECT_NEAR(r.translation, -3.0, 1e-12);  // Q (x in [4, 6]) moves by -3 to touch x = 1
}

// checkMddInput / checkIntersectsInput and tryIntersects, what a build without exceptions
// uses: for every bad pose, direction and option above, the Error's message is the what()
// that mdd() / intersects() throw; for good input, no Error, and tryIntersects answers as
// intersects() does. (The status InvalidInput itself only exists without exceptions:
// tests/no_exceptions/ checks it.)
TEST(MddHostile, InputChecksGiveTheMessagesThatAreThrown) {
  const auto B = box(1);
  Pose<double> q;
  q.translation = V(3, 0, 0);
  auto thrown = [](auto&& call) {
    try {
      call();
    } catch (const mink::InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  int checked = 0;
  for (const BadPose& b : badPoses()) {
    SCOPED_TRACE(b.name);
    const mink::Error ep = mink::checkMddInput(B, b.pose, B, q, V(-1, 0, 0));
    ASSERT_TRUE(ep);
    EXPECT_EQ(ep.message(), thrown([&] { (void)mink::mdd(B, b.pose, B, q, V(-1, 0, 0)); }));
    const mink::Error eq = mink::checkMddInput(B, Pose<double>(), B, b.pose, V(-1, 0, 0));
    ASSERT_TRUE(eq);
    EXPECT_EQ(eq.message(), thrown([&] { (void)mink::mdd(B, Pose<double>(), B, b.pose, V(-1, 0, 0)); }));
    const mink::Result<bool> ri = mink::tryIntersects(B, Pose<double>(), B, b.pose);
    ASSERT_FALSE(ri.ok());
    EXPECT_EQ(ri.error().message(), thrown([&] { (void)mink::intersects(B, Pose<double>(), B, b.pose); }));
    EXPECT_EQ(mink::checkIntersectsInput(B, Pose<double>(), B, b.pose).message(), ri.error().message());
    checked += 3;
  }
  for (const V& s : {V(0, 0, 0), V(0, kNaN, 0), V(1, 0, -kInf)}) {
    const mink::Error e = mink::checkMddInput(B, Pose<double>(), B, q, s);
    ASSERT_TRUE(e);
    EXPECT_EQ(e.message(), thrown([&] { (void)mink::mdd(B, Pose<double>(), B, q, s); }));
    ++checked;
  }
  mink::MddOptions<double> nanTol;
  nanTol.touchTolerance = kNaN;
  EXPECT_EQ(mink::checkMddInput(B, Pose<double>(), B, q, V(-1, 0, 0), nanTol).message(),
            thrown([&] { (void)mink::mdd(B, Pose<double>(), B, q, V(-1, 0, 0), nanTol); }));
  const mink::Result<bool> rt = mink::tryIntersects(B, Pose<double>(), B, q, nanTol);
  ASSERT_FALSE(rt.ok());
  EXPECT_EQ(rt.error().message(), thrown([&] { (void)mink::intersects(B, Pose<double>(), B, q, nanTol); }));
  EXPECT_GE(checked, 3 * static_cast<int>(badPoses().size()) + 3);
  // Good input: no Error, and the same answers.
  EXPECT_FALSE(mink::checkMddInput(B, Pose<double>(), B, q, V(-1, 0, 0)));
  EXPECT_FALSE(mink::checkIntersectsInput(B, Pose<double>(), B, q));
  for (double x : {1.5, 2.0, 2.5}) {
    Pose<double> at;
    at.translation = V(x, 0.3, 0);
    const mink::Result<bool> r = mink::tryIntersects(B, Pose<double>(), B, at);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.value(), mink::intersects(B, Pose<double>(), B, at)) << x;
    EXPECT_EQ(r.value(), x <= 2.0) << x;
  }
}

// Regression (fuzzer, fuzz/regressions/witnesses_of_the_nearer_exit_after_a_symmetric_chord):
// P and Q the same six points (1e-6 across) at the same pose, so M is symmetric about the
// origin and the line's chord [-1.1e-6, 1.1e-6] has two exits at the same distance. The
// first exit answers (the tie goes to +s); its witnesses must be its own. A version that
// kept the witnesses recorded with the first exit but left the facet check holding the
// second exit's support sets corrected them against the wrong facet (7.4e-7 off the
// motion, two thirds of the chord).
TEST(MddHostile, TiedExitsKeepTheirOwnWitnesses) {
  const std::vector<V> pts = {V(-0x1.418p-20, -0x1.71ep-19, -0x1.5e4p-20), V(0x1.38p-20, 0x1.7p-21, 0x1.a7cp-20),
                              V(-0x1.08p-23, -0x1.bcp-24, 0x1.00ap-19),   V(0x1.f4p-22, 0x1.8ap-21, 0x1.4ep-23),
                              V(0x1p-22, 0x1.704p-20, -0x1.3bap-19),       V(0x1p-22, 0x1p-29, 0x0p+0)};
  mink::HullOptions<double> exact;
  exact.tolerance = 0;
  const auto P = ConvexPolyhedron<double>::fromPoints(pts, exact);
  Pose<double> pose;
  pose.translation = V(-2, -2, -2);
  const V s(-2, 1, -2);
  const auto r = mink::mdd(P, pose, P, pose, s);
  ASSERT_EQ(r.status, MddStatus::Penetrating);
  EXPECT_NEAR(std::abs(r.translation), 1.1001178821120588e-06, 1e-12);
  EXPECT_LT((r.witnessP - r.witnessQ - r.parameter * s).norm(), 1e-12);
}

}  // namespace
