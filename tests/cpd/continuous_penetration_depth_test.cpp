// tests/cpd/continuous_penetration_depth_test.cpp — mink/cpd/continuous_penetration_depth.hpp
// (ContinuousPenetrationDepth, penetrationDepth) against independent references:
//   - axis-aligned boxes: M is the box [loA − hiB − t, hiA − loB − t], so ∂M, the exact
//     Euclidean depth and the status are known in closed form;
//   - the MDD paper's convex shapes P1, P2 (and P1 / P1, P2 / P2) triangulated: q on ∂M by
//     mink's MDD (the exit of M along q's direction), the depth at least the Euclidean one
//     of the hull of all vertex differences (polyhedron/, checked against CGAL elsewhere);
//   - turned boxes and non-convex pairs (L, U, torus, cube with a hole, star, cup; two linked
//     tori): q is on ∂M
//     by FCL's BVH collide — B moved by q + δn does not meet A, B moved by q − δn does;
//     for the linked tori, the ball around o below the Euclidean depth inside M, sampled
//     by FCL (on small pairs, its equality with CGAL's exact ∂M: minkowski_boundary_test.cpp);
//   - Definition 1 where the status is Penetrating: |n × q| <= 1e-9 |q|, n along q;
//   - coherence: along a motion across the medial axis of M the CPD direction turns by
//     a few degrees per frame while the Euclidean one jumps by 90;
//   - touching and apart is Separated, one box inside the other Penetrating; scales 2^-600
//     .. 2^280 exactly and 1e-3, 1e3 to 1e-9; bad poses and options are InvalidInput; float.
#include "mink/cpd/continuous_penetration_depth.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "mink/mdd/mdd.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"
#include "support/expect_rejected.hpp"
#include "support/fcl_mesh.hpp"
#include "support/mesh_shapes.hpp"
#include "support/paper_shapes.hpp"

namespace {

using V = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
using Mesh = mink::TriangleMesh<double>;
using Pose = mink::Pose<double>;
using mink::CpdStatus;

#ifdef MINK_SANITIZE_BUILD
constexpr int kPlacements = 3;
#else
constexpr int kPlacements = 12;
#endif

Mesh mesh(const mink_test::MeshShape& s) { return Mesh::fromMesh(s.verticesAs<double>(), s.triangles); }

Pose pose(const M3& R, const V& t) {
  Pose p;
  p.rotation = R;
  p.translation = t;
  return p;
}

M3 rotation(double angle, const V& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

M3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

/// Definition 1 and the conventions of CpdResult, for a Penetrating CPD answer.
void expectPhongCondition(const mink::CpdResult<double>& r) {
  EXPECT_NEAR(r.direction.norm(), 1, 1e-12);
  EXPECT_NEAR((r.point - r.depth * r.direction).norm(), 0, 1e-12 * r.depth);
  EXPECT_NEAR(r.normal.norm(), 1, 1e-12);
  EXPECT_LE(r.normal.cross(r.point).norm(), 1e-9 * r.depth);
  EXPECT_GT(r.normal.dot(r.direction), 0);
}

TEST(ContinuousPenetrationDepth, StatusNames) {
  static_assert(mink::toString(mink::CpdStatus::Approximate)[0] == 'A', "usable in constant expressions");
  EXPECT_STREQ(mink::toString(mink::CpdStatus::Separated), "Separated");
  EXPECT_STREQ(mink::toString(mink::CpdStatus::Penetrating), "Penetrating");
  EXPECT_STREQ(mink::toString(mink::CpdStatus::Approximate), "Approximate");
  EXPECT_STREQ(mink::toString(mink::CpdStatus::InvalidInput), "InvalidInput");
  EXPECT_STREQ(mink::toString(static_cast<mink::CpdStatus>(7)), "?");
}

TEST(ContinuousPenetrationDepth, AxisAlignedBoxesAgainstTheClosedForm) {
  const V loA(-1, -0.75, -0.5), hiA(1, 0.75, 0.5), loB(-0.4, -0.3, -0.6), hiB(0.4, 0.3, 0.6);
  const Mesh A = mesh(mink_test::boxShape(loA, hiA)), B = mesh(mink_test::boxShape(loB, hiB));
  mink::ContinuousPenetrationDepth<double> cpd(A, B);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const Pose I = pose(M3::Identity(), V::Zero());
  int penetrating = 0;
  for (int i = 0; i < 4 * kPlacements; ++i) {
    const V t(1.3 * u(rng), 1.0 * u(rng), 1.0 * u(rng));
    SCOPED_TRACE("placement " + std::to_string(i) + " t = (" + std::to_string(t.x()) + ", " + std::to_string(t.y()) +
                 ", " + std::to_string(t.z()) + ")");
    const V lo = loA - hiB - t, hi = hiA - loB - t;  // M
    const bool inside = (lo.array() < 0).all() && (hi.array() > 0).all();
    const double exactPd = std::min(-lo.maxCoeff(), hi.minCoeff());
    cpd.reset();
    const mink::CpdResult<double> r = cpd.query(I, pose(M3::Identity(), t));
    const mink::CpdResult<double> e = mink::penetrationDepth(A, I, B, pose(M3::Identity(), t));
    if (!inside) {
      EXPECT_EQ(r.status, CpdStatus::Separated);
      EXPECT_EQ(e.status, CpdStatus::Separated);
      EXPECT_EQ(r.depth, 0);
      continue;
    }
    ++penetrating;
    ASSERT_EQ(r.status, CpdStatus::Penetrating);
    ASSERT_EQ(e.status, CpdStatus::Penetrating);
    for (const auto* x : {&r, &e}) {
      // q on ∂M: within the box and on one of its faces.
      const V q = x->point;
      EXPECT_TRUE(((q - lo).array() >= -1e-12).all() && ((hi - q).array() >= -1e-12).all());
      EXPECT_LE(std::min((q - lo).cwiseAbs().minCoeff(), (hi - q).cwiseAbs().minCoeff()), 1e-12);
      EXPECT_GE(x->depth, exactPd - 1e-12);
    }
    // The Euclidean search starts from the exits along ±x, ±y, ±z: the nearest face.
    EXPECT_NEAR(e.depth, exactPd, 1e-12);
    expectPhongCondition(r);
    // A fresh CPD query stays near the Euclidean depth on a box.
    EXPECT_LE(r.depth, 1.5 * exactPd);
  }
  EXPECT_GE(penetrating, kPlacements);
}

/// A convex hull as a closed triangle mesh (faces fanned).
Mesh hullMesh(const mink::ConvexPolyhedron<double>& P) {
  std::vector<std::array<int, 3>> tris;
  for (int f = 0; f < P.numFaces(); ++f) {
    std::vector<int> v;
    for (int x : P.faceVertices(f)) v.push_back(x);
    for (std::size_t k = 1; k + 1 < v.size(); ++k) tris.push_back({v[0], v[k], v[k + 1]});
  }
  return Mesh::fromMesh(P.vertices(), tris);
}

TEST(ContinuousPenetrationDepth, PaperShapesOnTheExitOfMAndAboveTheEuclideanDepth) {
  using mink_test::PaperShape;
  const std::pair<PaperShape, PaperShape> pairs[] = {
      {PaperShape::P1, PaperShape::P2}, {PaperShape::P1, PaperShape::P1}, {PaperShape::P2, PaperShape::P2}};
  std::mt19937 rng(21);
  for (const auto& [pi, qi] : pairs) {
    SCOPED_TRACE(std::string(mink_test::paperShapeName(pi)) + " / " + mink_test::paperShapeName(qi));
    const auto P = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(pi, rng));
    const auto Q = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(qi, rng));
    const Mesh A = hullMesh(P), B = hullMesh(Q);
    mink::ContinuousPenetrationDepth<double> cpd(A, B);
    double worstRatio = 0;
    for (int i = 0; i < kPlacements; ++i) {
      SCOPED_TRACE("placement " + std::to_string(i));
      const Pose pa = pose(mink_test::randomRotation(rng), V(0.5, -0.25, 0.125));
      std::uniform_real_distribution<double> u(-2, 2);
      const Pose pb = pose(mink_test::randomRotation(rng), pa.translation + V(u(rng), u(rng), u(rng)));
      // The exact Euclidean depth: the hull of all vertex differences is M; o inside it,
      // the depth is the least distance to a facet plane.
      std::vector<V> diff;
      for (const V& a : P.vertices())
        for (const V& b : Q.vertices()) diff.push_back(pa.apply(a) - pb.apply(b));
      const auto Mh = mink::ConvexPolyhedron<double>::fromPoints(diff);
      double pd = std::numeric_limits<double>::infinity();
      bool inside = true;
      for (int f = 0; f < Mh.numFaces(); ++f) {
        const double d = Mh.faceOffset(f) / Mh.faceNormal(f).norm();  // plane n·x = offset
        inside = inside && d > 0;
        pd = std::min(pd, d);
      }
      cpd.reset();
      const mink::CpdResult<double> r = cpd.query(pa, pb);
      const mink::CpdResult<double> e = mink::penetrationDepth(A, pa, B, pb);
      if (!inside) {
        EXPECT_EQ(r.status, CpdStatus::Separated);
        continue;
      }
      ASSERT_NE(r.status, CpdStatus::Separated);
      ASSERT_EQ(e.status, CpdStatus::Penetrating);
      const double scale = 2 * mink_test::kPaperShapeRadius;
      for (const auto* x : {&r, &e}) {
        // The exit of M along q's direction d, by MDD: Q moved on by D d (D beyond M's
        // extent) is apart from P, and its M is M − D d, which the line t d meets for t in
        // [lo − D, exit − D]: MDD's answer is the nearer end, exit − D.
        const double D = 4 * scale;
        const Pose ahead = pose(pb.rotation, pb.translation + D * x->direction);
        const mink::MddResult<double> m = mink::mdd(P, pa, Q, ahead, x->direction);
        ASSERT_EQ(m.status, mink::MddStatus::Separated);
        const double exit = D + m.translation;
        EXPECT_NEAR(x->depth, exit, 1e-9 * scale) << "q is not where M ends along its direction";
        EXPECT_GE(x->depth, pd - 1e-9 * scale);
      }
      EXPECT_NEAR(e.depth, pd, 1e-9 * scale) << "the Euclidean depth is not the nearest point of ∂M";
      if (r.status == CpdStatus::Penetrating) expectPhongCondition(r);
      // A fresh query starts from the Euclidean depth's point; stated bound 1.5 (printed
      // below).
      EXPECT_LE(r.depth, 1.5 * pd);
      worstRatio = std::max(worstRatio, r.depth / pd);
    }
    std::printf("[cpd] %s / %s: fresh CPD depth at most %.3f x the Euclidean depth\n", mink_test::paperShapeName(pi),
                mink_test::paperShapeName(qi), worstRatio);
  }
}

/// q on ∂M by FCL: B moved by q − δn meets A, and moved by q + δn it does not (CPD: n is
/// the Phong normal, outward) or, for the Euclidean depth, by q + δd for one of the 26
/// directions d of a cube's corners, edges and faces or along n: a local nearest point of
/// ∂M can be the corner of a step (a concave crease of ∂M, where o's projections on the
/// two faces fall outside them), and there the direction to it points into M again.
void expectOnBoundaryByFcl(mink_test::FclPair& fcl, const Pose& pa, const Pose& pb, const mink::CpdResult<double>& r,
                           double delta, bool outwardNormal) {
  const M3 R = pa.rotation.transpose() * pb.rotation;
  const V t = pa.rotation.transpose() * (pb.translation - pa.translation);
  const V n = pa.rotation.transpose() * r.normal;
  const V q = pa.rotation.transpose() * r.point;
  EXPECT_TRUE(fcl.collide(R, t + q - delta * n)) << "B moved by q − δn does not meet A";
  if (outwardNormal) {
    EXPECT_FALSE(fcl.collide(R, t + q + delta * n)) << "B moved by q + δn still meets A";
    return;
  }
  bool free = !fcl.collide(R, t + q + delta * n);
  for (int i = -1; i <= 1 && !free; ++i)
    for (int j = -1; j <= 1 && !free; ++j)
      for (int k = -1; k <= 1 && !free; ++k)
        if (i || j || k) free = !fcl.collide(R, t + q + delta * V(i, j, k).normalized());
  EXPECT_TRUE(free) << "every translation within δ of q meets A: q is inside M";
}

struct Pair {
  std::string name;
  mink_test::MeshShape a, b;
  double spread;  // placements of B within this of A's centre
};

mink_test::MeshShape scaled(mink_test::MeshShape s, double f) {
  for (auto& v : s.vertices) v *= f;
  return s;
}

TEST(ContinuousPenetrationDepth, NonConvexPairsOnTheBoundaryByFcl) {
  const std::vector<Pair> pairs = {
      {"turned boxes", mink_test::boxShape(), mink_test::boxShape(V(-0.5, -0.3, -0.7), V(0.5, 0.3, 0.7)), 1.0},
      {"L-block / box", mink_test::lBlock(), mink_test::boxShape(V(-0.5, -0.25, -0.75), V(0.5, 0.25, 0.75)), 0.8},
      {"U-block / L-block", mink_test::uBlock(), mink_test::lBlock(), 0.8},
      {"torus / box", mink_test::torus(12, 8), mink_test::boxShape(V(-0.4, -0.3, -0.5), V(0.4, 0.3, 0.5)), 1.5},
      {"cube with hole / star", mink_test::cubeWithHole(), scaled(mink_test::starPrism(), 0.0625), 1.0},
      {"cup / box", mink_test::cup(), mink_test::boxShape(V(-0.3, -0.2, -0.4), V(0.3, 0.2, 0.4)), 1.0}};
  std::mt19937 rng(5);
  for (const Pair& p : pairs) {
    SCOPED_TRACE(p.name);
    const Mesh A = mesh(p.a), B = mesh(p.b);
    mink_test::FclPair fcl(A, B);
    mink::ContinuousPenetrationDepth<double> cpd(A, B);
    V ca = V::Zero(), cb = V::Zero();
    for (const V& v : A.vertices()) ca += v / A.numVertices();
    for (const V& v : B.vertices()) cb += v / B.numVertices();
    std::uniform_real_distribution<double> u(-p.spread, p.spread);
    int penetrating = 0, queries = 0;
    for (int i = 0; i < kPlacements; ++i) {
      const M3 RA = randomRotation(rng), RB = randomRotation(rng);
      const V offset(u(rng), u(rng), u(rng));
      // B's centre at A's centre + offset (world frame).
      const Pose pa = pose(RA, V(0.3, -0.2, 0.1));
      const Pose pb = pose(RB, pa.apply(ca) + offset - RB * cb);
      SCOPED_TRACE("placement " + std::to_string(i));
      cpd.reset();
      const mink::CpdResult<double> r = cpd.query(pa, pb);
      const mink::CpdResult<double> e = mink::penetrationDepth(A, pa, B, pb);
      EXPECT_EQ(r.status == CpdStatus::Separated, e.status == CpdStatus::Separated);
      if (r.status == CpdStatus::Separated) {
        // FCL sees no containment: it can only confirm that the boundaries do not cross.
        EXPECT_FALSE(fcl.collide(pa.rotation.transpose() * pb.rotation,
                                 pa.rotation.transpose() * (pb.translation - pa.translation)));
        continue;
      }
      ++queries;
      const double delta = 1e-7;
      expectOnBoundaryByFcl(fcl, pa, pb, r, delta, true);
      expectOnBoundaryByFcl(fcl, pa, pb, e, delta, false);
      if (r.status == CpdStatus::Penetrating) {
        ++penetrating;
        expectPhongCondition(r);
      }
      EXPECT_EQ(e.status, CpdStatus::Penetrating);
    }
    std::printf("%-22s %d of %d overlapping placements Penetrating (CPD)\n", p.name.c_str(), penetrating, queries);
    EXPECT_GE(2 * penetrating, queries);
  }
}

TEST(ContinuousPenetrationDepth, InterlockedToriOnTheBoundaryByFcl) {
  // Two linked tori (B's ring through A's hole, in the plane y = 0), B shifted by up to
  // 0.6 so that the tubes cut each other or just miss.
  const Mesh A = mesh(mink_test::torus(12, 8)), B = mesh(mink_test::torus(10, 6, 1.5, 0.5));
  mink_test::FclPair fcl(A, B);
  mink::ContinuousPenetrationDepth<double> cpd(A, B);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  const Pose I = pose(M3::Identity(), V::Zero());
  int overlapping = 0;
  for (int i = 0; i < (kPlacements + 3) / 4; ++i) {
    SCOPED_TRACE("placement " + std::to_string(i));
    const Pose pb = pose(rotation(M_PI / 2, V(1, 0, 0)) * rotation(0.1 * u(rng), V(0, 0, 1)), V(2 + u(rng), u(rng), u(rng)));
    cpd.reset();
    const mink::CpdResult<double> r = cpd.query(I, pb);
    if (r.status == CpdStatus::Separated) {
      EXPECT_FALSE(fcl.collide(pb.rotation, pb.translation));
      continue;
    }
    ++overlapping;
    expectOnBoundaryByFcl(fcl, I, pb, r, 1e-7, true);
    if (r.status == CpdStatus::Penetrating) expectPhongCondition(r);
    // The Euclidean depth is global: the ball around o of radius below it lies in M.
    // Sampled with FCL on 64 rays at 1/4, 1/2, 3/4 and 0.999 of the depth: B moved there
    // still crosses A (neither torus fits inside the other, so FCL's "no crossing" would
    // mean apart, a point outside M nearer than the depth).
    const mink::CpdResult<double> e = mink::penetrationDepth(A, I, B, pb);
    ASSERT_EQ(e.status, CpdStatus::Penetrating);
    expectOnBoundaryByFcl(fcl, I, pb, e, 1e-7, false);
    EXPECT_GE(r.depth, e.depth - 1e-9);
    const int rays = 64;
    int free = 0;
    for (int k = 0; k < rays; ++k) {
      // Fibonacci points on the sphere.
      const double z = 1 - (2 * k + 1.0) / rays, rho = std::sqrt(1 - z * z), phi = k * 2.399963229728653;
      const V d(rho * std::cos(phi), rho * std::sin(phi), z);
      for (double f : {0.25, 0.5, 0.75, 0.999})
        if (!fcl.collide(pb.rotation, pb.translation + f * e.depth * d)) ++free;
    }
    EXPECT_EQ(free, 0) << "translations shorter than the Euclidean depth that clear the tori";
    std::printf("[cpd] linked tori, placement %d: CPD %s depth %.4f (%d balls, %lld triangles); Euclidean depth %.4f\n", i,
                r.status == CpdStatus::Penetrating ? "Penetrating" : "Approximate", r.depth, r.iterations,
                r.trianglesBuilt, e.depth);
  }
  EXPECT_GE(overlapping, 1);
}

TEST(ContinuousPenetrationDepth, CoherentAcrossTheMedialAxisWhereEuclideanJumps) {
  const Mesh A = mesh(mink_test::boxShape()), B = mesh(mink_test::boxShape(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5)));
  mink::ContinuousPenetrationDepth<double> cpd(A, B);
  const Pose I = pose(M3::Identity(), V::Zero());
  // B slides along x + y = 1.2, across the plane x = y: the medial axis of M between its
  // faces x = 1.5 and y = 1.5.
  const int frames = 41;
  double cpdTurn = 0, pdTurn = 0;
  V lastC = V::Zero(), lastE = V::Zero();
  for (int i = 0; i < frames; ++i) {
    const double s = -0.2 + 0.4 * i / (frames - 1);
    const Pose pb = pose(M3::Identity(), V(0.6 + s, 0.6 - s, 0.05));
    const mink::CpdResult<double> r = cpd.query(I, pb);
    const mink::CpdResult<double> e = mink::penetrationDepth(A, I, B, pb);
    ASSERT_EQ(r.status, CpdStatus::Penetrating) << "frame " << i;
    ASSERT_EQ(e.status, CpdStatus::Penetrating) << "frame " << i;
    EXPECT_EQ(r.fromPreviousFrame, i > 0);
    expectPhongCondition(r);
    if (i > 0) {
      cpdTurn = std::max(cpdTurn, std::acos(std::clamp(r.direction.dot(lastC), -1.0, 1.0)));
      pdTurn = std::max(pdTurn, std::acos(std::clamp(e.direction.dot(lastE), -1.0, 1.0)));
    }
    lastC = r.direction;
    lastE = e.direction;
  }
  const double deg = 180 / M_PI;
  EXPECT_LT(cpdTurn * deg, 10) << "largest turn of the CPD direction between frames";
  EXPECT_GT(pdTurn * deg, 80) << "the Euclidean direction jumps from one face of M to the next";
  cpd.reset();
  EXPECT_FALSE(cpd.query(I, pose(M3::Identity(), V(0.6, 0.6, 0.05))).fromPreviousFrame);
}

TEST(ContinuousPenetrationDepth, ApproximateWithinTheCapsIsAPointOfTheBoundary) {
  // One ball only, started from the last frame's q = (0, 1.3, 0) on the face y = 1.3 of M
  // after B has moved to x = 1.2: the face's normals turn towards the edge x = 0.3 inside
  // that ball and no triangle has a projection, so the answer is the best barycentre
  // found — still on ∂M.
  const Mesh A = mesh(mink_test::boxShape()), B = mesh(mink_test::boxShape(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5)));
  mink::CpdOptions<double> o;
  o.maxIterations = 1;
  mink::ContinuousPenetrationDepth<double> cpd(A, B, o);
  const Pose I = pose(M3::Identity(), V::Zero());
  const mink::CpdResult<double> first = cpd.query(I, pose(M3::Identity(), V(0.0, 0.2, 0.1)));
  ASSERT_EQ(first.status, CpdStatus::Penetrating);
  ASSERT_NEAR((first.point - V(0, 1.3, 0)).norm(), 0, 1e-12);
  const V t(1.2, 0.2, 0.1);
  const mink::CpdResult<double> r = cpd.query(I, pose(M3::Identity(), t));
  EXPECT_TRUE(r.fromPreviousFrame);
  ASSERT_EQ(r.status, CpdStatus::Approximate);
  EXPECT_EQ(r.iterations, 1);
  const V lo = V(-1.5, -1.5, -1.5) - t, hi = V(1.5, 1.5, 1.5) - t;  // M
  const V q = r.point;
  EXPECT_TRUE(((q - lo).array() >= -1e-12).all() && ((hi - q).array() >= -1e-12).all());
  EXPECT_LE(std::min((q - lo).cwiseAbs().minCoeff(), (hi - q).cwiseAbs().minCoeff()), 1e-12);
  EXPECT_GE(r.depth, 0.3 - 1e-12);
  EXPECT_NEAR(r.direction.norm(), 1, 1e-12);
}

TEST(ContinuousPenetrationDepth, ConeSlidingInAnArmOfTheAxesNeedsOneBallPerFrame) {
  // The cone/axes motion of the paper's section 7 (benchmarks/cpd_paper_scenes.hpp): the
  // cone, apex down, pressed 0.3 into an arm and sliding along it while turning. Its
  // Phong projection sits on the crease between a flat FV facet of M and a sloped EE
  // facet. Where a piece of the flat facet had a corner inside a side of the sloped one
  // (a T-junction: the flat facet cut by a plane that stops at the crease), the vertex
  // normals jumped along the crease, the projection fell between the two triangles'
  // interpolations, and frames took 2 - 4 balls, 6 of 19 ending Approximate. The patch's
  // triangles now meet edge to edge there: one ball per frame, every frame Penetrating.
  const Mesh A = mesh(mink_test::axes(3)), B = mesh(mink_test::cone(500, 1.0, 2.0));
  const M3 R0 = rotation(M_PI, V(1, 0, 0));
  const V approach(0, 0, -1), aim(2, 0, 1.5);
  const double D = 4 * (A.extent() + B.extent()) + 4;
  const V start = aim - D * approach;
  mink::MeshOverlap<double> ov(A, B, R0, start);
  double lo = 0, hi = D;
  for (int i = 0; i < 60; ++i) (ov.overlaps(V(0.5 * (lo + hi) * approach)) ? hi : lo) = 0.5 * (lo + hi);
  const V t0 = start + (hi + 0.3) * approach;
  mink::ContinuousPenetrationDepth<double> cpd(A, B);
  const Pose I = pose(M3::Identity(), V::Zero());
  for (int f = 0; f < 20; ++f) {
    const mink::CpdResult<double> r = cpd.query(I, pose(rotation(0.01 * f, V(0.2, 0.3, 1)) * R0, t0 + f * V(-0.03, 0, 0)));
    ASSERT_EQ(r.status, CpdStatus::Penetrating) << "frame " << f;
    expectPhongCondition(r);
    if (f > 0) {
      EXPECT_EQ(r.iterations, 1) << "frame " << f;
    }
  }
}

TEST(ContinuousPenetrationDepth, SubnormalDepthHasAUnitDirection) {
  // fuzz/regressions_mesh/cpd_subnormal_depth_direction_not_unit_octahedron: an octahedron
  // whose two apexes are 7.6e-319 apart, against itself turned: a depth of 8.3e-319, whose
  // point has 17 significant bits; point / depth was 1e-5 off unit length. The direction
  // is now normalised from the point scaled near one.
  const std::vector<V> v = {V(0x0.0000000025757p-1022, 0, 0), V(0, 0, 0),       V(-256, 128, 0),
                            V(-256, -128, 0),                  V(-256, 0, 128), V(-256, 0, -128)};
  const std::vector<std::array<int, 3>> tri = {{0, 2, 4}, {0, 5, 2}, {0, 4, 3}, {0, 3, 5},
                                               {1, 4, 2}, {1, 2, 5}, {1, 3, 4}, {1, 5, 3}};
  const Mesh A = Mesh::fromMesh(v, tri);
  M3 R;
  R << 0.33333333333333348, -0.8717948717948717, -0.35897435897435892, 0.66666666666666663, 0.48717948717948723,
      -0.5641025641025641, 0.66666666666666663, -0.051282051282051266, 0.74358974358974361;
  const V t(-256, -256, -256);
  mink::ContinuousPenetrationDepth<double> cpd(A, A);
  for (const mink::CpdResult<double>& r : {cpd.query(pose(M3::Identity(), t), pose(R, t)),
                                           mink::penetrationDepth(A, pose(M3::Identity(), t), A, pose(R, t))}) {
    ASSERT_NE(r.status, CpdStatus::Separated);
    EXPECT_LT(r.depth, 1e-300);
    EXPECT_NEAR(r.direction.norm(), 1, 1e-15);
    EXPECT_NEAR(r.normal.norm(), 1, 1e-15);
  }
}

TEST(ContinuousPenetrationDepth, TouchingAndApartAreSeparated) {
  const Mesh A = mesh(mink_test::boxShape()), B = mesh(mink_test::boxShape(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5)));
  mink::ContinuousPenetrationDepth<double> cpd(A, B);
  const Pose I = pose(M3::Identity(), V::Zero());
  for (const V& t : {V(1.5, 0.2, 0.1), V(1.5, 1.5, 0.0), V(1.5, 1.5, 1.5), V(1.6, 0.0, 0.0), V(0.0, -3.0, 0.0)}) {
    SCOPED_TRACE("t = (" + std::to_string(t.x()) + ", " + std::to_string(t.y()) + ", " + std::to_string(t.z()) + ")");
    const mink::CpdResult<double> r = cpd.query(I, pose(M3::Identity(), t));
    EXPECT_EQ(r.status, CpdStatus::Separated);
    EXPECT_EQ(r.depth, 0);
    EXPECT_EQ(mink::penetrationDepth(A, I, B, pose(M3::Identity(), t)).status, CpdStatus::Separated);
  }
  // One shape wholly inside the other overlaps.
  const mink::CpdResult<double> in = cpd.query(I, pose(M3::Identity(), V(0.1, 0.0, 0.0)));
  EXPECT_EQ(in.status, CpdStatus::Penetrating);
  EXPECT_NEAR(in.depth, 1.4, 1e-12);  // M = [-1.5, 1.5]^3 − (0.1, 0, 0): its face x = 1.4
}

TEST(ContinuousPenetrationDepth, DecimalScalesScaleTheAnswer) {
  // 1e-3 and 1e3 of the unit scene (not powers of two: every coordinate rounds anew), to
  // 1e-9 relative; the status the same.
  const mink_test::MeshShape a = mink_test::lBlock(), b = mink_test::boxShape(V(-0.5, -0.25, -0.75), V(0.5, 0.25, 0.75));
  const M3 RA = rotation(0.3, V(1, 2, 3)), RB = rotation(-0.7, V(0.2, -1, 0.5));
  const V tA(0.25, -0.5, 0.125), tB(1.375, 0.75, 0.5);
  auto run = [&](double f, mink::CpdResult<double>& r, mink::CpdResult<double>& e) {
    const Mesh A = mesh(scaled(a, f)), B = mesh(scaled(b, f));
    const Pose pa = pose(RA, f * tA), pb = pose(RB, f * tB);
    r = mink::ContinuousPenetrationDepth<double>(A, B).query(pa, pb);
    e = mink::penetrationDepth(A, pa, B, pb);
  };
  mink::CpdResult<double> unitCpd, unitPd;
  run(1, unitCpd, unitPd);
  ASSERT_EQ(unitCpd.status, CpdStatus::Penetrating);
  ASSERT_EQ(unitPd.status, CpdStatus::Penetrating);
  for (double f : {1e-3, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(f));
    mink::CpdResult<double> r, e;
    run(f, r, e);
    EXPECT_EQ(r.status, unitCpd.status);
    EXPECT_EQ(e.status, unitPd.status);
    EXPECT_NEAR(r.depth / f, unitCpd.depth, 1e-9 * unitCpd.depth);
    EXPECT_NEAR(e.depth / f, unitPd.depth, 1e-9 * unitPd.depth);
    EXPECT_NEAR((r.direction - unitCpd.direction).norm(), 0, 1e-9);
    EXPECT_LE(r.normal.cross(r.point).norm(), 1e-9 * r.depth);
  }
}

TEST(ContinuousPenetrationDepth, ScalingByAPowerOfTwoScalesTheAnswer) {
  // Every step scales with the scene: bisection on exact predicates, the local sum's own
  // power-of-two unit, Phong projection and the nearest point in the patch's unit frame.
  const mink_test::MeshShape a = mink_test::lBlock(), b = mink_test::boxShape(V(-0.5, -0.25, -0.75), V(0.5, 0.25, 0.75));
  const M3 RA = rotation(0.3, V(1, 2, 3)), RB = rotation(-0.7, V(0.2, -1, 0.5));
  const V tA(0.25, -0.5, 0.125), tB(1.375, 0.75, 0.5);
  mink::CpdResult<double> unitCpd, unitPd;
  for (int k : {0, -600, -60, 60, 280}) {
    SCOPED_TRACE("scale 2^" + std::to_string(k));
    const double f = std::ldexp(1.0, k);
    const Mesh A = mesh(scaled(a, f)), B = mesh(scaled(b, f));
    const Pose pa = pose(RA, f * tA), pb = pose(RB, f * tB);
    mink::ContinuousPenetrationDepth<double> cpd(A, B);
    const mink::CpdResult<double> r = cpd.query(pa, pb);
    const mink::CpdResult<double> e = mink::penetrationDepth(A, pa, B, pb);
    if (k == 0) {
      ASSERT_EQ(r.status, CpdStatus::Penetrating);
      ASSERT_EQ(e.status, CpdStatus::Penetrating);
      unitCpd = r;
      unitPd = e;
      continue;
    }
    EXPECT_EQ(r.status, unitCpd.status);
    EXPECT_EQ(e.status, unitPd.status);
    EXPECT_NEAR(r.depth / f, unitCpd.depth, 1e-12 * unitCpd.depth);
    EXPECT_NEAR(e.depth / f, unitPd.depth, 1e-12 * unitPd.depth);
    EXPECT_NEAR((r.direction - unitCpd.direction).norm(), 0, 1e-12);
    EXPECT_NEAR((r.normal - unitCpd.normal).norm(), 0, 1e-12);
    EXPECT_LE(r.normal.cross(r.point).norm(), 1e-9 * r.depth);
  }
}

TEST(ContinuousPenetrationDepth, BadPosesAndOptionsAreInvalidInput) {
  const Mesh A = mesh(mink_test::boxShape()), B = mesh(mink_test::lBlock());
  mink::ContinuousPenetrationDepth<double> cpd(A, B);
  const Pose I = pose(M3::Identity(), V::Zero());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  mink_test::expectRejected([&] { cpd.query(I, pose(M3::Identity(), V(nan, 0, 0))); }, "poseB", "NaN translation");
  mink_test::expectRejected([&] { cpd.query(pose(2 * M3::Identity(), V::Zero()), I); }, "poseA", "scaled rotation");
  M3 reflect = M3::Identity();
  reflect(2, 2) = -1;
  mink_test::expectRejected([&] { mink::penetrationDepth(A, I, B, pose(reflect, V::Zero())); }, "poseB", "reflection");
  mink::CpdOptions<double> o;
  o.alpha = 0;
  mink_test::expectRejected([&] { mink::ContinuousPenetrationDepth<double>(A, B, o); }, "alpha", "alpha 0");
  o = {};
  o.beta = 1;
  mink_test::expectRejected([&] { mink::ContinuousPenetrationDepth<double>(A, B, o); }, "beta", "beta 1");
  o = {};
  o.maxIterations = 0;
  mink_test::expectRejected([&] { mink::ContinuousPenetrationDepth<double>(A, B, o); }, "maxIterations", "no iteration");
  // checkCpdInput / checkCpdOptions (what builds without exceptions report, with the
  // status InvalidInput): the messages thrown.
  auto thrown = [](auto&& call) {
    try {
      call();
    } catch (const mink::InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("(nothing thrown)");
  };
  const Pose nanB = pose(M3::Identity(), V(nan, 0, 0));
  EXPECT_EQ(mink::checkCpdInput(I, nanB).message(), thrown([&] { cpd.query(I, nanB); }));
  EXPECT_EQ(mink::checkCpdInput(I, pose(reflect, V::Zero()), "penetrationDepth").message(),
            thrown([&] { mink::penetrationDepth(A, I, B, pose(reflect, V::Zero())); }));
  EXPECT_EQ(mink::checkCpdOptions(o).message(), thrown([&] { mink::ContinuousPenetrationDepth<double>(A, B, o); }));
  EXPECT_FALSE(mink::checkCpdInput(I, I));
  EXPECT_FALSE(mink::checkCpdOptions(mink::CpdOptions<double>{}));
  EXPECT_FALSE(cpd.error());
}

TEST(ContinuousPenetrationDepth, FloatAgreesWithDouble) {
  const mink_test::MeshShape a = mink_test::lBlock(), b = mink_test::boxShape(V(-0.5, -0.25, -0.75), V(0.5, 0.25, 0.75));
  const mink::TriangleMesh<float> Af = mink::TriangleMesh<float>::fromMesh(a.verticesAs<float>(), a.triangles);
  const mink::TriangleMesh<float> Bf = mink::TriangleMesh<float>::fromMesh(b.verticesAs<float>(), b.triangles);
  const Mesh A = mesh(a), B = mesh(b);
  mink::ContinuousPenetrationDepth<float> cf(Af, Bf);
  mink::ContinuousPenetrationDepth<double> cd(A, B);
  for (const V& t : {V(0.5, 0.5, 0.5), V(1.4, 0.4, 0.3), V(0.4, 1.5, 0.6)}) {
    mink::Pose<float> pf;
    pf.translation = t.cast<float>();
    const auto rf = cf.query(mink::Pose<float>(), pf);
    const auto rd = cd.query(Pose(), pose(M3::Identity(), t));
    ASSERT_EQ(rd.status, CpdStatus::Penetrating);
    EXPECT_EQ(static_cast<int>(rf.status), static_cast<int>(rd.status));
    EXPECT_NEAR(rf.depth, rd.depth, 1e-5);
  }
}

}  // namespace
