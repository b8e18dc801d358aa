// Tests of mink/polyhedron/convex_polyhedron.hpp: the structure of every shape built
// (half-edges, vertex rings, face planes, convexity), fromMesh on closed convex meshes
// and every rejection path of fromMesh / fromPoints, and support queries.
//
// References are independent of the code under test: hand-written meshes with their
// expected merged faces, exact rational arithmetic (CGAL::Gmpq) for planes and signs,
// and brute-force scans for support. The hull-versus-CGAL comparisons live in
// hull_vs_cgal_test.cpp, which reuses expectValidPolyhedron from this file (explicitly
// instantiated at the bottom for float, double, long double and CGAL::Gmpq).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <CGAL/Gmpq.h>
#include <Eigen/Geometry>
#include <CGAL/Gmpz.h>

#include "mink/core/detail/spatial_order.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"
#include "support/to_rational.hpp"

namespace mink_test {

using Q = CGAL::Gmpq;
using Z = CGAL::Gmpz;
using mink::ConvexPolyhedron;
using mink::Vec3;

// ---------------------------------------------------------------------------------
// Exact conversions and printing.

// toQ: support/to_rational.hpp.
inline double dbl(const Q& x) { return CGAL::to_double(x); }
template <class T>
double dbl(const T& x) {
  return static_cast<double>(x);
}

template <class T>
std::string str(const Vec3<T>& p) {
  std::ostringstream os;
  os.precision(17);
  os << "(" << dbl(p[0]) << ", " << dbl(p[1]) << ", " << dbl(p[2]) << ")";
  return os.str();
}

// Accumulator for tolerance checks: products of two doubles (or floats) are exact to
// within 2^-64 relative in long double, far below the hull tolerance (64 eps); for
// long double inputs and exact scalars we evaluate exactly.
template <class T>
struct AccOf {
  using type = long double;
};
template <>
struct AccOf<long double> {
  using type = Q;
};
template <>
struct AccOf<Q> {
  using type = Q;
};
template <class A, class T>
A toAcc(const T& x) {
  if constexpr (std::is_same<A, Q>::value) {
    return toQ(x);
  } else {
    return static_cast<long double>(x);
  }
}
template <class A, class T>
std::array<A, 3> toAcc3(const Vec3<T>& p) {
  return {toAcc<A>(p[0]), toAcc<A>(p[1]), toAcc<A>(p[2])};
}
template <class A>
A dot3(const std::array<A, 3>& a, const std::array<A, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class A>
std::array<A, 3> sub3(const std::array<A, 3>& a, const std::array<A, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class A>
std::array<A, 3> cross3(const std::array<A, 3>& a, const std::array<A, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class T>
Vec3<Q> toQVec(const Vec3<T>& p) {
  return Vec3<Q>(toQ(p[0]), toQ(p[1]), toQ(p[2]));
}

// Exact coordinates for the structure checks: for floating T, Gmpz multiples of 2^-S
// with one S for the whole shape (ring operations only, several times faster than
// Gmpq); for exact T, the values themselves.
template <class T>
struct LoopNum {
  using type = Z;
};
template <>
struct LoopNum<Q> {
  using type = Q;
};
template <class T>
class ExactCoordinates {
 public:
  explicit ExactCoordinates(const std::vector<Vec3<T>>& pts) {
    if constexpr (!std::is_same<T, Q>::value)
      for (const auto& p : pts)
        for (int k = 0; k < 3; ++k)
          for (double part : doubles(p[k]))
            if (part != 0.0) {
              int e;
              std::frexp(part, &e);
              S_ = std::max(S_, std::numeric_limits<double>::digits - e);
            }
  }
  std::array<typename LoopNum<T>::type, 3> operator()(const Vec3<T>& p) const {
    if constexpr (std::is_same<T, Q>::value) {
      return {p[0], p[1], p[2]};
    } else {
      return {toZ(p[0]), toZ(p[1]), toZ(p[2])};
    }
  }

 private:
  // x as an exact sum of doubles.
  static std::vector<double> doubles(const T& x) {
    std::vector<double> out;
    long double rest = static_cast<long double>(x);
    for (int i = 0; i < 4 && rest != 0.0L; ++i) {
      out.push_back(static_cast<double>(rest));
      rest -= static_cast<long double>(out.back());
    }
    return out;
  }
  Z toZ(const T& x) const {
    Z sum(0);
    for (double part : doubles(x)) {
      if (part == 0.0) continue;
      int e;
      const double m = std::ldexp(std::frexp(part, &e), std::numeric_limits<double>::digits);  // integer
      Z z;
      mpz_set_d(z.mpz(), m);
      mpz_mul_2exp(z.mpz(), z.mpz(), static_cast<unsigned long>(e - std::numeric_limits<double>::digits + S_));
      sum += z;
    }
    return sum;
  }
  int S_ = 0;
};
template <class N>
bool isZero3(const std::array<N, 3>& a) {
  return CGAL::is_zero(a[0]) && CGAL::is_zero(a[1]) && CGAL::is_zero(a[2]);
}

// Counts failures of one check family and prints only the first few.
struct Failures {
  int printed = 0;
  int total = 0;
  bool report() {
    ++total;
    return printed++ < 8;
  }
  ~Failures() {
    if (total > 8) ADD_FAILURE() << total << " failures in total (only the first 8 printed)";
  }
};
#define MT_EXPECT(fails, cond) \
  switch (0)                   \
  case 0:                      \
  default:                     \
    if (cond) {                \
    } else if (!(fails).report()) { \
    } else                     \
      ADD_FAILURE()

// ---------------------------------------------------------------------------------
// Structure invariants of a ConvexPolyhedron. Combinatorics are checked for every T;
// the geometry of the vertex loops exactly (in Gmpq), and the reported planes exactly
// for exact T and within P.tolerance() for inexact T. Declared with the default
// exactGeometry = true in both test files.
template <class T>
void expectValidPolyhedron(const ConvexPolyhedron<T>& P, const std::string& context, bool exactGeometry = true);

template <class T>
void expectValidPolyhedron(const ConvexPolyhedron<T>& P, const std::string& context, bool exactGeometry) {
  SCOPED_TRACE("structure of " + context);
  Failures fails;
  const int V = P.numVertices(), E = P.numEdges(), F = P.numFaces(), H = P.numHalfEdges();
  ASSERT_GE(V, 4);
  ASSERT_GE(F, 4);
  ASSERT_EQ(H, 2 * E);
  EXPECT_EQ(V - E + F, 2) << "Euler characteristic: V=" << V << " E=" << E << " F=" << F;
  ASSERT_EQ(static_cast<int>(P.vertices().size()), V);
  ASSERT_EQ(P.faceStart(0), 0);
  ASSERT_EQ(P.faceStart(F), H);
  // Ranges first: the accessors index with these values.
  for (int f = 0; f < F; ++f) ASSERT_LT(P.faceStart(f), P.faceStart(f + 1)) << "face " << f;
  for (int h = 0; h < H; ++h) {
    ASSERT_TRUE(P.heFace(h) >= 0 && P.heFace(h) < F) << "half-edge " << h;
    ASSERT_TRUE(P.heOrigin(h) >= 0 && P.heOrigin(h) < V) << "half-edge " << h;
    ASSERT_TRUE(P.heTwin(h) >= 0 && P.heTwin(h) < H) << "half-edge " << h;
    ASSERT_TRUE(P.heEdge(h) >= 0 && P.heEdge(h) < E) << "half-edge " << h;
  }
  for (int e = 0; e < E; ++e) ASSERT_TRUE(P.edgeHalfEdge(e) >= 0 && P.edgeHalfEdge(e) < H) << "edge " << e;
  int degreeSum = 0;
  for (int v = 0; v < V; ++v) {
    ASSERT_GE(P.degree(v), 0) << "vertex " << v;
    degreeSum += P.degree(v);
  }
  ASSERT_EQ(degreeSum, H);

  // Faces: loops of >= 3 distinct vertices whose half-edges close by heNext.
  for (int f = 0; f < F; ++f) {
    const int m = P.faceSize(f);
    MT_EXPECT(fails, m >= 3) << "face " << f << " has " << m << " vertices";
    const auto loop = P.faceVertices(f);
    MT_EXPECT(fails, loop.size() == m) << "face " << f;
    std::vector<int> sorted(loop.begin(), loop.end());
    std::sort(sorted.begin(), sorted.end());
    MT_EXPECT(fails, std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end())
        << "face " << f << " repeats a vertex";
    for (int i = 0; i < m; ++i) {
      const int h = P.faceStart(f) + i;
      const int hn = P.faceStart(f) + (i + 1) % m;
      MT_EXPECT(fails, P.heFace(h) == f) << "half-edge " << h << " of face " << f;
      MT_EXPECT(fails, P.heOrigin(h) == loop[i]) << "half-edge " << h;
      MT_EXPECT(fails, P.heNext(h) == hn) << "heNext(" << h << ") does not close face " << f;
      MT_EXPECT(fails, P.hePrev(hn) == h) << "hePrev(heNext(" << h << "))";
      MT_EXPECT(fails, P.heTarget(h) == loop[(i + 1) % m]) << "half-edge " << h;
    }
  }

  // Twins run the opposite way on another face; directed edges are unique.
  std::vector<std::pair<int, int>> directed;
  for (int h = 0; h < H; ++h) {
    const int t = P.heTwin(h);
    MT_EXPECT(fails, t != h) << "half-edge " << h << " is its own twin";
    MT_EXPECT(fails, P.heTwin(t) == h) << "twin(twin(" << h << ")) != " << h;
    MT_EXPECT(fails, P.heOrigin(t) == P.heTarget(h) && P.heTarget(t) == P.heOrigin(h))
        << "twin of " << h << " does not run the opposite way";
    MT_EXPECT(fails, P.heFace(t) != P.heFace(h)) << "half-edge " << h << " and its twin on one face";
    directed.emplace_back(P.heOrigin(h), P.heTarget(h));
  }
  std::sort(directed.begin(), directed.end());
  MT_EXPECT(fails, std::adjacent_find(directed.begin(), directed.end()) == directed.end())
      << "a directed edge appears twice";

  // Edges: each undirected edge once, named by both of its half-edges.
  std::vector<int> edgeUses(E, 0);
  for (int h = 0; h < H; ++h) {
    const int e = P.heEdge(h);
    ++edgeUses[e];
    MT_EXPECT(fails, P.heEdge(P.heTwin(h)) == e) << "half-edge " << h;
    MT_EXPECT(fails, P.edgeHalfEdge(e) == h || P.edgeHalfEdge(e) == P.heTwin(h)) << "half-edge " << h;
  }
  for (int e = 0; e < E; ++e) {
    MT_EXPECT(fails, edgeUses[e] == 2) << "edge " << e << " used by " << edgeUses[e] << " half-edges";
    const int h = P.edgeHalfEdge(e);
    MT_EXPECT(fails, P.heEdge(h) == e) << "edge " << e;
    MT_EXPECT(fails, P.edgeVertices(e) == std::make_pair(P.heOrigin(h), P.heTarget(h))) << "edge " << e;
    MT_EXPECT(fails, P.edgeFaces(e) == std::make_pair(P.heFace(h), P.heFace(P.heTwin(h)))) << "edge " << e;
  }

  // Vertex rings: CCW from outside, vertexFaces(v)[i] between neighbours i and i+1.
  std::vector<int> outCount(V, 0), ringUses(H, 0);
  for (int h = 0; h < H; ++h) ++outCount[P.heOrigin(h)];
  for (int v = 0; v < V; ++v) {
    const int d = P.degree(v);
    MT_EXPECT(fails, d >= 3) << "vertex " << v << " " << str(P.vertex(v)) << " lies in only " << d
                             << " faces (not a corner)";
    MT_EXPECT(fails, d == outCount[v]) << "vertex " << v << " degree " << d << " but " << outCount[v]
                                       << " outgoing half-edges";
    const auto nb = P.vertexNeighbors(v);
    const auto fc = P.vertexFaces(v);
    const auto hs = P.vertexHalfEdges(v);
    if (nb.size() != d || fc.size() != d || hs.size() != d) {
      MT_EXPECT(fails, false) << "vertex " << v << " ring sizes differ";
      continue;
    }
    for (int i = 0; i < d; ++i) {
      const int h = hs[i];
      if (h < 0 || h >= H) {
        MT_EXPECT(fails, false) << "vertex " << v << " ring half-edge out of range";
        continue;
      }
      ++ringUses[h];
      MT_EXPECT(fails, P.heOrigin(h) == v) << "vertex " << v << " ring half-edge " << h;
      MT_EXPECT(fails, P.heTarget(h) == nb[i]) << "vertex " << v << " neighbour " << i;
      MT_EXPECT(fails, P.heFace(h) == fc[i]) << "vertex " << v << " face " << i;
      MT_EXPECT(fails, hs[(i + 1) % d] == P.heTwin(P.hePrev(h)))
          << "vertex " << v << ": ring not counter-clockwise at position " << i;
      const int f = fc[i];
      if (f < 0 || f >= F) continue;
      const auto loop = P.faceVertices(f);
      const int m = loop.size();
      int pos = -1;
      for (int k = 0; k < m; ++k)
        if (loop[k] == v) pos = k;
      MT_EXPECT(fails, pos >= 0 && loop[(pos + 1) % m] == nb[i] && loop[(pos + m - 1) % m] == nb[(i + 1) % d])
          << "vertex " << v << ": face " << f << " is not between neighbours " << nb[i] << " and "
          << nb[(i + 1) % d];
    }
    std::vector<int> s(nb.begin(), nb.end());
    std::sort(s.begin(), s.end());
    MT_EXPECT(fails, std::adjacent_find(s.begin(), s.end()) == s.end()) << "vertex " << v << " repeats a neighbour";
  }
  for (int h = 0; h < H; ++h) MT_EXPECT(fails, ringUses[h] == 1) << "half-edge " << h << " in " << ringUses[h] << " rings";

  // Vertices: distinct points with distinct input indices.
  std::vector<int> inputs;
  for (int v = 0; v < V; ++v) {
    MT_EXPECT(fails, P.inputIndex(v) >= 0) << "vertex " << v;
    inputs.push_back(P.inputIndex(v));
  }
  std::sort(inputs.begin(), inputs.end());
  MT_EXPECT(fails, std::adjacent_find(inputs.begin(), inputs.end()) == inputs.end()) << "input index repeated";
  {
    std::vector<std::array<Q, 3>> pts;
    for (int v = 0; v < V; ++v) pts.push_back(toAcc3<Q>(P.vertex(v)));
    std::sort(pts.begin(), pts.end());
    MT_EXPECT(fails, std::adjacent_find(pts.begin(), pts.end()) == pts.end()) << "two vertices coincide";
  }

  // The slack of the inexact checks below: the shape's tolerance, or for a shape built
  // with tolerance 0 (exact hull, rounded planes) the rounding of its planes, 64 eps of
  // its extent.
  T slack = P.tolerance();
  if constexpr (!mink::ScalarTraits<T>::isExact)
    if (!(slack > T(0))) slack = T(64) * std::numeric_limits<T>::epsilon() * P.extent();
  const Q slackQ = toQ(slack);

  // Extent as documented: |x|max + |y|max + |z|max over the vertices.
  {
    std::array<Q, 3> m = {Q(0), Q(0), Q(0)};
    for (int v = 0; v < V; ++v)
      for (int k = 0; k < 3; ++k) m[k] = std::max(m[k], CGAL::abs(toQ(P.vertex(v)[k])));
    const Q ext = m[0] + m[1] + m[2];
    if constexpr (mink::ScalarTraits<T>::isExact) {
      EXPECT_TRUE(toQ(P.extent()) == ext) << "extent " << dbl(P.extent()) << " vs " << dbl(ext);
    } else {
      // The extent is measured on the input, whose extreme coordinates are corners of
      // the exact hull; the tolerant hull keeps them up to the tolerance.
      EXPECT_LE(CGAL::abs(toQ(P.extent()) - ext), 4 * slackQ + Q(1e-300))
          << "extent " << dbl(P.extent()) << " vs " << dbl(ext);
    }
  }

  // Vertex-above-face scans are O(V F): all pairs when affordable (fewer when the
  // arithmetic is Gmpq), else every edge's two faces plus a sample of faces.
  auto scanPairs = [&](long long budget, const std::function<void(int, int)>& check) {
    if (static_cast<long long>(V) * F <= budget) {
      for (int f = 0; f < F; ++f)
        for (int v = 0; v < V; ++v) check(f, v);
      return;
    }
    for (int e = 0; e < E; ++e) {
      const auto fg = P.edgeFaces(e);
      for (int v : P.faceVertices(fg.second)) check(fg.first, v);
      for (int v : P.faceVertices(fg.first)) check(fg.second, v);
    }
    // Plus a sample of whole faces, as many as the budget allows (at most 64).
    const int samples = static_cast<int>(std::min<long long>(64, std::max<long long>(1, budget / V)));
    for (int f = 0; f < F; f += std::max(1, F / samples))
      for (int v = 0; v < V; ++v) check(f, v);
  };
  const long long qBudget = 300000LL;

  // Reported planes: exact Newell normals for exact T; for inexact T unit normals whose
  // planes pass within the tolerance of the face's vertices and have every vertex at
  // most the tolerance above them.
  if constexpr (mink::ScalarTraits<T>::isExact) {
    EXPECT_TRUE(P.tolerance() == T(0));
    for (int f = 0; f < F; ++f) {
      const auto loop = P.faceVertices(f);
      const int m = loop.size();
      Vec3<T> newell = Vec3<T>::Zero();
      for (int i = 0; i < m; ++i) newell += P.vertex(loop[i]).cross(P.vertex(loop[(i + 1) % m]));
      const Vec3<T>& n = P.faceNormal(f);
      MT_EXPECT(fails, n == newell) << "face " << f << ": normal is not the Newell normal";
      for (int i = 0; i < m; ++i)
        MT_EXPECT(fails, n.dot(P.vertex(loop[i])) == P.faceOffset(f))
            << "face " << f << ": vertex " << loop[i] << " is off the face's reported plane";
    }
  } else {
    using A = typename AccOf<T>::type;
    const A tol = toAcc<A>(slack);
    EXPECT_GE(P.tolerance(), T(0));
    const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
    const A unitSlack = toAcc<A>(T(16) * std::numeric_limits<T>::epsilon());
    std::vector<std::array<A, 3>> X(V), N(F);
    std::vector<A> off(F);
    for (int v = 0; v < V; ++v) X[v] = toAcc3<A>(P.vertex(v));
    for (int f = 0; f < F; ++f) {
      N[f] = toAcc3<A>(P.faceNormal(f));
      off[f] = toAcc<A>(P.faceOffset(f));
    }
    auto excess = [&](int f, int v) { return dot3(N[f], X[v]) - off[f]; };  // signed distance (unit n)
    for (int f = 0; f < F; ++f) {
      const A dev = dot3(N[f], N[f]) - A(1);
      MT_EXPECT(fails, dev <= unitSlack && -dev <= unitSlack)
          << "face " << f << ": normal not unit, |n|^2 - 1 = " << dbl(dev) << " (eps " << eps << ")";
      for (int v : P.faceVertices(f)) {
        const A d = excess(f, v);
        MT_EXPECT(fails, d <= tol && -d <= tol)
            << "face " << f << ": vertex " << v << " is " << dbl(d) / dbl(tol)
            << " tolerances off the face's reported plane (tolerance " << dbl(tol) << ")";
      }
    }
    scanPairs(std::is_same<A, Q>::value ? qBudget : 20000000LL, [&](int f, int v) {
      const A d = excess(f, v);
      MT_EXPECT(fails, d <= tol) << "vertex " << v << " " << str(P.vertex(v)) << " lies " << dbl(d) / dbl(tol)
                                 << " tolerances above face " << f << "'s reported plane (tolerance " << dbl(tol)
                                 << ")";
    });
  }

  // Geometry of the vertex loops themselves, in exact arithmetic. `exactGeometry`
  // (every exact-T shape, every fromPoints hull): faces exactly planar, corners strictly
  // convex, no vertex above a face, no two adjacent faces coplanar. Otherwise (fromMesh
  // with inexact T, which accepts faces within the tolerance of planar): corners convex
  // within the tolerance, and adjacent faces that are exactly coplanar must have been
  // merged.
  using N = typename LoopNum<T>::type;
  using N3 = std::array<N, 3>;
  const ExactCoordinates<T> exact(P.vertices());
  std::vector<N3> X(V), Nrm(F);
  std::vector<N> off(F);
  std::vector<char> planar(F, 1);
  for (int v = 0; v < V; ++v) X[v] = exact(P.vertex(v));
  for (int f = 0; f < F; ++f) {
    const auto loop = P.faceVertices(f);
    const int m = loop.size();
    Nrm[f] = {N(0), N(0), N(0)};
    for (int i = 1; i + 1 < m; ++i) {
      const N3 c = cross3(sub3(X[loop[i]], X[loop[0]]), sub3(X[loop[i + 1]], X[loop[0]]));
      for (int k = 0; k < 3; ++k) Nrm[f][k] += c[k];
    }
    off[f] = dot3(Nrm[f], X[loop[0]]);
    MT_EXPECT(fails, !isZero3(Nrm[f])) << "face " << f << " has zero area";
    for (int i = 0; i < m; ++i)
      if (dot3(Nrm[f], X[loop[i]]) != off[f]) planar[f] = 0;
    if (exactGeometry) {
      MT_EXPECT(fails, planar[f]) << "face " << f << " is not exactly planar";
    }
    for (int i = 0; i < m; ++i) {
      const N3& a = X[loop[i]];
      const N3& b = X[loop[(i + 1) % m]];
      const N3& c = X[loop[(i + 2) % m]];
      const N turn = dot3(cross3(sub3(b, a), sub3(c, a)), Nrm[f]);  // |c - a| |N| (distance of b from line ac)
      if (exactGeometry || mink::ScalarTraits<T>::isExact) {
        MT_EXPECT(fails, turn > N(0)) << "face " << f << ": corner at vertex " << loop[(i + 1) % m]
                                      << " is not strictly convex";
      } else if (!(turn > N(0))) {
        // Within the tolerance? Decide in Gmpq on the original coordinates.
        const auto qa = toQVec(P.vertex(loop[i])), qb = toQVec(P.vertex(loop[(i + 1) % m])),
                   qc = toQVec(P.vertex(loop[(i + 2) % m]));
        Vec3<Q> nq = Vec3<Q>::Zero();
        for (int j = 1; j + 1 < m; ++j)
          nq += (toQVec(P.vertex(loop[j])) - toQVec(P.vertex(loop[0])))
                    .cross(toQVec(P.vertex(loop[j + 1])) - toQVec(P.vertex(loop[0])));
        const Q tq = (qb - qa).cross(qc - qa).dot(nq);
        const Q tol = toQ(P.tolerance());
        MT_EXPECT(fails, tq * tq <= tol * tol * (qc - qa).squaredNorm() * nq.squaredNorm())
            << "face " << f << ": corner at vertex " << loop[(i + 1) % m] << " is reflex beyond the tolerance";
      }
    }
  }
  if (exactGeometry) {
    scanPairs(std::is_same<N, Q>::value ? 300000LL : 3000000LL, [&](int f, int v) {
      MT_EXPECT(fails, !(dot3(Nrm[f], X[v]) > off[f]))
          << "vertex " << v << " " << str(P.vertex(v)) << " lies above the plane of face " << f
          << " (not convex or not outward)";
    });
  }
  for (int e = 0; e < E; ++e) {
    const auto fg = P.edgeFaces(e);
    const int f = fg.first, g = fg.second;
    bool coplanar = planar[f] && planar[g] && isZero3(cross3(Nrm[f], Nrm[g]));
    for (int v : P.faceVertices(g)) coplanar = coplanar && dot3(Nrm[f], X[v]) == off[f];
    MT_EXPECT(fails, !coplanar) << "adjacent faces " << f << " and " << g << " are exactly coplanar (not merged)";
  }
}

template void expectValidPolyhedron<float>(const ConvexPolyhedron<float>&, const std::string&, bool);
template void expectValidPolyhedron<double>(const ConvexPolyhedron<double>&, const std::string&, bool);
template void expectValidPolyhedron<long double>(const ConvexPolyhedron<long double>&, const std::string&, bool);
template void expectValidPolyhedron<Q>(const ConvexPolyhedron<Q>&, const std::string&, bool);

// ---------------------------------------------------------------------------------
// Rejections: the exception is mink::InvalidInput, catchable as std::invalid_argument,
// and its message starts with "mink: " and contains every needle.

template <class Fn>
void expectInvalidInput(Fn&& fn, std::initializer_list<const char*> needles, const std::string& context) {
  SCOPED_TRACE(context);
  bool thrown = false;
  try {
    fn();
  } catch (const mink::InvalidInput& e) {
    thrown = true;
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("mink: ", 0), 0u) << msg;
    for (const char* needle : needles) EXPECT_PRED_FORMAT2(::testing::IsSubstring, needle, msg);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something other than mink::InvalidInput: " << e.what();
    return;
  }
  if (!thrown) {
    ADD_FAILURE() << "no exception";
    return;
  }
  bool asInvalidArgument = false;
  try {
    fn();
  } catch (const std::invalid_argument&) {
    asInvalidArgument = true;
  } catch (...) {
  }
  EXPECT_TRUE(asInvalidArgument) << "not catchable as std::invalid_argument";
}

// ---------------------------------------------------------------------------------
// Test shapes (vertex lists and CCW-from-outside face loops).

template <class T>
struct Mesh {
  std::vector<Vec3<T>> v;
  std::vector<std::vector<int>> f;
};

template <class T>
Vec3<T> P3(double x, double y, double z) {
  return Vec3<T>(T(x), T(y), T(z));
}

// Unit cube, vertex index x + 2y + 4z.
template <class T>
std::vector<Vec3<T>> cubeVertices(double lo = 0, double hi = 1) {
  std::vector<Vec3<T>> v;
  for (int i = 0; i < 8; ++i) v.push_back(P3<T>(i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo));
  return v;
}
inline std::vector<std::vector<int>> cubeQuads() {
  return {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
}
inline std::vector<std::vector<int>> triangulate(const std::vector<std::vector<int>>& faces) {
  std::vector<std::vector<int>> out;
  for (const auto& L : faces)
    for (std::size_t i = 1; i + 1 < L.size(); ++i) out.push_back({L[0], L[i], L[i + 1]});
  return out;
}
inline std::vector<std::vector<int>> flipped(std::vector<std::vector<int>> faces) {
  for (auto& L : faces) std::reverse(L.begin(), L.end());
  return faces;
}

// Orients each triangle so that its normal points away from `centre`.
template <class T>
std::vector<std::vector<int>> orientAway(const std::vector<Vec3<T>>& v, std::vector<std::vector<int>> tris,
                                         const Vec3<T>& centre) {
  for (auto& t : tris) {
    const Vec3<Q> a = toQVec(v[t[0]]), b = toQVec(v[t[1]]), c = toQVec(v[t[2]]);
    const Vec3<Q> o = toQVec(centre);
    if ((b - a).cross(c - a).dot(a - o) < Q(0)) std::swap(t[1], t[2]);
  }
  return tris;
}

template <class T>
Mesh<T> octahedron() {
  Mesh<T> m;
  m.v = {P3<T>(1, 0, 0), P3<T>(-1, 0, 0), P3<T>(0, 1, 0), P3<T>(0, -1, 0), P3<T>(0, 0, 1), P3<T>(0, 0, -1)};
  std::vector<std::vector<int>> tris;
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) tris.push_back({x, y, z});
  m.f = orientAway(m.v, tris, Vec3<T>(Vec3<T>::Zero()));
  return m;
}

// Icosahedron (0, +-1, +-t) and cyclic permutations with t = 1618/1000 (rational, close
// enough to the golden ratio that the 20 triangles stay the faces). Its faces are the
// triangles of vertices pairwise at squared distance ~4.
template <class T>
Mesh<T> icosahedron() {
  Mesh<T> m;
  const T t = T(1618) / T(1000);
  for (int s1 : {-1, 1})
    for (int s2 : {-1, 1}) {
      m.v.push_back(Vec3<T>(T(0), T(s1), T(s2) * t));
      m.v.push_back(Vec3<T>(T(s1), T(s2) * t, T(0)));
      m.v.push_back(Vec3<T>(T(s2) * t, T(0), T(s1)));
    }
  const int n = static_cast<int>(m.v.size());
  auto close = [&](int i, int j) {
    const double d = dbl((toQVec(m.v[i]) - toQVec(m.v[j])).squaredNorm());
    return std::abs(d - 4.0) < 0.1;
  };
  std::vector<std::vector<int>> tris;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        if (close(i, j) && close(j, k) && close(i, k)) tris.push_back({i, j, k});
  EXPECT_EQ(tris.size(), 20u);
  m.f = orientAway(m.v, tris, Vec3<T>(Vec3<T>::Zero()));
  return m;
}

template <class T>
Mesh<T> triangularPrism() {
  Mesh<T> m;
  m.v = {P3<T>(0, 0, 0), P3<T>(1, 0, 0), P3<T>(0, 1, 0), P3<T>(0, 0, 1), P3<T>(1, 0, 1), P3<T>(0, 1, 1)};
  m.f = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  return m;
}

// Canonical form of a face loop: rotated to start at its smallest index.
inline std::vector<int> canonical(std::vector<int> loop) {
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}
inline std::set<std::vector<int>> canonicalSet(const std::vector<std::vector<int>>& loops) {
  std::set<std::vector<int>> s;
  for (const auto& L : loops) s.insert(canonical(L));
  return s;
}
template <class T>
std::set<std::vector<int>> facesAsInputLoops(const ConvexPolyhedron<T>& P) {
  std::set<std::vector<int>> s;
  for (int f = 0; f < P.numFaces(); ++f) {
    std::vector<int> L;
    for (int v : P.faceVertices(f)) L.push_back(P.inputIndex(v));
    s.insert(canonical(L));
  }
  return s;
}
inline std::string loopsStr(const std::set<std::vector<int>>& s) {
  std::ostringstream os;
  for (const auto& L : s) {
    os << "{";
    for (std::size_t i = 0; i < L.size(); ++i) os << (i ? "," : "") << L[i];
    os << "} ";
  }
  return os.str();
}

// Builds the mesh, checks its structure, that every vertex is the input vertex it
// names, and that the faces are exactly `expected` (loops of input indices).
template <class T>
void expectMeshGives(const std::vector<Vec3<T>>& verts, const std::vector<std::vector<int>>& faces,
                     const std::vector<std::vector<int>>& expected, const std::string& context) {
  SCOPED_TRACE(context);
  try {
    const auto P = ConvexPolyhedron<T>::fromMesh(verts, faces);
    expectValidPolyhedron(P, context);
    for (int v = 0; v < P.numVertices(); ++v) {
      ASSERT_TRUE(P.inputIndex(v) >= 0 && P.inputIndex(v) < static_cast<int>(verts.size()));
      EXPECT_TRUE(P.vertex(v) == verts[P.inputIndex(v)]) << "vertex " << v;
    }
    const auto got = facesAsInputLoops(P);
    const auto want = canonicalSet(expected);
    EXPECT_EQ(got, want) << "got faces " << loopsStr(got) << "\nexpected " << loopsStr(want);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "fromMesh threw: " << e.what();
  }
}

struct ScalarNames {
  template <class T>
  static std::string GetName(int) {
    if (std::is_same<T, float>::value) return "float";
    if (std::is_same<T, double>::value) return "double";
    if (std::is_same<T, long double>::value) return "long_double";
    return "Gmpq";
  }
};
using Scalars = ::testing::Types<float, double, long double, Q>;

// ---------------------------------------------------------------------------------
// fromMesh: accepted shapes.

template <class T>
class FromMesh : public ::testing::Test {};
TYPED_TEST_SUITE(FromMesh, Scalars, ScalarNames);

TYPED_TEST(FromMesh, CubeAsQuads) {
  using T = TypeParam;
  expectMeshGives<T>(cubeVertices<T>(), cubeQuads(), cubeQuads(), "cube as 6 quads");
  // Shifted and scaled away from the origin: nothing may depend on the origin.
  expectMeshGives<T>(cubeVertices<T>(-7.5, 1024.25), cubeQuads(), cubeQuads(), "large cube as 6 quads");
}

TYPED_TEST(FromMesh, TriangulatedCubeMergesToQuads) {
  using T = TypeParam;
  expectMeshGives<T>(cubeVertices<T>(), triangulate(cubeQuads()), cubeQuads(), "cube as 12 triangles");
  // The other diagonal in every quad.
  std::vector<std::vector<int>> other;
  for (const auto& L : cubeQuads()) {
    other.push_back({L[1], L[2], L[3]});
    other.push_back({L[1], L[3], L[0]});
  }
  expectMeshGives<T>(cubeVertices<T>(), other, cubeQuads(), "cube as 12 triangles (other diagonals)");
}

TYPED_TEST(FromMesh, CubeWithFaceCentresMergesToQuads) {
  using T = TypeParam;
  // Every quad fanned around an extra vertex at its centre: 14 vertices, 24 triangles.
  auto v = cubeVertices<T>();
  std::vector<std::vector<int>> faces;
  for (const auto& L : cubeQuads()) {
    Vec3<T> c = (v[L[0]] + v[L[2]]) / T(2);
    const int ci = static_cast<int>(v.size());
    v.push_back(c);
    for (int i = 0; i < 4; ++i) faces.push_back({L[i], L[(i + 1) % 4], ci});
  }
  expectMeshGives<T>(v, faces, cubeQuads(), "cube with face centres");
}

TYPED_TEST(FromMesh, CubeWithEdgeMidpointsDropsThem) {
  using T = TypeParam;
  // Every edge split at its midpoint: faces are octagons with four straight angles; the
  // midpoints lie in two faces only, so they are not corners.
  auto v = cubeVertices<T>();
  std::map<std::pair<int, int>, int> mid;
  auto midpoint = [&](int a, int b) {
    const auto k = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = mid.find(k);
    if (it != mid.end()) return it->second;
    const int i = static_cast<int>(v.size());
    v.push_back((v[a] + v[b]) / T(2));
    mid[k] = i;
    return i;
  };
  std::vector<std::vector<int>> faces;
  for (const auto& L : cubeQuads()) {
    std::vector<int> oct;
    for (int i = 0; i < 4; ++i) {
      oct.push_back(L[i]);
      oct.push_back(midpoint(L[i], L[(i + 1) % 4]));
    }
    faces.push_back(oct);
  }
  ASSERT_EQ(v.size(), 20u);
  expectMeshGives<T>(v, faces, cubeQuads(), "cube with edge midpoints");
}

TYPED_TEST(FromMesh, Octahedron) {
  using T = TypeParam;
  const auto m = octahedron<T>();
  expectMeshGives<T>(m.v, m.f, m.f, "octahedron");
}

TYPED_TEST(FromMesh, Icosahedron) {
  using T = TypeParam;
  const auto m = icosahedron<T>();
  ASSERT_EQ(m.f.size(), 20u);
  expectMeshGives<T>(m.v, m.f, m.f, "icosahedron");
}

TYPED_TEST(FromMesh, Prism) {
  using T = TypeParam;
  const auto m = triangularPrism<T>();
  expectMeshGives<T>(m.v, m.f, m.f, "triangular prism");
  expectMeshGives<T>(m.v, triangulate(m.f), m.f, "triangulated triangular prism");
}

TYPED_TEST(FromMesh, UnreferencedVerticesAreIgnored) {
  using T = TypeParam;
  // Cube vertices at 1..8, unreferenced vertices around them that would break
  // convexity (or the extent) if they were used.
  std::vector<Vec3<T>> v = {P3<T>(100, 100, 100)};
  for (const auto& p : cubeVertices<T>()) v.push_back(p);
  v.push_back(P3<T>(-50, 0.5, 0.5));
  v.push_back(P3<T>(0.5, 0.5, 0.5));
  auto faces = cubeQuads();
  for (auto& L : faces)
    for (int& i : L) ++i;
  expectMeshGives<T>(v, faces, faces, "cube with unreferenced vertices");
  const auto P = ConvexPolyhedron<T>::fromMesh(v, faces);
  EXPECT_EQ(P.numVertices(), 8);
  EXPECT_TRUE(P.extent() == T(3)) << "extent must ignore unreferenced vertices, got " << dbl(P.extent());
}

/// fromMesh(v, f), after checking that its non-throwing twin agrees: tryFromMesh fails
/// with the very message fromMesh throws, or succeeds where fromMesh does.
template <class T>
std::function<void()> meshCall(std::vector<Vec3<T>> v, std::vector<std::vector<int>> f) {
  return [v, f] {
    const mink::Result<ConvexPolyhedron<T>> r = ConvexPolyhedron<T>::tryFromMesh(v, f);
    try {
      const ConvexPolyhedron<T> P = ConvexPolyhedron<T>::fromMesh(v, f);
      EXPECT_TRUE(r.ok()) << "tryFromMesh failed where fromMesh did not: " << r.error().message();
      if (r.ok()) {
        EXPECT_EQ(r.value().numFaces(), P.numFaces());
      }
    } catch (const mink::InvalidInput& e) {
      EXPECT_FALSE(r.ok()) << "tryFromMesh accepted what fromMesh rejects: " << e.what();
      EXPECT_EQ(r.error().message(), std::string(e.what()));
      throw;
    }
  };
}

// fromMesh with inexact T accepts faces within the tolerance of planar and vertices
// within it above neighbouring face planes; faces merge only when exactly coplanar.
TEST(FromMeshTolerance, NoisyCube) {
  const unsigned seed = 5001u;
  std::mt19937 rng(seed);
  // Corners moved by up to 1e-15 (default tolerance here: 64 eps * 3 = 4.3e-14).
  std::uniform_real_distribution<double> noise(-1e-15, 1e-15);
  auto v = cubeVertices<double>();
  for (auto& p : v)
    for (int k = 0; k < 3; ++k) p[k] += noise(rng);
  {
    SCOPED_TRACE("noisy cube as quads (seed 5001)");
    const auto P = ConvexPolyhedron<double>::fromMesh(v, cubeQuads());
    expectValidPolyhedron(P, "noisy cube as quads", /*exactGeometry=*/false);
    EXPECT_EQ(facesAsInputLoops(P), canonicalSet(cubeQuads()));
  }
  {
    // The two triangles of a noisy quad are not exactly coplanar: they stay apart.
    SCOPED_TRACE("noisy cube as triangles (seed 5001)");
    const auto P = ConvexPolyhedron<double>::fromMesh(v, triangulate(cubeQuads()));
    expectValidPolyhedron(P, "noisy cube as triangles", /*exactGeometry=*/false);
    EXPECT_EQ(facesAsInputLoops(P), canonicalSet(triangulate(cubeQuads())));
  }
  // Noise far beyond the default tolerance: rejected, unless the tolerance is raised.
  std::uniform_real_distribution<double> big(-1e-6, 1e-6);
  auto w = cubeVertices<double>();
  for (auto& p : w)
    for (int k = 0; k < 3; ++k) p[k] += big(rng);
  expectInvalidInput(meshCall<double>(w, cubeQuads()), {"not planar"}, "cube with 1e-6 noise as quads (seed 5001)");
  mink::HullOptions<double> loose;
  loose.tolerance = 1e-5;
  try {
    const auto P = ConvexPolyhedron<double>::fromMesh(w, cubeQuads(), loose);
    EXPECT_EQ(P.tolerance(), 1e-5);
    expectValidPolyhedron(P, "cube with 1e-6 noise, tolerance 1e-5", /*exactGeometry=*/false);
    EXPECT_EQ(facesAsInputLoops(P), canonicalSet(cubeQuads()));
  } catch (const std::exception& e) {
    ADD_FAILURE() << "cube with 1e-6 noise, tolerance 1e-5: " << e.what();
  }
}

// ---------------------------------------------------------------------------------
// fromMesh: rejections.

template <class T>
class FromMeshRejects : public ::testing::Test {};
TYPED_TEST_SUITE(FromMeshRejects, Scalars, ScalarNames);

TYPED_TEST(FromMeshRejects, Empty) {
  using T = TypeParam;
  expectInvalidInput(meshCall<T>({}, cubeQuads()), {"no vertices"}, "no vertices");
  expectInvalidInput(meshCall<T>({}, {}), {"no vertices"}, "no vertices, no faces");
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), {}), {"no faces"}, "no faces");
}

TYPED_TEST(FromMeshRejects, NonFiniteCoordinate) {
  using T = TypeParam;
  if constexpr (!mink::ScalarTraits<T>::isExact) {
    auto v = cubeVertices<T>();
    v[5][1] = std::numeric_limits<T>::quiet_NaN();
    expectInvalidInput(meshCall<T>(v, cubeQuads()), {"vertex 5", "non-finite"}, "NaN at vertex 5");
    v = cubeVertices<T>();
    v[2][2] = -std::numeric_limits<T>::infinity();
    expectInvalidInput(meshCall<T>(v, cubeQuads()), {"vertex 2", "non-finite"}, "-Inf at vertex 2");
    v = cubeVertices<T>();
    v[7][0] = std::numeric_limits<T>::infinity();
    expectInvalidInput(meshCall<T>(v, triangulate(cubeQuads())), {"vertex 7", "non-finite"}, "Inf at vertex 7");
  }
}

TYPED_TEST(FromMeshRejects, IndexOutOfRange) {
  using T = TypeParam;
  auto f = cubeQuads();
  f[3][2] = 42;
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"face 3", "42", "out of range"}, "index 42 in face 3");
  f = cubeQuads();
  f[4][0] = -1;
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"face 4", "out of range"}, "index -1 in face 4");
  f = cubeQuads();
  f[5][1] = 8;
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"face 5", "out of range"}, "index 8 (= #V) in face 5");
}

TYPED_TEST(FromMeshRejects, DegenerateFaces) {
  using T = TypeParam;
  auto f = cubeQuads();
  f[2] = {0, 1};
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"face 2", "at least 3"}, "face with 2 vertices");
  f = cubeQuads();
  f[0] = {};
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"face 0", "at least 3"}, "empty face");
  f = cubeQuads();
  f[1] = {4, 5, 4, 6};
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"face 1", "repeats vertex 4"}, "face repeating a vertex");
  // A closed sphere-like mesh whose face 1 is a zero-area triangle (A, M, B collinear).
  const std::vector<Vec3<T>> v = {P3<T>(0, 0, 0), P3<T>(2, 0, 0), P3<T>(1, 0, 0), P3<T>(1, 2, 0),
                                  P3<T>(1, 1, 2)};  // A B M C D
  const int A = 0, B = 1, M = 2, C = 3, D = 4;
  const std::vector<std::vector<int>> sliver = {{A, B, C}, {A, M, B}, {M, A, D}, {B, M, D}, {C, B, D}, {A, C, D}};
  expectInvalidInput(meshCall<T>(v, sliver), {"face 1", "zero area"}, "zero-area face");
}

TYPED_TEST(FromMeshRejects, OpenMesh) {
  using T = TypeParam;
  auto f = cubeQuads();
  f.erase(f.begin() + 2);
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"not closed"}, "cube without a face");
  auto t = triangulate(cubeQuads());
  t.pop_back();
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), t), {"not closed"}, "triangulated cube without a triangle");
}

TYPED_TEST(FromMeshRejects, NonManifoldOrInconsistent) {
  using T = TypeParam;
  // Edge 0-1 in a third face.
  auto f = triangulate(cubeQuads());
  f.push_back({0, 1, 7});
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"used twice in the same direction"},
                     "edge shared by three faces");
  // One face flipped.
  f = cubeQuads();
  std::reverse(f[3].begin(), f[3].end());
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"inconsistent orientation"}, "one face flipped");
  // A face given twice.
  f = cubeQuads();
  f.push_back(f[0]);
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), f), {"used twice in the same direction"}, "duplicate face");
}

TYPED_TEST(FromMeshRejects, InwardOrientation) {
  using T = TypeParam;
  expectInvalidInput(meshCall<T>(cubeVertices<T>(), flipped(cubeQuads())), {"oriented inward"}, "cube inside out");
  const auto m = icosahedron<T>();
  expectInvalidInput(meshCall<T>(m.v, flipped(m.f)), {"oriented inward"}, "icosahedron inside out");
}

TYPED_TEST(FromMeshRejects, NonPlanarFace) {
  using T = TypeParam;
  auto v = cubeVertices<T>();
  v[7] = P3<T>(1, 1, 1.25);  // lifts one corner of the top quad (and of two side quads)
  expectInvalidInput(meshCall<T>(v, cubeQuads()), {"not planar"}, "cube with a lifted corner");
  // A twisted top of a prism-like box whose sides are triangulated: only the top quad
  // is non-planar.
  v = cubeVertices<T>();
  v[6] = P3<T>(0, 1, 1.125);
  auto f = cubeQuads();
  std::vector<std::vector<int>> g = {f[1]};  // top quad 4 5 7 6 kept whole
  for (int i : {0, 2, 3, 4, 5})
    for (const auto& t : triangulate({f[i]})) g.push_back(t);
  expectInvalidInput(meshCall<T>(v, g), {"face 0", "not planar"}, "non-planar top quad");
}

TYPED_TEST(FromMeshRejects, NonConvex) {
  using T = TypeParam;
  // Corner 7 pushed inward (triangulated so that every face stays planar).
  auto v = cubeVertices<T>();
  v[7] = P3<T>(0.625, 0.625, 0.625);
  expectInvalidInput(meshCall<T>(v, triangulate(cubeQuads())), {"not convex"}, "cube with a dent");
  // L-shaped prism (two planar hexagons, six quads).
  const double L[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::vector<Vec3<T>> w;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 6; ++i) w.push_back(P3<T>(L[i][0], L[i][1], z));
  std::vector<std::vector<int>> f = {{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}};
  for (int i = 0; i < 6; ++i) f.push_back({i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6});
  expectInvalidInput(meshCall<T>(w, f), {"not convex"}, "L-shaped prism");
  expectInvalidInput(meshCall<T>(w, triangulate(f)), {"not convex"}, "triangulated L-shaped prism");
}

TYPED_TEST(FromMeshRejects, NotConnected) {
  using T = TypeParam;
  auto v = cubeVertices<T>();
  for (const auto& p : cubeVertices<T>(3, 4)) v.push_back(p);
  auto f = cubeQuads();
  for (auto L : cubeQuads()) {
    for (int& i : L) i += 8;
    f.push_back(L);
  }
  expectInvalidInput(meshCall<T>(v, f), {"not connected"}, "two disjoint cubes");
}

TYPED_TEST(FromMeshRejects, Torus) {
  using T = TypeParam;
  // Square torus: 4 corners around z times a square tube; 16 vertices, 16 planar
  // trapezoids, Euler characteristic 0.
  const int dir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const int rz[4][2] = {{2, -1}, {4, -1}, {4, 1}, {2, 1}};
  std::vector<Vec3<T>> v;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v.push_back(P3<T>(rz[j][0] * dir[i][0], rz[j][0] * dir[i][1], rz[j][1]));
  auto id = [](int i, int j) { return (i % 4) * 4 + (j % 4); };
  std::vector<std::vector<int>> f;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) f.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  expectInvalidInput(meshCall<T>(v, f), {"not a topological sphere"}, "square torus");
  expectInvalidInput(meshCall<T>(v, flipped(f)), {"not a topological sphere"}, "square torus, flipped");
}

// ---------------------------------------------------------------------------------
// fromPoints: rejections.

template <class T>
class FromPointsRejects : public ::testing::Test {};
TYPED_TEST_SUITE(FromPointsRejects, Scalars, ScalarNames);

template <class T>
std::function<void()> hullCall(std::vector<Vec3<T>> p) {
  return [p] { (void)ConvexPolyhedron<T>::fromPoints(p); };
}

TYPED_TEST(FromPointsRejects, TooFewPoints) {
  using T = TypeParam;
  expectInvalidInput(hullCall<T>({}), {"no points"}, "empty");
  expectInvalidInput(hullCall<T>({P3<T>(0, 0, 0), P3<T>(1, 0, 0), P3<T>(0, 1, 0)}), {"at least 4", "got 3"},
                     "3 points");
  expectInvalidInput(hullCall<T>({P3<T>(0, 0, 0)}), {"at least 4", "got 1"}, "1 point");
}

TYPED_TEST(FromPointsRejects, NonFinite) {
  using T = TypeParam;
  if constexpr (!mink::ScalarTraits<T>::isExact) {
    std::vector<Vec3<T>> p;
    for (int i = 0; i < 10; ++i) p.push_back(P3<T>(i % 2, (i / 2) % 2, i / 4));
    auto q = p;
    q[5][2] = std::numeric_limits<T>::quiet_NaN();
    expectInvalidInput(hullCall<T>(q), {"point 5", "non-finite"}, "NaN at point 5");
    q = p;
    q[0][0] = std::numeric_limits<T>::infinity();
    expectInvalidInput(hullCall<T>(q), {"point 0", "non-finite"}, "Inf at point 0");
    q = p;
    q[9][1] = -std::numeric_limits<T>::infinity();
    expectInvalidInput(hullCall<T>(q), {"point 9", "non-finite"}, "-Inf at point 9");
  }
}

TYPED_TEST(FromPointsRejects, Degenerate) {
  using T = TypeParam;
  std::mt19937 rng(20240601u);
  std::uniform_int_distribution<int> u(-50, 50);
  std::vector<Vec3<T>> same(12, P3<T>(0.5, -3, 7));
  expectInvalidInput(hullCall<T>(same), {"coincide"}, "all points identical");
  std::vector<Vec3<T>> line;
  for (int i = 0; i < 40; ++i) {
    const int s = u(rng);
    line.push_back(P3<T>(1 + s, 2 - 2 * s, 3 * s));
  }
  expectInvalidInput(hullCall<T>(line), {"collinear"}, "collinear (seed 20240601)");
  std::vector<Vec3<T>> plane;
  for (int i = 0; i < 60; ++i) {
    const int a = u(rng), b = u(rng);
    plane.push_back(P3<T>(a, b, 5 - a - b));  // x + y + z = 5
  }
  expectInvalidInput(hullCall<T>(plane), {"coplanar"}, "coplanar x+y+z=5 (seed 20240601)");
  std::vector<Vec3<T>> square = {P3<T>(0, 0, 0), P3<T>(1, 0, 0), P3<T>(1, 1, 0), P3<T>(0, 1, 0)};
  expectInvalidInput(hullCall<T>(square), {"coplanar"}, "unit square");
}

// ---------------------------------------------------------------------------------
// HullOptions: an explicit tolerance is used as given; bad tolerances are rejected.

// ---------------------------------------------------------------------------------
// fromPoints / fromMesh on another scalar's coordinates: the same shape as converting
// first. Reference: the hull of the converted points, built by the ordinary overload;
// float to double and double to Gmpq are exact conversions, so vertices must be equal.

TEST(FromOtherScalar, FloatPointsGiveTheHullOfTheirDoubleValues) {
  std::mt19937 rng(20261203u);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  std::vector<Vec3<float>> pf;
  for (int i = 0; i < 200; ++i) pf.emplace_back(u(rng), u(rng), u(rng));
  std::vector<Vec3<double>> pd;
  for (const auto& p : pf) pd.push_back(p.cast<double>());
  const auto a = ConvexPolyhedron<double>::fromPoints(pf);
  const auto b = ConvexPolyhedron<double>::fromPoints(pd);
  ASSERT_EQ(a.numVertices(), b.numVertices());
  ASSERT_EQ(a.numFaces(), b.numFaces());
  for (int v = 0; v < a.numVertices(); ++v) {
    EXPECT_TRUE(a.vertex(v) == b.vertex(v)) << "vertex " << v;
    EXPECT_EQ(a.inputIndex(v), b.inputIndex(v)) << "vertex " << v;
  }
  // Rejections still name the input index.
  auto bad = pf;
  bad[17][1] = std::numeric_limits<float>::quiet_NaN();
  expectInvalidInput([&] { (void)ConvexPolyhedron<double>::fromPoints(bad); }, {"point 17", "non-finite"},
                     "float NaN at point 17");
}

TEST(FromOtherScalar, DoublePointsGiveAnExactShapeAndFloatMeshesADoubleOne) {
  // Exactly representable non-dyadic-free numbers: 0.1 is not 1/10 in double, and the
  // exact shape must hold the double's value, not 1/10.
  const std::vector<Vec3<double>> box = {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}, {0.1, 0.1, 0},
                                         {0, 0, 0.3}, {0.1, 0, 0.3}, {0, 0.1, 0.3}, {0.1, 0.1, 0.3}};
  const auto e = ConvexPolyhedron<Q>::fromPoints(box);
  ASSERT_EQ(e.numVertices(), 8);
  ASSERT_EQ(e.numFaces(), 6);
  for (int v = 0; v < 8; ++v) {
    const auto& x = box[static_cast<std::size_t>(e.inputIndex(v))];
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(e.vertex(v)[k] == Q(x[k])) << "vertex " << v << " k=" << k;
  }
  EXPECT_FALSE(Q(0.1) == Q(1, 10));

  const std::vector<Vec3<float>> cube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<std::vector<int>> quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                               {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const auto m = ConvexPolyhedron<double>::fromMesh(cube, quads);
  EXPECT_EQ(m.numVertices(), 8);
  EXPECT_EQ(m.numFaces(), 6);
  auto inward = quads;
  for (auto& f : inward) std::reverse(f.begin(), f.end());
  EXPECT_THROW((void)ConvexPolyhedron<double>::fromMesh(cube, inward), mink::InvalidInput);
}

// worldBounds against a scan of every placed vertex: every vertex inside, and each side
// within the padding of the extreme vertex along it (exact for Gmpq).
TEST(WorldBounds, HoldEveryPlacedVertexAndTouchTheExtremes) {
  std::mt19937 rng(20261205u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec3<double>> pts;
    const int n = 8 + trial * 10;
    for (int i = 0; i < n; ++i) pts.emplace_back(u(rng) * 3, u(rng), u(rng) * 0.2);
    const auto P = ConvexPolyhedron<double>::fromPoints(pts);
    mink::Pose<double> pose;
    pose.rotation = Eigen::AngleAxisd(3.0 * u(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    pose.translation = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 100.0;
    const auto [lo, hi] = P.worldBounds(pose);
    Vec3<double> scanLo = Vec3<double>::Constant(1e300), scanHi = Vec3<double>::Constant(-1e300);
    for (const auto& v : P.vertices()) {
      const Vec3<double> w = pose.apply(v);
      scanLo = scanLo.cwiseMin(w);
      scanHi = scanHi.cwiseMax(w);
    }
    for (int i = 0; i < 3; ++i) {
      EXPECT_LE(lo[i], scanLo[i]) << "trial " << trial << " axis " << i;
      EXPECT_GE(hi[i], scanHi[i]) << "trial " << trial << " axis " << i;
      EXPECT_LE(scanLo[i] - lo[i], 1e-12) << "trial " << trial << " axis " << i;
      EXPECT_LE(hi[i] - scanHi[i], 1e-12) << "trial " << trial << " axis " << i;
    }
  }
  // Exact: a unit cube turned a quarter about z and moved: the box is exact.
  std::vector<Vec3<Q>> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(Q((i & 1) ? 1 : 0), Q((i & 2) ? 2 : 0), Q((i & 4) ? 3 : 0));
  const auto C = ConvexPolyhedron<Q>::fromPoints(cube);
  mink::Pose<Q> pose;
  pose.rotation << Q(0), Q(-1), Q(0), Q(1), Q(0), Q(0), Q(0), Q(0), Q(1);
  pose.translation = Vec3<Q>(Q(1, 2), Q(0), Q(-1));
  const auto [lo, hi] = C.worldBounds(pose);
  EXPECT_TRUE(lo == Vec3<Q>(Q(-3, 2), Q(0), Q(-1)));
  EXPECT_TRUE(hi == Vec3<Q>(Q(1, 2), Q(1), Q(2)));
}

TEST(HullOptions, ExplicitToleranceRejectsNearlyDegenerateInput) {
  // The tolerance only decides what counts as degenerate input; the hull is exact.
  const unsigned seed = 6001u;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), off(-1e-6, 1e-6);
  std::vector<Vec3<double>> slab, needle, blob;
  for (int i = 0; i < 200; ++i) {
    slab.emplace_back(u(rng), u(rng), 0.5 + off(rng));          // within 1e-6 of z = 0.5
    const double t = u(rng);
    needle.emplace_back(t, 2 * t + off(rng), -t + off(rng));     // within ~1.4e-6 of a line
    blob.emplace_back(3 + off(rng), off(rng), -1 + off(rng));    // within ~1.7e-6 of a point
  }
  mink::HullOptions<double> loose;
  loose.tolerance = 1e-5;
  expectInvalidInput([&] { (void)ConvexPolyhedron<double>::fromPoints(slab, loose); }, {"coplanar"},
                     "slab 1e-6 thick, tolerance 1e-5 (seed 6001)");
  expectInvalidInput([&] { (void)ConvexPolyhedron<double>::fromPoints(needle, loose); }, {"collinear"},
                     "needle 1e-6 thick, tolerance 1e-5 (seed 6001)");
  expectInvalidInput([&] { (void)ConvexPolyhedron<double>::fromPoints(blob, loose); }, {"coincide"},
                     "blob 1e-6 wide, tolerance 1e-5 (seed 6001)");
  // With the default tolerance (~5e-14 here) they are genuine, if thin, solids
  // (their structure is checked in FacePlanes.ThinSolids).
  for (const auto* pts : {&slab, &needle, &blob})
    EXPECT_NO_THROW((void)ConvexPolyhedron<double>::fromPoints(*pts)) << "thin solid, default tolerance (seed 6001)";
}

// Thin solids (the inputs above): exact hulls whose faces are slivers; every check of
// expectValidPolyhedron, including that each reported plane passes within the
// tolerance of its face's vertices.
TEST(FacePlanes, ThinSolids) {
  const unsigned seed = 6001u;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), off(-1e-6, 1e-6);
  std::vector<Vec3<double>> slab, needle, blob;
  for (int i = 0; i < 200; ++i) {
    slab.emplace_back(u(rng), u(rng), 0.5 + off(rng));
    const double t = u(rng);
    needle.emplace_back(t, 2 * t + off(rng), -t + off(rng));
    blob.emplace_back(3 + off(rng), off(rng), -1 + off(rng));
  }
  const char* names[3] = {"slab 2e-6 thick", "needle 2e-6 thick", "blob 2e-6 wide"};
  int i = 0;
  for (const auto* pts : {&slab, &needle, &blob}) {
    const std::string name = std::string(names[i++]) + " (seed 6001)";
    try {
      expectValidPolyhedron(ConvexPolyhedron<double>::fromPoints(*pts), name);
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << ": " << e.what();
    }
  }
}

// Reported planes of sliver faces: a needle-like tetrahedron (4 points within ~1e-6
// of the line x = t (1, 2, -1), shrunk from the needle above). The hull is exact; each
// face's reported (normal, offset) must still pass within the tolerance of the face's
// own vertices, which the exact plane rounded to double would (error ~ eps |x|).
TEST(FacePlanes, SliverFacesOfANeedle) {
  const std::vector<Vec3<double>> p = {
      Vec3<double>(-0.62522322948492903, -1.2504461579921056, 0.62522313042961608),
      Vec3<double>(0.57117365374440121, 1.1423466839668419, -0.5711735990184732),
      Vec3<double>(-0.15659529628699043, -0.31318984653865056, 0.15659442947951466),
      Vec3<double>(-0.66245829605557272, -1.3249165141138075, 0.66245741443753903)};
  const auto P = ConvexPolyhedron<double>::fromPoints(p);
  ASSERT_EQ(P.numVertices(), 4);
  ASSERT_EQ(P.numFaces(), 4);
  const Q tol = toQ(P.tolerance());
  for (int f = 0; f < P.numFaces(); ++f) {
    const Vec3<Q> n = toQVec(P.faceNormal(f));
    for (int v : P.faceVertices(f)) {
      const Q d = n.dot(toQVec(P.vertex(v))) - toQ(P.faceOffset(f));
      EXPECT_TRUE(CGAL::abs(d) <= tol) << "face " << f << ": vertex " << v << " is " << dbl(d) << " ("
                                   << dbl(d / tol) << " tolerances) off the reported plane";
    }
  }
}

TEST(HullOptions, BadToleranceRejected) {
  mink::HullOptions<Q> exact;
  exact.tolerance = Q(1, 1000);
  expectInvalidInput([&] { (void)ConvexPolyhedron<Q>::fromPoints(cubeVertices<Q>(), exact); },
                     {"positive tolerance"}, "fromPoints, Gmpq with tolerance 1/1000");
  expectInvalidInput([&] { (void)ConvexPolyhedron<Q>::fromMesh(cubeVertices<Q>(), cubeQuads(), exact); },
                     {"positive tolerance"}, "fromMesh, Gmpq with tolerance 1/1000");
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    mink::HullOptions<double> options;
    options.tolerance = bad;
    expectInvalidInput([&] { (void)ConvexPolyhedron<double>::fromPoints(cubeVertices<double>(), options); },
                       {"tolerance is not finite"}, "fromPoints, tolerance " + std::to_string(bad));
    expectInvalidInput([&] { (void)ConvexPolyhedron<double>::fromMesh(cubeVertices<double>(), cubeQuads(), options); },
                       {"tolerance is not finite"}, "fromMesh, tolerance " + std::to_string(bad));
  }
  // Exact scalars with an explicit zero tolerance are fine.
  mink::HullOptions<Q> zero;
  zero.tolerance = Q(0);
  EXPECT_NO_THROW((void)ConvexPolyhedron<Q>::fromPoints(cubeVertices<Q>(), zero));
}

// ---------------------------------------------------------------------------------
// Support: support(d, hint) and supportBruteForce(d) against a brute-force scan.

template <class T>
class Support : public ::testing::Test {};
TYPED_TEST_SUITE(Support, Scalars, ScalarNames);

template <class T>
double epsilonOf() {
  if constexpr (mink::ScalarTraits<T>::isExact) {
    return 0.0;
  } else {
    return static_cast<double>(std::numeric_limits<T>::epsilon());
  }
}

// Brute-force reference for support queries on P. Values are exact (Gmpq) for long
// double and exact T; for float and double they are evaluated in long double, whose
// rounding (2^-64 relative per product) is far below the bound used for them, and
// exact for small-integer data.
template <class T>
class SupportReference {
 public:
  using A = typename AccOf<T>::type;
  explicit SupportReference(const ConvexPolyhedron<T>& P) : P_(P), maxAbs_(0) {
    for (int v = 0; v < P.numVertices(); ++v) {
      X_.push_back(toAcc3<A>(P.vertex(v)));
      for (int k = 0; k < 3; ++k) maxAbs_ = std::max(maxAbs_, X_.back()[k] < A(0) ? A(-X_.back()[k]) : X_.back()[k]);
    }
  }

  // Checks support(d, h) for every hint h and supportBruteForce(d). Exact T, or
  // `exactDots` (every dot product exact in T): support's value is the maximum and
  // supportBruteForce is the lowest-index maximiser. Otherwise both are within
  // 64 eps |d|_1 max|x| of the maximum: each dot product in T is off by at most
  // 3 eps |d|_1 max|x|, and the hill-climb may stop where a neighbour is better by
  // less than the rounding.
  template <class Context>
  void check(const Vec3<T>& d, std::initializer_list<int> hints, bool exactDots, const Context& context,
             Failures& fails) const {
    const int V = P_.numVertices();
    const auto da = toAcc3<A>(d);
    A best = dot3(da, X_[0]);
    int arg = 0;
    for (int v = 1; v < V; ++v) {
      const A val = dot3(da, X_[v]);
      if (val > best) {
        best = val;
        arg = v;
      }
    }
    const bool exact = mink::ScalarTraits<T>::isExact || exactDots;
    auto absA = [](const A& x) { return x < A(0) ? A(-x) : x; };
    const A bound = exact ? A(0) : A(64 * epsilonOf<T>()) * (absA(da[0]) + absA(da[1]) + absA(da[2])) * maxAbs_;
    for (int h : hints) {
      const int sv = P_.support(d, h);
      if (sv < 0 || sv >= V) {
        MT_EXPECT(fails, false) << context() << ": support(d, " << h << ") = " << sv << " out of range";
        continue;
      }
      const A gap = best - dot3(da, X_[sv]);
      MT_EXPECT(fails, exact ? gap == A(0) : gap <= bound)
          << context() << ": support(d, " << h << ") = " << sv << " is short of the maximum (at " << arg << ") by "
          << dbl(gap) << (exact ? "" : " > bound ") << (exact ? 0.0 : dbl(bound));
    }
    const int b = P_.supportBruteForce(d);
    if (b < 0 || b >= V) {
      MT_EXPECT(fails, false) << context() << ": supportBruteForce = " << b << " out of range";
      return;
    }
    if (exact) {
      MT_EXPECT(fails, b == arg) << context() << ": supportBruteForce = " << b << ", lowest-index maximiser is " << arg;
    } else {
      MT_EXPECT(fails, best - dot3(da, X_[b]) <= bound)
          << context() << ": supportBruteForce = " << b << " is short of the maximum by " << dbl(best - dot3(da, X_[b]));
    }
  }

 private:
  const ConvexPolyhedron<T>& P_;
  std::vector<std::array<A, 3>> X_;
  A maxAbs_;
};

// Gaussian direction; for exact T rounded to integers (times 1e6) to keep Gmpq cheap.
template <class T>
Vec3<T> randomDirection(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  if constexpr (mink::ScalarTraits<T>::isExact) {
    return Vec3<T>(T(std::lround(1e6 * g(rng))), T(std::lround(1e6 * g(rng))), T(std::lround(1e6 * g(rng))));
  } else {
    return Vec3<T>(T(g(rng)), T(g(rng)), T(g(rng)));
  }
}

TYPED_TEST(Support, RandomHullRandomDirections) {
  using T = TypeParam;
  const unsigned seed = 7001u;
  std::mt19937 rng(seed);
  // 60 points on a sphere of radius 3 around (1, -2, 0.5): all are hull vertices.
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 60; ++i) {
    std::normal_distribution<double> g(0.0, 1.0);
    double x = g(rng), y = g(rng), z = g(rng);
    const double r = std::sqrt(x * x + y * y + z * z);
    pts.push_back(P3<T>(1 + 3 * x / r, -2 + 3 * y / r, 0.5 + 3 * z / r));
  }
  const auto P = ConvexPolyhedron<T>::fromPoints(pts);
  expectValidPolyhedron(P, "60 points on a sphere, seed 7001");
  const SupportReference<T> ref(P);
  std::uniform_int_distribution<int> hint(0, P.numVertices() - 1);
  Failures fails;
  int warm = 0;
  for (int k = 0; k < 10000; ++k) {
    const Vec3<T> d = randomDirection<T>(rng);
    // A random hint and a warm start from the previous answer.
    ref.check(d, {hint(rng), warm}, false,
              [&] { return "seed " + std::to_string(seed) + " direction #" + std::to_string(k) + " " + str(d); }, fails);
    warm = P.support(d, warm);
  }
}

// Two hull corners 2^-1022 apart (fuzzer, fuzz/regressions/support_across_an_edge_below_rounding):
// the values d . v of the two are equal in floating point, and the climb stopped at the
// one whose only way up is the tiny edge (0.13 where the maximum is 0.34), so mdd()
// built an FV face on a non-supporting vertex and answered a point 0.4 inside M.
TEST(SupportDouble, EdgeShorterThanTheRounding) {
  using T = double;
  const unsigned seed = 7004u;
  std::mt19937 rng(seed);
  const std::vector<Vec3<T>> pts = {P3<T>(0, -1, 1), P3<T>(0x1p-1022, -1, 1), P3<T>(1, 0.5, 1),
                                    P3<T>(1, 0.5, 0.5), P3<T>(0.5, 1, 0.5), P3<T>(-2, 0, 0)};
  const auto P = ConvexPolyhedron<T>::fromPoints(pts);
  ASSERT_EQ(P.numVertices(), 6);
  const SupportReference<T> ref(P);
  Failures fails;
  for (int k = 0; k < 5000; ++k) {
    const Vec3<T> d = randomDirection<T>(rng);
    for (int h = 0; h < P.numVertices(); ++h)
      ref.check(d, {h}, false,
                [&] { return "seed " + std::to_string(seed) + " direction #" + std::to_string(k) + " " + str(d); },
                fails);
  }
}

TYPED_TEST(Support, BoxTies) {
  using T = TypeParam;
  const unsigned seed = 7002u;
  std::mt19937 rng(seed);
  // Box [-1, 2] x [0, 3] x [-2, 5]: integer coordinates and integer directions keep
  // every dot product exact in every T, so ties are real ties.
  auto v = cubeVertices<T>();
  for (int i = 0; i < 8; ++i) v[i] = P3<T>(i & 1 ? 2 : -1, i & 2 ? 3 : 0, i & 4 ? 5 : -2);
  for (const auto& faces : {cubeQuads(), triangulate(cubeQuads())}) {
    const auto P = ConvexPolyhedron<T>::fromMesh(v, faces);
    expectValidPolyhedron(P, "box");
    ASSERT_EQ(P.numVertices(), 8);
    const SupportReference<T> ref(P);
    Failures fails;
    std::uniform_int_distribution<int> small(-3, 3);
    // Axis, edge-diagonal and corner-diagonal directions, scaled, from every hint.
    int count = 0;
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c) {
          if (a == 0 && b == 0 && c == 0) continue;
          for (int scale : {1, 2, 7}) {
            const Vec3<T> d(T(a * scale), T(b * scale), T(c * scale));
            ref.check(d, {0, 1, 2, 3, 4, 5, 6, 7}, true, [&] { return "box direction " + str(d); }, fails);
            count += 8;
          }
        }
    // Random small-integer directions (many with zero components).
    for (int k = 0; k < 3000; ++k, ++count) {
      Vec3<T> d(T(small(rng)), T(small(rng)), T(small(rng)));
      if (d == Vec3<T>::Zero()) d[0] = T(1);
      ref.check(d, {k % 8}, true,
                [&] { return "seed " + std::to_string(seed) + " box direction #" + std::to_string(k) + " " + str(d); },
                fails);
    }
    EXPECT_GT(count, 3500);
  }
}

TYPED_TEST(Support, RotatedBoxAndIcosahedron) {
  using T = TypeParam;
  const unsigned seed = 7003u;
  std::mt19937 rng(seed);
  Failures fails;
  // Icosahedron: random directions.
  {
    const auto m = icosahedron<T>();
    const auto P = ConvexPolyhedron<T>::fromMesh(m.v, m.f);
    const SupportReference<T> ref(P);
    std::uniform_int_distribution<int> hint(0, P.numVertices() - 1);
    for (int k = 0; k < 2000; ++k) {
      const Vec3<T> d = randomDirection<T>(rng);
      ref.check(d, {hint(rng)}, false,
                [&] { return "seed " + std::to_string(seed) + " icosahedron direction #" + std::to_string(k); }, fails);
    }
  }
  // Box rotated by a rational rotation (quaternion (1, 2, 3, 4) / 30): exact only for
  // exact T, where directions along the rotated axes give exact ties.
  if constexpr (mink::ScalarTraits<T>::isExact) {
    const Q w(1), x(2), y(3), z(4), s(30);
    Eigen::Matrix<Q, 3, 3> R;
    R << w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y),  //
        2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x),   //
        2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z;
    R /= s;
    ASSERT_TRUE(R * R.transpose() == (Eigen::Matrix<Q, 3, 3>::Identity()));
    std::vector<Vec3<T>> v;
    for (int i = 0; i < 8; ++i)
      v.push_back(R * Vec3<Q>(Q(i & 1 ? 1 : -1), Q(i & 2 ? 2 : -2), Q(i & 4 ? 3 : -3)) + Vec3<Q>(Q(1, 3), Q(0), Q(-5)));
    const auto P = ConvexPolyhedron<T>::fromMesh(v, triangulate(cubeQuads()));
    expectValidPolyhedron(P, "rotated box");
    ASSERT_EQ(P.numVertices(), 8);
    ASSERT_EQ(P.numFaces(), 6);
    const SupportReference<T> ref(P);
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c) {
          if (a == 0 && b == 0 && c == 0) continue;
          const Vec3<T> d = R * Vec3<Q>(Q(a), Q(b), Q(c));
          ref.check(d, {0, 1, 2, 3, 4, 5, 6, 7}, true,
                    [&] {
                      return "rotated box direction R*(" + std::to_string(a) + "," + std::to_string(b) + "," +
                             std::to_string(c) + ")";
                    },
                    fails);
        }
  }
}


// interiorDepth(): a ball of that radius around interiorPoint() lies inside the hull, and
// the bound is tight to rounding. Reference: the distance of interiorPoint() to each face
// plane through three of the face's vertices, in exact rationals (compared squared).
TEST(InteriorDepth, BallInsideTheHullAndTight) {
  std::mt19937 rng(20261205u);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3<double>> pts;
    const double sx = trial % 4 == 3 ? 1e-3 : 1.0;  // some flat ones
    for (int i = 0; i < 30; ++i) pts.emplace_back(3.0 * g(rng), g(rng), sx * g(rng));
    const auto P = ConvexPolyhedron<double>::fromPoints(pts);
    const double depth = P.interiorDepth();
    const Vec3<Q> c = toQ3(P.interiorPoint());
    Q nearest2(-1);  // squared distance to the nearest face plane
    for (int f = 0; f < P.numFaces(); ++f) {
      const auto& L = P.faceVertices(f);
      const Vec3<Q> a = toQ3(P.vertex(L[0])), b = toQ3(P.vertex(L[1])), d = toQ3(P.vertex(L[2]));
      const Vec3<Q> n = (b - a).cross(d - a);
      const Q h = n.dot(a - c);  // > 0: c below the plane
      ASSERT_GT(h, Q(0)) << "trial " << trial << " face " << f;
      const Q d2 = h * h / n.squaredNorm();
      if (nearest2 < Q(0) || d2 < nearest2) nearest2 = d2;
    }
    ASSERT_GT(depth, 0.0) << "trial " << trial;
    EXPECT_LE(Q(depth) * Q(depth), nearest2) << "trial " << trial;
    const double nearest = std::sqrt(CGAL::to_double(nearest2));
    EXPECT_GT(depth, nearest * (1 - 1e-9)) << "trial " << trial << " " << depth << " " << nearest;
  }
  // Exact-scalar shapes do not compute it.
  std::vector<Vec3<Q>> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(Q(i & 1), Q((i >> 1) & 1), Q((i >> 2) & 1));
  EXPECT_EQ(ConvexPolyhedron<Q>::fromPoints(cube).interiorDepth(), Q(0));
}


// Shapes of at least defaults::kSpatialOrderMinVertices vertices number their vertices and
// faces in Morton order (core/detail/spatial_order.hpp), from fromPoints and fromMesh
// alike; the structure stays valid and inputIndex still names each vertex's input point.
template <class T>
void expectMortonOrdered(const ConvexPolyhedron<T>& P, const std::string& context) {
  expectValidPolyhedron(P, context);
  std::vector<int> identity(P.numVertices());
  for (int v = 0; v < P.numVertices(); ++v) identity[v] = v;
  EXPECT_TRUE(mink::detail::mortonOrder(P.vertices()) == identity) << context << ": vertices";
  std::vector<Vec3<T>> centroids;
  for (int f = 0; f < P.numFaces(); ++f) {
    Vec3<T> c = Vec3<T>::Zero();
    for (int v : P.faceVertices(f)) c += P.vertex(v);
    centroids.push_back(c / T(P.faceSize(f)));
  }
  identity.resize(P.numFaces());
  for (int f = 0; f < P.numFaces(); ++f) identity[f] = f;
  EXPECT_TRUE(mink::detail::mortonOrder(centroids) == identity) << context << ": faces";
}

template <class T>
class SpatialOrder : public ::testing::Test {};
using SpatialOrderScalars = ::testing::Types<double, Q>;
TYPED_TEST_SUITE(SpatialOrder, SpatialOrderScalars, ScalarNames);

TYPED_TEST(SpatialOrder, LargeShapesNumberVerticesAndFacesInMortonOrder) {
  using T = TypeParam;
  std::mt19937 rng(7011u);
  std::normal_distribution<double> g(0.0, 1.0);
  const int n = mink::defaults::kSpatialOrderMinVertices + 100;
  std::vector<Vec3<T>> pts;
  while (static_cast<int>(pts.size()) < n) {  // an ellipsoid: every point a hull vertex
    const double x = g(rng), y = g(rng), z = g(rng), r = std::sqrt(x * x + y * y + z * z);
    if (r > 0) pts.push_back(P3<T>(2 * x / r, 2 * y / r, 5 * z / r));
  }
  const auto P = ConvexPolyhedron<T>::fromPoints(pts);
  ASSERT_EQ(P.numVertices(), n);
  expectMortonOrdered(P, "fromPoints");
  for (int v = 0; v < n; ++v) ASSERT_TRUE(P.vertex(v) == pts[P.inputIndex(v)]) << "vertex " << v;
  // The same surface as a mesh, vertices in reverse input order.
  std::vector<Vec3<T>> verts(pts.rbegin(), pts.rend());
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < P.numFaces(); ++f) {
    faces.emplace_back();
    for (int v : P.faceVertices(f)) faces.back().push_back(n - 1 - P.inputIndex(v));
  }
  const auto M = ConvexPolyhedron<T>::fromMesh(verts, faces);
  ASSERT_EQ(M.numVertices(), n);
  ASSERT_EQ(M.numFaces(), P.numFaces());
  expectMortonOrdered(M, "fromMesh");
  for (int v = 0; v < n; ++v) ASSERT_TRUE(M.vertex(v) == P.vertex(v)) << "vertex " << v;
  // Support answers by value against the scan.
  for (int k = 0; k < 200; ++k) {
    const Vec3<T> d = randomDirection<T>(rng);
    ASSERT_TRUE(d.dot(P.vertex(P.support(d))) == d.dot(P.vertex(P.supportBruteForce(d)))) << "direction " << k;
  }
}

}  // namespace mink_test
