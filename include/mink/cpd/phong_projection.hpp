// mink/cpd/phong_projection.hpp — Phong projection of a point onto a triangulated patch of
// ∂M: the point q of a triangle whose interpolated surface normal passes through o.
//
// Source: Y. Lee, E. Behar, J.-M. Lien, Y. J. Kim, "Continuous penetration depth
// computation for rigid models using dynamic Minkowski sums", CAD 2016, section 3.1
// (Definition 1) and section 6.2.
//   1. Corners with equal coordinates are merged (the patch names corners by how they were
//      made; two names can land on one point), so each point of the patch has one normal.
//   2. Vertex normals: the area-weighted mean of the incident triangles' normals (the sum
//      of the unnormalised cross products), unit length.
//   3. The normal at barycentric λ of a triangle is the normalised λ-combination of its
//      three vertex normals. Along an edge it depends on that edge's two corners only, so
//      the field is continuous across the patch; it is singular only where the three
//      vertex normals are not in an open hemisphere (the tangent-basis rotation of the
//      paper's Fig. 2b has the same singular set: the bases cannot be rotated into one
//      another continuously there either).
//   4. Definition 1 on triangle t: find λ with (q(λ) − o) × n(λ) = 0, Σλ = 1. Two of the
//      three components of the cross product in t's plane frame are a quadratic system in
//      (λ1, λ2): Newton's method from (1/3, 1/3, 1/3). The projection exists when Newton
//      converges, λ ≥ −tolerance, n(λ) points to t's outer side, and o lies behind q
//      along n (n · (q − o) > 0: o inside M locally, as it is for a penetration).
// Floating-point T only (Newton's method and unit normals need rounding and sqrt).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/cpd/minkowski_patch.hpp"

namespace mink {

template <class T>
struct PhongOptions {
  /// Definition 1's λ ≥ 0, accepted down to −barycentricTolerance (unit: barycentric
  /// coordinate, dimensionless). A point on an edge is the projection of both neighbours.
  T barycentricTolerance = T(defaults::kPhongBarycentricTolerance);
  /// Newton steps per triangle before the triangle is given up.
  int newtonIterations = defaults::kPhongNewtonIterations;
};

/// The Phong projection of o onto one triangle (Definition 1), or why there is none.
template <class T>
struct PhongHit {
  bool found = false;             ///< Definition 1 holds at lambda (within the tolerance)
  bool converged = false;         ///< Newton's method converged (found may still be false)
  std::array<T, 3> lambda{};      ///< barycentric coordinates of q on the triangle
  Vec3<T> point = Vec3<T>::Zero();   ///< q (same frame and unit as the patch)
  Vec3<T> normal = Vec3<T>::Zero();  ///< unit interpolated normal at q, outward
  T residual = T(0);              ///< |n × (q − o)|: distance from o to the normal line at q
  int iterations = 0;             ///< Newton steps taken
};

/// A patch of ∂M with continuous (Phong) normals. build() once per patch; project()
/// per triangle. Reuses its storage between builds. The work is done on the patch moved
/// to its bounding box's centre and scaled by a power of two to unit extent, so that the
/// products of coordinates neither over- nor underflow for a patch at 2^-900 or 2^290;
/// points and residuals in and out are in the patch's frame and unit.
template <class T>
class PhongSurface {
  static_assert(!ScalarTraits<T>::isExact, "PhongSurface: Phong projection needs a floating-point scalar");

 public:
  /// Merge coincident corners and compute the vertex normals of `patch`.
  void build(const MinkowskiPatch<T>& patch) {
    const int nv = static_cast<int>(patch.vertices.size());
    points_.clear();
    order_.resize(static_cast<std::size_t>(nv));
    std::iota(order_.begin(), order_.end(), 0);
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
      const Vec3<T>& p = patch.vertices[static_cast<std::size_t>(a)];
      const Vec3<T>& q = patch.vertices[static_cast<std::size_t>(b)];
      return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
    });
    merged_.resize(static_cast<std::size_t>(nv));
    for (int i = 0; i < nv; ++i) {
      const int v = order_[static_cast<std::size_t>(i)];
      if (i == 0 || patch.vertices[static_cast<std::size_t>(v)] !=
                        patch.vertices[static_cast<std::size_t>(order_[static_cast<std::size_t>(i - 1)])])
        points_.push_back(patch.vertices[static_cast<std::size_t>(v)]);
      merged_[static_cast<std::size_t>(v)] = static_cast<int>(points_.size()) - 1;
    }
    // The unit frame: the bounding box's centre, its extent scaled to [1/2, 1).
    exp_ = 0;
    origin_ = Vec3<T>::Zero();
    if (!points_.empty()) {
      Vec3<T> lo = points_[0], hi = points_[0];
      for (const Vec3<T>& p : points_) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      for (int k = 0; k < 3; ++k) origin_[k] = lo[k] + (hi[k] - lo[k]) / T(2);
      const T extent = (hi - lo).maxCoeff();
      if (extent > T(0) && std::isfinite(extent)) std::frexp(extent, &exp_);
      for (Vec3<T>& p : points_) p = toLocal(p);
    }
    normals_.assign(points_.size(), Vec3<T>::Zero());
    triangles_.clear();
    faceNormals_.clear();
    for (const auto& t : patch.triangles) {
      const std::array<int, 3> m = {merged_[static_cast<std::size_t>(t[0])], merged_[static_cast<std::size_t>(t[1])],
                                    merged_[static_cast<std::size_t>(t[2])]};
      const Vec3<T> n = (point(m[1]) - point(m[0])).cross(point(m[2]) - point(m[0]));
      triangles_.push_back(m);
      faceNormals_.push_back(n);
      for (int k = 0; k < 3; ++k) normals_[static_cast<std::size_t>(m[k])] += n;
    }
    for (std::size_t v = 0; v < normals_.size(); ++v) {
      const T len = normals_[v].stableNorm();
      if (len > T(0) && std::isfinite(len)) normals_[v] /= len;
    }
    // A corner whose incident normals cancel (a needle fan) takes any incident face's.
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        Vec3<T>& n = normals_[static_cast<std::size_t>(triangles_[t][k])];
        if (n.squaredNorm() == T(0)) {
          const T len = faceNormals_[t].stableNorm();
          if (len > T(0)) n = faceNormals_[t] / len;
        }
      }
  }

  int numTriangles() const { return static_cast<int>(triangles_.size()); }
  int numPoints() const { return static_cast<int>(points_.size()); }
  /// Corner k of triangle t (merged coordinates, the patch's frame).
  Vec3<T> corner(int t, int k) const { return toWorld(localCorner(t, k)); }
  /// Unit vertex normal of corner k of triangle t.
  const Vec3<T>& cornerNormal(int t, int k) const {
    return normals_[static_cast<std::size_t>(triangles_[static_cast<std::size_t>(t)][k])];
  }
  /// (v1 − v0) × (v2 − v0) of triangle t in the unit frame: outward (its length is twice
  /// the area in that frame's unit).
  const Vec3<T>& faceNormal(int t) const { return faceNormals_[static_cast<std::size_t>(t)]; }

  /// The unit interpolated normal at barycentric lambda of triangle t (zero where singular).
  Vec3<T> normalAt(int t, const std::array<T, 3>& lambda) const {
    Vec3<T> n = lambda[0] * cornerNormal(t, 0) + lambda[1] * cornerNormal(t, 1) + lambda[2] * cornerNormal(t, 2);
    const T len = n.stableNorm();
    return len > T(0) ? Vec3<T>(n / len) : Vec3<T>::Zero();
  }

  /// The point at barycentric lambda of triangle t (the patch's frame).
  Vec3<T> pointAt(int t, const std::array<T, 3>& lambda) const { return toWorld(localPointAt(t, lambda)); }

  /// Phong projection of o onto triangle t (Definition 1), by Newton's method from the
  /// barycentre (the paper's start) and, if that does not end inside t, from six more
  /// points of t (near its corners and at its edges' midpoints): the system is quadratic,
  /// and a root outside t can attract the barycentre's iteration.
  PhongHit<T> project(int t, const Vec3<T>& o, const PhongOptions<T>& options = {}) const {
    static constexpr T kStarts[7][2] = {{T(1) / T(3), T(1) / T(3)}, {T(0.8), T(0.1)}, {T(0.1), T(0.8)},
                                        {T(0.1), T(0.1)},           {T(0.5), T(0.5)}, {T(0), T(0.5)},
                                        {T(0.5), T(0)}};
    const Vec3<T> oL = toLocal(o);
    PhongHit<T> first;
    int iterations = 0;
    for (int k = 0; k < 7; ++k) {
      PhongHit<T> hit = newton(t, oL, options, kStarts[k][0], kStarts[k][1]);
      iterations += hit.iterations;
      if (hit.found || k == 6) {
        if (!hit.found) hit = first;
        hit.iterations = iterations;
        hit.point = toWorld(hit.point);
        hit.residual = std::ldexp(hit.residual, exp_);
        return hit;
      }
      if (k == 0) first = hit;
    }
    return first;
  }

  /// |n̂ × (c − o)| at the barycentre c of triangle t: how far o is from the normal line
  /// there (the paper's |Ψ · c|, used to relocate the search ball). Infinite when the
  /// normal there is singular or points o's way (o outside, locally).
  T barycentreResidual(int t, const Vec3<T>& o, Vec3<T>* centre = nullptr) const {
    const std::array<T, 3> third = {T(1) / T(3), T(1) / T(3), T(1) / T(3)};
    const Vec3<T> c = localPointAt(t, third);
    if (centre) *centre = toWorld(c);
    const Vec3<T> n = normalAt(t, third);
    const Vec3<T> x = c - toLocal(o);
    if (!(n.dot(x) > T(0))) return std::numeric_limits<T>::infinity();
    return std::ldexp(n.cross(x).stableNorm(), exp_);
  }

 private:
  Vec3<T> toLocal(const Vec3<T>& x) const {
    Vec3<T> y;
    for (int k = 0; k < 3; ++k) y[k] = std::ldexp(x[k] - origin_[k], -exp_);
    return y;
  }
  Vec3<T> toWorld(const Vec3<T>& y) const {
    Vec3<T> x;
    for (int k = 0; k < 3; ++k) x[k] = origin_[k] + std::ldexp(y[k], exp_);
    return x;
  }
  const Vec3<T>& localCorner(int t, int k) const { return point(triangles_[static_cast<std::size_t>(t)][k]); }
  Vec3<T> localPointAt(int t, const std::array<T, 3>& lambda) const {
    return lambda[0] * localCorner(t, 0) + lambda[1] * localCorner(t, 1) + lambda[2] * localCorner(t, 2);
  }

  /// Newton's method for Definition 1 on triangle t from λ = (a, b, 1 − a − b); o and the
  /// result in the unit frame.
  PhongHit<T> newton(int t, const Vec3<T>& o, const PhongOptions<T>& options, T a, T b) const {
    PhongHit<T> hit;
    const Vec3<T>& p3 = localCorner(t, 2);
    const Vec3<T> e1 = localCorner(t, 0) - p3, e2 = localCorner(t, 1) - p3;
    const Vec3<T>& n3 = cornerNormal(t, 2);
    const Vec3<T> d1 = cornerNormal(t, 0) - n3, d2 = cornerNormal(t, 1) - n3;
    const Vec3<T>& N = faceNormal(t);
    const T area2 = N.stableNorm();
    const T l1 = e1.stableNorm();
    if (!(area2 > T(0)) || !(l1 > T(0)) || !std::isfinite(area2)) return hit;
    // (q − o) ∥ n iff F = n × (q − o) = 0. F is normal to n, so its components along two
    // axes u, w of t's plane vanish only if F = 0 — unless n lies in t's plane, which the
    // final n · N > 0 check excludes: two equations in (λ1, λ2).
    const Vec3<T> u = e1 / l1;
    const Vec3<T> w = (N / area2).cross(u);
    const Vec3<T> x0 = p3 - o;
    const T eps = std::numeric_limits<T>::epsilon();
    for (int it = 0; it < options.newtonIterations; ++it) {
      hit.iterations = it + 1;
      const Vec3<T> x = x0 + a * e1 + b * e2;
      const Vec3<T> n = n3 + a * d1 + b * d2;
      const Vec3<T> F = n.cross(x);
      const Vec3<T> Fa = d1.cross(x) + n.cross(e1);
      const Vec3<T> Fb = d2.cross(x) + n.cross(e2);
      const T r0 = u.dot(F), r1 = w.dot(F);
      const T j00 = u.dot(Fa), j01 = u.dot(Fb), j10 = w.dot(Fa), j11 = w.dot(Fb);
      const T det = j00 * j11 - j01 * j10;
      if (!(std::abs(det) > T(0)) || !std::isfinite(det)) break;
      T da = -(r0 * j11 - j01 * r1) / det;
      T db = -(j00 * r1 - r0 * j10) / det;
      // Damped: no step longer than 1 in λ (the roots of interest have λ in [0, 1]), and
      // halved until the residual decreases (plain Newton can cycle on this system).
      const T step = std::max(std::abs(da), std::abs(db));
      if (step > T(1)) {
        da /= step;
        db /= step;
      }
      const T r2 = r0 * r0 + r1 * r1;
      for (int h = 0; h < 20; ++h) {
        const Vec3<T> xn = x0 + (a + da) * e1 + (b + db) * e2;
        const Vec3<T> Fn = (n3 + (a + da) * d1 + (b + db) * d2).cross(xn);
        const T s0 = u.dot(Fn), s1 = w.dot(Fn);
        if (s0 * s0 + s1 * s1 <= r2) break;
        da /= T(2);
        db /= T(2);
      }
      a += da;
      b += db;
      if (!std::isfinite(a) || !std::isfinite(b)) return hit;
      if (step <= T(8) * eps * (T(1) + std::max(std::abs(a), std::abs(b)))) {
        hit.converged = true;
        break;
      }
    }
    hit.lambda = {a, b, T(1) - a - b};
    hit.point = localPointAt(t, hit.lambda);
    hit.normal = normalAt(t, hit.lambda);
    const Vec3<T> x = hit.point - o;
    hit.residual = hit.normal.cross(x).stableNorm();
    // Newton may stop one step short of the rounding floor: accept a residual at the
    // rounding of the point's coordinates, too. And a step that vanished away from a root
    // (damped steps stalled where |F| has a non-zero minimum, as on the degenerate patches
    // of faces in exact contact) is not a root: Definition 1 needs the residual itself
    // small — at the rounding, with sqrt(eps) of the scene's size for ill-conditioned roots.
    const T scale = x.stableNorm() + e1.stableNorm() + e2.stableNorm();
    if (!hit.converged)
      hit.converged = hit.residual <= T(64) * eps * scale;
    else
      hit.converged = hit.residual <= std::sqrt(eps) * scale;
    const T tol = options.barycentricTolerance;
    hit.found = hit.converged && hit.lambda[0] >= -tol && hit.lambda[1] >= -tol && hit.lambda[2] >= -tol &&
                hit.normal.dot(N) > T(0) && hit.normal.dot(x) > T(0);
    return hit;
  }

  const Vec3<T>& point(int v) const { return points_[static_cast<std::size_t>(v)]; }

  std::vector<Vec3<T>> points_;
  std::vector<Vec3<T>> normals_;
  std::vector<Vec3<T>> faceNormals_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<int> order_, merged_;
  Vec3<T> origin_ = Vec3<T>::Zero();  // the unit frame: x_local = (x − origin_) · 2^-exp_
  int exp_ = 0;
};

}  // namespace mink
