// ConvexPolyhedron<T>::fromPoints against CGAL::convex_hull_3 with exact predicates.
//
// Reference: CGAL's hull (Epick for float / double / long double inputs, whose
// predicates are exact on the given coordinates; Simple_cartesian<Gmpq> for exact
// inputs), reduced to what mink reports: the CORNERS (CGAL vertices lying in >= 3
// distinct facet planes; CGAL may keep points in the middle of an edge or a face) and
// the set of DISTINCT facet PLANES, each computed exactly from three input points and
// put in a canonical, orientation-preserving form (Gmpq scaled so that the first
// non-zero normal coefficient is +-1; or, for floating inputs, integer coordinates
// x * 2^S with the plane divided by its gcd — the same thing, faster).
//
// mink's side is reduced the same way, exactly: its vertices as exact points, and for
// every face the exact plane of its vertex loop (which must be exactly planar).
// The header promises the exact hull of the given numbers in every scalar type (exact
// orientation predicates, merging of exactly coplanar faces only), so every case
// asserts EQUAL corner and plane sets. For nearly degenerate inexact inputs we also
// check the reported (rounded) planes: every input point lies at most P.tolerance()
// above every face plane, every exact-hull corner within P.tolerance() of P's boundary
// and every vertex of P within P.tolerance() of the exact hull's boundary.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include "mink/polyhedron/convex_polyhedron.hpp"
#include "support/to_rational.hpp"

#ifdef MINK_SANITIZE_BUILD
constexpr int kBigN = 10000;   // sanitizer build: 100k-point hulls take too long
constexpr int kMidN = 4000;
#else
constexpr int kBigN = 100000;
constexpr int kMidN = 20000;
#endif

namespace mink_test {

// Defined (and explicitly instantiated) in convex_polyhedron_test.cpp.
template <class T>
void expectValidPolyhedron(const mink::ConvexPolyhedron<T>& P, const std::string& context, bool exactGeometry = true);

namespace {

using mink::ConvexPolyhedron;
using mink::Vec3;
using Q = CGAL::Gmpq;
using QP = std::array<Q, 3>;
using Z = CGAL::Gmpz;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using QK = CGAL::Simple_cartesian<Q>;

// ---------------------------------------------------------------------------------
// Exact arithmetic helpers.

// toQ: support/to_rational.hpp.
double dbl(const Q& x) { return CGAL::to_double(x); }
double dbl(const Z& x) { return CGAL::to_double(x); }
template <class T>
double dbl(const T& x) {
  return static_cast<double>(x);
}
template <class T>
QP toQP(const Vec3<T>& p) {
  return {toQ(p[0]), toQ(p[1]), toQ(p[2])};
}
template <class N>
std::array<N, 3> sub(const std::array<N, 3>& a, const std::array<N, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class N>
std::array<N, 3> cross(const std::array<N, 3>& a, const std::array<N, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class N>
N dot(const std::array<N, 3>& a, const std::array<N, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class N>
bool isZero(const std::array<N, 3>& a) {
  return CGAL::is_zero(a[0]) && CGAL::is_zero(a[1]) && CGAL::is_zero(a[2]);
}
template <class N, std::size_t K>
std::string str(const std::array<N, K>& p, double scale = 1.0) {
  std::ostringstream os;
  os.precision(17);
  os << "(";
  for (std::size_t k = 0; k < K; ++k) os << (k ? ", " : "") << dbl(p[k]) * (k < 3 ? scale : 1.0);
  os << ")";
  return os.str();
}

template <class T>
std::string typeName() {
  if (std::is_same<T, float>::value) return "float";
  if (std::is_same<T, double>::value) return "double";
  if (std::is_same<T, long double>::value) return "long double";
  return "Gmpq";
}

// Exact number systems for one point set. Both turn points into exact coordinates
// and planes n.x == d into a canonical (orientation-preserving) key.
//   QConv (exact inputs): Gmpq; planes scaled so that the first non-zero |n_k| is 1.
//   ZConv (floating inputs, all representable in double): every coordinate is an
//     integer multiple of 2^-S, so points become Gmpz vectors x * 2^S and planes are
//     integer vectors divided by their (positive) gcd. Same result as Gmpq, ~4x faster.
struct QConv {
  using Num = Q;
  template <class T>
  explicit QConv(const std::vector<Vec3<T>>&) {}
  Q operator()(const Q& x) const { return x; }
  std::array<Q, 4> plane(const std::array<Q, 3>& n, const Q& d) const {
    int k = 0;
    while (k < 3 && CGAL::is_zero(n[k])) ++k;
    if (k == 3) {
      ADD_FAILURE() << "zero normal";
      return {Q(0), Q(0), Q(0), Q(0)};
    }
    const Q s = CGAL::abs(n[k]);
    return {n[0] / s, n[1] / s, n[2] / s, d / s};
  }
  Q toQ(const Q& x) const { return x; }
  double scale() const { return 1.0; }
};

struct ZConv {
  using Num = Z;
  int S = 0;
  Q unit;  // 2^-S
  template <class T>
  explicit ZConv(const std::vector<Vec3<T>>& pts) {
    for (const auto& p : pts)
      for (int k = 0; k < 3; ++k) {
        const double x = static_cast<double>(p[k]);
        if (x != 0.0) {
          int e;
          std::frexp(x, &e);
          S = std::max(S, std::numeric_limits<double>::digits - e);
        }
      }
    Z twoS(1);
    mpz_mul_2exp(twoS.mpz(), twoS.mpz(), static_cast<unsigned long>(S));
    unit = Q(1) / Q(twoS);
  }
  // x * 2^S, exactly: x = m * 2^(e - 53) with an integer m, and e - 53 + S >= 0.
  template <class T>
  Z operator()(const T& xt) const {
    const double x = static_cast<double>(xt);
    if (x == 0.0) return Z(0);
    int e;
    const double m = std::ldexp(std::frexp(x, &e), std::numeric_limits<double>::digits);
    const int shift = e - std::numeric_limits<double>::digits + S;
    if (shift < 0) {
      ADD_FAILURE() << "ZConv: " << x << " not a multiple of 2^-" << S;
      return Z(0);
    }
    Z z;
    mpz_set_d(z.mpz(), m);
    mpz_mul_2exp(z.mpz(), z.mpz(), static_cast<unsigned long>(shift));
    return z;
  }
  std::array<Z, 4> plane(const std::array<Z, 3>& n, const Z& d) const {
    Z g;
    mpz_gcd(g.mpz(), n[0].mpz(), n[1].mpz());
    mpz_gcd(g.mpz(), g.mpz(), n[2].mpz());
    mpz_gcd(g.mpz(), g.mpz(), d.mpz());
    if (CGAL::is_zero(g)) {
      ADD_FAILURE() << "zero normal";
      return {Z(0), Z(0), Z(0), Z(0)};
    }
    std::array<Z, 4> r = {n[0], n[1], n[2], d};
    for (auto& x : r) mpz_divexact(x.mpz(), x.mpz(), g.mpz());
    return r;
  }
  Q toQ(const Z& x) const { return Q(x) * unit; }
  double scale() const { return std::ldexp(1.0, -S); }
};

template <class T>
using ConvOf = typename std::conditional<std::is_same<T, Q>::value, QConv, ZConv>::type;

// ---------------------------------------------------------------------------------
// Reference: CGAL hull reduced to corners and distinct planes (sorted, unique).

template <class N>
struct ExactHull {
  std::vector<std::array<N, 3>> corners;
  std::vector<std::array<N, 4>> planes;
};

template <class V>
void sortUnique(std::vector<V>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

template <class K, class Conv>
ExactHull<typename Conv::Num> cgalHull(const std::vector<typename K::Point_3>& pts, const Conv& conv) {
  using N = typename Conv::Num;
  CGAL::Surface_mesh<typename K::Point_3> sm;
  CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
  ExactHull<N> r;
  std::vector<std::array<N, 3>> X(sm.number_of_vertices());
  for (auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    X[v.idx()] = {conv(p.x()), conv(p.y()), conv(p.z())};
  }
  // (plane, vertex) incidences; a vertex in >= 3 distinct planes is a corner.
  std::vector<std::pair<std::array<N, 4>, int>> inc;
  inc.reserve(3 * sm.number_of_faces());
  for (auto f : sm.faces()) {
    std::vector<int> loop;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) loop.push_back(static_cast<int>(v.idx()));
    if (loop.size() != 3) {
      ADD_FAILURE() << "CGAL facet with " << loop.size() << " vertices";
      continue;
    }
    const auto n = cross(sub(X[loop[1]], X[loop[0]]), sub(X[loop[2]], X[loop[0]]));
    const auto pl = conv.plane(n, dot(n, X[loop[0]]));
    r.planes.push_back(pl);
    for (int v : loop) inc.emplace_back(pl, v);
  }
  sortUnique(r.planes);
  sortUnique(inc);
  std::vector<int> planesAt(X.size(), 0);
  for (const auto& pv : inc) ++planesAt[pv.second];
  for (std::size_t v = 0; v < X.size(); ++v)
    if (planesAt[v] >= 3) r.corners.push_back(X[v]);
  sortUnique(r.corners);
  // Sanity of the reference itself: outward planes (the centroid of the corners is
  // strictly below each; compared as n.sum < |corners| d to stay in N).
  std::array<N, 3> c = {N(0), N(0), N(0)};
  for (const auto& p : r.corners)
    for (int k = 0; k < 3; ++k) c[k] += p[k];
  const N count(static_cast<int>(r.corners.size()));
  for (const auto& pl : r.planes)
    if (!(dot({pl[0], pl[1], pl[2]}, c) < count * pl[3])) {
      ADD_FAILURE() << "reference: CGAL facet plane not outward " << str(pl);
      break;
    }
  return r;
}

template <class T>
ExactHull<typename ConvOf<T>::Num> reference(const std::vector<Vec3<T>>& pts, const ConvOf<T>& conv) {
  if constexpr (std::is_same<T, Q>::value) {
    std::vector<QK::Point_3> cp;
    for (const auto& p : pts) cp.emplace_back(p[0], p[1], p[2]);
    return cgalHull<QK>(cp, conv);
  } else {
    std::vector<Epick::Point_3> cp;
    for (const auto& p : pts) {
      for (int k = 0; k < 3; ++k)
        if (static_cast<T>(static_cast<double>(p[k])) != p[k]) ADD_FAILURE() << "input not representable in double";
      cp.emplace_back(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]));
    }
    return cgalHull<Epick>(cp, conv);
  }
}

// ---------------------------------------------------------------------------------
// Comparisons.

template <class T>
void expectVerticesAreInputPoints(const std::vector<Vec3<T>>& pts, const ConvexPolyhedron<T>& P) {
  int bad = 0;
  for (int v = 0; v < P.numVertices(); ++v) {
    const int i = P.inputIndex(v);
    const bool ok = i >= 0 && i < static_cast<int>(pts.size()) && P.vertex(v) == pts[i];
    if (!ok && bad++ < 5) ADD_FAILURE() << "vertex " << v << " " << str(toQP(P.vertex(v))) << " is not input point " << i;
  }
  EXPECT_EQ(bad, 0) << "vertices that are not the input point they name";
}

// Both sorted and unique.
template <class V>
void expectSameSet(const std::vector<V>& got, const std::vector<V>& want, const char* what, double scale) {
  if (got == want) return;
  std::vector<V> extra, missing;
  std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra));
  std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing));
  std::ostringstream os;
  os << what << " differ: mink has " << got.size() << ", CGAL has " << want.size() << "; " << extra.size()
     << " only in mink, " << missing.size() << " only in CGAL.";
  for (std::size_t i = 0; i < std::min<std::size_t>(5, extra.size()); ++i)
    os << "\n  only in mink: " << str(extra[i], scale);
  for (std::size_t i = 0; i < std::min<std::size_t>(5, missing.size()); ++i)
    os << "\n  only in CGAL: " << str(missing[i], scale);
  ADD_FAILURE() << os.str();
}

template <class T, class Conv>
void expectSameHull(const std::vector<Vec3<T>>& pts, const ConvexPolyhedron<T>& P,
                    const ExactHull<typename Conv::Num>& ref, const Conv& conv) {
  using N = typename Conv::Num;
  using N3 = std::array<N, 3>;
  expectVerticesAreInputPoints(pts, P);
  std::vector<N3> X(P.numVertices());
  for (int v = 0; v < P.numVertices(); ++v) X[v] = {conv(P.vertex(v)[0]), conv(P.vertex(v)[1]), conv(P.vertex(v)[2])};
  std::vector<N3> corners = X;
  sortUnique(corners);
  std::vector<std::array<N, 4>> planes;
  int nonPlanar = 0;
  for (int f = 0; f < P.numFaces(); ++f) {
    std::vector<int> L(P.faceVertices(f).begin(), P.faceVertices(f).end());
    N3 n = {N(0), N(0), N(0)};
    for (std::size_t i = 1; i + 1 < L.size(); ++i) {
      const N3 c = cross(sub(X[L[i]], X[L[0]]), sub(X[L[i + 1]], X[L[0]]));
      for (int k = 0; k < 3; ++k) n[k] += c[k];
    }
    if (isZero(n)) {
      ADD_FAILURE() << "face " << f << " has zero area";
      continue;
    }
    const N d = dot(n, X[L[0]]);
    for (int v : L)
      if (dot(n, X[v]) != d && nonPlanar++ < 5)
        ADD_FAILURE() << "face " << f << " is not exactly planar: vertex " << v << " " << str(toQP(P.vertex(v)))
                      << " is off the plane of the face's loop";
    planes.push_back(conv.plane(n, d));
  }
  const std::size_t nFacePlanes = planes.size();
  sortUnique(planes);
  EXPECT_EQ(planes.size(), nFacePlanes) << "two faces of P have the same plane";
  expectSameSet(corners, ref.corners, "corner sets", conv.scale());
  expectSameSet(planes, ref.planes, "plane sets (normal, offset)", 1.0);
  EXPECT_EQ(static_cast<std::size_t>(P.numVertices()), ref.corners.size());
  EXPECT_EQ(static_cast<std::size_t>(P.numFaces()), ref.planes.size());
}

// The weaker, still strict, property for nearly degenerate inexact inputs.
template <class T, class Conv>
void expectWithinTolerance(const std::vector<Vec3<T>>& pts, const ConvexPolyhedron<T>& P,
                           const ExactHull<typename Conv::Num>& ref, const Conv& conv) {
  expectVerticesAreInputPoints(pts, P);
  const Q tol = toQ(P.tolerance());
  ASSERT_GT(tol, Q(0));
  const int F = P.numFaces();
  std::vector<QP> N(F);
  std::vector<Q> off(F);
  for (int f = 0; f < F; ++f) {
    N[f] = toQP(P.faceNormal(f));
    off[f] = toQ(P.faceOffset(f));
  }
  // Every input point inside P up to the tolerance (mink's normals are unit).
  {
    int bad = 0;
    Q worst(0);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const QP x = toQP(pts[i]);
      for (int f = 0; f < F; ++f) {
        const Q e = dot(N[f], x) - off[f];
        if (e > worst) worst = e;
        if (e > tol && bad++ < 5)
          ADD_FAILURE() << "input point " << i << " " << str(x) << " lies " << dbl(e / tol)
                        << " tolerances above face " << f << " (tolerance " << dbl(tol) << ")";
      }
    }
    EXPECT_EQ(bad, 0) << "input points outside P beyond the tolerance; worst excess " << dbl(worst / tol)
                      << " tolerances";
  }
  // Every exact-hull corner within the tolerance of P's boundary.
  {
    int bad = 0;
    for (const auto& cz : ref.corners) {
      const QP c = {conv.toQ(cz[0]), conv.toQ(cz[1]), conv.toQ(cz[2])};
      Q nearest;
      bool first = true;
      for (int f = 0; f < F; ++f) {
        const Q gap = off[f] - dot(N[f], c);
        if (first || gap < nearest) nearest = gap, first = false;
      }
      if (nearest > tol && bad++ < 5)
        ADD_FAILURE() << "exact-hull corner " << str(c) << " is " << dbl(nearest / tol)
                      << " tolerances inside P's boundary";
    }
    EXPECT_EQ(bad, 0);
  }
  // Every vertex of P within the tolerance of the exact hull's boundary:
  // some exact plane with (d - n.x)^2 <= tol^2 |n|^2.
  {
    std::vector<std::pair<QP, Q>> planes;
    for (const auto& pl : ref.planes) planes.push_back({{Q(pl[0]), Q(pl[1]), Q(pl[2])}, conv.toQ(pl[3])});
    int bad = 0;
    for (int v = 0; v < P.numVertices(); ++v) {
      const QP x = toQP(P.vertex(v));
      bool near = false;
      for (const auto& pl : planes) {
        const Q gap = pl.second - dot(pl.first, x);
        if (gap * gap <= tol * tol * dot(pl.first, pl.first)) {
          near = true;
          break;
        }
      }
      if (!near && bad++ < 5)
        ADD_FAILURE() << "vertex " << v << " " << str(x) << " is deeper than the tolerance inside the exact hull";
    }
    EXPECT_EQ(bad, 0);
  }
}

// Equal: same corners and planes as the exact hull. EqualAndTolerance: also the
// tolerance properties of the reported planes (nearly degenerate sets).
enum class Expect { Equal, EqualAndTolerance };

struct Counts {
  int vertices = -1, faces = -1;
};

template <class T>
void runCase(const std::string& name, unsigned seed, const std::vector<Vec3<T>>& pts, Expect expect,
             Counts counts = {}, const mink::HullOptions<T>& options = {}) {
  std::ostringstream ctx;
  ctx << name << " [T=" << typeName<T>() << ", seed " << seed << ", " << pts.size() << " points]";
  SCOPED_TRACE(ctx.str());
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  std::optional<ConvexPolyhedron<T>> P;
  try {
    P.emplace(ConvexPolyhedron<T>::fromPoints(pts, options));
  } catch (const std::exception& e) {
    ADD_FAILURE() << "fromPoints threw: " << e.what();
    return;
  }
  const auto t1 = clock::now();
  const ConvOf<T> conv(pts);
  const auto ref = reference(pts, conv);
  const auto t2 = clock::now();
  expectValidPolyhedron(*P, ctx.str());
  if constexpr (!mink::ScalarTraits<T>::isExact) {
    if (options.tolerance < T(0)) {
    // Documented default: kHullToleranceFactor * eps * (|x|max + |y|max + |z|max of the input).
    QP m = {Q(0), Q(0), Q(0)};
    for (const auto& p : pts)
      for (int k = 0; k < 3; ++k) m[k] = std::max(m[k], CGAL::abs(toQ(p[k])));
    const double ext = dbl(m[0] + m[1] + m[2]);
    const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
    EXPECT_NEAR(dbl(P->extent()), ext, 4 * eps * ext);
    EXPECT_NEAR(dbl(P->tolerance()), mink::defaults::kHullToleranceFactor * eps * ext, 1e-6 * dbl(P->tolerance()));
    }
  }
  expectSameHull(pts, *P, ref, conv);
  if constexpr (!mink::ScalarTraits<T>::isExact) {
    if (expect == Expect::EqualAndTolerance) expectWithinTolerance(pts, *P, ref, conv);
  }
  if (counts.vertices >= 0) {
    EXPECT_EQ(P->numVertices(), counts.vertices);
  }
  if (counts.faces >= 0) {
    EXPECT_EQ(P->numFaces(), counts.faces);
  }
  const auto t3 = clock::now();
  auto ms = [](clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  std::printf("    %-60s V=%6d F=%6d  mink %8.1f ms, CGAL %8.1f ms, checks %8.1f ms\n", ctx.str().c_str(),
              P->numVertices(), P->numFaces(), ms(t1 - t0), ms(t2 - t1), ms(t3 - t2));
}

// ---------------------------------------------------------------------------------
// Point sets (generated in double or exactly in Gmpq, then converted to T).

using D3 = std::array<double, 3>;

template <class T>
std::vector<Vec3<T>> toT(const std::vector<D3>& p) {
  std::vector<Vec3<T>> out;
  out.reserve(p.size());
  for (const auto& x : p) out.emplace_back(T(x[0]), T(x[1]), T(x[2]));
  return out;
}

std::vector<D3> inCube(std::mt19937& rng, int n, D3 centre, double half) {
  std::uniform_real_distribution<double> u(-half, half);
  std::vector<D3> p(n);
  for (auto& x : p) x = {centre[0] + u(rng), centre[1] + u(rng), centre[2] + u(rng)};
  return p;
}

std::vector<D3> onSphere(std::mt19937& rng, int n, D3 centre, double r) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<D3> p(n);
  for (auto& x : p) {
    const double a = g(rng), b = g(rng), c = g(rng), l = std::sqrt(a * a + b * b + c * c);
    x = {centre[0] + r * a / l, centre[1] + r * b / l, centre[2] + r * c / l};
  }
  return p;
}

std::vector<D3> inBall(std::mt19937& rng, int n, double r) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<D3> p;
  while (static_cast<int>(p.size()) < n) {
    const double a = u(rng), b = u(rng), c = u(rng);
    if (a * a + b * b + c * c <= 1.0) p.push_back({r * a, r * b, r * c});
  }
  return p;
}

// All points of a k x k x k grid, scaled and shifted, shuffled.
std::vector<D3> grid(std::mt19937& rng, int k, double scale, D3 origin) {
  std::vector<D3> p;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) p.push_back({origin[0] + scale * i, origin[1] + scale * j, origin[2] + scale * l});
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// Points on the surface of the box [-1, 2] x [0, 3] x [-2, 1]: on faces, on edges, the
// corners, plus interior points.
std::vector<D3> boxSurface(std::mt19937& rng, int n) {
  const D3 lo = {-1, 0, -2}, hi = {2, 3, 1};
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 5);
  std::vector<D3> p;
  auto at = [&](int k) { return lo[k] + (hi[k] - lo[k]) * u(rng); };
  for (int i = 0; i < n; ++i) {
    D3 x = {at(0), at(1), at(2)};
    const int kind = i % 4;  // 0, 1: on a face; 2: on an edge; 3: interior
    if (kind <= 2) {
      const int f = pick(rng);
      x[f / 2] = f % 2 ? hi[f / 2] : lo[f / 2];
      if (kind == 2) {
        const int g = (f / 2 + 1 + (i / 4) % 2) % 3;
        x[g] = u(rng) < 0.5 ? lo[g] : hi[g];
      }
    }
    p.push_back(x);
  }
  for (int c = 0; c < 8; ++c) p.push_back({c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]});
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// Every coordinate moved by -1, 0 or +1 ulp of T: a maximally nearly-degenerate set.
template <class T>
std::vector<Vec3<T>> ulpJitter(std::mt19937& rng, std::vector<Vec3<T>> p) {
  std::uniform_int_distribution<int> step(-1, 1);
  for (auto& x : p)
    for (int k = 0; k < 3; ++k) {
      const int s = step(rng);
      if (s != 0) x[k] = std::nextafter(x[k], s > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity());
    }
  return p;
}

template <class P>
std::vector<P> withDuplicates(std::mt19937& rng, const std::vector<P>& base) {
  std::uniform_int_distribution<int> copies(1, 5);
  std::vector<P> p;
  for (const auto& x : base) {
    const int c = copies(rng);
    for (int i = 0; i < c; ++i) p.push_back(x);
  }
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// All integer points with x^2 + y^2 + z^2 == N: exactly cospherical, in every T.
std::vector<D3> integerSphere(std::mt19937& rng, int N) {
  std::vector<D3> p;
  const int R = static_cast<int>(std::sqrt(static_cast<double>(N))) + 1;
  for (int x = -R; x <= R; ++x)
    for (int y = -R; y <= R; ++y)
      for (int z = -R; z <= R; ++z)
        if (x * x + y * y + z * z == N) p.push_back({double(x), double(y), double(z)});
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// Random unit vectors with all their images under sign changes and cyclic coordinate
// permutations (24 each): many exactly coplanar, exactly cocircular groups.
std::vector<D3> symmetricSphere(std::mt19937& rng, int m) {
  std::vector<D3> p;
  for (const auto& b : onSphere(rng, m, {0, 0, 0}, 1.0))
    for (int s = 0; s < 8; ++s)
      for (int r = 0; r < 3; ++r) {
        const D3 x = {s & 1 ? -b[0] : b[0], s & 2 ? -b[1] : b[1], s & 4 ? -b[2] : b[2]};
        p.push_back({x[r], x[(r + 1) % 3], x[(r + 2) % 3]});
      }
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// A slab of n points near the plane z = 0.3 x - 0.2 y + 1 over [-1, 1]^2, each moved off
// it by up to `rel` * extent, plus points far above (and below, if `twoSided`).
std::vector<D3> nearlyCoplanar(std::mt19937& rng, int n, double rel, bool twoSided) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double extent = 1 + 1 + 2.5;
  std::vector<D3> p;
  for (int i = 0; i < n; ++i) {
    const double x = u(rng), y = u(rng);
    p.push_back({x, y, 0.3 * x - 0.2 * y + 1 + rel * extent * u(rng)});
  }
  p.push_back({0.1, -0.2, 3.5});
  p.push_back({-0.3, 0.4, 3.0});
  if (twoSided) p.push_back({0.2, 0.1, -1.5});
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// ---- exact (Gmpq) point sets ----
using QV = Vec3<Q>;

std::vector<QV> gridQ(std::mt19937& rng, int k, const Q& scale) {
  std::vector<QV> p;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) p.emplace_back(scale * i, scale * j - 1, scale * l + Q(1, 3));
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

std::vector<QV> randomRationals(std::mt19937& rng, int n) {
  std::uniform_int_distribution<int> num(-1000, 1000), den(1, 97);
  std::vector<QV> p;
  for (int i = 0; i < n; ++i) p.emplace_back(Q(num(rng), den(rng)), Q(num(rng), den(rng)), Q(num(rng), den(rng)));
  return p;
}

// Rational points exactly on the unit sphere by inverse stereographic projection of
// (u, v) = (a/c, b/c), with their 8 sign-change images.
std::vector<QV> stereographicSphere(std::mt19937& rng, int m) {
  std::uniform_int_distribution<int> num(-60, 60), den(1, 40);
  std::vector<QV> p;
  for (int i = 0; i < m; ++i) {
    const int c = den(rng);
    const Q u(num(rng), c), v(num(rng), c);
    const Q s = u * u + v * v + 1;
    const QV x(2 * u / s, 2 * v / s, (u * u + v * v - 1) / s);
    if (!(x.squaredNorm() == Q(1))) ADD_FAILURE() << "stereographic point not on the unit sphere";
    for (int k = 0; k < 8; ++k) p.emplace_back(k & 1 ? -x[0] : x[0], k & 2 ? -x[1] : x[1], k & 4 ? -x[2] : x[2]);
  }
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// Points on the boundary of a rational tetrahedron (on faces and edges, as exact
// convex combinations), its corners, and interior points.
std::vector<QV> tetrahedronSurface(std::mt19937& rng, int n) {
  const QV C[4] = {QV(Q(0), Q(0), Q(0)), QV(Q(7), Q(1), Q(-2)), QV(Q(2), Q(6), Q(1, 2)), QV(Q(1), Q(2), Q(5))};
  std::uniform_int_distribution<int> w(0, 30), face(0, 3);
  std::vector<QV> p(C, C + 4);
  for (int i = 0; i < n; ++i) {
    int a[4] = {w(rng), w(rng), w(rng), w(rng)};
    if (i % 3 != 2) a[face(rng)] = 0;             // on a face
    if (i % 3 == 1) a[(face(rng) + 1) % 4] = 0;   // often on an edge
    int sum = a[0] + a[1] + a[2] + a[3];
    if (sum == 0) a[0] = sum = 1;
    QV x = QV::Zero();
    for (int k = 0; k < 4; ++k) x += C[k] * Q(a[k], sum);
    p.push_back(x);
  }
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// Points exactly on the plane z = (2x + 3y)/7 + 1, some moved off by +-1e-30-ish
// rationals, plus two apexes.
std::vector<QV> exactSlab(std::mt19937& rng, int n) {
  std::uniform_int_distribution<int> num(-500, 500), den(1, 50), coin(0, 3);
  const Q tiny = Q(1) / (Q(1000000000) * Q(1000000000) * Q(1000000000) * Q(1000));
  std::vector<QV> p;
  for (int i = 0; i < n; ++i) {
    const Q x(num(rng), den(rng)), y(num(rng), den(rng));
    Q z = (2 * x + 3 * y) / 7 + 1;
    const int c = coin(rng);
    if (c == 1) z += tiny * num(rng);
    p.emplace_back(x, y, z);
  }
  p.emplace_back(Q(1), Q(2), Q(40));
  p.emplace_back(Q(-3), Q(1), Q(-30));
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// ---------------------------------------------------------------------------------
// double

TEST(HullVsCgal, DoubleRandom) {
  for (unsigned seed : {101u, 102u, 103u}) {
    std::mt19937 rng(seed);
    runCase<double>("random in cube", seed, toT<double>(inCube(rng, 1000, {3, -2, 5}, 2.0)), Expect::Equal);
  }
  {
    std::mt19937 rng(104u);
    runCase<double>("random in cube", 104u, toT<double>(inCube(rng, kMidN, {0, 0, 0}, 1e3)), Expect::Equal);
  }
  {
    std::mt19937 rng(105u);
    runCase<double>("random in ball", 105u, toT<double>(inBall(rng, kBigN, 7.0)), Expect::Equal);
  }
  {
    // Tiny and huge scales: the tolerance is relative to the extent.
    std::mt19937 rng(106u);
    runCase<double>("random in tiny cube", 106u, toT<double>(inCube(rng, 2000, {1e-9, 0, 0}, 1e-9)), Expect::Equal);
    runCase<double>("random in huge cube", 106u, toT<double>(inCube(rng, 2000, {0, 5e8, 0}, 1e8)), Expect::Equal);
  }
}

TEST(HullVsCgal, DoubleSphere) {
  {
    std::mt19937 rng(201u);
    runCase<double>("on sphere", 201u, toT<double>(onSphere(rng, 2000, {1, 2, 3}, 5.0)), Expect::Equal);
  }
  {
    std::mt19937 rng(202u);
    runCase<double>("on sphere (big)", 202u, toT<double>(onSphere(rng, kBigN, {0, 0, 0}, 1.0)), Expect::Equal);
  }
  {
    std::mt19937 rng(203u);
    runCase<double>("symmetric sphere (24 images each)", 203u, toT<double>(symmetricSphere(rng, 60)), Expect::Equal);
  }
  {
    std::mt19937 rng(204u);
    runCase<double>("integer sphere x^2+y^2+z^2=5525", 204u, toT<double>(integerSphere(rng, 5525)), Expect::Equal);
  }
}

TEST(HullVsCgal, DoubleGridsAndBoxes) {
  {
    std::mt19937 rng(301u);
    runCase<double>("grid 10x10x10", 301u, toT<double>(grid(rng, 10, 1.0, {0, 0, 0})), Expect::Equal, {8, 6});
  }
  {
    std::mt19937 rng(302u);
    runCase<double>("grid 12x12x12 scaled 0.1, shifted", 302u, toT<double>(grid(rng, 12, 0.1, {5, -3, 0.25})),
                    Expect::Equal, {8, 6});
  }
  {
    std::mt19937 rng(303u);
    runCase<double>("box surface", 303u, toT<double>(boxSurface(rng, 3000)), Expect::Equal, {8, 6});
  }
}

TEST(HullVsCgal, DoubleDuplicates) {
  {
    std::mt19937 rng(401u);
    runCase<double>("random in cube, each 1-5 times", 401u,
                    toT<double>(withDuplicates(rng, inCube(rng, 500, {0, 0, 0}, 1.0))), Expect::Equal);
  }
  {
    std::mt19937 rng(402u);
    runCase<double>("sphere, each 1-5 times", 402u, toT<double>(withDuplicates(rng, onSphere(rng, 300, {0, 0, 0}, 2.0))),
                    Expect::Equal);
  }
  {
    std::mt19937 rng(403u);
    runCase<double>("grid 6x6x6, each 1-5 times", 403u, toT<double>(withDuplicates(rng, grid(rng, 6, 1.0, {0, 0, 0}))),
                    Expect::Equal, {8, 6});
  }
  {
    // Only the 8 box corners, many times each.
    std::mt19937 rng(404u);
    std::vector<D3> corners;
    for (int c = 0; c < 8; ++c) corners.push_back({c & 1 ? 1.5 : -1, c & 2 ? 2.0 : 0, c & 4 ? 0.5 : -4});
    std::vector<D3> many;
    for (int r = 0; r < 20; ++r) many.insert(many.end(), corners.begin(), corners.end());
    runCase<double>("box corners, 20 times each", 404u, toT<double>(withDuplicates(rng, many)), Expect::Equal, {8, 6});
  }
}

// Minimal nearly-coplanar sets (shrunk from nearlyCoplanar(seed 285 / 54, 8, 1e-13, one
// side) by deleting points while a failure of an earlier, tolerance-based quickhull
// persisted: folded faces, points 4.7 tolerances outside), kept as regression cases.
TEST(HullVsCgal, DoubleNearlyCoplanarSmall) {
  const std::vector<D3> a = {
      {0.059660222178055777, -0.98953336636344114, 1.2158047399261345},
      {0.85284872706015347, -0.22670135288676718, 1.3011948886955749},
      {0.10000000000000001, -0.20000000000000001, 3.5},
      {0.096606795349409191, -0.93503778897653811, 1.2159895964001217},
      {0.77772476837455673, 0.14702278017648185, 1.2039128744774996},
      {-0.43280959955770415, -0.75281524283040124, 1.0207201686989451},
      {-0.29999999999999999, 0.40000000000000002, 3},
      {-0.12022574839333566, -0.051956200464539526, 0.97432351557470931}};
  runCase<double>("8-point slab A", 285u, toT<double>(a), Expect::EqualAndTolerance);
  const std::vector<D3> b = {
      {-0.61213335142462377, -0.99496661901323147, 1.0153533183757015},
      {-0.29999999999999999, 0.40000000000000002, 3},
      {0.90482046777674641, -0.64927861405297926, 1.4013018631431748},
      {0.10000000000000001, -0.20000000000000001, 3.5},
      {0.81799281816446734, 0.47689801629963591, 1.1500182421892948},
      {-0.52743944874113291, -0.56593989533902822, 0.95495614444523425},
      {-0.11136854076693703, -0.0035690121551453791, 0.96730324020084069},
      {-0.3124857144292178, -0.92994400933777821, 1.09224308753854}};
  runCase<double>("8-point slab B", 54u, toT<double>(b), Expect::EqualAndTolerance);
}

TEST(HullVsCgal, DoubleNearlyCoplanar) {
  unsigned seed = 501u;
  for (double rel : {1e-13, 1e-15})
    for (bool twoSided : {false, true}) {
      std::mt19937 rng(seed);
      std::ostringstream name;
      name << "nearly coplanar slab, rel " << rel << (twoSided ? ", apexes on both sides" : ", one side");
      runCase<double>(name.str(), seed, toT<double>(nearlyCoplanar(rng, 2000, rel, twoSided)),
                      Expect::EqualAndTolerance);
      ++seed;
    }
}

// With tolerance 0 fromPoints accepts any set that is not exactly coplanar, so also sets
// within rounding of a plane. The first simplex was oriented by the sign of a rounded
// product, which such a sliver can get wrong: the hull came out inside out (fuzzer,
// fuzz/regressions/hull_sliver_simplex_inside_out: 1e-185 wide, 1e-294 thick, with
// denormal coordinates). Its orientation is exact now. Here: that set, and points of
// random planes rounded to double (off their plane by rounding only), at unit scale, at
// 2^-600 and at 2^200, each against CGAL's exact hull.
TEST(HullVsCgal, SliversWithZeroTolerance) {
  mink::HullOptions<double> zero;
  zero.tolerance = 0.0;
  const std::vector<D3> fuzz = {
      {0x0.0000000000001p-1022, -0x1.9999999999999p-614, -0x1.9999999999999p-614},
      {0x0.000000000000dp-1022, -0x1.9999999999999p-614, -0x1.9999999999999p-614},
      {-0x1.9999999999999p-614, -0x1.9999999999999p-614, 0x0.2000299999999p-1022},
      {0x1.1000200030002p-975, 0x1.20100020003p-975, 0x0.000000103fb02p-1022},
      {0x0.0020000020002p-1022, 0x1.20000030202p-991, 0x0.0000000010101p-1022}};
  runCase<double>("fuzzer's sliver: 1e-185 wide, 1e-294 thick", 0u, toT<double>(fuzz), Expect::Equal, {}, zero);
  const unsigned seed = 502u;
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int built = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Eigen::Vector3d n = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
    const Eigen::Vector3d o = 3.0 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    const int m = 4 + trial % 9;
    const int e = trial % 3 == 0 ? 0 : (trial % 3 == 1 ? -600 : 200);
    std::vector<D3> pts;
    for (int i = 0; i < m; ++i) {
      const Eigen::Vector3d x = o + u(rng) * a + u(rng) * b;
      pts.push_back({std::ldexp(x[0], e), std::ldexp(x[1], e), std::ldexp(x[2], e)});
    }
    // Exactly coplanar sets (rare) are rejected, as they must be.
    bool coplanar = true;
    for (int i = 3; i < m && coplanar; ++i) {
      const auto v = toT<double>({pts[0], pts[1], pts[2], pts[i]});
      coplanar = mink::orient3d(v[0], v[1], v[2], v[3]) == 0;
    }
    if (coplanar) continue;
    std::ostringstream name;
    name << "sliver " << trial << ": " << m << " points of a plane, scale 2^" << e;
    runCase<double>(name.str(), seed, toT<double>(pts), Expect::Equal, {}, zero);
    ++built;
  }
  EXPECT_GT(built, 40);
}

// fromMesh on the faces of such hulls: a closed convex mesh, so accepted (with its own
// default tolerance), with the same vertices and faces; reversed, rejected as inward. The
// fuzzer's case (fuzz/regressions/from_mesh_needle_volume_sign): a needle 1 long, 1e-27
// wide and 1e-40 thick (at unit scale), whose signed volume summed in floating point came
// out negative; the orientation is decided exactly now. Every mesh is checked convex here
// exactly first (each vertex on or below each face, by CGAL's orientation on Epick).
TEST(HullVsCgal, FromMeshOfSliverHulls) {
  mink::HullOptions<double> zero;
  zero.tolerance = 0.0;
  std::vector<std::vector<D3>> sets = {{{0x1.1630101010101p-1007, -0x1.aaaaaaaaaaa01p-341, 0x1.3aaabaaaaaaaap-1007},
                                        {0x1.4002501010103p-1021, 0x1.1010101010001p-1007, 0x1.1010301010301p-1007},
                                        {0x1.3010101030103p-1007, 0x1.3010103030103p-1007, 0x1.3030103f40301p-1007},
                                        {0x0.1000003034003p-1022, -0x1.0020204000001p-351, -0x1.aaaaaaaaaaaaap-341},
                                        {-0x1.aaaaaaaaaaaaap-341, -0x1.aaaaaaaaaaaaap-341, -0x1.aaaaaaaaaaaaap-341},
                                        {-0x1.aaaaaaaaaaaaap-341, -0x1.aaaaaaaaaabaap-341, -0x1.aaaaaaaaaaaaap-341},
                                        {0x1.0aaaaaaaaaaaap-252, 0x1.030303030303p-252, 0x1.030303030303p-252}}};
  std::mt19937 rng(504u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    // Points of a random plane, rounded (off it by rounding only), at three scales.
    const Eigen::Vector3d n = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
    const int e = trial % 3 == 0 ? 0 : (trial % 3 == 1 ? -600 : 200);
    std::vector<D3> pts;
    for (int i = 0; i < 5 + trial % 6; ++i) {
      const Eigen::Vector3d x = u(rng) * a + u(rng) * b + Eigen::Vector3d(0.5, 0.25, 0.125);
      pts.push_back({std::ldexp(x[0], e), std::ldexp(x[1], e), std::ldexp(x[2], e)});
    }
    sets.push_back(pts);
  }
  int meshes = 0;
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const auto pts = toT<double>(sets[k]);
    std::optional<ConvexPolyhedron<double>> hull;
    try {
      hull.emplace(ConvexPolyhedron<double>::fromPoints(pts, zero));
    } catch (const mink::InvalidInput&) {
      continue;  // exactly coplanar
    }
    const std::string what = "set " + std::to_string(k);
    std::vector<std::vector<int>> loops, reversed;
    for (int f = 0; f < hull->numFaces(); ++f) {
      std::vector<int> loop(hull->faceVertices(f).begin(), hull->faceVertices(f).end());
      loops.push_back(loop);
      std::reverse(loop.begin(), loop.end());
      reversed.push_back(loop);
    }
    const auto& V = hull->vertices();
    for (const auto& loop : loops)
      for (std::size_t v = 0; v < V.size(); ++v) {
        const auto P = [&](int i) { return Epick::Point_3(V[i].x(), V[i].y(), V[i].z()); };
        const auto o = CGAL::orientation(P(loop[0]), P(loop[1]), P(loop[2]), P(static_cast<int>(v)));
        ASSERT_NE(o, CGAL::POSITIVE) << what << ": vertex " << v << " above a face (not a convex mesh)";
      }
    try {
      const auto M = ConvexPolyhedron<double>::fromMesh(V, loops);
      EXPECT_EQ(M.numVertices(), hull->numVertices()) << what;
      EXPECT_EQ(M.numFaces(), hull->numFaces()) << what;
    } catch (const mink::InvalidInput& ex) {
      ADD_FAILURE() << what << ": fromMesh rejected a closed convex mesh: " << ex.what();
    }
    EXPECT_THROW(ConvexPolyhedron<double>::fromMesh(V, reversed), mink::InvalidInput) << what;
    ++meshes;
  }
  EXPECT_GT(meshes, 25);
}

// Needle faces across the double range: a face 2^286 long whose short edge is 2^-783
// (fuzzer, fuzz/regressions/needle_face_normal_underflows). Its fan from the sharp corner
// underflowed (angle 2^-2138) to a zero normal, so the face did not merge with the
// coplanar face beside it and a vertex in the middle of an edge stayed a "corner". Here:
// that set, and random sets of a few points of size 2^k beside a few of size 2^-j, each
// against CGAL's exact hull, with every face normal unit.
TEST(HullVsCgal, NeedleFacesAcrossTheRange) {
  // A shape beyond 2^±64 is built at unit scale: its coordinates are rounded to multiples
  // of 2^(e - 1074), e the exponent of its largest coordinate (convex_polyhedron.hpp).
  // The reference is the exact hull of those rounded points.
  auto onGrid = [](std::vector<D3> pts) {
    double m = 0.0;
    for (const auto& x : pts)
      for (double c : x) m = std::max(m, std::abs(c));
    const int e = std::ilogb(m);
    if (e > 64 || e < -64)
      for (auto& x : pts)
        for (double& c : x) c = std::ldexp(std::ldexp(c, -e), e);
    return pts;
  };
  auto unitNormals = [](const ConvexPolyhedron<double>& P, const std::string& what) {
    for (int f = 0; f < P.numFaces(); ++f)
      EXPECT_NEAR(P.faceNormal(f).norm(), 1.0, 1e-12) << what << " face " << f;
  };
  const std::vector<D3> fuzz = {{0x1.5630101p-1007, -0x1.1d1d1d1010301p+286, 0x1.6060606060606p-927},
                                {0x1.6060606060606p-927, 0x1.6060606060606p-927, 0x1.6060606060606p-927},
                                {0x0p+0, 0x1.606p-927, 0x1.6060606060606p-927},
                                {0x1.6060606060606p-927, 0x1.6060606060606p-927, -0x1.1d1d106060606p+286},
                                {-0x1.1d1d1d1d1d1d1p+286, -0x1.dd1d1d1d1d1d1p+278, 0x1.0d1d1d1d111d1p-1007},
                                {0x1.0010101030103p-967, 0x0.0000000000101p-1022, 0x1.f0f0f0f0003p-783},
                                {0x1.f0f0f0f0f0f0fp-783, 0x1.00000060f0f0fp-1007, -0x1.1030101056301p+286},
                                {-0x1.1d1d1d1d1d1d1p+286, -0x1.1d111d1d15dd1p+286, 0x1.30103030100d1p-1007}};
  runCase<double>("fuzzer's needle: 2^286 by 2^-783", 0u, toT<double>(onGrid(fuzz)), Expect::Equal);
  unitNormals(ConvexPolyhedron<double>::fromPoints(toT<double>(fuzz)), "fuzzer's needle");
  const unsigned seed = 503u;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> sgn(0, 1), big(200, 290), small(-1070, -600);
  std::uniform_real_distribution<double> u(1.0, 2.0);
  for (int trial = 0; trial < 40; ++trial) {
    const int kb = big(rng), ks = small(rng);
    std::vector<D3> pts;
    // Large points on the coordinate axes (and one diagonal), tiny ones near the origin:
    // the hull's faces through the origin region are needles.
    for (int i = 0; i < 4 + trial % 3; ++i) {
      D3 x = {0.0, 0.0, 0.0};
      x[i % 3] = (sgn(rng) ? 1 : -1) * std::ldexp(u(rng), kb);
      if (i == 3) x = {-std::ldexp(u(rng), kb), -std::ldexp(u(rng), kb), 0.0};
      pts.push_back(x);
    }
    for (int i = 0; i < 2 + trial % 4; ++i)
      pts.push_back({std::ldexp(u(rng), ks) * (sgn(rng) ? 1 : 0), std::ldexp(u(rng), ks) * (sgn(rng) ? 1 : 0),
                     std::ldexp(u(rng), ks) * (sgn(rng) ? 1 : -1)});
    std::ostringstream name;
    name << "needles " << trial << ": 2^" << kb << " beside 2^" << ks;
    runCase<double>(name.str(), seed, toT<double>(onGrid(pts)), Expect::Equal);
    unitNormals(ConvexPolyhedron<double>::fromPoints(toT<double>(pts)), name.str());
  }
}

// Shrunk from "grid 3x3x3 (scale 0.1) with 1-ulp jitter" in float (fuzzing, seed 62):
// points 0..3 lie exactly on x = 0.50000006f; triangle (0, 1, 2) is nearly degenerate,
// so its normal computed in float cancels to exactly zero.
TEST(HullVsCgal, FloatSliverOnAFace) {
  const std::vector<Vec3<float>> p = {Vec3<float>(0.50000006f, -0.25f, 1.0f),
                                      Vec3<float>(0.50000006f, -0.0500000045f, 1.20000005f),
                                      Vec3<float>(0.50000006f, -0.150000006f, 1.10000002f),
                                      Vec3<float>(0.50000006f, -0.049999997f, 1.0999999f),
                                      Vec3<float>(0.299999982f, -0.0500000045f, 1.19999993f)};
  runCase<float>("5 float points, sliver on the face x = 0.50000006", 62u, p, Expect::EqualAndTolerance);
}

TEST(HullVsCgal, UlpJitteredGrids) {
  {
    std::mt19937 rng(551u);
    runCase<double>("grid 8x8x8 (scale 0.1) with 1-ulp jitter", 551u,
                    ulpJitter(rng, toT<double>(grid(rng, 8, 0.1, {0.3, -0.2, 1.0}))), Expect::EqualAndTolerance);
  }
  {
    std::mt19937 rng(552u);
    // Shifted so that no coordinate is 0 (a 1-ulp step from 0 is a denormal, outside
    // the range orient3d documents).
    auto box = boxSurface(rng, 1000);
    for (auto& x : box) x = {x[0] + 0.125, x[1] + 0.375, x[2] + 0.625};
    runCase<double>("box surface with 1-ulp jitter", 552u, ulpJitter(rng, toT<double>(box)),
                    Expect::EqualAndTolerance);
  }
  {
    std::mt19937 rng(553u);
    runCase<float>("grid 6x6x6 (scale 0.1) with 1-ulp jitter", 553u,
                   ulpJitter(rng, toT<float>(grid(rng, 6, 0.1, {0.3, -0.2, 1.0}))), Expect::EqualAndTolerance);
  }
}

// ---------------------------------------------------------------------------------
// float and long double

TEST(HullVsCgal, Float) {
  {
    std::mt19937 rng(601u);
    runCase<float>("on sphere", 601u, toT<float>(onSphere(rng, 40, {0, 0, 0}, 1.0)), Expect::Equal);
  }
  {
    std::mt19937 rng(602u);
    runCase<float>("random in cube", 602u, toT<float>(inCube(rng, 60, {1, 0, 0}, 1.0)), Expect::Equal);
  }
  {
    std::mt19937 rng(603u);
    runCase<float>("grid 8x8x8", 603u, toT<float>(grid(rng, 8, 1.0, {0, 0, 0})), Expect::Equal, {8, 6});
  }
  {
    std::mt19937 rng(604u);
    runCase<float>("integer sphere x^2+y^2+z^2=325", 604u, toT<float>(integerSphere(rng, 325)), Expect::Equal);
  }
  {
    std::mt19937 rng(605u);
    runCase<float>("sphere, each 1-5 times", 605u, toT<float>(withDuplicates(rng, onSphere(rng, 30, {0, 0, 0}, 1.0))),
                   Expect::Equal);
  }
  {
    std::mt19937 rng(606u);
    runCase<float>("random in cube", 606u, toT<float>(inCube(rng, 1000, {0, 0, 0}, 1.0)),
                   Expect::EqualAndTolerance);
  }
  {
    std::mt19937 rng(607u);
    runCase<float>("nearly coplanar slab, rel 1e-6", 607u, toT<float>(nearlyCoplanar(rng, 500, 1e-6, true)),
                   Expect::EqualAndTolerance);
  }
}

TEST(HullVsCgal, LongDouble) {
  {
    std::mt19937 rng(701u);
    runCase<long double>("random in cube", 701u, toT<long double>(inCube(rng, 1000, {0, 0, 0}, 1.0)), Expect::Equal);
  }
  {
    std::mt19937 rng(702u);
    runCase<long double>("grid 7x7x7", 702u, toT<long double>(grid(rng, 7, 1.0, {0, 0, 0})), Expect::Equal, {8, 6});
  }
  {
    std::mt19937 rng(703u);
    runCase<long double>("integer sphere x^2+y^2+z^2=725", 703u, toT<long double>(integerSphere(rng, 725)),
                         Expect::Equal);
  }
}

// ---------------------------------------------------------------------------------
// Exact mode: T = Gmpq, tolerance 0, equality on degenerate sets.

TEST(HullVsCgal, GmpqDegenerate) {
  {
    std::mt19937 rng(801u);
    runCase<Q>("grid 10x10x10 (scale 2/3)", 801u, gridQ(rng, 10, Q(2, 3)), Expect::Equal, {8, 6});
  }
  {
    std::mt19937 rng(802u);
    runCase<Q>("random rationals, each 1-5 times", 802u, withDuplicates(rng, randomRationals(rng, 300)), Expect::Equal);
  }
  {
    std::mt19937 rng(803u);
    runCase<Q>("grid 5x5x5, each 1-5 times", 803u, withDuplicates(rng, gridQ(rng, 5, Q(1))), Expect::Equal, {8, 6});
  }
  {
    std::mt19937 rng(804u);
    runCase<Q>("tetrahedron surface", 804u, tetrahedronSurface(rng, 1500), Expect::Equal, {4, 4});
  }
  {
    std::mt19937 rng(805u);
    std::vector<QV> box;
    for (const auto& x : boxSurface(rng, 1500)) box.emplace_back(Q(x[0]), Q(x[1]), Q(x[2]));
    runCase<Q>("box surface", 805u, box, Expect::Equal, {8, 6});
  }
  {
    std::mt19937 rng(806u);
    runCase<Q>("exact slab with 1e-30 perturbations", 806u, exactSlab(rng, 1500), Expect::Equal);
  }
  {
    std::mt19937 rng(807u);
    runCase<Q>("stereographic rational sphere, 8 images each", 807u, stereographicSphere(rng, 120), Expect::Equal);
  }
  {
    std::mt19937 rng(808u);
    std::vector<QV> s;
    for (const auto& x : integerSphere(rng, 725)) s.emplace_back(Q(x[0]), Q(x[1]), Q(x[2]));
    runCase<Q>("integer sphere x^2+y^2+z^2=725", 808u, s, Expect::Equal);
  }
  {
    std::mt19937 rng(809u);
    std::vector<QV> s;
    for (const auto& x : symmetricSphere(rng, 20)) s.emplace_back(Q(x[0]), Q(x[1]), Q(x[2]));
    runCase<Q>("symmetric sphere (24 images each)", 809u, s, Expect::Equal);
  }
}

}  // namespace
}  // namespace mink_test
