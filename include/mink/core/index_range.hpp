// mink/core/index_range.hpp — IndexRange: a read-only view of a contiguous run of ints,
// the row type of every compressed (CSR) adjacency list in mink (vertex rings of
// ConvexPolyhedron and TriangleMesh, face loops, ...).
#pragma once

namespace mink {

/// Read-only view of a contiguous run of ints (a CSR row).
class IndexRange {
 public:
  IndexRange(const int* b, const int* e) : begin_(b), end_(e) {}
  const int* begin() const { return begin_; }
  const int* end() const { return end_; }
  int size() const { return static_cast<int>(end_ - begin_); }
  int operator[](int i) const { return begin_[i]; }

 private:
  const int* begin_;
  const int* end_;
};

}  // namespace mink
