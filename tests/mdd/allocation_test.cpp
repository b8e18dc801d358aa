// tests/mdd/allocation_test.cpp — a warm mdd() / intersects() query allocates nothing, with
// the caller's cache and without one (the overloads' per-thread scratch cache).
// Counts every global operator new in this test executable while a flag is set.
#include <gtest/gtest.h>

#include <random>

#include "mink/mdd/first_contact.hpp"
#include "mink/mdd/mdd.hpp"
#include "support/allocation_counter.hpp"
#include "support/paper_shapes.hpp"

namespace {

TEST(MddAllocation, WarmQueriesDoNotAllocate) {
  if (!mink_test::kCountAllocations) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  std::mt19937 rng(3);
  const auto P = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(mink_test::PaperShape::P4, rng));
  const auto Q = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(mink_test::PaperShape::P6, rng));
  mink::MddCache<double> cache;
  std::vector<std::pair<mink::Pose<double>, Eigen::Vector3d>> queries;
  for (int i = 0; i < 300; ++i) {
    mink::Pose<double> pose;
    pose.rotation = mink_test::randomRotation(rng);
    pose.translation = mink_test::randomUnitVector(rng) * mink_test::uniformIn(rng, 0.5, 10.0);
    queries.push_back({pose, mink_test::randomUnitVector(rng)});
  }
  // Warm-up pass: sizes every buffer (and builds the hierarchies, if any).
  for (const auto& q : queries) {
    mink::mdd(P, mink::Pose<double>(), Q, q.first, q.second, cache);
    mink::intersects(P, mink::Pose<double>(), Q, q.first, cache);
  }
  // The counter sees allocations (so a zero below means something).
  ASSERT_TRUE(mink_test::allocationCounterWorks());
  int contacts = 0;
  const long allocations = mink_test::allocationsDuring([&] {
    for (const auto& q : queries) {
      const auto r = mink::mdd(P, mink::Pose<double>(), Q, q.first, q.second, cache);
      contacts += r.status != mink::MddStatus::NoContact;
      contacts += mink::intersects(P, mink::Pose<double>(), Q, q.first, cache);
    }
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(contacts, 0);
  // Without a cache: the same queries once more to size the scratch, then counted.
  for (const auto& q : queries) {
    mink::mdd(P, mink::Pose<double>(), Q, q.first, q.second);
    mink::intersects(P, mink::Pose<double>(), Q, q.first);
    mink::firstContact(P, mink::Pose<double>(), Q, q.first, q.second);
  }
  int contactsNoCache = 0;
  const long allocationsNoCache = mink_test::allocationsDuring([&] {
    for (const auto& q : queries) {
      const auto r = mink::mdd(P, mink::Pose<double>(), Q, q.first, q.second);
      contactsNoCache += r.status != mink::MddStatus::NoContact;
      contactsNoCache += mink::intersects(P, mink::Pose<double>(), Q, q.first);
      contactsNoCache += mink::firstContact(P, mink::Pose<double>(), Q, q.first, q.second).hit;
    }
  });
  EXPECT_EQ(allocationsNoCache, 0);
  EXPECT_GE(contactsNoCache, contacts);  // the same mdd and intersects answers, and the hits
}

}  // namespace
