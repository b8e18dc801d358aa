// mink/extern_templates.hpp — explicit instantiation of mink's convex-polyhedron entry
// points for float and double, to compile them once per program instead of in every
// translation unit that calls them.
//
// mink is header-only: each translation unit that calls mdd<double> instantiates and
// optimises the whole query (hull, hierarchy, searches, certificates), several seconds at
// -O2. With MINK_EXTERN_TEMPLATES defined, <mink/mink.hpp> includes this header, whose
// `extern template` declarations tell the compiler that those instantiations exist
// elsewhere: one source file, src/mink_instantiations.cpp (installed as
// share/mink/mink_instantiations.cpp), holds their definitions. With CMake, link the
// target mink::instantiations, which adds that file to the target and defines the macro:
//
//   target_link_libraries(my_engine PRIVATE mink::mink mink::instantiations)
//
// Covered, for T = float and double: ConvexPolyhedron<T>::fromPoints and fromMesh (on
// Vec3<T> points), mdd, intersects and firstContact (with and without an MddCache) and
// prepare. Other scalar types, and everything else, are instantiated where used as usual.
#pragma once

#include "mink/hierarchy/prepare.hpp"
#include "mink/mdd/first_contact.hpp"
#include "mink/mdd/mdd.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

/// The instantiations, as declarations (EXTERN = extern) or definitions (EXTERN empty).
#define MINK_DETAIL_INSTANTIATIONS(EXTERN, T)                                                                    \
  EXTERN template ::mink::ConvexPolyhedron<T> (::mink::ConvexPolyhedron<T>::fromPoints)(                        \
      const std::vector<::mink::Vec3<T>>&, const ::mink::HullOptions<T>&);                                      \
  EXTERN template ::mink::ConvexPolyhedron<T> (::mink::ConvexPolyhedron<T>::fromMesh)(                          \
      const std::vector<::mink::Vec3<T>>&, const std::vector<std::vector<int>>&, const ::mink::HullOptions<T>&); \
  EXTERN template ::mink::MddResult<T> mink::mdd<T>(                                                            \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,           \
      const ::mink::Pose<T>&, const ::mink::Vec3<T>&, ::mink::MddCache<T>&, const ::mink::MddOptions<T>&);     \
  EXTERN template ::mink::MddResult<T> mink::mdd<T>(                                                            \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,           \
      const ::mink::Pose<T>&, const ::mink::Vec3<T>&, const ::mink::MddOptions<T>&);                            \
  EXTERN template bool mink::intersects<T>(const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&,          \
                                           const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&,          \
                                           ::mink::MddCache<T>&, const ::mink::MddOptions<T>&);                 \
  EXTERN template bool mink::intersects<T>(const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&,          \
                                           const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&,          \
                                           const ::mink::MddOptions<T>&);                                       \
  EXTERN template ::mink::FirstContact<T> mink::firstContact<T>(                                                \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,           \
      const ::mink::Pose<T>&, const ::mink::Vec3<T>&, ::mink::MddCache<T>&, const ::mink::MddOptions<T>&);     \
  EXTERN template ::mink::FirstContact<T> mink::firstContact<T>(                                                \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,           \
      const ::mink::Pose<T>&, const ::mink::Vec3<T>&, const ::mink::MddOptions<T>&);                            \
  EXTERN template const ::mink::DKHierarchy<T>* mink::prepare<T>(const ::mink::ConvexPolyhedron<T>&);

#if defined(MINK_EXTERN_TEMPLATES) && !defined(MINK_INSTANTIATING)
MINK_DETAIL_INSTANTIATIONS(extern, float)
MINK_DETAIL_INSTANTIATIONS(extern, double)
#endif
