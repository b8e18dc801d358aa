// mink/hierarchy/prepare.hpp — prepare(P): build up front every structure that a query on
// a ConvexPolyhedron would otherwise build lazily, inside its first call.
//
// A shape's derived structures (detail::DerivedSlots) are made on first use and shared by
// its copies: the Dobkin–Kirkpatrick hierarchy (hierarchyOf, shapes of at least
// defaults::kHierarchyMinVertices vertices) and the 26 support seeds (supportSeedsOf).
// On a large shape the hierarchy costs about twice the hull itself (README "Benchmarks"),
// and the first mdd(), intersects(), firstContact() or extremeVertex() call on the shape
// would pay it. prepare() moves that work to a moment the caller chooses (loading a
// scene, a background thread):
//   1. the hierarchy, when the shape is large enough to get one;
//   2. the support seeds (26 scans, O(n); small shapes' cold support queries start there).
// Nothing else is cached per shape: MddCache holds per-pair state, and mddExact's exact
// fallback converts the shapes per call (it depends on the caller's rational type). The
// non-convex meshes of CPD have their own overload, prepare(TriangleMesh) in
// cpd/convex_map.hpp (their convex maps).
//
// Thread-safety: every slot is filled under std::call_once, so prepare() may run in
// several threads at once and beside queries on the same shape; each structure is built
// once and the callers that arrive during the build wait for it. Calling it again costs
// one atomic load per slot. Copies of a shape share its slots, before or after prepare().
#pragma once

#include "mink/hierarchy/dk_hierarchy.hpp"
#include "mink/hierarchy/support_seeds.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {

/// Builds every derived structure of P that a query may use (see the header comment), so
/// that no later query on P or on a copy of it builds anything. Idempotent and
/// thread-safe. Returns P's hierarchy, or nullptr when P has fewer than
/// defaults::kHierarchyMinVertices vertices (queries then hill-climb from the seeds).
/// A hierarchy build that throws (it cannot for valid shapes) propagates; the next call
/// retries it.
template <class T>
const DKHierarchy<T>* prepare(const ConvexPolyhedron<T>& P) {
  static_assert(detail::DerivedSlots::kCount == 2,
                "a new derived slot must be built by prepare() and checked by isPrepared()");
  supportSeedsOf(P);
  return hierarchyOf(P);
}

/// True when every structure prepare(P) builds is built (by prepare or by earlier
/// queries), so a query on P builds nothing. Never builds or waits: false while a first
/// build is still running in another thread.
template <class T>
bool isPrepared(const ConvexPolyhedron<T>& P) {
  const detail::DerivedSlots& slots = P.derivedSlots();
  const bool needsHierarchy = P.numVertices() >= defaults::kHierarchyMinVertices;
  return slots.slot[detail::DerivedSlots::kSupportSeeds].isBuilt() &&
         (!needsHierarchy || slots.slot[detail::DerivedSlots::kHierarchy].isBuilt());
}

}  // namespace mink

// MINK_EXTERN_TEMPLATES: the float / double instantiations are compiled elsewhere
// (src/mink_instantiations.cpp; see mink/extern_templates.hpp).
#include "mink/core/detail/instantiation_lists.hpp"
MINK_DETAIL_DECLARE_EXTERN(PREPARE)
