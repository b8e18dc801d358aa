// tests/mdd/mdd_path_test.cpp — MddResult::path (mdd/mdd_types.hpp): which step of mdd()
// answered. Checked against the result's own independent flags on the degenerate contacts
// and their generic twins (tests/support/degenerate_contacts.hpp): usedFallback iff the
// exhaustive scan or the chord answered, a Grazing face iff the grazing step did, fromCache
// iff the cache did, None only without an answer; a repeated query with a cache is answered
// by it, a caller's visit cap of 0 by nothing.
#include <gtest/gtest.h>

#include <string>

#include "mink/mink.hpp"
#include "support/degenerate_contacts.hpp"

namespace {

using mink::MddPath;
using mink::MddStatus;

struct Pair {
  mink::ConvexPolyhedron<double> P, Q;
  mink::Pose<double> poseP, poseQ;
};

Pair build(const mink_test::ContactScene& sc) {
  Pair p{mink::ConvexPolyhedron<double>::fromPoints(sc.P), mink::ConvexPolyhedron<double>::fromPoints(sc.Q), {}, {}};
  p.poseQ.rotation = sc.rotQ;
  p.poseQ.translation = sc.tQ;
  return p;
}

TEST(MddPath, AgreesWithFallbackGrazingAndCacheFlags) {
  int searched = 0;
  for (const std::string& family : mink_test::degenerateFamilies()) {
    for (bool generic : {false, true}) {
      const mink_test::ContactScene sc = mink_test::degenerateScene(family, 12, generic);
      const Pair p = build(sc);
      for (std::size_t d = 0; d < sc.dirs.size(); ++d) {
        const std::string label = family + (generic ? " generic" : " degenerate") + " direction " + std::to_string(d);
        const auto r = mink::mdd(p.P, p.poseP, p.Q, p.poseQ, sc.dirs[d]);
        const bool fallback = r.path == MddPath::Exhaustive || r.path == MddPath::Chord;
        EXPECT_EQ(r.usedFallback, fallback) << label;
        EXPECT_EQ(r.faceType == mink::MddFaceType::Grazing, r.path == MddPath::Grazing) << label;
        EXPECT_FALSE(r.fromCache) << label;
        EXPECT_NE(r.path, MddPath::Cache) << label;
        if (r.status != MddStatus::NoContact && r.status != MddStatus::IterationLimit) {
          EXPECT_NE(r.path, MddPath::None) << label;
        }
        searched += r.path == MddPath::Search || r.path == MddPath::Certificate;
      }
    }
  }
  EXPECT_GT(searched, 0);
}

TEST(MddPath, RepeatedQueryIsAnsweredByTheCache) {
  // Boxes turned by the generic twin's rotation, Q above P: separated along -z, each exit
  // face a proper face of M.
  const mink_test::ContactScene sc = mink_test::degenerateScene("boxes-aligned", 4, true);
  const Pair p = build(sc);
  mink::MddCache<double> cache;
  const Eigen::Vector3d s(0.1, 0.2, -1.0);
  const auto first = mink::mdd(p.P, p.poseP, p.Q, p.poseQ, s, cache);
  ASSERT_NE(first.path, MddPath::None);
  EXPECT_NE(first.path, MddPath::Cache);
  const auto again = mink::mdd(p.P, p.poseP, p.Q, p.poseQ, s, cache);
  EXPECT_TRUE(again.fromCache);
  EXPECT_EQ(again.path, MddPath::Cache);
  EXPECT_EQ(again.parameter, first.parameter);
}

TEST(MddPath, CallersVisitCapLeavesNoPath) {
  const mink_test::ContactScene sc = mink_test::degenerateScene("cones-apex", 12, false);
  const Pair p = build(sc);
  mink::MddOptions<double> opt;
  opt.maxVisits = 0;
  const auto r = mink::mdd(p.P, p.poseP, p.Q, p.poseQ, sc.dirs[0], opt);
  ASSERT_EQ(r.status, MddStatus::IterationLimit);
  EXPECT_EQ(r.path, MddPath::None);
}

}  // namespace
