// mink/io/detail/text_io.hpp — the token-level helpers shared by the OBJ and OFF
// readers and writers: locale-independent number parsing and printing for any mink
// scalar, whitespace tokenising, and the one way a reader reports an error
// ("<file>:<line>: <problem>", an Error that the throwing readers raise as mink::InvalidInput).
#pragma once

#include <charconv>
#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {
namespace io {
namespace detail {

/// The Error "<source>:<line>: <problem>".
inline Error errorAt(const std::string& source, std::size_t line, const std::string& problem) {
  return Error(source + ":" + std::to_string(line) + ": " + problem);
}

/// Splits `text` at blanks (space, tab, CR, vertical tab, form feed).
inline std::vector<std::string_view> splitTokens(std::string_view text) {
  std::vector<std::string_view> tokens;
  const auto isBlank = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  };
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && isBlank(text[i])) ++i;
    const std::size_t begin = i;
    while (i < text.size() && !isBlank(text[i])) ++i;
    if (i > begin) tokens.push_back(text.substr(begin, i - begin));
  }
  return tokens;
}

/// Drops a UTF-8 byte-order mark, which some Windows tools put before the first line.
inline std::string_view stripByteOrderMark(std::string_view firstLine) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  return firstLine.substr(0, kBom.size()) == kBom ? firstLine.substr(kBom.size()) : firstLine;
}

/// Drops everything from the first '#' on (both formats use '#' for comments).
inline std::string_view stripComment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// Parses the whole token as a base-10 int. False on anything else (sign and
/// digits only, no trailing characters, within int range).
inline bool parseInt(std::string_view token, int& out) {
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (*first == '+') ++first;  // from_chars rejects an explicit '+'
  const auto result = std::from_chars(first, last, out);
  return result.ec == std::errc() && result.ptr == last;
}

/// Parses the whole token as a finite number of type T.
/// float / double / long double: correctly rounded from the decimal text (std::from_chars,
/// independent of the C locale). Any other T (exact rationals such as CGAL::Gmpq): the
/// text is rounded to the nearest double, which T then represents exactly.
/// Non-finite values ("nan", "inf") and out-of-range values are rejected: no mink shape
/// can be built from them, and the reader can still say which line they came from.
template <class T>
bool parseScalar(std::string_view token, T& out) {
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (*first == '+') ++first;
  using Parsed = std::conditional_t<std::is_floating_point<T>::value, T, double>;
  Parsed value{};
  const auto result = std::from_chars(first, last, value);
  if (result.ec != std::errc() || result.ptr != last) return false;
  if (!ScalarTraits<Parsed>::isFinite(value)) return false;
  out = T(value);
  return true;
}

/// `x` as a double for a non-floating-point scalar (see core/scalar_traits.hpp).
using mink::detail::toDouble;

/// Writes `x` so that parseScalar<T> gives it back exactly for float / double / long
/// double (shortest round-trip text, std::to_chars). Other scalars are written as the
/// nearest double, so an exact value survives a round trip only if it is a double.
template <class T>
void writeScalar(std::ostream& out, const T& x) {
  char buffer[64];
  std::to_chars_result result;
  if constexpr (std::is_floating_point<T>::value) {
    result = std::to_chars(buffer, buffer + sizeof(buffer), x);
  } else {
    result = std::to_chars(buffer, buffer + sizeof(buffer), toDouble(x));
  }
  // 64 characters hold the shortest form of any long double; failure would be a bug.
  out.write(buffer, result.ptr - buffer);
}

/// What both writers check before they create a file, so that a refused mesh leaves no
/// half-written file behind and everything written reads back: finite coordinates,
/// faces of >= 3 indices, every index in [0, #V). The Error names the first offender,
/// prefixed with `writer`; none if the mesh is writable.
template <class T>
[[nodiscard]] Error checkWritable(const char* writer, const std::vector<Vec3<T>>& vertices,
                                  const std::vector<std::vector<int>>& faces) {
  const long long count = static_cast<long long>(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      if (!ScalarTraits<T>::isFinite(vertices[v][k])) {
        return Error(std::string(writer) + ": vertex " + std::to_string(v) + " has a non-finite coordinate");
      }
    }
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() < 3) {
      return Error(std::string(writer) + ": face " + std::to_string(f) + " has " +
                   std::to_string(faces[f].size()) + " indices (at least 3 needed)");
    }
    for (int index : faces[f]) {
      if (index < 0 || index >= count) {
        return Error(std::string(writer) + ": face " + std::to_string(f) + " has index " + std::to_string(index) +
                     " outside [0, " + std::to_string(count) + ")");
      }
    }
  }
  return Error();
}

}  // namespace detail
}  // namespace io
}  // namespace mink
