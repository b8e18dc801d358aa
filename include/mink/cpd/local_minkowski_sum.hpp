// mink/cpd/local_minkowski_sum.hpp — the boundary of M = poseA(A) ⊕ −poseB(B) inside a
// query ball, for two closed non-convex triangle meshes, kept between calls.
//
// Source: Y. Lee, E. Behar, J.-M. Lien, Y. J. Kim, "Continuous penetration depth
// computation for rigid models using dynamic Minkowski sums", CAD 2016, section 5.
//   1. Culling (section 5.1, Theorem 2): the two bounding-sphere hierarchies are walked
//      in pairs; a node pair whose sphere S_A ⊕ −S_B misses the query region is dropped
//      with everything below it; at two leaves the tight sphere of t_A ⊕ −t_B decides.
//   2. Convolution (section 3.2): the feature pairs of the surviving triangle pairs (FV,
//      VF, EE) that are compatible (cpd/convolution.hpp) and whose facet meets the region.
//   3. Trimming (cpd/detail/trimming.hpp): the facets cut where they cross, each piece
//      classified by a collision test; the pieces on ∂M that meet the ball are the patch.
// The query region is the ball and, for the trimming, the axis-aligned box around it in
// A's frame (pieces are cut at the box, whose faces are planes; the patch keeps every
// piece that meets the ball, so a triangle may reach past the sphere, never past the box).
//
// Frames: poses and the ball are in the world frame; the work is done in A's frame (B
// placed in it by the relative pose, once per call), and the patch is returned in the
// world frame.
#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <cmath>
#include <string>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/cpd/convex_map.hpp"
#include "mink/cpd/convolution.hpp"
#include "mink/cpd/detail/cpd_scale.hpp"
#include "mink/cpd/detail/trimming.hpp"
#include "mink/cpd/minkowski_patch.hpp"
#include "mink/mesh/detail/enclosing_sphere.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {

/// How LocalMinkowskiSum finds the convolution facets in the ball.
enum class LocalSumMethod {
  BruteForce,  ///< every feature pair of A and B tested (the paper's "brute force" column)
  SphereTree,  ///< culling with the two bounding-sphere hierarchies, from scratch each call
  ConvexMaps,  ///< each feature's compatible partners located in the other's convex map,
               ///< walked from where they were in the last call
  BoxTrees,    ///< the triangle pairs whose boxes' difference meets the ball's box, from
               ///< the two box trees of the overlap test, then their feature pairs: the
               ///< work follows the part of the meshes near the ball, not their size (the
               ///< default; exact T, which has no box trees: as SphereTree)
};

template <class T>
struct LocalMinkowskiSumOptions {
  LocalSumMethod method = LocalSumMethod::BoxTrees;
};

template <class T>
class LocalMinkowskiSum {
 public:
  /// One object per pair of meshes (it keeps copies, which share the meshes' bodies).
  LocalMinkowskiSum(const TriangleMesh<T>& A, const TriangleMesh<T>& B, const LocalMinkowskiSumOptions<T>& options = {})
      : userA_(A),
        userB_(B),
        scale_(A, B),
        A_(A),
        B_(B),
        options_(options),
        frame_(A_, B_),
        overlap_(A_, B_, Mat3<T>::Identity(), Vec3<T>::Zero()),
        ownedA_(ownership(A_)),
        ownedB_(ownership(B_)) {}

  /// The Error update() raises for these arguments before any work, or none: a pose that is
  /// not rigid, a non-finite centre, a radius <= 0 or not finite.
  [[nodiscard]] static Error checkUpdate(const Pose<T>& poseA, const Pose<T>& poseB, const Vec3<T>& centre,
                                         const T& radius) {
    if (Error e = detail::checkRigidPlacement(poseA.rotation, poseA.translation, "LocalMinkowskiSum", "poseA"))
      return e;
    if (Error e = detail::checkRigidPlacement(poseB.rotation, poseB.translation, "LocalMinkowskiSum", "poseB"))
      return e;
    for (int i = 0; i < 3; ++i)
      if (!ScalarTraits<T>::isFinite(centre[i]))
        return Error("LocalMinkowskiSum::update: the ball's centre is not finite");
    if (!(radius > T(0)) || !ScalarTraits<T>::isFinite(radius))
      return Error("LocalMinkowskiSum::update: the ball's radius must be positive and finite");
    return Error();
  }

  /// A ball that holds all of M cuts nothing: it is replaced by one around M's bounding
  /// sphere (the same patch), so that the units chosen for the work follow the meshes and
  /// their offset, not the ball. Every point of M is a − (R b + t) with |a|, |b| at most
  /// sqrt(3) times the largest coordinate of the meshes, stretched by at most 1 + 2e-6 by
  /// a rotation within its tolerance; the bound is grown by 2^-16 for the rounding, and
  /// the distance is taken at unit scale (no overflow). A ball of radius 1e300 around a
  /// point 1e232 away from two meshes of size 8 made the work happen in units of 2^992,
  /// where the meshes are 2^-989 wide: every product of three coordinates underflowed, the
  /// trimming's corners were 0 / 0, and each update took 22 s in exact arithmetic on NaN
  /// (fuzz/README.md).
  void containedBall(const Vec3<T>& t) {
    const T ext = scale_.meshMax();
    if (!(ext > T(0))) return;
    const T rM = T(2) * std::sqrt(T(3)) * ext * (T(1) + std::ldexp(T(1), -16)) + std::ldexp(t.cwiseAbs().maxCoeff(), -40);
    Vec3<T> d = region_.centre + t;  // the centre relative to −t, M's middle
    const T m = d.cwiseAbs().maxCoeff();
    if (!ScalarTraits<T>::isFinite(m) || !ScalarTraits<T>::isFinite(rM)) return;
    T dist = T(0);
    if (m > T(0)) {
      int e = 0;
      std::frexp(m, &e);
      for (int a = 0; a < 3; ++a) d[a] = std::ldexp(d[a], -e);
      dist = std::ldexp(d.norm() * (T(1) + std::ldexp(T(1), -40)), e);
    }
    if (!(dist + rM <= region_.radius * (T(1) - std::ldexp(T(1), -40)))) return;
    region_.centre = -t;
    region_.radius = rM;
  }

  /// update() without exceptions: a pointer to the patch (the one patch() returns, valid
  /// until the next update), or the Error update() throws: checkUpdate's, or a ball whose
  /// centre or radius overflows in the units of the meshes' size (2^±1000 apart). Allocates
  /// nothing more than update() does.
  Result<const MinkowskiPatch<T>*> tryUpdate(const Pose<T>& poseA, const Pose<T>& poseB, const Vec3<T>& centre,
                                             T radius) {
    if (Error e = checkUpdate(poseA, poseB, centre, radius)) return e;
    const Mat3<T> RAt = poseA.rotation.transpose();  // the ball into A's frame
    Mat3<T> R;
    Vec3<T> t;
    relativePlacement(poseA, poseB, R, t);
    region_.ball = true;
    region_.centre = RAt * centre;
    region_.radius = radius;
    if constexpr (!ScalarTraits<T>::isExact) {
      containedBall(t);
      // The units follow the meshes and B's offset, not the ball (unless it would overflow
      // in them): the trimming multiplies mesh coordinates (up to nine), the ball enters
      // only through its box and the exact test of a piece against it, both at any scale.
      const int e = scale_.exponentFor(t.cwiseAbs().maxCoeff(), std::max(region_.centre.cwiseAbs().maxCoeff(), region_.radius));
      if (e != scaleExp_)
        if (Error err = rescale(e)) return err;
    }
    if (scaleExp_ != 0) {
      for (int a = 0; a < 3; ++a) {
        t[a] = scaled(t[a]);
        region_.centre[a] = scaled(region_.centre[a]);
      }
      // A radius below the smallest normal number in those units is taken as that number.
      region_.radius = std::max(scaled(region_.radius), std::numeric_limits<T>::min());
      bool finite = ScalarTraits<T>::isFinite(region_.radius);
      for (int a = 0; a < 3; ++a) finite = finite && ScalarTraits<T>::isFinite(region_.centre[a]);
      if (!finite)
        return Error("LocalMinkowskiSum::update: the ball's centre or radius overflows in units of the "
                     "meshes' size (2^" + std::to_string(scaleExp_) + ")");
    }
    if (Error e = place(R, t, true)) return e;
    region_.bounded = true;
    for (int a = 0; a < 3; ++a) {
      region_.lo[a] = region_.centre[a] - region_.radius;
      region_.hi[a] = region_.centre[a] + region_.radius;
      if constexpr (!ScalarTraits<T>::isExact) {
        // Rounded outward, so that the box holds the ball.
        region_.lo[a] = std::nextafter(region_.lo[a], -std::numeric_limits<T>::infinity());
        region_.hi[a] = std::nextafter(region_.hi[a], std::numeric_limits<T>::infinity());
      }
    }
    patch_.clear();
    patch_.rebuilt = true;
    gather();
    trimmer_.run(frame_, facets_, region_, overlap_, patch_);
    for (Vec3<T>& v : patch_.vertices) {
      v = poseA.rotation * v;
      if constexpr (!ScalarTraits<T>::isExact) {
        if (scaleExp_ != 0)
          for (int a = 0; a < 3; ++a) v[a] = std::ldexp(v[a], scaleExp_);
      }
    }
    return &patch_;
  }

  /// The patch of ∂M inside the ball (centre, radius), world frame. Throws InvalidInput for
  /// a non-finite centre, a radius <= 0 or not finite, or a pose that is not rigid
  /// (checkUpdate), or a ball that overflows in the meshes' units (without exceptions,
  /// prints the message and aborts: use tryUpdate).
  const MinkowskiPatch<T>& update(const Pose<T>& poseA, const Pose<T>& poseB, const Vec3<T>& centre, T radius) {
    return *tryUpdate(poseA, poseB, centre, radius).value();
  }

  /// The collision test of the meshes as given, B placed for (poseA, poseB) in A's frame as
  /// update() places it, so that a caller's collision tests and the next update() at these
  /// poses share one placement; nullptr while the work is in other units than the meshes'
  /// (a ball far larger or smaller than them rescaled it: the caller places a MeshOverlap
  /// of its own). The Error of a relative rotation that is not one. Floating-point T.
  Result<MeshOverlap<T>*> overlapAt(const Pose<T>& poseA, const Pose<T>& poseB) {
    static_assert(!ScalarTraits<T>::isExact, "LocalMinkowskiSum::overlapAt: floating-point T only");
    if (scaleExp_ != 0) return static_cast<MeshOverlap<T>*>(nullptr);
    Mat3<T> R;
    Vec3<T> t;
    relativePlacement(poseA, poseB, R, t);
    if (Error e = place(R, t, false)) return e;
    return &overlap_;
  }

  /// B's pose in A's frame (R, t); M in A's frame is RA^T times M in the world frame (the
  /// translations cancel in a − b up to tB − tA). Unscaled.
  static void relativePlacement(const Pose<T>& poseA, const Pose<T>& poseB, Mat3<T>& R, Vec3<T>& t) {
    const Mat3<T> RAt = poseA.rotation.transpose();
    R = RAt * poseB.rotation;
    t = RAt * (poseB.translation - poseA.translation);
  }

  /// The last patch.
  const MinkowskiPatch<T>& patch() const { return patch_; }

  /// The compatible pairs whose facets met the region in the last update, sorted by key.
  const std::vector<ConvolutionPair>& facets() const { return facets_; }

  /// How many updates with LocalSumMethod::ConvexMaps gathered by the box trees because
  /// B's map did not answer for B as placed (ConvexMap::answersPlacement).
  long long convexMapFallbacks() const { return mapFallbacks_; }

 private:
  // Places B (its vertices mapped, the overlap test's box tree of B refit) only when the
  // relative pose moved: a query's successive balls and its caller's collision tests
  // (overlapAt) share one; the convolution frame too when `frameToo` (update()).
  [[nodiscard]] Error place(const Mat3<T>& R, const Vec3<T>& t, bool frameToo) {
    if (!placed_ || !(R == placedR_) || !(t == placedT_)) {
      // Two rotations each within the tolerance can compose to one just outside it.
      if (Error e = overlap_.trySetPlacement(R, t)) {
        placed_ = false;
        return e;
      }
      placedR_ = R;
      placedT_ = t;
      placed_ = true;
      framePlaced_ = false;
    }
    if (frameToo && !framePlaced_) {
      frame_.place(R, t);
      framePlaced_ = true;
    }
    return Error();
  }

  /// facets_ := the compatible pairs whose facet meets the region box, sorted.
  void gather() {
    facets_.clear();
    if (options_.method == LocalSumMethod::BoxTrees) {
      if constexpr (ScalarTraits<T>::isExact) {
        cull();
      } else {
        viaBoxTrees();
      }
    } else if (options_.method == LocalSumMethod::ConvexMaps) {
      viaConvexMaps();
    } else if (options_.method == LocalSumMethod::BruteForce) {
      for (int f = 0; f < A_.numTriangles(); ++f)
        for (int v = 0; v < B_.numVertices(); ++v) consider({ConvolutionType::FV, f, v, 0});
      for (int u = 0; u < A_.numVertices(); ++u)
        for (int g = 0; g < B_.numTriangles(); ++g) consider({ConvolutionType::VF, u, g, 0});
      for (int e = 0; e < A_.numEdges(); ++e)
        for (int ep = 0; ep < B_.numEdges(); ++ep) consider({ConvolutionType::EE, e, ep, 0});
    } else {
      cull();
    }
    std::sort(facets_.begin(), facets_.end(),
              [](const ConvolutionPair& x, const ConvolutionPair& y) { return x.key() < y.key(); });
  }

  /// Every feature's compatible partners from the other mesh's convex map: FV from A's
  /// faces in C(B), VF from B's faces in C(A), EE from A's convex edges' arcs in C(B),
  /// each located from its cell of the last call. Complete: every compatible pair is in
  /// the correspondence set of the cell holding its direction (cpd/convex_map.hpp), as
  /// long as B's map answers for B as placed (ConvexMap::answersPlacement); where the
  /// placement's rounding is too coarse for B's thinnest triangle (or T is float), the
  /// facets are gathered by the box trees instead (inexact T), which find the same set.
  void viaConvexMaps() {
    using V3 = Eigen::Vector3d;
    if (!mapA_) mapA_ = ConvexMap<T>::of(A_);
    if (!mapB_) mapB_ = ConvexMap<T>::of(B_);
    if constexpr (!ScalarTraits<T>::isExact) {
      if (!mapB_->answersPlacement(frame_.R(), frame_.t())) {
        ++mapFallbacks_;
        viaBoxTrees();
        return;
      }
    }
    hintFA_.resize(static_cast<std::size_t>(A_.numTriangles()), -1);
    hintFB_.resize(static_cast<std::size_t>(B_.numTriangles()), -1);
    hintEA_.resize(static_cast<std::size_t>(A_.numEdges()), -1);
    Eigen::Matrix3d R;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R(i, j) = detail::toDouble(frame_.R()(i, j));
    const Eigen::Matrix3d Rt = R.transpose();
    for (int f = 0; f < A_.numTriangles(); ++f) {
      int& h = hintFA_[static_cast<std::size_t>(f)];
      h = mapB_->locate(V3(-(Rt * ConvexMap<T>::faceUnit(A_, f))), h);
      for (int v : mapB_->vertices(h)) consider({ConvolutionType::FV, f, v, 0});
    }
    for (int g = 0; g < B_.numTriangles(); ++g) {
      int& h = hintFB_[static_cast<std::size_t>(g)];
      h = mapA_->locate(V3(-(R * ConvexMap<T>::faceUnit(B_, g))), h);
      for (int u : mapA_->vertices(h)) consider({ConvolutionType::VF, u, g, 0});
    }
    edgeMarks_.assign(static_cast<std::size_t>(B_.numEdges()), -1);
    for (int e = 0; e < A_.numEdges(); ++e) {
      if (A_.edgeKind(e) != EdgeKind::Convex) continue;
      const auto tt = A_.edgeTriangles(e);
      const V3 p = -(Rt * ConvexMap<T>::faceUnit(A_, tt.first));
      const V3 q = -(Rt * ConvexMap<T>::faceUnit(A_, tt.second));
      mapB_->forCellsOnArc(p, q, hintEA_[static_cast<std::size_t>(e)], walk_, [&](int cell) {
        for (int ep : mapB_->edges(cell)) {
          int& m = edgeMarks_[static_cast<std::size_t>(ep)];
          if (m == e) continue;
          m = e;
          consider({ConvolutionType::EE, e, ep, 0});
        }
      });
    }
  }

  /// The triangle pairs (t_A, t_B) whose boxes' difference box(t_A) − box(t_B) meets the
  /// region's box, i.e. box(t_A) meets box(t_B) moved by the ball's centre and grown by
  /// its radius, then the feature pairs each owns. Complete: a feature pair's facet
  /// box lies in its triangles' difference box, so every facet meeting the region comes
  /// from such a triangle pair. The pad covers the double boxes' and the facet corners'
  /// rounding, generously (the exact box test in consider() decides).
  void viaBoxTrees() {
    const double u = std::max(detail::toDouble(ScalarTraits<T>::epsilon()), std::ldexp(1.0, -52));
    double reach = overlap_.boxScale() + detail::toDouble(region_.radius);
    for (int a = 0; a < 3; ++a) reach += std::abs(detail::toDouble(region_.centre[a]));
    const double pad = detail::toDouble(region_.radius) + 16.0 * u * reach;
    // The same pairs become the overlap tests' focus: the trimming tests its patches at
    // points inside the ball (MeshOverlap::focusNear).
    const long long visited = overlap_.focusNear(region_.centre, detail::toDouble(region_.radius), pad,
                                                 [&](int fa, int fb) { trianglePairFeatures(fa, fb); });
    patch_.nodePairs = static_cast<int>(std::min<long long>(visited, std::numeric_limits<int>::max()));
  }

  /// The feature pairs of triangle fa of A and fb of B (FV, VF, EE) that this triangle
  /// pair owns. A vertex or an edge is owned by one triangle that contains it (the first of
  /// vertexTriangles(v), edgeTriangles(e).first), a face by itself; a feature pair comes
  /// from its two owners only. Each feature pair is thus considered once, without a table
  /// of the pairs seen (which, tens of thousands of entries per call, cost a cache miss per
  /// lookup), and no culling loses one: its owners contain its features, so the owners'
  /// pair passes every test that is conservative for a triangle pair (the difference of
  /// their boxes, the sphere of t_A ⊕ −t_B) whenever the facet meets the region.
  ///
  /// The facet boxes are taken from the triangles' own: the box of the corners a_i − b_j
  /// (i over the feature of A, j over that of B), rounded, is [min a_i − max b_j,
  /// max a_i − min b_j] rounded, since rounding is monotone: the same bits as consider()'s
  /// box of the rounded corners, from per-axis extremes made once per triangle pair.
  void trianglePairFeatures(int fa, int fb) {
    const auto& ta = A_.triangle(fa);
    const auto& tb = B_.triangle(fb);
    const unsigned ownA = ownedA_[static_cast<std::size_t>(fa)], ownB = ownedB_[static_cast<std::size_t>(fb)];
    const Vec3<T>* pa[3];
    const Vec3<T>* pb[3];
    for (int i = 0; i < 3; ++i) {
      pa[i] = &frame_.a(ta[i]);
      pb[i] = &frame_.b(tb[i]);
    }
    // A feature's extremes per axis: the triangle's, or an edge's (k, k + 1).
    const Vec3<T> aLo = pa[0]->cwiseMin(*pa[1]).cwiseMin(*pa[2]), aHi = pa[0]->cwiseMax(*pa[1]).cwiseMax(*pa[2]);
    const Vec3<T> bLo = pb[0]->cwiseMin(*pb[1]).cwiseMin(*pb[2]), bHi = pb[0]->cwiseMax(*pb[1]).cwiseMax(*pb[2]);
    auto boxMeets = [&](const Vec3<T>& loA, const Vec3<T>& hiA, const Vec3<T>& loB, const Vec3<T>& hiB) {
      for (int a = 0; a < 3; ++a)
        if (T(loA[a] - hiB[a]) > region_.hi[a] || T(hiA[a] - loB[a]) < region_.lo[a]) return false;
      return true;
    };
    auto take = [&](ConvolutionPair c, bool meets) {
      ++patch_.candidatePairs;
      if (meets && frame_.compatible(c)) facets_.push_back(c);
    };
    for (int j = 0; j < 3; ++j)
      if (ownB & (1u << j)) take({ConvolutionType::FV, fa, tb[j], 0}, boxMeets(aLo, aHi, *pb[j], *pb[j]));
    for (int i = 0; i < 3; ++i)
      if (ownA & (1u << i)) take({ConvolutionType::VF, ta[i], fb, 0}, boxMeets(*pa[i], *pa[i], bLo, bHi));
    if (!(ownA & 070u) || !(ownB & 070u)) return;
    for (int i = 0; i < 3; ++i) {
      if (!(ownA & (8u << i))) continue;
      // Side i of a triangle runs from corner i to corner i + 1 (TriangleMesh).
      const Vec3<T>&a0 = *pa[i], &a1 = *pa[(i + 1) % 3];
      const Vec3<T> eaLo = a0.cwiseMin(a1), eaHi = a0.cwiseMax(a1);
      const int ea = A_.triangleEdge(fa, i);
      for (int j = 0; j < 3; ++j) {
        if (!(ownB & (8u << j))) continue;
        const Vec3<T>&b0 = *pb[j], &b1 = *pb[(j + 1) % 3];
        take({ConvolutionType::EE, ea, B_.triangleEdge(fb, j), 0},
             boxMeets(eaLo, eaHi, b0.cwiseMin(b1), b0.cwiseMax(b1)));
      }
    }
  }

  /// Per triangle t of X, the features it owns (see trianglePairFeatures): bit i (i < 3)
  /// its corner i, bit 3 + i its side i.
  static std::vector<unsigned char> ownership(const TriangleMesh<T>& X) {
    std::vector<unsigned char> own(static_cast<std::size_t>(X.numTriangles()), 0);
    for (int t = 0; t < X.numTriangles(); ++t) {
      unsigned bits = 0;
      for (int i = 0; i < 3; ++i) {
        if (X.vertexTriangles(X.triangle(t)[i])[0] == t) bits |= 1u << i;
        if (X.edgeTriangles(X.triangleEdge(t, i)).first == t) bits |= 8u << i;
      }
      own[static_cast<std::size_t>(t)] = static_cast<unsigned char>(bits);
    }
    return own;
  }

  /// A candidate pair: kept if compatible and its facet's box meets the region box.
  void consider(ConvolutionPair c) {
    ++patch_.candidatePairs;
    if (!facetBoxMeetsRegion(c) || !frame_.compatible(c)) return;
    facets_.push_back(c);
  }

  bool facetBoxMeetsRegion(const ConvolutionPair& c) const {
    std::array<std::array<int, 2>, 3> tris[2];
    const int n = frame_.facetTriangles(c, tris);
    Vec3<T> lo, hi;
    bool first = true;
    for (int t = 0; t < n; ++t)
      for (const auto& ij : tris[t]) {
        const Vec3<T> x = frame_.m(ij[0], ij[1]);
        if (first) {
          lo = hi = x;
          first = false;
        } else {
          lo = lo.cwiseMin(x);
          hi = hi.cwiseMax(x);
        }
      }
    for (int a = 0; a < 3; ++a)
      if (lo[a] > region_.hi[a] || hi[a] < region_.lo[a]) return false;
    return true;
  }

  /// Does the box of the sphere (x, r) meet the region box?
  bool sphereMeetsRegion(const Vec3<T>& x, const T& r) const {
    // The sphere's bounding box against the region's box, not the sphere itself: a facet is
    // kept when its *box* meets the region's (consider()), and a facet inside a sphere has
    // its box inside the sphere's box, not inside the sphere. Testing the sphere made the
    // facets kept depend on which other triangle pairs reached them.
    for (int a = 0; a < 3; ++a)
      if (x[a] + r < region_.lo[a] || x[a] - r > region_.hi[a]) return false;
    return true;
  }

  /// Theorem 2 culling over the two sphere trees, then the feature pairs of the leaves.
  void cull() {
    const SphereTree<T>& ta = A_.sphereTree();
    const SphereTree<T>& tb = B_.sphereTree();
    T slack = T(0);
    if constexpr (!ScalarTraits<T>::isExact) {
      // The rounding of R c + t for B's centres, as a length (a few ulps of the scene).
      slack = T(64) * ScalarTraits<T>::epsilon() *
              (A_.extent() + B_.extent() + frame_.t().cwiseAbs().maxCoeff() + region_.centre.cwiseAbs().maxCoeff());
    }
    stack_.clear();
    stack_.push_back({SphereTree<T>::root(), SphereTree<T>::root()});
    while (!stack_.empty()) {
      const auto [na, nb] = stack_.back();
      stack_.pop_back();
      ++patch_.nodePairs;
      const Vec3<T> cb = frame_.R() * tb.centre(nb) + frame_.t();
      if (!sphereMeetsRegion(Vec3<T>(ta.centre(na) - cb), T(ta.radius(na) + tb.radius(nb) + slack))) continue;
      const bool la = ta.isLeaf(na), lb = tb.isLeaf(nb);
      if (la && lb) {
        leafPair(ta.triangle(na), tb.triangle(nb), slack);
        continue;
      }
      // Split the larger sphere (a leaf is never split).
      if (lb || (!la && ta.radius(na) >= tb.radius(nb))) {
        stack_.push_back({ta.left(na), nb});
        stack_.push_back({ta.right(na), nb});
      } else {
        stack_.push_back({na, tb.left(nb)});
        stack_.push_back({na, tb.right(nb)});
      }
    }
  }

  /// Two leaves: the tight sphere of t_A ⊕ −t_B, then the feature pairs they own.
  void leafPair(int fa, int fb, const T& slack) {
    const auto& ta = A_.triangle(fa);
    const auto& tb = B_.triangle(fb);
    Vec3<T> pts[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) pts[3 * i + j] = frame_.m(ta[i], tb[j]);
    const Sphere<T> s = detail::enclosingSphere(pts, 9);
    if (!sphereMeetsRegion(s.centre, T(s.radius + slack))) return;
    trianglePairFeatures(fa, fb);
  }

  /// x in the units the pipeline works in (x · 2^-scaleExp_).
  T scaled(const T& x) const {
    if constexpr (ScalarTraits<T>::isExact) {
      return x;
    } else {
      return std::ldexp(x, -scaleExp_);
    }
  }

  /// Works from now on in units of 2^e (see CpdScale): the meshes scaled, and everything
  /// built on them (overlap test, convex maps, hints) rebuilt. Only when the scene's scale
  /// moves by a factor of 2^32 or more beyond 2^±64; never for a scene near unit scale.
  /// Where a scaled copy is not a valid mesh, nothing changes and the Error says why.
  [[nodiscard]] Error rescale(int e) {
    Result<TriangleMesh<T>> a = detail::scaledMesh(userA_, e);
    Result<TriangleMesh<T>> b = a.ok() ? detail::scaledMesh(userB_, e) : Result<TriangleMesh<T>>(a.error());
    if (!b.ok()) {
      std::string why = b.error().message();
      if (why.rfind("mink: ", 0) == 0) why.erase(0, 6);
      return Error("LocalMinkowskiSum::update: the meshes cannot be worked on in units of 2^" + std::to_string(e) +
                   " (the ball's scale against theirs): " + why);
    }
    scaleExp_ = e;
    A_ = std::move(a.value());
    B_ = std::move(b.value());
    overlap_ = MeshOverlap<T>(A_, B_, Mat3<T>::Identity(), Vec3<T>::Zero());
    placed_ = false;
    mapA_.reset();
    mapB_.reset();
    hintFA_.clear();
    hintFB_.clear();
    hintEA_.clear();
    return Error();
  }

  TriangleMesh<T> userA_, userB_;  // as given (copies share their bodies)
  detail::CpdScale<T> scale_;
  int scaleExp_ = 0;  // A_ and B_ are the user's meshes times 2^-scaleExp_
  TriangleMesh<T> A_, B_;
  LocalMinkowskiSumOptions<T> options_;
  ConvolutionFrame<T> frame_;
  MeshOverlap<T> overlap_;
  // The relative pose overlap_ (and frame_, when framePlaced_) were last placed at (in the
  // working units).
  bool placed_ = false, framePlaced_ = false;
  Mat3<T> placedR_ = Mat3<T>::Identity();
  Vec3<T> placedT_ = Vec3<T>::Zero();
  typename detail::Trimmer<T>::Region region_;
  detail::Trimmer<T> trimmer_;
  std::vector<ConvolutionPair> facets_;
  std::vector<std::pair<int, int>> stack_;
  // The features each triangle owns (ownership(); the meshes' topology, kept by rescale).
  std::vector<unsigned char> ownedA_, ownedB_;
  MinkowskiPatch<T> patch_;
  // ConvexMaps: the two maps, each feature's cell of the last call, a walk's work space.
  std::shared_ptr<const ConvexMap<T>> mapA_, mapB_;  // shared with every user of the mesh
  long long mapFallbacks_ = 0;  // updates ConvexMaps handed to the box trees
  std::vector<int> hintFA_, hintFB_, hintEA_, edgeMarks_;
  typename ConvexMap<T>::Walk walk_;
};

}  // namespace mink
