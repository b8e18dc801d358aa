// mink/mdd/detail/cached_exit.hpp — frame coherence (MDD paper section VI-E): the faces of
// M that ended the pair's last query answer this one if they still bound the line.
//
// A kept face answers only once certified again (FacetCheck::certifies: a supporting
// plane of M whose facet the line crosses), so a stale cache costs a few face checks and
// never a wrong answer. The line x(t) = t s meets M in [t_lo, t_hi]: the −s exit face
// gives t_lo and the +s exit face t_hi. A kept face that alone puts that stretch on one
// side of the origin (the −s exit ahead, t_lo > 0, or the +s exit behind, t_hi < 0)
// answers a separated query by itself; a penetrating one needs both ends.
#pragma once

#include <utility>

#include "mink/mdd/detail/exit_face.hpp"

namespace mink {
namespace detail {

/// What the kept faces answer: `face` invalid when they do not (the cold path decides).
template <class T>
struct CachedExit {
  MFace<T> face;
  T parameter = T(0);                     ///< the exit's line parameter, in units of s
  MddStatus status = MddStatus::NoContact;  ///< Separated or Penetrating when `face` is valid
};

/// The answer from the kept faces cache.exitFaces (sl: s in P's frame). Counts the faces
/// checked in res.visitedFV / VF / EE (reset to 0 when they do not answer). On an answer,
/// search.check() holds that face's witnesses.
template <class T>
CachedExit<T> cachedExit(ExitFaceSearch<T>& search, const MddCache<T>& cache, const Vec3<T>& sl,
                         MddResult<T>& res) {
  FacetCheck<T>& check = search.check();
  // Each kept face rebuilt (its plane from its features) only when it is looked at: a
  // separated query whose first kept face separates needs nothing of the other.
  MFace<T> kept[2];
  T tk[2] = {T(0), T(0)};
  bool built[2] = {false, false};
  auto face = [&](int i) -> const MFace<T>& {
    if (!built[i]) {
      built[i] = true;
      kept[i] = search.rebuild(cache.exitFaces[i]);
      if (kept[i].valid()) {
        const T ns = kept[i].N.dot(sl);
        if (ns == T(0))
          kept[i] = MFace<T>();
        else
          tk[i] = kept[i].k / ns;
      }
    }
    return kept[i];
  };
  auto separates = [&](int i) {
    if (!face(i).valid()) return false;
    const bool isHi = kept[i].N.dot(sl) > T(0);
    return isHi ? tk[i] < T(0) : tk[i] > T(0);
  };
  // A separating face first: it answers alone. (Both separate only where both are faces of
  // M at the same end of the line's stretch in M, a tie that either answers.)
  int order[2] = {0, 1};
  if (separates(1)) std::swap(order[0], order[1]);
  MFace<T> lo, hi;
  T tlo = T(0), thi = T(0);
  const MFace<T>* witnessed = nullptr;  // the face whose witnesses check holds
  for (int i : order) {
    const MFace<T>& m = face(i);
    if (!m.valid()) continue;
    const bool isHi = m.N.dot(sl) > T(0);
    if (isHi ? hi.valid() : lo.valid()) continue;
    (m.type == MddFaceType::FV ? res.visitedFV : m.type == MddFaceType::VF ? res.visitedVF : res.visitedEE) += 1;
    witnessed = nullptr;
    if (!check.certifies(m)) continue;
    if (check.lineInPlane(m)) {
      lo = hi = MFace<T>();  // a grazing line: the cold path decides
      break;
    }
    (isHi ? hi : lo) = m;
    (isHi ? thi : tlo) = tk[i];
    witnessed = isHi ? &hi : &lo;
    if (separates(i)) break;  // the other end is not needed
  }
  CachedExit<T> out;
  const MFace<T>* answer = nullptr;
  if (lo.valid() && tlo > T(0)) {
    answer = &lo;  // the whole line's stretch in M lies ahead: separated
    out.status = MddStatus::Separated;
  } else if (hi.valid() && thi < T(0)) {
    answer = &hi;
    out.status = MddStatus::Separated;
  } else if (lo.valid() && hi.valid()) {
    answer = absValue(tlo) < absValue(thi) ? &lo : &hi;  // tie: +s
    out.status = MddStatus::Penetrating;
  }
  if (!answer) {
    res.visitedFV = res.visitedVF = res.visitedEE = 0;
    return out;
  }
  if (answer != witnessed) check.certifies(*answer);  // its witnesses
  out.face = *answer;
  out.parameter = answer == &lo ? tlo : thi;
  return out;
}

}  // namespace detail
}  // namespace mink
