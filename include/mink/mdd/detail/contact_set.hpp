// mink/mdd/detail/contact_set.hpp — the facet of M in a given direction, as the
// Minkowski difference of the support sets of P and Q, and two questions asked of it:
// does the line of s cross it (the check of a search's answer, covering spans of faces
// with one normal, section VI-C), and where does the line run inside it when the line
// lies in its plane (the grazing case 2 of section IV-A).
#pragma once

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/orientation.hpp"
#include "mink/mdd/detail/difference_polygon.hpp"
#include "mink/mdd/detail/pair_frame.hpp"

namespace mink {
namespace detail {

/// Vertices of X whose `value` is within `eps` of value(v0), v0 a maximiser: the face,
/// edge or vertex of X supporting the direction (exactly for exact T, eps = 0).
/// Breadth-first over the vertex graph: the support set is connected. Returns false if
/// v0 is not a maximiser to within eps (a vertex reached has a value above value(v0) +
/// eps): then the set is every vertex above value(v0) − eps that the walk reached, no
/// support set (a face of M whose edge vertices do not support its normal is no face).
template <class T, class Value>
bool supportSet(const ConvexPolyhedron<T>& X, int v0, const Value& value, const T& eps, EpochMarks& marks,
                std::vector<int>& out) {
  out.clear();
  marks.reset(static_cast<std::size_t>(X.numVertices()));
  marks.mark(v0);
  out.push_back(v0);
  const T top = value(v0);
  const T floor = top - eps, ceiling = top + eps;
  bool maximiser = true;
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int w : X.vertexNeighbors(out[i])) {
      if (!marks.mark(w)) continue;
      const T x = value(w);
      if (x < floor) continue;
      if (x > ceiling) maximiser = false;
      out.push_back(w);
    }
  return maximiser;
}

/// Where a support set `set` (as supportSet left it: maximiser first, same value and eps)
/// is exactly the vertex set of one face of X, rewrites it in that face's cyclic order
/// and returns true (the order is then a convex polygon's, up to rounding, and
/// DifferencePolygon hulls it without sorting: two resting n-gon faces cost O(n), not
/// O(n log n)). Only for sets of at least defaults::kConvexCycleMinPoints vertices;
/// O(|set|) per face of that size at the maximiser. A face whose vertices all reach the
/// set's floor is connected through its own edges, so supportSet's walk took all of them;
/// with as many vertices as the set, it is the set.
template <class T, class Value>
bool toFaceOrder(const ConvexPolyhedron<T>& X, const Value& value, const T& eps, std::vector<int>& set) {
  const int k = static_cast<int>(set.size());
  if (k < defaults::kConvexCycleMinPoints) return false;
  const T floor = value(set[0]) - eps;
  for (int f : X.vertexFaces(set[0])) {
    if (X.faceSize(f) != k) continue;
    const IndexRange face = X.faceVertices(f);
    if (std::all_of(face.begin(), face.end(), [&](int v) { return !(value(v) < floor); })) {
      set.assign(face.begin(), face.end());
      return true;
    }
  }
  return false;
}

/// 2-D points and their (rounded) cross product, difference and dot product.
template <class T>
using Pt2 = std::pair<T, T>;

template <class T>
T cross2(const Pt2<T>& a, const Pt2<T>& b) {
  return a.first * b.second - a.second * b.first;
}
template <class T>
Pt2<T> sub2(const Pt2<T>& a, const Pt2<T>& b) {
  return {a.first - b.first, a.second - b.second};
}
template <class T>
T dot2(const Pt2<T>& a, const Pt2<T>& b) {
  return a.first * b.first + a.second * b.second;
}

/// 2-D orientation sign of (a, b, c), exact on the coordinates given (orient2d: a
/// floating-point filter, then expansion arithmetic).
template <class T>
int orient2(const std::pair<T, T>& a, const std::pair<T, T>& b, const std::pair<T, T>& c) {
  return orient2d<T>(a.first, a.second, b.first, b.second, c.first, c.second);
}

/// Where the origin lies in the closed convex hull of 2-D points `pts` (ids carried
/// along): false if outside; else up to three ids and non-negative weights summing to 1
/// whose combination of the points is the origin (exact for exact T). With slack > 0
/// (inexact T; coordinates in units of length), an origin outside the hull but within
/// `slack` of it also counts, located at the nearest point of the hull: a line through a
/// vertex or along an edge of M lands there only up to rounding, on every facet around it.
template <class T>
struct OriginLocation {
  int count = 0;
  int id[3] = {-1, -1, -1};
  T weight[3] = {T(0), T(0), T(0)};
};

/// The point the weights of `loc` make of the points q[0..count).
template <class T>
std::pair<T, T> combinationPoint(const OriginLocation<T>& loc, const std::pair<T, T>* const* q) {
  T x = T(0), y = T(0);
  for (int i = 0; i < loc.count; ++i) x += loc.weight[i] * q[i]->first, y += loc.weight[i] * q[i]->second;
  return {x, y};
}

/// max(|x|, |y|) of combinationPoint(loc, q).
template <class T>
T combinationSize(const OriginLocation<T>& loc, const std::pair<T, T>* const* q) {
  const std::pair<T, T> p = combinationPoint(loc, q);
  return std::max(absValue(p.first), absValue(p.second));
}

/// loc := the origin's barycentric weights in the triangle of points a, b, c (ids ia, ib,
/// ic), unchecked: they may be negative or noise. False when the triangle has zero area.
template <class T>
bool triangleWeights(const std::pair<T, T>& a, int ia, const std::pair<T, T>& b, int ib, const std::pair<T, T>& c,
                     int ic, OriginLocation<T>& loc) {
  const T dx = b.first - a.first, dy = b.second - a.second;
  const T A = dx * (c.second - a.second) - dy * (c.first - a.first);
  if (A == T(0)) return false;
  const T wb = (-a.first * (c.second - a.second) + a.second * (c.first - a.first)) / A;
  const T wc = (dx * -a.second - dy * -a.first) / A;
  loc.count = 3;
  loc.id[0] = ia;
  loc.id[1] = ib;
  loc.id[2] = ic;
  loc.weight[0] = T(1) - wb - wc;
  loc.weight[1] = wb;
  loc.weight[2] = wc;
  if constexpr (!ScalarTraits<T>::isExact) {
    // A sliver (points 0.6 apart, the triangle 1.2e-8 wide: A cancels to 1e-8 of its
    // products) has weights wrong in their ninth digit, and the point they rebuild is
    // 1e-9 of the triangle's size off the origin (witnesses 6e48 off the motion in a 1e57
    // scene). One step of iterative refinement: the residual r (accurate to rounding of
    // the points' size) located in the same triangle corrects the weights; kept only if
    // it rebuilds the origin better (a noise A, for collinear points, would not).
    const std::pair<T, T>* abc[3] = {&a, &b, &c};
    const std::pair<T, T> res = combinationPoint(loc, abc);
    const T rx = res.first, ry = res.second;
    const T r0 = std::max(absValue(rx), absValue(ry));
    if (r0 > T(0)) {
      OriginLocation<T> refined = loc;
      refined.weight[1] = wb + (-rx * (c.second - a.second) + ry * (c.first - a.first)) / A;
      refined.weight[2] = wc + (dx * -ry - dy * -rx) / A;
      refined.weight[0] = T(1) - refined.weight[1] - refined.weight[2];
      if (combinationSize(refined, abc) < r0) loc = refined;
    }
  }
  return true;
}

/// loc := the nearest point to the origin of the segment a b (ids ia, ib), as weights of
/// its ends (a itself when a == b). False when a == b.
template <class T>
bool segmentProjection(const std::pair<T, T>& a, int ia, const std::pair<T, T>& b, int ib, OriginLocation<T>& loc) {
  const T dx = b.first - a.first, dy = b.second - a.second;
  const T len2 = dx * dx + dy * dy;
  T l = T(0);
  if (len2 > T(0)) l = std::min(T(1), std::max(T(0), (-a.first * dx - a.second * dy) / len2));
  loc.count = 2;
  loc.id[0] = ia;
  loc.id[1] = ib;
  loc.weight[0] = T(1) - l;
  loc.weight[1] = l;
  return len2 > T(0);
}

/// loc := the origin's barycentric coordinates in the triangle of points a, b, c (with
/// their ids); false when the triangle is degenerate.
template <class T>
bool triangleLocation(const std::pair<std::pair<T, T>, int>& pa, const std::pair<std::pair<T, T>, int>& pb,
                      const std::pair<std::pair<T, T>, int>& pc, OriginLocation<T>& loc) {
  const auto& a = pa.first;
  const auto& b = pb.first;
  const auto& c = pc.first;
  if (!triangleWeights(a, pa.second, b, pb.second, c, pc.second, loc)) return false;
  if constexpr (!ScalarTraits<T>::isExact) {
    // Three points collinear up to rounding (the hull kept a point in the middle of an
    // edge, by a rounded orientation) or a sliver: A is (nearly) noise and so are the
    // weights (seen: 0.25, 0.5, 0.25, naming a point 1.17 from the origin, and -1, 2, 0,
    // rebuilding the origin but from outside the triangle). Weights that are clearly
    // negative, or that do not rebuild the origin to rounding, are replaced by the
    // weights clamped at zero, or by the origin's projection on the longest side,
    // whichever rebuilds it best; if neither does (and the weights were clearly negative)
    // the triangle does not hold the origin.
    const std::pair<T, T>* abc[3] = {&a, &b, &c};
    const T size = std::max({absValue(a.first), absValue(a.second), absValue(b.first), absValue(b.second),
                             absValue(c.first), absValue(c.second)});
    const T R = T(defaults::kMddWitnessResidualFactor) * ScalarTraits<T>::epsilon() * size;
    const T slackW = T(defaults::kMddWitnessWeightSlack);
    const bool negative = loc.weight[0] < -slackW || loc.weight[1] < -slackW || loc.weight[2] < -slackW;
    T r = negative ? std::numeric_limits<T>::infinity() : combinationSize(loc, abc);
    if (!(r <= R)) {
      OriginLocation<T> clamped = loc;
      T sum = T(0);
      for (int i = 0; i < 3; ++i) sum += clamped.weight[i] = std::max(T(0), clamped.weight[i]);
      if (sum > T(0)) {
        for (int i = 0; i < 3; ++i) clamped.weight[i] /= sum;
        const T rc = combinationSize(clamped, abc);
        if (rc < r) loc = clamped, r = rc;
      }
    }
    if (!(r <= R)) {
      auto d2 = [](const std::pair<T, T>& p, const std::pair<T, T>& q) {
        const T dx = q.first - p.first, dy = q.second - p.second;
        return dx * dx + dy * dy;
      };
      const T ab = d2(a, b), ac = d2(a, c), bc = d2(b, c);
      const std::pair<std::pair<T, T>, int>* p = &pa;
      const std::pair<std::pair<T, T>, int>* q = &pb;
      if (ac >= ab && ac >= bc) q = &pc;
      if (bc > ab && bc > ac) p = &pb, q = &pc;
      OriginLocation<T> seg;
      if (segmentProjection(p->first, p->second, q->first, q->second, seg)) {
        const std::pair<T, T>* pq[2] = {&p->first, &q->first};
        const T rs = combinationSize(seg, pq);
        if (rs < r) loc = seg, r = rs;
      }
    }
    if (negative && !(r <= R)) return false;
  }
  return true;
}

/// The fan triangle (h0, h_i, h_i+1) of a convex polygon (vertices in cyclic order,
/// orientation `side` = +1 CCW / −1 CW) that holds the origin, the polygon's edges being
/// known to hold it on their inner side. The diagonals' signs are computed once each and
/// shared by the two triangles beside them: testing each triangle's three sides afresh
/// let rounding put an origin lying on a diagonal outside both triangles.
template <class T>
bool fanLocate(const std::vector<std::pair<std::pair<T, T>, int>>& h, int side, OriginLocation<T>& loc) {
  const std::pair<T, T> o(T(0), T(0));
  const std::size_t n = h.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    // Beyond the diagonal h0 h_{i+1}? (the last "diagonal" is a polygon edge: inside).
    const bool last = i + 2 == n;
    if (!last && side * orient2(h[0].first, h[i + 1].first, o) > 0) continue;
    if (!triangleLocation(h[0], h[i], h[i + 1], loc)) return false;
    // A sliver triangle (a face seen almost edge-on along s) gives weights that rounding
    // has thrown far outside [0, 1]: no reliable location, so no hit (the caller's
    // search and its tolerant check take over).
    const T slackW = T(defaults::kMddWitnessWeightSlack);
    if (loc.weight[1] < -slackW || loc.weight[2] < -slackW || loc.weight[0] < -slackW) return false;
    return true;
  }
  return false;
}

template <class T>
bool locateOrigin2Strict(std::vector<std::pair<std::pair<T, T>, int>>& pts,
                         std::vector<std::pair<std::pair<T, T>, int>>& h, OriginLocation<T>& loc) {
  using P2 = std::pair<T, T>;
  const P2 o(T(0), T(0));
  // Points in cyclic order around a strictly convex polygon (a facet's vertices as
  // DifferencePolygon names them) are their own hull: O(n), no sort.
  int cycle = 0;
  if (pts.size() >= static_cast<std::size_t>(defaults::kConvexCycleMinPoints))
    cycle = convexCycleOrientation<T>(pts.size(), [&](std::size_t i) { return pts[i].first; });
  if (cycle != 0) {
    h.assign(pts.begin(), pts.end());
    if (cycle < 0) std::reverse(h.begin(), h.end());
  } else {
    std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    pts.erase(std::unique(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
              pts.end());
    const std::size_t n = pts.size();
    h.resize(2 * n + 1);
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
      while (k >= 2 && orient2(h[k - 2].first, h[k - 1].first, pts[i].first) <= 0) --k;
      h[k++] = pts[i];
    }
    for (std::size_t i = n - 1, lo = k + 1; i-- > 0;) {
      while (k >= lo && orient2(h[k - 2].first, h[k - 1].first, pts[i].first) <= 0) --k;
      h[k++] = pts[i];
    }
    if (k > 1) --k;  // last equals first
    h.resize(k);
  }
  auto onSegment = [&](const std::pair<P2, int>& a, const std::pair<P2, int>& b) {
    if (orient2(a.first, b.first, o) != 0) return false;
    const T dx = b.first.first - a.first.first, dy = b.first.second - a.first.second;
    const T len2 = dx * dx + dy * dy;
    const T dot = -a.first.first * dx - a.first.second * dy;
    if (dot < T(0) || dot > len2) return false;
    if (len2 == T(0)) {
      if (!(a.first == o)) return false;
      loc.count = 1;
      loc.id[0] = a.second;
      loc.weight[0] = T(1);
      return true;
    }
    const T l = dot / len2;
    loc.count = 2;
    loc.id[0] = a.second;
    loc.id[1] = b.second;
    loc.weight[0] = T(1) - l;
    loc.weight[1] = l;
    return true;
  };
  if (h.size() == 1) return onSegment(h[0], h[0]);
  if (h.size() == 2) return onSegment(h[0], h[1]);
  for (std::size_t i = 0; i < h.size(); ++i)
    if (orient2(h[i].first, h[(i + 1) % h.size()].first, o) < 0) return false;
  // Inside the convex polygon (counter-clockwise): find the fan triangle (h0, hi, hi+1)
  // holding the origin, each tested on its three sides.
  for (std::size_t i = 1; i + 1 < h.size(); ++i) {
    if (orient2(h[0].first, h[i].first, o) < 0 || orient2(h[i].first, h[i + 1].first, o) < 0 ||
        orient2(h[i + 1].first, h[0].first, o) < 0)
      continue;
    if (triangleLocation(h[0], h[i], h[i + 1], loc)) return true;
  }
  // None: rounding put an origin on a diagonal outside both triangles beside it.
  return fanLocate(h, 1, loc);
}

/// Inexact T: after a location whose weights rebuild the origin but are not all
/// non-negative (a sliver fan triangle: points nearly collinear, the weights 1 + 6e-8,
/// -1.7e-7, 1.1e-7), the non-negative combination of a single point, a pair or a triple
/// of `pts` that rebuilds the origin best replaces it if it rebuilds it as well (or to
/// defaults::kMddWitnessResidualFactor eps of the points' size). The weights feed the
/// witnesses: a sliver with near-parallel edges of P and Q behind it cancels in M but can
/// put a witness beyond the end of its edge. Small sets only
/// (defaults::kMddWitnessRepairMaxPoints: every triple is tried); otherwise, and if nothing
/// rebuilds the origin that well, loc is kept.
template <class T>
void preferNonNegative(const std::vector<std::pair<std::pair<T, T>, int>>& pts, OriginLocation<T>& loc) {
  if (!(loc.weight[0] < T(0) || loc.weight[1] < T(0) || loc.weight[2] < T(0))) return;
  const std::size_t n = pts.size();
  if (n > static_cast<std::size_t>(defaults::kMddWitnessRepairMaxPoints)) return;
  auto coords = [&](int id) -> const std::pair<T, T>* {
    for (const auto& p : pts)
      if (p.second == id) return &p.first;
    return nullptr;
  };
  const std::pair<T, T>* at[3] = {nullptr, nullptr, nullptr};
  for (int i = 0; i < loc.count; ++i)
    if (!(at[i] = coords(loc.id[i]))) return;
  T size = T(0);
  for (const auto& p : pts) size = std::max({size, absValue(p.first.first), absValue(p.first.second)});
  const T bound =
      std::max(combinationSize(loc, at), T(defaults::kMddWitnessResidualFactor) * ScalarTraits<T>::epsilon() * size);
  OriginLocation<T> best;
  T bestR = std::numeric_limits<T>::infinity();
  auto consider = [&](const OriginLocation<T>& c, const std::pair<T, T>* const* q) {
    for (int i = 0; i < c.count; ++i)
      if (c.weight[i] < T(0)) return;
    const T r = combinationSize(c, q);
    if (r < bestR) best = c, bestR = r;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::pair<T, T>* a = &pts[i].first;
    OriginLocation<T> c;
    c.count = 1;
    c.id[0] = pts[i].second;
    c.weight[0] = T(1);
    consider(c, &a);
    for (std::size_t j = i + 1; j < n; ++j) {
      const std::pair<T, T>* b = &pts[j].first;
      const std::pair<T, T>* ab[2] = {a, b};
      if (segmentProjection(*a, pts[i].second, *b, pts[j].second, c)) consider(c, ab);
      for (std::size_t k = j + 1; k < n; ++k) {
        const std::pair<T, T>* abd[3] = {a, b, &pts[k].first};
        if (triangleWeights(*a, pts[i].second, *b, pts[j].second, pts[k].first, pts[k].second, c)) consider(c, abd);
      }
    }
  }
  if (bestR <= bound) loc = best;
}

template <class T>
bool locateOrigin2(std::vector<std::pair<std::pair<T, T>, int>>& pts, std::vector<std::pair<std::pair<T, T>, int>>& h,
                   OriginLocation<T>& loc, const T& slack = T(0)) {
  if (locateOrigin2Strict(pts, h, loc)) {
    if constexpr (!ScalarTraits<T>::isExact) preferNonNegative(pts, loc);
    return true;
  }
  if (!(slack > T(0)) || h.empty()) return false;
  // Nearest point of the hull's boundary (h: its vertices in order, after the call).
  T best = T(-1);
  for (std::size_t i = 0; i < h.size(); ++i) {
    const auto& a = h[i];
    const auto& b = h[(i + 1) % h.size()];
    OriginLocation<T> seg;
    segmentProjection(a.first, a.second, b.first, b.second, seg);
    const T l = seg.weight[1];
    const T px = a.first.first + l * (b.first.first - a.first.first);
    const T py = a.first.second + l * (b.first.second - a.first.second);
    const T d2 = px * px + py * py;
    if (best < T(0) || d2 < best) best = d2, loc = seg;
  }
  return best <= slack * slack;
}

/// locateOrigin2 for points already in cyclic order around a convex polygon (either
/// orientation): no sorting or hull. False if outside or if the polygon is degenerate.
template <class T>
bool locateOriginConvex(const std::vector<std::pair<std::pair<T, T>, int>>& pts, OriginLocation<T>& loc) {
  const std::size_t n = pts.size();
  if (n < 3) return false;
  const std::pair<T, T> o(T(0), T(0));
  // The sides of the origin to the polygon's edges p_i p_i+1, kept for the fan below
  // (the edges of its triangles but the diagonals) up to kKept edges.
  constexpr std::size_t kKept = 32;
  signed char edgeSign[kKept];
  int pos = 0, neg = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int s = orient2(pts[i].first, pts[i + 1 < n ? i + 1 : 0].first, o);
    if (i < kKept) edgeSign[i] = static_cast<signed char>(s);
    pos += s > 0;
    neg += s < 0;
  }
  if ((pos > 0) == (neg > 0)) return false;  // outside, or every edge through the origin
  const int side = pos > 0 ? 1 : -1;
  auto edge = [&](std::size_t i) { return i < kKept ? int(edgeSign[i]) : orient2(pts[i].first, pts[i + 1].first, o); };
  // Each fan triangle (p0, pi, pi+1) tested on its own three sides: an origin on a
  // diagonal may then be refused by both triangles beside it (rounding); the caller's
  // search then decides. The sign on diagonal p0 pi+1 is the next triangle's on p0 pi,
  // negated (orient2 is exact, so antisymmetric): one new sign per triangle.
  int nearSide = side * edge(0);  // side of p0 p_i
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const int farSide = side * orient2(pts[0].first, pts[i + 1].first, o);  // −(side of p_i+1 p0)
    const bool inWedge = nearSide >= 0 && farSide <= 0;
    nearSide = farSide;
    if (!inWedge || side * edge(i) < 0) continue;
    if (triangleLocation(pts[0], pts[i], pts[i + 1], loc)) return true;
  }
  return false;
}

/// Basis (u1, u2) of the plane orthogonal to s, exact for exact T (not unit).
template <class T>
std::pair<Vec3<T>, Vec3<T>> orthogonalBasis(const Vec3<T>& s) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (absValue(s[i]) < absValue(s[k])) k = i;
  Vec3<T> e = Vec3<T>::Zero();
  e[k] = T(1);
  const Vec3<T> u1 = s.cross(e);
  return {u1, s.cross(u1)};
}

}  // namespace detail
}  // namespace mink
