// mink/polyhedron/detail/convex_polyhedron_impl.hpp — construction of ConvexPolyhedron:
// fromPoints (quickhull.hpp) and fromMesh validation, at unit scale where the input is
// tiny or huge, then the shared finish (polyhedron_finish.hpp: coplanar-face merging,
// half-edge arrays, face planes) on the numbers of polyhedron_geometry.hpp; and the
// support queries. Included at the bottom of convex_polyhedron.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "mink/core/detail/input_checks.hpp"
#include "mink/core/orientation.hpp"
#include "mink/polyhedron/detail/polyhedron_finish.hpp"
#include "mink/polyhedron/detail/quickhull.hpp"

namespace mink {
namespace detail {

template <class T>
struct PolyhedronBuilder : PolyhedronFinish<T> {
  using F = PolyhedronFinish<T>;
  using typename F::Loop;
  using typename F::Poly;
  using typename F::Width;
  using F::checkFinite;
  using F::extentOf;
  using F::facePlanes;
  using F::interiorDepth;
  using F::finish;
  using F::key;
  using F::newell;
  using F::testNormal;
  using F::toleranceFor;
  using F::width;

  // ---------------------------------------------------------------------------------
  static Result<Poly> fromPoints(const std::vector<Vec3<T>>& points, const HullOptions<T>& options) {
    const char* who = "fromPoints";
    if (points.empty()) return Error("fromPoints: no points given");
    if (points.size() < 4) return Error("fromPoints: need at least 4 points, got " + std::to_string(points.size()));
    if (Error e = checkFinite(points, who, "point")) return e;
    T m = T(0);
    if constexpr (!ScalarTraits<T>::isExact)
      for (const auto& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
    Result<Poly> P = atUnitScale(points, m, options, [&](const std::vector<Vec3<T>>& pts, const HullOptions<T>& opt) {
      return build(pts, opt, who);
    });
    // Quickhull decides every side exactly and faces merge only when exactly coplanar;
    // the rescaling is by powers of two, exact both ways on the vertices it keeps.
    if (P.ok()) P.value().exactHull_ = true;
    return P;
  }

  /// build(points, options), on a copy scaled to unit size by a power of two (exact both
  /// ways) when the largest coordinate m is beyond 2^±kRescaleExponent (1e-100 or 1e80):
  /// the degeneracy tests' squared lengths would otherwise underflow or overflow.
  /// Coordinates below 2^(e - 1074) (e: the exponent of m) are rounded to multiples of
  /// it, the resolution of doubles at unit scale: a vertex is then its input point
  /// within that (1e-300 in a 1e60 shape), not exactly.
  template <class Build>
  static Result<Poly> atUnitScale(const std::vector<Vec3<T>>& points, const T& m, const HullOptions<T>& options,
                                  Build&& build) {
    if constexpr (!ScalarTraits<T>::isExact) {
      const int e = m > T(0) ? std::ilogb(m) : 0;
      if (e > kRescaleExponent || e < -kRescaleExponent) {
        std::vector<Vec3<T>> scaled(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
          for (int k = 0; k < 3; ++k) scaled[i][k] = std::ldexp(points[i][k], -e);
        HullOptions<T> opt = options;
        if (opt.tolerance > T(0)) opt.tolerance = std::ldexp(opt.tolerance, -e);
        Result<Poly> built = build(scaled, opt);
        if (!built.ok()) return built;
        Poly& P = built.value();
        // Scaled back exactly: the hull is the exact hull of the scaled copy, whose
        // coordinates below 2^(e - 1074) were rounded to that grid (a 1e-300 coordinate in
        // a 1e60 shape); the vertices are those points, and the planes are theirs.
        for (auto& x : P.vertices_)
          for (int k = 0; k < 3; ++k) x[k] = std::ldexp(x[k], e);
        facePlanes(P);
        P.tolerance_ = std::ldexp(P.tolerance_, e);
        P.extent_ = std::ldexp(P.extent_, e);
        interiorDepth(P);
        return built;
      }
    }
    return build(points, options);
  }

  /// Beyond 2^±this, fromPoints works on a copy scaled to unit size.
  static constexpr int kRescaleExponent = 64;

  static Result<Poly> build(const std::vector<Vec3<T>>& points, const HullOptions<T>& options, const char* who) {
    const T extent = extentOf(points);
    T tol = T(0);
    if (Error e = toleranceFor(options, extent, who, tol)) return e;
    std::vector<std::array<int, 3>> tris;
    if (Error e = Quickhull<T>::run(points, tol, tris)) return e;
    std::vector<Loop> polys;
    polys.reserve(tris.size());
    for (const auto& t : tris) polys.push_back({t[0], t[1], t[2]});
    return finish(points, std::move(polys), tol, extent);
  }

  // ---------------------------------------------------------------------------------
  static Result<Poly> fromMesh(const std::vector<Vec3<T>>& verts, const std::vector<Loop>& faces,
                               const HullOptions<T>& options) {
    if (verts.empty()) return Error("fromMesh: no vertices given");
    if (faces.empty()) return Error("fromMesh: no faces given");
    if (Error e = checkFinite(verts, "fromMesh", "vertex")) return e;
    // The scale of the vertices the faces use (bad indices are reported by meshBody).
    T m = T(0);
    if constexpr (!ScalarTraits<T>::isExact)
      for (const Loop& L : faces)
        for (int v : L)
          if (v >= 0 && v < static_cast<int>(verts.size())) m = std::max(m, verts[v].cwiseAbs().maxCoeff());
    Result<Poly> P = atUnitScale(verts, m, options, [&](const std::vector<Vec3<T>>& pts, const HullOptions<T>& opt) {
      return meshBody(pts, faces, opt);
    });
    // Exact T with the default tolerance (0) validates planarity and convexity with no
    // slack; floating point, or a tolerance given, within the tolerance.
    if (P.ok()) P.value().exactHull_ = ScalarTraits<T>::isExact && P.value().tolerance_ == T(0);
    return P;
  }

  static Result<Poly> meshBody(const std::vector<Vec3<T>>& verts, const std::vector<Loop>& faces,
                               const HullOptions<T>& options) {
    const char* who = "fromMesh";
    const int nV = static_cast<int>(verts.size());
    const int nF = static_cast<int>(faces.size());
    auto faceName = [](int f) { return "face " + std::to_string(f); };
    for (int f = 0; f < nF; ++f) {
      const Loop& L = faces[f];
      if (L.size() < 3)
        return Error("fromMesh: " + faceName(f) + " has " + std::to_string(L.size()) +
                           " vertices; a face needs at least 3");
      for (std::size_t i = 0; i < L.size(); ++i) {
        if (L[i] < 0 || L[i] >= nV)
          return Error("fromMesh: " + faceName(f) + " has vertex index " + std::to_string(L[i]) +
                             " out of range [0, " + std::to_string(nV) + ")");
        for (std::size_t j = 0; j < i; ++j)
          if (L[j] == L[i])
            return Error("fromMesh: " + faceName(f) + " repeats vertex " + std::to_string(L[i]));
      }
    }
    // Only referenced vertices count (for extent and tolerance too).
    std::vector<char> used(nV, 0);
    for (const Loop& L : faces)
      for (int v : L) used[v] = 1;
    std::vector<Vec3<T>> usedPts;
    for (int v = 0; v < nV; ++v)
      if (used[v]) usedPts.push_back(verts[v]);
    const T extent = extentOf(usedPts);
    T tol = T(0);
    if (Error e = toleranceFor(options, extent, who, tol)) return e;

    // Closed, consistently oriented 2-manifold.
    std::unordered_map<std::uint64_t, int> owner;
    owner.reserve(static_cast<std::size_t>(nF) * 4);
    for (int f = 0; f < nF; ++f) {
      const Loop& L = faces[f];
      for (std::size_t i = 0; i < L.size(); ++i) {
        const int a = L[i], b = L[(i + 1) % L.size()];
        if (!owner.emplace(key(a, b), f).second)
          return Error("fromMesh: edge " + std::to_string(a) + "->" + std::to_string(b) +
                             " is used twice in the same direction (faces " +
                             std::to_string(owner.at(key(a, b))) + " and " + std::to_string(f) +
                             "): inconsistent orientation or non-manifold edge");
      }
    }
    std::size_t nE2 = 0;
    for (int f = 0; f < nF; ++f) {
      const Loop& L = faces[f];
      for (std::size_t i = 0; i < L.size(); ++i) {
        const int a = L[i], b = L[(i + 1) % L.size()];
        if (!owner.count(key(b, a)))
          return Error("fromMesh: mesh is not closed: edge " + std::to_string(a) + "-" +
                             std::to_string(b) + " of " + faceName(f) + " has no partner face");
        ++nE2;
      }
    }
    const long long nE = static_cast<long long>(nE2 / 2);
    // Vertex fans must be single cycles (no two cones touching at a vertex).
    {
      std::vector<std::vector<std::pair<int, int>>> outEdges(nV);
      for (int f = 0; f < nF; ++f) {
        const Loop& L = faces[f];
        const int m = static_cast<int>(L.size());
        for (int i = 0; i < m; ++i) outEdges[L[i]].push_back({L[(i + 1) % m], L[(i + m - 1) % m]});
      }
      for (int v = 0; v < nV; ++v) {
        if (outEdges[v].empty()) continue;
        std::unordered_map<int, int> next;
        for (const auto& wu : outEdges[v]) next[wu.first] = wu.second;
        int w = outEdges[v][0].first;
        std::size_t steps = 0;
        do {
          w = next.at(w);
          ++steps;
        } while (w != outEdges[v][0].first && steps <= outEdges[v].size());
        if (steps != outEdges[v].size())
          return Error("fromMesh: vertex " + std::to_string(v) +
                             " is non-manifold (its faces form more than one fan)");
      }
    }
    // Connected.
    {
      std::vector<char> seen(nF, 0);
      std::vector<int> queue{0};
      seen[0] = 1;
      for (std::size_t qi = 0; qi < queue.size(); ++qi) {
        const Loop& L = faces[queue[qi]];
        for (std::size_t i = 0; i < L.size(); ++i) {
          const int nb = owner.at(key(L[(i + 1) % L.size()], L[i]));
          if (!seen[nb]) {
            seen[nb] = 1;
            queue.push_back(nb);
          }
        }
      }
      if (static_cast<int>(queue.size()) != nF)
        return Error("fromMesh: mesh is not connected (" + std::to_string(nF - queue.size()) +
                           " faces are not reachable from face 0)");
    }
    const long long chi = static_cast<long long>(usedPts.size()) - nE + nF;
    if (chi != 2)
      return Error("fromMesh: mesh is not a topological sphere (Euler characteristic " +
                         std::to_string(chi) + ", expected 2)");
    // Planar, non-degenerate faces; outward orientation; local convexity.
    std::vector<Vec3<T>> n(nF);
    for (int f = 0; f < nF; ++f) {
      const Loop& L = faces[f];
      const Vec3<T> raw = newell(verts, L);
      if (raw == Vec3<T>::Zero())
        return Error("fromMesh: " + faceName(f) + " is degenerate (zero area)");
      n[f] = testNormal(raw);
      for (int v : L)
        if (absValue(n[f].dot(verts[v] - verts[L[0]])) > tol)
          return Error("fromMesh: " + faceName(f) + " is not planar (vertex " + std::to_string(v) +
                             " is off its plane)");
    }
    {
      const char* inward =
          "fromMesh: faces are oriented inward (clockwise seen from outside) or the mesh has no volume";
      if constexpr (ScalarTraits<T>::isExact) {
        // Six times the signed volume, relative to a mesh vertex (exact).
        const Vec3<T>& o = usedPts[0];
        T vol6 = T(0);
        for (const Loop& L : faces)
          for (std::size_t i = 1; i + 1 < L.size(); ++i)
            vol6 += (verts[L[0]] - o).dot((verts[L[i]] - o).cross(verts[L[i + 1]] - o));
        if (!(vol6 > T(0))) return Error(inward);
      } else {
        // The signed volume in floating point has the wrong sign on a needle 1 by 1e-27 by
        // 1e-40 (its terms cancel far above its value). The orientation of a consistently
        // oriented closed mesh is that of any one face against a vertex off its plane:
        // the largest face, against the vertex farthest from its plane, decided exactly.
        int best = 0;
        Width widest;
        for (int f = 0; f < nF; ++f) {
          Width w;
          newell(verts, faces[f], &w);
          if (w > widest) widest = w, best = f;
        }
        const Loop& L = faces[best];
        int k = 2;
        for (std::size_t i = 3; i < L.size(); ++i)
          if (width(verts[L[0]], verts[L[1]], verts[L[i]]) > width(verts[L[0]], verts[L[1]], verts[L[k]]))
            k = static_cast<int>(i);
        // The vertex farthest from its plane, unless that distance is within the rounding
        // of the face's normal (a mesh thinner than that: 1e-40 on a face 1 long); then
        // the first vertex off the plane, exactly. Vertices of the face itself are skipped
        // (a face planar only within the tolerance may have one above its fan triangle).
        std::vector<char> onFace(nV, 0);
        for (int v : L) onFace[v] = 1;
        auto side = [&](int v) { return orient3d(verts[L[0]], verts[L[1]], verts[L[k]], verts[v]); };
        int far = -1;
        T depth = T(0);
        for (int v = 0; v < nV; ++v) {
          if (!used[v] || onFace[v]) continue;
          const T d = absValue(n[best].dot(verts[v] - verts[L[0]]));
          if (far < 0 || d > depth) far = v, depth = d;
        }
        int o = 0;
        if (far >= 0 && depth > T(16) * ScalarTraits<T>::epsilon() * extent) o = side(far);
        for (int v = 0; o == 0 && v < nV; ++v)
          if (used[v] && !onFace[v]) o = side(v);
        if (!(o < 0)) return Error(inward);
      }
    }
    // Local convexity at every vertex: each vertex adjacent to v lies on or below every
    // face plane around v. With a closed connected surface this makes the mesh convex
    // (van Heijenoort 1952).
    {
      std::vector<std::vector<int>> facesAt(nV), nbrs(nV);
      for (int f = 0; f < nF; ++f) {
        const Loop& L = faces[f];
        const int m = static_cast<int>(L.size());
        for (int i = 0; i < m; ++i) {
          facesAt[L[i]].push_back(f);
          nbrs[L[i]].push_back(L[(i + 1) % m]);
        }
      }
      for (int v = 0; v < nV; ++v)
        for (int f : facesAt[v])
          for (int w : nbrs[v])
            if (n[f].dot(verts[w] - verts[v]) > tol)
              return Error("fromMesh: mesh is not convex (vertex " + std::to_string(w) + " lies above " +
                                 faceName(f) + ")");
    }
    return finish(verts, faces, tol, extent);
  }
};

}  // namespace detail

template <class T>
Result<ConvexPolyhedron<T>> ConvexPolyhedron<T>::tryFromPoints(const std::vector<Vec3<T>>& points,
                                                               const HullOptions<T>& options) {
  return detail::PolyhedronBuilder<T>::fromPoints(points, options);
}

template <class T>
Result<ConvexPolyhedron<T>> ConvexPolyhedron<T>::tryFromMesh(const std::vector<Vec3<T>>& vertices,
                                                             const std::vector<std::vector<int>>& faces,
                                                             const HullOptions<T>& options) {
  return detail::PolyhedronBuilder<T>::fromMesh(vertices, faces, options);
}

template <class T>
ConvexPolyhedron<T> ConvexPolyhedron<T>::fromPoints(const std::vector<Vec3<T>>& points,
                                                    const HullOptions<T>& options) {
  return tryFromPoints(points, options).value();
}

template <class T>
ConvexPolyhedron<T> ConvexPolyhedron<T>::fromMesh(const std::vector<Vec3<T>>& vertices,
                                                  const std::vector<std::vector<int>>& faces,
                                                  const HullOptions<T>& options) {
  return tryFromMesh(vertices, faces, options).value();
}

template <class T>
int ConvexPolyhedron<T>::support(const Vec3<T>& d, int hint) const {
  int v = (hint >= 0 && hint < numVertices()) ? hint : 0;
  T best = d.dot(vertices_[v]);
  // Steepest ascent by the values d . x (a total order: no cycles, so it terminates, and
  // GaussMap::regionContains mirrors these comparisons). A neighbour whose value equals
  // the current one in floating point is still taken if d . (w - v) > 0: across an edge
  // shorter than the rounding of the values (two hull corners 2e-308 apart) the values
  // tie, and the climb stopped at the corner whose only way up was that edge (0.13 where
  // the maximum is 0.34). The difference of two close vertices is exact, and the sign of
  // d . (w - v) is used only where it exceeds its rounding (a real tie, d normal to a
  // face, has a difference of pure rounding, and following it could cycle); the step
  // count guards the rest.
  for (int steps = 0; steps <= numVertices(); ++steps) {
    int next = -1, tied = -1;
    T top = best;
    for (int w : vertexNeighbors(v)) {
      const T val = d.dot(vertices_[w]);
      if (val > top) {
        top = val;
        next = w;
      } else if (val == best && next < 0 && tied < 0 && detail::surelyUphill(d, vertices_[v], vertices_[w])) {
        tied = w;
      }
    }
    if (next < 0) next = tied;
    if (next < 0) return v;
    v = next;
    best = top;
  }
  return v;
}

template <class T>
int ConvexPolyhedron<T>::supportBruteForce(const Vec3<T>& d) const {
  int arg = 0;
  T best = d.dot(vertices_[0]);
  for (int v = 1; v < numVertices(); ++v) {
    const T val = d.dot(vertices_[v]);
    if (val > best) {
      best = val;
      arg = v;
    }
  }
  return arg;
}

}  // namespace mink
