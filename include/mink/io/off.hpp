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
// Output: IndexedMesh<T>. Errors: mink::InvalidInput "<file>:<line>: <problem>".
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

/// Reads an OFF polygon mesh from `in`; `sourceName` names it in error messages.
/// Throws InvalidInput("<sourceName>:<line>: <problem>") for a missing or unsupported
/// header, bad counts, a malformed or missing vertex or face line, an index outside
/// [0, #V), a face with fewer than 3 vertices, or content after the last face.
template <class T>
IndexedMesh<T> readOff(std::istream& in, const std::string& sourceName = "<stream>") {
  IndexedMesh<T> mesh;
  std::string physical;
  std::size_t lineNumber = 0;
  const auto fail = [&](const std::string& problem) {
    detail::failAt(sourceName, lineNumber, problem);
  };
  // Next line that holds anything but comments and blanks, as tokens; empty at the end.
  const auto nextTokens = [&]() -> std::vector<std::string_view> {
    while (std::getline(in, physical)) {
      ++lineNumber;
      std::string_view text = physical;
      if (lineNumber == 1) text = detail::stripByteOrderMark(text);
      std::vector<std::string_view> tokens = detail::splitTokens(detail::stripComment(text));
      if (!tokens.empty()) return tokens;
    }
    if (in.bad()) fail("read error");
    return {};
  };
  const auto count = [&](std::string_view token, const char* what) {
    int n = 0;
    if (!detail::parseInt(token, n) || n < 0) {
      fail(std::string("'") + std::string(token) + "' is not a valid " + what);
    }
    return n;
  };

  std::vector<std::string_view> tokens = nextTokens();
  if (tokens.empty()) fail("empty file (expected the OFF header)");
  const std::string_view header = tokens[0];
  // [ST][C][N][4][n]OFF: mink accepts the 3-D forms only, so no '4' and no 'n'.
  const bool offSuffix = header.size() >= 3 && header.substr(header.size() - 3) == "OFF";
  const std::string_view prefix = offSuffix ? header.substr(0, header.size() - 3) : header;
  if (!offSuffix || prefix.find_first_not_of("STCN") != std::string_view::npos) {
    fail("expected an OFF header (OFF, COFF, NOFF, STOFF, ...), found '" +
         std::string(header) + "'");
  }
  std::vector<std::string_view> counts(tokens.begin() + 1, tokens.end());
  if (counts.empty()) counts = nextTokens();
  if (counts.size() < 2 || counts.size() > 3) {
    fail("expected the counts '#vertices #faces [#edges]'");
  }
  const int numVertices = count(counts[0], "vertex count");
  const int numFaces = count(counts[1], "face count");
  if (counts.size() == 3) count(counts[2], "edge count");

  // The counts come from the file: reserve no more than a modest amount up front, so a
  // forged header cannot demand gigabytes; a real large mesh just grows as it is read.
  constexpr int kReserveCap = 1 << 16;
  mesh.vertices.reserve(static_cast<std::size_t>(std::min(numVertices, kReserveCap)));
  for (int v = 0; v < numVertices; ++v) {
    tokens = nextTokens();
    if (tokens.empty()) {
      fail("file ends after " + std::to_string(v) + " of " + std::to_string(numVertices) +
           " vertices");
    }
    if (tokens.size() < 3) {
      fail("vertex " + std::to_string(v) + " needs 3 coordinates, found " +
           std::to_string(tokens.size()));
    }
    Vec3<T> p;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
      T value{};
      if (!detail::parseScalar(tokens[k], value)) {
        fail("'" + std::string(tokens[k]) + "' is not a finite number");
      }
      if (k < 3) p[static_cast<int>(k)] = value;
    }
    mesh.vertices.push_back(p);
  }

  mesh.faces.reserve(static_cast<std::size_t>(std::min(numFaces, kReserveCap)));
  for (int f = 0; f < numFaces; ++f) {
    tokens = nextTokens();
    if (tokens.empty()) {
      fail("file ends after " + std::to_string(f) + " of " + std::to_string(numFaces) +
           " faces");
    }
    const int n = count(tokens[0], "face size");
    if (n < 3) fail("face " + std::to_string(f) + " has " + std::to_string(n) +
                    " vertices (at least 3 needed)");
    if (tokens.size() < static_cast<std::size_t>(n) + 1) {
      fail("face " + std::to_string(f) + " announces " + std::to_string(n) +
           " vertices but lists " + std::to_string(tokens.size() - 1));
    }
    std::vector<int> face(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const std::string_view token = tokens[static_cast<std::size_t>(k) + 1];
      if (!detail::parseInt(token, face[k]) || face[k] < 0 || face[k] >= numVertices) {
        fail("'" + std::string(token) + "' is not a vertex index in [0, " +
             std::to_string(numVertices) + ")");
      }
    }
    for (std::size_t k = static_cast<std::size_t>(n) + 1; k < tokens.size(); ++k) {
      double colour = 0;
      if (!detail::parseScalar(tokens[k], colour)) {
        fail("'" + std::string(tokens[k]) + "' after the face's indices is not a colour value");
      }
    }
    mesh.faces.push_back(std::move(face));
  }
  if (!nextTokens().empty()) fail("unexpected content after the last face");
  return mesh;
}

/// Reads the OFF file at `path`. Throws InvalidInput naming the file when it cannot be
/// opened, and "<path>:<line>: <problem>" for malformed content.
template <class T>
IndexedMesh<T> readOff(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput("cannot open OFF file '" + path.string() + "'");
  return readOff<T>(in, path.string());
}

/// Writes `vertices` (#V points) and `faces` (#F loops of >= 3 0-based indices) as OFF.
/// The edge count in the header is the number of distinct undirected edges. Throws
/// InvalidInput, before writing, for the reasons writeObj does.
template <class T>
void writeOff(std::ostream& out, const std::vector<Vec3<T>>& vertices,
              const std::vector<std::vector<int>>& faces) {
  detail::checkWritable("writeOff", vertices, faces);
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
      detail::writeScalar(out, p[k]);
    }
    out << '\n';
  }
  for (const std::vector<int>& face : faces) {
    out << face.size();
    for (int index : face) out << ' ' << index;
    out << '\n';
  }
}

/// Writes an OFF file at `path` (created or truncated); throws InvalidInput as writeObj.
template <class T>
void writeOff(const std::filesystem::path& path, const std::vector<Vec3<T>>& vertices,
              const std::vector<std::vector<int>>& faces) {
  detail::checkWritable("writeOff", vertices, faces);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InvalidInput("cannot create OFF file '" + path.string() + "'");
  writeOff(out, vertices, faces);
  out.flush();
  if (!out) throw InvalidInput("error while writing OFF file '" + path.string() + "'");
}

template <class T>
void writeOff(const std::filesystem::path& path, const IndexedMesh<T>& mesh) {
  writeOff(path, mesh.vertices, mesh.faces);
}

}  // namespace io
}  // namespace mink
