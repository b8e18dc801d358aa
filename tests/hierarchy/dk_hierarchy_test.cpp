// Tests of mink/hierarchy/dk_hierarchy.hpp: DKHierarchy<T>::support, the hill-climbing
// ConvexPolyhedron<T>::support (cold from vertex 0 and from random hints), hierarchyOf
// and extremeVertex, on spheres and 2:2:5 ellipsoids of 4 .. 100k vertices, a box with
// coplanar / collinear extra points, a cone whose apex has degree m, and a cylinder with
// points on its rulings and caps; in float, double, long double and CGAL::Gmpq.
//
// Reference: an independent scan of all vertices, in double for float and double shapes,
// in long double for long double ones, and in exact rationals for CGAL::Gmpq.
// Exact shapes: the returned vertex's d.x equals the maximum exactly, and DK makes at most
// one move per level (the lemma of the header; for exact T the query has no final climb,
// so these tests check the hierarchy alone). Inexact shapes: the returned vertex has
//     d.x >= max - kSlack * (tolerance + eps * extent) * |d|,
// the tolerance being the shape's own hull tolerance (merging faces within it is what
// makes a local maximum of a rounded hull only approximately global), eps the unit
// roundoff of T (queries compare d.x computed in T) and kSlack = 4. The worst observed
// deficit / ((tolerance + eps * extent) |d|) is printed per case as "slack": 0 for every
// double and long double case, <= 0.011 for float.
//
// Depth and size: numLevels <= kLevelsPerDoubling * log2(n) + kLevelsOffset with 2.2 and
// 1, totalSize <= kSizeFactor * n with 4.5. Measured (printed per case): each round keeps
// ~72% of a level, i.e. 1 / log2(1 / 0.72) = 2.1 levels per doubling asymptotically;
// (levels - 1) / log2(n) = 1.75 at n = 100k; totalSize / n <= 3.8 on every case.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "mink/hierarchy/dk_hierarchy.hpp"
#include "support/bumpy_cube.hpp"

namespace mink {
namespace {

using Gmpq = CGAL::Gmpq;

// Under -fsanitize=address,undefined (GCC defines __SANITIZE_ADDRESS__; a build may also
// define MINK_SANITIZE_BUILD) the 100k-vertex and the larger exact cases take minutes:
// they shrink there (the same code paths run, on smaller shapes).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MINK_DK_TEST_SANITIZED 1
#endif
#endif
#if defined(MINK_SANITIZE_BUILD) || defined(__SANITIZE_ADDRESS__)
#define MINK_DK_TEST_SANITIZED 1
#endif
#ifdef MINK_DK_TEST_SANITIZED
constexpr int kLargeN = 20000;       // float / double sphere and ellipsoid
constexpr int kRoundM = 2000;        // circle points of the float / double cone and cylinder
constexpr int kExactLargeN = 500;    // CGAL::Gmpq
constexpr int kExactLargeDirs = 60;  // directions for the largest Gmpq cases
constexpr bool kSanitized = true;
#else
constexpr int kLargeN = 100000;
constexpr int kRoundM = 5000;
constexpr int kExactLargeN = 1000;
constexpr int kExactLargeDirs = 150;
constexpr bool kSanitized = false;
#endif

constexpr double kSlack = 4.0;
constexpr double kLevelsPerDoubling = 2.2;
constexpr double kLevelsOffset = 1.0;
constexpr double kSizeFactor = 4.5;
// Largest level whose exact convexity checkStructure verifies (O(V^2) orient3d calls).
constexpr int kConvexityCheckSize = kSanitized ? 200 : 600;
constexpr int kExactConvexityCheckSize = kSanitized ? 60 : 150;

template <class T>
constexpr bool isExact() {
  return ScalarTraits<T>::isExact;
}

// ---------------------------------------------------------------------------------------
// Point sets. Inexact T: computed in double, converted. Exact T: rational points exactly
// on the sphere / circle (stereographic parametrisation), so every point is a vertex.

template <class T>
Vec3<T> vec(double x, double y, double z) {
  return Vec3<T>(T(x), T(y), T(z));
}

/// Rational point of the unit sphere: inverse stereographic projection of (a, b)/64,
/// z mirrored when `flip`. Exact in T for exact T.
template <class T>
Vec3<T> rationalSpherePoint(int a, int b, bool flip) {
  const T den = T(4096 + a * a + b * b);
  const T z = T(a * a + b * b - 4096) / den;
  return Vec3<T>(T(128 * a) / den, T(128 * b) / den, flip ? T(-z) : z);
}

std::int64_t gcd64(std::int64_t a, std::int64_t b) {
  a = a < 0 ? -a : a;
  b = b < 0 ? -b : b;
  while (b != 0) {
    const std::int64_t t = a % b;
    a = b;
    b = t;
  }
  return a;
}

/// n distinct points on the ellipsoid with semi-axes `axes` (random-on-sphere, scaled).
template <class T>
std::vector<Vec3<T>> ellipsoidPoints(int n, const std::array<double, 3>& axes, std::mt19937& rng) {
  std::vector<Vec3<T>> pts;
  pts.reserve(n);
  if constexpr (isExact<T>()) {
    std::uniform_int_distribution<int> coord(-128, 128), coin(0, 1);
    std::set<std::array<std::int64_t, 4>> seen;  // reduced (X, Y, Z, D): unique per point
    while (static_cast<int>(pts.size()) < n) {
      const int a = coord(rng), b = coord(rng);
      const bool flip = coin(rng) == 1;
      std::int64_t X = 128 * a, Y = 128 * b, Z = a * a + b * b - 4096, D = 4096 + a * a + b * b;
      if (flip) Z = -Z;
      const std::int64_t g = gcd64(gcd64(X, Y), gcd64(Z, D));
      if (!seen.insert({X / g, Y / g, Z / g, D / g}).second) continue;
      const Vec3<T> p = rationalSpherePoint<T>(a, b, flip);
      pts.emplace_back(p[0] * T(axes[0]), p[1] * T(axes[1]), p[2] * T(axes[2]));
    }
  } else {
    std::normal_distribution<double> g;
    while (static_cast<int>(pts.size()) < n) {
      const double x = g(rng), y = g(rng), z = g(rng);
      const double r = std::sqrt(x * x + y * y + z * z);
      if (r == 0.0) continue;
      pts.push_back(vec<T>(axes[0] * x / r, axes[1] * y / r, axes[2] * z / r));
    }
  }
  return pts;
}

/// Point k of m around the unit circle (angle 2 pi k / m), exactly on it for exact T:
/// (1 - t^2, 2t) / (1 + t^2) with t a dyadic rational near tan(angle / 2), mirrored
/// through the origin for the half circle where |angle| > pi / 2.
template <class T>
std::pair<T, T> circlePoint(int k, int m) {
  const double pi = std::acos(-1.0);
  double angle = 2.0 * pi * k / m;
  if constexpr (isExact<T>()) {
    bool mirror = false;
    if (angle > pi / 2 && angle <= 3 * pi / 2) {
      angle -= pi;
      mirror = true;
    } else if (angle > 3 * pi / 2) {
      angle -= 2 * pi;
    }
    const T t = T(static_cast<int>(std::lround(std::tan(angle / 2) * (1 << 20)))) / T(1 << 20);
    const T den = T(1) + t * t;
    T c = (T(1) - t * t) / den, s = T(2) * t / den;
    if (mirror) {
      c = -c;
      s = -s;
    }
    return {c, s};
  } else {
    return {T(std::cos(angle)), T(std::sin(angle))};
  }
}

/// Box [-1,1] x [-2,2] x [-3,3] with extra points on its faces (coplanar) and edges
/// (collinear): 8 vertices.
template <class T>
std::vector<Vec3<T>> boxPoints(std::mt19937& rng) {
  std::vector<Vec3<T>> pts;
  const double h[3] = {1, 2, 3};
  for (int s = 0; s < 8; ++s) pts.push_back(vec<T>(s & 1 ? h[0] : -h[0], s & 2 ? h[1] : -h[1], s & 4 ? h[2] : -h[2]));
  std::uniform_int_distribution<int> eighth(-7, 7), axis(0, 2), coin(0, 1);
  for (int i = 0; i < 300; ++i) {
    const int k = axis(rng);
    double p[3];
    for (int j = 0; j < 3; ++j) p[j] = h[j] * eighth(rng) / 8.0;
    p[k] = coin(rng) ? h[k] : -h[k];  // on a face
    if (i % 3 == 0) {
      const int k2 = (k + 1) % 3;  // on an edge
      p[k2] = coin(rng) ? h[k2] : -h[k2];
    }
    pts.push_back(vec<T>(p[0], p[1], p[2]));
  }
  return pts;
}

/// Cone: apex (0, 0, 3) over m points of the unit circle at z = 0; the apex has degree m.
template <class T>
std::vector<Vec3<T>> conePoints(int m) {
  std::vector<Vec3<T>> pts;
  pts.push_back(vec<T>(0, 0, 3));
  for (int k = 0; k < m; ++k) {
    const auto cs = circlePoint<T>(k, m);
    pts.emplace_back(cs.first, cs.second, T(0));
  }
  return pts;
}

/// Cylinder: m points on each of the circles z = -1, z = 1, plus points on the rulings
/// between them (collinear with two vertices) and inside the caps (coplanar): 2m vertices.
template <class T>
std::vector<Vec3<T>> cylinderPoints(int m, std::mt19937& rng) {
  std::vector<Vec3<T>> pts;
  std::vector<std::pair<T, T>> circle;
  for (int k = 0; k < m; ++k) circle.push_back(circlePoint<T>(k, m));
  for (const auto& cs : circle) {
    pts.emplace_back(cs.first, cs.second, T(-1));
    pts.emplace_back(cs.first, cs.second, T(1));
  }
  std::uniform_int_distribution<int> pick(0, m - 1), level(-15, 15), coin(0, 1);
  for (int i = 0; i < m; ++i) {
    const auto& cs = circle[pick(rng)];
    pts.emplace_back(cs.first, cs.second, T(level(rng)) / T(16));  // on a ruling
    const T r = T(level(rng) + 16) / T(33);                          // inside a cap
    pts.emplace_back(r * cs.first, r * cs.second, T(coin(rng) ? 1 : -1));
  }
  return pts;
}

// ---------------------------------------------------------------------------------------
// Directions and the reference scan.

template <class T>
std::vector<Vec3<T>> directions(int count, std::mt19937& rng) {
  std::vector<Vec3<T>> dirs;
  // Ties on purpose: axes and diagonals (whole faces or edges of the box are extreme).
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) dirs.push_back(vec<T>(i, j, k));  // includes d = 0
  if constexpr (isExact<T>()) {
    std::uniform_int_distribution<int> c(-1000, 1000);
    while (static_cast<int>(dirs.size()) < count) dirs.push_back(vec<T>(c(rng), c(rng), c(rng)));
  } else {
    std::normal_distribution<double> g;
    while (static_cast<int>(dirs.size()) < count) dirs.push_back(vec<T>(g(rng), g(rng), g(rng)));
  }
  return dirs;
}

/// Scalar of the reference scan: T itself when exact; double for float (products of
/// floats are exact in double) and double; long double for long double. Its rounding,
/// at most 3 * 2^-53 * |d| * |x| per value, is covered by the eps * extent term.
template <class T>
using RefScalar = std::conditional_t<isExact<T>(), T, std::conditional_t<std::is_same<T, long double>::value, long double, double>>;

template <class T>
RefScalar<T> refDot(const Vec3<T>& d, const Vec3<T>& x) {
  using R = RefScalar<T>;
  return R(d[0]) * R(x[0]) + R(d[1]) * R(x[1]) + R(d[2]) * R(x[2]);
}

/// The shape's vertices in the reference scalar, coordinate by coordinate, for a fast scan.
template <class T>
struct ReferenceScan {
  using R = RefScalar<T>;
  std::vector<R> x, y, z;
  explicit ReferenceScan(const ConvexPolyhedron<T>& P) {
    for (const Vec3<T>& p : P.vertices()) {
      x.push_back(R(p[0]));
      y.push_back(R(p[1]));
      z.push_back(R(p[2]));
    }
  }
  R max(const Vec3<T>& d) const {
    const R a = R(d[0]), b = R(d[1]), c = R(d[2]);
    // Four running maxima (max is exact, so the order does not matter): the 100k-vertex
    // cases scan 10^9 vertices in total.
    R best[4];
    for (int k = 0; k < 4; ++k) best[k] = a * x[0] + b * y[0] + c * z[0];
    const std::size_t n = x.size();
    std::size_t v = 0;
    for (; v + 4 <= n; v += 4) {
      for (int k = 0; k < 4; ++k) {
        const R s = a * x[v + k] + b * y[v + k] + c * z[v + k];
        if (best[k] < s) best[k] = s;
      }
    }
    for (; v < n; ++v) {
      const R s = a * x[v] + b * y[v] + c * z[v];
      if (best[0] < s) best[0] = s;
    }
    for (int k = 1; k < 4; ++k)
      if (best[0] < best[k]) best[0] = best[k];
    return best[0];
  }
};

/// Checks one returned vertex against the maximum; accumulates failures and the worst
/// slack ratio (deficit / allowed) for the report.
template <class T>
struct Checker {
  using R = RefScalar<T>;
  Checker(const ConvexPolyhedron<T>& shape, std::string name) : P(shape), what(std::move(name)) {}

  const ConvexPolyhedron<T>& P;
  std::string what;
  int failures = 0;
  std::string firstFailure;
  double worstRatio = 0.0;

  /// Allowed deficit for direction d (0 for exact T).
  R allowed(const Vec3<T>& d) const {
    if constexpr (isExact<T>()) {
      return R(0);
    } else {
      const R eps = R(ScalarTraits<T>::epsilon());
      using std::sqrt;
      return R(kSlack) * (R(P.tolerance()) + eps * R(P.extent())) * sqrt(refDot(d, d));
    }
  }

  void check(const char* method, int k, const Vec3<T>& d, int v, const R& max) {
    bool ok = v >= 0 && v < P.numVertices();
    R value = R(0);
    if (ok) {
      value = refDot(d, P.vertex(v));
      if constexpr (isExact<T>()) {
        ok = value == max;
      } else {
        const R deficit = max - value, tol = allowed(d);
        if (tol > 0) worstRatio = std::max(worstRatio, static_cast<double>(deficit / (tol / kSlack)));
        ok = deficit <= tol;
      }
    }
    if (!ok && failures++ == 0) {
      std::ostringstream os;
      os << what << ": " << method << " direction #" << k << " (" << d.transpose() << ") returned vertex " << v;
      if (v >= 0 && v < P.numVertices()) os << " with d.x = " << value;
      os << ", maximum " << max;
      firstFailure = os.str();
    }
  }
};

/// Structural invariants of every level above L0, against the definition of the
/// construction: same points as the shape, consistent maps, strictly shrinking levels,
/// an independent removed set of vertices of degree <= maxRemovedDegree (every level is
/// L(i) minus that set: no kept point is dropped), and each level the exact hull of its
/// points, triangulated.
template <class T>
void checkStructure(const ConvexPolyhedron<T>& P, const DKHierarchy<T>& H, const DKHierarchyOptions& opt,
                    const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_GE(H.numLevels(), 1);
  ASSERT_EQ(H.levelSize(0), P.numVertices());
  std::size_t total = 0;
  for (int i = 0; i < H.numLevels(); ++i) total += static_cast<std::size_t>(H.levelSize(i));
  EXPECT_EQ(H.totalSize(), total);
  for (int i = 1; i < H.numLevels(); ++i) {
    ASSERT_LT(H.levelSize(i), H.levelSize(i - 1)) << "level " << i;
    std::vector<char> hit(H.levelSize(i - 1), 0);
    for (int w = 0; w < H.levelSize(i); ++w) {
      const int b = H.belowIndex(i, w);
      ASSERT_TRUE(b >= 0 && b < H.levelSize(i - 1)) << "level " << i << " vertex " << w;
      ASSERT_FALSE(hit[b]) << "level " << i << ": two vertices map to " << b;
      hit[b] = 1;
      ASSERT_EQ(H.originalIndex(i, w), H.originalIndex(i - 1, b));
      ASSERT_TRUE(H.levelPoint(i, w) == P.vertex(H.originalIndex(i, w))) << "level " << i << " vertex " << w;
      ASSERT_GE(H.levelNeighbors(i, w).size(), 3);
    }
    {
      for (int r = 0; r < H.levelSize(i - 1); ++r) {
        if (hit[r]) continue;
        EXPECT_LE(H.levelNeighbors(i - 1, r).size(), opt.maxRemovedDegree) << "level " << i - 1 << " vertex " << r;
        for (int u : H.levelNeighbors(i - 1, r))
          EXPECT_TRUE(hit[u]) << "level " << i - 1 << ": removed vertices " << r << " and " << u << " are adjacent";
      }
    }
  }
  // Every shape here comes from fromPoints (an exact hull), so no level is re-hulled and
  // every level is a triangulation of the exact hull of its points: 3V - 6 edges, and each
  // triangle (v, neighbour j, neighbour j+1) has every point of the level on or below its
  // plane and one strictly below (exact orient3d). O(V^2) per level: levels up to
  // kConvexityCheckSize points (exact T: kExactConvexityCheckSize) are checked.
  EXPECT_EQ(H.rehulledLevels(), 0);
  const int cap = isExact<T>() ? kExactConvexityCheckSize : kConvexityCheckSize;
  for (int i = 0; i < H.numLevels(); ++i) {
    const int V = H.levelSize(i);
    if (V > cap || V < 4) continue;
    long long degreeSum = 0;
    int bad = 0;
    for (int v = 0; v < V; ++v) {
      const IndexRange nb = H.levelNeighbors(i, v);
      degreeSum += nb.size();
      for (int j = 0; j < nb.size(); ++j) {
        const int a = nb[j], b = nb[(j + 1) % nb.size()];
        if (a < v || b < v) continue;  // each triangle once, from its lowest corner
        bool below = false;
        for (int q = 0; q < V; ++q) {
          const int o = orient3d(H.levelPoint(i, v), H.levelPoint(i, a), H.levelPoint(i, b), H.levelPoint(i, q));
          if (o > 0 && bad++ == 0)
            ADD_FAILURE() << "level " << i << ": point " << q << " above triangle (" << v << ", " << a << ", " << b << ")";
          below |= o < 0;
        }
        if (!below && bad++ == 0) ADD_FAILURE() << "level " << i << ": flat triangle (" << v << ", " << a << ", " << b << ")";
      }
    }
    EXPECT_EQ(degreeSum, 6LL * V - 12) << "level " << i << ": not a triangulated sphere";
  }
}

struct CaseReport {
  std::string name;
  int n = 0, levels = 0;
  std::size_t total = 0;
  double worstRatio = 0.0, avgMoves = 0.0, avgEvaluations = 0.0;
  std::array<double, 3> seconds{};  // hull, hierarchy, queries
};

/// Builds the shape and its hierarchy once and checks DK, hill-climbing from 0 and from
/// random hints, and extremeVertex against the reference on `numDirs` directions.
template <class T>
CaseReport checkCase(const std::string& name, const std::vector<Vec3<T>>& points, int numDirs,
                     unsigned seed, const DKHierarchyOptions& opt = {}) {
  SCOPED_TRACE(name + " seed " + std::to_string(seed));
  CaseReport report;
  report.name = name;
  const auto t0 = std::chrono::steady_clock::now();
  const ConvexPolyhedron<T> P = ConvexPolyhedron<T>::fromPoints(points);
  const auto t1 = std::chrono::steady_clock::now();
  // With default options a shape above the threshold uses the lazily built hierarchy
  // (the one extremeVertex uses too), so that large shapes are built once.
  const bool defaultOptions = opt.maxRemovedDegree == defaults::kHierarchyMaxRemovedDegree &&
                              opt.topVertices == defaults::kHierarchyTopVertices;
  const DKHierarchy<T>* lazy = defaultOptions ? hierarchyOf(P) : nullptr;
  std::unique_ptr<DKHierarchy<T>> own;
  if (lazy == nullptr) own = std::make_unique<DKHierarchy<T>>(P, opt);
  const DKHierarchy<T>& H = lazy ? *lazy : *own;
  const auto t2 = std::chrono::steady_clock::now();
  const int n = P.numVertices();
  report.n = n;
  report.levels = H.numLevels();
  report.total = H.totalSize();
  checkStructure(P, H, opt, name);

  // Depth and size: the constants are stated at the top of the file.
  EXPECT_LE(H.numLevels(), kLevelsPerDoubling * std::log2(static_cast<double>(n)) + kLevelsOffset)
      << name << ": n = " << n;
  EXPECT_LE(static_cast<double>(H.totalSize()), kSizeFactor * n) << name;
  EXPECT_NE(H.stopReason(), DKBuildStop::HullFailed) << name;
  if (H.stopReason() == DKBuildStop::ReachedTop) {
    EXPECT_LE(H.levelSize(H.numLevels() - 1), opt.topVertices) << name;
  }
  if (opt.maxRemovedDegree >= 6) {
    // A round removes nothing only if every vertex of degree <= D is an anchor. With m
    // vertices the degree sum is <= 6m - 12, so more than 4 have degree <= D as soon as
    // m > (4D - 8) / (D - 5): above that size the build cannot stop short of the top.
    const int D = opt.maxRemovedDegree;
    EXPECT_LE(H.levelSize(H.numLevels() - 1), std::max(opt.topVertices, (4 * D - 8) / (D - 5))) << name;
  }

  std::mt19937 rng(seed);
  const std::vector<Vec3<T>> dirs = directions<T>(numDirs, rng);
  std::uniform_int_distribution<int> hintDist(0, n - 1);
  const ReferenceScan<T> scan(P);
  Checker<T> dk{P, name}, climb0{P, name}, climbHint{P, name}, extreme{P, name}, from{P, name};
  long long moves = 0, evaluations = 0;
  int excessMoves = 0;
  for (int k = 0; k < static_cast<int>(dirs.size()); ++k) {
    const Vec3<T>& d = dirs[k];
    const auto max = scan.max(d);
    DKSupportStats stats;
    dk.check("DKHierarchy::support", k, d, H.support(d, stats), max);
    moves += stats.moves;
    evaluations += stats.evaluations;
    // The header's lemma: in exact arithmetic at most one move per level below the top.
    if (isExact<T>() && stats.moves > H.numLevels() - 1) ++excessMoves;
    climb0.check("support(d, 0)", k, d, P.support(d, 0), max);
    climbHint.check("support(d, hint)", k, d, P.support(d, hintDist(rng)), max);
    extreme.check("extremeVertex", k, d, extremeVertex(P, d), max);
    // Warm-started: the climb alone (large cap), cut short and finished by the descent
    // (caps 0 and 2 from a random vertex), from the last direction's answer, and from a
    // hint out of range (the descent).
    from.check("supportFrom(d, hint, 1 << 30)", k, d, H.supportFrom(d, hintDist(rng), 1 << 30), max);
    from.check("supportFrom(d, hint, 0)", k, d, H.supportFrom(d, hintDist(rng), 0), max);
    from.check("supportFrom(d, hint, -1)", k, d, H.supportFrom(d, hintDist(rng), -1), max);
    from.check("supportFrom(d, hint, 2)", k, d, H.supportFrom(d, hintDist(rng), 2), max);
    from.check("supportFrom(d, previous answer, 8)", k, d,
               H.supportFrom(d, k > 0 ? H.support(dirs[k - 1]) : 0, 8), max);
    from.check("supportFrom(d, -1, 8)", k, d, H.supportFrom(d, -1, 8), max);
    from.check("supportFrom(d, n, 8)", k, d, H.supportFrom(d, n, 8), max);
  }
  for (const Checker<T>* c : {&dk, &climb0, &climbHint, &extreme, &from}) {
    EXPECT_EQ(c->failures, 0) << c->firstFailure;
    report.worstRatio = std::max(report.worstRatio, c->worstRatio);
  }
  EXPECT_EQ(excessMoves, 0) << name << ": queries with more than one move per level";
  const auto t3 = std::chrono::steady_clock::now();
  report.seconds = {std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count(),
                    std::chrono::duration<double>(t3 - t2).count()};
  report.avgMoves = static_cast<double>(moves) / dirs.size();
  report.avgEvaluations = static_cast<double>(evaluations) / dirs.size();
  return report;
}

void print(const CaseReport& r) {
  std::printf(
      "  %-34s n=%7d levels=%3d (%.2f per doubling) total/n=%.2f moves=%.2f evals=%.1f slack=%.3g "
      "[hull %.2fs, hierarchy %.2fs, queries %.2fs]\n",
      r.name.c_str(), r.n, r.levels, r.n > 1 ? (r.levels - 1) / std::log2(static_cast<double>(r.n)) : 0.0,
      r.n ? static_cast<double>(r.total) / r.n : 0.0, r.avgMoves, r.avgEvaluations, r.worstRatio, r.seconds[0],
      r.seconds[1], r.seconds[2]);
}

/// checkCase, turning an exception (a shape the hull builder rejects) into a failure of
/// this case alone so that the other cases still run.
template <class T>
void runCase(std::vector<CaseReport>& reports, const std::string& name, const std::vector<Vec3<T>>& points,
             int numDirs, unsigned seed) {
  try {
    reports.push_back(checkCase<T>(name, points, numDirs, seed));
  } catch (const std::exception& e) {
    ADD_FAILURE() << name << " (seed " << seed << "): threw " << e.what();
  }
}

template <class T>
void runFamilies(const char* typeName, const std::vector<int>& sizes, int numDirs, int largeDirs, int coneM,
                 int cylinderM, unsigned seed) {
  std::mt19937 rng(seed);
  const std::array<double, 3> sphere{1, 1, 1}, ellipsoid{2, 2, 5};
  const std::string type(typeName);
  std::vector<CaseReport> reports;
  for (int n : sizes) {
    const int dirs = n >= 500 ? largeDirs : numDirs;
    runCase<T>(reports, type + " sphere " + std::to_string(n), ellipsoidPoints<T>(n, sphere, rng), dirs, seed + n);
    runCase<T>(reports, type + " ellipsoid 2:2:5 " + std::to_string(n), ellipsoidPoints<T>(n, ellipsoid, rng), dirs,
               seed + 2 * n);
  }
  runCase<T>(reports, type + " box + coplanar points", boxPoints<T>(rng), numDirs, seed + 3);
  runCase<T>(reports, type + " cone apex degree " + std::to_string(coneM), conePoints<T>(coneM), largeDirs, seed + 4);
  runCase<T>(reports, type + " cylinder 2x" + std::to_string(cylinderM), cylinderPoints<T>(cylinderM, rng), largeDirs,
             seed + 5);
  for (const CaseReport& r : reports) print(r);
}

// ---------------------------------------------------------------------------------------

TEST(DKHierarchy, DoubleAgreesWithBruteForce) {
  runFamilies<double>("double", {4, 8, 100, 1000, 10000, kLargeN}, 10000, 10000, kRoundM, kRoundM, 1001u);
}

TEST(DKHierarchy, FloatAgreesWithBruteForce) {
  runFamilies<float>("float", {4, 8, 100, 1000, 10000, kLargeN}, 10000, 10000, kRoundM, kRoundM, 2002u);
}

TEST(DKHierarchy, LongDoubleAgreesWithBruteForce) {
  runFamilies<long double>("long double", {4, 100, 1000}, 10000, 10000, 1000, 500, 3003u);
}

TEST(DKHierarchy, ExactGmpqEqualsMaximum) {
  // Exact: the returned vertex's d.x equals the maximum, and the header's lemma (at most
  // one move per level) holds on every query.
  runFamilies<Gmpq>("Gmpq", {4, 8, 100, kExactLargeN}, kSanitized ? 200 : 500, kExactLargeDirs,
                    kSanitized ? 300 : 600, kSanitized ? 200 : 400, 4004u);
  if (!kSanitized) {
    std::mt19937 rng(4005u);
    print(checkCase<Gmpq>("Gmpq ellipsoid 2:2:5 2000", ellipsoidPoints<Gmpq>(2000, {2, 2, 5}, rng), 60, 4006u));
  }
}

TEST(DKHierarchy, ExactGmpqOtherParameters) {
  std::mt19937 rng(5005u);
  const std::vector<Vec3<Gmpq>> pts = ellipsoidPoints<Gmpq>(300, {2, 2, 5}, rng);
  for (const auto& [deg, top] : std::vector<std::pair<int, int>>{{3, 4}, {6, 4}, {12, 64}, {8, 300}}) {
    DKHierarchyOptions opt;
    opt.maxRemovedDegree = deg;
    opt.topVertices = top;
    print(checkCase<Gmpq>("Gmpq ellipsoid 300 D=" + std::to_string(deg) + " top=" + std::to_string(top), pts,
                          kSanitized ? 60 : 150, 5006u + deg, opt));
  }
}

TEST(DKHierarchy, ShapeConvexOnlyWithinToleranceIsReHulled) {
  // Holes there can lack an ear with every ring point on or below it (a grid point lifted
  // by a rounding): such a level is re-hulled, and the queries stay right within the
  // shape's tolerance. An exact hull of the same points needs no re-hull.
  int rehulled = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto mesh = mink_test::bumpyCube(12, 1e-14, seed);
    const ConvexPolyhedron<double> P = ConvexPolyhedron<double>::fromMesh(mesh.first, mesh.second);
    ASSERT_FALSE(P.isExactHull());
    ASSERT_EQ(P.numVertices(), 866);
    DKHierarchyOptions opt;
    opt.topVertices = 4;
    const DKHierarchy<double> H(P, opt);
    rehulled += H.rehulledLevels();
    EXPECT_NE(H.stopReason(), DKBuildStop::HullFailed);
    std::mt19937 rng(seed);
    const std::vector<Vec3<double>> dirs = directions<double>(3000, rng);
    const ReferenceScan<double> scan(P);
    Checker<double> dk{P, "bumpy cube"};
    for (int k = 0; k < static_cast<int>(dirs.size()); ++k) dk.check("DKHierarchy::support", k, dirs[k], H.support(dirs[k]), scan.max(dirs[k]));
    EXPECT_EQ(dk.failures, 0) << dk.firstFailure;

    const ConvexPolyhedron<double> hull = ConvexPolyhedron<double>::fromPoints(mesh.first);
    EXPECT_EQ(DKHierarchy<double>(hull, opt).rehulledLevels(), 0);
  }
  EXPECT_GT(rehulled, 0) << "no seed exercised the re-hull";
}

TEST(DKHierarchy, RejectsBadOptions) {
  std::mt19937 rng(6006u);
  const auto P = ConvexPolyhedron<double>::fromPoints(ellipsoidPoints<double>(50, {1, 1, 1}, rng));
  DKHierarchyOptions deg;
  deg.maxRemovedDegree = 2;
  EXPECT_THROW(DKHierarchy<double>(P, deg), InvalidInput);
  DKHierarchyOptions top;
  top.topVertices = 3;
  EXPECT_THROW(DKHierarchy<double>(P, top), InvalidInput);
}

TEST(DKHierarchy, DoesNotReferToTheShapeAfterConstruction) {
  std::mt19937 rng(7007u);
  auto shape = std::make_unique<ConvexPolyhedron<double>>(
      ConvexPolyhedron<double>::fromPoints(ellipsoidPoints<double>(3000, {2, 2, 5}, rng)));
  const DKHierarchy<double> H(*shape);
  const std::vector<Vec3<double>> verts = shape->vertices();
  shape.reset();  // under ASan a dangling reference would be reported here
  std::normal_distribution<double> g;
  for (int k = 0; k < 1000; ++k) {
    const Vec3<double> d(g(rng), g(rng), g(rng));
    double best = -1e300;
    for (const auto& x : verts) best = std::max(best, d.dot(x));
    EXPECT_GE(d.dot(verts[H.support(d)]), best - 1e-12 * d.norm()) << "direction " << k;
  }
}

// ---------------------------------------------------------------------------------------
// Lazy per-shape build.

ConvexPolyhedron<double> sphereShape(int n, unsigned seed) {
  std::mt19937 rng(seed);
  return ConvexPolyhedron<double>::fromPoints(ellipsoidPoints<double>(n, {1, 1, 1}, rng));
}

TEST(DKHierarchyLazy, ThresholdAndSharing) {
  const int nMin = defaults::kHierarchyMinVertices;
  const auto small = sphereShape(nMin - 1, 8008u);
  const auto big = sphereShape(nMin, 8009u);
  // Points on a sphere are in convex position: every input point is a vertex.
  ASSERT_EQ(small.numVertices(), nMin - 1);
  ASSERT_EQ(big.numVertices(), nMin);

  EXPECT_EQ(hierarchyOf(small), nullptr);
  const ConvexPolyhedron<double> copyBefore = big;  // copied before the first build
  const DKHierarchy<double>* h1 = hierarchyOf(big);
  ASSERT_NE(h1, nullptr);
  EXPECT_EQ(hierarchyOf(big), h1);
  EXPECT_EQ(hierarchyOf(copyBefore), h1);
  const ConvexPolyhedron<double> copyAfter = big;
  EXPECT_EQ(hierarchyOf(copyAfter), h1);
  EXPECT_EQ(h1->levelSize(0), nMin);

  // A different shape of the same size gets its own hierarchy.
  const auto other = sphereShape(nMin, 8010u);
  const DKHierarchy<double>* h2 = hierarchyOf(other);
  ASSERT_NE(h2, nullptr);
  EXPECT_NE(h2, h1);

  // extremeVertex: all three paths against a scan.
  std::mt19937 rng(8011u);
  std::normal_distribution<double> g;
  std::uniform_int_distribution<int> hint(0, nMin - 2);
  for (int k = 0; k < 2000; ++k) {
    const Vec3<double> d(g(rng), g(rng), g(rng));
    for (const ConvexPolyhedron<double>* P : {&small, &big}) {
      double best = -1e300;
      for (const auto& x : P->vertices()) best = std::max(best, d.dot(x));
      const double slack = kSlack * (P->tolerance() + 1e-15 * P->extent()) * d.norm();
      EXPECT_GE(d.dot(P->vertex(extremeVertex(*P, d))), best - slack) << "direction " << k;
      EXPECT_GE(d.dot(P->vertex(extremeVertex(*P, d, hint(rng)))), best - slack) << "direction " << k;
    }
  }
}

TEST(DKHierarchyLazy, ConcurrentFirstCallsBuildOnce) {
  const int n = kSanitized ? 5000 : 20000;
  for (unsigned round = 0; round < 3; ++round) {
    const auto P = sphereShape(n, 9009u + round);
    const ConvexPolyhedron<double> copy = P;
    constexpr int kThreads = 4;
    std::atomic<bool> go{false};
    std::atomic<int> ready{0};
    std::vector<const DKHierarchy<double>*> got(kThreads, nullptr);
    std::vector<int> answers(kThreads, -1);
    const Vec3<double> d(0.3, -0.5, 0.8);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([&, t] {
        ++ready;
        while (!go.load()) std::this_thread::yield();
        // Half the threads go through a copy: copies share the slot.
        got[t] = hierarchyOf(t % 2 ? copy : P);
        answers[t] = got[t]->support(d);
      });
    }
    while (ready.load() < kThreads) std::this_thread::yield();
    go = true;
    for (auto& th : threads) th.join();
    int best = 0;
    for (int v = 1; v < P.numVertices(); ++v)
      if (d.dot(P.vertex(v)) > d.dot(P.vertex(best))) best = v;
    for (int t = 0; t < kThreads; ++t) {
      SCOPED_TRACE("round " + std::to_string(round) + " thread " + std::to_string(t));
      ASSERT_NE(got[t], nullptr);
      EXPECT_EQ(got[t], got[0]);
      const double slack = kSlack * (P.tolerance() + 1e-15 * P.extent()) * d.norm();
      EXPECT_GE(d.dot(P.vertex(answers[t])), d.dot(P.vertex(best)) - slack);
    }
    EXPECT_EQ(hierarchyOf(P), got[0]);
  }
}

}  // namespace
}  // namespace mink
