// mink/io/off.hpp — Object File Format (OFF) reader and writer for polygon meshes.
//
// Source: the OFF description of Geomview's manual (section "OFF Files"). mink reads the
// plain 3-D form:
//   1. drop '#' comments and blank lines;
//   2. header "OFF" (also "COFF", "NOFF", "CNOFF", "STOFF", ... whose extra per-vertex
//      values mink ignores), optionally followed on the same line by the counts;
//   3. counts "#V #F #E" (#E is informational and ignored);
//   4. #V lines "x y z [extra values]";
//   5. #F lines "n i_1 ... i_n [colour values]" with 0-based indices.
// Output: IndexedMesh<T>. Errors: mink::InvalidInput "<file>:<line>: <problem>" (readOff /
// writeOff), or that message as an Error (tryReadOff / tryWriteOff, which never throw).
// Numbers as in obj.hpp: locale-free, bit-exact round trips for floating-point T.
#pragma once

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/types.hpp"
#include "mink/io/detail/text_io.hpp"
#include "mink/io/indexed_mesh.hpp"

namespace mink {
namespace io {

/// Reads an OFF polygon mesh from `in`; `sourceName` names it in error messages. The mesh,
/// or the Error "<sourceName>:<line>: <problem>" for a missing or unsupported header, bad
/// counts, a malformed or missing vertex or face line, an index outside [0, #V), a face
/// with fewer than 3 vertices, or content after the last face. Never throws.
template <class T>
Result<IndexedMesh<T>> tryReadOff(std::istream& in, const std::string& sourceName = "<stream>") {
  IndexedMesh<T> mesh;
  std::string physical;
  std::size_t lineNumber = 0;
  const auto fail = [&](const std::string& problem) { return detail::errorAt(sourceName, lineNumber, problem); };
  // Next line that holds anything but comments and blanks, as tokens; empty at the end.
  const auto nextTokens = [&](std::vector<std::string_view>& tokens) -> Error {
    while (std::getline(in, physical)) {
      ++lineNumber;
      std::string_view text = physical;
      if (lineNumber == 1) text = detail::stripByteOrderMark(text);
      tokens = detail::splitTokens(detail::stripComment(text));
      if (!tokens.empty()) return Error();
    }
    tokens.clear();
    if (in.bad()) return fail("read error");
    return Error();
  };
  const auto count = [&](std::string_view token, const char* what, int& n) -> Error {
    if (!detail::parseInt(token, n) || n < 0) {
      return fail(std::string("'") + std::string(token) + "' is not a valid " + what);
    }
    return Error();
  };

  std::vector<std::string_view> tokens;
  if (Error e = nextTokens(tokens)) return e;
  if (tokens.empty()) return fail("empty file (expected the OFF header)");
  const std::string_view header = tokens[0];
  // [ST][C][N][4][n]OFF: mink accepts the 3-D forms only, so no '4' and no 'n'.
  const bool offSuffix = header.size() >= 3 && header.substr(header.size() - 3) == "OFF";
  const std::string_view prefix = offSuffix ? header.substr(0, header.size() - 3) : header;
  if (!offSuffix || prefix.find_first_not_of("STCN") != std::string_view::npos) {
    return fail("expected an OFF header (OFF, COFF, NOFF, STOFF, ...), found '" + std::string(header) + "'");
  }
  std::vector<std::string_view> counts(tokens.begin() + 1, tokens.end());
  if (counts.empty()) {
    if (Error e = nextTokens(counts)) return e;
  }
  if (counts.size() < 2 || counts.size() > 3) return fail("expected the counts '#vertices #faces [#edges]'");
  int numVertices = 0, numFaces = 0, numEdges = 0;
  if (Error e = count(counts[0], "vertex count", numVertices)) return e;
  if (Error e = count(counts[1], "face count", numFaces)) return e;
  if (counts.size() == 3) {
    if (Error e = count(counts[2], "edge count", numEdges)) return e;
  }

  // The counts come from the file: reserve no more than a modest amount up front, so a
  // forged header cannot demand gigabytes; a real large mesh just grows as it is read.
  constexpr int kReserveCap = 1 << 16;
  mesh.vertices.reserve(static_cast<std::size_t>(std::min(numVertices, kReserveCap)));
  for (int v = 0; v < numVertices; ++v) {
    if (Error e = nextTokens(tokens)) return e;
    if (tokens.empty()) {
      return fail("file ends after " + std::to_string(v) + " of " + std::to_string(numVertices) + " vertices");
    }
    if (tokens.size() < 3) {
      return fail("vertex " + std::to_string(v) + " needs 3 coordinates, found " + std::to_string(tokens.size()));
    }
    Vec3<T> p;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
      T value{};
      if (!detail::parseScalar(tokens[k], value)) {
        return fail("'" + std::string(tokens[k]) + "' is not a finite number");
      }
      if (k < 3) p[static_cast<int>(k)] = value;
    }
    mesh.vertices.push_back(p);
  }

  mesh.faces.reserve(static_cast<std::size_t>(std::min(numFaces, kReserveCap)));
  for (int f = 0; f < numFaces; ++f) {
    if (Error e = nextTokens(tokens)) return e;
    if (tokens.empty()) {
      return fail("file ends after " + std::to_string(f) + " of " + std::to_string(numFaces) + " faces");
    }
    int n = 0;
    if (Error e = count(tokens[0], "face size", n)) return e;
    if (n < 3) return fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices (at least 3 needed)");
    if (tokens.size() < static_cast<std::size_t>(n) + 1) {
      return fail("face " + std::to_string(f) + " announces " + std::to_string(n) + " vertices but lists " +
                  std::to_string(tokens.size() - 1));
    }
    std::vector<int> face(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const std::string_view token = tokens[static_cast<std::size_t>(k) + 1];
      if (!detail::parseInt(token, face[k]) || face[k] < 0 || face[k] >= numVertices) {
        return fail("'" + std::string(token) + "' is not a vertex index in [0, " + std::to_string(numVertices) + ")");
      }
    }
    for (std::size_t k = static_cast<std::size_t>(n) + 1; k < tokens.size(); ++k) {
      double colour = 0;
      if (!detail::parseScalar(tokens[k], colour)) {
        return fail("'" + std::string(tokens[k]) + "' after the face's indices is not a colour value");
      }
    }
    mesh.faces.push_back(std::move(face));
  }
  if (Error e = nextTokens(tokens)) return e;
  if (!tokens.empty()) return fail("unexpected content after the last face");
  return mesh;
}

/// Reads an OFF polygon mesh from `in` (see tryReadOff). Throws InvalidInput("<sourceName>:
/// <line>: <problem>") for a missing or unsupported header, bad counts, a malformed or
/// missing vertex or face line, an index outside [0, #V), a face with fewer than 3
/// vertices, or content after the last face.
template <class T>
IndexedMesh<T> readOff(std::istream& in, const std::string& sourceName = "<stream>") {
  return tryReadOff<T>(in, sourceName).value();
}

/// Reads the OFF file at `path`: the mesh, or the Error naming the file when it cannot be
/// opened, and "<path>:<line>: <problem>" for malformed content. Never throws.
template <class T>
Result<IndexedMesh<T>> tryReadOff(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error("cannot open OFF file '" + path.string() + "'");
  return tryReadOff<T>(in, path.string());
}

/// Reads the OFF file at `path`. Throws InvalidInput naming the file when it cannot be
/// opened, and "<path>:<line>: <problem>" for malformed content.
template <class T>
IndexedMesh<T> readOff(const std::filesystem::path& path) {
  return tryReadOff<T>(path).value();
}

namespace detail {

/// The OFF text of a mesh that checkWritable accepted; the header's edge count is the
/// number of distinct undirected edges.
template <class T>
void writeOffText(std::ostream& out, const std::vector<Vec3<T>>& vertices, const std::vector<std::vector<int>>& faces) {
  std::set<std::pair<int, int>> edges;
  for (const std::vector<int>& face : faces) {
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int a = face[k];
      const int b = face[(k + 1) % face.size()];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  out << "OFF\n# written by mink\n"
      << vertices.size() << ' ' << faces.size() << ' ' << edges.size() << '\n';
  for (const Vec3<T>& p : vertices) {
    for (int k = 0; k < 3; ++k) {
      if (k > 0) out << ' ';
      writeScalar(out, p[k]);
    }
    out << '\n';
  }
  for (const std::vector<int>& face : faces) {
    out << face.size();
    for (int index : face) out << ' ' << index;
    out << '\n';
  }
}

}  // namespace detail

/// Writes `vertices` (#V points) and `faces` (#F loops of >= 3 0-based indices) as OFF.
/// The edge count in the header is the number of distinct undirected edges. The Error,
/// before writing, for the reasons tryWriteObj gives; none when written. Never throws.
template <class T>
[[nodiscard]] Error tryWriteOff(std::ostream& out, const std::vector<Vec3<T>>& vertices,
                                const std::vector<std::vector<int>>& faces) {
  if (Error e = detail::checkWritable("writeOff", vertices, faces)) return e;
  detail::writeOffText(out, vertices, faces);
  return Error();
}

/// tryWriteOff, throwing InvalidInput for what it reports.
template <class T>
void writeOff(std::ostream& out, const std::vector<Vec3<T>>& vertices,
              const std::vector<std::vector<int>>& faces) {
  ::mink::detail::raiseIf(tryWriteOff(out, vertices, faces));
}

/// Writes an OFF file at `path` (created or truncated); the Error as tryWriteObj's, none
/// when written. Never throws.
template <class T>
[[nodiscard]] Error tryWriteOff(const std::filesystem::path& path, const std::vector<Vec3<T>>& vertices,
                                const std::vector<std::vector<int>>& faces) {
  if (Error e = detail::checkWritable("writeOff", vertices, faces)) return e;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return Error("cannot create OFF file '" + path.string() + "'");
  detail::writeOffText(out, vertices, faces);
  out.flush();
  if (!out) return Error("error while writing OFF file '" + path.string() + "'");
  return Error();
}

/// Writes an OFF file at `path`; throws InvalidInput for what tryWriteOff reports.
template <class T>
void writeOff(const std::filesystem::path& path, const std::vector<Vec3<T>>& vertices,
              const std::vector<std::vector<int>>& faces) {
  ::mink::detail::raiseIf(tryWriteOff(path, vertices, faces));
}

template <class T>
[[nodiscard]] Error tryWriteOff(const std::filesystem::path& path, const IndexedMesh<T>& mesh) {
  return tryWriteOff(path, mesh.vertices, mesh.faces);
}

template <class T>
void writeOff(const std::filesystem::path& path, const IndexedMesh<T>& mesh) {
  writeOff(path, mesh.vertices, mesh.faces);
}

}  // namespace io
}  // namespace mink
