// mink/cpd/minkowski_patch.hpp — MinkowskiPatch<T>: a triangulated piece of the boundary of
// M = poseA(A) ⊕ −poseB(B), as LocalMinkowskiSum and minkowskiBoundary return it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mink/core/types.hpp"
#include "mink/cpd/convolution.hpp"

namespace mink {

/// Triangles on ∂M (world frame). Every triangle lies on ∂M (for floating-point T: to the
/// rounding of its constructed corners), is counter-clockwise seen from outside M (its
/// normal (v1 − v0) × (v2 − v0) is M's outward normal) and names the convolution pair
/// (FV / VF / EE) and the features of A and B whose facet it is part of. Triangles of
/// one facet share their corners' indices, and so do neighbouring facets along the
/// convolution's edges: corners are identified by how they were made (a point a_i − b_j,
/// an edge of one facet cut by the plane of another, ...), not by their coordinates. A
/// corner of one piece inside a side of another on the same named line is a corner of
/// both (no T-junction there; Phong normals are continuous across it).
template <class T>
struct MinkowskiPatch {
  /// #V corners, world frame, length unit of the meshes.
  std::vector<Vec3<T>> vertices;
  /// #F triangles, indices into `vertices`, counter-clockwise seen from outside M.
  std::vector<std::array<int, 3>> triangles;
  /// #F: the facet of the convolution A ⊗ −B each triangle lies in.
  std::vector<ConvolutionPair> pairs;

  // Statistics of the call that built the patch.
  int facetsGathered = 0;   ///< compatible convolution facets met by the query region
  int pieces = 0;           ///< convex pieces the facets were cut into (inside the region)
  int overlapTests = 0;     ///< collision tests made to classify pieces (on ∂M or inside M)
  int nodePairs = 0;        ///< tree node pairs visited by the culling (SphereTree, BoxTrees)
  int candidatePairs = 0;   ///< feature pairs tested for compatibility
  /// Facets in the region too small beside their distance from the origin for any piece
  /// of them to have an area in the coordinates' precision (a box narrower than 2^-42 of
  /// its distance from the origin along an axis): not cut, no triangle. Nonzero explains
  /// an empty patch of meshes far smaller than their placement (e.g. 1e-300 across, 3 away).
  int facetsBelowResolution = 0;
  bool rebuilt = false;     ///< true when update() rebuilt from scratch (no kept state used)

  void clear() {
    vertices.clear();
    triangles.clear();
    pairs.clear();
    facetsGathered = pieces = overlapTests = nodePairs = candidatePairs = facetsBelowResolution = 0;
    rebuilt = false;
  }
};

}  // namespace mink
