// mink/io/triangle_mesh_io.hpp — from OBJ / OFF polygon meshes to TriangleMesh<T>.
//
//   1. readObj / readOff give the file's polygons (IndexedMesh<T>, nothing validated);
//   2. fanTriangulate splits every polygon (v0, v1, ..., vk) into (v0, vi, vi+1): right
//      for convex polygons (and those star-shaped from their first corner), which is what
//      mesh exporters write;
//   3. weldExactDuplicates (optional) merges vertices at exactly equal positions, for
//      files that repeat a vertex per face or per material (a mesh that is closed only
//      once they are merged);
//   4. TriangleMesh<T>::fromMesh validates the result; its message is prefixed with the
//      file name.
// readTriangleMesh throws mink::InvalidInput; tryReadTriangleMesh returns the same message
// as an Error and never throws.
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/types.hpp"
#include "mink/io/indexed_mesh.hpp"
#include "mink/io/obj.hpp"
#include "mink/io/off.hpp"
#include "mink/mesh/triangle_mesh.hpp"

namespace mink {
namespace io {

/// Vertices and triangles as TriangleMesh<T>::fromMesh takes them (nothing validated).
template <class T>
struct TriangleSoup {
  std::vector<Vec3<T>> vertices;             ///< #V points
  std::vector<std::array<int, 3>> triangles; ///< #F index triples into `vertices`
};

/// Every polygon (v0, ..., vk) of `mesh` as the triangles (v0, vi, vi+1), i = 1 .. k − 1,
/// in file order; vertices unchanged.
template <class T>
TriangleSoup<T> fanTriangulate(const IndexedMesh<T>& mesh) {
  TriangleSoup<T> soup;
  soup.vertices = mesh.vertices;
  for (const std::vector<int>& f : mesh.faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) soup.triangles.push_back({f[0], f[i], f[i + 1]});
  return soup;
}

/// Merges vertices at exactly equal positions (all three coordinates ==) into the first
/// of them in file order, drops the merged copies and renumbers the rest in order. A
/// triangle whose corners merge keeps its repeated index (fromMesh rejects it). If `map`
/// is given, map[old index] = new index.
template <class T>
TriangleSoup<T> weldExactDuplicates(const TriangleSoup<T>& soup, std::vector<int>* map = nullptr) {
  const int n = static_cast<int>(soup.vertices.size());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  auto less = [&](int a, int b) {
    const Vec3<T>&p = soup.vertices[a], &q = soup.vertices[b];
    for (int k = 0; k < 3; ++k) {
      if (p[k] < q[k]) return true;
      if (q[k] < p[k]) return false;
    }
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> first(n);  // the lowest index at the same position
  for (int i = 0; i < n; ++i) {
    const int v = order[i];
    first[v] = (i > 0 && soup.vertices[order[i - 1]] == soup.vertices[v]) ? first[order[i - 1]] : v;
  }
  TriangleSoup<T> out;
  std::vector<int> index(n, -1);
  for (int v = 0; v < n; ++v) {
    if (first[v] == v) {
      index[v] = static_cast<int>(out.vertices.size());
      out.vertices.push_back(soup.vertices[v]);
    } else {
      index[v] = index[first[v]];
    }
  }
  out.triangles.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles) {
    std::array<int, 3> r = t;
    for (int& v : r)
      if (v >= 0 && v < n) v = index[v];  // out-of-range indices are left for fromMesh to name
    out.triangles.push_back(r);
  }
  if (map) *map = std::move(index);
  return out;
}

struct TriangleMeshReadOptions {
  /// Merge vertices at equal positions before validation (weldExactDuplicates).
  bool weld = false;
};

/// Reads `path` (.obj or .off, by extension, any case), fan-triangulates it, optionally
/// welds it and builds the TriangleMesh. The mesh, or the Error: the readers' errors
/// ("<path>:<line>: ..."), an unknown extension, or fromMesh's rejection prefixed with the
/// path ("<path>: TriangleMesh::fromMesh: ..."). Never throws.
template <class T>
Result<TriangleMesh<T>> tryReadTriangleMesh(const std::filesystem::path& path,
                                            const TriangleMeshReadOptions& options = {}) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".obj" && ext != ".off")
    return Error("readTriangleMesh: '" + path.string() + "' is neither .obj nor .off");
  Result<IndexedMesh<T>> polygons = ext == ".obj" ? tryReadObj<T>(path) : tryReadOff<T>(path);
  if (!polygons.ok()) return polygons.error();
  TriangleSoup<T> soup = fanTriangulate(polygons.value());
  if (options.weld) soup = weldExactDuplicates(soup);
  Result<TriangleMesh<T>> mesh = TriangleMesh<T>::tryFromMesh(soup.vertices, soup.triangles);
  if (mesh.ok()) return mesh;
  // "mink: TriangleMesh::fromMesh: ..." becomes "mink: <path>: TriangleMesh::fromMesh: ...".
  std::string what = mesh.error().message();
  const std::string prefix = "mink: ";
  if (what.compare(0, prefix.size(), prefix) == 0) what.erase(0, prefix.size());
  return Error(path.string() + ": " + what);
}

/// tryReadTriangleMesh, throwing InvalidInput for what it reports: the readers' errors
/// ("<path>:<line>: ..."), an unknown extension, or fromMesh's rejection prefixed with the
/// path ("<path>: TriangleMesh::fromMesh: ...").
template <class T>
TriangleMesh<T> readTriangleMesh(const std::filesystem::path& path, const TriangleMeshReadOptions& options = {}) {
  return tryReadTriangleMesh<T>(path, options).value();
}

}  // namespace io
}  // namespace mink
