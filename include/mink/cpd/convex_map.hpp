// mink/cpd/convex_map.hpp — the convex map C(X) of a closed triangle mesh X: a convex
// polyhedron whose Gauss map subdivides X's, with correspondence sets back to X, used to
// find the compatible partners of a direction or an arc without scanning X.
//
// Source: Y. Lee, E. Behar, J.-M. Lien, Y. J. Kim, CAD 2016, section 4 (Algorithm 1) and
// Appendix A.
//   1. The points: the unit normals of X's faces, and the midpoint of the long arc of every
//      reflex edge (section 4.2: sub-arcs then have length < π).
//   2. C(X) is the intersection of the half-spaces tangent to the unit sphere at those
//      points: the polar dual of their convex hull H (built by ConvexPolyhedron's exact
//      quickhull), so C(X)'s vertices are H's faces and the Gauss-map cell of a vertex of
//      C(X) is the cone over a face of H.
//   3. Correspondence sets, per cell: V̄ — the vertices v of X whose cone of directions in
//      which v is a local maximum over its star (its Gauss region for a convex vertex;
//      possibly empty at a saddle) meets the cell; Ē — the convex edges of X whose short
//      arc meets the cell. (F̄ is not needed: faces are enumerated directly.)
// The paper claims G(C(X)) subdivides X's Gauss-map arrangement; it does not in general
// (a Delaunay triangulation of the normals need not keep X's arcs), so mink makes the
// correspondence conservative instead: a set lists everything whose region merely meets
// the cell, and every candidate is then decided by the exact compatibility predicates of
// cpd/convolution.hpp. The map is a search structure in double (slack 1e-7 in its
// tests), built once per mesh; it never decides a compatibility by itself.
//
// Queries (X's frame, any non-zero direction): vertex candidates for a direction d (the v
// with d in their region), edge candidates for an arc p → q (shorter than π). Each walks
// from a hint cell (the last answer: frame coherence) to the cell of d. The map is
// immutable once built and may be shared by threads; the arc query's work space is the
// caller's (ConvexMap::Walk, one per thread).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "mink/core/orientation.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/mesh/triangle_mesh.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {

template <class T>
class ConvexMap {
 public:
  using V3 = Eigen::Vector3d;

  /// Builds C(X) and its correspondence sets (O(n) cells, each vertex and edge of X
  /// registered in the few cells its region meets).
  explicit ConvexMap(const TriangleMesh<T>& X) {
    std::vector<V3> pts;
    pts.reserve(static_cast<std::size_t>(X.numTriangles() + X.numEdges() / 4 + 8));
    for (int t = 0; t < X.numTriangles(); ++t) pts.push_back(faceUnit(X, t));
    for (int e = 0; e < X.numEdges(); ++e) {
      if (X.edgeKind(e) != EdgeKind::Reflex) continue;
      const auto tt = X.edgeTriangles(e);
      const V3 m = -(faceUnit(X, tt.first) + faceUnit(X, tt.second));
      if (m.norm() > 0) pts.push_back(m.normalized());  // the long arc's midpoint
    }
    // Normals equal to rounding (the two triangles of a flat quad) would make cells of
    // zero width: the first of each run of near-equal points (in lexicographic order) is
    // kept. Any subdivision serves: the correspondence sets are conservative.
    std::sort(pts.begin(), pts.end(), [](const V3& a, const V3& b) {
      return a[0] < b[0] || (a[0] == b[0] && (a[1] < b[1] || (a[1] == b[1] && a[2] < b[2])));
    });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (kept == 0 || (pts[i] - pts[kept - 1]).norm() > 1e-12) pts[kept++] = pts[i];
    pts.resize(kept);
    // The six axis directions too: the cones over H's faces must cover the sphere, which
    // needs the origin inside H. The exact normals of a closed mesh are in no closed
    // hemisphere, but a sliver's rounded ones can all lie on a great circle (a tetrahedron
    // one denormal thick: its four unit normals came out as three coplanar points).
    for (int a = 0; a < 3; ++a)
      for (double sgn : {1.0, -1.0}) {
        V3 x = V3::Zero();
        x[a] = sgn;
        pts.push_back(x);
      }
    H_ = std::make_shared<const ConvexPolyhedron<double>>(ConvexPolyhedron<double>::fromPoints(pts));
    const int nf = H_->numFaces();
    reach_.assign(static_cast<std::size_t>(nf), 0.0);
    for (int f = 0; f < nf; ++f) {
      const int s = H_->faceStart(f), n = H_->faceSize(f);
      for (int k = 1; k < n; ++k)
        reach_[static_cast<std::size_t>(f)] = std::max(reach_[static_cast<std::size_t>(f)],
                                                      (H_->vertex(H_->heOrigin(s + k)) - H_->vertex(H_->heOrigin(s))).norm());
    }
    std::vector<std::vector<int>> vsets(static_cast<std::size_t>(nf)), esets(static_cast<std::size_t>(nf));
    Walk walk;
    for (int v = 0; v < X.numVertices(); ++v) registerVertex(X, v, walk, vsets);
    for (int e = 0; e < X.numEdges(); ++e)
      if (X.edgeKind(e) == EdgeKind::Convex) registerEdge(X, e, walk, esets);
    pack(vsets, vStart_, vItems_);
    pack(esets, eStart_, eItems_);
    measure(X);
  }

  /// The convex map of X, built on the first request and shared by every user of X.
  static std::shared_ptr<const ConvexMap> of(const TriangleMesh<T>& X) {
    return X.template derived<ConvexMap>([&] { return new ConvexMap(X); });
  }

  /// The polytope H whose faces are the cells (the polar dual of C(X)).
  const ConvexPolyhedron<double>& hull() const { return *H_; }
  int numCells() const { return H_->numFaces(); }

  /// The cell whose cone holds direction d (walked from `hint`, a cell or −1).
  int locate(const V3& d, int hint = -1) const {
    const ConvexPolyhedron<double>& H = *H_;
    int f = hint >= 0 && hint < H.numFaces() ? hint : 0;
    const int cap = 4 * H.numFaces() + 16;
    for (int step = 0; step < cap; ++step) {
      int next = -1, least = -1;
      double worst = 0.0, smallest = 1e300;
      const int s = H.faceStart(f), n = H.faceSize(f);
      for (int k = 0; k < n; ++k) {
        const int h = s + k;
        const double side = H.vertex(H.heOrigin(h)).cross(H.vertex(H.heTarget(h))).dot(d);
        if (side < worst) worst = side, next = H.heFace(H.heTwin(h));
        if (side < smallest) smallest = side, least = H.heFace(H.heTwin(h));
      }
      // A sliver cell (corners equal to rounding) passes every side test for its antipode
      // too: a cell holds d only if d is on its side of the origin.
      if (next < 0 && (!facesToward(f, d) || !nearTinyCell(f, d))) next = least;
      if (next < 0) return f;
      f = next;
    }
    // The walk cycled (d on cell boundaries within rounding): the best cell by scanning.
    int best = 0;
    double bestSide = -1e300;
    for (int g = 0; g < H.numFaces(); ++g) {
      double m = 1e300;
      const int s = H.faceStart(g), n = H.faceSize(g);
      if (!facesToward(g, d) || !nearTinyCell(g, d)) continue;
      for (int k = 0; k < n; ++k)
        m = std::min(m, H.vertex(H.heOrigin(s + k)).cross(H.vertex(H.heTarget(s + k))).dot(d));
      if (m > bestSide) bestSide = m, best = g;
    }
    return best;
  }

  /// False where cell f is tiny (its corners within kTinyCell of each other) and d is not
  /// near it. A tiny cell's sides are cross products of nearly equal unit vectors, whose
  /// directions are rounding: every side test can pass for a d far from it (a cell of
  /// three normals 4e-16 apart held directions 0.012 rad away, and a walk from it never
  /// reached the arc it was asked about). Such a cell holds d only within its own reach
  /// (and kTinyCell) of its first corner; a larger cell's side tests are accurate to
  /// rounding over its size.
  bool nearTinyCell(int f, const V3& d) const {
    const double reach = reach_[static_cast<std::size_t>(f)];
    if (!(reach < kTinyCell)) return true;
    const double l = d.norm();
    return l > 0 && (d / l - H_->vertex(H_->heOrigin(H_->faceStart(f)))).norm() <= reach + kTinyCell;
  }

  /// Is d on cell f's side of the origin? (d in the cone over f is a non-negative
  /// combination of its corners, so some corner has a positive dot product with it.)
  bool facesToward(int f, const V3& d) const {
    const int s = H_->faceStart(f), n = H_->faceSize(f);
    for (int k = 0; k < n; ++k)
      if (H_->vertex(H_->heOrigin(s + k)).dot(d) > 0) return true;
    return false;
  }

  /// The angle (radians, as a difference of unit vectors) by which every registration
  /// and arc test is widened: a direction located in the map may be off the one the exact
  /// predicates see by at most half of it (see answersPlacement).
  static constexpr double kSlack = 1e-7;
  /// A cell whose corners are all within this (chord) of its first corner is located by
  /// distance, not by its sides (nearTinyCell): far below kSlack.
  static constexpr double kTinyCell = 1e-9;

  /// A lower bound on the smallest height of X's triangles (0 if rounding could hide a
  /// degenerate one), and the largest |coordinate| of X's vertices, both in double.
  double leastHeight() const { return leastHeight_; }
  double extent() const { return extent_; }

  /// Does this map (X's own frame) still answer for X placed by fl(R x + t) in T, which is
  /// what the exact compatibility tests see? X's edge directions and face normals as
  /// placed differ from R times X's own by the rounding of the placement (at most 8 δ / h
  /// for a normal and 4 δ / h for an edge, h the least height, δ the per-coordinate error
  /// of fl(R x + t), bounded by 4 eps (3 |x|∞ + |t|∞)) and by R's departure from
  /// orthonormality E = R^T R − I (the lookups rotate normals by R, the placed triangles'
  /// normals turn by R^−T). A located direction and the cone it is tested against may
  /// then each be off by those angles, which must stay within half the slack. Fails for
  /// shapes thinner than about 1e-7 / eps of the placement's scale: a needle of width
  /// 2^-79 placed at distance 1 (its corners merge when rounded) or, in float, almost
  /// every shape.
  template <class M, class V>
  bool answersPlacement(const M& R, const V& t) const {
    if constexpr (ScalarTraits<T>::isExact) {
      (void)R, (void)t;
      return true;
    } else {
      const double eps = detail::toDouble(ScalarTraits<T>::epsilon());
      double tMax = 0.0, eMax = 0.0;
      for (int i = 0; i < 3; ++i) tMax = std::max(tMax, std::abs(detail::toDouble(t[i])));
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double e = i == j ? -1.0 : 0.0;
          for (int k = 0; k < 3; ++k) e += detail::toDouble(R(k, i)) * detail::toDouble(R(k, j));
          eMax = std::max(eMax, std::abs(e));
        }
      if (!(leastHeight_ > 0)) return false;
      const double delta = 4.0 * eps * (3.0 * extent_ + tMax);
      const double angle = 16.0 * delta / leastHeight_ + 8.0 * (eMax + 8.0 * eps);
      return angle <= 0.5 * kSlack;
    }
  }

  /// V̄(cell): vertices of X whose local-maximum cone meets the cell.
  IndexRange vertices(int cell) const { return range(vStart_, vItems_, cell); }
  /// Ē(cell): convex edges of X whose short Gauss arc meets the cell.
  IndexRange edges(int cell) const { return range(eStart_, eItems_, cell); }

  /// Work space of the breadth-first walks (marks per cell with O(1) clearing).
  struct Walk {
    std::vector<unsigned> marks;
    unsigned epoch = 0;
    std::vector<int> stack;
    void begin(int cells) {
      if (marks.size() != static_cast<std::size_t>(cells)) marks.assign(static_cast<std::size_t>(cells), 0u), epoch = 0;
      if (++epoch == 0) std::fill(marks.begin(), marks.end(), 0u), epoch = 1;
      stack.clear();
    }
    bool mark(int f) {
      if (marks[static_cast<std::size_t>(f)] == epoch) return false;
      marks[static_cast<std::size_t>(f)] = epoch;
      return true;
    }
  };

  /// Calls visit(cell) for every cell the arc p → q (unit vectors, not antipodal) meets,
  /// starting at `hint` (updated to the cell of p).
  template <class Visit>
  void forCellsOnArc(const V3& p, const V3& q, int& hint, Walk& walk, Visit&& visit) const {
    hint = locate(p, hint);
    walk.begin(H_->numFaces());
    walk.stack.push_back(hint);
    walk.mark(hint);
    while (!walk.stack.empty()) {
      const int f = walk.stack.back();
      walk.stack.pop_back();
      if (f != hint && !arcMeetsCell(p, q, f)) continue;
      visit(f);
      const int s = H_->faceStart(f), n = H_->faceSize(f);
      for (int k = 0; k < n; ++k) {
        const int g = H_->heFace(H_->heTwin(s + k));
        if (walk.mark(g)) walk.stack.push_back(g);
      }
    }
  }

  /// The unit outward normal of triangle t of X, in double, for meshes of any size
  /// fromMesh accepts: the normal is brought to a largest coordinate near one before its
  /// norm is taken (its square would overflow beyond about 2^511 and underflow below
  /// 2^-511), and a normal in the denormal range, where its direction is lost, is computed
  /// again from the corners with accurateCross's exponent.
  static V3 faceUnit(const TriangleMesh<T>& X, int t) {
    V3 d = toD(X.triangleNormal(t));
    if constexpr (!ScalarTraits<T>::isExact) {
      if (d.cwiseAbs().maxCoeff() < std::ldexp(1.0, -900)) {
        const auto tri = X.triangle(t);
        int e = 0;
        d = toD(accurateCross(X.vertex(tri[0]), X.vertex(tri[1]), X.vertex(tri[2]), &e));
      }
    }
    return unitOf(d);
  }

  /// d / |d|, its largest coordinate first brought near one by a power of two (so that
  /// |d|² neither over- nor underflows); zero for a zero or non-finite d.
  static V3 unitOf(V3 d) {
    const double m = d.cwiseAbs().maxCoeff();
    if (!(m > 0) || !std::isfinite(m)) return V3::Zero();
    int e = 0;
    std::frexp(m, &e);
    for (int k = 0; k < 3; ++k) d[k] = std::ldexp(d[k], -e);
    return d / d.norm();
  }

 private:
  /// leastHeight_ and extent_: a triangle's height is |(p1 − p0) × (p2 − p0)| over its
  /// longest edge, less the rounding of the differences and of the cross product (so a
  /// bound from below, 0 where the rounding could exceed it); X's coordinates are
  /// first brought near one by a power of two (no under- or overflow).
  void measure(const TriangleMesh<T>& X) {
    double m = 0.0;
    for (int v = 0; v < X.numVertices(); ++v) m = std::max(m, toD(X.vertex(v)).cwiseAbs().maxCoeff());
    extent_ = m;
    leastHeight_ = 0.0;
    if (!(m > 0) || !std::isfinite(m)) return;
    int ex = 0;
    std::frexp(m, &ex);
    const double u = std::ldexp(1.0, -52);
    double least = 1e300;
    for (int t = 0; t < X.numTriangles(); ++t) {
      const auto tri = X.triangle(t);
      V3 p[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = toD(X.vertex(tri[k]));
        for (int a = 0; a < 3; ++a) p[k][a] = std::ldexp(p[k][a], -ex);
      }
      const V3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[2] - p[1];
      const double l1 = e1.norm(), l2 = e2.norm(), longest = std::max({l1, l2, e3.norm()});
      // Componentwise: each difference rounded by u of itself, each product by u, the
      // subtraction by u: |error_i| <= 4u (|e1_j e2_k| + |e1_k e2_j|) (a needle's long,
      // nearly parallel edges keep a cross product far below u |e1| |e2|). Corners that
      // T holds beyond double are rounded by u more (they are at most 1 once scaled):
      // each edge off by 2 sqrt(3) u, the cross product by that times |e1| + |e2|.
      V3 err;
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        err[i] = 4.0 * u * (std::abs(e1[j] * e2[k]) + std::abs(e1[k] * e2[j]));
      }
      double bound = err.norm();
      if (std::numeric_limits<T>::digits > 53 || ScalarTraits<T>::isExact) bound += 4.0 * u * (l1 + l2);
      const double h = (e1.cross(e2).norm() - bound) / (longest * (1.0 + 4.0 * u));
      least = std::min(least, h);
    }
    leastHeight_ = least > 0 ? std::ldexp(least, ex) : 0.0;
  }


  static IndexRange range(const std::vector<int>& start, const std::vector<int>& items, int i) {
    return IndexRange(items.data() + start[static_cast<std::size_t>(i)], items.data() + start[static_cast<std::size_t>(i) + 1]);
  }
  static void pack(const std::vector<std::vector<int>>& sets, std::vector<int>& start, std::vector<int>& items) {
    start.assign(sets.size() + 1, 0);
    for (std::size_t i = 0; i < sets.size(); ++i) start[i + 1] = start[i] + static_cast<int>(sets[i].size());
    items.clear();
    items.reserve(static_cast<std::size_t>(start.back()));
    for (const auto& s : sets) items.insert(items.end(), s.begin(), s.end());
  }

  /// Does the cone over cell f meet {d : d · e <= slack |e| for every e in dirs}? Clips the
  /// cell's corner polygon by each half-space (conservatively: the corners are unit
  /// vectors and the clipped points shorter, for which the constant slack is looser).
  bool cellMeetsCone(int f, const std::vector<V3>& dirs) {
    poly_.clear();
    const int s = H_->faceStart(f), n = H_->faceSize(f);
    for (int k = 0; k < n; ++k) poly_.push_back(H_->vertex(H_->heOrigin(s + k)).normalized());
    for (const V3& e : dirs) {
      clipped_.clear();
      const std::size_t m = poly_.size();
      for (std::size_t i = 0; i < m; ++i) {
        const V3& a = poly_[i];
        const V3& b = poly_[(i + 1) % m];
        const double da = a.dot(e) - kSlack, db = b.dot(e) - kSlack;
        if (da <= 0) clipped_.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) clipped_.push_back(a + (da / (da - db)) * (b - a));
      }
      poly_.swap(clipped_);
      if (poly_.empty()) return false;
    }
    return true;
  }

  /// Does the arc p → q (the cone over the chord) meet the cone over cell f?
  bool arcMeetsCell(const V3& p, const V3& q, int f) const {
    double lo = 0.0, hi = 1.0;
    const int s = H_->faceStart(f), n = H_->faceSize(f);
    for (int k = 0; k < n; ++k) {
      V3 c = H_->vertex(H_->heOrigin(s + k)).cross(H_->vertex(H_->heTarget(s + k)));
      const double l = c.norm();
      if (!(l > kSlack)) continue;  // a sliver side (corners within rounding): no constraint
      c /= l;
      // Inside the cell: c · x >= −slack along x = p + t (q − p).
      const double a = c.dot(p) + kSlack, b = c.dot(q - p);
      if (b == 0) {
        if (a < 0) return false;
      } else if (b > 0) {
        lo = std::max(lo, -a / b);
      } else {
        hi = std::min(hi, -a / b);
      }
      if (lo > hi) return false;
    }
    return true;
  }

  /// Registers v in every cell its local-maximum cone {d : d · (w − v) <= 0} meets.
  void registerVertex(const TriangleMesh<T>& X, int v, Walk& walk, std::vector<std::vector<int>>& sets) {
    dirs_.clear();
    const V3 pv = toD(X.vertex(v));
    for (int w : X.vertexNeighbors(v)) {
      const V3 e = unitOf(toD(X.vertex(w)) - pv);
      if (e != V3::Zero()) dirs_.push_back(e);
    }
    // The cone's extreme rays are among the cross products of two constraint normals.
    rays_.clear();
    bool unsure = false;  // a pair too close to parallel for its cross product to say
    for (std::size_t i = 0; i < dirs_.size(); ++i)
      for (std::size_t j = i + 1; j < dirs_.size(); ++j) {
        V3 r = dirs_[i].cross(dirs_[j]);
        const double l = r.norm();
        if (!(l > 1e-12)) {
          unsure = true;
          continue;
        }
        r /= l;
        for (const V3& cand : {r, V3(-r)}) {
          bool ok = true;
          for (const V3& e : dirs_) ok = ok && cand.dot(e) <= kSlack;
          if (ok) rays_.push_back(cand);
        }
      }
    if (rays_.empty() && unsure) {
      // No ray found, but some were lost: the star's directions agree to 1e-12 in double
      // (a vertex 1 away from neighbours that lie within 1e-308 of each other). Its cone
      // cannot be told here: v goes into every cell (the exact predicates decide).
      for (auto& set : sets) set.push_back(v);
      return;
    }
    if (rays_.empty()) return;  // no direction makes v a local maximum (a saddle)
    walk.begin(H_->numFaces());
    for (const V3& r : rays_) {
      const int seed = locate(r, -1);
      if (!walk.mark(seed)) continue;
      walk.stack.push_back(seed);
      while (!walk.stack.empty()) {
        const int f = walk.stack.back();
        walk.stack.pop_back();
        if (f != seed && !cellMeetsCone(f, dirs_)) continue;
        sets[static_cast<std::size_t>(f)].push_back(v);
        const int s = H_->faceStart(f), n = H_->faceSize(f);
        for (int k = 0; k < n; ++k) {
          const int g = H_->heFace(H_->heTwin(s + k));
          if (walk.mark(g)) walk.stack.push_back(g);
        }
      }
    }
  }

  /// Registers convex edge e in every cell its short arc meets.
  void registerEdge(const TriangleMesh<T>& X, int e, Walk& walk, std::vector<std::vector<int>>& sets) {
    const auto tt = X.edgeTriangles(e);
    const V3 p = faceUnit(X, tt.first), q = faceUnit(X, tt.second);
    int hint = -1;
    forCellsOnArc(p, q, hint, walk, [&](int f) { sets[static_cast<std::size_t>(f)].push_back(e); });
  }

  static V3 toD(const Vec3<T>& x) { return V3(detail::toDouble(x[0]), detail::toDouble(x[1]), detail::toDouble(x[2])); }

  std::shared_ptr<const ConvexPolyhedron<double>> H_;
  double leastHeight_ = 0.0, extent_ = 0.0;
  std::vector<double> reach_;  // per cell: the largest distance of a corner from its first
  std::vector<int> vStart_, vItems_, eStart_, eItems_;
  // Build-time scratch.
  std::vector<V3> poly_, clipped_, dirs_, rays_;
};

/// Builds X's convex map up front: the one structure of a mesh that
/// LocalMinkowskiSum::update with LocalSumMethod::ConvexMaps (and a CPD query set to that
/// method) would otherwise build inside its first call; the default, BoxTrees, needs no
/// convex map. Shared by every copy of
/// X; thread-safe and idempotent. The mesh counterpart of prepare(ConvexPolyhedron)
/// (hierarchy/prepare.hpp). Returns the map.
template <class T>
std::shared_ptr<const ConvexMap<T>> prepare(const TriangleMesh<T>& X) {
  return ConvexMap<T>::of(X);
}

/// True when X's convex map is built (by prepare or an earlier query). Never builds.
template <class T>
bool isPrepared(const TriangleMesh<T>& X) {
  return X.template hasDerived<ConvexMap<T>>();
}

}  // namespace mink
