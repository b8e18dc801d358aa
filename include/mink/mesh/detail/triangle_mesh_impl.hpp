// mink/mesh/detail/triangle_mesh_impl.hpp — construction of TriangleMesh: validation,
// half-edge adjacency, edge classification, components and their volumes. Included at the
// bottom of triangle_mesh.hpp.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mink/core/detail/input_checks.hpp"
#include "mink/core/orientation.hpp"
#include "mink/mesh/detail/signed_volume.hpp"
#include "mink/mesh/triangle_intersection.hpp"

namespace mink {
namespace detail {

template <class T>
struct TriangleMeshBuilder {
  using Mesh = TriangleMesh<T>;
  using Data = TriangleMeshData<T>;
  using Tri = std::array<int, 3>;

  static constexpr const char* kWho = "TriangleMesh::fromMesh";

  /// The Error "TriangleMesh::fromMesh: <what>".
  static Error fail(const std::string& what) { return Error(std::string(kWho) + ": " + what); }
  static std::string str(long long i) { return std::to_string(i); }

  // Half-edge h = 3 t + i runs from corner i of triangle t to corner i + 1.
  static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }

  static Result<Mesh> build(const std::vector<Vec3<T>>& verts, const std::vector<Tri>& tris) {
    const int nV = static_cast<int>(verts.size());
    const int nF = static_cast<int>(tris.size());
    if (nV == 0) return fail("empty input (no vertices)");
    if (nF == 0) return fail("empty input (no triangles)");
    if (Error e = checkCoordinates(verts, kWho, "vertex")) return e;
    if (Error e = checkIndices(tris, nV)) return e;

    auto d = std::make_shared<Data>();
    d->vertices = verts;
    d->triangles = tris;
    std::vector<int> twin;
    if (Error e = pairHalfEdges(tris, twin)) return e;
    if (Error e = checkVertexFans(tris, twin, nV)) return e;
    if (Error e = checkCollinear(verts, tris)) return e;
    buildEdges(*d, twin);
    if (Error e = classifyEdges(*d)) return e;
    if (Error e = buildComponents(*d)) return e;
    buildStars(*d, twin);
    buildGeometry(*d);
    return Mesh(std::move(d));
  }

  [[nodiscard]] static Error checkIndices(const std::vector<Tri>& tris, int nV) {
    const int nF = static_cast<int>(tris.size());
    for (int t = 0; t < nF; ++t)
      for (int v : tris[t])
        if (v < 0 || v >= nV)
          return fail("triangle " + str(t) + " has vertex index " + str(v) + " out of range [0, " + str(nV) + ")");
    for (int t = 0; t < nF; ++t) {
      const Tri& c = tris[t];
      if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0])
        return fail("triangle " + str(t) + " is degenerate (it repeats vertex " +
                    str(c[0] == c[1] || c[0] == c[2] ? c[0] : c[1]) + ")");
    }
    return Error();
  }

  /// Groups the half-edges by undirected edge and gives each one's twin; rejects edges
  /// not used exactly twice, in opposite directions. Reported in this order over the
  /// whole mesh (an edge with three triangles usually leaves open edges next to it, and
  /// is the cause): non-manifold, open, inconsistently oriented.
  [[nodiscard]] static Error pairHalfEdges(const std::vector<Tri>& tris, std::vector<int>& twin) {
    const int nH = 3 * static_cast<int>(tris.size());
    auto origin = [&](int h) { return tris[h / 3][h % 3]; };
    auto target = [&](int h) { return origin(next(h)); };
    std::vector<std::pair<std::uint64_t, int>> keys(nH);
    for (int h = 0; h < nH; ++h) {
      const auto a = static_cast<std::uint32_t>(std::min(origin(h), target(h)));
      const auto b = static_cast<std::uint32_t>(std::max(origin(h), target(h)));
      keys[h] = {(static_cast<std::uint64_t>(a) << 32) | b, h};
    }
    std::sort(keys.begin(), keys.end());
    twin.assign(nH, -1);
    int open = -1, inconsistent = -1;
    for (int i = 0; i < nH;) {
      int j = i + 1;
      while (j < nH && keys[j].first == keys[i].first) ++j;
      const int h = keys[i].second;
      if (j - i > 2) {
        std::string list;
        for (int k = i; k < j && k < i + 6; ++k) list += (k > i ? ", " : "") + str(keys[k].second / 3);
        if (j - i > 6) list += ", ...";
        return fail("edge " + str(std::min(origin(h), target(h))) + "-" + str(std::max(origin(h), target(h))) +
                    " is non-manifold (used by " + str(j - i) + " triangles: " + list + ")");
      }
      if (j - i == 1) {
        if (open < 0) open = h;
      } else {
        const int g = keys[i + 1].second;
        if (origin(g) == origin(h)) {
          if (inconsistent < 0) inconsistent = std::min(h, g);
        } else {
          twin[h] = g;
          twin[g] = h;
        }
      }
      i = j;
    }
    if (open >= 0)
      return fail("edge " + str(origin(open)) + "-" + str(target(open)) + " of triangle " + str(open / 3) +
                  " is open (no other triangle uses it): the mesh is not closed");
    if (inconsistent >= 0) {
      const int h = inconsistent;
      int other = -1;
      for (int g = 0; g < nH; ++g)
        if (g != h && origin(g) == origin(h) && target(g) == target(h)) other = g;
      return fail("edge " + str(origin(h)) + "->" + str(target(h)) +
                  " is used twice in the same direction (triangles " + str(h / 3) + " and " + str(other / 3) +
                  "): inconsistent orientation");
    }
    return Error();
  }

  /// Around each vertex, the triangles must form a single fan (a disc): walking from one
  /// outgoing half-edge h to the next, twin(prev(h)), must visit all of them. Every
  /// vertex must be used.
  [[nodiscard]] static Error checkVertexFans(const std::vector<Tri>& tris, const std::vector<int>& twin, int nV) {
    const int nH = static_cast<int>(twin.size());
    std::vector<int> outCount(nV, 0), anyOut(nV, -1);
    for (int h = 0; h < nH; ++h) {
      const int v = tris[h / 3][h % 3];
      ++outCount[v];
      if (anyOut[v] < 0) anyOut[v] = h;
    }
    for (int v = 0; v < nV; ++v) {
      if (outCount[v] == 0) continue;
      int h = anyOut[v], steps = 0;
      do {
        h = twin[prev(h)];
        ++steps;
      } while (h != anyOut[v] && steps <= outCount[v]);
      if (steps != outCount[v])
        return fail("vertex " + str(v) + " is non-manifold (its triangles form more than one fan)");
    }
    for (int v = 0; v < nV; ++v)
      if (outCount[v] == 0) return fail("vertex " + str(v) + " is unreferenced (no triangle uses it)");
    return Error();
  }

  [[nodiscard]] static Error checkCollinear(const std::vector<Vec3<T>>& verts, const std::vector<Tri>& tris) {
    for (std::size_t t = 0; t < tris.size(); ++t)
      if (properAxis(verts[tris[t][0]], verts[tris[t][1]], verts[tris[t][2]]) < 0)
        return fail("triangle " + str(static_cast<long long>(t)) + " is degenerate (its corners are collinear)");
    return Error();
  }

  /// Undirected edges numbered in the order of their first half-edge; (a, b) runs along
  /// the half-edge of the lower-numbered triangle.
  static void buildEdges(Data& d, const std::vector<int>& twin) {
    const int nH = static_cast<int>(twin.size());
    d.triangleEdge.assign(nH, -1);
    d.triangleNeighbor.resize(nH);
    d.edgeVertices.reserve(nH / 2);
    d.edgeTriangles.reserve(nH / 2);
    for (int h = 0; h < nH; ++h) {
      d.triangleNeighbor[h] = twin[h] / 3;
      if (d.triangleEdge[h] >= 0) continue;
      const int e = static_cast<int>(d.edgeVertices.size());
      d.edgeVertices.push_back({d.triangles[h / 3][h % 3], d.triangles[h / 3][next(h) % 3]});
      d.edgeTriangles.push_back({h / 3, twin[h] / 3});
      d.triangleEdge[h] = d.triangleEdge[twin[h]] = e;
    }
  }

  /// Third corner of triangle t, opposite the edge (a, b).
  static int farCorner(const Tri& t, int a, int b) {
    for (int v : t)
      if (v != a && v != b) return v;
    return -1;
  }

  /// Convex / Reflex / Flat by the side of the second triangle's far corner d of the first
  /// triangle's plane (orient3d); when coplanar, by the side of the edge d lies on, in a
  /// projection where the first triangle is proper (orient2d): the side of its own far
  /// corner means the two are folded onto each other (rejected).
  [[nodiscard]] static Error classifyEdges(Data& d) {
    const int nE = static_cast<int>(d.edgeVertices.size());
    d.edgeKind.resize(nE);
    for (int e = 0; e < nE; ++e) {
      const auto [a, b] = d.edgeVertices[e];
      const auto [t1, t2] = d.edgeTriangles[e];
      const int c = farCorner(d.triangles[t1], a, b), q = farCorner(d.triangles[t2], a, b);
      const Vec3<T>&A = d.vertices[a], &B = d.vertices[b], &C = d.vertices[c], &D = d.vertices[q];
      const int o = orient3d(A, B, C, D);
      if (o < 0) {
        d.edgeKind[e] = EdgeKind::Convex;
      } else if (o > 0) {
        d.edgeKind[e] = EdgeKind::Reflex;
      } else {
        const int k = properAxis(A, B, C);
        if (orient2d(A, B, C, k) == orient2d(A, B, D, k))
          return fail("triangles " + str(t1) + " and " + str(t2) + " are folded onto each other across edge " +
                      str(a) + "-" + str(b) + " (coplanar, on the same side of it: a dihedral angle of 0)");
        d.edgeKind[e] = EdgeKind::Flat;
      }
    }
    return Error();
  }

  /// Connected components (across edges) and the sign of each one's volume.
  [[nodiscard]] static Error buildComponents(Data& d) {
    const int nF = static_cast<int>(d.triangles.size());
    d.component.assign(nF, -1);
    std::vector<int> members;
    for (int seed = 0; seed < nF; ++seed) {
      if (d.component[seed] >= 0) continue;
      const int k = d.numComponents++;
      members.assign(1, seed);
      d.component[seed] = k;
      for (std::size_t i = 0; i < members.size(); ++i)
        for (int s = 0; s < 3; ++s) {
          const int nb = d.triangleNeighbor[3 * members[i] + s];
          if (d.component[nb] < 0) {
            d.component[nb] = k;
            members.push_back(nb);
          }
        }
      std::sort(members.begin(), members.end());
      const int sign = signedVolumeSign(d.vertices, d.triangles, members);
      if (sign < 0)
        return fail("component " + str(k) + " (triangle " + str(seed) +
                    " and its neighbours) is oriented inward: its signed volume is negative");
      if (sign == 0)
        return fail("component " + str(k) + " (triangle " + str(seed) + " and its neighbours) has zero volume");
    }
    return Error();
  }

  /// Vertex stars in counter-clockwise order seen from outside: after the outgoing
  /// half-edge h (v -> w) comes twin(prev(h)) (v -> u); triangle h / 3 lies between w, u.
  static void buildStars(Data& d, const std::vector<int>& twin) {
    const int nV = static_cast<int>(d.vertices.size());
    const int nH = static_cast<int>(twin.size());
    std::vector<int> anyOut(nV, -1);
    for (int h = nH; h-- > 0;) anyOut[d.triangles[h / 3][h % 3]] = h;
    d.vertexStart.assign(1, 0);
    d.vertexNeighbor.reserve(nH);
    d.vertexTriangle.reserve(nH);
    d.vertexEdge.reserve(nH);
    d.vertexFlags.assign(nV, 0);
    for (int v = 0; v < nV; ++v) {
      bool allConvex = true, noReflex = true;
      int h = anyOut[v];
      do {
        const int e = d.triangleEdge[h];
        d.vertexNeighbor.push_back(d.triangles[h / 3][next(h) % 3]);
        d.vertexTriangle.push_back(h / 3);
        d.vertexEdge.push_back(e);
        allConvex = allConvex && d.edgeKind[e] == EdgeKind::Convex;
        noReflex = noReflex && d.edgeKind[e] != EdgeKind::Reflex;
        h = twin[prev(h)];
      } while (h != anyOut[v]);
      d.vertexStart.push_back(static_cast<int>(d.vertexNeighbor.size()));
      d.vertexFlags[v] = static_cast<unsigned char>((allConvex ? Mesh::kAllConvex : 0) | (noReflex ? Mesh::kNoReflex : 0));
    }
  }

  static void buildGeometry(Data& d) {
    d.normals.reserve(d.triangles.size());
    for (const Tri& t : d.triangles)
      d.normals.push_back(accurateCross(d.vertices[t[0]], d.vertices[t[1]], d.vertices[t[2]]));
    d.boxMin = d.boxMax = d.vertices[0];
    Vec3<T> m = Vec3<T>::Zero();
    for (const Vec3<T>& p : d.vertices)
      for (int k = 0; k < 3; ++k) {
        if (p[k] < d.boxMin[k]) d.boxMin[k] = p[k];
        if (d.boxMax[k] < p[k]) d.boxMax[k] = p[k];
        if (m[k] < absValue(p[k])) m[k] = absValue(p[k]);
      }
    d.extent = m[0] + m[1] + m[2];
    d.tree = SphereTree<T>::build(d.vertices, d.triangles);
  }
};

}  // namespace detail

template <class T>
Result<TriangleMesh<T>> TriangleMesh<T>::tryFromMesh(const std::vector<Vec3<T>>& vertices,
                                                     const std::vector<std::array<int, 3>>& triangles) {
  return detail::TriangleMeshBuilder<T>::build(vertices, triangles);
}

template <class T>
TriangleMesh<T> TriangleMesh<T>::fromMesh(const std::vector<Vec3<T>>& vertices,
                                          const std::vector<std::array<int, 3>>& triangles) {
  return tryFromMesh(vertices, triangles).value();
}

}  // namespace mink
