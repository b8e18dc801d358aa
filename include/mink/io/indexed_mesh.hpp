// mink/io/indexed_mesh.hpp — IndexedMesh<T>: what the OBJ and OFF readers return and
// the writers take, a vertex array plus polygons as 0-based index loops. It is plain
// data: nothing is validated here beyond what the file format itself requires;
// ConvexPolyhedron<T>::fromMesh or ::fromPoints decide whether it is a usable shape.
#pragma once

#include <vector>

#include "mink/core/types.hpp"

namespace mink {
namespace io {

template <class T>
struct IndexedMesh {
  /// #V points, in the file's frame and length unit, in file order.
  std::vector<Vec3<T>> vertices;
  /// #F polygons, each a loop of >= 3 indices into `vertices` (0-based), in file order
  /// and with the file's orientation (OBJ and OFF both mean counter-clockwise seen from
  /// outside, but nothing checks that a file keeps to it).
  std::vector<std::vector<int>> faces;
};

}  // namespace io
}  // namespace mink
