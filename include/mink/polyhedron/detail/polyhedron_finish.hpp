// mink/polyhedron/detail/polyhedron_finish.hpp — the last stage of shape construction,
// shared by fromPoints and fromMesh: coplanar-face merging, corner splicing, the
// half-edge arrays and the face planes. Base of PolyhedronBuilder
// (convex_polyhedron_impl.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mink/core/defaults.hpp"
#include "mink/core/detail/spatial_order.hpp"
#include "mink/core/orientation.hpp"
#include "mink/polyhedron/detail/polyhedron_geometry.hpp"

namespace mink {
namespace detail {

template <class T>
struct PolyhedronFinish : PolyhedronGeometry<T> {
  using G = PolyhedronGeometry<T>;
  using typename G::Loop;
  using typename G::Poly;
  using typename G::Width;
  using G::key;
  using G::newell;
  using G::sizeKey;
  using G::testNormal;
  using G::width;

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
        if (count != 1) internalError("edge without exactly one partner while building");
        if (org[partner] != tgt[e.h]) internalError("inconsistent orientation while building");
        twin[e.h] = partner;
      }
    }
    return twin;
  }

  /// Renumbers P's vertices (vertices_, inputIndex_ and newIndex, input -> vertex) in
  /// Morton order of their points and sorts `faces` by the Morton order of their
  /// centroids (core/detail/spatial_order.hpp): a walk over the surface then reads
  /// neighbouring memory. Ids change, and sums taken in id order (the interior point)
  /// may change in their last bits; the geometry does not.
  static void spatialOrder(Poly& P, std::vector<Loop>& faces, std::vector<int>& newIndex) {
    const std::vector<int> order = mortonOrder(P.vertices_);  // new -> old vertex id
    std::vector<Vec3<T>> vertices(order.size());
    std::vector<int> input(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      vertices[i] = P.vertices_[order[i]];
      input[i] = P.inputIndex_[order[i]];
      newIndex[input[i]] = static_cast<int>(i);
    }
    P.vertices_ = std::move(vertices);
    P.inputIndex_ = std::move(input);
    std::vector<Vec3<T>> centroids;
    centroids.reserve(faces.size());
    for (const Loop& L : faces) {
      Vec3<T> c = Vec3<T>::Zero();
      for (int v : L) c += P.vertices_[newIndex[v]];
      centroids.push_back(c / T(static_cast<int>(L.size())));
    }
    std::vector<Loop> sorted;
    sorted.reserve(faces.size());
    for (int f : mortonOrder(centroids)) sorted.push_back(std::move(faces[f]));
    faces = std::move(sorted);
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
      if (L.size() < 3) internalError("degenerate face after merging coplanar faces");
    }

    // Compact vertex numbering: order of first appearance in the faces, or on a large
    // shape Morton order for vertices and faces alike (spatialOrder below).
    std::vector<int> newIndex(nPts, -1);
    Poly P;
    for (const Loop& L : faces)
      for (int v : L)
        if (newIndex[v] < 0) {
          newIndex[v] = static_cast<int>(P.vertices_.size());
          P.vertices_.push_back(pts[v]);
          P.inputIndex_.push_back(v);
        }
    if (static_cast<int>(P.vertices_.size()) >= defaults::kSpatialOrderMinVertices) spatialOrder(P, faces, newIndex);
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
    P.edgeVertex_.reserve(nH);
    for (int h = 0; h < nH; ++h) {
      if (P.heEdge_[h] >= 0) continue;
      const int e = static_cast<int>(P.edgeHalfEdge_.size());
      P.edgeHalfEdge_.push_back(h);
      P.edgeVertex_.push_back(P.heOrigin(h));
      P.edgeVertex_.push_back(P.heTarget(h));
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
        if (++guard > nH) internalError("broken vertex ring");
      } while (h != h0);
      P.vertexStart_.push_back(static_cast<int>(P.vertexHalfEdge_.size()));
    }
    if (P.vertexStart_.back() != nH) internalError("non-manifold vertex after merging");
    if (nV - P.numEdges() + nF != 2) internalError("Euler characteristic is not 2 after merging");
    facePlanes(P);
    P.tolerance_ = tol;
    P.extent_ = extent;
    interiorDepth(P);
    return P;
  }

  /// ConvexPolyhedron::interiorDepth (inexact T; after the planes, tolerance and extent):
  /// the interior point's distance to the nearest face plane, less what the planes may
  /// be off the hull of the vertices: the shape's tolerance (a fromMesh face is planar
  /// within it) and their rounding. The normals are unit vectors, to rounding.
  static void interiorDepth(Poly& P) {
    if constexpr (!ScalarTraits<T>::isExact) {
      T depth = std::numeric_limits<T>::infinity();
      for (int f = 0; f < P.numFaces(); ++f)
        depth = std::min(depth, T(P.faceOffset_[f] - P.faceNormal_[f].dot(P.interior_)));
      depth -= P.tolerance_ + T(16) * ScalarTraits<T>::epsilon() * P.extent_;
      P.interiorDepth_ = depth > T(0) ? depth : T(0);
    }
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
};

}  // namespace detail
}  // namespace mink
