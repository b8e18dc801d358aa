// tests/cpd/local_minkowski_sum_test.cpp — mink/cpd/local_minkowski_sum.hpp against the
// whole boundary (cpd/minkowski_boundary.hpp, itself checked against CGAL's
// minkowski_sum_3 in minkowski_boundary_test.cpp) and against its own methods:
//   - the patch is the part of ∂M in the ball: every triangle on the whole boundary, every
//     point of the whole boundary inside the ball covered, every triangle meeting the ball;
//   - culling never drops a facet that meets the query box: the sphere-tree, convex-map
//     and box-tree enumerations give exactly the brute-force set;
//   - coherence: one object updated along a sampled motion (each feature walked from its
//     cell of the last call) gives, frame by frame, exactly the facets and triangles of an
//     object built afresh for that frame;
//   - balls far beyond M's size: one that holds M keeps what a ball around M keeps; spheres
//     of radius 5 · 2^27 … 5 · 2^700 through one point of M with one tangent plane there
//     keep the same triangles (the test of a piece against the ball is exact);
//   - bad input: a non-finite centre, a radius that is not positive and finite, a pose
//     that is not rigid;
//   - float and CGAL::Gmpq instantiate and agree with double.
#include "mink/cpd/local_minkowski_sum.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "mink/cpd/minkowski_boundary.hpp"
#include "support/expect_rejected.hpp"
#include "support/mesh_shapes.hpp"
#include "support/patch_measures.hpp"

namespace {

using V = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
using Mesh = mink::TriangleMesh<double>;
using mink_test::MeshShape;

#ifdef MINK_SANITIZE_BUILD
constexpr int kFrames = 3;
#else
constexpr int kFrames = 12;
#endif

Mesh mesh(const MeshShape& s) { return Mesh::fromMesh(s.verticesAs<double>(), s.triangles); }

struct Pair {
  std::string name;
  MeshShape a, b;
};

MeshShape scaledShape(MeshShape s, double f) {
  for (auto& v : s.vertices) v *= f;
  return s;
}

std::vector<Pair> pairs() {
  return {{"L-block / box", mink_test::lBlock(), mink_test::boxShape(V(-0.5, -0.25, -0.75), V(0.5, 0.25, 0.75))},
          {"torus 16x12 / box", mink_test::torus(16, 12), mink_test::boxShape(V(-0.4, -0.3, -0.5), V(0.4, 0.3, 0.5))},
          {"U-block / L-block", mink_test::uBlock(), mink_test::lBlock()},
          {"cube with hole / star", mink_test::cubeWithHole(), scaledShape(mink_test::starPrism(), 0.0625)},
          {"torus / torus", mink_test::torus(16, 10), mink_test::torus(12, 8, 1.5, 0.5)}};
}

M3 rotation(double angle, const V& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

/// A set of triangles by their corners' coordinates (order of triangles and of their
/// first corner free), for comparing two patches.
std::set<std::vector<double>> triangleSet(const mink::MinkowskiPatch<double>& p) {
  std::set<std::vector<double>> s;
  for (const auto& t : p.triangles) {
    int k = 0;
    for (int c = 1; c < 3; ++c)
      if (std::lexicographical_compare(p.vertices[t[c]].data(), p.vertices[t[c]].data() + 3, p.vertices[t[k]].data(),
                                       p.vertices[t[k]].data() + 3))
        k = c;
    std::vector<double> key;
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 3; ++a) key.push_back(p.vertices[t[(k + c) % 3]][a]);
    s.insert(key);
  }
  return s;
}

std::set<std::tuple<int, int, int>> facetSet(const std::vector<mink::ConvolutionPair>& f) {
  std::set<std::tuple<int, int, int>> s;
  for (const auto& c : f) s.insert({static_cast<int>(c.type), c.featureA, c.featureB});
  return s;
}

/// Patch corners lying inside an edge of a triangle they are not a corner of (a
/// T-junction: the triangles do not meet edge to edge there), within 1e-12 of the scene.
int tJunctions(const mink::MinkowskiPatch<double>& P, double L) {
  int n = 0;
  for (const auto& t : P.triangles)
    for (int e = 0; e < 3; ++e) {
      const V a = P.vertices[t[e]], d = P.vertices[t[(e + 1) % 3]] - a;
      for (int v = 0; v < static_cast<int>(P.vertices.size()); ++v) {
        if (v == t[0] || v == t[1] || v == t[2]) continue;
        const double s = (P.vertices[v] - a).dot(d) / d.squaredNorm();
        if (s > 1e-9 && s < 1 - 1e-9 && (P.vertices[v] - a - s * d).norm() < 1e-12 * L) ++n;
      }
    }
  return n;
}

TEST(LocalMinkowskiSum, ThePartOfTheWholeBoundaryInTheBall) {
  std::mt19937 rng(1401);
  std::uniform_real_distribution<double> U(-1, 1);
  for (const Pair& pr : pairs()) {
    SCOPED_TRACE(pr.name);
    const Mesh A = mesh(pr.a), B = mesh(pr.b);
    mink::Pose<double> poseA, poseB;
    poseA.rotation = rotation(0.7, V(-1, 2, 0.5));
    poseA.translation = V(0.5, 0.2, -0.1);
    poseB.rotation = rotation(0.4, V(1, 2, 3));
    poseB.translation = V(0.2, -0.1, 0.3);
    const auto full = mink::minkowskiBoundary(A, poseA, B, poseB);
    ASSERT_FALSE(full.triangles.empty());
    mink::LocalMinkowskiSum<double> local(A, B);
    double L = 0;
    for (const auto& v : full.vertices) L = std::max(L, v.cwiseAbs().maxCoeff());
    for (int k = 0; k < 4; ++k) {
      // A ball around a point of the boundary, of a quarter to half the scene.
      const auto& t = full.triangles[(37 * k + 11) % full.triangles.size()];
      const V c = full.vertices[t[0]] + 0.1 * L * V(U(rng), U(rng), U(rng));
      const double r = (0.25 + 0.25 * k / 3.0) * L;
      const auto& P = local.update(poseA, poseB, c, r);
      int off = 0, outside = 0;
      for (const auto& q : P.triangles) {
        const V x = (P.vertices[q[0]] + P.vertices[q[1]] + P.vertices[q[2]]) / 3;
        if (mink_test::distanceToPatch(full, x) > 1e-9 * L) ++off;
        // Meets the ball: the nearest point of the triangle within r.
        const double d = std::sqrt(mink_test::squaredDistanceToTriangle(c, P.vertices[q[0]], P.vertices[q[1]], P.vertices[q[2]]));
        if (d > r * (1 + 1e-12)) ++outside;
      }
      int missing = 0, inBall = 0;
      for (const auto& q : full.triangles)
        for (int i = 1; i < 5; ++i)
          for (int j = 1; i + j < 5; ++j) {
            const V x = full.vertices[q[0]] + (full.vertices[q[1]] - full.vertices[q[0]]) * (i / 5.0) +
                        (full.vertices[q[2]] - full.vertices[q[0]]) * (j / 5.0);
            if ((x - c).norm() > r) continue;
            ++inBall;
            if (mink_test::distanceToPatch(P, x) > 1e-9 * L) ++missing;
          }
      const int tj = tJunctions(P, L);
      std::printf("[cpd] %-22s ball %d: r %.2f, %zu triangles (whole %zu), facets %d, pieces %d, collision tests %d, %d points of the whole in the ball, %d T-junctions\n",
                  pr.name.c_str(), k, r, P.triangles.size(), full.triangles.size(), P.facetsGathered, P.pieces, P.overlapTests, inBall, tj);

      EXPECT_EQ(off, 0) << "ball " << k << ": triangles off the whole boundary";
      EXPECT_EQ(outside, 0) << "ball " << k << ": triangles not meeting the ball";
      EXPECT_EQ(missing, 0) << "ball " << k << ": points of the whole boundary in the ball not covered";
    }
  }
}

TEST(LocalMinkowskiSum, CullingDropsNoFacetThatMeetsTheRegion) {
  for (const Pair& pr : pairs()) {
    SCOPED_TRACE(pr.name);
    const Mesh A = mesh(pr.a), B = mesh(pr.b);
    mink::Pose<double> poseA, poseB;
    poseB.rotation = rotation(1.3, V(0.3, -1, 2));
    poseB.translation = V(0.1, 0.3, -0.2);
    mink::LocalMinkowskiSumOptions<double> brute, tree, maps, boxes;
    brute.method = mink::LocalSumMethod::BruteForce;
    tree.method = mink::LocalSumMethod::SphereTree;
    maps.method = mink::LocalSumMethod::ConvexMaps;
    boxes.method = mink::LocalSumMethod::BoxTrees;
    mink::LocalMinkowskiSum<double> lb(A, B, brute), lt(A, B, tree), lm(A, B, maps), lx(A, B, boxes);
    for (const V& c : {V(0, 0, 0), V(0.5, -0.3, 0.8), V(-1, 0.5, 0.2)}) {
      lb.update(poseA, poseB, c, 0.8);
      lt.update(poseA, poseB, c, 0.8);
      lm.update(poseA, poseB, c, 0.8);
      lx.update(poseA, poseB, c, 0.8);
      EXPECT_EQ(facetSet(lt.facets()), facetSet(lb.facets())) << "sphere tree";
      EXPECT_EQ(facetSet(lm.facets()), facetSet(lb.facets())) << "convex maps";
      EXPECT_EQ(facetSet(lx.facets()), facetSet(lb.facets())) << "box trees";
      EXPECT_EQ(triangleSet(lx.patch()), triangleSet(lb.patch())) << "box trees";
      EXPECT_GT(lb.patch().candidatePairs, lm.patch().candidatePairs);
      EXPECT_GT(lb.patch().candidatePairs, lx.patch().candidatePairs);
    }
  }
}

TEST(LocalMinkowskiSum, CoherentUpdatesEqualUpdatesFromScratch) {
  for (const Pair& pr : pairs()) {
    SCOPED_TRACE(pr.name);
    const Mesh A = mesh(pr.a), B = mesh(pr.b);
    mink::LocalMinkowskiSumOptions<double> maps;
    maps.method = mink::LocalSumMethod::ConvexMaps;
    // The default (BoxTrees) keeps B's placement and box tree between calls; ConvexMaps
    // keeps every feature's cell.
    mink::LocalMinkowskiSum<double> coherent(A, B), coherentMaps(A, B, maps);
    for (int f = 0; f < kFrames; ++f) {
      // B turns 3 degrees per frame about a tilted axis and slides; the ball follows.
      mink::Pose<double> poseA, poseB;
      poseB.rotation = rotation(0.05 * f, V(0.2, 1, 0.4)) * rotation(0.4, V(1, 2, 3));
      poseB.translation = V(0.2 + 0.02 * f, -0.1, 0.3);
      const V c(0.3 + 0.01 * f, 0.1, 0.4);
      const auto& P = coherent.update(poseA, poseB, c, 0.9);
      mink::LocalMinkowskiSum<double> fresh(A, B);
      const auto& Q = fresh.update(poseA, poseB, c, 0.9);
      EXPECT_EQ(facetSet(coherent.facets()), facetSet(fresh.facets())) << "frame " << f;
      EXPECT_EQ(triangleSet(P), triangleSet(Q)) << "frame " << f;
      const auto& PM = coherentMaps.update(poseA, poseB, c, 0.9);
      EXPECT_EQ(facetSet(coherentMaps.facets()), facetSet(fresh.facets())) << "convex maps, frame " << f;
      EXPECT_EQ(triangleSet(PM), triangleSet(Q)) << "convex maps, frame " << f;
      // A second ball at the same poses (as a CPD query's next iteration): B is not
      // placed again, and the patch is the fresh object's for that ball.
      const V c2 = c + V(0.2, -0.1, 0.05);
      mink::LocalMinkowskiSum<double> fresh2(A, B);
      EXPECT_EQ(triangleSet(coherent.update(poseA, poseB, c2, 0.5)), triangleSet(fresh2.update(poseA, poseB, c2, 0.5)))
          << "second ball, frame " << f;
    }
  }
}

TEST(LocalMinkowskiSum, ScalingByAPowerOfTwoScalesThePatch) {
  // Multiplying every coordinate, the centre and the radius by 2^k is exact in floating
  // point, so every method must return the patch of scale one times 2^k, triangle for
  // triangle: at 2^64 and 2^-66 (on either side of where LocalMinkowskiSum starts working
  // on copies scaled to unit size), at 2^270 (|normal|^2 and the trimming's products of
  // up to nine coordinates overflow), 2^-300 (they underflow) and 2^-520 (the normals
  // themselves are denormal). All within fromMesh's coordinate range.
  const MeshShape a = mink_test::torus(16, 12), b = mink_test::boxShape(V(-0.4, -0.3, -0.5), V(0.4, 0.3, 0.5));
  const M3 R = rotation(1.1, V(0.3, -1, 2));
  const V t(0.9, 0.3, -0.2), c(1.9, 0.2, 0.1);
  const double r = 0.8;
  for (auto method : {mink::LocalSumMethod::BruteForce, mink::LocalSumMethod::SphereTree, mink::LocalSumMethod::ConvexMaps,
                      mink::LocalSumMethod::BoxTrees}) {
    mink::LocalMinkowskiSumOptions<double> opt;
    opt.method = method;
    const Mesh A1 = mesh(a), B1 = mesh(b);
    mink::LocalMinkowskiSum<double> one(A1, B1, opt);
    mink::Pose<double> pA, pB;
    pB.rotation = R;
    pB.translation = t;
    const auto ref = triangleSet(one.update(pA, pB, c, r));
    ASSERT_FALSE(ref.empty());
    for (int k : {64, -66, 270, -300, -520}) {
      SCOPED_TRACE("method " + std::to_string(static_cast<int>(method)) + ", scale 2^" + std::to_string(k));
      const double f = std::ldexp(1.0, k);
      const Mesh A = mesh(scaledShape(a, f)), B = mesh(scaledShape(b, f));
      mink::LocalMinkowskiSum<double> local(A, B, opt);
      mink::Pose<double> qB = pB;
      qB.translation = t * f;
      std::set<std::vector<double>> back;
      for (auto key : triangleSet(local.update(pA, qB, V(c * f), r * f))) {
        for (double& x : key) x = std::ldexp(x, -k);
        back.insert(key);
      }
      EXPECT_EQ(back, ref);
    }
  }
}

TEST(LocalMinkowskiSum, NearlyFlatEdgeTurnedReflexByTheRotation) {
  // fuzz/regressions_mesh/convex_maps_misses_ee_pair_torus3x3_torus4x3: B's edge 10-5, the
  // diagonal of a planar quad, is convex by 1e-16 in B's frame and reflex once B's corners
  // are rotated and rounded. BruteForce took it into an EE pair (both far vertices beyond
  // the plane through the two edges), ConvexMaps (B's own Gauss arcs) did not.
  const std::vector<V> va = {
      V(0x1p+2, 0, 0), V(0x1.4p+1, 0, 0x1.bb67ae8584cabp-1), V(0x1.3ffffffffffffp+1, 0, -0x1.bb67ae8584ca8p-1),
      V(-0x1.ffffffffffffcp+0, 0x1.bb67ae8584cabp+1, 0), V(-0x1.3fffffffffffep+0, 0x1.1520cd1372febp+1, 0x1.bb67ae8584cabp-1),
      V(-0x1.3fffffffffffdp+0, 0x1.1520cd1372feap+1, -0x1.bb67ae8584ca8p-1), V(-0x1.0000000000004p+1, -0x1.bb67ae8584ca8p+1, 0),
      V(-0x1.4000000000005p+0, -0x1.1520cd1372fe9p+1, 0x1.bb67ae8584cabp-1),
      V(-0x1.4000000000004p+0, -0x1.1520cd1372fe8p+1, -0x1.bb67ae8584ca8p-1)};
  const std::vector<std::array<int, 3>> ta = {{0, 3, 4}, {0, 4, 1}, {1, 4, 5}, {1, 5, 2}, {2, 5, 3}, {2, 3, 0},
                                              {3, 6, 7}, {3, 7, 4}, {4, 7, 8}, {4, 8, 5}, {5, 8, 6}, {5, 6, 3},
                                              {6, 0, 1}, {6, 1, 7}, {7, 1, 2}, {7, 2, 8}, {8, 2, 0}, {8, 0, 6}};
  const std::vector<V> vb = {
      V(0x1p+1, 0, 0), V(0x1.8p+0, 0, 0x1p-1), V(0x1p+0, 0, 0x1.1a62633145c07p-54), V(0x1.8p+0, 0, -0x1p-1),
      V(-0x1.ffffffffffffcp-1, 0x1.bb67ae8584cabp+0, 0), V(-0x1.7fffffffffffdp-1, 0x1.4c8dc2e42398p+0, 0x1p-1),
      V(-0x1.ffffffffffffcp-2, 0x1.bb67ae8584cabp-1, 0x1.1a62633145c07p-54),
      V(-0x1.7fffffffffffdp-1, 0x1.4c8dc2e42398p+0, -0x1p-1), V(-0x1.0000000000004p+0, -0x1.bb67ae8584ca8p+0, 0),
      V(-0x1.8000000000006p-1, -0x1.4c8dc2e42397ep+0, 0x1p-1),
      V(-0x1.0000000000004p-1, -0x1.bb67ae8584ca8p-1, 0x1.1a62633145c07p-54),
      V(-0x1.8000000000006p-1, -0x1.4c8dc2e42397ep+0, -0x1p-1)};
  const std::vector<std::array<int, 3>> tb = {
      {0, 4, 5}, {0, 5, 1}, {1, 5, 6}, {1, 6, 2},  {2, 6, 7},  {2, 7, 3},  {3, 7, 4},   {3, 4, 0},
      {4, 8, 9}, {4, 9, 5}, {5, 9, 10}, {5, 10, 6}, {6, 10, 11}, {6, 11, 7}, {7, 11, 8}, {7, 8, 4},
      {8, 0, 1}, {8, 1, 9}, {9, 1, 2}, {9, 2, 10}, {10, 2, 3}, {10, 3, 11}, {11, 3, 0}, {11, 0, 8}};
  const Mesh A = Mesh::fromMesh(va, ta), B = Mesh::fromMesh(vb, tb);
  mink::Pose<double> pA, pB;
  pB.rotation << 0.96296296296296302, -0.25925925925925924, 0.07407407407407407, 0.25925925925925924,
      0.81481481481481488, -0.51851851851851849, 0.07407407407407407, 0.51851851851851849, 0.85185185185185186;
  std::set<std::tuple<int, int, int>> sets[4];
  std::set<std::vector<double>> tris[4];
  for (int m = 0; m < 4; ++m) {
    mink::LocalMinkowskiSumOptions<double> opt;
    opt.method = static_cast<mink::LocalSumMethod>(m);
    mink::LocalMinkowskiSum<double> local(A, B, opt);
    tris[m] = triangleSet(local.update(pA, pB, V(-1, -0.5, 0.5), 1.0));
    sets[m] = facetSet(local.facets());
  }
  EXPECT_FALSE(sets[0].empty());
  EXPECT_EQ(sets[1], sets[0]) << "sphere tree";
  EXPECT_EQ(sets[2], sets[0]) << "convex maps";
  EXPECT_EQ(sets[3], sets[0]) << "box trees";
  EXPECT_EQ(tris[2], tris[0]);
  EXPECT_EQ(tris[3], tris[0]);
  EXPECT_EQ(sets[0].count({static_cast<int>(mink::ConvolutionType::EE), 15, 21}), 0u);  // the pair of the flipped edge
}

TEST(LocalMinkowskiSum, ConvexMapsHandsCoarsePlacementsToTheBoxTrees) {
  // fuzz/regressions_mesh/convex_maps_misses_fv_octahedron_2e-80: A = B = an octahedron
  // with one corner at z = -1 and the others within 2^-79 of the z axis. Placed by a
  // rational rotation, B's corners 0 and 2 (3 * 2^-80 apart, at distance 1) round to the
  // same point: B's triangle 0 is degenerate as placed, so every vertex of A is compatible
  // with it (VF), which C(A) looked up along B's own normal of that triangle could not
  // know. B's map no longer answers for such a placement (ConvexMap::answersPlacement)
  // and the update is gathered by the box trees.
  const double a = std::ldexp(1.0, -80), b = std::ldexp(1.0, -79);
  const std::vector<V> pts = {V(b, a, -1), V(0, a, a), V(-a, b, -1), V(a, 0, a), V(a, a, b), V(a, a, 0)};
  const std::vector<std::array<int, 3>> tris = {{0, 2, 4}, {0, 5, 2}, {0, 4, 3}, {0, 3, 5},
                                                {1, 4, 2}, {1, 2, 5}, {1, 3, 4}, {1, 5, 3}};
  const Mesh X = Mesh::fromMesh(pts, tris);
  mink::Pose<double> pA, pB;
  pA.translation = pB.translation = V(-b, -b, -b);
  pB.rotation << 0.33333333333333348, -0.8717948717948717, -0.35897435897435892, 0.66666666666666663,
      0.48717948717948723, -0.5641025641025641, 0.66666666666666663, -0.051282051282051266, 0.74358974358974361;
  std::set<std::tuple<int, int, int>> sets[4];
  long long fallbacks = -1;
  for (int m = 0; m < 4; ++m) {
    mink::LocalMinkowskiSumOptions<double> opt;
    opt.method = static_cast<mink::LocalSumMethod>(m);
    mink::LocalMinkowskiSum<double> local(X, X, opt);
    local.update(pA, pB, V(-a, -a, -a), std::ldexp(1.0, -82));
    sets[m] = facetSet(local.facets());
    if (opt.method == mink::LocalSumMethod::ConvexMaps) fallbacks = local.convexMapFallbacks();
  }
  EXPECT_EQ(sets[0].count({static_cast<int>(mink::ConvolutionType::VF), 1, 0}), 1u);
  EXPECT_EQ(sets[2], sets[0]) << "convex maps";
  EXPECT_EQ(sets[3], sets[0]) << "box trees";
  EXPECT_EQ(fallbacks, 1);
  // The same needle at unit size is answered by the maps themselves.
  const auto& map = *mink::ConvexMap<double>::of(X);
  EXPECT_FALSE(map.answersPlacement(pB.rotation, V(0, 0, 0)));
  EXPECT_GT(map.leastHeight(), 0.0);
  EXPECT_LT(map.leastHeight(), 4 * a);
  const Mesh A = mesh(mink_test::torus(16, 12)), B = mesh(mink_test::boxShape(V(-0.4, -0.3, -0.5), V(0.4, 0.3, 0.5)));
  mink::LocalMinkowskiSumOptions<double> opt;
  opt.method = mink::LocalSumMethod::ConvexMaps;
  mink::LocalMinkowskiSum<double> local(A, B, opt);
  mink::Pose<double> qB;
  qB.rotation = rotation(1.1, V(0.3, -1, 2));
  qB.translation = V(0.9, 0.3, -0.2);
  EXPECT_FALSE(local.update(pA, qB, V(1.9, 0.2, 0.1), 0.8).triangles.empty());
  EXPECT_EQ(local.convexMapFallbacks(), 0);
}

TEST(LocalMinkowskiSum, ConvexMapOfATetrahedronOneDenormalThick) {
  // fuzz/regressions_mesh/convex_map_fromPoints_3_points_tetra_vertex_denorm_min: the
  // tetrahedron's rounded unit normals were three points on a great circle (two of its
  // four faces' normals equal to rounding), and ConvexMap's hull of them threw
  // "fromPoints: need at least 4 points". The map now adds the six axis directions.
  const std::vector<V> pts = {V(-1, 0, -8), V(8, 0, -8), V(0, 4.9406564584124654e-324, -8), V(0, 0, 0)};
  const std::vector<std::array<int, 3>> tris = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  const Mesh A = Mesh::fromMesh(pts, tris), B = mesh(mink_test::boxShape(V(-4, -4, -4), V(4, 4, 4)));
  const auto& map = *mink::ConvexMap<double>::of(A);
  for (const V& d : {V(0, 0, -1), V(0, 1, 0), V(0, -1, 0), V(1, 0, 0), V(-1, 0, 0), V(0.3, -0.2, 0.9)}) {
    const int cell = map.locate(d);
    EXPECT_TRUE(map.facesToward(cell, d));
  }
  mink::Pose<double> pA, pB;
  pB.rotation << 0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1;
  std::set<std::tuple<int, int, int>> sets[4];
  for (int m = 0; m < 4; ++m) {
    mink::LocalMinkowskiSumOptions<double> opt;
    opt.method = static_cast<mink::LocalSumMethod>(m);
    mink::LocalMinkowskiSum<double> local(A, B, opt);
    local.update(pA, pB, V(-4, -4, -4), 1.0);
    sets[m] = facetSet(local.facets());
  }
  EXPECT_FALSE(sets[0].empty());
  for (int m = 1; m < 4; ++m) EXPECT_EQ(sets[m], sets[0]) << "method " << m;
}

TEST(LocalMinkowskiSum, BallHoldingAllOfMIsWorkedOnAtTheMeshesScale) {
  // fuzz/regressions_mesh/slow_tetra_box_ball_radius_1e300_48_pairs: a ball of radius
  // 1e300 around a point 1e232 away, two meshes of size 8. The work was done in units of
  // 2^992 (the ball's scale), where the meshes are 2^-989 wide: products of three
  // coordinates underflowed, corners came out 0 / 0, each update took 22 s of exact
  // arithmetic on NaN, and the second pose lost a triangle. A ball that holds all of M is
  // now the ball around M's bounding sphere: the patch must be that of any ball holding M.
  const std::vector<V> va = {V(0x1.12e0be826d695p-30, -8, -8), V(8, -8, -8), V(0, 0, -8), V(0, -8, 0)};
  const std::vector<std::array<int, 3>> ta = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const Mesh A = Mesh::fromMesh(va, ta), B = mesh(mink_test::boxShape(V(-4, -4, -4), V(4, 4, 4)));
  mink::Pose<double> pA[2], pB[2];
  pA[0].translation = pA[1].translation = V(-8, -8, -8);
  pA[1].rotation << 1, 0, 0, 0, 0.99631417822928248, -0.085779124845789492, 0, 0.085779124845789492, 0.99631417822928248;
  pB[0].rotation << 0.33333333333333348, -0.8717948717948717, -0.35897435897435892, 0.66666666666666663,
      0.48717948717948723, -0.5641025641025641, 0.66666666666666663, -0.051282051282051266, 0.74358974358974361;
  pB[0].translation = V(-8, 4, 0);
  pB[1].rotation << 0.33333460489545075, -0.87073903508144501, -0.36152672648730644, 0.66731707068963486,
      0.48877842763568113, -0.56194623928290155, 0.66601499108158124, -0.053936828451671859, 0.74398578628302858;
  pB[1].translation = V(-8, 4.5625, -0.03125);
  const V farCentre(1.7387650154288008e-310, 5.3744319167353186e-299, -0x1.91c5a02020201p+770);
  for (auto method : {mink::LocalSumMethod::BruteForce, mink::LocalSumMethod::BoxTrees}) {
    mink::LocalMinkowskiSumOptions<double> opt;
    opt.method = method;
    mink::LocalMinkowskiSum<double> huge(A, B, opt), plain(A, B, opt);
    for (int k = 0; k < 2; ++k) {
      SCOPED_TRACE("method " + std::to_string(static_cast<int>(method)) + ", pose " + std::to_string(k));
      const auto big = triangleSet(huge.update(pA[k], pB[k], farCentre, 1e300));
      const auto ref = triangleSet(plain.update(pA[k], pB[k], V(pA[k].translation - pB[k].translation), 1e3));
      EXPECT_FALSE(ref.empty());
      EXPECT_EQ(big, ref);
    }
  }
}

TEST(LocalMinkowskiSum, BallCrossingMKeepsTheSamePiecesAtAnyRadius) {
  // The meshes above, B lowered so that M straddles the origin's plane, and balls whose
  // sphere passes exactly through (0, −12, 0) with normal (3, 0, 4) / 5 there: centre
  // (−3k, −12, −4k), radius 5k (exact numbers), far from the box's faces, so that the
  // sphere alone trims M; for k >= 2^27 it is within 1e-6 of its tangent plane over M.
  // Every such ball must keep the same triangles. The test of a piece against the ball
  // was in double (every piece "met" a sphere of radius 5 · 2^66: all 44 triangles kept
  // instead of 34), and the work moved to the ball's units (k = 2^332: a triangle too
  // many, products of coordinates underflowing; 8 s per update at 2^700).
  const std::vector<V> va = {V(0x1.12e0be826d695p-30, -8, -8), V(8, -8, -8), V(0, 0, -8), V(0, -8, 0)};
  const std::vector<std::array<int, 3>> ta = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const Mesh A = Mesh::fromMesh(va, ta), B = mesh(mink_test::boxShape(V(-4, -4, -4), V(4, 4, 4)));
  mink::Pose<double> pA, pB;
  pA.translation = V(-8, -8, -8);
  pB.rotation << 0.33333333333333348, -0.8717948717948717, -0.35897435897435892, 0.66666666666666663,
      0.48717948717948723, -0.5641025641025641, 0.66666666666666663, -0.051282051282051266, 0.74358974358974361;
  pB.translation = V(-8, 4, -12);
  auto ball = [](int e) {
    const double k = std::ldexp(1.0, e);
    return std::make_pair(V(-3 * k, -12, -4 * k), 5 * k);
  };
  for (auto method : {mink::LocalSumMethod::BruteForce, mink::LocalSumMethod::BoxTrees}) {
    mink::LocalMinkowskiSumOptions<double> opt;
    opt.method = method;
    mink::LocalMinkowskiSum<double> local(A, B, opt);
    const auto all = triangleSet(local.update(pA, pB, V(pA.translation - pB.translation), 1e3));
    const auto near = ball(27);
    const auto ref = triangleSet(local.update(pA, pB, near.first, near.second));
    EXPECT_GT(ref.size(), 10u);
    EXPECT_LT(ref.size(), all.size());  // the sphere trims M
    for (int e : {66, 133, 332, 700}) {
      SCOPED_TRACE("method " + std::to_string(static_cast<int>(method)) + ", k = 2^" + std::to_string(e));
      const auto b = ball(e);
      EXPECT_EQ(triangleSet(local.update(pA, pB, b.first, b.second)), ref);
    }
  }
}

TEST(LocalMinkowskiSum, FarBallBesideTinyMeshesIsAnsweredNotRejected) {
  // fuzz/regressions_mesh/tiny_boxes_ball_2e265_away_units_overflow: boxes of half-size
  // 2^-512 and a ball 1.6e265 away. With the units taken from the meshes alone (2^-480),
  // the ball's centre overflowed in them and update() refused valid arguments; the units
  // now rise as far as the ball needs. The ball meets nothing: an empty patch.
  const Mesh A = mesh(mink_test::boxShape(V::Constant(-std::ldexp(1.0, -512)), V::Constant(std::ldexp(1.0, -512))));
  mink::Pose<double> pA, pB;
  pB.rotation = V(-1, 1, -1).asDiagonal();
  pB.translation = V(-std::ldexp(1.0, -511), std::ldexp(1.0, -512), std::ldexp(1.0, -511));
  mink::LocalMinkowskiSum<double> local(A, A);
  const auto r = local.tryUpdate(pA, pB, V(-0x1.002f903ffffffp+881, 0, 0), std::ldexp(1.0, -514));
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_TRUE(r.value()->triangles.empty());
  // And the same boxes with a ball around them: the units still follow the meshes.
  const auto near = local.tryUpdate(pA, pB, V(pA.translation - pB.translation), std::ldexp(1.0, -509));
  ASSERT_TRUE(near.ok()) << near.error().message();
  EXPECT_FALSE(near.value()->triangles.empty());
}

TEST(LocalMinkowskiSum, SubnormalFacetsBesideAUnitMeshGetAFiniteOffset) {
  // fuzz/regressions_mesh/subnormal_needle_box_tiny_cube_nan_offset: A a needle 1 long
  // and 1.1e-308 wide, B a cube of side 1.1e-308 (subnormal coordinates beside 1: no
  // power of two brings both near one). The cross products of B's sides underflow to
  // zero, and the trimming offset a piece along their normalised value, NaN: every exact
  // orientation test on NaN took its slowest path (6 s per update) and the answer
  // depended on comparisons with NaN. The offset's direction now comes from the sides
  // scaled apart. (With assertions on, MeshOverlap::overlaps refuses a NaN offset.)
  const double h = 0x0.4p-1022, w = 0x0.8p-1022;
  const std::vector<std::array<int, 3>> tri = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                               {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  const std::vector<V> a = {V(-1, 0, 0),  V(-h, 0, 0), V(-1, w, 0),      V(-h, w, 0),
                            V(-3 * h, 0, w), V(-h, 0, w), V(-3 * h, w, w), V(-h, w, w)};
  std::vector<V> b;
  for (int i = 0; i < 8; ++i) b.push_back(V(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h));
  const Mesh A = Mesh::fromMesh(a, tri), B = Mesh::fromMesh(b, tri);
  mink::Pose<double> pA, pB;
  pA.translation = V(h, w, -h);
  // A half-turn about (1, -1, -4), to a few ulps (the fuzz input's numbers).
  const double r8 = 0.88888888888888928, r1 = 0.11111111111111113, r4 = 0.44444444444444453;
  pB.rotation << -r8, -r1, -r4, -r1, -r8, r4, -r4, r4, 0.77777777777777768;
  pB.translation = V(0x0.008p-1022, 0x0.004p-1022, 0);
  for (const auto method : {mink::LocalSumMethod::BruteForce, mink::LocalSumMethod::SphereTree,
                            mink::LocalSumMethod::ConvexMaps, mink::LocalSumMethod::BoxTrees}) {
    mink::LocalMinkowskiSumOptions<double> opt;
    opt.method = method;
    mink::LocalMinkowskiSum<double> local(A, B, opt);
    const auto r = local.tryUpdate(pA, pB, V(-0x0.008p-1022, 0x0.3fcp-1022, -w), 0x0.1p-1022);
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r.value()->triangles.size(), 3u);
    for (const V& v : r.value()->vertices) EXPECT_TRUE(v.allFinite());
  }
}

TEST(LocalMinkowskiSum, FacetsFarSmallerThanTheirDistanceAreNotCut) {
  // fuzz/regressions_mesh/subnormal_cubes_offset_3_not_cut: two cubes 1.1e-308 across,
  // B 3 above A. Every a - b rounds to z = -3, so the sum the trimming sees is flat:
  // dozens of coplanar facets, each cut by every other's edges with exact predicates on
  // subnormal coordinates (1 s per update), into pieces that all had no area in double
  // and were dropped. Such a facet is now counted and not cut; the patch is the same
  // (empty). At unit scale the same scene is cut as before.
  const std::vector<std::array<int, 3>> tri = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                               {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const double s : {0x0.8p-1022, 1e-300, 1.0}) {
    std::vector<V> c;
    for (int i = 0; i < 8; ++i) c.push_back(V(i & 1 ? s : 0, i & 2 ? s : 0, i & 4 ? s : 0));
    const Mesh A = Mesh::fromMesh(c, tri), B = Mesh::fromMesh(c, tri);
    mink::Pose<double> pA, pB;
    pB.rotation = Eigen::AngleAxisd(0.078, V(0.1, -1, 0.01).normalized()).toRotationMatrix();
    pB.translation = V(0, -s, 3);
    mink::LocalMinkowskiSum<double> local(A, B);
    const auto& P = local.update(pA, pB, V(0, 0, -3), 1.5 * s);
    char side[32];
    std::snprintf(side, sizeof side, "cube side %g", s);
    SCOPED_TRACE(side);
    EXPECT_GT(P.facetsGathered, 0);
    if (s < 1e-200) {
      EXPECT_GT(P.facetsBelowResolution, P.facetsGathered / 2);
      EXPECT_EQ(P.triangles.size(), 0u);
    } else {
      EXPECT_EQ(P.facetsBelowResolution, 0);
      EXPECT_GT(P.triangles.size(), 0u);
    }
  }
}

TEST(LocalMinkowskiSum, ConvexMapsFindAVertexWhoseNeighboursAgreeToRounding) {
  // fuzz/regressions_mesh/convex_map_vertex_unregistered_needle_star_box_2e-308_tetra: a
  // box 1.1e-308 across with one corner pulled to x = -1. From that corner its three
  // neighbours lie in the same direction to 1e-308, so the convex map could not compute
  // its cone (the rays are cross products of the neighbour directions) and registered it
  // nowhere: ConvexMaps missed its VF facets. Such a vertex is now listed in every cell.
  const double h = 0x0.4p-1022, w = 0x0.8p-1022;
  const std::vector<V> a = {V(-h, -w, -w), V(h, -w, -w), V(-1, 0, -w), V(h, 0, -w),
                            V(-h, -w, 0),  V(h, -w, 0),  V(-h, 0, 0),  V(h, 0, 0)};
  const std::vector<std::array<int, 3>> box = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                               {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  const Mesh A = Mesh::fromMesh(a, box);
  const Mesh B = Mesh::fromMesh(std::vector<V>{V(0, 0, 0), V(2, 0, 0), V(0, 2, 0), V(0, 0, 2)},
                                std::vector<std::array<int, 3>>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  mink::Pose<double> pA, pB;
  pA.translation = V(-w, w, -h);
  pB.rotation << 0.33333333333333348, -0.8717948717948717, -0.35897435897435892, 0.66666666666666663,
      0.48717948717948723, -0.5641025641025641, 0.66666666666666663, -0.051282051282051266, 0.74358974358974361;
  pB.translation = V(h, w, -h);
  mink::LocalMinkowskiSumOptions<double> brute, maps;
  brute.method = mink::LocalSumMethod::BruteForce;
  maps.method = mink::LocalSumMethod::ConvexMaps;
  mink::LocalMinkowskiSum<double> lb(A, B, brute), lm(A, B, maps);
  const V c(-0x1p-1022, -h, -h);
  lb.update(pA, pB, c, 0x0.1p-1022);
  lm.update(pA, pB, c, 0x0.1p-1022);
  EXPECT_FALSE(lb.facets().empty());
  EXPECT_EQ(facetSet(lm.facets()), facetSet(lb.facets()));
}

TEST(LocalMinkowskiSum, BadInputIsRejected) {
  const Mesh A = mesh(mink_test::lBlock()), B = mesh(mink_test::boxShape());
  mink::LocalMinkowskiSum<double> local(A, B);
  mink::Pose<double> p;
  const double nan = std::nan(""), inf = INFINITY;
  mink_test::expectRejected([&] { local.update(p, p, V(nan, 0, 0), 1.0); }, "centre is not finite", "NaN centre");
  mink_test::expectRejected([&] { local.update(p, p, V(0, inf, 0), 1.0); }, "centre is not finite", "infinite centre");
  for (double r : {0.0, -1.0, nan, inf})
    mink_test::expectRejected([&] { local.update(p, p, V(0, 0, 0), r); }, "radius", "radius " + std::to_string(r));
  mink::Pose<double> skew;
  skew.rotation(0, 1) = 0.5;
  mink_test::expectRejected([&] { local.update(skew, p, V(0, 0, 0), 1.0); }, "poseA", "non-rigid poseA");
  mink_test::expectRejected([&] { local.update(p, skew, V(0, 0, 0), 1.0); }, "poseB", "non-rigid poseB");
  mink::Pose<double> nanPose;
  nanPose.translation[2] = nan;
  mink_test::expectRejected([&] { local.update(p, nanPose, V(0, 0, 0), 1.0); }, "poseB", "NaN translation");
  // tryUpdate, the entry point of builds without exceptions: each of these as an Error with
  // the message update() throws; a good ball answered as update() answers it.
  struct Case {
    mink::Pose<double> a, b;
    V centre;
    double radius;
  };
  for (const Case& c : {Case{p, p, V(nan, 0, 0), 1.0}, Case{p, p, V(0, 0, 0), 0.0}, Case{skew, p, V(0, 0, 0), 1.0},
                        Case{p, nanPose, V(0, 0, 0), 1.0}}) {
    const auto r = local.tryUpdate(c.a, c.b, c.centre, c.radius);
    ASSERT_FALSE(r.ok());
    try {
      local.update(c.a, c.b, c.centre, c.radius);
      ADD_FAILURE() << "accepted";
    } catch (const mink::InvalidInput& e) {
      EXPECT_EQ(r.error().message(), std::string(e.what()));
    }
  }
  // M is about [-1.5, 2.5] x [-1.25, 2.75] x [-1, 2]: the ball meets its faces z = -1 and
  // y = -1.25.
  mink::Pose<double> near;
  near.translation = V(0.5, 0.25, 0);
  const auto ok = local.tryUpdate(p, near, V(0, 0, 0), 1.5);
  ASSERT_TRUE(ok.ok()) << ok.error().message();
  EXPECT_EQ(ok.value(), &local.patch());
  const std::vector<std::array<int, 3>> triangles = ok.value()->triangles;
  const std::vector<V> vertices = ok.value()->vertices;
  EXPECT_GT(triangles.size(), 0u);
  const mink::MinkowskiPatch<double>& again = local.update(p, near, V(0, 0, 0), 1.5);
  EXPECT_EQ(again.triangles, triangles);
  EXPECT_EQ(again.vertices, vertices);
}

// The copies the pipeline works on far from unit scale: exact powers of two of the user's
// mesh, or an Error (never an abort in builds without exceptions) where the copy would not
// be a valid mesh — here, coordinates that overflow.
TEST(LocalMinkowskiSum, ScaledWorkingCopiesAreExactOrAnError) {
  const Mesh A = mesh(mink_test::lBlock());
  const auto down = mink::detail::scaledMesh(A, 40);
  ASSERT_TRUE(down.ok()) << down.error().message();
  ASSERT_EQ(down.value().numVertices(), A.numVertices());
  for (int v = 0; v < A.numVertices(); ++v) EXPECT_EQ(down.value().vertex(v), V(std::ldexp(1.0, -40) * A.vertex(v)));
  const auto over = mink::detail::scaledMesh(A, -1100);
  ASSERT_FALSE(over.ok());
  EXPECT_NE(over.error().message().find("non-finite"), std::string::npos) << over.error().message();
}

template <class T>
double patchArea(const MeshShape& a, const MeshShape& b, const V& tb, const V& c, double r) {
  const auto A = mink::TriangleMesh<T>::fromMesh(a.verticesAs<T>(), a.triangles);
  const auto B = mink::TriangleMesh<T>::fromMesh(b.verticesAs<T>(), b.triangles);
  mink::LocalMinkowskiSum<T> local(A, B);
  mink::Pose<T> poseA, poseB;
  poseB.translation = mink::Vec3<T>(T(tb[0]), T(tb[1]), T(tb[2]));
  const auto& P = local.update(poseA, poseB, mink::Vec3<T>(T(c[0]), T(c[1]), T(c[2])), T(r));
  return mink_test::measure(P).area;
}

TEST(LocalMinkowskiSum, FloatAndExactRationalsAgreeWithDouble) {
  // Dyadic data: the same numbers in every scalar type.
  const MeshShape a = mink_test::uBlock(), b = mink_test::boxShape(V(-0.5, -0.25, -0.75), V(0.5, 0.25, 0.75));
  const V tb(0.375, 0.0625, 0.25), c(1.5, 1.25, 0.5);
  const double ad = patchArea<double>(a, b, tb, c, 1.0);
  EXPECT_GT(ad, 0.0);
  EXPECT_NEAR(patchArea<float>(a, b, tb, c, 1.0), ad, 1e-5 * ad);
  EXPECT_NEAR(patchArea<CGAL::Gmpq>(a, b, tb, c, 1.0), ad, 1e-12 * ad);
}

}  // namespace
