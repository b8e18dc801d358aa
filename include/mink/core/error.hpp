// mink/core/error.hpp — the one exception mink throws, and only where shapes and
// queries are *set up* (never inside a hot search loop).
#pragma once

#include <stdexcept>
#include <string>

namespace mink {

/// Bad input to a constructor or public entry point: empty, non-finite, degenerate,
/// non-convex or non-closed data, or out-of-range indices. The message names the
/// problem and, where there is one, the offending index.
class InvalidInput : public std::invalid_argument {
 public:
  explicit InvalidInput(const std::string& what) : std::invalid_argument("mink: " + what) {}
};

}  // namespace mink
