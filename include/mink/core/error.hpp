// mink/core/error.hpp — how mink reports bad input: the InvalidInput exception where
// exceptions are on, and Error / Result for the non-throwing entry points (tryFromPoints
// and the like), which also serve builds without exceptions (-fno-exceptions, as many
// engines build). Errors arise only where shapes and queries are *set up*, never inside
// a hot search loop.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

/// 1 when the translation unit is compiled with exceptions (the default), 0 under
/// -fno-exceptions. Define it yourself (0 or 1) to override the detection.
#ifndef MINK_EXCEPTIONS
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(_CPPUNWIND)
#define MINK_EXCEPTIONS 1
#else
#define MINK_EXCEPTIONS 0
#endif
#endif

namespace mink {

/// What went wrong with an input, or nothing (the default). message() reads exactly as
/// the what() of the InvalidInput that the throwing entry point throws for the same input:
/// "mink: <who>: <problem>", naming the offending element where there is one.
class Error {
 public:
  Error() = default;
  /// An error whose message is "mink: " + what.
  explicit Error(const std::string& what) : message_("mink: " + what) {}
  /// True when there is an error.
  explicit operator bool() const noexcept { return !message_.empty(); }
  const std::string& message() const noexcept { return message_; }

 private:
  std::string message_;
};

/// Bad input to a constructor or public entry point: empty, non-finite, degenerate,
/// non-convex or non-closed data, or out-of-range indices. The message names the
/// problem and, where there is one, the offending index.
class InvalidInput : public std::invalid_argument {
 public:
  explicit InvalidInput(const std::string& what) : std::invalid_argument("mink: " + what) {}
  /// The exception for an Error (its message unchanged).
  explicit InvalidInput(const Error& error) : std::invalid_argument(error.message()) {}
};

namespace detail {

/// Throws InvalidInput(error); without exceptions, prints the message to stderr and
/// aborts (the throwing entry points' behaviour in such builds: use their try* twins).
[[noreturn]] inline void raise(const Error& error) {
#if MINK_EXCEPTIONS
  throw InvalidInput(error);
#else
  std::fprintf(stderr, "%s\n", error.message().c_str());
  std::abort();
#endif
}

/// raise(error) if there is one.
inline void raiseIf(const Error& error) {
  if (error) raise(error);
}

/// A broken internal invariant (a bug, not bad input): InvalidInput "internal: <what>"
/// with exceptions, a message and abort without.
[[noreturn]] inline void internalError(const char* what) { raise(Error(std::string("internal: ") + what)); }

}  // namespace detail

/// A value, or the Error that kept it from being made: what the non-throwing entry points
/// (ConvexPolyhedron::tryFromPoints, TriangleMesh::tryFromMesh, tryReadTriangleMesh, ...)
/// return. Check ok() before value(); value() on an error throws the InvalidInput (or,
/// without exceptions, prints it and aborts).
template <class V>
class Result {
 public:
  Result(V value) : value_(std::move(value)) {}  // NOLINT: implicit, like std::optional
  Result(Error error) : error_(std::move(error)) {
    if (!error_) error_ = Error("internal: a Result made from an empty Error");
  }

  bool ok() const noexcept { return value_.has_value(); }
  explicit operator bool() const noexcept { return ok(); }
  /// The error (empty when ok()).
  const Error& error() const noexcept { return error_; }

  V& value() & { return check(), *value_; }
  const V& value() const& { return check(), *value_; }
  V&& value() && { return check(), std::move(*value_); }

 private:
  void check() const {
    if (!value_) detail::raise(error_);
  }

  std::optional<V> value_;
  Error error_;
};

}  // namespace mink
