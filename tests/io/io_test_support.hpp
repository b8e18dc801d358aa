// Shared by the io tests: a scratch directory per test, removed afterwards, random
// meshes with coordinates spread over many binades, and the check that a try* twin
// reports exactly what its throwing entry point throws.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/types.hpp"

namespace mink_io_test {

namespace fs = std::filesystem;

// A directory of its own per test: ctest runs tests as separate, possibly concurrent
// processes, and several build trees may run the same suite at once.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    dir_ = fs::temp_directory_path() /
           ("mink_io_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(stamp));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  fs::path file(const std::string& name, const std::string& content) const {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  fs::path dir_;
};

inline std::vector<std::vector<int>> randomFaces(std::mt19937& rng, int numVertices,
                                                 int numFaces) {
  std::uniform_int_distribution<int> size(3, 7);
  std::uniform_int_distribution<int> index(0, numVertices - 1);
  std::vector<std::vector<int>> faces(static_cast<std::size_t>(numFaces));
  for (auto& f : faces) {
    f.resize(static_cast<std::size_t>(size(rng)));
    for (int& i : f) i = index(rng);
  }
  return faces;
}

// Coordinates over 2^-30 .. 2^30 of both signs, so that shortest round-trip printing is
// exercised, not just "%.6f"-friendly values.
template <class T>
std::vector<mink::Vec3<T>> randomVertices(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  std::vector<mink::Vec3<T>> v(static_cast<std::size_t>(n));
  for (auto& p : v) {
    for (int k = 0; k < 3; ++k) {
      p[k] = static_cast<T>(std::ldexp(static_cast<long double>(mantissa(rng)), exponent(rng)));
    }
  }
  return v;
}

// The what() of the mink::InvalidInput that fn throws, or "(nothing thrown)".
template <class Fn>
std::string thrownMessage(Fn&& fn) {
  try {
    fn();
  } catch (const mink::InvalidInput& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

// The Error of a try* twin (tryWriteObj, ...) must be set and read as the InvalidInput that
// throwingCall throws for the same input.
template <class Fn>
void expectSameError(const mink::Error& error, Fn&& throwingCall, const std::string& context) {
  SCOPED_TRACE(context);
  EXPECT_TRUE(error) << "the try* twin accepted what the throwing call rejects";
  EXPECT_EQ(error.message(), thrownMessage(throwingCall));
}

// The same for a Result (tryReadObj, ...): not ok(), with that Error.
template <class V, class Fn>
void expectSameError(const mink::Result<V>& result, Fn&& throwingCall, const std::string& context) {
  EXPECT_FALSE(result.ok()) << context << ": the try* twin accepted what the throwing call rejects";
  expectSameError(result.error(), std::forward<Fn>(throwingCall), context);
}

}  // namespace mink_io_test
