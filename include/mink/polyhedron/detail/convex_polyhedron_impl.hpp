// mink/polyhedron/detail/convex_polyhedron_impl.hpp — construction of ConvexPolyhedron:
// input checks, fromMesh validation, coplanar-face merging and the half-edge arrays.
// Included at the bottom of convex_polyhedron.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mink/core/detail/input_checks.hpp"
#include "mink/core/orientation.hpp"
#include "mink/polyhedron/detail/quickhull.hpp"

namespace mink {
namespace detail {

template <class T>
struct PolyhedronBuilder {
  using Poly = ConvexPolyhedron<T>;
  using Loop = std::vector<int>;

  static std::uint64_t key(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }

  static T extentOf(const std::vector<Vec3<T>>& pts) {
    Vec3<T> m = Vec3<T>::Zero();
    for (const auto& p : pts)
      for (int k = 0; k < 3; ++k) m[k] = std::max(m[k], absValue(p[k]));
    return m[0] + m[1] + m[2];
  }

  static T toleranceFor(const HullOptions<T>& options, const T& extent, const char* who) {
    if constexpr (ScalarTraits<T>::isExact) {
      if (options.tolerance > T(0))
        throw InvalidInput(std::string(who) + ": a positive tolerance needs an inexact scalar type; "
                                              "exact scalars decide exactly (tolerance 0)");
      return T(0);
    } else {
      if (!ScalarTraits<T>::isFinite(options.tolerance))
        throw InvalidInput(std::string(who) + ": tolerance is not finite");
      if (options.tolerance >= T(0)) return options.tolerance;
      return T(defaults::kHullToleranceFactor) * ScalarTraits<T>::epsilon() * extent;
    }
  }

  static void checkFinite(const std::vector<Vec3<T>>& pts, const char* who, const char* what) {
    checkCoordinates(pts, who, what);
  }

  /// |(b − o) × (c − o)| as len · 2^exp, to compare triangles without underflow (the
  /// cross product of a triangle 1e-185 by 1e-300 is below the double range).
  struct Width {
    T len = T(0);
    int exp = 0;
    bool operator>(const Width& w) const {
      if (!(len > T(0))) return false;
      if (!(w.len > T(0))) return true;
      if constexpr (ScalarTraits<T>::isExact) {
        return len > w.len;
      } else {
        return len > std::ldexp(w.len, w.exp - exp);
      }
    }
  };
  /// A key ordering widths as Width::operator> does (exactly, where that rounds).
  static std::pair<int, T> sizeKey(const Width& w) {
    if (!(w.len > T(0))) return {std::numeric_limits<int>::min(), T(0)};
    if constexpr (ScalarTraits<T>::isExact) {
      return {0, w.len};
    } else {
      const int e = std::ilogb(w.len);
      return {w.exp + e, std::ldexp(w.len, -e)};
    }
  }
  static Width width(const Vec3<T>& o, const Vec3<T>& b, const Vec3<T>& c, Vec3<T>* normal = nullptr) {
    Width w;
    Vec3<T> n;
    if constexpr (ScalarTraits<T>::isExact) {
      n = (b - o).cross(c - o);
      w.len = n.squaredNorm();
    } else {
      n = accurateCross(o, b, c, &w.exp);
      w.len = n.stableNorm();
    }
    if (normal) *normal = n;
    return w;
  }

  // Normal of a loop: for exact T its Newell normal; otherwise, for an exactly planar
  // loop, the accurate cross product of its widest fan triangle from the first corner
  // (about one ulp per component, where the textbook Newell sum loses every digit on
  // sliver faces), and for a non-planar loop (fromMesh, within its tolerance) the Newell
  // normal of the whole loop.
  /// `size` (optional): the face's size, to order faces by.
  static Vec3<T> newell(const std::vector<Vec3<T>>& pts, const Loop& loop, Width* size = nullptr) {
    const Vec3<T>& o = pts[loop[0]];
    Width dummy;
    Width& widest = size ? *size : dummy;
    widest = Width();
    if constexpr (ScalarTraits<T>::isExact) {
      // Exact already: the Newell normal (the documented one for exact T).
      Vec3<T> n = Vec3<T>::Zero();
      for (std::size_t i = 1; i + 1 < loop.size(); ++i) n += (pts[loop[i]] - o).cross(pts[loop[i + 1]] - o);
      widest.len = n.squaredNorm();
      return n;
    } else {
      // The widest fan triangle's normal, scaled to order one (a face too small for its
      // normal to be a double, 1e-185 by 1e-300, keeps its direction).
      // The mantissa n is |cross| / (2^-998 |u| |v|) (u, v: the fan triangle's edges at
      // its corner), so a needle seen from its sharp corner can still underflow (a
      // triangle 2^286 long whose short edge is 2^-783: its angle there is 2^-2138, the
      // one at the short edge 2^-1069). Then the fans from the other corners are tried,
      // until one gives n clear of the denormal range (about one ulp per component).
      Vec3<T> best = Vec3<T>::Zero(), n;
      const std::size_t m = loop.size();
      const T reliable = std::ldexp(T(1), std::numeric_limits<T>::min_exponent - 1 + std::numeric_limits<T>::digits);
      for (std::size_t s = 0; s < m; ++s) {
        const Vec3<T>& os = pts[loop[s]];
        Width w0;
        Vec3<T> b0 = Vec3<T>::Zero();
        for (std::size_t i = 1; i + 1 < m; ++i) {
          const Width w = width(os, pts[loop[(s + i) % m]], pts[loop[(s + i + 1) % m]], &n);
          if (w > w0) {
            w0 = w;
            b0 = n;
          }
        }
        if (s == 0 || (!(widest.len > T(0)) && w0.len > T(0))) {
          widest = w0;
          best = b0;
        }
        if (b0.cwiseAbs().maxCoeff() >= reliable) {
          widest = w0;
          best = b0;
          break;
        }
      }
      if (loop.size() == 3) return best;
      Vec3<T> sum = Vec3<T>::Zero();
      for (std::size_t i = 1; i + 1 < loop.size(); ++i) sum += (pts[loop[i]] - o).cross(pts[loop[i + 1]] - o);
      // Prefer the accurate triangle normal when the loop is exactly planar.
      return isExactlyPlanar(pts, loop) ? best : sum;
    }
  }


  static bool isExactlyPlanar(const std::vector<Vec3<T>>& pts, const Loop& loop) {
    // The widest fan triangle spans the plane; every corner must be on it exactly.
    std::size_t k = 2;
    const Vec3<T>& o = pts[loop[0]];
    for (std::size_t i = 2; i < loop.size(); ++i)
      if (width(o, pts[loop[1]], pts[loop[i]]) > width(o, pts[loop[1]], pts[loop[k]])) k = i;
    // The three spanning corners are on it by definition (and would each cost the exact
    // stage, since their determinant is exactly zero).
    for (std::size_t i = 2; i < loop.size(); ++i)
      if (i != k && orient3d(o, pts[loop[1]], pts[loop[k]], pts[loop[i]]) != 0) return false;
    return true;
  }

  // Normal used for distance tests: unit for inexact T, exact Newell normal otherwise.
  static Vec3<T> testNormal(const Vec3<T>& n) {
    if constexpr (ScalarTraits<T>::isExact) {
      return n;
    } else {
      const T len = magnitude(n);
      return len > T(0) ? Vec3<T>(n / len) : n;
    }
  }

  /// An increasing function of |n|: |n| itself, without underflow or overflow, for
  /// inexact T; |n|^2 for exact T.
  static T magnitude(const Vec3<T>& n) {
    if constexpr (ScalarTraits<T>::isExact) {
      return n.squaredNorm();
    } else {
      return n.stableNorm();
    }
  }

  // ---------------------------------------------------------------------------------
  // Finishing: from a closed, consistently oriented, convex polygon mesh over `pts`
  // (loops CCW from outside) to the polyhedron: merge neighbouring polygons lying exactly
  // in one plane (orient3d == 0: merging within a tolerance instead leaves dents of that
  // size, on which hill-climbing stops at local maxima), splice out vertices that are no
  // longer corners (in fewer than three faces), and lay out the half-edge arrays.
  // Twins of a closed oriented polygon mesh given as flattened loops: half-edge h runs
  // from org[h] to org[nxt[h]]. The half-edges are bucketed by their lower endpoint
  // (counting sort, linear); an edge's two halves share a bucket, found by a scan of it
  // (a bucket holds about the vertex degree).
  static std::vector<int> twinsBySorting(const std::vector<int>& org, const std::vector<int>& nxt) {
    const int nH = static_cast<int>(org.size());
    std::vector<int> tgt(nH);
    int nV = 0;
    for (int h = 0; h < nH; ++h) {
      tgt[h] = org[nxt[h]];
      nV = std::max(nV, org[h] + 1);
    }
    // Bucket entries carry the upper endpoint, so that a scan reads one bucket only.
    struct Entry {
      int hi, h;
    };
    std::vector<int> start(nV + 2, 0);
    for (int h = 0; h < nH; ++h) ++start[std::min(org[h], tgt[h]) + 2];
    for (int v = 0; v < nV; ++v) start[v + 2] += start[v + 1];
    std::vector<Entry> bucket(nH);
    for (int h = 0; h < nH; ++h) {
      const int a = org[h], b = tgt[h];
      bucket[start[std::min(a, b) + 1]++] = {std::max(a, b), h};
    }
    // start[v] .. start[v + 1] is now bucket v.
    std::vector<int> twin(nH, -1);
    for (int v = 0; v < nV; ++v) {
      for (int i = start[v]; i < start[v + 1]; ++i) {
        const Entry e = bucket[i];
        int partner = -1, count = 0;
        for (int j = start[v]; j < start[v + 1]; ++j)
          if (j != i && bucket[j].hi == e.hi) {
            partner = bucket[j].h;
            ++count;
          }
        if (count != 1) throw InvalidInput("internal: edge without exactly one partner while building");
        if (org[partner] != tgt[e.h]) throw InvalidInput("internal: inconsistent orientation while building");
        twin[e.h] = partner;
      }
    }
    return twin;
  }

  /// `polys` is consumed (its loops are moved into the result's faces).
  static Poly finish(const std::vector<Vec3<T>>& pts, std::vector<Loop> polys, const T& tol,
                     const T& extent) {
    const int nP = static_cast<int>(polys.size());
    // Flattened input half-edges.
    std::vector<int> org, nxt, polyOf;
    std::vector<int> polyStart(nP + 1, 0);
    for (int f = 0; f < nP; ++f) polyStart[f + 1] = polyStart[f] + static_cast<int>(polys[f].size());
    const int nH0 = polyStart[nP];
    org.resize(nH0);
    nxt.resize(nH0);
    polyOf.resize(nH0);
    for (int f = 0; f < nP; ++f) {
      const int s0 = polyStart[f], m = polyStart[f + 1] - s0;
      for (int i = 0; i < m; ++i) {
        org[s0 + i] = polys[f][i];
        nxt[s0 + i] = s0 + (i + 1) % m;
        polyOf[s0 + i] = f;
      }
    }
    const std::vector<int> twin0 = twinsBySorting(org, nxt);

    std::vector<Vec3<T>> rawN(nP), unitN(nP);
    std::vector<Width> size(nP);
    for (int f = 0; f < nP; ++f) {
      rawN[f] = newell(pts, polys[f], &size[f]);
      unitN[f] = testNormal(rawN[f]);
    }
    std::vector<int> order(nP);
    for (int f = 0; f < nP; ++f) order[f] = f;
    {
      // Sizes as (binary exponent, mantissa in [1, 2)) pairs, compared lexicographically:
      // the order of len * 2^exp, without an ldexp per comparison (which the sort's
      // n log n comparisons made a tenth of fromPoints). Zero sizes sort last, all equal.
      std::vector<std::pair<int, T>> key(nP);
      for (int f = 0; f < nP; ++f) key[f] = sizeKey(size[f]);
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] > key[b]; });
    }

    std::vector<int> group(nP, -1);
    std::vector<int> queue;
    int nGroups = 0;
    for (int seed : order) {
      if (group[seed] >= 0) continue;
      const int g = nGroups++;
      group[seed] = g;
      queue.assign(1, seed);
      const Vec3<T>& n = unitN[seed];
      // Three corners of the seed spanning its plane (the widest fan triangle from its
      // first corner); neighbours join only if exactly in that plane.
      const Loop& S = polys[seed];
      int k2 = 2;
      for (std::size_t i = 3; i < S.size(); ++i)
        if (width(pts[S[0]], pts[S[1]], pts[S[i]]) > width(pts[S[0]], pts[S[1]], pts[S[k2]]))
          k2 = static_cast<int>(i);
      const Vec3<T>& a = pts[S[0]];
      const Vec3<T>& b = pts[S[1]];
      const Vec3<T>& c = pts[S[k2]];
      for (std::size_t qi = 0; qi < queue.size(); ++qi) {
        const int f = queue[qi];
        for (int h = polyStart[f]; h < polyStart[f + 1]; ++h) {
          const int nb = polyOf[twin0[h]];
          if (group[nb] >= 0) continue;
          if (!(n.dot(rawN[nb]) > T(0))) continue;
          bool coplanar = true;
          for (int v : polys[nb]) {
            if (v == S[0] || v == S[1] || v == S[k2]) continue;  // spanning corners: on the plane
            if (orient3d(a, b, c, pts[v]) != 0) {
              coplanar = false;
              break;
            }
          }
          if (coplanar) {
            group[nb] = g;
            queue.push_back(nb);
          }
        }
      }
    }

    // Boundary loop of each group: after boundary half-edge h (a -> b), turn around b
    // through the group's interior edges until the next boundary half-edge.
    // Group members listed CSR. (Faces stay in seed order, largest first: numbering them
    // by first polygon kept fromPoints' Morton order further, but changed which corner a
    // merged face's loop starts at, hence the rounding of its normal, past what the MDD
    // stress tests' bounds allow.)
    std::vector<int> memberStart(nGroups + 1, 0), memberList(nP);
    for (int f = 0; f < nP; ++f) ++memberStart[group[f] + 1];
    for (int g = 0; g < nGroups; ++g) memberStart[g + 1] += memberStart[g];
    {
      std::vector<int> fill(memberStart.begin(), memberStart.end() - 1);
      for (int f = 0; f < nP; ++f) memberList[fill[group[f]]++] = f;
    }
    auto members = [&](int g) { return IndexRange(memberList.data() + memberStart[g], memberList.data() + memberStart[g + 1]); };
    std::vector<Loop> faces;
    faces.reserve(nGroups);
    std::vector<char> used(nH0, 0);
    auto interior = [&](int h) { return group[polyOf[twin0[h]]] == group[polyOf[h]]; };
    for (int g = 0; g < nGroups; ++g) {
      if (members(g).size() == 1) {
        faces.push_back(std::move(polys[*members(g).begin()]));
        continue;
      }
      int count = 0, start = -1;
      for (int f : members(g))
        for (int h = polyStart[f]; h < polyStart[f + 1]; ++h)
          if (!interior(h)) {
            ++count;
            if (start < 0) start = h;
          }
      Loop loop;
      bool simple = start >= 0;
      int h = start;
      while (simple) {
        loop.push_back(org[h]);
        used[h] = 1;
        int c = nxt[h];
        int guard = 0;
        while (interior(c) && ++guard <= nH0) c = nxt[twin0[c]];
        if (guard > nH0) simple = false;
        h = c;
        if (h == start) break;
        if (used[h] || static_cast<int>(loop.size()) > count) simple = false;
      }
      simple = simple && static_cast<int>(loop.size()) == count;
      if (simple) {
        faces.push_back(std::move(loop));
      } else {
        // Only reachable with inexact T (a merged group that is not a disc): keep its
        // polygons as they are.
        for (int f : members(g)) faces.push_back(std::move(polys[f]));
      }
    }

    // Splice out vertices lying in fewer than three faces: on the edge between two
    // faces (collinear) — a corner of a 3-polytope lies in at least three facets.
    const int nPts = static_cast<int>(pts.size());
    std::vector<int> faceCount(nPts, 0);
    for (const Loop& L : faces)
      for (int v : L) ++faceCount[v];
    for (Loop& L : faces) {
      L.erase(std::remove_if(L.begin(), L.end(), [&](int v) { return faceCount[v] < 3; }), L.end());
      if (L.size() < 3) throw InvalidInput("internal: degenerate face after merging coplanar faces");
    }

    // Compact vertex numbering.
    std::vector<int> newIndex(nPts, -1);
    Poly P;
    for (const Loop& L : faces)
      for (int v : L)
        if (newIndex[v] < 0) {
          newIndex[v] = static_cast<int>(P.vertices_.size());
          P.vertices_.push_back(pts[v]);
          P.inputIndex_.push_back(v);
        }
    const int nV = static_cast<int>(P.vertices_.size());
    const int nF = static_cast<int>(faces.size());
    P.faceStart_.assign(1, 0);
    for (const Loop& L : faces) {
      for (int v : L) {
        P.heOrigin_.push_back(newIndex[v]);
        P.heFace_.push_back(static_cast<int>(P.faceStart_.size()) - 1);
      }
      P.faceStart_.push_back(static_cast<int>(P.heOrigin_.size()));
    }
    const int nH = static_cast<int>(P.heOrigin_.size());
    {
      std::vector<int> nx(nH);
      for (int h = 0; h < nH; ++h) nx[h] = P.heNext(h);
      P.heTwin_ = twinsBySorting(P.heOrigin_, nx);
    }
    P.heEdge_.assign(nH, -1);
    for (int h = 0; h < nH; ++h) {
      if (P.heEdge_[h] >= 0) continue;
      const int e = static_cast<int>(P.edgeHalfEdge_.size());
      P.edgeHalfEdge_.push_back(h);
      P.heEdge_[h] = e;
      P.heEdge_[P.heTwin_[h]] = e;
    }
    // Vertex rings, CCW from outside: the next outgoing half-edge after h (v -> w) is
    // twin(prev(h)) (v -> u), with face(h) between w and u.
    std::vector<int> anyOut(nV, -1);
    for (int h = 0; h < nH; ++h) anyOut[P.heOrigin_[h]] = h;
    P.vertexStart_.assign(1, 0);
    P.vertexStart_.reserve(nV + 1);
    P.vertexHalfEdge_.reserve(nH);
    P.vertexNeighbor_.reserve(nH);
    P.vertexFace_.reserve(nH);
    for (int v = 0; v < nV; ++v) {
      const int h0 = anyOut[v];
      int h = h0;
      int guard = 0;
      do {
        P.vertexHalfEdge_.push_back(h);
        P.vertexNeighbor_.push_back(P.heTarget(h));
        P.vertexFace_.push_back(P.heFace_[h]);
        h = P.heTwin_[P.hePrev(h)];
        if (++guard > nH) throw InvalidInput("internal: broken vertex ring");
      } while (h != h0);
      P.vertexStart_.push_back(static_cast<int>(P.vertexHalfEdge_.size()));
    }
    if (P.vertexStart_.back() != nH) throw InvalidInput("internal: non-manifold vertex after merging");
    if (nV - P.numEdges() + nF != 2) throw InvalidInput("internal: Euler characteristic is not 2 after merging");
    facePlanes(P);
    P.tolerance_ = tol;
    P.extent_ = extent;
    return P;
  }

  /// Face normals and offsets, and the interior point, from the vertices.
  static void facePlanes(Poly& P) {
    const int nF = P.numFaces();
    P.faceNormal_.resize(nF);
    P.faceOffset_.resize(nF);
    for (int f = 0; f < nF; ++f) {
      Loop L(P.faceVertices(f).begin(), P.faceVertices(f).end());
      const Vec3<T> n = testNormal(newell(P.vertices_, L));
      P.faceNormal_[f] = n;
      if constexpr (ScalarTraits<T>::isExact) {
        P.faceOffset_[f] = n.dot(P.vertices_[L[0]]);
      } else {
        T sum = T(0);
        for (int v : L) sum += n.dot(P.vertices_[v]);
        P.faceOffset_[f] = sum / T(static_cast<int>(L.size()));
      }
    }
    Vec3<T> sum = Vec3<T>::Zero();
    for (const auto& x : P.vertices_) sum += x;
    P.interior_ = sum / T(P.numVertices());
    P.edgesResolved_ = true;
    if constexpr (!ScalarTraits<T>::isExact) {
      const T floor = T(defaults::kMddParallelEdgeFactor) * ScalarTraits<T>::epsilon();
      for (int e = 0; e < P.numEdges() && P.edgesResolved_; ++e) {
        const auto fg = P.edgeFaces(e);
        P.edgesResolved_ = (P.faceNormal_[fg.first] + P.faceNormal_[fg.second]).cwiseAbs().maxCoeff() > floor;
      }
    }
  }

  // ---------------------------------------------------------------------------------
  static Poly fromPoints(const std::vector<Vec3<T>>& points, const HullOptions<T>& options) {
    const char* who = "fromPoints";
    if (points.empty()) throw InvalidInput("fromPoints: no points given");
    if (points.size() < 4)
      throw InvalidInput("fromPoints: need at least 4 points, got " + std::to_string(points.size()));
    checkFinite(points, who, "point");
    T m = T(0);
    if constexpr (!ScalarTraits<T>::isExact)
      for (const auto& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
    Poly P = atUnitScale(points, m, options, [&](const std::vector<Vec3<T>>& pts, const HullOptions<T>& opt) {
      return build(pts, opt, who);
    });
    // Quickhull decides every side exactly and faces merge only when exactly coplanar;
    // the rescaling is by powers of two, exact both ways on the vertices it keeps.
    P.exactHull_ = true;
    return P;
  }

  /// build(points, options), on a copy scaled to unit size by a power of two (exact both
  /// ways) when the largest coordinate m is beyond 2^±kRescaleExponent (1e-100 or 1e80):
  /// the degeneracy tests' squared lengths would otherwise underflow or overflow.
  /// Coordinates below 2^(e - 1074) (e: the exponent of m) are rounded to multiples of
  /// it, the resolution of doubles at unit scale: a vertex is then its input point
  /// within that (1e-300 in a 1e60 shape), not exactly.
  template <class Build>
  static Poly atUnitScale(const std::vector<Vec3<T>>& points, const T& m, const HullOptions<T>& options,
                          Build&& build) {
    if constexpr (!ScalarTraits<T>::isExact) {
      const int e = m > T(0) ? std::ilogb(m) : 0;
      if (e > kRescaleExponent || e < -kRescaleExponent) {
        std::vector<Vec3<T>> scaled(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
          for (int k = 0; k < 3; ++k) scaled[i][k] = std::ldexp(points[i][k], -e);
        HullOptions<T> opt = options;
        if (opt.tolerance > T(0)) opt.tolerance = std::ldexp(opt.tolerance, -e);
        Poly P = build(scaled, opt);
        // Scaled back exactly: the hull is the exact hull of the scaled copy, whose
        // coordinates below 2^(e - 1074) were rounded to that grid (a 1e-300 coordinate in
        // a 1e60 shape); the vertices are those points, and the planes are theirs.
        for (auto& x : P.vertices_)
          for (int k = 0; k < 3; ++k) x[k] = std::ldexp(x[k], e);
        facePlanes(P);
        P.tolerance_ = std::ldexp(P.tolerance_, e);
        P.extent_ = std::ldexp(P.extent_, e);
        return P;
      }
    }
    return build(points, options);
  }

  /// Beyond 2^±this, fromPoints works on a copy scaled to unit size.
  static constexpr int kRescaleExponent = 64;

  static Poly build(const std::vector<Vec3<T>>& points, const HullOptions<T>& options, const char* who) {
    const T extent = extentOf(points);
    const T tol = toleranceFor(options, extent, who);
    const auto tris = Quickhull<T>::run(points, tol);
    std::vector<Loop> polys;
    polys.reserve(tris.size());
    for (const auto& t : tris) polys.push_back({t[0], t[1], t[2]});
    return finish(points, std::move(polys), tol, extent);
  }

  // ---------------------------------------------------------------------------------
  static Poly fromMesh(const std::vector<Vec3<T>>& verts, const std::vector<Loop>& faces,
                       const HullOptions<T>& options) {
    if (verts.empty()) throw InvalidInput("fromMesh: no vertices given");
    if (faces.empty()) throw InvalidInput("fromMesh: no faces given");
    checkFinite(verts, "fromMesh", "vertex");
    // The scale of the vertices the faces use (bad indices are reported by meshBody).
    T m = T(0);
    if constexpr (!ScalarTraits<T>::isExact)
      for (const Loop& L : faces)
        for (int v : L)
          if (v >= 0 && v < static_cast<int>(verts.size())) m = std::max(m, verts[v].cwiseAbs().maxCoeff());
    Poly P = atUnitScale(verts, m, options, [&](const std::vector<Vec3<T>>& pts, const HullOptions<T>& opt) {
      return meshBody(pts, faces, opt);
    });
    // Exact T with the default tolerance (0) validates planarity and convexity with no
    // slack; floating point, or a tolerance given, within the tolerance.
    P.exactHull_ = ScalarTraits<T>::isExact && P.tolerance_ == T(0);
    return P;
  }

  static Poly meshBody(const std::vector<Vec3<T>>& verts, const std::vector<Loop>& faces,
                       const HullOptions<T>& options) {
    const char* who = "fromMesh";
    const int nV = static_cast<int>(verts.size());
    const int nF = static_cast<int>(faces.size());
    auto faceName = [](int f) { return "face " + std::to_string(f); };
    for (int f = 0; f < nF; ++f) {
      const Loop& L = faces[f];
      if (L.size() < 3)
        throw InvalidInput("fromMesh: " + faceName(f) + " has " + std::to_string(L.size()) +
                           " vertices; a face needs at least 3");
      for (std::size_t i = 0; i < L.size(); ++i) {
        if (L[i] < 0 || L[i] >= nV)
          throw InvalidInput("fromMesh: " + faceName(f) + " has vertex index " + std::to_string(L[i]) +
                             " out of range [0, " + std::to_string(nV) + ")");
        for (std::size_t j = 0; j < i; ++j)
          if (L[j] == L[i])
            throw InvalidInput("fromMesh: " + faceName(f) + " repeats vertex " + std::to_string(L[i]));
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
    const T tol = toleranceFor(options, extent, who);

    // Closed, consistently oriented 2-manifold.
    std::unordered_map<std::uint64_t, int> owner;
    owner.reserve(static_cast<std::size_t>(nF) * 4);
    for (int f = 0; f < nF; ++f) {
      const Loop& L = faces[f];
      for (std::size_t i = 0; i < L.size(); ++i) {
        const int a = L[i], b = L[(i + 1) % L.size()];
        if (!owner.emplace(key(a, b), f).second)
          throw InvalidInput("fromMesh: edge " + std::to_string(a) + "->" + std::to_string(b) +
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
          throw InvalidInput("fromMesh: mesh is not closed: edge " + std::to_string(a) + "-" +
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
          throw InvalidInput("fromMesh: vertex " + std::to_string(v) +
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
        throw InvalidInput("fromMesh: mesh is not connected (" + std::to_string(nF - queue.size()) +
                           " faces are not reachable from face 0)");
    }
    const long long chi = static_cast<long long>(usedPts.size()) - nE + nF;
    if (chi != 2)
      throw InvalidInput("fromMesh: mesh is not a topological sphere (Euler characteristic " +
                         std::to_string(chi) + ", expected 2)");
    // Planar, non-degenerate faces; outward orientation; local convexity.
    std::vector<Vec3<T>> n(nF);
    for (int f = 0; f < nF; ++f) {
      const Loop& L = faces[f];
      const Vec3<T> raw = newell(verts, L);
      if (raw == Vec3<T>::Zero())
        throw InvalidInput("fromMesh: " + faceName(f) + " is degenerate (zero area)");
      n[f] = testNormal(raw);
      for (int v : L)
        if (absValue(n[f].dot(verts[v] - verts[L[0]])) > tol)
          throw InvalidInput("fromMesh: " + faceName(f) + " is not planar (vertex " + std::to_string(v) +
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
        if (!(vol6 > T(0))) throw InvalidInput(inward);
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
        if (!(o < 0)) throw InvalidInput(inward);
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
              throw InvalidInput("fromMesh: mesh is not convex (vertex " + std::to_string(w) + " lies above " +
                                 faceName(f) + ")");
    }
    return finish(verts, faces, tol, extent);
  }
};

}  // namespace detail

template <class T>
ConvexPolyhedron<T> ConvexPolyhedron<T>::fromPoints(const std::vector<Vec3<T>>& points,
                                                    const HullOptions<T>& options) {
  return detail::PolyhedronBuilder<T>::fromPoints(points, options);
}

template <class T>
ConvexPolyhedron<T> ConvexPolyhedron<T>::fromMesh(const std::vector<Vec3<T>>& vertices,
                                                  const std::vector<std::vector<int>>& faces,
                                                  const HullOptions<T>& options) {
  return detail::PolyhedronBuilder<T>::fromMesh(vertices, faces, options);
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
      } else if (next < 0 && tied < 0 && val == best && detail::surelyUphill(d, vertices_[v], vertices_[w])) {
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
