// mink/cpd/minkowski_boundary.hpp — the whole boundary of M = poseA(A) ⊕ −poseB(B) for two
// closed triangle meshes: every compatible facet of the convolution (cpd/convolution.hpp),
// cut where facets cross and trimmed by collision tests (cpd/detail/trimming.hpp), with
// no query ball. The reference that LocalMinkowskiSum is a local part of, and the "full
// Minkowski sum" of the CPD paper's Table 2 (Lee et al., CAD 2016). Cost: all
// |F_A|·|V_B| + |V_A|·|F_B| + |E_A|·|E_B| compatibility tests, then one collision test per
// piece: meant for meshes of hundreds to a few thousand triangles.
#pragma once

#include <vector>

#include "mink/core/error.hpp"
#include "mink/cpd/convolution.hpp"
#include "mink/cpd/detail/trimming.hpp"
#include "mink/cpd/minkowski_patch.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {

/// ∂M for A at poseA and B at poseB, triangulated, world frame (see MinkowskiPatch), or the
/// Error minkowskiBoundary throws for a pose that is not rigid. Never throws.
template <class T>
Result<MinkowskiPatch<T>> tryMinkowskiBoundary(const TriangleMesh<T>& A, const Pose<T>& poseA,
                                               const TriangleMesh<T>& B, const Pose<T>& poseB) {
  if (Error e = detail::checkRigidPlacement(poseA.rotation, poseA.translation, "minkowskiBoundary", "poseA")) return e;
  if (Error e = detail::checkRigidPlacement(poseB.rotation, poseB.translation, "minkowskiBoundary", "poseB")) return e;
  const Mat3<T> RAt = poseA.rotation.transpose();
  const Mat3<T> R = RAt * poseB.rotation;
  const Vec3<T> t = RAt * (poseB.translation - poseA.translation);
  // The relative placement, as MeshOverlap's constructor checks it (two rotations each
  // within the tolerance can compose to one just outside it).
  if (Error e = detail::checkRigidPlacement(R, t, "MeshOverlap", "placement")) return e;
  ConvolutionFrame<T> frame(A, B);
  frame.place(R, t);
  MeshOverlap<T> overlap(A, B, R, t);
  std::vector<ConvolutionPair> facets = allCompatiblePairs(frame);
  MinkowskiPatch<T> patch;
  patch.candidatePairs = A.numTriangles() * B.numVertices() + A.numVertices() * B.numTriangles() + A.numEdges() * B.numEdges();
  detail::Trimmer<T> trimmer;
  trimmer.run(frame, facets, typename detail::Trimmer<T>::Region(), overlap, patch);
  for (Vec3<T>& v : patch.vertices) v = poseA.rotation * v;
  patch.rebuilt = true;
  return patch;
}

/// ∂M for A at poseA and B at poseB, triangulated, world frame (see MinkowskiPatch).
/// Throws InvalidInput for a pose that is not rigid (without exceptions, prints it and
/// aborts: use tryMinkowskiBoundary).
template <class T>
MinkowskiPatch<T> minkowskiBoundary(const TriangleMesh<T>& A, const Pose<T>& poseA, const TriangleMesh<T>& B,
                                    const Pose<T>& poseB) {
  return tryMinkowskiBoundary(A, poseA, B, poseB).value();
}

}  // namespace mink
