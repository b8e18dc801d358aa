// mink/mdd/detail/search_fv.hpp — SEARCH-FV and SEARCH-VF of MDD-DUAL (Choi et al.,
// section IV-B.1 and IV-B.2).
//
// SEARCH-FV walks the faces f_p of P; each stands for the FV face F(f_p, s_{−Q}(f_p)) of M.
//   1. Start from a face of P (the initial-face heuristic of section VI-A, or the last
//      optimal face kept in the coherence cache, section VI-E).
//   2. Evaluate every not yet visited face of P sharing a vertex with the current face
//      (visited marks: section VI-D), its −Q support vertex hill-climbed from the
//      current one.
//   3. Move to the best of them if it beats the current face; else stop.
// The FV faces' dual points are vertices of a convex polytope W* whose edges follow P's
// face adjacency (Theorem 3), so the local maximum is the maximum over F_fv.
// SEARCH-VF is the same walk over the faces of Q (the VF faces F(s_P(f_q), f_q)).
#pragma once

#include "mink/mdd/detail/pair_frame.hpp"

namespace mink {
namespace detail {

struct SearchBudget {
  long long left = 0;
  bool exhausted = false;
  bool take() {
    if (--left < 0) exhausted = true;
    return !exhausted;
  }
};


/// SEARCH-FV from face `start` of P. `hintQ` carries the −Q support vertex (warm start in,
/// last one out). Returns the best FV face; `visited` counts faces of M evaluated.
template <class T>
MFace<T> searchFV(const PairFrame<T>& F, const RayObjective<T>& obj, int start,
                          int& hintQ, EpochMarks& marks, SearchBudget& budget, int& visited) {
  const ConvexPolyhedron<T>& P = F.P();
  marks.reset(static_cast<std::size_t>(P.numFaces()));
  marks.mark(start);
  MFace<T> cur = F.fv(start, hintQ);
  ++visited;
  for (;;) {
    MFace<T> best;
    // The faces around the current one in cyclic order: each support query warm-starts
    // from the last one's answer, a neighbour of it. From cur.b every time, the faces
    // around an n-gon cap cost n steps each (n² for the ring).
    int h = cur.b;
    for (int v : P.faceVertices(cur.a)) {
      for (int g : P.vertexFaces(v)) {
        if (!marks.mark(g)) continue;
        if (!budget.take()) return cur;
        const MFace<T> f = F.fv(g, h);
        ++visited;
        if (obj.better(f, best)) best = f;
      }
    }
    if (obj.separated || !obj.better(best, cur)) return cur;
    cur = best;
  }
}

/// SEARCH-VF from face `start` of Q (roles of P and −Q exchanged).
template <class T>
MFace<T> searchVF(const PairFrame<T>& F, const RayObjective<T>& obj, int start,
                          int& hintP, EpochMarks& marks, SearchBudget& budget, int& visited) {
  const ConvexPolyhedron<T>& Q = F.Q();
  marks.reset(static_cast<std::size_t>(Q.numFaces()));
  marks.mark(start);
  MFace<T> cur = F.vf(start, hintP);
  ++visited;
  for (;;) {
    MFace<T> best;
    int h = cur.a;  // chained, as in searchFV
    for (int v : Q.faceVertices(cur.b)) {
      for (int g : Q.vertexFaces(v)) {
        if (!marks.mark(g)) continue;
        if (!budget.take()) return cur;
        const MFace<T> f = F.vf(g, h);
        ++visited;
        if (obj.better(f, best)) best = f;
      }
    }
    if (obj.separated || !obj.better(best, cur)) return cur;
    cur = best;
  }
}

}  // namespace detail
}  // namespace mink
