// Tests of mink/mesh/triangle_intersection.hpp against CGAL::do_intersect and
// CGAL::intersection with an exact kernel (Simple_cartesian<Gmpq>) on the same numbers:
// random triangle pairs, integer-grid pairs (full of touching), coplanar overlapping and
// touching pairs, a shared corner, a shared edge, edges crossing edges, corners on edges,
// and corners one ulp off the other triangle's plane. Segment contacts are checked
// against the exact intersection's shape (a point inside both, or anything else).
#include "mink/mesh/triangle_intersection.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "support/to_rational.hpp"

namespace {

using Q = CGAL::Gmpq;
using K = CGAL::Simple_cartesian<Q>;
template <class T>
using V = mink::Vec3<T>;

using mink_test::toQ;
template <class T>
K::Point_3 P(const V<T>& p) {
  return K::Point_3(toQ(p[0]), toQ(p[1]), toQ(p[2]));
}
template <class T>
std::string str(const V<T>& p) {
  std::ostringstream os;
  os.precision(20);
  os << "(" << CGAL::to_double(toQ(p[0])) << ", " << CGAL::to_double(toQ(p[1])) << ", " << CGAL::to_double(toQ(p[2]))
     << ")";
  return os.str();
}

template <class T>
using Tri = std::array<V<T>, 3>;

template <class T>
bool degenerate(const Tri<T>& t) {
  return CGAL::collinear(P(t[0]), P(t[1]), P(t[2]));
}

struct Tally {
  int failures = 0, hits = 0, misses = 0;
};

// mink against CGAL on one pair, both orders and a cyclic shift of the corners.
template <class T>
void check(const Tri<T>& a, const Tri<T>& b, const std::string& what, Tally& tally) {
  if (degenerate(a) || degenerate(b)) return;
  const bool want = CGAL::do_intersect(K::Triangle_3(P(a[0]), P(a[1]), P(a[2])), K::Triangle_3(P(b[0]), P(b[1]), P(b[2])));
  const bool got = mink::trianglesIntersect(a[0], a[1], a[2], b[0], b[1], b[2]);
  const bool swapped = mink::trianglesIntersect(b[0], b[1], b[2], a[0], a[1], a[2]);
  const bool shifted = mink::trianglesIntersect(a[1], a[2], a[0], b[2], b[0], b[1]);
  const bool flipped = mink::trianglesIntersect(a[0], a[2], a[1], b[0], b[1], b[2]);
  (want ? tally.hits : tally.misses)++;
  if ((got != want || swapped != want || shifted != want || flipped != want) && tally.failures++ < 8)
    ADD_FAILURE() << what << ": mink " << got << swapped << shifted << flipped << ", CGAL " << want << "\n  T1 "
                  << str(a[0]) << " " << str(a[1]) << " " << str(a[2]) << "\n  T2 " << str(b[0]) << " " << str(b[1])
                  << " " << str(b[2]);
}

// segmentTriangleContact against the exact intersection: Crossing iff it is one point,
// interior to the triangle and to the segment, with the segment not in the plane.
template <class T>
void checkSegment(const V<T>& s, const V<T>& e, const Tri<T>& t, const std::string& what, Tally& tally) {
  if (degenerate(t) || s == e) return;
  const K::Triangle_3 tri(P(t[0]), P(t[1]), P(t[2]));
  const K::Segment_3 seg(P(s), P(e));
  const auto x = CGAL::intersection(seg, tri);
  mink::SegmentContact want = mink::SegmentContact::None;
  if (x) {
    want = mink::SegmentContact::Touching;
    if (const K::Point_3* p = boost::get<K::Point_3>(&*x)) {
      bool interior = *p != seg.source() && *p != seg.target() && !tri.supporting_plane().has_on(seg.source()) &&
                      !tri.supporting_plane().has_on(seg.target());
      for (int i = 0; i < 3 && interior; ++i)
        interior = !K::Segment_3(tri.vertex(i), tri.vertex(i + 1)).has_on(*p);
      if (interior) want = mink::SegmentContact::Crossing;
    }
  }
  const mink::SegmentContact got = mink::segmentTriangleContact(s, e, t[0], t[1], t[2]);
  const mink::SegmentContact reversed = mink::segmentTriangleContact(e, s, t[1], t[2], t[0]);
  (want != mink::SegmentContact::None ? tally.hits : tally.misses)++;
  if ((got != want || reversed != want || mink::segmentIntersectsTriangle(s, e, t[0], t[1], t[2]) != bool(x)) &&
      tally.failures++ < 8)
    ADD_FAILURE() << what << ": mink " << static_cast<int>(got) << "/" << static_cast<int>(reversed) << ", exact "
                  << static_cast<int>(want) << "\n  segment " << str(s) << " " << str(e) << "\n  triangle " << str(t[0])
                  << " " << str(t[1]) << " " << str(t[2]);
}

template <class T>
V<T> rnd(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return V<T>(T(u(rng)), T(u(rng)), T(u(rng)));
}

template <class T>
class TriangleIntersection : public ::testing::Test {};
using Scalars = ::testing::Types<float, double, long double, Q>;
TYPED_TEST_SUITE(TriangleIntersection, Scalars);

TYPED_TEST(TriangleIntersection, RandomPairs) {
  using T = TypeParam;
  std::mt19937 rng(6101u);
  Tally tally;
  const int n = std::is_same<T, Q>::value ? 2000 : 20000;
  for (int i = 0; i < n; ++i) {
    const Tri<T> a = {rnd<T>(rng, -1, 1), rnd<T>(rng, -1, 1), rnd<T>(rng, -1, 1)};
    const Tri<T> b = {rnd<T>(rng, -1, 1), rnd<T>(rng, -1, 1), rnd<T>(rng, -1, 1)};
    check(a, b, "seed 6101 #" + std::to_string(i), tally);
    checkSegment(b[0], b[1], a, "seed 6101 segment #" + std::to_string(i), tally);
  }
  EXPECT_EQ(tally.failures, 0);
  EXPECT_GT(tally.hits, n / 10);
  EXPECT_GT(tally.misses, n / 10);
}

// Corners on a small integer grid: shared corners, corners on edges, coplanar overlaps,
// edges through edges, all the time.
TYPED_TEST(TriangleIntersection, IntegerGridPairs) {
  using T = TypeParam;
  std::mt19937 rng(6102u);
  std::uniform_int_distribution<int> g(-2, 2);
  auto pt = [&] { return V<T>(T(g(rng)), T(g(rng)), T(g(rng))); };
  Tally tally;
  const int n = std::is_same<T, Q>::value ? 3000 : 30000;
  for (int i = 0; i < n; ++i) {
    const Tri<T> a = {pt(), pt(), pt()}, b = {pt(), pt(), pt()};
    check(a, b, "seed 6102 #" + std::to_string(i), tally);
    checkSegment(b[0], b[1], a, "seed 6102 segment #" + std::to_string(i), tally);
  }
  EXPECT_EQ(tally.failures, 0);
}

// Both triangles in one plane (z = x + 2y, integers: exactly coplanar), overlapping,
// touching at a corner or along an edge, or apart.
TYPED_TEST(TriangleIntersection, CoplanarPairs) {
  using T = TypeParam;
  std::mt19937 rng(6103u);
  std::uniform_int_distribution<int> g(-3, 3);
  auto pt = [&] {
    const int x = g(rng), y = g(rng);
    return V<T>(T(x), T(y), T(x + 2 * y));
  };
  Tally tally;
  for (int i = 0; i < 5000; ++i) {
    const Tri<T> a = {pt(), pt(), pt()}, b = {pt(), pt(), pt()};
    check(a, b, "seed 6103 #" + std::to_string(i), tally);
    // Reflected through a corner of a: touching at that corner only.
    const Tri<T> r = {a[0], V<T>(a[0] * T(2) - a[1]), V<T>(a[0] * T(2) - a[2])};
    check(a, r, "seed 6103 corner #" + std::to_string(i), tally);
    // Reflected through the midpoint of an edge: sharing that edge, on its other side.
    const Tri<T> e = {a[1], a[0], V<T>(a[0] + a[1] - a[2])};
    check(a, e, "seed 6103 edge #" + std::to_string(i), tally);
    checkSegment(b[0], b[1], a, "seed 6103 segment #" + std::to_string(i), tally);
  }
  EXPECT_EQ(tally.failures, 0);
  EXPECT_GT(tally.hits, 1000);
  EXPECT_GT(tally.misses, 1000);
}

// Hand-made configurations with known answers, each also checked against CGAL.
TYPED_TEST(TriangleIntersection, DegenerateConfigurations) {
  using T = TypeParam;
  const Tri<T> base = {V<T>(T(0), T(0), T(0)), V<T>(T(4), T(0), T(0)), V<T>(T(0), T(4), T(0))};
  auto expectAnswer = [&](const Tri<T>& b, bool want, const std::string& what) {
    Tally tally;
    check(base, b, what, tally);
    EXPECT_EQ(tally.failures, 0);
    EXPECT_EQ(mink::trianglesIntersect(base[0], base[1], base[2], b[0], b[1], b[2]), want) << what;
  };
  // A shared corner only, the other triangle standing up or lying in the plane outside.
  expectAnswer({V<T>(T(0), T(0), T(0)), V<T>(T(-1), T(-1), T(3)), V<T>(T(-2), T(1), T(1))}, true, "shared corner");
  expectAnswer({V<T>(T(0), T(0), T(0)), V<T>(T(-1), T(0), T(0)), V<T>(T(0), T(-1), T(0))}, true, "corner, coplanar");
  // A corner of b on the edge of a (exactly: (2, 0, 0)), b standing up.
  expectAnswer({V<T>(T(2), T(0), T(0)), V<T>(T(2), T(-3), T(1)), V<T>(T(3), T(-3), T(-1))}, true, "corner on edge");
  // An edge of b crossing an edge of a at (1, 0, 0), b otherwise below the plane... b
  // pierces the line of a's edge from outside: it touches a only there.
  expectAnswer({V<T>(T(1), T(-1), T(-1)), V<T>(T(1), T(1), T(1)), V<T>(T(1), T(-3), T(5))}, true, "edge on edge");
  // The same, moved by 1/8 in -y: apart.
  expectAnswer({V<T>(T(1), T(-1.125), T(-1)), V<T>(T(1), T(0.875), T(1)), V<T>(T(1), T(-3.125), T(5))}, false,
               "edge past edge");
  // Coplanar, overlapping; coplanar, touching along part of an edge; coplanar, apart.
  expectAnswer({V<T>(T(1), T(1), T(0)), V<T>(T(5), T(1), T(0)), V<T>(T(1), T(5), T(0))}, true, "coplanar overlap");
  expectAnswer({V<T>(T(1), T(0), T(0)), V<T>(T(3), T(0), T(0)), V<T>(T(2), T(-2), T(0))}, true, "coplanar edge touch");
  expectAnswer({V<T>(T(3), T(3), T(0)), V<T>(T(5), T(3), T(0)), V<T>(T(3), T(5), T(0))}, false, "coplanar apart");
  // b's corner right on a's face, b otherwise above; then one ulp above the face.
  const T one = T(1);
  T up = one;
  if constexpr (!std::is_same<T, Q>::value) {
    up = std::nextafter(one, T(2));
  } else {
    up = Q(1) + Q(1, 1 << 30) / Q(1 << 22);
  }
  expectAnswer({V<T>(one, one, T(0)), V<T>(T(2), one, T(1)), V<T>(one, T(2), T(1))}, true, "corner on face");
  expectAnswer({V<T>(one, one, T(up - one)), V<T>(T(2), one, T(1)), V<T>(one, T(2), T(1))}, false, "corner 1 ulp above");
  // Two triangles on one plane z = 0 whose edges at y = 1 are one ulp apart.
  T below = T(1);
  if constexpr (!std::is_same<T, Q>::value) {
    below = std::nextafter(T(1), T(0));
  } else {
    below = Q(1) - Q(1, 1 << 30) / Q(1 << 22);
  }
  const Tri<T> upper = {V<T>(T(0), T(1), T(0)), V<T>(T(4), T(1), T(0)), V<T>(T(0), T(5), T(0))};
  const Tri<T> lower = {V<T>(T(0), below, T(0)), V<T>(T(4), below, T(0)), V<T>(T(2), T(-3), T(0))};
  Tally tally;
  check(upper, lower, "1 ulp apart, coplanar", tally);
  EXPECT_EQ(tally.failures, 0);
  EXPECT_FALSE(mink::trianglesIntersect(upper[0], upper[1], upper[2], lower[0], lower[1], lower[2]));
  const Tri<T> touching = {V<T>(T(0), T(1), T(0)), V<T>(T(4), T(1), T(0)), V<T>(T(2), T(-3), T(0))};
  EXPECT_TRUE(mink::trianglesIntersect(upper[0], upper[1], upper[2], touching[0], touching[1], touching[2]));
}

// A corner of T2 nudged by -3..3 ulps in z around a point of T1's face (inclined plane,
// so the plane test needs the exact stage).
TEST(TriangleIntersectionExact, UlpPerturbationsAroundAFace) {
  const Tri<double> a = {V<double>(0.1, 0.2, 0.3), V<double>(2.3, 0.7, 1.9), V<double>(0.4, 3.1, -0.7)};
  const V<double> onFace = V<double>(0.1, 0.2, 0.3) + 0.3 * (a[1] - a[0]) + 0.25 * (a[2] - a[0]);
  Tally tally;
  for (int k = -3; k <= 3; ++k) {
    V<double> c = onFace;
    for (int s = 0; s < std::abs(k); ++s) c[2] = std::nextafter(c[2], k > 0 ? 10.0 : -10.0);
    const Tri<double> b = {c, V<double>(c + V<double>(1, 0.5, 2)), V<double>(c + V<double>(-0.5, 1, 3))};
    check(a, b, "ulp " + std::to_string(k), tally);
    checkSegment(c, V<double>(c + V<double>(0.25, 0.5, -2)), a, "segment ulp " + std::to_string(k), tally);
  }
  EXPECT_EQ(tally.failures, 0);
  EXPECT_GT(tally.hits, 0);
  EXPECT_GT(tally.misses, 0);
}

TEST(TriangleIntersectionExact, PointOnTriangle) {
  const V<double> a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  EXPECT_TRUE(mink::triangleContainsPoint(V<double>(1, 1, 0), a, b, c));
  EXPECT_TRUE(mink::triangleContainsPoint(V<double>(2, 2, 0), a, b, c));  // on the hypotenuse
  EXPECT_TRUE(mink::triangleContainsPoint(V<double>(0, 0, 0), a, b, c));
  EXPECT_FALSE(mink::triangleContainsPoint(V<double>(2, std::nextafter(2.0, 3.0), 0), a, b, c));
  EXPECT_FALSE(mink::triangleContainsPoint(V<double>(1, 1, 1e-300), a, b, c));
}

}  // namespace
