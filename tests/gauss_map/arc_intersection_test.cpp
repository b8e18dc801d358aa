// Tests of mink/gauss_map/arc_intersection.hpp against exact references.
//
// References (independent of the signed-volume formula under test):
//  * signs of the four volumes: CGAL::orientation on Simple_cartesian<Gmpq> points (CGAL's
//    own exact evaluation, on the inputs converted exactly to rationals);
//  * "the arcs cross properly": exact geometry of the crossing line. n = (a×b)×(c×d) is the
//    line of the two great-circle planes; the arcs cross properly iff ±n lies strictly
//    inside both arcs, m strictly inside a–b iff (a×m)·(a×b) > 0 and (m×b)·(a×b) > 0;
//  * "the closed arcs touch": the same tests with >= 0, or, when the great circles
//    coincide (n = 0), an endpoint of one arc in the closed other arc.
// Reference class: Proper iff the geometric test says so; otherwise Degenerate iff some
// exact volume is zero and no pair of volumes is strictly same-signed, else None (that
// split is the documented contract). Consistency of the contract with geometry is checked
// too: a geometric proper crossing has no zero volume, and None never touches.
//
// Floating-point results are compared with the exact class when the rounded signs are
// provably reliable: volume i is reliable when its exact value satisfies
//   |V_i| > B_i = 6u·perm_i + 4(|x|_1 + 2)·min_normal,
// perm_i = Σ|x_k|(|y_l z_m| + |y_m z_l|) computed exactly: the evaluation in
// detail::det3 errs by at most γ5·perm + underflow < B_i (see arc_intersection.hpp),
// so a reliable volume has the exact sign in T.
#include "mink/gauss_map/arc_intersection.hpp"

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using mink::ArcIntersection;
using Q = CGAL::Gmpq;
using Z = CGAL::Gmpz;
template <class T>
using V3 = mink::Vec3<T>;
using Arcs = std::array<V3<double>, 4>;  // a, b, c, d

const char* name(ArcIntersection c) {
  switch (c) {
    case ArcIntersection::Proper: return "Proper";
    case ArcIntersection::None: return "None";
    case ArcIntersection::Degenerate: return "Degenerate";
    case ArcIntersection::Uncertain: return "Uncertain";
  }
  return "?";
}

// ---- exact conversions -------------------------------------------------------------
Q exact(double x) { return Q(x); }
template <class T>
V3<Q> exact(const V3<T>& v) {
  return V3<Q>(exact(v[0]), exact(v[1]), exact(v[2]));
}

Q pow2(int e) {
  Z p;
  mpz_ui_pow_ui(p.mpz(), 2, static_cast<unsigned long>(e < 0 ? -e : e));
  return e < 0 ? Q(Z(1), p) : Q(p, Z(1));
}

// The four vectors as integers times one common power of two: x = X * 2^E exactly. Every
// sign the reference computes is homogeneous in the four vectors, so the integers X
// decide it; Gmpz arithmetic avoids Gmpq's gcd normalisations (the tests run ~10x faster).
template <class T>
struct ScaledInput {
  V3<Z> v[4];
  int exponent = 0;  // E
};

template <class T>
ScaledInput<T> toIntegers(const std::array<V3<T>, 4>& x) {
  constexpr int digits = std::numeric_limits<T>::digits;
  static_assert(digits <= 64, "significand must fit an unsigned long");
  unsigned long mant[4][3];
  int ex[4][3];
  int lowest = std::numeric_limits<int>::max();
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      mant[i][k] = 0;
      ex[i][k] = 0;
      if (x[i][k] == T(0)) continue;
      int e = 0;
      const T m = std::frexp(std::abs(x[i][k]), &e);  // |x| = m 2^e, m in [1/2, 1)
      mant[i][k] = static_cast<unsigned long>(std::ldexp(m, digits));
      ex[i][k] = e - digits;
      lowest = std::min(lowest, ex[i][k]);
    }
  ScaledInput<T> out;
  out.exponent = lowest == std::numeric_limits<int>::max() ? 0 : lowest;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      Z z(mant[i][k]);
      mpz_mul_2exp(z.mpz(), z.mpz(), static_cast<unsigned long>(ex[i][k] - out.exponent));
      out.v[i][k] = x[i][k] < T(0) ? Z(-z) : z;
    }
  return out;
}

template <class N>
N nabs(const N& x) {
  return x < 0 ? N(-x) : x;
}
template <class N>
int nsign(const N& x) {
  return (x > 0) - (x < 0);
}
template <class N>
V3<N> cross(const V3<N>& x, const V3<N>& y) {
  return V3<N>(x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]);
}
template <class N>
N dot(const V3<N>& x, const V3<N>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}
template <class N>
bool isZero(const V3<N>& x) {
  return x[0] == 0 && x[1] == 0 && x[2] == 0;
}

// ---- the exact reference -----------------------------------------------------------
template <class N>
int orientationSign(const V3<N>& x, const V3<N>& y, const V3<N>& z) {
  using P = typename CGAL::Simple_cartesian<N>::Point_3;
  static const int basis = static_cast<int>(
      CGAL::orientation(P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 1)));  // CGAL's convention
  return basis * static_cast<int>(CGAL::orientation(P(0, 0, 0), P(x[0], x[1], x[2]),
                                                    P(y[0], y[1], y[2]), P(z[0], z[1], z[2])));
}

// m (in the plane of a, b, with a, b not parallel) is on the arc a–b: open or closed.
template <class N>
bool onArc(const V3<N>& m, const V3<N>& a, const V3<N>& b, bool closed) {
  const V3<N> ab = cross(a, b);
  const int s0 = nsign(dot(cross(a, m), ab)), s1 = nsign(dot(cross(m, b), ab));
  return closed ? (s0 >= 0 && s1 >= 0 && !isZero(m)) : (s0 > 0 && s1 > 0);
}
template <class N>
bool inPlane(const V3<N>& m, const V3<N>& a, const V3<N>& b) {
  return dot(m, cross(a, b)) == 0;
}

struct Reference {
  int sign[4];          // exact signs of |cba|, |dba|, |adc|, |bdc| (CGAL)
  bool proper = false;  // relative interiors cross (geometry of n)
  bool touch = false;   // closed arcs intersect
  ArcIntersection cls = ArcIntersection::None;
};

template <class N>
Reference reference(const V3<N>& a, const V3<N>& b, const V3<N>& c, const V3<N>& d) {
  Reference r;
  r.sign[0] = orientationSign(c, b, a);
  r.sign[1] = orientationSign(d, b, a);
  r.sign[2] = orientationSign(a, d, c);
  r.sign[3] = orientationSign(b, d, c);
  const V3<N> n = cross(cross(a, b), cross(c, d));
  if (!isZero(n)) {
    for (int s : {1, -1}) {
      const V3<N> m = s > 0 ? n : V3<N>(-n);
      r.proper |= onArc(m, a, b, false) && onArc(m, c, d, false);
      r.touch |= onArc(m, a, b, true) && onArc(m, c, d, true);
    }
  } else {
    // One common great circle: closed arcs meet iff one holds an endpoint of the other.
    r.touch = (inPlane(c, a, b) && onArc(c, a, b, true)) ||
              (inPlane(d, a, b) && onArc(d, a, b, true)) ||
              (inPlane(a, c, d) && onArc(a, c, d, true)) || (inPlane(b, c, d) && onArc(b, c, d, true));
  }
  const bool anyZero = r.sign[0] == 0 || r.sign[1] == 0 || r.sign[2] == 0 || r.sign[3] == 0;
  const bool separated = r.sign[0] * r.sign[1] > 0 || r.sign[2] * r.sign[3] > 0;
  if (r.proper)
    r.cls = ArcIntersection::Proper;
  else if (anyZero && !separated)
    r.cls = ArcIntersection::Degenerate;
  else
    r.cls = ArcIntersection::None;
  return r;
}

// ---- reliability of the rounded volumes in T ---------------------------------------
// For the integer inputs X (x = X 2^E): value, perm and |x|_1 of each determinant in the
// integer scale; true values are value 2^{3E}, perm 2^{3E}, |x|_1 2^E.
struct VolumeBounds {
  Z value[4];
  Z perm[4];
  Z l1[4];
  int exponent = 0;
};

template <class T>
VolumeBounds volumeBounds(const ScaledInput<T>& in) {
  VolumeBounds vb;
  vb.exponent = in.exponent;
  const int cols[4][3] = {{2, 1, 0}, {3, 1, 0}, {0, 3, 2}, {1, 3, 2}};
  for (int i = 0; i < 4; ++i) {
    const V3<Z>& x = in.v[cols[i][0]];
    const V3<Z>& y = in.v[cols[i][1]];
    const V3<Z>& z = in.v[cols[i][2]];
    vb.value[i] = dot(x, cross(y, z));
    vb.perm[i] = nabs(x[0]) * (nabs(Z(y[1] * z[2])) + nabs(Z(y[2] * z[1]))) +
                 nabs(x[1]) * (nabs(Z(y[2] * z[0])) + nabs(Z(y[0] * z[2]))) +
                 nabs(x[2]) * (nabs(Z(y[0] * z[1])) + nabs(Z(y[1] * z[0])));
    vb.l1[i] = nabs(x[0]) + nabs(x[1]) + nabs(x[2]);
  }
  return vb;
}

// True |V_i| > factor u perm_i + under (|x|_1 + 2) min_normal, u and min_normal of T.
template <class T>
bool exceeds(const VolumeBounds& vb, int i, int factor, int under) {
  constexpr int p = std::numeric_limits<T>::digits;  // u = 2^-p
  // Scaled by 2^{p - 3E}: |V| 2^p - factor perm > under (|x|_1 2^E + 2) min 2^{p - 3E}.
  Z lhs;  // a fresh Gmpz: CGAL's handles share representations, mpz() writes through
  mpz_mul_2exp(lhs.mpz(), vb.value[i].mpz(), p);
  mpz_abs(lhs.mpz(), lhs.mpz());
  lhs -= Z(factor) * vb.perm[i];
  if (!(lhs > 0)) return false;
  const int e = vb.exponent;
  // Fast path: rhs < 2^B with B from bit lengths (|x|_1 2^E + 2 < 2^(max(bits+E, 1) + 1)).
  const long l1Bits = static_cast<long>(mpz_sizeinbase(vb.l1[i].mpz(), 2));
  const long B = 4 + std::max<long>(l1Bits + e, 1) + 1 +
                 (std::numeric_limits<T>::min_exponent - 1) + p - 3L * e;
  if (static_cast<long>(mpz_sizeinbase(lhs.mpz(), 2)) - 1 >= B) return true;
  const Q rhs = Q(under) * (Q(vb.l1[i]) * pow2(e) + Q(2)) *
                pow2(std::numeric_limits<T>::min_exponent - 1 + p - 3 * e);
  return Q(lhs) > rhs;
}

struct Stats {
  long cases = 0, proper = 0, none = 0, degenerate = 0;
  long checkedPlain = 0, uncertain = 0;
  long plainWrong = 0;  ///< classifyArcs (rounded signs) differs from the exact class
};

// Checks classifyArcs<T> and classifyArcsFiltered<T> on inputs exactly representable in
// T against the exact reference of those inputs.
template <class T>
void checkFloating(const std::array<V3<T>, 4>& x, const ScaledInput<T>& in, const Reference& ref,
                   Stats& st) {
  const VolumeBounds vb = volumeBounds(in);
  bool reliable[4], strong[4];
  for (int i = 0; i < 4; ++i) {
    reliable[i] = exceeds<T>(vb, i, 6, 4);
    strong[i] = exceeds<T>(vb, i, 16, 8);
  }
  ++st.cases;
  const ArcIntersection plain = mink::classifyArcs(x[0], x[1], x[2], x[3]);
  const ArcIntersection filtered = mink::classifyArcsFiltered(x[0], x[1], x[2], x[3]);
  SCOPED_TRACE(std::string("exact=") + name(ref.cls) + " plain=" + name(plain) +
               " filtered=" + name(filtered));
  const bool allReliable = reliable[0] && reliable[1] && reliable[2] && reliable[3];
  const bool sepReliable = (reliable[0] && reliable[1] && ref.sign[0] * ref.sign[1] > 0) ||
                           (reliable[2] && reliable[3] && ref.sign[2] * ref.sign[3] > 0);
  if (allReliable || sepReliable) {
    ++st.checkedPlain;
    EXPECT_EQ(plain, ref.cls);
  }
  if (filtered == ArcIntersection::Uncertain)
    ++st.uncertain;
  else
    EXPECT_EQ(filtered, ref.cls);  // the filter is never wrong
  if (strong[0] && strong[1] && strong[2] && strong[3]) {
    EXPECT_NE(filtered, ArcIntersection::Uncertain);  // ... and not needlessly pessimistic
  }
  // The filter and then expansion arithmetic: the exact class on every input.
  EXPECT_EQ(mink::classifyArcsExact(x[0], x[1], x[2], x[3]), ref.cls);
  EXPECT_EQ(mink::det3Sign(x[2], x[1], x[0]), ref.sign[0]);
  EXPECT_EQ(mink::det3Sign(x[1], x[3], x[2]), ref.sign[3]);
  st.plainWrong += plain != ref.cls;
}

// classifyArcs<Gmpq> on the exactly converted inputs equals the reference; the contract
// holds against geometry; (every `deep`-th case) negation and symmetries.
void checkExact(const Arcs& in, const ScaledInput<double>& z, const Reference& ref, bool deep,
                Stats& st) {
  const V3<Q> a = exact(in[0]), b = exact(in[1]), c = exact(in[2]), d = exact(in[3]);
  const mink::ArcVolumes<Q> vol = mink::arcVolumes(a, b, c, d);
  const ArcIntersection got = mink::classifyArcs(vol);
  SCOPED_TRACE(std::string("exact=") + name(ref.cls) + " got=" + name(got));
  ++st.cases;
  st.proper += ref.cls == ArcIntersection::Proper;
  st.none += ref.cls == ArcIntersection::None;
  st.degenerate += ref.cls == ArcIntersection::Degenerate;
  ASSERT_EQ(got, ref.cls);
  EXPECT_EQ(mink::detail::sign(vol.cba), ref.sign[0]);  // agree with CGAL's orientation
  EXPECT_EQ(mink::detail::sign(vol.dba), ref.sign[1]);
  EXPECT_EQ(mink::detail::sign(vol.adc), ref.sign[2]);
  EXPECT_EQ(mink::detail::sign(vol.bdc), ref.sign[3]);
  // The contract against geometry: a proper crossing has no zero volume; None never touches.
  if (ref.proper) {
    EXPECT_TRUE(ref.sign[0] && ref.sign[1] && ref.sign[2] && ref.sign[3]);
  }
  if (got == ArcIntersection::None) {
    EXPECT_FALSE(ref.touch);
  }
  if (got == ArcIntersection::Proper) {
    // The direction is on the crossing line, strictly inside both arcs.
    const V3<Q> n = mink::arcIntersectionDirection(a, b, vol);
    EXPECT_TRUE(isZero(cross(n, cross(cross(a, b), cross(c, d)))));
    EXPECT_TRUE(onArc(n, a, b, false));
    EXPECT_TRUE(onArc(n, c, d, false));
  }
  if (deep) {
    EXPECT_EQ(mink::arcsIntersect(a, b, c, d), ref.proper);
    EXPECT_EQ(mink::classifyArcs(a, b, c, d), ref.cls);  // the vector overload
    // Arcs of -Q: volumes of (a, b, -c, -d) against the reference of the negated arc.
    EXPECT_EQ(mink::classifyArcs(vol.negatedSecondArc()),
              reference(z.v[0], z.v[1], V3<Z>(-z.v[2]), V3<Z>(-z.v[3])).cls);
    // Swapping the arcs or reversing one does not change the class.
    EXPECT_EQ(mink::classifyArcs(c, d, a, b), ref.cls);
    EXPECT_EQ(mink::classifyArcs(b, a, c, d), ref.cls);
    EXPECT_EQ(mink::classifyArcs(a, b, d, c), ref.cls);
  }
}

// ---- input families ------------------------------------------------------------------
struct Family {
  std::string name;
  std::vector<Arcs> cases;
};

V3<double> onSphere(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  for (;;) {
    V3<double> v(g(rng), g(rng), g(rng));
    const double n = v.norm();
    if (n > 1e-3) return v / n;
  }
}

double logUniform(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

std::vector<Family> families(std::mt19937& rng, int scale) {
  std::vector<Family> fam;
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  auto tiny = [&](double lo, double hi) {  // perturbation of random direction, length in [lo, hi]
    return V3<double>(onSphere(rng) * logUniform(rng, lo, hi));
  };
  auto unit = [&]() { return onSphere(rng); };

  Family random{"random", {}};
  for (int i = 0; i < 100000 / scale; ++i) random.cases.push_back({unit(), unit(), unit(), unit()});
  fam.push_back(random);

  // Small integers: exact in double, and full of exact degeneracies.
  Family ints{"small-integers", {}};
  std::uniform_int_distribution<int> si(-2, 2);
  auto iv = [&]() { return V3<double>(si(rng), si(rng), si(rng)); };
  while (static_cast<int>(ints.cases.size()) < 20000 / scale) {
    Arcs x{iv(), iv(), iv(), iv()};
    if (x[0].cross(x[1]).squaredNorm() == 0 || x[2].cross(x[3]).squaredNorm() == 0) continue;
    ints.cases.push_back(x);
  }
  fam.push_back(ints);

  Family shared{"shared-endpoints", {}};
  for (int i = 0; i < 3000 / scale; ++i) {
    const V3<double> a = unit(), b = unit(), d = unit();
    shared.cases.push_back({a, b, a, d});                 // c = a
    shared.cases.push_back({a, b, d, b});                 // d = b
    shared.cases.push_back({a, b, V3<double>(2 * a), d});  // exact positive multiple
    shared.cases.push_back({a, b, V3<double>(3 * a), d});  // rounded multiple: nearly shared
    shared.cases.push_back({a, b, V3<double>(a + tiny(1e-16, 1e-9)), d});
  }
  fam.push_back(shared);

  Family onCircle{"endpoint-on-great-circle", {}};
  for (int i = 0; i < 8000 / scale; ++i) {
    const V3<double> a = unit(), b = unit(), d = unit();
    const double lambda = uni(rng), mu = uni(rng);  // inside the arc or outside it
    V3<double> c = lambda * a + mu * b;
    if (i % 2) c += tiny(1e-15, 1e-9);
    if (c.squaredNorm() < 1e-6) continue;
    onCircle.cases.push_back({a, b, c, d});
    onCircle.cases.push_back({c, d, a, b});
  }
  fam.push_back(onCircle);

  Family antipodal{"antipodal-adjacent", {}};
  for (int i = 0; i < 8000 / scale; ++i) {
    const V3<double> a = unit(), b = unit(), d = unit();
    antipodal.cases.push_back({a, b, V3<double>(-a + tiny(1e-15, 1e-9)), d});
    antipodal.cases.push_back({a, b, V3<double>(-b + tiny(1e-15, 1e-9)), V3<double>(-a + tiny(1e-15, 1e-9))});
  }
  fam.push_back(antipodal);

  Family coplanar{"near-coplanar", {}};
  for (int i = 0; i < 8000 / scale; ++i) {
    const V3<double> m = unit();
    Arcs x;
    for (auto& v : x) {
      const V3<double> r = unit();
      v = r - r.dot(m) * m;  // rounded: within ~1e-16 of the plane
      if (i % 3) v += m * (uni(rng) * logUniform(rng, 1e-15, 1e-9));
    }
    coplanar.cases.push_back(x);
  }
  // Exactly coplanar in double as well: all z = 0.
  for (int i = 0; i < 2000 / scale; ++i) {
    Arcs x;
    for (auto& v : x) v = V3<double>(uni(rng), uni(rng), 0.0);
    coplanar.cases.push_back(x);
  }
  fam.push_back(coplanar);

  Family longArcs{"long-arcs", {}};
  for (int i = 0; i < 8000 / scale; ++i) {
    const V3<double> a = unit();
    const V3<double> b = -a + tiny(1e-12, 1e-3);  // arc a-b just under pi
    const V3<double> c = unit();
    const V3<double> d = i % 2 ? V3<double>(-c + tiny(1e-12, 1e-3)) : unit();
    longArcs.cases.push_back({a, b, c, d});
  }
  fam.push_back(longArcs);
  return fam;
}

#ifdef __SANITIZE_ADDRESS__
constexpr int kScale = 4;  // sanitizer builds: a quarter of the cases
#else
constexpr int kScale = 1;
#endif

// One exact reference per case serves the Gmpq instantiation, double and long double
// (a double is exactly a long double, so the inputs and the reference are the same).
TEST(ArcIntersection, ExactDoubleLongDoubleAgainstReference) {
  const unsigned seed = 20240611;
  std::mt19937 rng(seed);
  for (const Family& f : families(rng, kScale)) {
    Stats sq, sd, sl;
    for (std::size_t i = 0; i < f.cases.size(); ++i) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", family " + f.name + ", case " +
                   std::to_string(i));
      const Arcs& x = f.cases[i];
      const ScaledInput<double> z = toIntegers(x);
      if (isZero(cross(z.v[0], z.v[1])) || isZero(cross(z.v[2], z.v[3]))) continue;
      const Reference ref = reference(z.v[0], z.v[1], z.v[2], z.v[3]);
      checkExact(x, z, ref, i % 8 == 0, sq);
      if (HasFatalFailure()) return;
      checkFloating<double>(x, z, ref, sd);
      std::array<V3<long double>, 4> xl;
      for (int k = 0; k < 4; ++k) xl[k] = x[k].cast<long double>();
      checkFloating<long double>(xl, toIntegers(xl), ref, sl);
    }
    std::printf("%-25s cases %6ld (proper %6ld none %6ld degenerate %6ld) | double: plain "
                "checked %6ld, filter uncertain %6ld, rounded signs wrong %5ld (exact: 0) | long double: "
                "%6ld, %6ld\n",
                f.name.c_str(), sq.cases, sq.proper, sq.none, sq.degenerate, sd.checkedPlain,
                sd.uncertain, sd.plainWrong, sl.checkedPlain, sl.uncertain);
    EXPECT_GT(sq.cases, 0);
  }
}

// float: the inputs rounded to float (near-degenerate perturbations below float's
// precision often become exact degeneracies), with their own exact reference.
TEST(ArcIntersection, FloatAgainstReference) {
  const unsigned seed = 8;
  std::mt19937 rng(seed);
  for (const Family& f : families(rng, 4 * kScale)) {
    Stats st;
    for (std::size_t i = 0; i < f.cases.size(); ++i) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", family " + f.name + ", case " +
                   std::to_string(i));
      std::array<V3<float>, 4> x;
      for (int k = 0; k < 4; ++k) x[k] = f.cases[i][k].cast<float>();
      const ScaledInput<float> z = toIntegers(x);
      if (isZero(cross(z.v[0], z.v[1])) || isZero(cross(z.v[2], z.v[3]))) continue;
      checkFloating<float>(x, z, reference(z.v[0], z.v[1], z.v[2], z.v[3]), st);
    }
    std::printf("float %-25s cases %6ld | plain checked %6ld, filter uncertain %6ld, rounded signs wrong %5ld "
                "(exact: 0)\n",
                f.name.c_str(), st.cases, st.checkedPlain, st.uncertain, st.plainWrong);
  }
}

// Small integers: every operation of det3 is exact in double, so double must match the
// exact class on every input, Degenerate included.
TEST(ArcIntersection, DoubleIsExactOnSmallIntegers) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> si(-3, 3);
  auto iv = [&]() { return V3<double>(si(rng), si(rng), si(rng)); };
  int degenerate = 0;
  for (int i = 0; i < 20000 / kScale; ++i) {
    const V3<double> a = iv(), b = iv(), c = iv(), d = iv();
    if (a.cross(b).squaredNorm() == 0 || c.cross(d).squaredNorm() == 0) continue;
    const ScaledInput<double> z = toIntegers(Arcs{a, b, c, d});
    const Reference ref = reference(z.v[0], z.v[1], z.v[2], z.v[3]);
    SCOPED_TRACE("case " + std::to_string(i));
    ASSERT_EQ(mink::classifyArcs(a, b, c, d), ref.cls);
    degenerate += ref.cls == ArcIntersection::Degenerate;
  }
  EXPECT_GT(degenerate, 100 / kScale);  // the family does exercise the degenerate branch
}

// Positive scaling of each vector never changes the exact class; in double, scaling by
// powers of two is exact, so without overflow/underflow the class is unchanged, and the
// filter stays sound even when the products over- or underflow.
TEST(ArcIntersection, InvariantUnderPositiveScaling) {
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> num(1, 1000), expo(-400, 400), smallExpo(-100, 100);
  long uncertain = 0;
  for (int i = 0; i < 5000 / kScale; ++i) {
    Arcs x{onSphere(rng), onSphere(rng), onSphere(rng), onSphere(rng)};
    if (i % 4 == 0) x[2] = x[0] + 1e-12 * onSphere(rng);  // nearly shared endpoint
    const V3<Q> qa = exact(x[0]), qb = exact(x[1]), qc = exact(x[2]), qd = exact(x[3]);
    const ArcIntersection ref = reference(qa, qb, qc, qd).cls;
    SCOPED_TRACE("case " + std::to_string(i));
    // Exact: random positive rationals.
    const Q s[4] = {Q(num(rng), num(rng)), Q(num(rng), num(rng)), Q(num(rng), num(rng)),
                    Q(num(rng), num(rng))};
    EXPECT_EQ(mink::classifyArcs(V3<Q>(qa * s[0]), V3<Q>(qb * s[1]), V3<Q>(qc * s[2]),
                                 V3<Q>(qd * s[3])),
              ref);
    // Double, moderate powers of two: identical signs.
    Arcs y = x;
    for (auto& v : y) v *= std::ldexp(1.0, smallExpo(rng));
    EXPECT_EQ(mink::classifyArcs(y[0], y[1], y[2], y[3]), mink::classifyArcs(x[0], x[1], x[2], x[3]));
    // Double, extreme powers of two: the filter answers correctly or says Uncertain.
    for (auto& v : y) v = v * std::ldexp(1.0, expo(rng));
    const ArcIntersection f = mink::classifyArcsFiltered(y[0], y[1], y[2], y[3]);
    if (f == ArcIntersection::Uncertain)
      ++uncertain;
    else
      EXPECT_EQ(f, ref);
  }
  EXPECT_GT(uncertain, 0);  // some scalings do over/underflow
}

// Components near 2^-358 make every triple product land in the subnormal range, where
// rounding is absolute, not relative: the filter must still never certify a wrong sign
// (this is what the min_normal term of its bound is for).
TEST(ArcIntersection, FilterIsSoundWhenProductsUnderflow) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> mant(-1.0, 1.0);
  // Odd cases: products entirely subnormal (nothing can be certified there); even cases:
  // products just above the normal range, where the filter certifies most signs.
  std::uniform_int_distribution<int> subnormal(-362, -355), low(-340, -330);
  long certified = 0;
  for (int i = 0; i < 40000 / kScale; ++i) {
    Arcs x;
    for (auto& v : x)
      for (int k = 0; k < 3; ++k) v[k] = std::ldexp(mant(rng), i % 2 ? subnormal(rng) : low(rng));
    SCOPED_TRACE("case " + std::to_string(i));
    const ScaledInput<double> z = toIntegers(x);
    if (isZero(cross(z.v[0], z.v[1])) || isZero(cross(z.v[2], z.v[3]))) continue;
    const Reference ref = reference(z.v[0], z.v[1], z.v[2], z.v[3]);
    const int s = mink::detail::filteredSign(x[2], x[1], x[0]);
    if (s != 2) {
      ++certified;
      EXPECT_EQ(s, ref.sign[0]);
    }
    const ArcIntersection f = mink::classifyArcsFiltered(x[0], x[1], x[2], x[3]);
    if (f != ArcIntersection::Uncertain) {
      EXPECT_EQ(f, ref.cls);
    }
    // Below 2^-306 the exact stage runs in long double, where it has the range.
    if (std::numeric_limits<long double>::min_exponent < -4000) {
      EXPECT_EQ(mink::classifyArcsExact(x[0], x[1], x[2], x[3]), ref.cls);
    }
  }
  EXPECT_GT(certified, 0);
}

// The Proper test and the direction on a hand-made configuration: two quarter arcs on the
// equator and a meridian cross at (1, 1, 0)/√2 direction... and miss on the far side.
TEST(ArcIntersection, HandMadeCases) {
  using V = V3<double>;
  const V a(1, 0, 0), b(0, 1, 0);                      // equator, x to y
  const V c(1, 1, -1), d(1, 1, 1);                     // meridian through (1,1,0)
  EXPECT_EQ(mink::classifyArcs(a, b, c, d), ArcIntersection::Proper);
  const V n = mink::arcIntersectionDirection(a, b, c, d);
  EXPECT_GT(n[0], 0);
  EXPECT_DOUBLE_EQ(n[0], n[1]);
  EXPECT_EQ(n[2], 0);
  // The antipodal meridian: crosses the great circle of a-b at -(1,1,0), outside the arc.
  EXPECT_EQ(mink::classifyArcs(a, b, V(-c), V(-d)), ArcIntersection::None);
  EXPECT_EQ(mink::classifyArcs(mink::arcVolumes(a, b, c, d).negatedSecondArc()),
            ArcIntersection::None);
  // Shared endpoint and endpoint on the arc: Degenerate; strictly one side: None.
  EXPECT_EQ(mink::classifyArcs(a, b, a, d), ArcIntersection::Degenerate);
  EXPECT_EQ(mink::classifyArcs(a, b, V(1, 1, 0), d), ArcIntersection::Degenerate);
  EXPECT_EQ(mink::classifyArcs(a, b, V(1, 1, 1), V(0, 1, 1)), ArcIntersection::None);
  EXPECT_EQ(mink::classifyArcs(a, b, V(1, 0, 1), V(1, 0, 2)), ArcIntersection::None);
  // Collinear, overlapping: Degenerate.
  EXPECT_EQ(mink::classifyArcs(a, b, V(1, 1, 0), V(-1, 2, 0)), ArcIntersection::Degenerate);
  EXPECT_FALSE(mink::arcsIntersect(a, b, a, d));
  EXPECT_TRUE(mink::arcsIntersect(a, b, c, d));
  // The filter certifies clear cases and refuses exact ties.
  EXPECT_EQ(mink::classifyArcsFiltered(a, b, c, d), ArcIntersection::Proper);
  EXPECT_EQ(mink::classifyArcsFiltered(a, b, a, d), ArcIntersection::Uncertain);
  EXPECT_EQ(mink::classifyArcsFiltered(a, b, V(-c), V(-d)), ArcIntersection::None);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(mink::classifyArcsFiltered(a, b, V(inf, 1, 0), d), ArcIntersection::Uncertain);
}

}  // namespace
