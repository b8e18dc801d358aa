// mink/gauss_map/arc_intersection.hpp — do two great arcs on the Gauss sphere S² cross?
//
// Source: Y.-K. Choi, X. Li, F. Rong, W. Wang, S. Cameron, "Computing the Minimum
// Directional Distance between Two Convex Polyhedra" (MDD-DUAL), section VI-B "To decide
// whether two arcs on S² intersect", used by SEARCH-EE (section IV-B) to find the EE faces of
// M = P ⊕ −Q: edges e_p of P and e_q of −Q span a face of M iff their arcs cross.
// With arcs a–b and c–d, o the centre of the sphere and |xyz| = det[x y z]:
//   1. Compute the four signed volumes |cba|, |dba|, |adc|, |bdc| (and nothing else).
//   2. c, d strictly on opposite sides of the plane oab:   |cba|·|dba| < 0.
//   3. a, b strictly on opposite sides of the plane ocd:   |adc|·|bdc| < 0.
//   4. The crossing points of steps 2 and 3 coincide (all four points in one hemisphere,
//      a and d on the same side of the plane ocb): |acb|·|dcb| > 0, where |acb| = |cba|
//      and |dcb| = |bdc|.
// Products are taken of signs only (detail::sign), never of the determinants: that
// cannot overflow or underflow in floating point and stays exact for rational T.
//
// Inputs are arbitrary non-zero vectors (face normals: unit for inexact T, exact Newell
// normals for exact T); every answer is invariant under a positive scaling of each of the
// four vectors, so they need not be normalised. An arc x–y is the shorter great arc from
// x to y; its endpoints must not be parallel (neither equal nor opposite directions) —
// adjacent faces of a ConvexPolyhedron never are. Parallel endpoints make two volumes
// vanish and the answer is Degenerate (or None when the other arc is strictly on one side).
//
// Why Degenerate exists: when a volume is exactly zero an endpoint lies on the other
// arc's great circle (shared endpoints, a vertex of one Gauss map on an arc of the other,
// all four normals coplanar with o). Then the arcs' relative interiors cannot cross
// transversally, but the closed arcs may touch or overlap: the face of M there is a
// merged FV/VF/EE face, which SEARCH-EE has to treat explicitly (paper section VI-C).
#pragma once

#include <limits>
#include <type_traits>

#include "mink/core/difference_orientation.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {

/// How two great arcs a–b and c–d on S² meet.
enum class ArcIntersection {
  /// The relative interiors cross in exactly one point, transversally. All four signed
  /// volumes are non-zero. For Gauss maps G(P), G(−Q): an EE face of M.
  Proper,
  /// The closed arcs are disjoint. Returned when all four volumes are non-zero and the
  /// arcs miss, and also when some volume is zero but one arc lies strictly on one side
  /// of the other's great-circle plane (then not even the endpoints can touch).
  None,
  /// Some signed volume is exactly zero (as evaluated in T) and neither arc is strictly
  /// on one side of the other's plane: no proper crossing; the closed arcs may touch at an
  /// endpoint, overlap along their common great circle, or miss.
  Degenerate,
  /// Only from classifyArcsFiltered: a sign needed for the decision lies within the
  /// floating-point error bound of its determinant; redo the test exactly.
  Uncertain
};

/// The four signed volumes of section VI-B for arcs a–b and c–d (same unit as the product
/// of three input lengths; only their signs are meaningful to the predicate).
template <class T>
struct ArcVolumes {
  T cba;  ///< det[c b a]; > 0 iff c is on the side of plane oab that b×a points to
  T dba;  ///< det[d b a]
  T adc;  ///< det[a d c]
  T bdc;  ///< det[b d c]

  /// The volumes of the arcs a–b and (−c)–(−d): det is linear in each column, so the
  /// first two flip sign and the last two (two negated columns) do not. This is how the
  /// arcs of G(−Q) are tested without building negated normals.
  ArcVolumes negatedSecondArc() const { return {T(-cba), T(-dba), adc, bdc}; }
};

namespace detail {

/// det[x y z] = x · (y × z), evaluated as written (three 2x2 minors, then a dot product)
/// so that classifyArcsFiltered's error bound applies to exactly this evaluation order.
template <class T>
T det3(const Vec3<T>& x, const Vec3<T>& y, const Vec3<T>& z) {
  const T m0 = y[1] * z[2] - y[2] * z[1];
  const T m1 = y[2] * z[0] - y[0] * z[2];
  const T m2 = y[0] * z[1] - y[1] * z[0];
  return x[0] * m0 + x[1] * m1 + x[2] * m2;
}

/// The decision of section VI-B from the signs (-1, 0, +1) of |cba|, |dba|, |adc|, |bdc|.
inline ArcIntersection classifyArcSigns(int cba, int dba, int adc, int bdc) {
  // A strict same-side pair separates the closed arcs whatever the other signs are:
  // every point of the closed arc c–d is a non-negative, non-zero combination of c and d.
  if (cba * dba > 0 || adc * bdc > 0) return ArcIntersection::None;
  if (cba == 0 || dba == 0 || adc == 0 || bdc == 0) return ArcIntersection::Degenerate;
  // Now c–d crosses plane oab at p = |dba| c + |cba| d and a–b crosses plane ocd at
  // q = |bdc| a + |adc| b; both lie on the line of the two planes, so p = ±q. Their
  // sides of plane ocb are sign(p·(c×b)) = sign|dcb| = sign|bdc| and
  // sign(q·(c×b)) = sign|acb| = sign|cba|: equal iff the crossings coincide.
  return cba * bdc > 0 ? ArcIntersection::Proper : ArcIntersection::None;
}

}  // namespace detail

/// The four signed volumes of arcs a–b and c–d (any non-zero vectors, same frame).
template <class T>
ArcVolumes<T> arcVolumes(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                         const Vec3<T>& d) {
  return {detail::det3(c, b, a), detail::det3(d, b, a), detail::det3(a, d, c),
          detail::det3(b, d, c)};
}

/// Classification from already computed volumes (exact for exact T; for inexact T the
/// signs of the rounded volumes are trusted — see classifyArcsFiltered).
template <class T>
ArcIntersection classifyArcs(const ArcVolumes<T>& v) {
  return detail::classifyArcSigns(detail::sign(v.cba), detail::sign(v.dba), detail::sign(v.adc),
                                  detail::sign(v.bdc));
}

/// Classification of the arcs a–b and c–d. Never returns Uncertain.
template <class T>
ArcIntersection classifyArcs(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                             const Vec3<T>& d) {
  return classifyArcs(arcVolumes(a, b, c, d));
}

/// True iff the arcs a–b and c–d cross properly (classifyArcs(...) == Proper).
template <class T>
bool arcsIntersect(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
  return classifyArcs(a, b, c, d) == ArcIntersection::Proper;
}

/// Direction of the crossing point of arcs a–b and c–d, unnormalised:
///   n = |bdc| a + |adc| b = sign(|bdc|) · (a×b)×(c×d).
/// Precondition: classifyArcs(v) == Proper (otherwise the value is meaningless).
/// Sign convention: n is a strictly positive combination of a and b (and, by the
/// Proper test, of c and d), i.e. it points at the crossing, not at its antipode; for
/// unit a, b this means n·(a + b) > 0. For Gauss maps G(P), G(−Q) of the shapes in one
/// frame, n is the outward normal of the EE face of M = P ⊕ −Q (frame of a, b; length
/// unit: that of a times the volumes, no meaning).
/// Built from the volumes rather than from two cross products so that, even after
/// rounding of the volumes, n stays on the arc a–b (between a and b).
template <class T>
Vec3<T> arcIntersectionDirection(const Vec3<T>& a, const Vec3<T>& b, const ArcVolumes<T>& v) {
  return detail::absValue(v.bdc) * a + detail::absValue(v.adc) * b;
}

template <class T>
Vec3<T> arcIntersectionDirection(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                 const Vec3<T>& d) {
  return arcIntersectionDirection(a, b, arcVolumes(a, b, c, d));
}

namespace detail {

/// Sign of det[x y z] evaluated in floating point, or 2 when the rounded value does not
/// certify it.
///
/// Forward error bound (IEEE arithmetic, round to nearest, u = epsilon/2): every monomial
/// x_i y_j z_k of det3 passes through at most five rounded operations (product, minor
/// subtraction, product, two additions), so
///   |fl(det) − det| <= γ5 · perm + U,   perm = Σ_i |x_i| (|y_j z_k| + |y_k z_j|),
/// γ5 = 5u/(1−5u), and U <= 4(‖x‖₁ + 2)·min_normal covers results that underflow, even
/// with flush-to-zero (inputs that are themselves subnormal under denormals-are-zero
/// are not covered). perm is
/// itself evaluated with non-negative terms (relative error <= γ5), and 8u·fl(perm)
/// exceeds γ5·perm with margin for the rounding of the bound itself. A result that
/// overflows (Inf/NaN) never certifies.
template <class T>
int filteredSign(const Vec3<T>& x, const Vec3<T>& y, const Vec3<T>& z) {
  static_assert(std::is_floating_point<T>::value, "filteredSign needs a floating-point T");
  using std::abs;
  const T det = det3(x, y, z);
  const T p0 = abs(y[1] * z[2]) + abs(y[2] * z[1]);
  const T p1 = abs(y[2] * z[0]) + abs(y[0] * z[2]);
  const T p2 = abs(y[0] * z[1]) + abs(y[1] * z[0]);
  const T perm = abs(x[0]) * p0 + abs(x[1]) * p1 + abs(x[2]) * p2;
  const T u = std::numeric_limits<T>::epsilon() / T(2);
  const T underflow =
      T(4) * (abs(x[0]) + abs(x[1]) + abs(x[2]) + T(2)) * std::numeric_limits<T>::min();
  const T bound = T(8) * u * perm + underflow;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 2;  // within the bound, NaN, or an infinite bound
}

}  // namespace detail

/// classifyArcs with a floating-point filter (T = float, double, long double): each
/// volume's sign is used only when |volume| exceeds its forward error bound (see
/// detail::filteredSign). Returns Proper or None when the certified signs decide the
/// predicate as the exact arithmetic on the same inputs would, and Uncertain otherwise —
/// including every input for which the exact answer is Degenerate, since an exact zero
/// cannot be certified in floating point. Callers fall back to an exact evaluation
/// (e.g. classifyArcs on the inputs converted to a rational type).
template <class T>
ArcIntersection classifyArcsFiltered(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                     const Vec3<T>& d) {
  const int cba = detail::filteredSign(c, b, a);
  const int dba = detail::filteredSign(d, b, a);
  const int adc = detail::filteredSign(a, d, c);
  const int bdc = detail::filteredSign(b, d, c);
  // A certified strict same-side pair decides None on its own (see classifyArcSigns).
  const auto certain = [](int s) { return s != 2; };
  if ((certain(cba) && certain(dba) && cba * dba > 0) ||
      (certain(adc) && certain(bdc) && adc * bdc > 0))
    return ArcIntersection::None;
  if (!certain(cba) || !certain(dba) || !certain(adc) || !certain(bdc))
    return ArcIntersection::Uncertain;
  return detail::classifyArcSigns(cba, dba, adc, bdc);
}

/// classifyArcs decided exactly on the given numbers for every T: each volume's sign by
/// det3Sign (core/difference_orientation.hpp: the filter above, then expansion arithmetic
/// when it cannot tell). Never Uncertain; Degenerate exactly when a volume of the given
/// vectors is zero. Floating-point T: exact while every coordinate is within
/// ScalarTraits<T>::largestCoordinate() (unit normals always are).
template <class T>
ArcIntersection classifyArcsExact(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
  return detail::classifyArcSigns(det3Sign(c, b, a), det3Sign(d, b, a), det3Sign(a, d, c), det3Sign(b, d, c));
}

}  // namespace mink
