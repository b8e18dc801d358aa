// mink/mink.hpp — the whole public surface of mink in one include, for programs (physics
// engines, planners) that want everything and do not mind the compile time. Each layer's
// headers can also be included on their own; see README.md for the layout.
//
// mink is header-only and needs Eigen 3.3+ alone. Nothing here links, allocates at
// static-initialisation time or keeps global state.
#pragma once

// core: scalar traits, Vec3 / Pose, tolerances and the one exception type.
#include "mink/core/defaults.hpp"
#include "mink/core/error.hpp"
#include "mink/core/index_range.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/orientation.hpp"
#include "mink/core/types.hpp"

// polyhedron: ConvexPolyhedron<T> (hull, validation, adjacency, support).
#include "mink/polyhedron/convex_polyhedron.hpp"

// gauss_map: Gauss maps and their exact predicates; hierarchy: Dobkin–Kirkpatrick, and
// prepare() to build a shape's derived structures before its first query.
#include "mink/gauss_map/arc_intersection.hpp"
#include "mink/gauss_map/gauss_map.hpp"
#include "mink/hierarchy/dk_hierarchy.hpp"
#include "mink/hierarchy/prepare.hpp"

// mdd: the minimum directional distance between two convex polyhedra.
#include "mink/mdd/mdd.hpp"
#include "mink/mdd/mdd_exact.hpp"
#include "mink/mdd/first_contact.hpp"

// mesh: TriangleMesh<T> (closed, non-convex, any genus), its sphere tree, exact triangle
// tests, point location, self-intersection and mesh-mesh overlap.
#include "mink/mesh/mesh_overlap.hpp"
#include "mink/mesh/point_in_mesh.hpp"
#include "mink/mesh/self_intersection.hpp"
#include "mink/mesh/sphere_tree.hpp"
#include "mink/mesh/triangle_intersection.hpp"
#include "mink/mesh/triangle_mesh.hpp"

// cpd: the boundary of M = A ⊕ −B for two meshes — convex maps, convolution, trimming, the
// local Minkowski sum in a ball and the whole boundary.
#include "mink/cpd/continuous_penetration_depth.hpp"
#include "mink/cpd/convex_map.hpp"
#include "mink/cpd/convolution.hpp"
#include "mink/cpd/local_minkowski_sum.hpp"
#include "mink/cpd/minkowski_boundary.hpp"
#include "mink/cpd/minkowski_patch.hpp"
#include "mink/cpd/phong_projection.hpp"

// io: OBJ and OFF readers and writers, and OBJ / OFF to TriangleMesh.
#include "mink/io/indexed_mesh.hpp"
#include "mink/io/obj.hpp"
#include "mink/io/off.hpp"
#include "mink/io/triangle_mesh_io.hpp"
