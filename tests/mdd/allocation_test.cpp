// tests/mdd/allocation_test.cpp — a warm mdd() / intersects() query allocates nothing.
// Counts every global operator new in this test executable while a flag is set.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include "mink/mdd/mdd.hpp"
#include "support/paper_shapes.hpp"

// AddressSanitizer owns operator new/delete (replacing them there reports a mismatch), so
// the counting replacement, and this check, exist only in non-ASan builds.
#if defined(__SANITIZE_ADDRESS__)
#define MINK_COUNT_ALLOCATIONS 0
#else
#define MINK_COUNT_ALLOCATIONS 1
#endif

namespace {
std::atomic<bool> gCounting{false};
std::atomic<long> gAllocations{0};
}  // namespace

#if MINK_COUNT_ALLOCATIONS
// GCC 12 flags free() in a replacement operator delete as mismatched with operator new,
// although the replacement operator new allocates with malloc (the pair is consistent).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  if (gCounting.load(std::memory_order_relaxed)) gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif

namespace {

TEST(MddAllocation, WarmQueriesDoNotAllocate) {
  if (!MINK_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
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
  gAllocations = 0;
  gCounting = true;
  {
    void* (*volatile allocate)(std::size_t) = &::operator new;  // not elidable
    ::operator delete(allocate(8));
  }
  gCounting = false;
  ASSERT_EQ(gAllocations.load(), 1);
  gAllocations = 0;
  gCounting = true;
  int contacts = 0;
  for (const auto& q : queries) {
    const auto r = mink::mdd(P, mink::Pose<double>(), Q, q.first, q.second, cache);
    contacts += r.status != mink::MddStatus::NoContact;
    contacts += mink::intersects(P, mink::Pose<double>(), Q, q.first, cache);
  }
  gCounting = false;
  EXPECT_EQ(gAllocations.load(), 0);
  EXPECT_GT(contacts, 0);
}

}  // namespace
