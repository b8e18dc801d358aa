// mink/extern_templates.hpp — explicit instantiation of mink's convex-polyhedron entry
// points for float and double, to compile them once per program instead of in every
// translation unit that calls them.
//
// mink is header-only: each translation unit that calls mdd<double> instantiates and
// optimises the whole query (hull, hierarchy, searches, certificates), several seconds at
// -O2. With MINK_EXTERN_TEMPLATES defined, each header that defines one of the entry
// points below ends with their `extern template` declarations, which tell the compiler
// that those instantiations exist elsewhere: one source file, src/mink_instantiations.cpp
// (installed as share/mink/mink_instantiations.cpp), holds their definitions. With CMake,
// link the target mink::instantiations, which adds that file to the target and defines
// the macro:
//
//   target_link_libraries(my_engine PRIVATE mink::mink mink::instantiations)
//
// Covered, for T = float and double (core/detail/instantiation_lists.hpp):
// ConvexPolyhedron<T>::fromPoints and fromMesh (on Vec3<T> points), mdd, intersects and
// firstContact (with and without an MddCache) and prepare. Other scalar types, and
// everything else, are instantiated where used, as usual.
#pragma once

#include "mink/core/detail/instantiation_lists.hpp"
#include "mink/hierarchy/prepare.hpp"
#include "mink/mdd/first_contact.hpp"
#include "mink/mdd/mdd.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

/// Every instantiation of the list, as declarations (EXTERN = extern) or definitions.
#define MINK_DETAIL_INSTANTIATIONS(EXTERN, T)    \
  MINK_DETAIL_INSTANTIATE_POLYHEDRON(EXTERN, T)  \
  MINK_DETAIL_INSTANTIATE_PREPARE(EXTERN, T)     \
  MINK_DETAIL_INSTANTIATE_MDD(EXTERN, T)         \
  MINK_DETAIL_INSTANTIATE_INTERSECTS(EXTERN, T)  \
  MINK_DETAIL_INSTANTIATE_FIRST_CONTACT(EXTERN, T)
