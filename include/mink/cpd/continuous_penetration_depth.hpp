// mink/cpd/continuous_penetration_depth.hpp — the continuous penetration depth (CPD) of two
// closed triangle meshes, and the Euclidean penetration depth from the same machinery.
//
// Source: Y. Lee, E. Behar, J.-M. Lien, Y. J. Kim, "Continuous penetration depth
// computation for rigid models using dynamic Minkowski sums", CAD 2016, sections 3.3, 6
// and Algorithm 2. M = poseA(A) ⊕ −poseB(B); B moved by x overlaps A iff x ∈ M, so the
// interiors overlap iff the origin o is inside M, and the depth is a point q of ∂M.
//   1. Separated (depth 0) when A and B share no point (mesh/mesh_overlap.hpp), or when
//      they only touch: o lies on ∂M.
//   2. Start q0: the previous frame's q when it still has ∂M around it (coherence), else
//      the shortest first exit of o from M along 27 directions (the line between the
//      shapes' centres, and to a cube's faces, edges and corners), each found on the
//      overlap test: the first free
//      point of a ladder 2^-16 .. 1 of the far end, then bisection; and from that exit,
//      the point of ∂M nearest to o (the Euclidean penetration depth, global): the patch
//      of a ball around o, grown from |exit| / 8 by doubling until it meets ∂M, holds it
//      (mink's stand-in for the paper's PolyDepth, which seeds with the global depth).
//   3. Algorithm 2: the patch of ∂M in the ball S(q_i, r), r = alpha |q_i|
//      (cpd/local_minkowski_sum.hpp); Phong projection of o onto every triangle
//      (cpd/phong_projection.hpp); the nearest projection inside the ball is the answer —
//      nearest to o, or, in the first ball of a query started from the last frame's q,
//      nearest to that q (the continuation of the last answer: where ∂M has several
//      projections near q, as deep inside a coarse curved M, the nearest to o can switch
//      between them from frame to frame).
//      Otherwise the barycentre c of least |n̂ × c| (the paper's Ψ · c) becomes q_{i+1}
//      if it improves on the best so far, else the ball grows by beta, up to
//      maxRadiusFactor · |q0|; after the caps the best candidate is returned as
//      Approximate (it lies on ∂M).
//   4. penetrationDepth(): the nearest point of step 2, the global minimum of |q| over
//      ∂M. Only if rounding kept every ball around o empty, the loop of step 3 with the
//      nearest point of the patch to o instead of the Phong projection (a local minimum
//      of |q| when it lies strictly inside the ball).
// Floating-point T only (Phong projection needs rounding and sqrt).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/detail/input_checks.hpp"
#include "mink/core/error.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/cpd/local_minkowski_sum.hpp"
#include "mink/cpd/phong_projection.hpp"
#include "mink/mesh/detail/closest_point.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "mink/mesh/triangle_intersection.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {

/// Parameters of Algorithm 2 (defaults in core/defaults.hpp, with units and ranges).
template <class T>
struct CpdOptions {
  T alpha = T(defaults::kCpdAlpha);          ///< ball radius = alpha |q| (dimensionless)
  T beta = T(defaults::kCpdBeta);            ///< growth of the ball when q does not improve
  int maxIterations = defaults::kCpdMaxIterations;   ///< balls built per query
  int exitBisectionSteps = defaults::kCpdExitBisectionSteps;  ///< per start direction
  T maxRadiusFactor = T(defaults::kCpdMaxRadiusFactor);     ///< ball radius <= this · |start q|
  PhongOptions<T> phong;                     ///< Definition 1's tolerance, Newton's cap
  LocalMinkowskiSumOptions<T> localSum;      ///< how the patch finds its facets
};

enum class CpdStatus {
  Separated,    ///< the interiors do not overlap (touching included): depth 0
  Penetrating,  ///< overlap, and q satisfies Definition 1 (CPD) / is the nearest point of ∂M (PD)
  Approximate,  ///< overlap, but no such q within the caps: q is the best found, on ∂M
                ///< (if no ball met ∂M at all: the start, within 2^-exitBisectionSteps of
                ///< the scene's size outside M)
  InvalidInput  ///< builds without exceptions only (-fno-exceptions), where the query cannot
                ///< throw: options or a pose it would throw InvalidInput for
                ///< (ContinuousPenetrationDepth::error(), checkCpdOptions and checkCpdInput
                ///< give the message); depth, direction, point and normal are NaN
};

/// The enumerator's name ("Separated", "Penetrating", "Approximate", ...), for logs and
/// messages; "?" for a value outside the enumeration.
constexpr const char* toString(CpdStatus s) noexcept {
  switch (s) {
    case CpdStatus::Separated: return "Separated";
    case CpdStatus::Penetrating: return "Penetrating";
    case CpdStatus::Approximate: return "Approximate";
    case CpdStatus::InvalidInput: return "InvalidInput";
  }
  return "?";
}

/// The answer of a CPD or PD query. World frame, length unit of the meshes.
template <class T>
struct CpdResult {
  CpdStatus status = CpdStatus::Separated;
  T depth = T(0);                        ///< |q| >= 0
  Vec3<T> direction = Vec3<T>::Zero();   ///< unit; B moved by depth * direction touches A (zero when Separated)
  Vec3<T> point = Vec3<T>::Zero();       ///< q = depth * direction, a point of ∂M
  Vec3<T> normal = Vec3<T>::Zero();      ///< unit outward normal of ∂M at q: the Phong one for CPD, the
                                         ///< direction for PD; parallel to direction when Penetrating
  ConvolutionPair pair;                  ///< the convolution facet q lies on: its features of A and B
  T residual = T(0);                     ///< |normal × q|: how far o is from the normal line at q
                                         ///< (Penetrating: the rounding of the scene, ~eps · its size)
  int iterations = 0;                    ///< balls built (patches computed)
  T radius = T(0);                       ///< the last ball's radius
  long long trianglesBuilt = 0;          ///< patch triangles over all balls
  bool fromPreviousFrame = false;        ///< the search started from the last query's q
};

/// The Error for CpdOptions out of range (alpha <= 0, beta <= 1, caps < 1, ...), or none.
template <class T>
[[nodiscard]] Error checkCpdOptions(const CpdOptions<T>& options) {
  if (!(options.alpha > T(0)) || !std::isfinite(options.alpha))
    return Error("CpdOptions: alpha must be positive and finite");
  if (!(options.beta > T(1)) || !std::isfinite(options.beta))
    return Error("CpdOptions: beta must be greater than 1 and finite");
  if (options.maxIterations < 1) return Error("CpdOptions: maxIterations must be at least 1");
  if (options.exitBisectionSteps < 1) return Error("CpdOptions: exitBisectionSteps must be at least 1");
  if (!(options.maxRadiusFactor > T(0))) return Error("CpdOptions: maxRadiusFactor must be positive");
  if (!(options.phong.barycentricTolerance >= T(0)))
    return Error("CpdOptions: phong.barycentricTolerance must be >= 0");
  return Error();
}

/// The Error for poses a CPD or PD query does not take (not rigid, not finite), or none;
/// `who` names the query in the message.
template <class T>
[[nodiscard]] Error checkCpdInput(const Pose<T>& poseA, const Pose<T>& poseB,
                                  const char* who = "ContinuousPenetrationDepth::query") {
  if (Error e = detail::checkRigidPlacement(poseA.rotation, poseA.translation, who, "poseA")) return e;
  return detail::checkRigidPlacement(poseB.rotation, poseB.translation, who, "poseB");
}

namespace detail {

/// Algorithm 2 for both queries: mode Phong (CPD) or Euclidean (PD).
template <class T>
class PenetrationSearch {
  static_assert(!ScalarTraits<T>::isExact, "CPD: Phong projection needs a floating-point scalar");

 public:
  enum class Mode { Phong, Euclidean };

  PenetrationSearch(const TriangleMesh<T>& A, const TriangleMesh<T>& B, const CpdOptions<T>& options)
      : A_(A), B_(B), options_(options), sum_(A, B, options.localSum),
        overlap_(A, B, Mat3<T>::Identity(), Vec3<T>::Zero()), error_(checkCpdOptions(options)) {
#if MINK_EXCEPTIONS
    raiseIf(error_);
#endif
  }

  /// The options' Error, else the last query's (set in builds without exceptions only), or
  /// none.
  const Error& error() const { return error_ ? error_ : queryError_; }

  CpdResult<T> run(const Pose<T>& poseA, const Pose<T>& poseB, Mode mode, const char* who) {
    if (error_) return invalidInput(error_);
    if (queryError_) queryError_ = Error();  // error() tells of this query only
    if (Error e = checkCpdInput(poseA, poseB, who)) return invalidInput(e);
    CpdResult<T> res;
    RA_ = poseA.rotation;
    // The relative placement is checked too: two rotations each within the tolerance can
    // compose to one just outside it.
    Result<MeshOverlap<T>*> placed = overlapFor(poseA, poseB);
    if (!placed.ok()) return invalidInput(placed.error());
    if (!placed.value()->overlaps()) {
      hasLast_ = false;
      return res;
    }
    // The size of the scene: no point of ∂M is farther from o than this.
    const Vec3<T> cA = poseA.apply(A_.sphereTree().centre(SphereTree<T>::root()));
    const Vec3<T> cB = poseB.apply(B_.sphereTree().centre(SphereTree<T>::root()));
    const T reach = (cA - cB).stableNorm() + A_.sphereTree().radius(SphereTree<T>::root()) +
                    B_.sphereTree().radius(SphereTree<T>::root());
    const T rMax = T(4) * reach;

    Vec3<T> q;
    if (hasLast_ && mode == lastMode_) {
      q = last_;
      res.fromPreviousFrame = true;
    } else {
      q = firstExit(*placed.value(), cA - cB, reach);
      Candidate nearest;
      switch (nearestOfBoundary(poseA, poseB, q, res, nearest)) {
        case Nearest::Touching:
          hasLast_ = false;
          return CpdResult<T>{};
        case Nearest::Found:
          if (mode == Mode::Euclidean) {
            finish(nearest, CpdStatus::Penetrating, mode, res);
            return res;
          }
          q = nearest.point;
          break;
        case Nearest::Missed:
          break;
      }
    }
    T r = radiusAround(q);
    // Growth stops at maxRadiusFactor |q0|: past it, Algorithm 2 reaches projections far
    // deeper than the start (cone/axes: 3.7 where the start and PD are 0.31).
    T rCap = std::min(rMax, options_.maxRadiusFactor * q.stableNorm());
    T bestScore = std::numeric_limits<T>::infinity();
    bool haveBest = false;
    Candidate best;
    for (int it = 0; it < options_.maxIterations; ++it) {
      const MinkowskiPatch<T>& patch = sum_.update(poseA, poseB, q, r);
      ++res.iterations;
      res.radius = r;
      res.trianglesBuilt += static_cast<long long>(patch.triangles.size());
      if (patch.triangles.empty()) {
        // The previous frame's q may now lie deep inside M (or far outside): start afresh.
        if (res.fromPreviousFrame && it == 0) {
          res.fromPreviousFrame = false;
          // Placed again: this query's updates may have changed the sum's units.
          placed = overlapFor(poseA, poseB);
          if (!placed.ok()) return invalidInput(placed.error());
          q = firstExit(*placed.value(), cA - cB, reach);
          r = radiusAround(q);
          rCap = std::min(rMax, options_.maxRadiusFactor * q.stableNorm());
        } else {
          r *= options_.beta;
        }
        if (r > rMax) break;
        continue;
      }
      if (originOnPatch(patch)) {  // touching: o on ∂M
        hasLast_ = false;
        return CpdResult<T>{};
      }
      Candidate found, step;
      const bool done = mode == Mode::Phong ? phongStep(patch, q, r, res.fromPreviousFrame && it == 0, found, step) : euclideanStep(patch, q, r, found, step);
      if (done) {
        finish(found, CpdStatus::Penetrating, mode, res);
        return res;
      }
      const T score = mode == Mode::Phong ? step.residual : step.point.stableNorm();
      if (score < bestScore) {
        bestScore = score;
        best = step;
        haveBest = true;
        q = step.point;
        r = radiusAround(q);
      } else {
        r *= options_.beta;
      }
      if (r > rCap) break;
    }
    if (!haveBest) {
      // No patch at all within the caps: report the seed (on ∂M to the bisection's width).
      best.point = q;
      best.normal = unit(q);
      best.residual = T(0);
    }
    finish(best, CpdStatus::Approximate, mode, res);
    return res;
  }

  void reset() { hasLast_ = false; }

 private:
  /// Bad input: InvalidInput thrown, or (without exceptions) kept for error() and the status
  /// InvalidInput with NaN depth, direction, point and normal.
  CpdResult<T> invalidInput(const Error& e) {
#if MINK_EXCEPTIONS
    raise(e);
#else
    if (&e != &error_) queryError_ = e;
    CpdResult<T> r;
    const T nan = std::numeric_limits<T>::quiet_NaN();
    r.status = CpdStatus::InvalidInput;
    r.depth = nan;
    r.direction = r.point = r.normal = Vec3<T>::Constant(nan);
    return r;
#endif
  }

  struct Candidate {
    Vec3<T> point = Vec3<T>::Zero();
    Vec3<T> normal = Vec3<T>::Zero();
    T residual = T(0);
    ConvolutionPair pair;
  };

  /// x / |x|, from x scaled near one first: a subnormal x (a depth of 1e-319) has too few
  /// digits for x / |x| to be unit.
  static Vec3<T> unit(const Vec3<T>& x) {
    const Vec3<T> u = detail::unitOrder(x);
    return u / u.stableNorm();
  }

  void finish(const Candidate& c, CpdStatus status, Mode mode, CpdResult<T>& res) {
    if (c.point == Vec3<T>::Zero()) {
      // q = o: o on ∂M (touching, where the exact test on the patch's corners missed it
      // by their rounding), which counts as Separated.
      const int iterations = res.iterations;
      const T radius = res.radius;
      const long long built = res.trianglesBuilt;
      res = CpdResult<T>{};
      res.iterations = iterations;
      res.radius = radius;
      res.trianglesBuilt = built;
      hasLast_ = false;
      return;
    }
    res.status = status;
    res.point = c.point;
    res.depth = c.point.stableNorm();
    res.direction = res.depth > T(0) ? unit(c.point) : Vec3<T>::Zero();
    res.normal = c.normal;
    res.pair = c.pair;
    res.residual = c.normal.cross(c.point).stableNorm();
    last_ = c.point;
    lastMode_ = mode;
    hasLast_ = res.depth > T(0);
  }

  static constexpr int kExitLadder = 16;  // halvings of the far end tried before the bisection

  /// alpha |q|, but positive (the patch needs a ball).
  T radiusAround(const Vec3<T>& q) const {
    return std::max(options_.alpha * q.stableNorm(), std::numeric_limits<T>::min());
  }

  // B placed for this query in the local sum's collision test (one placement for both)
  // when the sum works in the meshes' own units, else in this object's own.
  Result<MeshOverlap<T>*> overlapFor(const Pose<T>& poseA, const Pose<T>& poseB) {
    Result<MeshOverlap<T>*> shared = sum_.overlapAt(poseA, poseB);
    if (!shared.ok() || shared.value() != nullptr) return shared;
    Mat3<T> R;
    Vec3<T> t;
    LocalMinkowskiSum<T>::relativePlacement(poseA, poseB, R, t);
    if (Error e = overlap_.trySetPlacement(R, t)) return e;
    return &overlap_;
  }

  /// The shortest first exit of o from M along the start directions (world frame): for
  /// each, bisection between 0 (B overlaps A) and a translation that clears the shapes'
  /// bounding spheres; the end that does not overlap is returned.
  Vec3<T> firstExit(MeshOverlap<T>& overlap, const Vec3<T>& between, const T& reach) {
    // The line between the centres first (often the shortest), then the 26 directions
    // to the faces, edges and corners of a cube: ±x, ±y, ±z alone miss the free cavity of
    // two linked tori, whose nearest exits lie between the axes.
    std::array<Vec3<T>, 27> dirs;
    int n = 0;
    const T len = between.stableNorm();
    if (len > T(0) && std::isfinite(len)) dirs[static_cast<std::size_t>(n++)] = between / len;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k)
          if (i || j || k) dirs[static_cast<std::size_t>(n++)] = Vec3<T>(T(i), T(j), T(k)).normalized();
    T bestT = std::numeric_limits<T>::infinity();
    Vec3<T> best = Vec3<T>::Zero();
    for (int k = 0; k < n; ++k) {
      const Vec3<T> dA = RA_.transpose() * dirs[static_cast<std::size_t>(k)];  // in A's frame
      T lo = T(0), hi = std::min(bestT, reach * T(1.0625));
      if (overlap.overlaps(Vec3<T>(hi * dA))) continue;  // no shorter than the best so far
      // The first exit, not just any: M is not convex along the ray (a linked pair of
      // tori leaves a free cavity near o inside an overlapping shell), so the free end
      // is first brought down by halves, from 2^-16 of it up, before the bisection.
      for (int h = kExitLadder; h >= 1; --h) {
        const T t = std::ldexp(hi, -h);
        if (!(t > lo)) continue;
        if (overlap.overlaps(Vec3<T>(t * dA))) {
          lo = t;
        } else {
          hi = t;
          break;
        }
      }
      for (int s = 0; s < options_.exitBisectionSteps; ++s) {
        const T mid = (lo + hi) / T(2);
        if (!(mid > lo && mid < hi)) break;
        if (overlap.overlaps(Vec3<T>(mid * dA)))
          lo = mid;
        else
          hi = mid;
      }
      if (hi < bestT) {
        bestT = hi;
        best = hi * dirs[static_cast<std::size_t>(k)];
      }
    }
    if (!std::isfinite(bestT)) best = reach * dirs[0];  // only if rounding kept every end overlapping
    return best;
  }

  enum class Nearest { Found, Touching, Missed };

  /// The point of ∂M nearest to o, globally: the patch of the ball around o of radius
  /// rho holds every point of ∂M within rho of o, so when its nearest point to o lies in
  /// the ball it is the nearest of all ∂M. rho climbs |exit| / 2^k, k = kNearestRungs..1,
  /// then the exit's own length (an exit is a point of ∂M, so the last ball meets ∂M):
  /// the first ball that meets ∂M answers, at most twice the depth, and a start deep in
  /// a narrow cavity of M (two linked tori) is found where no exit direction sees it.
  /// Missed only if rounding kept even the last ball empty.
  Nearest nearestOfBoundary(const Pose<T>& poseA, const Pose<T>& poseB, const Vec3<T>& exit, CpdResult<T>& res,
                            Candidate& nearest) {
    const T d0 = exit.stableNorm();
    if (!(d0 > T(0)) || !std::isfinite(d0)) return Nearest::Missed;
    const Vec3<T> o = Vec3<T>::Zero();
    for (int k = kNearestRungs; k >= 0; --k) {
      // The exit is the free end of its bisection: outside M by at most its width. (Finer
      // rungs, factors 2^(1/4), cost more: the depth is most often the exit's own length,
      // so every rung below it is built empty, which is cheap, but not free.)
      // Never below the smallest normal number: on a scene of denormal size (boxes
      // 1e-308 across) d0 / 2^k underflows to 0, and a larger ball is still sound (it
      // holds every point of ∂M within its radius), only less tight.
      const T rho = std::max(k > 0 ? std::ldexp(d0, -k) : d0 * T(1.0625), std::numeric_limits<T>::min());
      const MinkowskiPatch<T>& patch = sum_.update(poseA, poseB, o, rho);
      ++res.iterations;
      res.radius = rho;
      res.trianglesBuilt += static_cast<long long>(patch.triangles.size());
      if (patch.triangles.empty()) continue;
      if (originOnPatch(patch)) return Nearest::Touching;
      Candidate ignored;
      euclideanStep(patch, o, rho, ignored, nearest);
      if (nearest.point.stableNorm() <= rho) return Nearest::Found;
    }
    return Nearest::Missed;
  }

  static constexpr int kNearestRungs = 3;  // balls of |exit| / 8, / 4, / 2 before |exit|

  /// Does o lie on a triangle of the patch (exactly, on its corners' coordinates)?
  static bool originOnPatch(const MinkowskiPatch<T>& patch) {
    const Vec3<T> o = Vec3<T>::Zero();
    for (const auto& t : patch.triangles) {
      const Vec3<T>& a = patch.vertices[static_cast<std::size_t>(t[0])];
      const Vec3<T>& b = patch.vertices[static_cast<std::size_t>(t[1])];
      const Vec3<T>& c = patch.vertices[static_cast<std::size_t>(t[2])];
      if (orient3d(a, b, c, o) != 0) continue;
      const int k = properAxis(a, b, c);
      if (k >= 0 && pointInTriangle2d(o, a, b, c, k)) return true;
    }
    return false;
  }

  /// CPD: the Phong projection of o inside the ball nearest to o (nearest to the centre
  /// when `follow`) (true), else in `step` the barycentre of least residual.
  bool phongStep(const MinkowskiPatch<T>& patch, const Vec3<T>& centre, const T& r, bool follow, Candidate& found, Candidate& step) {
    surface_.build(patch);
    const Vec3<T> o = Vec3<T>::Zero();
    T bestDepth = std::numeric_limits<T>::infinity();
    step.residual = std::numeric_limits<T>::infinity();
    bool any = false;
    for (int t = 0; t < surface_.numTriangles(); ++t) {
      const PhongHit<T> hit = surface_.project(t, o, options_.phong);
      if (hit.found && (hit.point - centre).stableNorm() <= r) {
        const T d = follow ? (hit.point - centre).stableNorm() : hit.point.stableNorm();
        if (d < bestDepth) {
          bestDepth = d;
          found = {hit.point, hit.normal, hit.residual, patch.pairs[static_cast<std::size_t>(t)]};
          any = true;
        }
      }
      Vec3<T> c;
      const T res = surface_.barycentreResidual(t, o, &c);
      if (res < step.residual) {
        const std::array<T, 3> third = {T(1) / T(3), T(1) / T(3), T(1) / T(3)};
        step = {c, surface_.normalAt(t, third), res, patch.pairs[static_cast<std::size_t>(t)]};
      }
    }
    if (!std::isfinite(step.residual)) {
      // Every barycentre faces o (o outside M near this patch): step towards the nearest.
      Candidate e;
      euclideanStep(patch, centre, r, e, step);
      step.residual = std::numeric_limits<T>::max();
    }
    return any;
  }

  /// PD: the nearest point of the patch to o; true when it lies strictly inside the ball
  /// (then no point of ∂M near it is nearer: a local minimum).
  bool euclideanStep(const MinkowskiPatch<T>& patch, const Vec3<T>& centre, const T& r, Candidate& found,
                     Candidate& step) {
    // In the ball's unit frame (centre at 0, radius scaled to [1/2, 1) by a power of two):
    // the closest-point construction multiplies coordinates, which would underflow for a
    // patch at 2^-600 and lose the region tests.
    int e = 0;
    std::frexp(r, &e);
    auto local = [&](const Vec3<T>& x) {
      Vec3<T> y;
      for (int k = 0; k < 3; ++k) y[k] = std::ldexp(x[k] - centre[k], -e);
      return y;
    };
    const Vec3<T> o = local(Vec3<T>::Zero());
    T best = std::numeric_limits<T>::infinity();
    for (std::size_t t = 0; t < patch.triangles.size(); ++t) {
      const auto& tri = patch.triangles[t];
      const Vec3<T> a = local(patch.vertices[static_cast<std::size_t>(tri[0])]);
      const Vec3<T> b = local(patch.vertices[static_cast<std::size_t>(tri[1])]);
      const Vec3<T> c = local(patch.vertices[static_cast<std::size_t>(tri[2])]);
      const Vec3<T> pl = closestPointOnTriangle(o, a, b, c);
      const T d = (pl - o).squaredNorm();
      if (d < best) {
        best = d;
        Vec3<T> p;
        for (int k = 0; k < 3; ++k) p[k] = centre[k] + std::ldexp(pl[k], e);
        step = {p, p == Vec3<T>::Zero() ? Vec3<T>::Zero() : unit(p), T(0), patch.pairs[t]};
      }
    }
    found = step;
    return std::isfinite(best) && (step.point - centre).stableNorm() < r;
  }

  TriangleMesh<T> A_, B_;
  CpdOptions<T> options_;
  LocalMinkowskiSum<T> sum_;
  MeshOverlap<T> overlap_;
  Error error_;       // the options'
  Error queryError_;  // the last query's pose (builds without exceptions)
  PhongSurface<T> surface_;
  Mat3<T> RA_ = Mat3<T>::Identity();
  Vec3<T> last_ = Vec3<T>::Zero();
  Mode lastMode_ = Mode::Phong;
  bool hasLast_ = false;
};

}  // namespace detail

/// CPD of one pair of meshes, frame after frame: keeps its local Minkowski sum and the
/// last answer's q, from which the next query starts (section 6.2). Built without
/// exceptions, bad options or poses give CpdStatus::InvalidInput instead of a throw.
template <class T>
class ContinuousPenetrationDepth {
 public:
  /// Throws InvalidInput for options out of range (alpha <= 0, beta <= 1, caps < 1:
  /// checkCpdOptions); without exceptions, keeps that Error (error()) and answers every
  /// query InvalidInput.
  ContinuousPenetrationDepth(const TriangleMesh<T>& A, const TriangleMesh<T>& B, const CpdOptions<T>& options = {})
      : search_(A, B, options) {}

  /// Builds without exceptions only: why queries answer InvalidInput. The options' Error
  /// (checkCpdOptions; every query answers InvalidInput), else that of the last query if
  /// its poses were rejected; no Error otherwise (and always, with exceptions).
  const Error& error() const { return search_.error(); }

  /// A at poseA, B at poseB (world frame). Throws InvalidInput for a pose that is not
  /// rigid or not finite, before any work (without exceptions: the status InvalidInput,
  /// and error() gives the message).
  CpdResult<T> query(const Pose<T>& poseA, const Pose<T>& poseB) {
    return search_.run(poseA, poseB, detail::PenetrationSearch<T>::Mode::Phong, "ContinuousPenetrationDepth::query");
  }

  /// Forget the previous frame: the next query starts from the exits of o.
  void reset() { search_.reset(); }

 private:
  detail::PenetrationSearch<T> search_;
};

/// The Euclidean penetration depth: a point q of ∂M nearest to o (the global minimum of
/// |q|, from the patch of the smallest ball around o, among |exit| / 8, / 4, / 2 and
/// |exit|, that meets ∂M). Same result type; the normal is the direction. Such a
/// point can be the corner of a step of ∂M (a concave crease whose two faces both turn
/// away from o); B moved by depth * direction touches A there, but moving it a little
/// further along direction makes them overlap again.
/// Throws InvalidInput as ContinuousPenetrationDepth does (without exceptions: the status
/// InvalidInput).
template <class T>
CpdResult<T> penetrationDepth(const TriangleMesh<T>& A, const Pose<T>& poseA, const TriangleMesh<T>& B,
                              const Pose<T>& poseB, const CpdOptions<T>& options = {}) {
  detail::PenetrationSearch<T> search(A, B, options);
  return search.run(poseA, poseB, detail::PenetrationSearch<T>::Mode::Euclidean, "penetrationDepth");
}

}  // namespace mink
