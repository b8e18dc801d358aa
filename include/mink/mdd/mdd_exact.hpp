// mink/mdd/mdd_exact.hpp — mddExact: the exact status and rational parameter of an MDD
// query on floating-point shapes, certified from the floating-point search's faces.
//
// The double search (mdd.hpp) already finds the face of M = P ⊕ −Q that the line of s
// leaves through; proving that face right is far cheaper than searching in exact
// arithmetic. With the poses applied exactly in the caller's rational type E:
//   1. run mdd<T> (input checks, the answer's face, and for a penetrating query both
//      exits, kept in a local MddCache);
//   2. for each such face of M (FV, VF or EE features): its plane, with normal N, is a
//      supporting plane of M iff the feature of P is a maximum of N·x over P and that of
//      Q a maximum of −N·x over Q; on a shape that is exactly the hull of its vertices
//      (ConvexPolyhedron::isExactHull) a vertex that none of its neighbours beats is a
//      maximum, so this is a test at the features' neighbours;
//   3. the line's point t*·s in that plane (t* = N·(p − q) / N·s, N·s != 0) must lie in
//      the Minkowski difference of the two features (a polygon or parallelogram inside
//      the facet of M): then t* is an end of the chord [t_lo, t_hi] of M on the line, t_lo
//      when N·s < 0 and t_hi when N·s > 0;
//   4. the ends found give the status and parameter of eq. (1) of Choi et al. (MddStatus) (a penetrating
//      answer needs both ends). A NoContact answer is certified by its separating
//      direction u (MddResult::normal), made exactly orthogonal to s: M's support along
//      u, found by hill-climbing from the search's vertices, is below 0. When neither
//      certificate holds, mdd<E> on exact copies of the shapes answers (`certified` false).
// Every test above is the sign of a polynomial in the input numbers, written without
// division (detail/face_certificate.hpp). Each is evaluated first in an interval of T,
// which decides it unless the value is a tie or below the rounding; only then in E. The
// parameter returned is evaluated in E, once. Nothing is rounded.
#pragma once

#include <type_traits>
#include <utility>
#include <vector>

#include "mink/mdd/detail/face_certificate.hpp"
#include "mink/mdd/mdd.hpp"

namespace mink {

/// Result of mddExact. `parameter` is exact: moving Q by parameter * s (world
/// frame, s as given) brings P and Q into touching contact; 0 for Touching and NoContact.
template <class E>
struct ExactMdd {
  MddStatus status = MddStatus::NoContact;
  E parameter = E(0);
  /// true: the floating-point search's face was certified exactly (steps 2–4 above);
  /// false: the full mdd<E> on exact copies of the shapes answered.
  bool certified = false;
};

namespace detail {

/// The floating-point type the filter and the expansions of shapes in T work in: T, or
/// double for float (which converts exactly).
template <class T>
using FilterFloatOf = std::conditional_t<std::is_same<T, float>::value, double, T>;
/// The filter's number type: an interval of that type; void for a custom scalar, whose
/// queries go to E directly.
template <class T>
using FilterOf = std::conditional_t<std::is_floating_point<T>::value, IntervalOf<FilterFloatOf<T>>, void>;

/// Step 4's separation certificate in N: the separating direction n made orthogonal to s
/// without dividing, u = (s·s) n − (n·s) s, and M's support along u, from the search's
/// support vertices by proven uphill steps, below 0.
template <class N, class T>
Verdict certifySeparation(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                          const Pose<T>& poseQ, const Vec3<T>& s, const MddResult<T>& r) {
  const PlacedShape<N, T> xP(P, poseP), xQ(Q, poseQ);
  const Triple<N> n = toTriple<N>(r.normal), sN = toTriple<N>(s);
  const Triple<N> u = dot(sN, sN) * n - dot(n, sN) * sN;
  const int p = xP.climb(r.featureP, u), q = xQ.climb(r.featureQ, negated(u));
  if (p == -2 || q == -2) return Verdict::No;
  if (p < 0 || q < 0) return Verdict::Unknown;
  // Below 0 is "not at least 0"; u = 0 (n along s) gives 0, never a certificate.
  const Verdict nonNegative = atMostZero(N(-dot(u, xP.world(p) - xQ.world(q))));
  return nonNegative == Verdict::Unknown ? nonNegative : (nonNegative == Verdict::Yes ? Verdict::No : Verdict::Yes);
}

/// The chord ends found (t_lo, t_hi as num / den) and eq. (1) decided from their signs
/// without dividing: sign(t) = sign(num)·sign(den), den < 0 at t_lo and > 0 at t_hi.
template <class N>
struct ChordEnds {
  bool have[2] = {false, false};  // [0] t_lo, [1] t_hi
  N num[2] = {N(0), N(0)}, den[2] = {N(0), N(0)};
  int face[2] = {-1, -1};         // index of the face that gave the end
};
struct ChordDecision {
  Verdict decided = Verdict::No;  // Unknown: a sign the interval cannot tell
  MddStatus status = MddStatus::NoContact;
  int end = -1;                   // 0 / 1: the parameter is t_lo / t_hi; -1: 0
};
template <class N>
ChordDecision decideChord(const ChordEnds<N>& c) {
  ChordDecision d;
  const int sLo = c.have[0] ? signOf(c.num[0]) : 0, sHi = c.have[1] ? signOf(c.num[1]) : 0;
  if (sLo == kUnknownSign || sHi == kUnknownSign) {
    d.decided = Verdict::Unknown;
    return d;
  }
  d.decided = Verdict::Yes;
  if (c.have[0] && sLo < 0) {  // t_lo > 0: the origin is before the chord
    d.status = MddStatus::Separated;
    d.end = 0;
  } else if (c.have[1] && sHi < 0) {  // t_hi < 0: after it
    d.status = MddStatus::Separated;
    d.end = 1;
  } else if ((c.have[0] && sLo == 0) || (c.have[1] && sHi == 0)) {
    d.status = MddStatus::Touching;
  } else if (c.have[0] && c.have[1]) {
    // t_lo < 0 < t_hi: the nearer end, t_hi on a tie. sign(t_hi + t_lo) is that of
    // (t_hi + t_lo)·den_hi·(−den_lo), den_hi·(−den_lo) > 0.
    const int sSum = signOf(N(-(c.num[1] * c.den[0]) - c.num[0] * c.den[1]));
    if (sSum == kUnknownSign) {
      d.decided = Verdict::Unknown;
      return d;
    }
    d.status = MddStatus::Penetrating;
    d.end = sSum <= 0 ? 1 : 0;
  } else {
    d.decided = Verdict::No;
  }
  return d;
}

/// Steps 2–4 for the double search's faces: each face tested in the filter F first and in
/// E when F cannot tell; eq. (1) decided likewise; the parameter evaluated in E once.
/// false when no certificate holds.
template <class E, class F, class T>
bool certifyChord(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                  const Pose<T>& poseQ, const Vec3<T>& s, const MddCachedFace (&faces)[3], ExactMdd<E>& out) {
  constexpr bool kFilter = !std::is_void<F>::value;
  using FN = std::conditional_t<kFilter, F, E>;  // unused when there is no filter
  const PlacedShape<E, T> eP(P, poseP), eQ(Q, poseQ);
  const Triple<E> sE = toTriple<E>(s);
  ChordEnds<FN> ends;    // ends proven in the filter
  ChordEnds<E> exact;    // in E (every end, once one needs E)
  bool anyExact = false;
  for (int i = 0; i < 3; ++i) {
    const MddCachedFace& f = faces[i];
    bool seen = f.type == MddFaceType::None;
    for (int j = 0; j < i; ++j) seen |= faces[j].type == f.type && faces[j].a == f.a && faces[j].b == f.b;
    if (seen) continue;
    Verdict v = Verdict::Unknown;
    if constexpr (kFilter) {
      const PlacedShape<FN, T> fP(P, poseP), fQ(Q, poseQ);
      const FaceEnd<FN> e = testFace(f, fP, fQ, toTriple<FN>(s), true);
      v = e.valid;
      if (v == Verdict::Yes) {
        ends.have[e.isHi] = true;
        ends.num[e.isHi] = e.num;
        ends.den[e.isHi] = e.den;
        ends.face[e.isHi] = i;
        exact.have[e.isHi] = false;  // a later face replaces an earlier end
      }
    }
    if (v == Verdict::Unknown) {
      const FaceEnd<E> e = testFace(f, eP, eQ, sE, true);
      if (e.valid == Verdict::Yes) {
        anyExact = true;
        exact.have[e.isHi] = true;
        exact.num[e.isHi] = e.num;
        exact.den[e.isHi] = e.den;
        exact.face[e.isHi] = i;
        ends.have[e.isHi] = false;
      }
    }
  }
  auto exactEnd = [&](int k) {  // t_lo / t_hi in E, evaluated once
    if (exact.have[k]) return;
    exact.have[k] = true;
    const MddCachedFace& f = faces[ends.face[k]];
    bool done = false;
    if constexpr (kFilter) {
      // An expansion of doubles, rounded to E at the end, where its range allows: a few
      // E operations instead of about a hundred.
      if (inExpansionRange(f, P, poseP, Q, poseQ, s)) {
        using X = ExpansionOf<FilterFloatOf<T>>;
        const PlacedShape<X, T> xP(P, poseP), xQ(Q, poseQ);
        const FaceEnd<X> e = testFace(f, xP, xQ, toTriple<X>(s), false);
        exact.num[k] = e.num.template exactValue<E>();
        exact.den[k] = e.den.template exactValue<E>();
        done = true;
      }
    }
    if (!done) {
      const FaceEnd<E> e = testFace(f, eP, eQ, sE, false);
      exact.num[k] = e.num;
      exact.den[k] = e.den;
    }
    // Unchecked, an EE face's normal may point either way: den takes the sign of its end
    // (< 0 at t_lo), on which decideChord relies.
    if ((k == 1) != (exact.den[k] > E(0))) {
      exact.num[k] = -exact.num[k];
      exact.den[k] = -exact.den[k];
    }
  };
  ChordDecision d;
  d.decided = Verdict::Unknown;
  if constexpr (kFilter) {
    if (!anyExact) d = decideChord(ends);
  }
  if (d.decided == Verdict::Unknown) {
    for (int k = 0; k < 2; ++k)
      if (ends.have[k]) exactEnd(k);
    d = decideChord(exact);
  }
  if (d.decided != Verdict::Yes) return false;
  out.status = d.status;
  out.certified = true;
  if (d.end >= 0) {
    exactEnd(d.end);
    out.parameter = exact.num[d.end] / exact.den[d.end];
  }
  return true;
}

/// The full exact query on the exact hulls of the same vertices, placed in the world
/// exactly (mdd<E> accepts only exactly orthonormal rotations; the rounded rotation of a
/// double pose is applied here as the affine map it is).
template <class E, class T>
ExactMdd<E> mddExactFallback(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                             const Pose<T>& poseQ, const Vec3<T>& s, const MddOptions<T>& options) {
  auto placed = [](const ConvexPolyhedron<T>& X, const Pose<T>& pose) {
    const PlacedShape<E, T> x(X, pose);
    std::vector<Vec3<E>> pts;
    pts.reserve(static_cast<std::size_t>(X.numVertices()));
    for (int v = 0; v < X.numVertices(); ++v) {
      const Triple<E> w = x.world(v);
      pts.emplace_back(w[0], w[1], w[2]);
    }
    return ConvexPolyhedron<E>::fromPoints(pts);
  };
  const auto PE = placed(P, poseP);
  const auto QE = placed(Q, poseQ);
  MddOptions<E> optionsE;
  optionsE.maxVisits = options.maxVisits;
  optionsE.maxExhaustivePairs = options.maxExhaustivePairs;
  optionsE.useHierarchy = options.useHierarchy;
  const MddResult<E> e = mdd(PE, Pose<E>(), QE, Pose<E>(), Vec3<E>(E(s[0]), E(s[1]), E(s[2])), optionsE);
  ExactMdd<E> out;
  out.status = e.status;
  out.parameter = e.status == MddStatus::NoContact ? E(0) : e.parameter;
  out.certified = false;
  return out;
}

}  // namespace detail
/// The exact MDD of floating-point shapes for an exact rational type E supplied by the
/// caller (CGAL::Gmpq, boost::multiprecision::mpq_rational, ...; constructible from T and
/// closed under + − × ÷): the status and parameter of eq. (1) of Choi et al. (MddStatus) for the numbers
/// given, poses applied exactly (x_world = rotation * x + translation, in E), for the
/// convex hulls of the shapes' vertices. See the header comment for how; `certified`
/// says which path answered. Throws InvalidInput as mdd() does (without exceptions: status
/// InvalidInput, parameter 0). Cost: the tests at the
/// features of one or two faces (or at two support vertices) in interval arithmetic, E
/// only where an interval cannot tell (ties) and for the parameter returned, when
/// certified; a full mdd<E>, with the exact hulls of both shapes built first, when not
/// (a line grazing M, a fromMesh shape in floating point: see isExactHull).
template <class E, class T>
ExactMdd<E> mddExact(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                     const Pose<T>& poseQ, const Vec3<T>& s, const MddOptions<T>& options = {}) {
  static_assert(!ScalarTraits<T>::isExact, "mddExact: the shapes are floating point; call mdd<E> on exact shapes");
  static_assert(ScalarTraits<E>::isExact, "mddExact: E must be an exact rational type");
  static_assert(std::is_constructible<E, T>::value, "mddExact: E must be constructible from the shapes' scalar");
  using F = detail::FilterOf<T>;
  MddCache<T> cache;
  // Checks the input; both exits of a penetrating line, for the chord's certificate.
  const MddResult<T> r = detail::mddQuery(P, poseP, Q, poseQ, s, cache, options, true);
  if (r.status == MddStatus::InvalidInput) {  // builds without exceptions only
    ExactMdd<E> out;
    out.status = MddStatus::InvalidInput;
    out.parameter = E(0);
    out.certified = false;
    return out;
  }
  if (P.isExactHull() && Q.isExactHull()) {
    if (r.status == MddStatus::NoContact && r.featureP >= 0 && r.featureQ >= 0) {
      detail::Verdict v = detail::Verdict::Unknown;
      if constexpr (!std::is_void<F>::value) v = detail::certifySeparation<F>(P, poseP, Q, poseQ, s, r);
      if (v == detail::Verdict::Unknown) v = detail::certifySeparation<E>(P, poseP, Q, poseQ, s, r);
      if (v == detail::Verdict::Yes) {
        ExactMdd<E> out;
        out.status = MddStatus::NoContact;
        out.certified = true;
        return out;
      }
    } else if (r.status == MddStatus::Separated || r.status == MddStatus::Touching ||
               r.status == MddStatus::Penetrating) {
      const MddCachedFace faces[3] = {MddCachedFace{r.faceType, r.featureP, r.featureQ}, cache.exitFaces[0],
                                      cache.exitFaces[1]};
      ExactMdd<E> out;
      if (detail::certifyChord<E, F>(P, poseP, Q, poseQ, s, faces, out)) return out;
    }
  }
  return detail::mddExactFallback<E>(P, poseP, Q, poseQ, s, options);
}

}  // namespace mink
