// mink/cpd/detail/cpd_scale.hpp — the units LocalMinkowskiSum works in (CpdScale) and the
// meshes scaled to them by a power of two (scaledMesh).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {
namespace detail {

/// The unit LocalMinkowskiSum works in. The trimming's constructions and filters multiply
/// up to nine coordinates of M, which over- or underflow far from unit scale. When the
/// scene (the meshes' coordinates and B's offset from A) is beyond 2^±W, W =
/// max_exponent / 16 (64 for double), the work is done on copies of the meshes scaled by
/// 2^-e, e a multiple of W/2 near the scene's exponent: exact (a power of two), never so
/// far down that a mesh coordinate would lose a bit, and scaled back in the answer.
/// Always 0 for exact T.
template <class T>
class CpdScale {
 public:
  CpdScale(const TriangleMesh<T>& A, const TriangleMesh<T>& B) {
    if constexpr (!ScalarTraits<T>::isExact) {
      T small = std::numeric_limits<T>::infinity();
      for (const TriangleMesh<T>* X : {&A, &B})
        for (int v = 0; v < X->numVertices(); ++v)
          for (int k = 0; k < 3; ++k) {
            const T x = std::abs(X->vertex(v)[k]);
            meshMax_ = std::max(meshMax_, x);
            if (x > T(0)) small = std::min(small, x);
          }
      if (std::isfinite(small)) std::frexp(small, &meshMinExp_);
    }
  }

  /// The largest |coordinate| of the two meshes (their own frames; 0 for exact T).
  T meshMax() const { return meshMax_; }

  /// The exponent e for a scene whose offsets and ball reach `other` (0: unscaled).
  int exponentFor(const T& other) const {
    if constexpr (ScalarTraits<T>::isExact) {
      (void)other;
      return 0;
    } else {
      const T m = std::max(meshMax_, other);
      if (!(m > T(0)) || !std::isfinite(m)) return 0;
      int es = 0;
      std::frexp(m, &es);
      const int W = std::numeric_limits<T>::max_exponent / 16;
      if (es >= -W && es <= W) return 0;
      int e = (es / (W / 2)) * (W / 2);  // towards zero: the scaled scene within 2^±W/2
      // Scaling down: the smallest mesh coordinate must stay a normal number.
      if (e > 0) e = std::max(0, std::min(e, meshMinExp_ - std::numeric_limits<T>::min_exponent));
      return e;
    }
  }

  /// exponentFor(other), raised where a ball of magnitude `ball` (its centre's largest
  /// coordinate or its radius) would not stay below 2^(max_exponent − W) in those units:
  /// the units follow the meshes, and a ball 2^(max_exponent − W) times their size or more
  /// (its sums and padding must not overflow) moves them up.
  int exponentFor(const T& other, const T& ball) const {
    int e = exponentFor(other);
    if constexpr (!ScalarTraits<T>::isExact) {
      if (ball > T(0) && std::isfinite(ball)) {
        int eb = 0;
        std::frexp(ball, &eb);
        const int W = std::numeric_limits<T>::max_exponent / 16, step = W / 2;
        const int lowest = eb - (std::numeric_limits<T>::max_exponent - W);
        if (e < lowest) {
          e = lowest % step == 0 ? lowest : lowest + (lowest > 0 ? step - lowest % step : -(lowest % step));
          if (e > 0) e = std::max(0, std::min(e, meshMinExp_ - std::numeric_limits<T>::min_exponent));
        }
      }
    }
    return e;
  }

 private:
  T meshMax_ = T(0);
  int meshMinExp_ = 0;
};

/// X with every coordinate multiplied by 2^-e (the same ids for vertices, triangles, edges),
/// or the Error of TriangleMesh::tryFromMesh where the scaled copy is no longer a valid mesh
/// (products of its coordinates below the range of T).
template <class T>
Result<TriangleMesh<T>> scaledMesh(const TriangleMesh<T>& X, int e) {
  if constexpr (ScalarTraits<T>::isExact) {
    return X;
  } else {
    if (e == 0) return X;
    std::vector<Vec3<T>> v(static_cast<std::size_t>(X.numVertices()));
    for (int i = 0; i < X.numVertices(); ++i)
      for (int k = 0; k < 3; ++k) v[static_cast<std::size_t>(i)][k] = std::ldexp(X.vertex(i)[k], -e);
    return TriangleMesh<T>::tryFromMesh(v, X.triangles());
  }
}

}  // namespace detail
}  // namespace mink
