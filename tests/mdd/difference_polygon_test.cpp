// tests/mdd/difference_polygon_test.cpp — mdd/detail/difference_polygon.hpp: the vertices of
// conv(A) ⊕ −conv(B) from the two hulls' merge. Reference: CGAL's exact convex hull
// (convex_hull_2 on a kernel over CGAL::Gmpq) of all |A|·|B| differences, in exact rationals — the
// pairs named must be exactly its vertices, once each, in counter-clockwise order.
#include "mink/mdd/detail/difference_polygon.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

using K = CGAL::Simple_cartesian<CGAL::Gmpq>;  // exact: every operation in rationals
using Point = K::Point_2;

/// Checks D.pairs against the exact hull of all differences a_i − b_j. `label` names the case.
template <class T>
void expectHullVertices(const mink::detail::DifferencePolygon<T>& D, const std::string& label) {
  SCOPED_TRACE(label);
  auto diff = [&](int i, int j) {
    return Point(K::FT(double(D.a[i].first)) - K::FT(double(D.b[j].first)),
                 K::FT(double(D.a[i].second)) - K::FT(double(D.b[j].second)));
  };
  std::vector<Point> all, hull;
  for (std::size_t i = 0; i < D.a.size(); ++i)
    for (std::size_t j = 0; j < D.b.size(); ++j) all.push_back(diff(int(i), int(j)));
  CGAL::convex_hull_2(all.begin(), all.end(), std::back_inserter(hull));  // CCW, no collinear points
  std::vector<Point> got;
  for (const auto& ij : D.pairs) got.push_back(diff(ij.first, ij.second));
  ASSERT_EQ(got.size(), hull.size());
  if (hull.size() == 1) {
    EXPECT_EQ(got[0], hull[0]);
    return;
  }
  // The same cyclic sequence: find hull[0] in got, then walk both.
  std::size_t start = got.size();
  for (std::size_t k = 0; k < got.size(); ++k)
    if (got[k] == hull[0]) start = k;
  ASSERT_LT(start, got.size());
  for (std::size_t k = 0; k < hull.size(); ++k) EXPECT_EQ(got[(start + k) % got.size()], hull[k]) << "vertex " << k;
}

TEST(DifferencePolygon, RandomIntegerSetsMatchTheExactHullOfAllDifferences) {
  std::mt19937 rng(16);
  for (int trial = 0; trial < 3000; ++trial) {
    mink::detail::DifferencePolygon<double> D;
    const int m = 1 + int(rng() % 9), n = 1 + int(rng() % 9);
    // Small grids: collinear points, duplicates and parallel edges everywhere.
    std::uniform_int_distribution<int> u(-3, 3);
    for (int i = 0; i < m; ++i) D.a.push_back({double(u(rng)), double(u(rng))});
    for (int j = 0; j < n; ++j) D.b.push_back({double(u(rng)), double(u(rng))});
    D.compute();
    expectHullVertices(D, "trial " + std::to_string(trial));
  }
}

TEST(DifferencePolygon, RegularPolygonsAndDegenerateSets) {
  const double pi = 3.14159265358979323846;
  for (int m : {1, 2, 3, 7, 64, 257}) {
    for (int n : {1, 2, 4, 64, 256}) {
      mink::detail::DifferencePolygon<double> D;
      for (int i = 0; i < m; ++i) D.a.push_back({2 * std::cos(2 * pi * i / m), 2 * std::sin(2 * pi * i / m)});
      for (int j = 0; j < n; ++j) D.b.push_back({std::cos(2 * pi * j / n + 0.1), std::sin(2 * pi * j / n + 0.1)});
      D.compute();
      EXPECT_LE(D.pairs.size(), std::size_t(m + n));
      expectHullVertices(D, "m " + std::to_string(m) + " n " + std::to_string(n));
    }
  }
  // Collinear sets (segments), and a segment against a point set on one line.
  mink::detail::DifferencePolygon<double> D;
  D.a = {{0, 0}, {1, 1}, {3, 3}, {2, 2}};
  D.b = {{0, 1}, {0, -2}, {0, 0}};
  D.compute();
  expectHullVertices(D, "two segments");
  D.b = {{5, 5}, {-1, -1}};
  D.compute();
  expectHullVertices(D, "collinear segments");
}

TEST(DifferencePolygon, ExactRationals) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 200; ++trial) {
    mink::detail::DifferencePolygon<CGAL::Gmpq> D;
    std::uniform_int_distribution<int> u(-20, 20);
    const int m = 1 + int(rng() % 12), n = 1 + int(rng() % 12);
    for (int i = 0; i < m; ++i) D.a.push_back({CGAL::Gmpq(u(rng), 7), CGAL::Gmpq(u(rng), 3)});
    for (int j = 0; j < n; ++j) D.b.push_back({CGAL::Gmpq(u(rng), 5), CGAL::Gmpq(u(rng), 11)});
    D.compute();
    // The reference converts through double: these rationals are not doubles, so compare
    // in exact arithmetic directly here.
    std::vector<Point> all, hull;
    auto diff = [&](int i, int j) {
      return Point(K::FT(D.a[i].first - D.b[j].first), K::FT(D.a[i].second - D.b[j].second));
    };
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < n; ++j) all.push_back(diff(i, j));
    CGAL::convex_hull_2(all.begin(), all.end(), std::back_inserter(hull));
    ASSERT_EQ(D.pairs.size(), hull.size()) << "trial " << trial;
    std::set<std::pair<double, double>> want, got;
    for (const auto& p : hull) want.insert({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
    for (const auto& ij : D.pairs) {
      const Point p = diff(ij.first, ij.second);
      got.insert({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
    }
    EXPECT_EQ(got, want) << "trial " << trial;
  }
}

// convexCycleOrientation: +1 / -1 exactly for strictly convex polygons in cyclic order
// (any scale), 0 for a straight or reversed turn and for stars (every turn one way, but
// winding round more than once) — the cases where a hull of the points is not the points.
TEST(ConvexCycleOrientation, StrictlyConvexCyclesOnlyAtAnyScale) {
  using P = std::pair<double, double>;
  auto orientationOf = [](const std::vector<P>& v) {
    return mink::detail::convexCycleOrientation<double>(v.size(), [&](std::size_t k) { return v[k]; });
  };
  const double pi = 3.14159265358979323846;
  for (double scale : {1e-150, 1.0, 1e150}) {
    for (int n : {3, 4, 16, 33, 1024}) {
      std::vector<P> v;
      for (int i = 0; i < n; ++i) v.push_back({scale * std::cos(2 * pi * i / n + 0.3), scale * (2 + std::sin(2 * pi * i / n + 0.3))});
      EXPECT_EQ(orientationOf(v), 1) << "n " << n << " scale " << scale;
      std::reverse(v.begin(), v.end());
      EXPECT_EQ(orientationOf(v), -1) << "n " << n << " scale " << scale;
      if (n >= 16) {
        std::swap(v[3], v[7]);  // out of order
        EXPECT_EQ(orientationOf(v), 0) << "n " << n << " scale " << scale;
      }
    }
    // Stars {21/2}, {21/4}: every turn to the left, winding twice and four times.
    for (int k : {2, 4}) {
      std::vector<P> v;
      for (int i = 0; i < 21; ++i) v.push_back({scale * std::cos(2 * pi * (i * k % 21) / 21), scale * std::sin(2 * pi * (i * k % 21) / 21)});
      EXPECT_EQ(orientationOf(v), 0) << "star k " << k << " scale " << scale;
    }
  }
  // Points of the parabola y = x^2 (exact integers), closed by the chord above them.
  std::vector<P> v;
  for (int x = -10; x <= 10; ++x) v.push_back({double(x), double(x * x)});
  EXPECT_EQ(orientationOf(v), 1);
  v[10] = {0.0, 1.0};  // collinear with (-1, 1) and (1, 1): a straight turn
  EXPECT_EQ(orientationOf(v), 0);
  v[10] = {0.0, 1.5};  // a reflex vertex
  EXPECT_EQ(orientationOf(v), 0);
  v[10] = {0.0, 1.0 - std::ldexp(1.0, -52)};  // convex again, by one unit in the last place
  EXPECT_EQ(orientationOf(v), 1);
  EXPECT_EQ(orientationOf(std::vector<P>{{0, 0}, {1, 0}}), 0);
  EXPECT_EQ(orientationOf(std::vector<P>{{0, 0}, {1, 0}, {1, 0}, {0, 1}}), 0);  // a repeated point
}

// Sets in a face's cyclic order (the O(n) hull) and the same sets shuffled (sorted for a
// hull) give the exact hull of all differences; so do ordered sets the check refuses
// (a collinear point, a reflex vertex, a star order), which fall back to the sort.
TEST(DifferencePolygon, OrderedSetsTakeTheLinearHullAndMatchTheExactHull) {
  const double pi = 3.14159265358979323846;
  std::mt19937 rng(18);
  for (int m : {16, 17, 64, 300}) {
    for (int n : {16, 31, 256}) {
      mink::detail::DifferencePolygon<double> D;
      for (int i = 0; i < m; ++i) D.a.push_back({3 * std::cos(2 * pi * i / m + 0.2), 3 * std::sin(2 * pi * i / m + 0.2)});
      for (int j = n; j-- > 0;) D.b.push_back({std::cos(2 * pi * j / n), 0.5 * std::sin(2 * pi * j / n)});  // clockwise
      D.compute();
      expectHullVertices(D, "ordered m " + std::to_string(m) + " n " + std::to_string(n));
      std::set<std::pair<double, double>> ordered, shuffled;
      for (const auto& ij : D.pairs) ordered.insert({D.a[ij.first].first - D.b[ij.second].first, D.a[ij.first].second - D.b[ij.second].second});
      std::shuffle(D.a.begin(), D.a.end(), rng);
      std::shuffle(D.b.begin(), D.b.end(), rng);
      D.compute();
      expectHullVertices(D, "shuffled m " + std::to_string(m) + " n " + std::to_string(n));
      for (const auto& ij : D.pairs) shuffled.insert({D.a[ij.first].first - D.b[ij.second].first, D.a[ij.first].second - D.b[ij.second].second});
      EXPECT_EQ(ordered, shuffled);
    }
  }
  // Exact integer polygons of 21 points on a parabola, in order, then spoiled.
  mink::detail::DifferencePolygon<double> D;
  for (int x = -10; x <= 10; ++x) D.a.push_back({double(x), double(x * x)});
  for (int j = 0; j < 20; ++j) D.b.push_back({double(j % 5), double(j / 5)});  // a grid: no cyclic order
  D.compute();
  expectHullVertices(D, "parabola against a grid");
  D.a[10] = {0.0, 1.0};
  D.compute();
  expectHullVertices(D, "parabola with a collinear point");
  D.a[10] = {0.0, 1.5};
  D.compute();
  expectHullVertices(D, "parabola with a reflex vertex");
  D.a.clear();
  for (int i = 0; i < 21; ++i) D.a.push_back({std::cos(2 * pi * (i * 2 % 21) / 21), std::sin(2 * pi * (i * 2 % 21) / 21)});
  D.compute();
  expectHullVertices(D, "star order");
}

// Two polygons whose edges are pairwise parallel to within 2^-45 .. 2^-56 rad (B is A
// turned by that angle, scaled by 1 + 1e-3 x and negated): the rounded cross products of
// the edges' rounded differences misordered them, and the pairs named points inside the
// sum (8 of its 10 vertices in the first case, 12 of 14 in the third). Found by a random
// search against the exact hull; every order is now decided exactly.
TEST(DifferencePolygon, NearlyParallelEdgesAreOrderedExactly) {
  struct Case {
    std::vector<std::pair<double, double>> a, b;
  };
  const std::vector<Case> cases = {
      {{{0.71008699643859774, 0.8139818586302896}, {0.49615018777923614, 1.2198923666172017},
        {-0.42980481798984849, 0.79327208738280375}, {0.064510119140480021, 0.20746959552405664},
        {0.24990302990036944, 0.21290696901954365}},
       {{0.25630569808833481, 0.077806915986677994}, {0.47034387706430392, -0.32829592578779865},
        {1.3967376308575703, 0.098526500206888801}, {0.90218847100514599, 0.68460656460886149},
        {0.71670771496898888, 0.67916661470646167}}},
      {{{-0.59730745593130141, 1.3361933710476341}, {-0.63830182124884638, 1.2940836040856367},
        {-0.9111918625943769, 0.7119850856360519}, {-0.58226391896901353, -0.20810204751296801},
        {-0.44813060505553437, -0.31467887936083971}, {1.2110497813493235, 0.50295286421350827}},
       {{0.88426278094970523, -0.63737105415951278}, {0.9252667081711663, -0.59525146512703087},
        {1.1982204009071937, -0.013017172649479103}, {0.86921573509408834, 0.90728457010975072},
        {0.73505113468916927, 1.0138862609209924}, {-0.92451625425399775, 0.19606380537659096}}},
      {{{0.82630224730811319, 1.2963927253551666}, {0.64369626925427259, 1.4077091062642797},
        {0.56462829955936666, 1.4367811409226721}, {-0.28760768697918826, 1.1430565301854616},
        {-0.32993842238503446, 1.0751478499926099}, {0.22270102423157151, -0.052256207331750515},
        {0.59855609713894142, -0.016465092244500212}},
       {{-0.36097966152293282, -0.86421932807547397}, {-0.17837063649941032, -0.9755375664135788},
        {-0.099301347473620183, -1.0046100861689498}, {0.75294885950415869, -0.71088057433269913},
        {0.79528030124212368, -0.6429707610132549}, {0.24263163326454787, 0.48445210821430029},
        {-0.13322971117360194, 0.44866039591526252}}},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    mink::detail::DifferencePolygon<double> D;
    D.a = cases[k].a;
    D.b = cases[k].b;
    D.compute();
    expectHullVertices(D, "near-parallel case " + std::to_string(k));
  }
}

}  // namespace
