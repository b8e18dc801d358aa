// mink/mdd/first_contact.hpp — firstContact: the first contact of a translation over a
// bounded motion (a physics step's time of impact, a planner's straight segment), read
// off one MDD query along the motion.
//
// With M = P ⊕ −Q and [t_lo, t_hi] the chord of M on the line of d (eq. (1) of Choi et al.),
// Q moved by τ·d meets P (closed sets) exactly for τ in [t_lo, t_hi]. Over τ in [0, 1]
// the first contact is therefore:
//   Penetrating or Touching (0 in [t_lo, t_hi])  -> at τ = 0 (`approaching` tells a touching
//                                                  pair moving in from one moving away);
//   Separated with parameter t in (0, 1]          -> at τ = t (t = t_lo);
//   Separated with t > 1 (beyond the motion), t < 0 (t = t_hi: the shapes are moving
//   apart), or NoContact (the line misses M)      -> none.
// The MDD's parameter is exact for exact scalars, so the verdict is too.
#pragma once

#include "mink/mdd/mdd.hpp"

namespace mink {

/// Result of firstContact. Frames: world.
template <class T>
struct FirstContact {
  /// P and Q share a point for some τ in [0, 1] (touching counts). An MDD query that hit
  /// its iteration cap (mdd.status == IterationLimit; not seen on well-formed input) is
  /// reported as a contact at τ = 0: the conservative answer for a motion check.
  bool hit = false;
  /// The first such τ, as a fraction of d (0 when P and Q already touch or overlap); 1
  /// when there is no contact.
  T fraction = T(1);
  /// With a hit: does the motion push Q into P there (their interiors overlap just after
  /// `fraction`)? True for an overlap at the start; false when the motion only grazes P
  /// (the line of d meets M = P ⊕ −Q but not its interior: mdd.path == Grazing) and, for a
  /// pair touching at the start, when d points away from P or along the contact (by the
  /// sign of d against mdd.normal, the face of M at the origin) — contacts a physics
  /// engine need not treat as impacts. Exact for exact scalars; for floating point,
  /// touching is within the MDD's touchTolerance and this is the side d points to.
  bool approaching = false;
  /// The MDD along d itself: status, normal of the face of M hit (at a contact, the
  /// contact normal pointing from P towards Q's side, as in MddResult), witnesses, and
  /// the signed parameter beyond the motion when there is no contact.
  MddResult<T> mdd;
};

/// The first contact of Q translated by τ·d, τ in [0, 1] (d in the world frame, any
/// non-zero length: the whole motion, e.g. relative velocity × time step, or a segment's
/// end minus its start), P fixed at poseP. `cache` as for mdd(): one per pair of shapes
/// for coherent motion. Throws InvalidInput as mdd() does (zero or non-finite d, ...);
/// without exceptions, such input gives mdd.status InvalidInput, reported (like
/// IterationLimit) as a contact at τ = 0, the conservative answer.
template <class T>
FirstContact<T> firstContact(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                             const Pose<T>& poseQ, const Vec3<T>& d, MddCache<T>& cache,
                             const MddOptions<T>& options = {}) {
  FirstContact<T> out;
  out.mdd = mdd(P, poseP, Q, poseQ, d, cache, options);
  // A line that meets M but not its interior (in a supporting plane of M: a single point,
  // an edge or a facet of contact) is answered by the grazing step: Q then only touches P.
  const bool grazing = out.mdd.path == MddPath::Grazing;
  switch (out.mdd.status) {
    case MddStatus::Penetrating:
    case MddStatus::IterationLimit:
    case MddStatus::InvalidInput:
      out.hit = out.approaching = true;
      out.fraction = T(0);
      break;
    case MddStatus::Touching:
      // 0 is an end of M's chord on the line: the face reported is the one the line
      // crosses there (or, for a line in a facet plane, that facet). Normal·d < 0: the
      // line enters M at 0 (t_lo = 0 < t_hi); > 0: it leaves (t_hi = 0); 0: it slides
      // along the facet.
      out.hit = true;
      out.fraction = T(0);
      out.approaching = !grazing && out.mdd.normal.dot(d) < T(0);
      break;
    case MddStatus::Separated:
      if (out.mdd.parameter > T(0) && !(out.mdd.parameter > T(1))) {
        out.hit = true;
        out.approaching = !grazing;
        out.fraction = out.mdd.parameter;
      }
      break;
    case MddStatus::NoContact:
      break;
  }
  return out;
}

/// firstContact() without a coherence cache (detail::scratchCache: a fresh cache's answer).
template <class T>
FirstContact<T> firstContact(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                             const Pose<T>& poseQ, const Vec3<T>& d, const MddOptions<T>& options = {}) {
  return firstContact(P, poseP, Q, poseQ, d, detail::scratchCache<T>(), options);
}

}  // namespace mink

// MINK_EXTERN_TEMPLATES: the float / double instantiations are compiled elsewhere
// (src/mink_instantiations.cpp; see mink/extern_templates.hpp).
#include "mink/core/detail/instantiation_lists.hpp"
MINK_DETAIL_DECLARE_EXTERN(FIRST_CONTACT)
