// tests/mdd/epoch_marks_test.cpp — detail::EpochMarks (mdd/mdd_types.hpp): hashed marks
// that move to an array of epoch stamps once a pass marks more than an eighth of its ids.
// Reference: std::set, over passes of random sizes (fixed seed), before and after the move,
// with passes over fewer and over more ids than the array holds.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "mink/mdd/mdd_types.hpp"

TEST(EpochMarks, AgreesWithASetAcrossPassesAndTheMoveToAnArray) {
  std::mt19937 rng(16);
  mink::detail::EpochMarks marks;
  for (int pass = 0; pass < 200; ++pass) {
    const int ids = std::uniform_int_distribution<int>(1, pass < 100 ? 300 : 3000)(rng);
    // Some passes mark a few ids (hashed), some most of them (past the move).
    const int draws = std::uniform_int_distribution<int>(0, pass % 3 == 0 ? 2 * ids : 10)(rng);
    marks.reset(static_cast<std::size_t>(ids));
    std::set<int> seen;
    for (int k = 0; k < draws; ++k) {
      const int i = std::uniform_int_distribution<int>(0, ids - 1)(rng);
      ASSERT_EQ(marks.mark(i), seen.insert(i).second) << "seed 16, pass " << pass << ", draw " << k << ", id " << i;
    }
  }
}
