// tests/support/expect_rejected.hpp — the check shared by the hostile-input tests of every
// layer: a call must throw mink::InvalidInput whose message names the problem.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <initializer_list>
#include <string>
#include <utility>

#include "mink/core/error.hpp"

namespace mink_test {

/// Runs fn, which must throw mink::InvalidInput whose what() contains every needle; any
/// other outcome (no exception, another exception type, a message without a needle) is
/// a test failure, reported under `context`.
template <class Fn>
void expectRejected(Fn&& fn, std::initializer_list<std::string> needles, const std::string& context) {
  SCOPED_TRACE(context);
  try {
    fn();
    ADD_FAILURE() << "accepted, expected InvalidInput containing: " << (needles.size() ? *needles.begin() : "");
  } catch (const mink::InvalidInput& e) {
    const std::string msg = e.what();
    for (const std::string& n : needles)
      EXPECT_NE(msg.find(n), std::string::npos) << "message: " << msg << "; expected: " << n;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something other than InvalidInput: " << e.what();
  }
}

/// The same, for a single needle.
template <class Fn>
void expectRejected(Fn&& fn, const std::string& needle, const std::string& context) {
  expectRejected(std::forward<Fn>(fn), {needle}, context);
}

}  // namespace mink_test
