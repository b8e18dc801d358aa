// mink/cpd/detail/trimming.hpp — from convolution facets to the boundary of M: cut the
// facets where they cross, classify each piece as on ∂M or inside M, keep the first.
//
// Source: J.-M. Lien, "A simple method for computing Minkowski sum boundary in 3D using
// collision detection" (WAFR 2008), as the CPD paper (Lee et al., CAD 2016, sections 3.2
// and 5.1) uses it: the convolution facets are subdivided where they intersect, and each
// piece is on ∂M or inside M as a whole; a point x of a piece is on ∂M iff A and B + x
// touch without overlapping interiors, i.e. iff B + x + δn misses A for a small δ along the
// piece's outward normal n.
//
//   1. The facets become a soup of convex polygons over the points a_i − b_j (triangles,
//      and the parallelograms of EE pairs), each clipped to the query region (an
//      axis-aligned box around the ball; unbounded for the full boundary).
//   2. Each polygon F is cut by every other polygon G that crosses its plane (by G's
//      plane, wherever the crossing segment meets G), and by the edges of every polygon
//      lying in its plane, into convex pieces: no piece's interior is then crossed by a
//      facet (all facets meeting the region are known), so each piece has one status.
//   3. A piece inside a coplanar, equally oriented polygon of lower index is that
//      polygon's (the same part of ∂M once); any other piece is classified by one
//      collision test at its centroid moved by δ along its normal, δ half the distance to
//      the nearest other facet and to the region's boundary: the segment crosses no facet.
// Every corner is named by how it was made (a point a_i − b_j; a facet edge cut by a plane,
// a box face or another edge; three planes), and computed once from its name, so that
// neighbouring pieces and facets share it exactly. Decisions (sides of planes and lines)
// are exact predicates on those corners (orient3d / orient2d; a corner made on a line is on
// it by its name); the corners themselves are rounded constructions for floating-point T,
// and one made on a side of a piece is kept on that side: where its construction from the
// planes is ill-conditioned (two nearly parallel cutting planes, whose crossing with F lies
// far away or nowhere in double), it is placed by interpolation between the side's ends.
// The plane of a parallelogram is that of its first three corners (its fourth is on it up
// to the rounding of a_i − b_j).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "mink/core/expansion.hpp"
#include "mink/core/orientation.hpp"
#include "mink/cpd/convolution.hpp"
#include "mink/cpd/detail/box_tree.hpp"
#include "mink/cpd/minkowski_patch.hpp"
#include "mink/mesh/mesh_overlap.hpp"

namespace mink {
namespace detail {

/// A line of a facet's plane, by what makes it: the line of a soup edge (two point ids), the
/// plane of another soup triangle, or a face of the region box.
struct TrimLabel {
  static constexpr std::uint64_t kPlane = 1ull << 62, kBox = 2ull << 62, kEdge = 3ull << 62;
  static constexpr std::uint64_t kTag = 3ull << 62;
  static constexpr std::uint64_t kNone = ~0ull;
  static std::uint64_t plane(int g) { return kPlane | static_cast<std::uint64_t>(g); }
  static std::uint64_t box(int k) { return kBox | static_cast<std::uint64_t>(k); }
  static std::uint64_t edge(int u, int v) {
    const std::uint64_t a = static_cast<std::uint64_t>(std::min(u, v)), b = static_cast<std::uint64_t>(std::max(u, v));
    return kEdge | (a << 31) | b;
  }
  static bool isPlane(std::uint64_t x) { return x != kNone && (x & kTag) == kPlane; }
  static bool isBox(std::uint64_t x) { return x != kNone && (x & kTag) == kBox; }
  static bool isEdge(std::uint64_t x) { return x != kNone && (x & kTag) == kEdge; }
  static int index(std::uint64_t x) { return static_cast<int>(x & ((1ull << 62) - 1)); }
  static int edgeFirst(std::uint64_t x) { return static_cast<int>((x >> 31) & 0x7fffffffull); }
  static int edgeSecond(std::uint64_t x) { return static_cast<int>(x & 0x7fffffffull); }
};

/// The name of a corner: a point a_i − b_j {id, none, none}; two labels of which one is an
/// edge (the 3-D point where that edge meets the other line's plane, box face or edge);
/// or three planes / box faces. Sorted, so that every way of making a point names it once.
struct TrimKey {
  std::uint64_t k[3] = {TrimLabel::kNone, TrimLabel::kNone, TrimLabel::kNone};
  bool operator==(const TrimKey& o) const { return k[0] == o.k[0] && k[1] == o.k[1] && k[2] == o.k[2]; }
  bool contains(std::uint64_t x) const { return k[0] == x || k[1] == x || k[2] == x; }
  bool isPoint() const { return k[1] == TrimLabel::kNone; }
  bool isPair() const { return k[1] != TrimLabel::kNone && k[2] == TrimLabel::kNone; }
};

struct TrimKeyHash {
  std::size_t operator()(const TrimKey& x) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t v : x.k) {
      h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h *= 0xff51afd7ed558ccdull;
    }
    return static_cast<std::size_t>(h ^ (h >> 33));
  }
};

template <class T>
class Trimmer {
 public:
  // Floating T: the number types of the exact predicates on constructed corners.
  using FloatOf = std::conditional_t<std::is_same<T, long double>::value, long double, double>;
  using IV = IntervalOf<FloatOf>;
  using IVL = IntervalOf<long double>;  // a tighter filter where long double is wider
  using EX = ExpansionOf<FloatOf>;
  struct Homog {
    IV X[3];
    IV W = IV(FloatOf(1));
    IV x[3];             // X / W: an enclosure of the corner itself
    bool boxed = false;  // x is finite (W excludes 0)
  };

  /// Where the pieces are wanted: a box (pieces are clipped to it and all facets meeting it
  /// must be given) and a ball (pieces not meeting it are dropped unclassified), both in
  /// A's frame; or neither (the full boundary).
  struct Region {
    bool bounded = false;
    Vec3<T> lo = Vec3<T>::Zero(), hi = Vec3<T>::Zero();
    bool ball = false;
    Vec3<T> centre = Vec3<T>::Zero();
    T radius = T(0);
  };

  /// The pieces on ∂M of the given facets (compatible pairs of `frame`) in the region,
  /// appended to `out` in A's frame; `overlap` must place B exactly as `frame` does.
  void run(const ConvolutionFrame<T>& frame, const std::vector<ConvolutionPair>& facets, const Region& region,
           MeshOverlap<T>& overlap, MinkowskiPatch<T>& out) {
    frame_ = &frame;
    facets_ = &facets;
    region_ = region;
    reset();
    buildSoup();
    out.facetsGathered += static_cast<int>(facets.size());
    boxes_.resize(soup_.size());
    for (std::size_t s = 0; s < soup_.size(); ++s) boxes_[s] = soup_[s].box;
    tree_.build(boxes_);
    // 1. Every polygon cut into its final pieces (those inside the region).
    for (std::size_t s = 0; s < soup_.size(); ++s) {
      if (!initialPiece(static_cast<int>(s))) continue;
      cutByOthers(static_cast<int>(s));
      for (std::size_t i = 0; i < polyCount_; ++i) {
        const Poly& p = polys_[i];
        if (p.dead) continue;
        Final f;
        f.soup = static_cast<int>(s);
        f.first = static_cast<int>(finalV_.size());
        f.count = static_cast<int>(p.v.size());
        f.area = approxArea(p);
        // A sliver of no area (a cut that runs along a side within rounding) is dropped: its
        // centroid says nothing, and joining it would spread that to its neighbours.
        if (!(f.area > sliverArea(p))) continue;
        finalV_.insert(finalV_.end(), p.v.begin(), p.v.end());
        finalE_.insert(finalE_.end(), p.e.begin(), p.e.end());
        f.wanted = (!region_.ball || meetsBall(p)) && !ownedByOther(static_cast<int>(s), p);
        final_.push_back(f);
      }
    }
    out.pieces += static_cast<int>(final_.size());
    // 2. Pieces joined into patches where no facet separates them; 3. one collision test
    // per patch that holds a wanted piece; 4. the wanted pieces of patches on ∂M.
    stitch();
    // Each patch is classified at its largest piece (the nudge's room grows with the piece).
    status_.assign(final_.size(), -1);
    representative_.assign(final_.size(), -1);
    for (std::size_t i = 0; i < final_.size(); ++i) {
      int& r = representative_[static_cast<std::size_t>(find(static_cast<int>(i)))];
      if (r < 0 || final_[i].area > final_[static_cast<std::size_t>(r)].area) r = static_cast<int>(i);
    }
    outVertex_.clear();
    for (std::size_t i = 0; i < final_.size(); ++i) {
      if (!final_[i].wanted) continue;
      const int root = find(static_cast<int>(i));
      int& st = status_[static_cast<std::size_t>(root)];
      if (st < 0) {
        ++out.overlapTests;
        st = onBoundary(representative_[static_cast<std::size_t>(root)], overlap) ? 1 : 0;
      }
      if (st == 1) emit(static_cast<int>(i), out);
    }
  }

 private:
  struct Soup {
    int facet = -1;
    int nc = 3;                       // corners: 3, or 4 for an EE parallelogram
    int m[4] = {-1, -1, -1, -1};
    Vec3<T> n = Vec3<T>::Zero();  // (m1 − m0) × (m2 − m0), outward
    T k = T(0);                   // n · m0
    int axis = 0;                 // dominant axis of n
    int axisSign = 1;             // sign of n[axis]
    Box3 box;
  };
  struct Poly {
    std::vector<int> v;                 // corner ids, counter-clockwise seen along n
    std::vector<std::uint64_t> e;       // e[i]: the line of the side v[i] → v[i + 1]
    bool dead = false;
  };

  /// A final piece: corners finalV_[first .. first + count), side labels in finalE_.
  struct Final {
    int soup = -1, first = 0, count = 0;
    double area = 0;      // approximate, for choosing the piece a patch is tested at
    bool wanted = false;  // meets the ball and is not a coplanar duplicate
  };

  double approxArea(const Poly& p) const {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    const Eigen::Vector3d x0 = toD(coords_[static_cast<std::size_t>(p.v[0])]);
    for (std::size_t i = 1; i + 1 < p.v.size(); ++i)
      n += (toD(coords_[static_cast<std::size_t>(p.v[i])]) - x0).cross(toD(coords_[static_cast<std::size_t>(p.v[i + 1])]) - x0);
    return 0.5 * n.norm();
  }
  /// Below this a piece has no area to rounding: (2^-40 of its size)², its size the largest
  /// coordinate of its corners or of their spread.
  double sliverArea(const Poly& p) const {
    Box3 b;
    for (int id : p.v) b.add(toD(coords_[static_cast<std::size_t>(id)]));
    const double size = std::max((b.hi - b.lo).maxCoeff(), std::max(b.hi.cwiseAbs().maxCoeff(), b.lo.cwiseAbs().maxCoeff()));
    const double s = std::ldexp(size, -40);
    return s * s;
  }

  // ----- Patches ----------------------------------------------------------------------

  int find(int i) {
    while (parent_[static_cast<std::size_t>(i)] != i) {
      parent_[static_cast<std::size_t>(i)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)])];
      i = parent_[static_cast<std::size_t>(i)];
    }
    return i;
  }

  /// Joins pieces that share a side across which no facet passes: a side on a cut whose
  /// cutting polygon does not reach it (both ends provably outside the same side of that
  /// polygon, or beyond the same end of the coplanar edge), or an edge of the convolution
  /// shared by exactly two polygons and lying in no other polygon's plane. Crossing such a
  /// side stays on the convolution surface without meeting another facet, so the two
  /// pieces have one status.
  void stitch() {
    parent_.resize(final_.size());
    for (std::size_t i = 0; i < final_.size(); ++i) parent_[i] = static_cast<int>(i);
    edgeUse_.clear();
    for (const Soup& f : soup_)
      for (int c = 0; c < f.nc; ++c) ++edgeUse_[TrimLabel::edge(f.m[c], f.m[(c + 1) % f.nc])];
    sideOwner_.clear();
    for (std::size_t i = 0; i < final_.size(); ++i) {
      const Final& f = final_[i];
      for (int k = 0; k < f.count; ++k) {
        const int a = finalV_[static_cast<std::size_t>(f.first + k)];
        const int b = finalV_[static_cast<std::size_t>(f.first + (k + 1) % f.count)];
        sideOwner_[sideKey(a, b)] = static_cast<int>(i);
      }
    }
    for (std::size_t i = 0; i < final_.size(); ++i) {
      const Final& f = final_[i];
      for (int k = 0; k < f.count; ++k) {
        const int a = finalV_[static_cast<std::size_t>(f.first + k)];
        const int b = finalV_[static_cast<std::size_t>(f.first + (k + 1) % f.count)];
        const auto it = sideOwner_.find(sideKey(b, a));
        if (it == sideOwner_.end()) continue;
        const int j = it->second;
        if (find(static_cast<int>(i)) == find(j)) continue;
        if (!separated(f.soup, final_[static_cast<std::size_t>(j)].soup, finalE_[static_cast<std::size_t>(f.first + k)], a, b))
          parent_[static_cast<std::size_t>(find(static_cast<int>(i)))] = find(j);
      }
    }
  }

  /// Does some polygon other than F pass along the side a b of a piece of F? A polygon
  /// crossing F's plane does where its plane holds the side and it reaches the side (not
  /// strictly outside one of its edges); a polygon in F's plane does where one of its
  /// edges is collinear with the side and overlaps it.
  bool sideCrossed(int F, int a, int b) const {
    Box3 query;
    query.add(toD(coords_[static_cast<std::size_t>(a)]));
    query.add(toD(coords_[static_cast<std::size_t>(b)]));
    bool crossed = false;
    tree_.forOverlapping(padded(query), [&](int G) {
      if (crossed || G == F) return;
      const Soup& g = soup_[static_cast<std::size_t>(G)];
      const std::uint64_t plane = TrimLabel::plane(G);
      if (side(F, a, plane) != 0 || side(F, b, plane) != 0) return;
      bool inF = true;
      for (int c = 0; c < g.nc && inF; ++c) inF = pointSide(soup_[static_cast<std::size_t>(F)], g.m[c]) == 0;
      if (!inF) {
        crossed = segmentMayMeetTriangle(a, b, G);
        return;
      }
      for (int c = 0; c < g.nc && !crossed; ++c) {
        const int u = g.m[c], v = g.m[(c + 1) % g.nc];
        const std::uint64_t e = TrimLabel::edge(u, v);
        if (side(F, a, e) == 0 && side(F, b, e) == 0 && segmentOverlapsEdge(a, b, std::min(u, v), std::max(u, v)))
          crossed = true;
      }
    });
    return crossed;
  }

  static std::uint64_t sideKey(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }

  /// May a facet pass along the side a b (line `label`) of polygon F, next to polygon G?
  /// A side too short to be told from a point (two names of one point in a degenerate
  /// configuration) joins nothing: pieces that share only a point may differ.
  bool separated(int F, int G, std::uint64_t label, int a, int b) const {
    const Vec3<T>&xa = coords_[static_cast<std::size_t>(a)], &xb = coords_[static_cast<std::size_t>(b)];
    const T size = T((xa - xb).cwiseAbs().maxCoeff());
    const Soup& sf = soup_[static_cast<std::size_t>(F)];
    T scale = T(0);
    for (int c = 0; c < sf.nc; ++c) scale = std::max(scale, T(mCoord_[static_cast<std::size_t>(sf.m[c])].cwiseAbs().maxCoeff()));
    if (!(size > T(1e-9) * scale)) return true;
    if (TrimLabel::isBox(label)) return true;
    const Soup& f = soup_[static_cast<std::size_t>(F)];
    bool own = false;
    for (int c = 0; c < f.nc; ++c) own = own || label == TrimLabel::edge(f.m[c], f.m[(c + 1) % f.nc]);
    if (!own) {
      // A cut within F (a plane's trace, or a coplanar polygon's edge line): the pieces are
      // one if no polygon reaches the side along it — every polygon whose plane holds the
      // side is tested, not only the one that made the cut (several may share its line).
      if (F != G) return true;
      return sideCrossed(F, a, b);
    }
    if (F == G) return true;
    const auto it = edgeUse_.find(label);
    if (it == edgeUse_.end() || it->second != 2) return true;
    return blocked_.count(label) != 0;
  }


  void reset() {
    mIndex_.clear();
    mPair_.clear();
    mCoord_.clear();
    soup_.clear();
    keyIndex_.clear();
    keys_.clear();
    coords_.clear();
    hbox_.clear();
    planeCache_.clear();
    witnessA_ = witnessB_ = -1;
    final_.clear();
    finalV_.clear();
    finalE_.clear();
    blocked_.clear();
  }

  // ----- The soup -------------------------------------------------------------------

  int mVertex(int i, int j) {
    const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) | static_cast<std::uint32_t>(j);
    const auto it = mIndex_.find(key);
    if (it != mIndex_.end()) return it->second;
    const int id = static_cast<int>(mCoord_.size());
    mIndex_.emplace(key, id);
    mPair_.push_back({i, j});
    mCoord_.push_back(frame_->m(i, j));
    return id;
  }

  static Eigen::Vector3d toD(const Vec3<T>& x) { return Eigen::Vector3d(toDouble(x[0]), toDouble(x[1]), toDouble(x[2])); }

  void buildSoup() {
    std::array<int, 2> poly[4];
    for (std::size_t f = 0; f < facets_->size(); ++f) {
      {
        Soup s;
        s.facet = static_cast<int>(f);
        s.nc = frame_->facetPolygon((*facets_)[f], poly);
        for (int c = 0; c < s.nc; ++c) s.m[c] = mVertex(poly[c][0], poly[c][1]);
        const Vec3<T>&p0 = mCoord_[s.m[0]], &p1 = mCoord_[s.m[1]], &p2 = mCoord_[s.m[2]];
        // Exactly collinear corners (a degenerate facet): no area, no cut.
        if (orient2d(p0, p1, p2, 0) == 0 && orient2d(p0, p1, p2, 1) == 0 && orient2d(p0, p1, p2, 2) == 0) continue;
        s.n = (p1 - p0).cross(p2 - p0);
        s.k = s.n.dot(p0);
        s.axis = 0;
        for (int a = 1; a < 3; ++a)
          if (absValue(s.n[a]) > absValue(s.n[s.axis])) s.axis = a;
        // The dominant axis by the exact projected orientations (the rounded normal may
        // hide a tiny component's sign): orient2d along an axis is the sign of n there.
        s.axisSign = orient2d(p0, p1, p2, s.axis);
        if (s.axisSign == 0) {
          for (int a = 0; a < 3; ++a)
            if (const int sg = orient2d(p0, p1, p2, a)) s.axis = a, s.axisSign = sg;
        }
        for (int c = 0; c < s.nc; ++c) s.box.add(toD(mCoord_[s.m[c]]));
        soup_.push_back(s);
      }
    }
  }

  // ----- Corners ----------------------------------------------------------------------

  static TrimKey keyOf(std::uint64_t a, std::uint64_t b = TrimLabel::kNone, std::uint64_t c = TrimLabel::kNone) {
    TrimKey k;
    k.k[0] = a, k.k[1] = b, k.k[2] = c;
    std::sort(k.k, k.k + 3);  // kNone (all ones) sorts last
    return k;
  }

  int corner(const TrimKey& key) {
    const auto it = keyIndex_.find(key);
    if (it != keyIndex_.end()) return it->second;
    return addCorner(key, compute(key));
  }
  int addCorner(const TrimKey& key, const Vec3<T>& x) {
    if constexpr (!ScalarTraits<T>::isExact) {
      Homog h;
      if (!key.isPoint()) enclose(key, h);
      return addCorner(key, x, h);
    } else {
      return addCorner(key, x, Homog());
    }
  }
  int addCorner(const TrimKey& key, const Vec3<T>& x, const Homog& h) {
    const int id = static_cast<int>(keys_.size());
    keyIndex_.emplace(key, id);
    keys_.push_back(key);
    coords_.push_back(x);
    if constexpr (!ScalarTraits<T>::isExact) hbox_.push_back(h);
    return id;
  }
  /// h := the corner's homogeneous enclosure and its point enclosure.
  void enclose(const TrimKey& key, Homog& h) const {
    homogeneous<IV>(key, h.X, h.W);
    h.boxed = h.W.excludesZero();
    for (int k = 0; k < 3 && h.boxed; ++k) {
      h.x[k] = h.X[k] / h.W;
      h.boxed = std::isfinite(h.x[k].lo()) && std::isfinite(h.x[k].hi());
    }
  }
  int pointCorner(int mid) { return corner(keyOf(static_cast<std::uint64_t>(mid))); }

  /// The corner where the side of F on line `side` meets line `cut` (both lines of F's plane).
  /// Where an end point of an edge line lies on the other line (an edge of a coplanar
  /// facet extended across F through a corner, a corner on a cutting plane or box face),
  /// the crossing is that point, and named as such: one point, one name.
  int crossing(int F, std::uint64_t side, std::uint64_t cut, int ia, int ib) {
    const bool es = TrimLabel::isEdge(side), ec = TrimLabel::isEdge(cut);
    if (es && ec) {
      const int a = TrimLabel::edgeFirst(side), b = TrimLabel::edgeSecond(side);
      const int c = TrimLabel::edgeFirst(cut), d = TrimLabel::edgeSecond(cut);
      if (a == c || a == d) return pointCorner(a);
      if (b == c || b == d) return pointCorner(b);
      const int axis = soup_[static_cast<std::size_t>(F)].axis;
      if (orient2d(mCoord_[c], mCoord_[d], mCoord_[a], axis) == 0) return pointCorner(a);
      if (orient2d(mCoord_[c], mCoord_[d], mCoord_[b], axis) == 0) return pointCorner(b);
      if (orient2d(mCoord_[a], mCoord_[b], mCoord_[c], axis) == 0) return pointCorner(c);
      if (orient2d(mCoord_[a], mCoord_[b], mCoord_[d], axis) == 0) return pointCorner(d);
      return cornerOn(keyOf(side, cut), F, cut, ia, ib);
    }
    if (es || ec) {
      const std::uint64_t e = es ? side : cut, o = es ? cut : side;
      for (const int end : {TrimLabel::edgeFirst(e), TrimLabel::edgeSecond(e)})
        if (onPlaneLike(mCoord_[static_cast<std::size_t>(end)], o)) return pointCorner(end);
      return cornerOn(keyOf(side, cut), F, cut, ia, ib);
    }
    // Two polygons' planes that share an edge lying in both meet along it: the corner is
    // that edge's crossing with F's plane (one name for the point).
    if (TrimLabel::isPlane(side) && TrimLabel::isPlane(cut)) {
      const Soup& g = soup_[static_cast<std::size_t>(TrimLabel::index(side))];
      const Soup& h = soup_[static_cast<std::size_t>(TrimLabel::index(cut))];
      int shared[2], count = 0;
      for (int i = 0; i < g.nc; ++i)
        for (int j = 0; j < h.nc; ++j)
          if (g.m[i] == h.m[j] && count < 2) shared[count++] = g.m[i];
      // (A parallelogram's plane is that of its first three corners; its other sides may
      // be off it by rounding, and then the point is not on it.)
      if (count == 2 && pointSide(g, shared[0]) == 0 && pointSide(g, shared[1]) == 0 && pointSide(h, shared[0]) == 0 &&
          pointSide(h, shared[1]) == 0) {
        const std::uint64_t e = TrimLabel::edge(shared[0], shared[1]);
        for (const int end : {shared[0], shared[1]})
          if (onPlaneLike(mCoord_[static_cast<std::size_t>(end)], TrimLabel::plane(F))) return pointCorner(end);
        return cornerOn(keyOf(e, TrimLabel::plane(F)), F, cut, ia, ib);
      }
    }
    return cornerOn(keyOf(TrimLabel::plane(F), side, cut), F, cut, ia, ib);
  }

  /// The corner named `key`, made on the side from corner ia to corner ib where it meets
  /// `cut`: from its planes (canonical, shared with every other facet that makes it), or,
  /// for floating-point T where that construction is not on the side (ill-conditioned:
  /// nearly parallel planes), by interpolation of the signed distances to `cut` along it.
  int cornerOn(const TrimKey& key, int F, std::uint64_t cut, int ia, int ib) {
    const auto it = keyIndex_.find(key);
    if (it != keyIndex_.end()) return it->second;
    if constexpr (ScalarTraits<T>::isExact) {
      return addCorner(key, compute(key));
    } else {
      // The enclosure of the exact corner: its midpoint where it is tight; else (nearly
      // parallel planes) the exact X / W in expansion arithmetic, rounded once each.
      (void)F;
      (void)cut;
      Homog h;
      enclose(key, h);
      const Vec3<T>&a = coords_[static_cast<std::size_t>(ia)], &b = coords_[static_cast<std::size_t>(ib)];
      const T scale = T((b - a).cwiseAbs().maxCoeff());
      Vec3<T> x;
      bool tight = h.boxed;
      for (int k = 0; k < 3 && tight; ++k) {
        x[k] = T(h.x[k].mid());
        tight = T(h.x[k].hi() - h.x[k].lo()) <= std::ldexp(T(1), -40) * (absValue(x[k]) + scale);
      }
      if (!tight && std::numeric_limits<long double>::digits > std::numeric_limits<FloatOf>::digits) {
        IVL X[3], W;
        homogeneous<IVL>(key, X, W);
        tight = W.excludesZero();
        for (int k = 0; k < 3 && tight; ++k) {
          const IVL q = X[k] / W;
          x[k] = T(q.mid());
          tight = std::isfinite(static_cast<double>(q.lo())) && std::isfinite(static_cast<double>(q.hi())) &&
                  T(q.hi() - q.lo()) <= std::ldexp(T(1), -40) * (absValue(x[k]) + scale);
        }
      }
      if (!tight) {
        EX X[3], W;
        homogeneous<EX>(key, X, W);
        const FloatOf w = W.approx();
        for (int k = 0; k < 3; ++k) x[k] = w != FloatOf(0) ? T(X[k].approx() / w) : T((a[k] + b[k]) / T(2));
      }
      return addCorner(key, x, h);
    }
  }

  /// Side of the point a_i − b_j with id `mid` of polygon g's plane (orient3d; 0 at once
  /// for a corner of the three that define it).
  int pointSide(const Soup& g, int mid) const {
    if (mid == g.m[0] || mid == g.m[1] || mid == g.m[2]) return 0;
    return orient3d(mCoord_[g.m[0]], mCoord_[g.m[1]], mCoord_[g.m[2]], mCoord_[static_cast<std::size_t>(mid)]);
  }

  /// Is point x exactly on the plane of soup triangle / the box face `l`?
  bool onPlaneLike(const Vec3<T>& x, std::uint64_t l) const {
    if (TrimLabel::isPlane(l)) {
      const Soup& g = soup_[static_cast<std::size_t>(TrimLabel::index(l))];
      return orient3d(mCoord_[g.m[0]], mCoord_[g.m[1]], mCoord_[g.m[2]], x) == 0;
    }
    const int b = TrimLabel::index(l), axis = b / 2;
    return x[axis] == ((b % 2) ? region_.hi[axis] : region_.lo[axis]);
  }

  struct PlaneEq {
    Vec3<T> n;
    T k;
  };
  PlaneEq planeOf(std::uint64_t x) const {
    if (TrimLabel::isPlane(x)) {
      const Soup& s = soup_[static_cast<std::size_t>(TrimLabel::index(x))];
      return {s.n, s.k};
    }
    const int b = TrimLabel::index(x), axis = b / 2;
    Vec3<T> n = Vec3<T>::Zero();
    n[axis] = T(1);
    return {n, (b % 2) ? region_.hi[axis] : region_.lo[axis]};
  }

  Vec3<T> compute(const TrimKey& key) const {
    if (key.isPoint()) return mCoord_[static_cast<std::size_t>(key.k[0])];
    if (key.isPair()) {
      // Sorted: an edge label is the larger; the other is a plane, a box face or an edge.
      const std::uint64_t e = key.k[1], o = key.k[0];
      const Vec3<T>& p = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(e))];
      const Vec3<T>& q = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(e))];
      if (TrimLabel::isEdge(o)) {
        const Vec3<T>& r = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(o))];
        const Vec3<T>& s = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(o))];
        const Vec3<T> d1 = q - p, d2 = s - r, c = d1.cross(d2);
        const T den = c.squaredNorm();
        if (den == T(0)) return p;
        return p + (((r - p).cross(d2)).dot(c) / den) * d1;
      }
      const PlaneEq pl = planeOf(o);
      const T dp = pl.n.dot(p) - pl.k, dq = pl.n.dot(q) - pl.k;
      if (dp == dq) return p;
      Vec3<T> x = p + (dp / (dp - dq)) * (q - p);
      if (TrimLabel::isBox(o)) x[TrimLabel::index(o) / 2] = pl.k;  // exactly on the face
      return x;
    }
    // Three planes (box faces among them): Cramer's rule.
    const PlaneEq a = planeOf(key.k[0]), b = planeOf(key.k[1]), c = planeOf(key.k[2]);
    const Vec3<T> bc = b.n.cross(c.n), ca = c.n.cross(a.n), ab = a.n.cross(b.n);
    const T det = a.n.dot(bc);
    if (det == T(0)) return mCoord_[0];
    Vec3<T> x = (a.k * bc + b.k * ca + c.k * ab) / det;
    for (const std::uint64_t l : key.k)
      if (TrimLabel::isBox(l)) x[TrimLabel::index(l) / 2] = planeOf(l).k;
    return x;
  }

  // ----- Sides ------------------------------------------------------------------------

  /// Side of corner id of line `cut` within facet F's plane: > 0 outside / on the far side.
  /// Plane(G): orient3d against G; box face: outside the box is > 0; edge (a line of F's
  /// plane): the left of the edge's first → second point, seen along F's normal, is > 0.
  int side(int F, int id, std::uint64_t cut) const {
    const TrimKey& key = keys_[static_cast<std::size_t>(id)];
    if (key.contains(cut)) return 0;
    // A corner made on a line of F's plane that is the cut's line is on the cut: decided
    // from the inputs that name the lines (exactly), not from the rounded corner.
    if (!key.isPoint())
      for (const std::uint64_t l : key.k)
        if (l != TrimLabel::kNone && l != TrimLabel::plane(F) && sameLine(F, l, cut)) return 0;
    if constexpr (!ScalarTraits<T>::isExact) {
      if (!key.isPoint()) return constructedSide(F, id, cut);
    }
    const Vec3<T>& x = coords_[static_cast<std::size_t>(id)];
    if (TrimLabel::isPlane(cut)) {
      const Soup& g = soup_[static_cast<std::size_t>(TrimLabel::index(cut))];
      if (key.isPoint()) return pointSide(g, static_cast<int>(key.k[0]));
      return orient3d(mCoord_[g.m[0]], mCoord_[g.m[1]], mCoord_[g.m[2]], x);
    }
    if (TrimLabel::isBox(cut)) {
      const int b = TrimLabel::index(cut), axis = b / 2;
      if (b % 2) return detail::sign(T(x[axis] - region_.hi[axis]));
      return detail::sign(T(region_.lo[axis] - x[axis]));
    }
    const Soup& f = soup_[static_cast<std::size_t>(F)];
    const int u = TrimLabel::edgeFirst(cut), v = TrimLabel::edgeSecond(cut);
    return f.axisSign * orient2d(mCoord_[u], mCoord_[v], x, f.axis);
  }

  /// Do lines l and cut of F's plane coincide? (Each is an edge line, or the trace on F's
  /// plane of another polygon's plane or of a box face.) Exact on the named inputs: an edge
  /// line lies in a plane when both its ends do; two plane traces coincide when the planes
  /// do (the case of two different planes through one line of F is not detected).
  bool sameLine(int F, std::uint64_t l, std::uint64_t cut) const {
    if (TrimLabel::isEdge(l)) {
      const Vec3<T>& a = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(l))];
      const Vec3<T>& b = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(l))];
      if (TrimLabel::isEdge(cut)) {
        const int axis = soup_[static_cast<std::size_t>(F)].axis;
        const Vec3<T>& u = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(cut))];
        const Vec3<T>& v = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(cut))];
        return orient2d(u, v, a, axis) == 0 && orient2d(u, v, b, axis) == 0;
      }
      return onPlaneLike(a, cut) && onPlaneLike(b, cut);
    }
    if (TrimLabel::isEdge(cut)) return sameLine(F, cut, l);
    // Two planes (or box faces): the same plane.
    if (TrimLabel::isPlane(l)) {
      const Soup& h = soup_[static_cast<std::size_t>(TrimLabel::index(l))];
      for (int c = 0; c < 3; ++c)
        if (!onPlaneLike(mCoord_[h.m[c]], cut)) return false;
      return true;
    }
    if (TrimLabel::isPlane(cut)) return sameLine(F, cut, l);
    return false;  // two different box faces
  }

  // ----- Exact predicates on constructed corners (floating-point T) ------------------
  //
  // A corner made by construction is X / W in homogeneous coordinates, X and W polynomials
  // in the coordinates of the points a_i − b_j that name it (degree up to 7 and 6: three
  // planes by Cramer's rule). The side of a line or plane is then the sign of a polynomial
  // (degree up to 9) times sign(W): evaluated in interval arithmetic from the corner's
  // enclosure made when it was created, and, when that cannot tell, exactly in expansion
  // arithmetic (core/expansion.hpp) from the corner's name. Exact on the numbers
  // a_i − b_j as rounded, the same numbers every other predicate here uses.


  template <class N>
  void point(int mid, N p[3]) const {
    for (int a = 0; a < 3; ++a) p[a] = N(mCoord_[static_cast<std::size_t>(mid)][a]);
  }
  template <class N>
  static void cross(const N a[3], const N b[3], N out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
  }
  template <class N>
  static N dot(const N a[3], const N b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  /// The plane of soup polygon / box face l: n · x = k.
  template <class N>
  void planeN(std::uint64_t l, N n[3], N& k) const {
    if (TrimLabel::isPlane(l)) {
      const Soup& g = soup_[static_cast<std::size_t>(TrimLabel::index(l))];
      N p0[3], p1[3], p2[3], u[3], v[3];
      point(g.m[0], p0);
      point(g.m[1], p1);
      point(g.m[2], p2);
      for (int a = 0; a < 3; ++a) u[a] = p1[a] - p0[a], v[a] = p2[a] - p0[a];
      cross(u, v, n);
      k = dot(n, p0);
      return;
    }
    const int b = TrimLabel::index(l), axis = b / 2;
    for (int a = 0; a < 3; ++a) n[a] = N(FloatOf(a == axis ? 1 : 0));
    k = N(static_cast<FloatOf>((b % 2) ? region_.hi[axis] : region_.lo[axis]));
  }
  /// The corner named `key` as X / W.
  template <class N>
  void homogeneous(const TrimKey& key, N X[3], N& W) const {
    if (key.isPoint()) {
      point(static_cast<int>(key.k[0]), X);
      W = N(FloatOf(1));
      return;
    }
    if (key.isPair()) {
      const std::uint64_t e = key.k[1], o = key.k[0];
      N p[3], q[3], d[3];
      point(TrimLabel::edgeFirst(e), p);
      point(TrimLabel::edgeSecond(e), q);
      for (int a = 0; a < 3; ++a) d[a] = q[a] - p[a];
      if (TrimLabel::isEdge(o)) {
        N r[3], t[3], d2[3], c[3], rp[3], m[3];
        point(TrimLabel::edgeFirst(o), r);
        point(TrimLabel::edgeSecond(o), t);
        for (int a = 0; a < 3; ++a) d2[a] = t[a] - r[a], rp[a] = r[a] - p[a];
        cross(d, d2, c);
        cross(rp, d2, m);
        W = dot(c, c);
        const N s = dot(m, c);
        for (int a = 0; a < 3; ++a) X[a] = p[a] * W + s * d[a];
        return;
      }
      N n[3], k;
      planeN(o, n, k);
      W = dot(n, d);
      const N s = k - dot(n, p);
      for (int a = 0; a < 3; ++a) X[a] = p[a] * W + s * d[a];
      return;
    }
    N n1[3], n2[3], n3[3], k1, k2, k3, c23[3], c31[3], c12[3];
    planeN(key.k[0], n1, k1);
    planeN(key.k[1], n2, k2);
    planeN(key.k[2], n3, k3);
    cross(n2, n3, c23);
    cross(n3, n1, c31);
    cross(n1, n2, c12);
    W = dot(n1, c23);
    for (int a = 0; a < 3; ++a) X[a] = k1 * c23[a] + k2 * c31[a] + k3 * c12[a];
  }
  /// planeN in interval arithmetic, cached per polygon (box faces are exact).
  void planeIV(std::uint64_t l, const IV*& n, const IV*& k) const {
    if (TrimLabel::isPlane(l)) {
      const std::size_t g = static_cast<std::size_t>(TrimLabel::index(l));
      if (planeCache_.size() < soup_.size()) planeCache_.resize(soup_.size());
      PlaneIVCache& c = planeCache_[g];
      if (!c.ready) {
        planeN<IV>(l, c.n, c.k);
        c.ready = true;
      }
      n = c.n;
      k = &c.k;
      return;
    }
    const int b = TrimLabel::index(l);
    PlaneIVCache& c = boxCache_[b];
    planeN<IV>(l, c.n, c.k);
    n = c.n;
    k = &c.k;
  }

  /// The value whose sign (times sign(W)) is side(): see side().
  template <class N>
  N cutValue(int F, std::uint64_t cut, const N X[3], const N& W) const {
    if constexpr (std::is_same<N, IV>::value) {
      if (!TrimLabel::isEdge(cut)) {
        const IV* n;
        const IV* k;
        planeIV(cut, n, k);
        const IV val = dot(n, X) - *k * W;
        if (TrimLabel::isBox(cut) && TrimLabel::index(cut) % 2 == 0) return -val;
        return val;
      }
    }
    if (TrimLabel::isEdge(cut)) {
      const Soup& f = soup_[static_cast<std::size_t>(F)];
      N u[3], v[3], d[3], r[3];
      point(TrimLabel::edgeFirst(cut), u);
      point(TrimLabel::edgeSecond(cut), v);
      for (int a = 0; a < 3; ++a) d[a] = v[a] - u[a], r[a] = X[a] - u[a] * W;
      const int i = (f.axis + 1) % 3, j = (f.axis + 2) % 3;
      const N c = d[i] * r[j] - d[j] * r[i];
      return f.axisSign > 0 ? c : N(-c);
    }
    N n[3], k;
    planeN(cut, n, k);
    const N val = dot(n, X) - k * W;
    if (TrimLabel::isBox(cut) && TrimLabel::index(cut) % 2 == 0) return -val;  // outside: below the lower face
    return val;
  }
  int constructedSide(int F, int id, std::uint64_t cut) const {
    const Homog& h = hbox_[static_cast<std::size_t>(id)];
    if (h.boxed) {
      const IV one(FloatOf(1));
      const int sv = cutValue<IV>(F, cut, h.x, one).certainSign();
      if (sv != 0) return sv;
    }
    const int sw = h.W.certainSign();
    if (sw != 0) {
      const int sv = cutValue<IV>(F, cut, h.X, h.W).certainSign();
      if (sv != 0) return sv * sw;
    }
    const TrimKey& key = keys_[static_cast<std::size_t>(id)];
    if constexpr (std::numeric_limits<long double>::digits > std::numeric_limits<FloatOf>::digits) {
      IVL X[3], W;
      homogeneous<IVL>(key, X, W);
      const int swl = W.certainSign();
      if (swl != 0) {
        const int sv = cutValue<IVL>(F, cut, X, W).certainSign();
        if (sv != 0) return sv * swl;
      }
    }
    EX X[3], W;
    homogeneous<EX>(key, X, W);
    return cutValue<EX>(F, cut, X, W).sign() * W.sign();
  }
  /// Exact sign of (x − p) · (q − p) for corner id and points p, q (ids of a_i − b_j).
  int dotSign(int id, int p, int q) const {
    const TrimKey& key = keys_[static_cast<std::size_t>(id)];
    if constexpr (!ScalarTraits<T>::isExact) {
      auto value = [&](auto tag, const auto* X, const auto& W) {
        using N = decltype(tag);
        N pp[3], qq[3], d[3];
        point(p, pp);
        point(q, qq);
        N v = N(FloatOf(0));
        for (int a = 0; a < 3; ++a) d[a] = qq[a] - pp[a], v += (X[a] - pp[a] * W) * d[a];
        return v;
      };
      if (!key.isPoint()) {
        const Homog& h = hbox_[static_cast<std::size_t>(id)];
        const int sw = h.W.certainSign();
        if (sw != 0) {
          const int sv = value(IV(), h.X, h.W).certainSign();
          if (sv != 0) return sv * sw;
        }
        EX X[3], W;
        homogeneous<EX>(key, X, W);
        return value(EX(), X, W).sign() * W.sign();
      }
      EX X[3], W;
      homogeneous<EX>(key, X, W);
      return value(EX(), X, W).sign();
    } else {
      const Vec3<T>& x = coords_[static_cast<std::size_t>(id)];
      return detail::sign(T((x - mCoord_[static_cast<std::size_t>(p)]).dot(mCoord_[static_cast<std::size_t>(q)] - mCoord_[static_cast<std::size_t>(p)])));
    }
  }

  // ----- Pieces -----------------------------------------------------------------------

  Poly& newPoly() {
    if (polyCount_ == polys_.size()) polys_.emplace_back();
    Poly& p = polys_[polyCount_++];
    p.v.clear();
    p.e.clear();
    p.dead = false;
    return p;
  }

  /// polys_ := soup triangle F clipped to the region box; false if nothing is left.
  bool initialPiece(int F) {
    polyCount_ = 0;
    const Soup& f = soup_[static_cast<std::size_t>(F)];
    if (region_.bounded) {
      for (int a = 0; a < 3; ++a)
        if (f.box.lo[a] > toDouble(region_.hi[a]) || f.box.hi[a] < toDouble(region_.lo[a])) return false;
    }
    Poly& p = newPoly();
    for (int c = 0; c < f.nc; ++c) {
      p.v.push_back(pointCorner(f.m[c]));
      p.e.push_back(TrimLabel::edge(f.m[c], f.m[(c + 1) % f.nc]));
    }
    if (region_.bounded) {
      for (int b = 0; b < 6; ++b) {
        if (!clipKeep(F, 0, TrimLabel::box(b), -1)) return false;
      }
    }
    return true;
  }

  /// Cuts polys_[i] by line `cut`: keepSide −1 keeps the part with side <= 0 (in place) and
  /// returns false if nothing is left; keepSide 0 splits it into both parts (the positive
  /// one appended) and returns true if it was cut.
  bool clipKeep(int F, std::size_t i, std::uint64_t cut, int keepSide) {
    sides_.resize(polys_[i].v.size());
    bool pos = false, neg = false;
    for (std::size_t c = 0; c < polys_[i].v.size(); ++c) {
      sides_[c] = side(F, polys_[i].v[c], cut);
      pos |= sides_[c] > 0;
      neg |= sides_[c] < 0;
    }
    if (keepSide < 0) {
      if (!pos) return true;
      if (!neg) {
        polys_[i].dead = true;
        return false;
      }
      splitInto(F, i, cut, -1, scratch_);
      polys_[i].v.swap(scratch_.v);
      polys_[i].e.swap(scratch_.e);
      return polys_[i].v.size() >= 3;
    }
    if (!pos || !neg) return false;
    return true;  // the caller decides whether to split (see cutPlane / cutEdge)
  }

  /// out := the part of polys_[i] on side `keep` (+1 / −1) of `cut` (sides_ filled).
  void splitInto(int F, std::size_t i, std::uint64_t cut, int keep, Poly& out) {
    out.v.clear();
    out.e.clear();
    const Poly& p = polys_[i];
    const std::size_t n = p.v.size();
    for (std::size_t c = 0; c < n; ++c) {
      const std::size_t d = (c + 1) % n;
      const int a = keep * sides_[c], b = keep * sides_[d];
      if (a >= 0) {
        out.v.push_back(p.v[c]);
        out.e.push_back((b >= 0 || a > 0) ? p.e[c] : cut);
      }
      if ((a > 0 && b < 0) || (a < 0 && b > 0)) {
        out.v.push_back(crossing(F, p.e[c], cut, p.v[c], p.v[d]));
        out.e.push_back(a > 0 ? cut : p.e[c]);
      }
    }
  }

  /// The two corners where polys_[i] crosses `cut` (sides_ filled, both signs present).
  std::pair<int, int> crossingCorners(int F, std::size_t i, std::uint64_t cut) {
    const Poly& p = polys_[i];
    const std::size_t n = p.v.size();
    int c0 = -1, c1 = -1;
    for (std::size_t c = 0; c < n; ++c) {
      const std::size_t d = (c + 1) % n;
      const int a = sides_[c], b = sides_[d];
      int x = -1;
      if (a == 0 && b != 0) x = p.v[c];
      if ((a > 0 && b < 0) || (a < 0 && b > 0)) x = crossing(F, p.e[c], cut, p.v[c], p.v[d]);
      if (x < 0) continue;
      if (c0 < 0)
        c0 = x;
      else if (x != c0)
        c1 = x;
    }
    return {c0, c1 < 0 ? c0 : c1};
  }

  /// Splits every piece whose interior the segment (or triangle) `cut` crosses.
  template <class Meets>
  void cutPieces(int F, std::uint64_t cut, const Box3& reach, Meets&& meets) {
    const std::size_t n = polyCount_;
    for (std::size_t i = 0; i < n; ++i) {
      if (polys_[i].dead) continue;
      // The cut's polygon (or edge) lies in `reach`; a piece whose box misses it (with
      // room for rounding) cannot be crossed by it: no exact test is needed.
      if (!pieceBox(polys_[i]).overlaps(reach)) continue;
      if (!clipKeep(F, i, cut, 0)) continue;
      const std::pair<int, int> c = crossingCorners(F, i, cut);
      if (!meets(c.first, c.second)) continue;
      Poly& neg = newPoly();  // may reallocate polys_: index, not reference
      splitInto(F, i, cut, -1, neg);
      Poly& pos = newPoly();
      splitInto(F, i, cut, +1, pos);
      polys_[i].dead = true;
    }
  }

  static Box3 padded(Box3 b) {
    const double pad = std::ldexp(1.0, -30) * (b.hi.cwiseAbs().maxCoeff() + b.lo.cwiseAbs().maxCoeff() +
                                              (b.hi - b.lo).cwiseAbs().maxCoeff());
    b.lo.array() -= pad;
    b.hi.array() += pad;
    return b;
  }

  /// The box of a piece's corners, padded by a relative 2^-30 (their rounding, and then
  /// some: the box only decides which pieces are tested exactly).
  Box3 pieceBox(const Poly& p) const {
    Box3 b;
    for (int id : p.v) b.add(toD(coords_[static_cast<std::size_t>(id)]));
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(
        std::ldexp(1.0, -30) * (b.hi - b.lo).cwiseAbs().maxCoeff() + std::ldexp(1.0, -30) * b.hi.cwiseAbs().maxCoeff() +
        std::ldexp(1.0, -30) * b.lo.cwiseAbs().maxCoeff());
    b.lo -= pad;
    b.hi += pad;
    return b;
  }

  /// Cuts triangle F's pieces by every other soup triangle that crosses or overlaps it.
  void cutByOthers(int F) {
    const Soup& f = soup_[static_cast<std::size_t>(F)];
    Box3 query = f.box;
    if (region_.bounded)
      for (int a = 0; a < 3; ++a) {
        query.lo[a] = std::max(query.lo[a], toDouble(region_.lo[a]));
        query.hi[a] = std::min(query.hi[a], toDouble(region_.hi[a]));
      }
    cutters_.clear();
    tree_.forOverlapping(query, [&](int g) {
      if (g != F) cutters_.push_back(g);
    });
    coplanar_.clear();
    for (int G : cutters_) {
      const Soup& g = soup_[static_cast<std::size_t>(G)];
      // An edge of F in G's plane (G not one of its two polygons): a third sheet through
      // it, across which the pieces beside it must not be joined.
      for (int c = 0; c < f.nc; ++c) {
        const int a = f.m[c], b = f.m[(c + 1) % f.nc];
        if (pointSide(g, a) != 0 || pointSide(g, b) != 0) continue;
        bool side = false;
        for (int k = 0; k < g.nc; ++k)
          side = side || (g.m[k] == b && g.m[(k + 1) % g.nc] == a) || (g.m[k] == a && g.m[(k + 1) % g.nc] == b);
        if (!side) blocked_.insert(TrimLabel::edge(a, b));
      }
      int pos = 0, neg = 0;
      for (int c = 0; c < g.nc; ++c) {
        const int sc = pointSide(f, g.m[c]);
        pos += sc > 0;
        neg += sc < 0;
      }
      if (pos == 0 && neg == 0) {
        // In F's plane: cut by G's edges; remember G for the duplicate test.
        coplanar_.push_back(G);
        for (int c = 0; c < g.nc; ++c) {
          const int u = g.m[c], v = g.m[(c + 1) % g.nc];
          const std::uint64_t cut = TrimLabel::edge(u, v);
          Box3 reach;
          reach.add(toD(mCoord_[static_cast<std::size_t>(u)]));
          reach.add(toD(mCoord_[static_cast<std::size_t>(v)]));
          cutPieces(F, cut, padded(reach), [&](int c0, int c1) { return segmentOverlapsEdge(c0, c1, u, v); });
        }
        continue;
      }
      // On one side of F's plane: no crossing, unless an edge of G lies in F's plane (G
      // touches F along a line, as two walls meeting at a right angle in an aligned
      // configuration do): F's status may change across that line, so it is a cut.
      if ((pos == 0 || neg == 0) && g.nc - pos - neg < 2) continue;
      // Does F reach both sides of G's plane? Else no crossing either.
      int fp = 0, fn = 0;
      for (int c = 0; c < f.nc; ++c) {
        const int t = pointSide(g, f.m[c]);
        fp += t > 0;
        fn += t < 0;
      }
      if (fp == 0 || fn == 0) continue;
      cutPieces(F, TrimLabel::plane(G), padded(g.box), [&](int c0, int c1) { return segmentMayMeetTriangle(c0, c1, G); });
    }
  }

  /// False only if corners c0, c1 (on G's plane) are strictly outside the same side of
  /// polygon G (exact).
  bool segmentMayMeetTriangle(int c0, int c1, int G) const {
    const Soup& g = soup_[static_cast<std::size_t>(G)];
    for (int c = 0; c < g.nc; ++c) {
      const std::uint64_t e = TrimLabel::edge(g.m[c], g.m[(c + 1) % g.nc]);
      // side() > 0 is the left of the edge's first → second point; polygon G is
      // counter-clockwise, so outside is the right when m[c] < m[c + 1], else the left.
      const int out = g.m[c] < g.m[(c + 1) % g.nc] ? -1 : 1;
      if (side(G, c0, e) == out && side(G, c1, e) == out) return false;
    }
    return true;
  }

  /// False only if corners c0, c1 (on the line of u v) both lie beyond the same end of the
  /// segment u v (exact).
  bool segmentOverlapsEdge(int c0, int c1, int u, int v) const {
    if (dotSign(c0, u, v) < 0 && dotSign(c1, u, v) < 0) return false;
    if (dotSign(c0, v, u) < 0 && dotSign(c1, v, u) < 0) return false;
    return true;
  }

  // ----- Classification ---------------------------------------------------------------

  Vec3<T> centroid(const Poly& p) const {
    Vec3<T> c = Vec3<T>::Zero();
    for (int id : p.v) c += coords_[static_cast<std::size_t>(id)];
    return c / T(static_cast<int>(p.v.size()));
  }

  /// Does the piece meet the ball? (Squared distances, no root: exact for exact T.)
  bool meetsBall(const Poly& p) const { return polygonMeetsBall(p.v.data(), static_cast<int>(p.v.size())); }
  /// Does the convex polygon of corners v[0 .. n) meet the ball?
  bool polygonMeetsBall(const int* v, int count) const {
    const Vec3<T>& c = region_.centre;
    const T r2 = region_.radius * region_.radius;
    // Nearest point of the convex polygon: inside it (projection), else on a side.
    const std::size_t n = static_cast<std::size_t>(count);
    const Vec3<T>& x0 = coords_[static_cast<std::size_t>(v[0])];
    const Vec3<T> nrm = (coords_[static_cast<std::size_t>(v[1])] - x0).cross(coords_[static_cast<std::size_t>(v[n - 1])] - x0);
    const T nn = nrm.squaredNorm();
    bool inside = nn > T(0);
    for (std::size_t i = 0; i < n && inside; ++i) {
      const Vec3<T>& a = coords_[static_cast<std::size_t>(v[i])];
      const Vec3<T>& b = coords_[static_cast<std::size_t>(v[(i + 1) % n])];
      if ((b - a).cross(c - a).dot(nrm) < T(0)) inside = false;
    }
    if (inside) {
      const T h = nrm.dot(c - x0);
      return h * h <= r2 * nn;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3<T>& a = coords_[static_cast<std::size_t>(v[i])];
      const Vec3<T>& b = coords_[static_cast<std::size_t>(v[(i + 1) % n])];
      const Vec3<T> d = b - a;
      const T dd = d.squaredNorm();
      T t = dd > T(0) ? T((c - a).dot(d) / dd) : T(0);
      if (t < T(0)) t = T(0);
      if (t > T(1)) t = T(1);
      if ((a + t * d - c).squaredNorm() <= r2) return true;
    }
    return false;
  }

  /// Is the piece inside a coplanar, equally oriented soup triangle of lower index (which
  /// then emits this part of ∂M)? The piece lies inside it or outside it (step 2).
  bool ownedByOther(int F, const Poly& p) const {
    if (coplanar_.empty()) return false;
    const Soup& f = soup_[static_cast<std::size_t>(F)];
    const Vec3<T> x = centroid(p);
    for (int G : coplanar_) {
      if (G > F) continue;
      const Soup& g = soup_[static_cast<std::size_t>(G)];
      if (g.axis != f.axis || g.axisSign != f.axisSign) continue;  // opposite orientation
      bool inside = true;
      for (int c = 0; c < g.nc && inside; ++c)
        inside = f.axisSign * orient2d(mCoord_[g.m[c]], mCoord_[g.m[(c + 1) % g.nc]], x, f.axis) > 0;
      if (inside) return true;
    }
    return false;
  }

  /// Is the piece on ∂M? One collision test at its centroid moved outward by δ.
  bool onBoundary(int piece, MeshOverlap<T>& overlap) const {
    const Final& fp = final_[static_cast<std::size_t>(piece)];
    const int F = fp.soup;
    const Soup& f = soup_[static_cast<std::size_t>(F)];
    Vec3<T> x = Vec3<T>::Zero();
    for (int k = 0; k < fp.count; ++k) x += coords_[static_cast<std::size_t>(finalV_[static_cast<std::size_t>(fp.first + k)])];
    x /= T(fp.count);
    const Eigen::Vector3d xd = toD(x);
    Eigen::Vector3d nd = toD(f.n);
    nd /= nd.norm();
    double bound = std::numeric_limits<double>::infinity();
    if (region_.bounded)
      for (int a = 0; a < 3; ++a) {
        const double d = std::min(xd[a] - toDouble(region_.lo[a]), toDouble(region_.hi[a]) - xd[a]);
        bound = std::min(bound, d * d);
      }
    const double d2 = tree_.nearest(xd, bound, [&](int G) {
      if (G == F) return std::numeric_limits<double>::infinity();
      const Soup& g = soup_[static_cast<std::size_t>(G)];
      bool inPlane = true;
      for (int c = 0; c < g.nc && inPlane; ++c) inPlane = pointSide(f, g.m[c]) == 0;
      if (inPlane) return std::numeric_limits<double>::infinity();  // in F's plane: the motion leaves it
      double d = squaredDistanceToTriangle(xd, toD(mCoord_[g.m[0]]), toD(mCoord_[g.m[1]]), toD(mCoord_[g.m[2]]));
      if (g.nc == 4)
        d = std::min(d, squaredDistanceToTriangle(xd, toD(mCoord_[g.m[0]]), toD(mCoord_[g.m[2]]), toD(mCoord_[g.m[3]])));
      return d;
    });
    double delta = 0.5 * std::sqrt(d2);
    if (!std::isfinite(delta)) {
      delta = 0.0;
      for (int c = 0; c < f.nc; ++c) delta = std::max(delta, (toD(mCoord_[f.m[c]]) - xd).norm());
    }
    Vec3<T> y;
    for (int a = 0; a < 3; ++a) y[a] = x[a] + T(delta * nd[a]);
    // Most pieces inside M overlap where the last one did (they are tested in order along
    // the facets): that triangle pair first, exactly, before a full traversal.
    if (witnessA_ >= 0) {
      const auto& ta = frame_->A().triangle(witnessA_);
      const auto& tb = frame_->B().triangle(witnessB_);
      if (trianglesIntersect(frame_->a(ta[0]), frame_->a(ta[1]), frame_->a(ta[2]), Vec3<T>(frame_->b(tb[0]) + y),
                             Vec3<T>(frame_->b(tb[1]) + y), Vec3<T>(frame_->b(tb[2]) + y)))
        return false;
    }
    if (!overlap.overlaps(y)) return true;
    if (overlap.result().status == OverlapStatus::BoundariesMeet)
      witnessA_ = overlap.result().triangleA, witnessB_ = overlap.result().triangleB;
    return false;
  }

  static double squaredDistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c) {
    // Closest point on a triangle (C. Ericson, Real-Time Collision Detection, 5.1.5).
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + (d1 / (d1 - d3)) * ab)).squaredNorm();
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + (d2 / (d2 - d6)) * ac)).squaredNorm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
      return (p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b))).squaredNorm();
    const double den = 1.0 / (va + vb + vc);
    return (p - (a + ab * (vb * den) + ac * (vc * den))).squaredNorm();
  }

  void emit(int piece, MinkowskiPatch<T>& out) {
    const Final& fp = final_[static_cast<std::size_t>(piece)];
    const Soup& f = soup_[static_cast<std::size_t>(fp.soup)];
    const ConvolutionPair& pair = (*facets_)[static_cast<std::size_t>(f.facet)];
    auto index = [&](int id) {
      if (static_cast<std::size_t>(id) >= outVertex_.size()) outVertex_.resize(static_cast<std::size_t>(id) + 1, -1);
      int& o = outVertex_[static_cast<std::size_t>(id)];
      if (o < 0) {
        o = static_cast<int>(out.vertices.size());
        out.vertices.push_back(coords_[static_cast<std::size_t>(id)]);
      }
      return o;
    };
    const int* v = &finalV_[static_cast<std::size_t>(fp.first)];
    for (int i = 1; i + 1 < fp.count; ++i) {
      // A fan triangle of a piece that meets the ball may itself miss it: the patch keeps
      // only triangles that meet the ball.
      const int tri[3] = {v[0], v[i], v[i + 1]};
      if (region_.ball && !polygonMeetsBall(tri, 3)) continue;
      out.triangles.push_back({index(v[0]), index(v[i]), index(v[i + 1])});
      out.pairs.push_back(pair);
    }
  }

  const ConvolutionFrame<T>* frame_ = nullptr;
  const std::vector<ConvolutionPair>* facets_ = nullptr;
  Region region_;
  std::unordered_map<std::uint64_t, int> mIndex_;
  std::vector<std::pair<int, int>> mPair_;
  std::vector<Vec3<T>> mCoord_;
  std::vector<Soup> soup_;
  std::vector<Box3> boxes_;
  BoxTree tree_;
  std::unordered_map<TrimKey, int, TrimKeyHash> keyIndex_;
  std::vector<TrimKey> keys_;
  std::vector<Vec3<T>> coords_;
  std::vector<Homog> hbox_;  // floating T: each corner's enclosure (empty for points)
  struct PlaneIVCache {
    IV n[3], k;
    bool ready = false;
  };
  mutable std::vector<PlaneIVCache> planeCache_;  // floating T: per polygon, made on first use
  mutable PlaneIVCache boxCache_[6];
  mutable int witnessA_ = -1, witnessB_ = -1;  // the last triangle pair found overlapping
  std::vector<Poly> polys_;
  std::size_t polyCount_ = 0;
  Poly scratch_;
  std::vector<int> sides_, cutters_, coplanar_, outVertex_;
  std::vector<Final> final_;
  std::vector<int> finalV_, parent_, status_, representative_;
  std::vector<std::uint64_t> finalE_;
  std::unordered_map<std::uint64_t, int> edgeUse_, sideOwner_;
  std::unordered_set<std::uint64_t> blocked_;  // soup edges lying in another polygon's plane
};

}  // namespace detail
}  // namespace mink
