// mink/mesh/detail/box_tree.hpp — a static tree of axis-aligned boxes (in double): the
// triangle pairs of two placed meshes whose boxes overlap (MeshOverlap), and the searches
// CPD's trimming makes among the convolution facets gathered in a ball (the facets whose
// boxes overlap a box: candidate cutters; a lower bound on the distance from a point to
// every facet but a few: how far a point may be moved without crossing one). A search
// structure only: every decision it feeds is made exactly elsewhere, and it may return
// more candidates than needed, never fewer.
//
// Built top-down: boxes sorted by their centres along the longest axis of their union and
// split at the median; leaves hold up to kLeafSize boxes. Flat arrays, reused between
// builds (no allocation once warm).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace mink {
namespace detail {

struct Box3 {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  void add(const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void add(const Box3& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  bool overlaps(const Box3& b) const {
    return lo[0] <= b.hi[0] && b.lo[0] <= hi[0] && lo[1] <= b.hi[1] && b.lo[1] <= hi[1] && lo[2] <= b.hi[2] &&
           b.lo[2] <= hi[2];
  }
  /// Squared distance from p to the box (0 inside).
  double squaredDistance(const Eigen::Vector3d& p) const {
    double d = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double e = std::max({lo[i] - p[i], 0.0, p[i] - hi[i]});
      d += e * e;
    }
    return d;
  }
};

class BoxTree {
 public:
  static constexpr int kLeafSize = 4;

  /// Builds over boxes[0 .. n) (copied: the tree may outlive or be copied away from
  /// them); item i is boxes[i].
  void build(const std::vector<Box3>& boxes) {
    boxes_.assign(boxes.begin(), boxes.end());
    items_.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) items_[i] = static_cast<int>(i);
    nodes_.clear();
    if (!boxes.empty()) buildNode(0, static_cast<int>(boxes.size()));
  }

  /// Items that build() was given (refit() needs as many).
  std::size_t size() const { return boxes_.size(); }

  /// The same tree over new boxes (same count and items as the last build()): every node's
  /// box recomputed bottom-up from its items', the split kept. O(n), no allocation. For a
  /// rigidly moved set of boxes the tree stays a valid (if looser) search structure: its
  /// answers are the same as a rebuilt tree's, only the work to reach them differs.
  void refit(const std::vector<Box3>& boxes) {
    std::copy(boxes.begin(), boxes.end(), boxes_.begin());
    // Children are created after their parent (buildNode), so a reverse sweep sees them first.
    for (std::size_t id = nodes_.size(); id-- > 0;) {
      Node& n = nodes_[id];
      Box3 box;
      if (n.count > 0) {
        for (int k = n.first; k < n.first + n.count; ++k)
          box.add(boxes_[static_cast<std::size_t>(items_[static_cast<std::size_t>(k)])]);
      } else {
        box = nodes_[static_cast<std::size_t>(n.left)].box;
        box.add(nodes_[static_cast<std::size_t>(n.right)].box);
      }
      n.box = box;
    }
  }

  /// Calls visit(i) for every item whose box overlaps `query`.
  template <class Visit>
  void forOverlapping(const Box3& query, Visit&& visit) const {
    if (nodes_.empty()) return;
    stack_.clear();
    stack_.push_back(0);
    while (!stack_.empty()) {
      const Node& n = nodes_[static_cast<std::size_t>(stack_.back())];
      stack_.pop_back();
      if (!n.box.overlaps(query)) continue;
      if (n.count > 0) {
        for (int k = n.first; k < n.first + n.count; ++k)
          if (boxes_[static_cast<std::size_t>(items_[static_cast<std::size_t>(k)])].overlaps(query))
            visit(items_[static_cast<std::size_t>(k)]);
      } else {
        stack_.push_back(n.left);
        stack_.push_back(n.right);
      }
    }
  }

  /// The least of dist(i) over items whose box is nearer p than the best so far
  /// (dist(i) returns a squared distance, or +inf to skip the item), starting from
  /// `bound` (a squared distance): items farther than it are never asked.
  template <class Dist>
  double nearest(const Eigen::Vector3d& p, double bound, Dist&& dist) const {
    if (nodes_.empty()) return bound;
    stack_.clear();
    stack_.push_back(0);
    double best = bound;
    while (!stack_.empty()) {
      const Node& n = nodes_[static_cast<std::size_t>(stack_.back())];
      stack_.pop_back();
      if (n.box.squaredDistance(p) >= best) continue;
      if (n.count > 0) {
        for (int k = n.first; k < n.first + n.count; ++k) {
          const int i = items_[static_cast<std::size_t>(k)];
          if (boxes_[static_cast<std::size_t>(i)].squaredDistance(p) >= best) continue;
          best = std::min(best, dist(i));
        }
      } else {
        // Nearer child last, so that it is searched first.
        const Node& l = nodes_[static_cast<std::size_t>(n.left)];
        const Node& r = nodes_[static_cast<std::size_t>(n.right)];
        if (l.box.squaredDistance(p) < r.box.squaredDistance(p)) {
          stack_.push_back(n.right);
          stack_.push_back(n.left);
        } else {
          stack_.push_back(n.left);
          stack_.push_back(n.right);
        }
      }
    }
    return best;
  }

  /// Calls leaf(i, j) for pairs of items (i of this tree, j of `other`) whose boxes overlap
  /// once `other`'s are moved by `offset` and both are grown by `pad`, until leaf returns
  /// true; returns whether it did. Nodes are descended larger box first.
  template <class Leaf>
  bool anyPair(const BoxTree& other, const Eigen::Vector3d& offset, double pad, Leaf&& leaf) const {
    pairsVisited_ = 0;
    if (nodes_.empty() || other.nodes_.empty()) return false;
    pairStack_.clear();
    pairStack_.push_back({0, 0});
    auto apart = [&](const Box3& a, const Box3& b) {
      for (int k = 0; k < 3; ++k)
        if (a.lo[k] > b.hi[k] + offset[k] + pad || b.lo[k] + offset[k] > a.hi[k] + pad) return true;
      return false;
    };
    while (!pairStack_.empty()) {
      const auto [na, nb] = pairStack_.back();
      pairStack_.pop_back();
      ++pairsVisited_;
      const Node& a = nodes_[static_cast<std::size_t>(na)];
      const Node& b = other.nodes_[static_cast<std::size_t>(nb)];
      if (apart(a.box, b.box)) continue;
      if (a.count > 0 && b.count > 0) {
        for (int ka = a.first; ka < a.first + a.count; ++ka) {
          const int i = items_[static_cast<std::size_t>(ka)];
          const Box3& bi = boxes_[static_cast<std::size_t>(i)];
          for (int kb = b.first; kb < b.first + b.count; ++kb) {
            const int j = other.items_[static_cast<std::size_t>(kb)];
            if (apart(bi, other.boxes_[static_cast<std::size_t>(j)])) continue;
            if (leaf(i, j)) return true;
          }
        }
        continue;
      }
      const double ea = (a.box.hi - a.box.lo).maxCoeff(), eb = (b.box.hi - b.box.lo).maxCoeff();
      if (b.count > 0 || (a.count == 0 && ea >= eb)) {
        pairStack_.push_back({a.left, nb});
        pairStack_.push_back({a.right, nb});
      } else {
        pairStack_.push_back({na, b.left});
        pairStack_.push_back({na, b.right});
      }
    }
    return false;
  }
  /// Node pairs the last anyPair() popped.
  long long pairsVisited() const { return pairsVisited_; }

 private:
  struct Node {
    Box3 box;
    int left = -1, right = -1;
    int first = 0, count = 0;  // leaves: items_[first .. first + count)
  };

  int buildNode(int first, int count) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Box3 box;
    for (int k = first; k < first + count; ++k) box.add(boxes_[static_cast<std::size_t>(items_[static_cast<std::size_t>(k)])]);
    nodes_[static_cast<std::size_t>(id)].box = box;
    if (count <= kLeafSize) {
      nodes_[static_cast<std::size_t>(id)].first = first;
      nodes_[static_cast<std::size_t>(id)].count = count;
      return id;
    }
    int axis = 0;
    const Eigen::Vector3d ext = box.hi - box.lo;
    if (ext[1] > ext[axis]) axis = 1;
    if (ext[2] > ext[axis]) axis = 2;
    const int mid = first + count / 2;
    auto centre = [&](int i) {
      const Box3& b = boxes_[static_cast<std::size_t>(i)];
      return b.lo[axis] + b.hi[axis];
    };
    std::nth_element(items_.begin() + first, items_.begin() + mid, items_.begin() + first + count,
                     [&](int x, int y) { return centre(x) < centre(y); });
    const int l = buildNode(first, mid - first);
    const int r = buildNode(mid, first + count - mid);
    nodes_[static_cast<std::size_t>(id)].left = l;
    nodes_[static_cast<std::size_t>(id)].right = r;
    return id;
  }

  std::vector<Box3> boxes_;
  std::vector<int> items_;
  std::vector<Node> nodes_;
  mutable std::vector<int> stack_;
  mutable std::vector<std::pair<int, int>> pairStack_;
  mutable long long pairsVisited_ = 0;
};

}  // namespace detail
}  // namespace mink
