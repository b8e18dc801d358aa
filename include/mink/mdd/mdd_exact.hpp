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
//   4. the ends found give the status and parameter of DESIGN.md eq. (1) (a penetrating
//      answer needs both ends). A NoContact answer is certified by its separating
//      direction u (MddResult::normal), made exactly orthogonal to s: M's support along
//      u, found by exact hill-climbing from the search's vertices, is below 0. When
//      neither certificate holds, mdd<E> on exact copies of the shapes answers
//      (`certified` false). Every test above is a sign of a polynomial in the
//      input numbers, evaluated in E: nothing is rounded.
#pragma once

#include <type_traits>
#include <utility>
#include <vector>

#include "mink/mdd/mdd.hpp"

namespace mink {

/// Result of mddExact (DESIGN.md). `parameter` is exact: moving Q by parameter * s (world
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

/// A shape placed in the world exactly, in E: x_world = R x + t with the pose's numbers.
template <class E, class T>
class ExactPlacement {
 public:
  ExactPlacement(const ConvexPolyhedron<T>& X, const Pose<T>& pose) : X_(X) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) R_(r, c) = E(pose.rotation(r, c));
      t_[r] = E(pose.translation[r]);
    }
  }
  Vec3<E> local(int v) const {
    const Vec3<T>& x = X_.vertex(v);
    return Vec3<E>(E(x[0]), E(x[1]), E(x[2]));
  }
  Vec3<E> world(int v) const { return R_ * local(v) + t_; }
  /// Is vertex v a maximum of n·x over the shape (n in the world frame)? n·R(w − v) =
  /// (Rᵀn)·(w − v) for each neighbour w; local is global on an exact hull.
  bool isMaximum(int v, const Vec3<E>& n) const {
    const Vec3<E> m = R_.transpose() * n;
    const Vec3<E> x = local(v);
    for (int w : X_.vertexNeighbors(v))
      if (m.dot(local(w) - x) > E(0)) return false;
    return true;
  }
  /// Newell normal of face f in the world (exact: the face is exactly planar, and its
  /// direction is outward since det R > 0), with its corners.
  Vec3<E> faceNormal(int f, std::vector<Vec3<E>>& corners) const {
    corners.clear();
    for (int v : X_.faceVertices(f)) corners.push_back(world(v));
    Vec3<E> n = Vec3<E>::Zero();
    for (std::size_t i = 0; i < corners.size(); ++i) n += corners[i].cross(corners[(i + 1) % corners.size()]);
    return n;
  }
  /// From vertex v, to a maximum of n·x over the shape by exact hill-climbing (each step
  /// strictly better, so at most one visit per vertex); -1 past that bound.
  int climb(int v, const Vec3<E>& n) const {
    const Vec3<E> m = R_.transpose() * n;
    for (int steps = 0; steps <= X_.numVertices(); ++steps) {
      const Vec3<E> x = local(v);
      int better = -1;
      for (int w : X_.vertexNeighbors(v))
        if (m.dot(local(w) - x) > E(0)) {
          better = w;
          break;
        }
      if (better < 0) return v;
      v = better;
    }
    return -1;
  }
  const ConvexPolyhedron<T>& shape() const { return X_; }

 private:
  const ConvexPolyhedron<T>& X_;
  Mat3<E> R_;
  Vec3<E> t_;
};

/// Is y in the convex polygon `corners` (counter-clockwise about n), boundary included?
template <class E>
bool inConvexPolygon(const std::vector<Vec3<E>>& corners, const Vec3<E>& n, const Vec3<E>& y) {
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3<E>& a = corners[i];
    const Vec3<E>& b = corners[(i + 1) % corners.size()];
    if ((b - a).cross(y - a).dot(n) < E(0)) return false;
  }
  return true;
}

/// One end of M's chord on the line of s, proven exactly.
template <class E>
struct ExactChordEnd {
  bool valid = false;
  bool isHi = false;  // t_hi (the line leaves M going along +s) rather than t_lo
  E t = E(0);
};

/// Steps 2 and 3 of the header for one face of M.
template <class E, class T>
ExactChordEnd<E> certifyFace(const MddCachedFace& face, const ExactPlacement<E, T>& P,
                             const ExactPlacement<E, T>& Q, const Vec3<E>& s) {
  ExactChordEnd<E> end;
  std::vector<Vec3<E>> corners;
  Vec3<E> N;
  E den;
  switch (face.type) {
    case MddFaceType::FV: {  // face a of P, vertex b of Q: the facet holds face(a) − q_b
      N = P.faceNormal(face.a, corners);
      if (N == Vec3<E>::Zero() || !Q.isMaximum(face.b, Vec3<E>(-N))) return end;
      den = N.dot(s);
      if (den == E(0)) return end;
      const Vec3<E> q = Q.world(face.b);
      end.t = N.dot(corners[0] - q) / den;
      if (!inConvexPolygon(corners, N, Vec3<E>(end.t * s + q))) return end;
      break;
    }
    case MddFaceType::VF: {  // vertex a of P, face b of Q: the facet holds p_a − face(b)
      const Vec3<E> NQ = Q.faceNormal(face.b, corners);
      N = -NQ;
      if (N == Vec3<E>::Zero() || !P.isMaximum(face.a, N)) return end;
      den = N.dot(s);
      if (den == E(0)) return end;
      const Vec3<E> p = P.world(face.a);
      end.t = N.dot(p - corners[0]) / den;
      if (!inConvexPolygon(corners, NQ, Vec3<E>(p - end.t * s))) return end;
      break;
    }
    case MddFaceType::EE: {  // edge a of P, edge b of Q: the facet holds e_P − e_Q
      const std::pair<int, int> ep = P.shape().edgeVertices(face.a), eq = Q.shape().edgeVertices(face.b);
      const int pa = ep.first, pb = ep.second, qa = eq.first, qb = eq.second;
      const Vec3<E> p0 = P.world(pa), q0 = Q.world(qa);
      const Vec3<E> eP = P.world(pb) - p0, eQ = Q.world(qb) - q0;
      const Vec3<E> d = eP.cross(eQ);
      if (d == Vec3<E>::Zero()) return end;
      auto supports = [&](const Vec3<E>& n) {
        return P.isMaximum(pa, n) && P.isMaximum(pb, n) && Q.isMaximum(qa, Vec3<E>(-n)) &&
               Q.isMaximum(qb, Vec3<E>(-n));
      };
      if (supports(d))
        N = d;
      else if (supports(Vec3<E>(-d)))
        N = -d;
      else
        return end;
      den = N.dot(s);
      if (den == E(0)) return end;
      end.t = N.dot(p0 - q0) / den;
      // t*s − p0 + q0 = α e_P − β e_Q with α, β in [0, 1]: α (d·d) = (y × e_Q)·d and
      // β (d·d) = (y × e_P)·d.
      const Vec3<E> y = end.t * s - p0 + q0;
      const E dd = d.dot(d), a = y.cross(eQ).dot(d), b = y.cross(eP).dot(d);
      if (a < E(0) || a > dd || b < E(0) || b > dd) return end;
      break;
    }
    default:
      return end;
  }
  end.valid = true;
  end.isHi = den > E(0);
  return end;
}

}  // namespace detail

/// The exact MDD of floating-point shapes for an exact rational type E supplied by the
/// caller (CGAL::Gmpq, boost::multiprecision::mpq_rational, ...; constructible from T and
/// closed under + − × ÷): the status and parameter of DESIGN.md eq. (1) for the numbers
/// given, poses applied exactly (x_world = rotation * x + translation, in E), for the
/// convex hulls of the shapes' vertices. See the header comment for how; `certified`
/// says which path answered. Throws InvalidInput as mdd() does. Cost: a few exact
/// evaluations at the features of one or two faces (or at two support vertices) when
/// certified; a full mdd<E>, with the exact hulls of both shapes built first, when not
/// (a line grazing M, a fromMesh shape in floating point: see isExactHull).
template <class E, class T>
ExactMdd<E> mddExact(const ConvexPolyhedron<T>& P, const Pose<T>& poseP, const ConvexPolyhedron<T>& Q,
                     const Pose<T>& poseQ, const Vec3<T>& s, const MddOptions<T>& options = {}) {
  static_assert(!ScalarTraits<T>::isExact, "mddExact: the shapes are floating point; call mdd<E> on exact shapes");
  static_assert(ScalarTraits<E>::isExact, "mddExact: E must be an exact rational type");
  static_assert(std::is_constructible<E, T>::value, "mddExact: E must be constructible from the shapes' scalar");
  MddCache<T> cache;
  const MddResult<T> r = mdd(P, poseP, Q, poseQ, s, cache, options);  // checks the input
  const Vec3<E> sE{E(s[0]), E(s[1]), E(s[2])};
  ExactMdd<E> out;
  if (P.isExactHull() && Q.isExactHull() && r.status == MddStatus::NoContact && r.featureP >= 0 &&
      r.featureQ >= 0) {
    // The separating direction, made exactly orthogonal to s: if M's support along it is
    // below 0, every point t*s of the line (on which u·x = 0) is outside M.
    const detail::ExactPlacement<E, T> xP(P, poseP), xQ(Q, poseQ);
    const Vec3<E> n{E(r.normal[0]), E(r.normal[1]), E(r.normal[2])};
    const Vec3<E> u = n - (n.dot(sE) / sE.dot(sE)) * sE;
    const int p = xP.climb(r.featureP, u), q = xQ.climb(r.featureQ, Vec3<E>(-u));
    if (u != Vec3<E>::Zero() && p >= 0 && q >= 0 && u.dot(xP.world(p) - xQ.world(q)) < E(0)) {
      out.status = MddStatus::NoContact;
      out.certified = true;
      return out;
    }
  }
  if (P.isExactHull() && Q.isExactHull() &&
      (r.status == MddStatus::Separated || r.status == MddStatus::Touching || r.status == MddStatus::Penetrating)) {
    const detail::ExactPlacement<E, T> xP(P, poseP), xQ(Q, poseQ);
    MddCachedFace faces[3] = {MddCachedFace{r.faceType, r.featureP, r.featureQ}, cache.exitFaces[0],
                              cache.exitFaces[1]};
    bool haveLo = false, haveHi = false;
    E lo(0), hi(0);
    for (int i = 0; i < 3; ++i) {
      const MddCachedFace& f = faces[i];
      bool seen = false;
      for (int j = 0; j < i; ++j) seen |= faces[j].type == f.type && faces[j].a == f.a && faces[j].b == f.b;
      if (seen) continue;
      const detail::ExactChordEnd<E> end = detail::certifyFace(f, xP, xQ, sE);
      if (!end.valid) continue;
      if (end.isHi) {
        haveHi = true;
        hi = end.t;
      } else {
        haveLo = true;
        lo = end.t;
      }
    }
    // Eq. (1): the origin is before the chord (t_lo > 0), after it (t_hi < 0), on an end
    // (0), or inside (t_lo < 0 < t_hi, the nearer end; on a tie the one along +s).
    out.certified = true;
    if (haveLo && lo > E(0)) {
      out.status = MddStatus::Separated;
      out.parameter = lo;
    } else if (haveHi && hi < E(0)) {
      out.status = MddStatus::Separated;
      out.parameter = hi;
    } else if ((haveLo && lo == E(0)) || (haveHi && hi == E(0))) {
      out.status = MddStatus::Touching;
      out.parameter = E(0);
    } else if (haveLo && haveHi) {  // lo < 0 < hi here
      out.status = MddStatus::Penetrating;
      out.parameter = hi <= -lo ? hi : lo;
    } else {
      out.certified = false;
    }
    if (out.certified) return out;
  }
  // The full exact query on the exact hulls of the same vertices, placed in the world
  // exactly (mdd<E> accepts only exactly orthonormal rotations; the rounded rotation of a
  // double pose is applied here as the affine map it is).
  auto placed = [](const ConvexPolyhedron<T>& X, const Pose<T>& pose) {
    const detail::ExactPlacement<E, T> x(X, pose);
    std::vector<Vec3<E>> pts;
    pts.reserve(static_cast<std::size_t>(X.numVertices()));
    for (int v = 0; v < X.numVertices(); ++v) pts.push_back(x.world(v));
    return ConvexPolyhedron<E>::fromPoints(pts);
  };
  const auto PE = placed(P, poseP);
  const auto QE = placed(Q, poseQ);
  MddOptions<E> optionsE;
  optionsE.maxVisits = options.maxVisits;
  optionsE.maxExhaustivePairs = options.maxExhaustivePairs;
  optionsE.useHierarchy = options.useHierarchy;
  const MddResult<E> e = mdd(PE, Pose<E>(), QE, Pose<E>(), sE, optionsE);
  out.status = e.status;
  out.parameter = e.status == MddStatus::NoContact ? E(0) : e.parameter;
  out.certified = false;
  return out;
}

}  // namespace mink
