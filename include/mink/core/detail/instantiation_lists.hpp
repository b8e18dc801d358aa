// mink/core/detail/instantiation_lists.hpp — the explicit instantiations of the float /
// double entry points, one macro per header that defines them, written once for both
// uses: `extern template` declarations at the end of each header when
// MINK_EXTERN_TEMPLATES is defined (EXTERN = extern), and the definitions in
// src/mink_instantiations.cpp (EXTERN empty). See mink/extern_templates.hpp.
// Macros only: no includes, so that each header can declare its own entry points.
#pragma once

// polyhedron/convex_polyhedron.hpp
#define MINK_DETAIL_INSTANTIATE_POLYHEDRON(EXTERN, T)                                                            \
  EXTERN template ::mink::ConvexPolyhedron<T>(::mink::ConvexPolyhedron<T>::fromPoints)(                         \
      const std::vector<::mink::Vec3<T>>&, const ::mink::HullOptions<T>&);                                      \
  EXTERN template ::mink::ConvexPolyhedron<T>(::mink::ConvexPolyhedron<T>::fromMesh)(                           \
      const std::vector<::mink::Vec3<T>>&, const std::vector<std::vector<int>>&, const ::mink::HullOptions<T>&); \
  EXTERN template ::mink::Result<::mink::ConvexPolyhedron<T>>(::mink::ConvexPolyhedron<T>::tryFromPoints)(      \
      const std::vector<::mink::Vec3<T>>&, const ::mink::HullOptions<T>&);                                      \
  EXTERN template ::mink::Result<::mink::ConvexPolyhedron<T>>(::mink::ConvexPolyhedron<T>::tryFromMesh)(        \
      const std::vector<::mink::Vec3<T>>&, const std::vector<std::vector<int>>&, const ::mink::HullOptions<T>&);

// hierarchy/prepare.hpp
#define MINK_DETAIL_INSTANTIATE_PREPARE(EXTERN, T) \
  EXTERN template const ::mink::DKHierarchy<T>* mink::prepare<T>(const ::mink::ConvexPolyhedron<T>&);

// mdd/mdd.hpp (mdd) and mdd/intersects.hpp (intersects)
#define MINK_DETAIL_INSTANTIATE_MDD(EXTERN, T)                                                              \
  EXTERN template ::mink::MddResult<T> mink::mdd<T>(                                                       \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,      \
      const ::mink::Pose<T>&, const ::mink::Vec3<T>&, ::mink::MddCache<T>&, const ::mink::MddOptions<T>&); \
  EXTERN template ::mink::MddResult<T> mink::mdd<T>(                                                       \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,      \
      const ::mink::Pose<T>&, const ::mink::Vec3<T>&, const ::mink::MddOptions<T>&);

#define MINK_DETAIL_INSTANTIATE_INTERSECTS(EXTERN, T)                                                  \
  EXTERN template bool mink::intersects<T>(const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, \
                                           const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, \
                                           ::mink::MddCache<T>&, const ::mink::MddOptions<T>&);        \
  EXTERN template bool mink::intersects<T>(const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, \
                                           const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, \
                                           const ::mink::MddOptions<T>&);                              \
  EXTERN template ::mink::Result<bool> mink::tryIntersects<T>(                                         \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,  \
      const ::mink::Pose<T>&, ::mink::MddCache<T>&, const ::mink::MddOptions<T>&);

// mdd/first_contact.hpp
#define MINK_DETAIL_INSTANTIATE_FIRST_CONTACT(EXTERN, T)                                                   \
  EXTERN template ::mink::FirstContact<T> mink::firstContact<T>(                                           \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,      \
      const ::mink::Pose<T>&, const ::mink::Vec3<T>&, ::mink::MddCache<T>&, const ::mink::MddOptions<T>&); \
  EXTERN template ::mink::FirstContact<T> mink::firstContact<T>(                                           \
      const ::mink::ConvexPolyhedron<T>&, const ::mink::Pose<T>&, const ::mink::ConvexPolyhedron<T>&,      \
      const ::mink::Pose<T>&, const ::mink::Vec3<T>&, const ::mink::MddOptions<T>&);

/// The declarations a header adds at its end: MINK_DETAIL_DECLARE_EXTERN(POLYHEDRON) etc.
#if defined(MINK_EXTERN_TEMPLATES) && !defined(MINK_INSTANTIATING)
#define MINK_DETAIL_DECLARE_EXTERN(GROUP)            \
  MINK_DETAIL_INSTANTIATE_##GROUP(extern, float) \
  MINK_DETAIL_INSTANTIATE_##GROUP(extern, double)
#else
#define MINK_DETAIL_DECLARE_EXTERN(GROUP)
#endif
