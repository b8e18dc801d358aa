// Tests of mink/mesh/mesh_overlap.hpp:
//   - random poses of pairs of procedural and shipped meshes against FCL's mesh BVH
//     (fcl::BVHModel<OBBRSSd> + fcl::collide), and many translations y per pose. FCL
//     tests boundaries only, so poses where mink reports one solid inside the other are
//     checked instead against CGAL's exact Side_of_triangle_mesh (the witness vertex is
//     inside). Where FCL and mink disagree otherwise, the exact brute force (CGAL
//     do_intersect with exact predicates, every triangle pair, on the very numbers mink
//     used) decides: mink must agree with it, and the pose must be near touching
//     (FCL's distance below 1e-6 of the scene), the one stated reason to exclude it;
//   - containment and exact touching by hand: a box in a torus's tube, a box in a cube,
//     boxes in and beside the hole of the cube with a hole, two components, faces in
//     exact contact and one ulp apart;
//   - no allocation in warm queries; pose validation.
// Half of the random poses re-place one object (its box tree of B refit, not rebuilt).
#include "mink/mesh/mesh_overlap.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mink/io/triangle_mesh_io.hpp"
#include "support/allocation_counter.hpp"
#include "support/cgal_mesh.hpp"
#include "support/expect_rejected.hpp"
#include "support/fcl_mesh.hpp"
#include "support/mesh_shapes.hpp"
#include "support/paper_shapes.hpp"

namespace {

using Mesh = mink::TriangleMesh<double>;
using V = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
using mink::OverlapStatus;

Mesh fromShape(const mink_test::MeshShape& s) { return Mesh::fromMesh(s.verticesAs<double>(), s.triangles); }
// The shape scaled by a power of two (exactly).
Mesh scaled(const mink_test::MeshShape& s, double factor) {
  std::vector<mink::Vec3<double>> v = s.verticesAs<double>();
  for (auto& p : v) p *= factor;
  return Mesh::fromMesh(v, s.triangles);
}
Mesh shipped(const std::string& f) { return mink::io::readTriangleMesh<double>(std::string(MINK_TEST_DATA_DIR) + "/" + f); }

using mink_test::bruteForceBoundariesMeet;
using mink_test::FclPair;

using mink_test::randomRotation;

// ---- random poses against FCL ------------------------------------------------------

struct Tally {
  int overlapping = 0, separate = 0, contained = 0, fclTolerance = 0, failures = 0;
};

// One query: mink's answer against FCL (or, for containment, CGAL's point location), the
// exact brute force deciding any disagreement.
void checkQuery(mink::MeshOverlap<double>& o, FclPair& fcl, const mink_test::CgalPointLocation& inA,
                const mink_test::CgalPointLocation& inB, const V& y, const std::string& id, Tally& tally) {
  const bool ours = o.overlaps(y);
  const mink::OverlapResult r = o.result();
  const Mesh &A = o.meshA(), &B = o.meshB();
  std::vector<V> placed(B.vertices().size());
  for (std::size_t v = 0; v < placed.size(); ++v) placed[v] = o.placedVertexB(static_cast<int>(v));
  if (r.status == OverlapStatus::BInsideA || r.status == OverlapStatus::AInsideB) {
    ++tally.contained;
    // Independent check of the witness: CGAL's location of the vertex in the other solid
    // (A in B + y: moved back into B's frame, in double: a far-from-boundary witness).
    const bool ok = (r.status == OverlapStatus::BInsideA
                         ? inA(placed[r.vertex])
                         : inB(o.rotation().transpose() * (A.vertex(r.vertex) - o.translation() - y))) ==
                    mink::PointLocation::Inside;
    if (!ok && tally.failures++ < 5) ADD_FAILURE() << id << ": containment witness " << r.vertex << " not confirmed";
    return;
  }
  if (r.status == OverlapStatus::Undecided && tally.failures++ < 5) ADD_FAILURE() << id << ": Undecided";
  (ours ? tally.overlapping : tally.separate)++;
  const bool theirs = fcl.collide(o.rotation(), V(o.translation() + y));
  if (theirs == ours) return;
  const bool exact = bruteForceBoundariesMeet(A, placed, B);
  const double gap = fcl.distance(o.rotation(), V(o.translation() + y));
  const double scene = A.extent() + B.extent() + (o.translation() + y).cwiseAbs().sum();
  if (exact == ours && std::abs(gap) <= 1e-6 * scene) {
    ++tally.fclTolerance;  // FCL's own tolerance near touching: excluded, counted
    return;
  }
  if (tally.failures++ < 5)
    ADD_FAILURE() << id << ": mink " << ours << " (status " << static_cast<int>(r.status) << "), FCL " << theirs
                  << ", exact brute force " << exact << ", FCL distance " << gap;
}

struct PairCase {
  std::string name;
  Mesh A, B;
  int poses;
};

void runPairs(const std::vector<PairCase>& cases, unsigned seed, int ysPerPose) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const PairCase& c : cases) {
    SCOPED_TRACE(c.name);
    FclPair fcl(c.A, c.B);
    const mink_test::CgalPointLocation insideA(c.A), insideB(c.B);
    const auto& ta = c.A.sphereTree();
    const auto& tb = c.B.sphereTree();
    const double ra = ta.radius(0), rb = tb.radius(0);
    Tally tally;
    // Odd poses re-place one object made at the first pose (B's box tree then keeps the
    // split of that pose and is only refit); even poses make a new object.
    std::unique_ptr<mink::MeshOverlap<double>> kept;
    for (int i = 0; i < c.poses; ++i) {
      const M3 R = randomRotation(rng);
      // B's root centre placed at a random distance from A's: from deep inside to apart.
      const V t = ta.centre(0) - R * tb.centre(0) + mink_test::randomUnitVector(rng) * (ra + rb) * (0.05 + 1.1 * u(rng));
      mink::MeshOverlap<double> fresh(c.A, c.B, R, t);
      if (!kept) kept = std::make_unique<mink::MeshOverlap<double>>(c.A, c.B, R, t);
      if (i % 2 == 1) kept->setPlacement(R, t);
      mink::MeshOverlap<double>& o = i % 2 == 1 ? *kept : fresh;
      const std::string id = "seed " + std::to_string(seed) + " " + c.name + " pose " + std::to_string(i);
      checkQuery(o, fcl, insideA, insideB, V::Zero(), id, tally);
      for (int k = 0; k < ysPerPose; ++k)
        checkQuery(o, fcl, insideA, insideB, mink_test::randomUnitVector(rng) * 0.3 * (ra + rb) * u(rng), id + " y " + std::to_string(k),
                   tally);
    }
    std::printf("    %-28s overlap %4d, separate %4d, contained %3d, excluded (FCL tolerance near touching) %d\n",
                c.name.c_str(), tally.overlapping, tally.separate, tally.contained, tally.fclTolerance);
    EXPECT_EQ(tally.failures, 0);
    EXPECT_GT(tally.overlapping, 0);
    EXPECT_GT(tally.separate, 0);
    EXPECT_LE(tally.fclTolerance, (c.poses * (1 + ysPerPose)) / 50);
  }
}

TEST(MeshOverlap, ProceduralPairsAgainstFcl) {
#ifdef MINK_SANITIZE_BUILD
  const int poses = 20;
#else
  const int poses = 150;
#endif
  using namespace mink_test;
  runPairs({{"torus 12x8 / L-block", fromShape(torus(12, 8)), fromShape(lBlock()), poses},
            {"star prism / U-block", fromShape(starPrism()), fromShape(uBlock()), poses},
            {"axes / cup", fromShape(axes()), fromShape(cup()), poses},
            {"spoon / cup", fromShape(spoon()), fromShape(cup()), poses},
            {"cube with hole / cone", fromShape(cubeWithHole()), fromShape(cone()), poses},
            {"torus 24x12 / torus 12x8", fromShape(torus(24, 12)), fromShape(torus(12, 8)), poses}},
           5101u, 4);
}

TEST(MeshOverlap, ShippedPairsAgainstFcl) {
#ifdef MINK_SANITIZE_BUILD
  const int poses = 4;
#else
  const int poses = 40;
#endif
  runPairs({{"duck / torus.obj", shipped("duck.obj"), shipped("torus.obj"), poses},
            {"bunny / concave_box", shipped("bunny.obj"), shipped("concave_box.obj"), poses},
            {"shape_sorter / star prism", shipped("shape_sorter.obj"), scaled(mink_test::starPrism(), 1.0 / 128), poses}},
           5102u, 2);
}

// ---- containment and exact contact by hand -------------------------------------------

Mesh boxAt(const V& centre, double half) {
  return fromShape(mink_test::boxShape(centre - V(half, half, half), centre + V(half, half, half)));
}

OverlapStatus status(const Mesh& A, const Mesh& B, const M3& R = M3::Identity(), const V& t = V::Zero(),
                     const V& y = V::Zero()) {
  mink::MeshOverlap<double> o(A, B, R, t);
  o.overlaps(y);
  return o.result().status;
}

TEST(MeshOverlap, ContainmentByHand) {
  const Mesh torus = fromShape(mink_test::torus(12, 8));  // R = 2, r = 0.75: the tube holds x in (1.3, 2.7)
  const Mesh small = boxAt(V::Zero(), 0.1);
  std::mt19937 rng(5103u);
  EXPECT_EQ(status(torus, small, randomRotation(rng), V(2, 0, 0)), OverlapStatus::BInsideA);
  EXPECT_EQ(status(small, torus, M3::Identity(), V(-2, 0, 0)), OverlapStatus::AInsideB);
  EXPECT_EQ(status(torus, small, M3::Identity(), V(0, 0, 0)), OverlapStatus::Separate);  // in the hole
  EXPECT_EQ(status(torus, small, M3::Identity(), V(0, 2, 0.3)), OverlapStatus::BInsideA);
  // A box in a cube, turned; and the other way round.
  const Mesh cube = fromShape(mink_test::boxShape(V(-3, -3, -3), V(3, 3, 3)));
  const Mesh unit = boxAt(V::Zero(), 1);
  for (int i = 0; i < 10; ++i) {
    const M3 R = randomRotation(rng);
    EXPECT_EQ(status(cube, unit, R, V(0.5, -0.25, 0.125)), OverlapStatus::BInsideA) << i;
    EXPECT_EQ(status(unit, cube, R, V(0.5, -0.25, 0.125)), OverlapStatus::AInsideB) << i;
  }
  // The cube with a hole: a box in its hole is apart; in its wall, inside; across the
  // hole's wall, the boundaries meet.
  const Mesh holed = fromShape(mink_test::cubeWithHole());
  const Mesh quarter = boxAt(V::Zero(), 0.25);
  EXPECT_EQ(status(holed, quarter, M3::Identity(), V(1.5, 1.5, 1.5)), OverlapStatus::Separate);
  EXPECT_EQ(status(holed, quarter, M3::Identity(), V(0.5, 0.5, 1.5)), OverlapStatus::BInsideA);
  EXPECT_EQ(status(holed, quarter, M3::Identity(), V(1.0, 1.5, 1.5)), OverlapStatus::BoundariesMeet);
  // Two components in B: one far away, one inside A.
  auto a = mink_test::boxShape(V(10, 10, 10), V(11, 11, 11)), b = mink_test::boxShape(V(-1, -1, -1), V(1, 1, 1));
  std::vector<mink::Vec3<double>> verts = a.verticesAs<double>();
  std::vector<std::array<int, 3>> tris = a.triangles;
  for (const auto& p : b.verticesAs<double>()) verts.push_back(p);
  for (auto t : b.triangles) tris.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  const Mesh two = Mesh::fromMesh(verts, tris);
  mink::MeshOverlap<double> o(cube, two, M3::Identity(), V::Zero());
  EXPECT_TRUE(o.overlaps());
  EXPECT_EQ(o.result().status, OverlapStatus::BInsideA);
  EXPECT_GE(o.result().vertex, 8);
  EXPECT_FALSE(o.overlaps(V(20, 0, 0)));
}

TEST(MeshOverlap, ExactContactByHand) {
  const Mesh L = fromShape(mink_test::lBlock());
  const Mesh box = fromShape(mink_test::boxShape(V(0, 0, 0), V(1, 1, 1)));
  const double ulp = std::nextafter(2.0, 3.0) - 2.0;
  mink::MeshOverlap<double> o(L, box, M3::Identity(), V(2, 0, 0));  // face x = 2 against x = 2
  EXPECT_TRUE(o.overlaps());
  EXPECT_EQ(o.result().status, OverlapStatus::BoundariesMeet);
  EXPECT_FALSE(o.overlaps(V(ulp, 0, 0)));                  // one ulp apart
  EXPECT_TRUE(o.overlaps(V(-ulp, 0, 0)));                  // one ulp into it
  EXPECT_TRUE(o.overlaps(V(0, 1, 0)));                     // edge on edge at (2, 1)
  EXPECT_FALSE(o.overlaps(V(0, 1 + 1e-15, 0)));
  EXPECT_TRUE(o.overlaps(V(-1, 1, 0)));                    // into the inner corner: faces touch
  EXPECT_TRUE(o.overlaps(V(-1, 1, 1)));                    // corner on the top face's edge
  EXPECT_FALSE(o.overlaps(V(-1 + 1e-15, 1 + 1e-15, 0)));  // just clear of the inner corner
  EXPECT_TRUE(o.overlaps(V(-2, 0, 0)));                    // the same place as the L's first cube
}

TEST(MeshOverlap, PosesAndFreeFunction) {
  const Mesh torus = fromShape(mink_test::torus(12, 8));
  const Mesh L = fromShape(mink_test::lBlock());
  std::mt19937 rng(5104u);
  FclPair fcl(torus, L);
  int agree = 0;
  for (int i = 0; i < 100; ++i) {
    mink::Pose<double> pa, pb;
    pa.rotation = randomRotation(rng);
    pa.translation = mink_test::randomUnitVector(rng);
    pb.rotation = randomRotation(rng);
    pb.translation = pa.translation + mink_test::randomUnitVector(rng) * 3.5 * std::uniform_real_distribution<double>(0, 1)(rng);
    const bool ours = mink::meshesOverlap(torus, pa, L, pb);
    mink::MeshOverlap<double> o(torus, pa, L, pb);
    EXPECT_EQ(o.overlaps(), ours);
    agree += ours == fcl.collide(pa.rotation.transpose() * pb.rotation,
                                 pa.rotation.transpose() * (pb.translation - pa.translation));
  }
  EXPECT_GE(agree, 99);  // near-touching poses aside (covered by the tests above)
  mink::Pose<double> bad;
  bad.rotation(0, 1) = 0.1;
  mink_test::expectRejected([&] { (void)mink::meshesOverlap(torus, bad, L, mink::Pose<double>()); },
                            {"MeshOverlap", "poseA", "not orthonormal"}, "skewed pose");
  mink::Pose<double> mirror;
  mirror.rotation(2, 2) = -1;
  mink_test::expectRejected([&] { (void)mink::meshesOverlap(torus, mink::Pose<double>(), L, mirror); },
                            {"poseB", "reflection"}, "mirror");
  // tryMeshesOverlap: the same messages as Errors, and the same answer on good poses.
  for (const auto& [pa, pb] : {std::pair{bad, mink::Pose<double>()}, std::pair{mink::Pose<double>(), mirror}}) {
    const mink::Result<bool> r = mink::tryMeshesOverlap(torus, pa, L, pb);
    ASSERT_FALSE(r.ok());
    try {
      (void)mink::meshesOverlap(torus, pa, L, pb);
      ADD_FAILURE() << "accepted";
    } catch (const mink::InvalidInput& e) {
      EXPECT_EQ(r.error().message(), std::string(e.what()));
    }
  }
  const mink::Result<bool> good = mink::tryMeshesOverlap(torus, mink::Pose<double>(), L, mink::Pose<double>());
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(good.value(), mink::meshesOverlap(torus, mink::Pose<double>(), L, mink::Pose<double>()));
}

// trySetPlacement: a rejected placement is an Error with the message setPlacement throws,
// and B stays where it was; a good one places B as a new MeshOverlap would.
TEST(MeshOverlap, TrySetPlacement) {
  const Mesh torus = fromShape(mink_test::torus(12, 8));
  const Mesh L = fromShape(mink_test::lBlock());
  const V start(0.5, 0.25, 0);
  mink::MeshOverlap<double> o(torus, L, M3::Identity(), start);
  const bool before = o.overlaps();
  M3 skew = M3::Identity();
  skew(0, 1) = 0.1;
  const std::pair<M3, V> bad[] = {{skew, V::Zero()},
                                  {M3::Identity(), V(0, std::numeric_limits<double>::quiet_NaN(), 0)},
                                  {-M3::Identity(), V::Zero()}};
  for (const auto& [R, t] : bad) {
    const mink::Error e = o.trySetPlacement(R, t);
    ASSERT_TRUE(e);
    try {
      o.setPlacement(R, t);
      ADD_FAILURE() << "accepted";
    } catch (const mink::InvalidInput& x) {
      EXPECT_EQ(e.message(), std::string(x.what()));
    }
    EXPECT_EQ(o.translation(), start);
    EXPECT_EQ(o.overlaps(), before);
  }
  std::mt19937 rng(5106u);
  for (int i = 0; i < 20; ++i) {
    const M3 R = randomRotation(rng);
    const V t = mink_test::randomUnitVector(rng) * 3.0 * std::uniform_real_distribution<double>(0, 1)(rng);
    EXPECT_FALSE(o.trySetPlacement(R, t));
    EXPECT_EQ(o.overlaps(), mink::MeshOverlap<double>(torus, L, R, t).overlaps()) << "pose " << i;
  }
}

// focusNear: the queries whose y lies within reach of the centre test only the pairs the
// focus gathered; their answers (and statuses) must be those of the traversal, which an
// unfocused object at the same placement gives, and the boundary answers those of the
// exact brute force. Centres at touching placements (bisection along random directions),
// y all over the focus's cube, on its corners, and just beyond it (traversal again).
TEST(MeshOverlap, FocusedQueriesAnswerAsTheTraversal) {
  std::mt19937 rng(4242u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::vector<std::pair<Mesh, Mesh>> pairs = {{fromShape(mink_test::torus(12, 8)), fromShape(mink_test::lBlock())},
                                                    {fromShape(mink_test::torus(16, 12)), fromShape(mink_test::torus(12, 8))},
                                                    {fromShape(mink_test::lBlock()), fromShape(mink_test::uBlock())}};
  int focused = 0, traversed = 0, overlapping = 0, separate = 0;
  for (const auto& [A, B] : pairs) {
    for (int pose = 0; pose < 6; ++pose) {
      const M3 R = randomRotation(rng);
      const V t(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng));
      mink::MeshOverlap<double> o(A, B, R, t), plain(A, B, R, t);
      // The touching translation along a random direction (B pushed out of A).
      const V d = mink_test::randomUnitVector(rng);
      double lo = 0.0, hi = 4.0 * (A.extent() + B.extent());
      for (int k = 0; k < 40; ++k) ((plain.overlaps(V((lo + hi) / 2 * d)) ? lo : hi) = (lo + hi) / 2);
      const V c = hi * d;
      const double reach = 0.02 * (A.extent() + B.extent()) * (1 + pose % 3);
      long long gathered = 0, plainNear = 0;
      o.focusNear(c, reach, 0.0, [&](int, int) { ++gathered; });
      plain.forNearTrianglePairs(c, reach, [&](int, int) { ++plainNear; });
      EXPECT_GE(gathered, plainNear);  // at least the pairs within reach
      std::vector<V> ys;
      for (int k = 0; k < 60; ++k) ys.push_back(c + reach * V(u(rng), u(rng), u(rng)));
      for (int k = 0; k < 8; ++k) ys.push_back(c + reach * V(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
      for (int k = 0; k < 10; ++k) ys.push_back(c + reach * (1 + 1e-3 * (k + 1)) * mink_test::randomUnitVector(rng).cwiseSign());
      for (const V& y : ys) {
        const bool inside = (y - c).cwiseAbs().maxCoeff() <= reach;
        const bool ours = o.overlaps(y);
        const mink::OverlapResult r = o.result();
        const bool theirs = plain.overlaps(y);
        ASSERT_EQ(ours, theirs) << "pose " << pose << " y " << y.transpose();
        ASSERT_EQ(r.status == OverlapStatus::BoundariesMeet, plain.result().status == OverlapStatus::BoundariesMeet);
        if (A.numTriangles() * B.numTriangles() <= 10000) {  // the brute force on the smaller pairs
          std::vector<V> placed(B.vertices().size());
          for (std::size_t v = 0; v < placed.size(); ++v) placed[v] = o.placedVertexB(static_cast<int>(v));
          ASSERT_EQ(r.status == OverlapStatus::BoundariesMeet, bruteForceBoundariesMeet(A, placed, B));
        }
        // The focus answered inside (its pair count as node pairs), the traversal outside.
        if (inside && r.status != OverlapStatus::BoundariesMeet) {
          EXPECT_EQ(r.nodePairs, gathered);
          ++focused;
        }
        if (!inside) ++traversed;
        (ours ? overlapping : separate)++;
      }
      // A new placement forgets the focus.
      o.setPlacement(R, t);
      EXPECT_EQ(o.overlaps(c), plain.overlaps(c));
      EXPECT_EQ(o.result().nodePairs, plain.result().nodePairs);
    }
  }
  // A ball holding more than kMaxFocusPairs pairs keeps no focus: its queries traverse.
  {
    const Mesh& A = pairs[1].first;
    const Mesh& B = pairs[1].second;
    ASSERT_GT(static_cast<std::size_t>(A.numTriangles() * B.numTriangles()), mink::MeshOverlap<double>::kMaxFocusPairs);
    const M3 R = randomRotation(rng);
    mink::MeshOverlap<double> o(A, B, R, V::Zero()), plain(A, B, R, V::Zero());
    const double reach = 10.0 * (A.extent() + B.extent());
    long long gathered = 0;
    o.focusNear(V::Zero(), reach, 0.0, [&](int, int) { ++gathered; });
    EXPECT_EQ(gathered, static_cast<long long>(A.numTriangles()) * B.numTriangles());  // every pair is near
    for (int k = 0; k < 20; ++k) {
      const V y = 0.5 * (A.extent() + B.extent()) * V(u(rng), u(rng), u(rng));
      ASSERT_EQ(o.overlaps(y), plain.overlaps(y));
      EXPECT_EQ(o.result().nodePairs, plain.result().nodePairs);  // the traversal answered
    }
  }
  EXPECT_GT(focused, 500);
  EXPECT_GT(traversed, 100);
  EXPECT_GT(overlapping, 200);  // near touching: both answers, many times
  EXPECT_GT(separate, 200);
}

TEST(MeshOverlap, WarmQueriesDoNotAllocate) {
  if (!mink_test::kCountAllocations) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  const Mesh torus = fromShape(mink_test::torus(12, 8));
  const Mesh L = fromShape(mink_test::lBlock());
  std::mt19937 rng(5105u);
  mink::MeshOverlap<double> o(torus, L, randomRotation(rng), V(0.3, 0.1, -0.2));
  std::vector<V> ys;
  for (int i = 0; i < 500; ++i) ys.push_back(mink_test::randomUnitVector(rng) * 4.0 * std::uniform_real_distribution<double>(0, 1)(rng));
  int hits = 0;
  for (const V& y : ys) hits += o.overlaps(y);  // warm-up
  ASSERT_TRUE(mink_test::allocationCounterWorks());
  const M3 R = randomRotation(rng);
  int again = 0;
  const long allocations = mink_test::allocationsDuring([&] {
    for (const V& y : ys) again += o.overlaps(y);
    o.setPlacement(R, V(0.1, 0.2, 0.3));
    for (const V& y : ys) again += o.overlaps(y);
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(hits, 0);
  EXPECT_LT(hits, 500);
  EXPECT_GT(again, hits);
}

}  // namespace
