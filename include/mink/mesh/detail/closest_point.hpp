// mink/mesh/detail/closest_point.hpp — the point of a closed triangle nearest to a point
// (C. Ericson, Real-Time Collision Detection, 2005, section 5.1.5: the Voronoi regions of
// the corners, then of the edges, then the face). A construction, not a predicate: it
// rounds, and degenerate triangles fall into a corner or an edge region.
#pragma once

namespace mink {
namespace detail {

/// Nearest point to p of the triangle (a, b, c); V is any Eigen 3-vector type.
template <class V>
V closestPointOnTriangle(const V& p, const V& a, const V& b, const V& c) {
  using S = typename V::Scalar;
  const V ab = b - a, ac = c - a, ap = p - a;
  const S d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= S(0) && d2 <= S(0)) return a;
  const V bp = p - b;
  const S d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= S(0) && d4 <= d3) return b;
  const S vc = d1 * d4 - d3 * d2;
  if (vc <= S(0) && d1 >= S(0) && d3 <= S(0)) return a + (d1 / (d1 - d3)) * ab;
  const V cp = p - c;
  const S d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= S(0) && d5 <= d6) return c;
  const S vb = d5 * d2 - d1 * d6;
  if (vb <= S(0) && d2 >= S(0) && d6 <= S(0)) return a + (d2 / (d2 - d6)) * ac;
  const S va = d3 * d6 - d5 * d4;
  if (va <= S(0) && (d4 - d3) >= S(0) && (d5 - d6) >= S(0)) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const S den = S(1) / (va + vb + vc);
  return a + ab * (vb * den) + ac * (vc * den);
}

}  // namespace detail
}  // namespace mink
