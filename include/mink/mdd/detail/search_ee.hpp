// mink/mdd/detail/search_ee.hpp — SEARCH-EE of MDD-DUAL (Choi et al., section IV-B.3).
//
//   1. Start from the better of the SEARCH-FV and SEARCH-VF answers, f_m.
//   2. FS_0: the pairs (e_p, e_q) with e_p at a vertex of f_p and e_q at s_{−Q}(f_p) when
//      f_m = F(f_p, s_{−Q}(f_p)); symmetrically when f_m is a VF face.
//   3. Keep the pairs whose Gauss-map arcs cross (section VI-B): they are the EE faces.
//   4. If the best beats the current face, move there; FS_{i+1} is the pairs of edges at
//      the end vertices of ê_p and of ê_q; else stop.
// The crossing pairs among a vertex pair's edges are found in O(deg + deg) where the
// degrees are high (detail/region_crossings.hpp), not by testing every pair.
// Lemma 6 and 7: if the optimum is an EE face, FS_0 holds a better face, and each FS_i
// holds every EE neighbour, so the walk ends at the global maximum (Theorem 8).
#pragma once

#include <algorithm>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/mdd/detail/region_crossings.hpp"
#include "mink/mdd/detail/search_fv.hpp"

namespace mink {
namespace detail {

template <class T>
void edgesAround(const ConvexPolyhedron<T>& X, int v, std::vector<int>& out) {
  for (int h : X.vertexHalfEdges(v)) out.push_back(X.heEdge(h));
}

/// The EE faces at the vertex pair (u of P, w of Q): pairs of an edge at u and an edge at
/// w, each tested once (marks; a vertex pair too) and offered to `take(face)`. With
/// either degree at most defaults::kMddChaseMinDegree all deg u · deg w pairs are
/// tested (linear in the other degree); above it the chase of region_crossings.hpp tests
/// O(deg u + deg w) of them (a cone's apex against another's: n² pairs per step, past the
/// visit cap at n = 128). `pairScan` is set where two high degrees had every pair tested
/// (the chase declined). False on the visit cap.
template <class T, class Take>
bool eeAtVertices(const PairFrame<T>& F, int u, int w, PairMarks& marks, RegionCrossings<T>& chase,
                  SearchBudget& budget, int& visited, bool& pairScan, Take&& take) {
  const ConvexPolyhedron<T>& P = F.P();
  const ConvexPolyhedron<T>& Q = F.Q();
  // A vertex pair met again (the corners of consecutive faces) has offered its faces.
  if (!marks.mark(~u, ~w)) return true;
  bool capped = false, chasing = false;
  // 1: an EE face (offered), 0: none, -1: seen before (not offered again).
  auto test = [&](int ep, int eq) {
    if (capped) return 0;
    // The chase's steps count against the cap whether or not the pair was seen: a walk
    // through many faces at a vertex of degree n then stays within the cap's O(n) work.
    if (chasing && !budget.take()) {
      capped = true;
      return 0;
    }
    if (!marks.mark(ep, eq)) return -1;
    if (!chasing && !budget.take()) {
      capped = true;
      return 0;
    }
    const MFace<T> f = F.ee(ep, eq);
    if (!f.valid()) return 0;
    ++visited;
    take(f);
    return 1;
  };
  const int du = static_cast<int>(P.vertexHalfEdges(u).size()), dw = static_cast<int>(Q.vertexHalfEdges(w).size());
  chasing = std::min(du, dw) > defaults::kMddChaseMinDegree;
  if (!chasing || !chase.run(F, u, w, test)) {
    // Two high degrees and no chase (regions not in one hemisphere together): said so.
    if (chasing) pairScan = true;
    chasing = false;
    for (int hp : P.vertexHalfEdges(u))
      for (int hq : Q.vertexHalfEdges(w)) test(P.heEdge(hp), Q.heEdge(hq));
  }
  return !capped;
}


/// SEARCH-EE from `start` (an FV or VF face). Returns the best face found (possibly
/// `start`). Buffers and marks come from the caller (no allocation once warm). FS_i is
/// taken vertex pair by vertex pair (eeAtVertices): the pairs of edges at the corners of
/// the current face whose arcs cross, the same EE faces as all pairs there.
template <class T>
MFace<T> searchEE(const PairFrame<T>& F, const RayObjective<T>& obj,
                          const MFace<T>& start, PairMarks& marks, RegionCrossings<T>& chase,
                          SearchBudget& budget, int& visited, bool& pairScan) {
  const ConvexPolyhedron<T>& P = F.P();
  const ConvexPolyhedron<T>& Q = F.Q();
  marks.reset();
  MFace<T> cur = start;
  MFace<T> best;
  auto take = [&](const MFace<T>& f) {
    if (obj.better(f, best)) best = f;
  };
  auto at = [&](int u, int w) { return eeAtVertices(F, u, w, marks, chase, budget, visited, pairScan, take); };
  if (start.type == MddFaceType::FV) {
    for (int v : P.faceVertices(start.a))
      if (!at(v, start.b)) return cur;
  } else {
    for (int v : Q.faceVertices(start.b))
      if (!at(start.a, v)) return cur;
  }
  for (;;) {
    if (obj.separated || !obj.better(best, cur)) return cur;
    cur = best;
    best = MFace<T>();
    const auto vp = P.edgeVertices(cur.a);
    const auto vq = Q.edgeVertices(cur.b);
    for (int u : {vp.first, vp.second})
      for (int w : {vq.first, vq.second})
        if (!at(u, w)) return cur;
  }
}

}  // namespace detail
}  // namespace mink
