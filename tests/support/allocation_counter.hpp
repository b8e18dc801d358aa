// tests/support/allocation_counter.hpp — counts the global operator new calls a piece of
// code makes, for the "warm queries allocate nothing" tests. It *replaces* the global
// operator new / delete: include it in exactly one translation unit of a test executable.
//
// AddressSanitizer owns operator new/delete (replacing them there reports a mismatch), so
// under ASan nothing is replaced and kCountAllocations is false: such tests skip.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#define MINK_COUNT_ALLOCATIONS 0
#else
#define MINK_COUNT_ALLOCATIONS 1
#endif

namespace mink_test {

inline constexpr bool kCountAllocations = MINK_COUNT_ALLOCATIONS;
inline std::atomic<bool> gCountingAllocations{false};
inline std::atomic<long> gAllocations{0};

/// The number of operator new calls made while fn runs.
template <class Fn>
long allocationsDuring(Fn&& fn) {
  gAllocations = 0;
  gCountingAllocations = true;
  fn();
  gCountingAllocations = false;
  return gAllocations.load();
}

/// Self-check: the counter sees one deliberate allocation (so a zero elsewhere means
/// something).
inline bool allocationCounterWorks() {
  return allocationsDuring([] {
           void* (*volatile allocate)(std::size_t) = &::operator new;  // not elidable
           ::operator delete(allocate(8));
         }) == 1;
}

}  // namespace mink_test

#if MINK_COUNT_ALLOCATIONS
// GCC 12 flags free() in a replacement operator delete as mismatched with operator new,
// although the replacement operator new allocates with malloc (the pair is consistent).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  if (mink_test::gCountingAllocations.load(std::memory_order_relaxed))
    mink_test::gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif
