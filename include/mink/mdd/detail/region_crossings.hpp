// mink/mdd/detail/region_crossings.hpp — the EE faces of M = P ⊕ −Q at a vertex pair
// (u of P, w of Q) in O(deg u + deg w) instead of deg u · deg w.
//
// An edge e_p at u and an edge e_q at w span an EE face iff their Gauss arcs cross
// (section VI-B); those arcs are the boundaries of the Gauss regions R(u) on G(P) and
// R(w) on G(−Q), two convex spherical polygons. The crossings of two convex polygons'
// boundaries are found by J. O'Rourke, C.-B. Chien, T. Olson, D. Naddor, "A new linear
// algorithm for intersecting convex polygons" (CGIP 19, 1982; "Computational Geometry
// in C", 2nd ed., section 7.6), which chases one edge of each polygon:
//   1. R(u)'s corners are the normals of the faces around u, R(w)'s the negated normals
//      of the faces around w (Q's, in P's frame); both put counter-clockwise seen from
//      outside the sphere.
//   2. A direction h with h·x > 0 at every corner of both is sought (mean corners, then
//      perceptron steps); through it both regions are plane convex polygons (central
//      projection maps great circles to lines and keeps orientation), so the planar algorithm
//      applies with its tests as signs of 3x3 determinants of the corners:
//      "x left of edge a1→a" = det[a1 a x] > 0, "edge A turns left to edge B" =
//      det[h, a × a1, b × b1] > 0.
//   3. Each step tests the current pair exactly (PairFrame::ee) and advances one edge by
//      the algorithm's rules; after the first crossing the chase runs one more full
//      cycle. At most 4 (deg u + deg w) pairs are tested (half of them up to the first
//      crossing); every crossing pair is among them (tests/mdd/region_crossings_test.cpp
//      checks this against all pairs).
// The advance rules only choose which pairs are tested; whether a pair is an EE face is
// always decided by PairFrame::ee on its own. If no such h is found (the regions fit in
// no open hemisphere together, or only with a margin below what the capped perceptron
// reaches) the caller tests all pairs, and says so (MddResult::usedPairScan).
#pragma once

#include <algorithm>
#include <vector>

#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/gauss_map/arc_intersection.hpp"

namespace mink {
namespace detail {

template <class T>
class RegionCrossings {
 public:
  /// Calls visit(ep, eq) for the pairs of an edge at u (of P) and an edge at w (of Q)
  /// chosen by the chase, every pair whose arcs cross among them (a pair may come twice);
  /// visit returns 1 if the pair is an EE face, 0 if not, -1 if it cannot say (a pair it
  /// saw before: then F.ee decides here, while the first crossing is sought). False, having called nothing, if the
  /// chase cannot run (no common direction h): the caller then tests all pairs.
  /// Frame: PairFrame<T> (P, Q, Q's normals in P's frame).
  template <class Frame, class Visit>
  bool run(const Frame& F, int u, int w, Visit&& visit) {
    const auto& P = F.P();
    const auto& Q = F.Q();
    // Corner i of a region is face i around the vertex; the arc from corner i − 1 to
    // corner i is the edge to neighbour i (vertexFaces(v)[i] lies between the edges to
    // neighbours i and i + 1).
    a_.clear();
    ea_.clear();
    for (int f : P.vertexFaces(u)) a_.push_back(P.faceNormal(f));
    for (int h : P.vertexHalfEdges(u)) ea_.push_back(P.heEdge(h));
    b_.clear();
    eb_.clear();
    for (int g : Q.vertexFaces(w)) b_.push_back(Vec3<T>(-F.qNormal(g)));
    for (int h : Q.vertexHalfEdges(w)) eb_.push_back(Q.heEdge(h));
    if (!counterClockwise(a_, ea_) || !counterClockwise(b_, eb_)) return false;
    if (!commonDirection()) return false;
    const int n = static_cast<int>(a_.size()), m = static_cast<int>(b_.size());
    int i = 0, j = 0, ai = 0, bj = 0;  // edges (corner i − 1 → i), (j − 1 → j); advances
    bool found = false;
    do {
      const int i1 = (i + n - 1) % n, j1 = (j + m - 1) % m;
      const int r = visit(ea_[i], eb_[j]);
      if (!found && (r > 0 || (r < 0 && F.ee(ea_[i], eb_[j]).valid()))) {
        found = true;  // one full cycle from the first crossing finds every other
        ai = bj = 0;
      }
      const int cross = detail::sign(det3(h_, Vec3<T>(a_[i].cross(a_[i1])), Vec3<T>(b_[j].cross(b_[j1]))));
      const int aHB = detail::sign(det3(b_[j1], b_[j], a_[i]));  // head of A left of B
      const int bHA = detail::sign(det3(a_[i1], a_[i], b_[j]));  // head of B left of A
      bool advanceA;
      if (cross >= 0)
        advanceA = bHA > 0;
      else
        advanceA = !(aHB > 0);
      if (advanceA)
        i = (i + 1) % n, ++ai;
      else
        j = (j + 1) % m, ++bj;
    } while ((ai < n || bj < m) && ai < 2 * n && bj < 2 * m);
    return true;
  }

 private:
  // Puts the corners counter-clockwise seen from outside (det[x0 x1 x2] > 0: no three
  // consecutive corners of a region lie on one great circle, or two edges at the vertex
  // would be collinear), reversing them and their arcs if needed. False if degenerate.
  static bool counterClockwise(std::vector<Vec3<T>>& x, std::vector<int>& e) {
    const int d = static_cast<int>(x.size());
    if (d < 3 || static_cast<int>(e.size()) != d) return false;
    const int s = detail::sign(det3(x[0], x[1], x[2]));
    if (s == 0) return false;
    if (s > 0) return true;
    std::reverse(x.begin(), x.end());
    // Arc k of the reversed order (corner k − 1 → k) is old arc (d − k) mod d.
    std::reverse(e.begin() + 1, e.end());
    return true;
  }
  // h := a direction with h·x > 0 at every corner of both regions (a point of the open
  // hemisphere holding both). From the midpoint of the regions' mean corners (each corner
  // scaled by its 1-norm, no square root), perceptron steps: each corner x with h·x <= 0
  // adds x̂ to h. If the corners have a margin γ (a cone of half-angle 90° − γ around some
  // axis holds them all), that ends within 1/γ² steps; it is capped at
  // kPerceptronSteps, and every corner is checked again at the end. The chase's result
  // does not depend on which h is found.
  bool commonDirection() {
    const int m = static_cast<int>(a_.size()), n = static_cast<int>(b_.size());
    auto unit1 = [](const Vec3<T>& v) { return Vec3<T>(v / T(absValue(v[0]) + absValue(v[1]) + absValue(v[2]))); };
    auto corner = [&](int k) -> const Vec3<T>& { return k < m ? a_[k] : b_[k - m]; };
    Vec3<T> ha = Vec3<T>::Zero(), hb = Vec3<T>::Zero();
    for (const Vec3<T>& v : a_) ha += unit1(v);
    for (const Vec3<T>& v : b_) hb += unit1(v);
    h_ = ha / T(m) + hb / T(n);
    int steps = 0, clean = 0;
    for (int k = 0; clean < m + n; k = (k + 1) % (m + n)) {
      if (h_.dot(corner(k)) > T(0)) {
        ++clean;
        continue;
      }
      if (++steps > kPerceptronSteps) return false;
      h_ += unit1(corner(k));
      clean = 0;
    }
    return true;
  }

  static constexpr int kPerceptronSteps = 64;  // corners' margin down to about 1/8 rad

  std::vector<Vec3<T>> a_, b_;
  std::vector<int> ea_, eb_;
  Vec3<T> h_ = Vec3<T>::Zero();
};

}  // namespace detail
}  // namespace mink
