// tests/mdd/contact_set_test.cpp — mdd/detail/contact_set.hpp: locating the origin in the
// hull of 2-D points (the facet check's witnesses). Reference: the location's own claim,
// checked independently — non-negative weights summing to 1 whose combination of the
// named points is the origin (to a few ulps of the points' size) — and, for points made
// so that the origin is inside or outside their hull by construction, the yes / no.
#include "mink/mdd/detail/contact_set.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

namespace {

using P2 = std::pair<std::pair<double, double>, int>;

/// |sum w_i p_i| for the location, and whether the weights are a convex combination.
double residual(const std::vector<P2>& pts, const mink::detail::OriginLocation<double>& loc, bool& convex) {
  double x = 0.0, y = 0.0, sum = 0.0;
  convex = loc.count >= 1 && loc.count <= 3;
  for (int i = 0; i < loc.count; ++i) {
    const auto& p = pts.at(static_cast<std::size_t>(loc.id[i])).first;
    x += loc.weight[i] * p.first;
    y += loc.weight[i] * p.second;
    sum += loc.weight[i];
    convex = convex && loc.weight[i] >= -1e-12;
  }
  convex = convex && std::abs(sum - 1.0) <= 1e-12;
  return std::hypot(x, y);
}

/// Locates the origin in the hull of pts (slack as given) and checks the location: found,
/// a convex combination, rebuilding the origin within maxResidual.
void expectLocatedWithin(const std::vector<P2>& pts, double slack, double maxResidual) {
  std::vector<P2> work = pts, hull;
  mink::detail::OriginLocation<double> loc;
  ASSERT_TRUE(mink::detail::locateOrigin2(work, hull, loc, slack));
  bool convex = false;
  EXPECT_LE(residual(pts, loc, convex), maxResidual);
  EXPECT_TRUE(convex) << "weights " << loc.weight[0] << " " << loc.weight[1] << " " << loc.weight[2];
}

// The fuzzer's case (fuzz/regressions/witnesses_collinear_hull_points): a facet of M
// whose 2-D hull kept a point in the middle of the edge that the origin lies on (the
// rounded orientation of the three was positive). The fan triangle of those three is
// degenerate; its weights (0.25, 0.5, 0.25) named a point 1.17 from the origin, and
// mink's witnesses were 1 off parameter * s.
TEST(ContactSet, OriginOnAnEdgeWithACollinearHullPoint) {
  const std::vector<P2> pts = {{{0.89442719099991563, -0.73029674334022165}, 0},
                               {{1.7888543819998315, 0.36514837167011094}, 1},
                               {{3.5777087639996634, -2.9211869733608862}, 2},
                               {{-2.2204460492503131e-16, 1.8257418583505538}, 3},
                               {{0.89442719099991619, 2.9211869733608862}, 4},
                               {{2.6832815729997477, -0.36514837167011105}, 5},
                               {{-1.7888543819998319, 1.4605934866804433}, 6},
                               {{-0.89442719099991563, 2.5560386016907759}, 7},
                               {{0.89442719099991563, -0.73029674334022165}, 8}};
  expectLocatedWithin(pts, 1e-12, 1e-14);
}

// The fuzzer's case (fuzz/regressions/witness_off_motion_huge_penetration_tie): a facet
// of M (a face of P against a face of Q, a 1e57 scene in units of 2^192) whose hull is
// long and thin along the diagonal, the origin 1e-8 inside its edge 9-5. The fan
// triangle holding it (11, 6, 5) is 0.6 long and 1.2e-8 wide: its area cancels to 1e-8
// of its products, and its weights (0.25000000848, ...; exactly 0.25000001066, ...)
// rebuilt a point 1.3e-9 from the origin. Iterative refinement brings it to rounding.
TEST(ContactSet, SliverFanTriangleRebuildsTheOriginToRounding) {
  const std::vector<P2> pts = {{{0.10857843137254901, 0.1031831381367702}, 0},
                               {{0.10857843137254901, 0.10318315037907842}, 1},
                               {{0.10857844361487555, 0.1031831381367702}, 2},
                               {{-0.10857843137254901, -0.11397372429788698}, 3},
                               {{0.10857843137254901, 0.10857843137254901}, 4},
                               {{0.10857843137254901, 0.10857844361485723}, 5},
                               {{0.10857844361487555, 0.10857843137254901}, 6},
                               {{-0.10857843137254901, -0.10857843106210817}, 7},
                               {{-0.10857843137254901, -0.10857843137254901}, 8},
                               {{-0.10857843137254901, -0.1085784191302408}, 9},
                               {{-0.10857841913022245, -0.10857843137254901}, 10},
                               {{-0.32573529411764701, -0.32573529380720617}, 11}};
  expectLocatedWithin(pts, 1e-12, 1e-16);
}

// The fuzzer's case (fuzz/regressions/witness_negative_weights_collinear_fan): a facet
// that is a span of two parallel faces, the origin on its boundary edge, which the 2-D
// hull keeps as three collinear pieces. The fan triangle of the first three is
// degenerate and does not hold the origin; its weights (-1, 2, 0) rebuilt the origin
// exactly, from outside the triangle, and put mink's witness on Q 2 off Q.
TEST(ContactSet, OriginOnAnEdgeSplitIntoCollinearHullPieces) {
  const std::vector<P2> pts = {{{-2.8284271247461898, 1.6329931618554523}, 0},
                               {{0, 1.6329931618554523}, 1},
                               {{-2.1213203435596424, 2.0412414523193152}, 2},
                               {{-1.4142135623730949, 0.81649658092772615}, 3},
                               {{-1.4142135623730949, 2.4494897427831783}, 4},
                               {{1.4142135623730949, 2.4494897427831783}, 5},
                               {{-0.70710678118654746, 2.8577380332470415}, 6},
                               {{0, 1.6329931618554523}, 7},
                               {{-0.70710678118654746, 0.40824829046386307}, 8},
                               {{2.1213203435596424, 0.40824829046386307}, 9},
                               {{0, 0.81649658092772615}, 10},
                               {{0.70710678118654746, -0.40824829046386307}, 11}};
  expectLocatedWithin(pts, 1e-13, 1e-14);
}

// Random convex polygons (points of a circle) with extra points in the middle of their
// edges, and the origin placed on an edge, at a vertex or at the vertices' centroid; and
// the same polygons with the origin outside by a clear margin. Scales 2^-20 .. 2^20.
TEST(ContactSet, RandomPolygonsWithCollinearPoints) {
  const unsigned seed = 601u;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int located = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 3 + trial % 6;
    std::vector<double> ang(n);
    for (double& a : ang) a = 6.283185307179586 * u(rng);
    std::sort(ang.begin(), ang.end());
    const double scale = std::ldexp(1.0, static_cast<int>(trial % 41) - 20);
    // Convex: on a circle, in angular order.
    std::vector<std::pair<double, double>> poly;
    for (double a : ang) poly.push_back({scale * std::cos(a), scale * std::sin(a)});
    // Shift so that the origin is on edge 0 (mode 0), at vertex 0 (1), inside (2) or
    // outside (3).
    const int mode = trial % 4;
    std::pair<double, double> o(0.0, 0.0);
    const auto& a = poly[0];
    const auto& b = poly[1 % n];
    if (mode == 0) o = {a.first + 0.37 * (b.first - a.first), a.second + 0.37 * (b.second - a.second)};
    if (mode == 1) o = a;
    if (mode == 2) {
      for (const auto& p : poly) o = {o.first + p.first / n, o.second + p.second / n};
    }
    if (mode == 3) o = {4 * scale, 4 * scale};
    std::vector<P2> pts;
    int id = 0;
    for (int i = 0; i < n; ++i) {
      const auto& p = poly[i];
      const auto& q = poly[(i + 1) % n];
      pts.push_back({{p.first - o.first, p.second - o.second}, id++});
      // Midpoints of edges: collinear with their ends up to rounding.
      pts.push_back({{0.5 * (p.first + q.first) - o.first, 0.5 * (p.second + q.second) - o.second}, id++});
    }
    std::vector<P2> work = pts, hull;
    mink::detail::OriginLocation<double> loc;
    const double slack = 64 * 2.220446049250313e-16 * scale;
    const bool ok = mink::detail::locateOrigin2(work, hull, loc, slack);
    if (mode == 3) {
      EXPECT_FALSE(ok) << "seed " << seed << " trial " << trial;
      continue;
    }
    // Inside or on the boundary by construction (up to the rounding of the shift).
    ASSERT_TRUE(ok) << "seed " << seed << " trial " << trial << " mode " << mode;
    bool convex = false;
    // Within the slack of mink's facet checks (256 eps of the scene).
    EXPECT_LE(residual(pts, loc, convex), 256 * 2.220446049250313e-16 * scale)
        << "seed " << seed << " trial " << trial << " mode " << mode;
    EXPECT_TRUE(convex) << "seed " << seed << " trial " << trial;
    ++located;
  }
  EXPECT_GT(located, 2000);
}

// preferNonNegative (inexact T, after a location with a negative weight): the weights
// 0.5 - 5e-8, 0.5 + 1.5e-8, -1e-7 of a sliver triangle rebuild the origin to rounding
// (the third point is 1e-20 off the line of the other two), as the fuzzer's
// vertex_contact_sliver_fan_weights did; they are replaced by the non-negative pair.
TEST(ContactSet, PreferNonNegativeReplacesSliverWeights) {
  const std::vector<P2> pts = {{{-1.0, 0.0}, 0}, {{1.0, 0.0}, 1}, {{2.0, 1e-20}, 2}, {{0.0, 3.0}, 3}};
  mink::detail::OriginLocation<double> loc;
  loc.count = 3;
  loc.id[0] = 0, loc.id[1] = 1, loc.id[2] = 2;
  loc.weight[0] = 0.5 - 0.5e-7, loc.weight[1] = 0.5 + 1.5e-7, loc.weight[2] = -1e-7;
  bool convex = true;
  ASSERT_LE(residual(pts, loc, convex), 1e-15);
  ASSERT_FALSE(convex);
  mink::detail::preferNonNegative(pts, loc);
  EXPECT_LE(residual(pts, loc, convex), 1e-15);
  EXPECT_TRUE(convex) << "weights " << loc.weight[0] << " " << loc.weight[1] << " " << loc.weight[2];
  EXPECT_EQ(loc.count, 2);
}

// ... and kept when no non-negative combination rebuilds the origin as well (the origin
// outside the points' hull: weights 2, -1 rebuild it exactly), when the set is too large
// to search (more than 32 points), and when the weights are already non-negative.
TEST(ContactSet, PreferNonNegativeKeepsWhatItCannotImprove) {
  auto same = [](const mink::detail::OriginLocation<double>& a, const mink::detail::OriginLocation<double>& b) {
    if (a.count != b.count) return false;
    for (int i = 0; i < a.count; ++i)
      if (a.id[i] != b.id[i] || a.weight[i] != b.weight[i]) return false;
    return true;
  };
  mink::detail::OriginLocation<double> outside;
  outside.count = 2;
  outside.id[0] = 0, outside.id[1] = 1;
  outside.weight[0] = 2.0, outside.weight[1] = -1.0;
  const std::vector<P2> far = {{{1.0, 0.0}, 0}, {{2.0, 0.0}, 1}, {{1.0, 1.0}, 2}};
  mink::detail::OriginLocation<double> loc = outside;
  mink::detail::preferNonNegative(far, loc);
  EXPECT_TRUE(same(loc, outside));

  std::vector<P2> many = {{{-1.0, 0.0}, 0}, {{1.0, 0.0}, 1}, {{2.0, 1e-20}, 2}};
  for (int i = 3; i < 33; ++i) many.push_back({{std::cos(i), 3.0 + std::sin(i)}, i});
  mink::detail::OriginLocation<double> sliver;
  sliver.count = 3;
  sliver.id[0] = 0, sliver.id[1] = 1, sliver.id[2] = 2;
  sliver.weight[0] = 0.5 - 0.5e-7, sliver.weight[1] = 0.5 + 1.5e-7, sliver.weight[2] = -1e-7;
  loc = sliver;
  mink::detail::preferNonNegative(many, loc);
  EXPECT_TRUE(same(loc, sliver));
  many.pop_back();  // 32 points: searched
  mink::detail::preferNonNegative(many, loc);
  bool convex = false;
  EXPECT_LE(residual(many, loc, convex), 1e-15);
  EXPECT_TRUE(convex);

  mink::detail::OriginLocation<double> fine;
  fine.count = 3;
  fine.id[0] = 0, fine.id[1] = 1, fine.id[2] = 3;
  fine.weight[0] = 0.5, fine.weight[1] = 0.5, fine.weight[2] = 0.0;
  loc = fine;
  mink::detail::preferNonNegative(many, loc);
  EXPECT_TRUE(same(loc, fine));
}

// toFaceOrder: a support set that is one face of the shape (an n-gon prism's cap) comes
// back in the face's own cyclic order; sets that are not a face (an edge, a vertex) or
// are small stay as supportSet left them.
TEST(ContactSet, SupportSetsThatAreOneFaceTakeItsCyclicOrder) {
  const double pi = 3.14159265358979323846;
  for (int n : {8, 16, 64, 300}) {
    std::vector<mink::Vec3<double>> pts;
    for (int i = 0; i < n; ++i)
      for (double z : {0.0, 1.0}) pts.push_back({std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), z});
    const auto X = mink::ConvexPolyhedron<double>::fromPoints(pts);
    mink::detail::EpochMarks marks;
    std::vector<int> set;
    for (const mink::Vec3<double>& d : {mink::Vec3<double>(0, 0, 1), mink::Vec3<double>(0, 0, -1)}) {
      auto value = [&](int v) { return d.dot(X.vertex(v)); };
      const int v0 = X.support(d);
      ASSERT_TRUE(mink::detail::supportSet(X, v0, value, 0.0, marks, set));
      ASSERT_EQ(int(set.size()), n);
      const std::vector<int> bfs = set;
      const bool ordered = mink::detail::toFaceOrder(X, value, 0.0, set);
      EXPECT_EQ(ordered, n >= mink::defaults::kConvexCycleMinPoints) << "n " << n;
      if (!ordered) {
        EXPECT_EQ(set, bfs);
        continue;
      }
      std::vector<int> a = set, b = bfs;
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      EXPECT_EQ(a, b) << "the same vertices";
      // Consecutive vertices of the set are joined by edges of X (a cycle).
      for (int i = 0; i < n; ++i) {
        const auto nb = X.vertexNeighbors(set[i]);
        EXPECT_TRUE(std::find(nb.begin(), nb.end(), set[(i + 1) % n]) != nb.end()) << "n " << n << " i " << i;
      }
    }
    // A side edge's direction: a set of two vertices, never reordered.
    const mink::Vec3<double> d(std::cos(2 * pi * 0.5 / n), std::sin(2 * pi * 0.5 / n), 0);
    auto value = [&](int v) { return d.dot(X.vertex(v)); };
    ASSERT_TRUE(mink::detail::supportSet(X, X.support(d), value, 1e-12, marks, set));
    EXPECT_EQ(set.size(), 4u);  // the side face of the prism between vertices 0 and 1 (a rectangle)
    EXPECT_FALSE(mink::detail::toFaceOrder(X, value, 1e-12, set));
  }
}

// locateOrigin2 on many points in cyclic order around a convex polygon (no sort: its
// own hull) answers as on the same points shuffled (sorted and hulled): inside, on an
// edge, at a vertex, outside by an ulp-sized margin and by a clear one.
TEST(ContactSet, PointsInCyclicOrderLocateAsShuffled) {
  std::mt19937 rng(602u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 16 + trial % 40;
    std::vector<double> ang(n);
    for (double& a : ang) a = 6.283185307179586 * u(rng);
    std::sort(ang.begin(), ang.end());
    const double scale = std::ldexp(1.0, trial % 21 - 10);
    std::vector<std::pair<double, double>> poly;
    for (double a : ang) poly.push_back({scale * std::cos(a), scale * std::sin(a)});
    const int mode = trial % 4;
    std::pair<double, double> o(0.0, 0.0);
    if (mode == 0) o = {0.5 * (poly[0].first + poly[1].first), 0.5 * (poly[0].second + poly[1].second)};
    if (mode == 1) o = poly[0];
    if (mode == 2) o = {0.1 * scale, -0.2 * scale};
    if (mode == 3) o = {3 * scale, 0.0};
    std::vector<P2> pts;
    for (int i = 0; i < n; ++i) pts.push_back({{poly[i].first - o.first, poly[i].second - o.second}, i});
    const std::vector<P2> byId = pts;  // ids are indices here
    if (trial % 2) std::reverse(pts.begin(), pts.end());  // clockwise as well
    std::vector<P2> inOrder = pts, shuffled = pts, hull;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    mink::detail::OriginLocation<double> a, b;
    const bool hitA = mink::detail::locateOrigin2(inOrder, hull, a);
    const bool hitB = mink::detail::locateOrigin2(shuffled, hull, b);
    EXPECT_EQ(hitA, hitB) << "trial " << trial << " mode " << mode;
    if (mode == 3) {
      EXPECT_FALSE(hitA) << "trial " << trial;
    }
    if (mode == 2) {
      EXPECT_TRUE(hitA) << "trial " << trial;
    }
    if (hitA) {
      bool convex = false;
      EXPECT_LE(residual(byId, a, convex), 64 * 2.220446049250313e-16 * scale) << "trial " << trial;
      EXPECT_TRUE(convex) << "trial " << trial;
    }
  }
}

}  // namespace
