// Tests of mink/core/error.hpp: InvalidInput is a std::invalid_argument whose message
// is the caller's text prefixed with "mink: ".
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <type_traits>

#include "mink/core/error.hpp"

namespace {

static_assert(std::is_base_of<std::invalid_argument, mink::InvalidInput>::value,
              "InvalidInput must derive from std::invalid_argument");

TEST(InvalidInput, DerivesFromInvalidArgument) {
  EXPECT_TRUE((std::is_base_of<std::invalid_argument, mink::InvalidInput>::value));
  EXPECT_TRUE((std::is_base_of<std::logic_error, mink::InvalidInput>::value));
  bool caught = false;
  try {
    throw mink::InvalidInput("face 3 is not planar");
  } catch (const std::invalid_argument& e) {
    caught = true;
    EXPECT_NE(dynamic_cast<const mink::InvalidInput*>(&e), nullptr);
  }
  EXPECT_TRUE(caught);
}

TEST(InvalidInput, MessageHasPrefix) {
  const mink::InvalidInput e("face 3 is not planar");
  EXPECT_EQ(std::string(e.what()), "mink: face 3 is not planar");
  const mink::InvalidInput empty("");
  EXPECT_EQ(std::string(empty.what()), "mink: ");
}

}  // namespace
