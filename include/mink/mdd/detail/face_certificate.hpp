// mink/mdd/detail/face_certificate.hpp — the tests behind mddExact, written once over the
// number type N they are evaluated in: an interval of the shapes' floating-point type
// (the filter) or the caller's exact rational type E.
//
// Every test is the sign of a polynomial in the input numbers (vertex coordinates, the
// poses' entries, s); none divides. Evaluated in an interval it answers Yes or No when the
// enclosure decides the sign and Unknown otherwise (a tie, or a value below the rounding);
// evaluated in E it always decides. mddExact asks the interval first and E only for what
// the interval left Unknown, so the exact arithmetic runs on ties and on the one parameter
// it returns.
#pragma once

#include <array>
#include <type_traits>
#include <utility>
#include <vector>

#include "mink/core/expansion.hpp"
#include "mink/mdd/mdd_types.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"

namespace mink {
namespace detail {

/// The answer of a test evaluated in N: decided (Yes / No) or left to exact arithmetic.
enum class Verdict { No, Yes, Unknown };

/// Conjunction: No as soon as one part is No, Yes when all are Yes.
inline Verdict both(Verdict a, Verdict b) {
  if (a == Verdict::No || b == Verdict::No) return Verdict::No;
  return a == Verdict::Yes && b == Verdict::Yes ? Verdict::Yes : Verdict::Unknown;
}

/// x <= 0 ? (exact type: always decided.)
template <class N>
Verdict atMostZero(const N& x) {
  return x <= N(0) ? Verdict::Yes : Verdict::No;
}
template <class F>
Verdict atMostZero(const IntervalOf<F>& x) {
  if (x.hi() <= F(0)) return Verdict::Yes;
  return x.lo() > F(0) ? Verdict::No : Verdict::Unknown;
}
/// The sign of x: +1, -1, 0, or 2 when an interval cannot tell.
template <class N>
int signOf(const N& x) {
  return x > N(0) ? 1 : (x < N(0) ? -1 : 0);
}
template <class F>
int signOf(const IntervalOf<F>& x) {
  if (x.lo() > F(0)) return 1;
  if (x.hi() < F(0)) return -1;
  return x.lo() == F(0) && x.hi() == F(0) ? 0 : 2;
}
template <class F>
int signOf(const ExpansionOf<F>& x) {
  return x.sign();
}
template <class F>
Verdict atMostZero(const ExpansionOf<F>& x) {
  return x.sign() <= 0 ? Verdict::Yes : Verdict::No;
}
constexpr int kUnknownSign = 2;

template <class N>
using Triple = std::array<N, 3>;

template <class N>
Triple<N> operator-(const Triple<N>& a, const Triple<N>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class N>
Triple<N> operator+(const Triple<N>& a, const Triple<N>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class N>
Triple<N> operator*(const N& k, const Triple<N>& a) {
  return {k * a[0], k * a[1], k * a[2]};
}
template <class N>
Triple<N> negated(const Triple<N>& a) {
  return {-a[0], -a[1], -a[2]};
}
template <class N>
N dot(const Triple<N>& a, const Triple<N>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class N>
Triple<N> cross(const Triple<N>& a, const Triple<N>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class N, class T>
Triple<N> toTriple(const Vec3<T>& x) {
  return {N(x[0]), N(x[1]), N(x[2])};
}

/// A shape placed in the world in N, with the pose's numbers: x_world = R x + t (the
/// rounded rotation is applied as the affine map it is, never re-orthonormalised).
template <class N, class T>
class PlacedShape {
 public:
  PlacedShape(const ConvexPolyhedron<T>& X, const Pose<T>& pose) : X_(X) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) R_[r][c] = N(pose.rotation(r, c));
      t_[r] = N(pose.translation[r]);
    }
  }
  Triple<N> local(int v) const { return toTriple<N>(X_.vertex(v)); }
  Triple<N> world(int v) const {
    const Triple<N> x = local(v);
    return Triple<N>{dot(R_[0], x), dot(R_[1], x), dot(R_[2], x)} + t_;
  }
  /// Rᵀ n: n·(R x) = (Rᵀ n)·x, so tests between vertices run in the shape's own frame.
  Triple<N> toLocal(const Triple<N>& n) const {
    return {R_[0][0] * n[0] + R_[1][0] * n[1] + R_[2][0] * n[2], R_[0][1] * n[0] + R_[1][1] * n[1] + R_[2][1] * n[2],
            R_[0][2] * n[0] + R_[1][2] * n[1] + R_[2][2] * n[2]};
  }
  /// Is vertex v a maximum of n·x over the shape (n in the world frame)? No neighbour w
  /// (but `skip`, known to tie) has n·R(w − v) > 0; local is global on an exact hull.
  Verdict isMaximum(int v, const Triple<N>& n, int skip = -1) const {
    const Triple<N> m = toLocal(n);
    const Triple<N> x = local(v);
    Verdict all = Verdict::Yes;
    for (int w : X_.vertexNeighbors(v)) {
      if (w == skip) continue;
      all = both(all, atMostZero(dot(m, local(w) - x)));
      if (all == Verdict::No) break;
    }
    return all;
  }
  /// From vertex v, to a maximum of n·x by hill-climbing on steps proven uphill (so at
  /// most one visit per vertex): the vertex when proven a maximum, -1 when a neighbour
  /// can be neither proven better nor proven no better (N an interval), -2 past the bound.
  int climb(int v, const Triple<N>& n) const {
    const Triple<N> m = toLocal(n);
    for (int steps = 0; steps <= X_.numVertices(); ++steps) {
      const Triple<N> x = local(v);
      int better = -1;
      bool unknown = false;
      for (int w : X_.vertexNeighbors(v)) {
        const Verdict notBetter = atMostZero(dot(m, local(w) - x));
        if (notBetter == Verdict::No) {
          better = w;
          break;
        }
        unknown |= notBetter == Verdict::Unknown;
      }
      if (better < 0) return unknown ? -1 : v;
      v = better;
    }
    return -2;
  }
  /// Newell normal of face f in the world (the face is exactly planar; the normal points
  /// outward since det R > 0), with its world corners.
  Triple<N> faceNormal(int f, std::vector<Triple<N>>& corners) const {
    corners.clear();
    for (int v : X_.faceVertices(f)) corners.push_back(world(v));
    Triple<N> n{N(0), N(0), N(0)};
    for (std::size_t i = 0; i < corners.size(); ++i) n = n + cross(corners[i], corners[(i + 1) % corners.size()]);
    return n;
  }
  const ConvexPolyhedron<T>& shape() const { return X_; }

 private:
  const ConvexPolyhedron<T>& X_;
  Triple<N> R_[3];
  Triple<N> t_;
};

/// Is y / den in the convex polygon `corners` (counter-clockwise about n), boundary
/// included? y is given times den (den != 0, of sign sd) so that nothing divides.
template <class N>
Verdict inConvexPolygon(const std::vector<Triple<N>>& corners, const Triple<N>& n, const Triple<N>& yDen,
                        const N& den, int sd) {
  Verdict all = Verdict::Yes;
  for (std::size_t i = 0; i < corners.size() && all != Verdict::No; ++i) {
    const Triple<N>& a = corners[i];
    const Triple<N>& b = corners[(i + 1) % corners.size()];
    const N side = dot(cross(b - a, yDen - den * a), n);
    all = both(all, atMostZero(sd > 0 ? N(-side) : side));
  }
  return all;
}

/// One face of M on the line of s, tested in N: whether it is proven to be an end of M's
/// chord (`valid`), which end, and its parameter t = num / den.
template <class N>
struct FaceEnd {
  Verdict valid = Verdict::No;
  bool isHi = false;  // t_hi (the line leaves M going along +s) rather than t_lo
  N num = N(0), den = N(0);
};

/// The face's plane N·x = N·(p − q) (features p of P, q of Q) meets the line t s at
/// t = num / den, den = N·s. With `check`, also whether the plane supports M (the
/// features are maxima along N and −N) and t s lies in the features' Minkowski difference
/// (a polygon or parallelogram inside the facet): then t is t_lo (den < 0) or t_hi
/// (den > 0). Without, num and den only (the caller knows the face is valid).
template <class N, class T>
FaceEnd<N> testFace(const MddCachedFace& face, const PlacedShape<N, T>& P, const PlacedShape<N, T>& Q,
                    const Triple<N>& s, bool check) {
  FaceEnd<N> end;
  std::vector<Triple<N>> corners;
  auto denSign = [&](const Triple<N>& n) {
    end.den = dot(n, s);
    return signOf(end.den);
  };
  Verdict valid = Verdict::Yes;
  int sd = 0;
  switch (face.type) {
    case MddFaceType::FV: {  // face a of P, vertex b of Q: the facet holds face(a) − q_b
      const Triple<N> n = P.faceNormal(face.a, corners);
      const Triple<N> q = Q.world(face.b);
      sd = denSign(n);
      end.num = dot(n, corners[0] - q);
      if (!check) break;
      if (sd == 0) return end;
      if (sd == kUnknownSign) valid = Verdict::Unknown;
      valid = both(valid, Q.isMaximum(face.b, negated(n)));
      if (valid == Verdict::No || sd == kUnknownSign) break;
      valid = both(valid, inConvexPolygon(corners, n, end.num * s + end.den * q, end.den, sd));
      break;
    }
    case MddFaceType::VF: {  // vertex a of P, face b of Q: the facet holds p_a − face(b)
      const Triple<N> nQ = Q.faceNormal(face.b, corners);
      const Triple<N> n = negated(nQ);
      const Triple<N> p = P.world(face.a);
      sd = denSign(n);
      end.num = dot(n, p - corners[0]);
      if (!check) break;
      if (sd == 0) return end;
      if (sd == kUnknownSign) valid = Verdict::Unknown;
      valid = both(valid, P.isMaximum(face.a, n));
      if (valid == Verdict::No || sd == kUnknownSign) break;
      valid = both(valid, inConvexPolygon(corners, nQ, end.den * p - end.num * s, end.den, sd));
      break;
    }
    case MddFaceType::EE: {  // edge a of P, edge b of Q: the facet holds e_P − e_Q
      const std::pair<int, int> ep = P.shape().edgeVertices(face.a), eq = Q.shape().edgeVertices(face.b);
      const int pa = ep.first, pb = ep.second, qa = eq.first, qb = eq.second;
      const Triple<N> p0 = P.world(pa), q0 = Q.world(qa);
      const Triple<N> eP = P.world(pb) - p0, eQ = Q.world(qb) - q0;
      const Triple<N> d = cross(eP, eQ);
      Triple<N> n = d;
      if (!check) {
        sd = denSign(n);
        end.num = dot(n, p0 - q0);
        break;
      }
      // Each edge's far end ties with its near one along n (n·e = 0 identically).
      auto supports = [&](const Triple<N>& m) {
        Verdict v = both(P.isMaximum(pa, m, pb), P.isMaximum(pb, m, pa));
        if (v == Verdict::No) return v;
        const Triple<N> mq = negated(m);
        v = both(v, Q.isMaximum(qa, mq, qb));
        return v == Verdict::No ? v : both(v, Q.isMaximum(qb, mq, qa));
      };
      const Verdict plus = supports(n);
      if (plus != Verdict::Yes) {
        const Verdict minus = supports(negated(n));
        if (minus == Verdict::Yes) {
          n = negated(n);
        } else {
          valid = plus == Verdict::No && minus == Verdict::No ? Verdict::No : Verdict::Unknown;
          if (valid == Verdict::No) return end;
        }
      }
      // Both supports fail for a zero n, the edges being parallel (a degenerate face).
      sd = denSign(n);
      end.num = dot(n, p0 - q0);
      if (sd == 0) return FaceEnd<N>{};
      if (sd == kUnknownSign || valid == Verdict::Unknown) {
        valid = Verdict::Unknown;
        break;
      }
      // t s − p0 + q0 = α e_P − β e_Q with α, β in [0, 1]: α (d·d) = (y × e_Q)·d and
      // β (d·d) = (y × e_P)·d, d = e_P × e_Q, for y; here y is taken times den.
      const Triple<N> yDen = end.num * s - end.den * (p0 - q0);
      const N a = dot(cross(yDen, eQ), d), b = dot(cross(yDen, eP), d);
      const N denNN = end.den * dot(d, d);
      for (const N& x : {a, b}) {
        const N xs = sd > 0 ? x : N(-x), rest = sd > 0 ? N(denNN - x) : N(x - denNN);
        valid = both(valid, both(atMostZero(N(-xs)), atMostZero(N(-rest))));
      }
      break;
    }
    default:
      return end;
  }
  end.valid = check ? valid : Verdict::Yes;
  end.isHi = sd == 1;
  return end;
}

/// Are the numbers face's num and den are made of (its features' coordinates, both poses
/// and s) zero or between 2^-100 and 2^100 in magnitude, so that an expansion of F
/// evaluates them exactly (degree 6 at most: no product underflows or overflows)?
template <class T>
bool inExpansionRange(const MddCachedFace& face, const ConvexPolyhedron<T>& P, const Pose<T>& poseP,
                      const ConvexPolyhedron<T>& Q, const Pose<T>& poseQ, const Vec3<T>& s) {
  auto ok = [](const T& x) {
    using std::abs;
    return x == T(0) || (abs(x) >= T(0x1p-100) && abs(x) <= T(0x1p100));
  };
  auto okVertex = [&](const ConvexPolyhedron<T>& X, int v) { return ok(X.vertex(v)[0]) && ok(X.vertex(v)[1]) && ok(X.vertex(v)[2]); };
  auto okFace = [&](const ConvexPolyhedron<T>& X, int f) {
    for (int v : X.faceVertices(f))
      if (!okVertex(X, v)) return false;
    return true;
  };
  auto okEdge = [&](const ConvexPolyhedron<T>& X, int e) {
    const std::pair<int, int> ends = X.edgeVertices(e);
    return okVertex(X, ends.first) && okVertex(X, ends.second);
  };
  for (const Pose<T>* pose : {&poseP, &poseQ})
    for (int r = 0; r < 3; ++r) {
      if (!ok(pose->translation[r])) return false;
      for (int c = 0; c < 3; ++c)
        if (!ok(pose->rotation(r, c))) return false;
    }
  if (!ok(s[0]) || !ok(s[1]) || !ok(s[2])) return false;
  switch (face.type) {
    case MddFaceType::FV:
      return okFace(P, face.a) && okVertex(Q, face.b);
    case MddFaceType::VF:
      return okVertex(P, face.a) && okFace(Q, face.b);
    case MddFaceType::EE:
      return okEdge(P, face.a) && okEdge(Q, face.b);
    default:
      return false;
  }
}

}  // namespace detail
}  // namespace mink
