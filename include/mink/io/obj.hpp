// mink/io/obj.hpp — Wavefront OBJ reader and writer for polygon meshes.
//
// Source: the Wavefront "Object Files (.obj)" specification (Advanced Visualizer
// manual, appendix B1). Only the polygonal part matters to mink:
//   1. join lines ending in '\', drop '#' comments and blank lines;
//   2. "v x y z [w | r g b ...]" appends a vertex (x, y, z are kept);
//   3. "f a b c ..." appends a polygon; each reference is "v", "v/vt", "v//vn" or
//      "v/vt/vn"; v counts from 1, or is negative and counts back from the last
//      vertex read so far (-1 is the latest);
//   4. every other keyword of the specification (vt, vn, g, o, s, usemtl, l, ...) is
//      read past; anything that is not a keyword of the specification is an error.
// Output: IndexedMesh<T> with 0-based indices in file order. Errors: mink::InvalidInput
// whose message starts with "<file>:<line>:" and names the problem (readObj / writeObj), or
// that message as an Error (tryReadObj / tryWriteObj, which never throw).
//
// Numbers are parsed and printed without the C locale (std::from_chars / to_chars), so a
// float / double / long double mesh written by writeObj reads back bit for bit.
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/types.hpp"
#include "mink/io/detail/text_io.hpp"
#include "mink/io/indexed_mesh.hpp"

namespace mink {
namespace io {

namespace detail {

/// OBJ keywords that carry nothing mink uses (texture / normal data, grouping,
/// materials, free-form geometry, points and polylines). Read past without parsing.
inline bool isIgnoredObjKeyword(std::string_view keyword) {
  static constexpr std::string_view kIgnored[] = {
      "vt", "vn", "vp",                                          // vertex data
      "p", "l",                                                  // points, polylines
      "g", "o", "s", "mg",                                       // grouping
      "usemtl", "mtllib", "shadow_obj", "trace_obj", "bevel",    // display
      "c_interp", "d_interp", "lod", "ctech", "stech",           //   attributes
      "cstype", "deg", "bmat", "step", "curv", "curv2", "surf",  // free-form
      "parm", "trim", "hole", "scrv", "sp", "end", "con"};       //   geometry
  for (std::string_view k : kIgnored) {
    if (keyword == k) return true;
  }
  return false;
}

/// Vertex index of one face reference ("v", "v/vt", "v//vn", "v/vt/vn"), still in OBJ
/// numbering (1-based or negative), into `vertex`. The vt / vn parts must be integers
/// when present.
[[nodiscard]] inline Error parseObjFaceReference(std::string_view ref, const std::string& source, std::size_t line,
                                                 int& vertex) {
  std::string_view parts[3];
  std::size_t count = 0;
  std::size_t begin = 0;
  while (true) {
    const std::size_t slash = ref.find('/', begin);
    if (count == 3) {
      return errorAt(source, line,
                     "face reference '" + std::string(ref) + "' has more than three '/'-separated parts");
    }
    parts[count++] = ref.substr(begin, slash == std::string_view::npos ? slash : slash - begin);
    if (slash == std::string_view::npos) break;
    begin = slash + 1;
  }
  if (!parseInt(parts[0], vertex)) {
    return errorAt(source, line,
                   "face reference '" + std::string(ref) + "' does not start with an integer vertex index");
  }
  for (std::size_t k = 1; k < count; ++k) {
    int unused = 0;
    // "v//vn" leaves the texture part empty; an empty normal part ("v/vt/") is not OBJ.
    const bool mayBeEmpty = k == 1 && count == 3;
    if (parts[k].empty() ? !mayBeEmpty : !parseInt(parts[k], unused)) {
      return errorAt(source, line, "face reference '" + std::string(ref) + "' has a malformed " +
                                       (k == 1 ? "texture" : "normal") + " index");
    }
  }
  if (vertex == 0) {
    return errorAt(source, line, "vertex index 0 in face reference '" + std::string(ref) +
                                     "' (OBJ indices start at 1; negative ones count back)");
  }
  return Error();
}

}  // namespace detail

/// Reads an OBJ polygon mesh from `in`; `sourceName` names it in error messages. The
/// mesh, or the Error "<sourceName>:<line>: <problem>" for a malformed statement, a face
/// with fewer than 3 vertices, or a vertex index that is 0 or out of range. Never throws.
template <class T>
Result<IndexedMesh<T>> tryReadObj(std::istream& in, const std::string& sourceName = "<stream>") {
  IndexedMesh<T> mesh;
  // A positive index may name a vertex defined further down; those are checked at the end.
  struct ForwardReference {
    std::size_t line;
    int index;
  };
  std::vector<ForwardReference> forward;

  const auto fail = [&](std::size_t line, const std::string& problem) {
    return detail::errorAt(sourceName, line, problem);
  };
  const auto parseStatement = [&](std::string_view text, std::size_t line) -> Error {
    const std::vector<std::string_view> tokens = detail::splitTokens(text);
    if (tokens.empty()) return Error();
    const std::string_view keyword = tokens[0];
    if (keyword == "v") {
      const std::size_t n = tokens.size() - 1;
      if (n < 3 || n > 7) {
        return fail(line, "vertex statement needs x y z and at most 4 optional values, found " +
                              std::to_string(n) + " values");
      }
      Vec3<T> p;
      for (std::size_t k = 1; k <= n; ++k) {
        T value{};
        if (!detail::parseScalar(tokens[k], value)) {
          return fail(line, "'" + std::string(tokens[k]) + "' is not a finite number");
        }
        if (k <= 3) p[static_cast<int>(k - 1)] = value;
      }
      mesh.vertices.push_back(p);
    } else if (keyword == "f") {
      if (tokens.size() < 4) {
        return fail(line, "face needs at least 3 vertices, found " + std::to_string(tokens.size() - 1));
      }
      const long long defined = static_cast<long long>(mesh.vertices.size());
      std::vector<int> face;
      face.reserve(tokens.size() - 1);
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        int index = 0;
        if (Error e = detail::parseObjFaceReference(tokens[k], sourceName, line, index)) return e;
        if (index < 0) {
          const long long zeroBased = defined + index;
          if (zeroBased < 0) {
            return fail(line, "relative vertex index " + std::to_string(index) +
                                  " reaches before the first vertex (" + std::to_string(defined) +
                                  " defined so far)");
          }
          face.push_back(static_cast<int>(zeroBased));
        } else {
          if (index > defined) forward.push_back({line, index});
          face.push_back(index - 1);
        }
      }
      mesh.faces.push_back(std::move(face));
    } else if (!detail::isIgnoredObjKeyword(keyword)) {
      return fail(line, "'" + std::string(keyword) + "' is not an OBJ statement");
    }
    return Error();
  };

  std::string physical;
  std::string statement;
  std::size_t lineNumber = 0;
  std::size_t statementLine = 0;
  bool continued = false;
  while (std::getline(in, physical)) {
    ++lineNumber;
    if (!continued) {
      statement.clear();
      statementLine = lineNumber;
    }
    std::string_view text = physical;
    if (lineNumber == 1) text = detail::stripByteOrderMark(text);
    text = detail::stripComment(text);
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t')) {
      text.remove_suffix(1);
    }
    continued = !text.empty() && text.back() == '\\';
    if (continued) text.remove_suffix(1);
    statement.append(text.data(), text.size());
    statement.push_back(' ');
    if (!continued) {
      if (Error e = parseStatement(statement, statementLine)) return e;
    }
  }
  if (in.bad()) return fail(lineNumber, "read error");
  if (continued) {
    if (Error e = parseStatement(statement, statementLine)) return e;
  }

  const long long total = static_cast<long long>(mesh.vertices.size());
  for (const ForwardReference& ref : forward) {
    if (ref.index > total) {
      return fail(ref.line, "vertex index " + std::to_string(ref.index) + " is out of range (the file has " +
                                std::to_string(total) + " vertices)");
    }
  }
  return mesh;
}

/// Reads an OBJ polygon mesh from `in` (see tryReadObj). Throws InvalidInput("<sourceName>:
/// <line>: <problem>") on a malformed statement, a face with fewer than 3 vertices, or a
/// vertex index that is 0 or out of range.
template <class T>
IndexedMesh<T> readObj(std::istream& in, const std::string& sourceName = "<stream>") {
  return tryReadObj<T>(in, sourceName).value();
}

/// Reads the OBJ file at `path`: the mesh, or the Error naming the file when it cannot be
/// opened, and "<path>:<line>: <problem>" for malformed content. Never throws.
template <class T>
Result<IndexedMesh<T>> tryReadObj(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error("cannot open OBJ file '" + path.string() + "'");
  return tryReadObj<T>(in, path.string());
}

/// Reads the OBJ file at `path`. Throws InvalidInput naming the file when it cannot be
/// opened, and "<path>:<line>: <problem>" for malformed content (see the stream overload).
template <class T>
IndexedMesh<T> readObj(const std::filesystem::path& path) {
  return tryReadObj<T>(path).value();
}

namespace detail {

/// The OBJ text of a mesh that checkWritable accepted.
template <class T>
void writeObjText(std::ostream& out, const std::vector<Vec3<T>>& vertices, const std::vector<std::vector<int>>& faces) {
  out << "# written by mink: " << vertices.size() << " vertices, " << faces.size()
      << " faces\n";
  for (const Vec3<T>& p : vertices) {
    out << 'v';
    for (int k = 0; k < 3; ++k) {
      out << ' ';
      writeScalar(out, p[k]);
    }
    out << '\n';
  }
  for (const std::vector<int>& face : faces) {
    out << 'f';
    for (int index : face) out << ' ' << index + 1;
    out << '\n';
  }
}

}  // namespace detail

/// Writes `vertices` (#V points) and `faces` (#F loops of >= 3 0-based indices) as OBJ
/// text to `out`, 1-based as the format wants. Checks everything before writing a byte:
/// the Error for a non-finite coordinate, a face with fewer than 3 indices or an index
/// outside [0, #V); none when written. Never throws.
template <class T>
[[nodiscard]] Error tryWriteObj(std::ostream& out, const std::vector<Vec3<T>>& vertices,
                                const std::vector<std::vector<int>>& faces) {
  if (Error e = detail::checkWritable("writeObj", vertices, faces)) return e;
  detail::writeObjText(out, vertices, faces);
  return Error();
}

/// tryWriteObj, throwing InvalidInput for what it reports.
template <class T>
void writeObj(std::ostream& out, const std::vector<Vec3<T>>& vertices,
              const std::vector<std::vector<int>>& faces) {
  ::mink::detail::raiseIf(tryWriteObj(out, vertices, faces));
}

/// Writes an OBJ file at `path` (created or truncated). The Error, for the reasons of the
/// stream overload (before the file is touched), when the file cannot be created, or on a
/// write error; none when written. Never throws.
template <class T>
[[nodiscard]] Error tryWriteObj(const std::filesystem::path& path, const std::vector<Vec3<T>>& vertices,
                                const std::vector<std::vector<int>>& faces) {
  if (Error e = detail::checkWritable("writeObj", vertices, faces)) return e;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return Error("cannot create OBJ file '" + path.string() + "'");
  detail::writeObjText(out, vertices, faces);
  out.flush();
  if (!out) return Error("error while writing OBJ file '" + path.string() + "'");
  return Error();
}

/// Writes an OBJ file at `path`; throws InvalidInput for what tryWriteObj reports.
template <class T>
void writeObj(const std::filesystem::path& path, const std::vector<Vec3<T>>& vertices,
              const std::vector<std::vector<int>>& faces) {
  ::mink::detail::raiseIf(tryWriteObj(path, vertices, faces));
}

template <class T>
[[nodiscard]] Error tryWriteObj(const std::filesystem::path& path, const IndexedMesh<T>& mesh) {
  return tryWriteObj(path, mesh.vertices, mesh.faces);
}

template <class T>
void writeObj(const std::filesystem::path& path, const IndexedMesh<T>& mesh) {
  writeObj(path, mesh.vertices, mesh.faces);
}

}  // namespace io
}  // namespace mink
