// Tests of mink/gauss_map/gauss_map.hpp on real polyhedra, against brute force and CGAL.
//
//  * Structure (exact, CGAL::Gmpq): arcs are the normals of the edge's two faces, with
//    from × to a positive multiple of the edge vector; regions are strictly convex and
//    counter-clockwise (signed volumes of corner triples), each side orthogonal to its edge.
//  * regionContains / regionContainsByCorners / locate against brute force "v maximises
//    d·x over all vertices" — exact in Gmpq (including directions on region boundaries,
//    where the regions holding d must be exactly the brute-force maximisers), and
//    tie-aware for float / double / long double: a comparison fl(d·x_v) vs fl(d·x_w) is
//    trusted only when the two values differ by more than the sum of their forward error
//    bounds 2·eps·Σ|d_i x_i| + 4·min_normal (≥ γ3·Σ|d_i x_i| for Eigen's 3-term dot).
//  * The tiling of S²: every direction lies in at least one region; in exact arithmetic
//    in exactly one unless it is on a boundary (a tie among maximisers).
//  * The overlay G(P) / G(−Q): the arc pairs that cross properly are exactly the EE faces
//    of M = P ⊕ −Q. Checked two ways: for each crossing, the support sets of P and Q in the
//    crossing direction are exactly the two edges (brute force over vertices, exact), and
//    in general position #faces(M) = #faces(P) + #faces(Q) + #crossings, with M the exact
//    CGAL convex hull of all point differences (coplanar triangles merged).
#include "mink/gauss_map/gauss_map.hpp"

#include <CGAL/Gmpq.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/convex_hull_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace {

using mink::ArcIntersection;
using mink::ConvexPolyhedron;
using mink::GaussMap;
using Q = CGAL::Gmpq;
template <class T>
using V3 = mink::Vec3<T>;

#ifdef __SANITIZE_ADDRESS__
constexpr int kScale = 4;  // sanitizer builds run a quarter of the random cases
#else
constexpr int kScale = 1;
#endif

// ---- shapes (double points; converted exactly for Gmpq) -------------------------------
struct Shape {
  std::string name;
  std::vector<V3<double>> points;
};

V3<double> gaussian(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  return V3<double>(g(rng), g(rng), g(rng));
}
V3<double> onSphere(std::mt19937& rng) {
  for (;;) {
    const V3<double> v = gaussian(rng);
    if (v.norm() > 1e-3) return v / v.norm();
  }
}

Shape box(double hx, double hy, double hz) {
  Shape s{"box", {}};
  for (int i = 0; i < 8; ++i)
    s.points.emplace_back(i & 1 ? hx : -hx, i & 2 ? hy : -hy, i & 4 ? hz : -hz);
  return s;
}
Shape randomHull(std::mt19937& rng, int n, const char* name) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Shape s{name, {}};
  for (int i = 0; i < n; ++i) s.points.emplace_back(u(rng), u(rng), u(rng));
  return s;
}
Shape sphereHull(std::mt19937& rng, int n, const V3<double>& axes, const V3<double>& centre,
                 const char* name) {
  Shape s{name, {}};
  for (int i = 0; i < n; ++i) s.points.push_back(centre + onSphere(rng).cwiseProduct(axes));
  return s;
}

template <class T>
std::vector<V3<T>> convert(const std::vector<V3<double>>& p) {
  std::vector<V3<T>> out;
  for (const auto& x : p) out.push_back(V3<T>(T(x[0]), T(x[1]), T(x[2])));
  return out;
}

// ---- exact helpers ---------------------------------------------------------------------
template <class N>
V3<N> cross(const V3<N>& x, const V3<N>& y) {
  return V3<N>(x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]);
}
template <class N>
N dot(const V3<N>& x, const V3<N>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}
bool isZero(const V3<Q>& x) { return x[0] == 0 && x[1] == 0 && x[2] == 0; }
// y is a strictly positive multiple of x.
bool positivelyParallel(const V3<Q>& x, const V3<Q>& y) {
  return isZero(cross(x, y)) && dot(x, y) > 0;
}

// Vertices maximising d·x (brute force over all vertices, exact for exact T).
template <class T>
std::set<int> maximisers(const ConvexPolyhedron<T>& P, const V3<T>& d) {
  std::set<int> s;
  T best = dot(d, P.vertex(0));
  s.insert(0);
  for (int v = 1; v < P.numVertices(); ++v) {
    const T val = dot(d, P.vertex(v));
    if (val > best) {
      best = val;
      s.clear();
    }
    if (!(val < best)) s.insert(v);
  }
  return s;
}

// ---- structure (exact) ---------------------------------------------------------------
void checkStructureExact(const ConvexPolyhedron<Q>& P) {
  const GaussMap<Q> G(P);
  ASSERT_EQ(&G.polyhedron(), &P);
  ASSERT_EQ(G.numPoints(), P.numFaces());
  ASSERT_EQ(G.numArcs(), P.numEdges());
  ASSERT_EQ(G.numRegions(), P.numVertices());
  for (int f = 0; f < G.numPoints(); ++f) EXPECT_EQ(&G.point(f), &P.faceNormal(f));
  for (int e = 0; e < G.numArcs(); ++e) {
    SCOPED_TRACE("edge " + std::to_string(e));
    const auto faces = P.edgeFaces(e);
    const auto verts = P.edgeVertices(e);
    const auto arc = G.arc(e);
    EXPECT_EQ(&arc.from, &P.faceNormal(faces.first));  // a view: no copies
    EXPECT_EQ(&arc.to, &P.faceNormal(faces.second));
    // from × to is a positive multiple of x1 − x0.
    EXPECT_TRUE(positivelyParallel(cross(arc.from, arc.to),
                                   V3<Q>(P.vertex(verts.second) - P.vertex(verts.first))));
  }
  for (int v = 0; v < G.numRegions(); ++v) {
    SCOPED_TRACE("region " + std::to_string(v));
    const int m = G.regionSize(v);
    ASSERT_GE(m, 3);
    ASSERT_EQ(m, P.vertexNeighbors(v).size());
    for (int i = 0; i < m; ++i) {
      const V3<Q>& a = G.regionCorner(v, i);
      const V3<Q>& b = G.regionCorner(v, (i + 1) % m);
      // Side i is orthogonal to the edge to neighbour i+1, outward normal x_v − x_w.
      const int w = P.vertexNeighbors(v)[(i + 1) % m];
      EXPECT_TRUE(positivelyParallel(cross(a, b), V3<Q>(P.vertex(v) - P.vertex(w))));
      // Strictly convex and counter-clockwise: every other corner left of side i.
      for (int j = 0; j < m; ++j) {
        if (j == i || j == (i + 1) % m) continue;
        EXPECT_GT(mink::detail::det3(a, b, G.regionCorner(v, j)), 0) << "side " << i << " corner " << j;
      }
    }
  }
}

std::vector<Shape> exactShapes(std::mt19937& rng) {
  std::vector<Shape> s;
  s.push_back(box(1.0, 0.5, 0.25));
  s.push_back(randomHull(rng, 12, "cube-cloud-12"));
  s.push_back(randomHull(rng, 40, "cube-cloud-40"));
  s.push_back(sphereHull(rng, 25, V3<double>(1, 1, 1), V3<double>(0.3, -0.2, 0.1), "sphere-25"));
  s.push_back(sphereHull(rng, 60, V3<double>(2.0, 0.7, 0.3), V3<double>(0, 0, 0), "ellipsoid-60"));
  return s;
}

TEST(GaussMap, StructureExact) {
  std::mt19937 rng(101);
  for (const Shape& s : exactShapes(rng)) {
    SCOPED_TRACE(s.name);
    const auto P = ConvexPolyhedron<Q>::fromPoints(convert<Q>(s.points));
    checkStructureExact(P);
  }
}

// ---- regionContains / locate, exact ----------------------------------------------------
// All regions agree with the brute-force maximisers of d·x; locate lands in one of them.
void checkDirectionExact(const ConvexPolyhedron<Q>& P, const GaussMap<Q>& G, const V3<Q>& d,
                         int hint, const std::set<int>& expected, bool allVertices) {
  const std::set<int> arg = maximisers(P, d);
  EXPECT_EQ(arg, expected);
  int holding = 0;
  for (int v = 0; v < P.numVertices(); ++v) {
    const bool isMax = arg.count(v) > 0;
    if (!allVertices && !isMax && v % 7 != 0) continue;  // a sample of the others
    const bool in = G.regionContains(v, d);
    EXPECT_EQ(in, isMax) << "vertex " << v;
    EXPECT_EQ(G.regionContainsByCorners(v, d), isMax) << "vertex " << v;
    holding += in;
  }
  if (allVertices) {
    EXPECT_EQ(holding, static_cast<int>(arg.size()));  // the tiling
  }
  const int loc = G.locate(d, hint);
  EXPECT_TRUE(arg.count(loc)) << "locate from " << hint << " gave " << loc;
}

TEST(GaussMap, RegionContainsAndLocateExact) {
  std::mt19937 rng(102);
  const std::vector<Shape> shapes = exactShapes(rng);
  int random = 0, boundary = 0;
  for (const Shape& s : shapes) {
    SCOPED_TRACE(s.name);
    const auto P = ConvexPolyhedron<Q>::fromPoints(convert<Q>(s.points));
    const GaussMap<Q> G(P);
    std::uniform_int_distribution<int> anyVertex(0, P.numVertices() - 1);
    // Random directions: d lies in exactly one region (no ties with probability one,
    // and the brute force confirms it).
    for (int i = 0; i < 2000 / kScale; ++i, ++random) {
      SCOPED_TRACE("random direction " + std::to_string(i));
      const V3<Q> d = convert<Q>({gaussian(rng)})[0];
      const std::set<int> arg = maximisers(P, d);
      ASSERT_EQ(arg.size(), 1u);
      checkDirectionExact(P, G, d, anyVertex(rng), arg, i % 4 == 0);
    }
    // Boundary directions. A face normal is a corner of the regions of exactly the face's
    // vertices; a positive combination of an arc's endpoints lies in exactly the two
    // regions of the edge's endpoints; the sum of a region's corners is interior to it.
    for (int f = 0; f < P.numFaces(); ++f, ++boundary) {
      SCOPED_TRACE("face normal " + std::to_string(f));
      const auto fv = P.faceVertices(f);
      checkDirectionExact(P, G, G.point(f), anyVertex(rng), std::set<int>(fv.begin(), fv.end()),
                          true);
    }
    for (int e = 0; e < P.numEdges(); ++e, ++boundary) {
      SCOPED_TRACE("arc interior " + std::to_string(e));
      const auto arc = G.arc(e);
      const auto ev = P.edgeVertices(e);
      checkDirectionExact(P, G, V3<Q>(arc.from + Q(3, 7) * arc.to), anyVertex(rng),
                          {ev.first, ev.second}, true);
    }
    for (int v = 0; v < P.numVertices(); ++v) {
      V3<Q> c = V3<Q>::Zero();
      for (int i = 0; i < G.regionSize(v); ++i) c += G.regionCorner(v, i);
      checkDirectionExact(P, G, c, anyVertex(rng), {v}, false);
    }
    // locate from every start vertex.
    const V3<Q> d = convert<Q>({gaussian(rng)})[0];
    const std::set<int> arg = maximisers(P, d);
    for (int h = 0; h < P.numVertices(); ++h) EXPECT_TRUE(arg.count(G.locate(d, h))) << h;
  }
  EXPECT_GE(random, 10000 / kScale);
  std::printf("exact: %d random and %d boundary directions\n", random, boundary);
}

// ---- regionContains / locate, floating point, tie-aware --------------------------------
template <class T>
struct FloatCounts {
  long directions = 0, trusted = 0, ties = 0;
};

template <class T>
void checkDirectionFloating(const ConvexPolyhedron<T>& P, const GaussMap<T>& G, const V3<T>& d,
                            int hint, FloatCounts<T>& counts) {
  using std::abs;
  const int n = P.numVertices();
  std::vector<T> val(n), err(n);
  for (int v = 0; v < n; ++v) {
    const V3<T>& x = P.vertex(v);
    val[v] = d.dot(x);  // the same evaluation as the code under test
    err[v] = T(2) * std::numeric_limits<T>::epsilon() *
                 (abs(d[0] * x[0]) + abs(d[1] * x[1]) + abs(d[2] * x[2])) +
             T(4) * std::numeric_limits<T>::min();
  }
  const auto surelyGreater = [&](int a, int b) { return val[a] - val[b] > err[a] + err[b]; };
  ++counts.directions;
  // Brute force, certified: v is surely the maximiser when it surely beats every other
  // vertex; surely not one when some vertex surely beats it.
  int surelyMax = -1;
  int holding = 0;
  for (int v = 0; v < n; ++v) {
    bool beatsAll = true, beaten = false;
    for (int w = 0; w < n && (beatsAll || !beaten); ++w) {
      if (w == v) continue;
      beatsAll = beatsAll && surelyGreater(v, w);
      beaten = beaten || surelyGreater(w, v);
    }
    const bool in = G.regionContains(v, d);
    holding += in;
    // regionContains decides by comparing v with its neighbours only; a neighbour within
    // error of v makes its answer a tie, which we do not judge.
    bool neighbourTie = false, neighbourBeats = false;
    for (int w : P.vertexNeighbors(v)) {
      neighbourTie = neighbourTie || (!surelyGreater(v, w) && !surelyGreater(w, v));
      neighbourBeats = neighbourBeats || surelyGreater(w, v);
    }
    if (beatsAll) {
      surelyMax = v;
      ++counts.trusted;
      EXPECT_TRUE(in) << "vertex " << v << " surely maximises d.x";
    } else if (beaten && (neighbourBeats || !neighbourTie)) {
      ++counts.trusted;
      EXPECT_FALSE(in) << "vertex " << v << " surely does not maximise d.x";
    } else {
      ++counts.ties;
    }
    // The corner form on the rounded normals: judged where every side's sign is certified.
    bool allPositive = true, someNegative = false;
    const int m = G.regionSize(v);
    for (int i = 0; i < m; ++i) {
      const int s = mink::detail::filteredSign(G.regionCorner(v, i), G.regionCorner(v, (i + 1) % m), d);
      allPositive = allPositive && s == 1;
      someNegative = someNegative || s == -1;
    }
    if (allPositive) {
      EXPECT_TRUE(G.regionContainsByCorners(v, d)) << "vertex " << v;
    }
    if (someNegative) {
      EXPECT_FALSE(G.regionContainsByCorners(v, d)) << "vertex " << v;
    }
  }
  EXPECT_GE(holding, 1);  // the regions cover the sphere
  const int loc = G.locate(d, hint);
  EXPECT_TRUE(G.regionContains(loc, d));  // bit-for-bit the same comparisons
  if (surelyMax >= 0) {
    EXPECT_EQ(loc, surelyMax);
  }
}

template <class T>
void runFloating(const char* tname, int directionsPerShape, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Shape> shapes = exactShapes(rng);
  shapes.push_back(sphereHull(rng, 400, V3<double>(3.0, 1.0, 0.2), V3<double>(10, -5, 2), "ellipsoid-400"));
  shapes.push_back(box(1e3, 1e-2, 1.0));
  FloatCounts<T> counts;
  for (const Shape& s : shapes) {
    SCOPED_TRACE(s.name + " seed " + std::to_string(seed));
    const auto P = ConvexPolyhedron<T>::fromPoints(convert<T>(s.points));
    const GaussMap<T> G(P);
    std::uniform_int_distribution<int> anyVertex(0, P.numVertices() - 1);
    for (int i = 0; i < directionsPerShape; ++i) {
      SCOPED_TRACE("direction " + std::to_string(i));
      checkDirectionFloating(P, G, convert<T>({gaussian(rng)})[0], anyVertex(rng), counts);
    }
    // Directions on boundaries of the rounded map: face normals and arc midpoints (ties).
    for (int f = 0; f < P.numFaces(); ++f) checkDirectionFloating(P, G, G.point(f), anyVertex(rng), counts);
    for (int e = 0; e < P.numEdges(); ++e)
      checkDirectionFloating(P, G, V3<T>(G.arc(e).from + G.arc(e).to), anyVertex(rng), counts);
  }
  std::printf("%s: %ld directions, %ld vertex verdicts trusted, %ld ties not judged\n",
              tname, counts.directions, counts.trusted, counts.ties);
}

TEST(GaussMap, RegionContainsAndLocateDouble) { runFloating<double>("double", 2000 / kScale, 103); }
TEST(GaussMap, RegionContainsAndLocateFloat) { runFloating<float>("float", 300 / kScale, 104); }
TEST(GaussMap, RegionContainsAndLocateLongDouble) { runFloating<long double>("long double", 300 / kScale, 105); }

// ---- the overlay G(P) / G(−Q) and the EE faces of M = P ⊕ −Q ---------------------------
using HullKernel = CGAL::Simple_cartesian<Q>;  // exact predicates and constructions
using HullPoint = HullKernel::Point_3;
using HullMesh = CGAL::Polyhedron_3<HullKernel>;

// Faces of the convex hull of `pts`: triangles of CGAL's hull merged across edges whose
// four points are coplanar (union–find).
int hullFaceCount(const std::vector<HullPoint>& pts) {
  HullMesh hull;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
  std::unordered_map<const void*, int> id;
  for (auto f = hull.facets_begin(); f != hull.facets_end(); ++f) {
    const int k = static_cast<int>(id.size());
    id[&*f] = k;
  }
  std::vector<int> parent(id.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (auto h = hull.halfedges_begin(); h != hull.halfedges_end(); ++h) {
    if (h->is_border() || h->opposite()->is_border()) continue;
    if (CGAL::coplanar(h->vertex()->point(), h->prev()->vertex()->point(),
                       h->next()->vertex()->point(), h->opposite()->next()->vertex()->point()))
      parent[find(id[&*h->facet()])] = find(id[&*h->opposite()->facet()]);
  }
  int faces = 0;
  for (int i = 0; i < static_cast<int>(parent.size()); ++i) faces += find(i) == i;
  return faces;
}

// Rotation matrix of the integer quaternion (w, x, y, z): rational and exactly orthonormal.
mink::Mat3<Q> rationalRotation(int w, int x, int y, int z) {
  const Q s(w * w + x * x + y * y + z * z);
  mink::Mat3<Q> R;
  R << Q(w * w + x * x - y * y - z * z), Q(2 * (x * y - w * z)), Q(2 * (x * z + w * y)),
      Q(2 * (x * y + w * z)), Q(w * w - x * x + y * y - z * z), Q(2 * (y * z - w * x)),
      Q(2 * (x * z - w * y)), Q(2 * (y * z + w * x)), Q(w * w - x * x - y * y + z * z);
  return R / s;
}

using EdgeKey = std::pair<std::pair<int, int>, std::pair<int, int>>;  // input indices
template <class T>
std::pair<int, int> edgeKey(const ConvexPolyhedron<T>& P, int e) {
  const auto ev = P.edgeVertices(e);
  const int a = P.inputIndex(ev.first), b = P.inputIndex(ev.second);
  return {std::min(a, b), std::max(a, b)};
}

TEST(GaussMap, ArcCrossingsAreTheEEFacesOfTheMinkowskiDifference) {
  std::mt19937 rng(106);
  std::uniform_int_distribution<int> count(5, 18), quat(-5, 5);
  int cases = 0, skipped = 0, totalEE = 0, doubleCompared = 0;
  for (int c = 0; c < 16 / (kScale > 1 ? 2 : 1); ++c) {
    SCOPED_TRACE("case " + std::to_string(c));
    const Shape sp = c % 2 ? randomHull(rng, count(rng), "P")
                           : sphereHull(rng, count(rng), V3<double>(1.0, 0.6, 0.4), V3<double>(0, 0, 0), "P");
    const Shape sq = sphereHull(rng, count(rng), V3<double>(0.5, 1.2, 0.8), V3<double>(2, 0.5, -1), "Q");
    const bool rotate = c % 4 == 3;
    const mink::Mat3<Q> R = rotate ? rationalRotation(quat(rng), quat(rng), quat(rng), 1)
                                   : mink::Mat3<Q>(mink::Mat3<Q>::Identity());
    const auto P = ConvexPolyhedron<Q>::fromPoints(convert<Q>(sp.points));
    const auto Qh = ConvexPolyhedron<Q>::fromPoints(convert<Q>(sq.points));
    const GaussMap<Q> GP(P), GQ(Qh);

    // Brute force over all arc pairs of G(P) and G(−R·Q).
    std::set<EdgeKey> crossings;
    bool degenerate = false;
    for (int ep = 0; ep < P.numEdges(); ++ep)
      for (int eq = 0; eq < Qh.numEdges(); ++eq) {
        const ArcIntersection cls = rotate ? GP.edgeArcsIntersect(ep, GQ, eq, true, R)
                                           : GP.edgeArcsIntersect(ep, GQ, eq, true);
        if (cls == ArcIntersection::Degenerate) degenerate = true;
        if (cls != ArcIntersection::Proper) continue;
        crossings.insert({edgeKey(P, ep), edgeKey(Qh, eq)});
        // The crossing direction n is the normal of the EE face: P's support set in n is
        // exactly e_p, Q's support set in −n (that of −Q in n) exactly e_q.
        const auto a = GP.arc(ep);
        const mink::ArcEndpoints<Q> b = GQ.rotatedArc(eq, R, true);
        const V3<Q> n = mink::arcIntersectionDirection(a.from, a.to, b.from, b.to);
        const auto evp = P.edgeVertices(ep);
        const auto evq = Qh.edgeVertices(eq);
        EXPECT_EQ(maximisers(P, n), (std::set<int>{evp.first, evp.second})) << ep << " " << eq;
        EXPECT_EQ(maximisers(Qh, V3<Q>(-(R.transpose() * n))),
                  (std::set<int>{evq.first, evq.second}))
            << ep << " " << eq;
      }
    if (degenerate) {  // not in general position: the face-count identity does not apply
      ++skipped;
      continue;
    }
    ++cases;
    totalEE += static_cast<int>(crossings.size());

    // CGAL: faces of the exact hull of all differences p − R q.
    std::vector<HullPoint> diff;
    for (const auto& p : sp.points)
      for (const auto& q : sq.points) {
        const V3<Q> x = convert<Q>({p})[0] - R * convert<Q>({q})[0];
        diff.emplace_back(x[0], x[1], x[2]);
      }
    EXPECT_EQ(hullFaceCount(diff), P.numFaces() + Qh.numFaces() + static_cast<int>(crossings.size()));

    // double: where the filter certifies every pair, both the filtered and the plain
    // predicate give exactly the exact set of crossings.
    if (rotate) continue;
    const auto Pd = ConvexPolyhedron<double>::fromPoints(sp.points);
    const auto Qd = ConvexPolyhedron<double>::fromPoints(sq.points);
    if (Pd.numEdges() != P.numEdges() || Qd.numEdges() != Qh.numEdges()) continue;
    const GaussMap<double> GPd(Pd), GQd(Qd);
    std::set<EdgeKey> plain, filtered;
    bool uncertain = false;
    for (int ep = 0; ep < Pd.numEdges(); ++ep)
      for (int eq = 0; eq < Qd.numEdges(); ++eq) {
        const auto a = GPd.arc(ep);
        const auto b = GQd.rotatedArc(eq, mink::Mat3<double>::Identity(), true);
        const ArcIntersection f = mink::classifyArcsFiltered(a.from, a.to, b.from, b.to);
        uncertain = uncertain || f == ArcIntersection::Uncertain;
        if (f == ArcIntersection::Proper) filtered.insert({edgeKey(Pd, ep), edgeKey(Qd, eq)});
        if (GPd.edgeArcsIntersect(ep, GQd, eq, true) == ArcIntersection::Proper)
          plain.insert({edgeKey(Pd, ep), edgeKey(Qd, eq)});
      }
    if (!uncertain) {
      ++doubleCompared;
      EXPECT_EQ(filtered, crossings);
      EXPECT_EQ(plain, crossings);
    }
  }
  std::printf("overlay: %d cases in general position (%d skipped), %d EE faces, %d double "
              "comparisons\n", cases, skipped, totalEE, doubleCompared);
  EXPECT_GE(cases, 6 / kScale);
  EXPECT_GT(doubleCompared, 0);
}

// A hand-checkable overlay: two axis-aligned boxes have parallel normals, hence
// degenerate overlays; rotating one by a generic rational rotation removes that and the
// face count of the difference of two boxes (generic: 6 + 6 + 18 = 30, a truncated
// parallelepiped) must follow.
TEST(GaussMap, TwoBoxesGenericRotation) {
  const Shape b1 = box(1, 2, 3), b2 = box(0.5, 0.25, 2);
  const auto P = ConvexPolyhedron<Q>::fromPoints(convert<Q>(b1.points));
  const auto Qh = ConvexPolyhedron<Q>::fromPoints(convert<Q>(b2.points));
  const GaussMap<Q> GP(P), GQ(Qh);
  int identityDegenerate = 0;
  for (int ep = 0; ep < P.numEdges(); ++ep)
    for (int eq = 0; eq < Qh.numEdges(); ++eq)
      identityDegenerate += GP.edgeArcsIntersect(ep, GQ, eq, true) == ArcIntersection::Degenerate;
  EXPECT_GT(identityDegenerate, 0);  // shared normals: every arc meets its parallel twin
  const mink::Mat3<Q> R = rationalRotation(3, 1, 2, 1);
  int proper = 0, degenerate = 0;
  for (int ep = 0; ep < P.numEdges(); ++ep)
    for (int eq = 0; eq < Qh.numEdges(); ++eq) {
      const ArcIntersection c = GP.edgeArcsIntersect(ep, GQ, eq, true, R);
      proper += c == ArcIntersection::Proper;
      degenerate += c == ArcIntersection::Degenerate;
    }
  EXPECT_EQ(degenerate, 0);
  std::vector<HullPoint> diff;
  for (const auto& p : b1.points)
    for (const auto& q : b2.points) {
      const V3<Q> x = convert<Q>({p})[0] - R * convert<Q>({q})[0];
      diff.emplace_back(x[0], x[1], x[2]);
    }
  EXPECT_EQ(hullFaceCount(diff), 12 + proper);
  // Each edge direction of one box against the other's: 3 x 3 direction pairs, each
  // giving a pair of opposite faces, and each such face one crossing: 18.
  EXPECT_EQ(proper, 18);
}

}  // namespace
