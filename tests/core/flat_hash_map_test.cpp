// tests/core/flat_hash_map_test.cpp — mink/core/detail/flat_hash_map.hpp against
// std::unordered_map / std::unordered_set: random insertions, look-ups and clears (packed
// index keys, which an identity hash would cluster), growth, and the table kept by clear().
#include "mink/core/detail/flat_hash_map.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <unordered_map>
#include <unordered_set>

namespace {

TEST(FlatHashMap, AgreesWithUnorderedMapAcrossClears) {
  std::mt19937_64 rng(7);
  mink::detail::FlatHashMap<std::uint64_t, int> flat;
  std::unordered_map<std::uint64_t, int> ref;
  for (int round = 0; round < 50; ++round) {
    flat.clear();
    ref.clear();
    const int n = static_cast<int>(rng() % 2000);
    for (int i = 0; i < n; ++i) {
      // Packed pairs of small indices, like the trimming's edge labels.
      const std::uint64_t key = ((rng() % 64) << 32) | (rng() % 64);
      switch (rng() % 3) {
        case 0: {
          const auto r = flat.emplace(key, i);
          const auto e = ref.emplace(key, i);
          ASSERT_EQ(r.second, e.second);
          ASSERT_EQ(r.first->second, e.first->second);
          break;
        }
        case 1:
          ++flat[key];
          ++ref[key];
          break;
        default: {
          const auto* f = flat.find(key);
          const auto it = ref.find(key);
          ASSERT_EQ(f == flat.end(), it == ref.end());
          if (f) {
            ASSERT_EQ(f->second, it->second);
          }
          ASSERT_EQ(flat.count(key), ref.count(key));
        }
      }
      ASSERT_EQ(flat.size(), ref.size());
    }
    for (const auto& [k, v] : ref) {
      const auto* f = flat.find(k);
      ASSERT_NE(f, flat.end());
      EXPECT_EQ(f->second, v);
    }
  }
}

TEST(FlatHashSet, InsertCountClear) {
  mink::detail::FlatHashSet<std::uint64_t> flat;
  std::unordered_set<std::uint64_t> ref;
  std::mt19937_64 rng(11);
  for (int round = 0; round < 20; ++round) {
    flat.clear();
    ref.clear();
    for (int i = 0; i < 500; ++i) {
      const std::uint64_t key = rng() % 300;
      EXPECT_EQ(flat.insert(key).second, ref.insert(key).second);
    }
    EXPECT_EQ(flat.size(), ref.size());
    for (std::uint64_t k = 0; k < 300; ++k) EXPECT_EQ(flat.count(k), ref.count(k));
  }
}

}  // namespace
