// mink/core/detail/flat_hash_map.hpp — an open-addressing hash map for scratch tables that
// are rebuilt on every call (the CPD trimming's corner and edge indices, the local sum's
// seen pairs): clear() is O(1) (a generation counter) and keeps the slots, so a table that
// has once reached its working size allocates nothing again — a coherent CPD query in the
// steady state of a smooth motion allocates nothing (issue 15). std::unordered_map
// allocates a node per insertion, every call.
//
// Linear probing over a power-of-two table at most half full; keys are hashed by Hash and
// then mixed (splitmix64's finaliser), so identity hashes of packed indices do not cluster.
// The subset of std::unordered_map's interface the callers use: find / end (an entry
// pointer, nullptr at the end; `it->second`), emplace, operator[], count, clear, size.
// No erase. FlatHashSet: insert / count / clear / size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace mink {
namespace detail {

template <class K, class V, class Hash = std::hash<K>>
class FlatHashMap {
 public:
  struct Entry {
    K first{};
    V second{};
  };

  Entry* find(const K& key) { return const_cast<Entry*>(static_cast<const FlatHashMap*>(this)->find(key)); }
  const Entry* find(const K& key) const {
    if (size_ == 0) return nullptr;
    for (std::size_t i = home(key);; i = (i + 1) & mask()) {
      const Slot& s = slots_[i];
      if (s.gen != gen_) return nullptr;
      if (s.entry.first == key) return &s.entry;
    }
  }
  Entry* end() const { return nullptr; }

  /// Inserts (key, value) if key is absent; the entry, and whether it was inserted.
  std::pair<Entry*, bool> emplace(const K& key, const V& value) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    for (std::size_t i = home(key);; i = (i + 1) & mask()) {
      Slot& s = slots_[i];
      if (s.gen != gen_) {
        s.gen = gen_;
        s.entry.first = key;
        s.entry.second = value;
        ++size_;
        return {&s.entry, true};
      }
      if (s.entry.first == key) return {&s.entry, false};
    }
  }
  V& operator[](const K& key) { return emplace(key, V{}).first->second; }
  std::size_t count(const K& key) const { return find(key) ? 1 : 0; }
  std::size_t size() const { return size_; }

  /// Forgets every entry; keeps the table.
  void clear() {
    size_ = 0;
    if (++gen_ == 0) {  // the counter wrapped: mark every slot free for real
      for (Slot& s : slots_) s.gen = 0;
      gen_ = 1;
    }
  }

 private:
  struct Slot {
    std::uint32_t gen = 0;  // occupied iff gen == gen_
    Entry entry;
  };

  std::size_t mask() const { return slots_.size() - 1; }
  std::size_t home(const K& key) const {
    std::uint64_t z = static_cast<std::uint64_t>(Hash{}(key)) + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<std::size_t>(z) & mask();
  }
  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(old.empty() ? 16 : 2 * old.size(), Slot{});
    const std::uint32_t oldGen = gen_;
    gen_ = 1;
    size_ = 0;
    for (const Slot& s : old)
      if (s.gen == oldGen) emplace(s.entry.first, s.entry.second);
  }

  std::vector<Slot> slots_;
  std::uint32_t gen_ = 1;
  std::size_t size_ = 0;
};

template <class K, class Hash = std::hash<K>>
class FlatHashSet {
 public:
  /// Inserts key if absent; .second says whether it was.
  std::pair<const K*, bool> insert(const K& key) {
    const auto r = map_.emplace(key, char(0));
    return {&r.first->first, r.second};
  }
  std::size_t count(const K& key) const { return map_.count(key); }
  std::size_t size() const { return map_.size(); }
  void clear() { map_.clear(); }

 private:
  FlatHashMap<K, char, Hash> map_;
};

}  // namespace detail
}  // namespace mink
