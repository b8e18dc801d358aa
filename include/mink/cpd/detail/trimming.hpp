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
//   4. The pieces on ∂M become triangles that meet edge to edge: a corner of one piece
//      inside a side of another on the same line is put into that side (conform, emit).
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
#include <utility>
#include <vector>

#include "mink/core/detail/flat_hash_map.hpp"
#include "mink/core/double_double.hpp"
#include "mink/core/expansion.hpp"
#include "mink/core/orientation.hpp"
#include "mink/cpd/convolution.hpp"
#include "mink/mesh/detail/box_tree.hpp"
#include "mink/mesh/detail/closest_point.hpp"
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
  using IVD = DoubleDoubleInterval;       // the first wider filter (about 106 bits; FloatOf = double)
  using EX = ExpansionOf<FloatOf>;
  struct Homog {
    IV X[3];
    IV W = IV(FloatOf(1));
    IV x[3];             // X / W: an enclosure of the corner itself
    bool boxed = false;  // x is finite (W excludes 0)
    FloatOf mr[8] = {};  // boxed: (x, −1) as midpoints mr[0..3] and radii mr[4..7] (dotSignByRadius)
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
      if (belowResolution(polys_[0])) {  // every piece would be a sliver
        ++out.facetsBelowResolution;
        continue;
      }
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
        if (isSliver(p)) continue;
        finalV_.insert(finalV_.end(), p.v.begin(), p.v.end());
        finalE_.insert(finalE_.end(), p.e.begin(), p.e.end());
        f.wanted = (!region_.ball || meetsBall(p)) && !ownedByOther(static_cast<int>(s), p);
        final_.push_back(f);
      }
    }
    out.pieces += static_cast<int>(final_.size());
    // 2. Pieces joined into patches where no facet separates them; 3. each patch that
    // holds a wanted piece inside M by a side or by one collision test; 4. the wanted
    // pieces of patches on ∂M.
    stitch();
    classify(overlap, out);
    // 5. Triangles that meet edge to edge (trim_patches.hpp: conform, emit).
    conform();
    outVertex_.clear();
    for (const int i : emitted_) emit(i, out);
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

  /// Approximate area of a piece, for choosing the piece a patch is tested at (stableNorm:
  /// no overflow or underflow for any size fromMesh accepts).
  double approxArea(const Poly& p) const {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    const Eigen::Vector3d x0 = toD(coords_[static_cast<std::size_t>(p.v[0])]);
    for (std::size_t i = 1; i + 1 < p.v.size(); ++i)
      n += (toD(coords_[static_cast<std::size_t>(p.v[i])]) - x0).cross(toD(coords_[static_cast<std::size_t>(p.v[i + 1])]) - x0);
    return 0.5 * n.stableNorm();
  }
  /// Has the piece no area to rounding (trim_pieces.hpp)? Such a piece is dropped.
  bool isSliver(const Poly& p) const;
  /// Would every piece cut from p be a sliver (trim_pieces.hpp)? Then p is not cut.
  bool belowResolution(const Poly& p) const;

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
  void stitch();

  /// Does some polygon other than F pass along the side a b of a piece of F? A polygon
  /// crossing F's plane does where its plane holds the side and it reaches the side (not
  /// strictly outside one of its edges); a polygon in F's plane does where one of its
  /// edges is collinear with the side and overlaps it.
  bool sideCrossed(int F, int a, int b) const;

  static std::uint64_t sideKey(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }

  /// May a facet pass along the side a b (line `label`) of polygon F, next to polygon G?
  /// A side too short to be told from a point (two names of one point in a degenerate
  /// configuration) joins nothing: pieces that share only a point may differ.
  bool separated(int F, int G, std::uint64_t label, int a, int b) const;

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
    planeCacheL_.clear();
    planeCacheD_.clear();
    planeCacheX_.clear();
    cornerL_.clear();
    cornerD_.clear();
    cornerXIndex_.clear();
    cornerXCount_ = 0;
    exactSide_.clear();
    for (PlaneIVCache& c : boxCache_) c.ready = false;  // the region's faces: made again
    sameLine_.clear();
    sideCrossed_.clear();
    witnesses_.clear();
    nextWitness_ = 0;
    final_.clear();
    finalV_.clear();
    finalE_.clear();
    blocked_.clear();
  }

  // ----- The soup -------------------------------------------------------------------

  int mVertex(int i, int j);

  static Eigen::Vector3d toD(const Vec3<T>& x) { return Eigen::Vector3d(toDouble(x[0]), toDouble(x[1]), toDouble(x[2])); }

  void buildSoup();

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
  int addCorner(const TrimKey& key, const Vec3<T>& x);
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
      toMidRadius(h.x[k], h.mr[k], h.mr[k + 4]);
    }
    h.mr[3] = FloatOf(-1);
  }
  int pointCorner(int mid) { return corner(keyOf(static_cast<std::uint64_t>(mid))); }

  /// The corner where the side of F on line `side` meets line `cut` (both lines of F's plane).
  /// Where an end point of an edge line lies on the other line (an edge of a coplanar
  /// facet extended across F through a corner, a corner on a cutting plane or box face),
  /// the crossing is that point, and named as such: one point, one name.
  int crossing(int F, std::uint64_t side, std::uint64_t cut, int ia, int ib);

  /// The corner named `key`, made on the side from corner ia to corner ib where it meets
  /// `cut`: from its planes (canonical, shared with every other facet that makes it), or,
  /// for floating-point T where that construction is not on the side (ill-conditioned:
  /// nearly parallel planes), by interpolation of the signed distances to `cut` along it.
  int cornerOn(const TrimKey& key, int F, std::uint64_t cut, int ia, int ib);

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
  PlaneEq planeOf(std::uint64_t x) const;

  Vec3<T> compute(const TrimKey& key) const;

  // ----- Sides ------------------------------------------------------------------------

  /// Side of corner id of line `cut` within facet F's plane: > 0 outside / on the far side.
  /// Plane(G): orient3d against G; box face: outside the box is > 0; edge (a line of F's
  /// plane): the left of the edge's first → second point, seen along F's normal, is > 0.
  int side(int F, int id, std::uint64_t cut) const;

  /// Do lines l and cut of F's plane coincide? (Each is an edge line, or the trace on F's
  /// plane of another polygon's plane or of a box face.) Exact on the named inputs: an edge
  /// line lies in a plane when both its ends do; two plane traces coincide when the planes
  /// do (the case of two different planes through one line of F is not detected).
  bool sameLine(int F, std::uint64_t l, std::uint64_t cut) const;
  /// sameLine, once per pair of lines (and F, for two edge lines).
  bool sameLineCached(int F, std::uint64_t l, std::uint64_t cut) const;

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
  void planeN(std::uint64_t l, N n[3], N& k) const;
  /// The corner named `key` as X / W.
  template <class N>
  void homogeneous(const TrimKey& key, N X[3], N& W) const;
  /// planeN in interval arithmetic, cached per polygon (box faces are exact); mr: as midpoints and radii.
  void planeIV(std::uint64_t l, const IV*& n, const IV*& k, const FloatOf** mr = nullptr) const;
  /// planeN of label l: a polygon's from its cache (N: IV, IVL or EX), a box face's made
  /// in boxN, boxK.
  template <class N>
  void planeCached(std::uint64_t l, const N*& n, const N*& k, N boxN[3], N& boxK) const;

  /// The value whose sign (times sign(W)) is side(): see side().
  template <class N>
  N cutValue(int F, std::uint64_t cut, const N X[3], const N& W) const;
  /// side() of a constructed corner by the interval filter: ±1, or 0 when it cannot tell.
  int filteredSide(int F, int id, std::uint64_t cut) const;
  /// side() of a constructed corner from its name (cached): namedSign of cutValue.
  int exactSide(int F, int id, std::uint64_t cut) const;
  /// The exact sign of value(X, W) · sign(W) for the corner named `key` (value: a
  /// polynomial in X / W, called with long double intervals, then with expansions).
  template <class Value>
  int namedSign(int id, const Value& value) const;
  /// Exact sign of (x − p) · (q − p) for corner id and points p, q (ids of a_i − b_j).
  int dotSign(int id, int p, int q) const;

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
  bool initialPiece(int F);

  /// Cuts polys_[i] by line `cut`: keepSide −1 keeps the part with side <= 0 (in place) and
  /// returns false if nothing is left; keepSide 0 splits it into both parts (the positive
  /// one appended) and returns true if it was cut.
  bool clipKeep(int F, std::size_t i, std::uint64_t cut, int keepSide);

  /// out := the part of polys_[i] on side `keep` (+1 / −1) of `cut` (sides_ filled).
  void splitInto(int F, std::size_t i, std::uint64_t cut, int keep, Poly& out);

  /// The two corners where polys_[i] crosses `cut` (sides_ filled, both signs present).
  std::pair<int, int> crossingCorners(int F, std::size_t i, std::uint64_t cut);

  /// Splits every piece whose interior the segment (or triangle) `cut` crosses.
  template <class Meets>
  void cutPieces(int F, std::uint64_t cut, const Box3& reach, Meets&& meets);

  static Box3 padded(Box3 b) {
    const double pad = std::ldexp(1.0, -30) * (b.hi.cwiseAbs().maxCoeff() + b.lo.cwiseAbs().maxCoeff() +
                                              (b.hi - b.lo).cwiseAbs().maxCoeff());
    b.lo.array() -= pad;
    b.hi.array() += pad;
    return b;
  }

  /// The box of a piece's corners, padded by a relative 2^-30 (their rounding, and then
  /// some: the box only decides which pieces are tested exactly).
  Box3 pieceBox(const Poly& p) const;

  /// Cuts triangle F's pieces by every other soup triangle that crosses or overlaps it.
  void cutByOthers(int F);

  /// False only if corners c0, c1 (on G's plane) are strictly outside the same side of
  /// polygon G (exact).
  bool segmentMayMeetTriangle(int c0, int c1, int G) const;

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

  bool meetsBall(const Poly& p) const { return polygonMeetsBall(p.v.data(), static_cast<int>(p.v.size())); }
  /// Does the convex polygon of corners v[0 .. n) meet the closed ball? Exact on the corners,
  /// centre and radius given (trim_patches.hpp); ballTest: +1 yes, −1 no, 0 (intervals) unsure.
  bool polygonMeetsBall(const int* v, int count) const;
  template <class N>
  int ballTest(const int* v, int count) const;

  /// Is the piece inside a coplanar, equally oriented soup triangle of lower index (which
  /// then emits this part of ∂M)? The piece lies inside it or outside it (step 2).
  bool ownedByOther(int F, const Poly& p) const;
  /// Steps 3 and 4 (trim_patches.hpp): the patches' status_, emitted_.
  void classify(MeshOverlap<T>& overlap, MinkowskiPatch<T>& out);
  /// Is the piece inside M by a side on a crossing polygon (trim_patches.hpp)?
  bool insideAcrossCut(int piece) const;
  bool openSideInPolygon(int a, int b, int G) const;
  bool clearOfRounding(const Final& fp, int k, int G) const;

  /// Is the piece on ∂M? One collision test at its centroid moved outward by δ.
  bool onBoundary(int piece, MeshOverlap<T>& overlap) const;

  static double squaredDistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c) {
    return (p - closestPointOnTriangle(p, a, b, c)).squaredNorm();
  }

  /// The line a side labelled `label` of a piece of `soup` lies on, as a key (trim_patches.hpp).
  static TrimKey lineOf(int soup, std::uint64_t label);
  static bool lineOrder(const std::pair<TrimKey, int>& x, const std::pair<TrimKey, int>& y);
  void conform();
  void emit(int piece, MinkowskiPatch<T>& out);

  const ConvolutionFrame<T>* frame_ = nullptr;
  const std::vector<ConvolutionPair>* facets_ = nullptr;
  Region region_;
  FlatHashMap<std::uint64_t, int> mIndex_;
  std::vector<std::pair<int, int>> mPair_;
  std::vector<Vec3<T>> mCoord_;
  std::vector<Soup> soup_;
  std::vector<Box3> boxes_;
  BoxTree tree_;
  FlatHashMap<TrimKey, int, TrimKeyHash> keyIndex_;
  std::vector<TrimKey> keys_;
  std::vector<Vec3<T>> coords_;
  std::vector<Homog> hbox_;  // floating T: each corner's enclosure (empty for points)
  template <class N>
  struct PlaneCacheOf {
    N n[3], k;
    bool ready = false;
    FloatOf mr[8] = {};  // N = IV: (n, k) as midpoints and radii, as Homog::mr (made on first use)
  };
  using PlaneIVCache = PlaneCacheOf<IV>;
  // Floating T: each polygon's plane in the number types of the predicates on corners,
  // made on first use (a corner's three planes are shared with the other corners they cut).
  mutable std::vector<PlaneIVCache> planeCache_;
  mutable std::vector<PlaneCacheOf<IVL>> planeCacheL_;
  mutable std::vector<PlaneCacheOf<IVD>> planeCacheD_;
  mutable std::vector<PlaneCacheOf<EX>> planeCacheX_;
  template <class N>
  std::vector<PlaneCacheOf<N>>& planeCacheFor() const {
    if constexpr (std::is_same<N, IV>::value)
      return planeCache_;
    else if constexpr (std::is_same<N, IVL>::value)
      return planeCacheL_;
    else if constexpr (std::is_same<N, IVD>::value)
      return planeCacheD_;
    else
      return planeCacheX_;
  }
  mutable PlaneIVCache boxCache_[6];
  // Floating T: a corner's X / W in double-double (cornerD_) and long double (cornerL_,
  // where it is wider) intervals, made from its name on its first exact predicate (a
  // corner meets several cuts); namedSign asks them in that order.
  template <class N>
  struct CornerOf {
    N X[3], W;
    bool ready = false;
  };
  mutable std::vector<CornerOf<IVL>> cornerL_;
  mutable std::vector<CornerOf<IVD>> cornerD_;
  // The same in expansions, for the corners whose sides the intervals cannot tell.
  struct CornerX {
    EX X[3], W;
  };
  mutable std::vector<int> cornerXIndex_;  // per corner: its entry of cornerX_, or −1
  mutable std::vector<CornerX> cornerX_;
  mutable std::size_t cornerXCount_ = 0;
  mutable FlatHashMap<TrimKey, int, TrimKeyHash> exactSide_;  // (corner, cut, F) -> exact side
  mutable FlatHashMap<TrimKey, int, TrimKeyHash> sameLine_;   // (lines sorted, F or kNone) -> 1 / 0
  mutable FlatHashMap<TrimKey, int, TrimKeyHash> sideCrossed_;  // (F, corner ids sorted) -> 1 / 0
  // The last triangle pairs found overlapping (a ring of kWitnesses).
  static constexpr std::size_t kWitnesses = 16;
  mutable std::vector<std::pair<int, int>> witnesses_;
  mutable std::size_t nextWitness_ = 0;
  std::vector<Poly> polys_;
  std::size_t polyCount_ = 0;
  Poly scratch_;
  std::vector<int> sides_, cutters_, coplanar_, outVertex_, emitted_, ring_;
  std::vector<std::pair<TrimKey, int>> lineCorners_;  // (line, corner) of the emitted pieces' sides
  std::vector<Final> final_;
  std::vector<int> finalV_, parent_, status_, representative_;
  std::vector<std::uint64_t> finalE_;
  FlatHashMap<std::uint64_t, int> edgeUse_, sideOwner_;
  FlatHashSet<std::uint64_t> blocked_;  // soup edges lying in another polygon's plane
};

}  // namespace detail
}  // namespace mink

// The member definitions, by stage.
#include "mink/cpd/detail/trim_corners.hpp"
#include "mink/cpd/detail/trim_pieces.hpp"
#include "mink/cpd/detail/trim_patches.hpp"
