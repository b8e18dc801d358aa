// tests/cpd/allocation_test.cpp — a coherent CPD query in the steady state of a smooth
// motion allocates nothing (issue 15): the same motion is run twice from reset(), the
// first pass sizes every buffer (patch, trimming tables, Phong surface), and the second
// must not call operator new at all. Counts every global operator new in this test
// executable while a flag is set (tests/support/allocation_counter.hpp; skipped under
// AddressSanitizer, which owns operator new).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "mink/cpd/continuous_penetration_depth.hpp"
#include "support/allocation_counter.hpp"
#include "support/mesh_shapes.hpp"

namespace {

using V = Eigen::Vector3d;

struct Motion {
  std::string name;
  mink_test::MeshShape a, b;
  V from, to;
};

TEST(CpdAllocation, CoherentQueriesOfASmoothMotionDoNotAllocate) {
  if (!mink_test::kCountAllocations) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  const Eigen::Matrix3d G = Eigen::AngleAxisd(0.3, V(1, 2, 3).normalized()).toRotationMatrix();
  const std::vector<Motion> motions = {
      // Along an arm of the L, past its reflex edge (the query benchmark's L-block/box).
      {"L-block/box", mink_test::lBlock(), mink_test::boxShape(V(-0.3, -0.3, -0.75), V(0.3, 0.3, 0.75)),
       V(1.4, 0.4, 0.5), V(0.4, 1.4, 0.5)},
      // Radially across the tube of a torus (the query benchmark's torus/box), where the
      // trimming often falls back to its exact side test: 890,415 allocations in these 60
      // queries while an expansion was a std::vector, none since it keeps its components
      // inline (core/expansion.hpp).
      {"torus/box", mink_test::torus(12, 8), mink_test::boxShape(V(-0.4, -0.3, -0.5), V(0.4, 0.3, 0.5)),
       V(1.75, 0.1, 0.05), V(2.25, 0.1, 0.05)}};
  ASSERT_TRUE(mink_test::allocationCounterWorks());
  for (const Motion& m : motions) {
    SCOPED_TRACE(m.name);
    const auto A = mink::TriangleMesh<double>::fromMesh(m.a.verticesAs<double>(), m.a.triangles);
    const auto B = mink::TriangleMesh<double>::fromMesh(m.b.verticesAs<double>(), m.b.triangles);
    mink::ContinuousPenetrationDepth<double> cpd(A, B);
    const mink::Pose<double> poseA;
    std::vector<mink::Pose<double>> poses(60);
    for (std::size_t f = 0; f < poses.size(); ++f) {
      poses[f].rotation = G;
      poses[f].translation = m.from + (m.to - m.from) * (double(f) / (poses.size() - 1));
    }
    int penetrating = 0;
    auto pass = [&] {
      cpd.reset();
      for (const auto& pb : poses) penetrating += cpd.query(poseA, pb).status == mink::CpdStatus::Penetrating;
    };
    pass();  // sizes every buffer
    const long allocations = mink_test::allocationsDuring(pass);
    EXPECT_EQ(allocations, 0);
    EXPECT_GT(penetrating, 0);
  }
}

}  // namespace
