// mink/mesh/mesh_overlap.hpp — do two placed closed meshes share a point? (closed solids:
// touching counts, and so does one lying wholly inside the other)
//
// Built for CPD's trimming (CPD paper, section 5): for one relative pose
// of B in A's frame, many translations y, each asking "does A meet B + y?".
//   1. Per pose (constructor, setPlacement): B's vertices and sphere-tree centres are
//      mapped into A's frame once (x -> R x + t), with B's per-component boxes.
//   2. Per query, floating-point T: two trees of triangle boxes (double) are traversed
//      in pairs, A's built once, B's refit to its mapped vertices per placement (split
//      anew when the rotation has turned far), B's moved by y; a pair of boxes apart by
//      more than the rounding of the conversion to double is culled. Boxes hug thin and
//      hollow shapes (a torus through another's hole) far better than spheres do.
//      Exact T: the two sphere trees, a node pair culled when
//      |c_A − (c'_B + y)|² > (r_A + r_B + slack)², compared squared (no sqrt), with
//      `slack` bounding the rounding of the mapped points (0 for exact T); the node with
//      the larger radius is split first.
//   3. Leaf pairs are tested exactly (trianglesIntersect), on A's vertices and on the
//      points fl(R v + t) + y of B — the same numbers every step uses.
//   4. If no boundary pair meets, the solids still overlap iff one surface component lies
//      inside the other solid: for each component of B whose box lies in A's box, one of
//      its vertices is located in A (point_in_mesh.hpp: exact ray parity); likewise for A
//      in B + y. (A connected surface that meets no boundary lies wholly inside or
//      wholly outside the other solid; if the solids overlap with disjoint boundaries,
//      some component lies inside the other — at a common point, follow the component
//      of one solid's interior around it until the other's boundary.)
// Decisions are exact on the mapped numbers (floating T: B's vertices as rounded by the
// placement; exact T with a rational rotation: exactly). The meshes must be free of
// self-intersections (see self_intersection.hpp); nothing here checks it. Steady state:
// a query allocates nothing (the traversal stacks live in the object), except inside the
// exact stage of orient3d / orient2d on inputs the floating-point filter cannot decide.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "mink/core/detail/input_checks.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/mesh/detail/box_tree.hpp"
#include "mink/mesh/point_in_mesh.hpp"
#include "mink/mesh/triangle_intersection.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {

/// What decided the last MeshOverlap query.
enum class OverlapStatus {
  Separate,        ///< no common point
  BoundariesMeet,  ///< a triangle of A and one of B + y share a point
  BInsideA,        ///< a component of B + y lies inside A (boundaries apart)
  AInsideB,        ///< a component of A lies inside B + y (boundaries apart)
  Undecided,       ///< point location could not decide (see point_in_mesh.hpp); counted as overlap
};

struct OverlapResult {
  OverlapStatus status = OverlapStatus::Separate;
  int triangleA = -1, triangleB = -1;  ///< BoundariesMeet: the pair found first
  int vertex = -1;                     ///< BInsideA: a vertex of B; AInsideB: a vertex of A
  long long nodePairs = 0;             ///< node pairs popped from the traversal stack
  long long trianglePairs = 0;         ///< leaf pairs tested exactly
  int rays = 0;                        ///< rays cast by point location
  bool overlap() const { return status != OverlapStatus::Separate; }
};

/// One pair (A, B) and one placement of B in A's frame, queried for many translations.
/// Holds copies of both meshes (cheap: shared bodies) and its own scratch, so one object
/// serves one thread. Queries neither throw nor check their y (it must be finite and
/// within ScalarTraits<T>::largestCoordinate(), like every input coordinate).
template <class T>
class MeshOverlap {
 public:
  /// B placed in A's frame: a point x of B is at rotation · x + translation. Throws
  /// InvalidInput when the rotation is not one (see detail::checkRigidPlacement). Without
  /// exceptions, construct at the identity and place with trySetPlacement.
  MeshOverlap(const TriangleMesh<T>& A, const TriangleMesh<T>& B, const Mat3<T>& rotation,
              const Vec3<T>& translation)
      : A_(A), B_(B) {
    buildComponents(A_, aComponentVertex_, aComponentLo_, aComponentHi_);
    bPoints_.resize(B_.vertices().size());
    bCentres_.resize(static_cast<std::size_t>(B_.sphereTree().numNodes()));
    std::vector<Vec3<T>> dummyLo, dummyHi;
    buildComponents(B_, bComponentVertex_, dummyLo, dummyHi);
    bComponentLo_.resize(bComponentVertex_.size());
    bComponentHi_.resize(bComponentVertex_.size());
    bComponentOf_.assign(B_.vertices().size(), 0);
    for (int t = 0; t < B_.numTriangles(); ++t)
      for (int v : B_.triangle(t)) bComponentOf_[v] = B_.triangleComponent(t);
    if constexpr (!ScalarTraits<T>::isExact) {
      T m = T(0);
      for (const Vec3<T>& v : B_.vertices()) m = std::max(m, T(v.cwiseAbs().maxCoeff()));
      for (int n = 0; n < B_.sphereTree().numNodes(); ++n)
        m = std::max(m, T(B_.sphereTree().centre(n).cwiseAbs().maxCoeff()));
      bScale_ = m;
    }
    if constexpr (!ScalarTraits<T>::isExact) {
      aBoxes_.resize(static_cast<std::size_t>(A_.numTriangles()));
      for (int f = 0; f < A_.numTriangles(); ++f)
        for (int v : A_.triangle(f)) aBoxes_[static_cast<std::size_t>(f)].add(toD(A_.vertex(v)));
      aTree_.build(aBoxes_);
      bBoxes_.resize(static_cast<std::size_t>(B_.numTriangles()));
    }
    const std::size_t depth = static_cast<std::size_t>(A_.sphereTree().height() + B_.sphereTree().height());
    stack_.reserve(2 * depth + 8);
    rayStack_.reserve(2 * depth + 8);
    setPlacement(rotation, translation);
  }

  /// A at poseA and B at poseB (world frame): B's placement in A's frame is
  /// (RA^T RB, RA^T (tB − tA)). Throws InvalidInput for a pose that is not a rigid
  /// placement (without exceptions, see tryMeshesOverlap for the checks).
  MeshOverlap(const TriangleMesh<T>& A, const Pose<T>& poseA, const TriangleMesh<T>& B, const Pose<T>& poseB)
      : MeshOverlap(A, B, relativeRotation(poseA, poseB), relativeTranslation(poseA, poseB)) {}

  /// Places B anew (same meshes); allocates nothing. Throws InvalidInput when the rotation
  /// is not one (without exceptions, prints it and aborts: use trySetPlacement).
  void setPlacement(const Mat3<T>& rotation, const Vec3<T>& translation) {
    detail::raiseIf(trySetPlacement(rotation, translation));
  }

  /// setPlacement without exceptions: the Error "MeshOverlap: placement..." for a rotation
  /// that is not one or a translation that is not finite (B keeps its placement), or none
  /// once B is placed. Allocates nothing when the placement is fine.
  [[nodiscard]] Error trySetPlacement(const Mat3<T>& rotation, const Vec3<T>& translation) {
    if (Error e = detail::checkRigidPlacement(rotation, translation, "MeshOverlap", "placement")) return e;
    focused_ = false;
    R_ = rotation;
    t_ = translation;
    for (std::size_t v = 0; v < bPoints_.size(); ++v) bPoints_[v] = R_ * B_.vertex(static_cast<int>(v)) + t_;
    // B's sphere centres: every sphere test of exact T; for floating T only a point
    // location in B (A inside B, rare), so placed there, on first use (placeCentres).
    bCentresPlaced_ = false;
    if constexpr (ScalarTraits<T>::isExact) placeCentres();
    for (std::size_t c = 0; c < bComponentLo_.size(); ++c) {
      bComponentLo_[c] = bComponentHi_[c] = bPoints_[bComponentVertex_[c]];
    }
    for (std::size_t v = 0; v < bPoints_.size(); ++v) {
      const int c = bComponentOf_[v];
      bComponentLo_[c] = bComponentLo_[c].cwiseMin(bPoints_[v]);
      bComponentHi_[c] = bComponentHi_[c].cwiseMax(bPoints_[v]);
    }
    bLo_ = bComponentLo_[0];
    bHi_ = bComponentHi_[0];
    for (std::size_t c = 1; c < bComponentLo_.size(); ++c) {
      bLo_ = bLo_.cwiseMin(bComponentLo_[c]);
      bHi_ = bHi_.cwiseMax(bComponentHi_[c]);
    }
    if constexpr (!ScalarTraits<T>::isExact) {
      // Rounding of fl(R x + t) for |x|∞ <= bScale_ (3 products, 3 sums per component)
      // and of fl(w + y), as a Euclidean distance between two such points, with a factor
      // 2 to spare: see slackFor.
      const T eps = ScalarTraits<T>::epsilon();
      placementSlack_ = T(32) * eps * (T(3) * bScale_ + t_.cwiseAbs().maxCoeff());
      // A rotation is accepted up to R^T R = I + E with |E_ij| <= kRotationTolerance: it
      // may stretch B by up to sqrt(1 + 3 max|E_ij|) (Gershgorin), which B's radii must
      // follow; E itself is computed with a rounding of a few eps.
      const Mat3<T> E = R_.transpose() * R_ - Mat3<T>::Identity();
      radiusScale_ = T(1) + T(2) * E.cwiseAbs().maxCoeff() + T(8) * eps;
      // B's triangle boxes from the very points the exact tests use.
      double scale = 0.0;
      for (int f = 0; f < B_.numTriangles(); ++f) {
        detail::Box3& b = bBoxes_[static_cast<std::size_t>(f)];
        b = detail::Box3();
        for (int v : B_.triangle(f)) b.add(toD(bPoints_[static_cast<std::size_t>(v)]));
        scale = std::max({scale, b.hi.cwiseAbs().maxCoeff(), b.lo.cwiseAbs().maxCoeff()});
      }
      // B's tree is split anew only when the rotation has turned far from the one it was
      // split at; nearer placements (a motion's next frame) refit it: rebuilding with a
      // median split per node cost more than a coherent CPD query's collision tests on
      // meshes of a thousand triangles, and the boxes of a split made at a rotation far
      // from the current one grow loose (random poses of thin shapes: ~1.5x the node pairs).
      if (bTree_.size() == bBoxes_.size() && (R_ - bSplitR_).cwiseAbs().maxCoeff() <= T(kRefitTurn)) {
        bTree_.refit(bBoxes_);
      } else {
        bTree_.build(bBoxes_);
        bSplitR_ = R_;
      }
      for (const detail::Box3& b : aBoxes_) scale = std::max({scale, b.hi.cwiseAbs().maxCoeff(), b.lo.cwiseAbs().maxCoeff()});
      boxScale_ = scale;
    }
    return Error();
  }

  /// Largest change of a rotation entry since B's box tree was split under which
  /// placements refit it instead of splitting it again (about 0.25 rad of turn): a search
  /// structure's trade of placement time against query time, no effect on any answer.
  static constexpr double kRefitTurn = 0.25;

  const Mat3<T>& rotation() const { return R_; }
  const Vec3<T>& translation() const { return t_; }
  const TriangleMesh<T>& meshA() const { return A_; }
  const TriangleMesh<T>& meshB() const { return B_; }

  /// Does A meet B + y (y in A's frame)? Fills result().
  bool overlaps(const Vec3<T>& y = Vec3<T>::Zero()) {
    assert(ScalarTraits<T>::isFinite(y[0]) && ScalarTraits<T>::isFinite(y[1]) && ScalarTraits<T>::isFinite(y[2]) &&
           "MeshOverlap::overlaps: y must be finite");
    result_ = OverlapResult();
    y_ = y;
    slackB_ = slackFor(y);
    if (boundariesMeet()) {
      result_.status = OverlapStatus::BoundariesMeet;
      return true;
    }
    containment();
    return result_.overlap();
  }

  /// What decided the last overlaps() call, with traversal counts.
  const OverlapResult& result() const { return result_; }

  /// Floating-point T: forNearTrianglePairs(centre, pad, near), keeping the pairs as a
  /// focus for the queries that follow: a query whose y lies within `reach` (max norm) of
  /// `centre` then tests only those pairs (a box test each, then the exact test) instead
  /// of traversing both trees. The traversal's pad is grown to at least reach plus the
  /// boxes' rounding, so that a pair left out cannot meet at any such y (near() may see a
  /// few more pairs than `pad` alone would give). Other y, every query after unfocus()
  /// or a new placement, and all of them when more than kMaxFocusPairs pairs are near,
  /// traverse. No answer depends on it (CPD's trimming: the
  /// patches of one ball are tested at points inside it). Returns the node pairs visited.
  template <class Near>
  long long focusNear(const Vec3<T>& centre, double reach, double pad, Near&& near) {
    static_assert(!ScalarTraits<T>::isExact, "MeshOverlap::focusNear: floating-point T only");
    focused_ = false;
    focusPairs_.clear();
    focusCentre_ = toD(centre);
    focusReach_ = reach >= 0.0 && std::isfinite(reach) ? reach : 0.0;
    const double u = std::max(detail::toDouble(ScalarTraits<T>::epsilon()), std::ldexp(1.0, -52));
    const double P = std::max(pad, focusReach_ + 16.0 * u * (boxScale_ + focusCentre_.cwiseAbs().maxCoeff() + focusReach_));
    bool tooMany = false;
    aTree_.anyPair(bTree_, focusCentre_, P, [&](int fa, int fb) {
      if (!tooMany) {
        tooMany = focusPairs_.size() == kMaxFocusPairs;
        if (!tooMany) focusPairs_.emplace_back(fa, fb);
      }
      near(fa, fb);
      return false;
    });
    focused_ = std::isfinite(P) && !tooMany;
    return aTree_.pairsVisited();
  }
  /// The most pairs a focus keeps: a larger ball's queries traverse instead (scanning the
  /// list costs a box test per pair and query; a traversal near touching costs about as
  /// much as a few thousand of them). A search structure's choice, no effect on answers.
  static constexpr std::size_t kMaxFocusPairs = 4096;
  void unfocus() { focused_ = false; }

  /// B's vertex v placed in A's frame and moved by the last query's y: the point every
  /// test of that query used.
  Vec3<T> placedVertexB(int v) const { return bPoints_[v] + y_; }

  /// Floating-point T only (the box trees are in double): calls near(fa, fb) for every
  /// triangle fa of A and fb of B (as placed) whose boxes come within `pad` of each other
  /// on every axis once B's is moved by y. A search, not a decision: a caller that needs
  /// every pair within some distance adds the rounding of the conversion to double and
  /// of its own arithmetic to `pad` (boxScale() bounds the boxes' coordinates). Returns
  /// the node pairs the traversal visited.
  template <class Near>
  long long forNearTrianglePairs(const Vec3<T>& y, double pad, Near&& near) const {
    static_assert(!ScalarTraits<T>::isExact, "MeshOverlap::forNearTrianglePairs: floating-point T only");
    aTree_.anyPair(bTree_, toD(y), pad, [&](int fa, int fb) {
      near(fa, fb);
      return false;
    });
    return aTree_.pairsVisited();
  }

  /// Floating-point T: the largest coordinate of the triangle boxes (A's, B's as placed).
  double boxScale() const { return boxScale_; }

 private:
  // A view of B + y for point location (see detail::MeshInOwnFrame).
  struct PlacedB {
    const MeshOverlap& o;
    Vec3<T> corner(int t, int i) const { return o.bPoints_[o.B_.triangle(t)[i]] + o.y_; }
    const SphereTree<T>& tree() const { return o.B_.sphereTree(); }
    Vec3<T> nodeCentre(int node) const { return o.bCentres_[node] + o.y_; }
    T nodeRadius(int node) const { return o.inflated(o.B_.sphereTree().radius(node)); }
    Vec3<T> boxLo() const { return o.bLo_ + o.y_; }
    Vec3<T> boxHi() const { return o.bHi_ + o.y_; }
  };

  static Mat3<T> relativeRotation(const Pose<T>& a, const Pose<T>& b) {
    detail::raiseIf(detail::checkRigidPlacement(a.rotation, a.translation, "MeshOverlap", "poseA"));
    detail::raiseIf(detail::checkRigidPlacement(b.rotation, b.translation, "MeshOverlap", "poseB"));
    return a.rotation.transpose() * b.rotation;
  }
  static Vec3<T> relativeTranslation(const Pose<T>& a, const Pose<T>& b) {
    return a.rotation.transpose() * (b.translation - a.translation);
  }

  // One vertex per component and the component's box.
  static void buildComponents(const TriangleMesh<T>& M, std::vector<int>& vertex, std::vector<Vec3<T>>& lo,
                              std::vector<Vec3<T>>& hi) {
    const int nc = M.numComponents();
    vertex.assign(nc, -1);
    lo.assign(nc, Vec3<T>::Zero());
    hi.assign(nc, Vec3<T>::Zero());
    for (int t = 0; t < M.numTriangles(); ++t) {
      const int c = M.triangleComponent(t);
      for (int v : M.triangle(t)) {
        if (vertex[c] < 0) {
          vertex[c] = v;
          lo[c] = hi[c] = M.vertex(v);
        }
        lo[c] = lo[c].cwiseMin(M.vertex(v));
        hi[c] = hi[c].cwiseMax(M.vertex(v));
      }
    }
  }

  // Floating T: for every B vertex or centre x, the stored point P(x) = fl(fl(R x + t) + y)
  // is within e = 4 eps (3 bScale + |t|∞) + eps (3 bScale + |t|∞ + |y|∞) of R x + t + y in
  // each coordinate, so two such points are within 2 √3 e of their exact distance; this
  // returns 4 e rounded generously (32 eps and 8 eps), 0 for exact T.
  T slackFor(const Vec3<T>& y) const {
    if constexpr (ScalarTraits<T>::isExact) {
      (void)y;
      return T(0);
    } else {
      return placementSlack_ + T(8) * ScalarTraits<T>::epsilon() * y.cwiseAbs().maxCoeff();
    }
  }
  // A radius of B's tree, stretched as R may stretch, grown by the slack and rounded up
  // (exact T: unchanged; the rotation is then exactly orthonormal).
  T inflated(const T& r) const {
    if constexpr (ScalarTraits<T>::isExact) {
      return r;
    } else {
      return (r * radiusScale_ + slackB_) * (T(1) + T(4) * ScalarTraits<T>::epsilon());
    }
  }

  bool boundariesMeet() {
    if constexpr (!ScalarTraits<T>::isExact) return focused_ && inFocus() ? focusedBoxesMeet() : boxesMeet();
    const SphereTree<T>& ta = A_.sphereTree();
    const SphereTree<T>& tb = B_.sphereTree();
    stack_.clear();
    stack_.push_back({SphereTree<T>::root(), SphereTree<T>::root()});
    while (!stack_.empty()) {
      const auto [a, b] = stack_.back();
      stack_.pop_back();
      ++result_.nodePairs;
      const T rB = inflated(tb.radius(b));
      if (detail::spheresApart(ta.centre(a), ta.radius(a), Vec3<T>(bCentres_[b] + y_), rB)) continue;
      const bool leafA = ta.isLeaf(a), leafB = tb.isLeaf(b);
      if (leafA && leafB) {
        ++result_.trianglePairs;
        const int fa = ta.triangle(a), fb = tb.triangle(b);
        const auto& ia = A_.triangle(fa);
        const auto& ib = B_.triangle(fb);
        if (trianglesIntersect(A_.vertex(ia[0]), A_.vertex(ia[1]), A_.vertex(ia[2]), Vec3<T>(bPoints_[ib[0]] + y_),
                               Vec3<T>(bPoints_[ib[1]] + y_), Vec3<T>(bPoints_[ib[2]] + y_))) {
          result_.triangleA = fa;
          result_.triangleB = fb;
          return true;
        }
        continue;
      }
      // Split the larger sphere; its child nearer the other node is visited first (a
      // contact, when there is one, is found sooner; the order changes nothing else).
      if (leafB || (!leafA && !(ta.radius(a) < rB))) {
        const Vec3<T> cB = bCentres_[b] + y_;
        pushNearerLast({ta.left(a), b}, {ta.right(a), b}, T((ta.centre(ta.left(a)) - cB).squaredNorm()),
                       T((ta.centre(ta.right(a)) - cB).squaredNorm()));
      } else {
        const Vec3<T> cA = ta.centre(a) - y_;
        pushNearerLast({a, tb.left(b)}, {a, tb.right(b)}, T((bCentres_[tb.left(b)] - cA).squaredNorm()),
                       T((bCentres_[tb.right(b)] - cA).squaredNorm()));
      }
    }
    return false;
  }

  // Floating T: the box trees. A point p of B's triangle, rounded to double, lies in its
  // box; fl(p + y) in T and p + y in double differ by the rounding of T's sum and of the
  // conversions to double, each under one unit roundoff (T's or double's, the larger) of
  // the larger magnitude: `pad`, four of them, grows every comparison.
  bool boxesMeet() {
    const Eigen::Vector3d y = toD(y_);
    const double u = std::max(detail::toDouble(ScalarTraits<T>::epsilon()), std::ldexp(1.0, -52));
    const double pad = 4.0 * u * (boxScale_ + y.cwiseAbs().maxCoeff());
    const bool met = aTree_.anyPair(bTree_, y, pad, [&](int fa, int fb) {
      ++result_.trianglePairs;
      const auto& ia = A_.triangle(fa);
      const auto& ib = B_.triangle(fb);
      if (!trianglesIntersect(A_.vertex(ia[0]), A_.vertex(ia[1]), A_.vertex(ia[2]), Vec3<T>(bPoints_[ib[0]] + y_),
                              Vec3<T>(bPoints_[ib[1]] + y_), Vec3<T>(bPoints_[ib[2]] + y_)))
        return false;
      result_.triangleA = fa;
      result_.triangleB = fb;
      return true;
    });
    result_.nodePairs = aTree_.pairsVisited();
    return met;
  }
  // The focus (see focusNear()). Is y within reach of the centre, as the doubles compare?
  bool inFocus() const {
    const Eigen::Vector3d y = toD(y_);
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(y[k] - focusCentre_[k]) <= focusReach_)) return false;
    return true;
  }
  // boxesMeet over the focus's pairs. Why none is lost: triangles fa, fb that meet at y
  // have boxes within boxesMeet's pad p = 4u (S + |y|∞) at offset y on every axis (S =
  // boxScale_), hence within reach + p + u·reach at the offset c = centre (|y − c| <=
  // reach as compared, one rounding); focusNear's traversal drops a pair only when two
  // rounded sums (magnitudes under S + |c| + P, relative error u each) put them more
  // than P apart, i.e. truly more than P − 2u (S + |c| + P) >= reach + 13u (S + |c| +
  // reach), which exceeds reach + p + u·reach since |y| <= |c| + reach.
  bool focusedBoxesMeet() {
    const Eigen::Vector3d y = toD(y_);
    const double u = std::max(detail::toDouble(ScalarTraits<T>::epsilon()), std::ldexp(1.0, -52));
    const double pad = 4.0 * u * (boxScale_ + y.cwiseAbs().maxCoeff());
    result_.nodePairs = static_cast<long long>(focusPairs_.size());
    for (const std::pair<int, int>& fp : focusPairs_) {
      const detail::Box3& a = aBoxes_[static_cast<std::size_t>(fp.first)];
      const detail::Box3& b = bBoxes_[static_cast<std::size_t>(fp.second)];
      bool apart = false;
      for (int k = 0; k < 3 && !apart; ++k)
        apart = a.lo[k] > b.hi[k] + y[k] + pad || b.lo[k] + y[k] > a.hi[k] + pad;
      if (apart) continue;
      ++result_.trianglePairs;
      const auto& ia = A_.triangle(fp.first);
      const auto& ib = B_.triangle(fp.second);
      if (!trianglesIntersect(A_.vertex(ia[0]), A_.vertex(ia[1]), A_.vertex(ia[2]), Vec3<T>(bPoints_[ib[0]] + y_),
                              Vec3<T>(bPoints_[ib[1]] + y_), Vec3<T>(bPoints_[ib[2]] + y_)))
        continue;
      result_.triangleA = fp.first;
      result_.triangleB = fp.second;
      return true;
    }
    return false;
  }

  static Eigen::Vector3d toD(const Vec3<T>& x) {
    return Eigen::Vector3d(detail::toDouble(x[0]), detail::toDouble(x[1]), detail::toDouble(x[2]));
  }

  void pushNearerLast(const std::pair<int, int>& p, const std::pair<int, int>& q, const T& dp, const T& dq) {
    if (dp < dq) {
      stack_.push_back(q);
      stack_.push_back(p);
    } else {
      stack_.push_back(p);
      stack_.push_back(q);
    }
  }

  static bool boxInside(const Vec3<T>& lo, const Vec3<T>& hi, const Vec3<T>& outerLo, const Vec3<T>& outerHi) {
    for (int k = 0; k < 3; ++k)
      if (lo[k] < outerLo[k] || outerHi[k] < hi[k]) return false;
    return true;
  }

  // bCentres_ := B's sphere centres as placed (once per placement).
  void placeCentres() {
    if (bCentresPlaced_) return;
    const SphereTree<T>& tree = B_.sphereTree();
    for (int n = 0; n < tree.numNodes(); ++n) bCentres_[n] = R_ * tree.centre(n) + t_;
    bCentresPlaced_ = true;
  }

  // Step 4 of the header comment. A point of a surface that meets no boundary of the other
  // solid is not on it, so OnBoundary cannot come back; it would count as overlap.
  void containment() {
    const detail::MeshInOwnFrame<T> viewA{A_};
    for (std::size_t c = 0; c < bComponentVertex_.size(); ++c) {
      if (!boxInside(Vec3<T>(bComponentLo_[c] + y_), Vec3<T>(bComponentHi_[c] + y_), A_.boxMin(), A_.boxMax()))
        continue;
      const int v = bComponentVertex_[c];
      const PointLocation where = detail::locatePoint(viewA, Vec3<T>(bPoints_[v] + y_), rayStack_, &result_.rays);
      if (where != PointLocation::Outside) {
        result_.status = where == PointLocation::Undecided ? OverlapStatus::Undecided : OverlapStatus::BInsideA;
        result_.vertex = v;
        return;
      }
    }
    placeCentres();
    const PlacedB viewB{*this};
    const Vec3<T> lo = viewB.boxLo(), hi = viewB.boxHi();
    for (std::size_t c = 0; c < aComponentVertex_.size(); ++c) {
      if (!boxInside(aComponentLo_[c], aComponentHi_[c], lo, hi)) continue;
      const int v = aComponentVertex_[c];
      const PointLocation where = detail::locatePoint(viewB, A_.vertex(v), rayStack_, &result_.rays);
      if (where != PointLocation::Outside) {
        result_.status = where == PointLocation::Undecided ? OverlapStatus::Undecided : OverlapStatus::AInsideB;
        result_.vertex = v;
        return;
      }
    }
  }

  TriangleMesh<T> A_, B_;
  Mat3<T> R_ = Mat3<T>::Identity();
  Vec3<T> t_ = Vec3<T>::Zero(), y_ = Vec3<T>::Zero();
  std::vector<Vec3<T>> bPoints_, bCentres_;
  bool bCentresPlaced_ = false;
  std::vector<int> aComponentVertex_, bComponentVertex_, bComponentOf_;
  std::vector<Vec3<T>> aComponentLo_, aComponentHi_, bComponentLo_, bComponentHi_;
  Vec3<T> bLo_ = Vec3<T>::Zero(), bHi_ = Vec3<T>::Zero();
  T bScale_ = T(0), placementSlack_ = T(0), slackB_ = T(0), radiusScale_ = T(1);
  std::vector<std::pair<int, int>> stack_;
  std::vector<int> rayStack_;
  // Floating T: triangle boxes (A's fixed, B's per placement) and their trees.
  std::vector<detail::Box3> aBoxes_, bBoxes_;
  detail::BoxTree aTree_, bTree_;
  Mat3<T> bSplitR_ = Mat3<T>::Identity();  // the rotation B's tree was last split at
  double boxScale_ = 0.0;
  OverlapResult result_;
  // Floating T: the focus (see focusNear()).
  bool focused_ = false;
  Eigen::Vector3d focusCentre_ = Eigen::Vector3d::Zero();
  double focusReach_ = 0.0;
  std::vector<std::pair<int, int>> focusPairs_;
};

/// meshesOverlap without exceptions: whether A at poseA and B at poseB (world frame) share
/// a point, or the Error meshesOverlap throws for a pose that is not a rigid placement
/// (poseA, poseB, then their relative placement, as MeshOverlap's constructor checks them).
template <class T>
Result<bool> tryMeshesOverlap(const TriangleMesh<T>& A, const Pose<T>& poseA, const TriangleMesh<T>& B,
                              const Pose<T>& poseB) {
  if (Error e = detail::checkRigidPlacement(poseA.rotation, poseA.translation, "MeshOverlap", "poseA")) return e;
  if (Error e = detail::checkRigidPlacement(poseB.rotation, poseB.translation, "MeshOverlap", "poseB")) return e;
  const Mat3<T> RAt = poseA.rotation.transpose();
  const Mat3<T> R = RAt * poseB.rotation;
  const Vec3<T> t = RAt * (poseB.translation - poseA.translation);
  if (Error e = detail::checkRigidPlacement(R, t, "MeshOverlap", "placement")) return e;
  MeshOverlap<T> o(A, B, R, t);
  return o.overlaps();
}

/// Do A at poseA and B at poseB (world frame) share a point? One-off form of MeshOverlap
/// (which it builds: O(#vertices of B) set-up and allocation); throws InvalidInput for a
/// pose whose rotation is not one (without exceptions: prints it and aborts; use
/// tryMeshesOverlap).
template <class T>
bool meshesOverlap(const TriangleMesh<T>& A, const Pose<T>& poseA, const TriangleMesh<T>& B, const Pose<T>& poseB) {
  return tryMeshesOverlap(A, poseA, B, poseB).value();
}

}  // namespace mink
