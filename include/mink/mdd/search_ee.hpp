// mink/mdd/search_ee.hpp — SEARCH-EE of MDD-DUAL (Choi et al., seed 000, section IV-B.3).
//
//   1. Start from the better of the SEARCH-FV and SEARCH-VF answers, f_m.
//   2. FS_0: the pairs (e_p, e_q) with e_p at a vertex of f_p and e_q at s_{−Q}(f_p) when
//      f_m = F(f_p, s_{−Q}(f_p)); symmetrically when f_m is a VF face.
//   3. Keep the pairs whose Gauss-map arcs cross (section VI-B): they are the EE faces.
//   4. If the best beats the current face, move there; FS_{i+1} is the pairs of edges at
//      the end vertices of ê_p and of ê_q; else stop.
// Lemma 6 and 7: if the optimum is an EE face, FS_0 holds a better face, and each FS_i
// holds every EE neighbour, so the walk ends at the global maximum (Theorem 8).
#pragma once

#include <vector>

#include "mink/mdd/search_fv.hpp"

namespace mink {
namespace detail {

template <class T>
void edgesAround(const ConvexPolyhedron<T>& X, int v, std::vector<int>& out) {
  for (int h : X.vertexHalfEdges(v)) out.push_back(X.heEdge(h));
}

}  // namespace detail

/// SEARCH-EE from `start` (an FV or VF face). Returns the best face found (possibly
/// `start`). Buffers and marks come from the caller (no allocation once warm).
template <class T>
detail::MFace<T> searchEE(const detail::PairFrame<T>& F, const detail::RayObjective<T>& obj,
                          const detail::MFace<T>& start, detail::PairMarks& marks, std::vector<int>& EP,
                          std::vector<int>& EQ, detail::SearchBudget& budget, int& visited) {
  const ConvexPolyhedron<T>& P = F.P();
  const ConvexPolyhedron<T>& Q = F.Q();
  marks.reset();
  EP.clear();
  EQ.clear();
  if (start.type == MddFaceType::FV) {
    for (int v : P.faceVertices(start.a)) detail::edgesAround(P, v, EP);
    detail::edgesAround(Q, start.b, EQ);
  } else {
    detail::edgesAround(P, start.a, EP);
    for (int v : Q.faceVertices(start.b)) detail::edgesAround(Q, v, EQ);
  }
  detail::MFace<T> cur = start;
  for (;;) {
    detail::MFace<T> best;
    for (int ep : EP) {
      for (int eq : EQ) {
        if (!marks.mark(ep, eq)) continue;
        if (!budget.take()) return cur;
        const detail::MFace<T> f = F.ee(ep, eq);
        if (!f.valid()) continue;
        ++visited;
        if (obj.better(f, best)) best = f;
      }
    }
    if (obj.separated || !obj.better(best, cur)) return cur;
    cur = best;
    EP.clear();
    EQ.clear();
    const auto vp = P.edgeVertices(cur.a);
    const auto vq = Q.edgeVertices(cur.b);
    detail::edgesAround(P, vp.first, EP);
    detail::edgesAround(P, vp.second, EP);
    detail::edgesAround(Q, vq.first, EQ);
    detail::edgesAround(Q, vq.second, EQ);
  }
}

}  // namespace mink
